"""Machines: each composes the shared stages for one course task.

``MACHINES`` maps the brief's ``machine`` field to what the pipeline needs: the
conversion of the brief to SI parameters, the stages, the ``results.json`` document
and the module that prepares the report (figures and template context).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable

if TYPE_CHECKING:
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


def _from_registry(name: str) -> Machine:
    from ..registry import entry, resolve

    e = entry(name)
    stages = resolve(e.stages)
    return Machine(e.name, resolve(e.to_params), stages, resolve(e.document), e.report,
                   resolve(e.checks) if e.checks else None)


class _Machines(dict):
    """Machine name → factory of its :class:`Machine`, from :mod:`mechdesign.registry`."""

    def __init__(self):
        from ..registry import names

        super().__init__({n: (lambda n=n: _from_registry(n)) for n in names()})


MACHINES: dict[str, Callable[[], Machine]] = _Machines()


def stages_for(machine: Machine, params) -> list[Stage]:
    """The machine's stages for these parameters (some depend on optional brief sections)."""
    return machine.stages(params) if callable(machine.stages) else machine.stages


def get_machine(name: str) -> Machine:
    return MACHINES[name]()
