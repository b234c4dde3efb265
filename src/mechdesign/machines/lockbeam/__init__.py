"""Lock-beam bending machine (锁梁自动成型机): feed linkage, bending linkage, cam, the
transmission train and the working cycle.

The whole machine is this package: its brief (:mod:`.brief`), its model, stages and results
(:mod:`.stages`) and its report (:mod:`.report`).
"""
from ...i18n import N_
from ...registry import _DEG, _MM, Entry

_P = __name__
ENTRY = Entry(
    "lockbeam", f"{_P}.brief:LockbeamBrief", f"{_P}.brief:lockbeam_to_si",
    f"{_P}.stages:stages", f"{_P}.stages:results_document", f"{_P}.report",
    "lockbeam.yaml", results=f"{_P}.stages:LockbeamResults", summary=(
        (N_("total ratio"), "", "transmission.ratio", 1.0, "exact"),   # a product of tooth ratios
        (N_("feed stroke"), "mm", "feed.output.stroke", _MM),
        (N_("feed K"), "", "feed.time_ratio", 1.0),
        # the bending four-bar as drawn and built (its lengths rounded, when the brief rounds)
        (N_("bending four-bar as drawn: input rocker a"), "mm",
         "bending.rounded.input_rocker|bending.input_rocker", _MM),
        (N_("bending four-bar as drawn: coupler b"), "mm", "bending.rounded.coupler|bending.coupler",
         _MM),
        (N_("bend of the linkage as drawn (simulated)"), "°",
         "bending.bend_simulated", _DEG),
        (N_("bending γ_min of the linkage as drawn"), "°",
         "bending.cycle.gamma_min", _DEG)),
    checks=f"{_P}.stages:checks",
    # two cams on the main shaft, a sheet each
    cams=(("cam", N_("positioning cam")), ("bending_cam", N_("bending cam"))))
