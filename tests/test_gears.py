"""Involute gear geometry against hand values and independent geometric conditions.

References: the shaper's gear table (seed 000, m = 12, z1 = 18, z2 = 60, α = 20°, ha* = 1,
c* = 0.25), computed by hand from the textbook formulas; the involute-function table
(inv 20° = 0.014904); the no-backlash condition s1' + s2' = p' on the working pitch
circles; the contact ratio as B1B2 / p_b from the line-of-action geometry.
"""
from __future__ import annotations

import numpy as np
import pytest

from mechdesign.core.gears import helical_pair, inv, inv_inverse, spur_pair, worm_pair, worm_efficiency

D = np.radians


def test_involute_function_table_and_inverse():
    assert inv(D(20)) == pytest.approx(0.014904, abs=1e-6)        # textbook table
    assert inv(D(25)) == pytest.approx(0.029975, abs=1e-6)
    for a in np.linspace(0.05, 1.2, 12):
        assert inv_inverse(float(inv(a))) == pytest.approx(a, abs=1e-12)


def test_shaper_gear_table():
    """Seed 000's table (its heading 'm = 15' is a misprint: the table is m = 12)."""
    g = spur_pair(12, 18, 60)
    assert (g.g1.d, g.g2.d) == pytest.approx((216, 720))
    assert (g.g1.da, g.g2.da) == pytest.approx((240, 744))
    assert (g.g1.df, g.g2.df) == pytest.approx((186, 690))
    assert g.g1.db == pytest.approx(216 * np.cos(D(20)))           # 202.97
    assert g.g2.db == pytest.approx(676.58, abs=0.01)
    assert g.p == pytest.approx(37.699, abs=1e-3) and g.pb == pytest.approx(35.425, abs=1e-3)
    assert g.g1.s == pytest.approx(18.850, abs=1e-3) and g.g1.e == pytest.approx(18.850, abs=1e-3)
    assert g.clearance == pytest.approx(3.0)
    assert g.a == pytest.approx(468) and g.a_work == pytest.approx(468)
    assert g.ratio == pytest.approx(60 / 18)


def test_contact_ratio_equals_action_length_over_base_pitch():
    """ε by the tip pressure angles against B1B2 = √(ra1² − rb1²) + √(ra2² − rb2²) − a' sin α'.
    For the shaper pair this is 1.658: the seed's 1.69 was measured on its drawing."""
    for x1, x2 in ((0, 0), (0.3, -0.3), (0.5, 0.2)):
        g = spur_pair(12, 18, 60, x1=x1, x2=x2)
        ra1, ra2, rb1, rb2 = g.g1.da / 2, g.g2.da / 2, g.g1.db / 2, g.g2.db / 2
        b1b2 = np.sqrt(ra1**2 - rb1**2) + np.sqrt(ra2**2 - rb2**2) - g.a_work * np.sin(g.alpha_work)
        assert g.contact_ratio == pytest.approx(b1b2 / g.pb, rel=1e-12)
    assert spur_pair(12, 18, 60).contact_ratio == pytest.approx(1.658, abs=1e-3)


@pytest.mark.parametrize("x1, x2", [(0.5, 0.2), (0.3, 0.0), (0.6, -0.1), (0.2, 0.4)])
def test_profile_shifted_pair_meshes_without_backlash(x1, x2):
    """On the working pitch circles r' = r cos α / cos α' the two tooth thicknesses fill
    the working pitch: s1' + s2' = 2π r1' / z1, with s' = s r'/r − 2 r'(inv α' − inv α)."""
    g = spur_pair(5, 14, 33, x1=x1, x2=x2)
    aw = g.alpha_work
    th = []
    for gear in (g.g1, g.g2):
        r, rw = gear.d / 2, gear.d / 2 * np.cos(g.alpha) / np.cos(aw)
        th.append(gear.s * rw / r - 2 * rw * (inv(aw) - inv(g.alpha)))
    rw1 = g.g1.d / 2 * np.cos(g.alpha) / np.cos(aw)
    assert th[0] + th[1] == pytest.approx(2 * np.pi * rw1 / 14, rel=1e-12)
    assert g.g1.d / 2 * np.cos(g.alpha) / np.cos(aw) + g.g2.d / 2 * np.cos(g.alpha) / np.cos(aw) == \
        pytest.approx(g.a_work, rel=1e-12)
    assert g.clearance == pytest.approx(0.25 * 5, rel=1e-12)       # tips shortened by Δy m


def test_undercut_limits_are_the_textbooks():
    """孙桓《机械原理》 (变位齿轮): a standard gear cut by a rack has no undercut for
    z ≥ z_min = 17 (α = 20°, h_a* = 1) and z_min = 14 for short teeth (h_a* = 0.8); a gear
    below it needs the shift x ≥ x_min = h_a*(z_min − z)/z_min, (17 − z)/17 for α = 20°,
    h_a* = 1. The textbook's numbers, not 2h_a*/sin²α = 17.10 (13.68 for h_a* = 0.8)."""
    g = spur_pair(2, 12, 40)
    assert g.z_min == 17
    assert g.x_min1 == pytest.approx(5 / 17, rel=1e-12)
    assert g.x_min2 == pytest.approx(-23 / 17, rel=1e-12)
    assert spur_pair(2, 17, 40).x_min1 == 0.0                       # 17 teeth: standard gear
    assert spur_pair(2, 12, 40, ha_star=0.8).z_min == 14
    assert spur_pair(2, 12, 40, ha_star=0.8).x_min1 == pytest.approx(0.8 * 2 / 14, rel=1e-12)


def test_a_17_tooth_standard_pinion_loses_no_working_involute():
    """Why the textbook accepts z = 17 below 2h_a*/sin²α = 17.10: the rack's tip line passes
    the limit point N by (h_a* − z sin²α/2) m = 0.0057 m, the generated flank leaves the
    involute only at the base circle, and a mating 51-tooth gear's tip first touches the
    pinion higher up, at √(r_b² + N₁B₂²) (B₂ where the gear's tip circle cuts N₁N₂)."""
    from mechdesign.core.gears import form_radius

    p = spur_pair(5, 17, 51)
    assert (1 - 17 * np.sin(D(20)) ** 2 / 2) * 5 == pytest.approx(0.02844, abs=1e-5)
    rb1, rb2, ra2 = 85 / 2 * np.cos(D(20)), 255 / 2 * np.cos(D(20)), 265 / 2
    n1b2 = 170 * np.sin(D(20)) - np.sqrt(ra2**2 - rb2**2)
    lowest_contact = np.hypot(rb1, n1b2)
    assert form_radius(p.g1, 5, p.alpha) < rb1 + 1e-4 < lowest_contact - 0.02


def test_tip_thickness_of_a_strongly_shifted_pinion_gets_small():
    """Tooth thickness at radius r: s_r = s r/r_ref − 2r(inv α_r − inv α); a large shift
    thins the tip (pointing)."""
    plain, shifted = spur_pair(4, 12, 40).g1, spur_pair(4, 12, 40, x1=0.8).g1
    assert shifted.sa < plain.sa
    # by hand, z = 12, m = 4: r = 24, ra = 28, cos αa = 24 cos 20° / 28 → αa = 36.35°,
    # inv αa = 0.10145; sa = (π·4/2)·28/24 − 2·28·(0.10145 − 0.014904) = 2.4836 mm
    assert plain.sa == pytest.approx(2.4836, abs=2e-4)


def test_helical_and_worm_geometry():
    h = helical_pair(3, 20, 80, D(15))
    assert h.mt == pytest.approx(3 / np.cos(D(15)))
    assert h.a == pytest.approx(3 * 100 / (2 * np.cos(D(15))))
    assert np.tan(h.alpha_t) == pytest.approx(np.tan(D(20)) / np.cos(D(15)))
    w = worm_pair(5, 10, 2, 40)
    assert (w.d1, w.d2, w.a, w.ratio) == pytest.approx((50, 200, 125, 20))
    assert np.tan(w.lead_angle) == pytest.approx(0.2)
    # self-locking when γ ≤ φ_v: efficiency below one half
    assert worm_efficiency(D(3), D(5)) < 0.5 < worm_efficiency(D(20), D(2))
