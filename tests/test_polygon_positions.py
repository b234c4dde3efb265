"""The polygon positions a brief leaves to the program (stages/polygons.py default_positions):
the regular positions nearest the middle of each stroke, but never one whose velocity
polygon is a line. The lockbeam's feed linkage (a guide bar pinned at O3, its slider on the
crank pin A, the crank O2A = 50 mm on the line O2O3) has its guide bar in line with the crank
where the crank is perpendicular to the bar: at the stroke ends (positions 1, 9) and at the
middles 5 (φ = 120°) and 11 (300°) every velocity of the polygon is parallel to one line,
and the A1 sheet drew two lines for its velocity polygons (page review 46)."""
from __future__ import annotations

import numpy as np
import pytest

from mechdesign.core.polygons import Polygon, kinematic_polygon
from mechdesign.stages.polygons import FLAT, entry, flatness


def _polygon(points: dict) -> Polygon:
    return Polygon(kind="velocity", position="1", points=points, vectors=())


def test_flatness_of_points_on_a_line_and_of_a_square():
    on_line = {c: (1 + 0.5j) * t for c, t in zip("abc", (1.0, 2.5, -4.0))}
    assert flatness(_polygon(on_line)) == pytest.approx(0.0, abs=1e-12)
    # the pole 0 and the square's other corners 1, 1 + i, i: equal spread both ways
    assert flatness(_polygon({"a": 1, "b": 1 + 1j, "c": 1j})) == pytest.approx(1.0, rel=1e-12)
    # a thin rectangle 10 × 1: spread across / along = 1/10 (the four corners' deviations)
    assert flatness(_polygon({"a": 10, "b": 10 + 1j, "c": 1j})) == pytest.approx(0.1, rel=1e-12)


def test_the_lockbeam_feed_polygons_avoid_the_positions_where_the_polygon_is_a_line(example_results):
    r = example_results("lockbeam")
    k, mech, raw = r["feed"], r["feed_model"].mechanism, r["feed_raw"]
    labels = [str(x) for x in k.positions.labels]
    flat = {lab: flatness(kinematic_polygon(mech, raw, entry(k, lab), lab, "velocity")) for lab in labels}
    # the guide bar in line with the crank: at the crank angles where the crank pin's velocity
    # (perpendicular to the crank) is along the bar, sin(angle between crank and bar) = 0
    assert all(flat[lab] < 1e-9 for lab in ("1", "5", "9", "11"))
    assert all(flat[lab] > 0.2 for lab in labels if lab not in ("1", "5", "9", "11"))
    # brute force: of the regular positions whose polygon is not a line, the nearest to the
    # middle of the working stroke (240° long: 120°) and of the return (300°); of two as
    # near, the earlier
    phase = dict(zip(labels, np.degrees(np.asarray(k.positions.phase))))
    assert phase["5"] == pytest.approx(120.0) and phase["11"] == pytest.approx(300.0)
    expected = []
    for target in (120.0, 300.0):
        ok = [lab for lab in labels if flat[lab] >= FLAT]
        best = min(round(abs(phase[lab] - target), 6) for lab in ok)
        expected.append(next(lab for lab in ok if round(abs(phase[lab] - target), 6) == best))
    assert expected == ["4", "10"]
    assert tuple(r["feed_polygons"].positions) == ("4", "10")
    assert tuple(p.label for p in r["feed_graphical"].positions) == ("4", "10")


@pytest.mark.parametrize("name", ["shaper", "shaper_lengths", "slotter", "press", "die_cutter",
                                  "furnace_pusher", "lockbeam", "linkage_sixbar", "crank_rocker",
                                  "textbook_guide_bar"])
def test_no_example_draws_a_velocity_polygon_that_is_a_line(example_results, name):
    r = example_results(name)
    for key in [x for x in r if x.endswith("_polygons")]:
        found = r[key]
        k, mech = r[found.prefix], r[found.model_key].mechanism
        for lab in found.positions:
            poly = kinematic_polygon(mech, r[f"{found.prefix}_raw"], entry(k, lab), lab, "velocity")
            assert flatness(poly) >= FLAT, (key, lab)
