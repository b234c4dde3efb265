"""The gear meshing drawing sheet (齿轮啮合图) that the student hands in.

The pair is drawn in the layout of :func:`mechdesign.core.gears.mesh_layout` (computed by the
gear stage, :class:`mechdesign.stages.gear.GearDrawing`; the sheet only reads it): the line of
centres vertical, the pinion O1 below, the gear O2 above, gear 1 driving counter-clockwise.
Several generated teeth of each gear around the pitch point (true involutes with their
root fillets and any undercut, :func:`mechdesign.core.gears.tooth_outline`), the pitch,
reference, base, tip and root circles (arcs where a circle leaves the drawing area), the
theoretical line of action N1N2 tangent to both base circles, the actual line of action
B1B2 (bold), the pitch point P and the common tangent, the working pressure angle α′,
the dimensions a′, r, rb, ra, rf, a data table and notes, in the border with the title
block. Everything is clipped to the drawing area left of the table column.

The scale is a GB/T 14690 scale (enlargements 2:1 … 10:1 for small modules, reductions
1:1.5 … for large ones) chosen so that the whole pinion, the line of action and the
gear's teeth near P fit, with the module on paper at most :data:`MAX_PAPER_MODULE` mm.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..core.gears import SpurPair
from ..i18n import N_
from ..stages.gear import GearDrawing
from . import fmt
from .labels import LabelTable, pgettext, sheet_point
from .sheet import (MARKERS, LabelPlacer, Polyline, Sheet, TitleInfo, clip_segment, frame,
                    length_scale, plain, sample_polyline, scale_text, sub, table, text_width,
                    title_block_box, with_subscripts)

MM = 1e3
DEG = 180.0 / np.pi
TABLE_W = 180.0            # the right-hand column: data table, notes, title block
GAP = 6.0                  # drawing area ↔ border and table column [mm]
MAX_PAPER_MODULE = 16.0    # enlarge small modules up to this module on paper [mm]
MIN_PAPER_MODULE = 5.0     # below this, give up the whole pinion for a larger scale
ENLARGEMENTS = (10.0, 5.0, 4.0, 2.5, 2.0, 1.0)   # GB/T 14690 n:1 (2.5:1 and 4:1 allowed)

LABELS = LabelTable({
    "drawing": N_("Gear meshing drawing"),
    "action": N_("theoretical line of action N1N2"),
    "actual": N_("actual line of action B1B2"),
    "o2": N_("O2 (centre distance a′ = {a})"),
    "table": pgettext("gear sheet", "Meshing data"),
    "head": (pgettext("gear sheet", "Item"), N_("Symbol"), N_("Gear 1"), pgettext("gear sheet", "Gear 2"), N_("Unit")),
    "m": N_("module"),
    "alpha": N_("pressure angle"),
    "ha": N_("addendum coeff."),
    "c": N_("clearance coeff."),
    "z": N_("number of teeth"),
    "x": N_("profile shift coeff."),
    "d": N_("reference diameter"),
    "dw": N_("pitch diameter"),
    "da": N_("tip diameter"),
    "df": N_("root diameter"),
    "db": N_("base diameter"),
    "aw": N_("centre distance"),
    "alw": N_("working pressure angle"),
    "pb": N_("base pitch"),
    "b1b2": N_("length of action"),
    "eps_g": N_("contact ratio (drawn)"),
    "eps_f": N_("contact ratio (formula)"),
    "notes": N_("Notes"),
    "n_drive": N_("Gear 1 drives, counter-clockwise; gear 2 turns clockwise."),
    "n_teeth": N_("Generated involute tooth profiles with their root fillets."),
    "n_eps": N_("ε = B1B2 / pb = {g}; ε = [z1(tan αa1 − tan α′) + z2(tan αa2 − tan α′)] / 2π = {f}."),
    "n_undercut": N_("Gear {i} (z = {z}, x = {x} < xmin = {xmin}) is undercut."),
    "n_interf": N_("B1B2 runs beyond N1N2: interference."),
})


def _points(text: str) -> str:
    """``text`` with the point pairs N1N2, B1B2 written with subscripts (N₁N₂, B₁B₂)."""
    for a in ("N", "B"):
        text = text.replace(f"{a}1{a}2", sub(a, "1") + sub(a, "2"))
    return text


# -- clipping to the drawing area (paper mm) ---------------------------------------------

Box = tuple[float, float, float, float]


def _inside(p: complex, box: Box, tol: float = 1e-9) -> bool:
    return box[0] - tol <= p.real <= box[2] + tol and box[1] - tol <= p.imag <= box[3] + tol


def _clip_polyline(points, box: Box) -> list[np.ndarray]:
    """The pieces of an open polyline inside ``box``."""
    pts = np.asarray(points, dtype=complex)
    pieces, current = [], []
    for a, b in zip(pts[:-1], pts[1:]):
        span = clip_segment(a, b, box)
        if span is None:
            if current:
                pieces.append(current)
                current = []
            continue
        t0, t1 = span
        start, end = a + (b - a) * t0, a + (b - a) * t1
        if not current or t0 > 1e-12:
            if current:
                pieces.append(current)
            current = [start]
        current.append(end)
        if t1 < 1 - 1e-12:
            pieces.append(current)
            current = []
    if current:
        pieces.append(current)
    return [np.array(p) for p in pieces if np.sum(np.abs(np.diff(p))) > 1e-9]


def _circle_spans(c: complex, r: float, box: Box) -> list[tuple[float, float]] | None:
    """Counter-clockwise angular spans [rad] of the circle inside ``box``; None = whole."""
    cuts = []
    for x in (box[0], box[2]):
        if abs(x - c.real) < r:
            t = np.arccos((x - c.real) / r)
            cuts += [t, -t]
    for y in (box[1], box[3]):
        if abs(y - c.imag) < r:
            t = np.arcsin((y - c.imag) / r)
            cuts += [t, np.pi - t]
    if not cuts:
        return None if _inside(c + r, box) else []
    cuts = sorted(set(float(np.mod(t, 2 * np.pi)) for t in cuts))
    cuts.append(cuts[0] + 2 * np.pi)
    spans = [(a, b) for a, b in zip(cuts[:-1], cuts[1:])
             if b - a > 1e-9 and _inside(c + r * np.exp(1j * (a + b) / 2), box)]
    merged: list[list[float]] = []
    for a, b in spans:
        if merged and abs(a - merged[-1][1]) < 1e-9:
            merged[-1][1] = b
        else:
            merged.append([a, b])
    if len(merged) > 1 and abs(merged[-1][1] - 2 * np.pi - merged[0][0]) < 1e-9:
        merged[0][0] = merged.pop()[0] - 2 * np.pi
    return [(a, b) for a, b in merged]


class _Pen:
    """Draws on the sheet in paper mm, clipped to the drawing area."""

    def __init__(self, sheet: Sheet, box: Box):
        self.sheet, self.box = sheet, box

    def polyline(self, points, layer, weight=None):
        for piece in _clip_polyline(points, self.box):
            self.sheet.polyline(piece, layer, weight=weight)

    def line(self, a, b, layer, weight=None):
        for piece in _clip_polyline([a, b], self.box):
            self.sheet.line(piece[0], piece[-1], layer, weight)

    def circle(self, c, r, layer, weight=None):
        """The circle, or its arcs inside the area."""
        spans = _circle_spans(c, r, self.box)
        if spans is None:
            self.sheet.circle(c, r, layer, weight)
            return
        for a, b in spans:
            self.sheet.arc(c, r, a, b, layer, weight)


# -- scale and placement ------------------------------------------------------------------

@dataclass(frozen=True)
class _Plan:
    size: str
    k: float               # paper mm per model mm
    origin: complex        # paper position of O1
    box: Box               # the drawing area


def _drawing_box(size: str) -> Box:
    s = Sheet(size)
    x0, y0, x1, y1 = s.inner
    return x0 + GAP, y0 + GAP, x1 - TABLE_W - GAP, y1 - GAP


def _best_k(extent: complex, room: complex, m: float) -> float:
    """The largest GB scale (paper per model mm) drawing ``extent`` within ``room``."""
    if room.real <= 0 or room.imag <= 0:
        return 0.0
    bound = min(room.real / extent.real, room.imag / extent.imag)
    if bound >= 1.0:
        cap = max(1.0, MAX_PAPER_MODULE / m)
        return next(k for k in ENLARGEMENTS if k <= min(bound, cap) * (1 + 1e-12))
    return 1.0 / length_scale(extent, room)


def _teeth(drawing: GearDrawing, gear: int, extra: float = 1.5, least: float = 2.5):
    """Indices of the teeth drawn: those within the contact path's angle (seen from the
    gear's centre) widened by ``extra`` pitches, at least ``least`` pitches either side of
    the line of centres; and the outline of one tooth in the gear's own frame."""
    lay = drawing.layout
    pair = lay.pair
    g = pair.g1 if gear == 1 else pair.g2
    centre, rot = (lay.o1, lay.rotation1) if gear == 1 else (lay.o2, lay.rotation2)
    towards = (lay.p - centre) / abs(lay.p - centre)
    step = 2 * np.pi / g.z
    reach = max(abs(np.angle((b - centre) / towards)) for b in (lay.b1, lay.b2))
    half = max(reach + extra * step, least * step)
    centres = rot + step * np.arange(g.z)
    rel = np.angle(np.exp(1j * centres) / towards)
    idx = [int(j) for j in np.argsort(rel) if abs(rel[j]) <= half]
    return idx, drawing.teeth[gear - 1], centre, rot, step


def _plan(drawing: GearDrawing, size: str | None) -> _Plan:
    lay = drawing.layout
    pair = lay.pair
    ra1 = pair.g1.da / 2
    pts = [lay.p, lay.n1, lay.n2, lay.b1, lay.b2, lay.o1]
    for gear in (1, 2):
        idx, tooth, centre, rot, step = _teeth(drawing, gear)
        for j in idx:
            pts.extend(centre + np.exp(1j * (rot + j * step)) * tooth[:: 4])
    pts = np.asarray(pts)
    # paper margins [mm]: left (the a′ dimension beyond N2), right (the pinion's radius
    # dimensions, whose text CAD writes outside the circle), bottom, top
    left, right, bottom, top = 28.0, 48.0, 10.0, 22.0
    plans = []
    for name in ([size] if size else ["A2", "A3"]):
        box = _drawing_box(name)
        room = complex(box[2] - box[0] - left - right, box[3] - box[1] - bottom - top)
        tiers = []
        for whole in (True, False):     # the whole pinion, or only O1 (35 mm above the edge)
            zs = np.concatenate([pts, [-ra1 + 0j, ra1 + 0j, -1j * ra1]]) if whole else pts
            lo = complex(zs.real.min(), zs.imag.min())
            hi = complex(zs.real.max(), zs.imag.max())
            below = 0.0 if whole else 35.0
            tiers.append((_best_k(hi - lo, room - 1j * below, pair.m), lo, hi, below))
        k, lo, hi, below = tiers[0]
        if k * pair.m < MIN_PAPER_MODULE and tiers[1][0] > k:
            k, lo, hi, below = tiers[1]
        # centred across; the pinion kept low (more of gear 2 shows above)
        x_o1 = (box[0] + left + box[2] - right) / 2 - k * (lo.real + hi.real) / 2
        y_o1 = box[1] + bottom + below - k * lo.imag
        plans.append(_Plan(name, k, complex(x_o1, y_o1), box))
    if size:
        return plans[0]
    a2, a3 = plans
    return a3 if a3.k >= a2.k * (1 - 1e-12) else a2


def _scale_label(k: float) -> str:
    if k >= 1 - 1e-12:
        return f"{fmt.exact(k)}:1"
    return scale_text(1.0 / k)


def _num(x: float, decimals: int) -> str:
    """A table value to ``decimals`` (render/fmt.py's rule), the true minus sign."""
    return fmt.minus(fmt.f(x, decimals))


def _mm(x: float) -> str:
    """A length of the table [mm] by the rule: 0.01 mm."""
    return fmt.length(x)


# -- the sheet ----------------------------------------------------------------------------

def gear_sheet(drawing: GearDrawing, info: TitleInfo, lang: str, size: str | None = None) -> Sheet:
    """The gear meshing drawing (齿轮啮合图) of the gear stage's ``drawing`` (the pair in mm):
    on an A2 sheet, or A3 when the pair is drawn as large there (``size`` forces one),
    labels in ``lang`` ("zh" or "en"). The title block gets the scale and, when
    ``info.drawing`` is empty, the drawing's name."""
    lab = LABELS[lang]
    mm = drawing.pair
    lay = drawing.layout
    plan = _plan(drawing, size)
    k, box = plan.k, plan.box
    sheet = Sheet(plan.size)
    frame(sheet, replace(info, scale=_scale_label(k), drawing=info.drawing or lab["drawing"]))
    pen = _Pen(sheet, box)
    P = lambda z: plan.origin + k * np.asarray(z, dtype=complex)  # noqa: E731

    g1, g2 = mm.g1, mm.g2
    o1, o2, p = P(lay.o1), P(lay.o2), P(lay.p)
    n1, n2, b1, b2 = P(lay.n1), P(lay.n2), P(lay.b1), P(lay.b2)
    u = lay.direction
    o2_in = _inside(o2, box, -12.0)
    shifted = abs(lay.r1w - g1.d / 2) > 1e-9 * mm.m

    # circles: pitch (and reference, when shifted) dash-dotted, base, tip and root thin
    for centre, g, rw in ((o1, g1, lay.r1w), (o2, g2, lay.r2w)):
        pen.circle(centre, k * rw, "CENTER")
        if shifted:
            pen.circle(centre, k * g.d / 2, "CENTER")
        for r in (g.db / 2, g.da / 2, g.df / 2):
            pen.circle(centre, k * r, "CONSTRUCTION")

    # generated teeth around the pitch point, one polyline per tooth
    for gear in (1, 2):
        idx, tooth, centre, rot, step = _teeth(drawing, gear)
        for j in idx:
            pen.polyline(P(centre + np.exp(1j * (rot + j * step)) * tooth), "OUTLINE")

    # centre lines, the common tangent t–t, O1N1 and O2N2
    ra1k = k * g1.da / 2
    top = complex(o1.real, box[3])
    pen.line(o1 - 1j * (ra1k + 6.0), o2 + 10j if o2_in else top, "CENTER")
    pen.line(o1 - (ra1k + 6.0), o1 + ra1k + 6.0, "CENTER")
    if o2_in:
        pen.line(o2 - 12.0, o2 + 12.0, "CENTER")
    half_t = max(0.5 * abs(n2 - n1), 30.0)
    pen.line(p - half_t, p + half_t, "CONSTRUCTION")
    pen.line(o1, n1, "CONSTRUCTION")
    pen.line(o2, n2, "CONSTRUCTION")

    # the lines of action: N1N2 (a little beyond both ends), B1B2 bold
    sheet.line(n1, n2, "CONSTRUCTION", 0.35)
    pen.line(n1 - 8.0 * u, n1, "CONSTRUCTION", 0.35)
    pen.line(n2, n2 + 8.0 * u, "CONSTRUCTION", 0.35)
    sheet.line(b1, b2, "OUTLINE", 1.2)
    for q in (n1, n2, b1, b2, p):
        sheet.circle(q, 0.9, "CONSTRUCTION", 0.35)
    sheet.circle(o1, 1.2, "CONSTRUCTION", 0.35)
    if o2_in:
        sheet.circle(o2, 1.2, "CONSTRUCTION", 0.35)

    # the working pressure angle at P, between t–t and N1N2
    r_ang = min(max(0.4 * abs(p - n2), 20.0), 40.0)
    a0, a1 = np.pi - mm.alpha_work, np.pi
    sheet.arc(p, r_ang, a0, a1, "DIMENSIONS")
    for ang, sense in ((a0, -1), (a1, 1)):
        tip = p + r_ang * np.exp(1j * ang)
        tang = 1j * np.exp(1j * ang) * sense
        base = tip - 2.5 * tang
        sheet.fill([tip, base + 0.75j * tang, base - 0.75j * tang], "DIMENSIONS")

    # driving directions
    _turn(sheet, box, o1, 0.5 * k * g1.df / 2, np.radians(118), np.radians(168), sub("ω", "1"))
    w2r = max((o2.imag - box[3] + 24.0) / np.sin(np.radians(70)), 0.45 * k * g2.df / 2)
    if w2r < 0.8 * k * g2.df / 2:
        _turn(sheet, box, o2, w2r, np.radians(-70), np.radians(-84), sub("ω", "2"))

    _dimensions(sheet, drawing, plan, o2_in)

    # labels: first the linework as obstacles
    labels = LabelPlacer(sheet, box)
    labels.absorb(sheet.entities)
    labels.absorb([Polyline(tuple(sample_polyline([p - 3 + 3j, p + 3 + 3j], 0.5)), "TEXT")])
    for name, q, prefer in (("P", p, 1 + 1.2j), ("N1", n1, -u + 1j * u), ("N2", n2, 1j * u),
                            ("B2", b2, -1j * u), ("B1", b1, 1j * u - 0.3 * u), ("O1", o1, 1 + 1j)):
        labels.place_best(q, sheet_point(name), 5.0, prefer)
    if o2_in:
        labels.place_best(o2, sheet_point("O2"), 5.0, 1 + 1j)
    else:                   # the line of centres leaves the area towards O2
        sheet.arrow(top - 14.0j, top, "CONSTRUCTION", 4.0, 0.35)
        note = with_subscripts(lab["o2"], "O_2").format(a=fmt.length(mm.a_work))
        sheet.text(top + 2.5 - 5.0j, note, 3.5, "TEXT", "left", "top")
        labels.block_box((top.real, top.imag - 10.0, top.real + text_width(note, 3.5) + 4, top.imag))
    labels.leader(p + r_ang * np.exp(1j * (a0 + a1) / 2), f"α′ = {fmt.f(mm.alpha_work * DEG, 2)}°",
                  3.5, np.exp(1j * (a0 + a1) / 2), layer="DIMENSIONS")
    labels.leader(b2 + 0.35 * (p - b2), _points(lab["actual"]), 3.5, -1j * u + 0.7)
    labels.leader(n2 + 0.3 * (b1 - n2), _points(lab["action"]), 3.5, -1j * u - 0.5)
    _table(sheet, mm, lay, lab, drawing.interference)
    return sheet


def _turn(sheet: Sheet, box: Box, centre: complex, r: float, a0: float, a1: float,
          text: str) -> None:
    """A curved arrow about ``centre`` from angle a0 to a1 (paper mm), labelled at its tail;
    left out unless it lies in the area."""
    t = np.linspace(a0, a1, 24)
    pts = centre + r * np.exp(1j * t)
    if not all(_inside(q, box, -8.0) for q in pts):
        return
    sheet.polyline(pts[:-3], "CONSTRUCTION", weight=0.35)
    sheet.arrow(pts[-4], pts[-1], "CONSTRUCTION", 3.5, 0.35)
    out = np.exp(1j * a0)
    sheet.text(pts[0] + 2.5 * out, text, 3.5, "TEXT", "left" if out.real >= 0 else "right", "middle")


def _dimensions(sheet: Sheet, drawing: GearDrawing, plan: _Plan, o2_in: bool) -> None:
    """a′, and r, rb, ra, rf (and the pitch radii r′ of a shifted pair) of both gears."""
    lay, mm = drawing.layout, drawing.pair
    k, box = plan.k, plan.box
    o1 = plan.origin
    o2 = o1 + k * lay.o2
    g1, g2 = mm.g1, mm.g2
    shifted = abs(lay.r1w - g1.d / 2) > 1e-9 * mm.m
    # centre distance a′, left of the pinion and of N2
    n2x = o1.real + k * lay.n2.real
    x_dim = max(min(o1.real - k * g1.da / 2, n2x) - 14.0, box[0] + 8.0)
    if o2_in:
        sheet.dimension(o1, o2, o1.real - x_dim, mm.a_work, f"a′ = {fmt.length(mm.a_work)}")
    else:                   # the far end is off the sheet: one arrow, the line up to the border
        a, top = complex(x_dim, o1.imag), complex(x_dim, box[3])
        sheet.line(o1 - 1.5, a - 1.5, "DIMENSIONS")
        sheet.line(a, top, "DIMENSIONS")
        sheet.fill([a, a + 2.5j + 0.75, a + 2.5j - 0.75], "DIMENSIONS")
        # the text where none of the wheel's circles crosses the line (nearest 0.45 of it)
        text = f"a′ = {fmt.length(mm.a_work)}"
        w = text_width(text, 3.5)
        dx = x_dim - o2.real
        radii = [g2.df / 2, g2.db / 2, g2.d / 2, g2.da / 2] + ([lay.r2w] if shifted else [])
        cuts = [o2.imag - np.sqrt((k * q) ** 2 - dx ** 2) for q in radii if k * q > abs(dx)]
        want = o1.imag + 0.45 * (box[3] - o1.imag)
        ys = [y for y in np.arange(o1.imag + 10.0 + w / 2, box[3] - 10.0 - w / 2, 1.0)
              if all(abs(y - c) > w / 2 + 1.5 for c in cuts)]
        y_text = min(ys, key=lambda y: abs(y - want)) if ys else want
        sheet.text(complex(x_dim - 1.0, y_text), text, 3.5, "DIMENSIONS", "center", "bottom", np.pi / 2)

    def clear_length(r, others, w, length):
        """The shortest line from the circle of ``r`` inward, at least ``length`` mm, whose
        text (``w`` mm long, at the line's middle) crosses none of the gear's other circles
        (``others``, 1 mm kept): at ``length`` a wheel's text lay across its r, rf and rb."""
        cuts = [k * (r - q) for q in others if q < r]
        for extra in np.arange(0.0, 60.0, 1.0):
            mid = 0.5 * (length + extra)
            if all(abs(c - mid) > w / 2 + 1.0 for c in cuts):
                return length + extra
        return length

    def radial(centre, name, r, angles, length=None, others=()):
        """A radius dimension at the first angle [deg] whose ends lie in the area: from the
        centre, or (``length`` mm, centre off the area) from a point on the way to it, long
        enough for its text to clear the other circles. CAD writes a radius's text outside
        the circle: that end must have room for it too."""
        text = f"{name} = {fmt.length(r)}"
        outside = 1.05 * 3.5 * len(plain(text)) + 2.0           # as ezdxf renders it
        lengths = [length] if length is None else [clear_length(r, others, text_width(text, 3.5), length),
                                                     length]     # the longer line where it fits
        for size in lengths:
            for ang in angles:
                d = np.exp(1j * np.radians(ang))
                end = centre + k * r * d
                start = centre if size is None else end - size * d
                if (_inside(start, box, -2.0) and _inside(end, box, -2.0)
                        and _inside(end + outside * d, box, -3.0)):
                    sheet.dimension(start, end, 0.0, r, text, "radius", outside=0)
                    return

    r1 = [(sub("r", "f1"), g1.df / 2), (sub("r", "b1"), g1.db / 2), (sub("r", "1"), g1.d / 2),
          (sub("r", "a1"), g1.da / 2)]
    r2 = [(sub("r", "f2"), g2.df / 2), (sub("r", "b2"), g2.db / 2), (sub("r", "2"), g2.d / 2),
          (sub("r", "a2"), g2.da / 2)]
    if shifted:
        r1.insert(3, (sub("r", "1") + "′", lay.r1w))
        r2.insert(3, (sub("r", "2") + "′", lay.r2w))
    # the pinion: a fan to the lower right of O1, the largest radius the most level
    # (upper right when the pinion's lower half is cut off)
    for i, (name, r) in enumerate(r1[::-1]):
        slot = -9.0 - 12.0 * i
        radial(o1, name, r, [slot, -slot, slot - 6, -slot + 6, 180 - slot, 180 + slot,
                             40.0 - slot, 140.0 + slot])
    # the gear: radii just right of its drawn teeth, pointing at O2
    idx, _, _, rot, step = _teeth(drawing, 2)
    rel = np.angle(np.exp(1j * (rot + step * np.asarray(idx))) / -1j)
    first = np.degrees(np.max(rel) + 0.75 * step)
    spacing = np.degrees(14.0 / (k * g2.d / 2))
    length = None if o2_in and k * g2.da / 2 < 150.0 else 45.0
    for i, (name, r) in enumerate(r2):
        base = -90.0 + first + i * spacing
        tries = [base + j * spacing * len(r2) for j in range(3)]
        radial(o2, name, r, tries + [-180.0 - a for a in tries], length, [q for _, q in r2])


def _table(sheet: Sheet, mm: SpurPair, lay, lab: dict, interference: bool) -> None:
    """The data table in the upper right corner, the notes below it."""
    _, _, x1, y1 = sheet.inner
    g1, g2 = mm.g1, mm.g2
    tx0 = x1 - TABLE_W
    tw = np.tan(mm.alpha_work)
    eps_f = (g1.z * (np.tan(g1.alpha_a) - tw) + g2.z * (np.tan(g2.alpha_a) - tw)) / (2 * np.pi)
    rows = [
        (lab["m"], "m", _num(mm.m, 2), None, "mm"),
        (lab["alpha"], "α", _num(mm.alpha * DEG, 1), None, "°"),
        (lab["ha"], sub("h", "a") + "*", fmt.exact(mm.ha_star), None, "—"),
        (lab["c"], "c*", fmt.exact(mm.c_star), None, "—"),
        (lab["z"], "z", str(g1.z), str(g2.z), "—"),
        (lab["x"], "x", _num(g1.x, 3), _num(g2.x, 3), "—"),
        (lab["d"], "d", _mm(g1.d), _mm(g2.d), "mm"),
    ]
    if abs(lay.r1w - g1.d / 2) > 1e-9 * mm.m:
        rows.append((lab["dw"], "d′", _mm(2 * lay.r1w), _mm(2 * lay.r2w), "mm"))
    rows += [
        (lab["da"], sub("d", "a"), _mm(g1.da), _mm(g2.da), "mm"),
        (lab["df"], sub("d", "f"), _mm(g1.df), _mm(g2.df), "mm"),
        (lab["db"], sub("d", "b"), _mm(g1.db), _mm(g2.db), "mm"),
        (lab["aw"], "a′", _mm(mm.a_work), None, "mm"),
        (lab["alw"], "α′", _num(mm.alpha_work * DEG, 2), None, "°"),
        (lab["pb"], sub("p", "b"), _mm(mm.pb), None, "mm"),
        (lab["b1b2"], sub("B", "1") + sub("B", "2"), _mm(lay.action_length), None, "mm"),
        (lab["eps_g"], sub("B", "1") + sub("B", "2") + "/" + sub("p", "b"), _num(lay.contact_ratio, 3), None, "—"),
        (lab["eps_f"], "ε", _num(eps_f, 3), None, "—"),
    ]

    # v2 = None: one value for the pair, the two gear columns merged
    bottom = table(sheet, tx0, y1, [50.0, 32.0, 35.0, 35.0, 28.0], rows, lab["head"], row_h=7.0,
                   title=lab["table"], margin=1.0, outer=None, inner=0.25)

    notes = [lab["n_drive"], lab["n_teeth"],
             _points(with_subscripts(lab["n_eps"], "p_b", "z_1", "z_2", "α_a1", "α_a2")
                     .format(g=fmt.f(lay.contact_ratio, 3), f=fmt.f(eps_f, 3)))]
    for i, g, xmin in ((1, g1, mm.x_min1), (2, g2, mm.x_min2)):
        if g.x < xmin - 1e-9:
            notes.append(with_subscripts(lab["n_undercut"].format(i=i, z=g.z, x=fmt.minus(fmt.f(g.x, 3)),
                                                              xmin=fmt.minus(fmt.f(xmin, 3))), "x_min"))
    if interference:
        notes.append(_points(lab["n_interf"]))
    ty1 = title_block_box(sheet)[3]
    y = bottom - 9.0
    sheet.text(tx0 + 1j * y, lab["notes"], 5.0, "TEXT", "left", "bottom")
    for i, note in enumerate(notes, start=1):
        for j, chunk in enumerate(_wrap(f"{i}. {note}", TABLE_W - 10.0, 3.5)):
            y -= 6.0
            if y < ty1 + 4.0:
                return
            sheet.text(tx0 + (2.0 if j == 0 else 6.0) + 1j * y, chunk, 3.5, "TEXT", "left", "bottom")


def _wrap(text: str, width: float, height: float) -> list[str]:
    """``text`` broken into lines of at most ``width`` mm (CJK anywhere, Latin at spaces)."""
    lines, current = [], ""
    for token in _tokens(text):
        if current and text_width(current + token, height) > width:
            lines.append(current.rstrip())
            current = token.lstrip()
        else:
            current += token
    if current.strip():
        lines.append(current.rstrip())
    return lines


def _tokens(text: str) -> list[str]:
    out, word = [], ""
    for ch in text:
        if ord(ch) > 0x2E80 and ch not in MARKERS:   # a subscript stays in its word
            if word:
                out.append(word)
                word = ""
            out.append(ch)
        elif ch == " ":
            out.append(word + " ")
            word = ""
        else:
            word += ch
    if word:
        out.append(word)
    return out
