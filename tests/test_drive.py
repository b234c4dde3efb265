"""The drive's power, motor choice, ratio allocation and shaft table against hand
calculations (《机械设计课程设计》 chapter 2) and the furnace-pusher seed (003).

Hand references:
- furnace pusher: H = 220 mm, 20 strokes/min, 500 N working / 100 N return:
  P_w = (500 + 100) × 0.22 × 20 / 60 = 44.0 W (the seed uses 500 N on both strokes: 73.3 W);
  the smallest Y motor (0.55 kW) is Y801-4 at 1390 rpm, total ratio 1390/20 = 69.5 as the seed.
- shaper drive: belt (2–4) before the fixed pair 60/18: total ratios 6.67–13.3 are possible;
  1500 rpm motors need 1390/80 = 17.4 (no), 1000 rpm motors 910/80 = 11.4 (yes).
"""
from __future__ import annotations

import numpy as np
import pytest

from mechdesign.machines.drive.brief import DriveBrief, drive_brief_to_si
from mechdesign.brief.loader import BriefError, parse_brief
from mechdesign.core import drive as core
from mechdesign.stages.drive import design_drive, motor_catalogue


#: issue 20: every gear stage also checks its tips, undercut and contact ratio
GEOMETRY_CHECKS = ["tooth_tip", "undercut", "tooth_tip", "undercut", "contact_ratio"]

def _brief(stages, load=None, motor=None):
    data = {"machine": "drive", "report": {"title": "t", "student": "s"},
            "load": load or {"output_speed_rpm": 20, "stroke": {
                "stroke_mm": 220, "working_force_N": 500, "return_force_N": 100}},
            "drive": {"stages": stages, "motor": motor or {"speed_tolerance_pct": 4}}}
    return drive_brief_to_si(DriveBrief.model_validate(data))


def _run(p):
    return design_drive(p.drive, p.load.power, p.load.output_speed_rpm, p.load.how)


def test_stroke_load_power_is_work_per_cycle():
    p = _brief([{"type": "worm"}])
    assert p.load.power == pytest.approx((500 + 100) * 0.220 * 20 / 60)   # 44.0 W


def test_furnace_pusher_motor_and_total_ratio_match_the_seed():
    p = _brief([{"type": "coupling"}, {"type": "worm"}, {"type": "spur", "open": True}])
    d = _run(p)
    assert d.motor.designation == "Y801-4" and d.motor.full_load_rpm == 1390
    assert d.choice.total_ratio == pytest.approx(69.5)
    # η = 0.99 (coupling) × η_worm × 0.95 (open gears) × 0.99³ (bearings of shafts I–III)
    worm = d.stages[1].efficiency
    assert d.efficiency == pytest.approx(0.99 * worm * 0.95 * 0.99**3, rel=1e-12)
    assert d.power_required == pytest.approx(44.0 / d.efficiency, rel=1e-12)
    # Speeds: the realised teeth give the machine's speed; the error is within 4 %.
    z = [(s.z1, s.z2) for s in d.stages[1:]]
    assert d.output_speed == pytest.approx(1390 / (z[0][1] / z[0][0]) / (z[1][1] / z[1][0]))
    assert abs(d.speed_error) < 0.04 and not [w for w in d.warnings if w.code == "speed_error"]


def test_shaper_like_drive_prefers_the_speed_whose_ratio_fits():
    elements = [core.Element("belt", 0.96, (2, 4), 7), core.Element("open_spur", 0.95, (3, 7), 15, 60 / 18)]
    choice = core.choose_motor(motor_catalogue(), 690.0, 80.0, elements)
    assert choice.motor.designation == "Y90S-6"          # 0.75 kW, 910 rpm
    first = choice.candidates[0]
    assert first.synchronous_rpm == 1500 and not first.recommended
    assert first.total_ratio == pytest.approx(1390 / 80)
    # 0.8 kW needs the next size at 1000 rpm.
    assert core.choose_motor(motor_catalogue(), 800.0, 80.0, elements).motor.designation == "Y90L-6"


def test_a_smaller_motor_beyond_the_recommended_ratio_beats_a_larger_one_within_it():
    """The slotter's drive (BRIEFS: 60 strokes/min, V-belt before the fixed pair 54/18,
    P_d ≈ 0.18 kW): 1500 rpm motors need a belt of 1390/180 = 7.7 (above its maximum 7),
    1000 rpm 910/180 = 5.06 (beyond the recommended 2–4, within 7), 3000 rpm 15.7 (no),
    750 rpm 710/180 = 3.94 (recommended) — but the smallest 750 rpm motor of the Y series is
    Y132S-8, 2.2 kW, twelve times P_d. The 0.75 kW Y90S-6 is the design (吴宗泽《机械设计
    课程设计手册》: V-belt i ≤ 7; the motor's power is chosen first)."""
    elements = [core.Element("belt", 0.96, (2, 4), 7), core.Element("open_spur", 0.95, (3, 7), 15, 3.0)]
    choice = core.choose_motor(motor_catalogue(), 181.0, 60.0, elements)
    assert choice.motor.designation == "Y90S-6" and choice.reason == "maximum"
    assert choice.total_ratio / 3.0 == pytest.approx(910 / 180)
    by_speed = {c.synchronous_rpm: c for c in choice.candidates}
    assert by_speed[750].motor.designation == "Y132S-8" and by_speed[750].recommended
    assert not by_speed[1500].possible and not by_speed[3000].possible
    # equal powers: the recommended ratio first (the shaper: Y802-4 and Y90S-6 are both 0.75 kW)
    shaper = [core.Element("belt", 0.96, (2, 4), 7), core.Element("open_spur", 0.95, (3, 7), 15, 60 / 18)]
    assert core.choose_motor(motor_catalogue(), 690.0, 80.0, shaper).reason == "recommended"


def test_motor_choice_errors_name_the_problem():
    belt = [core.Element("belt", 0.96, (2, 4), 7)]
    with pytest.raises(core.DriveDesignError, match="no motor"):
        core.choose_motor(motor_catalogue(), 1e6, 100.0, belt)
    with pytest.raises(core.DriveDesignError, match="total ratios"):
        core.choose_motor(motor_catalogue(), 500.0, 1.0, belt)


def test_allocation_keeps_the_product_and_the_two_stage_rule():
    els = [core.Element("belt", 0.96, (2, 4), 7), core.Element("helical", 0.97, (3, 5), 8),
           core.Element("helical", 0.97, (3, 5), 8)]
    r = core.allocate_ratios(60.0, els)
    assert np.prod(r) == pytest.approx(60.0)
    assert r[1] == pytest.approx(np.sqrt(1.4 * r[1] * r[2]))     # i_fast = √(1.4 i_reducer)
    assert r[0] < r[2] < r[1]                                   # belt below the gears
    # Fixed stages are kept; the free ones share the rest.
    els[1] = core.Element("helical", 0.97, (3, 5), 8, 4.0)
    r = core.allocate_ratios(60.0, els)
    assert r[1] == 4.0 and np.prod(r) == pytest.approx(60.0)


def test_shaft_table_conserves_power_through_the_efficiencies():
    """T = 9550 P/n in course units, and T_{k+1} = T_k i η (η_b after the first shaft)."""
    s = core.shaft_table(1440.0, 4000.0, [2.5, 4.0, 3.0], [0.96, 0.97, 0.97], 0.99)
    assert s[0].torque == pytest.approx(9550 * 4.0 / 1440, rel=1e-3)
    assert s[1].torque == pytest.approx(s[0].torque * 2.5 * 0.96, rel=1e-12)
    assert s[2].torque == pytest.approx(s[1].torque * 4.0 * 0.97 * 0.99, rel=1e-12)
    assert s[3].speed_rpm == pytest.approx(1440 / 30)
    assert s[3].power == pytest.approx(4000 * 0.96 * 0.97**2 * 0.99**2)


def test_gear_train_sign_and_belt_slip():
    # Two external meshes: output turns the same way; 18/90 then 18/126 (seed 002) = 35.
    assert core.train_ratio([(18, 90, True), (18, 126, True)]) == pytest.approx(35.0)
    assert core.train_ratio([(18, 60, True)]) == pytest.approx(-60 / 18)
    assert core.train_ratio([(20, 60, False)]) == pytest.approx(3.0)     # internal mesh
    assert core.belt_ratio(0.1, 0.2, 0.0) == pytest.approx(2.0)           # seed 002's Ø100/Ø200
    assert core.belt_ratio(0.1, 0.2, 0.02) == pytest.approx(2 / 0.98)
    assert core.standard_pulley(330) == 335 and core.standard_pulley(101) == 100


def test_lock_beam_transmission_reaches_ten_rpm():
    """Seed 002: belt Ø100/Ø200, gears 18/90 and 18/126 from 700 rpm give exactly 10 rpm
    without slip; a 710 rpm Y motor with 1.5 % slip gives 10.3 rpm."""
    p = _brief([{"type": "belt", "d1_mm": 100, "d2_mm": 200, "slip": 0.0},
                {"type": "spur", "z1": 18, "z2": 90}, {"type": "spur", "z1": 18, "z2": 126}],
               load={"output_speed_rpm": 10, "power_kW": 0.5}, motor={"synchronous_rpm": 750})
    d = _run(p)
    assert [s.ratio for s in d.stages] == pytest.approx([2.0, 5.0, 7.0])
    assert d.output_speed == pytest.approx(d.motor.full_load_rpm / 70)
    assert d.motor.full_load_rpm == 710 and d.speed_error == pytest.approx(0.0143, abs=1e-4)


def test_speed_error_beyond_the_tolerance_is_a_finding():
    p = _brief([{"type": "spur", "z1": 20, "z2": 100}],
               load={"output_speed_rpm": 250, "power_kW": 1.0}, motor={"speed_tolerance_pct": 2,
                                                                       "synchronous_rpm": 1500})
    d = _run(p)                     # 1400 / 5 = 280 rpm: +12 %
    assert d.speed_error == pytest.approx(0.12, abs=1e-3)
    assert [w.code for w in d.warnings if w.code == "speed_error"] == ["speed_error"]


@pytest.mark.parametrize("stage, path, text", [
    # cross-field problems at the field to change (were at drive.stages.0)
    ({"type": "spur", "d1_mm": 100}, "drive.stages.0.d1_mm", "has no d1_mm"),
    ({"type": "spur", "ratio": 3, "z1": 20, "z2": 60}, "drive.stages.0.ratio", "fixed twice"),
    ({"type": "gearbox"}, "drive.stages.0.type", "coupling"),
    ({"type": "spur", "z1": 40, "z2": 20}, "drive.stages.0.z2", "z2 must be at least z1"),
])
def test_bad_drive_stages_name_the_field(stage, path, text):
    data = {"machine": "drive", "report": {"title": "t", "student": "s"},
            "load": {"output_speed_rpm": 20, "power_kW": 1.0}, "drive": {"stages": [stage]}}
    with pytest.raises(BriefError) as exc:
        parse_brief(data)
    problem = exc.value.problems[0]
    assert problem.path == path and text in str(problem)


def test_drive_load_needs_exactly_one_kind():
    data = {"machine": "drive", "report": {"title": "t", "student": "s"},
            "load": {"output_speed_rpm": 20, "power_kW": 1.0, "torque_Nm": 5.0},
            "drive": {"stages": [{"type": "worm"}]}}
    with pytest.raises(BriefError, match="exactly one of"):
        parse_brief(data)


def test_furnace_drive_strength_checks_by_hand():
    """The worm stage's checks use the textbook formulas: σH = ZE Zρ √(K T2/a³) with the
    realised a, and the oil temperature t = 20 + P1(1 − η)/(k_d A). Every gear and shaft
    check of the furnace drive passes (44 W is a light load for the smallest Y motor)."""
    p = _brief([{"type": "coupling"}, {"type": "worm", "z1": 2, "q": 10},
                {"type": "spur", "open": True, "z1": 20}])
    d = _run(p)
    worm = d.stages[1].design
    a, K, T2 = worm.extra["a"], worm.K, worm.T2
    contact = next(c for c in worm.checks if c.key == "worm_contact")
    from mechdesign.data.catalogues import worm_wheel_material
    ZE = worm_wheel_material("ZCuSn10P1_sand").ZE
    assert contact.value == pytest.approx(ZE * worm.extra["Zrho"] * np.sqrt(K * T2 / a**3), rel=1e-9)
    thermal = next(c for c in worm.checks if c.key == "worm_thermal")
    P1 = d.shafts[1].power
    assert thermal.value == pytest.approx(20 + P1 * (1 - worm.extra["eta"]) / (15.0 * worm.extra["area"]))
    # The worm's efficiency in the chain is the one its geometry gives.
    assert d.stages[1].efficiency == pytest.approx(worm.extra["eta"], abs=1e-4)
    assert worm.T2 == pytest.approx(d.shafts[2].torque)
    assert all(c.passed for st in d.stages if st.design for c in st.design.checks)
    assert all(c.passed for sh in d.shaft_designs for c in sh.checks)
    # Open gears: no contact check, the module is designed by bending with wear, ≥ 2 mm.
    spur = d.stages[2].design
    # (issue 20: the geometric checks of the stage follow the strength checks)
    assert [c.key for c in spur.checks] == ["gear_bending", "gear_bending"] + GEOMETRY_CHECKS
    assert spur.module >= 0.002


def test_overloaded_closed_pair_fails_and_is_reported():
    """A 10 kW pair with a given 2 mm module fails in contact: the finding names it."""
    p = _brief([{"type": "spur", "z1": 24, "z2": 96, "module_mm": 2}],
               load={"output_speed_rpm": 360, "power_kW": 10.0})
    d = _run(p)
    failed = [c for c in d.stages[0].design.checks if not c.passed]
    assert failed and any(w.code == "strength" for w in d.warnings)
    # The designed module (auto) passes every check of the same pair.
    p = _brief([{"type": "spur", "z1": 24, "z2": 96}], load={"output_speed_rpm": 360, "power_kW": 10.0})
    d = _run(p)
    assert all(c.passed for c in d.stages[0].design.checks)
    assert d.stages[0].design.module >= d.stages[0].design.module_min


def test_shaft_reactions_balance_the_gear_forces():
    p = _brief([{"type": "coupling"}, {"type": "worm", "z1": 2, "q": 10},
                {"type": "spur", "open": True, "z1": 20}])
    for sh in _run(p).shaft_designs:
        r = sh.result
        assert r.RAh + r.RBh + sum(ld.Fh for ld in sh.loads) == pytest.approx(0, abs=1e-9)
        assert r.RAv + r.RBv + sum(ld.Fv for ld in sh.loads) == pytest.approx(0, abs=1e-9)


def test_two_stage_helical_reducer_is_designed_and_checked():
    """A belt + two-stage helical reducer (the die-cutter's layout): ratios split by the
    √(1.4 i) rule before rounding, helical geometry m_t = m_n/cos β with β corrected to the
    centre distance rounded to a whole millimetre (β within 8°…20°), all checks run."""
    p = _brief([{"type": "belt"}, {"type": "helical", "z1": 24}, {"type": "helical", "z1": 24}],
               load={"output_speed_rpm": 50, "power_kW": 2.0})
    d = _run(p)
    fast, slow = d.stages[1], d.stages[2]
    assert fast.ratio_allocated == pytest.approx(np.sqrt(1.4 * fast.ratio_allocated * slow.ratio_allocated))
    g = fast.design.geometry
    assert g.mt == pytest.approx(g.mn / np.cos(g.beta))
    assert np.radians(8) <= g.beta <= np.radians(20)
    assert g.a * 1e3 == pytest.approx(round(g.a * 1e3), abs=1e-9)
    assert abs(g.a - g.mn * (24 + fast.z2) / (2 * np.cos(np.radians(14.0)))) <= 0.5e-3 + 1e-12
    assert [c.key for c in fast.design.checks] == ["gear_contact", "gear_bending", "gear_bending"] + GEOMETRY_CHECKS
    assert all(c.passed for c in fast.design.checks + slow.design.checks)
    assert fast.design.forces["Fa"] == pytest.approx(fast.design.forces["Ft"] * np.tan(g.beta))
