"""The generic A1 analysis sheet and the polygons the group types build.

References, all independent of the polygon code: finite differences of positions solved
again at nearby crank angles (velocities) and of the analytic velocities (accelerations);
the Coriolis term 2ω·v_rel from the bar's ω and the slider's sliding speed; the point of the
guide bar under the slider pin differentiated twice by finite differences of the bar's
motion; Newton's second law for every Assur group (ΣF = 0 of its known loads and
reactions); the balancing torque from the power balance −ΣP/ω, which never looks at a
reaction. The sheet is checked for texts and boxes that overlap and for a DXF with the
same entities."""
from __future__ import annotations

from collections import Counter

import numpy as np
import pytest

from mechdesign.core.mechanism import RPR, Crank
from mechdesign.core.polygons import image_name, kinematic_polygon
from mechdesign.render.analysis_sheet import analysis_sheet
from mechdesign.render.sheet import (SIZES, Arc, Circle, Dimension, Fill, Line, Polyline, Text,
                                     TitleInfo, boxes_overlap, text_width)
from mechdesign.stages.polygons import chosen_positions, entry, polygons

MACHINES = ["linkage_sixbar", "furnace_pusher", "die_cutter", "lockbeam", "shaper", "slotter", "press"]
INFO = TitleInfo("机构运动及动力分析图", "课程设计", "张三", "2023001", "机械 1", "李老师",
                 "2026-11-22", number="MD-01", sheet_no=1, sheets=1)


@pytest.fixture(scope="module", params=MACHINES)
def run(request):
    from mechdesign.brief.loader import load_brief
    from mechdesign.machines import get_machine, stages_for
    from mechdesign.pipeline import run_stages
    from mechdesign.render.sheets import _builders, linkage_results

    b = load_brief(f"designs/{request.param}.yaml")
    m = get_machine(b.machine)
    p = m.to_params(b)
    results, _ = run_stages(stages_for(m, p), {"params": p, "brief": b}, None)
    found = linkage_results(results)
    assert found is not None
    assert "analysis" in [name for name, _ in _builders(results, b)]
    prefix = found.polygons.prefix
    assert results[found.polygons.model_key] is found.model
    raw = results[f"{prefix}_raw"]
    # the polygons stage stored the polygons of the brief's (or the default) positions
    assert list(found.polygons.positions) == chosen_positions(found.motion, b, found.forces,
                                                              found.model.mechanism, raw)
    return request.param, (found.model, found.motion, raw, found.forces, found.flywheel), found


def _labels(k):
    return [str(x) for x in k.positions.labels]


def _fd(model, phi, h, name, what):
    """Central difference in time of a point's position ("pos") or velocity ("vel")."""
    w = model.crank_omega
    ahead = model.mechanism.solve(np.array([phi + h]))
    back = model.mechanism.solve(np.array([phi - h]))
    dt = h / w
    return (getattr(ahead.points[name], what)[0] - getattr(back.points[name], what)[0]) / (2 * dt)


def _points_of(mech, raw, prime=""):
    """Polygon point name → mechanism point, for the moving points (the pole, image of
    every frame point, is left out)."""
    return {image_name(pt, prime): pt for pt in raw.points if pt not in mech.frame_points}


def _check_closure(pg, scale):
    for v in pg.vectors:
        assert abs(pg.points[v.head] - pg.points[v.tail] - v.value) <= 1e-9 * scale, v.name
    named = {v.name: v.value for v in pg.vectors}
    for eq in pg.equations:
        left = sum((named[n] for n in eq.left), 0j)
        right = sum((named[n] for n in eq.right), 0j)
        assert abs(left - right) <= 1e-9 * scale, eq.text


def test_velocity_polygons_close_and_match_finite_differences(run):
    name, (model, k, raw, forces, fly), found = run
    mech = model.mechanism
    for label in _labels(k)[::2]:
        i = entry(k, label)
        pg = kinematic_polygon(mech, raw, i, label, "velocity")
        scale = max(abs(z) for z in pg.points.values())
        _check_closure(pg, scale)
        assert pg.equations
        for point in raw.points:
            if point in mech.frame_points:
                continue
            fd = _fd(model, k.crank_angle[i], 1e-6, point, "pos")
            assert abs(pg.points[image_name(point)] - fd) <= 1e-6 * scale, (name, label, point)
        point_of = _points_of(mech, raw)
        for v in pg.vectors:                  # relative velocities ⊥ the line joining the points
            a, b = point_of.get(v.tail), point_of.get(v.head)
            if v.role == "relative" and a in raw.points and b in raw.points and abs(v.value) > 0:
                r = raw.points[b].pos[i] - raw.points[a].pos[i]
                assert abs((np.conj(v.value) * r).real) <= 1e-9 * abs(v.value) * abs(r)


def test_acceleration_polygons_close_and_match_finite_differences(run):
    name, (model, k, raw, forces, fly), found = run
    mech = model.mechanism
    for label in _labels(k)[1::3]:
        i = entry(k, label)
        pg = kinematic_polygon(mech, raw, i, label, "acceleration")
        scale = max(abs(z) for z in pg.points.values())
        _check_closure(pg, scale)
        for point in raw.points:
            if point in mech.frame_points:
                continue
            fd = _fd(model, k.crank_angle[i], 1e-5, point, "vel")
            assert abs(pg.points[image_name(point, "'")] - fd) <= 1e-5 * scale, (name, label, point)
        # a normal component points from the moving point back along the link, the
        # tangential one is perpendicular to it
        point_of = _points_of(mech, raw, "'")
        for v in pg.vectors:
            tail = point_of.get(v.tail)
            if v.role != "normal" or tail not in raw.points:
                continue
            t = next((x for x in pg.vectors if x.tail == v.head and x.role == "tangential"), None)
            head = point_of.get(t.head if t is not None else v.head)
            if head not in raw.points:
                continue
            r = raw.points[head].pos[i] - raw.points[tail].pos[i]
            if abs(v.value) > 1e-12 * scale:
                assert abs((np.conj(v.value) * r).imag) <= 1e-9 * abs(v.value) * abs(r)
                assert (np.conj(v.value) * r).real < 0
            if t is not None and abs(t.value) > 1e-12 * scale:
                assert abs((np.conj(t.value) * r).real) <= 1e-9 * abs(t.value) * abs(r)


def test_coriolis_term_of_the_guide_bar(run):
    name, (model, k, raw, forces, fly), found = run
    mech = model.mechanism
    bars = [g for g in mech.groups if isinstance(g, RPR)]
    if not bars:
        pytest.skip("no sliding pair on a turning guide")
    g = bars[0]
    for label in _labels(k):
        i = entry(k, label)
        vel = kinematic_polygon(mech, raw, i, label, "velocity")
        acc = kinematic_polygon(mech, raw, i, label, "acceleration")
        w = raw.links[g.bar].omega[i]
        v_rel = next(v for v in vel.vectors if v.role == "sliding").value
        cor = next(v for v in acc.vectors if v.role == "coriolis").value
        # 2ω·v_rel turned 90° in the sense of ω: magnitude and direction
        assert abs(cor) == pytest.approx(2 * abs(w) * abs(v_rel), rel=1e-12, abs=1e-15)
        assert abs(cor - 2j * w * v_rel) <= 1e-12 * max(abs(cor), 1e-12)
        # the sliding speed itself: the slider's distance along the bar, differentiated
        h = 1e-6
        phi = k.crank_angle[i]
        s = [mech.solve(np.array([phi + d])).slides[g.slider].s[0] for d in (h, -h)]
        ds = (s[0] - s[1]) / (2 * h / model.crank_omega)
        assert abs(v_rel) == pytest.approx(abs(ds), rel=1e-6, abs=1e-9)
        # the bar's point under the pin: rigid with the bar, differentiated twice
        m0 = mech.solve(np.array([phi]))
        r0 = m0.points[g.a].pos[0] - m0.points[g.pivot].pos[0]
        th0 = m0.links[g.bar].angle[0]
        hh = 1e-4

        def bar_point(d):
            m1 = mech.solve(np.array([phi + d]))
            return m1.points[g.pivot].pos[0] + np.exp(1j * (m1.links[g.bar].angle[0] - th0)) * r0

        dt = hh / model.crank_omega
        a_fd = (bar_point(hh) - 2 * bar_point(0.0) + bar_point(-hh)) / dt ** 2
        a4 = acc.points[f"{g.a.lower()}{g.bar}'"]
        scale = max(abs(z) for z in acc.points.values())
        assert abs(a4 - a_fd) <= 1e-5 * scale, label


def _power_torque(model, raw, forces, i):
    """−Σ P / ω: the balancing torque from the power of every load (no reaction used)."""
    total = 0.0
    for b in model.bodies:
        if b.mass:
            s = raw.points[b.com]
            f = -b.mass * s.acc[i] - 1j * b.mass * model.gravity
            total += (f * np.conj(s.vel[i])).real
        if b.inertia:
            w = raw.links[b.link]
            total += -b.inertia * w.alpha[i] * w.omega[i]
    for j, r in enumerate(model.resistances):
        f = forces.resistance[f"R{j + 1}"][i] * np.exp(1j * r.direction)
        total += (f * np.conj(raw.points[r.point].vel[i])).real
    return -total / model.crank_omega


def test_force_polygons_close_and_the_crank_balances_the_power(run):
    name, (model, k, raw, forces, fly), found = run
    groups = [g for g in model.mechanism.groups if g.links]
    for label in _labels(k):
        i = entry(k, label)
        ps = polygons(model, k, raw, forces, label)
        fps = [p for p in ps if p.kind == "force"]
        assert [p.group for p in fps] == [g.name for g in groups]
        for pg in fps:
            if not pg.vectors:          # no load at all (the lock-beam feed): nothing to close
                assert name == "lockbeam"
                continue
            scale = max(abs(v.value) for v in pg.vectors)
            total = sum(v.value for v in pg.vectors if v.role != "internal")
            assert abs(total) <= 1e-9 * scale, (name, label, pg.group)
            assert abs(pg.points[pg.vectors[-1].head] if pg.vectors[-1].role != "internal"
                       else 0j) <= 1e-9 * scale
            _check_closure(pg, scale)
        crank = fps[0]
        assert isinstance(groups[0], Crank)
        mb = crank.moments["Mb"]
        ref = _power_torque(model, raw, forces, i)
        peak = max(np.max(np.abs(forces.balancing_torque)), 1e-9)
        assert abs(mb - ref) <= 1e-8 * peak, (name, label, mb, ref)
        # with P_b at the crank pin in place of M_b the frame reaction closing the polygon is
        # R' = R − P_b, named with its prime as the graphical method's text names it (the A1
        # cell wrote "FR72 = 193 N" beside the report's F_R72 = 2588 N); P_b·l = M_b
        if any(v.name == "Pb" for v in crank.vectors):
            pb = crank.vector("Pb").value
            tip = raw.points[groups[0].tip].pos[i] - raw.points[groups[0].pivot].pos[i]
            assert (np.conj(tip) * pb).imag == pytest.approx(mb, rel=1e-9, abs=1e-9 * peak)
            for v in crank.vectors:
                if v.role == "reaction":
                    assert v.name.endswith("'"), (name, label, v.name)
                    r = complex(forces.reactions[v.name[:-1]][i])
                    assert abs(v.value - (r - pb)) <= 1e-9 * max(abs(w.value) for w in crank.vectors), (name, label, v.name)


def _text_boxes(sheet):
    boxes = []
    for t in sheet.entities:
        if not isinstance(t, Text) or t.angle:
            continue
        wd, ht = text_width(t.text, t.height), t.height
        cx = {"left": t.position.real + wd / 2, "center": t.position.real,
              "right": t.position.real - wd / 2}[t.halign]
        cy = {"bottom": t.position.imag + ht / 2, "middle": t.position.imag,
              "top": t.position.imag - ht / 2}[t.valign]
        boxes.append(((cx - wd / 2, cy - ht / 2, cx + wd / 2, cy + ht / 2), t.text))
    return boxes


def test_sheet_has_no_overlaps_and_the_dxf_the_same_entities(run, tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    from mechdesign.render.sheet_dxf import plain_text, write_dxf

    name, (model, k, raw, forces, fly), found = run
    s, scales = analysis_sheet(found, INFO, "zh")
    assert scales["length"] >= 1
    chosen = list(found.polygons.positions)
    # the default positions (shaper: [4, 10]; lockbeam [4, 10], its 5 and 11 being lines:
    # tests/test_polygon_positions.py); designs/press.yaml names its own (session 40)
    assert len(chosen) == 2 and (name == "press" or chosen == chosen_positions(k, None, forces,
                                                                               model.mechanism, raw))
    n_groups = sum(1 for g in model.mechanism.groups if g.links)
    # the lock-beam's feed carries no load and has no masses: every reaction is zero, so the
    # sheet shows its kinematics only (no empty force cells, no flat M_b curve)
    unloaded = name == "lockbeam"
    if unloaded:
        assert not np.any(forces.balancing_torque) and not forces.inertia_force
        n_groups = 0
    assert sum(1 for key in scales if key.startswith("force_")) == 2 * n_groups
    # everything inside the sheet, everything but the frame inside the border
    w, h = SIZES["A1"]
    x0, y0, x1, y1 = s.inner
    for e in s.entities:
        for z in [getattr(e, a) for a in ("p0", "p1", "position", "center") if hasattr(e, a)]:
            assert 0 <= z.real <= w and 0 <= z.imag <= h
            if getattr(e, "layer", "") != "FRAME":
                assert x0 <= z.real <= x1 and y0 <= z.imag <= y1, (name, e)
    boxes = _text_boxes(s)
    clashes = [(a[1], b[1]) for j, a in enumerate(boxes) for b in boxes[j + 1:]
               if boxes_overlap(a[0], b[0], -0.3)]
    assert not clashes, (name, clashes[:10])
    # the polygon cells (thin frames) do not overlap one another
    cells = [e for e in s.entities if isinstance(e, Polyline) and e.closed and e.weight == 0.13]
    assert len(cells) == 4 + 2 * n_groups
    rects = [(min(p.real for p in c.points), min(p.imag for p in c.points),
              max(p.real for p in c.points), max(p.imag for p in c.points)) for c in cells]
    for j, a in enumerate(rects):
        for b in rects[j + 1:]:
            assert not boxes_overlap(a, b), (name, a, b)
    path = write_dxf(s, tmp_path / "analysis.dxf", INFO.drawing)
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    kinds = Counter(type(e).__name__ for e in s.entities)
    dxf = Counter(e.dxftype() for e in msp)
    assert dxf["LINE"] == kinds[Line.__name__]
    assert dxf["LWPOLYLINE"] == kinds[Polyline.__name__]
    assert dxf["CIRCLE"] == kinds[Circle.__name__]
    assert dxf["ARC"] == kinds[Arc.__name__]
    assert dxf["HATCH"] == kinds[Fill.__name__]
    assert dxf["TEXT"] + dxf["MTEXT"] == kinds[Text.__name__]     # MTEXT: with subscripts
    assert dxf["DIMENSION"] == kinds[Dimension.__name__]
    texts = {plain_text(e) for e in msp.query("TEXT MTEXT")}
    assert "张三" in texts and INFO.drawing in texts
    from mechdesign.render.analysis_sheet import LABELS
    lab = LABELS["zh"]
    assert not any(lab["noforce"] in t for t in texts)
    assert any("未给出载荷" in t for t in texts) == unloaded
    assert (lab["mbt"] in texts) == (not unloaded)
    # the velocity polygon at the first position is drawn at the μv written above it
    mu = scales[f"velocity_{chosen[0]}"]
    assert any(f"μv = {mu:g} (m/s)/mm" == t for t in texts)
    vel = found.polygons.at(chosen[0])[0]
    fresh = polygons(model, k, raw, forces, chosen[0])[0]      # the stage stored these
    assert [(v.name, v.value) for v in vel.vectors] == [(v.name, v.value) for v in fresh.vectors]
    vecs = np.array([complex(e.dxf.end.x - e.dxf.start.x, e.dxf.end.y - e.dxf.start.y)
                     for e in msp.query("LINE[layer=='VECTORS']")])
    for v in vel.vectors:
        want = v.value / mu
        if abs(want) > 1e-6:
            assert np.min(np.abs(vecs - want)) < 1e-6, (name, v.name)


def test_wide_mechanism_fills_the_left_column(run):
    """Review39: the lock-beam's feed is wider than tall; its view was limited by the left
    column's width (1:2, 248 × 180 mm) and with the table at the column's foot left ~60 % of
    the column empty. The column now widens into the kinematic polygons' column (two rows of
    tall cells on a sheet without force polygons) so the view is drawn at 1:1.5, and the
    table's rows grow into the height still unused: view and table cover over 60 % of the
    column's height (49 % before), nothing overlapping (the overlap test above)."""
    from mechdesign.render.analysis_sheet import (ROW_H, WIDEN, _left_column,
                                                  _mechanism_extent, _table_height, _top_room)

    name, (model, k, raw, forces, fly), found = run
    if name != "lockbeam":
        pytest.skip("the lock-beam feed is the wide mechanism of the examples")
    s, scales = analysis_sheet(found, INFO, "zh")
    assert scales["length"] == 1.5                       # GB/T 14690 1:1.5 (was 1:2)
    x0, y0, x1, y1 = s.inner
    ext = _mechanism_extent(model, k, "zh")
    drawn = (ext["hi"] - ext["lo"]).imag / scales["length"]
    right, rh = _left_column(model, k, "zh", s.inner, WIDEN)
    assert rh > ROW_H
    used = drawn + _top_room(ext["legend"]) + _table_height(k, rh)
    assert used / ((y1 - 6) - (y0 + 8)) > 0.6
