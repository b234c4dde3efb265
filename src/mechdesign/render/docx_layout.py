"""Page and line breaks of the Word report that pandoc leaves to the reader.

:func:`keep_table_rows`
    pandoc writes table rows that may break across a page, so that a cell's word is cut in
    two ("实际中心距" into "…中心" / "距", slotter zh), and a short table may leave its first
    row alone at a page foot. Every row of a data table gets ``w:cantSplit``; a table of at
    most :data:`SHORT_TABLE_ROWS` rows is kept on one page (``w:keepNext`` on the
    paragraphs of every row but the last, as Word's "keep with next" does). A longer table
    may break between rows, but leaves at least :data:`~.pdf.KEEP_ROWS` body rows on each
    side of the break, as the PDF does (issue 19 point 2; LibreOffice left one or two rows
    at a page foot or on the next page: linkage_sixbar zh tables 14, 15, 22 and 23): its
    header and first rows, and its last rows, are kept together the same way.
    (pandoc already marks the header row ``w:tblHeader``: repeated on each page.)
:func:`keep_lead_ins`
    A paragraph ending in a colon ("导杆长度、曲柄长度、连杆长度：", "…T = 9550 P/n:") introduces
    the formula, table or list after it; pandoc lets a page end under it (51 such page feet
    in the 28 example reports laid out by LibreOffice). It is kept with the next block
    (``w:keepNext``), as the PDF keeps it (templates/report.typ).
:func:`split_inline_formula_lists`
    An inline formula is one unbreakable object for LibreOffice: a list of them in one
    formula, "$C_v = 2.000, C_a = 4.000, C_j = ∞$", goes to the next line as a whole and the
    justified line before it is letter-spaced ("推 程 0°–70°： 等 加 速 …"). The formula is
    cut at its top-level commas into one formula per item, with ", " as text between them.
:func:`centre_tables`
    pandoc writes a data table narrower than the text without ``w:jc``: Word and LibreOffice
    set it at the left margin, under its centred caption (the PDF centres it). Every table
    without an alignment is centred.
:func:`separate_tables`
    A numbered display formula is a table of its own (templates/docx-numbering.lua); right
    after a data table the two tables touch, and Word shows touching tables as one table
    under the first one's table properties (pandoc issue 4315, python-docx issue 1072).
    Touching tables of different styles are kept apart by an empty paragraph of 6 pt.
    (LibreOffice 7 kept them apart and centred the formula on the text block: the formula
    "right of centre" of review36, shaper zh (12)–(15), was right of the left-set table.)
:func:`keep_headings_with_text`
    A heading's style keeps it with the next paragraph only (reference.docx: w:keepNext),
    and Word's widow control lets that paragraph leave two lines under it: a heading stood
    at a page foot over one or two rows of its text, its section on the next page
    ("References" and the first two-line reference, "8.6 Stage 3…" and two lines of a
    paragraph; LibreOffice's layout of die_cutter, shaper, slotter en). The PDF keeps 9 em
    of its section with a heading (templates/report.typ keep-room). The blocks after a
    heading are kept with it until :data:`HEADING_ROWS` rows of text are: a short
    paragraph (at most :data:`WHOLE_LINES` lines, estimated) is kept whole
    (``w:keepLines``) and, while the rows are fewer, with the next block (``w:keepNext``);
    one that a heading follows is kept with it too, whatever the rows: the estimate is of
    whole lines, and shaper en's purpose paragraph under "7 Cam mechanism", estimated three
    lines, took two in LibreOffice, and the heading stood over them at the foot of p.23 with
    "7.1" and its table on p.24;
    a numbered formula the same: written as one paragraph (:func:`formula_paragraph`: the
    formula on a centre tab stop, its number on a right one), since LibreOffice 7.4 keeps no
    table with the next block (its import gives a table no keep; Word keeps a table whose
    paragraphs are all ``w:keepNext``): "5.2.1 Velocities", its scale and formula (30) stood
    at the foot of crank_rocker en p.12 with the table after them on p.13 (die_cutter,
    furnace_pusher, textbook_guide_bar en likewise). A formula with a fraction, a sum, a stack
    or a matrix, which Word sets smaller in a line, stays a table kept on all its paragraphs.
    A caption, a figure, a data table or another heading ends the run: each is kept with its
    own content already.
"""
from __future__ import annotations

import re

from .pdf import KEEP_ROWS, UNBREAKABLE_ROWS

#: A table of at most this many rows (header included) is kept on one page, as the PDF keeps
#: one of at most UNBREAKABLE_ROWS body rows (render/pdf.py). 15 rows kept whole left up to
#: a third of a page empty (review36 Top 14: shaper zh p.10 ended at 70 %, its table 7 of
#: 14 rows went to p.11 whole).
SHORT_TABLE_ROWS = UNBREAKABLE_ROWS + 1

_TABLE = re.compile(r"<w:tbl>.*?</w:tbl>", re.DOTALL)     # pandoc's tables are not nested
_ROW = re.compile(r"<w:tr>(?:<w:trPr>(.*?)</w:trPr>)?", re.DOTALL)
_PPR = re.compile(r"<w:pPr>((?:<w:pStyle [^>]*/>)?)")


def _keep_with_next(row: str) -> str:
    """Every paragraph of a row given ``w:keepNext`` (after its style: the schema's order)."""
    row = re.sub(r"<w:p>(?!<w:pPr>)", "<w:p><w:pPr></w:pPr>", row)
    return _PPR.sub(lambda m: m.group(0) if "<w:keepNext" in m.group(0)
                    else f"<w:pPr>{m.group(1)}<w:keepNext />", row)


def _keep_table(table: str) -> str:
    if '<w:tblStyle w:val="EquationTable" />' in table:     # a numbered formula: one row, kept
        return table

    def cant_split(m: re.Match) -> str:
        pr = m.group(1) or ""
        if "<w:cantSplit" in pr:
            return m.group(0)
        return f"<w:tr><w:trPr><w:cantSplit />{pr}</w:trPr>"
    table = _ROW.sub(cant_split, table)
    rows = [m.start() for m in re.finditer(r"<w:tr>", table)]
    if len(rows) <= 1:
        return table
    if len(rows) <= SHORT_TABLE_ROWS:
        return table[:rows[0]] + _keep_with_next(table[rows[0]:rows[-1]]) + table[rows[-1]:]
    # the header row and the first KEEP_ROWS body rows together; the last KEEP_ROWS rows
    # together (a longer table than SHORT_TABLE_ROWS: the two groups do not meet)
    head, tail = rows[KEEP_ROWS], rows[-KEEP_ROWS]
    return (table[:rows[0]] + _keep_with_next(table[rows[0]:head]) + table[head:tail]
            + _keep_with_next(table[tail:rows[-1]]) + table[rows[-1]:])


def keep_table_rows(document_xml: str) -> str:
    """``word/document.xml`` with no table row split across pages and short tables on one
    page (see the module's docstring)."""
    return _TABLE.sub(lambda m: _keep_table(m.group(0)), document_xml)


_DISPLAY_MATH = re.compile(r"(<m:oMathPara>.*?</m:oMathPara>)", re.DOTALL)
_INLINE_MATH = re.compile(r"<m:oMath>(.*?)</m:oMath>", re.DOTALL)
_TAG = re.compile(r"<(/?)(m:[A-Za-z]+)\b[^>]*?(/?)>")
_COMMA = re.compile(r'<m:r><m:rPr><m:sty m:val="p" /></m:rPr><m:t>,</m:t></m:r>')
_OPENING, _CLOSING = "([{", ")]}"


def _top_level_commas(body: str) -> list[re.Match]:
    """The comma runs of a formula's body that are its direct children and stand outside
    any bracket written as a run ("f(x, y)" keeps its comma)."""
    depth, brackets, found = 0, 0, []
    commas = {m.start(): m for m in _COMMA.finditer(body)}
    for tag in _TAG.finditer(body):
        if depth == 0 and tag.start() in commas and brackets == 0:
            found.append(commas[tag.start()])
        if tag.group(3):
            continue
        if tag.group(1):
            depth -= 1
        else:
            depth += 1
            if depth == 1 and tag.group(2) == "m:r":
                text = re.match(r"<m:r>(?:<m:rPr>.*?</m:rPr>)?<m:t[^>]*>([^<]*)</m:t>",
                                body[tag.start():], re.DOTALL)
                if text:
                    brackets += sum(text.group(1).count(c) for c in _OPENING)
                    brackets -= sum(text.group(1).count(c) for c in _CLOSING)
    return found


def split_inline_formula_lists(document_xml: str) -> str:
    """Each inline formula (an ``m:oMath`` outside ``m:oMathPara``) that lists items at its
    top-level commas written as one formula per item with a text ", " between them."""
    def split(m: re.Match) -> str:
        body = m.group(1)
        commas = _top_level_commas(body)
        if not commas:
            return m.group(0)
        pieces, start = [], 0
        for comma in commas:
            pieces.append(body[start:comma.start()])
            start = comma.end()
        pieces.append(body[start:])
        if any(not piece.strip() for piece in pieces):
            return m.group(0)
        glue = '</m:oMath><w:r><w:t xml:space="preserve">, </w:t></w:r><m:oMath>'
        return "<m:oMath>" + glue.join(pieces) + "</m:oMath>"
    parts = _DISPLAY_MATH.split(document_xml)     # odd indices: display formulas, kept
    return "".join(part if k % 2 else _INLINE_MATH.sub(split, part) for k, part in enumerate(parts))


#: The text that follows an inline formula and may not start a line (closing brackets and
#: punctuation, GB/T 15834 and the kinsoku rules): "（$J \propto 1/n^2$）", "（峰值系数 $… C_j = 60.00$）".
_AFTER_FORMULA = re.compile(r'</m:oMath>(<w:r>(?:<w:rPr>(?:(?!</w:rPr>).)*</w:rPr>)?<w:t(?: xml:space="preserve")?>)'
                            r'([）)\]】」』，。、；：！？]+)', re.DOTALL)
#: An opening bracket right before an inline formula, which may not end a line either ("小（"
#: at a line end, "J ∝ 1/n²）" on the next).
_BEFORE_FORMULA = re.compile(r'(<w:t(?: xml:space="preserve")?>[^<]*?)([（(\[【「『]+)</w:t></w:r><m:oMath>')


def keep_closing_marks_with_formulas(document_xml: str) -> str:
    """A closing bracket or punctuation mark right after an inline formula moved into the
    formula's end as a normal-text run, an opening bracket right before it into its start: LibreOffice (and Word at a narrow cell) may break a
    line between an inline formula and the text after it, and left "）" alone at the start of
    the next line (review 38: the cam laws' "(peak coefficients …)", die_cutter's data table
    "（$J \\propto 1/n^2$）"). Display formulas are left as they are."""
    def move(m: re.Match) -> str:
        marks = m.group(2)
        return (f'<m:r><m:rPr><m:nor /><m:sty m:val="p" /></m:rPr><m:t>{marks}</m:t></m:r></m:oMath>'
                + m.group(1))

    def move_opening(m: re.Match) -> str:
        return (m.group(1) + '</w:t></w:r><m:oMath><m:r><m:rPr><m:nor /><m:sty m:val="p" /></m:rPr>'
                f'<m:t>{m.group(2)}</m:t></m:r>')
    parts = _DISPLAY_MATH.split(document_xml)     # odd indices: display formulas, kept
    return "".join(part if k % 2 else _BEFORE_FORMULA.sub(move_opening, _AFTER_FORMULA.sub(move, part))
                   for k, part in enumerate(parts))


__all__ = ["HEADING_ROWS", "SHORT_TABLE_ROWS", "keep_closing_marks_with_formulas", "keep_headings_with_text",
           "keep_lead_ins", "keep_references_together", "keep_table_rows", "split_inline_formula_lists"]


_TBL_PR = re.compile(r"<w:tbl><w:tblPr>(.*?)</w:tblPr>", re.DOTALL)
#: the children of w:tblPr that come before w:jc (ECMA-376 Part 1, §17.4.60, CT_TblPr)
_BEFORE_JC = re.compile(r"(?:<w:(?:tblStyle|tblpPr|tblOverlap|bidiVisual|tblStyleRowBandSize|"
                        r"tblStyleColBandSize|tblW)\b[^>]*/>)*")


def centre_tables(document_xml: str) -> str:
    """Every table without an alignment of its own centred between the margins
    (``<w:jc w:val="center" />`` in its w:tblPr, in the schema's order)."""
    def centre(m: re.Match) -> str:
        pr = m.group(1)
        if "<w:jc " in pr:
            return m.group(0)
        k = _BEFORE_JC.match(pr).end()
        return f'<w:tbl><w:tblPr>{pr[:k]}<w:jc w:val="center" />{pr[k:]}</w:tblPr>'
    return _TBL_PR.sub(centre, document_xml)


#: An empty paragraph of 6 pt (a line of exactly 6 pt, no spacing, a 1 pt mark) between two
#: tables: the formula stands a little below the table's bottom rule, as below text.
TABLE_SEPARATOR = ('<w:p><w:pPr><w:spacing w:before="0" w:after="0" w:line="120" w:lineRule="exact" />'
                   '<w:rPr><w:sz w:val="2" /><w:szCs w:val="2" /></w:rPr></w:pPr></w:p>')
_STYLE = re.compile(r'<w:tbl><w:tblPr><w:tblStyle w:val="([^"]*)"')
# a table's end, then only bookmarks and white space, then the next table
_TOUCHING = re.compile(r"</w:tbl>((?:\s|<w:bookmark(?:Start|End)\b[^>]*/>)*)(?=<w:tbl>)")


def separate_tables(document_xml: str) -> str:
    """An empty paragraph of 6 pt (:data:`TABLE_SEPARATOR`) between two touching tables of
    different styles (a data table and the numbered formula after it), so that Word does
    not join them into one table; touching formulas (one table style) stay as they are."""
    def style_at(end: int) -> str:
        m = _STYLE.match(document_xml, end)
        return m.group(1) if m else ""

    def style_before(start: int) -> str:
        k = document_xml.rfind("<w:tbl>", 0, start)
        m = _STYLE.match(document_xml, k) if k >= 0 else None
        return m.group(1) if m else ""

    def one(m: re.Match) -> str:
        if style_before(m.start()) == style_at(m.end()):
            return m.group(0)
        return "</w:tbl>" + TABLE_SEPARATOR + m.group(1)
    return _TOUCHING.sub(one, document_xml)


_BODY_PARAGRAPH = re.compile(r"<w:p>(?:(?!</w:p>).)*</w:p>", re.DOTALL)
_TEXT = re.compile(r"<(?:w|m):t(?:\s[^>]*)?>([^<]*)</(?:w|m):t>")


def keep_lead_ins(document_xml: str) -> str:
    """Every paragraph outside a table whose text ends in "：" or ":" given ``w:keepNext``
    (a program listing's lines are left as they are)."""
    def lead_in(m: re.Match) -> str:
        para = m.group(0)
        if '<w:pStyle w:val="SourceCode"' in para:
            return para
        text = "".join(_TEXT.findall(para)).rstrip()
        if not text.endswith(("：", ":")) or "<w:keepNext" in para:
            return para
        return _keep_with_next(para)
    parts = _TABLE.split(document_xml)
    tables = _TABLE.findall(document_xml)
    out = [_BODY_PARAGRAPH.sub(lead_in, parts[0])]
    for table, part in zip(tables, parts[1:]):
        out += [table, _BODY_PARAGRAPH.sub(lead_in, part)]
    return "".join(out)


#: Rows of text a heading keeps with it on its page (tests/test_typeset.py MIN_ROWS: a heading
#: with fewer rows under it at a page foot is a defect).
HEADING_ROWS = 3
#: A paragraph after a heading of at most this many lines (estimated) is kept whole; a
#: longer one may leave two lines under the heading (Word's widow control).
WHOLE_LINES = 6
#: Width of a body line [em of the 12 pt body text]: A4 with 2.5 cm margins, 453.5 pt.
_LINE_EM = 453.5 / 12.0
_BLOCK = re.compile(r"<w:tbl>.*?</w:tbl>|<w:p>(?:(?!</w:p>).)*</w:p>|<w:p\s*/>", re.DOTALL)
_STYLE_OF = re.compile(r'<w:pStyle w:val="([^"]*)"')
#: paragraphs that end a heading's run: kept with their own table or figure, or a heading
_OWN_KEEP = re.compile(r"Heading\d|TableCaption|ImageCaption|CaptionedFigure|Figure|SourceCode")


def _lines(paragraph: str) -> int:
    """Lines of a body paragraph, estimated: a CJK character 1 em, any other 0.5 em, the
    first-line indent 2 em."""
    text = "".join(_TEXT.findall(paragraph))
    if not text.strip():
        return 0
    em = 2.0 + sum(1.0 if ord(c) >= 0x2E80 else 0.5 for c in text)
    return max(1, -int(-em // _LINE_EM))


def _keep_lines(paragraph: str) -> str:
    """``paragraph`` given ``w:keepLines`` (after w:keepNext: the schema's order)."""
    if "<w:keepLines" in paragraph:
        return paragraph
    if "<w:keepNext />" in paragraph:
        return paragraph.replace("<w:keepNext />", "<w:keepNext /><w:keepLines />", 1)
    if not paragraph.startswith("<w:p><w:pPr>"):
        paragraph = paragraph.replace("<w:p>", "<w:p><w:pPr></w:pPr>", 1)
    return _PPR.sub(lambda m: f"<w:pPr>{m.group(1)}<w:keepLines />", paragraph, count=1)


def _heading_follows(blocks: list[re.Match], j: int) -> bool:
    """Whether the next block after ``blocks[j]`` with text (past empty paragraphs) is a heading."""
    for m in blocks[j + 1:]:
        block = m.group(0)
        style = _STYLE_OF.search(block[:300])
        if style and re.fullmatch(r"Heading\d", style.group(1)):
            return True
        if block.startswith("<w:tbl>") or _lines(block):
            return False
    return False


def keep_headings_with_text(document_xml: str) -> str:
    """The blocks after every heading of the body kept with it until it has
    :data:`HEADING_ROWS` rows of text (see the module's docstring)."""
    blocks = list(_BLOCK.finditer(document_xml))
    new: dict[int, str] = {}
    for k, m in enumerate(blocks):
        style = _STYLE_OF.search(m.group(0)[:300])
        if not (m.group(0).startswith("<w:p>") and style and re.fullmatch(r"Heading\d", style.group(1))):
            continue
        rows = 0
        for j in range(k + 1, len(blocks)):
            block = blocks[j].group(0)
            if block.startswith("<w:tbl>"):
                if '<w:tblStyle w:val="EquationTable" />' not in block:
                    break
                rows += len(_rows_of(block))
                if rows >= HEADING_ROWS:
                    break
                new[j] = formula_paragraph(block) or _keep_with_next(block)
                continue
            style = _STYLE_OF.search(block[:300])
            if style and _OWN_KEEP.fullmatch(style.group(1)):
                break
            lines = _lines(block)
            if lines == 0:
                continue                      # an empty paragraph (a table separator)
            if lines > WHOLE_LINES:
                break
            block = _keep_lines(block)
            rows += lines
            if (rows < HEADING_ROWS or _heading_follows(blocks, j)) and "<w:keepNext" not in block:
                block = _keep_with_next(block)
            new[j] = block
            if rows >= HEADING_ROWS:
                break
    if not new:
        return document_xml
    out, start = [], 0
    for j in sorted(new):
        out += [document_xml[start:blocks[j].start()], new[j]]
        start = blocks[j].end()
    return "".join(out) + document_xml[start:]


#: OMML whose inline form is not its display form: a fraction, a sum or integral, a stack of
#: lines, a matrix, limits under or over (Word sets them smaller or to the side in a line)
_DISPLAY_ONLY = re.compile(r"<m:(?:f|nary|eqArr|m|limLow|limUpp|groupChr|borderBox)\b")
_CELL = re.compile(r"<w:tc>.*?</w:tc>", re.DOTALL)
_PARA_BODY = re.compile(r"<w:p>(?:<w:pPr>.*?</w:pPr>)?(.*)</w:p>", re.DOTALL)


def formula_paragraph(table: str) -> str | None:
    """A numbered formula's table (one row: an empty cell, the formula, its number) as one
    paragraph kept with the next block (``w:keepNext``, ``w:keepLines``): the formula centred
    on a centre tab stop, its number on a right tab stop at the text's edge. LibreOffice (7.4)
    keeps a paragraph with the next block but not a table (its import gives a table no keep:
    the formula under a heading was left at a page foot, the table after it on the next page),
    so a formula that a heading's run keeps with the block after it is written as a paragraph,
    which Word and LibreOffice both keep. None when the formula looks otherwise inline than
    displayed (:data:`_DISPLAY_ONLY`) or the table is not of that form: it stays a table."""
    cells = _CELL.findall(table)
    if len(_rows_of(table)) != 1 or len(cells) != 3:
        return None
    formula = re.findall(r"<w:p>.*?</w:p>", cells[1], flags=re.DOTALL)
    number = re.findall(r"<w:p>.*?</w:p>", cells[2], flags=re.DOTALL)
    if len(formula) != 1 or len(number) != 1 or _DISPLAY_ONLY.search(formula[0]):
        return None
    math = re.fullmatch(r"\s*<m:oMathPara>(?:<m:oMathParaPr>.*?</m:oMathParaPr>)?(<m:oMath>.*</m:oMath>)"
                        r"</m:oMathPara>\s*", _PARA_BODY.fullmatch(formula[0]).group(1), flags=re.DOTALL)
    if math is None or math.group(1).count("<m:oMath>") != 1:
        return None
    width = sum(int(w) for w in re.findall(r'<w:gridCol w:w="(\d+)"', table))   # the text's [twips]
    tabs = (f'<w:tabs><w:tab w:val="center" w:pos="{width // 2}" />'
            f'<w:tab w:val="right" w:pos="{width}" /></w:tabs>')
    return (f'<w:p><w:pPr><w:pStyle w:val="Equation" /><w:keepNext /><w:keepLines />{tabs}'
            f'<w:jc w:val="left" /></w:pPr><w:r><w:tab /></w:r>{math.group(1)}<w:r><w:tab /></w:r>'
            f"{_PARA_BODY.fullmatch(number[0]).group(1)}</w:p>")


def _rows_of(table: str) -> list[str]:
    return re.findall(r"<w:tr>.*?</w:tr>", table, flags=re.DOTALL)


#: A reference list of at most this many entries is kept on one page with its heading.
REFERENCES_WHOLE = 16
#: A longer list keeps at least this many entries on its last page.
REFERENCES_LAST = 4
_REFERENCES = re.compile(r'(<w:bookmarkStart w:id="(\d+)" w:name="references" />)(.*?)(<w:bookmarkEnd w:id="\2" />)',
                         re.DOTALL)
_PARAGRAPH = re.compile(r"<w:p>(?:<w:pPr>(.*?)</w:pPr>)?", re.DOTALL)


def _kept(ppr: str) -> str:
    """Paragraph properties with ``w:keepNext`` and ``w:keepLines`` (after ``w:pStyle``, in
    the schema's order)."""
    style = re.match(r"<w:pStyle [^>]*/>", ppr)
    head = style.group(0) if style else ""
    rest = ppr[len(head):].replace("<w:keepNext />", "").replace("<w:keepLines />", "")
    return f"<w:p><w:pPr>{head}<w:keepNext /><w:keepLines />{rest}</w:pPr>"


def keep_references_together(document_xml: str) -> str:
    """The reference list (pandoc's section bookmarked "references") kept with its heading on
    one page when it has at most :data:`REFERENCES_WHOLE` entries, else its last
    :data:`REFERENCES_LAST` entries together: the last page of a report never holds one to
    three references alone (review 38: die_cutter en's last Word page held [9]–[11])."""
    def keep(m: re.Match) -> str:
        body = m.group(3)
        paras = list(_PARAGRAPH.finditer(body))
        if len(paras) < 2:
            return m.group(0)
        kept = paras[:-1] if len(paras) - 1 <= REFERENCES_WHOLE else paras[-REFERENCES_LAST:-1]
        out, last = [], 0
        for p in kept:
            out.append(body[last:p.start()])
            out.append(_kept(p.group(1) or ""))
            last = p.end()
        out.append(body[last:])
        return m.group(1) + "".join(out) + m.group(4)
    return _REFERENCES.sub(keep, document_xml)
