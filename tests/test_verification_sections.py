"""The 计算校核 / Verification chapters of the cam, eccentric-cam and drive reports, and the
corrected actual profile of a roller cam at its velocity jumps.

References are independent of the program: the 7-3 pitch curve and its corners written out
by hand (the inversion formula with the cycloidal and uniform laws), the eccentric disc at
δ = 90° by plane geometry (exercise 7-1), the drive's speeds from the catalogue motor speed
and the teeth. Every check is also shown to fail on a perturbed result.
"""
from __future__ import annotations

import copy
import csv
import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
import yaml
from scipy.spatial import cKDTree
from typer.testing import CliRunner

from mechdesign.brief.loader import load_brief, parse_brief
from mechdesign.cli import app
from mechdesign.core import cam as core
from mechdesign.machines import get_machine, stages_for
from mechdesign.stages import cam as mcam
from mechdesign.stages import drive as mdrive
from mechdesign.pipeline import run_stages
from mechdesign.render import cam_report
from mechdesign.machines.eccentric_cam import report as disc_report
from mechdesign.machines.drive import report as drive_report
from mechdesign.machines.eccentric_cam import stages as mdisc

ROOT = Path(__file__).resolve().parents[1]
DESIGNS = ROOT / "designs"
runner = CliRunner()
MM, D = 1e-3, math.radians

# exercise 7-3: offset roller follower, counter-clockwise cam
E73, R0_73, RR73, H73 = 12 * MM, 50 * MM, 10 * MM, 30 * MM


def run_brief(brief) -> dict:
    m = get_machine(brief.machine)
    p = m.to_params(brief)
    results, _ = run_stages(stages_for(m, p), {"params": p, "brief": brief})
    return results


@pytest.fixture(scope="module")
def cam73(example_results):
    return example_results("cam_7_3")


@pytest.fixture(scope="module")
def lockbeam(example_results):
    return example_results("lockbeam_cam")


@pytest.fixture(scope="module")
def disc(example_results):
    return example_results("cam_7_1")


@pytest.fixture(scope="module")
def drive(example_results):
    return example_results("furnace_drive")


def by_key(v, key):
    return [c for c in v.checks if c.key == key]


def only(v, key):
    found = by_key(v, key)
    assert len(found) == 1, key
    return found[0]


# ---------------------------------------------------------------- hand-written 7-3 pitch curve


def s73(delta):
    """Cycloidal rise 0–120°, far dwell to 150°, uniform return to 300°, near dwell."""
    d = np.degrees(np.mod(delta, 2 * np.pi))
    u = d / 120
    rise = H73 * (u - np.sin(2 * np.pi * u) / (2 * np.pi))
    ret = H73 * (1 - (d - 150) / 150)
    return np.select([d < 120, d < 150, d < 300], [rise, H73, ret], 0.0)


def pitch73(delta):
    s0 = math.sqrt(R0_73**2 - E73**2)
    return (E73 + 1j * (s0 + s73(delta))) * np.exp(-1j * delta)


def dense_pitch73(n=400_000):
    d = np.concatenate([np.arange(n) * (2 * np.pi / n), [D(150), D(300)]])
    return d, pitch73(d)


def nearest(points, curve):
    tree = cKDTree(np.column_stack([curve.real, curve.imag]))
    dist, idx = tree.query(np.column_stack([np.real(points), np.imag(points)]))
    return dist, idx


def tangent_angle73(s_prime, s):
    """Direction of dp/dδ at δ (up to the common factor e^(−iδ)): s0 + s + i(s' − e)."""
    s0 = math.sqrt(R0_73**2 - E73**2)
    return np.angle((s0 + s) + 1j * (s_prime - E73))


# ---------------------------------------------------------------- 1. the corrected profile


def test_73_outline_is_the_envelope_of_the_roller_circles(cam73):
    """Every vertex of the actual profile is r_r from the hand-written pitch curve, no pitch
    point comes closer than r_r to it (the roller never cuts the cam), and off the sharp edge
    at 150° every pitch point has the profile exactly r_r away (no gap)."""
    c = cam73["cam"]
    d, pitch = dense_pitch73()
    dist, _ = nearest(c.outline, pitch)
    assert np.max(np.abs(dist - RR73)) < 2e-6
    back, idx = nearest(pitch, c.outline)
    assert np.min(back) > RR73 - 2e-6
    off_edge = np.abs(np.degrees(d) - 150) > 1.0
    assert np.max(back[off_edge]) < RR73 + 2e-6


def test_plain_offset_curve_fails_the_same_test(cam73):
    """Control: the points r_r along each normal (what the profile was before the fix) come
    about 0.11 mm closer than r_r to the pitch curve next to 150°: a roller would cut them."""
    g = cam73["cam"].grid
    raw = g.pitch - RR73 * g.normal
    _, pitch = dense_pitch73()
    dist, _ = nearest(raw, pitch)
    assert RR73 - np.min(dist) > 0.05 * MM


def test_73_arc_at_300_degrees_spans_the_jump_of_the_normal(cam73):
    """At 300° (uniform return → near dwell) the pitch curve has a concave corner P: the
    profile there is the roller circle about P, over the angle through which the tangent
    turns, from s' = −h/Φ to s' = 0 (Φ = 150°)."""
    c = cam73["cam"]
    P = complex(pitch73(np.array([D(300)]))[0])
    turn = abs(tangent_angle73(0.0, 0.0) - tangent_angle73(-H73 / D(150), 0.0))
    on_circle = c.outline[np.abs(np.abs(c.outline - P) - RR73) < 1e-9]
    ang = np.angle((on_circle - P) / np.mean(on_circle - P))
    assert np.ptp(ang) == pytest.approx(turn, abs=D(0.3))
    assert math.degrees(turn) == pytest.approx(11.9, abs=0.1)
    corner = [k for k in c.envelope.corners if abs(k.delta - D(300)) < 1e-9][0]
    assert corner.kind == "arc" and abs(corner.turn) == pytest.approx(turn, rel=1e-9)


def test_73_sharp_edge_at_150_degrees(cam73):
    """At 150° (far dwell → uniform return) the offset branches cross: the profile's edge X
    is r_r from the pitch curve on both sides of the corner (two feet), and the corner P
    itself is farther than r_r from X: there the roller stands off the cam."""
    c = cam73["cam"]
    (lo, hi, X, off), = c.envelope.edges
    assert lo < D(150) < hi
    d, pitch = dense_pitch73()
    before, after = d < D(150), d > D(150)
    assert np.min(np.abs(pitch[before] - X)) == pytest.approx(RR73, abs=2e-6)
    assert np.min(np.abs(pitch[after] - X)) == pytest.approx(RR73, abs=2e-6)
    P = complex(pitch73(np.array([D(150)]))[0])
    assert abs(P - X) - RR73 == pytest.approx(off, abs=1e-12)
    assert off == c.envelope.stand_off and 0 < off < 0.05 * MM
    assert [k.stand_off for k in c.envelope.corners if k.kind == "edge"] == [off]
    # the contact points of the cut-away cam angles are that edge
    assert np.all(c.grid.actual[c.envelope.trimmed] == X)
    assert np.count_nonzero(c.envelope.trimmed) > 3


# ---------------------------------------------------------------- 2. cam self-checks


@pytest.mark.parametrize("name", ["cam73", "lockbeam"])
def test_cam_checks_pass_on_the_examples(name, request):
    v = request.getfixturevalue(name)["cam_verification"]
    verdicts = [c.passed for c in v.checks if c.sense != "info"]
    assert verdicts and all(verdicts)
    assert not v.warnings
    keys = {c.key for c in v.checks}
    assert {"velocity_fd", "acceleration_fd", "pressure_angle", "curvature_fd", "envelope",
            "interference", "gap", "closure", "angle_sum"} <= keys


def test_73_corner_rows(cam73):
    v = cam73["cam_verification"]
    corners = sorted(by_key(v, "corner"), key=lambda c: c.detail["delta"])
    assert [c.detail["kind"] for c in corners] == ["edge", "arc"]
    assert only(v, "offset_curve").value == pytest.approx(0.11 * MM, abs=0.01 * MM)


def test_finite_difference_errors_are_truncation_errors(cam73):
    """Halving the grid (h → 2h) multiplies the central-difference errors by about 4."""
    c = cam73["cam"]
    coarse = core.design_cam(c.params.programme, c.follower, c.base_radius, c.params.rotation, 1800)
    v1 = cam73["cam_verification"]
    v2 = mcam.verify_cam(replace(c, grid=coarse, outline=coarse.actual, envelope=None))
    for key in ("velocity_fd", "acceleration_fd", "curvature_fd"):
        ratio = only(v2, key).value / only(v1, key).value
        assert 3.5 < ratio < 4.5, (key, ratio)


def _motion(c, **change):
    return replace(c, grid=replace(c.grid, motion=replace(c.grid.motion, **change)))


PERTURBED = {
    "velocity_fd": lambda c: _motion(c, ds=c.grid.motion.ds * 1.002),
    "acceleration_fd": lambda c: _motion(c, d2s=c.grid.motion.d2s * 1.002),
    "closure": lambda c: _motion(c, s=c.grid.motion.s + 1e-6 * (np.arange(len(c.grid.delta)) == 0)),
    "stroke": lambda c: _motion(c, s=c.grid.motion.s * (1 + 1e-6)),
    "pressure_angle": lambda c: replace(c, grid=replace(c.grid, pressure_angle=c.grid.pressure_angle + D(0.02))),
    "curvature_fd": lambda c: replace(c, grid=replace(c.grid, rho_pitch=c.grid.rho_pitch * 1.01)),
    "envelope": lambda c: replace(c, outline=c.outline * (1 + 1e-4)),
    "interference": lambda c: replace(c, outline=c.grid.pitch - RR73 * c.grid.normal),
    "gap": lambda c: replace(c, outline=c.outline * (1 - 1e-4)),
}


@pytest.mark.parametrize("key", sorted(PERTURBED))
def test_each_cam_check_fails_on_a_perturbed_cam(cam73, key):
    c = PERTURBED[key](cam73["cam"])
    v = mcam.verify_cam(c)
    assert only(v, key).passed is False
    assert any(w.code == "self_check" and mcam.CAM_CHECK_NAMES[key][1] in w.en for w in v.warnings)
    rows = cam_report.cam_verification_rows(v, c, "zh")
    name = mcam.CAM_CHECK_NAMES[key][0].replace("r_r", "$r_r$")    # typeset in the report
    assert [r[3] for r in rows if r[0] == name] == ["不合格"]
    assert "FAIL" in [r[3] for r in cam_report.cam_verification_rows(v, c, "en")]


def test_angle_sum_check_fails_on_a_broken_programme(cam73):
    c = cam73["cam"]
    prog = copy.copy(c.params.programme)
    prog.spans = prog.spans + np.array([1e-6] + [0.0] * (len(prog.spans) - 1))
    v = mcam.verify_cam(replace(c, params=replace(c.params, programme=prog)))
    assert only(v, "angle_sum").passed is False


# ---------------------------------------------------------------- 3. flat-faced followers


def _flat_73(return_law: str):
    data = yaml.safe_load((DESIGNS / "cam_7_3.yaml").read_text(encoding="utf-8"))
    data["cam"]["follower"] = {"motion": "translating", "contact": "flat", "stroke_h_mm": 30}
    data["cam"]["programme"][2]["law"] = return_law
    return run_brief(parse_brief(data))


def test_flat_face_touches_a_smooth_cam_everywhere():
    r = _flat_73("cycloidal")
    v = r["cam_verification"]
    assert all(c.passed for c in v.checks if c.sense != "info")
    assert only(v, "face_support").value < 1e-6
    assert not v.warnings


def test_flat_face_cannot_follow_a_uniform_return():
    """Right after the far dwell (150°) the face drops at the uniform speed h/Φ while the end
    of the dwell arc, radius r0 + h, still stands under it: at δ = 158° that point is
    (r0 + h)·cos 8° − (r0 + s) = 0.82 mm above the face. The design checks (ρ = r0 + s + s'')
    do not see it; the verification does, as a design finding."""
    r = _flat_73("constant_velocity")
    v = r["cam_verification"]
    chk = only(v, "face_support")
    hand = (R0_73 + H73) * math.cos(D(8)) - (R0_73 + H73 * (1 - 8 / 150))
    assert hand == pytest.approx(0.8215 * MM, abs=1e-7)
    assert chk.passed is False and chk.value >= hand - 1e-6
    assert [w.code for w in v.warnings] == ["flat_face_cut"]


# ---------------------------------------------------------------- 4. eccentric disc


def test_disc_geometry_against_plane_geometry():
    """Exercise 7-1, R = 40, ε = 20, counter-clockwise, at δ = 90° the disc centre is at
    (20, 0): centred knife y = √(40² − 20²); knife offset 15 right y = √(40² − 5²); centred
    roller r_r = 20: y = √(60² − 20²)."""
    p = load_brief(DESIGNS / "cam_7_1.yaml")
    params = get_machine("eccentric_cam").to_params(p)
    expect = [math.sqrt(40**2 - 20**2), math.sqrt(40**2 - 5**2), math.sqrt(60**2 - 20**2)]
    for (_, fol), y in zip(params.followers, expect):
        got = mdisc.disc_geometric(np.array([D(90)]), params.radius, params.eccentricity, fol, 1)
        assert got[0] / MM == pytest.approx(y, abs=1e-9)


def test_disc_checks_pass(disc):
    v = disc["disc_verification"]
    assert len(v.checks) == 12 and all(c.passed for c in v.checks)   # 4 per follower
    strokes = {c.detail["label"]: c.detail["stroke"] / MM for c in by_key(v, "disc_stroke")}
    # (a) 2ε; (b) √(60² − 15²) − √(20² − 15²); (c) 2ε
    assert strokes["(a)"] == pytest.approx(40.0, abs=1e-6)
    assert strokes["(b)"] == pytest.approx(math.sqrt(3375) - math.sqrt(175), abs=1e-6)
    assert strokes["(c)"] == pytest.approx(40.0, abs=1e-6)
    rows = disc_report.verification_context(v, "zh")["verify_rows"]
    # one row per check (page review 51: the three largest-pressure-angle checks were not shown)
    assert len(rows) == len(v.checks) == 12 and {r[3] for r in rows} == {"合格"}


@pytest.mark.parametrize("key,change", [
    ("disc_s", lambda m: replace(m, s=m.s + 2e-9)),
    ("disc_alpha", lambda m: replace(m, pressure_angle=m.pressure_angle + D(1e-3))),
    ("disc_stroke", lambda m: replace(m, y_max=m.y_max + 1e-8)),
])
def test_each_disc_check_fails_on_a_perturbed_motion(disc, key, change):
    d = disc["disc"]
    bad = replace(d, motions=[change(d.motions[0])] + d.motions[1:])
    v = mdisc.verify_disc(bad)
    failed = [c for c in v.checks if not c.passed]
    assert [(c.key, c.detail["label"]) for c in failed] == [(key, "(a)")]
    assert [w.code for w in v.warnings] == ["self_check"]
    rows = disc_report.verification_context(v, "en")["verify_rows"]
    assert sum(r[3] == "FAIL" for r in rows) == 1


# ---------------------------------------------------------------- 5. drive


def test_drive_checks_pass_and_speed_error_by_hand(drive):
    d, v = drive["drive"], drive["drive_verification"]
    assert all(c.passed for c in v.checks) and not v.warnings
    teeth = [st.z2 / st.z1 for st in d.stages if st.z1]
    n_out = d.motor.full_load_rpm / np.prod(teeth)
    assert only(v, "speed_error").detail["signed"] == pytest.approx((n_out - 20) / 20, rel=1e-12)
    # the power that reaches the pusher: (500 + 100) N × 0.22 m × 20/min
    assert d.machine_power == pytest.approx(600 * 0.22 * 20 / 60)
    assert len(by_key(v, "reactions")) == len(d.shaft_designs)
    assert len(by_key(v, "margin")) == len([s for s in d.stages if s.design and s.design.checks]) + \
        len(d.shaft_designs)


def _shaft(d, k, **change):
    shafts = list(d.shafts)
    shafts[k] = replace(shafts[k], **change)
    return replace(d, shafts=tuple(shafts))


def _first_check(d, **change):
    sds = list(d.shaft_designs)
    checks = list(sds[0].checks)
    checks[0] = replace(checks[0], **change)
    sds[0] = replace(sds[0], checks=tuple(checks))
    return replace(d, shaft_designs=tuple(sds))


def _reaction(d):
    sds = list(d.shaft_designs)
    sds[1] = replace(sds[1], result=replace(sds[1].result, RAh=sds[1].result.RAh + 1.0))
    return replace(d, shaft_designs=tuple(sds))


def _ratio(d):
    stages = list(d.stages)
    stages[1] = replace(stages[1], ratio=stages[1].ratio * 1.01)
    return replace(d, stages=tuple(stages))


DRIVE_PERTURBED = {
    "power": (lambda d: _shaft(d, 2, power=d.shafts[2].power * 1.001),
              {"shaft_power", "shaft_torque"}),
    "last power": (lambda d: _shaft(d, len(d.shafts) - 1, power=d.shafts[-1].power * 1.001),
                   {"shaft_power", "shaft_torque", "power_balance"}),
    "speed": (lambda d: _shaft(d, 2, speed_rpm=d.shafts[2].speed_rpm * 1.001),
              {"shaft_speed", "shaft_torque"}),
    "ratio": (_ratio, {"shaft_speed", "stage_ratio", "ratio_product"}),
    "reaction": (_reaction, {"reactions"}),
    "strength": (lambda d: _first_check(d, value=d.shaft_designs[0].checks[0].allowable * 0.9),
                 {"margin", "verdicts"}),
    "tolerance": (lambda d: replace(d, speed_tolerance=0.001), {"speed_error"}),
}


@pytest.mark.parametrize("what", sorted(DRIVE_PERTURBED))
def test_each_drive_check_fails_on_a_perturbed_drive(drive, what):
    change, expect = DRIVE_PERTURBED[what]
    bad = change(drive["drive"])
    v = mdrive.verify_drive(bad)
    failed = {c.key for c in v.checks if c.passed is False}
    assert failed == expect
    computation = {c.key for c in v.checks if c.passed is False and not c.requirement}
    assert bool(v.warnings) == bool(computation)
    rows = drive_report.verification_context(bad, v, "zh")["verify_rows"]
    assert sum(r[3] == "不合格" for r in rows) == sum(1 for c in v.checks if c.passed is False)


# ---------------------------------------------------------------- 6. the reports


@pytest.mark.e2e
@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", ["cam_7_3", "lockbeam_cam", "cam_7_1", "furnace_drive"])
def test_reports_end_with_the_verification_chapter(tmp_path, name, lang):
    out = tmp_path / name
    result = runner.invoke(app, ["run", str(DESIGNS / f"{name}.yaml"), "--out", str(out),
                                 "--format", "md", "--lang", lang])
    assert result.exit_code == 0, result.output
    md = (out / "report.md").read_text(encoding="utf-8")
    head = "# 计算校核" if lang == "zh" else "# Verification"
    assert head in md
    chapter = md[md.index(head):]
    # the chapter runs to the next level-1 heading: since issue 19 the hand-in's summary and
    # references follow it (tests/test_handin.py)
    chapter = chapter[:chapter.find("\n# ", 1)] if "\n# " in chapter[1:] else chapter
    table = [line for line in chapter.splitlines() if line.startswith("| ")][1:]
    assert len(table) >= 9
    assert all(line.count(" | ") == 3 for line in table)           # four columns, no stray '|'
    assert ("不合格" if lang == "zh" else "FAIL") not in chapter
    doc = json.loads((out / "results.json").read_text(encoding="utf-8"))
    checks = doc["verification"]["checks"]
    assert checks and all(c["passed"] in (True, None) for c in checks)
    if name == "cam_7_3":
        _check_73_csv(out)


def _check_73_csv(out: Path):
    """The CSV files carry the corrected profile: no actual point inside the cut loop, and
    the outline file is the envelope."""
    _, pitch = dense_pitch73()
    for fname in ("cam_profile.csv", "cam_profile_fine.csv"):
        rows = list(csv.DictReader((out / fname).open(encoding="utf-8")))
        z = np.array([complex(float(r["actual_x_mm"]), float(r["actual_y_mm"])) for r in rows]) * MM
        dist, _ = nearest(z, pitch)
        assert np.min(dist) > RR73 - 2e-6, fname
    rows = list(csv.DictReader((out / "cam_profile_outline.csv").open(encoding="utf-8")))
    z = np.array([complex(float(r["actual_x_mm"]), float(r["actual_y_mm"])) for r in rows]) * MM
    dist, _ = nearest(z, pitch)
    assert np.max(np.abs(dist - RR73)) < 2e-6


def test_undercut_roller_profile_is_cut_at_its_loops():
    """A roller larger than the pitch curve's smallest convex radius (47.4 mm for 7-3)
    undercuts the cam: the offset curve loops, the profile is cut at the crossings, and the
    envelope checks still hold; the problem is the design's (an 'undercut' warning), not a
    failed self-check."""
    data = yaml.safe_load((DESIGNS / "cam_7_3.yaml").read_text(encoding="utf-8"))
    data["cam"]["follower"]["roller_radius_mm"] = 48
    r = run_brief(parse_brief(data))
    assert [w.code for w in r["cam"].warnings] == ["undercut"]
    v = r["cam_verification"]
    assert all(only(v, k).passed for k in ("envelope", "interference", "gap"))
    assert not v.warnings
    _, pitch = dense_pitch73()
    dist, _ = nearest(r["cam"].outline, pitch)
    assert np.min(dist) > 48 * MM - 2e-6
