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
