"""The heating-furnace pusher (加热炉推料机) brief: a crank-rocker O1A–AB–rocker DBC driving
the pushing slider E through the link CE, with its drive (worm reducer + open gear pair).

Course units in the brief; :func:`furnace_to_si` converts once to SI. Validation checks
the fields alone; whether the data admit a linkage is the synthesis's question, asked
once per run by :func:`mechdesign.machines.furnace_pusher.stages.checks`, which reports every problem
by its brief field, with the value and what to change.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Literal, Optional, Union

from ...lazy import np
from pydantic import Field

from ...brief.common import AnalysisSettings, ReportMeta, StrictModel
from ...brief.drive import DriveParams, DriveSection, drive_to_si


class PusherSection(StrictModel):
    """The pushing six-bar (执行机构): data of the task and the designer's free choices."""

    stroke_H_mm: float = Field(gt=0, le=5000, description="Slider stroke H [mm]")
    strokes_per_min: float = Field(gt=0, le=600, description=(
        "Slider strokes per minute n [1/min] = crank speed [rpm] (one working and one return "
        "stroke per crank revolution)"))
    time_ratio_K: float = Field(gt=1.0, lt=3.0, description=(
        "Time ratio K (行程速比系数) = working-stroke time / return-stroke time, 1 < K < 3 "
        "(with K = 1 the criterion would put the crank pivot at infinity)"))
    rocker_DC_mm: float = Field(gt=0, le=20000, description="Rocker length from its pivot D to C, DC [mm]")
    link_CE_mm: float = Field(gt=0, le=20000, description="Length of the link CE from the rocker to the slider [mm]")
    pressure_angle_max_deg: float = Field(gt=0, lt=90, description=(
        "Largest allowed pressure angle in the working stroke [°] (滑块工作行程最大压力角)"))
    working_force_N: float = Field(gt=0, le=1e7, description=(
        "Resistance on the slider in the working stroke, friction included [N]; > 0: it is "
        "what the crank torque, and the drive, are sized by"))
    return_force_N: float = Field(0.0, ge=0, le=1e7, description=(
        "Resistance on the slider in the return stroke, friction included [N]"))
    crank_rotation: Literal["cw", "ccw"] = Field("cw", description=(
        "Sense of rotation of the crank O1A seen on the drawing (rocker pointing up from D); "
        "it decides the side the slow working stroke pushes towards (the furnace's side)"))
    rocker_ratio_DB_DC: float = Field(0.5, gt=0, le=1, description=(
        "Free choice: position of the coupler joint B on the rocker, DB/DC (sets the four-bar's "
        "size; its angles do not depend on it)"))
    frame_O1D_mm: Union[Annotated[float, Field(gt=0, le=20000)], Literal["auto"]] = Field("auto", description=(
        "Free choice: frame length O1D [mm]; auto maximises the four-bar's minimum transmission "
        "angle under the pressure-angle limits"))
    guide_offset_mm: float = Field(0.0, ge=-10000, le=10000, description=(
        "Free choice: height of the slider guide above the middle of the sagitta of C's arc [mm] "
        "(0: the guide halves the sagitta, the smallest pressure angle at E)"))
    limit_rocker_pressure_angle: bool = Field(True, description=(
        "Also keep the four-bar's pressure angle at B (90° − transmission angle) within the limit "
        "over the working stroke, as the seed intended"))
    transmission_angle_min_deg: float = Field(40.0, gt=0, lt=90, description=(
        "Smallest acceptable transmission angle of the four-bar over the cycle [°] (textbook: 40)"))


class FurnaceBrief(StrictModel):
    """Design brief of the heating-furnace pusher (加热炉推料机)."""

    machine: Literal["furnace_pusher"] = Field(description="Machine type")
    report: ReportMeta
    pusher: PusherSection
    drive: Optional[DriveSection] = Field(None, description=(
        "Drive from the motor to the crank O1A (传动装置), listed from the motor"))
    analysis: AnalysisSettings = AnalysisSettings()



@dataclass(frozen=True)
class PusherParams:
    """The pusher section in SI (m, rad, rad/s, N)."""

    stroke: float               # H [m]
    crank_speed_rpm: float      # n [rpm]
    crank_omega: float          # signed, CCW + [rad/s]
    time_ratio_K: float
    rocker_DC: float            # [m]
    link_CE: float              # [m]
    pressure_angle_max: float   # [rad]
    working_force: float        # [N]
    return_force: float         # [N]
    rocker_ratio: float         # DB/DC
    frame: float | None         # O1D [m]; None = auto
    guide_offset: float         # [m]
    limit_rocker: bool
    transmission_angle_min: float  # [rad]


@dataclass(frozen=True)
class FurnaceParams:
    pusher: PusherParams
    drive: DriveParams | None
    grid_points: int
    position_step: float        # [rad]
    gravity: float              # [m/s²]


def pusher_to_si(s: PusherSection) -> PusherParams:
    mm = 1e-3
    sense = -1.0 if s.crank_rotation == "cw" else 1.0
    return PusherParams(
        stroke=s.stroke_H_mm * mm, crank_speed_rpm=s.strokes_per_min,
        crank_omega=sense * s.strokes_per_min * np.pi / 30.0, time_ratio_K=s.time_ratio_K,
        rocker_DC=s.rocker_DC_mm * mm, link_CE=s.link_CE_mm * mm,
        pressure_angle_max=np.radians(s.pressure_angle_max_deg),
        working_force=s.working_force_N, return_force=s.return_force_N,
        rocker_ratio=s.rocker_ratio_DB_DC,
        frame=None if s.frame_O1D_mm == "auto" else s.frame_O1D_mm * mm,
        guide_offset=s.guide_offset_mm * mm, limit_rocker=s.limit_rocker_pressure_angle,
        transmission_angle_min=np.radians(s.transmission_angle_min_deg))


def furnace_to_si(b: FurnaceBrief) -> FurnaceParams:
    """Convert the brief's course units to SI (the only unit conversion on input)."""
    a = b.analysis
    return FurnaceParams(pusher=pusher_to_si(b.pusher),
                         drive=None if b.drive is None else drive_to_si(b.drive),
                         grid_points=a.grid_points, position_step=np.radians(a.position_step_deg),
                         gravity=a.gravity)
