"""Typeset, never raw (issue 19, point 3): symbols with subscripts in tables, captions,
headings and prose are math, not plain letters ("γmin", "p'n4'", "μa" → γ_min, p′n′₄, μ_a);
a formula in a table cell is set at the cell's text size; an en heading's apostrophe is the
Latin face's; the lock-beam's program listing is English and never cut inside a name; a
cross-reference is written once.

The Markdown of every example brief in both languages is rendered as ``mechdesign run``
writes it (tests/test_handin.py's ``render``, placeholder figures) and read outside its
math, code and listing; the typst rules are checked in small PDFs rendered by the report's
own pipeline, whose characters (font, size) PyMuPDF reads.
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from test_handin import EXAMPLES, LANGS

ROOT = Path(__file__).resolve().parents[1]
TEMPLATE = ROOT / "templates" / "report.typ"


def prose(md: str) -> list[tuple[int, str]]:
    """(line number, text) of the report outside fenced code, with inline and display math,
    code spans, figure paths and attributes taken out."""
    out, fenced = [], False
    for i, line in enumerate(md.splitlines(), 1):
        if line.startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        s = re.sub(r"\$\$.*?\$\$", " ", line)
        s = re.sub(r"\$[^$]*\$", " ", s)
        s = re.sub(r"`[^`]*`", " ", s)
        s = re.sub(r"\]\([^)]*\)", "]", s)
        s = re.sub(r"\{[#.][^}]*\}", " ", s)
        out.append((i, s))
    return out


# A Greek symbol with a plain-letter subscript (γmin, αmax, φ1, ω4, ψ3), a drawing scale
# (μl, μv, μa, μF) and a polygon segment in a table cell (p'n4', ns3's3', pa4, aa4).
GREEK_SUB = re.compile(r"(?<![\w\\])[α-ω](?:min|max|\d)(?![\w])")
SCALE = re.compile(r"(?<![\w\\])μ[lvaF](?![\w])")
SEGMENT = re.compile(r"^[a-z]{1,2}\d*'?[a-z]{1,2}\d*'?$")
# user text, written as the brief has it: the textbook exercise's position label "φ45"
# (designs/textbook_guide_bar.yaml, polygon_positions)
USER_LABELS = {"φ45"}


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", EXAMPLES)
def test_symbols_with_subscripts_are_typeset(handin_reports, name, lang):
    md = handin_reports(name, lang)[0]
    raw = []
    for i, text in prose(md):
        for m in GREEK_SUB.finditer(text):
            if m.group(0) not in USER_LABELS:
                raw.append((i, m.group(0), text.strip()[:80]))
        raw += [(i, m.group(0), text.strip()[:80]) for m in SCALE.finditer(text)]
        if text.startswith("|"):
            for cell in (c.strip() for c in text.strip().strip("|").split("|")):
                if SEGMENT.match(cell) and re.search(r"[\d']", cell):
                    raw.append((i, cell, text.strip()[:80]))
    assert raw == []


def test_polygon_segments_and_vertices_are_math():
    """The polygon's segment as the table writes it and a vertex as the figure labels it."""
    from mechdesign.render.graphical_report import segment, vertex_label

    assert segment("p'", "n4'") == "$p'n_{4}'$"
    assert segment("ns3'", "s3'") == "$n_{s3}'s_{3}'$"
    assert segment("a", "a4") == "$aa_{4}$"
    assert segment("p", "b") == "$pb$"
    # the figure's prime is U+2032 before the subscript (mathtext draws "'" as a "0")
    assert vertex_label("nb'") == "$n′_{b}$"
    # a name of another form is drawn as written (never as broken mathtext)
    assert segment("E_1", "p") == "E_1p"
    assert vertex_label("s6(P)'") == "s6(P)′"


DOUBLED_REF = re.compile(r"(图|表|式|Figure|Fig\.|Table|Eq\.|Equation)\s*\[?@(fig|tbl|eq):")


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", EXAMPLES)
def test_cross_references_are_written_once(handin_reports, name, lang):
    """A reference's word ("图", "Table") comes from typst's supplement: the Markdown never
    writes it in front of @fig/@tbl/@eq, and never twice."""
    md = handin_reports(name, lang)[0]
    doubled = [(i, t.strip()[:80]) for i, t in prose(md)
               if DOUBLED_REF.search(t) or re.search(r"(图|表)\s+\1\s*\d|\b(Table|Figure) \2\b", t)]
    assert doubled == []


def _spans(pdf: Path):
    import pymupdf

    with pymupdf.open(pdf) as doc:
        for page in doc:
            for block in page.get_text("dict")["blocks"]:
                for line in block.get("lines", ()):
                    yield from line["spans"]


def _render(tmp_path: Path, md: str, lang: str) -> Path:
    from types import SimpleNamespace

    from mechdesign.render.pdf import render_pdf
    from mechdesign.render.report import pdf_metadata

    meta = SimpleNamespace(title="T", title_en="T", subtitle="", subtitle_en="", student="",
                           student_id="", class_name="", teacher="", date="2024-06-01")
    data = pdf_metadata(meta, lang)          # the report's fonts: en Latin first
    md_path = tmp_path / "report.md"
    md_path.write_text(md, encoding="utf-8")
    pdf = tmp_path / "report.pdf"
    render_pdf(md_path, pdf, data, TEMPLATE)
    return pdf


@pytest.mark.e2e
def test_en_heading_apostrophe_is_the_latin_one(tmp_path):
    """The en report's headings are set in the sans list, which starts with the CJK sans:
    its apostrophe (typst's smart quote) is full-width. It is the Latin serif's now."""
    pdf = _render(tmp_path, "# The machine's motion scheme\n\nThe seed's text.\n", "en")
    quotes = [s["font"] for s in _spans(pdf) if "\u2019" in s["text"] or "'" in s["text"]]
    assert quotes and all("Libertinus" in f for f in quotes), quotes


@pytest.mark.e2e
def test_fraction_in_a_table_cell_is_set_at_the_cell_size(tmp_path):
    """Inline math in a cell set its fraction's numerator and denominator in script size
    (about 6 pt in a 9 pt table): the press/shaper/slotter α′ row, the furnace pusher's
    check of the seed's equations. They are the cell's 9 pt now, and the row grows to hold
    the fraction: nothing of it runs into the rows above and below."""
    md = ("| Quantity | Formula |\n|:--|:--|\n"
          "| standard centre distance | $m(z_1+z_2)/2$ |\n"
          "| working pressure angle | $\\mathrm{inv}\\,\\alpha' = "
          "\\frac{2(x_1+x_2)\\tan\\alpha}{z_1+z_2}+\\mathrm{inv}\\,\\alpha$ |\n"
          "| working centre distance | $a\\cos\\alpha/\\cos\\alpha'$ |\n\n: Meshing data\n")
    pdf = _render(tmp_path, md, "en")
    spans = list(_spans(pdf))
    num = [s for s in spans if "tan 𝛼" in s["text"]]          # the numerator's last part
    inv = [s for s in spans if s["text"].startswith("inv")]    # at the cell's size
    assert num and inv
    assert num[0]["size"] == pytest.approx(inv[0]["size"], abs=0.05), (num, inv)
    # the fraction lies between the rows around it: the numerator below the formula of the
    # row above, the denominator above the row below
    col = inv[0]["bbox"][0] - 1
    prev = [s for s in spans if s["bbox"][0] >= col and "𝑚(𝑧" in s["text"]]
    nxt = [s for s in spans if "working centre" in s["text"]]
    den = [s for s in spans if "𝑧" in s["text"] and s["bbox"][1] >= num[0]["bbox"][3] - 1]
    assert prev and nxt and den
    assert prev[0]["bbox"][3] <= num[0]["bbox"][1] + 0.5, (prev, num)
    assert max(s["bbox"][3] for s in den) <= nxt[0]["bbox"][1] + 0.5, (den, nxt)
