"""The press (压床), issue 18 point 6, against independent references: the course's
graphical synthesis redone by hand in the test (triangle DE′E″, the crank-rocker from
AC′ and AC″), the rocker's extremes and the ram's stroke reproduced by the simulation,
the energy balance (mean M_b·ω = the pressing work per revolution), a bad brief naming
its field, and the rendered report with every section."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from mechdesign.cli import app

ROOT = Path(__file__).parents[1]
BRIEF = ROOT / "designs" / "press.yaml"


@pytest.fixture(scope="module")
def r(example_results):
    return example_results("press")


def test_synthesis_is_the_hand_construction(r):
    """designs/press.yaml: x1 = 50, x2 = 140, y = 220 mm, ψ3′ = 60°, ψ3″ = 120°, H = 150 mm,
    CE/CD = 1/2, EF/DE = 1/4. Triangle DE′E″ is equilateral (Δψ = 60°): DE = H = 150 mm;
    CD = DE/(1 + 1/2) = 100 mm; C′ = (100 sin 60°, 100 cos 60°) = (86.6025, 50),
    C″ = (86.6025, −50); A = (50, −220):
    AC′ = √(36.6025² + 270²) = 272.4697, AC″ = √(36.6025² + 170²) = 173.8957;
    AB = (AC′ − AC″)/2 = 49.2870, BC = (AC′ + AC″)/2 = 223.1828 mm."""
    s = r["synthesis"]
    dx = 100 * math.sin(math.radians(60)) - 50
    ac1, ac2 = math.hypot(dx, 270.0), math.hypot(dx, 170.0)
    assert s.rocker * 1e3 == pytest.approx(150.0, rel=1e-12)
    assert s.rocker_CD * 1e3 == pytest.approx(100.0, rel=1e-12)
    assert s.rocker_CE * 1e3 == pytest.approx(50.0, rel=1e-12)
    assert s.rod * 1e3 == pytest.approx(37.5, rel=1e-12)
    assert s.crank * 1e3 == pytest.approx((ac1 - ac2) / 2, rel=1e-12)
    assert s.coupler * 1e3 == pytest.approx((ac1 + ac2) / 2, rel=1e-12)
    assert s.crank * 1e3 == pytest.approx(49.2870, abs=1e-4)
    assert s.coupler * 1e3 == pytest.approx(223.1828, abs=1e-4)
    assert s.frame * 1e3 == pytest.approx(math.hypot(50, 220), rel=1e-12)


def test_simulated_extremes_reproduce_the_data(r):
    """The simulated rocker's extremes are ψ3′ and ψ3″ (ψ = 90° − the angle of D→C), the
    ram's stroke is H (the engine's velocity zeros and its bounded position search), and
    the ram's top and bottom positions agree with F = E − (0, √(EF² − (x_E − x2)²))."""
    k, v, p = r["linkage"], r["linkage_verification"], r["params"]
    assert k.stroke == pytest.approx(0.150, abs=1e-12)
    assert v.stroke == pytest.approx(0.150, abs=1e-9)
    n = k.grid_size
    top = n + list(k.positions.labels).index("1")
    bottom = n + int(np.argmin(np.abs(k.phase[n:] - k.working_span)))   # the other extreme
    psi = np.degrees(np.pi / 2 - k.link_angle["3"])
    assert psi[top] == pytest.approx(60.0, abs=1e-7)
    assert psi[bottom] == pytest.approx(120.0, abs=1e-7)
    grid = psi[:n]
    assert grid.min() >= 60.0 - 1e-7 and grid.max() <= 120.0 + 1e-7
    xe = 0.150 * math.sin(math.radians(60))
    drop = math.sqrt(0.0375 ** 2 - (xe - 0.140) ** 2)
    f_top = complex(0.140, 0.150 * 0.5 - drop)
    f_bottom = complex(0.140, -0.150 * 0.5 - drop)
    assert abs(k.points["F"][top] - f_top) < 1e-9
    assert abs(k.points["F"][bottom] - f_bottom) < 1e-9
    # the four-bar's time ratio: θ = ∠C′AC″, K = (180° + θ)/(180° − θ), the slow stroke down
    c1, c2, a = complex(86.60254037844386, 50), complex(86.60254037844386, -50), complex(50, -220)
    theta = abs(np.angle((c1 - a) / (c2 - a)))
    assert k.time_ratio == pytest.approx((np.pi + theta) / (np.pi - theta), abs=1e-9)
    assert k.time_ratio > 1.0


def test_energy_balance(r):
    """Weights and inertia do no net work per revolution: the mean power on the crank is
    the pressing work Q_max · 0.3 H per revolution times n1/60 = 4000 · 0.045 · 100/60 =
    300 W; at every position Σ power (M_b ω, every load, inertia) = 0."""
    f, v = r["linkage_forces"], r["linkage_verification"]
    assert f.mean_power == pytest.approx(4000 * 0.045 * 100 / 60, rel=2e-3)
    k = r["linkage"]
    n = k.grid_size
    omega = abs(r["params"].crank_omega)
    # the resistance's own power −R·v averaged over the grid (R signed along the downward line)
    press_power = np.mean(np.abs(f.resistance["R1"][:n] * k.v[:n]))
    assert np.mean(f.balancing_torque[:n]) * omega == pytest.approx(press_power, rel=1e-6)
    assert v.power_balance_residual < 1e-9
    pressing = np.abs(f.resistance["R1"][:n]) > 0
    assert np.all(k.phase[:n][pressing] <= k.working_span + 1e-12)   # only while going down
    assert np.all(k.s[:n][pressing] >= 0.7 * 0.150 - 1e-9)           # over the last 0.3 H


def _run(tmp_path, old: str, new: str):
    text = BRIEF.read_text(encoding="utf-8")
    assert old in text
    bad = tmp_path / "press.yaml"
    bad.write_text(text.replace(old, new), encoding="utf-8")
    return CliRunner().invoke(app, ["run", str(bad), "--out", str(tmp_path / "out"),
                                    "--format", "md", "--lang", "en"])


@pytest.mark.parametrize("old,new,field,value", [
    ("rocker_psi3_lower_deg: 120", "rocker_psi3_lower_deg: 110",
     "linkage.rocker_psi3_lower_deg", "110"),              # not symmetric: closed-form rule
    ("ratio_EF_DE: 0.25", "ratio_EF_DE: 0.05", "linkage.ratio_EF_DE", "0.05"),  # run-time check
    ("pivot_y_mm: 220", "pivot_y_mm: 0", "linkage.pivot_y_mm", "0"),             # no crank
])
def test_a_bad_brief_names_its_field(tmp_path, old, new, field, value):
    res = _run(tmp_path, old, new)
    assert res.exit_code == 2, res.output
    assert field in res.output and value in res.output
    assert "Traceback" not in res.output
    assert not (tmp_path / "out" / "report.md").exists()


@pytest.mark.e2e
@pytest.mark.parametrize("lang,heads", [
    ("zh", ["设计任务与原始数据", "连杆机构设计", "压床六杆机构分析", "动态静力分析", "飞轮",
            "凸轮机构设计", "齿轮设计", "计算校核", "设计图纸"]),
    ("en", ["Design task and data", "Linkage synthesis", "Six-bar linkage analysis"]),
])
def test_report_renders_with_every_section(tmp_path, lang, heads):
    out = tmp_path / lang
    res = CliRunner().invoke(app, ["run", str(BRIEF), "--out", str(out), "--format", "md,dxf",
                                   "--lang", lang])
    assert res.exit_code == 0, res.output
    md = (out / "report.md").read_text(encoding="utf-8")
    for h in heads:
        assert h in md, h
    assert "{{" not in md and "L_{AB}" in md
    for sheet in ("analysis_A1", "cam_A2", "gear_A2"):
        assert (out / "sheets" / f"{sheet}.dxf").exists(), sheet


def test_pinion_is_a_standard_gear_at_the_textbooks_least_tooth_number(r):
    """z1 = 17 = z_min (孙桓《机械原理》: 17 at α = 20°, h_a* = 1), so x_min = h_a*(17 − 17)/17 = 0:
    standard gears, no undercut finding, the standard centre distance m(z1 + z2)/2 and the
    standard tips d_a = m(z + 2h_a*)."""
    g = r["gear"]
    pair = g.pair
    ha, m, z1, z2 = 1.0, 0.005, 17, 51
    assert pair.z_min == 17 and pair.x_min1 == 0.0
    assert pair.g1.x == pair.g2.x == 0.0
    assert not [w for w in g.warnings if w.code == "undercut"]
    assert abs(pair.a - m * (z1 + z2) / 2) < 1e-12 and abs(pair.a_work - 0.170) < 1e-12
    assert abs(pair.g1.da - m * (z1 + 2 * ha)) < 1e-12
    assert abs(pair.g2.da - m * (z2 + 2 * ha)) < 1e-12
    assert abs(pair.g1.df - (m * z1 - 2 * (ha + 0.25) * m)) < 1e-12
