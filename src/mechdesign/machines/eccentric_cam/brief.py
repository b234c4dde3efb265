"""The `eccentric_cam` brief: analysis of a given eccentric circular disc with one or more translating followers."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Literal
from ...lazy import np
from pydantic import Field, model_validator
from ...brief.common import Problems, ReportMeta, StrictModel
from ...brief.cam import _check_roller, side_sign
from ...i18n import N_


class DiscFollower(StrictModel):
    """A translating follower on the eccentric disc."""

    label: str = Field(min_length=1, max_length=60, description="Name shown in the report, e.g. (a)")
    contact: Literal["knife", "roller", "flat"] = Field(description="knife (尖顶), roller (滚子) or flat (平底)")
    offset_mm: float = Field(0.0, ge=0, le=10000, description="Offset e of the follower axis [mm]")
    offset_side: Literal["right", "left"] = Field("right", description="Side of the axis, seen with the follower on top")
    roller_radius_mm: float = Field(0.0, ge=0, le=1000, description="Roller radius r_r [mm] (roller only)")

    @model_validator(mode="after")
    def _roller(self):
        out = Problems(self)
        _check_roller(out, self.contact, self.roller_radius_mm)
        out.raise_any()
        return self


class EccentricDisc(StrictModel):
    """The given cam: a circular disc mounted off-centre (偏心圆盘)."""

    radius_R_mm: float = Field(gt=0, le=10000, description="Disc radius R [mm]")
    eccentricity_mm: float = Field(gt=0, le=10000, description="Distance from the cam axis to the disc centre [mm]")
    rotation: Literal["cw", "ccw"] = Field("ccw", description="Sense of rotation")

    @model_validator(mode="after")
    def _inside(self):
        out = Problems(self)
        if self.eccentricity_mm >= self.radius_R_mm:
            out.add("eccentricity_mm", self.eccentricity_mm,
                    N_("eccentricity_mm must be smaller than radius_R_mm = {radius_R_mm:g} (the "
                       "cam axis lies inside the disc)"), radius_R_mm=self.radius_R_mm)
        out.raise_any()
        return self


class EccentricCamBrief(StrictModel):
    """Analysis of a given eccentric circular disc cam (凸轮机构分析) with one or more
    translating followers: displacement and pressure angle at every cam angle."""

    machine: Literal["eccentric_cam"] = Field(description="Machine type")
    report: ReportMeta
    disc: EccentricDisc
    followers: list[DiscFollower] = Field(min_length=1, max_length=6)
    query_angles_deg: list[Annotated[float, Field(ge=-3600, le=3600)]] = Field(default_factory=list, max_length=24, description=(
        "Cam angles [°] at which displacement and pressure angle are tabulated (e.g. exercise 7-2)"))
    table_step_deg: float = Field(10.0, ge=0.5, le=90, description="Step of the displacement table [°]")


@dataclass(frozen=True)
class DiscParams:
    radius: float                # [m]
    eccentricity: float          # [m]
    rotation: int
    followers: tuple             # ((label, core.cam.TranslatingFollower), …)
    query_angles: np.ndarray     # [rad]
    table_step: float            # [rad]


def eccentric_to_si(b: EccentricCamBrief) -> DiscParams:
    from ...core.cam import TranslatingFollower

    mm = 1e-3
    fols = tuple((f.label, TranslatingFollower(f.contact, side_sign(f.offset_side) * f.offset_mm * mm,
                                               f.roller_radius_mm * mm)) for f in b.followers)
    return DiscParams(b.disc.radius_R_mm * mm, b.disc.eccentricity_mm * mm,
                      1 if b.disc.rotation == "ccw" else -1, fols,
                      np.radians(np.array(b.query_angles_deg, dtype=float)),
                      np.radians(b.table_step_deg))
