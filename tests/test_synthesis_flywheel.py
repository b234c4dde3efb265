"""Dimensional synthesis (尺寸综合) and flywheel design (飞轮设计), 孙桓《机械原理》 §7–§8.

References, all independent of the program's output:

* θ = 180°(K − 1)/(K + 1): K = 1.2 gives 180/11 = 16.3636…°;
* guide-bar quick-return (导杆机构): ψ = θ, L_O3B = H/(2 sin(ψ/2)), L_O2A = L_O2O3 sin(ψ/2),
  L_O3M = L_O3B(1 + cos(ψ/2))/2 (ram guide through the middle of the sagitta of B's arc),
  evaluated here with exact sines. The seed report prints L_O3B = 1142.86 mm: that is
  160/0.14, i.e. sin 8.2° rounded to 0.14 (sin 8.18° = 0.1423); the correct value is
  1124.27 mm;
* simulation of the synthesised linkage: ram extremes found by scipy.optimize on
  Mechanism.solve, giving the stroke H and, from the crank angles of the extremes, K;
* flywheel: for M_r = M0 + A sinφ, ΔE(φ) = A(cosφ − 1) and ΔW_max = 2A exactly; for a
  rectangular or triangular torque pulse the areas between M_r and the mean M_d by hand;
  J_F = ΔW_max/(ω_m²[δ]) with ω_m = πn/30; rim m = 4J/D² and γ·π·D·H·b = m·g.
"""
from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq, minimize_scalar

from mechdesign.brief.loader import load_brief
from mechdesign.machines.shaper.brief import to_si
from mechdesign.core import flywheel as fw
from mechdesign.core.synthesis import extreme_angle, guide_bar_quick_return, time_ratio
from mechdesign.machines.shaper import stages as sh

DESIGN = Path(__file__).parents[1] / "designs" / "shaper.yaml"
H, K, L_FRAME = 0.320, 1.2, 0.650   # seed 000 data [m], [-], [m]


# ---------------------------------------------------------------------- extreme angle


def test_extreme_angle_for_K_1_2_is_180_over_11_degrees():
    assert np.degrees(extreme_angle(1.2)) == pytest.approx(180.0 / 11.0, rel=1e-15)
    assert np.degrees(extreme_angle(1.2)) == pytest.approx(16.3636, abs=5e-5)
    assert extreme_angle(1.0) == 0.0                       # no quick return
    assert np.degrees(extreme_angle(2.0)) == pytest.approx(60.0, rel=1e-15)  # 180·1/3


@pytest.mark.parametrize("k", [1.0, 1.2, 1.5, 2.7])
def test_time_ratio_inverts_extreme_angle(k):
    assert time_ratio(extreme_angle(k)) == pytest.approx(k, rel=1e-14)  # algebraic inverse


# ---------------------------------------------------------------------- guide-bar design


def test_guide_bar_design_of_the_seed_data():
    d = guide_bar_quick_return(H, K, L_FRAME, 0.25, 0.5)
    half = np.radians(90.0 / 11.0)                 # ψ/2 = 8.1818…°
    bar = H / (2 * np.sin(half))
    assert d.swing_angle == pytest.approx(2 * half, rel=1e-15)
    assert d.guide_bar == pytest.approx(bar, rel=1e-14)
    assert d.guide_bar * 1e3 == pytest.approx(1124.27, abs=0.005)  # not the seed's 1142.86
    assert d.guide_bar * 1e3 != pytest.approx(160 / 0.14, abs=1.0)  # the seed's rounding error
    assert d.crank * 1e3 == pytest.approx(92.50, abs=0.005)
    assert d.crank == pytest.approx(L_FRAME * np.sin(half), rel=1e-14)
    assert d.guide_height == pytest.approx(bar * (1 + np.cos(half)) / 2, rel=1e-14)
    assert d.rod == pytest.approx(0.25 * bar, rel=1e-14)
    assert d.bar_com == pytest.approx(0.5 * bar, rel=1e-14)
    assert d.frame == L_FRAME


def test_guide_bar_geometry_closes():
    """At the extremes the crank is perpendicular to the bar (tangent from O3 to the crank
    circle): sin(ψ/2) = L_O2A/L_O2O3; B's chord between the extremes is the stroke; the ram
    guide is half-way between the top of B's arc and the chord."""
    d = guide_bar_quick_return(H, K, L_FRAME, 0.25, 0.5)
    half = d.swing_angle / 2
    assert d.crank / d.frame == pytest.approx(np.sin(half), rel=1e-14)
    assert 2 * d.guide_bar * np.sin(half) == pytest.approx(H, rel=1e-14)
    chord_height = d.guide_bar * np.cos(half)
    assert d.guide_height - chord_height == pytest.approx(d.guide_bar - d.guide_height, rel=1e-12)


@pytest.fixture(scope="module")
def shaper():
    p = to_si(load_brief(DESIGN))
    p = dataclasses.replace(p, grid_points=720)  # the search below does its own refining
    syn = sh.synthesize(p)
    k, mech, motion = sh.kinematics(syn, p)
    return p, syn, k, mech


def test_simulated_linkage_reproduces_H_and_K(shaper):
    """Simulate the synthesised linkage with Mechanism.solve only: find the ram extremes
    with scipy (minimise ∓x_F for the stroke; root of v_F for the crank angles) and
    recompute H and K = (working crank angle)/(return crank angle)."""
    p, syn, k, mech = shaper
    d = syn.design

    def state(phi):
        mo = mech.solve(np.array([phi]))
        return mo.points["F"].pos.real[0], mo.points["F"].vel.real[0]

    grid = np.radians(np.arange(0.0, 360.0, 1.0))
    x = mech.solve(grid).points["F"].pos.real
    step = grid[1] - grid[0]
    extremes = []
    for sign, i in ((+1, np.argmin(x)), (-1, np.argmax(x))):
        r = minimize_scalar(lambda f: sign * state(f)[0], bounds=(grid[i] - step, grid[i] + step),
                            method="bounded", options={"xatol": 1e-10})
        # v_F changes sign at the extreme: its root fixes the angle to ~1e-15 rad, while the
        # flat minimum of x only fixes it to ~sqrt(ε) — use the root for K, x for the stroke.
        phi = brentq(lambda f: state(f)[1], grid[i] - step, grid[i] + step, xtol=1e-15)
        extremes.append((phi % (2 * np.pi), state(r.x)[0]))
    (phi_left, x_left), (phi_right, x_right) = extremes
    # Stroke at round-off: x_F is flat at an extreme, so an angle error δ ~ 1e-5 costs only
    # ½x''δ² ~ 1e-11 m.
    assert x_right - x_left == pytest.approx(H, abs=1e-9)
    # Extremes where the crank is perpendicular to the bar: π + ψ/2 and 2π − ψ/2.
    half = d.swing_angle / 2
    assert phi_left == pytest.approx(np.pi + half, abs=1e-9)
    assert phi_right == pytest.approx(2 * np.pi - half, abs=1e-9)
    # Crank turns clockwise (ω2 < 0): working stroke from the left extreme to the right
    # one, passing through the top (90°).
    assert p.crank_omega < 0
    working = (phi_left - phi_right) % (2 * np.pi)   # clockwise sweep left → right
    k_sim = working / (2 * np.pi - working)
    assert k_sim == pytest.approx(K, abs=1e-9)     # angles known to 1e-9 rad
    # The program's own self-check agrees with this independent search.
    # (the linkage engine's verification: a bounded search on x_F between grid points)
    from mechdesign.stages import linkage as lk

    v = lk.verify(k.model, k.linkage, mech.solve(k.crank_angle), None)
    stroke, k_prog = v.stroke, v.time_ratio
    assert stroke == pytest.approx(H, abs=1e-9)
    # Its K comes from a bounded minimisation of x (flat extremum, angle ~sqrt(ε) ≈ 1e-7 rad
    # per end) → K to ~1e-7.
    assert k_prog == pytest.approx(K, abs=1e-6)


# ---------------------------------------------------------------------- flywheel


N_GRID = 3600
PHI = np.arange(N_GRID) * 2 * np.pi / N_GRID
STEP = 2 * np.pi / N_GRID


def circular_distance(a, b):
    return abs(np.angle(np.exp(1j * (a - b))))


def test_energy_cycle_of_a_sine_torque_swings_by_2A():
    """M_r = M0 + A sinφ: M_d = M0, ΔE = A(cosφ − 1), max at 0, min at π, ΔW_max = 2A."""
    M0, A = 150.0, 40.0
    c = fw.energy_cycle(PHI, M0 + A * np.sin(PHI))
    # Cumulative trapezoid on a sine: relative error ≈ h²/12 ≈ 2.5e-7 → 1e-6 relative.
    assert c.driving_torque == pytest.approx(M0, rel=1e-12)  # periodic trapezoid is exact here
    assert c.max_energy_swing == pytest.approx(2 * A, rel=1e-6)
    np.testing.assert_allclose(c.energy, A * (np.cos(PHI) - 1), atol=1e-6 * A)
    assert circular_distance(c.angle_at_max, 0.0) <= 1.5 * STEP  # a grid step + round-off
    assert circular_distance(c.angle_at_min, np.pi) <= 1.5 * STEP


def test_energy_cycle_of_a_rectangular_torque():
    """M_r = M1 on [0, α), 0 elsewhere: M_d = M1·α/2π; ΔE falls by (M1 − M_d)·α while the
    load acts (the rectangle between M_r and M_d) and rises back afterwards."""
    M1, alpha = 300.0, np.radians(120.0)
    mr = np.where(PHI < alpha - 1e-12, M1, 0.0)
    c = fw.energy_cycle(PHI, mr)
    md = M1 * alpha / (2 * np.pi)
    # Each jump is smeared over one trapezoid step: ±M1·h/2 of work per jump, two jumps.
    assert c.driving_torque == pytest.approx(md, abs=M1 * STEP / (2 * np.pi))
    assert c.max_energy_swing == pytest.approx((M1 - md) * alpha, abs=M1 * STEP)
    # ΔE is periodic: its maximum at φ = 0 ≡ 2π may be picked at either end of the grid;
    # within one grid step (1.5 steps allows for the round-off in 2π − h).
    assert circular_distance(c.angle_at_max, 0.0) <= 1.5 * STEP
    assert circular_distance(c.angle_at_min, alpha) <= 1.5 * STEP


def test_energy_cycle_of_a_triangular_torque():
    """M_r rises linearly 0 → M1 on [0, α] and falls back on [α, 2α]: M_d = M1·α/2π.
    ΔW_max is the triangle of M_r above M_d: height M1 − M_d, base 2α(1 − M_d/M1),
    area α(M1 − M_d)²/M1; ΔE peaks where M_r = M_d on the way up, φ = α·M_d/M1."""
    M1, alpha = 500.0, np.radians(90.0)
    mr = np.clip(M1 * (1 - np.abs(PHI - alpha) / alpha), 0.0, None)
    c = fw.energy_cycle(PHI, mr)
    md = M1 * alpha / (2 * np.pi)
    # Kinks on grid points: the trapezoid rule is exact for the work (round-off only);
    # the extremes of ΔE are sampled on the grid: error ≤ ½|ΔE''|h² = ½(M1/α)h² ≈ 1e-3 J.
    assert c.driving_torque == pytest.approx(md, rel=1e-12)
    assert c.max_energy_swing == pytest.approx(alpha * (M1 - md) ** 2 / M1, abs=(M1 / alpha) * STEP**2)
    assert c.angle_at_max == pytest.approx(alpha * md / M1, abs=STEP)
    assert c.angle_at_min == pytest.approx(2 * alpha - alpha * md / M1, abs=STEP)


def test_flywheel_inertia_formula():
    dW, n, delta = 280.0, 80.0 * 60 / 18, 1 / 25
    omega = np.pi * n / 30
    assert fw.flywheel_inertia(dW, n, delta) == pytest.approx(dW / (omega**2 * delta), rel=1e-14)


def test_rim_dimensions():
    J, D, k, gamma, n = 8.9, 0.5, 1.5, 7.0e4, 80.0 * 60 / 18
    rim = fw.rim_dimensions(J, D, k, gamma, n, gravity=9.81)
    m = 4 * J / D**2                           # thin rim: J = m(D/2)²
    assert rim.rim_mass == pytest.approx(m, rel=1e-14)
    assert rim.height / rim.width == pytest.approx(k, rel=1e-14)
    # Weight of the rim ring: γ·(π·D)·(H·b) = m·g.
    assert gamma * np.pi * D * rim.height * rim.width == pytest.approx(m * 9.81, rel=1e-13)
    assert rim.rim_speed == pytest.approx(np.pi * D * n / 60, rel=1e-14)
    assert rim.diameter == D
