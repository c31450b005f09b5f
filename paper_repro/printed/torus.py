"""Example exmp:torus, verbatim: the printed control points of the toroidal triangle (order 2).

Each entry is ``label -> (x, y, z)`` with coordinates as functions of ``(a, rho, mu)`` in mpmath
(``a`` = alpha).  Transcribed character by character from the LaTeX source.
"""

from __future__ import annotations

from mpmath import cos, sin, tan

PRINTED = {
    "r_{4,4,0}": (lambda a, r, m: r + m * sin(a), lambda a, r, m: 0, lambda a, r, m: m * cos(a)),
    "r_{4,3,0}": (lambda a, r, m: r + m / 2 * (tan(a / 2) + sin(a)), lambda a, r, m: 0,
                  lambda a, r, m: m / 2 * (1 + cos(a))),
    "r_{4,2,0}": (lambda a, r, m: r + 3 * m * sin(a) / (4 + 2 * cos(a)), lambda a, r, m: 0,
                  lambda a, r, m: 3 * m * (1 + cos(a)) / (4 + 2 * cos(a))),
    "r_{4,1,0}": (lambda a, r, m: r + m / 2 * tan(a / 2), lambda a, r, m: 0, lambda a, r, m: m),
    "r_{4,3,1}": (lambda a, r, m: r + 3 * m * sin(a) / (4 + 2 * cos(a)),
                  lambda a, r, m: (3 * r * sin(a) + m * (3 + cos(a)) * (1 - cos(a))) / (8 + 4 * cos(a)),
                  lambda a, r, m: 3 * m * (1 + cos(a)) / (4 + 2 * cos(a))),
    "r_{4,2,1}": (lambda a, r, m: r + 3 * m * (2 + cos(a)) * sin(a) / ((1 + cos(a)) * (10 + 2 * cos(a))),
                  lambda a, r, m: (2 * r * (sin(a) + tan(a / 2)) + 3 * m * (1 - cos(a))) / (10 + 2 * cos(a)),
                  lambda a, r, m: 3 * m * (3 + cos(a)) / (10 + 2 * cos(a))),
    "r_{4,2,2}": (lambda a, r, m: (6 * r * (3 + 2 * cos(a)) + m * (9 + cos(a)) * sin(a)) / (20 + 10 * cos(a)),
                  lambda a, r, m: (10 * r * sin(a) + m * (7 + cos(a)) * (1 - cos(a))) / (20 + 10 * cos(a)),
                  lambda a, r, m: 3 * m * (3 + 2 * cos(a)) / (10 + 5 * cos(a))),
    "g_{4,4,0}": (lambda a, r, m: r, lambda a, r, m: 0, lambda a, r, m: m),
    "g_{4,3,0}": (lambda a, r, m: r, lambda a, r, m: r / 2 * tan(a / 2), lambda a, r, m: m),
    "g_{4,2,0}": (lambda a, r, m: 3 * r * (1 + cos(a)) / (4 + 2 * cos(a)),
                  lambda a, r, m: 3 * r * sin(a) / (4 + 2 * cos(a)), lambda a, r, m: m),
    "g_{4,1,0}": (lambda a, r, m: r / 2 * (1 + cos(a)), lambda a, r, m: r / 2 * (tan(a / 2) + sin(a)),
                  lambda a, r, m: m),
    "g_{4,3,1}": (lambda a, r, m: r + 3 * m * sin(a) / (8 + 4 * cos(a)),
                  lambda a, r, m: (3 * r * sin(a) + 2 * m * (1 - cos(a))) / (8 + 4 * cos(a)), lambda a, r, m: m),
    "g_{4,2,1}": (lambda a, r, m: (3 * r * (3 + cos(a)) + 3 * m * sin(a)) / (10 + 2 * cos(a)),
                  lambda a, r, m: (3 * r * (3 * sin(a / 2) + sin(3 * a / 2)) + 3 * m * (cos(a / 2) - cos(3 * a / 2)))
                  / ((20 + 4 * cos(a)) * cos(a / 2)),
                  lambda a, r, m: m),
    "b_{4,4,0}": (lambda a, r, m: r * cos(a), lambda a, r, m: r * sin(a), lambda a, r, m: m),
    "b_{4,3,0}": (lambda a, r, m: r / 2 * (1 + cos(a)) + m / 2 * tan(a / 2) * cos(a),
                  lambda a, r, m: r / 2 * (tan(a / 2) + sin(a)) + m / 2 * (1 - cos(a)), lambda a, r, m: m),
    "b_{4,2,0}": (lambda a, r, m: 3 * r * (1 + cos(a)) / (4 + 2 * cos(a)) + m / 2 * sin(a),
                  lambda a, r, m: (3 * r * sin(a) + m * (3 + cos(a)) * (1 - cos(a))) / (4 + 2 * cos(a)),
                  lambda a, r, m: 3 * m * (1 + cos(a)) / (4 + 2 * cos(a))),
    "b_{4,1,0}": (lambda a, r, m: r + m / 2 * (tan(a / 2) + sin(a)),
                  lambda a, r, m: r / 2 * tan(a / 2) + m / 2 * (1 - cos(a)), lambda a, r, m: m / 2 * (1 + cos(a))),
    "b_{4,3,1}": (lambda a, r, m: r * (7 - 2 * cos(a / 2) ** 2 + cos(a / 2)) * cos(a / 2) ** 2 / (4 + 2 * cos(a))
                  + m / 4 * sin(a),
                  lambda a, r, m: (6 * r * sin(a) + m * (1 - cos(a)) * (3 + cos(a))) / (8 + 4 * cos(a)),
                  lambda a, r, m: m),
    "b_{4,2,1}": (lambda a, r, m: (3 * r * (3 + cos(a)) * cos(a / 2) + m * (3 * sin(a / 2) + 2 * sin(3 * a / 2)))
                  / ((10 + 2 * cos(a)) * cos(a / 2)),
                  lambda a, r, m: (3 * r * (3 * sin(a / 2) + sin(3 * a / 2)) + 4 * m * (cos(a / 2) - cos(3 * a / 2)))
                  / ((20 + 4 * cos(a)) * cos(a / 2)),
                  lambda a, r, m: 3 * m * (3 + cos(a)) / (10 + 2 * cos(a))),
}


def torus(u, v, w, rho, mu):
    """eq. toroidal_triangle: t(u, v) = ((rho + mu sin u) cos v, (rho + mu sin u) sin v, mu cos u)."""
    from mpmath import cos as c
    from mpmath import sin as s

    return ((rho + mu * s(u)) * c(v), (rho + mu * s(u)) * s(v), mu * c(u))
