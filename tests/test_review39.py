"""Findings of the session-39 page review (review39), each checked on the example reports'
Markdown (rendered from the session's computed results, tests/conftest.py's
``handin_reports``) or on the computed results themselves.

- A report that checks "the original report" cites it: the seed report is an entry of its
  references, cited where the report first names it (furnace pusher, lock-beam).
- A drive without a flywheel does not speak of "after the flywheel" (furnace pusher).
- The summary names what each key number belongs to: the die-cutter's incomplete gear, the
  lock-beam's two cams, the drive's two powers (P_w at the machine, P_d = P_w/η at the motor).
- A check that checks nothing is not listed: the power balance of a linkage with no load or
  mass (M_b ≡ 0: 0 = 0), which the lock-beam's verification showed as "0, PASS".
- A table caption promises no column the table lacks (transmission and pressure angles).
- The position labels' rule is stated as the program applies it (the other extreme takes
  the label of the regular position after it: the textbook guide bar's 9′ at 214.92°).
- A known magnitude in a polygon's 大小 column is the value computed (ω²·l), not the value
  read back from its length drawn to the drawing's 0.5 mm.
"""
from __future__ import annotations

import math
import re

import pytest

from mechdesign.render.summary import reference_text

LANGS = ("zh", "en")
ORIGINAL = {"zh": "原报告", "en": "original report"}


def _references(md: str, lang: str) -> list[str]:
    title = "参考文献" if lang == "zh" else "References"
    listing = md.partition(f"# {title} {{-}}")[2].split("\n# ", 1)[0]
    return [t.replace("\\[", "[").replace("\\]", "]")
            for t in re.findall(r"^\\\[\d+\\\] (.+)$", listing, flags=re.M)]


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", ["furnace_pusher", "lockbeam"])
def test_the_original_report_is_cited_where_it_is_first_named(handin_reports, name, lang):
    md, _ = handin_reports(name, lang)
    body = md.split("# 参考文献" if lang == "zh" else "# References")[0]
    first = body.find(ORIGINAL[lang])
    assert first >= 0
    seed = reference_text(f"seed_{name.split('_')[0]}", lang)
    refs = _references(md, lang)
    assert seed in refs, refs
    number = refs.index(seed) + 1
    # the sentence that first names it carries the citation
    sentence = body[max(body.rfind("\n", 0, first), 0): body.find("\n", first)]
    assert re.search(rf"\\\[(\d+, )*{number}(, \d+)*\\\]", sentence), sentence


@pytest.mark.parametrize("lang", LANGS)
def test_a_drive_without_a_flywheel_does_not_speak_of_one(handin_reports, lang):
    md, document = handin_reports("furnace_pusher", lang)
    assert "flywheel" not in document or not document["flywheel"]
    after = "飞轮之后的轴" if lang == "zh" else "after the flywheel the shaft"
    assert after not in md
    assert ("本机不设飞轮，轴承受" if lang == "zh" else "with no flywheel the shaft carries") in md


def _summary_rows(md: str, lang: str) -> dict[str, str]:
    title = "设计小结" if lang == "zh" else "Summary"
    text = md.partition(f"# {title}")[2].split("\n# ", 1)[0]
    rows = {}
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("|") and len(cells) == 3:
            rows[cells[0]] = cells[1]
    return rows


def test_the_die_cutters_summary_names_the_incomplete_gears_module(handin_reports):
    md, document = handin_reports("die_cutter", "zh")
    rows = _summary_rows(md, "zh")
    assert "齿轮模数 $m$" not in rows
    assert float(rows["不完全齿轮模数 $m$"]) == pytest.approx(document["feed"]["gear"]["module"] * 1e3)


@pytest.mark.parametrize("lang", LANGS)
def test_the_lockbeams_summary_lists_both_cams(handin_reports, lang):
    md, document = handin_reports("lockbeam", lang)
    rows = _summary_rows(md, lang)
    for cam, zh, en in (("positioning_cam", "定位凸轮", "positioning cam"),
                        ("bending_cam", "扳弯凸轮", "bending cam")):
        name = zh if lang == "zh" else en
        base = next(v for k, v in rows.items() if k.startswith(name) and "r_0" in k)
        roller = next(v for k, v in rows.items() if k.startswith(name) and "r_r" in k)
        assert float(base) == pytest.approx(document[cam]["base_radius"] * 1e3, abs=0.005)
        assert float(roller) == pytest.approx(document[cam]["roller_radius"] * 1e3, abs=0.005)


def test_the_drive_summary_names_both_powers(handin_reports):
    """P_w at the machine and P_d = P_w/η at the motor (the furnace drive: 44.0 W of work and
    62.96 W asked of the motor; it listed the latter alone as "power required")."""
    md, document = handin_reports("furnace_drive", "en")
    rows = _summary_rows(md, "en")
    d = document["drive"]
    assert float(rows["power at the machine"]) == pytest.approx(d["machine_power"], rel=5e-4)
    assert float(rows["power the motor must give"]) == pytest.approx(d["power_required"], rel=5e-4)
    assert d["power_required"] == pytest.approx(d["machine_power"] / d["efficiency"])


@pytest.mark.parametrize("lang", LANGS)
def test_no_power_balance_is_listed_for_a_linkage_without_loads(handin_reports, lang):
    md, document = handin_reports("lockbeam", lang)
    assert "\\Sigma P / \\max" not in md
    assert ("故不作功率平衡校核" if lang == "zh" else "no power balance is checked") in md
    # and where there are loads it is still there (the shaper's kinetostatics)
    md, _ = handin_reports("linkage_sixbar", lang)
    assert "\\Sigma P / \\max" in md


def test_the_position_table_caption_promises_only_its_columns(handin_reports):
    md, _ = handin_reports("textbook_guide_bar", "en")
    assert "Output motion, transmission and pressure angles at the positions" not in md
    assert ": Output motion at the positions" in md


@pytest.mark.parametrize("name, label, between", [("textbook_guide_bar", "9'", (8, 9)),
                                                  ("shaper", "8'", (7, 8))])
def test_the_position_labels_rule_is_the_one_applied(handin_reports, example_results, name, label,
                                                     between):
    """The other extreme is labelled by the regular position after it: the guide bar's extreme
    at φ = 214.92° (between regular 8 at 210° and 9 at 240°) is 9′, the shaper's at 209.8°
    (between 7 and 8) is 8′; the text states that rule, not "the position before it"."""
    md, _ = handin_reports(name, "en")
    pos = example_results(name)["linkage"].positions
    regular = [p for p, s in zip(pos.phase, pos.special) if not s]
    phase = pos.phase[list(pos.labels).index(label)]
    assert regular[between[0] - 1] < phase < regular[between[1] - 1]
    if "Event positions are found exactly" in md:
        assert "the output's other extreme by the first regular position after it" in md
        assert "the regular position before them, primed" not in md


def _rows_of(md: str, symbol: str) -> list[list[str]]:
    return [[c.strip() for c in line.strip().strip("|").split("|")]
            for line in md.splitlines() if line.startswith(f"| ${symbol}$ |")]


def test_a_known_magnitude_is_listed_as_computed(handin_reports, example_results):
    """crank_rocker, position 4: a^n_CB = ω2²·l_BC with ω2 read off the velocity polygon
    (0.8438 rad/s, l_BC from the position's points): 0.0312 m/s², drawn 3.0 mm at μa = 0.01
    (the drawing's 0.5 mm) and read back 0.0300. The 大小 column lists 0.0312; it listed the
    read-back 0.0300."""
    md, _ = handin_reports("crank_rocker", "zh")
    pos = example_results("crank_rocker")["linkage_graphical"].positions[0]
    w2 = pos.velocity.rates["2"]
    expected = w2 ** 2 * abs(pos.points["C"] - pos.points["B"])
    rows = _rows_of(md, "a^{n}_{CB}")
    assert rows, "no a^n_CB row"
    size, length, value = float(rows[0][1]), float(rows[0][4]), float(rows[0][5])
    assert size == pytest.approx(expected, abs=5e-5)
    assert length == pytest.approx(round(expected / pos.acceleration.scale * 2) / 2)
    assert value == pytest.approx(length * pos.acceleration.scale)


def test_a_rocking_outputs_sheet_names_its_swing_and_lists_its_omega_once():
    """crank_rocker's A1 analysis sheet: the rocker's curves are its swing ψ (°), angular
    velocity ω and acceleration α (they were "s (°)", "v (rad/s)", "a (rad/s²)", a slider's
    letters), and the table has no second column of the rocker's ω (its "v" and "ω3" columns
    held the same numbers)."""
    import numpy as np

    from mechdesign.brief.loader import load_brief
    from mechdesign.machines import get_machine, stages_for
    from mechdesign.pipeline import run_stages
    from mechdesign.render.analysis_sheet import analysis_sheet, sub
    from mechdesign.render.sheet import Text, TitleInfo
    from mechdesign.render.sheets import linkage_results

    b = load_brief("designs/crank_rocker.yaml")
    m = get_machine(b.machine)
    p = m.to_params(b)
    results, _ = run_stages(stages_for(m, p), {"params": p, "brief": b}, None)
    found = linkage_results(results)
    k = found.motion
    assert k.output_unit == "rad"
    rocker = [link for link, w in k.link_omega.items() if np.allclose(w, k.v)]
    assert rocker, "the output's ω is a link's ω"
    info = TitleInfo("机构运动分析图", "课程设计", "张三", "1", "1", "李", "2026-11-27",
                     number="MD-01", sheet_no=1, sheets=1)
    s, _ = analysis_sheet(found, info, "zh")
    texts = [t.text for t in s.entities if isinstance(t, Text)]
    assert "输出摆角 ψ (°)" in texts and "输出角速度 ω (rad/s)" in texts
    assert not any(t.startswith("输出位移 s") for t in texts)
    # the table's output columns name the rocker (ψ3, ω3, α3; session 40) and its ω once
    r = str(rocker[0])
    assert sub("ψ", r) + " (°)" in texts and "s (°)" not in texts, texts
    assert texts.count(sub("ω", r) + " (rad/s)") == 1, texts


@pytest.mark.parametrize("lang", LANGS)
def test_two_editions_of_one_textbook_each_say_what_they_are_cited_for(handin_reports, lang):
    """Review39: the drive reports cite 濮良贵《机械设计》 in its 8th (2007) and 9th (2013)
    editions side by side, which a teacher marks; each entry now says what the report takes
    from it (the 8th edition's tabulated gear factors, the 9th's numbering of the belt, chain
    and worm tables), and a handbook without a confirmed year says so instead of ending short."""
    md, _ = handin_reports("die_cutter", lang)
    refs = _references(md, lang)
    pu8 = next(r for r in refs if "2007" in r)
    pu9 = next(r for r in refs if "2013" in r and ("濮良贵" in r or "PU Lianggui" in r))
    if lang == "zh":
        assert "表 10-5" in pu8 and "线图" in pu8
        assert "V 带" in pu9 and "按此版编号" in pu9
    else:
        assert "table" in pu8 and "10-5" in pu8 and "charts" in pu8
        assert "V-belt" in pu9 and "numbered as in this edition" in pu9
    handbook = next(r for r in refs if "吴宗泽" in r or "WU Zongze" in r)
    assert handbook.endswith("（版次、出版年不详）" if lang == "zh" else "(edition, year not known)")
