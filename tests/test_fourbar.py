"""Four-bar and slider-crank synthesis (core.fourbar) against references built here:
the law of cosines in the rocker's extreme triangles, a brute-force position analysis of
the four-bar over a dense crank-angle grid (written in this file, not the program's),
an independent construction of the θ-circle, Grashof's rule by hand, and the textbook's
slider-crank extremes x = √((b ∓ a)² − e²).
"""
from __future__ import annotations

import numpy as np
import pytest

from mechdesign.core import fourbar as fb
from mechdesign.machines.crank_rocker.stages import folded_branch, simulate_four_bar

RAD = np.pi / 180.0


# ------------------------------------------------------------------ independent helpers

def brute_four_bar(a, b, c, d, n=400_001):
    """Rocker angle and transmission angle over a dense crank-angle grid, A at the origin,
    D at (d, 0), by the law of cosines in triangle BCD (one assembly branch)."""
    phi = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
    B = a * np.exp(1j * phi)
    BD = d - B
    f = np.abs(BD)
    cos_delta = (b * b + c * c - f * f) / (2 * b * c)
    delta = np.arccos(cos_delta)
    # angle at D between D→B and D→C
    cos_beta = (c * c + f * f - b * b) / (2 * c * f)
    beta = np.arccos(cos_beta)
    rocker = np.angle(-BD) + beta                 # direction D→C
    gamma = np.minimum(delta, np.pi - delta)
    return phi, np.unwrap(rocker), gamma


def brute_extremes(a, b, c, d):
    """(θ, ψ, γmin) of a crank-rocker from the dense grid (accuracy ~ grid step²)."""
    phi, rocker, gamma = brute_four_bar(a, b, c, d)
    i_max, i_min = int(np.argmax(rocker)), int(np.argmin(rocker))
    psi = rocker[i_max] - rocker[i_min]
    span = (phi[i_max] - phi[i_min]) % (2 * np.pi)
    theta = abs(np.pi - span)
    return theta, psi, float(np.min(gamma))


def circle_by_hand(theta, psi, c):
    """Centre and radius of the θ-circle: chord C1C2 = 2c sin(ψ/2) seen under θ, centre on
    D's side of the chord, D at the origin, the chord horizontal at y = c cos(ψ/2)."""
    w, h = c * np.sin(psi / 2), c * np.cos(psi / 2)
    R = w / np.sin(theta)
    return complex(0.0, h - R * np.cos(theta)), R, complex(w, h), complex(-w, h)


def lengths_from_pivot(A, C1, C2):
    ac1, ac2 = abs(A - C1), abs(A - C2)
    return (ac2 - ac1) / 2, (ac2 + ac1) / 2, abs(A)


# ------------------------------------------------------------------------------- tests

@pytest.mark.parametrize("fbar, turns, kind", [
    (fb.FourBar(1.0, 3.0, 4.0, 5.0), True, "crank-rocker"),       # 1 + 5 < 3 + 4, crank shortest
    (fb.FourBar(3.0, 4.0, 5.0, 1.0), True, "double-crank"),       # frame shortest
    (fb.FourBar(3.0, 1.0, 4.0, 5.0), False, "double-rocker"),     # coupler shortest
    (fb.FourBar(3.0, 4.0, 1.0, 5.0), False, "rocker-crank"),      # rocker shortest
    (fb.FourBar(4.0, 5.0, 6.0, 8.0), False, "triple-rocker"),     # 4 + 8 > 5 + 6
    (fb.FourBar(2.0, 3.0, 3.0, 2.0), True, "change-point"),       # 2 + 3 = 3 + 2
])
def test_grashof_classification(fbar, turns, kind):
    ok, text = fb.grashof(fbar)
    assert ok is turns
    assert text.startswith(kind)


@pytest.mark.parametrize("lengths", [(16.0, 46.0, 50.0, 53.76), (20.0, 60.0, 45.0, 70.0),
                                     (10.0, 35.0, 30.0, 32.0), (25.0, 80.0, 60.0, 90.0)])
def test_transmission_angle_and_extremes_closed_forms_vs_brute_force(lengths):
    a, b, c, d = lengths
    design = fb.FourBar(a, b, c, d)
    assert fb.grashof(design) == (True, "crank-rocker")
    th_bf, psi_bf, g_bf = brute_extremes(a, b, c, d)
    gmin, gmax = fb.transmission_angle_extremes(design)
    theta, psi = fb.crank_rocker_extremes(design)
    assert gmin == pytest.approx(g_bf, abs=1e-9)      # γ is extreme exactly on the grid (φ = 0, π)
    assert theta == pytest.approx(th_bf, abs=2e-5)    # grid step 1.6e-5 rad
    assert psi == pytest.approx(psi_bf, abs=1e-9)
    _, _, gamma = brute_four_bar(a, b, c, d)
    assert gmax == pytest.approx(float(np.max(gamma)), abs=1e-4)   # a kink at 90°: linear in the step


def test_textbook_design_from_K_matches_hand_construction():
    """K = 1.25 (θ = 20°), ψ = 45°, rocker 60 mm, frame 65 mm: the crank pivot A is found
    here by bisection on the circle |AD| = 65 mm for ∠C1AC2 = θ, without the θ-circle."""
    K, psi, c, d = 1.25, 45 * RAD, 0.060, 0.065
    theta = np.pi * (K - 1) / (K + 1)
    w, h = c * np.sin(psi / 2), c * np.cos(psi / 2)
    C1, C2 = complex(w, h), complex(-w, h)

    def angle_at(beta):       # A = d·(sin β, −cos β), β from the downward vertical towards +x
        A = d * complex(np.sin(beta), -np.cos(beta))
        u, v = C1 - A, C2 - A
        return np.angle(v / u)

    # bracket the root of ∠C1AC2 − θ on a coarse grid of β, then bisect
    lo, hi = psi / 2 + 1e-9, np.pi - psi / 2 - 1e-9
    g = lambda beta: abs(angle_at(beta)) - theta   # noqa: E731
    betas = np.linspace(lo, hi, 2001)
    vals = np.array([g(x) for x in betas])
    k = int(np.nonzero(np.sign(vals[:-1]) != np.sign(vals[1:]))[0][0])
    x0, x1 = betas[k], betas[k + 1]
    for _ in range(200):
        xm = 0.5 * (x0 + x1)
        if np.sign(g(xm)) == np.sign(g(x0)):
            x0 = xm
        else:
            x1 = xm
    A = d * complex(np.sin(x0), -np.cos(x0))
    a_ref, b_ref, d_ref = lengths_from_pivot(A, C1, C2)
    got = fb.crank_rocker_from_K(K, psi, c, d)
    assert got.crank == pytest.approx(a_ref, rel=1e-10)
    assert got.coupler == pytest.approx(b_ref, rel=1e-10)
    assert got.frame == pytest.approx(d, rel=1e-12) and got.rocker == pytest.approx(c)
    # and its extremes are the specification, by the law of cosines
    th, ps = fb.crank_rocker_extremes(got)
    assert th == pytest.approx(theta, abs=1e-12) and ps == pytest.approx(psi, abs=1e-12)


@pytest.mark.parametrize("K, psi_deg, c, d", [(1.1818181818181819, 40, 0.05, 0.05376),
                                              (1.25, 45, 0.06, 0.065), (1.4, 80, 0.1, None),
                                              (1.1, 25, 0.08, 0.1)])
def test_synthesised_designs_reproduce_K_and_swing_in_simulation(K, psi_deg, c, d):
    """The designed linkage assembled with core.mechanism (crank + RRR) and simulated."""
    psi = psi_deg * RAD
    if d is None:
        d = float(np.mean(fb.frame_range(K, psi, c)))
    cons = fb.circle_construction(K, psi, c)
    p = fb.position_for_frame(cons, d)
    design = fb.crank_rocker_from_K(K, psi, c, d)
    A = complex(cons.point(p))
    sim = simulate_four_bar("t", design, A, folded_branch(design, A, cons.c1), 1.0, 3600)
    assert sim.K == pytest.approx(K, abs=1e-9)
    assert sim.swing == pytest.approx(psi, abs=1e-9)
    assert sim.gamma_min == pytest.approx(fb.transmission_angle_extremes(design)[0], abs=1e-9)
    # the independent brute force agrees to its grid accuracy
    th_bf, psi_bf, g_bf = brute_extremes(design.crank, design.coupler, design.rocker, design.frame)
    assert th_bf == pytest.approx(np.pi * (K - 1) / (K + 1), abs=2e-5)
    assert psi_bf == pytest.approx(psi, abs=1e-8)


def test_optimum_is_the_maximum_of_an_independent_dense_scan():
    theta, psi, c = 15 * RAD, 40 * RAD, 0.05
    K = (np.pi + theta) / (np.pi - theta)
    best, gbest = fb.optimal_crank_rocker(K, psi, c)
    O, R, C1, C2 = circle_by_hand(theta, psi, c)
    # points of the circle on C1's side (x > 0), below the chord, outside the wedge behind D
    t = np.linspace(1e-6, np.pi - theta - 1e-6, 400_001)
    A = O + R * (np.sin(t) - 1j * np.cos(t))
    same_side = (np.conj(A) * C1).imag * (np.conj(A) * C2).imag > 0
    a, b, d = lengths_from_pivot(A, C1, C2)
    d1 = np.arccos((b * b + c * c - (d - a) ** 2) / (2 * b * c))
    d2 = np.arccos((b * b + c * c - (d + a) ** 2) / (2 * b * c))
    g = np.where(same_side, np.minimum(np.minimum(d1, np.pi - d1), np.minimum(d2, np.pi - d2)), 0)
    k = int(np.argmax(g))
    assert gbest >= g[k] - 1e-12
    assert gbest == pytest.approx(g[k], abs=1e-9)
    assert best.frame == pytest.approx(d[k], rel=1e-4)
    assert best.crank == pytest.approx(a[k], rel=1e-4)
    # neighbours on the circle are not better
    p, _ = fb.optimal_position(K, psi, c)
    for dp in (-1e-4, 1e-4, -1e-2, 1e-2):
        assert float(fb.gamma_min_on_arc(K, psi, c, p + dp)) < gbest
    # the result meets θ and ψ; the optimum is scale-free (l3/l4 from the chart)
    th, ps = fb.crank_rocker_extremes(best)
    assert th == pytest.approx(theta, abs=1e-12) and ps == pytest.approx(psi, abs=1e-12)
    big, gbig = fb.optimal_crank_rocker(K, psi, 10 * c)
    assert gbig == pytest.approx(gbest, abs=1e-10)
    assert big.frame == pytest.approx(10 * best.frame, rel=1e-7)


def test_papers_computer_result_misses_its_own_theta_and_psi():
    paper = fb.FourBar(16.2227, 44.5093, 50.0, 53.8986)
    th, ps, g = brute_extremes(paper.crank, paper.coupler, paper.rocker, paper.frame)
    assert abs(th - 15 * RAD) > 0.3 * RAD          # it has θ ≈ 15.42°
    assert abs(ps - 40 * RAD) > 0.1 * RAD          # and ψ ≈ 40.12°
    _, gbest = fb.optimal_crank_rocker(195 / 165, 40 * RAD, 50.0)
    assert gbest > g                                # and our γmin is larger


def test_circle_centred_on_D_cannot_fix_the_frame():
    """θ = ψ/2 puts the θ-circle's centre on D: every A has frame = rocker."""
    with pytest.raises(fb.SynthesisError, match="centred on D"):
        fb.crank_rocker_from_K(1.4, 60 * RAD, 0.1, 0.09)


def test_theta_zero_only_approaches_the_limit():
    psi = 40 * RAD
    _, g = fb.optimal_position_theta(0.0, psi, 1.0)
    assert g <= np.pi / 2 - psi / 2 + 1e-9          # (cancellation at a huge frame)
    assert g == pytest.approx(np.pi / 2 - psi / 2, abs=1e-4)


@pytest.mark.parametrize("K, H, e", [(1.4, 0.1, 0.02), (1.2, 0.1, 0.005), (1.5, 0.3, 0.1)])
def test_offset_slider_crank_reproduces_stroke_and_K(K, H, e):
    a, b = fb.offset_slider_crank(K, H, e)
    x1, x2 = np.sqrt((b - a) ** 2 - e ** 2), np.sqrt((b + a) ** 2 - e ** 2)
    assert x2 - x1 == pytest.approx(H, rel=1e-12)
    theta = np.arcsin(e / (b - a)) - np.arcsin(e / (b + a))
    assert (np.pi + theta) / (np.pi - theta) == pytest.approx(K, rel=1e-12)
    # brute force: slider position and pressure angle over the crank angle, guide y = −e
    phi = np.linspace(0, 2 * np.pi, 400_001, endpoint=False)
    yb = a * np.sin(phi) + e
    x = a * np.cos(phi) + np.sqrt(b * b - yb * yb)
    assert x.max() - x.min() == pytest.approx(H, rel=1e-8)
    alpha = np.arcsin(np.abs(yb) / b)
    slow, fast = fb.slider_crank_pressure_angles(a, b, e)
    assert fast == pytest.approx(alpha.max(), abs=1e-9)
    assert fb.slider_crank_pressure_angle_max(a, b, e) == pytest.approx(alpha.max(), abs=1e-9)
    i_max, i_min = int(np.argmax(x)), int(np.argmin(x))
    out = ((phi - phi[i_min]) % (2 * np.pi)) <= ((phi[i_max] - phi[i_min]) % (2 * np.pi))
    slow_mask = out if ((phi[i_max] - phi[i_min]) % (2 * np.pi)) > np.pi else ~out
    assert slow == pytest.approx(alpha[slow_mask].max(), abs=1e-4)
    assert slow < fast


@pytest.mark.parametrize("call, words", [
    (lambda: fb.crank_rocker_from_K(1.25, 45 * RAD, 0.06, 0.5), "frame length"),
    (lambda: fb.crank_rocker_from_K(1.25, 45 * RAD, 0.06, 0.03), "frames between"),
    (lambda: fb.crank_rocker_from_K(3.5, 45 * RAD, 0.06, 0.065), "K < 3"),
    (lambda: fb.crank_rocker_from_K(1.25, 190 * RAD, 0.06, 0.065), "swing"),
    (lambda: fb.offset_slider_crank(1.4, 0.1, 0.2), "H·cot θ"),
    (lambda: fb.offset_slider_crank(1.0, 0.1, 0.02), "K = 1"),
    (lambda: fb.offset_slider_crank(1.4, 0.1, 0.0), "offset"),
    (lambda: fb.slider_crank_pressure_angle_max(0.05, 0.06, 0.02), "cannot turn fully"),
])
def test_synthesis_errors_say_what_to_change(call, words):
    with pytest.raises(fb.SynthesisError, match=words.replace("(", r"\(")):
        call()


def test_frame_range_ends_are_excluded_and_inside_works():
    K, psi, c = 1.25, 45 * RAD, 0.06
    lo, hi = fb.frame_range(K, psi, c)
    assert lo == pytest.approx(c, rel=1e-12)    # A → C1: the frame tends to the rocker
    for d in (lo * (1 - 1e-6), hi * (1 + 1e-6)):
        with pytest.raises(fb.SynthesisError, match="frames between"):
            fb.crank_rocker_from_K(K, psi, c, d)
    mid = fb.crank_rocker_from_K(K, psi, c, 0.5 * (lo + hi))
    assert fb.grashof(mid) == (True, "crank-rocker")
