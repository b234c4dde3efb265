"""Shaper (牛头刨床): a guide-bar six-bar driving a horizontal ram that cuts on its slow
stroke, with optional gear pair, drive and cam sections.

The whole machine is this package: its brief (:mod:`.brief`), its model, stages and results
(:mod:`.stages`) and its report (:mod:`.report`).
"""
from ...i18n import N_
from ...registry import _MM, Entry

_P = __name__
ENTRY = Entry(
    "shaper", f"{_P}.brief:ShaperBrief", f"{_P}.brief:to_si", f"{_P}.stages:stages",
    f"{_P}.stages:results_document", f"{_P}.report", "shaper.yaml", results=f"{_P}.stages:ShaperResults", summary=(
        (N_("crank"), "mm", "synthesis.crank", _MM),
        (N_("guide bar"), "mm", "synthesis.guide_bar", _MM),
        (N_("K (simulated)"), "", "verification.time_ratio_simulated", 1.0),
        (N_("flywheel J_F"), "kg·m²", "flywheel.inertia", 1.0),
        (N_("mean power"), "W", "flywheel.mean_power", 1.0),
        (N_("motor"), "", "drive.motor.designation", 1.0)))
