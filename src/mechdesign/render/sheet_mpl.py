"""Draw a :class:`~.sheet.Sheet` with matplotlib: vector PDF at true paper size and a
PNG preview. Lines of one layer and width go into one LineCollection (fast for the
thousands of segments of an A1 sheet); circles and arcs stay true arcs in the PDF."""
from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from .fonts import configure_matplotlib
from .sheet import LAYERS, Arc, Circle, Dimension, Fill, Line, Polyline, Sheet, Text, format_number

PT_PER_MM = 72.0 / 25.4
# Dash patterns in paper mm (GB/T 17450: long dash 15–20, gap 3, dot ≤ 0.5).
_DASHES = {"CENTER": (12.0, 2.0, 1.0, 2.0), "DASHED": (4.0, 1.5)}
_ALIGN_V = {"bottom": "baseline", "middle": "center", "top": "top"}


def _style(layer: str, weight: float | None):
    lay = LAYERS[layer]
    w = lay.weight if weight is None else weight
    dashes = _DASHES.get(lay.linetype)
    ls = "solid" if dashes is None else (0, tuple(d * PT_PER_MM for d in dashes))
    return w * PT_PER_MM, ls, lay.rgb


def dimension_geometry(d: Dimension):
    """Extension lines, dimension line with arrows and the text placement (paper mm)."""
    u = d.p1 - d.p0
    length = abs(u)
    u = u / length if length else 1.0
    n = 1j * u
    text = d.text or format_number(d.measurement, 5)
    lines = []
    arrows = []
    if d.kind == "aligned":
        a, b = d.p0 + n * d.offset, d.p1 + n * d.offset
        ext = np.sign(d.offset) * 1.5 if d.offset else 0
        lines += [(d.p0 + n * np.sign(d.offset) * 1.0, a + n * ext),
                  (d.p1 + n * np.sign(d.offset) * 1.0, b + n * ext), (a, b)]
        arrows += [(b, a), (a, b)]
        pos, ang = (a + b) / 2 + n * 1.0, np.angle(u)
    else:  # radius/diameter: p0 = centre side, p1 = on the circle
        prefix = "R" if d.kind == "radius" else "Φ"
        text = d.text or prefix + format_number(d.measurement, 5)
        lines.append((d.p0, d.p1))
        arrows.append((d.p1, d.p0))            # (tip, tail): the arrow touches the circle
        if d.kind == "diameter":
            arrows.append((d.p0, d.p1))
        pos, ang = (d.p0 + d.p1) / 2 + n * 1.0, np.angle(u)
    if np.cos(ang) < -1e-9:          # keep text readable (not upside down)
        ang += np.pi
        pos = pos - 2 * n * 1.0
    return lines, arrows, text, pos, ang


def _arrow_head(tip, tail, size=2.5):
    u = tip - tail
    u = u / abs(u) if abs(u) else 1.0
    base = tip - size * u
    w = 0.3 * size
    return [tip, base + 1j * u * w, base - 1j * u * w]


def _draw(sheet: Sheet):
    configure_matplotlib()
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection, PolyCollection
    from matplotlib.patches import Arc as MArc, Circle as MCircle

    w_in, h_in = sheet.width / 25.4, sheet.height / 25.4
    fig = plt.figure(figsize=(w_in, h_in))
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, sheet.width)
    ax.set_ylim(0, sheet.height)
    ax.set_aspect("equal")
    ax.axis("off")
    segments: dict = {}
    fills: dict = {}

    def seg(layer, weight, pts):
        segments.setdefault((layer, weight), []).append(np.column_stack([np.real(pts), np.imag(pts)]))

    for e in sheet.entities:
        if isinstance(e, Line):
            seg(e.layer, e.weight, [e.p0, e.p1])
        elif isinstance(e, Polyline):
            pts = list(e.points) + ([e.points[0]] if e.closed else [])
            seg(e.layer, e.weight, pts)
        elif isinstance(e, (Circle, Arc)):
            lw, ls, color = _style(e.layer, e.weight)
            if isinstance(e, Circle):
                patch = MCircle((e.center.real, e.center.imag), e.radius, fill=False)
            else:
                patch = MArc((e.center.real, e.center.imag), 2 * e.radius, 2 * e.radius,
                             theta1=np.degrees(e.start), theta2=np.degrees(e.end))
            patch.set(lw=lw, ls=ls, edgecolor=color, capstyle="round")
            # add_artist, not add_patch: the limits are the paper's, and add_patch would
            # measure every arc's Bézier extents to update them (most of the drawing time)
            ax.add_artist(patch)
        elif isinstance(e, Fill):
            fills.setdefault(e.layer, []).append(np.column_stack([np.real(e.points),
                                                                  np.imag(e.points)]))
        elif isinstance(e, Text):
            _text(ax, e.position, e.text, e.height, e.layer, e.halign, e.valign, e.angle)
        elif isinstance(e, Dimension):
            lines, arrows, text, pos, ang = dimension_geometry(e)
            for a, b in lines:
                seg(e.layer, None, [a, b])
            for tip, tail in arrows:
                fills.setdefault(e.layer, []).append(
                    np.column_stack([np.real(_arrow_head(tip, tail)), np.imag(_arrow_head(tip, tail))]))
            _text(ax, pos, text, e.height, e.layer, "center", "bottom", ang)
    for (layer, weight), segs in segments.items():
        lw, ls, color = _style(layer, weight)
        ax.add_collection(LineCollection(segs, linewidths=lw, linestyles=ls, colors=[color],
                                         capstyle="round", joinstyle="round"))
    for layer, polys in fills.items():
        ax.add_collection(PolyCollection(polys, facecolors=[LAYERS[layer].rgb], edgecolors="none"))
    return fig


def _text(ax, pos, text, height, layer, halign, valign, angle):
    # Sheet texts are printed as written (the title block holds the brief's title and
    # names): no mathtext, so a "$" is a dollar sign.
    ax.text(pos.real, pos.imag, text, fontsize=height * PT_PER_MM, color=LAYERS[layer].rgb,
            ha=halign, va=_ALIGN_V[valign], rotation=np.degrees(angle), rotation_mode="anchor",
            parse_math=False)


def write_sheet(sheet: Sheet, pdf: Path | None = None, png: Path | None = None,
                png_width_px: int = 2400) -> None:
    """Write the sheet as a vector PDF at true size and/or a PNG preview.

    The sheet is drawn once, as the PDF; the preview is that PDF rasterised by typst
    (:func:`.pdf.rasterize_pdf`), so the two cannot differ. Without ``pdf`` the PDF is a
    temporary file beside the PNG. In a report rendered with background saves the
    writing happens in a helper process (:mod:`.parallel`)."""
    import matplotlib.pyplot as plt

    from .parallel import save

    if pdf is None and png is None:
        return
    fig = _draw(sheet)
    target = Path(pdf) if pdf is not None else Path(png).with_name(f".{Path(png).stem}.sheet.pdf")

    def write():
        try:
            _atomic(fig, target, format="pdf", metadata={"CreationDate": _creation_date(sheet)})
            if png is not None:
                from .pdf import rasterize_pdf

                rasterize_pdf(target, Path(png), ppi=png_width_px / (sheet.width / 25.4))
        finally:
            if pdf is None:
                target.unlink(missing_ok=True)

    try:
        save(write, target.name if png is None else Path(png).name, uses_typst=png is not None)
    finally:
        plt.close(fig)


def _creation_date(sheet: Sheet):
    """The PDF's creation date: the title block's date (or SOURCE_DATE_EPOCH, or a fixed
    date; see :func:`.pdf.source_timestamp`), never the clock, so a brief gives the same bytes."""
    import datetime as dt

    from .pdf import source_timestamp

    date = sheet.info.date if sheet.info is not None else None
    return dt.datetime.fromtimestamp(source_timestamp(date), tz=dt.timezone.utc)


def _atomic(fig, path: Path, **kw) -> None:
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        fig.savefig(tmp, facecolor="white", **kw)
        os.replace(tmp, path)
    finally:
        tmp.unlink(missing_ok=True)
