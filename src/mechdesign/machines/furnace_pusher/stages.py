"""Heating-furnace pusher (加热炉推料机, seed 003): a crank-rocker O1A–AB–rocker DBC and the
link CE to the pushing slider E, driven through a worm reducer and an open gear pair.

Formulation of the synthesis (SI inside, D the origin, the rocker swinging symmetrically
about +y, C at the top):

* the slider's guide is perpendicular to the bisector of the rocker's swing (horizontal)
  at height y_g. At the rocker's two extremes C1, C2 are at the same height, so CE makes
  the same angle with the guide at both ends and E's stroke equals the chord C1C2
  exactly: H = 2·DC·sin(ψ/2), ψ = 2·arcsin(H/(2·DC)) (no chord approximation). E moves
  monotonically with the rocker (it would stop only where CE is perpendicular to C's
  path), so E's extremes are the rocker's and the six-bar's K is the four-bar's;
* the pressure angle at E is the angle of CE to the guide, sin α = |y_g − y_C|/CE; C's
  height spans the sagitta f = DC·(1 − cos(ψ/2)) in each stroke, so the guide through
  the middle of the sagitta gives the smallest α_max = arcsin(f/(2·CE)), and a guide
  offset by e gives arcsin((f/2 + |e|)/CE) — the limit [α] allows |e| ≤ CE·sin[α] − f/2;
* the crank-rocker O1A–AB–DB: θ = 180°(K − 1)/(K + 1), rocker DB = (DB/DC)·DC swinging
  ψ; the crank pivot O1 lies on the θ-circle through B1, B2 (:mod:`mechdesign.core.fourbar`),
  a = (O1B2 − O1B1)/2, b = (O1B2 + O1B1)/2. The free position of O1 on the circle (both
  circles, ``side`` ±1) is chosen to maximise the minimum transmission angle γ_min over the
  cycle, subject to the pressure angle at B, 90° − γ, staying within [α] over the working
  stroke (the seed applied the 30° there) — or is fixed by a given frame O1D.

The working (slow) stroke's direction in space follows from the crank's sense of rotation
(mirroring the linkage does not change it); E sits ahead of C in that direction.

Links (as the seed numbers the slider 5): 1 crank O1A, 2 coupler AB, 3 rocker DBC, 4 link
CE, 5 slider E, 6 frame.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, fields

import numpy as np

from .brief import FurnaceParams, PusherParams
from ...core import fourbar as fb
from ...core.fields import q
from ...core.mechanism import RRP, RRR, Crank, LinkPoint, Mechanism
from ...core.synthesis import extreme_angle
from ...pipeline import Stage
from ...stages.drive import DriveDocument, design_drive, drive_document
from ...i18n import N_
from ...stages.findings import Finding, Msg, Pair, finding, zh_en
from ...core.extremes import brentq, fminbound, polish_minimum
from ...stages.linkage import LinkageDocument, LinkageModel, Output, Resistance, linkage_document, linkage_stages
from ...stages import titles

FRAME = "6"
CRANK, COUPLER, ROCKER, ROD, SLIDER = "1", "2", "3", "4", "5"
TWO_PI = 2.0 * np.pi


def link_names() -> dict:
    """The links' names by link (catalogue messages)."""
    return {CRANK: Msg.pgettext("link", "crank O1A"), COUPLER: Msg.pgettext("link", "coupler AB"),
            ROCKER: Msg.pgettext("link", "rocker DBC"), ROD: Msg.pgettext("link", "link CE"),
            SLIDER: Msg.pgettext("link", "pusher slider E")}

# The original report's printed numbers (section 4): a, b, the chord B1B2 it used, its frame O1O2
# and the rocker length 1150 mm its second equation uses.
SEED = {"crank": 0.09192, "coupler": 1.17547, "chord": 0.19462, "frame": 0.50537,
        "rocker": 1.150, "theta_used_deg": 30.0}


# ----------------------------------------------------------------------------- synthesis

@dataclass(frozen=True)
class SeedCheck:
    """The original report's solution a = 91.92, b = 1175.47 mm put back into its own equations and
    simulated (closed-form extremes) with the rocker 1150 mm and frame 505.37 mm its
    second equation uses."""

    crank: float = q("m", "the original report's a = O1A")
    coupler: float = q("m", "the original report's b = AB")
    rocker: float = q("m", "the rocker its second equation uses")
    frame: float = q("m", "its frame O1O2")
    chord: float = q("m", "the B1B2 it used")
    theta_used: float = q("rad", "the angle it put into eq. (1) (30°, not θ)")
    eq1_printed: float = q("m²", "(a+b)² + (b−a)² − B1B2² − 2(a+b)(b−a)·cos 30°")
    eq1_correct: float = q("m²", "the same with the correct θ")
    chord_printed: float = q("m", "B1B2 implied by a, b with cos 30°")
    chord_correct: float = q("m", "B1B2 implied by a, b with θ")
    eq3_lhs: float = q("rad", "arccos((b² + c² − (d + a)²)/(2bc)) + 30°, printed '= 180°'")
    theta: float = q("rad", "simulated extreme-position angle θ")
    time_ratio: float = q("1", "simulated K")
    swing: float = q("rad", "simulated rocker swing ψ")
    stroke_C: float = q("m", "C's chord 2·DC·sin(ψ/2) (≈ the slider's stroke)")
    gamma_min: float = q("rad", "γ_min of the original report's four-bar")


@dataclass(frozen=True)
class PusherSynthesis:
    """Stage 执行机构设计: every dimension [m], angle [rad], and the equations' residuals."""

    stroke: float               # H
    time_ratio: float           # K
    theta: float                # θ
    swing: float                # ψ of the rocker
    rocker_DC: float
    link_CE: float
    rocker_DB: float            # c
    crank: float                # a = O1A
    coupler: float              # b = AB
    frame: float                # d = O1D
    O1: complex                 # crank pivot (D at the origin)
    B1: complex                 # B at the folded extreme (O1B1 = b − a)
    B2: complex                 # B at the extended extreme (O1B2 = b + a)
    C1: complex
    C2: complex
    E1: complex                 # slider at the extreme that starts the working stroke
    E2: complex                 # slider at the other extreme
    A_fold: complex             # crank pin at the folded extreme
    A_ext: complex
    crank_angle_fold: float     # [rad, CCW from +x]
    crank_angle_ext: float
    sense: float                # +1 CCW, −1 CW
    working_direction: float    # +1: the working stroke pushes E towards +x, −1: −x
    sagitta: float              # f = DC(1 − cos ψ/2)
    guide_height: float         # y_g above D
    guide_offset: float         # y_g − (middle of the sagitta)
    guide_offset_max: float     # |offset| allowed by [α] at E
    alpha_limit: float          # [α]
    alpha_E: float              # closed-form α_max at E over the working stroke
    gamma_min: float            # closed-form γ_min of the four-bar over the cycle
    gamma_max: float
    gamma_work: float           # closed-form γ_min over the working stroke
    alpha_B: float              # 90° − gamma_work
    gamma_limit: float          # [γ] for the check
    limit_rocker: bool          # the limit also applies at B
    criterion: str              # "max_gamma" | "frame" | "given" (the brief's dimensions)
    side: int                   # θ-circle: +1 (O1 on D's side of B1B2) or −1
    arc_position: float         # parameter of O1 on the θ-circle
    arc: tuple                  # (p_lo, p_hi) the allowed arc
    constraint_active: bool     # the pressure-angle limit at B bounds the optimum
    gamma_unconstrained: float  # best γ_min on the chosen circle without the limit at B
    gamma_other_side: float     # best feasible γ_min on the other circle (0: none)
    gamma_other_side_free: float  # best γ_min on the other circle without the limit at B
    scan: tuple                 # (positions, γ_min, γ_work, frame) over the chosen arc
    residuals: tuple            # ((name, equation, value), ...) relative residuals
    seed: SeedCheck
    warnings: tuple = ()


def _gamma_of(b, c, L):
    """Transmission angle [rad] with the crank pin at distance L from D (vectorised)."""
    cos_d = np.clip((b * b + c * c - L * L) / (2.0 * b * c), -1.0, 1.0)
    d = np.arccos(cos_d)
    return np.minimum(d, np.pi - d)


def extremes_of(cons: fb.CircleConstruction, p):
    """(O1, a, b, d, A_fold, A_ext, crank angle fold, crank angle ext) at arc parameter(s) p."""
    o1 = cons.point(p)
    a, b, d = cons.designs(p)
    u1 = (cons.c1 - o1) / np.abs(cons.c1 - o1)
    u2 = (cons.c2 - o1) / np.abs(cons.c2 - o1)
    a_fold, a_ext = o1 - a * u1, o1 + a * u2
    return o1, a, b, d, a_fold, a_ext, np.angle(-u1), np.angle(u2)


def _place_given(design: fb.FourBar, circles: dict):
    """(side, construction, extremes) of the brief's crank-rocker placed exactly: B1, B2 of
    the construction (D at the origin), O1 at the distance d from D and b − a from B1 (law
    of cosines), on the side where O1B2 = b + a; the extremes as :func:`extremes_of` gives
    them, but with the given lengths."""
    a, b, c, d = design.crank, design.coupler, design.rocker, design.frame
    cons0 = next(cons for cons in circles.values() if cons is not None)
    b1, b2 = cons0.c1, cons0.c2
    t = np.arccos(np.clip((d * d + c * c - (b - a) ** 2) / (2.0 * d * c), -1.0, 1.0))
    cands = [complex(d * b1 / abs(b1) * np.exp(1j * s * t)) for s in (+1.0, -1.0)]
    o1 = min(cands, key=lambda x: abs(abs(x - b2) - (b + a)))
    side = min((s for s in circles if circles[s] is not None),
               key=lambda s: abs(abs(o1 - circles[s].centre) - circles[s].radius))
    u1, u2 = (b1 - o1) / abs(b1 - o1), (b2 - o1) / abs(b2 - o1)
    return side, circles[side], (o1, a, b, d, o1 - a * u1, o1 + a * u2, float(np.angle(-u1)),
                                 float(np.angle(u2)))


def working_gamma(cons: fb.CircleConstruction, p, exact=None) -> np.ndarray:
    """Minimum transmission angle over the working (slow) stroke [rad], closed form,
    vectorised over the arc parameter p.

    The coupler-rocker angle depends only on L = |AD|, the crank pin's distance from D,
    which is stationary only with the crank along O1D (L = d − a, pointing at D) or
    against it (L = d + a). Over the working stroke — the longer of the two crank arcs
    between the extremes, 180° + θ whatever the sense of rotation — γ is therefore
    smallest at one of its ends or at a collinear position inside it.
    """
    o1, a, b, d, a_fold, a_ext, ph_f, ph_e = exact or extremes_of(cons, p)
    c = cons.rocker
    ccw = np.mod(ph_e - ph_f, TWO_PI)                # crank arc fold → ext, counter-clockwise
    start = np.where(ccw > np.pi, ph_f, ph_e)
    length = np.where(ccw > np.pi, ccw, TWO_PI - ccw)
    near = np.angle(-o1)                             # crank pointing at D: L = d − a
    far = near + np.pi

    def inside(x):
        return np.mod(x - start, TWO_PI) < length

    g = np.minimum(_gamma_of(b, c, np.abs(a_fold)), _gamma_of(b, c, np.abs(a_ext)))
    g = np.where(inside(near), np.minimum(g, _gamma_of(b, c, d - a)), g)
    g = np.where(inside(far), np.minimum(g, _gamma_of(b, c, d + a)), g)
    return g


def _best_on_circle(cons: fb.CircleConstruction, limit: float | None, grid: int = 2001):
    """(p*, γ_min(p*), constraint active?, best unconstrained γ_min) maximising γ_min on
    the allowed arc with working_gamma ≥ limit; None when no point is feasible."""
    span = cons.p_hi - cons.p_lo
    ps = cons.p_lo + span * (np.arange(1, grid + 1) / (grid + 1))
    g = cons.gamma_min(ps)
    free_best = float(np.max(g))
    if limit is None:
        feasible = np.ones_like(g, dtype=bool)
    else:
        feasible = working_gamma(cons, ps) >= limit

    def gw(x):
        return float(working_gamma(cons, x)) - (limit if limit is not None else -1.0)

    if not feasible.any():
        return None, 0.0, True, free_best
    k = int(np.argmax(np.where(feasible, g, -1.0)))
    lo = ps[k - 1] if k > 0 else cons.p_lo + 1e-12 * span
    hi = ps[k + 1] if k + 1 < grid else cons.p_hi - 1e-12 * span
    active = False
    # Shrink the bracket to the feasible side of any neighbour that breaks the limit.
    if k > 0 and not feasible[k - 1]:
        lo, active = brentq(gw, ps[k - 1], ps[k], xtol=1e-15), True
    if k + 1 < grid and not feasible[k + 1]:
        hi, active = brentq(gw, ps[k], ps[k + 1], xtol=1e-15), True
    x_best, f_best = fminbound(lambda x: -float(cons.gamma_min(x)), lo, hi,
                               xatol=1e-14 * max(1.0, span))
    # a smooth maximum's place to the zero of its slope, not Brent's √ε (machine-dependent)
    x_best = polish_minimum(lambda x: -float(cons.gamma_min(x)), x_best, lo, hi, 1e-4 * span)
    f_best = -float(cons.gamma_min(x_best))
    cands = [(x_best, -f_best), (ps[k], float(g[k]))]
    if active:
        cands += [(lo, float(cons.gamma_min(lo))), (hi, float(cons.gamma_min(hi)))]
    cands = [(x, v) for x, v in cands if limit is None or gw(x) >= -1e-12]
    p_best, g_best = max(cands, key=lambda t: t[1])
    on_limit = limit is not None and abs(gw(p_best)) < 1e-9
    return p_best, g_best, on_limit, free_best


def _seed_check(theta: float, rocker_DC: float) -> SeedCheck:
    a, b, chord = SEED["crank"], SEED["coupler"], SEED["chord"]
    c, d = SEED["rocker"], SEED["frame"]
    used = np.radians(SEED["theta_used_deg"])

    def eq1(t):
        return (a + b) ** 2 + (b - a) ** 2 - chord ** 2 - 2 * (a + b) * (b - a) * np.cos(t)

    def implied(t):
        return np.sqrt((a + b) ** 2 + (b - a) ** 2 - 2 * (a + b) * (b - a) * np.cos(t))

    lhs3 = np.arccos((b * b + c * c - (d + a) ** 2) / (2 * b * c)) + used
    design = fb.FourBar(a, b, c, d)
    th, psi = fb.crank_rocker_extremes(design)
    g_min, _ = fb.transmission_angle_extremes(design)
    return SeedCheck(a, b, c, d, chord, used, float(eq1(used)), float(eq1(theta)),
                     float(implied(used)), float(implied(theta)), float(lhs3), th,
                     float((np.pi + th) / (np.pi - th)), psi, float(2 * rocker_DC * np.sin(psi / 2)),
                     g_min)


def _circle(theta, swing, rocker, side):
    try:
        return fb.circle_construction_theta(theta, swing, rocker, side=side)
    except fb.SynthesisError:
        return None


def synthesize(pp: PusherParams) -> PusherSynthesis:
    """The six-bar from H, K, DC, CE and the pressure-angle limit (see the module text).
    Raises :class:`~mechdesign.core.fourbar.SynthesisError` naming the brief field to change."""
    H, R, L = pp.stroke, pp.rocker_DC, pp.link_CE
    if pp.given is not None:
        theta, swing = fb.crank_rocker_extremes(pp.given)
    if pp.given is None and not H < 2.0 * R:
        raise fb.SynthesisError(Msg(
            N_("pusher.stroke_H_mm = {H:g} mm needs a rocker DC longer than H/2: the chord of C's "
               "arc cannot exceed 2·DC = {chord:g} mm (pusher.rocker_DC_mm)"),
            H=H * 1e3, chord=2 * R * 1e3))
    if pp.given is None:
        swing = 2.0 * np.arcsin(H / (2.0 * R))
        theta = float(extreme_angle(pp.time_ratio_K))
    sag = R * (1.0 - np.cos(swing / 2.0))
    off_max = L * np.sin(pp.pressure_angle_max) - sag / 2.0
    if off_max < 0.0:
        raise fb.SynthesisError(Msg(
            N_("pusher.link_CE_mm = {L:g} mm is too short: C's arc has a sagitta of {sag:.4g} mm, "
               "so CE must be at least {need:.4g} mm for a pressure angle at E within {alpha:g}°"),
            L=L * 1e3, sag=sag * 1e3, need=sag / 2 / np.sin(pp.pressure_angle_max) * 1e3,
            alpha=np.degrees(pp.pressure_angle_max)))
    if abs(pp.guide_offset) > off_max:
        raise fb.SynthesisError(Msg(
            N_("pusher.guide_offset_mm = {e:g} mm puts the pressure angle at E above {alpha:g}°: "
               "allowed |offset| ≤ {off:.4g} mm (CE·sin[α] − f/2 with the sagitta f = {sag:.4g} mm)"),
            e=pp.guide_offset * 1e3, alpha=np.degrees(pp.pressure_angle_max), off=off_max * 1e3,
            sag=sag * 1e3))
    c = pp.rocker_ratio * R if pp.given is None else pp.given.rocker
    limit = (np.pi / 2 - pp.pressure_angle_max) if pp.limit_rocker else None
    circles = {s: _circle(theta, swing, c, s) for s in (+1, -1)}
    exact = None
    if pp.given is not None:
        if all(cons is None for cons in circles.values()):
            raise fb.SynthesisError(Msg(
                N_("pusher.dimensions = {given}: θ = {theta:.6g}°, ψ = {psi:.6g}° admit no θ-circle "
                   "construction"), given=pp.given, theta=np.degrees(theta), psi=np.degrees(swing)))
        side, cons, exact = _place_given(pp.given, circles)
        p = cons.position_of(exact[0])
        criterion, active = "given", False
        g_free = _best_on_circle(cons, None)[1]
    elif pp.frame is not None:
        side = p = None
        ranges = []
        for s, cons in circles.items():
            if cons is None:
                continue
            try:
                p, side = fb.position_for_frame(cons, pp.frame), s
                break
            except fb.SynthesisError:
                lo, hi = fb.frame_range_theta(theta, swing, c, side=s)
                ranges.append(f"{lo * 1e3:.5g} – {hi * 1e3:.5g} mm")
        if p is None:
            sep_zh, sep_en = zh_en.pgettext("alternatives", " or ")
            raise fb.SynthesisError(Msg(
                N_("pusher.frame_O1D_mm = {frame:g} mm: no crank-rocker with θ = {theta:.4g}°, "
                   "ψ = {psi:.4g}° and DB = {DB:.5g} mm has this frame; it must lie in {ranges} "
                   "(exclusive), or use auto"), frame=pp.frame * 1e3, theta=np.degrees(theta),
                psi=np.degrees(swing), DB=c * 1e3,
                ranges=Pair(sep_zh.join(ranges), sep_en.join(ranges))))
        cons = circles[side]
        criterion, active = "frame", False
        g_free = _best_on_circle(cons, None)[1]
    else:
        found = {}
        for s, cons in circles.items():
            if cons is None:
                continue
            p_s, g_s, act, free = _best_on_circle(cons, limit)
            if p_s is not None:
                found[s] = (p_s, g_s, act, free)
        if not found:
            best_work = max(float(np.max(working_gamma(cons, cons.p_lo + (cons.p_hi - cons.p_lo)
                                                        * np.linspace(0.001, 0.999, 4001))))
                            for cons in circles.values() if cons is not None)
            raise fb.SynthesisError(Msg(
                N_("pusher.pressure_angle_max_deg = {alpha:g}°: with K = {K:g} (θ = {theta:.4g}°) and "
                   "the swing ψ = {psi:.4g}° the four-bar's pressure angle at B in the working stroke "
                   "cannot be below {least:.4g}°; raise the limit or set "
                   "pusher.limit_rocker_pressure_angle: false"),
                alpha=np.degrees(pp.pressure_angle_max), K=pp.time_ratio_K, theta=np.degrees(theta),
                psi=np.degrees(swing), least=90 - np.degrees(best_work)))
        side = max(found, key=lambda s: found[s][1])
        p, _, active, _ = found[side]
        cons = circles[side]
        g_free = _best_on_circle(cons, None)[1]
        criterion = "max_gamma"
    other = circles[-side]
    g_other = g_other_free = 0.0
    if other is not None:
        g_other = _best_on_circle(other, limit)[1]
        g_other_free = _best_on_circle(other, None)[1]
    o1, a, b, d, a_fold, a_ext, ph_f, ph_e = (complex(x) if np.iscomplexobj(x) else float(x)
                                              for x in (exact or extremes_of(cons, p)))
    sense = float(np.sign(pp.crank_omega))
    # Working (slow) stroke: fold → ext when that arc in the sense of rotation exceeds π.
    fold_to_ext = np.mod(sense * (ph_e - ph_f), TWO_PI) > np.pi
    B1, B2 = cons.c1, cons.c2
    scale = R / c
    C1, C2 = B1 * scale, B2 * scale
    start_C, end_C = (C1, C2) if fold_to_ext else (C2, C1)
    direction = float(np.sign((end_C - start_C).real))
    y_g = R * (1.0 + np.cos(swing / 2.0)) / 2.0 + pp.guide_offset

    def slider(cp):
        return complex(cp.real + direction * np.sqrt(L * L - (y_g - cp.imag) ** 2), y_g)

    E1, E2 = slider(start_C), slider(end_C)
    g_min, g_max = fb.transmission_angle_extremes(fb.FourBar(a, b, c, d))
    g_work = float(working_gamma(cons, p, exact))
    alpha_E = float(np.arcsin((sag / 2.0 + abs(pp.guide_offset)) / L))
    chord = abs(B2 - B1)
    residuals = (
        ("stroke", r"\lvert E_1E_2\rvert - H", (abs(E2 - E1) - H) / H),
        ("chord", r"B_1B_2 - 2\,l_{DB}\sin(\psi/2)", (chord - 2 * c * np.sin(swing / 2)) / c),
        ("eq1", r"(b-a)^2+(b+a)^2-2(b-a)(b+a)\cos\theta - B_1B_2^2",
         ((b - a) ** 2 + (b + a) ** 2 - 2 * (b - a) * (b + a) * np.cos(theta) - chord ** 2) / chord ** 2),
        ("folded", r"O_1B_1 - (b-a)", (abs(B1 - o1) - (b - a)) / b),
        ("extended", r"O_1B_2 - (b+a)", (abs(B2 - o1) - (b + a)) / b),
        ("frame", r"O_1D - d", (abs(o1) - d) / d),
        ("theta", r"\angle B_1O_1B_2 - \theta",
         abs(np.angle((B2 - o1) / (B1 - o1))) - theta),
        ("K", r"\frac{180°+\theta}{180°-\theta} - K",
         (np.pi + theta) / (np.pi - theta) - pp.time_ratio_K),
    ) if pp.given is None else (
        ("stroke", r"\lvert E_1E_2\rvert - 2\,l_{DC}\sin(\psi/2)", (abs(E2 - E1) - H) / H),
        ("chord", r"B_1B_2 - 2\,l_{DB}\sin(\psi/2)", (chord - 2 * c * np.sin(swing / 2)) / c),
        ("folded", r"O_1B_1 - (b-a)", (abs(B1 - o1) - (b - a)) / b),
        ("extended", r"O_1B_2 - (b+a)", (abs(B2 - o1) - (b + a)) / b),
        ("frame", r"O_1D - d", (abs(o1) - d) / d),
        ("theta", r"\angle B_1O_1B_2 - \theta", abs(np.angle((B2 - o1) / (B1 - o1))) - theta),
    )
    span = cons.p_hi - cons.p_lo
    ps = cons.p_lo + span * np.linspace(0.002, 0.998, 241)
    scan = (ps, cons.gamma_min(ps), working_gamma(cons, ps), np.abs(cons.point(ps)))
    warnings = []
    if criterion == "max_gamma" and g_min < pp.transmission_angle_min - 1e-12:
        # The linkage check reports the shortfall itself; this says it cannot be helped here.
        warnings.append(finding(
            "transmission_angle_best",
            N_("the minimum transmission angle {gamma:.2f}° is already the largest possible for "
               "K = {K:g} and the swing ψ = {psi:.2f}°: raising it needs a smaller K or a larger "
               "swing (a larger H/DC)"), gamma=np.degrees(g_min), K=pp.time_ratio_K,
            psi=np.degrees(swing)))
    return PusherSynthesis(
        stroke=H, time_ratio=pp.time_ratio_K, theta=theta, swing=float(swing), rocker_DC=R, link_CE=L,
        rocker_DB=c, crank=a, coupler=b, frame=d, O1=o1, B1=B1, B2=B2, C1=C1, C2=C2, E1=E1, E2=E2,
        A_fold=a_fold, A_ext=a_ext, crank_angle_fold=ph_f, crank_angle_ext=ph_e, sense=sense,
        working_direction=direction, sagitta=float(sag), guide_height=float(y_g),
        guide_offset=pp.guide_offset, guide_offset_max=float(off_max),
        alpha_limit=pp.pressure_angle_max, alpha_E=alpha_E, gamma_min=g_min, gamma_max=g_max,
        gamma_work=g_work, alpha_B=float(np.pi / 2 - g_work),
        gamma_limit=pp.transmission_angle_min, limit_rocker=pp.limit_rocker,
        criterion=criterion, side=side, arc_position=float(p), arc=(cons.p_lo, cons.p_hi),
        constraint_active=bool(active), gamma_unconstrained=float(g_free),
        gamma_other_side=float(g_other), gamma_other_side_free=float(g_other_free), scan=scan,
        residuals=tuple((n, eq, float(v)) for n, eq, v in residuals),
        seed=_seed_check(theta, R), warnings=tuple(warnings))


def build_mechanism(syn: PusherSynthesis, crank_omega: float) -> Mechanism:
    """Crank O1A → RRR (AB, DB) → C on the rocker's extension → RRP (CE, slider E)."""
    m = Mechanism(FRAME, {"O1": syn.O1, "D": 0j})
    m.add(Crank("crank O1A", CRANK, "O1", "A", syn.crank, crank_omega))
    # Branch of B: the side of A→D it lies on at the folded extreme.
    branch = int(np.sign((np.conj(0j - syn.A_fold) * (syn.B1 - syn.A_fold)).imag))
    m.add(RRR("RRR ABD", COUPLER, ROCKER, "A", "D", "B", syn.coupler, syn.rocker_DB, branch))
    m.add(LinkPoint("C", ROCKER, "D", syn.rocker_DC, 0.0))
    guide = 0.0 if syn.working_direction > 0 else np.pi
    m.add(RRP("RRP CE", ROD, SLIDER, "C", "E", syn.link_CE, complex(0.0, syn.guide_height), guide,
              branch=+1, frame=FRAME))
    return m


def build_model(syn: PusherSynthesis, p: FurnaceParams) -> LinkageModel:
    pp = p.pusher
    guide = 0.0 if syn.working_direction > 0 else np.pi
    return LinkageModel(
        mechanism=build_mechanism(syn, pp.crank_omega), crank_omega=pp.crank_omega,
        output=Output("point", "E", guide, working=+1), bodies=(),
        resistances=(Resistance(SLIDER, "E", guide, pp.working_force, pp.return_force),),
        grid_points=p.grid_points, position_step=p.position_step, gravity=p.gravity,
        flywheel=None, pressure_angle_limit=pp.pressure_angle_max,
        transmission_angle_min=pp.transmission_angle_min, names=link_names(), advice={
            "pressure": Msg(N_("brief fields: a longer pusher.link_CE_mm, or "
                               "pusher.guide_offset_mm closer to 0")),
            "transmission": Msg(N_("brief fields: a smaller pusher.time_ratio_K or a larger "
                                   "swing (pusher.stroke_H_mm / pusher.rocker_DC_mm), "
                                   "pusher.frame_O1D_mm: auto"))})


def checks(p: FurnaceParams, keep: dict | None = None) -> list:
    """The feasibility checks of a run (after validation, once): can the data make the
    six-bar? Every problem as a :class:`~mechdesign.brief.loader.BriefProblem` at its brief
    field (the value is filled in from the brief by the runner). The synthesis is stored
    in ``keep["synthesis"]`` for :func:`synthesis_stage`, so it is not computed twice."""
    from ...brief.loader import BriefProblem

    try:
        syn = synthesize(p.pusher)
    except fb.SynthesisError as exc:
        field = re.match(r"(pusher\.[A-Za-z_0-9]+) = ", exc.en)
        return [BriefProblem(field.group(1) if field else "pusher", "", exc.en, exc.zh)]
    if keep is not None:
        keep["synthesis"] = syn
    return []


def synthesis_stage(r: dict):
    syn = r.get("checked", {}).get("synthesis") or synthesize(r["params"].pusher)
    return syn, build_model(syn, r["params"])


# ------------------------------------------------------------------------ spec checks

@dataclass(frozen=True)
class PusherCheck:
    """Stage 设计要求校核: the task's specification against the simulation of this run."""

    stroke: float = q("m", "simulated stroke of E (bounded position search)")
    stroke_error: float = q("m", "simulated stroke − H")
    time_ratio: float = q("1", "simulated K")
    alpha_E_work: float = q("rad", "simulated α_max at E over the working stroke")
    gamma_min: float = q("rad", "simulated γ_min of the four-bar over the cycle")
    gamma_work: float = q("rad", "simulated γ_min of the four-bar over the working stroke")
    alpha_B_work: float = q("rad", "pressure angle at B in the working stroke, 90° − gamma_work")
    mean_torque: float = q("N·m", "mean M_b")
    mean_power: float = q("W", "mean M_b·ω")
    resistance_power: float = q("W", "mean of F·|v_E| over the grid (the kinematics alone)")
    hand_power: float = q("W", "(F_w + F_r)·H·n/60")
    peak_torque: float = q("N·m", "max M_b")
    peak_factor: float = q("1", "peak / mean torque")
    resistance_force: np.ndarray = q("N", "|F| on E over the phase array (grid, then positions)")
    virtual_work_torque: np.ndarray = q("N·m", "F·|v_E|/ω over the phase array (virtual work)")
    virtual_work_error: float = q("1", "max |M_b − F·|v_E|/ω| / max M_b")
    warnings: tuple[Finding, ...] = q("", "specification misses", default=())


def _quality(k, kind: str):
    return next(q for q in k.quality if q.kind == kind)


def check(p: FurnaceParams, syn: PusherSynthesis, k, f, v) -> PusherCheck:
    pp = p.pusher
    n = k.grid_size
    working = k.phase <= k.working_span + 1e-12
    force = np.where(working, pp.working_force, pp.return_force)
    res_power = float(np.mean(force[:n] * np.abs(k.v[:n])))
    # Virtual work: with no friction, gravity or inertia M_b·ω = F·|v_E| at every instant.
    mb_vw = force * np.abs(k.v) / abs(pp.crank_omega)
    vw_error = float(np.max(np.abs(f.balancing_torque - mb_vw)) / np.max(np.abs(f.balancing_torque)))
    rrp, rrr = _quality(k, "pressure"), _quality(k, "transmission")
    hand = (pp.working_force + pp.return_force) * pp.stroke * pp.crank_speed_rpm / 60.0
    warnings = []
    if abs(v.stroke - pp.stroke) > 1e-6 * pp.stroke or abs(v.time_ratio - pp.time_ratio_K) > 1e-6:
        warnings.append(finding(
            "spec", N_("the simulated stroke {H:.2f} mm and K = {K:.4f} miss the specification (the check allows "
                        "a relative 10⁻⁶)"),
            H=v.stroke * 1e3, K=v.time_ratio))
    if pp.limit_rocker and np.pi / 2 - rrr.working_extreme > pp.pressure_angle_max + 1e-6:
        warnings.append(finding(
            "rocker_pressure_angle",
            N_("simulation: the pressure angle at B in the working stroke, {alpha:.2f}°, exceeds "
               "{limit:g}°"), alpha=90 - np.degrees(rrr.working_extreme),
            limit=np.degrees(pp.pressure_angle_max)))
    return PusherCheck(
        stroke=v.stroke, stroke_error=v.stroke - pp.stroke, time_ratio=v.time_ratio,
        alpha_E_work=rrp.working_extreme, gamma_min=rrr.extreme, gamma_work=rrr.working_extreme,
        alpha_B_work=float(np.pi / 2 - rrr.working_extreme), mean_torque=f.mean_torque,
        mean_power=f.mean_power, resistance_power=res_power, hand_power=float(hand),
        peak_torque=f.peak_torque, peak_factor=float(f.peak_torque / f.mean_torque),
        resistance_force=force, virtual_work_torque=mb_vw, virtual_work_error=vw_error,
        warnings=tuple(warnings))


# ------------------------------------------------------------------------------ drive

def _drive(r: dict):
    """The drive delivers the crank's mean power M̄_b·ω at the crank speed. There is no
    flywheel, so every stage carries the peak of M_b: the strength checks use the
    torques scaled by peak/mean from the first shaft on."""
    p, c = r["params"], r["pusher_check"]
    # the bearing life's equivalent load: the cycle's cube-mean torque (see design_drive)
    mb = r["linkage_forces"].balancing_torque[:r["linkage"].grid_size]
    life = float(np.mean(np.abs(mb) ** 3) ** (1 / 3) / c.mean_torque)
    from ...stages.crank_load import crank_load

    crank = {len(p.drive.stages): crank_load(r["model"], r["linkage"], r["linkage_forces"])}
    return design_drive(p.drive, c.mean_power, p.pusher.crank_speed_rpm, "mechanism",
                        c.peak_factor, 0, life, crank=crank)


def stages(params: FurnaceParams) -> list[Stage]:
    out = [Stage(("synthesis", "model"), titles.pgettext("stage", "six-bar synthesis"), synthesis_stage)]
    out += linkage_stages(model_key="model", prefix="linkage")
    out.append(Stage("pusher_check", titles.pgettext("stage", "specification check"),
                     lambda r: check(r["params"], r["synthesis"], r["linkage"], r["linkage_forces"],
                                     r["linkage_verification"])))
    if params.drive is not None:
        out.append(Stage("drive", titles.pgettext("stage", "drive"), _drive))
    return out


@dataclass(frozen=True)
class PusherSynthesisDoc:
    """The six-bar's synthesis (执行机构设计), D (the rocker's pivot) at the origin."""

    stroke: float = q("m", "H, the slider's stroke")
    time_ratio: float = q("1", "K")
    theta: float = q("rad", "θ = 180°(K − 1)/(K + 1)")
    swing: float = q("rad", "ψ = 2·arcsin(H/(2·DC)), the rocker's swing")
    rocker_DC: float = q("m", "L_DC")
    link_CE: float = q("m", "L_CE")
    rocker_DB: float = q("m", "c = L_DB")
    crank: float = q("m", "a = L_O1A")
    coupler: float = q("m", "b = L_AB")
    frame: float = q("m", "d = L_O1D")
    O1: complex = q("m", "crank pivot, [x, y]")
    B1: complex = q("m", "B at the folded extreme (O1B1 = b − a)")
    B2: complex = q("m", "B at the extended extreme (O1B2 = b + a)")
    C1: complex = q("m", "C at the folded extreme")
    C2: complex = q("m", "C at the extended extreme")
    E1: complex = q("m", "slider at the extreme that starts the working stroke")
    E2: complex = q("m", "slider at the other extreme")
    A_fold: complex = q("m", "crank pin at the folded extreme")
    A_ext: complex = q("m", "crank pin at the extended extreme")
    crank_angle_fold: float = q("rad", "crank angle at the folded extreme, CCW from +x")
    crank_angle_ext: float = q("rad", "crank angle at the extended extreme")
    sense: float = q("1", "+1 CCW, −1 CW crank")
    working_direction: float = q("1", "+1: the working stroke pushes E towards +x, −1: −x")
    sagitta: float = q("m", "f = DC·(1 − cos(ψ/2)), the sagitta of C's arc")
    guide_height: float = q("m", "y_g, the slider guide above D")
    guide_offset: float = q("m", "e = y_g − (middle of the sagitta)")
    guide_offset_max: float = q("m", "|e| allowed by [α] at E: CE·sin[α] − f/2")
    alpha_limit: float = q("rad", "[α], the allowed pressure angle")
    alpha_E: float = q("rad", "closed-form α_max at E over the working stroke")
    gamma_min: float = q("rad", "closed-form γ_min of the four-bar over the cycle")
    gamma_max: float = q("rad", "closed-form γ_max of the four-bar")
    gamma_work: float = q("rad", "closed-form γ_min over the working stroke")
    alpha_B: float = q("rad", "pressure angle at B in the working stroke, 90° − gamma_work")
    gamma_limit: float = q("rad", "[γ] for the check")
    limit_rocker: bool = q("", "the limit [α] also applies at B")
    criterion: str = q("", "'max_gamma' (O1 placed for the largest γ_min), 'frame' (given O1D) or "
                       "'given' (the brief's dimensions, no synthesis)")
    side: int = q("1", "θ-circle: +1 (O1 on D's side of B1B2) or −1")
    arc_position: float = q("rad", "parameter of O1 on the θ-circle (angle at its centre)")
    arc: tuple[float, float] = q("rad", "(p_lo, p_hi), the allowed arc")
    constraint_active: bool = q("", "the pressure-angle limit at B bounds the optimum")
    gamma_unconstrained: float = q("rad", "best γ_min on the chosen circle without the limit at B")
    gamma_other_side: float = q("rad", "best feasible γ_min on the other circle (0: none)")
    gamma_other_side_free: float = q("rad", "best γ_min on the other circle without the limit at B")
    residuals: dict[str, float] = q("1 (theta: rad)", "the synthesis equations put back: stroke, "
                                    "chord, eq1, folded, extended, frame (relative), theta, K")


@dataclass(frozen=True)
class FurnaceResults:
    """Heating-furnace pusher (加热炉推料机): crank-rocker O1A–AB–rocker DBC and the link CE
    to the pushing slider E (links 1 crank, 2 coupler AB, 3 rocker DBC, 4 link CE, 5 slider
    E, 6 frame), driven through a reducer. Frame: D (the rocker's pivot) at the origin, the
    rocker swinging symmetrically about +y with C at the top, the slider's guide horizontal
    at y = synthesis.guide_height; the linkage's output is E along the working direction."""

    schema: str = q("", "'mechdesign.results/2'")
    machine: str = q("", "'furnace_pusher'")
    units: str = q("", "reminder of the unit system")
    synthesis: PusherSynthesisDoc = q("", "the six-bar's dimensions and the synthesis' residuals")
    seed: SeedCheck = q("", "the original report's printed solution put back into its equations")
    linkage: LinkageDocument = q("", "the linkage engine's results")
    check: PusherCheck = q("", "the specification against the simulation")
    drive: DriveDocument | None = q("", "the drive, when the brief has one")


FURNACE_UNITS = "SI: m, s, rad, N, N·m, W; complex vectors as [x, y]; speeds in rpm where named _rpm"


def results_document(r: dict) -> FurnaceResults:
    """Everything computed, SI units, for ``results.json``."""
    from ...results import SCHEMA

    syn = r["synthesis"]
    plain = {f.name: getattr(syn, f.name) for f in fields(PusherSynthesisDoc)
             if f.name != "residuals"}
    return FurnaceResults(
        schema=SCHEMA, machine="furnace_pusher", units=FURNACE_UNITS,
        synthesis=PusherSynthesisDoc(**plain, residuals={name: value for name, _, value in
                                                         syn.residuals}),
        seed=syn.seed,
        linkage=linkage_document(r["model"], r["linkage"], r["linkage_forces"],
                                 r["linkage_flywheel"], r["linkage_verification"],
                                 r.get("linkage_graphical")),
        check=r["pusher_check"],
        drive=None if r.get("drive") is None else drive_document(r["drive"]))
