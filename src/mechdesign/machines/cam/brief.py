"""The `cam` brief: synthesis of a disc cam (its cam section is shared, :class:`mechdesign.brief.cam.CamSection`)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal
from pydantic import Field
from ...brief.common import ReportMeta, StrictModel
from ...brief.cam import CamParams, CamSection, cam_to_si


class CamBrief(StrictModel):
    """Stand-alone cam design brief (凸轮机构设计): synthesis of a disc cam for a given
    follower programme."""

    machine: Literal["cam"] = Field(description="Machine type")
    report: ReportMeta
    cam: CamSection


@dataclass(frozen=True)
class StandaloneCamParams:
    cam: CamParams


def cam_brief_to_si(b: CamBrief) -> StandaloneCamParams:
    return StandaloneCamParams(cam_to_si(b.cam))
