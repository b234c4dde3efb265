"""Texts of a drawing sheet's PDF that touch other texts or are crossed by its lines (used by
tests/test_sheet_labels_clear.py).

Read as a reader sees the page: every text span of the PDF (PyMuPDF: its baseline origin,
direction, font size and glyph boxes) and every stroked or filled path (lines, rectangles,
Bézier curves sampled). A text's *core* is the rectangle its glyphs fill in its own frame:
along the baseline from the first glyph to the end of the last (less 8 % of the size at
each end), across it from 10 % to 65 % of the size above the baseline (digits, capitals
and the body of a Chinese character; not the ascender or descender room of the line box,
which a table's rules may touch). Findings: two cores that overlap (with a gap of 0.15 mm
tolerated: two labels touching are not read apart either), a segment that crosses a
core (a dimension line through "R92.50", a hatch through "O").
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

MM = 72.0 / 25.4          # PDF points per mm


@dataclass(frozen=True)
class Core:
    text: str
    origin: np.ndarray      # baseline start (pt, PDF y down)
    along: np.ndarray       # unit vector along the baseline
    up: np.ndarray          # unit vector from the baseline up the glyphs
    u0: float
    u1: float
    v0: float
    v1: float

    def corners(self) -> np.ndarray:
        return np.array([self.origin + u * self.along + v * self.up
                         for u, v in ((self.u0, self.v0), (self.u1, self.v0),
                                      (self.u1, self.v1), (self.u0, self.v1))])

    def local(self, p: np.ndarray) -> np.ndarray:
        d = np.atleast_2d(p) - self.origin
        return np.column_stack([d @ self.along, d @ self.up])


def text_cores(page) -> list[Core]:
    """The cores of every line of text of ``page`` (its spans together: a subscript is part
    of its symbol's text) that prints something."""
    out = []
    for block in page.get_text("rawdict")["blocks"]:
        for line in block.get("lines", []):
            d = np.array(line["dir"], float)
            up = np.array([d[1], -d[0]])
            chars = [c for span in line["spans"] for c in span["chars"] if not c["c"].isspace()]
            if not chars:
                continue
            size = max(span["size"] for span in line["spans"])
            o = np.array(chars[0]["origin"], float)
            proj = [float((np.array([x, y]) - o) @ d) for c in chars
                    for x, y in ((c["bbox"][0], c["bbox"][1]), (c["bbox"][2], c["bbox"][3]),
                                 (c["bbox"][0], c["bbox"][3]), (c["bbox"][2], c["bbox"][1]))]
            u0, u1 = min(proj) + 0.08 * size, max(proj) - 0.08 * size
            if u1 <= u0:
                continue
            text = "".join(c["c"] for span in line["spans"] for c in span["chars"])
            out.append(Core(text, o, d, up, u0, u1, 0.10 * size, 0.65 * size))
    return out


def _bezier(p0, p1, p2, p3, n=8):
    t = np.linspace(0.0, 1.0, n)[:, None]
    return ((1 - t) ** 3 * p0 + 3 * (1 - t) ** 2 * t * p1 + 3 * (1 - t) * t ** 2 * p2 + t ** 3 * p3)


def segments(page) -> np.ndarray:
    """Every drawn segment of ``page`` as rows (x0, y0, x1, y1) [pt]."""
    out = []
    for path in page.get_drawings():
        for item in path["items"]:
            kind = item[0]
            if kind == "l":
                out.append((*item[1], *item[2]))
            elif kind == "c":
                pts = _bezier(*(np.array(p, float) for p in item[1:5]))
                out += [(*a, *b) for a, b in zip(pts[:-1], pts[1:])]
            elif kind == "re":
                r = item[1]
                c = [(r.x0, r.y0), (r.x1, r.y0), (r.x1, r.y1), (r.x0, r.y1)]
                out += [(*c[j], *c[(j + 1) % 4]) for j in range(4)]
            elif kind == "qu":
                q = item[1]
                c = [tuple(q.ul), tuple(q.ur), tuple(q.lr), tuple(q.ll)]
                out += [(*c[j], *c[(j + 1) % 4]) for j in range(4)]
    return np.array(out, float).reshape(-1, 4)


def crossing(core: Core, segs: np.ndarray) -> np.ndarray:
    """The rows of ``segs`` that pass through ``core`` (Liang–Barsky in the text's frame)."""
    if not len(segs):
        return segs
    a = core.local(segs[:, :2])
    b = core.local(segs[:, 2:])
    d = b - a
    t0 = np.zeros(len(segs))
    t1 = np.ones(len(segs))
    ok = np.ones(len(segs), bool)
    for p, q in ((-d[:, 0], a[:, 0] - core.u0), (d[:, 0], core.u1 - a[:, 0]),
                 (-d[:, 1], a[:, 1] - core.v0), (d[:, 1], core.v1 - a[:, 1])):
        par = np.abs(p) < 1e-12
        ok &= ~(par & (q < 0))
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.where(par, 0.0, q / np.where(par, 1.0, p))
        t0 = np.where(~par & (p < 0), np.maximum(t0, t), t0)
        t1 = np.where(~par & (p > 0), np.minimum(t1, t), t1)
    return segs[ok & (t1 - t0 > 1e-9)]


def cores_overlap(a: Core, b: Core, gap: float = 0.15 * MM) -> bool:
    """Whether two cores overlap, less ``gap`` (separating axis test of two rectangles)."""
    ca, cb = a.corners(), b.corners()
    for axis in (a.along, a.up, b.along, b.up):
        pa, pb = ca @ axis, cb @ axis
        if pa.max() - gap <= pb.min() or pb.max() - gap <= pa.min():
            return False
    return True


def findings(page) -> list[str]:
    """Each text crossed by a line or overlapping another text, with where it is [mm]."""
    cores = text_cores(page)
    segs = segments(page)
    out = []

    def where(c: Core) -> str:
        return f"{c.text!r} at ({c.origin[0] / MM:.0f}, {c.origin[1] / MM:.0f}) mm"

    for c in cores:
        hit = crossing(c, segs)
        if len(hit):
            out.append(f"{where(c)} crossed by {len(hit)} line(s), e.g. "
                       f"{np.round(hit[0] / MM, 1).tolist()} mm")
    for i, a in enumerate(cores):
        for b in cores[i + 1:]:
            if cores_overlap(a, b):
                out.append(f"{where(a)} overlaps {where(b)}")
    return out


def touching_labels(sheet, clearance: float = 0.3, space: float = 0.3) -> list[str]:
    """Pairs of texts of a sheet model (render/sheet.py; the DXF writes each as one TEXT or
    MTEXT at the same insert point) whose boxes — the insert point, the height and the
    width estimated as the sheet does (``text_width``: a Latin character 0.62 of the height,
    a Chinese one square) — come closer than ``clearance`` [mm]: two labels read as one
    ("3" and "5" side by side read "35"). Turned texts (axis titles, dimension texts) are
    left to :func:`findings`."""
    from mechdesign.render.sheet import Text, plain, text_box

    boxes = [(e.text, text_box(e.position, e.text, e.height, e.halign, e.valign))
             for e in sheet.entities
             if isinstance(e, Text) and abs(e.angle) < 1e-9 and plain(e.text).strip()]
    out = []
    for i, (ta, a) in enumerate(boxes):
        for tb, b in boxes[i + 1:]:
            gap = space * max(a[3] - a[1], b[3] - b[1])
            if (a[0] < b[2] + gap and b[0] < a[2] + gap
                    and a[1] < b[3] + clearance and b[1] < a[3] + clearance):
                out.append(f"{plain(ta)!r} at ({a[0]:.1f}, {a[1]:.1f}) and {plain(tb)!r} at "
                           f"({b[0]:.1f}, {b[1]:.1f}) mm")
    return out


# the clearance a point label keeps from every other text, a fraction of the smaller text
# height: the word space of ISO 3098-1 / GB/T 14691 lettering (type B: 0.6 h, 1.5 mm at the
# sheets' 2.5 mm labels). Two labels nearer than the space between the words of one text
# read as one text ("n4s4′", "n4′" and "n4b′" stacked 0.6–0.8 mm apart read as a note).
LABEL_SPACE = 0.6


def crowded_labels(sheet, space: float = LABEL_SPACE) -> list[str]:
    """The point labels of a sheet model (``sheet.labels``, the texts its label placers put
    beside their points) that come nearer another level text than ``space`` × the smaller
    of the two heights, across and along (boxes as :func:`touching_labels` reads them)."""
    from mechdesign.render.sheet import Text, plain, text_box

    texts = [e for e in sheet.entities
             if isinstance(e, Text) and abs(e.angle) < 1e-9 and plain(e.text).strip()]
    labels = {id(e) for e in sheet.labels}
    boxes = [(e, text_box(e.position, e.text, e.height, e.halign, e.valign)) for e in texts]
    out = []
    for i, (ea, a) in enumerate(boxes):
        for eb, b in boxes[i + 1:]:
            if id(ea) not in labels and id(eb) not in labels:
                continue
            c = space * min(ea.height, eb.height)
            dx = max(b[0] - a[2], a[0] - b[2])
            dy = max(b[1] - a[3], a[1] - b[3])
            if dx < c and dy < c:
                out.append(f"{plain(ea.text)!r} at ({a[0]:.1f}, {a[1]:.1f}) and {plain(eb.text)!r} at "
                           f"({b[0]:.1f}, {b[1]:.1f}) mm, {max(dx, dy):.1f} mm apart")
    return out
