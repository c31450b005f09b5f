"""Figures of the normalizing coefficients (issue 4).

* ``normalizing_coefficients``: r_{2n,2n-i,j}^alpha versus alpha for n = 1, 2, 3 (log scale), computed
  by the certified ball-arithmetic solve of :mod:`paper_repro.core.normalization` (not from closed forms).
* ``smallest_coefficient``: the smallest of r_{2n,2n-i,j}^alpha sin^{2n+j}(alpha/2) = P(cos(alpha/2))
  over all coefficients, versus n, for several alpha (closed forms of :mod:`paper_repro.core.closed_forms`).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from paper_repro.core.closed_forms import closed_forms_cached
from paper_repro.core.normalization import orbit_coefficients, orbits
from paper_repro.util.registry import figure

from . import plt, save


@figure("normalizing_coefficients", claims=["partition_of_unity"], outputs=["normalizing_coefficients.png"],
        caption="Normalizing coefficients r_{2n,2n-i,j}^alpha versus alpha in (0, pi) for n = 1, 2, 3 (log scale); "
                "G and B coefficients equal the R coefficient of the same orbit.")
def make_coefficients(outdir: Path) -> list[Path]:
    alphas = np.linspace(0.15, 3.05, 120)
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    for ax, n in zip(axes, (1, 2, 3)):
        vals = np.array([orbit_coefficients(n, a) for a in alphas])
        cmap = plt.get_cmap("viridis")
        for o, (rep, _) in enumerate(orbits(n)):
            ax.semilogy(alphas, vals[:, o], color=cmap(o / max(1, len(orbits(n)) - 1)), lw=1.4,
                        label=f"${rep.coefficient}^\\alpha$", ls="-" if rep.j % 2 == 0 else "--")
        ax.set_xlabel(r"$\alpha$")
        ax.set_title(f"n = {n}")
        ax.set_xticks([0, np.pi / 4, np.pi / 2, 3 * np.pi / 4, np.pi], ["0", "π/4", "π/2", "3π/4", "π"])
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7, ncol=2)
    axes[0].set_ylabel("coefficient (log scale)")
    return [save(fig, outdir / "normalizing_coefficients.png")]


@figure("smallest_coefficient", claims=["nonnegativity_extended"], outputs=["smallest_coefficient.png"],
        caption="New: min over all coefficients of r_{2n,2n-i,j}^alpha sin^{2n+j}(alpha/2) = P(cos(alpha/2)) versus "
                "the order n, for several alpha. Positive throughout (the closed forms' P have no root in (0,1)).")
def make_smallest(outdir: Path, n_max: int = 10) -> list[Path]:
    fig, ax = plt.subplots(figsize=(8, 5))
    ns = list(range(1, n_max + 1))
    for frac, lab in ((0.05, "0.05π"), (1 / 6, "π/6"), (1 / 2, "π/2"), (0.9, "0.9π"), (0.99, "0.99π")):
        c_q = _fmpq(np.cos(np.pi * frac / 2))
        mins, argmins = [], []
        for n in ns:
            vals = {lab_: float(f.numerator(c_q)) for lab_, f in closed_forms_cached(n).items()}
            arg = min(vals, key=vals.get)
            mins.append(vals[arg])
            argmins.append(arg)
        line, = ax.semilogy(ns, mins, "o-", label=f"α = {lab}")
        ax.annotate(f"${argmins[-1]}$", (ns[-1], mins[-1]), textcoords="offset points", xytext=(6, 0),
                    fontsize=7, color=line.get_color(), va="center")
    ax.set_xlabel("order n")
    ax.set_ylabel(r"$\min\; r^\alpha_{2n,2n-i,j}\,\sin^{2n+j}(\alpha/2)$ (minimiser labelled at n = 10)")
    ax.set_xlim(0.5, n_max + 2)
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    return [save(fig, outdir / "smallest_coefficient.png")]


def _fmpq(x: float):
    from flint import fmpq

    num, den = float(x).as_integer_ratio()
    return fmpq(num, den)
