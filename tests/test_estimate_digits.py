"""A bearing life is an estimate: printed to 4 significant digits (note36, issue 19).

The life chain printed its result to the hour (L_10h = 671 547 h), and its factors then
needed 6–7 significant digits to give it ("60 × 50.23355", "13 043.98"). A life rests on a
catalogue rating and load factors good to a few per cent; the report now prints it to 4
significant digits, "≈ 671 500 h" (a power of ten from 10⁶ h on, as every number: ≈ 6.157 ×
10⁶ h), its check-table cell alike, and the factors with the digits that give those 4.

Reference: the chain is evaluated from its printed numbers (tests/test_every_chain.py's
evaluator) and rounded to 4 significant digits by Python's own formatting."""
from __future__ import annotations

import math
import re

import pytest

from tests.test_every_chain import evaluate
from tests.test_report_prose import _markdown

DRIVES = ["shaper", "die_cutter", "slotter", "furnace_drive", "furnace_pusher", "press", "lockbeam"]
# the formula's numbers, then (next display) the printed life
LIFE = re.compile(r"L_\{10h\} = \\frac\{10\^6\}\{60 n\} \(\\frac\{f_t C\}\{P\}\)\^\{\\varepsilon\} = "
                  r"(?P<chain>.+?)(?:\$\$\s*\$\$\s*L_\{10h\})?\s*(?P<rel>=|\\approx) (?P<value>[\d.]+(?:\\times10\^\{\d+\})?)"
                  r"\\ \\text\{h\}", re.S)


def significant(text: str) -> int:
    """Significant digits as printed; an integer's trailing zeros are not (199600: 4)."""
    mant = text.partition("\\times")[0]
    mant = mant.replace(".", "") if "." in mant else mant.rstrip("0")
    return len(mant.lstrip("0"))


def four(x: float) -> float:
    return float(f"{x:.4g}")


def value(text: str) -> float:
    mant, _, power = text.partition("\\times10^{")
    return float(mant) * 10.0 ** int(power.rstrip("}") or 0)


def test_the_pattern_reads_the_reviewed_chain():
    old = (r"$$ L_{10h} = \frac{10^6}{60 n} (\frac{f_t C}{P})^{\varepsilon} = \frac{10^6}{60 \times "
           r"50.23355} \times (\frac{1 \times 1.65\times10^{5}}{13043.98})^{3} $$" "\n\n"
           r"$$ L_{10h} = 671547\ \text{h} \ge L_h' = 48000\ \text{h} $$")
    m = LIFE.search(old)
    assert m and m["value"] == "671547" and significant(m["value"]) == 6
    assert significant("671500") == 4 and significant("950.4") == 4 and significant("6.157\\times10^{6}") == 4


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", DRIVES)
def test_a_life_is_printed_to_four_digits_and_its_chain_gives_them(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    lives = list(LIFE.finditer(md))
    if not lives:
        pytest.skip(f"{name}: no bearing life")
    for m in lives:
        printed = value(m["value"])
        assert significant(m["value"]) <= 4, m["value"]
        computed = evaluate(m["chain"].replace("$$", " "))
        assert four(computed) == pytest.approx(four(printed), rel=1e-12), (m["chain"], computed, printed)
        # an estimate, rounded off: the relation says so, below 10⁶ h and above alike
        # (review38: "≈ 199600 h" and "= 6.157×10⁶ h" in one report)
        assert m["rel"] == "\\approx", (m["rel"], m["value"])
        # the factors need no more than 5 significant digits for 4 of the result, unless
        # the result sits at a rounding edge where 5 digits of that factor give another 4th
        # digit (furnace_pusher's crank shaft: P = 1245.26 N, 1245.3 gives another life)
        for n in re.findall(r"\d+\.\d+|\d{5,}", m["chain"]):
            if len(n.replace(".", "").lstrip("0")) > 5:
                short = f"{float(n):.5g}"
                other = evaluate(m["chain"].replace("$$", " ").replace(n, short, 1))
                assert four(other) != four(printed), (n, m["chain"])
        # the check table's cell: the same 4 digits, grouped ("671 500")
        cell = f"{printed:,.{max(0, 3 - int(math.floor(math.log10(printed))))}f}".replace(",", "\u202f")
        if printed < 1e6:
            # four digits stand ungrouped in a table cell (3294; GB/T 8170 groups from five)
            assert f"| {cell} |" in md or f"| {cell.replace(chr(0x202f), ' ')} |" in md or (
                printed < 1e4 and f"| {cell.replace(chr(0x202f), '')} |" in md), cell
