"""Brief of the lock-beam bender (锁梁自动成型机床扳弯机构, ``machine: lockbeam``).

The machine bends a padlock shackle blank through 180°: a feed slider pushes the blank
in (a guide-bar six-bar, ``feed_linkage``), a positioning pin rises into its groove
(translating cam, ``cam``), a bending wheel turns its roller round a fixed roller
(``bending``: a cam-driven rocker, ``bending_cam``, drives a four-bar whose output is the
large chain wheel; the chain turns the small bending wheel), then everything returns.
One distribution (main) shaft turns once per part; the motor drives it through a belt
and gear train (``transmission``). The motion cycle diagram (``cycle``) and the
morphological matrix (``morphology``) document the scheme.

Course units in the brief (mm, °, rpm, 1/min); :func:`lockbeam_to_si` converts once to
:class:`LockbeamParams` in SI units. Every cross-section rule (speeds, the cycle diagram
against the cam programmes) is checked when the brief is loaded; whether the feed
linkage assembles and the bending linkage can be synthesised is asked once per run by
:func:`mechdesign.machines.lockbeam.stages.checks` (validation never solves a linkage).
"""
from __future__ import annotations

import math

from dataclasses import dataclass
from fractions import Fraction
from typing import Annotated, Literal, Optional, Union

from ...lazy import np
from pydantic import Field, model_validator

from ...brief.cam import CamParams, CamSection, cam_to_si, follower_phases_deg
from ...brief.common import AnalysisSettings, Problems, ReportMeta, SheetSettings, StrictModel
from ...brief.components import CycleSection, MorphologySection, cycle_to_si, morphology_to_si
from ...brief.linkage import LinkageSection, linkage_to_model
from ...i18n import N_, tr

#: Keys the cycle diagram must use for the three actuators.
FEED, PIN, BEND = "feed", "pin", "bend"


class ProductionData(StrictModel):
    """Production data of the task (设计任务书)."""

    rate_per_min: float = Field(gt=0, le=600, description=(
        "Production rate [parts/min]; the main (distribution) shaft turns once per part, so "
        "its speed in rpm equals the rate"))
    motor_speed_rpm: float = Field(gt=0, le=10000, description="Motor speed n_m [rpm]")
    part_length_mm: float = Field(gt=0, le=5000, description="Unrolled length of the blank l [mm]")
    part_diameter_mm: float = Field(gt=0, le=200, description="Bar diameter d1 [mm]")
    groove_diameter_mm: float = Field(gt=0, le=200, description=(
        "Diameter at the bottom of the groove the positioning pin enters, d2 [mm]"))

    @model_validator(mode="after")
    def _groove_inside(self):
        out = Problems(self)
        if self.groove_diameter_mm >= self.part_diameter_mm:
            out.add("groove_diameter_mm", self.groove_diameter_mm,
                    N_("groove_diameter_mm = {groove_diameter_mm:g} must be smaller than "
                       "part_diameter_mm = {part_diameter_mm:g}"),
                    groove_diameter_mm=self.groove_diameter_mm, part_diameter_mm=self.part_diameter_mm)
        out.raise_any()
        return self


class BeltStage(StrictModel):
    """V-belt stage from the motor (带传动)."""

    driver_diameter_mm: float = Field(gt=0, le=5000, description="Driving pulley diameter d1 [mm]")
    driven_diameter_mm: float = Field(gt=0, le=5000, description="Driven pulley diameter d2 [mm]")
    slip: float = Field(0.0, ge=0, lt=0.1, description=(
        "Elastic slip ε [–]; the nominal train ignores it (0), 0.01–0.02 is typical"))


class GearStage(StrictModel):
    """One spur gear pair (直齿圆柱齿轮), driving gear first."""

    driver_teeth: int = Field(ge=5, le=1000, description="Teeth of the driving gear z1 [count]")
    driven_teeth: int = Field(ge=5, le=1000, description="Teeth of the driven gear z2 [count]")


class TransmissionSection(StrictModel):
    """Motor → main shaft: a belt stage then spur gear stages (传动系统)."""

    belt: BeltStage
    gears: list[GearStage] = Field(min_length=1, max_length=4, description="Gear stages in order")
    module_mm: float = Field(gt=0, le=50, description="Module m of every gear pair [mm]")
    pressure_angle_deg: float = Field(20.0, gt=0, lt=45, description="Pressure angle α [°]")
    motor_power_kW: Optional[float] = Field(None, gt=0, le=10000, description=(
        "Motor power P [kW], if known: then the shaft powers and torques are given too"))
    belt_efficiency: float = Field(0.96, gt=0, le=1, description="Efficiency of the belt stage η_b [–]")
    gear_efficiency: float = Field(0.97, gt=0, le=1, description=(
        "Efficiency of each gear stage incl. its bearings η_g [–]"))


class BendingStart(StrictModel):
    """A start position chosen by the designer (先设定一个起始位置)."""

    input_deg: float = Field(ge=-360, le=360, description=(
        "Angle of the input rocker at the start of the bend [°], CCW from the line from its "
        "pivot to the wheel's centre"))
    output_deg: float = Field(ge=-360, le=360, description=(
        "Angle of the output arm on the wheel at the start of the bend [°], same reference"))


class SeedLengths(StrictModel):
    """Link lengths of a design to check by simulation (e.g. the original report's graphical solution)."""

    input_rocker_mm: float = Field(gt=0, le=10000, description="Input rocker length [mm]")
    coupler_mm: float = Field(gt=0, le=10000, description="Coupler length [mm]")


class BendingSection(StrictModel):
    """The bending drive (扳弯机构): cam-driven input rocker → four-bar → large chain wheel →
    chain → small bending wheel. The input rocker is the bending cam's oscillating follower;
    the four-bar is synthesised for the swing ``bending_cam.follower.max_swing_deg``; the cam itself
    is designed for the swing the drawn (rounded) lengths need for exactly the bending angle."""

    bending_angle_deg: float = Field(gt=0, le=360, description="Angle the bending wheel turns [°]")
    driving_wheel_diameter_mm: float = Field(gt=0, le=5000, description=(
        "Pitch diameter of the large chain wheel turned by the four-bar [mm]"))
    bending_wheel_diameter_mm: float = Field(gt=0, le=5000, description=(
        "Pitch diameter of the small chain wheel on the bending arm's shaft [mm]"))
    frame_mm: float = Field(gt=0, le=10000, description=(
        "Distance from the input rocker's pivot to the large wheel's centre d [mm]"))
    output_arm_mm: float = Field(gt=0, le=10000, description=(
        "Length of the output arm on the large wheel c (centre to coupler pin) [mm]"))
    start: Union[Literal["auto"], BendingStart] = Field("auto", description=(
        "Start position of the two rockers: 'auto' chooses the one with the largest minimum "
        "transmission angle (within velocity_ratio_peak_factor); or give input_deg and output_deg"))
    output_sense: Literal["auto", "same", "opposite"] = Field("auto", description=(
        "Does the output turn the same way as the input rocker or the opposite way; 'auto' "
        "takes the better transmission angle"))
    link_length_range_mm: list[Annotated[float, Field(ge=-10000, le=10000)]] = Field([20.0, 300.0], min_length=2, max_length=2, description=(
        "Range [min, max] allowed for the input rocker and the coupler when start is 'auto' [mm]"))
    transmission_angle_min_deg: float = Field(40.0, gt=0, lt=90, description=(
        "Allowed minimum transmission angle [γ] [°]"))
    velocity_ratio_peak_factor: Optional[float] = Field(None, ge=1, le=10, description=(
        "With start 'auto': the largest |dβ/dα| allowed, as a multiple of its mean Δβ/Δα [–] "
        "(bounds the cam's peak force for a constant bending torque); leave out for no bound"))
    length_rounding_mm: float = Field(1.0, ge=0, le=100, description=(
        "The synthesised lengths are also checked rounded to this step, as drawn [mm]; 0: no check"))
    seed_check: Optional[SeedLengths] = Field(None, description=(
        "Lengths of another design to check by simulation (the original report's graphical solution)"))

    @model_validator(mode="after")
    def _swing(self):
        out = Problems(self)
        swing = self.bending_angle_deg * self.bending_wheel_diameter_mm / self.driving_wheel_diameter_mm
        if not swing < 180.0:
            out.add("driving_wheel_diameter_mm", self.driving_wheel_diameter_mm,
                    N_("the large wheel would have to turn {swing:.6g}° (= bending_angle_deg × "
                       "bending_wheel_diameter_mm / driving_wheel_diameter_mm); a rocker swings "
                       "less than 180°: use a larger driving wheel"), swing=swing)
        lo, hi = self.link_length_range_mm
        if not 0 < lo < hi:
            out.add("link_length_range_mm", f"[{lo:g}, {hi:g}]",
                    N_("link_length_range_mm = [{lo:g}, {hi:g}] must be [min, max] with 0 < min < "
                       "max"), lo=lo, hi=hi)
        out.raise_any()
        return self


class LockbeamBrief(StrictModel):
    """Lock-beam bender (锁梁自动成型机床扳弯机构): scheme, cycle diagram, transmission,
    positioning cam, bending linkage and its cam, feed linkage."""

    machine: Literal["lockbeam"] = Field(description="Machine type")
    report: ReportMeta
    production: ProductionData
    transmission: TransmissionSection
    cam: CamSection = Field(description="Positioning-pin cam (定位凸轮), translating follower")
    bending: BendingSection
    bending_cam: CamSection = Field(description=(
        "Bending cam (扳弯凸轮), oscillating follower = the four-bar's input rocker"))
    feed_linkage: LinkageSection = Field(description="Feed mechanism (送料机构) as Assur groups")
    cycle: CycleSection
    morphology: MorphologySection
    analysis: AnalysisSettings = AnalysisSettings()
    sheets: SheetSettings = SheetSettings()

    @model_validator(mode="after")
    def _consistent(self):
        """The rules between sections (closed form: no linkage is solved here; whether the
        feed assembles and the bending linkage can be synthesised is asked once per run by
        :func:`mechdesign.machines.lockbeam.stages.checks`). Every problem is reported, each at
        its field."""
        out = Problems(self)
        rate = self.production.rate_per_min
        if self.cam.follower.motion != "translating":
            out.add(("cam", "follower", "motion"), self.cam.follower.motion,
                    N_("the positioning pin moves straight up and down: use a translating follower"))
        if self.bending_cam.follower.motion != "oscillating":
            out.add(("bending_cam", "follower", "motion"), self.bending_cam.follower.motion,
                    N_("the bending cam swings the four-bar's input rocker: use an oscillating "
                       "follower"))
        for loc, value in ((("cam", "speed_rpm"), self.cam.speed_rpm),
                           (("bending_cam", "speed_rpm"), self.bending_cam.speed_rpm),
                           (("cycle", "shaft_speed_rpm"), self.cycle.shaft_speed_rpm),
                           (("feed_linkage", "crank", "speed_rpm"), self.feed_linkage.crank.speed_rpm)):
            if value is not None and abs(value - rate) > 1e-9 * rate:
                out.add(loc, value,
                        N_("{value:g} rpm, but it turns with the main shaft, once per part: it "
                           "must be production.rate_per_min = {rate:g} (or be left out)"),
                        value=value, rate=rate)
        _check_shaft_sense(self, out)
        out_point = self.feed_linkage.output
        if out_point.point is None:
            out.add(("feed_linkage", "output", "link"), out_point.link,
                    N_("the feed's output is the feed slider: give output.point (its pin), not a "
                       "link"))
        _check_cycle(self, out)
        out.raise_any()
        return self


#: The members keyed on the one main shaft (field paths); the first is the reference.
SHAFT_MEMBERS = (("feed_linkage", "crank", "rotation"), ("cam", "rotation"),
                 ("bending_cam", "rotation"))


def _check_shaft_sense(b: LockbeamBrief, out: Problems) -> None:
    """The feed crank and both cams are keyed on the one main shaft: they turn the same way.
    Every member that turns against the feed crank is reported at its field, naming both."""
    def sense(loc):
        obj = b
        for key in loc:
            obj = getattr(obj, key)
        return obj

    ref_loc = SHAFT_MEMBERS[0]
    ref = sense(ref_loc)
    for loc in SHAFT_MEMBERS[1:]:
        if sense(loc) != ref:
            out.add(loc, sense(loc),
                    N_("{name} = {sense}, but {ref_name} = {ref}: the feed crank and both cams are "
                       "keyed on the one main shaft, which turns one way; give them the same sense"),
                    name=".".join(loc), sense=sense(loc), ref_name=".".join(ref_loc), ref=ref)


#: Phase spans this close are the same (1e-9 rad, in degrees).
_SPAN_TOL_DEG = math.degrees(1e-9)


def _phases_text(phases) -> str:
    return ", ".join(f"{s} {w:.6g}°" for s, w in phases)


def _check_cycle(b: LockbeamBrief, out: Problems) -> None:
    """The cycle diagram names the three actuators, and the pin's and the bending arm's
    phases are exactly those of their cams."""
    keys = [a.key for a in b.cycle.actuators]
    missing = [k for k in (FEED, PIN, BEND) if k not in keys]
    if missing:
        need = ", ".join(repr(k) for k in (FEED, PIN, BEND))
        lack = ", ".join(repr(k) for k in missing)
        out.add(("cycle", "actuators"), ", ".join(keys),
                N_("the lock-beam bender's diagram needs the actuators {need}; missing {lack}"),
                need=need, lack=lack)
    if FEED in keys:
        feed = keys.index(FEED)
        states = [p.state for p in b.cycle.actuators[feed].phases]
        if sorted(states) != ["return", "rise"]:
            out.add(("cycle", "actuators", feed, "phases"), ", ".join(states),
                    N_("the feed slider reciprocates without dwelling: give a rise ({feed}) and a "
                       "return ({back})"), feed=tr("zh").pgettext("lock-beam phase", "feed"),
                    back=tr("zh").pgettext("lock-beam phase", "return"))
    for key, section, name in ((PIN, b.cam, "cam"), (BEND, b.bending_cam, "bending_cam")):
        if key not in keys:
            continue
        i = keys.index(key)
        act = b.cycle.actuators[i]
        want = follower_phases_deg(section)
        have = [(p.state, p.span_deg) for p in act.phases]
        same = len(want) == len(have) and all(
            sw == sh and abs(ww - wh) < _SPAN_TOL_DEG for (sw, ww), (sh, wh) in zip(want, have))
        if not same:
            out.add(("cycle", "actuators", i, "phases"), f"'{key}': {_phases_text(have)}",
                    N_("not what {name}.programme makes the follower do ({v1}); the cycle diagram "
                       "must show the cam's programme from its δ = 0, placed at start_deg"),
                    name=name, v1=_phases_text(want))


# --------------------------------------------------------------------------- to SI


@dataclass(frozen=True)
class TransmissionParams:
    belt_d1: float                  # [m]
    belt_d2: float                  # [m]
    slip: float
    gears: tuple[tuple[int, int], ...]
    module: float                   # [m]
    alpha: float                    # [rad]
    power: float | None             # [W]
    belt_efficiency: float
    gear_efficiency: float
    belt_ratio_exact: Fraction      # d2/d1 as an exact fraction of the brief's numbers


@dataclass(frozen=True)
class BendingParams:
    bending_angle: float            # [rad]
    driving_wheel: float            # pitch diameters [m]
    bending_wheel: float
    frame: float                    # [m]
    output_arm: float               # [m]
    input_swing: float              # [rad] > 0 (the bending cam's swing)
    start: tuple[float, float] | None   # (α1, β1) [rad] or None for auto
    sense: str                      # auto | same | opposite
    length_bounds: tuple[float, float]  # [m]
    gamma_allowed: float            # [rad]
    seed: tuple[float, float] | None    # (input rocker, coupler) [m]
    ratio_factor: float | None = None   # peak |dβ/dα| / (Δβ/Δα) allowed (auto start)
    rounding: float = 1e-3              # [m]; 0: no rounding check

    @property
    def ratio(self) -> float:
        """Chain drive ratio i = D_driving / D_bending (wheel angle = i × output swing)."""
        return self.driving_wheel / self.bending_wheel

    @property
    def output_swing(self) -> float:
        """Required swing of the large wheel Δβ = bending angle / i [rad] (> 0)."""
        return self.bending_angle / self.ratio


@dataclass(frozen=True)
class LockbeamParams:
    rate: float                     # parts per minute = main-shaft speed [rpm]
    main_omega: float               # [rad/s]
    motor_rpm: float
    part_length: float              # [m]
    part_diameter: float
    groove_diameter: float
    transmission: TransmissionParams
    cam: CamParams                  # positioning pin (result key "cam")
    bending_cam: CamParams
    bending: BendingParams
    feed: object                    # machines.linkage.LinkageModel
    cycle: object                   # core.cycle.CycleDiagram
    pin_cam_start: float            # main-shaft angle where the pin cam's δ = 0 [rad]
    bend_cam_start: float           # the same for the bending cam [rad]
    morphology: object              # brief.components.Morphology
    grid_points: int


def bending_params(b: LockbeamBrief) -> BendingParams:
    s, mm = b.bending, 1e-3
    start = None
    if not isinstance(s.start, str):
        start = (float(np.radians(s.start.input_deg)), float(np.radians(s.start.output_deg)))
    seed = None if s.seed_check is None else (s.seed_check.input_rocker_mm * mm,
                                              s.seed_check.coupler_mm * mm)
    return BendingParams(
        bending_angle=float(np.radians(s.bending_angle_deg)),
        driving_wheel=s.driving_wheel_diameter_mm * mm, bending_wheel=s.bending_wheel_diameter_mm * mm,
        frame=s.frame_mm * mm, output_arm=s.output_arm_mm * mm,
        input_swing=float(np.radians(b.bending_cam.follower.max_swing_deg)),
        start=start, sense=s.output_sense,
        length_bounds=(s.link_length_range_mm[0] * mm, s.link_length_range_mm[1] * mm),
        gamma_allowed=float(np.radians(s.transmission_angle_min_deg)), seed=seed,
        ratio_factor=s.velocity_ratio_peak_factor, rounding=s.length_rounding_mm * mm)


def feed_names() -> dict[str, tuple[str, str]]:
    """The feed linkage's links: id → (Chinese name, English name)."""
    zh = tr("zh")
    return {"2": (zh.pgettext("link", "crank"), "crank"),
            "3": (zh.pgettext("link", "slider block"), "slider block"),
            "4": (zh.pgettext("link", "guide bar"), "guide bar"),
            "5": (zh.pgettext("link", "rod"), "rod"),
            "6": (zh.pgettext("link", "feed slider"), "feed slider")}


def lockbeam_to_si(b: LockbeamBrief) -> LockbeamParams:
    """The only conversion of the brief to SI."""
    mm = 1e-3
    p, t = b.production, b.transmission
    rate = p.rate_per_min
    tr = TransmissionParams(
        belt_d1=t.belt.driver_diameter_mm * mm, belt_d2=t.belt.driven_diameter_mm * mm,
        slip=t.belt.slip, gears=tuple((g.driver_teeth, g.driven_teeth) for g in t.gears),
        module=t.module_mm * mm, alpha=float(np.radians(t.pressure_angle_deg)),
        power=None if t.motor_power_kW is None else t.motor_power_kW * 1e3,
        belt_efficiency=t.belt_efficiency, gear_efficiency=t.gear_efficiency,
        belt_ratio_exact=Fraction(t.belt.driven_diameter_mm) / Fraction(t.belt.driver_diameter_mm))
    acts = {a.key: a for a in b.cycle.actuators}
    return LockbeamParams(
        rate=rate, main_omega=rate * np.pi / 30.0, motor_rpm=p.motor_speed_rpm,
        part_length=p.part_length_mm * mm, part_diameter=p.part_diameter_mm * mm,
        groove_diameter=p.groove_diameter_mm * mm, transmission=tr,
        cam=cam_to_si(b.cam, rate), bending_cam=cam_to_si(b.bending_cam, rate),
        bending=bending_params(b),
        feed=linkage_to_model(b.feed_linkage, b.analysis, feed_names()),
        cycle=cycle_to_si(b.cycle, rate),
        pin_cam_start=float(np.radians(acts[PIN].start_deg)),
        bend_cam_start=float(np.radians(acts[BEND].start_deg)),
        morphology=morphology_to_si(b.morphology), grid_points=b.analysis.grid_points)
