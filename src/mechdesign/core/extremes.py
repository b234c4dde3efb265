"""The one extremes solver: where a function of the crank angle, sampled on a uniform grid
over one revolution, has its zeros (the dead centres: zeros of an analytic velocity) or
its extreme values (a bounded search between the grid's neighbours).

Every stroke, swing, time ratio and extreme angle of the package is found with these two:
the linkage engine's motion (zeros of the output's velocity) and verification (bounded
search on the position), the crank-rocker's simulated designs, the die-cutter's platen top.
"""
from __future__ import annotations

from typing import Callable

import numpy as np

TWO_PI = 2.0 * np.pi


def grid_roots(fun: Callable[[float], float], phi: np.ndarray, values: np.ndarray,
               zero_tol: float = 1e-9) -> list[float]:
    """Roots of ``fun`` on the periodic uniform grid ``phi`` (one revolution), where
    ``values`` = fun(phi): Brent's method between neighbours whose values change sign
    (to ~1e-15 rad); a zero on a grid point (round-off giving both neighbours the same sign,
    |value| ≤ ``zero_tol``·max|values|) is taken there. Roots past the last grid point are
    returned beyond phi[-1] (not wrapped)."""
    from scipy.optimize import brentq

    values = np.asarray(values, float)
    h = float(phi[1] - phi[0])
    scale = float(np.max(np.abs(values))) if len(values) else 0.0
    roots = []
    for i in np.flatnonzero(np.sign(values) != np.sign(np.roll(values, -1))):
        a, b = float(phi[i]), float(phi[i]) + h
        va, vb = fun(a), fun(b)
        if va == 0.0:
            roots.append(a)
        elif va * vb < 0:
            roots.append(float(brentq(fun, a, b, xtol=1e-15, rtol=4 * np.finfo(float).eps)))
        elif min(abs(va), abs(vb)) <= zero_tol * scale:
            roots.append(a if abs(va) <= abs(vb) else b)
    return roots


def refine_extreme(fun: Callable[[float], float], phi: np.ndarray, values: np.ndarray,
                   largest: bool = False, keep_grid: bool = False) -> tuple[float, float]:
    """(angle, value) of the smallest (``largest``: the largest) value of ``fun``: a bounded
    scalar search (Brent, xatol 1e-12 rad) between the grid neighbours of the grid's own
    extreme. ``keep_grid``: the grid point is kept when the search does not improve on it."""
    from scipy.optimize import minimize_scalar

    sign = -1.0 if largest else 1.0
    values = np.asarray(values, float)
    h = float(phi[1] - phi[0])
    k = int(np.argmax(values) if largest else np.argmin(values))
    res = minimize_scalar(lambda x: sign * fun(x), bounds=(phi[k] - h, phi[k] + h),
                          method="bounded", options={"xatol": 1e-12})
    if keep_grid and sign * res.fun > sign * values[k]:
        return float(phi[k]), float(values[k])
    return float(res.x), float(sign * res.fun)
