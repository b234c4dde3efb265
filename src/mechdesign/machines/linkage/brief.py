"""The `linkage` brief: any planar linkage written in the brief (its sections are shared, in :mod:`mechdesign.brief.linkage`)."""
from __future__ import annotations

from typing import Literal
from pydantic import Field
from ...brief.common import AnalysisSettings, ReportMeta, StrictModel
from ...brief.linkage import LinkageSection


class LinkageBrief(StrictModel):
    """Any planar linkage (平面连杆机构) from YAML: motion, forces and flywheel."""

    machine: Literal["linkage"] = Field(description="Machine type")
    report: ReportMeta
    linkage: LinkageSection
    analysis: AnalysisSettings = AnalysisSettings()
