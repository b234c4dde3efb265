"""The motion cycle diagram sheet (运动循环图, A3; issue 19 point 8, review33 item 12): read
from the written DXF, it carries the circular diagram — one ring per actuator, the first
innermost, each phase an arc of its ring from the phase's start to its end measured
clockwise from the top (DXF angles counter-clockwise from +x: 90° − φ), as the stage's
phases give them — and the timing checks; the drawing fills the frame down to the
title block (no empty lower half) and no two texts overlap."""
from __future__ import annotations


import numpy as np
import pytest

from mechdesign.render.sheet import Arc, Circle, Fill, Line, Polyline, Text, boxes_overlap, text_box
from one_sheet import written_sheet



def _written(example_results, tmp_path, name, lang):
    r = example_results(name)
    return r, written_sheet(r, name, "cycle", tmp_path, lang)[0]


def _sheet(r, lang):
    from mechdesign.render.sheet import TitleInfo
    from mechdesign.render.sheets import _builders

    return dict(_builders(r, None))["cycle"](TitleInfo("运动循环图", "test", number="T-01"), lang)


def _same_angle(a, b, tol=1e-6):
    return abs(((a - b + 180.0) % 360.0) - 180.0) < tol


@pytest.mark.parametrize("name", ["lockbeam", "die_cutter"])
@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_sheet_draws_the_circular_diagram_from_the_phases(example_results, tmp_path, name, lang):
    r, msp = _written(example_results, tmp_path, name, lang)
    diagram = r["cycle"].diagram
    arcs = [(e.dxf.radius, e.dxf.start_angle, e.dxf.end_angle, complex(e.dxf.center.x, e.dxf.center.y))
            for e in msp.query("ARC")]
    assert arcs
    centre = arcs[0][3]
    assert all(abs(c - centre) < 1e-6 for *_x, c in arcs)      # one diagram, concentric
    # one ring per actuator, the first innermost: the phases of actuator i are the arcs of
    # the i-th radius (a single arc is the arrow giving φ's sense)
    radii = [round(rad, 6) for rad, *_x in arcs]
    rings = sorted(rad for rad in set(radii) if radii.count(rad) >= 2)
    assert len(rings) == len(diagram.actuators)
    for act, rad in zip(diagram.actuators, rings):
        got = sorted((s % 360.0, e % 360.0) for rr, s, e, _c in arcs if abs(rr - rad) < 1e-6)
        assert len(got) == len(act.phases), act.key
        for ph in act.phases:
            a, span = np.degrees(ph.start), np.degrees(ph.span)
            want = (90.0 - (a + span), 90.0 - a)           # counter-clockwise from end to start
            assert any(_same_angle(s, want[0]) and _same_angle(e, want[1]) for s, e in got), \
                (act.key, a, span, got)
    # every timing check is in the written sheet, with its slack in degrees
    texts = [e.dxf.text if e.dxftype() == "TEXT" else e.text for e in msp.query("TEXT MTEXT")]
    for chk in r["cycle"].checks:
        assert f"{np.degrees(chk.slack):.2f}" in texts


@pytest.mark.parametrize("name", ["lockbeam", "die_cutter"])
@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_sheet_fills_the_frame_and_no_texts_overlap(example_results, name, lang):
    from mechdesign.render.sheet import title_block_box

    s = _sheet(example_results(name), lang)
    x0, y0, x1, y1 = s.inner
    tb = title_block_box(s)

    def inside_tb(z):
        return tb[0] - 1e-6 <= z.real and z.imag <= tb[3] + 1e-6

    lowest = np.inf
    for e in s.entities[2:]:                      # the trimmed edge and the border left out
        if isinstance(e, Line):
            pts = [e.p0, e.p1]
        elif isinstance(e, (Polyline, Fill)):
            pts = list(e.points)
        elif isinstance(e, (Circle, Arc)):
            pts = [e.center - 1j * e.radius]
        else:
            continue
        pts = [p for p in pts if not inside_tb(p)]
        if pts:
            lowest = min(lowest, min(p.imag for p in pts))
    # drawn content reaches down through at least 70 % of the height above the title block
    assert y1 - lowest >= 0.7 * (y1 - tb[3]), (y1 - lowest, y1 - tb[3])
    boxes = [(e.text, text_box(e.position, e.text, e.height, e.halign, e.valign))
             for e in s.entities if isinstance(e, Text) and e.text.strip()]
    for i, (ta, a) in enumerate(boxes):
        for tb_, b in boxes[i + 1:]:
            assert not boxes_overlap(a, b, -0.05), (ta, tb_)


@pytest.mark.parametrize("name", ["lockbeam", "die_cutter"])
@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_degree_sign_follows_its_number_on_the_sheet(example_results, name, lang):
    """The angle scale is written "μφ = 1.25°/mm", the degree sign right after the number as
    the reports write 34.92° (GB 3102.1: no space before °); the sheet wrote "1.25 °/mm" in
    its scale line and its title block."""
    import re

    s = _sheet(example_results(name), lang)
    texts = [e.text for e in s.entities if isinstance(e, Text)]
    scales = [t for t in texts if "/mm" in t]
    assert len(scales) >= 2, texts                   # the scale line and the title block
    apart = [t for t in texts if re.search(r"\d[ \u00a0\u202f\u2009]+°", t)]
    assert not apart, apart
    assert any(re.search(r"\d°/mm", t) for t in scales), scales
