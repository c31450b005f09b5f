"""Claim and figure registries.

A *claim* is a statement of the paper checked by a program.  Each claim module registers a
function with :func:`claim`; the function receives its parameters as keyword arguments and
returns an :class:`Outcome`.  :func:`run_claim` turns that into a :class:`ClaimResult`, the record
written to ``data/claims.json``.

A *figure* is registered with :func:`figure`; the function receives the output folder and returns
the files it wrote.

Kinds of claim (say what is proven and what is evidence):

* ``proof`` -- exhaustive or exact checks that settle the statement for the stated range;
* ``exact-evidence`` -- exact arithmetic at sampled parameters (e.g. rational-tangent alpha);
* ``numeric-evidence`` -- floating-point / high-precision checks at sampled parameters.
"""

from __future__ import annotations

import importlib
import re
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from typing import Any

from paper_repro.util.cache import cached, code_fingerprint, keys_and_types

KINDS = ("proof", "exact-evidence", "numeric-evidence")


@dataclass
class Outcome:
    """What a claim function returns."""

    passed: bool
    measured: dict[str, Any]
    kind: str | None = None  # overrides the registered kind when the run decides it
    errata: list[dict[str, Any]] = field(default_factory=list)
    #: data files to publish: path relative to ``data/`` -> JSON-able object, or str for text files
    data: dict[str, Any] = field(default_factory=dict)
    #: raw machine-dependent values (floats to the last bit) behind the bounds/rounded values of ``measured``:
    #: written to ``build/measured_raw.json``, never to ``data/`` (see :mod:`paper_repro.util.measured`)
    raw: dict[str, Any] = field(default_factory=dict)


@dataclass
class ClaimResult:
    id: str
    paper_ref: list[str]
    statement: str
    kind: str
    parameters: dict[str, Any]
    measured: dict[str, Any]
    status: str

    def as_dict(self) -> dict[str, Any]:
        return asdict(self)


@dataclass
class Claim:
    id: str
    paper_ref: list[str]
    statement: str
    kind: str
    func: Callable[..., Outcome]
    defaults: dict[str, Any]
    extended: dict[str, Any] | None = None  # parameters for `make reproduce-extended`
    #: runs after every other claim of the run and receives their results as ``claim_results`` (see
    #: :func:`run_claim`): a claim that resolves checks to other claims (``every_line``)
    uses_results: bool = False
    #: a split claim's body (a generator yielding lists of tasks, :mod:`paper_repro.util.tasks`); ``func`` then
    #: runs it inline
    body: Callable[..., Any] | None = None
    #: a ``uses_results`` claim's work that does not need the other claims' results: a function returning a list
    #: of tasks (:mod:`paper_repro.util.tasks`) that the runner computes beside the other claims (the first
    #: round); the claim then receives their results, in order, as ``prepared`` (``None`` when run alone)
    prepare: Callable[[], list[Any]] | None = None


@dataclass
class Figure:
    id: str
    caption: str
    paper_label: str | None
    func: Callable[..., list]
    module: str
    outputs: list[str]  # file names written into figures/ (PNG; an SVG of the same name is written beside)
    claims: list[str] = field(default_factory=list)  # claims the figure illustrates (beside those citing its label)


CLAIMS: dict[str, Claim] = {}
FIGURES: dict[str, Figure] = {}

#: Modules that register claims and figures, in report order.
CLAIM_MODULES = (
    "paper_repro.claims.dimension",
    "paper_repro.claims.boundary",
    "paper_repro.claims.symmetry",
    "paper_repro.claims.univariate",
    "paper_repro.claims.partition_of_unity",
    "paper_repro.claims.normalizing_closed_forms",
    "paper_repro.claims.nonnegativity",
    "paper_repro.claims.general_formulas",
    "paper_repro.claims.question1_all_n",
    "paper_repro.claims.limit_formula",
    "paper_repro.claims.independence_proof",
    "paper_repro.claims.matrix_closed_forms",
    "paper_repro.claims.transformation_all_n",
    "paper_repro.claims.linear_independence",
    "paper_repro.claims.derivative_signs",
    "paper_repro.claims.equivalence_classes",
    "paper_repro.claims.coincidence",
    "paper_repro.claims.basis_transformation",
    "paper_repro.claims.limits_claims",
    "paper_repro.claims.order_elevation",
    "paper_repro.claims.subdivision",
    "paper_repro.claims.joins",
    "paper_repro.claims.half_angle_all_n",
    "paper_repro.claims.torus",
    "paper_repro.claims.surfaces_claims",
    "paper_repro.claims.float_accuracy",
    "paper_repro.claims.every_line",
)
FIGURE_MODULES = (
    "paper_repro.figures.graph",
    "paper_repro.figures.normalization_plots",
    "paper_repro.figures.independence",
    "paper_repro.figures.limits_fig",
    "paper_repro.figures.patches_fig",
    "paper_repro.figures.accuracy",
    "paper_repro.figures.subdivision_fig",
    "paper_repro.figures.joins_fig",
)


def claim(id: str, *, paper_ref: list[str], statement: str, kind: str, extended: dict | None = None,
          uses_results: bool = False, alpha_range: tuple[float, float, str] | None = None, split: bool = False,
          prepare: Callable[[], list[Any]] | None = None,
          **defaults: Any) -> Callable[[Callable[..., Outcome]], Callable[..., Outcome]]:
    """Register a claim function under ``id`` with default parameters ``defaults``.

    ``alpha_range = (low, high, why)``: where the claim decides its statement at every order it runs at
    (measured: ``tools/alpha_ranges.py``); the command line refuses ``--alpha`` outside it before any work
    (:data:`ALPHA_RANGES`).

    With ``split`` the function is a generator that yields lists of tasks (:mod:`paper_repro.util.tasks`):
    a sweep runs them on every worker; the decorator returns a function that runs them inline.

    ``prepare`` (only with ``uses_results``): see :attr:`Claim.prepare`."""
    if prepare is not None and not uses_results:
        raise ValueError(f"claim {id!r}: prepare is for a claim that uses the other claims' results")
    if kind not in KINDS:
        raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")
    if alpha_range is not None:
        lo, hi, why = alpha_range
        if not (0 < lo < hi < 3.141592653589794 and isinstance(why, str) and why):
            raise ValueError(f"alpha_range must be (low, high, why) with 0 < low < high < pi, got {alpha_range!r}")
        ALPHA_RANGES[id] = (lo, hi, why)

    def deco(func: Callable[..., Any]) -> Callable[..., Outcome]:
        if id in CLAIMS:
            raise ValueError(f"claim {id!r} registered twice")
        body = None
        if split:
            import functools

            from paper_repro.util.tasks import drive_inline

            body = func

            @functools.wraps(body)
            def func(**params: Any) -> Outcome:
                return drive_inline(body(**params))

        CLAIMS[id] = Claim(id, list(paper_ref), statement, kind, func, dict(defaults), extended, uses_results, body,
                           prepare)
        return func

    return deco


def figure(id: str, *, caption: str, outputs: list[str], paper_label: str | None = None,
           claims: list[str] | None = None) -> Callable:
    """Register a figure generator ``func(outdir) -> list[Path]`` that writes ``outputs`` into outdir."""

    def deco(func: Callable[..., list]) -> Callable[..., list]:
        if id in FIGURES:
            raise ValueError(f"figure {id!r} registered twice")
        FIGURES[id] = Figure(id, caption, paper_label, func, func.__module__, list(outputs), list(claims or []))
        return func

    return deco


def load_all() -> None:
    """Import every claim and figure module (registration happens on import)."""
    code_fingerprint()  # fix the key of cached results to the code as loaded now
    for mod in CLAIM_MODULES + FIGURE_MODULES:
        importlib.import_module(mod)


#: How the command line's ``--n N`` maps onto the parameters a claim takes (only those it has).
N_PARAMETERS = {"ns": lambda n: [n], "n_min": lambda n: n, "n_max": lambda n: n, "bernstein_ns": lambda n: [n],
                "ns_numeric": lambda n: [n], "n_exact_max": lambda n: n}
ALPHA_PARAMETERS = {"alphas": lambda a: [a]}


#: Where ``--alpha`` is meaningful for a claim, when narrower than (0, pi): ``(low, high, why)``.  Outside it the
#: check cannot decide the statement in the claim's arithmetic (the reason is ``why``), so the CLI refuses the value
#: before any work instead of reporting a true statement as FAIL.
ALPHA_RANGES: dict[str, tuple[float, float, str]] = {}


def n_range(c: Claim) -> int | None:
    """Largest order the claim has been run and timed at (its default and extended parameters): ``--n`` beyond it
    is refused (``None`` if the claim takes no order)."""
    values: list[int] = []
    for params in (c.defaults, c.extended or {}):
        for k in N_PARAMETERS:
            v = params.get(k)
            if isinstance(v, list):
                values += [int(x) for x in v]
            elif isinstance(v, int):
                values.append(v)
    return max(values) if values else None


def check_cli_range(c: Claim, n: int | None, alpha: float | None) -> None:
    """``ValueError`` naming the option and the claim's range if ``--n``/``--alpha`` lies outside it."""
    top = n_range(c)
    if n is not None and top is not None and n > top:
        raise ValueError(f"--n: claim {c.id!r} runs for n from 1 to {top} (its measured budget), got {n}")
    if alpha is not None and c.id in ALPHA_RANGES:
        lo, hi, why = ALPHA_RANGES[c.id]
        if not lo <= alpha <= hi:
            raise ValueError(f"--alpha: claim {c.id!r} is meaningful for alpha in [{lo:g}, {hi:.15g}] ({why}), "
                             f"got {alpha}")


def cli_overrides(c: Claim, n: int | None, alpha: str | None) -> dict[str, Any] | None:
    """Overrides of claim ``c`` for ``--n``/``--alpha``; ``None`` if the claim takes neither given option."""
    out: dict[str, Any] = {}
    for given, table in ((n, N_PARAMETERS), (alpha, ALPHA_PARAMETERS)):
        if given is None:
            continue
        hits = {k: f(given) for k, f in table.items() if k in c.defaults}
        if not hits:
            return None
        out.update(hits)
    return out


def _range_text(value: Any) -> str:
    """A parameter as a reader writes it: consecutive integer lists as ``a..b``."""
    if isinstance(value, list) and len(value) > 2 and all(isinstance(v, int) for v in value) \
            and value == list(range(value[0], value[-1] + 1)):
        return f"{value[0]}..{value[-1]}"
    if isinstance(value, list):
        return ", ".join(str(v) for v in value)
    return str(value)


def fill_statement(statement: str, params: dict[str, Any]) -> str:
    """Fill ``{name}`` placeholders of a claim statement with the parameters it ran with (other braces,
    such as ``T_{2n}``, are left as they are).

    >>> fill_statement("proven for n = 1..{n_max}, T_{2n}", {"n_max": 8})
    'proven for n = 1..8, T_{2n}'
    """
    return re.sub(r"\{(\w+)\}", lambda m: _range_text(params[m.group(1)]) if m.group(1) in params else m.group(0),
                  statement)


def check_overrides(c: Claim, overrides: dict[str, Any] | None, extended: bool = False) -> dict[str, Any]:
    """The claim's parameters with ``overrides`` applied; ``ValueError`` listing the accepted names if an
    override names a parameter the claim does not take."""
    params = dict(c.defaults)
    if extended and c.extended:
        params.update(c.extended)
    unknown = sorted(set(overrides or {}) - set(params))
    if unknown:
        raise ValueError(f"claim {c.id!r} takes no parameter(s) {unknown}; it takes {sorted(params)}")
    params.update(overrides or {})
    return params


#: The fields of a stored claim outcome (validated before a cached outcome is used).
_OUTCOME = keys_and_types(passed=bool, measured=dict, kind=(str, type(None)), errata=list, data=dict, raw=dict)


def claim_cache_key(c: Claim, params: dict[str, Any], claim_results: dict[str, dict] | None = None) -> dict:
    """The key of a claim's cached result: id, parameters and the package source."""
    extra = {"claim_results": claim_results} if c.uses_results else {}
    return {"id": c.id, "params": params, "code": code_fingerprint(), **extra}


def run_claim(c: Claim, overrides: dict[str, Any] | None = None, extended: bool = False,
              claim_results: dict[str, dict] | None = None, outcome: Outcome | BaseException | None = None,
              seconds: float | None = None, prepared: list[Any] | None = None) -> tuple[ClaimResult, Outcome, float]:
    """Run one claim; returns its result, the raw outcome (errata, data files), and the seconds it took.

    ``overrides`` may only name parameters the claim takes (``ValueError`` listing them otherwise).  A
    claim that raises is reported as failing with the error, and that failure is never cached.
    ``outcome`` (with ``seconds``): what the claim's body returned (or raised) when a sweep ran its tasks
    (:func:`paper_repro.util.tasks.drive`); it is checked, cached and reported like a computed one.  A claim
    registered with ``uses_results`` receives ``claim_results`` (``{id: {"status", "kind", "errata", "statement"}}``
    of the claims run before it; ``None`` when run alone) as a keyword argument; they are part of its cache key.

    The rule of :mod:`paper_repro.util.measured` is enforced here: a claim whose ``measured`` or data files hold
    a raw float (rounding-level or more than ``MAX_DIGITS`` digits) fails, naming the offending fields.
    """
    params = check_overrides(c, overrides, extended)
    t0 = time.perf_counter()
    extra = {"claim_results": claim_results} if c.uses_results else {}
    if prepared is not None:
        extra["prepared"] = prepared

    def compute() -> dict:
        if isinstance(outcome, BaseException):
            raise outcome
        return asdict(outcome if outcome is not None else c.func(**params, **extra))

    try:
        # whole-claim cache: keyed by id, parameters and the package source (see cache.code_fingerprint)
        stored, hit = cached("claims", claim_cache_key(c, params, claim_results), compute, report_hit=True,
                             validate=_OUTCOME)
    except Exception as exc:  # a crashing check is a failing claim, reported as such (and not cached)
        stored, hit = asdict(Outcome(False, {"error": f"{type(exc).__name__}: {exc}"})), False
    out = Outcome(**stored)
    from paper_repro.util.measured import data_violations, violations

    bad = violations(out.measured) + data_violations(out.data)
    if bad:  # data/ must be machine-independent: raw floats go to build/, data/ gets bounds or rounded values
        out.passed = False
        out.measured = {**out.measured, "error": f"measured holds machine-dependent raw values at {bad} "
                                                 "(publish a bound or a rounded value: paper_repro.util.measured)"}
    spent = time.perf_counter() - t0
    seconds = spent if hit or seconds is None else spent + seconds  # a swept claim: its tasks' seconds
    kind = out.kind or c.kind
    if kind not in KINDS:
        raise ValueError(f"claim {c.id}: kind {kind!r} not in {KINDS}")
    result = ClaimResult(c.id, c.paper_ref, fill_statement(c.statement, params), kind, params, out.measured,
                         "pass" if out.passed else "fail")
    result.cached = hit  # type: ignore[attr-defined]
    return result, out, seconds
