"""Chapter 1 gives the task's data (review36 C): a teacher expects "已知：…" before the
analysis. linkage_sixbar and textbook_guide_bar (generic `machine: linkage` briefs) had a
one-line chapter 1; their link lengths, ω, masses and the textbook's φ = 45° first appeared
in chapter 2's tables.

The reference is the brief itself (designs/*.yaml read with yaml, not through the
program): every number it gives the linkage (lengths, masses, moments of inertia,
resistances, the asked position) is a value of chapter 1's data table."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
import yaml

from tests.test_report_prose import _markdown

DESIGNS = Path(__file__).resolve().parents[1] / "designs"
LINKAGE_BRIEFS = ["shaper", "shaper_lengths", "slotter", "press", "furnace_pusher", "die_cutter",
                  "crank_rocker", "lockbeam", "linkage_sixbar", "textbook_guide_bar"]


def chapter_one(md: str) -> str:
    """The text of the report's first chapter (its "# " heading to the next)."""
    parts = re.split(r"^# ", md, flags=re.M)
    return parts[1]


def table_values(text: str) -> list[str]:
    """The cells of every table row of ``text`` (pipe tables, header and rule rows too)."""
    return [c.strip() for row in re.findall(r"^\|(.+)\|$", text, re.M) for c in row.split("|")]


def numbers(cells: list[str]) -> set[float]:
    out = set()
    for c in cells:
        for m in re.findall(r"-?\d+(?:\.\d+)?", c.replace("\u2009", "").replace(" ", "")):
            out.add(round(float(m), 6))
    return out


def given_numbers(name: str) -> list[tuple[str, float]]:
    """The numbers the brief's `linkage` and `analysis.positions_deg` give, by field path."""
    b = yaml.safe_load((DESIGNS / f"{name}.yaml").read_text(encoding="utf-8"))
    lk, out = b["linkage"], []
    out.append(("crank.length_mm", lk["crank"]["length_mm"]))
    for i, g in enumerate(lk["groups"]):
        for key in ("lengths_mm", "length_mm", "distance_mm"):
            v = g.get(key)
            for j, x in enumerate(v if isinstance(v, list) else [] if v is None else [v]):
                out.append((f"groups[{i}].{key}[{j}]", x))
    for i, m in enumerate(lk.get("masses", [])):
        out += [(f"masses[{i}].{k}", m[k]) for k in ("mass_kg", "J_kgm2") if k in m]
    for i, r in enumerate(lk.get("resistances", [])):
        out += [(f"resistances[{i}].{k}", r[k]) for k in ("working_N", "return_N") if k in r]
    for k in ("pressure_angle_max_deg", "transmission_angle_min_deg"):
        if k in lk:
            out.append((k, lk[k]))
    out += [(f"analysis.positions_deg[{i}]", x)
            for i, x in enumerate(b.get("analysis", {}).get("positions_deg", []))]
    return out


def test_the_check_reads_a_data_table():
    md = "# 题目\n\n| 符号 | 名称 | 数值 | 单位 |\n|:--|:--|--:|:--|\n| $n$ | 转速 | 60.00 | r/min |\n\n# 机构\n"
    assert 60.0 in numbers(table_values(chapter_one(md)))
    assert table_values(chapter_one("# 题目\n\n**题目：** 某机构。\n\n# 机构\n\n| a | 1 |\n")) == []


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", LINKAGE_BRIEFS)
def test_chapter_one_has_a_data_table(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    one = chapter_one(md)
    assert table_values(one), f"{name} {lang}: chapter 1 has no data table"
    assert "{#tbl:" in one


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", ["linkage_sixbar", "textbook_guide_bar"])
def test_chapter_one_lists_every_given_number(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    have = numbers(table_values(chapter_one(md)))
    missing = [(k, v) for k, v in given_numbers(name) if round(float(v), 6) not in have]
    assert missing == []
    # the crank's speed, as n and as ω (the textbook gives ω1 = 10 rad/s as n = 300/π rpm)
    b = yaml.safe_load((DESIGNS / f"{name}.yaml").read_text(encoding="utf-8"))
    n = b["linkage"]["crank"]["speed_rpm"]
    omega = n * 3.141592653589793 / 30
    assert any(abs(x - omega) <= 0.005 * omega for x in have), omega


@pytest.mark.parametrize("written, shown", [
    ("100", "100"), ("-100", "-100"), ("0", "0"), ("0.5", "0.5"), ("0.11", "0.11"), ("95.5", "95.5"),
    ("0.004", "0.004"), ("0.001", "0.001"), ("1234.5678", "1234.5678"),
    # the README's rule: in text and tables an integer part of five or more digits is grouped
    ("12000", "12\u202f000"), ("123456.5", "123\u202f456.5"),
])
def test_a_given_number_is_written_as_the_brief_writes_it(written, shown):
    """The data table's number is the brief's text: no digit added or dropped, no trailing
    zero, and grouped as every table of the report groups (linkage/report._g writes it with
    fmt.exact, the writer of values as given)."""
    from mechdesign.machines.linkage.report import _g

    assert _g(float(written)) == shown
