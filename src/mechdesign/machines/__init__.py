"""Machines: each composes the shared stages for one course task.

``MACHINES`` maps the brief's ``machine`` field to what the pipeline needs: the
conversion of the brief to SI parameters, the stages, the ``results.json`` document
and the module that prepares the report (figures and template context).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from ..pipeline import Stage


@dataclass(frozen=True)
class Machine:
    name: str
    to_params: Callable
    stages: list[Stage] | Callable[[object], list[Stage]]   # or a function of the parameters
    document: Callable[[dict], dict]
    report_module: str
    #: Feasibility checks run once per run after validation: ``checks(params, keep)`` →
    #: every problem (BriefProblem at its brief field); what they compute goes into ``keep``,
    #: which the stages find as ``results["checked"]``. None: the machine has none.
    checks: Callable | None = None


def _shaper() -> Machine:
    from ..brief.shaper import to_si
    from . import shaper

    return Machine("shaper", to_si, shaper.stages, shaper.results_document,
                   "mechdesign.render.shaper_report")


def _cam() -> Machine:
    from ..brief.cam import cam_brief_to_si
    from . import cam

    return Machine("cam", cam_brief_to_si, cam.CAM_STAGES, cam.cam_results_document,
                   "mechdesign.render.cam_report")


def _eccentric_cam() -> Machine:
    from ..brief.cam import eccentric_to_si
    from . import cam

    return Machine("eccentric_cam", eccentric_to_si, cam.DISC_STAGES, cam.disc_results_document,
                   "mechdesign.render.disc_report")


def _drive() -> Machine:
    from ..brief.drive import drive_brief_to_si
    from . import drive

    return Machine("drive", drive_brief_to_si, drive.DRIVE_STAGES, drive.drive_results_document,
                   "mechdesign.render.drive_report")


def _linkage() -> Machine:
    from . import linkage

    return Machine("linkage", linkage.linkage_params, linkage.STAGES, linkage.results_document,
                   "mechdesign.render.linkage_report")


def _crank_rocker() -> Machine:
    from ..brief.crank_rocker import crank_rocker_to_si
    from . import crank_rocker

    return Machine("crank_rocker", crank_rocker_to_si, crank_rocker.stages,
                   crank_rocker.results_document, "mechdesign.render.crank_rocker_report")


def _furnace_pusher() -> Machine:
    from ..brief.furnace import furnace_to_si
    from . import furnace

    return Machine("furnace_pusher", furnace_to_si, furnace.stages, furnace.results_document,
                   "mechdesign.render.furnace_report", furnace.checks)


def _die_cutter() -> Machine:
    from ..brief.die_cutter import die_cutter_to_si
    from . import die_cutter

    return Machine("die_cutter", die_cutter_to_si, die_cutter.stages, die_cutter.results_document,
                   "mechdesign.render.die_cutter_report", die_cutter.checks)


def _lockbeam() -> Machine:
    from ..brief.lockbeam import lockbeam_to_si
    from . import lockbeam

    return Machine("lockbeam", lockbeam_to_si, lockbeam.stages, lockbeam.results_document,
                   "mechdesign.render.lockbeam_report", lockbeam.checks)


MACHINES: dict[str, Callable[[], Machine]] = {
    "shaper": _shaper, "furnace_pusher": _furnace_pusher, "lockbeam": _lockbeam,
    "die_cutter": _die_cutter, "crank_rocker": _crank_rocker, "linkage": _linkage,
    "cam": _cam, "eccentric_cam": _eccentric_cam, "drive": _drive}


def stages_for(machine: Machine, params) -> list[Stage]:
    """The machine's stages for these parameters (some depend on optional brief sections)."""
    return machine.stages(params) if callable(machine.stages) else machine.stages


def get_machine(name: str) -> Machine:
    return MACHINES[name]()
