"""Brief sections shared by the guide-bar (quick-return) machines — the shaper and the
slotter: masses, the gear pair z1/z2 that drives the crank, the flywheel, and the base of
their briefs (cam on the crank shaft, drive ending with the gear pair, analysis, sheets)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Literal, Optional

from pydantic import Field, field_validator, model_validator

from ..lazy import np
from .cam import CamParams, CamSection, cam_to_si
from .common import (AnalysisSettings, Problems, ReportMeta, SheetSettings, StrictModel,
                     parse_fraction)
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
    and ``loads`` to its own sections (the press too, with its own ``masses``; its linkage
    names the crank speed ``_crank_speed_field``)."""

    _crank_speed_field: ClassVar[str] = "crank_speed_n2_rpm"

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
    def _cross_fields(self):
        """Every cross-field problem at once, each at its field, in English and Chinese."""
        out = Problems(self)
        chosen = self.sheets.polygon_positions
        if chosen is not None:
            step = self.analysis.position_step_deg
            count = int(round(360.0 / step))
            for i, p in enumerate(chosen):
                if isinstance(p, int) and not 1 <= p <= count:   # a label: checked at run time
                    out.add(("sheets", "polygon_positions", i), p,
                            f"{p} is not a position: with analysis.position_step_deg = {step:g} the "
                            f"positions are 1 … {count}",
                            f"{p} 不是机构位置：analysis.position_step_deg = {step:g} 时位置为 1 … {count}")
            if len(chosen) == 2 and chosen[0] == chosen[1]:
                out.add(("sheets", "polygon_positions"), list(chosen),
                        "give two different positions", "应给出两个不同的位置")
        if self.drive is not None and self.gear_pair.module_mm is None:
            out.add(("gear_pair", "module_mm"), None,
                    "the module is needed with a drive section: the gear pair is its last stage",
                    "有传动装置（drive）时须给出模数：齿轮副是其最后一级")
        if self.cam is not None:
            sense = self.linkage.crank_rotation
            if self.cam.rotation != sense:
                out.add(("cam", "rotation"), self.cam.rotation,
                        f"the cam is on the crank shaft and turns with it: use {sense!r} "
                        f"(linkage.crank_rotation)",
                        f"凸轮装在曲柄轴上，随曲柄转动：应取 {sense!r}（linkage.crank_rotation）")
            n2 = getattr(self.linkage, self._crank_speed_field)
            if self.cam.speed_rpm is not None and self.cam.speed_rpm != n2:
                out.add(("cam", "speed_rpm"), self.cam.speed_rpm,
                        f"the cam turns at the crank speed {n2:g} rpm: leave speed_rpm out",
                        f"凸轮转速即曲柄转速 {n2:g} r/min：不要给出 speed_rpm")
        out.raise_any()
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


@dataclass(frozen=True)
class GuideBarParams:
    """What every guide-bar brief gives, in SI units (m, rad, rad/s, kg, N, kg·m²),
    converted once; each machine's parameters add their own fields."""

    stroke: float              # H [m]
    time_ratio_K: float
    frame: float               # L_O2O3 [m]
    rod_ratio: float           # L_rod / L_O3B
    com_ratio: float           # L_O3S4 / L_O3B
    crank_omega: float         # ω2, counter-clockwise positive [rad/s]
    crank_speed_rpm: float     # n2 [rpm]
    m4: float                  # [kg]
    J_S4: float                # [kg·m²]
    m6: float                  # [kg]
    G2: float                  # [N]
    cutting_force: float       # Fc [N]
    idle_travel_ratio: float
    z1: int
    z2: int
    fluctuation: float         # [δ]
    flywheel_shaft: str        # "pinion" | "crank"
    rim_diameter: float        # [m]
    rim_height_to_width: float
    specific_weight: float     # [N/m³]
    grid_points: int
    position_step: float       # [rad]
    gravity: float             # [m/s²]
    cam: CamParams | None = None
    gear: GearParams | None = None
    drive: DriveParams | None = None


def guide_bar_si(b: GuideBarBrief, rod_ratio: float) -> dict:
    """The :class:`GuideBarParams` fields of brief ``b`` (the rod ratio's field is named
    after each machine's rod)."""
    mm = 1e-3
    lk, ms = b.linkage, b.masses
    sense = -1.0 if lk.crank_rotation == "cw" else 1.0
    return dict(
        stroke=lk.stroke_H_mm * mm, time_ratio_K=lk.time_ratio_K, frame=lk.frame_O2O3_mm * mm,
        rod_ratio=rod_ratio, com_ratio=lk.com_ratio_O3S4_O3B,
        crank_omega=sense * lk.crank_speed_n2_rpm * 2.0 * np.pi / 60.0,
        crank_speed_rpm=lk.crank_speed_n2_rpm, m4=ms.guide_bar_m4_kg, J_S4=ms.guide_bar_J_S4_kgm2,
        m6=ms.ram_m6_kg, G2=ms.gear2_weight_G2_N, cutting_force=b.loads.cutting_force_Fc_N,
        idle_travel_ratio=b.loads.idle_travel_ratio, z1=b.gear_pair.z1, z2=b.gear_pair.z2,
        fluctuation=b.flywheel.fluctuation_delta, flywheel_shaft=b.flywheel.shaft,
        rim_diameter=b.flywheel.rim_diameter_mm * mm,
        rim_height_to_width=b.flywheel.rim_height_to_width,
        specific_weight=b.flywheel.specific_weight_N_m3, grid_points=b.analysis.grid_points,
        position_step=np.radians(b.analysis.position_step_deg), gravity=b.analysis.gravity,
        cam=None if b.cam is None else cam_to_si(b.cam, lk.crank_speed_n2_rpm),
        gear=gear_to_si(b.gear_pair), drive=drive_to_si_with_gear(b))
