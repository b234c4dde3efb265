"""The offset slider-crank figure of the crank-rocker report read back as data (the lines the
figure draws, not its pixels) against the mechanism's own definition: the slider's extremes
lie on the guide, where crank and rod are folded (AC1 = b − a) and extended (AC2 = b + a),
and the crank pivot A is the offset e away from the guide."""
from __future__ import annotations

import contextlib
import math
from types import SimpleNamespace

import numpy as np
import pytest

from mechdesign.machines.crank_rocker import report
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MM = 1e3


def _drawn(monkeypatch, sl):
    """The axes the figure drew into (the figure is not saved)."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    kept = {}

    @contextlib.contextmanager
    def fake(path, nrows=1, size=(7.0, 3.2), sharex=True):
        fig, axes = plt.subplots(nrows, 1, figsize=size, sharex=sharex, squeeze=False)
        kept["axes"] = [ax for ax in axes[:, 0]]
        yield kept["axes"]

    monkeypatch.setattr(report, "figure", fake)
    phi = np.linspace(0.0, 2 * np.pi, 37)
    ss = SimpleNamespace(phi=phi, alpha=np.zeros_like(phi), slow=phi < np.pi)
    report._slider(Path("unused.png"), "en", sl, ss, 50.0)
    ax = kept["axes"][0]
    plt.close(ax.figure)
    return ax


@pytest.mark.parametrize("K, H, e", [(1.4, 0.100, 0.020), (1.2, 0.080, 0.010)])
def test_slider_figure_draws_the_guide_through_the_slider_extremes(monkeypatch, K, H, e):
    from mechdesign.core import fourbar as fb

    cons = fb.slider_crank_construction(K, H, e)
    a, b = fb.offset_slider_crank(K, H, e)
    sl = SimpleNamespace(construction=cons, crank=a, rod=b, offset=e, stroke=H)
    ax = _drawn(monkeypatch, sl)
    guide = [ln for ln in ax.get_lines() if ln.get_label() == report.LABELS["en"]["guide"]]
    assert len(guide) == 1
    gy = np.asarray(guide[0].get_ydata(), float)
    assert np.ptp(gy) == 0.0                              # a straight horizontal guide
    y_guide = gy[0] / MM
    # A (drawn at the origin) is the offset e away from the guide
    assert abs(abs(y_guide) - e) < 1e-12
    # the slider blocks (open squares) of the two extremes sit on the guide, H apart, at the
    # folded and extended distances b − a and b + a from A
    blocks = [ln for ln in ax.get_lines() if ln.get_marker() == "s" and ln.get_mfc() == "none"]
    assert len(blocks) == 2
    pts = sorted((complex(ln.get_xdata()[0], ln.get_ydata()[0]) / MM for ln in blocks), key=abs)
    for p in pts:
        assert abs(p.imag - y_guide) < 1e-12
    assert abs(abs(pts[1].real - pts[0].real) - H) < 1e-12
    assert abs(abs(pts[0]) - (b - a)) < 1e-12
    assert abs(abs(pts[1]) - (b + a)) < 1e-12
    # the offset mark runs from A to the guide
    mark = [ln for ln in ax.get_lines() if ln.get_linestyle() == "--" and ln.get_xdata()[0] == 0
            and len(ln.get_xdata()) == 2]
    assert mark and abs(mark[0].get_ydata()[1] / MM - y_guide) < 1e-12
