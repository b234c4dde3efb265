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
