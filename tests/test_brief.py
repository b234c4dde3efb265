"""Brief loading and validation (designs/shaper.yaml, /work/shared/BRIEFS.md section 000).

References: the seed data of BRIEFS.md (H = 320 mm, K = 1.2, L_O2O3 = 650 mm, n2 = 80 rpm
clockwise, [δ] = 1/25, γ = 7×10⁴ N/m³, …) converted to SI by hand (mm → m, rpm → rad/s
as 2πn/60, clockwise negative); and the validation contract: every problem of a brief is
reported at once, each with its dotted field path and the value found.
"""
from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pytest
import yaml

from mechdesign.brief.loader import BriefError, load_brief, parse_brief
from mechdesign.machines.shaper.brief import ShaperBrief, to_si

DESIGN = Path(__file__).parents[1] / "designs" / "shaper.yaml"


@pytest.fixture()
def base():
    """The shipped brief as plain data (safe_load: 7.0e4 would be a string here, so set it)."""
    data = yaml.safe_load(DESIGN.read_text(encoding="utf-8"))
    data["flywheel"]["specific_weight_N_m3"] = 70000.0
    return data


def write(tmp_path, data_or_text) -> Path:
    path = tmp_path / "brief.yaml"
    text = data_or_text if isinstance(data_or_text, str) else yaml.safe_dump(data_or_text, allow_unicode=True)
    path.write_text(text, encoding="utf-8")
    return path


# ---------------------------------------------------------------------- the shipped brief


def test_shipped_brief_loads_and_converts_to_si():
    b = load_brief(DESIGN)
    assert isinstance(b, ShaperBrief)
    p = to_si(b)
    # Unit conversions are single multiplications: exact up to one rounding (rel 1e-15).
    assert p.stroke == pytest.approx(0.320, rel=1e-15)
    assert p.time_ratio_K == 1.2
    assert p.frame == pytest.approx(0.650, rel=1e-15)
    assert p.rod_ratio == 0.25 and p.com_ratio == 0.5
    assert p.ram_com_x == pytest.approx(0.250, rel=1e-15)
    assert p.crank_omega == pytest.approx(-80 * 2 * np.pi / 60, rel=1e-15)  # cw → negative
    assert p.crank_speed_rpm == 80
    assert (p.m4, p.J_S4, p.m6, p.G2) == (16, 1.6, 68, 500)  # m6 = 68, not the misprinted 6
    assert p.cutting_force == 1600
    assert p.cutting_height == pytest.approx(0.160, rel=1e-15)
    assert p.idle_travel_ratio == 0.05
    assert (p.z1, p.z2) == (18, 60)
    assert p.fluctuation == pytest.approx(1 / 25, rel=1e-15)
    assert p.flywheel_shaft == "pinion"
    assert p.rim_diameter == pytest.approx(0.5, rel=1e-15)
    assert p.rim_height_to_width == 1.5
    assert p.specific_weight == 70000.0 and isinstance(p.specific_weight, float)
    assert p.grid_points == 3600
    assert p.position_step == pytest.approx(np.pi / 6, rel=1e-15)
    assert p.gravity == 9.81
    # YAML reads the date as a date and the quoted student number as text; both stay text.
    assert b.report.date == "2026-11-22" and b.report.student_id == "2023010101"
    assert b.report.class_name == "机械设计 2301"


def test_counter_clockwise_crank_is_positive(base, tmp_path):
    base["linkage"]["crank_rotation"] = "ccw"
    base["cam"]["rotation"] = "ccw"          # the cam is on the crank shaft
    assert to_si(load_brief(write(tmp_path, base))).crank_omega == pytest.approx(80 * 2 * np.pi / 60)


def test_cam_must_turn_with_the_crank(base, tmp_path):
    base["linkage"]["crank_rotation"] = "ccw"
    with pytest.raises(BriefError) as err:
        load_brief(write(tmp_path, base))
    assert "cam.rotation" in str(err.value) and "crank_rotation" in str(err.value)


def test_shaper_without_cam_section_has_no_cam(base, tmp_path):
    del base["cam"]
    assert to_si(load_brief(write(tmp_path, base))).cam is None


def test_defaults_apply_when_optional_sections_are_left_out(base, tmp_path):
    del base["analysis"]
    del base["loads"]["idle_travel_ratio"]
    p = to_si(load_brief(write(tmp_path, base)))
    assert p.grid_points == 3600 and p.idle_travel_ratio == 0.05 and p.gravity == 9.81


# ---------------------------------------------------------------------- numbers


@pytest.mark.parametrize("text, value", [("1/25", 0.04), ("1 / 25", 0.04), ("0.04", None),
                                         ("3/100", 0.03)])
def test_fluctuation_accepts_a_fraction(base, tmp_path, text, value):
    body = DESIGN.read_text(encoding="utf-8").replace("fluctuation_delta: 1/25",
                                                      f"fluctuation_delta: {text}")
    assert f"fluctuation_delta: {text}" in body
    p = to_si(load_brief(write(tmp_path, body)))
    assert p.fluctuation == pytest.approx(0.04 if value is None else value, rel=1e-15)


@pytest.mark.parametrize("text", ["7.0e4", "7e4", "7.0E+4", "70_000.0"])
def test_exponent_notation_is_a_number(tmp_path, text):
    body = DESIGN.read_text(encoding="utf-8").replace("specific_weight_N_m3: 7.0e4",
                                                      f"specific_weight_N_m3: {text}")
    body = body.replace("cutting_force_Fc_N: 1600", "cutting_force_Fc_N: 1.6e3")
    p = to_si(load_brief(write(tmp_path, body)))
    assert p.specific_weight == 70000.0
    assert p.cutting_force == 1600.0


# ---------------------------------------------------------------------- many problems at once


def test_every_problem_is_listed_with_path_and_value(base, tmp_path):
    base["linkage"]["stroke_HH_mm"] = 320                 # unknown key
    del base["linkage"]["crank_speed_n2_rpm"]             # missing field
    base["linkage"]["frame_O2O3_mm"] = "650"              # string for a number
    base["linkage"]["time_ratio_K"] = 1.0                 # out of range (K ≤ 1)
    base["masses"]["ram_m6_kg"] = -68                     # out of range
    base["flywheel"]["fluctuation_delta"] = "1/x"         # bad fraction
    base["gear_pair"]["z1"] = 18.5                        # float for an integer
    base["analysis"]["grid_points"] = True                # bool is not a number
    base["colour"] = "red"                                # unknown section
    with pytest.raises(BriefError) as info:
        load_brief(write(tmp_path, base))
    err = info.value
    got = {pr.path: pr for pr in err.problems}
    expected = {
        "linkage.stroke_HH_mm": "320",
        "linkage.crank_speed_n2_rpm": "missing",
        "linkage.frame_O2O3_mm": "'650'",
        "linkage.time_ratio_K": "1.0",
        "masses.ram_m6_kg": "-68",
        "flywheel.fluctuation_delta": "'1/x'",
        "gear_pair.z1": "18.5",
        "analysis.grid_points": "True",
        "colour": "'red'",
    }
    assert set(got) == set(expected), err
    assert len(err.problems) == len(expected)
    for path, value in expected.items():
        assert got[path].value == value
        assert f"{path}: {value}" in str(err)       # one line per problem in the message
    assert str(err).startswith(f"{tmp_path / 'brief.yaml'}: 9 problems")
    assert "stroke_H_mm" in got["linkage.stroke_HH_mm"].allowed   # lists the allowed keys
    assert "greater than 1" in got["linkage.time_ratio_K"].allowed
    assert "1/25" in got["flywheel.fluctuation_delta"].allowed
    assert "[rpm]" in got["linkage.crank_speed_n2_rpm"].allowed   # the field's unit


@pytest.mark.parametrize("bad", ["1/0", "one", "1/2/3"])
def test_bad_fraction_is_a_problem(base, bad):
    base["flywheel"]["fluctuation_delta"] = bad
    with pytest.raises(BriefError) as info:
        parse_brief(base, "x.yaml")
    (pr,) = info.value.problems
    assert pr.path == "flywheel.fluctuation_delta" and pr.value == repr(bad)


def test_fraction_out_of_range_is_a_problem(base):
    base["flywheel"]["fluctuation_delta"] = "25/1"
    with pytest.raises(BriefError) as info:
        parse_brief(base)
    (pr,) = info.value.problems
    assert pr.path == "flywheel.fluctuation_delta" and "less than 1" in pr.allowed


# ---------------------------------------------------------------------- file-level problems


def test_duplicate_key_is_reported_with_both_lines(tmp_path):
    body = DESIGN.read_text(encoding="utf-8").replace(
        "  time_ratio_K: 1.2", "  time_ratio_K: 1.2\n  time_ratio_K: 1.3")
    lines = body.splitlines()
    first = lines.index("  time_ratio_K: 1.2") + 1
    with pytest.raises(BriefError) as info:
        load_brief(write(tmp_path, body))
    (pr,) = info.value.problems
    assert pr.value == "invalid YAML"
    assert f"'time_ratio_K' appears twice (lines {first} and {first + 1})" in pr.allowed
    assert pr.path.startswith(f"line {first + 1},")


def test_invalid_yaml(tmp_path):
    with pytest.raises(BriefError) as info:
        load_brief(write(tmp_path, "machine: shaper\nlinkage: [1, 2\n"))
    (pr,) = info.value.problems
    assert pr.value == "invalid YAML" and pr.path.startswith("line ")


@pytest.mark.parametrize("text, kind", [("- shaper\n- lathe\n", "list"), ("just text\n", "str"),
                                        ("", "NoneType")])
def test_top_level_must_be_a_mapping(tmp_path, text, kind):
    with pytest.raises(BriefError) as info:
        load_brief(write(tmp_path, text))
    (pr,) = info.value.problems
    assert pr.path == "(top level)" and kind in pr.value


@pytest.mark.parametrize("machine, shown", [("lathe", "'lathe'"), (None, "missing"), (3, "3")])
def test_unknown_machine(base, machine, shown):
    if machine is None:
        del base["machine"]
    else:
        base["machine"] = machine
    with pytest.raises(BriefError) as info:
        parse_brief(base)
    (pr,) = info.value.problems
    assert pr.path == "machine" and pr.value == shown and "shaper" in pr.allowed


def test_missing_file(tmp_path):
    with pytest.raises(BriefError) as info:
        load_brief(tmp_path / "nope.yaml")
    assert info.value.problems[0].path == "(file)"


def test_brief_error_is_a_value_error_not_a_validation_traceback(base):
    broken = copy.deepcopy(base)
    broken["linkage"]["stroke_H_mm"] = 0
    with pytest.raises(ValueError) as info:
        parse_brief(broken)
    assert type(info.value) is BriefError
    assert info.value.problems[0].path == "linkage.stroke_H_mm"


@pytest.mark.parametrize("section, field, text", [("linkage", "ram_com_x_S6_mm", ".nan"),
                                                  ("loads", "cutting_height_yP_mm", ".inf")])
def test_non_finite_numbers_are_problems(tmp_path, section, field, text):
    body = DESIGN.read_text(encoding="utf-8")
    old = next(line for line in body.splitlines() if line.strip().startswith(field + ":"))
    body = body.replace(old, f"  {field}: {text}")
    with pytest.raises(BriefError) as info:
        load_brief(write(tmp_path, body))
    assert [pr.path for pr in info.value.problems] == [f"{section}.{field}"]
