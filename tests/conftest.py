"""Shared test set-up: deterministic hypothesis runs (seeded, no deadline)."""

import os

import pytest
from hypothesis import HealthCheck, settings

settings.register_profile("repro", derandomize=True, deadline=None, max_examples=40,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repro"))

#: The absolute path of --html (make report), kept from the start of the session.
HTML_PATH = pytest.StashKey[str | None]()


def pytest_configure(config):
    # the report's path, made absolute now: a test that changes the working directory must not move the status
    # script of make report (written at the session's end) away from reports/
    html = config.getoption("htmlpath", None)
    config.stash[HTML_PATH] = os.path.abspath(html) if html else None
    config.addinivalue_line("markers", "other_env: builds another environment (a wheel's venv, other interpreters), "
                            "minutes each: run by make test-all, make test-wheel, make test-pythons; left out of "
                            "make report")
    config.addinivalue_line("markers", "warm_ahead: its module's warm_ahead() fills the disk cache it reads; make "
                            "report runs that in a second process from the start and these tests last")


# --- make report on 2 cores: the heaviest cache-filling work in a second process -----------------------------------
_WARM: list = []


def pytest_collection_modifyitems(session, config, items):
    """`make report` (PAPER_REPRO_REPORT_REUSE): tests marked warm_ahead run last, and their modules' warm_ahead()
    runs from now in a second process (the suite itself is one process: the second core was idle).  The disk
    cache's per-entry lock makes the two share the work: whichever comes first computes an entry, the other
    reads it.  Its output goes to reports/warm_ahead.log."""
    from paper_repro.app.test_report import reuse_certified_results

    _mark_bits(items)
    if not reuse_certified_results():
        return
    warm = [it for it in items if it.get_closest_marker("warm_ahead")]
    if not warm:
        return
    items[:] = [it for it in items if it not in warm] + warm
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    modules = sorted({it.module.__name__ for it in warm})
    code = ("import time; t = time.time(); " + "; ".join(f"import {m}; {m}.warm_ahead()" for m in modules)
            + "; print('warm_ahead done: cpu', round(time.process_time(), 1), 's, wall', "
            "round(time.time() - t, 1), 's')")
    log = root / "reports" / "warm_ahead.log"
    log.parent.mkdir(exist_ok=True)
    with open(log, "w") as out:
        _WARM.append(subprocess.Popen([sys.executable, "-c", code], cwd=root, stdout=out, stderr=subprocess.STDOUT))


# --- make report (pytest-html): what each claim states, its kind, ranges and measured values ---------------------
_CLAIM_RUNS: dict[str, dict] = {}
_OTHER_REUSED: list[str] = []  # tests (not claims) that reused make reproduce's work, e.g. the figure regression


def pytest_runtest_logreport(report):
    if report.when == "call":
        from paper_repro.app.test_report import properties_of

        rec = properties_of(report)
        if rec is not None:
            _CLAIM_RUNS[rec["id"]] = rec
        elif report.passed and dict(report.user_properties or []).get("reused"):
            _OTHER_REUSED.append(report.nodeid)


def pytest_sessionfinish(session, exitstatus):
    """With ``--html`` (``make report``): the status script beside the report, which turns the gallery's and the
    annotated paper's note "make report writes it" into the link.  A warm-ahead process still running (the run
    was cut short) is stopped."""
    for proc in _WARM:
        if proc.poll() is None:
            proc.terminate()
            proc.wait()
    html_path = session.config.stash.get(HTML_PATH, None)
    if not html_path:
        return
    from paper_repro.app.test_report import write_status

    stats = session.config.pluginmanager.get_plugin("terminalreporter").stats
    counts = {k: len([r for r in stats.get(k, []) if getattr(r, "when", "call") in ("call", "setup")])
              for k in ("passed", "failed", "error", "skipped")}
    write_status(html_path, counts, _CLAIM_RUNS)


@pytest.hookimpl(optionalhook=True)
def pytest_html_results_summary(prefix, summary, postfix, session):
    from paper_repro.app.test_report import summary_html

    prefix.append(summary_html(_CLAIM_RUNS))
    if _OTHER_REUSED:
        import html

        prefix.append(f"<p>Also reused from <code>make reproduce</code> (same code fingerprint, same data/, files "
                      f"unchanged; not redrawn): {len(_OTHER_REUSED)} figure regression tests ("
                      + html.escape(", ".join(n.split("[")[-1].rstrip("]") for n in _OTHER_REUSED)) + ").</p>")
    markexpr = session.config.getoption("markexpr", "") or ""
    if "not other_env" in markexpr:
        prefix.append("<p>Left out of this report: the tests that build other environments (marker "
                      "<code>other_env</code>: the wheel installed in a fresh venv, the fast suite on Python 3.12 "
                      "and 3.13), minutes each; <code>make test-wheel</code>, <code>make test-pythons</code> and "
                      "<code>make test-all</code> run them.</p>")


@pytest.hookimpl(optionalhook=True)
def pytest_html_results_table_header(cells):
    cells.insert(2, "<th>claim: statement, kind, measured</th>")


@pytest.hookimpl(optionalhook=True)
def pytest_html_results_table_row(report, cells):
    import html

    from paper_repro.app.test_report import properties_of, short_json

    rec = properties_of(report) if report.when == "call" else None
    text = (f"{html.escape(rec['statement'])} <i>({html.escape(rec['kind'])})</i> measured: "
            f"<code>{html.escape(short_json(rec.get('measured', {}), 200))}</code>") if rec else ""
    cells.insert(2, f"<td>{text}</td>")


#: The byte-sensitive tests (marker ``bits``): results promised to be the same bits for any memory layout, thread
#: count, OpenBLAS kernel, numba target or SIMD code of numpy's ufuncs.  ``make test-cpus`` runs them under every
#: OpenBLAS kernel this machine can be forced to (``OPENBLAS_CORETYPE``), with ``NUMBA_CPU_NAME=generic`` and with
#: numpy's dispatch limited to AVX2 and to the baseline (``NPY_DISABLE_CPU_FEATURES``); CI runs them under one kernel
#: other than the host's (``make test-bits-other-cpu``) and under the numpy variants
#: (``make test-bits-numpy-dispatch``).
BITS_TESTS = (
    "tests/test_cpu_bits.py::",
    "tests/test_numpy_dispatch.py::",
    "tests/test_figures_regression.py::",
    "tests/test_domain_of_validity.py::test_every_point_layout_gives_the_same_values",
    "tests/test_domain_of_validity.py::test_elevation_sums_in_a_fixed_order_whatever_the_cpu",
    "tests/test_fast_kernel.py::test_same_bits_with_one_and_several_threads",
    "tests/test_fast_kernel.py::test_concurrent_calls_from_user_threads",
    "tests/test_fast_jit.py::test_basis_values_are_the_numpy_bits",
    "tests/test_fast_jit.py::test_normals_pass_has_the_general_bits",
    "tests/test_fast_jit.py::test_a_point_has_the_same_bits_alone_in_a_batch_and_with_threads",
    "tests/test_library_api.py::test_alpha_text_everywhere_in_the_api",
)


def _mark_bits(items) -> None:
    for item in items:
        if item.nodeid.startswith(BITS_TESTS):
            item.add_marker(pytest.mark.bits)


def _sigint_state():
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread() or not hasattr(signal, "pthread_sigmask"):
        return None
    return signal.getsignal(signal.SIGINT), signal.SIGINT in signal.pthread_sigmask(signal.SIG_BLOCK, [])


@pytest.fixture(autouse=True)
def _sigint_left_as_found(request):
    """Ctrl-C handling is process state: a test that leaves SIGINT ignored, handled or blocked would silently change
    every later test of the Ctrl-C machinery.  The state is put back after every test, and a test that changed it is
    named in a warning.  (The tests of that machinery set the handler they need themselves: a suite started in the
    background inherits SIGINT ignored.)"""
    import signal
    import warnings

    before = _sigint_state()
    yield
    after = _sigint_state()
    if before is None or after == before:
        return
    signal.signal(signal.SIGINT, before[0])
    signal.pthread_sigmask(signal.SIG_BLOCK if before[1] else signal.SIG_UNBLOCK, [signal.SIGINT])
    warnings.warn(f"{request.node.nodeid} left SIGINT as {after} (was {before}); put back", stacklevel=1)
