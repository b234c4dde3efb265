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

from .errors import DesignError
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


def grashof_sums(fb: FourBar) -> tuple[str, str]:
    """The Grashof check in words with its numbers [mm]: (en, zh), e.g. "shortest + longest
    = 20 + 60 = 80 mm > 45 + 30 = 75 mm (the other two)"."""
    lengths = {"crank": fb.crank, "coupler": fb.coupler, "rocker": fb.rocker, "frame": fb.frame}
    zh_names = {"crank": "曲柄", "coupler": "连杆", "rocker": "摇杆", "frame": "机架"}
    order = sorted(lengths, key=lengths.get)
    s, p, q, l_ = (lengths[k] for k in order)

    def mm(x):
        return f"{x * 1e3:.6g}"
    rel = ">" if s + l_ > p + q else "≤"
    en = (f"crank a = {mm(fb.crank)}, coupler b = {mm(fb.coupler)}, rocker c = {mm(fb.rocker)}, "
          f"frame d = {mm(fb.frame)} mm: shortest ({order[0]}) + longest ({order[-1]}) = "
          f"{mm(s)} + {mm(l_)} = {mm(s + l_)} mm {rel} {mm(p)} + {mm(q)} = {mm(p + q)} mm "
          "(the other two)")
    zh = (f"曲柄 a = {mm(fb.crank)}，连杆 b = {mm(fb.coupler)}，摇杆 c = {mm(fb.rocker)}，"
          f"机架 d = {mm(fb.frame)} mm：最短杆（{zh_names[order[0]]}）+ 最长杆（{zh_names[order[-1]]}）"
          f"= {mm(s)} + {mm(l_)} = {mm(s + l_)} mm {rel} 其余两杆之和 {mm(p)} + {mm(q)} = {mm(p + q)} mm")
    return en, zh


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
        en, zh = grashof_sums(fb)
        raise SynthesisError(f"not a crank-rocker ({kind}; {en}): the extreme positions are undefined",
                             f"不是曲柄摇杆机构（{kind}；{zh}）：极位无定义")
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
        raise SynthesisError(f"extreme-position angle θ = {np.degrees(theta):.6g}° must be in "
                             "[0°, 90°) (time ratio 1 ≤ K < 3)",
                             f"极位夹角 θ = {np.degrees(theta):.6g}° 须在 [0°, 90°) 内"
                             "（行程速比系数 1 ≤ K < 3）")
    if not (np.isfinite(swing) and 0.0 < swing < np.pi):
        raise SynthesisError(f"rocker swing ψ = {np.degrees(swing):.6g}° must be in (0°, 180°)",
                             f"摇杆摆角 ψ = {np.degrees(swing):.6g}° 须在 (0°, 180°) 内")
    if not (np.isfinite(rocker) and rocker > 0.0):
        raise SynthesisError(f"rocker length {rocker} must be positive", f"摇杆长度 {rocker} 须为正")


def _theta_of(K: float) -> float:
    if not np.isfinite(K) or K < 1.0:
        raise SynthesisError(f"time ratio K = {K} must be ≥ 1", f"行程速比系数 K = {K} 须 ≥ 1")
    if K >= 3.0:
        raise SynthesisError(f"time ratio K = {K} gives θ ≥ 90°; a crank-rocker needs K < 3",
                             f"行程速比系数 K = {K} 使 θ ≥ 90°；曲柄摇杆机构须 K < 3")
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
            f"no crank-rocker on this θ-circle (side {side}) for θ = {np.degrees(theta):.6g}°, "
            f"ψ = {np.degrees(swing):.6g}°: the line AD separates C1 and C2 everywhere",
            f"θ = {np.degrees(theta):.6g}°、ψ = {np.degrees(swing):.6g}° 时该 θ 圆（第 {side} 侧）上"
            "无曲柄摇杆机构：直线 AD 处处把 C1 与 C2 分在两侧")
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
            f"position {np.degrees(position):.6g}° is outside the allowed arc "
            f"({np.degrees(cons.p_lo):.6g}°, {np.degrees(cons.p_hi):.6g}°)",
            f"位置 {np.degrees(position):.6g}° 不在允许的圆弧 "
            f"({np.degrees(cons.p_lo):.6g}°, {np.degrees(cons.p_hi):.6g}°) 内")
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
        raise SynthesisError(f"frame length {frame} must be positive", f"机架长度 {frame} 须为正")
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
            raise SynthesisError("the θ-circle is centred on D: every A has the same frame "
                                 "length, so the frame does not fix the design",
                                 "θ 圆圆心在 D 点：所有 A 点的机架长度相同，机架长度不能确定设计")
        big = abs(cons.centre) ** 2 + cons.radius ** 2
        cos_t = (frame ** 2 - big) / (2.0 * cons.radius * on)
        if abs(cos_t) <= 1.0:
            p = float(np.arccos(cos_t))
        ends = [abs(complex(cons.point(cons.p_lo))), abs(complex(cons.point(cons.p_hi)))]
        lo, hi = min(ends), max(ends)
    if p is None or not (cons.p_lo < p < cons.p_hi):
        top = "∞" if not np.isfinite(hi) else f"{hi * 1e3:.6g}"
        raise SynthesisError(
            f"frame length {frame * 1e3:.6g} mm cannot be met: with θ = "
            f"{np.degrees(cons.theta):.6g}°, ψ = {np.degrees(cons.swing):.6g}° and rocker "
            f"{c * 1e3:.6g} mm the crank pivot on the allowed arc gives frames between "
            f"{lo * 1e3:.6g} and {top} mm (exclusive)",
            f"机架长度 {frame * 1e3:.6g} mm 无法实现：θ = {np.degrees(cons.theta):.6g}°、"
            f"ψ = {np.degrees(cons.swing):.6g}°、摇杆 {c * 1e3:.6g} mm 时，曲柄转动中心在允许圆弧上"
            f"所得的机架长度介于 {lo * 1e3:.6g} 与 {top} mm 之间（不含端点）")
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
    neighbours of the best grid point."""
    cons = circle_construction_theta(theta, swing, rocker, side=side)
    span = cons.p_hi - cons.p_lo
    ps = cons.p_lo + span * (np.arange(1, grid + 1) / (grid + 1))
    gs = cons.gamma_min(ps)
    k = int(np.argmax(gs))
    lo = ps[k - 1] if k > 0 else cons.p_lo + 1e-12 * span
    hi = ps[k + 1] if k + 1 < len(ps) else cons.p_hi - 1e-12 * span

    def neg(p):
        return -float(cons.gamma_min(p))

    from .extremes import fminbound

    p_best, f_best = fminbound(neg, lo, hi, xatol=1e-13 * max(1.0, span))
    g_best = -f_best
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

    The slider guide is the line y = −e (offset below A); the slider's extremes are
    C1 = (x1, −e) (folded, AC1 = b − a) and C2 = (x2, −e) (extended, AC2 = b + a).
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
        raise SynthesisError(f"time ratio K = {K} must be > 1 for an offset slider-crank "
                             "(K = 1 needs no offset: a centred slider-crank)",
                             f"偏置曲柄滑块机构须 K > 1，而 K = {K}（K = 1 不需偏距：用对心曲柄滑块机构）")
    theta = extreme_angle(K)
    if not stroke > 0.0:
        raise SynthesisError(f"stroke H = {stroke} must be positive", f"行程 H = {stroke} 须为正")
    if not offset > 0.0:
        raise SynthesisError(f"offset e = {offset} must be > 0: with e = 0 the extreme "
                             "positions are 180° apart and K = 1",
                             f"偏距 e = {offset} 须 > 0：e = 0 时两极位相隔 180°，K = 1")
    limit = stroke / np.tan(theta)
    if offset >= limit:
        raise SynthesisError(
            f"offset e = {offset * 1e3:.6g} mm is too large for K = {K:.6g} and "
            f"H = {stroke * 1e3:.6g} mm: it must be below H·cot θ = {limit * 1e3:.6g} mm "
            "(reduce e or K, or increase H)",
            f"偏置曲柄滑块机构无实解：偏距 e = {offset * 1e3:.6g} mm 对 K = {K:.6g}、"
            f"H = {stroke * 1e3:.6g} mm 过大，须小于 H·cot θ = {limit * 1e3:.6g} mm"
            "（减小 e 或 K，或增大 H）")
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
        raise SynthesisError(f"crank {a} and rod {b} must be positive",
                             f"曲柄 {a} 与连杆 {b} 须为正")
    if a + e >= b:
        raise SynthesisError(
            f"crank + offset = {(a + e) * 1e3:.6g} mm ≥ rod {b * 1e3:.6g} mm: "
            "the crank cannot turn fully (lengthen the rod)",
            f"曲柄 + 偏距 = {(a + e) * 1e3:.6g} mm ≥ 连杆 {b * 1e3:.6g} mm：曲柄不能整周转动"
            "（加长连杆）")
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
