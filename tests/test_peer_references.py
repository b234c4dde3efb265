"""The hand-written closed forms of benchmarks/peers.py, checked so the peer benchmark's
independent reference can be trusted.

Against: our Mechanism (a different formulation: Assur groups by the law of cosines and
Cramer's rule, where the script uses Freudenstein's quadratic and the textbook ω/α formulas),
central finite differences (step rationale as in tests/test_kinematics.py: h = 1e-5 rad,
tolerance 1e-7 of the largest magnitude compared), the loop-closure lengths, the branch
convention the script states, and for the balancing torque our kinetostatics (reactions
group by group) against the script's power balance (no reaction at all).
The peer libraries are never needed: the end-to-end run hides them.
"""
from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest

from mechdesign.core.kinematics import cross
from mechdesign.core.kinetostatics import Body, solve_forces

SCRIPT = Path(__file__).resolve().parents[1] / "benchmarks" / "peers.py"
H_FD = 1e-5
FD_RTOL = 1e-7
EXACT = 1e-9


@pytest.fixture(scope="module")
def peers():
    spec = importlib.util.spec_from_file_location("bench_peers", SCRIPT)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod           # dataclasses look their module up there
    try:
        spec.loader.exec_module(mod)
        yield mod
    finally:
        sys.modules.pop(spec.name, None)


PHI = np.linspace(0.0, 2 * np.pi, 97, endpoint=False) + 0.013


def rel(actual, reference):
    return float(np.max(np.abs(actual - reference)) / np.max(np.abs(reference)))


def wrap(d):
    return np.angle(np.exp(1j * d))


def fd(f, phi, omega, h=H_FD):
    return omega * (f(phi + h) - f(phi - h)) / (2 * h)


def test_fourbar_closed_form_matches_our_mechanism(peers):
    p = peers.FOURBAR
    hand = peers.fourbar_closed_form(PHI, **p)
    mo = peers.ours_fourbar().solve(PHI)
    c = mo.points["C"]
    assert rel(hand["C"], c.pos) < EXACT
    assert rel(hand["vC"], c.vel) < EXACT
    assert rel(hand["aC"], c.acc) < EXACT
    for k, link in (("3", "3"), ("4", "4")):
        lm = mo.links[link]
        assert np.max(np.abs(wrap(hand["th" + k] - lm.angle))) < EXACT
        assert rel(hand["w" + k], lm.omega) < EXACT
        assert rel(hand["al" + k], lm.alpha) < EXACT
    pos = peers.fourbar_positions(PHI, **p)
    assert rel(pos["C"], c.pos) < EXACT


def test_fourbar_closed_form_branch_and_closure(peers):
    p = peers.FOURBAR
    k = peers.fourbar_closed_form(PHI, **p)
    B, C, D = k["B"], k["C"], p["d"] + 0j
    assert np.allclose(np.abs(C - B), p["b"], atol=1e-12, rtol=0)
    assert np.allclose(np.abs(C - D), p["c"], atol=1e-12, rtol=0)
    assert np.allclose(B + p["b"] * np.exp(1j * k["th3"]), C, atol=1e-12, rtol=0)
    assert np.all(cross(D - B, C - B) > 0)          # C left of (above) B→D, as stated


def test_fourbar_closed_form_against_finite_differences(peers):
    p = peers.FOURBAR
    w = p["omega"]
    k = peers.fourbar_closed_form(PHI, **p)

    def get(key):
        return lambda phi: peers.fourbar_closed_form(phi, **p)[key]

    for ang, vel, acc in (("th3", "w3", "al3"), ("th4", "w4", "al4")):
        dth = w * wrap(get(ang)(PHI + H_FD) - get(ang)(PHI - H_FD)) / (2 * H_FD)
        assert rel(k[vel], dth) < FD_RTOL
        assert rel(k[acc], fd(get(vel), PHI, w)) < FD_RTOL
    assert rel(k["vC"], fd(get("C"), PHI, w)) < FD_RTOL
    assert rel(k["aC"], fd(get("vC"), PHI, w)) < FD_RTOL


def test_slider_closed_form_matches_our_mechanism_and_fd(peers):
    p = peers.SLIDER
    w = p["omega"]
    hand = peers.slider_closed_form(PHI, **p)
    mo = peers.ours_slider().solve(PHI)
    c, rod = mo.points["C"], mo.links["3"]
    assert rel(hand["C"], c.pos) < EXACT
    assert rel(hand["vC"], c.vel) < EXACT
    assert rel(hand["aC"], c.acc) < EXACT
    assert np.max(np.abs(wrap(hand["th3"] - rod.angle))) < EXACT
    assert rel(hand["w3"], rod.omega) < EXACT
    assert rel(hand["al3"], rod.alpha) < EXACT
    assert rel(peers.slider_positions(PHI, **p)["C"], c.pos) < EXACT

    def get(key):
        return lambda phi: peers.slider_closed_form(phi, **p)[key]
    assert rel(hand["vC"], fd(get("C"), PHI, w)) < FD_RTOL
    assert rel(hand["aC"], fd(get("vC"), PHI, w)) < FD_RTOL
    assert rel(hand["al3"], fd(get("w3"), PHI, w)) < FD_RTOL
    # closure and the stated convention: guide y = e, rod length l, slider ahead of the pin
    B = p["r"] * np.exp(1j * PHI)
    assert np.allclose(hand["C"].imag, p["e"], atol=1e-15, rtol=0)
    assert np.allclose(np.abs(hand["C"] - B), p["l"], atol=1e-12, rtol=0)
    assert np.all(hand["C"].real > B.real)


def test_power_balance_torque_matches_our_kinetostatics(peers):
    p = peers.FOURBAR
    m = peers.ours_fourbar(with_masses=True)
    lengths = {"2": p["a"], "3": p["b"], "4": p["c"]}
    bodies = [Body(k, peers.FB_MASSES[k], f"S{k}", peers.FB_MASSES[k] * lengths[k] ** 2 / 12)
              for k in ("2", "3", "4")]
    ours = solve_forces(m, m.solve(PHI), bodies, [], gravity=peers.GRAVITY).driving_torque
    ref = peers.fourbar_power_balance_torque(PHI, **p)
    assert rel(ref, ours) < EXACT
    # and gravity alone at rest-like speed: the crank's own weight torque is m·g·(a/2)·cosφ
    slow = peers.fourbar_power_balance_torque(PHI, **{**p, "omega": 1e-6},
                                              masses={"2": 1.0, "3": 0.0, "4": 0.0})
    assert np.allclose(slow, peers.GRAVITY * p["a"] / 2 * np.cos(PHI), rtol=0, atol=1e-9)


def test_script_runs_without_peers(peers, monkeypatch, capsys):
    for name in ("pylinkage", "mechanism", "kinepy"):
        monkeypatch.setitem(sys.modules, name, None)       # import raises ImportError
    assert peers.main(["--sizes", "24", "--repeat", "1", "--markdown"]) == 0
    out = capsys.readouterr().out
    assert "| four-bar | pylinkage (numba) | 24 |" in out
    assert out.count("not installed") >= 6
    hand_rows = [ln for ln in out.splitlines() if "agreement plain closed form" in ln]
    assert len(hand_rows) == 2 and all("PASS" in ln for ln in hand_rows)
    # every solver measured also alone in a fresh process, with its spread
    assert "pos+vel+acc alone [ms]" in out and "interleaved" in out


def test_plain_closed_forms_match_freudenstein_and_ours(peers):
    """The timing reference (real arithmetic, circle intersection) against the two other
    formulations: Freudenstein's quadratic with complex exponentials, and our engine."""
    p = peers.FOURBAR
    th3, th4, w3, w4, al3, al4, cx, cy, vx, vy, ax, ay = peers.fourbar_plain(PHI, **p)
    ref = peers.fourbar_closed_form(PHI, **p)
    ang = lambda a, b: np.max(np.abs(np.angle(np.exp(1j * (a - b)))))   # noqa: E731
    assert ang(th3, ref["th3"]) < EXACT and ang(th4, ref["th4"]) < EXACT
    assert rel(ref["C"], cx + 1j * cy) < EXACT
    assert rel(ref["vC"], vx + 1j * vy) < EXACT and rel(ref["aC"], ax + 1j * ay) < EXACT
    assert rel(ref["w3"], w3) < EXACT and rel(ref["al4"], al4) < EXACT
    mo = peers.ours_fourbar().solve(PHI)
    assert rel(mo.points["C"].acc, ax + 1j * ay) < EXACT
    t3, t4, px, py = peers.fourbar_plain_positions(PHI, **p)
    assert rel(ref["C"], px + 1j * py) < EXACT and ang(t4, ref["th4"]) < EXACT
    s = peers.SLIDER
    th3, w3, al3, x, v, acc = peers.slider_plain(PHI, **s)
    sref = peers.slider_closed_form(PHI, **s)
    assert ang(th3, sref["th3"]) < EXACT and rel(sref["C"].real, x) < EXACT
    assert rel(sref["vC"].real, v) < EXACT and rel(sref["aC"].real, acc) < EXACT
