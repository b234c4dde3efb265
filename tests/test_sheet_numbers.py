"""Issue 19 point 8 on the drawing sheets: every number a sheet prints (tables, dimensions,
labels, notes, title block) is written by the report's rule (render/fmt.py), with the true
minus sign (U+2212), never E-notation, a negative zero or a hyphen-minus before a digit.

The scan (tests/sheet_numbers.py) reads the text of every sheet of every example brief as a
reader gets it: the PDF's text layer (PyMuPDF, a line's spans joined: a subscript follows its
letter) and the DXF's TEXT and MTEXT entities and the texts of its DIMENSION blocks (what CAD
shows for a measured dimension). The base commit (6d985f2) failed it: "MI4 = -4.086 N·m"
(hyphen-minus), "R16.254" and "54.062" (a length to 0.001 mm; the DXF showed 16.25 for the
same dimension), "ΔWmax = 278.04 J" (five significant digits), "ε = 1.6364", "202.974",
"FR23 = 12060 N" (five integer digits not grouped).
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from sheet_numbers import dxf_plain, rule_breaks

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted(p.stem for p in (ROOT / "designs").glob("*.yaml") if p.stem != "__init__")


# ------------------------------------------------------------------------------ the scan


@pytest.mark.parametrize("text", [
    "MI4 = -4.086 N·m", "R92.505", "ΔWmax = 278.04 J", "0.003102 m/s 4.8e+04", "54.062",
    "FR23 = 12060 N", "−0.00", "v = 1.23456 m/s", "α = 12.345°", "e = 0.0123 mm", "P = 3333.33 W",
    "-0", "ε = 1.6364", "d'n5' = 0.0000000000000000000000000000000003594 m/s²",
])
def test_the_scan_finds_what_breaks_the_rule(text):
    assert rule_breaks(text), text


@pytest.mark.parametrize("text", [
    "M\u2212I4 = \u22124.086 N·m".replace("\u2212I", "I"), "R92.51", "ΔWmax = 278.0 J",
    "0.003102 m/s", "FR23 = 12\u00a0060 N", "12\u202f738 N·m", "54.06", "e = 0.012 mm",
    "1:2.5", "μL = 0.005 m/mm", "Y90S-6", "2026-11-26", "φ = 137.71°–196.36°", "K = 1.250",
    "α′ = 20.00°", "1.636", "O2A = 57.04 mm", "FR12", "0", "−30", "B1B2 / pb",
])
def test_the_scan_passes_what_the_rule_writes(text):
    assert not rule_breaks(text), (text, rule_breaks(text))


def test_the_dxf_text_is_read_as_shown():
    assert dxf_plain("M\\S^ I4; = −4.086 N·m") == "MI4 = −4.086 N·m"
    assert dxf_plain("\\{50%%%\\}") == "{50%}"


# ------------------------------------------------------------------------------ the sheets


def _pdf_lines(pdf: Path) -> list[str]:
    import pymupdf

    out = []
    with pymupdf.open(pdf) as doc:
        for page in doc:
            for block in page.get_text("dict")["blocks"]:
                for line in block.get("lines", []):
                    out.append("".join(s["text"] for s in line["spans"]))
    return out


def _dxf_lines(dxf: Path) -> list[str]:
    import ezdxf

    out = []
    for e in ezdxf.readfile(dxf).modelspace().query("TEXT MTEXT DIMENSION"):
        if e.dxftype() == "DIMENSION":           # what CAD shows: the block's text
            out += [dxf_plain(t.text if t.dxftype() == "MTEXT" else t.dxf.text)
                    for t in e.get_geometry_block().query("TEXT MTEXT")]
        else:
            out.append(dxf_plain(e.text if e.dxftype() == "MTEXT" else e.dxf.text))
    return out


@pytest.mark.e2e
@pytest.mark.parametrize("name", EXAMPLES)
def test_every_sheet_number_follows_the_rule(example_results, name, tmp_path):
    from mechdesign.brief.loader import load_brief
    from mechdesign.render.sheets import _builders, write_all

    brief = load_brief(ROOT / "designs" / f"{name}.yaml")
    meta = brief.report
    # the title block's fields from the brief are printed as written (a student number)
    user = {str(getattr(meta, k, "")) for k in ("student", "student_id", "class_name", "teacher",
                                                 "date", "title", "title_en")} - {""}
    bad = []
    checked = 0
    for lang in ("zh", "en"):
        folder = tmp_path / lang
        (folder / "f").mkdir(parents=True)
        files = write_all(_builders(example_results(name), brief), brief, folder, folder / "f",
                          lang, ("pdf", "dxf"))
        for f in files:
            for path, lines in ((f.pdf, _pdf_lines(folder / f.pdf)), (f.dxf, _dxf_lines(folder / f.dxf))):
                assert lines, path
                checked += 1
                for line in lines:
                    if line.strip() in user:
                        continue
                    bad += [f"{lang} {path}: {b}" for b in rule_breaks(line)]
    assert checked
    assert not bad, f"{len(bad)} numbers break the rule:\n" + "\n".join(bad[:25])


def test_sheet_modules_write_numbers_through_fmt():
    """No sheet module formats a printed number itself (a format spec ``:.2f``, ``:g``): the
    one rule is render/fmt.py's. Not printed: an error message, the drawing number's
    ``-01``, the typst source's coordinates (sheet_typst ``_num``)."""
    spec = re.compile(r"\{[^{}\"']*:[^{}\"']*[efg%]\}")
    found = []
    for path in sorted((ROOT / "src/mechdesign/render").glob("*sheet*.py")):
        for j, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            code = line.split("#")[0]
            if spec.search(code) and "raise " not in code and "isfinite" not in code:
                found.append(f"{path.name}:{j}: {line.strip()}")
    assert not found, "\n".join(found)
