"""Slotting machine (插床): the shaper's guide-bar six-bar with a vertical ram that cuts on
its downward (slow) working stroke. The whole machine is this package: its brief
(:mod:`.brief`), its model and stages (:mod:`.stages`) and its report (:mod:`.report`);
everything else is the shared engine, stages and report sections.
"""
from ...i18n import N_
from ...registry import _DEG, _MM, Entry

_P = __name__
ENTRY = Entry(
    name="slotter", brief=f"{_P}.brief:SlotterBrief", to_params=f"{_P}.brief:to_si",
    stages=f"{_P}.stages:stages", document=f"{_P}.stages:results_document",
    report=f"{_P}.report", example="slotter.yaml", results=f"{_P}.stages:SlotterResults",
    summary=((N_("crank"), "mm", "synthesis.crank", _MM),
             (N_("guide bar"), "mm", "synthesis.guide_bar", _MM),
             (N_("K (simulated)"), "", "linkage.verification.time_ratio", 1.0),
             (N_("max pressure angle"), "°", "linkage.quality.0.extreme", _DEG),
             (N_("flywheel J_F"), "kg·m²", "flywheel.inertia", 1.0),
             (N_("mean power"), "W", "linkage.mean_power", 1.0),
             (N_("motor"), "", "drive.motor.designation", 1.0)))
