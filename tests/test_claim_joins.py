"""Claim joins_all_n (paper_repro.claims.joins): it passes on the library, and each of its checks fails on a broken
join (a check that cannot fail checks nothing)."""

from __future__ import annotations

import numpy as np
from flint import fmpq

from paper_repro.claims import joins as cj
from paper_repro.core.domain import rational_alpha
from paper_repro.core.labels import delta
from paper_repro.surfaces.joins import edge_rows, join_neighbour
from paper_repro.util.registry import CLAIMS, load_all


def test_claim_is_registered_and_passes_small():
    load_all()
    assert "joins_all_n" in CLAIMS
    out = cj.run(ts=["1/3"], n_max=2, seed=1, torus=["2", "1"], cyclide=["6", "32", "2", "3"], ts_pieces=["1/3"],
                 phases=[["1", "0"]])
    assert out.passed, out.measured


def test_derivative_check_sees_a_bent_second_row_and_a_wrong_multiplier():
    alpha = rational_alpha("1/3")
    net = [[fmpq(k + j, 3) for j in range(3)] for k in range(delta(2))]
    for edge in ("u", "v", "w"):
        other = join_neighbour(net, 2, alpha, edge)
        assert cj.derivatives_agree(net, other, 2, alpha, edge)
        assert not cj.derivatives_agree(net, other, 2, alpha, edge, lam=fmpq(2))
        _, s = edge_rows(2, edge)
        bent = other.copy()
        bent[s[1], 0] += fmpq(1, 100)
        assert not cj.derivatives_agree(net, bent, 2, alpha, edge)
        b, _ = edge_rows(2, edge)
        torn = other.copy()
        torn[b[2], 1] += fmpq(1, 100)
        assert not cj.derivatives_agree(net, torn, 2, alpha, edge)


def test_pieces_check_sees_pieces_that_do_not_meet(monkeypatch):
    """With the upper triangle of the next phase square instead of this one, nothing joins."""
    alpha = rational_alpha("1/3")
    model = cj.torus_model(fmpq(2), fmpq(1))
    ok = cj.pieces_check(model, alpha, (fmpq(1), fmpq(0)), (fmpq(1), fmpq(0)))
    assert all(all(v.values()) for v in ok.values())
    real_piece = cj.piece

    def shifted(model, phi, psi, alpha, upper):
        return real_piece(model, cj._rotate(phi, (fmpq(3, 5), fmpq(4, 5))) if upper else phi, psi, alpha, upper)

    monkeypatch.setattr(cj, "piece", shifted)
    bad = cj.pieces_check(model, alpha, (fmpq(1), fmpq(0)), (fmpq(1), fmpq(0)))
    assert not any(v["C0"] for v in bad.values())


def test_closed_form_check_sees_a_wrong_matrix(monkeypatch):
    import paper_repro.claims.joins as mod

    real = mod.edge_derivatives

    def wrong(n, alpha, edge, arith):
        d, t = real(n, alpha, edge, arith)
        d = d.copy()
        d[0, edge_rows(n, edge)[1][0]] *= 2
        return d, t

    monkeypatch.setattr(mod, "edge_derivatives", wrong)
    res = cj.closed_form_check(1, rational_alpha("1/3"))
    assert not any(v["cross"] for v in res.values()) and all(v["tangent"] for v in res.values())
    assert np.all([isinstance(v["second_row_block_invertible"], bool) for v in res.values()])
