"""Key results of a run, for the batch index: a few labelled numbers per machine.

Read from the machine's results document (what results.json holds, SI), converted to
the course's units here, at the boundary.
"""
from __future__ import annotations

import math
from typing import Any

# (zh label, en label, unit, dotted path in the results document, factor SI → unit)
_MM, _DEG = 1000.0, 180.0 / math.pi
_ROWS: dict[str, list[tuple[str, str, str, str, float]]] = {
    "shaper": [("曲柄", "crank", "mm", "synthesis.crank", _MM),
               ("导杆", "guide bar", "mm", "synthesis.guide_bar", _MM),
               ("K（仿真）", "K (simulated)", "", "verification.time_ratio_simulated", 1.0),
               ("飞轮 J_F", "flywheel J_F", "kg·m²", "flywheel.inertia", 1.0),
               ("平均功率", "mean power", "W", "flywheel.mean_power", 1.0),
               ("电动机", "motor", "", "drive.motor.designation", 1.0)],
    "furnace_pusher": [("曲柄", "crank", "mm", "synthesis.crank", _MM),
                       ("连杆", "coupler", "mm", "synthesis.coupler", _MM),
                       ("行程 H", "stroke H", "mm", "linkage.output.stroke", _MM),
                       ("K", "K", "", "linkage.time_ratio", 1.0),
                       ("γ_min", "γ_min", "°", "synthesis.gamma_min", _DEG),
                       ("平均功率", "mean power", "W", "linkage.mean_power", 1.0),
                       ("电动机", "motor", "", "drive.motor.designation", 1.0)],
    "die_cutter": [("曲柄", "crank", "mm", "toggle.crank", _MM),
                   ("行程", "stroke", "mm", "press.output.stroke", _MM),
                   ("K", "K", "", "press.time_ratio", 1.0),
                   ("峰值扭矩", "peak torque", "N·m", "press.peak_torque", 1.0),
                   ("飞轮 J_F", "flywheel J_F", "kg·m²", "flywheel.inertia", 1.0),
                   ("电动机", "motor", "", "drive.motor.designation", 1.0)],
    "lockbeam": [("总传动比", "total ratio", "", "transmission.ratio", 1.0),
                 ("送料行程", "feed stroke", "mm", "feed.output.stroke", _MM),
                 ("送料 K", "feed K", "", "feed.time_ratio", 1.0),
                 ("扳弯角（仿真）", "bend (simulated)", "°", "bending.bend_simulated", _DEG),
                 ("扳弯 γ_min", "bending γ_min", "°", "bending.gamma_min", _DEG)],
    "crank_rocker": [("曲柄", "crank", "mm", "optimum.crank", _MM),
                     ("连杆", "coupler", "mm", "optimum.coupler", _MM),
                     ("机架", "frame", "mm", "optimum.frame", _MM),
                     ("γ_min", "γ_min", "°", "optimum.gamma_min", _DEG)],
    "linkage": [("行程", "stroke", "mm", "linkage.output.stroke", _MM),
                ("K", "K", "", "linkage.time_ratio", 1.0),
                ("平均扭矩", "mean torque", "N·m", "linkage.mean_torque", 1.0),
                ("峰值扭矩", "peak torque", "N·m", "linkage.peak_torque", 1.0),
                ("飞轮 J_F", "flywheel J_F", "kg·m²", "linkage.flywheel.inertia", 1.0)],
    "cam": [("基圆半径 r0", "base radius r0", "mm", "cam.base_radius", _MM),
            ("最小基圆", "least base radius", "mm", "cam.min_base_radius", _MM),
            ("滚子半径", "roller radius", "mm", "cam.roller_radius", _MM),
            ("实际廓线最小曲率半径", "least profile radius of curvature", "mm",
             "cam.rho_actual_min_convex", _MM)],
    "eccentric_cam": [("圆盘半径", "disc radius", "mm", "radius", _MM),
                      ("偏心距", "eccentricity", "mm", "eccentricity", _MM)],
    "drive": [("总传动比", "total ratio", "", "drive.total_ratio", 1.0),
              ("所需功率", "power required", "W", "drive.power_required", 1.0),
              ("电动机", "motor", "", "drive.motor.designation", 1.0),
              ("输出转速", "output speed", "rpm", "drive.output_speed_rpm", 1.0)],
}


def _get(document: Any, path: str) -> Any:
    node = document
    for part in path.split("."):
        if isinstance(node, dict):
            node = node.get(part)
        else:
            node = getattr(node, part, None)
        if node is None:
            return None
    return node


def _show(value: Any, factor: float) -> str | None:
    if isinstance(value, bool) or value is None:
        return None
    if isinstance(value, str):
        return value
    try:
        x = float(value) * factor
    except (TypeError, ValueError):
        return None
    if math.isfinite(x):
        return f"{x:.4g}" if abs(x) < 1e4 else f"{x:.0f}"
    return None


def summary_rows(machine: str, document: dict, lang: str) -> list[tuple[str, str]]:
    """(label with unit, value) pairs of the machine's key results present in ``document``."""
    rows = []
    for zh, en, unit, path, factor in _ROWS.get(machine, []):
        text = _show(_get(document, path), factor)
        if text is None:
            continue
        label = zh if lang == "zh" else en
        rows.append((f"{label} [{unit}]" if unit else label, text))
    return rows


def summarise(machine_name: str, results: dict, lang: str) -> list[tuple[str, str]]:
    """Key results of a finished run (its results document, in the course's units)."""
    from . import get_machine

    return summary_rows(machine_name, get_machine(machine_name).document(results), lang)
