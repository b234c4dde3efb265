"""Issue 21 (4): integrals over piecewise loads integrate each piece between its exact ends.

References, all independent of the program's output:

* over a steady-state revolution inertia and gravity do no net work, so the mean driving
  torque is the resistances' work per cycle over 2π: the shaper cuts with F_c over
  (1 − 2·idle)·H, so M_d = F_c·(1 − 2·idle)·H/2π; a slider-crank resisted by F_w over the
  whole working stroke and F_r over the return gives M_d = (F_w + F_r)·H/2π with the
  closed-form stroke H = √((a+b)² − e²) − √((b−a)² − e²) (whatever its masses);
* ΔW_max by brute force: M_b from the kinetostatics (``solve_forces``, loads built here) on
  10⁶ crank angles, ΔE by the trapezoidal rule, max − min;
* the energy curve closes: ΔE(2π) = ΔE(0);
* J_F = 900·ΔW_max/(π²·n²·[δ]) (孙桓《机械原理》§7).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from mechdesign.brief.loader import load_variant, parse_brief
from mechdesign.core.kinetostatics import PointLoad, solve_forces
from mechdesign.machines import get_machine, stages_for
from mechdesign.pipeline import run_stages
from mechdesign.stages import linkage as lk

DESIGNS = Path(__file__).parents[1] / "designs"
REPORT = {"title": "t", "student": "s"}
TWO_PI = 2 * np.pi


def run_example(stem: str, group: str | None = None):
    v = load_variant(DESIGNS / f"{stem}.yaml", group)
    m = get_machine(v.brief.machine)
    p = m.to_params(v.brief)
    return v.brief, run_stages(stages_for(m, p), {"params": p, "brief": v.brief})[0]


def run(data: dict) -> dict:
    b = parse_brief(data)
    m = get_machine(b.machine)
    p = m.to_params(b)
    return run_stages(stages_for(m, p), {"params": p, "brief": b})[0]


@pytest.fixture(scope="module")
def shaper():
    return run_example("shaper", "I")


@pytest.mark.parametrize("group", ["I", "II", "III"])
def test_shaper_mean_torque_is_the_cutting_work_over_two_pi(group):
    b, r = run_example("shaper", group)
    H = b.linkage.stroke_H_mm / 1e3
    Fc, idle = b.loads.cutting_force_Fc_N, b.loads.idle_travel_ratio
    exact = Fc * (1 - 2 * idle) * H / TWO_PI
    f = r["linkage_forces"]
    assert f.mean_torque == pytest.approx(exact, rel=1e-9)
    assert f.cycle_work == pytest.approx(Fc * (1 - 2 * idle) * H, rel=1e-9)
    assert r["linkage_flywheel"].mean_torque == pytest.approx(exact, rel=1e-9)
    assert f.mean_power == pytest.approx(exact * b.linkage.crank_speed_n2_rpm * np.pi / 30, rel=1e-9)
    if group == "I":
        assert exact == pytest.approx(73.3386, abs=5e-5)       # the hand value


def test_press_and_die_cutter_mean_torque_is_the_pressing_work():
    b, r = run_example("press")
    H = b.linkage.stroke_H_mm / 1e3
    Q, ratio = b.loads.pressing_force_Qmax_N, b.loads.pressing_travel_ratio
    assert r["linkage_forces"].mean_torque == pytest.approx(Q * ratio * H / TWO_PI, rel=1e-9)
    _, r = run_example("die_cutter")
    p = r["params"]
    assert r["press_forces"].cycle_work == pytest.approx(p.cutting_force * p.pressing_travel, rel=1e-9)


@pytest.mark.parametrize("masses", [False, True])
def test_slider_crank_constant_resistance_over_the_working_stroke(masses):
    a, b_, e = 60.0, 240.0, 15.0
    data = {"machine": "linkage", "report": REPORT, "linkage": {
        "frame_points_mm": {"O": [0, 0]},
        "crank": {"pivot": "O", "tip": "A", "length_mm": a, "speed_rpm": 45, "rotation": "cw"},
        "groups": [{"type": "RRP", "links": [3, 4], "end": "A", "joint": "C", "length_mm": b_,
                    "guide_point_mm": [0, e], "guide_angle_deg": 0, "branch": 1}],
        "output": {"point": "C", "working": "increasing"},
        "resistances": [{"link": 4, "point": "C", "working_N": 500, "return_N": 100}],
        "flywheel": {"fluctuation_delta": "1/20"}}}
    if masses:
        data["linkage"]["groups"].append(
            {"type": "point", "name": "S3", "link": 3, "origin": "A", "distance_mm": 80})
        data["linkage"]["masses"] = [{"link": 3, "mass_kg": 4.0, "com": "S3", "J_kgm2": 0.03},
                                     {"link": 4, "mass_kg": 9.0, "com": "C"}]
    r = run(data)
    H = (np.sqrt((a + b_) ** 2 - e ** 2) - np.sqrt((b_ - a) ** 2 - e ** 2)) / 1e3
    f = r["linkage_forces"]
    assert f.mean_torque == pytest.approx((500 + 100) * H / TWO_PI, rel=1e-9)
    assert r["linkage_flywheel"].mean_torque == pytest.approx((500 + 100) * H / TWO_PI, rel=1e-9)
    # the old sampled mean missed it by more than the new tolerance
    n = r["linkage"].grid_size
    assert abs(np.mean(f.balancing_torque[:n]) - f.mean_torque) > 1e-9 * f.mean_torque


def test_power_balance_gives_the_kinetostatic_torque_on_every_piece(shaper):
    """M_b·|ω| = Σ resistance power + d(T + V)/dt, the engine's kinetostatics (Σ P = 0)."""
    _, r = shaper
    model, k, f = r["model"], r["linkage"], r["linkage_forces"]
    n = k.grid_size
    ci = lk.CycleIntegrals(model, k)
    mb = f.balancing_torque[:n]
    for i in range(len(ci.ends) - 1):
        a, b = ci.ends[i], ci.ends[i + 1]
        sel = (k.phase[:n] > a + 1e-9) & (k.phase[:n] < b - 1e-9)
        assert np.max(np.abs(ci.torque(k.phase[:n][sel], i) - mb[sel])) < 1e-9 * np.max(np.abs(mb))
    # the window ends are where the ram is idle·H from its extremes (scipy, independently)
    p = r["params"]
    idle = p.idle_travel_ratio * p.stroke

    def s(phase):
        return float(lk._output_coordinate(model, ci.solve(np.array([phase])), None)[0][0]) * \
            model.output.working
    s0 = s(0.0)
    start = brentq(lambda x: s(x) - s0 - idle, 1e-6, k.working_span / 2, xtol=1e-15)
    end = brentq(lambda x: s(x) - s0 - (p.stroke - idle), k.working_span / 2,
                 k.working_span - 1e-6, xtol=1e-15)
    assert sorted(ci.ends) == pytest.approx([0.0, start, end, k.working_span, TWO_PI], abs=1e-12)


def _brute_force_swing(model, start, sense, count=1_000_000, chunk=100_000):
    """ΔW_max and M_d from M_b on ``count`` crank angles: the kinetostatics with the cutting
    force built here (F_c opposing the ram's velocity while the ram is inside the window
    in the working stroke), the trapezoidal rule, the samples' max − min."""
    phase = np.arange(count + 1) * (TWO_PI / count)
    r = model.resistances[0]
    u = np.exp(1j * r.direction)
    w = model.output.working
    mb = np.empty(count + 1)
    s_at0 = None
    working_end = None
    # the working stroke ends where the output's velocity along its line changes sign
    for lo in range(0, count + 1, chunk):
        ph = phase[lo:lo + chunk]
        m = model.mechanism.solve(start + sense * ph)
        out = model.output
        x = (np.exp(-1j * out.direction) * m.points[out.name].pos).real * w
        if s_at0 is None:
            s_at0 = x[0]
        s = x - s_at0
        v_out = (np.exp(-1j * out.direction) * m.points[out.name].vel).real * w
        if working_end is None:
            stop = np.flatnonzero(v_out[1:] < 0)
            working_end = ph[stop[0] + 1] if len(stop) else None
        working = ph < working_end if working_end is not None else np.ones(len(ph), bool)
        inside = working & (s >= r.active[0]) & (s <= r.active[1])
        along = (np.conj(u) * m.points[r.point].vel).real
        force = -np.sign(along) * np.where(inside, r.working, r.returning) * u
        fa = solve_forces(model.mechanism, m, list(model.bodies),
                          [PointLoad(r.link, r.point, force)], model.gravity)
        mb[lo:lo + chunk] = sense * fa.driving_torque
    h = TWO_PI / count
    work = np.concatenate(([0.0], np.cumsum(0.5 * (mb[1:] + mb[:-1]) * h)))
    md = work[-1] / TWO_PI
    energy = md * phase - work
    _brute_force_swing.peak = float(np.max(np.abs(mb)))     # max |M_b| of the samples
    return md, energy.max() - energy.min()


def test_energy_swing_against_a_million_point_brute_force(shaper):
    _, r = shaper
    model, k, fl = r["model"], r["linkage"], r["linkage_flywheel"]
    md, swing = _brute_force_swing(model, k.start_angle, k.sense)
    # trapezoids across the two jumps of M_b: error ≤ h·(jump) ≈ 6e-6·240 N·m
    assert fl.mean_torque == pytest.approx(md, rel=1e-5)
    assert fl.max_energy_swing == pytest.approx(swing, rel=1e-5)
    # the exact extreme is at least every sample's
    assert fl.max_energy_swing >= swing - 1e-9 * swing
    # the exact peak |M_b| (one-sided at the jumps, refined between the 3600 samples) agrees
    # with the million samples and is at least every one of them
    peak = r["linkage_forces"].peak_torque
    assert peak == pytest.approx(_brute_force_swing.peak, rel=1e-6)
    assert peak >= _brute_force_swing.peak * (1 - 1e-12)


@pytest.mark.parametrize("stem", ["shaper", "slotter", "press", "linkage_sixbar", "die_cutter"])
def test_energy_curve_closes_and_the_flywheel_follows_the_textbook(stem):
    _, r = run_example(stem)
    pre, key = ("press", "press_model") if stem == "die_cutter" else ("linkage", "model")
    fl = r[f"{pre}_flywheel"]
    model = r[key] if key in r else r["params"]
    k = r[pre]
    ci = lk.CycleIntegrals(model, k)
    # ΔE(2π) = M_d·2π − ∮M_b dφ = 0 = ΔE(0)
    e_end = fl.mean_torque * TWO_PI - float(ci.integral([TWO_PI])[0])
    assert abs(e_end - fl.energy[0]) < 1e-9 * fl.max_energy_swing
    assert abs(fl.energy[0]) < 1e-12 * fl.max_energy_swing
    # the exact extremes bound every grid value; ΔE at them is the reported swing
    e_at = fl.mean_torque * np.array([fl.phase_at_min, fl.phase_at_max]) \
        - ci.integral([fl.phase_at_min, fl.phase_at_max])
    assert e_at[1] - e_at[0] == pytest.approx(fl.max_energy_swing, rel=1e-12)
    assert fl.max_energy_swing >= np.ptp(fl.energy) - 1e-12 * fl.max_energy_swing
    # each step of the grid energy against the trapezoidal rule of M_d − M_b (independent;
    # O(h³) on a step inside a piece, the steps across a jump of M_b left out)
    n = k.grid_size
    h = TWO_PI / n
    mb = np.append(r[f"{pre}_forces"].balancing_torque[:n], r[f"{pre}_forces"].balancing_torque[0])
    trap = (fl.mean_torque - 0.5 * (mb[1:] + mb[:-1])) * h
    step = np.diff(np.append(fl.energy, fl.energy[0]))
    grid = np.arange(n + 1) * h
    smooth = np.ones(n, bool)
    for end in ci.ends:
        smooth &= ~((grid[:-1] <= end) & (end <= grid[1:]))
    assert np.max(np.abs(step - trap)[smooth]) < 1e-5 * h * np.max(np.abs(mb))
    # J_F = 900·ΔW_max/(π²·n²·[δ]) on the flywheel shaft
    assert fl.inertia == pytest.approx(
        900 * fl.max_energy_swing / (np.pi ** 2 * fl.shaft_speed_rpm ** 2 * fl.fluctuation), rel=1e-12)
