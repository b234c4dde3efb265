"""Report of the eccentric-disc analysis (``machine: eccentric_cam``, exercises 7-1/7-2):
displacement and pressure angle of each follower, as curves and tables."""
from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

from ...fileio import atomic_open
from ...render import cam_figures as cf
from ...render.cam_report import CONTACT
from ...i18n import N_, tr
from ...render.fmt import e, f, md_meta, md_text, mpl_text
from ...render.fmt import residue, verdict

DEG = 180.0 / np.pi
MM = 1e3

def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    d = r["disc"]
    named = [(mpl_text(label), m.s * MM, m.pressure_angle * DEG)
             for (label, _), m in zip(d.params.followers, d.motions)]
    cf.disc_curves(fig_dir / "disc_curves.png", lang, d.grid_delta * DEG, named)
    return {"curves": f"{fig_dir.name}/disc_curves.png"}


def _describe(fol, lang):
    _ = tr(lang)
    contact = CONTACT[lang][fol.kind]
    if fol.offset == 0:
        where = _("centred")
    else:
        side = _.pgettext("offset side", "right") if fol.offset > 0 else _.pgettext("offset side", "left")
        where = _("offset $e$ = {offset} mm ({side})", offset=f(abs(fol.offset) * MM, 1), side=side)
    extra = ""
    if fol.kind == "roller":
        extra = _(", $r_r$ = {roller_radius} mm", roller_radius=f(fol.roller_radius * MM, 1))
    return _("{where} {contact} follower{extra}", where=where, contact=contact, extra=extra)


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    d = r["disc"]
    p = d.params
    _ = tr(lang)
    R, ecc = p.radius * MM, p.eccentricity * MM
    followers = []
    for (label, fol), m in zip(p.followers, d.motions):
        Rp = (p.radius + (fol.roller_radius if fol.kind == "roller" else 0.0)) * MM
        x = fol.offset * MM
        if fol.kind == "flat":
            y_eq = r"y = C_y + R"
            h_eq = rf"h = 2\varepsilon = {f(2 * ecc, 2)}\ \text{{mm}}"
            a_eq = r"\alpha = 0"
        else:
            y_eq = rf"y = C_y + \sqrt{{(R + r_r)^2 - (e - C_x)^2}}"
            h_eq = (rf"h = \sqrt{{(R + r_r + \varepsilon)^2 - e^2}} - \sqrt{{(R + r_r - \varepsilon)^2 - e^2}}"
                    rf" = \sqrt{{{f(Rp + ecc, 1)}^2 - {f(x, 1)}^2}} - \sqrt{{{f(Rp - ecc, 1)}^2 - "
                    rf"{f(x, 1)}^2}} = {f(m.stroke * MM, 2)}\ \text{{mm}}")
            a_eq = rf"\sin\alpha = \frac{{|e - C_x|}}{{R + r_r}},\quad R + r_r = {f(Rp, 1)}\ \text{{mm}}"
        followers.append({"label": md_text(label), "desc": _describe(fol, lang), "y": y_eq, "h": h_eq, "alpha": a_eq,
                          "stroke": f(m.stroke * MM, 2), "ymin": f(m.y_min * MM, 2),
                          "ymax": f(m.y_max * MM, 2),
                          "alpha_max": f(m.alpha_max * DEG, 2)})
    head = ["$\\delta$/°"] + [f"{md_text(label)} $s$/mm" for label, _ in p.followers] + \
        [f"{md_text(label)} $\\alpha$/°" for label, _ in p.followers]
    rows = []
    for i, delta in enumerate(d.table_delta):
        rows.append([f(delta * DEG, 1)] + [f(t.s[i] * MM, 2) for t in d.tables] +    # lengths to 0.01 mm
                    [f(t.pressure_angle[i] * DEG, 2) for t in d.tables])
    qrows = []
    for i, delta in enumerate(p.query_angles):
        qrows.append([f(delta * DEG, 1)] + [f"{f(q.s[i] * MM, 2)} / {f(q.pressure_angle[i] * DEG, 2)}°"
                                            for q in d.queries])
    return {
        "meta": md_meta(brief.report, lang), "fig": figures, "R": f(R, 1), "ecc": f(ecc, 1),
        "rotation": _("counter-clockwise") if p.rotation > 0 else _("clockwise"),
        "followers": followers, "table_head": head, "table_rows": rows,
        "table_align": "|".join(["--:"] * len(head)),
        "table_step": f(p.table_step * DEG, 1),
        "query_head": ["$\\delta$/°"] + [md_text(label) for label, _ in p.followers],
        "query_align": "|".join([":-:"] * (1 + len(p.followers))),
        "query_rows": qrows,
        **verification_context(r.get("disc_verification"), lang),
    }


_NOTE = N_("The checks do not use the closed forms: the displacement by inversion — the cam held "
           "still, the follower's line turned back through $\\delta$ and intersected with the disc (for "
           "a roller, the circle of radius $R + r_r$ on which its centre rolls); the pressure "
           "angle by the three-centre theorem — the relative pole $P$ of cam and follower lies on "
           "the line through $O$ perpendicular to the follower's line, $OP$ = $dy/d\\delta$ (central "
           "differences of the geometric displacement), and the common normal passes through $P$; "
           "the stroke from the extremes of the displacement (three-point parabola). Compared on "
           "every position of the 0.1° grid and at the given angles.")


def verification_context(v, lang: str) -> dict:
    """``verify_rows``, ``findings`` and ``verify_note`` of the verification section."""
    if v is None:
        return {"verify_rows": [], "findings": [], "verify_note": ""}
    from .stages import DISC_CHECK_NAMES

    _ = tr(lang)
    rows = []
    # the displacement differences are of the stroke's magnitude (rounding: fmt.residue)
    stroke = {k.detail.get("label"): k.reference for k in v.checks if k.key == "disc_stroke"}
    for k in v.checks:
        name = f"{md_text(k.detail.get('label', ''))} " + DISC_CHECK_NAMES[k.key][0 if _.zh else 1]
        ok = verdict(k.passed, lang)
        if k.key == "disc_s":
            value = residue(k.value * MM, stroke.get(k.detail.get("label"), 0.0) * MM)
            rows.append([name, f"{value} mm", f"≤ {e(k.limit * MM)} mm", ok])
        elif k.key == "disc_alpha":
            rows.append([name, f"{e(k.value * DEG)}°", f"≤ {e(k.limit * DEG)}°", ok])
        elif k.key == "disc_stroke":
            rows.append([name, f"{f(k.detail['stroke'] * MM, 3)} mm",
                         _("closed form h = {reference} mm", reference=f(k.reference * MM, 3)), ok])
        elif k.key == "disc_alpha_max":
            # (page review 51: the three checks were counted in the summary, not shown here)
            rows.append([name, f"{f(k.detail['top'] * DEG, 3)}°",
                         _("closed form $\\alpha_{{max}}$ = {reference}°", reference=f(k.reference * DEG, 3)), ok])
    return {"verify_rows": rows, "findings": [md_text(w.text(lang)) for w in v.warnings],
            "verify_note": _(_NOTE)}


def write_data(r: dict, folder: Path) -> list[Path]:
    d = r["disc"]
    path = folder / "disc_displacement.csv"
    with atomic_open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(["delta_deg"] + [f"s_mm[{label}]" for label, _ in d.params.followers] +
                   [f"alpha_deg[{label}]" for label, _ in d.params.followers])
        for i, delta in enumerate(d.table_delta):
            w.writerow([f"{delta * DEG:.4f}"] + [f"{t.s[i] * MM:.6f}" for t in d.tables] +
                       [f"{t.pressure_angle[i] * DEG:.6f}" for t in d.tables])
    return [path]
