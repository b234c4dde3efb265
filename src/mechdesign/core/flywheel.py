"""Flywheel design (飞轮设计) from the resistance torque over one steady-state cycle.

The driving torque is constant; over a cycle it does the same work as the
resistance, so it equals the mean resistance torque. The kinetic-energy change
ΔE(φ) = ∫(M_d − M_r)dφ; the largest swing ΔW_max = max ΔE − min ΔE (最大盈亏功), at the
exact extremes when the caller gives the exact integral and the extremes' candidates.
Textbook (孙桓 §7): J_F = ΔW_max / (ω_m²·[δ]) = 900·ΔW_max / (π²·n²·[δ]) with n in rpm
on the shaft carrying the flywheel; the mechanism's own inertia is neglected (course
convention, on the safe side).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np
from .fields import q


@dataclass(frozen=True)
class EnergyCycle:
    """Energy bookkeeping over one revolution of the reference shaft."""

    angle: np.ndarray = q("rad", "shaft angle from the cycle start")
    resistance_torque: np.ndarray = q("N·m", "M_r on the flywheel shaft")
    driving_torque: float = q("N·m", "constant M_d on the flywheel shaft")
    energy: np.ndarray = q("J", "ΔE(φ) = ∫(M_d − M_r)dφ")
    max_energy_swing: float = q("J", "ΔW_max")
    angle_at_min: float = q("rad")
    angle_at_max: float = q("rad")


def energy_cycle(angle: np.ndarray, resistance_torque: np.ndarray,
                 integral: Callable[[np.ndarray], np.ndarray] | None = None,
                 stationary: Callable[[float], np.ndarray] | None = None) -> EnergyCycle:
    """Energy over one cycle sampled at ``angle`` (uniform, covering [0, period), [rad]).

    ``integral(φ)``, when given, is the exact ∫₀^φ M_r dφ [J] at any φ in [0, period]
    (for a piecewise load: each piece integrated between its exact ends): M_d is then
    integral(period)/period and ΔE is exact at the samples. ``stationary(M_d)`` gives the
    angles where ΔE may be extreme (the roots of M_r − M_d and the angles where M_r jumps);
    ΔW_max is then the exact max − min over those and the samples. Without them: the
    trapezoidal rule on the closed (periodic) samples and the samples' extremes."""
    angle = np.asarray(angle, float)
    mr = np.asarray(resistance_torque, float)
    step = angle[1] - angle[0]
    period = step * len(angle)
    if integral is None:
        closed = np.append(mr, mr[0])
        work_r = np.concatenate(([0.0], np.cumsum((closed[1:] + closed[:-1]) / 2.0 * step)))
        md = work_r[-1] / period
        energy = md * angle - work_r[:-1]
        where, values = angle, energy
    else:
        md = float(integral(np.array([period]))[0]) / period
        energy = md * angle - integral(angle)
        where, values = angle, energy
        if stationary is not None:
            extra = np.asarray(stationary(md), float)
            if len(extra):
                where = np.concatenate((angle, extra))
                values = np.concatenate((energy, md * extra - integral(extra)))
    i_min, i_max = int(np.argmin(values)), int(np.argmax(values))
    return EnergyCycle(angle, mr, float(md), energy, float(values[i_max] - values[i_min]),
                       float(where[i_min]), float(where[i_max]))


def flywheel_inertia(max_energy_swing: float, speed_rpm: float, fluctuation: float) -> float:
    """J_F [kg·m²] = 900·ΔW_max/(π²·n²·[δ]), n [rpm] of the flywheel shaft."""
    return 900.0 * max_energy_swing / (np.pi**2 * speed_rpm**2 * fluctuation)


@dataclass(frozen=True)
class RimFlywheel:
    """Cast rim flywheel: mean diameter D, rim width b and height H (H = ratio·b) [m]."""

    diameter: float = q("m", "mean rim diameter D")
    width: float = q("m", "rim width b")
    height: float = q("m", "rim height H")
    rim_mass: float = q("kg")
    rim_speed: float = q("m/s", "peripheral speed at D")


def rim_dimensions(inertia: float, diameter: float, height_to_width: float,
                   specific_weight: float, speed_rpm: float, gravity: float = 9.81) -> RimFlywheel:
    """Rim of a wheel whose inertia is all in a thin rim at mean diameter D.

    m = 4·J_F/D²; m·g = γ·π·D·H·b with H = k·b → b = √(4·g·J_F / (π·D³·k·γ)).
    γ is the material's specific weight [N/m³] (cast iron ≈ 7×10⁴ N/m³).
    """
    mass = 4.0 * inertia / diameter**2
    width = np.sqrt(mass * gravity / (specific_weight * np.pi * diameter * height_to_width))
    return RimFlywheel(diameter, float(width), float(height_to_width * width), float(mass),
                       float(np.pi * diameter * speed_rpm / 60.0))
