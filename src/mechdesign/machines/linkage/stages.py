"""The `linkage` machine: any planar linkage written in the brief, on the one linkage
engine (:mod:`mechdesign.stages.linkage`)."""
from __future__ import annotations

from dataclasses import dataclass

from ...core.fields import q
from ...i18n import N_
from ...pipeline import Stage
from ...stages.findings import Msg, en_zh, zh_en
from ...stages.linkage import (LinkageDocument, linkage_document, linkage_stages, motion,
                               requests_of)


# ---------------------------------------------------------------- the `linkage` machine

def linkage_params(brief):
    """The generic brief's SI model."""
    from ...brief.linkage import linkage_to_model

    from dataclasses import replace

    model = linkage_to_model(brief.linkage, brief.analysis)
    now = brief.linkage.crank.rotation
    other = "ccw" if now == "cw" else "cw"
    return replace(model, advice={
        "pressure": Msg(N_("brief fields: linkage.groups[…].length_mm, guide_point_mm")),
        "transmission": Msg(N_(
            "brief fields: linkage.crank.length_mm, linkage.groups[…].lengths_mm")),
        "time_ratio": (Msg(N_("change linkage.crank.rotation to {other} (now {now}) or "
                              "linkage.output.working"), other=other, now=now),
                       "linkage.crank.rotation")})


def brief_fields(section, group: str, code: str, prefix: str = "linkage") -> tuple[str, str]:
    """The fields of a ``linkage:`` section to change for an assembly failure of the group
    named ``group`` (diagnosis ``code``): (en, zh) sentences, empty when not found."""
    for i, g in enumerate(section.groups):
        default = {"RRR": f"RRR {getattr(g, 'joint', '')}", "RRP": f"RRP {getattr(g, 'joint', '')}",
                   "RPR": f"RPR {getattr(g, 'slider_at', '')}"}.get(g.type, "")
        if (g.name or default) != group:
            continue
        here = f"{prefix}.groups[{i}]"
        crank = f"{prefix}.crank.length_mm"
        fields = {"grashof": [f"{here}.lengths_mm", crank, f"{prefix}.frame_points_mm"],
                  "slider_crank": [f"{here}.length_mm", crank, f"{here}.guide_point_mm"],
                  "guide_bar": [f"{here}.offset_mm", crank, f"{prefix}.frame_points_mm"]}.get(code)
        if fields is None:
            fields = {"RRR": [f"{here}.lengths_mm"], "RRP": [f"{here}.length_mm", f"{here}.guide_point_mm"],
                      "RPR": [f"{here}.offset_mm"]}.get(g.type, [here])
        names = ", ".join(fields)
        return en_zh(N_("(Brief fields: {names}.)"), names=names)
    return "", ""


def _motion_of_brief(r: dict):
    """The motion stage of the ``linkage`` machine: an assembly failure also names the
    brief's fields to change."""
    from ...core.mechanism import AssemblyError

    try:
        return motion(r["params"], requests_of(r.get("brief")))
    except AssemblyError as exc:
        brief = r.get("brief")
        en, zh = ("", "") if brief is None else brief_fields(brief.linkage, exc.group, exc.code)
        if en:
            raise exc.with_hint(en, zh) from None
        raise


STAGES = linkage_stages(model_key="params")
STAGES[0] = Stage(STAGES[0].key, STAGES[0].title, _motion_of_brief)


@dataclass(frozen=True)
class LinkageResults:
    """Any planar linkage written in the brief (crank + Assur groups)."""

    schema: str = q("", "'mechdesign.results/2'")
    machine: str = q("", "'linkage'")
    units: str = q("", "reminder of the unit system")
    linkage: LinkageDocument = q("", "the linkage engine's results")


def results_document(r: dict) -> LinkageResults:
    from ...results import SCHEMA, UNITS_NOTE

    return LinkageResults(SCHEMA, "linkage", UNITS_NOTE, linkage_document(
        r["params"], r["linkage"], r["linkage_forces"], r["linkage_flywheel"],
        r["linkage_verification"], r.get("linkage_graphical")))
