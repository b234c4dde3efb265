"""One value prints one way in the lines a reader sees together (review 38, finding 1).

A chain that needs more digits than the text gives a quantity (render/fmt.py: "a factor is
written with the digits that make it so") must not show a teacher the value change between
two adjacent lines: crank_rocker's "l₂ = … = 42.40 mm" above "42.395²", shaper_lengths'
J_F 204.1 above 4 × 204.13, die_cutter's F₀ 151.0 / 151 / 150.964 and d₁ 123.67 / 123.7,
linkage_sixbar's "M_b = −169 N·m" above "P_b = −168.6/0.1". Either the chain substitutes the
number as printed and its result follows from it, or the number is printed with the chain's
digits wherever it appears nearby.

The scan: a number written with three or more significant digits, and within
:data:`WINDOW` lines a number inside a formula with more decimals that rounds to it (42.40
and 42.395; 151 and 150.964): the same value printed two ways. Pairs that are two quantities
(a guide's chosen position beside the computed one it rounds) are listed in :data:`OPEN`
with the reason; the test fails when one of them is gone.
"""
from __future__ import annotations

import re
from decimal import ROUND_HALF_EVEN, ROUND_HALF_UP, Decimal

import pytest

from tests.test_report_prose import EXAMPLES, _markdown

WINDOW = 10
_NUM = re.compile(r"(?<![\d.^_{}\\])(\d+(?:\.\d+)?)(?!\d)")
_MATH = re.compile(r"\$\$.+?\$\$|\$[^$\n]+?\$")
_POWER = re.compile(r"\s*(?:\\times|×)\s*10")


def _significant(text: str) -> int:
    return len(text.replace(".", "").lstrip("0"))


def _decimals(text: str) -> int:
    return len(text.partition(".")[2])


#: the sentence after a formula that substitutes a factor with more digits than the text gives
#: it (render/linkage_report.carried_note): the two strings are then one value, said to be
CARRIED = ("carry more digits", "carries more digits", "比正文多取有效数字")


def _said_carried(lines: list[str], i: int) -> bool:
    """Line ``i`` (a formula) is followed by the carried-digits sentence: in the first line of
    text after it, past blank lines and the display formulas that follow it (the sentence
    heads the paragraph after a formula's run)."""
    for line in lines[i + 1:]:
        if not line.strip() or line.lstrip().startswith("$$"):
            continue
        return any(phrase in line for phrase in CARRIED)
    return False


def two_ways(md: str, window: int = WINDOW) -> list[tuple[str, str]]:
    """(shorter, longer) of each number printed with fewer digits within ``window`` lines of
    a formula's number with more decimals that rounds to it — unless the formula's text says
    that it carries more digits than the text (:data:`CARRIED`)."""
    tokens = []
    lines = md.split("\n")
    for i, line in enumerate(lines):
        if _said_carried(lines, i):
            continue
        spans = [m.span() for m in _MATH.finditer(line)]
        for m in _NUM.finditer(line):
            # a mantissa of a power of ten (2.288\times10^{8}) is compared with mantissas only
            mantissa = bool(_POWER.match(line, m.end()))
            tokens.append((i, m.group(1), any(a <= m.start() < b for a, b in spans), mantissa))
    out = set()
    for i, a, _in_math, a_mant in tokens:
        if _significant(a) < 3:
            continue
        q = Decimal(1).scaleb(-_decimals(a))
        for j, b, b_in_math, b_mant in tokens:
            if abs(i - j) > window or not b_in_math or _decimals(b) <= _decimals(a) or a_mant != b_mant:
                continue
            if Decimal(a) == Decimal(b):
                continue
            if a in {str(Decimal(b).quantize(q, ROUND_HALF_UP)), str(Decimal(b).quantize(q, ROUND_HALF_EVEN))}:
                out.add((a, b))
    return sorted(out)


#: (brief, shorter, longer) → why the two numbers are not one value printed two ways, or why
#: it cannot be mended yet
OPEN: dict[tuple[str, str, str], str] = {
    ("press", "140.0", "139.95"): "x_M = 139.95 mm computed, x₂ = 140.0 mm the guide's chosen position",
    ("press", "127.8", "127.83"): "F_I2 and F_I3: two inertia forces of about the same size",
    ("slotter", "41.8", "41.76"): "position 10's M_b: no text that its equation's printed forces "
                                  "give (−41.77) gives the printed P_b = −1069 (−41.76 does)",
    ("die_cutter", "124", "123.85"): "the face width b = 124 mm beside d₁ = 123.85 mm",
    ("die_cutter", "198", "197.76"): "the face width b = 198 mm beside d₁ = 197.76 mm",
    ("die_cutter", "338", "337.53"): "the centre distance a = 338 mm rounded from a₀ = 337.53 mm "
                                     "(session 49: β corrected to it)",
    ("die_cutter", "412", "412.25"): "the centre distance a = 412 mm rounded from a₀ = 412.25 mm",
    # the table of every position keeps its columns' decimals (render/fmt.py), the worked
    # position's formulas 4 significant digits
    ("shaper", "0.200", "0.2004"): "position table (3 decimals) beside the worked position 4",
    ("shaper_lengths", "0.124", "0.1241"): "position table (3 decimals) beside the worked position 4",
    ("shaper_lengths", "0.335", "0.3347"): "position table (3 decimals) beside the worked position 4",
    ("shaper_lengths", "0.671", "0.6708"): "position table (3 decimals) beside the worked position 4",
    ("shaper_lengths", "0.783", "0.7834"): "position table (3 decimals) beside the worked position 4",
}


def test_the_scan_finds_the_review_38_cases():
    """The old text of each case the review named is found; the mended text is not."""
    old = ["$$ l_2 = \\frac{58.72 + 26.07}{2} = 42.40\\ \\text{mm} $$\n\n"
           "$$ \\cos\\delta'' = \\frac{42.395^2 + 50.00^2}{2 \\times 42.395 \\times 50.00} = -0.1448 $$",
           "| $F_0$ | 151.0 | N |\n\n$$ F_p = 2 \\times 3 \\times 150.964 \\times \\sin 81.05^\\circ = 894.8 $$",
           "$$ M_b = -169\\ \\text{N·m} $$\n\n$$ P_b = \\frac{-168.6}{0.1} = -1686 $$",
           "$$ J_F = 204.1\\ \\text{kg·m}^2 $$\n\n$$ m = \\frac{4 \\times 204.13}{1.000^2} = 816.52 $$"]
    new = ["$$ l_2 = \\frac{58.716 + 26.075}{2} = 42.40\\ \\text{mm} $$\n\n"
           "$$ \\cos\\delta'' = \\frac{42.40^2 + 50.00^2}{2 \\times 42.40 \\times 50.00} = -0.1447 $$",
           "| $F_0$ | 151 | N |\n\n$$ F_p = 2 \\times 3 \\times 151 \\times \\sin 81.05^\\circ = 895 $$",
           "$$ M_b = -168.6\\ \\text{N·m} $$\n\n$$ P_b = \\frac{-168.6}{0.1} = -1686 $$",
           "$J_F$ = 204.1" + "\n" * (WINDOW + 1) + "$$ m = \\frac{4 \\times 204.13}{1.000^2} = 816.52 $$"]
    for text in old:
        assert len(two_ways(text)) == 1, (text, two_ways(text))
    for text in new:
        assert not two_ways(text), (text, two_ways(text))
    # a number outside the formulas with more digits is no chain's factor
    assert not two_ways("J_F = 204.13 and $J_F = 204.1$")


def test_a_factor_carried_with_more_digits_is_said_so():
    """The shaper's J_F = 900 × 278.04/(π² × 266.667² × (1/25)) = 8.914 beside the text's
    ΔW_max = 278.0 J and n = 266.67 rpm: the text keeps the rule's digits, the formula the
    digits its result needs (278.0 and 266.67 give 8.912), and the sentence under the formula
    says which is which; without the sentence the pair is two ways."""
    from mechdesign.i18n import tr
    from mechdesign.render.linkage_report import carried_note, flywheel_carried

    # 900 ΔW/(π² n² δ): 278.04 J at 800/3 rpm and δ = 1/25 is 8.914 kg·m²; 278.0 and 266.67 give 8.912
    assert round(900 * 278.0 / (3.141592653589793 ** 2 * 266.67 ** 2 / 25), 3) == 8.912
    carried = flywheel_carried(278.04, 800 / 3, 1 / 25, "8.914", "266.67", "278.0")
    assert [used for _sym, _shown, used in carried] == ["266.667", "278.04"]
    text = ("$\\Delta W_{max}$ = 278.0 J, $n$ = 266.67 rpm\n\n"
            "$$ J_F = \\frac{900 \\times 278.04}{\\pi^2 \\times 266.667^2 \\times (1/25)} = 8.914 $$\n")
    assert two_ways(text) == [("266.67", "266.667"), ("278.0", "278.04")]
    for lang in ("en", "zh"):
        note = carried_note(tr(lang), carried)
        assert "$n$" in note and "$\\Delta W_{max}$" in note
        assert not two_ways(text + "\n" + note + " The energy change is plotted in Figure 14.\n"), lang
        # said after a following formula, in the paragraph after the run
        assert not two_ways(text + "\n$$ m = 1 $$\n\n" + note + "\n"), lang
        # a sentence before the formula says nothing of it
        assert two_ways(note + "\n" + text + "\nThe energy change is plotted.\n"), lang
    # nothing carried (the thin space of a grouped number is no digit): no sentence
    assert carried_note(tr("en"), [("J_F", "1\u202f276.5", "1276.5")]) is None


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_one_value_prints_one_way(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    found = two_ways(md)
    open_here = {(a, b) for (n, a, b) in OPEN if n == name}
    new = [f"{a} and {b}" for a, b in found if (a, b) not in open_here]
    assert not new, "one value printed two ways within %d lines: %s" % (WINDOW, "; ".join(new))
    gone = open_here - set(found)
    assert not gone, f"listed in OPEN but gone (take it out): {gone}"


def test_a_half_unit_is_rounded_away_from_zero():
    """review 38, linkage_sixbar position 10: "(2.50 × 57.0)" printed as the sum 142; a reader
    adds 142.5 and rounds it to 143. A chain's printed result may not be a half unit rounded
    towards zero (mechdesign.numbers.gives, which every factor search asks)."""
    from mechdesign.numbers import gives, half_sum_decimals

    assert not gives(2.50 * 57.0, "142") and gives(2.50 * 57.0, "143") and gives(2.50 * 57.0, "142.5")
    assert not gives(-2.50 * 57.0, "-142") and gives(-2.50 * 57.0, "-143")
    assert gives(142.49, "142") and not gives(142.51, "142")
    # (58.72 − 26.07)/2 = 16.325: the lengths to 0.001 mm; (60.10 − 27.60)/2 = 16.25: 0.01 mm
    assert half_sum_decimals((26.07465812273429, 58.71578363094562)) == 3
    assert half_sum_decimals((27.596283103337143, 60.10388152631645)) == 2


def test_lockbeam_gear_table_holds_gears_only(example_results):
    """review 38: the lock-beam's gear table put the pairs' a, ε and z_min under its diameter
    columns; they have a table of their own."""
    md, _ = _markdown(example_results, "lockbeam", "en")
    gears = md[:md.index("{#tbl:gears}")].rsplit("\n\n", 2)[-2]
    rows = [r for r in gears.splitlines() if r.startswith("|") and not r.startswith("|:") and not r.startswith("|-")]
    assert rows and not any("centre distance" in r.lower() or "contact ratio" in r.lower() for r in rows[1:])
    assert all(len(r.strip("|").split("|")) == len(rows[0].strip("|").split("|")) for r in rows)
    pairs = md[:md.index("{#tbl:gear-pairs}")].rsplit("\n\n", 2)[-2]
    assert "| 2 | $z_{1}$ – $z_{2}$ | 324.0 | 1.685 | 17 |" in pairs     # 6 × (18 + 90)/2 = 324 mm
