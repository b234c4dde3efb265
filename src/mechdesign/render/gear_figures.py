"""The gear meshing drawing (齿轮啮合图) with generated involute teeth, in the layout of
:func:`mechdesign.core.gears.mesh_layout` (O1 at the origin, O2 straight above, gear 1
driving counter-clockwise), as the gear stage computed it (``GearDrawing``). Lengths in mm."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..i18n import N_
from ..stages.gear import GearDrawing
from .figures import cached, figure
from .labels import LabelTable, mpl_point

LABELS = LabelTable({
    "title": N_("Gear meshing drawing"),
    "pitch": N_("pitch circle"),
    "ref": N_("reference circle"),
    "base": N_("base circle"),
    "tip": N_("tip circle"),
    "root": N_("root circle"),
    "action": N_("line of action $N_1N_2$"),
    "actual": N_("actual contact $B_1B_2$"),
    "drive": N_(r"driver $\omega_1$"),
    "x": "x (mm)",
    "y": "y (mm)",
})


@cached
def meshing_drawing(path: Path, lang: str, drawing: GearDrawing, title: str | None = None):
    """Both gears with their generated involute teeth around the mesh, their pitch, base,
    tip and root circles, the centres and the line of centres (O2, far above, is marked by
    an arrow with a'), the pitch point P, the line of action N1N2, the actual contact B1B2
    (bold), the working pressure angle α' (at P and as ∠PO1N1) and the contact ratio
    ε = B1B2 / pb in a box. The view is cut to the mesh region."""
    lab = LABELS[lang]
    lay = drawing.layout
    pair = drawing.pair
    g1, g2, m = pair.g1, pair.g2, pair.m
    P, u, aw = lay.p, lay.direction, pair.alpha_work
    shifted = any(abs(w - g.d / 2) > 1e-6 * m for w, g in ((lay.r1w, g1), (lay.r2w, g2)))
    left, right = lay.n2.real - 3 * m, max(lay.n1.real, lay.b2.real) + 5 * m
    bottom, top = -2 * m, lay.n2.imag + 3.5 * m
    from matplotlib.collections import PolyCollection

    with figure(path, 1, (6.4, 6.6), sharex=False) as (ax,):
        plot = lambda z, *a, **k: ax.plot(np.real(z), np.imag(z), *a, **k)  # noqa: E731
        circle = np.exp(1j * np.linspace(0, 2 * np.pi, 1500))
        styles = {"pitch": dict(color="C0", lw=0.8, ls="-."), "ref": dict(color="C0", lw=0.6, ls=":"),
                  "base": dict(color="C2", lw=0.7, ls="--"), "tip": dict(color="0.5", lw=0.6)}
        for centre, gear, r_w in ((lay.o1, g1, lay.r1w), (lay.o2, g2, lay.r2w)):
            radii = {"pitch": r_w, "base": gear.db / 2, "tip": gear.da / 2, "root": gear.df / 2}
            if shifted:
                radii["ref"] = gear.d / 2
            for key, rad in radii.items():
                plot(centre + rad * circle, **styles.get(key, styles["tip"]))
        for outline, tint in zip(drawing.outlines, ("#d6e4f2", "#f4e2c8")):
            # a collection, not ax.fill: fill's patch would have its thousands of
            # segments measured one by one for the data limits, which are set below
            ax.add_collection(PolyCollection([np.column_stack([outline.real, outline.imag])],
                                             facecolors=tint, edgecolors="none", zorder=0),
                              autolim=False)
            plot(outline, color="k", lw=1.1)
        # line of centres (O2 above the frame), common tangent, line of action, B1B2
        plot([lay.o1, 1j * top], color="0.3", lw=0.7, ls="-.")
        ax.annotate("", xy=(0, top), xytext=(0, top - 2.5 * m),
                    arrowprops=dict(arrowstyle="->", color="0.3", lw=0.8))
        ax.annotate(f"{mpl_point('O2')} ↑  (a′ = {pair.a_work:.1f} mm)", (0, top), xytext=(6, -4),
                    textcoords="offset points", fontsize=8, va="top")
        plot([P - 5 * m, P + 5 * m], color="0.4", lw=0.6)
        plot([lay.n1 - 1.5 * m * u, lay.n2 + 1.5 * m * u], color="C3", lw=0.8)
        plot([lay.b1, lay.b2], color="C3", lw=3.2, solid_capstyle="butt")
        plot([lay.o1, lay.n1], color="C2", lw=0.6)
        plot([lay.o2, lay.n2], color="C2", lw=0.6)
        for pt in (lay.n1, lay.n2, lay.b1, lay.b2, P, lay.o1):
            plot(pt, "o", color="k", ms=3, zorder=5)
        box = dict(boxstyle="round,pad=0.12", fc="white", ec="none", alpha=0.85)
        for name, pt, off in (("O1", lay.o1, (9, -9)), ("P", P, (-7, 11)), ("N1", lay.n1, (10, 3)),
                              ("N2", lay.n2, (-4, 11)), ("B1", lay.b1, (-2, 11)), ("B2", lay.b2, (3, -12))):
            ax.annotate(mpl_point(name), (pt.real, pt.imag), xytext=off, textcoords="offset points", fontsize=10,
                        ha="center", va="center", zorder=6, bbox=box)
        # α′ at P (between the common tangent and N1N2) and as the angle P O1 N1
        size = right - left
        for centre, start, rad, off in ((P, np.pi - aw, 0.075 * size, (-4, 34)),
                                        (lay.o1, np.pi / 2 - aw, 0.45 * lay.r1w, (6, 10))):
            plot(centre + rad * np.exp(1j * np.linspace(start, start + aw, 30)), color="C3", lw=0.9, zorder=4)
            q = centre + rad * np.exp(1j * (start + aw / 2))
            ax.annotate("α′", (q.real, q.imag), xytext=off, textcoords="offset points", fontsize=9,
                        color="C3", ha="center", va="center", zorder=6, bbox=box,
                        arrowprops=dict(arrowstyle="-", color="C3", lw=0.5, shrinkA=0, shrinkB=0))
        # gear 1 drives counter-clockwise
        turn = 0.3 * lay.r1w * np.exp(1j * np.radians([105, 165]))
        ax.annotate("", xy=(turn[1].real, turn[1].imag), xytext=(turn[0].real, turn[0].imag),
                    arrowprops=dict(arrowstyle="->", color="0.25", lw=0.9, connectionstyle="arc3,rad=0.35"))
        ax.annotate(lab["drive"], (turn[1].real, turn[1].imag), xytext=(-4, 2), textcoords="offset points",
                    fontsize=8, ha="right", va="bottom")
        text = (f"m = {m:g} mm,  $z_1$ = {g1.z},  $z_2$ = {g2.z}\n"
                f"a′ = {pair.a_work:.2f} mm,  α′ = {np.degrees(aw):.2f}°\n"
                f"$B_1B_2$ = {lay.action_length:.2f} mm,  $p_b$ = {pair.pb:.2f} mm\n"
                f"ε = $B_1B_2$ / $p_b$ = {pair.contact_ratio:.3f}")
        ax.text(1.0, -0.1, text, transform=ax.transAxes, fontsize=8, va="top", ha="right",
                bbox=dict(boxstyle="round", fc="white", ec="0.6", lw=0.6))
        handles = [ax.plot([], [], **styles["pitch"])[0], ax.plot([], [], **styles["base"])[0],
                   ax.plot([], [], **styles["tip"])[0], ax.plot([], [], color="C3", lw=0.8)[0],
                   ax.plot([], [], color="C3", lw=3.2)[0]]
        names = [lab["pitch"], lab["base"], lab["tip"] + " / " + lab["root"], lab["action"], lab["actual"]]
        if shifted:
            handles.insert(1, ax.plot([], [], **styles["ref"])[0])
            names.insert(1, lab["ref"])
        ax.legend(handles, names, loc="upper left", bbox_to_anchor=(-0.02, -0.09), fontsize=8, frameon=False,
                  ncol=2, handlelength=2.6, columnspacing=1.2)
        ax.set_xlim(left, right)
        ax.set_ylim(bottom, top)
        ax.set_aspect("equal")
        ax.set_xlabel(lab["x"])
        ax.set_ylabel(lab["y"])
        ax.set_title(title if title is not None else lab["title"], fontsize=10)
