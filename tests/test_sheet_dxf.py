"""Drawing output thinned to the paper's resolution and written in bulk (issue 22, point 6),
and DXF files as a CAD program opens them (point 5): extents set, only the styles used.

The thinning is checked against a brute-force distance from every original point to every
kept segment (no code shared with :func:`mechdesign.render.sheet.thin`); the extremes of
the curve are compared with numpy's min/max of the full curve."""
from __future__ import annotations

import numpy as np
import pytest

from mechdesign.render.sheet import CHORD_TOLERANCE, Sheet, thin

ezdxf = pytest.importorskip("ezdxf")


def _distance_to_polyline(points: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """Distance of each point to the nearest segment of ``poly`` (brute force)."""
    a, b = poly[:-1][None, :], poly[1:][None, :]
    p = points[:, None]
    ab = b - a
    t = np.clip(((p - a) * ab.conj()).real / np.maximum(np.abs(ab) ** 2, 1e-300), 0, 1)
    return np.min(np.abs(p - (a + t * ab)), axis=1)


CURVES = {
    # a motion curve as the analysis sheet draws it: 0–300 mm wide, ±80 mm high
    "sine": lambda t: 300 * t / (2 * np.pi) + 1j * (60 * np.sin(t) + 20 * np.sin(3 * t)),
    # a closed coupler-like loop with a cusp-ish turn
    "loop": lambda t: 80 * np.cos(t) + 10 * np.cos(2 * t) + 1j * (50 * np.sin(t) - 30 * np.sin(2 * t)),
    # straight stretches with corners (a polygon sampled densely): the corners must stay
    "corners": lambda t: np.interp(t, [0, 2, 4, 2 * np.pi], [0, 100, 100, 0])
    + 1j * np.interp(t, [0, 2, 4, 2 * np.pi], [0, 0, 50, 50]),
}


@pytest.mark.parametrize("name", sorted(CURVES))
@pytest.mark.parametrize("tolerance", [CHORD_TOLERANCE, 0.1])
def test_thinned_curve_within_chord_error_and_extremes_kept(name, tolerance):
    t = np.linspace(0, 2 * np.pi, 6001)
    z = CURVES[name](t)
    w = thin(z, tolerance)
    assert 2 <= len(w) < len(z) / 4                 # thinned …
    assert w[0] == z[0] and w[-1] == z[-1]          # … ends kept
    assert np.all(np.isin(w, z))                    # a subset of the given points, in order
    idx = np.searchsorted(np.arange(len(z)), [np.flatnonzero(z == p)[0] for p in w])
    assert np.all(np.diff(idx) > 0)
    # every original point (so every point of the original polyline) within the tolerance
    assert _distance_to_polyline(z, w).max() <= tolerance * (1 + 1e-12)
    # the extremes exactly: the curve's least and greatest x and y are vertices
    for part in (np.real, np.imag):
        assert part(w).max() == part(z).max() and part(w).min() == part(z).min()


def test_thinning_100000_points_is_small():
    # its time is a benchmark (benchmarks/bench_limits.py)
    t = np.linspace(0, 2 * np.pi, 100_000)
    z = CURVES["sine"](t)
    w = thin(z)
    assert len(w) < 2000


def check_dxf_tables(doc) -> None:
    """Extents ⊇ every entity's box, every text style used is defined and every one
    defined is used (DXF's default style is Standard)."""
    from ezdxf import bbox

    lo, hi = doc.header["$EXTMIN"], doc.header["$EXTMAX"]
    assert lo[0] < hi[0] and lo[1] < hi[1], (lo, hi)
    for e in doc.modelspace():
        box = bbox.extents([e], fast=False)
        if box.has_data:
            assert box.extmin.x >= lo[0] - 1e-6 and box.extmin.y >= lo[1] - 1e-6, e
            assert box.extmax.x <= hi[0] + 1e-6 and box.extmax.y <= hi[1] + 1e-6, e
    defined = {s.dxf.name.lower() for s in doc.styles}
    used = set()
    for e in doc.entitydb.values():
        if e.dxftype() in ("TEXT", "MTEXT", "ATTRIB", "ATTDEF"):
            used.add(e.dxf.get("style", "Standard").lower())
    for d in doc.dimstyles:
        used.add((d.dxf.get("dimtxsty") or "Standard").lower())
    assert used == defined, (used, defined)
    for s in doc.styles:                         # a font with the CJK and Greek glyphs
        assert s.dxf.font.lower().startswith(("notosanssc", "notosanscjk", "notoserifsc",
                                              "sourcehan", "simsun", "simhei", "msyh")), s.dxf.font


def test_dxf_of_a_100000_point_sheet_in_bulk(tmp_path):
    # its time (was quadratic: ~350 s for a 100 000-point run's sheets) is a benchmark,
    # benchmarks/bench_limits.py
    from mechdesign.render.sheet_dxf import write_dxf

    s = Sheet("A3")
    t = np.linspace(0, 2 * np.pi, 100_000)
    s.polyline(50 + CURVES["sine"](t) + 150j, "CURVES")
    s.polyline(200 + CURVES["loop"](t) + 150j, "OUTLINE", closed=True, tolerance=None)
    s.text(30 + 20j, "机构 ω₂ α β φ θ μ", 5.0)
    s.dimension(30 + 40j, 130 + 40j, 8.0, 0.2)
    path = write_dxf(s, tmp_path / "big.dxf")
    doc = ezdxf.readfile(path)
    polys = list(doc.modelspace().query("LWPOLYLINE"))
    sizes = sorted(len(p) for p in polys)
    assert sizes[0] < 2000 and sizes[-1] == 100_000          # thinned; exact one kept whole
    exact = max(polys, key=len)
    xy = np.array(exact.get_points("xy"))
    z = 200 + CURVES["loop"](t) + 150j
    assert np.allclose(xy[:, 0], z.real) and np.allclose(xy[:, 1], z.imag)
    check_dxf_tables(doc)
    text = next(iter(doc.modelspace().query("TEXT")))
    assert "ω" in text.dxf.text and "机构" in text.dxf.text


# ------------------------------------------------------------------ the process's end

def _run_main(tmp_path, env_extra: dict, args: list[str]):
    """``mechdesign.__main__.main`` in a fresh interpreter with an atexit handler that
    writes a marker file: the handler runs only with the ordinary interpreter shutdown."""
    import os
    import subprocess
    import sys

    marker = tmp_path / "atexit-ran"
    code = ("import atexit, pathlib, sys\n"
            f"atexit.register(lambda: pathlib.Path({str(marker)!r}).write_text('x'))\n"
            f"sys.argv = ['mechdesign'] + {args!r}\n"
            "from mechdesign.__main__ import main\nmain()\n")
    env = {k: v for k, v in os.environ.items() if k != "MECHDESIGN_CLEAN_EXIT"}
    env.update(env_extra)
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    return proc, marker.exists()


def test_cli_process_ends_without_interpreter_shutdown(tmp_path):
    from pathlib import Path

    brief = str(Path(__file__).resolve().parents[1] / "designs" / "shaper.yaml")
    proc, ran = _run_main(tmp_path, {}, ["check", brief])
    assert proc.returncode == 0 and "ok:" in proc.stdout      # output flushed before leaving
    assert not ran                                            # os._exit: no shutdown
    proc, ran = _run_main(tmp_path, {}, ["check", str(tmp_path / "missing.yaml")])
    assert proc.returncode == 2 and "missing.yaml" in proc.stdout + proc.stderr
    proc, ran = _run_main(tmp_path, {"MECHDESIGN_CLEAN_EXIT": "1"}, ["check", brief])
    assert proc.returncode == 0 and ran                       # the ordinary shutdown on request


def test_typst_fonts_are_found_once_per_process():
    from mechdesign.render.pdf import typst_fonts

    fonts = typst_fonts()
    assert typst_fonts() is fonts                             # scanned once per process
    families = set(fonts.families())
    assert {"New Computer Modern", "New Computer Modern Math"} <= families
