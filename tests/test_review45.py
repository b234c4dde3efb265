"""Page review of session 45 (issue 19): what the reviewers of the 28 PDFs found, mended.

- lockbeam_cam: the summary said "verified by 12 checks" with "cam pressure angle 2" while the
  cam chapter's check table holds four checks (the two pressure angles and the profile's two
  curvature checks, ρ_min > r_r and ρ_a ≥ 3 mm): the curvature checks were judged in the
  rendering and never counted. The cam stage now records them (``curvature_checks``), the
  chapter's table and the summary both read them.
- "max pressure angle, rise 2": a bare segment number glued to the name read as a typo; the
  number is written only where the kind repeats, as "(segment 2)".
"""
from __future__ import annotations

import re

import pytest

from test_handin import LANGS

# every example whose report has a cam chapter: its check table(s) and summary groups
CAMS = {"cam_7_3": ("cam-checks",), "die_cutter": ("cam-checks",), "lockbeam_cam": ("cam-checks",),
        "press": ("cam-checks",), "shaper": ("cam-checks",), "slotter": ("cam-checks",),
        "lockbeam": ("cam-checks", "bcam-checks")}
GROUPS = {"zh": ("凸轮机构", "定位凸轮", "扳弯凸轮"), "en": ("cam mechanism", "positioning cam", "bending cam")}


def _table_rows(md: str, label: str) -> list[str]:
    """The body rows of the pipe table captioned ``{#tbl:label}``."""
    lines = md.split("\n")
    at = next(i for i, line in enumerate(lines) if "{#tbl:%s}" % label in line)
    rows, i = [], at - 1
    while i >= 0 and not lines[i].startswith("|"):
        i -= 1
    while i >= 0 and lines[i].startswith("|"):
        rows.append(lines[i])
        i -= 1
    rows.reverse()
    return [r for r in rows[2:]]           # header and rule


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", sorted(CAMS))
def test_the_summary_counts_every_check_of_the_cam_table(handin_reports, name, lang):
    md, document = handin_reports(name, lang)
    in_tables = sum(len(_table_rows(md, label)) for label in CAMS[name])
    summary = md[md.index("{#summary}"):]
    counted = 0
    for group in GROUPS[lang]:
        row = re.search(rf"^\| {re.escape(group)} \| (\d+) \|", summary, flags=re.M)
        counted += int(row.group(1)) if row else 0
    assert in_tables >= 3 and counted == in_tables, (in_tables, counted)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", sorted(CAMS))
def test_a_segment_number_only_where_its_kind_repeats(handin_reports, name, lang):
    md, _ = handin_reports(name, lang)
    for label in CAMS[name]:
        for row in _table_rows(md, label):
            first = row.strip("|").split("|")[0].strip()
            assert not re.search(r"(rise|return|推程|回程) \d+$", first), row


def _rows_of(md: str, label: str) -> list[list[str]]:
    return [[c.strip() for c in r.strip().strip("|").split("|")] for r in _table_rows(md, label)]


@pytest.mark.parametrize("lang", LANGS)
def test_the_motor_table_says_which_ratios_the_stages_can_reach(handin_reports, lang):
    """slotter: the chosen Y90S-6 and the lighter Y801-4 both read "not in the recommended
    range" with no word why the Y801-4 was passed over. Its V-belt (the only free stage
    after the fixed gear pair i = 3) may reach i = 7 at most (吴宗泽《机械设计课程设计手册》,
    table of recommended transmission ratios: V-belt 2–4, at most 7): i/3 = 23.17/3 = 7.72
    is beyond it, Y90S-6's 15.17/3 = 5.06 within."""
    md, _ = handin_reports("slotter", lang)
    rows = {r[1]: r for r in _rows_of(md, "motors")}
    yes, no = ("是", "否") if lang == "zh" else ("yes", "no")
    for motor, row in rows.items():
        if motor in ("—",):
            continue
        ratio = float(row[4])
        assert row[6] == (yes if ratio / 3.0 <= 7.0 else no), row
    assert rows["Y801-4"][6] == no and rows["Y90S-6"][6] == yes


@pytest.mark.parametrize("lang", LANGS)
def test_the_crank_rocker_judges_its_requirement(handin_reports, lang):
    """crank_rocker: [γ] = 40° was given and never judged; the optimum's γ_min (46.95°, the
    paper's law of cosines on the optimum's lengths) and the offset slider-crank's working-
    stroke pressure angle (39.12° ≤ 90° − 40°) now have their rows and verdicts."""
    md, _ = handin_reports("crank_rocker", lang)
    ok = "合格" if lang == "zh" else "PASS"
    rows = _rows_of(md, "verify")
    gamma = [r for r in rows if "[\\gamma]" in r[0] and "gamma_{min}" in r[0]]
    alpha = [r for r in rows if "90° - [\\gamma]" in r[0]]
    assert len(gamma) == 1 and len(alpha) == 1
    assert float(gamma[0][1]) >= 40 and gamma[0][2] == "≥ 40" and gamma[0][3] == ok
    assert float(alpha[0][1]) <= 50 and alpha[0][2] == "≤ 50" and alpha[0][3] == ok


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", ["furnace_pusher", "slotter", "press", "shaper"])
def test_verification_tables_write_values_by_the_number_rule(handin_reports, name, lang):
    """furnace_pusher: "44.3367 | ≥ 40 (44.3367)", "44.0000 … 44.0000", "220.000 | 220.000
    (velocity zeros)": no value in a verification table with more than 3 decimals outside a
    power of ten or a Δ (README "Numbers")."""
    md, _ = handin_reports(name, lang)
    for row in _rows_of(md, "verify"):
        for cell in row[1:3]:
            body = re.sub(r"\(\$?\\?Δ[^)]*\)|\$[^$]*\$|\d+(\.\d+)? × 10\S*", "", cell)
            assert not re.search(r"\d\.\d{4,}", body), row


def test_no_broken_plural_in_the_shaft_steps(handin_reports):
    """"(1 steps of 5 mm; …)", "(1 standard sizes; …)", "10 handbook data" (furnace_pusher en)."""
    md, _ = handin_reports("furnace_pusher", "en")
    assert not re.search(r"\b1 (steps|standard sizes)\b", md)
    assert "handbook data that" not in md
