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
    "shaper": "mechdesign.machines.shaper",
    "furnace_pusher": "mechdesign.machines.furnace_pusher",
    "lockbeam": "mechdesign.machines.lockbeam",
    "die_cutter": "mechdesign.machines.die_cutter",
    "crank_rocker": "mechdesign.machines.crank_rocker",
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
