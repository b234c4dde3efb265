"""Line breaks of the title page's title and subtitle (PDF and Word).

A title longer than the text block is set in lines of about equal width, broken only where
a reader would pause: between words in English (never at a hyphen: "lock-beam" stays
whole, never after "the"/"a"), at a phrase boundary in Chinese (after 、，；：的 and 与,
before 与、及、和 and an opening bracket; never inside a word such as 综合 or 运动分析), and
never with one word (en) or fewer than four characters (zh) alone on the last line. The
lines are chosen here, measured in the cover's font (the CJK sans, whose Latin letters the
English cover uses too), and written as explicit line breaks into the Markdown metadata,
so typst and Word set the same lines.

A Greek letter with a digit in a title ("φ1 = 45°") gets its digit as a subscript (φ₁).
"""

from __future__ import annotations

import re
from functools import lru_cache
from itertools import combinations

from .fmt import md_text

#: Text block of the A4 page (PDF and Word): 21 cm − 2 × 2.5 cm [pt]
TEXT_WIDTH = 453.5
#: Share of the block a line may fill: the measure leaves out kerning and the fallback
#: fonts' glyphs, and a line typst finds a little longer must not wrap again.
FILL = 0.96
#: Sizes [pt] of the cover's title and subtitle (templates/report.typ; Word's Title style
#: is 22 pt and its Subtitle 16 pt, no wider).
TITLE_SIZE = 24.0
SUBTITLE_SIZE = 16.0

# CJK symbols and punctuation, ideographs, full-width forms (built from code points: no
# Chinese literal in the code, tests/test_i18n.py)
_IS_CJK = re.compile("[" + "".join(f"{chr(a)}-{chr(b)}" for a, b in ((0x3000, 0x303F), (0x3400, 0x9FFF), (0xFF00, 0xFFEF))) + "]")
# zh: a line may end after these ...
# (enumeration comma, full-width comma, semicolon, colon, "de", "yu", closing parenthesis)
_ZH_AFTER = set(map(chr, (0x3001, 0xFF0C, 0xFF1B, 0xFF1A, 0x7684, 0x4E0E, 0xFF09))) | set(",;:)")
# ... and begin with these
# ("yu", "ji", "he", opening parenthesis)
_ZH_BEFORE = set(map(chr, (0x4E0E, 0x53CA, 0x548C, 0xFF08))) | {"("}
# a line never begins with a comma, colon or closing bracket, nor ends with an opening one
_ZH_NO_START = set(map(chr, (0x3001, 0xFF0C, 0xFF1B, 0xFF1A, 0xFF09))) | {")"}
_ZH_NO_END = {chr(0xFF08), "("}
# en: a line never ends with an article; after a preposition or conjunction it may, at a cost
_EN_NEVER_LAST = {"a", "an", "the"}
_EN_WEAK_LAST = {"of", "with", "by", "in", "for", "and", "or", "to", "on", "at", "from", "as"}
# a relation or operator keeps its neighbours on its line ("φ1 = 45°")
_GLUE = {"=", "≈", "≤", "≥", "<", ">", "+", "−", "×", "/", "–", "—"}
_GREEK_DIGIT = re.compile(r"(?<![A-Za-z])([\u0391-\u03a9\u03b1-\u03c9])(\d{1,2})(?![\d.])")


@lru_cache(maxsize=1)
def _advances():
    """(cmap, advance widths, units per em) of the cover font, or None without it."""
    from .fonts import _font_files

    path = _font_files().get("sans") or _font_files().get("serif")
    if path is None:
        return None
    try:
        from fontTools.ttLib import TTFont

        font = TTFont(str(path), lazy=True, fontNumber=0)
        return font.getBestCmap(), font["hmtx"], font["head"].unitsPerEm
    except Exception:       # an unreadable font: the estimate below
        return None


def text_width(text: str, size: float) -> float:
    """Width [pt] of ``text`` set at ``size`` in the cover font (a CJK character 1 em, a
    Latin one 0.55 em where the font is missing)."""
    font = _advances()
    total = 0.0
    for ch in _GREEK_DIGIT.sub(r"\1\2", text):
        glyph = font[0].get(ord(ch)) if font else None
        if glyph is not None:
            total += font[1][glyph][0] / font[2]
        else:
            total += 1.0 if _IS_CJK.match(ch) else 0.55
    return total * size


def _pieces(text: str, lang: str, loose: bool = False) -> list[tuple[str, float]]:
    """``text`` cut at its allowed break points: [(piece, cost of breaking after it [em])],
    the space at a break kept at the end of the piece before it. ``loose``: a line may end
    with a preposition too (when no other breaks fit)."""
    zh = lang.startswith("zh")
    pieces: list[tuple[str, float]] = []
    start = 0
    n = len(text)
    for i in range(1, n):
        prev, cur = text[i - 1], text[i]
        cost = None
        if prev == " " and cur != " ":
            before = text[start:i].split()
            last = before[-1] if before else ""
            after = text[i:].split()
            nxt = after[0] if after else ""
            if last in _GLUE or nxt in _GLUE or nxt in {"·", ":", ";", ","}:
                cost = None
            elif zh:
                # a space in a Chinese title: only after a separator (" · ", "：")
                cost = 0.0 if last in {"·"} or last[-1:] in _ZH_AFTER else None
            elif last.lower() in _EN_NEVER_LAST:
                cost = None
            elif last.lower() in _EN_WEAK_LAST:
                cost = 3.0 if loose else None   # "the theory of / machines"
            elif text[:i].count("(") > text[:i].count(")"):
                cost = None                     # inside a parenthesis: "(from / link lengths)"
            elif last[-1:] in {":", "·", ";"} or nxt[:1] == "(":
                cost = -3.0                     # a clause boundary: "…: / design report"
            elif nxt.lower() in _EN_WEAK_LAST:
                cost = -2.0                     # a phrase boundary: "… angle / of a cam"
            else:
                cost = 0.0
        elif zh and prev != " " and cur != " " and (_IS_CJK.match(prev) or _IS_CJK.match(cur)):
            if prev in _ZH_AFTER and cur not in _ZH_NO_START:
                cost = 0.0
            elif cur in _ZH_BEFORE and prev not in _ZH_NO_END:
                cost = 0.0
        if cost is not None:
            pieces.append((text[start:i], cost))
            start = i
    pieces.append((text[start:], 0.0))
    return pieces


def _last_line_ok(line: str, lang: str) -> bool:
    if lang.startswith("zh"):
        return len(line.replace(" ", "")) >= 4
    return len(line.split()) >= 2


def balanced_lines(text: str, lang: str, size: float, width: float = TEXT_WIDTH) -> list[str]:
    """``text`` as lines of about equal width, each at most ``FILL × width`` wide at
    ``size``, broken at allowed points only (see the module's docstring): the fewest lines
    that fit; among those the narrowest widest line, where a break at a phrase boundary
    gains 2 em of width (before "of") or 3 em (after ":", before "("), and a line may end
    with a preposition (at a cost of 3 em) only when nothing else fits. Never inside a
    parenthesis. Text that fits stays one line; text that cannot be broken so is returned
    as one line (typst and Word wrap it)."""
    text = " ".join(str(text or "").split())
    limit = FILL * width
    if not text or text_width(text, size) <= limit:
        return [text] if text else []
    for loose in (False, True):
        lines = _best_partition(_pieces(text, lang, loose), lang, size, limit)
        if lines:
            return lines
    return [text]


def _best_partition(pieces, lang: str, size: float, limit: float) -> list[str] | None:
    cuts = range(1, len(pieces))
    for nlines in range(2, min(len(pieces), 6) + 1):
        best = None
        for chosen in combinations(cuts, nlines - 1):
            bounds = (0, *chosen, len(pieces))
            lines = ["".join(p for p, _ in pieces[a:b]).strip() for a, b in zip(bounds, bounds[1:])]
            if not _last_line_ok(lines[-1], lang):
                continue
            widths = [text_width(line, size) for line in lines]
            if max(widths) > limit:
                continue
            score = max(widths) + sum(pieces[c - 1][1] for c in chosen) * size
            if best is None or score < best[0]:
                best = (score, lines)
        if best is not None:
            return best[1]
    return None


def title_markdown(text: str, lang: str, size: float) -> str:
    """The title (or subtitle) as pandoc Markdown for the title page: escaped as user text,
    balanced lines joined by hard line breaks, a Greek letter's digit as a subscript."""
    lines = balanced_lines(text, lang, size)
    return "\\\n".join(_GREEK_DIGIT.sub(r"\1~\2~", md_text(line)) for line in lines)
