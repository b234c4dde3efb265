"""The `cam` machine: synthesis of a disc cam on its own (the shared cam stage,
:mod:`mechdesign.stages.cam`).

The whole machine is this package: its brief (:mod:`.brief`), its stages and results
(:mod:`.stages`) and its report (:mod:`.report`).
"""
from ...i18n import N_
from ...registry import _MM, Entry

_P = __name__
ENTRY = Entry(
    "cam", f"{_P}.brief:CamBrief", f"{_P}.brief:cam_brief_to_si", f"{_P}.stages:CAM_STAGES",
    f"{_P}.stages:cam_results_document", f"{_P}.report", "cam_7_3.yaml",
    results=f"{_P}.stages:CamResults", summary=(
        (N_("base radius r0"), "mm", "cam.base_radius", _MM),
        (N_("least base radius"), "mm", "cam.min_base_radius", _MM),
        (N_("roller radius"), "mm", "cam.roller_radius", _MM),
        (N_("least profile radius of curvature"), "mm",
         "cam.rho_actual_min_convex", _MM)))
