"""The hand-in's closing chapters (issue 19, point 7): every report ends with its 设计小结 /
Summary and 参考文献 / References; the lock-beam's with the appendix of its analysis
program.

The Markdown of every example brief is rendered in both languages from the session's
computed results (figures replaced by placeholder names: the text does not depend on the
pictures). The references are checked against the report's own citation markers (every
marker has its entry, every entry is cited, numbered in order of first citation); the
failed checks are found here, independently, by reading the results document, and each
must appear in the summary as failed; the lock-beam appendix must list the stages the
pipeline runs, in order. One end-to-end run checks the wiring through ``mechdesign run``.
"""
from __future__ import annotations

import collections
import json
import math
import re
import unicodedata
from pathlib import Path

import jinja2
import pytest

from mechdesign.brief.loader import load_brief
from mechdesign.i18n import tr
from mechdesign.machines import get_machine
from mechdesign.render.fmt import meta_text
from mechdesign.render.report import render_markdown, template_dir
from mechdesign.render.summary import Citations, handin_context, reference_text, references
from mechdesign.results import to_plain

ROOT = Path(__file__).resolve().parents[1]
DESIGNS = ROOT / "designs"
EXAMPLES = sorted(p.stem for p in DESIGNS.glob("*.yaml"))
LANGS = ("zh", "en")
TITLES = {"zh": ("设计小结", "参考文献", "附录"), "en": ("Summary", "References", "Appendix")}


def render(name: str, lang: str, results: dict, tmp: Path) -> tuple[str, dict]:
    """(Markdown, results document) of example ``name`` as ``mechdesign run`` writes them,
    with placeholder figure names and no sheets."""
    import importlib

    from mechdesign.runner import _with_requested

    brief = load_brief(DESIGNS / f"{name}.yaml")
    machine = get_machine(brief.machine)
    report = importlib.import_module(machine.report_module)
    document = to_plain(machine.document(results))
    tmp.mkdir(parents=True, exist_ok=True)
    figs = collections.defaultdict(lambda: "figures/placeholder.png")
    try:
        ctx = _with_requested(report.context(results, brief, figs, lang), results, brief, figs, lang)
        ctx["sheets"] = []
        trial = dict(ctx)
        trial.update(handin_context(machine.name, document, trial, lang, brief.report.title),
                     cite=Citations(lang))
        render_markdown(f"{machine.name}.md.j2", trial, template_dir(), lang)
    except (jinja2.UndefinedError, KeyError):
        # a report that picks its figures by name prefix: draw them
        from mechdesign.runner import _with_requested_figures

        figs = _with_requested_figures(report, results, tmp, lang)
        ctx = _with_requested(report.context(results, brief, figs, lang), results, brief, figs, lang)
    ctx["sheets"] = []
    program = report.program_appendix(results) if hasattr(report, "program_appendix") else None
    ctx.update(handin_context(machine.name, document, ctx, lang,
                              meta_text(brief.report, "title", lang), program, tmp),
               cite=Citations(lang))
    md = render_markdown(f"{machine.name}.md.j2", ctx, template_dir(), lang)
    return md, document


def headings(md: str) -> list[str]:
    """Level-1 headings outside fenced code (a listing holds Python comments)."""
    out, fenced = [], False
    for line in md.splitlines():
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and line.startswith("# "):
            # without the heading's attributes ({-}, {#summary})
            out.append(re.sub(r"\s*\{[^}]*\}\s*$", "", line[2:]).strip())
    return out


def section(md: str, title: str) -> str:
    """The text of the level-1 section whose heading starts with ``title``."""
    lines, inside, fenced = [], False, False
    for line in md.splitlines():
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and line.startswith("# "):
            inside = line[2:].startswith(title)
            continue
        if inside:
            lines.append(line)
    return "\n".join(lines)


def failed_checks(document) -> list[dict]:
    """Every check of the results with a verdict that failed: a dict with ``passed`` or
    ``ok`` False (read here independently of render/summary.py)."""
    found = []

    def walk(node):
        if isinstance(node, dict):
            if node.get("passed") is False or node.get("ok") is False:
                found.append(node)
            for v in node.values():
                walk(v)
        elif isinstance(node, list):
            for v in node:
                walk(v)

    walk(json.loads(json.dumps(document)))
    # the same check recorded twice (a shaft's governing check is also in its list) is one
    return list({json.dumps(c, sort_keys=True): c for c in found}.values())


def all_checks(document) -> int:
    """The number of distinct checks with a verdict in the results."""
    seen = set()

    def walk(node):
        if isinstance(node, dict):
            # a cam's dwell records ok with no limit: nothing checked (session 40)
            dwell = "limit" in node and node["limit"] is None and node.get("kind") == "dwell"
            if (isinstance(node.get("passed"), bool) or isinstance(node.get("ok"), bool)) and not dwell:
                seen.add(json.dumps(node, sort_keys=True))
            for v in node.values():
                walk(v)
        elif isinstance(node, list):
            for v in node:
                walk(v)

    walk(json.loads(json.dumps(document)))
    return len(seen)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", EXAMPLES)
def test_every_report_ends_with_summary_then_references(handin_reports, name, lang):
    md, _ = handin_reports(name, lang)
    heads = headings(md)
    summary, refs, appendix = TITLES[lang]
    tail = heads[-3:] if heads[-1].startswith(appendix) else heads[-2:] + [None]
    assert tail[0] == summary and tail[1] == refs, heads[-4:]
    assert heads.count(summary) == 1 and heads.count(refs) == 1
    # the appendix only where the machine's seed hands in its program (the lock-beam)
    assert (tail[2] is not None) == (get_machine(load_brief(DESIGNS / f"{name}.yaml").machine).name
                                     == "lockbeam")


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", EXAMPLES)
def test_every_failed_check_is_named_failed_in_the_summary(handin_reports, name, lang):
    md, document = handin_reports(name, lang)
    text = section(md, TITLES[lang][0])
    fail_word, pass_word = ("不合格", "合格") if lang == "zh" else ("FAIL", "PASS")
    rows = [r for r in text.splitlines() if r.startswith("| ") and (fail_word in r or pass_word in r)]
    failed_rows = [r for r in rows if fail_word in r]
    failed = failed_checks(document)
    # every verdict of the results is counted in the summary's table
    assert sum(int(r.split("|")[2]) for r in rows) >= all_checks(document)
    for c in failed:
        name_ = c.get("name_zh" if lang == "zh" else "name_en")
        if "name_args" in c:                 # a strength check: an English msgid and its fields
            from mechdesign.stages.findings import check_name   # (a data-table name as {table, key})

            name_ = check_name(c).text(lang)
        if name_:
            assert any(name_ in r for r in failed_rows), (name_, failed_rows)
    assert len(failed_rows) >= (1 if failed else 0)
    # the count stated in the text is the number of failed names in the table
    listed = sum(len(re.split("、|, ", r.split(fail_word, 1)[1].lstrip("：: ").rstrip(" |")))
                 for r in failed_rows)
    stated = re.search(r"(\d+) 项不合格" if lang == "zh" else r"of which (\d+) failed", text)
    if failed_rows:
        assert int(stated.group(1)) == listed >= len(failed)
    elif rows:
        assert stated is None and ("项校核，全部合格" in text or "checks; all passed" in text)
    else:   # no check with a verdict in the results (the shaper's self-checks are values)
        assert all_checks(document) == 0
        assert "没有给出合格/不合格结论" in text or "no check with a verdict" in text
    if failed_rows:
        assert ("设计者应注意" in text) or ("should watch" in text)
    elif rows and (("设计者应注意" in text) or ("should watch" in text)):
        # every check passed, yet the run found problems no check covers (e.g. an undercut
        # gear pair's finding): "all passed" must not stand alone
        assert "不在这些校核之内" in text or "outside these checks" in text, text
    # one verdict vocabulary: no other verdict words in the summary's table
    for word in ("满足", "✓", "fails", " ok "):
        assert not any(word in r for r in rows)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", EXAMPLES)
def test_every_citation_has_its_entry_and_every_entry_is_cited(handin_reports, name, lang):
    md, _ = handin_reports(name, lang)
    refs_title = TITLES[lang][1]
    body, _, rest = md.partition(f"# {refs_title} {{-}}")
    listing = rest.split("\n# ", 1)[0]
    entries = re.findall(r"^\\\[(\d+)\\\] (.+)$", listing, flags=re.M)
    numbers = [int(n) for n, _ in entries]
    assert numbers == list(range(1, len(numbers) + 1)) and numbers, listing
    cited = []
    for group in re.findall(r"\\\[(\d+(?:, \d+)*)\\\]", body):
        cited += [int(n) for n in group.split(", ")]
    assert set(cited) == set(numbers)
    # numbered in order of first citation
    first = list(dict.fromkeys(cited))
    assert first == sorted(first)
    # every entry is a source of the data file, in the report's language, and a textbook
    # (孙桓 for every mechanism, 濮良贵 for a drive) is among them
    known = {reference_text(key, lang) for key in references()}
    texts = [t.replace("\\[", "[").replace("\\]", "]") for _, t in entries]
    assert all(t in known for t in texts), texts
    # every entry begins with its data file's text in the report's language
    assert all(any(t.startswith(v["zh" if lang == "zh" else "en"]) for v in references().values())
               for t in texts)
    assert any("[M]" in t for t in texts)


def appendix_listing(md: str, lang: str) -> str:
    """The program listed in the appendix, as the report prints it."""
    text = section(md, TITLES[lang][2])
    return text.split("```python\n", 1)[1].rsplit("```", 1)[0]


def table_rows(md: str, label: str) -> list[list[str]]:
    """The cells of the body rows of the Markdown table captioned ``{#label}``."""
    lines = md.splitlines()
    end = next(i for i, line in enumerate(lines) if line.startswith(": ") and f"{{#{label}}}" in line)
    start = end - 1
    while not lines[start].startswith("|"):
        start -= 1
    while start > 0 and lines[start - 1].startswith("|"):
        start -= 1
    rows = [line for line in lines[start:end] if line.startswith("|")][2:]
    return [[c.strip() for c in row.strip().strip("|").split("|")] for row in rows]


@pytest.mark.parametrize("lang", LANGS)
def test_lockbeam_appendix_program_runs_and_prints_the_feed_table(handin_reports, lang, tmp_path):
    """Issue 19 point 7 (review34 B): the appendix listed 12 pages of the tool's own stages
    module (imports of the package, English warnings, wrapped lines): no program a student
    hands in, and nothing that runs from the listing. The listing is a self-contained program
    (Python with numpy only) that, saved as printed and run, prints the report's feed table in
    the seed's format, to its printed digits; its input data are the brief's numbers."""
    import ast
    import subprocess
    import sys

    import yaml

    md, document = handin_reports("lockbeam", lang)
    listing = appendix_listing(md, lang)
    lines = listing.splitlines()
    assert 50 <= len(lines) <= 200
    # numpy and nothing else
    tree = ast.parse(listing)
    imported = {a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names}
    assert imported == {"numpy"} and not any(isinstance(n, ast.ImportFrom) for n in ast.walk(tree))
    # the input constants are the brief's numbers (read from the brief itself, in m)
    raw = yaml.safe_load((DESIGNS / "lockbeam.yaml").read_text(encoding="utf-8"))["feed_linkage"]
    consts = {t.id: ast.literal_eval(n.value) for n in tree.body if isinstance(n, ast.Assign)
              for t in n.targets if isinstance(t, ast.Name) and isinstance(n.value, ast.Constant)}
    pairs = {n.targets[0].elts[0].id: ast.literal_eval(n.value) for n in tree.body
             if isinstance(n, ast.Assign) and isinstance(n.targets[0], ast.Tuple)}
    rrp = next(g for g in raw["groups"] if g["type"] == "RRP")
    bar = next(g for g in raw["groups"] if g.get("name") == "D")
    same = lambda x: pytest.approx(x, rel=1e-12, abs=1e-15)     # noqa: E731
    assert consts["N1"] == same(raw["crank"]["speed_rpm"])
    assert consts["L2"] == same(raw["crank"]["length_mm"] / 1000)
    assert consts["L4"] == same(bar["distance_mm"] / 1000)
    assert consts["L5"] == same(rrp["length_mm"] / 1000)
    assert consts["YE"] == same(rrp["guide_point_mm"][1] / 1000)
    assert pairs["XO2"] == same(tuple(v / 1000 for v in raw["frame_points_mm"]["O2"]))
    assert pairs["XO3"] == same(tuple(v / 1000 for v in raw["frame_points_mm"]["O3"]))
    # run as printed
    path = tmp_path / "feed.py"
    path.write_text(listing, encoding="utf-8")
    out = subprocess.run([sys.executable, str(path)], capture_output=True, text=True,
                         timeout=120, cwd=tmp_path, check=True).stdout
    printed = [line.split() for line in out.splitlines()[2:]]      # after the header
    table = table_rows(md, "tbl:feed-seed")
    assert len(printed) == len(table) == 36
    # the report's table (its first eight columns), digit for digit
    assert printed == [row[:8] for row in table]
    # and results.json's values, to the printed digits
    ft = document["feed_table"]
    keys = ("x", "v", "a", "bar_omega", "rod_omega", "bar_alpha", "rod_alpha")
    for i, row in enumerate(printed):
        assert float(row[0]) == pytest.approx(math.degrees(ft["crank_angle"][i]), abs=1e-9)
        for j, key in enumerate(keys, 1):
            scale, digits = (1000, 2) if key == "x" else (1, 4)
            assert abs(float(row[j]) - ft[key][i] * scale) <= 0.5 * 10 ** -digits + 1e-12


@pytest.mark.parametrize("lang", LANGS)
def test_lockbeam_appendix_is_written_in_the_reports_language(handin_reports, lang):
    """The listing's comments are in the report's language (the code is ASCII), every line fits
    the 80 columns of the text block (a CJK character taking two), and the steps table names
    the program's steps in words, with no identifier of the tool (pin_check, feed_table)."""
    md, _ = handin_reports("lockbeam", lang)
    listing = appendix_listing(md, lang)
    cjk = re.compile(r"[\u3000-\u9fff\uff00-\uffef]")
    comments = [line.split("#", 1)[1] for line in listing.splitlines() if line.lstrip().startswith("#")]
    assert len(comments) >= 10
    assert all(bool(cjk.search(c)) == (lang == "zh") for c in comments)
    code = [line for line in listing.splitlines() if not line.lstrip().startswith("#")]
    assert not any(cjk.search(line) for line in code)
    width = [sum(2 if unicodedata.east_asian_width(ch) in "WF" else 1 for ch in line)
             for line in listing.splitlines()]
    assert max(width) <= 80
    rows = table_rows(md, "tbl:program-steps")
    assert [r[0] for r in rows] == [str(i) for i in range(1, len(rows) + 1)] and len(rows) >= 5
    text = section(md, TITLES[lang][2]).split("```")[0]
    assert "`" not in text
    for key in ("pin_check", "feed_table", "feed_model", "bending_cam", "transmission"):
        assert key not in text
    if lang == "zh":
        assert all(cjk.search(r[1]) and cjk.search(r[2]) for r in rows)


def test_summary_key_numbers_of_the_shaper(handin_reports):
    """The shaper's key numbers: θ = 180°(K − 1)/(K + 1) by hand from the brief's K = 1.2,
    the stroke as given (320 mm), each by its quantity's rule (0.01°, 0.01 mm; issue 19)."""
    md, _ = handin_reports("shaper", "zh")
    text = section(md, "设计小结")
    theta = 180 * (1.2 - 1) / (1.2 + 1)
    assert f"| 极位夹角 $\\theta$ | {theta:.2f} | ° |" in text
    assert "| 行程 | 320.00 | mm |" in text


@pytest.mark.e2e
def test_run_writes_summary_and_references(tmp_path):
    """The wiring through ``mechdesign run``: the written report ends with both chapters and
    cites the course's textbook."""
    from mechdesign.runner import run_one

    out = run_one(DESIGNS / "cam_7_1.yaml", out_dir=tmp_path / "r", lang="en", formats=("md",))
    assert out.exit_code == 0, out.message
    md = (tmp_path / "r" / "report.md").read_text(encoding="utf-8")
    assert headings(md)[-2:] == ["Summary", "References"]
    assert "SUN Huan, CHEN Zuomo, GE Wenjie" in md


def test_a_rocking_outputs_stroke_is_summarised_as_its_swing_in_degrees():
    """The summary's stroke row: metres → mm for a slider, rad → ° (labelled as the swing)
    for a rocker; a peak torque of 0 (no load given) is not listed."""
    import math

    from mechdesign.machines.summary import summary_rows
    from mechdesign.registry import shown_row

    row = ("stroke", "mm", "linkage.output.stroke", 1e3)
    rocker = {"linkage": {"output": {"unit": "rad", "stroke": math.radians(30.0)}}}
    slider = {"linkage": {"output": {"unit": "m", "stroke": 0.25}}}
    label, unit, factor, value = shown_row(row, "en", rocker)
    assert (label, unit) == ("swing of the output", "°")
    assert value * factor == pytest.approx(30.0)
    assert shown_row(row, "en", slider) == ("stroke", "mm", 1e3, 0.25)
    assert shown_row(row, "zh", rocker)[0] == "输出构件摆角"
    rows = dict(summary_rows("linkage", {"linkage": {**rocker["linkage"], "peak_torque": 0.0,
                                                     "mean_torque": 12.5}}, "en"))
    assert rows["swing of the output [°]"] == "30"
    assert "peak balancing torque [N·m]" not in rows and rows["mean balancing torque [N·m]"] == "12.5"


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", EXAMPLES)
def test_every_verdict_cell_is_pass_or_fail(handin_reports, name, lang):
    """Issue 19 point 4: one verdict vocabulary. A table with a verdict column holds only
    合格/不合格 (PASS/FAIL) in it; an item without a verdict belongs in the text, not in the
    table (cam 7-3's plain offset curve was "0.110 mm | ≤ 0.001 mm | 已按包络修正")."""
    md, _ = handin_reports(name, lang)
    allowed = {"合格", "不合格"} if lang == "zh" else {"PASS", "FAIL"}
    header, bad = None, []
    for line in md.splitlines():
        if not line.startswith("|"):
            header = None
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if header is None:
            header = cells
        elif not set(line) <= set("|:- ") and header[-1] in ("结论", "Verdict"):
            # the summary's failed group names its failed checks after the verdict word
            # ("不合格：轴弯扭合成强度、…", "FAIL: Shaft bending–torsion strength, …")
            word = re.split(r"[：:]", cells[-1], maxsplit=1)[0].strip()
            if word not in allowed or (word != cells[-1] and word not in ("不合格", "FAIL")):
                bad.append(line)
    assert not bad, bad


@pytest.mark.parametrize("lang", LANGS)
def test_flow_chart_named_as_a_teacher_names_it(handin_reports, lang):
    """small34: the appendix's flow chart, its stage table and their introduction spoke of
    "the stages this run executed" (本次运行执行的阶段), as a program speaks of itself; they
    name the analysis program's flow chart and stages."""
    md, _ = handin_reports("lockbeam", lang)
    text = section(md, TITLES[lang][2])
    caption = {"zh": "![分析程序流程图]", "en": "![Flow chart of the analysis program]"}[lang]
    table = {"zh": ": 分析程序的计算步骤 {#tbl:program-steps}",
             "en": ": Steps of the analysis program {#tbl:program-steps}"}[lang]
    assert caption in text and table in text
    assert "本次运行" not in md and "this run" not in md
