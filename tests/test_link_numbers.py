"""Issue 19: the crank-rocker's links carry one set of numbers in the report's text, its
figures and the sheets — the textbook's (孙桓《机械原理》, a four-bar ABCD): crank AB 1,
coupler BC 2, rocker CD 3, frame AD 4, the numbers of the synthesis's lengths l1 … l4.

The base commit numbered them three ways: the synthesis l1 … l4 (crank l1), the analysis
chapter by the linkage engine's frame 1, crank 2, coupler 3, rocker 4 ("曲柄 2", "杆组 3–4",
the rocker's ω4) and the kinematic sheet 1–3 (crank 1). These read the Markdown of both
languages and the labels the two sheets draw.
"""
from __future__ import annotations

import math
import re

import pytest

from mechdesign.render.sheet import Line, Text, TitleInfo, plain
from tests.test_report_prose import _markdown

TEXTBOOK = {"1": "AB", "2": "BC", "3": "CD", "4": "AD"}


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_report_numbers_the_links_as_the_textbook(example_results, lang):
    md, brief = _markdown(example_results, "crank_rocker", lang)
    # the synthesis: l_k is link k's length ("crank $l_1 = AB$ …")
    assert dict(re.findall(r"\$l_(\d) = ([A-D]{2})\$", md)) == TEXTBOOK
    # the analysis: links 1–3 move, and link 1 is the crank — its ω is the brief's speed
    assert set(re.findall(r"\\(?:omega|alpha)_\{?(\d)\}?", md)) == {"1", "2", "3"}
    crank = [float(w) for w in re.findall(r"\$\\omega_\{1\}\$ = ([-0-9.]+) rad/s", md)]
    assert crank and all(w == pytest.approx(2 * math.pi * brief.crank_speed_rpm / 60, abs=0.005)
                         for w in crank)
    # the vector equations group by group: the crank 1, then the group of coupler 2, rocker 3
    crank_word, group_word = ("曲柄", "杆组") if lang == "zh" else ("crank", "group")
    captions = [line for line in md.splitlines() if line.startswith(": ")]
    assert any(f"{crank_word} 1" in c for c in captions) and any(f"{group_word} 2–3" in c for c in captions)
    assert not any(re.search(rf"{crank_word} [02-9]|{group_word} 3–4", c) for c in captions)


def _named_points(sheet) -> dict[str, complex]:
    return {plain(e.text): e.position for e in sheet.entities
            if isinstance(e, Text) and re.fullmatch(r"[A-D]", plain(e.text))}


def _distance(z: complex, line: Line) -> float:
    d = line.p1 - line.p0
    t = min(max(((z - line.p0) * d.conjugate()).real / abs(d) ** 2, 0.0), 1.0) if abs(d) else 0.0
    return abs(z - (line.p0 + t * d))


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_kinematic_sheet_numbers_the_links_as_the_textbook(example_results, lang):
    """Each link number drawn on the four-bar sits by the link the textbook gives it (the
    link's ends are the points named nearest to them); the frame's 4 by a fixed pivot."""
    from mechdesign.render import kinematic_sheet as ks

    r = example_results("crank_rocker")
    sheet = ks.crank_rocker_diagram(r["optimum"], None, TitleInfo("", ""), lang)
    named = _named_points(sheet)
    assert set(named) == set("ABCD")

    def name_of(z: complex) -> str:
        return min(named, key=lambda n: abs(named[n] - z))

    links = [e for e in sheet.entities if isinstance(e, Line) and e.layer == "OUTLINE"
             and abs(e.p1 - e.p0) > 10.0]
    numbers = {e.text: e.position for e in sheet.entities
               if isinstance(e, Text) and e.text in TEXTBOOK}
    assert set(numbers) == set(TEXTBOOK)
    for number, z in numbers.items():
        if number == "4":
            assert name_of(z) in "AD", name_of(z)
            continue
        line = min(links, key=lambda ln: _distance(z, ln))
        assert "".join(sorted(name_of(line.p0) + name_of(line.p1))) == TEXTBOOK[number], number


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_analysis_sheet_lists_the_links_as_the_textbook(example_results, lang):
    """The analysis sheet's list of links ("1 曲柄 AB  2 连杆 BC  3 摇杆 CD")."""
    from mechdesign.render.sheets import _builders

    r = example_results("crank_rocker")
    (build,) = [b for name, b in _builders(r, r["brief"]) if name == "analysis"]
    sheet = build(TitleInfo("", ""), lang)
    texts = [plain(e.text) for e in sheet.entities if isinstance(e, Text)]
    listed = [dict(re.findall(r"(?<![0-9])([1-4]) \S+ ([A-D]{2})", t)) for t in texts]
    (legend,) = [d for d in listed if len(d) >= 3]
    assert legend == {k: v for k, v in TEXTBOOK.items() if k != "4"}
