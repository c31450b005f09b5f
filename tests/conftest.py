"""Shared test set-up: deterministic hypothesis runs (seeded, no deadline)."""

import os

import pytest
from hypothesis import HealthCheck, settings

settings.register_profile("repro", derandomize=True, deadline=None, max_examples=40,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repro"))


def pytest_configure(config):
    config.addinivalue_line("markers", "other_env: builds another environment (a wheel's venv, other interpreters), "
                            "minutes each: run by make test-all, make test-wheel, make test-pythons; left out of "
                            "make report")


# --- make report (pytest-html): what each claim states, its kind, ranges and measured values ---------------------
_CLAIM_RUNS: dict[str, dict] = {}


def pytest_runtest_logreport(report):
    if report.when == "call":
        from paper_repro.app.test_report import properties_of

        rec = properties_of(report)
        if rec is not None:
            _CLAIM_RUNS[rec["id"]] = rec


def pytest_sessionfinish(session, exitstatus):
    """With ``--html`` (``make report``): the status script beside the report, which turns the gallery's and the
    annotated paper's note "make report writes it" into the link."""
    html_path = session.config.getoption("htmlpath", None)
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
