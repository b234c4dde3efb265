"""The `drive` machine: the shared drive stage (:mod:`mechdesign.stages.drive`) on its own, with its results document."""
from __future__ import annotations

from dataclasses import dataclass
from ...core.fields import q
from ...pipeline import Stage
from ...stages.cam import VerificationDocument
from ...stages.drive import DriveDocument, design_drive, drive_document, verify_drive
from ...stages import titles


def drive_stage_standalone() -> Stage:
    def run(r):
        p = r["params"]
        return design_drive(p.drive, p.load.power, p.load.output_speed_rpm, p.load.how)
    return Stage("drive", titles.pgettext("stage", "drive"), run)


DRIVE_STAGES = [drive_stage_standalone(),
                Stage("drive_verification", titles.pgettext("stage: self-checks", "verification"), lambda r: verify_drive(r["drive"]))]


DRIVE_UNITS = "SI: m, s, rad, N, N·m, W, Pa; speeds in rpm where named _rpm"


@dataclass(frozen=True)
class DriveResults:
    """Drive (传动装置设计): a drive designed on its own for a machine's load at its input
    shaft (the brief's power, torque or stroke work at the machine's speed), with the
    self-checks of its table of speed, power and torque, its ratios and its strength
    verdicts. Speeds are in rpm where a key ends in `_rpm`; strength checks hold SI values
    with the course unit they are shown in."""

    schema: str = q("", "'mechdesign.results/2'")
    machine: str = q("", "'drive'")
    units: str = q("", "reminder of the unit system")
    drive: DriveDocument = q("", "the drive")
    verification: VerificationDocument | None = q("", "self-checks, as the cam's verification document")


def drive_results_document(r: dict) -> DriveResults:
    from ...results import SCHEMA
    from ...stages.cam import verification_document

    return DriveResults(
        schema=SCHEMA, machine="drive", units=DRIVE_UNITS, drive=drive_document(r["drive"]),
        verification=(None if r.get("drive_verification") is None
                      else verification_document(r["drive_verification"])))
