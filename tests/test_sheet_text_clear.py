"""The sheet model's means of keeping a text clear of the lines (issue 19 point 8, GB/T 4458.4:
a dimension's text is never crossed by a line; where it has no room along its line it goes
on a leader, or the line that would cross it is broken): a dimension's text on a leader
(``Dimension.text_at``) in the PDF's geometry and in the DXF, a text moved along its line
(``Dimension.along``), grid lines broken under a text (``break_lines``), the count of line
points on a dimension's text (``dimension_text_hits``) and a point label that finds no free
spot going on a leader (``LabelPlacer.place(last_leader=True)``). The expected values are
set by hand from the rule each states, not read from the program."""
from __future__ import annotations

import numpy as np
import pytest

from mechdesign.render.sheet import (DIM_ARROW, DIM_GAP, Dimension, LabelPlacer, Line, Sheet, Text,
                                     break_lines, dimension_geometry, dimension_text_hits,
                                     text_box, text_width)


def test_a_text_on_a_leader_is_level_on_its_shoulder_joined_to_the_line_middle():
    # a vertical dimension 20 mm long at x = 100, its text on a leader up and to the right
    d = Dimension(100 + 50j, 100 + 70j, 0.0, 278.0, "dW = 278.0 J", height=2.5, outside=1,
                  text_at=106 + 66j)
    lines, arrows, text, pos, ang = dimension_geometry(d)
    w = text_width("dW = 278.0 J", 2.5)
    assert ang == 0.0                                           # level, not along the line
    assert ((100 + 60j), (106 + 66j)) in lines                  # leader from the line's middle
    assert ((106 + 66j), (106 + w + 1.0 + 66j)) in lines        # shoulder away from the line
    assert pos == pytest.approx(106 + (w + 1.0) / 2 + (66 + DIM_GAP) * 1j)
    assert ((100 + 50j), (100 + 70j)) in lines and len(arrows) == 2   # the dimension itself
    # on the left of the line the shoulder runs to the left
    d = Dimension(100 + 50j, 100 + 70j, 0.0, 278.0, "dW = 278.0 J", height=2.5, text_at=94 + 56j)
    lines, _, _, pos, ang = dimension_geometry(d)
    assert ((94 + 56j), (94 - w - 1.0 + 56j)) in lines and ang == 0.0
    assert pos.real == pytest.approx(94 - (w + 1.0) / 2)


def test_the_dxf_keeps_the_measurement_and_writes_the_leader_text_level(tmp_path):
    import ezdxf

    from mechdesign.render.sheet_dxf import write_dxf

    s = Sheet("A4")
    s.dimension(100 + 50j, 100 + 70j, 0.0, 278.0, text="W=278.0 J", height=2.5, outside=1,
                text_at=106 + 66j)
    write_dxf(s, tmp_path / "d.dxf")
    (d,) = ezdxf.readfile(tmp_path / "d.dxf").modelspace().query("DIMENSION")
    assert d.get_measurement() * d.override().get("dimlfac") == pytest.approx(278.0)
    texts = [e for e in d.get_geometry_block() if e.dxftype() == "MTEXT"]
    assert len(texts) == 1 and not texts[0].dxf.get("rotation")       # level
    # the text where the PDF prints it: its middle half its height over the baseline
    _, _, _, pos, _ = dimension_geometry(s.entities[-1])
    ins = texts[0].dxf.insert
    assert abs(complex(ins.x, ins.y) - (pos + 1.25j)) < 0.5


def test_along_moves_an_aligned_text_but_not_onto_its_arrows():
    text = "L=120.00"
    w = text_width(text, 3.5)
    for along, want in ((0.5, 50.0), (0.3, 30.0), (0.7, 70.0)):
        _, _, _, pos, _ = dimension_geometry(Dimension(0j, 100 + 0j, 0.0, 100.0, text, height=3.5,
                                                       along=along))
        assert pos == pytest.approx(want + DIM_GAP * 1j)
    _, _, _, pos, _ = dimension_geometry(Dimension(0j, 100 + 0j, 0.0, 100.0, text, height=3.5,
                                                   along=0.0))
    assert pos.real == pytest.approx(0.5 * w + DIM_ARROW + DIM_GAP)
    # a radius' text inside the circle at the fraction asked for
    _, _, _, pos, _ = dimension_geometry(Dimension(0j, 50 + 0j, 0.0, 50.0, "r=50", "radius",
                                                   height=3.5, outside=0, along=0.7))
    assert pos == pytest.approx(35.0 + DIM_GAP * 1j)


def test_break_lines_leaves_the_parts_outside_the_box():
    s = Sheet("A4")
    s.line(0j, 10 + 0j, "CONSTRUCTION", 0.13)
    s.line(0 + 5j, 10 + 5j, "CONSTRUCTION", 0.13)             # misses the box
    s.line(5 - 5j, 5 + 5j, "OUTLINE")                          # crosses it, not asked to break
    grid = [s.entities[0], s.entities[1]]
    break_lines(s, (4.0, -1.0, 6.0, 1.0), grid)
    lines = [(e.p0, e.p1, e.layer) for e in s.entities if isinstance(e, Line)]
    assert (0j, 4 + 0j, "CONSTRUCTION") in lines and (6 + 0j, 10 + 0j, "CONSTRUCTION") in lines
    assert (0 + 5j, 10 + 5j, "CONSTRUCTION") in lines and (5 - 5j, 5 + 5j, "OUTLINE") in lines
    assert len(lines) == 4


def test_dimension_text_hits_counts_the_points_on_the_glyphs_only():
    d = Dimension(0j, 100 + 0j, 0.0, 100.0, "L=100.00", height=3.5)
    _, _, _, pos, _ = dimension_geometry(d)          # baseline middle (50, 1)
    on = np.array([pos + 1.5j, pos + 3 + 1.0j])       # in the glyphs' body
    off = np.array([pos - 1.0j, pos + 4.0j, pos + 20 + 1.5j])   # the line under it, above, beside
    assert dimension_text_hits(d, on) == 2
    assert dimension_text_hits(d, off) == 0
    # turned with the dimension: a vertical one reads its points in its own frame
    d = Dimension(0j, 100j, 0.0, 100.0, "L=100.00", height=3.5)
    _, _, _, pos, ang = dimension_geometry(d)
    assert dimension_text_hits(d, np.array([pos + 1.5j * np.exp(1j * ang)])) == 1


def test_a_label_with_no_free_spot_goes_on_a_leader_with_last_leader():
    def crowded():
        s = Sheet("A3")
        for k in range(-12, 13):                     # lines 1.2 mm apart, 24 mm each way
            s.line(complex(100 - 12, 100 + 1.2 * k), complex(100 + 12, 100 + 1.2 * k), "CONSTRUCTION")
        return s

    s = crowded()
    LabelPlacer(s).place(100 + 100j, "10", 2.5, prefer=1j, gap=1.5, apart=True)
    (t,) = [e for e in s.entities if isinstance(e, Text)]
    assert abs(t.position - (100 + 100j)) < 15              # over the lines, beside its point

    s = crowded()
    n = len(s.entities)
    placer = LabelPlacer(s)
    placer.place(100 + 100j, "10", 2.5, prefer=1j, gap=1.5, apart=True, last_leader=True)
    (t,) = [e for e in s.entities if isinstance(e, Text)]
    leader = [e for e in s.entities[n:] if isinstance(e, Line)]
    assert leader and leader[0].p0 == 100 + 100j             # a leader from the point
    box = text_box(t.position, t.text, t.height, t.halign, t.valign)
    # no line of the block crosses the text (the leader and its shoulder are its own)
    assert placer.crossed(box, LabelPlacer(crowded())._drawn_points()) == 0


def test_a_label_keeps_the_word_space_from_the_other_texts():
    """ISO 3098-1 / GB/T 14691: the space between words is 0.6 h (type B). A label's first
    spot, left of its point, lies 0.7 mm under a text already there (as "n4′" under
    "n4s4′" on the shaper's acceleration polygon): it reads as the second line of a note.
    The label goes where it keeps 0.6 × 2.5 = 1.5 mm from that text, and is listed among
    the sheet's labels; a text the caller places is not a label."""
    s = Sheet("A3")
    placer = LabelPlacer(s)
    h = 2.5
    w = text_width("n4'", h)
    first = (100 - 1.2 - w, 100 - h / 2, 100 - 1.2, 100 + h / 2)   # the first spot's box
    placer.text(complex(first[0], first[3] + 0.7), "n4s4'", h, "left", "bottom")
    placer.place(100 + 100j, "n4'", h, prefer=-1, gap=1.2, apart=True)
    note, label = [e for e in s.entities if isinstance(e, Text)]
    a = text_box(note.position, note.text, note.height, note.halign, note.valign)
    b = text_box(label.position, label.text, label.height, label.halign, label.valign)
    apart = max(b[0] - a[2], a[0] - b[2], b[1] - a[3], a[1] - b[3])
    assert apart >= 0.6 * h - 1e-9
    assert abs(label.position - (100 + 100j)) < 10              # still beside its point
    assert len(s.labels) == 1 and s.labels[0] is label


def test_a_label_on_a_leader_keeps_the_word_space_too():
    """The force polygons' labels that find no spot beside their vector go on a leader; its
    text keeps 0.6 h from the texts already there (F_R35 and F_R65 were 0.5 mm apart)."""
    s = Sheet("A3")
    placer = LabelPlacer(s)
    h = 2.5
    # the leader's first elbow is 8 mm straight up: its text from y = 108.8 to 111.3 over
    # an underline at 108 (the room kept, 108 … 111.7); a text 0.3 mm above that room
    placer.text(101 + 112.0j, "FR65", h, "left", "bottom")
    placer.leader(100 + 100j, "FR35", h, prefer=1j)
    note, label = [e for e in s.entities if isinstance(e, Text)]
    a = text_box(note.position, note.text, note.height, note.halign, note.valign)
    b = text_box(label.position, label.text, label.height, label.halign, label.valign)
    assert max(b[0] - a[2], a[0] - b[2], b[1] - a[3], a[1] - b[3]) >= 0.6 * h - 1e-9
    assert s.labels == [label]


def test_a_leader_never_runs_through_a_text():
    """A force label's leader starts on its vector, among the blocked points of the vectors
    around it, so that every way out crosses some of them; the one lane free of them here
    (straight up) runs through a text ("F_R16"'s leader through "F_I6"). The leader takes
    a way that crosses blocked points, not the text."""
    from mechdesign.render.sheet import clip_segment

    s = Sheet("A3")
    placer = LabelPlacer(s)
    a = 100 + 100j
    for r in (3.0, 4.0):                          # two rings of blocked points about the anchor
        for t in np.arange(0.0, 2 * np.pi, 0.5 / r):
            if abs(t - np.pi / 2) > np.radians(8):    # a lane left open straight up
                placer.block(a + r * np.exp(1j * t), 0.4)
    placer.text(a + 5.5j, "FI6", 2.5, "center", "middle")
    note = text_box(a + 5.5j, "FI6", 2.5, "center", "middle")
    n = len(s.entities)
    placer.leader(a, "FR16", 2.5, prefer=1j)
    (line, *_) = [e for e in s.entities[n:] if isinstance(e, Line)]
    assert line.p0 == a
    assert clip_segment(line.p0, line.p1, note) is None


def test_a_polygon_label_farther_than_its_reach_goes_on_a_leader():
    """A label that finds no free spot in its rings looks a little farther out (up to 10 mm:
    a position number in the fan of links); a polygon's label only up to ``reach``, then it
    goes on a leader (s4′ stood 7 mm from its point, beyond a vector, read as another
    point's)."""
    def crowded():
        s = Sheet("A3")
        for k in range(-5, 6):                    # lines 1.2 mm apart, 6 mm up and down
            s.line(complex(100 - 9, 100 + 1.2 * k), complex(100 + 9, 100 + 1.2 * k), "CONSTRUCTION")
        return s

    s = crowded()
    LabelPlacer(s).place(100 + 100j, "s4'", 2.5, prefer=1j, gap=1.2, apart=True, last_leader=True)
    (t,) = [e for e in s.entities if isinstance(e, Text)]
    assert abs(t.position - (100 + 100j)) > 4.5 + 1.25 and len([e for e in s.entities if isinstance(e, Line)]) == 11
    s = crowded()
    LabelPlacer(s).place(100 + 100j, "s4'", 2.5, prefer=1j, gap=1.2, apart=True, last_leader=True,
                         reach=4.5)
    leader = [e for e in s.entities[11:] if isinstance(e, Line)]
    assert leader and leader[0].p0 == 100 + 100j


# ------------------------------------------------------------------ notes too long for their room

def test_a_note_too_long_for_its_room_is_wrapped_at_a_word():
    from mechdesign.render.kinematic_sheet import NOTE_SMALLEST, wrap_note

    short = "each group to scale"
    assert wrap_note(short, 100.0) == [short]
    words = ["word%02d" % j for j in range(40)]
    text = " ".join(words)                          # 40 × 6 + 39 = 279 characters
    width = 100.0                                   # at 2.5 mm: 0.62 × 2.5 = 1.55 mm a character
    lines = wrap_note(text, width)
    assert len(lines) >= 2 and " ".join(lines) == text          # nothing lost, broken at spaces
    assert all(text_width(x, NOTE_SMALLEST) <= width for x in lines)
    # Chinese: after a "，" (no spaces), each part fits
    zh = "，".join(["各杆组按比例尺绘制"] * 12)
    parts = wrap_note(zh, 120.0)
    assert "".join(parts) == zh and len(parts) >= 2
    assert all(text_width(x, NOTE_SMALLEST) <= 120.0 for x in parts)
    assert all(x.endswith("，") for x in parts[:-1])


def test_the_lockbeam_english_note_keeps_off_the_title_block(example_results):
    """The lock-beam's kinematic sheet in English: its note "each group to μL; not given, so
    schematic: …the chain's centre distance" (150 characters) ran on at the smallest text
    height into the title block's "Student No." (the touching check ran on Chinese sheets
    only). Every note now ends left of the title block, by the width estimate."""
    from pathlib import Path

    from mechdesign.brief.loader import load_brief
    from mechdesign.render.sheet import plain, title_block_box
    from mechdesign.render.sheets import _builders, title_info
    from sheet_overlaps import touching_labels

    root = Path(__file__).resolve().parents[1]
    brief = load_brief(root / "designs" / "lockbeam.yaml")
    builders = dict(_builders(example_results("lockbeam"), brief))
    sheet = builders["kinematic"](title_info(brief.report, "kinematic", "MD-01", 1, 4, "en"), "en")
    assert not touching_labels(sheet)
    tb = title_block_box(sheet)
    notes = [e for e in sheet.entities if isinstance(e, Text) and e.position.imag < tb[3]
             and e.position.real < tb[0]]
    assert any("centre distance" in plain(e.text) for e in notes)
    for e in notes:
        assert e.position.real + text_width(e.text, e.height) <= tb[0] - 2.0, plain(e.text)
