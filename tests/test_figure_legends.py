"""Legends off the curves and cam curves in the caption's colours (page review of session 43).

- crank_rocker Figs 2–3, press Fig. 3, die_cutter Fig. 5: a legend lay over the curves
  (linkage_sixbar's angle figure, slotter's reactions, lockbeam's pressure angle likewise).
  Measured on the figure as it is saved (the real save_png runs): every point of every
  line an axes draws, sampled along its path at one pixel or less in display coordinates,
  and every text and arrow it draws, lie outside each legend's frame.
- cam_7_3 Fig. 1, die_cutter Fig. 16: the caption says "(blue: rise, orange: return)" while
  the curves were all one blue. Each curve is checked point by point: a point strictly
  inside a rise is drawn blue (C0), inside a return orange (C1), and no blue or orange
  line has a point in another segment.
"""
from __future__ import annotations

import importlib
import re
from pathlib import Path

import numpy as np
import pytest

from mechdesign.render import figures as F


def _drawn(monkeypatch, tmp_path) -> dict:
    """Figures as saved: the real save_png runs (it settles the legends) and the figure is
    kept for measuring."""
    figs: dict = {}
    real = F.save_png

    def save(fig, path):
        real(fig, path)
        figs[Path(path).name] = fig

    monkeypatch.setattr(F, "save_png", save)
    return figs


def _make_figures(example_results, brief, lang, monkeypatch, tmp_path) -> dict:
    from mechdesign.machines import get_machine

    figs = _drawn(monkeypatch, tmp_path)
    r = example_results(brief)
    report = importlib.import_module(get_machine(r["brief"].machine).report_module)
    report.make_figures(r, tmp_path, lang)
    assert figs
    return figs


def _points(line) -> np.ndarray:
    """The line's path in display coordinates, sampled at 1 px or less (NaN gaps kept out)."""
    xy = line.get_transform().transform_path(line.get_path()).vertices
    out = [xy[:1]]
    for p, q in zip(xy[:-1], xy[1:]):
        if not (np.isfinite(p).all() and np.isfinite(q).all()):
            out.append(xy[:0])
            continue
        n = max(int(np.ceil(np.hypot(*(q - p)))), 1)
        t = np.arange(1, n + 1)[:, None] / n
        out.append(p + t * (q - p))
    pts = np.concatenate(out)
    return pts[np.isfinite(pts).all(axis=1)]


def _legends(ax) -> list:
    from matplotlib.legend import Legend

    return [c for c in ax.get_children() if isinstance(c, Legend) and c.get_visible()]


def _covered(fig) -> list[str]:
    from matplotlib.text import Annotation

    from mechdesign.render.label_layout import _renderer

    renderer = _renderer(fig)           # the layout save_png left, as saved
    bad = []
    for ax in fig.axes:
        for leg in _legends(ax):
            box = leg.get_window_extent(renderer)
            for line in ax.lines:
                if not line.get_visible() or len(line.get_xydata()) == 0:
                    continue
                pts = _points(line)
                if line.get_clip_on():          # what the axes show of it
                    clip = ax.get_window_extent(renderer)
                    pts = pts[(pts[:, 0] >= clip.x0) & (pts[:, 0] <= clip.x1)
                              & (pts[:, 1] >= clip.y0) & (pts[:, 1] <= clip.y1)]
                inside = ((pts[:, 0] > box.x0) & (pts[:, 0] < box.x1)
                          & (pts[:, 1] > box.y0) & (pts[:, 1] < box.y1))
                if inside.any():
                    bad.append(f"line {line.get_label()!r}")
            for t in ax.texts:
                boxes = []
                if t.get_text().strip():
                    boxes.append(t.get_window_extent(renderer))
                if isinstance(t, Annotation) and t.arrow_patch is not None:
                    boxes.append(t.arrow_patch.get_window_extent(renderer))
                if any(b.x0 < box.x1 and box.x0 < b.x1 and b.y0 < box.y1 and box.y0 < b.y1
                       for b in boxes):
                    bad.append(f"text {t.get_text()!r}")
            # and within the figure
            if box.x0 < 0 or box.y0 < 0 or box.x1 > fig.bbox.x1 or box.y1 > fig.bbox.y1:
                bad.append("outside the figure")
    return bad


_LEGENDS = [("crank_rocker", "zh"), ("crank_rocker", "en"), ("press", "zh"), ("press", "en"),
            ("die_cutter", "zh"), ("die_cutter", "en"), ("linkage_sixbar", "en"),
            ("slotter", "en"), ("lockbeam", "en"), ("shaper_lengths", "en"),
            ("furnace_pusher", "en"), ("cam_7_3", "en")]


@pytest.mark.parametrize("brief,lang", _LEGENDS)
def test_no_legend_covers_a_curve(example_results, monkeypatch, tmp_path, brief, lang):
    figs = _make_figures(example_results, brief, lang, monkeypatch, tmp_path)
    bad = []
    with_legend = 0
    for name, fig in sorted(figs.items()):
        with_legend += any(_legends(ax) for ax in fig.axes)
        bad += [f"{name}: legend over {what}" for what in _covered(fig)]
    assert with_legend
    assert not bad, bad


def test_a_legend_with_no_free_place_goes_below_the_axes(tmp_path, monkeypatch):
    """A legend whose axes are full of curves everywhere (no corner free) is put under the
    axes, below their tick labels and axis label, not over the curves."""
    figs = _drawn(monkeypatch, tmp_path)
    from mechdesign.render.legends import legend

    x = np.linspace(0, 1, 50)
    with F.figure(tmp_path / "full.png", 1, (5.0, 3.0)) as (ax,):
        for k in range(25):
            ax.plot(x, np.full_like(x, k / 24), lw=0.8, label=f"curve {k}" if k < 4 else None)
        for k in range(25):
            ax.plot(np.full_like(x, k / 24), x, lw=0.8)
        ax.set_xlabel("x (mm)")
        legend(ax, fontsize=7, loc="upper right")
    fig = figs["full.png"]
    assert not _covered(fig)
    from mechdesign.render.label_layout import _renderer

    renderer = _renderer(fig)
    (ax,) = fig.axes
    box = ax.get_legend().get_window_extent(renderer)
    label = ax.xaxis.label.get_window_extent(renderer)
    assert box.y1 <= label.y0                       # under the axis label
    ticks = [t.get_window_extent(renderer) for t in ax.get_xticklabels() if t.get_text()]
    assert all(box.y1 <= t.y0 for t in ticks)


def test_every_legend_of_the_report_figures_is_asked_for_through_the_helper():
    """One rule for every multi-curve plot: no plotting module calls ``ax.legend`` itself
    but through render/legends.py (the cycle diagrams' and the gear mesh's legends, placed
    outside their drawings by design, aside)."""
    root = Path(__file__).resolve().parents[1] / "src" / "mechdesign"
    allowed = {"render/legends.py", "render/cycle_figures.py", "render/gear_figures.py"}
    bad = []
    for path in sorted(root.rglob("*.py")):
        rel = path.relative_to(root).as_posix()
        if rel in allowed:
            continue
        for n, text in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if re.search(r"\b\w+\.legend\(", text) and "ax" in text.split(".legend(")[0]:
                bad.append(f"{rel}:{n}: {text.strip()}")
    assert not bad, bad


# ---- cam motion diagrams: the colours the caption names

def _segment_kinds(c) -> list[tuple[float, float, str]]:
    prog = c.params.programme
    return [(float(np.degrees(s)), float(np.degrees(s + sp)), seg.kind)
            for s, sp, seg in zip(prog.starts, prog.spans, prog.segments)]


def _cam_of(results):
    return next(v for v in results.values() if hasattr(v, "drawing") and hasattr(v, "grid"))


@pytest.mark.parametrize("brief,name", [("cam_7_3", "cam_svaj.png"), ("die_cutter", "cam_svaj.png"),
                                        ("press", "cam_svaj.png")])
def test_cam_motion_curves_are_blue_on_the_rise_and_orange_on_the_return(
        example_results, monkeypatch, tmp_path, brief, name):
    from matplotlib.colors import to_rgb

    figs = _make_figures(example_results, brief, "en", monkeypatch, tmp_path)
    fig = figs[name]
    segs = _segment_kinds(_cam_of(example_results(brief)))
    kinds = {k for *_, k in segs}
    assert {"rise", "return"} <= kinds
    blue, orange = to_rgb("C0"), to_rgb("C1")
    tol = 0.05                          # degrees kept off the segments' ends

    def kind_at(x):
        for a, b, k in segs:
            if a + tol < x < b - tol:
                return k
        return None

    assert len(fig.axes) == 4
    for ax in fig.axes:
        spans = {"rise": [], "return": []}       # x ranges of the blue and orange lines
        for line in ax.lines:
            xs = np.asarray(line.get_xdata(), dtype=float)
            if len(xs) < 3:
                continue
            colour = to_rgb(line.get_color())
            for x in xs:
                k = kind_at(x)
                if colour == blue:
                    assert k == "rise", (name, x, k)
                elif colour == orange:
                    assert k == "return", (name, x, k)
            if colour in (blue, orange):
                spans["rise" if colour == blue else "return"].append((xs.min(), xs.max()))
        # each rise and return drawn in its colour over its whole span
        for a, b, k in segs:
            if k in spans:
                assert any(lo <= a + 0.5 and hi >= b - 0.5 for lo, hi in spans[k]), (k, a, b, spans)
