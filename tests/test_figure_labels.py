"""Figure labels clear of each other and of the links (issue 19, page review of session 28):
the shaper's free-body diagram and force polygon of group 3–4 at position 4 (zh Fig. 8:
F_R23/F_R43 printed over each other, G4 and F_I4 too small) and the die-cutter's skeleton
(zh Fig. 1: "D" and "B" on the links).

The figures are drawn as the report draws them; the figure is taken where it would be saved
and measured after its final layout with matplotlib's text extents. What is measured comes
from the drawn artists themselves (texts, arrows, thick link lines), not from the placement
code's own bookkeeping.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from mechdesign.render import figures as F
from mechdesign.render import label_layout as LL


def _captured(monkeypatch) -> dict:
    figs: dict = {}

    def save(fig, path):            # keep the figure instead of writing it
        figs[Path(path).name] = fig

    monkeypatch.setattr(F, "save_png", save)
    return figs


def _labels(ax) -> list:
    from matplotlib.text import Annotation

    return [t for t in ax.texts if t.get_text().strip() and not isinstance(t, Annotation)]


def _obstacles(ax, min_width: float) -> list:
    """The arrows (tail → head) and the thick lines (links) of an axes, as data segments."""
    from matplotlib.text import Annotation

    segs = []
    for t in ax.texts:
        if isinstance(t, Annotation) and t.arrow_patch is not None:
            (x0, y0), (x1, y1) = t.xyann, t.xy
            segs.append((complex(x0, y0), complex(x1, y1)))
    for line in ax.lines:
        if line.get_linewidth() >= min_width and line.get_linestyle() == "-":
            xs, ys = line.get_data()
            zs = [complex(x, y) for x, y in zip(xs, ys)]
            segs += list(zip(zs[:-1], zs[1:]))
    return segs


def test_the_clash_measure_sees_overlapping_labels():
    """The measure itself: two labels at the same place, a label on a line."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, 1], lw=2)
    a = ax.text(0.5, 0.5, "$F_{R23}$", fontsize=9)
    b = ax.text(0.5, 0.5, "$F_{R43}$", fontsize=9)
    c = ax.text(0.1, 0.9, "free", fontsize=9)
    clashes = LL.overlaps(ax, [a, b, c], [(0j, 1 + 1j)])
    plt.close(fig)
    assert any("over" in s for s in clashes) and any("on a line" in s for s in clashes)
    assert not any("free" in s for s in clashes)


def test_shaper_force_figure_labels_do_not_overlap(example_results, monkeypatch, tmp_path):
    from mechdesign.render import graphical_report as G

    figs = _captured(monkeypatch)
    G.graphical_figures(example_results("shaper"), tmp_path, "zh")
    fig = figs["linkage_graph_4_f1.png"]            # position 4, group 3–4 (zh Fig. 8)
    for ax in fig.axes:
        labels = _labels(ax)
        assert labels
        assert all(t.get_fontsize() >= 8 for t in labels), [t.get_text() for t in labels]
        clashes = LL.overlaps(ax, labels, _obstacles(ax, 2.0))
        assert not clashes, clashes
    for name, other in figs.items():                # every force figure of both positions
        if "_f" in name:
            for ax in other.axes:
                assert not [s for s in LL.overlaps(ax, _labels(ax), []) if "over" in s], name


def test_die_cutter_skeleton_names_are_off_the_links(example_results, monkeypatch, tmp_path):
    from mechdesign.machines import get_machine

    import importlib

    figs = _captured(monkeypatch)
    r = example_results("die_cutter")
    report = importlib.import_module(get_machine(r["brief"].machine).report_module)
    report.make_figures(r, tmp_path, "zh")
    fig = figs.get("press_mechanism.png")
    assert fig is not None, sorted(figs)
    (ax,) = fig.axes
    names = [t for t in _labels(ax) if t.get_fontsize() >= 7]      # not the position numbers
    # O1 typeset as O₁ (mathtext, upright in the text font; issue 19 point 3)
    assert {t.get_text() for t in names} >= {"B", "D", "C", r"$\mathregular{O_1}$"}
    clashes = LL.overlaps(ax, names, _obstacles(ax, 1.5))
    assert not clashes, clashes
