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
die_cutter, press, crank_rocker, lockbeam, slotter …). Figures and sheets keep their names
upright (the text font), names with a digit and without alike.
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from mechdesign.render.labels import (md_names, md_point, mpl_names, mpl_point, point_tex,
                                      sheet_names, sheet_point, subscripted, tex_names)
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
    assert mpl_point("O2") == r"$\mathregular{O_2}$" and mpl_point("A") == "A"
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
    assert mpl_names("A (folded)") == "A (folded)"
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
# column) and the lock-beam's morphology codes (scheme A1 + B2 + C1 …, one per list item)
NOT_POINTS = [re.compile(p) for p in (
    r"^\| [^|]+ \| A[0-4] \|", r"[(（]A[0-4][,，]", r"\bY\d+[A-Z]*\d*-\d", r"\bIP\d\d\b",
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
