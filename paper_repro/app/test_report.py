"""What ``make report`` (pytest-html, ``reports/tests.html``) shows beyond pass/fail: for each claim its statement,
kind, ranges (parameters), measured values and paper labels, linked to the annotated paper and the gallery.

The claim tests (``tests/test_all_claims_slow.py``) record these as user properties of the run itself; the
hooks in ``tests/conftest.py`` put them in a summary table at the top of the report and in a column of the
results table.  Where a claim's test did not run in the session (``-m "not slow"``), its row comes from
``data/claims.json`` and says so.

``make report`` sets :data:`REUSE_ENV`: a claim whose result is in the claim cache under the same id, parameters
and code fingerprint (:func:`paper_repro.util.cache.code_fingerprint`: the sha256 of every source file of the
package) -- as ``make reproduce`` left it -- is reused, not recomputed; the others are re-run (and cached).  The
report says which.  Without it (``make test-all``) every claim is re-run with the cache switched off.

The gallery and the annotated paper show the report's link through
:func:`paper_repro.app.report_link.report_link_html`: until
``make report`` has run in the clone they say that it builds the report (no link to a missing file);
``make report`` writes :data:`STATUS_JS` beside the report, which turns that note into the link.
"""

from __future__ import annotations

import html
import json
import os
from pathlib import Path

from paper_repro.app.report_link import STATUS_JS, status_js
from paper_repro.util.io import DATA

#: Links from reports/tests.html.
GALLERY = "../figures/index.html"
PAPER = "../paper/index.html"
#: Set (to 1) by ``make report``: claim tests reuse results certified by the same code fingerprint.
REUSE_ENV = "PAPER_REPRO_REPORT_REUSE"


def reuse_certified_results() -> bool:
    """Whether claim tests may reuse cached results of the same code (``make report``), i.e. :data:`REUSE_ENV` is
    set to anything but ``''``/``0``.

    >>> import os; os.environ.pop(REUSE_ENV, None) and None; reuse_certified_results()
    False
    """
    return os.environ.get(REUSE_ENV, "") not in ("", "0")


def write_status(html_path: Path, counts: dict[str, int], ran: dict[str, dict]) -> Path:
    """Write :data:`STATUS_JS` beside the report ``html_path``."""
    reused = sum(1 for r in ran.values() if r.get("reused"))
    path = Path(html_path).parent / STATUS_JS
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(status_js(counts, reused, len(ran) - reused), encoding="utf-8")
    return path


def short_json(obj, width: int = 160) -> str:
    """Compact JSON, cut at ``width`` characters (with an ellipsis)."""
    text = json.dumps(obj, ensure_ascii=False, separators=(", ", ": "))
    return text if len(text) <= width else text[: width - 1] + "…"


def measured_html(measured, keys: int = 6) -> str:
    """The first top-level measured values, one a line (each cut short)."""
    if not isinstance(measured, dict):
        return f"<code>{html.escape(short_json(measured, 200))}</code>"
    items = list(measured.items())
    lines = "".join(f'<li><b>{html.escape(str(k))}</b>: <code style="white-space:normal;word-break:break-word">'
                    f"{html.escape(short_json(v, 90))}</code></li>" for k, v in items[:keys])
    more = f"<li>… {len(items) - keys} more</li>" if len(items) > keys else ""
    return f'<ul style="margin:0;padding-left:1.1em">{lines}{more}</ul>'


def claim_row(rec: dict, source: str, index: dict | None = None) -> str:
    """One ``<tr>`` of the summary table: id (to the gallery), labels (to the annotated paper), statement, kind,
    ranges, measured values (short, with the whole JSON folded), status, and where the row comes from."""
    from paper_repro.app.gallery import math_html

    cid = rec["id"]
    labels = rec.get("paper_ref") or []
    index = index or {}
    lab_html = "<br>".join(f'<a href="{PAPER}#{html.escape(lab)}">{html.escape(index.get(lab, lab))}</a>'
                           for lab in labels)
    measured = rec.get("measured", {})
    full = html.escape(json.dumps(measured, indent=1, ensure_ascii=False))
    status = rec.get("status", "?")
    color = "#060" if status == "pass" else "#b00"
    return (f'<tr><td style="overflow-wrap:break-word"><a href="{GALLERY}#claim-{html.escape(cid)}">'
            f"<code>{html.escape(cid)}</code></a></td>"
            f'<td style="overflow-wrap:break-word">{lab_html}</td>'
            f"<td>{math_html(rec.get('statement', ''))}</td>"
            f"<td>{html.escape(rec.get('kind', ''))}"
            f'</td><td><code style="white-space:normal;word-break:break-word">'
            f"{html.escape(short_json(rec.get('parameters', {}), 160))}</code></td>"
            f'<td>{measured_html(measured)}<details><summary>all (JSON)</summary>'
            f'<pre style="max-height:24em;overflow:auto;white-space:pre-wrap">{full}</pre></details></td>'
            f'<td style="color:{color}"><b>{html.escape(status)}</b></td><td>{html.escape(source)}</td></tr>')


def summary_html(ran: dict[str, dict]) -> str:
    """The table at the top of the report: every claim, from this run where its test ran, else from data/."""
    from paper_repro.util.paper_labels import display_of, load_index

    index = {r["label"]: display_of(r["label"]) for r in load_index()}
    stored = json.loads((DATA / "claims.json").read_text()) if (DATA / "claims.json").exists() else []
    ids = list(dict.fromkeys([c["id"] for c in stored] + list(ran)))
    by_id = {c["id"]: c for c in stored}
    rows = []
    for cid in ids:
        if cid in ran and ran[cid].get("reused"):
            rows.append(claim_row(ran[cid], "reused (make reproduce, same code)", index))
        elif cid in ran:
            rows.append(claim_row(ran[cid], "re-run in this report", index))
        else:
            rows.append(claim_row(by_id[cid], "data/claims.json (not re-run)", index))
    reused = sorted(cid for cid, r in ran.items() if r.get("reused"))
    rerun = sorted(cid for cid, r in ran.items() if not r.get("reused"))
    claims_word = "claim" if len(rerun) == 1 else "claims"
    how = (f"<p><b>{len(rerun)} {claims_word} re-run</b> in this report ({html.escape(', '.join(rerun)) or 'none'}); "
           f"<b>{len(reused)} reused</b> ({html.escape(', '.join(reused)) or 'none'}): their results were in the claim "
           "cache under the same id, parameters and code fingerprint (the sha256 of every source file of the "
           f"package: {html.escape(', '.join(sorted({r['reused'] for r in ran.values() if r.get('reused')})))}), "
           "as <code>make reproduce</code> left them, so this code computed them. "
           "<code>make test-all</code> re-runs every claim without the cache.</p>") if ran else ""
    head = "".join(f"<th>{h}</th>" for h in ("claim", "in the paper", "statement", "kind", "ranges (parameters)",
                                            "measured (click for all)", "status", "from"))
    return (f"<h2>Claims: what was checked</h2><p>{len(ran)} of {len(ids)} claims checked in this run, re-run or "
            "reused (the slow claim tests, <code>tests/test_all_claims_slow.py</code>; <code>make report</code> runs "
            "them); "
            f'links: <a href="{PAPER}">the annotated paper</a> (each label), <a href="{GALLERY}">the gallery</a> '
            "(each claim). Kinds: <b>proof</b> (settles the statement for the stated range), <b>exact-evidence</b> "
            "(exact arithmetic at sampled parameters), <b>numeric-evidence</b> (floating point).</p>" + how +
            '<div style="overflow-x:auto"><table style="border-collapse:collapse;font-size:90%;table-layout:fixed;'
            'width:100%;min-width:1000px" border="1" cellpadding="3"><colgroup>'
            + "".join(f'<col style="width:{w}%">' for w in (10, 14, 22, 7, 12, 25, 4, 6))
            + f'</colgroup><tr>{head}</tr>{"".join(rows)}</table></div>')


def properties_of(report) -> dict | None:
    """The claim record a claim test attached to its report (None for other tests)."""
    props = dict(report.user_properties or [])
    if "claim" not in props:
        return None
    rec = {"id": props["claim"], "paper_ref": [s for s in props.get("paper_labels", "").split(", ") if s],
           "statement": props.get("statement", ""), "kind": props.get("kind", ""),
           "status": "pass" if report.passed else "fail"}
    if props.get("reused"):
        rec["reused"] = f"code fingerprint {props.get('code', '?')}"
    for key in ("parameters", "measured"):
        try:
            rec[key] = json.loads(props.get(key, "{}"))
        except ValueError:
            rec[key] = props.get(key)
    return rec
