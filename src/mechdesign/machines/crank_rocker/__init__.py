"""Crank-rocker synthesis (曲柄摇杆机构设计) from K, the swing angle and the rocker.

The whole machine is this package: its brief (:mod:`.brief`), its model, stages and results
(:mod:`.stages`) and its report (:mod:`.report`).
"""
from ...i18n import N_
from ...registry import _DEG, _MM, Entry

_P = __name__
ENTRY = Entry(
    "crank_rocker", f"{_P}.brief:CrankRockerBrief",
    f"{_P}.brief:crank_rocker_to_si", f"{_P}.stages:stages",
    f"{_P}.stages:results_document", f"{_P}.report", "crank_rocker.yaml",
    results=f"{_P}.stages:CrankRockerResults", checks=f"{_P}.stages:checks", summary=(
        (N_("crank"), "mm", "optimum.crank", _MM),
        (N_("coupler"), "mm", "optimum.coupler", _MM),
        (N_("frame"), "mm", "optimum.frame", _MM),
        ("γ_min", "°", "optimum.gamma_min", _DEG)))
