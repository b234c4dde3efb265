"""One sign convention for the balancing torque M_b across the hand-in (review36 Top 13).

The A1 analysis sheet wrote M_b, its mean M_d and P_b counter-clockwise positive ("Signs: Mb,
Md and Pb counter-clockwise positive"), while the report's force tables and its M_b curve
take M_b positive in the crank's sense of rotation. For a clockwise crank (7 of the 8
linkage briefs with forces) the sheet and the report printed opposite signs at the same
positions (shaper pos. 12: 80.3 on the sheet, −80.3 in table 5). Now the sheet writes M_b,
M_d and P_b in the crank's sense, as the report, and says so once in its notes.

The report's graphical method keeps its moment equations counter-clockwise positive (the
polygons are drawn so) and converts: "M_b = −228 N·m (counter-clockwise positive; 228 N·m in
the crank's sense of rotation)"; its comparison table lists the latter.

Checked against: the report's own M_b table (read from its Markdown); the graphical method's
moment equation (counter-clockwise positive, a construction separate from the forces stage)
times the sign of ω; and the physics: the crank has to be driven, the mean input power
M_d·|ω| is positive, so the mean torque in the crank's sense is positive.
"""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from tests.test_report_prose import example_markdown

ROOT = Path(__file__).resolve().parents[1]
# every linkage brief whose analysis sheet has force polygons and an M_b curve
FORCED = ["shaper", "shaper_lengths", "slotter", "textbook_guide_bar", "press", "die_cutter",
          "furnace_pusher", "linkage_sixbar"]
_SHEETS: dict = {}
_MD: dict = {}


def _number(text: str) -> float:
    return float(re.sub(r"[\s\u00a0\u202f\u2009]", "", text).replace("\u2212", "-"))


def _decimals(text: str) -> int:
    digits = re.sub(r"[^\d.]", "", text)
    return len(digits.partition(".")[2])


def _label(text: str) -> str:
    return text.strip().replace("'", "′")


def _sheet(example_results, name: str, lang: str):
    if (name, lang) not in _SHEETS:
        from mechdesign.brief.loader import load_brief
        from mechdesign.render.sheet import Text, plain
        from mechdesign.render.sheets import _builders, title_info

        brief = load_brief(ROOT / "designs" / f"{name}.yaml")
        r = example_results(name)
        build = dict(_builders(r, brief))["analysis"]
        sheet = build(title_info(brief.report, "analysis", "MD-01", 1, 1, lang), lang)
        _SHEETS[name, lang] = [(plain(e.text), e.position) for e in sheet.entities
                               if isinstance(e, Text)]
    return _SHEETS[name, lang]


def _markdown(example_results, name: str, lang: str) -> str:
    if (name, lang) not in _MD:
        _MD[name, lang] = example_markdown(example_results(name), lang)
    return _MD[name, lang]


def _sheet_table(texts) -> dict[str, str]:
    """{position label: the M_b cell} of the sheet's table (at the sheet's left, under the
    skeleton; its last column is M_b): a row is a label first and more than four texts
    level with it (the skeleton's position numbers stand alone)."""
    out = {}
    left = [(t, p) for t, p in texts if p.real < 300.0]
    for label, at in left:
        if not re.fullmatch(r"\S{1,5}", label):
            continue
        row = sorted((p.real, t) for t, p in left if abs(p.imag - at.imag) < 0.1)
        if row[0][1] == label and len(row) > 4:
            assert _label(label) not in out, label
            out[_label(label)] = row[-1][1]
    return out


def _report_table(md: str) -> dict[str, str]:
    """{position label: M_b} of the report's force table: the first table whose last
    column is $M_b$ and whose first is the position."""
    lines = md.splitlines()
    for j, line in enumerate(lines):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("|") and cells[-1].startswith("$M_b$") and cells[0] in ("Pos.", "Position", "位置"):
            out = {}
            for row in lines[j + 2:]:
                if not row.startswith("|"):
                    break
                rc = [c.strip() for c in row.strip().strip("|").split("|")]
                out[_label(rc[0])] = rc[-1]
            return out
    raise AssertionError("no M_b table in the report")


def _same_rounded(a: str, b: str) -> bool:
    """Two printings of one value: within half a unit of the last digit of each."""
    tol = 0.5 * 10.0 ** -_decimals(a) + 0.5 * 10.0 ** -_decimals(b) + 1e-9
    return abs(_number(a) - _number(b)) <= tol and (np.sign(_number(a)) == np.sign(_number(b))
                                                    or min(abs(_number(a)), abs(_number(b))) <= tol)


@pytest.mark.parametrize("name", FORCED)
def test_the_sheet_writes_mb_as_the_report_table(example_results, name):
    """Every position's M_b on the sheet's table equals the report's force table, sign
    included (the shaper's sheet wrote 80.3 at pos. 12 where table 5 has −80.3)."""
    sheet = _sheet_table(_sheet(example_results, name, "en"))
    report = _report_table(_markdown(example_results, name, "en"))
    assert len(report) >= 12 and set(report) <= set(sheet), (sorted(report), sorted(sheet))
    for label, value in report.items():
        assert _same_rounded(sheet[label], value), (name, label, sheet[label], value)
    # a clockwise crank: at some position the two conventions would differ in sign
    found = example_results(name)
    from mechdesign.render.sheets import linkage_results

    if float(linkage_results(found).model.crank.omega) < 0:
        assert any(abs(_number(v)) > 0.05 for v in report.values())


@pytest.mark.parametrize("name", FORCED)
def test_the_crank_cell_and_the_mean_line_take_the_crank_sense(example_results, name):
    """The crank's force polygon cell: M_b as the table at its position, P_b = M_b/l with
    M_b's sign, and that sign is the graphical method's (its moment equation is
    counter-clockwise positive) times the sign of ω. The M_b curve's mean line M_d is
    positive: the crank is driven, the mean input power M_d·|ω| > 0."""
    from mechdesign.render.sheets import linkage_results

    texts = _sheet(example_results, name, "en")
    found = linkage_results(example_results(name))
    crank = found.model.crank
    sense = np.sign(crank.omega)
    table = _sheet_table(texts)
    mb_cells = sorted((p.real, t.split("=")[1].replace("N·m", "").strip()) for t, p in texts
                      if re.fullmatch(r"Mb = [−\d.\s]+ N·m", t))
    pb_cells = sorted((p.real, _number(t.split("=")[1].replace("N", ""))) for t, p in texts
                      if re.fullmatch(r"Pb = [−\d.\s]+ N", t))
    chosen = [str(c) for c in found.polygons.positions]
    assert len(mb_cells) == len(pb_cells) == len(chosen)
    graphical = {str(p.label): p for p in found.graphical.positions}
    for label, (_, mb_text), (_, pb_cell) in zip(chosen, mb_cells, pb_cells):
        assert _same_rounded(mb_text, table[_label(label)]), (name, label, mb_text)
        mb_cell = _number(mb_text)
        assert pb_cell == pytest.approx(mb_cell / crank.length, rel=3e-3), (name, label, pb_cell)
        ccw = [fg.balancing_torque for fg in graphical[label].forces
               if fg.balancing_torque is not None]
        assert ccw and np.sign(mb_cell) == sense * np.sign(ccw[0]), (name, label, mb_cell, ccw)
    md = [_number(m.group(1)) for t, _ in texts
          for m in [re.search(r"(?:driving torque Md|mean Mb) = (\S+) N·m", t)] if m]
    assert len(md) == 1 and md[0] > 0, (name, md)


@pytest.mark.parametrize("name, lang, words", [
    ("shaper", "en", "Signs: Mb, Md and Pb positive in the crank's sense of rotation, "
                     "MI counter-clockwise positive"),
    ("shaper", "zh", "符号：Mb、Md、Pb 以与曲柄转向相同为正，MI 以逆时针为正"),
    ("press", "en", "Signs: Mb, Md and Pb positive in the crank's sense of rotation, "
                    "MI counter-clockwise positive")])
def test_the_notes_state_the_convention_once(example_results, name, lang, words):
    texts = [t for t, _ in _sheet(example_results, name, lang)]
    assert texts.count(words) == 1
    assert not any(re.search(r"M.?b[^,，。]*(counter-clockwise|逆时针)", t) for t in texts if t != words)
