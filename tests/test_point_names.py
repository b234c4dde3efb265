"""Issue 19 point 3: point names typeset as the textbook writes them — O₁, S₃, B₁B₂, A₄O₃
(digits a subscript, letters and primes as they are) — in every report, figure and sheet.

render/labels.py has one function per medium for a name (``md_point``, ``mpl_point``,
``sheet_point``, ``point_tex``) and one for a text holding names (``md_names`` …). This scans
the Markdown of every example brief in both languages for a run of point names with a digit
standing bare — outside a formula, or inside one at the baseline (``$\\perp O2A$``); a name
inside a subscript (``v_{S4}``, ``F_{R12}``, ``l_{O2A}``) is already lowered and stays — and
the analysis and kinematic sheets' PDFs for force names (R12, FI3, Pb, Mb) and point names
(O2, B1) drawn without a subscript. The base commit (a469fe1) failed both scans.

Names without a digit ("AB", "DBC", "BC") were upright text beside the italic names with a
digit, sometimes in one sentence: in the Markdown every point and link name is math italic
now (``md_point``, ``md_names`` and the catalogue's prose), and the scan finds a run of name
letters without a digit outside math (the base commit 6d985f2 failed it: furnace_pusher,
die_cutter, press, crank_rocker, lockbeam, slotter …). The sheets set them italic too, and so
do the report's figures (session 33): every text of every figure of every example is scanned
for a point name in plain text or a capital that matplotlib's mathtext draws from an upright
font (the base commit e9f1fc2 failed it: "B", "$\\mathregular{O_1}$", and — with a font cache
that lacks matplotlib's DejaVu Sans Display — every math letter).
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from mechdesign.render.labels import (md_names, md_point, mpl_label, mpl_names, mpl_point,
                                      point_tex, sheet_names, sheet_point, subscripted, tex_names)
from mechdesign.render.sheet import plain, split_subscripts
from tests.test_report_prose import EXAMPLES, _markdown

ROOT = Path(__file__).resolve().parents[1]

# ------------------------------------------------------------------------------ the functions


@pytest.mark.parametrize("name, tex", [
    ("O1", "O_1"), ("O1A", "O_1A"), ("A4O3", "A_4O_3"), ("B1B2", "B_1B_2"), ("S12'", "S_{12}'"),
    ("G0G", "G_0G"), ("A", "A"), ("C'", "C'"), ("S_3", "S_3"), ("B_", r"B\_"),
])
def test_point_tex(name, tex):
    assert point_tex(name) == tex


def test_one_function_per_medium():
    # Markdown: every point name in math italic, with a digit or without (issue 19 point 3)
    assert md_point("O2") == "$O_2$" and md_point("AB") == "$AB$" and md_point("C'") == "$C'$"
    assert md_point("x-y") == "x-y"
    # a figure: math italic too, with a digit or without; a prime as "′" (mathtext draws "'"
    # as a superscript)
    assert mpl_point("O2") == "$O_2$" and mpl_point("A") == "$A$" and mpl_point("O1A") == "$O_1A$"
    assert mpl_point("C'") == mpl_point("C′") == "$C′$" and mpl_point("ψ") == "ψ"
    # a sheet: the letters italic (as the report's math), the digits subscripts
    assert split_subscripts(sheet_point("O3B")) == [("O", "it"), ("3", True), ("B", "it")]
    assert split_subscripts(sheet_point("DE")) == [("D", "it"), ("E", "it")]
    assert sheet_point("x-y") == "x-y" and not subscripted("Y90S-6") and subscripted("O1A")
    # texts holding names: for a figure or a sheet only the runs of names with a digit change
    assert md_names("2 crank O1A") == "2 crank $O_1A$"
    assert md_names("导杆 O3D") == "导杆 $O_3D$" and md_names("rod BF") == "rod $BF$"
    # an Assur group's code is no point name
    assert md_names("RRR ABD") == "RRR $ABD$" and md_names("guide bar (RPR)") == "guide bar (RPR)"
    assert md_names("feed slider E") == "feed slider $E$"
    assert md_names("crank-rocker O1ABC's crank") == "crank-rocker $O_1ABC$\\'s crank"
    assert mpl_names("A (folded)") == "$A$ (folded)" and mpl_names("rocker O4B") == "rocker $O_4B$"
    assert mpl_names("RRR A-B-C") == "RRR $A$-$B$-$C$" and mpl_names("II 级杆组 $") == "II 级杆组 \\$"
    assert mpl_label(r"arc about D of radius $l_4$") == r"arc about $D$ of radius $l_4$"
    assert mpl_label("given-frame design A′") == "given-frame design $A′$"
    assert mpl_label(r"$\theta = 0$ is a limit (A at infinity)") == r"$\theta = 0$ is a limit ($A$ at infinity)"
    assert sheet_names("rocker at its first extreme C1") == "rocker at its first extreme " + sheet_point("C1")
    assert plain(sheet_names("rod BF (RRR)")) == "rod BF (RRR)"
    assert split_subscripts(sheet_names("rod BF (RRR)"))[1:3] == [("B", "it"), ("F", "it")]
    assert tex_names(r"\perp O2A") == r"\perp O_2A"
    # a name already inside a subscript stays as it is
    assert tex_names(r"F_{R12} + v_{A4A3} + l_{O2A}") == r"F_{R12} + v_{A4A3} + l_{O2A}"


# ------------------------------------------------------------------------------ the reports

_MATH = re.compile(r"\$\$.*?\$\$|\$[^$\n]+?\$", re.S)
_NAMES = re.compile(r"(?<![A-Za-z0-9_\\{])((?:[A-Z][0-9]*'*)*[A-Z][0-9]+'*(?:[A-Z][0-9]*'*)*)"
                    r"(?![A-Za-z0-9_}])")
# words of that form that are not point names: paper formats (sheet list, preview captions),
# motor types (Y90S-6), the enclosure code IP44, the resistances' labels R1, R2 … (first table
# column), the lock-beam's morphology codes (scheme A1 + B2 + C1 …, one per list item) and the
# coupling sizes LT1 … LT10 (GB/T 4323)
NOT_POINTS = [re.compile(p) for p in (
    r"^\| [^|]+ \| A[0-4] \|", r"[(（]A[0-4][,，]", r"\bY\d+[A-Z]*\d*-\d", r"\bIP\d\d\b", r"\bLT\d+\b",
    r"^\| R\d+ \|", r"[A-E]\d(?: \+ [A-E]\d)+", r"^- [A-E]\d ")]


def _scripts_removed(tex: str) -> str:
    """A formula without its sub- and superscripts (what is left is at the baseline)."""
    for _ in range(4):
        tex = re.sub(r"[_^]\{[^{}]*\}", "", tex)
    tex = re.sub(r"[_^]\\?[A-Za-z0-9]", "", tex)
    return re.sub(r"\\(?:text|mathrm|operatorname)\{[^{}]*\}", "", tex).replace("$", " ")


# a point or link name without a digit written as a word ("AB", "DBC", "DE′"), beside names with a
# digit set in math italic (issue 19 point 3: the textbook sets every point name in italic): a
# run of two to four of the letters the course's mechanisms name their points with; the words
# of that form that are no point names are listed
_PLAIN_NAMES = re.compile(r"(?<![A-Za-z0-9_\\{/.-])([A-HMOPS]{2,4})(?=[′″']*(?![A-Za-z0-9_}/-]))")
NOT_NAMES = {"PASS", "GB", "GE", "PDF", "CAD", "HB", "SS"}


def bare_names(md: str) -> list[tuple[str, str]]:
    """(name, line) of every run of point names with a digit not typeset as a subscript, and
    of every run of point names without a digit outside math."""
    md = re.sub(r"^```.*?^```", "", md, flags=re.S | re.M)
    out = []
    for line in md.splitlines():
        text = re.sub(r"\]\([^)]*\)(\{[^}]*\})?", "]", line)        # a figure's path and id
        for formula in _MATH.findall(text):
            out += [(m[1], line[:120]) for m in _NAMES.finditer(_scripts_removed(formula))]
        text = _MATH.sub(" ", text)
        for pattern in NOT_POINTS:
            text = pattern.sub(" ", text)
        out += [(m[1], line[:120]) for m in _NAMES.finditer(text)]
        out += [(m[1], line[:120]) for m in _PLAIN_NAMES.finditer(text) if m[1] not in NOT_NAMES]
    return out


def test_the_scan_finds_the_old_forms():
    """As the base commit wrote them; the typeset forms and the words that are no point
    names pass."""
    old = ["guide bar 4 swings about O3 and drives ram 6", "| crank | 2 crank O1A | O1A | O1A = 57.04 mm |",
           "| $v_{A}$ | 0.770 | $\\perp O2A$ | $pa$ | 38.5 | 0.770 |", "| $a_{S4}$ | 1.80 | $S4 \\to O3$ |",
           "![Meshing drawing: the line of action N1N2 and the segment B1B2](figures/gear_mesh.png)",
           "曲柄摇杆机构 O1ABC 的曲柄", "the crank-rocker O1ABC's crank a", "| 3 | S3 | 12.00 | 0.0250 |",
           # names without a digit, upright beside italic ones (the base commit 6d985f2)
           "| RRR ABD | 2 coupler AB, 3 rocker DBC | AB, DB | AB = 130.66 mm, DB = 575.00 mm |",
           "the crank-rocker $O_1A$–AB–rocker DBC (D the rocker's pivot)",
           "The rocker's extreme positions DE′ and DE″ are symmetric", "| $l_3$ | 摇杆长度 CD | 50.00 | mm |"]
    assert len({line for _, line in bare_names("\n".join(old))}) == len(old)
    ok = ["guide bar 4 swings about $O_3$", "| $v_{A4A3}$ | ? | ∥ bar 4 | $aa_{4}$ |",
          "$$ \\Sigma M_{O2} = 0:\\ M_b + F_{R32} \\times 9.0 = 0 $$", "| $L_{O_3M}$ | guide line |",
          "| Kinematic diagram | A3 | 1:10 | — |", "![机构运动简图（A3，预览）](figures/sheet_kinematic.png)",
          "**Y90S-6**, 0.75 kW", "| R1 | D | 6 | 90.0 |", "scheme A1 + B2 + C1 + D1 + E1 of the 243",
          "- A1 speed reduction: belt", "JB/T 10391-2008 Y series (IP44) motors",
          "| RRR $ABD$ | 2 coupler $AB$, 3 rocker $DBC$ | $AB$, $DB$ |", "guide bar (RPR), PASS",
          "GB/T 14689-2008", "a PDF and a DXF", "crank $l_1 = AB$, 217–255 HB",
          "```\nm.add(Crank(\"input rocker G0G\", \"2\", \"G0\"))\n```"]
    assert not bare_names("\n".join(ok))


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_point_names_typeset_in_every_report(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    bad = bare_names(md)
    assert not bad, "\n".join(map(str, bad[:12]))


# ------------------------------------------------------------------------------ the figures

# a run of point names standing as a word in a figure's plain text (outside its mathtext)
_FIG_NAMES = re.compile(r"(?<![A-Za-z0-9_\\'′{])((?:[A-Z][0-9]*['′]*)+)(?![A-Za-z0-9_}])")
# capitals in a figure's plain text that name no point: an Assur group's code, the units N, J,
# W ("N·m", "(J)", "50 N/mm"), and the quantity symbols of three die-cutter notes ("ΔE",
# "H − t = 46.0 mm", "F/M (kN/(kN·m))": symbols, not point names)
_NOT_FIG_NAMES = re.compile(r"(?<![A-Za-z])(?:[RP]{3}|[NJW](?=[·/)\s]|$))|ΔE|H − [a-z]|F/M")


def _italic_font(font) -> bool:
    return any(w in font.style_name for w in ("Oblique", "Italic"))


def upright_names(text: str) -> list[str]:
    """The point names of a figure's text drawn upright: a run of capitals in its plain text,
    or a capital letter of its mathtext that matplotlib draws from an upright font (as it
    lays the text out: the glyphs and their fonts)."""
    from matplotlib.mathtext import MathTextParser

    parser = MathTextParser("path")
    bad = []
    for k, part in enumerate(re.split(r"((?<!\\)\$[^$]*(?<!\\)\$)", text)):
        if k % 2 == 0:
            bad += _FIG_NAMES.findall(_NOT_FIG_NAMES.sub(" ", part))
        else:
            bad += [f"{chr(g[2])} in {part} ({g[0].style_name})" for g in parser.parse(part, dpi=72).glyphs
                    if "A" <= chr(g[2]) <= "Z" and not _italic_font(g[0])]
    return bad


def test_the_figure_scan_finds_upright_names():
    """As the base commit drew them (plain "B", mathtext "\\mathregular{O_1}"); the italic
    forms, units, group codes and the die-cutter's symbols pass."""
    from mechdesign.render.fonts import configure_matplotlib

    configure_matplotlib()
    for old in ["B", r"$\mathregular{O_1}$", "A (folded)", "pivot A", "摆杆转轴 A", "γ RRR A-B-C",
                r"arc about D of radius $l_4$", "given-frame design A′", "P", r"rocker $\mathregular{O_4B}$",
                r"$\mathrm{C}_2$"]:
        assert upright_names(old), old
    for ok in ["$B$", "$O_1$", "$A$ (folded)", "γ RRR $A$-$B$-$C$", r"arc about $D$ of radius $l_4$",
               "$A′$", "平衡力矩 $M_b$ (N·m)", "力多边形  $\\mu_F$ = 50 N/mm", "动能增量 ΔE (J)",
               "F/M (kN/(kN·m))", "开始压切 H − t = 46.0 mm", r"$\Delta W_{max}$ = 3499.5 J", "30°",
               "α rod–ram (RRP)", "$p(P)′$"]:
        assert not upright_names(ok), (ok, upright_names(ok))


def test_math_letters_are_italic_digits_upright():
    """The figures' mathtext draws a point name's letters from an oblique font and its digit
    subscripts upright, whatever font list matplotlib found (render/fonts.py)."""
    from matplotlib.mathtext import MathTextParser

    from mechdesign.render.fonts import configure_matplotlib

    configure_matplotlib()
    glyphs = MathTextParser("path").parse(mpl_point("O1A"), dpi=72).glyphs
    assert [(chr(g[2]), _italic_font(g[0])) for g in glyphs] == [("O", True), ("1", False), ("A", True)]


def test_word_subscripts_upright_in_figures():
    """With the math letters italic, a word subscript (γ_min, ΔW_max) is set upright in the
    figures as in the report's text: every figure is passed through this before it is saved."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    from matplotlib.mathtext import MathTextParser

    from mechdesign.render.figures import upright_subscript_words
    from mechdesign.render.fonts import configure_matplotlib

    configure_matplotlib()
    fig = Figure()
    t = fig.add_subplot().text(0, 0, r"$\gamma_{min}$ = 46.95°, $\Delta W_{max}$, $x_{m}$")
    upright_subscript_words(fig)
    assert t.get_text() == r"$\gamma_{\mathrm{min}}$ = 46.95°, $\Delta W_{\mathrm{max}}$, $x_{m}$"
    glyphs = MathTextParser("path").parse(r"$\gamma_{\mathrm{min}}$", dpi=72).glyphs
    assert [(chr(g[2]), _italic_font(g[0])) for g in glyphs] == [
        ("γ", True), ("m", False), ("i", False), ("n", False)]


def test_figure_names_in_user_text_parse():
    """A user's text (a group's name) through :func:`mpl_names`: the names become mathtext, the
    rest stays as written ("$" escaped), and matplotlib lays every one out."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    from tests.test_user_text import HOSTILE, ORDINARY

    fig = Figure()
    ax = fig.add_subplot()
    for text in HOSTILE + ORDINARY + ["A$B", "C\\", "'A' B′ $C$ D_1"]:
        ax.text(0, 0, mpl_names(text))
        ax.text(0, 0, mpl_label(mpl_names(text)))
    fig.canvas.draw()
    assert mpl_names("A$B") == "$A$\\$B" and mpl_names("摇杆 O4B") == "摇杆 $O_4B$"


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_point_names_italic_in_every_figure(example_results, monkeypatch, tmp_path, name, lang):
    """Every text of every figure of the report (the machine's, the requested and the
    graphical method's, drawn as the report draws them, taken where they would be saved)
    sets its point names in math italic, as the report's text and the sheets do (issue 19
    point 3); link numbers, units and words stay upright."""
    import importlib

    from matplotlib.text import Text

    from mechdesign.machines import get_machine
    from mechdesign.render import figures as F
    from mechdesign.runner import _with_requested_figures

    found: dict = {}

    def scan(fig, path):
        for t in fig.findobj(Text):
            if t.get_visible() and t.get_text().strip():
                for bad in upright_names(t.get_text()):
                    found.setdefault(Path(path).name, set()).add((t.get_text(), bad))

    monkeypatch.setattr(F, "save_png", scan)
    r = example_results(name)
    report = importlib.import_module(get_machine(r["brief"].machine).report_module)
    (tmp_path / "figures").mkdir()
    figures = _with_requested_figures(report, r, tmp_path / "figures", lang)
    assert figures or name == "furnace_drive"
    assert not found, found


# ------------------------------------------------------------------------------ the sheets

# force names as the polygons name them and point names with a digit, as words of their own
# (not R12: a radius dimension is written R57)
_SHEET_OLD = re.compile(r"(?<![A-Za-z0-9])(FI\d|MI\d|Mb|Pb|G\d|[OSGB]\d[A-Z]?|[BCE][12])"
                        r"(?![A-Za-z0-9])")
LINKAGES = ["shaper", "press", "linkage_sixbar", "die_cutter", "furnace_pusher", "lockbeam",
            "slotter", "textbook_guide_bar", "crank_rocker"]


@pytest.mark.e2e
@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", LINKAGES)
def test_sheet_names_have_real_subscripts(example_results, name, lang, tmp_path):
    """The analysis and kinematic sheets' full-size text spans hold no force or point name
    with its subscript written plain (F_R12's "R12" is a subscript span of its own); the force
    polygons' labels do not overlap."""
    from test_sheet_subscripts import _is_sub, _lines

    from mechdesign.brief.loader import load_brief
    from mechdesign.render.sheets import _builders, write_all

    brief = load_brief(ROOT / "designs" / f"{name}.yaml")
    (tmp_path / "f").mkdir()
    files = write_all(_builders(example_results(name), brief), brief, tmp_path, tmp_path / "f",
                      lang, ("pdf",))
    checked = 0
    for f in files:
        if Path(f.pdf).stem.split("_")[0] not in ("analysis", "kinematic"):
            continue
        checked += 1
        found = set()
        for spans in _lines(tmp_path / f.pdf):
            for j, b in enumerate(spans):
                if not (j and _is_sub(spans[j - 1], b)):
                    found.update(_SHEET_OLD.findall(b["text"]))
        assert not found, (name, lang, f.pdf, sorted(found))
        if Path(f.pdf).stem.startswith("analysis"):
            assert not _overlapping_lines(tmp_path / f.pdf), (name, lang)
    assert checked


def _overlapping_lines(pdf: Path) -> list:
    """Pairs of text lines whose boxes overlap by more than a sliver."""
    import itertools

    import pymupdf

    boxes = []
    with pymupdf.open(pdf) as doc:
        for page in doc:
            for block in page.get_text("dict")["blocks"]:
                for line in block.get("lines", []):
                    text = "".join(s["text"] for s in line["spans"]).strip()
                    if text:
                        boxes.append((pymupdf.Rect(line["bbox"]), text))
    out = []
    for (r1, t1), (r2, t2) in itertools.combinations(boxes, 2):
        a = r1 & r2
        h = min(r1.height, r2.height)
        if not a.is_empty and a.width > 0.15 * h and a.height > 0.3 * h:
            out.append((t1, t2))
    return out
