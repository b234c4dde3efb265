"""Drive section of a report (传动装置设计): power, efficiency chain, motor choice, ratio
allocation, the shaft table, each stage's geometry and strength checks."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from .fmt import f

MM = 1e3


def _stage_label(st, zh: bool) -> str:
    name = st.name_zh if zh else st.name_en
    if st.z1 is not None:
        teeth = f"z₁ = {st.z1}, z₂ = {st.z2}" if st.type != "worm" else f"z₁ = {st.z1}, z₂ = {st.z2}"
        return f"{name} ({teeth})"
    if st.d1 is not None:
        return f"{name} (d₁ = {f(st.d1 * MM, 0)}, d₂ = {f(st.d2 * MM, 0)} mm)"
    return name


def _shaft_name(i: int, last: int, zh: bool) -> str:
    roman = "0 Ⅰ Ⅱ Ⅲ Ⅳ Ⅴ Ⅵ Ⅶ Ⅷ Ⅸ".split()
    if i == 0:
        return "电动机轴 0" if zh else "motor shaft 0"
    tail = ("（工作机输入轴）" if zh else " (machine input)") if i == last else ""
    return (f"{roman[i]} 轴" if zh else f"shaft {roman[i]}") + tail


def drive_context(d, lang: str, figures: dict[str, str], machine_power_eq: str | None = None) -> dict:
    zh = lang == "zh"
    m = d.motor
    etas = [st.efficiency for st in d.stages]
    n_b = len(d.stages)
    eta_terms = " \\times ".join(f(e, 3) for e in etas)
    eq = {
        "eta": (rf"\eta = \prod \eta_i \cdot \eta_b^{{{n_b}}} \cdot \eta_w = {eta_terms} \times "
                rf"{f(d.bearing_eff, 3)}^{{{n_b}}} \times {f(d.machine_eff, 3)} = {f(d.efficiency, 4)}"),
        "pd": (rf"P_d = \frac{{P_w}}{{\eta}} = \frac{{{f(d.machine_power / 1e3, 4)}}}{{{f(d.efficiency, 4)}}}"
               rf" = {f(d.power_required / 1e3, 4)}\ \text{{kW}}"),
        "i": (rf"i = \frac{{n_m}}{{n_w}} = \frac{{{f(m.full_load_rpm, 0)}}}{{{f(d.output_speed_required, 3)}}}"
              rf" = {f(d.choice.total_ratio, 3)}"),
        "err": (rf"\Delta n = \frac{{n_w' - n_w}}{{n_w}} = \frac{{{f(d.output_speed, 3)} - "
                rf"{f(d.output_speed_required, 3)}}}{{{f(d.output_speed_required, 3)}}} = "
                rf"{f(d.speed_error * 100, 2)}\%"),
        "pw": machine_power_eq,
    }
    yes, no = ("是", "否") if zh else ("yes", "no")
    cand_rows = []
    for c in d.choice.candidates:
        if c.motor is None:
            cand_rows.append([f(c.synchronous_rpm, 0), "—", "—", "—", "—", no])
            continue
        cand_rows.append([f(c.synchronous_rpm, 0), c.motor.designation, f(c.motor.power / 1e3, 2),
                          f(c.motor.full_load_rpm, 0), f(c.total_ratio, 2),
                          yes if c.recommended else no])
    stage_rows = []
    for st in d.stages:
        stage_rows.append([str(st.index + 1), _stage_label(st, zh), f(st.ratio_allocated, 3),
                           f(st.ratio, 3), f(st.efficiency, 3)])
    shaft_rows = [[_shaft_name(s.index, len(d.shafts) - 1, zh), f(s.speed_rpm, 2), f(s.power / 1e3, 4),
                   f(s.torque, 3)] for s in d.shafts]
    reason = {
        "recommended": ("按同步转速 1500、1000、3000、750 rpm 的顺序，取总传动比落在各级推荐传动比范围之内的第一种",
                        "the first synchronous speed (in the order 1500, 1000, 3000, 750 rpm) whose total "
                        "ratio lies within the stages' recommended ranges"),
        "maximum": ("没有一种同步转速能使总传动比落在推荐范围内，取落在最大传动比范围内的第一种",
                    "no synchronous speed fits the recommended ranges; the first that fits the maximum ranges"),
        "given": ("同步转速由设计任务给定", "the synchronous speed the brief gives"),
    }[d.choice.reason][0 if zh else 1]
    return {
        "eq": eq, "cand_rows": cand_rows, "stage_rows": stage_rows, "shaft_rows": shaft_rows,
        "reason": reason,
        "motor": {"name": m.designation, "P": f(m.power / 1e3, 2), "sync": f(m.synchronous_rpm, 0),
                  "n": f(m.full_load_rpm, 0), "H": f(m.frame_height * MM, 0),
                  "tst": f(m.starting_torque_ratio, 1), "tmax": f(m.max_torque_ratio, 1)},
        "pw": f(d.machine_power / 1e3, 4), "pd": f(d.power_required / 1e3, 4),
        "eta": f(d.efficiency, 4), "i": f(d.choice.total_ratio, 3),
        "nw": f(d.output_speed_required, 3), "nw_real": f(d.output_speed, 3),
        "err": f(d.speed_error * 100, 2), "tol": f(d.speed_tolerance * 100, 1),
        "speed_ok": abs(d.speed_error) <= d.speed_tolerance,
        "hours": f(d.service_hours, 0), "KA": f(d.KA, 2),
        "peak": f(d.peak_factor, 3) if d.peak_from_shaft is not None else None,
        "peak_shaft": _shaft_name(d.peak_from_shaft, len(d.shafts) - 1, zh) if d.peak_from_shaft is not None else "",
        "warnings": [w.text(lang) for w in d.warnings],
        "stage_designs": stage_designs(d, lang),
        "fig": figures,
    }


def stage_designs(d, lang: str) -> list[dict]:
    """Per stage: title, text, dimension rows, formulas and check rows (strength part)."""
    return []


# --------------------------------------------------------------------------- machine: drive


def _load_equation(p) -> str:
    ld = p.load
    if ld.how == "stroke":
        return (rf"P_w = \frac{{(F_w + F_r) H n_w}}{{60}} = \frac{{({f(ld.working_force, 0)} + "
                rf"{f(ld.return_force, 0)}) \times {f(ld.stroke, 3)} \times {f(ld.output_speed_rpm, 2)}}}{{60}}"
                rf" = {f(ld.power, 2)}\ \text{{W}}")
    if ld.how == "torque":
        return (rf"P_w = T_w \frac{{\pi n_w}}{{30}} = {f(ld.power * 30 / (np.pi * ld.output_speed_rpm), 3)}"
                rf" \times \frac{{\pi \times {f(ld.output_speed_rpm, 2)}}}{{30}} = {f(ld.power, 2)}\ \text{{W}}")
    return rf"P_w = {f(ld.power / 1e3, 4)}\ \text{{kW}}"


def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    return {}


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    p = r["params"]
    return {"meta": brief.report,
            "drive": drive_context(r["drive"], lang, figures, _load_equation(p)),
            "load_how": p.load.how}
