"""The cam stage, shared by every machine with a disc cam, and the two cam-only machines:
``cam`` (synthesis of a disc cam) and ``eccentric_cam`` (analysis of an eccentric disc).

The stage designs the cam on a fine grid, tabulates it at the brief's step, designs the
smallest base circle for the allowed pressure angles and checks the result: pressure angle
per segment, convex radius of curvature against the roller (undercut, pointed profile) and,
for a flat face, convexity. Problems that leave the cam computable but unusable become
:class:`Finding` entries, which the report prints and the command line shows as warnings.
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from ..core import cam as core
from ..core.fields import q
from ..pipeline import Stage
from ..i18n import N_
from .findings import Cat, CheckNames, Finding, Msg, Pair, finding, zh_en
from . import titles

GRID_POINTS = 3600


@dataclass(frozen=True)
class SegmentCheck:
    """One segment of the follower programme with its pressure-angle check."""

    kind: str = q("", "'rise' | 'dwell' | 'return'")
    law: str | None = q("", "motion law (null for a dwell)")
    start: float = q("rad", "cam angle where the segment starts")
    span: float = q("rad", "cam angle of the segment (Φ, Φs, Φ′, Φs′)")
    lift: float = q("m or rad", "signed follower travel in the segment")
    impact: str = q("",
        "worst impact of the motion (its ends and interior): 'none' | 'soft' | 'rigid'")
    max_pressure_angle: float = q("rad", "α_max in the segment")
    at: float = q("rad", "cam angle of α_max")
    limit: float | None = q("rad", "allowed pressure angle [α] (null for a dwell)")
    ok: bool = q("", "α_max ≤ [α]")


DEG = 180.0 / np.pi


@dataclass(frozen=True)
class Division:
    """One division point of the graphical method (反转法), numbered through the cycle."""

    number: int
    delta: float            # cam angle in [0, 2π) [rad]
    s: float                # follower displacement [m] (translating) or [rad] (oscillating)


@dataclass(frozen=True)
class CamDrawing:
    """What the cam figures and the cam sheet draw, computed by the stage (render only reads)."""

    divisions: tuple                    # Division points: every rise/return in parts(span) equal parts
    division_profile: core.CamProfile   # the cam designed at exactly the division angles [m, rad]
    diagram_delta: np.ndarray           # s–δ curve: fine grid, 2π and every segment start [rad]
    diagram_s: np.ndarray               # displacement there [m] or [rad] (at 2π: the value at 0)
    segment_ends: tuple                 # per segment (δ end − 1e-9 [rad], (s, ds/dδ, d²s/dδ², d³s/dδ³)
                                        # left-hand limits [m or rad, per rad, per rad², per rad³])
    internal_jumps: tuple               # core.Boundary: acceleration jumps inside a segment
    offset_favourable: bool             # the offset's sign lowers the rise pressure angle
    arm_side: int                       # oscillating follower: k in β = π − k(φ0 + φ); 0 otherwise


@dataclass(frozen=True)
class CurvatureCheck:
    """A check of the profile's curvature: the pitch curve's smallest convex radius beside the
    roller (no undercut), the actual profile's beside the brief's least ρ_a (not pointed), a
    flat face's profile convex."""

    key: str = q("", "'pitch_curvature' (ρ_min > r_r) | 'actual_curvature' (ρ_a ≥ least) | "
                     "'convex' (flat face: ρ > 0)")
    value: float = q("m", "the smallest radius of curvature checked")
    limit: float = q("m", "r_r, the least ρ_a of the brief, or 0")
    ok: bool = q("", "value > limit (≥ for 'actual_curvature')")


@dataclass(frozen=True)
class CamResult:
    params: object
    base_radius: float               # used [m]
    offset: float                    # signed x of the translating follower's axis [m] (0 otherwise)
    base_radius_designed: bool
    min_base_radius: float | None    # smallest r0 for the limits with this follower [m]
    best_offset: tuple | None        # (r0, e) with the best offset, translating knife/roller [m]
    grid: core.CamProfile
    table: core.CamProfile
    segments: list[SegmentCheck]
    boundaries: list[core.Boundary]
    rho_pitch_min_convex: float      # exact [m] (inf if none convex)
    rho_actual_min_convex: float     # exact [m]
    face_extent: tuple | None        # flat face: (min, max) contact position along the face [m]
    warnings: list[Finding]
    outline: np.ndarray | None = None              # the actual profile as cut, closed polyline [m]
    envelope: core.RollerEnvelope | None = None    # roller follower: corners and cut loops
    follower: object = None                        # the follower as designed (with its offset)
    drawing: CamDrawing | None = None              # what the figures and the sheet draw
    rho_actual_min: float | None = None            # smallest ρ of the actual profile, any sign [m]
    rho_pitch_min_concave: float | None = None     # smallest |ρ| where the pitch curve is concave [m]
    rho_actual_min_concave: float | None = None    # the same for the actual profile [m]
    curvature_checks: tuple = ()                   # CurvatureCheck: the profile's checks


def design(p) -> CamResult:
    """Run the cam stage for the SI cam parameters ``p`` (brief.cam.CamParams)."""
    prog, fol = p.programme, p.follower
    translating = isinstance(fol, core.TranslatingFollower)
    best = None
    min_r0 = None
    if translating:
        if fol.kind != "flat":
            best = core.min_base_radius_translating(prog, fol, p.alpha_rise, p.alpha_return,
                                                    None, p.rotation)
        # an automatic offset is kept to a whole tenth of a millimetre
        offset = float(np.round(best[1], 4)) if (p.auto_offset and best) else fol.offset
        fol = replace(fol, offset=offset)
        min_r0 = core.min_base_radius_translating(
            prog, fol, p.alpha_rise, p.alpha_return, offset, p.rotation,
            min_curvature=p.min_actual_curvature)[0]
    else:
        offset = 0.0
        if fol.kind != "flat":
            try:
                min_r0 = core.min_base_radius_oscillating(prog, fol, p.alpha_rise, p.alpha_return,
                                                          p.rotation)
            except core.CamDesignError:
                min_r0 = None
        else:
            min_r0 = None
    designed = p.base_radius is None
    if designed:
        if min_r0 is None:
            raise core.CamDesignError(Msg(N_(
                "cam.base_radius_mm: 'auto' cannot be met: no base radius keeps the pressure angle "
                "within the limits; give a base radius")))
        r0 = float(np.ceil(min_r0 * 1e3 - 1e-9) / 1e3)          # whole millimetres, upwards
        if fol.kind == "roller":
            r0 = max(r0, float(np.ceil((fol.roller_radius + p.min_actual_curvature) * 1e3) / 1e3))
    else:
        r0 = p.base_radius
    grid = core.design_cam(prog, fol, r0, p.rotation, GRID_POINTS)
    n_table = int(round(2 * np.pi / p.table_step))
    table = core.design_cam(prog, fol, r0, p.rotation,
                            delta=np.arange(n_table) * (2 * np.pi / n_table))
    # A roller cam as it is cut: where the pitch curve has a corner (a velocity jump) or the
    # offset curve a loop, the actual profile is the envelope of the roller circles (see
    # core.roller_envelope); its points replace the plain offset points there.
    envelope = None
    outline = grid.actual
    if fol.kind == "roller":
        envelope = core.roller_envelope(prog, fol, grid)
        outline = envelope.outline
        grid = replace(grid, actual=envelope.contact)
        table = replace(table, actual=core.envelope_contact(envelope, table))
    impacts = prog.impacts()
    # Exact extremes per segment (never read off the grid): the largest pressure angle and
    # the extreme curvatures, one-sided limits at law boundaries included.
    ext = core.exact_extremes(prog, fol, r0, p.rotation, GRID_POINTS)
    segs = []
    for i, seg in enumerate(prog.segments):
        limit = None if seg.kind == core.DWELL else (
            p.alpha_rise if seg.kind == core.RISE else p.alpha_return)
        top = ext[i].max_pressure_angle
        amax = float(top.value)
        segs.append(SegmentCheck(seg.kind, seg.law, float(prog.starts[i]), float(seg.span),
                                 float(prog.lifts[i]), impacts[i], amax,
                                 float(top.delta % (2 * np.pi)), limit,
                                 limit is None or amax <= limit + 1e-12))
    rr = grid.roller_radius
    if fol.kind == "flat":
        rho_min = min(float(e.min_rho.value) for e in ext)
        rho_p = rho_a = rho_min if rho_min > 0 else 0.0
        rho_p_concave = rho_a_concave = None
    else:
        kmax = max((float(e.max_curvature.value) for e in ext if e.max_curvature), default=0.0)
        kmin = min((float(e.min_curvature.value) for e in ext if e.min_curvature), default=0.0)
        rho_p = 1.0 / kmax if kmax > 0 else float("inf")
        rho_a = rho_p - rr
        rho_p_concave = -1.0 / kmin if kmin < 0 else None
        rho_a_concave = None if rho_p_concave is None else rho_p_concave + rr
        rho_min = None
    face = None
    if fol.kind == "flat":
        along = _face_positions(grid, fol)
        face = (float(np.min(along)), float(np.max(along)))
    warnings = _checks(p, fol, r0, segs, rho_p, rho_a, rho_min, min_r0, best)
    if fol.kind == "roller":
        curvature = (CurvatureCheck("pitch_curvature", rho_p, rr, bool(rho_p > rr)),
                     CurvatureCheck("actual_curvature", rho_a, p.min_actual_curvature,
                                    bool(rho_a >= p.min_actual_curvature)))
    elif fol.kind == "flat":
        curvature = (CurvatureCheck("convex", rho_min, 0.0, bool(rho_min > 0)),)
    else:
        curvature = ()
    return CamResult(p, r0, offset, designed, min_r0, best, grid, table, segs,
                     prog.boundaries(), rho_p, rho_a, face, warnings, outline, envelope, fol,
                     drawing(p, fol, r0, grid, offset), rho_min, rho_p_concave, rho_a_concave,
                     curvature)


def parts(span: float) -> int:
    """Equal parts of a rise or return of ``span`` [rad] in the graphical method: an even
    number (the middle of a symmetric law is a division point), at most 25° each, at least 4
    (6 from 60° on)."""
    deg = span * DEG
    n = int(np.ceil(deg / 25.0 - 1e-9))
    n += n % 2
    return max(n, 6 if deg >= 60.0 - 1e-9 else 4)


def divisions(prog) -> tuple:
    """The division points of the programme ``prog``: every rise and return in :func:`parts`
    equal parts, the ends of every segment; numbered 0, 1, 2, … from δ = 0 (360° is point 0
    again)."""
    angles = []
    for i, seg in enumerate(prog.segments):
        start, span = float(prog.starts[i]), float(prog.spans[i])
        k = 1 if seg.kind == core.DWELL else parts(span)
        angles += [start + span * j / k for j in range(k)]
    angles = np.array(sorted(a for a in angles if a < 2 * np.pi - 1e-9))
    keep = np.concatenate([[True], np.diff(angles) > 1e-9])
    angles = angles[keep]
    s = prog.evaluate(angles).s
    return tuple(Division(k, float(a), float(v)) for k, (a, v) in enumerate(zip(angles, s)))


def drawing(p, fol, r0: float, grid: core.CamProfile, offset: float) -> CamDrawing:
    """The drawing data of the cam designed with follower ``fol`` and base radius ``r0``."""
    prog = p.programme
    divs = divisions(prog)
    dprof = core.design_cam(prog, fol, r0, grid.rotation, delta=np.array([d.delta for d in divs]))
    dg = np.sort(np.concatenate([grid.delta, [2 * np.pi], prog.starts[1:]]))
    sg = prog.evaluate(np.where(dg >= 2 * np.pi, 0.0, dg)).s
    ends = tuple((prog.starts[i] + prog.spans[i] - 1e-9, prog.end_values(i, 1.0))
                 for i in range(len(prog.segments)))
    jumps = tuple(j for _, j in prog.internal_jumps())
    fav = bool(np.sign(offset) == core.favourable_offset_sign(p.rotation))
    side = core.arm_side(fol, p.rotation) if isinstance(fol, core.OscillatingFollower) else 0
    return CamDrawing(divs, dprof, dg, sg, ends, jumps, fav, side)


def _face_positions(prof: core.CamProfile, fol) -> np.ndarray:
    """Contact position along a flat face: from the follower axis (translating, signed x) or
    the distance from the pivot (oscillating)."""
    if "pivot" in prof.extras:
        return np.abs(prof.contact - prof.extras["pivot"])
    return prof.contact.real - fol.offset


def _mm(x: float) -> str:
    return f"{x * 1e3:.2f} mm"


def _more(target: float | None, now: float) -> bool:
    """``target`` [m] is a meaningful increase over ``now``: larger by at least 0.01 mm
    (what the advice prints), so no advice reads 'at least' the value it already has."""
    return target is not None and np.isfinite(target) and target - now >= 1e-5


#: A base radius more than this many times the given one is no practical advice.
ABSURD_R0 = 20.0


def _checks(p, fol, r0, segs, rho_p, rho_a, rho_min, min_r0, best) -> list[Finding]:
    """``min_r0``: smallest base radius for the limits (convexity for a flat face) with this
    follower; ``best``: (r0, e) with the best offset (translating knife/roller), or None;
    ``rho_min``: flat face: the smallest ρ of the profile (any sign). Every advice says
    which way to change a value and never asks for a change it cannot print (below 0.01 mm)
    or for a negative size."""
    out = []
    bad = [s for s in segs if not s.ok]
    if bad:
        worst = max(bad, key=lambda s: s.max_pressure_angle - s.limit)
        which = (Msg.pgettext("cam segment", "rise") if worst.kind == core.RISE
                 else Msg.pgettext("cam segment", "return"))
        raise_r0 = _more(min_r0, r0)
        fix = Cat(Msg(N_("increase the base radius to at least {r0}"), r0=_mm(min_r0)) if raise_r0
                  else Msg(N_("increase the base radius")))
        head = Msg(N_("the base radius r0 = {r0} is too small: "), r0=_mm(r0))
        span = np.degrees(worst.span)
        if worst.span < np.radians(5.0) and raise_r0 and min_r0 > ABSURD_R0 * r0:
            head = ""
            # over so short an angle no practical base radius helps: the angle is the fix
            fix = Cat(Msg(N_("give the {which} a larger cam angle (now {span:.4g}°): the base "
                             "radius alone would have to be at least {r0}, which no cam can be"),
                          which=which, span=span, r0=_mm(min_r0)))
        elif worst.span < np.radians(5.0):
            fix += Msg(N_(", or give the {which} a larger cam angle (now {span:.4g}°)"),
                       which=which, span=span)
        if best is not None and best[0] < r0:
            side = Msg.pgettext("side", "right") if best[1] > 0 else Msg.pgettext("side", "left")
            fix += Msg(N_(", or change the offset to e = {e} on the {side} (then the smallest base "
                          "radius is {r0})"), e=_mm(abs(best[1])), side=side, r0=_mm(best[0]))
        out.append(finding(
            "pressure_angle",
            N_("pressure angle too large: the {which}'s maximum {alpha:.2f}° (at δ = {at:.1f}°) "
               "exceeds the allowed {limit:.0f}°; {head}{fix}."),
            which=which, alpha=np.degrees(worst.max_pressure_angle), at=np.degrees(worst.at),
            limit=np.degrees(worst.limit), head=head, fix=fix))
    if fol.kind == "roller" and np.isfinite(rho_p):
        rr = fol.roller_radius
        if rr >= rho_p:
            target = rho_p - p.min_actual_curvature        # the largest roller that would do
            if target >= 1e-5:
                fix = Msg(N_("use a roller below {r} or a larger base circle"), r=_mm(target))
            else:                                          # no roller is small enough
                fix = Msg(N_("no roller keeps the actual profile's radius of curvature at {r} or "
                             "more: use a larger base circle"), r=_mm(p.min_actual_curvature))
            out.append(finding(
                "undercut",
                N_("undercut (the actual profile intersects itself, the follower motion is "
                   "distorted): the roller radius r_r = {rr} is not smaller than the smallest "
                   "convex radius of curvature of the pitch curve ρmin = {rho}; {fix}."),
                rr=_mm(rr), rho=_mm(rho_p), fix=fix))
        elif rho_a < p.min_actual_curvature:
            out.append(finding(
                "pointed",
                N_("pointed profile: the actual profile's smallest radius of curvature ρa = {rho} "
                   "is below {least} and will wear quickly; use a smaller roller or a larger base "
                   "circle."), rho=_mm(rho_a), least=_mm(p.min_actual_curvature)))
    if fol.kind == "flat":
        if rho_min <= 0:
            raise_r0 = _more(min_r0, r0)
            fix = (Msg(N_("use a base radius of at least {r0}"), r0=_mm(min_r0)) if raise_r0
                   else Msg(N_("increase the base radius")))
            out.append(finding(
                "concave_flat",
                N_("a flat-faced follower needs a convex cam everywhere, but the smallest radius "
                   "of curvature is {rho} (concave: the motion is distorted); {fix}."),
                rho=_mm(rho_min), fix=fix))
    return out


def cam_stage() -> Stage:
    """The cam stage of any machine whose parameters carry ``.cam`` (brief.cam.CamParams)."""
    return Stage("cam", titles.pgettext("stage", "cam design"), lambda r: design(r["params"].cam))


# --------------------------------------------------------------------------- eccentric disc


# --------------------------------------------------------------------------- self-checks


@dataclass(frozen=True)
class SelfCheck:
    """One self-check of a result, computed by a route independent of the design formulas.

    ``value`` is SI (m, rad, or a ratio); it passes when ``value ≤ limit`` (sense "le"),
    ``value ≥ limit`` ("ge"); sense "info" reports a number without a verdict. ``reference``
    is the value it is compared with, where there is one; ``detail`` names what the row is
    about (e.g. the follower's label, the cam angle)."""

    key: str
    value: float
    limit: float | None
    sense: str = "le"
    reference: float | None = None
    detail: dict = field(default_factory=dict)
    requirement: bool = False    # a design requirement (e.g. a strength margin), not a check of
                                 # the computation: its failure is a design finding elsewhere

    @property
    def passed(self) -> bool | None:
        if self.sense == "info" or self.limit is None:
            return None
        ok = self.value <= self.limit if self.sense == "le" else self.value >= self.limit
        return bool(ok and np.isfinite(self.value))


def failed_findings(checks, names: dict) -> list[Finding]:
    """A finding for every failed check of the computation (not for a design requirement);
    ``names`` maps a key to its (zh, en) name."""
    out = []
    for c in checks:
        if c.passed is False and not c.requirement:
            zh, en = names.get(c.key, (c.key, c.key))
            out.append(finding(
                "self_check",
                N_("self-check failed: {name}{where} = {value:.4g} (limit {limit:.4g}, SI units); "
                   "the results cannot be trusted, please report it."),
                name=Pair(zh, en), where=_where_message(c), value=c.value, limit=c.limit))
    return out


def _where_message(c: SelfCheck):
    """What the check is about, as a message field: a drive shaft by its message (the
    detail's ``shaft`` index), else the detail's ``label`` (a text the data give), else
    nothing."""
    if "shaft" in c.detail and "label" not in c.detail:
        return Cat(" (", Msg(N_("shaft {name}"), name=c.detail["shaft"]), ")")
    label = c.detail.get("label")
    return f" ({label})" if label else ""


# Limits of the cam self-checks (SI). Central differences on the 0.1° grid have truncation
# errors of order h² ≈ 3e-6 relative; a geometric distance to a polyline of the pitch curve
# is exact to well below a micrometre.
FD_LIMIT = 1e-3                 # relative, velocity/acceleration/curvature vs central differences
ALPHA_LIMIT = np.radians(1e-2)  # pressure angle from the chord vs the analytic one [rad] (0.01°)
DIST_LIMIT = 1e-6               # envelope distances [m] (1 µm) per 100 mm of cam size: the
#                                 chords of a 0.1° polyline grow with the cam (a 2 m cam's
#                                 profile is compared against a 20 µm limit)
DIST_SIZE = 0.1                 # [m] the cam size DIST_LIMIT holds for
CLOSURE_LIMIT = 1e-9            # relative to the stroke
DENSE_FACTOR = 20               # the reference pitch curve: 20 × the design grid


CAM_CHECK_NAMES = CheckNames({
    "angle_sum": N_("sum of the programme's angles"),
    "closure": N_("closure: s(360°) − s(0)"),
    "stroke": N_("largest displacement (must equal the stroke)"),
    "velocity_fd": N_("velocity vs central difference of s (relative)"),
    "acceleration_fd": N_("acceleration vs central difference (relative)"),
    "pressure_angle": N_("pressure angle from the pitch-curve tangent vs analytic"),
    "curvature_fd": N_("curvature 1/ρ vs three-point difference (relative)"),
    "envelope": N_("actual profile to pitch curve, distance − r_r"),
    "interference": N_("largest penetration of the roller into the profile"),
    "gap": N_("largest gap between roller and profile (off the edges)"),
    "offset_curve": N_("plain offset curve to pitch curve, distance − r_r"),
    "face_support": N_("flat face tangent to the profile (profile never crosses it)"),
    "corner": N_("actual profile at a velocity jump"),
})


@dataclass(frozen=True)
class CamVerification:
    checks: tuple[SelfCheck, ...]
    fd_step: float                      # [rad]
    corners: tuple                      # core.Corner of the roller envelope
    stand_off: float                    # [m]
    warnings: tuple[Finding, ...] = ()


def _stencil_mask(delta: np.ndarray, seg: np.ndarray, programme, h: float) -> np.ndarray:
    """Grid points whose central-difference stencil stays inside one segment and away from
    any jump inside a segment (e.g. the middle of the parabolic law)."""
    ok = (np.roll(seg, 1) == seg) & (np.roll(seg, -1) == seg)
    for _, b in programme.internal_jumps():
        dist = np.abs((delta - b.delta + np.pi) % (2 * np.pi) - np.pi)
        ok &= dist > 1.5 * h
    return ok


def _rel(err: np.ndarray, scale: np.ndarray) -> float:
    top = float(np.max(np.abs(scale))) if scale.size else 0.0
    worst = float(np.max(np.abs(err))) if err.size else 0.0
    return worst / top if top > 0 else worst


def verify_cam(c: CamResult) -> CamVerification:
    """Self-checks of the cam on its design grid, each by a route that does not use the
    formula it checks: the programme's closure, velocity and acceleration against central
    differences of the displacement, the pressure angle from the chord direction of the pitch
    curve, the curvature from three neighbouring pitch points, and for a roller the actual
    profile against a 20 × denser pitch curve (shortest distances both ways)."""
    p = c.params
    prog = p.programme
    g = c.grid
    m = g.motion
    n = len(g.delta)
    h = 2 * np.pi / n
    scale_s = prog.stroke
    checks = []
    total = float(np.sum(prog.spans))
    checks.append(SelfCheck("angle_sum", abs(total - 2 * np.pi), 1e-9, reference=2 * np.pi,
                            detail={"sum": total}))
    s_end = prog.end_values(len(prog.segments) - 1, 1.0)[0]
    checks.append(SelfCheck("closure", abs(s_end - float(m.s[0])), CLOSURE_LIMIT * scale_s,
                            reference=0.0, detail={"end": s_end}))
    checks.append(SelfCheck("stroke", abs(float(np.max(m.s)) - prog.stroke), CLOSURE_LIMIT * scale_s,
                            reference=prog.stroke, detail={"max": float(np.max(m.s))}))
    ok = _stencil_mask(g.delta, m.segment, prog, h)
    fwd = lambda x: np.roll(x, -1)   # noqa: E731
    back = lambda x: np.roll(x, 1)   # noqa: E731
    v_fd = (fwd(m.s) - back(m.s)) / (2 * h)
    a_fd = (fwd(m.ds) - back(m.ds)) / (2 * h)
    checks.append(SelfCheck("velocity_fd", _rel(m.ds[ok] - v_fd[ok], m.ds[ok]), FD_LIMIT,
                            detail={"step": h}))
    checks.append(SelfCheck("acceleration_fd", _rel(m.d2s[ok] - a_fd[ok], m.d2s[ok]), FD_LIMIT,
                            detail={"step": h}))
    # Pressure angle: the normal from the chord p(δ+h) − p(δ−h) of the pitch curve (the
    # profile for a flat face), turned into the frame, against the follower point's direction
    # of motion (the axis, or ⟂ to the arm through the pivot A).
    pitch = g.pitch
    chord = fwd(pitch) - back(pitch)
    normal_frame = 1j * chord * np.exp(1j * g.rotation * g.delta)
    if "pivot" in g.extras:
        point = g.contact if p.follower.kind == "flat" else g.follower_point
        motion_dir = 1j * (point - g.extras["pivot"])
    else:
        motion_dir = np.full_like(pitch, 1j)
    dot = np.conj(normal_frame) * motion_dir
    alpha_geo = np.arctan2(np.abs(dot.imag), np.abs(dot.real))
    checks.append(SelfCheck("pressure_angle",
                            float(np.max(np.abs(alpha_geo[ok] - g.pressure_angle[ok]))), ALPHA_LIMIT,
                            detail={"step": h}))
    # Curvature from three neighbouring points (the sign by the curve's own orientation).
    d1 = chord / (2 * h)
    d2 = (fwd(pitch) - 2 * pitch + back(pitch)) / h ** 2
    area = 0.5 * float(np.sum(np.imag(np.conj(pitch) * fwd(pitch))))
    kappa_fd = np.sign(area) * np.imag(np.conj(d1) * d2) / np.abs(d1) ** 3
    kappa = 1.0 / g.rho_pitch
    checks.append(SelfCheck("curvature_fd", _rel(kappa[ok] - kappa_fd[ok], kappa[ok]), FD_LIMIT,
                            detail={"step": h}))
    corners, stand_off = (), 0.0
    fol = c.follower if c.follower is not None else p.follower
    dist_limit = DIST_LIMIT * max(1.0, float(np.max(np.abs(g.pitch))) / DIST_SIZE)
    # An undercut cam (named by its own finding) has a self-intersecting profile: the roller
    # then does penetrate it. The envelope checks are a design verdict there, not a sign
    # that the computation is wrong.
    undercut = any(w.code == "undercut" for w in (c.warnings or ()))
    if p.follower.kind == "roller":
        rr = g.roller_radius
        dense_delta = np.unique(np.concatenate([
            np.arange(n * DENSE_FACTOR) * (2 * np.pi / (n * DENSE_FACTOR)), prog.starts]))
        dense = core.design_cam(prog, fol, c.base_radius, p.rotation, delta=dense_delta)
        outline = c.outline if c.outline is not None else g.actual
        out_dist = core.polyline_distance(outline, dense.pitch)
        checks.append(SelfCheck("envelope", float(np.max(np.abs(out_dist - rr))), dist_limit,
                                reference=rr, detail={"points": len(outline)},
                                requirement=undercut))
        in_dist = core.polyline_distance(dense.pitch, outline)
        checks.append(SelfCheck("interference", max(float(np.max(rr - in_dist)), 0.0), dist_limit,
                                reference=rr, requirement=undercut))
        # Off the edges every roller position touches the profile: leave out the positions
        # whose nearest profile point is an edge (there the roller stands off by design).
        off_edge = np.ones_like(dense_delta, dtype=bool)
        env = c.envelope
        if env is not None:
            for _, _, x, _ in env.edges:
                off_edge &= np.abs(dense.pitch - x) > in_dist + dist_limit
            corners, stand_off = env.corners, env.stand_off
        gap = float(np.max(in_dist[off_edge] - rr)) if np.any(off_edge) else 0.0
        checks.append(SelfCheck("gap", max(gap, 0.0), dist_limit, reference=rr,
                                requirement=undercut))
        raw = g.pitch - rr * g.normal
        raw_err = float(np.max(np.abs(core.polyline_distance(raw, dense.pitch) - rr)))
        if raw_err > dist_limit:
            checks.append(SelfCheck("offset_curve", raw_err, None, sense="info", reference=rr))
        for k in corners:
            checks.append(SelfCheck("corner", abs(k.turn), None, sense="info",
                                    detail={"delta": k.delta, "kind": k.kind, "stand_off": k.stand_off}))
    design_findings = []
    if p.follower.kind == "flat":
        cut, at = _face_support(c)
        checks.append(SelfCheck("face_support", cut, DIST_LIMIT, requirement=True, detail={"delta": at}))
        if cut > DIST_LIMIT:
            # A flat face cannot envelope a velocity jump: the cam it would need crosses the face.
            design_findings.append(finding(
                "flat_face_cut",
                N_("the flat-faced follower's motion is distorted: at δ = {at:.1f}° the cam profile "
                   "crosses the face by {cut:.3f} mm, so the face cannot follow the programme (a "
                   "flat face cannot envelope a velocity jump); use a law without rigid impact or a "
                   "roller follower."), at=np.degrees(at), cut=cut * 1e3))
    return CamVerification(tuple(checks), h, corners, stand_off,
                           tuple(failed_findings(checks, CAM_CHECK_NAMES) + design_findings))


def _face_support(c: CamResult, every: int = 5) -> tuple[float, float]:
    """Largest distance by which the profile crosses the flat face and the cam angle where
    it does [m, rad], over every ``every``-th
    grid angle: the face is the line y = r0 + s (translating) or the line through the pivot
    and the contact point (oscillating); every profile point, turned into the frame, must lie
    on the cam's side of it."""
    g = c.grid
    idx = np.arange(0, len(g.delta), every)
    prof = g.actual[None, :] * np.exp(1j * g.rotation * g.delta[idx])[:, None]   # in the frame
    if "pivot" in g.extras:
        A = g.extras["pivot"]
        u = g.contact[idx] - A
        nu = 1j * u / np.abs(u)
        nu = np.where(np.real(np.conj(nu) * (0 - A)) > 0, -nu, nu)        # away from the cam
        excess = np.real(np.conj(nu)[:, None] * (prof - A))
    else:
        face = c.base_radius + g.motion.s[idx]
        excess = prof.imag - face[:, None]
    worst = np.abs(np.max(excess, axis=1))
    k = int(np.argmax(worst))
    return float(worst[k]), float(g.delta[idx[k]])


# --------------------------------------------------------------------------- results


@dataclass(frozen=True)
class BestOffset:
    """The smallest base circle with the best offset (translating knife or roller follower)."""

    base_radius: float = q("m", "r0 with the best offset")
    offset: float = q("m", "the best offset e, signed x of the follower's axis")


@dataclass(frozen=True)
class CamTable:
    """The cam at the brief's table step (cam frame: cam centre at the origin; at δ = 0 the
    frame and the cam coincide). s and its derivatives are in m for a translating follower,
    in rad for an oscillating one (the arm angle φ); derivatives per radian of cam angle."""

    delta: np.ndarray = q("rad", "cam angle δ")
    s: np.ndarray = q("m or rad", "follower displacement from its lowest position")
    ds: np.ndarray = q("m/rad or rad/rad", "ds/dδ")
    d2s: np.ndarray = q("m/rad² or rad/rad²", "d²s/dδ²")
    d3s: np.ndarray = q("m/rad³ or rad/rad³", "d³s/dδ³")
    pitch: np.ndarray = q("m", "pitch curve (theoretical profile), [x, y]")
    actual: np.ndarray = q("m", "actual profile point the follower touches, [x, y]")
    pressure_angle: np.ndarray = q("rad", "pressure angle α")
    rho_pitch: np.ndarray = q("m", "radius of curvature of the pitch curve ρ (+ convex)")
    rho_actual: np.ndarray = q("m", "radius of curvature of the actual profile ρ_a (+ convex)")


@dataclass(frozen=True)
class CamDocument:
    """The cam stage (凸轮机构设计): a disc cam designed for its follower programme."""

    base_radius: float = q("m",
        "base radius r0 used (of the pitch curve; of the profile for a flat face)")
    base_radius_designed: bool = q("", "true when r0 was chosen by the program ('auto')")
    min_base_radius: float | None = q("m",
        "smallest r0 for [α] (convexity for a flat face) with this follower")
    best_offset: BestOffset | None = q("",
        "r0 and e with the best offset (translating knife/roller)")
    offset: float = q("m", "signed x of the translating follower's axis (0 otherwise)")
    roller_radius: float = q("m", "roller radius r_r (0 without a roller)")
    rotation: int = q("1", "+1 counter-clockwise, −1 clockwise")
    initial: float = q("m or rad", "s0 = √(r0² − e²) [m] (translating) or φ0 [rad] (oscillating)")
    segments: tuple[SegmentCheck, ...] = q("", "the programme's segments with their checks")
    boundaries: tuple[core.Boundary, ...] = q("", "the joints between segments")
    rho_pitch_min_convex: float = q("m", "smallest convex ρ of the pitch curve (null if none)")
    rho_actual_min_convex: float = q("m",
        "smallest convex ρ_a of the actual profile (null if none)")
    face_extent: tuple[float, float] | None = q(
        "m", "flat face: (min, max) contact position along the face")
    warnings: tuple[str, ...] = q("", "codes of the design findings")
    outline: np.ndarray | None = q("m", "the actual profile as cut, closed polyline, [x, y]")
    corners: tuple[core.Corner, ...] = q("", "roller: corners of the pitch curve (velocity jumps)")
    stand_off: float | None = q("m", "roller: largest stand-off of the roller centre at an edge")
    table: CamTable = q("", "the cam at the brief's table step")
    curvature_checks: tuple[CurvatureCheck, ...] = q(
        "", "the profile's curvature checks (roller: no undercut, not pointed; flat: convex)")


def cam_document(c: CamResult) -> CamDocument:
    """The cam stage in ``results.json`` (SI: m, rad; derivatives per radian of cam angle)."""
    t = c.table
    return CamDocument(
        base_radius=c.base_radius, base_radius_designed=c.base_radius_designed,
        min_base_radius=c.min_base_radius,
        best_offset=None if c.best_offset is None else BestOffset(*c.best_offset),
        offset=c.offset, roller_radius=c.grid.roller_radius, rotation=c.grid.rotation,
        initial=c.grid.initial_angle,
        segments=tuple(c.segments), boundaries=tuple(c.boundaries),
        rho_pitch_min_convex=c.rho_pitch_min_convex,
        rho_actual_min_convex=c.rho_actual_min_convex,
        face_extent=c.face_extent,
        warnings=tuple(w.code for w in c.warnings),
        outline=c.outline,
        corners=() if c.envelope is None else tuple(c.envelope.corners),
        stand_off=None if c.envelope is None else c.envelope.stand_off,
        table=CamTable(t.delta, t.motion.s, t.motion.ds, t.motion.d2s, t.motion.d3s, t.pitch,
                       t.actual, t.pressure_angle, t.rho_pitch, t.rho_actual),
        curvature_checks=tuple(c.curvature_checks))


@dataclass(frozen=True)
class CheckDoc:
    """One self-check: a number computed by a route independent of the design formulas,
    with its limit and verdict."""

    key: str = q("", "what is checked (e.g. 'velocity_fd', 'envelope', 'disc_s')")
    value: float = q("m, rad or 1",
        "the check's value: a length, an angle or a relative error/margin")
    limit: float | None = q("m, rad or 1", "its limit (null: reported only)")
    sense: str = q("", "'le': passes when value ≤ limit; 'ge': value ≥ limit; 'info': no verdict")
    reference: float | None = q("m, rad, W or 1",
        "the value it is compared with, where there is one")
    passed: bool | None = q("", "the verdict (null for 'info')")
    requirement: bool = q("",
        "a design requirement (e.g. a strength margin), not a check of the computation")
    detail: dict = q("",
        "what the row is about (follower label, grid step [rad], cam angle [rad] …; a drive "
        "strength margin: the stage or shaft index and its governing check as check, a msgid, "
        "with check_args)")


@dataclass(frozen=True)
class VerificationDocument:
    """Self-checks (计算校核) of a stage: value, limit and verdict of each."""

    checks: tuple[CheckDoc, ...] = q("", "every self-check")
    failed: tuple[Finding, ...] = q("", "the failed checks of the computation, as findings")


def verification_document(v) -> VerificationDocument:
    """Self-checks in ``results.json``: value, limit and verdict of each (SI)."""
    return VerificationDocument(
        checks=tuple(CheckDoc(c.key, c.value, c.limit, c.sense, c.reference, c.passed,
                              c.requirement, c.detail) for c in v.checks),
        failed=tuple(v.warnings))


