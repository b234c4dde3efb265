"""Positions by crank angle and by event, named points, and the K < 1 finding (issue 18,
points 2, 3 and 7): every check against a closed form, a hand calculation, the regular
grid or the defining equation of the event — never a value copied from a run."""
from __future__ import annotations

import math

import numpy as np
import pytest
import yaml

from conftest import DESIGNS


def _run(tmp_path, name: str, edit) -> dict:
    """Compute designs/<name>.yaml after ``edit(data)`` (as the runner does)."""
    from mechdesign.brief.loader import load_brief
    from mechdesign.machines import get_machine, stages_for
    from mechdesign.pipeline import run_stages

    data = yaml.safe_load((DESIGNS / f"{name}.yaml").read_text(encoding="utf-8"))
    edit(data)
    path = tmp_path / f"{name}.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    brief = load_brief(path)
    machine = get_machine(brief.machine)
    params = machine.to_params(brief)
    results, _ = run_stages(stages_for(machine, params), {"params": params, "brief": brief})
    return results


def _at(k, label: str) -> int:
    return k.grid_size + list(k.positions.labels).index(label)


def test_textbook_guide_bar_at_45_deg_against_the_hand_calculation(example_results):
    """孙桓《机械原理》 guide-bar exercise (designs/textbook_guide_bar.yaml): l_AB = 30 mm,
    l_AC = 100 mm (C below A), φ1 = 45° from +x, ω1 = 10 rad/s CCW; D on the bar, l_CD = 150.
    Hand calculation (vector loop of the slider on the bar, polar coordinates about C):
      B = l_AB(cos φ1, sin φ1), CB = B − C, r = |CB|, e_r = CB/r, e_θ = e_r turned +90°;
      v_B = ω1 l_AB (−sin φ1, cos φ1);  a_B = −ω1² l_AB (cos φ1, sin φ1);
      ω3 = (v_B · e_θ)/r,  ṙ = v_B · e_r;
      α3 = (a_B · e_θ − 2 ṙ ω3)/r          (tangential component of a_B);
      v_D = ω3 l_CD e_θ;  a_D = −ω3² l_CD e_r + α3 l_CD e_θ.
    With the numbers: r = √(21.2132² + 121.2132²) = 123.0554 mm,
      ω3 = 0.0302132/0.0151426 = 1.99524 rad/s, v_D = 0.29928 m/s."""
    r_ = example_results("textbook_guide_bar")
    k = r_["linkage"]
    j = _at(k, "φ45")
    lab, lac, lcd, w1, phi = 0.030, 0.100, 0.150, 10.0, math.radians(45.0)
    bx, by = lab * math.cos(phi), lab * math.sin(phi)
    cbx, cby = bx - 0.0, by + lac
    r = math.hypot(cbx, cby)
    er = (cbx / r, cby / r)
    et = (-er[1], er[0])
    vb = (-w1 * lab * math.sin(phi), w1 * lab * math.cos(phi))
    ab = (-w1 ** 2 * bx, -w1 ** 2 * by)
    w3 = (vb[0] * et[0] + vb[1] * et[1]) / r
    rdot = vb[0] * er[0] + vb[1] * er[1]
    a3 = ((ab[0] * et[0] + ab[1] * et[1]) - 2 * rdot * w3) / r
    vd = complex(w3 * lcd * et[0], w3 * lcd * et[1])
    ad = complex(-w3 ** 2 * lcd * er[0] + a3 * lcd * et[0], -w3 ** 2 * lcd * er[1] + a3 * lcd * et[1])
    assert r == pytest.approx(0.1230554, rel=1e-6)
    assert w3 == pytest.approx(1.99524, rel=1e-5)
    assert abs(vd) == pytest.approx(0.29928, rel=1e-4)
    # the run at the requested angle
    assert k.crank_angle[j] % (2 * math.pi) == pytest.approx(phi, abs=1e-12)
    assert k.link_omega["4"][j] == pytest.approx(w3, rel=1e-10)
    assert k.link_alpha["4"][j] == pytest.approx(a3, rel=1e-9)
    assert k.point_vel["D"][j] == pytest.approx(vd, rel=1e-10)
    assert k.point_acc["D"][j] == pytest.approx(ad, rel=1e-9)
    assert abs(k.point_vel["B"][j]) == pytest.approx(w1 * lab, rel=1e-12)
    assert abs(k.point_acc["B"][j]) == pytest.approx(w1 ** 2 * lab, rel=1e-12)
    # Position 1 is the bar's extreme that starts its CCW (working) swing: the crank ⊥ CB
    # with the bar leaning right, the crank at −90° + acos(l_AB/l_AC) = −17.46° from +x;
    # the report's φ of the asked position is measured from there, CCW: 62.46°.
    start = -math.pi / 2 + math.acos(lab / lac)
    theta = 2 * math.asin(lab / lac)                      # the bar's swing = θ
    assert k.time_ratio == pytest.approx((math.pi + theta) / (math.pi - theta), rel=1e-12)
    assert k.phase[j] == pytest.approx((phi - start) % (2 * math.pi), abs=1e-9)
    # the polygons of the A1 sheet are drawn at the exercise's position
    assert r_["linkage_polygons"].positions[0] == "φ45"


def test_angle_positions_equal_the_grid_where_they_coincide(tmp_path):
    def edit(d):
        d["analysis"]["positions_deg"] = [45.1, 200.7]
    r = _run(tmp_path, "shaper", edit)
    k, f = r["linkage"], r["linkage_forces"]
    n = k.grid_size
    for value in (45.1, 200.7):
        j, g = _at(k, f"φ{value:g}"), int(round(value * n / 360.0))
        assert k.phase[j] == pytest.approx(k.phase[g], abs=1e-12)
        for a in (k.s, k.v, k.a, k.link_omega["4"], k.link_alpha["4"], f.balancing_torque):
            assert a[j] == pytest.approx(a[g], rel=1e-9, abs=1e-9 * np.max(np.abs(a[:n])))
    # a regular position asked for by angle is that position, not a second row
    def edit2(d):
        d["analysis"]["positions_deg"] = [60]
    k2 = _run(tmp_path, "shaper", edit2)["linkage"]
    assert k2.requested == {"φ60": "3"} and "φ60" not in k2.positions.labels


def test_events_satisfy_their_defining_equations(tmp_path):
    def edit(d):
        d["analysis"]["events"] = ["work_start", "work_end", "max_velocity_working",
                                   "max_velocity_return", "link_vertical:4"]
        d["sheets"]["polygon_positions"] = ["work_start", "work_end"]
    r = _run(tmp_path, "shaper", edit)
    k, p = r["linkage"], r["params"]
    n = k.grid_size
    idle = p.idle_travel_ratio * p.stroke
    start, end = _at(k, k.requested["work_start"]), _at(k, k.requested["work_end"])
    # the ram exactly H·idle from either extreme, inside the working stroke
    assert k.s[start] == pytest.approx(idle, abs=1e-12)
    assert k.s[end] == pytest.approx(p.stroke - idle, abs=1e-12)
    assert 0 < k.phase[start] < k.phase[end] < k.working_span
    assert k.requested["work_start"] == "1'"     # the course's label (BRIEFS: 1′ and 7′)
    # max velocity: a zero of the analytic acceleration, larger than every grid speed
    for code, sign in (("max_velocity_working", 1), ("max_velocity_return", -1)):
        j = _at(k, k.requested[code])
        assert abs(k.a[j]) < 1e-9 * np.max(np.abs(k.a[:n]))
        assert sign * k.v[j] >= np.max(sign * k.v[:n]) - 1e-12
    # the bar vertical: cos θ4 = 0 (it is the crank-vertical special position 4′)
    j = _at(k, k.requested["link_vertical:4"])
    assert abs(math.cos(k.link_angle["4"][j])) < 1e-12
    assert r["linkage_polygons"].positions == (k.requested["work_start"], k.requested["work_end"])


def test_named_point_velocities_are_derivatives_of_their_positions(tmp_path):
    def edit(d):
        d["analysis"]["points"] = ["C", "E", "S3"]
    r = _run(tmp_path, "linkage_sixbar", edit)
    k, model = r["linkage"], r["params"]
    n = k.grid_size
    dt = (2 * math.pi / n) / abs(model.crank_omega)
    for name in ("C", "E", "S3"):
        x, v, a = k.points[name][:n], k.point_vel[name][:n], k.point_acc[name][:n]
        fd_v = (np.roll(x, -1) - np.roll(x, 1)) / (2 * dt)
        fd_a = (np.roll(v, -1) - np.roll(v, 1)) / (2 * dt)
        assert np.max(np.abs(fd_v - v)) < 1e-4 * np.max(np.abs(v))
        assert np.max(np.abs(fd_a - a)) < 1e-4 * np.max(np.abs(a))
    from mechdesign.stages.linkage import requests_document

    doc = requests_document(k)
    e = next(p for p in doc.points if p.name == "E")
    j = list(k.positions.labels).index("4")
    assert e.positions[j].velocity == pytest.approx(abs(k.point_vel["E"][n + j]), rel=1e-15)
    # E slides on a horizontal guide: its velocity is along ±x
    assert math.sin(e.positions[j].velocity_direction) == pytest.approx(0.0, abs=1e-12)


def test_unknown_point_is_a_brief_error_naming_field_value_and_points(tmp_path):
    from mechdesign.brief.loader import load_brief

    data = yaml.safe_load((DESIGNS / "linkage_sixbar.yaml").read_text(encoding="utf-8"))
    data["analysis"]["points"] = ["E", "Q"]
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    with pytest.raises(Exception) as exc:
        load_brief(path)
    text = str(exc.value)
    assert "analysis.points" in text.replace("'points', 1", "points") or "points" in text
    assert "'Q'" in text and "O2" in text and "S4" in text
    # a machine whose points come from its model: a design error at run time
    from mechdesign.core.errors import DesignError

    with pytest.raises(DesignError, match=r"analysis\.points: 'Q' .*B, F"):
        _run(tmp_path, "shaper", lambda d: d["analysis"].update(points=["Q"]))


def test_reversed_crank_is_a_named_finding(tmp_path):
    """The six-bar with its crank turned the other way: the working stroke (E moving right)
    becomes the fast one, K < 1 and θ = 180°(K − 1)/(K + 1) < 0."""
    r = _run(tmp_path, "linkage_sixbar",
             lambda d: d["linkage"]["crank"].update(rotation="ccw"))
    k, v = r["linkage"], r["linkage_verification"]
    assert k.time_ratio < 1
    found = [w for w in v.warnings if w.code == "crank_sense_reversed"]
    assert len(found) == 1 and found[0].field == "linkage.crank.rotation"
    assert "rotation to cw" in found[0].en and "θ = -" in found[0].en
    # the brief as written (cw) has no such finding
    ok = _run(tmp_path, "linkage_sixbar", lambda d: None)["linkage_verification"]
    assert not [w for w in ok.warnings if w.code == "crank_sense_reversed"]


@pytest.mark.parametrize("example, chosen", [("furnace_pusher", [3, 9]), ("die_cutter", [2, 8]),
                                             ("lockbeam", [3, "5"])])
def test_every_linkage_machine_lets_the_brief_choose_the_polygon_positions(example, chosen):
    """The furnace pusher, the die-cutter press and the lock-beam feed take a `sheets` section
    too: the A1 sheet's polygons are drawn at the positions the brief chooses."""
    from mechdesign.brief.loader import parse_brief, read_brief_data
    from mechdesign.machines import get_machine, stages_for
    from mechdesign.pipeline import run_stages

    data = read_brief_data(DESIGNS / f"{example}.yaml")
    data.pop("groups", None)
    data["sheets"] = {"polygon_positions": chosen}
    b = parse_brief(data)
    m = get_machine(b.machine)
    p = m.to_params(b)
    r, _ = run_stages(stages_for(m, p), {"params": p, "brief": b, "checked": {}})
    (key,) = [k for k in r if k.endswith("_polygons")]
    assert list(r[key].positions) == [str(c) for c in chosen]
