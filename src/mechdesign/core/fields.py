"""Result fields that state their unit: ``x: float = q("m", "meaning")``.

``unit`` is the SI unit of a number or array ("m", "rad", "N·m", "kg·m²"; "rpm" where the
course's formula needs it), "1" for a pure number, "" for text, flags and structure.
``docs/results.md`` is generated from this metadata (``python -m mechdesign.results_docs``).
"""
from __future__ import annotations

import dataclasses
from typing import Any


def q(unit: str, doc: str = "", *, default: Any = dataclasses.MISSING,
      default_factory: Any = dataclasses.MISSING) -> Any:
    """A dataclass field with ``{"unit": unit, "doc": doc}`` metadata."""
    return dataclasses.field(default=default, default_factory=default_factory,
                             metadata={"unit": unit, "doc": doc})
