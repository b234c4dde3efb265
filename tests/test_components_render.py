"""Report sections of the motion-scheme components (render.components_report and the
templates cycle_section, morphology_section, intermittent_section in zh and en).

The sections are rendered through a small wrapper template with the report's own Jinja
settings (render.report.render_markdown); the rows are compared with values worked out by
hand: times t = Δφ/360° × 60/n, slacks from the phase angles, 3⁵ = 243 schemes, the
incomplete gear of m = 4 mm, z1 = 36, z2 = 30, 100° (10 teeth, Δφ2 = 120°).
"""
from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from mechdesign.brief.components import (CycleSection, IncompleteGearSection, MorphologySection,
                                          cycle_to_si, incomplete_gear_to_si, morphology_to_si)
from mechdesign.core import cycle as cy
from mechdesign.core.intermittent import intermittent_curves
from mechdesign.render import components_report as cr
from mechdesign.render.fmt import number
from mechdesign.render.report import render_markdown, template_dir

SECTIONS = ("cycle", "morphology", "intermittent")


def cycle_brief():
    return CycleSection.model_validate({"shaft_speed_rpm": 10, "actuators": [
        {"key": "feed", "name_zh": "送料滑块", "name_en": "feed slider",
         "phases": [{"state": "rise", "span_deg": 90, "label_zh": "送进", "label_en": "feed"},
                    {"state": "return", "span_deg": 70}, {"state": "dwell_low", "span_deg": 200}]},
        {"key": "pin", "name_zh": "定位销", "name_en": "positioning pin",
         "phases": [{"state": "dwell_low", "span_deg": 170}, {"state": "rise", "span_deg": 60},
                    {"state": "dwell_high", "span_deg": 70}, {"state": "return", "span_deg": 60}]},
        {"key": "bender", "name_zh": "扳弯架", "name_en": "bending arm", "start_deg": 235,
         "phases": [{"state": "rise", "span_deg": 30}, {"state": "return", "span_deg": 30},
                    {"state": "dwell_low", "span_deg": 300}]}],
        "constraints": [
            {"kind": "before", "a": {"actuator": "feed", "state": "rise"},
             "b": {"actuator": "pin", "state": "rise"}, "margin_deg": 5,
             "text_zh": "送料到位后定位销才上升", "text_en": "the pin rises after the feed"},
            {"kind": "before", "a": {"actuator": "bender", "state": "return"},
             "b": {"actuator": "pin", "state": "return"}, "margin_deg": 10}]})


def morph(chosen=(2, 1, 1, 3, 2), counts=(3, 3, 3, 3, 3)):
    names = ["送料", "定位", "夹紧", "扳弯", "减速"]
    return morphology_to_si(MorphologySection.model_validate({"functions": [
        {"name_zh": n, "name_en": f"function {n}", "chosen": c,
         "options": [{"name_zh": f"{n}机构{j + 1}", "name_en": f"mechanism {j + 1}"} for j in range(k)]}
        for n, c, k in zip(names, chosen, counts)], "reasons_zh": "理由。", "reasons_en": "Reasons."}))


def gear(rpm=None):
    return incomplete_gear_to_si(IncompleteGearSection.model_validate(
        {"module_mm": 4, "driver_teeth_full": 36, "driven_teeth": 30, "motion_span_deg": 100,
         "motion_start_deg": 300, "sprocket_pitch_radius_mm": 80}), rpm)


def render(tmp_path: Path, ctx: dict, section: str, lang: str) -> str:
    tdir = tmp_path / "tpl"
    if not tdir.exists():
        shutil.copytree(template_dir(), tdir)
    name = f"wrap_{section}.md.j2"
    (tdir / name).write_text(f'# Chapter\n\n{{% include "{section}_section.md.j2" %}}\n',
                             encoding="utf-8")
    return render_markdown(name, ctx, tdir, lang)


@pytest.fixture
def figs(tmp_path):
    d = tmp_path / "figures"
    d.mkdir()
    return d


# --------------------------------------------------------------------------- cycle


def test_cycle_rows_and_checks(tmp_path, figs):
    c = cycle_to_si(cycle_brief())
    checks = cy.check_constraints(c)          # what the cycle stage stores
    paths = cr.make_cycle_figures(c, figs, "zh", checks)
    assert set(paths) == {"linear", "circular"}
    for p in paths.values():
        assert (tmp_path / p).stat().st_size > 5000
    md = render(tmp_path, {"cycle": cr.cycle_context(c, "zh", paths, checks)}, "cycle", "zh")
    # T = 60/10 = 6 s; pin rise 170–230: starts 170/360 × 6 = 2.833 s, lasts 1 s
    assert r"\frac{60}{10.00} = 6.000\ \text{s}" in md
    assert "| 定位销 | 近停歇 | 0.0 – 170.0 | 170.0 | 0.000 | 2.833 |" in md
    assert "|  | 推程 | 170.0 – 230.0 | 60.0 | 2.833 | 1.000 |" in md
    # a phase through 0°: 295 → 235 (300°, 5 s), starting at 295/360 × 6 = 4.917 s
    assert "|  | 近停歇 | 295.0 – 235.0 | 300.0 | 4.917 | 5.000 |" in md
    assert "| 送料滑块 | 送进 | 0.0 – 90.0 | 90.0 | 0.000 | 1.500 |" in md
    # slacks: 170 − 90 − 5 = 75° (1.25 s); 300 − 295 − 10 = −5° (−0.083 s)
    assert "| 1 | 送料到位后定位销才上升 | 75.00 | 1.250 | 合格 |" in md
    assert "| 2 | 扳弯架回程在定位销回程开始前至少 10.0° 结束 | -5.00 | -0.083 | **不合格** |" in md
    assert "> **警告：** 不满足协调要求：扳弯架回程" in md
    assert "## 运动循环图" in md and "### 动作协调校核" in md
    assert "{#tbl:cycle-table}" in md and "{#fig:cycle-linear" in md


def test_cycle_english_level_and_label(tmp_path, figs):
    c = cycle_to_si(cycle_brief())
    ctx = cr.cycle_context(c, "en", {"linear": "a.png", "circular": "b.png"}, cy.check_constraints(c),
                           level=3, label="cyc2")
    md = render(tmp_path, {"cycle": ctx}, "cycle", "en")
    assert "### Motion cycle diagram" in md and "#### Timing checks" in md
    assert "| positioning pin | near dwell | 0.0 – 170.0 | 170.0 | 0.000 | 2.833 |" in md
    assert "bending arm return ends at least 10.0° before positioning pin return starts" in md
    assert "**FAIL**" in md and "{#fig:cyc2-circular" in md
    # verification residuals are computed, and tiny
    assert all(number(v) < 1e-9 for _, v in ctx["verify"])


def test_cycle_all_met_says_so(tmp_path):
    b = cycle_brief().model_dump()
    b["constraints"] = b["constraints"][:1]
    c = cycle_to_si(CycleSection.model_validate(b))
    md = render(tmp_path, {"cycle": cr.cycle_context(c, "zh", {"linear": "a", "circular": "b"},
                                                  cy.check_constraints(c))},
                "cycle", "zh")
    assert "各项协调要求均满足" in md and "警告" not in md


# --------------------------------------------------------------------------- morphology


def test_morphology_matrix(tmp_path):
    m = morph()
    assert m.scheme_count == 243
    md = render(tmp_path, {"morph": cr.morphology_context(m, "zh")}, "morphology", "zh")
    assert r"N = 3 \times 3 \times 3 \times 3 \times 3 = 3^{5} = 243" in md
    assert "| 分功能 | 方案 1 | 方案 2 | 方案 3 |\n|:--|:--|:--|:--|" in md
    assert "| A. 送料 | 送料机构1 | **送料机构2** ✓ | 送料机构3 |" in md
    assert "| D. 扳弯 | 扳弯机构1 | 扳弯机构2 | **扳弯机构3** ✓ |" in md
    assert "A2 + B1 + C1 + D3 + E2" in md and "理由。" in md


def test_morphology_unequal_counts_english(tmp_path):
    m = morph(chosen=(1, 2, 1, 4, 1), counts=(3, 2, 1, 4, 2))
    assert m.scheme_count == 3 * 2 * 1 * 4 * 2
    md = render(tmp_path, {"morph": cr.morphology_context(m, "en", level=3)}, "morphology", "en")
    assert r"N = \prod_i k_i = 3 \times 2 \times 1 \times 4 \times 2 = 48" in md
    assert "| C. function 夹紧 | **mechanism 1** ✓ | — | — | — |" in md
    assert "### Morphological matrix" in md


def test_morphology_chosen_must_exist():
    with pytest.raises(ValueError, match="chosen = 4, but it has only 3"):
        morph(chosen=(4, 1, 1, 1, 1))


# --------------------------------------------------------------------------- incomplete gear


def test_intermittent_section(tmp_path, figs):
    g = gear(rpm=50)
    curves = intermittent_curves(g)           # what the feed stage stores
    paths = cr.make_intermittent_figures(g, curves, figs, "zh")
    assert (tmp_path / paths["motion"]).stat().st_size > 5000
    ctx = cr.intermittent_context(g, curves, "zh", paths)
    md = render(tmp_path, {"ig": ctx}, "intermittent", "zh")
    assert r"\frac{360° \times 10}{36} = 100.00°" in md
    assert r"\frac{360° \times 10}{30} = 120.00°" in md
    # L = R_s Δφ2 = 80 × 2π/3 = 167.55 mm
    assert "= 167.55\\ \\text{mm}" in md
    assert "| 中心距 | $a$ | $m(z_1 + z_2)/2 = 4.00\\times(36 + 30)/2$ | 132.00 | mm |" in md
    assert "| 锁止弧半径 | $R_L$ | $R_L = r_{a1}$ | 76.00 | mm |" in md
    # k = 100/260, τ = 100/360; ω2 jump = (50·2π/60)·36/30 = 2π rad/s
    assert "| 动停比 | $k$ | $\\varphi_m/\\varphi_d$ | 0.3846 | — |" in md
    assert "| 运动系数 | $\\tau$ | $t_m/T = \\varphi_m/360°$ | 0.2778 | — |" in md
    assert f"{2 * np.pi:.3f}" in md              # 2π rad/s to 4 significant digits (the rule)
    assert r"$\varphi$ = 300.0° 进入啮合，至 $\varphi$ = 40.0° 脱离啮合" in md
    assert "{#fig:intermittent-motion" in md
    # the residuals are computed in the run and are rounding-small
    assert all(abs(number(v)) < 1e-9 for _, v in ctx["verify"])


def test_intermittent_per_radian_english(tmp_path):
    g = gear()
    md = render(tmp_path, {"ig": cr.intermittent_context(g, intermittent_curves(g), "en", {"motion": "m.png"},
                                                        level=3)},
                "intermittent", "en")
    assert "### Incomplete gear drive" in md
    # the ratio 36/30 to 4 significant digits (fmt's rule for ratios; it was 1.2000 before
    # issue 19 point 5's second review: no five significant digits with three decimals)
    from mechdesign.render.fmt import sig
    assert (r"\Delta\left(\frac{d\varphi_2}{d\theta}\right) = \frac{z_1}{z_2} = \frac{36}{30} = "
            + sig(36 / 30)) in md and sig(36 / 30) == "1.200"
    assert "| driver's motion angle | 100.00° | 100.00° |" in md


def test_intermittent_notes_shown(tmp_path):
    from mechdesign.core.intermittent import design_incomplete_gear

    g = design_incomplete_gear(0.004, 12, 16, teeth=3)
    md = render(tmp_path, {"ig": cr.intermittent_context(g, intermittent_curves(g), "zh", {"motion": "m.png"})},
                "intermittent", "zh")
    assert md.count("> **注意：**") == 2


# --------------------------------------------------------------------------- all sections


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_every_section_renders(tmp_path, figs, lang):
    c = cycle_to_si(cycle_brief())
    g = gear(rpm=10)
    checks = cy.check_constraints(c)
    ctx = {"cycle": cr.cycle_context(c, lang, cr.make_cycle_figures(c, figs, lang, checks), checks),
           "morph": cr.morphology_context(morph(), lang),
           "ig": cr.intermittent_context(g, intermittent_curves(g), lang,
                                         cr.make_intermittent_figures(g, intermittent_curves(g), figs, lang))}
    for s in SECTIONS:
        md = render(tmp_path, ctx, s, lang)
        assert md.startswith("# Chapter\n\n") and "{{" not in md and "{%" not in md


def test_heading_level_checked():
    with pytest.raises(ValueError, match="heading level"):
        cr.morphology_context(morph(), "zh", level=0)


def test_cycle_state_names_cover_the_figure_colours():
    from mechdesign.render.cycle_figures import COLOURS

    assert set(COLOURS) == set(cy.STATES)
