"""The constructs the reader of the paper's mathematics gained when the last formula-reading regular expressions of
the checks were folded into it (issue 37, item 1): lists of items (names, control points, bounded sets), a listed
subject of a membership, a superscript printed before the subscript, the prose frame of a line, and the members a
bounded set names.

Expected values are written by hand from the paper (the weights of Section 5, the control points of order 2 in
Section 7, the caption of Figure fig:limit), never copied from the reader's output."""

from __future__ import annotations

import pytest
import sympy
from sympy import Function, Symbol, Tuple

from paper_repro.printed import parsed as P
from paper_repro.printed.latex_math import (
    LDOTS,
    Family,
    LatexMathError,
    parse,
    parse_list,
    parse_relation,
    prose,
)
from paper_repro.printed.lines import verbatim

n, i, j, d, e, f, m, x = sympy.symbols("n i j d e f m x")
ALPHA = Symbol("alpha")
r_, g_, b_ = Function("r"), Function("g"), Function("b")
r_vec, g_vec, b_vec = Function("r_vec"), Function("g_vec"), Function("b_vec")


# -- a list of items whose relations sit inside groups -------------------------------------------------------------
def test_weights_list_is_a_name_and_three_bounded_sets():
    """Section 5 (partition_of_unity): the weights r_{2n,n,n}, {r_{2n,2n-i,j}}, {g..}, {b..} over j = 0..n-1,
    i = j..2n-1-j: the = of the bounds is no relation of the list."""
    items = parse_list(verbatim("sec4_5-weights"))
    bounds = Tuple(Tuple(j, 0, n - 1), Tuple(i, j, 2 * n - 1 - j))
    assert items == [r_(2 * n, n, n), Family(r_(2 * n, 2 * n - i, j), Tuple(), bounds),
                     Family(g_(2 * n, 2 * n - i, j), Tuple(), bounds), Family(b_(2 * n, 2 * n - i, j), Tuple(), bounds)]


def test_weights_at_order_one_are_the_seven_of_T2():
    """n = 1: r_{2,1,1}, and for j = 0, i = 0, 1 the weights x_{2,2,0}, x_{2,1,0} of each colour: 7 = 3n(n+1)+1."""
    named = [w for item in parse_list(verbatim("sec4_5-weights")) for w in P.members(item, n=1)]
    assert named == [r_(2, 1, 1), r_(2, 2, 0), r_(2, 1, 0), g_(2, 2, 0), g_(2, 1, 0), b_(2, 2, 0), b_(2, 1, 0)]


def test_control_points_of_order_two_listed_by_sets():
    """Section 7 (elevation example): r_{4,2,2} and {r_{4,4-i,j}}_{j=0,i=j}^{1,3-j} (and g, b): j = 0 gives
    i = 0..3, j = 1 gives i = 1..2; 1 + 3 * 6 = 19 = delta_2 points."""
    items = parse_list(verbatim("sec7-elev-index-sets"))
    assert items[0] == r_vec(4, 2, 2)
    assert P.members(items[1]) == [r_vec(4, 4, 0), r_vec(4, 3, 0), r_vec(4, 2, 0), r_vec(4, 1, 0),
                                   r_vec(4, 3, 1), r_vec(4, 2, 1)]
    assert sum(len(P.members(it)) for it in items) == 19


def test_a_displayed_list_after_prose():
    """A prose line with a displayed list: the list of sec7-elev-convex, the 7 control points of order 1."""
    assert parse_list(verbatim("sec7-elev-convex")) == [r_vec(2, 1, 1), r_vec(2, 2, 0), r_vec(2, 1, 0), g_vec(2, 2, 0),
                                                        g_vec(2, 1, 0), b_vec(2, 2, 0), b_vec(2, 1, 0)]


def test_one_item_and_refusals():
    assert parse_list(r"\mathbf{r}_{2,1,1}") == [r_vec(2, 1, 1)]
    with pytest.raises(LatexMathError):  # a listed range is a relation, not a list of items
        parse_list(r"i=0,1,\ldots,n")
    with pytest.raises(LatexMathError):  # a blank line
        parse_list("XXX")
    with pytest.raises(ValueError):  # a set with a condition names no members
        P.members(parse(r"\left\{ A_{2n,2n-i}^{\alpha}\left( x\right) :x\in\left[ 0,\alpha\right] \right\}"
                        r" _{i=0}^{2n}"), n=1)


# -- a listed subject of a membership --------------------------------------------------------------------------------
def test_listed_subject_in_a_listed_set():
    """Figure fig:limit's caption: d, e, f in {0, 1, ..., m} -- each of the three is in the set."""
    rel = parse_relation(r"d,e,f\in\left\{0,1,\ldots,m\right\}")
    assert rel.ops == ["in"]
    assert rel.parts == [Tuple(d, e, f), Family(Tuple(0, 1, LDOTS, m), Tuple(), Tuple())]


def test_listed_signs_of_the_product_rules():
    """Section 4 (the signs s_2, s_3, s_4 in {-1, +1}): the three signs are the subject."""
    rel = parse_relation(r"s_{2},s_{3},s_{4}\in\left\{ -1,+1\right\}")
    s = Function("s")
    assert rel.parts[0] == Tuple(s(2), s(3), s(4)) and rel.ops == ["in"]


def test_one_item_before_a_membership_stays_an_expression_and_its_clause():
    """``X, x\\in S`` is the paper's 'X for x in S': not a listed subject."""
    rel = parse_relation(r"A_{2n,i}^{\alpha}\left( x\right) ,~x\in\left[ 0,\alpha\right]")
    assert rel.parts == [Function("A")(2 * n, i, Tuple(x))]
    assert rel.conditions[0].parts == [x, sympy.Interval(0, ALPHA)]


# -- a superscript printed before the subscript ----------------------------------------------------------------------
def test_superscript_first():
    """P^{m}_{d,e,f} (caption of fig:limit) is P_{d,e,f}^{m}: the Bernstein polynomial of degree m."""
    assert parse(r"P^{m}_{d,e,f}") == parse(r"P_{d,e,f}^{m}") == Function("P_sup")(d, e, f, m)
    assert parse(r"P^{\alpha}_{d,e,f}") == Function("P")(d, e, f)  # the tag alpha, as after the subscript
    with pytest.raises(LatexMathError):
        parse(r"P^{m}")


# -- the prose frame -------------------------------------------------------------------------------------------------
def test_prose_frame():
    words, segs = prose("where parameters $a$, $b$, $c$ and $\\mu$ have to fulfill the conditions\n"
                        "$a^{2}=b^{2}+c^{2}$ and $c<\\mu\\leq a$")
    assert words == "where parameters $$, $$, $$ and $$ have to fulfill the conditions $$ and $$"
    assert segs == ["a", "b", "c", "\\mu", "a^{2}=b^{2}+c^{2}", "c<\\mu\\leq a"]


# -- superscripts other than the tag; the control net as a union of bounded sets ------------------------
def test_foreign_tags_of_the_partition_of_unity_lines():
    # eq. system_partition_of_unity's sum and its domain print every named object with the tag alpha only
    assert P.foreign_tags(verbatim("sec4_5-L-sum")) == []
    assert P.foreign_tags(verbatim("sec4_5-L-domain")) == []
    # another superscript is seen: a prime, a number; one the reader refuses raises
    assert P.foreign_tags(r"r_{2n,n,n}^{\prime}R_{2n,n,n}^{\alpha}\left( u,v,w\right)") == ["r_prime(2*n, n, n)"]
    assert P.foreign_tags(r"for all $c_{6,4}^{2}$") == ["c_sup(6, 4, 2)"]
    with pytest.raises(LatexMathError):
        P.foreign_tags(r"for all $\left( u,v,w\right) \in\Omega^{\beta}$.")


def test_control_net_of_order_one_read_as_a_union():
    from paper_repro.claims.lines.sec6 import net_from_transcription

    # def:surface_patch at n = 1: {r_{2,2-i,j}}_{j=0,i=j}^{1,1-j} is r_{2,2,0}, r_{2,1,0} (j = 1: i = 1..0, empty);
    # {g}, {b}_{j=0,i=j}^{0,1-j}: g_{2,2,0}, g_{2,1,0}, b_{2,2,0}, b_{2,1,0} -- six points, the centre r_{2,1,1} lacks
    assert net_from_transcription(1) == ["r_{2,2,0}", "r_{2,1,0}", "g_{2,2,0}", "g_{2,1,0}", "b_{2,2,0}", "b_{2,1,0}"]
    # a row that is not the union continued by \subset names no point
    assert net_from_transcription(1, verbatim("sec6-control-net-set").replace("\\subset", "")) == []
    assert net_from_transcription(1, "XXX") == []


def test_greek_letter_raised_to_a_power():
    mu = Symbol("mu")
    # Lemma 3's consequence "In particular, S_{j,mu}^{j}(0) = j! mu^{j}" (sec1_3-sin-leading): a Greek letter with a
    # superscript and no subscript is a power (refused before: the table expected the subscript of P^{m}_{d,e,f})
    rel = parse_relation(r"S_{j,\mu}^{j}\left( 0\right) =j!\mu^{j}")
    assert rel.ops == ["="]
    assert rel.parts == [Function("S_sup")(j, mu, j, Tuple(0)), sympy.factorial(j) * mu ** j]
    assert parse(r"\alpha^{2}") == ALPHA ** 2
    assert parse(r"\mu^{\prime}") == Symbol("mu_prime")
    # the tag stays a tag, and a superscript printed before a subscript stays an index
    assert parse(r"\Omega^{\alpha}") == Symbol("Omega")
    assert parse(r"\Omega^{m}_{d,e,f}") == Function("Omega_sup")(d, e, f, m)


def test_sentence_reads_prose_by_a_template_of_its_words():
    from paper_repro.printed.latex_math import sentence

    line = r"Thus, equality $b=2$ generates only two acceptable equivalence classes, namely $\left[ u\right]$."
    got = sentence("Thus, equality {b} generates only {k:count} acceptable equivalence classes, namely {c}.", line)
    assert got == {"b": "b=2", "k": 2, "c": r"\left[ u\right]"}
    # a changed word, a missing word, or a changed literal formula is no match
    assert sentence("Thus, equality {b} generates only {k:count} acceptable classes, namely {c}.", line) is None
    assert sentence("equality $b=2$ generates", line) is None  # the whole line must match ...
    assert sentence("equality $b=2$ generates", line, search=True) == {}  # ... unless asked to search
    assert sentence("equality $b=3$ generates", line, search=True) is None  # literal math read, not string-compared
    assert sentence("equality $b = 2$ generates", line, search=True) == {}  # spacing is not meaning
    # digits and number words, an unknown number word is None (the check decides)
    assert sentence("only {k:count} classes", "only 12 classes") == {"k": 12}
    assert sentence("only {k:count} classes", "only several classes") == {"k": None}
    assert sentence("of order {n:number}", "of order 3") == {"n": 3}
    assert sentence("of order {n:number}", "of order three") is None
    # `words` keeps the mathematics it spans, a space in the template also matches a line break
    assert sentence("where {w:words} holds", "where $a=1$ or\n$b=2$ holds") == {"w": "$a=1$ or $b=2$"}
    with pytest.raises(ValueError, match="slot kind"):
        sentence("{x:colour}", "red")
    # a brace after a command is the command's argument, matched literally (hand-derived: the labels must agree)
    line = r"under parametrizations (\ref{parametrization_1_y_0} )--(\ref{parametrization_3_y_0}), at $y=0$"
    assert sentence(r"under parametrizations (\ref{parametrization_1_y_0} )--(\ref{parametrization_3_y_0}), at {p}",
                    line) == {"p": "y=0"}
    assert sentence(r"under parametrizations (\ref{parametrization_1_y_0} )--(\ref{parametrization_2_x_0}), at {p}",
                    line) is None
    cases = r"Cases (\emph{a})--(\emph{c}) show three steps"
    assert sentence(r"Cases (\emph{a})--(\emph{c}) show {k:count} steps", cases) == {"k": 3}


def test_parse_as_printed_keeps_the_printed_structure():
    import sympy

    from paper_repro.printed.latex_math import parse_as_printed, parse_relation

    x, s, n = sympy.symbols("x s n")
    # ((1-s)+s)^{2n} is 1 when simplified; as printed it is a power of a two-term sum
    rel = parse_as_printed(r"\left( \left( 1-s\right) +s\right) ^{2n}=\left( 1-s\right) ^{2}+2\left( 1-s\right) s")
    assert rel.ops == ["="]
    assert sympy.expand(rel.parts[0].xreplace({1 - s: x})) != 1
    assert rel.parts[0].xreplace({1 - s: x}) == (x + s) ** (2 * n)
    # the number 2 is not multiplied into (1-s): the change of variable reaches it
    assert sympy.expand(rel.parts[1].xreplace({1 - s: x})) == x**2 + 2 * x * s
    assert parse_relation(r"\left( \left( 1-s\right) +s\right) ^{2n}").parts[0] == 1
    # the memo of the simplified reading is not polluted by the unevaluated one
    parse_as_printed(r"2\left( 1-s\right) s")
    assert parse_relation(r"2\left( 1-s\right) s").parts[0] == s * (2 - 2 * s)


def test_an_emphasized_space_in_a_formula_is_a_space():
    import sympy

    from paper_repro.printed.latex_math import LatexMathError, parse, parse_relation

    n = sympy.Symbol("n")
    rel = parse_relation(r"\mathcal{T}_{2n}^{\alpha}=~\operatorname{span}\emph{~}T_{2n}^{\alpha}")
    assert rel.ops == ["="]
    assert rel.parts == [sympy.Function("Tcal")(2 * n), sympy.Function("span")(sympy.Function("T")(2 * n))]
    with pytest.raises(LatexMathError, match="prose"):
        parse(r"\emph{span} x")  # an emphasized word is prose, not mathematics


def test_sentence_takes_a_control_words_argument_literally():
    from paper_repro.printed.latex_math import sentence

    line = r"as in Figure \ref{fig:limit} and (\emph{a}) for $n=1$"
    assert sentence(r"as in Figure \ref{fig:limit} and (\emph{a}) for {n}", line) == {"n": "n=1"}
    assert sentence(r"as in Figure \ref{fig:other} and (\emph{a}) for {n}", line) is None
    assert sentence(r"as in Figure \ref{{label:word}} and (\emph{a}) for {n}", line) is None  # ':' is not a word char
    assert sentence(r"as in Figure \ref{fig:{label:word}} and (\emph{a}) for {n}", line) == {"label": "limit",
                                                                                           "n": "n=1"}


def test_sentence_and_strip_comments_refuse_what_is_not_text():
    from paper_repro.printed.latex_math import sentence, strip_comments

    with pytest.raises(TypeError, match="template must be a str"):
        sentence(None, "x")
    with pytest.raises(TypeError, match="tex must be a str"):
        sentence("x", b"x")
    with pytest.raises(TypeError, match="tex must be a str"):
        strip_comments(None)
