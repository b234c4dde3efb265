"""Kinetostatics (动态静力分析, 孙桓《机械原理》 §4) against independent references.

* virtual work / virtual power: for a static slider-crank with a horizontal force P on
  the slider, M = P·dx/dφ with x = r cosφ + sqrt(l² − (r sinφ − e)²) differentiated by
  hand, and the wall reaction P·tan β (β the rod angle) from the slider's equilibrium;
* a single crank with a mass at its tip turning at constant speed: the pivot reaction is
  m·(g + centripetal acceleration) and the torque m·g·r·cosφ, by hand;
* Newton–Euler for every moving link, recomputed from the reactions the program returns:
  ΣF = m·a_S and ΣM_O = m·(r_S × a_S) + J_S·α, with each joint force acting as +F on
  link b and −F on link a (Newton's third law), for a four-bar and for the shaper;
* principle of virtual power (power_residual) ≈ 0 with masses, inertia, gravity and loads.

Kinematics come from the (separately tested) group solvers; no expected number here is
copied from the program's output.
"""
from __future__ import annotations

import numpy as np
import pytest

from mechdesign.brief.loader import load_brief
from mechdesign.machines.shaper.brief import to_si
from mechdesign.core.kinematics import cross
from mechdesign.core.kinetostatics import Body, PointLoad, power_residual, solve_forces
from mechdesign.core.mechanism import RPR, RRP, RRR, Crank, LinkPoint, Mechanism
from mechdesign.machines.shaper import stages as sh
from mechdesign.stages import linkage as lk

from pathlib import Path

DESIGN = Path(__file__).parents[1] / "designs" / "shaper.yaml"
G = 9.81
PHI = np.radians(np.arange(0.0, 360.0, 7.5)) + 0.013  # generic angles, none on a symmetry line


# ---------------------------------------------------------------------- static slider-crank


def slider_crank(r, l, e):
    m = Mechanism("1", {"O": 0j})
    m.add(Crank("crank", "2", "O", "B", r, 1.0))
    m.add(RRP("rod+slider", "3", "4", "B", "C", l, 1j * e, 0.0, +1, "1"))
    return m


@pytest.mark.parametrize("e", [0.0, 0.04])
def test_static_slider_crank_virtual_work_and_wall_reaction(e):
    r, l, P = 0.1, 0.35, 250.0
    mech = slider_crank(r, l, e)
    mo = mech.solve(PHI)
    load = PointLoad("4", "C", np.full(len(PHI), -P + 0j))  # P opposes +x
    fa = solve_forces(mech, mo, [], [load], gravity=G)

    g, g1 = r * np.sin(PHI) - e, r * np.cos(PHI)
    q = np.sqrt(l**2 - g**2)
    dx = -r * np.sin(PHI) - g * g1 / q                  # dx/dφ by hand
    beta = np.arctan2(e - r * np.sin(PHI), q)            # rod angle B→C
    # Virtual work: M·δφ − P·δx = 0. Loads of a few hundred N; a 3×3 / 6×6 solve on
    # well-conditioned matrices is accurate to ~1e-13 relative → 1e-9 N·m is generous.
    np.testing.assert_allclose(fa.driving_torque, P * dx, rtol=0, atol=1e-9)
    # Slider: rod force along the rod, horizontal part P, so the guide pushes −P·tanβ along y.
    np.testing.assert_allclose(fa.reactions["R14"].force, -1j * P * np.tan(beta), rtol=0, atol=1e-9)
    np.testing.assert_allclose(np.abs(fa.reactions["R14"].force), P * np.abs(np.tan(beta)), atol=1e-9)
    np.testing.assert_allclose(fa.reactions["R14"].couple, 0.0, atol=1e-9)  # all forces through C
    # Massless rod: a two-force member, the force along it of magnitude P/cosβ.
    rod_force = P / np.cos(beta) * np.exp(1j * beta)
    for name in ("R23", "R34", "R12"):
        np.testing.assert_allclose(fa.reactions[name].force, rod_force, rtol=0, atol=1e-9)


def test_static_slider_crank_load_above_the_slider_gives_a_guide_couple():
    """P applied h above C: its moment about C is +P·h, so the guide's couple is −P·h;
    the driving torque is unchanged (the slider translates, every point has v_C)."""
    r, l, e, P, h = 0.1, 0.35, 0.0, 250.0, 0.06
    mech = slider_crank(r, l, e)
    mech.add(LinkPoint("Q", "4", "C", h, np.pi / 2))
    mo = mech.solve(PHI)
    fa = solve_forces(mech, mo, [], [PointLoad("4", "Q", np.full(len(PHI), -P + 0j))])
    g, g1 = r * np.sin(PHI) - e, r * np.cos(PHI)
    dx = -r * np.sin(PHI) - g * g1 / np.sqrt(l**2 - g**2)
    np.testing.assert_allclose(fa.reactions["R14"].couple, -P * h, rtol=0, atol=1e-9)
    np.testing.assert_allclose(fa.driving_torque, P * dx, rtol=0, atol=1e-9)


# ---------------------------------------------------------------------- crank with a tip mass


@pytest.mark.parametrize("omega", [6.0, -4.0])
def test_crank_with_tip_mass_pivot_reaction_by_hand(omega):
    """R12 = m·a_A + m·g·j with a_A = −ω²r·e^{iφ} (uniform circular motion), and
    M + (r e^{iφ}) × (−m g j) = 0 → M = m·g·r·cosφ (the centrifugal force is radial)."""
    m_, r, o = 3.0, 0.2, 0.3 + 0.1j
    mech = Mechanism("1", {"O": o})
    mech.add(Crank("crank", "2", "O", "A", r, omega))
    mo = mech.solve(PHI)
    fa = solve_forces(mech, mo, [Body("2", m_, "A", inertia=0.7)], [], gravity=G)
    e = np.exp(1j * PHI)
    # Forces ~ tens of N; round-off of a 3×3 solve ~1e-14 N → 1e-10 N is generous.
    np.testing.assert_allclose(fa.reactions["R12"].force, m_ * (-omega**2 * r * e) + 1j * m_ * G,
                               rtol=0, atol=1e-10)
    np.testing.assert_allclose(fa.driving_torque, m_ * G * r * np.cos(PHI), rtol=0, atol=1e-10)
    # α = 0 at constant speed: J adds nothing; the inertia couple is recorded as zero.
    np.testing.assert_allclose(fa.inertia_couple["2"], 0.0, atol=0)


# ---------------------------------------------------------------------- Newton–Euler helpers


def moving_links(mech):
    return [link for g in mech.groups for link in g.links]


def newton_euler_residuals(mech, mo, fa, bodies, loads, gravity):
    """Per link: ΣF − m·a_S and ΣM_O − (m·r_S×a_S + J·α), from the returned reactions only."""
    body = {b.link: b for b in bodies}
    driver = next(g.driver for g in mech.groups if g.driver is not None)
    out = {}
    for link in moving_links(mech):
        F = np.zeros(len(mo.crank_angle), complex)
        M = np.zeros(len(mo.crank_angle))
        for joints in mech.joints.values():
            for j in joints:
                rx = fa.reactions[j.name]
                p = mo.points[j.point].pos
                couple = rx.couple if rx.couple is not None else 0.0
                for side, sign in ((j.link_b, 1.0), (j.link_a, -1.0)):  # third law: ±F
                    if side == link:
                        F += sign * rx.force
                        M += sign * (cross(p, rx.force) + couple)
        for ld in loads:
            if ld.link == link:
                F += ld.force
                M += cross(mo.points[ld.point].pos, ld.force)
        expected_F = np.zeros_like(F)
        expected_M = np.zeros_like(M)
        b = body.get(link)
        if b is not None and b.mass:
            s = mo.points[b.com]
            w = -1j * b.mass * gravity
            F += w
            M += cross(s.pos, w)
            expected_F = b.mass * s.acc
            expected_M = b.mass * cross(s.pos, s.acc)
        if b is not None and b.inertia:
            expected_M = expected_M + b.inertia * mo.links[link].alpha
        if link == driver:
            M += fa.driving_torque
        out[link] = (F - expected_F, M - expected_M)
    return out


def four_bar_with_masses():
    mech = Mechanism("1", {"O": 0j, "D": 0.4 + 0.05j})
    mech.add(Crank("crank", "2", "O", "B", 0.1, -7.0))
    mech.add(LinkPoint("S2", "2", "O", 0.04))
    mech.add(RRR("coupler-rocker", "3", "4", "B", "D", "C", 0.38, 0.3, +1))
    mech.add(LinkPoint("S3", "3", "B", 0.17, 0.15))
    mech.add(LinkPoint("E", "3", "B", 0.25, -0.3))
    mech.add(LinkPoint("S4", "4", "D", 0.13))
    mo = mech.solve(PHI)
    bodies = [Body("2", 1.2, "S2", 0.004), Body("3", 2.5, "S3", 0.03), Body("4", 1.8, "S4", 0.02)]
    n = len(PHI)
    loads = [PointLoad("4", "C", 120.0 * np.exp(1j * (PHI + 0.4))),     # varying with φ
             PointLoad("3", "E", np.full(n, -40.0 + 15.0j))]
    return mech, mo, bodies, loads


def test_four_bar_power_residual_is_zero():
    mech, mo, bodies, loads = four_bar_with_masses()
    fa = solve_forces(mech, mo, bodies, loads, gravity=G)
    res = power_residual(mech, mo, bodies, loads, fa.driving_torque, gravity=G)
    scale = np.max(np.abs(fa.driving_torque * mo.links["2"].omega))
    # Exact identity for ideal joints; round-off of the solves only: 1e-9 relative.
    assert np.max(np.abs(res)) <= 1e-9 * scale
    # ... and it is a real check: a torque 1 N·m off shows up as 1 N·m × ω of residual.
    off = power_residual(mech, mo, bodies, loads, fa.driving_torque + 1.0, gravity=G)
    np.testing.assert_allclose(off, mo.links["2"].omega, atol=1e-9 * scale)


def test_four_bar_newton_euler_of_every_link():
    mech, mo, bodies, loads = four_bar_with_masses()
    fa = solve_forces(mech, mo, bodies, loads, gravity=G)
    scale = max(np.max(np.abs(r.force)) for r in fa.reactions.values())
    for link, (dF, dM) in newton_euler_residuals(mech, mo, fa, bodies, loads, G).items():
        # Reactions of order 100 N, lever arms < 1 m: round-off 1e-9 relative is ample.
        assert np.max(np.abs(dF)) <= 1e-9 * scale, f"ΣF on link {link}"
        assert np.max(np.abs(dM)) <= 1e-9 * scale, f"ΣM on link {link}"


def offset_guide_bar_six_bar():
    """Crank + RPR with an offset slider path + RRP on an inclined guide, every link massive:
    exercises prismatic normals on a turning bar and on a slanted frame guide."""
    mech = Mechanism("1", {"O": 0.4j, "Q": 0j})
    mech.add(Crank("crank", "2", "O", "A", 0.12, 6.0))
    mech.add(RPR("guide bar", "3", "4", "A", "Q", +1, offset=0.03))
    mech.add(LinkPoint("B", "4", "Q", 0.7))
    mech.add(LinkPoint("S4", "4", "Q", 0.3, 0.05))
    mech.add(RRP("ram", "5", "6", "B", "C", 0.25, 0.6j, np.radians(20.0), -1, "1"))
    mech.add(LinkPoint("S5", "5", "B", 0.1))
    mech.add(LinkPoint("S6", "6", "C", 0.08, 1.0))
    mo = mech.solve(PHI)
    bodies = [Body("3", 0.8, "A", 0.002), Body("4", 9.0, "S4", 0.5),
              Body("5", 2.0, "S5", 0.01), Body("6", 30.0, "S6", 0.0)]
    n = len(PHI)
    loads = [PointLoad("6", "S6", np.full(n, -800.0 + 100.0j)),
             PointLoad("5", "S5", 50.0 * np.exp(2j * PHI))]
    return mech, mo, bodies, loads


def test_offset_guide_bar_six_bar_power_and_newton_euler():
    mech, mo, bodies, loads = offset_guide_bar_six_bar()
    fa = solve_forces(mech, mo, bodies, loads, gravity=G)
    res = power_residual(mech, mo, bodies, loads, fa.driving_torque, gravity=G)
    assert np.max(np.abs(res)) <= 1e-9 * np.max(np.abs(fa.driving_torque * 6.0))  # round-off
    scale = max(np.max(np.abs(r.force)) for r in fa.reactions.values())
    for link, (dF, dM) in newton_euler_residuals(mech, mo, fa, bodies, loads, G).items():
        assert np.max(np.abs(dF)) <= 1e-9 * scale, f"ΣF on link {link}"
        assert np.max(np.abs(dM)) <= 1e-9 * scale, f"ΣM on link {link}"
    # Frictionless prismatic pairs: the force is normal to the bar and to the 20° guide.
    u4 = np.exp(1j * mo.links["4"].angle)
    np.testing.assert_allclose((np.conj(u4) * fa.reactions["R43"].force).real, 0.0, atol=1e-9 * scale)
    e = np.exp(1j * np.radians(20.0))
    np.testing.assert_allclose((np.conj(e) * fa.reactions["R16"].force).real, 0.0, atol=1e-9 * scale)


# ---------------------------------------------------------------------- the shaper six-bar


@pytest.fixture(scope="module")
def shaper():
    p = to_si(load_brief(DESIGN))
    syn = sh.synthesize(p)
    k, mech, mo = sh.kinematics(syn, p)
    # Fc [N] over the phase array by the engine's resistance law (the shaper's one resistance)
    fc = np.abs(lk.resistance_loads(k.model, k.linkage, mo)[0].force)
    bodies = [Body("4", p.m4, "S4", p.J_S4), Body("6", p.m6, "S6", 0.0),
              Body("2", p.G2 / p.gravity, "O2", 0.0)]
    loads = [PointLoad("6", "P", -k.stroke_direction * fc + 0j)]
    fa = solve_forces(mech, mo, bodies, loads, p.gravity)
    return p, mech, mo, bodies, loads, fa


def test_shaper_power_residual_is_zero(shaper):
    p, mech, mo, bodies, loads, fa = shaper
    res = power_residual(mech, mo, bodies, loads, fa.driving_torque, p.gravity)
    scale = np.max(np.abs(fa.driving_torque * p.crank_omega))
    assert np.max(np.abs(res)) <= 1e-9 * scale  # exact identity up to round-off


def test_shaper_newton_euler_of_every_link(shaper):
    p, mech, mo, bodies, loads, fa = shaper
    scale = max(np.max(np.abs(r.force)) for r in fa.reactions.values())
    res = newton_euler_residuals(mech, mo, fa, bodies, loads, p.gravity)
    assert set(res) == {"2", "3", "4", "5", "6"}
    for link, (dF, dM) in res.items():
        # Reactions up to ~1e4 N, lever arms ~1 m: round-off 1e-9 relative is ample.
        assert np.max(np.abs(dF)) <= 1e-9 * scale, f"ΣF on link {link}"
        assert np.max(np.abs(dM)) <= 1e-9 * scale, f"ΣM on link {link}"


def test_shaper_prismatic_reactions_are_normal_to_their_guides(shaper):
    p, mech, mo, bodies, loads, fa = shaper
    u4 = np.exp(1j * mo.links["4"].angle)
    # Ideal (frictionless) slider on the bar: no component along the bar.
    np.testing.assert_allclose((np.conj(u4) * fa.reactions["R43"].force).real, 0.0, atol=1e-9)
    # Ram on the horizontal frame guide: vertical reaction only.
    np.testing.assert_allclose(fa.reactions["R76"].force.real, 0.0, atol=1e-9)
    # Massless rod 5: two-force member, the force along B→F.
    bf = mo.points["F"].pos - mo.points["B"].pos
    np.testing.assert_allclose(cross(bf, fa.reactions["R45"].force) / np.abs(bf), 0.0, atol=1e-8)
