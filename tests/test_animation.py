"""The mechanism animation (GIF): file properties and drawn geometry.

The geometric checks read pixels of the decoded GIF at positions computed here from
the rotation angle and the layout's fixed data → pixel mapping, so a bar drawn at the
wrong phase, mirrored, or on a different scale fails them.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PIL import Image, ImageChops

from mechdesign.machines.shaper import report as shaper_report
from mechdesign.render import animation as an

N = 360          # samples over the revolution
L = 100.0        # crank length [mm]
FRAMES = 24


def _crank_points(n: int = N, length: float = L) -> dict:
    theta = 2 * np.pi * np.arange(n) / n
    return {"O": np.zeros(n, complex), "A": length * np.exp(1j * theta)}


def _frame_rgb(path: Path, i: int) -> np.ndarray:
    with Image.open(path) as im:
        im.seek(i)
        return np.asarray(im.convert("RGB")).astype(int)


def _pixel(rgb: np.ndarray, layout: an.FrameLayout, z: complex) -> np.ndarray:
    col, row = layout.to_pixel(z)
    return rgb[int(row), int(col)]


def _near(px, color: str, tol: float = 30.0) -> bool:
    return float(np.linalg.norm(np.asarray(px) - np.asarray(an._rgb(color)))) < tol


@pytest.fixture(scope="module")
def crank_gif(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("anim") / "crank.gif"
    an.write_mechanism_gif(path, _crank_points(), [("O", "A")], pivots=["O"], trace="A",
                           title="crank", frames=FRAMES, fps=10, size_px=240)
    return path


def test_gif_file_properties(crank_gif):
    assert crank_gif.stat().st_size < 1_000_000
    assert not [p for p in crank_gif.parent.iterdir() if p != crank_gif]  # no temp file left
    with Image.open(crank_gif) as im:
        assert im.format == "GIF"
        assert im.is_animated
        assert im.n_frames == FRAMES
        assert im.info.get("loop") == 0
        assert im.info.get("duration") == pytest.approx(100, abs=10)
        assert max(im.size) <= 240


def test_frames_differ(crank_gif):
    with Image.open(crank_gif) as im:
        frames = []
        for i in (0, FRAMES // 3, 2 * FRAMES // 3):
            im.seek(i)
            frames.append(im.convert("RGB"))
    for a, b in ((0, 1), (1, 2), (0, 2)):
        assert ImageChops.difference(frames[a], frames[b]).getbbox() is not None


@pytest.mark.parametrize("frame", [0, FRAMES // 4, FRAMES // 2 + 2])
def test_crank_drawn_at_its_angle(crank_gif, frame):
    """Mid-crank pixel carries the crank colour; the opposite side and the perpendicular
    directions do not."""
    layout = an.mechanism_layout(_crank_points(), title="crank", size_px=240)
    rgb = _frame_rgb(crank_gif, frame)
    theta = 2 * np.pi * frame / FRAMES
    u = np.exp(1j * theta)
    bar = an.BAR_COLORS[0]
    for r in (0.45, 0.7):
        assert _near(_pixel(rgb, layout, r * L * u), bar), (frame, r)
        assert not _near(_pixel(rgb, layout, -r * L * u), bar), (frame, r)
        assert not _near(_pixel(rgb, layout, 1j * r * L * u), bar), (frame, r)
        assert not _near(_pixel(rgb, layout, -1j * r * L * u), bar), (frame, r)


def test_layout_orientation_and_scale():
    layout = an.mechanism_layout(_crank_points(), title="crank", size_px=240)
    c0, r0 = layout.to_pixel(0)
    c_up, r_up = layout.to_pixel(1j * L)
    c_right, r_right = layout.to_pixel(L)
    assert r_up < r0 and c_up == pytest.approx(c0)          # +y is up in the image
    assert c_right > c0 and r_right == pytest.approx(r0)    # +x is right
    assert c_right - c0 == pytest.approx(r0 - r_up)         # equal aspect
    # every sample lies inside the image, below the title band
    col, row = layout.to_pixel(_crank_points()["A"])
    assert col.min() > 0 and col.max() < layout.width
    assert row.min() > layout.title_px and row.max() < layout.height


def test_slider_block_aligned_with_its_angle(tmp_path):
    """A block on a bar turning about O: inside the block along the bar is block colour,
    the same distance across the bar (outside the thinner block) is background."""
    pts = _crank_points()
    pts["C"] = 0.6 * pts["A"]
    angle = np.angle(pts["A"])
    path = an.write_mechanism_gif(tmp_path / "slider.gif", pts, [("O", "A")], pivots=["O"],
                                  sliders=[("C", angle)], frames=8, size_px=240)
    layout = an.mechanism_layout({k: pts[k] for k in ("O", "A", "C")}, size_px=240)
    s = layout.mm_per_px
    hl, hh = an.BLOCK_PX[0] / 2 * s, an.BLOCK_PX[1] / 2 * s
    for frame in (1, 3):  # 45° and 135°
        u = np.exp(1j * 2 * np.pi * frame / 8)
        c = 0.6 * L * u
        rgb = _frame_rgb(path, frame)
        inside = c + 0.7 * hl * u + 0.6 * hh * 1j * u   # off the bar line, inside the block
        outside = c + 0.7 * hl * 1j * u                 # beyond the block's half-height
        assert _near(_pixel(rgb, layout, inside), an.BLOCK_FACE), frame
        assert _near(_pixel(rgb, layout, outside), an.BACKGROUND), frame


def test_bad_input_rejected(tmp_path):
    pts = _crank_points()
    with pytest.raises(KeyError):
        an.write_mechanism_gif(tmp_path / "x.gif", pts, [("O", "Z")], pivots=["O"])
    with pytest.raises(ValueError):
        an.write_mechanism_gif(tmp_path / "x.gif", {"O": np.zeros(10), "A": np.ones(12)},
                               [("O", "A")], pivots=["O"])
    assert not list(tmp_path.iterdir())


@pytest.fixture(scope="module")
def shaper_results(example_results):
    return example_results("shaper")


def test_shaper_gif(shaper_results, tmp_path):
    path = shaper_report.animate(shaper_results, tmp_path / "shaper.gif", "zh")   # time: bench_limits.py
    assert path.stat().st_size < 1_000_000
    with Image.open(path) as im:
        assert im.n_frames == 72 and im.info.get("loop") == 0
        assert max(im.size) <= 520

    args = shaper_report.animation_args(shaper_results, "zh")
    layout = an.animation_layout(**args)
    assert layout == an.mechanism_layout(args["points"], guides=args["guides"], title=args["title"])
    k = shaper_results["kinematics"]
    n = k.grid_size
    s = layout.mm_per_px
    for frame in (0, 9, 45):
        j = frame * n // 72
        p = {name: complex(k.points[name][j]) * 1e3 for name in ("O2", "O3", "A", "B", "F")}
        rgb = _frame_rgb(path, frame)
        # crank, guide bar (between A and B, away from the slider block) and rod
        assert _near(_pixel(rgb, layout, (p["O2"] + p["A"]) / 2), an.BAR_COLORS[0]), frame
        assert _near(_pixel(rgb, layout, p["A"] + 0.5 * (p["B"] - p["A"])), an.BAR_COLORS[1]), frame
        assert _near(_pixel(rgb, layout, (p["B"] + p["F"]) / 2), an.BAR_COLORS[2]), frame
        # ram block on the horizontal guide at F
        hl, hh = an.BLOCK_PX[0] / 2 * s, an.BLOCK_PX[1] / 2 * s
        assert _near(_pixel(rgb, layout, p["F"] - 0.7 * hl + 0.6j * hh), an.BLOCK_FACE), frame


def test_shaper_trace_is_the_ram_guide_line(shaper_results):
    args = shaper_report.animation_args(shaper_results, "en")
    f = args["points"][args["trace"]]
    y = float(shaper_results["synthesis"].design.guide_height) * 1e3
    assert np.allclose(f.imag, y, atol=1e-6)
    (a, b), = args["guides"]
    assert a.imag == b.imag == pytest.approx(y)
    assert a.real < f.real.min() and b.real > f.real.max()
    assert args["title"] == "Shaper linkage in motion"
