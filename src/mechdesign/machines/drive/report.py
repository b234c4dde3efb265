"""Report of the `drive` machine: the shared drive section (:mod:`mechdesign.render.drive_report`) and its self-checks."""
from __future__ import annotations

from pathlib import Path
import numpy as np
from ...i18n import N_, tr
from ...stages.findings import check_name
from ...render.fmt import e, f, grouped, md_meta, md_text, sig
from ...render.fmt import verdict
from ...render.drive_report import _shaft_name, _stage_name, drive_context


def _torque(ld) -> float:
    """[N·m] The mean torque at the machine's input: T = P·30/(π n)."""
    return ld.power * 30 / (np.pi * ld.output_speed_rpm)


def _load_equation(p) -> str:
    ld = p.load
    if ld.how == "stroke":
        return (rf"P_w = \frac{{(F_w + F_r) H n_w}}{{60}} = \frac{{({f(ld.working_force, 0)} + "
                rf"{f(ld.return_force, 0)}) \times {f(ld.stroke, 3)} \times {f(ld.output_speed_rpm, 2)}}}{{60}}"
                rf" = {f(ld.power, 2)}\ \text{{W}}")
    if ld.how == "torque":
        return (rf"P_w = T_w \frac{{\pi n_w}}{{30}} = {sig(_torque(ld), group=False)}"
                rf" \times \frac{{\pi \times {f(ld.output_speed_rpm, 2)}}}{{30}} = {f(ld.power, 2)}\ \text{{W}}")
    return rf"P_w = {sig(ld.power / 1e3, group=False)}\ \text{{kW}}"


def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    return {}


def data_rows(p, d, lang: str) -> list[list[str]]:
    """The task's data as the brief gives them (symbol, quantity, value, unit): the machine's
    load and speed, the service life, the application factor and the speed tolerance (page
    review 47: the drive report began with P_w = (F_w + F_r) H n_w/60 and defined none of
    them)."""
    _ = tr(lang)
    ld = p.load
    rows = []
    if ld.how == "stroke":
        rows += [["$F_w$", _("resistance on the working stroke"), f(ld.working_force, 0), "N"],
                 ["$F_r$", _("resistance on the return stroke"), f(ld.return_force, 0), "N"],
                 ["$H$", _("stroke"), f(ld.stroke * 1e3, 0), "mm"]]
    elif ld.how == "torque":
        rows.append(["$T_w$", _("mean torque at the machine's input shaft"),
                     sig(_torque(ld)), "N·m"])
    else:
        rows.append(["$P_w$", _("mean power at the machine's input shaft"), sig(ld.power / 1e3), "kW"])
    rows += [["$n_w$", _("speed of the machine's input shaft"), f(ld.output_speed_rpm, 2), "r/min"],
             ["$L_h$", _("service life"), grouped(f(d.service_hours, 0)), "h"],
             ["$K_A$", _("application factor"), f(d.KA, 2), "—"],
             ["$\\Delta n/n$", _("allowed speed error"), f(d.speed_tolerance * 100, 1), "%"]]
    return rows


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    p = r["params"]
    d = r["drive"]
    return {"meta": md_meta(brief.report, lang),
            "drive": drive_context(d, lang, figures, _load_equation(p)),
            "load_how": p.load.how,
            "data_rows": data_rows(p, d, lang),
            "stages": " → ".join(md_text(_stage_name(s.kind, lang)) for s in d.stages),
            **verification_context(d, r.get("drive_verification"), lang)}


_NOTE = N_("Each item is recomputed by its definition: every shaft's speed, power "
           "and torque from the shaft before it (no bearing loss between the motor and the first "
           "shaft, one pair of rolling bearings on every shaft after it) against the designed "
           "shaft table; the power balance checks that the power reaching the machine is exactly "
           "what it needs; a strength margin is 1 − value/allowable (for lives and diameters 1 − "
           "required/value), the smallest over all checks of a stage or shaft; the statics of "
           "each shaft take every load (an axial force as the couple $F_a r$ in the vertical "
           "plane) and both reactions, in both planes, with moments about bearing $B$.")


def verification_context(d, v, lang: str) -> dict:
    """``verify_rows``, ``findings`` and ``verify_note`` of the verification section."""
    if v is None:
        return {"verify_rows": [], "findings": [], "verify_note": ""}
    from ...stages.drive import DRIVE_CHECK_NAMES

    _ = tr(lang)
    last = len(d.shafts) - 1
    rows = []
    for k in v.checks:
        name = DRIVE_CHECK_NAMES[k.key][0 if _.zh else 1]
        ok = verdict(k.passed, lang)
        if k.key == "speed_error":
            rows.append([name, f"{f(k.detail['signed'] * 100, 3)}%", f"≤ ±{f(k.limit * 100, 1)}%", ok])
        elif k.key == "motor_power":
            rows.append([name, _("{value}% ({detail} / {detail2} kW)", value=f(k.value * 100, 1),
                                 # the power needed to 4 significant digits (the
                                 # rule of powers: 0.06296 kW, as in the shaft table)
                                 detail=sig(k.detail['required'] / 1e3, 4),
                                 detail2=f(k.detail['rated'] / 1e3, 2)),
                         "≥ 0", ok])
        elif k.key == "margin":
            if "shaft" in k.detail:
                where = _shaft_name(k.detail["shaft"], last, _.zh)
            else:
                st = d.stages[k.detail["stage"]]
                where = _("stage {index} ({name_en})", index=st.index + 1, name_en=st.name("en"),
                          name_zh=st.name("zh"))
            check = check_name(k.detail["check"], k.detail["check_args"]).text(_)   # its governing check
            item = _("{where}: {name} ({detail} checks)", where=where, name=name,
                      detail=k.detail['checks'])
            rows.append([item, _("{value}% ({check})", value=f(k.value * 100, 1), check=check),
                         "≥ 0", ok])
        elif k.key == "verdicts":
            rows.append([name, str(int(k.value)), "0", ok])
        elif k.key == "reactions":
            where = _shaft_name(k.detail["shaft"], last, _.zh)
            rows.append([_("{where}: {name}", where=where, name=name), e(k.value), f"≤ {e(k.limit)}", ok])
        else:
            rows.append([name, e(k.value), f"≤ {e(k.limit)}", ok])
    return {"verify_rows": rows, "findings": [md_text(w.text(lang)) for w in v.warnings],
            "verify_note": _(_NOTE)}
