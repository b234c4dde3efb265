"""The one linkage engine: any planar linkage, crank plus Assur groups, analysed by the
shared linkage stages.

This is the engine every linkage machine composes (the furnace pusher's six-bar, the
lock-beam bender's feed, the die-cutter's toggle press and the stand-alone ``linkage``
brief). A :class:`LinkageModel` in SI units goes through four stages:

- motion (机构运动分析): the whole revolution on a fine grid plus the textbook
  positions, numbered from the output extreme that starts the working stroke; the
  transmission angle of every RRR group and the pressure angle of every slider;
- forces (动态静力分析): inertia forces and couples of the bodies, their weights and the
  resistances; joint reactions group by group and the balancing torque M_b on the crank;
- flywheel (飞轮设计), when the model asks for one;
- verification (校核): closure of every group, finite differences of every point and
  link, Σ power = 0, and the output's stroke and time ratio found by a bounded search
  between grid points (independent of the grid and of any synthesis formula).
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from ..core.kinetostatics import Body, PointLoad, power_residual, solve_forces
from ..core.mechanism import RRR, Crank, Mechanism, Motion
from ..core.errors import DesignError
from ..core.extremes import brentq, grid_roots, refine_extreme
from ..core.fields import q
from ..i18n import N_, tr
from .findings import Finding, Msg, Pair, finding
from .positions import Positions, textbook_positions, with_requested
from ..pipeline import Stage
from .flywheel import Flywheel, FlywheelSpec, design_flywheel
from .graphical import GraphicalDocument, graphical_stage
from .polygons import polygon_stage
from . import titles

TWO_PI = 2.0 * np.pi


@dataclass(frozen=True)
class Output:
    """The output whose motion defines the strokes: a point measured along ``direction``
    [rad] (``kind`` "point") or a link's angle (``kind`` "link"). ``working`` = +1 when the
    working stroke is the one in which the coordinate grows, −1 when it falls."""

    kind: str
    name: str
    direction: float = 0.0
    working: int = 1


@dataclass(frozen=True)
class Resistance:
    """A force on ``link`` at ``point`` along the line of angle ``direction`` [rad],
    opposing the point's motion along it: ``working`` [N] in the working stroke,
    ``returning`` [N] in the return stroke. With ``active`` = (from, to) the working
    force acts only while the output's displacement from position 1 lies in that
    window [m or rad] (a cutting or pressing zone). ``symbol`` names it in the graphical
    method's equations, polygons and sheets as the machine's data table does ("Fr" → F_r,
    "Fc" → F_c, "Q"; numbered Fr1, Fr2 … when a linkage has several)."""

    link: str
    point: str
    direction: float
    working: float
    returning: float = 0.0
    active: tuple[float, float] | None = None
    symbol: str = "Fr"


def link_name(names: dict, key: str, lang) -> str | None:
    """A link's (or group's) name from ``LinkageModel.names`` (``group_labels``) in ``lang``:
    the machine's (a catalogue message, translated here) or the brief's (name_zh, name_en);
    None when it has none."""
    value = (names or {}).get(key)
    if value is None:
        return None
    if isinstance(value, Msg):
        return value.text(lang)
    return value[0 if lang == "zh" else 1]


@dataclass(frozen=True)
class LinkageModel:
    """Everything the linkage stages need, SI units. ``crank_omega`` is signed, CCW +."""

    mechanism: Mechanism
    crank_omega: float
    output: Output
    bodies: tuple[Body, ...] = ()
    resistances: tuple[Resistance, ...] = ()
    grid_points: int = 3600
    position_step: float = np.pi / 6
    gravity: float = 9.81
    flywheel: FlywheelSpec | None = None
    special_crank_angles: tuple = ()            # crank angles [rad, CCW from +x] added to
    #                                             the textbook positions (primed labels)
    pressure_angle_limit: float | None = None   # [rad], checked over the working stroke
    transmission_angle_min: float | None = None  # [rad], checked over the whole cycle
    names: dict = field(default_factory=dict)    # link id → its name, optional: the machine's
    #                                              a catalogue message (Msg), the brief's a
    #                                              (name_zh, name_en) pair; see link_name
    group_labels: dict = field(default_factory=dict)  # group name → its name shown in the
    #                                                   reports, optional, the same way
    advice: dict = field(default_factory=dict)   # "pressure"/"transmission" → a Msg (or (zh, en)): the
    #                                              brief fields to change, added to the finding;
    #                                              "time_ratio" → (zh, en, field): K < 1 (the
    #                                              crank turning against the quick return) is
    #                                              then a finding saying what to change

    @property
    def crank(self) -> Crank:
        return self.mechanism.groups[0]


@dataclass(frozen=True)
class QualityAngle:
    """Transmission angle γ of an RRR group (at its middle joint) or pressure angle α of
    an RRP slider (between the rod and the guide), over the grid and the positions."""

    group: str = q("")
    kind: str = q("", "'transmission' | 'pressure'")
    point: str = q("", "the joint where it is measured")
    values: np.ndarray = q("rad", "one per entry of the phase array")
    extreme: float = q("rad", "γ_min or α_max over the cycle (exact: refined between samples)")
    extreme_phase: float = q("rad")
    working_extreme: float = q("rad", "the same over the working stroke only")
    working_extreme_phase: float = q("rad")
    limit: float | None = q("rad", "the model's [γ] or [α] (None: none given)", default=None)
    passed: bool | None = q("", "within the limit (:func:`quality_passed`; None: no limit)",
                            default=None)


@dataclass(frozen=True)
class LinkageMotion:
    """Stage 机构运动分析. Arrays: the grid (``grid_size`` entries) then the positions.

    ``phase`` is the crank angle from position 1 in the sense of rotation [rad]; the output
    displacement ``s`` [m or rad] is measured from position 1 along the working direction.
    """

    positions: Positions = q("")
    phase: np.ndarray = q("rad", "crank angle from position 1 in the sense of rotation")
    crank_angle: np.ndarray = q("rad", "crank angle, CCW from +x")
    s: np.ndarray = q("m or rad", "output displacement from position 1 along the working direction")
    v: np.ndarray = q("m/s or rad/s", "output velocity")
    a: np.ndarray = q("m/s² or rad/s²", "output acceleration")
    output_unit: str = q("", "'m' | 'rad'")
    stroke: float = q("m or rad", "stroke (or swing) of the output")
    working_span: float = q("rad", "crank angle of the working stroke")
    time_ratio: float = q("1", "K = working span / return span")
    start_angle: float = q("rad", "crank angle of position 1")
    sense: float = q("1", "+1 CCW, −1 CW")
    points: dict = q("m", "name → complex positions")
    link_angle: dict = q("rad", "link → angle")
    link_omega: dict = q("rad/s", "link → ω  (CCW +)")
    link_alpha: dict = q("rad/s²", "link → α")
    quality: tuple[QualityAngle, ...] = q("")
    grid_size: int = q("1", "entries of the uniform grid before the positions")
    requested: dict = q("", "what the brief asked for (φ45, an event code) → position label",
                        default_factory=dict)
    point_vel: dict = q("m/s", "named point (analysis.points) → complex velocity",
                        default_factory=dict)
    point_acc: dict = q("m/s²", "named point → complex acceleration", default_factory=dict)
    speed_peak: float = q("m/s or rad/s", "max |v| of the output over the cycle (exact: a bounded "
                          "search between the samples)", default=0.0)
    accel_peak: float = q("m/s² or rad/s²", "max |a| of the output over the cycle (exact)",
                          default=0.0)


@dataclass(frozen=True)
class LinkageForces:
    """Stage 动态静力分析 (arrays as in :class:`LinkageMotion`)."""

    resistance: dict = q("N", "'R{i}' → signed force along its line")
    reactions: dict = q("N", "R{a}{b} → complex force of link a on b")
    couples: dict = q("N·m", "prismatic-pair couples")
    inertia_force: dict = q("N", "link → complex −m·a_S")
    inertia_couple: dict = q("N·m", "link → −J_S·α")
    balancing_torque: np.ndarray = q("N·m", "M_b on the crank, in its sense of rotation")
    power_residual: np.ndarray = q("W", "Σ power of every load incl. M_b")
    mean_torque: float = q("N·m", "mean M_b over a revolution")
    mean_power: float = q("W", "mean power delivered to the crank")
    peak_torque: float = q("N·m", "max |M_b| (exact: one-sided at the jumps, refined between samples)")
    cycle_work: float = q("J", "work of the resistances per revolution (= 2π·mean M_b), each "
                          "constant piece integrated between its exact ends", default=0.0)
    torque_max: float = q("N·m", "max M_b (exact, one-sided at the jumps)", default=0.0)
    torque_min: float = q("N·m", "min M_b (exact, one-sided at the jumps)", default=0.0)


@dataclass(frozen=True)
class LinkageVerification:
    """Stage 校核: self-checks of the linkage run."""

    closure_residual: float = q("m", "max constraint violation")
    velocity_fd_error: float = q("1", "max |v − Δx/Δt| / max |v| over every moving point and link")
    acceleration_fd_error: float = q("1", "the same for accelerations")
    power_balance_residual: float = q("1", "max |Σ P| / max |M_b ω| (0 when there is no load)")
    stroke: float = q("m or rad", "stroke by a bounded position search")
    time_ratio: float = q("1", "K from the searched extremes")
    fd_step: float = q("rad")
    warnings: tuple[Finding, ...] = q("", "quality-angle findings", default=())
    power_balance_checked: bool = q("", "False when no load or mass gives a balancing torque: "
                                    "the power balance then checks nothing", default=True)


# ---------------------------------------------------------------- motion

def _output_coordinate(model: LinkageModel, m: Motion, reference: float | None = None):
    """Raw output coordinate: a point's position along the direction, or a link angle
    relative to ``reference`` (wrapped into ±π so an oscillating link is continuous)."""
    out = model.output
    if out.kind == "point":
        u = np.exp(1j * out.direction)
        p = m.points[out.name]
        return ((np.conj(u) * p.pos).real, (np.conj(u) * p.vel).real, (np.conj(u) * p.acc).real)
    link = m.links[out.name]
    ref = link.angle[0] if reference is None else reference
    return np.angle(np.exp(1j * (link.angle - ref))), link.omega, link.alpha


def _extremes_by_position(model: LinkageModel, angles: np.ndarray, s: np.ndarray, ref):
    """Crank angles and values of the output's minimum and maximum, each refined by a
    bounded scalar search on the position between the neighbouring grid points."""
    def s_at(angle: float) -> float:
        return float(_output_coordinate(model, model.mechanism.solve(np.array([angle])), ref)[0][0])

    found = []
    for largest in (False, True):
        x, _ = refine_extreme(s_at, angles, s, largest=largest)
        found.append((x % TWO_PI, s_at(x)))
    return found


def _extremes_by_velocity(model: LinkageModel, angles: np.ndarray, v: np.ndarray, ref):
    """The same from the crank angles where the output's analytic velocity is zero
    (Brent's method between grid points where it changes sign; precise to ~1e-14 rad)."""
    def at(angle: float):
        s, vel, _ = _output_coordinate(model, model.mechanism.solve(np.array([angle])), ref)
        return float(s[0]), float(vel[0])

    roots = grid_roots(lambda x: at(x)[1], angles, v)
    if len(roots) < 2:
        raise ValueError("the output does not reciprocate: its velocity never changes sign")
    values = [at(x)[0] for x in roots]
    lo, hi = int(np.argmin(values)), int(np.argmax(values))
    return [(roots[lo] % TWO_PI, values[lo]), (roots[hi] % TWO_PI, values[hi])]


def _strokes(model: LinkageModel, by_velocity: bool = True):
    """(start angle, end angle, s_start, s_end, reference) of the working stroke: by the
    velocity's zeros (motion stage) or by a position search (verification)."""
    n = model.grid_points
    angles = np.arange(n) * (TWO_PI / n)
    m = model.mechanism.solve(angles)
    ref = m.links[model.output.name].angle[0] if model.output.kind == "link" else None
    s, v, _ = _output_coordinate(model, m, ref)
    if by_velocity:
        found = _extremes_by_velocity(model, angles, v, ref)
    else:
        found = _extremes_by_position(model, angles, s, ref)
    (a_min, s_min), (a_max, s_max) = found
    if model.output.working > 0:
        return a_min, a_max, s_min, s_max, ref
    return a_max, a_min, s_max, s_min, ref


def _quality(model: LinkageModel, m: Motion, phase: np.ndarray, working_span: float, n: int,
             start: float, sense: float):
    """Each group's own quality angle (:meth:`quality` of the group types): the
    transmission angle's minimum, the pressure angle's maximum — exact, not sampled: a
    bounded search (Brent) between the grid neighbours of the grid's extreme, over the
    cycle and over the working stroke (whose ends are candidates too)."""
    from ..core.extremes import fminbound

    out = []
    working = phase[:n] <= working_span + 1e-12
    step = TWO_PI / n
    for g in model.mechanism.groups:
        found = g.quality(m)
        if found is None:
            continue
        kind, point, values = found
        lowest = kind == "transmission"
        sign = 1.0 if lowest else -1.0

        def at(p: float, g=g) -> float:
            return float(g.quality(model.mechanism.solve(np.array([start + sense * p])))[2][0])

        def best(lo: float, hi: float, p0: float, v0: float, ends=()) -> tuple[float, float]:
            x, f = fminbound(lambda p: sign * at(p), lo, hi)
            cands = [(p0, v0), (x, sign * f)] + [(e, at(e)) for e in ends]
            return min(cands, key=lambda c: sign * c[1])

        grid = values[:n]
        i = int(np.argmin(sign * grid))
        p_all, v_all = best(phase[i] - step, phase[i] + step, float(phase[i]), float(grid[i]))
        wi = np.flatnonzero(working)[int(np.argmin(sign * grid[working]))]
        p_w, v_w = best(max(0.0, phase[wi] - step), min(working_span, phase[wi] + step),
                        float(phase[wi]), float(grid[wi]), ends=(0.0, working_span))
        qa = QualityAngle(g.name, kind, point, values, float(v_all), float(p_all % TWO_PI),
                          float(v_w), float(p_w))
        out.append(replace(qa, **dict(zip(("limit", "passed"), quality_passed(qa, model)))))
    return tuple(out)


@dataclass(frozen=True)
class Requests:
    """The extra positions and points a brief asks for (``analysis`` section): crank angles
    [rad] with their labels (φ from position 1 in the sense of rotation, or the crank's
    direction CCW from +x), event codes (:data:`mechdesign.brief.common.EVENTS`), points."""

    angles: tuple = ()
    labels: tuple = ()
    from_x_axis: bool = False
    events: tuple = ()
    points: tuple = ()


def requests_of(brief) -> Requests | None:
    """The brief's requests (its ``analysis`` section), or None when it asks for nothing."""
    a = getattr(brief, "analysis", None)
    if a is None or not (getattr(a, "positions_deg", None) or getattr(a, "events", None)
                         or getattr(a, "points", None)):
        return None
    from ..brief.common import angle_label

    return Requests(tuple(float(np.radians(x)) for x in a.positions_deg),
                    tuple(angle_label(x) for x in a.positions_deg),
                    a.positions_from == "x_axis", tuple(a.events), tuple(a.points))


def _roots(fun, lo: float, hi: float, count: int = 720) -> list[float]:
    """Zeros of ``fun`` on (lo, hi): Brent's method between samples that change sign."""
    x = np.linspace(lo, hi, count + 1)
    y = [fun(float(t)) for t in x]
    out = []
    for i in range(count):
        if y[i] == 0.0 and 0 < i:
            out.append(float(x[i]))
        elif y[i] * y[i + 1] < 0:
            out.append(brentq(fun, float(x[i]), float(x[i + 1]), xtol=1e-15))
    return out


def event_phases(model: LinkageModel, code: str, start: float, sense: float, span: float,
                 s0: float, ref) -> list[float]:
    """Crank phases [rad from position 1] of the event ``code``, found exactly."""
    w = float(model.output.working)

    def at(phase: float) -> Motion:
        return model.mechanism.solve(np.array([start + sense * phase]))

    def out(phase: float):
        raw, v, a = _output_coordinate(model, at(phase), ref)
        return w * (float(raw[0]) - s0), w * float(v[0]), w * float(a[0])

    if code in ("work_start", "work_end"):
        window = next((r.active for r in model.resistances if r.active is not None), None)
        if window is None:          # the resistance acts over the whole working stroke
            return [0.0 if code == "work_start" else span]
        target = window[0] if code == "work_start" else window[1]
        found = _roots(lambda p: out(p)[0] - target, 0.0, span)
        return found[:1] if code == "work_start" else found[-1:]
    if code.startswith("max_velocity"):
        working = code.endswith("working")
        lo, hi = (0.0, span) if working else (span, TWO_PI)
        found = _roots(lambda p: out(p)[2], lo, hi)
        if not found:
            return []
        return [max(found, key=lambda p: abs(out(p)[1]))]
    kind, _, link = code.partition(":")
    links = model.mechanism.solve(np.array([start])).links
    if link not in links:
        raise DesignError(Msg(
            N_("analysis.events: {code!r}: link {link!r} is not a moving link; links: {links}"),
            code=code, link=link, links=", ".join(links)))
    trig = np.cos if kind == "link_vertical" else np.sin
    return _roots(lambda p: float(trig(at(p).links[link].angle[0])), 0.0, TWO_PI)


def _requested(model: LinkageModel, req: Requests, start: float, sense: float, span: float,
               s0: float, ref) -> list:
    """(phase, label or None, key) of every requested position."""
    extra = []
    for angle, label in zip(req.angles, req.labels):
        phase = sense * (angle - start) if req.from_x_axis else angle
        extra.append((phase % TWO_PI, label, label))
    from ..brief.common import event_name

    for code in req.events:
        found = event_phases(model, code, start, sense, span, s0, ref)
        if not found:
            raise DesignError(Msg(
                N_("analysis.events: {code!r}: the event ({event}) never occurs in this linkage; "
                   "remove it"), code=code, event=Pair(event_name(code, "zh"), event_name(code, "en"))))
        for i, phase in enumerate(found):
            extra.append((phase, None, code if i == 0 else f"{code}#{i + 1}"))
    return extra


def motion(model: LinkageModel, requests: Requests | None = None) -> tuple[LinkageMotion, Motion]:
    """Solve the revolution; position 1 is the output extreme that starts the working stroke.
    ``requests``: extra positions (by crank angle, by event) and named points (the brief's
    ``analysis`` section)."""
    start, end, s0, s1, ref = _strokes(model)
    sense = float(np.sign(model.crank_omega))
    span = (sense * (end - start)) % TWO_PI
    specials = [(sense * (a - start)) % TWO_PI for a in model.special_crank_angles]
    pos = textbook_positions(model.position_step, span, specials)
    names = {}
    if requests is not None:
        pos, names = with_requested(pos, model.position_step,
                                    _requested(model, requests, start, sense, span, s0, ref))
    n = model.grid_points
    grid = np.arange(n) * (TWO_PI / n)
    phase = np.concatenate([grid, pos.phase])
    crank_angle = start + sense * phase
    m = model.mechanism.solve(crank_angle)
    raw, v, a = _output_coordinate(model, m, ref)
    w = float(model.output.working)
    speed_peak, accel_peak = _output_peaks(model, ref, start, sense, grid, v[:n], a[:n])
    k = LinkageMotion(
        positions=pos, phase=phase, crank_angle=crank_angle,
        s=w * (raw - s0), v=w * v, a=w * a,
        output_unit="m" if model.output.kind == "point" else "rad",
        stroke=abs(s1 - s0), working_span=float(span), time_ratio=float(span / (TWO_PI - span)),
        start_angle=float(start), sense=sense,
        points={name: p.pos for name, p in m.points.items()},
        link_angle={k_: v_.angle for k_, v_ in m.links.items()},
        link_omega={k_: v_.omega for k_, v_ in m.links.items()},
        link_alpha={k_: v_.alpha for k_, v_ in m.links.items()},
        quality=_quality(model, m, phase, span, n, start, sense), grid_size=n, requested=names,
        point_vel={p: m.points[p].vel for p in _named_points(requests, m)},
        point_acc={p: m.points[p].acc for p in _named_points(requests, m)},
        speed_peak=speed_peak, accel_peak=accel_peak)
    return k, m


def _output_peaks(model: LinkageModel, ref, start: float, sense: float, grid: np.ndarray,
                  v: np.ndarray, a: np.ndarray) -> tuple[float, float]:
    """max |v| and max |a| of the output over the cycle: Brent's bounded search between the
    grid neighbours of the samples' largest (the motion is smooth)."""
    from ..core.extremes import refine_extreme

    def at(p: float, which: int) -> float:
        out = _output_coordinate(model, model.mechanism.solve(np.array([start + sense * p])), ref)
        return abs(float(out[which][0]))

    _, vmax = refine_extreme(lambda p: at(p, 1), grid, np.abs(v), largest=True, keep_grid=True)
    _, amax = refine_extreme(lambda p: at(p, 2), grid, np.abs(a), largest=True, keep_grid=True)
    return float(vmax), float(amax)


def _named_points(requests: Requests | None, m: Motion) -> tuple:
    """The brief's named points, each a point of the linkage (else a design error naming
    the field, the value and the points there are)."""
    if requests is None:
        return ()
    for name in requests.points:
        if name not in m.points:
            known = ", ".join(sorted(m.points))
            raise DesignError(Msg(
                N_("analysis.points: {name!r} is not a point of the linkage; its points: {known}"),
                name=name, known=known))
    return requests.points


# ---------------------------------------------------------------- forces

def resistance_loads(model: LinkageModel, k: LinkageMotion, m: Motion) -> list[PointLoad]:
    """The resistances as point loads over the phase array (zero where the point is at rest
    along the line)."""
    loads = []
    working = k.phase <= k.working_span + 1e-12
    for r in model.resistances:
        u = np.exp(1j * r.direction)
        along = (np.conj(u) * m.points[r.point].vel).real
        # At rest the force opposes the motion of the stroke it belongs to (one-sided
        # limit): the motion about to start (the acceleration's sign) — except at the end
        # of the working stroke, where it is the working motion just ending (the opposite).
        ahead = (np.conj(u) * m.points[r.point].acc).real
        ending = np.abs(k.phase - k.working_span) <= 1e-12
        ahead = np.where(ending, -ahead, ahead)
        scale = np.max(np.abs(along[:k.grid_size])) or 1.0
        moving = np.where(np.abs(along) > 1e-12 * scale, np.sign(along), np.sign(ahead))
        magnitude = np.where(working, r.working, r.returning)
        if r.active is not None:
            lo, hi = r.active
            tol = 1e-9 * max(k.stroke, 1e-12)
            inside = (k.s >= lo - tol) & (k.s <= hi + tol)
            magnitude = np.where(working & ~inside, 0.0, magnitude)
        loads.append(PointLoad(r.link, r.point, -moving * magnitude * u))
    return loads


def forces(model: LinkageModel, k: LinkageMotion, m: Motion) -> LinkageForces:
    """Kinetostatics over the phase array; the mean M_b is exact: the resistances' work per
    revolution (integrated piece by piece between exact ends, :class:`CycleIntegrals`)
    over 2π — inertia and gravity do no net work over a cycle."""
    loads = resistance_loads(model, k, m)
    bodies = list(model.bodies)
    fa = solve_forces(model.mechanism, m, bodies, loads, model.gravity)
    mb = k.sense * fa.driving_torque
    residual = power_residual(model.mechanism, m, bodies, loads, fa.driving_torque, model.gravity)
    n = k.grid_size
    exact = CycleIntegrals(model, k)
    lo, hi = exact.extremes()
    work = exact.cycle_work
    mean = work / TWO_PI
    return LinkageForces(
        resistance={f"R{i + 1}": (np.conj(np.exp(1j * r.direction)) * ld.force).real
                    for i, (r, ld) in enumerate(zip(model.resistances, loads))},
        reactions={name: r.force for name, r in fa.reactions.items()},
        couples={name: r.couple for name, r in fa.reactions.items() if r.couple is not None},
        inertia_force=fa.inertia_force, inertia_couple=fa.inertia_couple,
        balancing_torque=mb, power_residual=residual, mean_torque=mean,
        mean_power=mean * abs(model.crank_omega), peak_torque=max(abs(lo), abs(hi)),
        cycle_work=work, torque_max=hi, torque_min=lo)


def flywheel(model: LinkageModel, k: LinkageMotion, f: LinkageForces) -> Flywheel | None:
    """The one flywheel stage on M_b over the grid, when the model asks for a flywheel."""
    if model.flywheel is None:
        return None
    n = k.grid_size
    return design_flywheel(model.flywheel, k.phase[:n], f.balancing_torque[:n],
                           model.crank_omega, model.gravity, exact=CycleIntegrals(model, k))


# ---------------------------------------------------------------- exact cycle integrals

_MERGE = 1e-12     # [rad] piece ends closer than this are one end


def _sign_roots(fun, xs: np.ndarray, ys: np.ndarray) -> list[float]:
    """Zeros of ``fun`` between consecutive samples (xs, ys = fun(xs)) that change sign
    (Brent, to ~1e-15 rad), and samples where it is exactly zero."""
    out = [float(x) for x, y in zip(xs, ys) if y == 0.0]
    for i in np.flatnonzero(ys[:-1] * ys[1:] < 0):
        a, b = float(xs[i]), float(xs[i + 1])
        fa, fb = fun(a), fun(b)
        if fa * fb < 0:
            out.append(brentq(fun, a, b, xtol=1e-15))
        else:       # a zero on a sample, its sign lost to round-off: take that sample
            out.append(a if abs(fa) <= abs(fb) else b)
    return out


def _merge(anchors, others) -> np.ndarray:
    """Sorted piece ends: every anchor, and each other point farther than _MERGE from all."""
    ends = sorted(float(a) for a in anchors)
    for x in sorted(others):
        if min(abs(x - e) for e in ends) > _MERGE:
            ends.append(float(x))
            ends.sort()
    return np.array(ends)


class CycleIntegrals:
    """Exact integrals over one revolution of the crank phase φ [rad from position 1].

    Each resistance (:class:`Resistance`) is constant in magnitude on pieces of the cycle
    whose ends are found exactly: the start and the end of the working stroke, the ends of
    its ``active`` window (roots of s(φ) − window end, Brent) and the zeros of its point's
    velocity along its line. On a piece its work is magnitude × |travel of the point along
    the line| (the point is monotone there), so W_res(0→φ) is exact at any φ, and

        ∫₀^φ M_b dφ = [T(φ) − T(0)] + [V(φ) − V(0)] + W_res(0→φ)

    (the power balance M_b·|ω| = Σ resistance power + d(T + V)/dt with T and V the bodies'
    kinetic and potential energy from the exact kinematics). Over a revolution T and V
    return: the mean M_b is W_res(cycle)/2π. :meth:`torque` is M_b at any φ on a piece
    (one-sided at its ends); :meth:`stationary` the extremes' candidates of the energy
    curve M_d·φ − ∫M_b dφ.
    """

    def __init__(self, model: LinkageModel, k: LinkageMotion):
        self.model, self.k = model, k
        n = k.grid_size
        self.span = float(k.working_span)
        grid = np.asarray(k.phase[:n], float)
        self.grid = grid
        self._ref = None
        if model.output.kind == "link":
            self._ref = float(model.mechanism.solve(np.array([0.0])).links[model.output.name].angle[0])
        self._raw0 = float(_output_coordinate(model, self.solve(np.zeros(1)), self._ref)[0][0])
        mg = self.solve(grid)
        s_grid = self._s(mg)
        working = grid <= self.span
        ends_per, mags_per, cum_per, x_per = [], [], [], []
        for r in model.resistances:
            others = []
            if r.active is not None:
                xs = np.append(grid[working], self.span)
                ss = np.append(s_grid[working], self._s(self.solve(np.array([self.span])))[0])
                for target in r.active:
                    others += _sign_roots(lambda p, t=target: self._s(self.solve(np.array([p])))[0] - t,
                                          xs, ss - target)
            xs = np.append(grid, TWO_PI)
            vg = self._along(r, mg)[1]
            others += _sign_roots(lambda p, r=r: self._along(r, self.solve(np.array([p])))[1][0],
                                  xs, np.append(vg, vg[0]))
            ends = _merge((0.0, self.span, TWO_PI), [x for x in others if 0.0 < x < TWO_PI])
            mid = 0.5 * (ends[:-1] + ends[1:])
            mags = self._magnitude(r, mid, self._s(self.solve(mid)))
            x = self._along(r, self.solve(ends))[0]
            cum = np.concatenate(([0.0], np.cumsum(mags * np.abs(np.diff(x)))))
            ends_per.append(ends)
            mags_per.append(mags)
            cum_per.append(cum)
            x_per.append(x)
        self._ends, self._mags, self._cum, self._x = ends_per, mags_per, cum_per, x_per
        self.cycle_work = float(sum(c[-1] for c in cum_per))
        self.ends = _merge((0.0, TWO_PI), [e for ends in ends_per for e in ends[1:-1]])
        self._stored0 = float(self.stored_energy(self.solve(np.zeros(1)))[0])

    # -- kinematics at any phase
    def solve(self, phase: np.ndarray) -> Motion:
        k = self.k
        return self.model.mechanism.solve(k.start_angle + k.sense * np.asarray(phase, float))

    def _s(self, m: Motion) -> np.ndarray:
        raw = _output_coordinate(self.model, m, self._ref)[0]
        return float(self.model.output.working) * (raw - self._raw0)

    @staticmethod
    def _along(r: Resistance, m: Motion):
        """Position and velocity of the resistance's point along its line."""
        u = np.exp(-1j * r.direction)
        p = m.points[r.point]
        return (u * p.pos).real, (u * p.vel).real

    def _magnitude(self, r: Resistance, phase: np.ndarray, s: np.ndarray) -> np.ndarray:
        """The force's magnitude inside a piece (the rule of :func:`resistance_loads`)."""
        working = phase <= self.span + 1e-12
        mag = np.where(working, r.working, r.returning)
        if r.active is not None:
            lo, hi = r.active
            tol = 1e-9 * max(self.k.stroke, 1e-12)
            mag = np.where(working & ~((s >= lo - tol) & (s <= hi + tol)), 0.0, mag)
        return mag

    # -- energies and work
    def stored_energy(self, m: Motion) -> np.ndarray:
        """T + V of the bodies [J] (kinetic from the exact velocities, potential from the
        centres' heights)."""
        total = np.zeros(len(m.crank_angle))
        for b in self.model.bodies:
            if b.mass:
                p = m.points[b.com]
                total = total + 0.5 * b.mass * np.abs(p.vel) ** 2 + b.mass * self.model.gravity * p.pos.imag
            if b.inertia:
                total = total + 0.5 * b.inertia * m.links[b.link].omega ** 2
        return total

    def resistance_work(self, phase: np.ndarray, m: Motion | None = None) -> np.ndarray:
        """W_res(0 → φ) [J]: the resistances' work from position 1, piece by piece."""
        phase = np.asarray(phase, float)
        m = self.solve(phase) if m is None else m
        total = np.zeros(len(phase))
        for r, ends, mags, cum, x in zip(self.model.resistances, self._ends, self._mags,
                                         self._cum, self._x):
            j = np.clip(np.searchsorted(ends, phase, side="right") - 1, 0, len(mags) - 1)
            total = total + cum[j] + mags[j] * np.abs(self._along(r, m)[0] - x[j])
        return total

    def integral(self, phase) -> np.ndarray:
        """∫₀^φ M_b dφ [J] at each phase (0 ≤ φ ≤ 2π)."""
        phase = np.atleast_1d(np.asarray(phase, float))
        m = self.solve(phase)
        return self.stored_energy(m) - self._stored0 + self.resistance_work(phase, m)

    def torque(self, phase: np.ndarray, piece: int) -> np.ndarray:
        """M_b [N·m] at ``phase`` with the resistances' magnitudes of ``piece`` (of
        :attr:`ends`): the power balance M_b·|ω| = d(T + V)/dt − Σ resistance power."""
        phase = np.atleast_1d(np.asarray(phase, float))
        m = self.solve(phase)
        mid = 0.5 * (self.ends[piece] + self.ends[piece + 1])
        g = self.model.gravity
        power = np.zeros(len(phase))
        for b in self.model.bodies:
            if b.mass:
                p = m.points[b.com]
                power = power + b.mass * ((p.acc.real * p.vel.real + p.acc.imag * p.vel.imag)
                                          + g * p.vel.imag)
            if b.inertia:
                w = m.links[b.link]
                power = power + b.inertia * w.alpha * w.omega
        for r, ends, mags in zip(self.model.resistances, self._ends, self._mags):
            j = int(np.clip(np.searchsorted(ends, mid, side="right") - 1, 0, len(mags) - 1))
            power = power + mags[j] * np.abs(self._along(r, m)[1])
        return power / abs(self.model.crank_omega)

    def extremes(self) -> tuple[float, float]:
        """(min M_b, max M_b) [N·m] over the cycle, exactly: on every piece its one-sided
        values at both ends (M_b jumps there) and each interior local extreme refined by a
        bounded search (Brent) between the grid neighbours of the grid's local extreme."""
        from ..core.extremes import fminbound

        lo_all, hi_all = np.inf, -np.inf
        for i in range(len(self.ends) - 1):
            a, b = float(self.ends[i]), float(self.ends[i + 1])
            inner = self.grid[(self.grid > a + _MERGE) & (self.grid < b - _MERGE)]
            xs = np.concatenate(([a], inner, [b]))
            ys = self.torque(xs, i)
            lo_all, hi_all = min(lo_all, float(ys.min())), max(hi_all, float(ys.max()))
            if len(xs) < 3:
                continue
            for sign in (1.0, -1.0):          # minima, then maxima
                z = sign * ys
                for j in np.nonzero((z[1:-1] <= z[:-2]) & (z[1:-1] <= z[2:]))[0] + 1:
                    _, f = fminbound(lambda p, i=i, sign=sign:
                                     sign * float(self.torque(np.array([p]), i)[0]),
                                     float(xs[j - 1]), float(xs[j + 1]))
                    if sign > 0:
                        lo_all = min(lo_all, f)
                    else:
                        hi_all = max(hi_all, -f)
        return float(lo_all), float(hi_all)

    def peak(self) -> float:
        """max |M_b| [N·m] over the cycle, exactly (see :meth:`extremes`)."""
        lo, hi = self.extremes()
        return max(abs(lo), abs(hi))

    def stationary(self, driving_torque: float) -> np.ndarray:
        """Phases where the energy curve M_d·φ − ∫M_b dφ may be extreme: the roots of
        M_b − M_d on every piece (sign changes between the grid's samples, Brent with M_b
        from :meth:`torque`) and the piece ends (M_b jumps there)."""
        found = list(self.ends[:-1])
        for i in range(len(self.ends) - 1):
            a, b = float(self.ends[i]), float(self.ends[i + 1])
            inner = self.grid[(self.grid > a + _MERGE) & (self.grid < b - _MERGE)]
            xs = np.concatenate(([a], inner, [b]))
            ys = self.torque(xs, i) - driving_torque
            found += _sign_roots(lambda p, i=i: float(self.torque(np.array([p]), i)[0]) - driving_torque,
                                 xs, ys)
        return np.array(sorted(x for x in found if 0.0 <= x < TWO_PI))


# ---------------------------------------------------------------- verification

def closure_residual(mech: Mechanism, m: Motion, n: int | None = None) -> float:
    """Largest violation of any group's constraints [m] (lengths, points on guides), each
    group's own closure equations (:meth:`residual` of the group types)."""
    P = {name: p.pos[:n] for name, p in m.points.items()}
    res = [0.0]
    for g in mech.groups:
        res.extend(float(np.max(np.abs(x))) for x in g.residual(P, m, n))
    return max(res)


def _fd_errors(m: Motion, n: int, omega: float) -> tuple[float, float]:
    """Central differences on the periodic grid against the analytic velocities and
    accelerations of every moving point and link (relative to each one's maximum)."""
    dt = (TWO_PI / n) / abs(omega)
    vel_err, acc_err = 0.0, 0.0

    def rel(x, ref):
        scale = np.max(np.abs(ref))
        return 0.0 if scale < 1e-12 else float(np.max(np.abs(x)) / scale)

    for p in m.points.values():
        pos, vel, acc = p.pos[:n], p.vel[:n], p.acc[:n]
        if np.max(np.abs(vel)) < 1e-12:
            continue
        vel_err = max(vel_err, rel(vel - (np.roll(pos, -1) - np.roll(pos, 1)) / (2 * dt), vel))
        acc_err = max(acc_err, rel(acc - (np.roll(vel, -1) - np.roll(vel, 1)) / (2 * dt), acc))
    for link in m.links.values():
        th, w, al = link.angle[:n], link.omega[:n], link.alpha[:n]
        if np.max(np.abs(w)) < 1e-12:
            continue
        dth = np.angle(np.exp(1j * (np.roll(th, -1) - np.roll(th, 1))))
        vel_err = max(vel_err, rel(w - dth / (2 * dt), w))
        acc_err = max(acc_err, rel(al - (np.roll(w, -1) - np.roll(w, 1)) / (2 * dt), al))
    return vel_err, acc_err


def verify(model: LinkageModel, k: LinkageMotion, m: Motion, f: LinkageForces | None
           ) -> LinkageVerification:
    n = k.grid_size
    vel_err, acc_err = _fd_errors(m, n, model.crank_omega)
    power, checked = 0.0, False
    if f is not None:
        scale = np.max(np.abs(f.balancing_torque[:n] * model.crank_omega))
        checked = bool(scale > 0)
        power = float(np.max(np.abs(f.power_residual[:n])) / scale) if checked else 0.0
    start, end, s0, s1, _ = _strokes(model, by_velocity=False)
    span = (k.sense * (end - start)) % TWO_PI
    stroke, ratio = abs(s1 - s0), float(span / (TWO_PI - span))
    return LinkageVerification(
        closure_residual=closure_residual(model.mechanism, m, n),
        velocity_fd_error=vel_err, acceleration_fd_error=acc_err,
        power_balance_residual=power, stroke=stroke, time_ratio=ratio, fd_step=TWO_PI / n,
        warnings=tuple(quality_findings(model, k)), power_balance_checked=checked)


def _four_bar_of(model: LinkageModel, group_name: str):
    """(a, b, c, d) [m] when the RRR group ``group_name`` closes a four-bar with the crank
    (one end on the crank pin, the other on the frame), else None."""
    mech = model.mechanism
    crank = mech.groups[0] if mech.groups and isinstance(mech.groups[0], Crank) else None
    for g in mech.groups:
        if crank is None or not isinstance(g, RRR) or g.name != group_name:
            continue
        for tip, fixed, b, c in ((g.b, g.d, g.l1, g.l2), (g.d, g.b, g.l2, g.l1)):
            if tip == crank.tip and fixed in mech.frame_points:
                d = abs(mech.frame_points[fixed] - mech.frame_points[crank.pivot])
                return crank.length, b, c, d
    return None


def _advice(value):
    """An entry of ``LinkageModel.advice`` as a message: a :class:`Msg`, or the (zh, en)
    texts a caller gave (a :class:`Pair`); None when there is none."""
    if value is None or isinstance(value, Msg):
        return value or None
    zh, en = value[:2]
    return Pair(zh, en) if (zh or en) else None


def quality_findings(model: LinkageModel, k: LinkageMotion) -> list[Finding]:
    """Pressure angle over the working stroke and transmission angle over the cycle
    against the model's limits, each saying what to change (``model.advice`` adds the
    brief's fields)."""
    found = []
    deg = 180.0 / np.pi

    def extra(kind):        # the brief's fields to change, appended in parentheses
        advice = _advice(model.advice.get(kind))
        return Msg(N_(" ({advice})"), advice=advice) if advice else ""

    if "time_ratio" in model.advice and k.time_ratio < 1.0 - 1e-9:
        # The working stroke is the faster one: the crank turns against the quick return.
        *said, where = model.advice["time_ratio"]
        theta = np.pi * (k.time_ratio - 1.0) / (k.time_ratio + 1.0) * deg
        work, back = k.working_span * deg, 360.0 - k.working_span * deg
        found.append(finding(
            "crank_sense_reversed",
            N_("time ratio K = {K:.4f} < 1 (extreme-position angle θ = {theta:.2f}° < 0): the "
               "working stroke takes {work:.2f}° of crank angle and the return {back:.2f}°, so the "
               "crank turns against the working stroke's sense (no quick return); {advice}"),
            field=where, K=k.time_ratio, theta=theta, work=work, back=back,
            advice=_advice(said[0] if len(said) == 1 else said)))
    for qa in k.quality:
        within = qa.passed
        if qa.kind == "pressure" and within is False:
            found.append(finding(
                "pressure_angle",
                N_("{group}: the largest pressure angle in the working stroke, {alpha:.2f}°, "
                   "exceeds the allowed {limit:.1f}°; lengthen the rod or move the guide{advice}"),
                group=qa.group, alpha=qa.working_extreme * deg,
                limit=model.pressure_angle_limit * deg, advice=extra("pressure")))
        if qa.kind == "transmission" and within is False:
            fix = Msg(N_("change the link lengths"))
            four = _four_bar_of(model, qa.group)
            if four is not None:
                # γ at the two crank–frame collinear positions is balanced (γmin largest for
                # these a, d) when b² + c² = a² + d²; a shorter crank raises both.
                a, b, c, d = (x * 1e3 for x in four)
                fix = Msg(N_("shorten the crank (a = {a:.6g} mm) and bring b² + c² close to "
                             "a² + d² (now {bc:.6g} and {ad:.6g} mm²; when equal, the transmission "
                             "angles at the two crank–frame collinear positions are the same)"),
                          a=a, bc=b * b + c * c, ad=a * a + d * d)
            found.append(finding(
                "transmission_angle",
                N_("{group}: the minimum transmission angle {gamma:.2f}° is below the allowed "
                   "{limit:.1f}°; {fix}{advice}"), group=qa.group, gamma=qa.extreme * deg,
                limit=model.transmission_angle_min * deg, fix=fix, advice=extra("transmission")))
    return found


# ---------------------------------------------------------------- stages and results

def linkage_stages(model_key: str = "model", prefix: str = "linkage") -> list[Stage]:
    """The stages on the model found at ``results[model_key]``; results are stored as
    ``{prefix}``, ``{prefix}_raw``, ``{prefix}_forces``, ``{prefix}_flywheel``,
    ``{prefix}_verification`` and ``{prefix}_polygons`` (the analysis sheet's polygons)."""
    return [
        Stage((prefix, f"{prefix}_raw"), titles.pgettext("stage", "kinematics"),
              lambda r: motion(r[model_key], requests_of(r.get("brief")))),
        Stage(f"{prefix}_forces", titles.pgettext("stage", "kinetostatics"),
              lambda r: forces(r[model_key], r[prefix], r[f"{prefix}_raw"])),
        Stage(f"{prefix}_flywheel", titles.pgettext("stage", "flywheel"),
              lambda r: flywheel(r[model_key], r[prefix], r[f"{prefix}_forces"])),
        Stage(f"{prefix}_verification", titles.pgettext("stage", "verification"),
              lambda r: verify(r[model_key], r[prefix], r[f"{prefix}_raw"],
                               r[f"{prefix}_forces"])),
        polygon_stage(model_key, prefix),
        graphical_stage(model_key, prefix),
    ]


@dataclass(frozen=True)
class OutputDoc:
    """The output whose motion defines the strokes."""

    kind: str = q("", "'point' (a point along a direction) or 'link' (a link's angle)")
    name: str = q("", "the point's or the link's name")
    unit: str = q("", "'m' or 'rad': the unit of s, v, a and the stroke")
    stroke: float = q("m or rad", "stroke (or swing) of the output")


@dataclass(frozen=True)
class QualityDoc:
    group: str = q("", "the Assur group")
    kind: str = q("", "'transmission' (γ of an RRR group) or 'pressure' (α of a slider)")
    point: str = q("", "the joint where it is measured")
    extreme: float = q("rad", "γ_min or α_max over the cycle (exact: refined between samples)")
    extreme_phase: float = q("rad", "crank phase where it occurs")
    working_extreme: float = q("rad", "the same over the working stroke only")
    limit: float | None = q("rad", "the brief's limit: [γ] (γ_min over the cycle ≥ it) or [α] "
                            "(α_max over the working stroke ≤ it); None when none is given")
    passed: bool | None = q("", "the angle within its limit (None: no limit given)")


def quality_passed(qa, model) -> tuple[float | None, bool | None]:
    """(limit, within it) of one transmission or pressure angle: γ_min over the cycle against
    the model's [γ], α_max over the working stroke against its [α]; (None, None) without a
    limit. The same judgement as the findings (:func:`quality_findings`)."""
    if qa.kind == "transmission" and model.transmission_angle_min is not None:
        return model.transmission_angle_min, bool(qa.extreme >= model.transmission_angle_min - 1e-9)
    if qa.kind == "pressure" and model.pressure_angle_limit is not None:
        return model.pressure_angle_limit, bool(qa.working_extreme <= model.pressure_angle_limit + 1e-9)
    return None, None


@dataclass(frozen=True)
class LinkagePosition:
    """One textbook position (机构位置)."""

    label: str = q("", "1, 2, …; primed labels are special positions (the other extreme, 4′ …)")
    phase: float = q("rad", "crank angle from position 1 in the sense of rotation")
    crank_angle: float = q("rad", "crank angle, CCW from +x")
    s: float = q("m or rad", "output displacement from position 1 along the working direction")
    v: float = q("m/s or rad/s", "output velocity")
    a: float = q("m/s² or rad/s²", "output acceleration")
    points: dict[str, complex] = q("m", "every named point, [x, y]")
    link_omega: dict[str, float] = q("rad/s", "angular velocity of every link (CCW +)")
    link_alpha: dict[str, float] = q("rad/s²", "angular acceleration of every link")
    quality: dict[str, float] = q("rad", "transmission/pressure angle of each group")
    reactions: dict[str, complex] = q("N", "R{a}{b}: force of link a on link b, [x, y]")
    balancing_torque: float = q("N·m", "M_b on the crank, in its sense of rotation")


@dataclass(frozen=True)
class LinkageGrid:
    """Arrays over one revolution on the uniform grid (phase from 0)."""

    phase: np.ndarray = q("rad", "crank phase from position 1")
    s: np.ndarray = q("m or rad", "output displacement")
    v: np.ndarray = q("m/s or rad/s", "output velocity")
    a: np.ndarray = q("m/s² or rad/s²", "output acceleration")
    balancing_torque: np.ndarray = q("N·m", "M_b")


@dataclass(frozen=True)
class LinkageDocument:
    """The linkage engine's results: motion at the positions and over the grid, quality
    angles, kinetostatics, flywheel and self-checks."""

    crank_omega: float = q("rad/s", "crank angular velocity, CCW +")
    output: OutputDoc = q("", "the output")
    working_stroke_crank_angle: float = q("rad", "crank rotation of the working stroke")
    time_ratio: float = q("1", "K = working span / return span (from the velocity zeros)")
    start_crank_angle: float = q("rad", "crank angle of position 1")
    quality: tuple[QualityDoc, ...] = q("", "transmission and pressure angles")
    positions: tuple[LinkagePosition, ...] = q("", "the textbook positions in crank order")
    grid: LinkageGrid = q("", "one revolution")
    mean_torque: float = q("N·m", "mean M_b")
    mean_power: float = q("W", "mean power delivered to the crank")
    peak_torque: float = q("N·m", "max |M_b| (exact: one-sided at the jumps, refined between samples)")
    flywheel: Flywheel | None = q("", "the flywheel (the one flywheel stage), if any")
    verification: LinkageVerification = q("", "self-checks")
    graphical: GraphicalDocument | None = q("", "the graphical method at the polygon "
                                            "positions", default=None)


def linkage_document(model: LinkageModel, k: LinkageMotion, f: LinkageForces,
                     fly: Flywheel | None, v: LinkageVerification,
                     graphical: GraphicalDocument | None = None) -> LinkageDocument:
    """The linkage part of results.json (SI)."""
    n = k.grid_size
    per_position = []
    for i, label in enumerate(k.positions.labels):
        j = n + i
        per_position.append(LinkagePosition(
            label=label, phase=k.phase[j], crank_angle=k.crank_angle[j] % TWO_PI,
            s=k.s[j], v=k.v[j], a=k.a[j],
            points={p: z[j] for p, z in k.points.items()},
            link_omega={l_: w[j] for l_, w in k.link_omega.items()},
            link_alpha={l_: a[j] for l_, a in k.link_alpha.items()},
            quality={q_.group: q_.values[j] for q_ in k.quality},
            reactions={name: r[j] for name, r in f.reactions.items()},
            balancing_torque=f.balancing_torque[j]))
    return LinkageDocument(
        crank_omega=model.crank_omega,
        output=OutputDoc(model.output.kind, model.output.name, k.output_unit, k.stroke),
        working_stroke_crank_angle=k.working_span, time_ratio=k.time_ratio,
        start_crank_angle=k.start_angle,
        quality=tuple(QualityDoc(q_.group, q_.kind, q_.point, q_.extreme, q_.extreme_phase,
                                 q_.working_extreme, q_.limit, q_.passed) for q_ in k.quality),
        positions=tuple(per_position),
        grid=LinkageGrid(k.phase[:n], k.s[:n], k.v[:n], k.a[:n], f.balancing_torque[:n]),
        mean_torque=f.mean_torque, mean_power=f.mean_power, peak_torque=f.peak_torque,
        flywheel=fly, verification=v, graphical=graphical)


def link_members(mech: Mechanism) -> tuple[dict, list]:
    """For drawings: the points each moving link carries, and the sliders as
    (slider link, point, guide: link id or fixed angle [rad], guide point or None), from
    each group's :meth:`members`."""
    members: dict[str, list[str]] = {}
    sliders = []
    for g in mech.groups:
        carried, slides = g.members()
        for link, pts in carried:
            lst = members.setdefault(link, [])
            lst.extend(p for p in pts if p not in lst)
        sliders.extend(slides)
    return members, sliders


# ---------------------------------------------------------------- the brief's requests

@dataclass(frozen=True)
class PointAtPosition:
    """A named point's motion at one position."""

    label: str = q("", "the position's label")
    velocity: float = q("m/s", "|v| of the point")
    velocity_direction: float = q("rad", "direction of v, CCW from +x (0 when at rest: |v| ≤ 1e-9·max |v|)")
    acceleration: float = q("m/s²", "|a| of the point")
    acceleration_direction: float = q("rad", "direction of a, CCW from +x (0 when zero)")


@dataclass(frozen=True)
class NamedPointDoc:
    """One point of ``analysis.points``: at every position and over the grid."""

    name: str = q("", "the point's name")
    positions: tuple[PointAtPosition, ...] = q("", "at every position, in crank order")
    grid_velocity: np.ndarray = q("m/s", "|v| over the uniform grid (phase from position 1)")
    grid_acceleration: np.ndarray = q("m/s²", "|a| over the uniform grid")


@dataclass(frozen=True)
class RequestedPosition:
    """A position the brief asked for (``analysis.positions_deg`` or ``analysis.events``)."""

    asked: str = q("", "φ45 for positions_deg: [45]; the event code (work_start …)")
    label: str = q("", "the label of the position it is (a regular position when they coincide)")
    phase: float = q("rad", "crank angle from position 1 in the sense of rotation")
    crank_angle: float = q("rad", "crank angle, CCW from +x")


@dataclass(frozen=True)
class AnalysisRequests:
    """What the brief's ``analysis`` section asked for, for every linkage machine: the
    positions by angle and by event (each also in the machine's position tables) and the
    named points' velocities and accelerations."""

    positions: tuple[RequestedPosition, ...] = q("", "the positions asked for")
    points: tuple[NamedPointDoc, ...] = q("", "the named points")


def requests_document(k: LinkageMotion) -> AnalysisRequests | None:
    """The ``analysis_requests`` part of results.json, or None when nothing was asked."""
    if not k.requested and not k.point_vel:
        return None
    n = k.grid_size
    labels = [str(x) for x in k.positions.labels]

    def at(label):
        return n + labels.index(label)

    def direction(z, scale):
        return float(np.angle(z)) if abs(z) > 1e-9 * scale else 0.0

    asked = tuple(RequestedPosition(key, label, float(k.phase[at(label)]),
                                    float(k.crank_angle[at(label)] % TWO_PI))
                  for key, label in k.requested.items())
    points = []
    for name, vel in k.point_vel.items():
        acc = k.point_acc[name]
        sv, sa = float(np.max(np.abs(vel))), float(np.max(np.abs(acc)))
        points.append(NamedPointDoc(name, tuple(
            PointAtPosition(lab, abs(vel[n + i]), direction(vel[n + i], sv), abs(acc[n + i]),
                            direction(acc[n + i], sa)) for i, lab in enumerate(labels)),
            np.abs(vel[:n]), np.abs(acc[:n])))
    return AnalysisRequests(asked, tuple(points))
