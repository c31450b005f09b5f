"""The link to the test report ``reports/tests.html`` as the gallery and the annotated paper show it.

Those pages are generated (and committed) before any ``make report`` has run, so they cannot know whether the
report exists.  They show a note saying that ``make report`` writes it, and load :data:`STATUS_JS` from
``reports/``: ``make report`` writes that script beside the report (not committed), and it replaces the note by the
link and the counts.  Until then the script is missing, the note stays, and no link leads to a missing file.
"""

from __future__ import annotations

import html

#: Written by ``make report`` beside ``reports/tests.html`` (not committed): turns the pages' note into the link.
STATUS_JS = "tests-status.js"


def report_link_html(root: str = "../") -> str:
    """The link to the test report as a generated page (one folder below the clone: ``root = "../"``) shows it.

    Until ``make report`` has run, the page says that ``make report`` builds it; the script :data:`STATUS_JS`
    that ``make report`` writes replaces the note by the link and the counts.

    >>> "make report" in report_link_html() and 'src="../reports/tests-status.js"' in report_link_html()
    True
    """
    return (f'<span class="test-report" data-href="{html.escape(root)}reports/tests.html">test report: not built '
            "in this clone yet; <code>make report</code> writes it (<code>reports/tests.html</code>)</span>"
            f'<script src="{html.escape(root)}reports/{STATUS_JS}"></script>')


def status_js(counts: dict[str, int], reused: int, rerun: int) -> str:
    """The script :data:`STATUS_JS`: every ``span.test-report`` of the page becomes the link, with the counts
    (deterministic: no date).

    >>> "2 passed" in status_js({"passed": 2, "failed": 0}, 1, 0)
    True
    """
    parts = [f"{v} {k}" for k, v in counts.items() if v]
    claims = f"; claims: {reused} reused from make reproduce (same code), {rerun} re-run" if reused + rerun else ""
    text = html.escape(", ".join(parts) + claims)
    return ("document.querySelectorAll('span.test-report').forEach(function(s){s.innerHTML='test report: "
            "<a href=\"'+s.dataset.href+'\">reports/tests.html</a> (make report: " + text.replace("'", "\\'")
            + ")';});\n")
