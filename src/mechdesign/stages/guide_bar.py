"""Stages shared by the guide-bar (quick-return) machines — the shaper and the slotter:
the synthesis from H, K, the frame and the link ratios, and the drive whose last stage is
the gear pair z1/z2 turning the crank."""
from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from ..core.fields import q
from ..core.synthesis import GuideBarDesign, guide_bar_quick_return
from ..i18n import N_
from ..pipeline import Stage
from . import titles
from .findings import Msg


@dataclass(frozen=True)
class Synthesis:
    """Stage 导杆机构设计: the link lengths [m] and angles [rad]."""

    design: GuideBarDesign = q("")
    extreme_angle: float = q("rad", "θ")
    guide_height_above_O2: float = q("m", "L_O2M = L_O3M − L_O2O3")
    stroke: float = q("m", "H, given or derived from the lengths", default=float("nan"))
    time_ratio: float = q("1", "K, given or derived from the lengths", default=float("nan"))
    given_dimensions: bool = q("", "True: the brief gave the link lengths, H and K derived", default=False)
    guide_given: bool = q("", "True: the brief gave L_O3M", default=False)


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
    stroke: float = q("m", "ram stroke H (given, or 2·L_O3B·sin(ψ/2) from the link lengths)")
    time_ratio: float = q("1", "time ratio K (given, or (180° + θ)/(180° − θ) from the link lengths)")
    given_dimensions: bool = q("", "true: the brief gave the link lengths (H, K derived); false: synthesis from H, K")


def synthesis_doc(syn: Synthesis) -> GuideBarSynthesisDoc:
    d = syn.design
    return GuideBarSynthesisDoc(syn.extreme_angle, d.swing_angle, d.crank, d.frame, d.guide_bar,
                                d.rod, d.guide_height, d.bar_com, syn.guide_height_above_O2,
                                syn.stroke, syn.time_ratio, syn.given_dimensions)


def motion(model, syn: Synthesis, p, rod: str, requests=None):
    """The engine's motion stage; an assembly failure names the brief's rod field
    (``rod``: the rod's letters, BF or BC): the rod must bridge half the sagitta of B's arc,
    L_rod ≥ L_O3B(1 − cos(ψ/2))/2. ``requests``: the brief's analysis requests."""
    from ..core.mechanism import AssemblyError
    from .linkage import motion as engine_motion

    try:
        return engine_motion(model, requests)
    except AssemblyError as exc:
        need = (1.0 - np.cos(syn.design.swing_angle / 2.0)) / 2.0
        if p.rod is not None:
            field, value, need = f"linkage.rod_{rod}_mm", p.rod * 1e3, need * syn.design.guide_bar * 1e3
        else:
            field, value = f"linkage.rod_ratio_{rod}_O3B", p.rod_ratio
        rule = "(1 − cos(ψ/2))/2" if p.rod is None else "L_O3B(1 − cos(ψ/2))/2"
        raise exc.with_hint(Msg(
            N_("(Brief field: {field} = {value:g} must be at least {rule} = {need:.6g}.)"),
            field=field, value=value, rule=rule, need=need)) from None


def optional_stages(p, flywheel_weight: bool = False, feed_cam: bool = False) -> list[Stage]:
    """The gear pair, the drive and the cam, when the brief has those sections
    (``flywheel_weight``: the drive's shafts carry the flywheel rim's weight; ``feed_cam``:
    the cam feeds the work, which must happen in the return stroke: its phase is checked)."""
    out = []
    if p.gear is not None:
        from .gear import gear_stage

        out.append(gear_stage())
    if p.drive is not None:
        out.append(drive_stage(flywheel_weight))
    if p.cam is not None:
        from .cam import cam_stage

        out.append(cam_stage())
        if feed_cam:
            out.append(Stage("cam_phase", titles.pgettext("stage", "cam phase"),
                             lambda r: cam_phase(r["cam"], r["linkage"])))
    return out


@dataclass(frozen=True)
class CamPhase:
    """The feed cam on the crank shaft keyed so that its motion starts with the return stroke
    (φ from position 1, the start of the working stroke, in the crank's sense; the cam turns
    with the crank: δ = φ − φ_0); the check that its motion ends before the next working
    stroke (the shaper's "进给须在刨头空回行程中完成"; page review 48)."""

    crank_angle: float = q("rad", "crank angle φ_0 at the cam's δ = 0: where the return stroke begins")
    motion: float = q("rad", "the follower's motion: δ from the rise's start to the return's end")
    return_span: float = q("rad", "the return stroke's crank angle")
    passed: bool = q("", "the motion lies within the return stroke")


def cam_phase(cam, k) -> CamPhase:
    start = float(k.working_span)
    ret = 2 * np.pi - start
    motion = max((sg.start + sg.span for sg in cam.segments if sg.kind != "dwell"), default=0.0)
    return CamPhase(start, float(motion), float(ret), bool(motion <= ret + 1e-12))


def synthesize(p) -> Synthesis:
    """``p``: stroke, time_ratio_K, frame, rod_ratio, com_ratio (SI) — the synthesis from H
    and K; or, when ``p.crank`` and ``p.guide_bar`` are given (the course table's lengths),
    those lengths kept exactly with ψ = θ = 2·arcsin(L_O2A/L_O2O3). A given rod length or
    guide distance L_O3M replaces the ratio or the mid-sagitta rule."""
    from dataclasses import replace

    if p.crank is not None:
        psi = 2.0 * np.arcsin(p.crank / p.frame)
        bar = p.guide_bar
        d = GuideBarDesign(swing_angle=psi, crank=p.crank, frame=p.frame, guide_bar=bar,
                           rod=p.rod_ratio * bar, guide_height=bar * (1.0 + np.cos(psi / 2.0)) / 2.0,
                           bar_com=p.com_ratio * bar)
    else:
        d = guide_bar_quick_return(p.stroke, p.time_ratio_K, p.frame, p.rod_ratio, p.com_ratio)
    if p.rod is not None:
        d = replace(d, rod=p.rod)
    if p.guide_height is not None:
        d = replace(d, guide_height=p.guide_height)
    return Synthesis(d, d.swing_angle, d.guide_height - d.frame, p.stroke, p.time_ratio_K,
                     p.crank is not None, p.guide_height is not None)


def _drive(r: dict, flywheel_weight: bool = False):
    """The drive delivers the crank's mean power at the crank speed. The flywheel evens out
    the torque upstream of its shaft only: the stages after it carry the peak of M_b.
    ``flywheel_weight``: the flywheel's cast rim (its weight m·g, its width b) is a load
    between the bearings of its shaft. (Any guide-bar machine whose gear pair z1/z2 is the
    drive's last stage.)"""
    from dataclasses import replace

    from .drive import design_drive

    p, f, fl = r["params"], r["linkage_forces"], r["linkage_flywheel"]
    n = r["linkage"].grid_size
    mb = f.balancing_torque[:n]
    mean = float(f.mean_torque)           # exact: the resistances' work per cycle / 2π
    peak = float(np.max(np.abs(mb)) / mean) if mean > 0 else float("inf")  # inf: no load
    shafts = len(p.drive.stages)          # the crank shaft's index
    flywheel_shaft = shafts - 1 if p.flywheel_shaft == "pinion" else shafts
    # the bearing life's equivalent load: the cycle's cube-mean torque (see design_drive)
    life = float(np.mean(np.abs(mb) ** 3) ** (1 / 3) / mean) if mean > 0 else None
    spec = getattr(r.get("model"), "flywheel", None)

    # J_F grows as 1/n²: where the drive turns the flywheel's shaft slower than nominal, the
    # flywheel is sized at that speed, and the drive's shafts carry the resized rim (the
    # motor, the ratios and the speeds do not depend on the rim's weight: one design)
    @functools.cache
    def flywheel_at(n_real: float):
        if spec is not None and n_real < fl.shaft_speed_rpm - 5e-3:
            from .flywheel import at_realised_speed

            return at_realised_speed(fl, spec, n_real, p.gravity)
        return fl

    def weights(table):
        if not flywheel_weight or flywheel_shaft < 1:
            return None
        rim = flywheel_at(table[flywheel_shaft].speed_rpm).rim
        return {flywheel_shaft: (rim.rim_mass * p.gravity, rim.width)} if rim is not None else None

    # the crank on the drive's last shaft (the gear z2's): its frame reaction loads that shaft
    # (review39b Top 1: the shaper's F_R72 up to 3649 N was left off shaft Ⅱ)
    crank = None
    if mean > 0:
        from .crank_load import crank_load

        crank = {shafts: crank_load(r["model"], r["linkage"], f)}
    result = design_drive(p.drive, fl.mean_power, p.crank_speed_rpm, "mechanism",
                          peak, flywheel_shaft if flywheel_shaft < shafts else None, life, weights,
                          crank=crank)
    flywheel = flywheel_at(result.shafts[flywheel_shaft].speed_rpm)
    # The last stage is gear_pair, whose undercut the gear stage reports with its own fields.
    last = f"drive.stages[{shafts - 1}]"
    return replace(result, warnings=tuple(w for w in result.warnings
                                          if not (w.code == "undercut" and w.field == last))), flywheel


def drive_stage(flywheel_weight: bool = False) -> Stage:
    """The drive; it also gives the flywheel again, sized at the realised speed when that is
    the slower (see :func:`_drive`)."""
    return Stage(("drive", "linkage_flywheel"), titles.pgettext("stage", "drive"),
                 lambda r: _drive(r, flywheel_weight))
