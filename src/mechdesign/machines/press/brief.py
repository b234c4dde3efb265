"""The press (压床) brief: the six-bar of the course's 压床机构设计 — crank AB, coupler BC,
rocker DE (pivot D, C on it between D and E), rod EF and the ram F on a vertical guide.

Course units in the brief; :func:`to_si` converts once to SI. The frame (the course's
figure, as this package reads it): D the rocker pivot; the crank pivot A lies x1 to the
right of D and y below it; the ram guide is the vertical line x2 to the right of D. The
rocker's extreme positions DE′, DE″ are given by their angles ψ3′, ψ3″ from the upward
vertical through D (clockwise, towards the ram); they are symmetric about the horizontal
through D (ψ3′ + ψ3″ = 180°), so E′E″ is parallel to the guide.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from pydantic import Field, model_validator

from ...brief.common import Problems, StrictModel
from ...brief.guide_bar import GuideBarBrief, drive_to_si_with_gear, gear_to_si
from ...brief.cam import CamParams, cam_to_si
from ...brief.drive import DriveParams
from ...brief.guide_bar import GearParams
from ...lazy import np
from ...i18n import N_


class PressLinkage(StrictModel):
    """Six-bar data (连杆机构设计数据), the course table's x1, x2, y, ψ3′, ψ3″, H, ratios, n1."""

    pivot_x1_mm: float = Field(ge=-5000, le=5000, description=(
        "x1: horizontal distance from the rocker pivot D to the crank pivot A, + towards the ram guide [mm]"))
    guide_x2_mm: float = Field(gt=0, le=5000, description=(
        "x2: horizontal distance from D to the ram's vertical guide [mm]"))
    pivot_y_mm: float = Field(ge=-5000, le=5000, description=(
        "y: vertical distance of the crank pivot A below D [mm]"))
    rocker_psi3_upper_deg: float = Field(gt=0, lt=180, description=(
        "ψ3′: the rocker DE's upper extreme, from the upward vertical through D, clockwise [°]"))
    rocker_psi3_lower_deg: float = Field(gt=0, lt=180, description=(
        "ψ3″: the rocker DE's lower extreme, from the upward vertical through D, clockwise [°]"))
    stroke_H_mm: float = Field(gt=0, le=5000, description="Ram stroke H [mm]")
    ratio_CE_CD: float = Field(gt=0, le=10, description="CE/CD (C on the rocker between D and E)")
    ratio_EF_DE: float = Field(gt=0, le=5, description="EF/DE (rod EF to the ram)")
    ratio_BS2_BC: float = Field(0.5, ge=0, le=1, description="BS2/BC: coupler's centre of mass")
    ratio_DS3_DE: float = Field(0.5, ge=0, le=1, description="DS3/DE: rocker's centre of mass")
    crank_speed_n1_rpm: float = Field(gt=0, le=3000, description="Crank speed n1 [rpm]")
    crank_rotation: Literal["cw", "ccw"] = Field(
        "ccw", description="Crank sense of rotation seen on the drawing: cw (顺时针) or ccw")

    @model_validator(mode="after")
    def _extremes(self):
        out = Problems(self)
        u, lo = self.rocker_psi3_upper_deg, self.rocker_psi3_lower_deg
        if not u < lo:
            out.add(("rocker_psi3_lower_deg",), lo,
                    N_("must exceed ψ3′ = {u:g}° (the lower extreme is further clockwise)"), u=u)
        elif abs(u + lo - 180.0) > 1e-9:
            out.add(("rocker_psi3_lower_deg",), lo,
                    N_("must be 180° − ψ3′ = {v1:g}°: the extremes are symmetric about the "
                       "horizontal through D, so E′E″ is parallel to the ram guide"), v1=180 - u)
        out.raise_any()
        return self


class PressMasses(StrictModel):
    """Weights and moments of inertia (动态静力分析数据); crank and rod EF massless."""

    coupler_G2_N: float = Field(ge=0, le=1e6, description="Coupler BC weight G2 [N]")
    rocker_G3_N: float = Field(ge=0, le=1e6, description="Rocker DE weight G3 [N]")
    ram_G5_N: float = Field(ge=0, le=1e6, description="Ram (slider F) weight G5 [N]")
    coupler_J_S2_kgm2: float = Field(ge=0, le=1e4, description="Coupler moment of inertia J_S2 [kg·m²]")
    rocker_J_S3_kgm2: float = Field(ge=0, le=1e4, description="Rocker moment of inertia J_S3 [kg·m²]")


class PressLoads(StrictModel):
    """The pressing resistance (生产阻力) on the ram's downward working stroke."""

    pressing_force_Qmax_N: float = Field(ge=0, le=1e7, description=(
        "Pressing force Q_max [N], upwards on the ram, while it presses"))
    pressing_travel_ratio: float = Field(0.3, gt=0, le=1, description=(
        "The part of the downward stroke, at its end, over which Q_max acts (a fraction of H)"))
    pressure_angle_max_deg: float = Field(30.0, gt=0, lt=90, description=(
        "Allowed pressure angle of the ram (rod EF to the guide) in the working stroke [°]"))
    transmission_angle_min_deg: float = Field(40.0, gt=0, lt=90, description=(
        "Smallest allowed transmission angle of the four-bar ABCD [°]"))


class PressBrief(GuideBarBrief):
    """Design brief of the press (压床) task."""

    _crank_speed_field = "crank_speed_n1_rpm"
    machine: Literal["press"] = Field(description="Machine type")
    linkage: PressLinkage
    masses: PressMasses
    loads: PressLoads


@dataclass(frozen=True, kw_only=True)
class PressParams:
    """The press brief in SI units (m, rad, rad/s, kg, N, kg·m²), converted once."""

    x1: float                  # A from D, + towards the guide [m]
    x2: float                  # the guide from D [m]
    y: float                   # A below D [m]
    psi_upper: float           # ψ3′ [rad] from the upward vertical, clockwise
    psi_lower: float           # ψ3″ [rad]
    stroke: float              # H [m]
    ratio_CE_CD: float
    ratio_EF_DE: float
    ratio_BS2_BC: float
    ratio_DS3_DE: float
    crank_omega: float         # ω1, counter-clockwise positive [rad/s]
    crank_speed_rpm: float     # n1 [rpm]
    m2: float
    m3: float
    m5: float
    J_S2: float
    J_S3: float
    pressing_force: float      # Q_max [N]
    pressing_ratio: float
    pressure_angle_max: float  # [rad]
    transmission_angle_min: float  # [rad]
    z1: int
    z2: int
    fluctuation: float
    flywheel_shaft: str        # "pinion" | "crank"
    rim_diameter: float
    rim_height_to_width: float
    specific_weight: float
    grid_points: int
    position_step: float
    gravity: float
    cam: CamParams | None = None
    gear: GearParams | None = None
    drive: DriveParams | None = None


def to_si(b: PressBrief) -> PressParams:
    mm, lk, ms, ld, g = 1e-3, b.linkage, b.masses, b.loads, b.analysis.gravity
    sense = -1.0 if lk.crank_rotation == "cw" else 1.0
    return PressParams(
        x1=lk.pivot_x1_mm * mm, x2=lk.guide_x2_mm * mm, y=lk.pivot_y_mm * mm,
        psi_upper=np.radians(lk.rocker_psi3_upper_deg), psi_lower=np.radians(lk.rocker_psi3_lower_deg),
        stroke=lk.stroke_H_mm * mm, ratio_CE_CD=lk.ratio_CE_CD, ratio_EF_DE=lk.ratio_EF_DE,
        ratio_BS2_BC=lk.ratio_BS2_BC, ratio_DS3_DE=lk.ratio_DS3_DE,
        crank_omega=sense * lk.crank_speed_n1_rpm * 2.0 * np.pi / 60.0,
        crank_speed_rpm=lk.crank_speed_n1_rpm,
        m2=ms.coupler_G2_N / g, m3=ms.rocker_G3_N / g, m5=ms.ram_G5_N / g,
        J_S2=ms.coupler_J_S2_kgm2, J_S3=ms.rocker_J_S3_kgm2,
        pressing_force=ld.pressing_force_Qmax_N, pressing_ratio=ld.pressing_travel_ratio,
        pressure_angle_max=np.radians(ld.pressure_angle_max_deg),
        transmission_angle_min=np.radians(ld.transmission_angle_min_deg),
        z1=b.gear_pair.z1, z2=b.gear_pair.z2, fluctuation=b.flywheel.fluctuation_delta,
        flywheel_shaft=b.flywheel.shaft, rim_diameter=b.flywheel.rim_diameter_mm * mm,
        rim_height_to_width=b.flywheel.rim_height_to_width,
        specific_weight=b.flywheel.specific_weight_N_m3, grid_points=b.analysis.grid_points,
        position_step=np.radians(b.analysis.position_step_deg), gravity=g,
        cam=None if b.cam is None else cam_to_si(b.cam, lk.crank_speed_n1_rpm),
        gear=gear_to_si(b.gear_pair), drive=drive_to_si_with_gear(b))
