"""Draw a :class:`~.sheet.Sheet` with typst: vector PDF at true paper size and a PNG
preview, both from one typst document compiled in-process.

Each primitive becomes an absolutely placed typst element on a page of the sheet's size
(paper mm, y measured downwards from the top edge): lines and polylines of one layer and
width one ``curve`` each, circles true circles, arcs cubic Bézier curves (at most 90° a
piece, radial error < 3e-4 of the radius), texts placed at their anchor with the sheet's
alignment and rotated about it. Line widths, GB line types (dash patterns in paper mm)
and colours come from the layers (:data:`.sheet.LAYERS`), as in the DXF back end
(:mod:`.sheet_dxf`). Text is the CJK sans serif (:mod:`.fonts`), printed as written.

Typst lays out the 700 texts of an A1 sheet in tens of milliseconds, which is why the
sheets are drawn by it rather than by matplotlib.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from .fonts import cjk_families
from .sheet import (LAYERS, Arc, Circle, Dimension, Fill, Line, Polyline, Sheet, Text,
                    dimension_geometry,
                    split_subscripts)

# Dash patterns in paper mm (GB/T 17450: long dash 15–20, gap 3, dot ≤ 0.5); as the
# DXF line types CENTER and DASHED.
_DASHES = {"CENTER": (12.0, 2.0, 1.0, 2.0), "DASHED": (4.0, 1.5)}
# the anchor's place in the text's box: share of the width from the left, of the
# height (ascender to baseline) from the top
_HALIGN = {"left": 0, "center": 0.5, "right": 1}
_VALIGN = {"bottom": 1, "middle": 0.5, "top": 0}


def arrow_head(tip, tail, size=2.5):
    """The filled triangle of a dimension arrow touching ``tip`` (paper mm)."""
    u = tip - tail
    u = u / abs(u) if abs(u) else 1.0
    base = tip - size * u
    w = 0.3 * size
    return [tip, base + 1j * u * w, base - 1j * u * w]


def typst_string(text: str) -> str:
    """A typst string literal holding ``text`` exactly (user text: names, titles)."""
    out = []
    for ch in text:
        if ch in '\\"':
            out.append("\\" + ch)
        elif ord(ch) < 0x20 or ch in "\u2028\u2029\x7f":
            out.append(f"\\u{{{ord(ch):x}}}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


# the slant of italic letters [°] (the DXF obliques them as much: sheet_dxf.mtext)
ITALIC_SLANT = 15


def typst_body(text: str) -> str:
    """The typst expression of a sheet text: a string literal, or with subscripts (see
    :func:`.sheet.sub`) the strings joined with ``sub(...)`` (drawn smaller and lowered,
    not with the font's subscript glyphs, which the CJK font lacks)."""
    runs = split_subscripts(text)
    if not any(is_sub for _, is_sub in runs):
        return typst_string(text)
    def run(t: str, kind) -> str:
        if kind == "sup":
            return f"super(typographic: false, {typst_string(t)})"
        if kind == "it":       # slanted: the CJK sans has no italic
            return f"box(skew(ax: -{ITALIC_SLANT}deg, reflow: false, {typst_string(t)}))"
        if kind:
            return f"sub(typographic: false, {typst_string(t)})"
        return typst_string(t)

    return "(" + " + ".join(run(t, kind) for t, kind in runs) + ")"


def _num(x: float) -> str:
    return f"{x:.4f}".rstrip("0").rstrip(".") if math.isfinite(x) else "0"


class _Writer:
    def __init__(self, sheet: Sheet):
        self.h = sheet.height
        self.lines: list[str] = []

    def pt(self, z: complex) -> str:
        return f"({_num(z.real)}mm, {_num(self.h - z.imag)}mm)"

    def stroke(self, layer: str, weight: float | None) -> str:
        lay = LAYERS[layer]
        w = lay.weight if weight is None else weight
        r, g, b = (round(255 * c) for c in lay.rgb)
        dashes = _DASHES.get(lay.linetype)
        dash = "" if dashes is None else \
            ", dash: (" + ", ".join(f"{_num(d)}mm" for d in dashes) + ",)"
        return (f'(paint: rgb({r}, {g}, {b}), thickness: {_num(w)}mm, cap: "round", '
                f'join: "round"{dash})')

    def curve(self, parts: list[str], stroke: str = "none", fill: str = "none") -> None:
        self.lines.append(f"#place(curve(stroke: {stroke}, fill: {fill}, {', '.join(parts)}))")

    def polyline(self, points, stroke: str, closed: bool = False) -> None:
        pts = [complex(p) for p in points]
        parts = [f"curve.move({self.pt(pts[0])})"] + [f"curve.line({self.pt(p)})" for p in pts[1:]]
        if closed:
            parts.append("curve.close()")
        self.curve(parts, stroke)

    def arc(self, c: complex, r: float, start: float, end: float, stroke: str) -> None:
        span = (end - start) % (2 * math.pi) or 2 * math.pi
        n = max(1, math.ceil(span / (math.pi / 2) - 1e-9))
        step = span / n
        k = 4.0 / 3.0 * math.tan(step / 4.0) * r
        a = start
        p = c + r * complex(math.cos(a), math.sin(a))
        parts = [f"curve.move({self.pt(p)})"]
        for _ in range(n):
            b = a + step
            q = c + r * complex(math.cos(b), math.sin(b))
            c1 = p + k * complex(-math.sin(a), math.cos(a))
            c2 = q - k * complex(-math.sin(b), math.cos(b))
            parts.append(f"curve.cubic({self.pt(c1)}, {self.pt(c2)}, {self.pt(q)})")
            a, p = b, q
        self.curve(parts, stroke)

    def circle(self, c: complex, r: float, stroke: str) -> None:
        self.lines.append(f"#place(dx: {_num(c.real - r)}mm, dy: {_num(self.h - c.imag - r)}mm, "
                          f"circle(radius: {_num(r)}mm, stroke: {stroke}))")

    def fill(self, points, layer: str) -> None:
        r, g, b = (round(255 * c) for c in LAYERS[layer].rgb)
        pts = [complex(p) for p in points]
        parts = [f"curve.move({self.pt(pts[0])})"] + [f"curve.line({self.pt(p)})" for p in pts[1:]]
        self.curve(parts + ["curve.close()"], "none", f"rgb({r}, {g}, {b})")

    def text(self, pos: complex, text: str, height: float, layer: str, halign: str,
             valign: str, angle: float) -> None:
        r, g, b = (round(255 * c) for c in LAYERS[layer].rgb)
        self.lines.append(
            f"#T({_num(pos.real)}mm, {_num(self.h - pos.imag)}mm, {_HALIGN[halign]}, "
            f"{_VALIGN[valign]}, {_num(-math.degrees(angle))}deg, {_num(height)}mm, "
            f"rgb({r}, {g}, {b}), {typst_body(text)})")


def sheet_source(sheet: Sheet) -> str:
    """The typst document that draws ``sheet`` on one page of its paper size."""
    w = _Writer(sheet)
    families = cjk_families()
    head = [
        f"#set page(width: {_num(sheet.width)}mm, height: {_num(sheet.height)}mm, margin: 0pt, "
        "fill: white)",
        f'#set text(font: ({typst_string(families["sans"])}, {typst_string(families["serif"])}), '
        'top-edge: "ascender", bottom-edge: "baseline", hyphenate: false)',
        "#set par(justify: false)",
        # the CJK sans's middle dot is full-width ("N • m"): the serif's is narrow
        f'#show "·": set text(font: {typst_string(families["serif"])})',
        # a text anchored at (x, y): its box shifted by its own size so that the anchor
        # falls where the alignment says, then turned about the anchor (clockwise angles)
        "#let T(x, y, ha, va, ang, size, col, body) = place(dx: x, dy: y, rotate(ang, "
        "origin: top + left, reflow: false, context { let t = text(size: size, fill: col, body); "
        "let m = measure(t); place(dx: -ha * m.width, dy: -va * m.height, t) }))",
    ]
    info = sheet.info
    if info is not None:
        # the PDF's metadata, as the report's: the drawing's name, the student, the project
        meta = [f"title: {typst_string(info.drawing)}"]
        if info.student:
            meta.append(f"author: {typst_string(info.student)}")
        if info.project:
            meta.append(f"description: {typst_string(info.project)}")
        head.insert(0, f"#set document({', '.join(meta)})")
    segments: dict = {}
    for e in sheet.entities:
        if isinstance(e, Line):
            segments.setdefault((e.layer, e.weight), []).append(("line", (e.p0, e.p1), False))
        elif isinstance(e, Polyline):
            segments.setdefault((e.layer, e.weight), []).append(("line", e.points, e.closed))
        elif isinstance(e, Circle):
            w.circle(complex(e.center), e.radius, w.stroke(e.layer, e.weight))
        elif isinstance(e, Arc):
            w.arc(complex(e.center), e.radius, e.start, e.end, w.stroke(e.layer, e.weight))
        elif isinstance(e, Fill):
            w.fill(e.points, e.layer)
        elif isinstance(e, Text):
            w.text(complex(e.position), e.text, e.height, e.layer, e.halign, e.valign, e.angle)
        elif isinstance(e, Dimension):
            lines, arrows, text, pos, ang = dimension_geometry(e)
            for a, b in lines:
                segments.setdefault((e.layer, None), []).append(("line", (a, b), False))
            for tip, tail in arrows:
                w.fill(arrow_head(tip, tail), e.layer)
            w.text(complex(pos), text, e.height, e.layer, "center", "bottom", ang)
    body = w.lines
    w.lines = []
    for (layer, weight), items in segments.items():
        stroke = w.stroke(layer, weight)
        for _, pts, closed in items:
            w.polyline(pts, stroke, closed)
    # lines first (as matplotlib's collections were drawn under the texts), then the rest
    return "\n".join(head + w.lines + body) + "\n"


def write_sheet(sheet: Sheet, pdf: Path | None = None, png: Path | None = None,
                png_width_px: int = 2400) -> None:
    """Write the sheet as a vector PDF at true size and/or a PNG preview ``png_width_px``
    wide, both from the same typst document, here and now (see :func:`write_sheets`)."""
    write_sheets([(sheet, pdf, png, png_width_px)])


def write_sheets(jobs) -> None:
    """Write several sheets: ``jobs`` of (sheet, pdf path or None, png path or None, PNG
    width [px]), compiled by typst in this process one after the other (its fonts are
    loaded once). :func:`.sheets.make_sheets` runs this in a helper process of its own
    when the report is rendered with background saves."""
    import typst

    from .parallel import note_typst_used
    from ..fileio import write_bytes
    from .pdf import PdfRenderError, _typst_message, cached_compile, source_timestamp, typst_fonts

    note_typst_used()
    fonts = typst_fonts()          # the shipped fonts only, found once
    for sheet, pdf, png, width in jobs:
        if pdf is None and png is None:
            continue
        source = sheet_source(sheet).encode("utf-8")
        date = sheet.info.date if sheet.info is not None else None
        try:
            if pdf is not None:
                write_bytes(Path(pdf), cached_compile(
                    source, font_paths=fonts, timestamp=source_timestamp(date)))
            if png is not None:
                image = cached_compile(source, font_paths=fonts, format="png",
                                       ppi=width / (sheet.width / 25.4))
                write_bytes(Path(png), image if isinstance(image, bytes) else image[0])
        except typst.TypstError as exc:
            raise PdfRenderError(f"typst failed to draw the sheet "
                                 f"{Path(pdf or png).name}:\n{_typst_message(exc)}") from exc

