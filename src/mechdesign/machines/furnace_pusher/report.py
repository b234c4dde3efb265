"""Prepare the heating-furnace pusher report: figures and the template context (strings
and rows only). Report units are the course's (mm, °, rpm, N, N·m, W)."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ...i18n import N_, tr
from ...render import figures as fig
from ...render.legends import legend
from ...render.fmt import e, f, md_meta, md_text, sig, time_ratio
from ...render.fmt import factor_for, gives, product, residue, verdict
from ...numbers import half_sum_decimals
from ...render.labels import mpl_names, mpl_point

DEG = 180.0 / np.pi
MM = 1e3


# ------------------------------------------------------------------------------ figures

def _scheme(path: Path, lang: str, syn) -> None:
    """Left: the six-bar at its two extreme positions with C's arc and the slider guide.
    Right: the four-bar's θ-circle construction (B1, B2, O1 and the crank circle)."""
    from ...render.fonts import configure_matplotlib

    configure_matplotlib()
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    _ = tr(lang)
    figure, (left, right) = plt.subplots(1, 2, figsize=(7.0, 5.4), dpi=fig.DPI,
                                         gridspec_kw={"width_ratios": [1.0, 1.25]})
    try:
        R, c = syn.rocker_DC * MM, syn.rocker_DB * MM
        half = syn.swing / 2
        t = np.linspace(-1.5 * half, 1.5 * half, 120)
        o1 = syn.O1 * MM
        extremes = ((syn.B1, syn.C1, syn.A_fold, "C0"), (syn.B2, syn.C2, syn.A_ext, "C3"))
        for ax in (left, right):
            for radius in (R, c):
                ax.plot(radius * np.sin(t), radius * np.cos(t), color="0.7", lw=0.7, ls="--")
            for B, C, A, col in extremes:
                B, C, A = B * MM, C * MM, A * MM
                ax.plot([0, C.real], [0, C.imag], color=col, lw=1.6)
                ax.plot([A.real, B.real], [A.imag, B.imag], color=col, lw=1.1)
                ax.plot([o1.real, A.real], [o1.imag, A.imag], color=col, lw=2.2)
                ax.plot([B.real], [B.imag], "o", color=col, ms=3)
            ring = o1 + syn.crank * MM * np.exp(1j * np.linspace(0, 2 * np.pi, 100))
            ax.plot(ring.real, ring.imag, color="0.5", lw=0.6)
            for q in (0j, o1):
                ax.plot([q.real], [q.imag], "^", color="k", ms=6, zorder=4)
            ax.set_aspect("equal")
            ax.grid(True, lw=0.3, color="0.88")
            ax.set_xlabel("x (mm)")
        # Left: the slider at both extremes (E1 starts the working stroke).
        yg = syn.guide_height * MM
        c_start = syn.C1 if abs(abs(syn.E1 - syn.C1) - syn.link_CE) < 1e-9 * syn.link_CE else syn.C2
        c_end = syn.C2 if c_start is syn.C1 else syn.C1
        xs = np.array([syn.E1.real, syn.E2.real, syn.C1.real, syn.C2.real, syn.O1.real, 0.0]) * MM
        left.plot([xs.min() - 80, xs.max() + 80], [yg, yg], color="0.4", lw=0.8, ls="-.")
        blk = 14.0
        for C, E, col in ((c_start, syn.E1, "0.15"), (c_end, syn.E2, "0.55")):
            C, E = C * MM, E * MM
            left.plot([C.real, E.real], [C.imag, E.imag], color=col, lw=1.2)
            left.plot(E.real + blk * np.array([-1, 1, 1, -1, -1]),
                      yg + 0.6 * blk * np.array([-1, -1, 1, 1, -1]), color=col, lw=1.0)
        left.annotate("", xy=(syn.E2.real * MM, yg + 45), xytext=(syn.E1.real * MM, yg + 45),
                      arrowprops=dict(arrowstyle="->", color="C2"))
        left.text(0.5 * (syn.E1.real + syn.E2.real) * MM, yg + 60, "$H$", ha="center", fontsize=8,
                  color="C2")
        for name, q, dy in (("C1", c_start, -60), ("C2", c_end, -60), ("E1", syn.E1, 22),
                            ("E2", syn.E2, 22)):
            left.text(q.real * MM, q.imag * MM + dy, mpl_point(name), fontsize=7, ha="center")
        left.text(20, -50, mpl_point("D"), fontsize=8)
        left.text(o1.real + 20, o1.imag - 50, mpl_point("O1"), fontsize=8)
        left.set_xlim(xs.min() - 350, xs.max() + 200)
        left.set_ylim(-100, yg + 130)
        left.set_ylabel("y (mm)")
        left.set_title(_("six-bar at its two extremes"), fontsize=8)
        # Right: the θ-circle through B1, B2 on which O1 lies.
        B1, B2 = syn.B1 * MM, syn.B2 * MM
        chord = abs(B2 - B1)
        if syn.theta > 0:
            rad = chord / (2 * np.sin(syn.theta))
            mid, nrm = 0.5 * (B1 + B2), 1j * (B2 - B1) / chord
            h = np.sqrt(max(rad ** 2 - (chord / 2) ** 2, 0.0))
            centre = min((mid + h * nrm, mid - h * nrm), key=lambda z: abs(abs(z - o1) - rad))
            circ = centre + rad * np.exp(1j * np.linspace(0, 2 * np.pi, 300))
            right.plot(circ.real, circ.imag, color="C2", lw=0.9, ls=":")
            right.plot([centre.real], [centre.imag], "+", color="C2", ms=6)
            right.text(centre.real + 6, centre.imag + 6, _("$\\theta$-circle"), color="C2", fontsize=7)
        for name, q in (("B1", B1), ("B2", B2), (_("A (folded)"), syn.A_fold * MM),
                        (_("A (extended)"), syn.A_ext * MM)):
            right.text(q.real + 5, q.imag + 6, mpl_names(name), fontsize=7)
        right.text(o1.real + 6, o1.imag - 16, mpl_point("O1"), fontsize=8)
        pts = np.array([B1, B2, o1, syn.A_fold * MM, syn.A_ext * MM])
        pad = 0.45 * max(np.ptp(pts.real), np.ptp(pts.imag))
        right.set_xlim(pts.real.min() - pad, pts.real.max() + pad)
        right.set_ylim(pts.imag.min() - pad, pts.imag.max() + pad)
        right.set_title(_("four-bar $\\theta$-circle (blue: folded, red: extended)"), fontsize=8)
        fig.save_png(figure, path)
    finally:
        plt.close(figure)


def _design_chart(path: Path, lang: str, syn) -> None:
    """γ_min over the cycle and over the working stroke along the allowed arc, against the
    frame length; the limits and the chosen design."""
    _ = tr(lang)
    ps, g, gw, d = syn.scan
    with fig.figure(path, 1, (7.0, 3.4)) as (ax,):
        ax.plot(d * MM, g * DEG, color="C0", lw=1.4,
                label=_("$\\gamma_{min}$ over the cycle"))
        ax.plot(d * MM, gw * DEG, color="C1", lw=1.4,
                label=_("$\\gamma_{min}$ over the working stroke"))
        ax.axhline(syn.gamma_limit * DEG, color="C2", ls=":", lw=0.9,
                   label=f"[γ] = {syn.gamma_limit * DEG:.0f}°")
        if syn.limit_rocker:
            ax.axhline(90 - syn.alpha_limit * DEG, color="C3", ls="--", lw=0.9,
                       label=f"90° − [α] = {90 - syn.alpha_limit * DEG:.0f}°")
        ax.plot([syn.frame * MM], [syn.gamma_min * DEG], "o", color="C0", ms=5)
        ax.plot([syn.frame * MM], [syn.gamma_work * DEG], "o", color="C1", ms=5)
        ax.axvline(syn.frame * MM, color="0.5", lw=0.6)
        ax.set_ylim(0, 90)
        ax.set_xlabel(_("frame $l_{O_1D}$ (mm)"))
        ax.set_ylabel(_("transmission angle (°)"))
        ax.grid(True, lw=0.4, color="0.85")
        legend(ax, fontsize=7, loc="lower center", ncol=2)


def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    from ...render.linkage_report import make_linkage_figures

    syn = r["synthesis"]
    paths = {}

    def out(name):
        paths[name] = f"{fig_dir.name}/{name}.png"
        return fig_dir / f"{name}.png"

    _scheme(out("furnace_scheme"), lang, syn)
    _design_chart(out("furnace_chart"), lang, syn)
    paths.update(make_linkage_figures(r["model"], r["linkage"], r["linkage_forces"],
                                      r["linkage_flywheel"], fig_dir, lang))
    return paths


def animate(r: dict, path: Path, lang: str) -> Path:
    """GIF of the six-bar over one revolution."""
    from ...render.animation import linkage_gif

    return linkage_gif(r["model"], r["linkage"], path, lang)


# ------------------------------------------------------------------------------ context

def _ok(flag: bool, _) -> str:
    return verdict(flag, _.lang)


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    from ...render.linkage_report import linkage_context, verification_rows

    _ = tr(lang)
    p, syn, chk = r["params"], r["synthesis"], r["pusher_check"]
    pp, ps = p.pusher, brief.pusher
    k, frc, v = r["linkage"], r["linkage_forces"], r["linkage_verification"]
    n = k.grid_size
    H, R, L = syn.stroke * MM, syn.rocker_DC * MM, syn.link_CE * MM
    a, b, c, d = syn.crank * MM, syn.coupler * MM, syn.rocker_DB * MM, syn.frame * MM
    th, psi = syn.theta * DEG, syn.swing * DEG
    sag = syn.sagitta * MM
    chord = abs(syn.B2 - syn.B1) * MM
    o1b1, o1b2 = abs(syn.B1 - syn.O1) * MM, abs(syn.B2 - syn.O1) * MM
    # O₁B₁, O₁B₂ with the decimals that make (O₁B₂ ± O₁B₁)/2 no half unit of 0.01 mm (181.54 +
    # 79.79 = 261.33: 130.665 printed 130.66, review 38)
    nb = half_sum_decimals((o1b1, o1b2))
    lim = syn.alpha_limit * DEG
    sense = _("clockwise") if syn.sense < 0 else _("counter-clockwise")
    towards = "+$x$" if syn.working_direction > 0 else "−$x$"

    given = pp.given is not None
    sub = _(" (derived)") if given else ""
    data_rows = [
        ["$H$", _("slider stroke") + sub, f(H, 2) if given else f(ps.stroke_H_mm, 0), "mm"],
        ["$n$", _("strokes per minute (crank speed)"),
         f(ps.strokes_per_min, 0), "1/min"],
        ["$K$", _("time ratio") + sub,
         f(pp.time_ratio_K, 4) if given else f(ps.time_ratio_K, 2), "—"],
        ["$l_{DC}$", _("rocker $DC$"), f(ps.rocker_DC_mm, 0), "mm"],
        ["$l_{CE}$", _("link $CE$"), f(ps.link_CE_mm, 0), "mm"],
        ["$[\\alpha]$", _("largest pressure angle, working stroke"),
         f(ps.pressure_angle_max_deg, 0), "°"],
        ["$F_{r1}$", _("working-stroke resistance (incl. friction)"),
         f(ps.working_force_N, 0), "N"],
        ["$F_{r2}$", _("return-stroke resistance (incl. friction)"),
         f(ps.return_force_N, 0), "N"],
    ]
    if given:
        gd = ps.dimensions
        data_rows[3:3] = [[sym, _(name) + _(" (given)"), f(v, 3), "mm"]
                          for sym, name, v in (
                              ("$l_{O_1A}=a$", N_("crank"), gd.crank_O1A_mm),
                              ("$l_{AB}=b$", N_("coupler"), gd.coupler_AB_mm),
                              ("$l_{DB}=c$", N_("rocker (to $B$)"), gd.rocker_DB_mm),
                              ("$l_{O_1D}=d$", N_("frame"), gd.frame_O1D_mm))]
    choice_rows = [
        [_("crank rotation"), sense,
         _("the slow working stroke pushes towards {towards}", towards=towards)],
        ["$l_{DB}/l_{DC}$", f(ps.rocker_ratio_DB_DC, 3),
         _("where $B$ sits on the rocker: sets the four-bar's size, not its angles")],
        ["$l_{O_1D}$", _("auto (optimised)") if pp.frame is None
         else f(pp.frame * MM, 2) + " mm",
         _("maximise $\\gamma_{min}$ over the cycle, the pressure angle at $B$ within "
            "$[\\alpha]$ in the working stroke")
         if pp.frame is None else (_("frame given"))],
    ]
    if given:
        choice_rows = choice_rows[:1]
    choice_rows += [
        ["$e$", f(pp.guide_offset * MM, 2) + " mm",
         _("guide offset from the middle of the sagitta of $C$'s arc")],
        ["$[\\gamma]$", f(ps.transmission_angle_min_deg, 0) + "°",
         _("smallest acceptable transmission angle")],
    ]
    cos_h = np.cos(syn.swing / 2)
    sag_txt = f(sag, 2 if round(float(f(sag, 2)) * 100) % 2 == 0 else 3)
    one_minus_cos = factor_for(1 - cos_h, lambda x: gives(float(f(R, 0)) * x, sag_txt))
    given_eq = None
    if given:
        l_dc = f(R, 0) if abs(R - round(R)) < 1e-9 else f(R, 2)      # as the brief gives it

        def ang(x, y, z):
            return float(np.degrees(np.arccos(np.clip((x * x + y * y - z * z) / (2 * x * y), -1, 1))))
        given_eq = {
            "theta": (rf"\theta = \left\lvert\arccos\frac{{(b-a)^2 + d^2 - c^2}}{{2(b-a)d}} - "
                      rf"\arccos\frac{{(b+a)^2 + d^2 - c^2}}{{2(b+a)d}}\right\rvert"),
            "theta_n": (rf"\theta = \lvert {f(ang(b - a, d, c), 2)}° - {f(ang(b + a, d, c), 2)}°\rvert = "
                        rf"{f(th, 2)}°"),
            "psi": (rf"\psi = \arccos\frac{{d^2 + c^2 - (b+a)^2}}{{2dc}} - \arccos\frac{{d^2 + c^2 - (b-a)^2}}{{2dc}}"),
            "psi_n": rf"\psi = {f(ang(d, c, b + a), 2)}° - {f(ang(d, c, b - a), 2)}° = {f(psi, 2)}°",
            "K": rf"K = \frac{{180° + \theta}}{{180° - \theta}} = {time_ratio(pp.time_ratio_K)}",
            "H": (rf"H = 2\,l_{{DC}}\sin\frac{{\psi}}{{2}} = 2 \times {l_dc} \times \sin {f(psi / 2, 2)}° = "
                  rf"2 \times {l_dc} \times {sig(np.sin(syn.swing / 2), 4, group=False)} = {f(H, 2)}\ \text{{mm}}"),
        }
    eq = {
        "psi": (rf"\psi = 2\arcsin\frac{{H}}{{2\,l_{{DC}}}} = 2\arcsin\frac{{{f(H, 0)}}}{{2 \times {f(R, 0)}}}"
                rf" = {f(psi, 2)}°"),
        "theta": (rf"\theta = 180° \times \frac{{K-1}}{{K+1}} = 180° \times \frac{{{f(pp.time_ratio_K, 2)}-1}}"
                  rf"{{{f(pp.time_ratio_K, 2)}+1}} = {f(th, 2)}°"),
        # f to 0.01 mm, 0.001 mm where f/2 of f to 0.01 mm ends in half a unit (5.27/2: y_g =
        # 1150 − 2.635 printed 1147.36, review 38), 1 − cos(ψ/2) with the digits that give it;
        # 1 - cos(ψ/2) itself to 4 significant digits (the difference of two numbers near 1
        # would need six decimals); y_g through f: (1 + cos)/2 = 1 - (1 - cos)/2
        "sagitta": (rf"f = l_{{DC}}\left(1-\cos\frac{{\psi}}{{2}}\right) = {f(R, 0)} \times (1 - \cos {f(psi / 2, 2)}°)"
                    rf" = {f(R, 0)} \times {one_minus_cos} = {sag_txt}\ \text{{mm}}"),
        "guide": (rf"y_g = l_{{DC}}\,\frac{{1+\cos(\psi/2)}}{{2}} + e = l_{{DC}} - \frac{{f}}{{2}} + e = {f(R, 0)} - "
                  rf"\frac{{{sag_txt}}}{{2}} + {f(syn.guide_offset * MM, 2)} = {f(syn.guide_height * MM, 2)}\ \text{{mm}}"),
        "alphaE": (rf"\alpha_{{E,max}} = \arcsin\frac{{f/2 + \lvert e\rvert}}{{l_{{CE}}}} = \arcsin\frac{{{f(sag / 2, 2)} + "
                   rf"{f(abs(syn.guide_offset) * MM, 2)}}}{{{f(L, 0)}}} = {f(syn.alpha_E * DEG, 2)}°"),
        "band": (rf"\lvert e\rvert \le l_{{CE}}\sin[\alpha] - \frac{{f}}{{2}} = {f(L, 0)} \times \sin {f(lim, 0)}° - "
                 rf"{f(sag / 2, 2)} = {f(syn.guide_offset_max * MM, 2)}\ \text{{mm}}"),
        "db": (rf"l_{{DB}} = {f(pp.rocker_ratio, 3)}\,l_{{DC}} = {f(c, 2)}\ \text{{mm}}, \quad "
               if not given else rf"l_{{DB}} = {f(c, 2)}\ \text{{mm}}, \quad "
               rf"B_1B_2 = 2\,l_{{DB}}\sin\frac{{\psi}}{{2}} = {f(chord, 2)}\ \text{{mm}}"),
        "radius": (rf"r_\theta = \frac{{B_1B_2}}{{2\sin\theta}} = \frac{{{f(chord, 2)}}}{{2\sin {f(th, 2)}°}}"
                   rf" = {f(chord / (2 * np.sin(syn.theta)), 2) if syn.theta > 0 else '∞'}\ \text{{mm}}"),
        "a": (rf"a = \frac{{O_1B_2 - O_1B_1}}{{2}} = \frac{{{f(o1b2, nb)} - {f(o1b1, nb)}}}{{2}} = {f(a, 2)}\ "
              rf"\text{{mm}}"),
        "b": (rf"b = \frac{{O_1B_2 + O_1B_1}}{{2}} = \frac{{{f(o1b2, nb)} + {f(o1b1, nb)}}}{{2}} = {f(b, 2)}\ "
              rf"\text{{mm}}, \quad d = O_1D = {f(d, 2)}\ \text{{mm}}"),
        "eq1": r"B_1B_2^2 = (b-a)^2 + (b+a)^2 - 2(b-a)(b+a)\cos\theta",
        "eq1n": (rf"{f(o1b1, nb)}^2 + {f(o1b2, nb)}^2 - 2 \times {f(o1b1, nb)} \times {f(o1b2, nb)} "
                 rf"\cos {f(th, 2)}° = {sig(chord ** 2, group=False)} = {f(chord, 2)}^2"),
        "delta": r"\cos\delta = \frac{b^2 + c^2 - (d \mp a)^2}{2bc}, \quad \gamma = \min(\delta,\ 180° - \delta)",
        "gamma": (rf"\gamma_{{min}} = {f(syn.gamma_min * DEG, 2)}°, \quad "
                  rf"\gamma_{{max}} = {f(syn.gamma_max * DEG, 2)}°"),
        # γ′_min: the least transmission angle on the working stroke (page review 47: the
        # English subscript "work,min" in the zh report, and never said)
        "gwork": (rf"\alpha_B = 90° - \gamma'_{{min}} = 90° - {f(syn.gamma_work * DEG, 2)}° = "
                  rf"{f(syn.alpha_B * DEG, 2)}°"),
        "torque": r"M_b\,\omega = F_r\,\lvert v_E\rvert \quad\Rightarrow\quad M_b = \frac{F_r\,\lvert v_E\rvert}{\omega}",
        "hand": (rf"\bar P = \frac{{(F_{{r1}} + F_{{r2}})\,H\,n}}{{60}} = \frac{{({f(pp.working_force, 0)} + "
                 rf"{f(pp.return_force, 0)}) \times {f(pp.stroke, 3)} \times {f(pp.crank_speed_rpm, 0)}}}{{60}}"
                 rf" = {sig(chk.hand_power, group=False)}\ \text{{W}}"),
        "mean": (rf"\bar P = \bar M_b\,\omega = {product((chk.mean_torque, abs(pp.crank_omega)), sig(chk.mean_power, 4, group=False))}"
                 rf" = {sig(chk.mean_power, 4, group=False)}\ \text{{W}}"),
    }
    # the rule's digits (0.01 mm, 0.01°) as the equations write them (d = 541.00 mm, issue 19)
    syn_rows = [
        ["$\\theta$", _("extreme-position angle"), f(th, 2), "°"],
        ["$\\psi$", _("rocker swing"), f(psi, 2), "°"],
        ["$l_{O_1A}=a$", _("crank"), f(a, 2), "mm"],
        ["$l_{AB}=b$", _("coupler"), f(b, 2), "mm"],
        ["$l_{DB}=c$", _("rocker (to $B$)"), f(c, 2), "mm"],
        ["$l_{DC}$", _("rocker (to $C$)"), f(R, 2), "mm"],
        ["$l_{O_1D}=d$", _("frame"), f(d, 2), "mm"],
        ["$O_1$", _("crank pivot ($D$ the origin)"),
         f"({f(syn.O1.real * MM, 2)}, {f(syn.O1.imag * MM, 2)})", "mm"],
        ["$l_{CE}$", _("link $CE$"), f(L, 2), "mm"],
        ["$y_g$", _("slider guide above $D$"), f(syn.guide_height * MM, 2), "mm"],
        ["$\\gamma_{min}$", _("four-bar minimum transmission angle"),
         f(syn.gamma_min * DEG, 2), "°"],
        ["$\\alpha_B$", _("largest pressure angle at $B$, working stroke"),
         f(syn.alpha_B * DEG, 2), "°"],
        ["$\\alpha_E$", _("largest pressure angle at $E$, working stroke"),
         f(syn.alpha_E * DEG, 2), "°"],
    ]
    names = {"stroke": N_("stroke"), "chord": N_("chord"), "eq1": N_("the original report's equation (1)"),
             "folded": N_("folded extreme"), "extended": N_("extended extreme"),
             "frame": N_("frame"), "theta": N_("extreme angle"), "K": "$K$"}
    res_rows = [[_(names[nm]), f"${eqn}$", residue(val)] for nm, eqn, val in syn.residuals]
    sd = syn.seed
    seed_rows = [
        [_("(1) as printed: $(a+b)^2+(b-a)^2-2(a+b)(b-a)\\cos 30° = B_1B_2^2$"),
         f"{f(sd.chord_printed * MM, 2)}²", f"{f(sd.chord * MM, 2)}²",
         f(sd.eq1_printed * 1e6, 0, group=True) + " mm²"],
        [_("(1) with the correct $\\theta$ = ") + f"{f(th, 0)}°",
         f"{f(sd.chord_correct * MM, 2)}²", f"{f(sd.chord * MM, 2)}²",
         f(sd.eq1_correct * 1e6, 0, group=True) + " mm²"],
        [_("(2) as printed: $\\arccos\\frac{b^2+1150^2-(a+505.37)^2}{2300\\,b} + 30° = 180°$"),
         f(sd.eq3_lhs * DEG, 2) + "°", "180°", f((sd.eq3_lhs - np.pi) * DEG, 2) + "°"],
    ]
    seed_sim_rows = [
        # by the rule: K to 0.001, angles to 0.01° (review33: 4/3/3 decimals in one table)
        ["$K$", time_ratio(sd.time_ratio), time_ratio(pp.time_ratio_K)],
        ["$\\theta$ /°", f(sd.theta * DEG, 2), f(th, 2)],
        ["$\\psi$ /°", f(sd.swing * DEG, 2), f(psi, 2)],
        [_("chord of $C$ (≈ the stroke) / mm"),
         f(sd.stroke_C * MM, 2), f(H, 2 if given else 0)],
        ["$\\gamma_{min}$ /°", f(sd.gamma_min * DEG, 2), "≥ " + f(syn.gamma_limit * DEG, 0)],
    ]
    side_txt = _({
        1: N_("$O_1$ on $D$'s side of the chord $B_1B_2$ (the textbook's $\\theta$-circle)"),
        -1: N_("$O_1$ beyond the chord $B_1B_2$ (the mirror $\\theta$-circle)"),
    }[syn.side])
    if syn.criterion == "max_gamma":
        if syn.constraint_active:
            crit = _("the limit at $B$ is active: $O_1$ sits where the working-stroke transmission angle "
                      "is exactly {lim}°; without it the best $\\gamma_{{min}}$ would be "
                      "{gamma_unconstrained}°.", lim=f(90 - lim, 0),
                      gamma_unconstrained=f(syn.gamma_unconstrained * DEG, 2))
        elif not syn.limit_rocker:
            crit = _("the pressure angle at $B$ is not limited.")
        else:
            crit = _("the limit at $B$ is not active at the optimum (the unconstrained maximum of "
                      "$\\gamma_{min}$ meets it).")
        best = f(syn.gamma_other_side_free * DEG, 2)
        other = (_("On the other $\\theta$-circle the best $\\gamma_{{min}}$ is only {best}°, and it cannot "
                   "meet the limit at $B$.", best=best)
                 if syn.limit_rocker and syn.gamma_other_side == 0 else
                 _("On the other $\\theta$-circle the best $\\gamma_{{min}}$ is only {best}°.", best=best))
    elif syn.criterion == "given":
        crit = _("the dimensions are the brief's, no synthesis: $O_1$ is where the circle of "
                  "radius d about D cuts the circle of radius b − a about $B_1$, on the $\\theta$-circle "
                  "(the best $\\gamma_{{min}}$ on the same $\\theta$-circle would be "
                  "{gamma_unconstrained}°).",
                  gamma_unconstrained=f(syn.gamma_unconstrained * DEG, 2))
        other = ""
    else:
        crit = _("the frame is given: $O_1$ is where the circle of radius d about D cuts the "
                  "$\\theta$-circle.")
        other = ""
    # Torque: kinetostatics against virtual work at the positions.
    labels = [lab.replace("'", "′") for lab in k.positions.labels]
    torque_rows = []
    for i, label in enumerate(labels):
        j = n + i
        torque_rows.append([label, f(k.phase[j] * DEG, 2), f(k.v[j], 4), f(chk.resistance_force[j], 0),
                            f(frc.balancing_torque[j], 4), f(chk.virtual_work_torque[j], 4)])
    lk = linkage_context(r["model"], k, frc, r["linkage_flywheel"], v, figures, lang,
                         title=_("Kinematics and crank driving torque"))
    drive = None
    if r.get("drive") is not None:
        from ...render.drive_report import drive_context

        pw = (rf"P_w = \bar M_b\,\omega = {product((chk.mean_torque, abs(pp.crank_omega)), sig(chk.mean_power, 4, group=False))}"
              rf" = {sig(chk.mean_power, 4, group=False)}\ \text{{W}}")
        drive = drive_context(r["drive"], lang, figures, pw)
        drive["peak"] = None        # no flywheel: the note is in this report's own text
    tol = 1e-6
    verify_rows = [
        [_("simulated stroke (position search) / mm"),
         # by the number rule (0.01 mm, K 0.001, 0.01°)
         f(chk.stroke * MM, 2), f"H = {f(H, 2 if given else 0)}", _ok(abs(chk.stroke_error) <= tol * pp.stroke, _)],
        [_("simulated time ratio $K$"), f(chk.time_ratio, 3),
         f(pp.time_ratio_K, 3 if given else 2), _ok(abs(chk.time_ratio - pp.time_ratio_K) <= tol, _)],
        [_("largest pressure angle at $E$, working stroke / °"),
         f(chk.alpha_E_work * DEG, 2), _("≤ {lim} (synthesis: {value})", lim=f(lim, 0),
                                         value=f(syn.alpha_E * DEG, 2)), _ok(chk.alpha_E_work <= syn.alpha_limit + 1e-9, _)],
        [_("largest pressure angle at $B$, working stroke / °"),
         f(chk.alpha_B_work * DEG, 2),
         _("≤ {lim} (synthesis: {value})", lim=f(lim, 0), value=f(syn.alpha_B * DEG, 2)) if pp.limit_rocker
         else _("— (synthesis: {value})", value=f(syn.alpha_B * DEG, 2)),
         _ok(chk.alpha_B_work <= syn.alpha_limit + 1e-9, _) if pp.limit_rocker else "—"],
        [_("four-bar minimum transmission angle / °"),
         f(chk.gamma_min * DEG, 2), _("≥ {lim} (synthesis: {value})", lim=f(syn.gamma_limit * DEG, 0),
                                      value=f(syn.gamma_min * DEG, 2)),
         _ok(chk.gamma_min >= syn.gamma_limit - 1e-9, _)],
        [_("mean driving power $\\bar M_b\\,\\omega$ / W"),
         sig(chk.mean_power),
         _("mean resistance power {resistance_power}; by hand {hand_power}",
            resistance_power=sig(chk.resistance_power), hand_power=sig(chk.hand_power)),
         _ok(abs(chk.mean_power - chk.hand_power) <= 1e-4 * chk.hand_power, _)],
        [_("$M_b$ vs virtual work $F_r\\lvert v_E\\rvert/\\omega$ (relative)"),
         e(chk.virtual_work_error), "≤ 10⁻⁹", _ok(chk.virtual_work_error <= 1e-9, _)],
    ] + verification_rows(v, lang)      # its position search: the first two rows (review45)
    # A bare "|" would split a pipe-table cell: escape it (math uses \lvert … \rvert).
    verify_rows = [[cell.replace("|", "\\|") for cell in row] for row in verify_rows]
    findings = [md_text(w.text(lang)) for key in ("synthesis", "linkage_verification", "pusher_check")
                for w in (getattr(r[key], "warnings", ()) or ())]
    return {
        "meta": md_meta(brief.report, lang), "fig": figures, "data_rows": data_rows, "choice_rows": choice_rows,
        "eq": eq, "syn_rows": syn_rows, "res_rows": res_rows, "seed_rows": seed_rows,
        "seed_sim_rows": seed_sim_rows, "side": side_txt, "criterion": crit, "other_side": other,
        "sense": sense, "towards": towards, "linkage": lk, "torque_rows": torque_rows,
        "drive": drive, "verify_rows": verify_rows, "findings": findings,
        "H": f(H, 2 if given else 0), "n": f(pp.crank_speed_rpm, 0),
        "K": time_ratio(pp.time_ratio_K) if given else f(pp.time_ratio_K, 2), "given": given_eq,
        "DC": f(R, 0), "CE": f(L, 0), "lim": f(lim, 0), "gam_lim": f(syn.gamma_limit * DEG, 0),
        "lim_B": f(90 - lim, 0), "limit_rocker": pp.limit_rocker,
        "gamma_min": f(syn.gamma_min * DEG, 2), "alpha_B": f(syn.alpha_B * DEG, 2),
        "alpha_E": f(syn.alpha_E * DEG, 2),
        "seed_a": f(sd.crank * MM, 2), "seed_b": f(sd.coupler * MM, 2),
        "seed_d": f(sd.frame * MM, 2), "seed_c": f(sd.rocker * MM, 0), "seed_chord": f(sd.chord * MM, 2),
        "mean_torque": sig(chk.mean_torque), "mean_power": sig(chk.mean_power),
        "peak_torque": sig(chk.peak_torque), "peak_factor": sig(chk.peak_factor),
        "hand_power": sig(chk.hand_power), "seed_power": sig(2 * pp.working_force * pp.stroke
                                                              * pp.crank_speed_rpm / 60.0),
    }
