"""The Word report's table of contents filled in before any reader updates it.

The table of contents is an empty ``TOC`` field (templates/docx-numbering.lua writes it, as
pandoc's ``--toc`` does, on a page after the title page); render/docx sets ``w:updateFields``
so that Word fills it when the file is opened. LibreOffice (and a Word whose user declines
the update) shows the field's stored result, empty: a heading with nothing under it.

:func:`fill_table_of_contents` stores a result in the form Word writes: one paragraph per
heading of levels 1–3 (styles TOC 1–3 of reference.docx), the heading's number and text
as a hyperlink to a ``_Toc`` bookmark around the heading. Without the page numbers: they
are known only once a reader lays out the pages (LibreOffice shows a stored ``PAGEREF``
result inside a table of contents as it is, and an empty one as nothing after a dotted
leader); Word recomputes the whole field, page numbers included, on opening.
"""
from __future__ import annotations

import re

_TOC_FIELD = re.compile(
    r'<w:p><w:r><w:fldChar w:fldCharType="begin"[^>]*/>'
    r'(<w:instrText[^>]*>TOC [^<]*</w:instrText>)'
    r'<w:fldChar w:fldCharType="separate" /><w:fldChar w:fldCharType="end" /></w:r></w:p>')
_HEADING = re.compile(r'<w:p><w:pPr><w:pStyle w:val="Heading([1-9])" />.*?</w:pPr>(.*?)</w:p>',
                      re.DOTALL)
_TEXT = re.compile(r"<w:t(?: [^>]*)?>([^<]*)</w:t>|<w:tab />")
#: Bookmark ids above pandoc's own (which count from 0).
_BOOKMARK_BASE = 900000


def _heading_text(content: str) -> str:
    """The text of a heading paragraph's runs, as stored (XML-escaped), tabs as spaces."""
    return re.sub(r"\s+", " ", "".join(m.group(1) if m.group(1) is not None else " "
                                       for m in _TEXT.finditer(content))).strip()


def _levels(instruction: str) -> int:
    """Deepest heading level of a ``TOC \\o "1-N"`` instruction (3 if it names none)."""
    found = re.search(r"\\o\s*&quot;1-(\d)&quot;", instruction)
    return int(found.group(1)) if found else 3


def fill_table_of_contents(document_xml: str) -> str:
    """``word/document.xml`` with the empty TOC field given an entry per heading (levels up to
    the field's ``\\o``), each heading wrapped in a ``_Toc`` bookmark. Unchanged if there is
    no empty TOC field."""
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
    paragraphs = []
    last = len(entries) - 1
    for n, (level, name, text) in enumerate(entries):
        opening = ('<w:r><w:fldChar w:fldCharType="begin" w:dirty="true" /></w:r>'
                   f"<w:r>{field.group(1)}</w:r>"
                   '<w:r><w:fldChar w:fldCharType="separate" /></w:r>') if n == 0 else ""
        paragraphs.append(
            f'<w:p><w:pPr><w:pStyle w:val="TOC{level}" /></w:pPr>{opening}'
            f'<w:hyperlink w:anchor="{name}" w:history="1">'
            f'<w:r><w:t xml:space="preserve">{text}</w:t></w:r></w:hyperlink>'
            # the field ends in the last entry: an empty paragraph of its own could be the
            # one line that spills onto a page after a full contents page
            + ('<w:r><w:fldChar w:fldCharType="end" /></w:r>' if n == last else "") + "</w:p>")
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
