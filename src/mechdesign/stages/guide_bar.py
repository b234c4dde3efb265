"""Stages shared by the guide-bar (quick-return) machines — the shaper and the slotter:
the synthesis from H, K, the frame and the link ratios, and the drive whose last stage is
the gear pair z1/z2 turning the crank."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.fields import q
from ..core.synthesis import GuideBarDesign, guide_bar_quick_return
from ..pipeline import Stage


@dataclass(frozen=True)
class Synthesis:
    """Stage 导杆机构设计: the link lengths [m] and angles [rad]."""

    design: GuideBarDesign = q("")
    extreme_angle: float = q("rad", "θ")
    guide_height_above_O2: float = q("m", "L_O2M = L_O3M − L_O2O3")


@dataclass(frozen=True)
class GuideBarSynthesisDoc:
    """The guide-bar mechanism's dimensions in results.json."""

    extreme_angle: float = q("rad", "θ = π(K − 1)/(K + 1)")
    swing_angle: float = q("rad", "guide-bar swing ψ (= θ)")
    crank: float = q("m", "L_O2A")
    frame: float = q("m", "L_O2O3")
    guide_bar: float = q("m", "L_O3B")
    rod: float = q("m", "the rod from B to the ram (L_BF, L_BC)")
    guide_height: float = q("m", "L_O3M, the ram guide line's distance from O3")
    bar_com: float = q("m", "L_O3S4")
    guide_height_above_O2: float = q("m", "L_O2M = L_O3M − L_O2O3, the guide line's distance from O2")


def synthesis_doc(syn: Synthesis) -> GuideBarSynthesisDoc:
    d = syn.design
    return GuideBarSynthesisDoc(syn.extreme_angle, d.swing_angle, d.crank, d.frame, d.guide_bar,
                                d.rod, d.guide_height, d.bar_com, syn.guide_height_above_O2)


def motion(model, syn: Synthesis, rod_ratio: float, field: str, requests=None):
    """The engine's motion stage; an assembly failure names the brief's rod-ratio field: the
    rod must bridge half the sagitta of B's arc, L_rod ≥ L_O3B(1 − cos(ψ/2))/2."""
    from ..core.mechanism import AssemblyError
    from .linkage import motion as engine_motion

    try:
        return engine_motion(model, requests)
    except AssemblyError as exc:
        need = (1.0 - np.cos(syn.design.swing_angle / 2.0)) / 2.0
        raise exc.with_hint(
            f"(Brief field: {field} = {rod_ratio:g} must be at least (1 − cos(ψ/2))/2 = {need:.6g}.)",
            f"（任务书字段：{field} = {rod_ratio:g}，须不小于 (1 − cos(ψ/2))/2 = {need:.6g}。）"
        ) from None


def optional_stages(p) -> list[Stage]:
    """The gear pair, the drive and the cam, when the brief has those sections."""
    out = []
    if p.gear is not None:
        from .gear import gear_stage

        out.append(gear_stage())
    if p.drive is not None:
        out.append(drive_stage())
    if p.cam is not None:
        from .cam import cam_stage

        out.append(cam_stage())
    return out


def synthesize(p) -> Synthesis:
    """``p``: stroke, time_ratio_K, frame, rod_ratio, com_ratio (SI)."""
    d = guide_bar_quick_return(p.stroke, p.time_ratio_K, p.frame, p.rod_ratio, p.com_ratio)
    return Synthesis(d, d.swing_angle, d.guide_height - d.frame)


def _drive(r: dict):
    """The drive delivers the crank's mean power at the crank speed. The flywheel evens out
    the torque upstream of its shaft only: the stages after it carry the peak of M_b.
    (Any guide-bar machine whose gear pair z1/z2 is the drive's last stage.)"""
    from dataclasses import replace

    from .drive import design_drive

    p, f, fl = r["params"], r["linkage_forces"], r["linkage_flywheel"]
    n = r["linkage"].grid_size
    mb = f.balancing_torque[:n]
    mean = float(f.mean_torque)           # exact: the resistances' work per cycle / 2π
    peak = float(np.max(np.abs(mb)) / mean) if mean > 0 else float("inf")  # inf: no load
    shafts = len(p.drive.stages)          # the crank shaft's index
    flywheel_shaft = shafts - 1 if p.flywheel_shaft == "pinion" else shafts
    result = design_drive(p.drive, fl.mean_power, p.crank_speed_rpm, "mechanism",
                          peak, flywheel_shaft if flywheel_shaft < shafts else None)
    # The last stage is gear_pair, whose undercut the gear stage reports with its own fields.
    last = f"drive.stages[{shafts - 1}]"
    return replace(result, warnings=tuple(w for w in result.warnings
                                          if not (w.code == "undercut" and w.field == last)))


def drive_stage() -> Stage:
    return Stage("drive", "传动装置设计 / drive", _drive)
