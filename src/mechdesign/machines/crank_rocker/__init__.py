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
        # two mechanisms are designed: each row names its own (the slider-crank's stroke and
        # K are not the crank-rocker's)
        (N_("crank-rocker: crank AB"), "mm", "optimum.crank", _MM),
        (N_("crank-rocker: coupler BC"), "mm", "optimum.coupler", _MM),
        (N_("crank-rocker: rocker CD"), "mm", "optimum.rocker", _MM),
        (N_("crank-rocker: frame AD"), "mm", "optimum.frame", _MM),
        (N_("crank-rocker: rocker swing ψ"), "°", "optimum.swing", _DEG),
        (N_("crank-rocker: time ratio K"), "", "linkage.time_ratio", 1.0),
        (N_("crank-rocker: γ_min"), "°", "optimum.gamma_min", _DEG),
        (N_("offset slider-crank: crank a"), "mm", "slider_crank.crank", _MM),
        (N_("offset slider-crank: rod b"), "mm", "slider_crank.rod", _MM),
        (N_("offset slider-crank: stroke H"), "mm", "slider_crank.stroke", _MM),
        (N_("offset slider-crank: time ratio K"), "", "slider_crank.K", 1.0)))
