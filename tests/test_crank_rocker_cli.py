"""The crank-rocker brief run as a user runs it: report (PDF), results.json checked against
references computed here (the specification, the law of cosines, a brute-force scan),
warnings, and exit code 2 naming the field for bad data."""
from __future__ import annotations

import json
import importlib.util
from pathlib import Path

import numpy as np
import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.cli import app

ROOT = Path(__file__).resolve().parents[1]
BRIEF = ROOT / "designs" / "crank_rocker.yaml"
runner = CliRunner()
RAD = np.pi / 180


def run(brief: Path, out: Path, *extra: str):
    return runner.invoke(app, ["run", str(brief), "--out", str(out), *extra])


def edited(tmp_path: Path, edit) -> Path:
    data = yaml.safe_load(BRIEF.read_text(encoding="utf-8"))
    edit(data)
    path = tmp_path / "crank_rocker.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    return path


def gamma_cos(a, b, c, d):
    """Minimum transmission angle by the law of cosines at the crank/frame collinear positions."""
    d1 = np.arccos((b * b + c * c - (d - a) ** 2) / (2 * b * c))
    d2 = np.arccos((b * b + c * c - (d + a) ** 2) / (2 * b * c))
    return min(d1, np.pi - d1, d2, np.pi - d2)


def extremes_cos(a, b, c, d):
    """θ and ψ by the law of cosines in triangles ADC1 (AC1 = b − a) and ADC2 (AC2 = b + a)."""
    def ang(x, y, z):
        return np.arccos((x * x + y * y - z * z) / (2 * x * y))
    theta = ang(b - a, d, c) - ang(b + a, d, c)
    psi = ang(d, c, b + a) - ang(d, c, b - a)
    return abs(theta), psi


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    out = tmp_path_factory.mktemp("cr") / "crank_rocker"
    result = run(BRIEF, out, "--format", "md,pdf")
    return result, out


@pytest.mark.e2e
@pytest.mark.skipif(importlib.util.find_spec("pypandoc") is None
                    or importlib.util.find_spec("typst") is None,
                    reason="pypandoc and typst are needed for the PDF")
def test_writes_pdf_report_and_figures(report):
    result, out = report
    assert result.exit_code == 0, result.output
    assert (out / "report.pdf").stat().st_size > 50_000
    for fig in ("chart", "construction", "motion", "slider"):
        assert (out / "figures" / f"{fig}.png").stat().st_size > 10_000
    md = (out / "report.md").read_text(encoding="utf-8")
    for heading in ("设计题目与数据", "按行程速比系数设计曲柄摇杆机构", "最小传动角最大的曲柄摇杆机构",
                    "偏置曲柄滑块机构设计", "计算校核"):
        assert f"# {heading}" in md
    assert "FAIL" not in md and "不合格" not in md  # every verification row passes
    assert (out / "design_chart.csv").is_file()


@pytest.mark.e2e
def test_results_meet_the_specification(report):
    result, out = report
    assert result.exit_code == 0, result.output
    doc = json.loads((out / "results.json").read_text(encoding="utf-8"))
    spec = yaml.safe_load(BRIEF.read_text(encoding="utf-8"))
    theta, psi = spec["extreme_angle_deg"] * RAD, spec["rocker_swing_deg"] * RAD
    K = (np.pi + theta) / (np.pi - theta)
    for key in ("optimum", "textbook"):
        d = doc[key]
        th, ps = extremes_cos(d["crank"], d["coupler"], d["rocker"], d["frame"])
        assert th == pytest.approx(theta, abs=1e-12) and ps == pytest.approx(psi, abs=1e-12)
        assert d["gamma_min"] == pytest.approx(gamma_cos(d["crank"], d["coupler"], d["rocker"],
                                                         d["frame"]), abs=1e-12)
    assert doc["textbook"]["frame"] == pytest.approx(spec["frame_length_mm"] * 1e-3, rel=1e-12)
    # a label is the brief's text, or {msgid} for a design the program names (issue 22: codes)
    sims = {s["label"] if isinstance(s["label"], str) else s["label"]["msgid"]: s
            for s in doc["simulation"]}
    for s in doc["simulation"][:2]:                         # ours: optimum and given frame
        assert s["K"] == pytest.approx(K, abs=1e-9)
        assert s["swing"] == pytest.approx(psi, abs=1e-9)
    # the paper's "computer result" misses its own θ and ψ, and has a smaller γmin
    paper = next(v for k, v in sims.items() if "computer" in k)
    assert abs(paper["theta"] - theta) > 0.3 * RAD and abs(paper["swing"] - psi) > 0.1 * RAD
    assert paper["gamma_min"] < doc["optimum"]["gamma_min"]
    sl = doc["slider_crank"]
    e, a, b = sl["offset"], sl["crank"], sl["rod"]
    H = np.sqrt((b + a) ** 2 - e ** 2) - np.sqrt((b - a) ** 2 - e ** 2)
    assert H == pytest.approx(spec["slider_crank"]["stroke_H_mm"] * 1e-3, rel=1e-12)
    assert sl["simulated"]["stroke"] == pytest.approx(H, rel=1e-9)
    assert sl["simulated"]["K"] == pytest.approx(spec["slider_crank"]["time_ratio_K"], abs=1e-9)
    assert sl["pressure_angle_fast"] == pytest.approx(np.arcsin((a + e) / b), abs=1e-12)


def test_optimum_beats_every_given_frame():
    """Textbook designs over the whole frame range never exceed the optimum's γmin."""
    from mechdesign.core import fourbar as fb
    theta, psi, c = 15 * RAD, 40 * RAD, 0.05
    K = (np.pi + theta) / (np.pi - theta)
    _, g_opt = fb.optimal_crank_rocker(K, psi, c)
    lo, hi = fb.frame_range(K, psi, c)
    best = 0.0
    for d in np.linspace(lo, hi, 2002)[1:-1]:
        x = fb.crank_rocker_from_K(K, psi, c, d)
        best = max(best, gamma_cos(x.crank, x.coupler, x.rocker, x.frame))
    assert best <= g_opt + 1e-12
    assert best == pytest.approx(g_opt, abs=1e-5)


@pytest.mark.e2e
def test_english_report(tmp_path):
    result = run(BRIEF, tmp_path / "en", "--format", "md", "--lang", "en")
    assert result.exit_code == 0, result.output
    md = (tmp_path / "en" / "report.md").read_text(encoding="utf-8")
    assert "# Verification" in md and "# Offset slider-crank" in md
    assert "最优设计" not in md


@pytest.mark.e2e
def test_poor_design_warns(tmp_path):
    def edit(d):
        d["extreme_angle_deg"] = 30
        d["rocker_swing_deg"] = 80
        d.pop("frame_length_mm")
    result = run(edited(tmp_path, edit), tmp_path / "o", "--format", "md")
    assert result.exit_code == 0, result.output
    assert "警告：" in result.output and "[γ] = 40°" in result.output   # zh brief: terminal lines in Chinese


@pytest.mark.parametrize("edit, words", [
    (lambda d: d.update(frame_length_mm=500), ["frame_length_mm", "500", "frames between"]),
    (lambda d: d.update(time_ratio_K=1.2), ["exactly one of time_ratio_K and extreme_angle_deg"]),
    (lambda d: d.update(rocker_swing_deg=200), ["rocker_swing_deg", "200", "less than 180"]),
    (lambda d: d["slider_crank"].update(offset_e_mm=200), ["offset_e_mm", "200", "H·cot θ"]),
    (lambda d: d["chart"].update(swing_deg=[50, 20]), ["chart.swing_deg", "0 < from < to < 180"]),
    (lambda d: d.update(bogus=1), ["bogus", "unknown field"]),
    (lambda d: d["compare"][0].update(crank_mm=60), ["compare.0", "not a crank-rocker"]),
])
def test_bad_data_exit_2_naming_the_field(tmp_path, edit, words):
    result = run(edited(tmp_path, edit), tmp_path / "o", "--format", "md", "--lang", "en")
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    for w in words:
        assert w in result.output, (w, result.output)
