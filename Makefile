# al2py developer tasks.  `make run` and `make test` work on a fresh clone.
PYTHON ?= python3
VENV   ?= .venv
PY     := $(VENV)/bin/python
PIP    := $(PY) -m pip
EXAMPLE ?= examples/tutor6.al
ANTLR  := $(VENV)/bin/antlr4

.PHONY: install run test grammar bench lint clean

$(VENV)/.installed: pyproject.toml runtime/pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PIP) install --quiet --upgrade pip
	$(PIP) install --quiet -e ".[dev,plot]"
	touch $@

install: $(VENV)/.installed

run: install
	mkdir -p out
	$(VENV)/bin/al2py $(EXAMPLE) -o out/$(basename $(notdir $(EXAMPLE))).py
	cd out && ../$(PY) $(basename $(notdir $(EXAMPLE))).py

test: install
	$(PY) -m pytest -q

lint: install
	$(VENV)/bin/ruff check src runtime tests
	$(VENV)/bin/black --check src runtime tests

grammar: install
	cd grammar && ../$(ANTLR) -Dlanguage=Python3 -visitor -no-listener \
		-o ../src/al2py/_antlr -Xexact-output-dir Autolev.g4
	$(PY) -m al2py._grammar_stamp --write

bench: install
	$(PY) benchmarks/run.py
	$(PY) benchmarks/large.py
	$(PY) benchmarks/numerics.py

clean:
	rm -rf out .pytest_cache .ruff_cache
