"""The eccentric disc cam's largest pressure angle is found exactly, not read off the table
(the report printed np.max over the 10° table: right for the examples only because their
extremes fall on multiples of 90°), and the summary states it beside the strokes (page
review 48: cam_7_1's task asks for the pressure angles, its summary gave the strokes only).

Closed form: the common normal of a knife edge or roller passes through the disc's centre,
so sin α = |x_f − C_x|/(R + r_r) and the largest is where C is farthest from the follower's
line: sin α_max = (|x_f| + ε)/(R + r_r); a flat face perpendicular to its axis has α = 0."""
from __future__ import annotations

import math

import numpy as np
import pytest

from mechdesign.core.cam import TranslatingFollower, eccentric_disc
from tests.test_report_prose import _markdown

CASES = [  # R, ε, follower, rotation [m]
    (0.040, 0.020, TranslatingFollower("knife", 0.0), 1),
    (0.040, 0.020, TranslatingFollower("knife", 0.015), 1),
    (0.040, 0.020, TranslatingFollower("roller", 0.0, 0.020), 1),
    (0.050, 0.012, TranslatingFollower("roller", -0.0137, 0.008), -1),   # off any table grid
    (0.050, 0.012, TranslatingFollower("flat"), 1),
]


@pytest.mark.parametrize("R, ecc, fol, rot", CASES)
def test_the_largest_pressure_angle_is_the_brute_force_maximum(R, ecc, fol, rot):
    m = eccentric_disc([0.0], R, ecc, fol, rot)
    dense = eccentric_disc(np.linspace(0.0, 2 * np.pi, 2_000_001), R, ecc, fol, rot)
    assert m.alpha_max == pytest.approx(float(np.max(dense.pressure_angle)), abs=1e-9)
    if fol.kind == "flat":
        assert m.alpha_max == 0.0
    else:
        Rp = R + fol.roller_radius
        assert math.sin(m.alpha_max) == pytest.approx((abs(fol.offset) + ecc) / Rp, rel=1e-12)


def test_the_examples_angles_by_hand(example_results):
    # designs/cam_7_1.yaml: R = 40 mm, ε = 20 mm; (a) centred knife edge, (b) knife edge
    # offset 15 mm, (c) centred roller r_r = 20 mm
    r = example_results("cam_7_1")
    got = [m.alpha_max for m in r["disc"].motions]
    hand = [math.asin(20 / 40), math.asin((15 + 20) / 40), math.asin(20 / (40 + 20))]
    assert np.degrees(hand) == pytest.approx([30.0, 61.0450, 19.4712], abs=1e-4)
    assert got == pytest.approx(hand, rel=1e-12)
    checks = [c for c in r["disc_verification"].checks if c.key == "disc_alpha_max"]
    assert len(checks) == 3 and all(c.passed for c in checks)


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_summary_states_the_largest_pressure_angles(example_results, lang):
    md, _ = _markdown(example_results, "cam_7_1", lang)
    summary = md[md.index("{#summary}"):]
    word = "最大压力角" if lang == "zh" else "largest pressure angle"
    rows = [line for line in summary.splitlines() if word in line and line.startswith("|")]
    assert [row.split("|")[2].strip() for row in rows] == ["30.00", "61.04", "19.47"]


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_verification_table_shows_every_check(handin_reports, lang):
    # page review 51: Table 3 listed 9 checks while the summary counted 12 (the three
    # largest-pressure-angle checks were not printed); each follower's row gives the
    # three-centre theorem's largest angle beside the closed form (30.00°, 61.04°, 19.47°
    # by hand: sin α_max = (|x_f| + ε)/(R + r_r), see test_the_examples_angles_by_hand)
    md, _ = handin_reports("cam_7_1", lang)
    word = "解析" if lang == "zh" else "closed form"
    rows = [line for line in md.splitlines() if f"{word} $\\alpha_{{max}}$ =" in line]
    assert len(rows) == 3
    for row, top in zip(rows, ("30.000", "61.045", "19.471")):
        cells = [c.strip() for c in row.strip("|").split("|")]
        assert cells[1] == f"{top}°" and cells[2].endswith(f"= {top}°"), cells
    assert ("12 项校核" in md) if lang == "zh" else ("12 checks" in md)
