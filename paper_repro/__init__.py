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
>>> bool(coefficients(1, "pi/2")["r_{2,1,1}"] == coefficients(1, np.pi / 2)["r_{2,1,1}"])
True

Layers (imports only go downwards): ``util`` (files, cache, validation, registry) <- ``core`` (labels,
contexts, domain, basis, normalization, collocation, ...) <- ``printed`` (verbatim transcriptions) and
``surfaces`` (patches, fitting, meshes) <- ``claims`` <- ``figures`` <- ``app`` (reports, CLI).
"""

from paper_repro._version import __version__
from paper_repro.core.basis import evaluate as _evaluate
from paper_repro.core.context import get_context
from paper_repro.core.derivatives_basis import basis_derivative as _basis_derivative
from paper_repro.core.domain import (
    RationalAngle,
    RationalPoints,
    rational_alpha,
    sample_points,
    sample_rational_points,
)
from paper_repro.core.elevation import elevate, elevation_matrix
from paper_repro.core.half_angle_matrices import product_matrix as _product_matrix
from paper_repro.core.labels import delta, parse_label, united_system
from paper_repro.core.nets import LabelledNet
from paper_repro.core.normalization import coefficients as _coefficients
from paper_repro.core.normalization import evaluate_normalized as _evaluate_normalized
from paper_repro.core.transformation import transformation_matrix
from paper_repro.surfaces.fitting import fit, fit_least_squares
from paper_repro.surfaces.limit import bezier_nodes, bezier_triangle
from paper_repro.surfaces.mesh import export_mesh
from paper_repro.surfaces.patch import Patch, merge_meshes
from paper_repro.theory.limits import bezier_limit
from paper_repro.util.validation import accepts_alpha_text, parse_alpha

# alpha may be given as text ("pi/2", "2pi/3") wherever the API takes it (read by parse_alpha)
evaluate = accepts_alpha_text(_evaluate)
basis_derivative = accepts_alpha_text(_basis_derivative)
coefficients = accepts_alpha_text(_coefficients)
evaluate_normalized = accepts_alpha_text(_evaluate_normalized)
product_matrix = accepts_alpha_text(_product_matrix)

__all__ = ["LabelledNet", "Patch", "RationalAngle", "RationalPoints", "__version__", "basis_derivative",
           "bezier_limit", "bezier_nodes", "bezier_triangle", "coefficients", "delta", "elevate", "elevation_matrix",
           "evaluate", "evaluate_normalized", "export_mesh", "fit", "fit_least_squares", "get_context",
           "merge_meshes", "parse_alpha", "parse_label", "product_matrix", "rational_alpha", "sample_points",
           "sample_rational_points", "transformation_matrix", "united_system"]
