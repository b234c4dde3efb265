"""A symbol in running text is set as math (review 34).

The shaper's §4 read "F_Rij is the force of link i on link j" (en: i italic, j upright)
and "构件 i 对构件 j" (zh: both upright): the indices i, j are symbols, italic as in the
formula F_Rij beside them, so they are written $i$, $j$ in both languages. This scans the
prose (math, code and figure paths taken out) of every example report for a link index
written as a bare letter.
"""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import EXAMPLES, _markdown, _prose

BARE_INDEX = re.compile(r"(?:\blinks?|构件)\s*[ijk](?![\w$])")


def test_the_scan_finds_the_reviewed_words():
    assert BARE_INDEX.search(_prose("$F_{Rij}$ is the force of link i on link j;"))
    assert BARE_INDEX.search(_prose("$F_{Rij}$ 表示构件 i 对构件 j 的作用力"))
    assert not BARE_INDEX.search(_prose("$F_{Rij}$ is the force of link $i$ on link $j$;"))
    assert not BARE_INDEX.search(_prose("$F_{Rij}$ 表示构件 $i$ 对构件 $j$ 的作用力"))


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_link_indices_are_math(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    bad = [line[:160] for line in _prose(md).splitlines() if BARE_INDEX.search(line)]
    assert not bad, bad


def test_the_scan_finds_program_variables():
    assert PROGRAM_NAME.search("（原程序的变量 `omega3`、`omega4` 即此处的 $\\omega_4$、$\\omega_5$）")
    assert not PROGRAM_NAME.search("（原报告的构件编号与本设计不同，其 $\\omega_3$、$\\omega_4$ 即此处的 $\\omega_4$）")


# a program's variable written as code in the text (``omega3``): a report says the
# quantity by its symbol (ω3)
PROGRAM_NAME = re.compile(r"`[^`\n]*\b(?:omega|alpha|theta|phi)\d*\b[^`\n]*`")


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_original_programs_quantities_are_named_by_their_symbols(example_results, lang):
    """Review 34: lockbeam §… "（原程序的变量 omega3、omega4 即此…）" — the original VB
    program's variable names in the report's prose; the report writes ω3, ω4."""
    md, _ = _markdown(example_results, "lockbeam", lang)
    body = re.sub(r"^```.*?^```", " ", md, flags=re.S | re.M)     # the code listing may
    bad = [line[:160] for line in body.splitlines() if PROGRAM_NAME.search(line)]
    assert not bad, bad
    assert "abs()" not in _prose(body)
