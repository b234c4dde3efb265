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
