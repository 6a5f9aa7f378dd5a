# al2py developer tasks.  `make run` and `make test` work on a fresh clone.
PYTHON ?= python3
VENV   ?= .venv
PY     := $(VENV)/bin/python
PIP    := $(PY) -m pip
EXAMPLE ?= examples/tutor6.al
ANTLR  := $(VENV)/bin/antlr4

.PHONY: install bytecode run test test-full golden grammar bench lint clean

$(VENV)/.installed: pyproject.toml setup.py runtime/pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PIP) install --quiet --upgrade pip
	$(PIP) install --quiet -e "./runtime[plot,dask]"
	$(PIP) install --quiet -e ".[dev,plot,notebook]"
	touch $@

install: $(VENV)/.installed

# Editable installs get no bytecode from pip, and with PYTHONDONTWRITEBYTECODE
# set every import would compile the runtime again (about 0.1 s per model
# import): compile it once here (only what changed since).
bytecode: install
	$(PY) -m compileall -q runtime/al2py_runtime src/al2py

run: bytecode
	mkdir -p out
	$(VENV)/bin/al2py $(EXAMPLE) -o out/$(basename $(notdir $(EXAMPLE))).py
	cd out && ../$(PY) $(basename $(notdir $(EXAMPLE))).py

# Tests run in one pytest-xdist worker per processor (TEST_WORKERS=1: one
# process); a worker takes the next test when it is free ("worksteal"),
# since a few tests take most of a minute.  The slowest are listed at the end.
TEST_WORKERS ?= auto
XDIST := -n $(TEST_WORKERS) --dist worksteal

# The default tier: about 15 minutes on 2 cores (2026-11-29).
test: bytecode
	$(PY) -m pytest -q $(XDIST) --durations=25

# The full tier adds the tests marked 'full' (pytest --full): the 500-mutant
# fuzz run, the full-size determinism runs, sympy's own derivation of the
# converted Whipple bicycle and every published Autolev program pair.
test-full: bytecode
	$(PY) -m pytest -q $(XDIST) --full

# Write the kept generated modules (tests/golden/modules/*.py) again.
golden: install
	$(PY) tests/test_golden_modules.py

lint: install
	$(VENV)/bin/ruff check src runtime tests
	$(VENV)/bin/black --check src runtime tests

grammar: install
	cd grammar && ../$(ANTLR) -Dlanguage=Python3 -visitor -no-listener \
		-o ../src/al2py/_antlr -Xexact-output-dir Autolev.g4
	$(PY) -m al2py._grammar_stamp --write

bench: bytecode
	$(PY) benchmarks/run.py
	$(PY) benchmarks/large.py
	$(PY) benchmarks/startup.py
	$(PY) benchmarks/numerics.py

clean:
	rm -rf out .pytest_cache .ruff_cache
