"""Drawing sheets (图纸): primitives in paper millimetres, drawn by two back ends.

A :class:`Sheet` is a list of primitives (lines, polylines, circles, arcs, texts, filled
polygons, dimensions) on named layers, in paper millimetres with the origin at the
sheet's lower-left corner. :mod:`.sheet_typst` draws it with typst (vector PDF and a
PNG preview) and :mod:`.sheet_dxf` with ezdxf (DXF for AutoCAD/CAXA), so both files
show the same drawing. Points are complex numbers (x + iy), as in the core.

A :class:`View` maps model coordinates (e.g. the mechanism in mm at a length scale, or
a velocity polygon in m/s at μv) onto the sheet. Sheet sizes, borders, line widths and
text heights follow GB/T 14689, 17450 and 14691 (A1 841 × 594, binding margin 25 mm,
thick lines 0.7 mm, thin 0.25 mm, text heights 2.5/3.5/5/7/10 mm).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable

import numpy as np

from ..i18n import N_, tr
from .fmt import GROUP, exact, minus
from .labels import LabelTable, pgettext, translated


@dataclass(frozen=True)
class Layer:
    name: str
    line: object           # the line type's Chinese name, from the catalogue (pgettext)
    use: str               # what the layer holds (English)
    weight: float          # line width [mm]
    linetype: str          # CONTINUOUS, CENTER or DASHED
    color: int             # AutoCAD colour index (7 = black/white)
    rgb: tuple             # colour in the PDF

    @property
    def description(self) -> str:
        """Shown in the CAD layer manager: the line type in Chinese and the use in English,
        whatever the report language (e.g. "粗实线 outlines (links, profiles)")."""
        return f"{translated(self.line, tr('zh'))} {self.use}"


LAYERS = {layer.name: layer for layer in (
    Layer("OUTLINE", pgettext("DXF layer", "thick solid line"), "outlines (links, profiles)",
          0.7, "CONTINUOUS", 7, (0, 0, 0)),
    Layer("CONSTRUCTION", pgettext("DXF layer", "thin solid line"),
          "construction and thin lines", 0.25, "CONTINUOUS", 8, (0.35, 0.35, 0.35)),
    Layer("CENTER", pgettext("DXF layer", "thin chain line"), "centre lines, pitch circles, guides",
          0.25, "CENTER", 1, (0.55, 0.1, 0.1)),
    Layer("HIDDEN", pgettext("DXF layer", "thin dashed line"), "other positions, hidden lines",
          0.25, "DASHED", 8, (0.4, 0.4, 0.4)),
    Layer("DIMENSIONS", pgettext("DXF layer", "dimensions"), "dimensions", 0.25, "CONTINUOUS",
          3, (0, 0.35, 0)),
    Layer("TEXT", pgettext("DXF layer", "text"), "text and labels", 0.25, "CONTINUOUS", 7,
          (0, 0, 0)),
    Layer("VECTORS", pgettext("DXF layer", "vectors"),
          "velocity, acceleration and force polygons", 0.5, "CONTINUOUS", 5, (0, 0.2, 0.65)),
    Layer("CURVES", pgettext("DXF layer", "curves"), "motion, torque and energy curves", 0.5,
          "CONTINUOUS", 4, (0, 0.3, 0.6)),
    Layer("FRAME", pgettext("DXF layer", "frame and title block"), "frame and title block",
          0.7, "CONTINUOUS", 7, (0, 0, 0)),
)}

SIZES = {"A0": (1189.0, 841.0), "A1": (841.0, 594.0), "A2": (594.0, 420.0),
         "A3": (420.0, 297.0), "A4": (297.0, 210.0)}
# GB/T 14689 margins with a binding edge: a = 25 mm left, c on the other sides.
MARGIN_C = {"A0": 10.0, "A1": 10.0, "A2": 10.0, "A3": 5.0, "A4": 5.0}
MARGIN_A = 25.0
THIN = 0.25
# Chord error allowed when a polyline is thinned to what paper shows [mm]: a tenth of the
# thin line width and below one dot of a 1200 dpi printer (0.021 mm).
CHORD_TOLERANCE = 0.02
TEXT_HEIGHTS = (2.5, 3.5, 5.0, 7.0, 10.0)
# digits are grouped (render/fmt.py's rule: 12 738 N) with a no-break space on the sheets:
# their font (Noto Sans SC, in the PDF and named by the DXF) has no narrow no-break space
NBSP = "\u00a0"


# -- primitives (paper mm, complex points) ------------------------------------------------

@dataclass(frozen=True)
class Line:
    p0: complex
    p1: complex
    layer: str
    weight: float | None = None      # overrides the layer's line width [mm]


@dataclass(frozen=True)
class Polyline:
    points: tuple                    # complex points
    layer: str
    closed: bool = False
    weight: float | None = None


@dataclass(frozen=True)
class Circle:
    center: complex
    radius: float
    layer: str
    weight: float | None = None


@dataclass(frozen=True)
class Arc:
    center: complex
    radius: float
    start: float                     # [rad], counter-clockwise to ``end``
    end: float
    layer: str
    weight: float | None = None


@dataclass(frozen=True)
class Text:
    position: complex
    text: str
    height: float                    # character height [mm]
    layer: str = "TEXT"
    halign: str = "left"             # left | center | right
    valign: str = "bottom"           # bottom | middle | top
    angle: float = 0.0               # [rad]


@dataclass(frozen=True)
class Fill:
    """A solid filled polygon (arrow heads, section marks)."""

    points: tuple
    layer: str


@dataclass(frozen=True)
class Dimension:
    """An aligned dimension between ``p0`` and ``p1`` (paper mm), its line ``offset`` mm
    to the left of p0→p1; ``measurement`` is the true value written (model units)."""

    p0: complex
    p1: complex
    offset: float
    measurement: float
    text: str = ""                   # "" → the measurement, formatted
    kind: str = "aligned"            # aligned; radius (p0 centre, p1 on the circle);
    #                                  diameter (p0, p1 the ends of the diameter)
    layer: str = "DIMENSIONS"
    height: float = 3.5
    outside: int = -1                # an aligned text too long for its line: beyond p0 (−1) or
    #                                  p1 (+1); a radius' text: outside the circle (≠ 0) or on
    #                                  the line inside it (0)
    along: float = 0.5               # where the text's middle stands on the line, a fraction of
    #                                  it from p0: an aligned text between the arrows (kept
    #                                  clear of them), a radius' text inside (outside=0)
    text_at: complex | None = None   # an aligned dimension's text on a leader instead: the
    #                                  shoulder's start, the leader drawn to it from the middle
    #                                  of the dimension line, the text level on the shoulder
    #                                  (GB/T 4458.4: no room for it along the line)


#: A dimension text's gap above its dimension line and from an extension line [mm]
#: (GB/T 4458.4: the text above the line, not crossed by it).
DIM_GAP = 1.0
# a point label keeps this fraction of the (smaller) text height from every other text: the
# word space of ISO 3098-1 / GB/T 14691 lettering (type B: 0.6 h, 1.5 mm at the labels'
# 2.5 mm). Two labels closer than the space between the words of one text read as one
# ("n4s4′ / n4′ / n4b′" stacked 0.6 mm apart read as a three-line note).
LABEL_CLEAR = 0.6
#: The dimension arrows' length on the sheets [mm].
DIM_ARROW = 2.5


def dimension_text(d: Dimension) -> str:
    from . import fmt

    if d.text:
        return d.text
    prefix = {"radius": "R", "diameter": "Φ"}.get(d.kind, "")
    return prefix + fmt.length(d.measurement)


def dimension_geometry(d: Dimension):
    """Extension lines, dimension line(s), arrows (tip, tail) and the text's baseline
    centre and angle of a dimension [paper mm], as a draughtsman sets them (GB/T 4458.4):
    the text above its dimension line, read from below or from the right, never crossed by
    a line. An aligned text that does not fit between the arrows goes beyond the extension
    line (``d.outside``: before p0 or after p1) on the dimension line drawn on under it;
    a radius' or diameter's text outside the circle, on the line from the centre drawn on
    past the arrow (the lines inside the circle — crank positions — stay clear of it), or on
    the line inside with ``outside=0`` (a gear's concentric circles, a cam's rollers outside).
    With ``d.text_at`` an aligned dimension's text is level, on a shoulder from that point
    away from the dimension line, joined to the line's middle by a leader (a short swing
    among a chart's grid lines, where a text along the line would be crossed by them)."""
    u = d.p1 - d.p0
    length = abs(u)
    u = u / length if length else 1.0
    n = 1j * u
    text = dimension_text(d)
    w = text_width(text, d.height)
    lines, arrows = [], []
    if d.kind == "aligned":
        a, b = d.p0 + n * d.offset, d.p1 + n * d.offset
        ext = np.sign(d.offset) * 1.5 if d.offset else 0
        lines += [(d.p0 + n * np.sign(d.offset) * 1.0, a + n * ext),
                  (d.p1 + n * np.sign(d.offset) * 1.0, b + n * ext), (a, b)]
        arrows += [(b, a), (a, b)]
        if d.text_at is not None:
            elbow = complex(d.text_at)
            mid = (a + b) / 2
            end = elbow + (1 if elbow.real >= mid.real else -1) * (w + 1.0)
            lines += [(mid, elbow), (elbow, end)]
            return lines, arrows, text, (elbow + end) / 2 + 1j * DIM_GAP, 0.0
        if w + 2 * DIM_ARROW + 2 * DIM_GAP <= length:
            edge = (0.5 * w + DIM_ARROW + DIM_GAP) / length
            centre = a + (b - a) * float(np.clip(d.along, edge, 1.0 - edge))
        elif d.outside >= 0:
            centre = b + u * (DIM_GAP + 0.5 + w / 2)
            lines.append((b, b + u * (2 * DIM_GAP + 0.5 + w)))
        else:
            centre = a - u * (DIM_GAP + 0.5 + w / 2)
            lines.append((a, a - u * (2 * DIM_GAP + 0.5 + w)))
    else:  # radius/diameter: p0 = centre side, p1 = on the circle
        lines.append((d.p0, d.p1))
        arrows.append((d.p1, d.p0))            # (tip, tail): the arrow touches the circle
        if d.kind == "diameter":
            arrows.append((d.p0, d.p1))
        if d.outside == 0:             # asked for on the line (concentric circles outside)
            centre = d.p0 + d.along * (d.p1 - d.p0) if d.kind == "radius" else (d.p0 + d.p1) / 2
        else:
            centre = d.p1 + u * (DIM_GAP + 0.5 + w / 2)
            lines.append((d.p1, d.p1 + u * (2 * DIM_GAP + 0.5 + w)))
    ang = float(np.angle(u))
    up = n
    if np.cos(ang) < -1e-9:          # keep text readable (not upside down)
        ang += np.pi
        up = -n
    # the text above the line: its baseline DIM_GAP over it on the reader's upper side
    return lines, arrows, text, centre + up * DIM_GAP, ang


def dimension_text_hits(d: Dimension, pts: np.ndarray, margin: float = 0.3) -> int:
    """How many of ``pts`` (drawn line points, :meth:`LabelPlacer._drawn_points`) lie on the
    text of dimension ``d`` as :func:`dimension_geometry` sets it, turned with it: on its
    glyphs' body (from 0.1 to 0.65 of its height above the baseline, its estimated width,
    ``margin`` mm round), where a line is read passing through the text (GB/T 4458.4; the
    core tests/sheet_overlaps.py measures)."""
    _lines, _arrows, text, pos, ang = dimension_geometry(d)
    if not len(pts):
        return 0
    q = (pts - pos) * np.exp(-1j * ang)
    w, h = text_width(text, d.height), d.height
    return int(np.count_nonzero((np.abs(q.real) < w / 2 + margin)
                                & (q.imag > 0.1 * h - margin) & (q.imag < 0.65 * h + margin)))


# -- the sheet ----------------------------------------------------------------------------

@dataclass
class Sheet:
    size: str = "A1"
    entities: list = field(default_factory=list)
    info: "TitleInfo | None" = None        # set by :func:`frame`
    # the point labels of ``entities`` (the Text objects a :class:`LabelPlacer` put beside
    # their points), which keep :data:`LABEL_CLEAR` from every other text
    labels: list = field(default_factory=list)

    @property
    def width(self) -> float:
        return SIZES[self.size][0]

    @property
    def height(self) -> float:
        return SIZES[self.size][1]

    @property
    def inner(self) -> tuple[float, float, float, float]:
        """The drawing area inside the border: (x0, y0, x1, y1) [mm]."""
        c = MARGIN_C[self.size]
        return MARGIN_A, c, self.width - c, self.height - c

    def add(self, entity) -> None:
        self.entities.append(entity)

    def line(self, p0, p1, layer="OUTLINE", weight=None):
        self.add(Line(complex(p0), complex(p1), layer, weight))

    def polyline(self, points, layer="OUTLINE", closed=False, weight=None,
                 tolerance: float | None = CHORD_TOLERANCE):
        """A polyline through ``points``, thinned to ``tolerance`` [paper mm] (:func:`thin`);
        ``tolerance=None`` keeps every point (a cam profile, which a CAM program reads)."""
        pts = np.asarray(points, dtype=complex).ravel()
        if tolerance is not None:
            pts = thin(pts, tolerance)
        pts = tuple(complex(p) for p in pts)
        if len(pts) >= 2:
            self.add(Polyline(pts, layer, closed, weight))

    def circle(self, center, radius, layer="OUTLINE", weight=None):
        self.add(Circle(complex(center), float(radius), layer, weight))

    def arc(self, center, radius, start, end, layer="OUTLINE", weight=None):
        self.add(Arc(complex(center), float(radius), float(start), float(end), layer, weight))

    def text(self, position, text, height=3.5, layer="TEXT", halign="left", valign="bottom",
             angle=0.0):
        self.add(Text(complex(position), str(text).replace(GROUP, NBSP), float(height), layer,
                      halign, valign, float(angle)))

    def fill(self, points, layer="OUTLINE"):
        self.add(Fill(tuple(complex(p) for p in points), layer))

    def arrow(self, p0, p1, layer="VECTORS", head=3.5, weight=None):
        """A vector p0 → p1 with a filled head at p1 (no head when shorter than it)."""
        p0, p1 = complex(p0), complex(p1)
        self.line(p0, p1, layer, weight)
        length = abs(p1 - p0)
        if length > 1e-9:
            u = (p1 - p0) / length
            h = min(head, 0.45 * length)
            base = p1 - h * u
            w = 0.3 * h
            self.fill([p1, base + 1j * u * w, base - 1j * u * w], layer)

    def dimension(self, p0, p1, offset, measurement, text="", kind="aligned", height=3.5,
                  outside=-1, text_at=None, along=0.5):
        self.add(Dimension(complex(p0), complex(p1), float(offset), float(measurement),
                           str(text).replace(GROUP, NBSP), kind, "DIMENSIONS", height,
                           int(outside), float(along), None if text_at is None else complex(text_at)))

    def view(self, origin, scale: float, flip_x: bool = False) -> "View":
        """Model coordinates → sheet: ``origin + scale * z`` (scale = paper mm per unit)."""
        return View(self, complex(origin), float(scale), flip_x)


@dataclass
class View:
    """Draws on a sheet in model units: paper point = origin + scale · z."""

    sheet: Sheet
    origin: complex
    scale: float
    flip_x: bool = False

    def p(self, z):
        z = np.asarray(z, dtype=complex)
        if self.flip_x:
            z = -z.conj()
        out = self.origin + self.scale * z
        return complex(out) if out.ndim == 0 else out

    def line(self, z0, z1, layer="OUTLINE", weight=None):
        self.sheet.line(self.p(z0), self.p(z1), layer, weight)

    def polyline(self, zs, layer="OUTLINE", closed=False, weight=None,
                 tolerance: float | None = CHORD_TOLERANCE):
        self.sheet.polyline(self.p(zs), layer, closed, weight, tolerance)

    def circle(self, z, r, layer="OUTLINE", weight=None):
        self.sheet.circle(self.p(z), r * self.scale, layer, weight)

    def arc(self, z, r, start, end, layer="OUTLINE", weight=None):
        if self.flip_x:
            start, end = np.pi - end, np.pi - start
        self.sheet.arc(self.p(z), r * self.scale, start, end, layer, weight)

    def text(self, z, text, height=3.5, **kw):
        self.sheet.text(self.p(z), text, height, **kw)

    def arrow(self, z0, z1, layer="VECTORS", head=3.5, weight=None):
        self.sheet.arrow(self.p(z0), self.p(z1), layer, head, weight)

    def fill(self, zs, layer="OUTLINE"):
        self.sheet.fill(self.p(np.asarray(zs)), layer)

    def dimension(self, z0, z1, offset, text="", kind="aligned", height=3.5, measurement=None,
                  outside=-1, along=0.5):
        """Aligned dimension in model units; ``offset`` in paper mm; writes the true length."""
        m = abs(complex(z1) - complex(z0)) if measurement is None else measurement
        self.sheet.dimension(self.p(z0), self.p(z1), offset, m, text, kind, height, outside,
                             along=along)


def thin(points, tolerance: float = CHORD_TOLERANCE) -> np.ndarray:
    """The points of a polyline that a sheet needs: a subset whose polyline stays within
    ``tolerance`` (paper mm) of every given point (Ramer–Douglas–Peucker on each stretch
    between the kept extremes), keeping both ends and the points of least and greatest x
    and y exactly, so a curve's peaks are drawn where they are. Distances are to the
    kept *segment* (not its line), so the error bound holds for every point of the
    original polyline (the distance to a segment is convex along a straight piece)."""
    z = np.asarray(points, dtype=complex).ravel()
    n = len(z)
    if n <= 2 or not np.all(np.isfinite(z)):       # (a gap or an undefined point: as given)
        return z
    x, y = z.real, z.imag
    fixed = sorted({0, n - 1, int(np.argmin(x)), int(np.argmax(x)), int(np.argmin(y)),
                    int(np.argmax(y))})
    keep = np.zeros(n, dtype=bool)
    keep[fixed] = True
    stack = list(zip(fixed[:-1], fixed[1:]))
    while stack:
        i, j = stack.pop()
        if j - i < 2:
            continue
        a, b = z[i], z[j]
        inner = z[i + 1:j]
        ab = b - a
        len2 = ab.real * ab.real + ab.imag * ab.imag
        if len2 > 0.0:
            d = inner - a
            t = np.clip((d.real * ab.real + d.imag * ab.imag) / len2, 0.0, 1.0)
            dist = np.abs(d - t * ab)
        else:
            dist = np.abs(inner - a)
        k = int(np.argmax(dist))
        if dist[k] > tolerance:
            m = i + 1 + k
            keep[m] = True
            stack.append((i, m))
            stack.append((m, j))
    return z[keep]


# -- helpers shared by every sheet --------------------------------------------------------

# -- subscripts in sheet texts ------------------------------------------------------------
# A sheet text marks a subscript with two private-use characters (never in user text):
# "μ" + SUB_ON + "v" + SUB_OFF is μ with the subscript v. The typst back end draws it with
# ``sub``, the DXF back end as an MTEXT with a stacked subscript (``\\S^ v;``); the DXF
# text font, Noto Sans SC, has none of the Unicode subscript characters (ₘᵢₙ, ₐ, ₁ …).
# The markers and ``sub`` live in render/labels.py (which names points for every medium:
# a sheet's point names need them, and labels may not import this module); re-exported here.
from .labels import (IT_OFF, IT_ON, MARKERS, SUB_OFF, SUB_ON, SUP_OFF, SUP_ON,  # noqa: E402,F401
                     italic, sub, sup)


def with_subscripts(text: str, *symbols: str) -> str:
    """``text`` with each of ``symbols`` (written "base_index", e.g. "μ_v", "ΔW_max") marked as
    a subscript where it stands as a word ("μv" in "μv = 0.01", not in "μvx")."""
    import re

    for symbol in symbols:
        base, index = symbol.split("_", 1)
        text = re.sub(rf"(?<![A-Za-z0-9]){re.escape(base + index)}(?![A-Za-z0-9])",
                      lambda _m: sub(base, index), text)
    return text


_KINDS = {SUB_ON: (SUB_OFF, True), SUP_ON: (SUP_OFF, "sup"), IT_ON: (IT_OFF, "it")}


def split_subscripts(text: str) -> list[tuple[str, object]]:
    """The runs of ``text``: (characters, kind): True for a subscript, "sup" for a
    superscript (:func:`sup`), "it" for italic letters (:func:`italic`), False for the
    rest; empty runs left out."""
    out = []
    rest = text
    while True:
        at = [(rest.find(on), on) for on in _KINDS if on in rest]
        if not at:
            break
        i, on = min(at)
        off, kind = _KINDS[on]
        head, tail = rest[:i], rest[i + 1:]
        index, _, rest = tail.partition(off)
        out += [(head, False), (index, kind)]
    out.append((rest, False))
    return [(t, s) for t, s in out if t]


def scripted(text: str) -> bool:
    """Whether ``text`` has a subscript, a superscript or italic letters."""
    return SUB_ON in text or SUP_ON in text or IT_ON in text


def plain(text: str) -> str:
    """``text`` with its subscripts written as plain letters ("μv", as the sheets used to)."""
    for m in MARKERS:
        text = text.replace(m, "")
    return text


def text_width(text: str, height: float) -> float:
    """Estimated width of ``text`` [mm]: CJK characters are square, Latin ~0.6 h; a
    subscript or superscript ~0.7 of that (typst draws it at 0.6 em)."""
    if scripted(text):
        return sum((0.7 if is_sub in (True, "sup") else 1.0) * text_width(t, height)
                   for t, is_sub in split_subscripts(text))
    wide = sum(1 for ch in text if ord(ch) > 0x2E80)
    return height * (wide + 0.62 * (len(text) - wide))


def fit_height(text: str, max_width: float, height: float, smallest: float = 2.5) -> float:
    """The largest text height ≤ ``height`` for which ``text`` fits ``max_width``."""
    w = text_width(text, height)
    return height if w <= max_width else max(smallest, height * max_width / w)


def nice_step(span: float, count: int = 5) -> float:
    """A 1-2-2.5-5 × 10ⁿ step giving about ``count`` intervals over ``span``."""
    if not span > 0:
        return 1.0
    raw = span / count
    mag = 10.0 ** np.floor(np.log10(raw))
    for m in (1.0, 2.0, 2.5, 5.0, 10.0):
        if raw <= m * mag * (1 + 1e-9):
            return m * mag
    return 10.0 * mag


def nice_scale(value: float, available: float) -> float:
    """Smallest 1-2-2.5-5 × 10ⁿ units-per-mm scale that draws ``value`` within ``available`` mm.

    Used for μv [(m/s)/mm], μa [(m/s²)/mm] and μF [N/mm]."""
    if not value > 0:
        return 1.0
    raw = value / available
    mag = 10.0 ** np.floor(np.log10(raw))
    for m in (1.0, 2.0, 2.5, 5.0, 10.0):
        if m * mag >= raw * (1 - 1e-12):
            return m * mag
    return 10.0 * mag


# The steps of a polygon's scale μ on a sheet within each decade (1, 1.5, 2, 2.5, 3, 4, 5,
# 6, 8 × 10ⁿ: GB/T 14690's reductions and 8): two neighbours differ by at most 1.5×, so
# the smallest step that fits draws the polygon over at least 2/3 of its limiting side.
POLYGON_STEPS = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)


def fill_scale(value: float, available: float) -> float:
    """The smallest :data:`POLYGON_STEPS` × 10ⁿ units-per-mm scale that draws ``value``
    within ``available`` mm: the polygon then spans at least 2/3 of ``available``."""
    if not value > 0 or not available > 0:
        return 1.0
    raw = value / available
    mag = 10.0 ** np.floor(np.log10(raw))
    for m in POLYGON_STEPS + (10.0,):
        if m * mag >= raw * (1 - 1e-12):
            return m * mag
    return 10.0 * mag


# GB/T 14690 reduction scales 1:n, preferred first within each decade.
_REDUCTIONS = (1, 1.5, 2, 2.5, 3, 4, 5, 6)
# GB/T 14690 enlargement scales m:1 within each decade, largest first: 5:1 and 2:1 preferred,
# 4:1 and 2.5:1 allowed, then 10:1 (and ×10ⁿ: 50:1, 40:1, 25:1, 20:1, 100:1 …).
_ENLARGEMENTS = (5, 4, 2.5, 2)


def length_scale(extent_mm: complex, box_mm: complex, enlarge: bool = False) -> float:
    """The GB/T 14690 length scale that fits a model of size ``extent_mm`` (width +
    i·height) into ``box_mm``, as n model mm per paper mm: the largest reduction 1:n
    (n ≥ 1) when the model is larger than the box; with ``enlarge``, a model that fits
    the box at 1:1 with room to spare is drawn at the largest enlargement m:1 that still
    fits (returned as n = 1/m < 1), so that a small mechanism fills its view."""
    ratio = max(extent_mm.real / box_mm.real, extent_mm.imag / box_mm.imag)
    if enlarge and 0 < ratio <= 0.5 * (1 + 1e-12):
        best = 1.0
        decade = 1.0
        while ratio * 10.0 * decade <= 1 + 1e-12:
            decade *= 10.0                      # 10:1, 100:1 … fit
        for m in _ENLARGEMENTS:
            if ratio * m * decade <= 1 + 1e-12:
                best = m * decade
                break
        else:
            best = decade
        return 1.0 / best
    need = max(ratio, 1.0)
    decade = 1.0
    while True:
        for m in _REDUCTIONS:
            if m * decade >= need * (1 - 1e-12):
                return m * decade
        decade *= 10.0


# GB/T 14690 preferred scales within each decade: 1:1, 1:2, 1:2.5, 1:4, 1:5 (then 1:10 …)
# and the enlargements 2:1, 2.5:1, 4:1, 5:1 (then 10:1 …).
PREFERRED = (1.0, 2.0, 2.5, 4.0, 5.0)


# as n model mm per paper mm, smallest (largest drawing) first: 1/(m·10ᵏ) the enlargements,
# m·10ᵏ the reductions
_PREFERRED_N = sorted({m * 10.0 ** k for m in PREFERRED for k in range(9)}
                      | {1.0 / (m * 10.0 ** k) for m in PREFERRED for k in range(5)})


def preferred_scale(limit: float) -> float:
    """The largest GB/T 14690 preferred scale that draws at most ``limit`` paper mm per
    model mm, as n model mm per paper mm (n < 1: the enlargement 1/n:1)."""
    if not limit > 0:
        return _PREFERRED_N[-1]
    need = 1.0 / limit
    return next((n for n in _PREFERRED_N if n >= need * (1 - 1e-12)), _PREFERRED_N[-1])


def scale_text(n: float) -> str:
    """'1:5', '1:2.5', '1:1'; an enlargement (n < 1, see :func:`length_scale`) '2:1', '2.5:1'."""
    if n < 1 - 1e-9:
        return f"{exact(1.0 / n, group=False)}:1"
    return f"1:{exact(n, group=False)}"


def ground(sheet_or_view, z, size=6.0, angle=-np.pi / 2):
    """A frame pivot: a small circle on a triangle with a hatched ground line below.

    ``size`` in paper mm; ``angle`` is the direction from the pivot to the ground."""
    s = sheet_or_view.sheet if isinstance(sheet_or_view, View) else sheet_or_view
    p = sheet_or_view.p(z) if isinstance(sheet_or_view, View) else complex(z)
    u = np.exp(1j * angle)
    n = 1j * u
    r = 0.22 * size
    s.circle(p, r, "OUTLINE", THIN * 2)
    a = p + u * r
    left, right = p + u * size - n * 0.55 * size, p + u * size + n * 0.55 * size
    s.line(a, left, "OUTLINE", 0.35)
    s.line(a, right, "OUTLINE", 0.35)
    g0, g1 = left - n * 0.35 * size, right + n * 0.35 * size
    s.line(g0, g1, "OUTLINE", 0.35)
    for t in np.linspace(0, 1, 6):
        q = g0 + (g1 - g0) * t
        s.line(q, q + 0.35 * size * (u - n * 0.6), "CONSTRUCTION")


def slider_block(sheet_or_view, z, angle, length=9.0, width=5.0, layer="OUTLINE"):
    """A slider block (rectangle) centred on ``z`` along ``angle`` [rad], size in paper mm."""
    s = sheet_or_view.sheet if isinstance(sheet_or_view, View) else sheet_or_view
    p = sheet_or_view.p(z) if isinstance(sheet_or_view, View) else complex(z)
    if isinstance(sheet_or_view, View) and sheet_or_view.flip_x:
        angle = np.pi - angle
    u = np.exp(1j * angle)
    n = 1j * u
    corners = [p + 0.5 * (sx * length * u + sy * width * n)
               for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    s.polyline(corners, layer, closed=True, weight=0.5)


def pin(sheet_or_view, z, radius=1.2):
    """A revolute joint: a small open circle."""
    s = sheet_or_view.sheet if isinstance(sheet_or_view, View) else sheet_or_view
    p = sheet_or_view.p(z) if isinstance(sheet_or_view, View) else complex(z)
    s.circle(p, radius, "OUTLINE", 0.35)


# -- frame and title block ----------------------------------------------------------------

@dataclass(frozen=True)
class TitleInfo:
    """What the title block (标题栏) shows; strings as printed."""

    drawing: str                 # 图名, e.g. 牛头刨床导杆机构运动分析图
    project: str                 # the brief's title (设计题目)
    student: str = ""
    student_id: str = ""
    class_name: str = ""
    teacher: str = ""
    date: str = ""
    scale: str = ""
    number: str = ""             # 图号
    sheet_no: int = 1
    sheets: int = 1
    lang: str = "zh"
    # the course the title block names: "theory" (机械原理课程设计) or "design" (机械设计课程设计:
    # a drive alone, designs/furnace_drive.yaml, whose cover says 机械设计; page review 41)
    course: str = "theory"


TITLE_LABELS = LabelTable({
    "drawn": N_("Drawn"),
    "id": N_("Student No."),
    "class": N_("Class"),
    "date": N_("Date"),
    "checked": N_("Checked"),
    "teacher": N_("Supervisor"),
    "grade": N_("Grade"),
    "scale": N_("Scale"),
    "size": N_("Size"),
    "number": N_("Drg. No."),
    "sheet": N_("Sheet {i} of {n}"),
    "course": N_("Theory of Machines: course design"),
    "course_design": N_("Machine Design: course design"),
})

TITLE_BLOCK_SIZE = (180.0, 40.0)


def frame(sheet: Sheet, info: TitleInfo) -> tuple[float, float, float, float]:
    """Draw the trimmed edge, the border and the title block; return the area inside the
    border (x0, y0, x1, y1). Callers keep clear of :func:`title_block_box`."""
    sheet.info = info
    w, h = sheet.width, sheet.height
    sheet.polyline([0, w, w + 1j * h, 1j * h], "FRAME", closed=True, weight=THIN)
    x0, y0, x1, y1 = sheet.inner
    sheet.polyline([x0 + 1j * y0, x1 + 1j * y0, x1 + 1j * y1, x0 + 1j * y1], "FRAME",
                   closed=True)
    _title_block(sheet, info)
    return sheet.inner


def title_block_box(sheet: Sheet) -> tuple[float, float, float, float]:
    """(x0, y0, x1, y1) of the title block in the lower-right corner."""
    _, y0, x1, _ = sheet.inner
    bw, bh = TITLE_BLOCK_SIZE
    return x1 - bw, y0, x1, y0 + bh


def _title_block(sheet: Sheet, info: TitleInfo) -> None:
    lab = TITLE_LABELS[info.lang]
    bx0, by0, bx1, by1 = title_block_box(sheet)
    row = 8.0
    sheet.polyline([bx0 + 1j * by0, bx1 + 1j * by0, bx1 + 1j * by1, bx0 + 1j * by1], "FRAME",
                   closed=True)
    mid = bx0 + 90.0
    sheet.line(mid + 1j * by0, mid + 1j * by1, "FRAME")
    for k in range(1, 5):                                    # left half: 5 rows
        y = by0 + k * row
        sheet.line(bx0 + 1j * y, mid + 1j * y, "FRAME", THIN)
    for x in (15.0, 45.0, 60.0):
        sheet.line(bx0 + x + 1j * (by0 + row), bx0 + x + 1j * by1, "FRAME", THIN)
    for y in (by0 + row, by0 + 2 * row):                     # right half: 2 rows + title
        sheet.line(mid + 1j * y, bx1 + 1j * y, "FRAME", THIN)
    for x in (15.0, 45.0):
        sheet.line(mid + x + 1j * by0, mid + x + 1j * (by0 + 2 * row), "FRAME", THIN)
    sheet.line(mid + 60.0 + 1j * (by0 + row), mid + 60.0 + 1j * (by0 + 2 * row), "FRAME", THIN)

    def cell(x, y, wdt, text, height=3.5):
        if text:
            hh = fit_height(text, wdt - 2.0, height)
            sheet.text(x + wdt / 2 + 1j * (y + row / 2), text, hh, "TEXT", "center", "middle")

    rows = [(lab["drawn"], info.student, lab["date"], info.date),
            (lab["id"], info.student_id, lab["class"], info.class_name),
            (lab["checked"], "", lab["date"], ""),
            (lab["teacher"], info.teacher, lab["grade"], "")]
    for k, (a, b, c, d) in enumerate(rows):
        y = by1 - (k + 1) * row
        cell(bx0, y, 15, a, 2.5)
        cell(bx0 + 15, y, 30, b)
        cell(bx0 + 45, y, 15, c, 2.5)
        cell(bx0 + 60, y, 30, d)
    cell(bx0, by0, 90, lab["course_design" if info.course == "design" else "course"], 3.5)
    cell(mid, by0 + row, 15, lab["scale"], 2.5)
    cell(mid + 15, by0 + row, 30, info.scale)
    cell(mid + 45, by0 + row, 15, lab["size"], 2.5)
    cell(mid + 60, by0 + row, 30, sheet.size)
    cell(mid, by0, 15, lab["number"], 2.5)
    cell(mid + 15, by0, 30, info.number)
    cell(mid + 45, by0, 45, lab["sheet"].format(i=info.sheet_no, n=info.sheets), 2.5)
    top = by0 + 2 * row
    hd = fit_height(info.drawing, 80.0, 7.0)
    sheet.text(mid + 45 + 1j * (top + 15.0), info.drawing, hd, "TEXT", "center", "middle")
    hp = fit_height(info.project, 86.0, 3.5)
    sheet.text(mid + 45 + 1j * (top + 5.0), info.project, hp, "TEXT", "center", "middle")


def heading(sheet: Sheet, position, text: str, height: float = 5.0):
    """A panel title, centred at ``position`` (paper mm)."""
    sheet.text(position, text, height, "TEXT", "center", "bottom")


# -- tables (lines and text, GB style) ---------------------------------------------------

def table(sheet: Sheet, x: float, ytop: float, widths, rows, head=None, aligns=None,
          row_h: float = 6.5, *, title: str | None = None, title_height: float = 5.0,
          height: float = 3.5, head_height: float | None = None, margin: float = 1.5,
          outer: float | None = 0.5, rule: float = 0.35, inner: float = THIN) -> float:
    """A drawn table with its top-left corner at (``x``, ``ytop``); return its bottom y.

    ``widths`` are the column widths [mm]; ``rows`` lists of cells (``""`` leaves a cell
    empty, ``None`` merges it into the cell on its left). An optional ``title`` row spans
    the whole width and an optional ``head`` row follows it; both are centred and closed
    by a ``rule``-weight line. The outer border has weight ``outer`` (None: the FRAME
    layer's), inner lines ``inner``. Text is fitted into its cell less ``margin`` on either
    side, with ``height`` (``head_height`` in the header) as the largest height;
    ``aligns`` gives each column's alignment (default centred)."""
    widths = [float(w) for w in widths]
    xs = x + np.concatenate([[0.0], np.cumsum(widths)])
    x1 = float(xs[-1])
    body = [list(r) for r in rows]
    lines = ([[title] + [None] * (len(widths) - 1)] if title is not None else []) \
        + ([list(head)] if head is not None else []) + body
    n_top = (title is not None) + (head is not None)       # rows closed by a rule
    ybot = ytop - len(lines) * row_h
    sheet.polyline([complex(x, ybot), complex(x1, ybot), complex(x1, ytop), complex(x, ytop)],
                   "FRAME", closed=True, weight=outer)
    for i in range(1, len(lines)):
        y = ytop - i * row_h
        sheet.line(complex(x, y), complex(x1, y), "FRAME", rule if i <= n_top else inner)
    # vertical lines, one per run of rows in which the boundary is not merged away
    for j in range(1, len(widths)):
        start = None
        for i, row in enumerate(lines + [[None] * len(widths)]):
            cut = i < len(lines) and j < len(row) and row[j] is not None
            if cut and start is None:
                start = i
            elif not cut and start is not None:
                sheet.line(complex(xs[j], ytop - start * row_h), complex(xs[j], ytop - i * row_h),
                           "FRAME", inner)
                start = None
    aligns = aligns or ["center"] * len(widths)
    for i, row in enumerate(lines):
        yc = ytop - (i + 0.5) * row_h
        top = i < n_top
        hh = title_height if (title is not None and i == 0) else (
            (head_height or height) if top else height)
        for j, cell in enumerate(row):
            if cell is None or cell == "":
                continue
            k = j + 1
            while k < len(row) and row[k] is None:
                k += 1
            text = str(cell)
            al = "center" if top else aligns[j]
            h = fit_height(text, xs[k] - xs[j] - 2 * margin, hh)
            px = {"left": xs[j] + margin, "center": (xs[j] + xs[k]) / 2, "right": xs[k] - margin}[al]
            sheet.text(complex(px, yc), text, h, "TEXT", al, "middle")
    return ybot


def fit_widths(widths, total: float) -> list[float]:
    """``widths`` scaled to add up to ``total``."""
    s = float(sum(widths))
    return [w * total / s for w in widths]


# -- charts (curves against an abscissa, drawn with primitives) --------------------------

@dataclass(frozen=True)
class Series:
    y: np.ndarray
    label: str = ""
    layer: str = "CURVES"
    weight: float | None = None


#: A chart's grid lines' width [mm] (thin: a text among them breaks them, :func:`break_lines`).
GRID_WEIGHT = 0.13


def break_lines(sheet: Sheet, box: Box, lines) -> None:
    """Break each of ``lines`` (Line entities of ``sheet``) where it crosses ``box``: the
    parts outside it stay (GB/T 4458.4: a line that would pass through a dimension's text
    is broken there)."""
    lines = {id(g) for g in lines}
    out = []
    for g in sheet.entities:
        cut = clip_segment(g.p0, g.p1, box) if id(g) in lines else None
        if cut is None:
            out.append(g)
            continue
        t0, t1 = cut
        d = g.p1 - g.p0
        for a, b in ((0.0, t0), (t1, 1.0)):
            if (b - a) * abs(d) > 1e-6:
                out.append(Line(g.p0 + a * d, g.p0 + b * d, g.layer, g.weight))
    sheet.entities[:] = out


def chart(sheet: Sheet, box: tuple[float, float, float, float], x: np.ndarray,
          series: Iterable[Series], *, xlabel: str, ylabel: str, title: str = "",
          xticks: Iterable[float] | None = None, shade: Iterable[tuple[float, float]] = (),
          marks: Iterable[tuple[float, float, str]] = (), hlines: Iterable[tuple[float, str]] = (),
          ylim: tuple[float, float] | None = None) -> "ChartMap":
    """A framed chart in ``box`` = (x0, y0, x1, y1) paper mm with a grid, tick labels and
    axis labels; returns the data → paper map (separate x and y scales)."""
    series = list(series)
    x = np.asarray(x, dtype=float)
    x0, y0, x1, y1 = box
    xs = np.asarray(list(xticks) if xticks is not None else [], dtype=float)
    xlo, xhi = (float(xs[0]), float(xs[-1])) if len(xs) else (float(x.min()), float(x.max()))
    if ylim is None:
        lo = min(float(np.min(s.y)) for s in series)
        hi = max(float(np.max(s.y)) for s in series)
        lo, hi = min(lo, 0.0), max(hi, 0.0)
        step = nice_step(hi - lo, 5)
        lo, hi = np.floor(lo / step - 1e-9) * step, np.ceil(hi / step + 1e-9) * step
        if hi - lo < 1e-12:
            lo, hi, step = -1.0, 1.0, 1.0
    else:
        lo, hi = ylim
        step = nice_step(hi - lo, 5)
    sx = (x1 - x0) / (xhi - xlo)
    sy = (y1 - y0) / (hi - lo)
    m = ChartMap(x0, y0, xlo, lo, sx, sy)
    for a, b in shade:                       # working stroke etc.: hatched band borders
        for v in (a, b):
            if xlo <= v <= xhi:
                sheet.line(m.p(v, lo), m.p(v, hi), "HIDDEN")
    for v in np.arange(lo, hi + step / 2, step):
        y = m.p(xlo, v).imag
        sheet.line(x0 + 1j * y, x1 + 1j * y, "CONSTRUCTION", GRID_WEIGHT)
        sheet.text(x0 - 1.5 + 1j * y, minus(exact(v)), 2.5, "TEXT", "right", "middle")
    for v in xs:
        xp = m.p(v, lo).real
        sheet.line(xp + 1j * y0, xp + 1j * y1, "CONSTRUCTION", GRID_WEIGHT)
        sheet.text(xp + 1j * (y0 - 2.0), minus(exact(v)), 2.5, "TEXT", "center", "top")
    sheet.polyline([x0 + 1j * y0, x1 + 1j * y0, x1 + 1j * y1, x0 + 1j * y1], "CONSTRUCTION",
                   closed=True, weight=0.35)
    if lo < 0 < hi:
        sheet.line(m.p(xlo, 0), m.p(xhi, 0), "CONSTRUCTION", 0.35)
    # a labelled horizontal line is named in a legend above the frame's right end (a sample
    # of its dashes, then the text): written on the line inside the frame it was crossed by
    # the curve and the grid's verticals (22 mm apart on an A1 chart, the text 45 mm long)
    right = x1
    for value, label in hlines:
        sheet.line(m.p(xlo, value), m.p(xhi, value), "HIDDEN")
        if label:
            y = y1 + 1.5
            sheet.text(right + 1j * y, label, 2.5, "TEXT", "right", "bottom")
            left = right - text_width(label, 2.5) - 1.5
            sheet.line(complex(left - 8.0, y + 1.25), complex(left, y + 1.25), "HIDDEN")
            right = left - 12.0
    for s in series:
        sheet.polyline(m.p(x, np.asarray(s.y, dtype=float)), s.layer, weight=s.weight)
    marks = list(marks)
    for xv, yv, _label in marks:
        sheet.circle(m.p(xv, yv), 0.8, "CURVES", 0.25)
    # the marks' numbers beside them, clear of the curves, the grid and each other
    placer = LabelPlacer(sheet, area=(x0, y0, x1, y1))
    for xv, yv, _label in marks:
        placer.block(m.p(xv, yv), 0.9)
    for xv, yv, label in marks:
        if label:
            placer.place(m.p(xv, yv), label, 2.5, prefer=1 + 1j, gap=0.8)
    sheet.text((x0 + x1) / 2 + 1j * (y0 - 6.5), xlabel, 3.5, "TEXT", "center", "top")
    sheet.text(x0 - 11.0 + 1j * (y0 + y1) / 2, ylabel, 3.5, "TEXT", "center", "bottom",
               np.pi / 2)
    if title:
        heading(sheet, (x0 + x1) / 2 + 1j * (y1 + 2.0), title, 5.0)
    return m


@dataclass(frozen=True)
class ChartMap:
    """Data (x, y) → paper point of a chart."""

    x0: float
    y0: float
    xlo: float
    ylo: float
    sx: float
    sy: float

    def p(self, x, y):
        out = (self.x0 + (np.asarray(x, dtype=float) - self.xlo) * self.sx
               + 1j * (self.y0 + (np.asarray(y, dtype=float) - self.ylo) * self.sy))
        return complex(out) if np.ndim(out) == 0 else out


Box = tuple[float, float, float, float]          # (x0, y0, x1, y1) in paper mm


def text_box(p: complex, text: str, h: float, halign: str = "left", valign: str = "bottom") -> Box:
    """(x0, y0, x1, y1) of an unrotated text [paper mm]."""
    w = text_width(text, h)
    x0 = {"left": p.real, "center": p.real - w / 2, "right": p.real - w}[halign]
    y0 = {"bottom": p.imag, "middle": p.imag - h / 2, "top": p.imag - h}[valign]
    return x0, y0, x0 + w, y0 + h


def boxes_overlap(a: Box, b: Box, pad: float = 0.0) -> bool:
    return not (a[2] + pad <= b[0] or b[2] + pad <= a[0] or a[3] + pad <= b[1] or b[3] + pad <= a[1])


def segment_hits_box(p0: complex, p1: complex, box: Box, pad: float = 0.5) -> bool:
    """Whether ``p0``→``p1`` (sampled) comes within ``pad`` of ``box``."""
    t = np.linspace(0.0, 1.0, 60)
    z = p0 + (p1 - p0) * t
    return bool(np.any((z.real > box[0] - pad) & (z.real < box[2] + pad)
                       & (z.imag > box[1] - pad) & (z.imag < box[3] + pad)))


def clip_segment(a: complex, b: complex, box: Box):
    """Liang–Barsky: the parameter interval (t0, t1) of a→b inside ``box``, or None."""
    d = b - a
    t0, t1 = 0.0, 1.0
    for p, q in ((-d.real, a.real - box[0]), (d.real, box[2] - a.real),
                 (-d.imag, a.imag - box[1]), (d.imag, box[3] - a.imag)):
        if abs(p) < 1e-15:
            if q < 0:
                return None
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
    return (t0, t1) if t1 - t0 > 1e-12 else None


def sample_polyline(points, step: float) -> np.ndarray:
    """Points along a polyline at most ``step`` apart."""
    pts = np.asarray(points, dtype=complex)
    out = [pts[:1]]
    for a, b in zip(pts[:-1], pts[1:]):
        n = max(int(abs(b - a) / step), 1)
        out.append(a + (b - a) * np.arange(1, n + 1) / n)
    return np.concatenate(out)


# a circled label (:meth:`LabelPlacer.place_breaking` with a ``balloon``) whose centre is
# farther than this from its point is joined to it by a leader [mm]
BALLOON_AT = 9.0


class LabelPlacer:
    """Places labels so that they do not overlap each other or marked obstacles.

    Obstacles are boxes (texts, blocked points), segments (lines that texts must not
    cover) and sampled points of the linework (:meth:`absorb`). :meth:`place` puts a point
    label at the first free spot among eight directions around its anchor (starting with
    the preferred one) at one to three offsets; :meth:`place_best` and :meth:`leader` take
    the cheapest of many candidates instead, where a candidate costs the number of line
    samples it covers, a large amount for each box or segment it hits and a little for
    leaving the preferred direction or distance. With an ``area`` no candidate outside it
    is taken by those two. ``pad`` is the clearance kept by :meth:`free`."""

    def __init__(self, sheet: Sheet, area: Box | None = None, pad: float = 0.0):
        self.sheet, self.area, self.pad = sheet, area, pad
        self.boxes: list[Box] = []
        # the texts among the boxes, with their heights (:meth:`crowding`)
        self.texts: list[tuple[Box, float]] = []
        self.segments: list[tuple[complex, complex]] = []
        self.points = np.zeros(0, dtype=complex)
        # the sheet's lines drawn so far, sampled (see :meth:`_drawn_points`)
        self._drawn = np.zeros(0, dtype=complex)
        self._seen = 0
        # indices into the sheet's entities of the thin lines a label may break
        # (:meth:`place_breaking`: the links of the other positions on the A1 skeleton)
        self.breakable: set[int] = set()

    # -- obstacles
    def block(self, z: complex, radius: float = 1.0) -> None:
        """Mark a point (e.g. a polygon vertex) that labels must keep clear of."""
        self.boxes.append((z.real - radius, z.imag - radius, z.real + radius, z.imag + radius))

    def block_segment(self, a: complex, b: complex, step: float = 2.0) -> None:
        count = max(2, int(abs(b - a) / step) + 1)
        for t in np.linspace(0.0, 1.0, count):
            self.block(a + (b - a) * t, 0.4)

    def block_box(self, b: Box) -> None:
        self.boxes.append(b)

    def absorb(self, entities, step: float = 0.8) -> None:
        """Sample the lines, arcs and dimension lines of ``entities`` as obstacles."""
        out = [self.points]
        for e in entities:
            if isinstance(e, Line):
                out.append(sample_polyline([e.p0, e.p1], step))
            elif isinstance(e, Polyline):
                out.append(sample_polyline(list(e.points) + ([e.points[0]] if e.closed else []), step))
            elif isinstance(e, (Circle, Arc)):
                a0, a1 = (0.0, 2 * np.pi) if isinstance(e, Circle) else (e.start, e.end)
                n = max(int(e.radius * abs(a1 - a0) / step), 2)
                out.append(e.center + e.radius * np.exp(1j * np.linspace(a0, a1, n)))
            elif isinstance(e, Dimension) and abs(e.p1 - e.p0) > 1e-9:
                lines, _arrows, text, pos, ang = dimension_geometry(e)
                for a, b in lines:
                    out.append(sample_polyline([a, b], step))
                u = np.exp(1j * ang)
                mid = pos + 1j * u * e.height / 2
                w = text_width(text, e.height)
                out.append(np.repeat(sample_polyline([mid - u * w / 2, mid + u * w / 2], 0.4), 6))
        self.points = np.concatenate(out)

    # -- tests
    def _drawn_points(self) -> np.ndarray:
        """Points along every line, arc and dimension the sheet holds so far (0.5 mm apart),
        sampled once each: a point label may not be crossed by any of them (GB/T 4458.4)."""
        new = [e for e in self.sheet.entities[self._seen:] if not isinstance(e, (Text, Fill))]
        self._seen = len(self.sheet.entities)
        if new:
            keep, self.points = self.points, np.zeros(0, dtype=complex)
            self.absorb(new, 0.5)
            self._drawn, self.points = np.concatenate([self._drawn, self.points]), keep
        return self._drawn

    def crossed(self, box: Box, pts: np.ndarray | None = None) -> int:
        """How many drawn line points lie inside ``box`` (its edges 0.2 mm in)."""
        pts = self._drawn_points() if pts is None else pts
        return int(np.count_nonzero((pts.real > box[0] + 0.2) & (pts.real < box[2] - 0.2)
                                    & (pts.imag > box[1] + 0.2) & (pts.imag < box[3] - 0.2)))

    def free(self, box: Box) -> bool:
        """No box within ``pad`` of ``box`` and no segment across it."""
        return (not any(boxes_overlap(box, b, self.pad) for b in self.boxes)
                and not any(segment_hits_box(p0, p1, box) for p0, p1 in self.segments))

    def crowding(self, box: Box, height: float) -> int:
        """How many texts come within :data:`LABEL_CLEAR` × the smaller height of a text
        ``height`` high in ``box``."""
        return sum(1 for b, h in self.texts if boxes_overlap(box, b, LABEL_CLEAR * min(height, h)))

    def _label(self, box: Box, height: float, label: bool = True) -> None:
        """Keep the text just drawn (the sheet's last entity) in ``box`` clear of later
        labels; a point label (``label``) is listed in the sheet's ``labels``."""
        self.boxes.append(box)
        self.texts.append((box, height))
        if label:
            self.sheet.labels.append(self.sheet.entities[-1])

    def cost(self, b: Box) -> float:
        a = self.area
        if a is not None and not (b[0] >= a[0] and b[2] <= a[2] and b[1] >= a[1] and b[3] <= a[3]):
            return np.inf
        pts = self.points
        hits = np.count_nonzero((pts.real > b[0]) & (pts.real < b[2]) & (pts.imag > b[1])
                                & (pts.imag < b[3]))
        overlap = sum(1 for o in self.boxes if boxes_overlap(b, o))
        overlap += sum(1 for p0, p1 in self.segments if clip_segment(p0, p1, b) is not None)
        return hits + 1000.0 * overlap

    def _clamp(self, c: complex, w: float, h: float) -> complex:
        if self.area is None:
            return c
        x0, y0, x1, y1 = self.area
        return complex(min(max(c.real, x0 + w / 2), x1 - w / 2), min(max(c.imag, y0 + h / 2), y1 - h / 2))

    # -- texts
    def text(self, p, text: str, h: float = 3.5, halign: str = "left", valign: str = "bottom",
             layer: str = "TEXT") -> None:
        """A text at a position chosen by the caller, kept clear of by later labels."""
        self.sheet.text(p, text, h, layer, halign, valign)
        self._label(text_box(complex(p), text, h, halign, valign), h, label=False)

    def place(self, anchor: complex, text: str, height: float = 3.5,
              prefer: complex = 1j, gap: float = 2.5, layer: str = "TEXT",
              crowded: bool = True, leader: bool = False, apart: bool = False,
              last_leader: bool = False, reach: float = 10.0) -> complex | None:
        """A point label at the first free spot (the three rings round the anchor, then a
        little farther out about the preferred direction, up to ``reach`` mm, with a margin from the
        lines and the other labels); where there is none, beside the anchor over
        whatever is there — or, with ``crowded=False``, nothing drawn and None returned, or,
        with ``leader``, on a leader line out to where no line crosses it (a frame pivot
        inside the fan of the crank's twelve positions). With ``leader`` or ``apart`` a free
        spot keeps 1.1 mm from the other labels (two labels side by side read as one), and
        every free spot keeps :data:`LABEL_CLEAR` from the texts the placer knows.
        With ``last_leader`` a label that finds no free spot even farther out goes on a
        leader as with ``leader`` (a position number where the fan of the other positions'
        links is densest), instead of over a line. A small label among close points (a
        polygon's) is given a short ``reach``: one farther from its point than that, across
        the vectors, is not read as its point's; a leader names the point."""
        w, h = text_width(text, height), height
        u = prefer / abs(prefer) if abs(prefer) > 1e-12 else 1j
        turns = [0, 1, -1, 2, -2, 3, -3, 4]
        drawn = self._drawn_points()
        best = None
        # the first candidate free of labels and lines within two rings is taken; else the
        # one touching the fewest labels, the outer ring (far from its point) only when the
        # inner two have no free one, then the fewest line points across it
        ranked = None
        for ring, dist in enumerate((gap, 2.0 * gap, 3.2 * gap)):
            for order, t in enumerate(turns):
                d = u * np.exp(1j * t * np.pi / 4)
                # centre so that the box edge, not its centre, sits ``dist`` from the anchor
                c = anchor + d * (dist + 0.5 * abs(d.real) * w + 0.5 * abs(d.imag) * h)
                box = (c.real - w / 2, c.imag - h / 2, c.real + w / 2, c.imag + h / 2)
                # with a leader to go to, a spot is taken only with a margin from the lines
                # (the glyphs reach past the estimated box: an italic O on a hatch stroke)
                # and from the other labels (B beside the position number 5 read "B5")
                free = (self.free(box if not (leader or apart) else (box[0] - 1.1, box[1] - 0.4,
                                                                     box[2] + 1.1, box[3] + 0.4))
                        and not self.crowding(box, h))
                hits = self.crossed(box if not leader else (box[0] - 0.5, box[1] - 0.5, box[2] + 0.5,
                                                            box[3] + 0.5), drawn)
                if free and hits == 0 and ring < 2:
                    best = (c, box)
                    break
                rank = (0 if free else 1 + sum(1 for b in self.boxes if boxes_overlap(box, b)),
                        ring == 2, hits, ring, order)
                if ranked is None or rank < ranked[0]:
                    ranked = (rank, c, box)
            if best is not None:
                break
        blocked = ranked is not None and ranked[0][0] + ranked[0][2] > 0
        if best is None and not leader and blocked:
            # no free spot in the rings: a little farther out, about the preferred direction,
            # before a label is put over a line or another label (a position number among
            # the links of the other positions; GB/T 4458.4: no text crossed by a line)
            for dist in sorted({4.5 * gap, 6.0 * gap, gap + 3.0, gap + 5.0}):
                if dist > reach or best is not None:
                    break
                for t in turns[:5]:
                    d = u * np.exp(1j * t * np.pi / 4)
                    c = anchor + d * (dist + 0.5 * abs(d.real) * w + 0.5 * abs(d.imag) * h)
                    box = (c.real - w / 2, c.imag - h / 2, c.real + w / 2, c.imag + h / 2)
                    grown = (box[0] - 1.1, box[1] - 0.4, box[2] + 1.1, box[3] + 0.4)
                    if self.free(grown) and not self.crowding(box, h) and self.crossed(
                            (box[0] - 0.5, box[1] - 0.5, box[2] + 0.5, box[3] + 0.5), drawn) == 0:
                        best = (c, box)
                        break
        if best is None and (leader or (last_leader and blocked)):
            self.leader(anchor, text, height, prefer, avoid_lines=True)
            return None
        if best is None and ranked is not None and (ranked[0][0] == 0 or crowded):
            best = ranked[1:]
        if best is None:
            if not crowded:
                return None
            c = anchor + u * (gap + 0.5 * w)
            best = (c, (c.real - w / 2, c.imag - h / 2, c.real + w / 2, c.imag + h / 2))
        c, box = best
        self.sheet.text(c, text, height, layer, "center", "middle")
        self._label(box, h)
        return c

    def spot(self, anchor: complex, text: str, height: float, prefer: complex,
             gap: float = 1.5, margin: float = 0.5) -> complex | None:
        """The centre of the first spot beside ``anchor`` (as :meth:`place` tries them, the
        two inner rings) that no label and no drawn line comes within ``margin`` of; None if
        there is none. Nothing is drawn."""
        w, h = text_width(text, height), height
        u = prefer / abs(prefer) if abs(prefer) > 1e-12 else 1j
        drawn = self._drawn_points()
        for dist in (gap, 2.0 * gap):
            for t in (0, 1, -1, 2, -2, 3, -3, 4):
                d = u * np.exp(1j * t * np.pi / 4)
                c = anchor + d * (dist + 0.5 * abs(d.real) * w + 0.5 * abs(d.imag) * h)
                box = (c.real - w / 2, c.imag - h / 2, c.real + w / 2, c.imag + h / 2)
                a = self.area
                if a is not None and not (box[0] >= a[0] and box[2] <= a[2] and box[1] >= a[1]
                                          and box[3] <= a[3]):
                    continue
                grown = (box[0] - margin, box[1] - margin, box[2] + margin, box[3] + margin)
                if self.free(grown) and not self.crowding(box, h) and self.crossed(grown, drawn) == 0:
                    return c
        return None

    def place_best(self, anchor: complex, text: str, height: float, prefer: complex,
                   gaps=(1.2, 2.5, 4.5, 7.0), layer: str = "TEXT") -> complex:
        """A point label at the cheapest of 16 directions × ``gaps``; returns its centre."""
        w, h = text_width(text, height), height
        u = prefer / abs(prefer)
        best = None
        for rank, dist in enumerate(gaps):
            for t in (0, 1, -1, 2, -2, 3, -3, 4, -4, 5, -5, 6, -6, 7, -7, 8):
                d = u * np.exp(1j * t * np.pi / 8)
                c = anchor + d * (dist + 0.5 * abs(d.real) * w + 0.5 * abs(d.imag) * h)
                b = (c.real - w / 2, c.imag - h / 2, c.real + w / 2, c.imag + h / 2)
                # the lines counted with a margin (the glyphs reach past the estimated box:
                # an italic P on the line of centres, N2 on the line of action drawn on)
                # (a text nearer than LABEL_CLEAR costs as much as a few lines across it)
                cost = (self.cost((b[0] - 0.5, b[1] - 0.5, b[2] + 0.5, b[3] + 0.5)) + 0.8 * rank
                        + 0.25 * abs(t) + 20.0 * self.crowding(b, h))
                if best is None or cost < best[0]:
                    best = (cost, c, b)
        cost, c, b = best
        if not np.isfinite(cost):                         # no room: pushed into the area
            c = self._clamp(c, w, h)
            b = (c.real - w / 2, c.imag - h / 2, c.real + w / 2, c.imag + h / 2)
        self.sheet.text(c, text, height, layer, "center", "middle")
        self._label(b, h)
        return c

    def leader(self, anchor: complex, text: str, height: float, prefer: complex,
               lengths=(8.0, 13.0, 19.0, 27.0, 37.0, 50.0), layer: str = "CONSTRUCTION",
               avoid_lines: bool = False, both_sides: bool = False) -> None:
        """A text on a short underline, joined to ``anchor`` by a leader line; with
        ``avoid_lines`` its text keeps clear of every line drawn so far, not only of what
        was blocked (a point label pushed out of a fan of lines: :meth:`place`). The leader
        leaves within 90° of ``prefer``; with ``both_sides`` also within 90° of its opposite
        where that is cheaper (a vector's label on either side of it: the press's F_R65 at
        the top edge of its polygon, where the preferred side is the cell's heading)."""
        w = text_width(text, height) + 2.0
        u = prefer / abs(prefer)
        sides = (u, -u) if both_sides else (u,)
        best = None
        drawn = self._drawn_points() if avoid_lines else None
        for rank, length in enumerate(lengths):
            for t, side in ((t, side) for side in sides
                            for t in (0, 1, -1, 2, -2, 3, -3, 4, -4, 5, -5, 6, -6)):
                d = side * np.exp(1j * t * np.pi / 12)
                elbow = anchor + length * d
                right = d.real >= 0
                x0, x1 = (elbow.real, elbow.real + w) if right else (elbow.real - w, elbow.real)
                b = (x0, elbow.imag, x1, elbow.imag + height + 1.2)
                leader_hits = sum(1 for o in self.boxes if clip_segment(anchor, elbow, o) is not None)
                # a leader kept out of the texts: one across a text costs as much as across ten
                # blocked points (each box above is one; the vector the leader starts from
                # is made of several, so every way out crosses some)
                leader_hits += 10 * sum(1 for o, _ in self.texts if clip_segment(anchor, elbow, o) is not None)
                # the text (over its underline, :data:`LABEL_CLEAR` from the other texts)
                tb = (x0 + 1.0, elbow.imag + 0.8, x1 - 1.0, elbow.imag + 0.8 + height)
                cost = (self.cost(b) + 1000.0 * (leader_hits + self.crowding(tb, height))
                        + 0.6 * rank + 0.2 * abs(t))
                if drawn is not None:
                    # the text clear of every line and read apart from the other labels, the
                    # leader not along a line (the crank's rays about its pivot)
                    cost += (100.0 * self.crossed(b, drawn) + 2.0 * _near_segment(drawn, anchor, elbow, 0.7, 2.0)
                             + 1000.0 * sum(1 for o in self.boxes if boxes_overlap(b, o, 1.1)))
                if best is None or cost < best[0]:
                    best = (cost, elbow, right, b)
        cost, elbow, right, b = best
        if not np.isfinite(cost):                         # no room: pushed into the area
            mid = self._clamp(complex((b[0] + b[2]) / 2, (b[1] + b[3]) / 2), w, height + 1.2)
            elbow += mid - complex((b[0] + b[2]) / 2, (b[1] + b[3]) / 2)
            b = (mid.real - w / 2, elbow.imag, mid.real + w / 2, elbow.imag + height + 1.2)
        end = complex(b[2] if right else b[0], elbow.imag)
        self.sheet.line(anchor, elbow, layer)
        self.sheet.line(elbow, end, layer)
        self.sheet.fill(anchor + 0.6 * np.exp(1j * np.linspace(0, 2 * np.pi, 9)[:-1]), layer)
        self.sheet.text(complex((b[0] + b[2]) / 2, elbow.imag + 0.8), text, height,
                        "TEXT" if layer == "CONSTRUCTION" else layer, "center", "bottom")
        self.boxes.append(b)
        self._label((b[0] + 1.0, b[1] + 0.8, b[2] - 1.0, b[1] + 0.8 + height), height)

    # -- labels that break the thin lines under them
    def mark_breakable(self, first: int, last: int | None = None, layers=("CONSTRUCTION",)) -> None:
        """The thin lines and polylines among the sheet's entities ``first``…``last`` (on
        ``layers``) may be broken by a label (:meth:`place_breaking`)."""
        last = len(self.sheet.entities) if last is None else last
        self.breakable |= {i for i in range(first, last)
                           if isinstance(self.sheet.entities[i], (Line, Polyline))
                           and self.sheet.entities[i].layer in layers}

    def _fixed_points(self) -> np.ndarray:
        """Points along every drawn line, arc and dimension that may not be broken."""
        n = len(self.sheet.entities)
        if getattr(self, "_fixed_n", -1) != n:
            keep, self.points = self.points, np.zeros(0, dtype=complex)
            self.absorb([e for i, e in enumerate(self.sheet.entities)
                         if i not in self.breakable and not isinstance(e, (Text, Fill))], 0.4)
            self._fixed, self.points, self._fixed_n = self.points, keep, n
        return self._fixed

    def _crossing_breakable(self, box: Box) -> list[int]:
        out = []
        for i in self.breakable:
            e = self.sheet.entities[i]
            pts = (e.p0, e.p1) if isinstance(e, Line) else tuple(e.points) + ((e.points[0],) if e.closed else ())
            if any(clip_segment(a, b, box) is not None for a, b in zip(pts[:-1], pts[1:])):
                out.append(i)
        return out

    def _break(self, box: Box) -> None:
        """The breakable lines crossing ``box`` drawn with a gap there (GB/T 4457.4: a thin
        line is broken where it would cross a text)."""
        for i in self._crossing_breakable(box):
            e = self.sheet.entities[i]
            pts = [e.p0, e.p1] if isinstance(e, Line) else list(e.points) + ([e.points[0]] if e.closed else [])
            runs, run = [], [pts[0]]
            for a, b in zip(pts[:-1], pts[1:]):
                cut = clip_segment(a, b, box)
                if cut is None:
                    run.append(b)
                    continue
                t0, t1 = cut
                if t0 > 1e-9:
                    run.append(a + (b - a) * t0)
                if len(run) >= 2:
                    runs.append(run)
                run = [a + (b - a) * t1] if t1 < 1 - 1e-9 else []
                if t1 < 1 - 1e-9:
                    run.append(b)
            if len(run) >= 2:
                runs.append(run)
            runs = [r for r in runs if abs(r[-1] - r[0]) > 0.3 or len(r) > 2]
            pieces = [Line(r[0], r[1], e.layer, e.weight) if len(r) == 2 else
                      Polyline(tuple(r), e.layer, False, e.weight) for r in runs]
            if not pieces:                  # wholly under the text: a zero-length stub
                pieces = [Line(pts[0], pts[0], e.layer, e.weight)]
            self.sheet.entities[i] = pieces[0]
            for piece in pieces[1:]:
                self.breakable.add(len(self.sheet.entities))
                self.sheet.entities.append(piece)

    def place_breaking(self, anchor: complex, text: str, height: float, prefer: complex,
                       gaps=(1.0, 2.0, 3.2, 4.5, 6.0), circled: bool = False,
                       margin: float = 0.6, balloon=()) -> complex | None:
        """A point label close beside ``anchor`` where only breakable thin lines cross it
        (:meth:`mark_breakable`), those broken round it: the nearest spot (``gaps`` from the
        anchor, 16 directions from ``prefer``) clear of every other line, arc, dimension,
        blocked point and label (the word space :data:`LABEL_CLEAR` from the texts), the
        fewest thin lines across it. With ``circled`` the text is drawn in a circle (a
        position number, told from a link number as GB drawings do). None (nothing drawn)
        when no spot is clear: a pivot inside the fan of the crank's twelve positions went
        on a 40 mm leader and its name stood at the crank circle among the position marks.
        ``balloon``: farther distances tried next for a circled text, which is then joined
        to its point by a thin leader (a balloon, as a part number of GB/T 4458.2) that
        crosses no text."""
        w, h = text_width(text, height), height
        r = max(w, h) / 2 + 0.25 * height + 0.3 if circled else 0.0
        bw, bh = (2 * r, 2 * r) if circled else (w, h)
        u = prefer / abs(prefer) if abs(prefer) > 1e-12 else 1j
        fixed = self._fixed_points()
        best = None
        far = list(balloon) if circled else []
        for rank, dist in enumerate(list(gaps) + far):
            if rank == len(gaps) and best is not None:
                break
            for t in (0, 1, -1, 2, -2, 3, -3, 4, -4, 5, -5, 6, -6, 7, -7, 8):
                d = u * np.exp(1j * t * np.pi / 8)
                c = anchor + d * (dist + 0.5 * abs(d.real) * bw + 0.5 * abs(d.imag) * bh)
                box = (c.real - bw / 2, c.imag - bh / 2, c.real + bw / 2, c.imag + bh / 2)
                grown = (box[0] - margin, box[1] - margin, box[2] + margin, box[3] + margin)
                if not self.free((box[0] - 1.1, box[1] - 0.4, box[2] + 1.1, box[3] + 0.4)) \
                        or self.crowding(box, h):
                    continue
                if np.count_nonzero((fixed.real > grown[0]) & (fixed.real < grown[2])
                                    & (fixed.imag > grown[1]) & (fixed.imag < grown[3])):
                    continue
                if far and abs(c - anchor) > BALLOON_AT:   # on a leader: crossing no text, no pin
                    foot = c - (c - anchor) / abs(c - anchor) * r
                    # (the boxes about the point itself, its pin and slider block, left out)
                    if any(clip_segment(anchor, foot, b) is not None for b in self.boxes
                           if not (b[0] - 6.0 <= anchor.real <= b[2] + 6.0
                                   and b[1] - 6.0 <= anchor.imag <= b[3] + 6.0)) \
                            or any(clip_segment(anchor, foot, b) is not None for b, _ in self.texts):
                        continue
                cost = len(self._crossing_breakable(grown)) + 1.5 * rank + 0.3 * abs(t)
                if best is None or cost < best[0]:
                    best = (cost, c, box, grown)
            if best is not None and best[0] < 1.5 * rank + 3.0:
                break
        if best is None:
            return None
        _, c, box, grown = best
        self._break(grown)
        if far and abs(c - anchor) > BALLOON_AT:
            foot = c - (c - anchor) / abs(c - anchor) * r
            self.sheet.line(anchor, foot, "CONSTRUCTION")
            self.sheet.fill(anchor + 0.5 * np.exp(1j * np.linspace(0, 2 * np.pi, 9)[:-1]), "CONSTRUCTION")
            self.segments.append((anchor + (foot - anchor) * 0.1, foot))
        self.sheet.text(c, text, height, "TEXT", "center", "middle")
        self._label(box, h)
        if circled:
            self.sheet.circle(c, r, "OUTLINE", 0.25)
        return c


def _near_segment(pts: np.ndarray, a: complex, b: complex, dist: float, skip: float) -> int:
    """How many of ``pts`` lie within ``dist`` of segment a–b, its first ``skip`` mm left
    out (the lines meeting at ``a``)."""
    length = abs(b - a)
    if length <= skip or not len(pts):
        return 0
    u = (b - a) / length
    q = (pts - a) * np.conj(u)
    return int(np.count_nonzero((q.real > skip) & (q.real < length) & (np.abs(q.imag) < dist)))


# -- more GB/T 4460 symbols for the kinematic diagrams (机构运动简图) ----------------------

def hatched_line(sheet_or_view, z0, z1, side: complex = -1j, step: float = 3.0,
                 length: float = 2.5, weight: float = 0.5) -> None:
    """A frame line z0 → z1 (e.g. a fixed slider guide) with short 45° hatch strokes on
    ``side`` (a direction relative to z0 → z1: −1j to the right of it), paper mm."""
    s = sheet_or_view.sheet if isinstance(sheet_or_view, View) else sheet_or_view
    p0 = sheet_or_view.p(z0) if isinstance(sheet_or_view, View) else complex(z0)
    p1 = sheet_or_view.p(z1) if isinstance(sheet_or_view, View) else complex(z1)
    s.line(p0, p1, "OUTLINE", weight)
    span = abs(p1 - p0)
    if span < 1e-9:
        return
    u = (p1 - p0) / span
    n = u * side / abs(side)
    count = max(int(span / step), 1)
    for t in np.linspace(0.0, span, count + 1)[:-1] + 0.5 * span / (count + 1):
        q = p0 + u * t
        s.line(q, q + length * (n - u) / np.sqrt(2.0), "CONSTRUCTION")


def turn_arrow(sheet: Sheet, centre: complex, radius: float, ccw: bool, start: float = 0.25 * np.pi,
               sweep: float = 0.6 * np.pi, layer: str = "OUTLINE", head: float = 2.5) -> complex:
    """A turning-direction arrow (ω) about ``centre`` [paper mm]: an arc of ``sweep`` from
    ``start`` with a filled head at its end in the turning sense. Returns the arc's middle."""
    a0, a1 = (start, start + sweep) if ccw else (start + sweep, start)
    lo, hi = min(a0, a1), max(a0, a1)
    sheet.arc(centre, radius, lo, hi, layer, 0.35)
    tip = centre + radius * np.exp(1j * a1)
    tangent = 1j * np.exp(1j * a1) * (1 if ccw else -1)
    base = tip - head * tangent
    w = 0.35 * head
    sheet.fill([tip, base + 1j * tangent * w, base - 1j * tangent * w], layer)
    return centre + radius * np.exp(1j * (lo + hi) / 2)
