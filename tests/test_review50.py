"""Page review 48, C findings on sentences and notes that named what the design does not
have: a drive without a flywheel (furnace_drive, furnace_pusher) was told that "the static
strength [takes] the peak" although it has no bearing static check; a transmission sheet
without a belt said "circles are pitch circles (pulleys: datum circles)"."""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import _markdown

DRIVES = ["furnace_drive", "furnace_pusher", "shaper", "die_cutter"]


@pytest.mark.parametrize("name", DRIVES)
def test_the_bearing_sentence_names_the_static_check_only_where_it_is_made(example_results, name):
    r = example_results(name)
    md, _ = _markdown(example_results, name, "en")
    sentences = re.findall(r"^Bearings \S+ \(.*$", md, re.M)
    shafts = [sh for sh in r["drive"].shaft_designs if sh.bearing is not None]
    assert len(sentences) == len(shafts) > 0
    for sh, s in zip(shafts, sentences):
        static = any(c.key == "bearing_static" for c in sh.checks)
        assert ("the static strength the peak" in s) == static, (sh.index, s[-80:])


def test_some_drive_has_no_static_check_and_some_has(example_results):
    # the cases: the furnace drive (no flywheel) none; the die-cutter's shafts after the flywheel
    def statics(name):
        return [any(c.key == "bearing_static" for c in sh.checks)
                for sh in example_results(name)["drive"].shaft_designs]
    assert not any(statics("furnace_drive"))
    assert any(statics("die_cutter"))


@pytest.mark.parametrize("name", ["furnace_drive", "shaper"])
def test_the_schematic_names_datum_circles_only_with_a_belt(example_results, name):
    from mechdesign.render.sheet import Text, TitleInfo, plain
    from mechdesign.render.sheets import _builders

    r = example_results(name)
    belt = any(st.type == "belt" for st in r["drive"].stages)
    assert belt == (name == "shaper")
    for lang, datum in (("en", "datum circles"), ("zh", "基准圆")):
        s = dict(_builders(r, None))["transmission"](TitleInfo("T", "test", number="T-01"), lang)
        texts = " ".join(plain(e.text) for e in s.entities if isinstance(e, Text))
        assert ("pitch circles" in texts or "节圆" in texts)
        assert (datum in texts) == belt, texts[:300]


@pytest.mark.parametrize("name", ["furnace_drive", "shaper"])
def test_the_ratio_rounding_names_standard_pulleys_only_with_a_belt(example_results, name):
    belt = any(st.type == "belt" for st in example_results(name)["drive"].stages)
    for lang, pulleys, teeth in (("en", "standard pulleys", "rounded to whole teeth"),
                                 ("zh", "标准带轮直径", "再圆整为整数齿数")):
        md, _ = _markdown(example_results, name, lang)
        assert teeth in md
        assert (pulleys in md) == belt, name
