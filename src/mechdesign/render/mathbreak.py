"""Long display formulas of the report's Markdown broken over lines, for the PDF and Word.

Every ``$$ … $$`` display formula of ``report.md`` passes through :func:`break_display_math`
before pandoc converts the Markdown (to typst for the PDF, to Word): a formula whose
estimated width (:func:`tex_width`, in em of the body text) exceeds the budget is set as
``\\begin{aligned} … \\end{aligned}`` with its continuation lines aligned at the first
top-level relation (``=``, ``\\le``, ``\\Rightarrow`` …), broken at top-level relations and
list separators (``,\\quad``) first and at top-level ``+ − \\times`` only inside a piece that
is itself too wide. Nothing inside braces, ``\\left … \\right`` or an environment is broken.
The estimate is deliberately generous; the PDF template still scales a block equation that
does not fit (templates/report.typ), so a wrong estimate never puts ink past the margin.

Budget: the PDF's text block is 453.5 pt = 41 em of 11 pt; the equation number "(44)" and
its gap take about 3 em on each side of a centred formula, leaving ~35 em. Word sets the
formula in the middle 80 % of the text width (templates/docx-numbering.lua) in Cambria
Math, wider than New Computer Modern: :data:`BUDGET_EM` = 30 em serves both.
"""
from __future__ import annotations

import re

#: Widest formula line (estimated em) set on one line.
BUDGET_EM = 30.0

#: A relation piece narrower than this (em) is kept with the next one.
GLUE_EM = 4.0

_RELATIONS = {"=", "<", ">", r"\le", r"\ge", r"\leq", r"\geq", r"\approx", r"\ne", r"\neq",
              r"\Rightarrow", r"\Leftarrow", r"\Leftrightarrow", r"\to", r"\equiv",
              r"\approxeq", r"\sim", r"\simeq"}
_BINARY = {"+", "-", r"\times", r"\cdot", r"\pm", r"\mp"}
_SPACES = {r"\,": 0.17, r"\:": 0.22, r"\;": 0.28, r"\ ": 0.33, r"\!": -0.17,
           r"\quad": 1.0, r"\qquad": 2.0, "~": 0.33}
_ONE_ARG = {r"\text", r"\mathrm", r"\mathbf", r"\mathit", r"\mathsf", r"\operatorname",
            r"\bar", r"\overline", r"\hat", r"\widehat", r"\dot", r"\ddot", r"\vec",
            r"\tilde", r"\widetilde", r"\underline", r"\boldsymbol", r"\mathbb", r"\mathcal"}
_ZERO = {r"\left", r"\right", r"\big", r"\Big", r"\bigg", r"\Bigg", r"\displaystyle",
         r"\limits", r"\nolimits"}

_TOKEN = re.compile(r"\\[A-Za-z]+\*?|\\.|[{}]|\s+|.", re.DOTALL)
_DISPLAY = re.compile(r"\$\$(.+?)\$\$", re.DOTALL)


def _tokens(tex: str) -> list[str]:
    return _TOKEN.findall(tex)


def _group(tokens: list[str], i: int) -> tuple[list[str], int]:
    """The argument starting at tokens[i] (a braced group or one token) and the index after it."""
    while i < len(tokens) and tokens[i].isspace():
        i += 1
    if i >= len(tokens):
        return [], i
    if tokens[i] != "{":
        return [tokens[i]], i + 1
    depth, j = 0, i
    while j < len(tokens):
        if tokens[j] == "{":
            depth += 1
        elif tokens[j] == "}":
            depth -= 1
            if depth == 0:
                return tokens[i + 1:j], j + 1
        j += 1
    return tokens[i + 1:], len(tokens)


def _char_width(ch: str) -> float:
    if "\u2e80" <= ch <= "\u9fff" or "\uff00" <= ch <= "\uffef" or "\u3000" <= ch <= "\u303f":
        return 1.0
    if ch in "=<>":
        return 1.4          # relation with its spaces
    if ch in "+-":
        return 1.2          # binary operator with its spaces
    if ch in "()[]|.,;:'°!/":
        return 0.4
    if ch.isupper():
        return 0.75
    return 0.55


def _width(tokens: list[str], scale: float = 1.0) -> float:
    w, i = 0.0, 0
    while i < len(tokens):
        t = tokens[i]
        i += 1
        if t.isspace() or t in ("{", "}", "&"):
            continue
        if t in ("^", "_"):
            arg, i = _group(tokens, i)
            w += 0.72 * _width(arg, scale)
            continue
        if t == r"\frac" or t == r"\dfrac" or t == r"\tfrac":
            num, i = _group(tokens, i)
            den, i = _group(tokens, i)
            w += max(_width(num, scale), _width(den, scale)) + 0.3 * scale
            continue
        if t == r"\sqrt":
            while i < len(tokens) and tokens[i].isspace():
                i += 1
            if i < len(tokens) and tokens[i] == "[":
                j = tokens.index("]", i) if "]" in tokens[i:] else i
                i = j + 1
            arg, i = _group(tokens, i)
            w += _width(arg, scale) + 1.0 * scale
            continue
        if t in _ONE_ARG:
            arg, i = _group(tokens, i)
            if t in (r"\text", r"\operatorname", r"\mathrm"):
                w += sum(_char_width(c) if not c.isspace() else 0.33 for c in "".join(arg)) * scale
            else:
                w += _width(arg, scale)
            continue
        if t in _SPACES:
            w += _SPACES[t] * scale
        elif t in _ZERO:
            continue
        elif t in _RELATIONS:
            w += (1.4 if t.startswith("\\") and len(t) < 5 else 1.9) * scale
        elif t in _BINARY:
            w += 1.2 * scale
        elif t.startswith("\\") and len(t) > 2:
            # Greek letters and symbols one glyph; \sin, \max … their letters
            w += (0.6 if t[1:] not in ("sin", "cos", "tan", "max", "min", "ln", "log", "exp",
                                        "arccos", "arcsin", "arctan", "lim", "det")
                  else 0.5 * (len(t) - 1) + 0.2) * scale
        elif t.startswith("\\"):
            w += 0.4 * scale
        else:
            w += _char_width(t) * scale
    return w


def tex_width(tex: str) -> float:
    """Estimated width (em of the body font) of a display formula given as TeX."""
    return _width(_tokens(tex))


def _pieces(tokens: list[str]) -> list[tuple[str, list[str]]]:
    """Split at top-level break points: [(kind, tokens)], kind of the break that starts the
    piece: "" (the first), "rel" (a relation), "sep" (after ``,\\quad``/``\\qquad``)."""
    out: list[tuple[str, list[str]]] = [("", [])]
    depth, i = 0, 0
    while i < len(tokens):
        t = tokens[i]
        if t == "{" or t == r"\left" or t == r"\begin":
            depth += 1
        elif t == "}" or t == r"\end":
            depth -= 1
        elif t == r"\right":
            depth -= 1
        if depth == 0 and t in _RELATIONS:
            out.append(("rel", [t]))
        elif depth == 0 and t in (r"\quad", r"\qquad") and _is_sep(tokens, i):
            out.append(("sep", []))
        else:
            out[-1][1].append(t)
        i += 1
    return [(k, p) for k, p in out if k or "".join(p).strip()]


def _is_sep(tokens: list[str], i: int) -> bool:
    """``\\quad`` after a comma (or a ``\\qquad``) separates two formulas of one display."""
    if tokens[i] == r"\qquad":
        return True
    j = i - 1
    while j >= 0 and (tokens[j].isspace() or tokens[j] in (r"\,", r"\ ")):
        j -= 1
    return j >= 0 and tokens[j] in (",", ";")


def _binary_split(tokens: list[str], budget: float) -> list[list[str]]:
    """A piece too wide for one line broken before top-level ``+ − \\times``."""
    parts: list[list[str]] = [[]]
    depth = 0
    paren = 0       # open ( and [ : never broken inside (clamped at 0 for intervals like [0, 1))
    for k, t in enumerate(tokens):
        if t in ("{", r"\left", r"\begin"):
            depth += 1
        elif t in ("}", r"\right", r"\end"):
            depth -= 1
        elif depth == 0 and t in ("(", "["):
            paren += 1
        elif depth == 0 and t in (")", "]"):
            paren = max(0, paren - 1)
        prev = "".join(tokens[:k]).strip()
        if depth == 0 and paren == 0 and t in _BINARY and prev \
                and not prev.endswith(("(", "[", "^", "_", "=")):
            parts.append([t])
        else:
            parts[-1].append(t)
    lines: list[list[str]] = []
    for part in parts:
        if lines and _width(lines[-1] + part) <= budget:
            lines[-1] += part
        else:
            lines.append(list(part))
    return lines


def break_formula(tex: str, budget: float = BUDGET_EM) -> str:
    """``tex`` unchanged if it fits ``budget`` em, else an ``aligned`` environment of lines
    that each fit where possible (a piece without a top-level break point stays whole).
    Each formula of a list (``a = …,\\quad b = …``) starts a line of its own, aligned at
    its first relation; a relation piece shorter than :data:`GLUE_EM` stays with the next
    one (``⇒ ψ = 28°``, ``> [σ] = 100 MPa`` are never split)."""
    if tex_width(tex) <= budget or r"\begin" in tex or r"\\" in tex or "&" in tex:
        return tex
    pieces = _pieces(_tokens(tex))
    # formulas of the display: [lhs tokens, [relation pieces]]
    formulas: list[list] = []
    for kind, toks in pieces:
        if kind == "rel" and formulas:
            rels = formulas[-1][1]
            if rels and _width(rels[-1]) < GLUE_EM:
                rels[-1] = rels[-1] + toks
            else:
                rels.append(list(toks))
        else:
            formulas.append([list(toks), []])
    rows: list[str] = []
    for lhs, rels in formulas:
        lhs_text = "".join(lhs).strip()
        lhs_w = _width(lhs)
        if not rels:
            rows.append("& " + lhs_text)
            continue
        if lhs_w + _width(rels[0]) > budget:
            left = _left_rows(lhs, rels, budget)
            widest = max(_width(_tokens(r.replace("&", ""))) for r in left)
            if widest <= budget or widest < 0.8 * (lhs_w + sum(_width(r) for r in rels)):
                rows.extend(left)
                continue
        lines: list[list[list[str]]] = []       # lines of pieces
        cur: list[list[str]] = []
        for piece in rels:
            w = _width(piece)
            if cur and lhs_w + _width(_flat(cur)) + w > budget:
                lines.append(cur)
                cur = []
            if lhs_w + w > budget and len(piece) > 1:
                # a piece wider than a line: break it before its top-level operators
                head, rest = piece[:1], piece[1:]
                sub = _binary_split(rest, budget - lhs_w - _width(head) - 1.0)
                cur.append(head + [" "] + sub[0])
                for part in sub[1:]:
                    lines.append(cur)
                    cur = [[r"\quad "] + part]
                continue
            cur.append(piece)
        if cur:
            lines.append(cur)
        _no_lone_result(lines, lhs_w, budget)
        for n, line in enumerate(lines):
            rows.append((lhs_text + " &" if n == 0 else "&") + " " + "".join(_flat(line)).strip())
    if len(rows) < 2:
        return tex
    return "\\begin{aligned} " + " \\\\ ".join(rows) + " \\end{aligned}"


def _left_rows(lhs: list[str], rels: list[list[str]], budget: float) -> list[str]:
    """Rows of a formula whose left side and first relation do not fit one line: aligned
    at the left, the left side first (broken before its top-level + − × when it alone is
    too wide), then the relations on lines indented by a quad. (Aligning the relations
    after a wide left side would keep every line as wide as the left side plus its
    relation: the continuation lines start where the left side ends.)"""
    indent = _SPACES.get(r"\quad", 1.0)
    rows: list[str] = []
    parts = _binary_split(lhs, budget) if _width(lhs) > budget else [lhs]
    for n, part in enumerate(parts[:-1] if len(parts) > 1 else parts):
        rows.append(("& " if n == 0 else "& \\quad ") + "".join(part).strip())
    # the left side's last line (when it was broken) takes the relations that fit after it
    # lines of pieces, each with its indent: the relation lines may pass a piece down
    # (see _no_lone_result), the lines of a piece broken at its operators may not
    lines: list[list[list[str]]] = []
    indents: list[str] = []
    cur: list[list[str]] = [list(parts[-1])] if len(parts) > 1 else []
    for piece in rels:
        if cur and indent + _width(_flat(cur)) + _width(piece) > budget:
            lines.append(cur)
            indents.append("& \\quad ")
            cur = []
        if indent + _width(piece) > budget and len(piece) > 1:
            head, rest = piece[:1], piece[1:]
            sub = _binary_split(rest, budget - indent - _width(head) - 1.0)
            lines.append([head + [" "] + sub[0]])
            indents.append("& \\quad ")
            for part in sub[1:]:
                lines.append([part])
                indents.append("& \\qquad ")
            continue
        cur.append(piece)
    if cur:
        lines.append(cur)
        indents.append("& \\quad ")
        _no_lone_result(lines, indent, budget)
    rows.extend(ind + "".join(_flat(line)).strip() for ind, line in zip(indents, lines) if line)
    return rows


def _flat(pieces: list[list[str]]) -> list[str]:
    return [t for p in pieces for t in p]


def _one_term(piece: list[str]) -> bool:
    """A relation piece whose right side is one term: no top-level + − × · after its sign."""
    depth, seen = 0, False
    for t in piece[1:]:
        if t in ("{", r"\left", r"\begin"):
            depth += 1
        elif t in ("}", r"\right", r"\end"):
            depth -= 1
        elif t.isspace() or t in _SPACES:
            continue
        elif depth == 0 and t in _BINARY and seen:
            return False
        seen = True
    return True


#: A bare result joins the line before it when the two stay below this share of the budget
#: (the budget keeps ~5 em in reserve: 30 of the 35 em the PDF leaves a numbered formula).
SLACK = 1.12


def _no_lone_result(lines: list[list[list[str]]], lead: float, budget: float) -> None:
    """A last line that is one short relation piece (``= 12.3 N·m``) takes
    the last piece of the line before it, so that the result follows at least one term
    (a teacher's rule: the result is never left alone on a line). When the line before is a
    single piece that cannot be broken (a root, a fraction), the result joins that line if
    both fit :data:`SLACK` × ``budget`` em after ``lead`` em (the left side or the indent)."""
    if len(lines) < 2 or len(lines[-1]) != 1:
        return
    last = lines[-1][0]
    if not last or last[0] not in _RELATIONS or not _one_term(last):
        return
    if len(lines[-2]) >= 2:
        lines[-1].insert(0, lines[-2].pop())
    elif lead + _width(_flat(lines[-2]) + last) <= SLACK * budget:
        # the line before is one piece that cannot be broken: the result joins it
        lines[-2].append(lines.pop()[0])


def break_display_math(markdown: str, budget: float = BUDGET_EM) -> str:
    """Every ``$$ … $$`` formula of ``markdown`` passed through :func:`break_formula`."""
    def one(m: re.Match) -> str:
        inner = m.group(1)
        broken = break_formula(inner.strip(), budget)
        return m.group(0) if broken == inner.strip() else f"$$ {broken} $$"
    return _DISPLAY.sub(one, markdown)


__all__ = ["BUDGET_EM", "break_display_math", "break_formula", "tex_width"]
