"""The slotter as a linkage model on the one engine, and its stages.

Coordinates: O3 (guide-bar pivot) at the origin, O2 on the x axis at ±L_O2O3 (to the right
for a clockwise crank, mirrored for a counter-clockwise one, so that the slow stroke is
always the downward cutting stroke), the ram guide vertical at x = ±L_O3M. Links: 2 crank
O2A, 3 slider at A, 4 guide bar O3B, 5 rod BC, 6 ram (slider C), 7 frame.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core.fields import q
from ...core.kinetostatics import Body
from ...core.mechanism import RPR, RRP, Crank, LinkPoint, Mechanism
from ...core.synthesis import GuideBarDesign
from ...pipeline import Stage
from ...stages.flywheel import Flywheel, brief_flywheel
from ...stages import linkage as lk
from ...stages.drive import DriveDocument, drive_document
from ...stages import guide_bar
from ...stages.guide_bar import Synthesis, synthesize
from .brief import SlotterParams
from ...stages.cam import CamDocument
from ...stages.gear import GearDocument
from ...stages import titles
from ...stages.findings import Msg

FRAME = "7"
DOWN = -np.pi / 2


def side(p: SlotterParams) -> float:
    """+1: O2 to the right of O3 (clockwise crank); −1: the mirror image."""
    return 1.0 if p.crank_omega < 0 else -1.0


def build_mechanism(d: GuideBarDesign, p: SlotterParams) -> Mechanism:
    s = side(p)
    m = Mechanism(FRAME, {"O3": 0j, "O2": s * d.frame + 0j})
    m.add(Crank("crank O2A", "2", "O2", "A", d.crank, p.crank_omega))
    m.add(RPR("guide bar (RPR)", "3", "4", "A", "O3", branch=+1))
    m.add(LinkPoint("B", "4", "O3", d.guide_bar))
    m.add(LinkPoint("S4", "4", "O3", d.bar_com))
    # The ram C below B on the vertical guide (its tool at the lower end).
    m.add(RRP("ram (RRP)", "5", "6", "B", "C", d.rod, s * d.guide_height + 0j, np.pi / 2,
              branch=-1, frame=FRAME))
    m.add(LinkPoint("S6", "6", "C", abs(p.ram_com), 0.0 if p.ram_com >= 0 else np.pi))
    # P on the cutting-force line, beside C (the ram translates, the line is vertical).
    xp = s * p.cutting_offset
    m.add(LinkPoint("P", "6", "C", abs(xp), -np.pi / 2 if xp >= 0 else np.pi / 2))
    return m


def model(syn: Synthesis, p: SlotterParams) -> lk.LinkageModel:
    """Output: the ram C measured downwards (the working stroke is the downward, slow one);
    resistance: Fc upwards while the ram cuts (idle travel at both ends); bodies: guide bar,
    ram (its weight acts along its motion), gear 2 on the crank shaft."""
    d = syn.design
    idle = p.idle_travel_ratio * p.stroke
    return lk.LinkageModel(
        mechanism=build_mechanism(d, p), crank_omega=p.crank_omega,
        output=lk.Output("point", "C", DOWN, 1),
        bodies=(Body("4", p.m4, "S4", p.J_S4), Body("6", p.m6, "S6", 0.0),
                Body("2", p.G2 / p.gravity, "O2", 0.0)),
        resistances=(lk.Resistance("6", "P", DOWN, p.cutting_force, 0.0,
                                   (idle, p.stroke - idle), symbol="Fc"),),
        grid_points=p.grid_points, position_step=p.position_step, gravity=p.gravity,
        flywheel=brief_flywheel(p),
        special_crank_angles=(0.0, np.pi),   # the crank level with O2O3: the bar at its mid-swing
        names={"2": Msg.pgettext("link", "crank O2A"), "3": Msg.pgettext("link", "slider A"),
               "4": Msg.pgettext("link", "guide bar O3B"), "5": Msg.pgettext("link", "rod BC"),
               "6": Msg.pgettext("link: slotter", "ram")},
        group_labels={"guide bar (RPR)": Msg.pgettext("link", "guide bar (RPR)"),
                      "ram (RRP)": Msg.pgettext("link: slotter", "ram (RRP)")})


def _synthesis(r: dict):
    syn = synthesize(r["params"])
    return syn, model(syn, r["params"])


def _motion(r: dict):
    p = r["params"]
    return guide_bar.motion(r["model"], r["synthesis"], p, "BC", lk.requests_of(r.get("brief")))


def stages(p: SlotterParams) -> list[Stage]:
    engine = lk.linkage_stages(model_key="model", prefix="linkage")
    out = [Stage(("synthesis", "model"), titles.pgettext("stage: guide bar", "linkage synthesis"), _synthesis),
           Stage(engine[0].key, engine[0].title, _motion), *engine[1:]]
    # the flywheel rim (on the pinion or the crank shaft) loads its shaft with its weight
    return out + guide_bar.optional_stages(p, flywheel_weight=True, feed_cam=True)


@dataclass(frozen=True)
class SlotterResults:
    """Slotting machine (插床): the shaper's guide-bar six-bar with a vertical ram that cuts
    on its downward (slow) working stroke. Frame: O3 (guide-bar pivot) at the origin, O2 on
    the x axis at ±L_O2O3 (to the right for a clockwise crank, mirrored for a
    counter-clockwise one), the ram guide vertical at x = ±synthesis.guide_height. Links: 2
    crank O2A, 3 slider A, 4 guide bar O3B, 5 rod BC, 6 ram (slider C), 7 frame. The
    linkage's output is the ram C measured downwards (along the working stroke)."""

    schema: str = q("", "'mechdesign.results/2'")
    machine: str = q("", "'slotter'")
    units: str = q("", "reminder of the unit system")
    synthesis: guide_bar.GuideBarSynthesisDoc = q("", "the guide-bar mechanism's dimensions")
    linkage: lk.LinkageDocument = q("", "the linkage engine's results")
    flywheel: Flywheel = q("", "the flywheel (the one flywheel stage) on the pinion or crank shaft")
    cam: CamDocument | None = q("", "the cam on the crank shaft, when the brief has one")
    gear: GearDocument | None = q("", "the gear pair z1/z2, when the brief gives its module")
    drive: DriveDocument | None = q("", "the drive, when the brief has one")
    cam_phase: guide_bar.CamPhase | None = q("", "the feed cam's phase to the crank and its "
                                             "check: its motion within the return stroke",
                                             default=None)


def results_document(r: dict) -> SlotterResults:
    from ...results import SCHEMA, UNITS_NOTE
    from ...stages.cam import cam_document
    from ...stages.gear import gear_document

    syn, fl = r["synthesis"], r["linkage_flywheel"]
    return SlotterResults(
        schema=SCHEMA, machine="slotter", units=UNITS_NOTE,
        synthesis=guide_bar.synthesis_doc(syn),
        linkage=lk.linkage_document(r["model"], r["linkage"], r["linkage_forces"], fl,
                                    r["linkage_verification"], r.get("linkage_graphical")),
        flywheel=fl,
        cam=None if r.get("cam") is None else cam_document(r["cam"]),
        cam_phase=r.get("cam_phase"),
        gear=None if r.get("gear") is None else gear_document(r["gear"]),
        drive=None if r.get("drive") is None else drive_document(r["drive"]))
