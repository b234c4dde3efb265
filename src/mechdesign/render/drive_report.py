"""Drive section of a report (传动装置设计): power, efficiency chain, motor choice, ratio
allocation, the shaft table, each stage's geometry and strength checks."""
from __future__ import annotations


import numpy as np

from ..stages.drive import shaft_numeral
from .fmt import f, grouped, md_text

MM = 1e3


def _stage_label(st, zh: bool) -> str:
    name = st.name_zh if zh else st.name_en
    if st.z1 is not None:
        return f"{name} (z₁ = {st.z1}, z₂ = {st.z2})"
    if st.d1 is not None:
        return f"{name} (d₁ = {f(st.d1 * MM, 0)}, d₂ = {f(st.d2 * MM, 0)} mm)"
    return name


def _shaft_name(i: int, last: int, zh: bool) -> str:
    if i == 0:
        return "电动机轴 0" if zh else "motor shaft 0"
    tail = ("（工作机输入轴）" if zh else " (machine input)") if i == last else ""
    return (f"{shaft_numeral(i)} 轴" if zh else f"shaft {shaft_numeral(i)}") + tail


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
                   f(s.torque, 3, group=True)] for s in d.shafts]
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
        "warnings": [md_text(w.text(lang)) for w in d.warnings],
        "stage_designs": stage_designs(d, lang),
        "fig": figures,
    }


def _mat_name(key: str, zh: bool) -> str:
    from ..data import catalogues as cat

    for get in (cat.gear_material, cat.worm_wheel_material):
        try:
            m = get(key)
            return m.name_zh if zh else m.name_en
        except KeyError:
            continue
    return key


def _rows(rows: list[list[str]], zh: bool) -> list[list[str]]:
    """Keep the check name in the report's language only; value and allowable grouped by
    render/fmt.py's rule (a life of 72 441 h)."""
    return [[r[0] if zh else r[1], grouped(r[2]), grouped(r[3]), *r[4:]] for r in rows]


def stage_designs(d, lang: str) -> list[dict]:
    """Per stage and per shaft: title, text, dimension rows, formulas and check rows."""
    from .strength_tex import check_formulas, check_rows

    zh = lang == "zh"
    out = []
    for r in d.stages:
        g = r.design
        if g is None or g.kind not in ("gear", "worm", "belt", "chain"):
            continue
        title = (f"第 {r.index + 1} 级：{r.name_zh}" if zh else f"Stage {r.index + 1}: {r.name_en}")
        text, rows = [], []
        if g.kind == "belt":
            out.append(_belt_design(r, g, title, zh))
            continue
        if g.kind == "chain":
            out.append(_chain_design(g, title, zh))
            continue
        m_text = (f"{f(g.module * MM, 2)} mm" + ("" if g.module_given else
                  (f"（设计公式得 {f(g.module_min * MM, 3)} mm，取标准值）" if zh else
                   f" (the design formula gives {f(g.module_min * MM, 3)} mm; next standard value)")))
        a = g.allowables
        if g.kind == "gear":
            e = g.extra
            mats = " / ".join(_mat_name(k, zh) for k in g.materials)
            text.append((f"材料（小齿轮 / 大齿轮）：{mats}。载荷系数 $K = K_A K_V K_\\alpha K_\\beta = {f(g.K, 3)}$，"
                         f"设计转矩 $T_1 = {f(g.T1, 3)}$ N·m，齿宽系数 $\\phi_d = {f(e['phi_d'], 2)}$，模数 m = {m_text}。")
                        if zh else
                        (f"Materials (pinion / gear): {mats}. Load factor $K = K_A K_V K_\\alpha K_\\beta = {f(g.K, 3)}$, "
                         f"design torque $T_1 = {f(g.T1, 3)}$ N·m, face width factor $\\phi_d = {f(e['phi_d'], 2)}$, "
                         f"module m = {m_text}."))
            if e["open"]:
                text.append("开式齿轮以磨损为主要失效形式：按齿根弯曲疲劳强度设计，模数加大 15% 计入磨损，不校核接触强度。"
                            if zh else "Open gears fail by wear: designed by root bending with the module raised 15 % "
                            "for wear; no contact check.")
            text.append((f"应力循环次数 $N_1 = {f(a['N1'] / 1e6, 1)}\\times10^6$，寿命系数 $K_{{HN}} = {f(a['KHN1'], 3)}/{f(a['KHN2'], 3)}$，"
                         f"$K_{{FN}} = {f(a['KFN1'], 3)}/{f(a['KFN2'], 3)}$；许用应力 $[\\sigma_H] = {f(a['sigma_H'] / 1e6, 1)}$ MPa，"
                         f"$[\\sigma_F] = {f(a['sigma_F1'] / 1e6, 1)}/{f(a['sigma_F2'] / 1e6, 1)}$ MPa（$S_H = 1$，$S_F = 1.4$）。")
                        if zh else
                        (f"Stress cycles $N_1 = {f(a['N1'] / 1e6, 1)}\\times10^6$, life factors $K_{{HN}} = {f(a['KHN1'], 3)}/{f(a['KHN2'], 3)}$, "
                         f"$K_{{FN}} = {f(a['KFN1'], 3)}/{f(a['KFN2'], 3)}$; allowable $[\\sigma_H] = {f(a['sigma_H'] / 1e6, 1)}$ MPa, "
                         f"$[\\sigma_F] = {f(a['sigma_F1'] / 1e6, 1)}/{f(a['sigma_F2'] / 1e6, 1)}$ MPa ($S_H = 1$, $S_F = 1.4$)."))
            geo = g.geometry
            d1 = g.forces["d1"]
            rows = [["$z_1 / z_2$", f"{r.z1} / {r.z2}", "—"], ["$m$", f(g.module * MM, 2), "mm"],
                    ["$d_1 / d_2$", f"{f(d1 * MM, 2)} / {f(g.forces['d2'] * MM, 2)}", "mm"],
                    ["$a$", f((geo.a_work if hasattr(geo, 'a_work') else geo.a) * MM, 2), "mm"],
                    ["$b$", f(g.face_width * MM, 0), "mm"], ["$v$", f(e["v"], 3), "m/s"],
                    ["$\\varepsilon_\\alpha$", f(e["eps_alpha"], 3), "—"],
                    ["$Y_{Fa}, Y_{Sa}$", f"{f(e['YFa1'], 3)}, {f(e['YSa1'], 3)} / {f(e['YFa2'], 3)}, {f(e['YSa2'], 3)}", "—"],
                    ["$F_t / F_r / F_a$", f"{f(g.forces['Ft'], 1, group=True)} / {f(g.forces['Fr'], 1, group=True)} / {f(g.forces['Fa'], 1, group=True)}", "N"]]
        else:
            e = g.extra
            geo = g.geometry
            text.append((f"蜗杆 45 钢表面淬火（>45 HRC），蜗轮 {_mat_name(g.materials[1], zh)}。$K = K_A \\times 1.1 = {f(g.K, 3)}$，"
                         f"蜗轮转矩 $T_2 = {f(g.T2, 3)}$ N·m，模数 m = {m_text}，q = {f(geo.q, 0)}。"
                         f"许用应力 $[\\sigma_H] = {f(a['sigma_H'] / 1e6, 1)}$ MPa，$[\\sigma_F] = {f(a['sigma_F'] / 1e6, 1)}$ MPa"
                         f"（$N = {f(a['N'] / 1e6, 2)}\\times10^6$）。")
                        if zh else
                        (f"Worm of surface-hardened 45 steel (>45 HRC), wheel {_mat_name(g.materials[1], zh)}. "
                         f"$K = K_A \\times 1.1 = {f(g.K, 3)}$, wheel torque $T_2 = {f(g.T2, 3)}$ N·m, module m = {m_text}, "
                         f"q = {f(geo.q, 0)}. Allowable $[\\sigma_H] = {f(a['sigma_H'] / 1e6, 1)}$ MPa, "
                         f"$[\\sigma_F] = {f(a['sigma_F'] / 1e6, 1)}$ MPa ($N = {f(a['N'] / 1e6, 2)}\\times10^6$)."))
            text.append((f"滑动速度 $v_s = {f(e['vs'], 3)}$ m/s，当量摩擦角 $\\varphi_v = {f(np.degrees(e['phi_v']), 3)}°$，"
                         f"效率 $\\eta = 0.95\\tan\\gamma/\\tan(\\gamma+\\varphi_v) = {f(e['eta'], 4)}$（用于效率链）。")
                        if zh else
                        (f"Sliding speed $v_s = {f(e['vs'], 3)}$ m/s, equivalent friction angle $\\varphi_v = "
                         f"{f(np.degrees(e['phi_v']), 3)}°$, efficiency $\\eta = 0.95\\tan\\gamma/\\tan(\\gamma+\\varphi_v) = "
                         f"{f(e['eta'], 4)}$ (used in the efficiency chain)."))
            for c in g.checks:
                if c.key == "worm_deflection":    # issue 20: 濮良贵 ch.11 stiffness check
                    i = c.inputs
                    span = ((f"支承跨距 L = {f(i['L'] * MM, 1)} mm（设计任务给定）" if zh else
                             f"bearing span L = {f(i['L'] * MM, 1)} mm (given in the brief)") if i["span_given"] else
                            (f"支承跨距按 L ≈ 0.9 $d_2$ = {f(i['L'] * MM, 1)} mm 估计" if zh else
                             f"bearing span estimated as L ≈ 0.9 $d_2$ = {f(i['L'] * MM, 1)} mm"))
                    text.append((f"蜗杆轴刚度：把蜗杆视为简支梁，中点受 $F_{{t1}}$、$F_{{r1}}$，{span}，"
                                 f"$I = \\pi d_{{f1}}^4/64$（$d_{{f1}} = d_1 - 2.4m = {f(i['df1'] * MM, 2)}$ mm），"
                                 "E = 206 GPa，许用挠度 [y] = $d_1$/1000。") if zh else
                                (f"Worm shaft stiffness: the worm as a simply supported beam loaded by $F_{{t1}}$ and "
                                 f"$F_{{r1}}$ at mid-span, {span}, $I = \\pi d_{{f1}}^4/64$ ($d_{{f1}} = d_1 - 2.4m = "
                                 f"{f(i['df1'] * MM, 2)}$ mm), E = 206 GPa, allowed deflection [y] = $d_1$/1000."))
            rows = [["$z_1 / z_2$", f"{r.z1} / {r.z2}", "—"], ["$m$", f(g.module * MM, 2), "mm"],
                    ["$q$", f(geo.q, 1), "—"], ["$d_1 / d_2$", f"{f(geo.d1 * MM, 2)} / {f(geo.d2 * MM, 2)}", "mm"],
                    ["$\\gamma$", f(np.degrees(geo.lead_angle), 3), "°"], ["$a$", f(e["a"] * MM, 2), "mm"],
                    ["$Z_\\rho$", f(e["Zrho"], 3), "—"], ["$z_{v2}, Y_{Fa2}$", f"{f(e['zv2'], 2)}, {f(e['YFa2'], 3)}", "—"],
                    ["$A$", f(e["area"], 3), "m²"]]
        out.append({"title": title, "text": text, "rows": rows,
                    "formulas": [eq for c in g.checks for eq in check_formulas(c)], "checks": _rows(check_rows(g.checks, lang), zh),
                    # the sources of the method and tables (data/references.yaml)
                    "refs": ("pu8", "gb1357") if g.kind == "gear" else ("pu9",)})
    for sh in d.shaft_designs:
        title = (f"{_shaft_name(sh.index, len(d.shafts) - 1, zh)}的设计与校核" if zh else
                 f"Design and checks of {_shaft_name(sh.index, len(d.shafts) - 1, zh)}")
        res = sh.result
        where = "、".join(n[0] for n in sh.names) if zh else ", ".join(n[1] for n in sh.names)
        text = [(f"轴上零件：{where}。按《机械设计》第 15 章的步骤设计（每步的规则与数值如下），"
                 "任一校核未通过即加大该段直径并重新校核。") if zh else
                (f"On the shaft: {where}. Designed by the procedure of PU Lianggui, Machine Design, ch. 15 (each step's rule "
                 "and numbers below); any failed check enlarges that section and everything is checked again.")]
        for k, (szh, sen) in enumerate(sh.steps, 1):
            text.append(f"第 {k} 步：{szh}。" if zh else f"Step {k}: {sen}.")
        text.append((f"支反力（强度计算）：$R_{{AH}} = {f(res.RAh, 1)}$ N，$R_{{AV}} = {f(res.RAv, 1)}$ N，"
                     f"$R_{{BH}} = {f(res.RBh, 1)}$ N，$R_{{BV}} = {f(res.RBv, 1)}$ N；危险截面 x = "
                     f"{f(res.critical.x * MM, 0)} mm，M = {f(res.critical.M, 2)} N·m。")
                    if zh else
                    (f"Reactions (strength case): $R_{{AH}} = {f(res.RAh, 1)}$ N, $R_{{AV}} = {f(res.RAv, 1)}$ N, "
                     f"$R_{{BH}} = {f(res.RBh, 1)}$ N, $R_{{BV}} = {f(res.RBv, 1)}$ N; largest equivalent moment "
                     f"at x = {f(res.critical.x * MM, 0)} mm, M = {f(res.critical.M, 2)} N·m."))
        if sh.bearing is not None:
            b = sh.bearing
            text.append((f"轴承 {b.designation}（d = {f(b.d * MM, 0)} mm，$C_r$ = {f(b.Cr / 1e3, 1)} kN），寿命按疲劳载荷："
                         f"当量动载荷 $P_A = {f(sh.bearing_loads[0], 1)}$ N，$P_B = {f(sh.bearing_loads[1], 1)}$ N"
                         f"（$f_p$ = 1.2，载荷为强度计算的 {f(sh.life_torque_factor, 3)} 倍）；静强度按峰值载荷。")
                        if zh else
                        (f"Bearings {b.designation} (d = {f(b.d * MM, 0)} mm, $C_r$ = {f(b.Cr / 1e3, 1)} kN); the life "
                         f"takes the fatigue load: equivalent loads $P_A = {f(sh.bearing_loads[0], 1)}$ N, "
                         f"$P_B = {f(sh.bearing_loads[1], 1)}$ N ($f_p$ = 1.2, the loads {f(sh.life_torque_factor, 3)} × "
                         "those of the strength case); the static strength the peak."))
        unit_mm = "mm"
        rows = [["$d_{min}$", f(sh.d_min * MM, 2), unit_mm]]
        if sh.d_end is not None:
            rows.append([("外伸端" if zh else "overhung end") + " $d_1$", f(sh.d_end * MM, 0), unit_mm])
        rows += [[("轴颈" if zh else "journal") + " $d_j$", f(sh.d_journal * MM, 0), unit_mm],
                 [("装配段" if zh else "hub seat") + " $d_s$", f(sh.d_seat * MM, 0), unit_mm],
                 [("轴环" if zh else "collar") + " $d_c$", f(sh.d_shoulder * MM, 0), unit_mm],
                 [("支承跨距" if zh else "bearing span") + " $L$", f(sh.span * MM, 0), unit_mm],
                 [("设计转矩" if zh else "design torque") + " $T$", f(sh.torque, 1, group=True), "N·m"]]
        if sh.bearing is not None:
            rows.append([("轴承" if zh else "bearing"), sh.bearing.designation, "—"])
        for k in sh.keys:
            lab = f"{f(k.b * MM, 0)}×{f(k.h * MM, 0)}×{f(k.L * MM, 0)}" + (" ×2" if k.count == 2 else "")
            rows.append([("平键" if zh else "key") + f" ({k.names[0] if zh else k.names[1]})", lab, unit_mm])
        bearing_std = () if sh.bearing is None else (
            ("gb297",) if sh.bearing.designation.startswith("3") else ("gb276",))
        out.append({"title": title, "text": text, "rows": rows,
                    "formulas": [eq for c in sh.checks for eq in check_formulas(c)], "checks": _rows(check_rows(sh.checks, lang), zh),
                    "refs": ("pu8", "gb1096", *bearing_std)})
    return out


def _belt_design(r, g, title: str, zh: bool) -> dict:
    """The V-belt subsection: each step of 濮良贵 ch.8 with its rule and its numbers."""
    from .strength_tex import check_rows, num

    b = g.geometry
    deg = np.degrees
    P, Pca = b.power / 1e3, b.power_design / 1e3
    d1, d2, a0 = b.d1 * MM, b.d2 * MM, b.a0 * MM
    d2_calc = r.ratio_allocated * d1 * (1 - b.slip)
    if b.section_given:
        how = "（设计任务给定）" if zh else " (given in the brief)"
    elif b.section_chart == b.section:
        how = "（按选型图 8-11）" if zh else " (from the selection chart, fig. 8-11)"
    else:
        how = (f"（选型图 8-11 给出 {b.section_chart} 型，但其包角或根数校核不合格，改用 {b.section} 型）" if zh else
               f" (the selection chart, fig. 8-11, gives {b.section_chart}, which fails the wrap-angle or "
               f"belt-count check; {b.section} is used)")
    sec = f"{b.section}{how}"
    if zh:
        text = [f"按濮良贵《机械设计》第 8 章设计普通 V 带：工况系数 $K_A = {f(b.KA, 2)}$（表 8-8），"
                f"计算功率 $P_{{ca}} = {f(Pca, 3)}$ kW，小带轮转速 $n_1 = {f(b.n1_rpm, 0)}$ r/min，带型 {sec}；"
                f"小带轮基准直径 $d_{{d1}} = {f(d1, 0)}$ mm ≥ $d_{{dmin}} = {f(b.d_min * MM, 0)}$ mm（表 8-7，"
                "并使带速不低于 5 m/s），大带轮取基准直径系列值（表 8-9）。",
                f"初定中心距 $a_0 = {f(a0, 0)}$ mm（$0.7(d_{{d1}}+d_{{d2}}) = {f(b.a0_min * MM, 0)}$ … "
                f"$2(d_{{d1}}+d_{{d2}}) = {f(b.a0_max * MM, 0)}$ mm）；安装、张紧范围 "
                f"$a_{{min}} … a_{{max}} = {f(b.a_min * MM, 0)} … {f(b.a_max * MM, 0)}$ mm。"
                f"$P_0$ 由表 8-4 按 $n_1$ 与 $d_{{d1}}$ 双线性插值，$\\Delta P_0$ 由表 8-5 按 $n_1$ 线性插值，"
                "$K_\\alpha$、$K_L$ 查表 8-6、8-2；选型图边界为读图近似值，部分表值未能与原书逐一核对"
                "（程序的数据文件中逐项注明）。"]
    else:
        text = [f"Ordinary V-belts designed by PU Lianggui, Machine Design, ch.8: application factor $K_A = {f(b.KA, 2)}$ "
                f"(table 8-8), design power $P_{{ca}} = {f(Pca, 3)}$ kW, small pulley speed $n_1 = {f(b.n1_rpm, 0)}$ rpm, "
                f"section {sec}; small datum diameter $d_{{d1}} = {f(d1, 0)}$ mm ≥ $d_{{dmin}} = {f(b.d_min * MM, 0)}$ mm "
                "(table 8-7, and a belt speed of at least 5 m/s), the large one from the datum series (table 8-9).",
                f"Initial centre distance $a_0 = {f(a0, 0)}$ mm ($0.7(d_{{d1}}+d_{{d2}}) = {f(b.a0_min * MM, 0)}$ … "
                f"$2(d_{{d1}}+d_{{d2}}) = {f(b.a0_max * MM, 0)}$ mm); fitting and take-up range "
                f"$a_{{min}} … a_{{max}} = {f(b.a_min * MM, 0)} … {f(b.a_max * MM, 0)}$ mm. "
                "$P_0$ interpolated bilinearly in $n_1$ and $d_{d1}$ (table 8-4), $\\Delta P_0$ linearly in $n_1$ "
                "(table 8-5), $K_\\alpha$ and $K_L$ from tables 8-6 and 8-2; the selection chart's boundaries are "
                "read off the figure and some table values could not be checked against the book "
                "(stated in data/belts.yaml)."]
    rows = [[("带型" if zh else "Section"), b.section, "—"],
            ["$d_{d1} / d_{d2}$", f"{f(d1, 0)} / {f(d2, 0)}", "mm"], ["$v$", f(b.v, 2), "m/s"],
            ["$L_d$", f(b.L_d * MM, 0), "mm"], ["$a$", f(b.a * MM, 1), "mm"],
            ["$\\alpha_1$", f(deg(b.alpha1), 2), "°"], ["$z$", str(b.z), "—"],
            ["$F_0$", f(b.F0, 1), "N"], ["$F_p$", f(b.Fp, 1), "N"]]
    d2_eq = (rf"d_{{d2}} = i\,d_{{d1}}(1-\varepsilon) = {num(r.ratio_allocated)} \times {num(d1)} \times "
             rf"(1-{num(b.slip)}) = {num(d2_calc)}\ \text{{mm}} \rightarrow {num(d2)}\ \text{{mm}}"
             if not r.fixed else rf"d_{{d2}} = {num(d2)}\ \text{{mm}}")
    formulas = [
        rf"P_{{ca}} = K_A P = {num(b.KA)} \times {num(P)} = {num(Pca)}\ \text{{kW}}",
        rf"v = \frac{{\pi d_{{d1}} n_1}}{{60 \times 1000}} = \frac{{\pi \times {num(d1)} \times {num(b.n1_rpm)}}}"
        rf"{{60000}} = {num(b.v)}\ \text{{m/s}}",
        d2_eq,
        rf"L_{{d0}} = 2a_0 + \frac{{\pi}}{{2}}(d_{{d1}}+d_{{d2}}) + \frac{{(d_{{d2}}-d_{{d1}})^2}}{{4a_0}} = "
        rf"2 \times {num(a0)} + \frac{{\pi}}{{2}} \times {num(d1 + d2)} + \frac{{{num(d2 - d1)}^2}}{{4 \times {num(a0)}}}"
        rf" = {num(b.L_d0 * MM)}\ \text{{mm}} \rightarrow L_d = {num(b.L_d * MM)}\ \text{{mm}},\ K_L = {num(b.K_L)}",
        rf"a = a_0 + \frac{{L_d - L_{{d0}}}}{{2}} = {num(a0)} + \frac{{{num(b.L_d * MM)} - {num(b.L_d0 * MM)}}}{{2}}"
        rf" = {num(b.a * MM)}\ \text{{mm}}",
        rf"\alpha_1 = 180^\circ - \frac{{d_{{d2}} - d_{{d1}}}}{{a}} \times \frac{{180^\circ}}{{\pi}} = 180^\circ - "
        rf"\frac{{{num(d2 - d1)}}}{{{num(b.a * MM)}}} \times \frac{{180^\circ}}{{\pi}} = {num(deg(b.alpha1))}^\circ",
        rf"z = \frac{{P_{{ca}}}}{{(P_0 + \Delta P_0) K_\alpha K_L}} = \frac{{{num(Pca)}}}{{({num(b.P0 / 1e3)} + "
        rf"{num(b.dP0 / 1e3)}) \times {num(b.K_alpha)} \times {num(b.K_L)}}} = {num(b.z_exact)} \rightarrow z = {b.z}",
        rf"F_0 = 500 \frac{{(2.5 - K_\alpha) P_{{ca}}}}{{K_\alpha z v}} + q v^2 = 500 \times \frac{{(2.5 - "
        rf"{num(b.K_alpha)}) \times {num(Pca)}}}{{{num(b.K_alpha)} \times {b.z} \times {num(b.v)}}} + {num(b.q_mass)}"
        rf" \times {num(b.v)}^2 = {num(b.F0)}\ \text{{N}}",
        rf"F_p = 2 z F_0 \sin\frac{{\alpha_1}}{{2}} = 2 \times {b.z} \times {num(b.F0)} \times \sin"
        rf"\frac{{{num(deg(b.alpha1))}^\circ}}{{2}} = {num(b.Fp)}\ \text{{N}}",
    ]
    return {"title": title, "text": text, "rows": rows, "formulas": formulas,
            "checks": _rows(check_rows(g.checks, "zh" if zh else "en"), zh), "refs": ("pu9", "gb13575")}


def _chain_design(g, title: str, zh: bool) -> dict:
    """The roller-chain subsection: each step of 濮良贵 ch.9 §9-5 with its numbers."""
    from .strength_tex import check_rows, num

    c = g.geometry
    p = c.pitch * MM
    P, Pca = c.power / 1e3, c.power_design / 1e3
    how = ((("链号由设计任务给定" if zh else "the chain given in the brief")) if c.chain_given else
           ("取额定功率不小于 $P_{ca}$ 的最小链号" if zh else "the smallest chain whose rated power carries $P_{ca}$"))
    if zh:
        text = [f"按濮良贵《机械设计》第 9 章设计滚子链（A 系列，{c.rows} 排）：工况系数 $K_A = {f(c.KA, 2)}$（表 9-6），"
                f"小链轮齿数系数 $K_z = (19/z_1)^{{1.08}} = {f(c.Kz, 3)}$，多排链系数 $K_p = {f(c.Kp, 2)}$；"
                f"{how}：{c.chain}（p = {f(p, 3)} mm），单排额定功率 {f(c.rated_power / 1e3, 3)} kW。",
                "图 9-11 的额定功率曲线未能按原图录入，以 ANSI B29.1 的额定功率公式（希格利《机械工程设计》式 17-32、"
                "17-33，$z_1 = 19$）代替（假设，见程序的数据文件）；中心距按链节数精确反算，"
                f"压轴力 $F_Q = {f(c.FQ_factor, 1)} F_e$。"]
    else:
        text = [f"Roller chain (A series, {c.rows} row(s)) designed by PU Lianggui, Machine Design, ch.9: application factor "
                f"$K_A = {f(c.KA, 2)}$ (table 9-6), tooth factor $K_z = (19/z_1)^{{1.08}} = {f(c.Kz, 3)}$, row factor "
                f"$K_p = {f(c.Kp, 2)}$; {how}: {c.chain} (p = {f(p, 3)} mm), rated power of one strand "
                f"{f(c.rated_power / 1e3, 3)} kW.",
                "The rated-power chart (fig. 9-11) could not be typed from the book: the ANSI B29.1 rating formulas "
                "(Shigley eqs. 17-32, 17-33, at $z_1 = 19$) stand in for it (an assumption, see data/chains.yaml); "
                f"the centre distance is the exact inverse of the link count; the load on the shafts $F_Q = "
                f"{f(c.FQ_factor, 1)} F_e$."]
    rows = [[("链号" if zh else "Chain"), c.chain, "—"], ["$z_1 / z_2$", f"{c.z1} / {c.z2}", "—"],
            ["$p$", f(p, 3), "mm"], ["$L_p$", str(c.L_p), "—"], ["$a$", f(c.a * MM, 1), "mm"],
            ["$v$", f(c.v, 3), "m/s"], ["$F_e$", f(c.Fe, 1), "N"], ["$F_Q$", f(c.FQ, 1), "N"]]
    formulas = [
        rf"P_{{ca}} = \frac{{K_A K_z P}}{{K_p}} = \frac{{{num(c.KA)} \times {num(c.Kz)} \times {num(P)}}}"
        rf"{{{num(c.Kp)}}} = {num(Pca)}\ \text{{kW}}",
        rf"L_{{p0}} = \frac{{2a_0}}{{p}} + \frac{{z_1 + z_2}}{{2}} + \frac{{p}}{{a_0}}\left(\frac{{z_2 - z_1}}"
        rf"{{2\pi}}\right)^2 = \frac{{2 \times {num(c.a0 * MM)}}}{{{num(p)}}} + \frac{{{c.z1 + c.z2}}}{{2}} + "
        rf"\frac{{{num(p)}}}{{{num(c.a0 * MM)}}}\left(\frac{{{c.z2 - c.z1}}}{{2\pi}}\right)^2 = {num(c.L_p0)}"
        rf" \rightarrow L_p = {c.L_p}",
        rf"a = \frac{{p}}{{4}}\left[\left(L_p - \frac{{z_1 + z_2}}{{2}}\right) + \sqrt{{\left(L_p - "
        rf"\frac{{z_1 + z_2}}{{2}}\right)^2 - 8\left(\frac{{z_2 - z_1}}{{2\pi}}\right)^2}}\right] = "
        rf"{num(c.a * MM)}\ \text{{mm}}",
        rf"v = \frac{{z_1 n_1 p}}{{60 \times 1000}} = \frac{{{c.z1} \times {num(c.n1_rpm)} \times {num(p)}}}"
        rf"{{60000}} = {num(c.v)}\ \text{{m/s}}",
        rf"F_Q = {num(c.FQ_factor)} F_e = {num(c.FQ_factor)} \times \frac{{1000 P}}{{v}} = {num(c.FQ_factor)} "
        rf"\times \frac{{1000 \times {num(P)}}}{{{num(c.v)}}} = {num(c.FQ)}\ \text{{N}}",
    ]
    return {"title": title, "text": text, "rows": rows, "formulas": formulas,
            "checks": _rows(check_rows(g.checks, "zh" if zh else "en"), zh), "refs": ("pu9",)}


# --------------------------------------------------------------------------- machine: drive


