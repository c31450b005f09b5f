"""Figures of the normalizing coefficients (issue 4).

* ``normalizing_coefficients``: r_{2n,2n-i,j}^alpha versus alpha for n = 1, 2, 3 (log scale), computed
  by the certified ball-arithmetic solve of :mod:`paper_repro.core.normalization` (not from closed forms).
* ``smallest_coefficient``: the smallest normalizing coefficient of each level versus alpha (n = 4), and the
  smallest interior one (levels j >= 1) versus alpha for n = 1..8 (closed forms of
  :mod:`paper_repro.theory.closed_forms`, proven for every alpha).
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


def _int_power(x: np.ndarray, k: int) -> np.ndarray:
    """``x ** k`` by k products in a fixed order: numpy's ``power`` ufunc runs SIMD code chosen per CPU (Intel SVML
    on AVX512), so its last bits depend on the machine.

    >>> _int_power(np.array([0.5, 3.0]), 3).tolist()
    [0.125, 27.0]
    """
    out = np.ones_like(x)
    for _ in range(k):
        out = out * x
    return out


def _level_values(n: int, alphas: np.ndarray) -> dict[int, np.ndarray]:
    """Per level j, the smallest normalizing coefficient r^alpha_{2n,2n-i,j} = P(cos(alpha/2)) / sin^{2n+j}(alpha/2)
    of that level at each alpha (from the closed forms, proven for every alpha)."""
    c, s = np.cos(alphas / 2), np.sin(alphas / 2)
    out: dict[int, list[np.ndarray]] = {}
    for lab, f in closed_forms_cached(n).items():
        j = int(lab.rstrip("}").split(",")[-1])
        coeffs = [int(x) for x in f.numerator.coeffs()]  # constant term first
        val = np.polyval(coeffs[::-1], c) / _int_power(s, f.sin_power)
        out.setdefault(j, []).append(val)
    return {j: np.min(v, axis=0) for j, v in sorted(out.items())}


@figure("smallest_coefficient", claims=["nonnegativity_extended"], outputs=["smallest_coefficient.png"],
        caption="New: (a) for n = 4, the smallest normalizing coefficient r_{2n,2n-i,j}^alpha of each level j "
                "versus alpha (level 0 is the boundary, level n the centre); "
                "(b) the smallest interior coefficient (levels j >= 1) versus alpha for n = 1..8. From the closed "
                "forms, which are proven for every alpha; every coefficient is positive.")
def make_smallest(outdir: Path, n_levels: int = 4, n_max: int = 8) -> list[Path]:
    alphas = np.linspace(0.08, 3.08, 151)
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(10, 12.5))
    colors = plt.get_cmap("viridis")
    for j, vals in _level_values(n_levels, alphas).items():
        ax1.semilogy(alphas, vals, lw=2.2, color=colors(j / n_levels), ls="-" if j else "--",
                     label=f"level {j}" + (" (centre)" if j == n_levels else " (boundary)" if j == 0 else ""))
    ax1.set_title(f"(a) n = {n_levels}: smallest coefficient of each level", fontsize=14)
    for n in range(1, n_max + 1):
        levels = _level_values(n, alphas)
        interior = np.min([v for j, v in levels.items() if j >= 1], axis=0)
        ax2.semilogy(alphas, interior, lw=2, color=plt.get_cmap("plasma")((n - 1) / n_max), label=f"n = {n}")
    ax2.set_title("(b) smallest interior coefficient (levels j ≥ 1)", fontsize=14)
    for ax in (ax1, ax2):
        ax.set_xlabel("α", fontsize=13)
        ax.set_ylabel(r"$\min\; r^\alpha_{2n,2n-i,j}$", fontsize=13)
        ax.set_xticks([0, np.pi / 4, np.pi / 2, 3 * np.pi / 4, np.pi], ["0", "π/4", "π/2", "3π/4", "π"])
        ax.tick_params(labelsize=12)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=12, ncol=2 if ax is ax2 else 1, loc="upper right")
    fig.tight_layout()
    return [save(fig, outdir / "smallest_coefficient.png")]
