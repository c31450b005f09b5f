"""Closed forms of the normalizing coefficients and their positivity (open Question 1).

For every orbit representative ``r_{2n,2n-i,j}`` we look for a polynomial P with rational
coefficients such that ``r_{2n,2n-i,j}^alpha = P(cos(alpha/2)) / sin^{2n+j}(alpha/2)``.

* Recovery (:func:`recover`, :mod:`paper_repro.theory.modular`): solves over F_p at rational-tangent alpha,
  interpolation in ``c = cos(alpha/2)``, Chinese remainders.  That alone is *evidence*.
* Proof (:func:`prove`, :mod:`paper_repro.theory.identity_proof`): the partition-of-unity residual of the
  candidates is the zero polynomial in t = tan(alpha/4) at alpha-independent points that are unisolvent
  for the symmetric functions of the space containing T_{2n}; with two rank certificates this proves the
  candidates for *every* alpha (the argument, with its assumptions, is in that module and in
  ``docs/proof_of_closed_forms.md``).
* Positivity (:func:`sign_on_unit_interval`): exact real-root count of P on the open interval
  0 < c < 1 (Sturm sequence in flint's exact ``fmpq_poly`` arithmetic) and its sign at one point.
  With a proven closed form this proves ``r > 0`` for all alpha in (0, pi).
"""

from __future__ import annotations

import hashlib
import json

from flint import fmpq, fmpq_poly

from paper_repro.core.domain import rational_alpha
from paper_repro.core.normalization import orbits, parse_fmpq, solve_reduced_exact
from paper_repro.theory.closed_form import ClosedForm, sin_power
from paper_repro.util.cache import cached, keys_and_types, rational_text

__all__ = ["ClosedForm", "sin_power"]




def recover(n: int, verify: int = 2, max_degree: int | None = None) -> dict[str, ClosedForm]:
    """Closed forms ``P(c)/s^{2n+j}`` of every orbit representative (multimodular, see
    :func:`paper_repro.theory.modular.recover_modular`)."""
    from paper_repro.theory.modular import recover_modular

    return recover_modular(n, verify=verify, max_degree=max_degree)


def prove(n: int, forms: dict[str, ClosedForm], progress: bool = False) -> dict:
    """Prove ``forms`` for every alpha (:func:`paper_repro.theory.identity_proof.prove_identity`).

    On failure, ``mismatch`` names the first candidate that differs from the exact coefficient at
    tan(alpha/4) = ``t`` (1/2, or the next 1/k where the candidates differ from the exact solution).
    """
    from paper_repro.theory.identity_proof import prove_identity

    res = prove_identity(n, forms, progress=progress)
    res["mismatch"] = None
    if not res["proved"]:
        for k in range(2, 12):
            alpha = rational_alpha(fmpq(1, k))
            sol, _ = solve_reduced_exact(n, alpha, verify=0)
            bad = [rep.coefficient for o, (rep, _) in enumerate(orbits(n))
                   if forms[rep.coefficient].value(alpha) != sol[o]]
            if bad:
                res["mismatch"], res["t"] = bad[0], str(alpha.t)
                break
    return res


def sturm_count(p: fmpq_poly, a: fmpq, b: fmpq) -> int:
    """Number of distinct real roots of ``p`` in the half-open interval (a, b] (Sturm's theorem)."""
    if p.degree() <= 0:
        return 0
    p = p / p.gcd(p.derivative())  # square-free part: same distinct roots
    seq = [p, p.derivative()]
    while seq[-1].degree() > 0:
        rem = -(seq[-2] % seq[-1])
        if rem.is_zero():
            break
        seq.append(rem)

    def variations(x: fmpq) -> int:
        signs = [v for v in (q(x) for q in seq) if v != 0]
        return sum(1 for u, v in zip(signs, signs[1:]) if (u > 0) != (v > 0))

    return variations(a) - variations(b)


def sign_on_unit_interval(p: fmpq_poly) -> dict:
    """Roots of ``p`` in the open interval (0, 1) and its sign there (``+1``/``-1``, or 0 if it changes)."""
    roots = sturm_count(p, fmpq(0), fmpq(1)) - (1 if p(fmpq(1)) == 0 else 0)
    mid = p(fmpq(1, 2))
    sign = 0 if roots or mid == 0 else (1 if mid > 0 else -1)
    return {"roots_in_open_unit_interval": roots, "sign": sign}


#: What a cached proof keeps of :func:`prove`'s answer.
PROOF_KEYS = ("proved", "independence", "unisolvence", "points", "residuals_zero", "residual_degree_bound")

#: What a stored proof must look like (validated before a cached proof is used).
PROOF_VALID = keys_and_types(proved=bool)

#: Closed forms and proofs handed to this process by a sweep (:func:`remember`): ``n -> record``.  A task on a
#: cluster worker has no shared disk cache; it receives the records it needs as arguments instead.
_REMEMBERED: dict[int, dict] = {}


def _forms_sha256(stored: dict) -> str:
    return hashlib.sha256(json.dumps(dict(sorted(stored.items())), sort_keys=True).encode()).hexdigest()


def record(n: int) -> dict:
    """The recovered closed forms of order ``n`` and their proof, as JSON (a task of the extended sweeps: computed
    once, then handed to every task and claim that needs them through :func:`remember`)."""
    forms = closed_forms_cached(n)
    return {"n": n, "forms": {k: v.as_json() for k, v in forms.items()}, "proof": proof_cached(n)}


#: Points of the identity proof per task (n = 30 has 499 points, about 0.4 s of CPU each).
PROOF_CHUNK = 48


def recovered(n: int) -> dict:
    """Task: the closed forms of order ``n`` as JSON (:func:`closed_forms_cached`)."""
    return {k: v.as_json() for k, v in closed_forms_cached(n).items()}


def _forms_from_json(stored: dict) -> dict[str, ClosedForm]:
    return {k: ClosedForm(k, v["sin_power"], fmpq_poly([parse_fmpq(x) for x in v["numerator"]]))
            for k, v in stored.items()}


def _proof_key(n: int, stored: dict) -> dict:
    return {"n": n, "forms_sha256": _forms_sha256(stored), "method": "identity-v1"}


def proof_points_count(n: int) -> int:
    from paper_repro.theory.identity_proof import EXTRA_POINTS

    return len(orbits(n)) + EXTRA_POINTS


def unisolvence(n: int) -> dict:
    """Task: step 2 of the identity proof (the rank certificate of the orbit sums at the proof points)."""
    from paper_repro.theory.identity_proof import proof_points, unisolvence_certificate

    return unisolvence_certificate(n, proof_points(n, proof_points_count(n)))


def residuals_vanish(n: int, stored: dict, start: int, stop: int) -> dict:
    """Task: step 3 of the identity proof at the proof points ``start:stop`` of order ``n`` for the forms ``stored``
    (JSON): the first point whose residual is not zero (``None``: all zero) and the residuals' degree bound."""
    from paper_repro.theory.identity_proof import prepare, proof_points, residual_at_point

    forms = _forms_from_json(stored)
    pts = proof_points(n, proof_points_count(n))
    cache = prepare(n, forms)
    bad = next((k for k in range(start, stop)
                if not residual_at_point(n, forms, pts.tu[k], pts.tv[k], _cache=cache).is_zero()), None)
    return {"first_nonzero": bad, "degree_bound": 2 * (cache["d"] + cache["K"] + cache["R"])}


def records(ns: list[int], extra: list | tuple = ()):
    """Generator of a split claim (``got, recs = yield from records(ns, tasks)``): the closed forms of every order in
    ``ns`` recovered (one task per n, with ``extra`` tasks of the caller in the same round), then proven -- the two
    rank certificates and the residuals in chunks of :data:`PROOF_CHUNK` points, each a task -- unless the proof is
    cached.  Returns the results of ``extra`` and the records (:func:`record`) in the order of ``ns``; the proof is
    the dict :func:`proof_cached` computes in one piece (and is cached under its key)."""
    from paper_repro.theory.identity_proof import independence_certificate
    from paper_repro.util.cache import cached, is_cached
    from paper_repro.util.tasks import Task

    extra = list(extra)
    got = yield [Task(recovered, (n,)) for n in ns] + extra
    forms, extra_results = dict(zip(ns, got[: len(ns)])), got[len(ns):]
    plans: dict[int, list] = {}
    for n in ns:
        if is_cached("closed_form_proof", _proof_key(n, forms[n]), PROOF_VALID):
            plans[n] = []
            continue
        total = proof_points_count(n)
        plans[n] = [Task(independence_certificate, (n,)), Task(unisolvence, (n,))] + [
            Task(residuals_vanish, (n, forms[n], a, min(a + PROOF_CHUNK, total))) for a in range(0, total, PROOF_CHUNK)]
    got = iter((yield [t for n in ns for t in plans[n]]))
    out = []
    for n in ns:
        parts = [next(got) for _ in plans[n]]

        def assemble(n=n, parts=parts) -> dict:
            if not parts:  # cached (the caller's call below reads it)
                raise AssertionError("proof expected in the cache")
            cert1, cert2, chunks = parts[0], parts[1], parts[2:]
            failed = next((c["first_nonzero"] for c in chunks if c["first_nonzero"] is not None), None)
            return {"proved": cert1["full"] and cert2["full"] and failed is None, "independence": cert1,
                    "unisolvence": cert2, "points": proof_points_count(n), "residuals_zero": failed is None,
                    "residual_degree_bound": chunks[0]["degree_bound"]}

        proof = cached("closed_form_proof", _proof_key(n, forms[n]), assemble, validate=PROOF_VALID)
        out.append({"n": n, "forms": forms[n], "proof": proof})
    return extra_results, out


def remember(rec: dict) -> None:
    """Make :func:`closed_forms_cached` and :func:`proof_cached` of ``rec["n"]`` return ``rec`` in this process
    (no recomputation, no disk)."""
    _REMEMBERED[rec["n"]] = rec


def proof_cached(n: int) -> dict:
    """:func:`prove` of the recovered forms (:func:`closed_forms_cached`), memoised on disk by n and the forms."""
    forms = closed_forms_cached(n)
    text = json.dumps({k: v.as_json() for k, v in sorted(forms.items())}, sort_keys=True)
    rec = _REMEMBERED.get(n)
    if rec is not None and rec.get("proof") is not None and _forms_sha256(rec["forms"]) == hashlib.sha256(
            text.encode()).hexdigest():
        return rec["proof"]
    return cached("closed_form_proof", {"n": n, "forms_sha256": hashlib.sha256(text.encode()).hexdigest(),
                                        "method": "identity-v1"},
                  lambda: {k: v for k, v in prove(n, forms).items() if k in PROOF_KEYS},
                  validate=PROOF_VALID)


def _forms_problem(n: int, value) -> str | None:
    """Why a stored set of closed forms is bad: not one form per orbit representative of order n, a sine power
    that is not 2n + j, or a numerator that is not a list of exact rationals."""
    labels = {rep.coefficient: rep.j for rep, _ in orbits(n)}
    if not isinstance(value, dict) or set(value) != set(labels):
        return f"not one closed form per orbit representative of order {n}"
    for lab, form in value.items():
        if not isinstance(form, dict) or form.get("sin_power") != 2 * n + labels[lab]:
            return f"{lab}: sine power is not {2 * n + labels[lab]}"
        num = form.get("numerator")
        if not isinstance(num, list) or not num or not all(rational_text(x) for x in num):
            return f"{lab}: numerator is not a list of exact rationals"
    return None


def closed_forms_cached(n: int) -> dict[str, ClosedForm]:
    """:func:`recover`, memoised on disk (or handed over by :func:`remember`)."""
    rec = _REMEMBERED.get(n)
    stored = rec["forms"] if rec is not None else cached(
        "closed_forms", {"n": n}, lambda: {k: v.as_json() for k, v in recover(n).items()},
        validate=lambda value: _forms_problem(n, value))
    return {k: ClosedForm(k, v["sin_power"], fmpq_poly([parse_fmpq(x) for x in v["numerator"]]))
            for k, v in stored.items()}
