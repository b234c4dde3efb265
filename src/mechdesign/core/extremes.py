"""The one extremes solver: where a function of the crank angle, sampled on a uniform grid
over one revolution, has its zeros (the dead centres: zeros of an analytic velocity) or
its extreme values (a bounded search between the grid's neighbours).

Every stroke, swing, time ratio and extreme angle of the package is found with these two:
the linkage engine's motion (zeros of the output's velocity) and verification (bounded
search on the position), the crank-rocker's simulated designs, the die-cutter's platen top.
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np

TWO_PI = 2.0 * np.pi
_RTOL = 4 * np.finfo(float).eps


def brentq(f: Callable[[float], float], xa: float, xb: float, xtol: float = 1e-15,
           rtol: float = _RTOL, maxiter: int = 100) -> float:
    """Brent's root finder on [xa, xb] (f changes sign there): the algorithm and the
    floating-point steps of SciPy's ``brentq`` (its C routine, transcribed), so that
    results agree to the last bit without importing scipy.optimize (a fifth of a run's
    start-up); ``tests/test_extremes.py`` checks the agreement."""
    xpre, xcur = float(xa), float(xb)
    xblk = fblk = spre = scur = 0.0
    fpre, fcur = float(f(xpre)), float(f(xcur))
    if fpre == 0:
        return xpre
    if fcur == 0:
        return xcur
    if math.copysign(1.0, fpre) == math.copysign(1.0, fcur):
        raise ValueError("f(a) and f(b) must have different signs")
    for _ in range(maxiter):
        if fpre != 0 and fcur != 0 and math.copysign(1.0, fpre) != math.copysign(1.0, fcur):
            xblk, fblk = xpre, fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = (xtol + rtol * abs(xcur)) / 2
        sbis = (xblk - xcur) / 2
        if fcur == 0 or abs(sbis) < delta:
            return xcur
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:
                stry = -fcur * (xcur - xpre) / (fcur - fpre)          # interpolate
            else:
                dpre = (fpre - fcur) / (xpre - xcur)                  # extrapolate
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            if 2 * abs(stry) < min(abs(spre), 3 * abs(sbis) - delta):
                spre, scur = scur, stry                               # good short step
            else:
                spre = scur = sbis                                    # bisect
        else:
            spre = scur = sbis                                        # bisect
        xpre, fpre = xcur, fcur
        if abs(scur) > delta:
            xcur += scur
        else:
            xcur += delta if sbis > 0 else -delta
        fcur = float(f(xcur))
    return xcur


def fminbound(func: Callable[[float], float], x1: float, x2: float, xatol: float = 1e-12,
              maxfun: int = 500) -> tuple[float, float]:
    """(x, f(x)) of the minimum of ``func`` on [x1, x2] by Brent's bounded method: the
    steps of SciPy's ``minimize_scalar(method='bounded')`` transcribed (tested to agree)."""
    sqrt_eps = math.sqrt(2.2e-16)
    golden_mean = 0.5 * (3.0 - math.sqrt(5.0))
    a, b = float(x1), float(x2)
    fulc = a + golden_mean * (b - a)
    nfc, xf = fulc, fulc
    rat = e = 0.0
    x = xf
    fx = float(func(x))
    num = 1
    ffulc = fnfc = fx
    xm = 0.5 * (a + b)
    tol1 = sqrt_eps * abs(xf) + xatol / 3.0
    tol2 = 2.0 * tol1
    while abs(xf - xm) > (tol2 - 0.5 * (b - a)):
        golden = True
        if abs(e) > tol1:                                   # a parabolic fit
            golden = False
            r = (xf - nfc) * (fx - ffulc)
            q = (xf - fulc) * (fx - fnfc)
            p = (xf - fulc) * q - (xf - nfc) * r
            q = 2.0 * (q - r)
            if q > 0.0:
                p = -p
            q = abs(q)
            r = e
            e = rat
            if abs(p) < abs(0.5 * q * r) and p > q * (a - xf) and p < q * (b - xf):
                rat = (p + 0.0) / q
                x = xf + rat
                if (x - a) < tol2 or (b - x) < tol2:
                    si = _sign(xm - xf) + ((xm - xf) == 0)
                    rat = tol1 * si
            else:
                golden = True
        if golden:                                          # a golden-section step
            e = (a - xf) if xf >= xm else (b - xf)
            rat = golden_mean * e
        si = _sign(rat) + (rat == 0)
        x = xf + si * max(abs(rat), tol1)
        fu = float(func(x))
        num += 1
        if fu <= fx:
            if x >= xf:
                a = xf
            else:
                b = xf
            fulc, ffulc = nfc, fnfc
            nfc, fnfc = xf, fx
            xf, fx = x, fu
        else:
            if x < xf:
                a = x
            else:
                b = x
            if fu <= fnfc or nfc == xf:
                fulc, ffulc = nfc, fnfc
                nfc, fnfc = x, fu
            elif fu <= ffulc or fulc == xf or fulc == nfc:
                fulc, ffulc = x, fu
        xm = 0.5 * (a + b)
        tol1 = sqrt_eps * abs(xf) + xatol / 3.0
        tol2 = 2.0 * tol1
        if num >= maxfun:
            break
    return xf, fx


def _sign(x: float) -> float:
    return (x > 0) - (x < 0)


def grid_roots(fun: Callable[[float], float], phi: np.ndarray, values: np.ndarray,
               zero_tol: float = 1e-9) -> list[float]:
    """Roots of ``fun`` on the periodic uniform grid ``phi`` (one revolution), where
    ``values`` = fun(phi): Brent's method between neighbours whose values change sign
    (to ~1e-15 rad); a zero on a grid point (round-off giving both neighbours the same sign,
    |value| ≤ ``zero_tol``·max|values|) is taken there. Roots past the last grid point are
    returned beyond phi[-1] (not wrapped)."""
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
            roots.append(brentq(fun, a, b, xtol=1e-15, rtol=_RTOL))
        elif min(abs(va), abs(vb)) <= zero_tol * scale:
            roots.append(a if abs(va) <= abs(vb) else b)
    return roots


def refine_extreme(fun: Callable[[float], float], phi: np.ndarray, values: np.ndarray,
                   largest: bool = False, keep_grid: bool = False) -> tuple[float, float]:
    """(angle, value) of the smallest (``largest``: the largest) value of ``fun``: a bounded
    scalar search (Brent, xatol 1e-12 rad) between the grid neighbours of the grid's own
    extreme. ``keep_grid``: the grid point is kept when the search does not improve on it."""
    sign = -1.0 if largest else 1.0
    values = np.asarray(values, float)
    h = float(phi[1] - phi[0])
    k = int(np.argmax(values) if largest else np.argmin(values))
    x, fx = fminbound(lambda x: sign * fun(x), float(phi[k] - h), float(phi[k] + h), xatol=1e-12)
    if keep_grid and fx > sign * values[k]:      # fx is sign·fun at the search's point
        return float(phi[k]), float(values[k])
    return float(x), float(sign * fx)


def polish_minimum(func: Callable[[float], float], x: float, lo: float, hi: float,
                   h: float) -> float:
    """The place of a smooth minimum of ``func`` near Brent's ``x`` to ~1e-12 of its scale.

    Brent's bounded search stops within √ε·|x| (its ``tol1``): near a smooth minimum the
    values of points that far apart differ by less than a rounding, so the place it returns
    moves by ~1e-8 with the last bit of the function (another numpy build, another CPU).
    Where the minimum is smooth — one-sided slopes over h and 2h in the ratio 1 : 2, as a
    parabola gives — the place is the zero of the five-point derivative
    (f(t − 2h) − 8f(t − h) + 8f(t + h) − f(t + 2h))/(12h) (Brent's root finder, bracket
    x ± h), whose error is its truncation, O(h⁴), the same on every machine.
    A kink (the minimum of two branches, a bound) is left as Brent found it: there the
    values fix the place to the search's own tolerance."""
    a, b = max(lo, x - 3 * h), min(hi, x + 3 * h)
    if a > x - 3 * h or b < x + 3 * h:
        return x                                   # at (or by) a bound: not a smooth interior minimum
    f0 = float(func(x))
    dl1, dl2 = (float(func(x - h)) - f0) / h, (float(func(x - 2 * h)) - f0) / (2 * h)
    dr1, dr2 = (float(func(x + h)) - f0) / h, (float(func(x + 2 * h)) - f0) / (2 * h)
    if not all(d > 0 for d in (dl1, dl2, dr1, dr2)) or not (
            1.5 <= dl2 / dl1 <= 2.5 and 1.5 <= dr2 / dr1 <= 2.5):
        return x

    def slope(t: float) -> float:        # 12h × the five-point derivative, error O(h⁴)
        return (float(func(t - 2 * h)) - float(func(t + 2 * h))
                + 8.0 * (float(func(t + h)) - float(func(t - h))))

    if not slope(x - h) < 0.0 < slope(x + h):
        return x
    return brentq(slope, x - h, x + h, xtol=1e-15, rtol=_RTOL)
