"""The cam drawing sheet (凸轮机构设计图, A2): what a student hands in for the cam.

The sheet is built as a :class:`~.sheet.Sheet` (paper millimetres) and drawn by
:mod:`.sheet_typst` (PDF, PNG) and :mod:`.sheet_dxf` (DXF). It holds, as the graphical
method of 孙桓《机械原理》 (chapter on cam mechanisms) draws them:

* the follower displacement diagram s–δ (φ–δ for an oscillating follower) at stated
  scales μs (μφ) and μδ: the δ axis divided into the programme's segments with their
  angles, every rise and return divided into equal parts numbered 0, 1, 2, … through the
  cycle, the ordinates at the division points thin and the curve bold;
* the cam at a GB length scale (1:1 when it fits) by inversion (反转法): the base circle,
  the offset circle (offset translating follower) or the circle of the pivot's inverted
  positions (oscillating follower), the follower's inverted positions at the division
  points numbered 0′, 1′, 2′, … (measured against the cam's rotation), the roller there,
  the pitch curve (细点画线), the actual profile (粗实线), the follower in its start position,
  the cam centre, ω and the key dimensions;
* the design data, the programme and the displacements at the division points as tables;
* the border and the title block.

The cam's own arrays (``c.grid``: fine grid, SI units) give the curves; the division points
and the cam designed at their exact angles come from the cam stage (``c.drawing``): the sheet
only reads the result.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..core.cam import DWELL, RETURN, RISE, OscillatingFollower
from ..core.motion_laws import LAWS
from ..i18n import N_, tr
from ..stages.cam import Division
from .cam_report import _IMPACT, CONTACT, _segment_name, _Units
from . import fmt
from .labels import LabelTable, pgettext, sheet_point
from .sheet import (
    sub,
    THIN,
    Dimension,
    LabelPlacer,
    boxes_overlap,
    dimension_text_hits,
    segment_hits_box,
    fit_widths,
    table,
    Sheet,
    TitleInfo,
    fit_height,
    frame,
    ground,
    heading,
    length_scale,
    nice_step,
    pin,
    scale_text,
    text_box,
    text_width,
    title_block_box,
)

MM = 1e3
DEG = 180.0 / np.pi
PRIME = "\u2032"          # ′

LABELS = LabelTable({
    "drawing": N_("Disc cam design drawing"),
    "diagram": N_("Follower displacement diagram"),
    "profile": N_("Cam profile (inversion method)"),
    "data": N_("Design data"),
    "programme": pgettext("cam sheet", "Follower programme"),
    "points": N_("Displacements at the division points"),
    "pitch": N_("pitch curve"),
    "actual": N_("actual profile"),
    "point": pgettext("cam sheet", "Point"),
    "cw": N_("clockwise"),
    "ccw": N_("counter-clockwise"),
    "follower": N_("Follower"),
    "rotation": N_("Cam rotation"),
    "speed": N_("Cam speed"),
    "stroke": N_("Stroke"),
    "swing": N_("Max. swing"),
    "r0": N_("Base radius"),
    "rr": N_("Roller radius"),
    "offset": N_("Offset"),
    "a": N_("Centre distance"),
    "L": N_("Arm length"),
    "phi0": N_("Initial arm angle"),
    "alpha_rise": N_("Max. pressure angle, rise"),
    "alpha_return": N_("Max. pressure angle, return"),
    "rho": N_("Min. radius of curvature, pitch"),
    "rho_a": N_("Min. radius of curvature, actual"),
    "rho_flat": N_("Min. radius of curvature"),
    "face": N_("Face width (at least)"),
    "head_data": (N_("Item"), N_("Symbol"), N_("Value"), pgettext("cam sheet", "Requirement")),
    "head_prog": (N_("Segment"), N_("Cam angle"), N_("Span"), N_("Motion law"), N_("Lift"), N_("Impact")),
    "ok": N_("PASS"),
    "fail": N_("FAIL"),
    "right": N_("right"),
    "left": N_("left"),
    "fav": N_("favourable"),
    "unfav": N_("unfavourable"),
    "translating": N_("translating"),
    "oscillating": N_("oscillating"),
    "note": (N_("Notes: 1. Pitch curve by inversion; actual profile = envelope of the roller circles."), N_("2. Lengths in mm, angles in degrees.")),
    "note_flat": (N_("Notes: 1. Profile by inversion: envelope of the inverted face positions."), N_("2. Lengths in mm, angles in degrees.")),
    "note_knife": (N_("Notes: 1. Profile by inversion: path of the inverted knife edge."), N_("2. Lengths in mm, angles in degrees.")),
})

# Scales of the displacement diagram: μδ [°/mm] and μs [mm/mm or °/mm], preferred values.
_MU_DELTA = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0)
# μs (μφ): the preferred 1-2-2.5-5 series; the values above 10 draw the long strokes
# (a 2000 mm stroke at μs = 50 mm/mm is 40 mm high)
_MU_S = (0.05, 0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 2.5, 5.0, 10.0,
         20.0, 25.0, 50.0, 100.0, 200.0, 250.0, 500.0, 1000.0)
ROW = 6.5                  # table row height [mm]
GAP = 7.0                  # vertical gap between the panels of the right column [mm]


# --------------------------------------------------------------------------- division points


def divisions(c) -> list:
    """The division points (stages.cam.Division) the cam stage chose: every rise and
    return in equal parts, the ends of every segment; numbered 0, 1, 2, … from δ = 0."""
    return list(c.drawing.divisions)


def _follower(c):
    """The follower as designed (an automatic offset is in ``c.offset``)."""
    return c.follower if c.follower is not None else c.params.follower


# --------------------------------------------------------------------------- the sheet


def cam_sheet(c, info: TitleInfo, lang: str = "zh") -> Sheet:
    """The A2 cam sheet (凸轮机构设计图) of the cam result ``c`` (stages.cam.CamResult).

    ``info`` fills the title block; an empty ``info.scale`` becomes the profile's scale and
    an empty ``info.drawing`` the sheet's default name. Raises ValueError if the drawing
    does not fit the sheet."""
    lab = LABELS[lang]
    sheet = Sheet("A2")
    x0, y0, x1, y1 = sheet.inner
    tb = title_block_box(sheet)
    divs = divisions(c)
    g = _ProfileGeometry(c, divs)

    # Left: the profile at the largest GB scale (≤ 1:1) that fits beside a displacement
    # diagram of at least 360°/μδ with the second-largest μδ; right: diagram and tables.
    need_right = _DIAGRAM_LEFT + 360.0 / _MU_DELTA[-2] + _DIAGRAM_RIGHT
    box_h = (y1 - y0) - _PROFILE_TOP - _PROFILE_BOTTOM
    n = length_scale(complex(g.width, g.height),
                     complex(x1 - x0 - need_right - _SPLIT_GAP - 2 * g.margin, box_h - 2 * g.margin))
    prof_w = g.width / n + 2 * g.margin
    right_w = x1 - x0 - max(prof_w, _PROFILE_MIN_W) - _SPLIT_GAP
    mu_d = next(m for m in _MU_DELTA if _DIAGRAM_LEFT + 360.0 / m + _DIAGRAM_RIGHT <= right_w)
    right_w = min(right_w, _DIAGRAM_LEFT + 360.0 / mu_d + _DIAGRAM_RIGHT + 30.0)
    split = x1 - right_w
    if info.scale == "":
        info = replace(info, scale=scale_text(n))
    if info.drawing == "":
        info = replace(info, drawing=lab["drawing"])
    frame(sheet, info)
    _profile(sheet, c, g, divs, n, (x0, y0, split - _SPLIT_GAP, y1), lab)
    _right_column(sheet, c, divs, g, mu_d, (split, tb[3] + 5.0, x1, y1), lab, lang)
    return sheet


_DIAGRAM_LEFT = 16.0       # s-axis ticks and label left of the diagram [mm]
_DIAGRAM_RIGHT = 15.0      # δ-axis arrow and label right of 360° [mm]
_SPLIT_GAP = 8.0           # between the profile panel and the right column [mm]
_PROFILE_TOP = 14.0        # heading of the profile panel [mm]
_PROFILE_BOTTOM = 14.0     # notes under the profile [mm]
_PROFILE_MIN_W = 200.0


# --------------------------------------------------------------------------- profile panel


class _ProfileGeometry:
    """Everything of the profile in model millimetres (cam frame = fixed frame at δ = 0)."""

    margin = 12.0          # paper mm around the model extent for labels and dimensions

    def __init__(self, c, divs: list[Division]):
        g = c.grid
        self.c = c
        self.fol = _follower(c)
        self.kind = self.fol.kind
        self.osc = isinstance(self.fol, OscillatingFollower)
        self.sigma = g.rotation
        self.r0 = c.base_radius * MM
        self.rr = g.roller_radius * MM
        self.e = 0.0 if self.osc else c.offset * MM
        self.pitch = g.pitch * MM
        self.actual = actual_profile(c)
        delta = np.array([d.delta for d in divs])
        self.dprof = c.drawing.division_profile                 # the cam at the divisions
        self.rot = np.exp(-1j * self.sigma * delta)            # frame → cam at each division
        self.B = self.dprof.pitch * MM                         # follower point, inverted
        self.B0 = complex(g.follower_point[0]) * MM            # follower point at δ = 0
        self.outer = float(max(np.max(np.abs(self.actual)), np.max(np.abs(self.pitch)) + self.rr))
        self.a = self.L = 0.0
        if self.osc:
            self.a = self.fol.pivot_distance * MM
            self.L = self.fol.arm_length * MM
        self.face = None
        if self.kind == "flat" and c.face_extent is not None:
            self.face = tuple(v * MM for v in c.face_extent)

    def ring(self, n: float = 1.0) -> float:
        """Radius of the division labels (translating) [model mm] at scale 1:n."""
        return self.outer + 7.0 * n

    def stem_top(self, n: float = 1.0) -> float:
        return self.ring(n) + 36.0 * n

    def extents(self, n: float = 1.0) -> tuple[float, float, float, float]:
        if self.osc:
            r = max(self.ring(n), self.a + 7.0 * n)
            return -r, -r, r, r
        r = self.ring(n) + 3.0 * n
        return -r, -r, r, self.stem_top(n)

    @property
    def width(self) -> float:
        x0, _, x1, _ = self.extents()
        return x1 - x0

    @property
    def height(self) -> float:
        _, y0, _, y1 = self.extents()
        return y1 - y0


def actual_profile(c) -> np.ndarray:
    """The actual profile [model mm] as drawn: the cam stage's outline (for a roller, the
    envelope of the roller circles, ``core.cam.roller_envelope``: arcs at the corners of the
    pitch curve, loops cut); a knife edge or flat face as computed."""
    outline = c.outline if c.outline is not None else c.grid.actual
    return np.asarray(outline) * MM


def _largest_gap(angles) -> tuple[float, float]:
    """(centre, width) of the largest empty angular interval between ``angles`` [rad]."""
    a = np.sort(np.mod(np.asarray(angles, dtype=float), 2 * np.pi))
    if len(a) == 0:
        return np.pi / 2, 2 * np.pi
    gaps = np.diff(np.concatenate([a, [a[0] + 2 * np.pi]]))
    j = int(np.argmax(gaps))
    return float(a[j] + gaps[j] / 2), float(gaps[j])


def _clear_radius_angle(view, labels: LabelPlacer, rc: float, r0: float, text: str,
                        taken) -> tuple[float, float]:
    """The angle of r0's radius line and where its text stands along it (a fraction from the
    centre): ``rc`` (the widest gap between the rays where they cross circles inside the cam)
    and the middle if no line crosses the text there; else the nearest angle, clear of
    ``taken`` (ω, the ground symbol, the centre lines) by 3°, with the text as near the
    middle as it can stand (and off the arrow) where none does. The inverted follower axes,
    tangent to the offset circle, sweep across a text in the middle of the line (the 12′
    axis of cam 7-3 through "r0=50.00"), less so nearer the circle. (``rc``, ½) if none."""
    pts = labels._drawn_points()
    p0 = view.p(0)
    length = abs(view.p(r0) - p0)
    room = 1.0 - (0.5 * text_width(text, 3.5) + 4.0) / length    # the text's middle at most

    def hits(a: float, along: float) -> int:
        d = Dimension(p0, view.p(r0 * np.exp(1j * a)), 0.0, r0, text, "radius", height=3.5,
                      outside=0, along=along)
        return dimension_text_hits(d, pts)

    if hits(rc, 0.5) == 0:
        return rc, 0.5
    taken = np.asarray(taken, dtype=float)
    alongs = [f for f in (0.5, 0.58, 0.66, 0.74) if f <= max(room, 0.5)]
    for step in range(1, 90):
        for a in (rc + np.radians(2.0 * step), rc - np.radians(2.0 * step)):
            off = np.abs((taken - a + np.pi) % (2 * np.pi) - np.pi)
            if off.min() < np.radians(3.0):
                continue
            for f in alongs:
                if hits(a, f) == 0:
                    return float(a), f
    return rc, 0.5


def _crossings(segments, radius: float) -> list[float]:
    """Angles where the line segments (z0, z1) cross the circle |z| = radius."""
    out = []
    for z0, z1 in segments:
        d = z1 - z0
        A = abs(d) ** 2
        if A < 1e-18:
            continue
        B = 2 * (z0.real * d.real + z0.imag * d.imag)
        C = abs(z0) ** 2 - radius ** 2
        disc = B * B - 4 * A * C
        if disc < 0:
            continue
        for t in ((-B - np.sqrt(disc)) / (2 * A), (-B + np.sqrt(disc)) / (2 * A)):
            if 0 <= t <= 1:
                out.append(float(np.angle(z0 + t * d)))
    return out


def _profile(sheet: Sheet, c, g: _ProfileGeometry, divs, n: float, box, lab):
    bx0, by0, bx1, by1 = box
    k = 1.0 / n                                   # paper mm per model mm
    ex0, ey0, ex1, ey1 = g.extents(n)
    cx = (bx0 + bx1) / 2 - k * (ex0 + ex1) / 2
    top, bottom = by1 - _PROFILE_TOP, by0 + _PROFILE_BOTTOM
    cy = (top + bottom) / 2 - k * (ey0 + ey1) / 2
    view = sheet.view(complex(cx, cy), k)
    P = view.p
    O = P(0)
    labels = LabelPlacer(sheet, pad=0.6)
    heading(sheet, complex((bx0 + bx1) / 2, by1 - 10.0), f"{lab['profile']}  {scale_text(n)}", 5.0)

    # -- the inversion: the follower's positions at the division points (thin)
    ring = g.ring(n)
    rays = []                                     # model segments, thin
    label_pos = []                                # model points of the labels 0′, 1′, …
    for rot, B in zip(g.rot, g.B):
        if g.osc:
            A = g.a * rot
            rays += [(0j, A), (A, B)]
            label_pos.append(A * (1 + 5.0 * n / g.a))
        else:
            K = g.e * rot                         # foot of the inverted axis on the offset circle
            u = 1j * rot                          # direction of the inverted follower axis
            t_end = np.sqrt(max(ring ** 2 - g.e ** 2, 0.0))
            if abs(g.e) > 1e-9:
                rays.append((0j, K))
            rays.append((K, K + t_end * u))
            label_pos.append(K + (t_end + 3.5 * n) * u)
    for z0, z1 in rays:
        view.line(z0, z1, "CONSTRUCTION")
    for d, B, rot in zip(divs, g.B, g.rot):
        if g.osc:
            view.circle(g.a * rot, 0.8 * n, "CONSTRUCTION")
        if g.kind == "roller":
            if d.number != 0:
                view.circle(B, g.rr, "CONSTRUCTION")
        elif g.kind == "flat":
            _flat_face_inverted(view, g, d, rot)
        else:
            view.circle(B, 0.6 * n, "CONSTRUCTION")

    # -- centre lines, circles, curves
    lim = (g.outer + 6.0 * n) if g.osc else ring + 4.0 * n
    view.line(-lim, (g.a + 12.0 * n) if g.osc else lim, "CENTER")
    view.line(-1j * lim, 1j * lim, "CENTER")
    view.circle(0, g.r0, "CONSTRUCTION")
    if not g.osc and abs(g.e) > 1e-9:
        view.circle(0, abs(g.e), "CONSTRUCTION")
    if g.osc:
        view.circle(0, g.a, "CENTER")
        view.line(g.a - 10j * n, g.a + 10j * n, "CENTER")
    if g.kind == "roller":
        view.polyline(g.pitch, "CENTER", closed=True, tolerance=None)     # every point: the
    view.polyline(g.actual, "OUTLINE", closed=True, tolerance=None)       # cam's geometry

    # -- division labels 0′, 1′, …; 0′ beside the follower, which stands on its own ray
    gap_c, _ = _largest_gap([np.angle(z) for z in label_pos])
    for d, z in zip(divs, label_pos):
        p = P(z)
        if d.number == 0 and g.osc:                          # beside the pivot's frame
            p = P(g.a * g.rot[0]) + complex(8.5, -4.0)
        elif d.number == 0:
            u = np.exp(1j * np.angle(z))
            side = np.sign(np.sin(gap_c - np.angle(z))) or 1.0
            p = p + side * 1j * u * 3.2 - u * 1.5
        elif min(abs((np.angle(z) - a + np.pi) % (2 * np.pi) - np.pi) for a in np.arange(4) * np.pi / 2) < 0.03 \
                and abs(z) < lim:
            # a ray along a centre line, which runs on past the label: the label beside it
            p = p + 1j * np.exp(1j * np.angle(z)) * (0.5 * text_width(f"{d.number}{PRIME}", 3.5) + 1.2)
        labels.text(p, f"{d.number}{PRIME}", 3.5, "center", "middle")

    # -- the follower in its start position, cam centre
    outside = _follower_start(sheet, view, g, n, labels)
    ground(view, 0, 7.0, -np.pi / 2)
    # between the rays, else on a leader out of their fan (not over the frame's hatching)
    labels.place(O, sheet_point("O"), 3.5, prefer=-1 - 1j, gap=2.5, leader=True)

    # -- ω and r0 inside the cam, where no construction line passes: ω in the first part
    # of the widest free sector, r0 in the widest sector left (clear of the centre lines)
    down = list(np.radians(np.arange(-120, -55, 5)))            # the ground symbol
    axes = [a * np.pi / 2 for a in range(4)]
    best = None
    r_in = float(np.min(np.abs(g.actual)))
    for f in np.linspace(0.3, 0.7, 9):
        if f * g.r0 > r_in - 3.0 * n:
            continue
        c_, w_ = _largest_gap(_crossings(rays, f * g.r0) + down + axes)
        if best is None or min(w_, np.radians(90)) * f > best[0] + 1e-9:
            best = (min(w_, np.radians(90)) * f, f * g.r0, c_, w_)
    if best is None:                                            # a thin cam: no room inside
        best = (0.0, 0.3 * g.r0) + _largest_gap(_crossings(rays, 0.3 * g.r0) + down + axes)
    _, r_w, wc, ww = best
    span = float(np.clip(0.45 * ww, 14.0 * n / r_w, np.radians(60)))
    w_mid = wc - ww / 2 + 0.1 * ww + span / 2
    _omega(sheet, view, r_w, w_mid, span / 2, g.sigma)
    taken = list(np.linspace(w_mid - span / 2 - 0.12, w_mid + span / 2 + 0.12, 12)) + down
    taken += [a + d for a in np.arange(4) * np.pi / 2 for d in (-0.12, 0.0, 0.12)]
    avoid = list(taken)                       # ω, the ground symbol, the centre lines
    if g.kind == "roller" and abs(g.B0) > g.rr:   # and the roller at the start, on r0's circle
        half = float(np.arcsin(g.rr / abs(g.B0))) + 0.05
        avoid += list(np.angle(g.B0) + np.linspace(-half, half, 9))
    for f in np.linspace(0.3, 1.0, 8):
        taken += _crossings(rays, f * g.r0)
    rc, _ = _largest_gap(taken)
    text = f"{sub('r', '0')}={fmt.length(g.r0)}"
    rc, along = _clear_radius_angle(view, labels, rc, g.r0, text, avoid)
    view.dimension(0, g.r0 * np.exp(1j * rc), 0.0, text=text, kind="radius", height=3.5, outside=0,
                   along=along)
    if g.kind == "roller":
        _roller_dimension(sheet, view, g, n, gap_c, labels)

    # -- names of the curves on radial leaders into the free sector outside the cam
    out_angles = [np.angle(z) for z in label_pos] + outside
    out_angles += [a * np.pi / 2 + d for a in range(4) for d in (-0.1, 0.0, 0.1)]
    sc, sw = _largest_gap(out_angles)
    _curve_leaders(sheet, view, g, n, sc, sw, labels, box, lab)

    # -- note under the drawing
    key = {"roller": "note", "flat": "note_flat"}.get(g.kind, "note_knife")
    for i, line in enumerate(lab[key]):
        sheet.text(complex(bx0 + 4.0, by0 + 8.5 - 5.0 * i), line,
                   fit_height(line, bx1 - bx0 - 8.0, 3.5), "TEXT", "left", "bottom")


def _flat_face_inverted(view, g: _ProfileGeometry, d: Division, rot) -> None:
    """A flat face at an inverted position (thin), over the face extent plus a margin."""
    fp = complex(g.dprof.follower_point[d.number]) * MM       # foot of the face, frame
    if g.osc:
        A = complex(g.a)
        u = (fp - A) / abs(fp - A) if abs(fp - A) > 1e-9 else -1.0
        lo, hi = g.face if g.face else (0.0, g.a)
        z0, z1 = A + u * max(lo - 5.0, 0.0), A + u * (hi + 5.0)
    else:
        lo, hi = g.face if g.face else (-g.r0, g.r0)
        z0 = complex(g.e + lo - 5.0, fp.imag)
        z1 = complex(g.e + hi + 5.0, fp.imag)
    view.line(z0 * rot, z1 * rot, "CONSTRUCTION")


def _omega(sheet, view, radius, centre, half, sigma):
    """The rotation arrow ω: an arc of ``2·half`` around ``centre`` with a head in the sense σ."""
    a0, a1 = centre - half, centre + half
    p = view.p(0)
    r = radius * view.scale
    head = 3.0
    dh = head / r
    if sigma > 0:
        sheet.arc(p, r, a0, a1 - dh, "CONSTRUCTION", 0.35)
        tip_a, tang = a1, 1j * np.exp(1j * a1)
    else:
        sheet.arc(p, r, a0 + dh, a1, "CONSTRUCTION", 0.35)
        tip_a, tang = a0, -1j * np.exp(1j * a0)
    tip = p + r * np.exp(1j * tip_a)
    base = tip - head * tang
    w = 0.35 * head
    sheet.fill([tip, base + 1j * tang * w, base - 1j * tang * w], "CONSTRUCTION")
    sheet.text(p + (r - 4.5) * np.exp(1j * centre), "ω", 5.0, "TEXT", "center", "middle")


def _follower_start(sheet, view, g: _ProfileGeometry, n, labels: LabelPlacer) -> list[float]:
    """Draw the follower at δ = 0 with its frame and dimensions; return the angles (from O)
    that it and its dimensions take outside the cam."""
    B0 = g.B0
    P = view.p
    k = 1.0 / n
    angles: list[float] = []
    if g.osc:
        A = complex(g.a)
        ground(view, A, 7.0, -np.pi / 2)
        if g.kind == "flat":
            u = (B0 - A) / abs(B0 - A)
            _, hi = g.face if g.face else (0.0, g.a)
            view.line(A, A + u * (hi + 8.0 * n), "OUTLINE")
        else:
            u = (B0 - A) / abs(B0 - A)
            view.line(A + u * 1.2 * n, B0 - u * 1.2 * n, "OUTLINE")
            pin(view, A)
            pin(view, B0)
            if g.kind == "roller":
                view.circle(B0, g.rr, "OUTLINE")
            # arm length L beside the arm, away from the cam centre
            side = -1.0 if np.imag(np.conj(u) * (0 - A)) > 0 else 1.0
            z0, z1 = (A, B0) if u.real >= 0 else (B0, A)        # text reads left to right
            # where no line crosses its text (the rays to the arm's positions fan out across
            # it): the offset nearest, this side first, the text in the middle or moved
            # along the line
            text = f"L={fmt.length(g.L)}"
            sign = side * (1 if u.real >= 0 else -1)
            pts = labels._drawn_points()
            tries = [(sign * o, f) for o in (7.0, 10.0, 13.0) for f in (0.5, 0.4, 0.6, 0.3, 0.7)]
            tries += [(-sign * o, f) for o, f in tries]
            off, along = next((t for t in tries if dimension_text_hits(
                Dimension(P(z0), P(z1), t[0], g.L, text, height=3.5, along=t[1]), pts) == 0),
                tries[0])
            view.dimension(z0, z1, off, text=text, height=3.5, along=along)
        # centre distance a under the drawing; extension lines start below the pivots' frames
        ink = np.concatenate([g.actual, g.pitch, g.B - 1j * g.rr, [-g.r0 * 1j]])
        near = ink[(ink.real > -5.0 * n) & (ink.real < g.a + 5.0 * n)]
        y = -float(np.min(near.imag)) + 10.0 * n
        drop = 12.0 * n
        # its text where no line crosses it (the circle of the pivot's inverted positions
        # runs through the middle of the line when the cam is large beside a: the lock-beam's
        # bending cam), moved along the line
        text = f"a={fmt.length(g.a)}"
        pts = labels._drawn_points()
        along = next((f for f in (0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8) if dimension_text_hits(
            Dimension(P(-1j * drop), P(A - 1j * drop), -(y - drop) * k, g.a, text, height=3.5,
                      along=f), pts) == 0), 0.5)
        view.dimension(-1j * drop, A - 1j * drop, -(y - drop) * k, text=text,
                       height=3.5, measurement=g.a, along=along)
        for z in np.linspace(0, g.a, 9):
            angles.append(float(np.angle(z - 1j * y)))
        # the pivot's name once its frame, arm and the extension line of a are drawn
        # beside the pivot, away from the fan of the rays to the arm's positions (which
        # leave the pivot towards the cam): the nearest spot no line crosses, on a leader
        # only where there is none (the lock-beam's bending cam: "A" stood on a 20 mm
        # leader inside the fan)
        away = -(0 - A) / abs(A) + 0.6j if abs(A) > 0 else -1 + 0.6j
        if labels.place_breaking(P(A), sheet_point("A"), 3.5, prefer=complex(away.real, abs(away.imag)),
                                 gaps=(1.5, 2.5, 3.5, 4.5, 6.0, 8.0)) is None:
            labels.place(P(A), sheet_point("A"), 3.5, prefer=-1 + 0.6j, gap=2.5, leader=True)
        angles += [float(np.angle(A + 1j * t)) for t in (-20 * n, 0.0, 20 * n)]
        return angles
    # translating: stem along x = e, guide near its top
    top = g.stem_top(n)
    x = g.e
    if g.kind == "roller":
        view.circle(B0, g.rr, "OUTLINE")
        pin(view, B0)
        view.line(B0 + 1.2j * n, x + 1j * top, "OUTLINE")
    elif g.kind == "knife":
        view.line(B0, x + 1j * top, "OUTLINE")
        view.polyline([B0 + complex(-1.8, 5.0) * n, B0, B0 + complex(1.8, 5.0) * n], "OUTLINE")
    else:
        lo, hi = g.face if g.face else (-g.r0 / 2, g.r0 / 2)
        view.line(complex(x + lo - 5.0, B0.imag), complex(x + hi + 5.0, B0.imag), "OUTLINE")
        view.line(complex(x, B0.imag), x + 1j * top, "OUTLINE")
    yc = top - 13.0 * n
    half = 7.0 * n
    for side in (-1, 1):                           # guide: hatched walls either side of the stem
        xw = x + side * 2.2 * n
        view.line(xw + 1j * (yc - half), xw + 1j * (yc + half), "OUTLINE", 0.5)
        for t in np.linspace(-half, half, 5):
            q = P(xw + 1j * (yc + t))
            sheet.line(q, q + complex(side * 2.2, 2.2), "CONSTRUCTION")
    labels.segments.append((P(complex(x, g.outer)), P(x + 1j * top)))
    labels.boxes.append((P(x).real - 7.0, P(1j * (yc - half)).imag, P(x).real + 7.0, P(1j * top).imag))
    for t in np.linspace(g.ring(n) - 6.0 * n, top, 6):
        angles.append(float(np.angle(complex(x, t))))
    if abs(x) > 1e-9:                               # offset e above the labels
        y = g.ring(n) + 8.0 * n
        view.line(0, 1j * (y + 3.0 * n), "CENTER")
        z0, z1 = (1j * y, x + 1j * y) if x > 0 else (x + 1j * y, 1j * y)
        text = f"e={fmt.length(abs(x))}"
        # a text too long for e goes beyond the centre line, away from the stem
        view.dimension(z0, z1, 0.0, text=text, height=3.5, outside=-1 if x > 0 else 1)
        room = text_width(text, 3.5) + 3.0
        labels.boxes.append((min(P(0).real, P(x).real) - (room if x > 0 else 6.0), P(1j * y).imag - 1.0,
                             max(P(0).real, P(x).real) + (6.0 if x > 0 else room), P(1j * y).imag + 5.5))
        angles += [float(np.angle(1j * y)), float(np.angle(x + 1j * y))]
    return angles


def _roller_dimension(sheet, view, g: _ProfileGeometry, n, gap_c, labels: LabelPlacer):
    """r_r on the start roller as a small-radius dimension (GB/T 4458.4): the arrow from
    outside onto the circle, the value on a shoulder; in the widest free direction from
    the roller centre (away from the stem or arm, the cam and the neighbouring rollers)."""
    B0 = g.B0
    P = view.p
    around = [np.angle(-B0)]                                   # the cam
    if len(g.B) > 2:
        around += [np.angle(g.B[1] - B0), np.angle(g.B[-1] - B0)]
    if g.osc:
        u = (B0 - g.a) / abs(B0 - g.a)                          # as in _follower_start
        side = -1.0 if np.imag(np.conj(u) * (0 - complex(g.a))) > 0 else 1.0
        around += [np.angle(-u), np.angle(1j * u * side)]       # arm, dimension L
    else:
        around += [np.pi / 2, -np.pi / 2]                       # stem, axis
    text = f"{sub('r', 'r')}={fmt.length(g.rr)}"
    h = 3.5
    w = text_width(text, h)
    drawn = labels._drawn_points()
    best = None
    for c_ in np.radians(np.arange(0, 360, 5)):
        clear = min(abs((c_ - a + np.pi) % (2 * np.pi) - np.pi) for a in around)
        u = np.exp(1j * c_)
        for k, reach in enumerate((7.0, 12.0, 18.0)):
            tip = P(B0 + g.rr * u)
            tail = tip + reach * u
            sgn = 1.0 if u.real >= -1e-9 else -1.0
            x0 = tail.real + (0.5 if sgn > 0 else -0.5 - w)
            box = (x0, tail.imag + 0.8, x0 + w, tail.imag + 0.8 + h)
            # the text clear of the lines drawn (the pitch curve, the rays, the rollers) and
            # of the labels; then the widest free direction, the side of the free sector
            # (the curve names go there, but further out), the shorter arrow
            hits = labels.crossed(box, drawn) + sum(1 for b in labels.boxes if boxes_overlap(box, b))
            score = -10.0 * hits + clear + 0.05 * np.cos(c_ - gap_c) - 0.3 * k
            if best is None or score > best[0]:
                best = (score, c_, reach)
    u = np.exp(1j * best[1])
    tip = P(B0 + g.rr * u)
    tail = tip + best[2] * u
    sgn = 1.0 if u.real >= -1e-9 else -1.0
    sheet.arrow(tail, tip, "DIMENSIONS", head=3.0, weight=THIN)
    sheet.line(tail, tail + sgn * (w + 1.0), "DIMENSIONS")
    labels.text(tail + sgn * 0.5 + 0.8j, text, h, "left" if sgn > 0 else "right", "bottom",
                layer="DIMENSIONS")
    labels.segments += [(tip, tail), (tail, tail + sgn * (w + 1.0))]


def _curve_leaders(sheet, view, g: _ProfileGeometry, n, sc, sw, labels: LabelPlacer, box, lab):
    """'实际廓线' and '理论廓线' on radial leaders in the free sector (centre ``sc``,
    width ``sw``) outside the cam; a name that finds no free place is left out."""
    k = 1.0 / n
    O = view.p(0)
    items = [("actual", g.actual)]
    if g.kind == "roller":
        items.append(("pitch", g.pitch))
    m = len(items)
    spread = min(sw * 0.55 / max(m - 1, 1), np.radians(14))
    angles = sc + (np.arange(m) - (m - 1) / 2) * spread
    bx0, by0, bx1, by1 = box
    for (key, curve), ang in zip(items, angles):
        u = np.exp(1j * ang)
        target = curve[int(np.argmin(np.abs(np.angle(curve * np.conj(u)))))]
        t = view.p(target)
        text = lab[key]
        w = text_width(text, 3.5)
        sgn = np.sign(np.cos(ang)) if abs(np.cos(ang)) > 0.15 else np.sign(ang - sc) or 1.0
        for extra in np.arange(0.0, 40.0, 1.5):
            elbow = O + (g.outer * k + 6.0 + extra) * u
            end = elbow + sgn * w
            tb = (min(elbow.real, end.real), elbow.imag + 0.8, max(elbow.real, end.real), elbow.imag + 4.3)
            if tb[0] < bx0 + 2 or tb[2] > bx1 - 2 or tb[1] < by0 + _PROFILE_BOTTOM or tb[3] > by1 - _PROFILE_TOP:
                break
            leader = (t, elbow)
            if labels.free(tb) and not any(segment_hits_box(t, elbow, b, 0.3) for b in labels.boxes):
                sheet.line(t, elbow, "CONSTRUCTION")
                sheet.circle(t, 0.5, "CONSTRUCTION")
                sheet.line(elbow, end, "CONSTRUCTION")
                sheet.text(elbow + 0.8j, text, 3.5, "TEXT", "left" if sgn > 0 else "right", "bottom")
                labels.boxes.append(tb)
                labels.segments += [leader, (elbow, end)]
                break


# --------------------------------------------------------------------------- displacement diagram


def _mu_s(stroke_display: float) -> float:
    """μs (μφ): the largest preferred value that draws the stroke at least 30 mm high."""
    ok = [m for m in _MU_S if stroke_display / m >= 30.0 - 1e-9]
    return max(ok) if ok else _MU_S[0]


_NAME_ROW = 4.5            # a segment name's row under the next one up [mm]


def _name_rows(names) -> list[int]:
    """The row (0 under the segment dimensions, 1, 2, … lower) of each segment name
    (x middle, text, height, room): a name that fits its segment stays in row 0; one wider
    than its segment (a short dwell: "远休止" under 6°) goes in the first row where it keeps
    the word space (0.6 of the height, ISO 3098-1) from the names there."""
    rows = [0 if text_width(t, h) <= room + 1e-9 else -1 for _x, t, h, room in names]
    placed = {0: [text_box(complex(x, 0.0), t, h, "center", "top")
                  for (x, t, h, _r), row in zip(names, rows) if row == 0]}
    for k, (x, t, h, _room) in enumerate(names):
        if rows[k] == 0:
            continue
        box = text_box(complex(x, 0.0), t, h, "center", "top")
        row = 0
        while any(box[0] < b[2] + 0.6 * h and b[0] < box[2] + 0.6 * h
                  for b in placed.get(row, [])):
            row += 1
        rows[k] = row
        placed.setdefault(row, []).append(box)
    return rows


def _diagram(sheet, c, divs, mu_d, mu_s, xo, ytop, lab, lang) -> float:
    """The s–δ (φ–δ) diagram with its origin at x = ``xo`` under ``ytop``; return the
    lowest y it takes."""
    u = _Units(c)
    prog = c.params.programme
    stroke = prog.stroke * u.s_scale
    H = stroke / mu_s
    W = 360.0 / mu_d
    heading(sheet, complex(xo + W / 2, ytop - 7.0), f"{lab['diagram']}  {u.s_sym}–δ", 5.0)
    yo = ytop - 12.0 - 9.0 - H
    O = complex(xo, yo)

    def P(delta_deg, s_disp):
        z = O + np.asarray(delta_deg, dtype=float) / mu_d + 1j * np.asarray(s_disp, dtype=float) / mu_s
        return complex(z) if np.ndim(z) == 0 else z

    sheet.arrow(O, O + W + 8.0, "OUTLINE", head=3.0, weight=0.35)
    sheet.arrow(O, O + 1j * (H + 8.0), "OUTLINE", head=3.0, weight=0.35)
    sheet.text(O + W + 9.0, "δ/(°)", 3.5, "TEXT", "left", "middle")
    unit = "(°)" if u.osc else "mm"
    sheet.text(O + 1j * (H + 9.0) - 1.5, f"{u.s_sym}/{unit}", 3.5, "TEXT", "right", "bottom")
    step = nice_step(stroke, 3)
    for v in np.arange(0.0, stroke + 1e-9, step):
        p = P(0, v)
        sheet.line(p, p - 1.5, "OUTLINE", 0.35)
        sheet.text(p - 2.5, fmt.minus(fmt.exact(v)), 2.5, "TEXT", "right", "middle")
    sheet.line(P(0, stroke), P(360, stroke), "HIDDEN")

    # ordinates at the division points (thin), numbered under the axis
    for d in divs:
        dd = d.delta * DEG
        sv = d.s * u.s_scale
        if sv / mu_s > 1e-6:
            sheet.line(P(dd, 0), P(dd, sv), "CONSTRUCTION")
        sheet.text(P(dd, 0) - 1.2j, str(d.number), 2.5, "TEXT", "center", "top")
    sheet.line(P(360, 0), P(360, stroke), "CONSTRUCTION")
    # the curve, bold, with both one-sided values at the segment ends
    dg = c.drawing.diagram_delta
    sg = c.drawing.diagram_s * u.s_scale
    sheet.polyline(P(dg * DEG, sg), "OUTLINE")

    # segment angles (dimensions) and names under the axis
    bounds = [float(prog.starts[i] * DEG) for i in range(len(prog.segments))] + [360.0]
    yd = yo - 5.0
    names = []
    for i in range(len(prog.segments)):
        pa, pb = P(bounds[i], 0).real, P(bounds[i + 1], 0).real
        name = _segment_name(c, i, lang)
        names.append(((pa + pb) / 2, name, fit_height(name, pb - pa - 1.0, 3.5), pb - pa - 1.0))
    rows = _name_rows(names)
    for i in range(len(prog.segments)):
        a, b = bounds[i], bounds[i + 1]
        pa, pb = P(a, 0).real, P(b, 0).real
        span_txt = f"{fmt.exact(b - a, decimals=2)}°"
        h = 3.5 if text_width(span_txt, 3.5) + 6.0 <= pb - pa else 2.5
        sheet.dimension(complex(pa, yd), complex(pb, yd), -6.0, b - a, span_txt, "aligned", h)
        x, name, hn, _room = names[i]
        sheet.text(complex(x, yd - 8.0 - _NAME_ROW * rows[i]), name, hn, "TEXT", "center", "top")
    mu_sym = sub("μ", "φ") if u.osc else sub("μ", "s")
    scale_txt = (f"{mu_sym} = {fmt.exact(mu_s)} {'(°)/mm' if u.osc else 'mm/mm'}    "
                 f"{sub('μ', 'δ')} = {fmt.exact(mu_d)} (°)/mm")
    y_scale = yd - 8.0 - 3.5 - 3.5 - _NAME_ROW * max(rows)
    sheet.text(complex(xo, y_scale), scale_txt, 3.5, "TEXT", "left", "top")
    return y_scale - 3.5


# --------------------------------------------------------------------------- tables


def _right_column(sheet, c, divs, g: _ProfileGeometry, mu_d, box, lab, lang):
    """Diagram and tables between y = box[1] and box[3]: the diagram as tall as the space
    allows (within 30 … 80 mm), then taller rows and wider gaps."""
    x0, ylim, x1, ytop = box
    u = _Units(c)
    stroke = c.params.programme.stroke * u.s_scale
    mu0 = _mu_s(stroke)
    avail = ytop - ylim

    def height(mu_s, row, gap):
        scratch = Sheet(sheet.size)
        return ytop - _right_draw(scratch, c, divs, g, mu_d, mu_s, row, gap, box, lab, lang)

    mu_s, row, gap = mu0, ROW, GAP
    for m in sorted((m for m in _MU_S if m < mu0 and stroke / m <= 60.0 + 1e-9), reverse=True):
        if height(m, row, gap) <= avail - 20.0:
            mu_s = m
    for r in (7.5, 7.0):
        if height(mu_s, r, gap) <= avail - 10.0:
            row = r
            break
    spare = avail - height(mu_s, row, gap)
    if spare < 0:
        # still too tall: a larger μs from the series (a lower diagram, at least 15 mm high)
        for m in (m for m in _MU_S if m > mu_s and stroke / m >= 15.0 - 1e-9):
            mu_s, row = m, ROW
            spare = avail - height(mu_s, row, gap)
            if spare >= 0:
                break
    if spare < 0:
        raise ValueError(f"the cam sheet's right column is {-spare:.1f} mm too tall")
    gap = min(GAP + spare / 4.0, 16.0)
    _right_draw(sheet, c, divs, g, mu_d, mu_s, row, gap, box, lab, lang)


def _right_draw(sheet, c, divs, g, mu_d, mu_s, row, gap, box, lab, lang) -> float:
    x0, ylim, x1, ytop = box
    xo = x0 + _DIAGRAM_LEFT
    W = 360.0 / mu_d
    y = _diagram(sheet, c, divs, mu_d, mu_s, xo, ytop, lab, lang) - gap
    width = min(x1 - x0 - 4.0, 255.0)
    xl = min(max(xo + W / 2 - width / 2, x0 + 2.0), x1 - 2.0 - width)
    xm = xl + width / 2
    u = _Units(c)
    hsize = 5.0

    # 1. displacements at the division points (horizontal, wrapped when long)
    heading(sheet, complex(xm, y - 5.0), lab["points"], hsize)
    y -= 7.5
    first = 22.0
    per_row = max(1, min(len(divs), int((width - first) // 12.0)))
    per_row = int(np.ceil(len(divs) / np.ceil(len(divs) / per_row)))     # balanced rows
    colw = min(16.0, (width - first) / per_row)
    twidth = first + colw * per_row
    tx = xm - twidth / 2
    for i in range(0, len(divs), per_row):
        chunk = divs[i:i + per_row]
        rows = [[lab["point"]] + [f"{d.number}" for d in chunk],
                ["δ/(°)"] + [fmt.exact(d.delta * DEG, decimals=2) for d in chunk],
                [f"{u.s_sym}/{'(°)' if u.osc else 'mm'}"] + [fmt.minus(fmt.f(d.s * u.s_scale, 2)) for d in chunk]]
        y = table(sheet, tx, y, [first] + [colw] * len(chunk), rows, row_h=row) - 2.0
    y -= gap - 2.0

    # 2. the programme
    heading(sheet, complex(xm, y - 5.0), lab["programme"], hsize)
    y -= 7.5
    prog = c.params.programme
    rows = []
    for i, seg in enumerate(prog.segments):
        a, b = prog.starts[i] * DEG, (prog.starts[i] + prog.spans[i]) * DEG
        law = "—" if seg.law is None else LAWS[seg.law].name(lang)
        lift = "—" if seg.kind == DWELL else (
            f"{fmt.f(abs(prog.lifts[i]) * u.s_scale, 2) if u.osc else fmt.length(abs(prog.lifts[i]) * u.s_scale)}"
            f"{'°' if u.osc else ' mm'}")
        impact = "—" if seg.kind == DWELL else _IMPACT[lang][c.segments[i].impact]
        rows.append([_segment_name(c, i, lang), f"{fmt.exact(a, decimals=2)}°–{fmt.exact(b, decimals=2)}°",
                     f"{fmt.exact(b - a, decimals=2)}°", law, lift, impact])
    y = table(sheet, xl, y, fit_widths([20, 30, 18, 78, 24, 24], width), rows, lab["head_prog"],
               row_h=row) - gap

    # 3. design data
    heading(sheet, complex(xm, y - 5.0), lab["data"], hsize)
    y -= 7.5
    y = table(sheet, xl, y, fit_widths([64, 20, 76, 60], width), _data_rows(c, g, lab, lang),
               lab["head_data"], ["left", "center", "center", "center"], row_h=row)
    return y


def _data_rows(c, g: _ProfileGeometry, lab, lang):
    p = c.params
    fol = g.fol
    _ = tr(lang)
    motion = lab["oscillating" if g.osc else "translating"]
    contact = CONTACT[lang][fol.kind]
    if g.osc:
        name = _("{motion} {contact} follower", motion=motion, contact=contact)
    elif abs(g.e) > 1e-9:
        name = _("offset {motion} {contact} follower", motion=motion, contact=contact)
    else:
        name = _("centred {motion} {contact} follower", motion=motion, contact=contact)
    rot = lab["ccw"] if p.rotation > 0 else lab["cw"]
    if p.speed_rpm:
        rot += _(", n = {n} rpm", n=fmt.rpm(p.speed_rpm))
    rows = [[lab["follower"], "—", name, ""], [lab["rotation"], "ω", rot, ""]]
    prog = p.programme
    if g.osc:
        rows.append([lab["swing"], sub("φ", "max"), f"{fmt.f(prog.stroke * DEG, 2)}°", ""])
    else:
        rows.append([lab["stroke"], "h", f"{fmt.length(prog.stroke * MM)} mm", ""])
    rows.append([lab["r0"], sub("r", "0"), f"{fmt.length(g.r0)} mm", ""])
    if fol.kind == "roller":
        rows.append([lab["rr"], sub("r", "r"), f"{fmt.length(g.rr)} mm", ""])
    if g.osc:
        rows.append([lab["a"], "a", f"{fmt.length(g.a)} mm", ""])
        if fol.kind != "flat":
            rows.append([lab["L"], "L", f"{fmt.length(g.L)} mm", ""])
        rows.append([lab["phi0"], sub("φ", "0"), f"{fmt.minus(fmt.f(c.grid.initial_angle * DEG, 2))}°", ""])
    elif fol.kind != "flat":
        value = f"{fmt.length(abs(g.e))} mm"
        if abs(g.e) > 1e-9:
            fav = c.drawing.offset_favourable
            side = lab["right"] if g.e > 0 else lab["left"]
            kind = lab["fav" if fav else "unfav"]
            value += _(" ({side}, {kind})", side=side, kind=kind)
        rows.append([lab["offset"], "e", value, ""])
    if fol.kind != "flat":
        for kind, key, sym, lim_sym in ((RISE, "alpha_rise", sub("α", "max"), "[α]"),
                                        (RETURN, "alpha_return", sub("α′", "max"), "[α′]")):
            segs = [s for s in c.segments if s.kind == kind]
            if not segs:
                continue
            worst = max(segs, key=lambda s: s.max_pressure_angle)
            ok = all(s.ok for s in segs)
            rows.append([lab[key], sym, f"{fmt.f(worst.max_pressure_angle * DEG, 2)}°",
                         f"≤ {lim_sym} = {fmt.exact(worst.limit * DEG, decimals=2)}°  "
                         f"{lab['ok'] if ok else lab['fail']}"])
    # the profile's curvature checks as the cam stage judged them (cam.curvature_checks)
    judged = {chk.key: chk for chk in c.curvature_checks}
    if fol.kind == "roller" and "pitch_curvature" in judged:
        rp, ra = judged["pitch_curvature"], judged["actual_curvature"]
        rows.append([lab["rho"], sub("ρ", "min"), f"{fmt.minus(fmt.length(rp.value * MM))} mm",
                     f"> {sub('r', 'r')} = {fmt.length(g.rr)} mm  {lab['ok'] if rp.ok else lab['fail']}"])
        rows.append([lab["rho_a"], sub("ρ", "a,min"), f"{fmt.minus(fmt.length(ra.value * MM))} mm",
                     f"≥ {fmt.length(ra.limit * MM)} mm  {lab['ok'] if ra.ok else lab['fail']}"])
    elif fol.kind == "flat" and "convex" in judged:
        rho = judged["convex"]
        rows.append([lab["rho_flat"], sub("ρ", "min"), f"{fmt.minus(fmt.length(rho.value * MM))} mm",
                     f"> 0  {lab['ok'] if rho.ok else lab['fail']}"])
        if c.face_extent is not None and not g.osc:
            lo, hi = c.face_extent
            rows.append([lab["face"], "b", f"{fmt.length(2 * max(abs(lo), abs(hi)) * MM + 7)} mm", ""])
    else:
        rows.append([lab["rho"], sub("ρ", "min"), f"{fmt.minus(fmt.length(c.rho_pitch_min_convex * MM))} mm", ""])
    return rows
