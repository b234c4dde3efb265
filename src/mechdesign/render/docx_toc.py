"""The Word report's table of contents written out, page numbers included, for every reader.

templates/docx-numbering.lua writes an empty ``TOC`` field, as pandoc's ``--toc`` does, on a
page after the title page. A reader that does not update fields shows its stored result:
nothing. :func:`fill_table_of_contents` replaces the field by one paragraph per heading of
levels 1–3 (styles TOC 1–3 of reference.docx): the heading's number and text, a dotted leader
to the right margin and a ``PAGEREF`` field of a ``_Toc`` bookmark around the heading, all a
hyperlink to the heading. A ``PAGEREF`` is computed by the reader as it lays out the pages:
LibreOffice shows the right page numbers, and Word updates them on opening (render/docx sets
``w:updateFields``; each field is also marked dirty). Inside a ``TOC`` field LibreOffice would
show a stored page number as it is (there is none to store: the pages are laid out by the
reader), which is why the entries stand outside one; Word's "Update Table" then has no field
to update (References > Table of Contents inserts a new one).
"""
from __future__ import annotations

import re

_TOC_FIELD = re.compile(
    r'<w:p><w:r><w:fldChar w:fldCharType="begin"[^>]*/>'
    r'(<w:instrText[^>]*>TOC [^<]*</w:instrText>)'
    r'<w:fldChar w:fldCharType="separate" /><w:fldChar w:fldCharType="end" /></w:r></w:p>')
_HEADING = re.compile(r'<w:p><w:pPr><w:pStyle w:val="Heading([1-9])" />.*?</w:pPr>(.*?)</w:p>',
                      re.DOTALL)
# (a heading's inline math, "time ratio $K$", holds its letters in m:t runs)
_TEXT = re.compile(r"<([wm]):t(?: [^>]*)?>([^<]*)</\1:t>|<w:tab />")
#: Bookmark ids above pandoc's own (which count from 0).
_BOOKMARK_BASE = 900000


def _heading_text(content: str) -> str:
    """The text of a heading paragraph's runs, as stored (XML-escaped), tabs as spaces."""
    return re.sub(r"\s+", " ", "".join(m.group(2) if m.group(2) is not None else " "
                                       for m in _TEXT.finditer(content))).strip()


def _levels(instruction: str) -> int:
    """Deepest heading level of a ``TOC \\o "1-N"`` instruction (3 if it names none)."""
    found = re.search(r"\\o\s*&quot;1-(\d)&quot;", instruction)
    return int(found.group(1)) if found else 3


def _text_width(document_xml: str) -> int:
    """Width [twips] between the margins of the document's last section (A4 with 2.5 cm
    margins if it names none): the position of the page numbers' right tab."""
    sect = document_xml[document_xml.rfind("<w:sectPr"):]
    page = re.search(r'<w:pgSz\b[^>]*\bw:w="(\d+)"', sect)
    left = re.search(r'<w:pgMar\b[^>]*\bw:left="(\d+)"', sect)
    right = re.search(r'<w:pgMar\b[^>]*\bw:right="(\d+)"', sect)
    if page and left and right and int(page.group(1)) > int(left.group(1)) + int(right.group(1)):
        return int(page.group(1)) - int(left.group(1)) - int(right.group(1))
    return 11906 - 2 * 1418


def fill_table_of_contents(document_xml: str) -> str:
    """``word/document.xml`` with the empty TOC field replaced by an entry per heading (levels
    up to the field's ``\\o``) with its page number, each heading wrapped in a ``_Toc``
    bookmark. Unchanged if there is no empty TOC field."""
    field = _TOC_FIELD.search(document_xml)
    if field is None:
        return document_xml
    depth = _levels(field.group(1))
    head, tail = document_xml[:field.end()], document_xml[field.end():]
    entries: list[tuple[int, str, str]] = []

    def mark(heading: re.Match) -> str:
        level = int(heading.group(1))
        text = _heading_text(heading.group(2))
        if level > depth or not text:
            return heading.group(0)
        n = len(entries) + 1
        name = f"_Toc{n:08d}"
        entries.append((level, name, text))
        start = heading.start(2) - heading.start()
        whole = heading.group(0)
        return (whole[:start] + f'<w:bookmarkStart w:id="{_BOOKMARK_BASE + n}" w:name="{name}" />'
                + whole[start:-len("</w:p>")] + f'<w:bookmarkEnd w:id="{_BOOKMARK_BASE + n}" /></w:p>')

    tail = _HEADING.sub(mark, tail)
    if not entries:
        return document_xml
    tab = (f'<w:tabs><w:tab w:val="right" w:leader="dot" w:pos="{_text_width(document_xml)}" />'
           "</w:tabs>")
    paragraphs = []
    for level, name, text in entries:
        paragraphs.append(
            f'<w:p><w:pPr><w:pStyle w:val="TOC{level}" />{tab}</w:pPr>'
            f'<w:hyperlink w:anchor="{name}" w:history="1">'
            f'<w:r><w:t xml:space="preserve">{text}</w:t></w:r><w:r><w:tab /></w:r>'
            '<w:r><w:fldChar w:fldCharType="begin" w:dirty="true" /></w:r>'
            f'<w:r><w:instrText xml:space="preserve"> PAGEREF {name} \\h </w:instrText></w:r>'
            '<w:r><w:fldChar w:fldCharType="separate" /></w:r>'
            '<w:r><w:fldChar w:fldCharType="end" /></w:r></w:hyperlink></w:p>')
    return head[:field.start()] + "".join(paragraphs) + tail


_BREAK_AFTER_CONTENTS = re.compile(
    r'(</w:sdt>\s*)<w:p><w:r><w:br w:type="page" /></w:r></w:p>(\s*(?:<w:bookmarkStart [^>]*/>\s*)*)'
    r'<w:p>(<w:pPr>(?:<w:pStyle [^>]*/>)?(?:<w:keepNext ?/>)?(?:<w:keepLines ?/>)?)?')


def body_on_a_new_page(document_xml: str) -> str:
    """``word/document.xml`` with the page break after the table of contents (a paragraph
    holding a ``w:br``, templates/docx-numbering.lua) replaced by ``w:pageBreakBefore`` on the
    body's first paragraph. The break's paragraph is a line of its own: on a contents page that
    is full it went to the next page, broke it, and left that page blank (slotter zh, p. 3)."""
    def replace(m: re.Match) -> str:
        ppr = m.group(3)
        ppr = (ppr + "<w:pageBreakBefore />") if ppr else "<w:pPr><w:pageBreakBefore /></w:pPr>"
        return m.group(1) + m.group(2) + "<w:p>" + ppr
    return _BREAK_AFTER_CONTENTS.sub(replace, document_xml, count=1)


__all__ = ["body_on_a_new_page", "fill_table_of_contents"]
