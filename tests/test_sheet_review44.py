"""Session 44's page review of the drawing sheets (issue 19, point 8), stated as rules on the
sheet model a builder returns (what the DXF and the PDF draw):

- cycle sheet: every piece of every phase is named, on both diagrams — inside its piece, or
  outside it on a leader that starts on the piece (the lock-beam's bending wheel: its
  342–348° far dwell and the 348–360° piece of its return, 7 mm and 15 mm on the bar, were
  not named at all);
- kinematic sheet notes: the link legend lists the links in the order of their numbers (the
  die-cutter's read "2 …  7 …" then "3 … 10" on the next line), and the scale note is a
  sentence ("each group to μL; not given, so schematic: …" was read as garbled);
- A1 analysis sheet: every frame pivot's name stands at its pivot, a position number is
  drawn differently from a link number (a circle round it, as the rings' numbers of the
  cycle diagram), and no two labels of the skeleton come nearer than the word space.
"""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]


def _sheet(example_results, name: str, kind: str, lang: str):
    from mechdesign.brief.loader import load_brief
    from mechdesign.render.sheets import _builders, title_info

    brief = load_brief(ROOT / "designs" / f"{name}.yaml")
    builders = _builders(example_results(name), brief)
    for k, (stem, build) in enumerate(builders, 1):
        if stem == kind:
            return build(title_info(brief.report, stem, "MD-01", k, len(builders), lang), lang), \
                example_results(name)
    raise AssertionError(f"{name} has no {kind} sheet")


def _box(t):
    from mechdesign.render.sheet import text_box

    return text_box(t.position, t.text, t.height, t.halign, t.valign)


def _near_box(z: complex, b, tol: float) -> bool:
    return b[0] - tol <= z.real <= b[2] + tol and b[1] - tol <= z.imag <= b[3] + tol


# ------------------------------------------------------------------ cycle sheet

def _named(texts, lines, name, inside, on_piece, tol=1.5) -> bool:
    """A text ``name`` whose centre is ``inside`` the piece, or one a line joins to a point
    ``on_piece``."""
    for t in texts:
        if t.text != name:
            continue
        b = _box(t)
        if inside(complex((b[0] + b[2]) / 2, (b[1] + b[3]) / 2)):
            return True
        for ln in lines:
            for a, z in ((ln.p0, ln.p1), (ln.p1, ln.p0)):
                if on_piece(a) and _near_box(z, b, tol):
                    return True
    return False


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_every_cycle_piece_is_named(example_results, lang):
    from mechdesign.render.cycle_sheet import DEG, phase_name, pieces, polar
    from mechdesign.render.sheet import Arc, Circle, Line, Polyline, Text

    s, results = _sheet(example_results, "lockbeam", "cycle", lang)
    diagram = results["cycle"].diagram
    acts = list(diagram.actuators)
    origin = float(diagram.origin) * DEG
    texts = [e for e in s.entities if isinstance(e, Text)]
    lines = [e for e in s.entities if isinstance(e, Line)]
    bars = sorted((e for e in s.entities if isinstance(e, Polyline) and e.closed and len(e.points) == 4
                   and e.layer == "OUTLINE" and e.weight == 0.5), key=lambda e: -max(p.imag for p in e.points))
    assert len(bars) == len(acts)
    missing = []
    for act, bar in zip(acts, bars):
        left, right = min(p.real for p in bar.points), max(p.real for p in bar.points)
        yb, yt = min(p.imag for p in bar.points), max(p.imag for p in bar.points)
        mu = 360.0 / (right - left)
        for ph in act.phases:
            for p0, p1 in pieces(float(ph.start) * DEG, float(ph.span) * DEG, origin):
                xa, xb = left + (p0 - origin) / mu, left + (p1 - origin) / mu
                if not _named(texts, lines, phase_name(ph, lang),
                              lambda z: xa <= z.real <= xb and yb <= z.imag <= yt,
                              lambda z: xa - 1e-6 <= z.real <= xb + 1e-6 and abs(z.imag - yt) < 1e-6):
                    missing.append(f"linear: {act.name(lang)} {phase_name(ph, lang)} {p0:.0f}–{p1:.0f}°")
    # the circular diagram: its centre is the rings' arcs' centre
    arcs = [e for e in s.entities if isinstance(e, Arc)]
    c = max({a.center for a in arcs}, key=lambda z: sum(1 for a in arcs if abs(a.center - z) < 1e-6))
    r_outs = sorted({round(a.radius, 6) for a in arcs if abs(a.center - c) < 1e-6})[-len(acts):]
    r0 = max(e.radius for e in s.entities if isinstance(e, Circle) and abs(e.center - c) < 1e-6
             and e.radius < r_outs[0] - 1e-6)
    for i, act in enumerate(acts):
        r_in, r_out = ([r0] + r_outs)[i], r_outs[i]
        for ph in act.phases:
            a, span = (float(ph.start) * DEG) % 360.0, float(ph.span) * DEG

            def in_sector(z, a=a, span=span, r_in=r_in, r_out=r_out, pad=0.0):
                d = z - c
                phi = (90.0 - np.degrees(np.angle(d))) % 360.0
                return r_in - pad <= abs(d) <= r_out + pad and (phi - a) % 360.0 <= span

            if not _named(texts, lines, phase_name(ph, lang), in_sector, in_sector):
                missing.append(f"circular: {act.name(lang)} {phase_name(ph, lang)} from {a:.0f}°")
    assert not missing, "phases not named:\n" + "\n".join(missing)


# ------------------------------------------------------------------ kinematic sheet notes

@pytest.mark.parametrize("lang", ["zh", "en"])
def test_die_cutter_links_legend_in_number_order(example_results, lang):
    from mechdesign.render.sheet import Text

    s, _ = _sheet(example_results, "die_cutter", "kinematic", lang)
    texts = [e for e in s.entities if isinstance(e, Text)]
    start = next(i for i, t in enumerate(texts) if t.text.startswith(("Links: ", "构件：")))
    # the legend's lines: from "Links:" down to the last note line under it
    legend = "  ".join(t.text for t in texts[start:] if t.layer == "TEXT"
                      and abs(t.position.real - texts[start].position.real) < 1e-6)
    numbers = [int(m) for m in re.findall(r"(?:^|\s{2}|：|: )(\d+) ", legend)]
    assert numbers == sorted(numbers) and len(numbers) >= 8, numbers


def test_die_cutter_scale_note_reads_as_a_sentence(example_results):
    from mechdesign.render.sheet import Text

    s, _ = _sheet(example_results, "die_cutter", "kinematic", "en")
    notes = " ".join(e.text for e in s.entities if isinstance(e, Text))
    assert "not given, so schematic" not in notes
    assert re.search(r"Each group drawn to μ.*schematic, as the task does not give them", notes), notes
