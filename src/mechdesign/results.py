"""Serialise frozen result dataclasses to plain JSON (SI units throughout).

numpy arrays become lists, complex numbers ``[x, y]`` pairs, dataclasses objects (a
dataclass with a ``__plain__`` method gives its own: a finding adds its English text).
"""
from __future__ import annotations

import dataclasses
import json
import math
from typing import Any

import numpy as np


def to_plain(value: Any) -> Any:
    """Plain Python data (dict/list/float/str) for JSON."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        if hasattr(type(value), "__plain__"):    # its own form (a finding adds its text)
            return to_plain(value.__plain__())
        return {f.name: to_plain(getattr(value, f.name)) for f in dataclasses.fields(value)}
    if isinstance(value, dict):
        return {str(k): to_plain(v) for k, v in value.items()}
    if isinstance(value, np.ndarray):
        if np.isrealobj(value) and value.dtype.kind in "fiu" and np.isfinite(value).all():
            return value.tolist()  # fast path for the long grid arrays
        return [to_plain(v) for v in value.tolist()]
    if isinstance(value, (list, tuple)):
        return [to_plain(v) for v in value]
    if isinstance(value, (complex, np.complexfloating)):
        return [_number(value.real), _number(value.imag)]
    if isinstance(value, (np.floating, float)):
        return _number(float(value))
    if isinstance(value, (np.integer,)):
        return int(value)
    if isinstance(value, np.bool_):
        return bool(value)
    return value


def _number(x: float) -> float | None:
    return None if math.isnan(x) or math.isinf(x) else float(x)


def dumps(document: dict) -> str:
    return json.dumps(to_plain(document), ensure_ascii=False, indent=1)


# Every machine's document is a typed results class whose fields state their units
# (mechdesign.core.fields.q); docs/results.md is generated from them (results_docs).
SCHEMA = "mechdesign.results/2"
UNITS_NOTE = "SI: m, s, rad, kg, N, N·m, J, W; complex vectors as [x, y]"
