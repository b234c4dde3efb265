"""Brief of ``machine: die_cutter``: the semi-automatic flat die-cutter (半自动平压模切机).

One distribution shaft (分配轴), one revolution per sheet, drives three actuators:

* the toggle press (肘杆机构): crank O1A → coupler AB → toggle links CB (pivot C on the
  frame) and BD → lower platen D on a vertical guide, pushed against the fixed upper die;
* the gripper-opening cam (夹爪张开凸轮), rise–dwell–return–dwell;
* the incomplete gear (不完全齿轮) that advances the gripper chain one sheet pitch per cycle.

The drive (motor → V-belt → two-stage helical reducer → distribution shaft) is the shared
``drive:`` section. Course units in the brief (mm, °, rpm, kg, N, m for the cut length);
:func:`die_cutter_to_si` converts once to the SI :class:`DieCutterParams`. Validation checks
fields and the closed-form rules between them; whether the press can be synthesised is
asked once per run by :func:`mechdesign.machines.die_cutter.stages.checks`.
"""
from __future__ import annotations

import math

from dataclasses import dataclass
from typing import Annotated, Literal, Optional, Union

from ...lazy import np
from pydantic import BeforeValidator, Field, model_validator

from ...brief.cam import CamParams, CamSection, cam_to_si
from ...brief.common import (AnalysisSettings, Msg, Problems, ReportMeta, RimHeightToWidth,
                             RimSpecificWeight, SheetSettings, StrictModel, parse_fraction)
from ...brief.components import IncompleteGearSection
from ...brief.drive import DriveParams, DriveSection, drive_to_si
from ...i18n import N_


def _fraction(value):
    """Accept 0.1 or the course's '1/10'."""
    return parse_fraction(value, N_("write the fluctuation as a number or a fraction such as 1/10"))


class Production(StrictModel):
    """Production data of the task (设计任务)."""

    sheets_per_hour: float = Field(gt=0, le=36000, description=(
        "Output [sheets/h]; one die-cutting cycle (one turn of the distribution shaft) per sheet"))
    table_height_mm: float = Field(1200.0, gt=0, le=3000, description=(
        "Height of the work table above the floor [mm] (layout datum, shown in the report)"))
    board_thickness_mm: float = Field(gt=0, le=20, description=(
        "Largest board thickness [mm]: the platen presses the board over this last travel"))


class PressDimensions(StrictModel):
    """The press's crank-rocker O1ABC as a data table gives it (给定尺寸); rocker: toggle_CB_mm.

    The rocker of the crank-rocker is the lower toggle CB, press.toggle_CB_mm."""

    crank_O1A_mm: float = Field(gt=0, le=5000, description="Crank O1A = a [mm]")
    coupler_AB_mm: float = Field(gt=0, le=10000, description="Coupler AB = b [mm]")
    frame_O1C_mm: float = Field(gt=0, le=10000, description=(
        "Frame O1C = d, from the crank pivot O1 to the toggle pivot C [mm]"))


#: TogglePress fields of the synthesis form, absent when dimensions are given.
_SYNTHESIS_ONLY = ("stroke_H_mm", "time_ratio_K", "frame_O1C_mm")


def _angle(x: float, y: float, z: float) -> float:
    """Angle opposite z in a triangle with sides x, y, z [rad] (law of cosines, plain math)."""
    return math.acos(max(-1.0, min(1.0, (x * x + y * y - z * z) / (2.0 * x * y))))


def toggle_reach(l_cb: float, l_bd: float) -> float:
    """Largest angle of CB from the guide [rad]: 90°, or where BD would lie flat (BD < CB)."""
    return math.pi / 2 if l_bd >= l_cb else math.asin(l_bd / l_cb)


def platen_height(beta: float, l_cb: float, l_bd: float) -> float:
    """Platen D above C with CB at beta [rad] from the guide (plain math)."""
    return l_cb * math.cos(beta) + math.sqrt(max(0.0, l_bd * l_bd - (l_cb * math.sin(beta)) ** 2))


def given_press(pr: "TogglePress") -> tuple[float, float, float, float]:
    """(θ [rad], ψ [rad], H [mm], K) of the press given by its dimensions, in closed form:
    crank and coupler folded (O1B1 = b − a) and extended (O1B2 = b + a) in the triangles
    O1CB1, O1CB2 (C the rocker's pivot, CB = c); θ = |∠CO1B1 − ∠CO1B2|,
    ψ = ∠O1CB2 − ∠O1CB1, K = (180° + θ)/(180° − θ), H = y_D(ε) − y_D(ε + ψ)."""
    dm = pr.dimensions
    a, b, c, d = dm.crank_O1A_mm, dm.coupler_AB_mm, pr.toggle_CB_mm, dm.frame_O1C_mm
    theta = abs(_angle(b - a, d, c) - _angle(b + a, d, c))
    psi = _angle(d, c, b + a) - _angle(d, c, b - a)
    eps = math.radians(pr.toggle_angle_at_top_deg)
    H = platen_height(eps, c, pr.toggle_BD_mm) - platen_height(eps + psi, c, pr.toggle_BD_mm)
    return theta, psi, H, (math.pi + theta) / (math.pi - theta)


class TogglePress(StrictModel):
    """Toggle press (肘杆机构) lifting the lower platen: crank O1A, coupler AB, toggles CB and BD.

    C is a frame pivot vertically below the platen D, on the platen's guide line. Either the
    requirements (stroke H, time ratio K: the crank-rocker O1ABC is synthesised) or the
    crank-rocker's dimensions (a, b, d: θ, ψ, K and H follow from them)."""

    stroke_H_mm: Optional[float] = Field(None, gt=0, le=500, description=(
        "Platen stroke H [mm]; required unless dimensions are given"))
    time_ratio_K: Optional[float] = Field(None, gt=1, lt=3, description=(
        "Time ratio K of the platen: rise (working stroke) time / fall time, 1 < K < 3; required "
        "unless dimensions are given"))
    toggle_CB_mm: float = Field(gt=0, le=5000, description=(
        "Lower toggle link CB [mm] (also the rocker of the crank-rocker O1ABC)"))
    toggle_BD_mm: float = Field(gt=0, le=5000, description="Upper toggle link BD to the platen [mm]")
    toggle_angle_at_top_deg: float = Field(0.0, ge=0, lt=30, description=(
        "Angle of CB from the platen guide when the platen is at its top [°]; 0: the toggle is "
        "straight at the top dead centre"))
    top_position: Literal["extended", "folded"] = Field("extended", description=(
        "Which extreme of the crank-rocker gives the platen's top: extended (crank and coupler "
        "in line, AB = b + a) or folded (AB overlapping the crank)"))
    frame_O1C_mm: Optional[float] = Field(None, gt=0, le=10000, description=(
        "Distance from the crank pivot O1 to the toggle pivot C [mm]; default: the crank-rocker "
        "with the largest minimum transmission angle (not with dimensions)"))
    dimensions: Optional[PressDimensions] = Field(None, description=(
        "Given dimensions (给定尺寸) of the crank-rocker O1ABC instead of stroke_H_mm, "
        "time_ratio_K and frame_O1C_mm: no synthesis; θ, ψ, K and the stroke H = y_D(ε) − "
        "y_D(ε + ψ) are computed from them"))
    crank_rotation: Literal["cw", "ccw"] = Field("cw", description=(
        "Sense of rotation of the distribution shaft (crank) seen on the drawing: cw or ccw"))
    linkages: Literal[1, 2] = Field(1, description=(
        "Identical toggle linkages side by side lifting the platen, in phase: 1, or 2 (one at each "
        "side of the platen, a crank overhung beyond each bearing of the distribution shaft). The "
        "planar analysis is that of one linkage carrying the whole resistance (the sum of the "
        "two); with 2, each crank carries half of the frame reaction and of the torque"))
    transmission_angle_min_deg: float = Field(40.0, gt=0, lt=90, description=(
        "Allowed minimum transmission angle of the crank-rocker [°] (textbook 40)"))
    pressure_angle_max_deg: float = Field(30.0, gt=0, lt=90, description=(
        "Allowed pressure angle of the platen slider in the working stroke [°]"))
    clearance_mm: float = Field(gt=0, le=500, description=(
        "The sheet and the gripper bar pass between die and platen only while the platen is at "
        "least this far below its top [mm]"))

    @model_validator(mode="after")
    def _one_form(self):
        """Either the requirements (H, K) or the dimensions; closed-form checks of the
        dimensions (Grashof's crank-rocker, the toggle's reach), each at its field."""
        from ...brief.rules import crank_rocker_problems, raise_missing

        if self.dimensions is None:
            raise_missing(self, [n for n in ("stroke_H_mm", "time_ratio_K") if getattr(self, n) is None])
            return self
        out = Problems(self)
        for name in _SYNTHESIS_ONLY:
            if getattr(self, name) is not None:
                out.add((name,), getattr(self, name),
                        N_("{name}: with dimensions given there is no synthesis, and H, K and the "
                           "frame follow from the dimensions; remove {name} (or remove dimensions)"),
                        name=name)
        dm = self.dimensions
        before = len(out.items)
        crank_rocker_problems(out, ("dimensions",), dm.crank_O1A_mm, dm.coupler_AB_mm,
                              self.toggle_CB_mm, dm.frame_O1C_mm,
                              ("crank_O1A_mm", "coupler_AB_mm", "toggle_CB_mm", "frame_O1C_mm"),
                              locs={"toggle_CB_mm": ("toggle_CB_mm",)})
        if len(out.items) == before:
            _, psi, _, _ = given_press(self)
            eps = math.radians(self.toggle_angle_at_top_deg)
            reach = toggle_reach(self.toggle_CB_mm, self.toggle_BD_mm)
            if not eps + psi < reach:
                flat = (Msg(N_("BD would lie flat")) if self.toggle_BD_mm < self.toggle_CB_mm else
                        Msg(N_("CB would pass the horizontal")))
                out.add(("dimensions", "crank_O1A_mm"), dm.crank_O1A_mm,
                        N_("dimensions.crank_O1A_mm = {crank_O1A_mm:g}: the dimensions swing CB "
                           "through ψ = {v1:.4g}°, and with toggle_angle_at_top_deg = "
                           "{toggle_angle_at_top_deg:g}° the bottom is {v2:.4g}° from the guide, "
                           "beyond {v3:.4g}° where {flat}: a shorter crank or a longer frame "
                           "gives less swing"),
                        crank_O1A_mm=dm.crank_O1A_mm, v1=math.degrees(psi),
                        toggle_angle_at_top_deg=self.toggle_angle_at_top_deg,
                        v2=math.degrees(eps + psi), v3=math.degrees(reach), flat=flat)
        out.raise_any()
        return self

    @property
    def stroke_mm(self) -> float:
        """The platen stroke H [mm]: the brief's, or derived from the dimensions."""
        return self.stroke_H_mm if self.dimensions is None else given_press(self)[2]


class PressMasses(StrictModel):
    """Mass properties (质量参数) of the platen and the links (uniform bars, J_S = m l²/12).

    The centre of mass of each link is at its middle; the crank is balanced."""

    platen_kg: float = Field(ge=0, le=1e5, description="Lower platen with its slide, at D [kg]")
    coupler_AB_kg: float = Field(0.0, ge=0, le=1e4, description="Coupler AB [kg]")
    toggle_CB_kg: float = Field(0.0, ge=0, le=1e4, description="Toggle link CB [kg]")
    toggle_BD_kg: float = Field(0.0, ge=0, le=1e4, description="Toggle link BD [kg]")


class CuttingLoad(StrictModel):
    """Die-cutting resistance (模切阻力) F = L·q against the rising platen near its top.

    It acts over the last ``pressing travel`` of the rise, not on the way down."""

    cut_length_m: float = Field(gt=0, le=1000, description=(
        "Total length of cutting and creasing rule in the die [m]"))
    specific_resistance_N_per_mm: float = Field(gt=0, le=1000, description=(
        "Force per millimetre of rule needed to cut the board [N/mm]"))
    pressing_travel_mm: Optional[float] = Field(None, gt=0, le=50, description=(
        "Platen travel before the top over which the force acts [mm]; default: the board thickness"))


class DieCutterFlywheel(StrictModel):
    """Flywheel (飞轮): it stores the energy of one cut between two cuts."""

    fluctuation_delta: Annotated[float, BeforeValidator(_fraction)] = Field(
        gt=0, lt=1, description="Allowed coefficient of speed fluctuation [δ], e.g. 0.1 or 1/10")
    shaft: int = Field(1, ge=0, le=8, description=(
        "Drive shaft carrying the flywheel: 0 the motor, 1 the shaft after the first drive stage "
        "(the V-belt's large pulley), …; the number of drive stages means the distribution shaft"))
    rim_diameter_mm: float = Field(600.0, gt=0, le=5000, description="Mean rim diameter D [mm]")
    rim_height_to_width: RimHeightToWidth = 1.5
    specific_weight_N_m3: RimSpecificWeight = 7.0e4


class ChainFeed(StrictModel):
    """The gripper chain (送纸链条) driven by a sprocket on the incomplete gear's driven wheel."""

    pitch_mm: float = Field(gt=0, le=200, description="Chain pitch p [mm] (e.g. 25.4 for 16A)")
    sprocket_teeth: int = Field(ge=9, le=150, description="Teeth of the driving sprocket z_s [count]")
    bar_spacing_mm: float = Field(gt=0, le=10000, description=(
        "Spacing of the gripper bars on the chain = the feed per cycle (one sheet pitch) [mm]"))


class Timing(StrictModel):
    """Placement of the cam and the incomplete gear on the distribution shaft (安装角).

    Angles from the platen's bottom position (位置 1) in the sense of rotation."""

    feed_start_deg: Union[float, Literal["auto"]] = Field("auto", description=(
        "Shaft angle where the incomplete gear's first tooth meshes [°], 0 ≤ value < 360; auto: the "
        "chain's motion centred in the arc where the platen is clear of the die"))
    gripper_open_deg: Union[float, Literal["auto"]] = Field("auto", description=(
        "Shaft angle where the gripper cam's rise (opening) begins [°], 0 ≤ value < 360; auto: the "
        "opening centred in the chain's dwell"))
    margin_deg: float = Field(5.0, ge=0, le=60, description=(
        "Margin every timing requirement of the cycle diagram must keep [°]"))

    @model_validator(mode="after")
    def _angles(self):
        out = Problems(self)
        for name in ("feed_start_deg", "gripper_open_deg"):
            v = getattr(self, name)
            if v != "auto" and not 0.0 <= v < 360.0:
                out.add(name, v, N_("{name} = {v1:g}: give an angle 0 ≤ value < 360 or 'auto'"),
                                 name=name, v1=v)
        out.raise_any()
        return self


class DieCutterBrief(StrictModel):
    """Semi-automatic flat die-cutter (半自动平压模切机): toggle press, gripper cam, chain feed by an incomplete gear, cycle diagram, flywheel, drive."""  # noqa: E501

    machine: Literal["die_cutter"] = Field(description="Machine type")
    report: ReportMeta
    production: Production
    press: TogglePress
    masses: PressMasses
    cutting: CuttingLoad
    flywheel: DieCutterFlywheel
    gripper_cam: CamSection = Field(description=(
        "Gripper-opening cam on the distribution shaft (夹爪张开凸轮): programme rise, dwell, "
        "return, dwell; it turns with the shaft"))
    incomplete_gear: IncompleteGearSection = Field(description=(
        "Incomplete gear driving the chain sprocket; its driver turns with the distribution shaft; "
        "place it with timing.feed_start_deg"))
    chain: ChainFeed
    timing: Timing = Timing()
    drive: DriveSection = Field(description=(
        "Drive from the motor to the distribution shaft (传动装置), e.g. V-belt and a two-stage "
        "helical reducer"))
    analysis: AnalysisSettings = AnalysisSettings()
    sheets: SheetSettings = SheetSettings()

    @model_validator(mode="after")
    def _consistent(self):
        """The rules between sections (closed form, no synthesis: whether the press can be
        built is asked once per run by :func:`mechdesign.machines.die_cutter.stages.checks`); every
        problem is reported, each at its field."""
        from ...brief.components import incomplete_gear_to_si

        out = Problems(self)
        pr = self.press
        travel = self.pressing_travel_mm
        if not travel < pr.clearance_mm:
            out.add(("press", "clearance_mm"), pr.clearance_mm,
                    N_("press.clearance_mm = {clearance_mm:g} must exceed the pressing travel "
                       "{travel:g} mm (cutting.pressing_travel_mm, default the board thickness): "
                       "the platen presses while the sheet is in the die"),
                    clearance_mm=pr.clearance_mm, travel=travel)
        H = pr.stroke_mm
        name = "stroke_H_mm" if pr.dimensions is None else Msg(N_("H (from the dimensions)"))
        if not pr.clearance_mm < H:
            out.add(("press", "clearance_mm"), pr.clearance_mm,
                    N_("press.clearance_mm = {clearance_mm:g} must be below the stroke {name} = "
                       "{H:.6g}: otherwise the platen is never clear"),
                    clearance_mm=pr.clearance_mm, name=name, H=H)
        c = self.gripper_cam
        if c.rotation != pr.crank_rotation:
            out.add(("gripper_cam", "rotation"), c.rotation,
                    N_("gripper_cam.rotation is {rotation!r} but the cam turns with the "
                       "distribution shaft: press.crank_rotation is {crank_rotation!r}"),
                    rotation=c.rotation, crank_rotation=pr.crank_rotation)
        if c.speed_rpm is not None:
            out.add(("gripper_cam", "speed_rpm"), c.speed_rpm,
                    N_("gripper_cam.speed_rpm: the cam turns with the distribution shaft "
                       "({shaft_rpm:g} rpm from production.sheets_per_hour); leave it out"),
                    shaft_rpm=self.shaft_rpm)
        kinds = [s.motion for s in c.programme]
        if kinds != ["rise", "dwell", "return", "dwell"]:
            out.add(("gripper_cam", "programme"), ", ".join(kinds),
                    N_("gripper_cam.programme: the gripper cam opens, holds, closes and rests: "
                       "give the segments rise, dwell, return, dwell (found {v1})"),
                    v1=', '.join(kinds))
        if "motion_start_deg" in self.incomplete_gear.model_fields_set:
            out.add(("incomplete_gear", "motion_start_deg"), self.incomplete_gear.motion_start_deg,
                    N_("incomplete_gear.motion_start_deg: place the incomplete gear with "
                       "timing.feed_start_deg (an angle or auto) instead"))
        g = incomplete_gear_to_si(self.incomplete_gear)
        ch = self.chain
        feed = g.advance / (2 * math.pi) * ch.sprocket_teeth * ch.pitch_mm
        if abs(feed - ch.bar_spacing_mm) > 0.01:
            links = ch.bar_spacing_mm / ch.pitch_mm
            out.add(("chain", "bar_spacing_mm"), ch.bar_spacing_mm,
                    N_("chain.bar_spacing_mm = {bar_spacing_mm:g}: the incomplete gear turns the "
                       "sprocket by z1'/z2 = {teeth}/{z2} of a turn per cycle, which moves the "
                       "chain {teeth}/{z2} × {sprocket_teeth} × {pitch_mm:g} = {feed:.2f} mm; the "
                       "bar spacing ({links:.3g} pitches) must equal it: change the teeth, the "
                       "sprocket or the spacing"),
                    bar_spacing_mm=ch.bar_spacing_mm, teeth=g.teeth, z2=g.z2, sprocket_teeth=ch.sprocket_teeth, pitch_mm=ch.pitch_mm, feed=feed, links=links)
        n = len(self.drive.stages)
        if self.flywheel.shaft > n:
            out.add(("flywheel", "shaft"), self.flywheel.shaft,
                    N_("flywheel.shaft = {shaft}: the drive has {n} stage(s), so its shafts are 0 "
                       "(motor) … {n} (distribution shaft)"), shaft=self.flywheel.shaft, n=n)
        out.raise_any()
        return self

    @property
    def shaft_rpm(self) -> float:
        """Distribution-shaft speed [rpm]: one revolution per sheet."""
        return self.production.sheets_per_hour / 60.0

    @property
    def pressing_travel_mm(self) -> float:
        t = self.cutting.pressing_travel_mm
        return self.production.board_thickness_mm if t is None else t


# --------------------------------------------------------------------------- SI parameters


@dataclass(frozen=True)
class PressGeometry:
    """Data of the toggle synthesis (SI: m, rad)."""

    stroke: float
    K: float
    toggle_CB: float
    toggle_BD: float
    top_angle: float            # ε: CB from the guide at the top [rad]
    top_position: str           # "extended" | "folded"
    frame: float | None         # O1C [m] or None (best transmission angle)
    sense: float                # +1 ccw, −1 cw
    given: tuple | None = None  # (a, b, d) [m] of the brief's dimensions (None: synthesis);
                                # stroke and K are then the derived ones


def _press_geometry(b: DieCutterBrief) -> PressGeometry:
    pr, mm = b.press, 1e-3
    if pr.dimensions is not None:
        # No synthesis: θ, ψ from the lengths (law of cosines), H from the toggle at ε, ε + ψ.
        from ...core import fourbar

        def toggle_height(beta, l_cb, l_bd):      # = stages.toggle_height (no import cycle)
            return l_cb * np.cos(beta) + np.sqrt(l_bd ** 2 - (l_cb * np.sin(beta)) ** 2)

        dm = pr.dimensions
        a, bb, d = dm.crank_O1A_mm * mm, dm.coupler_AB_mm * mm, dm.frame_O1C_mm * mm
        lt, ld = pr.toggle_CB_mm * mm, pr.toggle_BD_mm * mm
        theta, psi = fourbar.crank_rocker_extremes(fourbar.FourBar(a, bb, lt, d))
        eps = float(np.radians(pr.toggle_angle_at_top_deg))
        H = float(toggle_height(eps, lt, ld) - toggle_height(eps + psi, lt, ld))
        return PressGeometry(H, float((np.pi + theta) / (np.pi - theta)), lt, ld, eps,
                             pr.top_position, d, -1.0 if pr.crank_rotation == "cw" else 1.0,
                             (a, bb, d))
    return PressGeometry(pr.stroke_H_mm * mm, pr.time_ratio_K, pr.toggle_CB_mm * mm,
                         pr.toggle_BD_mm * mm, float(np.radians(pr.toggle_angle_at_top_deg)),
                         pr.top_position, None if pr.frame_O1C_mm is None else pr.frame_O1C_mm * mm,
                         -1.0 if pr.crank_rotation == "cw" else 1.0)


@dataclass(frozen=True)
class DieCutterParams:
    """The die-cutter brief in SI units (m, rad, rad/s, kg, N), converted once."""

    geometry: PressGeometry
    shaft_rpm: float            # distribution shaft n [rpm]
    crank_omega: float          # signed, CCW + [rad/s]
    board_thickness: float      # [m]
    table_height: float         # [m]
    clearance: float            # [m]
    pressing_travel: float      # [m]
    linkages: int               # toggle linkages side by side (each crank: 1/linkages of the load)
    cut_length: float           # [m]
    specific_resistance: float  # [N/m]
    cutting_force: float        # F = L·q [N]
    platen_mass: float          # [kg]
    link_masses: tuple          # (m_AB, m_CB, m_BD) [kg]
    transmission_angle_min: float   # [rad]
    pressure_angle_max: float   # [rad]
    fluctuation: float
    flywheel_shaft: int
    rim_diameter: float         # [m]
    rim_height_to_width: float
    specific_weight: float      # [N/m³]
    cam: CamParams
    gear_section: IncompleteGearSection
    chain_pitch: float          # [m]
    sprocket_teeth: int
    bar_spacing: float          # [m]
    feed_start: float | None    # [rad] or None (auto)
    gripper_open: float | None  # [rad] or None (auto)
    margin: float               # [rad]
    drive: DriveParams
    grid_points: int
    position_step: float        # [rad]
    gravity: float


def die_cutter_to_si(b: DieCutterBrief) -> DieCutterParams:
    """Convert the brief's course units to SI (the only unit conversion on input)."""
    mm, g = 1e-3, _press_geometry(b)
    rpm = b.shaft_rpm
    t = b.timing
    force = b.cutting.cut_length_m * b.cutting.specific_resistance_N_per_mm * 1e3
    return DieCutterParams(
        geometry=g, shaft_rpm=rpm, crank_omega=g.sense * rpm * np.pi / 30.0,
        board_thickness=b.production.board_thickness_mm * mm,
        table_height=b.production.table_height_mm * mm,
        clearance=b.press.clearance_mm * mm, pressing_travel=b.pressing_travel_mm * mm,
        linkages=b.press.linkages,
        cut_length=b.cutting.cut_length_m,
        specific_resistance=b.cutting.specific_resistance_N_per_mm * 1e3,
        cutting_force=force, platen_mass=b.masses.platen_kg,
        link_masses=(b.masses.coupler_AB_kg, b.masses.toggle_CB_kg, b.masses.toggle_BD_kg),
        transmission_angle_min=float(np.radians(b.press.transmission_angle_min_deg)),
        pressure_angle_max=float(np.radians(b.press.pressure_angle_max_deg)),
        fluctuation=b.flywheel.fluctuation_delta, flywheel_shaft=b.flywheel.shaft,
        rim_diameter=b.flywheel.rim_diameter_mm * mm,
        rim_height_to_width=b.flywheel.rim_height_to_width,
        specific_weight=b.flywheel.specific_weight_N_m3,
        cam=cam_to_si(b.gripper_cam, rpm), gear_section=b.incomplete_gear,
        chain_pitch=b.chain.pitch_mm * mm, sprocket_teeth=b.chain.sprocket_teeth,
        bar_spacing=b.chain.bar_spacing_mm * mm,
        feed_start=None if t.feed_start_deg == "auto" else float(np.radians(t.feed_start_deg)),
        gripper_open=None if t.gripper_open_deg == "auto" else float(np.radians(t.gripper_open_deg)),
        margin=float(np.radians(t.margin_deg)), drive=drive_to_si(b.drive),
        grid_points=b.analysis.grid_points,
        position_step=float(np.radians(b.analysis.position_step_deg)), gravity=b.analysis.gravity)
