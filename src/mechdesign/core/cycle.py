"""Motion cycle diagram (运动循环图) of several actuators against the main shaft angle.

Method (孙桓《机械原理》, chapter on the design of mechanical systems' motion schemes,
运动循环图): every actuator (执行构件) of a machine driven by one distribution shaft (分配轴)
repeats its motion once per shaft revolution; the diagram lists, for each actuator, the
consecutive phases (推程、远停歇、回程、近停歇 …) as arcs of the shaft angle φ, which together
cover exactly one revolution. The diagram is checked against timing constraints between
actuators (e.g. the positioning pin is up before bending starts) and against the cams that
actually produce the motions.

Conventions (SI, radians):

* φ is the shaft angle, increasing in the sense the shaft turns; every angle is taken
  modulo 2π. A phase is the half-open arc [start, start + span): the angle where one phase
  ends belongs to the next phase. Angles within 1e-9 rad of a boundary count as on it.
* The diagram starts at ``origin`` (default 0): it is drawn from φ = origin to origin + 2π,
  and "before" means "earlier in that window" (see :func:`check_constraints`).
* The cycle time is T = 2π/ω = 60/n (n in rpm); a phase of span Δφ lasts Δφ/ω.

States come from a small fixed vocabulary (:data:`STATES`); a phase may carry its own
display label (e.g. 扳弯 for the bending arm's rise).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Iterable, NamedTuple, Sequence

import numpy as np

from .errors import DesignError, N_, pgettext
from ..i18n import Msg
from .fields import q

TWO_PI = 2.0 * np.pi
#: Angles this close to a phase boundary count as lying on it [rad].
BOUNDARY_TOL = 1e-9
#: How far the phase spans may add up away from 2π before it is an error [rad].
COVER_TOL = 1e-6

RISE, DWELL_HIGH, RETURN, DWELL_LOW, MOVE, DWELL = (
    "rise", "dwell_high", "return", "dwell_low", "move", "dwell")
#: Windows of a reciprocating output that never stops (a crank-driven platen): near its
#: working end (the output moves in and out of the work zone), and clear of it.
WORK, CLEAR = "work", "clear"
MOTION, REST = "motion", "rest"

class _State(tuple):
    """(Chinese name, English name, motion or rest) of a state, as the rendering layer reads
    it; the core holds the English name (a msgid, context "cycle state") and the Chinese is
    its translation, looked up in the catalogue when it is read."""

    __slots__ = ()

    def __new__(cls, name, kind: str):
        en = getattr(name, "msgid", name)
        return tuple.__new__(cls, (en, en, kind))

    def __getnewargs__(self):
        return (tuple.__getitem__(self, 1), tuple.__getitem__(self, 2))

    def __getitem__(self, i):
        if isinstance(i, int) and i in (0, -3):
            return self.name("zh")
        if isinstance(i, slice):
            return tuple(self)[i]
        return tuple.__getitem__(self, i)

    def __iter__(self):
        yield self.name("zh")
        yield tuple.__getitem__(self, 1)
        yield tuple.__getitem__(self, 2)

    def name(self, lang: str) -> str:
        """The state's name in ``lang``."""
        return pgettext("cycle state", tuple.__getitem__(self, 1)).text(lang)


#: state → (Chinese name, English name, motion or rest). ``rise``/``return`` are the
#: outward and homeward strokes of a reciprocating (translating or swinging) output,
#: ``dwell_high``/``dwell_low`` its rests at the far and near ends; ``move``/``dwell`` are
#: for an output that advances in one direction only (an intermittently driven chain or
#: table) or when the end does not matter; ``work``/``clear`` are windows of an output
#: that moves all the time (near its working end, and clear of it). The names are msgids (context "cycle state"):
#: ``STATES[s].name(lang)`` translates; index 0 is the Chinese (looked up when read).
STATES: dict[str, tuple[str, str, str]] = {
    RISE: _State(pgettext("cycle state", "rise"), MOTION),
    DWELL_HIGH: _State(pgettext("cycle state", "far dwell"), REST),
    RETURN: _State(pgettext("cycle state", "return"), MOTION),
    DWELL_LOW: _State(pgettext("cycle state", "near dwell"), REST),
    MOVE: _State(pgettext("cycle state", "move"), MOTION),
    DWELL: _State(pgettext("cycle state", "dwell"), REST),
    WORK: _State(pgettext("cycle state", "moving, work zone"), MOTION),
    CLEAR: _State(pgettext("cycle state", "moving, clear zone"), MOTION),
}


class CycleError(DesignError):
    """A cycle diagram or constraint that is inconsistent; the message names the actuator."""


# --------------------------------------------------------------------------- data


@dataclass(frozen=True)
class Phase:
    """One phase of an actuator: ``state`` from :data:`STATES`, ``start`` ∈ [0, 2π) and
    ``span`` > 0 [rad]; optional display labels override the state's name: the brief's
    (label_zh, label_en), or the program's as a catalogue message (label_msg)."""

    state: str
    start: float
    span: float
    label_zh: str = ""
    label_en: str = ""
    label_msg: Msg | None = None

    @property
    def end(self) -> float:
        """start + span [rad]; may exceed 2π when the phase runs through φ = 0."""
        return self.start + self.span

    def name(self, lang: str) -> str:
        if self.label_msg is not None:
            return self.label_msg.text(lang)
        label = self.label_zh if lang == "zh" else self.label_en
        return label or STATES[self.state].name(lang)

    @property
    def moving(self) -> bool:
        return STATES[self.state][2] == MOTION


@dataclass(frozen=True)
class Actuator:
    """An actuator (执行构件) and its phases, consecutive from ``phases[0].start``; named by
    the brief (name_zh, name_en) or by the program (name_msg, a catalogue message)."""

    key: str
    name_zh: str
    name_en: str
    phases: tuple[Phase, ...]
    name_msg: Msg | None = None

    @property
    def start(self) -> float:
        return self.phases[0].start

    def name(self, lang: str) -> str:
        if self.name_msg is not None:
            return self.name_msg.text(lang)
        return self.name_zh if lang == "zh" else self.name_en


@dataclass(frozen=True)
class PhaseRef:
    """Reference to one phase of an actuator: ``occurrence`` counts from 1 among the
    actuator's phases of that state (None: the state must occur once)."""

    actuator: str
    state: str
    occurrence: int | None = None

    def __str__(self) -> str:
        occ = "" if self.occurrence is None else f"#{self.occurrence}"
        return f"{self.actuator}.{self.state}{occ}"


@dataclass(frozen=True)
class Constraint:
    """A timing requirement between two phases.

    * ``before``: phase ``a`` ends at least ``margin`` before phase ``b`` starts, both read
      in the diagram's window [origin, origin + 2π);
    * ``during``: phase ``a`` lies inside phase ``b`` with ``margin`` to spare at both ends.

    ``a`` and ``b`` are :class:`PhaseRef` or tuples (actuator key, state[, occurrence]);
    ``margin`` [rad]; the texts describe the requirement in the report.
    """

    kind: str
    a: PhaseRef
    b: PhaseRef
    margin: float = 0.0
    text_zh: str = ""
    text_en: str = ""

    def __post_init__(self):
        if self.kind not in ("before", "during"):
            raise CycleError(N_("constraint kind {kind!r} is not 'before' or 'during'"),
                             kind=self.kind)
        object.__setattr__(self, "a", _ref(self.a))
        object.__setattr__(self, "b", _ref(self.b))
        if not np.isfinite(self.margin):
            raise CycleError(N_("constraint {a} {kind} {b}: the margin must be finite"), a=self.a,
                             kind=self.kind, b=self.b)

    def text(self, lang: str) -> str:
        return self.text_zh if lang == "zh" else self.text_en


class ConstraintCheck(NamedTuple):
    """Result of one constraint: ``slack`` [rad] ≥ 0 when met (how much timing may shift
    before it fails), < 0 when not met (how far it misses)."""

    constraint: Constraint
    ok: bool
    slack: float


@dataclass(frozen=True)
class CycleDiagram:
    """The motion cycle diagram: actuators, shaft speed ω [rad/s], the angle where the
    diagram starts [rad] and the timing constraints."""

    actuators: tuple[Actuator, ...]
    shaft_speed: float
    origin: float = 0.0
    constraints: tuple[Constraint, ...] = ()

    @property
    def period(self) -> float:
        """Cycle time T = 2π/ω [s]."""
        return TWO_PI / self.shaft_speed

    @property
    def speed_rpm(self) -> float:
        return self.shaft_speed * 60.0 / TWO_PI

    def actuator(self, key: str) -> Actuator:
        for act in self.actuators:
            if act.key == key:
                return act
        raise CycleError(N_("no actuator {key!r}; the diagram has: {keys}"), key=key,
                         keys=', '.join(a.key for a in self.actuators))

    def duration(self, angle) -> np.ndarray | float:
        """Time the shaft takes to turn through ``angle`` [rad] → [s]."""
        t = np.asarray(angle, dtype=float) / self.shaft_speed
        return t if np.ndim(angle) else float(t)

    def time_at(self, angle) -> np.ndarray | float:
        """Time since the diagram's start (φ = origin) when the shaft is at ``angle`` [s]."""
        t = np.mod(np.asarray(angle, dtype=float) - self.origin, TWO_PI) / self.shaft_speed
        return t if np.ndim(angle) else float(t)

    def phase_times(self, key: str) -> list[tuple[Phase, float, float]]:
        """Per phase of actuator ``key``: (phase, start time since the diagram's start [s],
        duration [s])."""
        return [(ph, float(self.time_at(ph.start)), ph.span / self.shaft_speed)
                for ph in self.actuator(key).phases]


# --------------------------------------------------------------------------- building


def _ref(ref) -> PhaseRef:
    if isinstance(ref, PhaseRef):
        return ref
    if isinstance(ref, (tuple, list)) and len(ref) in (2, 3):
        return PhaseRef(*ref)
    raise CycleError(N_("a phase reference is (actuator, state[, occurrence]), not {ref!r}"),
                     ref=ref)


def make_actuator(key: str, name_zh: str, name_en: str, start: float,
                  phases: Iterable, tol: float = COVER_TOL) -> Actuator:
    """An actuator whose ``phases`` follow each other from shaft angle ``start`` [rad].

    ``phases``: items (state, span[, label_zh[, label_en]]) or :class:`Phase` (only its
    state, span and labels are used). The spans [rad] must add up to 2π within ``tol``;
    they are then scaled to exactly 2π (degrees converted to radians add up to 2π only
    within rounding). A name the program gives (not the brief) is a catalogue message
    (:class:`~mechdesign.i18n.Msg`) in place of ``name_zh`` (``name_en`` then empty), of
    a phase's ``label_zh`` (no ``label_en``).
    """
    msg = None
    if isinstance(name_zh, Msg):
        msg, name_zh, name_en = name_zh, "", ""
    items, msgs = [], []
    for i, ph in enumerate(phases):
        if isinstance(ph, Phase):
            state, span, lzh, len_ = ph.state, ph.span, ph.label_zh, ph.label_en
            lmsg = ph.label_msg
        else:
            ph = tuple(ph)
            if not 2 <= len(ph) <= 4:
                raise CycleError(N_("actuator {key!r}, phase {i}: give (state, span[, "
                                    "label_zh, label_en]), not {ph!r}"),
                                 key=key, i=i + 1, ph=ph)
            state, span = ph[0], ph[1]
            lzh = ph[2] if len(ph) > 2 else ""
            len_ = ph[3] if len(ph) > 3 else ""
            lmsg = None
            if isinstance(lzh, Msg):
                lmsg, lzh, len_ = lzh, "", ""
        if state not in STATES:
            raise CycleError(N_("actuator {key!r}, phase {i}: state {state!r} is not one of "
                                "{states}"), key=key, i=i + 1,
                             state=state, states=', '.join(STATES))
        span = float(span)
        if not (np.isfinite(span) and span > 0):
            raise CycleError(N_("actuator {key!r}, phase {i}: its span must be positive, not "
                                "{span_deg:g}°"), key=key, i=i + 1,
                             span_deg=np.degrees(span))
        items.append((state, span, lzh, len_))
        msgs.append(lmsg)
    if not items:
        raise CycleError(N_("actuator {key!r} has no phases"), key=key)
    total = sum(s for _, s, _, _ in items)
    if abs(total - TWO_PI) > tol:
        raise CycleError(N_("actuator {key!r} ({name_en}): the phase spans add up to "
                            "{total_deg:.6g}°; they must cover exactly 360°"),
                         key=key, name_en=msg or name_en, total_deg=np.degrees(total),
                         name=msg or name_zh or name_en)
    scale = TWO_PI / total
    out, at = [], float(np.mod(start, TWO_PI))
    for (state, span, lzh, len_), lmsg in zip(items, msgs):
        out.append(Phase(state, float(np.mod(at, TWO_PI)), span * scale, lzh, len_, lmsg))
        at += span * scale
    return Actuator(key, name_zh, name_en, tuple(out), msg)


def build_cycle(actuators: Sequence, shaft_speed: float, origin: float = 0.0,
                constraints: Sequence = ()) -> CycleDiagram:
    """Check and assemble a cycle diagram.

    ``actuators``: :class:`Actuator` or tuples (key, name_zh, name_en, start [rad], phases)
    as for :func:`make_actuator`; ``shaft_speed`` ω [rad/s] of the distribution shaft;
    ``constraints``: :class:`Constraint` whose phase references must exist.
    """
    if not (np.isfinite(shaft_speed) and shaft_speed > 0):
        raise CycleError(N_("the shaft speed must be positive, not {shaft_speed!r} rad/s"),
                         shaft_speed=shaft_speed)
    acts = []
    for item in actuators:
        acts.append(item if isinstance(item, Actuator) else make_actuator(*item))
    if not acts:
        raise CycleError(N_("a cycle diagram needs at least one actuator"))
    keys = [a.key for a in acts]
    dup = sorted({k for k in keys if keys.count(k) > 1})
    if dup:
        raise CycleError(N_("actuator key(s) {keys} appear more than once"),
                         keys=', '.join(map(repr, dup)))
    cycle = CycleDiagram(tuple(acts), float(shaft_speed), float(np.mod(origin, TWO_PI)), ())
    cons = tuple(constraints)
    for c in cons:
        if not isinstance(c, Constraint):
            raise CycleError(N_("not a Constraint: {c!r}"), c=c)
        resolve(cycle, c.a)
        resolve(cycle, c.b)
    return CycleDiagram(cycle.actuators, cycle.shaft_speed, cycle.origin, cons)


# --------------------------------------------------------------------------- queries


def phase_index(actuator: Actuator, angles) -> np.ndarray:
    """Index of the phase the actuator is in at shaft angles ``angles`` [rad] (vectorised;
    a boundary angle belongs to the phase that starts there)."""
    spans = np.array([p.span for p in actuator.phases])
    rel_starts = np.concatenate([[0.0], np.cumsum(spans)[:-1]])
    rel = np.mod(np.asarray(angles, dtype=float) - actuator.start + BOUNDARY_TOL, TWO_PI)
    return np.clip(np.searchsorted(rel_starts, rel, side="right") - 1, 0, len(spans) - 1)


def state_at(actuator: Actuator, angles) -> np.ndarray:
    """The actuator's state (strings of :data:`STATES`) at shaft angles ``angles`` [rad]."""
    states = np.array([p.state for p in actuator.phases])
    return states[phase_index(actuator, angles)]


def moving_at(actuator: Actuator, angles) -> np.ndarray:
    """True where the actuator moves (a motion state), False where it rests."""
    moving = np.array([p.moving for p in actuator.phases])
    return moving[phase_index(actuator, angles)]


def intervals_of(actuator: Actuator, state: str) -> list[Phase]:
    """All phases of ``state`` in order."""
    return [p for p in actuator.phases if p.state == state]


def interval_of(actuator: Actuator, state: str, occurrence: int | None = None) -> Phase:
    """The phase of ``state`` (its start, span and end in rad); ``occurrence`` (from 1)
    picks one when the state occurs more than once."""
    found = intervals_of(actuator, state)
    have = ", ".join(p.state for p in actuator.phases)
    if not found:
        raise CycleError(N_("actuator {key!r} has no {state!r} phase; its phases: {have}"),
                         key=actuator.key, state=state, have=have)
    if occurrence is None:
        if len(found) > 1:
            raise CycleError(N_("actuator {key!r} has {n_found} {state!r} phases; say which "
                                "(occurrence 1 … {n_found})"),
                             key=actuator.key, n_found=len(found), state=state)
        return found[0]
    if not 1 <= occurrence <= len(found):
        raise CycleError(N_("actuator {key!r} has {n_found} {state!r} phase(s); occurrence "
                            "{occurrence} does not exist"),
                         key=actuator.key, n_found=len(found), state=state, occurrence=occurrence)
    return found[occurrence - 1]


def resolve(cycle: CycleDiagram, ref) -> Phase:
    """The phase a :class:`PhaseRef` (or tuple) points to."""
    ref = _ref(ref)
    return interval_of(cycle.actuator(ref.actuator), ref.state, ref.occurrence)


# --------------------------------------------------------------------------- constraints


def _window(cycle: CycleDiagram, angle: float) -> float:
    """Position of ``angle`` in the diagram's window [0, 2π) measured from the origin."""
    rel = float(np.mod(angle - cycle.origin + BOUNDARY_TOL, TWO_PI)) - BOUNDARY_TOL
    return max(rel, 0.0)


def constraint_slack(cycle: CycleDiagram, c: Constraint) -> float:
    """Slack of one constraint [rad] (≥ 0: met).

    before: slack = w(b.start) − (w(a.start) + a.span) − margin, with w the position in the
    diagram's window from the origin; a phase running through the origin is not before
    anything in the window.
    during: with r = (a.start − b.start) mod 2π, taken as r or r − 2π whichever fits better,
    slack = min(r, b.span − r − a.span) − margin.
    """
    pa, pb = resolve(cycle, c.a), resolve(cycle, c.b)
    if c.kind == "before":
        return _window(cycle, pb.start) - (_window(cycle, pa.start) + pa.span) - c.margin
    r = float(np.mod(pa.start - pb.start, TWO_PI))
    fits = [min(x, pb.span - x - pa.span) for x in (r, r - TWO_PI)]
    return max(fits) - c.margin


def check_constraints(cycle: CycleDiagram, constraints: Sequence[Constraint] | None = None,
                      tol: float = BOUNDARY_TOL) -> list[ConstraintCheck]:
    """(constraint, ok, slack [rad]) for each constraint (default: the diagram's own)."""
    cons = cycle.constraints if constraints is None else tuple(constraints)
    out = []
    for c in cons:
        slack = constraint_slack(cycle, c)
        out.append(ConstraintCheck(c, bool(slack >= -tol), float(slack)))
    return out


# --------------------------------------------------------------------------- cams


def actuator_from_cam_programme(key: str, name_zh: str, name_en: str, programme,
                                start: float = 0.0) -> Actuator:
    """The cycle-diagram actuator that a disc cam produces.

    ``programme``: a :class:`mechdesign.core.cam.Programme`, a list of
    :class:`mechdesign.core.cam.Segment`, or (kind, span [rad]) pairs with kinds rise /
    dwell / return, in order from cam angle δ = 0 (the follower's lowest position).
    ``start`` is the shaft angle at which δ = 0 (the cam is keyed to the shaft so that its
    programme begins there; it turns once per cycle). Rises and returns keep their names;
    a dwell at the lowest level becomes ``dwell_low``, at the stroke ``dwell_high``,
    anywhere else ``dwell``.
    """
    from .cam import DWELL as CAM_DWELL, Programme, Segment

    if isinstance(programme, Programme):
        prog = programme
    else:
        segs = []
        for item in programme:
            if isinstance(item, Segment):
                segs.append(item)
            else:
                kind, span = item[0], float(item[1])
                segs.append(Segment(kind, span, None if kind == CAM_DWELL else "poly345"))
        total = sum(s.span for s in segs)
        if abs(total - TWO_PI) > COVER_TOL:
            raise CycleError(N_("actuator {key!r}: the cam programme covers {total_deg:.6g}°, "
                                "not 360°"), key=key,
                             total_deg=np.degrees(total))
        segs = [Segment(s.kind, s.span * TWO_PI / total, s.law, s.lift) for s in segs]
        prog = Programme(segs, _stroke_of(segs))
    phases = []
    for seg, level in zip(prog.segments, prog.levels):
        if seg.kind == CAM_DWELL:
            if level <= 1e-9 * prog.stroke:
                state = DWELL_LOW
            elif abs(level - prog.stroke) <= 1e-9 * prog.stroke:
                state = DWELL_HIGH
            else:
                state = DWELL
        else:
            state = seg.kind
        phases.append((state, seg.span))
    return make_actuator(key, name_zh, name_en, start, phases)


def _stroke_of(segs) -> float:
    """The stroke of segments without one: the highest level their lifts reach when every
    rise has a lift, else the largest lift given (a rise without one rises by the stroke)."""
    rises = [s for s in segs if s.kind == "rise"]
    if rises and all(s.lift is not None for s in rises):
        level, top = 0.0, 0.0
        for s in segs:
            if s.kind == "rise":
                level += s.lift
            elif s.kind == "return":
                level = 0.0 if s.lift is None else level - s.lift
            top = max(top, level)
        return top
    return max((s.lift for s in segs if s.lift is not None), default=1.0)


def timing_disagreement(a: Actuator, b: Actuator, by: str = "state") -> float:
    """Total shaft angle [rad] over which two actuators are in different states (0: the
    same timing). ``by="motion"`` compares only moving against resting, so that e.g. a
    ``dwell`` matches a ``dwell_low``, and a ``move`` a ``rise``."""
    if by not in ("state", "motion"):
        raise CycleError(N_("compare by 'state' or 'motion', not {by!r}"), by=by)
    cuts = np.sort(np.mod(np.array([p.start for p in a.phases + b.phases]), TWO_PI))
    cuts = np.concatenate([cuts, [cuts[0] + TWO_PI]])
    arcs = np.diff(cuts)
    keep = arcs > 2 * BOUNDARY_TOL
    mids = (cuts[:-1] + 0.5 * arcs)[keep]
    if by == "state":
        differ = state_at(a, mids) != state_at(b, mids)
    else:
        differ = moving_at(a, mids) != moving_at(b, mids)
    return float(np.sum(arcs[keep][differ]))


# --------------------------------------------------------------------------- results.json


@dataclass(frozen=True)
class PhaseDoc:
    """One phase of an actuator in ``results.json``."""

    state: str = q("", "rise, dwell_high, return, dwell_low (a reciprocating output); move, dwell; "
                   "work, clear (windows of an output that never stops: near its working end, "
                   "clear of it)")
    start: float = q("rad", "shaft angle φ where the phase begins, in [0, 2π)")
    span: float = q("rad", "shaft angle Δφ the phase lasts")
    duration: float = q("s", "Δφ/ω")
    label_zh: str = q("", "label shown instead of the state's name (zh), or empty")
    label_en: str = q("", "the same in English")
    label: dict | None = q("", "the label when the program gives it: a catalogue message {msgid, "
                           "context}, translated where shown (null: label_zh/label_en)", default=None)


@dataclass(frozen=True)
class ActuatorDoc:
    """An actuator (执行构件) of the cycle diagram and its consecutive phases."""

    key: str = q("", "the actuator's key")
    name_zh: str = q("", "its name (zh)")
    name_en: str = q("", "its name (en)")
    phases: tuple[PhaseDoc, ...] = q("", "consecutive phases covering one revolution")
    name: dict | None = q("", "its name when the program gives it (not the brief): a catalogue "
                          "message {msgid, context}, translated where shown (null: name_zh/name_en)",
                          default=None)


@dataclass(frozen=True)
class ConstraintDoc:
    """A timing requirement between two phases and whether the diagram meets it."""

    kind: str = q("", "'before' (a ends ≥ margin before b starts) or 'during' (a inside b)")
    a: str = q("", "phase a as actuator.state[#occurrence]")
    b: str = q("", "phase b, the same way")
    margin: float = q("rad", "required margin")
    ok: bool = q("", "met")
    slack: float = q("rad", "≥ 0: how far the timing may shift before it fails; < 0: the miss")


@dataclass(frozen=True)
class CycleDocument:
    """The motion cycle diagram (运动循环图) in ``results.json`` (SI: rad, s)."""

    shaft_speed: float = q("rad/s", "ω of the distribution shaft")
    period: float = q("s", "cycle time T = 2π/ω")
    origin: float = q("rad", "shaft angle where the diagram starts")
    actuators: tuple[ActuatorDoc, ...] = q("", "the actuators and their phases")
    constraints: tuple[ConstraintDoc, ...] = q("", "the timing requirements checked")


def _msg_data(msg: Msg | None) -> dict | None:
    """A name the program gives, as results.json holds it: {msgid, context}."""
    return None if msg is None else {"msgid": msg.msgid, "context": msg.context}


def cycle_document(cycle: CycleDiagram, checks: Sequence[ConstraintCheck] | None = None,
                   cls: type = CycleDocument, **extra) -> CycleDocument:
    """The cycle diagram for ``results.json`` (SI: rad, s). A machine that adds its own
    fields passes a subclass of :class:`CycleDocument` as ``cls`` and their values."""
    checks = check_constraints(cycle) if checks is None else checks
    return cls(
        shaft_speed=cycle.shaft_speed, period=cycle.period, origin=cycle.origin,
        actuators=tuple(ActuatorDoc(a.key, a.name_zh, a.name_en, tuple(
            PhaseDoc(p.state, p.start, p.span, p.span / cycle.shaft_speed, p.label_zh,
                     p.label_en, _msg_data(p.label_msg)) for p in a.phases), _msg_data(a.name_msg))
            for a in cycle.actuators),
        constraints=tuple(ConstraintDoc(c.constraint.kind, str(c.constraint.a),
                                        str(c.constraint.b), c.constraint.margin, c.ok, c.slack)
                          for c in checks),
        **extra)
