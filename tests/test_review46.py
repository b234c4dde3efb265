"""Issue 19, session 46: every verdict the report prints is in its summary.

Page review 45 (review45b/e): the summary's "checks" table left out the graphical method's
comparison tables (about 25 PASS rows per polygon position) and the die-cutter's table of
transmission and pressure angles stated the limits [γ] = 40° and [α] = 30° without a verdict.
The graphical stage now records each comparison's verdict (``passed``), the linkage stage
each angle's limit and verdict (``quality[].limit``, ``passed``); the tables print them and
the summary counts them, a group per polygon position.
"""
from __future__ import annotations

import math
import re
from types import SimpleNamespace

import pytest

from test_handin import LANGS

# the examples with a graphical chapter (linkage machines with polygon positions)
GRAPHICAL = ("crank_rocker", "die_cutter", "furnace_pusher", "linkage_sixbar", "lockbeam", "press",
             "shaper", "shaper_lengths", "slotter", "textbook_guide_bar")
COMPARE_CAPTION = {"zh": re.compile(r"^: 位置 (\S+) 图解法与解析法结果比较"),
                   "en": re.compile(r"^: Graphical and analytic results at position (\S+) ")}
GROUP = {"zh": "图解法（位置 {}）", "en": "graphical method at position {}"}
PASS = {"zh": "合格", "en": "PASS"}


def _table_above(lines: list[str], at: int) -> list[list[str]]:
    """The body rows of the pipe table whose caption is line ``at``."""
    i = at - 1
    while i >= 0 and not lines[i].startswith("|"):
        i -= 1
    rows = []
    while i >= 0 and lines[i].startswith("|"):
        rows.append(lines[i])
        i -= 1
    rows.reverse()
    return [[c.strip() for c in r.strip().strip("|").split("|")] for r in rows[2:]]


def _summary_rows(md: str) -> dict[str, list[str]]:
    lines = md[md.index("{#summary}"):].split("\n")
    at = next(i for i, line in enumerate(lines) if "{#tbl:summary-checks}" in line)
    return {row[0]: row for row in _table_above(lines, at)}


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", GRAPHICAL)
def test_the_summary_counts_each_comparison_table(handin_reports, name, lang):
    """Each position's comparison table (read from the Markdown, not from the results) is a
    summary row with as many checks as the table has rows, and PASS where every row does."""
    md, _document = handin_reports(name, lang)
    lines = md.split("\n")
    tables = {m.group(1): _table_above(lines, i) for i, line in enumerate(lines)
              if (m := COMPARE_CAPTION[lang].match(line))}
    assert tables, "no comparison table"
    summary = _summary_rows(md)
    for label, rows in tables.items():
        row = summary.get(GROUP[lang].format(label))
        assert row is not None, (label, sorted(summary))
        assert int(row[1]) == len(rows) >= 6, (label, row, len(rows))
        all_pass = all(r[-1] == PASS[lang] for r in rows)
        assert (row[2] == PASS[lang]) == all_pass, (label, row)


def test_a_comparison_beyond_the_drawing_accuracy_is_named_in_the_summary():
    from mechdesign.render.summary import check_groups

    doc = {"graphical": {"step": 0.5, "positions": [{"label": "8'", "comparison": [
        {"quantity": "ω3", "unit": "rad/s", "passed": True},
        {"quantity": "R12", "unit": "N", "passed": False},
        {"quantity": "Mb", "unit": "N·m", "passed": True}]}]}}
    (en,) = check_groups(doc, {}, "en")
    assert en["group"] == "graphical method at position 8′" and en["count"] == "3"
    assert not en["ok"] and en["failed"] == ["$F_{R12}$"] and en["verdict"] == "FAIL: $F_{R12}$"
    (zh,) = check_groups(doc, {}, "zh")
    assert zh["group"] == "图解法（位置 8′）" and zh["verdict"] == "不合格：$F_{R12}$"


def test_an_angle_is_judged_against_its_limit_as_the_findings_judge_it():
    """γ_min over the whole cycle ≥ [γ], α_max over the working stroke ≤ [α]; without a limit
    nothing is judged. At the limit itself the angle passes (the findings' 1e-9 rad)."""
    from mechdesign.stages.linkage import quality_passed

    model = SimpleNamespace(transmission_angle_min=math.radians(40), pressure_angle_limit=math.radians(30))
    gamma = lambda deg: SimpleNamespace(kind="transmission", extreme=math.radians(deg),  # noqa: E731
                                        working_extreme=math.radians(60))
    alpha = lambda whole, work: SimpleNamespace(kind="pressure", extreme=math.radians(whole),  # noqa: E731
                                                working_extreme=math.radians(work))
    assert quality_passed(gamma(47.89), model) == (math.radians(40), True)
    assert quality_passed(gamma(40.0), model)[1] is True
    assert quality_passed(gamma(39.99), model)[1] is False
    # the return stroke's larger α does not count: the limit is the working stroke's
    assert quality_passed(alpha(58.41, 29.7), model)[1] is True
    assert quality_passed(alpha(20.0, 30.01), model)[1] is False
    free = SimpleNamespace(transmission_angle_min=None, pressure_angle_limit=None)
    assert quality_passed(gamma(10.0), free) == (None, None)


ANGLES_CAPTION = {"zh": ": 传动角与压力角", "en": ": Transmission and pressure angles"}


@pytest.mark.parametrize("lang", LANGS)
def test_the_die_cutters_angle_table_has_its_verdicts(handin_reports, lang):
    """die_cutter: [γ] = 40° and [α] = 30° (working stroke) are given; the table prints
    γ_min = 47.89° and α_max = 19.69° with a verdict each, and the summary counts the two."""
    md, document = handin_reports("die_cutter", lang)
    lines = md.split("\n")
    at = next(i for i, line in enumerate(lines) if line.strip() == ANGLES_CAPTION[lang])
    head = lines[at - 1 - len(_table_above(lines, at)) - 2]
    assert head.rstrip("| ").endswith("结论" if lang == "zh" else "Verdict"), head
    rows = _table_above(lines, at)
    assert [r[-1] for r in rows] == [PASS[lang]] * 2
    assert "47.89" in rows[0][3] and "19.69" in rows[1][4]
    quality = document["press"]["quality"] if "press" in document else document["linkage"]["quality"]
    assert [q["passed"] for q in quality] == [True, True]
    group = "传动角与压力角" if lang == "zh" else "Transmission and pressure angles"
    assert _summary_rows(md)[group][1:] == ["2", PASS[lang]]


def test_the_summary_counts_angles_only_where_the_report_shows_their_table():
    """The crank-rocker's report judges γ_min against [γ] in its verification table and has
    no angle table: its linkage's recorded verdict is not counted a second time."""
    from mechdesign.render.summary import check_groups

    doc = {"linkage": {"quality": [{"group": "RRR", "kind": "transmission", "point": "C",
                                    "limit": 0.698, "passed": True}]}}
    assert check_groups(doc, {}, "en") == []
    shown = check_groups(doc, {"lk": {"qual_rows": [["RRR"]]}}, "en")
    assert [(g["group"], g["count"]) for g in shown] == [("Transmission and pressure angles", "1")]


@pytest.mark.parametrize("name", ("shaper", "shaper_lengths"))
def test_the_stated_torque_range_is_the_whole_cycles_and_holds_the_tables(handin_reports, name):
    """shaper_lengths (review45): "M_b ranges from −134.1 to 1070 N·m" beside a table whose
    extremes are −104.30 and 1067.14: the sentence gives the curve's exact extremes, which lie
    between the tabulated positions; it now says so, and its range holds every table value."""
    md, _document = handin_reports(name, "en")
    lines = md.split("\n")
    sentence = next(line for line in lines if "balancing torque ranges from" in line)
    assert sentence.startswith("Over the whole cycle (between the tabulated positions too)")
    lo, hi = (float(x.replace("\u2212", "-").replace("\u202f", ""))
              for x in re.search(r"ranges from (\S+) to (\S+) N·m", sentence).groups())
    at = next(i for i, line in enumerate(lines) if "{#tbl:loads}" in line)
    table = [float(r[-1].replace("\u202f", "")) for r in _table_above(lines, at)]
    assert lo <= min(table) and max(table) <= hi, (lo, hi, min(table), max(table))


@pytest.mark.parametrize("lang", LANGS)
def test_the_die_cutters_task_route_says_the_design_has_no_coupling(handin_reports, lang):
    """Seed 001b (the thesis, l. 168): belt → two-stage helical reducer → coupling → distribution
    shaft. The design carries the cranks on the reducer's output shaft (no coupling stage): the
    task table quoted the route and said nothing of it (review45)."""
    md, document = handin_reports("die_cutter", lang)
    assert [s["kind"] for s in document["drive"]["stages"]] == ["belt", "helical", "helical"]
    row = next(line for line in md.split("\n") if line.startswith(("| 传动路线 |", "| drive |")))
    assert ("不用联轴器" if lang == "zh" else "no coupling") in row, row


def _cells(line: str) -> int:
    """The cells of a pipe-table line (a '|' inside $…$ math is no separator)."""
    outside = re.sub(r"\$[^$]*\$", "", line.strip())
    return outside.strip("|").count("|") + 1


EXAMPLES = sorted(p.stem for p in __import__("pathlib").Path(__file__).resolve().parents[1].joinpath(
    "designs").glob("*.yaml"))


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", EXAMPLES)
def test_every_table_has_as_many_header_cells_as_its_rows(handin_reports, name, lang):
    """A header of 13 cells over rows of 8 (the kinematics table took the angle table's new
    header, 680921c) shrinks the table to fit and no word-position check sees it."""
    md, _document = handin_reports(name, lang)
    lines = md.split("\n")
    i, bad = 0, []
    while i < len(lines):
        if lines[i].startswith("|") and i + 1 < len(lines) and re.match(r"^\|[:\- |]+\|$", lines[i + 1]):
            width = _cells(lines[i])
            j = i + 1
            while j < len(lines) and lines[j].startswith("|"):
                if _cells(lines[j]) != width:
                    bad.append((i + 1, lines[i][:60], lines[j][:60]))
                j += 1
            i = j
        else:
            i += 1
    assert not bad, bad[:5]


def test_a_centre_of_mass_on_the_analysis_sheet_is_named_and_tied_to_its_link(example_results, tmp_path):
    """shaper_lengths' A1 sheet (review45): the ram's centre of mass S6, x_S6 = 200 mm ahead of
    and y_S6 = 50 mm above F, stood as two small circles alone above the mechanism (one per
    bold position), read as stray pins. Each is now tied to the ram by a thin line from F and
    named at the first bold position."""
    from one_sheet import written_sheet
    from mechdesign.render.sheet_dxf import plain_text

    msp, _builder = written_sheet(example_results("shaper_lengths"), "shaper_lengths", "analysis",
                                  tmp_path, "zh")
    texts = {plain_text(e) for e in msp.query("TEXT MTEXT")}
    assert "S6" in texts or "S₆" in texts, sorted(t for t in texts if t.startswith("S"))
    ends = [complex(e.dxf.start.x, e.dxf.start.y) for e in msp.query("LINE")] + \
        [complex(e.dxf.end.x, e.dxf.end.y) for e in msp.query("LINE")]
    for e in msp.query("LWPOLYLINE"):
        pts = [complex(p[0], p[1]) for p in e.get_points()]
        ends += [pts[0], pts[-1]]
    small = [complex(c.dxf.center.x, c.dxf.center.y) for c in msp.query("CIRCLE")
             if abs(c.dxf.radius - 0.8) < 1e-6 and c.dxf.layer == "OUTLINE"]   # not the curves' marks
    assert len(small) >= 2
    for c in small:
        assert any(abs(c - z) < 1e-3 for z in ends), c
