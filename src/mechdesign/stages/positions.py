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
