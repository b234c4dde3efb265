"""The shared linkage engine and the `linkage` brief, against closed forms, the shaper
machine (a different composition of the same physics) and virtual work."""
from __future__ import annotations

import copy

import numpy as np
import pytest

from mechdesign.brief.loader import BriefError, parse_brief
from mechdesign.machines import get_machine, stages_for
from mechdesign.pipeline import run_stages

REPORT = {"title": "t", "student": "s"}


def run(data: dict) -> dict:
    b = parse_brief(data)
    m = get_machine(b.machine)
    p = m.to_params(b)
    return run_stages(stages_for(m, p), {"params": p, "brief": b})[0]


def slider_crank(a, b, e, rpm=60.0, rotation="ccw", working="increasing", **extra):
    return {"machine": "linkage", "report": REPORT, "linkage": {
        "frame_points_mm": {"O": [0, 0]},
        "crank": {"pivot": "O", "tip": "A", "length_mm": a, "speed_rpm": rpm, "rotation": rotation},
        "groups": [{"type": "RRP", "links": [3, 4], "end": "A", "joint": "C", "length_mm": b,
                    "guide_point_mm": [0, e], "guide_angle_deg": 0, "branch": 1}],
        "output": {"point": "C", "working": working}, **extra}}


def four_bar(a, b, c, d, **extra):
    return {"machine": "linkage", "report": REPORT, "linkage": {
        "frame_points_mm": {"A0": [0, 0], "D": [d, 0]},
        "crank": {"pivot": "A0", "tip": "A", "length_mm": a, "speed_rpm": 95.492965855,
                  "rotation": "ccw"},
        "groups": [{"type": "RRR", "links": [3, 4], "ends": ["A", "D"], "joint": "B",
                    "lengths_mm": [b, c], "branch": 1}],
        "output": {"link": 4}, **extra}}


@pytest.mark.parametrize("a,b,e", [(50, 200, 10), (100, 350, -40), (30, 120, 0)])
def test_offset_slider_crank_stroke_and_K_closed_form(a, b, e):
    r = run(slider_crank(a, b, e))
    k = r["linkage"]
    # Extremes: crank and rod collinear (extended, folded).
    stroke = np.sqrt((a + b) ** 2 - e ** 2) - np.sqrt((b - a) ** 2 - e ** 2)
    theta = abs(np.arcsin(e / (b - a)) - np.arcsin(e / (a + b)))
    assert k.stroke * 1e3 == pytest.approx(stroke, rel=1e-12)
    K = (np.pi + theta) / (np.pi - theta)
    # Counter-clockwise crank, offset above: the rightward stroke is the slow one for e < 0.
    assert max(k.time_ratio, 1 / k.time_ratio) == pytest.approx(K, rel=1e-10)
    # The position search of the verification stage agrees to its own tolerance.
    v = r["linkage_verification"]
    assert v.stroke == pytest.approx(k.stroke, rel=1e-9)
    assert v.time_ratio == pytest.approx(k.time_ratio, rel=1e-6)


def test_slider_crank_position_and_pressure_angle_closed_form():
    a, b, e = 50.0, 200.0, 10.0
    r = run(slider_crank(a, b, e))
    k = r["linkage"]
    phi = k.crank_angle
    x = a * np.cos(phi) + np.sqrt(b ** 2 - (a * np.sin(phi) - e) ** 2)
    assert np.max(np.abs(k.points["C"].real * 1e3 - x)) < 1e-9
    (q,) = k.quality
    alpha = np.arcsin(np.abs(a * np.sin(phi) - e) / b)
    assert np.max(np.abs(q.values - alpha)) < 1e-12
    assert q.extreme == pytest.approx(np.arcsin((a + abs(e)) / b), rel=1e-6)


@pytest.mark.parametrize("a,b,c,d", [(5, 8, 8, 9), (100, 400, 300, 400), (40, 150, 90, 140)])
def test_crank_rocker_swing_K_and_transmission_angle(a, b, c, d):
    r = run(four_bar(a, b, c, d))
    k = r["linkage"]
    # Extreme positions: crank and coupler collinear, |A0B| = b + a and b − a.
    ext = np.arccos((d ** 2 + (b + a) ** 2 - c ** 2) / (2 * d * (b + a)))
    fold = np.arccos((d ** 2 + (b - a) ** 2 - c ** 2) / (2 * d * (b - a)))
    rocker_ext = np.arccos((d ** 2 + c ** 2 - (b + a) ** 2) / (2 * d * c))
    rocker_fold = np.arccos((d ** 2 + c ** 2 - (b - a) ** 2) / (2 * d * c))
    assert k.stroke == pytest.approx(abs(rocker_ext - rocker_fold), rel=1e-10)
    theta = abs(ext - fold)
    K = (np.pi + theta) / (np.pi - theta)
    assert max(k.time_ratio, 1 / k.time_ratio) == pytest.approx(K, rel=1e-10)
    (q,) = k.quality
    g1 = np.arccos((b ** 2 + c ** 2 - (d - a) ** 2) / (2 * b * c))
    g2 = np.pi - np.arccos((b ** 2 + c ** 2 - (d + a) ** 2) / (2 * b * c))
    gmin = min(g1, g2, np.pi - g1, np.pi - g2)
    assert q.kind == "transmission"
    assert q.extreme == pytest.approx(gmin, abs=1e-5)   # on the grid, 0.1° apart
    assert q.extreme >= gmin - 1e-12


def test_resistance_torque_is_virtual_work_and_power_balances():
    data = slider_crank(60, 240, 15, rpm=45, rotation="cw",
                        resistances=[{"link": 4, "point": "C", "working_N": 500, "return_N": 100}])
    r = run(data)
    k, f, p = r["linkage"], r["linkage_forces"], r["params"]
    n = k.grid_size
    working = k.phase <= k.working_span
    # Massless: M_b ω = F·v_C for the resistance opposing the motion.
    F = np.where(working, 500.0, 100.0)
    expected = F * np.abs(k.v) / abs(p.crank_omega)
    inner = np.abs(k.v) > 1e-9
    assert np.allclose(f.balancing_torque[inner], expected[inner], rtol=1e-9, atol=1e-9)
    # Mean power = work per cycle / period = (500 + 100)·H·n/60.
    hand = (500 + 100) * k.stroke * 45 / 60
    assert f.mean_power == pytest.approx(hand, rel=1e-5)
    assert np.max(np.abs(f.power_residual[:n])) < 1e-9 * f.peak_torque * abs(p.crank_omega)


def test_same_as_the_shaper_machine(example_results):
    """The shaper written as a generic linkage gives the shaper machine's M_b and ram motion."""
    sr = example_results("shaper")
    sp = sr["params"]
    d, ks = sr["synthesis"].design, sr["kinematics"]
    mm = 1e3
    drop = d.guide_height - (d.frame + sp.cutting_height)
    H = sp.stroke * mm
    idle = sp.idle_travel_ratio * H
    data = {"machine": "linkage", "report": REPORT, "linkage": {
        "frame_points_mm": {"O3": [0, 0], "O2": [0, d.frame * mm]},
        "crank": {"link": 2, "pivot": "O2", "tip": "A", "length_mm": d.crank * mm,
                  "speed_rpm": sp.crank_speed_rpm, "rotation": "cw"},
        "groups": [
            {"type": "RPR", "links": [3, 4], "slider_at": "A", "pivot": "O3", "branch": 1},
            {"type": "point", "name": "B", "link": 4, "origin": "O3", "distance_mm": d.guide_bar * mm},
            {"type": "point", "name": "S4", "link": 4, "origin": "O3", "distance_mm": d.bar_com * mm},
            {"type": "RRP", "links": [5, 6], "end": "B", "joint": "F", "length_mm": d.rod * mm,
             "guide_point_mm": [0, d.guide_height * mm], "guide_angle_deg": 0, "branch": -1},
            {"type": "point", "name": "S6", "link": 6, "origin": "F", "distance_mm": sp.ram_com_x * mm},
            {"type": "point", "name": "P", "link": 6, "origin": "F", "distance_mm": abs(drop) * mm,
             "angle_deg": -90 if drop >= 0 else 90}],
        "output": {"point": "F", "working": "increasing" if ks.stroke_direction > 0 else "decreasing"},
        "masses": [{"link": 4, "mass_kg": sp.m4, "com": "S4", "J_kgm2": sp.J_S4},
                   {"link": 6, "mass_kg": sp.m6, "com": "S6"}],
        "resistances": [{"link": 6, "point": "P", "working_N": sp.cutting_force, "return_N": 0,
                         "active_mm": [idle, H - idle]}]},
        "analysis": {"grid_points": sp.grid_points}}
    r = run(data)
    k, f = r["linkage"], r["linkage_forces"]
    n = k.grid_size
    assert k.grid_size == ks.grid_size
    assert k.time_ratio == pytest.approx(sp.time_ratio_K, rel=1e-10)
    assert k.stroke == pytest.approx(sp.stroke, rel=1e-10)
    assert np.allclose(k.s[:n], ks.ram_s[:n], atol=1e-9)
    assert np.allclose(k.a[:n], ks.ram_a[:n], atol=1e-7)
    mb_shaper = sr["forces"].balancing_torque[:n]
    # The gear weight G2 acts at O2 and adds no torque; everything else is the same physics.
    assert np.max(np.abs(f.balancing_torque[:n] - mb_shaper)) < 1e-6 * np.max(np.abs(mb_shaper))


def test_flywheel_from_energy_swing():
    data = four_bar(100, 400, 300, 400, resistances=[
        {"link": 4, "point": "B", "direction_deg": 90, "working_N": 300, "return_N": 0}],
        flywheel={"fluctuation_delta": "1/25"})
    data["linkage"]["output"] = {"link": 4}
    r = run(data)
    k, f, fly = r["linkage"], r["linkage_forces"], r["linkage_flywheel"]
    n = k.grid_size
    dphi = 2 * np.pi / n
    # ΔE by the trapezoid rule of (M_d − M_b), independently of the core's integration.
    excess = f.mean_torque - f.balancing_torque[:n]
    energy = np.concatenate([[0.0], np.cumsum(0.5 * (excess + np.roll(excess, -1)) * dphi)])
    swing = energy.max() - energy.min()
    assert fly.max_energy_swing == pytest.approx(swing, rel=2e-3)
    n_rpm = 95.492965855
    assert fly.inertia == pytest.approx(900 * fly.max_energy_swing / (np.pi ** 2 * n_rpm ** 2 / 25),
                                        rel=1e-9)


def test_pressure_angle_limit_is_reported():
    data = slider_crank(100, 180, 30, pressure_angle_max_deg=30)
    r = run(data)
    codes = [w.code for w in r["linkage_verification"].warnings]
    # the offset slider-crank turning CCW makes its working (increasing) stroke the fast one:
    # K < 1 is named too (issue 18, point 7)
    assert codes == ["crank_sense_reversed", "pressure_angle"]
    assert run(slider_crank(20, 400, 0, pressure_angle_max_deg=30))["linkage_verification"].warnings == ()


@pytest.mark.parametrize("change,field,words", [
    (lambda g: g[0].update(end="Q"), "linkage", "'Q' is not defined"),
    (lambda g: g[0].update(links=[2, 5]), "linkage", "already used"),
    (lambda g: g[0].update(type="RRX"), "linkage.groups.0", "RRX"),
    (lambda g: g[0].update(length_mm=-5), "linkage.groups.0.length_mm", "greater than 0"),
    (lambda g: g[0].update(joint="A"), "linkage", "already defined"),
])
def test_bad_groups_name_the_field(change, field, words):
    data = slider_crank(50, 200, 10)
    change(data["linkage"]["groups"])
    with pytest.raises(BriefError) as exc:
        parse_brief(data)
    text = str(exc.value)
    assert field in text and words in text


def test_mass_must_sit_on_its_link():
    data = slider_crank(50, 200, 10, masses=[{"link": 3, "mass_kg": 2, "com": "O"}])
    with pytest.raises(BriefError, match="com 'O' is not a point of link '3'"):
        parse_brief(data)


def test_assembly_failure_names_the_group_and_angle():
    from mechdesign.core.mechanism import AssemblyError

    with pytest.raises(AssemblyError, match=r"RRP C.*crank angle"):
        run(slider_crank(100, 80, 0))


def test_example_brief_runs_and_verifies(example_results):
    r = example_results("linkage_sixbar")
    v = r["linkage_verification"]
    assert v.closure_residual < 1e-12
    assert v.velocity_fd_error < 1e-4 and v.acceleration_fd_error < 1e-4
    assert v.power_balance_residual < 1e-12


def test_document_serialises(example_results):
    from mechdesign.results import dumps
    import json

    r = example_results("linkage_sixbar")
    doc = json.loads(dumps(get_machine("linkage").document(r)))
    lk = doc["linkage"]
    assert lk["output"]["name"] == "E" and len(lk["positions"]) >= 12
    assert lk["flywheel"]["inertia"] > 0
    assert copy.deepcopy(lk["verification"])["closure_residual"] < 1e-12


def test_duplicate_group_names_and_every_reference_problem_at_its_field():
    """Two groups under one name (it keyed the solver's links: a LinAlgError before), an
    undefined point, a mass off its link and an output that is no point: all reported at
    once, each at its exact field, in English and Chinese (issue 21, points 3 and 5)."""
    data = four_bar(100, 400, 300, 400)
    g = data["linkage"]["groups"]
    g[0]["name"] = "摇杆"
    g.append({"type": "RRP", "name": "摇杆", "links": [5, 6], "end": "B", "joint": "E",
              "length_mm": 300, "guide_point_mm": [0, 500], "guide_angle_deg": 0})
    g.append({"type": "point", "name": "S9", "link": 3, "origin": "Q", "distance_mm": 10})
    data["linkage"]["masses"] = [{"link": 4, "mass_kg": 1, "com": "E"}]
    data["linkage"]["output"] = {"point": "Z"}
    with pytest.raises(BriefError) as exc:
        parse_brief(data)
    probs = {p.path: p for p in exc.value.problems}
    assert set(probs) == {"linkage.groups.1.name", "linkage.groups.2.origin",
                          "linkage.masses.0.com", "linkage.output.point"}, probs
    assert "already used by groups[0]" in probs["linkage.groups.1.name"].allowed
    assert "已被 groups[0] 使用" in probs["linkage.groups.1.name"].allowed_zh
    assert probs["linkage.output.point"].value.strip("'") == "Z"
    assert all(p.allowed_zh for p in probs.values())


def test_transmission_angle_minimum_is_exact_not_sampled():
    """Four-bar a = 100, b = 400, c = 300, d = 400 on a 97-point grid (no sample near the
    extreme): γ_min at the crank along the frame is arccos((b² + c² − (d − a)²)/(2bc)) =
    arccos(2/3) by the cosine rule — found to 1e-9 by the search between the samples."""
    import math

    r = run(four_bar(100, 400, 300, 400))
    assert r["linkage"].quality  # the RRR group's transmission angle
    (qa,) = r["linkage"].quality
    assert qa.extreme == pytest.approx(math.acos(2 / 3), abs=1e-9)
    data = four_bar(100, 400, 300, 400)
    data["analysis"] = {"grid_points": 97}
    (coarse,) = run(data)["linkage"].quality
    assert coarse.extreme == pytest.approx(math.acos(2 / 3), abs=1e-9)
    assert min(coarse.values[:97]) > coarse.extreme + 1e-6      # the samples miss it


def test_output_speed_and_acceleration_peaks_are_exact():
    """Offset slider-crank a = 50, b = 200, e = 10 at 60 rpm, on a 97-point grid: the
    largest |v| and |a| of the slider are found between the samples — they agree with a
    200 000-point sampling of the closed-form slider position x(φ) = a cos φ + √(b² −
    (a sin φ − e)²) differentiated by central differences, and exceed every coarse sample."""
    data = slider_crank(50, 200, 10)
    data["analysis"] = {"grid_points": 97}
    k = run(data)["linkage"]
    a, b, e, w = 0.05, 0.2, 0.01, 2 * np.pi
    phi = np.linspace(0, 2 * np.pi, 200_001)
    h = 1e-4

    def x(p):
        return a * np.cos(p) + np.sqrt(b ** 2 - (a * np.sin(p) - e) ** 2)

    v = (x(phi + h) - x(phi - h)) / (2 * h) * w
    acc = (x(phi + h) - 2 * x(phi) + x(phi - h)) / h ** 2 * w ** 2
    assert k.speed_peak == pytest.approx(np.max(np.abs(v)), rel=1e-6)
    assert k.accel_peak == pytest.approx(np.max(np.abs(acc)), rel=1e-6)
    assert k.speed_peak > np.max(np.abs(k.v[:97])) and k.accel_peak >= np.max(np.abs(k.a[:97]))
