"""The slotter report: the shared linkage, flywheel, cam, gear, drive, verification and
sheet sections, plus the guide-bar synthesis (strings only; the templates place them)."""
from __future__ import annotations


import numpy as np

from ...i18n import N_, tr
from ...render.fmt import e, f, md_meta, md_text
from ...render.fmt import in_lang, residue, verdict
from ...render import guide_bar_report as gb_report
from ...render.linkage_report import linkage_context, verification_rows

DEG = 180.0 / np.pi


make_figures = gb_report.make_figures   # the linkage's figures and the optional cam/gear ones
write_data = gb_report.write_data       # the cam profile as CSV
animate = gb_report.animate             # the linkage as a GIF


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    _ = tr(lang)
    zh_words = tr("zh")     # the guide-bar tables take the ram's and the load's Chinese names
    p, syn, k, v = r["params"], r["synthesis"], r["linkage"], r["linkage_verification"]
    mm = 1e3
    H = p.stroke * mm
    lk, ld = brief.linkage, brief.loads
    data_rows = gb_report.data_rows(
        brief, p, zh_words.pgettext("slotter", "ram"), "BC", lk.rod_ratio_BC_O3B,
        ["$y_{S_6}$", _.pgettext("slotter", "ram CoM above $C$"), f(lk.ram_com_y_S6_mm, 0), "mm"],
        zh_words.pgettext("slotter", "cutting resistance"),
        ["$x_P$", _("cutting line from the guide"), f(ld.cutting_offset_xP_mm, 0), "mm"])
    guide_bar = gb_report.guide_bar_context(syn, p, "BC", zh_words.pgettext("slotter", "ram"))
    fl, drive = r["linkage_flywheel"], r.get("drive")
    # the flywheel shaft's speed as the drive realises it (pinion: the shaft before the crank)
    n_real = None if drive is None else drive.shafts[
        len(drive.stages) - (1 if fl.shaft == "pinion" else 0)].speed_rpm
    lkc = linkage_context(r["model"], k, r["linkage_forces"], fl, v, figures,
                          lang, title=_("Guide-bar linkage analysis"), flywheel_realised_rpm=n_real)
    findings = [md_text(w.text(lang)) for key in ("linkage_verification", "linkage_flywheel")
                for w in (getattr(r[key], "warnings", ()) or ())]
    sense = N_("clockwise") if p.crank_omega < 0 else N_("counter-clockwise")
    return {
        **gb_report.task_words(p, syn),
        "meta": md_meta(brief.report, lang), "data_rows": in_lang(data_rows, lang), "guide_bar": {**guide_bar, "rows": in_lang(guide_bar["rows"], lang)},
        "n2": f(p.crank_speed_rpm, 0), "sense_zh": zh_words(sense), "sense_en": sense,
        "idle_mm": f(p.idle_travel_ratio * H, 1), "cut_to": f((1 - p.idle_travel_ratio) * H, 1),
        "linkage": lkc, **gb_report.optional_sections(r, lang, figures, brief),
        "verify_rows": verification_rows(v, lang, k)
        + [[_("stroke error / mm"), residue((v.stroke - p.stroke) * mm, p.stroke * mm),
            "0", verdict(abs(v.stroke - p.stroke) <= 1e-9, "zh" if _.zh else "en")]],
        "findings": findings,
    }
