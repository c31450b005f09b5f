"""Claim ``every_line``: every line of the paper that states something, checked (issue 19).

The lines are transcribed verbatim in :mod:`paper_repro.printed.lines` (one module per part of the paper), the
checks registered in :mod:`paper_repro.claims.lines`.  This claim runs every check once and judges each line by
its status:

* ``checked``: the check finds the line holds as printed;
* ``erratum``: the check finds the printed line fails and the corrected line holds;
* ``excused``: the line gives a reason.

A check ``"claim:<id>"`` is not re-run: it is resolved to the result of claim ``<id>`` in the same run (the
runner passes the results of every other claim as ``claim_results``; run alone, the committed
``data/claims.json`` is read).  That claim must exist and pass; for an erratum line with an ``id`` the claim
must publish that erratum.  Errata of lines with their own check are published here (``data/errata.json``),
those resolved to a claim are published by that claim already.

Publishes ``data/paper_lines.json``: the coverage and, per line (sorted by source line), its transcription,
status, check, how it was checked, how far that settles it (``proof_kind``: ``proof`` for everything the line states,
``exhaustive`` for the finite range ``how`` names only, ``exact-evidence``, ``numeric-evidence``; see
:mod:`paper_repro.claims.lines`), and the PDF number of the nearest label (``paper_repro/resources/paper_index.json``).
"""

from __future__ import annotations

import json
from collections import Counter
from typing import Any

from paper_repro.util.registry import Outcome, claim

#: The weakest kind wins: a claim over lines of several kinds is as strong as its weakest check.
_KIND_ORDER = ("numeric-evidence", "exact-evidence", "exhaustive", "proof")

#: Claims of kind ``proof`` whose statement covers everything the lines resolved to them state (fixed orders: the
#: lines name orders 1, 2, 3 or printed order-2/3 conversions).  A line resolved to any other claim of kind ``proof``
#: is ``exhaustive``: that claim settles its statement for the finite range of n it names, the line states more.
CLAIMS_SETTLING_THEIR_LINES = {"nonnegativity": "the line states orders 1, 2, 3, the claim's range",
                               "bezier_conversion": "the line states one printed conversion of order 3"}


def _committed_results() -> dict[str, dict]:
    """Claim results of the committed ``data/claims.json`` and ``data/errata.json`` (a run of this claim alone)."""
    from paper_repro.util.io import DATA

    try:
        claims = json.loads((DATA / "claims.json").read_text())
        errata = [e["id"] for e in json.loads((DATA / "errata.json").read_text())]
    except (OSError, ValueError):
        return {}
    # the committed errata do not say which claim published them: any committed erratum id resolves
    return {c["id"]: {"status": c["status"], "kind": c["kind"], "errata": errata, "statement": c["statement"]}
            for c in claims}


def claim_line_kind(cid: str, res: dict) -> tuple[str, str]:
    """(kind, how) of a line resolved to claim ``cid`` with result ``res``: a ``proof`` claim that does not settle
    everything its lines state (:data:`CLAIMS_SETTLING_THEIR_LINES`) makes them ``exhaustive`` for the range its
    statement names."""
    from paper_repro.claims.lines import RANGE_WORDS

    how = f"claim {cid} ({res['status']})"
    if res["kind"] != "proof" or cid in CLAIMS_SETTLING_THEIR_LINES:
        return res["kind"], how
    ranges = RANGE_WORDS.findall(res.get("statement") or "")
    where = ", ".join(dict.fromkeys(ranges)) if ranges else "the range of n its statement names"
    return "exhaustive", f"{how}: exhaustive for {where} (the claim's statement), not for every n"


def _number(label: str, index: dict[str, dict]) -> str | None:
    rec = index.get(label)
    if not rec or not rec.get("number"):
        return None
    return rec.get("display") or None


def _erratum_record(line) -> dict[str, Any]:
    e = line.erratum
    return {"id": e.get("id", line.id), "paper_ref": line.near, "item": e.get("item", line.says),
            "severity": e["severity"], "printed": e["printed"], "corrected": e["corrected"],
            "evidence": e["evidence"], "source_lines": list(line.tex)}


def check_chunks(lines=None) -> list[tuple[str, ...]]:
    """The checks the lines name (not ``claim:``, not those of excused lines), grouped by the part of the paper of
    the first line naming each (a part's checks share the part's memos), in line order."""
    from paper_repro.printed.lines import all_lines

    groups: dict[str, dict[str, None]] = {}
    seen: set[str] = set()
    for line in all_lines() if lines is None else lines:
        if line.status != "excused" and line.check and not line.check.startswith("claim:") and line.check not in seen:
            seen.add(line.check)
            groups.setdefault(line.id.split("-", 1)[0], {})[line.check] = None
    return [tuple(g) for g in groups.values()]


def _outcome_record(run) -> dict[str, Any]:
    """What :func:`judge` uses of a check's result (or its exception), as JSON."""
    if isinstance(run, Exception):
        return {"error": f"{type(run).__name__}: {run}"}
    return {"holds_as_printed": run.holds_as_printed, "corrected_holds": run.corrected_holds, "how": run.how,
            "kind": run.kind}


def _transcriptions_digest() -> str:
    """sha256 of every transcription as read now (a line substituted by the mutation tests is a new key)."""
    import hashlib

    from paper_repro.printed.lines import all_lines

    h = hashlib.sha256()
    for line in all_lines():
        h.update(json.dumps([line.id, line.verbatim, line.status, line.check]).encode())
    return h.hexdigest()[:16]


class _Crashed(Exception):
    """A chunk in which a check raised: its records are returned, not stored."""

    def __init__(self, records: dict[str, dict[str, Any]]):
        super().__init__("a line check raised")
        self.records = records


def run_check_chunk(check_ids: tuple[str, ...]) -> dict[str, dict[str, Any]]:
    """Run the named line checks (a task of :func:`prepare_tasks`): ``{check: record}``, a record as
    :func:`_outcome_record`.  Stored in the cache under the package source when no check raised (a cache never
    stores a crash); the key names the package source and the transcriptions as read now."""
    from paper_repro.claims.lines import load_checks
    from paper_repro.util.cache import cached, code_fingerprint

    def compute() -> dict[str, dict[str, Any]]:
        checks = load_checks()
        out: dict[str, dict[str, Any]] = {}
        for cid in check_ids:
            try:
                out[cid] = _outcome_record(checks[cid]())
            except Exception as exc:  # a crashing check is a failing line (judge reports it)
                out[cid] = _outcome_record(exc)
        if any("error" in r for r in out.values()):
            raise _Crashed(out)
        return out

    try:
        return cached("line_checks", {"checks": list(check_ids), "code": code_fingerprint(),
                                      "lines": _transcriptions_digest()}, compute)
    except _Crashed as crash:
        return crash.records


def prepare_tasks() -> list:
    """Every line check, one task per part: run beside the other claims (``Claim.prepare``)."""
    from paper_repro.util.tasks import Task

    return [Task(run_check_chunk, (chunk,)) for chunk in check_chunks()]


def judge(lines, checks: dict, claim_results: dict[str, dict],
          prepared: dict[str, dict[str, Any]] | None = None) -> tuple[list[dict], list[dict], list[str]]:
    """(one record per line, the errata to publish, the problems found) -- see the module docstring.

    ``prepared``: the checks' records already computed (:func:`run_check_chunk`); the others run here."""
    from paper_repro.util.paper_labels import load_index

    index = {r["label"]: r for r in load_index()}
    ran: dict[str, Any] = dict(prepared or {})
    records, errata, problems = [], [], []
    for line in lines:
        holds, corrected, how, kind = None, None, "", None
        if line.status == "excused":
            if not (line.reason or "").strip():
                problems.append(f"{line.id}: excused without a reason")
        elif line.check and line.check.startswith("claim:"):
            cid = line.check.split(":", 1)[1]
            res = claim_results.get(cid)
            if res is None:
                problems.append(f"{line.id}: check {line.check} names no claim result")
            else:
                ok = res["status"] == "pass"
                kind, how = claim_line_kind(cid, res)
                if line.status == "checked":
                    holds = ok
                else:
                    holds = False if ok else None  # the claim records the printed line as failing
                    eid = (line.erratum or {}).get("id")
                    corrected = ok and (eid is None or eid in res.get("errata", []))
                    if eid is not None and eid not in res.get("errata", []):
                        problems.append(f"{line.id}: claim {cid} does not publish erratum {eid}")
        else:
            if line.check not in checks:
                problems.append(f"{line.id}: check {line.check!r} is not registered")
            else:
                if line.check not in ran:
                    try:
                        ran[line.check] = _outcome_record(checks[line.check]())
                    except Exception as exc:  # a crashing check is a failing line, reported as such
                        ran[line.check] = _outcome_record(exc)
                r = ran[line.check]
                if "error" in r:
                    problems.append(f"{line.id}: check {line.check} raised {r['error']}")
                else:
                    holds, corrected, how, kind = r["holds_as_printed"], r["corrected_holds"], r["how"], r["kind"]
        if line.status == "checked" and holds is not True:
            problems.append(f"{line.id}: does not hold as printed (check {line.check})")
        if line.status == "erratum" and not (holds is False and corrected is True):
            problems.append(f"{line.id}: erratum not confirmed (printed holds: {holds}, corrected holds: "
                            f"{corrected}; check {line.check})")
        erratum = None
        if line.status == "erratum":
            erratum = _erratum_record(line)
            if not line.check.startswith("claim:"):
                errata.append(erratum)
        records.append({"id": line.id, "part": line.id.split("-", 1)[0], "tex": list(line.tex), "near": line.near,
                        "number": _number(line.near, index), "kind": line.kind, "verbatim": line.verbatim,
                        "says": line.says, "status": line.status, "check": line.check, "how": how or None,
                        "proof_kind": kind, "holds_as_printed": holds, "corrected_holds": corrected,
                        "reason": line.reason, "erratum": erratum})
    return records, errata, problems


def coverage(records: list[dict]) -> dict:
    by_kind: dict[str, Counter] = {}
    by_part: dict[str, Counter] = {}
    for r in records:
        by_kind.setdefault(r["kind"], Counter())[r["status"]] += 1
        by_part.setdefault(r["part"], Counter())[r["status"]] += 1
    total = Counter(r["status"] for r in records)
    proof_kinds = Counter(r["proof_kind"] for r in records if r["proof_kind"])
    return {"lines": len(records), "checked": total["checked"], "erratum": total["erratum"],
            "excused": total["excused"],
            "by_proof_kind": {k: proof_kinds[k] for k in reversed(_KIND_ORDER) if proof_kinds[k]},
            "by_kind": {k: dict(sorted(v.items())) for k, v in sorted(by_kind.items())},
            "by_part": {k: dict(sorted(v.items())) for k, v in sorted(by_part.items())}}


@claim("every_line", paper_ref=["sec:RGB", "sec:linear_independence", "sec:coincidence", "sec:partition_of_unity",
                                "sec:applications", "sec:open_problems"],
       statement="Every line of the paper that states something (each displayed line, each inline index set, range, "
                 "bound, parametrization, count and caption value; data/paper_lines.json) holds as printed by an "
                 "independent computation, or is an erratum whose printed form fails and whose corrected form "
                 "holds, or is excused with a reason.",
       kind="exact-evidence", uses_results=True, prepare=prepare_tasks)
def run(claim_results: dict[str, dict] | None = None, prepared: list | None = None) -> Outcome:
    from paper_repro.claims.lines import load_checks
    from paper_repro.printed.lines import PARTS, all_lines

    results = dict(_committed_results())
    results.update(claim_results or {})
    lines = all_lines()
    ran = {k: v for chunk in (prepared or []) for k, v in chunk.items()}
    records, errata, problems = judge(lines, load_checks(), results, prepared=ran)
    cov = coverage(records)
    kinds = {r["proof_kind"] for r in records if r["proof_kind"]}
    kind = next((k for k in _KIND_ORDER if k in kinds), "exact-evidence")
    kind = "proof" if kind == "exhaustive" else kind  # a claim's "proof" is already "for the stated range"
    parts_present = sorted({r["part"] for r in records})
    passed = not problems and bool(records)
    measured = {"coverage": cov, "parts": parts_present, "parts_missing": [p for p in PARTS if p not in parts_present],
                "problems": problems,
                "checks_run": len({r["check"] for r in records if r["check"] and not r["check"].startswith("claim:")}),
                "errata_published_here": sorted(e["id"] for e in errata)}
    return Outcome(passed, measured, kind=kind, errata=errata,
                   data={"paper_lines.json": {"coverage": cov, "lines": records}})
