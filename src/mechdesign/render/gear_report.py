"""Gear section of a report (齿轮设计及啮合图): the dimension table, the formulas with
numbers, the undercut and contact-ratio checks and the meshing drawing."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..i18n import tr
from .fmt import f, length, md_text, sig

DEG = 180.0 / np.pi
MM = 1e3



def _ratio_for(b1b2: float, pb: float) -> tuple[str, str]:
    """B1B2 and p_b [mm] with the digits that give the printed ε = B1B2/p_b (24.16/14.76 gives
    1.6369, printed 1.636: the quotient's numbers carry the digits it was computed from); the
    line prints B1B2 with these digits on both sides (not 24.16 mm then 24.155/14.761)."""
    from ..numbers import factors_for, significant

    top, bottom = factors_for((b1b2 * MM, pb * MM), lambda a, b: a / b, sig(b1b2 / pb, group=False),
                              tuple(significant(f(x * MM, 2)) for x in (b1b2, pb)))
    return top, bottom


def make_gear_figures(g, fig_dir: Path, lang: str) -> dict[str, str]:
    from .gear_figures import meshing_drawing

    meshing_drawing(fig_dir / "gear_mesh.png", lang, g.drawing)   # the drawing is in mm
    return {"gear_mesh": f"{fig_dir.name}/gear_mesh.png"}


def gear_context(g, lang: str, figures: dict[str, str]) -> dict:
    p = g.pair
    g1, g2 = p.g1, p.g2
    _ = tr(lang)
    shifted = bool(g1.x or g2.x)

    def both(a, b, digits=None):
        """The two gears' values: a length [mm] by the rule (``digits`` None: 0.01 mm, as the
        gear sheet), any other quantity to ``digits`` decimals."""
        return [length(a), length(b)] if digits is None else [f(a, digits), f(b, digits)]

    rows = [
        [_("teeth"), "$z$", "—", str(g1.z), str(g2.z), "—"],
        [_("module"), "$m$", "—", *both(p.m * MM, p.m * MM, 2), "mm"],
        [_("pressure angle"), "$\\alpha$", "—", *both(p.alpha * DEG, p.alpha * DEG, 2), "°"],   # 0.01° as α′
        [_("profile shift"), "$x$", "—", *both(g1.x, g2.x, 3), "—"],
        [_.pgettext("gear table", "pitch diameter"), "$d$", "$mz$", *both(g1.d * MM, g2.d * MM), "mm"],
        [_("addendum"), "$h_a$", "$(h_a^*+x-\\Delta y)m$", *both(g1.ha * MM, g2.ha * MM), "mm"],
        [_("dedendum"), "$h_f$", "$(h_a^*+c^*-x)m$", *both(g1.hf * MM, g2.hf * MM), "mm"],
        [_("tooth depth"), "$h$", "$h_a+h_f$", *both((g1.ha + g1.hf) * MM, (g2.ha + g2.hf) * MM), "mm"],
        [_("tip diameter"), "$d_a$", "$d+2h_a$", *both(g1.da * MM, g2.da * MM), "mm"],
        [_("root diameter"), "$d_f$", "$d-2h_f$", *both(g1.df * MM, g2.df * MM), "mm"],
        [_("base diameter"), "$d_b$", "$d\\cos\\alpha$", *both(g1.db * MM, g2.db * MM), "mm"],
        [_("circular pitch"), "$p$", "$\\pi m$", *both(p.p * MM, p.p * MM), "mm"],
        [_("base pitch"), "$p_b$", "$p\\cos\\alpha$", *both(p.pb * MM, p.pb * MM), "mm"],
        [_("tooth thickness"), "$s$", "$m(\\pi/2+2x\\tan\\alpha)$", *both(g1.s * MM, g2.s * MM), "mm"],
        [_("space width"), "$e$", "$p-s$", *both(g1.e * MM, g2.e * MM), "mm"],
        [_("tip pressure angle"), "$\\alpha_a$", "$\\arccos(d_b/d_a)$",
         *both(g1.alpha_a * DEG, g2.alpha_a * DEG, 2), "°"],
        [_("tip thickness"), "$s_a$", "$s\\frac{r_a}{r}-2r_a(\\mathrm{inv}\\,\\alpha_a-\\mathrm{inv}\\,\\alpha)$",
         *both(g1.sa * MM, g2.sa * MM), "mm"],
    ]
    pair_rows = [
        [_("standard centre distance"), "$a$", "$m(z_1+z_2)/2$", length(p.a * MM), "mm"],
        [_("working pressure angle"), "$\\alpha'$", "$\\mathrm{inv}\\,\\alpha' = \\frac{2(x_1+x_2)\\tan\\alpha}{z_1+z_2}+\\mathrm{inv}\\,\\alpha$",
         f(p.alpha_work * DEG, 2), "°"],        # angles to 0.01° (the sheet too)
        [_("working centre distance"), "$a'$", "$a\\cos\\alpha/\\cos\\alpha'$", length(p.a_work * MM), "mm"],
        [_("clearance"), "$c$", "$a'-r_{a1}-r_{f2}$", length(p.clearance * MM), "mm"],
        [_("ratio"), "$i_{12}$", "$z_2/z_1$", sig(p.ratio, 4), "—"],
        [_("length of action"), "$\\overline{B_1B_2}$",
         "$\\varepsilon\\, p_b$", length(p.action_length * MM), "mm"],
        [_("contact ratio"), "$\\varepsilon_\\alpha$", _("see below"), f(p.contact_ratio, 3), "—"],   # as eq. and sheet
    ]
    tw = np.tan(p.alpha_work)
    limit = 2 * p.ha_star / np.sin(p.alpha) ** 2       # the exact limit; z_min is it rounded
    b1b2 = g.drawing.action_length   # |B1B2| from the points on the line of action
    top, bottom = _ratio_for(b1b2, p.pb)
    eq = {
        # the general form and the numbers on two lines: one line runs past the margin
        "eps": rf"\varepsilon_\alpha = \frac{{z_1(\tan\alpha_{{a1}}-\tan\alpha')+z_2(\tan\alpha_{{a2}}-\tan\alpha')}}{{2\pi}}",
        "eps_num": (rf"\varepsilon_\alpha = \frac{{{g1.z}\times({f(np.tan(g1.alpha_a), 4)}-{f(tw, 4)})+{g2.z}\times"
                    rf"({f(np.tan(g2.alpha_a), 4)}-{f(tw, 4)})}}{{2\pi}} = {f(p.contact_ratio, 3)}"),
        "b1b2": (rf"\overline{{B_1B_2}} = \sqrt{{r_{{a1}}^2-r_{{b1}}^2}}+\sqrt{{r_{{a2}}^2-r_{{b2}}^2}}-a'\sin\alpha'"
                 rf" = {top}\ \text{{mm}}, \quad \frac{{\overline{{B_1B_2}}}}{{p_b}} = "
                 rf"\frac{{{top}}}{{{bottom}}} = {sig(b1b2 / p.pb, group=False)}"),
        "zmin": (rf"z_{{min}} = \frac{{2h_a^*}}{{\sin^2\alpha}} = \frac{{2\times{f(p.ha_star, 2)}}}"
                 rf"{{\sin^2 {f(p.alpha * DEG, 1)}°}} = {f(limit, 2)} \approx {f(p.z_min, 0)}, \quad x_{{min}} = "
                 rf"h_a^*\frac{{z_{{min}}-z}}{{z_{{min}}}}, \quad x_{{min,1}} = {f(p.x_min1, 3)},\ "
                 rf"x_{{min,2}} = {f(p.x_min2, 3)}"),
    }
    undercut = [w for w in g.warnings if w.code == "undercut"]
    # a gear at or above the textbook's z_min but below the exact limit 2h_a*/sin²α: its rack
    # tip line passes the limit point N by (h_a* − z sin²α/2 − x) m; the mating tip's lowest
    # contact point on it, r = √(r_b² + N B²), shows whether the cut involute is ever used
    slight = []
    for gd, other, x_min in ((g1, g2, p.x_min1), (g2, g1, p.x_min2)):
        depth = (p.ha_star - gd.z * np.sin(p.alpha) ** 2 / 2 - gd.x) * p.m
        if depth > 0 and gd.x >= x_min - 1e-9:
            nb = p.a_work * np.sin(p.alpha_work) - np.sqrt((other.da / 2) ** 2 - (other.db / 2) ** 2)
            slight.append({"z": str(gd.z), "depth": f(depth * MM, 3), "rb": f(gd.db / 2 * MM, 2),
                           "r": f(np.hypot(gd.db / 2, nb) * MM, 2)})
    # the checks the chapter states (its verdict sentence), for the summary's verdict table:
    # each passes unless the stage found the matching problem
    codes = {w.code for w in g.warnings}
    checks = [[_("no undercut"), "undercut" not in codes],
              [_("tip thickness ≥ 0.25 $m$"), "pointed" not in codes],
              [_("contact ratio $\\varepsilon \\ge$ 1.2 (continuous transmission)"), "contact_ratio" not in codes]]
    return {
        "checks": checks,
        "rows": rows, "pair_rows": pair_rows, "eq": eq, "shifted": shifted,
        # height modification (x1 + x2 = 0): standard centre distance and pressure angle kept
        "height_mod": shifted and abs(g1.x + g2.x) < 1e-12,
        "z1": str(g1.z), "z2": str(g2.z), "m": f(p.m * MM, 2), "eps": f(p.contact_ratio, 3),
        "zmin": f(p.z_min, 0), "undercut": bool(undercut), "slight": slight,
        "warnings": [md_text(w.text(lang)) for w in g.warnings],
        "fig": figures,
    }
