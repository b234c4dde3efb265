"""Kinetostatics (动态静力分析) group by group, last group first.

d'Alembert: each moving link carries its inertia force −m·a_S at its centre of mass S
and inertia couple −J_S·α, its weight, the external loads, and the reactions of its
joints. Groups are solved in the reverse of the kinematic order, so a group's outer
joints to later groups are already known; each dyad is statically determinate
(6 equations: ΣFx, ΣFy, ΣM per link; 6 unknowns: 2 per revolute, a normal force and
a couple per prismatic pair), and the crank group gives the balancing torque M_b.

All quantities SI: forces [N] as complex numbers Fx + iFy, moments [N·m]
counter-clockwise positive. One batched linear solve per group covers every crank
angle at once.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .kinematics import cross
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


def _guide_direction(j: Joint, motion: Motion) -> np.ndarray:
    if j.guide_link is not None:
        return np.exp(1j * motion.links[j.guide_link].angle)
    n = len(motion.crank_angle)
    return np.full(n, np.exp(1j * j.guide_angle))


def solve_forces(mech: Mechanism, motion: Motion, bodies: list[Body],
                 loads: list[PointLoad], gravity: float = STANDARD_GRAVITY) -> ForceAnalysis:
    """Joint reactions and the balancing (driving) torque at every crank angle."""
    n = len(motion.crank_angle)
    # Known loads on each link: (force, point-of-application) pairs and couples.
    forces: dict[str, list[tuple[np.ndarray, np.ndarray]]] = {}
    couples: dict[str, list[np.ndarray]] = {}
    inertia_force, inertia_couple = {}, {}
    for b in bodies:
        if b.mass:
            s = motion.points[b.com]
            f = -b.mass * s.acc - 1j * b.mass * gravity
            inertia_force[b.link] = -b.mass * s.acc
            forces.setdefault(b.link, []).append((f, s.pos))
        if b.inertia:
            c = -b.inertia * motion.links[b.link].alpha
            inertia_couple[b.link] = c
            couples.setdefault(b.link, []).append(c)
    for ld in loads:
        forces.setdefault(ld.link, []).append((ld.force, motion.points[ld.point].pos))

    reactions: dict[str, JointReaction] = {}
    torque = np.zeros(n)
    for g in reversed(mech.groups):
        joints = mech.joints[g.name]
        if not g.links:
            continue
        row = {link: 3 * k for k, link in enumerate(g.links)}
        size = 3 * len(g.links)
        A = np.zeros((n, size, size))
        rhs = np.zeros((n, size))
        for link, r in row.items():
            for f, p in forces.get(link, []):
                rhs[:, r] -= f.real
                rhs[:, r + 1] -= f.imag
                rhs[:, r + 2] -= cross(p, f)
            for c in couples.get(link, []):
                rhs[:, r + 2] -= c
        col = 0
        columns = []
        for j in joints:
            p = motion.points[j.point].pos
            # Unit "force per unknown" on link b for the two unknowns of the joint.
            if j.kind == "R":
                units = [(np.ones(n, complex), 0.0), (np.full(n, 1j), 0.0)]
            else:
                normal = 1j * _guide_direction(j, motion)
                units = [(normal, 0.0), (np.zeros(n, complex), 1.0)]
            for k, (u, m_unit) in enumerate(units):
                for link, sign in ((j.link_b, 1.0), (j.link_a, -1.0)):
                    if link in row:
                        r = row[link]
                        A[:, r, col + k] += sign * u.real
                        A[:, r + 1, col + k] += sign * u.imag
                        A[:, r + 2, col + k] += sign * (cross(p, u) + m_unit)
            columns.append((j, col, units))
            col += 2
        if g.driver is not None:
            A[:, row[g.driver] + 2, col] = 1.0
            col += 1
        if col != size:
            raise ValueError(f"group '{g.name}' is not statically determinate "
                             f"({col} unknowns, {size} equations)")
        with np.errstate(all="ignore"):
            x = np.linalg.solve(A, rhs[..., None])[..., 0]
        for j, c0, units in columns:
            p = motion.points[j.point].pos
            if j.kind == "R":
                force = x[:, c0] + 1j * x[:, c0 + 1]
                reaction = JointReaction(j, force)
            else:
                force = x[:, c0] * units[0][0]
                reaction = JointReaction(j, force, couple=x[:, c0 + 1])
            reactions[j.name] = reaction
            if j.link_a not in row:  # pass the reaction on to the earlier link
                forces.setdefault(j.link_a, []).append((-force, p))
                if reaction.couple is not None:
                    couples.setdefault(j.link_a, []).append(-reaction.couple)
        if g.driver is not None:
            torque = x[:, col - 1]
    return ForceAnalysis(reactions, torque, inertia_force, inertia_couple)


def power_residual(mech: Mechanism, motion: Motion, bodies: list[Body],
                   loads: list[PointLoad], driving_torque: np.ndarray,
                   gravity: float = STANDARD_GRAVITY) -> np.ndarray:
    """Σ power of all applied and inertia loads plus the driving torque [W].

    By the principle of virtual power this is zero for ideal joints; it is an
    independent check of :func:`solve_forces` that never looks at a reaction.
    """
    def dot(f, v):
        return (np.conj(f) * v).real

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
