"""The kinematic diagram, transmission schematic and cycle diagram sheets (issue 19, point 8),
checked against references written out here: the joints of the shaper (link-length brief)
at position 1 and of the crank-rocker at its first extreme position from closed forms,
scaled by μL; the cycle sheet's phase boundaries from the brief's phases; everything inside
the drawing frame."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml

from mechdesign.render.sheet import (Arc, Circle, Dimension, Fill, Line, Polyline, Text, TitleInfo,
                                     plain, text_box)

ROOT = Path(__file__).resolve().parents[1]
INFO = TitleInfo("机构运动简图", "test", number="T-01")

NEW = {"kinematic", "transmission", "cycle"}


def _sheets(results, lang="zh"):
    from mechdesign.render.sheets import _builders

    return {name: build(INFO, lang) for name, build in _builders(results, None) if name in NEW}


def _circles(sheet, radius):
    return np.array([e.center for e in sheet.entities
                     if isinstance(e, Circle) and abs(e.radius - radius) < 1e-9])


def _near(points, z, tol=1e-6):
    return len(points) and np.min(np.abs(points - z)) < tol


def _scale(sheet) -> float:
    """Model mm per paper mm of the title block's scale: n of a reduction 1:n, 1/m of an
    enlargement m:1."""
    return _scales(sheet)[0]


def _scales(sheet) -> list[float]:
    """The same for every view's scale in the title block ("2:1, 1:1.5")."""
    out = []
    for text in sheet.info.scale.split(","):
        left, right = (float(x) for x in text.split(":"))
        out.append(right / left)
    return out


def test_shaper_pins_at_the_briefs_position_from_the_lengths(example_results):
    """designs/shaper_lengths.yaml: O3 at the origin, O2 = (0, 350) mm, crank 90, guide bar
    580, BF = 0.3·580. The brief names polygon positions [4, 10], so the diagram is drawn at
    position 4 (issue 19): 3 × 30° after position 1, the crank turning clockwise. Position 1
    is the extreme position: the guide bar tangent to the crank circle (O3A ⊥ O2A), so the
    angle at O3 between O3O2 and O3A is asin(90/350) and |O3A| = √(350² − 90²). At position 4
    A = O2 + 90·e^{i(θ1 − 90°)}, the guide bar along O3A, B on it at 580 from O3. The drawn
    pins (radius 1.2 mm) sit at O3 + z/n on paper (n from the title block), the frame
    pivots' circles give O3, O2."""
    brief = yaml.safe_load((ROOT / "designs" / "shaper_lengths.yaml").read_text(encoding="utf-8"))
    assert brief["sheets"]["polygon_positions"][0] == 4
    s = _sheets(example_results("shaper_lengths"))["kinematic"]
    assert any(isinstance(e, Text) and "位置 4" in e.text for e in s.entities)
    n = _scale(s)
    d, r, L = 350.0, 90.0, 580.0
    psi = np.arcsin(r / d)
    ground = _circles(s, 0.22 * 7.0)
    assert len(ground) == 2
    o3 = min(ground, key=lambda z: z.imag)          # O3 below O2
    o2 = max(ground, key=lambda z: z.imag)
    assert abs((o2 - o3) - 1j * d / n) < 1e-9
    pins = _circles(s, 1.2)
    ok = []
    for side in (1, -1):                             # either extreme (the sense of turning)
        u = 1j * np.exp(1j * side * psi)             # direction O3 → A at position 1
        A1 = u * np.sqrt(d ** 2 - r ** 2)
        theta = np.angle(A1 - 1j * d) - np.radians(90.0)     # 3 × 30° clockwise
        A = 1j * d + r * np.exp(1j * theta)
        B = A / abs(A) * L
        ok.append(_near(pins, o3 + A / n) and _near(pins, o3 + B / n))
        if ok[-1]:
            # F: a pin at BF = 0.3 L from B, on the ram's horizontal guide (a slider there)
            others = pins[np.abs(pins - (o3 + A / n)) > 1e-6]
            dist = np.abs(others - (o3 + B / n)) * n
            assert np.any(np.abs(dist - 0.3 * L) < 1e-6)
    assert any(ok)


def test_lockbeam_diagram_draws_the_whole_machine_at_phi_0(example_results):
    """designs/lockbeam.yaml at main-shaft angle φ = 0, every joint from a closed form:
    - feed linkage at position 1 (the guide bar tangent to the crank circle): O2 = 0,
      O3 = −100i, crank 50, A where O3A ⊥ O2A, D on O3A at 250, E on y = 156.7 at 80 from D;
    - positioning cam keyed at 80°: δ = −80° = 280° lies in the far dwell (170 + 60 … 300),
      so the roller centre is r0 + h = 40 + 10 = 50 mm straight above the cam centre;
    - bending cam keyed at 18°: δ = 342° is 12° into the 30° 3-4-5 return, t = 0.4, so
      ψ = Ψ (1 − (10t³ − 15t⁴ + 6t⁵)) with Ψ = 24.398°; the roller centre C is 35 mm from
      the pivot G0 and √(80² + 35² − 2·80·35 cos(φ0 + ψ)) from the cam centre;
    - the four-bar: G0B0 = 200 along the cam–pivot line, G = G0 + a e^{±i(α1 + ψ)} (mirrored
      or not), B where the circles (G, b) and (B0, 40) meet;
    - the chain wheels: pitch circles Ø144 about B0 and Ø40."""
    import math

    r = example_results("lockbeam")
    s = _sheets(r)["kinematic"]
    n = _scale(s)
    ground = _circles(s, 0.22 * 7.0)
    pins = _circles(s, 1.2)
    # feed linkage
    o2 = [g for g in ground if _near(ground, g - 100j / n)]
    assert len(o2) == 1
    o2 = o2[0]
    ok = False
    for side in (1, -1):
        u = 1j * np.exp(1j * side * math.asin(50 / 100))
        A = -100j + u * math.sqrt(100 ** 2 - 50 ** 2)
        D = -100j + u * 250
        E = complex(D.real + math.sqrt(80 ** 2 - (156.7 - D.imag) ** 2), 156.7)
        ok = ok or all(_near(pins, o2 + z / n) for z in (A, D, E))
    assert ok
    # positioning cam: a cam centre (ground) with a pin 50 mm above and a Ø20 roller there
    rollers = _circles(s, 10.0 / n)
    pin_cams = [g for g in ground if _near(pins, g + 50j / n) and _near(rollers, g + 50j / n)]
    assert len(pin_cams) == 1
    # bending cam, lever and four-bar
    t = 0.4
    # the cam's swing: what the drawn four-bar needs for 180° (24.42°, tests/test_lockbeam.py
    # finds it independently), not the brief's 24.398° the synthesis keeps
    Psi = r["bending_cam"].params.programme.stroke
    assert math.degrees(Psi) == pytest.approx(24.42, abs=0.005)
    psi = Psi * (1 - (10 * t ** 3 - 15 * t ** 4 + 6 * t ** 5))
    cam = r["bending_cam"]
    phi0 = cam.grid.initial_angle
    oc = math.sqrt(80 ** 2 + 35 ** 2 - 2 * 80 * 35 * math.cos(phi0 + psi))
    ds = r["bending"].design
    a, b, c, d = ds.input_rocker * 1e3, ds.coupler * 1e3, ds.output_rocker * 1e3, ds.frame * 1e3
    found = 0
    for o in ground:
        a0 = o + 80 / n
        b0 = a0 + d / n
        if not (_near(ground, a0) and _near(ground, b0)):
            continue
        C = [p for p in pins if abs(abs(p - a0) * n - 35) < 1e-6 and abs(abs(p - o) * n - oc) < 1e-6]
        assert len(C) == 1
        for sgn in (1, -1):
            A = a0 + a / n * np.exp(1j * sgn * (ds.alpha1 + psi))
            if not _near(pins, A):
                continue
            Bs = _circle_intersections(A, b / n, b0, c / n)
            assert any(_near(pins, B) for B in Bs)
            found += 1
        assert _near(_circles(s, 72.0 / n), b0)
        assert len(_circles(s, 20.0 / n)) == 1
    assert found == 1
    assert any(isinstance(e, Text) and "示意" in e.text for e in s.entities)


def _circle_intersections(c0, r0, c1, r1):
    """The two intersections of two circles (textbook formula)."""
    d = abs(c1 - c0)
    a = (r0 ** 2 - r1 ** 2 + d ** 2) / (2 * d)
    h = np.sqrt(r0 ** 2 - a ** 2)
    u = (c1 - c0) / d
    m = c0 + a * u
    return m + 1j * u * h, m - 1j * u * h


def test_crank_rocker_joints_at_the_first_extreme(example_results):
    """The optimum a, b, c, d: A at the origin, D = (d, 0); at the extreme C1 the crank and
    the coupler are folded, so C1 is where the circle of radius b − a about A meets the
    circle of radius c about D (the upper one), and B = −a·C1/|C1|."""
    r = example_results("crank_rocker")
    fb = r["optimum"].best.design
    a, b, c, d = (x * 1e3 for x in (fb.crank, fb.coupler, fb.rocker, fb.frame))
    s = _sheets(r)["kinematic"]
    n, n_slider = _scales(s)                         # each view at its own scale
    ground = _circles(s, 0.22 * 7.0)
    A = min(ground, key=lambda z: z.real)            # the four-bar is drawn left
    D = A + d / n
    assert _near(ground, D)
    C1 = max(_circle_intersections(0j, b - a, d + 0j, c), key=lambda z: z.imag)
    B1 = -a * C1 / abs(C1)
    pins = _circles(s, 1.2)
    assert _near(pins, A + C1 / n) and _near(pins, A + B1 / n)
    # the offset slider-crank at its far extreme: crank and rod in line, C on y = −e
    sl = r["slider"]
    a2, b2, e = sl.crank * 1e3, sl.rod * 1e3, sl.offset * 1e3
    C = complex(np.sqrt((a2 + b2) ** 2 - e ** 2), -e)
    A2 = [g for g in ground if abs(g - A) > 1e-6 and abs(g - D) > 1e-6]
    assert len(A2) == 1
    assert _near(pins, A2[0] + C / n_slider) and _near(pins, A2[0] + a2 * C / abs(C) / n_slider)


def test_crank_rocker_link_numbers_at_their_own_middles(example_results):
    """At the first extreme the coupler BC runs over the crank (B, A, C on one line), so the
    middle of BC lies a few millimetres from A and its "2" read as A's (review: "the coupler's
    2 sits next to A"). Each link's number stands at the middle of the stretch no other link
    covers: the coupler's at the middle of AC, clear of the point names A and C."""
    r = example_results("crank_rocker")
    fb = r["optimum"].best.design
    a, b, d = (x * 1e3 for x in (fb.crank, fb.coupler, fb.frame))
    s = _sheets(r)["kinematic"]
    n = _scales(s)[0]
    ground = _circles(s, 0.22 * 7.0)
    A = min(ground, key=lambda z: z.real)            # the four-bar is drawn left
    C1 = A + max(_circle_intersections(0j, b - a, d + 0j, fb.rocker * 1e3), key=lambda z: z.imag) / n
    texts = [(plain(e.text), e.position) for e in s.entities if isinstance(e, Text)]
    # the four-bar's texts (the slider-crank is drawn right of D)
    two = [p for t, p in texts if t == "2" and p.real < A.real + d / n]
    assert len(two) == 1, texts
    mid = (A + C1) / 2
    # across the coupler from the middle of AC, within the label's gap and half its size
    u = (C1 - A) / abs(C1 - A)
    along = ((two[0] - mid) / u).real
    assert abs(along) < 0.1 * abs(C1 - A), (two[0], mid, along)
    for name in ("A", "C"):
        at = [p for t, p in texts if t == name and p.real < A.real + d / n]
        assert len(at) == 1 and abs(two[0] - at[0]) > 0.3 * abs(C1 - A), (name, at, two)


@pytest.mark.parametrize("a,b,others,want", [
    (0j, 10 + 0j, [], 5 + 0j),                                   # alone: its middle
    (0j, 10 + 0j, [(0j, 4 + 0j)], 7 + 0j),                       # covered 0–4: middle of 4–10
    (0j, 10 + 0j, [(-3 + 0j, 2 + 0j), (6 + 0j, 12 + 0j)], 4 + 0j),   # free 2–6
    (0j, 10 + 0j, [(0j, 4 + 1j)], 5 + 0j),                       # not along it: ignored
    (0j, 4 + 0j, [(-1 + 0j, 10 + 0j)], 2 + 0j),                  # covered all along: its middle
])
def test_own_middle(a, b, others, want):
    from mechdesign.render.kinematic_sheet import own_middle

    assert abs(own_middle(a, b, others) - want) < 1e-12


def test_cycle_sheet_boundaries_are_the_brief_phases(example_results):
    """designs/lockbeam.yaml: each actuator's phase boundaries start + Σspan (mod 360) are
    the vertical lines inside its bar, at x = left + (φ − origin)/μφ."""
    brief = yaml.safe_load((ROOT / "designs" / "lockbeam.yaml").read_text(encoding="utf-8"))
    cyc = brief["cycle"]
    s = _sheets(example_results("lockbeam"))["cycle"]
    bars = sorted([e for e in s.entities if isinstance(e, Polyline) and e.closed and e.weight == 0.5
                   and e.layer == "OUTLINE"], key=lambda e: -e.points[0].imag)
    assert len(bars) == len(cyc["actuators"])
    for bar, act in zip(bars, cyc["actuators"]):
        xs = [p.real for p in bar.points]
        ys = [p.imag for p in bar.points]
        left, right, lo, hi = min(xs), max(xs), min(ys), max(ys)
        mu = 360.0 / (right - left)
        want, phi = set(), float(act["start_deg"])
        for ph in act["phases"]:
            want.add(round((phi - cyc["origin_deg"]) % 360.0, 6))
            phi += ph["span_deg"]
        want.discard(0.0)
        got = {round((e.p0.real - left) * mu, 6) for e in s.entities
               if isinstance(e, Line) and e.layer == "OUTLINE" and abs(e.p0.real - e.p1.real) < 1e-9
               and abs(min(e.p0.imag, e.p1.imag) - lo) < 1e-9 and abs(max(e.p0.imag, e.p1.imag) - hi) < 1e-9}
        assert got == want, act["key"]


def _extent(e):
    if isinstance(e, Line):
        return [e.p0, e.p1]
    if isinstance(e, (Polyline, Fill)):
        return list(e.points)
    if isinstance(e, Circle):
        return [e.center + e.radius * z for z in (1, 1j, -1, -1j)]
    if isinstance(e, Arc):
        return list(e.center + e.radius * np.exp(1j * np.linspace(e.start, e.end, 17)))
    if isinstance(e, Dimension):
        return [e.p0, e.p1]
    if isinstance(e, Text) and abs(e.angle) < 1e-12:
        b = text_box(e.position, e.text, e.height, e.halign, e.valign)
        return [complex(b[0], b[1]), complex(b[2], b[3])]
    return []


@pytest.mark.parametrize("name", ["shaper", "crank_rocker", "cam_7_3", "cam_7_1", "lockbeam",
                                  "furnace_drive", "die_cutter", "furnace_pusher", "linkage_sixbar",
                                  "textbook_guide_bar", "press", "lockbeam_cam", "slotter"])
@pytest.mark.parametrize("lang", ["zh", "en"])
def test_new_sheets_lie_inside_the_frame(example_results, name, lang):
    sheets = _sheets(example_results(name), lang)
    assert sheets, name
    for kind, s in sheets.items():
        x0, y0, x1, y1 = s.inner
        border = {id(e) for e in s.entities[:2]}          # the trimmed edge and the border
        for e in s.entities:
            if id(e) in border:
                continue
            for p in _extent(e):
                assert x0 - 1e-6 <= p.real <= x1 + 1e-6 and y0 - 1e-6 <= p.imag <= y1 + 1e-6, \
                    (name, kind, type(e).__name__, getattr(e, "text", ""), p)


@pytest.mark.e2e
@pytest.mark.parametrize("name", ["crank_rocker", "cam_7_1", "furnace_drive"])
def test_briefs_without_sheets_before_now_write_pdf_and_dxf(name, tmp_path):
    """The three briefs whose --format dxf wrote nothing: every sheet as PDF and DXF."""
    from mechdesign.render.sheets import _builders, write_all
    from mechdesign.brief.loader import load_brief
    from conftest import compute_example

    r = compute_example(name)
    brief = load_brief(ROOT / "designs" / f"{name}.yaml")
    (tmp_path / "f").mkdir()
    files = write_all(_builders(r, brief), brief, tmp_path, tmp_path / "f", "zh", ("pdf", "dxf"))
    assert files
    for f in files:
        assert (tmp_path / f.pdf).read_bytes().startswith(b"%PDF")
        assert (tmp_path / f.dxf).stat().st_size > 1000


def test_a_run_without_sheets_says_so_when_dxf_is_asked(tmp_path, capsys):
    from mechdesign.render.sheets import make_sheets

    collect = make_sheets({}, None, tmp_path, tmp_path, "en", ("md", "dxf"))
    assert collect() == []
    assert "no drawing sheet" in capsys.readouterr().err
    make_sheets({}, None, tmp_path, tmp_path, "zh", ("md", "dxf"))
    assert "没有可绘制的图纸" in capsys.readouterr().err
    make_sheets({}, None, tmp_path, tmp_path, "zh", ("md", "pdf"))
    assert capsys.readouterr().err == ""


def test_a_diagram_that_cannot_be_drawn_is_left_out_with_a_line(tmp_path, capsys):
    """A new diagram that fails for a user's geometry: the other sheets are written, the
    run says which sheet is missing and why; the existing sheets still raise."""
    from types import SimpleNamespace

    from mechdesign.render.sheets import write_all

    def bad(info, lang):
        raise ValueError("the layout does not fit")

    meta = SimpleNamespace(title="t", student="", student_id="", class_name="", teacher="", date="")
    brief = SimpleNamespace(report=meta, sheets=None)
    (tmp_path / "f").mkdir()
    files = write_all([("kinematic", bad)], brief, tmp_path, tmp_path / "f", "en", ("dxf",))
    assert files == []
    err = capsys.readouterr().err
    assert "Kinematic diagram could not be drawn (the layout does not fit)" in err
    with pytest.raises(ValueError):
        write_all([("analysis", bad)], brief, tmp_path, tmp_path / "f", "en", ("dxf",))


def test_sheet_notes_go_to_the_runs_warning_callback(tmp_path, capsys):
    """With the runner's ``on_warning`` the lines are handed to it (the run collects them
    and prints them as its warnings, in the report's language), not printed here."""
    from types import SimpleNamespace

    from mechdesign.render.sheets import make_sheets, write_all

    got = []
    make_sheets({}, None, tmp_path, tmp_path, "zh", ("md", "dxf"), on_warning=got.append)
    assert got and "没有可绘制的图纸" in got[0] and not got[0].startswith("提示")

    def bad(info, lang):
        raise ValueError("the layout does not fit")

    meta = SimpleNamespace(title="t", student="", student_id="", class_name="", teacher="", date="")
    brief = SimpleNamespace(report=meta, sheets=None)
    (tmp_path / "f").mkdir()
    write_all([("kinematic", bad)], brief, tmp_path, tmp_path / "f", "en", ("dxf",), on_warning=got.append)
    assert "Kinematic diagram could not be drawn (the layout does not fit)" in got[-1]
    assert capsys.readouterr().err == ""


def test_lockbeam_diagram_gives_the_cam_roller_its_own_letter(example_results):
    """Issue 19: the positioning pin's roller centre is F, not a second B (B is the bending
    four-bar's pin, as the report names it)."""
    r = example_results("lockbeam")
    sheet = _sheets(r)["kinematic"]
    texts = [plain(e.text) for e in sheet.entities if isinstance(e, Text)]
    assert texts.count("B") == 1 and texts.count("F") == 1


def test_lockbeam_diagram_gives_every_point_its_own_letter(example_results):
    """Issue 19: every point letter on the lock-beam diagram is written once; the feed
    crank's pin is A (the brief's feed_linkage.crank.tip) and the bending four-bar is
    G0 G B B0, as the report's bending section names it (not a second A); the main shaft O2
    carries the feed crank and both cams and is named O2 wherever it is drawn."""
    import re

    brief = yaml.safe_load((ROOT / "designs" / "lockbeam.yaml").read_text(encoding="utf-8"))
    assert brief["feed_linkage"]["crank"]["tip"] == "A"
    r = example_results("lockbeam")
    sheet = _sheets(r)["kinematic"]

    # the letters as read (O2 is drawn O₂: its digit a subscript, issue 19 point 3)
    letters = [plain(e.text) for e in sheet.entities if isinstance(e, Text)
               and re.fullmatch(r"[A-Z][0-9]?", plain(e.text)) and e.text != "A3"]   # A3: the sheet size
    # O2 is the one main shaft, drawn under each of the three groups it drives
    assert letters.count("O2") == 3
    others = [t for t in letters if t != "O2"]
    assert len(others) == len(set(others)), sorted(letters)
    assert {"A", "G0", "G", "B", "B0", "C", "F"} <= set(letters)
    assert "A0" not in letters


# GB/T 14690: reductions 1:1.5, 1:2, 1:2.5, 1:3, 1:4, 1:5, 1:6 (×10ⁿ); enlargements 2:1, 5:1
# (preferred), 2.5:1, 4:1 (allowed), 10:1 (×10ⁿ). The largest scale whose drawing fits.
@pytest.mark.parametrize("extent,box,enlarge,want", [
    (70 + 40j, 300 + 200j, True, "4:1"),        # 70·4 = 280 ≤ 300, 70·5 = 350 > 300
    (140 + 40j, 300 + 200j, True, "2:1"),       # 280 fits, 2.5·140 = 350 does not
    (110 + 40j, 300 + 200j, True, "2.5:1"),     # 275 fits, 4·110 = 440 does not
    (28 + 10j, 300 + 200j, True, "10:1"),       # 280 fits, 20·28 = 560 does not
    (5 + 5j, 300 + 200j, True, "40:1"),         # 40·5 = 200 fits the height, 50·5 = 250 not
    (200 + 40j, 300 + 200j, True, "1:1"),       # 2·200 = 400 > 300: no enlargement fits
    (70 + 40j, 300 + 200j, False, "1:1"),       # enlargement only where asked
    (450 + 40j, 300 + 200j, True, "1:1.5"),
    (1300 + 40j, 300 + 200j, True, "1:5"),      # 1300/300 = 4.33: 1:5
    (1300 + 40j, 300 + 200j, False, "1:5"),
])
def test_length_scale_is_the_largest_gb_scale_that_fits(extent, box, enlarge, want):
    from mechdesign.render.sheet import length_scale, scale_text

    n = length_scale(extent, box, enlarge=enlarge)
    assert scale_text(n) == want
    assert extent.real / n <= box.real + 1e-9 and extent.imag / n <= box.imag + 1e-9


def test_crank_rocker_sheets_enlarge_the_small_mechanism(example_results):
    """designs/crank_rocker.yaml: the four-bar is about 70 mm across, so its kinematic
    diagram (its first view; the slider-crank beside it has its own) and its analysis sheet
    draw it enlarged (m:1, m ≥ 2), not at 1:1; the shaper (about 600 mm) stays a reduction."""
    from mechdesign.render.sheets import _builders

    r = example_results("crank_rocker")
    built = {name: build(INFO, "zh") for name, build in _builders(r, None)}
    for name in ("kinematic", "analysis"):
        left, right = (float(x) for x in built[name].info.scale.split(",")[0].split(":"))
        assert right == 1 and left >= 2, (name, built[name].info.scale)
    assert _scale(_sheets(example_results("shaper"))["kinematic"]) > 1
