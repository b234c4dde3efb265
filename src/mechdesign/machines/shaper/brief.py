"""The shaper (牛头刨床) brief: guide-bar quick-return six-bar with a ram.

Course units in the brief; :func:`to_si` converts once to SI for the computation.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Literal, Optional

from pydantic import Field

from ...brief.common import StrictModel
from ...brief.guide_bar import (GearParams, GuideBarBrief, GuideBarLinkage,  # noqa: F401
                                GuideBarParams, guide_bar_si)


class ShaperLinkage(GuideBarLinkage):
    """Guide-bar mechanism data (导杆机构): H and K, or the link lengths (see
    :class:`~mechdesign.brief.guide_bar.GuideBarLinkage`)."""

    ROD: ClassVar[str] = "BF"

    frame_O2O3_mm: float = Field(gt=0, le=10000,
                                 description="Distance from crank pivot O2 to guide-bar pivot O3 [mm] (O2 above O3)")
    rod_ratio_BF_O3B: Optional[float] = Field(None, gt=0, le=2, description=(
        "Rod-to-guide-bar length ratio L_BF/L_O3B (or rod_BF_mm)"))
    rod_BF_mm: Optional[float] = Field(None, gt=0, le=20000, description="Rod length L_BF [mm] (or rod_ratio_BF_O3B)")
    com_ratio_O3S4_O3B: float = Field(0.5, ge=0, le=1,
                                      description="Guide-bar centre-of-mass position L_O3S4/L_O3B")
    ram_com_x_S6_mm: float = Field(ge=-10000, le=10000, description="Horizontal distance from F to the ram's centre of mass S6, +x to the right [mm]")
    ram_com_y_S6_mm: float = Field(0.0, ge=-10000, le=10000, description=(
        "Height of the ram's centre of mass S6 above F [mm] (its inertia force's line)"))
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


@dataclass(frozen=True, kw_only=True)
class ShaperParams(GuideBarParams):
    """The shaper brief in SI units, converted once."""

    ram_com_x: float           # x_S6: F → S6 along +x [m]
    ram_com_y: float           # y_S6: S6 above F [m]
    cutting_height: float      # y_P: the cutting-force line above O2 [m]


def to_si(b: ShaperBrief) -> ShaperParams:
    """Convert the brief's course units to SI (the only unit conversion on input)."""
    mm = 1e-3
    return ShaperParams(**guide_bar_si(b),
                        ram_com_x=b.linkage.ram_com_x_S6_mm * mm,
                        ram_com_y=b.linkage.ram_com_y_S6_mm * mm,
                        cutting_height=b.loads.cutting_height_yP_mm * mm)
