"""Brief sections shared by the guide-bar (quick-return) machines — the shaper and the
slotter: masses, the gear pair z1/z2 that drives the crank, the flywheel, and the base of
their briefs (cam on the crank shaft, drive ending with the gear pair, analysis, sheets)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, Optional

from pydantic import Field, field_validator, model_validator

from ..lazy import np
from .cam import CamSection
from .common import AnalysisSettings, ReportMeta, SheetSettings, StrictModel, parse_fraction
from .drive import DriveParams, DriveSection, DriveStage, check_material, drive_to_si


class GuideBarMasses(StrictModel):
    """Mass properties (质量参数); all other links are massless."""

    guide_bar_m4_kg: float = Field(ge=0, le=10000, description="Guide-bar mass m4 [kg]")
    guide_bar_J_S4_kgm2: float = Field(ge=0, le=10000,
                                       description="Guide-bar moment of inertia about S4, J_S4 [kg·m²]")
    ram_m6_kg: float = Field(ge=0, le=100000, description="Ram mass m6 [kg]")
    gear2_weight_G2_N: float = Field(0.0, ge=0, le=1e6,
                                     description="Weight of gear 2 on the crank shaft, acting at O2, G2 [N]")


class GearPair(StrictModel):
    """The gear pair z1/z2 that drives the crank (gear 2 turns with the crank)."""

    z1: int = Field(gt=0, le=1000, description="Pinion teeth z1 (on shaft O1)")
    z2: int = Field(gt=0, le=1000, description="Gear teeth z2 (on the crank shaft O2)")
    module_mm: Optional[float] = Field(None, gt=0, le=100, description=(
        "Module m [mm]; with it the report gains the gear section (齿轮设计及啮合图)"))
    pressure_angle_deg: float = Field(20.0, ge=14.5, le=25, description="Pressure angle α [°]")
    addendum_coeff: float = Field(1.0, gt=0, le=1.5, description="Addendum coefficient ha*")
    clearance_coeff: float = Field(0.25, ge=0, le=0.5, description="Clearance coefficient c*")
    x1: float = Field(0.0, ge=-1, le=1.5, description="Pinion profile-shift coefficient x1")
    x2: float = Field(0.0, ge=-1, le=1.5, description="Gear profile-shift coefficient x2")
    open: bool = Field(True, description=(
        "Open gears (开式, designed by bending with a wear allowance) or closed (闭式); for the drive's checks"))
    pinion_material: Optional[str] = Field(None, max_length=40, description="Pinion material key for the drive's checks")
    gear_material: Optional[str] = Field(None, max_length=40, description="Gear material key for the drive's checks")
    face_width_factor: Optional[float] = Field(None, gt=0, le=2, description="Face width factor φd = b/d1")

    @field_validator("pinion_material", "gear_material")
    @classmethod
    def _material(cls, v):
        return check_material(v, "gear")

    @model_validator(mode="after")
    def _reduction(self):
        if self.z2 < self.z1:
            raise ValueError("z2 must be at least z1: gear 2 on the crank turns slower than the pinion")
        return self


def _fraction(value):
    """Accept 0.04 or the course's '1/25'."""
    return parse_fraction(value, "must be a number or a fraction such as 1/25")


class GuideBarFlywheel(StrictModel):
    """Flywheel design data (飞轮设计)."""

    fluctuation_delta: float = Field(gt=0, lt=1, description="Allowed speed fluctuation [δ], a number or '1/25'")
    shaft: Literal["pinion", "crank"] = Field(
        "pinion", description="Shaft carrying the flywheel: pinion (O1, z1) or crank (O2)")
    rim_diameter_mm: float = Field(500.0, gt=0, le=10000, description="Mean rim diameter D [mm]")
    rim_height_to_width: float = Field(1.5, gt=0, le=10, description="Rim height/width H/b")
    specific_weight_N_m3: float = Field(7.0e4, gt=0, le=3e5,
                                        description="Rim material specific weight γ [N/m³] (cast iron 7×10⁴)")

    _delta = field_validator("fluctuation_delta", mode="before")(classmethod(lambda cls, v: _fraction(v)))


class GuideBarBrief(StrictModel):
    """What every guide-bar machine's brief has; each machine sets ``machine``, ``linkage``
    and ``loads`` to its own sections."""

    machine: str = Field(description="Machine type")
    report: ReportMeta
    linkage: StrictModel
    masses: GuideBarMasses
    loads: StrictModel
    gear_pair: GearPair
    flywheel: GuideBarFlywheel
    cam: Optional[CamSection] = Field(None, description=(
        "Cam on the crank shaft (设计凸轮轮廓曲线); it turns with the crank, at the crank speed"))
    drive: Optional[DriveSection] = Field(None, description=(
        "Drive from the motor to the pinion shaft O1 (传动装置); the gear pair z1/z2 is its last stage"))
    analysis: AnalysisSettings = AnalysisSettings()
    sheets: SheetSettings = SheetSettings()

    @model_validator(mode="after")
    def _polygon_positions_exist(self):
        chosen = self.sheets.polygon_positions
        if chosen is None:
            return self
        count = int(round(360.0 / self.analysis.position_step_deg))
        bad = [p for p in chosen if not 1 <= p <= count]
        if bad:
            raise ValueError(f"sheets.polygon_positions: {bad[0]} is not a position; with "
                             f"analysis.position_step_deg = {self.analysis.position_step_deg:g} the "
                             f"positions are 1 … {count}")
        if chosen[0] == chosen[1]:
            raise ValueError("sheets.polygon_positions: give two different positions")
        return self

    @model_validator(mode="after")
    def _drive_needs_module(self):
        if self.drive is not None and self.gear_pair.module_mm is None:
            raise ValueError("gear_pair.module_mm is needed with a drive section: the gear pair is its last stage")
        return self

    @model_validator(mode="after")
    def _cam_on_crank_shaft(self):
        if self.cam is None:
            return self
        if self.cam.rotation != self.linkage.crank_rotation:
            raise ValueError(f"cam.rotation is {self.cam.rotation!r} but the cam is on the crank shaft "
                             f"and turns with it: linkage.crank_rotation is {self.linkage.crank_rotation!r}")
        if self.cam.speed_rpm is not None and self.cam.speed_rpm != self.linkage.crank_speed_n2_rpm:
            raise ValueError("cam.speed_rpm: the cam turns at the crank speed "
                             f"{self.linkage.crank_speed_n2_rpm:g} rpm; leave speed_rpm out")
        return self


@dataclass(frozen=True)
class GearParams:
    """The gear pair in SI (m, rad)."""

    m: float
    z1: int
    z2: int
    alpha: float
    ha_star: float
    c_star: float
    x1: float
    x2: float


def gear_to_si(g: GearPair) -> GearParams | None:
    if g.module_mm is None:
        return None
    return GearParams(g.module_mm * 1e-3, g.z1, g.z2, np.radians(g.pressure_angle_deg),
                      g.addendum_coeff, g.clearance_coeff, g.x1, g.x2)


def drive_to_si_with_gear(b: GuideBarBrief) -> DriveParams | None:
    """The drive section with the gear pair z1/z2 appended as its last stage."""
    if b.drive is None:
        return None
    g = b.gear_pair
    last = DriveStage(type="spur", z1=g.z1, z2=g.z2, module_mm=g.module_mm, open=g.open,
                      x1=g.x1, x2=g.x2, pinion_material=g.pinion_material,
                      gear_material=g.gear_material, face_width_factor=g.face_width_factor)
    return drive_to_si(b.drive.model_copy(update={"stages": list(b.drive.stages) + [last]}))
