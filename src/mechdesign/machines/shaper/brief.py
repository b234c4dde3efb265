"""The shaper (牛头刨床) brief: guide-bar quick-return six-bar with a ram.

Course units in the brief; :func:`to_si` converts once to SI for the computation.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from ...lazy import np
from pydantic import Field

from ...brief.cam import CamParams, cam_to_si
from ...brief.common import StrictModel
from ...brief.guide_bar import GearParams, GuideBarBrief, drive_to_si_with_gear, gear_to_si
from ...brief.drive import DriveParams


class ShaperLinkage(StrictModel):
    """Guide-bar mechanism data (导杆机构)."""

    stroke_H_mm: float = Field(gt=0, le=5000, description="Ram stroke H [mm]")
    time_ratio_K: float = Field(gt=1.0, lt=3.0, description="Time ratio K (行程速比系数), 1 < K < 3")
    frame_O2O3_mm: float = Field(gt=0, le=10000,
                                 description="Distance from crank pivot O2 to guide-bar pivot O3 [mm] (O2 above O3)")
    rod_ratio_BF_O3B: float = Field(gt=0, le=2, description="Rod-to-guide-bar length ratio L_BF/L_O3B")
    com_ratio_O3S4_O3B: float = Field(0.5, ge=0, le=1,
                                      description="Guide-bar centre-of-mass position L_O3S4/L_O3B")
    ram_com_x_S6_mm: float = Field(ge=-10000, le=10000, description="Horizontal distance from F to the ram's centre of mass S6, +x to the right [mm]")
    crank_speed_n2_rpm: float = Field(gt=0, le=3000, description="Crank speed n2 [rpm]")
    crank_rotation: Literal["cw", "ccw"] = Field(
        "cw", description="Crank sense of rotation seen on the drawing: cw (顺时针) or ccw")


class ShaperLoads(StrictModel):
    """Cutting resistance (切削阻力)."""

    cutting_force_Fc_N: float = Field(ge=0, le=1e6, description="Cutting force Fc [N], opposing the working stroke")
    cutting_height_yP_mm: float = Field(ge=-10000, le=10000, description="Height of the cutting-force line above O2, y_P [mm]")
    idle_travel_ratio: float = Field(0.05, ge=0, lt=0.5,
                                     description="Idle travel at each end of the working stroke as a fraction of H (空刀距离)")


class ShaperBrief(GuideBarBrief):
    """Design brief of the shaper (牛头刨床) task."""

    machine: Literal["shaper"] = Field(description="Machine type")
    linkage: ShaperLinkage
    loads: ShaperLoads


@dataclass(frozen=True)
class ShaperParams:
    """The shaper brief in SI units (m, rad, rad/s, kg, N, kg·m²), converted once."""

    stroke: float              # H [m]
    time_ratio_K: float
    frame: float               # L_O2O3 [m]
    rod_ratio: float
    com_ratio: float
    ram_com_x: float           # x_S6 [m]
    crank_omega: float         # ω2, counter-clockwise positive [rad/s]
    crank_speed_rpm: float     # n2 [rpm]
    m4: float                  # [kg]
    J_S4: float                # [kg·m²]
    m6: float                  # [kg]
    G2: float                  # [N]
    cutting_force: float       # Fc [N]
    cutting_height: float      # y_P above O2 [m]
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
    gear: "GearParams | None" = None
    drive: DriveParams | None = None


def to_si(b: ShaperBrief) -> ShaperParams:
    """Convert the brief's course units to SI (the only unit conversion on input)."""
    mm = 1e-3
    sense = -1.0 if b.linkage.crank_rotation == "cw" else 1.0
    return ShaperParams(
        stroke=b.linkage.stroke_H_mm * mm,
        time_ratio_K=b.linkage.time_ratio_K,
        frame=b.linkage.frame_O2O3_mm * mm,
        rod_ratio=b.linkage.rod_ratio_BF_O3B,
        com_ratio=b.linkage.com_ratio_O3S4_O3B,
        ram_com_x=b.linkage.ram_com_x_S6_mm * mm,
        crank_omega=sense * b.linkage.crank_speed_n2_rpm * 2.0 * np.pi / 60.0,
        crank_speed_rpm=b.linkage.crank_speed_n2_rpm,
        m4=b.masses.guide_bar_m4_kg,
        J_S4=b.masses.guide_bar_J_S4_kgm2,
        m6=b.masses.ram_m6_kg,
        G2=b.masses.gear2_weight_G2_N,
        cutting_force=b.loads.cutting_force_Fc_N,
        cutting_height=b.loads.cutting_height_yP_mm * mm,
        idle_travel_ratio=b.loads.idle_travel_ratio,
        z1=b.gear_pair.z1,
        z2=b.gear_pair.z2,
        fluctuation=b.flywheel.fluctuation_delta,
        flywheel_shaft=b.flywheel.shaft,
        rim_diameter=b.flywheel.rim_diameter_mm * mm,
        rim_height_to_width=b.flywheel.rim_height_to_width,
        specific_weight=b.flywheel.specific_weight_N_m3,
        grid_points=b.analysis.grid_points,
        position_step=np.radians(b.analysis.position_step_deg),
        gravity=b.analysis.gravity,
        cam=None if b.cam is None else cam_to_si(b.cam, b.linkage.crank_speed_n2_rpm),
        gear=gear_to_si(b.gear_pair),
        drive=drive_to_si_with_gear(b),
    )
