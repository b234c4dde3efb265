"""Legends that cover no curve (page review of session 43: the legends of crank_rocker
Figs 2–3, die_cutter Fig. 5 and press Fig. 3 lay over their curves).

Every legend of a report figure is asked for with :func:`legend` instead of ``ax.legend``.
It is drawn at once at the place the plot prefers; when the figure is saved
(:func:`settle`, called by :func:`.figures.save_png` after its texts are final), each such
legend is measured on the figure as it is laid out for saving and kept where it is only
if its frame (padded by :data:`PAD` pt) meets no line of the axes (a curve, a limit line,
a marker), no text or arrow drawn in them and no other legend. Otherwise the other places
inside the axes are tried in turn (:data:`PLACES`), and where none is free the legend goes
below the axes, under their tick labels and axis label, in as many columns as their width
holds; the figure is laid out again then (the axes give it room) and every legend checked
once more. What is measured is what is drawn: the lines' paths in display coordinates
(steps, polar interpolation and all), the texts' extents, the arrows' extents.
"""
from __future__ import annotations

import numpy as np

#: The places inside the axes tried after the one asked for (matplotlib's names).
PLACES = ("upper right", "upper left", "lower left", "lower right", "upper center",
          "lower center", "center right", "center left", "center")
#: Clearance kept between a legend's frame and anything drawn [pt].
PAD = 4.0
#: Gap between the axes' tick labels / axis label and a legend put below them [pt].
BELOW_GAP = 4.0
#: Layout rounds: a legend moved below the axes shrinks them, and the others are checked again.
ROUNDS = 3

_KEY = "_mechdesign_clear_legend"


def legend(ax, handles=None, labels=None, *, loc: str = "upper right", **kwargs):
    """Draw the legend of ``ax`` (its labelled artists, or ``handles`` with ``labels``) at
    ``loc``, to be moved when the figure is saved to where it covers nothing drawn
    (:func:`settle`). Takes ``ax.legend``'s keyword arguments; returns the legend."""
    if handles is None:
        handles, found = ax.get_legend_handles_labels()
        labels = found if labels is None else labels
    elif labels is None:
        labels = [h.get_label() for h in handles]
    if "ncol" in kwargs:
        kwargs["ncols"] = kwargs.pop("ncol")
    leg = ax.legend(handles, labels, loc=loc, **kwargs)
    setattr(ax, _KEY, {"handles": list(handles), "loc": loc, "kwargs": dict(kwargs),
                       "below": False})
    return leg


def _remake(ax, request, **override):
    """The axes' legend drawn again with its present texts (already set as the figure
    prints them: italic symbols, narrow dots) and other placing arguments."""
    old = ax.get_legend()
    texts = [t.get_text() for t in old.get_texts()] if old is not None else None
    kwargs = {**request["kwargs"], "loc": request["loc"], **override}
    return ax.legend(request["handles"], texts, **kwargs)


def _renderer(fig):
    from .label_layout import _renderer as renderer

    return renderer(fig)


def _segments_meet_box(xy: np.ndarray, box) -> bool:
    """Whether the polyline ``xy`` (n × 2, display coordinates; NaN breaks it) meets the
    box (x0, y0, x1, y1): a segment meets it when their bounding boxes overlap and the
    box's corners do not all lie strictly on one side of the segment's line."""
    if len(xy) < 2:
        return False
    p, q = xy[:-1], xy[1:]
    ok = np.isfinite(p).all(axis=1) & np.isfinite(q).all(axis=1)
    p, q = p[ok], q[ok]
    if not len(p):
        return False
    x0, y0, x1, y1 = box
    near = ((np.minimum(p[:, 0], q[:, 0]) <= x1) & (np.maximum(p[:, 0], q[:, 0]) >= x0)
            & (np.minimum(p[:, 1], q[:, 1]) <= y1) & (np.maximum(p[:, 1], q[:, 1]) >= y0))
    if not near.any():
        return False
    p, q = p[near], q[near]
    d = q - p
    sides = [d[:, 0] * (cy - p[:, 1]) - d[:, 1] * (cx - p[:, 0])
             for cx, cy in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))]
    s = np.array(sides)
    one_side = (s > 0).all(axis=0) | (s < 0).all(axis=0)
    return bool((~one_side).any())


def _points_in_box(xy: np.ndarray, box, grow: float) -> bool:
    if not len(xy):
        return False
    x0, y0, x1, y1 = box
    x, y = xy[:, 0], xy[:, 1]
    return bool(((x >= x0 - grow) & (x <= x1 + grow) & (y >= y0 - grow) & (y <= y1 + grow)).any())


def _boxes_meet(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _extent(artist, renderer):
    bb = artist.get_window_extent(renderer)
    return (bb.x0, bb.y0, bb.x1, bb.y1)


def covered(ax, leg, renderer, pad_px: float = 0.0) -> list[str]:
    """What the legend ``leg`` of ``ax`` covers (its frame grown by ``pad_px``): the labels
    of the lines, markers, texts, arrows and other legends under it."""
    from matplotlib.collections import LineCollection, PathCollection
    from matplotlib.legend import Legend
    from matplotlib.patches import FancyArrowPatch
    from matplotlib.text import Annotation

    x0, y0, x1, y1 = _extent(leg, renderer)
    box = (x0 - pad_px, y0 - pad_px, x1 + pad_px, y1 + pad_px)
    px = ax.figure.dpi / 72.0
    hits = []
    for line in ax.lines:
        if not line.get_visible():
            continue
        path = line.get_path()
        if line.get_drawstyle() not in (None, "default"):
            from matplotlib.cbook import STEP_LOOKUP_MAP

            xs, ys = STEP_LOOKUP_MAP[line.get_drawstyle()](*line.get_xydata().T)
            from matplotlib.path import Path

            path = Path(np.column_stack([xs, ys]))
        xy = line.get_transform().transform_path(path).vertices
        drawn = line.get_linestyle() not in ("None", "none", "", " ") and line.get_linewidth() > 0
        if drawn and _segments_meet_box(xy, box):
            hits.append(f"line {line.get_label()}")
        elif line.get_marker() not in (None, "None", "none", "", " ") and _points_in_box(
                xy, box, 0.5 * line.get_markersize() * px):
            hits.append(f"marker {line.get_label()}")
    for coll in ax.collections:
        if not coll.get_visible():
            continue
        if isinstance(coll, PathCollection):
            pts = coll.get_offset_transform().transform(coll.get_offsets())
            size = float(np.sqrt(np.max(coll.get_sizes()))) if len(coll.get_sizes()) else 6.0
            if _points_in_box(np.asarray(pts), box, 0.5 * size * px):
                hits.append("markers")
        elif isinstance(coll, LineCollection):
            for seg in coll.get_segments():
                if _segments_meet_box(coll.get_transform().transform(seg), box):
                    hits.append("lines")
                    break
    for t in ax.texts:
        if not t.get_visible():
            continue
        if t.get_text().strip() and _boxes_meet(box, _extent(t, renderer)):
            hits.append(f"text {t.get_text()}")
        if isinstance(t, Annotation) and t.arrow_patch is not None:
            if _boxes_meet(box, _extent(t.arrow_patch, renderer)):
                hits.append("arrow")
    for p in ax.patches:
        if isinstance(p, FancyArrowPatch) and p.get_visible() and _boxes_meet(box, _extent(p, renderer)):
            hits.append("arrow")
    for other in ax.artists + [c for c in ax.get_children() if isinstance(c, Legend)]:
        if other is not leg and isinstance(other, Legend) and other.get_visible():
            if _boxes_meet(box, _extent(other, renderer)):
                hits.append("legend")
    return hits


def _inside(ax, leg, renderer) -> bool:
    a = ax.get_window_extent(renderer)
    x0, y0, x1, y1 = _extent(leg, renderer)
    return a.x0 <= x0 + 0.5 and x1 <= a.x1 + 0.5 and a.y0 <= y0 + 0.5 and y1 <= a.y1 + 0.5


def _free(ax, leg, renderer) -> bool:
    px = ax.figure.dpi / 72.0
    return _inside(ax, leg, renderer) and not covered(ax, leg, renderer, PAD * px)


def _place_inside(ax, request, renderer) -> bool:
    """The legend at the first free place inside the axes, the one asked for first."""
    leg = ax.get_legend()
    if leg is not None and _free(ax, leg, renderer):
        return True
    for loc in (request["loc"],) + tuple(p for p in PLACES if p != request["loc"]):
        request["loc"] = loc
        leg = _remake(ax, request)
        if _free(ax, leg, renderer):
            return True
    return False


def _place_below(ax, request, renderer) -> None:
    """The legend under the axes' tick labels and axis label (a fixed distance in points
    below the axes, which a new layout does not change), centred, in as many columns as
    the axes' width holds."""
    from matplotlib.transforms import ScaledTranslation

    fig = ax.figure
    leg = ax.get_legend()
    extra = [a for a in ax.get_default_bbox_extra_artists() if a is not leg]
    tight = ax.get_tightbbox(renderer, bbox_extra_artists=extra)
    frame = ax.get_window_extent(renderer)
    drop = (max(frame.y0 - tight.y0, 0.0) * 72.0 / fig.dpi + BELOW_GAP) / 72.0     # inches
    where = ax.transAxes + ScaledTranslation(0.0, -drop, fig.dpi_scale_trans)
    n = len(request["handles"])
    request["loc"] = "upper center"
    for ncols in range(n, 0, -1):
        leg = _remake(ax, request, bbox_to_anchor=(0.5, 0.0), bbox_transform=where,
                      borderaxespad=0.0, ncols=ncols)
        if _extent(leg, renderer)[2] - _extent(leg, renderer)[0] <= frame.width:
            break
    request["below"] = True
    request["kwargs"].update(bbox_to_anchor=(0.5, 0.0), bbox_transform=where,
                             borderaxespad=0.0, ncols=ncols)


def settle(fig) -> bool:
    """Move every legend asked for with :func:`legend` off what its axes draw (see the
    module's text). Lays the figure out (tight_layout) as it is saved; returns whether it
    did (the layout then is the final one: nothing has moved since)."""
    axes = [ax for ax in fig.axes if getattr(ax, _KEY, None) is not None]
    if not axes:
        return False
    for _round in range(ROUNDS):
        fig.tight_layout()
        for ax in fig.axes:         # an equal-aspect axes takes its box when drawn
            ax.apply_aspect()
        renderer = _renderer(fig)
        moved = False
        for ax in axes:
            request = getattr(ax, _KEY)
            if request["below"]:
                continue
            if not _place_inside(ax, request, renderer):
                _place_below(ax, request, renderer)
                moved = True
        if not moved:
            return True
    fig.tight_layout()
    return True
