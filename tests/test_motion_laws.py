"""Dimensionless cam follower motion laws (mechdesign.core.motion_laws).

References, independent of the module's formulas: central finite differences and
cumulative trapezoid integrals of the returned curves; the peak coefficients and impact
types of 孙桓《机械原理》 (cam chapter, table of v_max/a_max: 等速 1.00/∞ rigid, 等加速等减速
2.00/4.00 soft, 余弦加速度 1.57/4.93 soft, 正弦加速度 2.00/6.28 none, 五次多项式 1.88/5.77
none) and the cam-design literature (Rothbart, Cam Design Handbook; Norton, Cam Design
and Manufacturing Handbook) for 4-5-6-7, modified trapezoid and modified sine.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from mechdesign.core.motion_laws import LAWS, MotionLaw, law_names

KEYS = ["constant_velocity", "parabolic", "harmonic", "cycloidal", "poly345", "poly4567",
        "modified_trapezoid", "modified_sine"]
INF = math.inf
PI = math.pi
# Literature peak coefficients (Cv, Ca, Cj); inf = infinite when joined to dwells.
REFERENCE = {
    "constant_velocity": (1.0, INF, INF),
    "parabolic": (2.0, 4.0, INF),
    "harmonic": (PI / 2, PI**2 / 2, INF),
    "cycloidal": (2.0, 2 * PI, 4 * PI**2),
    "poly345": (1.875, 5.7735, 60.0),
    "poly4567": (2.1875, 7.513, 52.5),
    "modified_trapezoid": (2.0, 4.888, 61.43),
    "modified_sine": (1.760, 5.528, 69.47),
}
RIGID = {"constant_velocity"}                 # S' != 0 at an end
SOFT = {"parabolic", "harmonic"}              # S'' != 0 at an end
JUMP_INSIDE = {"parabolic"}                   # S'' jumps at u = 1/2

laws = pytest.mark.parametrize("key", KEYS)


def grid_away_from_breaks(law: MotionLaw, n: int = 4001, margin: float = 1e-3) -> np.ndarray:
    u = np.linspace(margin, 1 - margin, n)
    for b in law.breakpoints:
        u = u[np.abs(u - b) > margin]
    return u


def fine_grid(n: int = 160_000) -> np.ndarray:
    """Uniform grid with every breakpoint (multiples of 1/8) as a node."""
    return np.linspace(0.0, 1.0, n + 1)


def cumtrapz(y: np.ndarray, u: np.ndarray) -> np.ndarray:
    return np.concatenate(([0.0], np.cumsum((y[1:] + y[:-1]) / 2 * np.diff(u))))


def test_registry_order_and_names():
    assert list(LAWS) == KEYS
    assert law_names() == KEYS
    for key, law in LAWS.items():
        assert law.key == key
        assert law.name_zh and law.name_en
        assert len(law.latex) == 3 and all(isinstance(s, str) and "$" not in s for s in law.latex)
        assert list(law.breakpoints) == sorted(law.breakpoints)
        assert all(0 < b < 1 for b in law.breakpoints)
        piecewise = bool(law.breakpoints)
        assert all((r"\begin{cases}" in s) == piecewise for s in law.latex)
    assert LAWS["cycloidal"].name_zh == "摆线运动规律（正弦加速度）"


@laws
def test_end_values_and_monotone(key):
    law = LAWS[key]
    s0, s1 = law(0.0)[0], law(1.0)[0]
    assert s0 == pytest.approx(0.0, abs=1e-14)
    assert s1 == pytest.approx(1.0, abs=1e-14)
    u = np.linspace(0, 1, 100_001)
    s, v, _, _ = law(u)
    assert np.all(np.diff(s) >= -1e-12)  # rounding of polynomial coefficients up to 84
    assert np.all(v >= -1e-12)


@laws
def test_derivatives_match_finite_differences(key):
    law = LAWS[key]
    u = grid_away_from_breaks(law)
    h = 1e-5
    lo, hi = law(u - h), law(u + h)
    mid = law(u)
    for order in range(3):  # S->S', S'->S'', S''->S'''
        fd = (hi[order] - lo[order]) / (2 * h)
        scale = max(1.0, float(np.max(np.abs(mid[order + 1]))))
        np.testing.assert_allclose(mid[order + 1], fd, rtol=0, atol=2e-6 * scale,
                                   err_msg=f"{key}: derivative order {order + 1}")


@laws
def test_integrals_reproduce_lower_derivatives(key):
    law = LAWS[key]
    u = fine_grid()
    s, v, a, j = law(u)
    # A jump of S'' (parabolic) costs one trapezoid panel: error <= jump*h/2.
    tol_a = 1e-4 if key in JUMP_INSIDE else 1e-8
    np.testing.assert_allclose(v[0] + cumtrapz(a, u), v, rtol=0, atol=tol_a)
    np.testing.assert_allclose(s[0] + cumtrapz(v, u), s, rtol=0, atol=1e-8)
    if math.isfinite(law.cj):
        np.testing.assert_allclose(a[0] + cumtrapz(j, u), a, rtol=0, atol=1e-6)


@laws
def test_continuity_at_breakpoints(key):
    law = LAWS[key]
    eps = 1e-9
    assert law.internal_acceleration_jump == (key in JUMP_INSIDE)
    # Interior points: breakpoints plus u = 1/2 (where smooth laws must also be continuous).
    for b in sorted(set(law.breakpoints) | {0.5}):
        left, right = law(b - eps), law(b + eps)
        assert abs(right[0] - left[0]) < 1e-7, (key, b, "S")
        assert abs(right[1] - left[1]) < 1e-6, (key, b, "S'")
        jump_a = abs(right[2] - left[2])
        if law.internal_acceleration_jump and b in law.breakpoints:
            assert jump_a > 1.0, (key, b)
        else:
            assert jump_a < 1e-5, (key, b, "S''")
        if math.isfinite(law.cj):
            assert abs(right[3] - left[3]) < 1e-4, (key, b, "S'''")
    if key == "parabolic":
        left, right = law(0.5 - eps), law(0.5 + eps)
        assert left[2] == pytest.approx(4.0) and right[2] == pytest.approx(-4.0)


@laws
def test_end_values_classify_impacts(key):
    law = LAWS[key]
    _, v0, a0, _ = law(0.0)
    _, v1, a1, _ = law(1.0)
    rigid = abs(v0) > 1e-9 or abs(v1) > 1e-9
    soft = not rigid and (abs(a0) > 1e-9 or abs(a1) > 1e-9)
    assert rigid == (key in RIGID)
    assert soft == (key in SOFT)
    # Infinite coefficients exactly where the rise meets a dwell (or itself) with a jump.
    assert math.isinf(law.ca) == rigid
    assert math.isinf(law.cj) == (rigid or soft or law.internal_acceleration_jump)


@laws
def test_peak_coefficients(key):
    law = LAWS[key]
    u = np.union1d(np.linspace(0, 1, 1_000_001), law.breakpoints)
    curves = law(u)[1:]
    for name, ref, attr, curve in zip(("Cv", "Ca", "Cj"), REFERENCE[key],
                                      (law.cv, law.ca, law.cj), curves):
        if math.isinf(ref):
            assert math.isinf(attr), (key, name)
            continue
        peak = float(np.max(np.abs(curve)))
        assert peak == pytest.approx(ref, rel=1e-3), (key, name)
        assert attr == pytest.approx(ref, rel=1e-3), (key, name)
        assert attr == pytest.approx(peak, rel=1e-6), (key, name)


def test_closed_form_peaks_where_exact():
    assert LAWS["poly345"].ca == pytest.approx(10 / math.sqrt(3), rel=1e-12)
    assert LAWS["cycloidal"].cj == pytest.approx(4 * PI**2, rel=1e-12)
    assert LAWS["modified_trapezoid"].cv == pytest.approx(2.0, rel=1e-12)


@laws
def test_symmetry(key):
    law = LAWS[key]
    u = np.linspace(0, 1, 20_001)
    s, v, a, _ = law(u)
    sr, vr, ar, _ = law(1 - u)
    np.testing.assert_allclose(s + sr, 1.0, rtol=0, atol=1e-12)
    np.testing.assert_allclose(v, vr, rtol=0, atol=1e-10)
    if key not in JUMP_INSIDE:
        np.testing.assert_allclose(a, -ar, rtol=0, atol=1e-9)


@laws
def test_scalar_and_shape(key):
    law = LAWS[key]
    out = law(0.3)
    assert len(out) == 4
    assert all(isinstance(x, np.ndarray) and x.shape == () and x.dtype == float for x in out)
    grid = np.linspace(0, 1, 12).reshape(3, 4)
    out2 = law(grid)
    assert all(x.shape == (3, 4) for x in out2)
    assert float(out2[0][0, 0]) == pytest.approx(0.0, abs=1e-14)
    assert law([0, 1])[0].tolist() == pytest.approx([0.0, 1.0], abs=1e-14)
    assert float(out[0]) == pytest.approx(float(law(np.array([0.3]))[0][0]))
