"""The general linkage's flywheel may size its cast rim (issue 19, note40: linkage_sixbar's
flywheel stopped at J_F while every machine sizes its rim): ``linkage.flywheel.rim_diameter_mm``
(with H/b and γ) gives the rim, checked here by the closed forms of 孙桓《机械原理》 §7
(the rim carries J_F: m = 4 J_F / D²; its section b·H = m / (ρ π D) with H = k b, ρ = γ/g;
its speed v = π D n / 60), and a rim that cannot be is named at its field."""
from __future__ import annotations

import math
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]


def test_the_sixbars_rim_follows_from_its_inertia(example_results):
    r = example_results("linkage_sixbar")
    fw = r["linkage_flywheel"]
    spec = yaml.safe_load((ROOT / "designs" / "linkage_sixbar.yaml").read_text(encoding="utf-8"))
    given = spec["linkage"]["flywheel"]
    D = given["rim_diameter_mm"] / 1000
    k = given.get("rim_height_to_width", 1.5)
    gamma = given.get("specific_weight_N_m3", 7.0e4)
    g = r["params"].gravity if hasattr(r["params"], "gravity") else 9.81
    rim = fw.rim
    assert rim is not None
    m = 4 * fw.inertia / D ** 2
    assert rim.rim_mass == pytest.approx(m, rel=1e-9)
    b = math.sqrt(m / (gamma / g * math.pi * D * k))
    assert rim.width == pytest.approx(b, rel=1e-9)
    assert rim.height == pytest.approx(k * b, rel=1e-9)
    n = 60.0 * given.get("speed_ratio", 1)
    assert rim.rim_speed == pytest.approx(math.pi * D * n / 60, rel=1e-9)
    # the brief's D keeps the rim within its radius and cast iron's rim speed
    assert rim.height < D / 2 and rim.rim_speed < 30


def test_without_a_diameter_the_flywheel_stops_at_its_inertia(tmp_path):
    from mechdesign.brief.linkage import LinkageFlywheelSpec

    assert LinkageFlywheelSpec.model_validate({"fluctuation_delta": 0.05}).rim_diameter_mm is None


def test_an_impossible_rim_is_named_at_its_field(tmp_path):
    import subprocess
    import sys

    text = (ROOT / "designs" / "linkage_sixbar.yaml").read_text(encoding="utf-8")
    # J_F ≈ 96 kg·m² at 60 rpm: a 100 mm rim would need H far beyond D
    text = text.replace("rim_diameter_mm: 1200}", "rim_diameter_mm: 100}")
    path = tmp_path / "small_rim.yaml"
    path.write_text(text, encoding="utf-8")
    run = subprocess.run([sys.executable, "-m", "mechdesign", "run", str(path), "--format", "md",
                          "-o", str(tmp_path / "out"), "--lang", "en"],
                         capture_output=True, text=True)
    assert run.returncode != 0
    assert "linkage.flywheel.rim_diameter_mm" in run.stderr and "Traceback" not in run.stderr


def test_a_rim_higher_than_its_radius_is_told_in_the_report(tmp_path):
    """D = 600 mm: H = k b ≈ 346 mm > D/2 (the thin-rim estimate m = 4 J_F/D² fails): the
    run warns, and the report says it under the rim and on the summary's watch list."""
    import subprocess
    import sys

    text = (ROOT / "designs" / "linkage_sixbar.yaml").read_text(encoding="utf-8")
    path = tmp_path / "rim600.yaml"
    path.write_text(text.replace("rim_diameter_mm: 1200}", "rim_diameter_mm: 600}"), encoding="utf-8")
    out = tmp_path / "out"
    run = subprocess.run([sys.executable, "-m", "mechdesign", "run", str(path), "--format", "md",
                          "-o", str(out), "--lang", "en"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    md = (out / "report.md").read_text(encoding="utf-8")
    assert md.count("no longer a thin rim") == 2          # under the rim, on the watch list
    rim = md.index("Rim width $b$")
    assert md.index("no longer a thin rim") > rim
