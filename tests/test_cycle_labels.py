"""Issue 19 point 8: the motion cycle diagram's phase names stand clear of the lines of
their bar (the base commit set a rise's name 1 mm from its transition line, whose 0.5 mm
stroke left 0.75 mm: the names touched the lines on the die-cutter's sheet).

Read from the sheet's PDF as printed (PyMuPDF's boxes of the text spans, which hold the
glyphs' ascent and descent) against the sheet's transition lines (0.5 mm vertical lines
inside a bar) and diagonals (a rise or return): between a name and a line's edge there is
at least 1 mm of paper."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from mechdesign.render.sheet import Line, Polyline, TitleInfo

CLEAR = 1.0          # paper between a name and a line's edge [mm]
PT = 25.4 / 72.0     # mm per PDF point


def _cycle(results, lang, tmp_path):
    from mechdesign.render.sheet_typst import write_sheet
    from mechdesign.render.sheets import _builders

    build = dict(_builders(results, None))["cycle"]
    s = build(TitleInfo("运动循环图", "test", number="T-03"), lang)
    pdf = tmp_path / f"cycle_{lang}.pdf"
    write_sheet(s, pdf)
    return s, pdf


def _spans(pdf: Path, height: float):
    """(text, (x0, y0, x1, y1) in paper mm, y up) of every text span."""
    import pymupdf

    out = []
    with pymupdf.open(pdf) as doc:
        for block in doc[0].get_text("dict")["blocks"]:
            for line in block.get("lines", []):
                for span in line["spans"]:
                    if span["text"].strip():
                        x0, y0, x1, y1 = span["bbox"]
                        out.append((span["text"], (x0 * PT, height - y1 * PT, x1 * PT, height - y0 * PT)))
    return out


def _distance_to_segment(box, a: complex, b: complex) -> float:
    """Least distance between the box and the segment a–b [mm] (0 when they cross)."""
    t = np.linspace(0.0, 1.0, 400)
    z = a + (b - a) * t
    dx = np.maximum(np.maximum(box[0] - z.real, z.real - box[2]), 0.0)
    dy = np.maximum(np.maximum(box[1] - z.imag, z.imag - box[3]), 0.0)
    return float(np.min(np.hypot(dx, dy)))


@pytest.mark.parametrize("name", ["die_cutter", "lockbeam"])
@pytest.mark.parametrize("lang", ["zh", "en"])
def test_phase_names_clear_of_the_lines(example_results, name, lang, tmp_path):
    s, pdf = _cycle(example_results(name), lang, tmp_path)
    bars = [e for e in s.entities if isinstance(e, Polyline) and e.closed and e.weight == 0.5
            and e.layer == "OUTLINE"]
    assert bars
    boxes = [(min(p.real for p in b.points), min(p.imag for p in b.points),
              max(p.real for p in b.points), max(p.imag for p in b.points)) for b in bars]
    transitions = [e for e in s.entities if isinstance(e, Line) and e.layer == "OUTLINE"
                   and e.weight == 0.5 and abs(e.p0.real - e.p1.real) < 1e-9]
    diagonals = [e for e in s.entities if isinstance(e, Line) and e.layer == "CONSTRUCTION"
                 and abs(e.p0.real - e.p1.real) > 1e-9 and abs(e.p0.imag - e.p1.imag) > 1e-9]
    assert transitions and diagonals
    names = 0
    for text, box in _spans(pdf, s.height):
        cy = (box[1] + box[3]) / 2
        bar = next((b for b in boxes if b[0] < box[0] and box[2] < b[2] and b[1] < cy < b[3]), None)
        if bar is None:                      # not a phase name (actuator, table, axis)
            continue
        names += 1
        for ln in transitions:               # the lines' x positions: a gap to the stroke's edge
            lo, hi = sorted((ln.p0.imag, ln.p1.imag))
            if lo < box[3] and box[1] < hi:
                x = ln.p0.real
                gap = max(box[0] - x, x - box[2]) - 0.25
                assert gap >= CLEAR, (name, lang, text, "transition at", round(x, 2), round(gap, 2))
        for ln in diagonals:
            gap = _distance_to_segment(box, ln.p0, ln.p1) - 0.125
            assert gap >= CLEAR, (name, lang, text, "diagonal", round(gap, 2))
    assert names >= 4, (name, lang, names)
