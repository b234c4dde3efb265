"""A helical stage shows the numbers its checks come from (review38 Top 7).

die_cutter's helical stages printed "ε_α = 1.666 ≥ 1.2" and "x_min = (17 − 26.27)/17" with
no formula: 1.666 is 濮良贵's estimate ε_α ≈ [1.88 − 3.2(1/z₁ + 1/z₂)] cos β (《机械设计》
第 9 版, 式 10-? of the helical-gear section), not the end-face formula the spur chapters use
(1.657), and 26.27 is the equivalent spur gear z_v = z/cos³β under the symbol z. The stage
table gave no helix angle at all.

References: the formulas above, evaluated here from the brief's teeth and helix angle."""
from __future__ import annotations

import math
import re

import pytest

from tests.test_report_prose import _markdown


def _stages(md: str) -> list[str]:
    return [s for s in re.split(r"\n## ", md) if "helical" in s.split("\n", 1)[0] or "斜齿" in s.split("\n", 1)[0]]


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_a_helical_stage_prints_its_contact_ratio_formula_and_helix_angle(example_results, lang):
    md, brief = _markdown(example_results, "die_cutter", lang)
    stages = _stages(md)
    assert stages, "no helical stage"
    for st in stages:
        z1, z2 = map(int, re.search(r"\| \$z_1 / z_2\$ \| (\d+) / (\d+) \|", st).groups())
        beta = float(re.search(r"\| \$\\beta\$ \| ([\d.]+) \| ° \|", st)[1])
        assert re.search(r"\| \$m_n\$ \| [\d.]+ \| mm \|", st)
        eps = (1.88 - 3.2 * (1 / z1 + 1 / z2)) * math.cos(math.radians(beta))
        line = re.search(r"\\varepsilon_\\alpha = \\left\(1\.88 - 3\.2.*? = ([\d.]+) \\ge", st)
        assert line, "the estimate's formula"
        assert float(line[1]) == pytest.approx(eps, abs=5e-4)
        for z in (z1, z2):
            zv = z / math.cos(math.radians(beta)) ** 3
            m = re.search(re.escape(f"z_v = \\frac{{z}}{{\\cos^3\\beta}} = \\frac{{{z}}}{{\\cos^3 ")
                          + r"[\d.]+°\}" + re.escape(f" = \\frac{{{z}}}{{") + r"[\d.]+\^3\} = ([\d.]+)", st)
            assert m, z
            assert float(m[1]) == pytest.approx(zv, rel=5e-4)
            assert f"(17 - {m[1]})" in st          # x_min takes z_v
