"""Kinetostatics (动态静力分析) group by group, last group first.

d'Alembert: each moving link carries its inertia force −m·a_S at its centre of mass S
and inertia couple −J_S·α, its weight, the external loads, and the reactions of its
joints. Groups are solved in the reverse of the kinematic order, so a group's outer
joints to later groups are already known; each dyad is statically determinate
(6 equations: ΣFx, ΣFy, ΣM per link; 6 unknowns: 2 per revolute, a normal force and
a couple per prismatic pair), and the crank group gives the balancing torque M_b.

All quantities SI: forces [N] as complex numbers Fx + iFy, moments [N·m]
counter-clockwise positive. Every step covers all crank angles at once (whole arrays).

Each group is solved the textbook way (杆组法), in closed form: the driving link's three
equations give its pivot reaction and the balancing torque directly; in a dyad, each link
has one equation free of its outer joint's two unknowns (moments about that joint's pin,
or the force balance along that joint's guide), and these two equations give the inner
joint's two unknowns (Cramer's rule); each link's remaining equations then give its outer
joint. ``dense=True`` solves every group's 3k × 3k system with ``np.linalg.solve``
instead (the reference the closed forms are tested against; also the route for any
group shape other than a driver or a dyad).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .kinematics import cross, dot
from .mechanism import Joint, Mechanism, Motion

STANDARD_GRAVITY = 9.81  # [m/s²]; gravity acts along −y


@dataclass(frozen=True)
class Body:
    """Mass properties of link ``link``: mass [kg] at point ``com``, J_S [kg·m²] about it."""

    link: str
    mass: float = 0.0
    com: str | None = None
    inertia: float = 0.0


@dataclass(frozen=True)
class PointLoad:
    """External force [N] (complex array) on ``link``, applied at the named point."""

    link: str
    point: str
    force: np.ndarray


@dataclass(frozen=True)
class JointReaction:
    """Reaction of a joint: ``force`` [N] exerted by ``joint.link_a`` on ``joint.link_b``.

    For a prismatic pair the force is normal to the guide and ``couple`` [N·m] is the
    moment the guide also transmits; its line of action is shifted along the guide
    from the slider point along the guide direction by ``couple / normal`` [m]
    (the textbook's h).
    """

    joint: Joint
    force: np.ndarray
    couple: np.ndarray | None = None


@dataclass(frozen=True)
class ForceAnalysis:
    """Joint reactions by name (R{a}{b}), driving torque [N·m] on the driver link (CCW+),
    and the d'Alembert inertia loads used."""

    reactions: dict[str, JointReaction]
    driving_torque: np.ndarray
    inertia_force: dict[str, np.ndarray]
    inertia_couple: dict[str, np.ndarray]


def _guide_direction(j: Joint, motion: Motion):
    """Unit vector along the guide of prismatic joint ``j`` (an array, or a constant)."""
    if j.guide_link is not None:
        return np.exp(1j * motion.links[j.guide_link].angle)
    return complex(np.exp(1j * j.guide_angle))


# A planar wrench (Fx, Fy, M about the origin) as a tuple of three arrays or numbers; each
# link's three equilibrium equations say that the wrenches on it add up to zero. Unit
# wrenches have many entries 0 and ±1; _mul _add and _sub skip the array work for those.

def _is(x, value: float) -> bool:
    return isinstance(x, float) and x == value


def _mul(a, b):
    for x, y in ((a, b), (b, a)):
        if _is(x, 0.0):
            return 0.0
        if _is(x, 1.0):
            return y
        if _is(x, -1.0):
            return -y
    return a * b


def _add(*terms):
    out = 0.0
    for t in terms:
        if not _is(t, 0.0):
            out = t if _is(out, 0.0) else out + t
    return out


def _sub(a, b):
    if _is(b, 0.0):
        return a
    return -b if _is(a, 0.0) else a - b


def _dot3(a, b):
    return _add(_mul(a[0], b[0]), _mul(a[1], b[1]), _mul(a[2], b[2]))


def _cross3(a, b):
    return (_sub(_mul(a[1], b[2]), _mul(a[2], b[1])),
            _sub(_mul(a[2], b[0]), _mul(a[0], b[2])),
            _sub(_mul(a[0], b[1]), _mul(a[1], b[0])))


def _scaled(a, k):
    return tuple(_mul(x, k) for x in a)


def _unit_wrenches(j: Joint, motion: Motion) -> list:
    """The wrench on link b per unit value of each of the joint's two unknowns.

    Revolute at P: Fx and Fy acting at P. Prismatic: the normal force N along i·e at
    the slider point and the couple the guide transmits."""
    p = motion.points[j.point].pos
    if j.kind == "R":
        return [(1.0, 0.0, -p.imag), (0.0, 1.0, p.real)]
    normal = 1j * _guide_direction(j, motion)
    return [(normal.real, normal.imag, cross(p, normal)), (0.0, 0.0, 1.0)]


def _solve_driver(cols: list, rhs) -> list:
    """One link, three unknowns (the pivot's two and the balancing torque): Cramer's rule
    with 3×3 determinants det(a, b, c) = a · (b × c)."""
    a, b, c = cols
    with np.errstate(divide="ignore", invalid="ignore"):
        det = _dot3(a, _cross3(b, c))
        return [_dot3(rhs, _cross3(b, c)) / det, _dot3(a, _cross3(rhs, c)) / det,
                _dot3(a, _cross3(b, rhs)) / det]


def _solve_dyad(outer: list, inner: list, rhs: list) -> tuple[list, list]:
    """Two links k = 0, 1; ``outer[k]`` the two unknowns' wrench columns of link k's outer
    joint, ``inner[k]`` those of the joint between the links (on link k), ``rhs[k]`` minus
    the known wrench on link k. Returns the inner joint's two unknowns and, per link, its
    outer joint's two.

    n_k = a_k × c_k (a_k, c_k = outer[k]) is the combination of link k's three equations
    in which the outer joint's unknowns cancel: for a pin at P it is (y_P, −x_P, 1), the
    moment equation about P; for a slider it is the force balance along its guide."""
    n = [_cross3(*outer[k]) for k in (0, 1)]
    m = [[_dot3(n[k], inner[k][i]) for i in (0, 1)] for k in (0, 1)]
    r = [_dot3(n[k], rhs[k]) for k in (0, 1)]
    with np.errstate(divide="ignore", invalid="ignore"):
        det = m[0][0] * m[1][1] - m[0][1] * m[1][0]
        x = [(r[0] * m[1][1] - m[0][1] * r[1]) / det, (m[0][0] * r[1] - r[0] * m[1][0]) / det]
        outer_x = []
        for k in (0, 1):
            # What the outer joint must carry: a·y0 + c·y1 = rest, consistent by
            # construction, so y0 = (rest × c)·n / |n|², y1 = (a × rest)·n / |n|².
            p, q = inner[k]
            rest = tuple(_sub(_sub(rhs[k][i], _mul(p[i], x[0])), _mul(q[i], x[1]))
                         for i in range(3))
            a, c = outer[k]
            nn = _dot3(n[k], n[k])
            outer_x.append([_dot3(_cross3(rest, c), n[k]) / nn,
                            _dot3(_cross3(a, rest), n[k]) / nn])
    return x, outer_x


def _solve_dense(cols: list, rhs: list, links: list, n: int) -> list:
    """Any statically determinate group: its 3k × 3k system for every angle, one batched
    ``np.linalg.solve``. ``cols[i]`` maps each link to unknown i's wrench column."""
    size = 3 * len(links)
    A = np.zeros((n, size, size))
    b = np.zeros((n, size))
    for k, link in enumerate(links):
        for row in range(3):
            b[:, 3 * k + row] = rhs[k][row]
            for i, col in enumerate(cols):
                if link in col:
                    A[:, 3 * k + row, i] = col[link][row]
    with np.errstate(all="ignore"):
        x = np.linalg.solve(A, b[..., None])[..., 0]
    return [x[:, i] for i in range(size)]


def solve_forces(mech: Mechanism, motion: Motion, bodies: list[Body],
                 loads: list[PointLoad], gravity: float = STANDARD_GRAVITY,
                 dense: bool = False) -> ForceAnalysis:
    """Joint reactions and the balancing (driving) torque at every crank angle.

    ``dense`` solves each group as one dense linear system instead of in closed form."""
    n = len(motion.crank_angle)
    # Known load on each link: resultant force and moment about the origin.
    force: dict[str, np.ndarray] = {}
    moment: dict[str, np.ndarray] = {}

    def add(link, f=None, at=None, couple=None):
        if f is not None:
            force[link] = force[link] + f if link in force else f
            moment[link] = moment[link] + cross(at, f) if link in moment else cross(at, f)
        if couple is not None:
            moment[link] = moment[link] + couple if link in moment else couple

    inertia_force, inertia_couple = {}, {}
    for b in bodies:
        if b.mass:
            s = motion.points[b.com]
            inertia_force[b.link] = -b.mass * s.acc
            add(b.link, inertia_force[b.link] - 1j * b.mass * gravity, s.pos)
        if b.inertia:
            inertia_couple[b.link] = -b.inertia * motion.links[b.link].alpha
            add(b.link, couple=inertia_couple[b.link])
    for ld in loads:
        add(ld.link, ld.force, motion.points[ld.point].pos)

    reactions: dict[str, JointReaction] = {}
    torque = np.zeros(n)
    for g in reversed(mech.groups):
        joints = mech.joints[g.name]
        if not g.links:
            continue
        links = list(g.links)
        # Wrench columns of every unknown on the group's links: +unit on link b, −unit
        # on link a (Newton's third law); the driver's balancing torque last.
        unknowns = []   # (joint or None, {link: column})
        for j in joints:
            for unit in _unit_wrenches(j, motion):
                col = {}
                if j.link_b in links:
                    col[j.link_b] = unit
                if j.link_a in links:
                    col[j.link_a] = _scaled(unit, -1.0)
                unknowns.append((j, col))
        if g.driver is not None:
            unknowns.append((None, {g.driver: (0.0, 0.0, 1.0)}))
        if len(unknowns) != 3 * len(links):
            raise ValueError(f"group '{g.name}' is not statically determinate "
                             f"({len(unknowns)} unknowns, {3 * len(links)} equations)")
        rhs = []
        for link in links:
            f, m = force.get(link, 0j), moment.get(link, 0.0)
            rhs.append((-np.real(f), -np.imag(f), -m))
        x = None
        if not dense:
            x = _solve_closed_form(links, unknowns, rhs)
        if x is None:
            x = _solve_dense([col for _, col in unknowns], rhs, links, n)
        for i in range(0, len(joints) * 2, 2):
            j = unknowns[i][0]
            p = motion.points[j.point].pos
            if j.kind == "R":
                reaction = JointReaction(j, x[i] + 1j * x[i + 1])
            else:
                normal = 1j * _guide_direction(j, motion)
                reaction = JointReaction(j, x[i] * normal, couple=x[i + 1])
            reactions[j.name] = reaction
            if j.link_a not in links:  # pass the reaction on to the earlier link
                add(j.link_a, -reaction.force, p,
                    None if reaction.couple is None else -reaction.couple)
        if g.driver is not None:
            torque = x[-1]
    return ForceAnalysis(reactions, torque, inertia_force, inertia_couple)


def _solve_closed_form(links: list, unknowns: list, rhs: list):
    """The unknowns of a driver link or of a dyad in closed form, or None for any other
    group shape."""
    cols = [col for _, col in unknowns]
    if len(links) == 1:
        return _solve_driver([col[links[0]] for col in cols], rhs[0])
    if len(links) != 2 or len(cols) != 6 or any(j is None for j, _ in unknowns):
        return None
    pairs = [cols[i:i + 2] for i in (0, 2, 4)]          # two unknowns per joint
    inner = [p for p in pairs if len(p[0]) == 2]
    outer = {link: p for p in pairs if len(p[0]) == 1 for link in p[0]}
    if len(inner) != 1 or set(outer) != set(links):
        return None
    x_in, x_out = _solve_dyad([[c[link] for c in outer[link]] for link in links],
                              [[c[link] for c in inner[0]] for link in links], rhs)
    out = []
    for p in pairs:
        out += x_in if p is inner[0] else x_out[links.index(next(iter(p[0])))]
    return out


def power_residual(mech: Mechanism, motion: Motion, bodies: list[Body],
                   loads: list[PointLoad], driving_torque: np.ndarray,
                   gravity: float = STANDARD_GRAVITY) -> np.ndarray:
    """Σ power of all applied and inertia loads plus the driving torque [W].

    By the principle of virtual power this is zero for ideal joints; it is an
    independent check of :func:`solve_forces` that never looks at a reaction.
    """
    total = np.zeros(len(motion.crank_angle))
    for b in bodies:
        if b.mass:
            s = motion.points[b.com]
            total += dot(-b.mass * s.acc - 1j * b.mass * gravity, s.vel)
        if b.inertia:
            w = motion.links[b.link]
            total += -b.inertia * w.alpha * w.omega
    for ld in loads:
        total += dot(ld.force, motion.points[ld.point].vel)
    driver = next(g.driver for g in mech.groups if g.driver is not None)
    return total + driving_torque * motion.links[driver].omega
