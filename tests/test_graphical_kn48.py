"""The graphical-method chapter in kN (page review 46; the helper's graph46 c03ff74, landed
in session 48 without the ram's moment equation, which unsettled the layout).

1. die_cutter: a position whose largest force reaches 10⁶ N (the cutting force, 20 m of rule
   × 50 N/mm = 1 MN from the brief) writes its forces in kN, as the rest of the report does
   (fmt.force_unit): the known-loads sentences, the force table ("Value /kN") and the
   comparison rows of forces — no "1.000 × 10⁶ N"; the moment equations keep N and say so.
   A position with smaller forces keeps N.
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest
import yaml

from tests.test_report_prose import _markdown

ROOT = Path(__file__).resolve().parents[1]
LANGS = ["zh", "en"]


def _positions(md: str) -> dict[str, str]:
    """The graphical chapter's sections by position label (up to the next position or
    chapter)."""
    head = re.compile(r"^## (?:Position|位置) (\S+?)[ （(]", re.M)
    marks = [(m.start(), m[1]) for m in head.finditer(md)]
    out = {}
    for (start, label), nxt in zip(marks, marks[1:] + [(len(md), None)]):
        body = md[start:nxt[0]]
        end = re.search(r"^# ", body, re.M)
        out[label] = body[:end.start()] if end else body
    return out


def _group(section: str, name: str) -> str:
    m = re.search(rf"^#### (?:Group|杆组) {name}\n(.*?)(?=^#### |^\| )", section, re.M | re.S)
    assert m, name
    return m[1]


def _num(text: str) -> float:
    return float(text.replace("\u202f", "").replace("−", "-"))


# ---------------------------------------------------------------- 1. die_cutter in kN

def _cutting_force() -> float:
    brief = yaml.safe_load((ROOT / "designs" / "die_cutter.yaml").read_text(encoding="utf-8"))
    c = brief["cutting"]
    return c["cut_length_m"] * 1000.0 * c["specific_resistance_N_per_mm"]     # [N]


def test_kn_text_against_hand_values():
    from mechdesign.render.graphical_report import kn_text

    assert kn_text("1.000 × 10⁶", 1.0e6) == "1000"
    assert kn_text("245.3", 245.3) == "0.2453"
    assert kn_text("120", 120.0) == "0.120"
    assert kn_text("960\u202f000", 960000.0) == "960"
    assert kn_text("1662.5", 1662.5) == "1.663"
    assert kn_text("133\u202f237", 133237.0) == "133.2"


@pytest.mark.parametrize("lang", LANGS)
def test_die_cutter_forces_of_a_million_newtons_in_kn(example_results, lang):
    md, _ = _markdown(example_results, "die_cutter", lang)
    fc = _cutting_force()
    assert fc >= 1e6                       # the brief's 1 MN: the kN position
    sections = _positions(md)
    big = [s for s in sections.values() if re.search(r"\$F_c\$[^,，。.]*= ", s)
           and "kN" in s]
    assert big, "no position in kN"
    for s in big:
        # no power of ten for a force anywhere in the position's force section
        kin = s[s.index("#### "):]
        assert "10⁶" not in kin and "10^{6}" not in kin and "10⁵" not in kin, kin[:400]
        # the known loads: the cutting force as the brief gives it, in kN
        assert re.search(rf"\$F_c\$[^=]*= {fc / 1e3:g} kN", kin)
        # the force table in kN, each value its length × μF (μF stated in N/mm)
        assert ("Value /kN" if lang == "en" else "数值 /kN") in kin
        mus = [_num(m) for m in re.findall(r"\\mu_F\$ = ([\d\u202f.]+) N/mm", kin)]
        table = kin[kin.index("| 5–6 |"):]
        rows = re.findall(r"^\| ([^|\n]*)\| \$([^$]+)\$ \| ([√?]) \| ([\d.—]+) \| ([^|\n]+) \|$",
                          table, re.M)
        assert rows
        group = -1
        for first, name, mark, length, value in rows:
            if first.strip():
                group += 1                # the next group's polygon, its own μF
            if length == "—":
                continue
            mu = mus[min(group, len(mus) - 1)] / 1e3           # kN/mm
            last = value.strip().partition(".")[2]
            half = 0.5 * 10.0 ** -len(last)
            assert abs(float(length) * mu - _num(value)) <= half + 0.005 * mu, (name, length, value)
        # the comparison's forces in kN: the cutting force's reaction F_R35 ≈ F_c
        row = re.search(r"^\| \$F_\{R35\}\$ \| (\S+) \| ([^|]+) \| ([^|]+) \|", kin, re.M)
        assert row and row[1] == "kN"
        assert abs(_num(row[2]) - fc / 1e3) <= 0.05 * fc / 1e3
        # the moment equations keep N and say so
        assert ("forces in N" if lang == "en" else "力以 N 计") in kin


@pytest.mark.parametrize("lang", LANGS)
def test_die_cutter_small_forces_stay_in_newtons(example_results, lang):
    md, _ = _markdown(example_results, "die_cutter", lang)
    small = [s for s in _positions(md).values() if "#### " in s and "kN" not in s]
    assert small, "every position in kN"
    for s in small:
        assert ("Value /N" if lang == "en" else "数值 /N") in s
        assert "forces in N" not in s and "力以 N 计" not in s


# ---------------------------------------------------------------- 2. the ram's arm h

ARM = re.compile(r"\$\$ \\Sigma M_\{F\}\(6\) = F_\{R76\} \\times h \+ \((?P<terms>[^)]*)\) = 0 "
                 r"\\;\\Rightarrow\\; h = (?P<minus>-?)\\frac\{(?P<num>-?[\d.]+)\}\{(?P<den>[\d.]+)\}"
                 r" = (?P<h>-?[\d.]+)\\ \\mathrm\{mm\} \$\$")
TRUE = re.compile(r"\$h\\mu_l\$ = (?P<h>-?[\d.]+) × (?P<mu>[\d.]+) = (?P<m>-?[\d.]+) m")
