"""Brief sections shared by machines with a motion scheme (运动方案设计): the motion cycle
diagram (``cycle:``), the morphological matrix (``morphology:``) and the incomplete gear
intermittent drive (``incomplete_gear:``).

A machine brief embeds them as fields, e.g. ``cycle: CycleSection``; the converters turn a
validated section into the core's objects in SI units, once:

* :func:`cycle_to_si` → :class:`mechdesign.core.cycle.CycleDiagram`
* :func:`morphology_to_si` → :class:`Morphology`
* :func:`incomplete_gear_to_si` → :class:`mechdesign.core.intermittent.IncompleteGear`

The closed-form checks that could make a conversion fail run in the validators, so a brief
that loads always converts, and a problem is reported as a brief problem naming the field.
"""
from __future__ import annotations

import math

from dataclasses import dataclass
from math import prod
from typing import ClassVar, Literal, Optional

from ..lazy import np
from pydantic import Field, model_validator

from .common import MISSING, Msg, Problems, StrictModel
from ..i18n import N_

StateName = Literal["rise", "dwell_high", "return", "dwell_low", "move", "dwell", "work", "clear"]
_KEY = r"^[a-z][a-z0-9_]*$"


# --------------------------------------------------------------------------- cycle diagram


class CyclePhase(StrictModel):
    """One phase of an actuator in the cycle diagram."""

    state: StateName = Field(description=(
        "rise (推程), dwell_high (远停歇), return (回程), dwell_low (近停歇) for a reciprocating "
        "output; move (运动) or dwell (停歇) for one that advances one way (a chain, a table); "
        "work (工作区运动, moving, work zone) or clear (让开区运动, moving, clear zone) for one "
        "that never stops (a crank-driven platen): near its working end, and clear of it"))
    span_deg: float = Field(gt=0, le=360, description="Main-shaft angle the phase lasts [°]")
    label_zh: str = Field("", max_length=30, description="Chinese label shown instead of the state name, e.g. 扳弯")
    label_en: str = Field("", max_length=40, description="English label shown instead of the state name")


class CycleActuator(StrictModel):
    """An actuator (执行构件) and its phases, one after another from ``start_deg``."""

    key: str = Field(pattern=_KEY, max_length=30,
                     description="Short name used by the constraints, e.g. pin (lower-case letters, digits, _)")
    name_zh: str = Field(min_length=1, max_length=30, description="Chinese name, e.g. 定位销")
    name_en: str = Field(min_length=1, max_length=60, description="English name, e.g. positioning pin")
    start_deg: float = Field(0.0, ge=0, lt=360,
                             description="Main-shaft angle where the first phase begins [°]")
    phases: list[CyclePhase] = Field(min_length=1, max_length=24, description=(
        "Phases in order; their spans must add up to 360°"))

    @model_validator(mode="after")
    def _covers_360(self):
        out = Problems(self)
        total = sum(p.span_deg for p in self.phases)
        if abs(total - 360.0) > 1e-6:
            last = self.phases[-1].span_deg
            fix = last + 360.0 - total
            hint = (Msg(N_("e.g. make the last phase {fix:g}° instead of {last:g}°"), fix=fix, last=last)
                    if fix > 0 else
                    Msg(N_("shorten the phases by {excess:g}° in all"), excess=total - 360.0))
            out.add(("phases", len(self.phases) - 1, "span_deg"), last,
                    N_("actuator '{key}': the phase spans add up to {total:g}°; they must add up "
                       "to 360°: {hint}"), key=self.key, total=total, hint=hint)
        out.raise_any()
        return self


class CycleRef(StrictModel):
    """A phase of an actuator, named by the actuator's key and the state."""

    actuator: str = Field(pattern=_KEY, max_length=30, description="Key of the actuator")
    state: StateName = Field(description="State of the phase")
    occurrence: Optional[int] = Field(None, ge=1, le=24, description=(
        "Which phase of that state, counting from 1, when the actuator has several"))


class CycleConstraint(StrictModel):
    """A timing requirement between two actuators' phases, checked with its slack."""

    kind: Literal["before", "during"] = Field(description=(
        "before: phase a ends at least margin_deg before phase b starts (read in the diagram "
        "from origin_deg); during: phase a lies inside phase b with margin_deg to spare at both ends"))
    a: CycleRef
    b: CycleRef
    margin_deg: float = Field(0.0, ge=0, le=180, description="Required margin [°]")
    text_zh: str = Field("", max_length=80, description="The requirement in words (Chinese)")
    text_en: str = Field("", max_length=120, description="The requirement in words (English)")


class CycleSection(StrictModel):
    """Motion cycle diagram (运动循环图) of the actuators against the main-shaft angle."""

    shaft_speed_rpm: Optional[float] = Field(None, gt=0, le=100000, description=(
        "Speed of the main (distribution) shaft, one cycle per turn [rpm]; default: the "
        "machine's main-shaft speed"))
    origin_deg: float = Field(0.0, ge=0, lt=360, description=(
        "Main-shaft angle where the diagram starts (the start of the working cycle) [°]"))
    actuators: list[CycleActuator] = Field(min_length=1, max_length=12)
    constraints: list[CycleConstraint] = Field(default_factory=list, max_length=40)

    @model_validator(mode="after")
    def _references(self):
        out = Problems(self)
        keys = [a.key for a in self.actuators]
        for i, key in enumerate(keys):
            if key in keys[:i]:
                out.add(("actuators", i, "key"), key,
                        N_("actuator key '{key}' appears more than once (also "
                           "actuators.{v1}.key): give each actuator its own key"),
                        key=key, v1=keys.index(key))
        by_key = {a.key: a for a in self.actuators}
        known = ", ".join(by_key)
        for i, c in enumerate(self.constraints):
            for side in ("a", "b"):
                ref = getattr(c, side)
                where = ("constraints", i, side)
                act = by_key.get(ref.actuator)
                if act is None:
                    out.add(where + ("actuator",), ref.actuator,
                            N_("no actuator '{actuator}'; actuators: {known}"),
                            actuator=ref.actuator, known=known)
                    continue
                count = sum(p.state == ref.state for p in act.phases)
                have = ", ".join(p.state for p in act.phases)
                if count == 0:
                    out.add(where + ("state",), ref.state,
                            N_("actuator '{key}' has no '{state}' phase; its phases: {have}"),
                            key=act.key, state=ref.state, have=have)
                elif ref.occurrence is None and count > 1:
                    out.add(where + ("occurrence",), MISSING,
                            N_("actuator '{key}' has {count} '{state}' phases: say which one with "
                               "occurrence (1 … {count})"),
                            key=act.key, count=count, state=ref.state)
                elif ref.occurrence is not None and ref.occurrence > count:
                    out.add(where + ("occurrence",), ref.occurrence,
                            N_("actuator '{key}' has {count} '{state}' phase(s): occurrence is 1 "
                               "… {count}"), key=act.key, count=count, state=ref.state)
        out.raise_any()
        return self


def cycle_to_si(c: CycleSection, shaft_speed_rpm: float | None = None):
    """The section as a checked :class:`~mechdesign.core.cycle.CycleDiagram`;
    ``shaft_speed_rpm`` is the main-shaft speed the machine supplies when the section
    gives none."""
    from ..core.cycle import Constraint, PhaseRef, build_cycle, make_actuator

    rpm = c.shaft_speed_rpm if c.shaft_speed_rpm is not None else shaft_speed_rpm
    if rpm is None:
        raise ValueError("cycle.shaft_speed_rpm is needed: the machine supplies no main-shaft speed")
    acts = [make_actuator(a.key, a.name_zh, a.name_en, np.radians(a.start_deg),
                          [(p.state, np.radians(p.span_deg), p.label_zh, p.label_en)
                           for p in a.phases]) for a in c.actuators]
    cons = [Constraint(k.kind, PhaseRef(k.a.actuator, k.a.state, k.a.occurrence),
                       PhaseRef(k.b.actuator, k.b.state, k.b.occurrence),
                       np.radians(k.margin_deg), k.text_zh, k.text_en) for k in c.constraints]
    return build_cycle(acts, rpm * 2 * np.pi / 60, np.radians(c.origin_deg), cons)


# --------------------------------------------------------------------------- morphology


class MorphOption(StrictModel):
    """One candidate mechanism for a function."""

    name_zh: str = Field(min_length=1, max_length=40, description="Chinese name, e.g. 凸轮机构")
    name_en: str = Field(min_length=1, max_length=60, description="English name, e.g. cam mechanism")


class MorphFunction(StrictModel):
    """A sub-function (分功能) with its candidate mechanisms and the one chosen."""

    name_zh: str = Field(min_length=1, max_length=40, description="Chinese name, e.g. 定位夹紧")
    name_en: str = Field(min_length=1, max_length=60, description="English name, e.g. positioning and clamping")
    options: list[MorphOption] = Field(min_length=1, max_length=9)
    chosen: int = Field(ge=1, description="Number of the chosen option, counting from 1")

    @model_validator(mode="after")
    def _chosen_exists(self):
        out = Problems(self)
        n = len(self.options)
        if self.chosen > n:
            out.add("chosen", self.chosen,
                    N_("function '{name_en}': chosen = {chosen}, but it has only {n} option(s): "
                       "chosen is 1 … {n}"),
                    name_en=self.name_en, chosen=self.chosen, n=n, name_zh=self.name_zh)
        out.raise_any()
        return self


class MorphologySection(StrictModel):
    """Morphological matrix (形态学矩阵) of the functions and the candidate mechanisms."""

    functions: list[MorphFunction] = Field(min_length=1, max_length=12)
    reasons_zh: str = Field("", max_length=2000, description="Why the chosen scheme (Chinese)")
    reasons_en: str = Field("", max_length=3000, description="Why the chosen scheme (English)")


@dataclass(frozen=True)
class MorphFunctionData:
    name_zh: str
    name_en: str
    options: tuple[tuple[str, str], ...]   # (zh, en)
    chosen: int                            # index from 0


@dataclass(frozen=True)
class Morphology:
    """A morphological matrix: the number of schemes is the product of the option counts."""

    functions: tuple[MorphFunctionData, ...]
    reasons_zh: str = ""
    reasons_en: str = ""

    @property
    def counts(self) -> tuple[int, ...]:
        return tuple(len(f.options) for f in self.functions)

    @property
    def scheme_count(self) -> int:
        """N = Π k_i (k_i options for function i)."""
        return prod(self.counts)

    @property
    def chosen(self) -> tuple[int, ...]:
        """Index (from 0) of the chosen option of each function."""
        return tuple(f.chosen for f in self.functions)


def morphology_to_si(m: MorphologySection) -> Morphology:
    return Morphology(tuple(MorphFunctionData(f.name_zh, f.name_en,
                                              tuple((o.name_zh, o.name_en) for o in f.options),
                                              f.chosen - 1) for f in m.functions),
                      m.reasons_zh, m.reasons_en)


# --------------------------------------------------------------------------- incomplete gear


class IncompleteGearSection(StrictModel):
    """Incomplete gear (不完全齿轮) intermittent drive, designed from the timing.

    The driver turns once per cycle with the main shaft; its teeth advance the driven wheel
    (and a chain sprocket on it), its locking arc holds the driven wheel during the dwell.
    Give the module and enough of z1, z2, z1', the motion span and the advance (or feed) to
    fix whole teeth; every timing value given must be met within timing_tolerance_deg."""

    module_mm: float = Field(gt=0, le=50, description="Module m [mm]")
    driver_teeth_full: Optional[int] = Field(None, ge=3, le=1000, description=(
        "z1: teeth the driver would have if complete [count]; default: from teeth_present and "
        "motion_span_deg"))
    driven_teeth: Optional[int] = Field(None, ge=3, le=1000, description=(
        "z2: teeth of the (complete) driven wheel [count]; default: from teeth_present and the advance"))
    teeth_present: Optional[int] = Field(None, ge=1, le=999, description=(
        "z1': teeth actually cut on the driver [count]; default: from the timing"))
    motion_span_deg: Optional[float] = Field(None, gt=0, lt=360, description=(
        "Main-shaft angle during which the driven wheel moves (the driver's toothed arc) [°]"))
    advance_deg: Optional[float] = Field(None, gt=0, le=3600, description=(
        "Angle the driven wheel must turn per cycle [°]"))
    feed_mm: Optional[float] = Field(None, gt=0, le=10000, description=(
        "Chain (or belt) travel per cycle through the sprocket on the driven wheel [mm]; "
        "instead of advance_deg"))
    sprocket_pitch_radius_mm: Optional[float] = Field(None, gt=0, le=5000, description=(
        "Pitch radius of the sprocket on the driven wheel's shaft [mm]"))
    motion_start_deg: float = Field(0.0, ge=0, lt=360, description=(
        "Main-shaft angle where the driver's first tooth starts meshing [°]"))
    timing_tolerance_deg: float = Field(0.01, ge=0, le=5, description=(
        "Largest accepted difference between a required timing angle and the one whole teeth give [°]"))
    pressure_angle_deg: float = Field(20.0, gt=0, lt=45, description="Pressure angle α [°]")
    addendum_coefficient: float = Field(1.0, gt=0, le=2, description="Addendum coefficient h_a* [–]")
    clearance_coefficient: float = Field(0.25, ge=0, le=1, description="Clearance coefficient c* [–]")

    @model_validator(mode="after")
    def _timing_can_be_met(self):
        out = Problems(self)
        if self.feed_mm is not None and self.advance_deg is not None:
            out.add("feed_mm", self.feed_mm,
                    N_("the advance is already given as advance_deg: give it either as "
                       "advance_deg or as feed_mm, not both"))
        if self.feed_mm is not None and self.sprocket_pitch_radius_mm is None:
            out.add("sprocket_pitch_radius_mm", MISSING,
                    N_("feed_mm needs sprocket_pitch_radius_mm: the sprocket's pitch radius turns "
                       "the feed into the driven wheel's advance"))
        if not out.items:
            from ..core.intermittent import IntermittentDesignError

            try:
                _design(self, None)
            except IntermittentDesignError as exc:
                name = self._FIELDS.get(exc.field or "", "teeth_present")
                if exc.field == "advance" and self.feed_mm is not None:
                    name = "feed_mm"
                value = getattr(self, name)
                out.add(name, MISSING if value is None else value,
                        N_("{en} (z1 = driver_teeth_full, z2 = driven_teeth, z1' = teeth_present)"),
                        en=exc.en, v1=exc.zh or exc.en)
        out.raise_any()
        return self

    #: IntermittentDesignError.field → the brief field to change
    _FIELDS: ClassVar[dict[str, str]] = {
        "module": "module_mm", "z1": "driver_teeth_full", "z2": "driven_teeth",
        "teeth": "teeth_present", "motion_span": "motion_span_deg", "advance": "advance_deg",
        "feed": "feed_mm", "sprocket_radius": "sprocket_pitch_radius_mm"}


def _design(s: IncompleteGearSection, shaft_speed_rpm: float | None):
    from ..core.intermittent import design_incomplete_gear

    mm = 1e-3
    rad = math.radians
    return design_incomplete_gear(
        s.module_mm * mm, s.driver_teeth_full, s.driven_teeth, teeth=s.teeth_present,
        motion_span=None if s.motion_span_deg is None else rad(s.motion_span_deg),
        advance=None if s.advance_deg is None else rad(s.advance_deg),
        feed=None if s.feed_mm is None else s.feed_mm * mm,
        sprocket_radius=None if s.sprocket_pitch_radius_mm is None else s.sprocket_pitch_radius_mm * mm,
        motion_start=rad(s.motion_start_deg),
        driver_speed=None if shaft_speed_rpm is None else shaft_speed_rpm * 2 * math.pi / 60,
        tol=max(rad(s.timing_tolerance_deg), 1e-9), alpha=rad(s.pressure_angle_deg),
        ha_star=s.addendum_coefficient, c_star=s.clearance_coefficient)


def incomplete_gear_to_si(s: IncompleteGearSection, shaft_speed_rpm: float | None = None):
    """The designed :class:`~mechdesign.core.intermittent.IncompleteGear`; the driver turns
    with the main shaft at ``shaft_speed_rpm`` (None: motion per radian of driver angle)."""
    return _design(s, shaft_speed_rpm)
