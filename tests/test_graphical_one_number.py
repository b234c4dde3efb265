"""One measured value, one number (review36 Top 11, issue 19): a value read off a polygon
is printed with the same digits wherever the report lists it, the polygon's table and the
graphical-against-analytic comparison table alike. The shaper listed F_R45 = 1662.5 N in
its force-polygon table (66.5 mm × 25 N/mm) and 1662 N in the comparison.

The reference is the report itself: each position's velocity, acceleration and force
tables give a vector's value; the comparison table of the same position must print that
value (a reaction F_Rij may stand in the polygon table as its counterpart F_Rji: one
magnitude)."""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import _markdown

LINKAGES = ["shaper", "shaper_lengths", "slotter", "textbook_guide_bar", "press",
            "furnace_pusher", "die_cutter", "linkage_sixbar", "lockbeam", "crank_rocker"]

# | $v_{C}$ | ? | dir | seg | 51.0 | 0.510 |   (velocity / acceleration polygon)
KIN = re.compile(r"^\| (\$[^$|]+\$) \|[^|\n]*\|[^|\n]*\|[^|\n]*\| [\d.]+ \| ([^|\n]+) \|$", re.M)
# | 5–6 | $F_{R16}$ | ? | 9.5 | 475 |   (force polygon)
FORCE = re.compile(r"^\|[^|\n]*\| (\$[^$|]+\$) \| [√?] \| [\d.]+ \| ([^|\n]+) \|$", re.M)
# | $F_{R16}$ | N | 475 | 474 | 0.2 | 109 | PASS |   (comparison)
COMPARE = re.compile(r"^\| (\$[^$|]+\$) \| [^|\n]+ \| ([^|\n]+) \| [^|\n]+ \| [^|\n]+ \| "
                     r"[^|\n]+ \| [^|\n]+ \|$", re.M)
REACTION = re.compile(r"\$F_\{R(\w)(\w)\}\$")


def mismatches(section: str) -> tuple[list, int]:
    """(the comparison rows whose graphical value differs from the polygon tables', the
    number of rows compared) in one position's section of the report."""
    listed: dict[str, str] = {}
    for name, value in KIN.findall(section) + FORCE.findall(section):
        value = value.strip().lstrip("-−")
        if value and value[0].isdigit():
            listed.setdefault(name, value)
    bad, seen = [], 0
    for name, value in COMPARE.findall(section):
        value = value.strip().lstrip("-−")
        m = REACTION.fullmatch(name)
        other = f"$F_{{R{m[2]}{m[1]}}}$" if m else None
        there = listed.get(name) or listed.get(other)
        if there is None:
            continue
        seen += 1
        if there != value:
            bad.append((name, there, value))
    return bad, seen


def test_the_check_finds_the_reviewed_rows():
    old = ("| 5–6 | $F_{R45}$ | ? | 66.5 | 1662.5 |\n\n"
           "| $F_{R54}$ | N | 1662 | 1668 | -0.3 | 108 | 合格 |\n")
    assert mismatches(old) == ([("$F_{R54}$", "1662.5", "1662")], 1)
    new = old.replace("| 1662 |", "| 1662.5 |")
    assert mismatches(new) == ([], 1)


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", LINKAGES)
def test_a_measured_value_prints_alike_in_the_polygon_and_comparison_tables(
        example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    # one position per "## " section of the graphical chapter
    bad, seen = [], 0
    for section in re.split(r"\n## ", md):
        b, s = mismatches(section)
        bad += b
        seen += s
    assert seen, "no comparison row found in the polygon tables"
    assert bad == [], bad


# F_{R34} = -\frac{…}{123.0} = 123.5\ \mathrm{N}   (a force found by a moment equation)
SOLVED = re.compile(r"\\Rightarrow\\; (F_\{R\w\w\}) = -\\frac\{[^$]*?\}\{[\d.]+\} = (-?[\d.]+)\\ \\mathrm\{N\}")


def solved_mismatches(section: str) -> tuple[list, int]:
    """(the forces whose moment equation prints other digits than the force polygon's table
    of the same group, the number compared) in one position's section."""
    rows: dict[str, str] = {}
    for name, value in FORCE.findall(section):
        rows.setdefault(name.strip("$"), value.strip().lstrip("-−"))
    bad, seen = [], 0
    for name, value in SOLVED.findall(section):
        there = rows.get(name)
        if there is None or not there[0].isdigit():
            continue
        seen += 1
        if there.replace("\u202f", "") != value.lstrip("-"):
            bad.append((name, value, there))
    return bad, seen


def test_the_solved_check_finds_the_reviewed_force():
    old = (r"$$ \Sigma M_{C}(4) = F_{R34} \times 123.0 + (-19.62 \times 13.0) = 0 \;\Rightarrow\; "
           r"F_{R34} = -\frac{-15154 - 0.0341 / 0.001}{123.0} = 123\ \mathrm{N} $$" "\n\n"
           "|  | $F_{R34}$ | √ | 61.74 | 123.5 |\n")
    assert solved_mismatches(old) == ([("F_{R34}", "123", "123.5")], 1)
    assert solved_mismatches(old.replace("= 123\\ ", "= 123.5\\ ")) == ([], 1)


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", LINKAGES)
def test_a_force_found_by_a_moment_equation_prints_as_its_polygon_row(example_results, name, lang):
    """review38: textbook_guide_bar φ45 printed "F_R34 = … = 123 N" and, in the next lines,
    123.5 in its polygon row and in the crank's equation (slotter: 1137 and 1137.3)."""
    md, _ = _markdown(example_results, name, lang)
    bad = []
    for section in re.split(r"\n## ", md):
        bad += solved_mismatches(section)[0]
    assert bad == [], bad


# | $v_{B}$ | m/s | 1.17 | 1.17 | 0.0 | 0.0433 | 合格 |   (graphical, analytic, difference %)
ROW = re.compile(r"^\| \$[^$|]+\$ \| [^|\n]+ \| (-?[\d.\u202f ]+) \| (-?[\d.\u202f ]+) \| (-?[\d.]+) \| "
                 r"[^|\n]+ \| [^|\n]+ \|$", re.M)


def off_rows(md: str) -> tuple[list, int]:
    """(the comparison rows whose difference is not (graphical − analytic)/|analytic| of the
    printed values, to the printed 0.1 %, the number of rows read)."""
    bad, seen = [], 0
    for g, a, d in ROW.findall(md):
        g, a = (float(x.replace("\u202f", "").replace(" ", "")) for x in (g, a))
        if a == 0:
            continue
        seen += 1
        if abs(100 * (g - a) / abs(a) - float(d)) > 0.05 + 1e-9:
            bad.append((g, a, d))
    return bad, seen


def test_the_difference_check_finds_the_reviewed_row():
    assert off_rows("| $v_{B}$ | m/s | 1.17 | 1.17 | 0.4 | 0.0433 | 合格 |\n") == ([(1.17, 1.17, "0.4")], 1)
    assert off_rows("| $v_{B}$ | m/s | 1.17 | 1.17 | 0.0 | 0.0433 | 合格 |\n") == ([], 1)


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", LINKAGES)
def test_a_comparison_difference_follows_from_its_printed_values(example_results, name, lang):
    """review38: 92 of 726 comparison rows gave a difference a teacher cannot get from the
    row ("1.17 | 1.17 | 0.4 %", "2.60 | 2.55 | 1.7 %"): it was the unrounded values'."""
    md, _ = _markdown(example_results, name, lang)
    bad, seen = off_rows(md)
    assert seen
    assert bad == [], bad
