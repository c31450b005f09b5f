r"""The one reader of the paper's mathematics: a lark (LALR) grammar of the notation of Roth, Juhasz, Kristaly
(arXiv 1309.4747) that turns the verbatim LaTeX of a transcribed line into sympy objects.

API (names fixed by the common brief):

* :func:`parse` -- one expression -> ``sympy.Expr`` (or a ``sympy.Matrix`` for a bracketed array);
* :func:`parse_relation` -- a relation chain ``a = b \leq c`` with its trailing conditions
  (``,~\forall x\in\left[0,\alpha\right]``, ``,~i=0,1,\ldots,2n``) -> :class:`Relation`;
* :func:`parse_cases` -- the rows of a ``\left\{\begin{array}{rl} v, & cond \\ ...\end{array}\right.`` display
  -> ``[(value, condition), ...]`` (condition: a sympy boolean, or the text when it is not mathematics);
* :func:`parse_vector` -- ``\left[\begin{array}{ccc} a & b & c\end{array}\right]^{T}`` -> ``sympy.Matrix``;
* :func:`index_set` -- ``_{j=0,i=j}^{n,2n-j}`` -> ``[(j, 0, n), (i, j, 2*n - j)]``;
* :class:`LatexMathError` (a ``ValueError``) on anything unread, naming the unread part.

Notation (see ``docs/latex_reader.md`` for the whole list):

* juxtaposition multiplies (``2n`` is ``2*n``, ``ru`` is ``r*u``); ``\cdot`` multiplies;
* ``\sin^{k}\frac{u}{2}`` is ``sin(u/2)**k``; a function's argument is the next atom (a ``\frac``, a
  parenthesis, a group, a symbol with its indices, optionally preceded by a number: ``\sin 2\alpha``);
* greek letters are Symbols named ``alpha``, ``varrho``, ``mu``, ...; ``\pi`` is ``sympy.pi``;
* an indexed name ``X_{a,b,c}^{\alpha}`` is ``Function(X)(a, b, c)`` (the tag ``^{\alpha}`` is dropped,
  ``^{\prime}`` makes ``X_prime``, any other superscript ``s`` makes ``X_sup(a, b, c, s)``); ``\overline{R}`` is
  ``Rbar``, ``\mathbf{r}`` is ``r_vec``, ``\mathcal{V}`` is ``Vcal``, ``\widetilde{L}`` is ``Ltilde``,
  ``\widehat{L}`` is ``Lhat``; an argument list ``\left(u,v,w\right)`` right after an indexed (or capital) name
  is appended as a final ``sympy.Tuple(u, v, w)``;
* ``\binom``/``\dbinom`` -> ``binomial``; ``\left\lfloor..\right\rfloor`` -> ``floor``;
  ``\sum_{i=a}^{b}`` -> ``sympy.Sum`` (its body is the product that follows: it ends at the next ``+``/``-``);
* ``\frac{\partial^{r}}{\partial v^{r-k}\partial w^{k}}X`` and ``\frac{\text{d}^{p}}{\text{d}t^{p}}X`` ->
  ``D(X, Tuple(v, r - k), Tuple(w, k))`` with ``D = Function('D')`` (unevaluated; the numerator's order must be
  the sum of the denominator's orders, else :class:`LatexMathError`);
* ``\left. X\right\vert_{y=0}`` -> ``sympy.Subs(X, y, 0)``; ``\lim_{\alpha\rightarrow0} X`` -> ``sympy.Limit``;
* ``a \pm b`` -> ``a + pm*b`` and ``a \mp b`` -> ``a - pm*b`` with the one Symbol ``pm`` (so a chain keeps the
  upper/lower sign together);
* ``\left\{ X : cond \right\}_{i=0}^{2n}`` -> ``Family(X, Tuple(cond...), Tuple(Tuple(i, 0, 2n)))``
  (``Function('Family')``; a list of members is a ``Tuple``);
* intervals ``\left[a,b\right]`` -> ``sympy.Interval``; a parenthesised list ``\left(u,v,w\right)`` -> ``Tuple``;
* colour macros ``\Red{..}`` etc., ``%`` comments, ``\left``/``\right``, spacing, ``\displaystyle``, ``\limits``,
  ``\label``, ``\nonumber``, alignment ``&`` and row breaks ``\\`` (outside arrays) are ignored;
  ``\underset{..}{\overset{..}{=}}`` is ``=``.

Refused (raises :class:`LatexMathError`): unknown macros, ``\text{...}`` other than ``\text{d}``/``and``/``or``,
unbalanced braces, a run of two or more capital letters (a word such as ``XXX``, never the paper's notation), a
word of four or more lower-case letters, anything the grammar does not read.

>>> parse(r"\sin^{2}\frac{\alpha}{2}")
sin(alpha/2)**2
>>> parse(r"c_{2n,i}^{\alpha}")
c(2*n, i)
>>> parse(r"\sum_{i=0}^{2n}\binom{2n}{i}")
Sum(binomial(2*n, i), (i, 0, 2*n))
>>> r = parse_relation(r"c_{2n,i}^{\alpha}=c_{2n,2n-i}^{\alpha},~i=0,1,\ldots,n.")
>>> r.parts, r.ops
([c(2*n, i), c(2*n, -i + 2*n)], ['='])
>>> r.conditions[0].parts, r.conditions[0].ops
([i, (0, 1, ldots, n)], ['in'])
>>> index_set(r"\left\{ R_{2n,2n-i,j} \right\} _{j=0,i=j}^{n,2n-j}")
[(j, 0, n), (i, j, -j + 2*n)]
"""

from __future__ import annotations

import dataclasses
import functools
import re
from dataclasses import dataclass, field
from typing import Any

import sympy
from lark import Lark, Token, Transformer
from lark.exceptions import LarkError, UnexpectedCharacters, UnexpectedEOF, UnexpectedInput

__all__ = ["LatexMathError", "Relation", "parse", "parse_relation", "parse_cases", "parse_vector", "index_set",
           "inline_math", "prose", "sentence", "NUMBER_WORDS", "evaluate_sums", "Term", "terms", "untagged",
           "parse_conditions", "summands", "underset_marks", "clean", "strip_comments", "D", "Family", "Cartesian",
           "Cases", "PM", "Chain", "chain_relation"]


class LatexMathError(ValueError):
    """A part of the LaTeX this reader does not read (the message names the part)."""


D = sympy.Function("D")
Family = sympy.Function("Family")
#: ``\left\{..\right\} \times\left\{..\right\}``: the Cartesian product of sets, its factors in the printed order
Cartesian = sympy.Function("Cartesian")
Cases = sympy.Function("Cases")
#: a case value printed as a relation chain (``\left[ w\right] \in E_{1}^{\alpha}/_{\sim}``) inside an expression:
#: ``Chain(part, Symbol(op), part, ..)``; :func:`chain_relation` gives the :class:`Relation` back
Chain = sympy.Function("Chain")
PM = sympy.Symbol("pm")
LDOTS = sympy.Symbol("ldots")

GREEK = ("alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta", "vartheta", "iota",
         "kappa", "lambda", "mu", "nu", "xi", "rho", "varrho", "sigma", "tau", "upsilon", "phi", "varphi", "chi",
         "psi", "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Sigma", "Phi", "Psi", "Omega", "ell")
FUNCS = {"sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan, "cot": sympy.cot, "exp": sympy.exp,
         "ln": sympy.log, "log": sympy.log, "sign": sympy.sign, "dim": sympy.Function("dim"),
         "span": sympy.Function("span"), "det": sympy.Function("det"), "min": sympy.Function("min"),
         "max": sympy.Function("max")}
COLOURS = ("Red", "Green", "Blue", "Orange", "Cyan", "Magenta", "Purple", "Brown")
DECOR = {"overline": "bar", "mathbf": "_vec", "mathcal": "cal", "widetilde": "tilde", "widehat": "hat",
         "mathbb": "_bb", "bar": "bar", "tilde": "tilde", "hat": "hat", "boldsymbol": "_vec"}
# macros the tokenizer reads after clean() (anything else is an unknown macro)
KNOWN = set(GREEK) | set(FUNCS) | {"ROWBREAK", "frac", "sqrt",
    "binom", "sum", "lim", "partial", "dd", "cdot", "times", "pm", "mp", "neq", "ne", "leq", "le", "geq",
    "ge", "in", "notin", "sim", "nsim", "equiv", "rightarrow", "to", "forall", "exists", "ldots", "lfloor", "rfloor",
    "prime", "pi", "infty", "LDOT", "RDOT", "RVERT", "AND", "OR", "pmod", "cup", "setminus", "subset",
    "subseteq", "approx", "{", "}"}


# --------------------------------------------------------------------------------------------------- cleaning
def _match_brace(s: str, i: int) -> int:
    """Index of the ``}`` that closes the ``{`` at ``s[i]``."""
    depth = 0
    for k in range(i, len(s)):
        c = s[k]
        if c == "\\":
            continue
        if c == "{" and (k == 0 or s[k - 1] != "\\"):
            depth += 1
        elif c == "}" and (k == 0 or s[k - 1] != "\\"):
            depth -= 1
            if depth == 0:
                return k
    raise LatexMathError(f"unbalanced braces: no '}}' closes the '{{' of {s[i:i + 40]!r}")


def _check_balance(s: str) -> None:
    depth = 0
    for k, c in enumerate(s):
        if c in "{}" and k and s[k - 1] == "\\":
            continue
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth < 0:
                raise LatexMathError(f"unbalanced braces: '}}' without '{{' at {s[max(0, k - 30):k + 10]!r}")
    if depth:
        raise LatexMathError(f"unbalanced braces: {depth} '{{' never closed in {s[:60]!r}")


def _group_args(s: str, start: int, count: int) -> tuple[list[str], int]:
    """``count`` brace groups starting at or after ``start`` (whitespace skipped): contents and end index."""
    out = []
    k = start
    for _ in range(count):
        while k < len(s) and s[k].isspace():
            k += 1
        if k >= len(s) or s[k] != "{":
            raise LatexMathError(f"expected a {{group}} at {s[start:start + 40]!r}")
        e = _match_brace(s, k)
        out.append(s[k + 1:e])
        k = e + 1
    return out, k


def _replace_macro(s: str, name: str, nargs: int, fn) -> str:
    pat = re.compile(r"\\" + name + r"(?![A-Za-z])")
    while True:
        m = pat.search(s)
        if not m:
            return s
        args, end = _group_args(s, m.end(), nargs)
        s = s[:m.start()] + fn(*args) + s[end:]


_ARRAY_BEGIN = re.compile(r"\\begin\s*\{array\}\s*(\[[a-z]\])?\s*\{[^{}]*\}")
_TEXT = re.compile(r"\\(?:text|emph)\s*\{([^{}]*)\}")  # \emph{~} in a formula: an (emphasized) space


def _decor(kind: str, inner: str) -> str:
    inner = inner.strip()
    m = re.fullmatch(r"\\?([A-Za-z]+)", inner)
    if not m:
        raise LatexMathError(f"\\{kind}{{{inner}}}: only a letter or a greek name is read under \\{kind}")
    suffix = DECOR[kind]
    name = m.group(1) + suffix if suffix.startswith("_") else m.group(1) + suffix
    return f" @{name}@ "


def strip_comments(tex: str) -> str:
    r"""The LaTeX with its comments out (an unescaped ``%`` to the end of its line, line break included, becomes one
    space), nothing else changed: for a text shown as printed (an erratum's cell), where :func:`clean` would also
    drop ``\left``/``\right`` and the layout.

    >>> strip_comments("\\left( u\\right) %\n& 50\\%")
    '\\left( u\\right)  & 50\\%'
    """
    if not isinstance(tex, str):
        raise TypeError(f"tex must be a str, got {type(tex).__name__}")
    return re.sub(r"(?<!\\)%[^\n]*\n?", " ", tex)


def clean(tex: str, arrays: list | None = None) -> str:
    r"""The verbatim with everything typographical removed (see the module docstring); arrays are replaced by
    placeholders ``@ARRk@`` whose rows are stored in ``arrays`` (a list: ``(kind, rows)``).

    >>> clean(r"\Red{\mathbf{r}_{4,4,0}}%" "\n" r"& =\left( u\right) ,\label{x}")
    '{ @r_vec@ _{4,4,0}} = ( u )'
    """
    s = tex
    s = re.sub(r"(?<!\\)%\s*", "", s)
    _check_balance(s)
    s = re.sub(r"\\label\s*\{[^{}]*\}", " ", s)
    s = re.sub(r"\\(ref|eqref)\s*\{[^{}]*\}", " ", s)
    s = re.sub(r"\\(nonumber|normalcolor|displaystyle|textstyle|limits|notag|quad|qquad|medskip|noindent)"
               r"(?![A-Za-z])", " ", s)
    s = re.sub(r"\\(begin|end)\s*\{(equation\*?|align\*?|eqnarray\*?|gather\*?|multline\*?)\}", " ", s)
    s = s.replace(r"\[", " ").replace(r"\]", " ").replace("$", " ")
    s = re.sub(r"\\(" + "|".join(COLOURS) + r")\s*\{", "{", s)
    s = _replace_macro(s, "underset", 2, lambda a, b: b)
    s = _replace_macro(s, "overset", 2, lambda a, b: b)
    s = _replace_macro(s, "underbrace", 1, lambda a: "{" + a + "}")  # after underset: \underset{..}{\underbrace{X}}
    s = _replace_macro(s, "operatorname", 1, lambda a: "\\" + a.strip() + " ")
    for kind in DECOR:
        s = _replace_macro(s, kind, 1, functools.partial(_decor, kind))
    s = re.sub(r"\\(dfrac|tfrac|cfrac)(?![A-Za-z])", r"\\frac", s)
    s = re.sub(r"\\(dbinom|tbinom)(?![A-Za-z])", r"\\binom", s)

    def text(m: re.Match) -> str:
        t = m.group(1).strip()
        if t == "d":
            return " \\dd "
        if t in ("", ".", ",", ";", "~"):
            return " "
        if t == "and":
            return " \\AND "
        if t == "or":
            return " \\OR "
        raise LatexMathError(f"prose in {m.group(0)} is not mathematics")

    s = _TEXT.sub(text, s)
    s = re.sub(r"\\(mathrm|mathit|mbox)\s*\{\s*d\s*\}", " \\\\dd ", s)
    s = re.sub(r"\\left\s*\\\{", r"\\{", s)
    s = re.sub(r"\\right\s*\\\}", r"\\}", s)
    s = re.sub(r"\\left\s*\.", r" \\LDOT ", s)
    s = re.sub(r"\\right\s*\.", r" \\RDOT ", s)
    s = re.sub(r"\\right\s*(\\vert|\|)", r" \\RVERT ", s)
    s = re.sub(r"\\(left|right|bigl|bigr|Bigl|Bigr|big|Big)\s*(?=[()\[\]|]|\\lfloor|\\rfloor)", " ", s)
    s = re.sub(r"\\\\(\[[^\]]*\])?", r" \\ROWBREAK ", s)
    s = re.sub(r"\\(,|;|:|!| )", " ", s).replace("~", " ")
    s = re.sub(r"\(\s*\\(pmod|mod)\s*([^()]*?)\s*\)", r" \\pmod{\2} ", s)
    s = re.sub(r"\\(cdots|dots|ldots|dotsc)(?![A-Za-z])", r"\\ldots", s)
    s = re.sub(r"\\(ne)(?![A-Za-z])", r"\\neq", s)
    s = re.sub(r"\\(le)(?![A-Za-z])", r"\\leq", s)
    s = re.sub(r"\\(ge)(?![A-Za-z])", r"\\geq", s)
    s = re.sub(r"\\(mod)(?![A-Za-z])", r"\\pmod", s)
    s = re.sub(r"\\(to|longrightarrow)(?![A-Za-z])", r"\\rightarrow", s)
    # {\sum_{..}^{..}} -> \sum_{..}^{..}
    while True:
        m = re.search(r"\{\s*\\sum(?![A-Za-z])", s)
        if not m:
            break
        e = _match_brace(s, m.start())
        s = s[:m.start()] + " " + s[m.start() + 1:e] + " " + s[e + 1:]
    # arrays -> placeholders
    while True:
        m = _ARRAY_BEGIN.search(s)
        if not m:
            break
        e = s.find(r"\end", m.end())
        e2 = re.compile(r"\\end\s*\{array\}").search(s, m.end())
        opened = e < 0 or e2 is None
        end = len(s) if opened else e2.start()
        body = s[m.end():end]
        rows = body.split("\\ROWBREAK")
        cells = [[c.strip() for c in r.split("&")] for r in rows]
        while cells and all(not c for c in cells[-1]):
            cells.pop()
        k = len(arrays) if arrays is not None else 0
        if arrays is not None:
            arrays.append(cells)
        tail = " \\RDOT " if opened and re.search(r"\\\{\s*$", s[:m.start()]) else " "
        s = s[:m.start()] + f" @ARR{k}@" + tail + ("" if opened else s[e2.end():])
    s = s.replace("&", " ")
    s = s.replace("\\ROWBREAK", " ")
    s = re.sub(r"\s+", " ", s).strip()
    # trailing punctuation
    s = re.sub(r"[\s,.;]+$", "", s)
    for mac in re.findall(r"\\([A-Za-z]+|.)", s):
        if mac not in KNOWN:
            raise LatexMathError(f"unknown macro \\{mac}")
    for word in re.findall(r"(?<![\\A-Za-z@])[A-Za-z]{2,}(?![A-Za-z@])", s):
        if sum(c.isupper() for c in word) >= 2 or len(word) >= 4:
            raise LatexMathError(f"the word {word!r} is not the paper's notation")
    return s


# --------------------------------------------------------------------------------------------------- grammar
GRAMMAR = r"""
start_relation: relation
start_expr: expr
start_conditions: cond ("," cond)*

relation: expr (relop expr)*          -> rel
        | relop expr (relop expr)*    -> lead_rel

cond: relation                        -> cond_rel
    | FORALL relation                 -> cond_forall
    | cond AND cond                   -> cond_and
    | cond OR cond                    -> cond_or

relop: EQ | NEQ | LEQ | GEQ | LT | GT | IN | NOTIN | SIM | NSIM | EQUIV | SUBSET | APPROX | RIGHTARROW

?expr: expr "+" term                  -> add
     | expr "-" term                  -> sub
     | expr PM term                   -> pm
     | expr MP term                   -> mp
     | expr CUP term                  -> cup
     | expr SETMINUS term             -> setminus
     | "-" term                       -> neg
     | "+" term
     | CUP term                       -> cup_unary
     | PM term                        -> pm_unary
     | MP term                        -> mp_unary
     | term

?term: term factor                    -> mul
     | term CDOT factor               -> mul_dot
     | term "/" factor                -> div
     | prefix term                    -> apply_prefix
     | term prefix term               -> mul_prefix
     | term CDOT prefix term          -> mul_dot_prefix
     | term MODP "{" expr "}"         -> modp
     | term MODP NUMBER               -> modp
     | term "/" "_" "{" SIM ","? "}"  -> quotient
     | factor

prefix: SUM "_" "{" (NAMEVAR | GREEKV) "=" expr "}" "^" sarg                         -> sum_prefix
      | LIM "_" "{" (NAMEVAR | GREEKV) RIGHTARROW expr "}"                           -> lim_prefix
      | FRAC "{" DIFF ("^" sarg)? "}" "{" dvar+ "}"                            -> deriv_prefix
      | BIGCUP "{" (NAMEVAR | GREEKV) "=" expr "}" "^" sarg                          -> cup_prefix

dvar: DIFF dbase                      -> dvar
    | DIFF dbase "^" sarg             -> dvar_pow
dbase: NAMEVAR | GREEKV | NAMEVAR "_" sarg -> dbase

?factor: func
       | atom

func: FUNC atom                       -> func
    | FUNC func                       -> func
    | FUNC "^" sarg atom              -> func_pow
    | FUNC NUMBER atom                -> func_num
    | FUNC "^" sarg NUMBER atom       -> func_pow_num

?atom: primary
     | primary "^" sarg               -> power
     | GREEKV "^" sarg                -> greek_power
     | primary "!"                    -> factorial

?primary: NUMBER                      -> number
        | NAMEVAR                     -> symbol
        | GREEKV                      -> symbol
        | CAPVAR                      -> symbol
        | PI                          -> pi
        | INFTY                       -> infty
        | LDOTS                       -> ldots
        | indexed
        | indexed "(" exprlist ")"    -> applied
        | CAPVAR "(" exprlist ")"     -> applied_cap
        | NAMED "(" exprlist ")"      -> applied_named
        | "(" expr ")"                -> paren
        | "(" expr "," exprlist ")"   -> tuple
        | "[" expr "," expr "]"       -> interval
        | "(" expr "," expr "]"       -> interval_lopen
        | "[" expr "," expr ")"       -> interval_ropen
        | "[" expr "," expr "," exprlist "]" -> bracket_list
        | SQRT "{" expr "}"           -> sqrt
        | "[" expr "]"                -> bracket
        | "{" expr "}"                -> paren
        | "{" "}"                     -> empty_group
        | FRAC "{" expr "}" "{" expr "}"   -> frac
        | BINOM "{" expr "}" "{" expr "}"  -> binom
        | LFLOOR expr RFLOOR          -> floor
        | LDOT expr RVERT "_" "{" NAMEVAR "=" expr "}" -> evalbar
        | LSET setbody RSET           -> family
        | LSET setbody RSET "_" "{" bindings "}" "^" "{" exprlist "}" -> family_bounded
        | LSET setbody RSET "_" "{" NAMEVAR GEQ expr "}"  -> family_from
        | LSET ARRAY RDOT             -> cases
        | ARRAY                       -> array
        | NAMED                       -> named

indexed: (NAMEVAR | CAPVAR | GREEKV | NAMED) "_" sarg                 -> indexed
       | (NAMEVAR | CAPVAR | GREEKV | NAMED) "_" sarg "^" sarg        -> indexed_sup
       | (CAPVAR | NAMED | GREEKV) "^" TAGSUP                          -> tagged
       | (CAPVAR | NAMED | GREEKV) "^" TAGSUP "_" sarg                 -> indexed_sup_first
       | (CAPVAR | NAMED | GREEKV) "^" sarg "_" sarg                   -> indexed_sup_before

sarg: "{" exprlist "}"                -> sarg_group
    | "{" "}"                         -> sarg_empty
    | NUMBER                          -> sarg_num
    | NAMEVAR                         -> sarg_sym
    | GREEKV                          -> sarg_sym
    | PRIME                           -> sarg_prime
    | "{" PRIME "}"                   -> sarg_prime

exprlist: expr ("," expr)*
bindings: binding ("," binding)*
binding: NAMEVAR "=" expr
       | GREEKV "=" expr
setbody: relation ("," relation)* (COLON cond ("," cond)*)?
COLON: ":"

TAGSUP: /\{\s*\\alpha\s*\}/
FRAC: /\\frac(?![A-Za-z])/
SQRT: /\\sqrt(?![A-Za-z])/
BINOM: /\\binom(?![A-Za-z])/
SUM: /\\sum(?![A-Za-z])/
LIM: /\\lim(?![A-Za-z])/
DIFF: /\\(partial|dd)(?![A-Za-z])/
FUNC: /\\(sin|cos|tan|cot|exp|ln|log|sign|dim|span|det|min|max)(?![A-Za-z])/
GREEKV: /\\(GREEKNAMES)(?![A-Za-z])/
PI: /\\pi(?![A-Za-z])/
INFTY: /\\infty(?![A-Za-z])/
LDOTS: /\\ldots(?![A-Za-z])/
PRIME: /\\prime(?![A-Za-z])/
CDOT: /\\(cdot|times)(?![A-Za-z])/
PM: /\\pm(?![A-Za-z])/
MP: /\\mp(?![A-Za-z])/
CUP: /\\cup(?![A-Za-z])/
BIGCUP.2: /\\cup\s*_/
SETMINUS: /\\setminus(?![A-Za-z])/
MODP: /\\pmod(?![A-Za-z])/
FORALL: /\\forall(?![A-Za-z])/
AND: /\\AND(?![A-Za-z])/
OR: /\\OR(?![A-Za-z])/
LFLOOR: /\\lfloor(?![A-Za-z])/
RFLOOR: /\\rfloor(?![A-Za-z])/
LDOT: /\\LDOT(?![A-Za-z])/
RDOT: /\\RDOT(?![A-Za-z])/
RVERT: /\\RVERT(?![A-Za-z])/
LSET: "\\{"
RSET: "\\}"
EQ: "="
NEQ: /\\neq(?![A-Za-z])/
LEQ: /\\leq(?![A-Za-z])/
GEQ: /\\geq(?![A-Za-z])/
LT: "<"
GT: ">"
IN: /\\in(?![A-Za-z])/
NOTIN: /\\notin(?![A-Za-z])/
SIM: /\\sim(?![A-Za-z])/
NSIM: /\\nsim(?![A-Za-z])/
EQUIV: /\\equiv(?![A-Za-z])/
SUBSET: /\\subseteq?(?![A-Za-z])/
APPROX: /\\approx(?![A-Za-z])/
RIGHTARROW: /\\rightarrow(?![A-Za-z])/
ARRAY: /@ARR\d+@/
NAMED: /@[A-Za-z_]+@/
NUMBER: /\d+/
NAMEVAR: /[a-z]/
CAPVAR: /[A-Z]/

%import common.WS
%ignore WS
"""


@functools.cache
def _parser() -> Lark:
    """The LALR parser (built once: about 0.2 s), with the sympy builder run during the parse (no tree is kept:
    the builder's ``arrays`` is set before each parse, so one parse at a time per process)."""
    return Lark(GRAMMAR.replace("GREEKNAMES", "|".join(GREEK)), parser="lalr",
                start=["start_relation", "start_expr", "start_conditions"],
                maybe_placeholders=False, transformer=_BUILDER)


# --------------------------------------------------------------------------------------------------- values
@dataclass
class Relation:
    """A relation chain ``parts[0] ops[0] parts[1] ops[1] ...`` (``len(ops) == len(parts) - 1``).

    ``lead`` is the operator a continuation row starts with (``= & x`` has ``lead='='`` and ``parts=[x]``).
    ``conditions`` are the trailing clauses (``,~\\forall x\\in[0,\\alpha]``, ``,~i=0,1,\\ldots,2n``) as
    Relations; ``quantifier`` is ``'forall'`` (``'exists'``) on a clause that carries ``\\forall``
    (``\\exists``).  The op ``'equiv'`` has as right part ``Tuple(b, m)`` for ``a \\equiv b \\pmod{m}``; ``'in'``
    with a ``Tuple`` right part is a listed range ``i=0,1,\\ldots,2n`` (``ldots`` is the Symbol ``ldots``).
    ``continues`` is the operator (``'+'``, ``'-'``, ``'*'``) a row ends with when the next row continues it, or
    ``'forall'`` for a row that ends inside a clause (``,~\\forall\\left(``) the next row goes on with;
    ``unfinished`` the cleaned text of any other last clause that opens a parenthesis the next row closes.
    """

    parts: list[Any]
    ops: list[str]
    lead: str | None = None
    conditions: list[Relation] = field(default_factory=list)
    quantifier: str | None = None
    continues: str | None = None
    unfinished: str | None = None  # a last clause the next transcribed row finishes (``\forall (``), cleaned text

    def as_boolean(self):
        """The chain as a sympy boolean (``And`` of each link); ``in``/``sim`` links are refused."""
        links = []
        for a, op, b in zip(self.parts, self.ops, self.parts[1:]):
            links.append(_link(a, op, b))
        return sympy.And(*links)


def _link(a, op, b):
    if op == "=":
        return sympy.Eq(a, b, evaluate=False)
    if op == "!=":
        return sympy.Ne(a, b, evaluate=False)
    if op == "<=":
        return sympy.Le(a, b, evaluate=False)
    if op == ">=":
        return sympy.Ge(a, b, evaluate=False)
    if op == "<":
        return sympy.Lt(a, b, evaluate=False)
    if op == ">":
        return sympy.Gt(a, b, evaluate=False)
    if op == "equiv":
        rhs, m = b.args
        return sympy.Eq(sympy.Mod(a - rhs, m), 0, evaluate=False)
    if op == "in" and isinstance(b, sympy.Set):
        return sympy.Contains(a, b, evaluate=False)
    raise LatexMathError(f"the relation {op!r} has no boolean value")


_OPS = {"EQ": "=", "NEQ": "!=", "LEQ": "<=", "GEQ": ">=", "LT": "<", "GT": ">", "IN": "in", "NOTIN": "notin",
        "SIM": "sim", "NSIM": "nsim", "EQUIV": "equiv", "SUBSET": "subset", "APPROX": "approx",
        "RIGHTARROW": "->"}
_TAG = sympy.Symbol("alpha")


def _name(tok) -> str:
    t = str(tok)
    if t.startswith("@"):
        return t.strip("@")
    if t.startswith("\\"):
        return t[1:]
    return t


def _fn(name: str, args: list) -> sympy.Expr:
    return sympy.Function(name)(*args)


class _Build(Transformer):
    def __init__(self, arrays: list):
        super().__init__()
        self.arrays = arrays

    # starts
    def start_relation(self, c):
        return c[0]

    def start_expr(self, c):
        return c[0]

    def start_conditions(self, c):
        return list(c)

    # relations
    def relop(self, c):
        return _OPS[c[0].type]

    def _chain(self, items):
        parts, ops = [items[0]], []
        for k in range(1, len(items), 2):
            op, part = items[k], items[k + 1]
            if op == "equiv" and not (isinstance(part, sympy.Tuple) and getattr(part, "_is_mod", False)):
                pass
            ops.append(op)
            parts.append(part)
        return parts, ops

    def rel(self, c):
        parts, ops = self._chain(c)
        if not ops:
            return parts[0]
        return Relation(parts, ops)

    def lead_rel(self, c):
        lead = c[0]
        parts, ops = self._chain(c[1:])
        return Relation(parts, ops, lead=lead)

    def cond_rel(self, c):
        return c[0]

    def cond_forall(self, c):
        r = c[1]
        if not isinstance(r, Relation):
            r = Relation([r], [])
        r.quantifier = "forall"
        return r

    def cond_and(self, c):
        return ("and", c[0], c[2])

    def cond_or(self, c):
        return ("or", c[0], c[2])

    # arithmetic
    def add(self, c):
        if _ORDERED and all(isinstance(x, sympy.Expr) for x in c):
            return sympy.Add(c[0], c[1], evaluate=False)
        return c[0] + c[1]

    def sub(self, c):
        if _ORDERED and all(isinstance(x, sympy.Expr) for x in c):
            return sympy.Add(c[0], -c[1], evaluate=False)
        return c[0] - c[1]

    def pm(self, c):
        return c[0] + PM * c[2]

    def mp(self, c):
        return c[0] - PM * c[2]

    def pm_unary(self, c):
        if isinstance(c[1], sympy.Tuple) and len(c[1]) == 2:  # \equiv\pm1 \pmod{4}: the sign of the residue
            return sympy.Tuple(PM * c[1][0], c[1][1])
        return PM * c[1]

    def mp_unary(self, c):
        if isinstance(c[1], sympy.Tuple) and len(c[1]) == 2:
            return sympy.Tuple(-PM * c[1][0], c[1][1])
        return -PM * c[1]

    def cup(self, c):
        return sympy.Function("cup")(c[0], c[2])

    def setminus(self, c):
        return sympy.Function("setminus")(c[0], c[2])

    def cup_unary(self, c):
        return sympy.Function("cup")(c[1])

    def mul_prefix(self, c):
        return self.mul([c[0], self.apply_prefix(c[1:])])

    def mul_dot_prefix(self, c):
        return self.mul([c[0], self.apply_prefix(c[2:])])

    def neg(self, c):
        return -c[0]

    def mul(self, c):
        a, b = c
        if isinstance(b, sympy.Tuple):
            if isinstance(a, sympy.Symbol):
                return _fn(a.name, [b])
            raise LatexMathError(f"a list {tuple(b)} multiplied by {a}")
        if isinstance(a, sympy.Tuple):
            raise LatexMathError(f"a list {tuple(a)} multiplied by {b}")
        if isinstance(a, sympy.Set) or isinstance(b, sympy.Set):
            return sympy.ProductSet(a, b)
        if isinstance(a, sympy.MatrixBase) or isinstance(b, sympy.MatrixBase):
            return a * b
        return sympy.Mul(a, b)

    def mul_dot(self, c):
        sets = [x for x in (c[0], c[2]) if getattr(x, "func", None) in (Family, Cartesian)]
        if str(c[1]) == "\\times" and len(sets) == 2:  # a product of sets: sympy's Mul would reorder the factors
            return Cartesian(*(a for x in sets for a in (x.args if x.func == Cartesian else (x,))))
        return self.mul([c[0], c[2]])

    def div(self, c):
        return c[0] / c[1]

    def modp(self, c):
        return sympy.Tuple(c[0], c[2])

    def apply_prefix(self, c):
        kind, data = c[0]
        body = c[1]
        if kind == "cup":  # \cup_{i=a}^{b} X: the union of the family {X}_{i=a}^{b}
            return sympy.Function("bigcup")(Family(_as_basic(body), sympy.Tuple(), sympy.Tuple(sympy.Tuple(*data))))
        if kind == "sum":
            var, lo, hi = data
            return sympy.Sum(body, (var, lo, hi))
        if kind == "lim":
            var, to = data
            return sympy.Limit(body, var, to)
        return D(body, *data)

    def sum_prefix(self, c):
        return ("sum", (sympy.Symbol(_name(c[1])), c[2], c[3]))

    def cup_prefix(self, c):
        return ("cup", (sympy.Symbol(_name(c[1])), c[2], self._scalar(c[3])))

    def quotient(self, c):
        """``E_{n}^{\\alpha}/_{\\sim}`` (also as printed once, ``/_{\\sim,}``): the quotient set ``quot(E(n))``."""
        return sympy.Function("quot")(_as_basic(c[0]))

    def lim_prefix(self, c):
        return ("lim", (sympy.Symbol(_name(c[1])), c[3]))

    def deriv_prefix(self, c):
        kinds = {str(t) for t in c if isinstance(t, Token) and t.type == "DIFF"}
        if len(kinds) > 1:
            raise LatexMathError("a derivative mixes \\partial and d")
        rest = [x for x in c if not isinstance(x, Token)]
        if rest and not isinstance(rest[0], tuple):
            order, dvars = self._scalar(rest[0]), rest[1:]
        else:
            order, dvars = sympy.Integer(1), rest
        total = sum((o for _, o in dvars), sympy.Integer(0))
        if sympy.simplify(total - order) != 0:
            raise LatexMathError(f"derivative order {order} in the numerator but {total} in the denominator")
        return ("deriv", [sympy.Tuple(v, o) for v, o in dvars])

    def dvar(self, c):
        return (c[1], sympy.Integer(1))

    def dvar_pow(self, c):
        return (c[1], self._scalar(c[2]))

    def dbase(self, c):
        base = sympy.Symbol(_name(c[0]))
        if len(c) == 2:
            return _fn(str(base), list(c[1]))
        return base

    # functions
    def func(self, c):
        name, arg = _name(c[0]), c[1]
        if name in ("min", "max") and isinstance(arg, sympy.Function) and arg.func == Family \
                and not arg.args[1] and not arg.args[2]:  # \min\left\{a,b,c\right\}: a listed set, no condition
            members = arg.args[0].args if isinstance(arg.args[0], sympy.Tuple) else (arg.args[0],)
            return (sympy.Min if name == "min" else sympy.Max)(*members)
        return FUNCS[name](arg)

    def func_pow(self, c):
        return FUNCS[_name(c[0])](c[2]) ** self._scalar(c[1])

    def func_num(self, c):
        return FUNCS[_name(c[0])](sympy.Integer(str(c[1])) * c[2])

    def func_pow_num(self, c):
        return FUNCS[_name(c[0])](sympy.Integer(str(c[2])) * c[3]) ** self._scalar(c[1])

    def _scalar(self, s):
        if isinstance(s, sympy.Tuple):
            if len(s) != 1:
                raise LatexMathError(f"a list {tuple(s)} where one exponent is read")
            return s[0]
        if s == "prime":
            raise LatexMathError("\\prime where an exponent is read")
        return s

    def power(self, c):
        base, e = c
        if e == "prime":
            if isinstance(base, sympy.Symbol):
                return sympy.Symbol(base.name + "_prime")
            raise LatexMathError("\\prime on an expression")
        e = self._scalar(e)
        if isinstance(base, sympy.MatrixBase):
            if e == sympy.Symbol("T"):
                return base.T
            raise LatexMathError("a matrix power other than ^{T}")
        return sympy.Pow(base, e)

    # atoms
    def number(self, c):
        return sympy.Integer(str(c[0]))

    def symbol(self, c):
        return sympy.Symbol(_name(c[0]))

    def pi(self, c):
        return sympy.pi

    def infty(self, c):
        return sympy.oo

    def ldots(self, c):
        return LDOTS

    def named(self, c):
        return sympy.Symbol(_name(c[0]))

    def paren(self, c):
        return c[0]

    def empty_group(self, c):
        raise LatexMathError("an empty group {}")

    def tuple(self, c):
        return sympy.Tuple(c[0], *c[1])

    def interval(self, c):
        return sympy.Interval(c[0], c[1])

    def interval_lopen(self, c):
        return sympy.Interval.Lopen(c[0], c[1])

    def interval_ropen(self, c):
        return sympy.Interval.Ropen(c[0], c[1])

    def bracket_list(self, c):
        return sympy.Function("cls")(sympy.Tuple(c[0], c[1], *c[2]))

    def sqrt(self, c):
        return sympy.sqrt(c[1])

    def factorial(self, c):
        return sympy.factorial(c[0])

    def bracket(self, c):
        if isinstance(c[0], sympy.MatrixBase):
            return c[0]
        return sympy.Function("cls")(c[0])

    def frac(self, c):
        a, b = c[1], c[2]
        if isinstance(a, sympy.MatrixBase):
            return a / b
        return a / b

    def binom(self, c):
        return sympy.binomial(c[1], c[2])

    def floor(self, c):
        return sympy.floor(c[1])

    def evalbar(self, c):
        return sympy.Subs(c[1], sympy.Symbol(str(c[3])), c[4])

    def family(self, c):
        members, conds = c[1]
        m = members[0] if len(members) == 1 else sympy.Tuple(*members)
        return Family(_as_basic(m), sympy.Tuple(*[_as_basic(x) for x in conds]), sympy.Tuple())

    def family_bounded(self, c):
        members, conds = c[1]
        binds, his = c[3], c[4]
        if len(binds) != len(his):
            raise LatexMathError(f"{len(binds)} lower bounds but {len(his)} upper bounds")
        m = members[0] if len(members) == 1 else sympy.Tuple(*members)
        bounds = sympy.Tuple(*[sympy.Tuple(v, lo, hi) for (v, lo), hi in zip(binds, his)])
        return Family(_as_basic(m), sympy.Tuple(*[_as_basic(x) for x in conds]), bounds)

    def family_from(self, c):
        r"""``\left\{ X\right\} _{p\geq0}``: the one bound ``(p, 0, oo)`` (every p from the lower bound on)."""
        members, conds = c[1]
        m = members[0] if len(members) == 1 else sympy.Tuple(*members)
        bounds = sympy.Tuple(sympy.Tuple(sympy.Symbol(_name(c[3])), c[5], sympy.oo))
        return Family(_as_basic(m), sympy.Tuple(*[_as_basic(x) for x in conds]), bounds)

    def setbody(self, c):
        k = next((i for i, x in enumerate(c) if isinstance(x, Token) and x.type == "COLON"), len(c))
        return list(c[:k]), list(c[k + 1:])

    def bindings(self, c):
        return list(c)

    def binding(self, c):
        return (sympy.Symbol(_name(c[0])), c[1])

    def exprlist(self, c):
        return list(c)

    def cases(self, c):
        k = int(str(c[1]).strip("@")[3:])
        rows = self.arrays[k]
        return Cases(*[sympy.Tuple(_chain_value(v), cnd if isinstance(cnd, sympy.Basic) else sympy.Symbol(cnd))
                       for v, cnd in _case_rows(rows)])

    def array(self, c):
        k = int(str(c[0]).strip("@")[3:])
        rows = self.arrays[k]
        return sympy.Matrix([[parse(cell) for cell in row] for row in rows])

    # names
    def sarg_group(self, c):
        return sympy.Tuple(*c[0])

    def sarg_empty(self, c):
        raise LatexMathError("an empty sub- or superscript")

    def sarg_num(self, c):
        return sympy.Integer(str(c[0]))

    def sarg_sym(self, c):
        return sympy.Symbol(_name(c[0]))

    def sarg_prime(self, c):
        return "prime"

    def _indexed(self, base, sub, sup=None):
        name = _name(base)
        idx = list(sub) if isinstance(sub, sympy.Tuple) else [sub]
        if sup is None or sup == _TAG or sup == sympy.Tuple(_TAG):
            if sup is None and _UNTAGGED is not None:
                _UNTAGGED.append(_fn(name, idx))
            return _fn(name, idx)
        if sup == "prime":
            return _fn(name + "_prime", idx)
        s = self._scalar(sup)
        return _fn(name + "_sup", idx + [s])

    def greek_power(self, c):
        """``\\mu^{j}``: a lower-case Greek letter raised to a power (``\\Omega^{m}_{..}`` is indexed_sup_before).
        A capital (``\\Omega^{\\beta}``: a set, whose only superscript is the tag alpha) stays refused."""
        name = _name(c[0])
        if name[:1].isupper():
            raise LatexMathError(f"\\{name} with a superscript other than the tag alpha")
        return self.power([sympy.Symbol(name), c[1]])

    def indexed(self, c):
        return self._indexed(c[0], c[1])

    def indexed_sup(self, c):
        return self._indexed(c[0], c[1], c[2])

    def indexed_sup_first(self, c):
        return self._indexed(c[0], c[2])

    def indexed_sup_before(self, c):  # P^{m}_{d,e,f}: the superscript printed first
        return self._indexed(c[0], c[2], c[1])

    def tagged(self, c):
        return sympy.Symbol(_name(c[0]))

    def applied(self, c):
        f = c[0]
        args = sympy.Tuple(*c[1])
        if isinstance(f, sympy.Symbol):
            return _fn(f.name, [args])
        return f.func(*f.args, args)

    def applied_cap(self, c):
        return _fn(_name(c[0]), [sympy.Tuple(*c[1])])

    def applied_named(self, c):
        return _fn(_name(c[0]), [sympy.Tuple(*c[1])])



_BUILDER = _Build([])
_UNTAGGED: list | None = None  # while untagged() reads: the indexed names printed without a superscript
_ORDERED = False  # while summands() reads: a sum is built unevaluated, its terms in the printed order


def summands(tex: str) -> list[list]:
    r"""The terms of every part of the relation ``tex`` in the printed order (sympy reorders an evaluated sum):
    one list per part, each term a sympy product (a ``-`` is a factor -1).

    >>> summands(r"\mathbf{p}_{4,0,1}=\frac{1}{5}\mathbf{r}_{4,4,0}-\frac{4}{5}\mathbf{r}_{4,3,0}")
    [[p_vec(4, 0, 1)], [r_vec(4, 4, 0)/5, -4*r_vec(4, 3, 0)/5]]
    """
    global _ORDERED
    saved, _ORDERED = _ORDERED, True
    try:
        rel = parse_relation(tex)
    finally:
        _ORDERED = saved

    def flat(e) -> list:
        if isinstance(e, sympy.Add):
            return [t for a in e.args for t in flat(a)]
        return [e]

    return [flat(p) for p in rel.parts]


def underset_marks(tex: str) -> list[tuple[Relation, Any]]:
    r"""The marks :func:`parse` drops (its cleaning pass reads ``\underset{A}{B}`` as ``B``): each
    ``\underset{A}{B}`` of ``tex`` in the printed order, as ``(A read by parse_relation, B read by parse)``.  A mark
    ``\in\mathbb{N}`` is a relation without its left part (``lead == "in"``, ``parts == [N_bb]``).

    >>> [(a.lead, a.parts, b) for a, b in underset_marks(r"\left[ \underset{\in\mathbb{N}}{\underbrace{a-z}},b\right]")]
    [('in', [N_bb], a - z)]
    """
    found: list[tuple[str, str]] = []
    _replace_macro(re.sub(r"(?<!\\)%\s*", "", tex), "underset", 2, lambda a, b: found.append((a, b)) or b)
    return [(parse_relation(a), parse(b)) for a, b in found]


def untagged(tex: str) -> list:
    r"""The indexed names of the relation ``tex`` printed without a superscript (the tag ``^{\alpha}`` of the
    notation is dropped by :func:`parse`; this says where it was missing), in the order read.

    >>> untagged(r"r_{6,4,1}^{\alpha}=c_{6,4}\left( 2+\frac{1}{2}\right)")
    [c(6, 4)]
    """
    global _UNTAGGED
    saved, _UNTAGGED = _UNTAGGED, []
    try:
        parse_relation(tex)
        return list(_UNTAGGED)
    finally:
        _UNTAGGED = saved



def parse_as_printed(tex: str) -> Relation:
    r"""The relation ``tex`` read as :func:`parse_relation` does, but without sympy's automatic simplification: a
    sum keeps its printed terms (as in :func:`summands`), a number times a parenthesised sum is not multiplied out
    and ``\left(\left(1-s\right)+s\right)^{2n}`` stays a power of a sum, not 1.  For a check that substitutes in
    the printed structure (a change of variable ``x = 1-s`` in the parsed object, never in the text) before it
    computes; evaluate the parts (``sympy.expand``, ``.doit()``) after the substitution.

    >>> x, s = sympy.symbols("x s")
    >>> parse_as_printed(r"\left(\left(1-s\right)+s\right)^{2n}").parts[0].xreplace({1 - s: x})
    (s + x)**(2*n)
    >>> parse_relation(r"\left(\left(1-s\right)+s\right)^{2n}").parts[0]
    1
    """
    global _ORDERED
    saved, _ORDERED = _ORDERED, True  # also keeps the reading out of the memo (_run)
    try:
        with sympy.evaluate(False):
            return parse_relation(tex)
    finally:
        _ORDERED = saved

def _as_basic(x):
    if isinstance(x, Relation):
        if len(x.parts) == 2 and x.ops == ["in"]:
            return sympy.Function("In")(_as_basic(x.parts[0]), _as_basic(x.parts[1]))
        try:
            return x.as_boolean()
        except (LatexMathError, TypeError):
            return sympy.Function("Rel")(*x.parts, *[sympy.Symbol(o) for o in x.ops])
    if isinstance(x, tuple) and x and x[0] in ("and", "or"):
        a, b = _as_basic(x[1]), _as_basic(x[2])
        return sympy.And(a, b) if x[0] == "and" else sympy.Or(a, b)
    return x


# --------------------------------------------------------------------------------------------------- top level
def _fresh(x):
    """A copy of a parsed object that a caller may change without changing the memo (:func:`_run`): sympy
    expressions are immutable and shared; Relations, matrices, lists and dicts are copied."""
    if isinstance(x, Relation):
        return dataclasses.replace(x, parts=[_fresh(p) for p in x.parts], ops=list(x.ops),
                                   conditions=[_fresh(c) for c in x.conditions])
    if isinstance(x, sympy.MatrixBase) and not isinstance(x, sympy.ImmutableMatrix):
        return x.copy()
    if isinstance(x, list):
        return [_fresh(y) for y in x]
    if isinstance(x, tuple):
        return tuple(_fresh(y) for y in x)
    if isinstance(x, dict):
        return {k: _fresh(v) for k, v in x.items()}
    return x


_MEMO: dict[tuple[str, str, str], Any] = {}
_MEMO_SIZE = 20000


def _run(start: str, s: str, arrays: list):
    """Parse the cleaned text ``s`` from rule ``start``.  Memoised on (start, s, arrays): the blank and mutation
    tests and the claims read the same transcriptions many times; a changed line is a new text (and a refused one
    is never stored: it raises each time).  The caller gets a fresh copy (:func:`_fresh`)."""
    if _ORDERED or _UNTAGGED is not None:  # summands()/untagged() read as the parse runs: never from the memo
        return _parse_uncached(start, s, arrays)
    key = (start, s, repr(arrays))
    if key in _MEMO:
        return _fresh(_MEMO[key])
    out = _parse_uncached(start, s, arrays)
    if len(_MEMO) >= _MEMO_SIZE:
        _MEMO.clear()
    _MEMO[key] = out
    return _fresh(out)


def _parse_uncached(start: str, s: str, arrays: list):
    parser = _parser()
    saved = _BUILDER.arrays
    _BUILDER.arrays = arrays
    try:
        return parser.parse(s, start=start)
    except LatexMathError:
        raise
    except UnexpectedCharacters as e:
        raise LatexMathError(f"cannot read {s[e.pos_in_stream:e.pos_in_stream + 40]!r} (in {s[:80]!r})") from None
    except UnexpectedEOF:
        raise LatexMathError(f"unexpected end of {s[-60:]!r}") from None
    except UnexpectedInput as e:
        p = getattr(e, "pos_in_stream", None) or 0
        raise LatexMathError(f"cannot read {s[p:p + 40]!r} (in {s[:80]!r})") from None
    except LarkError as e:  # pragma: no cover
        raise LatexMathError(str(e)) from None
    except (TypeError, ValueError, AttributeError, IndexError, sympy.SympifyError) as e:
        raise LatexMathError(f"cannot build {s[:80]!r}: {e}") from None
    finally:
        _BUILDER.arrays = saved


def _split_top(s: str, sep: str = ",") -> list[str]:
    out, depth, cur = [], 0, []
    k = 0
    while k < len(s):
        ch = s[k]
        if ch == "\\" and k + 1 < len(s) and s[k + 1] in "{}":
            depth += 1 if s[k + 1] == "{" else -1
            cur.append(s[k:k + 2])
            k += 2
            continue
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        if ch == sep and depth == 0:
            out.append("".join(cur))
            cur = []
        else:
            cur.append(ch)
        k += 1
    out.append("".join(cur))
    return out


def parse(tex: str):
    r"""One expression of the paper's notation as a sympy object.

    >>> parse(r"\frac{20}{\sin^{3}\frac{\alpha}{2}}c_{6,6}^{\alpha}")
    20*c(6, 6)/sin(alpha/2)**3
    >>> parse(r"\left[\begin{array}[c]{ccc} \varrho & 0 & \mu\end{array}\right]^{T}")
    Matrix([
    [varrho],
    [     0],
    [    mu]])
    """
    arrays: list = []
    s = clean(tex, arrays)
    if not s:
        raise LatexMathError("nothing to read")
    out = _run("start_expr", s, arrays)
    if isinstance(out, Relation):  # pragma: no cover - the expr start cannot build one
        raise LatexMathError(f"a relation where an expression is read: {s[:60]!r}")
    return out


def parse_vector(tex: str) -> sympy.Matrix:
    """A bracketed array (row or column, ``^{T}`` transposes) as a ``sympy.Matrix``."""
    out = parse(tex)
    if not isinstance(out, sympy.MatrixBase):
        raise LatexMathError(f"not a bracketed array: {tex[:60]!r}")
    return out


def _listing(first: Relation, rest: list[str], arrays: list) -> Relation:
    """``i=0`` followed by ``1``, ``\\ldots``, ``2n`` -> ``i in (0, 1, ldots, 2n)``."""
    if any(not t.strip() for t in rest):
        raise LatexMathError(f"an empty item between commas (',,') in the list after {first.parts[-1]}")
    if not first.ops or first.ops[-1] != "=":  # i\neq0,1,\ldots,2n is no listed range
        raise LatexMathError(f"a list after {first.ops[-1] if first.ops else 'no relation'}, not after '='")
    items = [first.parts[-1]] + [_run("start_expr", t.strip(), arrays) for t in rest]
    return Relation(first.parts[:-1] + [sympy.Tuple(*items)], first.ops[:-1] + ["in"], first.lead,
                    quantifier=first.quantifier)


_RELOP_RE = re.compile(r"=|\\neq|\\leq|\\geq|<|>|\\in(?![A-Za-z])|\\notin|\\sim|\\nsim|\\equiv|\\subset")


def _top_level(s: str) -> str:
    """The text of ``s`` outside every group, parenthesis, bracket and set (the depth rule of :func:`_split_top`):
    the ``=`` of a bound ``_{j=0,i=j}`` or the ``\\in`` of a set ``\\{X : x\\in..\\}`` is not at the top."""
    out, depth, k = [], 0, 0
    while k < len(s):
        ch = s[k]
        if ch == "\\" and k + 1 < len(s) and s[k + 1] in "{}":
            depth += 1 if s[k + 1] == "{" else -1
            k += 2
            continue
        if ch in ")]}":
            depth -= 1
        elif depth == 0 and ch not in "([{":
            out.append(ch)
        if ch in "([{":
            depth += 1
        k += 1
    return "".join(out)


def _top_relop(chunk: str) -> bool:
    """Whether ``chunk`` carries a relation outside its groups (:func:`_top_level`)."""
    return bool(_RELOP_RE.search(_top_level(chunk)))


def _conditions(chunks: list[str], arrays: list) -> list[Relation]:
    out: list[Relation] = []
    k = 0
    while k < len(chunks):
        t = chunks[k].strip()
        if not t:
            raise LatexMathError("an empty clause between commas")
        quant = next((q for q in ("forall", "exists") if t.startswith("\\" + q)), None)
        body = t[len(quant) + 1:].strip() if quant else t
        if "\\AND" in body or "\\OR" in body:
            r = Relation([_condition(body)], [])
        else:
            r = _run("start_relation", body, arrays)
        if not isinstance(r, Relation):
            raise LatexMathError(f"a clause without a relation: {t!r}")
        if quant:
            r.quantifier = quant
        k += 1
        rest = []
        while (k < len(chunks) and not _RELOP_RE.search(chunks[k])
               and not chunks[k].strip().startswith(("\\forall", "\\exists"))):
            rest.append(chunks[k])
            k += 1
        if rest:
            r = _listing(r, rest, arrays)
        out.append(r)
    return out


def parse_relation(tex: str) -> Relation:
    r"""A relation chain with its trailing clauses (see :class:`Relation`).

    >>> r = parse_relation(r"\sum_{i=0}^{2n}A_{2n,i}^{\alpha}\left( \alpha s\right) =1,~\forall s\in\left[ 0,1\right]")
    >>> r.ops, r.parts[1], r.conditions[0].quantifier, r.conditions[0].parts
    (['='], 1, 'forall', [s, Interval(0, 1)])
    """
    arrays: list = []
    s = clean(_display_math(tex), arrays)
    if not s:
        raise LatexMathError("nothing to read")
    cont = None
    m = re.search(r",?\s*\\forall\s*\(\s*$", s)  # the row ends inside a clause that the next row goes on with
    if m:
        cont = "forall"
        s = s[:m.start()].rstrip()
    m = re.search(r"(\+|-|\\cdot|\\times)\s*$", s)
    if m and not cont:
        cont = {"+": "+", "-": "-"}.get(m.group(1), "*")
        s = s[:m.start()].rstrip()
    chunks = _split_top(s)
    unfinished = None
    if len(chunks) > 1 and chunks[-1].count("(") > chunks[-1].count(")"):
        # the last clause opens a parenthesis the next transcribed row closes (``,~\forall\left(``): kept as text
        unfinished = chunks.pop().strip()
    if len(chunks) > 1 and not any(_top_relop(c) for c in chunks):
        # a list of items: names, control points, sets with bounds (``r_{2n,n,n}^{\alpha},\left\{ ..\right\}
        # _{j=0,i=j}^{n-1,2n-1-j},..``): a relation inside a group (a bound, a set's condition) is the item's own
        items = [_run("start_expr", c.strip(), arrays) for c in chunks]
        return Relation([sympy.Tuple(*items)], [], continues=cont)
    head = chunks[0].strip()
    k = next((i for i, c in enumerate(chunks) if _top_relop(c)), 0)
    last = chunks[k].strip() if k else ""
    if k >= 2 and not last.startswith(("\\forall", "\\exists")) and "\\AND" not in last and "\\OR" not in last:
        # a listed subject ``d,e,f\in\left\{0,1,\ldots,m\right\}``: each listed item is in the set.  Two bare
        # items at least before the relation (one, ``X, x\in S``, is an expression and its clause)
        r = _run("start_relation", last, arrays)
        if isinstance(r, Relation) and r.lead is None and r.ops and r.ops[0] in ("in", "notin"):
            subjects = [_run("start_expr", c.strip(), arrays) for c in chunks[:k]] + [r.parts[0]]
            r = Relation([sympy.Tuple(*subjects), *r.parts[1:]], r.ops)
            r.conditions = _conditions(chunks[k + 1:], arrays) if len(chunks) > k + 1 else []
            r.continues, r.unfinished = cont, unfinished
            return r
    if head.startswith(("\\forall", "\\exists")):  # a lone quantified clause: \forall y\in[0, alpha-x]
        r = _conditions(chunks, arrays)
        if len(r) != 1:
            raise LatexMathError(f"{len(r)} clauses where one quantified relation is read")
        r[0].continues = cont
        return r[0]
    r = _run("start_relation", head, arrays)
    k = 1
    if isinstance(r, Relation):
        # ``n=1,2,3``: the chunks without a relation after the head list the head's last part
        rest = []
        while k < len(chunks) and not _RELOP_RE.search(chunks[k]):
            rest.append(chunks[k])
            k += 1
        if rest:
            r = _listing(r, rest, arrays)
    else:
        r = Relation([r], [])
    r.conditions = _conditions(chunks[k:], arrays) if len(chunks) > k else []
    r.continues = cont
    r.unfinished = unfinished
    return r


def parse_list(tex: str) -> list:
    r"""The items of a list printed with commas (control points, named constants, sets with bounds), each read by
    :func:`parse`; one item is a list of one.  A line that also carries prose: its displayed part.  A relation
    outside the items' groups is refused (a listed range ``i=0,1,\ldots,n`` is no list of items).

    >>> parse_list(r"\mathbf{r}_{2,1,1},~\left\{ \mathbf{g}_{2,2-i,0}\right\}_{i=0}^{1}")
    [r_vec(2, 1, 1), Family(g_vec(2, 2 - i, 0), (), ((i, 0, 1),))]
    """
    r = parse_relation(tex)
    if r.ops or r.conditions or r.lead or r.continues or r.unfinished or len(r.parts) != 1:
        raise LatexMathError(f"not a list of items: {tex[:60]!r}")
    return list(r.parts[0]) if isinstance(r.parts[0], sympy.Tuple) else [r.parts[0]]


def parse_conditions(tex: str) -> list[Relation]:
    r"""A list of clauses alone, as they follow a relation (each a :class:`Relation`; a listed range
    ``i=0,1,\ldots,2n`` is one clause ``i in (0, 1, ldots, 2n)``; ``\forall`` sets ``quantifier``); leading commas
    are skipped.

    >>> [(c.parts, c.ops, c.quantifier) for c in parse_conditions(r",~\forall i=0,1,\ldots,n.")]
    [([i, (0, 1, ldots, n)], ['in'], 'forall')]
    """
    arrays: list = []
    s = clean(tex, arrays).lstrip(", ")
    if not s:
        raise LatexMathError("nothing to read")
    return _conditions(_split_top(s), arrays)


_DISPLAY = re.compile(r"\\\[(.*?)(\\\]|$)|\\begin\{(equation|align)\*?\}(.*?)(\\end\{(equation|align)\*?\}|$)", re.S)


def _display_math(tex: str) -> str:
    """The displayed mathematics of a line that also carries prose (``... \\[ math \\] ...``, or its one ``$..$``
    segment), else ``tex``."""
    m = _DISPLAY.search(tex)
    if not m:
        segs = inline_math(tex)
        return segs[0] if len(segs) == 1 else tex
    return m.group(1) if m.group(1) is not None else m.group(4)


def _case_rows(rows: list[list[str]]) -> list[tuple[Any, Any]]:
    """A row whose condition cell is empty continues into the next row's value (a value printed over several rows,
    its parenthesis opened with ``\\left(..\\right.`` and closed with ``\\left...\\right)``)."""
    out = []
    pending = ""
    for row in rows:
        if not any(c.strip() for c in row):
            continue
        if len(row) != 2:
            raise LatexMathError(f"a case row with {len(row)} cells: {row!r}")
        v, cnd = row
        if not cnd.strip():
            pending = _join_rows(pending, v)
            continue
        v = _join_rows(pending, v).strip().rstrip(",").strip()
        pending = ""
        try:
            value = _run("start_expr", v, [])
        except LatexMathError as exc:  # a value printed as a relation chain: [w] \in E_{1}/_{\sim} (Section 4)
            try:
                value = _run("start_relation", v, [])
            except LatexMathError:
                raise exc from None
            if not isinstance(value, Relation) or value.lead:
                raise
        out.append((value, parse_condition_clean(cnd)))
    if pending:
        raise LatexMathError(f"a case value without its condition: {pending[:60]!r}")
    return out


def _chain_value(v):
    """A case value inside an expression: a :class:`Relation` as ``Chain(part, Symbol(op), part, ..)``."""
    if not isinstance(v, Relation):
        return v
    return Chain(*[x for k, p in enumerate(v.parts) for x in ((p,) if k == 0 else (sympy.Symbol(v.ops[k - 1]), p))])


def chain_relation(x) -> Relation:
    r"""The :class:`Relation` of a case value printed as a chain (``Chain``, see :func:`_chain_value`).

    >>> cases = parse(r"\left\{ \begin{array}{rc} \left[ w\right] =\left[ u+v\right]  & g=1 \end{array}\right.")
    >>> r = chain_relation(cases.args[0][0])
    >>> r.parts, r.ops
    ([cls(w), cls(u + v)], ['='])
    """
    if not (isinstance(x, sympy.Basic) and x.func == Chain and len(x.args) % 2 == 1):
        raise LatexMathError(f"not a chain of relations: {x}")
    return Relation(list(x.args[0::2]), [str(op) for op in x.args[1::2]])


def _join_rows(head: str, tail: str) -> str:
    """``head`` continued by ``tail``: a ``\\right.`` ending head and a ``\\left.`` starting tail are the
    invisible halves of one parenthesis split over rows, and go."""
    head, tail = head.strip(), tail.strip()
    if not head:
        return tail
    head = re.sub(r"\\RDOT\s*$", "", head)
    tail = re.sub(r"^\\LDOT\s*", "", tail)
    return head + " " + tail


def parse_condition_clean(cnd: str):
    """A cleaned condition text as a sympy boolean (``And`` over its commas), or the text if unread."""
    t = re.sub(r"[\s,.;]+$", "", cnd.strip())
    if not t:
        return sympy.true
    try:
        return _condition(t)
    except LatexMathError:
        return t


def _condition(t: str):
    """``a, b`` (and), ``X \\AND Y``, ``X \\OR Y``, ``( X )`` over relations, as a sympy boolean."""
    t = t.strip()
    for sep, op in (("\\OR", sympy.Or), ("\\AND", sympy.And)):
        pieces = _split_top_word(t, sep)
        if len(pieces) > 1:
            return op(*[_condition(x) for x in pieces])
    pieces = _split_top(t)
    if len(pieces) > 1:
        return sympy.And(*[_condition(x) for x in pieces])
    if t.startswith("(") and t.endswith(")") and _closing(t, 0) == len(t) - 1:
        return _condition(t[1:-1])
    forall = t.startswith("\\forall")
    r = _run("start_relation", t[len("\\forall"):] if forall else t, [])
    if not isinstance(r, Relation):
        raise LatexMathError(f"a condition without a relation: {t!r}")
    return _as_basic(r)


def _closing(s: str, k: int) -> int:
    """Index of the bracket that closes the one at ``s[k]`` (-1 if none)."""
    depth = 0
    for m in range(k, len(s)):
        if s[m] in "([{":
            depth += 1
        elif s[m] in ")]}":
            depth -= 1
            if depth == 0:
                return m
    return -1


def _split_top_word(s: str, word: str) -> list[str]:
    out, depth, start, k = [], 0, 0, 0
    while k < len(s):
        ch = s[k]
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif depth == 0 and s.startswith(word, k):
            out.append(s[start:k])
            k += len(word)
            start = k
            continue
        k += 1
    out.append(s[start:])
    return out


def parse_cases(tex: str) -> list[tuple[Any, Any]]:
    r"""The rows ``(value, condition)`` of the (first) ``\left\{\begin{array}..\end{array}\right.`` of ``tex``;
    a condition is a sympy boolean (``r\equiv1 \pmod 2`` is ``Eq(Mod(r - 1, 2), 0)``), or its cleaned text when
    it is not read.

    >>> parse_cases(r"=\left\{ \begin{array}[c]{rl} -1, & ~p-i=2r,\\ 0, & ~p\equiv1\left( \operatorname{mod}2\right)"
    ...             r"\end{array} \right.")
    [(-1, Eq(-i + p, 2*r)), (0, Eq(Mod(p + 1, 2), 0))]
    """
    arrays: list = []
    clean(_display_math(tex), arrays)
    if not arrays:
        raise LatexMathError(f"no array in {tex[:60]!r}")
    return _case_rows(arrays[0])


def index_set(tex: str) -> list[tuple[Any, Any, Any]]:
    r"""The bounds ``_{j=0,i=j}^{n,2n-j}`` of the last bounded set (or of a bare ``_{..}^{..}``) in ``tex``.

    >>> index_set(r"_{i=0}^{2n}")
    [(i, 0, 2*n)]
    """
    s = clean(tex)
    ms = list(re.finditer(r"_\s*\{([^{}]*=[^{}]*)\}\s*\^\s*\{", s))
    if not ms:
        raise LatexMathError(f"no index set _{{v=lo,..}}^{{hi,..}} in {tex[:60]!r}")
    m = ms[-1]
    e = _match_brace(s, m.end() - 1)
    los = [x.split("=", 1) for x in _split_top(m.group(1))]
    his = _split_top(s[m.end():e])
    if any(len(x) != 2 for x in los) or len(los) != len(his):
        raise LatexMathError(f"index set {m.group(0)}..: bounds do not pair")
    return [(sympy.Symbol(_name(v.strip())), _run("start_expr", lo.strip(), []), _run("start_expr", hi.strip(), []))
            for (v, lo), hi in zip(los, his)]


def inline_math(tex: str) -> list[str]:
    r"""The ``$..$`` segments of a prose line, in order (each can be given to :func:`parse_relation`).

    >>> inline_math(r"for $n=1$ and $\alpha\in\left(0,\pi\right)$.")
    ['n=1', '\\alpha\\in\\left(0,\\pi\\right)']
    """
    return re.findall(r"(?<!\\)\$(.+?)(?<!\\)\$", tex, flags=re.S)


def prose(tex: str) -> tuple[str, list[str]]:
    r"""The words of a prose line with each ``$..$`` segment replaced by ``$$`` (white space made single), and the
    segments (:func:`inline_math`): a check matches the words as prose and reads every segment with this reader.

    >>> prose("of radius $\\mu\\in\\left(\n0,\\rho\\right]$")
    ('of radius $$', ['\\mu\\in\\left(\n0,\\rho\\right]'])
    """
    words = re.sub(r"(?<!\\)\$(.+?)(?<!\\)\$", "$$", tex, flags=re.S)
    return " ".join(words.split()), inline_math(tex)


#: Number words of the paper's prose (``{name:count}`` of :func:`sentence` reads them, and digits).
NUMBER_WORDS = {"zero": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
                "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "sixteen": 16, "twenty-four": 24, "thirty-two": 32,
                "sixty-four": 64}
#: a slot ``{name[:kind]}``, ``...`` or literal ``$..$``; a brace right after a letter is the argument of a LaTeX
#: command (``\ref{label}``, ``\emph{a}``), literal text of the template, not a slot
_SLOT = re.compile(r"(?<![A-Za-z])\{(\w+)(?::(\w+))?\}|\.\.\.|(?<!\\)\$(.+?)(?<!\\)\$", flags=re.S)
_SLOT_PATTERNS = {"math": "\x00(\\d+)\x00", "word": r"([\w'-]+)", "words": r"(.+?)", "count": r"([\w-]+)",
                  "number": r"(\d+)"}
_MARK = re.compile("\x00(\\d+)\x00")


def _same_math(printed: str, template: str) -> bool:
    """Whether the printed ``$..$`` segment says what the template's literal math says: both read by :func:`parse`
    (or :func:`parse_relation`) and compared as sympy objects; white space alone where neither is read."""
    for reader in (parse, parse_relation):
        try:
            a, b = reader(printed), reader(template)
        except LatexMathError:
            continue
        if isinstance(a, Relation):
            return _same_relation(a, b)
        return a == b
    return "".join(printed.split()) == "".join(template.split())


def _same_relation(a: Relation, b: Relation) -> bool:
    r"""Whether two read relations say the same: operators, parts (equal as expressions) and, recursively, their
    conditions (``\lambda,\mu>0`` reads as ``lambda`` under the condition ``mu > 0``: the condition counts).

    >>> _same_relation(parse_relation(r"\lambda,\mu>0"), parse_relation(r"\lambda ,\mu> 0"))
    True
    >>> _same_relation(parse_relation(r"\lambda,\mu>0"), parse_relation(r"\lambda,\mu<0"))
    False
    """
    return (a.ops == b.ops and len(a.parts) == len(b.parts)
            and all(sympy.simplify(x - y) == 0 if isinstance(x, sympy.Expr) and isinstance(y, sympy.Expr)
                    else x == y for x, y in zip(a.parts, b.parts))
            and len(a.conditions) == len(b.conditions)
            and all(_same_relation(x, y) for x, y in zip(a.conditions, b.conditions)))


@functools.lru_cache(maxsize=4096)
def _template_regex(template: str) -> tuple[re.Pattern, tuple[tuple[str, str], ...]]:
    parts, slots, pos = [], [], 0
    for m in _SLOT.finditer(template):
        if m.group(0).startswith("{") and re.search(r"\\[A-Za-z]+$", template[:m.start()]):
            continue  # the argument of a control word (\ref{fig:x}, \emph{a}) is literal text
        parts.append(r"\s*".join(re.escape(w) for w in template[pos:m.start()].split(" ")) if template[pos:m.start()]
                     else "")
        if m.group(0) == "...":
            parts.append(r".*?")
        elif m.group(3) is not None:  # literal math: any segment, compared by the reader afterwards
            parts.append(_SLOT_PATTERNS["math"])
            slots.append(("=" + m.group(3), "literal"))
        else:
            kind = m.group(2) or "math"
            if kind not in _SLOT_PATTERNS:
                raise ValueError(f"template slot kind must be one of {sorted(_SLOT_PATTERNS)}, got {kind!r}")
            parts.append(_SLOT_PATTERNS[kind])
            slots.append((m.group(1), kind))
        pos = m.end()
    parts.append(r"\s*".join(re.escape(w) for w in template[pos:].split(" ")) if template[pos:] else "")
    return re.compile("".join(parts), flags=re.S), tuple(slots)


def sentence(template: str, tex: str, *, search: bool = False) -> dict[str, Any] | None:
    r"""Read a prose line by a template of its words: the one way a check reads prose.

    The template is the sentence as printed, with its claim-carrying parts as slots:

    * ``{name}`` (or ``{name:math}``): one ``$..$`` segment, returned as its LaTeX, to be read by this reader;
    * ``{name:word}`` one word, ``{name:words}`` any words (as few as possible), ``{name:number}`` digits (an int),
      ``{name:count}`` a number word or digits (an int, :data:`NUMBER_WORDS`; an unknown word gives ``None``);
    * ``$..$`` literal mathematics: the printed segment must *read* the same (:func:`parse`/:func:`parse_relation`,
      compared as sympy objects, so spacing and ``\left`` do not matter, while a changed index does);
    * ``...`` any text; a space any white space (also none, so a template may break where the line does);
    * a brace group right after a letter or a control word (``\ref{fig:limit}``, ``\emph{a}``) is literal text;
      write ``\ref{{label:word}}`` to read the label as a slot.

    The whole line must match (``search=True``: anywhere in it).  Returns the slots' values, or ``None`` when the
    words differ or a literal segment reads differently.

    >>> sentence("for {n} and $\\alpha\\in\\left(0,\\pi\\right)$ the {m:count} functions",
    ...          r"for $n=2$ and $\alpha\in\left( 0,\pi\right) $ the five functions")
    {'n': 'n=2', 'm': 5}
    >>> sentence("for {n} and $\\alpha\\in\\left(0,\\pi\\right)$", r"for $n=2$ and $\alpha\in\left(0,2\pi\right)$")
    >>> sentence("is {w:word}", "is non-negative.") is None, sentence("is {w:word}.", "is non-negative.")
    (True, {'w': 'non-negative'})
    """
    for name, val in (("template", template), ("tex", tex)):
        if not isinstance(val, str):
            raise TypeError(f"{name} must be a str, got {type(val).__name__}")
    words, segs = prose(tex)
    k = iter(range(len(segs)))
    marked = re.sub(r"\$\$", lambda _m: f"\x00{next(k)}\x00", words)
    rx, slots = _template_regex(" ".join(template.split()))
    m = (rx.search if search else rx.fullmatch)(marked)
    if m is None:
        return None
    out: dict[str, Any] = {}
    for (name, kind), val in zip(slots, m.groups()):
        if kind in ("math", "literal"):
            seg = segs[int(val)]
            if kind == "literal":
                if not _same_math(seg, name[1:]):
                    return None
                continue
            out[name] = seg
        elif _MARK.search(val) and kind != "words":  # pragma: no cover - the word patterns exclude the marks
            return None
        elif kind == "number":
            out[name] = int(val)
        elif kind == "count":
            out[name] = int(val) if val.isdigit() else NUMBER_WORDS.get(val.lower())
        else:
            out[name] = _MARK.sub(lambda mm: "$" + segs[int(mm.group(1))] + "$", val)
    return out


def evaluate_sums(expr):
    r"""``expr`` with every ``Sum`` whose bounds are integers written out term by term, the paper's way: a sum
    whose upper bound is below its lower bound is empty (0).  (sympy's ``Sum.doit`` follows Karr's convention
    instead, where ``Sum(f, (i, 3, 1))`` is ``-f(2)``; never ``doit`` a parsed sum with crossed bounds.)

    >>> e = parse(r"\sum_{j=r+1}^{n-1} x_{j}")
    >>> evaluate_sums(e.subs({sympy.Symbol("r"): 2, sympy.Symbol("n"): 3}))
    0
    >>> evaluate_sums(e.subs({sympy.Symbol("r"): 0, sympy.Symbol("n"): 3}))
    x(1) + x(2)
    """
    if not isinstance(expr, sympy.Basic) or not expr.args:
        return expr
    if isinstance(expr, sympy.Sum):
        terms = _expand_sum(expr.function, list(expr.limits))
        if terms is None:
            return expr.func(evaluate_sums(expr.function), *expr.limits)
        return evaluate_sums(sympy.Add(*terms))
    return expr.func(*[evaluate_sums(a) for a in expr.args])


def _expand_sum(body, limits: list):
    """The terms of ``Sum(body, *limits)`` (the last limit is the outermost), or None if a bound is not an
    integer."""
    if not limits:
        return [body]
    var, lo, hi = limits[-1]
    if not (lo.is_Integer and hi.is_Integer):
        return None
    out = []
    for k in range(int(lo), int(hi) + 1):
        inner = [(v, a.subs(var, k), b.subs(var, k)) for v, a, b in limits[:-1]]
        t = _expand_sum(body.subs(var, k), inner)
        if t is None:
            return None
        out += t
    return out


@dataclass
class Term:
    """One printed term of a (sum of) products: the sums around it (outermost first, ``(var, lo, hi)``), the
    applied names in it (``rho(2n, 2n-i, j)``, ``R(2n, 2n-i, j, (u, v, w))``, ...) and the rest (the coefficient)."""

    limits: list[tuple[Any, Any, Any]]
    names: list[Any]
    coefficient: Any


def terms(expr) -> list[Term]:
    r"""The terms of a parsed linear combination (sympy's order of an ``Add``, not the printed order).

    >>> [(t.limits, t.names) for t in terms(parse(r"\sum_{j=1}^{n-1}\sum_{i=j}^{2n-1-j}\gamma_{2n,2n-i,j}"
    ...                                          r"G_{2n,2n-i,j}^{\alpha}\left(u,v,w\right)"))]
    [([(j, 1, n - 1), (i, j, -j + 2*n - 1)], [G(2*n, -i + 2*n, j, (u, v, w)), gamma(2*n, -i + 2*n, j)])]
    """
    out: list[Term] = []
    for t in sympy.Add.make_args(expr):
        limits: list = []
        coeff = sympy.Integer(1)
        while True:
            if isinstance(t, sympy.Sum):
                limits += [tuple(lim) for lim in reversed(t.limits)]
                t = t.function
                continue
            if isinstance(t, sympy.Mul):
                inner = [a for a in t.args if isinstance(a, sympy.Sum)]
                if len(inner) == 1:
                    coeff *= sympy.Mul(*[a for a in t.args if a is not inner[0]])
                    t = inner[0]
                    continue
            break
        names = sorted((a for a in sympy.Mul.make_args(t) if isinstance(a, sympy.core.function.AppliedUndef)),
                       key=sympy.default_sort_key)
        rest = sympy.Mul(*[a for a in sympy.Mul.make_args(t) if a not in names])
        out.append(Term(limits, names, coeff * rest))
    return out
