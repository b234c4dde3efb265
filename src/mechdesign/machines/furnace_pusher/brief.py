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
from pydantic import Field, model_validator

from ...brief.common import AnalysisSettings, Problems, ReportMeta, SheetSettings, StrictModel
from ...brief.drive import DriveParams, DriveSection, drive_to_si
from ...i18n import N_


class PusherDimensions(StrictModel):
    """The crank-rocker O1A–AB–DB as a data table gives it (给定尺寸)."""

    crank_O1A_mm: float = Field(gt=0, le=20000, description="Crank O1A = a [mm]")
    coupler_AB_mm: float = Field(gt=0, le=20000, description="Coupler AB = b [mm]")
    rocker_DB_mm: float = Field(gt=0, le=20000, description="Rocker from its pivot D to B, DB = c [mm] (≤ DC)")
    frame_O1D_mm: float = Field(gt=0, le=20000, description="Frame O1D = d [mm]")


_SYNTHESIS_ONLY = ("stroke_H_mm", "time_ratio_K", "rocker_ratio_DB_DC", "frame_O1D_mm")


class PusherSection(StrictModel):
    """The pushing six-bar (执行机构): data of the task and the designer's free choices."""

    stroke_H_mm: Optional[float] = Field(None, gt=0, le=5000, description=(
        "Slider stroke H [mm]; required unless dimensions are given"))
    strokes_per_min: float = Field(gt=0, le=600, description=(
        "Slider strokes per minute n [1/min] = crank speed [rpm] (one working and one return "
        "stroke per crank revolution)"))
    time_ratio_K: Optional[float] = Field(None, gt=1.0, lt=3.0, description=(
        "Time ratio K (行程速比系数) = working-stroke time / return-stroke time, 1 < K < 3 "
        "(with K = 1 the criterion would put the crank pivot at infinity); required unless "
        "dimensions are given"))
    dimensions: Optional[PusherDimensions] = Field(None, description=(
        "Given dimensions (给定尺寸) of the crank-rocker instead of H, K and the free choices "
        "DB/DC and O1D: no synthesis; H = 2·DC·sin(ψ/2), K, θ, ψ and the transmission and "
        "pressure angles are computed from them"))
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

    @model_validator(mode="after")
    def _one_form(self):
        """Either the requirements (H, K) or the dimensions; closed-form checks of the
        dimensions (Grashof, B on the rocker)."""
        from ...brief.rules import crank_rocker_problems, raise_missing

        out = Problems(self)
        if self.dimensions is None:
            raise_missing(self, [n for n in ("stroke_H_mm", "time_ratio_K") if getattr(self, n) is None])
        else:
            for name in _SYNTHESIS_ONLY:
                if name in self.model_fields_set:
                    out.add((name,), getattr(self, name),
                            N_("{name}: with dimensions given there is no synthesis, and H, K and "
                               "the lengths follow from the dimensions; remove {name} (or remove "
                               "dimensions)"), name=name)
            dm = self.dimensions
            if dm.rocker_DB_mm > self.rocker_DC_mm:
                out.add(("dimensions", "rocker_DB_mm"), dm.rocker_DB_mm,
                        N_("dimensions.rocker_DB_mm = {rocker_DB_mm:g}: B lies on the rocker DC, "
                           "so DB must not exceed rocker_DC_mm = {rocker_DC_mm:g}"),
                        rocker_DB_mm=dm.rocker_DB_mm, rocker_DC_mm=self.rocker_DC_mm)
            crank_rocker_problems(out, ("dimensions",), dm.crank_O1A_mm, dm.coupler_AB_mm,
                                  dm.rocker_DB_mm, dm.frame_O1D_mm,
                                  ("crank_O1A_mm", "coupler_AB_mm", "rocker_DB_mm", "frame_O1D_mm"))
        out.raise_any()
        return self


class FurnaceBrief(StrictModel):
    """Design brief of the heating-furnace pusher (加热炉推料机)."""

    machine: Literal["furnace_pusher"] = Field(description="Machine type")
    report: ReportMeta
    pusher: PusherSection
    drive: Optional[DriveSection] = Field(None, description=(
        "Drive from the motor to the crank O1A (传动装置), listed from the motor"))
    analysis: AnalysisSettings = AnalysisSettings()
    sheets: SheetSettings = SheetSettings()



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
    given: object = None        # core.fourbar.FourBar of the brief's dimensions [m] (None: synthesis)


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
    given = None
    if s.dimensions is not None:
        # No synthesis: H and K are the dimensions' (law of cosines), exactly.
        from ...core import fourbar

        dm = s.dimensions
        given = fourbar.FourBar(dm.crank_O1A_mm * mm, dm.coupler_AB_mm * mm, dm.rocker_DB_mm * mm,
                                dm.frame_O1D_mm * mm)
        theta, swing = fourbar.crank_rocker_extremes(given)
        stroke = float(2.0 * s.rocker_DC_mm * mm * np.sin(swing / 2.0))
        K = float((np.pi + theta) / (np.pi - theta))
        ratio, frame = given.rocker / (s.rocker_DC_mm * mm), given.frame
    else:
        stroke, K = s.stroke_H_mm * mm, s.time_ratio_K
        ratio = s.rocker_ratio_DB_DC
        frame = None if s.frame_O1D_mm == "auto" else s.frame_O1D_mm * mm
    return PusherParams(
        stroke=stroke, crank_speed_rpm=s.strokes_per_min,
        crank_omega=sense * s.strokes_per_min * np.pi / 30.0, time_ratio_K=K,
        rocker_DC=s.rocker_DC_mm * mm, link_CE=s.link_CE_mm * mm,
        pressure_angle_max=np.radians(s.pressure_angle_max_deg),
        working_force=s.working_force_N, return_force=s.return_force_N,
        rocker_ratio=ratio, frame=frame,
        guide_offset=s.guide_offset_mm * mm, limit_rocker=s.limit_rocker_pressure_angle,
        transmission_angle_min=np.radians(s.transmission_angle_min_deg), given=given)


def furnace_to_si(b: FurnaceBrief) -> FurnaceParams:
    """Convert the brief's course units to SI (the only unit conversion on input)."""
    a = b.analysis
    return FurnaceParams(pusher=pusher_to_si(b.pusher),
                         drive=None if b.drive is None else drive_to_si(b.drive),
                         grid_points=a.grid_points, position_step=np.radians(a.position_step_deg),
                         gravity=a.gravity)
