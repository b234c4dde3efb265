"""The shaper (牛头刨床, BRIEFS.md 000) stages against independent references.

References (孙桓《机械原理》 and its 课程设计指导书), none copied from the program's output:

* textbook positions: 12 positions every 30° from the left extreme (position 1), plus the
  other extreme 8′ and the two positions with the guide bar vertical, 4′ and 10′; order
  1,2,3,4,4′,5,6,7,8′,8,9,10,10′,11,12;
* the ram extremes: v = 0 at 1 and 8′, s(8′) = H, working stroke 180° + θ of crank angle;
* the guide bar vertical (crank along O2O3): ω4 = r·ω2/(L_O2O3 ± r), v_ram = L_O3B·|ω4|;
* an independent closed form of the linkage written here from the geometry
  (A = O2 + r·e^{iφ}, bar through O3 and A, B = L_O3B·u, F on the guide y = L_O3M at
  x_B − sqrt(L_BF² − (L_O3M − y_B)²)), differentiated by five-point finite differences;
* the balancing torque by the principle of virtual power, M_b·ω2 + Σ F·v + Σ M·ω = 0,
  evaluated with that closed form (not with the program's power_residual);
* energy over a cycle: gravity and inertia do no net work, so mean(M_b)·2π equals the
  cutting work Fc·(1 − 2·0.05)·H = Fc·0.9H;
* flywheel J_F = 900·ΔW_max/(π²n²[δ]) on the pinion shaft n1 = n2·z2/z1, with ΔW_max from
  the independently computed torque.
"""
from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from mechdesign.brief.loader import load_brief
from mechdesign.machines.shaper.brief import to_si
from mechdesign.machines.shaper import stages as sh

DESIGN = Path(__file__).parents[1] / "designs" / "shaper.yaml"
LABELS = ("1", "2", "3", "4", "4'", "5", "6", "7", "8'", "8", "9", "10", "10'", "11", "12")

# Five-point differences in φ with step 3e-3 rad: truncation h⁴/30·|f⁽⁵⁾| ≈ 3e-12 and
# h⁴/90·|f⁽⁶⁾| ≈ 1e-12 (derivatives of order 10 m/radⁿ), round-off 1.5ε|f|/h ≈ 1e-13 for f'
# and 5ε|f|/h² ≈ 1.2e-10 m/rad² for f'' (|f| ≈ 1 m). With |x''| ≈ 0.1–0.5 m/rad², the
# relative error is ~1e-9; tolerances of 1e-7 (relative to the largest value) are safe.
H_FD = 3e-3
RTOL = 1e-7


def d1(f, x, h=H_FD):
    return (-f(x + 2 * h) + 8 * f(x + h) - 8 * f(x - h) + f(x - 2 * h)) / (12 * h)


def d2(f, x, h=H_FD):
    return (-f(x + 2 * h) + 16 * f(x + h) - 30 * f(x) + 16 * f(x - h) - f(x - 2 * h)) / (12 * h**2)


class ClosedForm:
    """The shaper linkage from its geometry alone; functions of the crank angle φ (CCW)."""

    def __init__(self, p, d):
        self.p, self.d = p, d
        self.drop = d.guide_height - (d.frame + p.cutting_height)

    def A(self, phi):
        return 1j * self.d.frame + self.d.crank * np.exp(1j * phi)

    def u(self, phi):
        a = self.A(phi)
        return a / np.abs(a)

    def B(self, phi):
        return self.d.guide_bar * self.u(phi)

    def S4(self, phi):
        return self.d.bar_com * self.u(phi)

    def F(self, phi):
        b = self.B(phi)
        dy = self.d.guide_height - b.imag
        return b.real - np.sqrt(self.d.rod**2 - dy**2) + 1j * self.d.guide_height

    def S6(self, phi):
        return self.F(phi) + self.p.ram_com_x

    def P(self, phi):
        return self.F(phi) - 1j * self.drop

    def theta_rel(self, phi0):
        """Bar angle relative to its value at φ0, unwrapped locally (for differences)."""
        u0 = self.u(phi0)
        return lambda phi: np.angle(self.u(phi) / u0)

    def balancing_torque(self, phi, working_dir, fc):
        """M_b in the sense of rotation from virtual power: M_b·ω2 + Σ F·v + Σ M·ω = 0.

        With v = ω2·(dr/dφ) and a = ω2²·(d²r/dφ²) at constant ω2, dividing by ω2 gives the
        CCW torque M = −Σ F·(dr/dφ) − Σ M·(dθ/dφ); the sense of rotation multiplies by sgn ω2.
        """
        p, w = self.p, self.p.crank_omega
        g = p.gravity

        def dot(f, v):
            return (np.conj(f) * v).real

        total = np.zeros_like(phi)
        for m, pt in ((p.m4, self.S4), (p.m6, self.S6)):
            r1, r2 = d1(pt, phi), d2(pt, phi)
            total += dot(-m * w**2 * r2 - 1j * m * g, r1)
        th = self.theta_rel(phi)
        total += -p.J_S4 * w**2 * d2(th, phi) * d1(th, phi)
        total += dot(-working_dir * fc + 0j, d1(self.P, phi))
        # Gear 2's weight acts at the fixed O2: no power.
        return np.sign(w) * (-total)


@pytest.fixture(scope="module")
def run():
    p = to_si(load_brief(DESIGN))
    syn = sh.synthesize(p)
    k, mech, motion = sh.kinematics(syn, p)
    f = sh.kinetostatics(k, mech, motion, p)
    fl = sh.flywheel(k, f, p)
    return p, syn, k, mech, motion, f, fl


def at_positions(k, arr):
    return arr[k.grid_size:]


# ---------------------------------------------------------------------- positions


def test_textbook_position_labels_and_order(run):
    p, syn, k, *_ = run
    assert k.positions.labels == LABELS
    assert [lab for lab, s in zip(k.positions.labels, k.positions.special) if s] == ["4'", "8'", "10'"]
    ph = np.degrees(k.positions.phase)
    theta = np.degrees(syn.extreme_angle)
    regular = [ph[i] for i, lab in enumerate(LABELS) if "'" not in lab]
    np.testing.assert_allclose(regular, np.arange(0, 360, 30), atol=1e-9)
    assert np.all(np.diff(ph) > 0)
    assert ph[LABELS.index("8'")] == pytest.approx(180 + theta, abs=1e-9)  # working stroke 180°+θ
    assert np.degrees(k.working_span) == pytest.approx(180 + theta, abs=1e-9)


def test_special_positions_crank_angles(run):
    p, syn, k, *_ = run
    ca = np.degrees(at_positions(k, k.crank_angle)) % 360
    half = np.degrees(syn.extreme_angle) / 2
    # Extremes: crank perpendicular to the bar, at 180° + ψ/2 (left) and 360° − ψ/2 (right);
    # bar vertical: crank straight up (90°) during the working stroke, down (270°) on return.
    assert ca[LABELS.index("1")] == pytest.approx(180 + half, abs=1e-9)
    assert ca[LABELS.index("8'")] == pytest.approx(360 - half, abs=1e-9)
    assert ca[LABELS.index("4'")] == pytest.approx(90.0, abs=1e-9)
    assert ca[LABELS.index("10'")] == pytest.approx(270.0, abs=1e-9)
    # Clockwise crank: the phase increases as the crank angle decreases.
    assert np.all(np.diff(k.crank_angle[: k.grid_size]) < 0)


def test_ram_extremes(run):
    p, syn, k, *_ = run
    s, v = at_positions(k, k.ram_s), at_positions(k, k.ram_v)
    vmax = np.max(np.abs(k.ram_v))
    # v = 0 at the extremes up to round-off (1e-12 of the peak speed).
    assert abs(v[LABELS.index("1")]) <= 1e-12 * vmax
    assert abs(v[LABELS.index("8'")]) <= 1e-12 * vmax
    assert s[LABELS.index("1")] == 0.0
    assert s[LABELS.index("8'")] == pytest.approx(p.stroke, abs=1e-12)  # H, metres, round-off
    grid_s = k.ram_s[: k.grid_size]
    assert grid_s.min() >= -1e-12 and grid_s.max() <= p.stroke + 1e-12
    # Working stroke moves forwards (v ≥ 0), return stroke backwards.
    work = k.phase[: k.grid_size] < k.working_span
    assert np.all(k.ram_v[: k.grid_size][work] >= -1e-12 * vmax)
    assert np.all(k.ram_v[: k.grid_size][~work] <= 1e-12 * vmax)


@pytest.mark.parametrize("label, sign", [("4'", +1), ("10'", -1)])
def test_guide_bar_vertical(run, label, sign):
    p, syn, k, *_ = run
    d = syn.design
    i = k.grid_size + LABELS.index(label)
    r, L, w2 = d.crank, d.frame, p.crank_omega
    w4 = r * w2 / (L + r) if sign > 0 else -r * w2 / (L - r)
    # Closed forms evaluated two ways: round-off (1e-12 relative).
    assert k.omega4[i] == pytest.approx(w4, rel=1e-12)
    assert abs(k.ram_v[i]) == pytest.approx(d.guide_bar * abs(w4), rel=1e-12)
    assert k.slide_v[i] == pytest.approx(0.0, abs=1e-12)  # v_A is across the vertical bar
    assert k.coriolis[i] == pytest.approx(0.0, abs=1e-12)


def test_guide_bar_motion_and_coriolis_at_every_position(run):
    """From the crank alone: v_A = iω2·r·e^{iφ}; along the bar v_A4A3 = v_A·u, across it
    ω4·|O3A| = v_A·(iu); Coriolis a_k = 2·ω4·v_A4A3."""
    p, syn, k, *_ = run
    cf = ClosedForm(p, syn.design)
    phi = at_positions(k, k.crank_angle)
    a, u = cf.A(phi), cf.u(phi)
    va = 1j * p.crank_omega * syn.design.crank * np.exp(1j * phi)
    vr = (np.conj(u) * va).real
    w4 = (np.conj(1j * u) * va).real / np.abs(a)
    np.testing.assert_allclose(at_positions(k, k.slide_v), vr, rtol=0, atol=1e-12)
    np.testing.assert_allclose(at_positions(k, k.omega4), w4, rtol=0, atol=1e-12)
    np.testing.assert_allclose(at_positions(k, k.coriolis), 2 * w4 * vr, rtol=0, atol=1e-12)


def test_ram_kinematics_against_closed_form(run):
    p, syn, k, *_ = run
    cf = ClosedForm(p, syn.design)
    w = p.crank_omega
    phi = k.crank_angle
    x0 = cf.F(k.crank_angle[k.grid_size]).real          # position 1
    x_end = cf.F(k.crank_angle[k.grid_size + LABELS.index("8'")]).real
    direction = np.sign(x_end - x0)
    s = direction * (cf.F(phi).real - x0)
    v = direction * w * d1(lambda f: cf.F(f).real, phi)
    acc = direction * w**2 * d2(lambda f: cf.F(f).real, phi)
    # Positions: same geometry, round-off only (1e-12 m).
    np.testing.assert_allclose(k.ram_s, s, rtol=0, atol=1e-12)
    np.testing.assert_allclose(k.ram_v, v, rtol=0, atol=RTOL * np.max(np.abs(v)))
    np.testing.assert_allclose(k.ram_a, acc, rtol=0, atol=RTOL * np.max(np.abs(acc)))
    th = cf.theta_rel(phi)
    np.testing.assert_allclose(k.alpha4, w**2 * d2(th, phi), rtol=0,
                               atol=RTOL * np.max(np.abs(k.alpha4)))


# ---------------------------------------------------------------------- forces


def independent_cutting_force(k, p, cf):
    """Fc while the ram moves forwards (first 180°+θ from position 1) with
    0.05H ≤ s ≤ 0.95H; the cutting force opposes the working motion."""
    x0 = cf.F(k.crank_angle[k.grid_size]).real
    s = k.stroke_direction * (cf.F(k.crank_angle).real - x0)
    theta = sh.synthesize(p).extreme_angle
    working = k.phase <= np.pi + theta
    idle = 0.05 * p.stroke
    inside = (s >= idle) & (s <= p.stroke - idle)
    near_edge = (np.abs(s - idle) < 1e-9) | (np.abs(s - (p.stroke - idle)) < 1e-9)
    return np.where(working & inside, p.cutting_force, 0.0), near_edge, s


def test_cutting_force_window(run):
    p, syn, k, mech, motion, f, fl = run
    cf = ClosedForm(p, syn.design)
    fc, near_edge, s = independent_cutting_force(k, p, cf)
    assert not near_edge.any()   # no grid point within 1e-9 m of a window edge
    np.testing.assert_array_equal(f.cutting_force, fc)
    ret = k.phase > k.working_span
    assert np.all(f.cutting_force[ret] == 0)                       # return stroke
    assert np.all(f.cutting_force[s < 0.05 * p.stroke] == 0)       # idle travel at the start
    assert np.all(f.cutting_force[s > 0.95 * p.stroke] == 0)       # idle travel at the end
    assert set(np.unique(f.cutting_force)) == {0.0, p.cutting_force}
    # Positions 1, 7 (s > 0.95H), 8' and the return positions have no cutting force.
    fc_pos = dict(zip(LABELS, at_positions(k, f.cutting_force)))
    assert [lab for lab, v in fc_pos.items() if v > 0] == ["2", "3", "4", "4'", "5", "6"]


def test_balancing_torque_at_textbook_positions_by_virtual_power(run):
    p, syn, k, mech, motion, f, fl = run
    cf = ClosedForm(p, syn.design)
    fc, _, _ = independent_cutting_force(k, p, cf)
    phi = at_positions(k, k.crank_angle)
    mb = cf.balancing_torque(phi, k.stroke_direction, at_positions(k, fc))
    # Five-point differences: relative error ~1e-9 (see H_FD); 1e-7 of the peak torque.
    scale = np.max(np.abs(mb))
    np.testing.assert_allclose(at_positions(k, f.balancing_torque), mb, rtol=0, atol=RTOL * scale)
    # Extremes: every massive point is at rest, so M_b = 0 there.
    assert abs(mb[LABELS.index("1")]) <= RTOL * scale
    assert abs(mb[LABELS.index("8'")]) <= RTOL * scale


def test_mean_balancing_torque_does_the_cutting_work(run):
    """Over one cycle gravity and inertia do no net work (periodic potential and kinetic
    energy), so Σ M_b·Δφ = Fc·0.9H. The grid mean of M_b is a rectangle rule: exact to
    round-off for the smooth periodic part, but each edge of the force window falls
    between grid points, costing at most Fc·|dx/dφ|·h of work per edge (two edges)."""
    p, syn, k, mech, motion, f, fl = run
    n = k.grid_size
    h = 2 * np.pi / n
    work = np.mean(f.balancing_torque[:n]) * 2 * np.pi
    cutting = p.cutting_force * 0.9 * p.stroke                     # 460.8 J
    assert cutting == pytest.approx(460.8, rel=1e-12)
    max_dx = np.max(np.abs(k.ram_v[:n])) / abs(p.crank_omega)      # max |dx/dφ| [m/rad]
    tol = 2 * p.cutting_force * max_dx * h                         # ≈ 1.0 J (0.2 %)
    assert abs(work - cutting) <= tol
    # The flywheel stage's mean power is the same number per second.
    assert fl.mean_power == pytest.approx(cutting * p.crank_speed_rpm / 60, abs=tol * 80 / 60)


# ---------------------------------------------------------------------- flywheel, verify


def test_flywheel_stage_from_independent_torque(run):
    """ΔE(φ) = ∫(M_d − M_b)dφ from the closed-form torque, integrated by the trapezoidal
    rule piece by piece between the exact ends of the cutting window (issue 21: M_b jumps
    there, so a grid straddling the jumps costs up to Fc·|dx/dφ|·h of work per edge)."""
    p, syn, k, mech, motion, f, fl = run
    cf = ClosedForm(p, syn.design)
    start, sense, wdir = k.crank_angle[0], np.sign(p.crank_omega), k.stroke_direction
    x0 = cf.F(start).real

    def s_of(ph):
        return wdir * (cf.F(start + sense * ph).real - x0)

    theta = sh.synthesize(p).extreme_angle
    span, idle = np.pi + theta, 0.05 * p.stroke
    e1 = brentq(lambda x: s_of(x) - idle, 1e-3, span / 2, xtol=1e-15)
    e2 = brentq(lambda x: s_of(x) - (p.stroke - idle), span / 2, span - 1e-3, xtol=1e-15)
    ends, forces_on = [0.0, e1, e2, span, 2 * np.pi], [0.0, p.cutting_force, 0.0, 0.0]
    nodes, work, total = [], [], 0.0
    for a, b, fc in zip(ends[:-1], ends[1:], forces_on):
        ph = np.linspace(a, b, 40001)
        mb = cf.balancing_torque(start + sense * ph, wdir, np.full(ph.size, fc))
        w = total + np.concatenate(([0.0], np.cumsum((mb[1:] + mb[:-1]) / 2 * np.diff(ph))))
        nodes.append(ph)
        work.append(w)
        total = w[-1]
    nodes, work = np.concatenate(nodes), np.concatenate(work)
    md = total / (2 * np.pi)
    energy = md * nodes - work
    dw = energy.max() - energy.min()
    assert md == pytest.approx(p.cutting_force * 0.9 * p.stroke / (2 * np.pi), rel=1e-9)
    # Trapezoids of 1e-5 rad on smooth pieces: ΔW to ~1e-8; the five-point derivatives ~1e-9.
    assert fl.max_energy_swing == pytest.approx(dw, rel=1e-6)
    # Where the energy peaks and bottoms out: the same node (one node step ≈ 1e-4 rad).
    assert fl.phase_at_max == pytest.approx(nodes[np.argmax(energy)], abs=2e-4)
    assert fl.phase_at_min == pytest.approx(nodes[np.argmin(energy)], abs=2e-4)
    i = p.z2 / p.z1                                   # pinion turns 60/18 times faster
    n1 = p.crank_speed_rpm * i
    assert fl.speed_ratio == pytest.approx(i) and fl.shaft_speed_rpm == pytest.approx(n1)
    J = 900 * dw / (np.pi**2 * n1**2 * p.fluctuation)
    assert fl.inertia == pytest.approx(J, rel=1e-6)
    # M_d on the crank and on the flywheel shaft (M_r there is M_b / i).
    assert fl.mean_torque == pytest.approx(md, rel=1e-6)
    assert fl.shaft_torque == pytest.approx(md / i, rel=1e-6)
    assert fl.rim.rim_mass == pytest.approx(4 * J / p.rim_diameter**2, rel=1e-6)


def test_verify_stage_residuals_are_small(run):
    p, syn, k, mech, motion, f, fl = run
    v = sh.verify(syn, k, mech, motion, f, p)
    assert v.closure_residual <= 1e-12                  # metres, round-off
    # Central differences with h = 0.1°: error ≈ h²/6·|f'''/f'| ≈ 5e-7·(a few) → 1e-5.
    assert v.velocity_fd_error <= 1e-5 and v.acceleration_fd_error <= 1e-5
    assert abs(v.stroke_error) <= 1e-9
    assert v.time_ratio_simulated == pytest.approx(p.time_ratio_K, abs=1e-6)
    assert v.power_balance_residual <= 1e-9


def test_counter_clockwise_crank_keeps_the_textbook_conventions(run):
    """Turning the crank the other way mirrors the working stroke; position 1 is still the
    start of the slow stroke, 8′ the other extreme, 4′ the bar vertical with the crank up."""
    p, syn, *_ = run
    q = dataclasses.replace(p, crank_omega=abs(p.crank_omega), grid_points=360)
    k, mech, motion = sh.kinematics(syn, q)
    assert k.positions.labels == LABELS
    assert np.degrees(k.working_span) == pytest.approx(180 + np.degrees(syn.extreme_angle), abs=1e-9)
    s = at_positions(k, k.ram_s)
    assert s[LABELS.index("8'")] == pytest.approx(q.stroke, abs=1e-12)
    ca = np.degrees(at_positions(k, k.crank_angle)) % 360
    assert ca[LABELS.index("4'")] == pytest.approx(90.0, abs=1e-9)
    assert ca[LABELS.index("1")] == pytest.approx(360 - np.degrees(syn.extreme_angle) / 2, abs=1e-9)


@pytest.mark.parametrize("massless", ["m4", "m6"])
def test_massless_guide_bar_or_ram_is_a_valid_brief(run, massless):
    p, syn, *_ = run
    q = dataclasses.replace(p, grid_points=360, **{massless: 0.0})
    k, mech, motion = sh.kinematics(syn, q)
    f = sh.kinetostatics(k, mech, motion, q)
    cf = ClosedForm(q, syn.design)
    fc, _, _ = independent_cutting_force(k, q, cf)
    mb = cf.balancing_torque(at_positions(k, k.crank_angle), k.stroke_direction, at_positions(k, fc))
    np.testing.assert_allclose(at_positions(k, f.balancing_torque), mb, rtol=0,
                               atol=RTOL * np.max(np.abs(mb)))


# ---------------------------------------------------------------------- issue 19: the
# flywheel rim's weight on shaft Ⅰ (the shaper's flywheel sits on the pinion's shaft O1)


def test_flywheel_rim_weight_loads_shaft_one_by_hand_statics(example_results):
    """Shaft Ⅰ carries the V-belt's pulley (overhung), the pinion z1 and the flywheel rim
    between its bearings. The loads are formed here from their own formulas — the rim's
    weight W = m·g with m = 4J_F/D² (thin rim), the belt's pull F_p from the belt design, the
    pinion's F_t = 2T/d1 and F_r = F_t·tan α — at the layout's stations, and the bearing
    reactions come from the two equilibrium equations of a beam on supports A (x = 0) and
    B (x = L) in each plane: R_B = −Σ F_i x_i / L, R_A = −Σ F_i − R_B."""
    r = example_results("shaper")
    fl, d, p = r["linkage_flywheel"], r["drive"], r["params"]
    W = 4 * fl.inertia / fl.rim.diameter ** 2 * p.gravity
    assert W == pytest.approx(fl.rim.rim_mass * p.gravity, rel=1e-9)
    sd = next(s for s in d.shaft_designs if s.index == 1)
    assert sorted(sd.elements) == ["belt", "flywheel", "open_spur"]
    at = dict(zip(sd.elements, sd.loads))
    L = sd.span
    # the rim hangs at mid-span, its width and 60 mm each side between the bearings
    assert at["flywheel"].x == pytest.approx(L / 2)
    assert L == pytest.approx(fl.rim.width + 0.12)
    belt = next(s for s in d.stages if s.type == "belt")
    spur = next(s for s in d.stages if s.type == "spur")
    Fp = belt.design.geometry.Fp
    T = sd.torque
    Ft = 2 * T / spur.design.geometry.g1.d             # d1 = m·z1
    Fr = Ft * np.tan(spur.design.geometry.alpha)        # α = 20°, unshifted mesh (α′ = α)
    # (x, Fh, Fv): the belt pulls horizontally, the mesh's tangential force horizontal and
    # its radial force vertical (their senses as laid out), the rim's weight downwards
    sg = at["open_spur"]
    loads = [(at["belt"].x, np.sign(at["belt"].Fh) * Fp, 0.0),
             (sg.x, np.sign(sg.Fh) * Ft, np.sign(sg.Fv) * Fr),
             (L / 2, 0.0, -W)]
    RBh = -sum(x * fh for x, fh, _ in loads) / L
    RBv = -sum(x * fv for x, _, fv in loads) / L
    RAh = -sum(fh for _, fh, _ in loads) - RBh
    RAv = -sum(fv for _, _, fv in loads) - RBv
    res = sd.result
    assert (res.RAh, res.RAv, res.RBh, res.RBv) == pytest.approx((RAh, RAv, RBh, RBv), rel=1e-6)
    assert res.FrA == pytest.approx(np.hypot(RAh, RAv), rel=1e-6)
    assert res.FrB == pytest.approx(np.hypot(RBh, RBv), rel=1e-6)
    # the bending moment at the rim: M_v = R_Av·L/2 + the overhung loads left of it
    Mv = RAv * L / 2 + sum(fv * (L / 2 - x) for x, _, fv in loads if x < 0)
    Mh = RAh * L / 2 + sum(fh * (L / 2 - x) for x, fh, _ in loads if x < 0)
    sec = [s for s in res.sections if abs(s.x - L / 2) < 1e-12]
    assert sec and sec[0].M == pytest.approx(np.hypot(Mh, Mv), rel=1e-6)

