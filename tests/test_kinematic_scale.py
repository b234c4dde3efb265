"""Issue 19 point 5: a kinematic diagram (机构运动简图, A3) is drawn at the largest GB/T 14690
preferred scale at which the mechanism fits the drawing area, as a student fills the sheet
(the base commit drew the shaper at 1:10 on ~15 % of the sheet; 1:5 fits).

For every example with a kinematic sheet: the mechanism (its linework and its labels) lies
inside the border, under the heading and clear of the title block and the notes; and at the
next larger preferred scale (found by walking the series 1, 2, 2.5, 4, 5 × 10ⁿ both ways)
its linework alone, grown about its centre, with the least room for a label around it
(one text height and its gap, 5 mm), fits nowhere on the sheet: neither over the whole
width above the title block nor over the whole height left of it.
"""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from mechdesign.render.sheet import (Arc, Circle, Fill, Line, Polyline, Text, text_width,
                                     title_block_box)

ROOT = Path(__file__).resolve().parents[1]
KINEMATIC = ["shaper", "shaper_lengths", "slotter", "furnace_pusher", "die_cutter", "press",
             "linkage_sixbar", "textbook_guide_bar", "lockbeam", "lockbeam_cam", "cam_7_1",
             "cam_7_3", "crank_rocker"]
LINEWORK = {"OUTLINE", "CENTER", "HIDDEN", "CONSTRUCTION", "DIMENSIONS"}
LABEL = 5.0          # a 3.5 mm label and its gap
HEADING = 16.0       # the heading's strip under the border (a 5 mm heading centred 12 mm under it)
GB = (1.0, 2.0, 2.5, 4.0, 5.0)


def series() -> list[float]:
    """Every preferred scale as paper mm per model mm, smallest first (1:10⁶ … 10⁴:1)."""
    return sorted({m * 10.0 ** k for m in GB for k in range(0, 5)}
                  | {1.0 / (m * 10.0 ** k) for m in GB for k in range(0, 7)})


def paper_per_model(scale: str) -> float:
    a, b = (float(x) for x in re.fullmatch(r"([\d.]+):([\d.]+)", scale).groups())
    return a / b


def _points(e) -> list[complex]:
    if isinstance(e, Line):
        return [e.p0, e.p1]
    if isinstance(e, (Polyline, Fill)):
        return list(e.points)
    if isinstance(e, (Circle, Arc)):
        return [e.center + e.radius * d for d in (1, 1j, -1, -1j)]
    return []


def _text_box(t: Text) -> tuple[float, float, float, float]:
    w, h = text_width(t.text, t.height), t.height
    x = t.position.real - {"left": 0, "center": 0.5, "right": 1}[t.halign] * w
    y = t.position.imag - {"bottom": 0, "middle": 0.5, "top": 1}[t.valign] * h
    if abs(np.sin(t.angle)) > 0.5:           # upright text: width along y
        return t.position.real - h, t.position.imag - w, t.position.real + h, t.position.imag + w
    return x, y, x + w, y + h


def _inside(box, area, tol=0.5) -> bool:
    return (box[0] >= area[0] - tol and box[1] >= area[1] - tol and box[2] <= area[2] + tol
            and box[3] <= area[3] + tol)


def _overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


@pytest.mark.e2e
@pytest.mark.parametrize("name", KINEMATIC)
def test_kinematic_sheet_fills_the_sheet(example_results, name):
    from mechdesign.brief.loader import load_brief
    from mechdesign.render.sheets import _builders, title_info

    brief = load_brief(ROOT / "designs" / f"{name}.yaml")
    builders = dict(_builders(example_results(name), brief))
    s = builders["kinematic"](title_info(brief.report, "k", "K-01", 1, 1, "zh"), "zh")
    x0, y0, x1, y1 = s.inner
    tb = title_block_box(s)
    pts = np.array([p for e in s.entities if getattr(e, "layer", "") in LINEWORK
                    and not (isinstance(e, Polyline) and e.layer == "FRAME")
                    for p in _points(e)])
    lo = complex(pts.real.min(), pts.imag.min())
    hi = complex(pts.real.max(), pts.imag.max())
    box = (lo.real, lo.imag, hi.real, hi.imag)
    # 1. inside the border, under the heading, clear of the title block
    assert _inside(box, (x0, y0, x1, y1 - HEADING)), (name, box)
    assert not _overlap(box, tb), (name, box, tb)
    texts = [e for e in s.entities if isinstance(e, Text)
             and not _inside(_text_box(e), tb)]
    heading = max(texts, key=lambda t: t.position.imag)
    for t in texts:
        tbox = _text_box(t)
        assert _inside(tbox, s.inner, 1.0), (name, t.text, tbox)
        if t is not heading:
            assert not _overlap(tbox, (tb[0] + 1, tb[1] + 1, tb[2] - 1, tb[3] - 1)), (name, t.text)
            assert tbox[3] <= y1 - HEADING + 1.0, (name, t.text, tbox)
    # 2. the next larger preferred scale would not fit
    scales = s.info.scale.split(", ")
    if len(scales) > 1:                      # two views at their own scales (crank-rocker)
        return
    k = paper_per_model(scales[0])
    bigger = [m for m in series() if m > k * (1 + 1e-9)]
    assert bigger and any(abs(m - k) < 1e-9 * k for m in series()), (name, scales)
    grow = bigger[0] / k
    w, h = (hi - lo).real * grow + 2 * LABEL, (hi - lo).imag * grow + 2 * LABEL
    free = [(x1 - x0, y1 - HEADING - tb[3]),           # the whole width above the title block
            (tb[0] - x0, y1 - HEADING - y0)]           # the whole height left of it
    assert not any(w <= fw and h <= fh for fw, fh in free), \
        (name, scales[0], "fits at the next scale", (w, h), free)
