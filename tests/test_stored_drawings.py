"""What the stages store for the figures and sheets (the render layer only reads it),
checked against references that do not use the stored arrays:

* gear: the pair in mm is the pair in metres × 1000; in the layout |O1O2| = a′, |O1N1| = rb1,
  |O2N2| = rb2; every tooth point lies between its root and tip circles; the measured
  |B1B2| is the textbook √(ra1² − rb1²) + √(ra2² − rb2²) − a′ sin α′;
* cam (exercise 7-3, offset translating roller): the division points divide every rise and
  return into equal parts; the cam at them is the pitch point by inversion
  B = e^(−iσδ)[e + i(√(r0² − e²) + s)]; each segment's left-hand end value is the level the
  next segment starts from; the favourable offset side of a ccw cam is the right;
* lock-beam bending four-bar: the drawn joints keep the link lengths a, b, c and span the
  input swing; the chosen candidate's peak |dβ/dα| is that of the Assur-group simulation
  and of finite differences of the stored sweep;
* incomplete gear: Δφ2 = 2π z1′/z2 from the stored integral, no motion in the dwell and the
  jump ω1 z1/z2.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from mechdesign.brief.components import IncompleteGearSection, incomplete_gear_to_si
from mechdesign.brief.loader import load_brief
from mechdesign.core.gears import spur_pair
from mechdesign.core.intermittent import intermittent_curves
from mechdesign.machines import get_machine, stages_for
from mechdesign.stages.gear import gear_drawing
from mechdesign.pipeline import run_stages

ROOT = Path(__file__).resolve().parents[1]


def _run(name):
    brief = load_brief(ROOT / "designs" / f"{name}.yaml")
    machine = get_machine(brief.machine)
    params = machine.to_params(brief)
    results, _ = run_stages(stages_for(machine, params), {"params": params, "brief": brief}, None)
    return results


@pytest.mark.parametrize("args", [(0.012, 18, 60), (0.005, 12, 40, np.radians(20), 1.0, 0.25, 0.4, 0.1)])
def test_gear_drawing(args):
    pair = spur_pair(*args)
    d = gear_drawing(pair)
    mm = d.pair
    for a, b in ((mm.m, pair.m), (mm.a_work, pair.a_work), (mm.g1.da, pair.g1.da),
                 (mm.g2.df, pair.g2.df), (mm.g1.db, pair.g1.db)):
        assert a == pytest.approx(b * 1e3, rel=1e-12)
    lay = d.layout
    assert abs(lay.o2 - lay.o1) == pytest.approx(mm.a_work, rel=1e-12)
    assert abs(lay.n1 - lay.o1) == pytest.approx(mm.g1.db / 2, rel=1e-9)
    assert abs(lay.n2 - lay.o2) == pytest.approx(mm.g2.db / 2, rel=1e-9)
    for tooth, g in zip(d.teeth, (mm.g1, mm.g2)):
        r = np.abs(tooth)
        assert r.min() >= g.df / 2 - 1e-9 and r.max() <= g.da / 2 + 1e-9
    for outline, g in zip(d.outlines, (mm.g1, mm.g2)):
        assert len(outline) > 40 * g.z
    ra1, ra2, rb1, rb2 = pair.g1.da / 2, pair.g2.da / 2, pair.g1.db / 2, pair.g2.db / 2
    b1b2 = (np.sqrt(ra1**2 - rb1**2) + np.sqrt(ra2**2 - rb2**2)
            - pair.a_work * np.sin(pair.alpha_work))
    assert d.action_length == pytest.approx(b1b2, rel=1e-9)
    assert d.interference is False


def test_cam_drawing_7_3():
    c = _run("cam_7_3")["cam"]
    dr = c.drawing
    prog = c.params.programme
    deltas = np.array([x.delta for x in dr.divisions])
    assert [x.number for x in dr.divisions] == list(range(len(deltas)))
    for i, seg in enumerate(prog.segments):
        start, end = prog.starts[i], prog.starts[i] + prog.spans[i]
        inside = deltas[(deltas >= start - 1e-9) & (deltas < end - 1e-9)]
        assert inside[0] == pytest.approx(start, abs=1e-12)
        if seg.kind != "dwell":
            steps = np.diff(np.append(inside, end))
            assert len(steps) >= 4 and np.ptp(steps) < 1e-12
            assert np.degrees(steps[0]) <= 25.0 + 1e-9
    # the pitch curve at the divisions by inversion (ccw cam, σ = +1)
    r0, e = c.base_radius, c.offset
    s = np.array([x.s for x in dr.divisions])
    pitch = np.exp(-1j * deltas) * (e + 1j * (np.sqrt(r0**2 - e**2) + s))
    assert np.max(np.abs(dr.division_profile.pitch - pitch)) < 1e-12
    # cycloidal rise 0 → 30 mm over 120°: s at 60° is half the stroke
    mid = np.argmin(np.abs(deltas - np.radians(60)))
    assert s[mid] == pytest.approx(0.015, abs=1e-12)
    n = len(prog.segments)
    for i, (_, (s_end, v, a, _)) in enumerate(dr.segment_ends):
        assert s_end == pytest.approx(prog.levels[(i + 1) % n], abs=1e-9)
        if prog.segments[i].kind == "dwell":
            assert v == a == 0.0
    assert dr.offset_favourable is True and dr.arm_side == 0


@pytest.fixture(scope="module")
def lockbeam():
    return _run("lockbeam")


def test_bending_drawing(lockbeam):
    b = lockbeam["bending"]
    ds, dr = b.design, b.drawing
    B0 = complex(ds.frame, 0.0)
    for A, B in ((dr.A, dr.B), (dr.path_A, dr.path_B)):
        assert np.max(np.abs(np.abs(A) - ds.input_rocker)) < 1e-9
        assert np.max(np.abs(np.abs(B - B0) - ds.output_rocker)) < 1e-9
        assert np.max(np.abs(np.abs(B - A) - ds.coupler)) < 1e-9
    assert np.angle(dr.A[0]) == pytest.approx(np.angle(np.exp(1j * ds.alpha1)), abs=1e-12)
    assert np.angle(dr.A[-1] / dr.A[0]) == pytest.approx(ds.dalpha, abs=1e-12)
    assert len(dr.A) == 5 and len(dr.path_A) == 60
    chosen = [p for (_, d_, _, _), p in zip(b.synthesis.candidates, b.candidate_ratio_peaks)
              if d_ is ds]
    # the peak (rocker_synthesis.sweep, 721 points) against the Assur-group simulation's
    # dβ/dα (1441 points) and against finite differences of its angles (one-sided, O(h), at
    # the ends where the peak lies)
    assert chosen[0] == pytest.approx(np.max(np.abs(b.velocity_ratio)), rel=1e-9)
    fd = np.abs(np.gradient(b.sweep_output, b.sweep_input))
    assert chosen[0] == pytest.approx(fd.max(), rel=1e-3)
    if b.seed is not None:
        assert len(b.seed.start_ratio_ranges) == len(b.seed.check.starts)
        assert all(0 < lo <= hi for lo, hi in b.seed.start_ratio_ranges)


@pytest.mark.parametrize("rpm", [None, 10.0])
def test_intermittent_curves(rpm):
    g = incomplete_gear_to_si(IncompleteGearSection.model_validate(
        {"module_mm": 4, "driver_teeth_full": 36, "driven_teeth": 30, "motion_span_deg": 100,
         "motion_start_deg": 300, "sprocket_pitch_radius_mm": 80}), rpm)
    c = intermittent_curves(g)
    assert g.teeth == 10                                   # 100° of 36 teeth
    assert c.advance_integral == pytest.approx(2 * np.pi * 10 / 30, rel=1e-9)
    assert c.dwell_speed_max == 0.0
    w = 1.0 if rpm is None else rpm * np.pi / 30
    assert c.jump.omega2 == pytest.approx(w * 36 / 30, rel=1e-12)
    assert (c.times is None) == (rpm is None)
    assert np.all(np.diff(c.theta) >= 0) and c.theta[0] == 0 and c.theta[-1] == pytest.approx(2 * np.pi)
