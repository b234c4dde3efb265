"""Issue 17: the redesign changed no number. Every example brief and every data group is
computed now and compared with the results saved before the redesign
(tests/data/baseline, reduced: long arrays sampled) by tools/compare_results.py: every
number to 1e-9 relative, renamed keys mapped by its RENAMES, the deliberate corrections
listed in its EXPECTED (each with its reason) excepted."""
from __future__ import annotations

import gzip
import importlib.util
import json
from pathlib import Path

import pytest

from mechdesign.brief.loader import load_variant, read_brief_data
from mechdesign.machines import get_machine, stages_for
from mechdesign.pipeline import run_stages
from mechdesign.results import to_plain

ROOT = Path(__file__).parents[1]
BASE = ROOT / "tests" / "data" / "baseline"

spec = importlib.util.spec_from_file_location("compare_results", ROOT / "tools" / "compare_results.py")
compare_results = importlib.util.module_from_spec(spec)
spec.loader.exec_module(compare_results)


def _runs():
    for f in sorted(BASE.glob("*.json.gz")):
        name = f.name.removesuffix(".json.gz")
        stem, _, group = name.partition("-g")
        yield pytest.param(stem, group or None, f, id=name)


@pytest.mark.parametrize("stem,group,saved", list(_runs()))
def test_every_number_as_before_the_redesign(stem, group, saved):
    variant = load_variant(ROOT / "designs" / f"{stem}.yaml", group)
    machine = get_machine(variant.brief.machine)
    params = machine.to_params(variant.brief)
    results, _ = run_stages(stages_for(machine, params), {"params": params, "brief": variant.brief})
    document = json.loads(json.dumps(to_plain(machine.document(results))))
    if group is not None:
        document["data_group"] = variant.group
    with gzip.open(saved, "rt", encoding="utf-8") as fh:
        old = json.load(fh)
    problems = compare_results.compare(old, document, stem=stem)
    assert not problems, "\n".join(problems[:30])


def test_the_comparison_can_fail():
    """A changed number, a missing key and a changed text are each reported."""
    old = {"machine": "x", "a": 1.0, "b": [1.0, 2.0], "c": "text"}
    assert compare_results.compare(old, old) == []
    assert compare_results.compare(old, {**old, "a": 1.0 + 1e-8})
    assert compare_results.compare(old, {"machine": "x", "b": [1.0, 2.0], "c": "text"})
    assert compare_results.compare(old, {**old, "c": "other"})
    assert compare_results.compare(old, {**old, "a": 1.0 + 1e-12}) == []
