"""core.cam.polyline_distance: the shortest distance from points to a closed polyline, in
numpy only (issue 22 point 6: it replaced a scipy.spatial.cKDTree query whose import cost
~0.2 s of every roller-cam run).

The reference is a brute force written here in real arithmetic: every point against every
segment (the foot of the perpendicular clipped to the segment), the minimum. The function
must give it for any polyline (self-crossing, repeated vertices, long segments beside short
ones, one or two vertices) and any order of the points. One case in closed form shows what
the former method (the segments next to the 6 nearest vertices) got wrong: a point beside
the middle of a long segment whose own vertices are far away."""
from __future__ import annotations

import numpy as np
import pytest

from mechdesign.core.cam import polyline_distance


def brute_force(points, polyline) -> np.ndarray:
    p = np.atleast_1d(np.asarray(points, dtype=complex))
    v = np.asarray(polyline, dtype=complex)
    x0, y0 = v.real, v.imag
    dx, dy = np.roll(x0, -1) - x0, np.roll(y0, -1) - y0
    ll = dx * dx + dy * dy
    out = np.empty(len(p))
    for s in range(0, len(p), 256):
        px, py = p[s:s + 256].real[:, None], p[s:s + 256].imag[:, None]
        t = ((px - x0) * dx + (py - y0) * dy) / np.where(ll > 0, ll, 1.0)
        t = np.clip(np.where(ll > 0, t, 0.0), 0.0, 1.0)
        out[s:s + 256] = np.min(np.hypot(px - x0 - t * dx, py - y0 - t * dy), axis=1)
    return out


def test_a_point_beside_a_long_segment_closed_form():
    """The segment (−1, 0)–(1, 0) closed by 2001 vertices along y = 0.1 back from x = 1 to
    x = −1. The point (0, −0.01) is 0.01 from the long segment; its 6 nearest vertices are
    all on y = 0.1 (0.11 away; the long segment's ends are 1.00005 away), so the former
    method answered 0.11."""
    back = np.linspace(1.0, -1.0, 2001) + 0.1j
    poly = np.concatenate([[-1.0 + 0j, 1.0 + 0j], back])
    got = polyline_distance([-0.01j, 0.5 + 0.05j, 3.0 + 0j], poly)
    # (0.5, 0.05) is midway between the two lines; (3, 0) is 2 from the vertex (1, 0)
    np.testing.assert_allclose(got, [0.01, 0.05, 2.0], rtol=0, atol=1e-15)


def test_circle_closed_form():
    """A regular 1000-gon inscribed in the unit circle: the distance of a point at radius ρ
    on the bisector of an edge is |ρ − cos(π/1000)|, at a vertex's angle |ρ − 1| (ρ ≥ 1)."""
    n = 1000
    poly = np.exp(2j * np.pi * np.arange(n) / n)
    mid = np.exp(2j * np.pi * (np.arange(n) + 0.5) / n)
    rho = np.linspace(0.2, 3.0, n)
    np.testing.assert_allclose(polyline_distance(rho * mid, poly),
                               np.abs(rho - np.cos(np.pi / n)), rtol=0, atol=1e-14)
    out = 1.0 + rho
    np.testing.assert_allclose(polyline_distance(out * poly, poly), rho, rtol=0, atol=1e-14)


def _polylines(rng):
    """Polylines of many kinds, with a point set for each."""
    t = np.sort(rng.uniform(0, 2 * np.pi, 1500))
    cam = (0.05 + 0.01 * np.sin(3 * t) + 0.004 * np.cos(7 * t)) * np.exp(1j * t)
    yield "cam-like, ordered offset points", cam, \
        cam + 0.008 * np.exp(1j * (t + 0.1)) * rng.uniform(0.5, 1.5, len(t))
    few = cam[::20]
    u, k = np.linspace(0, 1, 10000), np.linspace(0, 1, len(few))
    yield "cam-like, many more points than vertices", few, \
        (np.interp(u, k, few.real) + 1j * np.interp(u, k, few.imag)) * rng.uniform(0.8, 1.2, len(u))
    walk = np.cumsum(rng.normal(size=500) + 1j * rng.normal(size=500))
    yield "self-crossing random walk", walk, \
        rng.uniform(-30, 30, 3000) + 1j * rng.uniform(-30, 30, 3000)
    rep = np.repeat(rng.normal(size=200) + 1j * rng.normal(size=200), rng.integers(1, 4, 200))
    yield "repeated vertices (zero-length segments)", rep, \
        rng.normal(size=2000) + 1j * rng.normal(size=2000)
    mixed = np.concatenate([np.linspace(0, 1, 3000) * 0.001j, [5.0 + 0.001j, 5.0 + 0j]])
    yield "long segments beside dense short ones", mixed, \
        rng.uniform(-1, 6, 1500) + 1j * rng.uniform(-0.01, 0.01, 1500)
    for m in (1, 2, 3, 9, 64, 65, 513):
        v = rng.normal(size=m) + 1j * rng.normal(size=m)
        yield f"{m} vertices", v, rng.normal(size=500) * 3 + 1j * rng.normal(size=500) * 3
    many = np.exp(2j * np.pi * np.arange(40000) / 40000) * (1 + 0.05 * rng.normal(size=40000))
    yield "40 000 vertices, a few points", many, rng.normal(size=150) + 1j * rng.normal(size=150)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_equals_the_brute_force(seed):
    rng = np.random.default_rng(seed)
    for name, poly, pts in _polylines(rng):
        pts = np.concatenate([pts, poly[:: max(1, len(poly) // 50)]])   # and on vertices
        ref = brute_force(pts, poly)
        got = polyline_distance(pts, poly)
        scale = np.max(np.abs(poly)) + 1.0
        np.testing.assert_allclose(got, ref, rtol=0, atol=1e-12 * scale, err_msg=name)
        shuffled = rng.permutation(len(pts))             # any order: the same distances
        np.testing.assert_array_equal(polyline_distance(pts[shuffled], poly), got[shuffled])


def test_edge_cases():
    assert polyline_distance([], [1.0 + 0j, 2.0]).shape == (0,)
    assert polyline_distance(3.0 + 4.0j, [0j])[0] == pytest.approx(5.0, abs=1e-15)
    assert np.isnan(polyline_distance([np.nan + 0j], [0j, 1.0]))[0]


def test_a_roller_cam_run_does_not_import_scipy_spatial():
    """The roller envelope and the cam's self-checks measure distances without a spatial
    index: computing exercise 7-3 (a roller follower) imports no scipy.spatial."""
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).parents[1]
    script = r"""
import sys
from mechdesign.brief.loader import load_variant
from mechdesign.machines import get_machine, stages_for
from mechdesign.pipeline import run_stages
v = load_variant(sys.argv[1], None)
m = get_machine(v.brief.machine)
params = m.to_params(v.brief)
results, _ = run_stages(stages_for(m, params), {"params": params, "brief": v.brief})
print("scipy.spatial" in sys.modules)
"""
    out = subprocess.run([sys.executable, "-c", script, str(root / "designs" / "cam_7_3.yaml")],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr[-2000:]
    assert out.stdout.strip() == "False"
