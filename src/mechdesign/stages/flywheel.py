"""The one flywheel stage (飞轮设计) of every machine that has a flywheel.

From the balancing torque M_b on the crank over one steady-state revolution: the energy
cycle (ΔE, ΔW_max, where they occur), the flywheel inertia on the chosen shaft
J_F = 900·ΔW_max/(π²·n²·[δ]) (孙桓 §7, mechanism inertia neglected), the same flywheel
referred to the crank, and — when the machine sizes a cast rim — the rim (m = 4J_F/D²,
b, H = k·b) with its checks: the rim speed against cast iron's ~30 m/s and the rim's
proportions (its radial height must leave a hole: H < D).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core import flywheel as fw
from ..core.fields import q
from ..core.errors import DesignError
from ..i18n import N_
from .findings import Finding, Msg, finding

CAST_IRON_RIM_SPEED = 30.0   # [m/s] usual limit of a cast-iron rim's peripheral speed


@dataclass(frozen=True)
class RimSpec:
    """Cast rim to size: mean diameter D [m], H/b, material's specific weight γ [N/m³]."""

    diameter: float = q("m", "mean rim diameter D")
    height_to_width: float = q("1", "H/b")
    specific_weight: float = q("N/m³", "γ of the rim material")
    field: str = q("", "the brief's rim-diameter field: set, an impossible rim (H ≥ D) is an "
                   "error there and a rim higher than its radius a warning", default="")


@dataclass(frozen=True)
class FlywheelSpec:
    """Allowed speed fluctuation [δ]; the flywheel shaft's speed as a multiple of the
    crank's; the shaft's name (as the machine calls it); the rim to size, if any."""

    fluctuation: float = q("1", "[δ]")
    speed_ratio: float = q("1", "flywheel shaft speed / crank speed", default=1.0)
    shaft: object = q("", default="crank")
    rim: RimSpec | None = q("", default=None)


def brief_flywheel(p, ratio: float | None = None) -> FlywheelSpec:
    """The flywheel a machine's brief gives (its params ``p``): [δ], on shaft
    ``p.flywheel_shaft``, the cast rim to size (D, H/b, γ; a rim that cannot be is reported
    at the brief's field flywheel.rim_diameter_mm). ``ratio``: the shaft's speed over the
    crank's; by default the gear pair's z2/z1 on the pinion (a gear pair exists), 1 on the
    crank shaft."""
    if ratio is None:
        ratio = p.z2 / p.z1 if p.flywheel_shaft == "pinion" else 1.0
    return FlywheelSpec(p.fluctuation, ratio, p.flywheel_shaft,
                        RimSpec(p.rim_diameter, p.rim_height_to_width, p.specific_weight,
                                "flywheel.rim_diameter_mm"))


@dataclass(frozen=True)
class Flywheel:
    """Stage 飞轮设计 (the flywheel evens out M_b; the mechanism's own inertia neglected)."""

    shaft: str | int = q("", "the machine's name (or drive index) of the flywheel shaft")
    speed_ratio: float = q("1", "flywheel shaft speed / crank speed")
    shaft_speed_rpm: float = q("rpm")
    mean_torque: float = q("N·m", "M_d on the crank = mean M_b")
    shaft_torque: float = q("N·m", "the same on the flywheel shaft, M_d / i")
    mean_power: float = q("W", "mean power delivered to the crank")
    energy: np.ndarray = q("J", "ΔE over the crank phase grid")
    max_energy_swing: float = q("J", "ΔW_max")
    phase_at_min: float = q("rad")
    phase_at_max: float = q("rad")
    fluctuation: float = q("1", "[δ]")
    inertia: float = q("kg·m²", "J_F on the flywheel shaft")
    inertia_on_crank: float = q("kg·m²", "the same flywheel's duty on the crank")
    rim: fw.RimFlywheel | None = q("", "sized rim, when the machine asks for one")
    warnings: tuple[Finding, ...] = q("", "rim speed, rim proportions", default=())
    nominal_speed_rpm: float | None = q("rpm", "the shaft's nominal speed (crank speed × ratio) when "
                                        "J_F is sized at the slower speed the drive realises; "
                                        "None: sized at the nominal speed", default=None)


#: Crank speeds below this [rpm] or flywheels above this [kg·m²] are no course machine's:
#: named (a rim, when sized, is checked by its proportions instead).
SLOW_RPM = 1.0
ABSURD_INERTIA = 1e4


def design_flywheel(spec: FlywheelSpec, phase: np.ndarray, balancing_torque: np.ndarray,
                    crank_omega: float, gravity: float = 9.81, exact=None) -> Flywheel:
    """The flywheel for M_b [N·m] sampled on the uniform crank ``phase`` grid [rad].
    ``exact`` (the linkage engine's :class:`~mechdesign.stages.linkage.CycleIntegrals`):
    M_d, ΔE and ΔW_max from the exact ∫M_b dφ at the exact extremes, not the samples."""
    if exact is None:
        cycle = fw.energy_cycle(phase, balancing_torque)
    else:
        cycle = fw.energy_cycle(phase, balancing_torque, exact.integral, exact.stationary)
    crank_rpm = abs(crank_omega) * 30.0 / np.pi
    speed = crank_rpm * spec.speed_ratio
    inertia = fw.flywheel_inertia(cycle.max_energy_swing, speed, spec.fluctuation)
    on_crank = fw.flywheel_inertia(cycle.max_energy_swing, crank_rpm, spec.fluctuation)
    rim, warnings = None, []
    if spec.rim is not None:
        rim, warnings = _rim(spec, inertia, speed, crank_rpm, gravity)
    elif crank_rpm < SLOW_RPM or inertia > ABSURD_INERTIA:
        warnings.append(finding(
            "flywheel_absurd",
            N_("the flywheel J_F = {J:.4g} kg·m² (crank at {n:.4g} rpm) is beyond any machine of "
               "the course: J_F = 900·ΔW_max/(π²·n²·[δ]) grows as 1/n²; check the crank speed, or "
               "put the flywheel on a faster shaft."), J=inertia, n=crank_rpm))
    return Flywheel(
        shaft=spec.shaft, speed_ratio=float(spec.speed_ratio), shaft_speed_rpm=float(speed),
        mean_torque=cycle.driving_torque, shaft_torque=cycle.driving_torque / spec.speed_ratio,
        mean_power=cycle.driving_torque * abs(crank_omega), energy=cycle.energy,
        max_energy_swing=cycle.max_energy_swing, phase_at_min=cycle.angle_at_min,
        phase_at_max=cycle.angle_at_max, fluctuation=spec.fluctuation, inertia=inertia,
        inertia_on_crank=on_crank, rim=rim, warnings=tuple(warnings))


def _rim(spec: FlywheelSpec, inertia: float, speed: float, crank_rpm: float, gravity: float):
    """The cast rim for ``inertia`` at the shaft ``speed`` [rpm] and its findings (a rim the
    brief's diameter cannot carry raises :class:`FlywheelDesignError`)."""
    rim = fw.rim_dimensions(inertia, spec.rim.diameter, spec.rim.height_to_width,
                            spec.rim.specific_weight, speed, gravity)
    if spec.rim.field:
        impossible_rim(rim, spec, inertia, speed, crank_rpm, gravity)
    return rim, list(rim_findings(rim, spec.rim.field))


def at_realised_speed(fl: Flywheel, spec: FlywheelSpec, speed_rpm: float,
                      gravity: float = 9.81) -> Flywheel:
    """``fl`` sized again at the speed [rpm] the drive realises on its shaft, when that is
    slower than the nominal one: J_F = 900·ΔW_max/(π²·n′²·[δ]) grows as 1/n′², so the slower
    speed is the one that keeps δ ≤ [δ] (ΔW_max, computed at the nominal speed, is kept)."""
    from dataclasses import replace

    inertia = fw.flywheel_inertia(fl.max_energy_swing, speed_rpm, fl.fluctuation)
    rim, warnings = fl.rim, fl.warnings
    if spec.rim is not None:
        rim, found = _rim(spec, inertia, speed_rpm, speed_rpm / fl.speed_ratio, gravity)
        warnings = tuple(found)
    return replace(fl, shaft_speed_rpm=float(speed_rpm), inertia=float(inertia),
                   inertia_on_crank=float(inertia * fl.speed_ratio**2), rim=rim, warnings=warnings,
                   nominal_speed_rpm=float(fl.shaft_speed_rpm))


class FlywheelDesignError(DesignError):
    """No cast rim of the brief's diameter can carry the flywheel."""


def smallest_rim_diameter(inertia: float, height_to_width: float, specific_weight: float,
                          gravity: float) -> float:
    """The mean diameter [m] at which the rim's height equals its radius, H = D/2:
    H = √(4 g J_F k/(π D³ γ)) = D/2 ⇔ D⁵ = 16 g J_F k/(π γ)."""
    return float((16.0 * gravity * inertia * height_to_width / (np.pi * specific_weight)) ** 0.2)


def impossible_rim(rim: fw.RimFlywheel, spec: FlywheelSpec, inertia: float, speed: float,
                   crank_rpm: float, gravity: float) -> None:
    """Raise :class:`FlywheelDesignError` at the brief's rim field when the rim's radial
    height reaches its mean diameter (no hole left: no rim of that diameter can carry J_F)."""
    if rim.height < rim.diameter and np.isfinite(rim.height):
        return
    r = spec.rim
    d_min = smallest_rim_diameter(inertia, r.height_to_width, r.specific_weight, gravity)
    raise FlywheelDesignError(Msg(
        N_("{field} = {D:g}: the flywheel J_F = {J:.4g} kg·m² at {speed:.4g} rpm needs a rim of "
           "height H = {H:.4g} mm and width b = {b:.4g} mm, not smaller than its mean diameter "
           "D = {D:g} mm: no rim of this diameter can carry it. Take D ≥ {d_min:.4g} mm (then "
           "H ≤ D/2), put the flywheel on a faster shaft, or check the crank speed n = {n:.4g} "
           "rpm (J_F = 900·ΔW_max/(π²·n²·[δ]) grows as 1/n²)."),
        field=r.field, D=r.diameter * 1e3, J=inertia, speed=speed, H=rim.height * 1e3,
        b=rim.width * 1e3, d_min=d_min * 1e3, n=crank_rpm))


def rim_findings(rim: fw.RimFlywheel, field: str = "") -> list[Finding]:
    out = []
    if rim.rim_speed > CAST_IRON_RIM_SPEED:
        out.append(finding(
            "rim_speed",
            N_("the flywheel rim speed {v:.1f} m/s exceeds about 30 m/s allowed for cast iron: "
               "reduce the rim diameter or use a steel wheel."), v=rim.rim_speed))
    if rim.height >= rim.diameter:
        out.append(finding(
            "rim_proportion",
            N_("the flywheel rim height H = {H:.1f} mm is not smaller than its mean diameter "
               "D = {D:.1f} mm, so the rim cannot be made: increase the rim's mean diameter D or "
               "put the flywheel on a faster shaft."), H=rim.height * 1e3, D=rim.diameter * 1e3))
    elif field and rim.height > rim.diameter / 2.0:
        out.append(finding(
            "rim_proportion",
            N_("the flywheel rim height H = {H:.1f} mm exceeds its mean radius D/2 = {R:.1f} mm: "
               "it is no longer a thin rim and m = 4J_F/D² is a poor estimate; increase the rim's "
               "mean diameter D or put the flywheel on a faster shaft."), field=field, H=rim.height * 1e3,
            R=rim.diameter * 500))
    return out
