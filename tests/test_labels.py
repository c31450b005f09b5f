import pytest
from hypothesis import given
from hypothesis import strategies as st

from paper_repro.core.labels import (
    BasisLabel,
    delta,
    exponent_matrix,
    exponents,
    index_of,
    parse_label,
    r_exponents,
    united_system,
)


def test_t2_labels_match_paper_list():
    # Order-1 system as listed in Example exmp:degree_elevation_from_1_to_2.
    assert [lab.paper for lab in united_system(1)] == [
        "R_{2,1,1}", "R_{2,2,0}", "R_{2,1,0}", "G_{2,2,0}", "G_{2,1,0}", "B_{2,2,0}", "B_{2,1,0}"]


@given(st.integers(1, 40))
def test_count_is_delta(n):
    assert len(united_system(n)) == delta(n) == exponent_matrix(n).shape[0]
    assert len({tuple(r) for r in exponent_matrix(n)}) == delta(n)  # distinct functions


def test_r_formula_examples():
    # R_{4,3,1} (n=2, i=1, j=1): sin^3(u/2) sin(w/2) cos^0(v/2) sin(v/2)
    assert r_exponents(2, 1, 1) == (3, 0, 1, 0, 1, 0)
    # R_{6,1,1} (n=3, i=5 > n, j=1): sin^5(w/2) sin(u/2) cos^0(v/2) sin(v/2)
    assert r_exponents(3, 5, 1) == (1, 0, 1, 0, 5, 0)
    # centre R_{2n,n,n}: sin^n sin^n sin^n
    assert r_exponents(3, 3, 3) == (3, 0, 3, 0, 3, 0)


def test_aliases_point_to_same_function():
    idx = index_of(2)
    assert idx["R_{4,0,0}"] == idx["G_{4,4,0}"]
    assert idx["G_{4,2,2}"] == idx["B_{4,2,2}"] == idx["R_{4,2,2}"] == 0
    assert idx["r_{4,3,1}"] == idx["R_{4,3,1}"]
    for k, lab in enumerate(united_system(2)):
        assert idx[lab.paper] == k


def test_parse_label_roundtrip():
    for lab in united_system(3):
        assert exponents(parse_label(lab.paper)) == exponents(lab)
    with pytest.raises(ValueError, match="label"):
        parse_label("Q_{4,3,1}")
    with pytest.raises(ValueError):
        parse_label("R_{4,9,0}")


@pytest.mark.parametrize("bad", [0, -1, 1.5, True, "2", None])
def test_invalid_n(bad):
    # a wrong value is a ValueError, a wrong type a TypeError; both name n and its range
    with pytest.raises(ValueError if isinstance(bad, int) and not isinstance(bad, bool) else TypeError,
                       match="n must be a positive integer"):
        united_system(bad)


def test_basislabel_range():
    with pytest.raises(ValueError):
        exponents(BasisLabel("R", 2, 5, 0))
