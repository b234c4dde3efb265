"""Drive briefs (传动装置): the ``drive:`` section any machine brief may carry, and the
stand-alone drive brief (``machine: drive``) whose load is given instead of computed.

Course units in the brief (kW, rpm, mm, N, N·m, h); :func:`drive_to_si` converts once.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Literal, Optional, Union

from ..lazy import np
from pydantic import Field, field_validator, model_validator

from .common import Msg, Problems, StrictModel, invalid
from ..i18n import N_

#: Smallest tooth number of a roller-chain sprocket (机械设计手册: z_min = 9; z1 ≥ 17 advised).
CHAIN_Z_MIN = 9

StageType = Literal["coupling", "belt", "chain", "spur", "helical", "worm"]

_FIELDS_BY_TYPE = {
    "coupling": {"application_factor_KA"},
    "belt": {"ratio", "d1_mm", "d2_mm", "slip", "section", "center_distance_mm", "application_factor_KA"},
    "chain": {"ratio", "z1", "z2", "chain", "rows", "center_distance_mm", "application_factor_KA"},
    "spur": {"ratio", "z1", "z2", "module_mm", "open", "face_width_factor", "pinion_material",
             "gear_material", "x1", "x2", "span_mm"},
    "helical": {"ratio", "z1", "z2", "module_mm", "helix_angle_deg", "face_width_factor",
                "pinion_material", "gear_material", "span_mm"},
    "worm": {"ratio", "z1", "z2", "module_mm", "q", "x2", "wheel_material", "span_mm"},
}
_OPTIONAL = ("ratio", "d1_mm", "d2_mm", "slip", "z1", "z2", "module_mm", "open", "face_width_factor",
             "pinion_material", "gear_material", "x1", "x2", "helix_angle_deg", "q",
             "wheel_material", "span_mm", "section", "center_distance_mm", "application_factor_KA",
             "chain", "rows")


def check_material(value: str | None, which: str) -> str | None:
    """A material key must be in the shipped catalogue (mechdesign/data/materials.yaml)."""
    from ..data import catalogues as cat

    if value is None:
        return value
    try:
        {"gear": cat.gear_material, "wheel": cat.worm_wheel_material}[which](value)
    except KeyError as exc:       # its message lists the allowed keys
        allowed = str(exc.args[0]).partition("allowed: ")[2]
        raise invalid(N_("not in the shipped material catalogue; allowed: {allowed} (or the "
                         "Chinese name, e.g. {example})"), allowed=allowed,
                      example=cat.gear_material("45_QT").name_zh) from None
    return value


class DriveStage(StrictModel):
    """One element of the drive, listed from the motor to the machine (电动机 → 工作机).
    A ratio is fixed by ``ratio``, by both tooth numbers or by both pulley diameters;
    otherwise the program allocates it."""

    type: StageType = Field(description=(
        "coupling (联轴器), belt (V带), chain (链), spur (直齿圆柱齿轮), helical (斜齿), worm (蜗杆)"))
    ratio: Optional[float] = Field(None, ge=1, le=100, description="Stage ratio i = n_in/n_out (fixes it)")
    z1: Optional[int] = Field(None, ge=1, le=200, description=(
        "Teeth of the driving gear / sprocket, or worm starts (蜗杆头数) [count]"))
    z2: Optional[int] = Field(None, ge=8, le=1000, description="Teeth of the driven gear / wheel [count]")
    module_mm: Union[Annotated[float, Field(gt=0, le=100)], Literal["auto"], None] = Field(None, description=(
        "Module m [mm] (normal module for helical; axial for worm); 'auto' (default) sizes it "
        "by the strength design formula and takes the next standard module"))
    open: Optional[bool] = Field(None, description=(
        "Spur pair only: open gears (开式), designed by bending with a wear allowance"))
    face_width_factor: Optional[float] = Field(None, gt=0, le=2, description=(
        "Face width factor φd = b/d1 (default 1.0 closed, 0.5 open)"))
    pinion_material: Optional[str] = Field(None, max_length=40, description="Pinion material key (default 40Cr_QT)")
    gear_material: Optional[str] = Field(None, max_length=40, description="Gear material key (default 45_QT)")
    x1: Optional[float] = Field(None, ge=-1, le=1.5, description="Pinion profile-shift coefficient x1")
    x2: Optional[float] = Field(None, ge=-1, le=1.5, description=(
        "Gear (or worm-wheel) profile-shift coefficient x2"))
    helix_angle_deg: Optional[float] = Field(None, ge=8, le=25, description="Helix angle β [°] (default 14)")
    q: Optional[float] = Field(None, ge=6, le=20, description="Worm diameter factor q = d1/m (default 10)")
    wheel_material: Optional[str] = Field(None, max_length=40, description="Worm-wheel rim material key (default ZCuSn10P1)")
    d1_mm: Optional[float] = Field(None, gt=20, le=2000, description="Small pulley datum diameter d1 [mm] (default 100)")
    d2_mm: Optional[float] = Field(None, gt=20, le=5000, description="Large pulley datum diameter d2 [mm]")
    slip: Optional[float] = Field(None, ge=0, le=0.05, description="Belt elastic slip ε (default 0.015)")
    section: Optional[Literal["Z", "A", "B"]] = Field(None, description=(
        "V-belt section (带型), default from the selection chart (濮良贵 fig. 8-11) by P_ca and n1"))
    chain: Optional[Literal["08A", "10A", "12A", "16A", "20A", "24A", "28A", "32A"]] = Field(None, description=(
        "Roller chain number (链号, A series); default the smallest whose rated power carries P_ca"))
    rows: Optional[int] = Field(None, ge=1, le=3, description="Roller chain rows (排数, default 1)")
    center_distance_mm: Optional[float] = Field(None, gt=50, le=5000, description=(
        "Initial centre distance a0 [mm]: V-belt default d1 + d2 rounded up to 10 mm "
        "(0.7 (d1 + d2) … 2 (d1 + d2)); chain default 40 p (30 … 50 p)"))
    application_factor_KA: Optional[float] = Field(None, ge=1, le=2.5, description=(
        "Application factor K_A of the belt (工况系数, 濮良贵 table 8-8), the chain (table 9-6) or "
        "the coupling from the motor (table 14-1); default from the drive's load class (and, for "
        "belts, the hours per day)"))
    span_mm: Optional[float] = Field(None, gt=20, le=3000, description=(
        "Bearing span of the stage's output shaft [mm] (default: face width + 2 × 60 mm; a shaft "
        "driving a worm 0.9 d2, the span of its deflection check)"))
    efficiency: Optional[float] = Field(None, gt=0.3, le=1, description=(
        "Efficiency of the stage, overriding the textbook default (worm: computed)"))

    @field_validator("pinion_material", "gear_material")
    @classmethod
    def _gear_material(cls, v):
        return check_material(v, "gear")

    @field_validator("wheel_material")
    @classmethod
    def _wheel_material(cls, v):
        return check_material(v, "wheel")

    @model_validator(mode="after")
    def _fields_fit_type(self):
        out = Problems(self)
        allowed = _FIELDS_BY_TYPE[self.type]
        names = ", ".join(sorted(allowed | {"type", "efficiency"}))
        for n in _OPTIONAL:
            if getattr(self, n) is not None and n not in allowed:
                out.add(n, getattr(self, n),
                        N_("a {type} stage has no {n}: remove it (fields of a {type} stage: "
                           "{names})"), type=self.type, n=n, names=names)
        if self.type == "belt" and (self.d1_mm and self.d2_mm) and self.d2_mm < self.d1_mm:
            out.add("d2_mm", self.d2_mm,
                    N_("a reduction drive: the driven pulley d2 must be at least d1_mm = {d1_mm:g}"),
                    d1_mm=self.d1_mm)
        if self.type == "belt" and self.center_distance_mm is not None and self.d1_mm and self.d2_mm:
            lo, hi = 0.7 * (self.d1_mm + self.d2_mm), 2 * (self.d1_mm + self.d2_mm)
            if not lo <= self.center_distance_mm <= hi:
                out.add("center_distance_mm", self.center_distance_mm,
                        N_("the initial centre distance must lie in 0.7 (d1 + d2) … 2 (d1 + d2) = "
                           "{lo:g} … {hi:g} mm"), lo=lo, hi=hi)
        if self.z1 is not None and self.z2 is not None and self.z2 < self.z1:
            what = (Msg.pgettext("drive stage", "worm wheel") if self.type == "worm" else
                    Msg.pgettext("drive stage", "driven wheel"))
            out.add("z2", self.z2, N_("z2 must be at least z1 = {z1}: a reduction stage (the "
                                      "{what} turns slower than the driver)"),
                                   z1=self.z1, what=what)
        if self.type == "chain":
            for key in ("z1", "z2"):
                z = getattr(self, key)
                if z is not None and z < CHAIN_Z_MIN:
                    out.add(key, z,
                            N_("a roller-chain sprocket needs at least {CHAIN_Z_MIN} teeth (17 or "
                               "more recommended for smooth running); give more teeth"),
                            CHAIN_Z_MIN=CHAIN_Z_MIN)
        fixes = [n for n, given in (("ratio", self.ratio is not None),
                                    ("z1/z2", self.z1 is not None and self.z2 is not None),
                                    ("d1_mm/d2_mm", self.d1_mm is not None and self.d2_mm is not None))
                 if given]
        if len(fixes) > 1 and "ratio" in fixes:
            other = fixes[1]
            out.add("ratio", self.ratio,
                    N_("the ratio is fixed twice: {other} already fix it; remove `ratio` (or one "
                       "of {other})"), other=other)
        out.raise_any()
        return self


class MotorSpec(StrictModel):
    """Motor (电动机): Y-series three-phase asynchronous motor from the shipped catalogue."""

    synchronous_rpm: Union[Literal[750, 1000, 1500, 3000], Literal["auto"]] = Field(
        "auto", description="Synchronous speed [rpm]: 750, 1000, 1500, 3000 or auto")
    speed_tolerance_pct: float = Field(5.0, gt=0, le=20, description=(
        "Allowed error of the machine's speed [%] (转速误差)"))


class ServiceConditions(StrictModel):
    """Service conditions (工作条件)."""

    life_years: float = Field(10, gt=0, le=50, description="Service life [years]")
    days_per_year: float = Field(300, gt=0, le=366, description="Working days per year [d]")
    hours_per_day: float = Field(16, gt=0, le=24, description="Working hours per day [h] (two shifts: 16)")
    application_factor_KA: float = Field(1.25, ge=1, le=3, description=(
        "Application factor K_A (使用系数): 1.0 uniform, 1.25 moderate shocks, 1.75 heavy"))


class DriveEfficiencies(StrictModel):
    """Efficiencies not tied to one stage."""

    bearing_pair: float = Field(0.99, gt=0.9, le=1, description="One pair of rolling bearings η_b")
    machine: float = Field(1.0, gt=0.3, le=1, description=(
        "The machine's own mechanism η_w (1 when its crank torque is computed without friction)"))


class ShaftOverride(StrictModel):
    """Choices for one shaft that override the design (轴、轴承、键的指定); each is checked
    and a failing one is reported with what to change."""

    shaft: int = Field(ge=1, le=8, description=(
        "Shaft number Ⅰ, Ⅱ, … (1 = the first after the motor; the last drives the machine)"))
    material: Optional[str] = Field(None, max_length=40, description=(
        "Shaft material key (default 45_QT, 45 steel quenched and tempered; [σ-1b] from 表15-1)"))
    end_mm: Optional[float] = Field(None, ge=10, le=300, description=(
        "Diameter at the overhung hub (pulley, sprocket, coupling) [mm] (default: A0∛(P/n) "
        "with the keyway, rounded up to the standard series and upsized until it passes)"))
    journal_mm: Optional[float] = Field(None, ge=10, le=300, description=(
        "Bearing journal diameter [mm], a multiple of 5 (the bearing bore) (default: designed)"))
    seat_mm: Optional[float] = Field(None, ge=10, le=300, description=(
        "Diameter of the hub seat between the bearings [mm] (default: journal + 5 mm)"))
    bearing: Optional[str] = Field(None, max_length=10, description=(
        "Bearing designation from the catalogue, e.g. 6207 or 30207 (default: the lightest "
        "series whose life reaches the service life)"))
    key_length_mm: Optional[float] = Field(None, ge=6, le=500, description=(
        "Length of the flat keys on this shaft [mm], a standard length of GB/T 1096 (default: "
        "the longest standard length ≤ hub − 8 mm)"))

    @field_validator("material")
    @classmethod
    def _material(cls, v):
        from ..data import catalogues as cat

        if v is None:
            return v
        try:
            cat.shaft_material(v)
        except KeyError as exc:
            allowed = str(exc.args[0]).partition("allowed: ")[2]
            raise invalid(N_("not in the shipped shaft-material catalogue; allowed: {allowed}"),
                          allowed=allowed) from None
        return v

    @model_validator(mode="after")
    def _consistent(self):
        from ..data import catalogues as cat

        out = Problems(self)
        if self.journal_mm is not None and abs(self.journal_mm / 5 - round(self.journal_mm / 5)) > 1e-9:
            out.add("journal_mm", self.journal_mm,
                    N_("a bearing bore is a multiple of 5 mm (20, 25, 30, …): give the journal as "
                       "one"))
        if self.journal_mm is not None and self.seat_mm is not None and self.seat_mm < self.journal_mm:
            out.add("seat_mm", self.seat_mm,
                    N_("the hub seat must be at least the journal_mm = {journal_mm:g} (the hub "
                       "slides over the journal when it is mounted)"), journal_mm=self.journal_mm)
        if self.end_mm is not None and self.journal_mm is not None and self.end_mm > self.journal_mm:
            out.add("end_mm", self.end_mm,
                    N_("the overhung end must not exceed the journal_mm = {journal_mm:g} (the "
                       "bearing is mounted over the end)"), journal_mm=self.journal_mm)
        if self.bearing is not None:
            try:
                b = cat.bearing(self.bearing)
            except KeyError:
                allowed = ", ".join(cat.bearing_designations())
                out.add("bearing", self.bearing, N_("not in the bearing catalogue; allowed: "
                                                    "{allowed}"), allowed=allowed)
            else:
                bore = b.d * 1e3
                if self.journal_mm is not None and abs(bore - self.journal_mm) > 1e-6:
                    out.add("bearing", self.bearing,
                            N_("its bore is {bore:g} mm, the journal_mm is {journal_mm:g}: give a "
                               "bearing of bore {journal_mm:g} mm or change journal_mm"),
                            bore=bore, journal_mm=self.journal_mm)
        if self.key_length_mm is not None:
            series = cat.key_length_series()
            if not any(abs(L * 1e3 - self.key_length_mm) < 1e-6 for L in series):
                allowed = ", ".join(f"{L * 1e3:g}" for L in series)
                out.add("key_length_mm", self.key_length_mm,
                        N_("not a standard key length (GB/T 1096); allowed: {allowed}"),
                        allowed=allowed)
        out.raise_any()
        return self


class DriveFactors(StrictModel):
    """Factors of the gear-stage strength design (齿轮强度计算的系数); K_A is in ``service``."""

    K_V: Optional[float] = Field(None, ge=1, le=2, description=(
        "Dynamic factor K_V (default 1.1: 8-grade gears at moderate speed, 图10-8)"))
    K_beta: Optional[float] = Field(None, ge=1, le=2, description=(
        "Face load factor K_β (default 1.1: gears between the bearings, 表10-4)"))
    S_F: Optional[float] = Field(None, ge=1, le=3, description=(
        "Safety factor of bending fatigue S_F (default 1.4, 例题10-1)"))
    S_H: Optional[float] = Field(None, ge=0.8, le=2, description=(
        "Safety factor of contact fatigue S_H (default 1.0)"))


class DriveSection(StrictModel):
    """The drive from the motor to the machine (传动装置)."""

    stages: list[DriveStage] = Field(min_length=1, max_length=8, description=(
        "Transmission elements from the motor to the machine"))
    motor: MotorSpec = MotorSpec()
    service: ServiceConditions = ServiceConditions()
    efficiencies: DriveEfficiencies = DriveEfficiencies()
    shafts: list[ShaftOverride] = Field(default_factory=list, max_length=8, description=(
        "Overrides of the shaft, bearing and key design, by shaft (default: all designed)"))
    factors: DriveFactors = DriveFactors()

    @model_validator(mode="after")
    def _shafts_exist(self):
        out = Problems(self)
        seen = set()
        n = len(self.stages)
        for i, o in enumerate(self.shafts):
            if o.shaft > n:
                out.add(("shafts", i, "shaft"), o.shaft,
                        N_("the drive has shafts 1–{n} after the motor (one per stage)"), n=n)
            if o.shaft in seen:
                out.add(("shafts", i, "shaft"), o.shaft, N_("this shaft is given twice: merge the "
                                                            "entries"))
            seen.add(o.shaft)
        out.raise_any()
        return self


# --------------------------------------------------------------------------------------
# SI parameters

@dataclass(frozen=True)
class StageParams:
    type: str
    ratio: float | None
    z1: int | None
    z2: int | None
    module: float | None        # [m]; None = auto
    open: bool
    face_width_factor: float | None
    pinion_material: str | None
    gear_material: str | None
    x1: float
    x2: float
    helix_angle: float          # [rad]
    q: float
    wheel_material: str | None
    d1: float | None            # [m]
    d2: float | None            # [m]
    slip: float
    span: float | None          # [m]
    efficiency: float | None
    index: int                  # position in the brief's list (for messages)
    section: str | None = None          # V-belt section; None = from the selection chart
    center_distance: float | None = None  # [m] V-belt a0; None = default
    belt_KA: float | None = None        # V-belt / chain K_A; None = table 8-8 / 9-6
    chain: str | None = None            # chain number; None = from the rated power
    rows: int = 1                       # chain rows


@dataclass(frozen=True)
class DriveParams:
    stages: tuple[StageParams, ...]
    synchronous_rpm: float | None
    speed_tolerance: float      # fraction
    service_hours: float        # [h]
    KA: float
    bearing_eff: float
    machine_eff: float
    shafts: tuple = ()          # ShaftChoice, by shaft number
    factors: tuple = ()         # (name, value) of the given gear factors (K_V, K_beta, S_F, S_H)
    hours_per_day: float = 16.0  # [h] (the belt's K_A, table 8-8)


@dataclass(frozen=True)
class ShaftChoice:
    """A shaft override in SI (m); None = designed."""
    shaft: int
    material: str | None
    end: float | None
    journal: float | None
    seat: float | None
    bearing: str | None
    key_length: float | None
    index: int                  # position in drive.shafts (for messages)


def _stage_to_si(s: DriveStage, index: int) -> StageParams:
    mm = 1e-3
    return StageParams(
        type=s.type, ratio=s.ratio, z1=s.z1, z2=s.z2,
        module=None if s.module_mm in (None, "auto") else s.module_mm * mm,
        open=bool(s.open), face_width_factor=s.face_width_factor,
        pinion_material=s.pinion_material, gear_material=s.gear_material,
        x1=s.x1 or 0.0, x2=s.x2 or 0.0,
        helix_angle=np.radians(s.helix_angle_deg if s.helix_angle_deg is not None else 14.0)
        if s.type == "helical" else 0.0,
        q=s.q if s.q is not None else 10.0,
        wheel_material=s.wheel_material,
        d1=None if s.d1_mm is None else s.d1_mm * mm, d2=None if s.d2_mm is None else s.d2_mm * mm,
        slip=s.slip if s.slip is not None else 0.015,
        span=None if s.span_mm is None else s.span_mm * mm,
        efficiency=s.efficiency, index=index, section=s.section,
        center_distance=None if s.center_distance_mm is None else s.center_distance_mm * mm,
        belt_KA=s.application_factor_KA, chain=s.chain, rows=s.rows or 1)


def drive_to_si(d: DriveSection) -> DriveParams:
    sv = d.service
    sync = None if d.motor.synchronous_rpm == "auto" else float(d.motor.synchronous_rpm)
    return DriveParams(
        stages=tuple(_stage_to_si(s, i) for i, s in enumerate(d.stages)),
        synchronous_rpm=sync, speed_tolerance=d.motor.speed_tolerance_pct / 100.0,
        service_hours=sv.life_years * sv.days_per_year * sv.hours_per_day, KA=sv.application_factor_KA,
        bearing_eff=d.efficiencies.bearing_pair, machine_eff=d.efficiencies.machine,
        shafts=tuple(ShaftChoice(o.shaft, o.material, _mm(o.end_mm), _mm(o.journal_mm), _mm(o.seat_mm),
                                 o.bearing, _mm(o.key_length_mm), i) for i, o in enumerate(d.shafts)),
        factors=tuple((k, v) for k, v in d.factors.model_dump().items() if v is not None),
        hours_per_day=sv.hours_per_day)


def _mm(v: float | None) -> float | None:
    return None if v is None else v * 1e-3


