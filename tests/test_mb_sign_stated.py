"""Every table and curve of a report that shows the balancing torque M_b (or M_d, P_b) states
its sign convention in its head or caption (review36 Top 13, note37 "not done" 2).

The program gives M_b in the crank's sense of rotation everywhere (the forces stage, the
comparison of graphical and analytic results, the A1 sheet: tests/test_sheet_crank_signs.py);
the graphical section's sentence gives the polygon's counter-clockwise value beside it. A
teacher who reads "M_b = 228" in a table, "−228 N·m (counter-clockwise positive)" in the
sentence above it and "−232.3" on an old sheet needs the table itself to say which sign it
uses.

What counts as showing M_b: a table whose head row or first column has a cell that starts
with the symbol ($M_b$, "$M_b$ /N·m", "$M_b$（杆组法）/N·m"), and a figure whose caption
names it. Not counted: a formula that only contains the symbol ("$\\bar M_b\\,\\omega$",
"$\\Sigma P / \\max\\lvert M_b\\,\\omega\\rvert$": a power or a ratio), and the force-polygon
tables, whose $P_b$ row is in the second column: they list the drawn lengths, magnitudes, as
the sentence under each says ("力多边形中画出其大小 … N")."""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import _markdown

FORCE_BRIEFS = ["shaper", "shaper_lengths", "slotter", "press", "furnace_pusher", "die_cutter",
                "linkage_sixbar", "textbook_guide_bar"]
SIGN = {"zh": re.compile(r"曲柄转向"), "en": re.compile(r"crank's sense of rotation")}
# the symbol alone, or with a qualifier and a unit: "$M_b$", "$M_b$ /N·m", "$M_b$（杆组法）/N·m"
# ("$M_b$ 与虚功原理 … 之差（相对）" is a relative difference, not a value of M_b)
SYMBOL = re.compile(r"^\$(M_b|M_d|P_b)\$\s*(（[^）]*）|\([^)]*\))?\s*(/.*)?$")


def tables(md: str) -> list[tuple[list[list[str]], str]]:
    """Every pipe table of ``md``: (rows of cells, header row first; caption or "")."""
    out, lines, i = [], md.splitlines(), 0
    while i < len(lines):
        if not lines[i].startswith("|"):
            i += 1
            continue
        rows = []
        while i < len(lines) and lines[i].startswith("|"):
            if not re.fullmatch(r"\|[\s:|-]+\|", lines[i]):          # not the rule row
                rows.append([c.strip() for c in lines[i].strip().strip("|").split("|")])
            i += 1
        j = i
        while j < len(lines) and not lines[j].strip():
            j += 1
        caption = lines[j][2:] if j < len(lines) and lines[j].startswith(": ") else ""
        out.append((rows, caption))
    return out


def shows_torque(rows: list[list[str]]) -> bool:
    cells = rows[0] + [r[0] for r in rows[1:] if r]
    return any(SYMBOL.match(c) for c in cells)


def figure_captions(md: str) -> list[str]:
    return re.findall(r"^!\[(.*)\]\([^)]*\)", md, flags=re.M)


def unstated(md: str, lang: str) -> tuple[list[str], int]:
    """(the heads/captions of M_b tables and figures that do not state the sign, how many
    M_b tables and figures there are)."""
    bad, seen = [], 0
    for rows, caption in tables(md):
        if shows_torque(rows):
            seen += 1
            if not SIGN[lang].search(caption + " ".join(rows[0])):
                bad.append(caption or " | ".join(rows[0]))
    for cap in figure_captions(md):
        if re.search(r"\$(M_b|M_d|P_b)\$", cap):
            seen += 1
            if not SIGN[lang].search(cap):
                bad.append(cap)
    return bad, seen


def test_the_check_finds_a_table_and_a_figure_without_the_sign():
    md = ("| 位置 | $M_b$ /N·m |\n|:-:|--:|\n| 1 | 2.5 |\n\n: 各位置的平衡力矩\n\n"
          "| 量 | 单位 | 图解法 |\n|:-:|:-:|--:|\n| $M_b$ | N·m | 228 |\n\n: 比较（$M_b$ 以曲柄转向为正）\n\n"
          "| 平均功率 $\\bar M_b\\,\\omega$ /W | 1 |\n|:--|--:|\n\n: 校核\n\n"
          "![平衡力矩 $M_b$ 随曲柄转角的变化](x.png){#fig:x}\n")
    bad, seen = unstated(md, "zh")
    assert seen == 3
    assert bad == ["各位置的平衡力矩", "平衡力矩 $M_b$ 随曲柄转角的变化"]


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", FORCE_BRIEFS)
def test_every_balancing_torque_table_and_curve_states_its_sign(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    bad, seen = unstated(md, lang)
    # the force table or the loads table, the M_b curve and one comparison per drawn position
    assert seen >= 3, seen
    assert bad == []
