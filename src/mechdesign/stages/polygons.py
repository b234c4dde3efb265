"""The polygons stage (作图多边形) of every linkage: the velocity, acceleration and force
polygons at the positions the A1 analysis sheet draws, computed once and stored with the
results so that the sheet only reads them.

The positions are the brief's ``sheets.polygon_positions`` when it has them, else the
regular positions nearest the middle of the working and of the return stroke (where the
working resistance acts on less than 60 % of the working stroke, the regular position under
it with the largest balancing torque in place of the first). The polygons
come from the group types themselves (:mod:`mechdesign.core.polygons`), built from the
computed motion and the kinetostatic reactions. Works on any model with the engine's
attributes (``mechanism``, ``bodies``, ``resistances``, ``gravity``) and the engine's
motion and forces results.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..core.polygons import Polygon, kinematic_polygon, linkage_force_polygons, spread
from ..i18n import N_
from ..pipeline import Stage
from . import titles

TWO_PI = 2.0 * np.pi


@dataclass(frozen=True)
class LinkagePolygons:
    """Stage 作图多边形: ``positions`` the position labels drawn (in order); ``polygons``
    label → (velocity polygon, acceleration polygon, the force polygon of every group with
    links, the crank first; no force polygons without a forces stage). Values in SI (m/s,
    m/s², N, N·m) as complex x + iy, see :class:`mechdesign.core.polygons.Polygon`."""

    positions: tuple
    polygons: dict
    model_key: str = "model"    # where the stage found the engine's model …
    prefix: str = "linkage"     # … and its results (``{prefix}``, ``{prefix}_forces`` …)

    def at(self, label: str) -> tuple:
        return self.polygons[str(label)]


def entry(k, label: str) -> int:
    """Index of position ``label`` in the motion arrays (the grid comes first)."""
    return k.grid_size + [str(x) for x in k.positions.labels].index(str(label))


#: a velocity polygon whose points spread across their main line by less than this part of
#: their spread along it is a line (all vectors parallel: lockbeam's feed linkage at
#: mid-stroke, positions 5 and 11, its guide bar in line with the crank)
FLAT = 0.05


def flatness(poly: Polygon) -> float:
    """A polygon's width across its main line over its length along it (core/polygons.spread,
    the measure of the report's and the sheet's "nearly flat" notes), the pole among its
    points: 0 for points on one line."""
    length, width = spread([0j, *poly.points.values()])
    return width / length if length > 0 else 0.0


def default_positions(k, forces=None, flat=None) -> list[str]:
    """Regular positions nearest the middle of the working and of the return stroke; where
    the working resistance acts on less than 60 % of the working stroke (a die-cutter's
    last millimetres), the regular position in that part where the crank's balancing torque
    is largest (else the one nearest its middle), so that the force analysis meets the
    working load (review39: the die-cutter's positions 4 and 10 both missed its 1000 kN).
    ``flat(label)``: whether the velocity polygon there is a line; such a position gives way
    to the next nearest regular one whose polygon is not (of two as near, the earlier)."""
    regular = [(lab, ph) for lab, ph, sp in zip(k.positions.labels, k.positions.phase,
                                                 k.positions.special) if not sp]
    w = k.working_span
    work_target = w / 2
    if forces is not None and getattr(forces, "resistance", None):
        n = k.grid_size
        phase = np.asarray(k.phase[:n])
        total = sum(np.abs(np.asarray(v[:n])) for v in forces.resistance.values())
        work = phase <= w
        top = float(np.max(total[work])) if work.any() else 0.0
        resisted = work & (total > 1e-9 * top) if top > 0 else np.zeros_like(work)
        if resisted.any() and resisted.sum() < 0.6 * work.sum():
            lo, hi = float(phase[resisted].min()), float(phase[resisted].max())
            work_target = 0.5 * (lo + hi)
            # of the regular positions under the load, the one the crank is loaded most at
            # (the die-cutter's 7 sits by the toggle's straight line, where the crank's
            # small reaction closes two nearly opposite 1000 kN forces: 6 is the one)
            labels = [str(x) for x in k.positions.labels]
            torque = np.asarray(forces.balancing_torque)
            under = [(lab, abs(float(torque[n + labels.index(str(lab))])))
                     for lab, ph in regular if lo <= ph <= hi]
            if under:
                work_target = dict(regular)[max(under, key=lambda e: e[1])[0]]
    out = []
    for target in (work_target, (w + TWO_PI) / 2):
        # (distances to 1e-9 rad: two positions as near, by the float's last bits too, keep
        # their order)
        near = [str(lab) for lab, ph in sorted(regular, key=lambda e: round(abs(e[1] - target), 9))]
        best = near[0]
        if flat is not None and flat(best):
            best = next((lab for lab in near if not flat(lab)), best)
        if best not in out:
            out.append(best)
    return out


def chosen_positions(k, brief=None, forces=None, mech=None, raw=None) -> list[str]:
    """The brief's ``sheets.polygon_positions`` (validated with the brief) or the defaults
    (given the mechanism and its motion, none whose velocity polygon is a line)."""
    settings = getattr(brief, "sheets", None)
    chosen = getattr(settings, "polygon_positions", None)
    if chosen:
        return [resolve_label(k, p, f"sheets.polygon_positions[{i}]") for i, p in enumerate(chosen)]
    flat = None
    if mech is not None and raw is not None:
        def flat(label: str) -> bool:
            return flatness(kinematic_polygon(mech, raw, entry(k, label), label, "velocity")) < FLAT
    return default_positions(k, forces, flat)


def stage_positions(r: dict, model_key: str, prefix: str) -> list[str]:
    """The polygon positions of a pipeline's results ``r`` (the polygons and graphical-method
    stages draw the same ones)."""
    return chosen_positions(r[prefix], r.get("brief"), r.get(f"{prefix}_forces"),
                            r[model_key].mechanism, r[f"{prefix}_raw"])


def resolve_label(k, asked, field: str) -> str:
    """The position label that ``asked`` names: a label (4, "4'", "4′", "φ45") or what
    the brief's analysis asked for (an event code, φ45); else a design error at ``field``
    listing the labels there are."""
    from ..core.errors import DesignError

    labels = [str(x) for x in k.positions.labels]
    text = str(asked).replace("′", "'").strip()
    if text in labels:
        return text
    requested = getattr(k, "requested", {}) or {}
    if text in requested:
        return str(requested[text])
    known = ", ".join(labels + [key for key in requested if key not in labels])
    raise DesignError(N_("{field}: {asked!r} is not a position of the analysis; positions: {known}"),
                      field=field, asked=asked, known=known)


def polygons(model, k, raw, forces, label: str) -> tuple[Polygon, ...]:
    """Velocity polygon, acceleration polygon and the force polygons (one per group with
    links, the crank first) at position ``label``."""
    i = entry(k, label)
    label = str(label)
    mech = model.mechanism
    out = [kinematic_polygon(mech, raw, i, label, "velocity"),
           kinematic_polygon(mech, raw, i, label, "acceleration")]
    if forces is None:
        return tuple(out)
    multi = len(model.resistances) > 1
    external = [(r.link, f"{r.symbol}{j + 1}" if multi else r.symbol,
                 complex(forces.resistance[f"R{j + 1}"][i] * np.exp(1j * r.direction)))
                for j, r in enumerate(model.resistances)]
    out += linkage_force_polygons(
        mech, raw, i, label, model.bodies, model.gravity, external,
        {name: complex(v[i]) for name, v in forces.reactions.items()},
        {link: complex(v[i]) for link, v in forces.inertia_force.items()},
        {link: float(v[i]) for link, v in forces.inertia_couple.items()},
        float(k.sense * forces.balancing_torque[i]))
    return tuple(out)


def linkage_polygons(model, k, raw, forces, positions: list[str]) -> LinkagePolygons:
    labels = tuple(str(p) for p in positions)
    return LinkagePolygons(labels, {p: polygons(model, k, raw, forces, p) for p in labels})


def polygon_stage(model_key: str = "model", prefix: str = "linkage") -> Stage:
    """The stage that stores ``{prefix}_polygons`` from the engine's results under
    ``model_key``, ``prefix``, ``{prefix}_raw`` and ``{prefix}_forces``."""

    def run(r: dict) -> LinkagePolygons:
        k = r[prefix]
        forces = r.get(f"{prefix}_forces")
        found = linkage_polygons(r[model_key], k, r[f"{prefix}_raw"], forces,
                                 stage_positions(r, model_key, prefix))
        return replace(found, model_key=model_key, prefix=prefix)

    return Stage(f"{prefix}_polygons", titles.pgettext("stage", "polygons"), run)
