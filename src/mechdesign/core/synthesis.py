"""Dimensional synthesis (尺寸综合) of quick-return linkages from the time ratio K.

Textbook relations (孙桓《机械原理》 §8, 课程设计指导书): the extreme-position angle
θ = 180°·(K − 1)/(K + 1). For the guide-bar (导杆) quick-return mechanism the guide
bar's swing equals θ, the crank is perpendicular to the bar at both extremes, and the
ram guide passes through the mid-point of the sagitta of B's arc so that the
pressure angle on the ram is smallest on average.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def extreme_angle(time_ratio_K: float) -> float:
    """Extreme-position angle θ [rad] for time ratio K (K ≥ 1)."""
    return np.pi * (time_ratio_K - 1.0) / (time_ratio_K + 1.0)


def time_ratio(extreme_position_angle: float) -> float:
    """Time ratio K = (180° + θ)/(180° − θ) for θ [rad]."""
    return (np.pi + extreme_position_angle) / (np.pi - extreme_position_angle)


@dataclass(frozen=True)
class GuideBarDesign:
    """Link lengths of a guide-bar quick-return six-bar [m] and angles [rad]."""

    swing_angle: float        # ψ = θ, swing of the guide bar [rad]
    crank: float              # L_O2A [m]
    frame: float              # L_O2O3, crank pivot to guide-bar pivot [m]
    guide_bar: float          # L_O3B [m]
    rod: float                # L_BF [m]
    guide_height: float       # L_O3M, ram guide line above O3 [m]
    bar_com: float            # L_O3S4 [m]


def guide_bar_quick_return(stroke: float, time_ratio_K: float, frame: float,
                           rod_ratio: float, com_ratio: float) -> GuideBarDesign:
    """Synthesise the shaper-type guide-bar mechanism.

    stroke H [m], time ratio K, frame L_O2O3 [m], rod_ratio L_BF/L_O3B,
    com_ratio L_O3S4/L_O3B.
    """
    psi = extreme_angle(time_ratio_K)
    half = psi / 2.0
    bar = stroke / (2.0 * np.sin(half))
    return GuideBarDesign(
        swing_angle=psi,
        crank=frame * np.sin(half),
        frame=frame,
        guide_bar=bar,
        rod=rod_ratio * bar,
        guide_height=bar * (1.0 + np.cos(half)) / 2.0,
        bar_com=com_ratio * bar,
    )
