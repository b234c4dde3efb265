"""Cam briefs (mechdesign.brief.cam): validation with field locations, conversion to SI.

References: exercise 7-3 of 孙桓《机械原理》 chapter 7 (cycloidal rise 120° h = 30 mm, dwell 30°,
uniform return 150°, dwell 60°, ccw, r0 = 50 mm, e = 12 mm, r_r = 10 mm), the shaper cam of
seed 000 (parabolic 70°/10°/70°, φmax = 15°, a = 136 mm, L = 120 mm, r0 = 50 mm, r_r = 15 mm,
cw) and exercise 7-1 (R = 40 mm, ε = 20 mm), converted to SI by hand (mm → m: ×10⁻³,
° → rad: ×π/180, rpm → rad/s: ×2π/60), and the validation contract of the briefs: every
error names where it is (pydantic ``loc``; the loader's dotted ``path``) and what is wrong.
"""
from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pytest
import yaml
from pydantic import ValidationError

from mechdesign.machines.cam.brief import CamBrief
from mechdesign.brief.cam import CamSection, cam_to_si
from mechdesign.machines.eccentric_cam.brief import EccentricCamBrief, eccentric_to_si
from mechdesign.brief.loader import BRIEF_MODELS, BriefError, load_brief, parse_brief
from mechdesign.core.cam import OscillatingFollower, Programme, TranslatingFollower

MM = 1e-3
SHAPER = Path(__file__).parents[1] / "designs" / "shaper.yaml"
REPORT = {"title": "凸轮机构设计", "student": "Test"}


def brief_73() -> dict:
    """Exercise 7-3 as a stand-alone cam brief."""
    return {
        "machine": "cam",
        "report": dict(REPORT),
        "cam": {
            "rotation": "ccw",
            "base_radius_mm": 50.0,
            "follower": {"motion": "translating", "contact": "roller", "roller_radius_mm": 10.0,
                         "stroke_h_mm": 30.0, "offset_mm": 12.0, "offset_side": "right"},
            "programme": [
                {"motion": "rise", "angle_deg": 120.0, "law": "cycloidal"},
                {"motion": "dwell", "angle_deg": 30.0},
                {"motion": "return", "angle_deg": 150.0, "law": "constant_velocity"},
                {"motion": "dwell", "angle_deg": 60.0},
            ],
        },
    }


def brief_shaper_cam() -> dict:
    """The shaper cam (seed 000) as a stand-alone cam brief."""
    return {
        "machine": "cam",
        "report": dict(REPORT),
        "cam": {
            "rotation": "cw",
            "base_radius_mm": 50.0,
            "follower": {"motion": "oscillating", "contact": "roller", "roller_radius_mm": 15.0,
                         "max_swing_deg": 15.0, "arm_length_mm": 120.0, "pivot_distance_mm": 136.0},
            "programme": [
                {"motion": "rise", "angle_deg": 70.0, "law": "parabolic"},
                {"motion": "dwell", "angle_deg": 10.0},
                {"motion": "return", "angle_deg": 70.0, "law": "parabolic"},
                {"motion": "dwell", "angle_deg": 210.0},
            ],
        },
    }


def errors_of(model, data) -> list[dict]:
    with pytest.raises(ValidationError) as info:
        model.model_validate(data)
    return info.value.errors()


def only_error(model, data) -> dict:
    errs = errors_of(model, data)
    assert len(errs) == 1, errs
    return errs[0]


# ---------------------------------------------------------------------- valid briefs → SI


@pytest.mark.parametrize("side,sign", [("right", 1), ("left", -1)])
def test_73_converts_to_si(side, sign):
    """7-3: spans 120°, 30°, 150°, 60° → 2π/3, π/6, 5π/6, π/3 rad (summing to 2π); stroke
    0.030 m; roller 0.010 m; offset +0.012 m on the right, −0.012 m on the left; ccw → +1;
    r0 = 0.050 m; default limits 30° (translating) / 70° → rad; ρa,min 3 mm; table step 10°."""
    data = brief_73()
    data["cam"]["follower"]["offset_side"] = side
    p = cam_to_si(CamBrief.model_validate(data).cam)
    prog = p.programme
    assert isinstance(prog, Programme)
    np.testing.assert_allclose(prog.spans, [2 * math.pi / 3, math.pi / 6, 5 * math.pi / 6, math.pi / 3],
                               rtol=1e-15)
    assert abs(prog.spans.sum() - 2 * math.pi) < 1e-12
    assert [s.kind for s in prog.segments] == ["rise", "dwell", "return", "dwell"]
    assert [s.law for s in prog.segments] == ["cycloidal", None, "constant_velocity", None]
    assert prog.stroke == pytest.approx(0.030, rel=1e-15)
    # s at mid-rise (60°) is h/2 = 15 mm for a cycloidal rise
    assert prog.evaluate(math.radians(60)).s == pytest.approx(0.015, rel=1e-12)
    assert p.follower == TranslatingFollower("roller", sign * 0.012, 0.010)
    assert p.rotation == 1 and p.oscillating is False and p.auto_offset is False
    assert p.base_radius == pytest.approx(0.050, rel=1e-15)
    assert p.alpha_rise == pytest.approx(math.pi / 6, rel=1e-15)
    assert p.alpha_return == pytest.approx(70 * math.pi / 180, rel=1e-15)
    assert p.min_actual_curvature == pytest.approx(0.003, rel=1e-15)
    assert p.table_step == pytest.approx(math.pi / 18, rel=1e-15)
    assert p.omega is None and p.speed_rpm is None


def test_speed_and_limits_convert():
    """speed 60 rpm → 2π rad/s; a machine's shaft speed is used when the section has none;
    explicit limits 35°/65° → rad."""
    data = brief_73()
    data["cam"]["limits"] = {"pressure_angle_rise_deg": 35.0, "pressure_angle_return_deg": 65.0,
                             "min_actual_curvature_mm": 5.0}
    section = CamBrief.model_validate(data).cam
    p = cam_to_si(section, speed_rpm=60.0)
    assert p.omega == pytest.approx(2 * math.pi, rel=1e-15) and p.speed_rpm == 60.0
    assert p.alpha_rise == pytest.approx(math.radians(35), rel=1e-15)
    assert p.alpha_return == pytest.approx(math.radians(65), rel=1e-15)
    assert p.min_actual_curvature == pytest.approx(0.005, rel=1e-15)
    data["cam"]["speed_rpm"] = 30.0             # the section's own speed wins
    p = cam_to_si(CamBrief.model_validate(data).cam, speed_rpm=60.0)
    assert p.omega == pytest.approx(math.pi, rel=1e-15)


def test_shaper_cam_oscillating_converts_to_si():
    """Seed 000 cam: φmax 15° → π/12 rad stroke; a = 0.136 m, L = 0.120 m, r_r = 0.015 m;
    cw → −1; the oscillating default rise limit is 45°."""
    p = cam_to_si(CamBrief.model_validate(brief_shaper_cam()).cam)
    assert p.oscillating is True and p.rotation == -1
    assert p.programme.stroke == pytest.approx(math.pi / 12, rel=1e-15)
    assert p.follower == OscillatingFollower("roller", 0.136, 0.120, 0.015, "same")
    assert p.alpha_rise == pytest.approx(math.pi / 4, rel=1e-15)
    # parabolic rise: at δ = 35° (half the rise) φ = φmax/2
    assert p.programme.evaluate(math.radians(35)).s == pytest.approx(math.pi / 24, rel=1e-12)


def test_partial_lifts_convert():
    """Translating lifts in mm, oscillating lifts in degrees: rise 10 + rise 20 = stroke 30 mm
    and return 30 mm; 5° + 10° of a 15° swing."""
    data = brief_73()
    data["cam"]["programme"] = [
        {"motion": "rise", "angle_deg": 60.0, "law": "poly345", "lift_mm": 10.0},
        {"motion": "dwell", "angle_deg": 30.0},
        {"motion": "rise", "angle_deg": 60.0, "law": "poly345", "lift_mm": 20.0},
        {"motion": "return", "angle_deg": 150.0, "law": "cycloidal", "lift_mm": 30.0},
        {"motion": "dwell", "angle_deg": 60.0},
    ]
    p = cam_to_si(CamBrief.model_validate(data).cam)
    np.testing.assert_allclose(p.programme.lifts, [0.010, 0.0, 0.020, -0.030, 0.0], rtol=1e-15)
    osc = brief_shaper_cam()
    osc["cam"]["programme"][0]["lift_deg"] = 5.0
    osc["cam"]["programme"].insert(1, {"motion": "rise", "angle_deg": 10.0, "law": "cycloidal",
                                       "lift_deg": 10.0})
    osc["cam"]["programme"][2]["angle_deg"] = 0.5                     # dwell 10 → 0.5
    osc["cam"]["programme"][-1]["angle_deg"] = 209.5                  # 210 → 209.5: still 360
    p = cam_to_si(CamBrief.model_validate(osc).cam)
    np.testing.assert_allclose(p.programme.lifts[:2], np.radians([5.0, 10.0]), rtol=1e-15)


def test_base_radius_auto_accepted():
    data = brief_73()
    data["cam"]["base_radius_mm"] = "auto"
    p = cam_to_si(CamBrief.model_validate(data).cam)
    assert p.base_radius is None


def test_offset_auto_accepted():
    """offset 'auto': the design chooses the offset; the follower is built with e = 0 for now."""
    data = brief_73()
    data["cam"]["follower"]["offset_mm"] = "auto"
    p = cam_to_si(CamBrief.model_validate(data).cam)
    assert p.auto_offset is True and p.follower.offset == 0.0


# ---------------------------------------------------------------------- errors with their location


def test_programme_not_summing_to_360():
    data = brief_73()
    data["cam"]["programme"][3]["angle_deg"] = 50.0           # 350° in all
    err = only_error(CamBrief, data)
    # at the segment to change (was: at the section)
    assert err["loc"] == ("cam", "programme", 3, "angle_deg")
    assert "350" in err["msg"] and "360" in err["msg"] and "make the last segment 60°" in err["msg"]


def test_dwell_with_a_law():
    data = brief_73()
    data["cam"]["programme"][1]["law"] = "cycloidal"
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "programme", 1, "law")
    assert "dwell has no motion law" in err["msg"]


def test_dwell_with_a_lift():
    data = brief_73()
    data["cam"]["programme"][1]["lift_mm"] = 5.0
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "programme", 1, "lift_mm") and "dwell has no lift" in err["msg"]


def test_rise_without_a_law():
    data = brief_73()
    del data["cam"]["programme"][0]["law"]
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "programme", 0, "law")
    assert "rise needs `law`" in err["msg"] and "cycloidal" in err["msg"]


def test_unknown_law_rejected():
    data = brief_73()
    data["cam"]["programme"][2]["law"] = "uniform"
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "programme", 2, "law") and err["type"] == "literal_error"


def test_roller_without_roller_radius():
    data = brief_73()
    del data["cam"]["follower"]["roller_radius_mm"]
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "follower", "roller_radius_mm") and "roller_radius_mm > 0" in err["msg"]


def test_knife_with_a_roller_radius():
    data = brief_73()
    data["cam"]["follower"]["contact"] = "knife"
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "follower", "roller_radius_mm") and "remove roller_radius_mm" in err["msg"]


def test_translating_without_stroke():
    data = brief_73()
    del data["cam"]["follower"]["stroke_h_mm"]
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "follower", "stroke_h_mm") and "stroke_h_mm" in err["msg"]


def test_translating_with_oscillating_fields():
    data = brief_73()
    data["cam"]["follower"]["arm_length_mm"] = 120.0
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "follower", "arm_length_mm") and "arm_length_mm" in err["msg"]


def test_oscillating_without_pivot_distance():
    data = brief_shaper_cam()
    del data["cam"]["follower"]["pivot_distance_mm"]
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "follower", "pivot_distance_mm") and "pivot_distance_mm" in err["msg"]


def test_oscillating_with_stroke_or_offset():
    data = brief_shaper_cam()
    data["cam"]["follower"]["offset_mm"] = 5.0
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "follower", "offset_mm") and "offset_mm" in err["msg"]


def test_lift_deg_given_to_a_translating_follower():
    data = brief_73()
    data["cam"]["programme"][0]["lift_deg"] = 10.0
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "programme", 0, "lift_deg")       # was: ("cam",), "programme.0" in the text
    assert "lift_mm, not lift_deg" in err["msg"]


def test_lift_mm_given_to_an_oscillating_follower():
    data = brief_shaper_cam()
    data["cam"]["programme"][0]["lift_mm"] = 10.0
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "programme", 0, "lift_mm") and "lift_deg, not lift_mm" in err["msg"]


def test_returns_not_closing():
    """Rise 30 mm, return only 20 mm: the follower ends at 10 mm, not at the start."""
    data = brief_73()
    data["cam"]["programme"][2]["lift_mm"] = 20.0
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "programme", 2, "lift_mm") and "returns must undo the rises" in err["msg"]
    assert "make this lift_mm 30" in err["msg"]
    data["cam"]["programme"][2]["lift_mm"] = 40.0            # below the start
    err = only_error(CamBrief, data)
    # was: at the section, "programme.2 … outside 0 …"; now at the field, saying which side
    assert err["loc"] == ("cam", "programme", 2, "lift_mm") and "below its lowest position 0" in err["msg"]
    assert "at most 30" in err["msg"]


def test_rise_beyond_the_stroke():
    data = brief_73()
    data["cam"]["programme"][0]["lift_mm"] = 35.0
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "programme", 0, "lift_mm") and "at most 30" in err["msg"]


def test_negative_offset():
    data = brief_73()
    data["cam"]["follower"]["offset_mm"] = -12.0
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "follower", "offset_mm") and "offset_mm must be ≥ 0" in err["msg"]


def test_bad_base_radius():
    data = brief_73()
    data["cam"]["base_radius_mm"] = 0.0
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "base_radius_mm") and "base_radius_mm" in err["msg"]
    data["cam"]["base_radius_mm"] = "automatic"
    errs = errors_of(CamBrief, data)
    assert all(e["loc"][:2] == ("cam", "base_radius_mm") for e in errs)


def test_unknown_key_rejected():
    data = brief_73()
    data["cam"]["follower"]["colour"] = "red"
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "follower", "colour") and err["type"] == "extra_forbidden"
    data = brief_73()
    data["cam"]["programme"][0]["lift"] = 30.0
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "programme", 0, "lift") and err["type"] == "extra_forbidden"


def test_programme_needs_two_segments():
    data = brief_73()
    data["cam"]["programme"] = [{"motion": "rise", "angle_deg": 360.0, "law": "cycloidal"}]
    err = only_error(CamBrief, data)
    assert err["loc"] == ("cam", "programme") and err["type"] == "too_short"


def test_section_validates_on_its_own():
    """CamSection (as a machine brief carries it) gives the same errors, rooted at ()."""
    data = brief_73()["cam"]
    data["programme"][3]["angle_deg"] = 50.0
    err = only_error(CamSection, data)
    assert err["loc"] == ("programme", 3, "angle_deg") and "360" in err["msg"]


# ---------------------------------------------------------------------- eccentric disc brief


def brief_71() -> dict:
    return {
        "machine": "eccentric_cam",
        "report": dict(REPORT),
        "disc": {"radius_R_mm": 40.0, "eccentricity_mm": 20.0, "rotation": "ccw"},
        "followers": [
            {"label": "(a)", "contact": "knife"},
            {"label": "(b)", "contact": "knife", "offset_mm": 15.0, "offset_side": "left"},
            {"label": "(c)", "contact": "roller", "roller_radius_mm": 20.0},
        ],
        "query_angles_deg": [0.0, 45.0],
        "table_step_deg": 18.0,
    }


def test_eccentric_brief_converts_to_si():
    """7-1: R = 0.040 m, ε = 0.020 m, followers knife e = 0, knife e = −0.015 m (left),
    roller r_r = 0.020 m; query angles and the 18° table step in radians."""
    p = eccentric_to_si(EccentricCamBrief.model_validate(brief_71()))
    assert p.radius == pytest.approx(0.040, rel=1e-15)
    assert p.eccentricity == pytest.approx(0.020, rel=1e-15)
    assert p.rotation == 1
    assert [label for label, _ in p.followers] == ["(a)", "(b)", "(c)"]
    assert p.followers[0][1] == TranslatingFollower("knife", 0.0, 0.0)
    assert p.followers[1][1] == TranslatingFollower("knife", -0.015, 0.0)
    assert p.followers[2][1] == TranslatingFollower("roller", 0.0, 0.020)
    np.testing.assert_allclose(p.query_angles, [0.0, math.pi / 4], rtol=1e-15)
    assert p.table_step == pytest.approx(math.pi / 10, rel=1e-15)


@pytest.mark.parametrize("eps", [40.0, 55.0])
def test_eccentricity_not_below_radius_rejected(eps):
    data = brief_71()
    data["disc"]["eccentricity_mm"] = eps
    err = only_error(EccentricCamBrief, data)
    assert err["loc"] == ("disc", "eccentricity_mm") and "eccentricity_mm must be smaller than radius_R_mm" in err["msg"]


def test_eccentric_roller_without_radius_and_unknown_key():
    data = brief_71()
    data["followers"][2]["roller_radius_mm"] = 0.0
    err = only_error(EccentricCamBrief, data)
    assert err["loc"] == ("followers", 2, "roller_radius_mm") and "roller_radius_mm > 0" in err["msg"]
    data = brief_71()
    data["disc"]["centre"] = [0, -20]
    err = only_error(EccentricCamBrief, data)
    assert err["loc"] == ("disc", "centre") and err["type"] == "extra_forbidden"


# ---------------------------------------------------------------------- through parse_brief


def test_cam_machines_are_registered():
    assert BRIEF_MODELS["cam"] is CamBrief
    assert BRIEF_MODELS["eccentric_cam"] is EccentricCamBrief


def test_load_brief_reads_the_73_yaml(tmp_path):
    """A YAML file with `offset_mm: auto` and `base_radius_mm: auto` loads through load_brief."""
    data = brief_73()
    data["cam"]["follower"]["offset_mm"] = "auto"
    data["cam"]["base_radius_mm"] = "auto"
    path = tmp_path / "cam.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    p = cam_to_si(load_brief(path).cam)
    assert p.auto_offset is True and p.base_radius is None
    assert p.programme.stroke == pytest.approx(0.030, rel=1e-15)


def test_parse_brief_unknown_machine_lists_the_cam_machines():
    data = brief_73()
    data["machine"] = "cams"
    with pytest.raises(BriefError) as info:
        parse_brief(data)
    (pr,) = info.value.problems
    assert pr.path == "machine" and "cam" in pr.allowed and "eccentric_cam" in pr.allowed


def test_parse_brief_accepts_the_73_brief():
    b = parse_brief(brief_73())
    assert isinstance(b, CamBrief)
    assert cam_to_si(b.cam).follower.offset == pytest.approx(0.012, rel=1e-15)
    assert isinstance(parse_brief(brief_71()), EccentricCamBrief)


def test_parse_brief_reports_every_cam_problem_with_its_path():
    """Problems in different sub-models are reported together, each with its dotted path;
    the follower's cross-field check is reported at 'cam.follower', a dwell's at
    'cam.programme.1', an unknown key at its own path."""
    data = brief_73()
    data["cam"]["follower"]["offset_mm"] = -12.0
    data["cam"]["programme"][1]["law"] = "cycloidal"
    data["cam"]["programme"][2]["speed"] = 3
    with pytest.raises(BriefError) as info:
        parse_brief(data)
    got = {pr.path: pr for pr in info.value.problems}
    # cross-field problems at the field to change (were at cam.follower, cam.programme.1)
    assert set(got) == {"cam.follower.offset_mm", "cam.programme.1.law", "cam.programme.2.speed"}
    assert "offset_mm must be ≥ 0" in got["cam.follower.offset_mm"].allowed
    assert got["cam.follower.offset_mm"].value == "-12"
    assert "dwell has no motion law" in got["cam.programme.1.law"].allowed
    assert got["cam.programme.2.speed"].value == "3"
    assert "unknown field" in got["cam.programme.2.speed"].allowed


# The loader's _field_info walks the error location through nested models but stops at any
# annotation that is not a BaseModel class itself: list[CamSegment] (cam.programme.N…),
# list[DiscFollower] (followers.N…) and Optional[CamSection] (the shaper brief's cam). Below
# those it reports the *parent's* fields as "allowed here" and the parent field's description
# as the unit of the offending field.
# Problems below list items and optional sections name the item's own fields and units.


def test_unknown_key_in_a_programme_segment_lists_the_segment_fields():
    data = brief_73()
    data["cam"]["programme"][2]["speed"] = 3
    with pytest.raises(BriefError) as info:
        parse_brief(data)
    (pr,) = info.value.problems
    assert pr.path == "cam.programme.2.speed"
    # CamSegment's fields, not CamSection's (rotation, speed_rpm, base_radius_mm, …)
    assert "angle_deg" in pr.allowed and "lift_mm" in pr.allowed
    assert "base_radius_mm" not in pr.allowed


def test_range_error_in_a_programme_segment_shows_its_own_unit():
    data = brief_73()
    data["cam"]["programme"][0]["angle_deg"] = -5.0
    with pytest.raises(BriefError) as info:
        parse_brief(data)
    (pr,) = info.value.problems
    assert pr.path == "cam.programme.0.angle_deg"
    assert "Cam angle of the segment [°]" in pr.allowed


def test_shaper_cam_section_unknown_key_lists_the_follower_fields():
    """Through the registered shaper machine: an unknown key in cam.follower must list the
    follower's fields, not the shaper brief's top-level sections."""
    data = shaper_with_cam()
    data["cam"]["follower"]["colour"] = "red"
    with pytest.raises(BriefError) as info:
        parse_brief(data)
    (pr,) = info.value.problems
    assert pr.path == "cam.follower.colour"
    assert "roller_radius_mm" in pr.allowed and "linkage" not in pr.allowed


def test_parse_brief_section_level_problem_is_reported_at_cam():
    """The programme-closure check is a CamSection model check: reported at path 'cam'."""
    data = brief_73()
    data["cam"]["programme"][2]["lift_mm"] = 20.0
    with pytest.raises(BriefError) as info:
        parse_brief(data)
    (pr,) = info.value.problems
    assert pr.path == "cam.programme.2.lift_mm" and "returns must undo the rises" in pr.allowed


def test_parse_brief_eccentric_problem():
    data = brief_71()
    data["disc"]["eccentricity_mm"] = 45.0
    with pytest.raises(BriefError) as info:
        parse_brief(data)
    (pr,) = info.value.problems
    assert pr.path == "disc.eccentricity_mm" and "eccentricity_mm must be smaller" in pr.allowed


def shaper_with_cam() -> dict:
    """designs/shaper.yaml as data (7.0e4 set as a number, as in test_brief.py) with the
    seed-000 cam section added."""
    data = yaml.safe_load(SHAPER.read_text(encoding="utf-8"))
    data["flywheel"]["specific_weight_N_m3"] = 70000.0
    data["cam"] = copy.deepcopy(brief_shaper_cam()["cam"])
    data["cam"]["rotation"] = data["linkage"]["crank_rotation"]
    return data


def test_shaper_brief_carries_a_cam_section():
    """The shaper brief (registered machine) accepts the seed-000 cam section; parse_brief
    reports a cam problem inside it at 'cam.…'."""
    data = shaper_with_cam()
    b = parse_brief(data)
    p = cam_to_si(b.cam, speed_rpm=b.linkage.crank_speed_n2_rpm)
    assert p.omega == pytest.approx(80 * 2 * math.pi / 60, rel=1e-15)
    assert p.follower == OscillatingFollower("roller", 0.136, 0.120, 0.015, "same")
    del data["cam"]["follower"]["arm_length_mm"]
    with pytest.raises(BriefError) as info:
        parse_brief(data)
    (pr,) = info.value.problems
    assert pr.path == "cam.follower.arm_length_mm" and "arm_length_mm" in pr.allowed
    assert pr.value == "missing"
