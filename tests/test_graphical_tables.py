"""The graphical method's report text (review36, issue 19): what the polygon equations,
the force tables and the rates line say.

* A polygon equation sums the forces on one body: the action/reaction pair F_Rij, F_Rji
  of two bodies of the group never in one sum (their sum is zero; 孙桓《机械原理》, the
  guide-bar group RPR: link 4: G⃗4 + F⃗I4 + F⃗R54 + F⃗R34 + F⃗R74 = 0; slider 3: F⃗R23 = −F⃗R43
  = F⃗R34). The shaper printed "… + F⃗R34 + F⃗R74 + F⃗R43 + F⃗R23 = 0".
* One force, one number: an action/reaction pair of a position's force tables prints one
  magnitude with the same digits (shaper 表 12: F_R45 "1662", F_R54 "1662.5").
* The crank's ω and α are the brief's: not in the line of the measured ones.
"""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import _markdown

GUIDE_BAR = ["shaper", "shaper_lengths", "slotter", "textbook_guide_bar"]
FORCES = GUIDE_BAR + ["press", "furnace_pusher", "die_cutter", "linkage_sixbar"]
FORCE = re.compile(r"\\vec F_\{R(\w)(\w)\}(?!')")


def pair_sums(md: str) -> list[str]:
    """Displayed equations "… = 0" that add both F_Rij and F_Rji."""
    out = []
    for eq in re.findall(r"\$\$(.+?)\$\$|\$([^$]+)\$", md):
        eq = "".join(eq)
        for side in eq.split("="):
            found = set(FORCE.findall(side))
            if any((b, a) in found for a, b in found):
                out.append(eq.strip())
    return out


def test_the_check_finds_the_reviewed_equation():
    old = (r"$$ \vec G_{4} + \vec F_{I4} + \vec F_{R54} + \vec F_{R34} + \vec F_{R74} + "
           r"\vec F_{R43} + \vec F_{R23} = 0 $$")
    assert pair_sums(old)
    new = (r"$$ \vec G_{4} + \vec F_{I4} + \vec F_{R54} + \vec F_{R34} + \vec F_{R74} = 0 $$"
           "\n\n" r"$$ \vec F_{R23} = -\vec F_{R43} = \vec F_{R34} $$")
    assert not pair_sums(new)


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", FORCES)
def test_no_polygon_equation_adds_an_action_and_its_reaction(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    assert "\\vec F_{R" in md
    assert pair_sums(md) == []
    if name in GUIDE_BAR:
        # the slider's own balance, apart: F_R23 = −F_R43 = F_R34 (a slider without loads)
        slider = re.findall(r"\$ ?\\vec F_\{R(\w)(\w)\} = -\\vec F_\{R(\w)(\w)\} = "
                            r"\\vec F_\{R(\w)(\w)\} ?\$", md)
        assert slider, "the guide-bar group's slider equation is missing"
        for a, s, b, s2, s3, b2 in slider:
            # on slider s: the pin's force, minus the bar's force on it, = the slider's on the bar
            assert s == s2 == s3 and b == b2, (a, s, b, s2, s3, b2)


ROW = re.compile(r"^\|[^|\n]*\| \$F_\{R(\w)(\w)\}\$ \| [√?] \| [\d.]+ \| ([\d.\u202f ]+) \|$", re.M)


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", FORCES)
def test_a_reaction_pair_prints_one_magnitude(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    tables = re.split(r"\n: ", md)
    pairs = 0
    for table in tables:
        values = {(a, b): v.strip() for a, b, v in ROW.findall(table)}
        for (a, b), v in values.items():
            if (b, a) in values:
                pairs += 1
                assert v == values[(b, a)], (name, f"R{a}{b}", v, f"R{b}{a}", values[(b, a)])
    assert pairs, "no reaction pair in the force tables"


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", FORCES + ["lockbeam", "crank_rocker"])
def test_the_cranks_rates_are_given_not_measured(example_results, name, lang):
    """"由图 6 量得的角速度 ω₂ = −8.38 rad/s … α₂ = 0": the crank's ω is the brief's
    (2πn/60 = 8.378 rad/s for the shaper's 80 r/min) and its α zero: said to be given, with
    the brief's value, and left out of the measured ones."""
    md, _ = _markdown(example_results, name, lang)
    given = {"en": r"The crank's angular velocity \$\\omega_\{(\w+)\}\$ = (-?[\d.]+) rad/s and "
                   r"angular acceleration \$\\alpha_\{\1\}\$ = 0 rad/s² are given\.",
             "zh": r"曲柄的角速度 \$\\omega_\{(\w+)\}\$ = (-?[\d.]+) rad/s、角加速度 "
                   r"\$\\alpha_\{\1\}\$ = 0 rad/s² 为已知。"}[lang]
    from tests.test_measured_rates import LINE
    lines = md.splitlines()
    found = 0
    for n, line in enumerate(lines):
        if not LINE[lang].match(line):
            continue
        found += 1
        m = re.fullmatch(given, lines[n - 2])
        assert m, lines[n - 2]
        link, w = m[1], float(m[2])
        assert f"_{{{link}}}$" not in line, line
        assert w != 0 and len(m[2].replace("-", "").replace(".", "").lstrip("0")) == 4, m[2]
    assert found == md.count("_kin.png")


@pytest.mark.parametrize("name", FORCES)
def test_a_known_forces_length_times_mu_gives_its_value(example_results, name):
    """A known force (√) is drawn at its own value: its printed length is |F|/μF to 0.01 mm
    (a millimetre or more: length × μF and the value agree to their two roundings) or, shorter, × μF gives the value printed beside it to the value's
    last digit (shaper 表 12: F_R54 "33.0 mm, 1662.5 N" at μF = 50 gave 1650; die_cutter
    F_R23^t "1.00 mm, 49.9 N"). A measured one is a multiple
    of 0.5 mm and its value is length × μF as that product is (66.5 × 25 = 1662.5)."""
    from mechdesign.render.fmt import gives, number
    from mechdesign.render.graphical_report import _forces, known_zero

    doc = [v for v in example_results(name).values() if type(v).__name__ == "GraphicalDocument"][0]
    checked = 0
    for pos in doc.positions:
        for fc, fg in zip(_forces(pos, "en"), pos.forces):
            # a force known to be zero is no row (graph36): the rows are the other vectors
            sides = [v for v in fg.vectors if not known_zero(v)]
            assert len(sides) == len(fc["rows"])
            for (_sym, mark, length, value), v in zip(fc["rows"], sides):
                if "times" in value or "×" in value:
                    continue
                if length == "—":       # a known force too short to draw: a point
                    assert mark == "√" and abs(v.length) < 0.05, (name, _sym, v.length)
                    continue
                product = float(length) * fg.scale
                if mark == "√" and abs(float(length)) >= 1:
                    # a millimetre or more: drawn to 0.01 mm (a drawing is not more exact:
                    # "10.3466 mm" for 206.93 N, page review 41): the value's own length
                    # rounded to 0.01 mm
                    # rounded to 0.01 mm (the length) and to its last digit (the value)
                    last = 0.5 * 10.0 ** -len(value.replace("\u202f", "").partition(".")[2])
                    assert product == pytest.approx(number(value), abs=0.005 * fg.scale + last + 1e-9) \
                        and len(length.partition(".")[2]) <= 2, (name, _sym, length, value)
                elif mark == "√":
                    # (session 41: the number writer rounds a half away from zero, as the
                    # chain rule does: G5 = 245.25 N is written 245.3, no longer 245.2)
                    assert gives(product, value.replace("\u202f", "")), (name, _sym, length, value)
                else:
                    assert float(length) * 2 == round(float(length) * 2), (name, _sym, length)
                    assert product == pytest.approx(number(value), abs=1e-9), (name, _sym, length, value)
                checked += 1
    assert checked


@pytest.mark.parametrize("name", ["shaper", "press", "slotter"])
def test_a_weight_with_no_extra_decimals_changes_no_force_section(example_results, name):
    """graphical_report._force_sections keeps the first layout of a document whose weights
    need no extra decimals (shaper, press) instead of laying it out again with them: that
    holds because a weight seed of 0 is no seed — the chains start from the same digits
    (``least.get(name, 0)``) and the weight prints as without it. Here every position laid
    out with each of its weights seeded 0 equals the position laid out without seeds."""
    from mechdesign.render.graphical_report import _forces, _is_weight

    doc = [v for v in example_results(name).values() if type(v).__name__ == "GraphicalDocument"][0]
    for pos in doc.positions:
        weights = {ld.name: 0 for fg in pos.forces for lds in fg.loads.values() for ld in lds
                   if _is_weight(ld.name)}
        assert weights, pos.label
        assert _forces(pos, "en", weights) == _forces(pos, "en"), pos.label
