"""Measure the candidate readers of the paper's mathematics on every transcribed line (issue 37, item 1).

Candidates:

* ``ours`` -- :mod:`paper_repro.printed.latex_math` (a lark LALR grammar of the paper's notation);
* ``sympy-lark`` -- ``sympy.parsing.latex.parse_latex(text, backend="lark")`` (sympy's own lark grammar);
* ``latex2sympy2_extended`` -- ``latex2sympy2_extended.latex2sympy`` (ANTLR), when it is installed.

Input: the mathematics of each line of ``paper_repro.printed.lines``: a ``display`` line's verbatim (the part
inside ``\\[..\\]``/``equation`` when the line also carries prose); for the other kinds each ``$..$`` segment (a line
counts as read when every segment is read; a line without ``$`` is "no mathematics").  Two inputs are measured for
the two general parsers: the verbatim as it is, and a *fair* normalisation (``%`` line ends, ``\\label``,
``\\nonumber``, colour macros, ``\\displaystyle``/``\\limits``, alignment ``&``, row breaks ``\\\\`` and trailing
punctuation removed; ``\\dfrac``/``\\dbinom`` -> ``\\frac``/``\\binom``; the part after the first top-level comma
(``,~\\forall ...``) dropped) -- the typographical noise our reader strips itself.

"Reads" means: returns without an exception within 2 s, and (sympy-lark) returns no ``_ambig`` tree.
"Correct" is measured on a sample of lines with a hand-computed value at an exact point (see ``SAMPLE``): the
value of the parsed object (or of ``lhs - rhs`` for an identity) at the point agrees to 1e-9.

Run: ``python tools/latex_parsers.py [--out reports/latex_parsers.md]`` (about a minute).
"""

from __future__ import annotations

import argparse
import math
import re
import signal
import sys
import time
import warnings
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import sympy  # noqa: E402

from paper_repro.printed import latex_math as lm  # noqa: E402
from paper_repro.printed.lines import all_lines, verbatim  # noqa: E402

warnings.filterwarnings("ignore")
TIMEOUT = 2


class _Timeout(Exception):
    pass


def _alarm(signum, frame):  # pragma: no cover - signal handler
    raise _Timeout


def math_segments(line) -> list[str] | None:
    """The mathematics of a line (see the module docstring); None for a line without mathematics."""
    if line.kind == "display":
        return [lm._display_math(line.verbatim)]
    segs = re.findall(r"(?<!\\)\$(.+?)(?<!\\)\$", line.verbatim, flags=re.S)
    return segs or None


def fair(text: str) -> str:
    """The typographical normalisation given to the general parsers (see the module docstring)."""
    s = re.sub(r"(?<!\\)%\s*", "", text)
    s = re.sub(r"\\label\s*\{[^{}]*\}", " ", s)
    s = re.sub(r"\\(nonumber|normalcolor|displaystyle|limits|notag)(?![A-Za-z])", " ", s)
    s = re.sub(r"\\(Red|Green|Blue|Orange)\s*\{", "{", s)
    s = re.sub(r"\\(begin|end)\s*\{(equation\*?|align\*?)\}", " ", s)
    s = s.replace(r"\dfrac", r"\frac").replace(r"\dbinom", r"\binom")
    s = s.replace("&", " ")
    s = re.sub(r"\\\\", " ", s)
    s = s.replace("~", " ")
    s = re.sub(r"\s+", " ", s).strip()
    parts = lm._split_top(s)
    s = parts[0]
    return re.sub(r"[\s,.;]+$", "", s)


def _ours(text: str):
    return lm.parse_relation(text)


def _sympy_lark(text: str):
    from sympy.parsing.latex import parse_latex

    out = parse_latex(text, backend="lark")
    if "_ambig" in str(out) or type(out).__name__ == "Tree":
        raise ValueError("ambiguous (_ambig tree)")
    return out


def _l2s():
    try:
        from latex2sympy2_extended import latex2sympy
    except ImportError:
        return None
    return latex2sympy


def _try(fn, text: str, timeout: int = TIMEOUT) -> tuple[bool, object]:
    signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(timeout)
    try:
        return True, fn(text)
    except _Timeout:
        return False, "timeout"
    except Exception as e:  # noqa: BLE001 - any failure of a candidate is a failure to read
        return False, f"{type(e).__name__}: {str(e)[:80]}"
    finally:
        signal.alarm(0)


# ------------------------------------------------------------------------------------- correctness sample
# alpha = 0.9, not 1: at alpha = 1 a tag ^{\alpha} misread as a power (latex2sympy2_extended) would go unseen
AL = 0.9
s1, c1 = math.sin(AL / 2), math.cos(AL / 2)


def _c6(k: int) -> float:  # placeholder values for the c_{6,k} in the r_{6,3,3} lines (any numbers do)
    return float(k + 1)


# Each entry: line id, point (name -> value), the value computed by hand from the printed formula (a reading of
# the PDF by a person, not by a parser), and which value is compared: "rhs" (last part), "lhs-rhs" (an identity,
# value 0 at any point), or "matrix" (the vector's entries).
SAMPLE = [
    ("sec1_3-c-formula", {"n": 2, "i": 2, "alpha": AL}, (4 * c1**2 + 2) / s1**4, "rhs"),
    ("sec1_3-c-formula", {"n": 3, "i": 3, "alpha": AL}, (8 * c1**3 + 12 * c1) / s1**6, "rhs"),
    ("sec4_5-product-to-sum-1", {"x": 0.3, "y": 0.7}, 0.0, "lhs-rhs"),
    ("sec4_5-product-to-sum-2", {"x": 0.3, "y": 0.7}, 0.0, "lhs-rhs"),
    ("sec4_5-product-to-sum-3", {"x": 0.3, "y": 0.7}, 0.0, "lhs-rhs"),
    ("sec6-torus-point-r_{4,4,0}", {"alpha": AL, "varrho": 2, "mu": 1},
     [2 + math.sin(AL), 0.0, math.cos(AL)], "matrix"),
    ("sec6-torus-point-r_{4,1,0}", {"alpha": AL, "varrho": 2, "mu": 1},
     [2 + 0.5 * math.tan(AL / 2), 0.0, 1.0], "matrix"),
    ("sec6-torus-point-g_{4,2,1}", {"alpha": AL, "varrho": 2, "mu": 1},
     [(3 * 2 * (3 + math.cos(AL)) + 3 * math.sin(AL)) / (10 + 2 * math.cos(AL)),
      (3 * 2 * (3 * s1 + math.sin(1.5 * AL)) + 3 * (c1 - math.cos(1.5 * AL)))
      / ((20 + 4 * math.cos(AL)) * c1), 1.0], "matrix-first2"),
    ("sec7-conv2-p401", {}, None, "conversion"),
    ("sec4_5-ex-r633-mid", {"alpha": AL}, 20 / s1**3 * _c6(6) + 50 / s1**3 * c1 * _c6(5)
     - (56 / s1**3 * c1**4 - 60 / s1**3 * c1**2 - 8 / s1 + 56 / s1 * c1**2 - 4 / s1**3) * _c6(4)
     - (10 / s1**3 * c1**3 - 3 / s1 * c1 + 12 / s1**3 * c1) * _c6(3), "rhs-c6"),
    ("sec1_3-R-leq-n", {"n": 2, "i": 1, "j": 1, "u": 0.2, "v": 0.3, "w": 0.5},
     math.sin(0.1)**3 * math.sin(0.25) * math.cos(0.15)**0 * math.sin(0.15), "family-member"),
    ("sec7-rel-r431", {"alpha": AL}, None, "colour"),
]


def _num(expr, point: dict) -> complex:
    subs = {}
    for s in expr.free_symbols:
        key = s.name.lstrip("\\")
        if key in point:
            subs[s] = point[key]
    return complex(sympy.N(expr.subs(subs).doit()))


def _ours_value(line_id: str, point: dict, how: str):
    r = lm.parse_relation(verbatim(line_id))
    if how == "rhs":
        return _num(r.parts[-1], point)
    if how == "lhs-rhs":
        return _num(r.parts[0] - r.parts[-1], point)
    if how.startswith("matrix"):
        m = r.parts[-1]
        return [_num(x, point) for x in m]
    if how == "rhs-c6":
        e = r.parts[-1]
        e = e.replace(lambda x: isinstance(x, sympy.Function) and x.func.__name__ == "c",
                      lambda x: sympy.Float(_c6(int(x.args[1]))))
        return _num(e, point)
    if how == "family-member":
        fam = r.parts[-1]
        return _num(fam.args[0], point)
    raise ValueError(how)


def _check_conversion() -> bool:
    r = lm.parse_relation(verbatim("sec7-conv2-p401"))
    rv = sympy.Function("r_vec")
    want = sympy.Rational(1, 5) * rv(4, 4, 0) + sympy.Rational(4, 5) * rv(4, 3, 0)
    return r.parts[0] == sympy.Function("p_vec")(4, 0, 1) and sympy.expand(r.parts[1] - want) == 0


def _check_colour() -> bool:
    # 2 r220 r211 + r220^2 g210 sin(a) + 2 (1 + r220 cos^2(a/2)) r210 b210 sin(a/2), read by hand from the PDF
    r = lm.parse_relation(verbatim("sec7-rel-r431"))
    vals = {"r": {(2, 2, 0): 1.5, (2, 1, 0): 0.7, (2, 1, 1): 0.3}, "g": {(2, 1, 0): 1.1}, "b": {(2, 1, 0): 0.9}}
    e = r.parts[-1].replace(lambda x: isinstance(x, sympy.Function) and x.func.__name__ in vals,
                            lambda x: sympy.Float(vals[x.func.__name__][tuple(int(a) for a in x.args)]))
    got = complex(sympy.N(e.subs(sympy.Symbol("alpha"), AL)))
    want = (2 * 1.5 * 0.3 + 1.5**2 * 1.1 * math.sin(AL) + 2 * (1 + 1.5 * c1**2) * 0.7 * 0.9 * s1)
    return abs(got - want) < 1e-9


def correctness_ours() -> list[tuple[str, bool, str]]:
    out = []
    for line_id, point, want, how in SAMPLE:
        try:
            if how == "conversion":
                ok = _check_conversion()
            elif how == "colour":
                ok = _check_colour()
            else:
                got = _ours_value(line_id, point, how)
                if how == "matrix-first2":
                    got, want = got[:2], want[:2]
                if isinstance(want, list):
                    ok = all(abs(g - w) < 1e-9 for g, w in zip(got, want))
                else:
                    ok = abs(got - want) < 1e-9
            out.append((line_id, ok, how))
        except Exception as e:  # noqa: BLE001
            out.append((line_id, False, f"{how}: {type(e).__name__}: {e}"[:120]))
    return out


_IDX = re.compile(r"^\\?(?:mathbf\{)?([a-zA-Z]+)\}?_\{?([\d,]+)\}?")

# values of the indexed names in the conversion and colour samples (the same as _check_conversion/_check_colour)
_NAMED = {("c", (6, k)): _c6(k) for k in range(7)}
_NAMED.update({("r", (4, 4, 0)): 1.5, ("r", (4, 3, 0)): 0.7})
_COLOUR = {("r", (2, 2, 0)): 1.5, ("r", (2, 1, 0)): 0.7, ("r", (2, 1, 1)): 0.3, ("g", (2, 1, 0)): 1.1,
           ("b", (2, 1, 0)): 0.9}


def _num_named(expr, point: dict, named: dict) -> complex:
    """Value of a general parser's output: plain names from ``point``, indexed names (``c_{6,6}``) from ``named``
    by their printed name; a name left over (or an indexed name read as something else) fails."""
    subs = {}
    for sym in expr.free_symbols:
        key = sym.name.lstrip("\\")
        if key in point:
            subs[sym] = point[key]
            continue
        m = _IDX.match(sym.name)
        if m:
            idx = tuple(int(t) for t in m.group(2).split(","))
            if (m.group(1), idx) in named:
                subs[sym] = named[(m.group(1), idx)]
    val = sympy.N(expr.subs(subs).doit())
    if val.free_symbols:
        raise ValueError(f"names left unvalued: {sorted(str(t) for t in val.free_symbols)[:4]}")
    return complex(val)


def correctness_general(fn, name: str) -> list[tuple[str, bool, str]]:
    """The same sample read by a general parser from the fair text: the last '=' part, at the same point
    (indexed names valued by their printed name, see :func:`_num_named`)."""
    out = []
    for line_id, point, want, how in SAMPLE:
        if how == "family-member":
            out.append((line_id, False, f"{how}: a set with bounds is not read as one"))
            continue
        text = fair(lm._display_math(verbatim(line_id)))
        ok_parse, obj = _try(fn, text, timeout=30)
        if not ok_parse:
            out.append((line_id, False, f"does not parse: {obj}"))
            continue
        try:
            if isinstance(obj, sympy.Equality):
                lhs, rhs = obj.lhs, obj.rhs
            elif isinstance(obj, (list, tuple)) and obj:
                lhs, rhs = None, obj[-1]
            else:
                lhs, rhs = None, obj
            if how in ("rhs", "rhs-c6"):
                ok = abs(_num_named(rhs, point, _NAMED) - want) < 1e-9
            elif how == "lhs-rhs":
                ok = abs(_num_named(lhs - rhs, point, _NAMED)) < 1e-9
            elif how == "conversion":
                ok = abs(_num_named(rhs, {}, _NAMED) - (1.5 / 5 + 4 * 0.7 / 5)) < 1e-9
            elif how == "colour":
                want_c = 2 * 1.5 * 0.3 + 1.5**2 * 1.1 * math.sin(AL) + 2 * (1 + 1.5 * c1**2) * 0.7 * 0.9 * s1
                ok = abs(_num_named(rhs, {"alpha": AL}, _COLOUR) - want_c) < 1e-9
            else:
                vals = [_num_named(t, point, _NAMED) for t in rhs]
                kk = 2 if how == "matrix-first2" else 3
                ok = len(vals) >= kk and all(abs(g - w) < 1e-9 for g, w in zip(vals[:kk], want[:kk]))
            out.append((line_id, ok, how if ok else f"{how}: wrong value"))
        except Exception as e:  # noqa: BLE001
            out.append((line_id, False, f"{how}: {type(e).__name__}: {str(e)[:80]}"))
    return out


def measure() -> dict:
    lines = all_lines()
    cands = {"ours": _ours, "sympy-lark": _sympy_lark}
    l2s = _l2s()
    if l2s is not None:
        cands["latex2sympy2_extended"] = l2s
    res: dict = {"n_lines": len(lines), "kinds": Counter(x.kind for x in lines), "per": {}, "time": {},
                 "examples": {}}
    for name, fn in cands.items():
        for mode in (("raw",) if name == "ours" else ("raw", "fair")):
            key = f"{name} ({mode})"
            per: Counter = Counter()
            fails = []
            t0 = time.perf_counter()
            for x in lines:
                segs = math_segments(x)
                if segs is None:
                    per[(x.kind, "no math")] += 1
                    continue
                ok_all = True
                for seg in segs:
                    ok, why = _try(fn, seg if mode == "raw" else fair(seg))
                    if not ok:
                        ok_all = False
                        fails.append((x.id, why))
                        break
                per[(x.kind, "read" if ok_all else "unread")] += 1
            res["per"][key] = per
            res["time"][key] = time.perf_counter() - t0
            res["examples"][key] = fails
    res["sympy_lark_checks"] = _confirm_sympy_lark()
    res["correct"] = {"ours": correctness_ours(), "sympy-lark": correctness_general(_sympy_lark, "sympy-lark")}
    if l2s is not None:
        res["correct"]["latex2sympy2_extended"] = correctness_general(l2s, "latex2sympy2_extended")
    return res


def _confirm_sympy_lark() -> list[tuple[str, str]]:
    from sympy.parsing.latex import parse_latex

    out = []
    for t in (r"\sin^{3}\frac{u}{2}", r"\sin^{2n-i}\frac{u}{2}\sin^{i}\frac{w}{2}", r"c_{2,2}",
              r"c_{2n,i}^{\alpha}", r"\frac{20}{\sin^{3}\frac{\alpha}{2}}c_{6,6}^{\alpha}"):
        try:
            v = parse_latex(t, backend="lark")
            out.append((t, f"{type(v).__name__}: {str(v)[:90]}"))
        except Exception as e:  # noqa: BLE001
            out.append((t, f"{type(e).__name__}: {str(e).splitlines()[0][:90]}"))
    return out


def report(res: dict) -> str:
    kinds = sorted(res["kinds"])
    out = ["# The readers of the paper's mathematics, measured", "",
           "Made by `python tools/latex_parsers.py` (see its docstring for what is measured). "
           f"{res['n_lines']} transcribed lines; kinds: "
           + ", ".join(f"{k} {res['kinds'][k]}" for k in kinds) + ".", "",
           f"A candidate has {TIMEOUT} s per segment (30 s on the correctness sample); on a loaded machine the general "
           "parsers' counts move by a few lines between runs (display lines, fair text: sympy-lark 14-15, "
           "latex2sympy2_extended 123-130 in four runs).", "",
           "## Lines read (every mathematical segment parses)", "",
           "| candidate | " + " | ".join(kinds) + " | all with math | time (s) |",
           "|---|" + "---|" * (len(kinds) + 2)]
    for key, per in res["per"].items():
        cells, tot_r, tot_m = [], 0, 0
        for k in kinds:
            r, u = per[(k, "read")], per[(k, "unread")]
            cells.append(f"{r}/{r + u}" if r + u else "-")
            tot_r += r
            tot_m += r + u
        out.append(f"| {key} | " + " | ".join(cells) + f" | **{tot_r}/{tot_m}** | {res['time'][key]:.1f} |")
    out += ["", "## Correct on the sample (value at an exact point against a hand-computed value)", ""]
    for name, rows in res["correct"].items():
        ok = sum(1 for _, g, _ in rows if g)
        out.append(f"- **{name}**: {ok} of {len(rows)} correct")
        for line_id, good, how in rows:
            how1 = " ".join(how.split())
            out.append(f"  - `{line_id}`: {'correct' if good else 'NOT correct'} ({how1})")
    out += ["", "## sympy's lark backend on the paper's notation (confirmation)", ""]
    for t, v in res["sympy_lark_checks"]:
        out.append(f"- `{t}` -> {v}")
    out += ["", "## First unread lines per candidate", ""]
    for key, fails in res["examples"].items():
        reasons = Counter(re.sub(r"'.*", "", " ".join(w.split()))[:50] for _, w in fails)
        out.append(f"- **{key}**: {len(fails)} unread; commonest reasons: "
                   + "; ".join(f"{r.strip()} ({c})" for r, c in reasons.most_common(4)))
        if key.startswith("ours"):
            for line_id, why in fails:
                out.append(f"  - `{line_id}`: {' '.join(why.split())}")
    return "\n".join(out) + "\n"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(ROOT / "reports" / "latex_parsers.md"))
    a = ap.parse_args(argv)
    res = measure()
    text = report(res)
    Path(a.out).write_text(text)
    print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
