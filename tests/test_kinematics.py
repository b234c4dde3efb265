"""Kinematics of the Assur groups (孙桓《机械原理》 杆组法) against independent references.

References used here, never numbers copied from the program's output:

* closed forms derived by hand: the offset slider-crank
  x = r cosφ + sqrt(l² − (r sinφ − e)²) and its analytic first and second derivatives;
  a four-bar in a Pythagorean (3-4-5) assembly whose velocities and accelerations follow
  from the relative-motion equations by hand; the guide bar at its vertical positions,
  ω4 = r·ω/(L ± r); the guide bar with the crank horizontal, including the Coriolis
  term 2·ω4·ṡ;
* central finite differences of positions (velocities) and of the analytic velocities
  (accelerations), for the crank, RRR (both branches, moving outer points), RRP (both
  branches, inclined guide), RPR (with and without offset, branch ±1, moving pivot) and
  point_on_link;
* loop-closure residuals at round-off level (1e-12 m on metre-sized links);
* AssemblyError when links are too short, at the first failing angle found by the law
  of cosines.

All groups are driven by a crank at constant ω, so d/dt = ω·d/dφ and a central difference
in φ with step h gives the time derivative. Step rationale (used everywhere below):
h = 1e-5 rad makes the truncation error h²/6·|f'''| ≈ 2e-11·|f'''| and the round-off
error ε·|f|/h ≈ 2e-11·|f| (f of order 1 m or 1 rad); the tolerance FD_RTOL = 1e-7 of the
largest magnitude of the compared quantity leaves room for the higher derivatives of the
chosen (non-toggle) geometries: the worst case seen is 3e-10, a margin of 300.
"""
from __future__ import annotations

import numpy as np
import pytest

from mechdesign.core import kinematics as kin
from mechdesign.core.kinematics import AngleMotion, PointMotion
from mechdesign.core.mechanism import RPR, RRP, RRR, AssemblyError, Crank, LinkPoint, Mechanism

H_FD = 1e-5      # [rad] central-difference step, see module docstring
FD_RTOL = 1e-7   # relative to the largest magnitude compared, see module docstring
CLOSURE_ATOL = 1e-12  # [m] round-off on lengths of order 1 m (ε·|x| ≈ 2e-16·a few, ×1000 margin)

PHI = np.linspace(0.0, 2 * np.pi, 73, endpoint=False) + 0.01  # avoid landing on symmetric angles


def fixed(xy: complex, n: int) -> PointMotion:
    return kin.fixed_point(xy, n)


def fd(f, phi, omega, h=H_FD):
    """ω·(f(φ+h) − f(φ−h))/(2h): time derivative of f at constant crank speed."""
    return omega * (f(phi + h) - f(phi - h)) / (2 * h)


def fd_angle(f, phi, omega, h=H_FD):
    """Same for an angle, unwrapping the difference into (−π, π]."""
    return omega * np.angle(np.exp(1j * (f(phi + h) - f(phi - h)))) / (2 * h)


def assert_fd(actual, reference, what):
    scale = np.max(np.abs(reference))
    err = np.max(np.abs(actual - reference))
    assert err <= FD_RTOL * scale, f"{what}: max error {err:.3e} vs scale {scale:.3e}"


# ---------------------------------------------------------------------------------- helpers


def test_cross_is_z_component_of_planar_cross_product():
    # e_x × e_y = +e_z; (3, 4) × (−4, 3) = 3·3 − 4·(−4) = 25 (hand computed)
    assert kin.cross(np.array([1 + 0j]), np.array([1j]))[0] == 1.0
    assert kin.cross(np.array([3 + 4j]), np.array([-4 + 3j]))[0] == pytest.approx(25.0, abs=0)


def test_solve2_recovers_real_unknowns():
    rng = np.random.default_rng(1)
    a = rng.normal(size=50) + 1j * rng.normal(size=50)
    b = rng.normal(size=50) + 1j * rng.normal(size=50)
    x_true, y_true = rng.normal(size=50), rng.normal(size=50)
    keep = np.abs(kin.cross(a, b)) > 0.1 * np.abs(a) * np.abs(b)  # well-conditioned systems only
    x, y = kin.solve2(a[keep], b[keep], a[keep] * x_true[keep] + b[keep] * y_true[keep])
    # Cramer's rule on a system with condition number ≤ ~20: error a few ε·20 → 1e-13.
    np.testing.assert_allclose(x, x_true[keep], rtol=0, atol=1e-13)
    np.testing.assert_allclose(y, y_true[keep], rtol=0, atol=1e-13)


def test_fixed_point_has_no_motion():
    p = kin.fixed_point(0.3 - 0.2j, 4)
    assert np.all(p.pos == 0.3 - 0.2j) and np.all(p.vel == 0) and np.all(p.acc == 0)


# ---------------------------------------------------------------------------------- crank


@pytest.mark.parametrize("omega", [7.0, -3.5])
def test_crank_tip_closed_form(omega):
    r, o = 0.12, 0.4 + 0.1j
    link, tip = kin.crank(fixed(o, len(PHI)), r, PHI, omega)
    e = np.exp(1j * PHI)
    # Uniform circular motion: v = iωr·e^{iφ}, a = −ω²r·e^{iφ}; round-off only (1e-15·scale).
    np.testing.assert_allclose(tip.pos, o + r * e, rtol=0, atol=1e-15)
    np.testing.assert_allclose(tip.vel, 1j * omega * r * e, rtol=0, atol=1e-14)
    np.testing.assert_allclose(tip.acc, -omega**2 * r * e, rtol=0, atol=1e-13)
    assert np.all(link.omega == omega) and np.all(link.alpha == 0)


def test_crank_tip_finite_differences():
    omega = -4.0

    def solve(phi):
        return kin.crank(fixed(0j, len(phi)), 0.2, phi, omega)[1]

    tip = solve(PHI)
    assert_fd(tip.vel, fd(lambda f: solve(f).pos, PHI, omega), "crank velocity")
    assert_fd(tip.acc, fd(lambda f: solve(f).vel, PHI, omega), "crank acceleration")


# ---------------------------------------------------------------------------------- RRP


@pytest.mark.parametrize("e", [0.0, 0.03, -0.05])
def test_offset_slider_crank_matches_closed_form(e):
    """x = r cosφ + sqrt(l² − (r sinφ − e)²); x' and x'' differentiated by hand."""
    r, l, omega = 0.1, 0.35, 6.0
    n = len(PHI)
    _, tip = kin.crank(fixed(0j, n), r, PHI, omega)
    rod, slide, c = kin.rrp(tip, l, 1j * e, 0.0, branch=+1)

    g, g1, g2 = r * np.sin(PHI) - e, r * np.cos(PHI), -r * np.sin(PHI)
    q = np.sqrt(l**2 - g**2)
    x = r * np.cos(PHI) + q
    x1 = -r * np.sin(PHI) - g * g1 / q
    x2 = -r * np.cos(PHI) - (g1**2 + g * g2) / q - g**2 * g1**2 / q**3
    beta = np.arctan2(e - r * np.sin(PHI), q)  # rod direction B→C

    # Same closed form evaluated two ways: only round-off separates them (1e-15 m on 0.4 m).
    np.testing.assert_allclose(c.pos, x + 1j * e, rtol=0, atol=1e-14)
    np.testing.assert_allclose(slide.s, x, rtol=0, atol=1e-14)
    np.testing.assert_allclose(c.vel, omega * x1, rtol=0, atol=1e-13)
    np.testing.assert_allclose(slide.ds, omega * x1, rtol=0, atol=1e-13)
    np.testing.assert_allclose(c.acc, omega**2 * x2, rtol=0, atol=1e-12)
    np.testing.assert_allclose(slide.dds, omega**2 * x2, rtol=0, atol=1e-12)
    np.testing.assert_allclose(rod.angle, beta, rtol=0, atol=1e-14)


@pytest.mark.parametrize("branch", [+1, -1])
@pytest.mark.parametrize("omega", [5.0, -2.0])
def test_rrp_inclined_guide_finite_differences_and_closure(branch, omega):
    r, l = 0.1, 0.3
    gp, ga = 0.05 + 0.02j, np.radians(25.0)
    e = np.exp(1j * ga)

    def solve(phi):
        _, tip = kin.crank(fixed(0j, len(phi)), r, phi, omega)
        return (tip,) + kin.rrp(tip, l, gp, ga, branch)

    b, rod, slide, c = solve(PHI)
    # Loop closure: |BC| = l, C on the guide line, C = guide point + s·e.
    np.testing.assert_allclose(np.abs(c.pos - b.pos), l, rtol=0, atol=CLOSURE_ATOL)
    np.testing.assert_allclose((np.conj(e) * (c.pos - gp)).imag, 0, rtol=0, atol=CLOSURE_ATOL)
    np.testing.assert_allclose(c.pos, gp + slide.s * e, rtol=0, atol=CLOSURE_ATOL)
    # Branch: C ahead of (+1) or behind (−1) B's foot on the guide.
    assert np.all(np.sign((np.conj(e) * (c.pos - b.pos)).real) == branch)
    # Rod angle is the direction B→C.
    np.testing.assert_allclose(np.exp(1j * rod.angle), (c.pos - b.pos) / l, atol=1e-12)
    assert_fd(c.vel, fd(lambda f: solve(f)[3].pos, PHI, omega), "C velocity")
    assert_fd(slide.ds, fd(lambda f: solve(f)[2].s, PHI, omega), "slide speed")
    assert_fd(rod.omega, fd_angle(lambda f: solve(f)[1].angle, PHI, omega), "rod ω")
    assert_fd(c.acc, fd(lambda f: solve(f)[3].vel, PHI, omega), "C acceleration")
    assert_fd(slide.dds, fd(lambda f: solve(f)[2].ds, PHI, omega), "slide acceleration")
    assert_fd(rod.alpha, fd(lambda f: solve(f)[1].omega, PHI, omega), "rod α")
    # The slider moves along the guide only.
    np.testing.assert_allclose(c.vel, slide.ds * e, atol=1e-13)


# ---------------------------------------------------------------------------------- RRR


def test_four_bar_pythagorean_position_by_hand():
    """O=(0,0), D=(4,0), crank 1 at 90° → B=(0,1); coupler 5, rocker 4 → C=(4,4) (3-4-5).

    By hand (relative motion, ω the crank speed): v_B = −ω (along x); v_C ⟂ DC (vertical)
    so v_C is along x; rigid coupler BC=(4,3): (v_C − v_B)·BC = 0 → v_C = −ω, ω3 = 0,
    ω4 = ω/4. Accelerations: a_B = −iω²; a_C = −4α4 − 4iω4² = a_B + iα3(4+3i)
    → α3 = 3ω²/16, α4 = 9ω²/64, a_C = −(9/16)ω² − (1/4)iω².
    The other branch is the mirror of C in the line BD: C' = (36/17, −60/17).
    """
    omega = 2.0
    _, b = kin.crank(fixed(0j, 1), 1.0, np.array([np.pi / 2]), omega)
    d = fixed(4 + 0j, 1)
    l3, l4, c = kin.rrr(b, d, 5.0, 4.0, branch=+1)
    # Exact small integers: round-off only.
    assert c.pos[0] == pytest.approx(4 + 4j, abs=1e-14)
    assert c.vel[0] == pytest.approx(-omega + 0j, abs=1e-14)
    assert l3.omega[0] == pytest.approx(0.0, abs=1e-14)
    assert l4.omega[0] == pytest.approx(omega / 4, abs=1e-14)
    assert l3.alpha[0] == pytest.approx(3 * omega**2 / 16, abs=1e-13)
    assert l4.alpha[0] == pytest.approx(9 * omega**2 / 64, abs=1e-13)
    assert c.acc[0] == pytest.approx(-9 / 16 * omega**2 - 0.25j * omega**2, abs=1e-13)
    assert l3.angle[0] == pytest.approx(np.arctan2(3, 4), abs=1e-14)
    assert l4.angle[0] == pytest.approx(np.pi / 2, abs=1e-14)
    _, _, c2 = kin.rrr(b, d, 5.0, 4.0, branch=-1)
    assert c2.pos[0] == pytest.approx(36 / 17 - 60j / 17, abs=1e-14)


def test_crank_rocker_position_by_law_of_cosines():
    """Crank collinear with the frame (φ = 0): B, D on the x axis; the angle at B of the
    triangle B-C-D follows from the law of cosines with sides l1, l2 and d − r."""
    r, l1, l2, d_ = 0.1, 0.35, 0.3, 0.4
    _, b = kin.crank(fixed(0j, 1), r, np.array([0.0]), 1.0)
    _, _, c = kin.rrr(b, fixed(d_ + 0j, 1), l1, l2, branch=+1)
    dist = d_ - r
    beta = np.arccos((l1**2 + dist**2 - l2**2) / (2 * l1 * dist))
    assert c.pos[0] == pytest.approx(r + l1 * np.exp(1j * beta), abs=1e-15)


@pytest.mark.parametrize("branch", [+1, -1])
def test_rrr_finite_differences_with_both_outer_points_moving(branch):
    """B on a crank (ω), D on a second crank turning at 2ω: exercises v_D, a_D too."""
    omega = 3.0
    l1, l2 = 0.45, 0.4

    def solve(phi):
        n = len(phi)
        _, b = kin.crank(fixed(0j, n), 0.1, phi, omega)
        _, d = kin.crank(fixed(0.5 + 0.05j, n), 0.05, 2 * phi + 0.3, 2 * omega)
        return (b, d) + kin.rrr(b, d, l1, l2, branch)

    b, d, k1, k2, c = solve(PHI)
    np.testing.assert_allclose(np.abs(c.pos - b.pos), l1, rtol=0, atol=CLOSURE_ATOL)
    np.testing.assert_allclose(np.abs(c.pos - d.pos), l2, rtol=0, atol=CLOSURE_ATOL)
    np.testing.assert_allclose(np.exp(1j * k1.angle), (c.pos - b.pos) / l1, atol=1e-12)
    np.testing.assert_allclose(np.exp(1j * k2.angle), (c.pos - d.pos) / l2, atol=1e-12)
    # Branch +1: C to the left of B→D (positive cross product).
    assert np.all(np.sign(kin.cross(d.pos - b.pos, c.pos - b.pos)) == branch)
    assert_fd(c.vel, fd(lambda f: solve(f)[4].pos, PHI, omega), "C velocity")
    assert_fd(k1.omega, fd_angle(lambda f: solve(f)[2].angle, PHI, omega), "ω1")
    assert_fd(k2.omega, fd_angle(lambda f: solve(f)[3].angle, PHI, omega), "ω2")
    assert_fd(c.acc, fd(lambda f: solve(f)[4].vel, PHI, omega), "C acceleration")
    assert_fd(k1.alpha, fd(lambda f: solve(f)[2].omega, PHI, omega), "α1")
    assert_fd(k2.alpha, fd(lambda f: solve(f)[3].omega, PHI, omega), "α2")
    # C seen from D's side gives the same velocity (rigid link 2).
    np.testing.assert_allclose(c.vel, d.vel + 1j * k2.omega * (c.pos - d.pos), atol=1e-12)


# ---------------------------------------------------------------------------------- RPR


@pytest.mark.parametrize("offset", [0.0, 0.04, -0.03])
@pytest.mark.parametrize("branch", [+1, -1])
@pytest.mark.parametrize("moving_pivot", [False, True])
def test_rpr_finite_differences_and_closure(offset, branch, moving_pivot):
    omega = -4.0

    def solve(phi):
        n = len(phi)
        _, a = kin.crank(fixed(0.3j, n), 0.1, phi, omega)
        if moving_pivot:
            _, o = kin.crank(fixed(0.05 + 0j, n), 0.02, -phi + 1.0, -omega)
        else:
            o = fixed(0.05 + 0j, n)
        return (a, o) + kin.rpr(a, o, branch, offset)

    a, o, bar, slide = solve(PHI)
    u = np.exp(1j * bar.angle)
    # Closure: A = O + s·u + offset·(i·u), the slider path parallel to the bar.
    np.testing.assert_allclose(a.pos, o.pos + slide.s * u + offset * 1j * u, rtol=0, atol=CLOSURE_ATOL)
    # Branch: the bar points from the pivot towards A (+1, s > 0) or away (−1, s < 0).
    assert np.all(np.sign(slide.s) == branch)
    assert_fd(bar.omega, fd_angle(lambda f: solve(f)[2].angle, PHI, omega), "bar ω")
    assert_fd(slide.ds, fd(lambda f: solve(f)[3].s, PHI, omega), "slide speed")
    assert_fd(bar.alpha, fd(lambda f: solve(f)[2].omega, PHI, omega), "bar α")
    assert_fd(slide.dds, fd(lambda f: solve(f)[3].ds, PHI, omega), "slide acceleration")


def test_rpr_crank_horizontal_with_coriolis_by_hand():
    """O3 = 0, O2 = (0, L), crank r at φ = 0 → A = (r, L), ρ = |O3A|, u = (r, L)/ρ.

    v_A = iωr. Along the bar: ṡ = v_A·u = ωrL/ρ; across: ω4ρ = v_A·(iu) = ωr²/ρ.
    a_A = −ω²r = −ω4²ρu + α4ρ(iu) + 2ω4ṡ(iu) + s̈u (Coriolis 2ω4ṡ across the bar), so
    α4 = (ω²rL/ρ − 2ω4ṡ)/ρ and s̈ = −ω²r²/ρ + ω4²ρ.
    """
    L, r, omega = 0.65, 0.0925, -8.0
    _, a = kin.crank(fixed(1j * L, 1), r, np.array([0.0]), omega)
    bar, slide = kin.rpr(a, fixed(0j, 1), +1)
    rho = np.hypot(r, L)
    sdot = omega * r * L / rho
    w4 = omega * r**2 / rho**2
    a4 = (omega**2 * r * L / rho - 2 * w4 * sdot) / rho
    sdd = -omega**2 * r**2 / rho + w4**2 * rho
    # Closed form vs closed form: round-off (values of order 1, 1e-13 absolute).
    assert bar.angle[0] == pytest.approx(np.arctan2(L, r), abs=1e-14)
    assert slide.s[0] == pytest.approx(rho, abs=1e-15)
    assert slide.ds[0] == pytest.approx(sdot, abs=1e-13)
    assert bar.omega[0] == pytest.approx(w4, abs=1e-13)
    assert bar.alpha[0] == pytest.approx(a4, abs=1e-12)
    assert slide.dds[0] == pytest.approx(sdd, abs=1e-12)
    # The Coriolis term 2·ω4·ṡ (≈ 0.23 m/s² here) is 1e11 times the tolerance on α4·ρ,
    # so a missing or mis-signed Coriolis term could not pass.
    assert abs(2 * w4 * sdot) > 0.1


@pytest.mark.parametrize("phi, sign", [(np.pi / 2, +1), (3 * np.pi / 2, -1)])
def test_guide_bar_vertical_angular_velocity(phi, sign):
    """Bar vertical (crank along O3O2): ω4 = r·ω/(L + r) at the top, −r·ω/(L − r) at the
    bottom; the sliding speed is zero there (v_A is perpendicular to the bar)."""
    L, r, omega = 0.65, 0.0925, -8.0
    _, a = kin.crank(fixed(1j * L, 1), r, np.array([phi]), omega)
    bar, slide = kin.rpr(a, fixed(0j, 1), +1)
    expected = r * omega / (L + r) if sign > 0 else -r * omega / (L - r)
    assert bar.omega[0] == pytest.approx(expected, rel=1e-13)  # round-off of a closed form
    assert slide.ds[0] == pytest.approx(0.0, abs=1e-14)
    assert np.cos(bar.angle[0]) == pytest.approx(0.0, abs=1e-15)


# ---------------------------------------------------------------------------------- point_on_link


@pytest.mark.parametrize("offset_angle", [0.0, 0.7])
def test_point_on_link_finite_differences(offset_angle):
    """Link angle θ(φ) = 0.4 sinφ + 0.3φ² given analytically: ω_link = ω·θ', α = ω²·θ''."""
    omega = 2.5

    def solve(phi):
        n = len(phi)
        _, origin = kin.crank(fixed(0.1j, n), 0.15, phi, omega)
        link = AngleMotion(0.4 * np.sin(phi) + 0.3 * phi**2,
                           omega * (0.4 * np.cos(phi) + 0.6 * phi),
                           omega**2 * (-0.4 * np.sin(phi) + 0.6))
        return kin.point_on_link(origin, link, 0.25, offset_angle), link, origin

    p, link, origin = solve(PHI)
    np.testing.assert_allclose(np.abs(p.pos - origin.pos), 0.25, atol=CLOSURE_ATOL)
    np.testing.assert_allclose(np.angle((p.pos - origin.pos) * np.exp(-1j * (link.angle + offset_angle))),
                               0.0, atol=1e-13)
    assert_fd(p.vel, fd(lambda f: solve(f)[0].pos, PHI, omega), "point velocity")
    assert_fd(p.acc, fd(lambda f: solve(f)[0].vel, PHI, omega), "point acceleration")


# ---------------------------------------------------------------------------------- mechanism


def four_bar(r=0.1, l1=0.35, l2=0.3, d=0.4, branch=+1, omega=5.0):
    m = Mechanism("1", {"O": 0j, "D": d + 0j})
    m.add(Crank("crank", "2", "O", "B", r, omega))
    m.add(RRR("coupler-rocker", "3", "4", "B", "D", "C", l1, l2, branch))
    m.add(LinkPoint("E", "3", "B", 0.2, 0.5))
    return m


def test_mechanism_solve_matches_direct_group_calls():
    m = four_bar()
    mo = m.solve(PHI)
    _, b = kin.crank(fixed(0j, len(PHI)), 0.1, PHI, 5.0)
    k1, k2, c = kin.rrr(b, fixed(0.4 + 0j, len(PHI)), 0.35, 0.3, +1)
    e = kin.point_on_link(b, k1, 0.2, 0.5)
    # Identical arithmetic: equal to the last bit.
    np.testing.assert_array_equal(mo.points["C"].pos, c.pos)
    np.testing.assert_array_equal(mo.links["4"].alpha, k2.alpha)
    np.testing.assert_array_equal(mo.points["E"].acc, e.acc)
    names = [j.name for g in m.groups for j in m.joints[g.name]]
    assert names == ["R12", "R23", "R34", "R14"]  # force of link a on link b


def test_mechanism_add_rejects_unknown_points():
    m = Mechanism("1", {"O": 0j})
    with pytest.raises(ValueError, match="'coupler'.*'X'"):
        m.add(RRR("coupler", "3", "4", "B", "X", "C", 1.0, 1.0, 1))


def test_assembly_error_rrr_names_group_and_first_angle():
    """O=(0,0), D=(3,0), crank 1, links 1.5 + 1.2 = 2.7: |BD|² = 10 − 6cosφ > 2.7² for
    cosφ < (10 − 7.29)/6, i.e. φ > 63.14°; on a 1° grid the first failure is 64°, the
    last 296° (233 angles)."""
    m = Mechanism("1", {"O": 0j, "D": 3 + 0j})
    m.add(Crank("crank", "2", "O", "B", 1.0, 1.0))
    m.add(RRR("dyad BCD", "3", "4", "B", "D", "C", 1.5, 1.2, 1))
    limit = np.degrees(np.arccos((10 - 2.7**2) / 6))
    assert 63 < limit < 64
    phi = np.radians(np.arange(360.0))
    with pytest.raises(AssemblyError) as info:
        m.solve(phi)
    err = info.value
    assert err.group == "dyad BCD" and err.kind == "RRR"
    assert err.crank_angle_deg == pytest.approx(np.ceil(limit))
    assert err.count == 296 - 64 + 1
    assert "dyad BCD" in str(err) and "64.00°" in str(err)
    m.solve(np.radians(np.arange(0.0, 63.0)))  # assembles wherever the law of cosines allows


def test_assembly_error_rrp_rod_too_short():
    """Crank 0.1 about the origin, guide y = 0.2, rod 0.15: |y_B − 0.2| > 0.15 when
    sinφ < 0.5, so φ = 0 already fails; first reported angle 0°."""
    m = Mechanism("1", {"O": 0j})
    m.add(Crank("crank", "2", "O", "B", 0.1, 1.0))
    m.add(RRP("ram", "3", "4", "B", "C", 0.15, 0.2j, 0.0, 1, "1"))
    with pytest.raises(AssemblyError, match=r"group 'ram' \(RRP\).* 0\.00°"):
        m.solve(np.radians(np.arange(0.0, 360.0, 10.0)))
    m.solve(np.radians(np.arange(40.0, 140.0, 10.0)))  # sinφ ≥ 0.64 > 0.5 closes


def test_assembly_error_rpr_offset_larger_than_distance():
    """O2 = (0, 0.3), crank 0.1, offset 0.25: |O3A|² = 0.1 + 0.06 sinφ < 0.25² when
    sinφ < −0.625, i.e. 218.68° < φ < 321.32°; on a 1° grid 219°…321° fail (103 angles)."""
    m = Mechanism("1", {"O3": 0j, "O2": 0.3j})
    m.add(Crank("crank", "2", "O2", "A", 0.1, 1.0))
    m.add(RPR("bar", "3", "4", "A", "O3", 1, offset=0.25))
    with pytest.raises(AssemblyError) as info:
        m.solve(np.radians(np.arange(360.0)))
    err = info.value
    assert err.group == "bar" and err.kind == "RPR"
    assert "'bar'" in str(err) and "219.00°" in str(err) and err.count == 321 - 219 + 1
