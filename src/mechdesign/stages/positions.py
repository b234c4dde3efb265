"""Textbook crank positions (机构位置): every step from position 1 plus special positions.

Labels follow the course: regular positions 1, 2, …; the other extreme takes the
label of the first regular position after it with a prime (the shaper's 8′), any other
special position the label of the regular position before it with a prime (4′, 10′).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Positions:
    """Labels and crank phases [rad from position 1, in the sense of rotation]."""

    labels: tuple[str, ...]
    phase: np.ndarray
    special: tuple[bool, ...]


def textbook_positions(step: float, other_extreme: float, specials: list[float]) -> Positions:
    """Regular positions every ``step`` [rad] from 0, the other extreme, and ``specials``."""
    count = int(round(2 * np.pi / step))
    entries = [(i * step, str(i + 1), False) for i in range(count)]
    tol = 1e-9
    extra = [(other_extreme, True)] + [(s, False) for s in specials]
    for ph, is_extreme in extra:
        ph = ph % (2 * np.pi)
        if any(abs(ph - e[0]) < tol for e in entries):
            continue
        if is_extreme:
            label = f"{int(np.ceil(ph / step - tol)) % count + 1}'"
        else:
            label = f"{int(np.floor(ph / step + tol)) % count + 1}'"
        entries.append((ph, label, True))
    entries.sort(key=lambda e: e[0])
    return Positions(tuple(e[1] for e in entries), np.array([e[0] for e in entries]),
                     tuple(e[2] for e in entries))


def with_requested(pos: Positions, step: float, extra: list) -> tuple[Positions, dict]:
    """``pos`` plus the positions the brief asked for: ``extra`` of (phase [rad], label or
    None, key). A position at the phase of one already there is not repeated: its key names
    that one. Without a label a position takes the course's primed label (the regular
    position before it, 1′, 7′); a label in use gets one more prime. Returns the positions
    and key → label."""
    count = int(round(2 * np.pi / step))
    tol = 1e-9
    entries = list(zip(pos.labels, pos.phase, pos.special))
    names = {}
    for ph, label, key in extra:
        ph = float(ph) % (2 * np.pi)
        if ph > 2 * np.pi - tol:
            ph = 0.0
        hit = next((e for e in entries if abs(e[1] - ph) < tol), None)
        if hit is not None:
            names[key] = hit[0]
            continue
        if label is None:
            label = f"{int(np.floor(ph / step + tol)) % count + 1}'"
        while label in (e[0] for e in entries):
            label += "'"
        entries.append((label, ph, True))
        names[key] = label
    entries.sort(key=lambda e: e[1])
    return (Positions(tuple(e[0] for e in entries), np.array([e[1] for e in entries]),
                      tuple(e[2] for e in entries)), names)
