"""Disc cams (mechdesign.core.cam): programme, synthesis by inversion, base circle, eccentric disc.

Every expected value here comes from a reference that does not use the module's formulas:

* closed forms written out by hand in this file (cycloidal / uniform / parabolic / harmonic
  displacements and their derivatives, the inversion formulas of 孙桓《机械原理》 chapter 7,
  the textbook pressure-angle formula tan α = |ds/dδ − e| / (s0 + s));
* the pole (instant centre) method: the common normal at the contact passes through the
  relative instant centre of cam and follower, so the pressure angle follows from geometry;
* plain geometry: the envelope property of a roller profile (every actual-profile point lies at
  distance r_r from the pitch curve), the circle through three neighbouring points
  (discrete curvature), least-squares circle fits;
* finite differences of the module's own displacements (consistency of the derivatives);
* textbook numbers: exercise 7-1 (eccentric disc R = 40, ε = 20 mm), 7-3 (offset roller
  follower), and the shaper cam of seed 000 (/work/shared/BRIEFS.md).

Conventions of the module (its docstring): cam sense σ = +1 ccw / −1 cw, a frame point P is
P·e^(−iσδ) on the cam, translating followers move along +y with their axis at x = e.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.spatial import cKDTree

from mechdesign.core.cam import (
    CamDesignError,
    OscillatingFollower,
    Programme,
    Segment,
    TranslatingFollower,
    design_cam,
    eccentric_disc,
    favourable_offset_sign,
    min_base_radius_oscillating,
    min_base_radius_translating,
)
from mechdesign.core.motion_laws import LAWS

PI = math.pi
MM = 1e-3
D = math.radians


# ---------------------------------------------------------------------- hand-written references


def cycloid(u):
    """Cycloidal law S, S', S'' in u ∈ [0, 1] (textbook: s = h(u − sin 2πu / 2π))."""
    x = 2 * PI * u
    return u - np.sin(x) / (2 * PI), 1 - np.cos(x), 2 * PI * np.sin(x)


# Exercise 7-3 (孙桓 ch. 7): rise 120° cycloidal h = 30 mm, dwell 30°, return 150°, dwell 60°.
H73, R0_73, E73, RR73 = 30 * MM, 50 * MM, 12 * MM, 10 * MM
RISE73, DWELL73, RET73 = D(120), D(30), D(150)
RET73_START = RISE73 + DWELL73        # 150°
RET73_END = RET73_START + RET73       # 300°


def programme_73(return_law: str = "constant_velocity") -> Programme:
    return Programme([Segment("rise", RISE73, "cycloidal", H73), Segment("dwell", DWELL73),
                      Segment("return", RET73, return_law), Segment("dwell", D(60))])


def motion_73(delta, return_law: str = "constant_velocity"):
    """s, ds/dδ, d²s/dδ² of exercise 7-3 written out by hand (segments closed on the left)."""
    d = np.mod(np.asarray(delta, dtype=float), 2 * PI)
    s, ds, d2s = np.zeros_like(d), np.zeros_like(d), np.zeros_like(d)
    rise = d < RISE73
    u = d[rise] / RISE73
    S, S1, S2 = cycloid(u)
    s[rise], ds[rise], d2s[rise] = H73 * S, H73 * S1 / RISE73, H73 * S2 / RISE73**2
    s[(d >= RISE73) & (d < RET73_START)] = H73
    ret = (d >= RET73_START) & (d < RET73_END)
    u = (d[ret] - RET73_START) / RET73
    if return_law == "constant_velocity":       # uniform return: s = h(1 − u)
        s[ret], ds[ret] = H73 * (1 - u), -H73 / RET73
    else:                                       # cycloidal return: s = h(1 − S(u))
        S, S1, S2 = cycloid(u)
        s[ret], ds[ret], d2s[ret] = H73 * (1 - S), -H73 * S1 / RET73, -H73 * S2 / RET73**2
    return s, ds, d2s


def translating_pitch(delta, s, e, r0, sigma):
    """Roller centre (e, s0 + s) of the frame turned by −σδ into the cam frame (inversion).

    For σ = +1 this is the textbook pair x = (s0 + s) sin δ + e cos δ,
    y = (s0 + s) cos δ − e sin δ.
    """
    s0 = math.sqrt(r0 * r0 - e * e)
    c, sn = np.cos(delta), np.sin(delta)
    x = e * c + sigma * (s0 + s) * sn
    y = -sigma * e * sn + (s0 + s) * c
    return x + 1j * y


def half_step_grid(n: int) -> np.ndarray:
    """n cam angles offset by half a step, so no sample falls on a segment joint."""
    return (np.arange(n) + 0.5) * (2 * PI / n)


def angle_between_lines(u, v):
    """Acute angle between lines with complex directions u and v."""
    return np.arctan2(np.abs(np.imag(np.conj(u) * v)), np.abs(np.real(np.conj(u) * v)))


def discrete_rho(a, b, c, orientation):
    """Signed radius of the circle through three neighbouring points a, b, c (complex).

    Positive where the curve turns the same way as the whole closed curve is traversed
    (``orientation`` = sign of its enclosed signed area), i.e. where it is convex.
    """
    cross = np.imag(np.conj(b - a) * (c - b))
    kappa = 2 * cross / (np.abs(b - a) * np.abs(c - b) * np.abs(c - a))
    return orientation / kappa


def signed_area(z):
    return 0.5 * float(np.sum(np.imag(np.conj(z) * np.roll(z, -1))))


# ---------------------------------------------------------------------- 1. programme


def mixed_programme() -> Programme:
    """Two rises and two returns with several laws; stroke 30 mm."""
    return Programme([
        Segment("rise", D(50), "poly345", 20 * MM),
        Segment("dwell", D(20)),
        Segment("rise", D(40), "modified_sine", 10 * MM),
        Segment("dwell", D(30)),
        Segment("return", D(60), "harmonic", 15 * MM),
        Segment("return", D(70), "parabolic"),          # back to the start: 15 mm
        Segment("rise", D(30), "cycloidal", 5 * MM),
        Segment("return", D(40), "modified_trapezoid"),  # back to the start: 5 mm
        Segment("dwell", D(20)),
    ], stroke=30 * MM)


#: signed lift of every segment of mixed_programme, and its interior law breakpoints (u)
MIXED_LIFTS = [20, 0, 10, 0, -15, -15, 5, -5, 0]
MIXED_BREAKS = [(), (), (1 / 8, 7 / 8), (), (), (1 / 2,), (), (1 / 8, 3 / 8, 5 / 8, 7 / 8), ()]
MIXED_SPANS = [50, 20, 40, 30, 60, 70, 30, 40, 20]


def test_displacement_at_segment_ends_equals_the_cumulative_lifts():
    """s at the end of every segment (approached from inside, and at the joint itself)
    equals the sum of the signed lifts so far; the follower starts at s = 0."""
    prog = mixed_programme()
    ends = np.radians(np.cumsum(MIXED_SPANS))
    levels = np.cumsum(MIXED_LIFTS) * MM
    starts = np.concatenate([[0.0], ends[:-1]])
    inside_end = prog.evaluate(ends - 1e-10).s
    at_joint = prog.evaluate(ends).s                    # the next segment's start (360° → 0°)
    at_start = prog.evaluate(starts + 1e-10).s
    np.testing.assert_allclose(inside_end, levels, atol=1e-11)
    np.testing.assert_allclose(at_joint, levels, atol=1e-15)
    np.testing.assert_allclose(at_start, np.concatenate([[0.0], levels[:-1]]), atol=1e-11)
    assert prog.evaluate(0.0).s == 0.0


def test_derivatives_against_central_differences():
    """ds/dδ, d²s/dδ², d³s/dδ³ equal central differences (step 1e-5 rad) of s, ds, d2s at
    points inside every segment, away from joints and from the laws' interior breakpoints."""
    prog = mixed_programme()
    h = 1e-5
    starts = np.radians(np.concatenate([[0], np.cumsum(MIXED_SPANS)[:-1]]))
    pts = []
    for start, span, breaks in zip(starts, np.radians(MIXED_SPANS), MIXED_BREAKS):
        u = np.linspace(0.01, 0.99, 197)
        for b in breaks:
            u = u[np.abs(u - b) > 1e-3]
        pts.append(start + u * span)
    d = np.concatenate(pts)
    m, mp, mm_ = prog.evaluate(d), prog.evaluate(d + h), prog.evaluate(d - h)
    fd1 = (mp.s - mm_.s) / (2 * h)
    fd2 = (mp.ds - mm_.ds) / (2 * h)
    fd3 = (mp.d2s - mm_.d2s) / (2 * h)
    np.testing.assert_allclose(m.ds, fd1, rtol=0, atol=1e-7 * np.max(np.abs(m.ds)))
    np.testing.assert_allclose(m.d2s, fd2, rtol=0, atol=1e-7 * np.max(np.abs(m.d2s)))
    np.testing.assert_allclose(m.d3s, fd3, rtol=0, atol=1e-6 * np.max(np.abs(m.d3s)))
    # The check has teeth: the derivatives are not identically zero anywhere it matters.
    assert np.max(np.abs(m.ds)) > 0.01 and np.max(np.abs(m.d3s)) > 1.0


def test_exercise_73_displacement_matches_hand_closed_form():
    """The 7-3 programme equals s = h(δ/Φ − sin(2πδ/Φ)/2π) on the rise, h(1 − u) on the
    uniform return, and the dwells, with the hand-differentiated derivatives."""
    d = half_step_grid(3600)
    m = programme_73().evaluate(d)
    s, ds, d2s = motion_73(d)
    np.testing.assert_allclose(m.s, s, rtol=0, atol=1e-15)
    np.testing.assert_allclose(m.ds, ds, rtol=0, atol=1e-14)
    np.testing.assert_allclose(m.d2s, d2s, rtol=0, atol=1e-13)


def test_impacts_cycloidal_rise_uniform_return():
    """Cycloidal rise between dwells: no impact; uniform (constant-velocity) return between
    dwells: velocity jumps of h/Φ' at both ends, rigid impact (刚性冲击)."""
    prog = programme_73()
    assert prog.impacts() == ["none", "none", "rigid", "none"]
    b = prog.boundaries()
    assert b[2].velocity_jump == pytest.approx(-H73 / RET73, rel=1e-12)   # 150°: 0 → −h/Φ'
    assert b[3].velocity_jump == pytest.approx(+H73 / RET73, rel=1e-12)   # 300°: −h/Φ' → 0
    assert b[0].impact == b[1].impact == "none"


@pytest.mark.parametrize("law", ["parabolic", "harmonic"])
def test_impacts_parabolic_and_harmonic_next_to_dwells_are_soft(law):
    """Parabolic (等加速等减速) and harmonic (简谐) rises/returns joined to dwells start and end
    with a finite acceleration: an acceleration jump, soft impact (柔性冲击)."""
    prog = Programme([Segment("rise", D(90), law, 10 * MM), Segment("dwell", D(90)),
                      Segment("return", D(90), law), Segment("dwell", D(90))])
    assert prog.impacts() == ["soft", "none", "soft", "none"]
    # Harmonic: the rise starts with a = h π²/(2Φ²); parabolic: with 4h/Φ².
    a0 = 10 * MM * (PI**2 / 2 if law == "harmonic" else 4.0) / D(90) ** 2
    b = prog.boundaries()
    assert b[0].velocity_jump == pytest.approx(0.0, abs=1e-15)
    assert b[0].acceleration_jump == pytest.approx(a0, rel=1e-12)


def _impact_points(prog):
    """(δ [°], impact) of every joint with an impact and every jump inside a law."""
    pts = [(b.delta, b.impact) for b in prog.boundaries() if b.impact != "none"]
    pts += [(b.delta, b.impact) for _, b in prog.internal_jumps()]
    return sorted((round(math.degrees(d), 9), k) for d, k in pts)


def test_parabolic_law_has_soft_impacts_at_start_middle_and_end():
    """孙桓: the parabolic (等加速等减速) law, S'' = +4 on u < 1/2 and −4 on u > 1/2, joined to
    dwells: the acceleration jumps by 4h/Φ² at u = 0, by −8h/Φ² at u = 1/2 and by 4h/Φ² at
    u = 1 (soft impacts, no velocity jump); the return mirrors it. The shaper's programme
    (rise 70°, dwell 10°, return 70°, dwell 210°) has them at 0, 35, 70, 80, 115 and 150°."""
    h, rise, ret = 15 * MM, D(70), D(70)
    prog = Programme([Segment("rise", rise, "parabolic", h), Segment("dwell", D(10)),
                      Segment("return", ret, "parabolic"), Segment("dwell", D(210))])
    assert _impact_points(prog) == [(0.0, "soft"), (35.0, "soft"), (70.0, "soft"),
                                    (80.0, "soft"), (115.0, "soft"), (150.0, "soft")]
    (i0, mid_rise), (i2, mid_ret) = prog.internal_jumps()
    assert (i0, i2) == (0, 2)
    assert mid_rise.acceleration_jump == pytest.approx(-8 * h / rise**2, rel=1e-12)
    assert mid_ret.acceleration_jump == pytest.approx(+8 * h / ret**2, rel=1e-12)
    assert abs(mid_rise.velocity_jump) < 1e-12 * h / rise


@pytest.mark.parametrize("law", ["cycloidal", "poly345", "poly4567", "modified_trapezoid",
                                 "modified_sine"])
def test_laws_with_continuous_acceleration_have_no_impact_point(law):
    """Cycloidal, the polynomials and the modified laws have S' and S'' continuous inside
    (the modified laws' breakpoints join smoothly) and zero at both ends: no point at all."""
    prog = Programme([Segment("rise", D(100), law, 20 * MM), Segment("dwell", D(60)),
                      Segment("return", D(120), law), Segment("dwell", D(80))])
    assert _impact_points(prog) == []


def test_harmonic_law_has_impacts_at_its_ends_only_next_to_dwells():
    """Simple harmonic: S'' = (π²/2) cos πu is continuous inside; next to dwells it jumps at
    both ends (soft impact), nowhere inside."""
    prog = Programme([Segment("rise", D(90), "harmonic", 10 * MM), Segment("dwell", D(90)),
                      Segment("return", D(90), "harmonic"), Segment("dwell", D(90))])
    assert _impact_points(prog) == [(0.0, "soft"), (90.0, "soft"), (180.0, "soft"),
                                    (270.0, "soft")]


def test_report_lists_the_mid_points_of_the_parabolic_law(example_results):
    """The shaper's cam (parabolic rise 0–70°, return 80–150°): the report's list of impact
    points names the middles 35° and 115° besides the four joints, in order."""
    from mechdesign.render.cam_report import cam_context

    c = example_results("shaper")["cam"]
    en = cam_context(c, "en", {}, "cam_profile.csv")["joints"]
    assert en == ("0.0° (soft impact), 35.0° (soft impact, middle of the rise), "
                  "70.0° (soft impact), 80.0° (soft impact), "
                  "115.0° (soft impact, middle of the return), 150.0° (soft impact)")
    zh = cam_context(c, "zh", {}, "cam_profile.csv")["joints"]
    assert "35.0°（柔性冲击，推程中点）" in zh and "115.0°（柔性冲击，回程中点）" in zh


def test_cycloidal_rise_directly_into_cycloidal_return_has_no_impact():
    """Cycloidal rise then cycloidal return without a dwell: at the top v = a = 0 on both
    sides, so no jump anywhere."""
    prog = Programme([Segment("rise", D(120), "cycloidal", 10 * MM),
                      Segment("return", D(120), "cycloidal"), Segment("dwell", D(120))])
    assert prog.impacts() == ["none", "none", "none"]
    assert all(b.impact == "none" for b in prog.boundaries())


def test_harmonic_rise_directly_into_harmonic_return_has_no_impact():
    """Harmonic rise 180° + harmonic return 180° is s = h(1 − cos δ)/2: smooth everywhere,
    its end accelerations ±hπ²/(2Φ²) match across both joints, so no impact at all."""
    prog = Programme([Segment("rise", PI, "harmonic", 10 * MM), Segment("return", PI, "harmonic")])
    assert prog.impacts() == ["none", "none"]


def test_programme_angles_must_sum_to_360():
    with pytest.raises(CamDesignError, match="360"):
        Programme([Segment("rise", D(120), "cycloidal", 10 * MM), Segment("return", D(120), "cycloidal"),
                   Segment("dwell", D(110))])


def test_returns_must_undo_the_rises():
    with pytest.raises(CamDesignError, match="undo the rises"):
        Programme([Segment("rise", D(120), "cycloidal", 30 * MM), Segment("dwell", D(30)),
                   Segment("return", D(150), "constant_velocity", 20 * MM), Segment("dwell", D(60))])
    with pytest.raises(CamDesignError, match="outside 0"):        # return below the start
        Programme([Segment("rise", D(120), "cycloidal", 30 * MM),
                   Segment("return", D(150), "constant_velocity", 40 * MM), Segment("dwell", D(90))])


def test_programme_rejects_bad_segments():
    with pytest.raises(CamDesignError, match="motion law"):
        Programme([Segment("rise", PI, "sine_wave", 1 * MM), Segment("return", PI, "cycloidal")])
    with pytest.raises(CamDesignError, match="stroke"):
        Programme([Segment("rise", PI, "cycloidal"), Segment("return", PI, "cycloidal")])


# ---------------------------------------------------------------------- 2. exercise 7-3


@pytest.fixture(scope="module")
def cam73():
    follower = TranslatingFollower("roller", offset=E73, roller_radius=RR73)
    d = half_step_grid(3600)
    return d, design_cam(programme_73(), follower, R0_73, rotation=1, delta=d)


def test_73_initial_position_and_values_at_60_degrees():
    """s0 = √(r0² − e²) = √(50² − 12²) mm; at δ = 60° (half the cycloidal rise) s = h/2 = 15 mm
    and ds/dδ = h(1 − cos π)/Φ = 2h/Φ; the pitch point there is the textbook
    x = (s0 + s) sin δ + e cos δ, y = (s0 + s) cos δ − e sin δ."""
    follower = TranslatingFollower("roller", offset=E73, roller_radius=RR73)
    c = design_cam(programme_73(), follower, R0_73, rotation=1, delta=np.array([0.0, D(60)]))
    s0 = math.sqrt(50**2 - 12**2) * MM
    assert c.initial_angle == pytest.approx(s0, rel=1e-15)
    assert abs(c.pitch[0]) == pytest.approx(R0_73, rel=1e-14)       # on the base circle
    assert c.motion.s[1] == pytest.approx(15 * MM, rel=1e-14)
    assert c.motion.ds[1] == pytest.approx(2 * H73 / RISE73, rel=1e-14)
    x = (s0 + 15 * MM) * math.sin(D(60)) + E73 * math.cos(D(60))
    y = (s0 + 15 * MM) * math.cos(D(60)) - E73 * math.sin(D(60))
    assert c.pitch[1].real == pytest.approx(x, rel=1e-13)
    assert c.pitch[1].imag == pytest.approx(y, rel=1e-13)


def test_73_pitch_curve_equals_inversion_formula(cam73):
    """Whole cycle: pitch = (e, s0 + s) turned by −δ (ccw cam); the roller centre in the frame
    is (e, s0 + s)."""
    d, c = cam73
    s, _, _ = motion_73(d)
    np.testing.assert_allclose(c.pitch, translating_pitch(d, s, E73, R0_73, 1), rtol=0, atol=1e-14)
    s0 = math.sqrt(R0_73**2 - E73**2)
    np.testing.assert_allclose(c.follower_point, E73 + 1j * (s0 + s), rtol=0, atol=1e-15)


def test_73_pressure_angle_textbook_formula(cam73):
    """tan α = |ds/dδ − e| / (s0 + s) (offset on the favourable side of a ccw cam) over the
    whole cycle, dwells included (there α = atan(e/(s0 + s)))."""
    d, c = cam73
    s, ds, _ = motion_73(d)
    s0 = math.sqrt(R0_73**2 - E73**2)
    ref = np.arctan(np.abs(ds - E73) / (s0 + s))
    np.testing.assert_allclose(c.pressure_angle, ref, rtol=0, atol=1e-12)
    # sanity of the reference itself: the 7-3 rise stays below the usual 30° limit
    assert np.degrees(ref[d < RISE73].max()) < 30


def test_73_pressure_angle_by_the_pole_method(cam73):
    """Pole method: the relative instant centre P of cam and follower lies on the x-axis where
    a cam point moves like the follower: ω×OP = v, i.e. x_P = ds/dδ for a ccw cam. The
    common normal at the contact passes through P and the roller centre B; α is the angle
    between PB and the follower's direction of motion (+y). The module's normal must also
    lie along PB (transformed to the frame)."""
    d, c = cam73
    s, ds, _ = motion_73(d)
    s0 = math.sqrt(R0_73**2 - E73**2)
    B = E73 + 1j * (s0 + s)
    P = ds + 0j
    alpha = angle_between_lines(B - P, 1j * np.ones_like(B))
    np.testing.assert_allclose(c.pressure_angle, alpha, rtol=0, atol=1e-12)
    n_frame = c.normal * np.exp(1j * d)          # cam frame → fixed frame: turn by +σδ
    cross = np.imag(np.conj(n_frame) * (B - P)) / np.abs(B - P)
    assert np.max(np.abs(cross)) < 1e-12
    # the contact point lies on that normal, r_r from B, on the cam's side
    np.testing.assert_allclose(np.abs(c.contact - B), RR73, rtol=1e-13)


# ---------------------------------------------------------------------- 3. envelope


def dense_pitch_73(return_law: str, n: int = 400_000) -> np.ndarray:
    d = np.arange(n) * (2 * PI / n)
    s, _, _ = motion_73(d, return_law)
    return translating_pitch(d, s, E73, R0_73, 1)


def distance_to_curve(points: np.ndarray, curve: np.ndarray) -> np.ndarray:
    tree = cKDTree(np.column_stack([curve.real, curve.imag]))
    dist, _ = tree.query(np.column_stack([points.real, points.imag]))
    return dist


@pytest.mark.parametrize("return_law", ["cycloidal", "constant_velocity"])
def test_actual_profile_is_the_true_envelope(return_law):
    """Every actual-profile point is r_r from its own pitch point AND r_r from the whole pitch
    curve (minimum distance to 400 000 samples of the hand-written pitch curve, spacing
    ≈ 1 µm): that is what the envelope of the roller circles means. The uniform return has
    velocity jumps (pitch-curve kinks) at 150° and 300°; ±2° around them are left out."""
    d = half_step_grid(3600)
    prof = design_cam(programme_73(return_law), TranslatingFollower("roller", E73, RR73),
                      R0_73, rotation=1, delta=d)
    keep = np.ones_like(d, dtype=bool)
    if return_law == "constant_velocity":
        for kink in (RET73_START, RET73_END):
            keep &= np.abs(d - kink) > D(2)
    np.testing.assert_allclose(np.abs(prof.actual - prof.pitch), RR73, rtol=1e-13)
    dist = distance_to_curve(prof.actual[keep], dense_pitch_73(return_law))
    np.testing.assert_allclose(dist, RR73, rtol=1e-6)


def test_radial_offset_is_not_an_envelope():
    """Control for the envelope test: moving each pitch point r_r towards the cam centre (a
    radial offset) keeps |q − p| = r_r but brings q closer than r_r to the pitch curve wherever
    the pitch normal is not radial, so the same distance check must fail for it."""
    d = half_step_grid(3600)
    prof = design_cam(programme_73("cycloidal"), TranslatingFollower("roller", E73, RR73),
                      R0_73, rotation=1, delta=d)
    radial = prof.pitch * (1 - RR73 / np.abs(prof.pitch))
    dist = distance_to_curve(radial, dense_pitch_73("cycloidal"))
    assert np.max(RR73 - dist) > 1e-2 * RR73           # off by far more than the 1e-6 tolerance
    # and it really differs from the module's profile
    assert np.max(np.abs(radial - prof.actual)) > 1e-4


# ---------------------------------------------------------------------- 4. normal and curvature


@pytest.mark.parametrize("rotation", [1, -1])
def test_normal_is_perpendicular_to_pitch_tangent_and_points_outwards(rotation):
    """The profile normal is ⟂ to the central-difference tangent of the pitch curve
    (p(δ+h) − p(δ−h)), points away from the cam, and the actual profile is p − r_r·n."""
    follower = TranslatingFollower("roller", rotation * E73, RR73)
    prog, h = programme_73("cycloidal"), 1e-6
    d = half_step_grid(720)
    c = design_cam(prog, follower, R0_73, rotation, delta=d)
    tangent = (design_cam(prog, follower, R0_73, rotation, delta=d + h).pitch
               - design_cam(prog, follower, R0_73, rotation, delta=d - h).pitch)
    cos_nt = np.real(np.conj(c.normal) * tangent) / np.abs(tangent)
    assert np.max(np.abs(cos_nt)) < 1e-8
    np.testing.assert_allclose(np.abs(c.normal), 1.0, rtol=1e-14)
    assert np.all(np.real(np.conj(c.normal) * c.pitch) > 0)          # outward
    np.testing.assert_allclose(c.actual, c.pitch - RR73 * c.normal, rtol=0, atol=1e-16)


def steep_programme() -> Programme:
    """A steep cam (h = 30 mm over 60°) whose pitch curve has concave stretches."""
    return Programme([Segment("rise", D(60), "poly345", 30 * MM), Segment("dwell", D(60)),
                      Segment("return", D(90), "cycloidal"), Segment("dwell", D(150))])


@pytest.mark.parametrize("rotation", [1, -1])
@pytest.mark.parametrize("case", ["73_cycloidal", "steep"])
def test_radius_of_curvature_against_three_point_circles(case, rotation):
    """ρ of the pitch curve equals the signed radius of the circle through the pitch points at
    δ − h, δ, δ + h (h = 2e-4 rad; positive where the curve turns like the whole closed curve,
    i.e. convex); ρ_actual = ρ_pitch − r_r, and it too equals the three-point radius of the
    actual profile. The steep cam exercises concave stretches (ρ < 0)."""
    if case == "steep":
        prog, r0, e, rr = steep_programme(), 30 * MM, 0.0, 5 * MM
    else:
        prog, r0, e, rr = programme_73("cycloidal"), R0_73, rotation * E73, RR73
    follower = TranslatingFollower("roller", e, rr)
    h = 2e-4
    d = half_step_grid(1440)
    c0 = design_cam(prog, follower, r0, rotation, delta=d)
    cm = design_cam(prog, follower, r0, rotation, delta=d - h)
    cp = design_cam(prog, follower, r0, rotation, delta=d + h)
    orient = np.sign(signed_area(design_cam(prog, follower, r0, rotation, points=7200).pitch))
    rho_p = discrete_rho(cm.pitch, c0.pitch, cp.pitch, orient)
    rho_a = discrete_rho(cm.actual, c0.actual, cp.actual, orient)
    # compared as curvatures 1/ρ: near an inflection ρ → ∞ and only 1/ρ is well conditioned
    k_p = 1 / rho_p
    np.testing.assert_allclose(1 / c0.rho_pitch, k_p, rtol=1e-5, atol=1e-6 * np.max(np.abs(k_p)))
    np.testing.assert_allclose(c0.rho_actual, c0.rho_pitch - rr, rtol=1e-14, atol=1e-16)
    # the actual profile's own circles (skip where |ρ_a| is small compared with r_r: there
    # the three actual points crowd together and the difference quotient loses digits)
    ok = np.abs(c0.rho_actual) > 0.2 * rr
    k_a = 1 / rho_a[ok]
    np.testing.assert_allclose(1 / c0.rho_actual[ok], k_a, rtol=1e-5, atol=1e-6 * np.max(np.abs(k_a)))
    if case == "steep":
        assert np.min(c0.rho_pitch) < 0 < np.max(c0.rho_pitch)      # both signs exercised


# ---------------------------------------------------------------------- 5. eccentric disc, flat follower


@pytest.mark.parametrize("rotation", [1, -1])
def test_flat_follower_on_harmonic_programme_gives_the_eccentric_circle(rotation):
    """A disc of radius R with its centre ε from the axis moves a centred flat-faced follower by
    s = ε(1 − cos δ) — a harmonic rise of h = 2ε over 180° then a harmonic return over 180°.
    Synthesising that programme with r0 = R − ε must give back the disc: a circle of radius R
    about the point ε below the axis (the disc centre at δ = 0, when the follower is lowest),
    with ρ = R everywhere. A least-squares circle fit, which assumes no centre, agrees."""
    R, eps = 40 * MM, 20 * MM
    prog = Programme([Segment("rise", PI, "harmonic", 2 * eps), Segment("return", PI, "harmonic")])
    d = np.arange(3600) * (2 * PI / 3600)
    np.testing.assert_allclose(prog.evaluate(d).s, eps * (1 - np.cos(d)), rtol=0, atol=1e-15)
    c = design_cam(prog, TranslatingFollower("flat"), R - eps, rotation, delta=d)
    np.testing.assert_allclose(np.abs(c.actual - (-1j * eps)), R, rtol=1e-13)
    np.testing.assert_allclose(c.rho_actual, R, rtol=1e-13)
    np.testing.assert_allclose(c.rho_pitch, R, rtol=1e-13)
    # Kåsa fit x² + y² + Dx + Ey + F = 0
    x, y = c.actual.real, c.actual.imag
    A = np.column_stack([x, y, np.ones_like(x)])
    (Dc, Ec, Fc), *_ = np.linalg.lstsq(A, -(x * x + y * y), rcond=None)
    centre = complex(-Dc / 2, -Ec / 2)
    radius = math.sqrt(Dc * Dc / 4 + Ec * Ec / 4 - Fc)
    assert radius == pytest.approx(R, rel=1e-12)
    assert abs(centre) == pytest.approx(eps, rel=1e-12)
    # the contact points cover the whole circle (the profile is the full disc)
    ang = np.sort(np.angle(c.actual - centre))
    assert np.max(np.diff(ang)) < D(1)
    # the face is where eccentric_disc puts a flat face: y = C_y + R = R − ε cos δ
    disc = eccentric_disc(d, R, eps, TranslatingFollower("flat"), rotation)
    np.testing.assert_allclose(c.follower_point.imag, R - eps * np.cos(d), rtol=0, atol=1e-15)
    np.testing.assert_allclose(disc.y, R - eps * np.cos(d), rtol=0, atol=1e-15)


@pytest.mark.parametrize("rotation", [1, -1])
def test_translating_flat_face_contact_by_the_pole_method(rotation):
    """Flat face ⟂ to the axis at height r0 + s: the common normal is vertical and passes through
    the pole x = σ·ds/dδ, so the contact is at (σ·ds/dδ, r0 + s) in the frame (the textbook
    'contact offset = ds/dδ'); α = 0; ρ = r0 + s + d²s/dδ² equals the three-point radius of the
    profile; the normal is ⟂ to the profile's central-difference tangent."""
    prog, r0, h = programme_73("cycloidal"), 40 * MM, 2e-4
    d = half_step_grid(1440)
    c = design_cam(prog, TranslatingFollower("flat"), r0, rotation, delta=d)
    cm = design_cam(prog, TranslatingFollower("flat"), r0, rotation, delta=d - h)
    cp = design_cam(prog, TranslatingFollower("flat"), r0, rotation, delta=d + h)
    s, ds, d2s = motion_73(d, "cycloidal")
    np.testing.assert_allclose(c.contact, rotation * ds + 1j * (r0 + s), rtol=0, atol=1e-15)
    np.testing.assert_allclose(c.actual, c.contact * np.exp(-1j * rotation * d), rtol=0, atol=1e-15)
    np.testing.assert_array_equal(c.pressure_angle, 0.0)
    np.testing.assert_allclose(c.rho_actual, r0 + s + d2s, rtol=1e-13)
    orient = np.sign(signed_area(c.actual))
    k_ref = 1 / discrete_rho(cm.actual, c.actual, cp.actual, orient)
    np.testing.assert_allclose(1 / c.rho_actual, k_ref, rtol=1e-5)
    tangent = cp.actual - cm.actual
    assert np.max(np.abs(np.real(np.conj(c.normal) * tangent)) / np.abs(tangent)) < 1e-7


@pytest.mark.parametrize("rotation", [1, -1])
@pytest.mark.parametrize("sense", ["same", "opposite"])
def test_oscillating_flat_face_contact_by_the_pole_method(rotation, sense):
    """Flat face through the pivot A (a = 150 mm), r0 = 80 mm: at φ = 0 the face is r0 from O;
    it turns by ±σφ about A; the contact lies on the face and is the foot of the perpendicular
    from the pole P (x_P = ω2·a/(ω2 − ω1) on OA), because the common normal ⟂ face passes
    through P; the profile normal is ⟂ to its tangent; ρ matches three-point circles."""
    prog = Programme([Segment("rise", D(120), "cycloidal", D(15)), Segment("dwell", D(30)),
                      Segment("return", D(120), "cycloidal"), Segment("dwell", D(90))])
    a, r0, h = 150 * MM, 80 * MM, 2e-4
    follower = OscillatingFollower("flat", a, rise_sense=sense)
    d = half_step_grid(1440)
    c = design_cam(prog, follower, r0, rotation, delta=d)
    cm = design_cam(prog, follower, r0, rotation, delta=d - h)
    cp = design_cam(prog, follower, r0, rotation, delta=d + h)
    m = prog.evaluate(d)
    face = (c.follower_point - a) / np.abs(c.follower_point - a)     # unit vector along the face
    # contact and foot on one line through A
    assert np.max(np.abs(np.imag(np.conj(face) * (c.contact - a)))) < 1e-15
    # base position (last sample, φ = 0): distance from O to the face line = r0
    assert abs(np.imag(np.conj(face[-1]) * (0 - a))) == pytest.approx(r0, rel=1e-14)
    turn = np.angle(face / face[-1])
    np.testing.assert_allclose(turn, (rotation if sense == "same" else -rotation) * m.s,
                               rtol=0, atol=1e-13)
    w1 = rotation
    w2 = (rotation if sense == "same" else -rotation) * m.ds
    P = w2 * a / (w2 - w1)
    np.testing.assert_allclose(np.real(np.conj(face) * (c.contact - P)), 0.0, atol=1e-15)
    np.testing.assert_array_equal(c.pressure_angle, 0.0)
    tangent = cp.actual - cm.actual
    assert np.max(np.abs(np.real(np.conj(c.normal) * tangent)) / np.abs(tangent)) < 1e-7
    orient = np.sign(signed_area(c.actual))
    k_ref = 1 / discrete_rho(cm.actual, c.actual, cp.actual, orient)
    np.testing.assert_allclose(1 / c.rho_actual, k_ref, rtol=1e-5, atol=1e-6 * np.max(np.abs(k_ref)))


# ---------------------------------------------------------------------- 6. shaper cam (seed 000)


A0, L0, R00, RR0 = 136 * MM, 120 * MM, 50 * MM, 15 * MM
PHI_MAX, F0, F01, F02 = D(15), D(70), D(10), D(70)


def shaper_programme() -> Programme:
    return Programme([Segment("rise", F0, "parabolic", PHI_MAX), Segment("dwell", F01),
                      Segment("return", F02, "parabolic"), Segment("dwell", D(210))])


def parabolic_phi(delta):
    """φ(δ) and dφ/dδ of the shaper cam, correctly differentiated (seed formulas for φ)."""
    d = np.mod(np.asarray(delta, dtype=float), 2 * PI)
    phi, dphi = np.zeros_like(d), np.zeros_like(d)
    a = d <= F0 / 2
    phi[a], dphi[a] = 2 * PHI_MAX * (d[a] / F0) ** 2, 4 * PHI_MAX * d[a] / F0**2
    b = (d > F0 / 2) & (d <= F0)
    phi[b] = PHI_MAX - 2 * PHI_MAX * ((F0 - d[b]) / F0) ** 2
    dphi[b] = 4 * PHI_MAX * (F0 - d[b]) / F0**2
    c = (d > F0) & (d < F0 + F01)
    phi[c] = PHI_MAX
    t0 = F0 + F01
    r1 = (d >= t0) & (d < t0 + F02 / 2)
    phi[r1] = PHI_MAX - 2 * PHI_MAX * ((d[r1] - t0) / F02) ** 2
    dphi[r1] = -4 * PHI_MAX * (d[r1] - t0) / F02**2
    r2 = (d >= t0 + F02 / 2) & (d < t0 + F02)
    phi[r2] = 2 * PHI_MAX * ((t0 + F02 - d[r2]) / F02) ** 2
    dphi[r2] = -4 * PHI_MAX * (t0 + F02 - d[r2]) / F02**2
    return phi, dphi


def seed_rise(F):
    """The seed's C program, rise part, transcribed (float → double): q and dqdf."""
    F = np.asarray(F, dtype=float)
    F1a = F / F0
    F1b = (F0 - F) / F0
    first = F <= F0 / 2
    q = np.where(first, 2 * PHI_MAX * F1a * F1a, PHI_MAX - 2 * PHI_MAX * F1b * F1b)
    dqdf = np.where(first, 4 * PHI_MAX * F1a / F0, 4 * q * F1b / F0)   # seed: 4*q*F1/F0 (sic)
    return q, dqdf


PHI0_DEG = 21.369   # arccos((136² + 120² − 50²)/(2·136·120)) = arccos(0.931250) in degrees


def test_shaper_initial_arm_angle_and_base_circle():
    """φ0 = arccos((a² + L² − r0²)/(2aL)) ≈ 21.369°; at δ = 0 the roller centre is on the base
    circle, |pitch| = r0."""
    phi0 = math.acos((136**2 + 120**2 - 50**2) / (2 * 136 * 120))
    assert math.degrees(phi0) == pytest.approx(PHI0_DEG, abs=5e-4)
    c = design_cam(shaper_programme(), OscillatingFollower("roller", A0, L0, RR0, "same"), R00,
                   rotation=-1, delta=np.array([0.0]))
    assert c.initial_angle == pytest.approx(phi0, rel=1e-14)
    assert abs(c.pitch[0]) == pytest.approx(R00, rel=1e-14)


def test_shaper_pitch_equals_the_seed_inversion_formula():
    """Clockwise cam, pivot A on +x: the seed's x = a cos δ − L cos(δ − φ − φ0),
    y = a sin δ − L sin(δ − φ − φ0), with φ(δ) of the parabolic rise/return."""
    d = half_step_grid(3600)
    c = design_cam(shaper_programme(), OscillatingFollower("roller", A0, L0, RR0, "same"), R00,
                   rotation=-1, delta=d)
    phi, _ = parabolic_phi(d)
    phi0 = math.acos((A0**2 + L0**2 - R00**2) / (2 * A0 * L0))
    x = A0 * np.cos(d) - L0 * np.cos(d - phi - phi0)
    y = A0 * np.sin(d) - L0 * np.sin(d - phi - phi0)
    np.testing.assert_allclose(c.pitch, x + 1j * y, rtol=0, atol=1e-14)
    np.testing.assert_allclose(np.abs(c.actual - c.pitch), RR0, rtol=1e-13)


def pole_pressure_angle(B, A, dphi, sigma, sense):
    """Pressure angle of an oscillating roller follower by the pole method.

    Cam (pivot O = 0) turns with ω1 = σ (per unit cam speed); the follower (pivot A on the
    real axis) with ω2 = ±σ·dφ/dδ ('same' / 'opposite'). The instant centre P of the two lies
    on OA where the velocities agree, ω1·OP = ω2·AP (signed): x_P = ω2·a / (ω2 − ω1). The
    common normal is PB; the roller centre moves ⟂ AB.
    """
    w1 = sigma
    w2 = sigma * dphi if sense == "same" else -sigma * dphi
    P = w2 * A / (w2 - w1)
    velocity_dir = 1j * (B - A)
    return angle_between_lines(B - P, velocity_dir)


def test_shaper_pressure_angle_by_the_pole_method():
    """Seed 000 cam: α by the pole method with the hand-written φ, dφ/dδ and roller centre
    B = a − L·e^(−i(φ + φ0)) in the frame."""
    d = half_step_grid(3600)
    c = design_cam(shaper_programme(), OscillatingFollower("roller", A0, L0, RR0, "same"), R00,
                   rotation=-1, delta=d)
    phi, dphi = parabolic_phi(d)
    phi0 = math.acos((A0**2 + L0**2 - R00**2) / (2 * A0 * L0))
    B = A0 - L0 * np.exp(-1j * (phi + phi0))
    np.testing.assert_allclose(c.follower_point, B, rtol=0, atol=1e-15)
    alpha = pole_pressure_angle(B, A0, dphi, -1, "same")
    np.testing.assert_allclose(c.pressure_angle, alpha, rtol=0, atol=1e-12)
    assert np.degrees(alpha.max()) > 20          # a non-trivial check


@pytest.mark.parametrize("rotation", [1, -1])
@pytest.mark.parametrize("sense", ["same", "opposite"])
def test_oscillating_geometry_and_pole_method_all_senses(rotation, sense):
    """For both cam senses and both rise senses: |AB| = L, |B| = r0 at φ = 0, the arm turns by
    +φ in the cam's sense ('same') or against it ('opposite'), and α agrees with the pole
    method."""
    d = half_step_grid(1800)
    follower = OscillatingFollower("roller", A0, L0, RR0, sense)
    c = design_cam(shaper_programme(), follower, R00, rotation, delta=d)
    B = c.follower_point
    phi, dphi = parabolic_phi(d)
    np.testing.assert_allclose(np.abs(B - A0), L0, rtol=1e-14)
    np.testing.assert_allclose(np.abs(B[phi == 0]), R00, rtol=1e-14)
    B_base = B[-1]                                   # last sample: in the 210° dwell, φ = 0
    assert phi[-1] == 0.0
    turn = np.angle((B - A0) / (B_base - A0))
    expected = rotation * phi if sense == "same" else -rotation * phi
    np.testing.assert_allclose(turn, expected, rtol=0, atol=1e-13)
    np.testing.assert_allclose(c.pressure_angle, pole_pressure_angle(B, A0, dphi, rotation, sense),
                               rtol=0, atol=1e-12)


def test_seed_c_program_derivative_is_wrong_but_laws_parabolic_is_right():
    """The seed's C program (deceleration half of the rise) has dqdf = 4*q*F1/F0, using the
    current swing q where the law needs φmax: d/dδ[φmax − 2φmax((F0 − δ)/F0)²] =
    4φmax(F0 − δ)/F0². Its value disagrees with the central difference of its own q(δ);
    LAWS['parabolic'] (and the programme built on it) agrees."""
    F = np.radians(np.linspace(36, 69, 34))          # deceleration half of the 70° rise
    h = 1e-6
    q, dq_seed = seed_rise(F)
    fd = (seed_rise(F + h)[0] - seed_rise(F - h)[0]) / (2 * h)
    # wrong by the factor q/φmax ∈ (0.5, 1): half the true speed just after the mid-point of
    # the rise, correct only where q reaches φmax at the end of the rise
    rel_err_seed = np.abs(dq_seed - fd) / np.abs(fd)
    assert np.max(rel_err_seed) > 0.45
    assert np.max(np.abs(dq_seed - fd)) > 0.1 * np.max(np.abs(fd))
    np.testing.assert_allclose(dq_seed / fd, q / PHI_MAX, rtol=1e-6)
    _, S1, _, _ = LAWS["parabolic"](F / F0)
    np.testing.assert_allclose(PHI_MAX * S1 / F0, fd, rtol=1e-8)
    np.testing.assert_allclose(shaper_programme().evaluate(F).ds, fd, rtol=1e-8)


# ---------------------------------------------------------------------- 7. base circle design


def max_alpha_translating(r0, e, sigma, return_law, n=20001):
    """Max pressure angle on the closed rise and on the closed return of 7-3 by
    tan α = |σ·ds − e| / (s0 + s) (pole at x = σ·ds/dδ), on n angles per segment including
    both ends (the uniform return is worst at its very end, s → 0)."""
    s0 = math.sqrt(r0 * r0 - e * e)
    out = []
    for start, span in ((0.0, RISE73), (RET73_START, RET73)):
        d = start + np.linspace(0.0, 1.0, n) * span
        d[-1] = start + span * (1 - 1e-15)              # stay inside the segment at u = 1
        s, ds, _ = motion_73(d, return_law)
        out.append(np.max(np.arctan(np.abs(sigma * ds - e) / (s0 + s))))
    return tuple(out)


@pytest.mark.parametrize("limits,binding", [((30, 70), "rise"), ((45, 20), "return")])
@pytest.mark.parametrize("rotation", [1, -1])
def test_min_base_radius_translating_given_offset_is_tight(limits, binding, rotation):
    """With the offset given (12 mm on the favourable side): at the returned r0 the binding
    limit is met with equality (1e-6 rad) and the other respected; at 0.99·r0 it is exceeded."""
    lim_rise, lim_ret = D(limits[0]), D(limits[1])
    e = favourable_offset_sign(rotation) * E73
    follower = TranslatingFollower("roller", e, RR73)
    r0, e_used = min_base_radius_translating(programme_73(), follower, lim_rise, lim_ret,
                                             offset=e, rotation=rotation)
    assert e_used == e
    a_rise, a_ret = max_alpha_translating(r0, e, rotation, "constant_velocity")
    if binding == "rise":
        assert a_rise == pytest.approx(lim_rise, abs=1e-6)
        assert a_ret <= lim_ret + 1e-9
    else:
        assert a_ret == pytest.approx(lim_ret, abs=1e-6)
        assert a_rise <= lim_rise + 1e-9
    a_rise, a_ret = max_alpha_translating(0.99 * r0, e, rotation, "constant_velocity")
    assert a_rise > lim_rise or a_ret > lim_ret
    # and the designed cam, analysed by the module itself on the closed binding segment, agrees
    start, span = (0.0, RISE73) if binding == "rise" else (RET73_START, RET73)
    d = start + np.linspace(0.0, 1.0 - 1e-15, 20001) * span
    c = design_cam(programme_73(), follower, r0, rotation, delta=d)
    assert c.pressure_angle.max() == pytest.approx(lim_rise if binding == "rise" else lim_ret, abs=1e-6)


@pytest.mark.parametrize("rotation", [1, -1])
def test_min_base_radius_translating_auto_offset(rotation):
    """offset=None: for a rise-limited case ([α] = 30° rise, 70° return) the offset found lies on
    the favourable side (sign +1 ccw, −1 cw: there the pole and the axis are on the same side
    during the rise), it gives an r0 no larger than the centred follower's, and nearby offsets
    are no better (a minimum)."""
    prog = programme_73()
    follower = TranslatingFollower("roller", 0.0, RR73)
    lim = (D(30), D(70))
    r0, e = min_base_radius_translating(prog, follower, *lim, offset=None, rotation=rotation)
    r0_centred, _ = min_base_radius_translating(prog, follower, *lim, offset=0.0, rotation=rotation)
    assert np.sign(e) == favourable_offset_sign(rotation) == rotation
    assert r0 <= r0_centred
    assert r0 < 0.9 * r0_centred              # the offset really helps here
    a_rise, a_ret = max_alpha_translating(r0, e, rotation, "constant_velocity")
    assert a_rise == pytest.approx(lim[0], abs=1e-6) or a_ret == pytest.approx(lim[1], abs=1e-6)
    for de in (-1e-4, 1e-4):
        r_near, _ = min_base_radius_translating(prog, follower, *lim, offset=e + de, rotation=rotation)
        assert r_near >= r0 * (1 - 1e-9)


def test_min_base_radius_flat_follower_keeps_the_profile_convex():
    """Flat face: ρ = r0 + s + d²s/dδ² ≥ ρmin; at the returned r0 the smallest ρ of the
    synthesised profile equals ρmin."""
    prog = programme_73("cycloidal")
    rho_min = 3 * MM
    r0, _ = min_base_radius_translating(prog, TranslatingFollower("flat"), D(30), D(70),
                                        offset=0.0, min_curvature=rho_min)
    d = np.arange(7200) * (2 * PI / 7200)
    s, _, d2s = motion_73(d, "cycloidal")
    # issue 21: r0 comes from the exact minimum, so the grid's minimum lies at or above
    # ρmin; the exact minimum of the hand closed form (bounded search between the grid
    # neighbours of the grid's smallest value) equals it
    from scipy.optimize import minimize_scalar

    k = int(np.argmin(r0 + s + d2s))
    h = 2 * PI / 7200

    def rho(x):
        s1, _, d2s1 = motion_73(np.array([x]), "cycloidal")
        return float(r0 + s1[0] + d2s1[0])

    best = minimize_scalar(rho, bounds=(d[k] - h, d[k] + h), method="bounded",
                           options={"xatol": 1e-12})
    assert best.fun == pytest.approx(rho_min, abs=1e-12)
    assert np.min(r0 + s + d2s) >= rho_min - 1e-12
    assert np.min(r0 + s + d2s) == pytest.approx(rho_min, abs=1e-8)
    c = design_cam(prog, TranslatingFollower("flat"), r0, 1, points=7200)
    assert c.rho_actual.min() == pytest.approx(rho_min, abs=1e-8)


@pytest.mark.parametrize("limits", [(30, 70), (60, 40)])
def test_min_base_radius_oscillating_is_tight(limits):
    """Shaper cam (cw, a = 136, L = 120): at the returned r0 the max pole-method pressure angle
    on the rise or on the return equals its limit; at 0.99·r0 a limit is exceeded."""
    prog = shaper_programme()
    follower = OscillatingFollower("roller", A0, L0, RR0, "same")
    lim_rise, lim_ret = D(limits[0]), D(limits[1])
    r0 = min_base_radius_oscillating(prog, follower, lim_rise, lim_ret, rotation=-1)
    assert abs(A0 - L0) < r0 < A0 + L0
    d = np.arange(3600) * (2 * PI / 3600)
    phi, dphi = parabolic_phi(d)
    rise, ret = d < F0, (d >= F0 + F01) & (d < F0 + F01 + F02)

    def maxima(r):
        phi0 = math.acos((A0**2 + L0**2 - r * r) / (2 * A0 * L0))
        B = A0 - L0 * np.exp(-1j * (phi + phi0))
        alpha = pole_pressure_angle(B, A0, dphi, -1, "same")
        return alpha[rise].max(), alpha[ret].max()

    a_rise, a_ret = maxima(r0)
    assert a_rise <= lim_rise + 1e-9 and a_ret <= lim_ret + 1e-9
    assert a_rise == pytest.approx(lim_rise, abs=1e-6) or a_ret == pytest.approx(lim_ret, abs=1e-6)
    a_rise, a_ret = maxima(0.99 * r0)
    assert a_rise > lim_rise or a_ret > lim_ret


def uniform_return_programme() -> Programme:
    """Oscillating: cycloidal rise 90° to 20°, dwell 30°, uniform return 100°, dwell 140°."""
    return Programme([Segment("rise", D(90), "cycloidal", D(20)), Segment("dwell", D(30)),
                      Segment("return", D(100), "constant_velocity"), Segment("dwell", D(140))])


def test_min_base_radius_oscillating_respects_the_limit_at_the_end_of_a_uniform_return():
    """Uniform return limited to 23° (rise 75°, not binding): at the returned r0 the pole-method
    pressure angle over the closed return u ∈ [0, 1) must not exceed 23° (+1e-6 rad). The
    largest α is at the very end of the return, where the follower is lowest but still moving
    at −φ_ret/Φ'."""
    prog = uniform_return_programme()
    follower = OscillatingFollower("roller", A0, L0, RR0, "same")
    lim_rise, lim_ret = D(75), D(23)
    r0 = min_base_radius_oscillating(prog, follower, lim_rise, lim_ret, rotation=-1)
    u = np.linspace(0.0, 1.0 - 1e-15, 20001)
    phi, dphi = D(20) * (1 - u), np.full_like(u, -D(20) / D(100))    # uniform return by hand
    phi0 = math.acos((A0**2 + L0**2 - r0 * r0) / (2 * A0 * L0))
    B = A0 - L0 * np.exp(-1j * (phi + phi0))
    alpha = pole_pressure_angle(B, A0, dphi, -1, "same")
    assert alpha.argmax() == len(u) - 1                 # worst at the end of the return
    assert alpha.max() <= lim_ret + 1e-6


# ---------------------------------------------------------------------- 8. eccentric disc, exercise 7-1


R71, EPS71 = 40 * MM, 20 * MM

#: Textbook list of 7-1(a): distance from the cam centre to the knife edge [mm] at
#: δ = 18°, 36°, …, 180° from the lowest position (as printed; 29.0071 is a misprint of 29.0077).
TEXTBOOK_71A = [20.4985, 22.0532, 24.8257, 29.0071, 34.6410, 41.3684, 48.3371, 54.4139,
                58.5408, 60.0000]


def disc_closed_form(delta, R, eps, x_f, rr, sigma):
    """Disc centre C = ε(σ sin δ, −cos δ) (straight below the axis at δ = 0, turning with the
    cam); the knife edge / roller centre on the line x = x_f is at
    y = C_y + √((R + r_r)² − (x_f − C_x)²); sin α = |x_f − C_x| / (R + r_r)."""
    cx, cy = sigma * eps * np.sin(delta), -eps * np.cos(delta)
    y = cy + np.sqrt((R + rr) ** 2 - (x_f - cx) ** 2)
    alpha = np.arcsin(np.abs(x_f - cx) / (R + rr))
    return y, alpha


@pytest.mark.parametrize("rotation", [1, -1])
def test_71a_centred_knife_edge_textbook_list(rotation):
    """7-1(a): the printed list is the distance from the cam centre to the tip at 18° steps.
    Its header says k·360/19°, but that cannot be: the 10th value, 60.0000 = R + ε, is the
    maximum, reached only at exactly 180° (the disc centre straight above the axis), so ten
    steps span 180° → 18° each; there are 19 values from 18° to 342° (20 intervals of 18°
    in a turn, the 20th point, 360°, being the lowest position 20 = R − ε again). At the
    header's 10·360/19 = 189.47° the distance would be below 60. For a centred follower the
    tip's height y is that distance."""
    d = np.radians(18.0 * np.arange(1, 20))
    m = eccentric_disc(d, R71, EPS71, TranslatingFollower("knife"), rotation)
    expected = np.array(TEXTBOOK_71A + TEXTBOOK_71A[-2::-1])  # symmetric back to 342°
    # The printed 29.0071 at 72° (and 288°) is a misprint: by hand,
    # y = −20 cos 72° + √(40² − (20 sin 72°)²) = −6.18034 + 35.18802 = 29.00768 → 29.0077.
    by_hand_72 = -20 * math.cos(D(72)) + math.sqrt(40**2 - (20 * math.sin(D(72))) ** 2)
    assert round(by_hand_72, 4) == 29.0077
    misprint = np.isin(np.arange(19), [3, 15])
    np.testing.assert_allclose(m.y[~misprint] / MM, expected[~misprint], rtol=0, atol=6e-5)
    np.testing.assert_allclose(m.y[misprint] / MM, by_hand_72, rtol=1e-13)
    assert np.all(np.abs(m.y[misprint] / MM - 29.0071) < 1e-3)  # only the last digit is off
    y_ref, _ = disc_closed_form(d, R71, EPS71, 0.0, 0.0, rotation)
    np.testing.assert_allclose(m.y, y_ref, rtol=1e-14)
    assert eccentric_disc(0.0, R71, EPS71, TranslatingFollower("knife")).y == pytest.approx(20 * MM)
    y_header = eccentric_disc(np.radians(10 * 360 / 19), R71, EPS71, TranslatingFollower("knife")).y
    assert y_header / MM < 59.9
    assert m.stroke == pytest.approx(2 * EPS71, rel=1e-14)


def test_71b_offset_knife_edge_stroke():
    """7-1(b), e = 15 mm: the lowest and highest positions are where dy/dδ = 0, i.e. where the
    pole (x = σ·dy/dδ) is the cam centre: the common normal — the line from the disc centre C
    to the tip — passes through the axis, so the tip is R ∓ ε from it:
    stroke = √((R + ε)² − e²) − √((R − ε)² − e²) = √3375 − √175 = 44.866 mm.
    The seed's ADAMS value 40.7007 + 2.4972 = 43.1979 mm is 1.67 mm short, so whatever its
    simulation measured, it was not the distance between these two extreme positions."""
    e = 15 * MM
    stroke = math.sqrt(60**2 - 15**2) - math.sqrt(20**2 - 15**2)
    assert stroke == pytest.approx(44.866, abs=5e-4)
    assert abs(stroke - 43.1979) > 1.5
    m = eccentric_disc(np.arange(36000) * (2 * PI / 36000), R71, EPS71, TranslatingFollower("knife", e))
    assert m.stroke / MM == pytest.approx(stroke, rel=1e-13)
    assert (m.y.max() - m.y.min()) / MM == pytest.approx(stroke, abs=1e-6)
    assert m.y_min == pytest.approx(m.y.min(), abs=1e-9)
    assert m.y_max == pytest.approx(m.y.max(), abs=1e-9)
    np.testing.assert_allclose(m.s, m.y - m.y_min, rtol=0, atol=1e-16)


def test_71c_centred_roller_stroke():
    """7-1(c), centred roller r_r = 20 mm: the roller centre runs on a circle of R + r_r about
    C, y = C_y + √((R + r_r)² − C_x²), from 40 at δ = 0 to 80 at 180°: stroke 2ε = 40 mm."""
    m = eccentric_disc(np.arange(3600) * (2 * PI / 3600), R71, EPS71,
                       TranslatingFollower("roller", 0.0, 20 * MM))
    assert m.stroke == pytest.approx(40 * MM, rel=1e-14)
    assert m.y[0] == pytest.approx(40 * MM, rel=1e-14) and m.y[1800] == pytest.approx(80 * MM, rel=1e-14)


@pytest.mark.parametrize("rotation", [1, -1])
@pytest.mark.parametrize("e_mm,rr_mm,kind", [(0, 0, "knife"), (15, 0, "knife"), (-15, 0, "knife"),
                                              (0, 20, "roller"), (10, 20, "roller")])
def test_71_pressure_angle_closed_form_and_pole_method(rotation, e_mm, rr_mm, kind):
    """α from sin α = |x_f − C_x| / (R + r_r) and, independently, by the pole method: the pole
    is at x = σ·dy/dδ on the x-axis (dy/dδ by central differences of the closed-form y), the
    normal runs from it to the follower point (x_f, y), α is its angle to the vertical. The
    module's y, dy/dδ (vs central differences of its own y) agree as well."""
    e, rr = e_mm * MM, rr_mm * MM
    follower = TranslatingFollower(kind, e, rr)
    d = half_step_grid(720)
    h = 1e-6
    m = eccentric_disc(d, R71, EPS71, follower, rotation)
    y, alpha = disc_closed_form(d, R71, EPS71, e, rr, rotation)
    dy_fd = (disc_closed_form(d + h, R71, EPS71, e, rr, rotation)[0]
             - disc_closed_form(d - h, R71, EPS71, e, rr, rotation)[0]) / (2 * h)
    alpha_pole = np.arctan(np.abs(e - rotation * dy_fd) / y)
    np.testing.assert_allclose(m.y, y, rtol=1e-14)
    np.testing.assert_allclose(m.pressure_angle, alpha, rtol=0, atol=1e-12)
    np.testing.assert_allclose(m.pressure_angle, alpha_pole, rtol=0, atol=1e-8)
    dy_module_fd = (eccentric_disc(d + h, R71, EPS71, follower, rotation).y
                    - eccentric_disc(d - h, R71, EPS71, follower, rotation).y) / (2 * h)
    np.testing.assert_allclose(m.dy, dy_module_fd, rtol=0, atol=1e-9)
    np.testing.assert_allclose(m.dy, dy_fd, rtol=0, atol=1e-9)


# ---------------------------------------------------------------------- 9. errors


def test_oscillating_roller_that_cannot_reach_the_base_circle():
    """r0 must lie between |a − L| and a + L (triangle O-A-B); outside, no φ0 exists."""
    follower = OscillatingFollower("roller", A0, L0, RR0, "same")
    for r0 in (10 * MM, 300 * MM):      # |a − L| = 16 mm, a + L = 256 mm
        with pytest.raises(CamDesignError, match=r"base circle.*r0"):
            design_cam(shaper_programme(), follower, r0, -1, points=36)


def test_offset_not_smaller_than_base_radius():
    for e in (50 * MM, -60 * MM):
        with pytest.raises(CamDesignError, match=r"offset.*base radius"):
            design_cam(programme_73(), TranslatingFollower("roller", e, RR73), R0_73, 1, points=36)


def test_non_positive_base_radius():
    with pytest.raises(CamDesignError, match="base radius"):
        design_cam(programme_73(), TranslatingFollower("knife"), 0.0, 1, points=36)


def test_follower_leaving_the_disc():
    """|e| + ε ≥ R + r_r: at some angle the follower's line misses the disc."""
    with pytest.raises(CamDesignError, match=r"leaves the disc.*offset"):
        eccentric_disc(np.zeros(3), R71, EPS71, TranslatingFollower("knife", 20 * MM))
    with pytest.raises(CamDesignError, match=r"leaves the disc"):
        eccentric_disc(np.zeros(3), R71, EPS71, TranslatingFollower("roller", -45 * MM, 5 * MM))
    # just inside is fine
    eccentric_disc(np.zeros(3), R71, EPS71, TranslatingFollower("knife", 19.9 * MM))
