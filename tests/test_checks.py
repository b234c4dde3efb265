"""Validation never runs the engine; a machine's feasibility checks run once per run.

Issue 17 point 4: `mechdesign check` validates the brief alone (fields and the closed-form
rules between them, every problem at once, each at its field); whether the data admit a
design (the furnace six-bar's synthesis, the die-cutter's toggle press, the lock-beam's
feed assembly and bending synthesis) is asked once, by the run, after validation, and
every problem is reported in one message with its field path, its value and what to
change, in the report's language (exit 2).
"""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.brief.loader import BriefError, Variant, parse_brief, read_brief_data
from mechdesign.cli import app
from mechdesign.machines import get_machine, stages_for
from mechdesign.pipeline import run_stages
from mechdesign.runner import feasibility

ROOT = Path(__file__).resolve().parents[1]
DESIGNS = ROOT / "designs"
CJK = re.compile(r"[\u4e00-\u9fff]")


def example(name: str, keep_groups: bool = False) -> dict:
    data = read_brief_data(DESIGNS / name)
    if not keep_groups:
        data.pop("groups", None)
    return data


def write(tmp_path: Path, data: dict, name: str = "brief.yaml") -> Path:
    path = tmp_path / name
    path.write_text(yaml.safe_dump(data, allow_unicode=True, sort_keys=False), encoding="utf-8")
    return path


def lockbeam_two_problems() -> dict:
    """The feed's guide bar offset 60 mm > |d − a| = 100 − 50 = 50 mm (no assembly), and
    the bending rocker and coupler confined to 20…30 mm (no synthesis)."""
    data = example("lockbeam.yaml")
    data["feed_linkage"]["groups"][0]["offset_mm"] = 60
    data["bending"]["link_length_range_mm"] = [20, 30]
    return data


def run_cli(*args: str):
    return CliRunner().invoke(app, ["run", *args, "-f", "md"])


# ---------------------------------------------------------------- validation alone


def test_check_accepts_a_brief_only_the_run_finds_infeasible(tmp_path):
    """Validation runs no synthesis: both infeasible points pass `check` (its docs say it
    computes nothing), and the run rejects them."""
    path = write(tmp_path, lockbeam_two_problems())
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 0, result.output


def test_two_infeasible_points_in_one_message_with_both_paths(tmp_path):
    path = write(tmp_path, lockbeam_two_problems())
    result = run_cli(str(path), "-o", str(tmp_path / "out"), "--lang", "en")
    assert result.exit_code == 2
    text = result.output
    assert "the design is infeasible with the brief's data (2 problems)" in text
    feed = re.search(r"^  feed_linkage\.groups: (.*)$", text, re.M)
    bend = re.search(r"^  bending\.start: auto — (.*)$", text, re.M)
    assert feed and bend, text
    assert "offset 60 mm" in feed.group(1) and "|d − a| = 50 mm" in feed.group(1)
    assert "20 and 30 mm" in bend.group(1) and "widen the length range" in bend.group(1)
    assert "Traceback" not in text and not (tmp_path / "out").exists()
    assert "按任务书" not in text and "综合无实解" not in text


def test_a_zh_brief_gets_the_problems_in_chinese(tmp_path):
    """lockbeam.yaml says report.language: zh; no --lang: the message is Chinese."""
    path = write(tmp_path, lockbeam_two_problems())
    result = run_cli(str(path), "-o", str(tmp_path / "out"))
    assert result.exit_code == 2
    text = result.output
    assert "按任务书数据无法完成设计（2 处问题）" in text
    feed = re.search(r"^  feed_linkage\.groups：(.*)$", text, re.M)
    bend = re.search(r"^  bending\.start：auto — (.*)$", text, re.M)
    assert feed and bend, text
    assert "偏距 60 mm" in feed.group(1) and "50 mm 以内" in feed.group(1)
    assert "综合无实解" in bend.group(1) and "应放宽杆长范围" in bend.group(1)


def test_a_problem_set_by_a_data_group_is_reported_where_the_group_sets_it(tmp_path):
    """Group 3 of the furnace brief with H = 2400 mm: 2·DC = 2300 mm cannot hold the chord."""
    data = example("furnace_pusher.yaml", keep_groups=True)
    data["groups"]["variants"][3]["pusher.stroke_H_mm"] = 2400
    path = write(tmp_path, data)
    assert CliRunner().invoke(app, ["check", str(path)]).exit_code == 0
    result = run_cli(str(path), "--group", "3", "-o", str(tmp_path / "out"), "--lang", "en")
    assert result.exit_code == 2
    line = re.search(r"^  (\S+): (\S+) — (.*)$", result.output, re.M)
    assert line, result.output
    assert line.group(1) == "groups.variants.3.pusher.stroke_H_mm" and line.group(2) == "2400"
    assert "2·DC = 2300 mm" in line.group(3)
    assert "(group 3)" in result.output


def test_cross_field_rules_are_all_reported_at_once_each_at_its_field():
    """Die cutter: clearance 3 mm < pressing travel, the cam turning the other way and a
    flywheel shaft the drive does not have: three problems, three exact paths, zh text."""
    data = example("die_cutter.yaml")
    data["press"]["clearance_mm"] = 3
    data["gripper_cam"]["rotation"] = "ccw"
    data["flywheel"]["shaft"] = 5
    with pytest.raises(BriefError) as info:
        parse_brief(data, "x.yaml")
    got = {p.path: p for p in info.value.problems}
    assert set(got) == {"press.clearance_mm", "gripper_cam.rotation", "flywheel.shaft"}
    assert got["press.clearance_mm"].value == "3" and "pressing travel" in got["press.clearance_mm"].allowed
    assert got["flywheel.shaft"].value == "5" and "0 (motor) … 3" in got["flywheel.shaft"].allowed
    for p in got.values():
        assert p.allowed_zh and CJK.search(p.allowed_zh), p


def test_lockbeam_cross_section_rules_all_at_once():
    data = example("lockbeam.yaml")
    data["cam"]["speed_rpm"] = 7
    data["cycle"]["shaft_speed_rpm"] = 9
    with pytest.raises(BriefError) as info:
        parse_brief(data, "x.yaml")
    paths = [p.path for p in info.value.problems]
    assert paths == ["cam.speed_rpm", "cycle.shaft_speed_rpm"]
    assert "production.rate_per_min" in info.value.problems[0].allowed_zh


def test_brief_validation_imports_no_machine_and_no_engine():
    """`mechdesign check` of every example (every group) in a fresh process loads none of
    the engine and no machine's computation: of a machine written as one package only its
    brief model (``mechdesign.machines.<name>.brief``, with the package's registry entry)."""
    code = ("import sys, glob\n"
            "from typer.testing import CliRunner\n"
            "from mechdesign.cli import app\n"
            "r = CliRunner().invoke(app, ['check', *sorted(glob.glob('designs/*.yaml'))])\n"
            "assert r.exit_code == 0, r.output\n"
            "print(' '.join(m for m in sys.modules if m.startswith(('mechdesign.machines', "
            "'mechdesign.core.mechanism', 'mechdesign.core.kinematics', "
            "'mechdesign.core.kinetostatics', 'mechdesign.pipeline'))))\n")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                         check=True)
    loaded = set(out.stdout.split())
    assert "mechdesign.machines.slotter.brief" in loaded     # the scan sees machine packages
    packages = {m.split(".")[2] for m in loaded if m.count(".") >= 2}
    allowed = {"mechdesign.machines"} | {f"mechdesign.machines.{p}" for p in packages} \
        | {f"mechdesign.machines.{p}.brief" for p in packages}
    assert loaded <= allowed, sorted(loaded - allowed)


# ---------------------------------------------------------------- once per run


def _count(monkeypatch, module, name: str, where=None) -> list:
    calls = []
    original = getattr(module, name)

    def counted(*args, **kwargs):
        if where is None or where(*args):
            calls.append(args)
        return original(*args, **kwargs)

    monkeypatch.setattr(module, name, counted)
    return calls


def _compute(name: str):
    b = parse_brief(example(name))
    m = get_machine(b.machine)
    p = m.to_params(b)
    problems, checked = feasibility(m, p, Variant(b, None, ()))
    assert problems == []
    results, _ = run_stages(stages_for(m, p), {"params": p, "brief": b, "checked": checked})
    return p, results


def test_the_furnace_synthesis_runs_once(monkeypatch):
    from mechdesign.machines.furnace_pusher import stages as furnace

    calls = _count(monkeypatch, furnace, "synthesize")
    _, r = _compute("furnace_pusher.yaml")
    assert len(calls) == 1 and r["synthesis"].crank > 0


def test_the_toggle_synthesis_runs_once(monkeypatch):
    from mechdesign.machines.die_cutter import stages as die_cutter

    calls = _count(monkeypatch, die_cutter, "toggle_synthesis")
    _, r = _compute("die_cutter.yaml")
    assert len(calls) == 1 and r["toggle"].swing > 0


def test_the_lockbeam_feed_motion_and_bending_synthesis_run_once(monkeypatch):
    from mechdesign.stages import linkage
    from mechdesign.machines.lockbeam import stages as lockbeam

    lockbeam.synthesise_bending.cache_clear()
    bend = _count(monkeypatch, lockbeam, "synthesise_bending")
    feed = []
    original = linkage.motion

    def motion(model):
        if getattr(model.output, "name", None) is not None and model is params_feed[0]:
            feed.append(model)
        return original(model)

    params_feed: list = [None]
    b = parse_brief(example("lockbeam.yaml"))
    m = get_machine("lockbeam")
    p = m.to_params(b)
    params_feed[0] = p.feed
    monkeypatch.setattr(linkage, "motion", motion)
    problems, checked = feasibility(m, p, Variant(b, None, ()))
    assert problems == []
    r, _ = run_stages(stages_for(m, p), {"params": p, "brief": b, "checked": checked})
    assert len(bend) == 1 and len(feed) == 1
    assert r["feed"] is checked["feed_motion"][0] and r["bending"] is not None


@pytest.mark.parametrize("machine", ["shaper", "slotter"])
def test_guide_bar_cross_field_problems_all_at_once_in_the_brief_language(machine, tmp_path):
    """The guide-bar briefs' cross-field rules (polygon positions, module with a drive, the
    cam on the crank shaft) report every problem at once, each at its field with its value,
    in Chinese for a zh brief."""
    import yaml

    d = yaml.safe_load((ROOT / "designs" / f"{machine}.yaml").read_text(encoding="utf-8"))
    d["sheets"]["polygon_positions"] = [4, 40]
    d["cam"]["rotation"] = "ccw"
    d["cam"]["speed_rpm"] = 55
    del d["gear_pair"]["module_mm"]
    path = tmp_path / f"{machine}.yaml"
    path.write_text(yaml.safe_dump(d, allow_unicode=True), encoding="utf-8")
    from typer.testing import CliRunner

    from mechdesign.cli import app

    res = CliRunner().invoke(app, ["check", str(path), "--lang", "zh"])
    assert res.exit_code == 2, res.output
    for field, value in (("sheets.polygon_positions.1", "40"), ("gear_pair.module_mm", "缺少"),  # a left-out field: "missing"
                         ("cam.rotation", "'ccw'"), ("cam.speed_rpm", "55")):
        assert f"{field}：{value}" in res.output, field
    assert "4 处问题" in res.output and "凸轮装在曲柄轴上" in res.output
