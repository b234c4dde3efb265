"""The one place where machines are registered.

Each entry says where a machine's parts live, as "module:attribute" strings resolved on
first use (so `mechdesign check` imports only the brief model it needs, never the
engine): the brief model, the conversion to SI parameters, the stages, the results
document, the report module (figures, template context, optional animation and data
files), the example brief (the starter of `mechdesign new`), its template and the rows
of the batch index. A machine written as a package (``mechdesign.machines.slotter``)
exposes its own :class:`Entry` as ``ENTRY``; it is listed here by its package only.
"""
from __future__ import annotations

import importlib
import math
from dataclasses import dataclass
from typing import Any

_MM, _DEG = 1000.0, 180.0 / math.pi


@dataclass(frozen=True)
class Entry:
    name: str
    brief: str                  # "module:Class" of the pydantic brief model
    to_params: str              # "module:function" brief → SI parameters
    stages: str                 # "module:attr": a list of stages or a function of the parameters
    document: str               # "module:function" results → results.json document
    report: str                 # module with make_figures(r, dir, lang) and context(r, brief, figs, lang)
    example: str                # file name in designs/
    # (zh label, en label, unit, dotted path in the results document, factor SI → unit)
    summary: tuple = ()
    template: str = ""          # report template stem (default: the machine's name)
    results: str = ""           # "module:Class" of the typed results document
    checks: str = ""            # "module:function" feasibility checks(params, keep), run once

    @property
    def template_stem(self) -> str:
        return self.template or self.name


def resolve(ref: str) -> Any:
    module, _, attr = ref.partition(":")
    obj = importlib.import_module(module)
    return getattr(obj, attr) if attr else obj


_B, _M, _R = "mechdesign.brief.", "mechdesign.machines.", "mechdesign.render."

_ENTRIES: dict[str, Entry | str] = {
    "shaper": Entry(
        "shaper", _B + "shaper:ShaperBrief", _B + "shaper:to_si", _M + "shaper:stages",
        _M + "shaper:results_document", _R + "shaper_report", "shaper.yaml", results=_M + "shaper:ShaperResults", summary=(
            ("曲柄", "crank", "mm", "synthesis.crank", _MM),
            ("导杆", "guide bar", "mm", "synthesis.guide_bar", _MM),
            ("K（仿真）", "K (simulated)", "", "verification.time_ratio_simulated", 1.0),
            ("飞轮 J_F", "flywheel J_F", "kg·m²", "flywheel.inertia", 1.0),
            ("平均功率", "mean power", "W", "flywheel.mean_power", 1.0),
            ("电动机", "motor", "", "drive.motor.designation", 1.0))),
    "furnace_pusher": Entry(
        "furnace_pusher", _B + "furnace:FurnaceBrief", _B + "furnace:furnace_to_si",
        _M + "furnace:stages", _M + "furnace:results_document", _R + "furnace_report",
        "furnace_pusher.yaml", results=_M + "furnace:FurnaceResults", summary=(
            ("曲柄", "crank", "mm", "synthesis.crank", _MM),
            ("连杆", "coupler", "mm", "synthesis.coupler", _MM),
            ("行程 H", "stroke H", "mm", "linkage.output.stroke", _MM),
            ("K", "K", "", "linkage.time_ratio", 1.0),
            ("γ_min", "γ_min", "°", "synthesis.gamma_min", _DEG),
            ("平均功率", "mean power", "W", "linkage.mean_power", 1.0),
            ("电动机", "motor", "", "drive.motor.designation", 1.0)),
        checks=_M + "furnace:checks"),
    "lockbeam": Entry(
        "lockbeam", _B + "lockbeam:LockbeamBrief", _B + "lockbeam:lockbeam_to_si",
        _M + "lockbeam:stages", _M + "lockbeam:results_document", _R + "lockbeam_report",
        "lockbeam.yaml", results=_M + "lockbeam:LockbeamResults", summary=(
            ("总传动比", "total ratio", "", "transmission.ratio", 1.0),
            ("送料行程", "feed stroke", "mm", "feed.output.stroke", _MM),
            ("送料 K", "feed K", "", "feed.time_ratio", 1.0),
            ("扳弯角（仿真）", "bend (simulated)", "°", "bending.bend_simulated", _DEG),
            ("扳弯 γ_min", "bending γ_min", "°", "bending.gamma_min", _DEG)),
        checks=_M + "lockbeam:checks"),
    "die_cutter": Entry(
        "die_cutter", _B + "die_cutter:DieCutterBrief", _B + "die_cutter:die_cutter_to_si",
        _M + "die_cutter:stages", _M + "die_cutter:results_document", _R + "die_cutter_report",
        "die_cutter.yaml", results=_M + "die_cutter:DieCutterResults", summary=(
            ("曲柄", "crank", "mm", "toggle.crank", _MM),
            ("行程", "stroke", "mm", "press.output.stroke", _MM),
            ("K", "K", "", "press.time_ratio", 1.0),
            ("峰值扭矩", "peak torque", "N·m", "press.peak_torque", 1.0),
            ("飞轮 J_F", "flywheel J_F", "kg·m²", "flywheel.inertia", 1.0),
            ("电动机", "motor", "", "drive.motor.designation", 1.0)),
        checks=_M + "die_cutter:checks"),
    "crank_rocker": Entry(
        "crank_rocker", _B + "crank_rocker:CrankRockerBrief",
        _B + "crank_rocker:crank_rocker_to_si", _M + "crank_rocker:stages",
        _M + "crank_rocker:results_document", _R + "crank_rocker_report", "crank_rocker.yaml",
        results=_M + "crank_rocker:CrankRockerResults", summary=(
            ("曲柄", "crank", "mm", "optimum.crank", _MM),
            ("连杆", "coupler", "mm", "optimum.coupler", _MM),
            ("机架", "frame", "mm", "optimum.frame", _MM),
            ("γ_min", "γ_min", "°", "optimum.gamma_min", _DEG))),
    "linkage": Entry(
        "linkage", _B + "linkage:LinkageBrief", _M + "linkage:linkage_params",
        _M + "linkage:STAGES", _M + "linkage:results_document", _R + "linkage_report",
        "linkage_sixbar.yaml", results=_M + "linkage:LinkageResults", summary=(
            ("行程", "stroke", "mm", "linkage.output.stroke", _MM),
            ("K", "K", "", "linkage.time_ratio", 1.0),
            ("平均扭矩", "mean torque", "N·m", "linkage.mean_torque", 1.0),
            ("峰值扭矩", "peak torque", "N·m", "linkage.peak_torque", 1.0),
            ("飞轮 J_F", "flywheel J_F", "kg·m²", "linkage.flywheel.inertia", 1.0))),
    "cam": Entry(
        "cam", _B + "cam:CamBrief", _B + "cam:cam_brief_to_si", "mechdesign.stages.cam:CAM_STAGES",
        "mechdesign.stages.cam:cam_results_document", _R + "cam_report", "cam_7_3.yaml",
        results="mechdesign.stages.cam:CamResults", summary=(
            ("基圆半径 r0", "base radius r0", "mm", "cam.base_radius", _MM),
            ("最小基圆", "least base radius", "mm", "cam.min_base_radius", _MM),
            ("滚子半径", "roller radius", "mm", "cam.roller_radius", _MM),
            ("实际廓线最小曲率半径", "least profile radius of curvature", "mm",
             "cam.rho_actual_min_convex", _MM))),
    "eccentric_cam": Entry(
        "eccentric_cam", _B + "cam:EccentricCamBrief", _B + "cam:eccentric_to_si",
        "mechdesign.stages.cam:DISC_STAGES", "mechdesign.stages.cam:disc_results_document", _R + "disc_report",
        "cam_7_1.yaml", results="mechdesign.stages.cam:EccentricCamResults", summary=(
            ("圆盘半径", "disc radius", "mm", "radius", _MM),
            ("偏心距", "eccentricity", "mm", "eccentricity", _MM))),
    "drive": Entry(
        "drive", _B + "drive:DriveBrief", _B + "drive:drive_brief_to_si", "mechdesign.stages.drive:DRIVE_STAGES",
        "mechdesign.stages.drive:drive_results_document", _R + "drive_report", "furnace_drive.yaml",
        results="mechdesign.stages.drive:DriveResults", summary=(
            ("总传动比", "total ratio", "", "drive.total_ratio", 1.0),
            ("所需功率", "power required", "W", "drive.power_required", 1.0),
            ("电动机", "motor", "", "drive.motor.designation", 1.0),
            ("输出转速", "output speed", "rpm", "drive.output_speed_rpm", 1.0))),
    # Machines written as one package each:
    "slotter": "mechdesign.machines.slotter",
}


def names() -> list[str]:
    return list(_ENTRIES)


def entry(name: str) -> Entry:
    """The machine's entry (KeyError for an unknown machine)."""
    e = _ENTRIES[name]
    if isinstance(e, str):
        e = importlib.import_module(e).ENTRY
        _ENTRIES[name] = e
    return e
