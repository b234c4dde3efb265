"""The flywheel's hub has its key (note 49: the drive design treated the flywheel as a
weight only, yet its hub carries the fluctuating torque J_F·ε between the flywheel and the
shaft). The key is checked as every other hub's (濮良贵《机械设计》§6-1: σ_p = 4T/(d h l) ≤
[σ_p], two keys at 180° counted as 1.5) with the shaft's design torque, which bounds the
torque through the hub, and the cast-iron hub's allowable stress (table 6-2, light shock:
50-60 MPa, the lower value)."""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import _markdown

FLYWHEEL_MACHINES = ["shaper", "slotter", "die_cutter"]


def _flywheel_shaft(r):
    shafts = [sh for sh in r["drive"].shaft_designs if "flywheel" in sh.elements]
    assert len(shafts) == 1
    return shafts[0]


@pytest.mark.parametrize("name", FLYWHEEL_MACHINES)
def test_the_flywheel_has_a_key_checked_by_the_closed_form(example_results, name):
    r = example_results(name)
    sh = _flywheel_shaft(r)
    keys = [k for k in sh.keys if k.part == "flywheel"]
    assert len(keys) == 1
    k = keys[0]
    c = k.check
    assert c.passed
    # the closed form with the key's own numbers: l = L − b (form A)
    lw = k.L - k.b
    share = 1.5 if k.count == 2 else 1.0
    assert c.value == pytest.approx(4 * k.torque / (share * k.d * k.h * lw), rel=1e-12)
    assert c.allowable == pytest.approx(50e6)            # cast-iron hub, light shock
    # the shaft's design torque (the largest any hub on it carries), on the seat's diameter
    assert k.torque == pytest.approx(max(kk.torque for kk in sh.keys), rel=1e-12)
    assert k.d == pytest.approx(sh.d_seat, rel=1e-12)
    # b × h by the diameter (GB/T 1096): the same as any other key on a seat of that size
    same = [kk for kk in sh.keys if abs(kk.d - k.d) < 1e-12 and kk is not k]
    assert all((kk.b, kk.h) == (k.b, k.h) for kk in same)


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", FLYWHEEL_MACHINES)
def test_the_report_lists_the_flywheels_key(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    word = "飞轮" if lang == "zh" else "the flywheel"
    assert re.search(rf"^\| (?:Key|平键) [^|]*[（(]{word}[）)] \|", md, re.M), word
    assert re.search(rf"^(?:On the shaft|轴上零件)[:：][^\n]*{word}", md, re.M)
