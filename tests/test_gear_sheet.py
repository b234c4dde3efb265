"""The gear meshing sheet (齿轮啮合图), checked in the DXF as a CAD user would read it.

Each sheet is written with ``write_dxf`` and re-opened with ezdxf. The scale is read from
the title block's text; the centres are found as the centres of the pitch circles, which
must have the radius m z / 2 on paper, a′ apart. Independently of the core, the test
computes the working pressure angle (inv α′ = 2 tan α (x1 + x2)/(z1 + z2) + inv α), the
tip radii (with the tip reduction Δy m) and the contact ratio
ε = [z1 (tan αa1 − tan α′) + z2 (tan αa2 − tan α′)] / 2π, and checks on the drawing: the
line N1N2 tangent to both base circles, B1B2 / scale / pb = ε with B1, B2 on the tip
circles, every tooth outline point between the root and tip circles, the dimensions'
values and arrow ends, the labels, and nothing outside the border.
"""
from __future__ import annotations

import re
from math import radians

import ezdxf
import numpy as np
import pytest
from ezdxf import bbox
from scipy.optimize import brentq

from mechdesign.core.gears import spur_pair
from mechdesign.stages.gear import gear_drawing
from mechdesign.render.gear_sheet import gear_sheet
from mechdesign.render.sheet import SIZES, TitleInfo, title_block_box
from mechdesign.render.sheet_dxf import plain_text, write_dxf
from mechdesign.render.sheet_typst import write_sheet

pytestmark = pytest.mark.e2e     # renders drawing sheets (see tests/conftest.py)

PAIRS = {
    # (m [m], z1, z2, α, ha*, c*, x1, x2)
    "shaper": (0.012, 18, 60, radians(20), 1.0, 0.25, 0.0, 0.0),
    "shifted": (0.005, 12, 40, radians(20), 1.0, 0.25, 0.4, 0.1),
    "pusher": (0.002, 20, 79, radians(20), 1.0, 0.25, 0.0, 0.0),
    "small": (0.001, 13, 20, radians(20), 1.0, 0.25, 0.3, 0.0),      # both centres on the sheet
    "big": (0.010, 60, 90, radians(20), 1.0, 0.25, 0.0, 0.0),        # the pinion cut by the border
}
GB_SCALES = {"10:1", "5:1", "4:1", "2.5:1", "2:1", "1:1", "1:1.5", "1:2", "1:2.5", "1:3", "1:4",
             "1:5", "1:6", "1:10"}


def reference(m, z1, z2, alpha, ha, c, x1, x2):
    """The pair's geometry in mm from the textbook formulas (not from the core)."""
    m = m * 1e3
    inv = lambda a: np.tan(a) - a  # noqa: E731
    target = 2 * np.tan(alpha) * (x1 + x2) / (z1 + z2) + inv(alpha)
    alpha_w = brentq(lambda a: inv(a) - target, 1e-6, 1.5) if x1 + x2 else alpha
    a = m * (z1 + z2) / 2
    a_w = a * np.cos(alpha) / np.cos(alpha_w)
    dy = x1 + x2 - (a_w - a) / m
    out = {"m": m, "a_w": a_w, "alpha_w": alpha_w, "pb": np.pi * m * np.cos(alpha)}
    for i, z, x in ((1, z1, x1), (2, z2, x2)):
        r = m * z / 2
        out[f"r{i}"] = r
        out[f"rb{i}"] = r * np.cos(alpha)
        out[f"ra{i}"] = r + (ha + x - dy) * m
        out[f"rf{i}"] = r - (ha + c - x) * m
        out[f"alpha_a{i}"] = np.arccos(out[f"rb{i}"] / out[f"ra{i}"])
    tw = np.tan(alpha_w)
    out["eps"] = (z1 * (np.tan(out["alpha_a1"]) - tw) + z2 * (np.tan(out["alpha_a2"]) - tw)) / (2 * np.pi)
    return out


def xy(p) -> complex:
    return complex(p[0], p[1])


def text_point(t) -> complex:
    """Where a TEXT entity is anchored (its alignment point unless left/baseline); an MTEXT
    (a text with subscripts) at its insertion point."""
    if t.dxftype() == "MTEXT":
        return xy(t.dxf.insert)
    if t.dxf.halign == 0 and t.dxf.valign == 0:
        return xy(t.dxf.insert)
    return xy(t.dxf.align_point)


def arcs(msp, layer):
    """(centre, radius) of the circles and arcs on ``layer``."""
    return [(xy(e.dxf.center), e.dxf.radius) for e in msp.query(f'CIRCLE ARC[layer=="{layer}"]')]


def find_circle(circles, centre, radius, tol=1e-6):
    return any(abs(c - centre) < tol and abs(r - radius) < tol for c, r in circles)


def read_scale(sheet, msp) -> float:
    """Paper mm per model mm, from the scale written in the title block."""
    x0, y0, x1, y1 = title_block_box(sheet)
    found = []
    for t in msp.query("TEXT"):
        p = text_point(t)
        hit = re.fullmatch(r"(\d+(?:\.\d+)?):(\d+(?:\.\d+)?)", t.dxf.text.strip())
        if hit and x0 <= p.real <= x1 and y0 <= p.imag <= y1:
            found.append(float(hit.group(1)) / float(hit.group(2)))
    assert len(found) == 1, found
    return found[0]


@pytest.fixture(scope="module", params=[("shaper", "zh", None), ("shifted", "en", None),
                                        ("pusher", "zh", None), ("shaper", "en", "A3"),
                                        ("small", "zh", None), ("big", "en", None)],
                ids=["shaper-zh", "shifted-en", "pusher-zh", "shaper-A3", "small-zh", "big-en"])
def drawn(request, tmp_path_factory):
    name, lang, size = request.param
    pair = spur_pair(*PAIRS[name])
    info = TitleInfo(drawing="", project="Course design", student="Student", lang=lang)
    sheet = gear_sheet(gear_drawing(pair), info, lang, size)
    path = write_dxf(sheet, tmp_path_factory.mktemp("dxf") / f"{name}.dxf")
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    ref = reference(*PAIRS[name])
    k = read_scale(sheet, msp)
    # the centres: the pitch circles have the radius m z / 2 on paper
    centre = {}
    for i in (1, 2):
        hits = [c for c, r in arcs(msp, "CENTER") if abs(r - k * ref[f"r{i}"]) < 1e-6]
        assert hits, f"no pitch circle of gear {i} with r = m z{i} / 2 × scale"
        centre[i] = hits[0]
    texts = {}
    for t in msp.query("TEXT MTEXT"):            # subscripts as plain letters: "N1", "rb1"
        texts.setdefault(plain_text(t), []).append(text_point(t))
    return dict(name=name, lang=lang, size=size, pair=pair, sheet=sheet, doc=doc, msp=msp,
                ref=ref, k=k, o1=centre[1], o2=centre[2], texts=texts)


def labelled_line(d, query, first, second):
    """The line whose ends lie next to the labels ``first`` and ``second``."""
    a, b = d["texts"][first][0], d["texts"][second][0]
    best = min(d["msp"].query(query),
               key=lambda e: min(abs(xy(e.dxf.start) - a) + abs(xy(e.dxf.end) - b),
                                 abs(xy(e.dxf.start) - b) + abs(xy(e.dxf.end) - a)))
    p, q = xy(best.dxf.start), xy(best.dxf.end)
    if abs(p - a) > abs(p - b):
        p, q = q, p
    assert abs(p - a) < 12.0 and abs(q - b) < 12.0
    return p, q


def line_distance(c, p, q):
    u = (q - p) / abs(q - p)
    return abs(((c - p) * np.conj(u)).imag)


def test_layers_and_entity_counts(drawn):
    msp, doc = drawn["msp"], drawn["doc"]
    for layer in ("OUTLINE", "CONSTRUCTION", "CENTER", "DIMENSIONS", "TEXT", "FRAME"):
        assert layer in doc.layers
    outlines = msp.query('LWPOLYLINE[layer=="OUTLINE"]')
    assert len(outlines) >= 6                       # at least three teeth of each gear
    assert len(msp.query('CIRCLE ARC[layer=="CENTER"]')) >= 2
    assert len(msp.query('CIRCLE ARC[layer=="CONSTRUCTION"]')) >= 6   # base, tip, root × 2
    dims = msp.query('DIMENSION[layer=="DIMENSIONS"]')
    assert len(dims) >= 7                           # r, rb, ra, rf of the pinion, ≥ 3 of the gear
    assert len(msp.query('TEXT[layer=="TEXT"]')) >= 60
    for name in ("P", "N1", "N2", "B1", "B2", "O1"):
        assert name in drawn["texts"], name
    assert "O2" in drawn["texts"] or any(t.startswith("O2") for t in drawn["texts"])
    action = "理论啮合线 N1N2" if drawn["lang"] == "zh" else "theoretical line of action N1N2"
    assert action in drawn["texts"]
    assert drawn["sheet"].info.scale in GB_SCALES
    assert drawn["sheet"].size == (drawn["size"] or drawn["sheet"].size)


def test_scale_and_circles(drawn):
    ref, k, o1, o2 = drawn["ref"], drawn["k"], drawn["o1"], drawn["o2"]
    assert abs(abs(o2 - o1) - k * ref["a_w"]) < 1e-6
    assert abs((o2 - o1).real) < 1e-6               # line of centres vertical, O2 above
    assert o2.imag > o1.imag
    for i, c in ((1, o1), (2, o2)):
        for key in ("rb", "ra", "rf"):
            assert find_circle(arcs(drawn["msp"], "CONSTRUCTION"), c, k * ref[f"{key}{i}"]), key
    # the teeth are readable: the module on paper is 5 mm or more
    assert k * ref["m"] >= 5.0


def test_line_of_action_tangent_to_both_base_circles(drawn):
    ref, k = drawn["ref"], drawn["k"]
    n1, n2 = labelled_line(drawn, 'LINE[layer=="CONSTRUCTION"]', "N1", "N2")
    assert abs(line_distance(drawn["o1"], n1, n2) - k * ref["rb1"]) < 1e-6
    assert abs(line_distance(drawn["o2"], n1, n2) - k * ref["rb2"]) < 1e-6
    assert abs(abs(n1 - drawn["o1"]) - k * ref["rb1"]) < 1e-6          # the tangent points
    assert abs(abs(n2 - drawn["o2"]) - k * ref["rb2"]) < 1e-6
    # inclined at α′ to the common tangent (horizontal)
    assert abs(np.arctan(abs((n2 - n1).imag / (n2 - n1).real)) - ref["alpha_w"]) < 1e-9


def test_actual_line_of_action_gives_the_contact_ratio(drawn):
    ref, k = drawn["ref"], drawn["k"]
    b1, b2 = labelled_line(drawn, 'LINE[layer=="OUTLINE"]', "B1", "B2")
    assert abs(abs(b1 - drawn["o1"]) - k * ref["ra1"]) < 1e-6
    assert abs(abs(b2 - drawn["o2"]) - k * ref["ra2"]) < 1e-6
    eps = abs(b1 - b2) / k / ref["pb"]
    assert eps == pytest.approx(ref["eps"], abs=1e-9)
    # both values in the data table
    shown = f"{ref['eps']:.3f}"            # the number rule (render/fmt.py): ε to 0.001
    assert len(drawn["texts"].get(shown, [])) >= 2
    # the pitch point on the line of centres, on B1B2
    p = drawn["texts"]["P"][0]
    assert abs(p - (drawn["o1"] + 1j * k * ref["a_w"] * ref["rb1"] / (ref["rb1"] + ref["rb2"]))) < 12.0


def test_tooth_outlines_between_root_and_tip_circles(drawn):
    ref, k = drawn["ref"], drawn["k"]
    teeth = {1: 0, 2: 0}
    for e in drawn["msp"].query('LWPOLYLINE[layer=="OUTLINE"]'):
        pts = np.array([complex(x, y) for x, y in e.get_points("xy")])
        placed = False
        for i, c in ((1, drawn["o1"]), (2, drawn["o2"])):
            r = np.abs(pts - c)
            if np.all(r >= k * ref[f"rf{i}"] - 1e-6) and np.all(r <= k * ref[f"ra{i}"] + 1e-6):
                teeth[i] += 1
                placed = True
                # a whole tooth: reaches both the tip and the root circle
                assert np.max(r) == pytest.approx(k * ref[f"ra{i}"], abs=1e-6)
                assert np.min(r) == pytest.approx(k * ref[f"rf{i}"], abs=1e-6)
                break
        assert placed, "a tooth outline leaves the band between the root and tip circles"
    assert teeth[1] >= 3 and teeth[2] >= 3


def test_dimensions_write_the_true_radii(drawn):
    ref, k = drawn["ref"], drawn["k"]
    seen = set()
    for dim in drawn["msp"].query("DIMENSION"):
        hit = re.fullmatch(r"(r|rb|ra|rf)([12]) = ([\d.]+)", plain_text(dim))
        if not hit:
            continue
        key = hit.group(1) + hit.group(2)
        centre = drawn["o1"] if hit.group(2) == "1" else drawn["o2"]
        assert float(hit.group(3)) == pytest.approx(ref[key], abs=0.006)
        assert abs(abs(xy(dim.dxf.defpoint4) - centre) - k * ref[key]) < 1e-6   # arrow on the circle
        seen.add(key)
    assert {"r1", "rb1", "ra1", "rf1"} <= seen
    assert len(seen & {"r2", "rb2", "ra2", "rf2"}) >= 3
    a_text = f"a′ = {ref['a_w']:.2f}"      # a length to 0.01 mm (render/fmt.py)
    assert any(plain_text(t) == a_text for t in drawn["msp"].query("TEXT DIMENSION"))
    assert any(t.startswith("α′ = ") for t in drawn["texts"])


def test_nothing_outside_the_border(drawn):
    sheet = drawn["sheet"]
    x0, y0, x1, y1 = sheet.inner
    w, h = SIZES[sheet.size]
    bx0, by0, bx1, by1 = title_block_box(sheet)
    cache = bbox.Cache()
    for e in drawn["msp"]:
        if e.dxftype() == "TEXT" and bx0 <= text_point(e).real <= bx1 and by0 <= text_point(e).imag <= by1:
            continue            # the title block's own texts (frame()), fitted by estimate
        box = bbox.extents([e], cache=cache)
        if not box.has_data:
            continue
        lo, hi = box.extmin, box.extmax
        if e.dxf.layer == "FRAME":
            assert -1e-6 <= lo.x and hi.x <= w + 1e-6 and -1e-6 <= lo.y and hi.y <= h + 1e-6
        else:
            assert x0 - 0.01 <= lo.x and hi.x <= x1 + 0.01, (e.dxftype(), e.dxf.layer, lo, hi)
            assert y0 - 0.01 <= lo.y and hi.y <= y1 + 0.01, (e.dxftype(), e.dxf.layer, lo, hi)
    # and the drawing keeps clear of the title block
    for e in drawn["msp"]:
        if e.dxf.layer in ("FRAME",) or e.dxftype() == "TEXT" and e.dxf.layer == "TEXT":
            continue
        box = bbox.extents([e], cache=cache)
        if box.has_data:
            assert box.extmax.x <= bx0 + 1e-6 or box.extmax.y <= by0 or box.extmin.y >= by1 - 1e-6 \
                or box.extmin.x >= bx1, (e.dxftype(), e.dxf.layer)


def test_sheet_size_and_preview(tmp_path):
    pair = spur_pair(*PAIRS["shaper"])
    sheet = gear_sheet(gear_drawing(pair), TitleInfo(drawing="齿轮啮合图", project="牛头刨床"), "zh")
    assert sheet.size == "A2" and sheet.info.scale == "1:1"
    assert sheet.info.drawing == "齿轮啮合图"
    png = tmp_path / "gear.png"
    write_sheet(sheet, png=png, png_width_px=1200)
    assert png.stat().st_size > 20_000
    small = gear_sheet(gear_drawing(spur_pair(*PAIRS["pusher"])), TitleInfo(drawing="", project=""), "en")
    assert small.info.scale == "5:1"                # m = 2 mm enlarged: 10 mm on paper
    assert small.info.drawing == "Gear meshing drawing"
