"""A given quantity prints one way throughout a report (review37 Top 8).

The weights G_i are given (m g of the brief): the same value at every position of the
graphical kinetostatics. A teacher who reads "G₄ = 117.7 N" at position 5 and "G₄ = 117.72
N" at position 11 sees a constant change between two pages. Every text a report gives a
weight in its known-loads lines ("G₄（构件 4）= 117.72 N", "G_4 (link 4) = 117.72 N") and in
its force-polygon tables (the value column of the row "$G_4$ | √") is one text.
"""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import EXAMPLES, _markdown

_LINE = re.compile(r"\$G_\{(\d+)\}\$(?:（构件 \w+）| \(link \w+\)) ?= ([\d.,\u202f ]+?) N")
_ROW = re.compile(r"^\| (?:[^|\n]*\| )?\$G_\{(\d+)\}\$ \| √ \| [^|\n]* \| ([^|\n]+?) \|", re.M)


def weight_texts(md: str) -> dict[str, set[str]]:
    """Weight number → every text the report gives it (known-loads lines, polygon rows)."""
    out: dict[str, set[str]] = {}
    for m in list(_LINE.finditer(md)) + list(_ROW.finditer(md)):
        out.setdefault(m[1], set()).add(m[2].replace("\u202f", "").replace(",", "").replace(" ", ""))
    return out


def test_the_scan_sees_two_texts_of_one_weight():
    md = ("作用在杆组上的已知力：$G_{4}$（构件 4）= 117.7 N，$F_{I4}$（构件 4）= 3.00 N。\n"
          "| 3–4 | $G_{4}$ | √ | 5.886 | 117.72 |\n"
          "Known loads on the group: $G_{2}$ (link 2) = 300 N\n| $G_{2}$ | √ | 15.0 | 300 |\n")
    assert weight_texts(md) == {"4": {"117.7", "117.72"}, "2": {"300"}}


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_every_weight_prints_one_way_in_a_report(example_results, name, lang):
    md, brief = _markdown(example_results, name, lang)
    texts = weight_texts(md)
    # a weight in kN at a position whose forces are in kN (the die-cutter's: 117.72 N →
    # 0.1177 kN, by the rule's 4 significant digits) is that value rounded, not a second
    # value; the texts in N must be one (117.7 against 117.72 is not)
    def in_newtons(v: set[str]) -> set[str]:
        def kn_of(t: str, n: str) -> bool:
            half = 0.5 * 10.0 ** -len(t.partition(".")[2])
            return float(t) < float(n) / 100 and abs(float(t) * 1e3 - float(n)) <= half * 1e3 + 1e-9
        return {t for t in v if not any(kn_of(t, n) for n in v if n != t)}
    one = {k: in_newtons(v) for k, v in texts.items()}
    assert all(len(v) == 1 for v in one.values()), {k: v for k, v in texts.items() if len(one[k]) > 1}
    if name in ("slotter", "die_cutter", "textbook_guide_bar", "shaper"):
        assert texts, "no weight found: the scan is broken"


_B1B2 = re.compile(r"\\sin\\alpha' = ([\d.]+)\\ \\text\{mm\}, \\quad \\frac\{\\overline\{B_1B_2\}\}\{p_b\} = "
                   r"\\frac\{([\d.]+)\}\{([\d.]+)\} = ([\d.]+)")


@pytest.mark.parametrize("name", ["press", "shaper"])
def test_the_length_of_action_prints_one_way_in_its_line(example_results, name):
    """"B₁B₂ = … = 24.16 mm, B₁B₂/p_b = 24.155/14.761 = 1.636" (press eq. (76)) printed one
    length with two digit sets: the line prints the length the ratio is computed from."""
    md, _ = _markdown(example_results, name, "zh")
    found = _B1B2.findall(md)
    assert found, "no B1B2 line: the scan is broken"
    for length, top, bottom, ratio in found:
        assert length == top, (length, top)
        assert abs(float(top) / float(bottom) - float(ratio)) <= 0.5 * 10.0 ** -len(ratio.partition(".")[2])


def test_a_weight_prints_one_way_on_every_cell_of_the_sheet():
    """The shaper's A1 force cells wrote "G2 = 500 N, G4 = 157 N" at position 4 (largest force
    2530 N: no decimals) and "500.0 N, 157.0 N" at position 10 (largest force below 1000 N).
    A weight's text comes from its own value by the sheets' rule (4 significant digits,
    test_sheet_numbers), not from the cell's largest force."""
    from mechdesign.core.polygons import Polygon, Vector
    from mechdesign.render.analysis_sheet import _items

    def cell(largest: float, g4: float) -> list[str]:
        pg = Polygon("force", "4", {"a": 0j, "b": 500j, "c": 500j - g4, "d": largest + 0j},
                     (Vector("G2", "a", "b", 500j, "known"), Vector("G4", "b", "c", -g4 + 0j, "known"),
                      Vector("R32", "c", "d", largest + 0j, "absolute")))
        items = [re.sub("[\ue000-\uf8ff]", "", t) for t in _items(pg, [])]   # subscript marks
        return [t for t in items if t.startswith("G")]

    assert cell(2530.0, 157.0) == cell(800.0, 157.0) == ["G2 = 500 N", "G4 = 157 N"]
    assert cell(2530.0, 117.72) == cell(80.0, 117.72) == ["G2 = 500 N", "G4 = 117.7 N"]


@pytest.mark.parametrize("name", ["shaper", "slotter", "textbook_guide_bar"])
def test_the_sheet_prints_each_weight_as_the_report_to_the_sheets_digits(example_results, name):
    """The A1 force cells give each weight one text at every position, the report's value
    (slotter G4 117.72, the shaper's G6 667) to the sheets' 4 significant digits (117.7,
    667.1): the two agree to their last digits."""
    from mechdesign.render.analysis_sheet import _items
    from mechdesign.render.graphical_report import documents

    results = example_results(name)
    md, _ = _markdown(example_results, name, "zh")
    report = weight_texts(md)
    (prefix, doc), = documents(results)
    polygons = results[f"{prefix}_polygons"]
    seen: dict[str, set[str]] = {}
    for label in polygons.positions:
        for pg in polygons.at(label):
            for t in _items(pg, []) if pg.kind == "force" else ():
                m = re.fullmatch(r"G(\d+) = ([\d.]+) N", re.sub("[\ue000-\uf8ff]", "", t))
                if m:
                    (text,) = report[m[1]]
                    # both roundings of one value: within half a unit of each's last digit
                    unit = [10.0 ** -len(x.partition(".")[2]) for x in (m[2], text)]
                    assert abs(float(m[2]) - float(text)) <= 0.5 * sum(unit) + 1e-9, (label, t, text)
                    assert len(m[2].replace(".", "").lstrip("0")) <= 4, t
                    seen.setdefault(m[1], set()).add(m[2])
    assert seen and all(len(texts) == 1 for texts in seen.values()), seen
