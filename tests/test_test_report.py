"""`make report`: the claim summary shows statements, kinds, ranges and measured values, linked to the paper."""

import os
from pathlib import Path
from types import SimpleNamespace

from paper_repro.app.test_report import properties_of, summary_html


def _report(props, passed=True):
    return SimpleNamespace(user_properties=list(props.items()), passed=passed)


def test_claim_properties_become_a_row_with_links():
    rec = properties_of(_report({"claim": "dimension", "paper_labels": "united_system, dimension",
                                 "statement": "T_{2n} has delta_n = 3n(n+1)+1 functions", "kind": "proof",
                                 "parameters": '{"n_max": 7}', "measured": '{"n_checked": 7, "mismatches": []}'}))
    assert rec["status"] == "pass" and rec["measured"]["n_checked"] == 7 and rec["paper_ref"] == ["united_system",
                                                                                                  "dimension"]
    page = summary_html({"dimension": rec})
    assert "../figures/index.html#claim-dimension" in page and "../paper/index.html#united_system" in page
    assert "n_checked" in page and "&quot;n_max&quot;: 7" in page and "this run" in page and "<math" in page


def test_failed_claim_is_marked_and_other_tests_are_ignored():
    assert properties_of(_report({"other": "x"})) is None
    rec = properties_of(_report({"claim": "dimension", "measured": "not json"}, passed=False))
    assert rec["status"] == "fail" and rec["measured"] == "not json"


def test_reused_and_rerun_claims_are_told_apart():
    reused = properties_of(_report({"claim": "dimension", "reused": "1", "code": "abc123", "measured": "{}"}))
    rerun = properties_of(_report({"claim": "symmetry", "measured": "{}"}))
    assert reused["reused"] == "code fingerprint abc123" and "reused" not in rerun
    page = summary_html({"dimension": reused, "symmetry": rerun})
    assert "reused (make reproduce, same code)" in page and "code fingerprint abc123" in page
    assert "re-run in this report" in page
    assert "<b>1 claim re-run</b> in this report (symmetry)" in page and "<b>1 reused</b> (dimension)" in page


def test_report_reuses_only_results_of_the_same_code(tmp_path, monkeypatch):
    """What `make report` relies on: a claim result is reused only under the same code fingerprint."""
    from paper_repro.util import cache, registry
    from paper_repro.util.registry import CLAIMS, load_all, run_claim

    load_all()
    monkeypatch.setattr(cache, "CACHE_DIR", tmp_path)
    monkeypatch.delenv(cache.NO_CACHE_ENV, raising=False)
    first, _, _ = run_claim(CLAIMS["dimension"])
    again, _, _ = run_claim(CLAIMS["dimension"])
    assert not first.cached and again.cached and again.measured == first.measured
    monkeypatch.setattr(registry, "code_fingerprint", lambda: "other code")
    other, _, _ = run_claim(CLAIMS["dimension"])
    assert not other.cached  # a changed package is re-run, never served an old result


def test_reuse_is_switched_on_by_make_report_only(monkeypatch):
    import re

    from paper_repro.app.test_report import REUSE_ENV, reuse_certified_results
    from paper_repro.util.io import ROOT

    for value, on in (("", False), ("0", False), ("1", True)):
        monkeypatch.setenv(REUSE_ENV, value)
        assert reuse_certified_results() is on
    make = (ROOT / "Makefile").read_text()
    report = re.search(r"^report:.*?(?=^\S)", make, flags=re.M | re.S).group(0)
    test_all = re.search(r"^test-all:.*?(?=^\S)", make, flags=re.M | re.S).group(0)
    assert f"{REUSE_ENV}=1" in report and REUSE_ENV not in test_all


def test_pages_link_the_report_only_through_the_status_note():
    """The gallery and the annotated paper never link reports/tests.html directly (a dead link until `make report`
    has run): they show report_link_html's note, which the status script of `make report` turns into the link."""
    import inspect

    from paper_repro.app import annotated_paper, gallery
    from paper_repro.app.report_link import report_link_html

    for mod in (gallery, annotated_paper):
        src = inspect.getsource(mod)
        assert 'href="../reports/tests.html"' not in src.replace("\\", "") and "report_link_html(" in src
    assert 'class="test-report"' in report_link_html() and "<a " not in report_link_html()


def test_report_note_becomes_the_link_in_chromium(tmp_path):
    """In a real browser: before `make report` the page says that make report writes the report (no link, no
    console error); after it (the status script written), the note is the link to reports/tests.html."""
    import pytest

    from paper_repro.app import check_gallery
    from paper_repro.app.report_link import report_link_html
    from paper_repro.app.test_report import write_status

    if not (check_gallery.find(check_gallery.CHROMIUM) and check_gallery.find(check_gallery.DRIVER)):
        pytest.skip("no chromium/chromedriver on this machine: run `make check-gallery INSTALL=1`")
    page = tmp_path / "figures" / "index.html"
    page.parent.mkdir()
    page.write_text(f'<!DOCTYPE html><html><body><p id="p">{report_link_html("../")}.</p></body></html>')
    driver = check_gallery.make_driver(800, 600)
    try:
        driver.get(page.as_uri())
        before = driver.execute_script("var p=document.getElementById('p');return [p.textContent,"
                                       "[...p.querySelectorAll('a')].map(a=>a.getAttribute('href'))]")
        console_before, _, _ = check_gallery.console_and_requests(driver)
        write_status(tmp_path / "reports" / "tests.html", {"passed": 3, "failed": 0}, {"dimension": {"reused": "x"}})
        import time

        for attempt in range(10):  # a loaded machine (the suite on every core) may serve the first reload stale
            driver.get(f"{page.as_uri()}?reload={attempt}")
            after = driver.execute_script("var p=document.getElementById('p');return [p.textContent,"
                                          "[...p.querySelectorAll('a')].map(a=>a.getAttribute('href'))]")
            if after[1]:
                break
            time.sleep(0.5)
    finally:
        driver.quit()
    assert "make report writes it" in before[0] and before[1] == [] and console_before == []
    assert after[1] == ["../reports/tests.html"] and "3 passed" in after[0] and "1 reused" in after[0], after


def test_a_report_run_writes_the_status_script(tmp_path):
    """A pytest run with --html (what make report does) leaves reports/tests-status.js beside the report, with the
    counts: the gallery's and the annotated paper's note becomes the link.  The path is given relative to the
    working directory, as the Makefile gives it."""
    import subprocess
    import sys

    import pytest

    pytest.importorskip("pytest_html")
    root = Path(__file__).resolve().parent.parent
    out = tmp_path / "reports" / "tests.html"
    rel = os.path.relpath(out, root)
    proc = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-p", "no:randomly",
                           "tests/test_net_layout.py::test_net_edges_by_hand", f"--html={rel}",
                           "--self-contained-html"], cwd=root, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    status = (tmp_path / "reports" / "tests-status.js").read_text(encoding="utf-8")
    assert "2 passed" in status and "reports/tests.html" in status


def test_real_gallery_links_the_report_once_written(tmp_path):
    """The committed gallery page itself (not a stand-in): after the status script is written, its note is the link."""
    import shutil

    import pytest

    from paper_repro.app import check_gallery
    from paper_repro.app.test_report import write_status

    if not (check_gallery.find(check_gallery.CHROMIUM) and check_gallery.find(check_gallery.DRIVER)):
        pytest.skip(check_gallery.HOW_TO_GET)
    root = Path(__file__).resolve().parent.parent
    if not (root / "figures" / "index.html").is_file():
        pytest.skip("figures/index.html not generated (make reproduce)")
    shutil.copytree(root / "figures", tmp_path / "figures")
    write_status(tmp_path / "reports" / "tests.html", {"passed": 3}, {})
    (tmp_path / "reports" / "tests.html").write_text("<html></html>")
    driver = check_gallery.make_driver(1280, 900)
    try:
        driver.get((tmp_path / "figures" / "index.html").as_uri())
        links = driver.execute_script("return [...document.querySelectorAll('span.test-report a')]"
                                      ".map(a => a.getAttribute('href'))")
        text = driver.execute_script("return document.body.textContent")
    finally:
        driver.quit()
    assert links == ["../reports/tests.html"] and "not built" not in text
