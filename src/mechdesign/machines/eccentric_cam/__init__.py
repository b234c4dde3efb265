"""The `eccentric_cam` machine: analysis of a given eccentric circular disc cam with one or
more translating followers (exercises 7-1/7-2).

The whole machine is this package: its brief (:mod:`.brief`), its stages and results
(:mod:`.stages`) and its report (:mod:`.report`).
"""
from ...i18n import N_
from ...registry import _MM, Entry

_P = __name__
ENTRY = Entry(
    "eccentric_cam", f"{_P}.brief:EccentricCamBrief", f"{_P}.brief:eccentric_to_si",
    f"{_P}.stages:DISC_STAGES", f"{_P}.stages:disc_results_document", f"{_P}.report",
    "cam_7_1.yaml", results=f"{_P}.stages:EccentricCamResults", summary=(
        (N_("disc radius"), "mm", "radius", _MM),
        (N_("eccentricity"), "mm", "eccentricity", _MM)))
