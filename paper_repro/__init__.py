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

from importlib import import_module
from typing import Any

from paper_repro._version import __version__

#: The public names and where they live.  They are imported on first use (PEP 562), so that ``import
#: paper_repro`` -- the first thing ``python -m paper_repro`` does, before our Ctrl-C handling can run -- costs
#: almost nothing; ``(module, name, reads alpha text)``: alpha may be given as text ("pi/2", "2pi/3") wherever
#: the API takes it (read by :func:`~paper_repro.util.validation.parse_alpha`).
_PUBLIC: dict[str, tuple[str, str, bool]] = {
    "evaluate": ("paper_repro.core.basis", "evaluate", True),
    "get_context": ("paper_repro.core.context", "get_context", False),
    "basis_derivative": ("paper_repro.core.derivatives_basis", "basis_derivative", True),
    "RationalAngle": ("paper_repro.core.domain", "RationalAngle", False),
    "RationalPoints": ("paper_repro.core.domain", "RationalPoints", False),
    "rational_alpha": ("paper_repro.core.domain", "rational_alpha", False),
    "sample_points": ("paper_repro.core.domain", "sample_points", False),
    "sample_rational_points": ("paper_repro.core.domain", "sample_rational_points", False),
    "subdivide": ("paper_repro.core.subdivision", "subdivide", True),
    "subdivide_to_depth": ("paper_repro.core.subdivision", "subdivide_to_depth", True),
    "subdivision_matrix": ("paper_repro.core.subdivision", "subdivision_matrix", True),
    "elevate": ("paper_repro.core.elevation", "elevate", False),
    "elevation_matrix": ("paper_repro.core.elevation", "elevation_matrix", False),
    "product_matrix": ("paper_repro.core.half_angle_matrices", "product_matrix", True),
    "delta": ("paper_repro.core.labels", "delta", False),
    "parse_label": ("paper_repro.core.labels", "parse_label", False),
    "united_system": ("paper_repro.core.labels", "united_system", False),
    "barycentric": ("paper_repro.core.layout", "barycentric", False),
    "net_edges": ("paper_repro.core.layout", "net_edges", False),
    "position": ("paper_repro.core.layout", "position", False),
    "LabelledNet": ("paper_repro.core.nets", "LabelledNet", False),
    "coefficients": ("paper_repro.core.normalization", "coefficients", True),
    "evaluate_normalized": ("paper_repro.core.normalization", "evaluate_normalized", True),
    "transformation_matrix": ("paper_repro.core.transformation", "transformation_matrix", False),
    "fit": ("paper_repro.surfaces.fitting", "fit", False),
    "c1_neighbour_row": ("paper_repro.surfaces.joins", "c1_neighbour_row", True),
    "g1_neighbour_row": ("paper_repro.surfaces.joins", "g1_neighbour_row", True),
    "join_neighbour": ("paper_repro.surfaces.joins", "join_neighbour", True),
    "edge_derivatives": ("paper_repro.surfaces.joins", "edge_derivatives", True),
    "join_error": ("paper_repro.surfaces.joins", "join_error", True),
    "fit_least_squares": ("paper_repro.surfaces.fitting", "fit_least_squares", False),
    "bezier_nodes": ("paper_repro.surfaces.limit", "bezier_nodes", False),
    "bezier_triangle": ("paper_repro.surfaces.limit", "bezier_triangle", False),
    "export_mesh": ("paper_repro.surfaces.mesh", "export_mesh", False),
    "Patch": ("paper_repro.surfaces.patch", "Patch", False),
    "tessellate": ("paper_repro.surfaces.tessellation", "tessellate", False),
    "merge_meshes": ("paper_repro.surfaces.patch", "merge_meshes", False),
    "triangle_grid": ("paper_repro.surfaces.patch", "triangle_grid", False),
    "bezier_limit": ("paper_repro.theory.limits", "bezier_limit", False),
    "accepts_alpha_text": ("paper_repro.util.validation", "accepts_alpha_text", False),
    "parse_alpha": ("paper_repro.util.validation", "parse_alpha", False),
}


def __getattr__(name: str) -> Any:
    """The public names, imported on first use (and then kept in this module)."""
    where = _PUBLIC.get(name)
    if where is None:
        raise AttributeError(f"module 'paper_repro' has no attribute {name!r}")
    module, attr, alpha_text = where
    value = getattr(import_module(module), attr)
    if alpha_text:
        value = __getattr__("accepts_alpha_text")(value)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_PUBLIC))



__all__ = ["LabelledNet", "Patch", "RationalAngle", "RationalPoints", "__version__", "barycentric", "basis_derivative",
           "bezier_limit", "bezier_nodes", "bezier_triangle", "c1_neighbour_row", "coefficients", "delta",
           "edge_derivatives", "elevate", "elevation_matrix", "evaluate", "evaluate_normalized",
           "export_mesh", "fit", "fit_least_squares", "g1_neighbour_row", "get_context", "join_error",
           "join_neighbour", "merge_meshes", "net_edges", "parse_alpha",
           "parse_label", "position", "product_matrix", "rational_alpha", "sample_points", "sample_rational_points",
           "subdivide", "subdivide_to_depth", "subdivision_matrix", "tessellate", "transformation_matrix",
           "triangle_grid", "united_system"]
