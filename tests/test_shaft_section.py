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

_SENTENCE = {"zh": re.compile(r"危险截面（[^）]*）：\$x\$ = (−?\d+) mm（([^）]+)），\$d\$ = (\d+(?:\.\d+)?) mm。([^\n]*)\n\n\$\$ \\sigma_\{ca\}"),
             "en": re.compile(r"Critical section \([^)]*\): \$x\$ = (−?\d+) mm \(([^)]+)\), \$d\$ = (\d+(?:\.\d+)?) mm\.([^\n]*)\n\n\$\$ \\sigma_\{ca\}")}


def _shafts(results):
    return [sh for v in results.values() for sh in getattr(v, "shaft_designs", ())]


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", ["shaper", "furnace_drive", "die_cutter", "furnace_pusher"])
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
        assert float(d) == round(c.inputs["d"] * 1e3, 2) == round(sh.diameter_at(c.inputs["x"]) * 1e3, 2)
        # the line's numbers are the section's: σ_ca = √(M² + (αT)²)/(0.1 d³) there
        assert math.isclose(c.value, math.hypot(c.inputs["M"], 0.6 * c.inputs["T"]) / (0.1 * c.inputs["d"] ** 3))
        # a reason is given exactly where the section is not the one of the largest M_ca
        assert bool(why.strip()) == (abs(c.inputs["x"] - sh.result.critical.x) > 1e-9
                                     and c.inputs["d"] < sh.diameter_at(sh.result.critical.x))


def test_the_shaper_shaft_one_by_hand(example_results):
    """Shaft Ⅰ of the shaper: T = 76.54 N·m (αT = 45.92 N·m); the open spur pinion overhung
    80 mm beyond bearing B with F = √(708.70² + 257.95²) = 754.2 N on a 108 mm hub, bearings
    6206 (B = 16 mm). The moment grows linearly from the pinion to the bearing: at the hub's
    inner edge (80 − 54 = 26 mm from B) M = 754.2 × 0.054 = 40.73 N·m, at the bearing's outer
    face (8 mm from B) 754.2 × 0.072 = 54.30 N·m, at B 60.33 N·m, at the flywheel (x = 106 mm)
    93.31 N·m. On a 20 mm end the hub's edge gives √(40.73² + 45.92²)/(0.1 × 20³) = 76.7 MPa
    > 60 (session 41 checked the end at the pinion only, 0.6 × 76.54/(0.1 × 20³) = 57.4 MPa:
    PASS); the next standard end, 22 mm, gives 57.6 MPa, against the 26 mm seal at the face
    40.5, the 30 mm journal at B 28.1 and the 35 mm seat 24.3: the end at the hub's inner edge
    governs."""
    F = math.hypot(708.70, 257.95)
    aT = 0.6 * 76.54
    M_edge, M_face = F * 0.054, F * 0.072
    assert round(M_edge, 2) == 40.73 and round(M_face, 2) == 54.30
    sig = lambda M, d: math.hypot(M, aT) * 1e3 / (0.1 * d ** 3)          # MPa, d in mm
    assert round(sig(M_edge, 20), 1) == 76.7 and round(sig(M_edge, 22), 1) == 57.6
    others = {"face": sig(M_face, 26), "B": sig(60.33, 30), "mid": sig(93.31, 35)}
    assert max(others.values()) < sig(M_edge, 22) <= 60 < sig(M_edge, 20)
    md, _ = _markdown(example_results, "shaper", "en")
    first = _SENTENCE["en"].search(md)
    assert first is not None
    x, where, d, why = first.groups()
    assert (where, d) == ("overhung end, at the hub's inner edge", "22") and x == "238"
    assert "(22 mm < 35 mm)" in why and "$x$ = 106 mm" in why and "(40.73 N·m)" in why
    md, _ = _markdown(example_results, "shaper", "zh")
    assert "（外伸端，轮毂内侧端面处），$d$ = 22 mm。该截面弯矩（40.73 N·m）小于 $x$ = 106 mm 处" in md



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
