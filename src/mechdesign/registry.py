"""The one place where machines are registered: one line per machine, naming its package.

Each package's ``ENTRY`` says where the machine's parts live, as "module:attribute"
strings resolved on first use (so `mechdesign check` imports only the brief model it
needs, never the engine): the brief model, the conversion to SI parameters, the stages,
the results document and its typed class, the report module (figures, template context,
optional animation and data files), the example brief (the starter of `mechdesign new`),
the feasibility checks and the rows of the batch index.
"""
from __future__ import annotations

import importlib
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, Callable

_MM, _DEG = 1000.0, 180.0 / math.pi


@dataclass(frozen=True)
class Entry:
    name: str
    brief: str                  # "module:Class" of the pydantic brief model
    to_params: str              # "module:function" brief → SI parameters
    stages: str                 # "module:attr": a list of stages or a function of the parameters
    document: str               # "module:function" results → results.json document
    report: str                 # module with make_figures(r, dir, lang) and context(r, brief, figs, lang)
    example: str                # file name in designs/
    # (label: N_(English), unit, dotted path in the results document, factor SI → unit
    # [, digits: the decimals the report's body writes it with, or "exact" for a value it
    # writes as the design gives it; without: the unit's rule, else 4 significant digits])
    summary: tuple = ()
    results: str = ""           # "module:Class" of the typed results document
    checks: str = ""            # "module:function" feasibility checks(params, keep), run once
    # (result key, N_(name)) of each cam of a machine that designs several: one cam sheet
    # per cam, titled with its name (render/sheets.py); a machine with one cam needs none
    cams: tuple = ()


def summary_row(row: tuple, lang: str) -> tuple:
    """(label in ``lang``, unit, path, factor) of an entry's summary row: (N_(English label),
    unit, path, factor)."""
    from .i18n import tr

    label, unit, path, factor = row[:4]
    return tr(lang)(label), unit, path, factor


def lookup(document: Any, path: str) -> Any:
    """The value at a dotted ``path`` of a results document (dicts or objects), or None;
    ``"a.b|a.c"``: the first of the alternatives that has a value."""
    if "|" in path:
        return next((v for v in (lookup(document, alt) for alt in path.split("|"))
                     if v is not None), None)
    node = document
    for part in path.split("."):
        node = node.get(part) if isinstance(node, dict) else getattr(node, part, None)
        if node is None:
            return None
    return node


def shown_row(row: tuple, lang: str, document: Any) -> tuple | None:
    """(label in ``lang``, unit, factor, value) of a summary row (:func:`summary_row`) as the
    results ``document`` gives it, or None when it has no value to show. A stroke whose
    output is a rocker (the output's ``unit`` is rad) is its swing in degrees; a peak torque
    of 0 means no load was given (no driving torque computed) and is not shown."""
    from .i18n import tr

    label, unit, path, factor = summary_row(row, lang)
    value = lookup(document, path)
    if value is None or (path.endswith(".peak_torque") and not value):
        return None
    if path.endswith(".stroke") and lookup(document, path.rsplit(".", 1)[0] + ".unit") == "rad":
        _ = tr(lang)
        return _("swing of the output"), "°", 180 / math.pi, value
    if unit == "rpm":                   # the course's unit word: r/min in Chinese
        unit = tr(lang)("rpm")
    return label, unit, factor, value


def resolve(ref: str) -> Any:
    module, _, attr = ref.partition(":")
    obj = importlib.import_module(module)
    return getattr(obj, attr) if attr else obj


#: Every machine, by its package (each package's ``ENTRY`` says the rest). Adding a machine
#: is adding its line here.
_ENTRIES: dict[str, Entry | str] = {
    "shaper": "mechdesign.machines.shaper",
    "furnace_pusher": "mechdesign.machines.furnace_pusher",
    "lockbeam": "mechdesign.machines.lockbeam",
    "die_cutter": "mechdesign.machines.die_cutter",
    "crank_rocker": "mechdesign.machines.crank_rocker",
    "linkage": "mechdesign.machines.linkage",
    "cam": "mechdesign.machines.cam",
    "eccentric_cam": "mechdesign.machines.eccentric_cam",
    "drive": "mechdesign.machines.drive",
    "slotter": "mechdesign.machines.slotter",
    "press": "mechdesign.machines.press",
}


def names() -> list[str]:
    return list(_ENTRIES)


def entry(name: str) -> Entry:
    """The machine's entry (KeyError for an unknown machine)."""
    e = _ENTRIES[name]
    if isinstance(e, str):
        e = importlib.import_module(e).ENTRY
        _ENTRIES[name] = e
    return e


class Lookup(Mapping):
    """Machine name → ``get(entry)``, each machine's package imported only when its value
    is asked for (``mechdesign check`` of one brief imports one machine)."""

    def __init__(self, get: Callable[[Entry], Any]):
        self._get = get

    def __getitem__(self, machine: str) -> Any:
        return self._get(entry(machine))

    def __iter__(self):
        return iter(_ENTRIES)

    def __len__(self) -> int:
        return len(_ENTRIES)
