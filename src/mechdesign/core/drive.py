"""The drive (传动装置): efficiency chain, motor choice, ratio allocation and the table
of speed, power and torque on every shaft (运动和动力参数), following
《机械设计课程设计》 (chapter 2, 传动装置的总体设计).

Pure computation: the motor catalogue and default efficiencies come in as arguments.
SI inside: power [W], torque [N·m], speeds in rpm where a name says ``_rpm``.

Conventions:
- The drive is a chain of elements from the motor shaft (shaft 0) to the machine's input
  shaft; element k connects shaft k to shaft k + 1 (a coupling, too: the course's table
  lists the motor shaft and the first reducer shaft separately).
- Every shaft after the motor runs in one pair of rolling bearings; its loss is charged to
  the power the shaft passes on (η₁₂ = η_bearing · η_gear, as the course tables do), and the
  last shaft's bearings to the power delivered to the machine.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import DesignError, Msg, N_, pgettext
from .fields import q

SYNCHRONOUS_PREFERENCE = (1500, 1000, 3000, 750)   # rpm; 1500 and 1000 are the usual choice


class DriveDesignError(DesignError):
    """A drive that cannot meet the brief (no motor, ratio out of every range)."""


@dataclass(frozen=True)
class Motor:
    designation: str = q("", "catalogue designation (Y series)")
    power: float = q("W", "rated power P_ed")
    synchronous_rpm: float = q("rpm", "synchronous speed")
    full_load_rpm: float = q("rpm", "full-load speed n_m")
    frame_height: float = q("m", "shaft centre height")
    starting_torque_ratio: float = q("1", "T_st / T_n")
    max_torque_ratio: float = q("1", "T_max / T_n")
    shaft_diameter: float | None = q("m", "shaft extension diameter D (by frame; null: not "
                                     "in the catalogue)", default=None)
    shaft_length: float | None = q("m", "shaft extension length E (null: not in the catalogue)",
                                   default=None)

    @property
    def rated_torque(self) -> float:
        """T_n = P / ω at full load [N·m]."""
        return self.power / (self.full_load_rpm * np.pi / 30.0)


@dataclass(frozen=True)
class Element:
    """One transmission element. ``ratio`` is fixed by the brief (teeth, pulleys) or
    ``None`` for the allocation to choose within ``recommended`` (lo, hi)."""

    kind: str = q("", "belt | chain | spur | helical | open_spur | worm | coupling")
    efficiency: float = q("1", "η of the element")
    recommended: tuple[float, float] = q("1", "recommended ratio range (lo, hi)")
    ratio_max: float = q("1", "largest ratio")
    ratio: float | None = q("1", "fixed ratio, None: free", default=None)


@dataclass(frozen=True)
class MotorCandidate:
    """The motor a synchronous speed offers and whether the chain can reach its ratio."""

    synchronous_rpm: float = q("rpm", "synchronous speed tried")
    motor: Motor | None = q("", "the smallest motor of that speed with P ≥ P_d")
    total_ratio: float = q("1", "i = n_m / n_w (null without a motor)")
    recommended: bool = q("", "the total ratio lies in the product of the recommended ranges")
    possible: bool = q("", "the total ratio lies in the product of the maximum ranges")


@dataclass(frozen=True)
class MotorChoice:
    motor: Motor = q("", "the motor chosen")
    total_ratio: float = q("1", "i = n_m / n_w")
    candidates: tuple[MotorCandidate, ...] = q("", "one per synchronous speed tried")
    reason: str = q("", "'given' | 'recommended' | 'maximum'")


@dataclass(frozen=True)
class ShaftState:
    """One row of the table of speed, power and torque (运动和动力参数)."""

    index: int = q("1", "shaft number, 0 = motor shaft")
    speed_rpm: float = q("rpm", "n")
    power: float = q("W", "P")
    torque: float = q("N·m", "T = P/ω")


def chain_efficiency(element_eff: list[float], bearing_eff: float, machine_eff: float = 1.0) -> float:
    """η = Π η_elements · η_bearing^(shafts after the motor) · η_machine."""
    return float(np.prod(element_eff) * bearing_eff ** len(element_eff) * machine_eff)


def ratio_bounds(elements: list[Element], recommended: bool = True) -> tuple[float, float]:
    """Smallest and largest total ratio the chain can give."""
    lo = hi = 1.0
    for el in elements:
        if el.ratio is not None:
            lo, hi = lo * el.ratio, hi * el.ratio
        elif recommended:
            lo, hi = lo * el.recommended[0], hi * el.recommended[1]
        else:
            hi *= el.ratio_max
    return lo, hi


def choose_motor(catalogue: list[Motor], power_required: float, output_rpm: float,
                 elements: list[Element], synchronous_rpm: float | None = None,
                 tolerance: float = 0.0) -> MotorChoice:
    """The smallest motor the drive can use: at each synchronous speed (1500, 1000, 3000,
    750 rpm, or the brief's) the smallest motor with P_ed ≥ P_d; of these, the one of
    least rated power whose total ratio n_m/n_w the chain can give within its maximum
    ranges; among equal powers, one whose ratio lies within the recommended ranges, then
    the order of the speeds. A stage beyond its recommended but within its maximum ratio
    is a usual design; a motor several catalogue sizes larger than P_d needs (a 750 rpm
    motor is heavy for its power) is not, so power comes before the recommended range.
    The ranges are widened by the speed ``tolerance`` (a fraction), so a chain of fixed
    ratios accepts a motor whose speed it meets within the tolerance; a given speed with
    only fixed ratios is taken as it is (the speed check then reports the error)."""
    speeds = (synchronous_rpm,) if synchronous_rpm else SYNCHRONOUS_PREFERENCE
    rec_lo, rec_hi = ratio_bounds(elements, True)
    max_lo, max_hi = ratio_bounds(elements, False)
    widen = 1.0 + tolerance
    rec_lo, max_lo, rec_hi, max_hi = rec_lo / widen, max_lo / widen, rec_hi * widen, max_hi * widen
    all_fixed = all(el.ratio is not None for el in elements)
    candidates = []
    for sync in speeds:
        fitting = [m for m in catalogue if m.synchronous_rpm == sync and m.power >= power_required]
        motor = min(fitting, key=lambda m: m.power) if fitting else None
        i = motor.full_load_rpm / output_rpm if motor else float("nan")
        candidates.append(MotorCandidate(sync, motor, i, bool(motor and rec_lo <= i <= rec_hi),
                                         bool(motor and max_lo <= i <= max_hi)))
    usable = [(k, c) for k, c in enumerate(candidates)
              if c.motor and (c.possible or (synchronous_rpm and all_fixed))]
    if usable:
        _, c = min(usable, key=lambda kc: (kc[1].motor.power, not kc[1].recommended, kc[0]))
        reason = "given" if synchronous_rpm else ("recommended" if c.recommended else "maximum")
        return MotorChoice(c.motor, c.total_ratio, tuple(candidates), reason)
    largest = max((m.power for m in catalogue), default=0.0)
    if not any(c.motor for c in candidates):
        at = pgettext("synchronous speed", " at {rpm:g} rpm", rpm=synchronous_rpm) if synchronous_rpm else ""
        raise DriveDesignError(
            N_("no motor in the catalogue gives {power_kw:.3f} kW{at} (largest: {largest_kw:g} "
               "kW): reduce the load or the speed, or allow another synchronous speed"),
            power_kw=power_required / 1e3, at=at, largest_kw=largest / 1e3)
    # each "1500 rpm → i = 12.3" a message of its own (the unit is "r/min" in Chinese), joined
    # by a message without words
    tried = [pgettext("synchronous speed", "{rpm:g} rpm → i = {i:.1f}", rpm=c.synchronous_rpm,
                      i=c.total_ratio) for c in candidates if c.motor]
    ratios = Msg(", ".join(f"{{r{k}}}" for k in range(len(tried))),
                 **{f"r{k}": m for k, m in enumerate(tried)})
    raise DriveDesignError(
        N_("the drive's stages give total ratios {max_lo:.3g}–{max_hi:.3g}, but the motors "
           "need {ratios} to reach {output_rpm:g} rpm: add a stage or change a fixed ratio"),
        max_lo=max_lo, max_hi=max_hi, ratios=ratios, output_rpm=output_rpm)


def allocate_ratios(total: float, elements: list[Element]) -> list[float]:
    """Split ``total`` over the elements without a fixed ratio.

    Each free stage gets its typical ratio (the geometric mean of its recommended range)
    scaled by a common factor, so stages stay in proportion (a belt below the gear pair
    it drives, as the textbook asks). Two adjacent closed cylindrical gear stages (a
    two-stage expanded reducer) then split their product by i_fast = √(1.4 i), the
    textbook's i₁ ≈ (1.3–1.5) i₂ for similar immersion of both wheels.
    """
    fixed = float(np.prod([el.ratio for el in elements if el.ratio is not None]))
    free = [k for k, el in enumerate(elements) if el.ratio is None and el.kind != "coupling"]
    ratios = [el.ratio if el.ratio is not None else 1.0 for el in elements]
    if not free:
        return ratios
    typical = [float(np.sqrt(elements[k].recommended[0] * elements[k].recommended[1])) for k in free]
    scale = (total / fixed / np.prod(typical)) ** (1.0 / len(free))
    for k, t in zip(free, typical):
        ratios[k] = t * scale
    closed = ("spur", "helical")
    for a, b in zip(free, free[1:]):
        if b == a + 1 and elements[a].kind in closed and elements[b].kind in closed:
            pair = ratios[a] * ratios[b]
            ratios[a] = float(np.sqrt(1.4 * pair))
            ratios[b] = pair / ratios[a]
    return ratios


def shaft_table(motor_rpm: float, power_in: float, ratios: list[float], element_eff: list[float],
                bearing_eff: float) -> list[ShaftState]:
    """Speed, power and torque (T = P/ω) of every shaft, shaft 0 being the motor's."""
    n, P = motor_rpm, power_in
    shafts = [ShaftState(0, n, P, P / (n * np.pi / 30.0))]
    for k, (i, eta) in enumerate(zip(ratios, element_eff)):
        P = P * eta * (bearing_eff if k > 0 else 1.0)
        n = n / i
        shafts.append(ShaftState(k + 1, n, P, P / (n * np.pi / 30.0)))
    return shafts


def train_ratio(meshes: list[tuple[int, int, bool]]) -> float:
    """Signed ratio ω_in/ω_out of an ordinary (fixed-axis) gear train:
    i = (−1)^m Π z_driven / Π z_driving, m = number of external meshes.
    ``meshes`` = (z_driving, z_driven, external) in order from input to output."""
    sign = (-1) ** sum(1 for _, _, ext in meshes if ext)
    return sign * float(np.prod([zb / za for za, zb, _ in meshes]))


# Worm starts by ratio (textbook table 11-1): i ≈ 7–13 → 4, 14–27 → 2, 28–40 → 2 or 1, > 40 → 1.
def worm_starts(ratio: float) -> int:
    return 4 if ratio < 14 else 2 if ratio < 30 else 1


# V-belt pulley datum diameters, GB/T 13575.1 (mm).
PULLEY_DIAMETERS_MM = (50, 53, 56, 60, 63, 67, 71, 75, 80, 85, 90, 95, 100, 106, 112, 118, 125, 132,
                       140, 150, 160, 170, 180, 200, 212, 224, 236, 250, 265, 280, 300, 315, 335, 355,
                       375, 400, 425, 450, 475, 500, 530, 560, 600, 630, 670, 710, 750, 800, 900, 1000)


def standard_pulley(d_mm: float) -> float:
    """The standard datum diameter nearest to ``d_mm`` [mm]."""
    return float(min(PULLEY_DIAMETERS_MM, key=lambda s: abs(s - d_mm)))


def belt_ratio(d1: float, d2: float, slip: float) -> float:
    """n1/n2 = d2 / (d1 (1 − ε)) with elastic slip ε."""
    return d2 / (d1 * (1.0 - slip))
