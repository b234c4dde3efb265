"""Issue 21 (4, 5): the cam's extremes are exact, never read off a grid, and an infeasible
cam is refused at its field.

References, all independent of the program's formulas:

* the pressure angle of an offset translating follower from the textbook's closed form
  tan α = |ds/dδ − e| / (s0 + s), s0 = √(r0² − e²) (counter-clockwise cam, the offset on
  the favourable right side), maximised by a brute-force search over 10⁶ cam angles, and
  for a parabolic rise with e = 0 by hand;
* the radius of curvature of the pitch curve from its Cartesian parametrisation
  x = (s0 + s)·sin δ + e·cos δ, y = (s0 + s)·cos δ − e·sin δ (inversion, cam turning
  counter-clockwise) and ρ = (x'² + y'²)^{3/2} / |x'y'' − x''y'|, with the derivatives
  written out below and s, ds/dδ, d²s/dδ² of the parabolic law by hand;
* exit codes and field paths of the command line.
"""
from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from mechdesign.core.cam import Programme, Segment, TranslatingFollower, exact_extremes

ROOT = Path(__file__).parents[1]
H, R0, E = 0.030, 0.050, 0.012          # stroke, base radius, offset [m] (exercise 7-3)
PHI = math.radians(120)                 # rise angle


def programme(law: str, rise_deg: float = 120.0, dwell_deg: float = 30.0) -> Programme:
    return Programme([Segment("rise", math.radians(rise_deg), law),
                      Segment("dwell", math.radians(dwell_deg)),
                      Segment("return", math.radians(150), "constant_velocity"),
                      Segment("dwell", math.radians(60))], H)


def cycloidal_tan_alpha(u, e):
    s = H * (u - np.sin(2 * np.pi * u) / (2 * np.pi))
    ds = H / PHI * (1 - np.cos(2 * np.pi * u))
    return np.abs(ds - e) / (math.sqrt(R0**2 - e**2) + s)


def test_max_pressure_angle_of_cycloidal_rise_against_a_million_points():
    u = np.linspace(0.0, 1.0, 1_000_001)
    brute = math.atan(float(np.max(cycloidal_tan_alpha(u, E))))
    ext = exact_extremes(programme("cycloidal"), TranslatingFollower("roller", E, 0.010), R0, 1)
    got = ext[0].max_pressure_angle.value
    # the brute force's own error: curvature of α at its peak × (step/2)² ≈ 1e-12 rad
    assert got == pytest.approx(brute, abs=1e-10)
    assert got >= brute - 1e-15          # never below a sampled value


def test_max_pressure_angle_of_parabolic_rise_by_hand():
    # e = 0: tan α = ds/(r0 + s). First half s = 2hu², ds = 4hu/Φ: d/du[u/(r0 + 2hu²)] = 0
    # at u² = r0/(2h) = 0.833 > 1/4, so α grows over the whole first half; in the second
    # half ds falls and s grows: the maximum is at mid-rise, tan α = (2h/Φ)/(r0 + h/2).
    hand = math.atan((2 * H / PHI) / (R0 + H / 2))
    assert math.degrees(hand) == pytest.approx(23.785, abs=1e-3)   # atan(0.028648/0.065 = 0.44074)
    ext = exact_extremes(programme("parabolic"), TranslatingFollower("roller", 0.0, 0.005), R0, 1)
    top = ext[0].max_pressure_angle
    assert top.value == pytest.approx(hand, rel=1e-12)
    assert math.degrees(top.delta) == pytest.approx(60.0, abs=1e-9)


def pitch_rho(delta, s, ds, d2s, e=E, r0=R0):
    """ρ of the pitch curve x = R sin δ + e cos δ, y = R cos δ − e sin δ, R = s0 + s."""
    R = math.sqrt(r0**2 - e**2) + s
    sn, cs = math.sin(delta), math.cos(delta)
    x1 = ds * sn + R * cs - e * sn
    y1 = ds * cs - R * sn - e * cs
    x2 = d2s * sn + 2 * ds * cs - R * sn - e * cs
    y2 = d2s * cs - 2 * ds * sn - R * cs + e * sn
    return (x1 * x1 + y1 * y1) ** 1.5 / abs(x1 * y2 - x2 * y1)


def test_curvature_one_sided_limit_at_parabolic_mid_rise():
    # at mid-rise s = h/2, ds = 2h/Φ; d²s jumps from +4h/Φ² (left) to −4h/Φ² (right)
    mid = PHI / 2
    left = pitch_rho(mid, H / 2, 2 * H / PHI, 4 * H / PHI**2)
    right = pitch_rho(mid, H / 2, 2 * H / PHI, -4 * H / PHI**2)
    assert right < left                      # decelerating: the pitch curve bends more
    ext = exact_extremes(programme("parabolic"), TranslatingFollower("roller", E, 0.005), R0, 1)
    k = max(e.max_curvature.value for e in ext if e.max_curvature)
    where = max((e.max_curvature for e in ext if e.max_curvature), key=lambda x: x.value)
    assert 1 / k == pytest.approx(right, rel=1e-10)
    assert math.degrees(where.delta) == pytest.approx(60.0, abs=1e-9) and where.side == 1
    # a 0.1° grid that does not hit the jump exactly sees only the points beside it: its
    # minimum is larger (on the unsafe side of the undercut check)
    grid = (np.arange(3600) + 0.5) * (2 * np.pi / 3600)
    rise = grid[grid <= PHI]
    u = rise / PHI
    s = np.where(u <= 0.5, 2 * H * u**2, H - 2 * H * (1 - u) ** 2)
    ds = np.where(u <= 0.5, 4 * H * u / PHI, 4 * H * (1 - u) / PHI)
    d2s = np.where(u <= 0.5, 4 * H / PHI**2, -4 * H / PHI**2)
    sampled = min(pitch_rho(d, a, b, c) for d, a, b, c in zip(rise, s, ds, d2s))
    assert sampled > right + 1e-6
    # and no point of the rise has a smaller radius than the one-sided limit (10⁵ points)
    u = np.linspace(0.5, 1.0, 100_001)[1:]
    dense = min(pitch_rho(PHI * x, H - 2 * H * (1 - x) ** 2, 4 * H * (1 - x) / PHI, -4 * H / PHI**2)
                for x in u[::10])
    assert dense >= right - 1e-15


def _brief(tmp_path: Path, name: str, **swap) -> Path:
    text = (ROOT / "designs" / "cam_7_3.yaml").read_text(encoding="utf-8")
    for old, new in swap.items():
        old = old.replace("__", " ")
        assert old in text, old
        text = text.replace(old, new)
    path = tmp_path / f"{name}.yaml"
    path.write_text(text.replace("language: zh", "language: en"), encoding="utf-8")
    return path


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "mechdesign", *map(str, args)],
                          capture_output=True, text=True, timeout=600)


def test_a_tiny_rise_has_its_true_pressure_angle_and_fails_by_name():
    from mechdesign.stages.cam import design
    from types import SimpleNamespace

    prog = programme("cycloidal", rise_deg=0.001, dwell_deg=149.999)
    fol = TranslatingFollower("roller", E, 0.010)
    # by hand: at mid-rise ds/dδ = 2h/Φ = 3438 m/rad, tan α = (2h/Φ − e)/(s0 + h/2)
    phi = math.radians(0.001)
    mid = math.atan((2 * H / phi - E) / (math.sqrt(R0**2 - E**2) + H / 2))
    p = SimpleNamespace(programme=prog, follower=fol, alpha_rise=math.radians(30),
                        alpha_return=math.radians(70), rotation=1, base_radius=R0,
                        auto_offset=False, min_actual_curvature=0.003, table_step=math.radians(10))
    c = design(p)
    rise = c.segments[0]
    assert rise.max_pressure_angle >= mid - 1e-12 and math.degrees(rise.max_pressure_angle) > 89.99
    assert not rise.ok
    finding = next(w for w in c.warnings if w.code == "pressure_angle")
    assert "rise" in finding.en and "larger cam angle" in finding.en


def test_roller_not_smaller_than_base_circle_exits_2_at_its_field(tmp_path):
    for rr in ("50", "55"):
        brief = _brief(tmp_path, f"rr{rr}", **{"roller_radius_mm: 10": f"roller_radius_mm: {rr}"})
        run = _cli("check", brief)
        assert run.returncode == 2, run.stdout + run.stderr
        out = run.stdout + run.stderr
        assert "cam.follower.roller_radius_mm" in out
        assert "below 50 mm" in out and "−" not in out.split("use a roller")[1].split("mm")[0]


def test_undercut_advice_never_asks_for_a_negative_roller():
    from mechdesign.stages.cam import _checks
    from types import SimpleNamespace

    fol = TranslatingFollower("roller", 0.0, 0.010)
    p = SimpleNamespace(min_actual_curvature=0.003)
    out = _checks(p, fol, 0.05, [], 0.002, -0.008, None, 0.04, None)   # ρmin 2 mm < 3 mm
    text = " ".join(w.en for w in out)
    assert "undercut" in [w.code for w in out]
    assert "below -" not in text and "below −" not in text and "larger base circle" in text


def test_a_2000_mm_stroke_lays_out_its_sheet(tmp_path):
    from mechdesign.brief.loader import load_variant
    from mechdesign.machines import get_machine, stages_for
    from mechdesign.pipeline import run_stages
    from mechdesign.render.cam_sheet import cam_sheet
    from mechdesign.render.sheet import TitleInfo

    brief = _brief(tmp_path, "long", **{"stroke_h_mm: 30": "stroke_h_mm: 2000",
                                         "base_radius_mm: 50 ": "base_radius_mm: auto"})
    v = load_variant(brief, None)
    m = get_machine(v.brief.machine)
    params = m.to_params(v.brief)
    results, _ = run_stages(stages_for(m, params), {"params": params, "brief": v.brief})
    sheet = cam_sheet(results["cam"], TitleInfo("", "t", "s", "1", "c", "t", "2026-01-01"), "en")
    assert sheet is not None
