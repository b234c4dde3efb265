"""Brief sections shared by the guide-bar (quick-return) machines — the shaper and the
slotter: masses, the gear pair z1/z2 that drives the crank, the flywheel, and the base of
their briefs (cam on the crank shaft, drive ending with the gear pair, analysis, sheets)."""
from __future__ import annotations

from dataclasses import dataclass
import math
from typing import ClassVar, Literal, Optional

from pydantic import Field, field_validator, model_validator

from ..lazy import np
from .cam import CamParams, CamSection, cam_to_si
from .common import (MISSING, AnalysisSettings, Problems, ReportMeta, RimHeightToWidth,
                     RimSpecificWeight, SheetSettings, StrictModel, parse_fraction)
from .drive import DriveParams, DriveSection, DriveStage, check_material, drive_to_si
from ..i18n import N_


class GuideBarMasses(StrictModel):
    """Mass properties (质量参数); all other links are massless. Each mass may be given as a
    mass in kg or as a weight in N (the course tables give G4, G6), exactly one of the two;
    a weight is divided by analysis.gravity."""

    guide_bar_m4_kg: Optional[float] = Field(None, ge=0, le=10000, description=(
        "Guide-bar mass m4 [kg] (or guide_bar_G4_N)"))
    guide_bar_G4_N: Optional[float] = Field(None, ge=0, le=1e5, description=(
        "Guide-bar weight G4 [N] (or guide_bar_m4_kg)"))
    guide_bar_J_S4_kgm2: float = Field(ge=0, le=10000,
                                       description="Guide-bar moment of inertia about S4, J_S4 [kg·m²]")
    ram_m6_kg: Optional[float] = Field(None, ge=0, le=100000, description="Ram mass m6 [kg] (or ram_G6_N)")
    ram_G6_N: Optional[float] = Field(None, ge=0, le=1e6, description="Ram weight G6 [N] (or ram_m6_kg)")
    gear2_weight_G2_N: float = Field(0.0, ge=0, le=1e6,
                                     description="Weight of gear 2 on the crank shaft, acting at O2, G2 [N] (or gear2_m2_kg)")
    gear2_m2_kg: Optional[float] = Field(None, ge=0, le=1e5, description=(
        "Mass of gear 2 on the crank shaft [kg] (or gear2_weight_G2_N)"))

    @model_validator(mode="after")
    def _mass_or_weight(self):
        out = Problems(self)
        for mass, weight in (("guide_bar_m4_kg", "guide_bar_G4_N"), ("ram_m6_kg", "ram_G6_N"),
                             ("gear2_m2_kg", "gear2_weight_G2_N")):
            given = [k for k in (mass, weight) if k in self.model_fields_set and getattr(self, k) is not None]
            if len(given) == 2:
                out.add(weight, getattr(self, weight), N_("give either {mass} or {weight}, not both"),
                                                       mass=mass, weight=weight)
            elif not given and weight != "gear2_weight_G2_N":
                out.add(mass, MISSING, N_("give the mass {mass} [kg] or the weight {weight} [N]"),
                                       mass=mass, weight=weight)
        out.raise_any()
        return self

    def si(self, g: float) -> tuple[float, float, float]:
        """(m4 [kg], m6 [kg], G2 [N]) with weights divided (and a gear mass multiplied) by g."""
        m4 = self.guide_bar_m4_kg if self.guide_bar_m4_kg is not None else self.guide_bar_G4_N / g
        m6 = self.ram_m6_kg if self.ram_m6_kg is not None else self.ram_G6_N / g
        g2 = self.gear2_weight_G2_N if self.gear2_m2_kg is None else self.gear2_m2_kg * g
        return m4, m6, g2


class GuideBarLinkage(StrictModel):
    """Guide-bar mechanism data (导杆机构), in either of the forms the course tables use:
    the stroke H and the time ratio K (synthesis), or the link lengths (the crank L_O2A and
    the guide bar L_O3B; H, K, θ and ψ then follow). The frame L_O2O3 is given in both; the
    rod as a length or as a ratio of L_O3B; the ram guide's distance L_O3M given or by the
    rule (through the mid-point of the sagitta of B's arc). Each machine adds its rod."""

    ROD: ClassVar[str] = "BF"

    stroke_H_mm: Optional[float] = Field(None, gt=0, le=5000, description=(
        "Ram stroke H [mm] (synthesis form, with time_ratio_K)"))
    time_ratio_K: Optional[float] = Field(None, gt=1.0, lt=3.0, description=(
        "Time ratio K (行程速比系数), 1 < K < 3 (synthesis form, with stroke_H_mm)"))
    crank_O2A_mm: Optional[float] = Field(None, gt=0, le=10000, description=(
        "Crank length L_O2A [mm] (link-length form, with guide_bar_O3B_mm; then H and K are derived)"))
    guide_bar_O3B_mm: Optional[float] = Field(None, gt=0, le=20000, description=(
        "Guide-bar length L_O3B [mm] (link-length form, with crank_O2A_mm)"))
    guide_O3M_mm: Optional[float] = Field(None, gt=0, le=20000, description=(
        "Distance L_O3M of the ram guide line from O3 [mm]; default: through the mid-point of "
        "the sagitta of B's arc, L_O3B(1 + cos(ψ/2))/2"))

    def rod_fields(self) -> tuple[str, str]:
        return f"rod_ratio_{self.ROD}_O3B", f"rod_{self.ROD}_mm"

    @model_validator(mode="after")
    def _form(self):
        """Either H and K or the link lengths; the rod as a ratio or a length; and the closed-form
        feasibility of the lengths (crank shorter than the frame, bar long enough for the pin)."""
        out = Problems(self)
        hk = [k for k in ("stroke_H_mm", "time_ratio_K") if getattr(self, k) is not None]
        ln = [k for k in ("crank_O2A_mm", "guide_bar_O3B_mm") if getattr(self, k) is not None]
        ratio_f, rod_f = self.rod_fields()
        d = self.frame_O2O3_mm
        if hk and ln:
            out.add(ln[0], getattr(self, ln[0]),
                    N_("give either stroke_H_mm and time_ratio_K (synthesis) or crank_O2A_mm and "
                       "guide_bar_O3B_mm (link lengths), not both: H and K follow from the lengths"))
        elif len(hk) == 1 or len(ln) == 1:
            missing = ({"stroke_H_mm", "time_ratio_K"} - set(hk)) if hk else \
                ({"crank_O2A_mm", "guide_bar_O3B_mm"} - set(ln))
            m = missing.pop()
            out.add(m, MISSING, N_("{m} is needed with {v1}"), m=m, v1=(hk or ln)[0])
        elif not hk and not ln:
            out.add("stroke_H_mm", MISSING,
                    N_("give stroke_H_mm and time_ratio_K, or the link lengths crank_O2A_mm and "
                       "guide_bar_O3B_mm"))
        ratio, rod = getattr(self, ratio_f), getattr(self, rod_f)
        if (ratio is None) == (rod is None):
            out.add(ratio_f, MISSING if ratio is None else ratio, N_("give the rod as {ratio_f} "
                                                                     "(L_{ROD}/L_O3B) or as {rod_f}, exactly "
                                                                     "one"),
                                                                  ratio_f=ratio_f, ROD=self.ROD, rod_f=rod_f)
        if out.items:
            out.raise_any()
        if ln:
            r, bar = self.crank_O2A_mm, self.guide_bar_O3B_mm
            if r >= d:
                out.add("crank_O2A_mm", r,
                        N_("the crank L_O2A = {r:g} mm must be shorter than the frame L_O2O3 = "
                           "{d:g} mm: otherwise the guide bar turns fully round and there is no "
                           "quick return"), r=r, d=d)
                out.raise_any()
            half = math.asin(r / d)
        else:
            theta = math.pi * (self.time_ratio_K - 1.0) / (self.time_ratio_K + 1.0)
            half = theta / 2.0
            r, bar = d * math.sin(half), self.stroke_H_mm / (2.0 * math.sin(half))
        if bar < d + r:
            if ln:
                out.add("guide_bar_O3B_mm", bar,
                        N_("the guide bar L_O3B = {bar:g} mm is shorter than the crank pin's "
                           "reach L_O2O3 + L_O2A = {v1:g} mm: the slider A would run off the bar; "
                           "lengthen the bar to at least {v1:g} mm"), bar=bar, v1=d + r)
            else:
                need = 2.0 * math.sin(half) * (d + r)
                out.add("stroke_H_mm", self.stroke_H_mm,
                        N_("with L_O2O3 = {d:g} mm and K = {time_ratio_K:g} the guide bar L_O3B = "
                           "H/(2 sin(ψ/2)) = {bar:.6g} mm is shorter than the crank pin's reach "
                           "L_O2O3 + L_O2A = {v1:.6g} mm (the crank circle would leave the bar): "
                           "take H ≥ {need:.6g} mm or a shorter frame"),
                        d=d, time_ratio_K=self.time_ratio_K, bar=bar, v1=d + r, need=need)
        h = self.guide_O3M_mm
        if h is not None and not out.items:
            rod_len = rod if rod is not None else ratio * bar
            low = bar * math.cos(half)
            reach = max(abs(bar - h), abs(low - h))
            if reach > rod_len:
                out.add("guide_O3M_mm", h,
                        N_("the rod L_{ROD} = {rod_len:.6g} mm cannot reach the guide line at "
                           "L_O3M = {h:g} mm from B, which moves between {low:.6g} and {bar:.6g} "
                           "mm from O3 along the guide's normal: take L_O3M between {v1:.6g} and "
                           "{v2:.6g} mm"),
                        ROD=self.ROD, rod_len=rod_len, h=h, low=low, bar=bar, v1=bar - rod_len, v2=low + rod_len)
        out.raise_any()
        return self

    def derived(self) -> dict:
        """H [mm], K, θ = ψ [rad], L_O2A, L_O3B [mm] in closed form (no numpy)."""
        d = self.frame_O2O3_mm
        if self.crank_O2A_mm is not None:
            r, bar = self.crank_O2A_mm, self.guide_bar_O3B_mm
            theta = 2.0 * math.asin(r / d)
            return dict(stroke=2.0 * bar * r / d, K=(math.pi + theta) / (math.pi - theta),
                        theta=theta, crank=r, bar=bar, given=True)
        K = self.time_ratio_K
        theta = math.pi * (K - 1.0) / (K + 1.0)
        return dict(stroke=self.stroke_H_mm, K=K, theta=theta, crank=None, bar=None, given=False)


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
            out = Problems(self)
            out.add(("z2",), self.z2,
                    N_("z2 must be at least z1 = {z1}: gear 2 on the crank turns slower than the "
                       "pinion (a reduction); raise z2 or lower z1"), z1=self.z1)
            out.raise_any()
        return self


def _fraction(value):
    """Accept 0.04 or the course's '1/25'."""
    return parse_fraction(value, N_("must be a number or a fraction such as 1/25"))


class GuideBarFlywheel(StrictModel):
    """Flywheel design data (飞轮设计)."""

    fluctuation_delta: float = Field(gt=0, lt=1, description="Allowed speed fluctuation [δ], a number or '1/25'")
    shaft: Optional[Literal["pinion", "crank"]] = Field(None, description=(
        "Shaft carrying the flywheel: pinion (O1, z1) or crank (O2); default: pinion when the "
        "brief has a gear_pair, else crank (the pinion shaft's speed needs the gear ratio)"))
    rim_diameter_mm: float = Field(500.0, gt=0, le=10000, description="Mean rim diameter D [mm]")
    rim_height_to_width: RimHeightToWidth = 1.5
    specific_weight_N_m3: RimSpecificWeight = 7.0e4

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
    gear_pair: Optional[GearPair] = Field(None, description=(
        "The gear pair z1/z2 driving the crank (optional; needed for a flywheel on the pinion "
        "shaft and for a drive)"))
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
                            N_("{p} is not a position: with analysis.position_step_deg = {step:g} "
                               "the positions are 1 … {count}"), p=p, step=step, count=count)
            if len(chosen) == 2 and chosen[0] == chosen[1]:
                out.add(("sheets", "polygon_positions"), list(chosen),
                        N_("give two different positions"))
        if self.gear_pair is None:
            if self.flywheel.shaft == "pinion":
                out.add(("flywheel", "shaft"), "pinion",
                        N_("a flywheel on the pinion shaft needs the gear ratio z2/z1: add a "
                           "gear_pair section or put the flywheel on the crank (shaft: crank)"))
            if self.drive is not None:
                out.add(("drive",), "…",
                        N_("the drive ends with the gear pair z1/z2 that turns the crank: add a "
                           "gear_pair section"))
        elif self.drive is not None and self.gear_pair.module_mm is None:
            out.add(("gear_pair", "module_mm"), MISSING,
                    N_("the module is needed with a drive section: the gear pair is its last stage"))
        if self.cam is not None:
            sense = self.linkage.crank_rotation
            if self.cam.rotation != sense and "rotation" in self.cam.model_fields_set:
                out.add(("cam", "rotation"), self.cam.rotation,
                        N_("the cam is on the crank shaft and turns with it: use {sense!r} "
                           "(linkage.crank_rotation)"), sense=sense)
            elif self.cam.rotation != sense:   # the cam's default sense: say so at the cam
                out.add(("cam",), "…",
                        N_("the cam is on the crank shaft and turns with it: set cam.rotation: "
                           "{sense!r} (linkage.crank_rotation)"), sense=sense)
            n2 = getattr(self.linkage, self._crank_speed_field)
            if self.cam.speed_rpm is not None and self.cam.speed_rpm != n2:
                out.add(("cam", "speed_rpm"), self.cam.speed_rpm,
                        N_("the cam turns at the crank speed {n2:g} rpm: leave speed_rpm out"),
                        n2=n2)
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
    if b.drive is None or b.gear_pair is None:
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
    z1: int | None             # None: no gear pair
    z2: int | None
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
    crank: float | None = None         # L_O2A [m] when the brief gives the link lengths
    guide_bar: float | None = None     # L_O3B [m], likewise
    rod: float | None = None           # the rod's length [m] when given as a length
    guide_height: float | None = None  # L_O3M [m] when given (else the mid-sagitta rule)


def guide_bar_si(b: GuideBarBrief) -> dict:
    """The :class:`GuideBarParams` fields of brief ``b``: H and K as given, or derived in
    closed form from the link lengths (which are then kept exactly, never recomputed)."""
    mm = 1e-3
    lk, ms = b.linkage, b.masses
    sense = -1.0 if lk.crank_rotation == "cw" else 1.0
    ratio_f, rod_f = lk.rod_fields()
    rod = getattr(lk, rod_f)
    dv = lk.derived()
    bar_mm = dv["bar"] if dv["given"] else dv["stroke"] / (2.0 * np.sin(dv["theta"] / 2.0))
    rod_ratio = getattr(lk, ratio_f) if rod is None else rod / bar_mm
    m4, m6, g2 = ms.si(b.analysis.gravity)
    gp = b.gear_pair
    shaft = b.flywheel.shaft or ("pinion" if gp is not None else "crank")
    return dict(
        stroke=dv["stroke"] * mm, time_ratio_K=dv["K"], frame=lk.frame_O2O3_mm * mm,
        rod_ratio=rod_ratio, com_ratio=lk.com_ratio_O3S4_O3B,
        crank_omega=sense * lk.crank_speed_n2_rpm * 2.0 * np.pi / 60.0,
        crank_speed_rpm=lk.crank_speed_n2_rpm, m4=m4, J_S4=ms.guide_bar_J_S4_kgm2,
        m6=m6, G2=g2, cutting_force=b.loads.cutting_force_Fc_N,
        idle_travel_ratio=b.loads.idle_travel_ratio, z1=None if gp is None else gp.z1,
        z2=None if gp is None else gp.z2,
        crank=None if dv["crank"] is None else dv["crank"] * mm,
        guide_bar=None if dv["bar"] is None else dv["bar"] * mm,
        rod=None if rod is None else rod * mm,
        guide_height=None if lk.guide_O3M_mm is None else lk.guide_O3M_mm * mm,
        fluctuation=b.flywheel.fluctuation_delta, flywheel_shaft=shaft,
        rim_diameter=b.flywheel.rim_diameter_mm * mm,
        rim_height_to_width=b.flywheel.rim_height_to_width,
        specific_weight=b.flywheel.specific_weight_N_m3, grid_points=b.analysis.grid_points,
        position_step=np.radians(b.analysis.position_step_deg), gravity=b.analysis.gravity,
        cam=None if b.cam is None else cam_to_si(b.cam, lk.crank_speed_n2_rpm),
        gear=None if gp is None else gear_to_si(gp), drive=drive_to_si_with_gear(b))
