"""The `linkage` brief: any planar linkage written in the brief (its sections are shared, in :mod:`mechdesign.brief.linkage`)."""
from __future__ import annotations

from typing import Literal
from pydantic import Field, model_validator
from ...brief.common import AnalysisSettings, Problems, ReportMeta, SheetSettings, StrictModel
from ...brief.linkage import LinkageSection, check_requests
from ...i18n import N_


class LinkageBrief(StrictModel):
    """Any planar linkage (平面连杆机构) from YAML: motion, forces and flywheel."""

    machine: Literal["linkage"] = Field(description="Machine type")
    report: ReportMeta
    linkage: LinkageSection
    analysis: AnalysisSettings = AnalysisSettings()
    sheets: SheetSettings = SheetSettings()

    @model_validator(mode="after")
    def _requests(self):
        """Named points and link events of ``analysis`` are the linkage's; regular polygon
        positions exist (labels such as 'φ45' or event codes are resolved at run time)."""
        out = Problems(self)
        check_requests(self.linkage, self.analysis, out)
        chosen = self.sheets.polygon_positions or []
        count = int(round(360.0 / self.analysis.position_step_deg))
        for i, p in enumerate(chosen):
            if isinstance(p, int) and not 1 <= p <= count:
                out.add(("sheets", "polygon_positions", i), p,
                        N_("{p} is not a position: with analysis.position_step_deg = "
                           "{position_step_deg:g} the positions are 1 … {count}"),
                        p=p, position_step_deg=self.analysis.position_step_deg, count=count)
        out.raise_any()
        return self
