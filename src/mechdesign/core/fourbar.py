"""Four-bar and slider-crank dimensional synthesis (尺寸综合) and the checks that go with it.

Textbook method (孙桓《机械原理》 §8 平面连杆机构及其设计, 按行程速比系数 K 设计四杆机构),
written analytically instead of with ruler and compasses:

* extreme-position angle θ = 180°·(K − 1)/(K + 1);
* the rocker's two extreme positions C1 (crank and coupler folded, AC1 = b − a) and
  C2 (extended, AC2 = b + a) lie on the rocker circle, ψ apart;
* the crank pivot A sees the chord C1C2 under the angle θ, so A lies on the circle
  through C1, C2 of radius R = C1C2 / (2 sin θ) (the θ-circle);
* a = (AC2 − AC1)/2, b = (AC2 + AC1)/2, frame d = AD.

Coordinates used throughout: rocker pivot D at the origin, the rocker's extremes
symmetric about the +y axis, C1 = (w, h), C2 = (−w, h), w = c·sin(ψ/2), h = c·cos(ψ/2).
A point of the θ-circle is A(t) = O + R·(sin t·x̂ + cos t·n̂), n̂ the unit normal of the
chord pointing to the side of the major arc; ``t`` = 0 is the point of the arc farthest
from the chord and C1 is at t = π − θ. A must not lie where the line AD separates C1 from
C2 (then the two extremes belong to different assembly branches), which leaves the arc
t_lo < t < π − θ on the C1 side (the mirror arc gives the mirror-image linkage).

``side`` = +1 is the textbook's θ-circle, whose centre is on D's side of the chord;
``side`` = −1 is its mirror image across the chord (A beyond the rocker's chord).

Everything is SI (metres) and radians; nothing here does I/O.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import DesignError, Msg, N_, mm, pgettext
from .synthesis import extreme_angle

_TOL = 1e-12


class SynthesisError(DesignError):
    """No real solution: the message says which datum to change and in which direction."""


@dataclass(frozen=True)
class FourBar:
    """Link lengths of a four-bar [m]: crank a, coupler b, rocker c, frame d."""

    crank: float
    coupler: float
    rocker: float
    frame: float

    def scaled(self, factor: float) -> "FourBar":
        return FourBar(self.crank * factor, self.coupler * factor,
                       self.rocker * factor, self.frame * factor)


# ----------------------------------------------------------------------------- checks

def grashof(fb: FourBar) -> tuple[bool, str]:
    """Grashof's rule: (does the crank a turn fully?, classification text).

    s + l < p + q: the shortest link fully rotates relative to its neighbours; which link
    is the shortest decides crank-rocker / double-crank / double-rocker / rocker-crank.
    s + l = p + q: change-point mechanism (the links can become collinear all at once).
    s + l > p + q: no link fully rotates (triple-rocker).
    """
    lengths = {"crank": fb.crank, "coupler": fb.coupler, "rocker": fb.rocker, "frame": fb.frame}
    if min(lengths.values()) <= 0.0:
        raise ValueError(f"link lengths must be positive, got {lengths}")
    vals = sorted(lengths.values())
    s, p, q, l = vals
    margin = (p + q) - (s + l)
    scale = l
    shortest = min(lengths, key=lengths.get)
    if margin < -1e-12 * scale:
        return False, "triple-rocker (non-Grashof: s + l > p + q)"
    change = abs(margin) <= 1e-12 * scale
    if change:
        turns = fb.crank <= min(fb.coupler, fb.rocker) + 1e-12 * scale or \
            fb.frame <= min(fb.crank, fb.coupler, fb.rocker) + 1e-12 * scale
        return turns, "change-point (s + l = p + q)"
    if shortest == "crank":
        return True, "crank-rocker"
    if shortest == "frame":
        return True, "double-crank"
    if shortest == "coupler":
        return False, "double-rocker (Grashof, coupler shortest)"
    return False, "rocker-crank (the rocker is the shortest and turns fully)"


def grashof_sums_message(fb: FourBar) -> Msg:
    """The Grashof check in words with its numbers [mm], as a message, e.g. "shortest +
    longest = 20 + 60 = 80 mm > 45 + 30 = 75 mm (the other two)"."""
    lengths = {"crank": fb.crank, "coupler": fb.coupler, "rocker": fb.rocker, "frame": fb.frame}
    order = sorted(lengths, key=lengths.get)
    s, p, q, l_ = (lengths[k] for k in order)
    return Msg(N_("crank a = {a}, coupler b = {b}, rocker c = {c}, frame d = {d} mm: shortest "
                  "({shortest}) + longest ({longest}) = {s} + {l} = {sl} mm {rel} {p} + {q} = "
                  "{pq} mm (the other two)"),
               a=mm(fb.crank), b=mm(fb.coupler), c=mm(fb.rocker), d=mm(fb.frame),
               shortest=_LINK[order[0]], longest=_LINK[order[-1]], s=mm(s), l=mm(l_),
               sl=mm(s + l_), rel=">" if s + l_ > p + q else "≤", p=mm(p), q=mm(q), pq=mm(p + q))


#: the links of a four-bar by their role, as the messages name them (English: the code)
_LINK = {"crank": pgettext("link", "crank"), "coupler": pgettext("link", "coupler"),
         "rocker": pgettext("link", "rocker"), "frame": pgettext("link", "frame")}


def grashof_sums(fb: FourBar) -> tuple[str, str]:
    """:func:`grashof_sums_message` as its (English, Chinese) texts."""
    msg = grashof_sums_message(fb)
    return msg.text("en"), msg.text("zh")


def _deviation(fb: FourBar) -> tuple[float, float]:
    """Coupler-rocker angles δ' (crank along AD towards D) and δ'' (crank pointing away)."""
    a, b, c, d = fb.crank, fb.coupler, fb.rocker, fb.frame
    cos1 = (b * b + c * c - (d - a) ** 2) / (2.0 * b * c)
    cos2 = (b * b + c * c - (d + a) ** 2) / (2.0 * b * c)
    return (float(np.arccos(np.clip(cos1, -1.0, 1.0))),
            float(np.arccos(np.clip(cos2, -1.0, 1.0))))


def transmission_angle_extremes(fb: FourBar) -> tuple[float, float]:
    """(γ_min, γ_max) [rad] of a four-bar whose crank a turns fully.

    The coupler-rocker angle δ is extreme when the crank is collinear with the frame:
    cos δ = (b² + c² − (d ∓ a)²)/(2bc); the transmission angle is γ = min(δ, π − δ).
    γ_min is the smaller of γ at those two positions; γ_max is π/2 when δ passes
    through 90° during the revolution, otherwise the larger of the two.
    """
    d1, d2 = _deviation(fb)
    g1, g2 = min(d1, np.pi - d1), min(d2, np.pi - d2)
    lo, hi = min(d1, d2), max(d1, d2)
    gmax = np.pi / 2.0 if lo <= np.pi / 2.0 <= hi else max(g1, g2)
    return float(min(g1, g2)), float(gmax)


def crank_rocker_extremes(fb: FourBar) -> tuple[float, float]:
    """(θ, ψ) [rad]: extreme-position angle and rocker swing by the closed forms.

    At the folded extreme AC1 = b − a, at the extended AC2 = b + a; in triangles ADC1 and
    ADC2 (law of cosines) θ = ∠DAC1 − ∠DAC2 (the angle between the crank's two
    positions, taken positive) and ψ = ∠ADC2 − ∠ADC1.
    """
    a, b, c, d = fb.crank, fb.coupler, fb.rocker, fb.frame
    ok, kind = grashof(fb)
    if not (ok and kind == "crank-rocker"):
        raise SynthesisError(N_("not a crank-rocker ({kind}; {sums}): the extreme positions are "
                                "undefined"), kind=kind, sums=grashof_sums_message(fb))
    r1, r2 = b - a, b + a

    def ang(x, y, z):  # angle opposite z in a triangle with sides x, y, z
        return np.arccos(np.clip((x * x + y * y - z * z) / (2.0 * x * y), -1.0, 1.0))
    theta = abs(float(ang(r1, d, c) - ang(r2, d, c)))
    psi = float(ang(d, c, r2) - ang(d, c, r1))
    return theta, psi


# ------------------------------------------------------------------ θ-circle synthesis

@dataclass(frozen=True)
class CircleConstruction:
    """The θ-circle construction of a crank-rocker, D at the origin [m] (complex points).

    ``point(p)`` gives the crank pivot A for the arc parameter p; the allowed arc is
    p_lo < p < p_hi. For θ > 0, p = t, the angle at the circle's centre O measured from
    the arc's point farthest from the chord towards C1 (C1 at t = π − θ). For θ = 0 the
    circle degenerates into the line C1C2 and A = C1 + w·tan(p)·x̂, 0 < p < π/2.
    """

    c1: complex            # rocker tip at the folded extreme (AC1 = b − a)
    c2: complex            # rocker tip at the extended extreme (AC2 = b + a)
    centre: complex | None  # centre O of the θ-circle (None for θ = 0)
    radius: float          # R = C1C2 / (2 sin θ) (inf for θ = 0)
    theta: float           # extreme-position angle θ [rad]
    swing: float           # rocker swing ψ [rad]
    side: int              # +1 textbook circle (centre on D's side of the chord), −1 mirror
    p_lo: float            # allowed arc: p_lo < p < p_hi
    p_hi: float

    @property
    def rocker(self) -> float:
        return abs(self.c1)

    def point(self, p):
        """Crank pivot(s) A(p) (complex), p [rad] scalar or array."""
        p = np.asarray(p, dtype=float)
        if self.centre is None:
            return self.c1 + self.c1.real * np.tan(p)
        n = -1j * self.side          # unit normal towards the major arc (as a complex number)
        return self.centre + self.radius * (np.sin(p) + n * np.cos(p))

    def position_of(self, a: complex) -> float:
        """Parameter p of a point A of the construction."""
        if self.centre is None:
            return float(np.arctan2((a - self.c1).real, self.c1.real))
        r = (a - self.centre) / self.radius
        n = -1j * self.side
        return float(np.arctan2(r.real, (np.conj(n) * r).real))

    def designs(self, p) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(a, b, d) [m] of the designs at the parameters p (vectorised)."""
        a_pt = self.point(p)
        ac1, ac2 = np.abs(a_pt - self.c1), np.abs(a_pt - self.c2)
        return (ac2 - ac1) / 2.0, (ac2 + ac1) / 2.0, np.abs(a_pt)

    def gamma_min(self, p) -> np.ndarray:
        """γ_min [rad] of the designs at the parameters p (vectorised; 0 off the arc)."""
        p = np.asarray(p, dtype=float)
        a, b, d = self.designs(p)
        c = self.rocker
        with np.errstate(invalid="ignore", divide="ignore"):
            cos1 = np.clip((b * b + c * c - (d - a) ** 2) / (2.0 * b * c), -1.0, 1.0)
            cos2 = np.clip((b * b + c * c - (d + a) ** 2) / (2.0 * b * c), -1.0, 1.0)
        d1, d2 = np.arccos(cos1), np.arccos(cos2)
        g = np.minimum(np.minimum(d1, np.pi - d1), np.minimum(d2, np.pi - d2))
        inside = (p > self.p_lo) & (p < self.p_hi) & np.isfinite(g)
        return np.where(inside, g, 0.0)


def _check_data(theta: float, swing: float, rocker: float) -> None:
    if not (np.isfinite(theta) and 0.0 <= theta < np.pi / 2.0):
        raise SynthesisError(N_("extreme-position angle θ = {theta_deg:.6g}° must be in [0°, "
                                "90°) (time ratio 1 ≤ K < 3)"),
                             theta_deg=np.degrees(theta))
    if not (np.isfinite(swing) and 0.0 < swing < np.pi):
        raise SynthesisError(N_("rocker swing ψ = {swing_deg:.6g}° must be in (0°, 180°)"),
                             swing_deg=np.degrees(swing))
    if not (np.isfinite(rocker) and rocker > 0.0):
        raise SynthesisError(N_("rocker length {rocker} must be positive"), rocker=rocker)


def _theta_of(K: float) -> float:
    if not np.isfinite(K) or K < 1.0:
        raise SynthesisError(N_("time ratio K = {K} must be ≥ 1"), K=K)
    if K >= 3.0:
        raise SynthesisError(N_("time ratio K = {K} gives θ ≥ 90°; a crank-rocker needs K < 3"),
                             K=K)
    return float(extreme_angle(K))


def circle_construction_theta(theta: float, swing: float, rocker: float, *, side: int = +1
                              ) -> CircleConstruction:
    """The θ-circle through the rocker's extremes C1, C2 and the allowed arc for A."""
    _check_data(theta, swing, rocker)
    if side not in (+1, -1):
        raise ValueError(f"side must be +1 or -1, got {side}")
    w, h = rocker * np.sin(swing / 2.0), rocker * np.cos(swing / 2.0)
    c1, c2 = complex(w, h), complex(-w, h)
    if theta == 0.0:
        # A on the line C1C2 beyond C1: the line AD never separates C1 and C2
        return CircleConstruction(c1, c2, None, float("inf"), 0.0, swing, side, 0.0, np.pi / 2.0)
    radius = w / np.sin(theta)
    n = -1j * side
    centre = complex(0.0, h) + n * radius * np.cos(theta)
    p_hi = np.pi - theta
    # the lines D–C1 and D–C2 meet the circle a second time at s·u with
    # s·c = |O|² − R² (power of D); those points bound the arc where AD separates C1, C2
    power = abs(centre) ** 2 - radius ** 2
    proto = CircleConstruction(c1, c2, centre, radius, theta, swing, side, 0.0, p_hi)
    p_lo = 0.0
    for tip in (c1, c2):
        other = tip / abs(tip) * power / rocker
        if abs(other - tip) < 1e-12 * rocker:       # tangent: no second point
            continue
        t = proto.position_of(other)
        if 0.0 < t < p_hi - 1e-12:
            p_lo = max(p_lo, t)
    cons = CircleConstruction(c1, c2, centre, radius, theta, swing, side, p_lo, p_hi)
    mid = complex(cons.point(0.5 * (p_lo + p_hi)))
    if not _same_branch(mid, c1, c2):
        raise SynthesisError(
            N_("no crank-rocker on this θ-circle (side {side}) for θ = {theta_deg:.6g}°, ψ = "
               "{swing_deg:.6g}°: the line AD separates C1 and C2 everywhere"),
            side=side, theta_deg=np.degrees(theta), swing_deg=np.degrees(swing))
    return cons


def circle_construction(K: float, swing: float, rocker: float, *, side: int = +1
                        ) -> CircleConstruction:
    """:func:`circle_construction_theta` for the time ratio K."""
    return circle_construction_theta(_theta_of(K), swing, rocker, side=side)


def _same_branch(a: complex, c1: complex, c2: complex) -> bool:
    """C1 and C2 on the same side of the line AD (D the origin): one assembly branch."""
    s1 = (np.conj(a) * c1).imag
    s2 = (np.conj(a) * c2).imag
    return bool(s1 * s2 > 0.0)


def _design_at(cons: CircleConstruction, p: float) -> FourBar:
    a, b, d = cons.designs(p)
    return FourBar(crank=float(a), coupler=float(b), rocker=cons.rocker, frame=float(d))


def design_at(cons: CircleConstruction, position: float) -> FourBar:
    """The crank-rocker with A at the arc parameter ``position`` of ``cons`` (no range check)."""
    return _design_at(cons, position)


def crank_rocker_on_circle(K: float, swing: float, rocker: float, position: float,
                           *, side: int = +1) -> FourBar:
    """Crank-rocker with A at the arc parameter ``position`` (see CircleConstruction).

    Raises SynthesisError when the position is outside the allowed arc.
    """
    cons = circle_construction(K, swing, rocker, side=side)
    if not (cons.p_lo < position < cons.p_hi):
        raise SynthesisError(
            N_("position {position_deg:.6g}° is outside the allowed arc ({p_lo_deg:.6g}°, "
               "{p_hi_deg:.6g}°)"), position_deg=np.degrees(position),
            p_lo_deg=np.degrees(cons.p_lo), p_hi_deg=np.degrees(cons.p_hi))
    return _design_at(cons, position)


def frame_range_theta(theta: float, swing: float, rocker: float, *, side: int = +1
                      ) -> tuple[float, float]:
    """(smallest, largest) frame AD [m] on the allowed arc (open interval; may be inf)."""
    cons = circle_construction_theta(theta, swing, rocker, side=side)
    if cons.centre is None:
        return rocker, float("inf")
    ends = [abs(complex(cons.point(cons.p_lo))), abs(complex(cons.point(cons.p_hi)))]
    return min(ends), max(ends)


def frame_range(K: float, swing: float, rocker: float, *, side: int = +1) -> tuple[float, float]:
    """:func:`frame_range_theta` for the time ratio K."""
    return frame_range_theta(_theta_of(K), swing, rocker, side=side)


def position_for_frame(cons: CircleConstruction, frame: float) -> float:
    """Arc parameter p of the A with |AD| = frame. |A(t)|² = |O|² + R² + 2R·(O·n̂)·cos t is
    monotonic in t on (0, π), so there is at most one such A on the arc.
    Raises SynthesisError naming the frame range that works."""
    if not (np.isfinite(frame) and frame > 0.0):
        raise SynthesisError(N_("frame length {frame} must be positive"), frame=frame)
    c = cons.rocker
    p = None
    if cons.centre is None:
        if frame > c:
            x = np.sqrt(frame ** 2 - cons.c1.imag ** 2)
            p = float(np.arctan((x - cons.c1.real) / cons.c1.real))
        lo, hi = c, float("inf")
    else:
        n = -1j * cons.side
        on = (np.conj(n) * cons.centre).real              # O·n̂
        if abs(on) < 1e-15 * c:
            raise SynthesisError(N_("the θ-circle is centred on D: every A has the same frame "
                                    "length, so the frame does not fix the design"))
        big = abs(cons.centre) ** 2 + cons.radius ** 2
        cos_t = (frame ** 2 - big) / (2.0 * cons.radius * on)
        if abs(cos_t) <= 1.0:
            p = float(np.arccos(cos_t))
        ends = [abs(complex(cons.point(cons.p_lo))), abs(complex(cons.point(cons.p_hi)))]
        lo, hi = min(ends), max(ends)
    if p is None or not (cons.p_lo < p < cons.p_hi):
        top = "∞" if not np.isfinite(hi) else f"{hi * 1e3:.6g}"
        raise SynthesisError(
            N_("frame length {frame_mm:.6g} mm cannot be met: with θ = {theta_deg:.6g}°, ψ = "
               "{swing_deg:.6g}° and rocker {c_mm:.6g} mm the crank pivot on the allowed arc "
               "gives frames between {lo_mm:.6g} and {top} mm (exclusive)"),
            frame_mm=frame * 1e3, theta_deg=np.degrees(cons.theta),
            swing_deg=np.degrees(cons.swing), c_mm=c * 1e3, lo_mm=lo * 1e3, top=top)
    return p


def crank_rocker_from_K(K: float, swing: float, rocker: float, frame: float, *,
                        side: int = +1) -> FourBar:
    """Textbook design: A where the circle |AD| = frame cuts the allowed arc of the θ-circle;
    a = (AC2 − AC1)/2, b = (AC2 + AC1)/2. Raises SynthesisError naming the frame range
    that works."""
    cons = circle_construction(K, swing, rocker, side=side)
    return _design_at(cons, position_for_frame(cons, frame))


def gamma_min_on_arc(K: float, swing: float, rocker: float, positions, *, side: int = +1
                     ) -> np.ndarray:
    """γ_min [rad] of the designs at the arc parameters ``positions`` (vectorised)."""
    return circle_construction(K, swing, rocker, side=side).gamma_min(positions)


def optimal_position_theta(theta: float, swing: float, rocker: float = 1.0, *,
                           side: int = +1, grid: int = 721) -> tuple[float, float]:
    """(p*, γ_min*) maximising γ_min over the allowed arc: grid pre-scan, then a bounded
    Brent search (:func:`mechdesign.core.extremes.fminbound`) between the grid
    neighbours of the best grid point, a smooth maximum's place polished to the zero of
    its slope (:func:`mechdesign.core.extremes.polish_minimum`)."""
    cons = circle_construction_theta(theta, swing, rocker, side=side)
    span = cons.p_hi - cons.p_lo
    ps = cons.p_lo + span * (np.arange(1, grid + 1) / (grid + 1))
    gs = cons.gamma_min(ps)
    k = int(np.argmax(gs))
    lo = ps[k - 1] if k > 0 else cons.p_lo + 1e-12 * span
    hi = ps[k + 1] if k + 1 < len(ps) else cons.p_hi - 1e-12 * span

    def neg(p):
        return -float(cons.gamma_min(p))

    from .extremes import fminbound, polish_minimum

    p_best, f_best = fminbound(neg, lo, hi, xatol=1e-13 * max(1.0, span))
    p_best = polish_minimum(neg, p_best, cons.p_lo, cons.p_hi, 1e-4 * span)
    g_best = -neg(p_best)
    if gs[k] > g_best:            # never worse than the grid
        p_best, g_best = float(ps[k]), float(gs[k])
    return p_best, g_best


def optimal_position(K: float, swing: float, rocker: float = 1.0, *, side: int = +1,
                     grid: int = 721) -> tuple[float, float]:
    """:func:`optimal_position_theta` for the time ratio K."""
    return optimal_position_theta(_theta_of(K), swing, rocker, side=side, grid=grid)


def optimal_crank_rocker(K: float, swing: float, rocker: float, *, side: int = +1
                         ) -> tuple[FourBar, float]:
    """(design, γ_min [rad]) of the crank-rocker with the largest minimum transmission
    angle for the given K, ψ and rocker length (A searched over the allowed arc)."""
    cons = circle_construction(K, swing, rocker, side=side)
    p, g = optimal_position(K, swing, rocker, side=side)
    return _design_at(cons, p), g


# -------------------------------------------------------------- offset slider-crank

@dataclass(frozen=True)
class SliderConstruction:
    """θ-circle construction of an offset slider-crank, A at the origin [m].

    The slider guide is the line y = +e (A lies e below it); the slider's extremes are
    C1 = (x1, e) (folded, AC1 = b − a) and C2 = (x2, e) (extended, AC2 = b + a).
    """

    c1: complex
    c2: complex
    centre: complex
    radius: float
    theta: float


def slider_crank_construction(K: float, stroke: float, offset: float) -> SliderConstruction:
    """C1, C2 on the guide H apart; A on the θ-circle through them at distance e from it.

    With the chord C1C2 as x-axis and its midpoint as origin the circle's centre is at
    (0, −R cos θ), R = H/(2 sin θ); A = (x_A, −e) with x_A² = R² − (R cos θ − e)² and A
    on C1's side (x_A < −H/2, i.e. e < H·cot θ); then shifted so that A is the origin.
    """
    if not np.isfinite(K) or K <= 1.0:
        raise SynthesisError(N_("time ratio K = {K} must be > 1 for an offset slider-crank (K "
                                "= 1 needs no offset: a centred slider-crank)"),
                             K=K)
    theta = extreme_angle(K)
    if not stroke > 0.0:
        raise SynthesisError(N_("stroke H = {stroke} must be positive"), stroke=stroke)
    if not offset > 0.0:
        raise SynthesisError(N_("offset e = {offset} must be > 0: with e = 0 the extreme "
                                "positions are 180° apart and K = 1"),
                             offset=offset)
    limit = stroke / np.tan(theta)
    if offset >= limit:
        raise SynthesisError(
            N_("offset e = {offset_mm:.6g} mm is too large for K = {K:.6g} and H = "
               "{stroke_mm:.6g} mm: it must be below H·cot θ = {limit_mm:.6g} mm (reduce e or "
               "K, or increase H)"), offset_mm=offset * 1e3, K=K,
            stroke_mm=stroke * 1e3, limit_mm=limit * 1e3)
    radius = stroke / (2.0 * np.sin(theta))
    yc = -radius * np.cos(theta)
    xa = -np.sqrt(radius ** 2 - (yc + offset) ** 2)
    shift = complex(xa, -offset)                      # A in chord coordinates
    c1 = complex(-stroke / 2.0, 0.0) - shift
    c2 = complex(stroke / 2.0, 0.0) - shift
    return SliderConstruction(c1, c2, complex(0.0, yc) - shift, float(radius), float(theta))


def offset_slider_crank(K: float, stroke: float, offset: float) -> tuple[float, float]:
    """(crank a, rod b) [m] of the offset slider-crank with time ratio K, stroke H, offset e."""
    cons = slider_crank_construction(K, stroke, offset)
    ac1, ac2 = abs(cons.c1), abs(cons.c2)
    return (ac2 - ac1) / 2.0, (ac2 + ac1) / 2.0


def slider_crank_pressure_angle_max(crank: float, rod: float, offset: float) -> float:
    """Largest pressure angle α_max [rad] on the slider over a revolution.

    The rod's angle to the guide obeys b·sin α = a·sin φ + e (φ the crank angle from the
    guide direction), largest with the crank perpendicular to the guide on the offset's
    far side: α_max = arcsin((a + e)/b). The crank turns fully only if a + e < b.
    """
    a, b, e = crank, rod, abs(offset)
    if not (a > 0.0 and b > 0.0):
        raise SynthesisError(N_("crank {a} and rod {b} must be positive"), a=a, b=b)
    if a + e >= b:
        raise SynthesisError(
            N_("crank + offset = {ae_mm:.6g} mm ≥ rod {b_mm:.6g} mm: the crank cannot turn "
               "fully (lengthen the rod)"), ae_mm=(a + e) * 1e3, b_mm=b * 1e3)
    return float(np.arcsin((a + e) / b))


def slider_crank_pressure_angles(crank: float, rod: float, offset: float) -> tuple[float, float]:
    """(α_max in the slow stroke, α_max in the fast stroke) [rad] of an offset slider-crank.

    With the guide at distance e from A, the slider's distance from the guide's foot of A
    grows during the slow stroke (180° + θ), which carries the crank through the position
    pointing at the guide: there |a sin φ + e| stays between e − a and the folded value, so
    α_slow = max(arcsin(e/(b − a)), arcsin(|a − e|/b)). The fast stroke carries the crank
    through the position pointing away from the guide: α_fast = arcsin((a + e)/b), the
    largest of the revolution. Giving the slow stroke the work keeps its pressure angle small.
    """
    a, b, e = crank, rod, abs(offset)
    fast = slider_crank_pressure_angle_max(a, b, e)
    slow = max(np.arcsin(e / (b - a)), np.arcsin(abs(a - e) / b))
    return float(slow), float(fast)
