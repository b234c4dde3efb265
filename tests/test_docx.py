"""Rendering of the report as a Word file: Markdown -> pandoc (+ Lua filter) -> .docx."""

from __future__ import annotations

import re
import shutil
import zipfile
from xml.etree import ElementTree
from pathlib import Path

import pytest

pytest.importorskip("pypandoc")
PIL_Image = pytest.importorskip("PIL.Image")

from mechdesign.render.docx import (  # noqa: E402
    DocxRenderError,
    reference_text_width,
    render_docx,
)
from mechdesign.render.report import template_dir  # noqa: E402

pytestmark = pytest.mark.e2e     # renders Word files (see tests/conftest.py)

ROOT = Path(__file__).parents[1]
TEMPLATES = template_dir()
EN_METADATA = {"title": "Course design", "lang": "en"}
METADATA = {
    "title": "机械原理课程设计说明书",
    "subtitle": "牛头刨床导杆机构",
    "student": "张三",
    "student_id": "2021012345",
    "class": "",  # empty values are skipped
    "teacher": "李四",
    "date": "2024 年 6 月",
    "lang": "zh",
}
MARKDOWN = """\
# 运动分析

曲柄转速 $n_2 = 60\\ \\text{r/min}$，刨头位移线图见 @fig:ram，运动参数见 @tbl:kin。

$$ \\theta = 180° \\times \\frac{K-1}{K+1} $$

$$ L_{O_3B} = \\frac{H}{2\\sin(\\theta/2)} $$

| $\\varphi$/° | 位置 | $s_5$/mm |
|:--|:-:|--:|
| 0 | 左极限 | 12.50 |
| 30 | 中间 | 25.10 |

: 各位置运动参数 {#tbl:kin}

![刨头位移线图](figures/ram.png){#fig:ram width=70%}
"""
MARKDOWN_EN = """\
# Kinematics

The ram displacement is shown in @fig:ram and listed in @tbl:kin.

$$ v = \\frac{ds}{dt} $$

| $\\varphi$/° | $s_5$/mm |
|:--|--:|
| 0 | 12.50 |

: Positions {#tbl:kin}

![Ram displacement](figures/ram.png){#fig:ram width=70%}
"""


def _write_sample(folder: Path, text: str) -> Path:
    (folder / "figures").mkdir(parents=True, exist_ok=True)
    PIL_Image.new("RGB", (60, 30), (30, 90, 200)).save(folder / "figures" / "ram.png")
    md = folder / "report.md"
    md.write_text(text, encoding="utf-8")
    return md


def _sample_docx(folder: Path, text: str, metadata: dict | None = None) -> Path:
    """The Word file of the sample Markdown ``text`` (zh metadata unless ``metadata``)."""
    out = folder / "report.docx"
    render_docx(_write_sample(folder, text), out, METADATA if metadata is None else metadata, TEMPLATES)
    return out


def _sample_document(folder: Path, text: str, metadata: dict | None = None) -> str:
    """word/document.xml of :func:`_sample_docx`, checked to be well-formed XML."""
    document = _part(_sample_docx(folder, text, metadata), "word/document.xml")
    ElementTree.fromstring(document)
    return document


def _part(docx: Path, name: str) -> str:
    with zipfile.ZipFile(docx) as archive:
        return archive.read(name).decode("utf-8")


def _paragraph_texts(document_xml: str) -> list[str]:
    """Visible text of each paragraph (runs and field results joined, tags removed)."""
    texts = []
    for para in re.findall(r"<w:p[ >].*?</w:p>", document_xml, flags=re.DOTALL):
        para = re.sub(r"<w:instrText[^>]*>.*?</w:instrText>", "", para, flags=re.DOTALL)
        texts.append("".join(re.findall(r"<w:t(?: [^>]*)?>([^<]*)</w:t>", para)))
    return texts


@pytest.fixture(scope="module")
def zh_docx(tmp_path_factory) -> Path:
    return _sample_docx(tmp_path_factory.mktemp("docx-zh"), MARKDOWN)


def test_chinese_text_tables_math_and_image(zh_docx):
    document = _part(zh_docx, "word/document.xml")
    texts = _paragraph_texts(document)
    joined = "\n".join(texts)
    assert "曲柄转速" in document and "左极限" in document
    assert document.count("<w:tbl>") >= 1
    assert 'w:tblStyle w:val="Table"' in document  # the pipe table (three-line style)
    # display equations stay editable Word equations (OMML), not images
    assert document.count("<m:oMathPara>") == 2
    assert document.count("<m:oMath") >= 3  # 2 display + inline math
    assert "<m:f>" in document and "<m:sSub>" in document  # \frac and subscripts
    with zipfile.ZipFile(zh_docx) as archive:
        assert any(n.startswith("word/media/") and n.endswith(".png") for n in archive.namelist())
    # pipe-table alignment survives
    assert '<w:jc w:val="right" />' in document and '<w:jc w:val="center" />' in document
    assert "机械原理课程设计说明书" in joined


def test_numbered_captions_references_and_equations(zh_docx):
    texts = _paragraph_texts(_part(zh_docx, "word/document.xml"))
    assert any(t.startswith("图 1 ") and "刨头位移线图" in t for t in texts)
    assert any(t.startswith("表 1 ") and "各位置运动参数" in t for t in texts)
    body = next(t for t in texts if t.startswith("曲柄转速"))
    assert "@fig" not in body and "@tbl" not in body
    assert "见图 1" in body and "见表 1" in body  # no space between CJK text and reference
    assert "(1)" in texts and "(2)" in texts
    document = _part(zh_docx, "word/document.xml")
    assert "SEQ 图" in document and "SEQ 表" in document and "SEQ Equation" in document


def test_a_reference_number_is_set_apart_from_the_chinese_word_after_it(tmp_path):
    """Issue 19: Word read "由图 6量得" where the PDF sets "由图 6 量得" (typst's CJK–Latin
    spacing puts the same gap, a quarter em, on both sides of the number). The space the
    Markdown has after the reference stays before a Chinese word; none is added before a
    punctuation mark, nor between a Chinese character and the reference before it."""
    text = MARKDOWN.replace("曲柄转速 $n_2 = 60\\ \\text{r/min}$，刨头位移线图见 @fig:ram，运动参数见 @tbl:kin。",
                            "由 @fig:ram 量得的角速度；位移如 @fig:ram 所示，数据见 @tbl:kin。")
    assert text != MARKDOWN
    body = next(t for t in _paragraph_texts(_sample_document(tmp_path, text)) if "量得" in t)
    assert body == "由图 1 量得的角速度；位移如图 1 所示，数据见表 1。"


def test_title_block(zh_docx):
    texts = _paragraph_texts(_part(zh_docx, "word/document.xml"))
    assert "牛头刨床导杆机构" in texts
    assert "姓名：张三" in texts and "学号：2021012345" in texts and "指导教师：李四" in texts
    assert any(t.startswith("日期：2024") for t in texts)
    assert not any(t.startswith("班级") for t in texts)  # empty value skipped


def test_reference_doc_fonts_and_page(zh_docx):
    styles = _part(zh_docx, "word/styles.xml")
    east_asia = set(re.findall(r'w:eastAsia="([^"]+)"', styles))
    assert east_asia & {"宋体", "SimSun"}
    assert east_asia & {"黑体", "SimHei"}
    heading1 = re.search(r'<w:style [^>]*w:styleId="Heading1".*?</w:style>', styles, re.DOTALL)
    assert heading1 and 'w:eastAsia="黑体"' in heading1.group(0) and 'w:val="32"' in heading1.group(0)
    # body lines a fixed least distance apart, not a multiple of the font's line height: the
    # font standing in for 宋体 (LibreOffice: Noto Sans CJK, 1.45 em) made a zh report's lines
    # 26 pt apart against 20.7 pt in en (review36 Top 14: shaper zh 48 pages, 38 in the PDF)
    body = re.search(r'<w:style [^>]*w:styleId="BodyText".*?</w:style>', styles, re.DOTALL).group(0)
    spacing = re.search(r"<w:spacing\b[^>]*>", body).group(0)
    assert re.search(r'w:lineRule="(?:atLeast|exact)"', spacing), spacing
    assert 18 * 20 <= int(re.search(r'w:line="(\d+)"', spacing).group(1)) <= 24 * 20, spacing
    document = _part(zh_docx, "word/document.xml")
    assert re.search(r'<w:pgSz w:h="16838" w:w="11906"|<w:pgSz w:w="11906" w:h="16838"', document)
    assert reference_text_width(TEMPLATES / "reference.docx") == 11906 - 2 * 1418


def test_english_captions(tmp_path):
    texts = _paragraph_texts(_sample_document(tmp_path, MARKDOWN_EN, {**EN_METADATA, "student": "Zhang San"}))
    assert any(t.startswith("Figure 1: Ram displacement") for t in texts)
    assert any(t.startswith("Table 1: Positions") for t in texts)
    assert any("shown in Figure 1 and listed in Table 1." in t for t in texts)
    assert "(1)" in texts
    assert "Name: Zhang San" in texts


def test_pandoc_failure_raises_and_leaves_no_file(tmp_path):
    templates = tmp_path / "templates"
    templates.mkdir()
    shutil.copy(TEMPLATES / "docx-numbering.lua", templates)
    (templates / "reference.docx").write_bytes(b"not a zip file")
    md = _write_sample(tmp_path, MARKDOWN)
    out = tmp_path / "report.docx"
    with pytest.raises(DocxRenderError, match="pandoc"):
        render_docx(md, out, METADATA, templates)
    assert list(tmp_path.glob("*.docx")) == [] and not list(tmp_path.glob(".*tmp*"))
    with pytest.raises(DocxRenderError, match="not found"):
        render_docx(md, out, METADATA, tmp_path / "missing")


def test_real_cam_report(tmp_path):
    from typer.testing import CliRunner

    from mechdesign.cli import app

    out = tmp_path / "cam"
    result = CliRunner().invoke(app, ["run", str(ROOT / "designs" / "cam_7_3.yaml"),
                                      "-f", "md", "-o", str(out)])
    assert result.exit_code == 0, result.output
    docx = out / "report.docx"
    render_docx(out / "report.md", docx, METADATA, TEMPLATES)
    document = _part(docx, "word/document.xml")
    texts = _paragraph_texts(document)
    markdown = (out / "report.md").read_text(encoding="utf-8")
    n_display = len(re.findall(r"\$\$.+?\$\$", markdown, flags=re.DOTALL))
    assert n_display > 0
    assert document.count("<m:oMathPara>") == n_display
    assert f"({n_display})" in texts
    assert document.count('w:tblStyle w:val="Table"') >= 2
    assert any(t.startswith("表 1 ") for t in texts) and any(t.startswith("图 1 ") for t in texts)


def test_running_header_names_title_and_student_and_properties_author_and_subject(tmp_path):
    """Issue 22 (5): the header shows the title and the student (TITLE and AUTHOR fields with
    their results filled in); without a student, the title alone (no dangling separator)."""
    out = _sample_docx(tmp_path, MARKDOWN_EN, {**EN_METADATA, "student": "Zhang San",
                                               "description": "Course design — shaper"})
    header = _part(out, "word/header1.xml")
    shown = "".join(re.findall(r"<w:t(?: [^>]*)?>([^<]*)</w:t>", header))
    assert shown == "Course design\u2003Zhang San"
    assert " TITLE " in header and " AUTHOR " in header and "REPORT-" not in header
    core = _part(out, "docProps/core.xml")
    assert "<dc:creator>Zhang San</dc:creator>" in core
    assert "<dc:subject>Course design — shaper</dc:subject>" in core
    document = _part(out, "word/document.xml")
    assert re.search(r"<w:instrText[^>]*>\s*PAGEREF _Toc\d+ \\h", document)       # table of contents
    assert re.search(r"<w:instrText[^>]*>\s*PAGE\s*<", _part(out, "word/footer1.xml"))
    alone = tmp_path / "alone.docx"
    render_docx(tmp_path / "report.md", alone, EN_METADATA, TEMPLATES)
    header = _part(alone, "word/header1.xml")
    assert "".join(re.findall(r"<w:t(?: [^>]*)?>([^<]*)</w:t>", header)) == "Course design"


# CT_Settings children in schema order (ECMA-376 Part 1, §17.15.1.78), the part of the
# sequence around w:updateFields that pandoc's settings.xml uses
_SETTINGS_ORDER = ("zoom", "embedSystemFonts", "proofState", "defaultTabStop", "characterSpacingControl",
                   "updateFields", "hdrShapeDefaults", "footnotePr", "endnotePr", "compat", "docVars",
                   "rsids", "mathPr", "themeFontLang", "clrSchemeMapping", "shapeDefaults",
                   "decimalSymbol", "listSeparator")


def test_the_table_of_contents_is_filled_when_word_opens_the_file(zh_docx):
    """Review finding: the TOC field pandoc writes is empty until the user updates fields.
    ``w:updateFields`` makes Word fill it on opening; it must stand in schema order, or Word
    calls the file corrupt."""
    settings = _part(zh_docx, "word/settings.xml")
    assert settings.count('<w:updateFields w:val="true"/>') == 1
    children = [t for t in re.findall(r"<(?:w|m):(\w+)", settings) if t in _SETTINGS_ORDER]
    tops = list(dict.fromkeys(children))
    assert tops == sorted(tops, key=_SETTINGS_ORDER.index), tops


# A formula far wider than a line: render/mathbreak sets it as `aligned` (rows at "=").
LONG_FORMULA = ("L_{O_3M} = L_{O_3B}\\,\\frac{1+\\cos(\\psi/2)}{2} = L_{O_3B} - "
                "\\frac{L_{O_3B}\\,(1-\\cos(\\psi/2))}{2} = 1124.27 - "
                "\\frac{1124.27 \\times 0.01018}{2} = 1118.55\\ \\text{mm}")


def _math_paragraphs(document_xml: str) -> list[str]:
    return re.findall(r"<m:oMathPara>.*?</m:oMathPara>", document_xml, flags=re.DOTALL)


def test_broken_equation_is_aligned_lines_without_ampersands(tmp_path):
    """Issue 19 (1): LibreOffice drew "∧¿" at the alignment marks of broken equations (the
    literal "&" of an m:eqArr is StarMath's logical and). Each line is an m:oMath of its own,
    separated by a line break run, aligned by m:aln (Word's form for aligned equations of a
    math paragraph); a line that starts with "=" has an empty operand before it."""
    from mechdesign.render.docx import WORD_BUDGET_EM
    from mechdesign.render.mathbreak import break_formula

    broken = break_formula(LONG_FORMULA, WORD_BUDGET_EM)
    n_rows = broken.count("\\\\") + 1
    assert n_rows >= 2                       # the sample is broken at all
    document = _sample_document(tmp_path, f"# Kinematics\n\n$$ {LONG_FORMULA} $$\n", EN_METADATA)
    assert "<m:t>&amp;</m:t>" not in document and "<m:eqArr>" not in document
    [para] = _math_paragraphs(document)
    lines = re.findall(r"<m:oMath>(.*?)</m:oMath>", para, flags=re.DOTALL)
    assert len(lines) == n_rows
    assert all(line.endswith("<m:r><w:br /></m:r>") for line in lines[:-1])
    assert "<w:br" not in lines[-1]
    assert '<m:jc m:val="centerGroup" />' in para
    # one alignment point per line, the last property of its run (CT_RPR order)
    for line in lines:
        assert line.count("<m:aln />") == 1
        assert re.search(r"<m:rPr>(?:<m:(?:lit|nor|scr|sty|brk)\b[^>]*/>)*<m:aln /></m:rPr>", line)
    # continuation lines start with "=": an empty normal-text run stands before it
    continued = [line for line in lines[1:] if "<m:t>=</m:t>" in line[:200]]
    assert continued and all(line.startswith("<m:r><m:rPr><m:nor /></m:rPr><m:t></m:t></m:r>")
                             for line in continued)
    # the first line keeps its left side before the alignment point
    assert lines[0].index("<m:aln />") > lines[0].index("<m:t>L</m:t>")


def test_alignment_point_before_a_structure_is_an_empty_run():
    """A line whose alignment point precedes a structure (not a run): an empty run carries
    m:aln (an operator-emulator box would space the structure as an operator)."""
    from mechdesign.render.docx_math import align_broken_equations

    amp = "<m:r><m:t>&amp;</m:t></m:r>"
    sub = "<m:sSub><m:e><m:r><m:t>x</m:t></m:r></m:e><m:sub><m:r><m:t>1</m:t></m:r></m:sub></m:sSub>"
    xml = ('<w:p><m:oMathPara><m:oMathParaPr><m:jc m:val="center" /></m:oMathParaPr>'
           f"<m:oMath><m:eqArr><m:e>{amp}{sub}</m:e><m:e>{amp}<m:r><m:t>y</m:t></m:r></m:e>"
           "</m:eqArr></m:oMath></m:oMathPara></w:p>")
    out = align_broken_equations(xml)
    lines = re.findall(r"<m:oMath>(.*?)</m:oMath>", out)
    # a broken line ends in an em space before its break (session 39, text39: LibreOffice set
    # "57.04 mm ,b" where a \quad stood at the break)
    assert lines[0] == (f"<m:r><m:rPr><m:aln /></m:rPr><m:t></m:t></m:r>{sub}<m:r><m:rPr><m:nor /></m:rPr>"
                        '<m:t xml:space="preserve">\u2003</m:t></m:r><m:r><w:br /></m:r>')
    assert lines[1] == "<m:r><m:rPr><m:aln /></m:rPr><m:t>y</m:t></m:r>"
    # an equation array inside a formula (not the whole display) is left alone
    inner = xml.replace("<m:oMath><m:eqArr>", "<m:oMath><m:r><m:t>a</m:t></m:r><m:eqArr>")
    assert align_broken_equations(inner) == inner


def test_a_bracket_pair_split_over_two_lines_is_normal_text():
    """LibreOffice reads each line as a formula of its own: a bracket without its partner on
    the line would be an error mark "¿" there; as normal text (m:nor) it is drawn as is."""
    from mechdesign.render.docx_math import align_broken_equations

    amp = "<m:r><m:t>&amp;</m:t></m:r>"

    def run(text, props=""):
        return f"<m:r><m:rPr>{props}</m:rPr><m:t>{text}</m:t></m:r>" if props else f"<m:r><m:t>{text}</m:t></m:r>"

    p = '<m:sty m:val="p" />'
    row1 = run("a") + amp + run("=", p) + run("(", p) + run("b") + run("+", p) + run("(", p) + run("c") + run(")", p)
    row2 = amp + run("+", p) + run("d") + run(")", p) + run("[", p) + run("e") + run("]", p)
    xml = (f"<m:oMathPara><m:oMath><m:eqArr><m:e>{row1}</m:e><m:e>{row2}</m:e></m:eqArr>"
           "</m:oMath></m:oMathPara>")
    lines = re.findall(r"<m:oMath>(.*?)</m:oMath>", align_broken_equations(xml))
    nor = "<m:r><m:rPr><m:nor /></m:rPr><m:t>{}</m:t></m:r>"
    # line 1: the first "(" is open at the line's end; "(c)" is a pair
    assert lines[0].count(nor.format("(")) == 1 and lines[0].count(run("(", p)) == 1
    assert run(")", p) in lines[0]
    # line 2: its ")" closes a bracket of line 1; "[e]" is a pair
    assert lines[1].count(nor.format(")")) == 1
    assert run("[", p) in lines[1] and run("]", p) in lines[1]


# Advance widths of Times (Adobe AFM, 1/1000 em): the digits, "." and "-" of the numbers below.
_TIMES_WIDTH = {**{d: 500 for d in "0123456789"}, ".": 250, "-": 333}
_TEXT_WIDTH = 11906 - 2 * 1418            # twips between the margins of reference.docx
_CELL_MARGINS = 2 * 108                   # left + right cell margins of the Table style


def _number_twips(number: str, half_points: int) -> float:
    return sum(_TIMES_WIDTH[c] for c in number) / 1000 * half_points / 2 * 20


def test_numbers_fit_their_columns_in_a_wide_table(tmp_path):
    """Issue 19 (7) / 22: numbers broke inside narrow cells ("188." | "18"). Every column is
    at least as wide as its widest number (Times metrics) plus the cell margins; a table too
    wide for that at 10.5 pt is set in the 9 pt table style."""
    numbers = [f"-{1000 + 37 * r + c}.{(7 * r + c) % 100:02d}" for r in range(4) for c in range(10)]
    header = "| " + " | ".join(f"$F_{{R{c}}}$/kN" for c in range(10)) + " |"
    rows = ["| " + " | ".join(numbers[10 * r:10 * r + 10]) + " |" for r in range(4)]
    narrow = "| a | b |\n|--:|--:|\n| 12.5 | 3.25 |"
    out = _sample_docx(tmp_path, "# Forces\n\n" + "\n".join([header, "|" + "--:|" * 10, *rows])
                       + "\n\n: Reactions\n\n" + narrow + "\n", EN_METADATA)
    document = _part(out, "word/document.xml")
    styles = _part(out, "word/styles.xml")
    wide, small = [t for t in re.findall(r"<w:tbl>.*?</w:tbl>", document, flags=re.DOTALL)
                   if 'w:tblStyle w:val="Table"' in t]
    style = re.search(r'<w:pStyle w:val="(TableText\w*)"', wide).group(1)
    assert style == "TableTextSmall"
    assert re.search(r'<w:pStyle w:val="TableText"', small)     # a narrow table keeps 10.5 pt
    definition = re.search(rf'<w:style [^>]*w:styleId="{style}".*?</w:style>', styles, re.DOTALL)
    half_points = int(re.search(r'<w:sz w:val="(\d+)"', definition.group(0)).group(1))
    assert half_points == 18
    grid = [int(w) for w in re.findall(r'<w:gridCol w:w="(\d+)"', wide)]
    assert len(grid) == 10
    for c, col in enumerate(grid):
        width = col / sum(grid) * _TEXT_WIDTH
        widest = max(_number_twips(numbers[10 * r + c], half_points) for r in range(4))
        assert width >= widest + _CELL_MARGINS, (c, width, widest)


def test_table_of_contents_after_the_title_page_with_an_entry_per_heading(tmp_path):
    """Issue 22 (5): the contents page. It holds an entry per heading (levels 1-3) with its
    page number, so that a reader that does not update a TOC field (LibreOffice; Word when
    the user declines) shows it, each a link to a bookmark around its heading; it stands on a page of its own
    after the title block, not between the subtitle and the student's name."""
    document = _sample_document(tmp_path, "# Kinematics\n\nText.\n\n## Velocities\n\nText.\n\n"
                                "### Polygon & scale\n\nText.\n\n#### Too deep\n\nText.\n\n"
                                "# Summary {-}\n\nText.\n", {**EN_METADATA, "student": "Zhang San"})
    toc = re.search(r"<w:sdt>.*?</w:sdt>", document, flags=re.DOTALL).group(0)
    entries = re.findall(r'<w:pStyle w:val="TOC(\d)" />.*?<w:hyperlink w:anchor="(\w+)"[^>]*>(.*?)</w:hyperlink>',
                         toc, flags=re.DOTALL)
    texts = ["".join(re.findall(r"<w:t[^>]*>([^<]*)</w:t>", body)) for _, _, body in entries]
    assert [int(level) for level, _, _ in entries] == [1, 2, 3, 1]
    assert texts == ["1 Kinematics", "1.1 Velocities", "1.1.1 Polygon &amp; scale", "Summary"]
    for _, anchor, _ in entries:
        heading = re.search(rf'<w:p><w:pPr><w:pStyle w:val="Heading\d" />(?:(?!</w:p>).)*'
                            rf'w:name="{anchor}"', document, flags=re.DOTALL)
        assert heading is not None, anchor
    # each entry ends in a dotted leader to the right margin and its page number, a PAGEREF
    # of the heading's bookmark that the reader computes (review35: LibreOffice showed the
    # contents without page numbers: a TOC field's stored result, which cannot hold them)
    width = int(re.search(r'<w:pgSz\b[^>]*\bw:w="(\d+)"', document).group(1)) - sum(
        int(re.search(rf'<w:pgMar\b[^>]*\bw:{side}="(\d+)"', document).group(1)) for side in ("left", "right"))
    paragraphs = re.findall(r"<w:p>.*?</w:p>", toc, flags=re.DOTALL)[1:]     # after the title
    assert len(paragraphs) == 4
    for paragraph, (_, anchor, _) in zip(paragraphs, entries):
        assert f'<w:tab w:val="right" w:leader="dot" w:pos="{width}" />' in paragraph
        assert re.search(rf'<w:tab /></w:r><w:r><w:fldChar w:fldCharType="begin" w:dirty="true" /></w:r>'
                         rf'<w:r><w:instrText xml:space="preserve"> PAGEREF {anchor} \\h </w:instrText>', paragraph)
    assert "TOC \\o" not in document
    # order: title block, page break, contents, page break, body
    name, toc_at = document.index("Name: Zhang San"), document.index("<w:sdt>")
    body = document.index("Kinematics</w:t>", document.index("</w:sdt>"))
    assert name < toc_at < body
    assert '<w:br w:type="page" />' in document[name:toc_at]
    # the body's first heading starts the next page (w:pageBreakBefore), not a paragraph
    # holding a page break: on a full contents page that paragraph went to a page of its own
    # and left it blank (slotter zh p. 3, review35); no empty paragraph ends the contents
    after = document[document.index("</w:sdt>"):body]
    assert "<w:p>" in after and '<w:br w:type="page" />' not in after
    first = after[after.index("<w:p>"):]
    assert re.match(r'<w:p><w:pPr><w:pStyle w:val="Heading1" /><w:pageBreakBefore />', first), first[:200]
    assert all(text for text in _paragraph_texts(toc)), _paragraph_texts(toc)


def test_a_bracket_closed_in_a_superscript_base_becomes_a_delimiter(tmp_path):
    """texmath writes (a+b)^2 as "(" a + b and a superscript whose base is ")" alone:
    LibreOffice draws each unbalanced bracket "¿". The bracketed runs become the base of the
    superscript as a delimiter object (m:d), Word's form of (a+b)²."""
    # a long paragraph first: a formula among a heading's first rows is written as a
    # paragraph with tab stops (docx_layout.formula_paragraph), not a displayed one
    long = "The stress of the shaft is combined from bending and torsion as below. " * 8
    document = _sample_document(tmp_path, "# A\n\n" + long + "\n\n"
                                "$$ \\sigma = \\sqrt{M^2 + (\\alpha T)^2} + (C/P)^{3} $$\n", EN_METADATA)
    [para] = _math_paragraphs(document)
    # no script has a lone bracket as its base any more
    assert not re.search(r"<m:sSup><m:e><m:r>(?:<m:rPr>(?:<[^>]*/>)*</m:rPr>)?<m:t>[)\]]</m:t></m:r></m:e>", para)
    bases = re.findall(r'<m:sSup><m:e><m:d><m:dPr><m:begChr m:val="\(" /><m:endChr m:val="\)" />'
                       r"</m:dPr><m:e>(.*?)</m:e></m:d></m:e><m:sup>", para)
    texts = ["".join(re.findall(r"<m:t>([^<]*)</m:t>", b)) for b in bases]
    assert texts == ["αT", "C/P"]
    # no bracket run left over outside them
    assert not re.search(r"<m:t>[()]</m:t>", para)


def test_bars_in_pairs_become_absolute_values():
    """A bare "|" is StarMath's logical or ("∨" in LibreOffice): bars in pairs become a
    delimiter |x| (m:d); a single bar (a conditional, a divisor) stays a run. A superscript
    "*" (an operator to StarMath, drawn "¿") becomes U+2217."""
    from mechdesign.render.docx_math import group_scripted_brackets

    def r(t):
        return f"<m:r><m:t>{t}</m:t></m:r>"

    pair = f'<w:p xmlns:w="w"><m:oMath>{r("max")}{r("|")}{r("M")}{r("ω")}{r("|")}</m:oMath></w:p>'
    out = group_scripted_brackets(pair)
    assert out == ('<w:p xmlns:w="w"><m:oMath>' + r("max")
                   + '<m:d><m:dPr><m:begChr m:val="|" /><m:endChr m:val="|" /></m:dPr>'
                   + f"<m:e>{r('M')}{r('ω')}</m:e></m:d></m:oMath></w:p>")
    single = f'<w:p xmlns:w="w"><m:oMath>{r("P")}{r("(")}{r("A")}{r("|")}{r("B")}{r(")")}</m:oMath></w:p>'
    assert group_scripted_brackets(single) == single
    # |B|^3: the closing bar is the superscript's base
    cubed = (f'<w:p xmlns:w="w"><m:oMath>{r("|")}{r("B")}<m:sSup><m:e>{r("|")}</m:e>'
             f"<m:sup>{r('3')}</m:sup></m:sSup></m:oMath></w:p>")
    assert group_scripted_brackets(cubed) == (
        '<w:p xmlns:w="w"><m:oMath><m:sSup><m:e><m:d><m:dPr><m:begChr m:val="|" />'
        f'<m:endChr m:val="|" /></m:dPr><m:e>{r("B")}</m:e></m:d></m:e>'
        f"<m:sup>{r('3')}</m:sup></m:sSup></m:oMath></w:p>")
    # a superscript asterisk (h_a^*) is the asterisk operator, a symbol to StarMath
    star = f"<m:oMath><m:sSup><m:e>{r('h')}</m:e><m:sup>{r('*')}</m:sup></m:sSup></m:oMath>"
    assert group_scripted_brackets(star) == star.replace("<m:t>*</m:t>", "<m:t>\u2217</m:t>")


def _runs(document_xml: str) -> list[tuple[str, str]]:
    """(run properties, text) of every text run."""
    return re.findall(r"<w:r>(?:<w:rPr>((?:(?!</w:rPr>).)*)</w:rPr>)?<w:t(?: [^>]*)?>([^<]*)</w:t></w:r>",
                      document_xml, flags=re.DOTALL)


def test_unit_signs_in_chinese_text_are_set_in_the_latin_font(tmp_path):
    """Issue 19 (7): pandoc hints every run holding Chinese text ``w:hint="eastAsia"``, and
    Word then draws U+00B0–00B4, 00B6–00BA, 00D7 of that run in the East-Asian font
    ([MS-OI29500] §2.1.88, rFonts), 宋体's full-width "·": "N · m". A sign in Latin text (a
    unit, a number) stands in a run without the hint; one between Chinese characters (the
    间隔号 of a name) keeps it; the text reads the same."""
    text = ("最大 12 738 N·m，最小 -84.70 N·m；角加速度 3.2 rad/s²（逆时针为正），压力角 19.69°（许用），"
            "白求恩·诺尔。\n\n| 位置 | （杆组法）/N·m | 说明 |\n|--|--:|--|\n"
            "| 0 | 1.0 | 刀线总长 L = 20.0 m（估计值）× 单位长度模切阻力 q = 50 N/mm |\n\n: 力矩\n")
    runs = _runs(_sample_document(tmp_path, "# 力矩\n\n" + text))
    latin = [t for p, t in runs if "·" in t or "²" in t or "°" in t]
    assert latin, "no run holds the signs"
    for props, run_text in runs:
        if 'w:hint="eastAsia"' not in props:
            continue
        for k, ch in enumerate(run_text):
            if ch in "·°²":
                # only between two Chinese characters of the run (a run ends at a space or
                # a formula: a sign at its end stands before Latin text or a number)
                assert 0 < k < len(run_text) - 1, run_text
                assert ord(run_text[k - 1]) > 0x2E80 and ord(run_text[k + 1]) > 0x2E80, run_text
    joined = "".join(t for _, t in runs)
    assert joined.count("N·m") == 3 and "rad/s²（" in joined and "19.69°（" in joined
    # the 间隔号 between Chinese characters keeps its (full-width) East-Asian form
    assert any('w:hint="eastAsia"' in p and "白求恩·诺尔" in t for p, t in runs)


def test_code_in_a_table_keeps_its_words_whole_and_listings_fit_the_line(tmp_path):
    """Issue 19 (1): the lock-beam appendix's table of stages and their result types broke
    "feed_verification" over four lines in Word (the column widths did not count code). A
    column of code is as wide as its longest word in Verbatim Char (Consolas, 1126/2048 em a
    character) plus the cell margins, and Verbatim Char is small enough that a listing line
    of 80 columns (render/summary.LISTING_WIDTH) fits the text width."""
    from mechdesign.render.summary import LISTING_WIDTH

    words = ["transmission", "bending_cam", "feed_verification", "feed_graphical"]
    rows = "\n".join(f"| {k} | stage {k} | `{w}` |" for k, w in enumerate(words, 1))
    out = _sample_docx(tmp_path, "# Appendix\n\n| No. | Stage | Result |\n|--:|:--|:--|\n"
                       + rows + "\n\n: Stages\n", EN_METADATA)
    styles = _part(out, "word/styles.xml")
    verbatim = re.search(r'<w:style [^>]*w:styleId="VerbatimChar".*?</w:style>', styles, re.DOTALL)
    assert "Consolas" in verbatim.group(0)
    half_points = int(re.search(r'<w:sz w:val="(\d+)"', verbatim.group(0)).group(1))
    em = 1126 / 2048
    assert LISTING_WIDTH * em * half_points / 2 <= _TEXT_WIDTH / 20
    table = re.search(r"<w:tbl>.*?</w:tbl>", _part(out, "word/document.xml"), flags=re.DOTALL).group(0)
    assert "feed_verification" in table
    grid = [int(w) for w in re.findall(r'<w:gridCol w:w="(\d+)"', table)]
    width = grid[2] / sum(grid) * _TEXT_WIDTH if 'w:tblW w:type="pct" w:w="5000"' in table else grid[2]
    longest = max(len(w) for w in words) * em * half_points * 10      # twips
    assert width >= longest + _CELL_MARGINS, (width, longest)


# ---- Word, laid out: LibreOffice's PDF of whole example reports ---------------------------
# LibreOffice lays the .docx out (not Word: its formulas come out narrower than Word's Cambria
# Math, so tests/test_typeset.py also checks every formula's width in the XML), and the PDF's
# characters are checked as the typst PDF's are: inside the text block (the margins of
# reference.docx), no equation number over another word. LibreOffice reads
# w:overflowPunct="0" (Normal; Word: no punctuation past the margin, ISO/IEC 29500-1
# §17.3.1.21) as its opposite (writerfilter/source/dmapper/DomainMapper.cxx: hanging
# punctuation = (value == 0)) and hangs a closing CJK punctuation mark at a line end into the
# margin: such a mark is let pass by up to one em. Review35 (slotter zh): every contents
# entry shows its page number, and no page is blank (a page break's paragraph of its own after
# a full contents page). Issue 19 point 2: no table caption alone at a page foot, at least
# three rows on each side of a table's break, the header row repeated. Every example brief in
# both languages is checked so by tests/test_typeset.py::test_every_report_stays_in_the_text_block,
# on the .docx that test renders anyway (LibreOffice takes some 5-40 s a report; skipped
# where soffice is not installed).
SOFFICE = shutil.which("soffice") or shutil.which("libreoffice")
_CJK_CLOSING = set("，。、；：？！）」』】》〉”’")


def _docx_margins() -> tuple[float, float]:
    """Left and right edges [pt] of the text block of reference.docx's A4 page."""
    xml = _part(TEMPLATES / "reference.docx", "word/document.xml")
    page = int(re.search(r'<w:pgSz\b[^>]*\bw:w="(\d+)"', xml).group(1))
    left = int(re.search(r'<w:pgMar\b[^>]*\bw:left="(\d+)"', xml).group(1))
    right = int(re.search(r'<w:pgMar\b[^>]*\bw:right="(\d+)"', xml).group(1))
    return left / 20, (page - right) / 20


def _outside_docx_block(pdf: Path) -> list[tuple[int, float, float, str]]:
    import pymupdf

    left, right = _docx_margins()
    bad = []
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            for block in page.get_text("rawdict")["blocks"]:
                for line in block.get("lines", []):
                    for span in line["spans"]:
                        for ch in span["chars"]:
                            c, (x0, _, x1, _) = ch["c"], ch["bbox"]
                            if c.isspace():
                                continue
                            if c in _CJK_CLOSING and x1 <= right + span["size"] + 1.0:
                                continue          # hung by LibreOffice (see above)
                            if x0 < left - 1.0 or x1 > right + 1.0:
                                bad.append((number, round(x0, 1), round(x1, 1), c))
    return bad


def libreoffice_pdf(docx: Path, folder: Path, profile: Path) -> Path:
    """``docx`` laid out by LibreOffice: its PDF in ``folder`` (``profile``: a LibreOffice
    user profile of the caller's own, no clash with a running soffice; made on first use)."""
    import subprocess

    folder.mkdir(parents=True, exist_ok=True)
    subprocess.run([SOFFICE, f"-env:UserInstallation={profile.as_uri()}", "--headless", "--convert-to", "pdf",
                    "--outdir", str(folder), str(docx)], check=True, capture_output=True, timeout=600)
    pdf = folder / (docx.stem + ".pdf")
    assert pdf.is_file()
    return pdf


def word_layout_defects(docx: Path, pdf: Path) -> dict[str, list]:
    """What LibreOffice's PDF of a Word report shows against issue 19 points 1 and 2 (see
    the comment above): characters outside the text block, equation numbers over words,
    contents entries without a page number, blank pages, captioned tables split badly
    (:func:`_table_breaks`), figure captions parted from their figures, a page ending in a
    lead-in ("…：" / "…:", as tests/test_typeset.py checks the PDF), a heading with fewer than
    three rows of its text under it at a page foot (tests/test_typeset.py's
    heading_at_page_foot, on LibreOffice's PDF outline). Called for every example brief × language by
    tests/test_typeset.py::test_every_report_stays_in_the_text_block on the .docx it renders
    (one render of each report serves both files' checks)."""
    from tests.test_typeset import colon_at_page_foot, heading_at_page_foot, numbers_over_words

    found = {"outside": _outside_docx_block(pdf), "numbers over words": numbers_over_words(pdf),
             "contents": _contents_without_page_numbers(pdf), "blank pages": _blank_pages(pdf),
             "tables": _table_breaks(docx, pdf), "figure captions": _figure_captions_alone(pdf),
             "lead-ins at a page foot": colon_at_page_foot(pdf),
             "headings at a page foot": heading_at_page_foot(pdf)}
    return {name: v for name, v in found.items() if v}


def _figure_captions_alone(pdf: Path) -> list[tuple[int, str]]:
    """(page, caption) of every figure caption ("图 N" / "Figure N:") that starts a page
    with no image above it: parted from its figure (reference.docx keeps the figure's
    paragraph with its caption, Captioned Figure: keep with next)."""
    import pymupdf

    from tests.test_typeset import _FIGURE_CAPTION, page_rows

    bad = []
    with pymupdf.open(pdf) as doc:
        for number, page in enumerate(doc, 1):
            rows = page_rows(page)
            if rows and _FIGURE_CAPTION.match(rows[0][2]) and not any(
                    info["bbox"][3] <= rows[0][0] + 1 for info in page.get_image_info()):
                bad.append((number, rows[0][2][:30]))
    return bad


def _flat(text: str) -> str:
    """Text without white space, hyphen-minus read as the minus sign (the PDF's and the XML's
    characters compared as one)."""
    return re.sub(r"\s+", "", text).replace("-", "\u2212")


def _captioned_tables(document_xml: str) -> list[tuple[str, list[list[str]]]]:
    """(caption, rows as lists of cell texts) of every data table with a caption."""
    found = []
    for m in re.finditer(r'(<w:p>(?:(?!<w:p>).)*?<w:pStyle w:val="TableCaption" />.*?</w:p>)'
                         r"(?:\s|<w:bookmark(?:Start|End)\b[^>]*/>)*(<w:tbl>.*?</w:tbl>)", document_xml, re.DOTALL):
        # a cell's text, each formula in it marked "\0" (LibreOffice sets it otherwise)
        rows = [["".join(re.findall(r"<w:t(?: [^>]*)?>([^<]*)</w:t>",
                                    re.sub(r"<m:oMath>.*?</m:oMath>", "<w:t>\0</w:t>", cell, flags=re.DOTALL)))
                 for cell in re.findall(r"<w:tc>.*?</w:tc>", row, re.DOTALL)]
                for row in _rows(m.group(2))]
        # a formula in the caption marked "\0": the caption is looked for up to it
        caption = re.sub(r"<m:oMath>.*?</m:oMath>", "<w:t>\0</w:t>", m.group(1), flags=re.DOTALL)
        found.append(("".join(_paragraph_texts(caption)), rows))
    return found


def _table_breaks(docx: Path, pdf: Path, keep: int = 3) -> list[tuple]:
    """(what, page, table) of every captioned table whose caption stands alone at a page's
    foot, which is split leaving fewer than ``keep`` body rows on a page, or whose header row
    is not repeated on a page it goes on to (issue 19 point 2). The rows are found in the
    PDF's text, in order, by their text (a row's whole text, or its longest piece between
    formulas: LibreOffice sets a formula's text otherwise; a single cell, "PASS", "0.000",
    could be the next row's), on the nearest page that has it; a row not found counts on
    either side of a break (no defect is made up from it)."""
    import pymupdf

    with pymupdf.open(pdf) as doc:
        pages = [_flat(page.get_text()) for page in doc]
    bad = []
    for caption, rows in _captioned_tables(_part(docx, "word/document.xml")):
        name = caption[:24]
        key = _flat(caption).split("\0")[0][:20]
        start = next((k for k, text in enumerate(pages) if key in text), None)
        if start is None:
            continue                                  # a caption with a formula: not read
        page, pos, where = start, pages[start].find(key) + len(key), []
        for row in rows:
            found = None
            pieces = [piece for piece in _flat("".join(row)).split("\0") if len(piece) >= 4]
            keys = [max(pieces, key=len)] if pieces else []
            for k in range(page, min(page + 3, len(pages))):      # the nearest page first
                for cell in keys:
                    i = pages[k].find(cell, pos if k == page else 0)
                    if i >= 0:
                        found = (k, i + len(cell))
                        break
                if found:
                    break
            if found:
                page, pos = found
            where.append(found[0] if found else None)
        if where and where[0] is not None and where[0] > start:
            bad.append(("caption alone at a page foot", start + 1, name))
        body = where[1:]
        parts = sorted({w for w in body if w is not None})
        if len(parts) < 2:
            continue
        lo = [body.index(p) for p in parts]
        hi = [len(body) - 1 - body[::-1].index(p) for p in parts]
        head = [_flat(c) for c in rows[0] if len(_flat(c)) >= 2 and "\0" not in c]
        for i, p in enumerate(parts):
            # the most rows this part can hold: those between the parts before and after it
            most = (lo[i + 1] if i + 1 < len(parts) else len(body)) - (hi[i - 1] if i else -1) - 1
            if most < keep:
                bad.append((f"{most} rows on a page of a split table", p + 1, name))
            if i and head and not any(h in pages[p] for h in head):
                bad.append(("header not repeated", p + 1, name))
    return bad


def _contents_without_page_numbers(pdf: Path) -> list[str]:
    """The contents page's entry lines (those with a dotted leader) that do not end in a page
    number no smaller than the contents page's own; [] also if there are no entries at all."""
    import pymupdf

    with pymupdf.open(pdf) as doc:
        lines = [line.strip() for line in doc[1].get_text().splitlines()]
    entries = [line for line in lines if "....." in line]
    if not entries:
        return ["(no entries)"]
    return [line for line in entries
            if not (re.search(r"\.(\d+)$", line) and int(re.search(r"(\d+)$", line).group(1)) >= 2)]


def _blank_pages(pdf: Path) -> list[int]:
    """Pages that hold at most a running header and a page number (two text lines)."""
    import pymupdf

    with pymupdf.open(pdf) as doc:
        return [number for number, page in enumerate(doc, 1)
                if number > 1 and len([ln for ln in page.get_text().splitlines() if ln.strip()]) <= 2
                and not page.get_image_info()]


def test_a_short_chinese_word_in_a_cell_is_never_broken(tmp_path):
    """Issue 19 (1): the verification tables of the zh reports (furnace drive, die-cutter,
    lock-beam) had their 结论 column squeezed to one character in Word, "合" over "格": the
    column widths let a line break between any two Chinese characters. A cell of one short
    word (at most four characters) keeps it on one line: its column is at least two
    characters of 10.5 pt (宋体's advance: 1 em) wide plus the cell margins and a little."""
    rows = [f"| 各轴转速 $n_{{k+1}} = n_k / i_k$（相对误差），第 {k} 对轴承与齿轮的功率与转矩平衡 "
            f"| {k}.0 | ≤ 1.0 × 10⁻⁹ | 合格 |" for k in range(6)]
    # a result written out in words widens the second column (the furnace drive's table 14)
    rows.append("| 各级传动比与齿数比、带轮直径比 | 由电动机转速与各级传动比逐级相乘得到的工作机转速与任务书要求的"
                "工作机转速之相对误差 0.542% | ≤ ±4.0% | 合格 |")
    document = _sample_document(tmp_path, "# 校核\n\n| 校核项目 | 结果 | 参考值 / 限值 | 结论 |\n|:--|--:|:--|:-:|\n"
                                + "\n".join(rows) + "\n\n: 校核\n")
    table = re.search(r"<w:tbl>.*?</w:tbl>", document, flags=re.DOTALL).group(0)
    style = re.search(r'<w:pStyle w:val="(TableText\w*)"', table).group(1)
    half_points = {"TableText": 21, "TableTextSmall": 18, "TableTextSmaller": 15}[style]
    grid = [int(w) for w in re.findall(r'<w:gridCol w:w="(\d+)"', table)]
    width = grid[3] / sum(grid) * _TEXT_WIDTH if 'w:tblW w:type="pct" w:w="5000"' in table else grid[3]
    # (1.5 pt of room: LibreOffice broke "合格" in a column of 639 twips, 3 more than the two
    # characters and the margins)
    assert width >= 2 * half_points * 10 + _CELL_MARGINS + 30, (width, grid)


def _rows(table: str) -> list[str]:
    return re.findall(r"<w:tr>.*?</w:tr>", table, flags=re.DOTALL)


def test_table_rows_never_split_and_a_short_table_stays_on_one_page(tmp_path):
    """Review35 (Word): a row broke across two pages ("实际中心距" cut into "…中心" / "距",
    slotter zh p. 31-32) and a short table left one row at a page foot (p. 35). Every row of
    a data table may not split (w:cantSplit) and the header row repeats (w:tblHeader); a
    table of at most SHORT_TABLE_ROWS rows keeps each row but the last with the next
    (w:keepNext on all its paragraphs: the whole table on one page); a longer one may break
    between rows, but keeps its header row and first KEEP_ROWS rows together and its last
    KEEP_ROWS rows (issue 19 point 2: LibreOffice left one row of linkage_sixbar zh's table 14
    on the next page, two of table 15)."""
    from mechdesign.render.docx_layout import SHORT_TABLE_ROWS
    from mechdesign.render.pdf import KEEP_ROWS

    def table(n_rows: int, caption: str) -> str:
        body = "".join(f"| 第 {k} 行 | {k}.0 |\n" for k in range(n_rows - 1))
        return f"| 名称 | 数值 |\n|:--|--:|\n{body}\n: {caption}\n\n"
    document = _sample_document(tmp_path, "# 表\n\n" + table(4, "短表") + table(SHORT_TABLE_ROWS + 5, "长表")
                                + "$$ x = 1 $$\n")
    tables = [t for t in re.findall(r"<w:tbl>.*?</w:tbl>", document, flags=re.DOTALL)
              if "EquationTable" not in t]
    assert [len(_rows(t)) for t in tables] == [4, SHORT_TABLE_ROWS + 5]
    for t in tables:
        rows = _rows(t)
        assert all("<w:trPr><w:cantSplit />" in row for row in rows)
        assert "<w:tblHeader" in rows[0] and not any("<w:tblHeader" in row for row in rows[1:])
    short, long = (_rows(t) for t in tables)
    for row in short[:-1]:
        paragraphs = re.findall(r"<w:p>.*?</w:p>", row, flags=re.DOTALL)
        assert paragraphs and all(re.match(r'<w:p><w:pPr><w:pStyle w:val="TableText\w*" /><w:keepNext />', p)
                                  for p in paragraphs), row[:300]
    assert "<w:keepNext" not in short[-1]
    kept = [k for k, row in enumerate(long) if "<w:keepNext" in row]
    n = len(long)
    assert kept == list(range(KEEP_ROWS)) + list(range(n - KEEP_ROWS, n - 1)), kept
    for k in kept:          # every paragraph of a kept row
        assert all("<w:keepNext />" in p for p in re.findall(r"<w:p>.*?</w:p>", long[k], flags=re.DOTALL))


def test_a_list_of_formulas_in_one_inline_formula_may_break_between_its_items(tmp_path):
    """Review35 (Word, slotter zh p. 25): "（峰值系数 $C_v = 2.000, C_a = 4.000, C_j = ∞$）"
    is one formula object, which LibreOffice does not break: it went to the next line whole
    and the justified line before it was letter-spaced ("推 程 0°–70°： 等 加 速 …"). The
    formula becomes one per item, with ", " as text between them; a comma inside brackets
    ("f(x, y)") or in a display formula stays in its formula."""
    document = _sample_document(tmp_path, "# 凸轮\n\n**推程 0°–70°：等加速等减速运动规律（抛物线）**"
                                "（峰值系数 $C_v = 2.000, C_a = 4.000, C_j = ∞$），"
                                "函数 $f(x, y)$。\n\n$$ a = 1, b = 2 $$\n")
    para = next(p for p in re.findall(r"<w:p>.*?</w:p>", document, flags=re.DOTALL) if "峰值系数" in p)
    formulas = ["".join(re.findall(r"<m:t>([^<]*)</m:t>", f)) for f in re.findall(r"<m:oMath>.*?</m:oMath>", para)]
    # the closing bracket and stop after a formula go into it (session 39, text39: a lone "）"
    # began the next line in LibreOffice)
    assert formulas == ["Cv=2.000", "Ca=4.000", "Cj=∞），", "f(x,y)。"]
    assert para.count('<w:t xml:space="preserve">, </w:t>') == 2
    display = re.search(r"<m:oMathPara>.*?</m:oMathPara>", document, flags=re.DOTALL).group(0)
    assert display.count("<m:oMath>") == 1 and "<m:t>,</m:t>" in display


# a hyphen-minus before a digit at a paragraph's (a cell's) start or after white space, an
# opening bracket, a relation or a separator: a number's sign, printed "−" in the PDF
_SIGNED_BY_HYPHEN = re.compile(r"(?:^|[\s(\[（=＝<>≤≥≈:：,，;；、~～])-\d")


def _hyphen_signed_numbers(document_xml: str) -> list[str]:
    """The paragraphs whose text (runs joined) holds a number signed by a hyphen-minus; code
    (a SourceCode paragraph, a run of inline code or of a highlighted token) is not read."""
    text = re.sub(r'<w:p><w:pPr><w:pStyle w:val="SourceCode" />.*?</w:p>', "", document_xml,
                  flags=re.DOTALL)
    text = re.sub(r'<w:r><w:rPr><w:rStyle w:val="(?:VerbatimChar|\w+Tok)" />.*?</w:r>', "", text,
                  flags=re.DOTALL)
    return [t for t in _paragraph_texts(text) if _SIGNED_BY_HYPHEN.search(t)]


def test_negative_numbers_take_the_minus_sign_and_designations_keep_their_hyphen(tmp_path):
    """Review36 Top 14: the Word file printed negative numbers with the hyphen-minus of the
    Markdown ("-6.946" in a cell, "ω₂ = -8.38 rad/s"), where the PDF has the minus sign
    U+2212. A hyphen that starts a number becomes "−", also across runs; one inside a word,
    a designation, a standard's number, a date or a range stays ("Y90S-6", "6204-2RS",
    "GB/T 276-1994", "2026-11-22", "表 8-11", "3-4-5"), and so does a formula's text."""
    document = _sample_document(tmp_path, (
        "# 数值\n\n角速度 $\\omega_2$ = -8.38 rad/s，最小 -84.70 N·m，坐标 (-190.54, 3.0)；"
        "电动机 Y90S-6，轴承 6204-2RS，GB/T 276-1994，日期 2026-11-22，表 8-11，3-4-5 多项式，"
        "**Y132S**-8，范围 20–300 mm，x-1。\n\n"
        "$$ M = -2468 \\times 0.5 $$\n\n"
        "| 位置 | $M_b$/N·m | 说明 |\n|:--|--:|:--|\n| 1 | -6.946 | 见表 15-3 |\n| 2 | -0.3215 | -- |\n\n: 力矩\n\n"
        "程序中 `y = -1` 不变：\n\n```python\nYO3 = -0.1\nx = [-2, 3]\n```\n"))
    assert _hyphen_signed_numbers(document) == []
    texts = "\n".join(_paragraph_texts(document))
    for signed in ("= \u22128.38", "最小 \u221284.70", "(\u2212190.54", "\u22126.946", "\u22120.3215"):
        assert signed.replace(" ", "\u00a0") in texts.replace(" ", "\u00a0"), signed
    for kept in ("Y90S-6", "6204-2RS", "GB/T 276-1994", "2026-11-22", "8-11", "3-4-5", "x-1", "15-3",
                 "20–300", "Y132S-8"):         # Y132S bold: its "-8" starts the next run
        assert kept in texts, kept
    # code, inline or a listing, is left as written
    code = "".join(t for p, t in _runs(document) if "Tok" in p or "VerbatimChar" in p)
    assert "y = -1" in code and "\u2212" not in code
    assert "".join(_paragraph_texts(document)).count("-0.1") == 1
    # the formula keeps pandoc's own minus (U+2212), untouched
    assert "<m:t>\u2212</m:t>" in document
    # in a run hinted eastAsia, the minus sign stands in a run of its own in the Latin font
    for props, run_text in _runs(document):
        if "\u2212" in run_text:
            assert 'w:hint="eastAsia"' not in props, run_text


def test_tables_are_centred_and_a_formula_after_a_table_stays_a_table_of_its_own(tmp_path):
    """Review36 Top 14 (LibreOffice): data tables stood at the left margin under their
    centred captions (pandoc writes a table narrower than the text without w:jc), and a
    numbered formula right after one looked right of centre. The formula's table
    (templates/docx-numbering.lua) touched the data table, and Word shows touching tables
    as one, under the first one's properties. Every table is centred; a formula's table is
    never right after a table of another style (a 6 pt paragraph between), and its
    properties are those of a formula after text."""
    document = _sample_document(tmp_path, (
        "# 表\n\n由下式：\n\n$$ a = b + c $$\n\n"
        "| 矢量 | 大小 |\n|:--|--:|\n| $v_A$ | 0.770 |\n\n: 速度\n\n"
        "$$ \\vec v_{A4} = \\vec v_{A3} + \\vec v_{A4A3} $$\n\n$$ v_B = v_{B5} $$\n\n文字。\n"))
    _assert_tables_centred_and_apart(document)
    from mechdesign.render.docx_layout import TABLE_SEPARATOR

    assert document.count(TABLE_SEPARATOR) == 1       # only between the data table and (2)


def _assert_tables_centred_and_apart(document: str) -> None:
    tables = list(re.finditer(r"<w:tbl>.*?</w:tbl>", document, flags=re.DOTALL))
    assert tables
    for t in tables:
        pr = re.match(r"<w:tbl><w:tblPr>(.*?)</w:tblPr>", t.group(0), flags=re.DOTALL).group(1)
        assert '<w:jc w:val="center" />' in pr, pr[:200]
    style = [re.match(r'<w:tbl><w:tblPr><w:tblStyle w:val="([^"]*)"', t.group(0)).group(1) for t in tables]
    assert "EquationTable" in style and "Table" in style
    for k in range(1, len(tables)):
        between = document[tables[k - 1].end():tables[k].start()]
        touching = re.fullmatch(r"(?:\s|<w:bookmark(?:Start|End)\b[^>]*/>)*", between) is not None
        assert not (touching and style[k - 1] != style[k]), (style[k - 1], style[k])
    # a formula after a table is set as one after text: the same table properties
    props = {re.match(r"<w:tbl><w:tblPr>.*?</w:tblPr>", t.group(0), flags=re.DOTALL).group(0)
             for t, s in zip(tables, style) if s == "EquationTable"}
    assert len(props) == 1, props


def test_a_lead_in_ending_in_a_colon_is_kept_with_what_it_introduces(tmp_path):
    """Issue 19 point 2 (Word, laid out by LibreOffice): 51 pages of the 28 example reports
    ended in a lead-in, "导杆长度、曲柄长度、连杆长度：" at the foot of shaper zh p.3 and its
    formulas on p.4. A paragraph ending in "：" or ":" keeps with the next block (w:keepNext);
    other paragraphs, table cells and program lines do not get it."""
    md = _write_sample(tmp_path, (
        "# 设计\n\n导杆长度、曲柄长度、连杆长度：\n\n$$ L = \\frac{H}{2} $$\n\n"
        "The torque follows from $T = 9550\\,P/n$:\n\n| 项目 | 说明： |\n|:--|:--|\n| a | b： |\n\n: 表\n\n"
        "普通的一句话。\n\n```python\ndef f():\n    return 1\n```\n"))
    out = tmp_path / "report.docx"
    render_docx(md, out, METADATA, TEMPLATES)
    document = _part(out, "word/document.xml")
    ElementTree.fromstring(document)
    outside = re.sub(r"<w:tbl>.*?</w:tbl>", "", document, flags=re.DOTALL)
    kept = {t for p, t in zip(re.findall(r"<w:p>.*?</w:p>", outside, flags=re.DOTALL),
                              _paragraph_texts(outside)) if "<w:keepNext />" in p}
    assert "导杆长度、曲柄长度、连杆长度：" in kept
    assert any(t.startswith("The torque follows from") for t in kept), kept
    assert not any(t.startswith(("普通", "def")) for t in kept), kept
    for table in re.findall(r"<w:tbl>.*?</w:tbl>", document, flags=re.DOTALL):
        if "说明：" in table:
            assert "<w:keepNext" not in _rows(table)[-1]


def test_a_heading_keeps_three_rows_of_its_text(tmp_path):
    """Issue 19 (Word, laid out by LibreOffice): "8.6 Stage 3: closed helical gear pair" stood
    at the foot of die_cutter en p.33 over two lines of its four-line paragraph, "References"
    at the foot of shaper en p.45 over a two-line first entry: the heading style keeps a
    heading with its next paragraph only, and widow control lets two lines of it stay. The
    blocks after a heading are kept with it until three rows (HEADING_ROWS) of text are: a
    paragraph of at most WHOLE_LINES lines whole (w:keepLines), and, while the rows are fewer,
    with the next block (w:keepNext; on every paragraph of a numbered formula's table); a
    long paragraph, a table caption and what follows them are left as they are."""
    from mechdesign.render.docx_layout import HEADING_ROWS, WHOLE_LINES

    assert HEADING_ROWS == 3 and WHOLE_LINES >= 4
    words = "the gear pair is checked for contact and root bending fatigue "   # 62 characters
    document = _sample_document(tmp_path, (
        "# Gears\n\n## Velocities\n\nLength scale 0.5 m/mm.\n\n$$ v_B = v_A + v_{BA} $$\n\n"
        "| a | b |\n|:--|--:|\n| 1 | 2 |\n\n: Velocities\n\n"
        "## Forces\n\nForce scale 10 N/mm.\n\n$$ F = \\frac{T}{r} $$\n\n"
        "| a | b |\n|:--|--:|\n| 1 | 2 |\n\n: Forces\n\n"
        # about four lines of 12 pt Times on 453.5 pt (62 characters ≈ 31 em, 37.8 em a line)
        "## Stage 3\n\n" + "Stage three: " + words * 4 + "\n\nNext paragraph of the section.\n\n"
        "## Cam\n\n" + "Purpose: " + words * 3 + "\n\n### Design data\n\nThe cam's data.\n\n"
        "## Long\n\n" + words * 12 + "\n\nAfter the long one.\n\n"
        "## References\n\n[1] First entry, " + words + "\n\n[2] Second entry.\n\n[3] Third entry.\n"),
        {**METADATA, "lang": "en"})
    blocks = re.findall(r"<w:tbl>.*?</w:tbl>|<w:p>(?:(?!</w:p>).)*</w:p>", document, flags=re.DOTALL)
    body = blocks[next(k for k, b in enumerate(blocks) if "Heading1" in b and "Gears" in b):]

    def after(title: str, n: int) -> list[str]:
        k = next(k for k, b in enumerate(body) if re.search(r'w:val="Heading\d"', b) and title in b)
        return [b for b in body[k + 1:] if _paragraph_texts(b) != [""] or "<w:tbl>" in b][:n]

    # a one-line paragraph and a formula (two rows): both kept with the next block; the
    # formula as one paragraph (LibreOffice keeps no table with the next block: crank_rocker
    # en p.12 "5.2.1 Velocities", the scale, formula (30), then the table on the next page),
    # centred on a tab stop at the middle of the text, its number on one at the right edge;
    # the data table's caption is kept by its style
    line, formula, caption = after("Velocities", 3)
    assert "<w:keepNext /><w:keepLines />" in line
    assert formula.startswith("<w:p>") and "<w:keepNext />" in formula and "<m:oMathPara>" not in formula
    assert re.findall(r'<w:tab w:val="(\w+)" w:pos="(\d+)" />', formula) == [("center", "4535"),
                                                                         ("right", "9070")]
    assert re.search(r"<w:tab />.*<m:oMath>.*</m:oMath><w:r><w:tab /></w:r>.*\(.*SEQ Equation.*\)",
                     formula, flags=re.DOTALL)
    assert "TableCaption" in caption and "<w:keepLines" not in caption
    # a fraction is set smaller by Word in a line than displayed: that formula stays a table,
    # kept with the next block on every paragraph (Word keeps it; LibreOffice does not)
    line, formula, caption = after("Forces", 3)
    assert "EquationTable" in formula and "<m:f>" in formula and all(
        "<w:keepNext />" in p for p in re.findall(r"<w:p>.*?</w:p>", formula, flags=re.DOTALL))
    # a four-line paragraph: kept whole, three rows reached, the next paragraph left alone
    four, nxt = after("Stage 3", 2)
    assert "<w:keepLines />" in four and "<w:keepNext" not in four
    assert "<w:keep" not in nxt
    # a paragraph of (estimated) three rows with a heading after it: kept with that heading
    # too (shaper en: the purpose paragraph, three lines estimated, took two in LibreOffice;
    # "7 Cam mechanism" stood over them at the foot of p.23, "7.1" and its table on p.24)
    purpose, heading = after("Cam", 2)
    assert "<w:keepNext /><w:keepLines />" in purpose and "Heading3" in heading
    # a long paragraph: widow control's two lines are all Word can do
    long, nxt = after("Long", 2)
    assert "<w:keep" not in long and "<w:keep" not in nxt
    # a short reference list (≤ 16 entries) is kept whole with its heading (session 39,
    # text39: die_cutter en's last Word page held three references alone)
    first, second, third = after("References", 3)
    assert "<w:keepNext /><w:keepLines />" in first and "<w:keepNext /><w:keepLines />" in second
    assert "<w:keep" not in third       # the last entry: the one the others keep with
