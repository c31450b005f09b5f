"""Shared test set-up: deterministic hypothesis runs (seeded, no deadline)."""

import os

import pytest
from hypothesis import HealthCheck, settings

settings.register_profile("repro", derandomize=True, deadline=None, max_examples=40,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repro"))


# --- make report (pytest-html): what each claim states, its kind, ranges and measured values ---------------------
_CLAIM_RUNS: dict[str, dict] = {}


def pytest_runtest_logreport(report):
    if report.when == "call":
        from paper_repro.app.test_report import properties_of

        rec = properties_of(report)
        if rec is not None:
            _CLAIM_RUNS[rec["id"]] = rec


@pytest.hookimpl(optionalhook=True)
def pytest_html_results_summary(prefix, summary, postfix, session):
    from paper_repro.app.test_report import summary_html

    prefix.append(summary_html(_CLAIM_RUNS))


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
#: count, OpenBLAS kernel or numba target.  ``make test-cpus`` runs them under every OpenBLAS kernel this machine can
#: be forced to (``OPENBLAS_CORETYPE``) and with ``NUMBA_CPU_NAME=generic``; CI runs them under one kernel other
#: than the host's (``make test-bits-other-cpu``).
BITS_TESTS = (
    "tests/test_cpu_bits.py::",
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


def pytest_collection_modifyitems(config, items):
    for item in items:
        if item.nodeid.startswith(BITS_TESTS):
            item.add_marker(pytest.mark.bits)
