import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from paper_repro.core.univariate import A, c_const, c_numerator

from .strategies import alphas, orders


@given(orders, alphas, st.lists(st.floats(0, 1), min_size=1, max_size=10))
def test_partition_of_unity_float(n, alpha, fr):
    vals = A(n, alpha, np.array(fr) * alpha)
    assert np.all(vals >= 0)
    # 2n+1 non-negative terms summing to 1, each a product of <= 2n+2 float factors (relative error
    # <= (2n+2) eps each, eps = 1.1e-16) and a constant of relative error ~ (2n+1) eps: |sum - 1| <= 1e-13
    assert np.max(np.abs(vals.sum(axis=1) - 1.0)) <= 1e-13


@given(orders, alphas)
def test_c_symmetric(n, alpha):
    for i in range(2 * n + 1):
        assert c_const(n, i, alpha) == pytest.approx(c_const(n, 2 * n - i, alpha), rel=1e-14)


def test_c_examples_printed():
    # Example normalizing_coefficients_n_3 prints c_{6,4} = (12 cos^2 + 3)/sin^6 and c_{6,3} = (8cos^3+12cos)/sin^6
    assert c_numerator(3, 4) == [3, 0, 12, 0, 0]
    assert c_numerator(3, 3) == [0, 12, 0, 8]


def test_t_out_of_range():
    with pytest.raises(ValueError, match="t must lie"):
        A(1, 1.0, [1.5])
