"""Build ``templates/reference.docx``, the Word style sheet of the .docx report.

Usage::

    python tools/make_reference_docx.py [OUTPUT]      # default: templates/reference.docx

Starts from pandoc's own default reference document (``pandoc
--print-default-data-file reference.docx``, pandoc from ``pypandoc_binary``)
and patches it with :mod:`zipfile` and :mod:`xml.etree` (no python-docx):

* fonts: body text Times New Roman + 宋体 (SimSun), headings and titles
  Arial + 黑体 (SimHei), set explicitly in ``w:rFonts`` (``w:ascii``,
  ``w:hAnsi``, ``w:eastAsia``) instead of theme fonts; the theme and the font
  table are patched to match;
* sizes: body 小四 12 pt (lines at least 20 pt apart, first-line indent of
  two characters; see BODY_SPACING), headings 16/14/12 pt bold, tables and captions 五号 10.5 pt;
* tables: three-line table style (heavy top/bottom rule, light rule under the
  header row, header bold), centred; borderless styles for figure and
  equation layout tables; paragraph styles used by
  ``templates/docx-numbering.lua`` (Equation, Equation Number, Title Info,
  Table Text, and Table Text Small / Smaller at 9 / 7.5 pt for wide tables) and by
  ``render/docx_toc.py`` (toc 1-3);
* page: A4, 2.5 cm margins, page number centred in the footer and the report's
  title and the student (TITLE and AUTHOR fields) right-aligned in the header
  (neither on the title page).

The output is byte-for-byte reproducible for a given pandoc version (fixed
zip timestamps and member order).  Students may edit the produced file in
Word instead (Modify Style ...) -- pandoc only uses its styles, page setup,
header and footer.
"""

from __future__ import annotations

import re
import subprocess
import sys
import zipfile
import xml.etree.ElementTree as ET
from pathlib import Path

W_NS = "http://schemas.openxmlformats.org/wordprocessingml/2006/main"
R_NS = "http://schemas.openxmlformats.org/officeDocument/2006/relationships"
W = f"{{{W_NS}}}"

SERIF = ("Times New Roman", "宋体")  # Latin, East Asian
SANS = ("Arial", "黑体")

# A4 in twips (1/1440 in) and 2.5 cm margins.
PAGE_W, PAGE_H = 11906, 16838
MARGIN = 1418
HEADER, FOOTER = 851, 992

DEFAULT_OUT = Path(__file__).resolve().parents[1] / "templates" / "reference.docx"


def pandoc_default_reference() -> bytes:
    """pandoc's built-in reference.docx (bytes)."""
    import pypandoc

    return subprocess.run(
        [pypandoc.get_pandoc_path(), "--print-default-data-file", "reference.docx"],
        check=True, capture_output=True,
    ).stdout


def rfonts(fonts: tuple[str, str]) -> str:
    latin, east = fonts
    return (f'<w:rFonts w:ascii="{latin}" w:hAnsi="{latin}" w:eastAsia="{east}" '
            f'w:cs="{latin}" />')


def _size(half_points: int) -> str:
    return f'<w:sz w:val="{half_points}" /><w:szCs w:val="{half_points}" />'


def _pstyle(style_id: str, name: str, *, based_on: str | None = "Normal", next_: str | None = None,
            custom: bool = False, ppr: str = "", rpr: str = "", extra: str = "") -> str:
    attrs = ' w:customStyle="1"' if custom else ""
    parts = [f'<w:style w:type="paragraph"{attrs} w:styleId="{style_id}">',
             f'<w:name w:val="{name}" />']
    if based_on:
        parts.append(f'<w:basedOn w:val="{based_on}" />')
    if next_:
        parts.append(f'<w:next w:val="{next_}" />')
    parts.append(extra or "<w:qFormat />")
    if ppr:
        parts.append(f"<w:pPr>{ppr}</w:pPr>")
    if rpr:
        parts.append(f"<w:rPr>{rpr}</w:rPr>")
    parts.append("</w:style>")
    return "".join(parts)


def _cstyle(style_id: str, name: str, link: str, rpr: str) -> str:
    return (f'<w:style w:type="character" w:customStyle="1" w:styleId="{style_id}">'
            f'<w:name w:val="{name}" /><w:basedOn w:val="DefaultParagraphFont" />'
            f'<w:link w:val="{link}" /><w:rPr>{rpr}</w:rPr></w:style>')


def _borders(tag: str, **sides: str) -> str:
    """``<w:tblBorders>``/``<w:tcBorders>`` with ``side="val:size"`` entries."""
    inner = ""
    for side, spec in sides.items():
        val, _, size = spec.partition(":")
        if val in ("nil", "none"):
            inner += f'<w:{side} w:val="nil" />'
        else:
            inner += f'<w:{side} w:val="{val}" w:sz="{size}" w:space="0" w:color="000000" />'
    return f"<w:{tag}>{inner}</w:{tag}>"


NO_BORDERS = dict(top="nil", left="nil", bottom="nil", right="nil", insideH="nil", insideV="nil")

#: Body text lines at least 20 pt apart (固定值/最小值 20 磅, the usual line pitch of 小四 text),
#: taller where an inline formula needs it. "1.5 lines" (w:line="360" auto) multiplied the
#: line height of whatever font stands in for 宋体: 26 pt a line with LibreOffice's Noto Sans
#: CJK (1.45 em), 20.7 pt for Times New Roman, so that a zh Word report ran to a quarter more
#: pages than its en twin (review36 Top 14: shaper zh 48 pages against 38 in the PDF).
BODY_SPACING = '<w:spacing w:before="0" w:after="0" w:line="400" w:lineRule="atLeast" />'
SINGLE = '<w:spacing w:before="0" w:after="0" w:line="240" w:lineRule="auto" />'


def _heading(level: int, size: int, before: int, after: int) -> str:
    ppr = (f'<w:keepNext /><w:keepLines /><w:spacing w:before="{before}" w:after="{after}" '
           f'w:line="240" w:lineRule="auto" /><w:ind w:firstLine="0" /><w:jc w:val="left" />'
           f'<w:outlineLvl w:val="{level - 1}" />')
    rpr = rfonts(SANS) + "<w:b /><w:bCs />" + '<w:color w:val="000000" />' + _size(size)
    extra = '<w:link w:val="Heading%dChar" /><w:uiPriority w:val="9" />%s<w:qFormat />' % (
        level, "" if level == 1 else "<w:unhideWhenUsed />")
    return (_pstyle(f"Heading{level}", f"heading {level}", next_="BodyText", ppr=ppr, rpr=rpr,
                    extra=extra)
            + _cstyle(f"Heading{level}Char", f"Heading {level} Char", f"Heading{level}", rpr))


def replacement_styles() -> dict[str, str]:
    """New definitions (XML) of paragraph, character and table styles, by style id."""
    styles: dict[str, str] = {}
    styles["Normal"] = (
        '<w:style w:type="paragraph" w:default="1" w:styleId="Normal"><w:name w:val="Normal" />'
        f'<w:qFormat /><w:pPr><w:widowControl /><w:overflowPunct w:val="0" />{SINGLE}</w:pPr>'
        f"<w:rPr>{rfonts(SERIF)}</w:rPr></w:style>")
    body_ppr = BODY_SPACING + '<w:ind w:firstLine="480" /><w:jc w:val="both" />'
    styles["BodyText"] = _pstyle("BodyText", "Body Text", ppr=body_ppr,
                                 extra='<w:link w:val="BodyTextChar" /><w:qFormat />')
    styles["FirstParagraph"] = _pstyle("FirstParagraph", "First Paragraph", based_on="BodyText",
                                       next_="BodyText", custom=True)
    # tight lists and (unless styled otherwise) table cells
    styles["Compact"] = _pstyle("Compact", "Compact", based_on="BodyText", custom=True,
                                ppr='<w:spacing w:before="36" w:after="36" w:line="300" '
                                    'w:lineRule="auto" /><w:ind w:firstLine="0" />')
    title_ppr = ('<w:keepNext /><w:spacing w:before="2400" w:after="480" w:line="240" '
                 'w:lineRule="auto" /><w:ind w:firstLine="0" /><w:jc w:val="center" />')
    title_rpr = rfonts(SANS) + "<w:b /><w:bCs />" + _size(44)
    styles["Title"] = _pstyle("Title", "Title", next_="BodyText", ppr=title_ppr, rpr=title_rpr,
                              extra='<w:link w:val="TitleChar" /><w:uiPriority w:val="10" /><w:qFormat />')
    styles["TitleChar"] = _cstyle("TitleChar", "Title Char", "Title", title_rpr)
    sub_ppr = ('<w:keepNext /><w:spacing w:before="0" w:after="1200" w:line="240" '
               'w:lineRule="auto" /><w:ind w:firstLine="0" /><w:jc w:val="center" />')
    sub_rpr = rfonts(SANS) + _size(32)
    styles["Subtitle"] = _pstyle("Subtitle", "Subtitle", next_="BodyText", ppr=sub_ppr, rpr=sub_rpr,
                                 extra='<w:link w:val="SubtitleChar" /><w:uiPriority w:val="11" /><w:qFormat />')
    styles["SubtitleChar"] = _cstyle("SubtitleChar", "Subtitle Char", "Subtitle", sub_rpr)
    for sid, name in (("Author", "Author"), ("Date", "Date")):
        styles[sid] = _pstyle(sid, name, next_="BodyText", custom=(sid == "Author"),
                              ppr='<w:keepNext /><w:spacing w:before="0" w:after="240" />'
                                  '<w:ind w:firstLine="0" /><w:jc w:val="center" />',
                              rpr=_size(28))
    # the student / class / supervisor / date lines under the title (Lua filter)
    styles["TitleInfo"] = _pstyle("TitleInfo", "Title Info", custom=True,
                                  ppr='<w:keepNext /><w:spacing w:before="0" w:after="200" '
                                      'w:line="240" w:lineRule="auto" /><w:ind w:firstLine="0" />'
                                      '<w:jc w:val="center" />',
                                  rpr=_size(28))
    for level, size, before, after in ((1, 32, 480, 240), (2, 28, 360, 180), (3, 24, 240, 120),
                                       (4, 24, 240, 120), (5, 24, 120, 60), (6, 24, 120, 60),
                                       (7, 24, 120, 60), (8, 24, 120, 60), (9, 24, 120, 60)):
        both = _heading(level, size, before, after)
        cut = both.index('<w:style w:type="character"')
        styles[f"Heading{level}"] = both[:cut]
        styles[f"Heading{level}Char"] = both[cut:]
    caption_rpr = _size(21)
    styles["Caption"] = _pstyle("Caption", "caption", ppr=(
        '<w:spacing w:before="60" w:after="240" w:line="240" w:lineRule="auto" />'
        '<w:ind w:firstLine="0" /><w:jc w:val="center" />'), rpr=caption_rpr,
        extra="<w:qFormat />")
    styles["TableCaption"] = _pstyle("TableCaption", "Table Caption", based_on="Caption", custom=True,
                                     ppr='<w:keepNext /><w:spacing w:before="240" w:after="60" />')
    styles["ImageCaption"] = _pstyle("ImageCaption", "Image Caption", based_on="Caption", custom=True)
    styles["Figure"] = _pstyle("Figure", "Figure", custom=True, ppr=(
        '<w:spacing w:before="240" w:after="0" w:line="240" w:lineRule="auto" />'
        '<w:ind w:firstLine="0" /><w:jc w:val="center" />'))
    styles["CaptionedFigure"] = _pstyle("CaptionedFigure", "Captioned Figure", based_on="Figure",
                                        custom=True, ppr="<w:keepNext />")
    styles["Equation"] = _pstyle("Equation", "Equation", custom=True, ppr=(
        '<w:spacing w:before="60" w:after="60" w:line="240" w:lineRule="auto" />'
        '<w:ind w:firstLine="0" /><w:jc w:val="center" />'))
    styles["EquationNumber"] = _pstyle("EquationNumber", "Equation Number", custom=True, ppr=(
        '<w:spacing w:before="0" w:after="0" w:line="240" w:lineRule="auto" />'
        '<w:ind w:firstLine="0" /><w:jc w:val="right" />'))
    styles["TableText"] = _pstyle("TableText", "Table Text", custom=True, ppr=(
        '<w:spacing w:before="20" w:after="20" w:line="240" w:lineRule="auto" />'
        '<w:ind w:firstLine="0" />'), rpr=_size(21))
    # table of contents entries (render/docx_toc.py; Word's built-in "toc 1"-"toc 3"):
    # no first-line indent, each level two characters further in
    for level in (1, 2, 3):
        styles[f"TOC{level}"] = _pstyle(f"TOC{level}", f"toc {level}", next_="Normal", ppr=(
            '<w:spacing w:before="0" w:after="0" />'
            f'<w:ind w:left="{(level - 1) * 480}" w:firstLine="0" />'))
    # wide tables whose numbers would not fit their columns at 10.5 pt (docx-numbering.lua):
    # 小五 9 pt, then 7.5 pt
    for style_id, name, size in (("TableTextSmall", "Table Text Small", 18),
                                 ("TableTextSmaller", "Table Text Smaller", 15)):
        styles[style_id] = _pstyle(style_id, name, based_on="TableText", custom=True,
                                   rpr=_size(size))
    # code (inline, and the appendix listing): Consolas at 9 pt, as the PDF's 9 pt mono, so
    # that a listing line of render/summary.LISTING_WIDTH = 80 columns fits the 453.5 pt text
    # width (80 × 0.55 em × 9 pt = 396 pt; at pandoc's 11 pt it wrapped at 484 pt)
    styles["VerbatimChar"] = (
        '<w:style w:type="character" w:customStyle="1" w:styleId="VerbatimChar">'
        '<w:name w:val="Verbatim Char" /><w:basedOn w:val="BodyTextChar" />'
        '<w:rPr><w:rFonts w:ascii="Consolas" w:hAnsi="Consolas" />' + _size(18) + '</w:rPr></w:style>')
    # three-line table: 1.5 pt rules at top and bottom, 0.75 pt under the header row
    styles["Table"] = (
        '<w:style w:type="table" w:default="1" w:styleId="Table"><w:name w:val="Table" />'
        '<w:basedOn w:val="TableNormal" /><w:uiPriority w:val="59" /><w:qFormat />'
        '<w:pPr><w:spacing w:before="20" w:after="20" w:line="240" w:lineRule="auto" />'
        '<w:ind w:firstLine="0" /></w:pPr>'
        f"<w:rPr>{_size(21)}</w:rPr>"
        '<w:tblPr><w:jc w:val="center" /><w:tblInd w:w="0" w:type="dxa" />'
        + _borders("tblBorders", top="single:12", left="nil", bottom="single:12", right="nil",
                   insideH="nil", insideV="nil")
        + '<w:tblCellMar><w:top w:w="28" w:type="dxa" /><w:left w:w="108" w:type="dxa" />'
        '<w:bottom w:w="28" w:type="dxa" /><w:right w:w="108" w:type="dxa" /></w:tblCellMar>'
        '</w:tblPr>'
        '<w:tblStylePr w:type="firstRow"><w:rPr><w:b /><w:bCs /></w:rPr><w:tcPr>'
        + _borders("tcBorders", bottom="single:6")
        + '<w:vAlign w:val="bottom" /></w:tcPr></w:tblStylePr></w:style>')
    styles["Footer"] = _pstyle("Footer", "footer", ppr=(
        '<w:tabs><w:tab w:val="center" w:pos="4535" /><w:tab w:val="right" w:pos="9070" /></w:tabs>'
        '<w:ind w:firstLine="0" /><w:jc w:val="center" />'), rpr=_size(18),
        extra='<w:uiPriority w:val="99" /><w:unhideWhenUsed />')
    borderless = (
        '<w:tblPr><w:jc w:val="center" /><w:tblInd w:w="0" w:type="dxa" />'
        + _borders("tblBorders", **NO_BORDERS)
        + '<w:tblCellMar><w:top w:w="0" w:type="dxa" /><w:left w:w="0" w:type="dxa" />'
        '<w:bottom w:w="0" w:type="dxa" /><w:right w:w="0" w:type="dxa" /></w:tblCellMar>'
        '</w:tblPr>')
    # pandoc lays out a figure whose content is not a single image as a table
    styles["FigureTable"] = (
        '<w:style w:type="table" w:customStyle="1" w:styleId="FigureTable">'
        '<w:name w:val="Figure Table" /><w:basedOn w:val="TableNormal" /><w:qFormat />'
        + borderless + "</w:style>")
    # numbered display equations: | (empty) | equation | (N) |, see docx-numbering.lua
    styles["EquationTable"] = (
        '<w:style w:type="table" w:customStyle="1" w:styleId="EquationTable">'
        '<w:name w:val="Equation Table" /><w:basedOn w:val="TableNormal" /><w:qFormat />'
        + borderless + "</w:style>")
    return styles


_THEME_ATTR = re.compile(r'\s+w:(?:ascii|hAnsi|eastAsia|cs)Theme="[^"]*"')


def patch_styles(xml: str) -> str:
    """Fonts, sizes and the styles of :func:`replacement_styles` in ``word/styles.xml``."""
    ET.register_namespace("w", W_NS)
    ET.register_namespace("r", R_NS)
    root = ET.fromstring(_THEME_ATTR.sub("", xml).encode("utf-8"))
    # document defaults: 小四, Times New Roman + 宋体, Chinese as East-Asian language
    rpr = root.find(f"{W}docDefaults/{W}rPrDefault/{W}rPr")
    for child in list(rpr):
        rpr.remove(child)
    wrapped = (f'<w:rPr xmlns:w="{W_NS}">{rfonts(SERIF)}<w:kern w:val="2" />{_size(24)}'
               '<w:lang w:val="en-US" w:eastAsia="zh-CN" w:bidi="ar-SA" /></w:rPr>')
    for child in ET.fromstring(wrapped):
        rpr.append(child)
    ppr = root.find(f"{W}docDefaults/{W}pPrDefault/{W}pPr")
    for child in list(ppr):
        ppr.remove(child)
    # no punctuation hanging past the right margin (Word and LibreOffice let a line-end "，" or "、"
    # overhang a justified CJK line by default; the report keeps every glyph inside the text block)
    ppr.append(ET.fromstring(f'<w:overflowPunct xmlns:w="{W_NS}" w:val="0" />'))
    ppr.append(ET.fromstring(f'<w:spacing xmlns:w="{W_NS}" w:after="0" w:line="240" w:lineRule="auto" />'))

    new = replacement_styles()
    existing = {el.get(f"{W}styleId"): el for el in root.findall(f"{W}style")}
    for style_id, text in new.items():
        element = ET.fromstring(f'<w:styles xmlns:w="{W_NS}">{text}</w:styles>')[0]
        if style_id in existing:
            index = list(root).index(existing[style_id])
            root.remove(existing[style_id])
            root.insert(index, element)
        else:
            root.append(element)
    # remaining styles: no theme colours / italics in headings 4-9 were replaced above;
    # block text, footnotes etc. keep pandoc's definitions (fonts come from Normal)
    out = ET.tostring(root, encoding="unicode")
    return '<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n' + out


def patch_document(xml: str) -> str:
    """A4 page, 2.5 cm margins, footer with the page number (pandoc copies the sectPr)."""
    sect = (
        "<w:sectPr>"
        '<w:headerReference w:type="default" r:id="rIdMdHeader1" />'
        '<w:footerReference w:type="default" r:id="rIdMdFooter1" />'
        '<w:footnotePr><w:numRestart w:val="eachSect" /></w:footnotePr>'
        f'<w:pgSz w:w="{PAGE_W}" w:h="{PAGE_H}" />'
        f'<w:pgMar w:top="{MARGIN}" w:right="{MARGIN}" w:bottom="{MARGIN}" w:left="{MARGIN}" '
        f'w:header="{HEADER}" w:footer="{FOOTER}" w:gutter="0" />'
        '<w:cols w:space="425" />'
        # no page number on the title page (no "first" footer is defined)
        "<w:titlePg />"
        "</w:sectPr>")
    xml, count = re.subn(r"<w:sectPr>.*?</w:sectPr>", sect, xml, flags=re.DOTALL)
    if count != 1:
        raise RuntimeError("pandoc's reference document.xml has no single <w:sectPr>")
    return xml


FOOTER_XML = (
    '<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n'
    f'<w:ftr xmlns:w="{W_NS}" xmlns:r="{R_NS}">'
    '<w:p><w:pPr><w:pStyle w:val="Footer" /><w:jc w:val="center" /></w:pPr>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:fldChar w:fldCharType="begin" /></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:instrText xml:space="preserve"> PAGE </w:instrText></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:fldChar w:fldCharType="separate" /></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:t>1</w:t></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:fldChar w:fldCharType="end" /></w:r>'
    "</w:p></w:ftr>")


#: Running header: the report's title and the student, right-aligned over a thin rule, as
#: TITLE and AUTHOR fields (the document properties); render/docx.py writes the title, the
#: separator and the student into the fields' shown results, so it reads right before Word
#: updates fields (and drops the separator when the brief names no student).
HEADER_XML = (
    '<?xml version="1.0" encoding="UTF-8" standalone="yes"?>\n'
    f'<w:hdr xmlns:w="{W_NS}" xmlns:r="{R_NS}">'
    '<w:p><w:pPr><w:pStyle w:val="Header" /><w:pBdr><w:bottom w:val="single" w:sz="4" '
    'w:space="1" w:color="808080" /></w:pBdr><w:jc w:val="right" /></w:pPr>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:fldChar w:fldCharType="begin" /></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:instrText xml:space="preserve"> TITLE </w:instrText></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:fldChar w:fldCharType="separate" /></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:t>REPORT-TITLE</w:t></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:fldChar w:fldCharType="end" /></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:t xml:space="preserve">REPORT-SEPARATOR</w:t></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:fldChar w:fldCharType="begin" /></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:instrText xml:space="preserve"> AUTHOR </w:instrText></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:fldChar w:fldCharType="separate" /></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:t>REPORT-AUTHOR</w:t></w:r>'
    '<w:r><w:rPr><w:sz w:val="18" /></w:rPr><w:fldChar w:fldCharType="end" /></w:r>'
    "</w:p></w:hdr>")


def patch_rels(xml: str) -> str:
    rel = ('<Relationship Type="http://schemas.openxmlformats.org/officeDocument/2006/'
           'relationships/footer" Id="rIdMdFooter1" Target="footer1.xml" />'
           '<Relationship Type="http://schemas.openxmlformats.org/officeDocument/2006/'
           'relationships/header" Id="rIdMdHeader1" Target="header1.xml" />')
    return xml.replace("</Relationships>", rel + "</Relationships>")


def patch_content_types(xml: str) -> str:
    override = ('<Override PartName="/word/footer1.xml" ContentType="application/'
                'vnd.openxmlformats-officedocument.wordprocessingml.footer+xml" />'
                '<Override PartName="/word/header1.xml" ContentType="application/'
                'vnd.openxmlformats-officedocument.wordprocessingml.header+xml" />')
    return xml.replace("</Types>", override + "</Types>")


def patch_theme(xml: str) -> str:
    """Theme fonts (used by text a student types with theme-based styles) to match."""
    major = re.search(r"<a:majorFont>.*?</a:majorFont>", xml, flags=re.DOTALL)
    minor = re.search(r"<a:minorFont>.*?</a:minorFont>", xml, flags=re.DOTALL)
    if not (major and minor):
        return xml

    def fonts(block: str, latin: str, east: str) -> str:
        block = re.sub(r'<a:latin typeface="[^"]*"[^>]*/>', f'<a:latin typeface="{latin}"/>', block)
        return re.sub(r'<a:font script="Hans" typeface="[^"]*"/>',
                      f'<a:font script="Hans" typeface="{east}"/>', block)

    return (xml[:major.start()] + fonts(major.group(0), *SANS)
            + xml[major.end():minor.start()] + fonts(minor.group(0), *SERIF) + xml[minor.end():])


FONT_ENTRIES = {
    "宋体": ("SimSun", "02010600030101010101", "86", "auto", "fixed",
             '<w:sig w:usb0="00000003" w:usb1="288F0000" w:usb2="00000016" w:usb3="00000000" '
             'w:csb0="00040001" w:csb1="00000000" />'),
    "黑体": ("SimHei", "02010609060101010101", "86", "modern", "fixed",
             '<w:sig w:usb0="800002BF" w:usb1="38CF7CFA" w:usb2="00000016" w:usb3="00000000" '
             'w:csb0="00040001" w:csb1="00000000" />'),
    "Arial": (None, "020B0604020202020204", "00", "swiss", "variable",
              '<w:sig w:usb0="E0002EFF" w:usb1="C000785B" w:usb2="00000009" w:usb3="00000000" '
              'w:csb0="000001FF" w:csb1="00000000" />'),
}


def patch_font_table(xml: str) -> str:
    """Declare 宋体 (alt. SimSun), 黑体 (alt. SimHei) and Arial for font substitution."""
    entries = ""
    for name, (alt, panose, charset, family, pitch, sig) in FONT_ENTRIES.items():
        if f'w:name="{name}"' in xml:
            continue
        alt_xml = f'<w:altName w:val="{alt}" />' if alt else ""
        entries += (f'<w:font w:name="{name}">{alt_xml}<w:panose1 w:val="{panose}" />'
                    f'<w:charset w:val="{charset}" /><w:family w:val="{family}" />'
                    f'<w:pitch w:val="{pitch}" />{sig}</w:font>')
    return xml.replace("</w:fonts>", entries + "</w:fonts>")


def patch_settings(xml: str) -> str:
    """Open in Word's current layout mode (not 'Compatibility Mode'); Chinese theme language."""
    xml = xml.replace('<w:themeFontLang w:val="en-US" />',
                      '<w:themeFontLang w:val="en-US" w:eastAsia="zh-CN" />')
    xml = xml.replace('<w:characterSpacingControl w:val="doNotCompress" />',
                      '<w:characterSpacingControl w:val="compressPunctuation" />')
    compat = ('<w:compat><w:compatSetting w:name="compatibilityMode" '
              'w:uri="http://schemas.microsoft.com/office/word" w:val="15" /></w:compat>')
    if "<w:compat>" not in xml:
        xml = xml.replace("<w:rsids>", compat + "<w:rsids>", 1)
    return xml


def build(source: bytes) -> dict[str, bytes]:
    """Patched members (name -> bytes) of the reference docx, in archive order."""
    import io

    members: dict[str, bytes] = {}
    with zipfile.ZipFile(io.BytesIO(source)) as zin:
        for name in zin.namelist():
            members[name] = zin.read(name)

    def edit(name: str, func) -> None:
        members[name] = func(members[name].decode("utf-8")).encode("utf-8")

    edit("word/styles.xml", patch_styles)
    edit("word/document.xml", patch_document)
    edit("word/_rels/document.xml.rels", patch_rels)
    edit("[Content_Types].xml", patch_content_types)
    edit("word/theme/theme1.xml", patch_theme)
    edit("word/fontTable.xml", patch_font_table)
    edit("word/settings.xml", patch_settings)
    members["word/footer1.xml"] = FOOTER_XML.encode("utf-8")
    members["word/header1.xml"] = HEADER_XML.encode("utf-8")
    return members


def write_docx(members: dict[str, bytes], out: Path) -> None:
    """Write the archive reproducibly: [Content_Types].xml first, fixed timestamps."""
    names = ["[Content_Types].xml"] + [n for n in members if n != "[Content_Types].xml"]
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = out.with_name(f".{out.name}.tmp")
    with zipfile.ZipFile(tmp, "w") as zout:
        for name in names:
            info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            zout.writestr(info, members[name])
    tmp.replace(out)


def main(argv: list[str]) -> int:
    out = Path(argv[1]) if len(argv) > 1 else DEFAULT_OUT
    write_docx(build(pandoc_default_reference()), out)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
