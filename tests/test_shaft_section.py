"""Each shaft's σ_ca line is preceded by its section (review37 Top 10).

The shaper's shaft Ⅰ said "largest equivalent moment M = 93.31 N·m at x = 106 mm" and then
checked σ_ca with M = 0 and d = 20 mm — the overhung end, not said. The line now follows
"critical section: x = … mm (overhung end / journal / hub seat), d = … mm", taken from the
shaft design's own check (the section of the largest σ_ca, each section with its
diameter), and says why where it is not the section of the largest equivalent moment.
"""
from __future__ import annotations

import math
import re

import pytest

from tests.test_report_prose import _markdown

_SENTENCE = {"zh": re.compile(r"危险截面（[^）]*）：\$x\$ = (−?\d+) mm（([^）]+)），\$d\$ = (\d+) mm。([^\n]*)\n\n\$\$ \\sigma_\{ca\}"),
             "en": re.compile(r"Critical section \([^)]*\): \$x\$ = (−?\d+) mm \(([^)]+)\), \$d\$ = (\d+) mm\.([^\n]*)\n\n\$\$ \\sigma_\{ca\}")}


def _shafts(results):
    return [sh for v in results.values() for sh in getattr(v, "shaft_designs", ())]


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", ["shaper", "furnace_drive", "die_cutter"])
def test_every_sigma_ca_line_names_the_section_the_design_checked(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    shafts = _shafts(example_results(name))
    found = _SENTENCE[lang].findall(md)
    assert len(found) == len(shafts) == len(re.findall(r"^\$\$ \\sigma_\{ca\} = \\frac", md, re.M)), \
        (len(found), len(shafts))
    for (x, where, d, why), sh in zip(found, shafts):
        c = next(c for c in sh.checks if c.key == "shaft_bending")
        # the shaft design's own section: its x and d, and d is the diameter of the section
        # there by the layout (journal at a bearing, end outside, seat between)
        assert float(x.replace("−", "-")) == round(c.inputs["x"] * 1e3)
        assert float(d) == round(c.inputs["d"] * 1e3) == round(sh.diameter_at(c.inputs["x"]) * 1e3)
        # the line's numbers are the section's: σ_ca = √(M² + (αT)²)/(0.1 d³) there
        assert math.isclose(c.value, math.hypot(c.inputs["M"], 0.6 * c.inputs["T"]) / (0.1 * c.inputs["d"] ** 3))
        # a reason is given exactly where the section is not the one of the largest M_ca
        assert bool(why.strip()) == (abs(c.inputs["x"] - sh.result.critical.x) > 1e-9
                                     and c.inputs["d"] < sh.diameter_at(sh.result.critical.x))


def test_the_shaper_shaft_one_by_hand(example_results):
    """Shaft Ⅰ of the shaper (table: end 20, journal 25, seat 30 mm; T = 76.54 N·m; M = 93.31
    N·m at x = 106 mm, 60.33 at bearing B, 22.46 at bearing A, 0 at the overhung end):
    σ_ca = 0.6 × 76540/(0.1 × 20³) = 57.4 MPa at the end against √(93310² + 45924²)/(0.1 × 30³)
    = 38.5, √(60330² + 45924²)/(0.1 × 25³) = 48.5 and √(22460² + 45924²)/(0.1 × 25³) = 32.7:
    the overhung end governs, by its smaller diameter."""
    by_hand = {"end": 0.6 * 76540 / (0.1 * 20 ** 3), "mid": math.hypot(93310, 45924) / (0.1 * 30 ** 3),
               "B": math.hypot(60330, 45924) / (0.1 * 25 ** 3), "A": math.hypot(22460, 45924) / (0.1 * 25 ** 3)}
    assert max(by_hand, key=by_hand.get) == "end" and round(by_hand["end"], 1) == 57.4
    md, _ = _markdown(example_results, "shaper", "en")
    first = _SENTENCE["en"].search(md)
    assert first is not None
    x, where, d, why = first.groups()
    assert (where, d) == ("overhung end", "20")
    assert "(20 mm < 30 mm)" in why and "$x$ = 106 mm" in why
    md, _ = _markdown(example_results, "shaper", "zh")
    assert "（外伸端），$d$ = 20 mm。该截面弯矩（0 N·m）小于 $x$ = 106 mm 处" in md


_ORIGIN = {"zh": "$x$ 沿轴线自轴承 $A$ 量起", "en": "$x$ is measured along the shaft from bearing $A$"}


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", ["shaper", "furnace_drive", "die_cutter"])
def test_the_text_says_once_where_x_is_measured_from(example_results, name, lang):
    """"x = 106 mm" from where? The shaft design puts bearing A at x = 0 and B at the span:
    by statics (moments about bearing A, horizontal plane) Σ x·F_h + L·R_Bh = 0 and
    R_Ah + R_Bh + ΣF_h = 0 hold with the loads' x as stored, so x is measured from A. The
    text says so once, at the first shaft, before its first x."""
    md, _ = _markdown(example_results, name, lang)
    for sh in _shafts(example_results(name)):
        res, span = sh.result, sh.span
        fh = sum(ld.Fh for ld in sh.loads)
        scale = max(abs(ld.Fh) for ld in sh.loads) or 1.0
        assert abs(sum(ld.x * ld.Fh for ld in sh.loads) + span * res.RBh) <= 1e-9 * scale * span
        assert abs(res.RAh + res.RBh + fh) <= 1e-9 * scale
    assert md.count(_ORIGIN[lang]) == 1
    first_x = md.index("$x$ = ", md.index("最大当量弯矩" if lang == "zh" else "Largest equivalent moment"))
    assert md.index(_ORIGIN[lang]) > first_x - 40 and md.index(_ORIGIN[lang]) < first_x + 200
