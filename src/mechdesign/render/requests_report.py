"""Report pieces of the brief's ``analysis`` requests, shared by every linkage machine:
the positions asked for by crank angle and by event, and the named points' velocities
and accelerations (a table at every position and their curves over the cycle).

The runner adds :func:`requests_figures` to a machine's figures and
:func:`requests_context` to its template context (key ``requested``); the base templates
include ``requested_section.*.md.j2`` when it is there.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..i18n import N_, tr
from .fmt import f
from .legends import legend
from .labels import LabelTable, md_point

DEG = 180.0 / np.pi

_TXT = LabelTable({
    "v": N_("speed |v| (m/s)"),
    "a": N_("acceleration |a| (m/s²)"),
    "phase": N_("crank angle φ (°)"),
    "angle": N_("given crank angle"),
    "x_axis": N_("the crank's direction, CCW from +$x$"),
    "position_1": N_("from position 1 in the sense of rotation"),
})


def _found(results: dict):
    from .sheets import linkage_results

    found = linkage_results(results)
    if found is None:
        return None
    k = found.motion
    if not getattr(k, "requested", None) and not getattr(k, "point_vel", None):
        return None
    return found


def requests_figures(results: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    """The named points' speed and acceleration over the cycle (one figure)."""
    found = _found(results)
    if found is None or not found.motion.point_vel:
        return {}
    from . import figures as fig

    k, t = found.motion, _TXT[lang]
    _ = tr(lang)
    n = k.grid_size
    ph = k.phase[:n] * DEG
    path = fig_dir / "named_points.png"
    with fig.figure(path, nrows=2, size=(7.0, 4.6)) as (ax_v, ax_a):
        for name, vel in k.point_vel.items():
            acc = k.point_acc[name]
            ax_v.plot(ph, np.abs(vel[:n]), lw=1.1, label=f"$v_{{{name}}}$")
            ax_a.plot(ph, np.abs(acc[:n]), lw=1.1, label=f"$a_{{{name}}}$")
        for ax, key in ((ax_v, "v"), (ax_a, "a")):
            ax.set_xlim(0, 360)
            ax.set_xticks(np.arange(0, 361, 30))
            ax.axvspan(0, k.working_span * DEG, color="0.93", zorder=0)
            ax.grid(True, lw=0.4, color="0.8")
            ax.set_ylabel(t[key])
            legend(ax, fontsize=7, loc="upper right", ncol=min(4, len(k.point_vel)))
        ax_a.set_xlabel(t["phase"])
    return {"named_points": f"{fig_dir.name}/named_points.png"}


def requests_context(results: dict, brief, figures: dict, lang: str) -> dict | None:
    """Rows of the positions asked for and of the named points at every position."""
    found = _found(results)
    if found is None:
        return None
    from ..brief.common import EVENTS, event_name

    k, t = found.motion, _TXT[lang]
    _ = tr(lang)
    n = k.grid_size
    labels = [str(x) for x in k.positions.labels]
    analysis = getattr(brief, "analysis", None)
    convention = t[getattr(analysis, "positions_from", "position_1")]

    def shown(label):
        return label.replace("'", "′")

    asked = []
    for key, label in k.requested.items():
        j = n + labels.index(label)
        base = key.split("#")[0]
        if base.split(":")[0] in {c.split(":")[0] for c in EVENTS}:
            # what the event means, in both languages (the brief's key is a program name)
            what = event_name(base, lang)
        else:
            what = _("{angle} {key} ({convention})", angle=t["angle"], key=key,
                     convention=convention)
        asked.append([what, shown(label), f(k.phase[j] * DEG, 2),
                      f((k.crank_angle[j] % (2 * np.pi)) * DEG, 2)])
    tables = []
    for name in k.point_vel:
        rows = []
        for i, label in enumerate(labels):
            j = n + i
            v, a = k.point_vel[name][j], k.point_acc[name][j]
            sv = float(np.max(np.abs(k.point_vel[name])))
            sa = float(np.max(np.abs(k.point_acc[name])))
            rows.append([shown(label), f(k.phase[j] * DEG, 2), f(abs(v), 4),
                         f(np.degrees(np.angle(v)) if abs(v) > 1e-9 * sv else 0.0, 2), f(abs(a), 4),
                         f(np.degrees(np.angle(a)) if abs(a) > 1e-9 * sa else 0.0, 2)])
        tables.append({"name": name, "label": md_point(name), "rows": rows})
    return {"asked": asked, "tables": tables, "fig": figures.get("named_points")}
