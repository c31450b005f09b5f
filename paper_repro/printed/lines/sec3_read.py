"""Readers of the formulas of Section 3 (sec:linear_independence) in the verbatim transcriptions.

The proof of Theorem joint_systems_linear_independence writes its values as sums of products: a combining constant
(``\\rho_{2n,2n-i,j}``, possibly primed), sines and cosines of half angles of the variables at the boundary
(``\\left. \\sin^{2n-i}\\frac{u_{1}\\left( x,y\\right) }{2}\\right\\vert _{y=0}``), derivatives of such factors
(``\\frac{\\text{d}^{k}}{\\text{d}w_{1}^{k}}``), the derivatives at 0 of Lemma lem:sign_cos_power_derivative and
Proposition derivative_cosine_sine (``S_{j,\\frac{1}{2}}^{z}\\left( 0\\right)``, ``M_{i,\\frac{1}{2},j,
\\frac{1}{2}}^{z}\\left( 0\\right)``), the normalizing constants ``c_{2n,k}^{\\alpha}`` and the univariate functions
``A_{2n,k}^{\\alpha}\\left( x\\right)``.  :func:`read_products` reads such a line into terms (the sums written before
each term, its constant, its factors) exactly as printed; evaluating them is left to the checks
(:mod:`paper_repro.claims.lines.sec1_3`).  Anything not of this form raises ``ValueError`` (a blank or garbled line
is refused, never read charitably).

Also: the parametrizations of the proof (:func:`read_parametrization`: the three coordinate maps as integer linear
forms in alpha, x, y, and the printed ranges of x and y), the definitions of the primed constants
(:func:`read_prime_definition`) and linear forms such as ``\\alpha-x`` (:func:`linear_form`).

>>> linear_form(r"\\alpha-x-y")
(1, -1, -1)
>>> t = read_products(r"\\rho_{2n,n,n}\\left. \\sin^{n}\\frac{u_{1}\\left( x,y\\right) }{2}\\right\\vert _{y=0}")
>>> [f.kind for f in t[0].factors]
['trig', 'bar']
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from fractions import Fraction

_GREEK = {"rho": "R", "gamma": "G", "beta": "B"}


def _normalize(tex: str) -> str:
    """Drop what carries no mathematics here: ``%`` continuations, ``\\displaystyle``, ``\\limits``, alignment, line
    breaks of arrays, ``\\cdot`` (a product), ``\\left.``/``\\right.`` (invisible delimiters); ``\\left(`` -> ``(``."""
    t = tex.replace("%", " ")
    t = re.sub(r"\\(?:displaystyle|limits|nonumber)(?![a-zA-Z])", " ", t)
    t = t.replace("\\left(", "(").replace("\\right)", ")").replace("\\dfrac", "\\frac")
    t = re.sub(r"\\left\.", " ", t)
    t = re.sub(r"\\right\.(?!\w)", " ", t)
    t = t.replace("\\cdot", " ")
    t = re.sub(r"\{\s*(\\sum\s*_\{[^{}]*\}\s*\^\{(?:[^{}]|\{[^{}]*\})*\})\s*\}", r"\1", t)  # {\sum_{..}^{..}}
    return t


def _group(t: str, k: int) -> tuple[str, int]:
    """The balanced brace group starting at ``t[k] == '{'``: (its content, index after it)."""
    if k >= len(t) or t[k] != "{":
        raise ValueError(f"expected '{{' at {t[k:k + 20]!r}")
    depth = 0
    for m in range(k, len(t)):
        if t[m] == "{":
            depth += 1
        elif t[m] == "}":
            depth -= 1
            if depth == 0:
                return t[k + 1:m], m + 1
    raise ValueError(f"unbalanced braces in {t[k:k + 30]!r}")


def _skip(t: str, k: int) -> int:
    while k < len(t) and t[k].isspace():
        k += 1
    return k


def linear_form(expr: str) -> tuple[int, int, int]:
    """Integer coefficients (of alpha, x, y) of a printed linear form such as ``\\alpha-x-y``, ``x-y``, ``y``, ``0``,
    read by the paper's LaTeX reader (:func:`paper_repro.printed.latex_math.parse`); ``ValueError`` for anything
    else (another symbol, a constant term, a non-integer or non-linear coefficient)."""
    import sympy

    from paper_repro.printed.latex_math import parse

    e = sympy.expand(parse(expr))
    alpha, x, y = sympy.symbols("alpha x y")
    if not isinstance(e, sympy.Expr) or not e.free_symbols <= {alpha, x, y}:
        raise ValueError(f"not a linear form in alpha, x, y: {expr!r}")
    poly = sympy.Poly(e, alpha, x, y) if e != 0 else None
    if poly is None:
        return 0, 0, 0
    coeffs = poly.as_dict()
    if any(sum(m) != 1 for m in coeffs) or any(not c.is_integer for c in coeffs.values()):
        raise ValueError(f"not a linear form in alpha, x, y: {expr!r}")
    return tuple(int(coeffs.get(m, 0)) for m in ((1, 0, 0), (0, 1, 0), (0, 0, 1)))


# -- factors ----------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Factor:
    """One printed factor.  ``kind``: ``trig`` (sin^s cos^c of half an argument, ``deriv`` times differentiated in
    it), ``S``/``M`` (derivatives at 0 of Lemma lem:sign_cos_power_derivative / Proposition
    derivative_cosine_sine), ``c`` (normalizing constant), ``A`` (univariate function).  Exponents, orders and
    indices are the printed expressions (strings)."""

    kind: str
    args: tuple
    deriv: tuple[str, str] | None = None  # (order expression, variable differentiated in)


@dataclass
class Term:
    sums: list[tuple[str, str, str]]
    constant: tuple[str, str, str, bool] | None  # (colour, first index, level, primed)
    factors: list[Factor] = field(default_factory=list)


_TRIG = re.compile(r"\\(sin|cos)\s*(\^)?")


def _read_arg(arg: str) -> str:
    """The argument of a half angle: ``u_{1}(x,y)`` -> ``u_1``; ``\\alpha-x`` stays a linear form."""
    a = re.sub(r"\s+", "", arg)
    m = re.fullmatch(r"([uvw])(?:_\{(\d)\})?(?:\(x,y\))?", a)
    if m:
        return m.group(1) + ("_" + m.group(2) if m.group(2) else "")
    linear_form(a)  # raises unless a linear form
    return a


def _trig_at(t: str, k: int) -> tuple[str, str, int]:
    """``\\sin^{p}\\frac{ARG}{2}`` at k: (function, power, argument, end)."""
    m = _TRIG.match(t, k)
    fn = m.group(1)
    k = _skip(t, m.end())
    power = "1"
    if m.group(2):
        power, k = _group(t, k)
        k = _skip(t, k)
    if not t.startswith("\\frac", k):
        raise ValueError(f"\\{fn} without \\frac{{..}}{{2}} at {t[k:k + 30]!r}")
    num, k = _group(t, _skip(t, k + 5))
    den, k = _group(t, _skip(t, k))
    if den.strip() != "2":
        raise ValueError(f"a half angle must be over 2, not {den!r}")
    return fn, power.strip(), _read_arg(num), k


def _bar(t: str, k: int) -> tuple[str | None, int]:
    """``\\right\\vert _{y=0}`` at k: (the variable set to 0, end); (None, k) if there is none."""
    m = re.compile(r"\s*\\right\\vert\s*_\{\s*([xy])\s*=\s*0\s*\}").match(t, k)
    return (m.group(1), m.end()) if m else (None, k)


def read_products(tex: str) -> list[Term]:
    """The terms of a printed sum of products (see the module docstring), in order.  A ``\\left( .. \\right)``
    group holding a sum is multiplied out (the factors before it multiply each of its terms).  Evaluation bars
    ``\\right\\vert _{y=0}`` are collected in :data:`Term` factors' ``args`` of kind ``bar``."""
    t = re.sub(r"\\\\", " ", _normalize(tex)).replace("&", " ")
    t = re.sub(r"^\s*=", " ", t)
    terms, _ = _read_sum(t, 0, top=True)
    if not terms or any(term.constant is None and not term.factors for term in terms):
        raise ValueError(f"no product read in {tex[:60]!r}")
    return terms


def _read_sum(t: str, k: int, top: bool) -> tuple[list[Term], int]:
    terms: list[Term] = []
    cur = Term([], None, [])
    prefix: list[Factor] = []  # factors multiplying a following group
    pending_deriv: tuple[str, str] | None = None
    pending_sums: list[tuple[str, str, str]] = []
    while True:
        k = _skip(t, k)
        if k >= len(t):
            break
        if t[k] == ")":
            if top:
                raise ValueError(f"unbalanced ')' at {t[k:k + 20]!r}")
            break
        if t[k] == "+":
            if cur.constant is not None or cur.factors:
                terms.append(cur)
            cur = Term([], None, [])
            k += 1
            continue
        m = re.compile(r"\\sum\s*_\{\s*(\w)\s*=").match(t, k)
        if m:
            lo_hi, k2 = _group(t, _skip(t, k + 4) + 1)  # _{...}
            var, lo = lo_hi.split("=", 1)
            k2 = _skip(t, k2)
            if t[k2] != "^":
                raise ValueError("a sum without an upper bound")
            hi, k = _group(t, _skip(t, k2 + 1))
            pending_sums.append((var.strip(), lo.strip(), hi.strip()))
            continue
        m = re.compile(r"\\(rho|gamma|beta)\s*_\{").match(t, k)
        if m:
            idx, k = _group(t, m.end() - 1)
            parts = [p.strip() for p in idx.split(",")]
            if len(parts) != 3 or parts[0] != "2n":
                raise ValueError(f"constant indices {idx!r}")
            k = _skip(t, k)
            primed = False
            if t.startswith("^", k):
                sup, k = _group(t, _skip(t, k + 1))
                if sup.strip() != "\\prime":
                    raise ValueError(f"constant superscript {sup!r}")
                primed = True
            if cur.constant is not None:
                raise ValueError("two constants in one term")
            cur.constant = (_GREEK[m.group(1)], parts[1], parts[2], primed)
            cur.sums = pending_sums
            pending_sums = []
            continue
        if _TRIG.match(t, k):
            fn, power, arg, k = _trig_at(t, k)
            fac = Factor("trig", ((power, "0") if fn == "sin" else ("0", power), arg), pending_deriv)
            pending_deriv = None
            bar, k = _bar(t, k)
            cur.factors.append(fac)
            if bar:
                cur.factors.append(Factor("bar", (bar,)))
            continue
        m = re.compile(r"\\frac\s*\{\s*\\text\{d\}\s*\^\{([^{}]+)\}\s*\}\s*\{\s*\\text\{d\}\s*([uvw])(?:_\{(\d)\})?\s*"
                       r"\^\{([^{}]+)\}\s*\}").match(t, k)
        if m:
            if m.group(1).strip() != m.group(4).strip():
                raise ValueError(f"derivative orders differ: d^{m.group(1)} / d{m.group(2)}^{m.group(4)}")
            pending_deriv = (m.group(1).strip(), m.group(2) + ("_" + m.group(3) if m.group(3) else ""))
            k = m.end()
            continue
        m = re.compile(r"([SM])\s*_\{").match(t, k)
        if m:
            sub, k = _group(t, m.end() - 1)
            k = _skip(t, k)
            if not t.startswith("^", k):
                raise ValueError(f"{m.group(1)} without an order")
            order, k = _group(t, _skip(t, k + 1))
            m0 = re.compile(r"\s*\(\s*0\s*\)").match(t, k)
            if not m0:
                raise ValueError(f"{m.group(1)} not evaluated at 0")
            k = m0.end()
            cur.factors.append(Factor(m.group(1), (tuple(p.strip() for p in _split_top(sub)), order.strip())))
            continue
        m = re.compile(r"c_\{").match(t, k)
        if m:
            sub, k = _group(t, m.end() - 1)
            k = _skip(t, k)
            sup, k = _group(t, _skip(t, k + 1)) if t.startswith("^", k) else ("", k)
            parts = [p.strip() for p in sub.split(",")]
            if len(parts) != 2 or parts[0] != "2n" or sup.strip() != "\\alpha":
                raise ValueError(f"c_{{{sub}}}^{{{sup}}}")
            cur.factors.append(Factor("c", (parts[1],)))
            continue
        m = re.compile(r"A_\{").match(t, k)
        if m:
            sub, k = _group(t, m.end() - 1)
            k = _skip(t, k)
            sup, k = _group(t, _skip(t, k + 1)) if t.startswith("^", k) else ("", k)
            m2 = re.compile(r"\s*\(\s*([xy])\s*\)").match(t, k)
            parts = [p.strip() for p in sub.split(",")]
            if len(parts) != 2 or parts[0] != "2n" or sup.strip() != "\\alpha" or not m2:
                raise ValueError(f"A_{{{sub}}}^{{{sup}}} without its variable")
            cur.factors.append(Factor("A", (parts[1], m2.group(1))))
            k = m2.end()
            continue
        if t[k] == "(":
            inner, k = _read_sum(t, k + 1, top=False)
            if k >= len(t) or t[k] != ")":
                raise ValueError("unclosed '('")
            k += 1
            bar, k = _bar(t, k)
            if len(inner) == 1 and inner[0].constant is None and not inner[0].sums:
                facs = [f for f in inner[0].factors if f.kind == "trig"]
                if pending_deriv or bar:
                    args = {f.args[1] for f in facs}
                    if len(args) != 1 or any(f.deriv for f in facs):
                        raise ValueError("a differentiated group must be sines and cosines of one argument")
                    s = "+".join(f"({f.args[0][0]})" for f in facs)
                    c = "+".join(f"({f.args[0][1]})" for f in facs)
                    cur.factors.append(Factor("trig", ((s, c), args.pop()), pending_deriv))
                    pending_deriv = None
                    cur.factors += [f for f in inner[0].factors if f.kind == "bar"]
                else:
                    cur.factors += inner[0].factors
                if bar:
                    cur.factors.append(Factor("bar", (bar,)))
                continue
            # a sum in parentheses: what stood before multiplies each of its terms
            prefix = cur.factors
            if cur.constant is not None or pending_sums:
                raise ValueError("a constant or a sum before a parenthesized sum")
            for term in inner:
                terms.append(Term(term.sums, term.constant, prefix + term.factors))
            cur = Term([], None, [])
            continue
        raise ValueError(f"unread at {t[k:k + 40]!r}")
    if cur.constant is not None or cur.factors:
        terms.append(cur)
    if pending_sums or pending_deriv:
        raise ValueError("a sum or derivative with nothing after it")
    return terms, k


def _split_top(s: str) -> list[str]:
    """Split at commas outside braces."""
    out, depth, cur = [], 0, ""
    for ch in s:
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        if ch == "," and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += ch
    return out + [cur]


def rate(tex: str) -> Fraction:
    """``\\frac{1}{2}`` -> 1/2, ``3`` -> 3 (an angular velocity of S or M)."""
    s = re.sub(r"\s+", "", tex)
    m = re.fullmatch(r"\\frac\{(\d+)\}\{(\d+)\}", s)
    if m:
        return Fraction(int(m.group(1)), int(m.group(2)))
    if re.fullmatch(r"\d+", s):
        return Fraction(int(s))
    raise ValueError(f"unread rate {tex!r}")


# -- case lines: ", & k=0" and "0, & 1\leq k\leq r+1" ---------------------------------------------------------
def split_case(tex: str) -> tuple[str, str]:
    """(value, condition) of one row ``VALUE , & CONDITION \\\\`` of a printed case distinction (the leading
    ``= &`` / ``\\underset{..}{\\overset{..}{=}} &`` and ``\\left\\{ \\begin{array}[c]{rl}`` are dropped)."""
    t = tex.replace("%", " ")
    t = re.sub(r"^\s*\\underset\{.*?\}\{\\overset\s*\{.*?\}\{=\}\}\s*&", " ", t, flags=re.S)
    t = re.sub(r"^\s*=?\s*&", " ", t)
    t = re.sub(r"\\left\\\{\s*\\begin\{array\}\s*\[c\]\{rl\}", " ", t)
    t = re.sub(r"\\\\\s*$", "", t.strip())
    m = re.search(r",\s*&\s*([^&]*?)\s*[,.]?\s*$", t)
    if not m:
        raise ValueError(f"no case condition in {tex[:60]!r}")
    return t[:m.start()].strip(), m.group(1).strip()


def case_range(cond: str, var: str = "k") -> tuple[str, str]:
    """``k=0`` -> ('0', '0'); ``1\\leq k\\leq r+1`` -> ('1', 'r+1') (``ValueError`` otherwise)."""
    c = re.sub(r"\s+", "", cond)
    m = re.fullmatch(rf"{var}=([^=<>\\]+)", c)
    if m:
        return m.group(1), m.group(1)
    m = re.fullmatch(rf"([^=<>\\]+)\\leq{var}\\leq([^=<>\\]+)", c)
    if m:
        return m.group(1), m.group(2)
    raise ValueError(f"unread condition {cond!r}")


# -- primed constants -------------------------------------------------------------------------------------------
def read_prime_definition(tex: str) -> tuple[tuple[str, str], list[tuple[tuple[str, str, str], str, str, str]]]:
    """A printed definition ``\\rho_{2n,2n-i,L}^{\\prime} = {CONST/c_{2n,K}^{\\alpha}, i=a,..,b; ...}``: ((colour,
    level) of the primed constant, [((colour, first index, level) of CONST, K, first i, last i), ...]); a single case
    ``i=2n-(r+1)`` has first = last."""
    t = _normalize(tex)
    m = re.search(r"\\(rho|gamma|beta)_\{\s*2n\s*,\s*2n-i\s*,([^{}]+)\}\s*\^\{\s*\\prime\s*\}\s*=", t)
    if not m:
        raise ValueError(f"no primed constant defined in {tex[:60]!r}")
    head = (_GREEK[m.group(1)], m.group(2).strip())
    body = t[m.end():]
    cases = []
    pat = re.compile(r"\\frac\s*\{\s*\\(rho|gamma|beta)_\{([^{}]+)\}\s*\}\s*\{\s*c_\{([^{}]+)\}\s*\^\{\s*\\alpha\s*\}"
                     r"\s*\}\s*,\s*(?:&|~)\s*i\s*=\s*(.*?)\s*[,.]?\s*(?=\\\\|\\end|\\\]|$)", re.S)
    for c in pat.finditer(body):
        idx = [p.strip() for p in c.group(2).split(",")]
        cidx = [p.strip() for p in c.group(3).split(",")]
        if len(idx) != 3 or idx[0] != "2n" or len(cidx) != 2 or cidx[0] != "2n":
            raise ValueError(f"unread case {c.group(0)[:40]!r}")
        rng = [p.strip() for p in re.sub(r"\\ldots\s*", lambda _m: "\\ldots", c.group(4)).split(",")]
        if "\\ldots" in rng:
            first, last = rng[0], rng[-1]
            if rng.index("\\ldots") != len(rng) - 2 or len(rng) > 4:
                raise ValueError(f"unread range {c.group(4)!r}")
            if len(rng) == 4:  # a, b, ..., c: b must be a + 1
                from paper_repro.printed.parsed import bound

                def val(e: str, n: int, r: int) -> int:
                    return bound(e.replace("\\left(", "(").replace("\\right)", ")"), n=n, r=r)
                if any(val(rng[1], n, r) != val(rng[0], n, r) + 1 for n in (3, 5) for r in (0, 1)):
                    raise ValueError(f"the listed range {c.group(4)!r} does not step by one")
        elif len(rng) == 1:
            first = last = rng[0]
        else:
            raise ValueError(f"unread range {c.group(4)!r}")
        cases.append(((_GREEK[c.group(1)], idx[1], idx[2]), cidx[1], first, last))
    if not cases:
        raise ValueError(f"no case of the definition read in {tex[:60]!r}")
    return head, cases


# -- parametrizations -------------------------------------------------------------------------------------------
def read_parametrization(tex: str) -> tuple[tuple[tuple[int, int, int], ...], dict[str, tuple[str, str]]]:
    """The printed parametrization ``u_{1}\\left( x,y\\right) & = & x,~x\\in\\left[ 0,\\alpha\\right] ,\\\\ ...``: the
    maps of u, v, w (in this order, as integer linear forms in alpha, x, y) and the printed ranges {x: (lo, hi),
    y: (lo, hi)} (linear forms as printed)."""
    t = tex.replace("%", " ").replace("\\left(", "(").replace("\\right)", ")")
    rows = re.findall(r"([uvw])(?:_\{(\d)\})?\s*\(\s*x\s*,\s*y\s*\)\s*&\s*=\s*&\s*(.*?)(?=\\\\|\\end\{array\})", t,
                      flags=re.S)
    if [r[0] for r in rows] != ["u", "v", "w"] or len({r[1] for r in rows}) != 1:
        raise ValueError(f"not a parametrization of u, v, w: {tex[:60]!r}")
    maps, ranges = [], {}
    for _var, _idx, body in rows:
        parts = re.split(r",\s*~?", body.strip().rstrip(",.").strip(), maxsplit=1)
        maps.append(linear_form(parts[0]))
        if len(parts) > 1 and parts[1].strip():
            m = re.fullmatch(r"\s*([xy])\s*\\in\s*\\left\[\s*([^,\]]+?)\s*,\s*([^\]]+?)\s*\\right\]\s*[,.]?\s*",
                             parts[1])
            if not m or m.group(1) in ranges:
                raise ValueError(f"unread range {parts[1]!r}")
            ranges[m.group(1)] = (m.group(2), m.group(3))
    if set(ranges) != {"x", "y"}:
        raise ValueError(f"ranges of x and y not both printed: {sorted(ranges)}")
    return tuple(maps), ranges


__all__ = ["Factor", "Term", "read_products", "linear_form", "rate", "split_case", "case_range",
           "read_prime_definition", "read_parametrization", "read_sign_function", "sign_of", "row_residue", "listing"]


# -- sign functions (Lemma lem:sign_cos_power_derivative, Proposition derivative_cosine_sine) --------------------
def _condition(cond: str) -> str:
    """A printed case condition as a Python boolean expression in the index letters (see :func:`read_sign_function`).
    ``A=2r`` binds r = A/2 (and requires A even) for the rest of the condition; ``X\\equiv Y(mod M)`` and
    ``X\\equiv\\pm Y(mod M)`` are congruences; ``,~`` and ``\\text{ and }`` are conjunctions, ``\\text{or }``
    a disjunction; ``<``, ``>``, ``\\geq``, ``\\leq``, ``\\neq`` relations."""
    c = cond.replace("\\left(", "(").replace("\\right)", ")").replace("%", " ")
    c = re.sub(r"\\operatorname\{mod\}", "mod", c)
    c = re.sub(r"\\text\{\s*and\s*\}", " and ", c)
    c = re.sub(r"(\\\s)?\\text\{\s*or\s*\}", " or ", c)
    c = re.sub(r",\s*~", " and ", c)
    c = re.sub(r"^\s*~", "", c).strip().rstrip(",.").strip()
    c = c.replace("\\geq", ">=").replace("\\leq", "<=").replace("\\neq", "!=")
    m = re.search(r"([a-z0-9+\-]+)\s*=\s*2r\b", c)
    if m:  # p-i=2r: r is bound by it
        half = f"(({_implicit(m.group(1))})//2)"
        c = c[:m.start()] + f"(({_implicit(m.group(1))})%2==0)" + re.sub(r"\br\b", half, c[m.end():])
    def congruence(mm):
        x, pm, y, mod = mm.group(1), mm.group(2), mm.group(3), mm.group(4)
        x = _implicit(x)
        if pm:
            return f"((({x})-({y}))%{mod}==0 or (({x})+({y}))%{mod}==0)"
        return f"((({x})-({y}))%{mod}==0)"
    c = re.sub(r"([a-z0-9+\-()/%]+?)\s*\\equiv\s*(\\pm)?\s*(\d+)\s*\(\s*mod\s*(\d+)\s*\)", congruence, c)
    c = re.sub(r"(?<![<>!=])=(?!=)", "==", c)
    if "\\" in c or re.search(r"[^\sa-z0-9+\-*/%()<>=!]", c):
        raise ValueError(f"unread condition {cond!r}")
    return c


def _implicit(expr: str) -> str:
    return re.sub(r"(\d)([a-z(])", r"\1*\2", expr)


def read_sign_function(tex: str) -> list[tuple[int, str]]:
    """The branches of a printed sign function ``\\operatorname{sign} X = \\left\\{ \\begin{array}[c]{rl} -1, &
    COND,\\\\ 0, & COND,\\\\ +1, & COND \\end{array}\\right.``: [(value, Python condition), ...] in printed order."""
    t = tex.replace("%", " ")
    m = re.search(r"\\begin\{array\}\s*\[c\]\{rl\}(.*?)\\end\{array\}", t, flags=re.S)
    if not m or "\\operatorname{sign}" not in t:
        raise ValueError(f"no sign function in {tex[:50]!r}")
    out = []
    for row in re.split(r"\\\\", m.group(1)):
        if not row.strip():
            continue
        mm = re.fullmatch(r"\s*([+-]?\d+)\s*,\s*&(.*)", row, flags=re.S)
        if not mm:
            raise ValueError(f"unread branch {row!r}")
        out.append((int(mm.group(1)), _condition(mm.group(2))))
    return out


def sign_of(branches: list[tuple[int, str]], **env: int) -> int | None:
    """The value the printed branches give at ``env``: the one value of the branches whose condition holds; None if
    none holds or holding branches disagree (the printed case analysis gives no single value)."""
    vals = {v for v, c in branches if eval(c, {"__builtins__": {}}, dict(env))}  # noqa: S307 - read above
    return vals.pop() if len(vals) == 1 else None


# -- strict reading of the rows of the proof's equalities -------------------------------------------------------
_ROW_PIECES = (
    r"\\begin\{equation\}", r"\\end\{equation\}", r"\\label\{[^{}]*\}", r"\\nonumber", r"\\displaystyle", r"\\limits",
    r"&", r"\\\\",
)


def row_residue(tex: str) -> str:
    """What a row of a printed equality ``0 = L(u,v,w) = rho_{2n,n,n} R_{2n,n,n}^{\\alpha}(u,v,w) + sum ... ,
    \\forall (u,v,w) in \\Omega^{\\alpha}`` holds besides its head, sums, terms (constant, function of order 2n with
    superscript alpha applied to (u, v, w)), plus signs and the quantifier: '' for a row read completely."""
    t = re.sub(r"\s+", "", tex.replace("%", ""))
    for p in _ROW_PIECES:
        t = re.sub(p, "", t)
    t = re.sub(r"^(0=)?(L|\\widetilde\{L\}|\\widehat\{L\})(_\{[^{}]*\})?\\left\(u,v,w\\right\)=", "", t)
    t = re.sub(r"^=", "", t)
    t = re.sub(r",~?\\forall\\left\(u,v,w\\right\)\\in\\Omega\^\{\\alpha\}[.,]?$", "", t)
    t = re.sub(r",~?\\forall\\left\($", "", t)  # a row the transcription ends inside the quantifier
    t = re.sub(r"\\(rho|gamma|beta)_\{[^{}]*\}[RGB]_\{[^{}]*\}\^\{\\alpha\}\\left\(u,v,w\\right\)", "", t)
    t = re.sub(r"\{?\\sum_\{[^{}]*\}\^\{[^{}]*\}\}?", "", t)
    return t.replace("+", "")


def listing(tex: str, var: str) -> list[tuple[str, str | None, str]]:
    """Every listed range ``var=a,b,\\ldots,c`` (or ``var=a,\\ldots,c``) of ``tex``: [(a, b or None, c), ...] as
    printed (``\\left( .. \\right)`` -> parentheses)."""
    t = re.sub(r"\s*\\right\)", ")", re.sub(r"\\left\(\s*", "(", tex.replace("%", " ")))
    out = []
    pat = rf"(?<![\w\\]){var}\s*=\s*([^,=$]+?)\s*,(?:\s*([^,=$]+?)\s*,)?\s*\\ldots\s*,\s*([^,.\s$]+)"
    for m in re.finditer(pat, t):
        out.append((m.group(1).strip(), m.group(2).strip() if m.group(2) else None, m.group(3).strip()))
    return out
