"""The `drive` machine: a transmission (motor, stages, shafts) designed for a given load on
its own (the shared drive stage, :mod:`mechdesign.stages.drive`).

The whole machine is this package: its brief (:mod:`.brief`), its stages and results
(:mod:`.stages`) and its report (:mod:`.report`).
"""
from ...i18n import N_
from ...registry import Entry

_P = __name__
ENTRY = Entry(
    "drive", f"{_P}.brief:DriveBrief", f"{_P}.brief:drive_brief_to_si", f"{_P}.stages:DRIVE_STAGES",
    f"{_P}.stages:drive_results_document", f"{_P}.report", "furnace_drive.yaml",
    results=f"{_P}.stages:DriveResults", summary=(
        (N_("total ratio"), "", "drive.total_ratio", 1.0),
        # review39: "power required 62.96 W" read as the work's need (44.0 W): both, named
        (N_("power at the machine"), "W", "drive.machine_power", 1.0),
        (N_("power the motor must give"), "W", "drive.power_required", 1.0),
        (N_("motor"), "", "drive.motor.designation", 1.0),
        (N_("output speed"), "rpm", "drive.output_speed_rpm", 1.0)))
