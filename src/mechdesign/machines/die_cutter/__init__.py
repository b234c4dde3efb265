"""Die-cutting press (平压模切机): a toggle press with its flywheel, drive, the
intermittent feed, the cam and the working cycle.

The whole machine is this package: its brief (:mod:`.brief`), its model, stages and results
(:mod:`.stages`) and its report (:mod:`.report`).
"""
from ...i18n import N_
from ...registry import _MM, Entry

_P = __name__
ENTRY = Entry(
    "die_cutter", f"{_P}.brief:DieCutterBrief", f"{_P}.brief:die_cutter_to_si",
    f"{_P}.stages:stages", f"{_P}.stages:results_document", f"{_P}.report",
    "die_cutter.yaml", results=f"{_P}.stages:DieCutterResults", summary=(
        (N_("crank"), "mm", "toggle.crank", _MM),
        (N_("stroke"), "mm", "press.output.stroke", _MM),
        ("K", "", "press.time_ratio", 1.0),
        (N_("peak balancing torque"), "N·m", "press.peak_torque", 1.0),
        (N_("flywheel J_F"), "kg·m²", "flywheel.inertia", 1.0),
        # to 0.1 J as the body writes it: J_F = 900 ΔW/(π²n²[δ]) then checks to its 4 digits
        (N_("largest energy swing ΔW_max"), "J", "flywheel.max_energy_swing", 1.0, 1),
        (N_("motor"), "", "drive.motor.designation", 1.0)),
    checks=f"{_P}.stages:checks")
