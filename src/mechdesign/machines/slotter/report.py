"""The slotter report: the shared linkage, flywheel, cam, gear, drive, verification and
sheet sections, plus the guide-bar synthesis (strings only; the templates place them)."""
from __future__ import annotations


import numpy as np

from ...render.fmt import e, f, md_meta, md_text
from ...render.fmt import in_lang, verdict
from ...render import guide_bar_report as gb_report
from ...render.linkage_report import linkage_context, verification_rows

DEG = 180.0 / np.pi


make_figures = gb_report.make_figures   # the linkage's figures and the optional cam/gear ones
write_data = gb_report.write_data       # the cam profile as CSV
animate = gb_report.animate             # the linkage as a GIF


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    zh = lang == "zh"
    p, syn, k, v = r["params"], r["synthesis"], r["linkage"], r["linkage_verification"]
    mm = 1e3
    H = p.stroke * mm
    lk, ld = brief.linkage, brief.loads
    data_rows = gb_report.data_rows(
        brief, p, "滑枕", "BC", lk.rod_ratio_BC_O3B,
        ["$y_{S_6}$", "滑枕质心至 C / ram CoM above C", f(lk.ram_com_y_S6_mm, 0), "mm"], "插削阻力",
        ["$x_P$", "切削力作用线至导路 / cutting line from the guide", f(ld.cutting_offset_xP_mm, 0), "mm"])
    guide_bar = gb_report.guide_bar_context(syn, p, "BC", "滑枕")
    lkc = linkage_context(r["model"], k, r["linkage_forces"], r["linkage_flywheel"], v, figures,
                          lang, title="插床导杆机构分析" if zh else "Guide-bar linkage analysis")
    findings = [md_text(w.text(lang)) for key in ("linkage_verification", "linkage_flywheel")
                for w in (getattr(r[key], "warnings", ()) or ())]
    return {
        **gb_report.task_words(p, syn),
        "meta": md_meta(brief.report, lang), "data_rows": in_lang(data_rows, lang), "guide_bar": {**guide_bar, "rows": in_lang(guide_bar["rows"], lang)},
        "n2": f(p.crank_speed_rpm, 0), "sense_zh": "顺时针" if p.crank_omega < 0 else "逆时针",
        "sense_en": "clockwise" if p.crank_omega < 0 else "counter-clockwise",
        "idle_mm": f(p.idle_travel_ratio * H, 1), "cut_to": f((1 - p.idle_travel_ratio) * H, 1),
        "linkage": lkc, **gb_report.optional_sections(r, lang, figures),
        "verify_rows": verification_rows(v, lang, k)
        + [["行程误差 / mm" if zh else "stroke error / mm", e((v.stroke - p.stroke) * mm),
            "0", verdict(abs(v.stroke - p.stroke) <= 1e-9, "zh" if zh else "en")]],
        "findings": findings,
    }
