"""Figures of the motion-scheme components: the linear (直线式) and circular (圆周式) motion
cycle diagrams and the incomplete gear's driven-wheel motion. Arrays and angles arrive in
course units (°, s, mm); computation never imports this module."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..i18n import N_
from .figures import cached, figure
from .labels import LabelTable

LABELS = LabelTable({
    "phi": N_("main-shaft angle φ (°)"),
    "theta": N_("driver (main-shaft) angle θ (°)"),
    "angle": N_(r"driven angle $\varphi_2$ (°)"),
    "travel": N_("chain travel (mm)"),
    "jump": N_("speed jump"),
})

#: Fill colour of each state of mechdesign.core.cycle.STATES.
COLOURS = {"rise": "#5B8FD0", "return": "#E8955A", "dwell_high": "#9CCB9C",
           "dwell_low": "#D9D9D9", "move": "#8C7BC8", "dwell": "#ECECEC",
           # windows of an output that moves all the time: motion colours, not a rest grey
           "work": "#2F5F9E", "clear": "#C9B8E8"}


def window_pieces(start: float, span: float, origin: float):
    """A phase [start, start + span) (°) as pieces inside the window [origin, origin + 360)."""
    s = origin + np.mod(start - origin, 360.0)
    if s >= origin + 360.0 - 1e-9:
        s -= 360.0
    end = s + span
    if end <= origin + 360.0 + 1e-9:
        return [(s, span)]
    return [(s, origin + 360.0 - s), (origin, end - origin - 360.0)]


def _angle_axis(ax, origin: float):
    ticks = np.arange(origin, origin + 361.0, 30.0)
    ax.set_xlim(origin, origin + 360.0)
    ax.set_xticks(ticks)
    last = origin % 360 or 360.0           # the window ends where it began, shown as 360 for 0
    ax.set_xticklabels([f"{t % 360:g}" for t in ticks[:-1]] + [f"{last:g}"], fontsize=7)


@cached
def linear(path: Path, lang: str, actuators, origin: float = 0.0, links=(), states=None):
    """Linear (rectangular) cycle diagram: one bar per actuator.

    ``actuators``: [(name, [(start°, span°, state, label), …]), …], first on top;
    ``links``: constraint marks (kind, (row_a, x_a0, x_a1), (row_b, x_b0, x_b1), ok) with
    x in degrees; ``states``: {state: legend label}."""
    lab = LABELS[lang]
    n = len(actuators)
    with figure(path, 1, (7.2, 0.75 + 0.62 * n + 0.5), sharex=False) as (ax,):
        _angle_axis(ax, origin)
        y_of = {i: n - 1 - i for i in range(n)}
        for i, (name, phases) in enumerate(actuators):
            y = y_of[i]
            for start, span, state, label in phases:
                for s, w in window_pieces(start, span, origin):
                    ax.barh(y, w, left=s, height=0.56, color=COLOURS.get(state, "#DDDDDD"),
                            edgecolor="0.25", lw=0.7)
                    if w >= 24:
                        ax.text(s + w / 2, y, label, ha="center", va="center", fontsize=7.5)
                    elif w >= 11:
                        ax.text(s + w / 2, y, label, ha="center", va="center", fontsize=6,
                                rotation=90)
        for kind, (ra, a0, a1), (rb, b0, b1), ok in links:
            colour = "#2E7D32" if ok else "#C62828"
            ya, yb = y_of[ra], y_of[rb]
            if kind == "before":
                ax.annotate("", xy=(b0, yb + (0.3 if yb < ya else -0.3)),
                            xytext=(a1, ya + (-0.3 if yb < ya else 0.3)),
                            arrowprops=dict(arrowstyle="->", color=colour, lw=1.1))
            else:
                lo, hi = min(ya, yb) - 0.3, max(ya, yb) + 0.3
                for x in (a0, a1):
                    ax.plot([x, x], [lo, hi], color=colour, lw=0.9, ls="--")
        ax.set_yticks([y_of[i] for i in range(n)])
        ax.set_yticklabels([name for name, _ in actuators], fontsize=8)
        ax.set_ylim(-0.6, n - 0.4)
        ax.grid(True, axis="x", lw=0.4, color="0.82")
        ax.set_axisbelow(True)
        ax.set_xlabel(lab["phi"])
        if states:
            from matplotlib.patches import Patch

            handles = [Patch(facecolor=COLOURS[s], edgecolor="0.25", label=t) for s, t in states.items()]
            ax.legend(handles=handles, fontsize=7, ncol=min(6, len(handles)), loc="lower center",
                      bbox_to_anchor=(0.5, 1.0), frameon=False)


#: Legend rows the circular diagram's upper-left corner takes without reaching the ring.
LEGEND_ROWS = 9


@cached
def circular(path: Path, lang: str, actuators, origin: float = 0.0, states=None):
    """Circular cycle diagram: concentric rings, the first actuator innermost; φ = 0 at the
    top, increasing clockwise."""
    from matplotlib.patches import Patch, Wedge

    n = len(actuators)
    r0, w = 1.0, 0.8
    outer = r0 + n * w
    with figure(path, 1, (5.6, 5.6), sharex=False) as (ax,):
        names, bounds = [], []
        for i, (name, phases) in enumerate(actuators):
            r_in = r0 + i * w
            bounds.append([start for start, *_ in phases])
            for start, span, state, label in phases:
                # matplotlib measures counter-clockwise from +x; the diagram clockwise from the top.
                t1, t2 = 90.0 - (start + span), 90.0 - start
                ax.add_patch(Wedge((0, 0), r_in + w, t1, t2, width=w, facecolor=COLOURS.get(state, "#DDD"),
                                   edgecolor="0.25", lw=0.7))
                mid = np.radians(90.0 - (start + span / 2))
                rm = r_in + w / 2
                arc = np.radians(span) * rm
                if arc >= 0.55:
                    rot = (np.degrees(mid) % 180.0) - 90.0     # along the ring, never upside down
                    # on a ground of its phase's colour: the origin's dash-dot radius, drawn
                    # below the texts, does not run through a name at φ = 0
                    names.append(ax.text(rm * np.cos(mid), rm * np.sin(mid), label, ha="center",
                                         va="center", fontsize=6.5, rotation=rot,
                                         rotation_mode="anchor", zorder=4,
                                         bbox=dict(boxstyle="square,pad=0.3", lw=0,
                                                   fc=COLOURS.get(state, "#DDD"))))
        for deg in range(0, 360, 30):
            t = np.radians(90.0 - deg)
            ax.plot([outer * np.cos(t), (outer + 0.12) * np.cos(t)],
                    [outer * np.sin(t), (outer + 0.12) * np.sin(t)], color="0.3", lw=0.7)
            ax.text((outer + 0.32) * np.cos(t), (outer + 0.32) * np.sin(t), f"{deg}°", fontsize=7,
                    ha="center", va="center")
        t = np.radians(90.0 - origin)
        ax.plot([0, outer * np.cos(t)], [0, outer * np.sin(t)], color="0.2", lw=1.0, ls="-.")
        ax.annotate("", xy=(0.55 * np.cos(np.radians(40)), 0.55 * np.sin(np.radians(40))),
                    xytext=(0.55 * np.cos(np.radians(110)), 0.55 * np.sin(np.radians(110))),
                    arrowprops=dict(arrowstyle="->", color="0.3", lw=0.9,
                                    connectionstyle="arc3,rad=-0.35"))
        ax.text(0.0, -0.3, "φ", ha="center", va="center", fontsize=9)
        lim = outer + 0.6
        ax.set_xlim(-lim, lim)
        ax.set_ylim(-lim, lim)
        ax.set_aspect("equal")
        ax.axis("off")
        handles = [Patch(facecolor="white", edgecolor="white", label=f"{i + 1}  {name}")
                   for i, (name, _) in enumerate(actuators)]
        kinds = [Patch(facecolor=COLOURS[s], edgecolor="0.25", label=t) for s, t in (states or {}).items()]
        if len(handles) + len(kinds) <= LEGEND_ROWS:
            ax.legend(handles=handles + kinds, fontsize=7, loc="upper left",
                      bbox_to_anchor=(-0.02, 1.02), frameon=False, handlelength=1.0)
        else:       # the upper-left corner holds about nine rows before the ring's 300° label
            first = ax.legend(handles=handles, fontsize=7, loc="upper left",
                              bbox_to_anchor=(-0.02, 1.02), frameon=False, handlelength=1.0)
            ax.add_artist(first)
            ax.legend(handles=kinds, fontsize=7, loc="lower left", bbox_to_anchor=(-0.02, -0.02),
                      frameon=False, handlelength=1.0)
        _number_rings(ax, r0, w, bounds, origin, names)


def _number_rings(ax, r0: float, w: float, bounds, origin: float, names) -> None:
    """Each ring's number in a small circle on the ring, as near its top (just clockwise of
    φ = 0) as it stands clear of the phase names, of the numbers placed before and of the
    ring's phase boundaries and the origin's radius (the names at φ ≈ 0 were covered by
    the numbers set at the top: review36 Top 6). Measured on the figure as laid out for
    saving (tight_layout), as :mod:`.label_layout` does."""
    from .label_layout import _box, _box_overlap, _renderer

    fig = ax.figure
    ax.apply_aspect()
    fig.tight_layout()
    ax.apply_aspect()
    renderer = _renderer(fig)
    pad = 1.5 * fig.dpi / 72.0
    taken = [_box(t, renderer, pad) for t in names]
    # from 6° (the number just right of the top) clockwise, then anticlockwise from 354°
    order = [*range(6, 180, 2), *range(354, 180, -2)]
    for i, starts in enumerate(bounds):
        r_in, rm = r0 + i * w, r0 + (i + 0.5) * w
        lines = [np.radians(90.0 - a) for a in (*starts, origin)]
        t = ax.text(0.0, 0.0, str(i + 1), fontsize=7, ha="center", va="center", color="0.15",
                    bbox=dict(boxstyle="circle,pad=0.15", fc="white", ec="0.4", lw=0.5))
        first = None
        for phi in order:
            a = np.radians(90.0 - phi)
            t.set_position((rm * np.cos(a), rm * np.sin(a)))
            t.update_bbox_position_size(renderer)
            bb = t.get_bbox_patch().get_window_extent(renderer)
            box = (bb.x0 - pad, bb.y0 - pad, bb.x1 + pad, bb.y1 + pad)
            first = first or (a, box)
            if any(_box_overlap(box, b) > 0 for b in taken):
                continue
            # the ring's boundary radii (and the origin's) sampled through the ring
            pts = ax.transData.transform([(r * np.cos(g), r * np.sin(g)) for g in lines
                                          for r in np.linspace(r_in, r_in + w, 17)])
            if any(box[0] <= x <= box[2] and box[1] <= y <= box[3] for x, y in pts):
                continue
            break
        else:               # nowhere free: at the top, where it always stood
            a, box = first
            t.set_position((rm * np.cos(a), rm * np.sin(a)))
        taken.append(box)


@cached
def intermittent_motion(path: Path, lang: str, theta_deg, angle_deg, velocity, vel_label: str,
                        motion_arcs, jump_text: str, travel_mm=None):
    """Driven-wheel angle (and chain travel) and velocity against the driver angle; the
    meshing arcs ``motion_arcs`` [(start°, end°)] shaded; the jumps marked."""
    lab = LABELS[lang]
    with figure(path, 2, (7.0, 5.0)) as (ax1, ax2):
        for ax in (ax1, ax2):
            ax.set_xlim(0, 360)
            ax.set_xticks(np.arange(0, 361, 30))
            ax.grid(True, lw=0.4, color="0.82")
            for a, b in motion_arcs:
                ax.axvspan(a, b, color="C0", alpha=0.08, lw=0)
        ax1.plot(theta_deg, angle_deg, color="C0", lw=1.4)
        ax1.set_ylabel(lab["angle"])
        if travel_mm is not None:
            top = max(float(np.max(angle_deg)), 1e-9)
            scale = float(np.max(travel_mm)) / top
            sec = ax1.secondary_yaxis("right", functions=(lambda x: x * scale, lambda x: x / scale))
            sec.set_ylabel(lab["travel"])
        ax2.plot(theta_deg, velocity, color="C3", lw=1.4)
        ax2.axhline(0, color="0.4", lw=0.6)
        ax2.set_ylabel(vel_label)
        ax2.set_xlabel(lab["theta"])
        hi = float(np.max(velocity)) if np.size(velocity) else 1.0
        ax2.set_ylim(-0.12 * hi, 1.3 * hi if hi > 0 else 1.0)
        for a, _ in motion_arcs[:1]:
            right = a <= 200.0          # the note on the side with room for it
            ax2.annotate(f"{lab['jump']} {jump_text}", xy=(a, 0.5 * hi),
                         xytext=(a + 12 if right else a - 12, 1.12 * hi), ha="left" if right else "right",
                         fontsize=7.5, color="C3",
                         arrowprops=dict(arrowstyle="->", color="C3", lw=0.8))
