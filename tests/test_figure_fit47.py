"""Page review 47 (tgb en Fig. 2, lockbeam en Fig. 11): a stacked panel's y-label longer than
the panel ran into the label above it, and the name of the bending cam's 6° far dwell ran into
"rise" and "return" ("risefar dwellreturn"). Both are measured on the texts as drawn."""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from mechdesign.render.cam_figures import stagger_names  # noqa: E402
from mechdesign.render.figures import _split_label, fit_ylabels  # noqa: E402


def _overlap(a, b) -> bool:
    return a.x0 < b.x1 and b.x0 < a.x1 and a.y0 < b.y1 and b.y0 < a.y1


def test_a_ylabel_longer_than_its_panel_is_set_in_two_lines_and_fits():
    fig, axes = plt.subplots(4, 1, figsize=(7.0, 7.4), sharex=True)
    long = "angular acceleration $\\mathrm{d}^2\\varphi/\\mathrm{d}t^2$ (rad/s²)"
    axes[2].set_ylabel(long, fontsize=8)
    axes[0].set_ylabel("swing (°)", fontsize=8)
    renderer = fig.canvas.get_renderer()
    assert axes[2].yaxis.label.get_window_extent(renderer).height > axes[2].get_window_extent(renderer).height
    fit_ylabels(fig)
    label = axes[2].yaxis.label
    assert "\n" in label.get_text() and label.get_text().replace("\n", " ") == long
    assert label.get_window_extent(renderer).height <= axes[2].get_window_extent(renderer).height
    assert axes[0].yaxis.label.get_text() == "swing (°)"            # short: left alone
    plt.close(fig)


def test_a_label_is_never_broken_inside_its_mathtext():
    assert _split_label("a $b c d e f$ g") in ("a\n$b c d e f$ g", "a $b c d e f$\ng")
    assert _split_label("$x y$") is None


def test_names_that_would_run_into_each_other_go_up_a_row():
    fig, ax = plt.subplots(figsize=(7.0, 2.0))
    ax.set_xlim(0, 360)
    segments = [(0, 294, "near dwell"), (294, 324, "rise"), (324, 330, "far dwell"), (330, 360, "return")]
    texts = [ax.text((a + b) / 2, 1.02, name, transform=ax.get_xaxis_transform(), ha="center",
                     va="bottom", fontsize=8) for a, b, name in segments]
    renderer = fig.canvas.get_renderer()
    before = [t.get_window_extent(renderer) for t in texts]
    assert any(_overlap(before[i], before[j]) for i in range(4) for j in range(i + 1, 4))
    stagger_names(texts)
    after = [t.get_window_extent(renderer) for t in texts]
    assert not any(_overlap(after[i], after[j]) for i in range(4) for j in range(i + 1, 4))
    assert texts[0].get_position()[1] == 1.02          # the wide dwell's name stays in the row
    plt.close(fig)
