"""User text (titles, names, labels from the brief) appears literally in every output and
cannot inject markup: Markdown (body, table cells, lists, metadata), PDF (typst), Word,
matplotlib figures, formulas (point names), DXF.

The references are independent of the escaping code: pandoc's own reading of the
Markdown (its JSON AST must hold nothing but the text), the text extracted from the PDF
(PyMuPDF), the Word XML, matplotlib's mathtext decision, ezdxf's decoding of DXF text.
Each helper is also shown to matter: the same text unescaped does become markup.
"""
from __future__ import annotations

import html
import importlib.util
import json
import re
import unicodedata
import zipfile
from pathlib import Path

import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from mechdesign.cli import app
from mechdesign.render.fmt import (dxf_text, md_meta, md_paragraphs, md_text, mpl_text,
                                   plain_line, tex_name)
from conftest import read_pdf_text

ROOT = Path(__file__).resolve().parents[1]
HAVE_PANDOC = importlib.util.find_spec("pypandoc") is not None
HAVE_TYPST = importlib.util.find_spec("typst") is not None
needs_pandoc = pytest.mark.skipif(not HAVE_PANDOC, reason="pypandoc is needed")
needs_pdf = pytest.mark.skipif(not (HAVE_PANDOC and HAVE_TYPST),
                               reason="pypandoc and typst are needed")

CORE = "#$x$*_<>\\@\"'|[]~^&😀"
# Hostile text: every character pandoc, typst, matplotlib or LaTeX give a meaning, block
# markers at the start, smart punctuation, raw HTML/TeX, citations, links, entities.
HOSTILE = [
    "- A " + CORE, "1. B " + CORE, "+ C", "* D", "(a) E", "2) F", "iv. G", "# H", "> I", "| J",
    ": K", "= L", "% M", "::: N", "~~~ O", "``` P", "--- Q", "a--b---c", "wait...", "a-?b",
    "*em* _em_ **strong** `code` $x^2$ $$y$$", "<b>bold</b> <!-- c --> <http://x.org>",
    "\\emph{z} \\\\ \\", "[link](http://x) ![img](y.png) [^1] ^[note]", "@fig:x [@tbl:y] -@z",
    "&amp; &#35; &lt;", "~sub~ ^sup^ ~~del~~", "{#id .class} [span]{.c}", "\"double\" 'single' O'Brien",
    "a|b||c \\| d", "$5 and $6", "100% 50%%d ^J", "张三 😀 🎉", "tab\tand\nnewline  spaces",
]
ORDINARY = ["张三", "2023010101", "2026-11-22", "机械设计 2301", "李老师", "O4B", "摇杆 O4B",
            "最小传动角最大的曲柄摇杆机构设计", "机械原理课程设计 · 按行程速比系数设计四杆机构",
            "论文计算机结果 / paper, computer result", "Zhang San", "e = 15 mm, R = 40 mm (b)"]


def _md_format():
    from mechdesign.render.pdf import MARKDOWN_FORMAT

    return MARKDOWN_FORMAT


def ast(md: str, *extra: str) -> dict:
    import pypandoc

    return json.loads(pypandoc.convert_text(md, "json", format=_md_format(),
                                            extra_args=list(extra)))


def inline_text(inlines: list) -> str:
    """The text of a list of inlines, if it holds only Str and Space; any other element
    (Emph, Math, Code, Link, Cite, RawInline, Quoted, …) shows as <<Name>>."""
    out = []
    for el in inlines:
        if el["t"] == "Str":
            out.append(el["c"])
        elif el["t"] == "Space":
            out.append(" ")
        else:
            out.append(f"<<{el['t']}>>")
    return "".join(out)


def block_text(block: dict) -> str:
    return inline_text(block["c"]) if block["t"] in ("Para", "Plain") else f"<<{block['t']}>>"


def read_back(texts: list[str], escape=md_text) -> dict[str, list[str]]:
    """Each text escaped and placed where user text goes: a paragraph of its own, a list
    item, bold, a pipe-table cell; what pandoc reads back in each place."""
    n = len(texts)
    esc = [escape(t) for t in texts]
    md = "\n\n".join(esc) + "\n\n"
    md += "\n".join(f"- {t}" for t in esc) + "\n\n"
    md += "\n\n".join(f"**{t}**" if t else "x" for t in esc) + "\n\n"
    md += "| " + " | ".join(esc) + " |\n|" + "---|" * n + "\n"
    blocks = ast(md)["blocks"]
    paras = [block_text(b) for b in blocks[:n]]
    items = [block_text(item[0]) if len(item) == 1 else "<<blocks>>" for item in blocks[n]["c"]]
    bold = []
    for t, b in zip(esc, blocks[n + 1:2 * n + 1]):
        inl = b["c"]
        if not t:
            bold.append("")
        elif len(inl) == 1 and inl[0]["t"] == "Strong":
            bold.append(inline_text(inl[0]["c"]))
        else:
            bold.append(inline_text(inl))
    table = blocks[2 * n + 1]
    assert table["t"] == "Table"
    head_cells = table["c"][3][1][0][1]
    cells = [block_text(c[4][0]) if c[4] else "" for c in head_cells]
    return {"paragraph": paras, "list item": items, "bold": bold, "table cell": cells}


# ------------------------------------------------------------------------- Markdown


@needs_pandoc
def test_md_text_reads_back_as_the_literal_text_everywhere():
    texts = HOSTILE + ORDINARY
    got = read_back(texts)
    for place, values in got.items():
        assert len(values) == len(texts), place
        for text, value in zip(texts, values):
            assert value == plain_line(text), f"{place}: {text!r} read back as {value!r}"


@needs_pandoc
def test_unescaped_text_would_be_markup():
    # The same texts without escaping: pandoc makes lists, headings, emphasis, math, code,
    # HTML, links, citations, smart quotes and dashes of them (so the test above can fail).
    got = [[block_text(b) for b in ast(plain_line(t))["blocks"]] for t in HOSTILE]
    changed = [t for t, blocks in zip(HOSTILE, got) if blocks != [plain_line(t)]]
    # (": K", "= L" need a line before them, "a-?b" is special to typst only, …)
    assert len(changed) >= 24, set(HOSTILE) - set(changed)
    assert got[0] == ["<<BulletList>>"] and got[7] == ["<<Header>>"]
    assert "<<Emph>>" in got[20][0] and "<<Math>>" in got[20][0]
    # a bare "|" splits a pipe-table cell
    cells = ast("| a|b | c |\n|---|---|\n")["blocks"][0]["c"][3][1][0][1]
    assert [block_text(c[4][0]) for c in cells] == ["a", "b"]


@needs_pandoc
@settings(max_examples=6, deadline=None)
@given(st.lists(st.text(alphabet=st.sampled_from(
    list("\\`*_{}[]<>#$@|~^&\"'-+=:%.()!/,;?0123456789aZiv  \t\n") + ["张", "😀", "\u3000"]),
    min_size=1, max_size=24), min_size=40, max_size=40))
def test_md_text_reads_back_any_text(texts):
    texts = [t for t in texts if plain_line(t)]
    if not texts:
        return
    got = read_back(texts)
    for place in ("paragraph", "table cell", "list item"):
        assert got[place] == [plain_line(t) for t in texts], place


def test_md_text_keeps_ordinary_text_as_it_is():
    for text in ORDINARY:
        assert md_text(text) == text
    assert md_text("  a\n b\t") == "a b"
    assert md_text("a\x00b\x1bc\u2028d") == "abcd"


@needs_pandoc
def test_md_paragraphs_keeps_paragraphs_and_nothing_else():
    text = "- first *line*\nsecond | line\n\n1. new paragraph $x$\n\n\n# third"
    blocks = ast(md_paragraphs(text))["blocks"]
    assert [b["t"] for b in blocks] == ["Para", "Para", "Para"]
    first = blocks[0]["c"]
    assert "SoftBreak" in [el["t"] for el in first]
    assert inline_text([el for el in first if el["t"] != "SoftBreak"]) == \
        "- first *line*second | line"
    assert block_text(blocks[1]) == "1. new paragraph $x$"
    assert block_text(blocks[2]) == "# third"


@needs_pandoc
def test_metadata_values_read_back_literally(tmp_path):
    meta = {f"k{i}": md_text(t) for i, t in enumerate(HOSTILE)}
    meta_file = tmp_path / "meta.json"
    meta_file.write_text(json.dumps(meta, ensure_ascii=False), encoding="utf-8")
    doc = ast("x", f"--metadata-file={meta_file}")
    for i, text in enumerate(HOSTILE):
        value = doc["meta"][f"k{i}"]
        assert value["t"] == "MetaInlines", (text, value["t"])
        assert inline_text(value["c"]) == plain_line(text)


def test_md_meta_escapes_every_text_field():
    from mechdesign.brief.common import ReportMeta

    meta = ReportMeta(title="*T*", student="- S", student_id="1. 2", **{"class": "a|b"},
                      teacher="$t$", date="2026-11-22")
    got = md_meta(meta)
    assert got["title"] == r"\*T\*" and got["student"] == r"\- S"
    assert got["student_id"] == r"1\. 2" and got["class_name"] == r"a\|b"
    assert got["teacher"] == r"\$t\$" and got["date"] == "2026-11-22"


# ------------------------------------------------------------------------- matplotlib


def test_mpl_text_is_never_mathtext():
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    fig = Figure()
    ax = fig.add_subplot()
    for text in HOSTILE:
        for s in (mpl_text(text), mpl_text(text) + r" $\alpha_2$ " + mpl_text(text)):
            t = ax.text(0, 0, s)
            shown, is_math = t._preprocess_math(t.get_text())
            if "$" in s.replace(r"\$", ""):        # mixed with a real formula: math mode,
                assert is_math                     # the user's "$" escaped in it
                assert s.count("$") - s.count(r"\$") == 2
            else:
                assert not is_math
                assert shown.replace("\u200b", "") == plain_line(text)   # zero-width space
    fig.canvas.draw()                               # no mathtext parse errors
    # unescaped, "$x$*_<>…" would be parsed as math and fail to parse
    t = ax.text(0, 0, "a $*_$ b")
    assert t._preprocess_math(t.get_text())[1]


def test_mpl_text_label_starting_with_underscore_shows_in_the_legend():
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    ax = Figure().add_subplot()
    ax.plot([0, 1], label="_hidden")
    ax.plot([0, 1], label=mpl_text("_shown"))
    labels = [t.get_text() for t in ax.legend().get_texts()]
    assert labels == ["\u200b_shown"]


def test_tex_name_is_valid_in_mathtext_latex_and_pandoc():
    from matplotlib.mathtext import MathTextParser

    parser = MathTextParser("path")
    names = ["O2", "C'", "C''", "S_3", "S_34", "B_", "B__2", "B_'", "A_b_c", "B_2'", "C'_2", "X_1_"]
    assert [tex_name(n) for n in ("O2", "C'", "S_3")] == ["O2", "C'", "S_3"]
    for name in names:
        parser.parse(f"$F_{{{tex_name(name)}}}$")
    with pytest.raises(ValueError):                  # the raw name is an error
        parser.parse("$F_{A_b_c}$")
    if HAVE_PANDOC:
        import pypandoc

        md = " ".join(f"$F_{{{tex_name(n)}}}$" for n in names)
        pypandoc.convert_text(md, "typst", format="markdown",
                              extra_args=["--fail-if-warnings"])     # texmath parses all


# ------------------------------------------------------------------------- DXF


def test_dxf_text_decodes_to_the_literal_text():
    from ezdxf.tools.text import plain_text

    # (not a caret at the very end: ezdxf's decoder drops it, whatever the encoding)
    for text in HOSTILE + ["100%%d 50%%c %%p %%%", "^J^M^ ^x"]:
        assert plain_text(dxf_text(text)) == plain_line(text)
    assert plain_text("100%%d ^J") != "100%%d ^J"   # raw: a degree sign and a line feed


# ------------------------------------------------------------------------- PDF (typst)


def pdf_text(path: Path, first: int | None = None, last: int | None = None) -> str:
    # A character no font has is typeset as the .notdef glyph, read back as U+0000. The only
    # such character here is the emoji on a machine with no emoji font (a bare Debian has
    # none; the shipped fonts are CJK): it was passed to typst literally, its glyph is missing.
    # A point name the report sets in math italic (the user's group "rocker OB" → "rocker
    # $OB$") is read back as the Mathematical Alphanumeric letters 𝑂𝐵: compared as the
    # letters they are (NFKC of that block only).
    text = re.sub(r"[\U0001D400-\U0001D7FF]", lambda c: unicodedata.normalize("NFKC", c[0]),
                  read_pdf_text(path, first, last))
    return re.sub(r"\s+", "", text).replace("\x00", "😀")


def squeeze(text: str) -> str:
    return re.sub(r"\s+", "", plain_line(text))


@pytest.mark.e2e
@needs_pdf
def test_typst_shows_user_text_literally_at_block_starts(tmp_path):
    from mechdesign.render.pdf import render_pdf
    from mechdesign.render.report import pdf_metadata, template_dir
    from mechdesign.brief.common import ReportMeta

    texts = ["- list", "+ enum", "1. enum", "/ term: def", "= heading", "a...b", "a-?b", "x // y",
             "#let x = 1", "<label> @ref", "*b* _i_ `r` $m$", "~ \\ ' \""]
    cells = " | ".join(md_text(t) for t in texts)
    md = ("\n\n".join(md_text(t) for t in texts) + "\n\n| " + cells + " |\n|"
          + "---|" * len(texts) + "\n\n: " + md_text("- caption *x*") + "\n")
    (tmp_path / "r.md").write_text(md, encoding="utf-8")
    meta = ReportMeta(title="- " + CORE, subtitle="1. sub", student="+ S", student_id="= 7",
                      **{"class": "/ c: d"}, teacher="# T", date="2026-11-22")
    render_pdf(tmp_path / "r.md", tmp_path / "r.pdf", pdf_metadata(meta, "zh", "(a) g"),
               template_dir() / "report.typ")
    title_page = pdf_text(tmp_path / "r.pdf", 1, 1)
    for value in ("- " + CORE, "1. sub", "+ S", "= 7", "/ c: d", "# T", "(a) g"):
        assert squeeze(value) in title_page, value
    body = pdf_text(tmp_path / "r.pdf", 3)
    for text in texts:                    # twice: the paragraph and the table cell
        assert body.count(squeeze(text)) >= 2, (text, body)
    assert squeeze("- caption *x*") in body


# ------------------------------------------------------------------------- whole runs

BAD = "#$*_$<>\\@\"'|[]~^&😀"


def hostile_cam_brief(tmp_path: Path) -> tuple[Path, dict]:
    """The eccentric-disc exercise (designs/cam_7_1.yaml) with hostile report fields,
    follower labels and a hostile data-group label."""
    data = yaml.safe_load((ROOT / "designs" / "cam_7_1.yaml").read_text(encoding="utf-8"))
    values = {
        "title": "- Title " + BAD, "subtitle": "1. Sub " + BAD, "student": "+ Stu " + BAD,
        "student_id": "(a) 7 " + BAD, "class": "= Cls " + BAD, "teacher": "# Tea " + BAD,
        "date": "2026-11-22",
    }
    data["report"].update(values)
    labels = ["- Fa " + BAD, "1. Fb " + BAD, "(c) Fc " + BAD]
    for fol, label in zip(data["followers"], labels):
        fol["label"] = label
    group = "* Grp $g$ | @x"
    data["groups"] = {"default": 1, "variants": {1: {}, group: {"disc.eccentricity_mm": 18}}}
    path = tmp_path / "cam.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True, sort_keys=False), encoding="utf-8")
    return path, {**values, "labels": labels, "group": group}


def rename(data, points: dict, links: dict):
    """Rename points and link ids throughout a linkage section."""
    if isinstance(data, dict):
        out = {}
        for key, value in data.items():
            if key in ("links", "link"):
                value = [links.get(v, v) for v in value] if isinstance(value, list) else \
                    links.get(value, value)
            elif key == "frame_points_mm":
                value = {points.get(k, k): v for k, v in value.items()}
            elif key != "name" or data.get("type") == "point":
                value = rename(value, points, links)
            out[key] = value
        return out
    if isinstance(data, list):
        return [rename(v, points, links) for v in data]
    if isinstance(data, str):
        return points.get(data, data)
    return data


def hostile_linkage_brief(tmp_path: Path) -> tuple[Path, dict]:
    """designs/linkage_sixbar.yaml with hostile group names and point names / link ids
    that are valid but awkward in formulas (B_, C'', E_1_x, link 4_)."""
    data = yaml.safe_load((ROOT / "designs" / "linkage_sixbar.yaml").read_text(encoding="utf-8"))
    points = {"B": "B_", "C": "C''", "E": "E_1_x"}
    data["linkage"] = rename(data["linkage"], points, {4: "4_"})
    groups = data["linkage"]["groups"]
    # no point name with a digit here: "O4B" in a link's name is typeset O₄B by design
    # (issue 19 point 3, tests/test_point_names.py); the markup characters stay literal
    names = ["- rocker *OB* | " + BAD[:12], "1. slider $E$ @x <i>"]
    groups[0]["name"], groups[4]["name"] = names
    # the English names and title too: the example gives them, and en reports use them
    groups[0]["name_en"], groups[4]["name_en"] = names
    data["report"]["title"] = data["report"]["title_en"] = "Linkage `code` [x](y) " + BAD
    data["analysis"]["grid_points"] = 360
    path = tmp_path / "linkage.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True, sort_keys=False), encoding="utf-8")
    return path, {"names": names, "points": list(points.values()), "title": data["report"]["title"]}


def docx_paragraphs(path: Path) -> str:
    xml = zipfile.ZipFile(path).read("word/document.xml").decode("utf-8")
    # the text runs and the math runs (a point name set as math, "rocker $OB$") in order
    paras = ["".join(html.unescape(t) for t in re.findall(r"<[wm]:t(?: [^>]*)?>([^<]*)</[wm]:t>", p))
             for p in re.findall(r"<w:p[ >].*?</w:p>", xml, flags=re.S)]
    return "\n".join(paras)


def md_plain(path: Path) -> str:
    import pypandoc

    return pypandoc.convert_text(path.read_text(encoding="utf-8"), "plain", format=_md_format(),
                                 extra_args=["--wrap=none", "--columns=100000"])


@pytest.fixture(scope="module")
def cam_run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("hostile_cam")
    brief, values = hostile_cam_brief(tmp)
    result = CliRunner().invoke(app, ["run", str(brief), "-o", str(tmp / "out"), "--group",
                                      values["group"], "-f", "md,pdf,docx"])
    return result, tmp / "out", values


@pytest.mark.e2e
@needs_pdf
def test_hostile_cam_brief_renders_literally(cam_run):
    result, out, v = cam_run
    assert result.exit_code == 0, result.output
    plain = md_plain(out / "report.md")
    pdf_all = pdf_text(out / "report.pdf")
    title_page = pdf_text(out / "report.pdf", 1, 1)
    docx = docx_paragraphs(out / "report.docx")
    for label in v["labels"]:
        # the label heads a paragraph, table columns and verification rows
        assert plain.count(label) >= 3, label
        assert pdf_all.count(squeeze(label)) >= 3, label
        assert docx.count(label) >= 3, label
    for key in ("title", "subtitle", "student", "student_id", "class", "teacher", "date"):
        assert squeeze(v[key]) in title_page, key
        assert v[key] in docx, key
    group_line = plain.splitlines()[0]
    assert v["group"] in group_line                 # the banner atop the report
    assert squeeze(v["group"]) in title_page
    assert v["group"] in docx
    doc = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert doc["data_group"] == v["group"]
    assert [f["label"] for f in doc["followers"]] == v["labels"]


@pytest.mark.e2e
@needs_pdf
def test_hostile_linkage_names_render_literally(tmp_path):
    brief, v = hostile_linkage_brief(tmp_path)
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["run", str(brief), "-o", str(out), "-f", "md,pdf,docx",
                                      "--lang", "en"])
    assert result.exit_code == 0, result.output
    plain = md_plain(out / "report.md")
    pdf_all = pdf_text(out / "report.pdf")
    docx = docx_paragraphs(out / "report.docx")
    assert v["title"] in plain                      # "**Task:** {{ meta.title }}"
    for name in v["names"]:                         # group table and quality table
        assert plain.count(name) >= 2, name
        assert pdf_all.count(squeeze(name)) >= 2, name
        assert docx.count(name) >= 2, name
    # frame / group tables as written; a point name is set in math, which pandoc's plain
    # text writes with its primes raised (C'' → C^(″))
    primes = plain.replace("^(″)", "''").replace("^(′)", "'")
    for point in v["points"]:
        assert re.search(rf"(^|\s){re.escape(point)}(\s|$)", primes, flags=re.M), point
    # reactions at the joints of link 4_ are F_{R34\_}, F_{R14\_} in formulas and figures
    # (raw, "R34_" would be a subscript without its argument: a LaTeX and mathtext error)
    md = (out / "report.md").read_text(encoding="utf-8")
    assert r"$F_{R34\_}$" in md and r"$F_{R14\_}$" in md
