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

Speed (issue 8): every function below is a short chain of whole-array numpy operations.
Trigonometric functions are the expensive part (~10 ns per angle each, against ~1 ns for
an addition), so unit vectors e^{iθ} come from the closure geometry where the group gives
them for free (the RRR's rotation by β, the RPR's r = (s + i·e)·u) and from cos/sin only
where an angle is the input (crank, point on a link). Constants (frame points, the crank's
ω, a fixed guide's angle) are read-only full-length broadcast views of one number: they
behave as arrays of shape (N,) for every reader and cost no memory.
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


def cross(p, q):
    """z-component of the planar cross product p × q for complex vectors (or scalars)."""
    return p.real * q.imag - p.imag * q.real


def dot(p, q):
    """Scalar product p · q of complex vectors (or scalars)."""
    return p.real * q.real + p.imag * q.imag


def solve2(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Real x, y with ``a·x + b·y = c`` for complex a, b, c (Cramer's rule)."""
    return _cramer(a, b, c, cross(a, b))


def _cramer(a, b, c, det):
    """solve2 with the determinant a × b given (groups reuse it for ω and α)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return cross(c, b) / det, cross(a, c) / det


def unit(angle: np.ndarray) -> np.ndarray:
    """e^{iθ} for an array of angles, as cos θ + i·sin θ (faster than np.exp(1j·θ))."""
    angle = np.asarray(angle, dtype=float)
    u = np.empty(angle.shape, dtype=complex)
    np.cos(angle, out=u.real)
    np.sin(angle, out=u.imag)
    return u


def constant(value, n: int) -> np.ndarray:
    """A read-only array of n equal entries (a broadcast view: no memory per entry)."""
    return np.broadcast_to(value, (n,))


def fixed_point(xy: complex, n: int) -> PointMotion:
    """A frame point, repeated for n crank positions (read-only constant arrays)."""
    zero = constant(0j, n)
    return PointMotion(constant(complex(xy), n), zero, zero)


def _moving(origin: PointMotion, u: np.ndarray, omega, alpha) -> tuple[np.ndarray, np.ndarray]:
    """Velocity and acceleration of the point at ``origin + u`` on a link turning at ω, α
    (u rigid on the link): v = v_O + iω·u,  a = a_O + (iα − ω²)·u."""
    vel = 1j * u
    vel *= omega
    vel += origin.vel
    acc = (1j * alpha - omega * omega) * u
    acc += origin.acc
    return vel, acc


def _carried(origin: PointMotion, u: np.ndarray, omega, alpha, *, own: bool = False
             ) -> PointMotion:
    """The point at ``origin + u`` on a link turning at ω, α (see :func:`_moving`); with
    ``own`` the caller's temporary ``u`` becomes the position (added to in place: one array
    fewer)."""
    vel, acc = _moving(origin, u, omega, alpha)
    if own:
        u += origin.pos
        return PointMotion(u, vel, acc)
    return PointMotion(origin.pos + u, vel, acc)


def point_on_link(origin: PointMotion, link: AngleMotion, distance: float,
                  offset_angle: float = 0.0) -> PointMotion:
    """A point rigidly attached to a link.

    The point lies ``distance`` [m] from ``origin`` (a point of the same link) in the
    direction ``link.angle + offset_angle``.
    """
    u = unit(link.angle + offset_angle if offset_angle else link.angle)
    u *= distance
    return _carried(origin, u, link.omega, link.alpha, own=True)


def crank(pivot: PointMotion, length: float, angle: np.ndarray, omega: float
          ) -> tuple[AngleMotion, PointMotion]:
    """Driving link turning at constant angular velocity ``omega`` [rad/s].

    ``angle`` [rad] is the array of crank angles. Returns the crank's angular motion
    and its tip.
    """
    angle = np.asarray(angle, dtype=float)
    n = len(angle)
    motion = AngleMotion(angle, constant(float(omega), n), constant(0.0, n))
    u = unit(angle)
    u *= length
    return motion, _carried(pivot, u, float(omega), 0.0, own=True)


def rrr(b: PointMotion, d: PointMotion, l1: float, l2: float, branch: int
        ) -> tuple[AngleMotion, AngleMotion, PointMotion]:
    """RRR dyad: link 1 (B–C, length l1) and link 2 (D–C, length l2) meet at C.

    ``branch`` = +1 puts C to the left of B→D (counter-clockwise from BD), −1 to the right.
    Returns the motions of link 1 (angle of B→C), link 2 (angle of D→C) and of C.
    """
    bd = d.pos - b.pos
    dist = np.abs(bd)
    with np.errstate(divide="ignore", invalid="ignore"):
        cos_beta = (l1**2 + dist**2 - l2**2) / (2.0 * l1 * dist)   # law of cosines
        cos_beta[~(np.abs(cos_beta) <= 1.0)] = np.nan            # cannot close there
    beta = np.arccos(cos_beta)
    th1 = np.arctan2(bd.imag, bd.real) + branch * beta          # angle(BD) ± β
    del beta
    # e^{iθ1} = e^{i·angle(BD)}·e^{±iβ}: rotate the unit vector along BD by β
    # (sin β = √((1 − cos β)(1 + cos β)), accurate near β = 0 and π).
    rot = np.empty_like(bd)
    rot.real = cos_beta
    np.sqrt((1.0 - cos_beta) * (1.0 + cos_beta), out=rot.imag)
    rot.imag *= branch
    rot *= bd
    rot *= l1 / dist
    u1 = rot                                  # B→C
    del bd, dist, cos_beta                    # (temporaries freed early: less memory)
    c_pos = b.pos + u1
    u2 = c_pos - d.pos                        # D→C
    th2 = np.arctan2(u2.imag, u2.real)
    # Closure B + u1 = D + u2 differentiated: iω1·u1 − iω2·u2 = vD − vB.
    col1, col2 = 1j * u1, -1j * u2            # the 2×2 system's columns, for ω and α
    det = cross(col1, col2)
    w1, w2 = _cramer(col1, col2, d.vel - b.vel, det)
    # Twice: iα1·u1 − iα2·u2 = aD − aB + ω1²·u1 − ω2²·u2.
    rhs = d.acc - b.acc
    rhs += (w1 * w1) * u1
    rhs -= (w2 * w2) * u2
    a1, a2 = _cramer(col1, col2, rhs, det)
    link1 = AngleMotion(th1, w1, a1)
    link2 = AngleMotion(th2, w2, a2)
    vel, acc = _moving(b, u1, w1, a1)
    return link1, link2, PointMotion(c_pos, vel, acc)


def rrp(b: PointMotion, length: float, guide_point: complex, guide_angle: float,
        branch: int) -> tuple[AngleMotion, SlideMotion, PointMotion]:
    """RRP dyad: link B–C (length) with C on a slider moving along a frame guide.

    The guide is the frame line through ``guide_point`` with direction ``guide_angle``
    [rad]; ``branch`` = +1 puts C ahead of B's foot on the guide (along the guide
    direction), −1 behind it. Returns the rod's motion (angle of B→C), the slider's
    position along the guide measured from ``guide_point``, and C.
    """
    e = np.exp(1j * guide_angle)
    # The closure equation's complex products written out in real arithmetic where that
    # gives the same bits (fewer passes over the arrays, fewer temporaries: issue 22's peer
    # figure); the products numpy rounds its own way (a complex array times a complex
    # number) are kept as they were.
    er, ei = e.real, e.imag
    local = (b.pos - guide_point) * np.conj(e)   # B in guide coordinates (numpy's complex
                                                 # product, as its rounding is)
    s = local.real.copy()
    h = local.imag
    root = h * h                                 # l² − h², in place
    del local, h
    np.subtract(length**2, root, out=root)
    root[~(root >= 0.0)] = np.nan                # the rod cannot reach the guide there
    np.sqrt(root, out=root)
    if branch != 1:
        root *= branch
    s += root
    del root
    c_pos = s * e
    c_pos += guide_point
    u = c_pos - b.pos
    ux, uy = u.real, u.imag
    th = np.arctan2(uy, ux)
    # vB + iω·u = ṡ·e  →  iω·u − ṡ·e = −vB (Cramer's rule on its real and imaginary parts;
    # det = (iu) × (−e) = u·e)
    det = ux * er
    det += uy * ei
    vb, ab = b.vel, b.acc
    with np.errstate(divide="ignore", invalid="ignore"):
        w_rod = vb.real * ei
        w_rod -= vb.imag * er
        w_rod /= det
        ds = ux * vb.real
        ds += uy * vb.imag
        ds /= det
        # Twice: iα·u − s̈·e = ω²·u − aB
        w2 = w_rod * w_rod
        rx = w2 * ux
        rx -= ab.real
        ry = w2 * uy
        ry -= ab.imag
        del w2
        a_rod = ry * er
        a_rod -= rx * ei
        a_rod /= det
        rx *= ux
        ry *= uy
        rx += ry
        dds = np.negative(rx, out=rx)
        dds /= det
    del ry
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
    root[~(root >= 0.0)] = np.nan
    s = np.sqrt(root)
    s *= branch
    th = np.arctan2(r.imag, r.real) - np.arctan2(offset, s)
    # The bar's unit vector from the closure r = (s + i·offset)·u, no trigonometry.
    u = r * (s - 1j * offset)
    u /= dist2
    # vA − vO = iω·r + ṡ·u   (r = s·u + offset·iu)
    ir = 1j * r
    det = cross(ir, u)
    w, ds = _cramer(ir, u, a.vel - pivot.vel, det)
    # aA − aO = iα·r − ω²·r + 2ω·ṡ·iu + s̈·u
    rhs = a.acc - pivot.acc
    rhs += (w * w) * r
    rhs -= (2.0 * w * ds) * (1j * u)
    al, dds = _cramer(ir, u, rhs, det)
    return AngleMotion(th, w, al), SlideMotion(s, ds, dds)
