"""Lock-beam bender (seed 002), composed from shared stages.

One main (distribution) shaft turns once per part. Stages:

- transmission: motor → belt → spur gears → main shaft; exact ratio, shaft
  speeds (powers and torques only when the brief gives the motor power: the seed does not);
- positioning cam: the shared cam stage on ``params.cam`` (result ``cam``);
- bending cam: the shared cam design on ``params.bending_cam``, for the swing the drawn
  (rounded) four-bar needs to bend exactly the required angle (:func:`bending_cam_params`);
- bending linkage: two-position synthesis of the double rocker
  (:mod:`mechdesign.core.rocker_synthesis`), simulated with :mod:`mechdesign.core.mechanism`
  over the input swing and over the main-shaft cycle (cam → rocker → four-bar as drawn →
  chain → bending wheel), the original report's graphical lengths checked the same way;
- feed linkage: the shared linkage stages (prefix ``feed``) on the brief's
  Assur-group description, plus the seed-format table and the guide-bar closed forms;
- cycle (motion cycle diagram): the brief's diagram, its timing constraints,
  and its agreement with what the cams and the feed linkage actually do, found
  by simulation along the main shaft.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from fractions import Fraction
from functools import lru_cache

import numpy as np

from .brief import BEND, FEED, PIN, BendingParams, LockbeamParams
from ...core import cycle as cy
from ...core import rocker_synthesis as rs
from ...core.fourbar import FourBar, SynthesisError, grashof
from ...core.gears import SpurPair, spur_pair
from ...core.mechanism import RPR, RRP, RRR, Crank, LinkPoint, Mechanism
from ...pipeline import Stage
from ...stages.cam import cam_document, cam_stage, design as design_cam
from ...i18n import N_, tr
from ...stages.findings import Cat, Msg, Pair, finding, zh_en
from ...core.cycle import CycleDocument
from ...core.fields import q
from ...stages.linkage import LinkageDocument, closure_residual, linkage_document, linkage_stages
from ...stages.cam import CamDocument
from ...stages import titles

TWO_PI = 2.0 * np.pi
DEG = 180.0 / np.pi


# --------------------------------------------------------------------------- transmission


@dataclass(frozen=True)
class TrainStage:
    kind: str                   # "belt" | "gear"
    driver: float               # pulley diameter [m] or teeth
    driven: float
    ratio: float                # nominal n_in / n_out
    ratio_exact: Fraction
    pair: SpurPair | None
    speed_in: float             # [rpm]
    speed_out: float            # [rpm]


@dataclass(frozen=True)
class Shaft:
    """A shaft of the transmission (powers and torques only with the motor power given)."""

    index: int = q("1", "0 the motor shaft, then one per stage")
    speed_rpm: float = q("rpm", "its speed")
    power: float | None = q("W", "power on it, when the brief gives the motor power")
    torque: float | None = q("N·m", "torque on it, the same")


@dataclass(frozen=True)
class Transmission:
    """Stage 'transmission design'."""

    stages: tuple[TrainStage, ...]
    ratio: float
    ratio_exact: Fraction       # product of the stage ratios, exact
    required_ratio: float       # motor speed / main-shaft speed
    motor_rpm: float
    output_rpm: float           # nominal (no slip)
    output_rpm_slip: float      # with the belt's elastic slip
    required_rpm: float
    shafts: tuple[Shaft, ...]
    warnings: list


def transmission(p: LockbeamParams) -> Transmission:
    t = p.transmission
    stages, warnings = [], []
    n = p.motor_rpm
    belt = t.belt_ratio_exact
    stages.append(TrainStage("belt", t.belt_d1, t.belt_d2, t.belt_d2 / t.belt_d1, belt, None,
                             n, n / float(belt)))
    n = n / float(belt)
    for z1, z2 in t.gears:
        r = Fraction(z2, z1)
        pair = spur_pair(t.module, z1, z2, t.alpha)
        stages.append(TrainStage("gear", z1, z2, z2 / z1, r, pair, n, n / float(r)))
        n = n / float(r)
        if z1 < pair.z_min - 1e-12:
            warnings.append(finding(
                "undercut", N_("the gear with z1 = {z1} teeth is below the least tooth number "
                               "without undercut ({z_min:g}): a standard gear is undercut; add "
                               "teeth or use a positive shift"), z1=z1, z_min=pair.z_min))
    exact = Fraction(1)
    for s in stages:
        exact *= s.ratio_exact
    out = p.motor_rpm / float(exact)
    slip = p.motor_rpm * (1.0 - t.slip) / float(exact)
    if abs(out - p.rate) > 1e-9 * p.rate:
        warnings.append(finding(
            "ratio", N_("the train's ratio {i:.4g} turns the main shaft at {n:.2f} rpm, but the "
                        "production rate needs {rate:g} rpm (a ratio of {need:.4g})"),
            i=float(exact), n=out, rate=p.rate, need=p.motor_rpm / p.rate))
    shafts = []
    power = t.power
    speed = p.motor_rpm
    shafts.append(Shaft(0, speed, power, None if power is None else power / (speed * np.pi / 30)))
    for i, s in enumerate(stages, 1):
        speed = s.speed_out
        if power is not None:
            power = power * (t.belt_efficiency if s.kind == "belt" else t.gear_efficiency)
        shafts.append(Shaft(i, speed, power, None if power is None else power / (speed * np.pi / 30)))
    return Transmission(tuple(stages), float(exact), exact, p.motor_rpm / p.rate, p.motor_rpm,
                        out, slip, p.rate, tuple(shafts), warnings)


# --------------------------------------------------------------------------- bending linkage


@dataclass(frozen=True)
class BendingSynthesis:
    """The chosen design and the candidates considered (one per output sense)."""

    design: rs.RockerDesign
    gamma_min: float
    sense: str                          # same | opposite
    candidates: tuple                   # (sense, design or None, γ_min, message)


def _dbeta(bp: BendingParams, sense: str) -> float:
    return bp.output_swing if sense == "same" else -bp.output_swing


@lru_cache(maxsize=32)
def synthesise_bending(bp: BendingParams) -> BendingSynthesis:
    """Two-position synthesis of the bending four-bar (the input rocker turns CCW by the cam's
    swing Δα; the output by Δβ = bending angle / chain ratio, the same way or the opposite
    way). Raises SynthesisError when no sense gives a valid design."""
    senses = ("opposite", "same") if bp.sense == "auto" else (bp.sense,)
    cands = []
    zh_of = {}
    for sense in senses:
        try:
            if bp.start is None:
                limit = None if bp.ratio_factor is None else \
                    bp.ratio_factor * bp.output_swing / bp.input_swing
                ds, g = rs.best_start(bp.frame, bp.output_arm, bp.input_swing, _dbeta(bp, sense),
                                      bp.length_bounds, limit)
            else:
                ds = rs.design_two_position(bp.frame, bp.output_arm, bp.start[0], bp.input_swing,
                                            bp.start[1], _dbeta(bp, sense))
                g = rs.sweep(ds).gamma_min
            cands.append((sense, ds, float(g), ""))
        except SynthesisError as exc:
            cands.append((sense, None, 0.0, str(exc)))
            zh_of[sense] = exc.text("zh")
    valid = [c for c in cands if c[1] is not None]
    if not valid:
        way = {"same": zh_en.pgettext("turning", "same")[0],
               "opposite": zh_en.pgettext("turning", "opposite")[0]}
        parts = [Msg(N_("output turning the {way} way: {reason}"),
                     way=Pair(way.get(c[0], c[0]), c[0]), reason=Pair(zh_of.get(c[0], c[3]), c[3]))
                 for c in cands]
        texts = []
        for lang in ("en", "zh"):
            _ = tr(lang)
            texts.append(_.pgettext("list", "; ").join(m.text(_) for m in parts))
        raise SynthesisError(*texts)
    best = max(valid, key=lambda c: c[2])
    return BendingSynthesis(best[1], best[2], best[0], tuple(cands))


def bending_mechanism(ds: rs.RockerDesign) -> Mechanism:
    """The four-bar as Assur groups: the input rocker 2 (driven like a crank, ω = 1 so that
    the links' ω and α are dβ/dα and d²β/dα²), then the RRR dyad coupler 3 – output 4."""
    m = Mechanism("1", {"G0": 0j, "B0": complex(ds.frame, 0.0)})
    m.add(Crank("input rocker G0G", "2", "G0", "G", ds.input_rocker, 1.0))
    m.add(RRR("coupler GB – wheel arm B0B", "3", "4", "G", "B0", "B", ds.coupler,
              ds.output_rocker, ds.branch))
    return m


#: The drawn (rounded) lengths must keep Grashof's inequality (or its reverse, when the
#: synthesis is non-Grashof) by at least this many rounding steps: never a change-point.
GRASHOF_MARGIN_STEPS = 0.5


def grashof_margin(a: float, b: float, c: float, d: float) -> float:
    """(p + q) − (s + l) of the four lengths [m]: > 0 Grashof, 0 change-point, < 0 not."""
    s_, p_, q_, l_ = sorted((a, b, c, d))
    return (p_ + q_) - (s_ + l_)


@dataclass(frozen=True)
class RoundedCheck:
    """The design with its lengths rounded as drawn, assembled at the same input start."""

    input_rocker: float         # [m]
    coupler: float              # [m]
    beta1: float                # [rad]
    swing: float                # |Δβ| produced by the cam's swing [rad]
    bend: float                 # bending angle that gives [rad]
    gamma_min: float            # [rad]
    input_swing_needed: float | None   # cam swing for exactly the required Δβ [rad]
    margin: float = 0.0         # (p + q) − (s + l) of the drawn lengths [m]
    margin_required: float = 0.0   # |margin| at least this, with the synthesis's sign [m]
    nearest: tuple | None = None   # (a, b, margin) of plain rounding when that was not kept [m]


def _rounded_candidate(ds: rs.RockerDesign, a: float, b: float, ratio: float
                       ) -> RoundedCheck | None:
    """Lengths a, b with α1 and the branch of ``ds``, simulated over the input swing (None if
    that linkage cannot move through it)."""
    from ...core.extremes import brentq

    beta1 = float(rs.output_angle(ds.frame, a, b, ds.output_rocker, ds.alpha1, ds.branch))
    if not np.isfinite(beta1):
        return None
    rd = rs.RockerDesign(ds.frame, a, b, ds.output_rocker, ds.alpha1, ds.dalpha, beta1, ds.dbeta,
                         ds.branch)
    sw = rs.sweep(rd)
    if not (sw.assembled and sw.monotonic):
        return None
    target = abs(ds.dbeta)

    def miss(x):
        z = rs.output_angle(ds.frame, a, b, ds.output_rocker, ds.alpha1 + x, ds.branch)
        return abs(float(np.angle(np.exp(1j * (z - beta1))))) - target

    needed = None
    lo, hi = 0.5 * ds.dalpha, min(1.5 * ds.dalpha, np.pi / 2)
    try:
        if np.isfinite(miss(lo)) and np.isfinite(miss(hi)) and miss(lo) * miss(hi) < 0:
            needed = float(brentq(miss, lo, hi, xtol=1e-15))
    except ValueError:
        needed = None
    return RoundedCheck(a, b, beta1, abs(sw.swing), ratio * abs(sw.swing), sw.gamma_min, needed,
                        grashof_margin(a, b, ds.output_rocker, ds.frame))


def rounded_check(ds: rs.RockerDesign, step: float, ratio: float) -> RoundedCheck | None:
    """The drawn lengths: a and b each rounded down or up to ``step`` [m] (four candidates),
    α1 and the branch kept. Of the candidates that move through the swing and keep the
    synthesis's side of Grashof's rule by at least GRASHOF_MARGIN_STEPS × step (never a
    change-point linkage), the one whose swing misses the required Δβ least. None when the
    brief does not round or no candidate qualifies."""
    if step <= 0:
        return None
    need = GRASHOF_MARGIN_STEPS * step
    side = 1.0 if grashof_margin(ds.input_rocker, ds.coupler, ds.output_rocker, ds.frame) >= 0 \
        else -1.0
    a_opts = sorted({np.floor(ds.input_rocker / step) * step, np.ceil(ds.input_rocker / step) * step})
    b_opts = sorted({np.floor(ds.coupler / step) * step, np.ceil(ds.coupler / step) * step})
    target = abs(ds.dbeta)
    best = None
    for a in a_opts:
        for b in b_opts:
            if a <= 0 or b <= 0:
                continue
            if side * grashof_margin(a, b, ds.output_rocker, ds.frame) < need - 1e-12 * ds.frame:
                continue
            rc = _rounded_candidate(ds, float(a), float(b), ratio)
            if rc is not None and (best is None or
                                   abs(rc.swing - target) < abs(best.swing - target)):
                best = rc
    if best is None:
        return None
    a0, b0 = round(ds.input_rocker / step) * step, round(ds.coupler / step) * step
    nearest = None
    if abs(a0 - best.input_rocker) > 1e-12 or abs(b0 - best.coupler) > 1e-12:
        nearest = (a0, b0, grashof_margin(a0, b0, ds.output_rocker, ds.frame))
    return replace(best, margin_required=side * need, nearest=nearest)


def built_design(ds: rs.RockerDesign, rc: RoundedCheck | None) -> rs.RockerDesign:
    """The four-bar as built: the drawn lengths of ``rc`` assembled at the same input start,
    swung by the input swing they need for exactly the required Δβ; ``ds`` itself when the
    brief does not round or no such swing exists."""
    if rc is None or rc.input_swing_needed is None:
        return ds
    return rs.RockerDesign(ds.frame, rc.input_rocker, rc.coupler, ds.output_rocker, ds.alpha1,
                           float(np.copysign(rc.input_swing_needed, ds.dalpha)), rc.beta1,
                           ds.dbeta, ds.branch)


def bending_cam_params(p: LockbeamParams, syn: BendingSynthesis | None = None):
    """The bending cam's parameters with its swing set to what the four-bar as built needs
    (:func:`built_design`): the synthesis uses the brief's swing, the drawn lengths are rounded,
    and a cam made for the brief's swing would bend the rounded linkage short of the required
    angle. Explicit lifts of the programme are scaled with the stroke."""
    from ...core.cam import Programme, Segment

    bp, cam = p.bending, p.bending_cam
    syn = synthesise_bending(bp) if syn is None else syn
    swing = abs(built_design(syn.design, rounded_check(syn.design, bp.rounding, bp.ratio)).dalpha)
    prog = cam.programme
    if swing == prog.stroke:
        return cam
    k = swing / prog.stroke
    segs = [Segment(s.kind, s.span, s.law, None if s.lift is None else s.lift * k)
            for s in prog.segments]
    return replace(cam, programme=Programme(segs, swing))


@dataclass(frozen=True)
class SeedCheck:
    input_rocker: float
    coupler: float
    grashof: str
    check: rs.LengthCheck
    # per start of ``check.starts``: (least, largest) |dβ/dα| over the swing [–]
    start_ratio_ranges: tuple = ()


@dataclass(frozen=True)
class BendingDrawing:
    """The bending four-bar as the report draws it (positions solved by the stage)."""

    A: np.ndarray               # joint G at 5 equal steps of the input swing, start to end [m]
    B: np.ndarray               # joint B at the same input angles [m]
    path_A: np.ndarray          # G over the swing, 60 points [m]
    path_B: np.ndarray          # B over the swing, 60 points [m]


def bending_drawing(ds: rs.RockerDesign, mech: Mechanism) -> BendingDrawing:
    m = mech.solve(ds.alpha1 + ds.dalpha * np.linspace(0.0, 1.0, 5))
    arc = mech.solve(ds.alpha1 + ds.dalpha * np.linspace(0, 1, 60))
    return BendingDrawing(m.points["G"].pos, m.points["B"].pos, arc.points["G"].pos,
                          arc.points["B"].pos)


def seed_check(ds: rs.RockerDesign, bp: BendingParams) -> SeedCheck:
    """The original report's graphical lengths checked over the swing, with the velocity ratio range of
    every start the check tried."""
    sa, sb = bp.seed
    check = rs.check_lengths(ds.frame, sa, sb, ds.output_rocker, ds.dalpha, bp.output_swing)
    ranges = []
    for a1, b1, _ in check.starts:
        sw = rs.sweep(rs.RockerDesign(ds.frame, sa, sb, ds.output_rocker, a1, ds.dalpha, b1, 0.0, 1))
        r_ = np.abs(sw.ratio)
        ranges.append((float(r_.min()), float(r_.max())))
    return SeedCheck(sa, sb, grashof(FourBar(sa, sb, ds.output_rocker, ds.frame))[1], check,
                     tuple(ranges))


@dataclass(frozen=True)
class BendingResult:
    """Stage 'bending linkage design': synthesis and its simulation."""

    synthesis: BendingSynthesis
    design: rs.RockerDesign
    mechanism: Mechanism
    ratio: float                # chain ratio i = D_driving / D_bending
    output_swing: float         # required |Δβ| [rad]
    input_swing: float          # Δα [rad]
    grashof: str
    # simulation over the input swing (core.mechanism)
    sweep_input: np.ndarray     # [rad]
    sweep_output: np.ndarray    # [rad], continuous
    sweep_gamma: np.ndarray     # [rad]
    swing_simulated: float      # signed [rad]
    gamma_min: float
    gamma_max: float
    gamma_min_at: float         # input rotation from the start where γ is least [rad]
    velocity_ratio: np.ndarray  # dβ/dα over the sweep (core.mechanism, input ω = 1) [–]
    rounded: RoundedCheck | None
    closure: float              # [m]
    # over the main-shaft cycle
    shaft_angle: np.ndarray     # φ [rad], grid over one revolution
    rocker_angle: np.ndarray    # input rocker angle from its start [rad]
    rocker_omega: np.ndarray    # [rad/s]
    wheel_angle: np.ndarray     # bending wheel, from its start, in the bending sense [rad]
    wheel_omega: np.ndarray     # [rad/s]
    wheel_alpha: np.ndarray     # [rad/s²]
    bend_simulated: float       # largest wheel angle [rad]
    gamma_min_built: float      # least transmission angle of the four-bar as built over the cycle [rad]
    fd_velocity: float          # max |ω − Δθ/Δt| / max |ω|
    fd_acceleration: float
    seed: SeedCheck | None
    warnings: list
    # per synthesis candidate: peak |dβ/dα| over its swing (rs.sweep), None without a design [–]
    candidate_ratio_peaks: tuple = ()
    drawing: BendingDrawing | None = None


def checks(p: LockbeamParams, keep: dict | None = None) -> list:
    """The feasibility checks of a run (after validation, once): does the feed linkage
    assemble over the turn, and can the bending four-bar be synthesised? Both are asked and
    every problem returned as a :class:`~mechdesign.brief.loader.BriefProblem` at its brief
    field. The results are stored in ``keep`` (``feed_motion``, ``bending_synthesis``)
    for the stages, so nothing is computed twice."""
    from ...brief.loader import BriefProblem
    from ...core.mechanism import AssemblyError
    from ...stages.linkage import motion

    problems = []
    try:
        feed = motion(p.feed)
    except AssemblyError as exc:
        problems.append(BriefProblem("feed_linkage.groups", "", exc.en, exc.zh))
    except ValueError as exc:
        problems.append(BriefProblem("feed_linkage.output.point", "", str(exc),
                                     getattr(exc, "zh", None)))
    else:
        if keep is not None:
            keep["feed_motion"] = feed
    bp = p.bending
    try:
        syn = synthesise_bending(bp)
    except SynthesisError as exc:
        start = "auto" if bp.start is None else \
            f"input {np.degrees(bp.start[0]):g}°, output {np.degrees(bp.start[1]):g}°"
        problems.append(BriefProblem("bending.start", start, exc.en, exc.zh))
    else:
        if keep is not None:
            keep["bending_synthesis"] = syn
    return problems


def bending(p: LockbeamParams, bcam, syn: BendingSynthesis | None = None) -> BendingResult:
    """The bending linkage (``syn``: its synthesis when the checks already made it)."""
    bp = p.bending
    syn = synthesise_bending(bp) if syn is None else syn
    ds = syn.design
    mech = bending_mechanism(ds)
    rounded = rounded_check(ds, bp.rounding, bp.ratio)
    built = built_design(ds, rounded)
    # 1. over the input swing
    alpha = ds.alpha1 + ds.dalpha * np.linspace(0.0, 1.0, 1441)
    m = mech.solve(alpha)
    out = m.links["4"].angle
    beta = ds.beta1 + np.unwrap(np.angle(np.exp(1j * (out - ds.beta1))))
    delta = np.abs(np.angle(np.exp(1j * (m.links["3"].angle - m.links["4"].angle))))
    gamma = np.minimum(delta, np.pi - delta)
    i_min = int(np.argmin(gamma))
    # 2. over the main-shaft cycle, the four-bar as built (drawn lengths): δ = φ − φ0 on the
    #    bending cam, α = α1 + ψ(δ)
    n = p.grid_points
    phi = np.arange(n) * (TWO_PI / n)
    prog = bcam.params.programme
    fm = prog.evaluate(phi - p.bend_cam_start)
    w = p.main_omega
    mc = (mech if built is ds else bending_mechanism(built)).solve(built.alpha1 + fm.s)
    g1, g2 = mc.links["4"].omega, mc.links["4"].alpha           # dβ/dα, d²β/dα²
    a_dot, a_ddot = fm.ds * w, fm.d2s * w * w
    beta_c = built.beta1 + np.angle(np.exp(1j * (mc.links["4"].angle - built.beta1)))
    delta_c = np.abs(np.angle(np.exp(1j * (mc.links["3"].angle - mc.links["4"].angle))))
    sign = np.sign(ds.dbeta)
    ratio = bp.ratio
    wheel = ratio * sign * (beta_c - built.beta1)
    wheel_w = ratio * sign * g1 * a_dot
    wheel_a = ratio * sign * (g2 * a_dot ** 2 + g1 * a_ddot)
    dt = (TWO_PI / n) / w

    # Central differences are O(h²) only where the cam law is smooth: leave out the grid
    # points next to a segment boundary (the 3-4-5 law's jerk jumps there).
    edges = np.mod(prog.starts + p.bend_cam_start, TWO_PI)
    gap = np.abs(np.angle(np.exp(1j * (phi[:, None] - edges[None, :]))))
    smooth = np.all(gap > 1.5 * (TWO_PI / n), axis=1)

    def rel(x, ref):
        scale = np.max(np.abs(ref))
        return 0.0 if scale == 0 else float(np.max(np.abs(x[smooth])) / scale)

    fd_v = rel(wheel_w - (np.roll(wheel, -1) - np.roll(wheel, 1)) / (2 * dt), wheel_w)
    fd_a = rel(wheel_a - (np.roll(wheel_w, -1) - np.roll(wheel_w, 1)) / (2 * dt), wheel_a)
    warnings = []
    g_min = float(gamma[i_min])
    if g_min < bp.gamma_allowed - 1e-12:
        warnings.append(finding(
            "transmission_angle",
            N_("the bending four-bar's minimum transmission angle {gamma:.2f}° is below the allowed "
               "{limit:.0f}°; change the start position or the lengths"),
            gamma=g_min * DEG, limit=bp.gamma_allowed * DEG))
    seed = None if bp.seed is None else seed_check(ds, bp)
    peaks = tuple(None if d_ is None else rs.sweep(d_).ratio_peak
                  for _, d_, _, _ in syn.candidates)
    return BendingResult(
        synthesis=syn, design=ds, mechanism=mech, ratio=ratio, output_swing=bp.output_swing,
        input_swing=bp.input_swing,
        grashof=grashof(FourBar(ds.input_rocker, ds.coupler, ds.output_rocker, ds.frame))[1],
        sweep_input=alpha, sweep_output=beta, sweep_gamma=gamma,
        swing_simulated=float(beta[-1] - beta[0]), gamma_min=g_min, gamma_max=float(np.max(gamma)),
        gamma_min_at=float(alpha[i_min] - ds.alpha1), velocity_ratio=m.links["4"].omega,
        rounded=rounded,
        closure=closure_residual(mech, m),
        shaft_angle=phi, rocker_angle=fm.s, rocker_omega=a_dot, wheel_angle=wheel,
        wheel_omega=wheel_w, wheel_alpha=wheel_a, bend_simulated=float(np.max(wheel)),
        gamma_min_built=float(np.min(np.minimum(delta_c, np.pi - delta_c))),
        fd_velocity=fd_v, fd_acceleration=fd_a, seed=seed, warnings=warnings,
        candidate_ratio_peaks=peaks, drawing=bending_drawing(ds, mech))


# --------------------------------------------------------------------------- feed linkage


@dataclass(frozen=True)
class GuideBarClosedForm:
    """Closed forms of a guide-bar (oscillating guide bar) drive with the crank pin on the bar's slider:
    swing θ = 2 arcsin(r/d) (the bar is perpendicular to the crank at both extremes, and the
    slider's extremes are the bar's), K = (180° + θ)/(180° − θ); with the slider guide
    perpendicular to O2O3 the two extremes are mirror images, so H = 2 L sin(θ/2) = 2Lr/d."""

    crank: float                # r [m]
    centres: float              # d = |O2O3| [m]
    bar_point: float | None     # L [m]: distance of the rod's pin on the bar from its pivot
    theta: float                # [rad]
    K: float
    stroke: float | None        # [m] (None when the layout is not symmetric)


def guide_bar_closed_form(model) -> GuideBarClosedForm | None:
    """The closed forms when the feed linkage is crank + RPR (+ a point on the bar driving an
    RRP slider); None for any other topology."""
    g = model.mechanism.groups
    crank = g[0]
    rpr = next((x for x in g if isinstance(x, RPR)), None)
    if rpr is None or rpr.a != crank.tip or abs(rpr.offset) > 0:
        return None
    frame = model.mechanism.frame_points
    if rpr.pivot not in frame:
        return None
    o2o3 = complex(frame[crank.pivot]) - complex(frame[rpr.pivot])
    d, r = abs(o2o3), crank.length
    if not r < d:
        return None
    theta = 2.0 * np.arcsin(r / d)
    K = (np.pi + theta) / (np.pi - theta)
    L = stroke = None
    rrp = next((x for x in g if isinstance(x, RRP) and x.c == model.output.name), None)
    pt = None if rrp is None else next(
        (x for x in g if isinstance(x, LinkPoint) and x.name == rrp.b and x.link == rpr.bar
         and x.origin == rpr.pivot and x.offset_angle == 0.0), None)
    if pt is not None:
        L = pt.distance
        u = np.exp(1j * rrp.guide_angle)
        perpendicular = abs((np.conj(u) * o2o3).real) < 1e-12 * d
        if perpendicular and model.output.kind == "point" and \
                abs(np.sin(model.output.direction - rrp.guide_angle)) < 1e-12:
            stroke = 2.0 * L * r / d
    return GuideBarClosedForm(r, d, L, float(theta), float(K), stroke)


@dataclass(frozen=True)
class FeedTable:
    """The original report's VB output: every 10° of crank angle from +x (counter-clockwise)."""

    crank_angle: np.ndarray     # [rad]
    x: np.ndarray               # slider x [m]
    v: np.ndarray               # [m/s]
    a: np.ndarray               # [m/s²]
    bar_omega: np.ndarray       # [rad/s]
    bar_alpha: np.ndarray
    rod_omega: np.ndarray
    rod_alpha: np.ndarray
    seed_x: np.ndarray | None   # the original report's RRP routine: x_P + |x − x_P| (its abs())
    closed: GuideBarClosedForm | None


def feed_table(model, step: float = np.radians(10.0)) -> FeedTable:
    angles = np.arange(0.0, TWO_PI - 1e-9, step)
    m = model.mechanism.solve(angles)
    out = model.output.name
    rrp = next((x for x in model.mechanism.groups if isinstance(x, RRP) and x.c == out), None)
    rpr = next((x for x in model.mechanism.groups if isinstance(x, RPR)), None)
    e = m.points[out]
    bar = m.links[rpr.bar] if rpr is not None else None
    rod = m.links[rrp.rod] if rrp is not None else None
    nan = np.full_like(angles, np.nan)
    seed_x = None
    if rrp is not None and abs(np.sin(rrp.guide_angle)) < 1e-12:
        xp = rrp.guide_point.real
        seed_x = xp + np.abs(e.pos.real - xp)
    return FeedTable(angles, e.pos.real, e.vel.real, e.acc.real,
                     bar.omega if bar else nan, bar.alpha if bar else nan,
                     rod.omega if rod else nan, rod.alpha if rod else nan, seed_x,
                     guide_bar_closed_form(model))


# --------------------------------------------------------------------------- cycle


@dataclass(frozen=True)
class CycleResult:
    """Stage 'motion cycle diagram': the brief's diagram, its checks, and the motions along the main shaft."""

    diagram: cy.CycleDiagram
    checks: list
    shaft_angle: np.ndarray     # φ [rad]
    feed_s: np.ndarray          # feed slider from its start of feed [m]
    pin_lift: np.ndarray        # [m]
    wheel_angle: np.ndarray     # [rad]
    cam_timing_error: dict      # key → largest deviation of the cam from the diagram's phases (fraction of stroke)
    cam_disagreement: dict      # key → shaft angle where diagram and cam states differ [rad]
    feed_span_cycle: float      # the diagram's feed rise [rad]
    feed_span_simulated: float  # the linkage's working stroke [rad]
    pin_lift_while_bending: float   # least pin lift while the bending wheel moves [m]
    pin_stroke: float
    feed_at_pin_down: float     # feed travel when the pin is fully down [m]
    feed_at_pin_rise: float     # feed travel (from its start) when the pin starts to rise [m]
    pin_down_angle: float       # φ where the pin is fully down [rad]
    pin_rise_angle: float
    warnings: list


def _phase_error(act: cy.Actuator, phi: np.ndarray, s: np.ndarray, ds: np.ndarray,
                 stroke: float) -> float:
    """Largest violation, as a fraction of the stroke, of what the diagram says the
    follower does at the shaft angles ``phi`` (a uniform grid): at 0 in a near dwell, at the
    stroke in a far dwell, not falling in a rise and not rising in a return (a wrong-way
    step counts with its size over one grid step)."""
    step = phi[1] - phi[0]
    states = cy.state_at(act, phi)
    err = np.zeros_like(phi)
    err = np.where(states == cy.DWELL_LOW, np.abs(s), err)
    err = np.where(states == cy.DWELL_HIGH, np.abs(s - stroke), err)
    err = np.where(states == cy.RISE, np.maximum(-ds, 0.0) * step, err)
    err = np.where(states == cy.RETURN, np.maximum(ds, 0.0) * step, err)
    return float(np.max(err) / stroke)


def _requirement(c: cy.Constraint):
    """A timing requirement as a finding's field: the brief's text (both languages, the
    user's), else "a before b" with the catalogue's word for the kind."""
    kind = {"before": Msg.pgettext("timing requirement", "before"),
            "during": Msg.pgettext("timing requirement", "during")}[c.kind]
    said = Cat(str(c.a), " ", kind, " ", str(c.b))
    if not (c.text("zh") or c.text("en")):
        return said
    return Pair(c.text("zh") or said.text("zh"), c.text("en") or said.text("en"))


def cycle(p: LockbeamParams, r: dict) -> CycleResult:
    diagram = p.cycle
    checks = cy.check_constraints(diagram)
    phi = r["bending"].shaft_angle
    pin = r["cam"].params.programme
    bprog = r["bending_cam"].params.programme
    pm = pin.evaluate(phi - p.pin_cam_start)
    bm = bprog.evaluate(phi - p.bend_cam_start)
    acts = {a.key: a for a in diagram.actuators}
    errors = {PIN: _phase_error(acts[PIN], phi, pm.s, pm.ds, pin.stroke),
              BEND: _phase_error(acts[BEND], phi, bm.s, bm.ds, bprog.stroke)}
    disagree = {PIN: cy.timing_disagreement(acts[PIN], cy.actuator_from_cam_programme(
                    PIN, "", "", pin, p.pin_cam_start)),
                BEND: cy.timing_disagreement(acts[BEND], cy.actuator_from_cam_programme(
                    BEND, "", "", bprog, p.bend_cam_start))}
    # The feed crank turns with the main shaft; φ = feed start is its position 1.
    k, model = r["feed"], p.feed
    feed = acts[FEED]
    rise = cy.intervals_of(feed, cy.RISE)[0]
    feed_phase = np.mod(phi - rise.start, TWO_PI)
    fmotion = model.mechanism.solve(k.start_angle + k.sense * feed_phase)
    u = np.exp(1j * model.output.direction)
    raw = (np.conj(u) * fmotion.points[model.output.name].pos).real
    raw0 = (np.conj(u) * model.mechanism.solve(np.array([k.start_angle])).points[
        model.output.name].pos).real[0]
    feed_s = model.output.working * (raw - raw0)
    wheel = r["bending"].wheel_angle
    moving = np.abs(r["bending"].wheel_omega) > 1e-9 * np.max(np.abs(r["bending"].wheel_omega))
    lift_bending = float(np.min(pm.s[moving])) if np.any(moving) else float("nan")
    pin_act = acts[PIN]
    ret = cy.intervals_of(pin_act, cy.RETURN)[-1]     # the pin is fully down after its last return
    up = cy.intervals_of(pin_act, cy.RISE)[0]
    down_at, rise_at = float(np.mod(ret.end, TWO_PI)), float(up.start)

    def feed_at(angle):
        ph = np.mod(angle - rise.start, TWO_PI)
        z = model.mechanism.solve(np.array([k.start_angle + k.sense * ph])).points[model.output.name].pos
        return float(model.output.working * ((np.conj(u) * z).real[0] - raw0))

    warnings = []
    for chk in checks:
        if not chk.ok:
            warnings.append(finding(
                "cycle", N_("the motion cycle diagram misses a timing requirement: {req} (short by "
                            "{short:.2f}°)"),
                req=_requirement(chk.constraint),
                short=-chk.slack * DEG))
    span_sim = k.working_span
    if abs(rise.span - span_sim) > np.radians(0.5):
        warnings.append(finding(
            "feed_timing",
            N_("the cycle diagram's feed stroke {cyc:.2f}° differs from the feed linkage's working "
               "stroke {sim:.2f}° (K = {K:.4f}); correct the diagram"),
            cyc=rise.span * DEG, sim=span_sim * DEG, K=k.time_ratio))
    if np.isfinite(lift_bending) and lift_bending < pin.stroke * (1 - 1e-9):
        warnings.append(finding(
            "pin_not_up",
            N_("while the bending wheel turns the pin is only {lift:.3f} mm up (it should be fully "
               "up, {stroke:.3f} mm)"), lift=lift_bending * 1e3, stroke=pin.stroke * 1e3))
    return CycleResult(
        diagram=diagram, checks=checks, shaft_angle=phi, feed_s=feed_s, pin_lift=pm.s,
        wheel_angle=wheel, cam_timing_error=errors, cam_disagreement=disagree,
        feed_span_cycle=float(rise.span), feed_span_simulated=float(span_sim),
        pin_lift_while_bending=lift_bending, pin_stroke=float(pin.stroke),
        feed_at_pin_down=feed_at(down_at), feed_at_pin_rise=feed_at(rise_at),
        pin_down_angle=down_at, pin_rise_angle=rise_at, warnings=warnings)


@dataclass(frozen=True)
class PinCheck:
    """The positioning pin must rise more than the groove depth (d1 − d2)/2."""

    lift: float
    required: float
    warnings: list


def pin_check(p: LockbeamParams) -> PinCheck:
    need = (p.part_diameter - p.groove_diameter) / 2.0
    h = p.cam.programme.stroke
    warnings = []
    if not h > need:
        warnings.append(finding(
            "pin_lift", N_("the pin's lift {h:.2f} mm does not exceed the groove depth (d1 − d2)/2 "
                           "= {need:.2f} mm: it cannot enter the groove"), h=h * 1e3, need=need * 1e3))
    return PinCheck(float(h), float(need), warnings)


# --------------------------------------------------------------------------- stages


def _reuse(stage: Stage, key: str) -> Stage:
    """``stage``, returning the run's checks' result ``key`` instead when they made it."""
    def run(r: dict):
        done = r.get("checked", {}).get(key)
        return stage.run(r) if done is None else done
    return Stage(stage.key, stage.title, run)


def stages(params: LockbeamParams) -> list[Stage]:
    feed_kinematics, *feed_rest = linkage_stages(model_key="feed_model", prefix="feed")
    return [
        Stage("transmission", titles.pgettext("stage", "transmission"), lambda r: transmission(r["params"])),
        cam_stage(),
        Stage("pin_check", titles.pgettext("stage", "pin lift"), lambda r: pin_check(r["params"])),
        Stage("bending_cam", titles.pgettext("stage", "bending cam"),
              lambda r: design_cam(bending_cam_params(
                  r["params"], r.get("checked", {}).get("bending_synthesis")))),
        Stage("bending", titles.pgettext("stage", "bending linkage"),
              lambda r: bending(r["params"], r["bending_cam"],
                                r.get("checked", {}).get("bending_synthesis"))),
        Stage("feed_model", titles.pgettext("stage", "feed linkage"), lambda r: r["params"].feed),
        _reuse(feed_kinematics, "feed_motion"), *feed_rest,
        Stage("feed_table", titles.pgettext("stage", "feed table"), lambda r: feed_table(r["params"].feed)),
        Stage("cycle", titles.pgettext("stage", "motion cycle"), lambda r: cycle(r["params"], r)),
    ]


@dataclass(frozen=True)
class TrainStageDoc:
    """One stage of the transmission."""

    kind: str = q("", "'belt' or 'gear'")
    driver: float = q("m or 1", "driving pulley diameter (belt) or pinion teeth z1 (gear)")
    driven: float = q("m or 1", "driven pulley diameter or wheel teeth z2")
    ratio: float = q("1", "nominal n_in / n_out")
    speed_in_rpm: float = q("rpm", "input speed")
    speed_out_rpm: float = q("rpm", "output speed (no slip)")
    centre_distance: float | None = q("m", "a of a gear pair (null for a belt)")
    contact_ratio: float | None = q("1", "ε_α of a gear pair (null for a belt)")


@dataclass(frozen=True)
class TransmissionDoc:
    """The transmission: motor → belt → spur gears → main shaft."""

    stages: tuple[TrainStageDoc, ...] = q("", "the stages from the motor")
    ratio: float = q("1", "total ratio (product of the stage ratios)")
    ratio_exact: str = q("", "the same as an exact fraction")
    output_rpm: float = q("rpm", "main-shaft speed (no slip)")
    output_rpm_with_slip: float = q("rpm", "main-shaft speed with the belt's elastic slip")
    shafts: tuple[Shaft, ...] = q("", "the shafts from the motor's")


@dataclass(frozen=True)
class PinDoc:
    """The positioning pin's lift against the groove depth."""

    lift: float = q("m", "the pin's lift (the positioning cam's stroke)")
    required: float = q("m", "groove depth (d1 − d2)/2 it must exceed")


@dataclass(frozen=True)
class RangeDoc:
    min: float = q("1", "least value")
    max: float = q("1", "largest value")


@dataclass(frozen=True)
class RoundedDoc:
    """The design with its lengths rounded as drawn, assembled at the same input start."""

    input_rocker: float = q("m", "L_G0G rounded")
    coupler: float = q("m", "L_GB rounded")
    output_start: float = q("rad", "β1 of the rounded linkage")
    swing: float = q("rad", "|Δβ| the cam's swing then gives")
    bend: float = q("rad", "the bending angle that gives")
    gamma_min: float = q("rad", "γ_min over the swing")
    input_swing_needed: float | None = q("rad", "cam swing for exactly the required Δβ")
    grashof_margin: float = q("m", "(p + q) − (s + l) of the drawn lengths: > 0 Grashof, 0 "
                              "change-point, < 0 non-Grashof")


@dataclass(frozen=True)
class CandidateDoc:
    """A synthesis candidate, one per output sense."""

    sense: str = q("", "'same' or 'opposite': the output turns the input's way or not")
    gamma_min: float = q("rad", "its γ_min (0 without a design)")
    message: str = q("", "why there is no design, or empty")
    input_rocker: float | None = q("m", "L_G0G")
    coupler: float | None = q("m", "L_GB")


@dataclass(frozen=True)
class SeedStartDoc:
    input_start: float = q("rad", "α1 of a start giving the required swing")
    output_start: float = q("rad", "β1 there")
    gamma_min: float = q("rad", "γ_min over the swing from that start")


@dataclass(frozen=True)
class SeedDoc:
    """The original report's graphical lengths checked over the swing."""

    input_rocker: float = q("m", "the original report's L_G0G")
    coupler: float = q("m", "the original report's L_GB")
    grashof: str = q("", "Grashof type of the original report's four-bar")
    swing_range: tuple[float, float] = q("rad", "least and largest |Δβ| over every start that "
                                                "moves through the whole input swing")
    starts: tuple[SeedStartDoc, ...] = q("", "starts giving exactly the required swing")


@dataclass(frozen=True)
class BendingCycleDoc:
    """The bending wheel over the main-shaft cycle (uniform grid)."""

    shaft_angle: np.ndarray = q("rad", "main-shaft angle φ")
    wheel_angle: np.ndarray = q("rad", "bending wheel from its start, in the bending sense")
    wheel_omega: np.ndarray = q("rad/s", "its angular velocity")
    wheel_alpha: np.ndarray = q("rad/s²", "its angular acceleration")
    gamma_min: float = q("rad", "least transmission angle of the four-bar as built (drawn "
                         "lengths, when the brief rounds) over the cycle")


@dataclass(frozen=True)
class BendingDoc:
    """The bending double rocker: input rocker G0G (cam-driven) 2, coupler GB 3,
    output rocker B0B 4 (chained to the bending wheel); G0 at the origin, B0 on +x (G, not
    A: A is the feed crank's pin)."""

    frame: float = q("m", "L_G0B0")
    input_rocker: float = q("m", "L_G0G")
    coupler: float = q("m", "L_GB")
    output_rocker: float = q("m", "L_B0B")
    input_start: float = q("rad", "α1, input rocker at the start")
    input_swing: float = q("rad", "Δα of the synthesis (the brief's bending-cam swing; the cam "
                           "is designed for rounded.input_swing_needed when the brief rounds)")
    output_start: float = q("rad", "β1")
    output_swing: float = q("rad", "Δβ, signed (negative: clockwise)")
    branch: int = q("1", "assembly branch (±1)")
    sense: str = q("", "'same' or 'opposite': the chosen output sense")
    chain_ratio: float = q("1", "i = D_driving / D_bending")
    swing_simulated: float = q("rad", "Δβ simulated over the input swing, signed")
    bend_simulated: float = q("rad", "largest bending-wheel angle over the main-shaft cycle (the "
                              "four-bar as built: drawn lengths, when the brief rounds)")
    gamma_min: float = q("rad", "γ_min over the swing")
    gamma_max: float = q("rad", "γ_max over the swing")
    grashof: str = q("", "Grashof type of the four-bar")
    velocity_ratio: RangeDoc = q("", "least and largest |dβ/dα| over the swing")
    rounded: RoundedDoc | None = q("", "the lengths rounded as drawn, when the brief rounds")
    candidates: tuple[CandidateDoc, ...] = q("", "the synthesis candidates")
    seed: SeedDoc | None = q("", "the original report's lengths checked, when the brief gives them")
    cycle: BendingCycleDoc = q("", "over the main-shaft cycle")


@dataclass(frozen=True)
class FeedTableDoc:
    """The original report's table of the feed linkage: every 10° of crank angle (NaN → null where the
    linkage has no guide bar or rod)."""

    crank_angle: np.ndarray = q("rad", "crank angle CCW from +x")
    x: np.ndarray = q("m", "slider x")
    v: np.ndarray = q("m/s", "slider velocity along x")
    a: np.ndarray = q("m/s²", "slider acceleration along x")
    bar_omega: np.ndarray = q("rad/s", "guide bar ω")
    bar_alpha: np.ndarray = q("rad/s²", "guide bar α")
    rod_omega: np.ndarray = q("rad/s", "rod ω")
    rod_alpha: np.ndarray = q("rad/s²", "rod α")


@dataclass(frozen=True)
class LockbeamCycle(CycleDocument):
    """The brief's motion cycle diagram and its agreement with the cams and the feed."""

    cam_timing_error: dict[str, float] = q("1", "actuator key → largest deviation of its cam "
                                                "from the diagram's phases / stroke")
    feed_span_simulated: float = q("rad", "the feed linkage's working stroke (shaft angle)")
    pin_lift_while_bending: float = q("m", "least pin lift while the bending wheel turns")


@dataclass(frozen=True)
class MorphFunctionDoc:
    name_zh: str = q("", "the function (zh)")
    name_en: str = q("", "the function (en)")
    options: tuple[tuple[str, str], ...] = q("", "candidate mechanisms as [zh, en]")
    chosen: int = q("1", "index (from 0) of the chosen option")


@dataclass(frozen=True)
class MorphologyDoc:
    """The morphological matrix."""

    functions: tuple[MorphFunctionDoc, ...] = q("", "the functions and their options")
    counts: tuple[int, ...] = q("1", "options per function k_i")
    scheme_count: int = q("1", "N = Π k_i")


@dataclass(frozen=True)
class LockbeamResults:
    """Lock-beam bender. One main shaft turns once per part: the
    transmission drives it; on it the positioning cam (pin), the bending cam (double rocker
    → chain → bending wheel) and the feed linkage's crank (`feed`: the linkage engine's
    result, crank angles from its position 1). Shaft angles φ of the cycle diagram from its
    origin; SI units, speeds in rpm where the key says so."""

    schema: str = q("", "'mechdesign.results/2'")
    machine: str = q("", "'lockbeam'")
    units: str = q("", "reminder of the unit system")
    main_shaft_rpm: float = q("rpm", "main-shaft speed (the production rate, parts per minute)")
    transmission: TransmissionDoc = q("", "the transmission")
    positioning_cam: CamDocument = q("", "the positioning-pin cam")
    pin: PinDoc = q("", "the pin's lift check")
    bending_cam: CamDocument = q("", "the bending cam (oscillating follower: the input rocker)")
    bending: BendingDoc = q("", "the bending linkage")
    feed: LinkageDocument = q("", "the feed linkage on the linkage engine")
    feed_table: FeedTableDoc = q("", "the seed-format table of the feed linkage")
    cycle: LockbeamCycle = q("", "the motion cycle diagram")
    morphology: MorphologyDoc = q("", "the morphological matrix of the scheme")


#: The lock-beam's units note (no energies in its results).
UNITS = "SI: m, s, rad, kg, N, N·m, W; complex vectors as [x, y]"


def morphology_document(m) -> MorphologyDoc:
    """``m``: the brief's :class:`~mechdesign.brief.components.Morphology`."""
    return MorphologyDoc(
        tuple(MorphFunctionDoc(f.name_zh, f.name_en, tuple(tuple(o) for o in f.options),
                               f.chosen) for f in m.functions),
        tuple(m.counts), m.scheme_count)


def results_document(r: dict) -> LockbeamResults:
    from ...results import SCHEMA

    p: LockbeamParams = r["params"]
    tr, b, cyc, ft = r["transmission"], r["bending"], r["cycle"], r["feed_table"]
    ds = b.design
    rd, seed = b.rounded, b.seed
    return LockbeamResults(
        schema=SCHEMA, machine="lockbeam", units=UNITS, main_shaft_rpm=p.rate,
        transmission=TransmissionDoc(
            stages=tuple(TrainStageDoc(
                s.kind, s.driver, s.driven, s.ratio, s.speed_in, s.speed_out,
                None if s.pair is None else s.pair.a,
                None if s.pair is None else s.pair.contact_ratio) for s in tr.stages),
            ratio=tr.ratio, ratio_exact=str(tr.ratio_exact), output_rpm=tr.output_rpm,
            output_rpm_with_slip=tr.output_rpm_slip, shafts=tr.shafts),
        positioning_cam=cam_document(r["cam"]),
        pin=PinDoc(r["pin_check"].lift, r["pin_check"].required),
        bending_cam=cam_document(r["bending_cam"]),
        bending=BendingDoc(
            frame=ds.frame, input_rocker=ds.input_rocker, coupler=ds.coupler,
            output_rocker=ds.output_rocker, input_start=ds.alpha1, input_swing=ds.dalpha,
            output_start=ds.beta1, output_swing=ds.dbeta, branch=ds.branch,
            sense=b.synthesis.sense, chain_ratio=b.ratio, swing_simulated=b.swing_simulated,
            bend_simulated=b.bend_simulated, gamma_min=b.gamma_min, gamma_max=b.gamma_max,
            grashof=b.grashof,
            velocity_ratio=RangeDoc(float(np.min(np.abs(b.velocity_ratio))),
                                    float(np.max(np.abs(b.velocity_ratio)))),
            rounded=None if rd is None else RoundedDoc(
                rd.input_rocker, rd.coupler, rd.beta1, rd.swing, rd.bend, rd.gamma_min,
                rd.input_swing_needed, rd.margin),
            candidates=tuple(CandidateDoc(c[0], c[2], c[3],
                                          None if c[1] is None else c[1].input_rocker,
                                          None if c[1] is None else c[1].coupler)
                             for c in b.synthesis.candidates),
            seed=None if seed is None else SeedDoc(
                seed.input_rocker, seed.coupler, seed.grashof, tuple(seed.check.swing_range),
                tuple(SeedStartDoc(s[0], s[1], s[2]) for s in seed.check.starts)),
            cycle=BendingCycleDoc(b.shaft_angle, b.wheel_angle, b.wheel_omega, b.wheel_alpha,
                                  b.gamma_min_built)),
        feed=linkage_document(p.feed, r["feed"], r["feed_forces"], r["feed_flywheel"],
                              r["feed_verification"], r.get("feed_graphical")),
        feed_table=FeedTableDoc(ft.crank_angle, ft.x, ft.v, ft.a, ft.bar_omega, ft.bar_alpha,
                                ft.rod_omega, ft.rod_alpha),
        cycle=cy.cycle_document(cyc.diagram, cyc.checks, LockbeamCycle,
                                cam_timing_error=cyc.cam_timing_error,
                                feed_span_simulated=cyc.feed_span_simulated,
                                pin_lift_while_bending=cyc.pin_lift_while_bending),
        morphology=morphology_document(p.morphology))
