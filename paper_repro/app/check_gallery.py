"""`make check-gallery`: open ``figures/index.html`` in a real, headless Chromium and check what a reader sees.

Checks: every image loaded (``naturalWidth > 0``); every 3D view drew (its WebGL canvas, photographed,
is not blank); every 3D view's data lies inside its frame at the initial camera (no side of the scene's box has
anything but background within 3 px of it, legend, title and slider hidden for that photograph); a view whose
caption names a legend shows one; a view's title is shown; no console errors; no network request (every
request is a ``file://`` URL of this
repository). A full-page screenshot is saved as ``reports/gallery.png``, and one of each view as
``reports/gallery-view-<name>.png``.  The browser is Debian's
``chromium`` driven by selenium through Debian's ``chromedriver``.  Nothing is installed unless asked:
``--install`` (``make check-gallery INSTALL=1``) installs only those two with
``apt-get install --no-install-recommends --no-upgrade``, saying so first.
Exit status 0 when every check passes, 1 otherwise, 3 when no Chromium can be had
(the test suite skips then, saying so).

Run: ``python -m paper_repro.app.check_gallery [--install] [--page figures/index.html]``.
"""

from __future__ import annotations

import argparse
import io
import json
import shutil
import subprocess
import sys
from pathlib import Path

from paper_repro.app.report_link import STATUS_JS
from paper_repro.util.io import figures_dir, reports_dir

CHROMIUM = ("chromium", "chromium-browser", "google-chrome")
DRIVER = ("chromedriver",)
NO_BROWSER = 3


def find(names: tuple[str, ...]) -> str | None:
    for name in names:
        path = shutil.which(name) or (f"/usr/bin/{name}" if Path(f"/usr/bin/{name}").exists() else None)
        if path:
            return path
    return None


#: What ``--install`` runs (and nothing else): only the browser and its driver, no recommended packages, no
#: upgrade of anything already installed.
APT_INSTALL = ["apt-get", "install", "-y", "-qq", "--no-install-recommends", "--no-upgrade", "chromium",
               "chromium-driver"]
HOW_TO_GET = ("no headless Chromium here: run `make check-gallery INSTALL=1` (as root: apt-get installs only "
              "chromium and chromium-driver) or install them yourself (Debian/Ubuntu: "
              "apt-get install --no-install-recommends chromium chromium-driver)")


def install() -> None:
    """Debian's chromium and chromium-driver with apt-get, only when missing and only when asked (``--install``):
    says first what it will run; ``--no-install-recommends --no-upgrade``, so no other package changes."""
    if find(CHROMIUM) and find(DRIVER):
        print("check-gallery: chromium and chromedriver are installed; nothing to install", flush=True)
        return
    print(f"check-gallery: installing Debian's chromium and chromium-driver: apt-get update, then "
          f"{' '.join(APT_INSTALL)}", flush=True)
    env = {"DEBIAN_FRONTEND": "noninteractive", "PATH": "/usr/sbin:/usr/bin:/sbin:/bin"}
    subprocess.run(["apt-get", "update", "-qq"], check=False, env=env)
    subprocess.run(APT_INSTALL, check=False, env=env)


def _blank(png: bytes) -> bool:
    """Whether a screenshot is a single colour (nothing drawn)."""
    import matplotlib.image as mpimg

    img = mpimg.imread(io.BytesIO(png), format="png")
    return float(img[..., :3].std()) < 0.01


def make_driver(width: int = 1300, height: int = 1000):
    """Headless Chromium (Debian's, through chromedriver) with the browser and network logs on."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    opts = webdriver.ChromeOptions()
    opts.binary_location = find(CHROMIUM)
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--use-angle=swiftshader", "--enable-unsafe-swiftshader", f"--window-size={width},{height}",
                 "--allow-file-access-from-files", "--hide-scrollbars"):
        opts.add_argument(flag)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    return webdriver.Chrome(service=Service(find(DRIVER)), options=opts)


def console_and_requests(driver) -> tuple[list, list[str], list[str]]:
    """(console errors, every requested URL, the requests leaving this machine's files)."""
    # the one optional file: reports/tests-status.js exists only after `make report` (the page then links the
    # report; before, it says that make report writes it), so its absence is no error
    console = [e for e in driver.get_log("browser") if e["level"] in ("SEVERE", "ERROR")
               and not (f"reports/{STATUS_JS}" in e.get("message", "") and "ERR_FILE_NOT_FOUND" in e["message"])]
    requests = []
    for e in driver.get_log("performance"):
        msg = json.loads(e["message"])["message"]
        if msg.get("method") == "Network.requestWillBeSent":
            requests.append(msg["params"]["request"]["url"])
    external = [u for u in requests if not u.startswith(("file://", "data:", "blob:", "about:"))]
    return console, requests, external


#: Per view: its caption (the figure's figcaption), whether a legend is drawn, its layout title and whether shown.
_JS_VIEW_INFO = """var v=arguments[0];var f=v.closest('figure');
var cap=f?(f.querySelector('figcaption')||{}).textContent:'';
var t=(v.layout||{}).title;var text=(t&&typeof t==='object')?t.text:t;
return {caption:(cap||'').toLowerCase(),legend:v.querySelectorAll('g.legend').length>0,title:text||'',
title_shown:[...v.querySelectorAll('.gtitle')].some(e=>e.textContent.trim().length>0)};"""

#: The 3D scene's box in the view (CSS px, relative to the plot's container), with titles, legends and sliders hidden
#: (they may lie over the scene's box; only the data is looked at).
_JS_SCENE_BOX = """var v=arguments[0],hide=arguments[1];var fl=v._fullLayout;
v.querySelectorAll('.infolayer, .menulayer, .modebar-container, .legend')
.forEach(e=>{e.style.visibility=hide?'hidden':'';});
if(!fl||!fl.scene)return null;var s=fl._size,d=fl.scene.domain;
return [s.l+d.x[0]*s.w, s.t+(1-d.y[1])*s.h, (d.x[1]-d.x[0])*s.w, (d.y[1]-d.y[0])*s.h];"""


def frame_sides_touched(img, box: tuple[float, float, float, float], band: int = 3) -> list[str]:
    """The sides of ``box`` (x, y, width, height in pixels of the RGB(A) float image ``img``) where something other
    than the white background lies within ``band`` pixels of the edge: data cut off by the frame (or touching it).

    >>> import numpy as np
    >>> img = np.ones((100, 100, 3)); img[40:60, 40:60] = 0.2
    >>> frame_sides_touched(img, (0, 0, 100, 100)), frame_sides_touched(img, (0, 0, 100, 58))
    ([], ['bottom'])
    """
    x, y, w, h = (int(round(c)) for c in box)
    x0, y0 = max(x, 0), max(y, 0)
    x1, y1 = min(x + w, img.shape[1]), min(y + h, img.shape[0])
    sub = img[y0:y1, x0:x1, :3]
    ink = sub.min(axis=2) < 0.94
    bands = {"top": ink[:band], "bottom": ink[-band:], "left": ink[:, :band], "right": ink[:, -band:]}
    return [side for side, b in bands.items() if b.any()]


def data_outside_frame(driver, view) -> list[str]:
    """The sides of the view's 3D scene where its data, at the initial camera, reaches the frame (screenshot of the
    plot with legend, title and slider hidden)."""
    import matplotlib.image as mpimg

    box = driver.execute_script(_JS_SCENE_BOX, view, True)
    try:
        if box is None:
            return []
        container = view.find_element("css selector", ".svg-container")
        img = mpimg.imread(io.BytesIO(container.screenshot_as_png), format="png")
        ratio = img.shape[1] / max(1.0, container.size["width"])  # device pixels per CSS pixel
        return frame_sides_touched(img, tuple(c * ratio for c in box))
    finally:
        driver.execute_script(_JS_SCENE_BOX, view, False)


def check(page: Path, screenshot: Path) -> dict:
    driver = make_driver()
    try:
        driver.set_script_timeout(90)
        driver.get(page.resolve().as_uri())
        screenshot.parent.mkdir(parents=True, exist_ok=True)
        driver.execute_async_script(
            "var done=arguments[0];var imgs=[...document.images];"
            "Promise.all(imgs.map(i=>i.complete?1:new Promise(r=>{i.onload=i.onerror=r;})))"
            ".then(()=>setTimeout(done,1500));")
        images = driver.execute_script("return [...document.images].map(i=>[i.getAttribute('src'),i.naturalWidth])")
        views = driver.find_elements("css selector", "div.view")
        drawn, clipped, no_legend, untitled = {}, {}, [], []
        for v in views:
            driver.execute_script("arguments[0].scrollIntoView()", v)
            canvases = v.find_elements("css selector", "canvas")
            png = v.screenshot_as_png
            vid = v.get_attribute("id")
            (screenshot.parent / f"gallery-{vid}.png").write_bytes(png)
            drawn[vid] = bool(canvases) and not _blank(png)
            sides = data_outside_frame(driver, v)
            if sides:
                clipped[vid] = sides
            info = driver.execute_script(_JS_VIEW_INFO, v)
            if "legend" in info["caption"] and not info["legend"]:
                no_legend.append(vid)
            if info["title"] and not info["title_shown"]:
                untitled.append(vid)
        console, requests, external = console_and_requests(driver)
        driver.execute_script("window.scrollTo(0, 0)")
        height = driver.execute_script("return document.body.scrollHeight")
        driver.set_window_size(1300, min(int(height), 16000))
        screenshot.parent.mkdir(parents=True, exist_ok=True)
        driver.save_screenshot(str(screenshot))
    finally:
        driver.quit()
    bad_images = [src for src, w in images if not w]
    return {"images": len(images), "images_not_loaded": bad_images, "views": drawn,
            "views_blank": [k for k, ok in drawn.items() if not ok], "views_clipped": clipped,
            "views_caption_names_a_missing_legend": no_legend, "views_title_not_shown": untitled,
            "console_errors": console,
            "requests": len(requests), "external_requests": external, "screenshot": str(screenshot)}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m paper_repro.app.check_gallery")
    ap.add_argument("--install", action="store_true",
                    help="if missing, apt-get install only chromium and chromium-driver (no recommends, no upgrades)")
    ap.add_argument("--page", type=Path, default=figures_dir() / "index.html")
    ap.add_argument("--screenshot", type=Path, default=reports_dir() / "gallery.png")
    args = ap.parse_args(argv)
    if args.install:
        install()
    if not (find(CHROMIUM) and find(DRIVER)):
        print(f"check-gallery: {HOW_TO_GET}.", file=sys.stderr)
        return NO_BROWSER
    res = check(args.page, args.screenshot)
    ok = (res["images"] > 0 and not res["images_not_loaded"] and res["views"] and not res["views_blank"]
          and not res["views_clipped"] and not res["views_caption_names_a_missing_legend"]
          and not res["views_title_not_shown"] and not res["console_errors"] and not res["external_requests"])
    print(json.dumps(res, indent=2))
    print("check-gallery: " + ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
