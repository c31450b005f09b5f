"""The documentation: the tutorial's code runs as written, and the built site works offline in a browser.

The site test builds ``docs/_build/html`` (``make docs``) when Sphinx is installed and opens it in headless
Chromium (skipped, saying why, without Sphinx or a browser): no console error, no request leaving the site,
math rendered by the vendored MathJax.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"


EXAMPLES = sorted((DOCS / "examples").glob("plot_*.py"))


@pytest.mark.parametrize("script", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_example_runs(script, tmp_path, monkeypatch):
    """Every example of the tutorial runs as written (``make docs`` runs them too, and fails on a broken one)."""
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    monkeypatch.chdir(tmp_path)
    try:
        exec(compile(script.read_text(encoding="utf-8"), str(script), "exec"), {"__name__": "__main__"})
    finally:
        plt.close("all")


def test_examples_fit_the_column_and_are_linked():
    """Code of at most 88 characters a line (the column of the site), every example linked from the tutorial,
    and no code block left in the tutorial that the build would not run."""
    assert len(EXAMPLES) >= 8
    wide = [f"{p.name}:{k}" for p in EXAMPLES for k, line in enumerate(p.read_text().splitlines(), 1) if len(line) > 88]
    assert wide == []
    tutorial = (DOCS / "guide" / "tutorial.md").read_text(encoding="utf-8")
    assert [p.stem for p in EXAMPLES if f"auto_examples/{p.stem}.rst" not in tutorial] == []
    assert "```python" not in tutorial
    conf = (DOCS / "conf.py").read_text(encoding="utf-8")
    assert "sphinx_gallery.gen_gallery" in conf and '"only_warn_on_example_error": False' in conf
    assert '"run_stale_examples": True' in conf  # an unchanged script runs again: the library under it may change


def test_every_docs_page_is_in_the_site():
    index = (DOCS / "index.md").read_text(encoding="utf-8")
    assert ":glob:" in index  # every docs/*.md is picked up by the glob toctree


@pytest.mark.slow
def test_site_in_headless_chromium(tmp_path):
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_parser")
    pytest.importorskip("sphinx_gallery")  # runs the examples at every build (the docs extra; in the lock)
    from paper_repro.app import check_gallery

    if not (check_gallery.find(check_gallery.CHROMIUM) and check_gallery.find(check_gallery.DRIVER)):
        pytest.skip(check_gallery.HOW_TO_GET)
    out = tmp_path / "html"
    proc = subprocess.run([sys.executable, "-m", "sphinx", "-q", "-b", "html", str(DOCS), str(out)],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr[-3000:]
    import paper_repro

    api = (out / "guide" / "api.html").read_text(encoding="utf-8")
    assert [n for n in paper_repro.__all__ if f'id="paper_repro.{n}"' not in api] == []  # every public name
    for md in DOCS.glob("*.md"):  # every page of docs/ is in the site
        if md.name != "index.md":
            assert (out / md.with_suffix(".html").name).is_file(), md.name
    proofs = [out / md.with_suffix(".html").name for md in sorted(DOCS.glob("*.md")) if md.name != "index.md"]
    res = check_docs_site(out / "index.html", out / "guide" / "tutorial.html", *proofs)  # proofs: no merror
    assert res["console_errors"] == [] and res["external_requests"] == [], res
    assert res["math_rendered"] > 0 and res["math_errors"] == 0, res


def check_docs_site(*pages: Path) -> dict:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    from paper_repro.app import check_gallery

    opts = webdriver.ChromeOptions()
    opts.binary_location = check_gallery.find(check_gallery.CHROMIUM)
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"):
        opts.add_argument(arg)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    driver = webdriver.Chrome(service=Service(check_gallery.find(check_gallery.DRIVER)), options=opts)
    console, external, rendered, errors = [], [], 0, 0
    try:
        for page in pages:
            driver.get(page.resolve().as_uri())
            for _ in range(100):
                done = driver.execute_script("return !!(window.MathJax && MathJax.startup && MathJax.startup.promise"
                                             " && document.querySelectorAll('mjx-container').length)")
                if done:
                    break
                driver.implicitly_wait(0.1)
                import time

                time.sleep(0.1)
            rendered += driver.execute_script("return document.querySelectorAll('mjx-container').length")
            errors += driver.execute_script("return document.querySelectorAll('mjx-merror, merror').length")
            console += [e["message"] for e in driver.get_log("browser") if e["level"] == "SEVERE"]
            import json

            for entry in driver.get_log("performance"):
                msg = json.loads(entry["message"])["message"]
                if msg.get("method") == "Network.requestWillBeSent":
                    url = msg["params"]["request"]["url"]
                    if not url.startswith(("file://", "data:", "about:")):
                        external.append(url)
    finally:
        driver.quit()
    return {"console_errors": console, "external_requests": external, "math_rendered": rendered,
            "math_errors": errors}


def test_check_gallery_installs_nothing_unless_asked(monkeypatch, capsys):
    from paper_repro.app import check_gallery

    calls = []
    monkeypatch.setattr(check_gallery, "find", lambda names: None)
    monkeypatch.setattr(check_gallery.subprocess, "run", lambda *a, **k: calls.append(a))
    assert check_gallery.main(["--page", "x.html"]) == check_gallery.NO_BROWSER
    assert calls == []
    assert "INSTALL=1" in capsys.readouterr().err
    assert check_gallery.main(["--install", "--page", "x.html"]) == check_gallery.NO_BROWSER
    apt = [c[0] for c in calls if c[0][:2] == ["apt-get", "install"]]
    assert apt == [check_gallery.APT_INSTALL]
    assert "--no-install-recommends" in apt[0] and "--no-upgrade" in apt[0]
    assert set(apt[0][-2:]) == {"chromium", "chromium-driver"}
    assert "installing" in capsys.readouterr().out


def _napoleon_fields(obj, what: str) -> list[str]:
    import inspect

    from sphinx.ext.napoleon import Config
    from sphinx.ext.napoleon.docstring import NumpyDocstring

    doc = inspect.getdoc(obj) or ""
    return NumpyDocstring(doc, Config(napoleon_use_param=True), what=what, obj=obj).lines()


def _api_check():
    sys.path.insert(0, str(DOCS / "_ext"))
    try:
        import api_check
    finally:
        sys.path.remove(str(DOCS / "_ext"))
    return api_check


def _documented_objects():
    """Every object the API reference renders: the package root and the modules named in api.rst."""
    import importlib
    import inspect

    import paper_repro

    objs = {f"paper_repro.{n}": getattr(paper_repro, n) for n in paper_repro.__all__ if n != "__version__"}
    api = (DOCS / "guide" / "api.rst").read_text(encoding="utf-8")
    for module, members in re.findall(r"\.\. automodule:: (\S+)\n   :members:(.*)", api):
        mod = importlib.import_module(module)
        names = [m.strip() for m in members.split(",") if m.strip()] or [
            n for n, o in vars(mod).items() if not n.startswith("_") and getattr(o, "__module__", None) == module]
        objs.update({f"{module}.{n}": getattr(mod, n) for n in names})
    for name in re.findall(r"\.\. autofunction:: (\S+)", api):
        module, _, attr = name.rpartition(".")
        objs[name] = getattr(importlib.import_module(module), attr)
    out = []
    for name, obj in objs.items():
        if inspect.isclass(obj):
            out.append((name, obj, "class"))
            out += [(f"{name}.{m}", f, "method") for m, f in vars(obj).items()
                    if not m.startswith("_") and callable(f) and f.__doc__]
        elif callable(obj):
            out.append((name, obj, "function"))
    return out


def test_no_public_docstring_is_garbled_by_napoleon():
    """Issue 33: Patch's examples after its Parameters section were rendered as ~60 parameters ('7)', 'np', ...).
    Every object of the API reference goes through napoleon here, as in `make docs` (where api_check fails the
    build): every documented parameter is one of the signature's and no field holds a doctest line."""
    check = _api_check()
    objects = _documented_objects()
    assert len(objects) > 60
    bad = {name: check.field_problems(obj, _napoleon_fields(obj, what)) for name, obj, what in objects}
    assert {k: v for k, v in bad.items() if v} == {}


def test_the_api_check_catches_the_old_patch_docstring():
    check = _api_check()

    def garbled(n, alpha):
        """A patch.

        Parameters
        ----------
        n : the order.
        alpha : the shape parameter.

        Control-net order for n = 1 (delta_1 = 7):

        >>> import numpy as np
        >>> net = np.arange(14.0).reshape(7, 2)
        """

    problems = check.field_problems(garbled, _napoleon_fields(garbled, "function"))
    assert any("doctest" in p for p in problems) and any("not in the signature" in p for p in problems), problems


def _plain_math():
    sys.path.insert(0, str(DOCS / "_ext"))
    try:
        import plain_math
    finally:
        sys.path.remove(str(DOCS / "_ext"))
    return plain_math


@pytest.mark.parametrize("text, want", [
    ("For R_{2n,2n−i,j} (Eqs. (8), (9)) and", "For $R_{2n,2n-i,j}$ (Eqs. (8), (9)) and"),
    ("the system T_{2n}^α non-negative", r"the system $T_{2n}^\alpha$ non-negative"),
    ("Write σ = x + y + z and", r"Write $\sigma = x + y + z$ and"),
    ("Δ = {x + y + z = 1, x, y, z ≥ 0}.", r"$\Delta = \{x + y + z = 1, x, y, z \ge  0\}$."),
    ("is (1 + 2cX + X²)^n here", "is $(1 + 2cX + X^{2})^n$ here"),
    ("on 0 < c < 1 (Sturm), so x_f(α) > 0 and", r"on $0 < c < 1$ (Sturm), so $x_f(\alpha) > 0$ and"),
    ("`R_{2n}` in code and $a_b$ as math stay", "`R_{2n}` in code and $a_b$ as math stay"),
    ("times multinomial(r). So", r"times $\operatorname{multinomial}(r)$. So"),
    ("with T̄_f^α = x_f f, and", r"with $\bar{T}_f^\alpha = x_f f$, and"),  # a combining accent is TeX's accent
    ("a bijection π̂ of", r"a bijection $\hat{\pi}$ of"),
])
def test_plain_math_inline(text, want):
    assert _plain_math().convert_inline(text) == want


def test_plain_math_display_and_untouched_blocks():
    pm = _plain_math()
    src = ("Text with T_{2n}.\n\n  sin²(β/2) = sin²(u/2) + sin²(w/2)   whenever u + w = β.          (U)\n\n"
           "```python\nx_1 = a^2\n```\n\n## Heading with R_{2n}\n")
    out = pm.convert(src).split("\n")
    assert out[0] == "Text with $T_{2n}$."
    assert out[2].startswith(r"$$\sin^{2}(\beta/2) = ") and out[2].endswith(r"\tag{U}$$")
    assert r"\text{whenever}" in out[2]
    assert "x_1 = a^2" in out and "## Heading with R_{2n}" in out
    assert pm.convert("<!-- plain-math: off -->\nR_{2n}") == "<!-- plain-math: off -->\nR_{2n}"


class _Text(__import__("html.parser").parser.HTMLParser):
    """The text of a built page outside code, math, scripts and navigation; and how many math elements it has."""

    def __init__(self):
        super().__init__()
        self.stack, self.skip, self.text, self.math = [], 0, [], 0

    def handle_starttag(self, tag, attrs):
        if tag in ("br", "img", "meta", "link", "input", "hr"):
            return
        cls = (dict(attrs).get("class") or "").split()
        skip = tag in ("code", "pre", "script", "style", "nav", "aside", "head") or "math" in cls
        self.math += "math" in cls
        self.stack.append(skip)
        self.skip += skip

    def handle_endtag(self, tag):
        if tag not in ("br", "img", "meta", "link", "input", "hr") and self.stack:
            self.skip -= self.stack.pop()

    def handle_data(self, data):
        if not self.skip:
            self.text.append(data)


def test_proof_pages_render_their_formulas_as_math(tmp_path):
    """Issue 33: the proof pages showed `R_{2n,2n−j,j}` as plain text.  Every docs/*.md page (the proofs, and
    pages added later) is built; none may show an index `x_{..}`/`x_k` or a power `x^k` outside math."""
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_parser")
    pytest.importorskip("sphinx_gallery")  # runs the examples at every build (the docs extra; in the lock)
    out = tmp_path / "html"
    proc = subprocess.run([sys.executable, "-m", "sphinx", "-q", "-W", "--keep-going", "-b", "html", str(DOCS),
                           str(out)], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr[-3000:]
    pages = [md for md in sorted(DOCS.glob("*.md")) if md.name != "index.md"]
    assert {"question1_for_all_n.md", "limit_for_all_n.md"} <= {p.name for p in pages}
    plain = re.compile(r"(?<![A-Za-z])[A-Za-zα-ωΩΔ][′']*_(?:\{|[A-Za-z0-9](?![a-z]))|\^[{(0-9A-Za-zα-ω−]")
    for md in pages:
        parser = _Text()
        parser.feed((out / md.with_suffix(".html").name).read_text(encoding="utf-8"))
        text = " ".join(parser.text)
        left = [text[max(0, m.start() - 30):m.end() + 30] for m in plain.finditer(text)]
        assert left == [], (md.name, left[:5])
        if "for_all_n" in md.name or md.name == "proof_of_closed_forms.md":  # the proof pages carry formulas
            assert parser.math >= 20, (md.name, parser.math)


def _chromium_or_skip():
    from paper_repro.app import check_gallery

    if not (check_gallery.find(check_gallery.CHROMIUM) and check_gallery.find(check_gallery.DRIVER)):
        pytest.skip(check_gallery.HOW_TO_GET)


def test_width_check_finds_an_overflow_and_accepts_a_scroll_box(tmp_path):
    """make check-docs: a formula wider than the window fails; the same inside its own scrolling box passes."""
    _chromium_or_skip()
    from paper_repro.app.check_docs import check

    wide = tmp_path / "wide.html"
    wide.write_text('<!DOCTYPE html><html><body><p><span style="white-space:nowrap">' + "x + " * 600
                    + "</span></p></body></html>")
    boxed = tmp_path / "boxed.html"
    boxed.write_text('<!DOCTYPE html><html><body><div style="overflow-x:auto"><span style="white-space:nowrap">'
                     + "x + " * 600 + "</span></div></body></html>")
    records = check([wide, boxed], widths=(1024,))
    assert [r["ok"] for r in records] == [False, True], records


@pytest.mark.slow
def test_no_page_wider_than_its_window(tmp_path):
    """Every page that exists in this clone (the docs site once `make docs` has run, reports/tests.html once `make
    report` has, the gallery, the annotated paper) at 1024, 1280 and 1920 px."""
    _chromium_or_skip()
    from paper_repro.app.check_docs import check, pages

    found = pages()
    assert any(p.name == "index.html" and p.parent.name == "figures" for p in found)
    bad = [(r["page"], r["width"], r["document"], r["overflow"][:2]) for r in check(found) if not r["ok"]]
    assert bad == []
