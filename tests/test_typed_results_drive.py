"""Typed results (issue 17 point 3) of the drive, furnace_pusher and slotter machines: the
document is the registered results class, every numeric field states its unit, and the
serialised numbers agree with independent references (the shaft table's T = P/ω, the
flywheel's torque on its shaft M_d·n_crank/n_shaft from the brief's teeth)."""
from __future__ import annotations

import json

import numpy as np
import pytest

from mechdesign.machines import get_machine
from mechdesign.registry import entry, resolve
from mechdesign.results import SCHEMA, dumps
from mechdesign.results_docs import missing_units

CASES = [("drive", "furnace_drive"), ("furnace_pusher", "furnace_pusher"),
         ("slotter", "slotter")]


@pytest.mark.parametrize("machine,example", CASES)
def test_document_is_the_registered_class_with_units(machine, example, example_results):
    cls = resolve(entry(machine).results)
    assert missing_units(cls) == []
    doc = get_machine(machine).document(example_results(example))
    assert isinstance(doc, cls)
    plain = json.loads(dumps(doc))
    assert plain["schema"] == SCHEMA and plain["machine"] == machine


def test_drive_document_shaft_table_by_definition(example_results):
    """T = P/ω on every shaft of the document, and its stage ratios multiply to n_m/n_w′."""
    doc = json.loads(dumps(get_machine("drive").document(example_results("furnace_drive"))))
    d = doc["drive"]
    for s in d["shafts"]:
        assert s["torque"] == pytest.approx(s["power"] / (s["speed_rpm"] * np.pi / 30), rel=1e-12)
    ratio = np.prod([st["ratio"] for st in d["stages"]])
    assert ratio == pytest.approx(d["motor"]["full_load_rpm"] / d["output_speed_rpm"], rel=1e-12)
    assert d["motor"]["power"] >= d["power_required"]


def test_slotter_flywheel_is_the_one_flywheel_result(example_results):
    """The flywheel on the pinion shaft (z1 = 18, z2 = 54 in designs/slotter.yaml) turns
    3× the crank and carries the crank's mean M_b divided by 3."""
    r = example_results("slotter")
    fl = json.loads(dumps(get_machine("slotter").document(r)))["flywheel"]
    mb = r["linkage_forces"].balancing_torque[:r["linkage"].grid_size]
    assert fl["speed_ratio"] == pytest.approx(54 / 18, rel=1e-12)
    # issue 21: M_d = the cutting work per cycle / 2π exactly (the grid mean is 3e-4 off)
    pp = r["params"]
    cut = pp.cutting_force * (1 - 2 * pp.idle_travel_ratio) * pp.stroke
    assert fl["mean_torque"] == pytest.approx(cut / (2 * np.pi), rel=1e-9)
    assert fl["mean_torque"] == pytest.approx(float(np.mean(mb)), rel=1e-3)
    assert fl["shaft_torque"] == pytest.approx(cut / (2 * np.pi) * 18 / 54, rel=1e-9)
    assert "ratio_to_crank" not in fl and "driving_torque" not in fl
