"""Typesetting of the report (issue 19, points 1-2 and 7): long formulas broken over lines,
nothing outside the text block, no equation number over a formula, Word's TOC, header,
footer page number and author.

The word-position test renders EVERY example brief (designs/*.yaml) in zh and en to PDF and
reads the characters' boxes with PyMuPDF (a PyPI wheel; pdftotext is a system package CI
does not have). Text block of A4 with 2.5 cm margins: x from 70.87 to 524.41 pt.
Tolerance 1 pt: typst places glyphs at fractional positions and a justified line ends at
the block's edge to within rounding; the fonts' boxes overshoot their advance by a fraction
of a point. Full-width CJK punctuation is measured by its inked half: typst sets "，" at a
line end (and "（" at a line start) at half width — its box reaches half an em past the
edge, its ink does not.
"""
from __future__ import annotations

import re
import warnings
import zipfile
from pathlib import Path

import pytest

from mechdesign.render.mathbreak import BUDGET_EM, break_display_math, break_formula, tex_width
from tests.test_cover import cover_defects, wide_middle_dots
from tests.test_unit_words import parted_at_line_ends

ROOT = Path(__file__).resolve().parents[1]
LEFT, RIGHT, TOL = 70.87, 524.41, 1.0
_CLOSING = set("，。、；：？！）」』】》〉”’")
_OPENING = set("（「『【《〈“‘")


# ---- formula breaking ------------------------------------------------------------------

LONG = (r"h = \sqrt{(R + r_r + \varepsilon)^2 - e^2} - \sqrt{(R + r_r - \varepsilon)^2 - e^2}"
        r" = \sqrt{60.0^2 - 15.0^2} - \sqrt{20.0^2 - 15.0^2} = 44.8660\ \text{mm}")


def _lines(aligned: str) -> list[str]:
    inner = aligned.removeprefix(r"\begin{aligned}").removesuffix(r"\end{aligned}")
    return [line.strip() for line in inner.split(r"\\")]


def test_long_formula_is_split_at_its_top_level_equals_and_each_line_fits():
    out = break_formula(LONG)
    assert out.startswith(r"\begin{aligned}") and out.endswith(r"\end{aligned}")
    lines = _lines(out)
    # the left-hand side and the alignment point come first, continuation lines start at "="
    assert lines[0].startswith("h &= ") or lines[0].startswith("h & = ")
    assert all(line.startswith("& =") or line.startswith("&=") for line in lines[1:])
    # nothing lost: the lines, with the markers removed, are the formula
    joined = " ".join(line.replace("&", "") for line in lines)
    assert re.sub(r"\s+", "", joined) == re.sub(r"\s+", "", LONG)
    # every line fits the budget (the left-hand side counts on the first line)
    assert all(tex_width(line.replace("&", "")) <= BUDGET_EM for line in lines)
    # the '=' inside the square roots' arguments is never a break point: no line ends
    # inside braces
    assert all(line.count("{") == line.count("}") for line in lines)


def test_short_formula_is_untouched():
    short = r"a = \frac{b}{c} = 2.5\ \text{mm}"
    assert break_formula(short) == short
    md = f"text\n\n$$ {short} $$\n\nmore $x = 1$\n"
    assert break_display_math(md) == md


def test_list_of_formulas_starts_each_on_its_own_line():
    tex = (r"a = \frac{AC_2 - AC_1}{2} = 57.041\ \text{mm},\quad b = \frac{AC_2 + AC_1}{2}"
           r" = 157.966\ \text{mm},\quad d = 242.746\ \text{mm}")
    lines = _lines(break_formula(tex))
    assert [line.split("&")[0].strip() for line in lines] == ["a", "b", "d"]


def test_braces_are_never_split():
    inner = " + ".join(f"x_{{{k}}} = y_{{{k}}}" for k in range(30))
    tex = rf"z = \sqrt{{{inner}}}"
    # one top-level relation only and no top-level operator: stays one line (the PDF
    # template scales it instead)
    assert break_formula(tex) == tex


def _top_level_balanced(line: str) -> bool:
    """Round and square brackets of a line balanced (braces aside)."""
    line = re.sub(r"\\(left|right)[()\[\]]", "", line)
    return line.count("(") == line.count(")") and line.count("[") == line.count("]")


def test_operators_inside_round_brackets_are_never_break_points():
    # the shaper's moment equation (issue 19 point 1): the only top-level operators are the
    # "+" before and after the bracket; the bracket's own "+ ×" must stay on one line
    inner = " + ".join(f"{100 + k} \\times {10 + k}.5" for k in range(6))
    tex = (rf"\Sigma M_{{O3}} = 0:\ F_{{R34}} \times 74.0 + ({inner}) + 1.29 / 0.01"
           rf" = 0 \;\Rightarrow\; F_{{R34}} = -\frac{{187590}}{{74.0}} = -2537\ \mathrm{{N}}")
    lines = _lines(break_formula(tex))
    assert len(lines) >= 2
    assert all(_top_level_balanced(line) for line in lines), lines
    joined = " ".join(line.replace("&", "") for line in lines)
    assert re.sub(r"\s+|\\quad|\\qquad", "", joined) == re.sub(r"\s+", "", tex)


@pytest.mark.parametrize("tex", [
    # die_cutter: the moment equation's result alone after "⇒ M_b"
    r"\Sigma M_{O1} = 0:\ M_b + (1225 \times 10.5) \times 0.005 = 0 \;\Rightarrow\; M_b"
    r" = -64.3\ \mathrm{N\cdot m}",
    # an efficiency product: the value alone after the product of the factors
    r"\eta = \prod \eta_i \cdot \eta_b^{3} \cdot \eta_w = 0.960 \times 0.970 \times 0.970"
    r" \times 0.990^{3} \times 1.000 = 0.8764",
    # a root that cannot be broken: the result joins it
    r"S = \sqrt{0.6500^2 + 0.0925^2 + 2 \times 0.6500 \times 0.0925 \sin 98.18°}"
    r" = 0.7417\ \text{m}",
])
def test_a_result_is_never_alone_on_the_last_line(tex):
    lines = _lines(break_formula(tex))
    last = lines[-1].replace("&", "").replace(r"\quad", "").strip()
    # at least one term before the last "= result": the last line holds two relations
    # or is the whole formula's single line
    rel = re.findall(r"(?<![\\a-z])=|\\Rightarrow", last)
    assert len(lines) == 1 or len(rel) >= 2 or not last.startswith("="), lines
    joined = " ".join(line.replace("&", "") for line in lines)
    assert re.sub(r"\s+|\\quad", "", joined) == re.sub(r"\s+", "", tex)


# ---- word positions in every example PDF -------------------------------------------------

def _chars(page):
    for block in page.get_text("rawdict")["blocks"]:
        for line in block.get("lines", []):
            for span in line["spans"]:
                for ch in span["chars"]:
                    yield ch, span["size"]


def outside_text_block(pdf: Path) -> list[tuple[int, float, float, str]]:
    """(page, x0, x1, char) of every inked character outside the text block."""
    import pymupdf

    bad = []
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            for ch, size in _chars(page):
                c = ch["c"]
                if c.isspace():
                    continue
                x0, x1 = ch["bbox"][0], ch["bbox"][2]
                if c in _CLOSING:
                    x1 = min(x1, x0 + size / 2)
                elif c in _OPENING:
                    x0 = max(x0, x1 - size / 2)
                if x0 < LEFT - TOL or x1 > RIGHT + TOL:
                    bad.append((number, round(x0, 1), round(x1, 1), c))
    return bad


def numbers_over_words(pdf: Path) -> list[tuple[int, str, str]]:
    """(page, "(N)", word) where an equation number's box overlaps another word."""
    import pymupdf

    bad = []
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            words = page.get_text("words")
            for w in words:
                if not re.fullmatch(r"\(\d+\)", w[4]):
                    continue
                for o in words:
                    if o is w:
                        continue
                    dx = min(w[2], o[2]) - max(w[0], o[0])
                    dy = min(w[3], o[3]) - max(w[1], o[1])
                    if dx > 0.5 and dy > 0.5:
                        bad.append((number, w[4], o[4]))
    return bad


# the text block's height on A4 (report.typ: 2.5 cm top and bottom margins)
TOP, BOTTOM = 70.87, 841.89 - 70.87


def page_fill(page) -> float:
    """How far down the text block the page's content reaches (text lines, images, vector
    drawings such as figures and table rules), as a part of the block's height, 0 … 1: a
    page of equations with air between them is full, one whose lower half is blank is not."""
    bottoms = []
    for block in page.get_text("dict")["blocks"]:
        if block.get("type") == 1:                       # an image
            bottoms.append(block["bbox"][3])
            continue
        for line in block.get("lines", []):
            if any(sp["text"].strip() for sp in line["spans"]):
                bottoms.append(line["bbox"][3])
    bottoms += [info["bbox"][3] for info in page.get_image_info()]
    bottoms += [path["rect"].y1 for path in page.get_drawings()]
    inside = [min(y, BOTTOM) for y in bottoms if TOP < y < BOTTOM + 1]
    return (max(inside) - TOP) / (BOTTOM - TOP) if inside else 0.0


# A page mid-chapter whose content ends above this part of the text block reads as "half
# empty" to a teacher (issue 19 point 2: the reviewers' "~60 % empty" pages furnace_drive
# p.11, lockbeam_cam en p.8, crank_rocker zh p.11 reached 0.54–0.57 and passed 0.5).
FILL_LIMIT = 0.6


# A blank band inside a page, between its text and a figure set at the foot, taller than
# this part of the text block (review33 item 12: 22-34 % "quarter-page holes" above a
# figure at the foot: shaper en p.4, cam_7_1 p.6, lockbeam p.20; issue 19 point 2).
HOLE_LIMIT = 0.15


def page_holes(pdf, limit: float = HOLE_LIMIT) -> list[tuple[int, float]]:
    """(page, height as a part of the text block) of every blank band inside a page's text
    block taller than ``limit``: between two pieces of content (text lines, images, vector
    drawings such as a sheet's preview or a table's rules), not the room under the page's
    last content (half_empty_pages judges that). Sheets and the pages before the first
    chapter are not checked."""
    import pymupdf

    bad = []
    with pymupdf.open(pdf) as doc:
        first = body_start(doc)
        for number, page in enumerate(doc, 1):
            if number < first or _is_sheet(page):
                continue
            spans = []
            for block in page.get_text("dict")["blocks"]:
                if block.get("type") == 1:
                    spans.append((block["bbox"][1], block["bbox"][3]))
                    continue
                spans += [(ln["bbox"][1], ln["bbox"][3]) for ln in block.get("lines", [])
                          if any(sp["text"].strip() for sp in ln["spans"])]
            spans += [(info["bbox"][1], info["bbox"][3]) for info in page.get_image_info()]
            spans += [(path["rect"].y0, path["rect"].y1) for path in page.get_drawings()]
            spans = sorted((max(a, TOP), min(b, BOTTOM)) for a, b in spans if b > TOP and a < BOTTOM)
            if not spans:
                continue
            end, widest = spans[0][1], 0.0
            for top, bottom in spans[1:]:
                widest = max(widest, top - end)
                end = max(end, bottom)
            if widest > limit * (BOTTOM - TOP):
                bad.append((number, round(widest / (BOTTOM - TOP), 2)))
    return bad


_EQUATION_NUMBER = re.compile(r"\(\d+\)$")


# A row of a display equation: set in from the text block's left edge (centred), in the math
# font only (a line of prose starts at the edge or one indent in, a table row is in text fonts).
DISPLAY_INDENT = 40.0
# captions are set in 10 pt, the body in 11 pt
CAPTION_SIZE = 10.5


def _flow_rows(page) -> tuple[list, list]:
    """(rows, figures) of a page: its text rows without the figures' captions, as
    (top, bottom, text, display, size), and the (top, bottom) of each figure (image, caption
    included). A row that overlaps the one above it by more than 2 pt (an equation's
    subscripts or a fraction's denominator, set lower than its line) is part of it: its text
    goes before that row's when that row ends with an equation number. ``display``: every
    line of the row is a display equation's (DISPLAY_INDENT); ``size``: the largest font size
    of its lines (the body's 11 pt, a table's 9 pt, a heading's 11.5 pt and more)."""
    lines = [(ln["bbox"][1], ln["bbox"][0], all("Math" in sp["font"] for sp in ln["spans"] if sp["text"].strip()),
              max(sp["size"] for sp in ln["spans"] if sp["text"].strip()))
             for b in page.get_text("dict")["blocks"] for ln in b.get("lines", [])
             if any(sp["text"].strip() for sp in ln["spans"])]

    def of(row):                                    # the lines of a row
        return [ln for ln in lines if row[0] - 0.5 <= ln[0] < row[1] - 2]
    rows = []
    for top, bottom, text in page_rows(page):
        if rows and top < rows[-1][1] - 2:
            above = rows[-1]
            text = f"{text} {above[2]}" if _EQUATION_NUMBER.search(above[2]) else f"{above[2]} {text}"
            rows[-1] = (above[0], max(above[1], bottom), text)
        else:
            rows.append((top, bottom, text))
    rows = [row + (all(x > LEFT + DISPLAY_INDENT and math for _, x, math, _ in of(row)),
                   max((size for *_, size in of(row)), default=0.0)) for row in rows]
    images = sorted((i["bbox"][1], i["bbox"][3]) for i in page.get_image_info()
                    if i["bbox"][3] - i["bbox"][1] > 40)
    figures, captions = [], set()
    for top, bottom in images:
        below = [r for r in rows if r[0] >= bottom - 2 and _FIGURE_CAPTION.match(r[2])]
        if below:
            cap = below[0]
            captions.add(cap[0])
            bottom = cap[1]
            # a caption's second line (in the caption's smaller size: not a lead-in under it)
            captions.update(r[0] for r in rows if cap[1] - 1 < r[0] < cap[1] + 12 and r[0] not in captions
                            and not _EQUATION_NUMBER.search(r[2])
                            and all(size < CAPTION_SIZE for *_, size in of(r)))
        figures.append((top, bottom))
    return [r for r in rows if r[0] not in captions], figures


def _is_equation_row(row) -> bool:
    return bool(_EQUATION_NUMBER.search(row[2]))


def _opens_equation(rows) -> bool:
    """Whether rows[0] is a numbered display equation's row: its number stands on it, or on
    the last of the display rows that follow it (an equation of several lines, the number on
    its last: linkage_sixbar en's ΣM_B(4) over eq. 36)."""
    for row in rows[:8]:
        if _is_equation_row(row):
            return True
        if not row[3]:
            return False
    return False


# a row of the body's text (11 pt): not a table's (9 pt), a caption's (10 pt) or a heading's
BODY_SIZES = (10.5, 11.3)


def _is_prose_row(row) -> bool:
    """Whether a row (of _flow_rows) is a line of the body's text, not a display equation's."""
    return not row[3] and BODY_SIZES[0] <= row[4] < BODY_SIZES[1]


def figures_in_derivations(pdf) -> list[tuple[int, str]]:
    """(page, row) of every figure set between two lines of a derivation (issue 19 point 2:
    press fig. 6, die_cutter fig. 5, shaper fig. 4-5): a figure at a page's foot or on the top
    of the next page, where the text before it (the last row above it, on its page or the
    page before) is a numbered display equation, a lead-in ending in a colon or any other
    line of the body's text (the sentence that leads to the equation: slotter en fig. 8-9
    between "No known force on link 3 has a moment about A: M43 = 0." and eq. 22, die_cutter
    zh fig. 14 inside the sentence "若没有飞轮…只能在压切开始处产生" that eq. 53 ends), and the
    text after it (the first row under it) is a numbered display equation or the first row of
    one (_opens_equation). (A table's row before it is not taken for a lead-in.)"""
    import pymupdf

    bad = []
    with pymupdf.open(pdf) as doc:
        pages = [None if _is_sheet(p) else _flow_rows(p) for p in doc]
        for k, got in enumerate(pages):
            if got is None:
                continue
            rows, figures = got
            for top, bottom in figures:
                above = [r for r in rows if r[1] <= top + 1]
                under = [r for r in rows if r[0] >= bottom - 1]
                if not above and k > 0 and pages[k - 1] is not None:
                    above = pages[k - 1][0]
                if not under and k + 1 < len(pages) and pages[k + 1] is not None:
                    nxt_rows, nxt_figs = pages[k + 1]
                    # the next page's flow starts under the figures on its top (an equation
                    # that opens the page may reach a little above the text block: a fraction)
                    start = nxt_rows[0][0] if nxt_rows else BOTTOM
                    tops = [b for t, b in nxt_figs if t < start]
                    under = [r for r in nxt_rows if r[0] >= max(tops, default=TOP - 6) - 1]
                if not above or not under:
                    continue
                before, after = above[-1], under[0]
                if _opens_equation(under) and (_is_equation_row(before) or before[2].endswith(("：", ":"))
                                               or _is_prose_row(before)):
                    bad.append((k + 1, after[2][-40:]))
    return sorted(set(bad))


def half_empty_pages(pdf, limit: float = FILL_LIMIT) -> list[tuple[int, float]]:
    """(page, fill) of every page whose text and images cover less than ``limit`` of the
    text block's height where no chapter ends: not the cover, not the last page, not a
    page followed by one that starts with a level-1 heading (the PDF outline), not a sheet
    (a page larger than A4 or in landscape), not the cover and contents before the first
    chapter."""
    import pymupdf

    bad = []
    with pymupdf.open(pdf) as doc:
        starts = set()
        for level, title, page_no, dest in doc.get_toc(simple=False):
            if level != 1 or page_no < 1:
                continue
            to = dest.get("to")                 # the heading's anchor (top-left origin)
            y = None if to is None else to.y + 2.0
            # the heading opens its page when no text line stands above it
            page = doc[page_no - 1]
            above = [ln for b in page.get_text("dict")["blocks"] for ln in b.get("lines", [])
                     if TOP - 1 <= ln["bbox"][1] and y is not None and ln["bbox"][3] < y - 2
                     and any(sp["text"].strip() for sp in ln["spans"])]
            if not above:
                starts.add(page_no)
        first = body_start(doc)                         # the cover and the contents before it
        for number, page in enumerate(doc, 1):
            if number < first or number == len(doc) or number + 1 in starts:
                continue
            if page.rect.width > 600 or page.rect.height > 850 or page.rect.width > page.rect.height:
                continue
            fill = page_fill(page)
            if fill < limit:
                bad.append((number, round(fill, 2)))
    return bad


# ---- pages: split tables, lead-ins, short last pages, figure order -------------------------

def page_rows(page, code: bool = True) -> list[tuple[float, float, str]]:
    """(top, bottom, text) of every text row inside the text block (the running header and
    the page number outside it), top to bottom: the lines whose tops lie within 3 pt form a
    row, their text joined left to right (a table row, a line of prose). ``code=False``
    leaves out the lines set wholly in a monospaced font (a program listing)."""
    lines = []
    for block in page.get_text("dict")["blocks"]:
        for line in block.get("lines", []):
            spans = [sp for sp in line["spans"] if sp["text"].strip()]
            text = "".join(sp["text"] for sp in line["spans"]).strip()
            x0, y0, _, y1 = line["bbox"]
            if not code and spans and all("Mono" in sp["font"] for sp in spans):
                continue
            if text and TOP - 6 <= y0 <= BOTTOM:
                lines.append((y0, y1, x0, text))
    lines.sort()
    rows: list[list] = []
    for y0, y1, x0, text in lines:
        if rows and y0 - rows[-1][0] < 3.0:
            rows[-1][1] = max(rows[-1][1], y1)
            rows[-1][2].append((x0, text))
        else:
            rows.append([y0, y1, [(x0, text)]])
    return [(r[0], r[1], " ".join(t for _, t in sorted(r[2]))) for r in rows]


def _is_sheet(page) -> bool:
    return page.rect.width > 600 or page.rect.height > 850 or page.rect.width > page.rect.height


_TABLE_CAPTION = re.compile(r"^(?:表\s*(\d+)|Table\s+(\d+)\s*:)")
# (a zh caption's number is followed by an em space: a line of text that starts with "图 1 为…"
# is no caption; taken for one, it made figure_order count figure 2 from its page)
_FIGURE_CAPTION = re.compile(r"^(?:图\s*(\d+)\u2003|Figure\s+(\d+)\s*:)")
_CONTINUED = re.compile(r"^(?:续表\s*(\d+)|Table\s+(\d+)\s+\(continued\))")


def continued_missing(pdf) -> list[tuple[int, int]]:
    """(page, table) of every page on which a table goes on from an earlier page without
    "续表 N" / "Table N (continued)" (N its number) as its first row. A table goes on where
    a page's first row is the header row of the last table whose caption stood on an earlier
    page (one of the three rows after the caption's first line: the caption may take two)."""
    import pymupdf

    bad = []
    last = None                        # (table number, rows after its caption, caption page)
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            if _is_sheet(page):
                continue
            rows = page_rows(page)
            if rows and last is not None and last[2] < number:
                cont = _CONTINUED.match(rows[0][2])
                if cont and int(cont.group(1) or cont.group(2)) != last[0]:
                    bad.append((number, last[0]))
                elif not cont and rows[0][2] in last[1]:
                    bad.append((number, last[0]))
            for k, (_, _, text) in enumerate(rows):
                m = _TABLE_CAPTION.match(text)
                if m:
                    last = (int(m.group(1) or m.group(2)), [r[2] for r in rows[k + 1:k + 4]], number)
    return bad


def tables_interrupted(pdf) -> list[tuple[int, str]]:
    """(page, what) of every table split across pages with something between its parts
    (issue 19 point 2: lockbeam tables 12 and 14, cam_7_3 en table 4, die_cutter table 48 with
    a figure between them). A table that goes on to page P ("续表 N" / "Table N (continued)")
    must stand on page P − 1 down to the page's foot and go on at the top of page P: no row
    (a figure's caption, text) and no image above the continued label on P, no figure (its
    caption or image) below the table's start on P − 1, and no page between its parts."""
    import pymupdf

    bad = []
    where = {}                         # table number -> (page, top) of its last part's start
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            if _is_sheet(page):
                continue
            rows = page_rows(page)
            images = [info["bbox"] for info in page.get_image_info()]
            for k, (top, _, text) in enumerate(rows):
                cont = _CONTINUED.match(text)
                if cont:
                    n = int(cont.group(1) or cont.group(2))
                    start = where.get(n)
                    if k > 0 or any(b[3] < top for b in images):
                        above = rows[0][2] if k > 0 else "an image"
                        bad.append((number, f"table {n} continued under {above[:30]!r}"))
                    if start is None or start[0] != number - 1:
                        bad.append((number, f"table {n} continued from p.{start and start[0]}"))
                    else:
                        before = doc[number - 2]
                        after = [r[2] for r in page_rows(before)
                                 if r[0] > start[1] and _FIGURE_CAPTION.match(r[2])]
                        if after or any(b[1] > start[1] for b in
                                        (i["bbox"] for i in before.get_image_info())):
                            what = after[0][:30] if after else "an image"
                            bad.append((number - 1, f"table {n} ends its page above {what!r}"))
                    where[n] = (number, top)
                    continue
                m = _TABLE_CAPTION.match(text)
                if m:
                    where[int(m.group(1) or m.group(2))] = (number, top)
    return bad


def _sized_rows(page) -> list[tuple[float, float, str]]:
    """(top, size, text) of every text row inside the text block, as page_rows makes them; a
    row's size is the largest font size of its spans (table text 9 pt, captions 10 pt)."""
    lines = []
    for block in page.get_text("dict")["blocks"]:
        for line in block.get("lines", []):
            spans = [sp for sp in line["spans"] if sp["text"].strip()]
            if spans and TOP - 6 <= line["bbox"][1] <= BOTTOM:
                lines.append((line["bbox"][1], line["bbox"][0], max(sp["size"] for sp in spans),
                              "".join(sp["text"] for sp in line["spans"]).strip()))
    lines.sort()
    rows: list[list] = []
    for y0, x0, size, text in lines:
        if rows and y0 - rows[-1][0] < 3.0:
            rows[-1][1] = max(rows[-1][1], size)
            rows[-1][2].append((x0, text))
        else:
            rows.append([y0, size, [(x0, text)]])
    return [(r[0], r[1], " ".join(t for _, t in sorted(r[2]))) for r in rows]


def _table_rows_after(rows, k: int) -> int:
    """The text rows of a table's body after rows[k] (its caption or its continued label): past
    the caption's further lines and the header row, up to the first row not in table text."""
    k += 1
    while k < len(rows) and 9.5 < rows[k][1] <= 10.5:
        k += 1
    n = 0
    for _, size, text in rows[k + 1:]:
        if size > 9.5 or _TABLE_CAPTION.match(text):
            break
        n += 1
    return n


def thin_table_parts(pdf, keep: int = 3) -> list[tuple[int, str]]:
    """(page, what) of every part of a table split across pages that holds fewer than ``keep``
    rows (issue 19: at least three rows on each side of the break; render/pdf.py's KEEP_ROWS
    groups). Counted in text rows, so a row whose cell wraps counts more than once."""
    import pymupdf

    bad = []
    start = {}                         # table number -> (page, rows) of its last part
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            if _is_sheet(page):
                continue
            rows = _sized_rows(page)
            for k, (_, size, text) in enumerate(rows):
                cont = _CONTINUED.match(text)
                caption = _TABLE_CAPTION.match(text) if size > 9.5 else None
                if cont:
                    n = int(cont.group(1) or cont.group(2))
                    after = _table_rows_after(rows, k)
                    before = start.get(n)
                    if before is not None and before[0] == number - 1 and before[1] < keep:
                        bad.append((number - 1, f"table {n}: {before[1]} rows before the break"))
                    if after < keep:
                        bad.append((number, f"table {n}: {after} rows after the break"))
                    start[n] = (number, after)
                elif caption:
                    start[int(caption.group(1) or caption.group(2))] = (number, _table_rows_after(rows, k))
    return bad


def colon_at_page_foot(pdf) -> list[tuple[int, str]]:
    """(page, row) of every page whose last text row ends in "：" or ":" (a lead-in
    sentence parted from the list or table it introduces). A program listing's own rows
    (``def f():``) are not lead-ins, and a lead-in followed on its page by the listing's
    first rows is not at the foot."""
    import pymupdf

    bad = []
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            rows = page_rows(page)
            prose = page_rows(page, code=False)
            if (rows and prose and not _is_sheet(page) and rows[-1][0] == prose[-1][0]
                    and rows[-1][2].endswith(("：", ":"))
                    and not (number < len(doc) and _continues_paragraph(doc[number]))):
                bad.append((number, rows[-1][2][-40:]))
    return bad


def _continues_paragraph(page) -> bool:
    """The page's first text line carries on a paragraph of prose: it starts at the text
    block's left edge (a zh paragraph's first line is indented 2em, a display formula or a
    table caption is centred) and not with a list's mark. A colon that ends a line inside
    a sentence ("取整后的杆长条件：s + l = …") is not a lead-in parted from its block."""
    lines = []
    for block in page.get_text("dict")["blocks"]:
        for line in block.get("lines", []):
            text = "".join(sp["text"] for sp in line["spans"]).strip()
            x0, y0 = line["bbox"][0], line["bbox"][1]
            if text and TOP - 6 <= y0 <= BOTTOM:
                lines.append((y0, x0, text))
    # a figure floated to the page's top comes first: its caption is not the text flow
    lines.sort()
    while lines and re.match(r"^(图|Figure)\s*\d", lines[0][2]):
        lines = [ln for ln in lines if ln[0] > lines[0][0] + 3.0]
    if not lines:
        return False
    y0, x0, text = min(lines)
    first = [(x, t) for y, x, t in lines if y - y0 < 3.0]
    x0, text = min(first)
    return abs(x0 - LEFT) < 1.5 and not text.startswith(("•", "–", "-", "‣"))


def body_start(doc) -> int:
    """The page of the first level-1 heading (the cover and the contents come before)."""
    return min((page_no for level, _, page_no in doc.get_toc() if level == 1 and page_no >= 1),
               default=1)


def chapter_starts(doc) -> set[int]:
    """The pages on which a level-1 heading (the PDF outline) is the first row."""
    starts = set()
    for level, title, page_no, dest in doc.get_toc(simple=False):
        if level != 1 or page_no < 1:
            continue
        to = dest.get("to")
        y = None if to is None else to.y + 2.0
        rows = page_rows(doc[page_no - 1])
        if y is None or not [r for r in rows if r[1] < y - 2]:
            starts.add(page_no)
    return starts


MIN_ROWS = 3


def short_last_pages(pdf) -> list[tuple[int, int]]:
    """(page, rows) of every page that ends a chapter (the last page, or a page followed by
    one that a level-1 heading opens) with fewer than MIN_ROWS text rows and no figure: a
    reference or two, a line of a table, a heading alone. The rule: a chapter's last page
    holds at least three rows of text or an image (a figure or a sheet's page counts as
    full). Pages before the first chapter (the cover, the contents) are not checked."""
    import pymupdf

    bad = []
    with pymupdf.open(pdf) as doc:
        starts = chapter_starts(doc)
        first = body_start(doc)
        for number, page in enumerate(doc, 1):
            if number < first or _is_sheet(page):
                continue
            if number != len(doc) and number + 1 not in starts:
                continue
            if page.get_image_info() or any(b.get("type") == 1 for b in page.get_text("dict")["blocks"]):
                continue
            rows = page_rows(page)
            if len(rows) < MIN_ROWS:
                bad.append((number, len(rows)))
    return bad


MIN_LAST_ROWS = 6


def thin_last_page(pdf) -> list[tuple[int, int]]:
    """(page, rows) when the report's last page holds fewer than MIN_LAST_ROWS rows of text
    and no chapter starts on it (issue 19 point 2: a page holding only the last two or three
    references). A last page that a level-1 heading (the references) opens or holds, or a
    sheet, is not checked."""
    import pymupdf

    with pymupdf.open(pdf) as doc:
        last = len(doc)
        page = doc[last - 1]
        if last < body_start(doc) or _is_sheet(page):
            return []
        if any(level == 1 and page_no == last for level, _, page_no in doc.get_toc()):
            return []
        rows = page_rows(page)
        return [(last, len(rows))] if len(rows) < MIN_LAST_ROWS else []


def off_centre_figures(pdf) -> list[tuple[int, float]]:
    """(page, x of the centre) of every image not centred on the text block (to 1 pt): a
    figure floated to a page's top or foot stood at the block's left edge when it was
    narrower than the block (typst's `place(top)` aligns left; a figure set smaller to fit
    (close-chapters) stood up to 70 pt left of the centre: crank_rocker zh fig. 4)."""
    import pymupdf

    centre = (LEFT + RIGHT) / 2
    with pymupdf.open(pdf) as doc:
        return [(page.number + 1, round((b[0] + b[2]) / 2, 1)) for page in doc
                for b in (info["bbox"] for info in page.get_image_info())
                if abs((b[0] + b[2]) / 2 - centre) > TOL]


def references_alone(pdf, limit: float = 0.2) -> list[tuple[int, float]]:
    """(page, fill) when the report's last page holds the heading of its last chapter (the
    references) and fills less than ``limit`` of the text block: a short list alone on the
    last page, or with a line of the summary (issue 19 point 2: shaper_lengths, lockbeam_cam,
    cam_7_1). templates/report.typ takes the summary's last blocks along with such a list."""
    import pymupdf

    with pymupdf.open(pdf) as doc:
        last = len(doc)
        page = doc[last - 1]
        heads = [page_no for level, _, page_no in doc.get_toc() if level == 1]
        if last < body_start(doc) or _is_sheet(page) or not heads or heads[-1] != last:
            return []
        fill = page_fill(page)
        return [(last, round(fill, 2))] if fill < limit else []


_ENTRY = re.compile(r"^\[\d+\]")
# the room a level-1 heading takes above its text (templates/report.typ: 1.6em at 15 pt)
HEADING_ABOVE = 1.6 * 15


def references_apart(pdf, head: int = 3, tol: float = 2.0) -> list[tuple[int, float, float]]:
    """(page, room, needed) when the report's last chapter (the references) opens a page of
    its own while the page before, where the chapter before ends, has room for its heading
    and its first ``head`` entries (issue 19 point 2, review35: furnace_pusher en p.33, shaper
    en p.38, slotter zh/en p.38, die_cutter zh p.49: a short list alone on the last page
    under the summary's last page, 30-40 % of it empty). The rule: the list starts on the
    page where the summary ends when it fits there, or at least its heading and three
    entries do. ``room``: from the lowest content of the page before to the text block's
    foot; ``needed``: the heading's space above it and its rows down to the last row of its
    third entry (the row before the fourth entry's "[4]"), as set on its own page."""
    import pymupdf

    with pymupdf.open(pdf) as doc:
        heads = [page_no for level, _, page_no in doc.get_toc() if level == 1 and page_no >= 1]
        if not heads:
            return []
        page_no = heads[-1]
        if page_no - 1 < body_start(doc) or page_no not in chapter_starts(doc):
            return []
        before, page = doc[page_no - 2], doc[page_no - 1]
        if _is_sheet(before) or _is_sheet(page):
            return []
        rows = page_rows(page)
        entries = [k for k, r in enumerate(rows) if _ENTRY.match(r[2])]
        if not rows or not entries or entries[0] == 0:
            return []
        last = entries[head] - 1 if len(entries) > head else len(rows) - 1
        needed = rows[last][1] - rows[0][0] + HEADING_ABOVE
        room = BOTTOM - (TOP + page_fill(before) * (BOTTOM - TOP))
        return [(page_no, round(room, 1), round(needed, 1))] if needed + tol <= room else []


_CJK = re.compile(r"[\u4e00-\u9fff]")


def letter_spaced_lines(pdf, limit: float = 0.15) -> list[tuple[int, float, str]]:
    """(page, gap, line) of every text line whose Chinese characters stand apart: the median
    gap between two neighbouring ideographs of the line more than ``limit`` of the font size
    (set solid, they touch). Justification stretches a zh line that ends before an
    unbreakable Latin run or formula ("蜗 杆 45 钢 表 面 淬 火 …" before "ZCuSn10P1",
    "回 程 80°–150° …" before an inline formula): issue 19 point 2."""
    import pymupdf

    bad = []
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            for block in page.get_text("rawdict")["blocks"]:
                for line in block.get("lines", []):
                    chars = [(ch["c"], ch["bbox"], sp["size"]) for sp in line["spans"] for ch in sp["chars"]]
                    gaps = sorted((b[1][0] - a[1][2]) / a[2] for a, b in zip(chars, chars[1:])
                                  if _CJK.match(a[0]) and _CJK.match(b[0]))
                    if len(gaps) >= 4 and gaps[len(gaps) // 2] > limit:
                        text = "".join(c for c, _, _ in chars)
                        bad.append((number, round(gaps[len(gaps) // 2], 2), text[:40]))
    return bad


def lone_lines(pdf, share: float = 0.25) -> list[tuple[int, str]]:
    """(page, text) of every short line inside a paragraph: a row that starts at the text
    block's left edge and ends within its first ``share`` of the width, without a closing
    punctuation mark, between a full row (reaching the right edge) and a row that goes on
    at the left edge, all of one size and closely spaced. zh: "…一周" / "平均" / "636.6 N·m；…"
    (page review 48, five reports): a forced break before the run (templates/report.typ's
    run-break) had kept itself once typst's optimizer moved the last word down onto the
    unjustified line. A reference's last line before the next entry ("[4] …") is no paragraph."""
    import pymupdf

    bad = []
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            rows: list[list] = []
            lines = []
            for block in page.get_text("dict")["blocks"]:
                for line in block.get("lines", []):
                    spans = [sp for sp in line["spans"] if sp["text"].strip()]
                    x0, y0, x1, y1 = line["bbox"]
                    if spans and TOP - 6 <= y0 <= BOTTOM:
                        lines.append([y0, y1, x0, x1, "".join(sp["text"] for sp in spans),
                                      max(sp["size"] for sp in spans)])
            for line in sorted(lines):
                if rows and line[0] - rows[-1][0] < 3.0:
                    r = rows[-1]
                    r[1], r[2], r[3] = max(r[1], line[1]), min(r[2], line[2]), max(r[3], line[3])
                    r[4], r[5] = r[4] + line[4], max(r[5], line[5])
                else:
                    rows.append(line)
            for a, b, c in zip(rows, rows[1:], rows[2:]):
                if (a[3] > RIGHT - 3 and b[2] < LEFT + 2 and b[3] < LEFT + share * (RIGHT - LEFT)
                        and c[2] < LEFT + 2 and abs(a[5] - b[5]) < 0.5 and abs(b[5] - c[5]) < 0.5
                        and b[0] - a[1] < 12 and c[0] - b[1] < 12
                        and not re.search(r"[。：:；;.!?！？]$", b[4].strip())
                        and not re.match(r"\[\d+\]|[•–-]", c[4])):
                    bad.append((number, b[4]))
    return bad


def wide_word_gaps(pdf, factor: float = 2.0) -> list[tuple[int, float, str]]:
    """(page, widest gap [pt], line) of every justified body line (11 pt text reaching the text
    block's right edge; not a table's row, a contents line or a display equation's line with
    its number) with a word space wider than ``factor`` times the normal one (New Computer
    Modern's 0.333 em at 11 pt): an en line before an unbreakable run that did not fit on it
    (a formula, a number with its unit, a material name) spread its few spaces to 8-11 pt
    (issue 19 point 2)."""
    import pymupdf

    space = 11 * 0.333
    bad = []
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            # the words of a printed line (pymupdf parts a line at an inline formula): their
            # vertical middles within 3 pt
            lines: list[list] = []
            every = page.get_text("words")
            for w in sorted(every, key=lambda w: (w[1] + w[3]) / 2):
                middle = (w[1] + w[3]) / 2
                if lines and middle - lines[-1][0] < 3.0:
                    lines[-1][1].append(w)
                else:
                    lines.append([middle, [w]])
            for middle, words in lines:
                words.sort(key=lambda w: w[0])
                if (len(words) < 3 or words[-1][2] < RIGHT - 1.5
                        or max(w[3] - w[1] for w in words) < 12       # 9 pt table text, captions
                        or re.fullmatch(r"\(\d+\)", words[-1][4])      # an equation's number
                        or sum(w[4] == "." for w in words) > 3):      # contents' dot leaders
                    continue
                # a gap holding a glyph of a taller sign (a root's radical over the line) is none
                widest = max([b[0] - a[2] for a, b in zip(words, words[1:]) if not any(
                    w[1] < middle and w[3] > middle - 6 and w[0] < b[0] and w[2] > a[2] for w in every)] + [0])
                if widest > factor * space:
                    bad.append((number, round(widest, 1), " ".join(w[4] for w in words)[:60]))
    return bad


def uncited_figures(pdf) -> list[tuple[int, int]]:
    """(page, number) of every figure whose number no reference in the text names: a link
    whose words are "图 N" / "Figure N" (typst's reference from an ``@fig:x`` of the
    Markdown; review35 item 10, "图未在正文中引用")."""
    import pymupdf

    captions, refs = {}, set()
    with pymupdf.open(pdf) as doc:
        first = body_start(doc)
        for number, page in enumerate(doc, 1):
            if number < first:
                continue
            for _, _, text in page_rows(page):
                m = _FIGURE_CAPTION.match(text)
                if m:
                    captions.setdefault(int(m.group(1) or m.group(2)), number)
            for link in page.get_links():
                # a zh link's box may take in the character beside it ("见图 5")
                words = page.get_textbox(link["from"]).strip()
                r = re.search(r"(?:图|Figure|Fig\.)\s*(\d+)", words)
                if r and len(words) <= 12:
                    refs.add(int(r.group(1)))
    return sorted((page, n) for n, page in captions.items() if n not in refs)


def figure_order(pdf) -> list[tuple[int, str]]:
    """Figures out of order or far from their text: (page, what) for every figure whose
    number is not one more than the figure before it (typst's floats keep the order), and
    for every figure placed more than one page after the first reference to it (a link in
    the text whose words are "图 N" / "Figure N")."""
    import pymupdf

    bad = []
    captions, refs = {}, {}
    with pymupdf.open(pdf) as doc:
        first = body_start(doc)                         # not the contents
        for number, page in enumerate(doc, 1):
            if number < first:
                continue
            for top, _, text in page_rows(page):
                m = _FIGURE_CAPTION.match(text)
                if m:
                    captions.setdefault(int(m.group(1) or m.group(2)), (number, top))
            for link in page.get_links():
                words = page.get_textbox(link["from"]).strip()
                r = re.fullmatch(r"(?:图|Figure|Fig\.)\s*(\d+)", words)
                if r:
                    refs.setdefault(int(r.group(1)), number)
    previous, previous_page = 0, 0
    for n, (page, _) in sorted(captions.items(), key=lambda kv: kv[1]):
        if n != previous + 1:
            bad.append((page, f"figure {n} after figure {previous}"))
        # a figure of a run cited together (the sheet previews: "图 19、图 20、…") follows
        # the figure before it: far only when more than a page after both
        far = n in refs and page - max(refs[n], previous_page) > 1
        previous, previous_page = n, page
        if far:
            bad.append((page, f"figure {n} on p.{page}, first referred to on p.{refs[n]}"))
    return bad


def figure_anchors(pdf) -> list[tuple[tuple[int, float], tuple[int, float]]]:
    """((page, y) of the anchor, (page, y) of the figure) of every image figure, in the order
    of the text: templates/report.typ leaves where a figure stands in the text an invisible
    1 pt link to the floated figure."""
    import pymupdf

    out = []
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            for link in page.get_links():
                box = link["from"]
                if link.get("kind") == pymupdf.LINK_GOTO and box.width <= 1.5 and box.height <= 1.5:
                    out.append(((number, box.y0), (link["page"] + 1, link["to"].y)))
    return out


def _listing_rows(page) -> list[tuple[float, bool, str]]:
    """(top, whether set in a monospaced font, text) of every text line inside the text
    block, top to bottom: a line of code starts in the monospaced font (a comment's Chinese
    characters come from another font)."""
    out = []
    for block in page.get_text("dict")["blocks"]:
        for line in block.get("lines", []):
            spans = [sp for sp in line["spans"] if sp["text"].strip()]
            if spans and TOP - 6 <= line["bbox"][1] <= BOTTOM:
                out.append((line["bbox"][1], "Mono" in spans[0]["font"],
                            "".join(sp["text"] for sp in line["spans"]).strip()))
    return sorted(out)


def figures_in_listings(pdf) -> list[tuple[int, str]]:
    """(page, what) of every figure that stands inside a program listing (review37 Top 12:
    lockbeam p.35, the flow chart floated to the top of the page the listing went on to, the
    code going on under it): a figure whose caption has the listing's code under it (the next
    line, or the next page's first) and above it (a line of its page, or the last line of the
    page before when the figure opens its page)."""
    import pymupdf

    bad = []
    with pymupdf.open(pdf) as doc:
        pages = [None if _is_sheet(page) else _listing_rows(page) for page in doc]
        for number, rows in enumerate(pages, 1):
            if not rows:
                continue
            before = pages[number - 2] if number > 1 else None
            after = pages[number] if number < len(pages) else None
            for k, (_, mono, text) in enumerate(rows):
                m = _FIGURE_CAPTION.match(text)
                if not m:
                    continue
                code_above = any(r[1] for r in rows[:k]) or bool(before and before[-1][1])
                code_under = rows[k + 1][1] if k + 1 < len(rows) else bool(after and after[0][1])
                if code_above and code_under:
                    bad.append((number, f"figure {m.group(1) or m.group(2)} inside a program listing"))
    return bad


def figures_far_from_anchor(pdf) -> list[tuple[int, str]]:
    """(page, what) of every figure placed more than one page after where it stands in the
    text. A figure that follows the one before it with no text between them (a run of
    drawing-sheet previews) is counted from the page of that figure: two figures of half a
    page each cannot share the page after their anchor with a third."""
    bad = []
    previous = None
    for k, (anchor, placed) in enumerate(figure_anchors(pdf), 1):
        start = anchor[0]
        if previous is not None and previous[0][0] == anchor[0] and abs(previous[0][1] - anchor[1]) < 1:
            start = max(start, previous[1][0])
        if placed[0] - start > 1:
            bad.append((placed[0], f"figure {k} on p.{placed[0]}, its text on p.{anchor[0]}"))
        previous = (anchor, placed)
    return bad


def figures_above_their_chapter(pdf) -> list[tuple[int, str]]:
    """(page, heading) of every figure placed on the page of its own chapter's level-1
    heading above that heading (the figure's anchor comes after the heading's line: its
    destination plus the 15 pt of the heading's text)."""
    import pymupdf

    with pymupdf.open(pdf) as doc:
        heads = [(page_no, dest["to"].y, title) for level, title, page_no, dest
                 in doc.get_toc(simple=False) if level == 1 and page_no >= 1 and dest.get("to")]
    bad = []
    for anchor, placed in figure_anchors(pdf):
        own = [h for h in heads if (h[0], h[1] + 18) < anchor]
        if own and own[-1][0] == placed[0] and placed[1] < own[-1][1]:
            bad.append((placed[0], own[-1][2][:40]))
    return bad


def figures_after_their_chapter(pdf) -> list[tuple[int, str]]:
    """(page, what) of every figure placed after the level-1 heading of the chapter that
    follows its own (issue 19 point 2: slotter fig. 18, chapter 6's gear meshing drawing, on
    the top of p.24 after chapter 7 began on p.23). A figure's chapter is the chapter of its
    anchor (where it stands in the text); it must stand before the next chapter's heading
    (its destination in the PDF outline)."""
    import pymupdf

    with pymupdf.open(pdf) as doc:
        heads = [(page_no, dest["to"].y, title) for level, title, page_no, dest
                 in doc.get_toc(simple=False) if level == 1 and page_no >= 1 and dest.get("to")]
    bad = []
    for k, (anchor, placed) in enumerate(figure_anchors(pdf), 1):
        later = [h for h in heads if (h[0], h[1] + 18) > anchor]
        if later and placed > (later[0][0], later[0][1]):
            bad.append((placed[0], f"figure {k} after '{later[0][2][:30]}' (p.{later[0][0]})"))
    return bad


def heading_at_page_foot(pdf) -> list[tuple[int, str]]:
    """(page, heading) of every heading (the PDF outline, all levels) with fewer than
    MIN_ROWS rows of text below it on its page: a heading left at the foot of a page."""
    import pymupdf

    bad = []
    with pymupdf.open(pdf) as doc:
        for level, title, page_no, dest in doc.get_toc(simple=False):
            to = dest.get("to")
            if page_no < body_start(doc) or to is None:
                continue
            rows = page_rows(doc[page_no - 1])
            below = [r for r in rows if r[0] > to.y + 4]
            # the heading's own row (a title over two rows counts as one)
            if len(below) < MIN_ROWS + (1 if len(title) > 40 else 0):
                bad.append((page_no, title[:40]))
    return bad


# ---- Word: every display equation's width -----------------------------------------------
# The OMML of each line estimated as render/mathbreak estimates TeX (characters × em, fractions
# their wider part, scripts at 0.72, radicals + 1 em, delimiters + 0.8 em): it must fit the
# equation's cell, the middle 80 % of the 453.5 pt text width, in Cambria Math at 12 pt, about
# 1.1 × as wide as the estimate's New Computer Modern: 362.8 / 12 / 1.1 = 27.5 em.
import xml.etree.ElementTree as ET  # noqa: E402

from mechdesign.render.mathbreak import _char_width  # noqa: E402

WORD_CELL_EM = 0.8 * 453.5 / 12.0 / 1.1

M = "{http://schemas.openxmlformats.org/officeDocument/2006/math}"


def _kids(e, tag):
    return [c for c in e if c.tag == M + tag]


def _omml_width(e, scale=1.0):
    t = e.tag[len(M):] if e.tag.startswith(M) else None
    if t is None:
        return 0.0
    if t == "r":
        return sum(_char_width(ch) if not ch.isspace() else 0.33 for x in _kids(e, "t") for ch in (x.text or "")) * scale
    if t == "f":
        return max([_omml_width(c, scale) for c in _kids(e, "num") + _kids(e, "den")] + [0]) + 0.3 * scale
    if t in ("sSub", "sSup", "sSubSup", "sPre"):
        base = sum(_omml_width(c, scale) for c in _kids(e, "e"))
        scr = max([_omml_width(c, 0.72 * scale) for c in _kids(e, "sub") + _kids(e, "sup")] + [0])
        return base + scr
    if t == "rad":
        return sum(_omml_width(c, scale) for c in _kids(e, "e")) + 1.0 * scale
    if t == "d":
        inner = [_omml_width(c, scale) for c in _kids(e, "e")]
        return sum(inner) + 0.4 * scale * (len(inner) - 1) + 0.8 * scale
    if t == "nary":
        return 1.2 * scale + max([_omml_width(c, 0.72 * scale) for c in _kids(e, "sub") + _kids(e, "sup")] + [0]) + sum(_omml_width(c, scale) for c in _kids(e, "e"))
    if t == "eqArr":
        return max([_omml_width(c, scale) for c in _kids(e, "e")] + [0])
    if t in ("limLow", "limUpp"):
        return max(sum(_omml_width(c, scale) for c in _kids(e, "e")), max([_omml_width(c, 0.72 * scale) for c in _kids(e, "lim")] + [0]))
    if t == "m":
        rows = [[_omml_width(c, scale) for c in _kids(r, "e")] for r in _kids(e, "mr")]
        if not rows:
            return 0.0
        cols = max(len(r) for r in rows)
        return sum(max(r[j] if j < len(r) else 0 for r in rows) for j in range(cols)) + 1.0 * scale * (cols - 1)
    if t in ("rPr", "fPr", "sSubPr", "sSupPr", "radPr", "dPr", "naryPr", "eqArrPr", "ctrlPr", "deg", "oMathParaPr", "accPr", "barPr", "funcPr", "limLowPr", "limUppPr", "mPr", "groupChrPr", "boxPr", "borderBoxPr", "sSubSupPr", "sPrePr"):
        return 0.0
    return sum(_omml_width(c, scale) for c in e)


def display_widths(docx) -> list[tuple[float, str]]:
    """(estimated width [em], text) of every line of every display equation of a .docx (a line
    is an m:oMath of the math paragraph, or a row of an equation array)."""
    z = zipfile.ZipFile(docx)
    root = ET.fromstring(z.read("word/document.xml"))
    out = []
    for para in root.iter(M + "oMathPara"):
        for om in _kids(para, "oMath"):
            arrays = list(om.iter(M + "eqArr"))
            rows = [r for a in arrays for r in _kids(a, "e")] if arrays else [om]
            for row in rows:
                text = "".join(x.text or "" for x in row.iter(M + "t"))
                out.append((_omml_width(row), text[:80]))
    return out


BRIEFS = sorted(p.stem for p in (ROOT / "designs").glob("*.yaml"))
# Layout defects found by the checks above and not fixed yet (issue 19 point 2). The zh lines
# spread before an inline formula the line breaker cannot break ("动能增量 …" before
# "$ΔW_max$ = 3499.5 J", die_cutter, furnace_drive, furnace_pusher, press, shaper, slotter zh)
# now end short (render/unitjoin.py's "#run-break;", templates/report.typ).
LETTER_SPACED_OPEN: set[tuple[str, str]] = set()
# reports whose typst layout does not settle in typst's five passes. lockbeam zh and press zh
# did not after the session-33 merges (words33's text): the figure plan, first made in the
# third pass, was made anew in the fourth (lockbeam: the tails of a run, press: figures its
# layout left too far), and the fifth laid it out unchecked; lockbeam zh's stale pass then
# missed a "续表" label. The plan is now made once and stands (templates/report.typ).
# Where the held figures do not settle in typst's passes (six reports in session 36, set again
# without the figure rules, silently), render/pdf.py settles them in rounds (_settle); a report
# it cannot settle so falls back with the warning "the figure plan did not converge …", which
# the e2e check counts here: no example report falls back.
CONVERGE_OPEN: set[tuple[str, str]] = set()
CONTINUED_OPEN: set[tuple[str, str]] = set()
# en lines with word spaces over twice the normal (wide_word_gaps) before a run that may not
# break (a line never breaks after or before a relation, render/unitjoin.py): die_cutter's
# "Reactions (strength case): R_AH = …, R_AV = …" and the furnace drive's "Sliding speed …
# efficiency η = …" (15 pt) were mended by displaying the reactions and the efficiency
# relation (render/drive_report.py, session 35)
# Open lists recomputed on the merged session-36 tree (all 28 reports through the e2e
# checks at f870436). Session 35's rules: figures go to the top of a page, a level-1 heading
# flushes them, a chapter's last figure that would go to the foot stands in the text
# (layout35), the sheet previews stand in the flow under the sheets' table (previews35),
# every figure is cited (cite35). Session 36's: a chapter's last figures set smaller to fill
# the room under its text or to share a page (halfempty36), a short derivation kept whole
# (floats36).
# a figure more than a page after its text (figures_far_from_anchor): press's figure 16 (the
# cam profile, two pages after its text); press en and slotter en no longer since graph36 (the
# force tables two rows shorter: a force known to be zero is no row); press zh since the figure
# rounds (render/pdf.py _settle: the report set with its figures 1 and 2 held past table 5)
# press zh: figure 16 (the cam's profile, after the cam chapter's long data tables) two pages
# after its text since session 43 (the data table's two more rows and the figures' new legend
# places moved the pages; CI of 35a8eb75). The cause (session 44, templates/report.typ
# plan-figures), not a `mid` figure: figures 15 and 16, cited on p.22, land on pp.23 and 24
# already in typst's second pass, the layout the figures' plan is made from, but the plan does
# not see it: a figure it plans to share a page (there figure 2, with figure 1 on p.6) moves
# every later figure a page up in its model, so figure 16 counts one page after its text.
# Tried in session 44 (commit 418b6bcc on branch layout44, taken back): only the figures queued
# behind that figure move up with it (each landed after its anchor's page, its anchor no later
# than the page the one before it landed on; the first on its anchor's page ends the queue).
# press zh was then clean (figures 15 and 16 planned smaller: 15 under its text on p.22, 16 on
# the top of p.23 with its text) and 26 other reports unchanged in their findings, but press en
# p.28 (the sheets' chapter) ended at 54 %, its first preview moved on to p.29 (a figure the plan
# now saw far set smaller; skipping the sheet previews in plan-figures did not mend it)
# Gone in session 46 (the linkage chapter's angle table with its verdict column and the torque
# range's words moved press zh's pages); the cause above is not mended
FAR_OPEN: set[tuple[str, str]] = set()
WIDE_GAPS_OPEN: set[tuple[str, str]] = set()
# pages where a chapter's text ends above the half and its last figure, too tall for the room
# left, went on to the top of the next page (crank_rocker zh/en), or where a chapter's last
# figures went on over two pages, the first holding one alone (cam_7_3 zh, lockbeam_cam zh,
# shaper zh), were mended in session 36 (templates/report.typ: close-chapters, the figures
# set smaller to fill the room under the text or to share one page). Mended in session 37:
# slotter zh p.34 and textbook_guide_bar en p.17, the sheets' chapter, where the first
# preview, planned to fill the room under the sheets' table (preview-heights), did not fit
# under the line after the table that cites the previews ("各图纸的预览见图 19…") and started
# the next page whole (the previews are now planned from that line's end: mark-previews)
# textbook_guide_bar zh p.8 (half empty since text37's chapter-1 data table) is gone since
# text38: chapter 2 refers to that table instead of repeating its data in three more tables
# Mended in session 38: textbook_guide_bar zh p.8 (since text37's chapter-1 data table): the
# plan's own figures set smaller (figures 1-2 sharing p.4) moved chapter 2's end up to 58 %
# only after the close plan was made; it is applied once more from typst's third pass
# (current-close), and the rounds give it as an input where the passes do not settle
# Was open since the session-39 merges (die_cutter en p.22 at 42 %): gone in session 41 (the
# graphical method's first position moved to 6, under the cutting load; the pages moved)
HALF_EMPTY_OPEN: set[tuple[str, str]] = set()
# Open since the session-39 merges: lockbeam zh, figure 6 on p.13 first cited on p.10 (text39's
# gear-pairs table lengthened chapter 3). The cause (session 44), not a `mid` figure: figure 6,
# cited with figure 5 on p.10 (a run: no text between them), floats in typst's second pass to the
# top of p.12, between the parts of table 11 (pp.11-12), and is held past the table from the
# third (figure-held). Its rule reads its page from the pass before, where it still stood before
# the table (p.10) and had floated to p.12: it has `moved`, so neither after-split (the flow
# under the table's end, or its foot) nor `mid` applies and it is a top float, which under the
# table's last part goes on to p.13 (its anchor would move down with the table's rest); read
# from there it has moved for good, and p.12 ends at a third. Under the table there is room for
# it only set smaller (~300 pt for its 348 pt). Tried in session 44 and taken back (commit
# 3b45650e on branch layout44): a held figure placed from its table's end, never `moved`, set
# smaller to fill the room under it: figure 6 then stands under table 11 on p.12, but the pages
# after it come up and figures 14 and 15 (both cited on p.20) land on pp.21 and 22 (figure 15
# far: the figures' plan is made from typst's second pass, before any figure is held, and does
# not see it); a round with the held figures given (render/pdf.py) did not mend that, and
# cam_7_3 zh had figures 2 and 3 between the parts of table 4 with those changes
# Gone after the session-44 text changes (the positioning cam's purpose paragraph and the
# source note moved lockbeam zh's pages; checks.py on f538cb43's tree: lockbeam zh clean); the
# cause above is not mended and may show again when the text before table 11 changes
FIGURE_ORDER_OPEN: set[tuple[str, str]] = set()
# A figure between the parts of a split table whose text stands BEFORE the table is held back
# past the table (templates/report.typ: figure-held; the figures whose text follows a split
# table go to the foot of its last page: after-split). Where typst's five passes do not settle
# the held figures, render/pdf.py settles them in rounds (_settle: linkage_sixbar zh, press zh,
# textbook_guide_bar zh/en mended; they were set again without the figure rules); slotter
# zh/en mended by the after-split figures in the flow (session 37). Was open: die_cutter zh since the
# session-37 merges: figures 17 and 18 held past table 47 keep typst's passes from settling
# and land far from their text, so the rounds let them go (figure 2's hold past table 5
# stays) and figure 17 stood between the parts of table 48. Mended in session 38: with the
# close plan given in the rounds (current-close, figure-close) figures 17 and 18 stand
# before table 48, which starts under them
# Open since session 44 (the cam's purpose paragraph moved the pages): slotter zh, table 29
# (the cam profile's coordinates) starts with three rows at the foot of p.22, figures 16 and 17
# (cited before table 28) fill p.23 and the table goes on on p.24. The figures' text stands
# before the table, so figure-held should have kept them before it or past it; not mended
# linkage_sixbar en since session 44 (the flywheel's rim, three formulas more at the chapter's
# end, moved the pages): table 5 (the joint reactions) starts with three rows at the foot of
# p.5 and goes on on p.6 under figures 3 and 4, both cited before the table
# linkage_sixbar en gone in session 46 (the angle table's verdict column and the flywheel's
# note moved the pages); the cause is not mended
# slotter zh mended in session 48: the cam's profile-coordinates section keeps 14em with its
# heading (templates/report.typ keep-room-long), so heading, lead-in and the table's first rows
# no longer start at the foot of p.22 with figures 16 and 17 between the table's parts
TABLES_INTERRUPTED_OPEN: set[tuple[str, str]] = set()
# A blank band above a figure at a page's foot (page_holes). Mended in session 37 (a figure whose text follows a split table stands in the flow under
# its text where it fits, no longer at the page's foot under a hole): cam_7_3 en p.7,
# die_cutter en p.20, linkage_sixbar zh/en p.7.
HOLES_OPEN: set[tuple[str, str]] = set()
# A figure between two lines of a derivation (figures_in_derivations). A short derivation is
# not broken across pages (templates/report.typ: keep-derivations); a page whose text starts
# in the middle of a longer one takes no figure on its top, the figure whose text stands on
# it goes where its text ends (session 37: die_cutter en fig. 16 above eqs. 129-133, press en
# before eq. 65; and, seen since the check reads an equation's subscript rows as part of it,
# die_cutter en fig. 6 between eqs. 16 and 17, cam_7_3 zh/en fig. 1 between eqs. 8 and 9)
# Open since text38: linkage_sixbar en p.11, fig. 8 (group 5-6, cited on p.10) floats to the top
# of p.11 between eqs. 16 and 17 of group 3-4 (chapter 2 no longer repeats chapter 1's data,
# so the text moved up; the run 16-17 is too tall to be kept whole, and a figure floated on
# from an earlier page still goes to the top of a page that starts mid-run: the figure rule)
# Mended in session 39: linkage_sixbar en (a figure that floated on from an earlier page to a
# page that starts in the middle of a derivation is held past it: detect-run-held). The check
# now also takes a line of the body's text for the derivation's lead-in (slotter en p.12, figs.
# 8-9 between "No known force on link 3 …: M43 = 0." and eq. 22; die_cutter zh p.22): mended by
# the same rules (crossings: the lead-in's end and its equation marked)
# Open since session 40 (its digits and the crank shaft's bearing sentence moved the pages):
# die_cutter en p.39, the cam chapter: figure 16 (cited after eq. 135) on the top of the page
# that goes on with the rise's eqs. 127–128 from the page before (the crossing is not
# detected there: a run of numbered equations under a bold lead-in). Not shown since session
# 41's text (e0717cc8's remedies moved the pages; CI of stop 39): the cause is not mended, a
# `mid` figure that does not fit under its text is still a top float on the page it crosses to
# lockbeam_cam en since session 44 (the cam's purpose paragraph moved the pages): figure 1
# (the motion diagrams) on top of p.4 between the return law's heading line at the foot of p.3
# and its eq. 8; the rule that keeps a figure off the top of a page starting mid-derivation
# does not see a derivation whose first line is its bold heading. Mended in session 46
# (templates/report.typ): figure 1's text stands on p.4 after eq. 14, under the derivation that
# went on from p.3 (a `mid` figure); too tall for the room under its text, it was a top float,
# which typst set on p.4's top, above eq. 8. A `mid` figure that does not fit under its text is
# now a bottom float: at p.4's foot, after its text
DERIVATION_OPEN: set[tuple[str, str]] = set()
# Word, as LibreOffice 7.4 lays it out: a heading at a page foot with fewer than three rows
# under it. render/docx_layout.keep_headings_with_text keeps a heading's first blocks with
# it. A numbered formula's table was kept by w:keepNext on all its paragraphs, which Word reads
# as "keep the table with the next paragraph"; LibreOffice does not (its import sets no keep
# on a table): "5.2.1 Velocities", a one-line scale, formula (30), then the table's caption on
# the next page (crank_rocker en p.12; die_cutter en p.12 "5.1.1", textbook_guide_bar en p.10
# "3.1.1", furnace_pusher en p.20 "4.2.1 Velocities"). Mended in session 45 (word45): such a
# formula is written as one paragraph, the formula on a centre tab stop and its number on a
# right one, which both keep with the next block (docx_layout.formula_paragraph; a formula
# with a fraction, sum, stack or matrix stays a table, which LibreOffice still does not keep:
# 24 such in the 28 reports, none at a page foot now; 55 formulas written as paragraphs). shaper en p.23 "7 Cam mechanism" (since
# session 44) over its purpose paragraph, estimated three lines (so not kept with the next
# block), two in LibreOffice, "7.1" and its table on p.24: mended in session 45, a paragraph
# of a heading's first rows that a heading follows is kept with it. Earlier: furnace_pusher
# en p.36 "7 Drawing sheets" over two lines of a long first paragraph (session 38; closed by
# drive39's page breaks, a paragraph longer than WHOLE_LINES is still not kept whole).
WORD_HEADINGS_OPEN: set[tuple[str, str]] = set()

@pytest.mark.e2e
@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("brief", BRIEFS)
def test_every_report_stays_in_the_text_block(brief, lang, tmp_path, libreoffice_profile):
    from typer.testing import CliRunner

    from mechdesign.cli import app as cli_app

    out = tmp_path / f"{brief}-{lang}"
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = CliRunner().invoke(cli_app, ["run", str(ROOT / "designs" / f"{brief}.yaml"),
                                              "--lang", lang, "--format", "pdf,docx", "--out", str(out)])
    assert result.exit_code == 0, result.output
    # typst's layout settled (the figure plan reads the positions of the pass before)
    unsettled = [str(w.message)[:80] for w in caught if "converge" in str(w.message)]
    assert (unsettled != []) if (brief, lang) in CONVERGE_OPEN else (unsettled == []), unsettled
    # Word: every line of every display equation fits its cell (after render/mathbreak)
    wide = [(round(w, 1), text) for w, text in display_widths(out / "report.docx") if w > WORD_CELL_EM]
    assert wide == []
    pdf = out / "report.pdf"
    assert outside_text_block(pdf) == []
    assert numbers_over_words(pdf) == []
    # issue 19, point 5: no number parted from its unit (or from its "=") at a line end
    assert parted_at_line_ends(pdf) == []
    # issue 19, point 2 (templates/report.typ): no page more than half empty where no
    # chapter ends; "续表 N" / "Table N (continued)" atop every page a table goes on to; no
    # page ending in a lead-in ("…：" / "…:"); no chapter ending on a page of one or two
    # rows; no heading without three rows under it; figures in order, near their text
    half = half_empty_pages(pdf)
    assert (half != []) if (brief, lang) in HALF_EMPTY_OPEN else (half == []), half
    cont = continued_missing(pdf)
    assert (cont != []) if (brief, lang) in CONTINUED_OPEN else (cont == []), cont
    # nothing between the parts of a split table (the open ones must still show it)
    parted = tables_interrupted(pdf)
    assert (parted != []) if (brief, lang) in TABLES_INTERRUPTED_OPEN else (parted == []), parted
    # no quarter-page hole above a figure at a page's foot, no figure inside a derivation
    holes = page_holes(pdf)
    assert (holes != []) if (brief, lang) in HOLES_OPEN else (holes == []), holes
    inside = figures_in_derivations(pdf)
    assert (inside != []) if (brief, lang) in DERIVATION_OPEN else (inside == []), inside
    assert colon_at_page_foot(pdf) == []
    # a table split across pages keeps at least three rows on each side (issue 19)
    assert thin_table_parts(pdf) == []
    assert short_last_pages(pdf) == []
    # the last page holds more than a few lines, or the references chapter starts on it
    assert thin_last_page(pdf) == []
    # nor a short references list alone on it
    assert references_alone(pdf) == []
    # nor alone on a page of its own where the page before has room for its heading and
    # its first three entries
    assert references_apart(pdf) == []
    # no zh line letter-spaced by justification; the reports where the defect is still open
    # must still show it (so that the entry goes when it is fixed)
    spaced = letter_spaced_lines(pdf)
    assert (spaced != []) if (brief, lang) in LETTER_SPACED_OPEN else (spaced == []), spaced
    # nor a paragraph's line holding a lone word or two ("一周 / 平均 / 636.6 N·m")
    assert lone_lines(pdf) == []
    # nor an en line with word spaces over twice the normal (templates/report.typ's tracking
    # limits, render/unitjoin.py's lists of relations boxed item by item)
    wide = wide_word_gaps(pdf) if lang == "en" else []
    assert (wide != []) if (brief, lang) in WIDE_GAPS_OPEN else (wide == []), wide
    assert heading_at_page_foot(pdf) == []
    # the cover's title and subtitle broken at phrase boundaries; "N·m" with a narrow dot
    assert cover_defects(pdf, lang) == []
    assert wide_middle_dots(pdf) == []
    order = figure_order(pdf)
    assert (order != []) if (brief, lang) in FIGURE_ORDER_OPEN else (order == []), order
    # every figure stands in the middle of the text block
    assert off_centre_figures(pdf) == []
    # every figure is cited in the text: "如图 5 所示" / "(Figure 5)" (review35 item 10)
    assert uncited_figures(pdf) == []
    # no figure above its own chapter's heading, none more than a page after its text
    assert figures_above_their_chapter(pdf) == []
    # nor after the next chapter's heading (a level-1 heading flushes the floats)
    assert figures_after_their_chapter(pdf) == []
    far = figures_far_from_anchor(pdf)
    assert (far != []) if (brief, lang) in FAR_OPEN else (far == []), far
    # no figure inside the appendix's program listing (lockbeam, review37 Top 12)
    assert figures_in_listings(pdf) == []
    # the Word file as LibreOffice lays it out: issue 19 points 1 and 2 (tests/test_docx.py)
    from tests.test_docx import SOFFICE, libreoffice_pdf, word_layout_defects
    if SOFFICE is not None:
        word_pdf = libreoffice_pdf(out / "report.docx", tmp_path / "word", libreoffice_profile)
        defects = word_layout_defects(out / "report.docx", word_pdf)
        heads = defects.pop("headings at a page foot", [])
        assert (heads != []) if (brief, lang) in WORD_HEADINGS_OPEN else (heads == []), heads
        assert defects == {}


@pytest.fixture(scope="module")
def libreoffice_profile(tmp_path_factory) -> Path:
    """A LibreOffice user profile for this module's conversions (made once: the first
    conversion with a new profile takes some seconds more)."""
    return tmp_path_factory.mktemp("lo-profile")


# ---- Word: table of contents, running header, page numbers, author ------------------------

@pytest.mark.e2e
def test_word_has_toc_header_page_field_and_author(tmp_path):
    from mechdesign.render.docx import render_docx
    from mechdesign.render.report import template_dir

    md = tmp_path / "report.md"
    md.write_text("# One\n\nText.\n\n$$ " + LONG + " $$\n\n## Two\n\nMore.\n", encoding="utf-8")
    meta = {"title": "Shaper & co design", "student": "Zhang San", "lang": "en",
            "description": "Shaper & co design — course project"}
    out = tmp_path / "report.docx"
    render_docx(md, out, meta, template_dir())
    with zipfile.ZipFile(out) as docx:
        document = docx.read("word/document.xml").decode("utf-8")
        headers = [docx.read(n).decode("utf-8") for n in docx.namelist()
                   if re.fullmatch(r"word/header\d+\.xml", n)]
        footers = [docx.read(n).decode("utf-8") for n in docx.namelist()
                   if re.fullmatch(r"word/footer\d+\.xml", n)]
        core = docx.read("docProps/core.xml").decode("utf-8")
    assert re.search(r"<w:instrText[^>]*>\s*PAGEREF _Toc\d+ \\h", document)     # contents, render/docx_toc
    assert "headerReference" in document and "footerReference" in document
    assert any("Shaper &amp; co design" in h and " TITLE " in h for h in headers)
    assert any(re.search(r"<w:instrText[^>]*>\s*PAGE\s*<", f) for f in footers)
    assert "<dc:creator>Zhang San</dc:creator>" in core
    assert "<dc:subject>Shaper &amp; co design — course project</dc:subject>" in core
    # the long equation reached Word broken over lines (one equation per line of its math
    # paragraph, render/docx_math.py), not clipped
    assert max(len(re.findall(r"<m:oMath>", p))
               for p in re.findall(r"<m:oMathPara>.*?</m:oMathPara>", document, re.DOTALL)) >= 2


# ---- tables prepared for page breaks -------------------------------------------------------

def _pipe_table(rows: int) -> str:
    lines = ["| a | b |", "|---|--:|"] + [f"| r{k} | {k} |" for k in range(rows)]
    return "\n".join(lines) + "\n\n: Caption {#tbl:t}\n"


@pytest.mark.parametrize("rows, groups", [(4, ["rowspan: 4"]), (10, ["rowspan: 3", "rowspan: 3"])])
def test_tables_get_a_continued_header_and_unbreakable_row_groups(rows, groups):
    from mechdesign.render.pdf import markdown_to_typst
    from mechdesign.render.report import template_dir

    source = markdown_to_typst("# T\n\n" + _pipe_table(rows), template_dir() / "report.typ",
                               {"title": "t", "lang": "en"}, ROOT)
    table = source[source.index("#table("):]
    table = table[:table.index("\n  )")]
    # a zero-width extra column, the continued label spanning all three columns
    assert "columns: (auto, auto, 0pt)," in table
    assert "table.header(table.cell(colspan: 3, inset: 0pt)[#table-continued()]" in table
    assert re.findall(r"rowspan: \d+", table) == groups
    # every row line carries its cell of the extra column or is covered by a group
    row_lines = [line for line in table.splitlines() if line.strip().startswith("[r")]
    assert len(row_lines) == rows


# ---- the page rules of templates/report.typ on small documents ------------------------------

def _render(tmp_path, md: str, lang: str = "en") -> Path:
    from mechdesign.render.pdf import render_pdf
    from mechdesign.render.report import template_dir

    (tmp_path / "doc.md").write_text(md, encoding="utf-8")
    pdf = tmp_path / "doc.pdf"
    render_pdf(tmp_path / "doc.md", pdf, {"title": "T", "lang": lang}, template_dir() / "report.typ")
    return pdf


_FILLER = ("The crank turns at a constant speed and the rocker swings between its two limit "
           "positions; the transmission angle is checked at every position of the cycle. ")


def test_a_long_table_repeats_its_header_under_a_continued_label(tmp_path):
    import pymupdf

    rows = "\n".join(f"| r{k} | {k} |" for k in range(90))
    md = f"# One\n\n{_FILLER * 3}\n\n| Name | Value |\n|---|--:|\n{rows}\n\n: Long table {{#tbl:long}}\n"
    pdf = _render(tmp_path, md)
    assert continued_missing(pdf) == []
    with pymupdf.open(pdf) as doc:
        pages = [page_rows(p) for p in doc]
    later = [rows for rows in pages if rows and rows[0][2] == "Table 1 (continued)"]
    assert len(later) >= 1
    # under the label the repeated header, then at least KEEP_ROWS rows of the table
    for rows in later:
        assert rows[1][2] == "Name Value"
        assert len([r for r in rows[2:] if re.fullmatch(r"r\d+ \d+", r[2])]) >= 3


def test_a_lead_in_never_ends_a_page(tmp_path):
    # forty lead-ins ("… as follows:") before a formula, a list or a table, after texts of
    # growing length: without the rule several of them end a page
    parts = ["# One\n"]
    for k in range(40):
        parts.append(_FILLER * (1 + k % 4))
        parts.append(f"The values of case {k} are as follows:")
        if k % 3 == 0:
            parts.append(f"$$ x_{{{k}}} = \\frac{{a + b}}{{2}} = {k}.5 $$")
        elif k % 3 == 1:
            parts.append("- first item\n- second item\n- third item")
        else:
            parts.append("| a | b |\n|---|---|\n| 1 | 2 |\n| 3 | 4 |\n\n: Case table")
    pdf = _render(tmp_path, "\n\n".join(parts) + "\n")
    assert colon_at_page_foot(pdf) == []


def test_a_short_derivation_is_not_broken_across_pages(tmp_path):
    # forty derivations of two display equations after a lead-in ("… follows:"), after texts
    # of growing length: without the rule (templates/report.typ keep-derivations) a page
    # ends between the two equations of several of them, where a figure floated to the top
    # of the next page would stand between them (figures_in_derivations)

    parts = ["# One\n"]
    for k in range(40):
        parts.append(_FILLER * (1 + k % 4))
        parts.append(f"The moment equation of case {k} and the force it gives follow:")
        parts.append(f"$$ \\Sigma M_{{{k}}} = M_b + (2537 \\times 9.0) \\times 0.01 = 0 $$")
        parts.append(f"$$ P_{{{k}}} = \\frac{{M_b}}{{l_{{AB}}}} = \\frac{{-228.3}}{{0.0925}} = -2468 $$")
    pdf = _render(tmp_path, "\n\n".join(parts) + "\n")
    page_of = equation_pages(pdf)
    assert sorted(page_of) == list(range(1, 81))
    assert len(set(page_of.values())) > 3
    split = [k for k in range(40) if page_of[2 * k + 1] != page_of[2 * k + 2]]
    assert split == []


def equation_pages(pdf: Path) -> dict[int, int]:
    """Each equation number's page (the first page a row ends in "(n)")."""
    import pymupdf

    page_of: dict[int, int] = {}
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            for row in page_rows(page):
                m = re.search(r"\((\d+)\)$", row[2])
                if m:
                    page_of.setdefault(int(m.group(1)), number)
    return page_of


@pytest.mark.parametrize("lines", [30, 31])
def test_the_sheets_previews_start_under_the_line_that_cites_them(tmp_path, lines):
    # the sheets' table ends a little above the middle of a page and two lines cite the
    # previews under it: planned from the table's foot (preview-heights), the first preview
    # was set to a room two lines taller than the one left, did not fit and started the next
    # page whole, which left the table's page half empty (slotter zh p.34, textbook en p.17)
    from PIL import Image

    Image.new("RGB", (1189, 841), (200, 220, 240)).save(tmp_path / "a1.png")
    Image.new("RGB", (420, 297), (220, 240, 200)).save(tmp_path / "a3.png")
    md = "\n\n".join([
        "# One\n", _FILLER * 20, "# Drawing sheets\n", _FILLER * lines,
        "| Drawing | Size |\n|---|---|\n| Kinematic diagram | A3 |\n| Analysis | A1 |\n\n: Drawing sheets {#tbl:sheets}",
        "The previews of the sheets are " + ", ".join(["@fig:sheet-kinematic"] * 8) + " and @fig:sheet-analysis.",
        "![Kinematic diagram (A3, preview)](a3.png){#fig:sheet-kinematic width=100%}",
        "![Analysis (A1, preview)](a1.png){#fig:sheet-analysis width=100%}",
        "# Summary {#summary .unnumbered}\n", _FILLER * 3]) + "\n"
    pdf = _render(tmp_path, md)
    assert half_empty_pages(pdf) == []
    assert page_holes(pdf) == []


def test_a_figure_stays_off_a_long_derivation_that_went_on_to_its_page(tmp_path):
    # derivations of seven equations (too long to keep whole: keep-derivations), each followed
    # by a line citing a figure; the second goes on from page 4 to page 5, where its figure's
    # text stands: the figure floated to the top of page 5, between eqs. 10 and 11 (die_cutter
    # en fig. 16 above eqs. 129-133). It now stands in the flow where its text ends.
    from PIL import Image

    Image.new("RGB", (800, 500), (200, 220, 240)).save(tmp_path / "a.png")
    parts = ["# One\n", _FILLER * 24]
    for k in range(3):
        parts.append(_FILLER * (1 + k))
        parts.append(f"The law of segment {k} follows:")
        parts += [f"$$ S_{{{k}{i}}}(u) = 10 u^3 - 15 u^4 + 6 u^5 + {i} $$" for i in range(7)]
        parts.append(f"The curves of segment {k} are plotted in the figure.")
        parts.append(f"![Curves {k}](a.png){{width=70%}}")
    pdf = _render(tmp_path, "\n\n".join(parts) + "\n")
    page_of = equation_pages(pdf)
    assert page_of[8] < page_of[14]                  # the case: the second derivation breaks
    assert figure_anchors(pdf)[1][0][0] == page_of[14]    # and its figure's text is on its page
    assert figures_in_derivations(pdf) == []
    assert page_holes(pdf) == [] and half_empty_pages(pdf) == []


def test_a_figure_floated_on_stays_off_the_derivation_that_went_on_to_its_page(tmp_path):
    # a figure cited before a derivation of five equations (too long to keep whole) and too
    # tall for the rest of its page floats on to the top of the next page, where the
    # derivation goes on: it stood between eqs. 37 and 38 (linkage_sixbar en fig. 8 between
    # eqs. 16 and 17). It is now held past the derivation (templates/report.typ:
    # detect-run-held) and stands under its last equation
    from PIL import Image

    Image.new("RGB", (800, 500), (200, 220, 240)).save(tmp_path / "a.png")
    parts = ["# One\n"]
    for k in range(12):
        parts.append(_FILLER * (1 + k % 5))
        parts.append(f"The forces of case {k} are drawn in Figure {k + 1}.")
        parts.append(f"![Case {k}](a.png){{width=70%}}")
        parts.append(f"The law of case {k} follows:")
        parts += [f"$$ S_{{{k}{i}}}(u) = 10 u^3 - 15 u^4 + 6 u^5 + {i} $$" for i in range(5)]
    pdf = _render(tmp_path, "\n\n".join(parts) + "\n")
    page_of = equation_pages(pdf)
    anchors = figure_anchors(pdf)
    # the case: a derivation goes on from one page to the next and the figure cited before it
    # stands on that next page
    assert any(page_of[5 * k + 1] < page_of[5 * k + 5] == anchors[k][1][0] for k in range(12))
    assert figures_in_derivations(pdf) == []
    assert figure_order(pdf) == [] and figures_far_from_anchor(pdf) == []
    assert page_holes(pdf) == [] and half_empty_pages(pdf) == []


def test_a_figure_stays_off_a_lead_in_and_the_equation_it_leads_to(tmp_path):
    # sentences that lead to a display equation ("… gives the reaction of case 10 as", no colon)
    # end a page and the equation opens the next, with a figure cited under it: the figure
    # stood on the top of that page (or at the foot of the page before) between the sentence
    # and its equation (slotter en figs. 8-9 above eq. 22, die_cutter zh fig. 14 above eq.
    # 53). It now stands where its text ends (templates/report.typ: crossings)
    import pymupdf
    from PIL import Image

    Image.new("RGB", (800, 500), (200, 220, 240)).save(tmp_path / "a.png")
    parts = ["# One\n"]
    for k in range(30):
        parts.append(_FILLER * (1 + (2 * k) % 5))
        parts.append(f"With no force on link {k} the moment about its pivot gives the reaction of case {k} as")
        parts.append(f"$$ F_{{{k}}} = \\frac{{M_b}}{{l_{{AB}}}} = \\frac{{-228.3}}{{0.0925}} = -2468 $$")
        parts.append(f"The forces of case {k} are drawn in Figure {k // 2 + 1}.")
        if k % 2 == 0:
            parts.append(f"![Case {k}](a.png){{width=55%}}")
    pdf = _render(tmp_path, "\n\n".join(parts) + "\n")
    page_of = equation_pages(pdf)
    with pymupdf.open(pdf) as doc:
        lead = {int(m.group(1)): number for number, page in enumerate(doc, 1) for row in page_rows(page)
                for m in [re.search(r"reaction of case (\d+) as$", row[2])] if m}
    # the case: a lead-in ends a page and its equation opens the next
    assert any(lead[k] < page_of[k + 1] for k in range(30))
    assert figures_in_derivations(pdf) == []
    assert figure_order(pdf) == [] and figures_far_from_anchor(pdf) == []
    assert page_holes(pdf) == [] and half_empty_pages(pdf) == []


@pytest.mark.parametrize("lines", [12, 13])
def test_a_chapters_last_figure_a_little_too_tall_fills_the_rest_of_its_page(tmp_path, lines):
    # a chapter's text ends at about two thirds of its page, and its figure is a little taller
    # than the room left: it went on to the top of the next page, before the next chapter, and
    # the page ended at 63 % (die_cutter en p.9, figure 5). It is now set smaller to fill that
    # room (templates/report.typ: close-floor, at least 80 % of its height)
    from PIL import Image

    Image.new("RGB", (800, 500), (200, 220, 240)).save(tmp_path / "a.png")
    md = (f"# One\n\n{_FILLER * lines}\n\nThe joint reactions are plotted in Figure 1.\n\n"
          f"![Reactions](a.png){{width=100%}}\n\n# Two\n\n{_FILLER * 8}\n")
    pdf = _render(tmp_path, md)
    (anchor, placed), = figure_anchors(pdf)
    assert placed[0] == anchor[0]
    assert half_empty_pages(pdf) == [] and page_holes(pdf) == []


def test_the_references_take_no_whole_chapter_with_them_to_the_last_page(tmp_path):
    # a short summary and a short reference list after a chapter that ends low on its page:
    # the list, too short to stand alone on the last page, takes the summary's last blocks
    # with it (keep-together's lead); it took the whole summary, its heading too, and left the
    # page before 65 % full (shaper_lengths zh p.21, the A1 preview alone, 48 %). The summary
    # now starts on that page; the last page still holds more than the references
    import pymupdf

    rows = "\n".join(f"| item {k} | {k}.00 | mm |" for k in range(9))
    md = (f"# Sheets\n\n{_FILLER * 14}\n\n# Summary {{#summary}}\n\nThis design comprises the analysis; "
          f"the key results:\n\n| Quantity | Value | Unit |\n|---|--:|---|\n{rows}\n\n: Key results\n\n"
          "The design was verified by 6 checks, all passed:\n\n| Checks | Number | Verdict |\n|---|--:|---|\n"
          "| checks | 6 | PASS |\n\n: Check verdicts\n\nNothing was found that the designer has to act on.\n\n"
          "# References {-}\n\n[1] SUN Huan. Theory of Machines[M]. 2013.\n\n[2] ZHU Baoli. Guide[M]. 2004.\n\n"
          "[3] GB/T 14689-2008 Technical drawings[S].\n")
    pdf = _render(tmp_path, md)
    with pymupdf.open(pdf) as doc:
        pages = {key: min(i for i, page in enumerate(doc, 1) if any(r[2].endswith(key) for r in page_rows(page)))
                 for key in ("Sheets", "Summary")}
        assert len(doc) == pages["Sheets"] + 1      # the case: the references go on to a page of their own
    assert pages["Summary"] == pages["Sheets"]
    assert references_alone(pdf) == [] and thin_last_page(pdf) == []


@pytest.mark.parametrize("lines", [12, 17])
def test_a_figure_stands_before_the_program_listing_that_follows_its_text(tmp_path, lines):
    # a figure cited on a page, too tall for the room under its text (as a float), then a
    # section with a long program listing (lockbeam's appendix): the figure floated to the top
    # of the next page, and the listing, begun under its heading, went on under it (review37
    # Top 12). It now stands in the flow under its text (12 lines of text before it) or on the
    # top of the next page with the listing's section after it (17 lines)
    from PIL import Image

    Image.new("RGB", (800, 600), (200, 220, 240)).save(tmp_path / "a.png")
    code = "\n".join(f"x{k} = {k} * 2  # step {k}" for k in range(90))
    md = (f"# Appendix\n\n{_FILLER * lines}\n\nThe flow chart of the program is Figure 1.\n\n"
          f"![Flow chart](a.png){{width=80%}}\n\n## Listing\n\nThe program:\n\n```python\n{code}\n```\n")
    pdf = _render(tmp_path, md)
    assert figures_in_listings(pdf) == []
    assert page_holes(pdf) == [] and half_empty_pages(pdf) == []


def test_a_figure_over_an_equation_of_several_lines_is_seen_inside_its_derivation(tmp_path):
    # figures_in_derivations on pages set by hand: eq. (1) ends page 1 and a figure opens page
    # 2 above an equation of two lines numbered on its last (linkage_sixbar en: ΣM_B(4) over
    # eq. 36): the row under the figure has no number of its own. With a line of prose between
    # the figure and the equation it is no derivation's.
    import typst
    from PIL import Image

    Image.new("RGB", (400, 300), (200, 220, 240)).save(tmp_path / "a.png")

    def pages(between: str) -> Path:
        src = ('#set page(paper: "a4", margin: 2.5cm)\n#set text(size: 11pt)\n'
               '#show figure.caption: set text(size: 10pt)\n'
               '#set math.equation(numbering: "(1)", number-align: bottom)\n'
               '#lorem(60)\n$ a = b + c $\n#pagebreak()\n'
               '#figure(image("a.png", width: 60%), caption: [A figure])\n' + between +
               '$ Sigma M_B = F times 60.0 + 2.31 \\ = 0 => F = -10.1 $\n#lorem(30)\n')
        (tmp_path / "p.typ").write_text(src, encoding="utf-8")
        pdf = tmp_path / f"p{len(between)}.pdf"
        pdf.write_bytes(typst.compile(str(tmp_path / "p.typ"), root=str(tmp_path)))
        return pdf

    # (the equation a float's clearance under the caption, as in a report)
    assert [p for p, _ in figures_in_derivations(pages("#v(10pt)\n"))] == [2]
    assert figures_in_derivations(pages("#v(10pt)\nThe moment about B gives the force:\n\n#lorem(12)\n\n")) == []


def test_figures_float_in_order_and_pages_stay_full(tmp_path):
    from PIL import Image

    parts = ["# One\n"]
    for k in range(12):
        Image.new("RGB", (800, 300 + 90 * (k % 5)), (200, 220, 240)).save(tmp_path / f"f{k}.png")
        parts.append(_FILLER * (2 + k % 3))
        parts.append(f"![Figure number {k + 1}](f{k}.png){{#fig:f{k} width=90%}}")
    parts.append("# Two\n\n" + _FILLER * 4)
    parts.append("# References {-}\n\n" + "\n\n".join(f"[{k}] Author. Book {k}." for k in range(1, 6)))
    pdf = _render(tmp_path, "\n\n".join(parts) + "\n")
    assert figure_order(pdf) == []
    assert half_empty_pages(pdf) == []
    assert short_last_pages(pdf) == []


def _references(count: int, words: int = 8) -> str:
    return "\n\n".join(f"[{k}] Author, Other Author. " + " ".join(["Title"] * words)
                       + f" {k} [M]. Beijing: Press, 2013." for k in range(1, count + 1))


@pytest.mark.parametrize("count, words, lines", [(11, 6, range(19, 27, 2)), (40, 14, range(0, 40, 9))])
def test_the_last_page_never_holds_only_the_last_references(tmp_path, count, words, lines):
    # a summary of growing length before a references list: a short list (11 entries, a
    # third of a page) moves whole with its heading to the next page where it does not fit;
    # a long one (40 entries of two lines) breaks, but leaves more than a few lines to the
    # last page. The old rule (the last three paragraphs together) left three references
    # alone on the last page for three of the four short cases.
    for k in lines:
        md = ("# One\n\n" + "\n\n".join(_FILLER * 2 for _ in range(10)) + "\n\n# Summary\n\n"
              + "\n\n".join(f"Result line {j}." for j in range(k))
              + "\n\n# References {-}\n\n" + _references(count, words) + "\n")
        (tmp_path / str(k)).mkdir()
        pdf = _render(tmp_path / str(k), md)
        assert thin_last_page(pdf) == [], k
        assert short_last_pages(pdf) == [], k
        assert half_empty_pages(pdf) == [], k


def test_a_short_references_list_takes_the_summarys_last_lines_along(tmp_path):
    # three references after a summary that ends near the page foot: moved whole to the next
    # page, they stood there alone (shaper_lengths, lockbeam_cam, cam_7_1); the summary's
    # last lines now go with them
    bad = []
    for k in range(30, 40, 3):
        md = ("# One\n\n" + "\n\n".join(_FILLER * 2 for _ in range(10)) + "\n\n# Summary {#summary}\n\n"
              + "\n\n".join(f"Result line {j}." for j in range(k))
              + "\n\n# References {-}\n\n" + _references(3, 8) + "\n")
        (tmp_path / str(k)).mkdir()
        pdf = _render(tmp_path / str(k), md)
        bad += [(k, r) for r in references_alone(pdf) + half_empty_pages(pdf)]
    assert bad == []


def test_a_chapter_figure_stays_under_its_heading(tmp_path):
    # a figure anchored in the upper half of a page a chapter opens: `auto` would float it
    # to the top of the page, above the chapter's heading
    from PIL import Image

    Image.new("RGB", (800, 300), (200, 220, 240)).save(tmp_path / "a.png")
    Image.new("RGB", (800, 300), (200, 220, 240)).save(tmp_path / "b.png")
    md = (f"# One\n\n{_FILLER}\n\n![First figure](a.png){{width=80%}}\n\n{_FILLER * 9}\n\n"
          f"# Two\n\n{_FILLER}\n\n![Second figure](b.png){{width=80%}}\n\n{_FILLER * 12}\n")
    pdf = _render(tmp_path, md)
    assert len(figure_anchors(pdf)) == 2
    assert figures_above_their_chapter(pdf) == []
    assert figure_order(pdf) == []


def test_a_run_of_tall_figures_stays_near_its_text(tmp_path):
    # two figures of about half a page anchored close together in the lower half of a page:
    # the first floats to the top of the next page, the second (53 % of the text block)
    # would not fit beside it and wait two pages; it is set smaller to share that page
    from PIL import Image

    Image.new("RGB", (800, 584), (200, 220, 240)).save(tmp_path / "a.png")
    Image.new("RGB", (800, 688), (200, 220, 240)).save(tmp_path / "b.png")
    md = "\n\n".join(["# One\n", _FILLER * 12, "![Figure A](a.png){width=95%}", _FILLER,
                       "![Figure B](b.png){width=95%}", _FILLER * 12]) + "\n"
    pdf = _render(tmp_path, md)
    anchors = figure_anchors(pdf)
    assert [a[0] for a, _ in anchors] == [3, 3]       # the case: both anchored on one page
    assert figures_far_from_anchor(pdf) == []
    assert figure_order(pdf) == []
    assert half_empty_pages(pdf) == []


# Appended to a report's typst source: what each of typst's layout passes saw of the pass
# before (a query reads the positions of the pass before), as a line of text "PASSES …": the
# number of figure anchors and of floated figures. (It never settles itself, so typst runs
# all five passes.)
_PASS_PROBE = """
#context {
  let before = query(<pass-probe>)
  let seen = if before.len() > 0 { before.first().value } else { () }
  let now = seen + ((query(<figure-anchor>).len(), query(<figure-float>).len()),)
  [#metadata(now)<pass-probe>]
  [PASSES #now.map(p => str(p.at(0)) + "/" + str(p.at(1))).join(" ")]
}
"""


def test_every_figure_is_in_typsts_first_layout_pass(tmp_path):
    # the figure plan reads the layout of the pass before and typst stops after five passes:
    # the figures must be laid out from the first pass on, the plan's first pass among them
    # (the figure rule asked the plan for figure n - 1 while typst's counters still read 0
    # in the first pass, failed, and left every figure out of it: lockbeam zh did not
    # settle, issue 19 point 1)
    import pymupdf
    import typst
    from PIL import Image

    from mechdesign.render.pdf import typst_fonts, typst_source
    from mechdesign.render.report import template_dir

    for k in range(3):
        Image.new("RGB", (800, 400), (200, 220, 240)).save(tmp_path / f"f{k}.png")
    md = "\n\n".join(["# One\n"] + [f"{_FILLER * 4}\n\n![Figure {k}](f{k}.png)" for k in range(3)])
    (tmp_path / "doc.md").write_text(md + "\n", encoding="utf-8")
    source = typst_source(tmp_path / "doc.md", {"title": "T", "lang": "en"}, template_dir() / "report.typ").result()
    (tmp_path / "doc.typ").write_text(source + _PASS_PROBE, encoding="utf-8")
    pdf, _ = typst.compile_with_warnings(str(tmp_path / "doc.typ"), root=str(tmp_path), font_paths=typst_fonts())
    with pymupdf.open(stream=pdf, filetype="pdf") as doc:
        text = " ".join(page.get_text() for page in doc)
    passes = re.search(r"PASSES ([\d/ ]+)", text).group(1).split()
    # what the second pass saw of the first: the three figures, anchored and floated
    assert passes[0] == "0/0" and passes[1] == "3/3", passes


def test_a_zh_line_before_a_run_that_does_not_fit_is_not_letter_spaced(tmp_path):
    # the same sentence after a growing number of characters: its boxed formula (about 11 em,
    # unbreakable) falls at every place of a line; where it does not fit, the line before it
    # ends short, set solid (render/unitjoin.py's "#run-break;", templates/report.typ), instead
    # of spreading its characters apart (issue 19 point 2: die_cutter, press, shaper … zh)
    import pymupdf

    paras = [("设计" * k + "动能增量 $\\Delta E(\\varphi) = \\int (M_d - M_b) d\\varphi = 3499.5$ J "
              "的最大值与最小值之差即最大盈亏功，约为一次模切功的百分之八十七。") for k in range(1, 21)]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        pdf = _render(tmp_path, "# 一\n\n" + "\n\n".join(paras) + "\n", lang="zh")
    # the breaks read the line starts of the pass before: the layout settles
    assert [str(w.message)[:80] for w in caught if "converge" in str(w.message)] == []
    assert letter_spaced_lines(pdf) == []
    # the case: some lines end short, well before the right edge, with the formula next
    with pymupdf.open(pdf) as doc:
        ends = [line["bbox"][2] for page in doc for block in page.get_text("dict")["blocks"]
                for line in block.get("lines", []) if "动能增量" in "".join(s["text"] for s in line["spans"])]
    assert any(x < RIGHT - 33 for x in ends), ends


def test_the_cells_of_a_row_grown_by_a_fraction_stand_in_its_middle(tmp_path):
    # a display-size fraction makes its row taller; the plain cells beside it are centred
    # on the row's height (typst sets them at its top unless told), i.e. on the fraction
    import pymupdf

    md = ("# One\n\n| Name | Formula | Value |\n|---|---|--:|\n"
          "| ratio | $i = \\frac{z_2}{z_1}$ | 2.5 |\n| plain | $x$ | 1 |\n\n: Cells {#tbl:c}\n")
    pdf = _render(tmp_path, md)
    with pymupdf.open(pdf) as doc:
        page = next(p for p in doc if "ratio" in p.get_text())
        words = {w[4]: w for w in page.get_text("words")}
        spans = [(ch["c"], ch["bbox"]) for b in page.get_text("rawdict")["blocks"]
                 for ln in b.get("lines", []) for sp in ln["spans"] for ch in sp["chars"]]
    ratio, value = words["ratio"], words["2.5"]
    # the fraction: from the numerator's top to the denominator's bottom
    digits = [bbox for c, bbox in spans if c in "12" and bbox[1] < value[3] + 20 and bbox[3] > ratio[1] - 20
              and bbox[0] < value[0] - 10 and bbox[0] > ratio[2]]
    top, bottom = min(b[1] for b in digits), max(b[3] for b in digits)
    middle = (top + bottom) / 2
    for w in (ratio, value):
        assert abs((w[1] + w[3]) / 2 - middle) < 2.5, (w, top, bottom)


def test_a_figure_after_a_split_table_stays_out_of_its_parts(tmp_path):
    # a table that starts low on a page and goes on to the next, and a figure whose text
    # follows the table: floated to the top of the next page (`auto`, its text in the upper
    # half) it stood between the table's first part and "Table 1 (continued)" (lockbeam
    # tables 34 and 40, die_cutter, shaper, press, slotter, textbook_guide_bar)
    from PIL import Image

    rows = "\n".join(f"| r{k} | {k} |" for k in range(24))
    bad = []
    for lead in (8, 9, 10):
        md = (f"# One\n\n{_FILLER * lead}\n\n| Name | Value |\n|---|--:|\n{rows}\n\n: Long table\n\n"
              f"The table is drawn in Figure 1.\n\n![A figure](a.png){{width=80%}}\n\n{_FILLER * 8}\n")
        (tmp_path / str(lead)).mkdir()
        Image.new("RGB", (800, 300), (200, 220, 240)).save(tmp_path / str(lead) / "a.png")
        pdf = _render(tmp_path / str(lead), md)
        assert continued_missing(pdf) == []
        bad += [(lead, r) for r in tables_interrupted(pdf)]
    assert bad == []


def test_a_figure_before_a_split_table_is_held_past_it(tmp_path):
    # a figure whose text stands before a table that starts low on a page and goes on to
    # the next: it floated to the top of the next page, between the table's first part and
    # "Table 1 (continued)" (or to the foot of the first page, under the first part: die_cutter
    # table 6, linkage_sixbar table 7, cam_7_3 en table 4; TABLES_INTERRUPTED_OPEN). It is
    # held back past the table (templates/report.typ: figure-held), and the layout settles.
    from PIL import Image

    rows = "\n".join(f"| r{k} | {k} |" for k in range(24))
    bad = []
    for lead in (6, 7, 8, 9, 10):
        md = (f"# One\n\n{_FILLER * lead}\n\nThe table is drawn in Figure 1.\n\n"
              f"![A figure](a.png){{width=80%}}\n\n| Name | Value |\n|---|--:|\n{rows}\n\n: Long table\n\n"
              f"{_FILLER * 8}\n")
        (tmp_path / str(lead)).mkdir()
        Image.new("RGB", (800, 500), (200, 220, 240)).save(tmp_path / str(lead) / "a.png")
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            pdf = _render(tmp_path / str(lead), md)
        bad += [(lead, "unsettled") for w in caught if "converge" in str(w.message)]
        assert continued_missing(pdf) == []
        bad += [(lead, r) for r in tables_interrupted(pdf)]
    assert bad == []


def test_a_figure_whose_text_follows_a_split_table_stands_under_its_text(tmp_path):
    # a table goes on from one page to the next, the line after it cites a figure, and the
    # next section begins: set at the page's foot (after-split), the figure stood under the
    # next section's heading and its text, away from the line citing it (press en fig. 7
    # under "4.1.3 Kinetostatics"), or under a blank band (cam_7_3 en p.7). It now stands
    # in the flow under the line citing it, where it fits there.
    import pymupdf
    from PIL import Image

    Image.new("RGB", (800, 500), (200, 220, 240)).save(tmp_path / "a.png")
    rows = "\n".join(f"| {k} | {10 * k} | {k * k} |" for k in range(1, 41))
    md = "\n\n".join([
        "# One\n", _FILLER * 8,
        f"| Position | Angle | Value |\n|---|---|---|\n{rows}\n\n: Values {{#tbl:values}}",
        "The polygons of the last position are drawn in @fig:poly.",
        "![Polygons](a.png){#fig:poly width=60%}",
        "## Next section\n", _FILLER * 6]) + "\n"
    pdf = _render(tmp_path, md)
    with pymupdf.open(pdf) as doc:
        found = {}
        for number, page in enumerate(doc, 1):
            if "Contents" in page.get_text():
                continue
            for block in page.get_text("blocks"):
                text = block[4].strip()
                for key in ("Figure", "Next section", "(continued)"):
                    if text.startswith(key) if key == "Figure" else key in text:
                        found.setdefault(key, (number, block[1]))
    assert "(continued)" in found                       # the case: the table went on
    caption, heading = found["Figure"], found["Next section"]
    assert caption[0] == found["(continued)"][0]        # on the table's last page
    assert caption < heading                            # above the next section
    assert page_holes(pdf) == [] and tables_interrupted(pdf) == []



def test_zh_strong_text_is_set_in_the_sans_face(tmp_path):
    # page review 51: the shipped CJK fonts have the regular weight only, so a zh report's
    # "**题目：**" printed as the text around it (lockbeam zh: "粗体并打 ✓ 者为所选" with
    # nothing bold). Chinese typesetting marks it in the sans face (黑体); en keeps its bold.
    import pymupdf

    md = "# 一\n\n**题目：** 锁梁自动成型机床扳弯机构设计。\n"

    def fonts(lang):
        doc = pymupdf.open(_render(tmp_path, md, lang))
        spans = [s for page in doc for b in page.get_text("dict")["blocks"] for line in b.get("lines", ())
                 for s in line["spans"]]
        return ({s["font"] for s in spans if "题目" in s["text"]},
                {s["font"] for s in spans if "锁梁" in s["text"]})

    strong, plain = fonts("zh")
    assert strong and plain and all("Sans" in f for f in strong) and all("Serif" in f for f in plain)
