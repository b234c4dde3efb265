"""Key results of a run, for the batch index: a few labelled numbers per machine.

Read from the machine's results document (what results.json holds, SI), converted to
the course's units here, at the boundary.
"""
from __future__ import annotations

import math
from typing import Any

def _rows(machine: str) -> tuple:
    """(label (English, translated where shown), unit, dotted path in the results document,
    factor SI → unit), as the machine's registry entry lists them."""
    from ..registry import entry

    try:
        return entry(machine).summary
    except KeyError:
        return ()


def _get(document: Any, path: str) -> Any:
    node = document
    for part in path.split("."):
        if isinstance(node, dict):
            node = node.get(part)
        else:
            node = getattr(node, part, None)
        if node is None:
            return None
    return node


def _show(value: Any, factor: float) -> str | None:
    if isinstance(value, bool) or value is None:
        return None
    if isinstance(value, str):
        return value
    try:
        x = float(value) * factor
    except (TypeError, ValueError):
        return None
    if math.isfinite(x):
        return f"{x:.4g}" if abs(x) < 1e4 else f"{x:.0f}"
    return None


def summary_rows(machine: str, document: dict, lang: str) -> list[tuple[str, str]]:
    """(label with unit, value) pairs of the machine's key results present in ``document``."""
    from ..registry import summary_row

    rows = []
    for row in _rows(machine):
        label, unit, path, factor = summary_row(row, lang, document)
        value = _get(document, path)
        if path.endswith(".peak_torque") and not value:
            continue        # no loads given: no driving torque was computed
        text = _show(value, factor)
        if text is None:
            continue
        rows.append((f"{label} [{unit}]" if unit else label, text))
    return rows


def summarise(machine_name: str, results: dict, lang: str) -> list[tuple[str, str]]:
    """Key results of a finished run (its results document, in the course's units)."""
    from . import get_machine

    from ..results import to_plain

    return summary_rows(machine_name, to_plain(get_machine(machine_name).document(results)), lang)
