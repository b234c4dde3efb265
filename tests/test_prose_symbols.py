"""A symbol in running text is set as math (review 34).

The shaper's §4 read "F_Rij is the force of link i on link j" (en: i italic, j upright)
and "构件 i 对构件 j" (zh: both upright): the indices i, j are symbols, italic as in the
formula F_Rij beside them, so they are written $i$, $j$ in both languages. This scans the
prose (math, code and figure paths taken out) of every example report for a link index
written as a bare letter.
"""
from __future__ import annotations

import re

import pytest

from tests.test_report_prose import EXAMPLES, _markdown, _prose

BARE_INDEX = re.compile(r"(?:\blinks?|构件)\s*[ijk](?![\w$])")


def test_the_scan_finds_the_reviewed_words():
    assert BARE_INDEX.search(_prose("$F_{Rij}$ is the force of link i on link j;"))
    assert BARE_INDEX.search(_prose("$F_{Rij}$ 表示构件 i 对构件 j 的作用力"))
    assert not BARE_INDEX.search(_prose("$F_{Rij}$ is the force of link $i$ on link $j$;"))
    assert not BARE_INDEX.search(_prose("$F_{Rij}$ 表示构件 $i$ 对构件 $j$ 的作用力"))


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_link_indices_are_math(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    bad = [line[:160] for line in _prose(md).splitlines() if BARE_INDEX.search(line)]
    assert not bad, bad


def test_the_scan_finds_program_variables():
    assert PROGRAM_NAME.search("（原程序的变量 `omega3`、`omega4` 即此处的 $\\omega_4$、$\\omega_5$）")
    assert not PROGRAM_NAME.search("（原报告的构件编号与本设计不同，其 $\\omega_3$、$\\omega_4$ 即此处的 $\\omega_4$）")


# a program's variable written as code in the text (``omega3``): a report says the
# quantity by its symbol (ω3)
PROGRAM_NAME = re.compile(r"`[^`\n]*\b(?:omega|alpha|theta|phi)\d*\b[^`\n]*`")


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_original_programs_quantities_are_named_by_their_symbols(example_results, lang):
    """Review 34: lockbeam §… "（原程序的变量 omega3、omega4 即此…）" — the original VB
    program's variable names in the report's prose; the report writes ω3, ω4."""
    md, _ = _markdown(example_results, "lockbeam", lang)
    body = re.sub(r"^```.*?^```", " ", md, flags=re.S | re.M)     # the code listing may
    bad = [line[:160] for line in body.splitlines() if PROGRAM_NAME.search(line)]
    assert not bad, bad
    assert "abs()" not in _prose(body)


# ---------------------------------------------------------------- quantity letters in prose
# Issue 19: the zh prose wrote quantity letters upright ("由行程 H 与行程速比系数 K",
# "n = 50.00 r/min") while the tables' formulas and the derivations set them italic (math).
# GB 3102 and the textbooks set a quantity symbol in italic wherever it stands, so the text
# writes it as inline math ($H$, $K$, $n$, $J_F$) in both languages.
# A bare letter is a quantity unless it is one of these (every example checked):
#   a unit after a number or a formula ("50 N", "$T$ N·m", "1.2 s"), an English article or
#   pronoun ("a", "A", "I"), an item label "(a)", a product or type designation ("V 带",
#   "V-belt", "Y 系列", "A 型", "form A"), a sheet size or a scheme code (A1, B2: a capital
#   with a digit), a standard's number (GB/T 1096), a bibliography's type mark ([M], [S]);
# the references chapter (titles as published) and the tables are left out.
_QUANTITY = re.compile(r"(?<![A-Za-z0-9_/.\-·'’\\\u0370-\u03ff])"
                       r"([A-Za-z](?:_\{?[A-Za-z0-9]+\}?)?[′″']?)"
                       r"(?![A-Za-z0-9/·\-'’(]|\.[A-Za-z])")
_UNIT_LETTERS = {"N", "m", "s", "J", "h", "W", "V", "A", "g", "K", "t"}


def _bare_quantities(line: str, lang: str) -> list[str]:
    """The bare quantity letters of one prose line (math and code already taken out as §)."""
    out = []
    for m in _QUANTITY.finditer(line):
        tok, before, after = m.group(1), line[:m.start()], line[m.end():]
        if tok in _UNIT_LETTERS and re.search(r"([\d⁰¹²³⁴-⁹§%]\s?|/ ?)$",
                                              before):
            continue                                           # a unit: 50 N, $T$ N·m, /W, 10⁶ N
        if tok in _UNIT_LETTERS and re.search(r"(\bin |以 ?)$", before):
            continue                                           # a unit named: "forces in N", "力以 N 计"
        if lang == "en" and tok in ("a", "A", "I") and re.match(r"\s+[A-Za-z\d\"“]", after):
            continue                                           # an article, a pronoun
        if re.search(r"\\?\($", before) and after.startswith(")"):
            continue                                           # an item label (a)
        if tok == "V" and re.match(r"\s?(带|形|-|belt)", after):
            continue                                           # V 带, V-belt, V 形块
        if tok == "Y" and re.match(r"\s?(系列|-|series|motor)", after):
            continue                                           # Y 系列 motors
        if re.fullmatch(r"[A-Z]", tok) and (re.match(r"\s?型", after)
                                            or re.search(r"(form|type|section|带型|chart, fig\. [\d-]+, gives)\s?$", before)):
            continue                                           # A 型 key, belt section Z
        out.append(tok)
    return out


def _prose_lines(md: str):
    """The report's running text line by line: no code blocks, displayed math, tables,
    raw blocks or references chapter; inline math and code replaced by §."""
    fence = display = False
    for line in md.splitlines():
        s = line.strip()
        if s.startswith(("```", "~~~")):
            fence = not fence
            continue
        if s.startswith("$$") and s.count("$$") == 1:
            display = not display
            continue
        if fence or display or s.startswith(("|", "<", "$$", "{%", "```{=")):
            continue
        if re.match(r"#+ (References|参考文献)", s):
            break
        s = re.sub(r"(?<!\\)\$[^$]*?(?<!\\)\$", "§", s)
        s = re.sub(r"`[^`]*`", "§", s)
        s = re.sub(r"\]\([^)]*\)", "] ", s)
        s = re.sub(r"\{[#.][^}]*\}|\{width=[^}]*\}", " ", s)
        s = re.sub(r"\[@[^\]]*\]|@(fig|tbl|eq|sec):[\w:.\-]*\w", " ", s)
        yield s


def bare_quantities(md: str, lang: str) -> list[tuple[str, str]]:
    return [(tok, line[:160]) for line in _prose_lines(md) for tok in _bare_quantities(line, lang)]


@pytest.mark.parametrize("text, lang, found", [
    ("由行程 H 与行程速比系数 K 设计", "zh", ["H", "K"]),
    ("分配轴每转一周（n = 50.00 r/min，T = 1.200 s）", "zh", ["n", "T"]),
    ("飞轮转动惯量 J_F = 2.569 kg·m²", "zh", ["J_F"]),
    ("实际转速为 n′ = 709.20 r/min", "zh", ["n′"]),
    ("the stroke H and the time ratio K", "en", ["H", "K"]),
    ("由行程 $H$ 与行程速比系数 $K$ 设计，$n$ = 50.00 r/min，$T$ = 1.200 s", "zh", []),
    ("a V-belt, a Y-series motor, key form A, 带型 A，A 型平键，V 带，Y 系列", "en", []),
    ("belt section A (the selection chart, fig. 8-11, gives Z; Z 型), a 4-pole Y motor; 1 − value/allowable, / W", "en", []),
    ("A1 + B2 + C1 on the A1 sheet (GB/T 1096) ## \\(b): 12 738 N·m, 1.2 s, 48 000 h", "en", []),
    ("the cutting force $F_r$ (link 6) = 1.000 × 10⁶ N and the stroke H", "en", ["H"]),
    ("force $P$ N and a torque of $T$ N·m; d'Alembert's principle, i.e. the load", "en", []),
    ("见图 6 量得 ω3 = 1.2 rad/s，表 3 中 mm 与 kW", "zh", []),
    ("# 参考文献\n\n吴宗泽 V 带 K", "zh", []),
    ("| 行程 H | K |", "zh", []),
])
def test_the_quantity_scan(text, lang, found):
    assert [tok for tok, _ in bare_quantities(text, lang)] == found


def test_a_heading_with_a_quantity_letter_keeps_it_in_the_word_contents():
    """"# Crank-rocker from the time ratio $K$": Word holds the K of the heading's inline math
    in an m:t run; the contents entry (render/docx_toc.py) reads it too."""
    from mechdesign.render.docx_toc import _heading_text

    heading = ('<w:r><w:t xml:space="preserve">Crank-rocker from the time ratio </w:t></w:r>'
               '<m:oMath><m:r><m:rPr /><m:t>K</m:t></m:r></m:oMath>')
    assert _heading_text(heading) == "Crank-rocker from the time ratio K"


# ---------------------------------------------------------------- Greek quantity letters
# review36 C / issue 19: Greek quantity letters stood upright in running text and in table
# labels ("(ω = 5.236 rad/s)", "[δ] = 1/20", "θ 圆", "传动角 γ") while the formulas beside
# them set ω, δ, θ, γ italic. A Greek letter of the prose is a quantity; it is written as
# inline math ($\omega$, $[\delta]$, $\theta$-circle) in both languages. Not quantities: a
# position's label ("φ45", the brief's name of the position asked at 45°, like "8′"), the
# unit prefix μ ("μm"), the constant π.
_GREEK = re.compile(r"[\u0391-\u03a9\u03b1-\u03c9]")
_NOT_GREEK_QUANTITY = re.compile(r"φ\d+|μ(?=m\b|s\b)|π")


def bare_greek(md: str, cells: bool = True) -> list[tuple[str, str]]:
    """The bare Greek letters of the report's prose lines and, with ``cells``, of its table
    cells (math and code taken out)."""
    lines = list(_prose_lines(md))
    if cells:
        for row in re.findall(r"^\|(.+)\|$", md, re.M):
            for cell in row.split("|"):
                cell = re.sub(r"(?<!\\)\$[^$]*?(?<!\\)\$", "§", cell)
                lines.append(cell.strip())
    out = []
    for line in lines:
        text = _NOT_GREEK_QUANTITY.sub(" ", line)
        out += [(m.group(0), line[:160]) for m in _GREEK.finditer(text)]
    return out


@pytest.mark.parametrize("text, found", [
    ("原动件为曲柄，以 $n$ = 60.00 r/min 顺时针匀速转动（ω = 6.283 rad/s）", ["ω"]),
    ("飞轮轴转速 60.00 r/min，[δ] = 1/20", ["δ"]),
    ("| 摇杆 $O_4B$ | 传动角 γ | $B$ |", ["γ"]),
    ("## Position φ45 (crank angle 45.0°)", []),
    ("（$\\omega$ = 6.283 rad/s），$[\\delta]$ = 1/20，$\\theta$ 圆，2π，10 μm", []),
])
def test_the_greek_scan(text, found):
    assert [g for g, _ in bare_greek(text)] == found


# A table's label cell (its first column: a check, a result, a quantity) names quantities as
# the prose does: "stroke $H$", "$K$ by position search", not "stroke H" (review36 C). An
# item label "A. speed reduction" (a function of the lock-beam's tree) is no quantity.
_ITEM = re.compile(r"^[A-Z]\. ")


def bare_label_letters(md: str, lang: str) -> list[tuple[str, str]]:
    md = re.split(r"^# (?:References|参考文献)", md, flags=re.M)[0]
    out = []
    for row in re.findall(r"^\|(.+)\|$", md, re.M):
        cell = row.split("|")[0].strip()
        if _ITEM.match(cell):
            continue
        text = re.sub(r"(?<!\\)\$[^$]*?(?<!\\)\$", "§", cell)
        out += [(tok, cell[:160]) for tok in _bare_quantities(text, lang)]
    return out


@pytest.mark.parametrize("text, found", [
    ("| 偏置曲柄滑块机构：行程 H | 100.00 | mm |", ["H"]),
    ("| K by position search | 1.4 | 1.4 | PASS |", ["K"]),
    ("| stroke $H$ | 220.00 | mm |\n| A. speed reduction | x |\n| $K$ by position search | 1.4 |", []),
])
def test_the_label_scan(text, found):
    assert [t for t, _ in bare_label_letters(text, "en")] == found


# every example report, zh and en, by each scan: a quantity letter in the prose, a Greek
# letter in the prose or a table cell, a letter in a table's label cell
SCANS = {"prose": bare_quantities, "greek": lambda md, lang: bare_greek(md),
         "labels": bare_label_letters}


@pytest.mark.parametrize("scan", SCANS)
@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_quantity_letters_are_math(example_results, name, lang, scan):
    md, _ = _markdown(example_results, name, lang)
    bad = SCANS[scan](md, lang)
    assert not bad, bad
