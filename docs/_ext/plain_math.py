"""Sphinx extension: the plain-text mathematics of the proof pages rendered as MathJax.

The pages of ``docs/`` that carry the project's proofs (``question1_for_all_n.md``, ``limit_for_all_n.md``, and
any page added later) are written in plain text with TeX-like indices: ``R_{2n,2n−i,j}``, ``T_{2n}^α``,
``s^{2n+j} r_{2n,2n−i,j} = [t^j X^i] F_n(t, X)``.  Before MyST parses a page, this finds the runs of such
mathematics in its prose and wraps them in ``$...$`` (``dollarmath``), translated to TeX (``α`` -> ``\\alpha``,
``≤`` -> ``\\le``, ``sin`` -> ``\\sin``, set braces -> ``\\{ \\}``); an indented display line (two or three spaces
after a blank line) becomes display math, its words set as text and a trailing ``(U)`` as its tag.  Code spans,
fenced blocks, existing ``$...$``, headings, links and HTML are left alone, so a page may also be written in
``$...$`` directly.  ``tests/test_docs.py`` builds the site and checks that no proof page shows ``_{`` or ``^``
outside math.

A page opts out with the line ``<!-- plain-math: off -->``.
"""

from __future__ import annotations

import re

GREEK = {
    "α": r"\alpha", "β": r"\beta", "γ": r"\gamma", "δ": r"\delta", "ε": r"\varepsilon", "ζ": r"\zeta",
    "η": r"\eta", "θ": r"\theta", "ι": r"\iota", "κ": r"\kappa", "λ": r"\lambda", "μ": r"\mu", "ν": r"\nu",
    "ξ": r"\xi", "π": r"\pi", "ρ": r"\rho", "σ": r"\sigma", "τ": r"\tau", "υ": r"\upsilon", "φ": r"\varphi",
    "χ": r"\chi", "ψ": r"\psi", "ω": r"\omega", "Γ": r"\Gamma", "Δ": r"\Delta", "Θ": r"\Theta",
    "Λ": r"\Lambda", "Ξ": r"\Xi", "Π": r"\Pi", "Σ": r"\sum", "Φ": r"\Phi", "Ψ": r"\Psi", "Ω": r"\Omega",
}
SYMBOLS = {
    "−": "-", "·": r"\cdot ", "×": r"\times ", "≤": r"\le ", "≥": r"\ge ", "≠": r"\ne ", "→": r"\to ",
    "←": r"\leftarrow ", "↦": r"\mapsto ", "⇒": r"\Rightarrow ", "⇔": r"\Leftrightarrow ", "∈": r"\in ",
    "∉": r"\notin ", "⊂": r"\subset ", "⊆": r"\subseteq ", "∪": r"\cup ", "∩": r"\cap ", "∞": r"\infty ",
    "∘": r"\circ ", "≡": r"\equiv ", "≈": r"\approx ", "∼": r"\sim ", "∂": r"\partial ", "√": r"\sqrt ",
    "±": r"\pm ", "∓": r"\mp ", "…": r"\dots ", "⋯": r"\cdots ", "∑": r"\sum ", "∏": r"\prod ",
    "ℕ": r"\mathbb{N}", "ℤ": r"\mathbb{Z}", "ℚ": r"\mathbb{Q}", "ℝ": r"\mathbb{R}", "ℂ": r"\mathbb{C}",
    "𝒱": r"\mathcal{V}", "𝐞": r"\mathbf{e}", "𝐫": r"\mathbf{r}", "𝐩": r"\mathbf{p}", "𝐬": r"\mathbf{s}",
    "′": "'", "″": "''", "⟨": r"\langle ", "⟩": r"\rangle ", "‖": r"\| ", "⌊": r"\lfloor ", "⌋": r"\rfloor ",
    "⌈": r"\lceil ", "⌉": r"\rceil ", "∀": r"\forall ", "∃": r"\exists ", "ℓ": r"\ell ", "∅": r"\emptyset ",
    "<": "<", ">": ">",
}
SUPERSCRIPTS = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻ⁿ", "0123456789+-n", strict=True))
SUBSCRIPTS = dict(zip("₀₁₂₃₄₅₆₇₈₉₊₋", "0123456789+-", strict=True))
#: Combining accents written after a letter (T̄, π̂, p̃): TeX's accent on that letter.
ACCENTS = {"\u0304": r"\bar", "\u0305": r"\bar", "\u0302": r"\hat", "\u0303": r"\tilde"}
#: Words that are mathematics: TeX's operators, and the names this project's pages use as functions.
OPERATORS = {"sin": r"\sin", "cos": r"\cos", "tan": r"\tan", "exp": r"\exp", "log": r"\log", "ln": r"\ln",
             "min": r"\min", "max": r"\max", "det": r"\det", "dim": r"\dim", "deg": r"\deg", "gcd": r"\gcd",
             "arctan": r"\arctan", "mod": r"\bmod", "lim": r"\lim", "pi": r"\pi", "sup": r"\sup", "inf": r"\inf"}
NAMED = {"atan", "binom", "multinomial", "span", "rank", "sign", "diag", "ord", "lcm", "sgn"}
#: Short lowercase words of English that are never a product of one-letter variables.
ENGLISH = {"a", "i", "an", "as", "at", "be", "by", "do", "if", "in", "is", "it", "no", "of", "on", "or", "so", "to",
           "up", "we", "and", "are", "but", "can", "for", "has", "its", "let", "not", "now", "one", "our", "the",
           "two", "use", "was", "all", "any", "see", "set", "six", "ten", "yes", "how", "why", "who", "get", "per",
           "via", "new", "old", "few", "own", "out", "off", "too", "say", "put", "try", "run", "etc", "eq", "eqs",
           "iff", "also", "each", "else", "from", "into", "only", "that", "then", "thus", "this", "when", "with",
           "non", "sum", "row", "mid", "lie", "end", "top", "th", "net", "tie", "way", "sec", "que",
           "pip", "nor", "ge", "far", "def", "bar", "api", "act", "fix", "map", "ii", "iii", "iv", "vi", "md", "py",
           "re", "im", "had", "may", "did", "his", "her", "she", "him", "yet", "ago", "due", "key", "low", "add",
           "big", "odd", "sub", "max", "min", "ok", "vs", "ie", "eg", "cf", "us", "my", "me", "he", "go", "am",
           "dps", "lu", "qr", "log", "pdf", "doc", "src", "tex", "csv", "css", "js", "url", "www", "com", "org"}
TRIGGERS = set("_^=≤≥<>→≡∈∉≠∑∏Σ∘·×±∓⊂⊆∪∩∞↦⇒′″+−/!") | set(GREEK) | set(SUPERSCRIPTS) | set(SUBSCRIPTS) | set(
    "ℕℤℚℝℂ𝒱𝐞𝐫𝐩𝐬ℓ∂√") | set(ACCENTS)
LETTER = r"A-Za-z" + "".join(GREEK) + "ℓ𝒱𝐞𝐫𝐩𝐬ℕℤℚℝℂ"
MARK = "[" + "".join(ACCENTS) + "]?"
BASE = rf"[{LETTER}]{MARK}(?:[′″']*)"
GROUP = r"\{(?:[^{}]|\{(?:[^{}]|\{[^{}]*\})*\})*\}"
SCRIPT = rf"[_^](?:{GROUP}|[−-]?[0-9]+|[{LETTER}0-9]{MARK}[′″']*)"
TOKEN = re.compile(
    rf"(?P<word>[A-Za-z]{{2,}}(?:{SCRIPT})*)"  # a word: an operator, a named function, a product or English
    rf"|(?P<atom>{BASE}(?:{SCRIPT}|[′″'])*)"
    rf"|(?P<script>(?:{SCRIPT})+)"  # an index after a bracket: (1 + X²)^n
    r"|(?P<num>[0-9]+(?:\.[0-9]+)?)"
    r"|(?P<dots>\.\.\.)"  # a full stop ends a formula; three are an ellipsis
    r"|(?P<op>[-−+=≤≥<>→←↦⇒⇔≡≈∼∈∉⊂⊆∪∩∞∘·×±∓…⋯∑∏∂√/()\[\]{},:!|⟨⟩‖⌊⌋⌈⌉∀∃∅ \u00a0"
    + "".join(SUPERSCRIPTS) + "".join(SUBSCRIPTS) + r"])"
)
PROTECT = re.compile(r"(`+)(?:(?!\1).)+?\1|\$\$.*?\$\$|\$[^$\n]+\$|\]\([^)]*\)|</?[A-Za-z][A-Za-z0-9-]*(?:\s[^<>\n]*)?/?>|<!--.*?-->|https?://\S+|\{[a-z]+\}`[^`]*`")


def _to_tex(text: str) -> str:
    """The TeX of a run of plain-text mathematics."""
    out, braces, k = [], [], 0
    while k < len(text):
        ch = text[k]
        word = re.match(r"[A-Za-z]{2,}", text[k:]) if (k == 0 or not text[k - 1].isalpha()) else None
        if word:
            w = word.group(0)
            if w in OPERATORS:
                out.append(OPERATORS[w] + (" " if k + len(w) < len(text) and text[k + len(w)].isalpha() else ""))
            elif w in NAMED:
                out.append(rf"\operatorname{{{w}}}")
            else:
                out.append(w)
            k += len(w)
            continue
        if ch == "{":
            grouping = k > 0 and text[k - 1] in "_^"
            braces.append(grouping)
            out.append("{" if grouping else r"\{")
        elif ch == "}":
            out.append("}" if (braces.pop() if braces else False) else r"\}")
        elif k + 1 < len(text) and text[k + 1] in ACCENTS:  # T̄ -> \bar{T}, π̂ -> \hat{\pi}
            out.append(ACCENTS[text[k + 1]] + "{" + GREEK.get(ch, SYMBOLS.get(ch, ch)).strip() + "}")
            k += 2
            continue
        elif ch in GREEK:
            nxt = text[k + 1] if k + 1 < len(text) else ""
            out.append(GREEK[ch] + (" " if nxt.isalnum() else ""))
        elif ch in SYMBOLS:
            out.append(SYMBOLS[ch])
        elif ch in SUPERSCRIPTS:
            run = re.match(f"[{''.join(SUPERSCRIPTS)}]+", text[k:]).group(0)
            out.append("^{" + "".join(SUPERSCRIPTS[c] for c in run) + "}")
            k += len(run)
            continue
        elif ch in SUBSCRIPTS:
            run = re.match(f"[{''.join(SUBSCRIPTS)}]+", text[k:]).group(0)
            out.append("_{" + "".join(SUBSCRIPTS[c] for c in run) + "}")
            k += len(run)
            continue
        elif ch == "\u00a0":
            out.append(" ")
        elif ch in "#%&":
            out.append("\\" + ch)
        else:
            out.append(ch)
        k += 1
    return "".join(out).replace(r"\cdot  ", r"\cdot ").strip()


def _is_math_word(word: str) -> bool:
    """An operator (sin), a named function (binom) or a product of one-letter variables (ct, cX, xyz)."""
    base = re.match(r"[A-Za-z]+", word).group(0)
    if base in OPERATORS or base in NAMED:
        return True
    return (len(base) <= 3 and base.lower() not in ENGLISH and not re.fullmatch(r"[A-Z][a-z]+|[A-Z]{2,}", base))


def _unmatched(text: str) -> int | None:
    """Position of the first bracket of ``text`` without its partner, or None."""
    pairs = {")": "(", "]": "[", "}": "{"}
    stack: list[tuple[str, int]] = []
    for k, ch in enumerate(text):
        if ch in "([{":
            stack.append((ch, k))
        elif ch in pairs:
            if not stack or stack[-1][0] != pairs[ch]:
                return k
            stack.pop()
    return stack[0][1] if stack else None


def _useful(core: str) -> bool:
    if re.fullmatch(r"[A-Za-z]+", core):
        return False
    call = re.search(r"\b([a-z]+)\(", core)
    return bool(any(c in TRIGGERS for c in core) and re.search(rf"[{LETTER}]", core)
                or re.search(r"[0-9)][_^]", core)  # a power or index of a number: 10^8
                or call and (call.group(1) in OPERATORS or call.group(1) in NAMED))


def _split_math(piece: str) -> list[tuple[bool, str]]:
    """A stretch of mathematical tokens as (is mathematics, text) pieces: punctuation and lone English letters at
    the ends stay text, and an unmatched bracket splits it (each side is tried on its own)."""
    lead = re.match(r"^(?:[\s,.;:!]|[aAI](?=\s))*", piece).group(0)  # a leading "!" is not a factorial
    rest = piece[len(lead):]
    tail = re.search(r"(?:[\s,.;:]|(?<=\s)[aAI])*$", rest).group(0)
    core = rest[:len(rest) - len(tail)]
    if not core:
        return [(False, piece)]
    k = _unmatched(core)
    if k is not None:
        return [(False, lead), *_split_math(core[:k]), (False, core[k]), *_split_math(core[k + 1:]), (False, tail)]
    return [(False, lead), (_useful(core), core), (False, tail)]


def _math_runs(text: str, table: bool = False) -> list[tuple[bool, str]]:
    """``text`` split into (is mathematics, piece)."""
    pieces: list[tuple[bool, str]] = []
    pos, run = 0, None  # run: (start, end) of the current stretch of mathematical tokens

    def close():
        nonlocal run
        if run is not None:
            pieces.append((True, text[run[0]:run[1]]))
            if run[1] < pos:
                pieces.append((False, text[run[1]:pos]))
            run = None

    for m in TOKEN.finditer(text):
        if m.start() > pos:  # characters no token takes: text
            close()
            pieces.append((False, text[pos:m.start()]))
            pos = m.start()
        kind, tok = m.lastgroup, m.group(0)
        mathy = not (kind == "word" and not _is_math_word(tok) or table and tok == "|"
                     or kind == "atom" and m.end() < len(text) and text[m.end()] in "_*`\\")
        if mathy:
            run = (run[0] if run else m.start(), m.end())
        else:
            close()
            pieces.append((False, tok))
        pos = m.end()
    close()
    if pos < len(text):
        pieces.append((False, text[pos:]))
    out: list[tuple[bool, str]] = []
    for is_math, piece in pieces:
        out += _split_math(piece) if is_math else [(False, piece)]
    merged: list[tuple[bool, str]] = []
    for is_math, piece in out:
        if piece and merged and merged[-1][0] == is_math:
            merged[-1] = (is_math, merged[-1][1] + piece)
        elif piece:
            merged.append((is_math, piece))
    return merged


def convert_inline(line: str, table: bool = False) -> str:
    """``line`` with its plain-text mathematics as ``$...$``."""
    out, pos = [], 0
    for m in PROTECT.finditer(line):
        out.append(_convert_text(line[pos:m.start()], table))
        out.append(m.group(0))
        pos = m.end()
    out.append(_convert_text(line[pos:], table))
    return "".join(out)


def _convert_text(text: str, table: bool) -> str:
    return "".join(f"${_to_tex(p)}$" if is_math else p for is_math, p in _math_runs(text, table))


def convert_display(line: str) -> str | None:
    """An indented display line as ``$$...$$`` (its words as text, a trailing ``(X)`` as its tag), or None when
    the line is more prose than mathematics."""
    body = line.strip()
    tag = None
    m = re.search(r"\s{3,}\(([A-Z0-9][A-Za-z0-9′']*)\)\s*$", body)
    if m:
        body, tag = body[:m.start()].rstrip(), m.group(1)
    if "`" in body or "$" in body or "*" in body:
        return None
    pieces = _math_runs(body)
    words = sum(len(p.split()) for is_math, p in pieces if not is_math and re.search("[A-Za-z]", p))
    math = sum(len(p) for is_math, p in pieces if is_math)
    if not math or words > 6 or math < 0.5 * len(body):
        return None
    tex = []
    for is_math, p in pieces:
        tex.append(_to_tex(p) if is_math else (r"\text{" + p.replace("\\", "") + "}" if p.strip() else r"\quad "))
    text = "".join(tex)
    text = re.sub(r"\\text\{(\s+)([^}]*?)(\s+)\}", r"\\quad\\text{\2}\\quad ", text)
    return "$$" + text.strip() + (rf" \tag{{{tag}}}" if tag else "") + "$$"


def convert(source: str) -> str:
    """Every plain-text formula of a Markdown page as MathJax math (see the module's docstring)."""
    if "<!-- plain-math: off -->" in source:
        return source
    lines = source.split("\n")
    out: list[str] = []
    fence = None
    prev_blank, in_list = True, False
    for line in lines:
        stripped = line.lstrip()
        if fence:
            out.append(line)
            if stripped.startswith(fence):
                fence = None
            prev_blank = False
            continue
        m = re.match(r"(`{3,}|~{3,})", stripped)
        if m:
            fence = m.group(1)
            out.append(line)
            continue
        if not stripped:
            out.append(line)
            prev_blank = True
            continue
        indent = len(line) - len(stripped)
        if indent == 0:
            in_list = bool(re.match(r"([*+-]|\d+\.)\s", stripped))
        display_indent = 4 <= indent <= 6 if in_list else 2 <= indent <= 3  # (in a list item: one level deeper)
        if stripped.startswith(("#", "<", "$$", ":::")) or indent >= 4 and prev_blank and not in_list:
            out.append(line)
        elif display_indent and (prev_blank or out and out[-1].startswith("$$")):
            display = convert_display(line)
            if display:
                out.append(display)
                prev_blank = False
                continue
            out.append(convert_inline(line))
        else:
            out.append(convert_inline(line, table=stripped.startswith("|") and stripped.rstrip().endswith("|")))
        prev_blank = False
    return "\n".join(out)


def _source_read(app, docname: str, source: list[str]) -> None:
    if app.env.doc2path(docname).suffix == ".md" and "/" not in docname and docname != "index":
        source[0] = convert(source[0])


def setup(app):
    app.connect("source-read", _source_read)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
