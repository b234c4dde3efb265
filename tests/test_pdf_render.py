"""Rendering of a small Chinese report: Markdown -> typst -> PDF."""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

pytest.importorskip("pypandoc")
pytest.importorskip("typst")
matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

from mechdesign.render.fonts import cjk_families, configure_matplotlib  # noqa: E402
from mechdesign.render.pdf import PdfRenderError, markdown_to_typst, render_pdf  # noqa: E402
from conftest import read_pdf_text

TEMPLATE = Path(__file__).parents[1] / "templates" / "report.typ"
METADATA = {
    "title": "机械原理课程设计说明书",
    "subtitle": "牛头刨床导杆机构",
    "student": "张三",
    "student_id": "2021012345",
    "class": "机械 2101 班",
    "teacher": "李四",
    "date": "2024 年 6 月",
    "lang": "zh",
}
MARKDOWN = """\
# 运动分析

曲柄转速 $n_2 = 60\\ \\text{r/min}$，极位夹角 $\\psi = 16.36°$。结果见 @tbl:kin 与 @fig:ram。

$$ \\theta = 180° \\times \\frac{K-1}{K+1}, \\qquad L_{O_3B} = \\frac{H}{2\\sin(\\theta/2)} $$

| $\\varphi$/° | $s_5$/mm | $v_5$/(m/s) |
|---:|---:|---:|
| 0 | 12.50 | 0.314 |
| 30 | 25.10 | 0.628 |

: 各位置运动参数 {#tbl:kin}

![刨头位移线图](figures/ram.png){#fig:ram width=70%}
"""


def _chinese_figure(path: Path) -> None:
    """Save a small matplotlib figure with Chinese labels to ``path``."""
    configure_matplotlib()
    from matplotlib.figure import Figure

    fig = Figure(figsize=(4, 2.5))
    ax = fig.add_subplot()
    ax.plot([0, 90, 180, 270, 360], [0, 1, 0, -1, 0])
    ax.set_xlabel("曲柄转角 $\\varphi$ / (°)")
    ax.set_ylabel("位移 / mm")
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=80)


def test_configure_matplotlib_has_chinese_glyphs():
    configure_matplotlib()
    configure_matplotlib()  # idempotent
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(3, 2))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    ax.plot([-1, 0, 1], [1, -1, 0])
    ax.set_title("刨头运动线图")
    ax.set_xlabel("曲柄转角 $\\omega_2 t$ / rad")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        fig.canvas.draw()
    missing = [str(w.message) for w in caught if "missing" in str(w.message).lower()]
    assert not missing, missing


def test_markdown_to_typst_metadata_and_refs(tmp_path):
    source = markdown_to_typst(MARKDOWN, TEMPLATE, METADATA, tmp_path)
    assert "机械原理课程设计说明书" in source
    assert "指导教师" in source  # default Chinese label
    assert f'"{cjk_families()["serif"]}"' in source
    assert "#ref(<tbl:kin>)" in source and "#cite(" not in source
    assert "math.equation(numbering" in source


@pytest.mark.e2e
def test_render_pdf_embeds_chinese_fonts(tmp_path):
    _chinese_figure(tmp_path / "figures" / "ram.png")
    md_path = tmp_path / "report.md"
    md_path.write_text(MARKDOWN, encoding="utf-8")
    pdf_path = tmp_path / "out" / "report.pdf"

    render_pdf(md_path, pdf_path, METADATA, TEMPLATE)

    data = pdf_path.read_bytes()
    assert data.startswith(b"%PDF")
    assert not list(tmp_path.glob(".*.typ")), "temporary typst source left behind"
    assert not list(pdf_path.parent.glob(".*.tmp*")), "temporary PDF left behind"
    text = read_pdf_text(pdf_path)
    for phrase in ("机械原理课程设计说明书", "指导教师", "运动分析", "表 1", "图 1"):
        assert phrase in text, phrase
    if cjk_families()["serif"] == "Noto Serif SC":  # fonts from pylopdf_fonts_zh_cn
        assert b"NotoSerifSC" in data and b"NotoSansSC" in data


@pytest.mark.e2e
def test_render_pdf_reports_typst_errors(tmp_path):
    md_path = tmp_path / "bad.md"
    md_path.write_text("# 标题\n\n![缺图](figures/none.png)\n", encoding="utf-8")
    with pytest.raises(PdfRenderError, match="none.png"):
        render_pdf(md_path, tmp_path / "bad.pdf", METADATA, TEMPLATE)
    assert not (tmp_path / "bad.pdf").exists()


def test_table_cell_starting_with_equals_is_text_not_a_heading(tmp_path):
    md = "| a | b |\n|--|--|\n| = 5 mm | x |\n"
    src = markdown_to_typst(md, TEMPLATE, {"title": "t"}, tmp_path)
    # pandoc escapes it ([\= 5 mm]), or the unit filter joins it with no-break spaces
    # ([=~5~mm]): either way "=" is not followed by a space, so typst reads no heading
    assert ("[\\= 5 mm]" in src or "[=~5~mm]" in src) and "[= 5 mm]" not in src
    md_path = tmp_path / "t.md"
    md_path.write_text(md, encoding="utf-8")
    render_pdf(md_path, tmp_path / "t.pdf", METADATA, TEMPLATE)
    assert "= 5 mm" in read_pdf_text(tmp_path / "t.pdf")      # a heading would drop the "="
