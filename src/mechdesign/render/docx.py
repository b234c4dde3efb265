"""Markdown -> Word (.docx) rendering of the report with pandoc.

The same ``report.md`` that becomes the PDF is converted by pandoc (from
``pypandoc_binary``; no system pandoc needed) with two files from the
templates folder, both editable by students:

``reference.docx``
    Word style sheet and page setup (pandoc ``--reference-doc``): 宋体 /
    Times New Roman body text, 黑体 / Arial headings, A4.  Rebuilt by
    ``tools/make_reference_docx.py``, or edit it in Word (Modify Style).
``docx-numbering.lua``
    pandoc Lua filter: numbered figure/table captions ("图 1" / "Figure 1:"),
    references ``@fig:x``/``@tbl:x`` replaced by the same text, display
    equations numbered "(N)" at the right margin (still Word equations), the
    title block (student, class, supervisor, date) under the title.

Metadata keys (all optional): ``title``, ``subtitle``, ``student``,
``student_id``, ``class``, ``teacher``, ``date``, ``lang`` ("zh" or "en",
default "zh") and a nested ``labels`` mapping as for the PDF
(:data:`mechdesign.render.pdf.DEFAULT_LABELS`). Values are pandoc Markdown.

Reproducible output: pandoc dates the file (document properties and ZIP entries) by
``SOURCE_DATE_EPOCH``, which is set for the conversion to
:func:`mechdesign.render.pdf.source_timestamp` (the brief's date, or a fixed date).
"""

from __future__ import annotations

import json
import os
import re
import tempfile
import zipfile
from contextlib import contextmanager
from pathlib import Path

from ..fileio import atomic_path
from .docx_math import align_broken_equations, group_scripted_brackets
from .docx_layout import (centre_tables, keep_headings_with_text, keep_lead_ins, keep_table_rows,
                          separate_tables, split_inline_formula_lists,
                          keep_closing_marks_with_formulas, keep_references_together)
from .docx_toc import body_on_a_new_page, fill_table_of_contents
from .mathbreak import break_display_math

#: Widest formula line for Word [em of the PDF's math font, as render/mathbreak estimates]:
#: the equation sits in the middle 80 % of the 453.5 pt text width (templates/docx-numbering.lua),
#: 362.8 pt, set in Cambria Math at the body's 12 pt, about 1.1 × as wide as the PDF's New
#: Computer Modern: 362.8 / 12 / 1.1 = 27.5 em; 27 em leaves the estimate a little room
#: (the PDF budget, 30 em at 11 pt, would let a line run over the cell in Word).
WORD_BUDGET_EM = 27.0
from .pdf import DEFAULT_LABELS, MARKDOWN_FORMAT, source_timestamp
from .unitjoin import LUA_FILTER as UNIT_FILTER

REFERENCE_DOCX = "reference.docx"
LUA_FILTER = "docx-numbering.lua"

# Text width (twips) of A4 with 2.5 cm margins, used if the reference document has no page setup.
_DEFAULT_TEXT_WIDTH = 11906 - 2 * 1418


class DocxRenderError(RuntimeError):
    """Pandoc failed while rendering the report to .docx (or a template file is missing)."""


def _docx_metadata(metadata: dict, text_width: int) -> dict:
    """``metadata`` completed with language, labels and the text width for the Lua filter."""
    meta = {key: value for key, value in dict(metadata).items() if value not in (None, "")}
    lang = str(meta.get("lang") or "zh")
    is_zh = lang.lower().startswith("zh")
    # The Lua filter reads "report-lang".  pandoc's "lang" sets the Word proofing language;
    # reference.docx already has Chinese (zh-CN) as East-Asian language, and pandoc would
    # warn about missing "zh-CN" translations, so "lang" is only passed for other languages.
    meta.pop("lang", None)
    meta["report-lang"] = "zh" if is_zh else lang
    if not is_zh:
        meta["lang"] = "en-US" if lang.lower() == "en" else lang
    base = DEFAULT_LABELS["zh" if is_zh else "en"]
    meta["labels"] = {**base, **(meta.get("labels") or {})}
    meta["docx-text-width"] = text_width
    meta["toc-title"] = meta["labels"]["contents"]
    # the title page's title and subtitle in the lines the PDF's cover sets (explicit line
    # breaks, render/titlebreak.py); the document properties keep the plain title (_finish)
    for key in ("title", "subtitle"):
        cover = meta.pop("cover-" + key, None)
        if cover:
            meta[key] = cover
    return meta


@contextmanager
def _source_date_epoch(timestamp: int):
    """``SOURCE_DATE_EPOCH`` set for the pandoc child process (pypandoc passes a copy of
    ``os.environ``), restored afterwards."""
    old = os.environ.get("SOURCE_DATE_EPOCH")
    os.environ["SOURCE_DATE_EPOCH"] = str(int(timestamp))
    try:
        yield
    finally:
        if old is None:
            os.environ.pop("SOURCE_DATE_EPOCH", None)
        else:
            os.environ["SOURCE_DATE_EPOCH"] = old


def reference_text_width(reference: Path) -> int:
    """Width (twips) between the margins of the reference document's page."""
    try:
        with zipfile.ZipFile(reference) as docx:
            xml = docx.read("word/document.xml").decode("utf-8")
    except (OSError, KeyError, zipfile.BadZipFile):
        return _DEFAULT_TEXT_WIDTH
    sect = xml[xml.rfind("<w:sectPr"):]
    page = re.search(r'<w:pgSz\b[^>]*\bw:w="(\d+)"', sect)
    left = re.search(r'<w:pgMar\b[^>]*\bw:left="(\d+)"', sect)
    right = re.search(r'<w:pgMar\b[^>]*\bw:right="(\d+)"', sect)
    if not (page and left and right):
        return _DEFAULT_TEXT_WIDTH
    width = int(page.group(1)) - int(left.group(1)) - int(right.group(1))
    return width if width > 0 else _DEFAULT_TEXT_WIDTH


def render_docx(md_path: Path, docx_path: Path, metadata: dict, template_dir: Path) -> None:
    """Render a Markdown file to a Word document via pandoc.

    Inputs: the Markdown file (images referenced relative to its directory),
    the output .docx path, the metadata mapping (see module docstring) and the
    templates folder holding ``reference.docx`` and ``docx-numbering.lua``.
    Metadata from a YAML block inside the Markdown takes precedence.
    The document is written to a temporary file next to ``docx_path`` and
    moved into place (atomic); it is dated :func:`~.pdf.source_timestamp` of
    ``metadata["date"]``, so the same input gives the same bytes.  Raises
    DocxRenderError if pandoc fails or a template file is missing.
    """
    import pypandoc

    md_path = Path(md_path).resolve()
    docx_path = Path(docx_path).resolve()
    template_dir = Path(template_dir)
    reference = template_dir / REFERENCE_DOCX
    lua_filter = template_dir / LUA_FILTER
    for needed in (reference, lua_filter):
        if not needed.is_file():
            raise DocxRenderError(f"template file not found: {needed}")
    try:
        md_text = break_display_math(md_path.read_text(encoding="utf-8"), WORD_BUDGET_EM)
    except OSError as exc:
        raise DocxRenderError(f"cannot read {md_path}: {exc}") from exc

    meta = _docx_metadata(metadata, reference_text_width(reference))
    with atomic_path(docx_path) as tmp_docx:
        with tempfile.TemporaryDirectory(prefix="mechdesign-pandoc-") as tmp:
            meta_file = Path(tmp) / "metadata.json"
            unit_filter = Path(tmp) / "unit-join.lua"       # a number kept with its unit
            unit_filter.write_text(UNIT_FILTER, encoding="utf-8")
            # JSON is valid YAML, which is what --metadata-file expects.
            meta_file.write_text(json.dumps(meta, ensure_ascii=False, default=str),
                                 encoding="utf-8")
            try:
                with _source_date_epoch(source_timestamp(metadata.get("date"))):
                    pypandoc.convert_text(
                        md_text,
                        "docx",
                        format=MARKDOWN_FORMAT,
                        outputfile=str(tmp_docx),
                        extra_args=[
                            f"--reference-doc={reference.resolve()}",
                            f"--lua-filter={unit_filter}",
                            f"--lua-filter={lua_filter.resolve()}",
                            f"--metadata-file={meta_file}",
                            f"--resource-path={md_path.parent}",
                            "--number-sections",
                            # no relative column widths from long pipe-table rows (as for the PDF)
                            "--columns=10000",
                        ],
                    )
            except (RuntimeError, OSError) as exc:
                raise DocxRenderError(
                    f"pandoc failed to convert {md_path.name} to .docx: {exc}") from exc
        if not tmp_docx.is_file() or tmp_docx.stat().st_size == 0:
            raise DocxRenderError(f"pandoc wrote no output for {md_path.name}")
        _finish(tmp_docx, title=_plain(metadata.get("title")), author=_plain(metadata.get("student")),
                subject=_plain(metadata.get("description") or metadata.get("title")))


def _plain(markdown: object) -> str:
    """Plain text of a metadata value (pandoc Markdown escaped by ``md_text``)."""
    return re.sub(r"\\(.)", r"\1", str(markdown or "")).strip()


def _xml_text(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


# the elements that follow w:updateFields in CT_Settings (ECMA-376 Part 1, §17.15.1.78):
# Word rejects a settings part whose children are out of schema order
_AFTER_UPDATE_FIELDS = ("hdrShapeDefaults", "footnotePr", "endnotePr", "compat", "docVars", "rsids",
                        "mathPr", "attachedSchema", "themeFontLang", "clrSchemeMapping",
                        "doNotIncludeSubdocsInStats", "doNotAutoCompressPictures", "forceUpgrade",
                        "captions", "readModeInkLockDown", "smartTagType", "schemaLibrary",
                        "shapeDefaults", "doNotEmbedSmartTags", "decimalSymbol", "listSeparator")


def _update_fields_on_open(settings: bytes) -> bytes:
    """``<w:updateFields w:val="true"/>`` in word/settings.xml: Word updates the fields when
    the document is opened, after asking the user: the page numbers of the table of contents
    (``PAGEREF`` fields, :mod:`.docx_toc`), the captions' numbers, the running header."""
    xml = settings.decode("utf-8")
    if "<w:updateFields" in xml:
        return settings
    tag = '<w:updateFields w:val="true"/>'
    first = re.search(r"<(?:w|m):(%s)\b" % "|".join(_AFTER_UPDATE_FIELDS), xml)
    if first is not None:
        xml = xml[:first.start()] + tag + xml[first.start():]
    else:
        xml = xml.replace("</w:settings>", tag + "</w:settings>")
    return xml.encode("utf-8")


#: Latin-1 signs that Word sets in the East-Asian font of a run hinted ``eastAsia`` (pandoc
#: hints every run with Chinese text): [MS-OI29500] §2.1.88, rFonts: U+00B0–B4 and B6–BA,
#: D7, F7 among them. 宋体's are full-width: "N·m" would read "N · m", "25°" "25 °". The
#: minus sign U+2212 of :func:`minus_signs` is kept in the Latin font too ("−84.70" as the
#: PDF, whichever font Word would take for it in a hinted run).
_LATIN_MARKS = "·°×±²³¹÷\u2212"
_HINTED_RUN = re.compile(
    r'<w:r><w:rPr>(?P<pr>(?:(?!</w:rPr>).)*?w:hint="eastAsia"(?:(?!</w:rPr>).)*?)</w:rPr>'
    r'<w:t(?: xml:space="preserve")?>(?P<text>[^<]*)</w:t></w:r>', re.DOTALL)


def _is_latin_mark(text: str, k: int) -> bool:
    """``text[k]`` is one of :data:`_LATIN_MARKS` standing in Latin text: a printable ASCII
    character or another such mark right before or after it ("N·m", "s²)", "28×16", "/°"), or
    the run's first or last character (pandoc ends a run at a space or a formula: "（估计值）×")."""
    if text[k] not in _LATIN_MARKS:
        return False
    for j in (k - 1, k + 1):
        if not 0 <= j < len(text) or "!" <= text[j] <= "~" or text[j] in _LATIN_MARKS:
            return True
    return False


def latin_marks_in_latin_font(xml: str) -> str:
    """Every :data:`_LATIN_MARKS` sign that stands in Latin text ("N·m", "rad/s²", "19.69°")
    of a run hinted ``eastAsia`` moved into a run of its own without the hint, so that Word
    draws it in the text's Latin font (Times New Roman: the narrow middle dot, as the PDF),
    not in 宋体; the run's other properties are kept."""
    def one(m: re.Match) -> str:
        text = m.group("text")
        marks = [k for k in range(len(text)) if _is_latin_mark(text, k)]
        if not marks:
            return m.group(0)
        pr = m.group("pr")
        plain = re.sub(r'<w:rFonts w:hint="eastAsia"\s*/>', "", pr).replace(' w:hint="eastAsia"', "")
        out, start = [], 0
        for k in marks + [len(text)]:
            if k > start:
                out.append((pr, text[start:k]))
            if k < len(text):
                out.append((plain, text[k]))
            start = k + 1
        return "".join(("<w:r>" + (f"<w:rPr>{p}</w:rPr>" if p else "")
                        + f'<w:t xml:space="preserve">{t}</w:t></w:r>') for p, t in out)
    return _HINTED_RUN.sub(one, xml)


#: Characters after which a hyphen-minus before a digit is a minus sign: a cell's or a
#: paragraph's start, white space, an opening bracket, a relation, a separator ("= -2468 N",
#: "(-190.54, ", "最小 -84.70"); after a letter or a digit it stays a hyphen ("Y90S-6",
#: "6204-2RS", "GB/T 14689-2008", "2026-11-22", "表 8-11", "exercises 7-1"). typst draws the
#: same text of the PDF so: a "-" that starts a word before a digit is its minus shorthand.
_BEFORE_MINUS = set("([{（【=＝<>≤≥≈:：,，;；、~～")
_TEXT_TOKEN = re.compile(r"<w:p(?=[\s>/])[^>]*>|<w:r>|<w:(?:tab|br|cr)\b[^>]*/>"
                         r'|<w:pStyle w:val="SourceCode"|<w:rStyle w:val="(?:VerbatimChar|[A-Za-z]+Tok)"'
                         r"|<(?P<ns>[wm]):t(?:\s[^>]*)?>(?P<text>[^<]*)</(?P=ns):t>")


def minus_signs(xml: str) -> str:
    """Every hyphen-minus that signs a number in the text of ``word/document.xml`` ("-6.946"
    in a table cell, "ω₂ = -8.38 rad/s") made the minus sign U+2212, as the PDF prints it
    (review36: 160 such hyphens in the shaper's zh Word file); the character before it,
    across the runs of its paragraph, decides (:data:`_BEFORE_MINUS`). Formulas (m:t, whose
    minus pandoc writes as U+2212) and code (a SourceCode paragraph, a run of inline code or
    of a highlighted token) are only passed over."""
    prev, code_paragraph, code_run = "", False, False

    def one(m: re.Match) -> str:
        nonlocal prev, code_paragraph, code_run
        text, tag = m.group("text"), m.group(0)
        if text is None:
            if tag.startswith("<w:pStyle"):
                code_paragraph = True
            elif tag.startswith("<w:rStyle"):
                code_run = True
            elif tag == "<w:r>":
                code_run = False
            elif tag.startswith("<w:p"):         # a paragraph's start
                prev, code_paragraph, code_run = "", False, False
            else:                                # a tab or a line break
                prev = " "
            return tag
        if m.group("ns") == "m" or code_paragraph or code_run or "-" not in text:
            prev = text[-1:] or prev
            return tag
        out = []
        for k, ch in enumerate(text):
            before = out[-1] if out else prev
            if (ch == "-" and text[k + 1:k + 2].isdigit()
                    and (before == "" or before.isspace() or before in _BEFORE_MINUS)):
                ch = "\u2212"
            out.append(ch)
        prev = out[-1] if out else prev
        start, end = m.span("text")
        return tag[:start - m.start()] + "".join(out) + tag[end - m.start():]
    return _TEXT_TOKEN.sub(one, xml)


def _finish(docx: Path, *, title: str, author: str, subject: str) -> None:
    """The running header shows the title and the student (the TITLE and AUTHOR fields'
    shown results, filled in here so that they read right before Word updates fields;
    a reference.docx from before the AUTHOR field shows the title alone); the properties
    name the student as author and the report as subject; broken display formulas become
    aligned lines that Word and LibreOffice both read, and a bracket closed in a script's
    base a delimiter (:mod:`.docx_math`); the table of
    contents holds its entries and their page numbers and the body starts on the next page
    (:mod:`.docx_toc`); table rows do not split, short tables stay on one page, a lead-in
    ending in a colon stays with what it introduces, a heading keeps three rows of its text
    and a list of
    formulas in one inline formula may break between its items, tables are centred and a numbered
    formula after a table stays a table of its own (:mod:`.docx_layout`); a negative number's
    hyphen is the minus sign (:func:`minus_signs`); "N·m", "s²", "25°"
    in Chinese text take the Latin font's signs (:func:`latin_marks_in_latin_font`). The archive keeps
    its member order and dates (reproducible)."""
    with zipfile.ZipFile(docx) as zin:
        items = [(info, zin.read(info.filename)) for info in zin.infolist()]
    out: list[tuple[zipfile.ZipInfo, bytes]] = []
    for info, data in items:
        name = info.filename
        if name.startswith("word/header") and name.endswith(".xml"):
            data = data.replace(b"REPORT-TITLE", _xml_text(title).encode("utf-8"))
            data = data.replace(b"REPORT-SEPARATOR", "\u2003".encode("utf-8") if author else b"")
            data = data.replace(b"REPORT-AUTHOR", _xml_text(author).encode("utf-8"))
        elif name == "word/document.xml":
            xml = align_broken_equations(data.decode("utf-8"))
            xml = body_on_a_new_page(fill_table_of_contents(group_scripted_brackets(xml)))
            xml = keep_headings_with_text(split_inline_formula_lists(keep_lead_ins(keep_table_rows(xml))))
            xml = keep_references_together(keep_closing_marks_with_formulas(xml))
            xml = separate_tables(centre_tables(xml))
            data = latin_marks_in_latin_font(minus_signs(xml)).encode("utf-8")
        elif name == "word/settings.xml":
            data = _update_fields_on_open(data)
        elif name == "docProps/core.xml":
            xml = data.decode("utf-8")
            for tag, value in (("dc:creator", author), ("dc:subject", subject)):
                if not value:
                    continue
                element = f"<{tag}>{_xml_text(value)}</{tag}>"
                xml, n = re.subn(rf"<{tag}>.*?</{tag}>|<{tag}\s*/>", lambda _m: element, xml, flags=re.DOTALL)
                if n == 0:
                    xml = xml.replace("</cp:coreProperties>", element + "</cp:coreProperties>")
            data = xml.encode("utf-8")
        out.append((info, data))
    with zipfile.ZipFile(docx, "w") as zout:
        for info, data in out:
            zout.writestr(info, data)
