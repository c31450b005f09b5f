"""`make check-gallery`: open ``figures/index.html`` in a real, headless Chromium and check what a reader sees.

Checks: every image loaded (``naturalWidth > 0``); every 3D view drew (its WebGL canvas, photographed,
is not blank); no console errors; no network request (every request is a ``file://`` URL of this
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
        drawn = {}
        for v in views:
            driver.execute_script("arguments[0].scrollIntoView()", v)
            canvases = v.find_elements("css selector", "canvas")
            png = v.screenshot_as_png
            (screenshot.parent / f"gallery-{v.get_attribute('id')}.png").write_bytes(png)
            drawn[v.get_attribute("id")] = bool(canvases) and not _blank(png)
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
            "views_blank": [k for k, ok in drawn.items() if not ok], "console_errors": console,
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
          and not res["console_errors"] and not res["external_requests"])
    print(json.dumps(res, indent=2))
    print("check-gallery: " + ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
