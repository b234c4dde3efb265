"""Disc cams (盘形凸轮): follower programme, followers, profile synthesis, base-circle design,
and the analysis of a given eccentric circular disc.

Method (孙桓《机械原理》, chapter on cam mechanisms): the profile is found by inversion
(反转法). Everything is written in complex numbers and differentiated exactly with
respect to the cam angle δ, so no derivative in this module is numerical:

* the cam turns with sense σ = +1 (counter-clockwise) or −1 (clockwise); δ ≥ 0 is the
  angle it has turned; a point ``P`` fixed in the frame is ``P·e^(−iσδ)`` on the cam;
* the pitch curve (理论廓线) is the path of the roller centre (or knife edge) in the cam
  frame; the actual profile (实际廓线) of a roller follower is its exact envelope, the
  curve at distance r_r along the pitch curve's normal (not a radial offset);
* a flat-faced follower's profile is the envelope of its face: with the face's distance
  h from the cam centre and the angle ψ of its normal, the contact point is
  e^(iψ)(h + i·dh/dψ) and the radius of curvature is ρ = h + d²h/dψ²;
* the pressure angle (压力角) is the angle between the common normal at the contact and the
  velocity of the follower point there;
* the radius of curvature is ρ = |p'|³ / (p' × p''), positive where the profile is convex.

SI units throughout: metres, radians. Translating followers move along +y; their offset
is the signed x of their axis (+ to the right of the cam centre). The offset that lowers
the rise pressure angle (正偏置) is on the right for a counter-clockwise cam and on the
left for a clockwise one: ``favourable_offset_sign(rotation)``.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .errors import DesignError, N_
from .fields import q
from .motion_laws import LAWS

TWO_PI = 2.0 * np.pi
RISE, DWELL, RETURN = "rise", "dwell", "return"
NO_IMPACT, SOFT_IMPACT, RIGID_IMPACT = "none", "soft", "rigid"
_SEVERITY = {NO_IMPACT: 0, SOFT_IMPACT: 1, RIGID_IMPACT: 2}


class CamDesignError(DesignError):
    """A cam that cannot be built with the given data; the message says what to change."""


# --------------------------------------------------------------------------- programme


@dataclass(frozen=True)
class Segment:
    """One part of the follower programme.

    ``span`` [rad]; ``law`` a key of :data:`LAWS` (not for a dwell); ``lift`` the
    follower's travel in this segment [m or rad], always positive: ``None`` means the whole
    stroke for a rise and back to the start for a return.
    """

    kind: str
    span: float
    law: str | None = None
    lift: float | None = None


@dataclass(frozen=True)
class FollowerMotion:
    """Follower displacement and its derivatives with respect to the cam angle."""

    delta: np.ndarray     # cam angle [rad], in [0, 2π)
    s: np.ndarray         # displacement from the lowest position [m] or [rad]
    ds: np.ndarray        # ds/dδ
    d2s: np.ndarray       # d²s/dδ²
    d3s: np.ndarray       # d³s/dδ³
    segment: np.ndarray   # index of the programme segment


@dataclass(frozen=True)
class Boundary:
    """The joint between two segments at cam angle ``delta``, with what jumps there."""

    delta: float = q("rad", "cam angle δ of the joint")
    velocity_jump: float = q("m/rad or rad/rad", "jump of ds/dδ (per radian of cam angle)")
    acceleration_jump: float = q("m/rad² or rad/rad²", "jump of d²s/dδ²")
    impact: str = q("", "'none' | 'soft' | 'rigid'")


class Programme:
    """A follower programme: rise / dwell / return segments covering one revolution.

    The follower starts at its lowest position (s = 0) at δ = 0.
    """

    def __init__(self, segments: list[Segment], stroke: float | None = None):
        if not segments:
            raise CamDesignError(N_("the programme has no segments"))
        for i, seg in enumerate(segments):
            if seg.kind not in (RISE, DWELL, RETURN):
                raise CamDesignError(N_("segment {i}: kind {kind!r} is not rise, dwell or "
                                        "return"), i=i + 1,
                                     kind=seg.kind)
            if not seg.span > 0:
                raise CamDesignError(N_("segment {i}: its angle must be positive"), i=i + 1)
            if seg.kind != DWELL and seg.law not in LAWS:
                raise CamDesignError(N_("segment {i}: motion law {law!r} is not one of {laws}"),
                                     i=i + 1, law=seg.law, laws=', '.join(LAWS))
        total = sum(seg.span for seg in segments)
        if abs(total - TWO_PI) > 1e-9:
            raise CamDesignError(N_("the segment angles add up to {total_deg:.4g}°, not 360°"),
                                 total_deg=np.degrees(total))
        rises = [seg.lift for seg in segments if seg.kind == RISE]
        if stroke is None:
            stroke = max((x for x in rises if x is not None), default=None)
        if stroke is None or not stroke > 0:
            raise CamDesignError(N_("the programme needs a stroke (a rise with a lift)"))
        self.segments = tuple(segments)
        self.stroke = float(stroke)
        self.spans = np.array([seg.span for seg in segments])
        self.starts = np.concatenate([[0.0], np.cumsum(self.spans)[:-1]])
        levels, lifts, level = [], [], 0.0
        for i, seg in enumerate(segments):
            levels.append(level)
            if seg.kind == RISE:
                lift = self.stroke if seg.lift is None else seg.lift
            elif seg.kind == RETURN:
                lift = -(level if seg.lift is None else seg.lift)
            else:
                lift = 0.0
            level += lift
            if level > self.stroke * (1 + 1e-9) or level < -self.stroke * 1e-9:
                raise CamDesignError(N_("segment {i}: the follower would reach {level:.6g}, "
                                        "outside 0 … stroke {stroke:.6g}"),
                                     i=i + 1, level=level, stroke=self.stroke)
            lifts.append(lift)
        if abs(level) > self.stroke * 1e-9:
            raise CamDesignError(N_("the programme ends at {level:.6g} instead of returning "
                                    "to the start (0): the returns must undo the rises"),
                                 level=level)
        self.levels = np.array(levels)
        self.lifts = np.array(lifts)

    def evaluate(self, delta) -> FollowerMotion:
        """Displacement and exact derivatives at cam angles ``delta`` [rad] (vectorised)."""
        d = np.mod(np.asarray(delta, dtype=float), TWO_PI)
        idx = np.clip(np.searchsorted(self.starts, d, side="right") - 1, 0, len(self.segments) - 1)
        s = np.empty_like(d)
        ds, d2s, d3s = np.zeros_like(d), np.zeros_like(d), np.zeros_like(d)
        for i, seg in enumerate(self.segments):
            m = idx == i
            if not np.any(m):
                continue
            if seg.kind == DWELL:
                s[m] = self.levels[i]
                continue
            span, lift = self.spans[i], self.lifts[i]
            u = np.clip((d[m] - self.starts[i]) / span, 0.0, 1.0)
            S, S1, S2, S3 = LAWS[seg.law](u)
            s[m] = self.levels[i] + lift * S
            ds[m] = lift * S1 / span
            d2s[m] = lift * S2 / span**2
            d3s[m] = lift * S3 / span**3
        return FollowerMotion(d, s, ds, d2s, d3s, idx)

    def end_values(self, i: int, u: float) -> tuple[float, float, float, float]:
        """s, ds/dδ, d²s/dδ², d³s/dδ³ of segment ``i`` at its own u ∈ [0, 1] (u = 1 is the
        left-hand limit at the segment's end, which ``evaluate`` gives to the next segment)."""
        seg = self.segments[i]
        if seg.kind == DWELL:
            return float(self.levels[i]), 0.0, 0.0, 0.0
        S, S1, S2, S3 = (float(x) for x in LAWS[seg.law](np.array(u)))
        lift, span = self.lifts[i], self.spans[i]
        return (float(self.levels[i] + lift * S), lift * S1 / span, lift * S2 / span**2,
                lift * S3 / span**3)

    def boundaries(self) -> list[Boundary]:
        """What happens at the start of every segment (cyclically, so the first one is δ = 0)."""
        n = len(self.segments)
        out = []
        for i in range(n):
            _, v0, a0, _ = self.end_values((i - 1) % n, 1.0)
            _, v1, a1, _ = self.end_values(i, 0.0)
            out.append(self._jump(float(self.starts[i]), v1 - v0, a1 - a0))
        return out

    def _jump(self, delta: float, dv: float, da: float) -> Boundary:
        """The jump (dv, da) at cam angle ``delta`` classified: a velocity jump is a rigid
        impact (刚性冲击), a finite acceleration jump a soft one (柔性冲击), else none; jumps
        below 10⁻⁹ of the programme's scale (stroke over its shortest segment) are round-off."""
        v_scale = self.stroke / np.min(self.spans)
        if abs(dv) > 1e-9 * v_scale:
            impact = RIGID_IMPACT
        elif abs(da) > 1e-9 * v_scale / np.min(self.spans):
            impact = SOFT_IMPACT
        else:
            impact = NO_IMPACT
        return Boundary(delta, dv, da, impact)

    def internal_jumps(self) -> list[tuple[int, Boundary]]:
        """Velocity or acceleration jumps inside a segment, found from its law: the one-sided
        limits of S' and S'' at every breakpoint where the law's formula changes (the
        parabolic law's middle u = 1/2 jumps from +4 to −4; the modified laws' breakpoints
        are smooth and give none). (segment index, the jump as a Boundary at its cam angle)."""
        out = []
        for i, seg in enumerate(self.segments):
            if seg.kind == DWELL:
                continue
            for bp in LAWS[seg.law].breakpoints:
                _, v0, a0, _ = self.end_values(i, bp)                        # piece u ≤ bp
                _, v1, a1, _ = self.end_values(i, float(np.nextafter(bp, 2.0)))  # piece u > bp
                b = self._jump(float(self.starts[i] + bp * self.spans[i]), v1 - v0, a1 - a0)
                if b.impact != NO_IMPACT:
                    out.append((i, b))
        return out

    def impacts(self) -> list[str]:
        """Per segment: 'rigid' (velocity jump, 刚性冲击), 'soft' (acceleration jump, 柔性冲击)
        or 'none', from its two ends and its interior. Dwells report 'none': a jump at the
        joint of a dwell and a motion belongs to the motion."""
        b = self.boundaries()
        inside = self.internal_jumps()
        n = len(self.segments)
        out = []
        for i, seg in enumerate(self.segments):
            if seg.kind == DWELL:
                out.append(NO_IMPACT)
                continue
            found = [b[i].impact, b[(i + 1) % n].impact] + [j.impact for k, j in inside if k == i]
            out.append(max(found, key=_SEVERITY.get))
        return out


# --------------------------------------------------------------------------- followers


@dataclass(frozen=True)
class TranslatingFollower:
    """直动从动件: ``kind`` knife | roller | flat; ``offset`` the signed x of its axis [m]
    (+ right of the cam centre); ``roller_radius`` [m] (roller only). A flat face is
    perpendicular to the axis."""

    kind: str
    offset: float = 0.0
    roller_radius: float = 0.0


@dataclass(frozen=True)
class OscillatingFollower:
    """摆动从动件: ``kind`` roller | flat; pivot A at ``pivot_distance`` a from the cam centre
    [m]; ``arm_length`` L to the roller centre [m] (roller only); a flat face passes through
    the pivot. ``rise_sense`` 'same' if during the rise the follower turns the same way as the
    cam, 'opposite' otherwise. The programme's displacement is the arm angle φ [rad]."""

    kind: str
    pivot_distance: float
    arm_length: float = 0.0
    roller_radius: float = 0.0
    rise_sense: str = "same"


def favourable_offset_sign(rotation: int) -> int:
    """Sign of the offset x that lowers the rise pressure angle: + (right) for a
    counter-clockwise cam, − (left) for a clockwise one."""
    return 1 if rotation > 0 else -1


def _roller(follower) -> float:
    return follower.roller_radius if follower.kind == "roller" else 0.0


def arm_side(follower: OscillatingFollower, sigma: int) -> int:
    # The arm angle is β = π − k(φ0 + φ); during the rise it turns with sense −k.
    return -sigma if follower.rise_sense == "same" else sigma


def initial_arm_angle(follower: OscillatingFollower, base_radius: float) -> float:
    """φ0: the arm's angle from the line of centres when the roller centre (or the face)
    touches the base circle, e.g. φ0 = arccos((a² + L² − r0²)/(2aL)) for a roller."""
    a, L, r0 = follower.pivot_distance, follower.arm_length, base_radius
    if follower.kind == "flat":
        if not 0 < r0 < a:
            raise CamDesignError(N_("a flat-faced oscillating follower needs base radius r0 < "
                                    "pivot distance a; r0 = {r0_mm:.4g} mm, a = {a_mm:.4g} mm"),
                                 r0_mm=r0 * 1e3, a_mm=a * 1e3)
        return float(np.arcsin(r0 / a))
    c = (a * a + L * L - r0 * r0) / (2 * a * L)
    if not -1.0 < c < 1.0:
        raise CamDesignError(
            N_("the roller centre cannot reach the base circle: r0 = {r0_mm:.4g} mm must lie "
               "between |a − L| = {diff_mm:.4g} mm and a + L = {sum_mm:.4g} mm"),
            r0_mm=r0 * 1e3, diff_mm=abs(a - L) * 1e3, sum_mm=(a + L) * 1e3)
    return float(np.arccos(c))


# --------------------------------------------------------------------------- synthesis


@dataclass(frozen=True)
class CamProfile:
    """A synthesised cam over the cam angles ``delta`` (cam-frame coordinates, cam centre
    at the origin; at δ = 0 the frame and cam coincide)."""

    delta: np.ndarray
    motion: FollowerMotion
    rotation: int
    base_radius: float           # r0 of the pitch curve (knife/roller) or of the profile (flat)
    roller_radius: float
    pitch: np.ndarray            # theoretical profile (complex) [m]; = actual for flat/knife
    actual: np.ndarray           # actual profile (complex) [m]
    normal: np.ndarray           # outward unit normal of the profile (complex, cam frame)
    pressure_angle: np.ndarray   # [rad], 0 … π/2
    rho_pitch: np.ndarray        # radius of curvature of the pitch curve [m], + convex
    rho_actual: np.ndarray       # radius of curvature of the actual profile [m], + convex
    follower_point: np.ndarray   # roller centre / knife edge / face foot in the frame (complex)
    contact: np.ndarray          # contact point in the frame (complex)
    initial_angle: float = 0.0   # φ0 [rad] (oscillating) or s0 = √(r0² − e²) [m] (translating)
    extras: dict = field(default_factory=dict)


def design_cam(programme: Programme, follower, base_radius: float, rotation: int = 1,
               points: int = 3600, delta=None) -> CamProfile:
    """Synthesise the cam for ``follower`` on a grid of ``points`` cam angles (or at the
    given ``delta`` [rad])."""
    sigma = 1 if rotation > 0 else -1
    if delta is None:
        delta = np.arange(points) * (TWO_PI / points)
    if not base_radius > 0:
        raise CamDesignError(N_("the base radius must be positive"))
    return _profile(programme.evaluate(delta), follower, base_radius, sigma)


def _profile(m: FollowerMotion, follower, base_radius: float, sigma: int) -> CamProfile:
    """The cam geometry for the follower motion ``m`` (values and derivatives at m.delta)."""
    d = m.delta
    rot = np.exp(-1j * sigma * d)
    if follower.kind == "flat":
        return _flat(follower, base_radius, sigma, m, rot)
    rr = _roller(follower)
    if isinstance(follower, TranslatingFollower):
        e = follower.offset
        if abs(e) >= base_radius:
            raise CamDesignError(N_("the offset |e| = {e_mm:.4g} mm must be smaller than the "
                                    "base radius r0 = {base_radius_mm:.4g} mm: increase the "
                                    "base radius or reduce the offset"),
                                 e_mm=abs(e) * 1e3, base_radius_mm=base_radius * 1e3)
        s0 = float(np.sqrt(base_radius**2 - e * e))
        B = e + 1j * (s0 + m.s)
        B1 = 1j * m.ds
        B2 = 1j * m.d2s
        direction = np.full_like(B, 1j)          # follower point moves along +y
        initial = s0
        A = None
    else:
        a, L = follower.pivot_distance, follower.arm_length
        phi0 = initial_arm_angle(follower, base_radius)
        k = arm_side(follower, sigma)
        beta = np.pi - k * (phi0 + m.s)
        b1, b2 = -k * m.ds, -k * m.d2s
        arm = L * np.exp(1j * beta)
        B = a + arm
        B1 = 1j * b1 * arm
        B2 = (1j * b2 - b1 * b1) * arm
        direction = 1j * np.exp(1j * beta)       # roller centre moves ⟂ to the arm
        initial = phi0
        A = a
    p = rot * B
    p1 = rot * (B1 - 1j * sigma * B)
    p2 = rot * (B2 - 2j * sigma * B1 - B)
    speed = np.abs(p1)
    t = p1 / speed
    n_out = 1j * sigma * t
    rho = -sigma * speed**3 / np.imag(np.conj(p1) * p2)
    actual = p - rr * n_out
    n_frame = n_out / rot
    cosang = np.abs(np.real(np.conj(n_frame) * direction))
    sinang = np.abs(np.imag(np.conj(n_frame) * direction))
    alpha = np.arctan2(sinang, cosang)
    extras = {} if A is None else {"pivot": A}
    return CamProfile(d, m, sigma, base_radius, rr, p, actual, n_out, alpha, rho, rho - rr,
                      B, B - rr * n_frame, initial, extras)


def _flat(follower, r0, sigma, m, rot) -> CamProfile:
    """Flat-faced followers: envelope of the face lines via the support function."""
    if isinstance(follower, TranslatingFollower):
        h, h1, h2 = r0 + m.s, m.ds, m.d2s
        psi = np.pi / 2 - sigma * m.delta
        psi1 = np.full_like(h, -float(sigma))
        psi2 = np.zeros_like(h)
        initial = r0
        extras = {}
    else:
        a = follower.pivot_distance
        g0 = initial_arm_angle(follower, r0)
        k = arm_side(follower, sigma)
        g = g0 + m.s
        h = a * np.sin(g)
        h1 = a * np.cos(g) * m.ds
        h2 = a * (np.cos(g) * m.d2s - np.sin(g) * m.ds**2)
        psi = np.pi - k * g - k * np.pi / 2 - sigma * m.delta
        psi1 = -k * m.ds - sigma
        psi2 = -k * m.d2s
        initial = g0
        extras = {"pivot": a}
    if np.any(np.abs(psi1) < 1e-12):
        raise CamDesignError(N_("the follower face turns as fast as the cam: no envelope "
                                "exists"))
    hp = h1 / psi1
    hpp = (h2 * psi1 - h1 * psi2) / psi1**3
    n_out = np.exp(1j * psi)
    contact_cam = n_out * (h + 1j * hp)
    rho = h + hpp
    contact = contact_cam / rot
    foot = n_out * h / rot
    zero = np.zeros_like(h)
    return CamProfile(m.delta, m, sigma, r0, 0.0, contact_cam, contact_cam, n_out, zero, rho, rho,
                      foot, contact, initial, extras)


# --------------------------------------------------------------------------- exact extremes


@dataclass(frozen=True)
class Extreme:
    """An extreme value of the cam's geometry in one segment: ``value`` at cam angle
    ``delta`` [rad]; ``side`` −1 where it is the left-hand limit at a law boundary (the end
    of a segment or of a piece of a piecewise law), +1 the right-hand limit, 0 inside."""

    value: float
    delta: float
    side: int = 0


@dataclass(frozen=True)
class SegmentExtremes:
    """The exact extremes of one segment (``None`` where there is nothing of that kind)."""

    max_pressure_angle: Extreme
    max_curvature: Extreme | None     # largest convex curvature 1/ρ of the pitch curve [1/m]
    min_curvature: Extreme | None     # most concave (most negative) curvature [1/m]
    min_rho: Extreme | None           # flat face: smallest ρ = h + h'' (any sign) [m]


def segment_pieces(programme: Programme, i: int) -> list[tuple[float, float]]:
    """The pieces [u_a, u_b] of segment ``i`` on which its law is one smooth formula: split
    at the law's breakpoints (e.g. the parabolic law's middle)."""
    seg = programme.segments[i]
    bps = () if seg.kind == DWELL else LAWS[seg.law].breakpoints
    edges = [0.0, *bps, 1.0]
    return list(zip(edges[:-1], edges[1:]))


def segment_motion(programme: Programme, i: int, u) -> FollowerMotion:
    """The follower motion of segment ``i`` at its own u ∈ [0, 1] (vectorised): u = 1 is the
    left-hand limit at its end, u = 0 its start; the cam angle is start + u·span (not wrapped
    to [0, 2π), so that the limit at 360° keeps its side)."""
    u = np.atleast_1d(np.asarray(u, dtype=float))
    seg = programme.segments[i]
    span, start = programme.spans[i], programme.starts[i]
    d = start + u * span
    idx = np.full(u.shape, i)
    if seg.kind == DWELL:
        z = np.zeros_like(u)
        return FollowerMotion(d, np.full_like(u, programme.levels[i]), z, z.copy(), z.copy(), idx)
    S, S1, S2, S3 = LAWS[seg.law](u)
    lift = programme.lifts[i]
    return FollowerMotion(d, programme.levels[i] + lift * S, lift * S1 / span,
                          lift * S2 / span**2, lift * S3 / span**3, idx)


def _piece_extreme(fun, ua: float, ub: float, samples: int, largest: bool = True,
                   where=None) -> tuple[float, float, int] | None:
    """(u, value, side) of the largest (smallest) value of ``fun`` on the closed piece
    [ua, ub] of one smooth formula; ``fun`` takes an array of u. The interior extremes are
    found by Brent's bounded search between the neighbours of every local extreme of a
    sample (the three best), the ends are evaluated as one-sided limits (u on the piece's
    own side: the adjacent float inside the piece at a law breakpoint). ``where``: only
    values for which where(value) holds count (None: all)."""
    from .extremes import fminbound

    sign = 1.0 if largest else -1.0
    # one-sided ends: just inside [ua, ub] where the neighbouring piece takes over at ua
    a = ua if ua == 0.0 else float(np.nextafter(ua, 1.0))
    b = ub
    u = np.linspace(a, b, samples + 1)
    v = sign * np.asarray(fun(u), dtype=float)
    ok = np.isfinite(v) if where is None else (np.isfinite(v) & where(sign * v))
    if not np.any(ok):
        return None
    w = np.where(ok, v, -np.inf)
    cand = [(float(u[k]), float(w[k])) for k in np.flatnonzero(ok)
            if (k == 0 or w[k] >= w[k - 1]) and (k == len(w) - 1 or w[k] >= w[k + 1])]
    cand.sort(key=lambda t: -t[1])
    best = cand[0]
    for uk, _ in cand[:3]:
        k = int(np.searchsorted(u, uk))
        lo, hi = float(u[max(k - 1, 0)]), float(u[min(k + 1, len(u) - 1)])
        if hi <= lo:
            continue

        def neg(x):
            val = sign * float(fun(np.array([x]))[0])
            ok1 = np.isfinite(val) and (where is None or bool(where(sign * val)))
            return -val if ok1 else np.inf

        x, fx = fminbound(neg, lo, hi, xatol=1e-13 * max(b - a, 1e-300) + 1e-16)
        if np.isfinite(fx) and -fx > best[1]:
            best = (float(x), -fx)
    side = -1 if best[0] == b else (1 if best[0] == a else 0)
    return best[0], sign * best[1], side


def _curvature(prof: CamProfile) -> np.ndarray:
    """Signed curvature 1/ρ of the pitch curve (+ convex); smooth where ρ passes ±∞."""
    with np.errstate(divide="ignore"):
        return 1.0 / prof.rho_pitch


def exact_extremes(programme: Programme, follower, base_radius: float, rotation: int = 1,
                   points: int = 3600) -> list[SegmentExtremes]:
    """Per segment, the exact largest pressure angle and the exact extreme curvatures of
    the pitch curve (the largest convex and the most concave curvature; for a flat face the
    smallest ρ of the profile), never read off a grid: every smooth piece of the segment's
    law is searched with Brent's bounded method from a sample (``points`` per revolution,
    at least 64 per piece) and its two ends enter as one-sided limits: a segment end, a
    jump of the curvature inside a law (parabolic: its middle). A rise over a tiny angle
    gets its true, nearly 90° pressure angle."""
    sigma = 1 if rotation > 0 else -1
    flat = follower.kind == "flat"
    out = []
    for i, seg in enumerate(programme.segments):
        span = programme.spans[i]
        found = {"alpha": [], "kmax": [], "kmin": [], "rho": []}
        if seg.kind == DWELL:
            # the follower stands still: the pitch curve is an arc about the cam centre, its
            # pressure angle and curvature constant: reported at the dwell's start
            pr = _profile(segment_motion(programme, i, 0.0), follower, base_radius, sigma)
            at = float(programme.starts[i])
            k = float(_curvature(pr)[0])
            out.append(SegmentExtremes(
                Extreme(float(pr.pressure_angle[0]), at, 1),
                Extreme(k, at, 1) if k > 0 and not flat else None,
                Extreme(k, at, 1) if k < 0 and not flat else None,
                Extreme(float(pr.rho_pitch[0]), at, 1) if flat else None))
            continue
        for ua, ub in segment_pieces(programme, i):
            n = max(64, int(np.ceil(points * span * (ub - ua) / TWO_PI)))

            def prof(u, i=i):
                return _profile(segment_motion(programme, i, u), follower, base_radius, sigma)

            def delta_of(u, i=i):
                return float(programme.starts[i] + u * programme.spans[i])

            def keep(key, res):
                if res is not None:
                    found[key].append(Extreme(res[1], delta_of(res[0]), res[2]))

            if not flat:
                keep("alpha", _piece_extreme(lambda u: prof(u).pressure_angle, ua, ub, n))
                keep("kmax", _piece_extreme(lambda u: _curvature(prof(u)), ua, ub, n,
                                            where=lambda k: k > 0))
                keep("kmin", _piece_extreme(lambda u: _curvature(prof(u)), ua, ub, n,
                                            largest=False, where=lambda k: k < 0))
            else:
                keep("alpha", (ua, 0.0, 0))
                keep("rho", _piece_extreme(lambda u: prof(u).rho_pitch, ua, ub, n, largest=False))
        pick = lambda key, f: (f(found[key], key=lambda e: e.value) if found[key] else None)  # noqa: E731
        out.append(SegmentExtremes(pick("alpha", max), pick("kmax", max), pick("kmin", min),
                                   pick("rho", min)))
    return out


# --------------------------------------------------------------------------- roller envelope


@dataclass(frozen=True)
class Corner:
    """A corner of the pitch curve: a joint where the follower's velocity jumps (刚性冲击)."""

    delta: float = q("rad", "cam angle of the joint")
    point: complex = q("m", "the corner P of the pitch curve (cam frame), [x, y]")
    turn: float = q("rad", "signed angle through which the profile normal turns at P")
    # "arc": the actual profile follows the roller circle about P (a concave arc of radius
    # r_r); "edge": the two offset branches cross, the loop between them is cut away and
    # the profile has a sharp edge
    kind: str = q("",
        "'arc' (the roller circle about P) | 'edge' (the loop cut away: a sharp edge)")
    # edge: how far the designed roller centre stands off the edge beyond r_r, at most
    # (the follower cannot follow exactly)
    stand_off: float = q("m", "edge: largest stand-off of the roller centre beyond r_r",
                         default=0.0)


@dataclass(frozen=True)
class RollerEnvelope:
    """The actual profile of a roller cam as it is cut: the envelope of the roller circles.

    The offset curve ``CamProfile.actual`` (r_r along each normal) is that envelope only where
    the pitch curve is smooth. At a corner of the pitch curve it leaves a gap on one side of
    the corner and a loop on the other: the gap is filled with the roller circle about the
    corner, the loop is cut at the crossing of its two branches (also any loop of an undercut
    profile). ``contact`` is, for every cam angle of the profile it was built from, the point
    of the real profile the roller touches: the offset point, or the edge where it was cut
    away (there the designed roller centre stands ``stand_off`` at most off the edge, beyond
    r_r: the follower cannot follow the velocity jump exactly)."""

    outline: np.ndarray              # closed polyline of the actual profile, cam frame [m]
    pitch_outline: np.ndarray        # closed polyline of the pitch curve with its corners [m]
    contact: np.ndarray              # per cam angle of the profile [m] (complex)
    trimmed: np.ndarray              # per cam angle: the offset point was cut away
    corners: tuple[Corner, ...]
    edges: tuple[tuple[float, float, complex, float], ...]   # (δ from, δ to, edge point,
                                     # stand-off [m]) of each cut
    stand_off: float                 # the largest stand-off [m]
    roller_radius: float             # [m]


def _segment_distance(p, a, d):
    """Distance from the points ``p`` to the segments from ``a`` along ``d`` (complex,
    broadcast)."""
    t = np.real(np.conj(d) * (p - a)) / np.maximum(np.abs(d) ** 2, 1e-300)
    return np.abs(p - (a + np.clip(t, 0.0, 1.0) * d))


def _lower_bound_by_owner(owner, dist, slack, bound, tol):
    """For pairs sorted by ``owner``: lower each owner's ``bound`` (in place) to its smallest
    ``dist + slack``, and return the mask of the pairs with ``dist - slack <= bound``."""
    if len(owner) == 0:
        return np.zeros(0, dtype=bool)
    first = np.flatnonzero(np.r_[True, owner[1:] != owner[:-1]])
    who = owner[first]
    bound[who] = np.minimum(bound[who], np.minimum.reduceat(dist + slack, first))
    return dist - slack <= bound[owner] + tol


_LEAF, _FAN, _TOP, _BATCH = 8, 8, 64, 65536


def polyline_distance(points, polyline) -> np.ndarray:
    """Shortest distance from each point (complex) to the closed polyline (complex vertices,
    the last joined to the first): exactly the minimum over all its segments, for any points.

    Pure numpy, no spatial index to import: the segments are grouped along the polyline
    into runs of 8, 64, 512, … consecutive segments; a run lies inside the capsule of
    radius ``dev`` (the largest distance of its vertices from it) around its chord, so its
    distance from a point is at least chord distance − dev and at most chord distance + dev.
    Walking down from the longest runs, a run is dropped where its lower bound exceeds the
    smallest upper bound found for the point; the segments of the runs of 8 that are left
    are measured. The points are taken in blocks of consecutive points inside a disk (the
    disk's radius widens both bounds), which is fast when they lie along a curve as the
    cam's do; any order gives the same result."""
    pts = np.atleast_1d(np.asarray(points, dtype=complex))
    poly = np.asarray(polyline, dtype=complex)
    m, n = len(poly), len(pts)
    out = np.full(n, np.nan)                        # stays NaN for a point that is not finite
    if n == 0 or m == 0:
        return out
    # runs of segments: run j of a level holds the segments [j·size, (j+1)·size)
    sizes = [_LEAF]
    while -(-m // sizes[-1]) > _TOP:
        sizes.append(sizes[-1] * _FAN)
    levels = []
    for size in sizes:
        start = np.arange(-(-m // size)) * size
        c0 = poly[start]
        cd = poly[np.minimum(start + size, m) % m] - c0
        verts = poly[np.minimum(start[:, None] + np.arange(size + 1), m) % m]
        levels.append((c0, cd, np.max(_segment_distance(verts, c0[:, None], cd[:, None]), axis=1)))
    seg = np.minimum(np.arange(len(levels[0][0]) * _LEAF), m - 1).reshape(-1, _LEAF)
    a = poly[seg]                                   # the last run padded with its last segment
    d = poly[(seg + 1) % m] - a
    size = np.abs(np.concatenate([poly, pts]))
    tol = 1e-10 * 2 * np.max(size[np.isfinite(size)], initial=1.0)     # rounding of the bounds
    # a block of points spans about as much of a curve as a run of 8 segments
    q = int(np.clip(round(_LEAF * n / m), 1, 32))
    for s0 in range(0, n, _BATCH):
        p = pts[s0:s0 + _BATCH]
        k = len(p)
        nb = -(-k // q)
        grp = p[np.minimum(np.arange(nb * q), k - 1)].reshape(nb, q)
        centre = (0.5 * (grp.real.min(axis=1) + grp.real.max(axis=1))
                  + 0.5j * (grp.imag.min(axis=1) + grp.imag.max(axis=1)))
        radius = np.max(np.abs(grp - centre[:, None]), axis=1)
        top = len(levels[-1][0])
        blk, run = np.repeat(np.arange(nb), top), np.tile(np.arange(top), nb)
        bound = np.full(nb, np.inf)
        for level in range(len(levels) - 1, -1, -1):
            c0, cd, dev = levels[level]
            if level < len(levels) - 1:             # the sub-runs of the runs left
                blk = np.repeat(blk, _FAN)
                run = (run[:, None] * _FAN + np.arange(_FAN)).ravel()
                ok = run < len(c0)
                blk, run = blk[ok], run[ok]
            dist = _segment_distance(centre[blk], c0[run], cd[run])
            keep = _lower_bound_by_owner(blk, dist, dev[run] + radius[blk], bound, tol)
            blk, run = blk[keep], run[keep]
        # each point of a block against the block's runs of 8, then their segments
        c0, cd, dev = levels[0]
        i = (blk[:, None] * q + np.arange(q)).ravel()
        run = np.repeat(run, q)
        ok = i < k
        i, run = i[ok], run[ok]
        order = np.argsort(i, kind="stable")
        i, run = i[order], run[order]
        dist = _segment_distance(p[i], c0[run], cd[run])
        keep = _lower_bound_by_owner(i, dist, dev[run], np.full(k, np.inf), tol)
        i, run = i[keep], run[keep]
        if len(i) == 0:                             # no finite point in this batch
            continue
        best = np.min(_segment_distance(p[i, None], a[run], d[run]), axis=1)
        first = np.flatnonzero(np.r_[True, i[1:] != i[:-1]])
        out[s0 + i[first]] = np.minimum.reduceat(best, first)
    return out


def _crossing(p0, p1, q0, q1, lines: bool = False):
    """The intersection of the segments (or, with ``lines``, the lines) p0p1 and q0q1."""
    d1, d2 = p1 - p0, q1 - q0
    den = d1.real * d2.imag - d1.imag * d2.real
    if abs(den) < 1e-300 or abs(den) < 1e-14 * abs(d1) * abs(d2):
        return None
    w = q0 - p0
    t = (w.real * d2.imag - w.imag * d2.real) / den
    u = (w.real * d1.imag - w.imag * d1.real) / den
    if not lines and not (-1e-9 <= t <= 1 + 1e-9 and -1e-9 <= u <= 1 + 1e-9):
        return None
    x = p0 + t * d1
    if lines and abs(x - p1) > 5 * (abs(d1) + abs(d2)):
        return None
    return complex(x)


ARC_STEP = np.radians(0.25)   # roller arcs at corners are drawn every 0.25°


def roller_envelope(programme: Programme, follower, grid: CamProfile,
                    tolerance: float = 1e-6) -> RollerEnvelope:
    """The true actual profile of the roller cam ``grid`` (designed for ``programme`` and
    ``follower`` on cam angles sorted over one whole revolution). A point of the offset curve
    is cut away where it lies closer than r_r − ``tolerance`` [m] to the pitch curve."""
    rr = grid.roller_radius
    delta = np.asarray(grid.delta)
    n = len(delta)
    if rr <= 0:
        raise ValueError("roller_envelope needs a roller follower")
    if n < 8 or np.any(np.diff(delta) <= 0) or delta[-1] - delta[0] < TWO_PI * (1 - 2.0 / n) - 1e-12:
        raise ValueError("roller_envelope needs the profile on sorted cam angles over one revolution")
    sigma = grid.rotation
    # The corners: left- and right-hand limits of the geometry at every velocity jump.
    corners, inserts = [], []
    for i, b in enumerate(programme.boundaries()):
        if b.impact != RIGID_IMPACT:
            continue
        db = float(programme.starts[i])
        s, v, a, j = programme.end_values((i - 1) % len(programme.segments), 1.0)
        one = lambda x: np.array([x])  # noqa: E731
        left = _profile(FollowerMotion(one(db), one(s), one(v), one(a), one(j), one((i - 1) % len(programme.segments))),
                        follower, grid.base_radius, sigma)
        right = _profile(programme.evaluate(one(db)), follower, grid.base_radius, sigma)
        P = complex(right.pitch[0])
        n0, n1 = complex(left.normal[0]), complex(right.normal[0])
        turn = float(np.angle(n1 / n0))
        m = max(2, int(np.ceil(abs(turn) / ARC_STEP))) + 1
        arc = P - rr * n0 * np.exp(1j * turn * np.linspace(0.0, 1.0, m))
        at = int(np.searchsorted(delta, db, side="left"))
        inserts.append((at, arc, P, len(corners)))
        corners.append((db, P, turn))
    # Offset curve and pitch curve as polylines, with the arcs and corner points inserted;
    # ``src`` is the profile index of every vertex, −1 − c on the arc of corner c.
    z_parts, p_parts, src_parts, last = [], [], [], 0
    for at, arc, P, c in sorted(inserts, key=lambda t: t[0]):
        z_parts += [grid.actual[last:at], arc]
        p_parts += [grid.pitch[last:at], np.array([P])]
        src_parts += [np.arange(last, at), np.full(len(arc), -1 - c)]
        last = at
    z = np.concatenate(z_parts + [grid.actual[last:]])
    pitch = np.concatenate(p_parts + [grid.pitch[last:]])
    src = np.concatenate(src_parts + [np.arange(last, n)])
    bad = polyline_distance(z, pitch) < rr - tolerance
    contact = np.array(grid.actual, dtype=complex)
    trimmed = np.zeros(n, dtype=bool)
    edges, stand_off, cut_corners = [], 0.0, {}
    if np.any(bad) and not np.all(bad):
        shift = int(np.argmin(bad))                  # start the cycle at a kept vertex
        z, bad, src = np.roll(z, -shift), np.roll(bad, -shift), np.roll(src, -shift)
        N = len(z)
        starts = np.flatnonzero(bad & ~np.roll(bad, 1))
        ends = np.flatnonzero(bad & ~np.roll(bad, -1))
        keep = ~bad
        out_pts, out_idx = [], []
        for i, j in zip(starts, ends):               # one cut per loop (a few per cam)
            k, l = i - 1, (j + 1) % N
            x = _crossing(z[k], z[i], z[j], z[l])
            if x is None:
                x = _crossing(z[k - 1], z[k], z[l], z[(l + 1) % N], lines=True)
            if x is None:                             # no crossing found: keep the points
                keep[i:j + 1] = True
                continue
            out_pts.append(x)
            out_idx.append(i)
            run = src[i:j + 1]
            grid_idx = run[run >= 0]
            contact[grid_idx] = x
            trimmed[grid_idx] = True
            on_arcs = {int(-1 - c) for c in run[run < 0]}
            # how far the designed roller centre (grid points, corners) stands off the edge
            centres = np.concatenate([grid.pitch[grid_idx], [corners[c][1] for c in on_arcs]])
            off = max(float(np.max(np.abs(centres - x))) - rr, 0.0) if len(centres) else 0.0
            stand_off = max(stand_off, off)
            cut_corners.update({c: off for c in on_arcs})
            # the cut spans the cam angles from the last kept grid point to the next one
            d_from = float(delta[src[k]]) if src[k] >= 0 else float("nan")
            d_to = float(delta[src[l]]) if src[l] >= 0 else float("nan")
            edges.append((d_from, d_to, x, off))
        # assemble: kept vertices, each cut replaced by its edge point
        pieces, pos = [], 0
        for x, i in sorted(zip(out_pts, out_idx), key=lambda t: t[1]):
            pieces.append(z[pos:i][keep[pos:i]])
            pieces.append(np.array([x]))
            pos = i
            while pos < N and bad[pos] and not keep[pos]:
                pos += 1
        pieces.append(z[pos:][keep[pos:]])
        outline = np.concatenate(pieces)
    else:
        outline = z
    # a corner is an edge when its arc fell inside a cut loop
    corner_list = [Corner(db, P, turn, "edge", cut_corners[c]) if c in cut_corners else
                   Corner(db, P, turn, "arc") for c, (db, P, turn) in enumerate(corners)]
    keep_mask = np.concatenate([[True], np.abs(np.diff(outline)) > 1e-12])
    return RollerEnvelope(outline[keep_mask], pitch, contact, trimmed, tuple(corner_list), tuple(edges),
                          max(stand_off, 0.0), rr)


def envelope_contact(env: RollerEnvelope, profile: CamProfile) -> np.ndarray:
    """The actual-profile points a roller touches at the cam angles of ``profile`` (the same
    cam, any cam angles): its offset points, except where they were cut away by ``env``,
    where it is the edge of that cut."""
    out = np.array(profile.actual, dtype=complex)
    if not env.edges:
        return out
    bad = polyline_distance(out, env.pitch_outline) < env.roller_radius - 1e-6
    for lo, hi, x, _ in env.edges:
        if np.isnan(lo) or np.isnan(hi):
            continue
        inside = bad & ((profile.delta - lo) % TWO_PI <= (hi - lo) % TWO_PI)
        out[inside] = x
    return out


# --------------------------------------------------------------------------- base circle


def min_base_radius_translating(programme: Programme, follower: TranslatingFollower,
                                alpha_rise: float, alpha_return: float, offset: float | None = None,
                                rotation: int = 1, points: int = 7200,
                                min_curvature: float = 0.0) -> tuple[float, float]:
    """Smallest base radius r0 [m] (and the offset e [m] used) of a translating follower.

    Knife edge / roller: the pressure angle obeys tan α = |σ·ds/dδ − e| / (s0 + s) with
    s0 = √(r0² − e²) (the pole of cam and follower lies at x = σ·ds/dδ), so α ≤ [α] everywhere
    on the rises ([α] = ``alpha_rise``) and returns (``alpha_return``) is
    s0 ≥ max(|σ·ds/dδ − e| / tan[α] − s). With ``offset=None`` the offset minimising r0 is
    searched. Flat face: the profile must stay convex, r0 + s + d²s/dδ² ≥ ``min_curvature``.
    """
    from .extremes import fminbound

    sigma = 1 if rotation > 0 else -1
    m = programme.evaluate(np.arange(points) * (TWO_PI / points))
    if follower.kind == "flat":
        # r0 ≥ max(ρ_min − s − d²s/dδ²), the maximum exact per smooth piece (one-sided ends)
        need = 1e-9
        for i, _ in enumerate(programme.segments):
            for ua, ub in segment_pieces(programme, i):
                def g(u, i=i):
                    mm_ = segment_motion(programme, i, u)
                    return min_curvature - mm_.s - mm_.d2s
                res = _piece_extreme(g, ua, ub, 64)
                need = max(need, res[1])
        return float(need), follower.offset
    # Sample every rise and return on its own closed interval [0, 1], ends included: the
    # largest pressure angle is often at an end (e.g. where a uniform return stops).
    s_parts, x_parts, tan_parts = [], [], []
    for i, seg in enumerate(programme.segments):
        if seg.kind == DWELL:
            continue
        u = np.linspace(0.0, 1.0, max(points * seg.span / TWO_PI, 64).__int__() + 1)
        S, S1, _, _ = LAWS[seg.law](u)
        s_parts.append(programme.levels[i] + programme.lifts[i] * S)
        x_parts.append(sigma * programme.lifts[i] * S1 / programme.spans[i])
        lim = alpha_rise if seg.kind == RISE else alpha_return
        tan_parts.append(np.full_like(u, np.tan(lim)))
    s, x_pole, tan_lim = (np.concatenate(v) for v in (s_parts, x_parts, tan_parts))

    def r0_for(e: float) -> float:
        s0 = max(float(np.max(np.abs(x_pole - e) / tan_lim - s)), 0.0)
        return float(np.hypot(s0, e))

    def r0_exact(e: float) -> float:
        # s0 ≥ max(|σ·ds/dδ − e| / tan[α] − s) over every rise and return, the maximum
        # exact per smooth piece of the law (its ends as one-sided limits)
        s0 = 0.0
        for i, seg in enumerate(programme.segments):
            if seg.kind == DWELL:
                continue
            t = np.tan(alpha_rise if seg.kind == RISE else alpha_return)
            for ua, ub in segment_pieces(programme, i):
                def g(u, i=i, t=t):
                    mm_ = segment_motion(programme, i, u)
                    return np.abs(sigma * mm_.ds - e) / t - mm_.s
                n = max(64, int(np.ceil(points * programme.spans[i] * (ub - ua) / TWO_PI)))
                s0 = max(s0, _piece_extreme(g, ua, ub, n)[1])
        return float(np.hypot(s0, e))

    if offset is not None:
        return r0_exact(offset), float(offset)
    # the best offset from the sampled programme (a minimax over e), its r0 exact
    span = float(np.max(np.abs(x_pole))) + 1e-12
    x, _ = fminbound(r0_for, -span, span, xatol=span * 1e-10)
    return r0_exact(x), x


def min_base_radius_oscillating(programme: Programme, follower: OscillatingFollower,
                                alpha_rise: float, alpha_return: float, rotation: int = 1,
                                points: int = 3600) -> float:
    """Smallest base radius [m] of an oscillating roller follower with the given pivot
    distance and arm length that keeps the pressure angle within the limits (scan, then
    bisection on the first feasible interval)."""
    a, L = follower.pivot_distance, follower.arm_length
    lo, hi = abs(a - L), a + L
    kinds = np.array([seg.kind for seg in programme.segments])

    # The grid plus the closed end of every segment (the pressure angle after a uniform
    # return is largest at its very end).
    ends = programme.starts + programme.spans * (1 - 1e-12)
    delta = np.concatenate([np.arange(points) * (TWO_PI / points), ends])
    motion = programme.evaluate(delta)           # the same for every base radius tried
    sigma = 1 if rotation > 0 else -1

    def excess(r0: float) -> float:
        prof = _profile(motion, follower, r0, sigma)
        k = kinds[prof.motion.segment]
        lim = np.where(k == RISE, alpha_rise, alpha_return)
        mov = k != DWELL
        return float(np.max(prof.pressure_angle[mov] - lim[mov]))

    grid = lo + (hi - lo) * np.linspace(0.01, 0.99, 99)
    values = np.array([excess(r) for r in grid])
    ok = np.nonzero(values <= 0)[0]
    if len(ok) == 0:
        raise CamDesignError(N_("no base radius keeps the pressure angle within the limits "
                                "with this pivot distance and arm length"))
    j = ok[0]
    if j == 0:
        return float(grid[0])
    # Plain bisection (the excess is a maximum over the cam angles: continuous, with
    # corners): ~25 evaluations to 1e-10 m, cheaper than importing scipy.optimize (~0.3 s)
    # for a single root in a run.
    bad, good = float(grid[j - 1]), float(grid[j])
    while good - bad > 1e-10:
        mid = 0.5 * (bad + good)
        if excess(mid) <= 0:
            good = mid
        else:
            bad = mid
    # The grid may miss the true largest pressure angle: continue with the exact one
    # (per smooth piece, one-sided ends), which can only move r0 up.
    def exact_excess(r0: float) -> float:
        worst = -np.inf
        for i, seg in enumerate(programme.segments):
            if seg.kind == DWELL:
                continue
            lim = alpha_rise if seg.kind == RISE else alpha_return
            for ua, ub in segment_pieces(programme, i):
                def g(u, i=i):
                    return _profile(segment_motion(programme, i, u), follower, r0,
                                    sigma).pressure_angle
                n = max(64, int(np.ceil(points * programme.spans[i] * (ub - ua) / TWO_PI)))
                worst = max(worst, _piece_extreme(g, ua, ub, n)[1] - lim)
        return worst

    if exact_excess(good) > 0:
        bad, step = good, 1e-9
        while True:
            up = min(good + step, hi * (1 - 1e-12))
            if exact_excess(up) <= 0:
                good = up
                break
            if up >= hi * (1 - 1e-12):
                raise CamDesignError(N_("no base radius keeps the pressure angle within the "
                                        "limits with this pivot distance and arm length"))
            bad, step = up, step * 4
        while good - bad > 1e-10:
            mid = 0.5 * (bad + good)
            if exact_excess(mid) <= 0:
                good = mid
            else:
                bad = mid
    return good


# --------------------------------------------------------------------------- analysis


@dataclass(frozen=True)
class DiscMotion:
    """Follower on an eccentric circular disc at cam angles ``delta``."""

    delta: np.ndarray
    y: np.ndarray               # height of the follower point (knife edge, roller centre, face) [m]
    dy: np.ndarray              # dy/dδ [m/rad]
    s: np.ndarray               # displacement from the lowest position [m]
    pressure_angle: np.ndarray  # [rad]
    centre: np.ndarray          # disc centre in the frame (complex) [m]
    y_min: float
    y_max: float
    alpha_max: float = 0.0      # the largest pressure angle over the turn, exact [rad]

    @property
    def stroke(self) -> float:
        return self.y_max - self.y_min


def eccentric_disc(delta, radius: float, eccentricity: float, follower: TranslatingFollower,
                   rotation: int = 1) -> DiscMotion:
    """An eccentric circular disc (偏心圆盘凸轮) of ``radius`` R whose centre C is
    ``eccentricity`` ε from the axis, driving a translating follower; at δ = 0 the disc centre
    is straight below the axis. Closed forms: y = C_y + √((R + r_r)² − (x_f − C_x)²) for a
    knife edge (r_r = 0) or roller, y = C_y + R for a flat face; the pressure angle of a knife
    edge or roller is sin α = |x_f − C_x| / (R + r_r), of a flat face 0. The lowest and highest
    positions are where the common normal passes through the axis:
    y = √((R + r_r ∓ ε)² − x_f²). The largest pressure angle over the turn is where the disc
    centre is farthest from the follower's line, |x_f − C_x| = |x_f| + ε:
    sin α_max = (|x_f| + ε)/(R + r_r) (0 for a flat face)."""
    sigma = 1 if rotation > 0 else -1
    d = np.asarray(delta, dtype=float)
    C = eccentricity * np.exp(1j * (-np.pi / 2 + sigma * d))
    C1 = 1j * sigma * C
    x = follower.offset
    if follower.kind == "flat":
        y = C.imag + radius
        dy = C1.imag
        alpha = np.zeros_like(d)
        alpha_max = 0.0
        y_min, y_max = radius - eccentricity, radius + eccentricity
    else:
        Rp = radius + _roller(follower)
        if abs(x) + eccentricity >= Rp:
            raise CamDesignError(
                N_("the follower leaves the disc: offset |e| + eccentricity = {reach_mm:.4g} mm "
                   "must stay below R + r_r = {Rp_mm:.4g} mm"),
                reach_mm=(abs(x) + eccentricity) * 1e3, Rp_mm=Rp * 1e3)
        dx = x - C.real
        root = np.sqrt(Rp * Rp - dx * dx)
        y = C.imag + root
        dy = C1.imag + dx * C1.real / root
        alpha = np.arcsin(np.abs(dx) / Rp)
        alpha_max = float(np.arcsin((abs(x) + eccentricity) / Rp))
        y_min = float(np.sqrt((Rp - eccentricity) ** 2 - x * x))
        y_max = float(np.sqrt((Rp + eccentricity) ** 2 - x * x))
    return DiscMotion(d, y, dy, y - y_min, alpha, C, float(y_min), float(y_max), alpha_max)
