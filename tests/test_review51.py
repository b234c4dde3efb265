"""Page review 51, B findings on wording (the rendered reports):
- the furnace drive's coupling step said "K_A = 1.3 (table 14-1)" beside Table 1's
  "K_A application factor 1.00": one symbol, two values, unexplained there (濮良贵, 机械设计,
  table 14-1 is the coupling's working factor, T_ca = K_A T);
- the die-cutter's chosen-values lead-in said that changing the brief recomputes the report
  (a program's words in a hand-in), and its flywheel placement kept "the brief's" mean
  diameter, which Table 2 lists as a value chosen in this design."""
import pytest


@pytest.mark.parametrize("lang, words", [
    ("en", "$K_A$ = 1.3 (the coupling's working factor, table 14-1, not the gears' application factor)"),
    ("zh", "$K_A$ = 1.3（联轴器工况系数，表 14-1，非齿轮的使用系数）"),
])
def test_the_couplings_factor_is_told_apart_from_the_gears(handin_reports, lang, words):
    md, _ = handin_reports("furnace_drive", lang)
    assert words in md
    assert "$K_A$ = 1.3 (table 14-1)" not in md and "$K_A$ = 1.3（表 14-1）" not in md


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_die_cutters_report_speaks_of_the_design_not_the_program(handin_reports, lang):
    md, _ = handin_reports("die_cutter", lang)
    for words in ("recomputes the report", "报告随之重算", "the brief's mean diameter", "设计任务书的值"):
        assert words not in md
    assert ("chosen in @tbl:dc-choices" in md) if lang == "en" else ("@tbl:dc-choices 选定的 $D$" in md)


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_every_velocity_compared_was_constructed(handin_reports, lang):
    # page review 51 (press position 10): link 2 turns so slowly there (v_CB = 0.005 m/s) that
    # v_S2B rounds to no length on the drawing, and the construction of v_S2 was left out of
    # the vector equations while the graphical-against-analytic table compared its value.
    # Every centre of mass's v_S / a_S compared at a position has its row among that
    # position's vector tables (the image method: v_S2 = v_B + v_S2B).
    import re

    md, _ = handin_reports("press", lang)
    parts = re.split(r"^## .*?(?=\d)(\d+)", md, flags=re.M)
    checked = 0
    for k in range(1, len(parts) - 1, 2):
        body = parts[k + 1]
        compared = set(re.findall(r"^\| \$([va]_\{S\d\})\$ \| m/s", body, flags=re.M))
        built = set(re.findall(r"^\| \$([va]_\{S\d\})\$ \| (?:\?|√|[\d.]+) \|", body, flags=re.M))
        assert compared <= built, (parts[k], compared - built)
        checked += len(compared)
    assert checked >= 8          # v and a of S2, S3 at positions 5 and 10


@pytest.mark.parametrize("name", ["shaper", "shaper_lengths", "die_cutter", "press"])
@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_rims_height_is_not_the_stroke(handin_reports, name, lang):
    # page review 51 (shaper_lengths p.17/19): "height H = 233.7 mm" of the flywheel rim,
    # while H is the ram's stroke (298.29 mm) everywhere else; the rim's height is H_F
    md, _ = handin_reports(name, lang)
    if "J_F" not in md or "\\gamma" not in md:
        pytest.skip("no rim flywheel in this report")
    assert "H_F/b" in md and "$H/b$" not in md and "(H/b)" not in md
    assert "height $H$ =" not in md and "高 $H$ =" not in md
