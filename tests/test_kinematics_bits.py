"""The RRP dyad's solver (kin.rrp, written in real arithmetic with few temporaries for
speed) gives the numbers of the closure equation solved in complex form bit for bit.

Reference: the complex-form solution below (the form kin.rrp had before issue 22's speed
work): B in guide coordinates by one complex product, s = x ± √(l² − h²), C = G + s·e, and
the velocity and acceleration closures iω·u − ṡ·e = −v_B, iα·u − s̈·e = ω²·u − a_B solved by
Cramer's rule on complex columns. Signs of zeros are compared too; NaN where the rod cannot
reach the guide.
"""
from __future__ import annotations

import numpy as np
import pytest

from mechdesign.core import kinematics as kin


def _cross(p, q):
    return p.real * q.imag - p.imag * q.real


def _rrp_complex(b, length, guide_point, guide_angle, branch):
    e = np.exp(1j * guide_angle)
    local = (b.pos - guide_point) * np.conj(e)
    h = local.imag
    root = length**2 - h**2
    root[~(root >= 0.0)] = np.nan
    s = local.real + branch * np.sqrt(root)
    c_pos = guide_point + s * e
    u = c_pos - b.pos
    th = np.arctan2(u.imag, u.real)
    a = 1j * u
    det = _cross(a, -e)
    with np.errstate(divide="ignore", invalid="ignore"):
        w, ds = _cross(-b.vel, -e) / det, _cross(a, -b.vel) / det
        rhs = w * w * u
        rhs -= b.acc
        al, dds = _cross(rhs, -e) / det, _cross(a, rhs) / det
    return (th, w, al, s, ds, dds, c_pos, ds * e, dds * e)


def _same(x, y):
    x, y = np.asarray(x), np.asarray(y)
    if x.dtype.kind == "c":
        return _same(x.real, y.real) and _same(x.imag, y.imag)
    ok = ~np.isnan(x)
    return np.array_equal(x, y, equal_nan=True) and \
        np.array_equal(np.signbit(x[ok]), np.signbit(y[ok]))


@pytest.mark.parametrize("seed", range(4))
def test_rrp_equals_the_complex_form_bit_for_bit(seed):
    rng = np.random.default_rng(seed)
    for trial in range(150):
        n = int(rng.integers(1, 60))
        phi = rng.uniform(0, 2 * np.pi, n)
        phi[: min(n, 4)] = [0.0, np.pi / 2, np.pi, 1.5 * np.pi][: min(n, 4)]
        r = rng.uniform(0.01, 1.0)
        omega = rng.choice([-1.0, 1.0]) * rng.uniform(0.1, 30.0)
        pivot = kin.fixed_point(complex(*rng.normal(size=2)) if trial % 2 else 0j, n)
        _, b = kin.crank(pivot, r, phi, omega)
        if trial % 3 == 1:                      # B with an acceleration of its own
            b = kin.PointMotion(b.pos, b.vel * rng.normal(), b.acc + rng.normal())
        angle = rng.choice([0.0, np.pi / 2, np.pi, -np.pi / 2, rng.uniform(-np.pi, np.pi)])
        guide = complex(*rng.normal(size=2))
        length = rng.uniform(0.5, 3.0) * r         # some positions cannot be assembled (NaN)
        branch = int(rng.choice([1, -1]))
        rod, slide, c = kin.rrp(b, length, guide, angle, branch)
        got = (rod.angle, rod.omega, rod.alpha, slide.s, slide.ds, slide.dds, c.pos, c.vel, c.acc)
        want = _rrp_complex(b, length, guide, angle, branch)
        for name, x, y in zip(("θ", "ω", "α", "s", "ṡ", "s̈", "C", "v_C", "a_C"), got, want):
            assert _same(x, y), (trial, name)
