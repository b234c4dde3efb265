"""The transmission schematic (传动系统示意图, A3; issue 19 point 8, review33 item 14), read
from the written DXF: the wheels seen end-on do not cover each other — two pitch circles
(layer CENTER) on different centres either mesh (touch: centre distance = r1 + r2) or lie
apart with their tip circles (pitch + 1.5 mm) clear — every stage has its number, and no
stage number or shaft numeral is written over a shaft's centre mark."""
from __future__ import annotations


import numpy as np
import pytest

from mechdesign.render.sheet import Circle, Text, text_box
from one_sheet import written_sheet

TIP = 1.5            # tip circle outside the pitch circle [paper mm], as drawn


def _written(example_results, tmp_path, name, lang):
    from mechdesign.render.sheet import TitleInfo

    r = example_results(name)
    msp, build = written_sheet(r, name, "transmission", tmp_path, lang)
    return r, msp, build(TitleInfo("传动系统示意图", "test", number="T-01"), lang)


@pytest.mark.parametrize("name", ["furnace_pusher", "furnace_drive", "die_cutter", "shaper", "slotter"])
def test_wheels_do_not_cover_each_other_and_stages_are_numbered(example_results, tmp_path, name):
    r, msp, sheet = _written(example_results, tmp_path, name, "zh")
    pitch = [(complex(e.dxf.center.x, e.dxf.center.y), e.dxf.radius) for e in msp.query("CIRCLE")
             if e.dxf.layer == "CENTER"]
    # a gear pair's two pitch circles, a worm's wheel one
    want = sum(1 if st.type == "worm" else 2 for st in r["drive"].stages
               if st.type not in ("belt", "chain", "coupling"))
    assert len(pitch) == want
    for i, (ca, ra) in enumerate(pitch):
        for cb, rb in pitch[i + 1:]:
            d = abs(ca - cb)
            if d < 1e-6:
                continue                                   # two wheels on one shaft
            meshing = abs(d - (ra + rb)) < 1e-6
            assert meshing or d >= ra + rb + 2 * TIP - 1e-6, (name, ca, ra, cb, rb, d)
    # every stage numbered, no number or numeral on a shaft's centre mark (radius 1.6 mm)
    marks = [e.center for e in sheet.entities if isinstance(e, Circle) and abs(e.radius - 1.6) < 1e-9]
    assert marks
    texts = [e for e in sheet.entities if isinstance(e, Text)]
    numbers = {e.text for e in texts}
    for j in range(1, len(r["drive"].stages) + 1):
        assert str(j) in numbers, (name, j)
    for e in texts:
        b = text_box(e.position, e.text, e.height, e.halign, e.valign)
        for m in marks:
            dx = max(b[0] - m.real, 0.0, m.real - b[2])
            dy = max(b[1] - m.imag, 0.0, m.imag - b[3])
            assert np.hypot(dx, dy) >= 1.6 + 0.5, (name, e.text, m)


@pytest.mark.parametrize("name", ["die_cutter", "shaper", "slotter", "furnace_pusher"])
def test_layout_beside_keeps_every_wheel_clear_of_the_others(example_results, name):
    """The layout both drive drawings use (the transmission schematic, the die-cutter's
    drive group): with ``beside`` two wheels on different centres either mesh (a stage's
    pair, centre distance r1 + r2, a belt's pulleys farther) or do not reach into each
    other; a shaft drawn twice is joined to its first drawing."""
    from mechdesign.render.kinematic_sheet import _layout_drive, _schematic_radius

    stages = list(example_results(name)["drive"].stages)
    r = [(_schematic_radius(st, 1), _schematic_radius(st, 2)) for st in stages]
    k = 34.0 / max(max(a, b) for a, b in r)
    r = [(max(a * k, 6.0), max(b * k, 8.0)) for a, b in r]
    centres, items = _layout_drive(stages, r, beside=True)
    wheels = []                                     # (centre, radius, stage)
    for kind, a, b, r1, r2, j in items:
        if kind == "shaft":
            assert abs(a - centres[j]) < 1e-9       # a second drawing of shaft j
        elif kind == "worm":
            wheels += [(a, 1.3 * r1, j), (b, r2, j)]
        elif kind != "coupling":
            wheels += [(a, r1, j), (b, r2, j)]
    for i, (ca, ra, ja) in enumerate(wheels):
        for cb, rb, jb in wheels[i + 1:]:
            d = abs(ca - cb)
            if d < 1e-9 or (ja == jb):
                continue                            # one shaft; one stage's pair
            assert d >= ra + rb - 1e-9, (name, ca, ra, ja, cb, rb, jb)
