# paper_repro: `make reproduce` and `make test` need nothing but python3 (>= 3.11);
# the first run creates .venv and installs the package with its dependencies, later runs reuse it.
PYTHON ?= python3
comma := ,
# One environment per interpreter: .venv for the reference CPython 3.11 (byte-identical figures), .venv-3.12 etc.
PYVER  := $(if $(strip $(PYTHON)),$(shell $(PYTHON) -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null))
VENV   ?= $(if $(filter-out 3.11,$(PYVER)),.venv-$(PYVER),.venv)
PY     := $(VENV)/bin/python
# An interpreter that does not run, or is older than 3.11, stops every target that needs Python with one sentence
# (before, an empty PYVER silently chose the 3.11 .venv: `make test PYTHON=python3.99` tested 3.11).
ifneq ($(filter-out clean distclean,$(or $(MAKECMDGOALS),default)),)
ifeq ($(strip $(PYTHON)),)
$(error PYTHON is empty; give a Python >= 3.11$(comma) e.g. PYTHON=python3.11$(comma) or leave PYTHON unset for python3)
endif
ifeq ($(shell $(PYTHON) -c 'import sys; sys.exit(0 if sys.version_info >= (3, 11) else 1)' >/dev/null 2>&1 && echo ok),)
_PYV := $(shell $(PYTHON) -V 2>&1 | head -n 1)
$(error $(if $(filter Python 3.%,$(_PYV)),paper_repro needs Python >= 3.11$(comma) but '$(PYTHON)' is $(_PYV); run with PYTHON=python3.11 (or newer),PYTHON=$(PYTHON) does not run (no such interpreter); give a Python >= 3.11$(comma) e.g. PYTHON=python3.11))
endif
endif
STAMP  := $(VENV)/.installed-stamp
# bezier has no CPython 3.13 wheel: there pip builds its locked sdist as pure Python (no compiled speed-up;
# bezier's setup refuses an untested Python unless told); no effect where a wheel is installed
export BEZIER_NO_EXTENSION := True
export BEZIER_IGNORE_VERSION_CHECK := True
# claim results cached by another interpreter are not reused: non-reference versions keep their cache in their venv
ifneq ($(filter-out 3.11,$(PYVER)),)
export PAPER_REPRO_CACHE ?= $(CURDIR)/$(VENV)/cache
endif

.PHONY: check-docs mutate-lines mutate-code test-cpus test-bits-other-cpu test-bits-numpy-dispatch venv lock report paper check-paper check-gallery test-min test-pythons test-wheel docs reproduce reproduce-extended test test-all bench bench-coefficients bench-question1 figures lint clean distclean

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

lock:                          ## refresh requirements.lock from pyproject's ranges (newest that install), hashes for 3.11-3.13
	$(PYTHON) -m venv build/lock-venv
	build/lock-venv/bin/python -m pip install --quiet --disable-pip-version-check '.[dev,docs,fast,dask]'
	build/lock-venv/bin/python -m pip freeze --exclude-editable | grep -v '^paper.repro' > requirements.lock
	rm -rf build/lock-venv build/lock-wheels
	PYTHON=$(PYTHON) sh tools/lock_download.sh requirements.lock build/lock-wheels
	$(PYTHON) tools/hash_lock.py requirements.lock build/lock-wheels/*
	rm -rf build/lock-wheels

reproduce: $(STAMP)            ## all claims, data/, figures/, gallery
	$(PY) -m paper_repro reproduce

reproduce-extended: $(STAMP)   ## the same with the extended ranges (larger n)
	$(PY) -m paper_repro reproduce --extended

# the fast suite runs on every core up to 4 (pytest-xdist; TEST_JOBS=1 runs it in one process)
TEST_JOBS ?= $(shell n=$$(nproc 2>/dev/null || echo 1); [ "$$n" -gt 4 ] && n=4; echo $$n)
test: $(STAMP)                 ## fast test suite (on TEST_JOBS processes, default: the cores, at most 4)
	$(PY) -m pytest -q -m "not slow and not benchmark" -n $(TEST_JOBS) --dist worksteal

# (data/*_extended* come from reproduce-extended; the gallery index.html names the commit and the extended data.)
# OpenBLAS kernels numpy's DYNAMIC_ARCH build can be forced to here (Zen runs the Haswell kernel in this build;
# Sandybridge and Nehalem are pre-AVX2).  The compiled kernel also runs for numba's generic CPU target.
CORETYPES ?= Haswell SkylakeX Zen Sandybridge Nehalem
#: numpy dispatch variants (tools/cpu_bits.py numpy-env): no AVX512 (a Haswell-like CPU), only the baseline (SSE4.2)
NUMPY_VARIANTS ?= avx2 baseline
test-cpus: $(STAMP)            ## byte-sensitive tests (-m bits) and a cold `reproduce` data comparison under every OpenBLAS kernel, numba's generic target and numpy's SIMD dispatch limited to AVX2 and to the baseline -> reports/cpu_bits.md (about 1.5 hours)
	mkdir -p build/cpus reports
	$(PY) tools/cpu_bits.py compute build/cpus/host.json
	@for k in $(CORETYPES); do echo "== OPENBLAS_CORETYPE=$$k"; \
	  OPENBLAS_CORETYPE=$$k $(PY) -m pytest -q -p no:cacheprovider -m bits || exit 1; \
	  OPENBLAS_CORETYPE=$$k $(PY) tools/cpu_bits.py compute build/cpus/openblas-$$k.json || exit 1; done
	@echo "== NUMBA_CPU_NAME=generic"
	NUMBA_CPU_NAME=generic PAPER_REPRO_CACHE=$(CURDIR)/build/cpus/cache-generic $(PY) -m pytest -q -p no:cacheprovider -m bits
	NUMBA_CPU_NAME=generic PAPER_REPRO_CACHE=$(CURDIR)/build/cpus/cache-generic $(PY) tools/cpu_bits.py compute build/cpus/numba-generic.json
	rm -f build/cpus/numpy-*.json
	@for v in $(NUMPY_VARIANTS); do d=$$($(PY) tools/cpu_bits.py numpy-env $$v) || continue; \
	  echo "== numpy dispatch $$v: NPY_DISABLE_CPU_FEATURES='$$d'"; \
	  NPY_DISABLE_CPU_FEATURES="$$d" PAPER_REPRO_CACHE=$(CURDIR)/build/cpus/cache-numpy-$$v $(PY) -m pytest -q -p no:cacheprovider -m bits || exit 1; \
	  NPY_DISABLE_CPU_FEATURES="$$d" PAPER_REPRO_CACHE=$(CURDIR)/build/cpus/cache-numpy-$$v $(PY) tools/cpu_bits.py compute build/cpus/numpy-$$v.json || exit 1; done
	$(PY) tools/cpu_bits.py compare build/cpus/host.json build/cpus/openblas-*.json build/cpus/numba-generic.json $$(ls build/cpus/numpy-*.json 2>/dev/null) --report reports/cpu_bits.md
	@for k in $(CORETYPES); do echo "== make reproduce, cold, OPENBLAS_CORETYPE=$$k"; rm -rf build/cpus/reproduce-$$k; \
	  OPENBLAS_CORETYPE=$$k PAPER_REPRO_NO_CACHE=1 $(PY) -m paper_repro reproduce --out build/cpus/reproduce-$$k >/dev/null || exit 1; \
	  diff -r -x '*_extended*' data build/cpus/reproduce-$$k/data && \
	  diff -r -x index.html figures build/cpus/reproduce-$$k/figures || \
	  { echo "test-cpus: data/ or figures/ differ under OPENBLAS_CORETYPE=$$k"; exit 1; }; done
	@for v in $(NUMPY_VARIANTS); do d=$$($(PY) tools/cpu_bits.py numpy-env $$v) || continue; \
	  echo "== make reproduce, cold, numpy dispatch $$v (NPY_DISABLE_CPU_FEATURES='$$d')"; rm -rf build/cpus/reproduce-numpy-$$v; \
	  NPY_DISABLE_CPU_FEATURES="$$d" PAPER_REPRO_NO_CACHE=1 $(PY) -m paper_repro reproduce --out build/cpus/reproduce-numpy-$$v >/dev/null || exit 1; \
	  diff -r -x '*_extended*' data build/cpus/reproduce-numpy-$$v/data && \
	  diff -r -x index.html figures build/cpus/reproduce-numpy-$$v/figures || \
	  { echo "test-cpus: data/ or figures/ differ under numpy dispatch $$v"; exit 1; }; done
	@echo "test-cpus: same bits under $(CORETYPES), numba's generic target and numpy dispatch $(NUMPY_VARIANTS) (reports/cpu_bits.md)"

# CI: the byte-sensitive subset under one OpenBLAS kernel other than the host's
test-bits-other-cpu: $(STAMP)  ## the byte-sensitive tests under an OpenBLAS kernel other than the host's
	@host=$$($(PY) -c 'import numpy, threadpoolctl; numpy.ones(2) @ numpy.ones(2); print([i["architecture"] for i in threadpoolctl.threadpool_info() if i["user_api"] == "blas"][0])'); \
	k=Sandybridge; [ "$$host" = Sandybridge ] && k=Haswell; echo "== byte-sensitive tests: host kernel $$host, forced OPENBLAS_CORETYPE=$$k"; \
	OPENBLAS_CORETYPE=$$k $(PY) -m pytest -q -p no:cacheprovider -m bits

# CI: the byte-sensitive subset with numpy's run-time SIMD dispatch limited as on other CPUs (NPY_DISABLE_CPU_FEATURES:
# avx2 = no AVX512, so no Intel SVML exp/log/power; baseline = SSE4.2 on x86-64); a variant that does not apply to the
# numpy build (avx2 off x86-64) is skipped.  Each run has its own cache, so nothing computed by the host is reused.
test-bits-numpy-dispatch: $(STAMP)  ## the byte-sensitive tests with numpy's SIMD dispatch limited to AVX2 and to the baseline
	@for v in $(NUMPY_VARIANTS); do d=$$($(PY) tools/cpu_bits.py numpy-env $$v) || continue; \
	  echo "== byte-sensitive tests, numpy dispatch $$v: NPY_DISABLE_CPU_FEATURES='$$d'"; \
	  NPY_DISABLE_CPU_FEATURES="$$d" PAPER_REPRO_CACHE=$(CURDIR)/build/cpus/cache-numpy-$$v $(PY) -m pytest -q -p no:cacheprovider -m bits || exit 1; done

mutate-lines: $(STAMP)         ## blank and mutate every checked line; each check must fail -> reports/mutate_lines.{md,json}
	$(PY) tools/mutate_lines.py --out reports

mutate-code: $(STAMP)          ## mutation test of the core and surfaces modules -> reports/mutate_code.{md,json} (10 seeded mutants a module, one worker: about 1 h; --resume keeps mutants already killed on unchanged code)
	$(PY) tools/mutate_code.py --per-module 10 --jobs 1 --resume --out reports

test-all: $(STAMP)             ## every test, slow ones included
	$(PY) -m pytest -q -m "not benchmark"

# bezier (a dev tool for cross-checks) needs numpy >= 2, above the lowest numpy allowed: left out here, its tests skip.
# The claims run without the cache of other environments (PAPER_REPRO_CACHE inside the min venv).
test-min:                      ## the fast suite with the lowest versions pyproject.toml allows (requirements-min.txt)
	rm -rf build/min-venv
	$(PYTHON) -m venv build/min-venv
	build/min-venv/bin/python -m pip install --quiet --disable-pip-version-check --only-binary=:all: \
	  -c requirements-min.txt -e '.[fast]' pytest hypothesis pytest-benchmark pytest-html selenium
	build/min-venv/bin/python -m pip check
	build/min-venv/bin/python -m pip freeze | grep -iE '^(numpy|scipy|mpmath|python.flint|matplotlib|tqdm|meshio|plotly|latex2mathml|platformdirs|threadpoolctl|numba)=='
	PAPER_REPRO_CACHE=$(CURDIR)/build/min-venv/cache build/min-venv/bin/python -m pytest -q \
	  -m "not slow and not benchmark" -p no:cacheprovider
	PAPER_REPRO_CACHE=$(CURDIR)/build/min-venv/cache build/min-venv/bin/python -m paper_repro claims \
	  --only limit_formula bezier_conversion dimension symmetry

# the other supported interpreters: those on PATH, or PYTHONS="path/to/python3.12 path/to/python3.13"
# (per name: the one on PATH if it runs -- a pyenv shim of a version that is not selected does not -- else
# pyenv's own build; one `command -v` per name, since dash prints only the first of several)
_runs = $(shell $(1) -c '' >/dev/null 2>&1 && echo $(1))
_find = $(or $(call _runs,$(shell command -v $(1) 2>/dev/null)),$(call _runs,$(firstword $(wildcard $(HOME)/.pyenv/versions/*/bin/$(1)))))
PYTHONS ?= $(strip $(foreach p,python3.12 python3.13,$(call _find,$(p))))
test-pythons:                  ## the fast suite on every other supported interpreter found (python3.12, python3.13)
	@if [ -z "$(strip $(PYTHONS))" ]; then echo "test-pythons: no python3.12 or python3.13 found (set PYTHONS=...)"; fi
	@for p in $(PYTHONS) ""; do [ -n "$$p" ] || continue; \
	  $$p -c '' >/dev/null 2>&1 || { echo "test-pythons: $$p does not run; give interpreters that do, e.g. PYTHONS=\"python3.12 python3.13\"." >&2; exit 1; }; done
	@for p in $(PYTHONS) ""; do [ -n "$$p" ] || continue; echo "== make test PYTHON=$$p"; \
	  $(MAKE) --no-print-directory test PYTHON=$$p || exit 1; done

test-wheel: $(STAMP)           ## build the wheel, install it in a fresh venv outside the clone, run it there (slow)
	$(PY) -m pytest -q -m slow tests/test_wheel.py

docs: $(STAMP)                 ## the documentation site, offline -> docs/_build/html
	$(PY) -m sphinx -q -W --keep-going -b html docs docs/_build/html
	@echo "docs: open docs/_build/html/index.html"

# The claim tests reuse what `make reproduce` computed where the claim cache holds it under the same id, parameters
# and code fingerprint (PAPER_REPRO_REPORT_REUSE=1; the report says which were reused and which re-run); the tests
# that build other environments (other_env: make test-wheel, make test-pythons) are left out, and the report says so.
report: $(STAMP)               ## the suite (slow tests too) as reports/tests.html (each claim's statement, kind, ranges, measured values) + reports/junit.xml
	mkdir -p reports
	PAPER_REPRO_REPORT_REUSE=1 $(PY) -m pytest -q -m "not benchmark and not other_env" \
	  --html=reports/tests.html --self-contained-html --junitxml=reports/junit.xml -o junit_family=xunit1

paper: $(STAMP)                ## the annotated paper paper/index.html (needs ../shared/paper's LaTeX source)
	$(PY) -m paper_repro paper

check-paper: $(STAMP)          ## open paper/index.html in headless chromium: badges resolve, no errors/requests
	$(PY) -m paper_repro.app.check_paper

check-docs: $(STAMP)           ## every docs page, reports/tests.html, the gallery and the annotated paper at 1024/1280/1920 px in headless chromium: none wider than its window (screenshots: build/check-docs/)
	$(PY) -m paper_repro.app.check_docs --shots

check-gallery: $(STAMP)        ## open figures/index.html in headless chromium; installs nothing unless INSTALL=1
	$(PY) -m paper_repro.app.check_gallery $(if $(INSTALL),--install)

# The pole check of Proposition 11.6 (docs/subdivision_for_all_n.md section 11) in a range of about 2 min on an idle
# machine; the full one-off record (n <= 13 with the comparisons to n = 10 and mp at n = 4, 8, 12; n = 14..16) is
# reports/subdivision_pole_check.md and reports/subdivision_pole_check_14_16.md, commands in their first lines.
POLE_CHECK_BENCH ?= 1 2 3 4 5 6 7 8 9 10 11 12 --float --collocation --even --compare-upto 8 --mp 4
bench: $(STAMP)                ## speed: pytest-benchmark, the comparison with bezier and mpmath, subdivision accuracy, the pole check, tessellation -> reports/
	mkdir -p reports
	$(PY) -m pytest -q -m benchmark --benchmark-enable --benchmark-only --benchmark-json=reports/pytest-benchmark.json tests
	$(PY) -m paper_repro.app.bench
	PYTHONPATH=$(CURDIR) $(PY) tools/subdivision_accuracy.py
	PYTHONPATH=$(CURDIR) $(PY) tools/subdivision_pole_check.py $(POLE_CHECK_BENCH) --out reports/subdivision_pole_check_bench.md
	PYTHONPATH=$(CURDIR) $(PY) tools/tessellation_bench.py --out reports/tessellation_bench.md

bench-coefficients: $(STAMP)   ## accuracy (float64 vs 40 digits, n <= 200) and cost of the normalizing coefficients -> reports/
	mkdir -p reports
	$(PY) -m paper_repro.app.coefficient_accuracy

bench-question1: $(STAMP)      ## Question 1: recovery and proof time per n (1..20, 25, 30; about 15 min) -> reports/
	mkdir -p reports
	$(PY) -m paper_repro.app.q1_timings

figures: $(STAMP)
	$(PY) -m paper_repro figures

lint: $(STAMP)                 ## ruff, and mypy on the package (type hints of the public API)
	$(PY) -m ruff check paper_repro tests
	$(PY) -m mypy

clean:                         ## caches and build products (not data/ or figures/, not the environment)
	rm -rf build .cache .pytest_cache .hypothesis .ruff_cache .mypy_cache docs/_build

distclean: clean               ## also the environment .venv/ (the next target rebuilds it)
	rm -rf .venv .venv-3.*
