"""The slotter (插床) brief: the shaper's sections with a vertical ram.

Course units in the brief; :func:`to_si` converts once to SI.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Literal, Optional

from pydantic import Field

from ...brief.common import StrictModel
from ...brief.guide_bar import GuideBarBrief, GuideBarLinkage, GuideBarParams, guide_bar_si


class SlotterLinkage(GuideBarLinkage):
    """Guide-bar mechanism data (导杆机构); O2 level with O3, the ram guide vertical: H and K,
    or the link lengths (see :class:`~mechdesign.brief.guide_bar.GuideBarLinkage`)."""

    ROD: ClassVar[str] = "BC"

    frame_O2O3_mm: float = Field(gt=0, le=10000, description=(
        "Distance from crank pivot O2 to guide-bar pivot O3 [mm] (O2 level with O3, on the side "
        "that makes the slow stroke go down)"))
    rod_ratio_BC_O3B: Optional[float] = Field(None, gt=0, le=2, description=(
        "Rod-to-guide-bar length ratio L_BC/L_O3B (or rod_BC_mm)"))
    rod_BC_mm: Optional[float] = Field(None, gt=0, le=20000, description="Rod length L_BC [mm] (or rod_ratio_BC_O3B)")
    com_ratio_O3S4_O3B: float = Field(0.5, ge=0, le=1,
                                      description="Guide-bar centre-of-mass position L_O3S4/L_O3B")
    ram_com_y_S6_mm: float = Field(0.0, ge=-10000, le=10000, description=(
        "Distance along the ram from C to its centre of mass S6, + upwards [mm]"))
    crank_speed_n2_rpm: float = Field(gt=0, le=3000, description="Crank speed n2 [rpm]")
    crank_rotation: Literal["cw", "ccw"] = Field(
        "cw", description="Crank sense of rotation seen on the drawing: cw (顺时针) or ccw")


class SlotterLoads(StrictModel):
    """Cutting resistance (插削阻力) on the downward working stroke."""

    cutting_force_Fc_N: float = Field(ge=0, le=1e6, description="Cutting force Fc [N], upwards, opposing the working stroke")
    cutting_offset_xP_mm: float = Field(0.0, ge=-10000, le=10000, description=(
        "Horizontal distance of the cutting-force line from the ram guide, + away from O3 [mm]"))
    idle_travel_ratio: float = Field(0.05, ge=0, lt=0.5, description=(
        "Idle travel at each end of the working stroke as a fraction of H (空刀距离)"))


class SlotterBrief(GuideBarBrief):
    """Design brief of the slotting machine (插床) task."""

    machine: Literal["slotter"] = Field(description="Machine type")
    linkage: SlotterLinkage
    loads: SlotterLoads


@dataclass(frozen=True, kw_only=True)
class SlotterParams(GuideBarParams):
    """The slotter brief in SI units, converted once."""

    ram_com: float             # C → S6 along the ram, + up [m]
    cutting_offset: float      # x_P from the guide, + away from O3 [m]


def to_si(b: SlotterBrief) -> SlotterParams:
    mm = 1e-3
    return SlotterParams(**guide_bar_si(b),
                         ram_com=b.linkage.ram_com_y_S6_mm * mm,
                         cutting_offset=b.loads.cutting_offset_xP_mm * mm)
