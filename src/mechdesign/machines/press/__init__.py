"""Press (压床): a six-bar in which a crank-rocker (crank AB, coupler BC, rocker DE) drives
the ram F on a vertical guide through the rod EF; the ram presses on its downward stroke.
The whole machine is this package: its brief (:mod:`.brief`), its synthesis, model and
stages (:mod:`.stages`) and its report (:mod:`.report`); everything else is the shared
engine, stages and report sections.
"""
from ...i18n import N_
from ...registry import _DEG, _MM, Entry

_P = __name__
ENTRY = Entry(
    name="press", brief=f"{_P}.brief:PressBrief", to_params=f"{_P}.brief:to_si",
    stages=f"{_P}.stages:stages", document=f"{_P}.stages:results_document",
    report=f"{_P}.report", example="press.yaml", results=f"{_P}.stages:PressResults",
    checks=f"{_P}.stages:checks",
    summary=((N_("crank"), "mm", "synthesis.crank", _MM),
             (N_("coupler BC"), "mm", "synthesis.coupler", _MM),
             (N_("rocker DE"), "mm", "synthesis.rocker", _MM),
             (N_("K (simulated)"), "", "linkage.verification.time_ratio", 1.0),
             (N_("flywheel J_F"), "kg·m²", "flywheel.inertia", 1.0),
             (N_("mean power"), "W", "linkage.mean_power", 1.0)))
