"""The command line as a user drives it: exit codes, messages, files written.

References: the issue's contract (exit code 2 with field paths for a bad brief, no
traceback, nothing half-written) and the closed-form synthesis values for the
cross-check between results.json and the report text.
"""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import pytest
import yaml
from typer.testing import CliRunner

from mechdesign import __version__
from mechdesign.brief.docs import brief_markdown
from mechdesign.cli import app

ROOT = Path(__file__).resolve().parents[1]
BRIEF = ROOT / "designs" / "shaper.yaml"
runner = CliRunner()


def _write_brief(tmp_path: Path, edit) -> Path:
    data = yaml.safe_load(BRIEF.read_text(encoding="utf-8"))
    data["flywheel"]["specific_weight_N_m3"] = 7.0e4  # safe_load reads 7.0e4 as text
    edit(data)
    path = tmp_path / "brief.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def md_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("run") / "shaper"
    result = runner.invoke(app, ["run", str(BRIEF), "--out", str(out), "--format", "md"])
    return result, out


def test_version():
    result = runner.invoke(app, ["--version"])
    assert result.exit_code == 0
    assert __version__ in result.output


@pytest.mark.e2e
def test_run_writes_report_json_and_figures(md_run):
    result, out = md_run
    assert result.exit_code == 0, result.output
    assert (out / "report.md").is_file() and (out / "results.json").is_file()
    assert not (out / "report.pdf").exists()  # --format md only
    for name in ("mechanism", "ram_motion", "guide_bar", "balancing_torque", "energy", "reactions"):
        assert (out / "figures" / f"{name}.png").stat().st_size > 10_000
    # Stage progress is shown while it runs.
    # seven stages (the graphical method the seventh) + gear, drive, cam, the cam's phase
    assert "[1/11]" in result.output and "[11/11]" in result.output
    assert not list(out.glob(".mechdesign-*")), "staging folders must not remain"


@pytest.mark.e2e
def test_results_json_matches_closed_form_and_report(md_run):
    _, out = md_run
    doc = json.loads((out / "results.json").read_text(encoding="utf-8"))
    # Closed form: L_O3B = H / (2 sin(θ/2)), θ = 180°(K−1)/(K+1) with H = 0.32 m, K = 1.2.
    theta = np.pi * 0.2 / 2.2
    assert doc["synthesis"]["guide_bar"] == pytest.approx(0.32 / (2 * np.sin(theta / 2)), rel=1e-12)
    labels = [p["label"] for p in doc["positions"]]
    assert labels == ["1", "2", "3", "4", "4'", "5", "6", "7", "8'", "8", "9", "10", "10'", "11", "12"]
    assert len(doc["grid"]["phase"]) == 3600
    for key in ("R72", "R23", "R74", "R45", "R76"):
        assert len(doc["positions"][3]["reactions"][key]) == 2
    assert doc["flywheel"]["inertia"] > 0
    # The report shows the same numbers as results.json (rounded for display).
    md = (out / "report.md").read_text(encoding="utf-8")
    assert f"{doc['synthesis']['guide_bar'] * 1e3:.2f}" in md
    # energies in the text to 4 significant digits (render/fmt.py's rule since session 29)
    swing = doc["flywheel"]["max_energy_swing"]
    assert f"{swing:.{max(3 - int(np.floor(np.log10(abs(swing)))), 0)}f}" in md
    assert "# 导杆机构设计" in md and "# 计算校核" in md


@pytest.mark.e2e
def test_english_report(tmp_path):
    result = runner.invoke(app, ["run", str(BRIEF), "--out", str(tmp_path), "--format", "md",
                                 "--lang", "en"])
    assert result.exit_code == 0, result.output
    md = (tmp_path / "report.md").read_text(encoding="utf-8")
    assert "# Linkage synthesis" in md and "# Verification" in md


def test_bad_brief_lists_every_problem_with_exit_code_2(tmp_path):
    def edit(d):
        d["linkage"]["stroke_H_mm"] = -320
        d["linkage"]["colour"] = "red"
        del d["masses"]["ram_m6_kg"]
        d["linkage"]["time_ratio_K"] = "fast"
    path = _write_brief(tmp_path, edit)
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(path), "--out", str(out), "--lang", "en"])
    assert result.exit_code == 2
    text = result.output
    assert "4 problems" in text
    assert "linkage.stroke_H_mm: -320" in text and "greater than 0" in text
    assert "linkage.colour: 'red'" in text and "unknown field" in text
    assert "masses.ram_m6_kg: missing" in text
    assert "linkage.time_ratio_K: 'fast'" in text
    assert "Traceback" not in text
    assert not out.exists()


def test_unassemblable_linkage_names_the_group_and_angle(tmp_path):
    # Half the sagitta of B's arc is ~5.7 mm; a 1.1 mm rod cannot reach the ram guide.
    path = _write_brief(tmp_path, lambda d: d["linkage"].update(rod_ratio_BF_O3B=0.001))
    result = runner.invoke(app, ["run", str(path), "--out", str(tmp_path / "out"), "--lang", "en"])
    assert result.exit_code == 2
    assert "ram (RRP)" in result.output and "crank angle" in result.output
    assert "Traceback" not in result.output


def test_bad_format_is_a_usage_error(tmp_path):
    result = runner.invoke(app, ["run", str(BRIEF), "--out", str(tmp_path), "--format", "html"])
    assert result.exit_code == 2
    assert "md, pdf" in result.output


@pytest.mark.e2e
def test_failed_render_leaves_the_previous_report_untouched(tmp_path, md_run):
    _, good = md_run
    out = tmp_path / "out"
    shutil.copytree(good, out)
    before = (out / "report.md").read_text(encoding="utf-8")
    broken = tmp_path / "templates"
    shutil.copytree(ROOT / "templates", broken)
    (broken / "shaper.zh.md.j2").write_text("{{ no_such_value }}\n", encoding="utf-8")
    result = runner.invoke(app, ["run", str(BRIEF), "--out", str(out), "--templates", str(broken)])
    assert result.exit_code == 1
    assert "no_such_value" in result.output and "Traceback" not in result.output
    assert (out / "report.md").read_text(encoding="utf-8") == before
    assert not list(out.glob(".mechdesign-*"))


def test_brief_reference_is_up_to_date():
    committed = (ROOT / "docs" / "brief.md").read_text(encoding="utf-8")
    assert committed.strip() == brief_markdown().strip(), \
        "regenerate with: python -m mechdesign.brief.docs > docs/brief.md"


@pytest.mark.e2e
def test_full_run_renders_a_chinese_pdf(tmp_path, pdf_text):
    result = runner.invoke(app, ["run", str(BRIEF), "--out", str(tmp_path)])
    assert result.exit_code == 0, result.output
    pdf = (tmp_path / "report.pdf").read_bytes()
    assert pdf.startswith(b"%PDF") and len(pdf) > 200_000
    assert b"NotoSerifSC" in pdf and b"NotoSansSC" in pdf  # Chinese fonts embedded
    text = pdf_text(tmp_path / "report.pdf")
    for words in ("导杆机构设计", "动态静力分析", "飞轮设计", "张三"):
        assert words in text
