"""The crank's load on the shaft that carries it (review 39: shaft Ⅲ of the die cutter and
the furnace pusher was designed for the gear forces only). References: the kinetostatics'
own samples (the piece-wise evaluation reproduces them), a brute-force dense search over
the crank angle for the exact extreme, the statics of an overhung load in closed form and
the combined stress σ_ca = √(M² + (αT)²)/(0.1 d³) (濮良贵《机械设计》 9th ed., (15-5))."""
from __future__ import annotations

import math

import numpy as np
import pytest

from mechdesign.stages.crank_load import crank_joint, crank_load, reaction_at
from mechdesign.stages.linkage import CycleIntegrals

CASES = {"die_cutter": ("press_model", "press", "press_forces"),
         "furnace_pusher": ("model", "linkage", "linkage_forces"),
         # the guide-bar machines: the crank on the gear z2's shaft (review39b Top 1)
         "shaper": ("model", "linkage", "linkage_forces"),
         "slotter": ("model", "linkage", "linkage_forces")}


@pytest.fixture(scope="module", params=sorted(CASES))
def case(request, example_results):
    r = example_results(request.param)
    mk, kk, fk = CASES[request.param]
    return request.param, r, r[mk], r[kk], r[fk]


def test_piecewise_reaction_reproduces_the_kinetostatics_samples(case):
    _, _, model, k, f = case
    ci = CycleIntegrals(model, k)
    joint = crank_joint(model)
    n = k.grid_size
    grid = np.asarray(k.phase[:n])
    ref = np.asarray(f.reactions[joint])[:n]
    scale = np.max(np.abs(ref))
    for i in range(len(ci.ends) - 1):
        a, b = ci.ends[i], ci.ends[i + 1]
        inside = (grid > a + 1e-9) & (grid < b - 1e-9)
        if inside.any():
            got = reaction_at(ci, grid[inside], i, joint)[0]
            assert np.max(np.abs(got - ref[inside])) < 1e-9 * scale


def test_exact_extreme_against_a_dense_search(case):
    _, _, model, k, f = case
    cl = crank_load(model, k, f)
    ci = CycleIntegrals(model, k)
    dense_max, dense_phase = 0.0, 0.0
    for i in range(len(ci.ends) - 1):
        a, b = float(ci.ends[i]), float(ci.ends[i + 1])
        xs = np.linspace(a, b, max(3, int(40000 * (b - a) / (2 * np.pi))))
        ys = np.abs(reaction_at(ci, xs, i, crank_joint(model))[0])
        if ys.max() > dense_max:
            dense_max, dense_phase = float(ys.max()), float(xs[np.argmax(ys)])
    assert cl.F >= dense_max * (1 - 1e-12)
    assert cl.F == pytest.approx(dense_max, rel=1e-6)
    assert cl.phase == pytest.approx(dense_phase, abs=2e-3) or abs(cl.F - dense_max) < 1e-6 * cl.F
    assert cl.F >= cl.grid_max * (1 - 1e-12)
    assert math.hypot(cl.Fx, cl.Fy) == pytest.approx(cl.F, rel=1e-12)


def test_the_crank_shaft_carries_the_crank(case):
    """The last drive shaft's loads contain the crank's force overhung 80 mm beyond a
    bearing; the moment at that bearing is F·a (statics of an overhung load), and the check
    there is σ_ca = √(M² + (αT)²)/(0.1 d³) with the journal's diameter. The die cutter lifts
    its platen with two identical linkages side by side (designs/die_cutter.yaml
    press.linkages: 2): a crank beyond each bearing, each with F/2 and half the torque."""
    name, r, model, k, f = case
    cl = crank_load(model, k, f)
    sh = r["drive"].shaft_designs[-1]
    n = 2 if name == "die_cutter" else 1
    cranks = [ld for ld, nm in zip(sh.loads, sh.elements) if nm == "crank"]
    assert len(cranks) == n
    a = 0.080
    for load in cranks:
        assert math.hypot(load.Fh, load.Fv) == pytest.approx(cl.F / n, rel=1e-12)
        xb = sh.span if load.x > sh.span else 0.0
        assert abs(load.x - xb) == pytest.approx(a)
        # the moment at the bearing next to the crank: the crank's force on its lever arm plus
        # whatever else is overhung on that side (nothing else on these shafts)
        others = [ld for ld, nm in zip(sh.loads, sh.elements)
                  if nm != "crank" and (ld.x > sh.span if xb else ld.x < 0)]
        assert not others
        sec = next(s for s in sh.result.sections if abs(s.x - xb) < 1e-12)
        assert sec.M == pytest.approx(cl.F / n * a, rel=1e-9)
    if n == 2:           # one on each side
        assert min(ld.x for ld in cranks) < 0 < sh.span < max(ld.x for ld in cranks)
    # the combined stress at that bearing with the journal and the sections' torque
    T = sh.torque / n
    sigma = math.sqrt((cl.F / n * a) ** 2 + (0.6 * T) ** 2) / (0.1 * sh.d_journal ** 3)
    bend = next(c for c in sh.checks if c.key == "shaft_bending")
    assert bend.value >= sigma * (1 - 1e-9)
    assert bend.inputs["T"] == pytest.approx(T, rel=1e-12)
    assert bend.passed == (bend.value <= bend.allowable)
    assert bend.passed
    if name == "die_cutter":
        # one crank with the whole 235.6 kN would need d ≥ ∛(M_ca/(0.1·60 MPa)) ≈ 150 mm at
        # its bearing: beyond the catalogue's largest bearing bore (130 mm) — why two
        m_ca = math.sqrt((cl.F * a) ** 2 + (0.6 * sh.torque) ** 2)
        assert (m_ca / (0.1 * 60e6)) ** (1 / 3) > 0.130
        # every check of the shaft passes with two; each crank key carries T/2, the gear's T
        assert all(c.passed for c in sh.checks), [c.key for c in sh.checks if not c.passed]
        keys = {kd.element: kd.torque for kd in sh.keys}
        assert keys["crank"] == pytest.approx(sh.torque / 2, rel=1e-12)
        assert max(keys.values()) == pytest.approx(sh.torque, rel=1e-12)


