"""Involute gear geometry (孙桓《机械原理》, chapter on gears): external spur pairs, standard
or profile-shifted, helical and worm pairs' basic geometry.

SI or any consistent length unit (the formulas are homogeneous); angles in radians.
Work in progress for the gear issue: geometry only, no strength checks yet.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .fields import q


def inv(alpha):
    """Involute function inv α = tan α − α."""
    return np.tan(alpha) - alpha


def inv_inverse(value: float) -> float:
    """The angle α in [0, π/2) with inv α = ``value`` (≥ 0).

    Newton's method on f(α) = tan α − α − value (f′ = tan²α). f is increasing and convex
    on [0, π/2), so from a start where f ≥ 0 the iterates fall monotonically onto the
    root: both α = ∛(3·value) (tan α − α ≥ α³/3) and α = atan(value + π/2) are such
    starts, and so is the smaller of them."""
    if value < 0:
        raise ValueError("the involute function is not negative")
    if value == 0:
        return 0.0
    a = min(np.cbrt(3.0 * value), np.arctan(value + np.pi / 2))
    for _ in range(100):
        t = np.tan(a)
        step = (t - a - value) / (t * t)
        a -= step
        if step <= 4e-16 * a:
            break
    return float(a)


@dataclass(frozen=True)
class GearDims:
    """One gear of a spur pair (lengths in the pair's length unit: m in results)."""

    z: int = q("1", "number of teeth z")
    x: float = q("1", "profile-shift coefficient x")
    d: float = q("m", "pitch (reference) diameter d = m z")
    db: float = q("m", "base diameter d_b = d cos α")
    da: float = q("m", "tip diameter d_a")
    df: float = q("m", "root diameter d_f")
    ha: float = q("m", "addendum h_a")
    hf: float = q("m", "dedendum h_f")
    s: float = q("m", "tooth thickness on the pitch circle s")
    e: float = q("m", "space width on the pitch circle e")
    sa: float = q("m", "tooth thickness on the tip circle s_a")
    alpha_a: float = q("rad", "pressure angle at the tip α_a")


@dataclass(frozen=True)
class SpurPair:
    """An external spur pair without backlash (lengths in the pair's length unit: m in results)."""

    m: float = q("m", "module m")
    alpha: float = q("rad", "pressure angle α of the reference circle")
    ha_star: float = q("1", "addendum coefficient h_a*")
    c_star: float = q("1", "clearance coefficient c*")
    g1: GearDims = q("", "gear 1 (the pinion z1)")
    g2: GearDims = q("", "gear 2 (the wheel z2)")
    p: float = q("m", "circular pitch p = π m")
    pb: float = q("m", "base pitch p_b = p cos α")
    a: float = q("m", "standard centre distance a")
    a_work: float = q("m", "working centre distance a′")
    alpha_work: float = q("rad", "working pressure angle α′")
    y: float = q("1", "centre distance modification coefficient y = (a′ − a)/m")
    dy: float = q("1", "tip reduction coefficient Δy = x1 + x2 − y")
    clearance: float = q("m", "radial clearance at the working centre distance")
    ratio: float = q("1", "gear ratio u = z2/z1")
    contact_ratio: float = q("1", "contact ratio ε")
    action_length: float = q("m", "B1B2, the actual line of action")
    z_min: float = q("1", "least tooth number of a standard gear without undercut, 2h_a*/sin²α "
                          "rounded to the nearest integer (Sun Huan: 17 at α = 20°, h_a* = 1)")
    x_min1: float = q("1", "smallest shift avoiding undercut, gear 1")
    x_min2: float = q("1", "smallest shift avoiding undercut, gear 2")


def _gear(m, z, x, alpha, ha, hf) -> GearDims:
    d = m * z
    db = d * np.cos(alpha)
    da, df = d + 2 * ha, d - 2 * hf
    s = m * (np.pi / 2 + 2 * x * np.tan(alpha))
    e = np.pi * m - s
    alpha_a = float(np.arccos(db / da))
    sa = s * da / d - da * (inv(alpha_a) - inv(alpha))
    return GearDims(z, x, d, db, da, df, ha, hf, s, e, float(sa), alpha_a)


def least_teeth(alpha: float = np.radians(20.0), ha_star: float = 1.0) -> float:
    """The least tooth number z_min of a standard gear cut by a rack without undercut, as the
    textbook states it (孙桓《机械原理》, 变位齿轮: z_min = 17 for α = 20°, h_a* = 1; 14 for
    short teeth, h_a* = 0.8): the limit 2h_a*/sin²α rounded to the nearest integer. The
    rounding accepts a 17-tooth standard gear although 2/sin²20° = 17.10: its rack tip line
    passes the limit point N by (1 − 17 sin²20°/2) m = 0.0057 m, which cuts the involute only
    within 10⁻⁶ m of the base circle, below where any mating gear's tip reaches."""
    return float(np.rint(2 * ha_star / np.sin(alpha) ** 2))


def spur_pair(m: float, z1: int, z2: int, alpha: float = np.radians(20.0), ha_star: float = 1.0,
              c_star: float = 0.25, x1: float = 0.0, x2: float = 0.0) -> SpurPair:
    """External spur pair without backlash. The working pressure angle follows from
    inv α' = 2 tan α (x1 + x2)/(z1 + z2) + inv α, the centre distance from a' cos α' = a cos α;
    the tips are shortened by Δy·m so that the clearance stays c*·m."""
    a = m * (z1 + z2) / 2
    alpha_w = inv_inverse(2 * np.tan(alpha) * (x1 + x2) / (z1 + z2) + inv(alpha))
    a_w = a * np.cos(alpha) / np.cos(alpha_w)
    y = (a_w - a) / m
    dy = x1 + x2 - y
    g1 = _gear(m, z1, x1, alpha, (ha_star + x1 - dy) * m, (ha_star + c_star - x1) * m)
    g2 = _gear(m, z2, x2, alpha, (ha_star + x2 - dy) * m, (ha_star + c_star - x2) * m)
    eps = (z1 * (np.tan(g1.alpha_a) - np.tan(alpha_w)) + z2 * (np.tan(g2.alpha_a) - np.tan(alpha_w))) / (2 * np.pi)
    pb = np.pi * m * np.cos(alpha)
    z_min = least_teeth(alpha, ha_star)
    return SpurPair(m, alpha, ha_star, c_star, g1, g2, np.pi * m, pb, a, a_w, alpha_w, y, dy,
                    a_w - g1.da / 2 - g2.df / 2, z2 / z1, float(eps), float(eps * pb), z_min,
                    ha_star * (z_min - z1) / z_min, ha_star * (z_min - z2) / z_min)



# --- Tooth outlines and the meshing layout (the course's 啮合图) ---------------------------
#
# A gear's own frame: centre at the origin, tooth 0 centred on the +x axis, the teeth
# numbered counter-clockwise. The outline is the one the pair's basic rack generates: straight
# flanks at α, tip line hf + x m below the reference line, tip corners rounded with the
# standard radius ρf = c* m / (1 − sin α) (0.38 m for c* = 0.25), tangent to the tip line and
# to the flank at the depth ha* m, so that the outline is undercut exactly when
# x < h_a* − z sin²α/2 (the exact limit; x_min rounds z_min to the textbook's integer).
#   * Involute flank: half angular thickness at radius ρ (from s_ρ = s ρ/r − 2ρ(inv α_ρ − inv α))
#         ψ(ρ) = s/(2r) − (inv α_ρ − inv α),   cos α_ρ = rb/ρ.
#   * Root fillet: the envelope of the rounded tip. Rolling the rack's pitch line on the pitch
#     circle, the rack point (u, h) (u along the rack, h above the rolling line) is at
#         X = e^{i(π/z − φ)} (r + h + i k),   k = u + r φ,
#     and the rounding's centre C touches the gear where the normal from the rolling point
#     meets it: X = C + ρf (C − P)/|C − P|, for k from 0 (bottom: the root circle) to h_C cot α
#     (the rounding's end at the flank, then on the line of action: the form circle, where
#     the fillet meets the involute tangentially). If that end lies beyond N the
#     fillet cuts the involute instead: the outline is the generated, undercut one.


def _rack_fillet(gear: GearDims, m, alpha, c_star, k):
    """Points (complex, own frame, the tooth's counter-clockwise side) that the rack's tip
    rounding generates at the rack positions ``k``; also the rounding centre's height h_C."""
    r, rho_f = gear.d / 2, c_star * m / (1 - np.sin(alpha))
    h_c = rho_f - gear.hf
    u_c = rho_f * np.cos(alpha) - (np.pi * m / 4 - gear.hf * np.tan(alpha) + (c_star - gear.x) * m * np.tan(alpha))
    rel = h_c + 1j * np.asarray(k, dtype=float)           # C − P in the rolling frame
    side = -np.sign(h_c) if h_c != 0 else -1.0             # the rounding's active side
    points = np.exp(1j * (np.pi / gear.z - (rel.imag - u_c) / r)) * (r + rel * (1 + side * rho_f / np.abs(rel)))
    return points, h_c


def _involute_half_angle(gear: GearDims, alpha, rho):
    return gear.s / gear.d - (inv(np.arccos(np.minimum(gear.db / 2 / np.asarray(rho, dtype=float), 1.0))) - inv(alpha))


def _fillet_end(gear: GearDims, m, alpha, c_star) -> float:
    """Rack position k where the fillet hands over to the involute."""
    h_c = _rack_fillet(gear, m, alpha, c_star, 0.0)[1]
    k_end = h_c / np.tan(alpha)                            # the rounding's end on the line of action
    if gear.d / 2 * np.sin(alpha) >= (gear.hf - c_star * m) / np.sin(alpha):
        return k_end                                       # that point lies before N: no undercut
    from .extremes import brentq

    at = lambda k: _rack_fillet(gear, m, alpha, c_star, k)[0]  # noqa: E731
    k_b = brentq(lambda k: abs(at(k)) - gear.db / 2, k_end, 0.0, xtol=2e-12)
    gap = lambda k: _involute_half_angle(gear, alpha, abs(at(k))) - np.angle(at(k))  # noqa: E731
    return brentq(gap, k_end, k_b, xtol=2e-12) if gap(k_b) > 0 else k_b


def form_radius(gear: GearDims, m, alpha, c_star=0.25) -> float:
    """Radius where the flank stops being the involute: the form circle (the fillet meets
    the involute tangentially there), or for an undercut gear the radius where the fillet
    cuts the involute."""
    return float(abs(_rack_fillet(gear, m, alpha, c_star, _fillet_end(gear, m, alpha, c_star))[0]))


def tooth_half_angle(gear: GearDims, m, alpha, c_star, rho):
    """Half the angular thickness ψ(ρ) [rad] of the generated tooth at radius ρ: the tooth
    occupies |θ| ≤ ψ(ρ). The involute's closed form above :func:`form_radius`, the fillet
    (interpolated between 400 generated points) below it."""
    fillet = _rack_fillet(gear, m, alpha, c_star, np.linspace(0.0, _fillet_end(gear, m, alpha, c_star), 400))[0]
    rho = np.asarray(rho, dtype=float)
    return np.where(rho >= abs(fillet[-1]), _involute_half_angle(gear, alpha, rho),
                    np.interp(rho, np.abs(fillet), np.angle(fillet)))


def tooth_outline(gear: GearDims, m, alpha, c_star=0.25, points: int = 40) -> np.ndarray:
    """One generated tooth (complex, the gear's own frame, tooth centred on the +x axis),
    counter-clockwise from the middle of the space below it (angle −π/z on the root circle)
    to the middle of the space above it (+π/z): root arc, fillet, involute flank, tip arc,
    flank, fillet, root arc. ``points`` samples per fillet and per involute flank."""
    rb, ra = gear.db / 2, gear.da / 2
    fillet = _rack_fillet(gear, m, alpha, c_star, np.linspace(0.0, _fillet_end(gear, m, alpha, c_star), points))[0]
    # the involute sampled evenly in its roll angle tan α_ρ, from the fillet's end to the tip
    roll = np.linspace(np.sqrt(max((abs(fillet[-1]) / rb) ** 2 - 1, 0.0)), np.sqrt((ra / rb) ** 2 - 1), points)[1:]
    rho = rb * np.sqrt(1 + roll**2)
    psi = np.maximum(_involute_half_angle(gear, alpha, rho), 0.0)     # a pointed tooth stays closed
    flank = np.concatenate([fillet, rho * np.exp(1j * psi)])           # the counter-clockwise side
    tip = ra * np.exp(1j * np.linspace(-psi[-1], psi[-1], max(points // 4, 3))[1:-1])
    root = gear.df / 2 * np.exp(1j * np.linspace(np.angle(fillet[0]), np.pi / gear.z, max(points // 4, 2)))
    return np.concatenate([np.conj(root[:0:-1]), np.conj(flank), tip, flank[::-1], root[1:]])


def gear_outline(gear: GearDims, m, alpha, c_star=0.25, rotation: float = 0.0, centre: complex = 0j,
                 points: int = 40) -> np.ndarray:
    """Closed outline (complex, counter-clockwise, first point repeated at the end) of all z
    teeth: tooth k centred at angle rotation + 2πk/z about ``centre``."""
    tooth = tooth_outline(gear, m, alpha, c_star, points)[:-1]
    turns = np.exp(1j * (rotation + 2 * np.pi * np.arange(gear.z) / gear.z))
    ring = (turns[:, None] * tooth[None, :]).ravel()
    return centre + np.append(ring, ring[:1])


@dataclass(frozen=True)
class MeshLayout:
    """Everything the meshing drawing needs, in the pair's length unit (complex points).

    Frame: O1 at the origin, O2 = i a' (the line of centres vertical, gear 2 above), the
    pitch point P = i r1'. Gear 1 drives counter-clockwise (gear 2 turns clockwise): the
    line of action runs from N1 (on base circle 1, right of the line of centres) up to N2
    (on base circle 2, left of it), inclined at α' to the common tangent at P;
    ``direction`` is its unit vector N1 → N2, the way the contact point travels. Contact
    starts at B2 (tip circle 2 on N1N2) and ends at B1 (tip circle 1).

    ``rotation1``/``rotation2`` turn the gears' own frames (:func:`gear_outline`) so that the
    counter-clockwise flank of a tooth of each touches at P (``phase`` = 0), tangent to each
    other with their common normal N1N2."""
    pair: SpurPair
    o1: complex
    o2: complex
    p: complex
    n1: complex
    n2: complex
    b1: complex
    b2: complex
    direction: complex
    r1w: float            # working pitch radii r' = rb / cos α'
    r2w: float
    rotation1: float
    rotation2: float
    action_length: float  # |B1B2|
    pb: float
    contact_ratio: float  # |B1B2| / pb

    @property
    def interference(self) -> bool:
        """True when B2 falls before N1 or B1 beyond N2: a tip would then work below the
        other gear's base circle (the contact ratio formula no longer holds there)."""
        along = ((np.array([self.b2, self.b1, self.n2]) - self.n1) * np.conj(self.direction)).real
        return bool(along[0] < 0 or along[1] > along[2])

    def outlines(self, points: int = 40) -> tuple[np.ndarray, np.ndarray]:
        """Both gears' closed outlines placed in the layout."""
        g = self.pair
        return (gear_outline(g.g1, g.m, g.alpha, g.c_star, self.rotation1, self.o1, points),
                gear_outline(g.g2, g.m, g.alpha, g.c_star, self.rotation2, self.o2, points))


def mesh_layout(pair: SpurPair, phase: float = 0.0) -> MeshLayout:
    """The meshing layout of ``pair``; ``phase`` [rad] turns gear 1 further counter-clockwise
    (gear 2 follows clockwise by phase z1/z2), moving the contact along N1N2 by rb1·phase."""
    g1, g2, aw = pair.g1, pair.g2, pair.alpha_work
    r1w, r2w = g1.db / 2 / np.cos(aw), g2.db / 2 / np.cos(aw)
    o1, o2, p = 0j, 1j * pair.a_work, 1j * r1w
    u = complex(np.exp(1j * (np.pi - aw)))              # N1 → N2
    n1, n2 = p - r1w * np.sin(aw) * u, p + r2w * np.sin(aw) * u
    b1 = n1 + np.sqrt((g1.da / 2) ** 2 - (g1.db / 2) ** 2) * u
    b2 = n2 - np.sqrt((g2.da / 2) ** 2 - (g2.db / 2) ** 2) * u
    rot1 = np.pi / 2 - float(tooth_half_angle(g1, pair.m, pair.alpha, pair.c_star, r1w)) + phase
    rot2 = -np.pi / 2 - float(tooth_half_angle(g2, pair.m, pair.alpha, pair.c_star, r2w)) - phase * g1.z / g2.z
    length = abs(b1 - b2)
    return MeshLayout(pair, o1, o2, p, complex(n1), complex(n2), complex(b1), complex(b2), u,
                      float(r1w), float(r2w), rot1, rot2, length, pair.pb, length / pair.pb)


@dataclass(frozen=True)
class HelicalPair:
    mn: float
    mt: float
    beta: float
    alpha_t: float
    d1: float
    d2: float
    a: float


def helical_pair(mn: float, z1: int, z2: int, beta: float, alpha_n: float = np.radians(20.0)) -> HelicalPair:
    """Basic geometry of a standard helical pair: m_t = m_n / cos β, tan α_t = tan α_n / cos β."""
    mt = mn / np.cos(beta)
    return HelicalPair(mn, mt, beta, float(np.arctan(np.tan(alpha_n) / np.cos(beta))), mt * z1, mt * z2,
                       mt * (z1 + z2) / 2)


@dataclass(frozen=True)
class WormPair:
    m: float
    q: float
    z1: int
    z2: int
    d1: float
    d2: float
    lead_angle: float
    a: float
    ratio: float


def worm_pair(m: float, q: float, z1: int, z2: int) -> WormPair:
    """Worm (z1 starts, diameter factor q) and wheel (z2): d1 = m q, d2 = m z2,
    tan γ = z1 / q, a = m (q + z2)/2."""
    return WormPair(m, q, z1, z2, m * q, m * z2, float(np.arctan(z1 / q)), m * (q + z2) / 2, z2 / z1)


def worm_efficiency(lead_angle: float, friction_angle: float) -> float:
    """Meshing efficiency of a worm driving its wheel: η = tan γ / tan(γ + φ_v)."""
    return float(np.tan(lead_angle) / np.tan(lead_angle + friction_angle))
