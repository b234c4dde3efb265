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
    stages: list[Stage]
    document: Callable[[dict], dict]
    report_module: str


def _shaper() -> Machine:
    from ..brief.shaper import to_si
    from . import shaper

    return Machine("shaper", to_si, shaper.STAGES, shaper.results_document,
                   "mechdesign.render.shaper_report")


MACHINES: dict[str, Callable[[], Machine]] = {"shaper": _shaper}


def get_machine(name: str) -> Machine:
    return MACHINES[name]()
