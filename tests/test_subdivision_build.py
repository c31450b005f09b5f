"""The building of the integer product forms of the float subdivision route (paper_repro.core.subdivision_products;
issue 38, item 6; docs/subdivision_for_all_n.md, section 11, Lemma 8).

The level forms are built level by level: the centre embedding of the previous level merged with the new columns,
with no sort of the whole level.  The references: the dictionary construction of Theorem P in
``paper_repro.core.half_angle_rules`` (``product_terms``, the code of the proofs) for n <= 16 (the levels the pole
check of section 11 runs on for n <= 17), and the former build (the seven forms of each order concatenated and the
whole level sorted), kept below, for n <= 14.
Equal arrays (integers: exact) mean the float sums see the same terms in the same order, so the same bits.
"""

from __future__ import annotations

import numpy as np
import pytest

from paper_repro.core import subdivision_products as sp_mod
from paper_repro.core.half_angle_rules import merge, product_terms
from paper_repro.core.labels import delta


def _reference_level_terms(k: int) -> tuple[np.ndarray, ...]:
    """The former ``_level_terms``: the seven forms of order k - 1 from the proofs' dictionary construction, merged
    (sorted by (row, col, a, b)), concatenated by h and sorted stably by (row, col)."""
    forms = [merge(product_terms(k - 1, h)) for h in range(7)]
    cat = [np.concatenate([f[i] for f in forms]) for i in range(5)]
    hidx = np.concatenate([np.full(len(f[0]), h) for h, f in enumerate(forms)])
    order = np.argsort(cat[0] * delta(k - 1) + cat[1], kind="stable")
    return tuple(arr[order] for arr in cat) + (hidx[order],)


@pytest.mark.parametrize("k", range(2, 18))
def test_level_terms_equal_the_proofs_construction(k):
    """n = k - 1 <= 16: every term (row, col, a, b, coef, h) in the same order as the dictionary construction."""
    got, ref = sp_mod._level_terms(k), _reference_level_terms(k)
    assert len(got) == len(ref) == 6
    for x, y in zip(got, ref):
        assert np.array_equal(x, y)
    rows, cols = got[0], got[1]
    _, key = sp_mod._level_build(k)
    assert np.array_equal(key, rows.astype(np.int64) * delta(k - 1) + cols)
    assert (np.diff(key) >= 0).all()


def test_level_terms_equal_the_former_construction_n_le_14():
    """Beyond the dictionary construction's reach: against the former vectorised build (each order alone, then the
    whole level sorted), for n <= 14."""
    for k in range(2, 16):
        forms = [sp_mod._product_terms_unsorted(k - 1, h) for h in range(7)]
        cat = [np.concatenate([f[i] for f in forms]) for i in range(5)]
        hidx = np.concatenate([np.full(len(f[0]), h) for h, f in enumerate(forms)])
        order = np.argsort(cat[0] * delta(k - 1) + cat[1], kind="stable")
        ref = tuple(arr[order] for arr in cat) + (hidx[order],)
        for x, y in zip(sp_mod._level_terms(k), ref):
            assert np.array_equal(x, y), k


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_outer_columns_equal_the_proofs_construction(n):
    """The new columns (j = 0) of order n against the dictionary construction, every h."""
    f = np.arange(delta(1)) if n == 1 else np.flatnonzero(sp_mod.member_parts_fast(n)[:, 3] == 0)
    for h in range(7):
        rows, cols, a, b, coef = merge(product_terms(n, h))
        keep = np.isin(cols, f)
        for x, y in zip(sp_mod._outer_columns(n)[h], (rows[keep], cols[keep], a[keep], b[keep], coef[keep])):
            assert np.array_equal(x, y), (n, h)


def test_a_wrong_form_is_seen():
    """The comparison can fail: one coefficient changed in the reference is detected."""
    ref = list(_reference_level_terms(4))
    coef = ref[4].copy()
    coef[len(coef) // 2] += 1
    assert not np.array_equal(sp_mod._level_terms(4)[4], coef)
