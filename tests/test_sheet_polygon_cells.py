"""The A1 analysis sheet as a reader gets it (issue 19 point 8, review of session 31): its
polygons fill their cells, its vector list names the quantities the report names (v_A4A3 in
m/s, a^n_BO3 in m/s², not the segment "aa4" with a velocity's unit read as an acceleration),
its table numbers the links as the report does (ω4 of the shaper's guide bar 4, not ω3 of
its slider), every point of the mechanism is named on it, in italic as the report sets
point names.

Read from the written files: the DXF with ezdxf (the cells are the thin closed frames, the
polygons the VECTORS lines, texts by their MTEXT codes), the PDF's words with their boxes
with PyMuPDF (as pdftotext -bbox gives them). References: the cell's own size, the units
of the quantities, the graphical method's vector equations and rates (the report's
numbering), the mechanism's joints."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
BRIEFS = ["shaper", "press", "slotter", "lockbeam"]


@pytest.fixture(scope="module", params=BRIEFS)
def written(request, example_results, tmp_path_factory):
    from mechdesign.brief.loader import load_brief
    from mechdesign.render.sheets import _builders, linkage_results, write_all

    name = request.param
    brief = load_brief(ROOT / "designs" / f"{name}.yaml")
    results = example_results(name)
    folder = tmp_path_factory.mktemp(f"sheets-{name}")
    (folder / "f").mkdir()
    builders = [(n, b) for n, b in _builders(results, brief) if n == "analysis"]
    files = write_all(builders, brief, folder, folder / "f", "en", ("pdf", "dxf"))
    (f,) = files
    return name, results, linkage_results(results), folder / f.pdf, folder / f.dxf


def _cells(msp):
    """(x0, y0, x1, y1) of the polygon cells: the thin closed frames of the CONSTRUCTION
    layer (lineweight 0.13 mm)."""
    out = []
    for e in msp.query("LWPOLYLINE[layer=='CONSTRUCTION']"):
        pts = np.array([(p[0], p[1]) for p in e.get_points()])
        if e.closed and len(pts) == 4 and e.dxf.get("lineweight", -1) == 13:
            out.append((pts[:, 0].min(), pts[:, 1].min(), pts[:, 0].max(), pts[:, 1].max()))
    return out


def _inside(p, box, pad=0.0):
    return box[0] - pad <= p[0] <= box[2] + pad and box[1] - pad <= p[1] <= box[3] + pad


def test_every_polygon_fills_its_cell(written):
    """The polygon spans at least 60 % of the room its cell leaves it in the limiting
    direction: the cell's width less 8 mm a side, or its height between the list of values
    under it and the scale written above it (old sheets: 1-2-2.5-5 steps, as little as
    half; the shaper's acceleration polygon at position 4 took 46 % of the height)."""
    import ezdxf
    from mechdesign.render.sheet_dxf import plain_text

    name, *_, dxf = written
    msp = ezdxf.readfile(dxf).modelspace()
    cells = _cells(msp)
    assert len(cells) >= 4, name
    lines = [(np.array([e.dxf.start.x, e.dxf.start.y]), np.array([e.dxf.end.x, e.dxf.end.y]))
             for e in msp.query("LINE[layer=='VECTORS']")]
    texts = [(plain_text(e), np.array([e.dxf.insert.x, e.dxf.insert.y]), e.dxf.char_height)
             for e in msp.query("MTEXT TEXT") if e.dxftype() == "MTEXT"] + \
        [(e.dxf.text, np.array([e.dxf.align_point.x, e.dxf.align_point.y]), e.dxf.height)
         for e in msp.query("TEXT")]
    checked = 0
    for box in cells:
        pts = np.array([p for a, b in lines for p in (a, b) if _inside(a, box) and _inside(b, box)])
        if len(pts) < 2:
            continue                  # a cell without a load ("no load at this position")
        inner = [(t, p, h) for t, p, h in texts if _inside(p, box)]
        scale = [p[1] - h for t, p, h in inner if t.startswith("μ")]
        values = [p[1] for t, p, h in inner if " = " in t and not t.startswith("μ")
                  and p[1] < pts[:, 1].min()]
        assert scale, (name, box)
        top = min(scale) - 1.0
        bottom = (max(values) + 1.0) if values else box[1]
        room_x, room_y = box[2] - box[0] - 16.0, top - bottom
        span = np.ptp(pts, axis=0)
        fill = max(span[0] / room_x, span[1] / room_y)
        assert fill >= 0.6, (name, box, span, (room_x, room_y), fill)
        assert span[0] <= room_x + 1e-6 and span[1] <= room_y + 6.0, (name, box, span)
        checked += 1
    assert checked >= 4, name


def test_vector_list_names_the_quantities_with_their_units(written):
    """In a velocity cell every vector is v with its points as subscript, in m/s; in an
    acceleration cell a with its points (and n, t, k, r as superscript) in m/s²; the report's symbols for the
    segments the graphical method names (old sheets: "aa4 = 0.09666 m/s", the segment's
    name, read as an acceleration)."""
    import pymupdf

    name, results, found, pdf, _ = written
    with pymupdf.open(pdf) as doc:
        lines = ["".join(s["text"] for s in line["spans"])
                 for block in doc[0].get_text("dict")["blocks"] for line in block.get("lines", [])]
    vel = [t for t in lines if re.search(r" = \S+ m/s$", t)]
    acc = [t for t in lines if re.search(r" = \S+ m/s²$", t)]
    assert vel and acc, name
    for t in vel:
        assert re.match(r"v[A-Z][A-Z0-9]* = ", t), (name, t)
    for t in acc:
        assert re.match(r"a[A-Z][A-Z0-9]*[ntkr]? = ", t), (name, t)
    # the report's symbols are all there (graphical document of the same positions)
    doc = results[f"{found.polygons.prefix}_graphical"]
    want = set()
    for pos in doc.positions:
        for poly in (pos.velocity, pos.acceleration):
            first = {}                  # a segment's first symbol (v_A, not v_AO2 = v_A3)
            for eq in poly.equations:
                rel = [t for t in eq.left + eq.right if t.kind != "absolute"]
                if rel and all(t.known and t.length == 0 for t in rel):
                    continue    # two points of a link in translation (v_S6F = 0): no result,
                                # the report leaves the equation out and the cell the vector
                for t in list(eq.left) + list(eq.right):
                    if t.tail and t.head and t.tail != t.head:
                        first.setdefault((t.tail, t.head), t.symbol)
            # "a^n_BO3" reads "aBO3n": a, its subscript, then the superscript
            want |= {re.sub(r"^(\w)(?:\^(\w))?_?(\w*)$", r"\1\3\2", s) for s in first.values()}
    have = {t.split(" = ")[0] for t in vel + acc}
    assert want <= have, (name, sorted(want - have))


def test_table_numbers_the_links_as_the_report(written):
    """The table's ω columns name links, not a slider block that turns with its guide: the
    report names the guide (the shaper's guide-bar table: ω4 of bar 4; old sheets: ω3 of
    slider 3, whose ω is the bar's)."""
    import pymupdf
    from mechdesign.stages.linkage import link_members

    name, results, found, pdf, _ = written
    with pymupdf.open(pdf) as doc:
        lines = ["".join(s["text"] for s in line["spans"])
                 for block in doc[0].get_text("dict")["blocks"] for line in block.get("lines", [])]
    heads = {m[1] for t in lines for m in [re.fullmatch(r"ω(\w+) \(rad/s\)", t.strip())] if m}
    assert heads, name
    k = found.motion
    _, sliders = link_members(found.model.mechanism)
    turning = {s for s, *_ in sliders if np.ptp(np.asarray(k.link_omega[s])) > 1e-12}
    assert not heads & turning, (name, heads, turning)
    for s, _, guide, _ in sliders:
        if s in turning and isinstance(guide, str):   # the guide has the same ω, and is named
            assert np.allclose(k.link_omega[s], k.link_omega[guide])
            assert guide in heads, (name, guide, heads)


def test_every_point_is_named_in_italic(written):
    """Every joint and frame point of the mechanism is named on the sheet, each name set
    in italic: in the DXF an MTEXT obliqued (\\Q15;) around its letters."""
    import ezdxf
    from mechdesign.render.sheet_dxf import plain_text

    name, results, found, _, dxf = written
    msp = ezdxf.readfile(dxf).modelspace()
    mech = found.model.mechanism
    joints = {j.point for js in mech.joints.values() for j in js} | set(mech.frame_points)
    italic = {plain_text(e) for e in msp.query("MTEXT") if "\\Q15;" in e.text}
    missing = sorted(p for p in joints if p in found.motion.points and p not in italic)
    assert not missing, (name, missing)
