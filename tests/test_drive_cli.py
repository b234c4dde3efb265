"""The drive and gear sections from the command line, as a user runs them."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.cli import app

pytestmark = pytest.mark.e2e     # runs `mechdesign run` to a report (see tests/conftest.py)

ROOT = Path(__file__).resolve().parents[1]
runner = CliRunner()


def test_furnace_drive_report_prints_checks_with_verdicts(tmp_path):
    result = runner.invoke(app, ["run", str(ROOT / "designs/furnace_drive.yaml"), "--out", str(tmp_path),
                                 "--format", "md"])
    assert result.exit_code == 0, result.output
    md = (tmp_path / "report.md").read_text(encoding="utf-8")
    assert "Y801-4" in md and "蜗轮齿面接触疲劳强度" in md and "热平衡" in md
    assert md.count("| 合格 |") >= 10 and "不合格" not in md
    doc = json.loads((tmp_path / "results.json").read_text(encoding="utf-8"))
    assert doc["drive"]["total_ratio"] == pytest.approx(69.5)
    assert doc["drive"]["machine_power"] == pytest.approx(44.0)


def test_english_drive_report(tmp_path):
    result = runner.invoke(app, ["run", str(ROOT / "designs/furnace_drive.yaml"), "--out", str(tmp_path),
                                 "--format", "md", "--lang", "en"])
    assert result.exit_code == 0, result.output
    md = (tmp_path / "report.md").read_text(encoding="utf-8")
    assert "| PASS |" in md and "Worm-wheel contact fatigue" in md


def test_shaper_gear_section_matches_hand_values(tmp_path):
    """m = 12, z = 18/60: d = 216/720, da = 240/744, a = 468 mm, ε = 1.6572 (not the seed's
    1.69 measured on a drawing); the drive's power is the crank's mean power."""
    result = runner.invoke(app, ["run", str(ROOT / "designs/shaper.yaml"), "--out", str(tmp_path),
                                 "--format", "md"])
    assert result.exit_code == 0, result.output
    md = (tmp_path / "report.md").read_text(encoding="utf-8")
    assert "| 分度圆直径 | $d$ | $mz$ | 216.000 | 720.000 | mm |" in md
    assert "| 齿顶圆直径 | $d_a$ | $d+2h_a$ | 240.000 | 744.000 | mm |" in md
    assert "468.000" in md and "1.6572" in md
    assert (tmp_path / "figures/gear_mesh.png").stat().st_size > 10_000
    doc = json.loads((tmp_path / "results.json").read_text(encoding="utf-8"))
    mb = np.array(doc["grid"]["balancing_torque"])
    assert doc["drive"]["machine_power"] == pytest.approx(np.mean(mb) * 80 * np.pi / 30, rel=1e-9)


def test_undercut_pinion_warns_and_unknown_material_names_the_field(tmp_path):
    brief = yaml.safe_load((ROOT / "designs/shaper.yaml").read_text(encoding="utf-8"))
    brief["gear_pair"].update(z1=12, z2=40)
    brief.pop("drive")
    path = tmp_path / "b.yaml"
    path.write_text(yaml.safe_dump(brief, allow_unicode=True), encoding="utf-8")
    result = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "o"), "--format", "md"])
    assert result.exit_code == 0
    assert "warning: 齿轮 1（z = 12）根切" in result.output
    brief = yaml.safe_load((ROOT / "designs/shaper.yaml").read_text(encoding="utf-8"))
    brief["gear_pair"]["pinion_material"] = "unobtainium"
    path.write_text(yaml.safe_dump(brief, allow_unicode=True), encoding="utf-8")
    result = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "o2"), "--format", "md"])
    assert result.exit_code == 2
    assert "gear_pair.pinion_material" in result.output and "40Cr_QT" in result.output
