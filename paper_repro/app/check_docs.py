"""`make check-docs`: no page wider than its window, in headless Chromium.

Every page of the documentation site (``docs/_build/html``, built by ``make docs``), the test report
(``reports/tests.html``, ``make report``), the gallery (``figures/index.html``) and the annotated paper
(``paper/index.html``, ``make paper``) -- those that exist -- is opened at window widths of 1024, 1280 and 1920 px.
A page overflows when the document is wider than the window, or when an element reaches past the window's right
edge without a box of its own that scrolls or clips it (a long formula, a wide table or code block must wrap, or
scroll inside its own box).  With ``--shots``, screenshots at 1280 px go to ``build/check-docs/<page>.png``.

Needs Chromium and chromedriver (:mod:`paper_repro.app.check_gallery` says how to get them); exit status 1 when a
page overflows, 2 when no browser is found.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from paper_repro.app.check_gallery import CHROMIUM, DRIVER, HOW_TO_GET, find, make_driver

ROOT = Path(__file__).resolve().parents[2]
WIDTHS = (1024, 1280, 1920)
#: Sphinx's generated index and search pages carry no content of ours.
SKIP = {"genindex.html", "search.html", "py-modindex.html"}

#: Calls back once MathJax (where the page has it) has typeset the page and the page has been laid out again.
_SETTLED = r"""
const done = arguments[arguments.length - 1];
const later = () => requestAnimationFrame(() => requestAnimationFrame(() => done(true)));
let tries = 0;
(function wait() {
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) MathJax.startup.promise.then(later);
  else if (document.querySelector('script[src*="mathjax"]') && tries++ < 100) setTimeout(wait, 50);
  else later();
})();
"""

#: Returns [document width, window width, [(element, its right edge), ...]] for elements reaching past the window
#: whose overflow no ancestor scrolls or clips.
_MEASURE = r"""
const W = document.documentElement.clientWidth;
function clipped(el) {
  // MathJax's assistive MathML is clipped to 1px for screen readers; an off-canvas drawer is position: fixed
  if (el.closest('mjx-assistive-mml')) return true;
  for (let a = el.parentElement; a && a !== document.body && a !== document.documentElement; a = a.parentElement) {
    const s = getComputedStyle(a);
    if (s.position === 'fixed') return true;
    if (['auto', 'scroll', 'hidden', 'clip'].includes(s.overflowX) && a.getBoundingClientRect().right <= W + 1)
      return true;
  }
  return false;
}
function name(el) {
  let s = el.tagName.toLowerCase();
  if (el.id) s += '#' + el.id;
  if (el.className && typeof el.className === 'string') s += '.' + el.className.trim().split(/\s+/).join('.');
  return s + ' "' + (el.textContent || '').trim().slice(0, 60) + '"';
}
const out = [];
for (const el of document.body.querySelectorAll('*')) {
  const r = el.getBoundingClientRect();
  if (r.width === 0 || r.right <= W + 1) continue;
  const s = getComputedStyle(el);
  if (s.visibility === 'hidden' || s.display === 'none' || s.position === 'fixed') continue;
  if (clipped(el)) continue;
  out.push([name(el), Math.round(r.right)]);
}
return [document.documentElement.scrollWidth, W, out.slice(0, 8)];
"""


def pages(root: Path = ROOT) -> list[Path]:
    """The pages to check that exist in this clone."""
    site = root / "docs" / "_build" / "html"
    out = sorted(p for p in site.rglob("*.html") if p.name not in SKIP and "_static" not in p.parts
                 and "_modules" not in p.parts) if site.is_dir() else []
    return out + [p for p in (root / "reports" / "tests.html", root / "figures" / "index.html",
                              root / "paper" / "index.html") if p.is_file()]


def shot_name(page: Path) -> str:
    """``docs/_build/html/guide/api.html`` -> ``docs-guide-api``; ``figures/index.html`` -> ``figures-index``."""
    page = page.resolve()
    site = (ROOT / "docs" / "_build" / "html").resolve()
    if page.is_relative_to(site):
        return "-".join(("docs", *page.relative_to(site).with_suffix("").parts))
    return "-".join(page.relative_to(ROOT).with_suffix("").parts) if page.is_relative_to(ROOT) else page.stem


def check(paths: list[Path], widths: tuple[int, ...] = WIDTHS, shots: Path | None = None) -> list[dict]:
    """One record per page and width: ``{"page", "width", "document", "window", "overflow": [(element, right)]}``;
    ``ok`` when the document fits and no element overflows."""
    driver = make_driver(1280, 900)
    driver.set_script_timeout(30)
    records = []
    try:
        for page in paths:
            for width in widths:
                driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                                       {"width": width, "height": 900, "deviceScaleFactor": 1, "mobile": False})
                driver.get(page.resolve().as_uri())
                driver.execute_async_script(_SETTLED)  # formulas typeset, marked, laid out
                doc, win, over = driver.execute_script(_MEASURE)
                records.append({"page": str(page), "width": width, "document": doc, "window": win,
                                "overflow": over, "ok": doc <= win and not over})
                if shots is not None and width == 1280:
                    shots.mkdir(parents=True, exist_ok=True)
                    driver.save_screenshot(str(shots / (shot_name(page) + ".png")))
    finally:
        driver.quit()
    return records


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m paper_repro.app.check_docs", description=__doc__.splitlines()[0])
    ap.add_argument("pages", nargs="*", type=Path, help="pages to check (default: every page that exists)")
    ap.add_argument("--shots", action="store_true", help="screenshots at 1280 px in build/check-docs/")
    args = ap.parse_args(argv)
    if not (find(CHROMIUM) and find(DRIVER)):
        print(f"check-docs: {HOW_TO_GET}.", file=sys.stderr)
        return 2
    paths = args.pages or pages()
    records = check(paths, shots=ROOT / "build" / "check-docs" if args.shots else None)
    bad = [r for r in records if not r["ok"]]
    for r in bad:
        print(f"{r['page']} at {r['width']} px: document {r['document']} px wide in a {r['window']} px window; "
              + "; ".join(f"{el} reaches {right} px" for el, right in r["overflow"][:3]))
    print(f"check-docs: {len(paths)} pages at {', '.join(map(str, WIDTHS))} px: "
          f"{len(bad)} of {len(records)} overflow")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
