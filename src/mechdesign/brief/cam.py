"""Cam briefs: the cam section (凸轮机构) any machine brief may carry, the stand-alone cam
design brief (``machine: cam``) and the analysis of a given eccentric disc
(``machine: eccentric_cam``).

Course units in the brief (mm, °, rpm); :func:`cam_to_si` converts once to the core's
objects in SI units (m, rad, rad/s).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Literal, Optional, Union

from ..lazy import np
from pydantic import Field, model_validator

from .common import MISSING, Msg, Problems, Shown, StrictModel
from ..i18n import N_

LawName = Literal["constant_velocity", "parabolic", "harmonic", "cycloidal", "poly345",
                  "poly4567", "modified_trapezoid", "modified_sine"]


class CamSegment(StrictModel):
    """One segment of the follower programme (推程 / 休止 / 回程)."""

    motion: Literal["rise", "dwell", "return"] = Field(
        description="rise (推程), dwell (休止) or return (回程)")
    angle_deg: float = Field(gt=0, le=360, description="Cam angle of the segment [°]")
    law: Optional[LawName] = Field(None, description="Motion law of a rise or return (not for a dwell)")
    lift_mm: Optional[float] = Field(None, gt=0, le=2000, description=(
        "Travel of a translating follower in this segment [mm]; default: the whole stroke for a "
        "rise, back to the start for a return"))
    lift_deg: Optional[float] = Field(None, gt=0, le=120, description=(
        "Swing of an oscillating follower in this segment [°]; default as lift_mm"))

    @model_validator(mode="after")
    def _law_only_for_motion(self):
        out = Problems(self)
        laws = ", ".join(LawName.__args__)
        if self.motion == "dwell" and self.law is not None:
            out.add("law", self.law, N_("a dwell has no motion law: remove `law` (or make the "
                                        "segment a rise or a return)"))
        for name in ("lift_mm", "lift_deg"):
            if self.motion == "dwell" and getattr(self, name) is not None:
                out.add(name, getattr(self, name), N_("a dwell has no lift: remove `{name}`"),
                                                   name=name)
        if self.motion != "dwell" and self.law is None:
            if self.motion == "rise":
                out.add("law", MISSING, N_("a rise needs `law` (its motion law): one of {laws}"),
                        laws=laws)
            else:
                out.add("law", MISSING, N_("a {motion} needs `law` (its motion law): one of {laws}"),
                        motion=self.motion, laws=laws)
        out.raise_any()
        return self


def _check_roller(out: Problems, contact: str, roller_radius_mm: float) -> None:
    """A roller follower has a roller (r_r > 0); a knife-edge or flat-faced one has none."""
    if contact == "roller" and not roller_radius_mm > 0:
        out.add("roller_radius_mm", roller_radius_mm if roller_radius_mm else MISSING,
                N_("a roller follower needs roller_radius_mm > 0 (or choose contact: knife)"))
    if contact != "roller" and roller_radius_mm:
        name = Msg.pgettext("follower contact", "knife") if contact == "knife" else \
            Msg.pgettext("follower contact", "flat-faced")
        out.add("roller_radius_mm", roller_radius_mm,
                N_("a {contact} follower has no roller: remove roller_radius_mm (or choose "
                   "contact: roller)"), contact=contact, name=name)


class CamFollower(StrictModel):
    """Follower (从动件): translating (直动) or oscillating (摆动); knife-edge, roller or flat-faced."""

    motion: Literal["translating", "oscillating"] = Field(description="translating (直动) or oscillating (摆动)")
    contact: Literal["knife", "roller", "flat"] = Field(
        description="knife (尖顶), roller (滚子) or flat (平底)")
    roller_radius_mm: float = Field(0.0, ge=0, le=1000, description="Roller radius r_r [mm] (roller only)")
    stroke_h_mm: Optional[float] = Field(None, gt=0, le=2000,
                                         description="Stroke h of a translating follower [mm]")
    offset_mm: Union[Annotated[float, Field(le=10000)], Literal["auto"]] = Field(0.0, description=(
        "Offset e of a translating follower's axis from the cam centre [mm], ≥ 0; 'auto' chooses "
        "the offset that allows the smallest base circle"))
    offset_side: Literal["right", "left"] = Field("right", description=(
        "Side of the cam centre the axis is on, seen with the follower above the cam moving up"))
    max_swing_deg: Optional[float] = Field(None, gt=0, le=120,
                                           description="Maximum swing φmax of an oscillating follower [°]")
    arm_length_mm: Optional[float] = Field(None, gt=0, le=10000,
                                           description="Oscillating follower: pivot to roller centre L [mm]")
    pivot_distance_mm: Optional[float] = Field(None, gt=0, le=10000,
                                               description="Oscillating follower: cam centre to pivot a [mm]")
    rise_sense: Literal["same", "opposite"] = Field("same", description=(
        "Oscillating follower: during the rise it turns the same way as the cam, or the opposite way"))

    @model_validator(mode="after")
    def _complete(self):
        out = Problems(self)
        _check_roller(out, self.contact, self.roller_radius_mm)
        if self.offset_mm != "auto" and self.offset_mm < 0:
            out.add("offset_mm", self.offset_mm,
                    N_("offset_mm must be ≥ 0 (a distance): write {v1:g} and give the side in "
                       "offset_side (now {offset_side})"),
                    v1=-self.offset_mm, offset_side=self.offset_side)
        oscillating_only = ("max_swing_deg", "arm_length_mm", "pivot_distance_mm")
        if self.motion == "translating":
            if self.stroke_h_mm is None:
                out.add("stroke_h_mm", MISSING, N_("a translating follower needs stroke_h_mm, its "
                                                   "stroke h [mm]"))
            for name in oscillating_only:
                if getattr(self, name) is not None:
                    out.add(name, getattr(self, name),
                            N_("{name} belongs to an oscillating follower: remove it (or set "
                               "motion: oscillating)"), name=name)
        else:
            needed = ["max_swing_deg", "pivot_distance_mm"] + (
                ["arm_length_mm"] if self.contact != "flat" else [])
            for name in needed:
                if getattr(self, name) is None:
                    out.add(name, MISSING, N_("an oscillating follower needs {name}"), name=name)
            if self.stroke_h_mm is not None:
                out.add("stroke_h_mm", self.stroke_h_mm,
                        N_("stroke_h_mm belongs to a translating follower: give the swing as "
                           "max_swing_deg instead"))
            if self.offset_mm not in (0.0, 0):
                out.add("offset_mm", self.offset_mm,
                        N_("offset_mm belongs to a translating follower: remove it (an "
                           "oscillating follower is placed by pivot_distance_mm)"))
        out.raise_any()
        return self


class CamLimits(StrictModel):
    """Allowed values (许用值) checked on the designed cam."""

    pressure_angle_rise_deg: Optional[float] = Field(None, gt=0, lt=90, description=(
        "Allowed pressure angle on rises [α] [°]; default 30 (translating) or 45 (oscillating)"))
    pressure_angle_return_deg: float = Field(70.0, gt=0, lt=90,
                                             description="Allowed pressure angle on returns [α'] [°]")
    min_actual_curvature_mm: float = Field(3.0, ge=0, le=1000, description=(
        "Smallest radius of curvature accepted on the convex actual profile ρa,min [mm]"))


class CamSection(StrictModel):
    """Cam mechanism (凸轮机构): follower, programme, base circle, limits."""

    rotation: Literal["cw", "ccw"] = Field("ccw", description=(
        "Cam sense of rotation: ccw (逆时针) or cw (顺时针); in a machine it turns with its shaft"))
    speed_rpm: Optional[float] = Field(None, gt=0, le=100000, description=(
        "Cam speed [rpm]; gives time derivatives (mm/s …); default: the crank speed in a machine "
        "brief, none (derivatives per radian) in a stand-alone cam brief"))
    base_radius_mm: Union[Annotated[float, Field(le=10000)], Literal["auto"]] = Field(description=(
        "Base radius r0 of the pitch curve (roller/knife) or of the profile (flat face) [mm]; "
        "'auto' designs the smallest one that keeps the pressure angle within the limits"))
    follower: CamFollower
    programme: list[CamSegment] = Field(min_length=2, max_length=32, description=(
        "Segments in order from δ = 0, covering 360° together; the follower starts at its lowest position"))
    limits: CamLimits = CamLimits()
    table_step_deg: float = Field(10.0, ge=0.5, le=90, description="Step of the profile coordinate table [°]")
    purpose_zh: str = Field("", max_length=300, description=(
        "What the cam does in its machine and when, in Chinese, e.g. 驱动润滑油泵的柱塞; shown at "
        "the head of the cam chapter of a zh report (an en report shows purpose_en, else this)"))
    purpose_en: str = Field("", max_length=400, description=(
        "The same in English, e.g. drives the plunger of the lubricating oil pump; shown in an en "
        "report (a zh report shows purpose_zh, else this)"))

    @model_validator(mode="after")
    def _programme_closes(self):
        out = Problems(self)
        if self.base_radius_mm != "auto" and not self.base_radius_mm > 0:
            out.add("base_radius_mm", self.base_radius_mm,
                    N_("base_radius_mm must be > 0, or 'auto' to design the smallest one"))
        total = sum(s.angle_deg for s in self.programme)
        if abs(total - 360.0) > 1e-6:
            last = self.programme[-1].angle_deg
            fix = last + 360.0 - total
            hint = (Msg(N_("e.g. make the last segment {fix:g}° instead of {last:g}°"), fix=fix, last=last)
                    if fix > 0 else
                    Msg(N_("shorten the segments by {excess:g}° in all"), excess=total - 360.0))
            out.add(("programme", len(self.programme) - 1, "angle_deg"), last,
                    N_("the programme's angles add up to {total:g}°; they must cover 360°: {hint}"),
                    total=total, hint=hint)
        osc = self.follower.motion == "oscillating"
        unit, wrong = ("lift_deg", "lift_mm") if osc else ("lift_mm", "lift_deg")
        kind = "an oscillating" if osc else "a translating"
        kind_name = Msg.pgettext("follower motion", "oscillating") if osc else \
            Msg.pgettext("follower motion", "translating")
        stroke_name = "follower.max_swing_deg" if osc else "follower.stroke_h_mm"
        stroke = self.follower.max_swing_deg if osc else self.follower.stroke_h_mm
        level, closes = 0.0, stroke is not None
        for i, seg in enumerate(self.programme):
            if getattr(seg, wrong) is not None:
                out.add(("programme", i, wrong), getattr(seg, wrong),
                        N_("{kind} follower's lift is given as {unit}, not {wrong}"),
                        kind=kind, unit=unit, wrong=wrong, kind_name=kind_name)
                closes = False
            if stroke is None or not closes:
                continue
            lift = getattr(seg, unit)
            before = level
            if seg.motion == "rise":
                level += stroke if lift is None else lift
            elif seg.motion == "return":
                level -= level if lift is None else lift
            room = stroke - before if seg.motion == "rise" else before
            if room <= 1e-9 * stroke and (level > stroke * (1 + 1e-9) or level < -1e-9 * stroke):
                if seg.motion == "rise":
                    out.add(("programme", i, "motion"), seg.motion,
                            N_("the follower is already at its stroke here: make this segment a "
                               "dwell or a return"))
                else:
                    out.add(("programme", i, "motion"), seg.motion,
                            N_("the follower is already at its lowest position here: make this "
                               "segment a dwell or a rise"))
                closes = False
            elif level > stroke * (1 + 1e-9):
                field = ("programme", i, unit if lift is not None else "motion")
                out.add(field, lift if lift is not None else seg.motion,
                        N_("the follower would reach {level:g}, above its stroke {stroke:g} "
                           "({stroke_name}): this rise may lift at most {room:g} (give {unit})"),
                        level=level, stroke=stroke, stroke_name=stroke_name, room=room, unit=unit)
                closes = False
            elif level < -1e-9 * stroke:
                out.add(("programme", i, unit), lift,
                        N_("the follower would reach {level:g}, below its lowest position 0: this "
                           "return's {unit} may be at most {room:g}"),
                        level=level, unit=unit, room=room)
                closes = False
        if closes and abs(level) > 1e-9 * stroke:
            returns = [i for i, s in enumerate(self.programme) if s.motion == "return"]
            lift = getattr(self.programme[returns[-1]], unit) if returns else None
            if lift is not None and returns[-1] > max(i for i, s in enumerate(self.programme)
                                                       if s.motion == "rise"):
                out.add(("programme", returns[-1], unit), lift,
                        N_("the programme ends at {level:g} instead of 0: the returns must undo "
                           "the rises; make this {unit} {v1:g} (or leave it out: back to 0)"),
                        level=level, unit=unit, v1=lift + level)
            else:
                n = len(self.programme) - 1
                out.add(("programme", n, "motion"), self.programme[n].motion,
                        N_("the programme ends at {level:g} instead of 0: the follower must come "
                           "back; add a return after the last rise"), level=level)
        if not any(s.motion == "rise" for s in self.programme):
            out.add("programme", Shown(", ".join(s.motion for s in self.programme)),
                    N_("the programme needs at least one rise"))
        out.raise_any()
        return self

    @model_validator(mode="after")
    def _roller_inside_base_circle(self):
        # issue 21: the actual base radius r0 − r_r must be positive, or the cam cannot be made
        fo, r0 = self.follower, self.base_radius_mm
        if fo.contact == "roller" and r0 != "auto" and not r0 - fo.roller_radius_mm > 0:
            out = Problems(self)
            out.add(("follower", "roller_radius_mm"), fo.roller_radius_mm,
                    N_("the roller radius r_r = {roller_radius_mm:g} mm is not smaller than the "
                       "base radius r0 = {r0:g} mm: the actual profile's base radius r0 − r_r = "
                       "{v1:g} mm ≤ 0 and the cam cannot be made; use a roller below {r0:g} mm "
                       "(typically r_r ≤ 0.4·r0 = {v2:g} mm) or a base radius above "
                       "{roller_radius_mm:g} mm"),
                    roller_radius_mm=fo.roller_radius_mm, r0=r0, v1=r0 - fo.roller_radius_mm, v2=0.4 * r0)
            out.raise_any()
        return self


# --------------------------------------------------------------------------- to SI


@dataclass(frozen=True)
class CamParams:
    """A cam section converted to SI and to the core's objects."""

    programme: object            # core.cam.Programme
    follower: object             # core.cam.TranslatingFollower | OscillatingFollower
    rotation: int                # +1 ccw, −1 cw
    omega: float | None          # cam speed [rad/s] or None
    speed_rpm: float | None
    base_radius: float | None    # [m]; None = design the smallest
    auto_offset: bool
    alpha_rise: float            # [rad]
    alpha_return: float          # [rad]
    min_actual_curvature: float  # [m]
    table_step: float            # [rad]
    oscillating: bool


def side_sign(side: str) -> int:
    return 1 if side == "right" else -1


def follower_phases_deg(c: CamSection) -> list[tuple[str, float]]:
    """The follower's phases from the cam's δ = 0, as a cycle diagram draws them: (state,
    span [°]) with the spans scaled to 360°; rises and returns keep their names, a dwell at
    the lowest level is ``dwell_low``, at the stroke ``dwell_high``, anywhere else ``dwell``
    (the states of :mod:`mechdesign.core.cycle`; the levels follow
    :class:`mechdesign.core.cam.Programme`). Plain arithmetic: validation needs no numpy."""
    osc = c.follower.motion == "oscillating"
    stroke = c.follower.max_swing_deg if osc else c.follower.stroke_h_mm
    total = sum(seg.angle_deg for seg in c.programme)
    out, level = [], 0.0
    for seg in c.programme:
        lift = seg.lift_deg if osc else seg.lift_mm
        span = seg.angle_deg * 360.0 / total
        if seg.motion == "dwell":
            if level <= 1e-9 * stroke:
                state = "dwell_low"
            elif abs(level - stroke) <= 1e-9 * stroke:
                state = "dwell_high"
            else:
                state = "dwell"
        else:
            state = seg.motion
            if seg.motion == "rise":
                level += stroke if lift is None else lift
            else:
                level -= level if lift is None else lift
        out.append((state, span))
    return out


def cam_to_si(c: CamSection, speed_rpm: float | None = None) -> CamParams:
    """Convert a cam section; ``speed_rpm`` is the shaft speed a machine supplies."""
    from ..core.cam import OscillatingFollower, Programme, Segment, TranslatingFollower

    mm = 1e-3
    fo = c.follower
    osc = fo.motion == "oscillating"
    rpm = c.speed_rpm if c.speed_rpm is not None else speed_rpm
    segments = []
    for seg in c.programme:
        lift = seg.lift_deg if osc else seg.lift_mm
        lift = None if lift is None else (np.radians(lift) if osc else lift * mm)
        segments.append(Segment(seg.motion, np.radians(seg.angle_deg), seg.law, lift))
    stroke = np.radians(fo.max_swing_deg) if osc else fo.stroke_h_mm * mm
    # Angles in degrees summing to 360 become radians summing to 2π within rounding.
    scale = 2 * np.pi / sum(s.span for s in segments)
    segments = [Segment(s.kind, s.span * scale, s.law, s.lift) for s in segments]
    programme = Programme(segments, stroke)
    rr = fo.roller_radius_mm * mm
    auto_offset = fo.offset_mm == "auto"
    if osc:
        follower = OscillatingFollower(fo.contact, fo.pivot_distance_mm * mm,
                                       (fo.arm_length_mm or 0.0) * mm, rr, fo.rise_sense)
    else:
        e = 0.0 if auto_offset else side_sign(fo.offset_side) * fo.offset_mm * mm
        follower = TranslatingFollower(fo.contact, e, rr)
    rise = c.limits.pressure_angle_rise_deg
    if rise is None:
        rise = 45.0 if osc else 30.0
    return CamParams(
        programme=programme, follower=follower, rotation=1 if c.rotation == "ccw" else -1,
        omega=None if rpm is None else rpm * 2 * np.pi / 60, speed_rpm=rpm,
        base_radius=None if c.base_radius_mm == "auto" else c.base_radius_mm * mm,
        auto_offset=auto_offset, alpha_rise=np.radians(rise),
        alpha_return=np.radians(c.limits.pressure_angle_return_deg),
        min_actual_curvature=c.limits.min_actual_curvature_mm * mm,
        table_step=np.radians(c.table_step_deg), oscillating=osc)


