"""The graphical-method chapter, page review 46.

1. die_cutter: a position whose largest force reaches 10⁶ N (the cutting force, 20 m of rule
   × 50 N/mm = 1 MN from the brief) writes its forces in kN, as the rest of the report does
   (fmt.force_unit): the known-loads sentences, the force table ("Value /kN") and the
   comparison rows of forces — no "1.000 × 10⁶ N"; the moment equations keep N and say so.
   A position with smaller forces keeps N.
2. shaper, group 5–6 (RRP: rod 5, ram 6 on its guide): (a) "Moment equations …" is announced
   only where the group has a numeric equation; (b) after the force polygon the ram's moment
   equation about F gives the arm h of the guide's reaction F_R76. Its printed chain is
   re-evaluated, and h is checked against the engine: with the engine's forces on the ram
   (weight m·g, inertia force −m·a_S, resistance, the guide's reaction at h·μl along the
   guide) ΣM_F = 0 within the drawing's accuracy (0.5 mm at μl).
"""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
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
    big = [s for s in sections.values() if re.search(r"\$F_r\$[^,，。.]*= ", s)
           and "kN" in s]
    assert big, "no position in kN"
    for s in big:
        # no power of ten for a force anywhere in the position's force section
        kin = s[s.index("#### "):]
        assert "10⁶" not in kin and "10^{6}" not in kin and "10⁵" not in kin, kin[:400]
        # the known loads: the cutting force as the brief gives it, in kN
        assert re.search(rf"\$F_r\$[^=]*= {fc / 1e3:g} kN", kin)
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


def _arm(section: str) -> tuple[float, float, re.Match]:
    g = _group(section, "5–6")
    m = ARM.search(g)
    assert m, g
    t = TRUE.search(g)
    assert t and t["h"] == m["h"]
    return float(m["h"]), float(t["mu"]), m


@pytest.mark.parametrize("lang", LANGS)
def test_shaper_group_56_announces_no_equation_it_does_not_give(example_results, lang):
    md, _ = _markdown(example_results, "shaper", lang)
    announce = "Moment equations (" if lang == "en" else "力矩方程（"
    for label in ("4", "10"):
        s = _positions(md)[label]
        g56, g34 = _group(s, "5–6"), _group(s, "3–4")
        # link 5's moment about F is a sentence (F_R45^t = 0), no equation: nothing announced
        assert announce not in g56.split("$$")[0]
        assert "F_{R45}^{t} = 0" in g56
        # group 3–4 has its equations, announced
        assert announce in g34 and "\\Rightarrow" in g34


@pytest.mark.parametrize("lang", LANGS)
def test_shaper_ram_moment_equation_reproduces_its_result(example_results, lang):
    md, _ = _markdown(example_results, "shaper", lang)
    for label in ("4", "10"):
        h, mu, m = _arm(_positions(md)[label])
        # the printed products' sum is the printed numerator (with its sign)
        total = 0.0
        for sign, force, arm in re.findall(r"(-?)\s*([\d.]+) \\times ([\d.]+)", m["terms"]):
            total += (-1 if sign else 1) * float(force) * float(arm)
        num = float(m["num"]) * (-1 if m["minus"] else 1)
        assert abs(-total - num) < 1e-6 * max(1.0, abs(total)) or abs(total - num) < 1e-6
        value = -total / float(m["den"])
        assert abs(value - h) <= 0.005 + 1e-9
        t = TRUE.search(_group(_positions(md)[label], "5–6"))
        assert abs(h * mu - float(t["m"])) <= 0.5 * 10.0 ** -len(t["m"].partition(".")[2]) + 1e-12


def _ram_residual(r, prefix: str, label: str, h_mm: float) -> tuple[float, float, float]:
    """ΣM about the ram's pin of the engine's forces on the ram with the guide's reaction at
    the arm h [mm on the drawing]: (residual [N·m], |R| [N], μl [m/mm])."""
    from mechdesign.core.mechanism import RRP
    from mechdesign.stages.polygons import entry

    model = r.get("model", r.get(f"{prefix}_model"))
    k, raw, F = r[prefix], r[f"{prefix}_raw"], r[f"{prefix}_forces"]
    doc = r[f"{prefix}_graphical"]
    pos = next(p for p in doc.positions if p.label == label)
    i = entry(k, label)
    g = next(g for g in model.mechanism.groups if isinstance(g, RRP))
    C = complex(raw.points[g.c].pos[i])
    u = complex(np.exp(1j * g.guide_angle))
    R = complex(F.reactions[f"R{model.mechanism.frame}{g.slider}"][i])
    loads = []
    for b in model.bodies:
        if b.link == g.slider and b.mass:
            at = complex(raw.points[b.com].pos[i])
            loads.append((-1j * b.mass * model.gravity, at))
            loads.append((complex(F.inertia_force[g.slider][i]), at))
    for j, res in enumerate(model.resistances):
        if res.link == g.slider:
            loads.append((complex(F.resistance[f"R{j + 1}"][i] * np.exp(1j * res.direction)),
                          complex(raw.points[res.point].pos[i])))
    cross = lambda a, b: a.real * b.imag - a.imag * b.real          # noqa: E731
    known = sum(cross(at - C, f) for f, at in loads)
    # h > 0: R's moment about C counter-clockwise; its line crosses the guide at C + s·u
    s = abs(R) * h_mm * pos.length_scale / cross(u, R)
    return known + cross(s * u, R), abs(R), pos.length_scale


@pytest.mark.parametrize("lang", LANGS)
def test_shaper_ram_arm_balances_the_engines_forces(example_results, lang):
    """The analytic ΣM_F(6) of every force on the ram (the pin's reaction at F has none) is
    zero with the guide's reaction at the printed arm h, within 0.5 mm at μl."""
    r = example_results("shaper")
    md, _ = _markdown(example_results, "shaper", lang)
    for label in ("4", "10"):
        h, mu, _m = _arm(_positions(md)[label])
        residual, R, mu_l = _ram_residual(r, "linkage", label, h)
        assert mu == mu_l
        assert abs(residual) <= R * 0.5 * mu_l, (label, residual / R / mu_l)
        # and not by chance: the other side of F is far off
        wrong, _R, _mu = _ram_residual(r, "linkage", label, -h)
        assert abs(wrong) > R * 5 * mu_l


def test_shaper_ram_arm_agrees_with_the_engines_couple(example_results):
    """The engine gives the guide's couple (its line of action shifted by couple/normal,
    kinetostatics.JointReaction): |h|·μl equals |couple|/|R| within 0.5 mm at μl."""
    from mechdesign.stages.polygons import entry

    r = example_results("shaper")
    F, k = r["linkage_forces"], r["linkage"]
    for pos in r["linkage_graphical"].positions:
        sm = next(fg.slider_moment for fg in pos.forces if fg.slider_moment is not None)
        i = entry(k, pos.label)
        R = abs(complex(F.reactions["R76"][i]))
        shift = abs(float(F.couples["R76"][i])) / R
        assert abs(abs(sm.arm) * pos.length_scale - shift) <= 0.5 * pos.length_scale


@pytest.mark.parametrize("name", ["slotter", "press", "die_cutter"])
def test_other_rams_arm_within_the_reactions_accuracy(example_results, name):
    """The other RRP rams: the arm balances the engine's forces within 0.5 mm plus what the
    reaction's own drawing accuracy (2 % + 2 mm at μF, the comparison's allowance) moves it
    (the slotter's F_R76 is a short closing side: 70 N read for 65.3 N)."""
    r = example_results(name)
    prefix = next(k[: -len("_graphical")] for k in r if k.endswith("_graphical"))
    for pos in r[f"{prefix}_graphical"].positions:
        for fg in pos.forces:
            sm = fg.slider_moment
            if sm is None:
                continue
            residual, R, mu_l = _ram_residual(r, prefix, pos.label, sm.arm)
            rel = (0.02 * R + 2 * fg.scale) / R
            assert abs(residual) <= R * mu_l * (0.5 + abs(sm.arm) * rel), (pos.label, sm)
