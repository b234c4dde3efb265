"""The fast paths of the linkage engine (issue 8) against independent references.

* the closed-form group solutions of kinetostatics (driver: 3×3 Cramer; dyads: moments
  about the outer pins / force along the outer guides, then Cramer for the inner joint)
  against one dense ``np.linalg.solve`` of every group's full system, on mechanisms with
  every joint kind (RRR, RRP on a slanted guide, RPR with an offset, moving pivots);
* the closed-form RRR/RRP/RPR solutions (no trigonometry for the unit vectors) against the
  textbook formulas with np.exp(1j·θ) written out independently here, at many angles;
* constant arrays (frame points, the crank's ω, a fixed guide's angle) are read-only
  full-length views that every reader sees as shape (N,);
* the output's velocity zero on a grid point with round-off of opposite signs between the
  grid and a re-solve (a regression seen on the lockbeam feed).
"""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from mechdesign.core import kinematics as kin
from mechdesign.core.kinematics import PointMotion
from mechdesign.core.kinetostatics import Body, PointLoad, solve_forces
from mechdesign.core.mechanism import RPR, RRP, RRR, Crank, LinkPoint, Mechanism, Motion

PHI = np.linspace(0.0, 2 * np.pi, 2001, endpoint=False) + 0.0123
G = 9.81


def six_bar(offset: float, guide_deg: float, branch: int) -> tuple:
    mech = Mechanism("1", {"O": 0.4j, "Q": 0j})
    mech.add(Crank("crank", "2", "O", "A", 0.12, -6.0))
    mech.add(RPR("guide bar", "3", "4", "A", "Q", +1, offset=offset))
    mech.add(LinkPoint("B", "4", "Q", 0.7))
    mech.add(LinkPoint("S4", "4", "Q", 0.3, 0.05))
    mech.add(RRP("ram", "5", "6", "B", "C", 0.25, 0.6j, np.radians(guide_deg), branch, "1"))
    mech.add(LinkPoint("S5", "5", "B", 0.1))
    mech.add(LinkPoint("S6", "6", "C", 0.08, 1.0))
    mo = mech.solve(PHI)
    bodies = [Body("2", 0.5, "A", 0.001), Body("3", 0.8, "A", 0.002), Body("4", 9.0, "S4", 0.5),
              Body("5", 2.0, "S5", 0.01), Body("6", 30.0, "S6", 0.0)]
    loads = [PointLoad("6", "S6", np.full(len(PHI), -800.0 + 100.0j)),
             PointLoad("5", "S5", 50.0 * np.exp(2j * PHI))]
    return mech, mo, bodies, loads


def four_bar_on_a_moving_pivot() -> tuple:
    """Crank + RRR + a second RRR hung on the coupler point and a frame pin: the second
    dyad's outer joints move."""
    mech = Mechanism("1", {"A0": 0j, "D": 0.9 + 0j, "F": 1.1 + 0.6j})
    mech.add(Crank("crank", "2", "A0", "A", 0.25, 8.0))
    mech.add(RRR("4-bar", "3", "4", "A", "D", "B", 0.8, 0.7, +1))
    mech.add(LinkPoint("E", "3", "A", 0.5, 0.4))
    mech.add(RRR("dyad", "5", "6", "E", "F", "G", 0.8, 0.6, -1))
    mech.add(LinkPoint("S5", "5", "E", 0.3))
    mo = mech.solve(PHI)
    bodies = [Body("3", 2.0, "E", 0.02), Body("4", 1.5, "B", 0.01), Body("5", 1.0, "S5", 0.03),
              Body("6", 0.7, "G", 0.004)]
    loads = [PointLoad("6", "G", 30.0 * np.exp(1j * PHI))]
    return mech, mo, bodies, loads


CASES = [lambda: six_bar(0.0, 0.0, -1), lambda: six_bar(0.03, 20.0, -1),
         lambda: six_bar(-0.02, -35.0, +1), four_bar_on_a_moving_pivot]


@pytest.mark.parametrize("case", range(len(CASES)))
def test_closed_form_groups_match_a_dense_solve(case):
    mech, mo, bodies, loads = CASES[case]()
    fast = solve_forces(mech, mo, bodies, loads, G)
    dense = solve_forces(mech, mo, bodies, loads, G, dense=True)
    scale = max(np.max(np.abs(r.force)) for r in dense.reactions.values())
    assert set(fast.reactions) == set(dense.reactions)
    for name, r in dense.reactions.items():
        # Two exact methods on systems of condition ~1e3: round-off 1e-12 of the largest force.
        np.testing.assert_allclose(fast.reactions[name].force, r.force, rtol=0,
                                   atol=1e-12 * scale, err_msg=name)
        if r.couple is not None:
            np.testing.assert_allclose(fast.reactions[name].couple, r.couple, rtol=0,
                                       atol=1e-12 * scale, err_msg=name)
    np.testing.assert_allclose(fast.driving_torque, dense.driving_torque, rtol=0,
                               atol=1e-12 * np.max(np.abs(dense.driving_torque)))


def _carried(origin, u, w, al):
    return origin.pos + u, origin.vel + 1j * w * u, origin.acc + (1j * al - w**2) * u


def test_rrr_matches_the_textbook_formulas_written_out():
    """θ1 = ∠BD ± β by the law of cosines, C = B + l1·e^{iθ1}; ω, α from the closure's
    derivatives dotted with the unit vectors (written here without solve2)."""
    n = len(PHI)
    _, b = kin.crank(kin.fixed_point(0j, n), 0.1, PHI, 5.0)
    _, d = kin.crank(kin.fixed_point(0.5 + 0.05j, n), 0.05, 2 * PHI + 0.3, 10.0)
    for branch in (+1, -1):
        l1, l2 = 0.45, 0.3
        link1, link2, c = kin.rrr(b, d, l1, l2, branch)
        bd = d.pos - b.pos
        beta = np.arccos((l1**2 + np.abs(bd)**2 - l2**2) / (2 * l1 * np.abs(bd)))
        th1 = np.angle(bd) + branch * beta
        u1 = l1 * np.exp(1j * th1)
        u2 = b.pos + u1 - d.pos
        dv = d.vel - b.vel
        w1 = (np.conj(u2) * dv).real / (np.conj(u1) * u2).imag
        w2 = (np.conj(u1) * dv).real / (np.conj(u1) * u2).imag
        da = d.acc - b.acc + w1**2 * u1 - w2**2 * u2
        a1 = (np.conj(u2) * da).real / (np.conj(u1) * u2).imag
        a2 = (np.conj(u1) * da).real / (np.conj(u1) * u2).imag
        for got, want in [(link1.angle, th1), (link2.angle, np.angle(u2)), (link1.omega, w1),
                          (link2.omega, w2), (link1.alpha, a1), (link2.alpha, a2)]:
            np.testing.assert_allclose(got, want, rtol=0, atol=1e-12 * np.max(np.abs(want)))
        for got, want in zip((c.pos, c.vel, c.acc), _carried(b, u1, w1, a1)):
            np.testing.assert_allclose(got, want, rtol=0, atol=1e-12 * np.max(np.abs(want)))


@pytest.mark.parametrize("offset,branch", [(0.0, 1), (0.03, 1), (-0.02, -1)])
def test_rpr_unit_vector_is_the_bar_direction(offset, branch):
    """u = r·(s − i·e)/|r|² (from r = (s + i·e)·u) equals e^{iθ} of the returned angle."""
    n = len(PHI)
    _, a = kin.crank(kin.fixed_point(0.3j, n), 0.1, PHI, 4.0)
    o = kin.fixed_point(0.05 + 0j, n)
    bar, slide = kin.rpr(a, o, branch, offset)
    u = np.exp(1j * bar.angle)
    r = a.pos - o.pos
    np.testing.assert_allclose(slide.s * u + offset * 1j * u, r, rtol=0, atol=1e-15)
    # Sliding velocity: the relative velocity of A along the bar, (vA − iω·r)·u.
    v_rel = a.vel - 1j * bar.omega * r
    np.testing.assert_allclose(slide.ds, (np.conj(u) * v_rel).real, rtol=0, atol=1e-14)


def test_constants_are_read_only_full_length_views():
    n = 7
    p = kin.fixed_point(0.3 - 0.2j, n)
    for arr in (p.pos, p.vel, p.acc):
        assert arr.shape == (n,) and not arr.flags.writeable
        with pytest.raises(ValueError):
            arr[0] = 1.0
    mo = Mechanism("1", {"O": 0j}).add(Crank("c", "2", "O", "B", 0.05, 3.0)).add(
        RRP("g", "3", "4", "B", "C", 0.2, 0.01j, 0.3, 1, "1")).solve(PHI[:n])
    for arr in (mo.links["2"].omega, mo.links["2"].alpha, mo.links["4"].angle,
                mo.links["4"].omega, mo.points["O"].pos):
        assert arr.shape == (n,)
    assert np.all(mo.links["4"].angle == 0.3) and np.all(mo.links["2"].omega == 3.0)
    # Results derived from constants are ordinary writable arrays.
    assert (mo.points["O"].pos + 1.0).flags.writeable


def test_velocity_zero_on_a_grid_point_despite_round_off():
    """The grid solve and a single-angle re-solve round the output's velocity at a grid
    point where it vanishes to opposite signs; both extremes must still be found."""
    from mechdesign.stages.linkage import _extremes_by_velocity

    def solve(phi):
        bias = -1e-17 if len(phi) > 1 else 1e-17     # grid vs re-solve: opposite round-off
        v = np.round(np.cos(phi), 12) + bias          # zero at π/2 and 3π/2 (grid points)
        return Motion(phi, points={"P": PointMotion(np.sin(phi) + 0j, v + 0j, 0j * phi)})

    model = SimpleNamespace(mechanism=SimpleNamespace(solve=solve),
                            output=SimpleNamespace(kind="point", name="P", direction=0.0))
    angles = np.arange(8) * (2 * np.pi / 8)
    v = solve(angles).points["P"].vel.real
    (a_min, s_min), (a_max, s_max) = _extremes_by_velocity(model, angles, v, None)
    assert a_max == pytest.approx(np.pi / 2, abs=1e-15) and s_max == pytest.approx(1.0)
    assert a_min == pytest.approx(3 * np.pi / 2, abs=1e-15) and s_min == pytest.approx(-1.0)
