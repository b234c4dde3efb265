"""Issue 18, point 1 for the guide-bar machines (shaper, slotter): the link-length form of
the brief, masses or weights, the shaper's y_S6, optional gear/cam/drive sections, and the
errors of point 7 (crank ≥ frame, a guide bar shorter than the crank pin's reach, an
impossible flywheel rim) — each at its field, exit 2, no traceback.

References (independent of the program):
- the guide-bar quick-return mechanism's closed forms (孙桓《机械原理》第 8 版 §8-3, 导杆机构的
  急回特性): at both extremes the crank is perpendicular to the bar, so
  sin(ψ/2) = L_O2A/L_O2O3, θ = ψ, K = (180° + θ)/(180° − θ), H = 2·L_O3B·sin(ψ/2);
- the analytic kinematics of the RPR (guide-bar) group (孙桓 §3-4, the closed-vector
  method): tan φ4 = (L_O2O3 + L_O2A sin φ2)/(L_O2A cos φ2), differentiated by hand below;
- the principle of virtual work: a force on a translating body does the same work wherever
  it acts on the body, so moving the ram's centre of mass across its guide cannot change
  the balancing torque; it changes only the guide's couple on the ram, by the inertia force
  times the offset (moment balance of the ram).
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.brief.loader import load_variant
from mechdesign.cli import app
from mechdesign.machines import get_machine, stages_for
from mechdesign.pipeline import run_stages

ROOT = Path(__file__).resolve().parents[1]
LENGTHS = ROOT / "designs" / "shaper_lengths.yaml"
runner = CliRunner()


def _data(path: Path) -> dict:
    data = yaml.safe_load(path.read_text(encoding="utf-8"))
    fw = data.get("flywheel", {})
    if isinstance(fw.get("specific_weight_N_m3"), str):     # safe_load reads 7.0e4 as text
        fw["specific_weight_N_m3"] = float(fw["specific_weight_N_m3"])
    return data


def _write(tmp_path: Path, data: dict, name: str = "brief.yaml") -> Path:
    path = tmp_path / name
    path.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    return path


def _run(path: Path, group=None):
    v = load_variant(path, group)
    m = get_machine(v.brief.machine)
    p = m.to_params(v.brief)
    r, _ = run_stages(stages_for(m, p), {"params": p, "brief": v.brief})
    return p, r, m.document(r)


def _group_I(tmp_path: Path) -> dict:
    data = _data(LENGTHS)
    data.pop("groups")
    return data


# --------------------------------------------------------------- closed form of the lengths

def test_lengths_give_H_K_theta_psi_in_closed_form_and_keep_the_lengths(tmp_path):
    p, r, doc = _run(LENGTHS, "I")
    d, r2, bar = 350.0, 90.0, 580.0                 # the table: L_O2O4, L_O2A, L_O4B [mm]
    theta = 2.0 * math.asin(r2 / d)                  # = ψ
    K = (math.pi + theta) / (math.pi - theta)        # (180° + θ)/(180° − θ)
    H = 2.0 * bar * math.sin(theta / 2.0)            # = 2·L_O3B·L_O2A/L_O2O3
    syn = doc.synthesis
    assert syn.given_dimensions is True
    assert syn.extreme_angle == pytest.approx(theta, rel=1e-14)
    assert syn.swing_angle == pytest.approx(theta, rel=1e-14)
    assert syn.time_ratio == pytest.approx(K, rel=1e-14)
    assert syn.stroke == pytest.approx(H * 1e-3, rel=1e-14)
    assert math.degrees(theta) == pytest.approx(29.8012, abs=1e-4)     # issue 18: K = 1.3968…
    assert K == pytest.approx(1.3968, abs=1e-4) and H == pytest.approx(298.29, abs=0.01)
    # the lengths are the table's, exactly (never rounded through K)
    assert syn.crank == 90e-3 and syn.guide_bar == 580e-3
    assert syn.rod == pytest.approx(0.3 * 0.58, rel=1e-15)
    # the guide by the mid-sagitta rule: L_O3M = L_O3B (1 + cos(ψ/2))/2
    assert syn.guide_height == pytest.approx(0.58 * (1 + math.cos(theta / 2)) / 2, rel=1e-14)
    # the simulation agrees: the stroke and the time ratio of the simulated extremes
    v = doc.verification
    assert abs(v.stroke_error) < 1e-9
    assert v.time_ratio_simulated == pytest.approx(K, rel=1e-9)
    # the report shows the table's lengths as given and the derived H, K
    from mechdesign.render.guide_bar_report import guide_bar_context
    gb = guide_bar_context(r["synthesis"], p)
    rows = {row[0]: row[2] for row in gb["rows"]}
    assert rows["$L_{O_2A}$"] == "90" and rows["$L_{O_3B}$"] == "580"
    assert gb["given"] and "arcsin" in gb["eq"]["theta"] and "bar" not in gb["eq"]


def _same(a, b, rel=1e-9):
    a, b = np.asarray(a, float), np.asarray(b, float)
    scale = max(np.max(np.abs(a)), 1e-300)
    assert np.max(np.abs(a - b)) <= rel * scale


def _compare(doc_a, doc_b):
    for pa, pb in zip(doc_a.positions, doc_b.positions, strict=True):
        assert pa.label == pb.label
    for key in ("ram_s", "ram_v", "ram_a", "omega4", "alpha4", "balancing_torque"):
        _same([getattr(q, key) for q in doc_a.positions], [getattr(q, key) for q in doc_b.positions])
    _same(doc_a.grid.balancing_torque, doc_b.grid.balancing_torque)
    assert doc_a.flywheel.inertia == pytest.approx(doc_b.flywheel.inertia, rel=1e-9)
    for key in ("crank", "guide_bar", "rod", "guide_height", "extreme_angle"):
        assert getattr(doc_a.synthesis, key) == pytest.approx(getattr(doc_b.synthesis, key), rel=1e-12)


def test_round_trip_H_K_brief_and_lengths_brief_of_the_same_shaper(tmp_path):
    # designs/shaper.yaml: H = 320, K = 1.2, L_O2O3 = 650 → the lengths by hand
    data = _data(ROOT / "designs" / "shaper.yaml")
    data.pop("groups")
    hk = _write(tmp_path, data, "hk.yaml")
    theta = math.pi * (1.2 - 1) / (1.2 + 1)
    lk = data["linkage"]
    del lk["stroke_H_mm"], lk["time_ratio_K"]
    lk["crank_O2A_mm"] = 650 * math.sin(theta / 2)
    lk["guide_bar_O3B_mm"] = 320 / (2 * math.sin(theta / 2))
    lengths = _write(tmp_path, data, "lengths.yaml")
    _, _, a = _run(hk)
    _, _, b = _run(lengths)
    assert a.synthesis.given_dimensions is False and b.synthesis.given_dimensions is True
    assert b.synthesis.time_ratio == pytest.approx(1.2, rel=1e-12)
    assert b.synthesis.stroke == pytest.approx(0.32, rel=1e-12)
    _compare(a, b)


def test_round_trip_lengths_group_to_H_K(tmp_path):
    data = _group_I(tmp_path)
    lk = data["linkage"]
    theta = 2 * math.asin(90 / 350)
    del lk["crank_O2A_mm"], lk["guide_bar_O3B_mm"]
    lk["stroke_H_mm"] = 2 * 580 * 90 / 350
    lk["time_ratio_K"] = (math.pi + theta) / (math.pi - theta)
    _, _, a = _run(_write(tmp_path, data))
    _, _, b = _run(LENGTHS, "I")
    _compare(a, b)


def test_slotter_takes_the_same_forms(tmp_path):
    """The slotter shares the brief: lengths, weights, no gear pair/cam/drive."""
    data = _data(ROOT / "designs" / "slotter.yaml")
    data.pop("groups", None)
    hk = _write(tmp_path, data, "hk.yaml")
    lk = data["linkage"]
    H, K, d = lk.pop("stroke_H_mm"), lk.pop("time_ratio_K"), lk["frame_O2O3_mm"]
    theta = math.pi * (K - 1) / (K + 1)
    lk["crank_O2A_mm"] = d * math.sin(theta / 2)
    lk["guide_bar_O3B_mm"] = H / (2 * math.sin(theta / 2))
    _, _, a = _run(hk)
    _, _, b = _run(_write(tmp_path, data, "lengths.yaml"))
    for key in ("s", "v", "a", "balancing_torque"):
        _same(getattr(a.linkage.grid, key), getattr(b.linkage.grid, key))
    assert a.flywheel.inertia == pytest.approx(b.flywheel.inertia, rel=1e-9)
    assert b.synthesis.time_ratio == pytest.approx(K, rel=1e-12)
    # without gear pair, cam and drive: the flywheel on the crank, no such results
    for key in ("gear_pair", "cam", "drive"):
        data.pop(key)
    data["flywheel"].pop("shaft")
    data["masses"]["ram_G6_N"] = data["masses"].pop("ram_m6_kg") * data["analysis"].get("gravity", 9.81)
    _, r, c = _run(_write(tmp_path, data, "bare.yaml"))
    assert c.gear is None and c.cam is None and c.drive is None
    assert c.flywheel.shaft == "crank" and c.flywheel.speed_ratio == 1.0


# ------------------------------------------------------------- position 4 by hand (group I)

def test_position_4_ram_s_v_a_by_hand():
    """Group I of shaper_lengths (n2 = 64 rpm clockwise, L_O2O3 = 350, L_O2A = 90,
    L_O3B = 580, L_BF = 0.3 L_O3B mm). O3 at the origin, O2 at (0, d); angles CCW from +x.
    Position 1 is the left extreme: the crank perpendicular to the bar leaning left,
    φ2 = 180° + ψ/2; the crank turns clockwise, so position 4 is φ2 = 180° + ψ/2 − 90°."""
    _, _, doc = _run(LENGTHS, "I")
    d, r, L = 0.350, 0.090, 0.580
    l = 0.3 * L
    w2 = -64 * 2 * math.pi / 60                          # clockwise: ω2 < 0
    half = math.asin(r / d)
    h = L * (1 + math.cos(half)) / 2                     # guide line through the sagitta's mid-point

    def ram_x(phi2):
        """x of F (to the left of B) and the bar angle."""
        phi4 = math.atan2(d + r * math.sin(phi2), r * math.cos(phi2))
        yB = L * math.sin(phi4)
        return L * math.cos(phi4) - math.sqrt(l**2 - (h - yB) ** 2), phi4

    phi2 = math.pi + half - math.pi / 2                  # position 4
    x1, _ = ram_x(math.pi + half)                        # position 1
    x4, phi4 = ram_x(phi2)
    S2 = d**2 + r**2 + 2 * d * r * math.sin(phi2)        # |O3A|²
    # d/dt atan2(y, x) = (x ẏ − y ẋ)/S²  with x = r cos φ2, y = d + r sin φ2:
    w4 = w2 * r * (r + d * math.sin(phi2)) / S2          # = ω2 r cos(φ2 − φ4)/S (textbook form)
    assert w4 == pytest.approx(w2 * r * math.cos(phi2 - phi4) / math.sqrt(S2), rel=1e-12)
    # α4 = dω4/dt at constant ω2, with dS²/dφ2 = 2 d r cos φ2:
    a4 = w2**2 * r * d * math.cos(phi2) * (S2 - 2 * r * (r + d * math.sin(phi2))) / S2**2
    # B and F: x_F = x_B − c, c² = l² − (h − y_B)²
    xB_d = -L * math.sin(phi4) * w4
    yB_d = L * math.cos(phi4) * w4
    xB_dd = -L * math.cos(phi4) * w4**2 - L * math.sin(phi4) * a4
    yB_dd = -L * math.sin(phi4) * w4**2 + L * math.cos(phi4) * a4
    yB = L * math.sin(phi4)
    c = math.sqrt(l**2 - (h - yB) ** 2)
    c_d = (h - yB) * yB_d / c
    c_dd = ((h - yB) * yB_dd - yB_d**2 - c_d**2) / c
    s, v, a = x4 - x1, xB_d - c_d, xB_dd - c_dd          # the working stroke runs towards +x
    pos = {q.label: q for q in doc.positions}["4"]
    assert pos.crank_angle == pytest.approx(phi2 % (2 * math.pi), rel=1e-12)
    assert pos.ram_s == pytest.approx(s, rel=1e-9)
    assert pos.ram_v == pytest.approx(v, rel=1e-9)
    assert pos.ram_a == pytest.approx(a, rel=1e-9)
    assert pos.omega4 == pytest.approx(w4, rel=1e-9)
    assert pos.alpha4 == pytest.approx(a4, rel=1e-9)


# ---------------------------------------------------------------- loads: weights, y_S6

def test_weights_and_masses_give_the_same_shaper(tmp_path):
    data = _group_I(tmp_path)
    g = data["analysis"]["gravity"]
    _, _, a = _run(_write(tmp_path, data, "weights.yaml"))
    ms = data["masses"]
    ms["guide_bar_m4_kg"] = ms.pop("guide_bar_G4_N") / g
    ms["ram_m6_kg"] = ms.pop("ram_G6_N") / g
    _, _, b = _run(_write(tmp_path, data, "masses.yaml"))
    _compare(a, b)
    for qa, qb in zip(a.positions, b.positions):
        assert qa.inertia_force6 == pytest.approx(qb.inertia_force6, rel=1e-12, abs=1e-12)


def test_y_S6_moves_the_ram_inertia_line_not_the_balancing_torque(tmp_path):
    data = _group_I(tmp_path)
    dy = data["linkage"]["ram_com_y_S6_mm"] * 1e-3
    assert dy == 0.05
    _, ra, a = _run(_write(tmp_path, data, "y50.yaml"))
    data["linkage"]["ram_com_y_S6_mm"] = 0
    _, rb, b = _run(_write(tmp_path, data, "y0.yaml"))
    # virtual work: the ram translates, so where its inertia force acts does not change M_b
    _same([q.balancing_torque for q in a.positions], [q.balancing_torque for q in b.positions],
          rel=1e-12)
    # moment balance of the ram: the guide's couple on it changes by the inertia force's
    # extra moment, ΔM76 = Δy·P_I6 (P_I6 horizontal, raised by Δy: its moment −Δy·P_I6)
    fa, fb = ra["forces"], rb["forces"]
    n = ra["kinematics"].grid_size
    p_i6 = fa.inertia_force6
    m6 = 800 / 9.81
    _same(p_i6, -m6 * ra["kinematics"].ram_a * ra["kinematics"].stroke_direction, rel=1e-12)
    delta = fa.couples["R76"] - fb.couples["R76"]
    _same(delta[:n], dy * p_i6[:n], rel=1e-9)
    assert np.max(np.abs(delta)) > 1.0                  # it does change (a real offset)


# ------------------------------------------------------------ optional sections, rendering

@pytest.mark.e2e
def test_brief_without_gear_cam_drive_renders(tmp_path):
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(LENGTHS), "--out", str(out), "--format", "md,dxf",
                                 "--lang", "en"])
    assert result.exit_code == 0, result.output
    md = (out / "report.md").read_text(encoding="utf-8")
    assert "# Linkage synthesis" in md and "given dimensions → derived $H$, $K$" in md
    for heading in ("# Gear", "# Cam", "# Drive", "gear z2", "z_1, z_2"):
        assert heading not in md
    import json
    doc = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert doc["gear"] is None and doc["cam"] is None and doc["drive"] is None
    assert doc["synthesis"]["crank"] == 0.09 and doc["synthesis"]["guide_bar"] == 0.58
    sheets = sorted(p.name for p in (out / "sheets").iterdir())
    assert sheets == ["analysis_A1.dxf", "kinematic_A3.dxf"]   # no cam, gear or drive sheet


# --------------------------------------------------------------------- errors at the field

def _edit_I(tmp_path, edit) -> Path:
    data = _group_I(tmp_path)
    edit(data)
    return _write(tmp_path, data, "bad.yaml")


def _hk_100(d):
    lk = d["linkage"]
    del lk["crank_O2A_mm"], lk["guide_bar_O3B_mm"]
    lk.update(stroke_H_mm=100, time_ratio_K=1.2, frame_O2O3_mm=650)


CASES = {
    "crank_ge_frame": (lambda d: d["linkage"].update(crank_O2A_mm=350),
                       "linkage.crank_O2A_mm: 350", "shorter than the frame"),
    "bar_too_short": (lambda d: d["linkage"].update(guide_bar_O3B_mm=430),
                      "linkage.guide_bar_O3B_mm: 430", "lengthen the bar to at least 440 mm"),
    "H_too_small": (_hk_100, "linkage.stroke_H_mm: 100", "crank pin's reach"),
    "both_forms": (lambda d: d["linkage"].update(stroke_H_mm=300, time_ratio_K=1.4),
                   "linkage.crank_O2A_mm: 90", "not both"),
    "half_form": (lambda d: d["linkage"].pop("guide_bar_O3B_mm"),
                  "linkage.guide_bar_O3B_mm: missing", "needed with crank_O2A_mm"),
    "mass_and_weight": (lambda d: d["masses"].update(ram_m6_kg=80),
                        "masses.ram_G6_N: 800", "not both"),
    "no_mass": (lambda d: d["masses"].pop("guide_bar_G4_N"),
                "masses.guide_bar_m4_kg: missing", "guide_bar_G4_N"),
    "rod_twice": (lambda d: d["linkage"].update(rod_BF_mm=174),
                  "linkage.rod_ratio_BF_O3B: 0.3", "exactly one"),
    "guide_unreachable": (lambda d: d["linkage"].update(guide_O3M_mm=300),
                          "linkage.guide_O3M_mm: 300", "cannot reach"),
    "pinion_without_gears": (lambda d: d["flywheel"].update(shaft="pinion"),
                             "flywheel.shaft: 'pinion'", "gear_pair"),
    "rim_0.001mm": (lambda d: d["flywheel"].update(rim_diameter_mm=0.001),
                    "flywheel.rim_diameter_mm = 0.001", "no rim of this diameter"),
    "1e-9_rpm": (lambda d: d["linkage"].update(crank_speed_n2_rpm=1e-9),
                 "flywheel.rim_diameter_mm = 1000", "crank speed n = 1e-09 rpm"),
}


@pytest.mark.parametrize("name", list(CASES))
def test_every_new_error_names_its_field_exit_2(tmp_path, name):
    edit, field, words = CASES[name]
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(_edit_I(tmp_path, edit)), "--out", str(out),
                                 "--format", "md", "--lang", "en"])
    assert result.exit_code == 2, result.output
    assert field in result.output and words in result.output, result.output
    assert "Traceback" not in result.output
    assert not (out / "report.md").exists()
    zh = runner.invoke(app, ["run", str(_edit_I(tmp_path, edit)), "--out", str(out),
                             "--format", "md", "--lang", "zh"])
    assert zh.exit_code == 2 and field.split(":")[0].split(" =")[0] in zh.output
    assert any("\u4e00" <= ch <= "\u9fff" for ch in zh.output)


def test_impossible_rim_bound_is_where_H_equals_D_over_2():
    """The smallest rim diameter the error proposes gives H = D/2 (by the rim formula)."""
    from mechdesign.core.flywheel import rim_dimensions
    from mechdesign.stages.flywheel import smallest_rim_diameter

    J, k, gamma, g = 204.0, 1.5, 7.0e4, 9.81
    D = smallest_rim_diameter(J, k, gamma, g)
    rim = rim_dimensions(J, D, k, gamma, 64.0, g)
    assert rim.height == pytest.approx(D / 2, rel=1e-12)
    # and by hand: H = √(4 g J k/(π D³ γ)) = D/2  ⇔  D⁵ = 16 g J k/(π γ)
    assert D == pytest.approx((16 * g * J * k / (math.pi * gamma)) ** 0.2, rel=1e-14)


@pytest.mark.parametrize("name", ["shaper", "slotter", "shaper_lengths"])
def test_link_table_writes_theta_and_K_with_the_texts_digits(example_results, name):
    """Review 34: the link table printed θ = ψ to 0.001° or 0.0001° (``16.364``,
    ``29.8012``) and K to 0.0001 (``1.3968``) beside the text's 16.36°, 29.80° and 1.397:
    one value, written once by the rule (render/fmt.py: angles to 0.01°, K to 0.001)."""
    import re

    from tests.test_report_prose import _markdown

    md, _ = _markdown(example_results, name, "en")
    text_theta = re.search(r"\$\$ \\theta = [^$]*= (\d+\.\d+)° \$\$", md).group(1)
    row = re.search(r"^\| \$\\theta = \\psi\$ \|[^|]*\| ([^|]*) \|", md, re.M)
    assert row.group(1).strip() == text_theta
    table = md[row.start():].split("\n\n")[0]          # the link table, from its θ row on
    k_cell = re.search(r"^\| \$K\$ \|[^|]*\| ([^|]*) \|", table, re.M)
    if k_cell:                                  # the lengths form lists K among the links
        text_k = re.search(r"\$\$ K = \\frac[^$]*= (\d+\.\d+) \$\$", md).group(1)
        assert k_cell.group(1).strip() == text_k
        assert len(text_k.partition(".")[2]) == 3
