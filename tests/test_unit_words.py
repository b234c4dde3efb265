"""Issue 19, points 4 and 5: one unit word per language, and a number never parted from its
unit.

* Chinese reports write a rotational speed in r/min (GB 3102 and the textbook), English ones
  in rpm (the course's table unit): every zh report's Markdown holds no "rpm" outside the
  program listings, and no Chinese catalogue entry (report text, figures, sheets, terminal
  messages) uses the word.
* A value's number and its unit stay on one line in the PDF and in Word ("−4.27" | "rad/s²"
  and "n =" | "1450" were parted at line ends): render/unitjoin.py's pandoc filter joins
  them with no-break spaces and keeps a short inline formula with a relation in one box.
  :func:`parted_at_line_ends` finds such a break in a PDF; the e2e test of every report
  (tests/test_typeset.py) asserts it finds none. The base commit (6d985f2) failed both.
"""
from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

from tests.test_report_prose import EXAMPLES, _markdown

ROOT = Path(__file__).resolve().parents[1]

# ------------------------------------------------------------------------------ rpm, r/min

_RPM = re.compile(r"(?<![A-Za-z_])rpm(?![A-Za-z_])")


def _prose(md: str) -> str:
    """The Markdown without its code blocks (the appendix's program listing)."""
    return re.sub(r"^```.*?^```", "", md, flags=re.S | re.M)


@pytest.mark.parametrize("name", EXAMPLES)
def test_chinese_reports_write_r_per_min(example_results, name):
    md, _ = _markdown(example_results, name, "zh")
    found = [line[:120] for line in _prose(md).splitlines() if _RPM.search(line)]
    assert not found, "\n".join(found[:8])


def test_english_keeps_rpm_and_the_catalogue_has_no_rpm_in_chinese(example_results):
    md, _ = _markdown(example_results, "shaper", "en")
    assert _RPM.search(_prose(md)) and "r/min" not in _prose(md)
    from babel.messages.pofile import read_po

    for name in ("zh.po", "zh_TW.po"):
        with open(ROOT / "src" / "mechdesign" / "locale" / name, "rb") as fh:
            catalogue = read_po(fh)
        words = [m.id for m in catalogue if m.id and isinstance(m.string, str)
                 # a placeholder's name ({rpm:g}, %(rpm)s, speed_rpm) is no word of the text
                 and _RPM.search(re.sub(r"\{[^{}]*\}|%\([^)]*\)s", "", m.string))]
        assert not words, (name, words[:5])


def test_a_terminal_message_of_the_drive_in_chinese():
    """The drive's "the stages cannot reach the ratio" message lists the synchronous speeds
    it tried, each with its unit: r/min in Chinese, rpm in English."""
    from mechdesign.core.drive import Element, Motor, choose_motor
    from mechdesign.core.errors import DesignError

    motors = [Motor(f"M{s}", 1000.0, s, s * 0.95, 0.1, 2.0, 2.2) for s in (1000.0, 1500.0)]
    fixed = [Element("spur", 0.97, (3.0, 5.0), 8.0, 2.0)]           # i = 2 only
    with pytest.raises(DesignError) as err:
        choose_motor(motors, 500.0, 100.0, fixed)
    en, zh = err.value.message.text("en"), err.value.message.text("zh")
    assert "1500 rpm → i = 14.2" in en and "1000 rpm → i = 9.5" in en
    assert "1500 r/min → i = 14.2" in zh and not _RPM.search(zh)


def test_a_speed_written_with_its_unit_is_answered_in_the_language_of_the_message(tmp_path):
    """A brief's "80 rpm" or "80 r/min" in an _rpm field: drop the unit, which the Chinese
    message calls r/min."""
    from mechdesign.brief.loader import BriefError, load_variant

    text = (ROOT / "designs" / "shaper.yaml").read_text(encoding="utf-8")
    for written in ("80 rpm", "80 r/min"):
        brief = tmp_path / "b.yaml"
        brief.write_text(text.replace("crank_speed_n2_rpm: 80", f"crank_speed_n2_rpm: {written}"),
                         encoding="utf-8")
        with pytest.raises(BriefError) as info:
            load_variant(brief)
        (p,) = [p for p in info.value.problems if p.path == "linkage.crank_speed_n2_rpm"]
        assert "a number in rpm, without the unit: write 80" in p.allowed
        assert "r/min" in p.allowed_zh and not _RPM.search(p.allowed_zh), p.allowed_zh


# ------------------------------------------------------------------------------ line ends

# the unit words the reports write after a number (a word beginning with one of them and going
# on with no letter or digit: "rad/s²", "N·m", "r/min，")
_UNITS = ("mm", "m", "μm", "s", "min", "h", "N", "kN", "W", "kW", "J", "kg", "rad", "rpm",
          "r/min", "°", "%", "Pa", "MPa", "Hz")
_NUMBER_END = re.compile(r"(?<![A-Za-z_])[-−+]?\d+(?:\.\d+)?[⁰¹²³⁴⁵⁶⁷⁸⁹⁻]*$")
_UNIT_START = re.compile(r"^(?:%s)(?![A-Za-z0-9_])"
                         % "|".join(re.escape(u) for u in sorted(_UNITS, key=len, reverse=True)))
_RELATION_END = re.compile(r"[=≈≤≥]$")
_NUMBER_START = re.compile(r"^[-−+]?\d")


def parted_at_line_ends(pdf: Path) -> list[tuple[int, str, str]]:
    """(page, end of a line, start of the next) wherever a line of a paragraph or table cell
    ends with a number whose unit starts the next line, or with a relation sign ("=") whose
    number starts the next line. The next line is the one PyMuPDF reads after it that stands
    right under it (overlapping it across, less than a line's height below); a program
    listing (monospaced) is not prose."""
    import pymupdf

    out = []
    with pymupdf.open(pdf) as doc:
        for pno, page in enumerate(doc, 1):
            lines = [(line["bbox"], "".join(s["text"] for s in line["spans"]).strip())
                     for block in page.get_text("dict")["blocks"] for line in block.get("lines", [])
                     # not a program listing's line (a monospaced font)
                     if not any("Mono" in s["font"] for s in line["spans"])]
            lines = [(box, text) for box, text in lines if text]
            for (a_box, a), (b_box, b) in zip(lines, lines[1:]):
                height = a_box[3] - a_box[1]
                under = a_box[3] - 2 <= b_box[1] < a_box[3] + 0.9 * height
                if not (under and b_box[0] < a_box[2] and a_box[0] < b_box[2]):
                    continue
                if (_NUMBER_END.search(a) and _UNIT_START.match(b)) or \
                        (_RELATION_END.search(a) and _NUMBER_START.match(b)):
                    out.append((pno, a[-24:], b[:24]))
    return out


def test_the_scan_finds_a_parted_value(tmp_path):
    """Typeset without the filter (pandoc and typst alone), a paragraph whose line ends at
    "4.27" or at "=" is found; the same with the filter is not."""
    from mechdesign.render.pdf import render_pdf
    from mechdesign.render.report import template_dir

    md = _line_end_trials()
    (tmp_path / "doc.md").write_text(md, encoding="utf-8")
    render_pdf(tmp_path / "doc.md", tmp_path / "doc.pdf", {"title": "T", "lang": "en"},
               template_dir() / "report.typ")
    assert parted_at_line_ends(tmp_path / "doc.pdf") == []
    # the same text through pandoc and typst without the filter parts some of them
    import pypandoc
    import typst

    plain = tmp_path / "plain.typ"
    subprocess.run([pypandoc.get_pandoc_path(), "--from=markdown+tex_math_dollars",
                    "--to=typst", "--wrap=none", str(tmp_path / "doc.md"), "-o", str(plain)],
                   check=True)
    (tmp_path / "plain.pdf").write_bytes(typst.compile(str(plain)))
    found = parted_at_line_ends(tmp_path / "plain.pdf")
    assert any(re.search(r"\d$", a) for _, a, _ in found), found
    assert any(a.endswith("=") for _, a, _ in found), found


def _line_end_trials() -> str:
    """Paragraphs whose value falls at every place of a line: the same sentence after a
    growing number of words."""
    paras = []
    for k in range(40):
        lead = " ".join(["word"] * k)
        paras.append(f"{lead} the slider's angular acceleration $\\alpha_5$ = -4.27 rad/s² and "
                     f"the reaction $R_{{BV}} = -1978.4$ N at n = 1450 rpm.")
    return "\n\n".join(paras) + "\n"


def _filtered(tmp_path: Path, markdown: str, lang: str = "en") -> str:
    """``markdown`` through pandoc's typst writer with the unit filter, as render/pdf.py runs it
    (``lang`` the report's language in the metadata: render/pdf.py writes zh as zh-Hans)."""
    import pypandoc

    from mechdesign.render.unitjoin import LUA_FILTER

    (tmp_path / "f.lua").write_text(LUA_FILTER, encoding="utf-8")
    (tmp_path / "in.md").write_text(markdown, encoding="utf-8")
    return subprocess.run([pypandoc.get_pandoc_path(), "--from=markdown+tex_math_dollars",
                           "--to=typst", "--wrap=none", f"--lua-filter={tmp_path / 'f.lua'}",
                           f"--metadata=lang:{'zh-Hans' if lang == 'zh' else lang}",
                           str(tmp_path / "in.md")], capture_output=True, check=True).stdout.decode()


def test_the_filter_joins_numbers_units_and_relations(tmp_path):
    """The filter's rule, on pandoc's typst output: "~" (no-break) between a number and its
    unit word, after a relation before a number, around × between numbers; ordinary words,
    formulas and code untouched; a short inline formula with a relation boxed."""
    typ = _filtered(tmp_path,
        "$\\alpha_5$ = -4.27 rad/s², 5 steps, $h = 14.9$ mm, 1.4 × 10⁻¹⁴ mm, "
        "转速 n = 60.00 r/min，循环 2 crank，$G_6$（构件 6）= 1962 N\n\n```\nx = 5 mm\n```\n")
    assert "$alpha_5$~=~-4.27~#box[rad/s²,];" in typ   # the symbol stays with its "=" too
    assert "5 steps" in typ and "2 crank" in typ
    assert "#box($h = 14.9$);~mm" in typ
    assert "1.4~×~10⁻¹⁴~mm" in typ
    assert "$n$~=~60.00~#box[r/min，];循环" in typ   # the symbol set italic too
    assert "（构件 6）\u2060=~1962~N" in typ   # a relation ending a word: joined on both sides
    assert "x = 5 mm" in typ                 # a code block as written


def test_a_list_of_relations_is_boxed_item_by_item(tmp_path):
    """A formula listing relations ("C_v = 2.000, C_a = 4.000, C_j = ∞") is boxed item by item,
    with a breakable space after each comma (one box for the list was the unbreakable run that
    left the shaper en's cam-law line before it with 11 pt word spaces); a comma inside braces
    or brackets, or an item without a relation, keeps the formula one box."""
    typ = _filtered(tmp_path,
        "coefficients $C_v = 2.000, C_a = 4.000, C_j = \\infty$ and $f(a, b) = 1$ and "
        "$x = 1, y$ end\n")
    assert "#box($C_v = 2.000$);, #box($C_a = 4.000$);, #box($C_j = oo$);" in typ
    assert "#box($f \\( a \\, b \\) = 1$);" in typ and "#box($x = 1 \\, y$);" in typ
    assert typ.count("#box(") == 5, typ


def test_a_break_before_a_long_run_is_marked_in_chinese_paragraphs(tmp_path):
    """zh: "#run-break;" (templates/report.typ: the line before ends unjustified when the run
    went to the next line) where a line may break before an unbreakable run of at least six
    characters: after a space or a Chinese character, before a boxed formula, a value joined
    by no-break spaces, a Latin word, an opening bracket before a run; never after an opening
    bracket (no break there), before a short run, in a table's cell, or in English."""
    md = ("动能增量 $\\Delta E = \\int M_d d\\varphi$ 的最大值即最大盈亏功 $\\Delta W_{max}$ = 3499.5 J，"
          "在 $x$ = 1 处，拉直共线（$L_{AC} = L_{BC} + L_{AB}$），粗实线（OUTLINE）、细点画线（CENTER）\n\n"
          "| a | b |\n|---|---|\n| 转角 $\\varphi = 120.5$ | 细实线 CONSTRUCTION |\n")
    typ = _filtered(tmp_path, md, lang="zh")
    para, table = typ.split("#table", 1) if "#table" in typ else (typ, "")
    # the mark carries the run's length in characters, counted from the source (an
    # over-estimate of its width: templates/report.typ's run-break keeps a forced break only
    # where the run would not fit after the line before it)
    assert "粗实线#run-break(9);（OUTLINE）、细点画线#run-break(8);（CENTER）" in para   # 2 + 7, 2 + 6
    para = re.sub(r"#run-break\((\d+)\);", "#run-break;", para)
    assert "动能增量 #run-break;#box($Delta E" in para            # after a space, a boxed formula
    assert "盈亏功 #run-break;$Delta W_max$~=~3499.5~J" in para  # a value joined by no-break spaces
    assert "在 $x$~=~1" in para                                     # "x = 1": too short
    assert "拉直共线#run-break;（#box(" in para                     # the bracket goes with the run
    assert "粗实线#run-break;（OUTLINE）、细点画线#run-break;（CENTER）" in para
    assert "（#run-break" not in typ and "run-break" not in table
    assert "run-break" not in _filtered(tmp_path, md, lang="en")


def test_min_and_max_subscripts_are_set_upright(tmp_path):
    """"min" and "max" in a subscript are words (孙桓《机械原理》 writes γ_min, s_max with an
    upright subscript; ISO 80000-1 §7.1: a subscript that is not a quantity is upright).
    The Markdown writes "_{min}" (italic m·i·n as TeX reads it); the filter turns it into the
    operator \\min, which the typst writer sets as the upright word "min" and Word as a
    function name. A subscript letter that is a symbol ("_{d}") and text in \\text{} stay."""
    typ = _filtered(tmp_path,
        "$\\gamma_{min} = 40°$, $s_{max}$, $z_{min,1}$, $F_{E,max}$, $x_{dmin}$, $y_{\\text{min}}$, "
        "$R_{d}$, $\\gamma_{minor}$\n")
    assert "gamma_min = 40 degree" in typ          # typst's "min": an upright operator
    assert "$s_max$" in typ and "z_(min \\, 1)" in typ and "F_(E \\, max)" in typ
    assert "$R_d$" in typ and "upright(\"min\")" in typ   # \text{min} as written
    assert re.findall(r"_\((?:[A-Za-z] )?m i n\)", typ) == ["_(d m i n)"]   # only "dmin" left
    assert "gamma_(m i n o r)" in typ                      # a longer word is not touched


def test_a_symbol_written_as_a_word_is_set_italic(tmp_path):
    """A quantity's symbol in running text ("K = 1.05", "（φ = 0.0°）", "，q = 10") is set as
    a formula, italic like the same symbol in the equations (ISO 80000-1 §7.1.1: symbols for
    quantities in italic type); a letter that ends a longer word ("ab", "μφ", "2z") and a
    letter not followed by a relation ("a b") stay text."""
    typ = _filtered(tmp_path,
        "行程速比系数 K = 1.05，（φ = 0.0°） 取键，q = 10。 μφ = 1.25, ab = 3, 2z = 4, "
        "$x$ = 3, a b and e = 0.00 mm\n")
    assert "系数 $K$~=~1.05" in typ and "（$phi$~=~0.0°）" in typ and "，$q$~=~10" in typ
    assert "$e$~=~0.00~mm" in typ
    assert "μφ~=~1.25" in typ and "ab~=~3" in typ and "2z~=~4" in typ
    assert typ.count("$x$") == 1                   # a formula is not wrapped twice


def test_a_lone_letter_in_a_sentence_is_a_symbol_but_not_a_unit(tmp_path):
    """"刨头位移 s 由位置 1 起算": the lone letter is the displacement's symbol, italic; "5 s",
    "residual / m" and a unit column's cell "| s |" are units, upright; "a" is the English
    article, capitals ("A 型 V 带") belt sections."""
    typ = _filtered(tmp_path,
        "刨头位移 s 由位置 1 起算，时间 5 s 内，选用 A 型 V 带，a b and δ 为 x\n\n"
        "| residual / m | time | unit |\n|--|--|--|\n| 1 | 2 | s |\n")
    assert "位移 $s$ 由" in typ and "$delta$ 为" in typ and "a $b$ and" in typ
    assert "5~s 内" in typ and "A 型 V 带" in typ
    assert "[residual / m]" in typ and "[s]" in typ


@pytest.mark.e2e
def test_a_run_prints_no_font_lookup_noise(tmp_path):
    """matplotlib's mathtext (the DejaVu set) looks up its STIX and Computer Modern fallback
    families by name; where its font list lacks them it logged "findfont: Font family
    ['STIXGeneral'] not found. Falling back to DejaVu Sans." — 42 such lines in the middle of
    the progress display of a lock-beam run. A run's terminal output holds none."""
    import os
    import sys

    env = {**os.environ, "MECHDESIGN_CACHE": "off"}
    run = subprocess.run([sys.executable, "-m", "mechdesign", "run", str(ROOT / "designs" / "lockbeam.yaml"),
                          "-f", "md", "-o", str(tmp_path / "out")], capture_output=True, text=True, env=env)
    assert run.returncode == 0, run.stderr[-2000:]
    assert "findfont" not in run.stdout + run.stderr


# ------------------------------------------------------------------------------ the degree sign

# a number, a space of any kind, then the degree sign of an angle (not °C, not a scale °/mm)
_DEG_APART = re.compile(r"\d[ \u00a0\u202f\u2009]+°(?![C/])")


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_degree_sign_follows_its_number(example_results, lang):
    """The course writes an angle as 34.92°, the sign right after the number (GB 3102.1: no
    space before °, ′, ″); the guide-bar exercise's linkage chapter printed "Swing 34.92 °"
    (the output's unit after a space, as for mm)."""
    md, _ = _markdown(example_results, "textbook_guide_bar", lang)
    found = [line[:120] for line in _prose(md).splitlines() if _DEG_APART.search(line)]
    assert not found, "\n".join(found[:8])
    word = "Swing" if lang == "en" else "摆角"
    assert re.search(word + r" \d+\.\d\d°[;；]", md)


def test_a_unit_after_a_value_before_a_relation_stays_a_unit(tmp_path):
    """A quantity's symbol before its relation is set italic ("K = 1.05"), but a unit word
    after a value is no symbol: "$T_c = 0.9983$ N·m ≤ …" and "48 000 h → 6311" printed
    "N·𝑚" and "ℎ" (page review 41). ISO 80000-1: unit symbols upright."""
    typ = _filtered(tmp_path,
        "so $T_c = 0.9983$ N·m ≤ $T_n$ = 16 N·m, the life reaches 48 000 h → 6311, "
        "and K = 1.05 while 5 s = 5 s\n")
    assert "N·m~≤" in typ and "N·$m$" not in typ, typ
    assert "000~h~→" in typ and "$h$" not in typ, typ
    assert "$K$~=~1.05" in typ                  # a symbol before its relation still italic


def test_a_unit_with_a_solidus_is_not_parted_at_its_slash(tmp_path):
    """typst may end a line after the "/" of a unit ("𝜔5 = 0 rad/" | "s;": lockbeam en p.26,
    page review 47): a unit word with a solidus is set in a box in the PDF (its text stays
    "rad/s"); a word with a slash that is no unit ("and/or", "d/D") is left as written, and so
    are formulas and code."""
    typ = _filtered(tmp_path, "ω5 = 0 rad/s; q in N/mm and (mm/s²), kN/mm² here, and/or d/D, "
                              "$v = 3$ m/s. `rad/s`\n")
    assert "#box[rad/s;];" in typ and "#box[N/mm];" in typ and "#box[\\(mm/s²),];" in typ
    assert "#box[kN/mm²];" in typ and "#box[m/s.];" in typ
    assert "and/or" in typ and "#box[and" not in typ and "#box[d/D" not in typ
    assert "`rad/s`" in typ or "raw(\"rad/s\")" in typ
