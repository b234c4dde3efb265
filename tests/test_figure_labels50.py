"""The crank-rocker's construction figure (Fig. 1): the angle θ's label stood on the point
label B₂ (page review 48, crank_rocker zh/en p.5): B₂ lies on the ray A–C₂ at the crank's
length from A, and θ's arc and label were put at a fixed share of |AC| that fell on it.
Measured with matplotlib's text extents after the figure's final layout, as
tests/test_figure_labels.py measures the other figures."""
from __future__ import annotations

import pytest

from mechdesign.render import label_layout as LL
from tests.test_figure_labels import _captured, _gap_pt, _labels


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_no_label_of_the_construction_figure_stands_over_another(example_results, monkeypatch,
                                                                 tmp_path, lang):
    from mechdesign.machines.crank_rocker import report as R

    figs = _captured(monkeypatch)
    R.make_figures(example_results("crank_rocker"), tmp_path, lang)
    fig = figs["construction.png"]
    (ax,) = [a for a in fig.axes if _labels(a)]
    labels = _labels(ax)
    clashes = [s for s in LL.overlaps(ax, labels, []) if "over" in s]
    assert clashes == [], clashes
    # θ's label stands apart from every other label
    renderer = LL._renderer(fig)
    box = {t.get_text(): t.get_window_extent(renderer) for t in labels}
    theta = [k for k in box if "θ" in k or "theta" in k]
    assert len(theta) == 1, sorted(box)
    gaps = {k: _gap_pt(box[theta[0]], b, fig) for k, b in box.items() if k != theta[0]}
    assert min(gaps.values()) >= 5.0, gaps      # was 2.3 pt from B₂ (read "θ B₂")
