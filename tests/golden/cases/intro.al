Constants A, B
X = 4*(A+B) - 3*(a-b)
