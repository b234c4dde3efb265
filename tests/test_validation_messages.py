"""Every validation message goes through the project's own formatter (issue 21, point 3):
bad briefs derived from every example — wrong types, out-of-range values and cross-field
contradictions in each section — are refused by ``mechdesign check`` and ``mechdesign run``
with exit 2, each problem at the exact field that must change, with its value and what is
allowed, in the brief's language; never pydantic's wording, a URL, a traceback,
``(top level)`` or a section's repr.

Each case: an example, the changes made to it (dotted path → value, ``DELETE`` to remove
the key) and the field paths the message must name (all of them: every problem of a section
is reported at once).
"""
from __future__ import annotations

import copy
import re
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.brief.loader import BriefError, load_variant, read_brief_data
from mechdesign.cli import app

ROOT = Path(__file__).resolve().parents[1]
runner = CliRunner()
DELETE = object()
CJK = re.compile(r"[\u4e00-\u9fff]")
#: what must never reach the user from validation
FORBIDDEN = ("pydantic", "errors.pydantic.dev", "Traceback", "(top level)", "{'", "Input should",
             "Value error", "validation error for", "[type=")

#: Sections whose validators live in modules other helpers edit now (issue 21 point 3 is
#: not done there yet): the problem still lands at the section, or in English only.
PENDING = "cross-field check in brief/guide_bar.py, brief/linkage.py or machines/crank_rocker (not converted yet)"

CASES = [
    # --- cam (stand-alone cam brief, 7-3)
    ("cam_7_3", {"cam.follower.roller_radius_mm": DELETE}, ["cam.follower.roller_radius_mm"]),
    ("cam_7_3", {"cam.follower.offset_mm": -12}, ["cam.follower.offset_mm"]),
    ("cam_7_3", {"cam.programme.3.angle_deg": 50}, ["cam.programme.3.angle_deg"]),
    ("cam_7_3", {"cam.programme.1.law": "cycloidal", "cam.programme.1.lift_mm": 5,
                 "cam.follower.contact": "knife"},
     ["cam.programme.1.law", "cam.programme.1.lift_mm", "cam.follower.roller_radius_mm"]),
    ("cam_7_3", {"cam.programme.0.law": DELETE}, ["cam.programme.0.law"]),
    ("cam_7_3", {"cam.programme.2.lift_mm": 40}, ["cam.programme.2.lift_mm"]),
    ("cam_7_3", {"cam.programme.2.lift_mm": 20}, ["cam.programme.2.lift_mm"]),
    ("cam_7_3", {"cam.programme.0.lift_mm": 35}, ["cam.programme.0.lift_mm"]),
    ("cam_7_3", {"cam.programme.2.motion": "rise"}, ["cam.programme.2.motion"]),
    ("cam_7_3", {"cam.programme.0.lift_deg": 10}, ["cam.programme.0.lift_deg"]),
    ("cam_7_3", {"cam.base_radius_mm": 0}, ["cam.base_radius_mm"]),
    ("cam_7_3", {"cam.base_radius_mm": "big"}, ["cam.base_radius_mm"]),
    ("cam_7_3", {"cam.follower.arm_length_mm": 120, "cam.follower.stroke_h_mm": DELETE},
     ["cam.follower.arm_length_mm", "cam.follower.stroke_h_mm"]),
    ("cam_7_3", {"cam.follower.motion": "oscillating"},
     ["cam.follower.max_swing_deg", "cam.follower.pivot_distance_mm",
      "cam.follower.arm_length_mm", "cam.follower.stroke_h_mm", "cam.follower.offset_mm"]),
    ("cam_7_3", {"cam.follower.stroke_h_mm": "30 mm"}, ["cam.follower.stroke_h_mm"]),
    ("cam_7_3", {"cam.rotation": "clockwise"}, ["cam.rotation"]),
    ("cam_7_3", {"cam.programme": "rise"}, ["cam.programme"]),
    ("cam_7_3", {"cam.follower": 5}, ["cam.follower"]),
    ("cam_7_3", {"cam.programme.0": "rise"}, ["cam.programme.0"]),
    ("cam_7_3", {"cam.limits.pressure_angle_rise_deg": 95}, ["cam.limits.pressure_angle_rise_deg"]),
    ("cam_7_3", {"cam.limits": [1, 2]}, ["cam.limits"]),
    ("lockbeam_cam", {"cam.follower.contact": "flat"}, ["cam.follower.roller_radius_mm"]),
    ("lockbeam_cam", {"report.language": "fr"}, ["report.language"]),
    ("lockbeam_cam", {"report": "me"}, ["report"]),
    ("lockbeam_cam", {"cam.programme.0.motion": "return"}, ["cam.programme.0.law"]),
    ("lockbeam_cam", {"cam.programme.0.motion": "return", "cam.programme.0.law": "poly345",
                      "cam.programme.0.lift_mm": 5},
     ["cam.programme.0.motion"]),
    # --- eccentric disc (7-1)
    ("cam_7_1", {"disc.eccentricity_mm": 45}, ["disc.eccentricity_mm"]),
    ("cam_7_1", {"followers.2.roller_radius_mm": DELETE, "followers.0.roller_radius_mm": 5},
     ["followers.2.roller_radius_mm", "followers.0.roller_radius_mm"]),
    ("cam_7_1", {"followers": []}, ["followers"]),
    ("cam_7_1", {"query_angles_deg": [0, "ninety"]}, ["query_angles_deg.1"]),
    # --- drive (furnace drive)
    ("furnace_drive", {"load.power_kW": 1.0}, ["load.stroke"]),
    ("furnace_drive", {"load.stroke": DELETE}, ["load.power_kW"]),
    ("furnace_drive", {"drive.stages.1.d1_mm": 100, "drive.stages.2.z2": 10},
     ["drive.stages.1.d1_mm", "drive.stages.2.z2"]),
    ("furnace_drive", {"drive.stages.2.ratio": 3, "drive.stages.2.z2": 60}, ["drive.stages.2.ratio"]),
    ("furnace_drive", {"drive.stages.2.pinion_material": "unobtainium"},
     ["drive.stages.2.pinion_material"]),
    ("furnace_drive", {"drive.stages.0.type": "gearbox"}, ["drive.stages.0.type"]),
    ("furnace_drive", {"drive.stages.1.z1": 0}, ["drive.stages.1.z1"]),
    ("furnace_drive", {"drive.stages.2.module_mm": "large"}, ["drive.stages.2.module_mm"]),
    ("furnace_drive", {"drive.motor.synchronous_rpm": 1200}, ["drive.motor.synchronous_rpm"]),
    # --- die cutter
    ("die_cutter", {"incomplete_gear.teeth_present": 45}, ["incomplete_gear.teeth_present"]),
    ("die_cutter", {"incomplete_gear.feed_mm": 300}, ["incomplete_gear.sprocket_pitch_radius_mm"]),
    ("die_cutter", {"incomplete_gear.motion_span_deg": 150}, ["incomplete_gear.motion_span_deg"]),
    ("die_cutter", {"gripper_cam.programme.0.angle_deg": 40}, ["gripper_cam.programme.3.angle_deg"]),
    ("die_cutter", {"flywheel.fluctuation_delta": "1/0"}, ["flywheel.fluctuation_delta"]),
    ("die_cutter", {"press.clearance_mm": 60}, ["press.clearance_mm"]),
    # --- lockbeam: cycle diagram, morphology, cams
    ("lockbeam", {"production.groove_diameter_mm": 12}, ["production.groove_diameter_mm"]),
    ("lockbeam", {"cam.programme.1.lift_mm": 12}, ["cam.programme.1.lift_mm"]),
    ("lockbeam", {"bending_cam.follower.stroke_h_mm": 10}, ["bending_cam.follower.stroke_h_mm"]),
    ("lockbeam", {"cycle.actuators.1.phases.0.span_deg": 160},
     ["cycle.actuators.1.phases.3.span_deg"]),
    ("lockbeam", {"cycle.actuators.2.key": "feed", "cycle.constraints.0.b.state": "move",
                  "cycle.constraints.1.a.actuator": "arm"},
     ["cycle.actuators.2.key", "cycle.constraints.0.b.state", "cycle.constraints.1.a.actuator"]),
    ("lockbeam", {"cycle.constraints.0.a.occurrence": 2}, ["cycle.constraints.0.a.occurrence"]),
    ("lockbeam", {"morphology.functions.0.chosen": 7}, ["morphology.functions.0.chosen"]),
    # --- guide-bar machines, crank-rocker, linkage, furnace pusher
    ("shaper", {"gear_pair.z1": 1000}, ["gear_pair.z2"]),
    ("shaper", {"masses.ram_m6_kg": -1}, ["masses.ram_m6_kg"]),
    ("shaper", {"flywheel.fluctuation_delta": "a lot"}, ["flywheel.fluctuation_delta"]),
    ("shaper", {"cam.rotation": "ccw"}, ["cam.rotation"]),
    ("shaper", {"cam.programme.0.lift_mm": 10}, ["cam.programme.0.lift_mm"]),
    ("slotter", {"gear_pair.module_mm": 0}, ["gear_pair.module_mm"]),
    ("furnace_pusher", {"pusher.stroke_H_mm": "220 mm"}, ["pusher.stroke_H_mm"]),
    ("furnace_pusher", {"drive.stages.2.z1": 80, "drive.stages.2.z2": 40}, ["drive.stages.2.z2"]),
    ("crank_rocker", {"chart.theta_deg": [0, 95]}, ["chart.theta_deg"]),
    ("linkage_sixbar", {"linkage.crank.pivot": "Z"}, ["linkage.crank.pivot"]),
    ("press", {"linkage.ratio_EF_DE": -0.25}, ["linkage.ratio_EF_DE"]),
    ("press", {"masses.ram_G5_N": "300 N"}, ["masses.ram_G5_N"]),
    ("shaper_lengths", {"linkage.crank_O2A_mm": 400}, ["linkage.crank_O2A_mm"]),
    ("shaper_lengths", {"masses.ram_m6_kg": 80}, ["masses.ram_G6_N"]),   # both: one must go
    ("textbook_guide_bar", {"analysis.points": ["B", "B"]}, ["analysis.points"]),
    ("textbook_guide_bar", {"analysis.points": ["Q"]}, ["analysis.points.0"]),
    ("linkage_sixbar", {"linkage.masses.0.mass_kg": -8}, ["linkage.masses.0.mass_kg"]),
]


def _set(data, path: str, value) -> None:
    parts = [int(p) if p.isdigit() else p for p in path.split(".")]
    node = data
    for part in parts[:-1]:
        node = node[part]
    if value is DELETE:
        del node[parts[-1]]
    else:
        node[parts[-1]] = value


def _brief(tmp_path: Path, example: str, changes: dict, lang: str) -> Path:
    data = copy.deepcopy(read_brief_data(ROOT / "designs" / f"{example}.yaml"))
    data.pop("groups", None)
    for path, value in changes.items():
        _set(data, path, value)
    if isinstance(data.get("report"), dict):
        data["report"]["language"] = data["report"].get("language") if "report.language" in changes else lang
    target = tmp_path / f"{example}_bad.yaml"
    target.write_text(yaml.safe_dump(data, allow_unicode=True, sort_keys=False), encoding="utf-8")
    return target


def _params():
    for i, case in enumerate(CASES):
        example, changes, paths, *pending = case
        marks = [pytest.mark.xfail(reason=pending[0], strict=True)] if pending else []
        yield pytest.param(example, changes, paths, marks=marks,
                           id=f"{i:02d}-{example}-{'+'.join(changes)}"[:90])


def test_the_corpus_covers_every_example_and_enough_briefs():
    examples = {p.stem for p in (ROOT / "designs").glob("*.yaml")}
    assert {c[0] for c in CASES} == examples
    assert len(CASES) >= 30


@pytest.mark.parametrize("example, changes, paths", list(_params()))
def test_bad_brief_is_refused_at_its_fields_in_its_language(tmp_path, example, changes, paths):
    for lang in ("zh", "en"):
        brief = _brief(tmp_path, example, changes, lang)
        # the problems themselves: each at its field, with Chinese text
        with pytest.raises(BriefError) as info:
            load_variant(brief)
        problems = info.value.problems
        found = [p.path for p in problems]
        for path in paths:
            assert path in found, (path, found)
        for p in problems:
            assert p.allowed_zh and CJK.search(p.allowed_zh), p
        # the CLI: exit 2, the formatter's lines only
        out = tmp_path / "out"
        for args in (["check", str(brief)], ["run", str(brief), "-o", str(out), "-f", "md"]):
            result = runner.invoke(app, args)
            text = result.output
            assert result.exit_code == 2, text
            assert isinstance(result.exception, SystemExit), repr(result.exception)
            for bad in FORBIDDEN:
                assert bad not in text, (bad, text)
            zh = "任务书中有" in text           # the brief's language (zh when it gives none)
            assert zh == (lang == "zh" or not isinstance(changes.get("report", {}), dict)
                          or changes.get("report.language") not in (None, "en")), text
            sep = "：" if zh else ": "
            for path in paths:
                assert f"  {path}{sep}" in text, (path, text)
            lines = [ln for ln in text.splitlines() if ln.startswith("  ")]
            assert len(lines) >= len(paths)
            if zh:
                assert all(CJK.search(ln.split("—", 1)[-1]) for ln in lines), text
            assert not out.exists()


def test_advice_goes_the_right_way():
    """The texts say what to change with the right numbers (hand-checked): the 7-3 programme
    with the last dwell 50° instead of 60° adds up to 350°, so that dwell must be 60°; a
    rise of 35 mm on a 30 mm stroke may lift at most 30; a return of 40 mm after a 30 mm rise
    may fall at most 30; a return of 20 mm leaves the follower at 10, so it must be 30."""
    import mechdesign.brief.loader as loader

    def problem(changes):
        data = yaml.safe_load((ROOT / "designs" / "cam_7_3.yaml").read_text(encoding="utf-8"))
        for path, value in changes.items():
            _set(data, path, value)
        with pytest.raises(BriefError) as info:
            loader.parse_brief(data)
        (p,) = info.value.problems
        return p

    p = problem({"cam.programme.3.angle_deg": 50})
    assert "350°" in p.allowed and "make the last segment 60° instead of 50°" in p.allowed
    assert "将最后一段由 50° 改为 60°" in p.allowed_zh
    p = problem({"cam.programme.0.lift_mm": 35})
    assert p.value == "35" and "above its stroke 30" in p.allowed and "at most 30" in p.allowed
    p = problem({"cam.programme.2.lift_mm": 40})
    assert "below its lowest position 0" in p.allowed and "at most 30" in p.allowed
    p = problem({"cam.programme.2.lift_mm": 20})
    assert "ends at 10" in p.allowed and "make this lift_mm 30" in p.allowed
    p = problem({"cam.follower.offset_mm": -12})
    assert "write 12" in p.allowed and "offset_side" in p.allowed
