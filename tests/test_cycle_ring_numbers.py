"""review36 Top 6: the ring numbers of the circular motion-cycle diagram (report figure,
render.cycle_figures.circular) stood at φ ≈ 0 over the phase names written there
(die_cutter "② osed", "① ar"; lockbeam "③ ck", zh "③回").

Measured on the figure as saved (tight_layout, then matplotlib's own text boxes after
canvas.draw()): each number's circle meets no phase name, no other number, and lies on its
own ring."""
from __future__ import annotations

import numpy as np
import pytest

from mechdesign.render import components_report as cr
from mechdesign.render import cycle_figures as cf
from mechdesign.render import figures


def _drawn(results, lang, tmp_path, monkeypatch):
    """The circular diagram's figure of the example's cycle, laid out as saved."""
    cyc = results["cycle"].diagram
    kept = []
    monkeypatch.setattr(figures, "save_png", lambda fig, path: kept.append(fig))
    rows = cr._phase_rows(cyc, lang)
    cf.circular.__wrapped__(tmp_path / "c.png", lang, rows, cyc.origin * cr.DEG,
                            cr._states_used(cyc, lang))
    (fig,) = kept
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(fig)           # the figure was closed after "saving"
    fig.tight_layout()
    canvas.draw()
    return fig, rows, canvas.get_renderer()


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", ["die_cutter", "lockbeam"])
def test_ring_numbers_clear_of_the_phase_names(example_results, name, lang, tmp_path,
                                               monkeypatch):
    fig, rows, renderer = _drawn(example_results(name), lang, tmp_path, monkeypatch)
    (ax,) = fig.axes
    labels = {p[3] for _, phases in rows for p in phases}
    names = [t for t in ax.texts if t.get_text() in labels]
    numbers = [t for t in ax.texts if t.get_text().isdigit() and t.get_bbox_patch() is not None]
    assert sorted(t.get_text() for t in numbers) == [str(i + 1) for i in range(len(rows))]
    assert len(names) >= len(rows)           # the names that fit their arc are drawn

    def overlap(a, b):
        return a.x0 < b.x1 and b.x0 < a.x1 and a.y0 < b.y1 and b.y0 < a.y1

    r0, w = 1.0, 0.8                         # the rings of cycle_figures.circular
    for t in numbers:
        text_box = t.get_window_extent(renderer)
        circle = t.get_bbox_patch().get_window_extent(renderer)
        for n in names:
            box = n.get_window_extent(renderer)
            assert not overlap(text_box, box), f"ring number {t.get_text()} over «{n.get_text()}»"
            assert not overlap(circle, box), f"ring number {t.get_text()}'s circle over «{n.get_text()}»"
        for u in numbers:
            if u is not t:
                assert not overlap(circle, u.get_bbox_patch().get_window_extent(renderer))
        k = int(t.get_text()) - 1
        assert r0 + k * w < np.hypot(*t.get_position()) < r0 + (k + 1) * w
