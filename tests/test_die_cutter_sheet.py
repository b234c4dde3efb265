"""The die-cutter's kinematic diagram (机构运动简图, issue 19 point 8): the whole machine, not
the toggle press alone. Read from the written DXF and checked against the brief's numbers
(designs/die_cutter.yaml) through closed forms written out here: the chain's sprockets
(pitch radius R_s = p / (2 sin(180°/z_s))) with the chain's straight runs tangent to both,
the incomplete gear pair's pitch circles m z / 2 touching, its toothed sector 360° z1'/z1,
the driven gear coaxial with the driving sprocket, and the gripper cam's actual profile
between r0 − r_r and r0 + h − r_r (translating roller follower without offset)."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
BRIEF = yaml.safe_load((ROOT / "designs" / "die_cutter.yaml").read_text(encoding="utf-8"))
TOL = 1e-6          # paper mm: the DXF stores the model's doubles


@pytest.fixture(scope="module")
def dxf_sheet(example_results, tmp_path_factory):
    """(model space of the written kinematic DXF, model mm per paper mm) of the example."""
    import ezdxf

    from mechdesign.brief.loader import load_brief
    from mechdesign.render.sheets import _builders, write_all

    brief = load_brief(ROOT / "designs" / "die_cutter.yaml")
    out = tmp_path_factory.mktemp("dc_sheet")
    (out / "f").mkdir()
    builders = [b for b in _builders(example_results("die_cutter"), brief) if b[0] == "kinematic"]
    files = write_all(builders, brief, out, out / "f", "zh", ("dxf",))
    assert len(files) == 1 and files[0].dxf
    left, right = (float(x) for x in files[0].scale.split(":"))
    return ezdxf.readfile(out / files[0].dxf).modelspace(), right / left


def _round(e, r):
    """Circles and arcs of radius ``r``: {centre: [sweep in degrees, …]}."""
    out: dict[complex, list[float]] = {}
    for c in e:
        if c.dxftype() not in ("CIRCLE", "ARC") or abs(c.dxf.radius - r) > TOL:
            continue
        z = complex(round(c.dxf.center.x, 6), round(c.dxf.center.y, 6))
        sweep = 360.0 if c.dxftype() == "CIRCLE" else (c.dxf.end_angle - c.dxf.start_angle) % 360.0
        out.setdefault(z, []).append(sweep)
    return out


def test_chain_sprockets_and_tangent_runs(dxf_sheet):
    msp, n = dxf_sheet
    p, z = BRIEF["chain"]["pitch_mm"], BRIEF["chain"]["sprocket_teeth"]
    rs = p / (2 * np.sin(np.pi / z)) / n
    wheels = _round(msp, rs)
    # two sprockets: the tail one a whole circle; the driving one behind the gear pair, with
    # the arc the driver hides (inside its tip circle r_a1 = m(z1/2 + 1), centres
    # d = m(z1 + z2)/2 apart) not drawn, as a diagram draws no hidden lines (review34 C: a
    # dashed arc across incomplete gear 2): 360° − 2β, cos β = (R_s² + d² − r_a1²)/(2 R_s d)
    assert len(wheels) == 2, wheels
    g = BRIEF["incomplete_gear"]
    m = g["module_mm"]
    ra1 = m * (g["driver_teeth_full"] / 2 + 1) / n
    d = m * (g["driver_teeth_full"] + g["driven_teeth"]) / 2 / n
    beta = np.degrees(np.arccos((rs ** 2 + d ** 2 - ra1 ** 2) / (2 * rs * d)))
    assert sorted(sum(sw) for sw in wheels.values()) == pytest.approx([360.0 - 2 * beta, 360.0])
    assert all(len(sw) == 1 for sw in wheels.values())        # one arc each, nothing dashed
    a, b = wheels
    runs = []
    for ln in msp.query("LINE"):
        p0 = complex(ln.dxf.start.x, ln.dxf.start.y)
        p1 = complex(ln.dxf.end.x, ln.dxf.end.y)
        if abs(abs(p0 - a) - rs) < 1e-6 and abs(abs(p1 - b) - rs) < 1e-6 or \
           abs(abs(p0 - b) - rs) < 1e-6 and abs(abs(p1 - a) - rs) < 1e-6:
            u = (p1 - p0) / abs(p1 - p0)
            for c in (a, b):
                # distance of each centre from the run's line = R_s: tangent to both
                assert abs(abs((np.conj(u) * (c - p0)).imag) - rs) < 1e-6
            runs.append((p0, p1))
    assert len(runs) == 2


def test_incomplete_gear_pair_touches_and_drives_the_sprocket(dxf_sheet):
    msp, n = dxf_sheet
    g = BRIEF["incomplete_gear"]
    m = g["module_mm"]
    r1, r2 = m * g["driver_teeth_full"] / 2 / n, m * g["driven_teeth"] / 2 / n
    pitch = [e for e in msp.query("CIRCLE") if e.dxf.layer == "CENTER"]
    drivers = [complex(e.dxf.center.x, e.dxf.center.y) for e in pitch if abs(e.dxf.radius - r1) < TOL]
    driven = [complex(e.dxf.center.x, e.dxf.center.y) for e in pitch if abs(e.dxf.radius - r2) < TOL]
    pairs = [(o1, o2) for o1 in drivers for o2 in driven if abs(abs(o2 - o1) - (r1 + r2)) < 1e-6]
    assert len(pairs) == 1
    o1, o2 = pairs[0]
    # the driving sprocket on the driven gear's shaft
    rs = BRIEF["chain"]["pitch_mm"] / (2 * np.sin(np.pi / BRIEF["chain"]["sprocket_teeth"])) / n
    assert complex(round(o2.real, 6), round(o2.imag, 6)) in _round(msp, rs)
    # the toothed sector: tip and root arcs over 360° z1'/z1, the locking arc over the rest
    sector = 360.0 * g["teeth_present"] / g["driver_teeth_full"]
    root = (m * g["driver_teeth_full"] / 2 - 1.25 * m) / n
    key = complex(round(o1.real, 6), round(o1.imag, 6))
    assert _round(msp, root)[key] == pytest.approx([sector])
    tip = sorted(_round(msp, (m * g["driver_teeth_full"] / 2 + m) / n)[key])
    assert tip == pytest.approx(sorted([sector, 360.0 - sector]))


def _drawn_phi(example_results) -> float:
    """[°] The shaft angle of the position the diagram is drawn at: position p lies
    (p − 1) × the brief's position step from position 1 (φ = 0, the platen's bottom). Position 1
    is the folded extreme position (the coupler over the crank), so the diagram is drawn at the
    graphical method's first position (page review 47)."""
    from mechdesign.render import kinematic_sheet as ks
    from mechdesign.render.sheets import linkage_results

    r = example_results("die_cutter")
    label = ks.diagram_position(linkage_results(r), r["brief"])
    assert label != "1"
    return (int(label) - 1) * BRIEF["analysis"]["position_step_deg"]


def test_incomplete_gear_sector_turned_to_the_drawn_position(dxf_sheet, example_results):
    """At the drawn position (shaft angle φ from the platen's bottom) the driver, turning
    clockwise (press.crank_rotation: cw) from its meshing start φ_s (the feed stage's
    placement), has turned φ − φ_s past the contact point: the toothed sector's leading end
    lies (φ − φ_s) mod 360° clockwise from the direction O1 → O2, its trailing end
    360° z1'/z1 behind it."""
    msp, n = dxf_sheet
    g = BRIEF["incomplete_gear"]
    assert BRIEF["press"]["crank_rotation"] == "cw"
    start = np.degrees(example_results("die_cutter")["feed"].gear.motion_start)
    turned = (_drawn_phi(example_results) - start) % 360.0
    sector = 360.0 * g["teeth_present"] / g["driver_teeth_full"]
    m = g["module_mm"]
    r1, r2 = m * g["driver_teeth_full"] / 2 / n, m * g["driven_teeth"] / 2 / n
    pitch = [e for e in msp.query("CIRCLE") if e.dxf.layer == "CENTER"]
    o1 = [complex(e.dxf.center.x, e.dxf.center.y) for e in pitch if abs(e.dxf.radius - r1) < TOL]
    o2 = [complex(e.dxf.center.x, e.dxf.center.y) for e in pitch if abs(e.dxf.radius - r2) < TOL]
    (o1, o2), = [(a, b) for a in o1 for b in o2 if abs(abs(b - a) - (r1 + r2)) < 1e-6]
    contact = np.degrees(np.angle(o2 - o1))
    root = (m * g["driver_teeth_full"] / 2 - 1.25 * m) / n
    arcs = [e for e in msp.query("ARC") if abs(e.dxf.radius - root) < TOL
            and abs(complex(e.dxf.center.x, e.dxf.center.y) - o1) < 1e-6]
    assert len(arcs) == 1
    lead = (contact - turned) % 360.0                 # clockwise: the angle decreases
    trail = (lead + sector) % 360.0
    assert (arcs[0].dxf.start_angle - lead + 180.0) % 360.0 - 180.0 == pytest.approx(0.0, abs=1e-9)
    assert (arcs[0].dxf.end_angle - trail + 180.0) % 360.0 - 180.0 == pytest.approx(0.0, abs=1e-9)


def test_gripper_cam_profile_spans_base_to_lift(dxf_sheet, example_results):
    msp, n = dxf_sheet
    cam = BRIEF["gripper_cam"]
    r0, rr, h = cam["base_radius_mm"], cam["follower"]["roller_radius_mm"], cam["follower"]["stroke_h_mm"]
    assert cam["follower"]["offset_mm"] == 0
    pins = [complex(e.dxf.center.x, e.dxf.center.y) for e in msp.query("CIRCLE")
            if abs(e.dxf.radius - 1.2) < TOL]
    found = []
    for pl in msp.query("LWPOLYLINE"):
        pts = np.array([complex(x, y) for x, y, *_ in pl.get_points()])
        if len(pts) < 40:
            continue
        for c in pins:
            d = np.abs(pts - c) * n
            if abs(d.min() - (r0 - rr)) < 1e-3 and abs(d.max() - (r0 + h - rr)) < 1e-3:
                found.append(c)
    assert len(found) == 1
    o = found[0]
    # the roller (radius r_r) on the vertical through the cam centre, r0 … r0 + h above it
    rollers = [complex(e.dxf.center.x, e.dxf.center.y) for e in msp.query("CIRCLE")
               if abs(e.dxf.radius - rr / n) < TOL]
    above = [z for z in rollers if abs(z.real - o.real) < 1e-6 and r0 - 1e-6 <= (z.imag - o.imag) * n <= r0 + h + 1e-6]
    assert len(above) == 1
    # at the drawn position the cam has turned φ − φ_g (φ_g: the cycle's gripper start) into
    # its programme: the lift there by the programme's 3-4-5 laws, above the base circle
    phi_g = np.degrees(example_results("die_cutter")["cycle"].gripper_start)
    delta = (_drawn_phi(example_results) - phi_g) % 360.0
    want = r0 + _programme_lift(cam["programme"], delta, h)
    assert (above[0].imag - o.imag) * n == pytest.approx(want, abs=1e-6 * r0)


def _programme_lift(programme, delta: float, h: float) -> float:
    """Lift [mm] of a rise–dwell–return–dwell programme of 3-4-5 polynomials at cam angle
    ``delta`` [°]: s = h (10t³ − 15t⁴ + 6t⁵) on the rise, h minus that on the return."""
    at, s = 0.0, 0.0
    for seg in programme:
        span = seg["angle_deg"]
        if at <= delta < at + span:
            t = (delta - at) / span
            p = 10 * t ** 3 - 15 * t ** 4 + 6 * t ** 5
            assert seg["motion"] == "dwell" or seg.get("law") == "poly345"
            return {"rise": h * p, "return": h * (1 - p), "dwell": s}[seg["motion"]]
        s = {"rise": h, "return": 0.0}.get(seg["motion"], s)
        at += span
    raise AssertionError(delta)


def test_labels_do_not_overlap(example_results):
    """Every label of the diagram (point names, link numbers, the drive's shaft numbers,
    ω) keeps clear of the others."""
    from mechdesign.render.sheet import Text, TitleInfo, plain, text_box
    from mechdesign.render.sheets import _builders

    for lang in ("zh", "en"):
        build = dict(_builders(example_results("die_cutter"), None))["kinematic"]
        s = build(TitleInfo("机构运动简图", "test", number="T-01"), lang)
        boxes = [text_box(e.position, e.text, e.height, e.halign, e.valign) for e in s.entities
                 if isinstance(e, Text) and len(plain(e.text)) <= 8 and abs(e.angle) < 1e-12
                 and e.height <= 3.5 and e.layer == "TEXT"]
        labels = [b for b in boxes if b[2] - b[0] < 20.0]
        names = {plain(e.text) for e in s.entities if isinstance(e, Text)}
        # the feed's and the cam's points and links are named
        assert {"E", "O2", "O3", "7", "8", "9", "10"} <= names
        # the drive from the motor: the motor, its last shaft named as the distribution shaft
        # O1, the flywheel (the brief's flywheel.shaft) named
        assert "M" in names and any(t.endswith("(O1)") for t in names), names
        assert ("飞轮" if lang == "zh" else "flywheel") in names
        for i, a in enumerate(labels):
            for b in labels[i + 1:]:
                assert a[2] <= b[0] or b[2] <= a[0] or a[3] <= b[1] or b[3] <= a[1], (lang, a, b)


@pytest.mark.parametrize("name", ["die_cutter", "slotter", "shaper"])
def test_transmission_sheet_draws_the_flywheel(example_results, name):
    """The flywheel of the brief (die_cutter: on shaft I, the V-belt's large pulley; slotter,
    shaper: on the pinion shaft, the belt's large pulley's shaft) is drawn on the transmission
    schematic as a rim concentric with that pulley, in proportion to it: rim diameter D
    (brief) : pulley datum diameter d2; named, and its J_F in the notes."""
    from mechdesign.render.sheet import Circle, Text, TitleInfo, plain
    from mechdesign.render.sheets import _builders
    from mechdesign.stages.drive import shaft_numeral

    brief = yaml.safe_load((ROOT / "designs" / f"{name}.yaml").read_text(encoding="utf-8"))
    r = example_results(name)
    belt = r["drive"].stages[0]
    assert belt.type == "belt"
    ratio = brief["flywheel"]["rim_diameter_mm"] / (belt.d2 * 1e3)
    s = dict(_builders(r, None))["transmission"](TitleInfo("传动系统示意图", "test", number="T-01"), "zh")
    circles = [e for e in s.entities if isinstance(e, Circle) and e.layer == "OUTLINE"]
    # the rim dashed (hidden lines: behind the pulley, whose belt runs cross it)
    rims = [e for e in s.entities if isinstance(e, Circle) and e.layer == "HIDDEN"]
    pairs = [(a, b) for a in circles for b in rims if abs(a.center - b.center) < 1e-9
             and abs(b.radius / a.radius - ratio) < 1e-9]
    assert len(pairs) == 1
    texts = [plain(e.text) for e in s.entities if isinstance(e, Text)]
    assert "飞轮" in texts
    # shaft 1: the belt's driven shaft (die_cutter: flywheel.shaft 1; the others: the pinion
    # of their belt + gear-pair drive)
    assert brief["flywheel"]["shaft"] in (1, "pinion") and len(r["drive"].stages) == (3 if name == "die_cutter" else 2)
    assert any(t.startswith(f"飞轮装在轴 {shaft_numeral(1)} 上") for t in texts), texts


def test_number_8_on_the_driven_gear(dxf_sheet):
    """Member 8 (the driven gear with the driving sprocket on its shaft, as the notes list
    it) is numbered on the driven gear: "8" between the gear's tip circle r_a2 = m(z2/2 + 1)
    and the sprocket R_s, nearer the gear (review34 C: it sat on the sprocket's circle, up by
    the chain, and read as the sprocket's number)."""
    msp, n = dxf_sheet
    g = BRIEF["incomplete_gear"]
    m = g["module_mm"]
    r2, ra2 = m * g["driven_teeth"] / 2 / n, m * (g["driven_teeth"] / 2 + 1) / n
    rs = BRIEF["chain"]["pitch_mm"] / (2 * np.sin(np.pi / BRIEF["chain"]["sprocket_teeth"])) / n
    o2 = [complex(e.dxf.center.x, e.dxf.center.y) for e in msp.query("CIRCLE")
          if e.dxf.layer == "CENTER" and abs(e.dxf.radius - r2) < TOL]
    assert len(o2) == 1
    eights = [e for e in msp.query("TEXT MTEXT")
              if (e.dxf.text if e.dxftype() == "TEXT" else e.text).strip() == "8"]
    assert len(eights) == 1
    e = eights[0]
    p = e.dxf.align_point if e.dxftype() == "TEXT" and e.dxf.hasattr("align_point") else e.dxf.insert
    r = abs(complex(p.x, p.y) - o2[0])
    assert ra2 < r < rs and r - ra2 < rs - r, (r, ra2, rs)
