"""The collocation routine: a point set with two equal rows is skipped as singular, as the solve would."""

import numpy as np
import pytest

from paper_repro.core.collocation import collocate, has_equal_rows
from paper_repro.core.context import get_context


@pytest.mark.parametrize("arith", ["exact", "modp"])
def test_equal_rows_skip_to_the_next_point_set(arith, monkeypatch):
    ctx = get_context(arith)
    sets = {0: [0, 1, 0, 5], 1: [0, 1, 2, 5]}  # y = 2x + 1 at x = sets[k]: m = 3 rows (set 0 repeats a point)

    def system(k):
        xs = sets[k]
        return (ctx.asarray([[x * x, x, 1] for x in xs]), ctx.asarray([[2 * x + 1] for x in xs]))

    res = collocate(ctx, system, m=3)
    assert res.point_set == 1 and [int(v) for v in res.solution.reshape(-1)] == [0, 2, 1]
    # without the shortcut the exact solve of set 0 raises ZeroDivisionError: the same set is chosen
    monkeypatch.setattr("paper_repro.core.collocation.has_equal_rows", lambda a: False)
    assert collocate(ctx, system, m=3).point_set == 1


def test_has_equal_rows():
    assert has_equal_rows(np.array([[1, 2], [1, 2]])) and not has_equal_rows(np.array([[1, 2], [2, 1]]))
    ctx = get_context("exact")
    assert has_equal_rows(ctx.asarray([[1, 2], [3, 4], [1, 2]]))
    assert not has_equal_rows(np.array([[object()], [object()]], dtype=object))
