"""The graphical-against-analytic table: the analytic value (the reference) is printed with
at least the graphical reading's decimals, one more where the reading has fewer than four
significant digits, so that the difference a teacher recomputes from the printed pair is close
to the values' (page review 47: the textbook guide bar's F_R23 read 123.5 against "123",
0.4 %, where the values differ by 0.24 %; ω4 1.99 against "2.00", −0.5 % for −0.21 %).

The rows are read from the Markdown and checked against the unrounded values in the results
document: the analytic cell is that value rounded, and the printed difference is within what
the graphical reading's rounding can make of the true one.
"""
from __future__ import annotations

import re

import pytest

from mechdesign.numbers import significant

ROW = re.compile(r"^\| (\$[^|]+\$) \| ([^|]+) \| ([^|]+) \| ([^|]+) \| ([^|]+) \| ([^|]+) \| [^|]+ \|$",
                 re.M)
CASES = [("textbook_guide_bar", "en"), ("shaper", "zh"), ("die_cutter", "en"),
         ("linkage_sixbar", "zh")]


def _value(text: str) -> float:
    return float(text.replace("\u202f", "").replace(" ", "").replace("−", "-"))


def _decimals(text: str) -> int:
    return len(text.partition(".")[2])


def _tables(md: str) -> list[list[tuple]]:
    """The comparison tables in order, each its rows (name, unit, graphical, analytic,
    difference, allowed)."""
    out, current = [], None
    for line in md.splitlines():
        m = ROW.match(line)
        if m and m[4].strip() not in ("Analytic", "解析法"):
            if current is None:
                current = []
                out.append(current)
            current.append(tuple(c.strip() for c in m.groups()))
        elif not line.startswith("|"):
            current = None
    return [t for t in out if t and t[0][4] and any(ch.isdigit() or ch == "—" for ch in t[0][4])]


def _positions(doc) -> list[dict]:
    """The graphical stage's positions wherever the machine keeps its linkage."""
    if isinstance(doc, dict):
        if "positions" in doc and "step" in doc:
            return doc["positions"]
        for v in doc.values():
            if found := _positions(v):
                return found
    return []


@pytest.mark.parametrize("name,lang", CASES)
def test_the_analytic_column_carries_the_readings_digits(handin_reports, name, lang):
    md, doc = handin_reports(name, lang)
    positions = _positions(doc)
    tables = [t for t in _tables(md) if len(t) >= 3]
    assert len(tables) == len(positions)
    checked = 0
    for table, pos in zip(tables, positions):
        assert len(table) == len(pos["comparison"])
        for (name_, unit, g, a, diff, _allowed), c in zip(table, pos["comparison"]):
            scale = 1e3 if unit == "kN" else 1.0
            exact_a = c["analytic"] / scale
            if a == "0":
                assert abs(c["analytic"]) < 0.5 * scale * 10.0 ** -3, (name_, a)
                continue
            # the analytic cell is the unrounded value, rounded
            assert abs(_value(a) - exact_a) <= 0.5 * 10.0 ** -_decimals(a) + 1e-12, (name_, a, exact_a)
            # at least the reading's decimals, one more beside a reading of < 4 digits
            want = min(4, _decimals(g) + (significant(g) < 4))
            assert _decimals(a) >= want, (name_, g, a)
            if diff == "—":
                continue
            # the printed difference is the printed pair's ...
            gv, av = _value(g), _value(a)
            assert abs(_value(diff) - 100 * (gv - av) / abs(av)) <= 0.05 + 1e-9, (name_, g, a, diff)
            # ... and within the readings' rounding (half a unit of the last digit of each,
            # and 0.05 % of the difference's own rounding) of the values' difference
            slack = 100 * (0.5 * 10.0 ** -_decimals(g) + 0.5 * 10.0 ** -_decimals(a)) / abs(av)
            true = 100 * (c["graphical"] - c["analytic"]) / abs(c["analytic"])
            if 10.0 ** -_decimals(g) * scale < abs(c["graphical"]) * 0.01:
                assert abs(_value(diff) - true) <= slack + 0.05 + 1e-9, (name_, g, a, diff, true)
            checked += 1
    assert checked >= 10


def test_the_guide_bars_reaction_against_its_analytic_value(handin_reports):
    """The review's row: F_R23 = 123.5 N read off the polygon (eq. (10): (15154 + 34.1)/123.0)
    against the analytic 123.18 N: 123.2, 0.2 % (it printed 123 and 0.4 %)."""
    md, doc = handin_reports("textbook_guide_bar", "en")
    row = re.search(r"^\| \$F_\{R23\}\$ \| N \| 123\.5 \| ([^|]+) \| ([^|]+) \|", md, re.M)
    assert row, "no F_R23 row"
    assert row[1].strip() == "123.2" and row[2].strip() == "0.2"
