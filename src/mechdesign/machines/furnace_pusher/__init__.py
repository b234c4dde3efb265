"""Furnace pusher (推料机): a crank-rocker with a slider output pushing the charge,
synthesised from the stroke, K and the pressure angle limit, with its drive.

The whole machine is this package: its brief (:mod:`.brief`), its model, stages and results
(:mod:`.stages`) and its report (:mod:`.report`).
"""
from ...i18n import N_
from ...registry import _DEG, _MM, Entry

_P = __name__
ENTRY = Entry(
    "furnace_pusher", f"{_P}.brief:FurnaceBrief", f"{_P}.brief:furnace_to_si",
    f"{_P}.stages:stages", f"{_P}.stages:results_document", f"{_P}.report",
    "furnace_pusher.yaml", results=f"{_P}.stages:FurnaceResults", summary=(
        (N_("crank"), "mm", "synthesis.crank", _MM),
        (N_("coupler"), "mm", "synthesis.coupler", _MM),
        (N_("stroke H"), "mm", "linkage.output.stroke", _MM),
        ("K", "", "linkage.time_ratio", 1.0),
        ("γ_min", "°", "synthesis.gamma_min", _DEG),
        (N_("mean power"), "W", "linkage.mean_power", 1.0),
        (N_("motor"), "", "drive.motor.designation", 1.0)),
    checks=f"{_P}.stages:checks")
