"""Infeasible and poor designs are diagnosed by name, with their numbers, in zh and en.

Each test takes an example brief from designs/ (or a small brief written here), changes one
field and checks the diagnosis: the error class (infeasible: exit 2) or the finding code
(computable but poor), that the Chinese and English texts name the problem, that they give
the numbers (checked against hand computations written out here) and the brief field to
change. References (孙桓《机械原理》): Grashof's crank condition (§8-2: the shortest link plus
the longest ≤ the other two, the crank or the frame shortest); the slider-crank's crank turns
iff rod ≥ crank + offset; the offset slider-crank from K, H, e exists iff e < H·cot θ,
θ = 180°(K − 1)/(K + 1); the transmission angle of a four-bar at the crank–frame collinear
positions cos δ = (b² + c² − (d ∓ a)²)/(2bc); the translating roller follower's pressure angle
tan α = |ds/dδ − e|/(s0 + s), s0 = √(r0² − e²); the standard spur gear's z_min = 2h_a*/sin²α
and x_min = h_a*(z_min − z)/z_min.
"""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from mechdesign.brief.loader import (BriefError, FeasibilityError, Variant, parse_brief,
                                     read_brief_data)
from mechdesign.core.cam import CamDesignError
from mechdesign.core.cycle import CycleError
from mechdesign.core.drive import DriveDesignError
from mechdesign.core.errors import DesignError
from mechdesign.core.fourbar import SynthesisError
from mechdesign.core.intermittent import IntermittentDesignError
from mechdesign.core.mechanism import AssemblyError
from mechdesign.machines import get_machine, stages_for
from mechdesign.pipeline import run_stages
from mechdesign.runner import describe_design_error, feasibility

DESIGNS = Path(__file__).resolve().parents[1] / "designs"
REPORT = {"title": "t", "student": "s"}
CJK = re.compile(r"[\u4e00-\u9fff]")


def example(name: str) -> dict:
    """An example brief as data (its groups table dropped: the brief as written)."""
    data = read_brief_data(DESIGNS / name)
    data.pop("groups", None)
    return data


def run(data: dict, stop_after: str | None = None) -> dict:
    """Validate and compute (no rendering); ``stop_after`` ends after that stage key."""
    b = parse_brief(data)
    m = get_machine(b.machine)
    p = m.to_params(b)
    stages = stages_for(m, p)
    if stop_after is not None:
        keys = [(s.key,) if isinstance(s.key, str) else s.key for s in stages]
        stages = stages[:next(i for i, k in enumerate(keys) if stop_after in k) + 1]
    return run_stages(stages, {"params": p, "brief": b})[0]


def findings(results: dict) -> list:
    return [f for v in results.values() for f in (getattr(v, "warnings", None) or ())]


def brief_error(data: dict) -> BriefError:
    with pytest.raises(BriefError) as info:
        parse_brief(data, "x.yaml")
    return info.value


def infeasible(data: dict) -> FeasibilityError:
    """A valid brief whose data admit no design: validation accepts it (it runs no
    synthesis), the run's feasibility checks (once, after validation) report it."""
    b = parse_brief(data, "x.yaml")
    m = get_machine(b.machine)
    problems, _ = feasibility(m, m.to_params(b), Variant(b, None, ()))
    assert problems
    return FeasibilityError("x.yaml", problems)


def both(exc_or_finding, names: tuple[str, ...] = ()) -> tuple[str, str]:
    """The Chinese and English texts; the English one has no Chinese but the user's own
    names (quoted group names, or ``names``)."""
    zh, en = exc_or_finding.text("zh"), exc_or_finding.text("en")
    assert CJK.search(zh), zh
    bare = re.sub(r"'[^']*'", "", en)
    for n in names:
        bare = bare.replace(n, "")
    assert not CJK.search(bare), en
    return zh, en


def number(x: float, digits: int = 6) -> str:
    return f"{x:.{digits}g}"


# ------------------------------------------------------------------------- the base class

def test_every_design_error_is_bilingual():
    for cls in (AssemblyError, CamDesignError, DriveDesignError, SynthesisError, CycleError,
                IntermittentDesignError):
        assert issubclass(cls, DesignError) and issubclass(cls, ValueError)
    e = SynthesisError("no solution", "无实解")
    assert str(e) == "no solution" and e.text("zh") == "无实解" and e.text("en") == "no solution"
    assert SynthesisError("only English").text("zh") == "only English"
    zh = describe_design_error(e, "zh")
    assert zh.startswith("按任务书数据连杆机构无法综合") and "无实解" in zh
    assert "cannot be synthesised" in describe_design_error(e, "en")
    assert describe_design_error(ValueError("x"), "en") is None
    # batch workers may pass errors between processes: both texts survive pickling
    import pickle

    back = pickle.loads(pickle.dumps(e))
    assert type(back) is SynthesisError and back.text("zh") == "无实解" and str(back) == "no solution"


# ------------------------------------------------------------- Grashof: linkage machine

def test_grashof_four_bar_in_a_linkage_brief():
    """Sixbar example with the rocker group shortened to BC = 200, DC = 150 (crank 100, frame
    400): 100 + 400 = 500 > 150 + 200 = 350. The crank is first stopped where
    |AO4|² = a² + d² − 2ad cos φ exceeds (b + c)²: cos φ < (170000 − 122500)/80000."""
    data = example("linkage_sixbar.yaml")
    data["linkage"]["groups"][0]["lengths_mm"] = [200, 150]
    with pytest.raises(AssemblyError) as info:
        run(data, stop_after="linkage")
    err = info.value
    assert err.code == "grashof"
    a, b, c, d = 100, 200, 150, 400
    s_l, p_q = min(a, b, c, d) + max(a, b, c, d), sorted([a, b, c, d])[1] + sorted([a, b, c, d])[2]
    assert (s_l, p_q) == (500, 350)
    limit = math.degrees(math.acos((a * a + d * d - (b + c) ** 2) / (2 * a * d)))
    assert limit < err.crank_angle_deg < limit + 0.1 + 1e-9   # 0.1° grid of the motion stage
    zh, en = both(err)
    assert "曲柄不能整周转动" in zh and "Grashof" in zh and f"= {s_l} mm > " in zh
    assert f"{p_q} mm" in zh and f"{err.crank_angle_deg:.2f}°" in zh
    assert "the crank cannot make a full turn (Grashof)" in en and f"= {s_l} mm > " in en
    # what to change: coupler + rocker ≥ a + d, i.e. 150 mm longer in total
    assert f"a + d = {a + d} mm" in en and f"by {a + d - b - c} mm in total" in en
    assert f"共加长 {a + d - b - c} mm" in zh
    for text in (zh, en):
        assert "linkage.groups[0].lengths_mm" in text and "linkage.crank.length_mm" in text
    import pickle

    back = pickle.loads(pickle.dumps(err))
    assert (back.code, back.group, back.count, back.text("zh"), str(back)) == \
        (err.code, err.group, err.count, zh, en)


def test_grashof_shortest_link_not_the_crank():
    """Four-bar a = 80, b = 30, c = 90, d = 100: 30 + 100 = 130 ≤ 170 holds but the coupler is
    the shortest: |b − c| = 60 > |d − a| = 20 stops the crank (change the rocker by 40 mm)."""
    data = {"machine": "linkage", "report": REPORT, "linkage": {
        "frame_points_mm": {"A0": [0, 0], "D": [100, 0]},
        "crank": {"pivot": "A0", "tip": "A", "length_mm": 80, "speed_rpm": 60},
        "groups": [{"type": "RRR", "links": [3, 4], "ends": ["A", "D"], "joint": "B",
                    "lengths_mm": [30, 90]}],
        "output": {"link": 4}}}
    with pytest.raises(AssemblyError) as info:
        run(data, stop_after="linkage")
    zh, en = both(info.value)
    assert info.value.code == "grashof"
    assert "shortest link is the coupler" in en and "最短杆是连杆" in zh
    assert "130 mm ≤" in en and "170 mm" in en
    assert "|b − c| = 60 mm at most |d − a| = 20 mm" in en and "shorten the rocker by 40 mm" in en
    assert "将摇杆缩短 40 mm" in zh


def test_slider_crank_crank_cannot_turn():
    """Slider-crank, crank 100, rod 80, offset 30: the rod must be ≥ a + e = 130 mm."""
    data = {"machine": "linkage", "report": REPORT, "linkage": {
        "frame_points_mm": {"O": [0, 0]},
        "crank": {"pivot": "O", "tip": "A", "length_mm": 100, "speed_rpm": 60},
        "groups": [{"type": "RRP", "links": [3, 4], "end": "A", "joint": "C", "length_mm": 80,
                    "guide_point_mm": [0, 30], "guide_angle_deg": 0}],
        "output": {"point": "C"}}}
    with pytest.raises(AssemblyError) as info:
        run(data, stop_after="linkage")
    err = info.value
    assert err.code == "slider_crank"
    zh, en = both(err)
    assert "曲柄不能整周转动" in zh and "b ≥ a + e = 130 mm" in zh and "至少加长 50 mm" in zh
    assert "the crank cannot make a full turn" in en and "b ≥ a + e = 130 mm" in en
    assert "Lengthen the rod by at least 50 mm" in en
    assert "linkage.groups[0].length_mm" in en and "linkage.groups[0].length_mm" in zh
    # the first crank angle where |y_A − 30| > 80: 100 sin φ < −50 → φ > 210°
    assert 210.0 < err.crank_angle_deg <= 210.1 + 1e-9


# ------------------------------------------------ assembly of a group, with the crank angle

def test_guide_bar_offset_in_the_lockbeam_feed():
    """Lock-beam feed: crank O2A = 50 about O2 = (0, 0), guide bar about O3 = (0, −100); an
    offset of 60 mm exceeds A's least distance from O3, |d − a| = 100 − 50 = 50 mm."""
    data = example("lockbeam.yaml")
    data["feed_linkage"]["groups"][0]["offset_mm"] = 60
    (p,) = infeasible(data).problems
    assert p.path == "feed_linkage.groups"
    for text, words in ((p.allowed, ("guide bar", "offset 60 mm", "|d − a| = 50 mm",
                                     "at most 50 mm", "crank angle")),
                        (p.allowed_zh, ("导杆", "偏距 60 mm", "|d − a| = 50 mm", "50 mm 以内",
                                        "曲柄转角"))):
        for w in words:
            assert w in text, (w, text)
    # A = 50·e^{iφ}: |A − O3|² = 12500 + 10000 sin φ < 60² first at sin φ < −0.89
    first = math.degrees(math.pi + math.asin(0.89))
    angle = float(re.search(r"crank angle ([\d.]+)°", p.allowed).group(1))
    assert first < angle < first + 0.5


def test_shaper_ram_rod_too_short_names_the_ratio():
    """Shaper, K = 1.2, H = 320: ψ = θ = 16.3636°, L_O3B = H/(2 sin(ψ/2)); B is up to
    L_O3B(1 − cos(ψ/2))/2 from the ram guide, so L_BF/L_O3B ≥ (1 − cos(ψ/2))/2."""
    data = example("shaper.yaml")
    data["linkage"]["rod_ratio_BF_O3B"] = 0.004
    with pytest.raises(AssemblyError) as info:
        run(data, stop_after="kinematics")
    half = math.radians(180 * 0.2 / 2.2) / 2
    bar = 320 / (2 * math.sin(half))
    need = (1 - math.cos(half)) / 2
    zh, en = both(info.value)
    assert "cannot be assembled at crank angle" in en and "在曲柄转角" in zh
    assert number(bar * need) + " mm" in en and number(bar * need) + " mm" in zh
    for text in (zh, en):
        assert "linkage.rod_ratio_BF_O3B" in text and number(need) in text


def test_assembly_failure_of_a_later_group():
    """Sixbar with the rod CE = 100 mm (C swings on the rocker, 600 mm from O4): the group
    is diagnosed as a rod that cannot reach its guide, with the field to change."""
    data = example("linkage_sixbar.yaml")
    data["linkage"]["groups"][4]["length_mm"] = 100
    with pytest.raises(AssemblyError) as info:
        run(data, stop_after="linkage")
    err = info.value
    assert err.code == "assembly"
    zh, en = both(err)
    assert "cannot reach the guide" in en and "够不到导路" in zh
    need = err.numbers["max"] * 1e3
    assert need > 100 and f"at least {number(need)} mm" in en
    assert "linkage.groups[4].length_mm" in en and "linkage.groups[4].length_mm" in zh


# ------------------------------------------------------- synthesis with no real solution

def test_offset_slider_crank_without_a_real_solution():
    """K = 1.4 → θ = 30°: e must be below H·cot θ = 100·√3 = 173.205 mm."""
    data = example("crank_rocker.yaml")
    data["slider_crank"]["offset_e_mm"] = 200
    (p,) = infeasible(data).problems
    assert p.path == "slider_crank.offset_e_mm" and p.value == "200"
    limit = number(100 / math.tan(math.radians(30)))
    assert limit == "173.205"
    assert "offset_e_mm = 200" in p.allowed and f"H·cot θ = {limit} mm" in p.allowed
    assert "偏置曲柄滑块机构无实解" in p.allowed_zh and f"H·cot θ = {limit} mm" in p.allowed_zh
    assert "offset_e_mm" in p.allowed_zh


def test_crank_rocker_frame_outside_the_allowed_arc():
    """θ = 15°, ψ = 40°, rocker 50: the crank pivot on the θ-circle's allowed arc gives frames
    from the rocker length 50 mm (A at C1's end of the arc: AD = DC1) upwards."""
    data = example("crank_rocker.yaml")
    data["frame_length_mm"] = 20
    (p,) = infeasible(data).problems
    assert p.path == "frame_length_mm" and p.value == "20"
    assert "frame_length_mm = 20" in p.allowed and "between 50 and" in p.allowed
    assert "机架长度 20 mm 无法实现" in p.allowed_zh and "介于 50 与" in p.allowed_zh


def test_crank_rocker_every_problem_at_its_field():
    """A frame off the allowed arc, an offset slider-crank without a real solution and a
    compared design that is no crank-rocker (l1 = 60 > the other links' Grashof limit) are
    all reported at once, each at its own field, in both languages."""
    data = example("crank_rocker.yaml")
    data["frame_length_mm"] = 20
    data["slider_crank"]["offset_e_mm"] = 200
    data["compare"][0]["crank_mm"] = 60
    probs = {p.path: p for p in infeasible(data).problems}
    assert set(probs) == {"frame_length_mm", "slider_crank.offset_e_mm", "compare.0"}
    assert "not a crank-rocker" in probs["compare.0"].allowed
    assert "不是曲柄摇杆机构" in probs["compare.0"].allowed_zh


def test_furnace_stroke_beyond_the_rocker_chord():
    """H = 2400 mm cannot be a chord of C's arc with DC = 1150 mm: 2·DC = 2300 mm."""
    data = example("furnace_pusher.yaml")
    data["pusher"]["stroke_H_mm"] = 2400
    (p,) = infeasible(data).problems
    assert "2·DC = 2300 mm" in p.allowed and "2·DC = 2300 mm" in p.allowed_zh
    assert "pusher.rocker_DC_mm" in p.allowed_zh and "要求摇杆 DC 长于 H/2" in p.allowed_zh


def test_lockbeam_bending_synthesis_without_a_solution():
    data = example("lockbeam.yaml")
    data["bending"]["link_length_range_mm"] = [20, 30]
    (p,) = infeasible(data).problems
    assert p.path == "bending.start"
    assert "widen the length range" in p.allowed and "20 and 30 mm" in p.allowed
    assert "综合无实解" in p.allowed_zh and "应放宽杆长范围" in p.allowed_zh
    assert "输出摇杆反向转动时" in p.allowed_zh and "输出摇杆同向转动时" in p.allowed_zh


def test_cam_offset_not_below_the_base_radius():
    data = example("cam_7_3.yaml")
    data["cam"]["base_radius_mm"] = 10
    # a roller below r0 (r_r ≥ r0 is refused by validation since issue 21), so that the
    # offset is what fails
    data["cam"]["follower"]["roller_radius_mm"] = 4
    with pytest.raises(CamDesignError) as info:
        run(data)
    zh, en = both(info.value)
    assert "|e| = 12 mm" in en and "r0 = 10 mm" in en and "increase the base radius" in en
    assert "偏距 |e| = 12 mm" in zh and "应增大基圆半径" in zh


# ------------------------------------------------ pressure and transmission angle findings

def test_transmission_angle_below_the_limit_in_a_linkage():
    """Sixbar four-bar a = 100, b = 400, c = 300, d = 400: cos δ' = (b² + c² − (d − a)²)/(2bc)
    = 2/3, cos δ'' = (b² + c² − (d + a)²)/(2bc) = 0 → γmin = arccos(2/3) = 48.19° < 60°."""
    data = example("linkage_sixbar.yaml")
    data["linkage"]["transmission_angle_min_deg"] = 60
    found = [f for f in findings(run(data)) if f.code == "transmission_angle"]
    (f,) = found
    gmin = math.degrees(math.acos(2 / 3))
    zh, en = both(f, ("摇杆 O4B",))
    assert f"{gmin:.2f}°" in zh and f"{gmin:.2f}°" in en and "60.0°" in en
    assert "b² + c² close to a² + d²" in en and "250000 and 170000 mm²" in en
    assert "linkage.crank.length_mm" in en and "linkage.crank.length_mm" in zh


def test_pressure_angle_of_the_offset_slider_crank():
    """Offset slider-crank from K = 1.4, H = 100, e = 150: its largest pressure angle,
    asin((a + e)/b) at the crank perpendicular to the guide, exceeds 90° − [γ] = 50°."""
    data = example("crank_rocker.yaml")
    data["slider_crank"]["offset_e_mm"] = 150
    r = run(data, stop_after="slider")
    s = r["slider"]
    (f,) = [f for f in s.warnings if f.code == "pressure_angle"]
    zh, en = both(f)
    shown = float(re.search(r"([\d.]+)°, exceeds", en).group(1))
    worst = math.degrees(math.asin((s.crank + s.offset) / s.rod))
    assert 50 < shown <= worst + 0.005
    assert "slider_crank.offset_e_mm" in en and "slider_crank.offset_e_mm" in zh


def test_cam_pressure_angle_finding():
    """Exercise 7-3 with r0 = 20 mm: at δ = 0 (cycloidal rise, ds/dδ = 0) the pressure angle is
    atan(e/s0), s0 = √(20² − 12²) = 16 mm: 36.87° > 30°."""
    data = example("cam_7_3.yaml")
    data["cam"]["base_radius_mm"] = 20
    (f,) = [f for f in findings(run(data)) if f.code == "pressure_angle"]
    alpha = math.degrees(math.atan(12 / 16))
    zh, en = both(f)
    assert f"{alpha:.2f}°" in zh and f"{alpha:.2f}°" in en
    assert "基圆半径" in zh and "increase the base radius" in en


# ----------------------------------------------------------------- undercut gears and cams

def test_undercut_gear_in_the_shaper():
    """z1 = 12, α = 20°, h_a* = 1: z_min = 17 (孙桓), x_min = (17 − 12)/17 = 0.294."""
    data = example("shaper.yaml")
    data["gear_pair"]["z1"] = 12
    r = run(data, stop_after="gear")
    (f,) = [f for f in r["gear"].warnings if f.code == "undercut"]
    z_min = 17
    x_min = (z_min - 12) / z_min
    zh, en = both(f)
    assert f"{z_min:g}" in en and f"{z_min:.1f}" not in en and f"{x_min:.3f}" in en and f"{x_min:.3f}" in zh
    # the brief field is the finding's field (the terminal names it), not part of the
    # report's prose; the least tooth number is z_min = 17
    assert f.field == "gear_pair.x1" and "gear_pair" not in en + zh
    assert f"x ≥ {x_min:.3f}" in en and "at least 17 teeth" in en and "≥ 17" in zh


def test_undercut_gear_in_a_drive():
    """furnace_drive's open spur stage (index 2) with z1 = 12 and x1 = 0 is undercut."""
    data = example("furnace_drive.yaml")
    stage = data["drive"]["stages"][2]
    assert stage["type"] == "spur"
    stage["z1"] = 12
    r = run(data)
    found = [f for f in r["drive"].warnings if f.code == "undercut"]
    assert found, [f.en for f in r["drive"].warnings]
    z_min = 17                                        # 孙桓: α = 20°, h_a* = 1
    zh, en = both(found[0])
    # the brief field is the finding's (the terminal names it), not the report's prose
    assert f"{(z_min - 12) / z_min:.3f}" in en and found[0].field == "drive.stages[2].x1"
    assert "drive.stages" not in en + zh and "at least 17 teeth" in en
    assert "≥ 17" in zh and "根切" in zh


def test_roller_cam_undercut_and_pointed():
    """A roller at least the pitch curve's smallest convex radius of curvature undercuts the
    cam; a little smaller leaves a pointed profile. ρ is checked against the curvature of
    the pitch points by finite differences (κ = (x'y'' − y'x'')/|z'|³)."""
    data = example("cam_7_3.yaml")
    r = run(data)
    pitch = r["cam"].grid.pitch
    d1 = (np.roll(pitch, -1) - np.roll(pitch, 1)) / 2
    d2 = np.roll(pitch, -1) - 2 * pitch + np.roll(pitch, 1)
    kappa = (d1.real * d2.imag - d1.imag * d2.real) / np.abs(d1) ** 3
    kappa *= np.sign(np.median(kappa))                    # + where convex, either sense
    rho = 1 / kappa[kappa > 0]
    # the uniform return's velocity jumps put two corners in the pitch curve: not curvature
    rho_fd = float(np.min(rho[rho > 0.1 * np.median(rho)])) * 1e3    # mm
    data["cam"]["follower"]["roller_radius_mm"] = math.ceil(rho_fd) + 1
    (f,) = [f for f in findings(run(data)) if f.code == "undercut"]
    zh, en = both(f)
    rho = float(re.search(r"ρmin = ([\d.]+)", en).group(1))
    assert rho == pytest.approx(rho_fd, rel=2e-3)
    assert "根切" in zh and "undercut" in en and "roller" in en and "滚子半径" in zh
    data["cam"]["follower"]["roller_radius_mm"] = round(rho_fd - 1.0, 1)
    assert "pointed" in [f.code for f in findings(run(data))]


# ------------------------------------------------------------ brief errors in Chinese

def test_brief_problems_in_chinese():
    data = example("linkage_sixbar.yaml")
    data["linkage"]["crank"]["length_mm"] = -5
    data["linkage"]["crank"]["rotation"] = "left"
    data["linkage"]["extra_field"] = 1
    del data["linkage"]["output"]
    err = brief_error(data)
    got = {p.path: p for p in err.problems}
    assert got["linkage.crank.length_mm"].allowed_zh.startswith("须大于 0")
    assert "须为以下之一" in got["linkage.crank.rotation"].allowed_zh
    assert got["linkage.extra_field"].allowed_zh.startswith("未知字段")
    assert got["linkage.output"].allowed_zh.startswith("必填")
    zh = err.text("zh")
    assert "任务书中有 4 处问题" in zh and "linkage.output：缺少" in zh
    assert str(err) == err.text("en") and "4 problems in the brief" in str(err)
