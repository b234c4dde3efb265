"""A shaft's parts are named by their stage and role (page review 48: "On the shaft: closed
helical gear pair, closed helical gear pair" and two keys "(closed helical gear pair)": which
gear was which). Shaft j carries the driven part of drive stage j − 1 and the driving part of
stage j (the drive's order: motor shaft 0, then one shaft after each stage)."""
import pytest


@pytest.mark.parametrize("name", ["die_cutter", "shaper"])
def test_each_shaft_carries_the_driven_part_before_it_and_the_driving_part_after(example_results, name):
    d = example_results(name)["drive"]
    for sh in d.shaft_designs:
        j = sh.index
        roles = [p for p in sh.element_parts if p.startswith(("driving:", "driven:"))]
        assert f"driven:{j - 1}" in roles
        if j < len(d.stages):
            assert f"driving:{j}" in roles
        assert all(p in (f"driven:{j - 1}", f"driving:{j}") for p in roles)
        for k in sh.keys:
            assert k.part in sh.element_parts


def test_the_die_cutters_middle_shaft_names_its_gear_and_its_pinion(handin_reports):
    for lang, (gear, pinion, joint) in {
            "en": ("the gear of stage 2", "the pinion of stage 3", ", "),
            "zh": ("第 2 级大齿轮", "第 3 级小齿轮", "、")}.items():
        md, _ = handin_reports("die_cutter", lang)
        assert gear + joint + pinion in md
        assert md.count("closed helical gear pair, closed helical gear pair") == 0
        assert md.count("闭式斜齿圆柱齿轮传动、闭式斜齿圆柱齿轮传动") == 0
