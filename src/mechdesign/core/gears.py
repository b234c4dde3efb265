"""Involute gear geometry (孙桓《机械原理》, chapter on gears): external spur pairs, standard
or profile-shifted, helical and worm pairs' basic geometry.

SI or any consistent length unit (the formulas are homogeneous); angles in radians.
Work in progress for the gear issue: geometry only, no strength checks yet.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq


def inv(alpha):
    """Involute function inv α = tan α − α."""
    return np.tan(alpha) - alpha


def inv_inverse(value: float) -> float:
    """The angle α in [0, π/2) with inv α = ``value`` (≥ 0)."""
    if value < 0:
        raise ValueError("the involute function is not negative")
    if value == 0:
        return 0.0
    return float(brentq(lambda a: inv(a) - value, 0.0, np.pi / 2 - 1e-9, xtol=1e-15))


@dataclass(frozen=True)
class GearDims:
    z: int
    x: float          # profile-shift coefficient
    d: float          # pitch (reference) diameter
    db: float         # base diameter
    da: float         # tip diameter
    df: float         # root diameter
    ha: float         # addendum
    hf: float         # dedendum
    s: float          # tooth thickness on the pitch circle
    e: float          # space width on the pitch circle
    sa: float         # tooth thickness on the tip circle
    alpha_a: float    # pressure angle at the tip


@dataclass(frozen=True)
class SpurPair:
    m: float
    alpha: float
    ha_star: float
    c_star: float
    g1: GearDims
    g2: GearDims
    p: float            # circular pitch π m
    pb: float           # base pitch p cos α
    a: float            # standard centre distance
    a_work: float       # working centre distance a'
    alpha_work: float   # working pressure angle α'
    y: float            # centre distance modification coefficient (a' − a)/m
    dy: float           # tip reduction coefficient Δy = x1 + x2 − y
    clearance: float    # radial clearance at the working centre distance
    ratio: float        # z2 / z1
    contact_ratio: float
    action_length: float  # B1B2, the actual line of action
    z_min: float        # smallest tooth number without undercut (standard, this α, ha*)
    x_min1: float       # smallest shift avoiding undercut, gear 1
    x_min2: float


def _gear(m, z, x, alpha, ha, hf) -> GearDims:
    d = m * z
    db = d * np.cos(alpha)
    da, df = d + 2 * ha, d - 2 * hf
    s = m * (np.pi / 2 + 2 * x * np.tan(alpha))
    e = np.pi * m - s
    alpha_a = float(np.arccos(db / da))
    sa = s * da / d - da * (inv(alpha_a) - inv(alpha))
    return GearDims(z, x, d, db, da, df, ha, hf, s, e, float(sa), alpha_a)


def spur_pair(m: float, z1: int, z2: int, alpha: float = np.radians(20.0), ha_star: float = 1.0,
              c_star: float = 0.25, x1: float = 0.0, x2: float = 0.0) -> SpurPair:
    """External spur pair without backlash. The working pressure angle follows from
    inv α' = 2 tan α (x1 + x2)/(z1 + z2) + inv α, the centre distance from a' cos α' = a cos α;
    the tips are shortened by Δy·m so that the clearance stays c*·m."""
    a = m * (z1 + z2) / 2
    alpha_w = inv_inverse(2 * np.tan(alpha) * (x1 + x2) / (z1 + z2) + inv(alpha))
    a_w = a * np.cos(alpha) / np.cos(alpha_w)
    y = (a_w - a) / m
    dy = x1 + x2 - y
    g1 = _gear(m, z1, x1, alpha, (ha_star + x1 - dy) * m, (ha_star + c_star - x1) * m)
    g2 = _gear(m, z2, x2, alpha, (ha_star + x2 - dy) * m, (ha_star + c_star - x2) * m)
    eps = (z1 * (np.tan(g1.alpha_a) - np.tan(alpha_w)) + z2 * (np.tan(g2.alpha_a) - np.tan(alpha_w))) / (2 * np.pi)
    pb = np.pi * m * np.cos(alpha)
    z_min = 2 * ha_star / np.sin(alpha) ** 2
    return SpurPair(m, alpha, ha_star, c_star, g1, g2, np.pi * m, pb, a, a_w, alpha_w, y, dy,
                    a_w - g1.da / 2 - g2.df / 2, z2 / z1, float(eps), float(eps * pb), z_min,
                    ha_star * (z_min - z1) / z_min, ha_star * (z_min - z2) / z_min)


@dataclass(frozen=True)
class HelicalPair:
    mn: float
    mt: float
    beta: float
    alpha_t: float
    d1: float
    d2: float
    a: float


def helical_pair(mn: float, z1: int, z2: int, beta: float, alpha_n: float = np.radians(20.0)) -> HelicalPair:
    """Basic geometry of a standard helical pair: m_t = m_n / cos β, tan α_t = tan α_n / cos β."""
    mt = mn / np.cos(beta)
    return HelicalPair(mn, mt, beta, float(np.arctan(np.tan(alpha_n) / np.cos(beta))), mt * z1, mt * z2,
                       mt * (z1 + z2) / 2)


@dataclass(frozen=True)
class WormPair:
    m: float
    q: float
    z1: int
    z2: int
    d1: float
    d2: float
    lead_angle: float
    a: float
    ratio: float


def worm_pair(m: float, q: float, z1: int, z2: int) -> WormPair:
    """Worm (z1 starts, diameter factor q) and wheel (z2): d1 = m q, d2 = m z2,
    tan γ = z1 / q, a = m (q + z2)/2."""
    return WormPair(m, q, z1, z2, m * q, m * z2, float(np.arctan(z1 / q)), m * (q + z2) / 2, z2 / z1)


def worm_efficiency(lead_angle: float, friction_angle: float) -> float:
    """Meshing efficiency of a worm driving its wheel: η = tan γ / tan(γ + φ_v)."""
    return float(np.tan(lead_angle) / np.tan(lead_angle + friction_angle))
