"""Report of the `linkage` machine: the shared linkage section (:mod:`mechdesign.render.linkage_report`) for the brief's linkage."""
from __future__ import annotations

from pathlib import Path
from ...i18n import tr
import math

from ...render.fmt import exact, fluctuation, md_meta, md_text, sig
from ...render.labels import md_point, point_tex
from ...render.linkage_report import linkage_context, make_linkage_figures, verification_rows


def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    return make_linkage_figures(r["params"], r["linkage"], r["linkage_forces"],
                                r["linkage_flywheel"], fig_dir, lang)


def _g(x: float) -> str:
    """A given number as the brief writes it (no digits added: 100, 0.11, 95.5), to 10⁻⁶;
    five or more integer digits grouped, as in every table (12 000)."""
    return exact(x, None, decimals=6)


def data_rows(brief, lang: str) -> list[list[str]]:
    """The task's data, as the brief gives them (course units), for chapter 1's table
    (symbol, quantity, value, unit), as the machines with a named task list theirs (press,
    shaper): the crank, the frame points, every group's lengths, the masses, the
    resistances, the limits, the flywheel's [δ] and the positions the task asks for."""
    _ = tr(lang)
    lk, an = brief.linkage, brief.analysis
    ck = lk.crank

    def ln(a, b):
        return f"$l_{{{point_tex(a + b)}}}$"

    sense = _("clockwise") if ck.rotation == "cw" else _("counter-clockwise")
    # n to 4 significant digits and ω beside it: a textbook's ω = 10 rad/s is given as
    # n = 300/π rpm (95.49296585513721 in the brief)
    rows = [[ln(ck.pivot, ck.tip), _("crank {link}", link=md_text(ck.link)), _g(ck.length_mm), "mm"],
            ["$n$", _("crank speed ({sense})", sense=sense), sig(ck.speed_rpm, 4), _("rpm")],
            ["$\\omega$", _("crank angular velocity"), sig(ck.speed_rpm * math.pi / 30, 4), "rad/s"]]
    # the frame points in one row: "$O_2$, $O_4$ | (0, 0), (400, 0)"
    pts = lk.frame_points_mm
    rows.append([", ".join(md_point(n) for n in pts), _("frame points"),
                 ", ".join(f"({_g(x)}, {_g(y)})" for x, y in pts.values()), "mm"])
    for g in lk.groups:
        if g.type == "RRR":
            (b, d), c = g.ends, g.joint
            rows += [[ln(b, c), _("link {link}", link=md_text(g.links[0])), _g(g.lengths_mm[0]), "mm"],
                     [ln(d, c), _("link {link}", link=md_text(g.links[1])), _g(g.lengths_mm[1]), "mm"]]
        elif g.type == "RRP":
            rows += [[ln(g.end, g.joint), _("link {link}", link=md_text(g.links[0])), _g(g.length_mm), "mm"],
                     ["—", _("guide of slider {link}: through the point, direction from +$x$",
                             link=md_text(g.links[1])),
                      f"({_g(g.guide_point_mm[0])}, {_g(g.guide_point_mm[1])}), {_g(g.guide_angle_deg)}°",
                      "mm, °"]]
        elif g.type == "RPR":
            if g.offset_mm:
                rows.append(["$e$", _("offset of guide bar {link}", link=md_text(g.links[1])),
                             _g(g.offset_mm), "mm"])
        else:
            where = _g(g.distance_mm) + (f", {_g(g.angle_deg)}°" if g.angle_deg else "")
            rows.append([ln(g.origin, g.name), _("point {name} on link {link}", name=md_point(g.name),
                                                 link=md_text(g.link)), where,
                         "mm, °" if g.angle_deg else "mm"])
    for m in lk.masses:
        # a link's mass and its moment of inertia about the centre of mass in one row
        link, com, com_md = md_text(m.link), point_tex(m.com), md_point(m.com)
        if m.mass_kg and m.J_kgm2:
            rows.append([f"$m_{{{point_tex(m.link)}}}$, $J_{{{com}}}$",
                         _("mass of link {link} and its moment of inertia about its centre of mass {com}",
                           link=link, com=com_md), f"{_g(m.mass_kg)}, {_g(m.J_kgm2)}", "kg, kg·m²"])
        elif m.mass_kg:
            rows.append([f"$m_{{{point_tex(m.link)}}}$", _("mass of link {link} (centre of mass {com})",
                                                            link=link, com=com_md), _g(m.mass_kg), "kg"])
        elif m.J_kgm2:
            rows.append([f"$J_{{{com}}}$", _("moment of inertia of link {link} about its centre of mass",
                                             link=link), _g(m.J_kgm2), "kg·m²"])
    for r in lk.resistances:
        rows.append(["$F_r$", _("resistance on link {link} at {point}, {angle}° from +$x$: working / "
                                "return stroke", link=md_text(r.link), point=md_point(r.point),
                                angle=_g(r.direction_deg)), f"{_g(r.working_N)} / {_g(r.return_N)}", "N"])
        # where the working resistance acts, as a window of the output's displacement
        for window, unit in ((r.active_mm, "mm"), (r.active_deg, "°")):
            if window is not None:
                rows.append(["—", _("where the working resistance acts: output displacement from "
                                    "position 1"), f"{_g(window[0])} – {_g(window[1])}", unit])
    if lk.pressure_angle_max_deg is not None:
        rows.append(["$[\\alpha]$", _("allowed pressure angle (working stroke)"),
                     _g(lk.pressure_angle_max_deg), "°"])
    if lk.transmission_angle_min_deg is not None:
        rows.append(["$[\\gamma]$", _("allowed minimum transmission angle"),
                     _g(lk.transmission_angle_min_deg), "°"])
    if lk.flywheel is not None:
        rows.append(["$[\\delta]$", _("speed fluctuation"), fluctuation(lk.flywheel.fluctuation_delta), "—"])
    for deg in an.positions_deg:
        what = (_("position asked for: the crank's direction from +$x$") if an.positions_from == "x_axis"
                else _("position asked for: crank angle from position 1"))
        rows.append([f"$\\varphi_{{{point_tex(ck.link)}}}$" if an.positions_from == "x_axis" else "$\\varphi$",
                     what, _g(deg), "°"])
    return rows


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    _ = tr(lang)
    k, v = r["linkage"], r["linkage_verification"]
    lk = linkage_context(r["params"], k, r["linkage_forces"], r["linkage_flywheel"], v,
                         figures, lang, title=_.pgettext("linkage machine", "Linkage analysis"),
                         given="tbl:data")
    warnings = [md_text(w.text(lang)) for w in v.warnings]
    return {"meta": md_meta(brief.report, lang), "linkage": lk, "data_rows": data_rows(brief, lang),
            "asked_points": tr(lang).pgettext("list", ", ").join(md_point(p) for p in brief.analysis.points), "verify_rows": verification_rows(v, lang, k),
            "findings": warnings}


def animate(r: dict, path: Path, lang: str) -> Path:
    """GIF of the linkage over one revolution."""
    from ...render.animation import linkage_gif

    return linkage_gif(r["params"], r["linkage"], path, lang)
