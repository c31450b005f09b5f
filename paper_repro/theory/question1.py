"""Question 1 for every n: the machine-checked ingredients of the hand proof in docs/question1_for_all_n.md.

The proof restricts the partition of unity (and any vanishing combination) to the segment u + w = alpha - v at
fixed v, writes every function of T_{2n} there as a homogeneous polynomial of degree 2n in x = sin(u/2),
z = sin(w/2) (:func:`restriction`), and expands each of its 2n + 1 coordinates in v around v = 0.  The finite
facts it uses are checked here, each by an independent exact computation:

* :func:`restriction_identity` (Lemma 1): cos(u/2) = (z + c'x)/s', cos(w/2) = (x + c'z)/s' and
  x^2 + 2c'xz + z^2 = s'^2 on the segment (c' = cos((alpha - v)/2), s' = sin((alpha - v)/2));
* :func:`order_table` (Lemmas 2 and 3, the order lemma): for every function of T_{2n}, which coordinates
  y^k = z^k x^{2n-k} it reaches, the order in v of each, and the leading coefficients the proof names; computed
  by exact power series in v at rational-tangent alpha and compared with the predictions of
  :func:`predicted_profile`;
* :func:`triangular_block` (the orbit system in the proof of Theorem B): the orbit matrix of Taylor data is block
  diagonal, each block lower triangular with diagonal 2^-j (so the system for the coefficients is triangular);
* :func:`hexagon_check` (Lemma 5): every function of T_{2n} lies in the span of cos/sin(pu + qv) over the hexagon
  |p|, |q|, |p - q| <= n of 3n^2 + 3n + 1 points;
* :func:`weights_nonnegative` (Corollary C): the t-weights of the expanded formula are non-negative;
* :func:`triangular_solution` (Theorem B at sampled alpha): solving the triangular system from the Taylor data of
  the right-hand side 1 = ((x^2 + 2c'xz + z^2)/s'^2)^n reproduces the formula's coefficients exactly.

Each check returns a dict with ``ok`` and the evidence; tests feed each a wrong input and see it fail.
"""

from __future__ import annotations

from math import factorial

from flint import fmpq, fmpq_poly

from paper_repro.core.domain import RationalAngle
from paper_repro.core.labels import BasisLabel, exponents, united_system
from paper_repro.core.normalization import orbits
from paper_repro.core.normalizing_formula import scaled_table, t_weight
from paper_repro.util.validation import check_n


# --- exact power series in v (truncated at order N: coefficients of v^0..v^N) ---------------------------------
def _trunc(p: fmpq_poly, order: int) -> fmpq_poly:
    return p.truncate(order + 1)


def _mul(a: fmpq_poly, b: fmpq_poly, order: int) -> fmpq_poly:
    """``a b`` truncated after v^order (flint's low product: the terms above are never formed)."""
    return a.mul_low(b, order + 1)


def _sin_half_series(order: int) -> fmpq_poly:
    """sin(v/2) = sum (-1)^k (v/2)^(2k+1)/(2k+1)!"""
    return fmpq_poly([fmpq((-1) ** (k // 2), 2**k * factorial(k)) if k % 2 else 0 for k in range(order + 1)])


def _cos_half_series(order: int) -> fmpq_poly:
    return fmpq_poly([fmpq((-1) ** (k // 2), 2**k * factorial(k)) if k % 2 == 0 else 0 for k in range(order + 1)])


def _inv_series(p: fmpq_poly, order: int) -> fmpq_poly:
    """1/p as a power series (p(0) != 0), Newton-free: the schoolbook recurrence."""
    c = p.coeffs() + [fmpq(0)] * (order + 1)
    inv = [fmpq(1) / c[0]]
    for k in range(1, order + 1):
        inv.append(-sum((c[m] * inv[k - m] for m in range(1, k + 1)), fmpq(0)) / c[0])
    return fmpq_poly(inv)


class SegmentSeries:
    """The series in v of sigma = sin(v/2), kappa = cos(v/2), c' = cos((alpha-v)/2), 1/s' at rational alpha."""

    def __init__(self, alpha: RationalAngle, order: int):
        self.order = order
        self.c, self.s = alpha.cos_half, alpha.sin_half
        self.sigma = _sin_half_series(order)
        self.kappa = _cos_half_series(order)
        # c' = c cos(v/2) + s sin(v/2), s' = s cos(v/2) - c sin(v/2)   (angle differences)
        self.cp = self.kappa * self.c + self.sigma * self.s
        self.sp = self.kappa * self.s - self.sigma * self.c
        self.inv_sp = _inv_series(self.sp, order)
        self._pow_cache: dict[tuple[str, int], fmpq_poly] = {}

    def factor(self, name: str, k: int) -> list[fmpq_poly]:
        """y-polynomials (y + c')^k, (1 + c'y)^k, (1 + 2c'y + y^2)^k with series coefficients (cached)."""
        key = (name, k)
        if key not in self._pow_cache:
            if k == 0:
                val = [fmpq_poly([1])]
            else:
                base = {"y+c": [self.cp, fmpq_poly([1])], "1+cy": [fmpq_poly([1]), self.cp],
                        "q": [fmpq_poly([1]), self.cp * 2, fmpq_poly([1])]}[name]
                val = _poly_y_mul(self.factor(name, k - 1), base, self.order)
            self._pow_cache[key] = val
        return self._pow_cache[key]

    def power(self, name: str, k: int) -> fmpq_poly:
        key = (name, k)
        if key not in self._pow_cache:
            base = {"sigma": self.sigma, "kappa": self.kappa, "cp": self.cp, "inv_sp": self.inv_sp}[name]
            out = fmpq_poly([1])
            for _ in range(k):
                out = _mul(out, base, self.order)
            self._pow_cache[key] = out
        return self._pow_cache[key]


def _poly_y_mul(a: list[fmpq_poly], b: list[fmpq_poly], order: int) -> list[fmpq_poly]:
    """Product of two polynomials in y whose coefficients are truncated series in v."""
    out = [fmpq_poly() for _ in range(len(a) + len(b) - 1)]
    for i, x in enumerate(a):
        if x == 0:
            continue
        for j, y in enumerate(b):
            if y != 0:
                out[i + j] += _mul(x, y, order)
    return out


def restriction(exps: tuple[int, ...], n: int, seg: SegmentSeries) -> list[fmpq_poly]:
    """Coordinates of a function with half-angle exponents ``exps`` restricted to the segment at fixed v.

    Returns the 2n + 1 coefficients of y^k (y = z/x, i.e. of x^{2n-k} z^k) of the homogenised restriction
    ``sigma^{a_v} kappa^{b_v} x^{a_u} ((z + c'x)/s')^{b_u} z^{a_w} ((x + c'z)/s')^{b_w} ((x^2 + 2c'xz + z^2)/s'^2)^h``
    with h = (2n - a_u - b_u - a_w - b_w)/2, each a power series in v truncated at ``seg.order``.
    """
    au, bu, av, bv, aw, bw = exps
    d = au + bu + aw + bw
    if d % 2 or d > 2 * n:
        raise ValueError(f"exponents {exps}: the (u, w)-degree {d} is odd or exceeds 2n = {2 * n}")
    h = (2 * n - d) // 2
    order = seg.order
    poly = _poly_y_mul(seg.factor("y+c", bu), seg.factor("1+cy", bw), order)
    poly = _poly_y_mul(poly, seg.factor("q", h), order)
    scale = _mul(_mul(seg.power("sigma", av), seg.power("kappa", bv), order), seg.power("inv_sp", bu + bw + 2 * h),
                 order)
    out = [fmpq_poly() for _ in range(2 * n + 1)]
    for k, coef in enumerate(poly):
        out[aw + k] = _mul(coef, scale, order)
    return out


_RESTRICTIONS: dict[tuple[int, str], tuple[SegmentSeries, list[list[fmpq_poly]]]] = {}


def restrictions(n: int, alpha: RationalAngle) -> tuple[SegmentSeries, list[list[fmpq_poly]]]:
    """:func:`restriction` of every function of T_{2n} (internal order) at ``alpha``, series to order n (memoised
    for the last few (n, alpha): the three checks below share them)."""
    key = (n, str(alpha.t))
    if key not in _RESTRICTIONS:
        if len(_RESTRICTIONS) > 4:
            _RESTRICTIONS.clear()
        seg = SegmentSeries(alpha, n)
        _RESTRICTIONS[key] = (seg, [restriction(exponents(lab), n, seg) for lab in united_system(n)])
    return _RESTRICTIONS[key]


def _orbit_coordinates(n: int, alpha: RationalAngle) -> dict[tuple[int, int], list[fmpq_poly]]:
    _, rows = restrictions(n, alpha)
    out = {}
    for rep, members in orbits(n):
        coords = [fmpq_poly() for _ in range(2 * n + 1)]
        for k_ in members:
            for k, ser in enumerate(rows[k_]):
                coords[k] += ser
        out[(rep.i, rep.j)] = coords
    return out


def _valuation(p: fmpq_poly) -> int | None:
    for k, x in enumerate(p.coeffs()):
        if x != 0:
            return k
    return None


# --- Lemma 1 ----------------------------------------------------------------------------------------------------
def restriction_identity(alpha: RationalAngle, tv: fmpq, tus: list[fmpq]) -> dict:
    """Lemma 1 at exact points: with v = 4 atan(tv) and u = 4 atan(tu) (w = alpha - u - v), check
    cos(u/2) s' = z + c'x, cos(w/2) s' = x + c'z and x^2 + 2c'xz + z^2 = s'^2 exactly."""
    from paper_repro.core.context import ExactContext
    from paper_repro.core.domain import RationalPoints

    pts = RationalPoints(alpha, tuple(tus), tuple([tv] * len(tus)), check=False)
    su, cu, sv, cv, sw, cw = pts.half_angle_values()
    ctx = ExactContext()
    sa, ca = ctx.alpha_half(alpha)
    # c' = cos((alpha - v)/2), s' = sin((alpha - v)/2): angle differences
    cpv = ca * cv[0] + sa * sv[0]
    spv = sa * cv[0] - ca * sv[0]
    bad = []
    for k in range(len(tus)):
        x, z = su[k], sw[k]
        if cu[k] * spv != z + cpv * x or cw[k] * spv != x + cpv * z or x * x + 2 * cpv * x * z + z * z != spv * spv:
            bad.append(k)
    return {"ok": not bad, "points": len(tus), "failures": bad}


# --- Lemma 2: the order lemma ----------------------------------------------------------------------------------
def predicted_profile(lab: BasisLabel) -> dict:
    """What the order lemma says of one function: sine power of v (its order in v), the coordinates it reaches
    (z-powers ``lo..hi``), and the leading coefficients the proof uses (as functions of c/s)."""
    n = lab.n
    au, bu, av, bv, aw, bw = exponents(lab)
    d = au + bu + aw + bw
    return {"order": av, "lo": aw, "hi": 2 * n - au, "degree_uw": d}


def order_table(n: int, alpha: RationalAngle, labels=None) -> dict:
    """Check the order lemma for every function of T_{2n} (or ``labels``) at ``alpha``, by exact series to order n.

    For each function: (a) no coordinate outside z-powers ``lo..hi`` is non-zero; (b) every coordinate vanishes to
    order >= the sine power of v (and the coordinate ``lo`` to exactly that order when it is <= n); (c) the named
    leading terms: R_{2n,2n-i,j} contributes only sigma^j kappa^{min(i,2n-i)-j} to coordinate i; for i > n,
    B_{2n,2n-i,j} has leading coefficient (c/s)^{k-j}/2^k at coordinate k = 2n - i; G_{2n,n,j} and B_{2n,n,j}
    have (c/s)^{n-j}/2^n at coordinate n.
    """
    n = check_n(n)
    if labels is None:
        seg, rows = restrictions(n, alpha)
        labels = united_system(n)
    else:
        seg = SegmentSeries(alpha, n)
        rows = [restriction(exponents(lab), n, seg) for lab in labels]
    ratio = seg.c / seg.s
    problems = []
    for lab, coords in zip(labels, rows):
        prof = predicted_profile(lab)
        for k, ser in enumerate(coords):
            val = _valuation(ser)
            if val is None:
                continue
            if not prof["lo"] <= k <= prof["hi"]:
                problems.append((lab.name, k, "coordinate outside the predicted range"))
            if val < prof["order"]:
                problems.append((lab.name, k, f"order {val} below the predicted {prof['order']}"))
        lo_val = _valuation(coords[prof["lo"]])
        if prof["order"] <= n and lo_val != prof["order"]:
            problems.append((lab.name, prof["lo"], f"lowest coordinate has order {lo_val}, predicted {prof['order']}"))
        i, j = lab.i, lab.j
        if lab.color == "R" and not lab.is_centre or lab.is_centre:
            m = min(i, 2 * n - i)
            want = _mul(seg.power("sigma", j), seg.power("kappa", m - j), n)
            if coords[i] != want or any(ser != 0 for k, ser in enumerate(coords) if k != i):
                problems.append((lab.name, i, "an R function is not the monomial sigma^j kappa^(m-j) x^(2n-i) z^i"))
        lead = None
        if lab.color == "B" and i > n:
            k = 2 * n - i
            lead = (k, ratio ** (k - j) / 2**k)
        elif lab.color in ("G", "B") and i == n and not lab.is_centre:
            lead = (n, ratio ** (n - j) / 2**n)
        if lead is not None:
            k, want = lead
            got = coords[k].coeffs()[k] if len(coords[k].coeffs()) > k else fmpq(0)
            if got != want or _valuation(coords[k]) != k:
                problems.append((lab.name, k, f"leading coefficient {got}, predicted {want}"))
    return {"ok": not problems, "n": n, "functions": len(labels), "problems": problems[:20]}


# --- the triangular orbit system of the proof of Theorem B --------------------------------------------------
def triangular_block(n: int, alpha: RationalAngle) -> dict:
    """The orbit matrix M[(k, l), (i, j)] = [v^l] coordinate k of the orbit sum (i, j), rows k = 0..n, l = 0..k:
    zero unless k = i and l >= j, with diagonal [v^j] sigma^j kappa^(..) = 2^-j."""
    n = check_n(n)
    data = _orbit_coordinates(n, alpha)
    bad = []
    for rep, _ in orbits(n):
        coords = data[(rep.i, rep.j)]
        i, j = rep.i, rep.j
        for k in range(n + 1):
            cs = coords[k].coeffs()
            for ell in range(k + 1):
                x = cs[ell] if ell < len(cs) else fmpq(0)
                if (k != i or ell < j) and x != 0:
                    bad.append((rep.coefficient, k, ell, "non-zero off the triangle"))
                if k == i and ell == j and x != fmpq(1, 2**j):
                    bad.append((rep.coefficient, k, ell, f"diagonal {x}, expected 1/2^{j}"))
    return {"ok": not bad, "n": n, "orbits": len(orbits(n)), "problems": bad[:20]}


# --- Theorem B at sampled alpha: the triangular solve reproduces the formula -----------------------------------
def triangular_solution(n: int, alpha: RationalAngle) -> dict:
    """Solve the triangular system of Lemma 3 with the Taylor data of the right-hand side
    ((x^2 + 2c'xz + z^2)/s'^2)^n (coordinate k: C_{n,k}(c')/s'^{2n}) and compare with the formula's coefficients."""
    n = check_n(n)
    seg, _ = restrictions(n, alpha)
    inv = seg.power("inv_sp", 2 * n)
    rhs = [_mul(x, inv, n) for x in seg.factor("q", n)]
    data = _orbit_coordinates(n, alpha)
    solved: dict[tuple[int, int], fmpq] = {}
    for k in range(n + 1):
        for ell in range(k + 1):  # row (k, l) determines the unknown (i, j) = (k, l)
            acc = rhs[k].coeffs()[ell] if ell < len(rhs[k].coeffs()) else fmpq(0)
            for jj in range(ell):
                cs = data[(k, jj)][k].coeffs()
                acc -= solved[(k, jj)] * (cs[ell] if ell < len(cs) else fmpq(0))
            diag = data[(k, ell)][k].coeffs()[ell]
            solved[(k, ell)] = acc / diag
    s = alpha.sin_half
    formula = scaled_table(n, alpha.cos_half, s * s, _exact())
    reps = [rep for rep, _ in orbits(n)]
    mismatch = [rep.coefficient for rep, f in zip(reps, formula) if solved[(rep.i, rep.j)] * s ** (2 * n + rep.j) != f]
    return {"ok": not mismatch, "n": n, "t": str(alpha.t), "mismatches": mismatch[:10]}


def _exact():
    from paper_repro.core.context import ExactContext

    return ExactContext()


# --- Lemma 5: the hexagon -----------------------------------------------------------------------------------------
def hexagon(n: int) -> set[tuple[int, int]]:
    """Frequencies (p, q) with |p|, |q|, |p - q| <= n."""
    return {(p, q) for p in range(-n, n + 1) for q in range(-n, n + 1) if abs(p - q) <= n}


def hexagon_check(n: int, labels=None) -> dict:
    """Every function of T_{2n} (or ``labels``) lies in the span of the hexagon's frequencies, and |hexagon| = delta_n.

    A function with per-variable half-angle degrees d_u, d_v, d_w has the frequencies
    ((eps_u - eps_w)/2, (eps_v - eps_w)/2), eps_x in {-d_x, -d_x + 2, ..., d_x}: integers iff the three degrees have
    one parity, and -- the map being linear and the hexagon convex -- all in the hexagon iff the images of the eight
    corners eps_x = +-d_x are.  Both are checked for every function."""
    n = check_n(n)
    hexa = hexagon(n)
    labels = united_system(n) if labels is None else labels
    bad = []
    for lab in labels:
        au, bu, av, bv, aw, bw = exponents(lab)
        du, dv, dw = au + bu, av + bv, aw + bw
        if (du - dw) % 2 or (dv - dw) % 2:
            bad.append((lab.name, "half-integer frequency"))
            continue
        for eu in (-du, du):
            for ev in (-dv, dv):
                for ew in (-dw, dw):
                    if ((eu - ew) // 2, (ev - ew) // 2) not in hexa:
                        bad.append((lab.name, ((eu - ew) // 2, (ev - ew) // 2)))
    return {"ok": not bad and len(hexa) == 3 * n * n + 3 * n + 1, "hexagon": len(hexa),
            "delta_n": 3 * n * n + 3 * n + 1, "problems": bad[:10]}


# --- Corollary C: positivity of the weights --------------------------------------------------------------------------
def weights_nonnegative(n: int) -> dict:
    """w_f(m) = [t^f] (1 - m t)/(1 - t)^{2n+1} >= 0 for f <= n and m = 1, 2, 3, computed as a power-series
    coefficient (not from the closed form t_weight), and equal to the closed form."""
    n = check_n(n)
    bad = []
    for m in (1, 2, 3):
        ser = fmpq_poly([1, -m]) * _inv_series(fmpq_poly([1, -1]) ** (2 * n + 1), n)
        cs = ser.coeffs() + [fmpq(0)] * (n + 1)
        for f in range(n + 1):
            if cs[f] < 0 or cs[f] != t_weight(n, f, m):
                bad.append((m, f, str(cs[f])))
    return {"ok": not bad, "n": n, "problems": bad[:10]}


__all__ = ["SegmentSeries", "restriction", "restriction_identity", "predicted_profile", "order_table",
           "triangular_block", "triangular_solution", "hexagon", "hexagon_check", "weights_nonnegative"]
