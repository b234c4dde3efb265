"""The title block names the course the brief belongs to (page review 41: the furnace drive's
transmission sheet said 机械原理课程设计 under a cover that says 机械设计课程设计说明书: a drive
designed alone is the machine-design course's task)."""
from __future__ import annotations

import pytest


def _texts(sheet):
    from mechdesign.render.sheet import Text

    return " ".join(t.text for t in sheet.entities if isinstance(t, Text))


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name, course", [("furnace_drive", "design"), ("crank_rocker", "theory")])
def test_the_title_block_names_the_course(example_results, name, course, lang):
    from mechdesign.render.sheets import _builders, course_of, title_info

    r = example_results(name)
    (key, build), *_ = _builders(r, r["brief"])
    assert course_of(r["brief"]) == course
    info = title_info(r["brief"].report, "t", "A-01", 1, 1, lang, course_of(r["brief"]))
    texts = _texts(build(info, lang))
    words = {"zh": {"design": "机械设计课程设计", "theory": "机械原理课程设计"},
             "en": {"design": "Machine Design: course design",
                    "theory": "Theory of Machines: course design"}}[lang]
    assert words[course] in texts
    assert words["theory" if course == "design" else "design"] not in texts
