"""A small stage pipeline: each stage reads earlier results and adds one entry.

Machines declare their stages as a list; the pipeline runs them in order, reports
progress and times each stage. It knows nothing about any machine.
"""
from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any, Callable

Progress = Callable[[int, int, str], None]


@dataclass(frozen=True)
class Stage:
    """``key`` names the result, ``title`` is shown while it runs, ``run`` computes it.

    A stage that yields several results names them all: ``key`` is then a tuple and
    ``run`` returns a tuple of the same length.
    """

    key: str | tuple[str, ...]
    title: str
    run: Callable[[dict[str, Any]], Any]


def run_stages(stages: list[Stage], inputs: dict[str, Any],
               progress: Progress | None = None) -> tuple[dict[str, Any], dict[str, float]]:
    """Run ``stages`` on ``inputs``; return all results and the seconds each stage took
    (by stage title)."""
    results = dict(inputs)
    timings: dict[str, float] = {}
    for i, stage in enumerate(stages, 1):
        if progress is not None:
            progress(i, len(stages), stage.title)
        start = time.perf_counter()
        value = stage.run(results)
        if isinstance(stage.key, tuple):
            results.update(zip(stage.key, value, strict=True))
        else:
            results[stage.key] = value
        timings[stage.title] = time.perf_counter() - start
    return results, timings
