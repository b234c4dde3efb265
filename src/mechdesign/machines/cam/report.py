"""Report of the `cam` machine: the shared cam section (:mod:`mechdesign.render.cam_report`) and its self-checks."""
from __future__ import annotations

from pathlib import Path
from ...render.fmt import md_meta, md_text
from ...render.cam_report import cam_context, cam_verification_rows, envelope_note, make_cam_figures, write_cam_csv


def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    return make_cam_figures(r["cam"], fig_dir, lang)


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    c, v = r["cam"], r.get("cam_verification")
    out = {"meta": md_meta(brief.report, lang), "cam": cam_context(c, lang, figures, "cam_profile.csv"),
           "envelope_note": envelope_note(c, lang, "cam_profile"),
           "verify_rows": [], "findings": [], "verify_note": ""}
    if v is not None:
        out.update(verify_rows=cam_verification_rows(v, c, lang),
                   findings=[md_text(w.text(lang)) for w in v.warnings],
                   verify_note=_CAM_NOTE[lang])
    return out


_CAM_NOTE = {
    "zh": "各项均由本次运行在 0.1° 设计网格上重新算出，不用被校核的公式：速度、加速度与位移（速度）的中心差分比较，"
          "截断误差与步长平方成正比（跨越冲击点的差分不计）；压力角由理论廓线相邻两点的弦向求法线，再与从动件在该点的运动方向求夹角；"
          "曲率由相邻三点求得；滚子从动件的实际廓线与 20 倍加密的理论廓线比较两向最短距离（实际廓线上各点到理论廓线、"
          "理论廓线上各点到实际廓线），两者都应等于滚子半径。",
    "en": "Every item is recomputed in this run on the 0.1° design grid without the formula it checks: velocity and "
          "acceleration against central differences of the displacement (velocity), whose truncation error scales with "
          "the square of the step (stencils across an impact are left out); the pressure angle from the normal to the chord "
          "of two neighbouring pitch points and the follower's direction of motion; the curvature from three neighbouring "
          "points; a roller follower's actual profile against a 20 × denser pitch curve by the shortest distance both ways "
          "(profile to pitch curve and pitch curve to profile), both of which must equal the roller radius.",
}


def write_data(r: dict, folder: Path) -> list[Path]:
    return write_cam_csv(r["cam"], folder)
