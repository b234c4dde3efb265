"""Placing the point and vector labels of a drawn figure so that they overlap neither each
other nor the lines they name (issue 19: labels F_R36/F_R43 printed over each other in the
force polygon, "D" and "B" lying on the links of the die-cutter's skeleton).

A label is anchored at a point (a joint, the middle of a vector) and offered positions at
growing distances along preferred directions — the normal of its vector or link first, on
either side, then the other directions round the point; it takes the first whose text box
(measured by matplotlib at the figure's final resolution, padded) meets no label placed
before it and no obstacle segment (links, vectors), inside the axes. Offsets are in points, so the text keeps
its distance from the anchor whatever the data scale. When no candidate is free, the one
with the least overlap is taken. The text is measured once, at its anchor (a candidate's
box is that box shifted by its offset), and a candidate is scored only against the segments
and labels that reach the region all candidates lie in; only the chosen place is drawn.

:func:`overlaps` is the measure the tests use: the pairs of overlapping label boxes and the
labels that cross an obstacle segment, after the figure's final layout.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

#: Distances from the anchor tried in turn [pt] and the padding round a text box [pt].
DISTANCES = (5.0, 8.0, 12.0, 17.0, 23.0, 30.0, 38.0, 48.0)
PAD = 1.5
#: Directions tried after the preferred ones: the eight compass directions.
COMPASS = tuple(np.exp(1j * np.pi * k / 4) for k in (0, 2, 4, 6, 1, 3, 5, 7))


@dataclass
class Label:
    """A text to place: its anchor (data coordinates, complex), the preferred directions
    (unit complex numbers in screen orientation: +x right, +y up) and matplotlib text
    keyword arguments. ``along``: further anchors the label may take instead (points along
    a long side of a force polygon), each at a cost of :data:`ALONG` pt per pt away from
    ``anchor``."""

    text: str
    anchor: complex
    directions: tuple = ()
    kwargs: dict = field(default_factory=dict)
    artist: object = None
    along: tuple = ()


def _renderer(fig):
    canvas = fig.canvas
    if not hasattr(canvas, "get_renderer"):
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        canvas = FigureCanvasAgg(fig)
    return canvas.get_renderer()


def _box(artist, renderer, pad_px: float):
    bb = artist.get_window_extent(renderer)
    return (bb.x0 - pad_px, bb.y0 - pad_px, bb.x1 + pad_px, bb.y1 + pad_px)


def _box_overlap(a, b) -> float:
    """Area of the intersection of two boxes (x0, y0, x1, y1)."""
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    return w * h if w > 0 and h > 0 else 0.0


def _segment_hits_box(p0, p1, box) -> bool:
    """Whether the segment p0–p1 (display coordinates) meets the box."""
    from .sheet import clip_segment

    return clip_segment(complex(*p0), complex(*p1), box) is not None


def _screen_segments(ax, segments) -> list:
    out = []
    for a, b in segments:
        (p, q) = ax.transData.transform([(a.real, a.imag), (b.real, b.imag)])
        out.append((tuple(p), tuple(q)))
    return out


def _head_segments(ax, heads, size_px: float) -> list:
    """The outline of each arrow head (tail, tip in data coordinates; a filled triangle of
    ``size_px``, matplotlib's "-|>" at that mutation scale: 0.4 long, 0.2 half-wide, here
    taken a little larger for the line width) as display segments."""
    out = []
    for a, b in heads:
        (p, q) = ax.transData.transform([(a.real, a.imag), (b.real, b.imag)])
        tip = complex(*q)
        d = tip - complex(*p)
        if abs(d) < 1e-9:
            continue
        u = d / abs(d)
        base = tip - 0.5 * size_px * u
        c1, c2 = base + 0.3 * size_px * 1j * u, base - 0.3 * size_px * 1j * u
        for z0, z1 in ((tip, c1), (c1, c2), (c2, tip)):
            out.append(((z0.real, z0.imag), (z1.real, z1.imag)))
    return out


#: What a line between a label and its anchor costs with ``sight`` (see :func:`place`), as
#: a distance from the anchor [pt].
SIGHT = 10.0
#: What moving a label's anchor along its side costs (see :class:`Label`), per pt moved [pt].
ALONG = 0.5

#: Times the axes' limits are widened when a label found no place inside them.
GROW_ROUNDS = 3
#: Extra margin [fraction of the limits' span] added when the limits are widened.
GROW_MARGIN = 0.04


#: The cost of a place nearer another label's point than the label's own: worse than a
#: place over the axes' edge (the limits then grow to take it in), better than one on a line
#: or another label.
AMBIGUOUS = 4e3


def place(ax, labels: list[Label], obstacles=(), fixed=(), heads=(), head_size=9.0,
          gap: float = 2 * PAD, sight: bool = False) -> list:
    """Draw ``labels`` in ``ax`` clear of each other and of the ``obstacles`` (segments as
    pairs of complex data points; a point is a segment of zero length), of the arrow
    ``heads`` (tail, tip pairs of complex data points; heads of ``head_size`` pt) and of the
    ``fixed`` text artists already drawn, each label at least ``gap`` pt from every other
    (the labels of a force polygon keep more than the default: issue 19, page review of
    session 43, press Fig. 9: labels two points apart read as one stack). With ``sight``, a
    place from which the line to the label's anchor crosses an obstacle segment is taken
    only when no free place is less than :data:`SIGHT` pt further off: the name of a side of
    a force polygon is not set beyond another side (where it reads as that side's). Call it after
    everything else is drawn and the axes limits are set; it lays the figure out
    (tight_layout) first so that the data-to-screen scale is the final one. Where a label
    could only be placed over the axes' edge (a long list of names of forces drawn as
    points at one vertex of a narrow force polygon, the die-cutter under its 1000 kN), the
    limits are widened to take it in and the labels placed again (at most
    :data:`GROW_ROUNDS` times). Returns the text artists."""
    artists = _place_once(ax, labels, obstacles, fixed, heads, head_size, gap, sight)
    fig = ax.figure
    for _ in range(GROW_ROUNDS):
        renderer = _renderer(fig)
        bb = ax.get_window_extent(renderer)
        px = fig.dpi / 72.0
        out = [b for b in (_box(t, renderer, PAD * px) for t in artists)
               if b[0] < bb.x0 or b[1] < bb.y0 or b[2] > bb.x1 or b[3] > bb.y1]
        if not out:
            break
        inv = ax.transData.inverted()
        corners = inv.transform([(b[0], b[1]) for b in out] + [(b[2], b[3]) for b in out])
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        mx, my = GROW_MARGIN * (x1 - x0), GROW_MARGIN * (y1 - y0)
        lo_x, hi_x = corners[:, 0].min(), corners[:, 0].max()
        lo_y, hi_y = corners[:, 1].min(), corners[:, 1].max()
        ax.set_xlim(min(x0, lo_x - mx) if lo_x < x0 else x0, max(x1, hi_x + mx) if hi_x > x1 else x1)
        ax.set_ylim(min(y0, lo_y - my) if lo_y < y0 else y0, max(y1, hi_y + my) if hi_y > y1 else y1)
        for t in artists:
            t.remove()
        artists = _place_once(ax, labels, obstacles, fixed, heads, head_size, gap, sight)
    return artists


def _place_once(ax, labels, obstacles, fixed, heads, head_size, gap=2 * PAD,
                sight=False) -> list:
    """One placing of ``labels`` at the axes' present limits (see :func:`place`)."""
    from matplotlib.transforms import offset_copy

    fig = ax.figure
    ax.autoscale_view()
    ax.apply_aspect()
    fig.tight_layout()
    ax.apply_aspect()
    renderer = _renderer(fig)
    px = fig.dpi / 72.0
    lines = _screen_segments(ax, obstacles)
    segments = lines + _head_segments(ax, heads, head_size * px)
    bb = ax.get_window_extent(renderer)
    frame = (bb.x0, bb.y0, bb.x1, bb.y1)
    placed: list = [_box(t, renderer, PAD * px) for t in fixed]
    artists = []
    # every label's point on the screen: a name set nearer another named point than its own
    # reads as that point's (review45, shaper Fig. 10: "n′_b" beside n′_4, 10.5 mm from p′,
    # and "n′_4, n′_s4" beside n′_b at 21 mm)
    points = [ax.transData.transform((lb.anchor.real, lb.anchor.imag)) for lb in labels]
    for lab in labels:
        kwargs = {"ha": "center", "va": "center", **lab.kwargs}
        # The text is measured once, at the anchor: an offset in points only translates
        # its box (by the offset × dpi/72 px), so each candidate is its box shifted.
        probe = ax.text(lab.anchor.real, lab.anchor.imag, lab.text,
                        transform=offset_copy(ax.transData, fig=fig, x=0.0, y=0.0,
                                              units="points"), **kwargs)
        x0, y0, x1, y1 = _box(probe, renderer, PAD * px)
        probe.remove()
        # only the segments and labels that reach the region every candidate lies in
        reach = max(DISTANCES) * px + 1.0
        region = (x0 - reach, y0 - reach, x1 + reach, y1 + reach)
        near = [(p, q) for p, q in segments if _segment_hits_box(p, q, region)]
        at = ax.transData.transform((lab.anchor.real, lab.anchor.imag))
        rivals = [q for q in points if math.hypot(q[0] - at[0], q[1] - at[1]) > 1.0]
        anchors = [(lab.anchor, 0.0, 0.0)]
        for z in lab.along:
            ex, ey = ax.transData.transform((z.real, z.imag)) - at
            anchors.append((z, ex, ey))
        if len(anchors) > 1:
            shift = max(abs(ex) + abs(ey) for _z, ex, ey in anchors)
            region = (region[0] - shift, region[1] - shift, region[2] + shift, region[3] + shift)
            near = [(p, q) for p, q in segments if _segment_hits_box(p, q, region)]
        seen = [(p, q) for p, q in lines if _segment_hits_box(p, q, region)] if sight else []
        # the placed labels' boxes (each padded by PAD) grown to keep ``gap`` between texts
        grow = max(gap - 2 * PAD, 0.0) * px
        others = [(b[0] - grow, b[1] - grow, b[2] + grow, b[3] + grow) for b in placed]
        others = [b for b in others if _box_overlap(b, region) > 0]
        best = None
        tried = [d / abs(d) for d in lab.directions if abs(d) > 0] + list(COMPASS)
        # scanned nearest first: each distance, each anchor, each direction
        scan = ((dist, a, d) for dist in DISTANCES for a in anchors for d in tried)
        for dist, (z, ex, ey), d in scan:
            dx, dy = dist * d.real, dist * d.imag
            box = (x0 + ex + dx * px, y0 + ey + dy * px, x1 + ex + dx * px, y1 + ey + dy * px)
            # a label over another is worst after one on a line, then one over the edge
            cost = sum(5e3 + a for a in (_box_overlap(box, other) for other in others) if a > 0)
            cost += sum(1e4 for p, q in near if _segment_hits_box(p, q, box))
            area = (box[2] - box[0]) * (box[3] - box[1])
            outside = area - _box_overlap(box, frame)
            cost += 2e3 + outside if outside > 1e-6 else 0.0     # over the axes' edge
            if rivals and len(anchors) == 1:
                cx, cy = (box[0] + box[2]) / 2, (box[1] + box[3]) / 2
                own = math.hypot(cx - at[0], cy - at[1])
                if min(math.hypot(cx - q[0], cy - q[1]) for q in rivals) < own:
                    cost += AMBIGUOUS                         # nearer another named point
            # among the places free of those: the nearest (in scanning order), or with
            # ``sight`` the nearest counting each line between it and its anchor as
            # SIGHT pt further
            soft = 0.0
            if sight:
                mid = ((box[0] + box[2]) / 2, (box[1] + box[3]) / 2)
                base = (at[0] + ex, at[1] + ey)
                soft = dist + SIGHT * sum(1 for p, q in seen if _crosses(base, mid, p, q))
            soft += ALONG * math.hypot(ex, ey) / px
            if best is None or (cost, soft) < best[0]:
                best = ((cost, soft), (dx, dy), box, z)
            if cost == 0 and not sight and len(anchors) == 1:
                break
        dx, dy = best[1]
        z = best[3]
        t = ax.text(z.real, z.imag, lab.text,
                    transform=offset_copy(ax.transData, fig=fig, x=dx, y=dy, units="points"),
                    **kwargs)
        placed.append(best[2])
        lab.artist = t
        artists.append(t)
    return artists


def _crosses(a, b, p, q) -> bool:
    """Whether the segments a–b and p–q (display coordinates) cross properly: each one's
    ends strictly on either side of the other's line (touching and collinear ones do not)."""
    def side(o, u, v):
        return (u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0])

    d1, d2 = side(p, q, a), side(p, q, b)
    d3, d4 = side(a, b, p), side(a, b, q)
    return d1 * d2 < 0 and d3 * d4 < 0


def overlaps(ax, artists, obstacles=()) -> list[str]:
    """What a reader would see as clashes, measured after the figure's final layout: pairs
    of label texts whose boxes overlap, and labels whose box an obstacle segment crosses."""
    fig = ax.figure
    fig.tight_layout()          # as the figure is saved (render/figures.save_png)
    ax.apply_aspect()
    renderer = _renderer(fig)
    boxes = [(a.get_text(), _box(a, renderer, 0.0)) for a in artists]
    out = []
    for i, (ta, ba) in enumerate(boxes):
        for tb, bb in boxes[i + 1:]:
            if _box_overlap(ba, bb) > 0:
                out.append(f"{ta} over {tb}")
    for p, q in _screen_segments(ax, obstacles):
        for t, b in boxes:
            if _segment_hits_box(p, q, b):
                out.append(f"{t} on a line")
    return out
