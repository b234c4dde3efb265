"""Numbers as an engineer writes them, in every example report (issue 19 point 5).

render/fmt.py states the rule; this scans the Markdown of every example brief in both
languages (formulas and tables included, the program listing left out) for the faults a
page review found: five or more decimals with five or more significant digits (``K = 2.000000``, ``cos δ' = 0.683012``),
E-notation (``4.8e+04``), a negative zero, numbers of seven or more digits (a bearing life
of ``40 680 894 h``, a press load of ``1 000 000.0 N``: a power of ten or a larger unit), and
a length or angle in running text or a formula written to 0.0001 (``h = 40.0000 mm``: the
rule is 0.01 mm and 0.01°; the crank-rocker's worked example keeps the four decimals of the
paper it reproduces, and tables keep the decimals their column states).
"""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import EXAMPLES, _markdown

FAULTS = {
    # five or more decimals and five or more significant digits (0.06233 kW is 4 digits)
    "five or more decimals": re.compile(r"(?<![\d.])(?:-?[1-9]\d*\.\d{5,}|0\.0*[1-9]\d{4,})"),
    "E-notation": re.compile(r"\d[eE][-+]?\d"),
    "negative zero": re.compile(r"(?<![\w.])[-−]0(\.0+)?(?![.\d])"),
    "seven or more digits": re.compile(r"(?<![\d\u202f.])(\d{7,}|\d{1,3}(?:\u202f\d{3}){2,})(?![\d\u202f])"),
}
# a length or angle to 0.0001 outside a table (``40.0000 mm``, ``20.0000°``, ``\ \text{mm}``)
LENGTH_4 = re.compile(r"\d\.\d{4}(?:\\ |\s)*(?:\\text\{\s*)?(?:mm\b|°)")
KEEPS_SOURCE_DECIMALS = {"crank_rocker"}


def faults(md: str, name: str = "") -> list[tuple[str, str]]:
    """(kind, line) for every fault in a report's Markdown (code blocks left out)."""
    md = re.sub(r"^```.*?^```", "", md, flags=re.S | re.M)
    out = []
    for line in md.splitlines():
        for kind, pattern in FAULTS.items():
            if pattern.search(line):
                out.append((kind, line.strip()[:140]))
        if not line.startswith("|") and name not in KEEPS_SOURCE_DECIMALS and LENGTH_4.search(line):
            out.append(("length or angle to 0.0001", line.strip()[:140]))
    return out


def test_the_scan_finds_the_reviewed_faults():
    """The faults of the page review, as the old reports printed them, are found."""
    old = ["$$ K = \\frac{240.0000}{120.0000} = 2.000000 $$",
           "| R1 | D | 6 | 90.0 | 1\u202f000\u202f000.0 | 0.0 | 46.0 – 50.0 mm |",
           "| Bearing 30204 life | 40\u202f680\u202f894 | 48\u202f000 | h | PASS |",
           "$$ L_{10h} = 40680894\\ \\text{h} \\ge L_h' = 48000\\ \\text{h} $$",
           "Lowest position $y_{min}$ = 20.0000 mm, highest",
           "$$ h = \\sqrt{60.0^2} = 40.0000\\ \\text{mm} $$",
           "mean 4.8e+04 h", "M_b = -0.000"]
    assert len({line for _, line in faults("\n".join(old), "cam_7_1")}) == len(old)
    ok = ["| 1 | 0.00 | 0.0000 | 5.7162 |", "$$ L_{10h} = 4.068\\times10^{7}\\ \\text{h} $$",
          "life 4.068 × 10⁷ h", "12\u202f698.4 N·m", "P = 0.06233 kW", "```\nx = 1e-12\n```", "h = 40.00 mm"]
    assert not faults("\n".join(ok), "cam_7_1")


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_numbers_as_an_engineer_writes_them(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    bad = faults(md, name)
    assert not bad, "\n".join(map(str, bad[:12]))
