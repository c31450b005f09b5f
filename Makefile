# paper_repro: `make reproduce` and `make test` need nothing but python3 (>= 3.11);
# the first run creates .venv and installs the package with its dependencies, later runs reuse it.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-stamp

.PHONY: venv reproduce reproduce-extended test test-all bench figures lint clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --disable-pip-version-check -e '.[dev]'
	touch $(STAMP)

venv: $(STAMP)

reproduce: $(STAMP)            ## all claims, data/, figures/, gallery
	$(PY) -m paper_repro reproduce

reproduce-extended: $(STAMP)   ## the same with the extended ranges (larger n)
	$(PY) -m paper_repro reproduce --extended

test: $(STAMP)                 ## fast test suite
	$(PY) -m pytest -q -m "not slow and not benchmark"

test-all: $(STAMP)             ## every test, slow ones included
	$(PY) -m pytest -q -m "not benchmark"

bench: $(STAMP)                ## speed: pytest-benchmark, then the comparison with bezier and mpmath -> reports/
	mkdir -p reports
	$(PY) -m pytest -q -m benchmark --benchmark-enable --benchmark-only --benchmark-json=reports/pytest-benchmark.json tests
	$(PY) -m paper_repro.app.bench

figures: $(STAMP)
	$(PY) -m paper_repro figures

lint: $(STAMP)
	$(PY) -m ruff check paper_repro tests

clean:                         ## caches and build products (not data/ or figures/)
	rm -rf build .cache .pytest_cache .hypothesis .ruff_cache
