"""Velocity, acceleration and force polygons (速度、加速度、力多边形) as data.

The graphical (relative-motion) method builds a velocity polygon from vector equations
such as v_C = v_B + v_CB, group by group in the order the mechanism is solved; the
acceleration polygon adds normal and tangential components (and the Coriolis term 2ω·v_rel
where a slider slides on a turning guide); a force polygon lays an Assur group's known
loads tip to tail (weights, inertia forces, external loads, the reactions passed on by the
later groups) and closes it with the reactions of the group's outer joints.

A :class:`Polygon` is plain data: named points (the pole at 0) and named vectors tail →
head with their values in SI units (complex x + iy), plus the vector equations it was
built from (two paths of vector names with the same start and end). The group classes of
:mod:`.mechanism` add their own vectors (``velocity_polygon``, ``acceleration_polygon``,
``force_polygon``); nothing here draws.

Names follow the textbook: the image of point B is ``b`` (``b'`` in the acceleration
polygon), the pole ``p`` (``p'``; a mechanism point P is written ``p(P)``); the image of the point of a guide bar 4 that coincides
with the slider's pin A is ``a4``; the intermediate point of a normal + tangential pair on
link 3 is ``n3'``; the Coriolis point ``k'``. Force polygons number their vertices 0, 1, …
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np



@dataclass(frozen=True)
class Vector:
    """One vector of a polygon from point ``tail`` to ``head``; ``value`` in SI (complex).

    ``role``: velocity/acceleration polygons "absolute" (from the pole), "relative"
    (rotation of a link: v = iω·r), "normal" (−ω²·r), "tangential" (iα·r), "sliding"
    (relative motion along a guide), "coriolis" (2ω·v_rel); force polygons "known" (a load
    of the group's links), "reaction" (an outer joint's reaction that closes the polygon),
    "internal" (the reaction between the group's links, the diagonal)."""

    name: str
    tail: str
    head: str
    value: complex
    role: str = ""


@dataclass(frozen=True)
class Equation:
    """A vector equation of the construction: the vectors of ``left`` laid tip to tail
    reach the same point as those of ``right`` (both start at the same point)."""

    text: str
    left: tuple
    right: tuple


@dataclass(frozen=True)
class Polygon:
    """``kind`` velocity | acceleration | force; ``group`` the Assur group (force polygons);
    ``position`` the position label; ``points`` name → location (SI, pole at 0);
    ``moments`` couples acting on the group that a force polygon cannot show [N·m]
    (inertia couples, the balancing torque "Mb" on the crank, CCW +)."""

    kind: str
    position: str
    points: dict
    vectors: tuple
    equations: tuple = ()
    group: str = ""
    moments: dict = field(default_factory=dict)

    def vector(self, name: str) -> Vector:
        return next(v for v in self.vectors if v.name == name)


def spread(points) -> tuple[float, float]:
    """(length, width) of a set of points (complex): their extent along their main direction
    and across it (0 width: the points lie on one line, as a polygon whose vectors are all
    parallel)."""
    z = np.asarray(list(points), dtype=complex)
    if len(z) < 2:
        return 0.0, 0.0
    xy = np.column_stack([z.real, z.imag])
    xy = xy - xy.mean(axis=0)
    _u, _sv, vt = np.linalg.svd(xy, full_matrices=False)
    return float(np.ptp(xy @ vt[0])), float(np.ptp(xy @ vt[1]))


def image_name(point: str, prime: str = "") -> str:
    """The polygon name of moving point ``point``: its name in lower case (``b``, ``b'``);
    a point whose lower-case name is the pole's (``P``) is written ``p(P)`` so that it
    does not take the pole's place."""
    low = point.lower()
    return (f"p({point})" if low == "p" else low) + prime


class Builder:
    """Collects the points, vectors and equations of a velocity or acceleration polygon.

    ``prime`` is "" (velocities) or "'" (accelerations); frame points map onto the pole."""

    def __init__(self, kind: str, frame_points, index: int, prime: str = ""):
        self.kind, self.prime, self.i = kind, prime, index
        self.pole = "p" + prime
        self.points: dict[str, complex] = {self.pole: 0j}
        self.vectors: list[Vector] = []
        self.equations: list[Equation] = []
        self.frame = set(frame_points)

    def img(self, point: str) -> str:
        """The polygon point of mechanism point ``point`` (the pole for a frame point)."""
        return self.pole if point in self.frame else image_name(point, self.prime)

    def value(self, point_motion) -> complex:
        """A mechanism point's velocity or acceleration at this entry."""
        return complex((point_motion.vel if self.prime == "" else point_motion.acc)[self.i])

    def put(self, name: str, value: complex) -> str:
        self.points[name] = complex(value)
        return name

    def fresh(self, base: str) -> str:
        """An unused point name ``base'`` (or ``base.2'``, …)."""
        name, k = base + self.prime, 2
        while name in self.points:
            name, k = f"{base}.{k}{self.prime}", k + 1
        return name

    def vec(self, tail: str, head: str, value: complex, role: str) -> str:
        name = f"{tail}{head}"
        self.vectors.append(Vector(name, tail, head, complex(value), role))
        return name

    def path_to(self, name: str) -> list[str]:
        """Vector names from the pole to polygon point ``name`` (one absolute vector;
        none for the pole itself)."""
        if name == self.pole:
            return []
        for v in self.vectors:
            if v.tail == self.pole and v.head == name:
                return [v.name]
        return [self.vec(self.pole, name, self.points[name], "absolute")]

    def rotation(self, tail: str, head: str, link, r: complex, link_id: str = "") -> list[str]:
        """The motion of ``head`` relative to ``tail`` on a link turning at ω, α, r = the
        vector from tail to head on the mechanism: one vector iω·r (velocities), or the
        normal −ω²·r and the tangential iα·r components (accelerations; a component that
        is exactly zero, as α of a crank at constant speed, is left out)."""
        w, al = float(link.omega[self.i]), float(link.alpha[self.i])
        if self.prime == "":
            return [self.vec(tail, head, 1j * w * r, "relative")]
        n, t = -w * w * r, 1j * al * r
        if t == 0:
            return [self.vec(tail, head, n, "normal")]
        if n == 0:
            return [self.vec(tail, head, t, "tangential")]
        base = f"n{link_id}"
        if base + self.prime in self.points:
            base = f"n{link_id}{head.rstrip(self.prime)}"
        mid = self.put(self.fresh(base), self.points[tail] + n)
        return [self.vec(tail, mid, n, "normal"), self.vec(mid, head, t, "tangential")]

    def equation(self, text: str, left: list[str], right: list[str]) -> None:
        self.equations.append(Equation(text, tuple(left), tuple(right)))

    def polygon(self, position: str) -> Polygon:
        return Polygon(self.kind, position, dict(self.points), tuple(self.vectors),
                       tuple(self.equations))


def kinematic_polygon(mech, motion, index: int, position: str, kind: str) -> Polygon:
    """The velocity (``kind`` "velocity") or acceleration polygon of the whole mechanism at
    entry ``index`` of the motion arrays, built group by group."""
    b = Builder(kind, mech.frame_points, index, "" if kind == "velocity" else "'")
    for g in mech.groups:
        if kind == "velocity":
            g.velocity_polygon(b, motion)
        else:
            g.acceleration_polygon(b, motion)
    return b.polygon(position)


def force_polygon(group, joints: dict, loads: dict, reactions: dict, moments: dict,
                  position: str, tol: float = 1e-9) -> Polygon:
    """The force polygon of ``group`` (its links in order): per link its known loads
    (``loads[link]``: (name, force) pairs), the reactions passed on by later groups, the
    reaction of its outer joint; after the first link of a dyad the diagonal back to the
    start is the reaction between the links. ``joints`` maps every group's name to its
    joints, ``reactions`` every joint's R{a}{b} (force of link a on link b) to its value.
    Forces smaller than ``tol`` × the largest are left out (e.g. no cutting force on the
    return stroke)."""
    links = list(group.links)
    own = joints[group.name]
    later = [j for name, js in joints.items() if name != group.name for j in js
             if j.link_a in links and j.link_b not in links]
    parts = []                       # per link: [(name, value, role)]
    for link in links:
        items = [(n, complex(f), "known") for n, f in loads.get(link, [])]
        items += [(f"R{j.link_b}{j.link_a}", -complex(reactions[j.name]), "known")
                  for j in later if j.link_a == link]
        items += [(j.name, complex(reactions[j.name]), "reaction")
                  for j in own if j.link_b == link and j.link_a not in links]
        parts.append(items)
    scale = max([abs(f) for items in parts for _, f, _ in items] + [0.0])
    pts, vecs, at = {"0": 0j}, [], 0j
    left: list[str] = []
    for k, items in enumerate(parts):
        for name, f, role in items:
            if scale == 0 or abs(f) < tol * scale:
                continue
            tail = list(pts)[-1]
            at = at + f
            head = str(len(pts))
            pts[head] = at
            vecs.append(Vector(name, tail, head, f, role))
        if k == 0 and len(links) == 2:
            left = [v.name for v in vecs]
            inner = [j for j in own if j.link_a in links and j.link_b in links]
            if inner and scale > 0:
                j = inner[0]
                f = complex(reactions[j.name])
                on_first = -f if j.link_a == links[0] else f
                tail = list(pts)[-1]
                if abs(on_first) >= tol * scale and tail != "0":
                    vecs.append(Vector(f"R{links[1]}{links[0]}", tail, "0", on_first, "internal"))
    eqs = ()
    if vecs:
        closing = [v.name for v in vecs if v.role != "internal"]
        eqs = (Equation("ΣF = 0", tuple(closing), ()),)
        if left and any(v.role == "internal" for v in vecs):
            eqs += (Equation(f"ΣF on link {links[0]} = 0",
                             tuple(left) + (f"R{links[1]}{links[0]}",), ()),)
    return Polygon("force", position, pts, tuple(vecs), eqs, group.name, dict(moments))


def linkage_force_polygons(mech, motion, index: int, position: str, bodies, gravity: float,
                           external: list, reactions: dict, inertia_force: dict,
                           inertia_couple: dict, driving_torque: float) -> list[Polygon]:
    """The force polygon of every group that has links (the crank first) at entry ``index``.

    ``bodies``: objects with link, mass, com; ``external``: (link, name, force) of the
    external loads at this entry; ``reactions``/``inertia_force``/``inertia_couple``: the
    kinetostatic results at this entry; ``driving_torque``: M_b on the driver (CCW +)."""
    loads: dict[str, list] = {}
    for b in bodies:
        if b.mass:
            loads.setdefault(b.link, []).append((f"G{b.link}", -1j * b.mass * gravity))
            if b.link in inertia_force:
                loads[b.link].append((f"FI{b.link}", inertia_force[b.link]))
    for link, name, f in external:
        loads.setdefault(link, []).append((name, f))
    out = []
    for g in mech.groups:
        if not g.links:
            continue
        moments = {f"MI{link}": float(inertia_couple[link]) for link in g.links
                   if link in inertia_couple}
        own = reactions
        group_loads = loads
        if g.driver is not None:
            moments["Mb"] = float(driving_torque)
            # the balancing force P_b at the crank pin ⊥ the crank (its moment about the
            # pivot is M_b); the frame reaction then closes the polygon with it (R' = R − P_b)
            r = complex(motion.points[g.tip].pos[index] - motion.points[g.pivot].pos[index])
            if abs(r) > 0 and driving_torque:
                pb = float(driving_torque) / abs(r) * 1j * r / abs(r)
                group_loads = {**loads, g.link: list(loads.get(g.link, [])) + [("Pb", pb)]}
                own = dict(reactions)
                for j in mech.joints[g.name]:
                    own[j.name] = complex(reactions[j.name]) - pb
        poly = g.force_polygon(mech.joints, group_loads, own, moments, position)
        if group_loads is not loads:
            # with P_b in place of M_b the frame reaction is the primed one (R' = R − P_b),
            # as the graphical method's text names it
            primed = {v.name: v.name + "'" for v in poly.vectors if v.role == "reaction"}
            poly = replace(poly, vectors=tuple(replace(v, name=primed.get(v.name, v.name))
                                               for v in poly.vectors),
                           equations=tuple(replace(e, left=tuple(primed.get(n, n) for n in e.left),
                                                   right=tuple(primed.get(n, n) for n in e.right))
                                           for e in poly.equations))
        out.append(poly)
    return out
