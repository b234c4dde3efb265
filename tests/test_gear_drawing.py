"""Generated tooth outlines and the meshing layout (啮合图) against independent geometry:
the involute as a rolled-off string, the thickness relation on the pitch and tip circles,
a brute-force sweep of the basic rack (it generates the outline and never cuts into it),
the line of action as the common tangent of the base circles, B1B2 / pb against the contact
ratio from the tip pressure angles, and the drawn teeth touching at P without overlapping
anywhere in the mesh cycle.
"""
from __future__ import annotations

import numpy as np
import pytest
from matplotlib.path import Path

from mechdesign.core.gears import (form_radius, gear_outline, inv, mesh_layout, spur_pair,
                                   tooth_half_angle, tooth_outline)

SHAPER = spur_pair(12, 18, 60)                      # m = 12, z1 = 18, z2 = 60: ε = 1.658
SHIFTED = spur_pair(5, 12, 40, x1=0.4)              # 12-tooth pinion shifted clear of undercut
UNDERCUT = spur_pair(5, 12, 40)                     # standard 12-tooth pinion: undercut
GEARS = [(SHAPER, SHAPER.g1), (SHAPER, SHAPER.g2), (SHIFTED, SHIFTED.g1), (SHIFTED, SHIFTED.g2),
         (UNDERCUT, UNDERCUT.g1), (spur_pair(12, 18, 60, x1=0.5, x2=0.2), spur_pair(12, 18, 60, x1=0.5, x2=0.2).g1)]


def seg_dist(points, poly):
    """Distance of each point to the polyline ``poly`` (complex arrays)."""
    a, d = poly[:-1], np.diff(poly)
    t = np.clip(((points[:, None] - a) * np.conj(d)).real / np.abs(d) ** 2, 0, 1)
    return np.min(np.abs(points[:, None] - (a + t * d)), axis=1)


def inside(points, poly):
    return Path(np.c_[poly.real, poly.imag]).contains_points(np.c_[points.real, points.imag])


def upper_flank(pair, gear, points=60):
    """The counter-clockwise side of tooth 0, from the root up to the tip."""
    tooth = tooth_outline(gear, pair.m, pair.alpha, pair.c_star, points)
    half = tooth[len(tooth) // 2:][::-1]
    return half[(np.abs(half) > gear.df / 2 * (1 + 1e-12)) & (np.abs(half) < gear.da / 2 * (1 - 1e-12))]


@pytest.mark.parametrize("pair, gear", GEARS)
def test_flank_above_the_form_circle_is_the_involute(pair, gear):
    """A string unwound from the base circle: X = rb e^{i(θ0 − t)} (1 + i t), t = tan α_ρ,
    with the base point at θ0 = s/d + inv α (half the base thickness)."""
    rb = gear.db / 2
    flank = upper_flank(pair, gear)
    flank = flank[np.abs(flank) > form_radius(gear, pair.m, pair.alpha, pair.c_star) * (1 + 1e-9)]
    assert len(flank) > 30
    t = np.sqrt((np.abs(flank) / rb) ** 2 - 1)
    theta0 = gear.s / gear.d + inv(pair.alpha)
    string = rb * np.exp(1j * (theta0 - t)) * (1 + 1j * t)
    assert np.max(np.abs(flank - string)) < 1e-9 * pair.m


@pytest.mark.parametrize("pair, gear", GEARS)
def test_thickness_on_the_pitch_and_tip_circles(pair, gear):
    """The arc thickness read off the outline: s on the reference circle, sa on the tip."""
    flank = upper_flank(pair, gear, 200)
    r, ra = gear.d / 2, gear.da / 2
    angle_at_r = np.interp(r, np.abs(flank), np.angle(flank))
    assert 2 * r * angle_at_r == pytest.approx(gear.s, abs=2e-5 * pair.m)
    tooth = tooth_outline(gear, pair.m, pair.alpha, pair.c_star)
    tip = tooth[np.isclose(np.abs(tooth), ra, rtol=1e-12)]
    assert 2 * ra * np.max(np.angle(tip)) == pytest.approx(gear.sa, rel=1e-9)
    assert np.min(np.abs(tooth)) == pytest.approx(gear.df / 2, rel=1e-12)
    assert np.max(np.abs(tooth)) == pytest.approx(ra, rel=1e-12)


def test_no_backlash_on_the_working_pitch_circles_from_the_outlines():
    pair = spur_pair(12, 18, 60, x1=0.5, x2=0.2)
    lay = mesh_layout(pair)
    s_w = [2 * rw * np.interp(rw, np.abs(f), np.angle(f))
           for rw, f in ((lay.r1w, upper_flank(pair, pair.g1, 300)), (lay.r2w, upper_flank(pair, pair.g2, 300)))]
    assert sum(s_w) == pytest.approx(2 * np.pi * lay.r1w / 18, abs=1e-4 * pair.m)


@pytest.mark.parametrize("pair, gear", GEARS)
def test_the_basic_rack_generates_the_outline(pair, gear):
    """Sweep the rack (flank at α, tip line hf + x m below the reference line, tip rounded
    with ρf = c* m/(1 − sin α)) along the pitch circle: it never cuts into the outline and
    it touches every point of the fillet and flank."""
    m, a, c = pair.m, pair.alpha, pair.c_star
    r, rho_f = gear.d / 2, c * m / (1 - np.sin(a))
    h_tip, h_t = -gear.hf, -gear.hf + c * m                 # heights above the rolling line
    u_of = lambda h: -(np.pi * m / 4 + (h - gear.x * m) * np.tan(a))  # noqa: E731  left flank
    centre = u_of(h_t) + rho_f * np.cos(a) + 1j * (h_tip + rho_f)
    arc = centre + rho_f * np.exp(1j * np.linspace(np.pi + a, 1.5 * np.pi, 80))
    h_top = gear.da / 2 - r + 0.5 * m
    flank_h = np.linspace(h_t, h_top, 150)
    rack = np.concatenate([(u_of(flank_h) + 1j * flank_h)[::-1], arc, np.linspace(centre.real, 0, 10) + 1j * h_tip])
    phi = np.linspace(-1, 1, 3000) * 1.2 * np.sqrt((gear.da / 2) ** 2 - (gear.db / 2) ** 2) / r
    cut = (np.exp(1j * (np.pi / gear.z - phi))[:, None]
           * (r + rack.imag + 1j * (rack.real + r * phi[:, None]))).ravel()
    tooth = tooth_outline(gear, m, a, c, 120)
    cell = np.append(np.append(tooth, 0j), tooth[0])
    near = cut[np.abs(cut) < gear.da / 2 + 1e-9]
    bad = near[inside(near, cell)]
    assert len(bad) == 0 or np.max(seg_dist(bad, tooth)) < 1e-4 * m
    flank = upper_flank(pair, gear, 30)
    d = np.array([np.min(np.abs(near - p)) for p in flank])
    assert np.max(d) < 0.01 * m


def test_undercut_starts_below_x_min():
    """With the standard rounded rack the fillet meets the involute tangentially at the form
    circle (≥ rb) for x ≥ x_min; below x_min it cuts into the involute near the base circle."""
    for z in (12, 15):
        x_min = spur_pair(5, z, 40).x_min1
        for x, undercut in ((x_min + 0.02, False), (x_min - 0.15, True)):
            pair = spur_pair(5, z, 40, x1=x)
            g = pair.g1
            rf_ = form_radius(g, 5, pair.alpha, 0.25)
            rb = g.db / 2
            psi_b = g.s / g.d + inv(pair.alpha)                # the involute's half angle at rb
            flank = upper_flank(pair, g, 400)
            j = np.argmin(np.abs(np.abs(flank) - rf_))              # the join fillet → involute
            turn = np.angle((flank[j + 1] - flank[j]) / (flank[j] - flank[j - 1]))
            if undercut:
                assert tooth_half_angle(g, 5, pair.alpha, 0.25, rb * (1 + 1e-6)) < psi_b - 1e-5
                assert rf_ > rb and abs(turn) > 0.05                # the fillet cuts the involute
            else:
                lead = g.d / 2 * np.sin(pair.alpha) - (1 - x) * 5 / np.sin(pair.alpha)
                assert rf_ == pytest.approx(np.hypot(rb, lead), rel=1e-9)
                assert abs(turn) < 0.01                             # tangent
    assert form_radius(SHAPER.g1, 12, SHAPER.alpha, 0.25) > SHAPER.g1.db / 2   # z = 18 > z_min


def test_gear_outline_is_closed_counter_clockwise_and_periodic():
    g = SHAPER.g1
    ring = gear_outline(g, 12, SHAPER.alpha, 0.25, rotation=0.3, centre=5 + 7j)
    assert ring[0] == ring[-1]
    z = ring[:-1] - (5 + 7j)
    area = 0.5 * np.sum((np.conj(z) * np.roll(z, -1)).imag)
    assert 0 < area < np.pi * (g.da / 2) ** 2
    per_tooth = len(z) // g.z
    assert np.allclose(np.roll(z, per_tooth) * np.exp(2j * np.pi / g.z), z, atol=1e-9)
    tooth0 = tooth_outline(g, 12, SHAPER.alpha, 0.25)[:-1] * np.exp(0.3j)
    assert np.allclose(z[:per_tooth], tooth0)


@pytest.mark.parametrize("pair", [SHAPER, SHIFTED, spur_pair(12, 18, 60, x1=0.5, x2=0.2)])
def test_line_of_action_is_the_common_tangent_of_the_base_circles(pair):
    lay = mesh_layout(pair)
    rb1, rb2, aw = pair.g1.db / 2, pair.g2.db / 2, pair.alpha_work
    assert lay.o1 == 0 and lay.o2 == pytest.approx(1j * pair.a_work)
    assert lay.p == pytest.approx(1j * lay.r1w) and lay.r1w + lay.r2w == pytest.approx(pair.a_work)
    assert abs(lay.n1 - lay.o1) == pytest.approx(rb1) and abs(lay.n2 - lay.o2) == pytest.approx(rb2)
    u = (lay.n2 - lay.n1) / abs(lay.n2 - lay.n1)
    assert u == pytest.approx(lay.direction)
    for o, n in ((lay.o1, lay.n1), (lay.o2, lay.n2)):
        assert ((n - o) * np.conj(u)).real == pytest.approx(0, abs=1e-9 * pair.m)  # ⊥: tangent
    dist = lambda q: abs(((q - lay.n1) * np.conj(u)).imag)  # noqa: E731  distance to the line
    assert dist(lay.o1) == pytest.approx(rb1) and dist(lay.o2) == pytest.approx(rb2)
    assert dist(lay.p) == pytest.approx(0, abs=1e-9 * pair.m)
    assert np.angle(-u) == pytest.approx(-aw)            # α′ to the common tangent (the x axis)
    assert lay.n1.real > 0 > lay.n2.real                # gear 1 driving counter-clockwise


@pytest.mark.parametrize("pair", [SHAPER, SHIFTED, spur_pair(12, 18, 60, x1=0.5, x2=0.2), spur_pair(12, 18, 60, x1=0.3, x2=-0.3)])
def test_actual_contact_b1b2_and_the_contact_ratio(pair):
    lay = mesh_layout(pair)
    u = lay.direction
    assert abs(lay.b1) == pytest.approx(pair.g1.da / 2) and abs(lay.b2 - lay.o2) == pytest.approx(pair.g2.da / 2)
    along = lambda q: ((q - lay.n1) * np.conj(u)).real  # noqa: E731
    for q in (lay.b1, lay.b2):
        assert ((q - lay.n1) * np.conj(u)).imag == pytest.approx(0, abs=1e-9 * pair.m)
    assert 0 < along(lay.b2) < along(lay.p) < along(lay.b1) < along(lay.n2)
    assert not lay.interference
    # ε two ways: |B1B2| / pb from the drawing, the tip pressure angles in spur_pair
    eps = (pair.g1.z * (np.tan(pair.g1.alpha_a) - np.tan(pair.alpha_work))
           + pair.g2.z * (np.tan(pair.g2.alpha_a) - np.tan(pair.alpha_work))) / (2 * np.pi)
    assert abs(lay.b1 - lay.b2) / pair.pb == pytest.approx(eps, rel=1e-12)
    assert lay.contact_ratio == pytest.approx(pair.contact_ratio, rel=1e-12)
    assert lay.action_length == pytest.approx(pair.action_length, rel=1e-12)
    assert mesh_layout(SHAPER).contact_ratio == pytest.approx(1.658, abs=1e-3)


def test_interference_flag():
    """The standard 12-tooth pinion with a 40-tooth wheel: B2 lies beyond N1."""
    assert mesh_layout(UNDERCUT).interference
    assert not mesh_layout(SHAPER).interference


def _penetration(lay, m):
    """How far the teeth of either gear reach into the other (0 if they only touch), and
    the nearest distance between them, near the pitch point."""
    c1, c2 = lay.outlines(60)
    near1, near2 = c1[np.abs(c1 - lay.p) < 4 * m], c2[np.abs(c2 - lay.p) < 4 * m]
    seg1, seg2 = c1[np.abs(c1 - lay.p) < 6 * m], c2[np.abs(c2 - lay.p) < 6 * m]
    depth = [np.max(seg_dist(q[inside(q, poly)], s), initial=0.0)
             for q, poly, s in ((near2, c1, seg1), (near1, c2, seg2))]
    return max(depth), np.min(seg_dist(near2, seg1)), c1, c2


@pytest.mark.parametrize("pair", [SHAPER, SHIFTED, UNDERCUT, spur_pair(12, 18, 60, x1=0.5, x2=0.2)])
def test_drawn_teeth_touch_at_p_and_never_overlap(pair):
    m = pair.m
    lay = mesh_layout(pair)
    depth, gap, c1, c2 = _penetration(lay, m)
    assert depth < 1e-6 * m and gap < 2e-3 * m
    p = np.array([lay.p])
    assert seg_dist(p, c1)[0] < 1e-3 * m and seg_dist(p, c2)[0] < 1e-3 * m
    # the flanks are tangent at P: both outlines run across the line of action there
    for c in (c1, c2):
        k = np.argmin(np.abs(c - lay.p))
        d = c[k + 1] - c[k - 1]
        assert abs(((d / abs(d)) * np.conj(lay.direction)).real) < 0.02
    # through one angular pitch of gear 1 the teeth still never overlap
    for phase in np.linspace(0, 2 * np.pi / pair.g1.z, 9)[1:]:
        assert _penetration(mesh_layout(pair, phase), m)[0] < 1e-6 * m


def test_overlap_check_is_sensitive():
    """Turning gear 2 by 0.2° into gear 1 is caught."""
    from dataclasses import replace

    lay = mesh_layout(SHAPER)
    assert _penetration(replace(lay, rotation2=lay.rotation2 + np.radians(0.2)), 12)[0] > 0.05


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_meshing_drawing_writes_png(tmp_path, lang):
    from mechdesign.stages.gear import gear_drawing
    from mechdesign.render.gear_figures import meshing_drawing

    # the gear stage's drawing data of SHAPER and SHIFTED (given in metres; drawn in mm)
    for i, pair in enumerate((spur_pair(0.012, 18, 60), spur_pair(0.005, 12, 40, x1=0.4))):
        out = tmp_path / f"mesh_{lang}_{i}.png"
        meshing_drawing(out, lang, gear_drawing(pair))
        assert out.stat().st_size > 20_000
        assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
