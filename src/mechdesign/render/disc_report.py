"""Report of the eccentric-disc analysis (``machine: eccentric_cam``, exercises 7-1/7-2):
displacement and pressure angle of each follower, as curves and tables."""
from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

from . import cam_figures as cf
from .cam_report import CONTACT
from .fmt import f

DEG = 180.0 / np.pi
MM = 1e3

def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    d = r["disc"]
    named = [(label, m.s * MM, m.pressure_angle * DEG)
             for (label, _), m in zip(d.params.followers, d.motions)]
    cf.disc_curves(fig_dir / "disc_curves.png", lang, d.grid_delta * DEG, named)
    return {"curves": f"{fig_dir.name}/disc_curves.png"}


def _describe(fol, lang):
    zh = lang == "zh"
    contact = CONTACT[lang][fol.kind]
    if fol.offset == 0:
        where = "对心" if zh else "centred"
    else:
        side = ("右" if fol.offset > 0 else "左") if zh else ("right" if fol.offset > 0 else "left")
        where = (f"偏置 e = {f(abs(fol.offset) * MM, 1)} mm（{side}）" if zh
                 else f"offset e = {f(abs(fol.offset) * MM, 1)} mm ({side})")
    extra = ""
    if fol.kind == "roller":
        extra = f"，r_r = {f(fol.roller_radius * MM, 1)} mm" if zh else f", r_r = {f(fol.roller_radius * MM, 1)} mm"
    return f"{where}{contact}从动件{extra}" if zh else f"{where} {contact} follower{extra}"


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    d = r["disc"]
    p = d.params
    zh = lang == "zh"
    R, ecc = p.radius * MM, p.eccentricity * MM
    followers = []
    for (label, fol), m in zip(p.followers, d.motions):
        Rp = (p.radius + (fol.roller_radius if fol.kind == "roller" else 0.0)) * MM
        x = fol.offset * MM
        if fol.kind == "flat":
            y_eq = r"y = C_y + R"
            h_eq = rf"h = 2\varepsilon = {f(2 * ecc, 3)}\ \text{{mm}}"
            a_eq = r"\alpha = 0"
        else:
            y_eq = rf"y = C_y + \sqrt{{(R + r_r)^2 - (e - C_x)^2}}"
            h_eq = (rf"h = \sqrt{{(R + r_r + \varepsilon)^2 - e^2}} - \sqrt{{(R + r_r - \varepsilon)^2 - e^2}}"
                    rf" = \sqrt{{{f(Rp + ecc, 1)}^2 - {f(x, 1)}^2}} - \sqrt{{{f(Rp - ecc, 1)}^2 - "
                    rf"{f(x, 1)}^2}} = {f(m.stroke * MM, 4)}\ \text{{mm}}")
            a_eq = rf"\sin\alpha = \frac{{|e - C_x|}}{{R + r_r}},\quad R + r_r = {f(Rp, 1)}\ \text{{mm}}"
        followers.append({"label": label, "desc": _describe(fol, lang), "y": y_eq, "h": h_eq, "alpha": a_eq,
                          "stroke": f(m.stroke * MM, 4), "ymin": f(m.y_min * MM, 4),
                          "ymax": f(m.y_max * MM, 4),
                          "alpha_max": f(float(np.max(m.pressure_angle)) * DEG, 2)})
    head = ["δ/°"] + [f"{label} s/mm" for label, _ in p.followers] + \
        [f"{label} α/°" for label, _ in p.followers]
    rows = []
    for i, delta in enumerate(d.table_delta):
        rows.append([f(delta * DEG, 1)] + [f(t.s[i] * MM, 4) for t in d.tables] +
                    [f(t.pressure_angle[i] * DEG, 2) for t in d.tables])
    qrows = []
    for i, delta in enumerate(p.query_angles):
        qrows.append([f(delta * DEG, 1)] + [f"{f(q.s[i] * MM, 3)} / {f(q.pressure_angle[i] * DEG, 2)}°"
                                            for q in d.queries])
    return {
        "meta": brief.report, "fig": figures, "R": f(R, 1), "ecc": f(ecc, 1),
        "rotation": ("逆时针" if p.rotation > 0 else "顺时针") if zh else
                    ("counter-clockwise" if p.rotation > 0 else "clockwise"),
        "followers": followers, "table_head": head, "table_rows": rows,
        "table_align": "|".join(["--:"] * len(head)),
        "table_step": f(p.table_step * DEG, 1),
        "query_head": ["δ/°"] + [label for label, _ in p.followers],
        "query_align": "|".join([":-:"] * (1 + len(p.followers))),
        "query_rows": qrows,
    }


def write_data(r: dict, folder: Path) -> list[Path]:
    d = r["disc"]
    path = folder / "disc_displacement.csv"
    with path.open("w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(["delta_deg"] + [f"s_mm[{label}]" for label, _ in d.params.followers] +
                   [f"alpha_deg[{label}]" for label, _ in d.params.followers])
        for i, delta in enumerate(d.table_delta):
            w.writerow([f"{delta * DEG:.4f}"] + [f"{t.s[i] * MM:.6f}" for t in d.tables] +
                       [f"{t.pressure_angle[i] * DEG:.6f}" for t in d.tables])
    return [path]
