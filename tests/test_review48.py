"""Page review 47/48 (the reports' text):

- the summary names the graphical method and a linkage's flywheel where the report has them
  (the six-bar's said "kinematic and kinetostatic analysis" over both);
- the lockbeam's cam lift is stated with the digits the formula substitutes (it printed
  "h = 14.90 mm (the original report prints 14.904 mm)" above "14.904/35": a typed number);
- the flywheel rim's H/b and γ are stated with the numbers its width formula substitutes (the
  shaper typed "H/b = 1.5", γ = 70000 was never introduced);
- the furnace pusher's least working-stroke transmission angle is named before it is used
  (an English subscript "work,min" in the zh report).
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from mechdesign.cli import app

ROOT = Path(__file__).resolve().parents[1]
_MD: dict = {}


def _md(tmp_path_factory, name: str, lang: str) -> str:
    if (name, lang) not in _MD:
        out = tmp_path_factory.mktemp(f"{name}-{lang}")
        r = CliRunner().invoke(app, ["run", str(ROOT / "designs" / f"{name}.yaml"), "--lang", lang,
                                     "--format", "md", "--out", str(out)])
        assert r.exit_code == 0, r.output
        _MD[name, lang] = (out / "report.md").read_text(encoding="utf-8")
    return _MD[name, lang]


def _parts(md: str) -> str:
    m = re.search(r"(?:comprises|完成了以下内容)[:：] (.*?)[.。] ", md) or re.search(
        r"(?:comprises|完成了以下内容)[:：](.*?)。", md)
    assert m, "no parts sentence"
    return m[1]


@pytest.mark.parametrize("name,forces,flywheel", [("linkage_sixbar", True, True),
                                                  ("textbook_guide_bar", True, False),
                                                  ("crank_rocker", False, False),
                                                  ("shaper", True, True)])
def test_the_summary_names_the_graphical_method_and_the_flywheel(tmp_path_factory, name, forces, flywheel):
    md = _md(tmp_path_factory, name, "en")
    parts = _parts(md)
    # the report has the chapter and the flywheel's formula
    assert "Graphical method" in md or "graphical method" in md
    has_fly = "J_F = " in md
    assert has_fly is flywheel
    want = ("graphical method (velocity, acceleration and force polygons)" if forces
            else "graphical method (velocity and acceleration polygons)")
    assert want in parts, parts
    assert ("flywheel design" in parts) is flywheel, parts
    # after the analysis it belongs to
    assert parts.index("analysis") < parts.index("graphical method")


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_lockbeams_lift_is_the_number_its_formula_uses(tmp_path_factory, lang):
    md = _md(tmp_path_factory, "lockbeam", lang)
    said = re.search(r"\$h\$ = ([\d.]+) mm", md)
    used = re.search(r"\\Delta\\alpha = \\frac\{h\}\{L\} = \\frac\{([\d.]+)\}\{(\d+)\} = ([\d.]+)", md)
    assert said and used
    # the text by the rule (0.01 mm), the formula with the digits of its Δα, and said so
    assert f"{float(used[1]):.2f}" == said[1]
    if said[1] != used[1]:
        assert ("carries more digits" if lang == "en" else "多取有效数字") in md[used.end():used.end() + 200]
    assert float(used[1]) / float(used[2]) == pytest.approx(float(used[3]), abs=5e-5)
    assert "14.904 mm）" not in md and "prints 14.904" not in md


@pytest.mark.parametrize("name", ["shaper", "die_cutter", "shaper_lengths"])
@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_rims_proportion_and_specific_weight_are_stated_as_used(tmp_path_factory, name, lang):
    md = _md(tmp_path_factory, name, lang)
    width = re.search(r"b = \\sqrt\{\\frac\{4 g J_F\}\{\\pi D\^3 \(H_F/b\) \\gamma\}\} = \\sqrt\{\\frac\{[^}]*\}"
                      r"\{\\pi \\times [\d.]+\^3 \\times ([\d.]+) \\times (\d+)\}\}", md)
    assert width, "no rim width formula"
    hb, gamma = width[1], width[2]
    before = md[:width.start()]
    assert re.search(rf"\$H_F/b\$ = {re.escape(hb)}", before)
    stated = re.findall(r"\$\\gamma\$ = ([\d\u202f ]+) N/m³", before)
    assert stated and stated[-1].replace("\u202f", "").replace(" ", "") == gamma


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_working_strokes_least_transmission_angle_is_named(tmp_path_factory, lang):
    md = _md(tmp_path_factory, "furnace_pusher", lang)
    eq = md.index(r"\alpha_B = 90° - \gamma'_{min}")
    assert "work,min" not in md
    assert r"$\gamma'_{min}$" in md[eq - 200:eq]
