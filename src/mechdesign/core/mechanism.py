"""A planar mechanism as a driving crank followed by Assur groups.

A :class:`Mechanism` knows frame points, groups added in solving order and the
joints between links; it solves the motion of every point and link for a whole array
of crank angles in one pass (one numpy call chain per group). Nothing here knows
about any particular machine.

Links and points are named by strings (the course numbers links: "2" the crank, ...);
each joint records which link is already known (``link_a``: frame or an earlier group)
and which belongs to the group (``link_b``), the order kinetostatics needs.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from . import kinematics as kin
from .kinematics import AngleMotion, PointMotion, SlideMotion


class AssemblyError(ValueError):
    """A group cannot be assembled at some crank angle."""

    def __init__(self, group: str, kind: str, crank_angle_deg: float, count: int):
        self.group, self.kind = group, kind
        self.crank_angle_deg, self.count = crank_angle_deg, count
        super().__init__(
            f"group '{group}' ({kind}) cannot be assembled at crank angle "
            f"{crank_angle_deg:.2f}° (and {count - 1} more of the angles asked): "
            "the links are too short to close; check the lengths or the branch")


@dataclass(frozen=True)
class Joint:
    """A kinematic pair between an already-known link ``link_a`` and a group's ``link_b``.

    kind "R": revolute at point ``point``; kind "P": prismatic, the slider reference
    point ``point`` moving along a guide whose direction is the angle of link
    ``guide_link`` (or the fixed ``guide_angle`` [rad]).
    """

    kind: str
    point: str
    link_a: str
    link_b: str
    guide_link: str | None = None
    guide_angle: float | None = None

    @property
    def name(self) -> str:
        """Course symbol of the reaction: force of link a on link b, F_R{a}{b}."""
        return f"R{self.link_a}{self.link_b}"


@dataclass
class Motion:
    """Motion of every named point, link and slider over the crank-angle array."""

    crank_angle: np.ndarray
    points: dict[str, PointMotion] = field(default_factory=dict)
    links: dict[str, AngleMotion] = field(default_factory=dict)
    slides: dict[str, SlideMotion] = field(default_factory=dict)


class Group(Protocol):
    name: str
    kind: str
    links: tuple[str, ...]
    driver: str | None

    @property
    def outer(self) -> tuple[str, ...]:
        """Points of earlier groups or the frame that this group attaches to."""
    @property
    def produced(self) -> dict[str, str]:
        """Points this group adds, each with the link that carries it."""
    def joints(self, owner: dict[str, str]) -> tuple[Joint, ...]:
        """The group's joints, given the carrying link of every known point."""
    def solve(self, m: Motion) -> None:
        """Add the group's links, sliders and points to ``m``."""


def _const_angle(angle: float, n: int) -> AngleMotion:
    z = np.zeros(n)
    return AngleMotion(np.full(n, angle), z, z.copy())


@dataclass(frozen=True)
class Crank:
    """Driving link ``link`` turning about ``pivot`` at constant ``omega`` [rad/s]; tip ``tip``."""

    name: str
    link: str
    pivot: str
    tip: str
    length: float
    omega: float
    kind: str = "crank"

    @property
    def links(self): return (self.link,)

    @property
    def driver(self): return self.link

    @property
    def outer(self): return (self.pivot,)

    @property
    def produced(self): return {self.tip: self.link}

    def joints(self, owner):
        return (Joint("R", self.pivot, owner[self.pivot], self.link),)

    def solve(self, m):
        m.links[self.link], m.points[self.tip] = kin.crank(
            m.points[self.pivot], self.length, m.crank_angle, self.omega)


@dataclass(frozen=True)
class RRR:
    """RRR dyad: ``link1`` from B to C (l1), ``link2`` from D to C (l2)."""

    name: str
    link1: str
    link2: str
    b: str
    d: str
    c: str
    l1: float
    l2: float
    branch: int
    kind: str = "RRR"
    driver = None

    @property
    def links(self): return (self.link1, self.link2)

    @property
    def outer(self): return (self.b, self.d)

    @property
    def produced(self): return {self.c: self.link1}

    def joints(self, owner):
        return (Joint("R", self.b, owner[self.b], self.link1),
                Joint("R", self.c, self.link1, self.link2),
                Joint("R", self.d, owner[self.d], self.link2))

    def solve(self, m):
        l1, l2, c = kin.rrr(m.points[self.b], m.points[self.d], self.l1, self.l2, self.branch)
        m.links[self.link1], m.links[self.link2], m.points[self.c] = l1, l2, c


@dataclass(frozen=True)
class RRP:
    """RRP dyad: rod ``rod`` from B to C, slider ``slider`` at C on a frame guide."""

    name: str
    rod: str
    slider: str
    b: str
    c: str
    length: float
    guide_point: complex
    guide_angle: float
    branch: int
    frame: str
    kind: str = "RRP"
    driver = None

    @property
    def links(self): return (self.rod, self.slider)

    @property
    def outer(self): return (self.b,)

    @property
    def produced(self): return {self.c: self.slider}

    def joints(self, owner):
        return (Joint("R", self.b, owner[self.b], self.rod),
                Joint("R", self.c, self.rod, self.slider),
                Joint("P", self.c, self.frame, self.slider, guide_angle=self.guide_angle))

    def solve(self, m):
        rod, slide, c = kin.rrp(m.points[self.b], self.length, self.guide_point,
                                self.guide_angle, self.branch)
        m.links[self.rod], m.slides[self.slider], m.points[self.c] = rod, slide, c
        m.links[self.slider] = _const_angle(self.guide_angle, len(m.crank_angle))


@dataclass(frozen=True)
class RPR:
    """RPR dyad: ``slider`` pinned at A slides on guide bar ``bar`` pinned at ``pivot``."""

    name: str
    slider: str
    bar: str
    a: str
    pivot: str
    branch: int
    offset: float = 0.0
    kind: str = "RPR"
    driver = None

    @property
    def links(self): return (self.slider, self.bar)

    @property
    def outer(self): return (self.a, self.pivot)

    @property
    def produced(self): return {}

    def joints(self, owner):
        return (Joint("R", self.a, owner[self.a], self.slider),
                Joint("P", self.a, self.bar, self.slider, guide_link=self.bar),
                Joint("R", self.pivot, owner[self.pivot], self.bar))

    def solve(self, m):
        bar, slide = kin.rpr(m.points[self.a], m.points[self.pivot], self.branch, self.offset)
        m.links[self.bar] = m.links[self.slider] = bar
        m.slides[self.slider] = slide


@dataclass(frozen=True)
class LinkPoint:
    """A named point fixed on ``link``: ``distance`` [m] from its point ``origin`` at
    ``offset_angle`` [rad] from the link's direction. Adds no joint."""

    name: str
    link: str
    origin: str
    distance: float
    offset_angle: float = 0.0
    kind: str = "point"
    links = ()
    driver = None

    @property
    def outer(self): return (self.origin,)

    @property
    def produced(self): return {self.name: self.link}

    def joints(self, owner):
        return ()

    def solve(self, m):
        m.points[self.name] = kin.point_on_link(
            m.points[self.origin], m.links[self.link], self.distance, self.offset_angle)


class Mechanism:
    """Frame points plus groups in solving order (the crank first)."""

    def __init__(self, frame: str, frame_points: dict[str, complex]):
        self.frame = frame
        self.frame_points = dict(frame_points)
        self.groups: list = []
        self.joints: dict[str, tuple[Joint, ...]] = {}
        self._owner = {p: frame for p in frame_points}

    def add(self, group) -> "Mechanism":
        """Append a group; its outer points must already exist."""
        missing = [p for p in group.outer if p not in self._owner]
        if missing:
            raise ValueError(f"group '{group.name}' needs points {missing} defined before it")
        self.joints[group.name] = group.joints(self._owner)
        self._owner.update(group.produced)
        self.groups.append(group)
        return self

    def solve(self, crank_angle: np.ndarray) -> Motion:
        """Motion of everything for crank angles [rad] (array). Raises AssemblyError."""
        phi = np.atleast_1d(np.asarray(crank_angle, dtype=float))
        m = Motion(phi)
        for name, xy in self.frame_points.items():
            m.points[name] = kin.fixed_point(xy, len(phi))
        for g in self.groups:
            g.solve(m)
            _check_assembled(g, m, g.produced, phi)
        return m


def _check_assembled(group, m: Motion, produced: dict[str, str], phi: np.ndarray) -> None:
    bad = np.zeros(len(phi), dtype=bool)
    for link in group.links:
        bad |= ~np.isfinite(m.links[link].angle)
    for p in produced:
        bad |= ~np.isfinite(m.points[p].pos)
    if bad.any():
        first = float(np.degrees(phi[bad][0]) % 360.0)
        raise AssemblyError(group.name, group.kind, first, int(bad.sum()))
