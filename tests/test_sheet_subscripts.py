"""Issue 19 point 3 on the drawing sheets: symbols typeset with real subscripts (φ_max, ρ_min,
μ_v, μ_a, μ_F, μ_L, d_a, d_b, p_b, ω_1 …), not as plain letters ("φmax", "μv"); the DXF layer
descriptions name the line types as GB/T 4457.4 does (细点画线, 细虚线).

A subscript is marked in a sheet text (render/sheet.py ``sub``); typst draws it smaller and
lowered (``sub(typographic: false)``), so in the PDF it is a span of its own, smaller than the
letter before it (read with PyMuPDF); the DXF writes the text as an MTEXT whose subscript is
stacked below an empty top (``\\S^ v;``, AutoCAD's subscript), since the DXF text font (Noto
Sans SC) has no Unicode subscript characters.
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from mechdesign.render.sheet import (LAYERS, SUB_ON, Sheet, plain, split_subscripts, sub,
                                     with_subscripts)

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ["shaper", "crank_rocker", "cam_7_3", "cam_7_1", "lockbeam", "furnace_drive",
            "die_cutter", "furnace_pusher", "linkage_sixbar", "textbook_guide_bar", "press",
            "lockbeam_cam", "slotter"]
# the labels the sheets used to write with plain-letter subscripts (a word of its own);
# "pb" is left out: in a velocity polygon it is the segment p→b, not p with subscript b;
# the force polygons' names (R12, FI3, MI3, Mb …) and the point names: tests/test_point_names.py
OLD = re.compile(r"(?<![A-Za-z0-9])(φmax|αmax|α′max|ρmin|ρa,min|μ[vaFLsφδ]|ω\d|ΔWmax|Md|JF|"
                 r"d[abf]|r[0r]|r[abf]\d|ha\*|B1B2|N1N2)(?![A-Za-z0-9])")


def test_sub_marks_split_and_plain():
    t = sub("μ", "v") + " = 0.01 (m/s)/mm"
    assert split_subscripts(t) == [("μ", False), ("v", True), (" = 0.01 (m/s)/mm", False)]
    assert plain(t) == "μv = 0.01 (m/s)/mm"
    # a symbol is marked where it stands as a word only
    assert with_subscripts("μv, μa、μF 注在上方; μvx", "μ_v", "μ_a", "μ_F") == \
        f"{sub('μ', 'v')}, {sub('μ', 'a')}、{sub('μ', 'F')} 注在上方; μvx"
    assert with_subscripts("ΔWmax = 3 J", "ΔW_max") == sub("ΔW", "max") + " = 3 J"


def test_typst_draws_a_subscript_with_sub():
    from mechdesign.render.sheet_typst import sheet_source

    s = Sheet("A4")
    s.text(10 + 10j, sub("φ", "max") + " = 15°", 3.5)
    s.text(10 + 20j, "φmax as written", 3.5)
    src = sheet_source(s)
    assert '("φ" + sub(typographic: false, "max") + " = 15°")' in src
    assert '"φmax as written"' in src and SUB_ON not in src


def test_dxf_writes_a_subscript_as_a_stacked_mtext(tmp_path):
    import ezdxf

    from mechdesign.render.sheet_dxf import write_dxf

    s = Sheet("A4")
    s.text(10 + 10j, sub("ρ", "a,min") + " = 3 mm {50%}", 3.5, halign="right", valign="top",
           angle=0.5)
    s.text(10 + 20j, "plain 50%", 3.5)
    s.dimension(0j, 20 + 0j, 0.0, 20.0, sub("r", "a1") + " = 20", "radius")
    doc = ezdxf.readfile(write_dxf(s, tmp_path / "s.dxf"))
    msp = doc.modelspace()
    (m,) = msp.query("MTEXT")
    # \S^ a,min; : the subscript below an empty top; braces escaped, % as DXF writes it
    assert m.text == "ρ\\S^ a,min; = 3 mm \\{50%%%\\}"
    assert m.dxf.attachment_point == 3 and abs(m.dxf.rotation - 28.6479) < 1e-3
    assert m.dxf.char_height == 3.5 and m.dxf.layer == "TEXT"
    assert [t.dxf.text for t in msp.query("TEXT")] == ["plain 50%%%"]
    (d,) = msp.query("DIMENSION")
    assert d.dxf.text == "r\\S^ a1; = 20"
    # the extents: the sheet, not a wrapped narrow MTEXT column
    assert doc.header["$EXTMAX"][0] <= s.width + 1e-9


def test_layer_descriptions_use_the_gb_line_type_names():
    """GB/T 4457.4: 细点画线 (centre lines), 细虚线 (hidden lines); 粗实线, 细实线."""
    assert LAYERS["CENTER"].description.startswith("细点画线 ")
    assert LAYERS["HIDDEN"].description.startswith("细虚线 ")
    assert LAYERS["OUTLINE"].description.startswith("粗实线 ")
    assert LAYERS["CONSTRUCTION"].description.startswith("细实线 ")


def _lines(pdf: Path):
    """The spans of every text line of the PDF (PyMuPDF)."""
    import pymupdf

    with pymupdf.open(pdf) as doc:
        for page in doc:
            for block in page.get_text("dict")["blocks"]:
                for line in block.get("lines", []):
                    yield line["spans"]


def _is_sub(a: dict, b: dict) -> bool:
    """Span ``b`` is a subscript of span ``a`` (smaller, lower)."""
    return bool(a["text"].strip()) and b["size"] < 0.8 * a["size"] and b["origin"][1] > a["origin"][1]


def _old_labels(pdf: Path) -> list[str]:
    """The old plain-letter labels in the full-size spans (a subscript span holds "R12" of
    F_R12 rightly)."""
    found = set()
    for spans in _lines(pdf):
        for j, b in enumerate(spans):
            if j and _is_sub(spans[j - 1], b):
                continue
            found.update(OLD.findall(b["text"]))
    return sorted(found)


def _subscripts(pdf: Path) -> set[str]:
    """"base_index" for every span drawn smaller and lower right after a letter."""
    out = set()
    for spans in _lines(pdf):
        for a, b in zip(spans, spans[1:]):
            if _is_sub(a, b):
                out.add(a["text"].rstrip()[-1] + "_" + b["text"])
    return out


@pytest.mark.e2e
@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_sheet_pdfs_have_no_plain_letter_subscripts(example_results, name, lang, tmp_path):
    from conftest import read_pdf_text

    from mechdesign.brief.loader import load_brief
    from mechdesign.render.sheets import _builders, write_all

    brief = load_brief(ROOT / "designs" / f"{name}.yaml")
    (tmp_path / "f").mkdir()
    files = write_all(_builders(example_results(name), brief), brief, tmp_path, tmp_path / "f",
                      lang, ("pdf",))
    assert files
    for f in files:
        pdf = tmp_path / f.pdf
        old = _old_labels(pdf)
        assert not old, (name, lang, f.pdf, old)
        subs = _subscripts(pdf)
        text = read_pdf_text(pdf)
        kind = Path(f.pdf).stem.rsplit("_", 1)[0]          # "bending_cam_A2": bending_cam
        if kind == "analysis":
            assert {"μ_v", "μ_a", "μ_L"} <= subs and any(x.startswith("ω_") for x in subs), \
                (name, subs)
            assert "μv" in text.replace(" ", "")      # the letters stay text (searchable)
        if kind == "cam" or kind.endswith("_cam"):       # one sheet per cam (lockbeam: two)
            assert {"ρ_min", "r_0"} <= subs, (name, subs)
            if "φmax" in text:                          # an oscillating follower
                assert "φ_max" in subs, (name, subs)
        if kind == "gear":
            assert {"d_a", "d_b", "d_f", "p_b", "ω_1", "ω_2", "h_a"} <= subs, (name, subs)



def test_sheet_pdf_names_drawing_student_and_project(tmp_path):
    """Review finding: the sheet PDFs carried no metadata (pdfinfo: only "Creator: Typst").
    Like the report, a sheet's PDF names its drawing (title), the student (author) and the
    project (subject), read back from the PDF's Info dictionary (parsed here, no PDF library)."""
    from mechdesign.render.sheet import TitleInfo, frame
    from mechdesign.render.sheet_typst import write_sheet

    s = Sheet("A3")
    frame(s, TitleInfo("机构运动简图", "牛头刨床设计", "张三", "2023001", "机械 1", "李老师", "2026-11-26"))
    pdf = tmp_path / "k.pdf"
    write_sheet(s, pdf)
    raw = pdf.read_bytes()
    # typst writes the Info strings as UTF-16BE hex or literal strings; decode both
    texts = []
    for m in re.finditer(rb"/(Title|Author|Subject)\s*(<[0-9A-Fa-f]+>|\((?:\\.|[^)])*\))", raw):
        v = m.group(2)
        if v.startswith(b"<"):
            b = bytes.fromhex(v[1:-1].decode())
            texts.append((m.group(1).decode(), b[2:].decode("utf-16-be") if b[:2] == b"\xfe\xff" else b.decode("latin-1")))
        else:
            b = re.sub(rb"\\(.)", rb"\1", v[1:-1])
            texts.append((m.group(1).decode(), b[2:].decode("utf-16-be") if b[:2] == b"\xfe\xff" else b.decode("utf-8")))
    found = dict(texts)
    assert found.get("Title") == "机构运动简图" and found.get("Author") == "张三", found
    assert found.get("Subject") == "牛头刨床设计", found
