"""Quotient sets and bounded unions of Section 4 (Definition equivalence_relation_definition, Proposition
iterative_construction_of_trivariate_extension), read by the one reader of the paper's mathematics (issue 37, item 1,
the fourth step): ``E_{n}^{\\alpha}/_{\\sim}`` is ``quot(E(n))``, ``\\cup_{i=a}^{b} X`` is ``bigcup`` of the family
``{X}_{i=a}^{b}``.

Expected values are written by hand from the paper's lines, never copied from the reader's output."""

from __future__ import annotations

import pytest
import sympy
from sympy import Function, Symbol, Tuple

from paper_repro.printed.latex_math import Family, LatexMathError, parse, parse_relation
from paper_repro.printed.lines import verbatim

n, i, g, b, r, u, v, w = sympy.symbols("n i g b r u v w")
E, quot, cls = Function("E"), Function("quot"), Function("cls")
cup, setminus, bigcup = Function("cup"), Function("setminus"), Function("bigcup")


def test_quotient_set_and_its_difference():
    """E_{2}/~ minus (E_{0}/~ cup E_{1}/~), as printed in the text of order 2 (sec4_5-n2-r0); the tag alpha and the
    spacing do not matter; the comma printed inside the subscript once (``/_{\\sim,}``, sec4_5-n2-g12) is the same
    quotient."""
    e2 = parse(r"E_{2}^{\alpha}/_{\sim}\setminus\left( E_{0}^{\alpha}/_{\sim}\cup E_{1}^{\alpha}/_{\sim}\right)")
    assert e2 == setminus(quot(E(2)), cup(quot(E(0)), quot(E(1))))
    assert parse(r"E_{1}^{\alpha }/_{\sim,}") == quot(E(1)) == parse(r"E_{1}/_{\sim }")
    rel = parse_relation(r"\left[ 0\right] \in E_{0}^{\alpha}/_{\sim}")
    assert rel.ops == ["in"] and rel.parts == [cls(0), quot(E(0))]


def test_bounded_union_of_quotient_sets():
    """Proposition iterative_construction_of_trivariate_extension: E_{n}/~ minus the union of E_{i}/~ over
    i = 1..n-1, equal to three families of classes over g, b, r = 0..n-1 (sec4_5-prop-new-classes)."""
    rel = parse_relation(verbatim("sec4_5-prop-new-classes"))
    union = bigcup(Family(quot(E(i)), Tuple(), Tuple(Tuple(i, 1, n - 1))))
    assert rel.ops == ["="] and rel.parts[0] == setminus(quot(E(n)), union)
    fams = [Family(cls(n * w + g * v), Tuple(), Tuple(Tuple(g, 0, n - 1))),
            Family(cls(n * u + b * w), Tuple(), Tuple(Tuple(b, 0, n - 1))),
            Family(cls(r * u + n * v), Tuple(), Tuple(Tuple(r, 0, n - 1)))]
    assert rel.parts[1] == cup(cup(fams[0], fams[1]), fams[2])


def test_union_keeps_its_plain_forms():
    """The bounded union's ``\\cup_`` does not change the plain ``A\\cup B`` nor the row that starts with ``\\cup``."""
    assert parse(r"A\cup B") == cup(Symbol("A"), Symbol("B"))
    assert parse(r"E_{0}/_{\sim}\cup E_{1}/_{\sim}") == cup(quot(E(0)), quot(E(1)))
    assert parse_relation(r"& \cup\left\{ \cos\left( 2u\right) :\left( u,v,w\right) \in\Omega^{\alpha}\right\}").parts[
        0].func == cup


@pytest.mark.parametrize("tex", [r"E_{1}/_{x}", r"E_{1}/_{}", r"\cup_{i}^{n}E_{i}", r"\cup_{i=1}E_{i}"])
def test_malformed_quotients_and_unions_are_refused(tex):
    with pytest.raises(LatexMathError):
        parse(tex)
