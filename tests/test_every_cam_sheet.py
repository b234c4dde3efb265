"""Every cam a run designs has its A2 cam sheet (issue 19 point 8): the lock-beam bender's
positioning cam and its bending cam (an oscillating roller follower, the four-bar's input
rocker) get a sheet each, titled with the cam's name; a machine with one cam keeps its one
sheet "cam".

The bending cam's sheet is read back from its DXF and measured against references that do
not use the sheet module:

* the bold profile and the pitch curve are the result's own coordinates (``outline``, the
  pitch curve of the cam's grid), point for point, at the scale written in the title block;
* the rocker at δ = 0: the pivot A at the brief's centre distance a on the x axis, the roller
  centre B0 where the arm of length L meets the base circle r0 (the two circles' intersection
  on the side the rise carries away from the cam centre), the roller circle r_r there and the
  arm on the line A–B0;
* the design data printed in the table: r0, r_r, a, L as the results and the brief give them,
  the swing φmax (the four-bar as built needs it: ``bending.rounded.input_swing_needed``),
  φ0 from the triangle O–A–B0 (law of cosines), and the largest pressure angles of the rise and
  the return from a brute-force evaluation of the inverted mechanism over 400 000 cam angles.
"""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

ezdxf = pytest.importorskip("ezdxf")

from mechdesign.render.sheet import Text, TitleInfo  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.e2e


def _cams(results: dict) -> list[str]:
    """The result keys holding a designed cam (a cam stage's result)."""
    from mechdesign.stages.cam import CamResult

    return [k for k, v in results.items() if isinstance(v, CamResult)]


def _brief(name: str):
    from mechdesign.brief.loader import load_brief

    return load_brief(ROOT / "designs" / f"{name}.yaml")


def test_every_cam_of_the_lockbeam_has_its_sheet(example_results):
    from mechdesign.render.sheets import _builders, sheet_title

    results = example_results("lockbeam")
    # the brief designs two cams: the positioning (pin) cam and the bending cam
    assert _cams(results) == ["cam", "bending_cam"]
    builders = dict(_builders(results, _brief("lockbeam")))
    assert {"cam", "bending_cam"} <= set(builders)
    titles = {(k, lang): sheet_title(k, builders[k], lang)
              for k in ("cam", "bending_cam") for lang in ("zh", "en")}
    assert titles == {("cam", "zh"): "定位凸轮机构设计图",
                      ("bending_cam", "zh"): "扳弯凸轮机构设计图",
                      ("cam", "en"): "Cam mechanism design: positioning cam",
                      ("bending_cam", "en"): "Cam mechanism design: bending cam"}
    # each sheet draws its own cam: the base radius in its data table is that cam's
    for key in ("cam", "bending_cam"):
        sheet = builders[key](TitleInfo("", "t", lang="zh"), "zh")
        r0 = _row(sheet, "基圆半径")
        assert r0 == [f"{results[key].base_radius * 1e3:.2f} mm"], (key, r0)


def test_a_machine_with_one_cam_keeps_its_one_sheet(example_results):
    from mechdesign.render.sheets import _builders, sheet_title

    results = example_results("cam_7_3")
    assert _cams(results) == ["cam"]
    builders = _builders(results, _brief("cam_7_3"))
    cams = [(k, b) for k, b in builders if "cam" in k and k != "kinematic"]
    assert [k for k, _ in cams] == ["cam"]
    assert sheet_title("cam", cams[0][1], "zh") == "凸轮机构设计图"
    assert sheet_title("cam", cams[0][1], "en") == "Cam mechanism design"


# --------------------------------------------------------------------------- the bending cam


def _row(sheet, label: str) -> list[str]:
    """The texts right of ``label`` on its table row (left to right, the symbol cell left out)."""
    texts = [t for t in sheet.entities if isinstance(t, Text)]
    heads = [t for t in texts if t.text == label]
    assert len(heads) == 1, (label, len(heads))
    y, x = heads[0].position.imag, heads[0].position.real
    row = sorted((t for t in texts if abs(t.position.imag - y) < 0.3 and t.position.real > x),
                 key=lambda t: t.position.real)
    return [t.text for t in row][1:]


def _number(text: str) -> float:
    return float(re.match(r"-?[\d.]+", text.replace("−", "-")).group(0))


@pytest.fixture(scope="module")
def bending(example_results, tmp_path_factory):
    from mechdesign.render.sheet_dxf import write_dxf
    from mechdesign.render.sheets import _builders

    results = example_results("lockbeam")
    build = dict(_builders(results, _brief("lockbeam")))["bending_cam"]
    sheet = build(TitleInfo("", "锁梁", number="MD-05", lang="zh"), "zh")
    out = tmp_path_factory.mktemp("bending_cam")
    msp = ezdxf.readfile(write_dxf(sheet, out / "bending_cam.dxf")).modelspace()
    scale = [t.dxf.text for t in msp.query("TEXT") if re.fullmatch(r"1:[\d.]+", t.dxf.text)]
    assert len(scale) == 1
    return {"results": results, "cam": results["bending_cam"], "sheet": sheet, "msp": msp,
            "n": float(scale[0][2:]), "brief": _brief("lockbeam")}


def _centre(msp, r0_mm: float, n: float) -> complex:
    hits = {(round(c.dxf.center.x, 9), round(c.dxf.center.y, 9)) for c in msp.query("CIRCLE")
            if abs(c.dxf.radius * n - r0_mm) < 1e-9}
    assert len(hits) == 1, hits
    x, y = hits.pop()
    return complex(x, y)


def _rocker_start(brief) -> tuple[float, float, float]:
    """(a, L, r_r) [mm] of the bending cam's rocker as the brief gives them."""
    f = brief.bending_cam.follower
    return f.pivot_distance_mm, f.arm_length_mm, f.roller_radius_mm


def _b0(a: float, L: float, r0: float, sense: int) -> complex:
    """Where the arm (length L about A = (a, 0)) meets the base circle r0: of the two
    intersections, the one a small turn of the arm in the rise sense carries outward."""
    x = (a * a + r0 * r0 - L * L) / (2 * a)
    for y in (np.sqrt(r0 * r0 - x * x), -np.sqrt(r0 * r0 - x * x)):
        B0 = complex(x, y)
        if abs(a + (B0 - a) * np.exp(1j * sense * 1e-3)) > abs(B0):
            return B0
    raise AssertionError("no intersection moves outward")


def test_bending_cam_profile_and_pitch_curve_are_the_results(bending):
    """The DXF's bold closed profile and its centre-line pitch curve, back at the scale, are
    the result's coordinates point for point (no thinning: the cam's geometry as computed)."""
    cam, msp, n = bending["cam"], bending["msp"], bending["n"]
    O = _centre(msp, cam.base_radius * 1e3, n)

    def model(layer):
        polys = [p for p in msp.query(f'LWPOLYLINE[layer=="{layer}"]') if p.closed and len(p) > 1000]
        assert len(polys) == 1, layer
        return (np.array([complex(x, y) for x, y in polys[0].get_points("xy")]) - O) * n

    actual = model("OUTLINE")
    assert actual.shape == cam.outline.shape
    assert np.max(np.abs(actual - cam.outline * 1e3)) < 1e-6
    pitch = model("CENTER")
    assert pitch.shape == cam.grid.pitch.shape
    assert np.max(np.abs(pitch - cam.grid.pitch * 1e3)) < 1e-6


def test_bending_cam_rocker_is_drawn_at_its_start(bending):
    """Pivot A at a on the x axis (its pin circle), the roller r_r at B0 on the base circle,
    the arm (bold) on the line A–B0: a, L, r_r from the brief, r0 as designed."""
    cam, msp, n = bending["cam"], bending["msp"], bending["n"]
    a, L, rr = _rocker_start(bending["brief"])
    r0 = cam.base_radius * 1e3
    O = _centre(msp, r0, n)
    sigma = 1 if cam.params.rotation > 0 else -1
    sense = sigma if bending["brief"].bending_cam.follower.rise_sense == "same" else -sigma
    A, B0 = complex(a), _b0(a, L, r0, sense)
    assert abs(abs(B0 - A) - L) < 1e-9 and abs(abs(B0) - r0) < 1e-9

    def paper(z):
        return O + z / n

    circles = [(complex(c.dxf.center.x, c.dxf.center.y), c.dxf.radius, c.dxf.layer)
               for c in msp.query("CIRCLE")]
    assert any(abs(c - paper(A)) < 1e-6 for c, _, _ in circles), "no pin at the pivot A"
    rollers = [c for c, r, layer in circles if layer == "OUTLINE" and abs(r * n - rr) < 1e-6]
    assert any(abs(c - paper(B0)) < 1e-6 for c in rollers), "no roller r_r at B0"
    u = (B0 - A) / L
    arms = []
    for ln in msp.query('LINE[layer=="OUTLINE"]'):
        p, q = (complex(ln.dxf.start.x, ln.dxf.start.y) - O) * n, (complex(ln.dxf.end.x, ln.dxf.end.y) - O) * n
        off = [abs(np.imag((z - A) * np.conj(u))) for z in (p, q)]        # distance from A–B0
        along = [np.real((z - A) * np.conj(u)) for z in (p, q)]
        if max(off) < 1e-6 and min(along) > -1e-6 and max(along) < L + 1e-6:
            arms.append(abs(q - p))
    assert arms and max(arms) > 0.8 * L, arms


def _pressure_angles(cam, a, L, r0, sense, sigma, points=400_000):
    """Largest pressure angle of the rise and of the return [°] by brute force: the rocker
    point B in the frame, the cam's profile normal there (the pitch curve's, turned back by
    the cam angle) against B's velocity as a point of the rocker (⟂ AB)."""
    prog = cam.params.programme
    delta = np.linspace(0.0, 2 * np.pi, points, endpoint=False)
    h = 2 * np.pi / points
    A, B0 = complex(a), _b0(a, L, r0, sense)

    def pitch(d):                       # the rocker point in the cam frame
        s = prog.evaluate(np.mod(d, 2 * np.pi)).s
        return (A + (B0 - A) * np.exp(1j * sense * s)) * np.exp(-1j * sigma * d)

    F = pitch(delta) * np.exp(1j * sigma * delta)                     # frame position
    T = (pitch(delta + h / 2) - pitch(delta - h / 2)) / h * np.exp(1j * sigma * delta)
    normal = 1j * T / np.abs(T)
    v = 1j * (F - A) / np.abs(F - A)
    alpha = np.degrees(np.arccos(np.clip(np.abs(np.real(normal * np.conj(v))), 0, 1)))
    out = {}
    for kind in ("rise", "return"):
        mask = np.zeros_like(delta, dtype=bool)
        for start, span, seg in zip(prog.starts, prog.spans, prog.segments):
            if seg.kind == kind:
                mask |= (delta > start + 2 * h) & (delta < start + span - 2 * h)
        out[kind] = float(np.max(alpha[mask]))
    return out


def test_bending_cam_data_table_prints_the_design(bending):
    cam, sheet, results = bending["cam"], bending["sheet"], bending["results"]
    a, L, rr = _rocker_start(bending["brief"])
    r0 = cam.base_radius * 1e3
    assert _row(sheet, "基圆半径") == [f"{r0:.2f} mm"]
    assert r0 == pytest.approx(results["bending_cam"].base_radius * 1e3)
    assert _row(sheet, "滚子半径") == [f"{rr:.2f} mm"]
    assert _row(sheet, "中心距") == [f"{a:.2f} mm"]
    assert _row(sheet, "摆杆长度") == [f"{L:.2f} mm"]
    # the swing the drawn four-bar needs for the full bend (the cam is designed for it)
    need = np.degrees(results["bending"].rounded.input_swing_needed)
    assert _number(_row(sheet, "最大摆角")[0]) == pytest.approx(need, abs=0.005 + 1e-9)
    # φ0: the angle at A in the triangle O–A–B0
    phi0 = np.degrees(np.arccos((a * a + L * L - r0 * r0) / (2 * a * L)))
    assert _number(_row(sheet, "初始摆角")[0]) == pytest.approx(phi0, abs=0.005 + 1e-9)
    sigma = 1 if cam.params.rotation > 0 else -1
    sense = sigma if bending["brief"].bending_cam.follower.rise_sense == "same" else -sigma
    ref = _pressure_angles(cam, a, L, r0, sense, sigma)
    rise, ret = _row(sheet, "推程最大压力角"), _row(sheet, "回程最大压力角")
    assert _number(rise[0]) == pytest.approx(ref["rise"], abs=0.006)
    assert _number(ret[0]) == pytest.approx(ref["return"], abs=0.006)
    assert rise[1].endswith("合格") and ret[1].endswith("合格")
