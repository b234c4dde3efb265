"""The `linkage` machine: any planar linkage written in the brief (crank + Assur groups) on
the one linkage engine (:mod:`mechdesign.stages.linkage`).

The whole machine is this package: its brief (:mod:`.brief`), its stages and results
(:mod:`.stages`) and its report (:mod:`.report`).
"""
from ...i18n import N_
from ...registry import _MM, Entry

_P = __name__
ENTRY = Entry(
    "linkage", f"{_P}.brief:LinkageBrief", f"{_P}.stages:linkage_params",
    f"{_P}.stages:STAGES", f"{_P}.stages:results_document", f"{_P}.report",
    "linkage_sixbar.yaml", results=f"{_P}.stages:LinkageResults", summary=(
        (N_("stroke"), "mm", "linkage.output.stroke", _MM),
        ("K", "", "linkage.time_ratio", 1.0),
        (N_("mean balancing torque"), "N·m", "linkage.mean_torque", 1.0),
        (N_("peak balancing torque"), "N·m", "linkage.peak_torque", 1.0),
        (N_("flywheel J_F"), "kg·m²", "linkage.flywheel.inertia", 1.0)))
