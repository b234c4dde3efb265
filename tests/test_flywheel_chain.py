"""The flywheel line J_F = 900ΔW_max/(π²n²[δ]) gives its printed result from its printed
factors (review 36, Top 3).

A teacher re-evaluates the line with π: the shaper printed "900 × 278.0/(π² × 266.67² ×
0.0400) = 8.914" (the factors give 8.912), the slotter and the press printed [δ] = 1/30 as
0.0333 (2.572 for 2.569, 4.668 for 4.663), the six-bar 190.3 for ΔW_max = 190.32 (96.41 for
96.42). The rule: the printed factors reproduce the printed J_F to half a unit of its last
digit, [δ] as a fraction ``(1/30)`` or a decimal. This test re-evaluates every such line of
every example report in both languages (the general scanner of displayed chains is
tests/test_displayed_arithmetic.py)."""
from __future__ import annotations

import math
import re

import pytest

from tests.test_report_prose import EXAMPLES, _markdown

_N = r"\d+(?:\.\d+)?"
JF = re.compile(rf"J_F = \\frac\{{900\\,\\Delta W_\{{max\}}\}}\{{\\pi\^2 n\^2 \[\\delta\]\}} = "
                rf"\\frac\{{900 \\times ({_N})\}}\{{\\pi\^2 \\times ({_N})\^2 \\times "
                rf"(?:\((\d+)/(\d+)\)|({_N}))\}} = ({_N})\\ ")
# any substituted J_F line at all: the pattern above must read every one of them
ANY_JF = re.compile(r"J_F = \\frac\{900\\,\\Delta W_\{max\}\}\{\\pi\^2 n\^2 \[\\delta\]\} = \\frac")

# the briefs with a flywheel, each printing its line once
FLYWHEELS = {"die_cutter", "linkage_sixbar", "press", "shaper", "shaper_lengths", "slotter"}


def jf_faults(md: str) -> tuple[int, list[str]]:
    """(number of J_F lines read, the lines whose printed factors miss the printed J_F)."""
    out, lines = [], JF.findall(md)
    for dw, n, num, den, dec, printed in lines:
        delta = int(num) / int(den) if num else float(dec)
        x = 900 * float(dw) / (math.pi ** 2 * float(n) ** 2 * delta)
        half = 0.5 * 10.0 ** -len(printed.partition(".")[2])
        if abs(x - float(printed)) > half * (1 + 1e-9):
            out.append(f"900 × {dw}/(π² × {n}² × {num and f'{num}/{den}' or dec}) = {x:.6g}, printed {printed}")
    return len(lines), out


def test_the_scan_finds_the_reviewed_lines():
    """The four lines of review 36 (old reports) fail; the same lines with the digits the
    result was computed from pass."""
    head = r"$$ J_F = \frac{900\,\Delta W_{max}}{\pi^2 n^2 [\delta]} = "
    old = [r"\frac{900 \times 278.0}{\pi^2 \times 266.67^2 \times 0.0400} = 8.914\ \text{kg·m}^2 $$",
           r"\frac{900 \times 30.18}{\pi^2 \times 179.27^2 \times 0.0333} = 2.569\ \text{kg·m}^2 $$",
           r"\frac{900 \times 153.4}{\pi^2 \times 300.00^2 \times 0.0333} = 4.663\ \text{kg·m}^2 $$",
           r"\frac{900 \times 190.3}{\pi^2 \times 60.00^2 \times 0.0500} = 96.42\ \text{kg·m}^2 $$"]
    new = [r"\frac{900 \times 278.04}{\pi^2 \times 266.667^2 \times (1/25)} = 8.914\ \text{kg·m}^2 $$",
           r"\frac{900 \times 30.18}{\pi^2 \times 179.27^2 \times (1/30)} = 2.569\ \text{kg·m}^2 $$",
           r"\frac{900 \times 153.4}{\pi^2 \times 300.00^2 \times (1/30)} = 4.663\ \text{kg·m}^2 $$",
           r"\frac{900 \times 190.32}{\pi^2 \times 60.00^2 \times (1/20)} = 96.42\ \text{kg·m}^2 $$"]
    for line in old:
        assert jf_faults(head + line)[0] == 1 and len(jf_faults(head + line)[1]) == 1, line
    for line in new:
        assert jf_faults(head + line) == (1, []), line


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_every_flywheel_line_gives_its_printed_result(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    read, faults = jf_faults(md)
    assert read == len(ANY_JF.findall(md)), "a J_F line the scan cannot read"
    assert read == (1 if name in FLYWHEELS else 0)
    assert not faults, "\n".join(faults)


def test_the_line_prints_the_briefs_fraction():
    """[δ] = 1/30 is printed as the fraction the brief gives, never as 0.0333."""
    from mechdesign.render.linkage_report import flywheel_equation

    line = flywheel_equation(153.4, 300.0, 1 / 30, "4.663")
    assert r"\times (1/30)}" in line and "0.0333" not in line
    assert r"\times 0.15}" in flywheel_equation(1375.0, 64.0, 0.15, "204.1")


@pytest.mark.parametrize("dw, n, delta, D, J_digits, dw_digits", [
    # shaper: ΔW_max = 278.0373 J on the pinion shaft at 800/3 rpm, [δ] = 1/25, D = 500 mm:
    # 278.0 gives J_F = 8.912 for 8.9135, so the text must print 278.04 (5 digits)
    (278.0372559, 800 / 3, 0.04, 0.5, "8.914", "278.04"),
    # shaper_lengths: J_F = 204.129 on a 1000 mm rim, m = 4 J_F = 816.517 kg: 204.1 gives
    # 816.4, so the text must print J_F = 204.13 (and ΔW_max the digits that give it)
    (1375.351207, 64.0, 0.15, 1.0, "204.13", None),
])
def test_the_text_prints_the_digits_its_formulas_need(dw, n, delta, D, J_digits, dw_digits):
    """review 38 / one value one way: ΔW_max and J_F are printed with the digits the formula
    each is substituted in needs (J_F = 900ΔW/(π²n²[δ]), m = 4J_F/D²), the same string in the
    text, the summary and the sheet (mechdesign.render.flywheel_text). Closed forms here:
    each printed factor reproduces the printed result to half a unit of its last digit."""
    from mechdesign.render.flywheel_text import flywheel_texts

    J = 900 * dw / (math.pi ** 2 * n ** 2 * delta)
    m = 4 * J / D ** 2
    m_text = f"{m:.2f}"
    texts = flywheel_texts(dw, n, delta, J, D, m)
    assert texts.jf == J_digits
    # J_F's printed digits give the printed rim mass; one digit fewer would not
    half_m = 0.5 * 10 ** -2
    assert abs(4 * float(texts.jf) / D ** 2 - float(m_text)) <= half_m + 1e-12
    fewer = f"{J:.{len(J_digits.split('.')[1]) - 1}f}"
    if fewer != J_digits[:-1]:
        assert abs(4 * float(fewer) / D ** 2 - float(m_text)) > half_m
    # ΔW_max's printed digits give the printed J_F at n to 0.01 rpm or finer
    if dw_digits is not None:
        assert texts.dw == dw_digits
        assert abs(900 * float(f"{dw:.1f}") / (math.pi ** 2 * n ** 2 * delta) - float(J_digits)) > 0.0005
    half_j = 0.5 * 10 ** -len(texts.jf.split(".")[1])
    assert abs(900 * float(texts.dw) / (math.pi ** 2 * n ** 2 * delta) - float(texts.jf)) <= half_j + 1e-12
