"""The summary counts every check the report states (review36 A): press's "本设计共进行 11 项
校核" counted the linkage and cam checks, while the gear chapter states three more (no
undercut, tip thickness, contact ratio ε ≥ 1.2) and its verdict table had no gear row.

Reference: the gear chapter's own verdict sentence names the three checks; the summary's
total is the sum of its verdict table's counts."""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import _markdown


@pytest.mark.parametrize("lang, total_re, row", [
    ("zh", r"本设计共进行 (\d+) 项校核", "| 齿轮传动 | 3 | 合格 |"),
    ("en", r"verified by (\d+) checks", "| gear pair | 3 | PASS |"),
])
def test_the_gear_checks_are_counted_in_the_summary(example_results, lang, total_re, row):
    md, _ = _markdown(example_results, "press", lang)
    # the gear chapter states its three checks
    assert ("不根切" in md and "齿顶厚足够" in md and "ε ≥ 1.2" in md.replace("$\\varepsilon$", "ε")) if lang == "zh" \
        else ("undercut" in md and "tips are thick enough" in md)
    assert row in md, row
    table = md[md.index(row[:8]) - 400:md.index(row) + 200]
    counts = [int(c) for c in re.findall(r"^\| [^|\n]+ \| (\d+) \| [^|\n]+ \|$", md, re.M)]
    total = int(re.search(total_re, md)[1])
    assert total == sum(counts), (total, counts, table)
