"""The graphical-method stage (图解法): at the polygon positions (those of the A1 sheet, see
:mod:`.polygons`) the velocity, acceleration and force polygons are *constructed*
(:mod:`mechdesign.core.graphical`: direction lines intersected, lengths drawn and measured
to 0.5 mm) and the values read from them are set beside the analytic ones of the engine.

Only the drawing scales and the given loads (weights, resistances) come from outside the
construction; the scales are chosen as a draughtsman would, so that the largest vector of
a polygon is about 60–80 mm long (from a sketch: the engine's extent at that position).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core import graphical as gr
from ..core.fields import q
from ..pipeline import Stage
from . import titles
from .polygons import entry, stage_positions

#: Target length of the largest vector of a polygon [mm] and of the kinematic diagram.
POLYGON_MM = 80.0
DIAGRAM_MM = 150.0


@dataclass(frozen=True)
class KinPolygon:
    """A velocity or acceleration polygon as constructed."""

    kind: str = q("", "velocity | acceleration")
    scale: float = q("(m/s)/mm or (m/s²)/mm", "μv or μa")
    points: dict[str, complex] = q("mm", "polygon point → position on the drawing (pole p at 0)")
    equations: tuple[gr.VectorEquation, ...] = q("", "the vector equations, group by group")
    rates: dict[str, float] = q("rad/s or rad/s²", "ω (velocity) or α (acceleration) of every "
                                "link found from the measured lengths, CCW +")


@dataclass(frozen=True)
class Comparison:
    """One quantity found graphically beside the engine's analytic value."""

    quantity: str = q("", "v_C, ω3, a_C, α3, R12, Mb, …")
    unit: str = q("", "its unit")
    graphical: float = q("SI of `unit`", "read from the drawing (magnitude; a link's ω, α and M_b signed, CCW positive)")
    analytic: float = q("SI of `unit`", "the engine's value (magnitude; a link's ω, α and M_b signed, CCW positive)")
    difference: float = q("1", "(graphical − analytic) / |analytic| (0 when both vanish)")
    tolerance: float = q("SI of `unit`", "drawing accuracy allowed: 2 % of the analytic value "
                         "plus 1 mm at μv for velocities, 2 mm at μa or μF for accelerations, "
                         "forces and M_b (their errors carry over from the polygons before)")
    passed: bool = q("", "within the drawing accuracy: |graphical − analytic| ≤ tolerance")


@dataclass(frozen=True)
class GraphicalPosition:
    """The graphical method at one position."""

    label: str = q("", "the position's label")
    crank_angle: float = q("rad", "crank angle, CCW from +x")
    length_scale: float = q("m/mm", "μl of the kinematic diagram")
    points: dict[str, complex] = q("m", "the joint positions (the kinematic diagram)")
    velocity: KinPolygon = q("", "the velocity polygon")
    acceleration: KinPolygon = q("", "the acceleration polygon")
    forces: tuple[gr.ForceGroup, ...] = q("", "force analysis, last group first, the crank last")
    balancing_torque: float | None = q("N·m", "M_b from the crank's moment equation, in the "
                                       "crank's sense of rotation (None without masses/loads)")
    comparison: tuple[Comparison, ...] = q("", "graphical beside analytic")


@dataclass(frozen=True)
class GraphicalDocument:
    """Stage 图解法: the graphical method at the polygon positions."""

    step: float = q("mm", "drawing accuracy: every length drawn or measured to this")
    positions: tuple[GraphicalPosition, ...] = q("", "in the order of the polygon positions")


def _extent(points) -> float:
    z = np.array(list(points))
    return float(max(np.ptp(z.real), np.ptp(z.imag), 1e-9))


def _bound(values) -> float:
    return max([abs(v) for v in values] + [1e-12])


#: Enlargements of the velocity and acceleration polygons tried in turn (see
#: :func:`graphical_position`).
ENLARGE = (1.0, 2.0, 4.0)


def graphical_position(model, k, raw, forces, label: str) -> GraphicalPosition:
    """The graphical method at position ``label``, drawn as a student would: at the usual
    polygon size first; when a value then misses the drawing accuracy, the velocity and
    acceleration polygons are drawn again larger (2×, then 4×). The forces take their
    inertia loads m·a_S and J·α from the acceleration polygon, and where two direction lines
    of a force polygon meet at a small angle the accelerations' own rounding (within their
    2 mm at μa) is amplified beyond the force's accuracy (the six-bar's position 10: R14
    −14 %, M_b −6 % at 1×); a larger acceleration polygon is the drafting remedy."""
    for factor in ENLARGE:
        pos = _graphical_position(model, k, raw, forces, label, factor)
        if all(c.passed for c in pos.comparison):
            break
    return pos


def _graphical_position(model, k, raw, forces, label: str, enlarge: float) -> GraphicalPosition:
    mech = model.mechanism
    i = entry(k, label)
    pos = {p: complex(m.pos[i]) for p, m in raw.points.items()}
    mu_l = gr.nice_scale(_extent(pos.values()) / DIAGRAM_MM)
    w2 = float(model.crank_omega)
    # scales from a sketch (the extent of the polygon): only the scale, never a value
    mu_v = gr.nice_scale(_bound(m.vel[i] for m in raw.points.values()) / (enlarge * POLYGON_MM))
    mu_a = gr.nice_scale(_bound(m.acc[i] for m in raw.points.values()) / (enlarge * POLYGON_MM))
    vel = gr.kinematic_drawing(mech, pos, w2, "velocity", mu_v)
    acc = gr.kinematic_drawing(mech, pos, w2, "acceleration", mu_a, vel)
    groups, mb = (), None
    if forces is not None and (model.bodies or model.resistances):
        loads: dict[str, list] = {}
        couples = {}
        g0 = model.gravity
        for b in model.bodies:
            if b.mass:
                at = pos[b.com]
                loads.setdefault(b.link, []).append(gr.Force(f"G{b.link}", -1j * b.mass * g0, at))
                a_s = gr.point_acceleration(mech, pos, vel, acc, b.com)
                loads[b.link].append(gr.Force(f"FI{b.link}", -b.mass * a_s, at))
            if b.inertia:
                couples[b.link] = -b.inertia * acc.alpha.get(b.link, 0.0)
        multi = len(model.resistances) > 1
        for j, r in enumerate(model.resistances):
            f = complex(forces.resistance[f"R{j + 1}"][i] * np.exp(1j * r.direction))
            loads.setdefault(r.link, []).append(
                gr.Force(f"{r.symbol}{j + 1}" if multi else r.symbol, f, pos[r.point]))
        mu_f = {}
        for g in mech.groups:
            if g.links:
                names = [j.name for j in mech.joints[g.name]]
                big = [abs(forces.reactions[n][i]) for n in names if n in forces.reactions]
                big += [abs(f.value) for lk in g.links for f in loads.get(lk, [])]
                mu_f[g.name] = gr.nice_scale(_bound(big) / POLYGON_MM)
        groups = tuple(gr.force_drawing(mech, pos, loads, couples, mu_l, mu_f))
        crank = groups[-1]
        mb = float(k.sense * crank.balancing_torque)
    comparison = _compare(model, k, raw, forces, i, vel, acc, groups, mu_l)
    return GraphicalPosition(
        str(label), float(k.crank_angle[i] % (2 * np.pi)), mu_l, pos,
        KinPolygon("velocity", mu_v, dict(vel.points), tuple(vel.equations), dict(vel.omega)),
        KinPolygon("acceleration", mu_a, dict(acc.points), tuple(acc.equations),
                   dict(acc.alpha)),
        groups, mb, comparison)


def _row(name, unit, g, a, tol) -> Comparison:
    diff = (g - a) / abs(a) if abs(a) > 0 else 0.0
    return Comparison(name, unit, float(g), float(a), float(diff), float(tol), bool(abs(g - a) <= tol))


def _compare(model, k, raw, forces, i, vel, acc, groups, mu_l) -> tuple[Comparison, ...]:
    """Every link's ω and α, every drawn point's |v| and |a| (but the given ones), every
    reaction and M_b."""
    mech = model.mechanism
    out = []
    crank = mech.groups[0].link
    frame = set(mech.frame_points)
    lengths = {}
    for g in mech.groups:
        for link, pts in g.members()[0]:
            if len(pts) >= 2:
                lengths.setdefault(link, abs(raw.points[pts[1]].pos[i] - raw.points[pts[0]].pos[i]))
    for g in mech.groups:
        for link, pts in g.members()[0]:
            if link == crank:
                continue
            if any(r.quantity == f"ω{link}" for r in out):
                continue
            L = lengths.get(link, 1.0)
            # a link's ω and α signed (counter-clockwise positive), as the text lists them
            # (review39: the text's α2 = −9.81 rad/s² was 9.81 in the table)
            out.append(_row(f"ω{link}", "rad/s", vel.omega.get(link, 0.0),
                            raw.links[link].omega[i], 0.02 * abs(raw.links[link].omega[i])
                            + vel.scale / L))
            out.append(_row(f"α{link}", "rad/s²", acc.alpha.get(link, 0.0),
                            raw.links[link].alpha[i], 0.02 * abs(raw.links[link].alpha[i])
                            + 2 * acc.scale / L))
    for p, m in raw.points.items():
        if p in frame:
            continue
        # a point reached by given vectors only (the crank pin: ω·l, ω²·l with the brief's
        # ω) is drawn at its computed value: an input, not a result to compare
        name = gr.img(p, frame, "")
        if name in vel.points and name not in vel.exact:
            a = abs(m.vel[i])
            out.append(_row(f"v_{p}", "m/s", abs(vel.read(name)), a, 0.02 * a + vel.scale))
        name = gr.img(p, frame, "'")
        if name in acc.points and name not in acc.exact:
            a = abs(m.acc[i])
            out.append(_row(f"a_{p}", "m/s²", abs(acc.read(name)), a, 0.02 * a + 2 * acc.scale))
    for sl, v in vel.slide.items():
        a = abs(raw.slides[sl].ds[i])
        out.append(_row(f"v_r{sl}", "m/s", abs(v), a, 0.02 * a + vel.scale))
    if groups:
        cg = groups[-1]
        tip = complex(raw.points[mech.groups[0].tip].pos[i])
        pivot = complex(raw.points[mech.groups[0].pivot].pos[i])
        arm = abs(tip - pivot)
        for fg in groups:
            for name, value in fg.reactions.items():
                if name in forces.reactions:
                    a = abs(forces.reactions[name][i])
                elif (fg is cg and name.endswith("'") and name[:-1] in forces.reactions
                      and arm > 0):
                    # the crank's frame reaction with P_b at the pin in place of M_b (R72′ =
                    # R72 − P_b, the drawing sheet's polygon): the small closing side of two
                    # large, nearly opposite forces, so the drawing's rounding shows most here
                    # (the shaper's position 4: 225 N read, 193 N analytic); compared, so the
                    # report states both (review: the sheet's 193 N beside the report's 225 N)
                    pb = (float(k.sense * forces.balancing_torque[i]) / arm
                          * 1j * (tip - pivot) / arm)
                    a = abs(complex(forces.reactions[name[:-1]][i]) - pb)
                else:
                    continue
                out.append(_row(name, "N", abs(value), a, 0.02 * a + 2 * fg.scale))
        a = float(forces.balancing_torque[i])
        g_ = float(k.sense * cg.balancing_torque)
        out.append(_row("Mb", "N·m", g_, a, 0.02 * abs(a) + 2 * cg.scale * arm))
    return tuple(out)


def graphical(model, k, raw, forces, positions) -> GraphicalDocument:
    return GraphicalDocument(gr.STEP_MM, tuple(graphical_position(model, k, raw, forces, str(p))
                                               for p in positions))


def graphical_stage(model_key: str = "model", prefix: str = "linkage") -> Stage:
    """The stage that stores ``{prefix}_graphical`` at the polygon positions."""

    def run(r: dict) -> GraphicalDocument:
        k = r[prefix]
        forces = r.get(f"{prefix}_forces")
        return graphical(r[model_key], k, r[f"{prefix}_raw"], forces,
                         stage_positions(r, model_key, prefix))

    return Stage(f"{prefix}_graphical", titles.pgettext("stage", "graphical method"), run)
