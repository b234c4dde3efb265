"""The input shaft joined to the motor by a coupling (session 39): the motor's shaft extension,
the course guides' rule for the shaft end and the coupling that bores both shafts.

Independent references:
- shaft extensions D × E of the Y series by frame = those of IEC 60072-1 / EN 50347 for the
  frame (the Y series' mounting dimensions, JB/T 10391; the handbook's Y-motor dimension table):
  80 19 × 40, 90S/L 24 × 50, 100L 28 × 60, 112M 28 × 60, 132S/M 38 × 80, 160M/L 42 × 110,
  180M/L 48 × 110, 200L 55 × 110; D of frames 80, 90, 100, 112 and 160 and E = 110 of frame 160
  also read off the EN 50347 dimension tables of a stored motor catalogue (ABM Greiffenberger
  TechLine 1, 2007);
- the course guides (《机械设计课程设计》): the end of a shaft coupled to the motor takes
  d ≈ (0.8 … 1.2) D, so that one coupling has bores for both shafts: the furnace drive's Y801-4
  (D = 19 mm) needs d ≥ 0.8 × 19 = 15.2 mm, the next size of the standard series (GB/T 2822
  R40: … 15, 16, 17 …) 16 mm, which the coupling must also bore;
- LT couplings (GB/T 4323, the handbook's table): LT1 6.3 N·m, bores 9–14 mm (no 19); LT2
  16 N·m, 7600 rpm, bores 12, 14, 16, 18, 19 mm: the smallest size boring 19 and 16 mm;
  LT6 250 N·m, bores 32 … 42 mm, the smallest boring 38 mm (LT5 ends at 35);
- K_A of a coupling driven by an electric motor whose torque varies very little: 1.3
  (濮良贵《机械设计》表14-1, the value its worked shaft example takes); T_c = K_A T ≤ T_n;
- flat key of a 16 mm shaft: 5 × 5 (GB/T 1096, 12 < d ≤ 17 mm).
These tests fail on the base commit 8e42e4e (no shaft extension in the motor data, the
furnace drive's worm shaft end was 10 mm with a 3 × 3 key, no coupling chosen).
"""
from __future__ import annotations

import pytest

from mechdesign.core.drive import DriveDesignError
from mechdesign.data import catalogues as cat
from mechdesign.machines.drive.brief import DriveBrief, drive_brief_to_si
from mechdesign.stages import drive as sd
from mechdesign.stages.drive import design_drive, motor_catalogue

MM = 1e-3

#: Y-series shaft extensions D × E [mm] by frame (IEC 60072-1 / EN 50347)
SHAFT_BY_FRAME = {80: (19, 40), 90: (24, 50), 100: (28, 60), 112: (28, 60), 132: (38, 80),
                  160: (42, 110), 180: (48, 110), 200: (55, 110)}


@pytest.mark.parametrize("designation, frame", [
    ("Y801-4", 80), ("Y802-2", 80), ("Y90S-4", 90), ("Y90L-6", 90), ("Y100L2-4", 100),
    ("Y112M-4", 112), ("Y132S-4", 132), ("Y132M2-6", 132), ("Y160M-4", 160), ("Y160L-8", 160),
    ("Y180L-4", 180), ("Y200L-4", 200)])
def test_motor_shaft_extension_by_frame(designation, frame):
    m = next(m for m in motor_catalogue() if m.designation == designation)
    D, E = SHAFT_BY_FRAME[frame]
    assert m.frame_height == pytest.approx(frame * MM)
    assert m.shaft_diameter == pytest.approx(D * MM) and m.shaft_length == pytest.approx(E * MM)


def test_every_motor_has_its_frames_shaft():
    for m in motor_catalogue():
        D, E = SHAFT_BY_FRAME[round(m.frame_height / MM)]
        assert (m.shaft_diameter, m.shaft_length) == (pytest.approx(D * MM), pytest.approx(E * MM)), m


def test_a_bad_motor_row_is_a_message_naming_it(monkeypatch):
    rows = [dict(r) for r in sd.load_csv("motors.csv")]
    rows[3]["shaft_D_mm"] = "nineteen"
    monkeypatch.setattr(sd, "load_csv", lambda name: tuple(rows))
    with pytest.raises(DriveDesignError) as e:
        motor_catalogue()
    text = str(e.value)
    assert rows[3]["designation"] in text and "shaft_D_mm" in text and "nineteen" in text


def test_coupling_choice_by_bores_torque_and_speed():
    # Y801-4: D = 19 mm, end ≥ 15.2 mm, T_c = 1.3 × 0.43 N·m: LT1 has no 19 mm bore → LT2, 16 mm
    c, d = cat.coupling_for(19 * MM, 15.2 * MM, 0.56, 1390)
    assert (c.size, d) == ("LT2", pytest.approx(16 * MM)) and c.Tn == 16
    # a torque above LT2's 16 N·m → LT3 (31.5 N·m, bores 16 … 22)
    c, d = cat.coupling_for(19 * MM, 15.2 * MM, 20.0, 1390)
    assert (c.size, d, c.Tn) == ("LT3", pytest.approx(16 * MM), 31.5)
    # Y132M-4: D = 38 mm, end ≥ 30.4 mm: LT5 ends at 35 mm → LT6, its bore 32 mm
    c, d = cat.coupling_for(38 * MM, 0.8 * 38 * MM, 1.3 * 49.7, 1440)
    assert (c.size, d) == ("LT6", pytest.approx(32 * MM))
    # no LT size bores 19 mm and 30 mm
    assert cat.coupling_bores_for(19 * MM, 30 * MM) is None
    assert cat.coupling_application_factor(1.0) == 1.3      # 表14-1, torque varies very little


def _brief(stages, shafts=None, **peak):
    data = {"machine": "drive", "report": {"title": "t", "student": "s"},
            "load": {"output_speed_rpm": 20, "stroke": {
                "stroke_mm": 220, "working_force_N": 500, "return_force_N": 100}},
            "drive": {"stages": stages, "motor": {"speed_tolerance_pct": 4},
                      "service": {"application_factor_KA": 1.0}}}
    if shafts:
        data["drive"]["shafts"] = shafts
    p = drive_brief_to_si(DriveBrief.model_validate(data))
    return design_drive(p.drive, p.load.power, p.load.output_speed_rpm, p.load.how, **peak)


FURNACE = [{"type": "coupling"}, {"type": "worm", "z1": 2, "q": 10},
           {"type": "spur", "open": True, "z1": 20}]


def test_furnace_worm_shaft_end_fits_the_motor_coupling():
    d = _brief(FURNACE)
    assert d.motor.designation == "Y801-4"
    s1 = d.shaft_designs[0]
    # d ≥ max(d_min, 0.8 × 19 = 15.2 mm) → 16 mm (GB/T 2822); the strength minimum is ~4 mm
    assert s1.d_min < 15.2 * MM and s1.d_end == pytest.approx(16 * MM)
    c = s1.coupling
    assert (c.size, c.motor_d, c.d) == ("LT2", pytest.approx(19 * MM), pytest.approx(16 * MM))
    # T_c = K_A T by hand: T = 9549.3 P/n of shaft Ⅰ (the coupling's torque), K_A = 1.3
    sh = d.shafts[1]
    T = 30000 / 3.141592653589793 * sh.power / 1e3 / sh.speed_rpm
    assert c.torque == pytest.approx(T, rel=1e-9) and c.KA == 1.3
    assert c.Tc == pytest.approx(1.3 * T, rel=1e-9) and c.Tc <= c.Tn == 16
    checks = {k.key: k for k in s1.checks}
    assert checks["motor_end"].passed and checks["motor_end"].allowable == pytest.approx(15.2 * MM)
    assert checks["coupling_torque"].passed and checks["coupling_torque"].value == pytest.approx(1.3 * T)
    # the coupling hub's key follows the new diameter: 5 × 5 for 12 < d ≤ 17 mm
    key = next(k for k in s1.keys if k.element == "coupling")
    assert (key.d, key.b, key.h) == (pytest.approx(16 * MM), pytest.approx(5 * MM), pytest.approx(5 * MM))
    assert "coupling_table" in d.data_assumptions and "coupling_KA" in d.data_assumptions


def test_a_belt_first_stage_has_no_motor_coupling():
    d = _brief([{"type": "belt"}, {"type": "helical"}, FURNACE[2]])
    assert all(s.coupling is None for s in d.shaft_designs)
    assert not {"coupling_table", "coupling_KA"} & set(d.data_assumptions)


def test_brief_KA_overrides_and_a_given_small_end_fails_the_rule():
    d = _brief([dict(FURNACE[0], application_factor_KA=1.7), *FURNACE[1:]],
               shafts=[{"shaft": 1, "end_mm": 12}])
    s1 = d.shaft_designs[0]
    assert s1.coupling.KA == 1.7 and s1.coupling.KA_given
    rule = next(c for c in s1.checks if c.key == "motor_end")
    assert not rule.passed and rule.value == pytest.approx(12 * MM)
    # LT1 bores 12 but not 19, LT2 both: the coupling is LT2; the rule's failure is a finding
    # that names the brief field
    assert s1.coupling.size == "LT2"
    assert any(w.field == "drive.shafts[0].end_mm" for w in d.warnings if w.code == "strength")


def test_after_the_flywheel_the_coupling_takes_the_peak_without_K_A():
    # a flywheel on the motor shaft (the furnace pusher's): the coupling carries the cycle's peak
    # torque, which contains the load variations K_A stands for: K_A = 1 (as the gear stages there)
    d = _brief(FURNACE, peak_factor=2.5, peak_from_shaft=0)
    c = d.shaft_designs[0].coupling
    sh = d.shafts[1]
    T = 30000 / 3.141592653589793 * sh.power / 1e3 / sh.speed_rpm
    assert c.peak and c.KA == 1.0 and c.torque == pytest.approx(2.5 * T, rel=1e-9)
    assert c.Tc == pytest.approx(2.5 * T, rel=1e-9) and "coupling_KA" not in d.data_assumptions
