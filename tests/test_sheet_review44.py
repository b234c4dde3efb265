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


# ------------------------------------------------------------------ A1 analysis sheet

PIVOT_NEAR = 5.0     # a pivot's name: its text box within this of the pivot [mm]
NUMBER_NEAR = 9.0    # a position number: its circle's centre within this of its crank pin,
#                      or a leader from the pin to the circle


def _dist_box(z: complex, b) -> float:
    dx = max(b[0] - z.real, 0.0, z.real - b[2])
    dy = max(b[1] - z.imag, 0.0, z.imag - b[3])
    return float(np.hypot(dx, dy))


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", ["lockbeam", "furnace_pusher", "linkage_sixbar"])
def test_a1_skeleton_labels_at_their_points(example_results, name, lang):
    """A frame pivot's name stands beside its pivot (lockbeam: "O2" stood 40 mm out on a
    leader, at the crank circle among the position numbers); every position number is
    circled (told from the link numbers: "5" for position 5 and link 5 read alike) and
    stands at its crank pin or is joined to it by a leader; no two labels of the sheet
    touch or come nearer than the word space (tests/sheet_overlaps.py)."""
    from sheet_overlaps import crowded_labels, touching_labels

    from mechdesign.render.analysis_sheet import _mechanism_extent
    from mechdesign.render.labels import sheet_point
    from mechdesign.render.sheet import Circle, Line, Text
    from mechdesign.render.sheets import linkage_results

    s, results = _sheet(example_results, name, "analysis", lang)
    found = linkage_results(results)
    model, k = found.model, found.motion
    crank = model.crank
    ext = _mechanism_extent(model, k, lang)
    P = ext["P"]
    piv = P[crank.pivot][0]
    # the crank circle (its centre is the crank pivot on the paper) gives the drawing's scale
    R = crank.length * 1e3
    circles = [e for e in s.entities if isinstance(e, Circle) and e.layer == "CENTER"]
    ratios = [e.radius / R for e in circles]
    assert circles, "no crank circle"
    crank_circle = circles[0]
    sc = ratios[0]

    def paper(z: complex) -> complex:
        return crank_circle.center + sc * (z - piv)

    texts = [e for e in s.entities if isinstance(e, Text)]
    problems = []
    for pname, z in model.mechanism.frame_points.items():
        label = sheet_point(pname)
        where = paper(z * 1e3)
        near = [t for t in texts if t.text == label]
        d = min((_dist_box(where, _box(t)) for t in near), default=np.inf)
        if d > PIVOT_NEAR:
            problems.append(f"pivot {label}: its name {d:.1f} mm from it")
    rings = [e for e in s.entities if isinstance(e, Circle) and e.layer != "CENTER"]
    lines = [e for e in s.entities if isinstance(e, Line)]
    tip = P[crank.tip]
    for i, number in enumerate(k.positions.labels):
        pin = paper(tip[i])
        circled = [(t, c) for t in texts if t.text == number for c in rings
                   if abs(c.center - t.position) < 1e-6 and c.radius > 0.4 * t.height]
        if not circled:
            problems.append(f"position {number}: not circled")
            continue
        ok = any(abs(c.center - pin) <= NUMBER_NEAR
                 or any(min(abs(ln.p0 - pin), abs(ln.p1 - pin)) < 1e-6
                        and abs(abs((ln.p1 if abs(ln.p0 - pin) < 1e-6 else ln.p0) - c.center) - c.radius) < 0.1
                        for ln in lines)
                 for _, c in circled)
        if not ok:
            problems.append(f"position {number}: {min(abs(c.center - pin) for _, c in circled):.1f} mm "
                            "from its crank pin, no leader")
    problems += [f"touching: {t}" for t in touching_labels(s)]
    problems += [f"crowded: {t}" for t in crowded_labels(s)]
    assert not problems, f"{name} {lang}:\n" + "\n".join(problems)


# ------------------------------------------------------------------ cam sheet

@pytest.mark.parametrize("lang", ["zh", "en"])
def test_bending_cam_pivot_named_beside_it(example_results, lang):
    """The rocker's pivot A of the lock-beam's bending cam is named beside it (it stood on a
    20 mm leader inside the fan of the rays to the arm's positions): its name's box within
    :data:`PIVOT_NEAR` of the pivot, found as the pin at the right end of the centre
    distance a's dimension."""
    from mechdesign.render.labels import sheet_point
    from mechdesign.render.sheet import Circle, Dimension, Text

    s, _ = _sheet(example_results, "lockbeam", "bending_cam", lang)
    dim = next(e for e in s.entities if isinstance(e, Dimension) and (e.text or "").startswith("a="))
    ends = (dim.p0.real, dim.p1.real)
    pins = [e for e in s.entities if isinstance(e, Circle) and abs(e.radius - 1.2) < 1e-9
            and e.layer == "OUTLINE" and min(abs(e.center.real - x) for x in ends) < 1e-6]
    assert pins, "no pivot pin at the end of a"
    # the rocker's pivot: the pin at the end of a that is not the cam centre's (the one
    # farther from the dimension's other end's pin, i.e. at x of the end the arm starts from)
    names = [t for t in s.entities if isinstance(t, Text) and t.text == sheet_point("A")]
    assert names
    d = min(_dist_box(p.center, _box(t)) for p in pins for t in names)
    assert d <= PIVOT_NEAR, f"A's name {d:.1f} mm from its pivot"
