"""Closed-form position, velocity and acceleration of planar Assur groups.

Points are complex numbers ``x + iy`` [m]; every function works on whole arrays of
crank positions at once (shape ``(N,)``). Angles are measured counter-clockwise
from +x [rad], angular velocities [rad/s] and accelerations [rad/s²] are
counter-clockwise positive.

The inner solvers return NaN where a group cannot be assembled; the mechanism layer
(:mod:`mechdesign.core.mechanism`) turns NaN into an error naming the group and angle.

Method: 孙桓《机械原理》 杆组法 (analysis by Assur groups). Velocities and accelerations
come from differentiating the closure equation of each group analytically; the two
unknowns of each group follow from a 2×2 real system solved by Cramer's rule.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class PointMotion:
    """Position [m], velocity [m/s] and acceleration [m/s²] of a point, complex arrays."""

    pos: np.ndarray
    vel: np.ndarray
    acc: np.ndarray


@dataclass(frozen=True)
class AngleMotion:
    """Angle [rad], angular velocity [rad/s], angular acceleration [rad/s²] of a link."""

    angle: np.ndarray
    omega: np.ndarray
    alpha: np.ndarray


@dataclass(frozen=True)
class SlideMotion:
    """Relative sliding of a slider on its guide: distance [m], speed [m/s], acceleration [m/s²]."""

    s: np.ndarray
    ds: np.ndarray
    dds: np.ndarray


def cross(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    """z-component of the planar cross product p × q for complex vectors."""
    return (np.conj(p) * q).imag


def solve2(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Real x, y with ``a·x + b·y = c`` for complex a, b, c (Cramer's rule)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        x = cross(b, c) / cross(b, a)
        y = cross(a, c) / cross(a, b)
    return x, y


def fixed_point(xy: complex, n: int) -> PointMotion:
    """A frame point, repeated for n crank positions."""
    zero = np.zeros(n, dtype=complex)
    return PointMotion(np.full(n, complex(xy)), zero, zero.copy())


def point_on_link(origin: PointMotion, link: AngleMotion, distance: float,
                  offset_angle: float = 0.0) -> PointMotion:
    """A point rigidly attached to a link.

    The point lies ``distance`` [m] from ``origin`` (a point of the same link) in the
    direction ``link.angle + offset_angle``.
    """
    u = distance * np.exp(1j * (link.angle + offset_angle))
    vel = origin.vel + 1j * link.omega * u
    acc = origin.acc + (1j * link.alpha - link.omega**2) * u
    return PointMotion(origin.pos + u, vel, acc)


def crank(pivot: PointMotion, length: float, angle: np.ndarray, omega: float
          ) -> tuple[AngleMotion, PointMotion]:
    """Driving link turning at constant angular velocity ``omega`` [rad/s].

    ``angle`` [rad] is the array of crank angles. Returns the crank's angular motion
    and its tip.
    """
    angle = np.asarray(angle, dtype=float)
    w = np.full_like(angle, omega)
    motion = AngleMotion(angle, w, np.zeros_like(angle))
    return motion, point_on_link(pivot, motion, length)


def rrr(b: PointMotion, d: PointMotion, l1: float, l2: float, branch: int
        ) -> tuple[AngleMotion, AngleMotion, PointMotion]:
    """RRR dyad: link 1 (B–C, length l1) and link 2 (D–C, length l2) meet at C.

    ``branch`` = +1 puts C to the left of B→D (counter-clockwise from BD), −1 to the right.
    Returns the motions of link 1 (angle of B→C), link 2 (angle of D→C) and of C.
    """
    bd = d.pos - b.pos
    dist = np.abs(bd)
    with np.errstate(divide="ignore", invalid="ignore"):
        cos_beta = (l1**2 + dist**2 - l2**2) / (2.0 * l1 * dist)
    beta = np.arccos(np.where(np.abs(cos_beta) <= 1.0, cos_beta, np.nan))
    th1 = np.angle(bd) + branch * beta
    u1 = l1 * np.exp(1j * th1)
    c_pos = b.pos + u1
    u2 = c_pos - d.pos
    th2 = np.angle(u2)
    # vB + iω1·u1 = vD + iω2·u2
    w1, w2 = solve2(1j * u1, -1j * u2, d.vel - b.vel)
    rhs = d.acc - b.acc + w1**2 * u1 - w2**2 * u2
    a1, a2 = solve2(1j * u1, -1j * u2, rhs)
    link1 = AngleMotion(th1, w1, a1)
    link2 = AngleMotion(th2, w2, a2)
    c = PointMotion(c_pos, b.vel + 1j * w1 * u1, b.acc + (1j * a1 - w1**2) * u1)
    return link1, link2, c


def rrp(b: PointMotion, length: float, guide_point: complex, guide_angle: float,
        branch: int) -> tuple[AngleMotion, SlideMotion, PointMotion]:
    """RRP dyad: link B–C (length) with C on a slider moving along a frame guide.

    The guide is the frame line through ``guide_point`` with direction ``guide_angle``
    [rad]; ``branch`` = +1 puts C ahead of B's foot on the guide (along the guide
    direction), −1 behind it. Returns the rod's motion (angle of B→C), the slider's
    position along the guide measured from ``guide_point``, and C.
    """
    e = np.exp(1j * guide_angle)
    w = b.pos - guide_point
    along = (np.conj(e) * w).real
    h = (np.conj(e) * w).imag
    root = length**2 - h**2
    s = along + branch * np.sqrt(np.where(root >= 0.0, root, np.nan))
    c_pos = guide_point + s * e
    u = c_pos - b.pos
    th = np.angle(u)
    # vB + iω·u = ṡ·e
    w_rod, ds = solve2(1j * u, -e * np.ones_like(u), -b.vel)
    rhs = -b.acc + w_rod**2 * u
    a_rod, dds = solve2(1j * u, -e * np.ones_like(u), rhs)
    rod = AngleMotion(th, w_rod, a_rod)
    slide = SlideMotion(s, ds, dds)
    c = PointMotion(c_pos, ds * e, dds * e)
    return rod, slide, c


def rpr(a: PointMotion, pivot: PointMotion, branch: int, offset: float = 0.0
        ) -> tuple[AngleMotion, SlideMotion]:
    """RPR dyad: a slider pinned at A slides along a guide bar pinned at ``pivot``.

    The slider's path is parallel to the bar at perpendicular distance ``offset`` [m]
    (to the bar's left); ``branch`` = +1 when the bar points from the pivot towards A,
    −1 when it points away. Returns the bar's angular motion (the slider turns with
    it) and the slider's position along the bar from the pivot, its relative (sliding)
    velocity and acceleration. The Coriolis acceleration of A on the bar is
    ``2·ω·ṡ`` perpendicular to the bar.
    """
    r = a.pos - pivot.pos
    dist2 = np.abs(r) ** 2
    root = dist2 - offset**2
    s = branch * np.sqrt(np.where(root >= 0.0, root, np.nan))
    th = np.angle(r) - np.arctan2(offset, s)
    u = np.exp(1j * th)
    # vA − vO = iω·r + ṡ·u   (r = s·u + offset·iu)
    w, ds = solve2(1j * r, u, a.vel - pivot.vel)
    rhs = a.acc - pivot.acc + w**2 * r - 2.0 * w * ds * 1j * u
    al, dds = solve2(1j * r, u, rhs)
    return AngleMotion(th, w, al), SlideMotion(s, ds, dds)
