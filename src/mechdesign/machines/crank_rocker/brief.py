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

from ...brief.common import ReportMeta, StrictModel

if TYPE_CHECKING:
    from ...core import fourbar

_DEFAULT_THETAS = [0.0, 5.0, 10.0, 15.0, 20.0, 25.0, 30.0]


class SliderCrankSection(StrictModel):
    """Offset slider-crank (偏置曲柄滑块机构) designed from K, the stroke H and the offset e."""

    time_ratio_K: float = Field(gt=1, lt=3, description=(
        "Time ratio K of the slider (行程速比系数), 1 < K < 3 (dimensionless)"))
    stroke_H_mm: float = Field(gt=0, le=10000, description="Slider stroke H [mm]")
    offset_e_mm: float = Field(gt=0, le=10000, description=(
        "Offset e of the slider guide from the crank pivot [mm]; must be below H·cot θ"))


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
            raise ValueError(f"each θ must be in [0°, 90°); got {bad}")
        return sorted(set(value))

    @field_validator("swing_deg")
    @classmethod
    def _swings(cls, value):
        lo, hi = value
        if not 0.0 < lo < hi < 180.0:
            raise ValueError(f"swing_deg must be [from, to] with 0 < from < to < 180; got {value}")
        return value


class CompareDesign(StrictModel):
    """A published or hand-made design to check by simulation (e.g. a paper's result)."""

    label: str = Field(min_length=1, max_length=60, description="Name shown in the report, e.g. 'paper, computer result'")
    crank_mm: float = Field(gt=0, le=100000, description="Crank l1 [mm]")
    coupler_mm: float = Field(gt=0, le=100000, description="Coupler l2 [mm]")
    rocker_mm: Optional[float] = Field(None, gt=0, le=100000,
                                       description="Rocker l3 [mm]; default rocker_length_mm")
    frame_mm: float = Field(gt=0, le=100000, description="Frame l4 [mm]")


class CrankRockerBrief(StrictModel):
    """Crank-rocker (曲柄摇杆机构) synthesis from K and ψ, with the best transmission angle."""

    machine: Literal["crank_rocker"] = Field(description="crank_rocker")
    report: ReportMeta
    time_ratio_K: Optional[float] = Field(None, gt=1, lt=3, description=(
        "Time ratio K (行程速比系数), 1 < K < 3 (dimensionless; K = 1 has no finite optimum: "
        "γmin only approaches 90° − ψ/2 as the frame grows); give this or extreme_angle_deg"))
    extreme_angle_deg: Optional[float] = Field(None, gt=0, lt=90, description=(
        "Extreme-position angle θ (极位夹角) [°], 0 < θ < 90; give this or time_ratio_K"))
    rocker_swing_deg: float = Field(gt=0, lt=180, description="Rocker swing ψ (摇杆摆角) [°]")
    rocker_length_mm: float = Field(gt=0, le=100000, description="Rocker length l3 = CD [mm]")
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
        if (self.time_ratio_K is None) == (self.extreme_angle_deg is None):
            raise ValueError("give exactly one of time_ratio_K and extreme_angle_deg")
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


def crank_rocker_to_si(b: CrankRockerBrief) -> CrankRockerParams:
    """Convert the brief's course units to SI (the only unit conversion on input)."""
    from ...core import fourbar

    mm = 1e-3
    theta = b.theta_rad
    K = b.time_ratio_K if b.time_ratio_K is not None else float((np.pi + theta) / (np.pi - theta))
    sc = b.slider_crank
    slider = None if sc is None else SliderParams(
        sc.time_ratio_K, float(_extreme_angle(sc.time_ratio_K)), sc.stroke_H_mm * mm,
        sc.offset_e_mm * mm)
    speed = b.crank_speed_rpm
    return CrankRockerParams(
        theta=theta, K=float(K), K_given=b.time_ratio_K is not None,
        swing=float(np.radians(b.rocker_swing_deg)), rocker=b.rocker_length_mm * mm,
        frame=None if b.frame_length_mm is None else b.frame_length_mm * mm,
        crank_speed_rpm=speed, omega=1.0 if speed is None else speed * 2.0 * np.pi / 60.0,
        gamma_allowed=float(np.radians(b.allowed_transmission_angle_deg)),
        slider=slider,
        chart_thetas=tuple(float(np.radians(t)) for t in b.chart.theta_deg),
        chart_swing=(float(np.radians(b.chart.swing_deg[0])), float(np.radians(b.chart.swing_deg[1]))),
        chart_points=b.chart.points,
        compare=tuple(CompareParams(c.label, fourbar.FourBar(
            c.crank_mm * mm, c.coupler_mm * mm, (c.rocker_mm or b.rocker_length_mm) * mm,
            c.frame_mm * mm)) for c in b.compare),
        grid_points=b.simulation_points,
    )


def _extreme_angle(K: float) -> float:
    from ...core.synthesis import extreme_angle

    return extreme_angle(K)
