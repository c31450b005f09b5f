"""Figures of the normalizing coefficients (issue 4).

* ``normalizing_coefficients``: r_{2n,2n-i,j}^alpha versus alpha for n = 1, 2, 3 (log scale), computed
  by the certified ball-arithmetic solve of :mod:`paper_repro.core.normalization` (not from closed forms).
* ``smallest_coefficient``: the smallest of r_{2n,2n-i,j}^alpha sin^{2n+j}(alpha/2) = P(cos(alpha/2))
  over all coefficients, versus n, for several alpha (closed forms of :mod:`paper_repro.theory.closed_forms`).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from paper_repro.core.normalization import orbit_coefficients, orbits
from paper_repro.theory.closed_forms import closed_forms_cached
from paper_repro.util.registry import figure

from . import plt, save


@figure("normalizing_coefficients", claims=["partition_of_unity"], outputs=["normalizing_coefficients.png"],
        caption="Normalizing coefficients r_{2n,2n-i,j}^alpha versus alpha in (0, pi) for n = 1, 2, 3 (log scale); "
                "G and B coefficients equal the R coefficient of the same orbit.")
def make_coefficients(outdir: Path) -> list[Path]:
    alphas = np.linspace(0.15, 3.05, 120)
    fig, axes = plt.subplots(3, 1, figsize=(10, 17))
    colors = plt.get_cmap("tab10").colors  # ten distinguishable colours; line style by level
    styles = ["-", "--", ":", "-."]
    for ax, n in zip(axes, (1, 2, 3)):
        vals = np.array([orbit_coefficients(n, a) for a in alphas])
        for o, (rep, _) in enumerate(orbits(n)):
            ax.semilogy(alphas, vals[:, o], color=colors[o % 10], lw=2, ls=styles[rep.j % 4],
                        label=f"${rep.coefficient}^\\alpha$ (level {rep.j})")
        ax.set_xlabel(r"$\alpha$", fontsize=13)
        ax.set_title(f"n = {n}", fontsize=14)
        ax.set_xticks([0, np.pi / 4, np.pi / 2, 3 * np.pi / 4, np.pi], ["0", "π/4", "π/2", "3π/4", "π"])
        ax.tick_params(labelsize=12)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=12, ncol=2, loc="upper right")
        ax.set_ylabel("coefficient (log scale)", fontsize=13)
    fig.tight_layout()
    return [save(fig, outdir / "normalizing_coefficients.png")]


@figure("smallest_coefficient", claims=["nonnegativity_extended"], outputs=["smallest_coefficient.png"],
        caption="New: min over all coefficients of r_{2n,2n-i,j}^alpha sin^{2n+j}(alpha/2) = P(cos(alpha/2)) versus "
                "the order n, for several alpha. Positive throughout (the closed forms' P have no root in (0,1)).")
def make_smallest(outdir: Path, n_max: int = 10) -> list[Path]:
    fig, ax = plt.subplots(figsize=(9, 6))
    ns = list(range(1, n_max + 1))
    for frac, lab in ((0.05, "0.05π"), (1 / 6, "π/6"), (1 / 2, "π/2"), (0.9, "0.9π"), (0.99, "0.99π")):
        c_q = _fmpq(np.cos(np.pi * frac / 2))
        mins, argmins = [], []
        for n in ns:
            vals = {lab_: float(f.numerator(c_q)) for lab_, f in closed_forms_cached(n).items()}
            arg = min(vals, key=vals.get)
            mins.append(vals[arg])
            argmins.append(arg)
        ax.semilogy(ns, mins, "o-", label=f"α = {lab}; minimiser at n = {n_max}: ${argmins[-1]}$")
    ax.set_xlabel("order n", fontsize=13)
    ax.set_ylabel(r"$\min\; r^\alpha_{2n,2n-i,j}\,\sin^{2n+j}(\alpha/2)$", fontsize=13)
    ax.tick_params(labelsize=12)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=11)
    return [save(fig, outdir / "smallest_coefficient.png")]


def _fmpq(x: float):
    from flint import fmpq

    num, den = float(x).as_integer_ratio()
    return fmpq(num, den)
