"""paper_repro: executable companion to "A constructive approach to triangular trigonometric patches"
(Róth, Juhász, Kristály; arXiv 1309.4747).

The public API (every function takes ``arith=`` -- ``'float'``, ``'mp'``, ``'exact'``, ``'ball'``,
``'modp'`` or a context of :mod:`paper_repro.core.context` -- where the arithmetic matters):

>>> import numpy as np
>>> from paper_repro import Patch, coefficients, evaluate_normalized, sample_points
>>> vals = evaluate_normalized(3, np.pi / 2, sample_points(np.pi / 2, 4, seed=1))
>>> bool(np.allclose(vals.sum(axis=1), 1.0)), bool((vals >= 0).all())
(True, True)
>>> sorted(coefficients(1, 1.0))[:3]
['b_{2,1,0}', 'b_{2,2,0}', 'g_{2,1,0}']

Layers (imports only go downwards): ``util`` (files, cache, validation, registry) <- ``core`` (labels,
contexts, domain, basis, normalization, collocation, ...) <- ``printed`` (verbatim transcriptions) and
``surfaces`` (patches, fitting, meshes) <- ``claims`` <- ``figures`` <- ``app`` (reports, CLI).
"""

from paper_repro.core.basis import evaluate
from paper_repro.core.context import get_context
from paper_repro.core.derivatives_basis import basis_derivative
from paper_repro.core.domain import (
    RationalAngle,
    RationalPoints,
    rational_alpha,
    sample_points,
    sample_rational_points,
)
from paper_repro.core.elevation import elevate, elevation_matrix
from paper_repro.core.labels import delta, parse_label, united_system
from paper_repro.core.normalization import coefficients, evaluate_normalized
from paper_repro.surfaces.fitting import fit
from paper_repro.surfaces.mesh import export_mesh
from paper_repro.surfaces.patch import Patch, merge_meshes
from paper_repro.theory.limits import bezier_limit

__all__ = ["Patch", "RationalAngle", "RationalPoints", "basis_derivative", "bezier_limit", "coefficients", "delta",
           "elevate", "elevation_matrix", "evaluate", "evaluate_normalized", "export_mesh", "fit", "get_context",
           "merge_meshes", "parse_label", "rational_alpha", "sample_points", "sample_rational_points",
           "united_system"]
