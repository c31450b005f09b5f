"""Does each line check read its line?  The blank test and the mutation test of the line checks.

A check of a transcribed line (:mod:`paper_repro.printed.lines`) that still says "holds as printed" when its line
is blanked, or when the line is changed in a way that makes it false, checks nothing about the paper.  Two tests
run the checks on changed transcriptions (:func:`paper_repro.printed.lines.substituted`):

* :func:`blank_test`: every line a check belongs to replaced by ``XXX``; the check must fail (return another
  verdict, or raise);
* :func:`mutation_test`: the operators of :func:`mutants` (an index bound moved by one, a sign, two variables
  swapped, a constant, a dropped term, a relation, a quantifier, a key word) applied one at a time to each line;
  a mutant is *killed* when the check's verdict changes or the check raises.  A mutant that keeps the line true
  (a wider interval, a swap of two variables the formula is symmetric in) is *equivalent*: it is listed in
  :data:`paper_repro.claims.lines.equivalents.EQUIVALENT` with the reason, and not counted.

A line resolved to a claim (``claim:<id>``) is tested by running that claim's body on the changed line.

The verdict of a check is ``(holds_as_printed, corrected_holds)``; a check that raises on a changed line has
refused it (killed).

>>> sorted({m.op for m in mutants(r"\\sum_{i=0}^{2n}x_i=1,~\\forall t")})
['bound', 'constant', 'quantifier', 'relation']
"""

from __future__ import annotations

import hashlib
import random
import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass

BLANK = "XXX"


@dataclass(frozen=True)
class Mutant:
    line_id: str
    op: str  # bound, sign, swap, constant, drop, relation, quantifier, word
    where: str  # what was changed, in a few characters
    text: str  # the mutated transcription

    @property
    def key(self) -> str:
        """A stable name of the mutant: line id, operator and a hash of the mutated text."""
        return f"{self.line_id}:{self.op}:{hashlib.sha256(self.text.encode()).hexdigest()[:10]}"


# -- running a check -----------------------------------------------------------------------------------------------
Verdict = tuple  # (holds_as_printed, corrected_holds) or ("raised", exception name)


def _claim_verdict(cid: str) -> Verdict:
    from paper_repro.util.registry import CLAIMS, check_overrides, load_all

    load_all()
    c = CLAIMS[cid]
    extra = {"claim_results": {}} if c.uses_results else {}
    out = c.func(**check_overrides(c, None), **extra)
    return (bool(out.passed), None)


def verdict(check_id: str) -> Verdict:
    """What check ``check_id`` says now: ``(holds_as_printed, corrected_holds)``, or ``("raised", name)``."""
    from paper_repro.claims.lines import load_checks

    try:
        if check_id.startswith("claim:"):
            return _claim_verdict(check_id.split(":", 1)[1])
        r = load_checks()[check_id]()
        return (r.holds_as_printed, r.corrected_holds)
    except Exception as exc:  # a check that cannot read a changed line refuses it
        return ("raised", type(exc).__name__)


def verdict_with(check_id: str, texts: dict[str, str]) -> Verdict:
    from paper_repro.printed.lines import substituted

    with substituted(texts):
        return verdict(check_id)


def check_ids(include_claims: bool = False) -> list[str]:
    """Every check named by a checked or erratum line (the ``claim:`` ones with ``include_claims``)."""
    from paper_repro.printed.lines import all_lines

    ids = {x.check for x in all_lines() if x.status != "excused"}
    return sorted(c for c in ids if include_claims or not c.startswith("claim:"))


def blank_test(checks: Iterable[str] | None = None, progress: Callable[[str], None] | None = None) -> list[dict]:
    """One record per check: its verdict, and its verdict with every line it belongs to blanked.  ``killed`` is
    False for a check that says the same of a blank line as of the paper's."""
    from paper_repro.printed.lines import lines_of

    out = []
    for cid in (check_ids() if checks is None else checks):
        ids = [x.id for x in lines_of(cid)]
        base = verdict(cid)
        blank = verdict_with(cid, dict.fromkeys(ids, BLANK))
        out.append({"check": cid, "lines": ids, "verdict": base, "blank": blank,
                    "killed": blank != base})
        if progress:
            progress(cid)
    return out


# -- the mutation operators ----------------------------------------------------------------------------------------
_SWAPS = (("u", "v"), ("v", "w"), ("u", "w"), ("x", "y"), ("i", "j"), ("R", "G"), ("G", "B"), ("r", "g"))
_WORDS = (("non-negative", "negative"), ("nonnegative", "negative"), ("independent", "dependent"),
          ("positive", "negative"), ("at least", "at most"), ("greater", "less"), ("vanish", "never vanish"),
          ("unique", "several"), ("symmetric", "antisymmetric"), ("first", "second"), ("second", "third"),
          ("third", "fourth"), ("order $n", "order $n+1"), ("two", "three"), ("three", "four"), ("six", "five"),
          ("\\rightarrow0", "\\rightarrow1"), ("\\to 0", "\\to 1"), ("\\to0", "\\to1"), ("\\pi", "2\\pi"),
          ("coincide", "differ"), ("convex", "concave"), ("interpolates", "misses"), ("lower", "upper"),
          ("boundary", "interior"), ("inner", "outer"), ("zero", "non-zero"), ("non-zero", "zero"))
_RELATIONS = ((r"(?<![\\<>!])=(?!=)", "\\neq "), (r"\\leq", "\\geq"), (r"\\geq", "\\leq"), (r"\\neq", "="),
              (r"(?<!\\)<", ">"), (r"(?<![\\-])>", "<"), (r"\\in(?![a-z])", "\\notin"),
              (r"\\subseteq", "\\supsetneq"), (r"\\sim(?![a-z])", "\\nsim"), (r"\\nsim", "\\sim"))
_QUANTIFIERS = ((r"\\forall", "\\exists"), (r"\\exists", "\\forall"), (r"\bfor all\b", "for some"),
                (r"\bfor some\b", "for all"), (r"\bany\b", "some"))


def _seed(line_id: str, op: str) -> random.Random:
    return random.Random(int(hashlib.sha256(f"{line_id}/{op}".encode()).hexdigest()[:12], 16))


def _pick(matches: list, line_id: str, op: str, most: int) -> list:
    """At most ``most`` of ``matches``, chosen by a generator seeded with the line and operator (deterministic)."""
    if len(matches) <= most:
        return matches
    return sorted(_seed(line_id, op).sample(matches, most), key=lambda m: m[0] if isinstance(m, tuple) else m.start())


def _sites(pattern: str, tex: str) -> list[re.Match]:
    return list(re.finditer(pattern, tex))


#: superscripts that name rather than bound: the paper's ^{\alpha} tags, a transpose, a prime
_TAGS = {"\\alpha", "T", "\\prime"}


def _bound_sites(tex: str) -> list[tuple[int, int, str]]:
    """Upper and lower bounds of index sets, sums and listed ranges: (start, end, replacement) with the bound moved
    by one."""
    out = []
    for m in re.finditer(r"([_^])\{([^{}]*)\}", tex):
        body = m.group(2)
        if m.group(1) == "_" and "=" not in body:
            continue  # a plain subscript (an index, not a bound) -- the constant and sign operators reach it
        if m.group(1) == "^" and body.strip() in _TAGS:
            continue  # a tag such as ^{\alpha} or ^{T}: a name, not a bound
        last = body.split(",")[-1]
        head = body[: len(body) - len(last)]
        if "=" in last:
            var, val = last.split("=", 1)
            moved = f"{var}={val.strip()}+1"
        else:
            moved = f"{last.strip()}-1" if last.strip() else ""
        if moved:
            out.append((m.start(2), m.end(2), head + moved))
    for m in re.finditer(r"\\ldots\s*,\s*([^,.\s$\\]+)", tex):
        out.append((m.start(1), m.end(1), m.group(1) + "-1"))
    return out


def _drop_sites(tex: str) -> list[tuple[int, int]]:
    """Spans ``+ term`` / ``- term`` at brace depth 0 up to the next such operator (a dropped term)."""
    depth, cuts = 0, []
    for k, ch in enumerate(tex):
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif ch in "+-" and depth == 0 and k > 0 and "-" not in (tex[k - 1], tex[k + 1:k + 2]):
            cuts.append(k)  # (not the dash of a range "--")
    spans = []
    for a, b in zip(cuts, cuts[1:] + [len(tex)]):
        seg = tex[a:b]
        stop = re.search(r"\\\\|&|=|,~", seg)
        end = a + (stop.start() if stop else len(seg))
        if end - a > 2:
            spans.append((a, end))
    return spans


def mutants(tex: str, line_id: str = "", most: int = 2) -> list[Mutant]:
    """The mutants of one transcription: each operator at up to ``most`` sites (chosen deterministically), texts
    that differ from ``tex`` only, each once."""
    out: list[Mutant] = []

    def add(op: str, where: str, text: str) -> None:
        if text != tex and all(text != m.text for m in out):
            out.append(Mutant(line_id, op, where, text))

    sites = _bound_sites(tex)
    for a, b, rep in (sites if len(sites) <= most else sorted(_seed(line_id, "bound").sample(sites, most))):
        add("bound", f"{tex[a:b]} -> {rep}", tex[:a] + rep + tex[b:])
    for m in _pick(_sites(r"(?<=[^{(\s=,^_\-])\s*[+-]\s*(?=[^\s}\-])", tex), line_id, "sign", most):
        flip = m.group().replace("+", "\0").replace("-", "+").replace("\0", "-")
        add("sign", f"{m.group().strip()} -> {flip.strip()}", tex[: m.start()] + flip + tex[m.end():])
    for m in _pick(_sites(r"(?<![\w\\{])\d+(?![\w])", tex), line_id, "constant", most):
        d = int(m.group())
        add("constant", f"{d} -> {d + 1}", tex[: m.start()] + str(d + 1) + tex[m.end():])
    swaps = [(a, b) for a, b in _SWAPS if re.search(rf"(?<![\\\w]){a}(?!\w)", tex)
             and re.search(rf"(?<![\\\w]){b}(?!\w)", tex)]
    for a, b in swaps[:most]:
        text = re.sub(rf"(?<![\\\w])({a}|{b})(?!\w)", lambda m, a=a, b=b: b if m.group() == a else a, tex)
        add("swap", f"{a} <-> {b}", text)
    for a, b in _pick(_drop_sites(tex), line_id, "drop", most):
        add("drop", tex[a:b][:24], tex[:a] + tex[b:])
    for pat, rep in _RELATIONS:
        for m in _pick(_sites(pat, tex), line_id, "relation", 1):
            add("relation", f"{m.group()} -> {rep.strip()}", tex[: m.start()] + rep + tex[m.end():])
    for pat, rep in _QUANTIFIERS:
        for m in _pick(_sites(pat, tex), line_id, "quantifier", 1):
            add("quantifier", f"{m.group()} -> {rep}", tex[: m.start()] + rep + tex[m.end():])
    for word, rep in _WORDS:
        m = re.search(r"(?<![\d\w])" + re.escape(word) if word[0] in "\\" else re.escape(word), tex)
        k = m.start() if m else -1  # (a macro such as \pi not after a digit: 2\pi -> 22\pi is no mutant)
        if k >= 0:
            add("word", f"{word} -> {rep}", tex[:k] + rep + tex[k + len(word):])
    return out


def mutation_test(checks: Iterable[str] | None = None, most: int = 2, include_claims: bool = False,
                  progress: Callable[[str], None] | None = None) -> list[dict]:
    """One record per mutant: line, check, operator, what changed, verdict, killed, and the reason of an
    equivalent mutant (:data:`~paper_repro.claims.lines.equivalents.EQUIVALENT`)."""
    from paper_repro.claims.lines.equivalents import EQUIVALENT
    from paper_repro.printed.lines import lines_of

    out = []
    for cid in (check_ids(include_claims) if checks is None else checks):
        base = verdict(cid)
        for ln in lines_of(cid):
            for m in mutants(ln.verbatim, ln.id, most):
                v = verdict_with(cid, {ln.id: m.text})
                out.append({"key": m.key, "line": ln.id, "check": cid, "op": m.op, "where": m.where,
                            "verdict": v, "base": base, "killed": v != base,
                            "equivalent": EQUIVALENT.get(m.key)})
        if progress:
            progress(cid)
    return out


def summary(records: list[dict]) -> dict:
    """Kill rate over the non-equivalent mutants, per operator and overall."""
    real = [r for r in records if not r["equivalent"]]
    by_op: dict[str, list[int]] = {}
    for r in real:
        k = by_op.setdefault(r["op"], [0, 0])
        k[0] += r["killed"]
        k[1] += 1
    killed = sum(r["killed"] for r in real)
    return {"mutants": len(records), "equivalent": len(records) - len(real), "counted": len(real),
            "killed": killed, "rate": (killed / len(real)) if real else 1.0,
            "by_op": {op: {"killed": a, "of": b} for op, (a, b) in sorted(by_op.items())}}


__all__ = ["BLANK", "Mutant", "verdict", "verdict_with", "check_ids", "blank_test", "mutants", "mutation_test",
           "summary"]
