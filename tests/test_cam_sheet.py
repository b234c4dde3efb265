"""The A2 cam sheet (mechdesign.render.cam_sheet), checked on the files it produces.

The DXF is read back with ezdxf and measured against references that do not use the
module's arrays:

* the scale is read from the title block ('1:n'), the cam centre from the base circle,
  whose radius on the sheet × n must be r0;
* the pitch curve is rebuilt here by inversion from the programme alone (the follower
  point in the frame, turned back by the cam angle: translating follower on x = e at
  height √(r0² − e²) + s; oscillating arm turned by φ about the pivot from the point where
  it meets the base circle), and every vertex of the bold profile must lie r_r from it;
* the ordinates of the displacement diagram are found as the thin verticals above the
  division numbers; their cam angle comes from their position and μδ (read from the
  sheet), their length × μs must be s(δ) from ``programme.evaluate``; the numbers must
  divide every rise and return into equal parts;
* everything lies inside the border, and nothing but the title block inside the title
  block; texts do not overlap each other.
"""
from __future__ import annotations

import re

import numpy as np
import pytest

ezdxf = pytest.importorskip("ezdxf")
from ezdxf import bbox as dxf_bbox  # noqa: E402
from ezdxf.enums import TextEntityAlignment  # noqa: E402
from scipy.spatial import cKDTree  # noqa: E402

from mechdesign.core.cam import OscillatingFollower  # noqa: E402
from mechdesign.render.cam_sheet import cam_sheet  # noqa: E402
from mechdesign.render.sheet import Text, TitleInfo, text_width, title_block_box  # noqa: E402
from mechdesign.render.sheet_dxf import plain_text, write_dxf  # noqa: E402
from mechdesign.render.sheet_typst import write_sheet  # noqa: E402

# "brief:key": the cam ``key`` of a brief with several (the lock-beam's bending cam: an
# oscillating roller follower, the four-bar's input rocker, base radius designed)
DESIGNS = ["cam_7_3", "lockbeam_cam", "shaper", "lockbeam:bending_cam"]
BORDER = (25.0, 10.0, 584.0, 410.0)
LAYERS = ("OUTLINE", "CENTER", "CONSTRUCTION", "DIMENSIONS", "TEXT", "FRAME")


def _cam(example_results, name):
    """The brief and the cam result of designs/<name>.yaml (computed once per session);
    "<name>:<key>": its cam ``key``."""
    name, _, key = name.partition(":")
    results = example_results(name)
    return results["brief"], results[key or "cam"]


@pytest.fixture(scope="module", params=DESIGNS)
def drawn(request, tmp_path_factory, example_results):
    name = request.param
    brief, cam = _cam(example_results, name)
    rep = brief.report
    info = TitleInfo("", rep.title, rep.student, rep.student_id, rep.class_name, rep.teacher,
                     str(rep.date), number="MD-CAM", lang="zh")
    sheet = cam_sheet(cam, info, "zh")
    name = name.replace(":", "-")
    out = tmp_path_factory.mktemp(name)
    dxf = write_dxf(sheet, out / f"{name}.dxf")
    write_sheet(sheet, pdf=out / f"{name}.pdf", png=out / f"{name}.png", png_width_px=1200)
    doc = ezdxf.readfile(dxf)
    return {"name": name, "cam": cam, "sheet": sheet, "doc": doc, "msp": doc.modelspace(),
            "out": out}


# --------------------------------------------------------------------------- helpers


def _texts(msp):
    """(text, alignment, point) of every TEXT (and MTEXT: alignment None)."""
    out = []
    for t in msp.query("TEXT"):
        align, p1, _ = t.get_placement()
        out.append((t.dxf.text, align, complex(p1.x, p1.y)))
    for t in msp.query("MTEXT"):              # a text with subscripts, read as plain letters
        out.append((plain_text(t), None, complex(t.dxf.insert.x, t.dxf.insert.y)))
    return out


def _scale(msp) -> float:
    found = [float(m.group(1)) for s, _, _ in _texts(msp) if (m := re.fullmatch(r"1:(\d+(?:\.\d+)?)", s))]
    assert len(found) == 1, found
    return found[0]


def _cam_centre(msp, cam, n) -> complex:
    r0 = cam.base_radius * 1e3
    hits = [c for c in msp.query("CIRCLE") if abs(c.dxf.radius * n - r0) < 1e-6]
    assert hits, f"no circle of radius r0/n = {r0 / n} mm on the sheet"
    centres = {(round(c.dxf.center.x, 6), round(c.dxf.center.y, 6)) for c in hits}
    assert len(centres) == 1, centres
    x, y = centres.pop()
    return complex(x, y)


def _pitch_reference(cam, points=200_000) -> np.ndarray:
    """The pitch curve [mm, cam frame] by inversion, from the programme and the follower."""
    p = cam.params
    prog = p.programme
    sigma = 1 if p.rotation > 0 else -1
    delta = np.linspace(0.0, 2 * np.pi, points, endpoint=False)
    s = prog.evaluate(delta).s
    r0 = cam.base_radius
    fol = p.follower
    if isinstance(fol, OscillatingFollower):
        a, L = fol.pivot_distance, fol.arm_length
        x = (a * a + r0 * r0 - L * L) / (2 * a)
        sense = sigma if fol.rise_sense == "same" else -sigma
        # of the two points where the arm meets the base circle, the one that the rise
        # carries away from the cam centre
        for y in (np.sqrt(r0 * r0 - x * x), -np.sqrt(r0 * r0 - x * x)):
            B0 = complex(x, y)
            if abs(a + (B0 - a) * np.exp(1j * sense * 1e-3)) > abs(B0):
                break
        frame_point = a + (B0 - a) * np.exp(1j * sense * s)
    else:
        e = cam.offset
        frame_point = e + 1j * (np.sqrt(r0 * r0 - e * e) + s)
    return frame_point * np.exp(-1j * sigma * delta) * 1e3


# --------------------------------------------------------------------------- tests


@pytest.mark.e2e
def test_layers_have_entities(drawn):
    doc, msp = drawn["doc"], drawn["msp"]
    for layer in LAYERS:
        assert layer in doc.layers, layer
        assert len(msp.query(f'*[layer=="{layer}"]')) > 0, layer
    assert len(msp.query("DIMENSION")) >= 1           # r0 (rr is a leader), e or a, L


@pytest.mark.e2e
def test_actual_profile_is_the_roller_envelope_of_the_pitch_curve(drawn):
    cam, msp = drawn["cam"], drawn["msp"]
    n = _scale(msp)
    O = _cam_centre(msp, cam, n)
    polys = [pl for pl in msp.query('LWPOLYLINE[layer=="OUTLINE"]') if pl.closed]
    profile = max(polys, key=len)
    assert len(profile) > 1000
    z = np.array([complex(x, y) for x, y in profile.get_points("xy")])
    z = np.concatenate([z, (z + np.roll(z, -1)) / 2])          # vertices and mid-chords
    model = (z - O) * n
    pitch = _pitch_reference(cam)
    rr = cam.params.follower.roller_radius * 1e3
    assert rr > 0
    tree = cKDTree(np.column_stack([pitch.real, pitch.imag]))
    dist, _ = tree.query(np.column_stack([model.real, model.imag]))
    assert np.max(np.abs(dist - rr)) < 0.01, (dist.min(), dist.max(), rr)
    # and the profile goes all round: every pitch point has the profile r_r away (a roller
    # centred next to a concave corner of the pitch curve, where a uniform-velocity law
    # starts or stops, stands a few hundredths of a millimetre off: the envelope is cut at
    # the crossing of its two branches)
    back = cKDTree(np.column_stack([model.real, model.imag]))
    dist2, _ = back.query(np.column_stack([pitch.real[::20], pitch.imag[::20]]))
    assert np.max(np.abs(dist2 - rr)) < 0.05
    assert np.mean(np.abs(dist2 - rr) < 1e-3) > 0.98


@pytest.mark.e2e
def test_pitch_curve_and_base_circle(drawn):
    cam, msp = drawn["cam"], drawn["msp"]
    n = _scale(msp)
    O = _cam_centre(msp, cam, n)                    # asserts the base circle r0/n exists
    pitch = _pitch_reference(cam, 20_000)
    centre = [pl for pl in msp.query('LWPOLYLINE[layer=="CENTER"]') if pl.closed and len(pl) > 1000]
    assert len(centre) == 1
    z = (np.array([complex(x, y) for x, y in centre[0].get_points("xy")]) - O) * n
    dist, _ = cKDTree(np.column_stack([pitch.real, pitch.imag])).query(np.column_stack([z.real, z.imag]))
    assert np.max(dist) < 0.02
    # the pitch curve touches the base circle (s = 0) and reaches r0 + stroke (translating)
    r = np.abs(z)
    assert abs(r.min() - cam.base_radius * 1e3) < 0.01


@pytest.mark.e2e
def test_displacement_ordinates(drawn):
    cam, msp = drawn["cam"], drawn["msp"]
    prog = cam.params.programme
    osc = cam.params.oscillating
    texts = _texts(msp)
    joined = " ".join(s for s, _, _ in texts)
    mu_s = float(re.search(r"μ[sφ] = ([\d.]+)", joined).group(1))
    mu_d = float(re.search(r"μδ = ([\d.]+)", joined).group(1))
    numbers = sorted(((int(s), p) for s, a, p in texts
                      if re.fullmatch(r"\d+", s) and a == TextEntityAlignment.TOP_CENTER),
                     key=lambda t: t[0])
    assert [k for k, _ in numbers] == list(range(len(numbers)))
    x0 = numbers[0][1].real
    deltas = np.array([(p.real - x0) * mu_d for _, p in numbers])       # [°]
    assert np.all(np.diff(deltas) > 0) and deltas[-1] < 360.0
    # every segment end is a division point; rises and returns in ≥ 4 equal parts
    starts = np.degrees(prog.starts)
    ends = starts + np.degrees(prog.spans)
    for a, b, seg in zip(starts, ends, prog.segments):
        inside = deltas[(deltas >= a - 1e-6) & (deltas <= b + 1e-6)]
        if b >= 360 - 1e-6:
            inside = np.append(inside, 360.0)
        assert abs(inside[0] - a) < 1e-6 and abs(inside[-1] - b) < 1e-6
        if seg.kind != "dwell":
            steps = np.diff(inside)
            assert len(steps) >= 4 and np.allclose(steps, steps[0], atol=1e-6)
        else:
            assert len(inside) == 2
    lines = [ln for ln in msp.query('LINE[layer=="CONSTRUCTION"]')
             if abs(ln.dxf.start.x - ln.dxf.end.x) < 1e-9]
    unit = np.degrees(1.0) if osc else 1e3
    checked = 0
    for (k, p), d in zip(numbers, deltas):
        expect = float(prog.evaluate(np.radians(d)).s) * unit
        above = [ln for ln in lines if abs(ln.dxf.start.x - p.real) < 1e-6
                 and 0 < min(ln.dxf.start.y, ln.dxf.end.y) - p.imag < 3.0]
        if expect < 1e-9:
            continue
        assert len(above) == 1, (k, d)
        length = abs(above[0].dxf.end.y - above[0].dxf.start.y)
        assert abs(length * mu_s - expect) < 1e-6, (k, d, length * mu_s, expect)
        checked += 1
    assert checked >= 8
    # the profile carries the same numbers, primed
    primed = {s for s, _, _ in texts if re.fullmatch(r"\d+′", s)}
    assert primed == {f"{k}′" for k, _ in numbers}


@pytest.mark.e2e
def test_everything_inside_the_border(drawn):
    msp = drawn["msp"]
    x0, y0, x1, y1 = BORDER
    outside = []
    for e in msp:
        ext = dxf_bbox.extents([e], fast=True)
        if not ext.has_data:
            continue
        if e.dxf.layer == "FRAME" and ext.extmin.x < 1e-6 and ext.extmin.y < 1e-6:
            continue                                      # the trimmed edge of the sheet
        if (ext.extmin.x < x0 - 1e-6 or ext.extmin.y < y0 - 1e-6 or ext.extmax.x > x1 + 1e-6
                or ext.extmax.y > y1 + 1e-6):
            outside.append((e.dxftype(), e.dxf.layer, tuple(ext.extmin), tuple(ext.extmax)))
    assert not outside, outside[:5]


@pytest.mark.e2e
def test_title_block_kept_clear(drawn):
    sheet, msp = drawn["sheet"], drawn["msp"]
    tx0, ty0, tx1, ty1 = title_block_box(sheet)
    intruders = []
    for e in msp:
        if e.dxf.layer == "FRAME":
            continue
        ext = dxf_bbox.extents([e], fast=True)
        if not ext.has_data:
            continue
        inside = (ext.extmin.x >= tx0 - 1e-6 and ext.extmax.x <= tx1 + 1e-6
                  and ext.extmin.y >= ty0 - 1e-6 and ext.extmax.y <= ty1 + 1e-6)
        if e.dxftype() == "TEXT" and inside:
            continue                                      # the title block's own texts
        if ext.extmax.x > tx0 and ext.extmin.x < tx1 and ext.extmax.y > ty0 and ext.extmin.y < ty1:
            intruders.append((e.dxftype(), e.dxf.layer, getattr(e.dxf, "text", "")))
    assert not intruders, intruders[:5]


def _box(t: Text):
    w = text_width(t.text, t.height)
    x = {"left": t.position.real, "center": t.position.real - w / 2, "right": t.position.real - w}[t.halign]
    y = {"bottom": t.position.imag, "middle": t.position.imag - t.height / 2,
         "top": t.position.imag - t.height}[t.valign]
    return x, y, x + w, y + t.height


@pytest.mark.e2e
def test_texts_do_not_overlap(drawn):
    sheet = drawn["sheet"]
    texts = [t for t in sheet.entities if isinstance(t, Text)]
    assert all(t.height >= 2.5 - 1e-9 for t in texts)
    boxes = [_box(t) for t in texts]
    clashes = []
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            a, b = boxes[i], boxes[j]
            if a[0] < b[2] - 0.2 and b[0] < a[2] - 0.2 and a[1] < b[3] - 0.2 and b[1] < a[3] - 0.2:
                clashes.append((texts[i].text, texts[j].text))
    assert not clashes, clashes


@pytest.mark.e2e
def test_pdf_and_png_written(drawn):
    from matplotlib.image import imread

    name, out = drawn["name"], drawn["out"]
    pdf, png = out / f"{name}.pdf", out / f"{name}.png"
    assert pdf.read_bytes()[:5] == b"%PDF-" and pdf.stat().st_size > 20_000
    img = imread(png)
    assert img.shape[1] == 1200 and abs(img.shape[0] / img.shape[1] - 420 / 594) < 0.01
    assert img[..., :3].mean() < 0.995                   # something is drawn


def test_english_sheet_builds(example_results):
    _, cam = _cam(example_results, "cam_7_3")
    sheet = cam_sheet(cam, TitleInfo("Cam drawing", "Exercise 7-3", lang="en"), "en")
    words = " ".join(t.text for t in sheet.entities if isinstance(t, Text))
    assert "Follower displacement diagram" in words and "pitch curve" in words
    assert not re.search(r"[\u4e00-\u9fff]", words)


@pytest.mark.e2e
def test_dimensions_measure_the_design(drawn):
    """Every DIMENSION's measured paper length, back at the sheet's scale (or μδ for the
    segment angles of the diagram), equals its written value and the design's value."""
    cam, msp = drawn["cam"], drawn["msp"]
    n = _scale(msp)
    O = _cam_centre(msp, cam, n)
    fol = cam.params.follower
    expect = {"r0": cam.base_radius * 1e3}
    if isinstance(fol, OscillatingFollower):
        expect.update(a=fol.pivot_distance * 1e3, L=fol.arm_length * 1e3)
    elif abs(cam.offset) > 0:
        expect["e"] = abs(cam.offset) * 1e3
    joined = " ".join(s for s, _, _ in _texts(msp))
    mu_d = float(re.search(r"μδ = ([\d.]+)", joined).group(1))
    seen, angles = {}, []
    for dim in msp.query("DIMENSION"):
        text = plain_text(dim)                # r0 with its subscript, as plain letters
        if m := re.fullmatch(r"(\w+)=([\d.]+)", text):
            key, value = m.group(1), float(m.group(2))
            assert abs(dim.get_measurement() * n - value) < 1e-6, text
            seen[key] = value
            if key == "r0":
                c = dim.dxf.defpoint
                assert abs(complex(c.x, c.y) - O) < 1e-6
        elif m := re.fullmatch(r"([\d.]+)°", text):
            assert abs(dim.get_measurement() * mu_d - float(m.group(1))) < 1e-6, text
            angles.append(float(m.group(1)))
    assert set(seen) == set(expect)
    for key, value in expect.items():
        assert abs(seen[key] - value) < 1e-6, key
    assert sorted(angles) == pytest.approx(sorted(np.degrees(cam.params.programme.spans)))
    # the roller radius is written on its leader
    rr = cam.params.follower.roller_radius * 1e3
    assert f"rr={rr:g}" in joined
