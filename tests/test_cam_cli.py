"""The cam briefs run as a user runs them: reports, CSV, warnings by name, exit codes.

References: closed forms derived here (the 7-3 pitch point, the smallest base radius
2e of a knife/roller follower whose rise starts from a dwell, the eccentric-disc stroke),
the textbook's printed list for exercise 7-1 (a), and the brief's own data.
"""
from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.cli import app

ROOT = Path(__file__).resolve().parents[1]
DESIGNS = ROOT / "designs"
runner = CliRunner()


def run(brief: Path, out: Path, *extra: str):
    return runner.invoke(app, ["run", str(brief), "--out", str(out), "--format", "md", *extra])


def edited(tmp_path: Path, name: str, edit) -> Path:
    data = yaml.safe_load((DESIGNS / name).read_text(encoding="utf-8"))
    edit(data)
    path = tmp_path / name
    path.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def run_73(tmp_path_factory):
    out = tmp_path_factory.mktemp("c73") / "cam_7_3"
    return run(DESIGNS / "cam_7_3.yaml", out), out


@pytest.mark.e2e
def test_73_writes_report_results_and_csv(run_73):
    result, out = run_73
    assert result.exit_code == 0, result.output
    for name in ("report.md", "results.json", "cam_profile.csv", "cam_profile_fine.csv"):
        assert (out / name).is_file(), name
    for fig in ("cam_svaj", "cam_profile", "cam_alpha"):
        assert (out / "figures" / f"{fig}.png").stat().st_size > 10_000
    assert "warning" not in result.output        # r0 = 50 mm, r_r = 10 mm is a sound design


@pytest.mark.e2e
def test_73_csv_matches_closed_form_pitch_point(run_73):
    """At δ = 60° (mid-rise of the cycloidal 120° rise) s = h/2 = 15 mm. The roller centre
    in the frame is (e, s0 + s); a counter-clockwise cam sees it turned by −δ."""
    _, out = run_73
    rows = list(csv.DictReader((out / "cam_profile.csv").open(encoding="utf-8")))
    assert len(rows) == 36                              # every 10°
    row = next(r for r in rows if abs(float(r["delta_deg"]) - 60) < 1e-9)
    e, r0, s = 12.0, 50.0, 15.0
    s0 = np.sqrt(r0**2 - e**2)
    z = (e + 1j * (s0 + s)) * np.exp(-1j * np.radians(60))
    assert float(row["s_mm"]) == pytest.approx(s, abs=1e-6)
    assert float(row["pitch_x_mm"]) == pytest.approx(z.real, abs=1e-5)
    assert float(row["pitch_y_mm"]) == pytest.approx(z.imag, abs=1e-5)
    # pressure angle by the textbook formula, ds/dδ = 2h/Φ at mid-rise
    ds = 2 * 30 / np.radians(120)
    assert float(row["pressure_angle_deg"]) == pytest.approx(
        np.degrees(np.arctan(abs(ds - e) / (s0 + s))), abs=1e-5)
    # the actual profile is r_r from the pitch curve
    d = np.hypot(float(row["actual_x_mm"]) - z.real, float(row["actual_y_mm"]) - z.imag)
    assert d == pytest.approx(10.0, abs=1e-5)


@pytest.mark.e2e
def test_73_report_text_carries_the_numbers(run_73):
    _, out = run_73
    md = (out / "report.md").read_text(encoding="utf-8")
    assert "摆线运动规律" in md and "等速运动规律" in md
    assert "刚性冲击" in md                         # the uniform return
    assert "48.539" in md                           # s0 = √(50² − 12²)
    doc = json.loads((out / "results.json").read_text(encoding="utf-8"))
    # smallest base radius with e = 12 mm: the rise starts from a dwell, where the pole is at
    # the cam centre and tan α = e/s0, so α ≤ 30° needs r0 ≥ e / sin 30° = 2e = 24 mm.
    assert doc["cam"]["min_base_radius"] == pytest.approx(0.024, rel=1e-9)
    assert "24.00 mm" in md


@pytest.mark.e2e
def test_73_english_report(tmp_path):
    result = run(DESIGNS / "cam_7_3.yaml", tmp_path / "en", "--lang", "en")
    assert result.exit_code == 0, result.output
    md = (tmp_path / "en" / "report.md").read_text(encoding="utf-8")
    assert "# Cam mechanism" in md and "cycloidal" in md and "rigid impact" in md


@pytest.mark.e2e
def test_71_textbook_list_and_offset_stroke(tmp_path):
    result = run(DESIGNS / "cam_7_1.yaml", tmp_path / "c71")
    assert result.exit_code == 0, result.output
    doc = json.loads((tmp_path / "c71" / "results.json").read_text(encoding="utf-8"))
    a, b, c = doc["followers"]
    # (a): distance from the cam centre every 18°, as printed in the textbook solution, except
    # at 72°: printed 29.0071, but −20 cos 72° + √(40² − 20² sin² 72°) = 29.00768 (misprint).
    printed = [20.0, 20.4985, 22.0532, 24.8257, 29.0077, 34.6410, 41.3684, 48.3371, 54.4139,
               58.5408, 60.0]
    distance = (np.array(a["table"]["s"]) + a["y_min"]) * 1e3
    assert distance[:11] == pytest.approx(printed, abs=1e-4)
    # (b): closed-form stroke of the offset knife edge (the seed's ADAMS 43.1979 mm is wrong)
    assert b["stroke"] * 1e3 == pytest.approx(np.sqrt(60**2 - 15**2) - np.sqrt(20**2 - 15**2), abs=1e-9)
    # (c): centred roller: stroke 2ε
    assert c["stroke"] * 1e3 == pytest.approx(40.0, abs=1e-9)
    md = (tmp_path / "c71" / "report.md").read_text(encoding="utf-8")
    # the report writes the closed-form stroke to 0.01 mm (render/fmt.py's rule for lengths)
    stroke = np.sqrt(60**2 - 15**2) - np.sqrt(20**2 - 15**2)
    assert f"= {stroke:.2f}" in md and f"{stroke:.2f}" == "44.87"
    assert (tmp_path / "c71" / "disc_displacement.csv").is_file()


@pytest.mark.e2e
def test_shaper_report_has_the_cam_section(tmp_path):
    result = runner.invoke(app, ["run", str(DESIGNS / "shaper.yaml"), "--out", str(tmp_path / "s"),
                                 "--format", "md"])
    assert result.exit_code == 0, result.output
    md = (tmp_path / "s" / "report.md").read_text(encoding="utf-8")
    assert "# 凸轮机构设计" in md
    # φ0 = arccos((a² + L² − r0²)/(2aL)) with a = 136, L = 120, r0 = 50
    phi0 = np.degrees(np.arccos((136**2 + 120**2 - 50**2) / (2 * 136 * 120)))
    assert f"{phi0:.2f}°" in md                      # an angle to 0.01° (fmt's rule)
    assert "柔性冲击" in md                          # 等加速等减速: soft impacts
    assert (tmp_path / "s" / "cam_profile.csv").is_file()


@pytest.mark.e2e
def test_lockbeam_cam_has_no_impacts(tmp_path):
    result = run(DESIGNS / "lockbeam_cam.yaml", tmp_path / "lb")
    assert result.exit_code == 0, result.output
    doc = json.loads((tmp_path / "lb" / "results.json").read_text(encoding="utf-8"))
    assert [s["impact"] for s in doc["cam"]["segments"]] == ["none"] * 4
    assert max(s["max_pressure_angle"] for s in doc["cam"]["segments"]) < np.radians(30)


@pytest.mark.e2e
def test_roller_larger_than_curvature_is_reported_as_undercut(tmp_path):
    def big_roller(d):
        d["cam"]["follower"]["roller_radius_mm"] = 48   # the pitch curve's convex ρmin ≈ 47.4 mm
    result = run(edited(tmp_path, "cam_7_3.yaml", big_roller), tmp_path / "u")
    assert result.exit_code == 0
    assert "警告：运动失真" in result.output and "滚子半径 r_r = 48.00 mm" in result.output
    md = (tmp_path / "u" / "report.md").read_text(encoding="utf-8")
    assert "运动失真" in md and "不合格" in md   # the zh report's verdict word


@pytest.mark.e2e
def test_base_circle_too_small_is_reported_with_the_smallest_one(tmp_path):
    def small(d):
        d["cam"]["base_radius_mm"] = 22
    result = run(edited(tmp_path, "cam_7_3.yaml", small), tmp_path / "p", "--lang", "en")
    assert result.exit_code == 0
    assert "warning: pressure angle too large" in result.output
    assert "at least 24.00 mm" in result.output               # 2e, see test_73_report_text…


@pytest.mark.e2e
def test_auto_base_radius_meets_the_limit(tmp_path):
    def auto(d):
        d["cam"]["base_radius_mm"] = "auto"
    result = run(edited(tmp_path, "cam_7_3.yaml", auto), tmp_path / "a")
    assert result.exit_code == 0, result.output
    doc = json.loads((tmp_path / "a" / "results.json").read_text(encoding="utf-8"))
    cam = doc["cam"]
    assert cam["base_radius_designed"] and cam["base_radius"] == pytest.approx(0.024)
    assert all(s["ok"] for s in cam["segments"])


def test_unreachable_base_circle_is_exit_2_with_a_message(tmp_path):
    def far(d):
        d["cam"]["base_radius_mm"] = 300                # beyond a + L = 256 mm
    result = runner.invoke(app, ["run", str(edited(tmp_path, "shaper.yaml", far)),
                                 "--out", str(tmp_path / "x"), "--format", "md"])
    assert result.exit_code == 2                     # the brief is Chinese: so is the message
    assert "滚子中心到不了基圆" in result.output and "Traceback" not in result.output
    result = runner.invoke(app, ["run", str(edited(tmp_path, "shaper.yaml", far)),
                                 "--out", str(tmp_path / "x"), "--format", "md", "--lang", "en"])
    assert result.exit_code == 2
    assert "cannot reach the base circle" in result.output and "Traceback" not in result.output
    assert not (tmp_path / "x" / "report.md").exists()


# The cross-field problems are at the field to change (were at cam, cam.programme.1,
# cam.follower); the texts are checked in English (--lang en: they were English-only and so
# showed in the Chinese run too) and the Chinese run names the same field.
@pytest.mark.parametrize("edit, path, words", [
    (lambda d: d["cam"]["programme"][0].update(angle_deg=110), "cam.programme.3.angle_deg", "add up to 350"),
    (lambda d: d["cam"]["programme"][1].update(law="cycloidal"), "cam.programme.1.law", "dwell has no motion law"),
    (lambda d: d["cam"]["programme"][0].update(law="sinusoid"), "cam.programme.0.law", "cycloidal"),
    (lambda d: d["cam"]["follower"].pop("roller_radius_mm"), "cam.follower.roller_radius_mm", "roller_radius_mm"),
    (lambda d: d["cam"].update(base_radius_mm=-5), "cam.base_radius_mm", "base_radius_mm"),
])
def test_bad_cam_brief_names_the_field(tmp_path, edit, path, words):
    result = run(edited(tmp_path, "cam_7_3.yaml", edit), tmp_path / "bad", "--lang", "en")
    assert result.exit_code == 2, result.output
    assert f"  {path}: " in result.output and words in result.output
    assert "Traceback" not in result.output
    result = run(edited(tmp_path, "cam_7_3.yaml", edit), tmp_path / "bad")
    assert result.exit_code == 2 and f"  {path}：" in result.output, result.output


@pytest.mark.e2e
def test_73_pdf_renders(tmp_path):
    result = runner.invoke(app, ["run", str(DESIGNS / "cam_7_3.yaml"), "--out", str(tmp_path / "pdf")])
    assert result.exit_code == 0, result.output
    pdf = tmp_path / "pdf" / "report.pdf"
    assert pdf.read_bytes()[:5] == b"%PDF-" and pdf.stat().st_size > 50_000


@pytest.mark.e2e
def test_73_notation_keeps_the_offset_apart_from_the_exponential(run_73):
    """The pitch curve B(δ) = exp(−iδ)[e + i(s0 + s)]: e is the offset, so the complex
    exponential is written exp(…), never e^{…}; and the inversion paragraph of this
    translating roller follower says nothing of knife edges or oscillating pivots."""
    _, out = run_73
    md = (out / "report.md").read_text(encoding="utf-8")
    assert r"\exp(-i\delta)\left[e + i\," in md
    assert "e^{" not in md
    assert "滚子中心的轨迹即理论廓线" in md
    assert "尖顶" not in md and "摆动从动件转轴" not in md
