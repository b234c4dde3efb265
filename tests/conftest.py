"""Shared test fixtures.

``example_results(name)`` gives the computed results of the example brief
``designs/<name>.yaml`` (its default group): what ``mechdesign run`` computes before it
renders — the brief read by :func:`~mechdesign.brief.loader.load_brief`, the machine's
SI parameters and every stage (:func:`~mechdesign.pipeline.run_stages`), no rendering.
Each brief is computed once per test session, on first use, and shared by every test
module that asks for it.

The results must NOT be mutated. Each call returns a fresh shallow copy of the results
dict, so adding or replacing a top-level key stays local to the caller, but the values
(frozen dataclasses holding numpy arrays, dicts and lists; ``params`` and ``brief`` too)
are the same objects for every test: never write into an array, a dict or a list taken
from them. A test that needs changed results computes its own (e.g. from an edited
brief) or uses :func:`dataclasses.replace`.

Markers: ``e2e`` (registered in pyproject.toml) marks end-to-end tests — the CLI run in a
subprocess or through typer's runner, a PDF, DOCX or drawing sheets rendered, a whole
batch run. ``python -m pytest -m "not e2e"`` runs the fast suite alone.
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Callable

import pytest

# Every test draws and compiles for itself: the render cache (mechdesign/render/cache.py)
# would otherwise serve files drawn by an earlier run, and a test that breaks drawing
# would pass. tests/test_render_cache.py turns it on in a folder of its own.
os.environ.setdefault("MECHDESIGN_CACHE", "off")

ROOT = Path(__file__).resolve().parents[1]
DESIGNS = ROOT / "designs"


def compute_example(name: str) -> dict[str, Any]:
    """Validate and compute ``designs/<name>.yaml`` (default group) without rendering, as
    :func:`mechdesign.runner.run_one` does."""
    from mechdesign.brief.loader import load_brief
    from mechdesign.machines import get_machine, stages_for
    from mechdesign.pipeline import run_stages

    brief = load_brief(DESIGNS / f"{name}.yaml")
    machine = get_machine(brief.machine)
    params = machine.to_params(brief)
    results, _ = run_stages(stages_for(machine, params), {"params": params, "brief": brief})
    return results


@pytest.fixture(scope="session")
def example_results() -> Callable[[str], dict[str, Any]]:
    """``example_results("shaper")``: the computed results of designs/shaper.yaml, cached
    for the session (a fresh shallow copy of the dict per call; do not mutate the values)."""
    cache: dict[str, dict[str, Any]] = {}

    def get(name: str) -> dict[str, Any]:
        if not (DESIGNS / f"{name}.yaml").is_file():
            raise ValueError(f"no example brief designs/{name}.yaml")
        if name not in cache:
            cache[name] = compute_example(name)
        return dict(cache[name])

    return get


@pytest.fixture(scope="session")
def handin_reports(example_results, tmp_path_factory) -> Callable[[str, str], tuple[str, dict]]:
    """``handin_reports("shaper", "zh")``: (Markdown, results document) of an example report
    as ``mechdesign run`` writes them, with placeholder figures and no sheets
    (tests/test_handin.py's ``render``), rendered on first use and cached for the session."""
    cache: dict[tuple[str, str], tuple[str, dict]] = {}

    def get(name: str, lang: str) -> tuple[str, dict]:
        from test_handin import render

        if (name, lang) not in cache:
            tmp = tmp_path_factory.mktemp(f"{name}-{lang}") / "figures"
            cache[name, lang] = render(name, lang, example_results(name), tmp)
        return cache[name, lang]

    return get


def read_pdf_text(path: Path, first: int | None = None, last: int | None = None) -> str:
    """The text of a PDF's pages ``first``..``last`` (1-based, inclusive), in content-stream
    order, read with PyMuPDF (a test dependency from PyPI, so the tests that read a PDF's text
    run on a bare machine too; pdftotext is a system package). Runs of spaces of any kind
    (no-break, em space) become one space, as pdftotext writes them."""
    import re

    import pymupdf

    with pymupdf.open(path) as doc:
        lo = (first or 1) - 1
        hi = last or doc.page_count
        text = "\n".join(doc[i].get_text("text", sort=False) for i in range(lo, hi))
    return re.sub(r"[^\S\n]+", " ", text)


@pytest.fixture
def pdf_text() -> Callable[..., str]:
    """:func:`read_pdf_text`, for tests that check words in a rendered PDF."""
    return read_pdf_text


def wait_until(predicate: Callable[[], Any], timeout: float, proc, step: float = 0.05) -> None:
    """Poll ``predicate`` until it holds, failing when ``proc`` (a watch) ends or after
    ``timeout`` seconds (the watch tests)."""
    import time

    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():
            return
        assert proc.poll() is None, "the watch ended"
        time.sleep(step)
    raise AssertionError("timed out")
