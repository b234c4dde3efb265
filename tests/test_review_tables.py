"""Page review of session 28 (issue 19 points 4–5): the shaper's verification table has a
limit and a verdict column whose verdicts are the checks' own; a Chinese report names the
DXF layers by their GB/T 4457.4 line types, the layer name (which the DXF keeps) in
parentheses."""
from __future__ import annotations

import dataclasses
import re

import pytest

from mechdesign.render.fmt import Verdict
from tests.test_report_prose import _markdown

LAYERS = ("OUTLINE", "CENTER", "CONSTRUCTION", "DIMENSIONS", "TEXT", "VECTORS", "CURVES", "FRAME")


def _verify_table(md: str) -> list[list[str]]:
    block = md[md.index("{#tbl:verify}") - 2000: md.index("{#tbl:verify}")]
    rows = [ln for ln in block.splitlines() if ln.startswith("|")]
    start = max(i for i, ln in enumerate(rows) if re.match(r"\|\s*(Check|校核项目)\s*\|", ln))
    return [[c.strip() for c in ln.strip("|").split("|")] for ln in rows[start:]]


@pytest.mark.parametrize("name", ["shaper", "shaper_lengths"])
@pytest.mark.parametrize("lang", ["zh", "en"])
def test_shaper_verification_has_limit_and_verdict(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    head, _rule, *rows = _verify_table(md)
    assert head == (["Check", "Result", "Reference / limit", "Verdict"] if lang == "en"
                    else ["校核项目", "结果", "参考值 / 限值", "结论"])
    assert len(rows) == 6
    word = {"en": "PASS", "zh": "合格"}[lang]
    assert all(r[3] == word and r[2] for r in rows), rows


def test_shaper_verdicts_come_from_the_checks(example_results):
    """A residual over its limit turns that row, and only that row, to FAIL."""
    from mechdesign.machines.shaper import report
    from mechdesign.machines.shaper.stages import CLOSURE_LIMIT, self_checks

    r = example_results("shaper")
    v, syn = r["verification"], r["synthesis"]
    assert all(c.passed for c in self_checks(v, syn))
    bad = dataclasses.replace(v, closure_residual=10 * CLOSURE_LIMIT)
    rows = report._verify_rows(bad, syn, "en")
    assert [isinstance(row[3], Verdict) for row in rows] == [True] * 6
    assert [row[3].passed for row in rows] == [False, True, True, True, True, True]
    assert rows[0][3] == "FAIL" and rows[0][1] == "1.0 × 10⁻⁸"
    off = dataclasses.replace(v, time_ratio_simulated=syn.time_ratio + 1e-3)
    assert [row[3].passed for row in report._verify_rows(off, syn, "zh")] == [True] * 4 + [False, True]


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_layers_named_in_the_reports_language(lang):
    """The drawing-sheets section (every report with sheets includes it), where the run
    wrote DXF files (only then are their layers described)."""
    from mechdesign.render.report import render_markdown, sheets_context, template_dir
    from mechdesign.render.summary import Citations

    sheet = {"title": "A1", "size": "A1", "scale": "1:2", "files": "x.pdf", "preview": "", "label": "s"}
    md = render_markdown("sheets_section.md.j2", {**sheets_context([sheet], lang, dxf=True),
                                                  "cite": Citations(lang)}, template_dir(None), lang)
    for layer in LAYERS:
        found = re.findall(rf"(.)({layer})(.)", md)
        assert found, layer
        if lang == "zh":
            assert all(a == "（" and b == "）" for a, _l, b in found), (layer, found)
    if lang == "zh":
        for line_type in ("粗实线（OUTLINE）", "细点画线（CENTER）", "细实线（CONSTRUCTION）"):
            assert line_type in md


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_drawing_list_names_drawings_not_files(lang):
    """Review 34: the 说明书's table of drawings listed file names
    (``sheets/kinematic_A3.pdf``); a design report names a drawing by its title, size and
    scale (机构运动简图, A3, 1:5), the files are the hand-in's."""
    from mechdesign.render.report import _sheet_row, render_markdown, sheets_context, template_dir
    from mechdesign.render.summary import Citations

    class Sheet:
        name, title, size, scale, preview = "kinematic", "机构运动简图", "A3", "1:5", "figures/k.png"
        pdf, dxf = "sheets/kinematic_A3.pdf", "sheets/kinematic_A3.dxf"

    md = render_markdown("sheets_section.md.j2", {**sheets_context([_sheet_row(Sheet, lang)], lang),
                                                  "cite": Citations(lang)}, template_dir(None), lang)
    rows = [line for line in md.splitlines() if line.startswith("|")]
    assert rows and "| 机构运动简图 | A3 | 1:5 |" in rows
    assert not re.search(r"\.pdf|\.dxf|sheets/", "\n".join(rows))
