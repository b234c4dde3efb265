"""Two cranks on one shaft are named by the bearing each sits beyond (page review 48: the
die-cutter's shaft Ⅲ listed "crank, crank" and two identical key rows "Key 28×16×140 ×2
(crank)": its two linkages side by side, one crank beyond each bearing,
stages/drive_strength.py)."""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import _markdown


def test_the_die_cutters_cranks_are_named_by_their_bearing(example_results):
    r = example_results("die_cutter")
    sh = next(sh for sh in r["drive"].shaft_designs if "crank" in sh.elements)
    assert sh.elements.count("crank") == 2                                # the case
    cranks = [(p, x) for p, e, x in zip(sh.element_parts, sh.elements, [ld.x for ld in sh.loads])
              if e == "crank"]
    # the one at x < 0 is beyond bearing A (x = 0), the other beyond bearing B (x = L)
    assert sorted(cranks, key=lambda c: c[1])[0][0] == "crank:A"
    assert sorted(cranks, key=lambda c: c[1])[1][0] == "crank:B"
    keys = [k.part for k in sh.keys]
    assert "crank:A" in keys and "crank:B" in keys


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_no_shaft_lists_a_part_twice(example_results, lang):
    md, _ = _markdown(example_results, "die_cutter", lang)
    lines = re.findall(r"^(?:On the shaft|轴上零件)[:：]([^。\n]*?)(?:\. |。)", md, re.M)
    assert len(lines) == len(example_results("die_cutter")["drive"].shaft_designs)
    for s in lines:
        names = re.split(r", |、", s.strip())
        assert len(names) == len(set(names)), s
    crank = "the crank beyond bearing $A$" if lang == "en" else "轴承 $A$ 外侧的曲柄"
    assert any(crank in s for s in lines), lines
    # the key rows of the check tables are distinct too
    rows = re.findall(r"^\| (?:Key|平键) [^|]*\|", md, re.M)
    assert len(rows) == len(set(rows)) > 0, rows
