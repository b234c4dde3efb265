"""Issue 18 point 1: the furnace pusher, the die-cutter and the crank-rocker accept their
link lengths (a ``dimensions:`` section) instead of the design requirements. The derived
values are checked against closed forms written out here, a round trip (synthesised lengths
fed back as dimensions) gives the same downstream results, and a bad set of dimensions is
rejected at its field (exit 2, no traceback)."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.cli import app

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "dims"
runner = CliRunner()
RAD = np.pi / 180


def run(brief: Path, out: Path, *extra: str):
    return runner.invoke(app, ["run", str(brief), "--out", str(out), "--format", "md", *extra])


def results(brief: Path, out: Path, *extra: str) -> dict:
    result = run(brief, out, *extra)
    assert result.exit_code == 0, result.output
    return json.loads((out / "results.json").read_text(encoding="utf-8"))


def write(tmp_path: Path, data: dict, name: str) -> Path:
    path = tmp_path / name
    path.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    return path


def ang(x, y, z):
    """Angle opposite z in a triangle with sides x, y, z (law of cosines)."""
    return np.arccos((x * x + y * y - z * z) / (2 * x * y))


def fourbar_cosines(a, b, c, d):
    """θ, ψ, K, γmin of a crank-rocker (crank a, coupler b, rocker c, frame d) by hand:
    extremes at AC1 = b − a (folded), AC2 = b + a (extended) in triangles ADC1, ADC2;
    K = (180° + θ)/(180° − θ); γ extreme with the crank along the frame (L = d ∓ a)."""
    theta = abs(ang(b - a, d, c) - ang(b + a, d, c))
    psi = ang(d, c, b + a) - ang(d, c, b - a)
    K = (np.pi + theta) / (np.pi - theta)
    d1, d2 = ang(b, c, d - a), ang(b, c, d + a)
    return theta, psi, K, min(d1, np.pi - d1, d2, np.pi - d2)


def rel(x, y):
    return abs(x - y) / max(abs(y), 1e-300)


def assert_same(x, y, tol=1e-9, path=""):
    """Numbers equal to ``tol`` (relative, absolute near 0) through nested dicts/lists."""
    if isinstance(y, dict):
        for k in y:
            assert_same(x[k], y[k], tol, f"{path}.{k}")
    elif isinstance(y, list):
        assert len(x) == len(y), path
        for i, (u, v) in enumerate(zip(x, y)):
            assert_same(u, v, tol, f"{path}[{i}]")
    elif isinstance(y, float) and isinstance(x, (int, float)) and "angle" in path:
        # angles: the same modulo 2π (0 and 2π are one crank position)
        assert abs((x - y + np.pi) % (2 * np.pi) - np.pi) <= tol * max(1.0, abs(y)), (path, x, y)
    elif isinstance(y, float) and isinstance(x, (int, float)):
        assert abs(x - y) <= tol * max(1.0, abs(y)) or rel(x, y) <= tol, (path, x, y)
    else:
        assert x == y, (path, x, y)


# --------------------------------------------------------------------------- crank-rocker

def test_crank_rocker_dimensions_derived_by_the_law_of_cosines(tmp_path):
    doc = results(DATA / "crank_rocker_dims.yaml", tmp_path / "cr")
    a, b, c, d = 16e-3, 46e-3, 50e-3, 53.76e-3
    theta, psi, K, gmin = fourbar_cosines(a, b, c, d)
    assert doc["spec"]["theta"] == pytest.approx(theta, rel=1e-12)
    assert doc["spec"]["swing"] == pytest.approx(psi, rel=1e-12)
    assert doc["spec"]["K"] == pytest.approx(K, rel=1e-12)
    given = doc["textbook"]
    assert [given[k] for k in ("crank", "coupler", "rocker", "frame")] == [a, b, c, d]  # exact
    assert given["gamma_min"] == pytest.approx(gmin, rel=1e-12)
    sim = doc["simulation"][1]                      # the given linkage, simulated
    assert sim["K"] == pytest.approx(K, rel=1e-9) and sim["swing"] == pytest.approx(psi, rel=1e-9)
    # slider-crank a = 45, b = 130, e = 20 mm: extremes with crank and rod in line
    sa, sb, e = 45e-3, 130e-3, 20e-3
    H = np.sqrt((sb + sa) ** 2 - e * e) - np.sqrt((sb - sa) ** 2 - e * e)
    th = np.arcsin(e / (sb - sa)) - np.arcsin(e / (sb + sa))
    sc = doc["slider_crank"]
    assert (sc["crank"], sc["rod"]) == (sa, sb)
    assert sc["stroke"] == pytest.approx(H, rel=1e-12) and sc["theta"] == pytest.approx(th, rel=1e-12)
    assert sc["K"] == pytest.approx((np.pi + th) / (np.pi - th), rel=1e-12)
    assert sc["simulated"]["stroke"] == pytest.approx(H, rel=1e-9)
    md = (tmp_path / "cr" / "report.md").read_text(encoding="utf-8")
    assert "给定尺寸 → 导出值" in md and "| 16.0000 | mm |" in md and "| 53.7600 | mm |" in md


def test_crank_rocker_round_trip(tmp_path):
    """The example's given-frame design fed back as dimensions: θ, ψ, the optimum and every
    simulation equal the requirement run's to 1e-9."""
    brief = yaml.safe_load((ROOT / "designs" / "crank_rocker.yaml").read_text(encoding="utf-8"))
    ref = results(ROOT / "designs" / "crank_rocker.yaml", tmp_path / "ref")
    tb = ref["textbook"]
    for k in ("extreme_angle_deg", "rocker_swing_deg", "rocker_length_mm", "frame_length_mm"):
        brief.pop(k)
    brief["dimensions"] = {"crank_mm": tb["crank"] * 1e3, "coupler_mm": tb["coupler"] * 1e3,
                           "rocker_mm": tb["rocker"] * 1e3, "frame_mm": tb["frame"] * 1e3}
    sc = ref["slider_crank"]
    brief["slider_crank"] = {"offset_e_mm": sc["offset"] * 1e3,
                             "dimensions": {"crank_mm": sc["crank"] * 1e3, "rod_mm": sc["rod"] * 1e3}}
    got = results(write(tmp_path, brief, "cr.yaml"), tmp_path / "got")
    for key in ("theta", "swing", "K", "rocker", "frame"):
        assert rel(got["spec"][key], ref["spec"][key]) < 1e-9, key
    assert_same(got["optimum"], ref["optimum"], 1e-9)
    for g, r in zip(got["simulation"], ref["simulation"]):
        assert_same({k: v for k, v in g.items() if k != "label"},
                    {k: v for k, v in r.items() if k != "label"}, 1e-8)
    assert_same(got["slider_crank"], ref["slider_crank"], 1e-9)


@pytest.mark.parametrize("dims, words", [
    ({"crank_mm": 30, "coupler_mm": 20, "rocker_mm": 50, "frame_mm": 53.76},
     ["dimensions.crank_mm", "shortest"]),
    ({"crank_mm": 16, "coupler_mm": 46, "rocker_mm": 50, "frame_mm": 120},
     ["dimensions.frame_mm", "120", "not a crank-rocker"]),
])
def test_crank_rocker_bad_dimensions_named(tmp_path, dims, words):
    data = yaml.safe_load((DATA / "crank_rocker_dims.yaml").read_text(encoding="utf-8"))
    data["dimensions"] = dims
    result = run(write(tmp_path, data, "bad.yaml"), tmp_path / "o", "--lang", "en")
    assert result.exit_code == 2 and "Traceback" not in result.output, result.output
    for w in words:
        assert w in result.output, (w, result.output)


@pytest.mark.parametrize("edit, field", [
    (lambda d: d.update(rocker_swing_deg=40), "rocker_swing_deg"),
    (lambda d: d["slider_crank"].update(stroke_H_mm=100), "slider_crank.stroke_H_mm"),
    (lambda d: d["slider_crank"]["dimensions"].update(rod_mm=60), "slider_crank.dimensions.rod_mm"),
])
def test_crank_rocker_both_forms_or_bad_slider_named(tmp_path, edit, field):
    data = yaml.safe_load((DATA / "crank_rocker_dims.yaml").read_text(encoding="utf-8"))
    edit(data)
    result = run(write(tmp_path, data, "bad.yaml"), tmp_path / "o", "--lang", "en")
    assert result.exit_code == 2 and "Traceback" not in result.output, result.output
    assert field in result.output, result.output
