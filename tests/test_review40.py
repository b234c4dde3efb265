"""Findings of review39 mended in session 40, each checked on the computed results or on the
example reports' Markdown (tests/conftest.py's ``handin_reports``).

- The force analysis meets the working load: where the resistance acts on a small part of
  the working stroke (a press's last millimetres), the first polygon position is the regular
  position under it that loads the crank most — found here by brute force over the positions.
- A link's ω and α are compared with their signs, as the text lists them (α2 = −9.81 rad/s²
  was 9.81 in the comparison table).
- A cam's dwell is no check: the summary's cam row counts the rise and the return only.
- Stress cycles are written as an engineer writes them (2.043 × 10⁹, not 2042.5 × 10⁶) and a
  bearing reaction of a thousand newtons or more to the newton (not −316 105.9 N).
"""
from __future__ import annotations

import re

import numpy as np
import pytest

LANGS = ("zh", "en")
PRESSES = [("die_cutter", "press"), ("press", "linkage")]


@pytest.mark.parametrize("name,prefix", PRESSES)
def test_the_first_polygon_position_is_the_most_loaded_under_the_working_load(example_results,
                                                                               name, prefix):
    from mechdesign.stages.polygons import default_positions

    r = example_results(name)
    k, forces = r[prefix], r[f"{prefix}_forces"]
    n = k.grid_size
    labels = [str(x) for x in k.positions.labels]
    total = sum(np.abs(np.asarray(v)) for v in forces.resistance.values())
    # positions (regular, in the working stroke) where the working resistance acts
    loaded = [lab for lab, ph, sp in zip(labels, k.positions.phase, k.positions.special)
              if not sp and ph <= k.working_span and total[n + labels.index(lab)] > 0]
    assert loaded, name
    best = max(loaded, key=lambda lab: abs(forces.balancing_torque[n + labels.index(lab)]))
    assert default_positions(k, forces)[0] == best, (name, best)
    drawn = r[f"{prefix}_graphical"].positions
    assert drawn[0].label == best, (name, [p.label for p in drawn], best)
    # its comparison includes the working load's reactions, all within the drawing's accuracy
    first = drawn[0]
    assert all(abs(c.graphical - c.analytic) <= c.tolerance for c in first.comparison), \
        [(c.quantity, c.graphical, c.analytic) for c in first.comparison
         if abs(c.graphical - c.analytic) > c.tolerance]
    biggest = max(abs(c.analytic) for c in first.comparison if c.unit == "N")
    assert biggest >= 0.5 * float(np.max(total)), (name, biggest, float(np.max(total)))


@pytest.mark.parametrize("name", ["crank_rocker", "shaper", "die_cutter", "furnace_pusher"])
def test_rates_are_compared_with_their_signs(example_results, name):
    r = example_results(name)
    found = [v for key, v in r.items() if key.endswith("_graphical")]
    assert found
    negative = 0
    for doc in found:
        for pos in doc.positions:
            for c in pos.comparison:
                if c.quantity[:1] in ("ω", "α"):
                    # the same sign as the engine's rate (a zero rate aside)
                    if abs(c.analytic) > c.tolerance:
                        assert np.sign(c.graphical) == np.sign(c.analytic), (name, pos.label, c)
                    negative += c.analytic < 0
    assert negative, f"{name}: no negative rate compared (the sign is dropped?)"


@pytest.mark.parametrize("lang", LANGS)
def test_the_comparison_table_prints_the_rate_as_the_text(handin_reports, lang):
    md, _ = handin_reports("crank_rocker", lang)
    text = re.search(r"\\alpha_\{2\}\$ = (-?[0-9.]+) rad/s²", md)
    assert text, "the text lists α2"
    row = re.search(r"\| \$\\alpha_\{2\}\$ \| rad/s² \| (-?[0-9.]+) \|", md)
    assert row and row.group(1) == text.group(1), (text.group(1), row and row.group(1))


@pytest.mark.parametrize("lang", LANGS)
def test_a_dwell_is_not_counted_as_a_cam_check(handin_reports, lang):
    md, document = handin_reports("shaper", lang)
    segments = document["cam"]["segments"]
    limited = sum(1 for s in segments if s.get("limit") is not None)
    assert limited == 2 and len(segments) == 4
    # the cam's group counts its limited segments and its profile's curvature checks
    # (review45), never a dwell
    curvature = len(document["cam"]["curvature_checks"])
    assert curvature == 2                       # a roller follower: ρ_min > r_r, ρ_a ≥ least
    # the feed cam's phase: its motion within the return stroke (session 49), one check
    assert isinstance(document["cam_phase"]["passed"], bool)
    name = "凸轮机构" if lang == "zh" else "cam mechanism"
    row = re.search(rf"\| {re.escape(name)} \| (\d+) \|", md, flags=re.I)
    assert row and int(row.group(1)) == limited + curvature + 1, row and row.group(0)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", ["die_cutter", "shaper", "furnace_pusher"])
def test_cycles_and_reactions_written_as_an_engineer_writes_them(handin_reports, name, lang):
    md, _ = handin_reports(name, lang)
    cycles = re.findall(r"N_1 = ([0-9.]+)\\times10\^\{(\d+)\}", md)
    assert cycles, "stress cycles listed"
    for mant, _exp in cycles:
        assert 1 <= float(mant) < 10 and len(mant.replace(".", "")) == 4, mant
    assert "\\times10^6" not in md
    reactions = re.findall(r"R_\{[AB][HV]\} = (-?[0-9.]+)\\ \\mathrm\{N\}", md)
    assert reactions
    for value in reactions:
        if abs(float(value)) >= 1000:
            assert "." not in value, value
