"""The shaper on the generic A1 analysis sheet: polygons built as the graphical method
builds them (by the group types, stored by the polygons stage), drawn to scale, and a DXF
that re-opens with the expected layers, vectors and dimensions.

References: the vector equations' directions (⊥ / ∥ to the links), closed forms
(ω2·L_O2A, ω2²·L_O2A), finite differences of the positions for the velocities, the
equilibrium of each Assur group (force polygons close), the brief's H and L_O2O3."""
from __future__ import annotations

import re

import numpy as np
import pytest

ezdxf = pytest.importorskip("ezdxf")

from mechdesign.render.analysis_sheet import analysis_sheet  # noqa: E402
from mechdesign.render.sheet import SIZES, Dimension, Text, TitleInfo, plain, text_width  # noqa: E402
from mechdesign.render.sheet_dxf import plain_text, write_dxf  # noqa: E402
from mechdesign.render.sheets import linkage_results  # noqa: E402
from mechdesign.stages.polygons import default_positions  # noqa: E402

INFO = TitleInfo("机构运动及动力分析图", "牛头刨床", "张三", "2023001", "机械 1", "李老师",
                 "2026-11-22", number="MD-01", sheet_no=1, sheets=3)


@pytest.fixture(scope="module")
def shaper_results(example_results):
    return example_results("shaper")


@pytest.fixture(scope="module")
def sheet(shaper_results):
    found = linkage_results(shaper_results)
    assert list(found.polygons.positions) == ["4", "10"]     # the brief's polygon_positions
    return analysis_sheet(found, INFO, "zh")


def polygons(r, label):
    """Velocity, acceleration and the force polygons of groups 5-6 and 3-4 at ``label``,
    as the polygons stage stored them (the brief's positions) or built afresh."""
    from mechdesign.stages.polygons import polygons as build

    stored = r["linkage_polygons"].polygons.get(label)
    ps = stored if stored is not None else build(r["model"], r["linkage"], r["linkage_raw"],
                                                 r["linkage_forces"], label)
    by_group = {pg.group: pg for pg in ps[2:]}
    return ps[0], ps[1], by_group["ram (RRP)"], by_group["guide bar (RPR)"]


def _unit(z):
    return z / abs(z)


def _perp(a, b):
    return abs((np.conj(_unit(a)) * _unit(b)).real)


def _par(a, b):
    return abs((np.conj(_unit(a)) * _unit(b)).imag)


@pytest.mark.parametrize("label", ["4", "10", "1", "7"])
def test_velocity_polygon_follows_the_vector_equations(shaper_results, label):
    r = shaper_results
    vel, acc, f56, f34 = polygons(r, label)
    k, motion, p = r["linkage"], r["linkage_raw"], r["params"]
    i = k.grid_size + list(k.positions.labels).index(label)
    P = {n: motion.points[n].pos[i] for n in ("O2", "O3", "A", "B", "F")}
    v = {x.name: x.value for x in vel.vectors}
    L_O2A = abs(P["A"] - P["O2"])
    w2 = abs(p.crank_omega)
    assert abs(v["pa"]) == pytest.approx(w2 * L_O2A, rel=1e-12)
    assert _perp(v["pa"], P["A"] - P["O2"]) < 1e-9
    assert _perp(v["pa4"], P["A"] - P["O3"]) < 1e-9
    assert _par(v["aa4"], P["A"] - P["O3"]) < 1e-9
    # image of the bar: pb/pa4 = O3B/O3A, same direction
    ratio = abs(P["B"] - P["O3"]) / abs(P["A"] - P["O3"])
    assert abs(v["pb"] - ratio * v["pa4"]) < 1e-9 * abs(v["pb"])
    assert abs(v["pf"].imag) < 1e-9 * abs(v["pb"])           # ram moves along its guide
    assert _perp(v["bf"], P["F"] - P["B"]) < 1e-7 or abs(v["bf"]) < 1e-9
    # the polygon's own closure: pa + aa4 = pa4, pb + bf = pf
    assert abs(v["pa"] + v["aa4"] - v["pa4"]) < 1e-12
    assert abs(v["pb"] + v["bf"] - v["pf"]) < 1e-12
    # finite differences of the positions alone (central, small crank step)
    mech = r["model"].mechanism
    h = 1e-6
    phi = k.crank_angle[i]
    ahead, back = mech.solve(np.array([phi + h])), mech.solve(np.array([phi - h]))
    dt = h / w2 * np.sign(p.crank_omega)
    for name, key in (("B", "pb"), ("F", "pf"), ("A", "pa")):
        fd = (ahead.points[name].pos[0] - back.points[name].pos[0]) / (2 * dt)
        assert abs(fd - v[key]) < 1e-6 * max(1.0, abs(v[key]))


@pytest.mark.parametrize("label", ["4", "10", "2"])
def test_acceleration_polygon_components(shaper_results, label):
    r = shaper_results
    vel, acc, _, _ = polygons(r, label)
    k, motion, p = r["linkage"], r["linkage_raw"], r["params"]
    i = k.grid_size + list(k.positions.labels).index(label)
    P = {n: motion.points[n].pos[i] for n in ("O2", "O3", "A", "B", "F")}
    a = {x.name: x.value for x in acc.vectors}
    v = {x.name: x.value for x in vel.vectors}
    w2 = abs(p.crank_omega)
    rA = P["A"] - P["O3"]
    # crank pin: centripetal only, towards O2
    assert abs(a["p'a'"] - w2 ** 2 * (P["O2"] - P["A"])) < 1e-9
    w4 = abs(v["pa4"]) / abs(rA)
    assert abs(a["p'n4'"]) == pytest.approx(w4 ** 2 * abs(rA), rel=1e-9)
    assert _par(a["p'n4'"], -rA) < 1e-9 and (np.conj(a["p'n4'"]) * -rA).real > 0
    assert _perp(a["n4'a4'"], rA) < 1e-9
    # Coriolis: 2 ω4 v_A4A3, perpendicular to the bar
    assert abs(a["a'k'"]) == pytest.approx(2 * w4 * abs(v["aa4"]), rel=1e-9)
    assert _perp(a["a'k'"], rA) < 1e-9
    assert _par(a["k'a4'"], rA) < 1e-9
    # both routes reach a4'
    assert abs(a["p'n4'"] + a["n4'a4'"] - (a["p'a'"] + a["a'k'"] + a["k'a4'"])) < 1e-9
    assert abs(a["p'f'"].imag) < 1e-9 * abs(a["p'b'"])
    assert _perp(a["n5'f'"], P["F"] - P["B"]) < 1e-6 or abs(a["n5'f'"]) < 1e-9
    # finite differences of the ram velocity
    mech = r["model"].mechanism
    h = 1e-5
    phi = k.crank_angle[i]
    dt = h / w2 * np.sign(p.crank_omega)
    vf = [mech.solve(np.array([phi + s * h])).points["F"].vel[0] for s in (1, -1)]
    assert abs((vf[0] - vf[1]) / (2 * dt) - a["p'f'"]) < 1e-5 * abs(a["p'f'"]) + 1e-6


@pytest.mark.parametrize("label", ["4", "10"])
def test_force_polygons_close(shaper_results, label):
    _, _, f56, f34 = polygons(shaper_results, label)
    for pg in (f56, f34):
        outer = [x for x in pg.vectors if x.role != "internal"]   # the diagonal R65 / R43
        total = sum(x.value for x in outer)
        scale = max(abs(x.value) for x in pg.vectors)
        assert abs(total) < 1e-9 * scale
        assert abs(pg.points[outer[-1].head]) < 1e-9 * scale
    names = [x.name for x in f56.vectors]
    fc = {x.name: x.value for x in f56.vectors}
    p = shaper_results["params"]
    if label == "4":       # inside the cutting zone: Fc = 1600 N against the motion
        assert abs(fc["Fc"]) == pytest.approx(p.cutting_force)   # named as Table 1 names it
        assert abs(fc["G6"]) == pytest.approx(p.m6 * p.gravity)
    else:                  # return stroke: no cutting force in the polygon
        assert "Fc" not in names


def test_default_positions_are_mid_working_and_mid_return(shaper_results):
    assert default_positions(shaper_results["linkage"]) == ["4", "10"]


@pytest.mark.e2e
def test_dxf_reopens_with_layers_vectors_and_dimensions(sheet, shaper_results, tmp_path):
    s, scales = sheet
    path = write_dxf(s, tmp_path / "linkage.dxf")
    doc = ezdxf.readfile(path)
    names = {layer.dxf.name for layer in doc.layers}
    assert {"OUTLINE", "CENTER", "CONSTRUCTION", "DIMENSIONS", "TEXT", "VECTORS", "CURVES",
            "FRAME"} <= names
    assert doc.layers.get("CENTER").dxf.linetype == "CENTER"
    msp = doc.modelspace()
    count = {}
    for e in msp:
        count[e.dxf.layer] = count.get(e.dxf.layer, 0) + 1
    for layer in ("OUTLINE", "CENTER", "CONSTRUCTION", "DIMENSIONS", "TEXT", "VECTORS",
                  "CURVES", "FRAME"):
        assert count.get(layer, 0) > 0, layer
    texts = [plain_text(e) for e in msp.query("TEXT MTEXT")]      # MTEXT: with subscripts
    assert "张三" in texts and "李老师" in texts and "1:4" in texts
    lines = [(complex(e.dxf.start.x, e.dxf.start.y), complex(e.dxf.end.x, e.dxf.end.y))
             for e in msp.query("LINE[layer=='VECTORS']")]
    vecs = np.array([b - a for a, b in lines])
    for label in ("4", "10"):
        vel, acc, _, _ = polygons(shaper_results, label)
        mu_v, mu_a = scales[f"velocity_{label}"], scales[f"acceleration_{label}"]
        # the scale the vectors are drawn at is the one written on the sheet
        assert f"μv = {mu_v:g} (m/s)/mm" in texts and f"μa = {mu_a:g} (m/s²)/mm" in texts
        for pg, mu in ((vel, mu_v), (acc, mu_a)):
            for x in pg.vectors:
                want = x.value / mu       # paper mm, same direction (the sheet is not mirrored)
                if abs(want) < 1e-6:
                    continue
                assert np.min(np.abs(vecs - want)) < 1e-6, (label, x.name)
    # the dimensions state the true lengths: the frame L_O2O3 and the stroke H of the brief
    measured = []
    for d in msp.query("DIMENSION"):
        lfac = d.get_dim_style().dxf.dimlfac
        override = d.override()
        lfac = override.get("dimlfac", lfac)
        measured.append(d.get_measurement() * lfac)
    assert any(abs(m - 650.0) < 1e-6 for m in measured)
    assert any(abs(m - 320.0) < 1e-6 for m in measured)


def test_everything_inside_the_border_and_texts_do_not_collide(sheet):
    s, _ = sheet
    w, h = SIZES["A1"]
    pts = []
    for e in s.entities:
        for attr in ("p0", "p1", "center", "position"):
            if hasattr(e, attr):
                pts.append(getattr(e, attr))
        pts.extend(getattr(e, "points", ()))
    pts = np.array(pts)
    assert pts.real.min() >= 0 and pts.real.max() <= w
    assert pts.imag.min() >= 0 and pts.imag.max() <= h
    x0, y0, x1, y1 = s.inner
    inner = [e for e in s.entities if getattr(e, "layer", "") != "FRAME"]
    for e in inner:
        for z in [getattr(e, a) for a in ("p0", "p1", "position") if hasattr(e, a)]:
            assert x0 <= z.real <= x1 and y0 <= z.imag <= y1, e
    boxes = []
    for t in s.entities:
        if not isinstance(t, Text) or t.angle:
            continue
        wd, ht = text_width(t.text, t.height), t.height
        cx = {"left": t.position.real + wd / 2, "center": t.position.real,
              "right": t.position.real - wd / 2}[t.halign]
        cy = {"bottom": t.position.imag + ht / 2, "middle": t.position.imag,
              "top": t.position.imag - ht / 2}[t.valign]
        boxes.append((cx - wd / 2, cy - ht / 2, cx + wd / 2, cy + ht / 2, t.text))
    clashes = []
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            ox = min(a[2], b[2]) - max(a[0], b[0])
            oy = min(a[3], b[3]) - max(a[1], b[1])
            if ox > 0.3 and oy > 0.3:
                clashes.append((a[4], b[4]))
    assert not clashes, clashes[:10]


@pytest.mark.e2e
def test_sheet_pdf_and_preview_are_written(sheet, tmp_path):
    from mechdesign.render.sheet_typst import write_sheet

    s, _ = sheet
    write_sheet(s, pdf=tmp_path / "a1.pdf", png=tmp_path / "a1.png", png_width_px=800)
    data = (tmp_path / "a1.pdf").read_bytes()
    assert data.startswith(b"%PDF")
    # true A1 paper size in points: 841 × 594 mm
    box = re.search(rb"/MediaBox *\[ *0 0 ([0-9.]+) ([0-9.]+)", data)
    assert box is not None
    assert float(box.group(1)) == pytest.approx(841 / 25.4 * 72, abs=0.5)
    assert float(box.group(2)) == pytest.approx(594 / 25.4 * 72, abs=0.5)
    from PIL import Image

    with Image.open(tmp_path / "a1.png") as im:
        assert im.size[0] == 800


def test_dimension_entities_for_the_mechanism(sheet):
    s, scales = sheet
    dims = [e for e in s.entities if isinstance(e, Dimension)]
    assert any(abs(d.measurement - 650.0) < 1e-9 for d in dims)
    # paper length × scale = true length for every aligned dimension of the mechanism
    for d in dims:
        if d.kind == "aligned" and d.measurement in (650.0,):
            assert abs(d.p1 - d.p0) * scales["length"] == pytest.approx(650.0)


def test_guide_height_dimension_and_link_names(sheet, shaper_results):
    """The ram guide's distance from O3 by the closed form of the guide-bar synthesis: the
    guide halves the sagitta of B's arc, L_O3M = L_O3B (1 + cos(ψ/2)) / 2 with
    L_O3B = H / (2 sin(ψ/2)), ψ = θ = 180° (K − 1)/(K + 1); the links named on the sheet."""
    s, scales = sheet
    H, K = 320.0, 1.2
    half = np.radians(180.0 * (K - 1) / (K + 1)) / 2
    guide = H / (2 * np.sin(half)) * (1 + np.cos(half)) / 2
    dims = [e for e in s.entities if isinstance(e, Dimension)]
    hit = [d for d in dims if abs(d.measurement - guide) < 1e-6]
    assert hit and abs(abs(hit[0].p1 - hit[0].p0) * scales["length"] - guide) < 1e-6
    texts = [t.text for t in s.entities if isinstance(t, Text)]
    # point names carry subscript markers on the sheet (O₂A): compare the plain text
    legend = plain(next(t for t in texts if t.startswith("构件：")))
    for link, name in (("2", "曲柄 O2A"), ("3", "滑块 A"), ("4", "导杆 O3B"), ("5", "连杆 BF"),
                       ("6", "刨头")):
        assert f"{link} {name}" in legend
        assert link in texts                 # the number beside the link on the skeleton
    assert "刨头导路" in texts


def test_energy_chart_uses_the_work_curves(sheet, shaper_results):
    """W_d straight, W_r = ∫M_b dφ and ΔE = W_d − W_r, with the ΔW_max dimension: the
    dimension states ΔW_max of the energy cycle, found here from M_b by the trapezoid rule
    (independent of the flywheel stage)."""
    s, _ = sheet
    texts = [plain(t.text) for t in s.entities if isinstance(t, Text)]     # W_d, W_r
    assert {"Wd", "Wr", "ΔE"} <= set(texts)
    k, f = shaper_results["linkage"], shaper_results["linkage_forces"]
    n = k.grid_size
    mb = np.append(f.balancing_torque[:n], f.balancing_torque[0])
    phi = np.append(k.phase[:n], 2 * np.pi)
    w_r = np.concatenate([[0.0], np.cumsum(0.5 * (mb[1:] + mb[:-1]) * np.diff(phi))])
    e = w_r[-1] / (2 * np.pi) * phi - w_r
    swing = e.max() - e.min()
    dims = [d for d in s.entities if isinstance(d, Dimension) and plain(d.text).startswith("ΔWmax")]
    assert len(dims) == 1 and dims[0].measurement == pytest.approx(swing, rel=1e-3)
