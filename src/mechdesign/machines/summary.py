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
    from ..registry import shown_row

    rows = []
    for row in _rows(machine):
        shown = shown_row(row, lang, document)
        if shown is None:
            continue
        label, unit, factor, value = shown
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
