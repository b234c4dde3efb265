"""Figures of the cam sections: s–v–a–j diagrams, the profile, pressure angle and
curvature, and the eccentric-disc displacement curves. Arrays arrive in course units."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..i18n import N_
from .figures import cached, figure
from .legends import legend
from .labels import LabelTable, mpl_label

LABELS = LabelTable({
    "delta": N_("cam angle δ (°)"),
    "alpha": N_("pressure angle α (°)"),
    "rho": N_("radius of curvature ρ (mm)"),
    "limit_rise": N_("allowed (rise)"),
    "limit_return": N_("allowed (return)"),
    "base": N_("base circle"),
    "pitch": N_("pitch curve"),
    "actual": N_("actual profile"),
    "roller": N_("roller"),
    "rho_pitch": N_("pitch curve ρ"),
    "rho_actual": N_("actual profile ρa"),
    "rr": N_("roller radius"),
    "x": "x (mm)",
    "y": "y (mm)",
    "rise": N_("rise"),
    "return": N_("return"),
    "dwell": N_("dwell"),
    "s_disc": N_("follower displacement s (mm)"),
    "follower": N_("follower"),
    "pivot": N_("pivot A"),
    "cw": N_("clockwise"),
    "ccw": N_("counter-clockwise"),
    "convex_only": N_(" (convex parts only)"),
})


def _delta_axis(ax, segments, lab):
    """0–360° axis; rises and returns shaded, segment names on top of the first panel."""
    ax.set_xlim(0, 360)
    ax.set_xticks(np.arange(0, 361, 30))
    ax.grid(True, lw=0.4, color="0.82")
    for start, end, kind, _ in segments:
        if kind == "rise":
            ax.axvspan(start, end, color="C0", alpha=0.06, lw=0)
        elif kind == "return":
            ax.axvspan(start, end, color="C1", alpha=0.06, lw=0)
        ax.axvline(start, color="0.6", lw=0.5, ls=":")


#: The curves of the motion diagrams: a rise in blue, a return in orange (the colours of
#: their shading and of the figure's caption), the dwells and the jumps between segments
#: in dark grey.
SEGMENT_COLOURS = {"rise": "C0", "return": "C1"}
DWELL_COLOUR = "0.25"


def _interior(delta_deg, start: float, end: float, tol: float = 1e-6) -> np.ndarray:
    """The cam angles strictly inside the segment start–end [°] (one that runs past 360°
    continues from 0°): not its end points, where the curve may jump to its neighbour's
    value."""
    span = end - start
    rel = (np.asarray(delta_deg) - start) % 360.0
    if span >= 360.0 - tol:
        return np.ones(len(rel), dtype=bool)
    return (rel > tol) & (rel < span - tol)


def stagger_names(texts, gap_px: float = 3.0) -> None:
    """Raise a name above the panel by a row where it would run into the one before it
    (lockbeam's bending cam: the 6° far dwell's name between "rise" and "return" printed
    "risefar dwellreturn"); measured on the texts as drawn."""
    if not texts:
        return
    renderer = texts[0].figure.canvas.get_renderer()
    ends: list[float] = []                       # the right end of the last name of each row
    for t in sorted(texts, key=lambda t: t.get_position()[0]):
        box = t.get_window_extent(renderer)
        row = next((i for i, e in enumerate(ends) if box.x0 >= e + gap_px), len(ends))
        if row == len(ends):
            ends.append(box.x1)
        else:
            ends[row] = box.x1
        if row:
            x, y = t.get_position()
            t.set_position((x, y + 0.11 * row))


@cached
def svaj(path: Path, lang: str, delta_deg, series, ylabels, segments, impulses=()):
    """Stacked displacement, velocity, acceleration and jerk against the cam angle.
    ``impulses`` = (δ [°], panel, sign): an infinite value there, drawn as an arrow "∞"."""
    lab = LABELS[lang]
    delta_deg = np.asarray(delta_deg, dtype=float)
    with figure(path, len(series), (7.0, 7.4)) as axes:
        for ax, y, yl in zip(axes, series, ylabels):
            _delta_axis(ax, segments, None)
            # Jumps (rigid/soft impact) must show as vertical steps, not sloped lines: the
            # whole curve in the dwells' colour (its jumps too), and over it each rise and
            # return in the colour the caption names (blue: rise, orange: return)
            y = np.asarray(y, dtype=float)
            ax.plot(delta_deg, y, lw=1.3, color=DWELL_COLOUR)
            for start, end, kind, _name in segments:
                if kind in SEGMENT_COLOURS:
                    inside = _interior(delta_deg, start, end)
                    ax.plot(delta_deg[inside], y[inside], lw=1.3, color=SEGMENT_COLOURS[kind])
            ax.axhline(0, color="0.4", lw=0.6)
            ax.set_ylabel(yl, fontsize=8)
            if np.allclose(y, 0.0):
                ax.set_ylim(-1, 1)
                ax.set_yticks([0])
        for x, panel, sign in impulses:
            ax = axes[panel]
            lo, hi = ax.get_ylim()
            if hi - lo < 1e-9 or (abs(lo) < 1e-12 and abs(hi) < 1e-12):
                lo, hi = -1.0, 1.0
                ax.set_ylim(lo, hi)
            tip = 0.92 * (hi if sign >= 0 else -lo) * (1 if sign >= 0 else -1)
            if sign == 0:
                ax.annotate("", xy=(x, 0.9 * hi), xytext=(x, 0), arrowprops=dict(arrowstyle="->", color="C3", lw=1.0))
                ax.annotate("", xy=(x, 0.9 * lo), xytext=(x, 0), arrowprops=dict(arrowstyle="->", color="C3", lw=1.0))
                ax.text(x + 3, 0.7 * hi, "±∞", color="C3", fontsize=7)
            else:
                ax.annotate("", xy=(x, tip), xytext=(x, 0), arrowprops=dict(arrowstyle="->", color="C3", lw=1.0))
                ax.text(x + 3, 0.75 * tip, "∞" if sign > 0 else "−∞", color="C3", fontsize=7)
        names = [axes[0].text((start + end) / 2, 1.02, name, transform=axes[0].get_xaxis_transform(),
                              ha="center", va="bottom", fontsize=8, color="0.3")
                 for start, end, kind, name in segments]
        stagger_names(names)
        axes[-1].set_xlabel(lab["delta"])


@cached
def pressure_and_curvature(path: Path, lang: str, delta_deg, alpha_deg, limits, segments,
                           rho_pitch=None, rho_actual=None, roller=0.0, clip=None):
    """Pressure angle with the allowed values per segment; below it the radii of curvature
    of the convex parts (concave and nearly straight parts are left out)."""
    lab = LABELS[lang]
    two = rho_pitch is not None
    with figure(path, 2 if two else 1, (7.0, 5.6 if two else 3.2)) as axes:
        ax = axes[0]
        _delta_axis(ax, segments, lab)
        ax.plot(delta_deg, alpha_deg, lw=1.3, color="C0", label="α")
        shown = set()
        for (start, end, kind, _), limit in zip(segments, limits):
            if limit is None:
                continue
            name = lab["limit_rise"] if kind == "rise" else lab["limit_return"]
            ax.plot([start, end], [limit, limit], color="C3", lw=1.1, ls="--",
                    label=None if name in shown else f"{name}")
            # the return's allowed angle is [α′], as the tables write it (page review 41)
            sym = "[α]" if kind == "rise" else "[α′]"
            ax.text(end - 2, limit + 1, f"{sym} = {limit:.0f}°", fontsize=7, color="C3", ha="right")
            shown.add(name)
        j = int(np.argmax(alpha_deg))
        ax.plot([delta_deg[j]], [alpha_deg[j]], "o", color="C3", ms=4)
        ax.annotate(f"$\\alpha_{{max}}$ = {alpha_deg[j]:.2f}°", (delta_deg[j], alpha_deg[j]),
                    xytext=(6, -12), textcoords="offset points", fontsize=7.5)
        top = max(float(np.max(alpha_deg)), max((x for x in limits if x is not None), default=0))
        ax.set_ylim(0, top * 1.18 + 1)
        ax.set_ylabel(lab["alpha"])
        legend(ax, fontsize=7, loc="upper right")
        if two:
            ax = axes[1]
            _delta_axis(ax, segments, lab)
            cap = clip if clip is not None else np.inf
            for rho, name, color in ((rho_pitch, lab["rho_pitch"], "C0"),
                                     (rho_actual, lab["rho_actual"], "C2")):
                y = np.where((rho > 0) & (rho < cap), rho, np.nan)
                ax.plot(delta_deg, y, lw=1.2, color=color, label=name)
            if roller > 0:
                ax.axhline(roller, color="C3", lw=1.0, ls="--", label=f"{lab['rr']} {roller:g} mm")
            ax.axhline(0, color="0.4", lw=0.6)
            ax.set_ylabel(lab["rho"] + lab["convex_only"], fontsize=8)
            legend(ax, fontsize=7, loc="upper right")
        axes[-1].set_xlabel(lab["delta"])


@cached
def profile(path: Path, lang: str, pitch, actual, base_radius, roller, marks, rotation,
            follower=None, pivot=None, flat=False):
    """The cam drawn in its own frame (mm): base circle, pitch curve, actual profile, the
    roller at the marked cam angles, the rays of the inversion method and the follower at δ = 0.

    ``marks`` is a list of (label, index into the arrays)."""
    lab = LABELS[lang]
    with figure(path, 1, (6.4, 6.4), sharex=False) as (ax,):
        t = np.linspace(0, 2 * np.pi, 361)
        circ = np.exp(1j * t)
        ax.plot((base_radius * circ).real, (base_radius * circ).imag, color="0.45", lw=0.8, ls="--",
                label=f"{lab['base']} $r_0$ = {base_radius:.1f} mm")
        closed = lambda z: np.append(z, z[:1])  # noqa: E731
        if not flat and roller > 0:
            ax.plot(closed(pitch).real, closed(pitch).imag, color="C0", lw=0.9, ls="-.",
                    label=lab["pitch"])
        ax.plot(closed(actual).real, closed(actual).imag, color="k", lw=1.8, label=lab["actual"])
        spots = []                      # the angle labels' centres, kept inside the axes
        for text, i in marks:
            p = pitch[i]
            ax.plot([0, p.real], [0, p.imag], color="0.75", lw=0.4)
            if roller > 0:
                ring = p + roller * circ
                ax.plot(ring.real, ring.imag, color="C3", lw=0.7)
            ax.plot([p.real], [p.imag], ".", color="C3", ms=3)
            u = p / abs(p) if abs(p) > 0 else 1
            q = p + u * (roller + 0.06 * base_radius + 3)
            ax.text(q.real, q.imag, text, fontsize=6.5, ha="center", va="center", color="0.25")
            spots.append(q)
        ax.plot([0], [0], "+", color="k", ms=10)
        if pivot is not None:
            ax.plot([pivot.real], [pivot.imag], "^", color="k", ms=6)
            ax.text(pivot.real + 3, pivot.imag - 8, mpl_label(lab["pivot"]), fontsize=7)
            if follower is not None:
                ax.plot([pivot.real, follower.real], [pivot.imag, follower.imag], color="C0", lw=2.0)
        elif follower is not None and not flat:
            ax.plot([follower.real] * 2, [follower.imag, follower.imag + 0.6 * base_radius],
                    color="C0", lw=2.0)
        # rotation arrow
        r = 0.28 * base_radius
        a = np.linspace(0.35, 1.45, 30) * np.pi
        arc = r * np.exp(1j * (a if rotation > 0 else a[::-1]))
        ax.plot(arc.real, arc.imag, color="C2", lw=1.0)
        ax.annotate("", xy=(arc[-1].real, arc[-1].imag), xytext=(arc[-3].real, arc[-3].imag),
                    arrowprops=dict(arrowstyle="->", color="C2", lw=1.0))
        ax.text(0, -0.55 * base_radius, "ω " + (lab["ccw"] if rotation > 0 else lab["cw"]),
                fontsize=7, color="C2", ha="center")
        if spots:
            # room for each angle label (review45: "270°" on the y axis' "0", "90°" on the frame):
            # a label's half width and a gap, about a tenth of the labels' radius
            z = np.array(spots)
            pad = 0.1 * float(np.max(np.abs(z)))
            x0, x1 = ax.get_xlim()
            y0, y1 = ax.get_ylim()
            ax.set_xlim(min(x0, float(z.real.min()) - pad), max(x1, float(z.real.max()) + pad))
            ax.set_ylim(min(y0, float(z.imag.min()) - pad), max(y1, float(z.imag.max()) + pad))
        ax.set_aspect("equal")
        ax.set_xlabel(lab["x"])
        ax.set_ylabel(lab["y"])
        ax.grid(True, lw=0.3, color="0.88")
        legend(ax, fontsize=7, loc="lower right", framealpha=0.9)


@cached
def disc_curves(path: Path, lang: str, delta_deg, named):
    """Eccentric disc: displacement and pressure angle of every follower on one chart each.
    ``named`` = list of (label, s [mm], α [°])."""
    lab = LABELS[lang]
    with figure(path, 2, (7.0, 5.6)) as (ax1, ax2):
        styles = ["-", "--", "-.", ":"]
        for i, (name, s, alpha) in enumerate(named):
            ax1.plot(delta_deg, s, lw=1.4, ls=styles[i % 4], label=name)
            ax2.plot(delta_deg, alpha, lw=1.4, ls=styles[i % 4], label=name)
        for ax in (ax1, ax2):
            ax.set_xlim(0, 360)
            ax.set_xticks(np.arange(0, 361, 30))
            ax.grid(True, lw=0.4, color="0.82")
            legend(ax, fontsize=7, loc="upper right")
        ax1.set_ylabel(lab["s_disc"])
        ax2.set_ylabel(lab["alpha"])
        ax2.set_xlabel(lab["delta"])
