# paper_repro: `make reproduce` and `make test` need nothing but python3 (>= 3.11);
# the first run creates .venv and installs the package with its dependencies, later runs reuse it.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-stamp

.PHONY: venv lock report paper check-paper check-gallery reproduce reproduce-extended test test-all bench bench-coefficients bench-question1 figures lint clean distclean

# The environment: the exact versions of requirements.lock (what `make reproduce` was run with, so
# figures stay byte-identical), then the package itself without resolving anything.  A failed install
# removes the half-built environment, so nothing stale is reused.
$(STAMP): pyproject.toml requirements.lock
	@$(PYTHON) -c 'import sys; sys.exit(0 if sys.version_info >= (3, 11) else 1)' 2>/dev/null || \
	  { echo "paper_repro needs Python >= 3.11, but '$(PYTHON)' is $$($(PYTHON) -V 2>&1); run with PYTHON=python3.11 (or newer)." >&2; exit 1; }
	rm -f $(STAMP)
	$(PYTHON) -m venv $(VENV) || { rm -rf $(VENV); exit 1; }
	$(PY) -m pip install --quiet --disable-pip-version-check --require-hashes -r requirements.lock || { rm -rf $(VENV); exit 1; }
	$(PY) -m pip install --quiet --disable-pip-version-check --no-deps -e . || { rm -rf $(VENV); exit 1; }
	touch $(STAMP)

venv: $(STAMP)

lock:                          ## refresh requirements.lock from pyproject's ranges (newest that install)
	$(PYTHON) -m venv build/lock-venv
	build/lock-venv/bin/python -m pip install --quiet --disable-pip-version-check '.[dev]'
	build/lock-venv/bin/python -m pip freeze --exclude-editable | grep -v '^paper.repro' > requirements.lock
	rm -rf build/lock-venv build/lock-wheels
	$(PYTHON) -m pip download --quiet --no-deps --only-binary=:all: -r requirements.lock -d build/lock-wheels
	$(PYTHON) tools/hash_lock.py requirements.lock build/lock-wheels
	rm -rf build/lock-wheels

reproduce: $(STAMP)            ## all claims, data/, figures/, gallery
	$(PY) -m paper_repro reproduce

reproduce-extended: $(STAMP)   ## the same with the extended ranges (larger n)
	$(PY) -m paper_repro reproduce --extended

test: $(STAMP)                 ## fast test suite
	$(PY) -m pytest -q -m "not slow and not benchmark"

test-all: $(STAMP)             ## every test, slow ones included
	$(PY) -m pytest -q -m "not benchmark"

report: $(STAMP)               ## the whole suite (slow claim tests too) as reports/tests.html (with each claim's statement, kind, ranges, measured values) + reports/junit.xml
	mkdir -p reports
	$(PY) -m pytest -q -m "not benchmark" --html=reports/tests.html --self-contained-html \
	  --junitxml=reports/junit.xml -o junit_family=xunit1

paper: $(STAMP)                ## the annotated paper paper/index.html (needs ../shared/paper's LaTeX source)
	$(PY) -m paper_repro paper

check-paper: $(STAMP)          ## open paper/index.html in headless chromium: badges resolve, no errors/requests
	$(PY) -m paper_repro.app.check_paper

check-gallery: $(STAMP)        ## open figures/index.html in headless chromium (installed if missing), screenshot
	$(PY) -m paper_repro.app.check_gallery --install

bench: $(STAMP)                ## speed: pytest-benchmark, then the comparison with bezier and mpmath -> reports/
	mkdir -p reports
	$(PY) -m pytest -q -m benchmark --benchmark-enable --benchmark-only --benchmark-json=reports/pytest-benchmark.json tests
	$(PY) -m paper_repro.app.bench

bench-coefficients: $(STAMP)   ## accuracy (float64 vs 40 digits, n <= 200) and cost of the normalizing coefficients -> reports/
	mkdir -p reports
	$(PY) -m paper_repro.app.coefficient_accuracy

bench-question1: $(STAMP)      ## Question 1: recovery and proof time per n (1..20, 25, 30; about 15 min) -> reports/
	mkdir -p reports
	$(PY) -m paper_repro.app.q1_timings

figures: $(STAMP)
	$(PY) -m paper_repro figures

lint: $(STAMP)
	$(PY) -m ruff check paper_repro tests

clean:                         ## caches and build products (not data/ or figures/, not the environment)
	rm -rf build .cache .pytest_cache .hypothesis .ruff_cache

distclean: clean               ## also the environment .venv/ (the next target rebuilds it)
	rm -rf $(VENV)
