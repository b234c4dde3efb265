"""A class table (groups from a CSV or XLSX file next to the brief: brief/class_table.py),
the batch index's students and the answer table (``batch --answers``).

References are independent of the code under test: the CSV read with the csv module, the
same groups written inline by hand or into an XLSX with openpyxl, the crank and guide-bar
lengths of the guide-bar synthesis by hand (θ = 180°(K − 1)/(K + 1), r = L_O2O3·sin(θ/2),
L_O3B = H / (2 sin(θ/2))), messages against the file's lines as written.
"""
from __future__ import annotations

import csv
import json
import math
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.batch import Job, answers_document, answers_markdown, index_document, index_markdown
from mechdesign.brief.class_table import cell_value, target_types
from mechdesign.brief.loader import BriefError, brief_groups, load_variant
from mechdesign.cli import app
from mechdesign.machines import get_machine
from mechdesign.machines.shaper.brief import ShaperBrief
from conftest import read_pdf_text

ROOT = Path(__file__).resolve().parents[1]
CLASS = ROOT / "designs" / "class"
runner = CliRunner()


def _rows() -> list[list[str]]:
    with open(CLASS / "class.csv", encoding="utf-8", newline="") as f:
        return list(csv.reader(f))


def _brief(tmp_path: Path, table: str, text: str | None = None, **groups) -> Path:
    """designs/class/class.yaml copied into tmp_path with ``groups: {file: table}``; the
    table's text ``text`` written next to it when given."""
    data = yaml.safe_load((CLASS / "class.yaml").read_text(encoding="utf-8"))
    data["groups"] = {"file": table, **groups}
    path = tmp_path / "class.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True, sort_keys=False), encoding="utf-8")
    if text is not None:
        (tmp_path / table).write_text(text, encoding="utf-8")
    return path


def _xlsx(path: Path, rows: list[list]) -> None:
    import openpyxl

    book = openpyxl.Workbook()
    sheet = book.active
    sheet.title = "class"
    for row in rows:
        sheet.append(row)
    book.save(path)


def _typed(text: str):
    """A cell as a spreadsheet stores it: digits as an int, a decimal as a float."""
    if text == "":
        return None
    try:
        return int(text)
    except ValueError:
        try:
            return float(text)
        except ValueError:
            return text


# ------------------------------------------------------------------------ reading the table
def test_the_example_has_six_students_with_their_data():
    rows = _rows()
    header, body = rows[0], rows[1:]
    assert len(body) == 6 and brief_groups(CLASS / "class.yaml") == tuple(r[0] for r in body)
    col = {name: i for i, name in enumerate(header)}
    for row in body:
        b = load_variant(CLASS / "class.yaml", row[0]).brief
        assert b.report.student == row[col["report.student"]]
        assert b.report.student_id == row[col["report.student_id"]]      # text, digits kept
        assert b.linkage.stroke_H_mm == float(row[col["linkage.stroke_H_mm"]])
        assert b.linkage.time_ratio_K == float(row[col["linkage.time_ratio_K"]])
        ram = row[col["masses.ram_m6_kg"]]
        assert b.masses.ram_m6_kg == (float(ram) if ram else 68)        # empty cell: the brief's
    assert len({tuple(r[3:8]) for r in body}) == 6                      # six different data sets


def test_csv_and_xlsx_give_identical_groups(tmp_path):
    rows = _rows()
    (tmp_path / "c").mkdir()
    (tmp_path / "x").mkdir()
    csv_brief = _brief(tmp_path / "c", "class.csv", (CLASS / "class.csv").read_text(encoding="utf-8"))
    # in the workbook numbers are numbers (the student number too) and the note is text
    _xlsx(tmp_path / "x" / "class.xlsx", [rows[0]] + [[_typed(c) for c in r] for r in rows[1:]])
    xlsx_brief = _brief(tmp_path / "x", "class.xlsx", sheet="class")
    labels = brief_groups(csv_brief)
    assert labels == brief_groups(xlsx_brief) == tuple(r[0] for r in rows[1:])
    for label in labels:
        a, b = load_variant(csv_brief, label), load_variant(xlsx_brief, label)
        assert a.brief == b.brief
        assert a.brief.report.student_id == b.brief.report.student_id == \
            next(r[2] for r in rows[1:] if r[0] == label)


def test_a_class_table_equals_the_same_groups_written_inline(tmp_path):
    """Every row gives the same validated brief and SI parameters as the inline group
    written by hand from the row."""
    rows = _rows()
    header = rows[0]
    inline = yaml.safe_load((CLASS / "class.yaml").read_text(encoding="utf-8"))
    variants = {}
    for row in rows[1:]:
        variants[row[0]] = {h: _typed(c) for h, c in zip(header[1:], row[1:])
                            if c != "" and not h.startswith("#")}
        variants[row[0]]["report.student_id"] = row[2]
    inline["groups"] = {"default": 1, "variants": variants}
    path = tmp_path / "inline.yaml"
    path.write_text(yaml.safe_dump(inline, allow_unicode=True), encoding="utf-8")
    shaper = get_machine("shaper")
    for row in rows[1:]:
        a, b = load_variant(CLASS / "class.yaml", row[0]), load_variant(path, row[0])
        assert a.brief == b.brief
        assert shaper.to_params(a.brief) == shaper.to_params(b.brief)


@pytest.mark.parametrize("text, types, expected", [
    ("300", [float], 300), ("1.25", [float], 1.25), ("7.0e4", [float], 7.0e4),
    ("-5", [float], -5), ("true", [bool], True), ("1/25", [float, str], "1/25"),
    ("", [float], None), ("  ", [str], None), ("0123", [str], "0123"), ("2101", [str], "2101"),
    (2023010101, [str], "2023010101"), (300.0, [float], 300.0), ("auto", [float, str], "auto")])
def test_cells_read_as_yaml_would_and_text_fields_keep_their_text(text, types, expected):
    value = cell_value(text, types)
    assert value == expected and type(value) is type(expected)


def test_target_types_follow_the_brief_model():
    assert target_types(ShaperBrief, "report.class") == [str]
    # Optional since the link-length form (issue 18): None is "not given", never a cell
    assert [t for t in target_types(ShaperBrief, "linkage.stroke_H_mm") if t is not type(None)] == [float]
    assert target_types(ShaperBrief, "linkage") is None          # a section, not a value
    assert target_types(ShaperBrief, "linkage.stroke_mm") is None


# ------------------------------------------------------------------------ messages
HEAD = "group,report.student,report.student_id,linkage.stroke_H_mm,linkage.time_ratio_K\n"


def _problems(path: Path) -> list[str]:
    with pytest.raises(BriefError) as info:
        for label in brief_groups(path) or (None,):
            load_variant(path, label)
    return [str(p) for p in info.value.problems]


@pytest.mark.parametrize("table, text, expected", [
    ("missing.csv", None, ["groups.file: 'missing.csv' — no such file next to the brief"]),
    ("class.ods", "x", ["groups.file: 'class.ods' — a .csv or .xlsx file"]),
    ("c.csv", "report.student,linkage.stroke_H_mm\n王,300\n",
     ["c.csv line 1: columns report.student, linkage.stroke_H_mm — a column named `group`"]),
    ("c.csv", HEAD.replace("linkage.stroke_H_mm", "linkage.stroke_H") + "1,王,1,300,1.2\n",
     ["c.csv line 1, column linkage.stroke_H: not a field of the brief — a column is a dotted "
      "path to one value of the brief; nearest: linkage.stroke_H_mm"]),
    ("c.csv", HEAD.replace("linkage.stroke_H_mm", "stroke_H_mm") + "1,王,1,300,1.2\n",
     ["c.csv line 1, column stroke_H_mm: not a field of the brief — a column is a dotted path "
      "to one value of the brief; nearest: linkage.stroke_H_mm"]),
    ("c.csv", HEAD + "1,王,1,300,1.2\n2,李,2,310,1.3\n1,赵,3,320,1.4\n",
     ["c.csv line 4, column group: '1' — labels must be unique (also on line 2)"]),
    ("c.csv", HEAD + "1,王,1,300,1.2\n,李,2,310,1.3\n",
     ["c.csv line 3, column group: empty — every row needs its group label"]),
    ("c.csv", HEAD + "1,王,1,300,1.2,9\n", ["c.csv line 2: 6 cells — at most 5"]),
    ("c.csv", HEAD + "1,王,1,300 mm,1.2\n",
     ["c.csv line 2 (group 1), column linkage.stroke_H_mm: '300 mm' — a number in mm, "
      "without the unit: write 300"]),
    ("c.csv", HEAD + "1,王,1,300,1.2\n2,李,2,-5,1.2\n",
     ["c.csv line 3 (group 2), column linkage.stroke_H_mm: -5 — must be greater than 0"]),
    ("c.csv", HEAD + '1,王,1,300,1.2\n"2\nb",李,2,310,1.2\n3,赵,3,320,0.9\n',
     ["c.csv line 5 (group 3), column linkage.time_ratio_K: 0.9 — must be greater than 1"]),
])
def test_bad_files_columns_rows_and_cells_are_named(tmp_path, table, text, expected):
    lines = _problems(_brief(tmp_path, table, text))
    assert len(lines) == len(expected), lines
    for line, start in zip(lines, expected):
        assert line.startswith(start), line


@pytest.mark.parametrize("default", [{}, {"default": 1}])
def test_every_bad_cell_of_every_row_is_reported_by_check(tmp_path, default):
    path = _brief(tmp_path, "c.csv", HEAD + "1,王,1,-300,1.2\n2,李,2,310,abc\n3,赵,3,320,1.3\n",
                  **default)
    result = runner.invoke(app, ["check", str(path), "--lang", "en"])
    assert result.exit_code == 2 and "Traceback" not in result.output
    assert result.output.count("c.csv line 2 (group 1), column linkage.stroke_H_mm: -300") == 1
    assert "c.csv line 3 (group 2), column linkage.time_ratio_K: 'abc'" in result.output
    assert "1 of 1 brief invalid" in result.output
    result = runner.invoke(app, ["run", str(path), "--group", "2", "--out", str(tmp_path / "o")])
    assert result.exit_code == 2 and "c.csv line 3 (group 2), column linkage.time_ratio_K" in result.output
    assert not (tmp_path / "o").exists()


def test_xlsx_problems_name_the_row_and_an_unknown_sheet(tmp_path):
    _xlsx(tmp_path / "c.xlsx", [HEAD.strip().split(","), [1, "王", 1, 300, 1.2], [2, "李", 2, 0, 1.2]])
    lines = _problems(_brief(tmp_path, "c.xlsx"))
    assert lines == ["c.xlsx row 3 (group 2), column linkage.stroke_H_mm: 0 — must be "
                     "greater than 0 (Ram stroke H [mm] (synthesis form, with time_ratio_K))"]
    assert _problems(_brief(tmp_path, "c.xlsx", sheet="Tabelle1"))[0].startswith(
        "groups.sheet: 'Tabelle1' — one of the sheets of c.xlsx: class")


def test_a_gbk_csv_from_excel_and_notes_columns(tmp_path):
    path = _brief(tmp_path, "c.csv")
    (tmp_path / "c.csv").write_bytes(("group;report.student;# 备注\n1;王芳;补交\n").encode("gb18030"))
    v = load_variant(path, "1")
    assert v.brief.report.student == "王芳"


def test_check_of_a_class_table_imports_no_numpy(tmp_path):
    """`mechdesign check` of the class example (CSV) and of an XLSX table in a fresh
    interpreter: every row validated, numpy never imported (openpyxl would import it)."""
    rows = _rows()
    _xlsx(tmp_path / "class.xlsx", [rows[0]] + [[_typed(c) for c in r] for r in rows[1:]])
    xlsx_brief = _brief(tmp_path, "class.xlsx")
    script = r"""
import sys
from typer.testing import CliRunner
from mechdesign.cli import app
for path in sys.argv[1:]:
    result = CliRunner().invoke(app, ["check", path])
    assert result.exit_code == 0 and "groups 1, 2, 3, 4, 5, 6" in result.output, result.output
assert "numpy" not in sys.modules and "openpyxl" in sys.modules
print("ok")
"""
    out = subprocess.run([sys.executable, "-c", script, str(CLASS / "class.yaml"), str(xlsx_brief)],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0 and out.stdout.strip() == "ok", out.stderr[-2000:]


# ------------------------------------------------------------------------ index and answers
def _fake_index():
    jobs = [Job("c.yaml", "1", "c-g1"), Job("c.yaml", "2", "c-g2"), Job("d.yaml", None, "d")]
    results = [
        {"status": "ok", "exit_code": 0, "group": "1", "machine": "shaper", "files": (),
         "summary": (("crank [mm]", "92.5"), ("K", "1.2")), "student": ("张伟", "2023010101", "A")},
        {"status": "invalid", "exit_code": 2, "group": "2", "machine": "", "files": (),
         "message": "bad", "student": ("王芳", "2023010102", "A")},
        {"status": "ok", "exit_code": 0, "group": None, "machine": "cam", "files": (),
         "summary": (("r0 [mm]", "40"),), "student": ("", "", "")}]
    return index_document(jobs, results, Path("."))


def test_the_index_lists_each_groups_student():
    md = index_markdown(_fake_index(), "en")
    rows = [line for line in md.splitlines() if line.startswith("| ")][1:]
    assert "| 张伟 (2023010101) |" in rows[0] and "| 王芳 (2023010102) |" in rows[1]
    assert "| — |" in rows[2]


def test_the_answer_table_has_one_row_per_group_with_the_names():
    doc = answers_document(_fake_index())
    assert doc["columns"] == ["crank [mm]", "K", "r0 [mm]"]
    assert [(r["group"], r["name"], r["number"]) for r in doc["rows"]] == [
        ("1", "张伟", "2023010101"), ("2", "王芳", "2023010102"), (None, "", "")]
    md = answers_markdown(doc, "en").splitlines()
    assert md[-3].startswith("| 1 | 张伟 | 2023010101 | A | c.yaml | ✓ | 92.5 | 1.2 | — |")
    assert md[-2].startswith("| 2 | 王芳 | 2023010102 | A | c.yaml | ✗ invalid | — | — | — |")


@pytest.mark.e2e
def test_batch_of_the_class_writes_the_answer_table(tmp_path):
    """`batch designs/class/ --answers`: six reports, the index and the answer table name
    every student; group 4's crank and guide bar are the synthesis by hand from its row
    (H = 440 mm, K = 1.4, L_O2O3 = 650 mm); an unrelated file in the output folder stays."""
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("mine", encoding="utf-8")
    result = runner.invoke(app, ["batch", str(CLASS), "--answers", "-o", str(out), "-f", "md,pdf",
                                 "--jobs", "2"])
    assert result.exit_code == 0, result.output
    rows = _rows()[1:]
    with open(out / "answers.csv", encoding="utf-8-sig", newline="") as f:
        table = list(csv.reader(f))
    assert [r[:3] for r in table[1:]] == [r[:3] for r in rows]          # group, name, number
    md = (out / "answers.md").read_text(encoding="utf-8")
    index = (out / "index.md").read_text(encoding="utf-8")
    for row in rows:
        assert f"| {row[0]} | {row[1]} | {row[2]} |" in md
        assert f"| {row[1]} ({row[2]}) |" in index
    assert (out / "notes.txt").read_text(encoding="utf-8") == "mine"
    doc = json.loads((out / "class-g4" / "results.json").read_text(encoding="utf-8"))
    theta = math.pi * (1.4 - 1) / (1.4 + 1)                              # 30°
    assert doc["data_group"] == "4"
    assert abs(doc["synthesis"]["crank"] - 0.650 * math.sin(theta / 2)) < 1e-9      # 168.24 mm
    assert abs(doc["synthesis"]["guide_bar"] - 0.440 / (2 * math.sin(theta / 2))) < 1e-9
    for pdf, page in (("report.pdf", 1), ("sheets/analysis_A1.pdf", 1)):   # the title page and the A1 sheet's title block name 刘洋
        text = read_pdf_text(out / "class-g4" / pdf, page, page)
        assert rows[3][1] in text and rows[3][2] in text, pdf
    col = table[0].index("曲柄 [mm]")
    assert table[4][col] == f"{650 * math.sin(theta / 2):.4g}"
