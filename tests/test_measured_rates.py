"""The graphical method's "angular velocities measured" line (review 34).

The shaper's report read "ω2 = −8.38; ω4 = −1.02; ω3 = −1.02; ω5 …; ω6 = 0 rad/s" and
"α6 = 0": the links in the order the groups were solved (the bar 4 before the block 3), and
the ram 6 — a link in translation, which has no angular velocity to measure — listed as a
result. A student lists the links by number and measures only rotating links: every line
lists its links in increasing order, and no link with both ω = 0 and α = 0 (a translating
link; a crank turning at constant speed keeps its α = 0, its ω is not zero).
"""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import EXAMPLES, _markdown

# the line names the polygons' figure: "Angular velocities measured on the polygons of @fig:x:"
LINE = {"en": re.compile(r"Angular velocities measured( on the polygons of @fig:[\w-]+)?:"),
        "zh": re.compile(r"(由 @fig:[\w-]+ )?量得的角速度")}
RATE = re.compile(r"\$\\(omega|alpha)_\{(\w+)\}\$ = (-?[\d.]+)")


def rate_faults(md: str, lang: str) -> list[str]:
    out = []
    for line in md.splitlines():
        if not LINE[lang].match(line):
            continue
        rates = RATE.findall(line)
        for kind in ("omega", "alpha"):
            links = [link for k, link, _v in rates if k == kind]
            if links != sorted(links, key=lambda s: (not s.isdigit(), int(s) if s.isdigit() else 0, s)):
                out.append(f"{kind} not by link number: {links}")
        values = {(k, link): float(v) for k, link, v in rates}
        still = [link for (k, link), v in values.items()
                 if k == "omega" and v == 0 and values.get(("alpha", link)) == 0]
        if still:
            out.append(f"links in translation listed with ω = α = 0: {still}")
    return out


def test_the_check_finds_the_reviewed_line():
    old = ("量得的角速度 $\\omega_{2}$ = -8.38 rad/s；$\\omega_{4}$ = -1.02 rad/s；$\\omega_{3}$ = -1.02 rad/s；"
           "$\\omega_{5}$ = 0.0712 rad/s；$\\omega_{6}$ = 0 rad/s；角加速度 $\\alpha_{2}$ = 0 rad/s²；"
           "$\\alpha_{4}$ = -0.809 rad/s²；$\\alpha_{3}$ = -0.809 rad/s²；$\\alpha_{5}$ = -4.27 rad/s²；"
           "$\\alpha_{6}$ = 0 rad/s²（逆时针为正）。")
    assert len(rate_faults(old, "zh")) == 3


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_measured_rates_by_link_number_without_translating_links(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    lines = [line for line in md.splitlines() if LINE[lang].match(line)]
    assert len(lines) == md.count("_kin.png"), "a polygon figure without its measured rates"
    faults = rate_faults(md, lang)
    assert not faults, faults
