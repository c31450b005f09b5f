"""The annotated paper ``paper/index.html`` in a real, headless Chromium (like :mod:`check_gallery`).

Checks: every display, statement and figure carries a badge and every badge has one of the four statuses;
every link of a badge resolves (an anchor of the page, or a file of this repository, and its ``#anchor`` where
it points into another page of the repository); every image loaded; the formulas were laid out (MathML
elements with a non-zero width); no horizontal overflow of the page, and none of any display box (a display
that scrolls or is clipped inside its box), at 1024, 1280 and 1920 px; the badge counts of the page's table
equal the badges in the browser; no console errors; no network request (only ``file://`` URLs).
Screenshots: ``reports/paper-1280-top.png`` (the head of the page), ``reports/paper-1280-erratum.png`` (an
erratum badge opened), ``reports/paper-1280-figure.png`` (a regenerated figure in its place),
``reports/paper-1024-top.png``.

Run: ``python -m paper_repro.app.check_paper [--page paper/index.html]``; exit 0 when every check passes,
1 otherwise, 3 when no Chromium can be had.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
import time
from pathlib import Path
from urllib.parse import unquote, urlparse

from paper_repro.app.check_gallery import CHROMIUM, DRIVER, NO_BROWSER, console_and_requests, find, make_driver
from paper_repro.util.io import ROOT

PAGE = ROOT / "paper" / "index.html"
STATUSES = ("checked", "erratum", "excused", "not yet checked")
_JS_STATE = """
const blocks=[...document.querySelectorAll('.display,.stmt,figure')];
const unbadged=blocks.filter(b=>!b.querySelector('.badges .badge')).map(b=>b.id);
const badges=[...document.querySelectorAll('.badge[data-status]')].map(b=>b.dataset.status);
const links=[...document.querySelectorAll('.badges a, .answers a, .regen a, figure a')].map(a=>a.getAttribute('href'));
const maths=[...document.querySelectorAll('math')];
const boxes=[...document.querySelectorAll('.display')].map(b=>{const m=b.querySelector('.math')||b;
  return {id:b.id, tex:b.dataset.tex, x:m.scrollWidth-m.clientWidth, y:m.scrollHeight-m.clientHeight,
          scale:parseFloat((b.querySelector('.math')||{dataset:{}}).dataset.scale||'1')};});
const table=document.querySelector('table.summary');
const flat=maths.filter(m=>m.getBoundingClientRect().width===0 && m.offsetParent!==null).length;
return {blocks:blocks.length, unbadged:unbadged, badges:badges, links:links, maths:maths.length, flat_math:flat,
        images:[...document.images].map(i=>[i.getAttribute('src'), i.naturalWidth]),
        scroll_width:document.documentElement.scrollWidth, inner_width:window.innerWidth,
        display_overflow:boxes.filter(b=>b.x>1||b.y>1), displays_scaled:boxes.filter(b=>b.scale<1).length,
        smallest_scale:Math.min(1,...boxes.map(b=>b.scale)), page_counts:table?JSON.parse(table.dataset.counts):null};
"""


def resolve(page: Path, href: str, ids: set[str]) -> str | None:
    """None if ``href`` (of ``page``) resolves, else why not."""
    if href.startswith("#"):
        return None if unquote(href[1:]) in ids else f"no anchor {href}"
    u = urlparse(href)
    if u.scheme:
        return f"not a local link: {href}"
    target = (page.parent / unquote(u.path)).resolve()
    if not target.exists():
        return f"missing file {target}"
    if u.fragment and target.suffix == ".html":
        text = target.read_text(encoding="utf-8")
        if not re.search(rf'id="{re.escape(unquote(u.fragment))}"', text):
            return f"no anchor #{u.fragment} in {target.name}"
    return None


def _shot_of(driver, selector: str, path: Path, open_badge: bool = False) -> bool:
    els = driver.find_elements("css selector", selector)
    if not els:
        return False
    el = els[0]
    if open_badge:
        driver.execute_script("arguments[0].open=true", el)
    driver.execute_script("arguments[0].scrollIntoView({block:'center'})", el)
    time.sleep(0.4)
    driver.save_screenshot(str(path))
    return True


def check(page: Path = PAGE, shots: Path = ROOT / "reports") -> dict:
    shots.mkdir(parents=True, exist_ok=True)
    res: dict = {"overflow": {}}
    ids = set(re.findall(r'id="([^"]+)"', page.read_text(encoding="utf-8")))
    for width in (1920, 1024, 1280):  # 1280 last: its state is the one reported
        driver = make_driver(width, 900)
        try:
            driver.set_script_timeout(90)
            driver.get(page.resolve().as_uri())
            driver.execute_async_script(
                "var done=arguments[0];var imgs=[...document.images];"
                "Promise.all(imgs.map(i=>i.complete?1:new Promise(r=>{i.onload=i.onerror=r;})))"
                ".then(()=>setTimeout(done,500));")
            state = driver.execute_script(_JS_STATE)
            res["overflow"][width] = state["scroll_width"] - state["inner_width"]
            # every display box, not only the page: a display that scrolls (or is clipped) inside its box
            res.setdefault("display_overflow", {})[width] = [f"{b['id']} (lines {b['tex']}): {b['x']} px wide, "
                                                            f"{b['y']} px tall too much" for b in state.pop(
                                                                "display_overflow")]
            res.setdefault("displays_scaled", {})[width] = [state.pop("displays_scaled"),
                                                           round(state.pop("smallest_scale"), 2)]
            if width in (1024, 1280):
                driver.save_screenshot(str(shots / f"paper-{width}-top.png"))
            if width == 1280:
                _shot_of(driver, '.badge[data-status="erratum"]', shots / "paper-1280-erratum.png", open_badge=True)
                _shot_of(driver, 'figure[id="fig:torus"]', shots / "paper-1280-figure.png")
                _shot_of(driver, ".stmt.question", shots / "paper-1280-question.png")
                console, requests, external = console_and_requests(driver)
                res.update(state)
                res.update(console_errors=console, requests=len(requests), external_requests=external)
        finally:
            driver.quit()
    res["bad_links"] = sorted({f"{h}: {why}" for h in res.pop("links") if (why := resolve(page, h, ids))})
    res["bad_status"] = sorted({s for s in res["badges"] if s not in STATUSES})
    counts = {s: res["badges"].count(s) for s in STATUSES}
    res["badges"] = counts
    # one tally: the badges counted in the browser are the page's own table (and its header)
    res["counts_disagree"] = None if res.get("page_counts") == counts else {"page": res.get("page_counts"),
                                                                              "browser": counts}
    res["images_not_loaded"] = [src for src, w in res.pop("images") if not w]
    return res


def passed(res: dict) -> bool:
    return (res["blocks"] > 0 and not res["unbadged"] and sum(res["badges"].values()) >= res["blocks"]
            and not res["bad_links"] and not res["bad_status"] and not res["images_not_loaded"]
            and res["maths"] > 0 and not res["flat_math"] and all(v <= 0 for v in res["overflow"].values())
            and not any(res["display_overflow"].values()) and not res["counts_disagree"]
            and not res["console_errors"] and not res["external_requests"])


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m paper_repro.app.check_paper")
    ap.add_argument("--page", type=Path, default=PAGE)
    args = ap.parse_args(argv)
    if not (find(CHROMIUM) and find(DRIVER)):
        print("check-paper: no chromium/chromedriver on this machine (`make check-gallery INSTALL=1` installs them)",
              file=sys.stderr)
        return NO_BROWSER
    if not args.page.exists():
        print(f"check-paper: {args.page} does not exist (make paper; it needs the paper's LaTeX source)",
              file=sys.stderr)
        return 1
    res = check(args.page)
    ok = passed(res)
    print(json.dumps(res, indent=2, default=str))
    print("check-paper: " + ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
