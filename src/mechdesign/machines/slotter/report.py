"""The slotter report: the shared linkage, flywheel, cam, gear, drive, verification and
sheet sections, plus the guide-bar synthesis (strings only; the templates place them)."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ...render.fmt import f, md_meta, md_text
from ...render.guide_bar_report import guide_bar_context
from ...render.linkage_report import linkage_context, make_linkage_figures, verification_rows

DEG = 180.0 / np.pi


def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    paths = make_linkage_figures(r["model"], r["linkage"], r["linkage_forces"],
                                 r["linkage_flywheel"], fig_dir, lang)
    if r.get("cam") is not None:
        from ...render.cam_report import make_cam_figures

        paths.update(make_cam_figures(r["cam"], fig_dir, lang))
    if r.get("gear") is not None:
        from ...render.gear_report import make_gear_figures

        paths.update(make_gear_figures(r["gear"], fig_dir, lang))
    return paths


def write_data(r: dict, folder: Path) -> list[Path]:
    if r.get("cam") is None:
        return []
    from ...render.cam_report import write_cam_csv

    return write_cam_csv(r["cam"], folder)


def animate(r: dict, path: Path, lang: str) -> Path:
    from ...render.animation import linkage_gif

    return linkage_gif(r["model"], r["linkage"], path, lang)


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    zh = lang == "zh"
    p, syn, k, v = r["params"], r["synthesis"], r["linkage"], r["linkage_verification"]
    mm = 1e3
    K, H = p.time_ratio_K, p.stroke * mm
    lk, ms, ld = brief.linkage, brief.masses, brief.loads
    data_rows = [
        ["$H$", "插刀行程 / ram stroke", f(lk.stroke_H_mm, 0), "mm"],
        ["$K$", "行程速比系数 / time ratio", f(K, 2), "—"],
        ["$L_{O_2O_3}$", "机架长 / frame", f(lk.frame_O2O3_mm, 0), "mm"],
        ["$L_{BC}/L_{O_3B}$", "连杆与导杆之比 / rod ratio", f(lk.rod_ratio_BC_O3B, 2), "—"],
        ["$L_{O_3S_4}/L_{O_3B}$", "导杆质心位置 / bar CoM ratio", f(lk.com_ratio_O3S4_O3B, 2), "—"],
        ["$y_{S_6}$", "滑枕质心至 C / ram CoM above C", f(lk.ram_com_y_S6_mm, 0), "mm"],
        ["$n_2$", "曲柄转速 / crank speed", f(lk.crank_speed_n2_rpm, 0), "rpm"],
        ["$m_4$", "导杆质量 / guide-bar mass", f(ms.guide_bar_m4_kg, 1), "kg"],
        ["$J_{S_4}$", "导杆转动惯量 / guide-bar inertia", f(ms.guide_bar_J_S4_kgm2, 3), "kg·m²"],
        ["$m_6$", "滑枕质量 / ram mass", f(ms.ram_m6_kg, 1), "kg"],
        ["$G_2$", "齿轮2重量 / gear 2 weight", f(ms.gear2_weight_G2_N, 0), "N"],
        ["$F_c$", "插削阻力 / cutting force", f(ld.cutting_force_Fc_N, 0), "N"],
        ["$x_P$", "切削力作用线至导路 / cutting line from the guide", f(ld.cutting_offset_xP_mm, 0), "mm"],
        ["$z_1, z_2$", "齿轮齿数 / gear teeth", f"{p.z1}, {p.z2}", "—"],
        ["$[\\delta]$", "许用速度不均匀系数 / speed fluctuation", f"1/{1 / p.fluctuation:.4g}", "—"],
    ]
    guide_bar = guide_bar_context(syn, p, "BC", "滑枕")
    lkc = linkage_context(r["model"], k, r["linkage_forces"], r["linkage_flywheel"], v, figures,
                          lang, title="插床导杆机构分析" if zh else "Guide-bar linkage analysis")
    cam = gear = drive = None
    if r.get("cam") is not None:
        from ...render.cam_report import cam_context

        cam = cam_context(r["cam"], lang, figures, "cam_profile.csv")
    if r.get("gear") is not None:
        from ...render.gear_report import gear_context

        gear = gear_context(r["gear"], lang, figures)
    if r.get("drive") is not None:
        from ...render.drive_report import drive_context

        fl = r["linkage_flywheel"]
        pw = (rf"P_w = \bar M_b\,\omega_2 = {f(fl.mean_torque, 3)} \times "
              rf"{f(abs(p.crank_omega), 4)} = {f(fl.mean_power, 2)}\ \text{{W}}")
        drive = drive_context(r["drive"], lang, figures, pw)
    findings = [md_text(w.text(lang)) for key in ("linkage_verification", "linkage_flywheel")
                for w in (getattr(r[key], "warnings", ()) or ())]
    return {
        "meta": md_meta(brief.report), "data_rows": data_rows, "guide_bar": guide_bar,
        "n2": f(p.crank_speed_rpm, 0), "sense_zh": "顺时针" if p.crank_omega < 0 else "逆时针",
        "sense_en": "clockwise" if p.crank_omega < 0 else "counter-clockwise",
        "idle_mm": f(p.idle_travel_ratio * H, 1), "cut_to": f((1 - p.idle_travel_ratio) * H, 1),
        "linkage": lkc, "cam": cam, "gear": gear, "drive": drive,
        "verify_rows": verification_rows(v, lang, k)
        + [["行程误差 / mm" if zh else "stroke error / mm", f((v.stroke - p.stroke) * mm, 6),
            "0", ("满足" if zh else "ok") if abs(v.stroke - p.stroke) <= 1e-9 else
            ("不满足" if zh else "fails")]],
        "findings": findings,
    }
