"""Report of the `drive` machine: the shared drive section (:mod:`mechdesign.render.drive_report`) and its self-checks."""
from __future__ import annotations

from pathlib import Path
import numpy as np
from ...render.fmt import e, f, md_meta, md_text
from ...render.fmt import verdict
from ...render.drive_report import _shaft_name, drive_context


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
    return {"meta": md_meta(brief.report, lang),
            "drive": drive_context(r["drive"], lang, figures, _load_equation(p)),
            "load_how": p.load.how,
            **verification_context(r["drive"], r.get("drive_verification"), lang)}


_NOTE = {
    "zh": "各项由本次运行按定义重算：各轴转速、功率、转矩逐级由上一轴推出（电动机轴到第一根轴不计轴承损失，"
          "其后每根轴一对滚动轴承），与设计所得的轴表比较；功率平衡检查传到工作机的功率是否正好等于其所需功率；"
          "强度裕度 = 1 − 计算值/许用值（寿命、直径为 1 − 要求值/计算值），各轴取所有校核项目中最小者；"
          "支反力平衡对两个平面分别计入全部外载荷（轴向力以 $F_a r$ 的力偶计入垂直面）与支反力，对轴承 B 取矩。",
    "en": "Each item is recomputed in this run by its definition: every shaft's speed, power and torque from the shaft "
          "before it (no bearing loss between the motor and the first shaft, one pair of rolling bearings on every "
          "shaft after it) against the designed shaft table; the power balance checks that the power reaching the "
          "machine is exactly what it needs; a strength margin is 1 − value/allowable (for lives and diameters "
          "1 − required/value), the smallest over all checks of a stage or shaft; the statics of each shaft take every "
          "load (an axial force as the couple $F_a r$ in the vertical plane) and both reactions, in both planes, with "
          "moments about bearing B.",
}


def verification_context(d, v, lang: str) -> dict:
    """``verify_rows``, ``findings`` and ``verify_note`` of the verification section."""
    if v is None:
        return {"verify_rows": [], "findings": [], "verify_note": ""}
    from ...stages.drive import DRIVE_CHECK_NAMES

    zh = lang == "zh"
    last = len(d.shafts) - 1
    rows = []
    for k in v.checks:
        name = DRIVE_CHECK_NAMES[k.key][0 if zh else 1]
        ok = verdict(k.passed, lang)
        if k.key == "speed_error":
            rows.append([name, f"{f(k.detail['signed'] * 100, 3)}%", f"≤ ±{f(k.limit * 100, 1)}%", ok])
        elif k.key == "motor_power":
            rows.append([name, f"{f(k.value * 100, 1)}%（{f(k.detail['required'] / 1e3, 4)} / {f(k.detail['rated'] / 1e3, 2)} kW）"
                         if zh else f"{f(k.value * 100, 1)}% ({f(k.detail['required'] / 1e3, 4)} / {f(k.detail['rated'] / 1e3, 2)} kW)",
                         "≥ 0", ok])
        elif k.key == "margin":
            if "shaft" in k.detail:
                where = _shaft_name(k.detail["shaft"], last, zh)
            else:
                st = d.stages[k.detail["stage"]]
                where = f"第 {st.index + 1} 级{st.name_zh}" if zh else f"stage {st.index + 1} ({st.name_en})"
            check = k.detail["check_zh"] if zh else k.detail["check_en"]
            item = (f"{where}：{name}（{k.detail['checks']} 项）" if zh else
                    f"{where}: {name} ({k.detail['checks']} checks)")
            rows.append([item, f"{f(k.value * 100, 1)}%（{check}）" if zh else f"{f(k.value * 100, 1)}% ({check})",
                         "≥ 0", ok])
        elif k.key == "verdicts":
            rows.append([name, str(int(k.value)), "0", ok])
        elif k.key == "reactions":
            where = _shaft_name(k.detail["shaft"], last, zh)
            rows.append([f"{where}：{name}" if zh else f"{where}: {name}", e(k.value), f"≤ {e(k.limit)}", ok])
        else:
            rows.append([name, e(k.value), f"≤ {e(k.limit)}", ok])
    return {"verify_rows": rows, "findings": [md_text(w.text(lang)) for w in v.warnings],
            "verify_note": _NOTE[lang]}
