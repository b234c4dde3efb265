"""The press report: the six-bar's synthesis (the course's graphical construction written
analytically, formulas with the numbers), plus the shared linkage, flywheel, cam, gear,
drive, verification and sheet sections (strings only; the templates place them)."""
from __future__ import annotations


import numpy as np

from ...i18n import N_, tr
from ...render import guide_bar_report as gb_report
from ...render.fmt import e, f, md_meta, md_text, time_ratio, fluctuation
from ...render.fmt import residue, verdict
from ...render.linkage_report import linkage_context, verification_rows

DEG = 180.0 / np.pi


make_figures = gb_report.make_figures   # the linkage's figures and the optional cam/gear ones
write_data = gb_report.write_data       # the cam profile as CSV
animate = gb_report.animate             # the linkage as a GIF


def _data_rows(b, p, _) -> list[list[str]]:
    lk, ms, ld = b.linkage, b.masses, b.loads
    return [
        ["$x_1$", _("$A$ right of $D$"), f(lk.pivot_x1_mm, 0), "mm"],
        ["$x_2$", _("guide right of $D$"), f(lk.guide_x2_mm, 0), "mm"],
        ["$y$", _("$A$ below $D$"), f(lk.pivot_y_mm, 0), "mm"],
        ["$\\psi_3'$", _("rocker upper extreme"), f(lk.rocker_psi3_upper_deg, 1), "°"],
        ["$\\psi_3''$", _("rocker lower extreme"), f(lk.rocker_psi3_lower_deg, 1), "°"],
        ["$H$", _("ram stroke"), f(lk.stroke_H_mm, 1), "mm"],
        ["$CE/CD$", _("$C$ on the rocker"), f(lk.ratio_CE_CD, 3), "—"],
        ["$EF/DE$", _.pgettext("press", "rod ratio"), f(lk.ratio_EF_DE, 3), "—"],
        ["$BS_2/BC$", _("coupler CoM"), f(lk.ratio_BS2_BC, 2), "—"],
        ["$DS_3/DE$", _("rocker CoM"), f(lk.ratio_DS3_DE, 2), "—"],
        ["$n_1$", _("crank speed"), f(lk.crank_speed_n1_rpm, 0), _("rpm")],
        ["$G_2$", _("coupler weight"), f(ms.coupler_G2_N, 0), "N"],
        ["$G_3$", _("rocker weight"), f(ms.rocker_G3_N, 0), "N"],
        ["$G_5$", _("ram weight"), f(ms.ram_G5_N, 0), "N"],
        ["$J_{S_2}$", _("coupler inertia"), f(ms.coupler_J_S2_kgm2, 3), "kg·m²"],
        ["$J_{S_3}$", _("rocker inertia"), f(ms.rocker_J_S3_kgm2, 3), "kg·m²"],
        ["$Q_{max}$", _("pressing force"), f(ld.pressing_force_Qmax_N, 0), "N"],
        ["$z_1, z_2$", _("gear teeth"), f"{p.z1}, {p.z2}", "—"],
        # the pair's module and pressure angle with its teeth (page review 41: the data table
        # gave z1, z2 alone; the cam's data are the cam chapter's own table)
        ["$m$", _("gear module"), f"{b.gear_pair.module_mm:g}", "mm"],
        ["$\\alpha$", _("gear pressure angle"), f"{b.gear_pair.pressure_angle_deg:g}", "°"],
        ["$[\\delta]$", _("speed fluctuation"), fluctuation(p.fluctuation), "—"],
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
        "theta": (rf"\theta = \angle C'AC'' = {f(theta, 2)}°,\quad K = \frac{{180° + \theta}}"
                  rf"{{180° - \theta}} = {time_ratio(s.time_ratio)}"),
        "gamma": (rf"\cos\gamma = \frac{{b^2 + c^2 - (d \mp a)^2}}{{2bc}}:\quad "
                  rf"\gamma_1 = {f(g1, 2)}°,\ \gamma_2 = {f(g2, 2)}°"),
        "guide": (rf"x_M = L_{{DE}}\,\frac{{1 + \cos\frac{{\psi_3''-\psi_3'}}{{2}}}}{{2}} = "
                  rf"{f(s.sagitta_guide * mm, 2)}\ \text{{mm}}\quad (x_2 = {f(p.x2 * mm, 1)}\ \text{{mm}})"),
    }
    rows = [
        ["$L_{AB}$", N_("crank"), f(a, 2), "mm"],
        ["$L_{BC}$", N_("coupler"), f(b, 2), "mm"],
        ["$L_{CD}$", N_("rocker to $C$"), f(c, 2), "mm"],
        ["$L_{DE}$", N_("rocker"), f(de, 2), "mm"],
        ["$L_{CE}$", N_("$C$ to $E$"), f(s.rocker_CE * mm, 2), "mm"],
        ["$L_{EF}$", N_("rod $EF$"), f(s.rod * mm, 2), "mm"],
        ["$L_{AD}$", N_("frame"), f(d, 2), "mm"],
        ["$L_{BS_2}$", N_("coupler CoM"), f(s.coupler_com * mm, 2), "mm"],
        ["$L_{DS_3}$", N_("rocker CoM"), f(s.rocker_com * mm, 2), "mm"],
        ["$\\theta$", N_("extreme-position angle"), f(theta, 2), "°"],   # as in eq. and text
        ["$K$", N_("time ratio"), time_ratio(s.time_ratio), "—"],
    ]
    return {"eq": eq, "rows": rows, "gmin": f(min(g1, g2), 2)}


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    _ = tr(lang)
    p, s, k, v = r["params"], r["synthesis"], r["linkage"], r["linkage_verification"]
    mm = 1e3
    lkc = linkage_context(r["model"], k, r["linkage_forces"], r["linkage_flywheel"], v, figures,
                          lang, title=_("Six-bar linkage analysis"))
    findings = [md_text(w.text(lang)) for key in ("linkage_verification", "linkage_flywheel")
                for w in (getattr(r[key], "warnings", ()) or ())]
    slow = k.time_ratio >= 1.0
    speed = N_("slow") if slow else N_("fast")
    sense = N_("clockwise") if p.crank_omega < 0 else N_("counter-clockwise")
    zh_words = tr("zh")     # the template's Chinese words (sense_zh, slow_zh)
    press = synthesis_context(s, p)
    return {
        "meta": md_meta(brief.report, lang), "data_rows": _data_rows(brief, p, _),
        "press": {**press, "rows": [[sym, _(name), *rest] for sym, name, *rest in press["rows"]]},
        "n1": f(p.crank_speed_rpm, 0), "sense_zh": zh_words(sense), "sense_en": sense,
        "slow_zh": zh_words(speed), "slow_en": speed,
        "press_from": f((1 - p.pressing_ratio) * p.stroke * mm, 1), "H": f(p.stroke * mm, 1),
        "Q": f(p.pressing_force, 0),
        "linkage": lkc, **gb_report.optional_sections(r, lang, figures, brief),
        "verify_rows": verification_rows(v, lang, k)
        + [[_("stroke error / mm"), residue((v.stroke - p.stroke) * mm, p.stroke * mm),
            "0", verdict(abs(v.stroke - p.stroke) <= 1e-9, _.lang)]],
        "findings": findings,
    }
