"""The press report: the six-bar's synthesis (the course's graphical construction written
analytically, formulas with the numbers), plus the shared linkage, flywheel, cam, gear,
drive, verification and sheet sections (strings only; the templates place them)."""
from __future__ import annotations


import numpy as np

from ...render import guide_bar_report as gb_report
from ...render.fmt import e, f, md_meta, md_text
from ...render.fmt import in_lang, verdict
from ...render.linkage_report import linkage_context, verification_rows

DEG = 180.0 / np.pi


make_figures = gb_report.make_figures   # the linkage's figures and the optional cam/gear ones
write_data = gb_report.write_data       # the cam profile as CSV
animate = gb_report.animate             # the linkage as a GIF


def _data_rows(b, p) -> list[list[str]]:
    lk, ms, ld = b.linkage, b.masses, b.loads
    return [
        ["$x_1$", "A 在 D 右侧 / A right of D", f(lk.pivot_x1_mm, 0), "mm"],
        ["$x_2$", "导路在 D 右侧 / guide right of D", f(lk.guide_x2_mm, 0), "mm"],
        ["$y$", "A 在 D 下方 / A below D", f(lk.pivot_y_mm, 0), "mm"],
        ["$\\psi_3'$", "摇杆上极限角 / rocker upper extreme", f(lk.rocker_psi3_upper_deg, 1), "°"],
        ["$\\psi_3''$", "摇杆下极限角 / rocker lower extreme", f(lk.rocker_psi3_lower_deg, 1), "°"],
        ["$H$", "滑块行程 / ram stroke", f(lk.stroke_H_mm, 1), "mm"],
        ["$CE/CD$", "摇杆上 C 点位置 / C on the rocker", f(lk.ratio_CE_CD, 3), "—"],
        ["$EF/DE$", "连杆 EF 与摇杆之比 / rod ratio", f(lk.ratio_EF_DE, 3), "—"],
        ["$BS_2/BC$", "连杆质心 / coupler CoM", f(lk.ratio_BS2_BC, 2), "—"],
        ["$DS_3/DE$", "摇杆质心 / rocker CoM", f(lk.ratio_DS3_DE, 2), "—"],
        ["$n_1$", "曲柄转速 / crank speed", f(lk.crank_speed_n1_rpm, 0), "rpm"],
        ["$G_2$", "连杆重量 / coupler weight", f(ms.coupler_G2_N, 0), "N"],
        ["$G_3$", "摇杆重量 / rocker weight", f(ms.rocker_G3_N, 0), "N"],
        ["$G_5$", "滑块重量 / ram weight", f(ms.ram_G5_N, 0), "N"],
        ["$J_{S_2}$", "连杆转动惯量 / coupler inertia", f(ms.coupler_J_S2_kgm2, 3), "kg·m²"],
        ["$J_{S_3}$", "摇杆转动惯量 / rocker inertia", f(ms.rocker_J_S3_kgm2, 3), "kg·m²"],
        ["$Q_{max}$", "最大生产阻力 / pressing force", f(ld.pressing_force_Qmax_N, 0), "N"],
        ["$z_1, z_2$", "齿轮齿数 / gear teeth", f"{p.z1}, {p.z2}", "—"],
        ["$[\\delta]$", "许用速度不均匀系数 / speed fluctuation", f"1/{1 / p.fluctuation:.4g}", "—"],
    ]


def synthesis_context(s, p) -> dict:
    """Formulas with the numbers substituted and the link-length table."""
    mm = 1e3
    H, de, cd = p.stroke * mm, s.rocker * mm, s.rocker_CD * mm
    pu, pl = p.psi_upper * DEG, p.psi_lower * DEG
    half = (pl - pu) / 2
    x1, y = p.x1 * mm, p.y * mm
    cu, cl = s.C_upper * mm, s.C_lower * mm
    a, b, c, d = s.crank * mm, s.coupler * mm, s.rocker_CD * mm, s.frame * mm
    lmax = max(b, c, d)
    others = b + c + d - lmax
    theta = s.extreme_angle * DEG
    g1 = np.degrees(np.arccos((b * b + c * c - (d - a) ** 2) / (2 * b * c)))
    g2 = np.degrees(np.arccos((b * b + c * c - (d + a) ** 2) / (2 * b * c)))
    g2 = min(g2, 180 - g2)
    near, far = sorted((s.AC_upper * mm, s.AC_lower * mm))

    def ac(name, cpt):
        return (rf"L_{{A{name}}} = \sqrt{{(x_{{{name}}} - x_1)^2 + (y_{{{name}}} + y)^2}} = "
                rf"\sqrt{{({f(cpt.real, 2)} - {f(x1, 0)})^2 + ({f(cpt.imag, 2)} + {f(y, 0)})^2}} = "
                rf"{f(abs(cpt - complex(x1, -y)), 2)}\ \text{{mm}}")
    eq = {
        "de": (rf"L_{{DE}} = \frac{{H}}{{2\sin\frac{{\psi_3''-\psi_3'}}{{2}}}} = "
               rf"\frac{{{f(H, 1)}}}{{2\sin {f(half, 2)}°}} = {f(de, 2)}\ \text{{mm}}"),
        "cd": (rf"L_{{CD}} = \frac{{L_{{DE}}}}{{1 + CE/CD}} = \frac{{{f(de, 2)}}}{{1 + {f(p.ratio_CE_CD, 3)}}}"
               rf" = {f(cd, 2)}\ \text{{mm}},\quad L_{{CE}} = L_{{DE}} - L_{{CD}} = {f(s.rocker_CE * mm, 2)}\ \text{{mm}}"),
        "ef": (rf"L_{{EF}} = (EF/DE)\,L_{{DE}} = {f(p.ratio_EF_DE, 3)} \times {f(de, 2)} = "
               rf"{f(s.rod * mm, 2)}\ \text{{mm}}"),
        "c": (rf"C' = L_{{CD}}(\sin\psi_3', \cos\psi_3') = ({f(cu.real, 2)}, {f(cu.imag, 2)}),\quad "
              rf"C'' = ({f(cl.real, 2)}, {f(cl.imag, 2)})\ \text{{mm}}"),
        "ac1": ac("C'", cu), "ac2": ac("C''", cl),
        "ab": (rf"L_{{AB}} = \frac{{L_{{AC}}^{{\max}} - L_{{AC}}^{{\min}}}}{{2}} = "
               rf"\frac{{{f(far, 2)} - {f(near, 2)}}}{{2}} = {f(a, 2)}\ \text{{mm}}"),
        "bc": (rf"L_{{BC}} = \frac{{L_{{AC}}^{{\max}} + L_{{AC}}^{{\min}}}}{{2}} = "
               rf"\frac{{{f(far, 2)} + {f(near, 2)}}}{{2}} = {f(b, 2)}\ \text{{mm}}"),
        "ad": rf"L_{{AD}} = \sqrt{{x_1^2 + y^2}} = {f(d, 2)}\ \text{{mm}}",
        "grashof": (rf"L_{{AB}} + l_{{\max}} = {f(a, 2)} + {f(lmax, 2)} = {f(a + lmax, 2)} "
                    rf"\le {f(others, 2)}\ \text{{mm}}"),
        "theta": (rf"\theta = \angle C'AC'' = {f(theta, 3)}°,\quad K = \frac{{180° + \theta}}"
                  rf"{{180° - \theta}} = {f(s.time_ratio, 4)}"),
        "gamma": (rf"\cos\gamma = \frac{{b^2 + c^2 - (d \mp a)^2}}{{2bc}}:\quad "
                  rf"\gamma_1 = {f(g1, 2)}°,\ \gamma_2 = {f(g2, 2)}°"),
        "guide": (rf"x_M = L_{{DE}}\,\frac{{1 + \cos\frac{{\psi_3''-\psi_3'}}{{2}}}}{{2}} = "
                  rf"{f(s.sagitta_guide * mm, 2)}\ \text{{mm}}\quad (x_2 = {f(p.x2 * mm, 1)}\ \text{{mm}})"),
    }
    rows = [
        ["$L_{AB}$", "曲柄 / crank", f(a, 2), "mm"],
        ["$L_{BC}$", "连杆 / coupler", f(b, 2), "mm"],
        ["$L_{CD}$", "摇杆 DC 段 / rocker to C", f(c, 2), "mm"],
        ["$L_{DE}$", "摇杆 / rocker", f(de, 2), "mm"],
        ["$L_{CE}$", "C 至 E / C to E", f(s.rocker_CE * mm, 2), "mm"],
        ["$L_{EF}$", "连杆 EF / rod EF", f(s.rod * mm, 2), "mm"],
        ["$L_{AD}$", "机架 / frame", f(d, 2), "mm"],
        ["$L_{BS_2}$", "连杆质心 / coupler CoM", f(s.coupler_com * mm, 2), "mm"],
        ["$L_{DS_3}$", "摇杆质心 / rocker CoM", f(s.rocker_com * mm, 2), "mm"],
        ["$\\theta$", "极位夹角 / extreme-position angle", f(theta, 3), "°"],
        ["$K$", "行程速比系数 / time ratio", f(s.time_ratio, 4), "—"],
    ]
    return {"eq": eq, "rows": rows, "gmin": f(min(g1, g2), 2)}


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    zh = lang == "zh"
    p, s, k, v = r["params"], r["synthesis"], r["linkage"], r["linkage_verification"]
    mm = 1e3
    lkc = linkage_context(r["model"], k, r["linkage_forces"], r["linkage_flywheel"], v, figures,
                          lang, title="压床六杆机构分析" if zh else "Six-bar linkage analysis")
    findings = [md_text(w.text(lang)) for key in ("linkage_verification", "linkage_flywheel")
                for w in (getattr(r[key], "warnings", ()) or ())]
    slow = k.time_ratio >= 1.0
    return {
        "meta": md_meta(brief.report, lang), "data_rows": in_lang(_data_rows(brief, p), lang),
        "press": (lambda c: {**c, "rows": in_lang(c["rows"], lang)})(synthesis_context(s, p)),
        "n1": f(p.crank_speed_rpm, 0), "sense_zh": "顺时针" if p.crank_omega < 0 else "逆时针",
        "sense_en": "clockwise" if p.crank_omega < 0 else "counter-clockwise",
        "slow_zh": "慢" if slow else "快", "slow_en": "slow" if slow else "fast",
        "press_from": f((1 - p.pressing_ratio) * p.stroke * mm, 1), "H": f(p.stroke * mm, 1),
        "Q": f(p.pressing_force, 0),
        "linkage": lkc, **gb_report.optional_sections(r, lang, figures),
        "verify_rows": verification_rows(v, lang, k)
        + [["行程误差 / mm" if zh else "stroke error / mm", e((v.stroke - p.stroke) * mm),
            "0", verdict(abs(v.stroke - p.stroke) <= 1e-9, "zh" if zh else "en")]],
        "findings": findings,
    }
