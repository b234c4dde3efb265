"""Two runs of the same tree give the same results.json, and the comparison tool says so.

Session 35 saw the die-cutter's ``cycle.actuators.*`` names and phase labels differ between
two snapshots of the same commit. The documents were byte-identical (also under different
``PYTHONHASHSEED``s: nothing in the cycle depends on set or dict order); the difference was
tools/compare_results.py's: it made the texts of a phase's message label (``label`` =
{msgid, context}, ``label_zh`` empty) on the new document only, so a document compared with
itself reported 40 differences.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
import compare_results  # noqa: E402


def _document(results) -> dict:
    from mechdesign.machines import get_machine
    from mechdesign.results import dumps, to_plain

    machine = get_machine(results["brief"].machine)
    return json.loads(dumps(to_plain(machine.document(results))))


def test_the_die_cutter_document_holds_its_cycle_names_as_messages(example_results):
    doc = _document(example_results("die_cutter"))
    acts = doc["cycle"]["actuators"]
    # what made the one-sided comparison differ: program-named actuators and phases are
    # catalogue messages with empty text fields
    assert any(isinstance(a.get("name"), dict) and a["name_zh"] == "" for a in acts)
    assert any(isinstance(ph.get("label"), dict) and ph["label_zh"] == ""
               for a in acts for ph in a["phases"])


@pytest.mark.parametrize("name", ["die_cutter", "lockbeam", "furnace_drive"])
def test_a_document_compared_with_itself_agrees(example_results, name):
    # (not crank_rocker: RENAMES maps its old link numbers 2, 3, 4 to 1, 2, 3, for old documents)
    doc = _document(example_results(name))
    assert compare_results.compare(doc, json.loads(json.dumps(doc))) == []


def test_a_changed_cycle_label_is_still_found(example_results):
    doc = _document(example_results("die_cutter"))
    other = json.loads(json.dumps(doc))
    phase = other["cycle"]["actuators"][0]["phases"][0]
    phase["label"] = {**phase["label"], "msgid": "falling"}
    problems = compare_results.compare(doc, other)
    assert problems and all("cycle.actuators.0.phases.0.label" in p for p in problems)


_CYCLE = """
import json, sys
sys.path.insert(0, {root!r})
from tests.conftest import compute_example
from tests.test_compare_self import _document
doc = _document(compute_example("die_cutter"))
print(json.dumps(doc["cycle"], sort_keys=False))
"""


@pytest.mark.e2e
def test_the_die_cutter_cycle_does_not_depend_on_the_hash_seed():
    """The cycle's actuators, phases and labels, in order, from two processes whose set
    and str hashes differ (PYTHONHASHSEED 0 and 1)."""
    out = []
    for seed in ("0", "1"):
        env = {**os.environ, "PYTHONHASHSEED": seed, "MECHDESIGN_CACHE": "off"}
        run = subprocess.run([sys.executable, "-c", _CYCLE.format(root=str(ROOT))], cwd=ROOT,
                             env=env, capture_output=True, text=True, timeout=600)
        assert run.returncode == 0, run.stderr[-2000:]
        out.append(run.stdout)
    assert out[0] == out[1]
    keys = [a["key"] for a in json.loads(out[0])["actuators"]]
    assert keys == ["platen", "gripper", "chain"]
