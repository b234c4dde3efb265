"""Brief of ``machine: crank_rocker``: crank-rocker synthesis from the time ratio K
(按行程速比系数设计曲柄摇杆机构), the crank-rocker with the largest minimum transmission
angle, the design chart, and optionally an offset slider-crank (偏置曲柄滑块机构).

Course units in the brief (mm, °, rpm); :func:`crank_rocker_to_si` converts once to SI.
Data that admit no linkage are rejected here, naming the field and the range that works.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING
from typing import Literal, Optional

from ...lazy import np
from pydantic import Field, field_validator, model_validator

from ...brief.common import MISSING, Problems, ReportMeta, StrictModel, invalid
from ...brief.rules import crank_rocker_problems, raise_missing  # noqa: F401  (shared)
from ...i18n import N_

if TYPE_CHECKING:
    from ...core import fourbar

_DEFAULT_THETAS = [0.0, 5.0, 10.0, 15.0, 20.0, 25.0, 30.0]


class SliderDimensions(StrictModel):
    """The offset slider-crank's link lengths as a data table gives them."""

    crank_mm: float = Field(gt=0, le=10000, description="Crank AB [mm]")
    rod_mm: float = Field(gt=0, le=100000, description="Connecting rod BC [mm]")


class SliderCrankSection(StrictModel):
    """Offset slider-crank (偏置曲柄滑块机构): designed from K, the stroke H and the offset e,
    or given by its dimensions (crank, rod and e), from which H, θ and K are derived."""

    time_ratio_K: Optional[float] = Field(None, gt=1, lt=3, description=(
        "Time ratio K of the slider (行程速比系数), 1 < K < 3 (dimensionless); with stroke_H_mm, "
        "or leave both out and give dimensions"))
    stroke_H_mm: Optional[float] = Field(None, gt=0, le=10000, description=(
        "Slider stroke H [mm]; with time_ratio_K, or give dimensions"))
    offset_e_mm: float = Field(gt=0, le=10000, description=(
        "Offset e of the slider guide from the crank pivot [mm]; must be below H·cot θ"))
    dimensions: Optional[SliderDimensions] = Field(None, description=(
        "Given dimensions (给定尺寸) instead of K and H: no synthesis; H, θ and K are computed "
        "from them"))

    @model_validator(mode="after")
    def _one_form(self):
        out = Problems(self)
        if self.dimensions is None:
            raise_missing(self, [n for n in ("time_ratio_K", "stroke_H_mm") if getattr(self, n) is None])
        else:
            for name in ("time_ratio_K", "stroke_H_mm"):
                if getattr(self, name) is not None:
                    out.add((name,), getattr(self, name),
                            N_("{name}: with dimensions given, H and K are computed from them; "
                               "remove {name} (or remove dimensions to design from K and H)"), name=name)
            dm = self.dimensions
            if not dm.crank_mm + self.offset_e_mm < dm.rod_mm:
                out.add(("dimensions", "rod_mm"), dm.rod_mm,
                        N_("dimensions.rod_mm = {rod:g}: the crank turns fully only with rod > "
                           "crank + e = {crank:g} + {e:g} = {sum:g} mm"),
                        rod=dm.rod_mm, crank=dm.crank_mm, e=self.offset_e_mm, sum=dm.crank_mm + self.offset_e_mm)
        out.raise_any()
        return self


class ChartSettings(StrictModel):
    """Design chart (设计线图): optimum l3/l4 and γmin against ψ, one curve per θ."""

    theta_deg: list[float] = Field(default_factory=lambda: list(_DEFAULT_THETAS), min_length=1,
                                   max_length=12, description=(
                                       "Extreme-position angles θ of the curves [°], each 0 ≤ θ < 90"))
    swing_deg: list[float] = Field(default_factory=lambda: [10.0, 120.0], min_length=2,
                                   max_length=2, description=(
                                       "Range of the rocker swing ψ on the chart [from, to] [°], "
                                       "0 < from < to < 180"))
    points: int = Field(56, ge=5, le=400, description="Swing values per curve (count)")

    @field_validator("theta_deg")
    @classmethod
    def _thetas(cls, value):
        bad = [x for x in value if not 0.0 <= x < 90.0]
        if bad:
            raise invalid(N_("each θ must be in [0°, 90°); got {bad}"), bad=bad)
        return sorted(set(value))

    @field_validator("swing_deg")
    @classmethod
    def _swings(cls, value):
        lo, hi = value
        if not 0.0 < lo < hi < 180.0:
            raise invalid(N_("swing_deg must be [from, to] with 0 < from < to < 180; got {value}"),
                          value=value)
        return value


class CompareDesign(StrictModel):
    """A published or hand-made design to check by simulation (e.g. a paper's result)."""

    label: str = Field(min_length=1, max_length=60, description="Name shown in the report, e.g. 'paper, computer result'")
    crank_mm: float = Field(gt=0, le=100000, description="Crank l1 [mm]")
    coupler_mm: float = Field(gt=0, le=100000, description="Coupler l2 [mm]")
    rocker_mm: Optional[float] = Field(None, gt=0, le=100000,
                                       description="Rocker l3 [mm]; default rocker_length_mm")
    frame_mm: float = Field(gt=0, le=100000, description="Frame l4 [mm]")


class FourBarDimensions(StrictModel):
    """The crank-rocker's link lengths as a data table gives them (给定尺寸)."""

    crank_mm: float = Field(gt=0, le=100000, description="Crank l1 = AB [mm]")
    coupler_mm: float = Field(gt=0, le=100000, description="Coupler l2 = BC [mm]")
    rocker_mm: float = Field(gt=0, le=100000, description="Rocker l3 = CD [mm]")
    frame_mm: float = Field(gt=0, le=100000, description="Frame l4 = AD [mm]")


_REQUIREMENTS = ("time_ratio_K", "extreme_angle_deg", "rocker_swing_deg", "rocker_length_mm",
                 "frame_length_mm")


class CrankRockerBrief(StrictModel):
    """Crank-rocker (曲柄摇杆机构) synthesis from K and ψ, with the best transmission angle."""

    machine: Literal["crank_rocker"] = Field(description="crank_rocker")
    report: ReportMeta
    time_ratio_K: Optional[float] = Field(None, gt=1, lt=3, description=(
        "Time ratio K (行程速比系数), 1 < K < 3 (dimensionless; K = 1 has no finite optimum: "
        "γmin only approaches 90° − ψ/2 as the frame grows); give this or extreme_angle_deg"))
    extreme_angle_deg: Optional[float] = Field(None, gt=0, lt=90, description=(
        "Extreme-position angle θ (极位夹角) [°], 0 < θ < 90; give this or time_ratio_K"))
    rocker_swing_deg: Optional[float] = Field(None, gt=0, lt=180, description=(
        "Rocker swing ψ (摇杆摆角) [°]; required unless dimensions are given"))
    rocker_length_mm: Optional[float] = Field(None, gt=0, le=100000, description=(
        "Rocker length l3 = CD [mm]; required unless dimensions are given"))
    dimensions: Optional[FourBarDimensions] = Field(None, description=(
        "Given dimensions (给定尺寸) l1 … l4 instead of K (or θ), ψ, l3 and the frame: no "
        "synthesis of this linkage; θ, K, ψ and γmin are computed from the lengths, and the "
        "optimum for the same θ, ψ and l3 is designed next to it"))
    frame_length_mm: Optional[float] = Field(None, gt=0, le=100000, description=(
        "Frame length l4 = AD [mm]: when given, also the textbook design with this frame"))
    crank_speed_rpm: Optional[float] = Field(None, gt=0, le=100000, description=(
        "Crank speed [rpm]: when given, the rocker's angular velocity and acceleration are plotted"))
    allowed_transmission_angle_deg: float = Field(40.0, gt=0, lt=90, description=(
        "Allowed minimum transmission angle [γ] [°] (textbook 40°); the slider's allowed "
        "pressure angle is 90° − [γ]"))
    slider_crank: Optional[SliderCrankSection] = None
    chart: ChartSettings = Field(default_factory=ChartSettings)
    compare: list[CompareDesign] = Field(default_factory=list, max_length=8, description=(
        "Designs to check by simulation next to ours (list of sections)"))
    simulation_points: int = Field(3600, ge=360, le=100000, description=(
        "Crank positions per revolution of the simulation grid (count)"))

    @model_validator(mode="after")
    def _complete(self):
        """Only the brief's own rules (closed form): whether the data admit the construction,
        the given frame, the slider-crank and the compared crank-rockers is asked once per
        run by :func:`mechdesign.machines.crank_rocker.stages.checks`."""
        if self.dimensions is not None:
            out = Problems(self)
            for name in _REQUIREMENTS:
                if getattr(self, name) is not None:
                    out.add((name,), getattr(self, name),
                            N_("{name}: with dimensions given, θ, K, ψ and the lengths are computed "
                               "from them; remove {name} (or remove dimensions to design from K and ψ)"),
                            name=name)
            dm = self.dimensions
            crank_rocker_problems(out, ("dimensions",), dm.crank_mm, dm.coupler_mm, dm.rocker_mm,
                                  dm.frame_mm, ("crank_mm", "coupler_mm", "rocker_mm", "frame_mm"))
            out.raise_any()
            return self
        if (self.time_ratio_K is None) == (self.extreme_angle_deg is None):
            out = Problems(self)
            both = self.time_ratio_K is not None
            out.add(("extreme_angle_deg",) if both else ("time_ratio_K",),
                    self.extreme_angle_deg if both else MISSING,
                    N_("give exactly one of time_ratio_K and extreme_angle_deg: remove one") if both
                    else N_("give exactly one of time_ratio_K and extreme_angle_deg"))
            out.raise_any()
        raise_missing(self, [n for n in ("rocker_swing_deg", "rocker_length_mm") if getattr(self, n) is None])
        return self

    @property
    def theta_rad(self) -> float:
        if self.extreme_angle_deg is not None:
            return float(np.radians(self.extreme_angle_deg))
        from ...core.synthesis import extreme_angle

        return float(extreme_angle(self.time_ratio_K))


@dataclass(frozen=True)
class SliderParams:
    K: float
    theta: float          # [rad]
    stroke: float         # [m]
    offset: float         # [m]
    crank: float | None = None   # given dimensions [m] (None: designed from K, H, e)
    rod: float | None = None


@dataclass(frozen=True)
class CompareParams:
    label: str
    design: fourbar.FourBar   # [m]


@dataclass(frozen=True)
class CrankRockerParams:
    """SI parameters of the crank-rocker brief (m, rad, rad/s)."""

    theta: float                 # extreme-position angle θ [rad]
    K: float                     # time ratio
    K_given: bool                # K written in the brief (else θ)
    swing: float                 # ψ [rad]
    rocker: float                # l3 [m]
    frame: float | None          # l4 for the textbook design [m]
    crank_speed_rpm: float | None
    omega: float                 # crank angular velocity [rad/s] (1 when no speed is given)
    gamma_allowed: float         # [γ] [rad]
    slider: SliderParams | None
    chart_thetas: tuple[float, ...]   # [rad]
    chart_swing: tuple[float, float]  # [rad]
    chart_points: int
    compare: tuple[CompareParams, ...]
    grid_points: int
    given: fourbar.FourBar | None = None   # the brief's dimensions [m] (None: synthesis)


def crank_rocker_to_si(b: CrankRockerBrief) -> CrankRockerParams:
    """Convert the brief's course units to SI (the only unit conversion on input)."""
    from ...core import fourbar

    mm = 1e-3
    given = None
    if b.dimensions is not None:
        dm = b.dimensions
        given = fourbar.FourBar(dm.crank_mm * mm, dm.coupler_mm * mm, dm.rocker_mm * mm,
                                dm.frame_mm * mm)
        theta, swing = fourbar.crank_rocker_extremes(given)
        rocker, frame = given.rocker, given.frame
    else:
        theta = b.theta_rad
        swing = float(np.radians(b.rocker_swing_deg))
        rocker = b.rocker_length_mm * mm
        frame = None if b.frame_length_mm is None else b.frame_length_mm * mm
    K = b.time_ratio_K if b.time_ratio_K is not None else float((np.pi + theta) / (np.pi - theta))
    sc = b.slider_crank
    slider = None
    if sc is not None and sc.dimensions is not None:
        a, rod, e = sc.dimensions.crank_mm * mm, sc.dimensions.rod_mm * mm, sc.offset_e_mm * mm
        H, th = slider_crank_extremes(a, rod, e)
        slider = SliderParams(float((np.pi + th) / (np.pi - th)), th, H, e, a, rod)
    elif sc is not None:
        slider = SliderParams(sc.time_ratio_K, float(_extreme_angle(sc.time_ratio_K)),
                              sc.stroke_H_mm * mm, sc.offset_e_mm * mm)
    speed = b.crank_speed_rpm
    rocker_default = b.dimensions.rocker_mm if b.dimensions is not None else b.rocker_length_mm
    return CrankRockerParams(
        theta=float(theta), K=float(K), K_given=b.time_ratio_K is not None,
        swing=float(swing), rocker=rocker, frame=frame,
        crank_speed_rpm=speed, omega=1.0 if speed is None else speed * 2.0 * np.pi / 60.0,
        gamma_allowed=float(np.radians(b.allowed_transmission_angle_deg)),
        slider=slider,
        chart_thetas=tuple(float(np.radians(t)) for t in b.chart.theta_deg),
        chart_swing=(float(np.radians(b.chart.swing_deg[0])), float(np.radians(b.chart.swing_deg[1]))),
        chart_points=b.chart.points,
        compare=tuple(CompareParams(c.label, fourbar.FourBar(
            c.crank_mm * mm, c.coupler_mm * mm, (c.rocker_mm or rocker_default) * mm,
            c.frame_mm * mm)) for c in b.compare),
        grid_points=b.simulation_points, given=given,
    )


def slider_crank_extremes(crank: float, rod: float, offset: float) -> tuple[float, float]:
    """(H, θ) of an offset slider-crank from its dimensions, closed form: the slider's
    extremes are at the crank and rod extended (|s| = √((l+r)² − e²)) and folded
    (√((l−r)² − e²)), so H is their difference and the crank lines make
    θ = arcsin(e/(l − r)) − arcsin(e/(l + r))."""
    r, l_, e = crank, rod, offset
    H = np.sqrt((l_ + r) ** 2 - e * e) - np.sqrt((l_ - r) ** 2 - e * e)
    theta = np.arcsin(e / (l_ - r)) - np.arcsin(e / (l_ + r))
    return float(H), float(theta)


def _extreme_angle(K: float) -> float:
    from ...core.synthesis import extreme_angle

    return extreme_angle(K)
