"""The one extremes solver (core/extremes.py) against closed forms."""
from __future__ import annotations

import numpy as np
import pytest

from mechdesign.core.extremes import grid_roots, refine_extreme


def test_roots_of_a_shifted_sine_between_grid_points():
    c = 0.123456789
    phi = np.arange(360) * (2 * np.pi / 360)
    roots = grid_roots(lambda x: np.sin(x - c), phi, np.sin(phi - c))
    assert len(roots) == 2
    assert roots[0] == pytest.approx(c, abs=1e-14)
    assert roots[1] == pytest.approx(np.pi + c, abs=1e-14)


def test_a_zero_on_a_grid_point_and_the_wrap_past_the_last_point():
    phi = np.arange(12) * (np.pi / 6)
    # zeros exactly at 90° and at 270°: on grid points
    roots = grid_roots(np.cos, phi, np.cos(phi))
    assert sorted(np.round(np.degrees(roots), 9)) == [90.0, 270.0]
    # a zero between the last grid point (330°) and 360°: returned beyond 330°
    c = np.radians(345.0)
    roots = grid_roots(lambda x: np.sin(x - c), phi, np.sin(phi - c))
    assert any(abs(r - c) < 1e-13 for r in roots)


def test_refined_extremes_of_a_cosine():
    c = 1.2345
    phi = np.arange(100) * (2 * np.pi / 100)
    f = lambda x: 3.0 + np.cos(x - c)  # noqa: E731
    x_max, v_max = refine_extreme(f, phi, f(phi), largest=True)
    x_min, v_min = refine_extreme(f, phi, f(phi))
    assert v_max == pytest.approx(4.0, abs=1e-15) and v_min == pytest.approx(2.0, abs=1e-15)
    # a flat extremum fixes its angle only to ~sqrt(ε) through the values
    assert x_max == pytest.approx(c, abs=1e-6) and x_min == pytest.approx(c + np.pi, abs=1e-6)


def test_the_transcribed_brent_methods_agree_with_scipy_to_the_last_bit():
    """core.extremes carries SciPy's brentq and bounded minimisation transcribed (a run
    need not import scipy.optimize); on 1,500 random functions they give the same bits."""
    from scipy.optimize import brentq as scipy_brentq
    from scipy.optimize import minimize_scalar

    from mechdesign.core.extremes import brentq, fminbound

    rng = np.random.default_rng(7)
    compared = 0
    for t in range(1500):
        c, k, amp = rng.uniform(-2, 2), int(rng.integers(1, 6)), rng.uniform(0.1, 5)
        if t % 3 == 0:
            f = lambda x: amp * np.sin(k * (x - c)) ** 3 + 1e-3 * (x - c)  # noqa: E731
        elif t % 3 == 1:
            f = lambda x: amp * np.tanh(x - c)  # noqa: E731
        else:   # flat, with noise at the rounding level: where an algorithm's path shows
            f = lambda x: amp * (x - c) ** 5 + 1e-17 * np.cos(1e5 * x)  # noqa: E731
        a, b = c - rng.uniform(0.01, 1), c + rng.uniform(0.01, 1)
        if f(a) * f(b) < 0:
            assert brentq(f, a, b) == scipy_brentq(f, a, b, xtol=1e-15,
                                                   rtol=4 * np.finfo(float).eps)
            compared += 1
        g = lambda x: amp * np.cos(k * (x - c)) + 1e-3 * (x - c) ** 4  # noqa: E731
        res = minimize_scalar(g, bounds=(a, b), method="bounded", options={"xatol": 1e-12})
        assert fminbound(g, a, b, 1e-12) == (float(res.x), float(res.fun))
    assert compared > 500


def test_refine_extreme_largest_keeps_the_grid_only_when_the_search_is_worse():
    """sin on a coarse grid whose samples miss its peak at π/2: the search finds 1 (the
    largest), with keep_grid too; a function whose samples are its true extreme keeps them."""
    import numpy as np

    from mechdesign.core.extremes import refine_extreme

    phi = np.linspace(0.0, 3.0, 7)            # samples at 0, 0.5, …: none at π/2
    x, v = refine_extreme(np.sin, phi, np.sin(phi), largest=True, keep_grid=True)
    assert v == pytest.approx(1.0, abs=1e-12) and x == pytest.approx(np.pi / 2, abs=1e-6)
    x, v = refine_extreme(lambda t: -np.cos(t), phi, -np.cos(phi), keep_grid=True)
    assert v == pytest.approx(-1.0, abs=1e-15) and abs(x) < 1e-9


def test_polish_places_a_smooth_minimum_where_its_slope_vanishes():
    """f = 3(t − c)² + 0.1(t − c)³ + 0.5: the minimum is at c exactly (f′(c) = 0, f″ = 6).
    Brent stops within √ε·|t| of it; the polish puts it within 1e-12 — and a last-bit change
    of f (1 ulp of noise added) no longer moves it by ~1e-8."""
    from mechdesign.core.extremes import fminbound, polish_minimum
    c = 1.2345678901234
    f = lambda t: 3 * (t - c) ** 2 + 0.1 * (t - c) ** 3 + 0.5
    x, _ = fminbound(f, 0.0, 2.0)
    assert abs(polish_minimum(f, x, 0.0, 2.0, 1e-4) - c) < 1e-12
    noisy = lambda t: f(t) * (1 + 2.2e-16 * np.sin(1e9 * t))
    xn, _ = fminbound(noisy, 0.0, 2.0)
    assert abs(polish_minimum(noisy, xn, 0.0, 2.0, 1e-4) - c) < 1e-11


def test_polish_leaves_a_kink_and_a_bound_as_brent_found_them():
    """The largest of two lines (a kink at 1.1) and a minimum on the interval's end are not
    smooth minima: the place is returned unchanged."""
    from mechdesign.core.extremes import fminbound, polish_minimum
    g = lambda t: max(t - 1.1, -2 * (t - 1.1))
    x, _ = fminbound(g, 0.0, 2.0)
    assert polish_minimum(g, x, 0.0, 2.0, 1e-4) == x
    assert abs(x - 1.1) < 1e-8
    assert polish_minimum(lambda t: t * t, 1e-5, 0.0, 1.0, 1e-4) == 1e-5
