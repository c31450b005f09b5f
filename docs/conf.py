"""Sphinx configuration of the documentation site (``make docs`` -> docs/_build/html, offline).

Sphinx with autodoc + napoleon (the API reference from the docstrings), MyST for the Markdown pages (every
``docs/*.md`` is included automatically) and the furo theme.  Math is rendered by MathJax 3 served from
``docs/_vendor/mathjax`` (vendored from the npm registry), so the site loads nothing from the network.
The claims table and the errata are generated at build time from ``data/claims.md`` and ``data/errata.json``.
Two local extensions (``docs/_ext``): ``plain_math`` renders the plain-text formulas of the proof pages as MathJax
math (every ``docs/*.md``), ``api_check`` fails the build (``-W``) on a docstring napoleon garbles.
The examples (``docs/examples/plot_*.py``) are run by sphinx-gallery at every build, their printed output and
matplotlib figures shown under each block (``docs/auto_examples``, generated); an example that raises fails the
build.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(HERE / "_ext"))

import paper_repro  # noqa: E402

project = "paper_repro"
author = "paper_repro contributors"
release = version = paper_repro.__version__
extensions = ["sphinx.ext.autodoc", "sphinx.ext.napoleon", "sphinx.ext.mathjax", "myst_parser",
              "sphinx_gallery.gen_gallery", "api_check", "plain_math"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
myst_enable_extensions = ["dollarmath", "amsmath"]
exclude_patterns = ["_build", "_vendor", "_ext", "_css", "README.md", "examples"]
html_theme = "furo"
html_title = f"paper_repro {release}"
html_static_path = ["_vendor", "_css"]
html_css_files = ["paper_repro.css"]   # no page wider than its window (long formulas, tables, code scroll in a box)
html_js_files = ["wide_math.js"]
mathjax_path = "mathjax/tex-chtml.js"  # relative to _static: the vendored copy, never a CDN
html_show_sourcelink = False
autodoc_member_order = "bysource"
autodoc_typehints = "description"
nitpicky = False
sphinx_gallery_conf = {
    "examples_dirs": "examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"/plot_",          # run every example (all are named plot_*.py)
    "run_stale_examples": True,             # at every build, not only when the script changed (the library may)
    "within_subsection_order": "FileNameSortKey",
    "abort_on_example_error": False,        # run them all, then fail the build naming every broken one
    "only_warn_on_example_error": False,
    "download_all_examples": False,
    "write_computation_times": False,
    "show_signature": False,
    "min_reported_time": 1e9,
    "image_scrapers": ("matplotlib",),
    "reset_modules": ("matplotlib",),
    "matplotlib_animations": False,
    "capture_repr": (),
    "remove_config_comments": True,
}
suppress_warnings = ["myst.header", "myst.xref_missing", "docutils", "ref.python", "autodoc.import_object"]


def _generated() -> None:
    """docs/_generated/claims.md and errata.md from the committed results of ``make reproduce``."""
    out = HERE / "_generated"
    out.mkdir(exist_ok=True)
    claims = ROOT / "data" / "claims.md"
    text = (claims.read_text(encoding="utf-8") if claims.exists()
            else "# Claims\n\nNot computed yet: `make reproduce`.\n")
    (out / "claims.md").write_text(text, encoding="utf-8")
    from paper_repro.app.report import errata_markdown

    path = ROOT / "data" / "errata.json"
    errata = json.loads(path.read_text(encoding="utf-8")) if path.exists() else []
    (out / "errata.md").write_text("# Errata of the paper\n\nEach entry compares a verbatim transcription of a "
                                   "printed formula with an independent computation (evidence in "
                                   "`data/errata.json`).\n\n" + errata_markdown(errata), encoding="utf-8")


_generated()

