"""Incomplete gear intermittent drive (mechdesign.core.intermittent) and its brief section.

References, worked by hand with the textbook relations (孙桓《机械原理》第11章 不完全齿轮机构):
φm = 360° z1'/z1, Δφ2 = 360° z1'/z2, k = φm/(360° − φm), τ = φm/360°, r = m z/2,
a = m (z1 + z2)/2, ω2 = ω1 z1/z2 while meshing. Example: m = 4 mm, z1 = 36, z2 = 30 and a
motion span of 100° → z1' = 36 × 100/360 = 10 teeth, Δφ2 = 360 × 10/30 = 120°,
φd = 260°, k = 100/260, τ = 100/360, r1 = 72 mm, r2 = 60 mm, a = 132 mm, r_a1 = 76 mm.
The driven motion is checked by integrating, differencing and timing the arrays.
"""
from __future__ import annotations

import numpy as np
import pytest
from pydantic import ValidationError

from mechdesign.brief.components import IncompleteGearSection, incomplete_gear_to_si
from mechdesign.core import intermittent as im

R = np.radians
MM = 1e-3


def example(**kw):
    args = dict(module=4 * MM, z1=36, z2=30, motion_span=R(100))
    args.update(kw)
    return im.design_incomplete_gear(**args)


def test_hand_example():
    g = example()
    assert g.teeth == 10
    assert np.degrees(g.motion_angle) == pytest.approx(100.0)
    assert np.degrees(g.dwell_angle) == pytest.approx(260.0)
    assert np.degrees(g.advance) == pytest.approx(120.0)
    assert g.motion_dwell_ratio == pytest.approx(100 / 260)
    assert g.tau == pytest.approx(100 / 360)
    assert (g.r1, g.r2, g.centre_distance) == pytest.approx((72 * MM, 60 * MM, 132 * MM))
    assert (g.ra1, g.ra2, g.rf1) == pytest.approx((76 * MM, 64 * MM, 67 * MM))
    assert g.locking_radius == pytest.approx(76 * MM)
    assert g.speed_ratio == pytest.approx(36 / 30)
    assert g.stations == 3                     # 30 / 10
    assert g.notes == ()


def test_the_teeth_are_found_from_any_sufficient_timing():
    # z1 from the teeth and the span: 360 × 4 / 120 = 12
    g = im.design_incomplete_gear(3 * MM, None, 16, teeth=4, motion_span=R(120))
    assert (g.z1, np.degrees(g.advance)) == (12, pytest.approx(90.0))
    # z2 from the teeth and the advance: 360 × 4 / 90 = 16
    g = im.design_incomplete_gear(3 * MM, 12, None, teeth=4, advance=R(90))
    assert g.z2 == 16
    # the teeth from z2 and a chain feed: 60 mm sprocket, feed a quarter of its pitch circle
    feed = 2 * np.pi * 60 * MM / 4
    g = im.design_incomplete_gear(3 * MM, 40, 24, feed=feed, sprocket_radius=60 * MM)
    assert g.teeth == 6                       # 24 × 90/360
    assert g.feed == pytest.approx(feed)
    assert np.degrees(g.motion_angle) == pytest.approx(54.0)   # 360 × 6 / 40


def test_timing_that_whole_teeth_cannot_meet():
    with pytest.raises(im.IntermittentDesignError,
                       match=r"105°.*10\.5 teeth.*100° \(10 teeth\) or 110° \(11 teeth\)"):
        example(motion_span=R(105))
    with pytest.raises(im.IntermittentDesignError, match=r"advance 100°.*3\.333 teeth"):
        im.design_incomplete_gear(4 * MM, None, 12, advance=R(100), motion_span=R(90))
    with pytest.raises(im.IntermittentDesignError, match=r"z1 = 360°·z1'/φm = 11\.52"):
        im.design_incomplete_gear(4 * MM, None, 16, teeth=4, motion_span=R(125))
    # consistent teeth but the required advance is not what they give (10 teeth on z2 = 30 → 120°)
    with pytest.raises(im.IntermittentDesignError, match=r"120°, not the required 100°"):
        example(advance=R(100))
    with pytest.raises(im.IntermittentDesignError, match="no toothless arc"):
        im.design_incomplete_gear(4 * MM, 20, 30, teeth=20)
    with pytest.raises(im.IntermittentDesignError, match="not fixed"):
        im.design_incomplete_gear(4 * MM, 20, 30)
    with pytest.raises(im.IntermittentDesignError, match="give one of them"):
        im.design_incomplete_gear(4 * MM, 36, 30, teeth=10, advance=R(120),
                                  feed=0.1, sprocket_radius=0.05)
    with pytest.raises(im.IntermittentDesignError, match="sprocket"):
        im.design_incomplete_gear(4 * MM, 36, 30, teeth=10, feed=0.1)


def test_tolerance_accepts_near_misses_and_keeps_the_request():
    with pytest.raises(im.IntermittentDesignError):
        example(motion_span=R(100.005))
    g = example(motion_span=R(100.005), tol=R(0.01))
    assert g.teeth == 10
    assert np.degrees(g.requested_motion_angle) == pytest.approx(100.005)
    assert np.degrees(g.motion_angle) == pytest.approx(100.0)


def test_driven_motion_on_a_grid():
    w1 = 50 * 2 * np.pi / 60
    g = example(driver_speed=w1, motion_start=R(300), sprocket_radius=80 * MM)
    n = 36000
    theta = np.arange(n) * (2 * np.pi / n)
    dm = g.driven_motion(theta)
    # the dwell is exactly still, the meshing exactly at the gear ratio
    assert np.all(dm.omega[~dm.moving] == 0.0)
    assert np.all(dm.ratio[~dm.moving] == 0.0)
    assert np.allclose(dm.omega[dm.moving], w1 * 36 / 30, rtol=0, atol=1e-12)
    # meshing is 300° … 40°: the time fraction is τ and the motion/dwell ratio k (to a grid step)
    deg = np.degrees(theta)
    assert np.array_equal(dm.moving, (deg >= 300 - 1e-9) | (deg < 40 - 1e-9))
    frac = np.mean(dm.moving)
    assert frac == pytest.approx(g.tau, abs=1.5 / n)
    assert frac / (1 - frac) == pytest.approx(g.motion_dwell_ratio, rel=1e-3)
    # ∫ω2 dt over one cycle (rectangle rule on the uniform grid) = the advance
    dt = (2 * np.pi / n) / w1
    assert np.sum(dm.omega) * dt == pytest.approx(g.advance, rel=2e-4)
    # chain travel = R_s × driven angle; the angle read from the motion start ends at Δφ2
    assert dm.travel == pytest.approx(80 * MM * dm.angle)
    assert float(np.max(dm.angle)) == pytest.approx(g.advance, rel=1e-4)


def test_driven_angle_read_from_another_angle_and_its_derivative():
    g = example(motion_start=R(300))
    k = 36 / 30
    theta = R(np.array([0.0, 20.0, 40.0, 120.0, 299.0, 330.0, 359.999]))
    dm = g.driven_motion(theta, since=0.0)
    # from φ = 0 the motion runs 0 … 40° (the end of last cycle's meshing) and again from 300°
    expected = k * np.array([0.0, 20.0, 40.0, 40.0, 40.0, 70.0, 99.999])
    assert np.degrees(dm.angle) == pytest.approx(expected, abs=1e-9)
    # finite differences of the angle reproduce dφ2/dθ away from the jumps
    fine = np.linspace(0, 2 * np.pi, 7201)[:-1]
    d = g.driven_motion(fine, since=0.0)
    slope = np.diff(d.angle) / np.diff(fine)
    inside = d.moving[:-1] == d.moving[1:]
    assert np.allclose(slope[inside], d.ratio[:-1][inside], atol=1e-9)


def test_engagement_jump():
    w1 = 2.0
    g = example(driver_speed=w1, motion_start=R(90), sprocket_radius=50 * MM)
    eps = 1e-7
    dm = g.driven_motion(np.array([R(90) - eps, R(90) + eps, R(190) - eps, R(190) + eps]))
    jump = g.engagement_jump()
    assert dm.omega[1] - dm.omega[0] == pytest.approx(jump.omega2)
    assert dm.omega[2] - dm.omega[3] == pytest.approx(jump.omega2)
    assert jump.omega2 == pytest.approx(2.0 * 36 / 30)
    assert jump.pitch_speed == pytest.approx(2.0 * 72 * MM)          # ω1 r1 = ω2 r2
    assert jump.pitch_speed == pytest.approx(jump.omega2 * g.r2)
    assert jump.chain_speed == pytest.approx(50 * MM * jump.omega2)
    T, tm, td = g.times()
    assert (T, tm, td) == pytest.approx((np.pi, R(100) / 2, R(260) / 2))
    assert example().times() is None
    assert example().engagement_jump().omega2 == pytest.approx(36 / 30)   # per radian


def test_notes():
    g = im.design_incomplete_gear(4 * MM, 12, 16, teeth=3)
    codes = [n.code for n in g.notes]
    assert codes == ["undercut", "stations"]       # 12 < 17; 16 is not a multiple of 3
    assert g.stations is None
    assert "z1 = 12" in g.notes[0].en and "z2 = 16" in g.notes[0].en
    assert "16" in g.notes[1].zh


def test_cycle_phases_feed_a_cycle_diagram():
    from mechdesign.core import cycle as cy

    g = example(motion_start=R(300))
    act = cy.make_actuator("chain", "链条", "chain", g.motion_start, g.cycle_phases())
    assert list(cy.state_at(act, R(np.array([299.9, 300.0, 39.9, 40.0])))) == [
        "dwell", "move", "move", "dwell"]


def test_document():
    doc = im.intermittent_document(example(driver_speed=1.0))
    assert doc.teeth == 10 and doc.stations == 3
    assert doc.advance == pytest.approx(R(120))
    assert doc.times.motion == pytest.approx(R(100))


# --------------------------------------------------------------------------- brief section


def test_section_converts():
    s = IncompleteGearSection.model_validate(
        {"module_mm": 4, "driver_teeth_full": 36, "driven_teeth": 30, "motion_span_deg": 100,
         "motion_start_deg": 300, "sprocket_pitch_radius_mm": 80})
    g = incomplete_gear_to_si(s, 50)
    assert g.teeth == 10 and g.module == pytest.approx(0.004)
    assert g.driver_speed == pytest.approx(50 * 2 * np.pi / 60)
    assert g.motion_start == pytest.approx(R(300))
    assert g.feed == pytest.approx(0.080 * R(120))
    assert incomplete_gear_to_si(s).driver_speed is None


def test_section_errors_say_what_to_change():
    base = {"module_mm": 4, "driver_teeth_full": 36, "driven_teeth": 30}
    with pytest.raises(ValidationError, match=r"10\.5 teeth.*change the motion span or z1"):
        IncompleteGearSection.model_validate({**base, "motion_span_deg": 105})
    with pytest.raises(ValidationError, match="feed_mm needs sprocket_pitch_radius_mm"):
        IncompleteGearSection.model_validate({**base, "feed_mm": 300})
    with pytest.raises(ValidationError, match="not both"):
        IncompleteGearSection.model_validate({**base, "feed_mm": 300, "advance_deg": 90,
                                              "sprocket_pitch_radius_mm": 50})
    with pytest.raises(ValidationError) as exc:
        IncompleteGearSection.model_validate({**base, "teeth_present": 2.5})
    assert exc.value.errors()[0]["loc"] == ("teeth_present",)
    # a 0.01° tolerance (the default) accepts 100.005°
    s = IncompleteGearSection.model_validate({**base, "motion_span_deg": 100.005})
    assert incomplete_gear_to_si(s).teeth == 10
