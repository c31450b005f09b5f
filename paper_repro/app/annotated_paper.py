"""The paper, annotated: ``make paper`` -> ``paper/index.html``.

The paper's own text, rendered section by section from its LaTeX source (:data:`paper_index.PAPER`) as an
offline HTML page: formulas as MathML (``latex2mathml``; browsers render it natively, nothing is fetched),
theorem-like environments numbered as in the PDF, the regenerated figures where the paper has them, with
their captions.  Every display, every theorem-like statement and every figure carries a badge:

* **checked** -- the line-by-line index (``data/paper_lines.json``) says so; the badge links to the claim,
  test and figure that check it;
* **erratum** -- printed and corrected side by side, with severity and evidence (from the index, or, where
  the index does not yet cover it, from ``data/errata.json`` at the erratum's label);
* **excused** -- nothing to compute; the reason;
* **not yet checked** -- no entry of the index covers it (every display, while the index is absent).

Open questions link to their answers in ``docs/`` and the gallery.  The page is generated only where the
paper's source is beside the clone (the repository does not hold the paper's text); otherwise one sentence
says so and nothing is written.  Deterministic: reruns give identical bytes.
"""

from __future__ import annotations

import bisect
import html
import json
import re
import unicodedata
from dataclasses import dataclass, field
from pathlib import Path

from paper_repro.app.paper_index import PAPER, load_index
from paper_repro.app.report_link import report_link_html
from paper_repro.util.io import DATA, FIGURES, ROOT, write_text

OUT = ROOT / "paper" / "index.html"
LINES = DATA / "paper_lines.json"
STATUSES = ("checked", "erratum", "excused", "not yet checked")
DISPLAY_ENVS = ("equation", "equation*", "align", "align*", "gather", "gather*", "multline", "multline*",
                "eqnarray", "eqnarray*")
#: Where each open question is answered (labels of the source; the first question has none: key "Question 7.1").
ANSWERS = {
    "Question 7.1": [("docs/proof_of_closed_forms.md", "closed forms and positivity, proven for each n in range"),
                     ("figures/index.html#general-formulas", "formulas by level (gallery)"),
                     ("figures/index.html#questions", "where the question stands (gallery)")],
    "que:open_problem_basis_transformation": [("figures/index.html#questions", "where the question stands (gallery)")],
    "que:limiting_case": [("docs/limit_for_all_n.md", "answered for every n: the written proof"),
                          ("figures/index.html#questions", "where the question stands (gallery)")],
}
_ACCENT = {"'": "\u0301", "`": "\u0300", "^": "\u0302", '"': "\u0308", "~": "\u0303", "c": "\u0327", "H": "\u030b",
           "v": "\u030c", "u": "\u0306", "=": "\u0304", ".": "\u0307"}
_COLORS = {"Red": "#d00000", "Green": "#006600", "Blue": "#0000b3", "Orange": "#e69500"}


# --- the source --------------------------------------------------------------------------------------------
def strip_comments(text: str) -> str:
    """``%`` comments removed line by line (line numbers stay those of the source)."""
    return "\n".join(re.sub(r"(?<!\\)%.*", "", ln) for ln in text.split("\n"))


def balanced(text: str, start: int, open_: str = "{", close: str = "}") -> int:
    """Index just after the group opening at ``text[start] == open_``."""
    depth, k = 0, start
    while k < len(text):
        c = text[k]
        if c == "\\":
            k += 2
            continue
        if c == open_:
            depth += 1
        elif c == close:
            depth -= 1
            if depth == 0:
                return k + 1
        k += 1
    raise ValueError(f"unbalanced {open_} at offset {start}")


def _arg(text: str, k: int) -> tuple[str, int]:
    """The next argument at ``k`` (a braced group, or one token), skipping spaces; (content, end)."""
    while k < len(text) and text[k] in " \t\n":
        k += 1
    if k < len(text) and text[k] == "{":
        end = balanced(text, k)
        return text[k + 1:end - 1], end
    if k < len(text) and text[k] == "\\":
        m = re.match(r"\\([A-Za-z]+|.)", text[k:])
        return m.group(0), k + m.end()
    return text[k:k + 1], k + 1


# --- math ------------------------------------------------------------------------------------------------
def _colour_macros(tex: str) -> str:
    r"""``\Red{x}`` -> ``{\color{#d00000}{x}}``: the colour kept inside its own group (latex2mathml's ``\color``
    colours everything after it in the group, across rows of an alignment)."""
    out, k = [], 0
    for m in re.finditer(r"\\(Red|Green|Blue|Orange)\s*\{", tex):
        if m.start() < k:
            continue
        end = balanced(tex, m.end() - 1)
        out.append(tex[k:m.start()])
        out.append("{\\color{" + _COLORS[m.group(1)] + "}{" + _colour_macros(tex[m.end():end - 1]) + "}}")
        k = end
    out.append(tex[k:])
    return "".join(out)


def _hex(rgb: str) -> str:
    """'1.0, 0.6, 0.0' (xcolor's rgb model) -> '#ff9900'."""
    return "#" + "".join(f"{round(float(x) * 255):02x}" for x in rgb.split(","))


def prepare_math(tex: str) -> str:
    """The paper's math made digestible for latex2mathml (markup only; no symbol changes)."""
    tex = re.sub(r"\\color\[rgb\]\{([^}]*)\}(.*?)\\normalcolor",
                 lambda m: "{\\color{" + _hex(m.group(1)) + "}{" + m.group(2) + "}}", tex, flags=re.S)
    tex = re.sub(r"\\color\[rgb\]\{([^}]*)\}", lambda m: "\\color{" + _hex(m.group(1)) + "}", tex)
    tex = re.sub(r"\\label\{[^}]*\}|\\nonumber|\\notag|\\qedhere|\\allowbreak|\\normalcolor", "", tex)
    tex = re.sub(r"\\begin\{array\}\s*\[[tcb]\]", r"\\begin{array}", tex)
    tex = _colour_macros(tex)
    tex = tex.replace(r"\dfrac", r"\frac").replace(r"\dbinom", r"\binom").replace(r"\limits", "")
    tex = re.sub(r"\\overfrown\s*\{", r"\\overset{\\frown}{", tex)
    # \text and \operatorname stay: latex2mathml writes <mtext> with the spaces around words ("\text{ and }") and
    # <mo>mod</mo> with an operator's spacing; as \mathrm they lost both ("2(mod4)andz")
    tex = re.sub(r"\\(?:mathbf|boldsymbol)\s*\{", r"\\mathbf{", tex)
    tex = tex.replace(r"\vert", "|").replace(r"\ell", "l")
    tex = re.sub(r"(?<!\\)\\(?=\s|$)", r"\\;", tex)  # control space "\ " (latex2mathml prints the backslash)
    return tex.strip()


def mathml(tex: str, display: bool = False) -> str | None:
    """MathML of ``tex`` (None where latex2mathml fails)."""
    from latex2mathml.converter import convert

    try:
        return convert(prepare_math(tex), display="block" if display else "inline")
    except Exception:  # latex2mathml raises assorted exceptions on what it does not know
        return None


def math_or_source(tex: str, display: bool, stats: dict) -> str:
    out = mathml(tex, display)
    if out is None:
        stats["math_fallback"] += 1
        cls = "tex display" if display else "tex"
        return f'<code class="{cls}" title="LaTeX source (not converted)">{html.escape(tex.strip())}</code>'
    stats["math"] += 1
    return out


def split_rows(body: str) -> list[str]:
    """Rows of an align-like body at top-level ``\\\\`` (not inside braces or nested environments)."""
    rows, depth, env, k, last = [], 0, 0, 0, 0
    while k < len(body):
        if body.startswith("\\begin{", k):
            env += 1
        elif body.startswith("\\end{", k):
            env -= 1
        c = body[k]
        if c == "\\" and k + 1 < len(body) and body[k + 1] == "\\" and depth == 0 and env == 0:
            rows.append(body[last:k])
            k += 2
            last = k
            continue
        if c == "\\":
            k += 2
            continue
        depth += {"{": 1, "}": -1}.get(c, 0)
        k += 1
    rows.append(body[last:])
    return rows


def display_tex(env: str, body: str) -> tuple[str, int]:
    """(LaTeX for the converter, number of numbered rows) of one display environment."""
    if env in ("align", "gather", "multline", "eqnarray"):
        rows = [r for r in split_rows(body)]
        numbered = sum(1 for r in rows if r.strip() and not re.search(r"\\nonumber|\\notag", r))
    elif env == "equation":
        numbered = 0 if re.search(r"\\nonumber|\\notag", body) else 1
    else:
        numbered = 0
    if env.startswith("align"):
        return r"\begin{align*}" + body + r"\end{align*}", numbered  # latex2mathml's aligned ignores &
    if env.startswith("eqnarray"):
        return r"\begin{array}{rcl}" + body + r"\end{array}", numbered
    if env.startswith(("gather", "multline")):
        return r"\begin{gathered}" + body + r"\end{gathered}", numbered
    return body, numbered


# --- the model ---------------------------------------------------------------------------------------------
@dataclass
class Block:
    """A piece of the page with its source lines; ``kind`` display | statement | figure | text | heading."""
    kind: str
    first: int
    last: int
    anchor: str
    title: str = ""
    labels: list[str] = field(default_factory=list)
    entries: list[dict] = field(default_factory=list)
    errata: list[dict] = field(default_factory=list)
    #: entries of the index that cover lines of this block but stand at another block (where their badge is)
    covered: list[tuple[dict, Block]] = field(default_factory=list)


class Renderer:
    """LaTeX -> HTML of this paper's subset of LaTeX (elsarticle, amsmath, amsthm, graphicx)."""

    def __init__(self, source: str, index: list[dict], manifest: list[dict], claims: list[dict],
                 pmap: dict, lines: dict | None, errata: list[dict]):
        self.src = strip_comments(source)
        self.line_starts = [0] + [m.end() for m in re.finditer("\n", self.src)]
        self.index = {r["label"]: r for r in index}
        self.fig_of = {}
        for m in manifest:
            if m.get("paper_label"):
                self.fig_of.setdefault(m["paper_label"], []).append(m)
        self.claims = {c["id"]: c for c in claims}
        self.map = {r["label"]: r for r in pmap.get("labels", [])}
        self.lines = lines
        self.errata = errata
        self.blocks: list[Block] = []
        self.stats = {"math": 0, "math_fallback": 0}
        self.theorems: dict[str, str] = dict(re.findall(r"\\newtheorem\{(\w+)\}\{([^}]*)\}", self.src))
        self.counters = {"equation": 0, "figure": 0, "section": 0, "subsection": 0}
        self.thm: dict[str, int] = {}
        self.section = ""

    def line(self, offset: int) -> int:
        return bisect.bisect_right(self.line_starts, offset)

    # inline text ----------------------------------------------------------------------------------------
    def inline(self, s: str) -> str:
        out, k, n = [], 0, len(s)
        while k < n:
            c = s[k]
            if c == "$":
                dd = s.startswith("$$", k)
                end = s.find("$$" if dd else "$", k + (2 if dd else 1))
                while end > 0 and s[end - 1] == "\\":
                    end = s.find("$", end + 1)
                if end < 0:
                    out.append(html.escape(s[k:]))
                    break
                tex = s[k + (2 if dd else 1):end]
                out.append(math_or_source(tex, dd, self.stats))
                k = end + (2 if dd else 1)
                continue
            if c == "\\":
                m = re.match(r"\\([A-Za-z]+\*?|.)", s[k:])
                name, k = m.group(1), k + m.end()
                k = self.command(name, s, k, out)
                continue
            if c in "{}":
                k += 1
                continue
            if s.startswith("---", k):
                out.append("—")
                k += 3
                continue
            if s.startswith("--", k):
                out.append("–")
                k += 2
                continue
            if s.startswith("``", k) or s.startswith("''", k):
                out.append("“" if c == "`" else "”")
                k += 2
                continue
            out.append("\u00a0" if c == "~" else html.escape(c))
            k += 1
        return re.sub(r"[ \t]*\n[ \t]*", "\n", "".join(out))

    def command(self, name: str, s: str, k: int, out: list[str]) -> int:
        if name in _ACCENT and len(name) == 1 or name == "c":
            arg, k = _arg(s, k)
            arg = arg.lstrip("\\") if arg in ("\\i", "\\j") else arg
            out.append(unicodedata.normalize("NFC", arg[:1] + _ACCENT[name] + arg[1:]) if arg else "")
            return k
        if name in ("emph", "textit", "textbf", "textsc", "mathbf", "textrm", "mbox", "text"):
            arg, k = _arg(s, k)
            tag = {"emph": "em", "textit": "em", "textbf": "b", "mathbf": "b"}.get(name)
            inner = self.inline(arg)
            out.append(f"<{tag}>{inner}</{tag}>" if tag else inner)
            return k
        if name in _COLORS:
            arg, k = _arg(s, k)
            out.append(f'<span style="color:{_COLORS[name]}">{self.inline(arg)}</span>')
            return k
        if name in ("ref", "eqref"):
            arg, k = _arg(s, k)
            rec = self.index.get(arg, {})
            num = rec.get("number") or "?"
            out.append(f'<a class="ref" href="#{html.escape(arg)}">{html.escape(num)}</a>')
            return k
        if name == "cite":
            arg, k = _arg(s, k)
            out.append("[" + ", ".join(html.escape(a.strip()) for a in arg.split(",")) + "]")
            return k
        if name == "footnote":
            arg, k = _arg(s, k)
            out.append(f'<span class="fn">(Footnote: {self.inline(arg)})</span>')
            return k
        if name == "label":
            arg, k = _arg(s, k)
            out.append(f'<span id="{html.escape(arg)}"></span>')
            return k
        if name in ("url", "href"):
            arg, k = _arg(s, k)
            out.append(html.escape(arg))
            return k
        if name == "\\":
            out.append("<br>")
            return k
        if name in (",", " ", ";", "quad", "qquad"):
            out.append(" ")
            return k
        if name in ("%", "&", "#", "_", "$", "{", "}"):
            out.append(html.escape(name))
            return k
        if name in ("ldots", "dots"):
            out.append("…")
            return k
        if name in ("corref", "ead", "thanks", "cortext", "tnoteref", "fnref", "hypersetup"):
            _, k = _arg(s, k)
            return k
        if name in ("setcounter",):
            _, k = _arg(s, k)
            _, k = _arg(s, k)
            return k
        return k  # formatting commands without visible text (\noindent, \center, \smallskip, ...)

    # blocks ---------------------------------------------------------------------------------------------
    def add(self, kind: str, start: int, end: int, anchor: str, title: str = "", labels=()) -> Block:
        b = Block(kind, self.line(start), self.line(max(start, end - 1)), anchor, title, list(labels))
        self.blocks.append(b)
        return b

    def render(self) -> str:
        s = self.src
        body_start = s.index("\\begin{document}") + len("\\begin{document}")
        body_end = s.index("\\end{document}")
        s = re.sub(r"\\makeatletter.*?\\makeatother", lambda m: re.sub(r"[^\n]", " ", m.group(0)), s, flags=re.S)
        self.src = s
        return self.flow(body_start, body_end)

    _BLOCK = re.compile(r"\\begin\{(\w+\*?)\}|\\end\{(\w+\*?)\}|\\\[|\\(section|subsection)(\*?)\s*\{|\\item\b|"
                        r"\n[ \t]*\n")

    def flow(self, start: int, end: int) -> str:
        s, out, para, k = self.src, [], [], start
        open_env: list[str] = []

        def flush(upto: int) -> None:
            nonlocal para
            text = "".join(para)
            para = []
            if text.strip():
                first = upto - len(text)
                b = self.add("text", first + (len(text) - len(text.lstrip())), upto, f"p{len(self.blocks)}")
                out.append(f'<p id="{b.anchor}" data-tex="{b.first}-{b.last}">{self.inline(text).strip()}'
                           f"{{BADGES:{len(self.blocks) - 1}}}</p>")

        while k < end:
            m = self._BLOCK.search(s, k, end)
            if not m:
                para.append(s[k:end])
                k = end
                break
            para.append(s[k:m.start()])
            tok = m.group(0)
            if tok.strip() == "":
                flush(m.start())
                k = m.end()
                continue
            flush(m.start())
            if m.group(1):
                env = m.group(1)
                k = self.begin(env, m, out, open_env)
            elif m.group(2):
                env = m.group(2)
                if open_env and open_env[-1] == env:
                    open_env.pop()
                    out.append(self.close(env))
                k = m.end()
            elif tok == "\\[":
                stop = s.index("\\]", m.end())
                out.append(self.display("displaymath", s[m.end():stop], m.start(), stop + 2))
                k = stop + 2
            elif m.group(3):
                close = balanced(s, m.end() - 1)
                raw = s[m.end():close - 1]
                out.append(self.heading(m.group(3), bool(m.group(4)), raw, m.start(), close))
                k = close
            else:  # \item
                if open_env and open_env[-1] in ("itemize", "enumerate"):
                    out.append("</li><li>")
                k = m.end()
        flush(k)
        return "\n".join(o.replace("<li></li>", "") for o in out)

    def begin(self, env: str, m: re.Match, out: list[str], open_env: list[str]) -> int:
        s = self.src
        if env in DISPLAY_ENVS:
            stop = s.index(f"\\end{{{env}}}", m.end())
            out.append(self.display(env, s[m.end():stop], m.start(), stop + len(env) + 6))
            return stop + len(env) + 6
        if env == "figure":
            stop = s.index("\\end{figure}", m.end())
            out.append(self.figure(s[m.end():stop], m.start(), stop + 12))
            return stop + 12
        if env == "frontmatter":
            stop = s.index("\\end{frontmatter}", m.end())
            out.append(self.frontmatter(s[m.end():stop], m.end()))
            return stop + len("\\end{frontmatter}")
        k = m.end()
        if env in self.theorems or env == "proof":
            opt = ""
            rest = s[k:]
            mo = re.match(r"\s*\[", rest)
            if mo and env != "proof":
                close = balanced(s, k + mo.end() - 1, "[", "]")
                opt, k = s[k + mo.end():close - 1], close
            labels = []
            ml = re.match(r"\s*\\label\{([^}]*)\}", s[k:])
            if ml:
                labels = [ml.group(1)]
            stop = self._env_end(env, k)
            open_env.append(env)
            if env == "proof":
                return self._open_proof(out, k)
            self.thm[env] = self.thm.get(env, 0) + 1
            num = f"{self.counters['section']}.{self.thm[env]}"
            name = f"{self.theorems[env]} {num}"
            anchor = labels[0] if labels else f"{env}-{num}"
            b = self.add("statement", m.start(), stop, anchor, name, labels)
            opt_html = f" ({self.inline(opt)})" if opt else ""
            answers = ""
            if env == "question":
                key = labels[0] if labels else name
                answers = "".join(f'<li><a href="../{html.escape(href)}">{html.escape(text)}</a></li>'
                                  for href, text in ANSWERS.get(key, []))
                answers = f'<div class="answers">Answers: <ul>{answers}</ul></div>' if answers else ""
            out.append(f'<div class="stmt {env}" id="{html.escape(anchor)}" data-tex="{b.first}-{b.last}">'
                       f'<div class="stmt-head"><b>{html.escape(name)}</b>{opt_html}'
                       f"{{BADGES:{len(self.blocks) - 1}}}</div>{answers}")
            return k
        if env in ("itemize", "enumerate"):
            open_env.append(env)
            out.append("<ul><li>" if env == "itemize" else "<ol><li>")
            return k
        if env == "abstract":
            open_env.append(env)
            out.append('<div class="abstract"><b>Abstract.</b> ')
            return k
        return k  # center, document-level wrappers: nothing to draw

    def _env_end(self, env: str, k: int) -> int:
        depth, pat = 1, re.compile(rf"\\(begin|end)\{{{re.escape(env)}\}}")
        for m in pat.finditer(self.src, k):
            depth += 1 if m.group(1) == "begin" else -1
            if depth == 0:
                return m.end()
        return len(self.src)

    def _open_proof(self, out: list[str], k: int) -> int:
        out.append('<div class="proof"><i>Proof.</i> ')
        return k

    def close(self, env: str) -> str:
        if env == "proof":
            return " ∎</div>"
        if env in self.theorems:
            return "</div>"
        if env in ("itemize", "enumerate"):
            return "</li></ul>" if env == "itemize" else "</li></ol>"
        if env == "abstract":
            return "</div>"
        return ""

    def heading(self, level: str, star: bool, raw: str, start: int, end: int) -> str:
        labels = re.findall(r"\\label\{([^}]*)\}", raw)
        title = self.inline(re.sub(r"\\label\{[^}]*\}", "", raw)).strip()
        if star:
            num = ""
        elif level == "section":
            self.counters["section"] += 1
            self.counters["subsection"] = 0
            self.thm.clear()
            num = str(self.counters["section"])
        else:
            self.counters["subsection"] += 1
            num = f"{self.counters['section']}.{self.counters['subsection']}"
        anchor = labels[0] if labels else f"sec-{num or len(self.blocks)}"
        self.section = num
        b = self.add("heading", start, end, anchor, f"{num} {title}".strip(), labels)
        tag = "h2" if level == "section" else "h3"
        return (f'<{tag} id="{html.escape(anchor)}" data-tex="{b.first}-{b.last}">{html.escape(num)} {title}'
                f"</{tag}>{{BADGES:{len(self.blocks) - 1}}}")

    def display(self, env: str, body: str, start: int, end: int) -> str:
        labels = re.findall(r"\\label\{([^}]*)\}", body)
        if env == "displaymath":
            tex, numbered = body, 0
        else:
            tex, numbered = display_tex(env, body)
        nums = []
        for _ in range(numbered):
            self.counters["equation"] += 1
            nums.append(f"({self.counters['equation']})")
        anchor = labels[0] if labels else f"d{len(self.blocks)}"
        b = self.add("display", start, end, anchor, ", ".join(nums), labels)
        extra = "".join(f'<span id="{html.escape(lab)}"></span>' for lab in labels[1:])
        numtxt = f'<span class="eqno">{html.escape(", ".join(nums))}</span>' if nums else ""
        return (f'<div class="display" id="{html.escape(anchor)}" data-tex="{b.first}-{b.last}">{extra}'
                f'<div class="math">{math_or_source(tex, True, self.stats)}</div>{numtxt}'
                f"{{BADGES:{len(self.blocks) - 1}}}</div>")

    def figure(self, body: str, start: int, end: int) -> str:
        self.counters["figure"] += 1
        num = self.counters["figure"]
        labels = re.findall(r"\\label\{([^}]*)\}", body)
        mc = re.search(r"\\caption\s*\{", body)
        caption = body[mc.end():balanced(body, mc.end() - 1) - 1] if mc else ""
        anchor = labels[0] if labels else f"fig-{num}"
        b = self.add("figure", start, end, anchor, f"Fig. {num}", labels)
        imgs, notes = [], []
        for f in self.fig_of.get(anchor, []):
            for o in f["outputs"]:
                name = Path(o).name
                imgs.append(f'<a href="../figures/{html.escape(Path(name).with_suffix(".svg").name)}">'
                            f'<img src="../figures/{html.escape(name)}" alt="Fig. {num}: regenerated ({f["id"]})">'
                            "</a>")
            from paper_repro.app.gallery import math_html

            notes.append(f'<div class="regen">Regenerated by figure <a href="../figures/index.html#{f["id"]}">'
                         f'<code>{html.escape(f["id"])}</code></a> of the gallery: {math_html(f["caption"])}</div>')
        if not imgs:
            imgs.append('<div class="noimg">The paper\'s figure is not regenerated by this project.</div>')
        return (f'<figure id="{html.escape(anchor)}" data-tex="{b.first}-{b.last}">{"".join(imgs)}'
                f"<figcaption><b>Fig. {num}.</b> {self.inline(caption)}{''.join(notes)}"
                f"{{BADGES:{len(self.blocks) - 1}}}</figcaption></figure>")

    def frontmatter(self, body: str, offset: int) -> str:
        title = re.search(r"\\title\s*\{", body)
        t = self.inline(body[title.end():balanced(body, title.end() - 1) - 1]) if title else ""
        authors = []
        for ma in re.finditer(r"\\author(?:\[[^]]*\])?\{", body):
            authors.append(self.inline(body[ma.end():balanced(body, ma.end() - 1) - 1]))
        authors = [re.sub(r"\s+", " ", a).strip() for a in authors]
        ab = re.search(r"\\begin\{abstract\}(.*?)\\end\{abstract\}", body, re.S)
        kw = re.search(r"\\begin\{keyword\}(.*?)\\end\{keyword\}", body, re.S)
        parts = [f"<h1>{t}</h1>", f'<p class="authors">{", ".join(authors)}</p>']
        if ab:
            b = self.add("text", offset + ab.start(1), offset + ab.end(1), "abstract")
            parts.append(f'<div class="abstract" id="abstract" data-tex="{b.first}-{b.last}"><b>Abstract.</b> '
                         f"{self.inline(ab.group(1)).strip()}{{BADGES:{len(self.blocks) - 1}}}</div>")
        if kw:
            parts.append(f'<p class="keywords"><b>Keywords:</b> {self.inline(kw.group(1)).strip()}</p>')
        parts.append("<!--TOC-->")
        return "\n".join(parts)


# --- badges ------------------------------------------------------------------------------------------------
def place_entries(blocks: list[Block], entries: list[dict]) -> list[dict]:
    """Attach each entry of the line index to the block that holds its source lines: a display first, then a
    figure, a theorem-like statement, a paragraph, a heading.  Returns the entries no block holds."""
    order = {"display": 0, "figure": 1, "statement": 2, "text": 3, "heading": 4}
    unplaced = []
    for e in entries:
        a, b = e["tex"]
        hits = [bl for bl in blocks if bl.first <= b and a <= bl.last]
        if not hits:
            unplaced.append(e)
            continue
        best = min(hits, key=lambda bl: (order[bl.kind], bl.last - bl.first))
        best.entries.append(e)
        for bl in hits:  # a display, statement or figure whose lines the entry also covers points to its badge
            if bl is not best and bl.kind in ("display", "statement", "figure"):
                bl.covered.append((e, best))
    return unplaced


def _same_erratum(a: dict, b: dict) -> bool:
    text = ("printed", "corrected")
    return a.get("id") == b.get("id") or [a.get(k) for k in text] == [b.get(k) for k in text]


def held_errata(entries: list[dict], errata: list[dict]) -> dict[str, dict]:
    """For each erratum of ``data/errata.json`` that an entry of the line index holds (the same id, or the same
    printed and corrected text), that entry."""
    held = {}
    for er in errata:
        hit = next((e for e in entries if e.get("status") == "erratum" and _same_erratum(e.get("erratum") or {}, er)),
                   None)
        if hit is not None:
            held[er["id"]] = hit
    return held


def place_errata(blocks: list[Block], errata: list[dict], entries: list[dict]) -> list[dict]:
    """Errata of ``data/errata.json`` the line index does not already hold, at the block carrying their label.

    An erratum is held when an index entry has the same erratum (same id, or the same printed and corrected text):
    its badge then names the erratum's id (before, a label match hid ``torus-b_{4,3,1}-x`` from the page and showed
    five errata twice, at their label and at their line)."""
    held = held_errata(entries, errata)
    unplaced = []
    for er in errata:
        if er["id"] in held:
            continue
        hit = next((b for b in blocks if er["paper_ref"] in b.labels), None)
        if hit is None:
            unplaced.append(er)
        else:
            hit.errata.append(er)
    return unplaced


def _rich(text: str | None) -> str:
    """A field of the index: LaTeX-looking text as MathML where it converts, otherwise label-aware text."""
    from paper_repro.app.gallery import math_html

    if not text:
        return ""
    if "\\" in text and "$" not in text:
        m = mathml(text, False)
        if m:
            return m
    return math_html(text)


class Linker:
    """Links of a badge: claims and figures to the gallery, tests to their file, code to the package."""

    def __init__(self, claims: dict, figures: set[str], pmap: dict):
        self.claims, self.figures, self.pmap = claims, figures, pmap

    def claim(self, cid: str) -> str:
        c = self.claims.get(cid, {})
        st = c.get("status", "not run")
        return (f'<a href="../figures/index.html#claim-{html.escape(cid)}"><code>{html.escape(cid)}</code></a> '
                f'<span class="{html.escape(st)}">({html.escape(c.get("kind", "?"))}, {html.escape(st)})</span>')

    def test(self, cid: str) -> str:
        return (f'<a href="../tests/test_all_claims_slow.py"><code>test_claim_passes[{html.escape(cid)}]</code></a>')

    def figure(self, fid: str) -> str:
        return f'<a href="../figures/index.html#{html.escape(fid)}"><code>{html.escape(fid)}</code></a>'

    def code(self, path: str) -> str:
        short = f'<code>{html.escape(path.removeprefix("paper_repro/"))}</code>'
        return f'<a href="../{html.escape(path)}">{short}</a>' if (ROOT / path).exists() else short

    def words(self, text: str) -> str:
        """Free text with claim ids, figure ids and test/code paths turned into links."""
        out, last = [], 0
        for m in re.finditer(r"(?:tests|paper_repro|docs)/[\w/.-]+(?:::[\w\[\]\-.,]+)?|[A-Za-z][\w-]*", text):
            w = m.group(0)
            link = None
            if w in self.claims:
                link = self.claim(w)
            elif w in self.figures:
                link = self.figure(w)
            elif "/" in w and (ROOT / w.split("::")[0]).exists():
                link = f'<a href="../{html.escape(w.split("::")[0])}"><code>{html.escape(w)}</code></a>'
            if link:
                out.append(html.escape(text[last:m.start()]) + link)
                last = m.end()
        out.append(html.escape(text[last:]))
        return "".join(out)

    def label_context(self, labels: list[str]) -> str:
        """What the paper map knows of these labels: claims, figures, code naming them."""
        parts = []
        for lab in labels:
            r = self.pmap.get(lab)
            if not r:
                continue
            bits = [", ".join(self.claim(c) for c in r["claims"])] if r["claims"] else []
            bits += [", ".join(self.figure(f) for f in r["figures"])] if r["figures"] else []
            bits += ["code " + ", ".join(self.code(c) for c in r["code"][:4])] if r["code"] else []
            if bits:
                parts.append(f"<code>{html.escape(lab)}</code>: " + "; ".join(bits))
        return "<br>".join(parts)


#: What a line's ``proof_kind`` means (data/paper_lines.json; :mod:`paper_repro.claims.lines`).
KIND_MEANING = {
    "proof": "settles everything the line states",
    "exhaustive": "exact and complete for the range named in 'how' only; the line states more (every n)",
    "exact-evidence": "exact arithmetic at sampled parameters",
    "numeric-evidence": "floating-point or high-precision values at sampled parameters",
}


_HEAD = {"checked": "✓ checked", "erratum": "✗ erratum", "excused": "○ excused"}
_CLS = {"checked": "ok", "erratum": "err", "excused": "exc"}


def _where(block: Block) -> str:
    """How a block is named in a pointer to it: its number, or its kind and source lines."""
    if block.kind == "display":
        return f"display {block.title}" if block.title else f"the display at lines {block.first}–{block.last}"
    if block.title:
        return block.title
    return {"text": "the paragraph", "heading": "the heading"}.get(block.kind, block.kind) + \
        f" at lines {block.first}–{block.last}"


def covered_badge(block: Block) -> str:
    """The badge of a block whose lines the index covers with entries that stand at other blocks (a statement whose
    displays are checked, a display inside a checked paragraph): the worst of their statuses, not counted again,
    with a link to each entry's badge."""
    seen, targets, rows = [], [], []
    for e, at in block.covered:
        if e["id"] in seen:
            continue
        seen.append(e["id"])
        link = f'<a href="#{html.escape(at.anchor)}">{html.escape(_where(at))}</a>'
        if link not in targets:
            targets.append(link)
        rows.append(f'<div>{html.escape(e.get("status", ""))}: lines {e["tex"][0]}–{e["tex"][1]}, entry '
                    f"<code>{html.escape(str(e['id']))}</code>, badge at {link}</div>")
    statuses = [e.get("status") for e, _ in block.covered]
    st = next(s for s in ("erratum", "checked", "excused") if s in statuses)
    what = {"erratum": "holds an erratum", "checked": "checked", "excused": "excused"}[st]
    return (f'<details class="badge {_CLS[st]} covered" data-covered="{html.escape(st)}"><summary>'
            f"{_HEAD[st][0]} {what}, see the badge{'s' if len(targets) > 1 else ''} of {', '.join(targets)}"
            f"</summary>{''.join(rows)}</details>")


def badge_html(block: Block, linker: Linker, errata_ids: dict[str, list[str]] | None = None) -> str:
    errata_ids = errata_ids or {}
    items = []
    for e in block.entries:
        st = e.get("status", "not yet checked")
        cls = {"checked": "ok", "erratum": "err", "excused": "exc"}.get(st, "none")
        says = html.escape((e.get("says") or "")[:140])
        head = {"checked": "✓ checked", "erratum": "✗ erratum", "excused": "○ excused"}.get(st, "? not yet checked")
        rows = [f"<div><b>{html.escape(e.get('number') or '')}</b> lines {e['tex'][0]}–{e['tex'][1]}"
                f" ({html.escape(e.get('kind') or '')}, id <code>{html.escape(str(e.get('id')))}</code>)</div>"]
        if e.get("says"):
            rows.append(f"<div>says: {_rich(e['says'])}</div>")
        if st == "erratum" and e.get("erratum"):
            er = e["erratum"]
            rows.append(_pair(er.get("printed"), er.get("corrected"), er.get("severity"), er.get("evidence")))
            for eid in errata_ids.get(str(e.get("id")), []):
                rows.append(f'<div>erratum <code>{html.escape(eid)}</code> of <a href="../figures/index.html#errata">'
                            "data/errata.json</a></div>")
        if st == "excused" and e.get("reason"):
            rows.append(f"<div>reason: {html.escape(e['reason'])}</div>")
        for key in ("check", "how", "proof_kind"):
            if e.get(key):
                meaning = KIND_MEANING.get(str(e[key]), "") if key == "proof_kind" else ""
                rows.append(f"<div>{key.replace('_', ' ')}: {linker.words(str(e[key]))}"
                            f"{' (' + html.escape(meaning) + ')' if meaning else ''}</div>")
        for key, what in (("holds_as_printed", "as printed"), ("corrected_holds", "as corrected")):
            if e.get(key) is not None:
                rows.append(f"<div>{what}: {'holds' if e[key] else 'fails'}</div>")
        checks = [w for w in re.findall(r"[A-Za-z][\w-]*", str(e.get("check") or "")) if w in linker.claims]
        if checks:
            rows.append("<div>test: " + ", ".join(linker.test(c) for c in dict.fromkeys(checks)) + "</div>")
        if e.get("near"):
            ctx = linker.label_context([e["near"]])
            if ctx:
                rows.append(f"<div>paper map: {ctx}</div>")
        items.append(f'<details class="badge {cls}" data-status="{html.escape(st)}"><summary>{head}'
                     f'{": " + says if says else ""}</summary>{"".join(rows)}</details>')
    for er in block.errata:
        items.append(f'<details class="badge err" data-status="erratum"><summary>✗ erratum '
                     f"<code>{html.escape(er['id'])}</code> ({html.escape(er['severity'])})</summary>"
                     f"{_pair(er['printed'], er['corrected'], er['severity'], er['evidence'])}"
                     f'<div>from <a href="../figures/index.html#errata">data/errata.json</a> (label '
                     f"<code>{html.escape(er['paper_ref'])}</code>)</div></details>")
    if not items and block.covered:
        items.append(covered_badge(block))
    if not items and block.kind in ("display", "statement", "figure"):
        ctx = linker.label_context(block.labels)
        body = (f"<div>No entry of the line-by-line index covers lines {block.first}–{block.last}.</div>"
                + (f"<div>The paper map relates its label to: {ctx}</div>" if ctx else ""))
        items.append(f'<details class="badge none" data-status="not yet checked"><summary>? not yet checked'
                     f"</summary>{body}</details>")
    return f'<div class="badges">{"".join(items)}</div>' if items else ""


def _pair(printed, corrected, severity, evidence) -> str:
    from paper_repro.app.gallery import evidence_html

    return (f'<table class="pair"><tr><th>printed</th><th>corrected</th></tr><tr><td>{_rich(printed)}</td>'
            f"<td>{_rich(corrected)}</td></tr></table><div>severity: <b>{html.escape(str(severity or ''))}</b>; "
            f"evidence: {evidence_html(str(evidence or ''))}</div>")


CSS = """
body{font-family:Georgia,serif;max-width:1100px;margin:1.5em auto;padding:0 1em;color:#222;line-height:1.5}
h1{font-size:1.6em}h2{margin-top:2em;border-bottom:1px solid #ccc}
.display{position:relative;margin:0.8em 0;padding:0.3em 4.2em 0.3em 0.5em;border-left:3px solid #ddd}
.display .eqno{position:absolute;right:0.3em;top:0.4em;color:#333}
.math{overflow-x:auto;overflow-y:hidden;padding:0.25em 0}math{font-size:1.05em}
code.tex{white-space:pre-wrap;background:#f6f6f6;display:inline-block}
.stmt{margin:1em 0;padding:0.4em 0.8em;background:#fafaf5;border-left:3px solid #cc9}
.proof{margin:0.6em 0 1em 0;padding-left:0.8em;border-left:2px dotted #ccc}
figure{margin:1.5em 0;padding:0.6em;border:1px solid #ddd}figure img{max-width:100%;height:auto}
figcaption{font-size:93%}.regen{margin-top:0.3em;color:#444}
.badges{margin:0.2em 0;font-family:sans-serif;font-size:82%;line-height:1.35}
.badge{display:block;margin:2px 0;border-radius:4px;padding:1px 6px;max-width:100%}
.badge summary{cursor:pointer}.badge>div{margin:2px 0 2px 1em}
.badge.ok{background:#e6f4e6;border:1px solid #8c8}.badge.err{background:#fde8e8;border:1px solid #d88}
.badge.exc{background:#eef0f8;border:1px solid #99b}.badge.none{background:#f4f4f4;border:1px solid #bbb;color:#555}
table.pair{border-collapse:collapse;margin:3px 0 3px 1em;display:block;overflow-x:auto;max-width:calc(100% - 1em)}
table.pair td,table.pair th{border:1px solid #caa;padding:2px 6px;vertical-align:top;overflow-x:auto}
.pass{color:#060}.fail{color:#b00}.summary td,.summary th{border:1px solid #ccc;padding:2px 8px}
.summary{border-collapse:collapse}.fn{font-size:90%;color:#555}.answers{font-family:sans-serif;font-size:90%}
.authors{font-style:italic}.abstract{margin:1em 0;padding:0.5em;background:#f7f7f7}
nav.toc{font-family:sans-serif;font-size:90%;columns:2}
"""


#: Displays wider than their box are set in a smaller size until they fit (down to 55 %), as a PDF viewer scales a
#: page: MathML has no line breaking, and the rows of an alignment are already broken where the source has ``\\``.
#: Run at load and on resize; ``check_paper`` measures every display box afterwards.
FIT_JS = """
function fitDisplays(){document.querySelectorAll('.display .math').forEach(function(m){
  var math=m.querySelector('math'); if(!math) return; math.style.fontSize='';
  var base=parseFloat(getComputedStyle(math).fontSize), size=base;
  while(m.scrollWidth>m.clientWidth+1 && size>0.55*base){size-=0.02*base; math.style.fontSize=size+'px';}
  m.dataset.scale=(size/base).toFixed(2);});}
window.addEventListener('load',fitDisplays);window.addEventListener('resize',fitDisplays);
"""


def unique_ids(body: str) -> str:
    """Every element id once: a ``\\label`` inside a statement or display whose element already carries that label
    as its id left an empty ``<span id=...>`` behind -- dropped; any other repeated id gets ``-2``, ``-3``, ...

    >>> unique_ids('<div id="a"><span id="a"></span><p id="b"></p><p id="b"></p></div>')
    '<div id="a"><p id="b"></p><p id="b-2"></p></div>'
    """
    seen: dict[str, int] = {}

    def one(m: re.Match) -> str:
        ident = html.unescape(m.group(2))
        if ident not in seen:
            seen[ident] = 1
            return m.group(0)
        if m.group(3) is not None:  # an empty anchor span: the id is already on the page
            return ""
        seen[ident] += 1
        return f'{m.group(1)}id="{html.escape(f"{ident}-{seen[ident]}")}"{m.group(4) or ""}'

    return re.sub(r'(<\w+\b[^>]*?\s)id="([^"]*)"(?:(></span>)|([^>]*>))', one, body)


def build(source: str, index: list[dict], manifest: list[dict], claims: list[dict], pmap: dict,
          lines: dict | None, errata: list[dict]) -> tuple[str, dict]:
    """(the page, a summary: badges by status, unplaced entries and errata, math conversion counts)."""
    r = Renderer(source, index, manifest, claims, pmap, lines, errata)
    body = r.render()
    entries = (lines or {}).get("lines", [])
    unplaced = place_entries(r.blocks, entries)
    loose = place_errata(r.blocks, errata, entries)
    linker = Linker(r.claims, {m["id"] for m in manifest}, r.map)
    errata_ids: dict[str, list[str]] = {}
    for eid, entry in held_errata(entries, errata).items():
        errata_ids.setdefault(str(entry["id"]), []).append(eid)
    counts = dict.fromkeys(STATUSES, 0)
    for k, b in enumerate(r.blocks):
        placeholder = f"{{BADGES:{k}}}"
        badges = badge_html(b, linker, errata_ids)
        if placeholder not in body:
            raise RuntimeError(f"block {b.kind} at lines {b.first}-{b.last} has no place for its badges")
        for st in re.findall(r'data-status="([^"]+)"', badges):  # one tally: the badges on the page
            counts[st] = counts.get(st, 0) + 1
        body = body.replace(placeholder, badges, 1)
    body = unique_ids(body)
    displays = sum(1 for b in r.blocks if b.kind == "display")
    toc = "".join(f'<li><a href="#{html.escape(b.anchor)}">{b.title}</a></li>' for b in r.blocks
                  if b.kind == "heading")
    if lines:
        cov = lines.get("coverage", {})
        source_note = (f"Badges from <code>data/paper_lines.json</code>, the line-by-line index of "
                       f"{cov.get('lines', len(entries))} entries: one badge per entry, {counts['checked']} checked, "
                       f"{counts['erratum']} errata, {counts['excused']} excused (the table below); a display or "
                       "statement whose lines an entry at another place covers points to that badge.")
    else:
        source_note = ("<code>data/paper_lines.json</code> (the line-by-line index) is not present yet: every display "
                       "is marked <i>not yet checked</i>; the errata of <code>data/errata.json</code> are shown at "
                       "their labels, and each badge lists what the paper map relates to the label.")
    summary = (f'<table class="summary" data-counts="{html.escape(json.dumps(counts))}"><tr><th>badges</th>'
               f'{"".join(f"<th>{s}</th>" for s in STATUSES)}</tr>'
               f'<tr><td>count</td>{"".join(f"<td>{counts.get(s, 0)}</td>" for s in STATUSES)}</tr></table>')
    extra = ""
    if unplaced or loose:
        extra = ('<h2 id="unplaced">Index entries and errata without a place in the text</h2><ul>'
                 + "".join(f"<li>entry <code>{html.escape(str(e.get('id')))}</code> lines {e['tex']}</li>"
                           for e in unplaced)
                 + "".join(f"<li>erratum <code>{html.escape(e['id'])}</code> at "
                           f"<code>{html.escape(e['paper_ref'])}</code></li>" for e in loose) + "</ul>")
    page = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
            '<meta name="viewport" content="width=device-width, initial-scale=1">',
            "<title>The paper, annotated — paper_repro</title>", f"<style>{CSS}</style></head><body>",
            '<div class="intro" style="font-family:sans-serif;font-size:90%;background:#eef5fb;padding:0.6em 1em">'
            "<b>The paper, annotated.</b> The text of arXiv:1309.4747 rendered from its LaTeX source by "
            "<code>make paper</code> (<code>paper_repro/app/annotated_paper.py</code>); formulas as MathML. "
            "Each display, statement and figure carries a badge: <span class=\"badge ok\" style=\"display:inline\">"
            "✓ checked</span> <span class=\"badge err\" style=\"display:inline\">✗ erratum</span> "
            "<span class=\"badge exc\" style=\"display:inline\">○ excused</span> "
            "<span class=\"badge none\" style=\"display:inline\">? not yet checked</span> (click to open). "
            f"{source_note} Gallery: <a href=\"../figures/index.html\">figures/index.html</a>; "
            f"{report_link_html('../')}.{summary}"
            f"<p>{displays} displays; {r.stats['math']} formulas as MathML, {r.stats['math_fallback']} shown as "
            "LaTeX source (the converter failed on them).</p></div>",
            body.replace("<!--TOC-->", f'<nav class="toc"><b>Contents</b><ul>{toc}</ul></nav>', 1), extra,
            f"<script>{FIT_JS}</script>", "</body></html>\n"]
    info = {"badges": counts, "displays": displays, "unplaced_entries": len(unplaced), "unplaced_errata": len(loose),
            **r.stats}
    return "\n".join(page), info


def _load(path: Path, default):
    return json.loads(path.read_text(encoding="utf-8")) if path.exists() else default


def paper_line(where, info: dict) -> str:
    """What ``make paper`` says: one sentence, not the raw summary dict.

    >>> print(paper_line("paper/index.html", {"badges": {"checked": 3, "erratum": 1, "excused": 2,
    ...       "not yet checked": 0}, "displays": 5, "math": 9, "math_fallback": 0, "unplaced_entries": 0,
    ...       "unplaced_errata": 0}))  # doctest: +NORMALIZE_WHITESPACE
    paper: paper/index.html written: 5 displays, 9 formulas as MathML; badges 3 checked, 1 erratum, 2 excused,
    0 not yet checked.
    """
    b = info["badges"]
    text = (f"paper: {where} written: {info['displays']} displays, {info['math']} formulas as MathML"
            + (f" ({info['math_fallback']} shown as LaTeX source)" if info["math_fallback"] else "")
            + f"; badges {b['checked']} checked, {b['erratum']} errat{'um' if b['erratum'] == 1 else 'a'}, "
            f"{b['excused']} excused, {b['not yet checked']} not yet checked")
    lost = info["unplaced_entries"] + info["unplaced_errata"]
    return text + (f"; {lost} index entries or errata without a place (listed at the end)." if lost else ".")


def write_paper(source_path: Path = PAPER, out: Path = OUT, lines_path: Path = LINES) -> dict | None:
    """Write ``paper/index.html``; None (and one sentence) where the paper's source is absent."""
    if not source_path.exists():
        print(f"paper: the LaTeX source {source_path} is not beside this clone; the annotated paper is not built.")
        return None
    page, info = build(source_path.read_text(encoding="utf-8"), load_index(), _load(FIGURES / "manifest.json", []),
                       _load(DATA / "claims.json", []), _load(DATA / "paper_map.json", {}), _load(lines_path, None),
                       _load(DATA / "errata.json", []))
    write_text(out, page)
    print(paper_line(out.relative_to(ROOT) if out.is_relative_to(ROOT) else out, info))
    return info


if __name__ == "__main__":
    write_paper()
