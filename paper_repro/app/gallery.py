"""The figure gallery ``figures/index.html``: offline, generated from the registries and ``data/``.

Per figure: the paper's caption, its number in the PDF and its label, the claims it belongs to with their
status, the generating function with its parameters, the command that regenerates it, and a SHA-256 of
each file (PNG and SVG) -- all read from ``figures/manifest.json``.  Then: the claims table (statements
with their ranges), the errata table (with severity), the open questions' standing, the paper map, the
benchmark summary, the provenance of the build, and interactive 3D views (torus, Dupin cyclide, a third
order patch with its control net, an alpha slider) drawn by plotly.js, copied from the ``plotly`` Python
package into ``figures/vendor/`` (no CDN, no network).  Formulas are MathML (``latex2mathml``), which
browsers render natively.  Everything is deterministic: reruns give identical bytes.
"""

from __future__ import annotations

import html
import json
import re
import subprocess
from pathlib import Path

import numpy as np

from paper_repro.app.paper_index import display_of, load_index
from paper_repro.app.report_link import report_link_html
from paper_repro.util.io import ROOT, data_dir, figures_dir, in_checkout, output_root, reports_dir, write_text


def vendor_dir() -> Path:
    """``figures/vendor/`` below the output root (plotly.js for the offline gallery)."""
    return figures_dir() / "vendor"

#: Where each open question of Section 7 stands, by the claims that address it.
OPEN_QUESTIONS = [
    ("Question 7.1 (unlabelled in the source): non-negativity, symmetry, closed/recursive formulas of the "
     "normalizing coefficients", ["question1_all_n", "nonnegativity", "nonnegativity_extended",
                                  "normalizing_closed_forms", "general_formulas"],
     "Answered for every n: one formula gives every coefficient, all positive and symmetric, for every α "
     "(docs/question1_for_all_n.md: a hand proof whose lemmas the program checks exactly for n ≤ 12 / 20; the "
     "formula equals the closed forms proven by machine for n ≤ 30). Still open: proofs for every n of the "
     "centre's two end-value simplifications and of the fitted level formulas (checked consequences to n = 60)."),
    ("Question 7.2 (que:open_problem_basis_transformation): the basis transformation between T̄ and V",
     ["transformation_all_n", "basis_transformation", "coincidence", "transformation_closed_forms"],
     "Answered for every n: V in terms of T̄ by a generating function, T̄ in terms of V by the binomial expansion, "
     "for every α (docs/transformation_for_all_n.md, a hand proof; equal to exact solves for n ≤ 7 and, as a "
     "polynomial identity, to the machine-proven closed forms for n ≤ 4). Still open: the observed largest power "
     "3n − 1 of s in the denominators of N⁻¹ (n ≤ 4; the formula bounds it by 3n)."),
    ("Question 7.3 (que:limiting_case): the α → 0 limit of the patches", ["bernstein_limit", "bezier_limit_degree",
                                                                        "bezier_conversion", "limit_formula"],
     "Nothing: answered for every n, polynomial and rational patches, with explicit convex conversion weights "
     "(written proof docs/limit_for_all_n.md, its lemmas checked exactly to n = 40)."),
    ("Order elevation and the products of the text after Question 7.1 (Examples 7.1, 7.2)",
     ["elevation_all_n", "pairwise_products_all_n", "derivative_all_n", "order_elevation", "elevation_closed_forms"],
     "Answered for every n: elevation in closed form, a convex combination for every α; every product of a member of "
     "order n with one of order 1 -- B̄_{2,2,0}, Ḡ_{2,1,0}, B̄_{2,1,0} among them -- with non-negative coefficients, "
     "giving the recurrence of the coefficients and their inherited symmetry and positivity "
     "(docs/elevation_and_derivative_for_all_n.md, hand proofs). Still open: whether E factors into corner-cutting "
     "steps; the observed 9n − 2 non-zeros per row of E (n ≤ 15)."),
    ("Beyond the paper (issue 38): midpoint subdivision and joins", ["subdivision_all_n", "joins_all_n"],
     "Proven for every n and α: the restriction to each midpoint sub-triangle is an order-n patch with parameter α/2, "
     "net S_k P (docs/subdivision_for_all_n.md, a hand proof, refereed cold); n = 1, 2: S_k in closed form "
     "for every α, with negative entries (not corner cutting); C0/C1/G1 joins with the point-reflected neighbour as "
     "linear conditions for every n, the edge coefficients in closed form (docs/joins_for_all_n.md); the "
     "torus and the cyclide pieces of Section 6 join C1 (exactly, at sampled rational α; the cyclide through its "
     "homogeneous nets). Proven for every n: a negative corner entry (Corollary W), so midpoint subdivision is "
     "not corner cutting; no Bézier-type de Casteljau step at the sampled α (exact certificates, n ≤ 4). "
     "S_k is analytic and even at α = 0 for n ≤ 16 (an exact, computer-assisted check of Proposition 11.6's "
     "condition; evidence beyond). Adaptive tessellation within a tolerance: the bound proven, and with "
     "arith='ball' every rounding included (float64: measured rounding allowances; docs/tessellation.md). "
     "Measured only: "
     "the rates at which sub-nets approach the patch (h² at the boundary, h inside at the layout positions). Still "
     "open: the remaining signs for n ≥ 3, the de Casteljau question at other α, proofs of the convergence rates."),
]

_MATH_TOKEN = re.compile(r"\$([^$]+)\$|"
                         r"(?<![\w\\])((?:delta|Omega|T-bar|R-bar|G-bar|B-bar|[A-Za-z])"
                         r"(?:_\{[^}]*\}|_[A-Za-z0-9])?(?:\^\{[^}]*\}|\^[A-Za-z0-9]+)?)(?![\w{])")
_IS_MATH = re.compile(r"[_^]")


def math_html(text: str) -> str:
    """Text with its formulas as MathML: ``$...$`` segments and label-like tokens such as ``r_{2n,2n-i,j}^alpha``.

    >>> "<math" in math_html("coefficient r_{4,3,1}^alpha")
    True
    >>> math_html("a < b")
    'a &lt; b'
    """
    from latex2mathml.converter import convert

    out, last = [], 0

    def plain(t: str) -> str:
        return re.sub(r"(?<![A-Za-z_])pi\b", "π", re.sub(r"\balpha\b", "α", html.escape(t)))  # 2pi/3 -> 2π/3

    for m in _MATH_TOKEN.finditer(text):
        tex = m.group(1) or m.group(2)
        if m.group(2) and not _IS_MATH.search(tex):
            continue  # a plain word
        out.append(plain(text[last:m.start()]))
        tex = re.sub(r"^(delta|Omega)", r"\\\1", tex)
        tex = re.sub(r"(T|R|G|B)-bar", r"\\overline{\1}", tex)
        tex = re.sub(r"\^alpha\b", "^{alpha}", tex)
        tex = re.sub(r"(?<!\\)\balpha\b", r"\\alpha", tex)  # a bare alpha, not one already written \alpha
        out.append(convert(tex))
        last = m.end()
    out.append(plain(text[last:]))
    return "".join(out)


def _git(*args: str) -> str:
    if not in_checkout():  # an installed package: whatever repository surrounds site-packages is not ours
        return ""
    try:
        return subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


#: Set by ``reproduce`` once every claim has run and written data/: the gallery then knows that data/ on disk was
#: just recomputed by this code (if it also equals the last commit of data/, the committed data is this code's).
REPRODUCED = False


def _recorded_fingerprint() -> str | None:
    """The code fingerprint a standard run recorded in ``data/provenance.json`` (``None`` if there is none)."""
    import json

    from paper_repro.util.io import data_dir

    try:
        return json.loads((data_dir() / "provenance.json").read_text())["code_fingerprint"]
    except (OSError, ValueError, KeyError, TypeError):
        return None


def provenance() -> dict:
    """The commit of the code that computed the data (the last commit touching the package, pyproject or
    the lock), its date (not the clock), whether the code differs from it, whether ``data/`` was computed by this
    code (the code fingerprint recorded in ``data/provenance.json`` by the standard run equals this code's; without
    that file, from the git history), and the locked versions (``name==version`` of each lock line,
    without its ``--hash=`` options)."""
    paths = ["paper_repro", "pyproject.toml", "requirements.lock"]
    commit = _git("log", "-1", "--format=%H", "--", *paths) or "unknown (no git)"
    date = _git("log", "-1", "--format=%cs", "--", *paths) or "unknown"
    dirty = bool(_git("status", "--porcelain", "--", *paths))
    code_time = _git("log", "-1", "--format=%ct", "--", *paths)
    data_commit = _git("log", "-1", "--format=%H", "--", "data")
    data_time = _git("log", "-1", "--format=%ct", "--", "data")
    data_dirty = bool(_git("status", "--porcelain", "--", "data"))
    recorded = _recorded_fingerprint()
    if recorded is not None:
        from paper_repro.util.cache import code_fingerprint

        now = code_fingerprint()
        data_state = (f"yes: data/ was computed by this code (code fingerprint {now})" if recorded == now else
                      f"no: data/ was computed by other code (fingerprint {recorded}; this code is {now}); "
                      "run make reproduce")
        # (whether data/ is committed yet is no property of the data: the page that a clean reproduce of the
        # committed tree writes must be the committed page)
    elif not (code_time and data_time):
        data_state = "unknown (no git history)"
    elif data_dirty:
        data_state = "data/ has uncommitted changes (a run of make reproduce not yet committed)"
    elif int(data_time) >= int(code_time) and not dirty:
        data_state = f"yes: data/ was last committed ({data_commit[:12]}) after the last change of the code"
    elif REPRODUCED and not dirty:
        data_state = (f"yes: make reproduce with this code recomputed data/ and it equals its last commit "
                      f"({data_commit[:12]})")
    else:
        data_state = (f"no: the code changed after data/ was last committed ({data_commit[:12]}); "
                      "run make reproduce")
    lock = (ROOT / "requirements.lock").read_text().splitlines() if (ROOT / "requirements.lock").exists() else []
    versions = parse_lock(lock)
    return {"commit": commit + (" + uncommitted changes" if dirty else ""), "date": date, "versions": versions,
            "data_matches_code": data_state}


#: The packages whose versions the provenance table shows (those that compute or draw).
PROVENANCE_PACKAGES = ("numpy", "scipy", "mpmath", "python-flint", "matplotlib", "plotly", "latex2mathml", "bezier")


def parse_lock(lines: list[str], wanted: tuple[str, ...] = PROVENANCE_PACKAGES) -> dict[str, str]:
    """``{package: version}`` from lock lines ``name==version [--hash=sha256:...] [\\]``.

    >>> parse_lock(["numpy==2.4.6 --hash=sha256:89cd \\\\", "    --hash=sha256:aa", "scipy==1.17.1"])
    {'numpy': '2.4.6', 'scipy': '1.17.1'}
    """
    out = {}
    for ln in lines:
        m = re.match(r"\s*([A-Za-z0-9_.-]+)==([^\s;\\]+)", ln)
        if m and m.group(1).lower() in wanted:
            out[m.group(1).lower()] = m.group(2)
    return out


def _table(headers: list[str], rows: list[list[str]]) -> str:
    """A table; no header row where every header is empty."""
    head = f"<tr>{''.join(f'<th>{h}</th>' for h in headers)}</tr>" if any(headers) else ""
    body = "".join("<tr>" + "".join(f"<td>{c}</td>" for c in r) + "</tr>" for r in rows)
    return f"<table>{head}{body}</table>"


def _load(path: Path, default):
    return json.loads(path.read_text(encoding="utf-8")) if path.exists() else default


# --- interactive views -------------------------------------------------------------------------------
def _mesh_trace(verts: np.ndarray, faces: np.ndarray, color: str, name: str, opacity: float = 1.0,
                legend: bool = True) -> dict:
    r = lambda a: [float(f"{x:.5g}") for x in a]  # noqa: E731 -- compact, deterministic numbers
    return {"type": "mesh3d", "x": r(verts[:, 0]), "y": r(verts[:, 1]), "z": r(verts[:, 2]),
            "i": faces[:, 0].tolist(), "j": faces[:, 1].tolist(), "k": faces[:, 2].tolist(), "color": color,
            "opacity": opacity, "name": name, "showlegend": legend, "flatshading": False,
            # soft light: mostly ambient and diffuse, little specular (the default's highlights and dark sides
            # turned the cyclide's inner faces into a dark blob)
            "lighting": {"ambient": 0.85, "diffuse": 0.45, "specular": 0.02, "roughness": 0.9, "fresnel": 0.02}}


def _net_trace(net: np.ndarray, edges: list[tuple[int, int]], name: str) -> dict:
    xs, ys, zs = [], [], []
    for a, b in edges:
        for coord, arr in ((xs, 0), (ys, 1), (zs, 2)):
            coord += [float(f"{net[a, arr]:.5g}"), float(f"{net[b, arr]:.5g}"), None]
    return {"type": "scatter3d", "mode": "lines+markers", "x": xs, "y": ys, "z": zs, "name": name,
            "line": {"color": "#333", "width": 3}, "marker": {"size": 3, "color": "#333"}}


def views() -> dict[str, dict]:
    """Plotly figure specs (data + layout) of the interactive views."""
    import mpmath

    from paper_repro.core.layout import net_edges
    from paper_repro.figures.patches_fig import third_order_net
    from paper_repro.surfaces.models import cyclide_pieces, torus_pieces
    from paper_repro.surfaces.patch import Patch

    palette = ["#4c78a8", "#f58518", "#54a24b", "#e45756", "#72b7b2", "#eeca3b", "#b279a2", "#ff9da6"]
    layout = {"margin": {"l": 0, "r": 0, "t": 30, "b": 0}, "height": 520,
              "scene": {"aspectmode": "data", "xaxis": {"visible": False}, "yaxis": {"visible": False},
                        "zaxis": {"visible": False}, "camera": {"eye": {"x": 0.95, "y": -0.95, "z": 0.7}}},
              "legend": {"x": 0, "y": 1}}
    out: dict[str, dict] = {}
    al = np.pi / 2
    mu = 3.0
    tor = torus_pieces(al, (1 + 5**0.5) / 2 * mu, mu, [0.0, al], [0.0, al, 2 * al])
    data = [_mesh_trace(*p.patch.mesh(10), palette[k % 8], f"patch {k + 1}", legend=False) for k, p in enumerate(tor)]
    first = next(p for p in tor if p.phi == 0 and p.psi == 0 and not p.upper)
    data.append(_net_trace(first.patch.net, net_edges(2), "control net of the toroidal triangle (toggle)"))
    # one legend entry only: plotly hides a legend of one entry unless told (the caption points to it)
    out["torus"] = {"data": data, "layout": {**layout, "showlegend": True,
                                             "title": {"text": "Torus: 12 second-order patches"}}}
    phases = [k * al for k in range(4)]
    with mpmath.workdps(30):
        params = {"a": mpmath.mpf(6), "b": mpmath.sqrt(32), "c": mpmath.mpf(2), "mu": mpmath.mpf(3)}
    cyc = cyclide_pieces(al, params, phases, phases)
    out["dupin"] = {"data": [_mesh_trace(*p.patch.mesh(16), palette[k % 8], f"patch {k + 1}", legend=False)
                             for k, p in enumerate(cyc)],
                    "layout": {**layout, "title": {"text": "Dupin cyclide: 32 rational second-order patches"}}}
    net = third_order_net()
    p3 = Patch(3, np.pi / 2, net)
    out["third"] = {"data": [_mesh_trace(*p3.mesh(24), "#9ecae1", "order-3 patch"),
                             _net_trace(net, net_edges(3), "control net (toggle)")],
                    # a taller view, orthographic and zoomed: the net's apex reaches far up, the
                    # patch's front corner far forward (in perspective it was cut off), and from the other views'
                    # distance the patch filled a third of the frame
                    "layout": {**layout, "height": 640,
                               "title": {"text": "Third-order patch (α = π/2) and its 37-point control net"},
                               "scene": {**layout["scene"], **_ortho(np.vstack([p3.mesh(24)[0], net]), 1.8)}}}
    # alpha slider: one order-2 net, the patch for several alpha
    net2 = _order2_net()
    alphas = [0.2, 0.6, 1.0, 1.4, np.pi / 2, 2.0, 2.4, 2.8, 3.1]
    frames = []
    for a in alphas:
        v, f = Patch(2, a, net2).mesh(16)
        frames.append({"name": f"{a:.3g}", "data": [_mesh_trace(v, f, "#f58518", "patch")]})
    steps = [{"label": fr["name"], "method": "animate",
              "args": [[fr["name"]], {"mode": "immediate", "frame": {"duration": 0, "redraw": True}}]}
             for fr in frames]
    # fixed axes over every frame (the patch moves with alpha; autoscaling per frame would cut it off), and the
    # scene above the slider, so that the slider never covers the patch
    allv = np.vstack([np.c_[fr["data"][0]["x"], fr["data"][0]["y"], fr["data"][0]["z"]] for fr in frames] + [net2])
    lo, hi = allv.min(axis=0), allv.max(axis=0)
    pad = 0.05 * (hi - lo).max()
    axes = {f"{ax}axis": {"visible": False, "range": [float(f"{lo[k] - pad:.4g}"), float(f"{hi[k] + pad:.4g}")]}
            for k, ax in enumerate("xyz")}
    scene = {**layout["scene"], **axes, **_ortho(allv, 1.5), "domain": {"x": [0, 1], "y": [0.16, 1]}}
    out["slider"] = {"data": frames[4]["data"] + [_net_trace(net2, net_edges(2), "control net (toggle)")],
                     "frames": frames,
                     "layout": {**layout, "height": 680, "scene": scene,
                                "title": {"text": "One order-2 control net, the patch as α varies"},
                                "sliders": [{"active": 4, "steps": steps, "currentvalue": {"prefix": "α = "},
                                             "y": 0.02, "yanchor": "bottom", "len": 0.95, "x": 0.025}]}}
    return out


def _ortho(points: np.ndarray, zoom: float) -> dict:
    """Scene settings: orthographic projection, the box of ``points`` in true proportions, ``zoom`` times plotly's
    default size (in an orthographic projection plotly zooms by the aspect ratio, not by the camera's distance)."""
    span = np.ptp(points, axis=0)
    span = np.maximum(span, 1e-9 * span.max())
    return {"aspectmode": "manual",
            "aspectratio": {ax: float(f"{zoom * span[k] / span.max():.4g}") for k, ax in enumerate("xyz")},
            "camera": {"eye": {"x": 0.95, "y": -0.95, "z": 0.7}, "projection": {"type": "orthographic"}}}


def _order2_net() -> np.ndarray:
    from paper_repro.core.labels import united_system
    from paper_repro.core.layout import position

    pos = np.array([position(lab) for lab in united_system(2)])
    z = 0.5 * np.sin(np.pi * pos[:, 0]) * np.sin(np.pi * pos[:, 1] / 0.866)
    z[0] += 0.4
    return np.c_[pos, z]


def write_vendor() -> Path:
    """figures/vendor/plotly.min.js from the installed plotly package (written only when it differs)."""
    from plotly.offline import get_plotlyjs

    path = vendor_dir() / "plotly.min.js"
    js = get_plotlyjs()
    if not path.exists() or path.read_text(encoding="utf-8") != js:
        write_text(path, js)
    return path


# --- the page ------------------------------------------------------------------------------------------
def figure_order(manifest: list[dict]) -> list[dict]:
    """The paper's figures by their number (Fig. 1 ... Fig. 12), then the project's own in registry order."""
    def key(m: dict) -> tuple:
        num = re.search(r"Fig\. (\d+)", m.get("paper_number") or "")
        return (0, int(num.group(1)), 0) if num else (1, 0, manifest.index(m))
    return sorted(manifest, key=key)


#: Captions of the interactive views (what they show and how they were made).
VIEW_CAPTIONS = {
    "torus": "Fig. 8 of the paper, interactive: part of the ring torus (μ = 3, ρ = (1+√5)/2·μ, α = π/2) by 12 "
             "second-order patches, with the control net of the toroidal triangle of Example 6.1 (hide or show "
             "it by clicking its entry in the legend, top left).",
    "dupin": "Fig. 9 of the paper, interactive: the ring Dupin cyclide (a = 6, b = 4√2, c = 2, μ = 3) by 32 rational "
             "second-order patches, α = π/2.",
    "third": "Fig. 7 of the paper, interactive: a third-order patch (α = π/2) with its 37-point control net.",
    "slider": "New: one fixed second-order control net and its patch for α from 0.2 to 3.1 (slider below the view); "
              "as α → 0 the patch tends to the degree-5 Bézier triangle of Question 7.3.",
}


def _pair_diff(printed: str, corrected: str) -> str:
    """The tokens that differ between printed and corrected (``printed → corrected``), or ''."""
    import difflib

    tok = lambda t: re.findall(r"[A-Za-z]+_\{[^}]*\}|\S+", t)  # noqa: E731
    a, b = tok(printed), tok(corrected)
    changes = []
    for op, i1, i2, j1, j2 in difflib.SequenceMatcher(a=a, b=b, autojunk=False).get_opcodes():
        if op != "equal":
            changes.append(f"{' '.join(a[i1:i2]) or '∅'} → {' '.join(b[j1:j2]) or '∅'}")
    return "; ".join(changes) if 0 < len(changes) <= 3 else ""


def _cell(value) -> str:
    """A value of an evidence record: Python's None (no case of a printed rule applies) in words."""
    return "<i>no case</i>" if value is None else html.escape(str(value))


def evidence_html(text: str) -> str:
    """Evidence text with its embedded Python lists of records (``[{'i': 1, ...}, ...]``) as small tables."""
    import ast

    out, last = [], 0
    for m in re.finditer(r"\[\{.*?\}\]", text):
        try:
            rows = ast.literal_eval(m.group(0))
        except (ValueError, SyntaxError):
            continue
        if not (isinstance(rows, list) and rows and all(isinstance(r, dict) for r in rows)):
            continue
        keys = list(dict.fromkeys(k for r in rows for k in r))
        out.append(html.escape(text[last:m.start()]))
        out.append('<table class="mini">' + "<tr>" + "".join(f"<th>{html.escape(str(k))}</th>" for k in keys)
                   + "</tr>" + "".join("<tr>" + "".join(f"<td>{_cell(r.get(k, ''))}</td>" for k in keys)
                                       + "</tr>" for r in rows) + "</table>")
        last = m.end()
    out.append(html.escape(text[last:]))
    return "".join(out)


def _anchor(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_:.-]", "-", text)


CSS = ("body{font-family:sans-serif;max-width:1150px;margin:2em auto;padding:0 1em;color:#222;line-height:1.45}"
       "figure{margin:2em 0;border-top:1px solid #ddd;padding-top:1em}img{max-width:100%;height:auto}"
       "table{border-collapse:collapse;margin:0.5em 0}td,th{border:1px solid #ccc;padding:3px 6px;"
       "font-size:90%;vertical-align:top}.pass{color:#060}.fail{color:#b00}code{font-size:90%}"
       ".meta{font-size:88%;color:#444}.meta code{overflow-wrap:anywhere}.view{border:1px solid #ddd;margin:0.5em 0}"
       "nav a{margin-right:1em}.scroll{max-width:100%;overflow-x:auto}table.mini td,table.mini th{font-size:80%;"
       "padding:1px 4px}.pair td{min-width:14em}.figindex{columns:2;font-size:95%}.view-fig{margin:1.5em 0}"
       "details.map>summary{cursor:pointer;font-weight:bold}td.diff{color:#800}")


def gallery_html(manifest: list[dict], view_specs: dict[str, dict] | None = None) -> str:
    claims = _load(data_dir() / "claims.json", [])
    errata = _load(data_dir() / "errata.json", [])
    pmap = _load(data_dir() / "paper_map.json", {"labels": [], "summary": {}})
    bench = _load(reports_dir() / "bench.json", None)
    prov = provenance()
    status = {c["id"]: c for c in claims}
    index = load_index()
    ordered = figure_order(manifest)
    scroll = lambda t: f'<div class="scroll">{t}</div>'  # noqa: E731 -- wide tables scroll, the page does not
    p = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
         '<meta name="viewport" content="width=device-width, initial-scale=1">',
         "<title>paper_repro: gallery</title>", f"<style>{CSS}</style>",
         '<script src="vendor/plotly.min.js"></script></head><body>',
         "<h1>A constructive approach to triangular trigonometric patches — reproduced</h1>",
         "<p>Á. Róth, I. Juhász, A. Kristály, arXiv:1309.4747. Generated by <code>make reproduce</code> "
         "from the registries and <code>data/</code>; nothing on this page is typed in by hand. "
         '<b>The paper, annotated</b> (its text with a badge at every display): '
         '<a href="../paper/index.html">paper/index.html</a> (<code>make paper</code>; needs the paper\'s LaTeX '
         'source beside the clone); ' + report_link_html("../") + ".</p>",
         '<nav><a href="#provenance">provenance</a><a href="#claims">claims</a><a href="#errata">errata</a>'
         '<a href="#questions">open questions</a><a href="#figures">figures</a><a href="#views">3D views</a>'
         '<a href="#bench">performance</a><a href="#map">paper map</a><a href="../paper/index.html">annotated paper</a>'
         "</nav>",
         '<h2 id="provenance">Provenance</h2>',
         _table(["", ""], [["code commit", f"<code>{html.escape(prov['commit'])}</code> ({prov['date']})"],
                           ["data/ computed by this code", html.escape(prov["data_matches_code"])]]),
         _table(["package", "version (requirements.lock)"],
                [[html.escape(k), html.escape(v)] for k, v in sorted(prov["versions"].items())]),
         '<h2 id="claims">Claims</h2>',
         scroll(_table(["id", "in the paper", "statement", "kind", "status"],
                       [[f'<code id="claim-{html.escape(c["id"])}">{html.escape(c["id"])}</code>',
                         "<br>".join(f'<a href="../paper/index.html#{html.escape(r)}">'
                                     f"{html.escape(display_of(r, index))}</a>" for r in c["paper_ref"]),
                         math_html(c["statement"]), c["kind"], f"<span class=\"{c['status']}\">{c['status']}</span>"]
                        for c in claims])),
         '<h2 id="errata">Errata</h2>',
         "<p>Severity: <b>typo</b> (meaning clear, nothing downstream changes), <b>statement</b> (a printed formula "
         "or rule is false as written), <b>result</b> (a result of the paper changes). Each erratum is shown in its "
         'place in the <a href="../paper/index.html">annotated paper</a>.</p>']
    for e in errata:
        diff = _pair_diff(e["printed"], e["corrected"])
        p.append(f'<h3 id="erratum-{_anchor(e["id"])}"><code>{html.escape(e["id"])}</code> — '
                 f'<a href="../paper/index.html#{html.escape(e["paper_ref"])}">'
                 f'{html.escape(display_of(e["paper_ref"], index))}</a>, severity <b>{html.escape(e["severity"])}</b>'
                 "</h3>")
        p.append(scroll(f'<table class="pair"><tr><th>printed</th><th>corrected</th></tr><tr><td>'
                        f'{math_html(e["printed"])}</td><td>{math_html(e["corrected"])}</td></tr>'
                        + (f'<tr><td class="diff" colspan="2">changed: {math_html(diff)}</td></tr>' if diff else "")
                        + "</table>"))
        p.append(f'<p class="meta">evidence: {evidence_html(e["evidence"])}</p>')
    p += ['<h2 id="questions">Open questions of Section 7: where they stand</h2>',
          scroll(_table(["question", "claims (kind, status)", "not reached"],
                        [[html.escape(q), "<br>".join(f'<a href="#claim-{c}"><code>{c}</code></a> '
                                                      f"({status[c]['kind']}, {status[c]['status']})"
                                                      for c in cids if c in status), html.escape(missing)]
                         for q, cids, missing in OPEN_QUESTIONS])),
          *general_formulas_html(),
          '<h2 id="figures">Figures</h2>',
          "<p>In the paper's order, then the project's own figures. Click a figure for its SVG.</p>",
          '<ol class="figindex">' + "".join(
              f'<li><a href="#{html.escape(m["id"])}">{html.escape(m["paper_number"] or "new")}: '
              f'{html.escape(m["id"])}</a></li>' for m in ordered) + "</ol>"]
    for m in ordered:
        number = f"{m['paper_number']} of the paper" if m.get("paper_number") else "new (not in the paper)"
        paper_link = (f' <small><a href="../paper/index.html#{html.escape(m["paper_label"])}">in the annotated paper'
                      f'</a> · <code>{html.escape(m["paper_label"])}</code></small>' if m["paper_label"] else "")
        p.append(f'<figure id="{m["id"]}"><h3>{html.escape(number[0].upper() + number[1:])} — '
                 f'{html.escape(m["id"])}{paper_link}</h3>')
        for out in m["outputs"]:
            name = Path(out).name
            p.append(f'<a href="{html.escape(Path(name).with_suffix(".svg").name)}"><img src="{html.escape(name)}" '
                     f'alt="{html.escape(m["id"])}"></a>')
        claims_txt = ", ".join(f'<a href="#claim-{c["id"]}"><code>{c["id"]}</code></a> '
                               f'<span class="{c["status"]}">{c["status"]}</span>' for c in m["claims"]) or "none"
        files = "<br>".join(f'<code>{html.escape(f["path"])}</code> sha256 <code>{f["sha256"]}</code>'
                            for f in m["files"])
        params = html.escape(json.dumps(m["parameters"])) if m["parameters"] else "none"
        p.append(f"<figcaption>{math_html(m['caption'])}<div class=\"meta\">claims: {claims_txt}<br>"
                 f"generator: <code>{html.escape(m['generator'])}</code>, parameters <code>{params}</code><br>"
                 f"regenerate: <code>{html.escape(m['command'])}</code><br>{files}</div></figcaption></figure>")
    p.append('<h2 id="views">Interactive 3D views</h2><p>Drag to rotate, scroll to zoom; click a legend entry to '
             "toggle the control net. Drawn offline by plotly.js (from the plotly package, in "
             "<code>figures/vendor/</code>).</p>")
    for key, spec in (view_specs or {}).items():
        p.append(f'<figure class="view-fig" id="fig-view-{key}"><div class="view" id="view-{key}"></div>'
                 f"<figcaption>{html.escape(VIEW_CAPTIONS.get(key, ''))}</figcaption></figure>")
        p.append("<script>(function(){var s=" + json.dumps(spec, separators=(",", ":")) + ";"
                 f"Plotly.newPlot('view-{key}',s.data,s.layout,{{displaylogo:false,responsive:true}})"
                 ".then(function(g){if(s.frames){Plotly.addFrames(g,s.frames);}});})();</script>")
    p.append('<h2 id="bench">Performance</h2>')
    if bench:
        p.append(f"<p>From <code>reports/bench.json</code> (<code>make bench</code>; {bench['machine']['cpus']} "
                 f"CPUs, numpy {bench['machine']['numpy']}, bezier {bench['machine']['bezier']}).</p>")
        runs = bench.get("ratios", [])
        mp = {r["n"]: r["speedup_vs_mp"] for r in bench.get("mp", [])}
        head = ["n"] + [f"Patch / bezier, {r['load']}, BLAS {r['blas_threads']}" for r in runs] + ["speed-up vs mpmath"]
        ns = [r["n"] for r in runs[0]["rows"]] if runs else []
        p.append(_table(head, [[str(n)] + [str(next(x["ratio_patch_over_bezier"] for x in r["rows"] if x["n"] == n))
                                           for r in runs] + [f"{mp.get(n, '–')}×"] for n in ns]))
    else:
        p.append("<p>No benchmark report yet (<code>make bench</code>).</p>")
    s = pmap.get("summary", {})
    figs = {m["id"] for m in manifest}
    p.append(f'<h2 id="map">Paper map</h2><p>{s.get("labels", 0)} labels: {s.get("covered_by_claim_or_figure", 0)} '
             f'checked by a claim or figure, {len(s.get("excused", []))} excused (nothing to compute; reason given), '
             f'{len(s.get("neither_checked_nor_excused", []))} neither. Each label links to its place in the '
             "annotated paper, its claims and figures on this page, and the code that names it.</p>")
    rows = []
    for r in pmap.get("labels", []):
        code = ", ".join((f'<a href="../{html.escape(c)}"><code>{html.escape(c.removeprefix("paper_repro/"))}'
                          "</code></a>" if (ROOT / c).exists() else f"<code>{html.escape(c)}</code>")
                         for c in r.get("code", []))
        rows.append([f'<a href="../paper/index.html#{html.escape(r["label"])}">{html.escape(r.get("paper", ""))}</a>',
                     f"<code>{html.escape(r['label'])}</code>",
                     ", ".join(f'<a href="#claim-{c}">{c}</a>' for c in r["claims"]),
                     ", ".join(f'<a href="#{f}">{f}</a>' if f in figs else f for f in r["figures"]), code,
                     html.escape(r.get("excused", "")) if not (r["claims"] or r["figures"]) else ""])
    p.append(f'<details class="map"><summary>the {len(rows)} labels (click to open)</summary>'
             + scroll(_table(["in the PDF", "label", "claims", "figures", "code", "excused because"], rows))
             + "</details>")
    p.append("</body></html>\n")
    return "\n".join(p)


def general_formulas_html() -> list[str]:
    """Question 1's level formulas from ``data/normalization/general_formulas*.json`` (the widest range present)."""
    path = next((p for p in (data_dir() / "normalization" / "general_formulas_extended.json",
                             data_dir() / "normalization" / "general_formulas.json") if p.exists()), None)
    if path is None:
        return []
    gf = json.loads(path.read_text())
    out = ['<h3 id="general-formulas">Question 1: formulas of the normalizing coefficients by level</h3>',
           f"<p>From <code>{html.escape(path.relative_to(output_root()).as_posix())}</code>: "
           + math_html("$r_{2n,2n-i,j} = P_{n,i,j}(c)/s^{2n+j}$, $c = \\cos(\\alpha/2)$, $s = \\sin(\\alpha/2)$, "
                       "$C_{n,k}$ the coefficient of $X^k$ in $(1+2cX+X^2)^n$")
           + ". <i>Proven for n ≤ N</i>: equal to the closed forms proven for every α for each n ≤ N; a conjecture "
             "beyond.</p>"]
    rows = []
    for e in gf["levels"]:
        formula = math_html(f"${e['latex']}$") if "latex" in e else html.escape(e.get("searched", ""))
        rows.append([html.escape(str(e["level"])), html.escape(e.get("cases", e["kind"])), html.escape(e["status"]),
                     formula])
    out.append('<div class="scroll">' + _table(["level", "cases", "status", "formula / what was searched"], rows)
               + "</div>")
    return out


def write_gallery(manifest: list[dict]) -> Path:
    write_vendor()
    return write_text(figures_dir() / "index.html", gallery_html(manifest, views()))
