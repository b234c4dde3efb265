"""Report of the `cam` machine: the shared cam section (:mod:`mechdesign.render.cam_report`) and its self-checks."""
from __future__ import annotations

from pathlib import Path
from ...i18n import N_, tr
from ...render.fmt import md_meta, md_text
from ...render.cam_report import cam_context, cam_verification_rows, envelope_note, make_cam_figures, write_cam_csv


def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    return make_cam_figures(r["cam"], fig_dir, lang)


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    c, v = r["cam"], r.get("cam_verification")
    out = {"meta": md_meta(brief.report, lang), "cam": cam_context(c, lang, figures, "cam_profile.csv", brief.cam),
           "envelope_note": envelope_note(c, lang, v),
           "verify_rows": [], "findings": [], "verify_note": ""}
    if v is not None:
        out.update(verify_rows=cam_verification_rows(v, c, lang),
                   findings=[md_text(w.text(lang)) for w in v.warnings],
                   verify_note=tr(lang)(_CAM_NOTE))
    return out


_CAM_NOTE = N_("Every item is recomputed on the 0.1° design grid without the formula "
               "it checks: the velocity against central differences of the displacement and the "
               "acceleration against those of the velocity, whose truncation error scales with "
               "the square of the step (stencils across an impact are left out); the pressure angle from the "
               "normal to the chord of two neighbouring pitch points and the follower's "
               "direction of motion; the curvature from three neighbouring points; a roller "
               "follower's actual profile against a 20 × denser pitch curve by the shortest "
               "distance both ways (profile to pitch curve and pitch curve to profile), both of "
               "which must equal the roller radius.")


def write_data(r: dict, folder: Path) -> list[Path]:
    return write_cam_csv(r["cam"], folder)
