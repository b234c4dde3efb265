"""The kinematic diagram sheets (机构运动简图, A3): every machine's mechanism at one position
drawn to a GB length scale with the GB/T 4460 symbols — frame pivots (circle on a hatched
base), revolute pins (small circles), sliders (blocks; on a fixed guide the guide is a
hatched frame line), cams (the actual profile) with their followers, the links numbered,
the crank's turning direction, the scale μL in the heading and the title block — and the
transmission schematic (传动系统示意图) of a drive: motor, belt, gear pairs (pitch circles),
worm, the shafts numbered with their speed, power and torque.

Each builder only reads results: :func:`linkage_diagram` (any linkage run through the shared
linkage stages, at the brief's first polygon position, else position 1), :func:`lockbeam_diagram`
(the whole lock-beam machine: feed linkage, both cams with their followers, the bending
four-bar and chain, at φ = 0), :func:`die_cutter_diagram` (the whole die-cutter: toggle press,
gripper cam and push rod, incomplete gear pair, gripper chain, the drive from the motor as a
schematic), :func:`crank_rocker_diagram` (the crank-rocker brief's
optimum, at its first extreme position, and its offset slider-crank), :func:`cam_diagram`
(a synthesised cam at δ = 0), :func:`disc_diagram` (the eccentric disc cam at δ = 0) and
:func:`drive_schematic` (with the flywheel on its shaft where the design has one).
"""
from __future__ import annotations

import re

import unicodedata
from dataclasses import replace

import numpy as np

from ..i18n import tr
from ..stages.drive import shaft_numeral
from . import fmt
from .labels import LabelTable, pgettext, sheet_names, sheet_point, translated
from .sheet import (Arc, Circle, Fill, LabelPlacer, Line, Polyline, Sheet, Text, TitleInfo, fit_height, frame, ground,
                    hatched_line, heading, pin, preferred_scale, scale_text, slider_block, table,
                    sub, text_box, text_width, title_block_box, turn_arrow, with_subscripts)

MM = 1e3
SIZE = "A3"

LABELS = LabelTable({
    "diagram": pgettext("kinematic sheet", "Kinematic diagram"),
    "drive": pgettext("kinematic sheet", "Transmission schematic"),
    "position": pgettext("kinematic sheet", "position {p}"),
    "scale": pgettext("kinematic sheet", "length scale μL = {mu} m/mm ({s})"),
    "links": pgettext("kinematic sheet", "Links: "),
    "frame": pgettext("kinematic sheet", "frame"),
    "crank_rocker": pgettext("kinematic sheet", "Crank-rocker (optimum design, rocker at its first extreme C1)"),
    "slider_crank": pgettext("kinematic sheet", "Offset slider-crank (slider at its right extreme)"),
    "cam": pgettext("kinematic sheet", "Cam mechanism (δ = 0, follower at its lowest)"),
    "disc": pgettext("kinematic sheet", "Eccentric disc cam (δ = 0)"),
    "not_scale": pgettext("kinematic sheet", "schematic, not to scale; circles are pitch circles (pulleys: datum circles)"),
    "not_scale_nobelt": pgettext("kinematic sheet", "schematic, not to scale; circles are pitch circles"),
    "shaft": pgettext("kinematic sheet", "Shaft"),
    "n": pgettext("kinematic sheet", "n (rpm)"),
    "P": "P (kW)",
    "T": "T (N·m)",
    "stage": pgettext("kinematic sheet", "Stage"),
    "ratio": pgettext("kinematic sheet", "ratio i"),
    "data": pgettext("kinematic sheet", "data"),
    "motor": pgettext("kinematic sheet", "motor {m}"),
    "shafts": pgettext("kinematic sheet", "Speed, power and torque of the shafts"),
    "stages": pgettext("kinematic sheet", "Stages"),
    "omega": "ω",
    "guide": pgettext("kinematic sheet", "guide"),
    "drawn_at": pgettext("kinematic sheet", "; drawn at position {p}"),
})



# ------------------------------------------------------------------ the common frame

def _area(s: Sheet) -> tuple[float, float, float, float]:
    """The area under the heading and above the title block (the heading is centred on it)."""
    x0, y0, x1, y1 = s.inner
    tb = title_block_box(s)
    return x0 + 10.0, tb[3] + 14.0, x1 - 10.0, y1 - 16.0


# paper mm kept around a mechanism's points for its labels, ground symbols and ω arrow:
# the first guess (a label and its gap), and for the two views of the crank-rocker brief
LABEL_MIN = 5.0
LABEL_ROOM = 10.0
HEADING = 16.0          # the heading's strip under the border [mm]


def regions(s: Sheet) -> dict[str, tuple[float, float, float, float]]:
    """Where a mechanism may be drawn, labels included: the whole width above the title
    block (the notes then stand left of the title block), or the whole height left of it
    (the notes then stand above the title block)."""
    x0, y0, x1, y1 = s.inner
    tb = title_block_box(s)
    return {"above": (x0 + 4.0, tb[3] + 4.0, x1 - 4.0, y1 - HEADING),
            "left": (x0 + 4.0, y0 + 4.0, tb[0] - 4.0, y1 - HEADING)}


def _fit(s: Sheet, pts_mm: np.ndarray, area, pad_paper: float = LABEL_ROOM):
    """(view, n) drawing the model points ``pts_mm`` [mm] centred in ``area`` at the
    largest GB/T 14690 preferred scale (sheet.preferred_scale) at which they keep
    ``pad_paper`` mm from its sides."""
    pts = np.asarray(pts_mm, dtype=complex)
    n = preferred_scale(_limit(pts, area, pad_paper))
    return _view(s, pts, n, area), n


def _limit(pts: np.ndarray, area, pad: float) -> float:
    """The largest paper mm per model mm at which ``pts`` keep ``pad`` mm inside ``area``."""
    ext = complex(max(np.ptp(pts.real), 1e-6), max(np.ptp(pts.imag), 1e-6))
    ax0, ay0, ax1, ay1 = area
    return min((ax1 - ax0 - 2 * pad) / ext.real, (ay1 - ay0 - 2 * pad) / ext.imag)


def _view(s: Sheet, pts: np.ndarray, n: float, area):
    """The view drawing ``pts`` at 1:n centred in ``area``."""
    ax0, ay0, ax1, ay1 = area
    centre = complex(pts.real.min() + pts.real.max(), pts.imag.min() + pts.imag.max()) / 2
    return s.view(complex((ax0 + ax1) / 2, (ay0 + ay1) / 2) - centre / n, 1.0 / n)


def _tries(pts_mm, pad: float = LABEL_MIN, count: int = 8):
    """The sheets to draw a mechanism on, largest scale first, as (sheet, view, n, where):
    in each of the :func:`regions` the largest GB/T 14690 preferred scale at which the
    model points ``pts_mm`` keep ``pad`` mm from its sides, then the smaller ones; at one
    scale the region above the title block first. The caller draws on each until its
    drawing, labels included, lies in the region (:func:`drawing_fits`); the last is kept."""
    pts = np.asarray(pts_mm, dtype=complex)
    areas = regions(Sheet(SIZE))
    order = list(areas)
    cands = set()
    for where, area in areas.items():
        n = preferred_scale(_limit(pts, area, pad))
        for _ in range(count):
            cands.add((n, order.index(where), where))
            n = preferred_scale((1 - 1e-9) / n)
    for n, _, where in sorted(cands)[:count]:
        s = Sheet(SIZE)
        yield s, _view(s, pts, n, areas[where]), n, where


def _box(e) -> tuple[float, float, float, float] | None:
    """The box an entity covers on the paper (a text's estimated from its width)."""
    if isinstance(e, Text):
        b = text_box(0j, e.text, e.height, e.halign, e.valign)
        zs = [e.position + complex(x, y) * np.exp(1j * e.angle) for x in b[::2] for y in b[1::2]]
    elif isinstance(e, Line):
        zs = [e.p0, e.p1]
    elif isinstance(e, (Polyline, Fill)):
        zs = list(e.points)
    elif isinstance(e, (Circle, Arc)):
        zs = [e.center + e.radius * d for d in (1, 1j, -1, -1j)]
    else:
        return None
    zs = np.asarray(zs, dtype=complex)
    return zs.real.min(), zs.imag.min(), zs.real.max(), zs.imag.max()


def drawing_fits(entities, area, tol: float = 0.5) -> bool:
    """Every one of ``entities`` (a mechanism's lines, symbols and labels) lies in ``area``."""
    for e in entities:
        b = _box(e)
        if b is not None and (b[0] < area[0] - tol or b[1] < area[1] - tol
                              or b[2] > area[2] + tol or b[3] > area[3] + tol):
            return False
    return True


def _title(s: Sheet, text: str, area) -> None:
    ax0, _, ax1, ay1 = area
    heading(s, complex((ax0 + ax1) / 2, ay1 + 4.0), text, fit_height(text, ax1 - ax0, 5.0))


NOTE_SMALLEST = 2.5      # the notes' smallest text height [mm] (fit_height's floor)


def wrap_note(text: str, width: float, smallest: float = NOTE_SMALLEST) -> list[str]:
    """``text`` as lines each ``width`` mm wide at the most at text height ``smallest``:
    the text itself if it fits, else as much as fits on the first line, broken at a space
    (or, in Chinese, after a full-width comma or stop), at the gap between two items of a
    legend (two spaces) when one fits, and the rest wrapped again. A note too long for its
    room at the smallest height ran on into the title block (lockbeam en: "…the chain's
    centre distance" over "Student No.")."""
    if text_width(text, smallest) <= width:
        return [text]
    breaks = [j for j, ch in enumerate(text) if ch == " " and 0 < j < len(text) - 1]
    # after a full-width stop or comma (Chinese: no spaces)
    breaks += [j + 1 for j, ch in enumerate(text) if j + 1 < len(text)
               and unicodedata.category(ch) == "Po" and unicodedata.east_asian_width(ch) in "WF"]
    if not breaks:
        return [text]
    fits = [b for b in breaks if text_width(text[:b].rstrip(), smallest) <= width]
    items = [b for b in fits if text[b - 1:b + 1] == "  "]
    j = max(items or fits) if fits else min(breaks)
    head, tail = text[:j].rstrip(), text[j:].lstrip()
    return [head] + wrap_note(tail, width, smallest)


def numbered_items(*legends: str) -> str:
    """The items of link legends ("2 crank  3 coupler", items two spaces apart) in the order
    of their numbers, as one legend: the die-cutter's legend listed 2, 7, then 3 … 10 on
    two lines (its groups' legends one after the other), read as two lists."""
    items = [item for legend in legends for item in legend.split("  ") if item.strip()]

    def number(item: str) -> float:
        m = re.match(r"\s*(\d+)", item)
        return int(m.group(1)) if m else float("inf")

    return "  ".join(sorted(items, key=number))


def _notes(s: Sheet, lines: list[str], where: str = "above") -> None:
    """Notes, top line first: left of the title block, or above it when the drawing
    takes the height left of it (``where`` = "left", see :func:`regions`); a line too long
    for the room at the smallest text height is wrapped (:func:`wrap_note`), its lines at
    that height."""
    x0, y0, _, _ = s.inner
    tb = title_block_box(s)

    def wrapped(width):
        return [(part, fit_height(text, width, 3.5)) for text in lines
                for part in wrap_note(text, width)]

    if where == "left":
        width = tb[2] - tb[0] - 4.0
        rows = wrapped(width)
        for j, (text, height) in enumerate(rows):
            s.text(complex(tb[0] + 2.0, tb[3] + 4.0 + 6.0 * (len(rows) - 1 - j)), text, height, "TEXT")
        return
    width = tb[0] - x0 - 14.0
    rows = wrapped(width)
    # 6 mm apart, closer when more lines than that leaves room for beside the title block
    step = min(6.0, (tb[3] - tb[1] - 10.0) / max(len(rows) - 1, 1))
    for j, (text, height) in enumerate(rows):
        s.text(complex(x0 + 6.0, tb[3] - 6.0 - step * j), text, height, "TEXT")


def _scale_note(lab: dict, n: float) -> str:
    return with_subscripts(lab["scale"], "μ_L").format(mu=fmt.exact(n / 1000.0), s=scale_text(n))


def _omega_arrow(s: Sheet, view, pivot_mm: complex, radius_mm: float, ccw: bool,
                 placer: LabelPlacer, lab: dict) -> None:
    """The crank's turning arrow about its pivot, a little outside the crank circle, where
    it crosses the fewest lines and labels already placed (eight places tried)."""
    r = radius_mm * view.scale + 5.0
    c = view.p(pivot_mm)
    sweep = 0.45 * np.pi
    best = None
    for j in range(8):
        start = 0.15 * np.pi + j * np.pi / 4
        arc = c + (r + np.array([-1.5, 0.0, 1.5]))[:, None] * np.exp(1j * np.linspace(start, start + sweep, 12))
        hits = sum(not placer.free((z.real - 0.8, z.imag - 0.8, z.real + 0.8, z.imag + 0.8))
                   for z in arc.ravel())
        if best is None or hits < best[0]:
            best = (hits, start)
    start = best[1]
    mid = turn_arrow(s, c, r, ccw, start=start, sweep=sweep)
    for t in np.linspace(start, start + sweep, 10):
        placer.block(c + r * np.exp(1j * t), 1.0)
    placer.place(mid, lab["omega"], 3.5, prefer=(mid - c), gap=1.5)


# ------------------------------------------------------------------ linkages

def _link_outline(zs: list) -> list:
    """The points to join for one link: the two farthest apart when they are in line, else
    all of them around their centre (a ternary link, closed)."""
    zs = list(dict.fromkeys(complex(z) for z in zs))
    if len(zs) <= 2:
        return zs
    _, a, b = max(((abs(p - q), p, q) for p in zs for q in zs), key=lambda t: t[0])
    u = (b - a) / abs(b - a)
    if all(abs((np.conj(u) * (z - a)).imag) < 1e-6 * abs(b - a) for z in zs):
        return [a, b]
    c = np.mean(zs)
    ring = sorted(zs, key=lambda z: np.angle(z - c))
    return ring + ring[:1]


def linkage_positions(found, label: str = "1") -> int:
    """Index of the drawn position among the textbook positions (``label``, else position 1)."""
    labels = [str(x) for x in found.motion.positions.labels]
    return labels.index(str(label)) if str(label) in labels else 0


#: [rad] a link through the crank's tip that turns back along the crank within this angle
#: covers it on the drawing
FOLDED = np.radians(5.0)


def crank_covered(found, label: str = "1") -> bool:
    """Whether at position ``label`` a link pinned to the crank's tip lies back along the
    crank (the folded extreme position: the coupler runs over the crank and its pivot, so
    the crank cannot be seen on the diagram; linkage_sixbar's position 1, page review 47)."""
    from ..stages.linkage import link_members

    model, k = found.model, found.motion
    crank = model.crank
    i = k.grid_size + linkage_positions(found, label)
    pts = {name: complex(np.asarray(z)[i]) for name, z in k.points.items()}
    pivot = complex(model.mechanism.frame_points[crank.pivot])
    tip = pts.get(crank.tip)
    if tip is None:
        return False
    back = pivot - tip
    members, _sliders = link_members(model.mechanism)
    for link, names in members.items():
        if link == crank.link or crank.tip not in names:
            continue
        for name in names:
            z = pts.get(name)
            if z is None or abs(z - tip) < 1e-9 * max(abs(back), 1e-12):
                continue
            if abs(np.angle((z - tip) / back)) < FOLDED:
                return True
    return False


def diagram_position(found, brief=None) -> str:
    """The position a linkage's diagram is drawn at: the first of the brief's
    ``sheets.polygon_positions`` when it names them (the position the graphical method and
    the A1 sheet work at), else position 1 — unless the crank lies under a link there
    (:func:`crank_covered`), then the graphical method's first position."""
    settings = getattr(brief, "sheets", None)
    chosen = getattr(settings, "polygon_positions", None)
    polygons = getattr(found, "polygons", None)
    if polygons is not None and polygons.positions and (chosen or crank_covered(found, "1")):
        return str(polygons.positions[0])
    return "1"


class _LinkageDrawing:
    """One linkage at one position in model millimetres (``shift`` added to every point):
    the points to fit (:attr:`pts`) and :meth:`draw`."""

    def __init__(self, found, label: str = "1", shift: complex = 0j):
        from ..stages.linkage import link_members

        model, k = found.model, found.motion
        self.model, self.k = model, k
        mech = self.mech = model.mechanism
        self.members, self.sliders = link_members(mech)
        n_grid = self.n_grid = k.grid_size
        i = self.i = linkage_positions(found, label)
        self.label = str(list(k.positions.labels)[i])
        P = self.P = {name: complex(np.asarray(z)[n_grid + i]) * MM + shift for name, z in k.points.items()}
        self.joints = {j.point for js in mech.joints.values() for j in js} | set(mech.frame_points)
        coms = {b.com for b in model.bodies if b.com is not None} - self.joints
        # a point the brief asks about (analysis.points: the textbook's D) is drawn and named
        # even where a load acts on it
        self.named = (set(getattr(k, "point_vel", None) or {}) & set(P)) - self.joints - coms
        loads = {r.point for r in model.resistances} - self.joints - coms - self.named
        self.drawn = {nm: z for nm, z in P.items() if nm not in coms | loads}
        self.frame_pts = {nm: complex(z) * MM + shift for nm, z in mech.frame_points.items()}
        crank = model.crank
        self.piv = self.frame_pts[crank.pivot]
        self.r_crank = crank.length * MM
        pts = list(self.drawn.values())
        pts += list(self.piv + self.r_crank * np.exp(1j * np.linspace(0, 2 * np.pi, 13)))
        self.guides = []
        for slider, point, guide, gpoint in self.sliders:
            if isinstance(guide, str):
                continue
            # the fixed guide over the slider's travel and a little beyond
            u = np.exp(1j * guide)
            g0 = complex(gpoint) * MM + shift
            t = (np.conj(u) * (np.asarray(k.points[point])[:n_grid] * MM + shift - g0)).real
            lo, hi = float(t.min()), float(t.max())
            extra = max(0.12 * (hi - lo), 15.0)
            a, b = g0 + u * (lo - extra), g0 + u * (hi + extra)
            self.guides.append((slider, point, a, b, u))
            pts += [a, b]
        self.pts = pts

    def draw(self, s: Sheet, view, placer: LabelPlacer, lab: dict) -> list:
        """Draw the linkage; returns the link numbers placed."""
        P, drawn, joints, mech, k, i = self.P, self.drawn, self.joints, self.mech, self.k, self.i
        n_grid = self.n_grid
        # links (thick lines; a ternary link as a closed outline)
        for link, names in self.members.items():
            outline = _link_outline([P[p] for p in names if p in drawn])
            if len(outline) >= 2:
                view.polyline(np.array(outline), "OUTLINE")
                for a, b in zip(outline[:-1], outline[1:]):
                    placer.block_segment(view.p(a), view.p(b), 1.5)
        # fixed guides: hatched frame lines offset by half the block; sliders as blocks
        for slider, point, a, b, u in self.guides:
            hatched_line(view, a - 1j * u * 3.5 / view.scale, b - 1j * u * 3.5 / view.scale,
                         side=-1j)
            for off in (0.0, 3.5, 6.0):
                placer.block_segment(view.p(a - 1j * u * off / view.scale),
                                     view.p(b - 1j * u * off / view.scale), 1.0)
        for slider, point, guide, _ in self.sliders:
            ang = guide if not isinstance(guide, str) else float(np.asarray(k.link_angle[guide])[n_grid + i])
            slider_block(view, P[point], ang, 10.0, 6.0 if not isinstance(guide, str) else 5.0)
            placer.block(view.p(P[point]), 5.5)
        for name in sorted(joints - set(mech.frame_points)):
            if name in P:
                pin(view, P[name])
                placer.block(view.p(P[name]), 1.5)
        for name, z in self.frame_pts.items():
            ground(view, z, 7.0)
            placer.block(view.p(z) - 3.5j, 5.0)
        view.circle(self.piv, self.r_crank, "CENTER")
        _omega_arrow(s, view, self.piv, self.r_crank, self.model.crank_omega > 0, placer, lab)
        # names of the points, then the link numbers
        mid = np.mean(list(drawn.values()))
        for name in sorted(set(mech.frame_points) | (joints & set(P)) | self.named):
            d = P[name] - mid
            placer.place(view.p(P[name]), sheet_point(name), 3.5, prefer=d if abs(d) > 1e-9 else 1j, gap=2.5)
        numbered = []
        for link, names in self.members.items():
            outline = _link_outline([P[p] for p in names if p in drawn])
            if len(outline) < 2:
                continue
            a, b = outline[0], outline[1]
            d = (b - a) / abs(b - a) if abs(b - a) > 1e-9 else 1.0
            placer.place(view.p(a + 0.45 * (b - a)), link, 3.5, prefer=1j * d, gap=2.0)
            numbered.append(link)
        for slider, point, guide, _ in self.sliders:
            if slider not in numbered:
                ang = guide if not isinstance(guide, str) else float(np.asarray(k.link_angle[guide])[n_grid + i])
                placer.place(view.p(P[point]), slider, 3.5, prefer=1j * np.exp(1j * ang), gap=5.0)
                numbered.append(slider)
        return numbered

    def legend(self, numbered: list, lang: str) -> str:
        from ..stages.linkage import link_name

        names = getattr(self.model, "names", None) or {}
        return "  ".join(f"{lk} {sheet_names(link_name(names, lk, lang))}" for lk in
                         sorted(set(numbered), key=lambda x: (len(x), x)) if lk in names)


def _placer(s: Sheet) -> LabelPlacer:
    placer = LabelPlacer(s, area=(s.inner[0] + 2, s.inner[1] + 2, s.inner[2] - 2, s.inner[3] - 2))
    tb = title_block_box(s)
    placer.block_box((tb[0] - 2, tb[1], tb[2], tb[3] + 2))
    return placer


def _begin(s: Sheet, info: TitleInfo, n, heading: str, placer_of=None):
    """One try of a diagram at scale ``n``: the frame and title block with the scale, the
    heading with the scale after it, a label placer (:func:`_placer` unless given); returns
    (drawing area, placer, index of the first drawing entity)."""
    area = _area(s)
    frame(s, replace(info, scale=scale_text(n)))
    placer = (placer_of or _placer)(s)
    _title(s, f"{heading}  {scale_text(n)}", area)
    return area, placer, len(s.entities)


def linkage_diagram(found, info: TitleInfo, lang: str, label: str = "1") -> Sheet:
    """The kinematic diagram of a linkage (``found``: sheets.LinkageResults) at position
    ``label`` (see :func:`diagram_position`), at the largest preferred scale it fits."""
    lab = LABELS[lang]
    ld = _LinkageDrawing(found, label)
    for s, view, n, where in _tries(np.array(ld.pts)):
        area, placer, first = _begin(s, info, n, f"{lab['diagram']}  {lab['position'].format(p=ld.label)}")
        numbered = ld.draw(s, view, placer, lab)
        if drawing_fits(s.entities[first:], regions(s)[where]):
            break
    legend = ld.legend(numbered, lang)
    notes = [_scale_note(lab, n) + lab["drawn_at"].format(p=ld.label)]
    if legend:
        notes.append(lab["links"] + legend)
    _notes(s, notes, where)
    return s


# ------------------------------------------------------------------ the lock-beam machine

def cam_state(c, delta: float) -> tuple[np.ndarray, complex, int]:
    """(actual profile in the fixed frame [model mm], follower point [model mm], grid index)
    of the synthesised cam ``c`` turned to cam angle ``delta`` [rad]: the grid angle nearest
    ``delta``; the cam body turned by σδ (the profile is stored at δ = 0)."""
    g = c.grid
    n = len(g.delta)
    step = 2 * np.pi / n
    j = int(round(float(np.mod(delta, 2 * np.pi)) / step)) % n
    turn = np.exp(1j * g.rotation * float(g.delta[j]))
    return actual_profile_mm(c) * turn, complex(g.follower_point[j]) * MM, j


def actual_profile_mm(c) -> np.ndarray:
    from .cam_sheet import actual_profile

    return np.asarray(actual_profile(c))


def _tangent_runs(a: complex, r1: float, b: complex, r2: float) -> list[tuple[complex, complex]]:
    """The two outer tangents of circles (a, r1) and (b, r2): an open chain's or belt's runs.
    The unit normal n of a run (from the centres to the run) satisfies (b − a)·n = r1 − r2, so
    it leans from the perpendicular towards the smaller circle by arcsin((r2 − r1)/|b − a|)
    (leaned the other way, the runs cut the larger circle: the shaper's V-belt, page review 51)."""
    d = b - a
    u = d / abs(d)
    ang = np.arcsin((r2 - r1) / abs(d))
    out = []
    for sgn in (1, -1):
        nrm = 1j * u * np.exp(1j * sgn * ang) * sgn
        out.append((a + r1 * nrm, b + r2 * nrm))
    return out


CHAIN_CENTRES = 1.6      # schematic chain centre distance, in large-wheel diameters


def lockbeam_layout(results, found, phi: float = 0.0) -> dict:
    """The lock-beam machine at main-shaft angle ``phi`` [rad] in model millimetres: three
    groups side by side on one horizontal through the main shaft, each drawn to scale in
    itself — the feed linkage (at its position 1, φ = 0), the positioning cam with its
    translating roller follower (the pin), and the bending cam whose oscillating follower
    is the four-bar's input rocker (one rigid lever about A0), the four-bar A0–A–B–B0 and
    the chain from the large wheel (on B0) to the bending wheel. What the brief does not
    give is schematic: where the groups sit relative to each other, the angle between the
    follower arm and the input rocker (the four-bar is mirrored if needed so that the lever
    turns one way), the direction of the four-bar's frame line (along the cam–pivot line)
    and the chain's centre distance (:data:`CHAIN_CENTRES` × the large wheel's diameter).

    Returns ``{"feed": _LinkageDrawing, "pin": {...}, "bend": {...}, "pts": [...]}``."""
    p = results["params"]
    pin_cam, bend_cam, bending = results["cam"], results["bending_cam"], results["bending"]
    feed = _LinkageDrawing(found, "1")
    fx1 = max(z.real for z in feed.pts)
    gap = 60.0
    # the positioning cam: centre on the main-shaft line right of the feed linkage
    prof, B, _ = cam_state(pin_cam, phi - p.pin_cam_start)
    r_out = float(np.max(np.abs(prof)))
    rr_pin = pin_cam.grid.roller_radius * MM
    o_pin = complex(fx1 + gap + r_out, 0.0)
    top = float(np.max(np.abs(pin_cam.grid.pitch))) * MM + rr_pin + 35.0
    pin_d = {"O": o_pin, "profile": prof + o_pin, "B": B + o_pin, "rr": rr_pin,
             "stem_top": o_pin + complex(B.real, top), "guide_y": top - 13.0,
             "e": B.real}
    # the bending cam and its lever
    prof_b, C, j = cam_state(bend_cam, phi - p.bend_cam_start)
    rb_out = float(np.max(np.abs(prof_b)))
    fol = bend_cam.follower if bend_cam.follower is not None else bend_cam.params.follower
    a_piv = fol.pivot_distance * MM
    o_b = complex(o_pin.real + r_out + gap + rb_out, 0.0)
    A0 = o_b + a_piv
    ds = bending.design
    psi = float(bend_cam.grid.motion.s[j])
    # which way the follower arm turns as ψ grows (from the grid: the arm's angle at the
    # far end of the rise against its angle at the lowest position)
    fp = np.asarray(bend_cam.grid.follower_point)
    s_all = np.asarray(bend_cam.grid.motion.s)
    hi, lo = int(np.argmax(s_all)), int(np.argmin(s_all))
    turn = np.angle((fp[hi] - fol.pivot_distance) / (fp[lo] - fol.pivot_distance))
    mirror = turn < 0
    m = bending.mechanism.solve(np.array([ds.alpha1 + psi]))
    raw = {"G": complex(m.points["G"].pos[0]), "B": complex(m.points["B"].pos[0]),
           "G0": 0j, "B0": complex(ds.frame, 0.0)}
    four = {k: A0 + (np.conj(v) if mirror else v) * MM for k, v in raw.items()}
    r_big = p.bending.driving_wheel / 2 * MM
    r_small = p.bending.bending_wheel / 2 * MM
    small = four["B0"] + 1j * CHAIN_CENTRES * 2 * r_big
    # the bending wheel turns with the large wheel (open chain): its arm starts upwards
    beta = float(np.angle(raw["B"] - raw["B0"]))
    dbeta = float(np.angle(np.exp(1j * (beta - ds.beta1))))
    if mirror:
        dbeta = -dbeta
    arm_len = 1.6 * r_small
    arm = small + arm_len * np.exp(1j * (np.pi / 2 + bending.ratio * dbeta))
    bend_d = {"O": o_b, "profile": prof_b + o_b, "C": C + o_b, "rr": bend_cam.grid.roller_radius * MM,
              "four": four, "r_big": r_big, "r_small": r_small, "small": small, "arm": arm,
              "mirror": mirror, "sigma": bend_cam.grid.rotation}
    pts = list(feed.pts) + list(pin_d["profile"]) + [pin_d["stem_top"], o_pin - 10j]
    pts += list(bend_d["profile"]) + list(four.values())
    pts += [four["B0"] + r_big * np.exp(1j * t) for t in np.linspace(0, 2 * np.pi, 13)]
    pts += [small + (r_small + 4.0) * np.exp(1j * t) for t in np.linspace(0, 2 * np.pi, 13)]
    return {"feed": feed, "pin": pin_d, "bend": bend_d, "pts": pts, "found": found,
            "sigma_pin": pin_cam.grid.rotation}



def free_side(view, z, neighbours, prefer: float = -np.pi / 2) -> float:
    """[rad, paper] The direction for a frame symbol at the pivot ``z``: of the directions
    in 15° steps the one farthest in angle from every neighbour (the points whose links or
    parts meet at the pivot), the usual one below the pivot (``prefer``) where it is clear
    by 45° or more."""
    p = view.p(z)
    away = [np.angle(view.p(q) - p) for q in neighbours if abs(view.p(q) - p) > 1e-9]

    def clearance(a: float) -> float:
        return min((abs(np.angle(np.exp(1j * (a - b)))) for b in away), default=np.pi)

    if clearance(prefer) >= np.radians(45.0):
        return prefer
    steps = prefer + np.radians(15.0) * np.arange(24)
    return float(max(steps, key=lambda a: (round(clearance(a), 6), -abs(np.angle(np.exp(1j * (a - prefer)))))))


def _rod_guide(view, placer, x: float, yc: float) -> None:
    """A translating follower's guide: two hatched walls 2.5 mm (paper) either side of the
    rod at x, 14 units long about yc, kept clear of labels."""
    for side in (-1, 1):
        xw = x + side * 2.5 / view.scale
        hatched_line(view, complex(xw, yc - 7.0), complex(xw, yc + 7.0), side=(-1j if side < 0 else 1j))
        placer.block_box((view.p(complex(xw, yc)).real - 4, view.p(complex(xw, yc - 7.0)).imag,
                          view.p(complex(xw, yc)).real + 4, view.p(complex(xw, yc + 7.0)).imag))


def _cam_disc(view, placer, profile, o) -> None:
    """A disc cam on its fixed pivot o: the closed profile, the frame symbol and the pin, the
    pivot and the profile's outline (every ~120th point) kept clear of labels."""
    view.polyline(np.append(profile, profile[:1]), "OUTLINE")
    ground(view, o, 7.0)
    pin(view, o)
    placer.block(view.p(o), 6.0)
    for z in profile[:: max(len(profile) // 120, 1)]:
        placer.block(view.p(complex(z)), 0.6)

def lockbeam_diagram(results, found, info: TitleInfo, lang: str) -> Sheet:
    """The whole lock-beam machine (see :func:`lockbeam_layout`) at φ = 0 on one A3 sheet
    at one length scale; the main shaft's link (the feed crank and both cams, keyed to one
    shaft) is link 2."""
    lab = LABELS[lang]
    L = lockbeam_layout(results, found)
    for s, view, n, where in _tries(np.array(L["pts"])):
        area, placer, first = _begin(s, info, n, f"{lab['diagram']}  φ = 0°")
        feed = L["feed"]
        feed.draw(s, view, placer, lab)
        # the positioning cam: profile, centre, translating roller follower in its guide
        pd = L["pin"]
        o = pd["O"]
        _cam_disc(view, placer, pd["profile"], o)
        view.circle(pd["B"], pd["rr"], "OUTLINE")
        pin(view, pd["B"])
        view.line(pd["B"] + 1j * pd["rr"], pd["stem_top"], "OUTLINE")
        placer.block(view.p(pd["B"]), pd["rr"] * view.scale + 0.5)
        placer.block_segment(view.p(pd["B"]), view.p(pd["stem_top"]), 1.5)
        _rod_guide(view, placer, pd["stem_top"].real, o.imag + pd["guide_y"])
        _omega_arrow(s, view, o, float(np.max(np.abs(pd["profile"] - o))), L["sigma_pin"] > 0, placer, lab)
        placer.place(view.p(o), sheet_point("O2"), 3.5, prefer=-1 - 1j, gap=3.0)
        # the roller centre of the positioning pin: F (B is the bending four-bar's pin)
        placer.place(view.p(pd["B"]), sheet_point("F"), 3.5, prefer=-1 + 0.3j, gap=3.0)
        placer.place(view.p((pd["B"] + pd["stem_top"]) / 2), "7", 3.5, prefer=1, gap=3.0)
        k = pd["profile"][len(pd["profile"]) // 2]
        placer.place(view.p(k), "2", 3.5, prefer=k - o, gap=2.5)
        # the bending cam, the lever (follower arm + input rocker), the four-bar, the chain
        bd = L["bend"]
        o = bd["O"]
        f = bd["four"]
        _cam_disc(view, placer, bd["profile"], o)
        _omega_arrow(s, view, o, float(np.max(np.abs(bd["profile"] - o))), bd["sigma"] > 0, placer, lab)
        view.circle(bd["C"], bd["rr"], "OUTLINE")
        lever = [f["G0"], bd["C"], f["G"], f["G0"]]
        view.polyline(np.array(lever), "OUTLINE")
        for a, b in zip(lever[:-1], lever[1:]):
            placer.block_segment(view.p(a), view.p(b), 1.5)
        for a, b in ((f["G"], f["B"]), (f["B0"], f["B"])):
            view.line(a, b, "OUTLINE")
            placer.block_segment(view.p(a), view.p(b), 1.5)
        for z, away in ((f["G0"], (bd["C"], f["G"], o)), (f["B0"], (f["B"],))):
            # the frame symbol on the side free of the links at the pivot (G0's below it ran
            # across the rocker, the roller C and the cam: page review 47)
            angle = free_side(view, z, away)
            ground(view, z, 7.0, angle)
            placer.block(view.p(z) + 3.5 * np.exp(1j * angle), 5.0)
        for z in (bd["C"], f["G"], f["B"]):
            pin(view, z)
            placer.block(view.p(z), 1.5)
        # chain: the large wheel on B0 (one link with the arm B0B), the bending wheel and its arm
        view.circle(f["B0"], bd["r_big"], "OUTLINE")
        view.circle(bd["small"], bd["r_small"], "OUTLINE")
        for a, b in _tangent_runs(f["B0"], bd["r_big"], bd["small"], bd["r_small"]):
            view.line(a, b, "HIDDEN")
            placer.block_segment(view.p(a), view.p(b), 1.5)
        for c0, r in ((f["B0"], bd["r_big"]), (bd["small"], bd["r_small"])):
            for t in np.linspace(0, 2 * np.pi, 48)[:-1]:
                placer.block(view.p(c0 + r * np.exp(1j * t)), 0.8)
        ground(view, bd["small"], 7.0)
        view.line(bd["small"], bd["arm"], "OUTLINE")
        pin(view, bd["arm"])
        placer.block(view.p(bd["small"]) - 3.5j, 5.0)
        placer.block_segment(view.p(bd["small"]), view.p(bd["arm"]), 1.5)
        # the four-bar as the report names it: G0 G B B0 (A is the feed crank's pin)
        for name, z, d in (("O2", o, -1 - 1j), ("C", bd["C"], -1j), ("G0", f["G0"], -1 + 1j), ("G", f["G"], 1),
                           ("B", f["B"], 1j), ("B0", f["B0"], 1 - 1j), ("E0", bd["small"], 1 - 1j)):
            placer.place(view.p(z), sheet_point(name), 3.5, prefer=d, gap=2.5)
        k = bd["profile"][len(bd["profile"]) // 2]
        placer.place(view.p(k), "2", 3.5, prefer=k - o, gap=2.5)
        for num, a, b in (("8", f["G0"], f["G"]), ("9", f["G"], f["B"])):
            d = (b - a) / abs(b - a)
            placer.place(view.p((a + b) / 2), num, 3.5, prefer=1j * d, gap=2.0)
        placer.place(view.p(f["B0"] + bd["r_big"] * np.exp(-0.25j * np.pi)), "10", 3.5, prefer=1 - 1j, gap=2.0)
        runs = _tangent_runs(f["B0"], bd["r_big"], bd["small"], bd["r_small"])
        placer.place(view.p((runs[0][0] + runs[0][1]) / 2), "11", 3.5, prefer=1, gap=2.0)
        placer.place(view.p((bd["small"] + bd["arm"]) / 2), "12", 3.5, prefer=-1, gap=2.0)
        _ = tr(lang)
        legend = (_.pgettext("kinematic sheet", "2 main shaft (feed crank and both cams on one shaft)  3 block  "
                             "4 guide bar  5 rod  6 feed slider  7 positioning pin"),
                  _.pgettext("kinematic sheet", "8 rocker (cam follower and input rocker)  9 coupler  "
                             "10 large chain wheel  11 chain  12 bending wheel (bending arm)"))
        note = _.pgettext("kinematic sheet", "Each group drawn to μL; schematic, as the task does not give them: "
                          "the groups' relative placing, the angle between the rocker's arms, the direction of "
                          "the four-bar's frame line, the chain's centre distance")
        if drawing_fits(s.entities[first:], regions(s)[where]):
            break
    _notes(s, [_scale_note(lab, n) + _.pgettext("kinematic sheet", "; φ = 0°: feed linkage at position 1"),
               with_subscripts(note, "μ_L"), lab["links"] + legend[0], legend[1]], where)
    return s


# ------------------------------------------------------------------ the die-cutter

DC_GAP = 60.0            # model mm between the groups
DC_CHAIN_CENTRES = 2.0   # schematic chain centre distance, in sprocket pitch diameters


def die_cutter_layout(results, found) -> dict:
    """The die-cutter at the linkage's drawn position (shaft angle φ from position 1) in
    model millimetres: three groups on the distribution shaft's horizontal through O1, each
    drawn to scale in itself — the toggle press (:class:`_LinkageDrawing`), the gripper cam
    with its translating roller follower (the push rod) at δ = φ − φ_g (φ_g: the cycle's
    gripper start), and the incomplete gear pair (driver: the toothed sector on the tip
    circle, turned to φ from its meshing start, and the locking arc R_L on the rest; driven
    wheel right of it, its pitch circle touching the driver's) whose driven shaft carries
    the chain's driving sprocket (pitch radius R_s, behind the gear pair), the chain's tail
    sprocket right of it. What the results do not give is schematic: where the groups sit
    relative to each other, the direction of the gear pair's centre line (horizontal) and
    the chain's centre distance
    (:data:`DC_CHAIN_CENTRES` × 2R_s). Returns ``{"press", "cam", "gear", "pts", "phi"}``."""
    press = _LinkageDrawing(found, diagram_position(found, results.get("brief")))
    k = found.motion
    phi = float(np.asarray(k.phase)[press.n_grid + press.i])
    y0 = press.piv.imag
    x_right = max(z.real for z in press.pts)
    cam, fd = results["cam"], results["feed"]
    cyc = results.get("cycle")
    g_start = float(getattr(cyc, "gripper_start", 0.0) or 0.0)
    prof, B, _ = cam_state(cam, phi - g_start)
    r_out = float(np.max(np.abs(prof)))
    rr = cam.grid.roller_radius * MM
    o_cam = complex(x_right + DC_GAP + r_out, y0)
    top = float(np.max(np.abs(cam.grid.pitch))) * MM + rr + 35.0
    from ..core.cam import OscillatingFollower
    from .cam_sheet import _follower

    fol = _follower(cam)
    # an oscillating follower: its arm about the pivot at the pivot distance on +x
    pivot = (o_cam + fol.pivot_distance * MM) if isinstance(fol, OscillatingFollower) else None
    cam_d = {"O": o_cam, "profile": prof + o_cam, "B": B + o_cam, "rr": rr,
             "stem_top": o_cam + complex(B.real, top), "guide_y": top - 13.0,
             "sigma": cam.grid.rotation, "pivot": pivot, "kind": getattr(fol, "kind", "roller")}
    g = fd.gear
    r1, r2, ra1, ra2 = (x * MM for x in (g.r1, g.r2, g.ra1, g.ra2))
    cam_right = max(o_cam.real + r_out, -np.inf if pivot is None else pivot.real + 10.0)
    o_g = complex(cam_right + DC_GAP + ra1, y0)
    o_2 = o_g + (r1 + r2)
    sigma = cam.grid.rotation                     # the driver turns with the distribution shaft
    contact = 0.0                                 # direction O1 → O2 on the sheet
    lead = contact + sigma * (phi - g.motion_start)
    sector = sorted((lead, lead - sigma * g.motion_angle))
    rs = fd.sprocket_radius * MM
    tail = o_2 + DC_CHAIN_CENTRES * 2 * rs
    gear_d = {"O": o_g, "O2": o_2, "r1": r1, "r2": r2, "ra1": ra1, "ra2": ra2, "rf1": g.rf1 * MM,
              "rl": g.locking_radius * MM, "sector": tuple(sector), "rs": rs, "tail": tail,
              "sigma": sigma}
    pts = list(press.pts) + list(cam_d["profile"]) + [o_cam - 10j]
    pts += [cam_d["stem_top"]] if pivot is None else [pivot - 10j, cam_d["B"] + rr]
    pts += [o_g + ra1 * np.exp(1j * t) for t in np.linspace(0, 2 * np.pi, 13)]
    pts += [c + (rs + 4.0) * np.exp(1j * t) for c in (o_2, tail) for t in np.linspace(0, 2 * np.pi, 13)]
    return {"press": press, "cam": cam_d, "gear": gear_d, "pts": pts, "phi": phi}


def _drive_group(s: Sheet, box, drive, placer: LabelPlacer, caption: str, last: str,
                 flywheel=None, flywheel_text: str = "") -> bool:
    """A drive's wheels (motor end-on, belts and chains as two circles with their straight
    runs, gear pairs as touching pitch circles, GB/T 4460) laid out as on the transmission
    schematic (:func:`_layout_drive`), not to scale, fitted into the paper box ``box`` under
    ``caption``; the shafts numbered 0, I, II, … and the last one also ``last`` (the shaft it
    drives in the mechanism). Drawn only when every stage is a belt, chain, gear pair or
    coupling and the box holds it at a readable size; returns whether it was drawn. A
    ``flywheel`` is drawn on its shaft as on the transmission schematic."""
    stages = list(drive.stages)
    if not stages or any(st.type == "worm" for st in stages):
        return False
    r = [(_schematic_radius(st, 1), _schematic_radius(st, 2)) for st in stages]
    biggest = max([max(a, b) for a, b in r] + [1.0])
    r = [(max(a * 34.0 / biggest, 6.0), max(b * 34.0 / biggest, 8.0)) for a, b in r]
    motor_w = 24.0                                  # schematic units left of shaft 0
    fw_idx = flywheel_shaft(drive, flywheel)
    r_fw = _flywheel_radius(stages, r, fw_idx, flywheel) if fw_idx is not None else 0.0
    bx0, by0, bx1, by1 = box
    head = 8.0                                      # the caption's strip at the top
    # the wheels clear of each other (a shaft drawn twice, as on the transmission
    # schematic) when the box holds that at a readable size, else on their shafts
    for beside in (True, False):
        centres, items = _layout_drive(stages, r, beside,
                                       {fw_idx: r_fw} if fw_idx is not None and beside else None)
        pts = [centres[0] - motor_w - 14.0]
        if fw_idx is not None:
            pts += [centres[fw_idx] + r_fw * (1 + 1j), centres[fw_idx] - r_fw * (1 + 1j)]
        for kind, a, b, r1, r2, _ in items:
            for c0, rr in ((a, r1), (b, r2)):
                pts += [c0 + rr * (1 + 1j), c0 - rr * (1 + 1j)]
        pts = np.array(pts + list(centres))
        lo = complex(pts.real.min(), pts.imag.min())
        hi = complex(pts.real.max(), pts.imag.max())
        sc = min((bx1 - bx0 - 8.0) / max(hi.real - lo.real, 1.0),
                 (by1 - by0 - head - 10.0) / max(hi.imag - lo.imag, 1.0), 1.0)
        if sc >= 0.45:
            break
    if sc < 0.45:
        return False
    view = s.view(complex((bx0 + bx1) / 2, (by0 + by1 - head) / 2) - sc * (lo + hi) / 2, sc)
    placer.text(complex((bx0 + bx1) / 2, by1 - 1.0), caption, fit_height(caption, bx1 - bx0, 3.5),
                "center", "top")
    p0 = view.p(centres[0])
    half = 6.0                                      # the motor's square [paper mm]
    m = p0 - motor_w * sc - half
    s.polyline([m - half - half * 1j, m + half - half * 1j, m + half + half * 1j, m - half + half * 1j],
               "OUTLINE", closed=True, weight=0.5)
    s.text(m, "M", 4.0, "TEXT", "center", "middle")
    s.line(m + half, p0, "OUTLINE", 0.35)
    placer.block_box((m.real - half - 1, m.imag - half - 1, p0.real, m.imag + half + 1))
    for kind, a, b, r1, r2, j in items:
        if kind == "shaft":                         # a shaft drawn twice: a chain line joins them
            view.line(a, b, "CENTER")
            placer.block_segment(view.p(a), view.p(b), 1.0)
            continue
        if kind == "coupling":
            continue
        if kind == "belt":
            view.circle(a, r1, "OUTLINE", 0.5)
            view.circle(b, r2, "OUTLINE", 0.5)
            for u0, u1 in _tangent_runs(a, r1, b, r2):
                view.line(u0, u1, "OUTLINE" if stages[j].type == "belt" else "HIDDEN", 0.35)
                placer.block_segment(view.p(u0), view.p(u1), 1.5)
        else:
            for c0, rr in ((a, r1), (b, r2)):
                view.circle(c0, rr, "OUTLINE", 0.5)
        for c0, rr in ((a, r1), (b, r2)):
            for t in np.linspace(0, 2 * np.pi, 36)[:-1]:
                placer.block(view.p(c0 + rr * np.exp(1j * t)), 1.0)
    if fw_idx is not None:
        _flywheel_rim(view, placer, centres[fw_idx], r_fw, flywheel_text)
    for idx, c0 in enumerate(centres):
        if idx > 0 and stages[idx - 1].type == "coupling":
            continue
        name = shaft_numeral(idx) + (f" ({last})" if idx == len(centres) - 1 else "")
        for k, q in enumerate([c0] + [it[2] for it in items if it[0] == "shaft" and it[5] == idx]):
            p = view.p(q)
            s.circle(p, 1.2, "OUTLINE", 0.35)
            placer.block(p, 1.8)
            placer.place_best(p, name if k == 0 else shaft_numeral(idx), 3.0, prefer=1 + 1j,
                              gaps=(1.5, 3.0, 5.0))
    return True


def die_cutter_diagram(results, found, info: TitleInfo, lang: str) -> Sheet:
    """The die-cutter (see :func:`die_cutter_layout`) on one A3 sheet at one length scale:
    the toggle press, the gripper cam with its push rod, the incomplete gear pair and the
    gripper chain on its two sprockets; the distribution shaft's link (crank, cam and the
    incomplete gear's driver, keyed to one shaft) is link 2, named O1 under each group."""
    lab = LABELS[lang]
    L = die_cutter_layout(results, found)
    _ = tr(lang)
    press = L["press"]
    for s, view, n, where in _tries(np.array(L["pts"])):
        area, placer, first = _begin(s, info, n, f"{lab['diagram']}  {lab['position'].format(p=press.label)}")
        numbered = press.draw(s, view, placer, lab)
        # the gripper cam: profile, centre, translating roller follower (push rod) in its guide
        cd = L["cam"]
        o = cd["O"]
        _cam_disc(view, placer, cd["profile"], o)
        if cd["kind"] == "roller" and cd["rr"] > 0:
            view.circle(cd["B"], cd["rr"], "OUTLINE")
            pin(view, cd["B"])
        elif cd["kind"] == "flat" and cd["pivot"] is None:
            view.line(cd["B"] - 12.0 / view.scale, cd["B"] + 12.0 / view.scale, "OUTLINE")
            placer.block_segment(view.p(cd["B"] - 12.0 / view.scale), view.p(cd["B"] + 12.0 / view.scale), 1.0)
        placer.block(view.p(cd["B"]), cd["rr"] * view.scale + 0.5)
        if cd["pivot"] is not None:              # the lever about its frame pivot
            view.line(cd["pivot"], cd["B"], "OUTLINE")
            placer.block_segment(view.p(cd["pivot"]), view.p(cd["B"]), 1.5)
            ground(view, cd["pivot"], 7.0)
            pin(view, cd["pivot"])
            placer.block(view.p(cd["pivot"]) - 3.5j, 5.0)
            stem = (cd["pivot"] + cd["B"]) / 2
        else:                                    # the push rod in its guide
            view.line(cd["B"] + 1j * (cd["rr"] if cd["kind"] == "roller" else 0.0), cd["stem_top"], "OUTLINE")
            placer.block_segment(view.p(cd["B"]), view.p(cd["stem_top"]), 1.5)
            _rod_guide(view, placer, cd["stem_top"].real, o.imag + cd["guide_y"])
            stem = (cd["B"] + cd["stem_top"]) / 2
        _omega_arrow(s, view, o, float(np.max(np.abs(cd["profile"] - o))), cd["sigma"] > 0, placer, lab)
        placer.place(view.p(o), sheet_point("O1"), 3.5, prefer=-1 + 1j, gap=3.0)
        placer.place(view.p(cd["B"]), sheet_point("E"), 3.5, prefer=-1 + 0.3j, gap=3.0)
        placer.place(view.p(stem), "7", 3.5, prefer=1 if cd["pivot"] is None else 1j, gap=3.0)
        kz = cd["profile"][len(cd["profile"]) // 2]
        placer.place(view.p(kz), "2", 3.5, prefer=kz - o, gap=2.5)
        # the incomplete gear pair: pitch circles touching (chain line), the driver's toothed
        # sector on its tip circle, its locking arc, the driven wheel's tip circle
        gd = L["gear"]
        og, o2 = gd["O"], gd["O2"]
        view.circle(og, gd["r1"], "CENTER")
        view.circle(o2, gd["r2"], "CENTER")
        a0, a1 = gd["sector"]
        view.arc(og, gd["ra1"], a0, a1, "OUTLINE")
        view.arc(og, gd["rf1"], a0, a1, "CONSTRUCTION")
        view.arc(og, gd["rl"], a1, a0 + 2 * np.pi, "OUTLINE")
        for a in (a0, a1):
            view.line(og + gd["rf1"] * np.exp(1j * a), og + max(gd["ra1"], gd["rl"]) * np.exp(1j * a),
                      "OUTLINE")
        view.circle(o2, gd["ra2"], "OUTLINE")
        for c0, rr in ((og, gd["ra1"]), (o2, gd["ra2"]), (o2, gd["rs"]), (gd["tail"], gd["rs"])):
            for t in np.linspace(0, 2 * np.pi, 48)[:-1]:
                placer.block(view.p(c0 + rr * np.exp(1j * t)), 0.8)
        ground(view, og, 7.0)
        pin(view, og)
        placer.block(view.p(og) - 3.5j, 5.0)
        _omega_arrow(s, view, og, gd["ra1"], gd["sigma"] > 0, placer, lab)
        # the chain: the driving sprocket on the driven wheel's shaft behind the gear pair
        # (hidden by the driver where they overlap: its arc there not drawn, as a diagram
        # draws no hidden lines and a dashed arc across wheel 2 read as one more wheel of
        # it), the tail sprocket
        d = abs(o2 - og)
        r_front = max(gd["ra1"], gd["rl"])
        cos_b = (gd["rs"] ** 2 + d ** 2 - r_front ** 2) / (2 * gd["rs"] * d)
        if abs(cos_b) < 1.0:
            beta = float(np.arccos(cos_b))
            toward = float(np.angle(og - o2))
            view.arc(o2, gd["rs"], toward + beta, toward - beta + 2 * np.pi, "OUTLINE")
        else:
            view.circle(o2, gd["rs"], "OUTLINE")
        view.circle(gd["tail"], gd["rs"], "OUTLINE")
        runs = _tangent_runs(o2, gd["rs"], gd["tail"], gd["rs"])
        for a, b in runs:
            view.line(a, b, "HIDDEN")
            placer.block_segment(view.p(a), view.p(b), 1.5)
        for z, size in ((o2, 5.0), (gd["tail"], 7.0)):       # O2's inside the driven gear
            ground(view, z, size)
            pin(view, z)
            placer.block(view.p(z) - 0.5j * size, 0.7 * size)
        placer.place(view.p(og), sheet_point("O1"), 3.5, prefer=-1 - 1j, gap=3.0)
        placer.place(view.p(o2), sheet_point("O2"), 3.5, prefer=1 + 1j, gap=3.0)
        placer.place(view.p(gd["tail"]), sheet_point("O3"), 3.5, prefer=1 + 1j, gap=3.0)
        mid = a1 + np.pi - (a1 - a0) / 2                # middle of the locking arc
        placer.place(view.p(og + gd["rl"] * np.exp(1j * mid)), "2", 3.5, prefer=-np.exp(1j * mid), gap=2.0)
        # member 8 (the driven wheel and the sprocket on its shaft): its number on the
        # driven wheel, in the ring between the wheel and the sprocket, away from the mesh
        placer.place(view.p(o2 + gd["ra2"] * np.exp(-0.25j * np.pi)), "8", 3.5,
                     prefer=np.exp(-0.25j * np.pi), gap=1.5)
        top_run = max(runs, key=lambda ab: ab[0].imag)
        placer.place(view.p((top_run[0] + top_run[1]) / 2), "9", 3.5, prefer=1j, gap=2.0)
        placer.place(view.p(gd["tail"] + gd["rs"] * np.exp(-0.25j * np.pi)), "10", 3.5, prefer=1 - 1j, gap=2.0)
        legend = (_.pgettext("kinematic sheet", "2 distribution shaft (crank, gripper cam and incomplete-gear "
                             "driver on one shaft)  7 push rod (follower of the gripper cam)")
                  if cd["pivot"] is None else
                  _.pgettext("kinematic sheet", "2 distribution shaft (crank, gripper cam and incomplete-gear "
                             "driver on one shaft)  7 lever (follower of the gripper cam)"))
        legend2 = _.pgettext("kinematic sheet", "8 driven gear with the driving sprocket  9 gripper chain  "
                             "10 tail sprocket")
        if drawing_fits(s.entities[first:], regions(s)[where]):
            break
    # the drive from the motor, schematic, in the room above the cam and the gears right of
    # the press (left out where there is too little)
    drive = results.get("drive")
    if drive is not None and getattr(drive, "stages", None):
        reg = regions(s)[where]
        x_press = max(view.p(z).real for z in press.pts) + 12.0
        tops = [view.p(cd["stem_top"] if cd["pivot"] is None else cd["B"]).imag + cd["rr"] * view.scale, view.p(L["gear"]["O2"]).imag + L["gear"]["rs"] * view.scale,
                view.p(L["gear"]["O"]).imag + L["gear"]["ra1"] * view.scale]
        box = (x_press, max(tops) + 12.0, reg[2], reg[3])
        if box[2] - box[0] > 60.0 and box[3] - box[1] > 40.0:
            _drive_group(s, box, drive, placer,
                         _.pgettext("kinematic sheet", "Drive from the motor (schematic, not to scale)"),
                         sheet_point("O1"), found.flywheel, _.pgettext("kinematic sheet", "flywheel"))
    press_legend = press.legend([x for x in numbered if x != "2"], lang)
    note = _.pgettext("kinematic sheet", "Each group drawn to μL; schematic, as the task does not give them: "
                      "the groups' relative placing, the direction of the gear pair's centre line, the "
                      "chain's centre distance")
    _notes(s, [_scale_note(lab, n) + lab["drawn_at"].format(p=press.label), with_subscripts(note, "μ_L"),
               lab["links"] + numbered_items(legend, press_legend, legend2)], where)
    return s


# ------------------------------------------------------------------ crank-rocker brief

def own_middle(a: complex, b: complex, others: list, tol: float = 1e-6) -> complex:
    """Where link a–b's number goes: the middle of the longest stretch of a–b that no other
    link (``others``: their ends) lies along. At the crank-rocker's extreme the coupler runs
    over the crank (B, A, C on one line); the middle of BC was then a few millimetres from
    A, so its "2" read as A's; the middle of AC, the coupler's own part, is not. A link
    covered all along (the crank under the coupler) keeps its middle."""
    u = b - a
    length = abs(u)
    covered = []
    for p, q in others:
        # another link on the same line: its ends' positions along a–b, clipped to [0, 1]
        tp, tq = ((p - a) / u), ((q - a) / u)
        if abs(tp.imag) * length > tol * max(length, 1.0) or abs(tq.imag) * length > tol * max(length, 1.0):
            continue
        lo, hi = sorted((tp.real, tq.real))
        lo, hi = max(lo, 0.0), min(hi, 1.0)
        if hi > lo:
            covered.append((lo, hi))
    free, t = [], 0.0
    for lo, hi in sorted(covered):
        if lo > t:
            free.append((t, lo))
        t = max(t, hi)
    if t < 1.0:
        free.append((t, 1.0))
    if not free:
        return (a + b) / 2
    lo, hi = max(free, key=lambda span: span[1] - span[0])
    return a + u * (lo + hi) / 2


def crank_rocker_points(a: float, b: float, c: float, d: float) -> dict:
    """Joint positions [same units] of the crank-rocker A B C D with A at the origin and D
    on +x, at the rocker's first extreme C1 (crank and coupler folded: AC1 = b − a)."""
    ac = b - a
    cos_a = (ac ** 2 + d ** 2 - c ** 2) / (2 * ac * d)
    C = ac * np.exp(1j * np.arccos(np.clip(cos_a, -1, 1)))
    B = -a * C / abs(C)
    return {"A": 0j, "B": complex(B), "C": complex(C), "D": complex(d)}


def slider_crank_points(a: float, b: float, e: float) -> dict:
    """The offset slider-crank at the slider's far extreme (crank and rod in line): A at the
    origin, the guide at y = −e, C = ((a + b)² − e²)^½ − i e."""
    x = np.sqrt((a + b) ** 2 - e ** 2)
    C = complex(x, -e)
    return {"A": 0j, "B": a * C / abs(C), "C": C}


def crank_rocker_diagram(opt, slider, info: TitleInfo, lang: str) -> Sheet:
    """The crank-rocker brief's optimum four-bar and (when given) its offset slider-crank."""
    lab = LABELS[lang]
    fb = opt.best.design
    four = {k: v * MM for k, v in crank_rocker_points(fb.crank, fb.coupler, fb.rocker, fb.frame).items()}
    pts4 = list(four.values()) + list(fb.crank * MM * np.exp(1j * np.linspace(0, 2 * np.pi, 13)))
    sc_pts = {}
    if slider is not None:
        raw = slider_crank_points(slider.crank, slider.rod, slider.offset)
        sc_pts = {k: v * MM for k, v in raw.items()}
        pts_s = list(sc_pts.values()) + [slider.crank * MM * np.exp(1j * t) for t in np.linspace(0, 2 * np.pi, 13)]
        pts_s += [sc_pts["C"] - slider.stroke * MM - 10.0, sc_pts["C"] + 15.0]
    s = Sheet(SIZE)
    area = _area(s)
    if sc_pts:
        # two views side by side, each at its own GB scale (the ~70 mm four-bar enlarged,
        # the longer slider-crank as it fits): the split of the width that gives the
        # largest product of the two scales
        ax0, ay0, ax1, ay1 = regions(s)["above"]
        best = None
        for k in range(30, 71):
            xm = ax0 + (ax1 - ax0) * k / 100.0
            v4, n4 = _fit(s, np.array(pts4), (ax0, ay0, xm, ay1), pad_paper=14.0)
            vs, ns = _fit(s, np.array(pts_s), (xm, ay0, ax1, ay1), pad_paper=14.0)
            if best is None or 1.0 / (n4 * ns) > best[0] * (1 + 1e-9):
                best = (1.0 / (n4 * ns), (v4, n4), (vs, ns))
        views = [best[1], best[2]]
    else:
        views = [_fit(s, np.array(pts4), regions(s)["above"], pad_paper=14.0)]
    scales = list(dict.fromkeys(scale_text(n) for _, n in views))
    frame(s, replace(info, scale=", ".join(scales)))
    placer = LabelPlacer(s)
    tb = title_block_box(s)
    placer.block_box((tb[0] - 2, tb[1], tb[2], tb[3] + 2))
    _title(s, f"{lab['diagram']}  {', '.join(scales)}", area)
    view = views[0][0]

    def mechanism(P, sliding: bool, caption: str, crank_len: float):
        links = [("1", P["A"], P["B"]), ("2", P["B"], P["C"])]
        if not sliding:
            links.append(("3", P["C"], P["D"]))
        for _, a, b in links:
            view.line(a, b, "OUTLINE")
            placer.block_segment(view.p(a), view.p(b), 1.5)
        view.circle(P["A"], crank_len, "CENTER")
        ground(view, P["A"], 7.0)
        placer.block(view.p(P["A"]) - 3.5j, 5.0)
        if sliding:
            lo = P["C"] - slider.stroke * MM - 10.0
            hi = P["C"] + 15.0
            hatched_line(view, lo - 3.5j / view.scale, hi - 3.5j / view.scale)
            slider_block(view, P["C"], 0.0, 10.0, 6.0)
            placer.block(view.p(P["C"]), 5.5)
            placer.block_segment(view.p(lo - 5j / view.scale), view.p(hi - 5j / view.scale), 2.0)
        else:
            ground(view, P["D"], 7.0)
            placer.block(view.p(P["D"]) - 3.5j, 5.0)
        for name, z in P.items():
            if name != "A" and not (not sliding and name == "D"):
                pin(view, z)
            placer.block(view.p(z), 1.5)
        _omega_arrow(s, view, P["A"], crank_len, True, placer, lab)
        mid = np.mean(list(P.values()))
        for name, z in P.items():
            d = z - mid
            placer.place(view.p(z), sheet_point(name), 3.5, prefer=d if abs(d) > 1e-9 else 1j, gap=2.5)
        for num, a, b in links:
            d = (b - a) / abs(b - a)
            at = own_middle(a, b, [(p, q) for m, p, q in links if m != num])
            placer.place(view.p(at), num, 3.5, prefer=1j * d, gap=2.0)
        if sliding:
            placer.place(view.p(P["C"]), "3", 3.5, prefer=1j, gap=4.5)
        # the frame is link 4 (crank 1, coupler 2, rocker or slider 3: the textbook's numbers,
        # the synthesis's l1 … l4 and the report's analysis), at the fixed pivot D or the guide
        fixed = P["C"] - 0.5 * slider.stroke * MM - 3.5j / view.scale if sliding else P["D"] - 3.5j / view.scale
        placer.place(view.p(fixed), "4", 3.5, prefer=-1j if sliding else 1 - 1j, gap=3.5)
        low = min(min(view.p(z).imag for z in P.values()) - 8.0,
                  view.p(P["A"]).imag - crank_len * view.scale - 4.0)
        cx = float(np.mean([view.p(z).real for z in P.values()]))
        caption = sheet_names(caption)          # "… its first extreme C1" → C₁
        placer.text(complex(cx, max(low, area[1] - 4.0)), caption, fit_height(caption, 180.0, 3.5),
                    "center", "top")

    mechanism(four, False, f"{lab['crank_rocker']}  {scale_text(views[0][1])}", fb.crank * MM)
    scale_notes = "ABCD: " + _scale_note(lab, views[0][1])
    if sc_pts:
        view = views[1][0]
        mechanism(sc_pts, True, f"{lab['slider_crank']}  {scale_text(views[1][1])}", slider.crank * MM)
        scale_notes += ";  ABC: " + _scale_note(lab, views[1][1])
    notes = [scale_notes,
             "ABCD: " + "  ".join(f"{sub('l', str(k))} = {fmt.length(v * MM)}" for k, v in
                                  enumerate((fb.crank, fb.coupler, fb.rocker, fb.frame), 1)) + " mm"]
    if slider is not None:
        notes.append(f"ABC: a = {fmt.length(slider.crank * MM)}  b = {fmt.length(slider.rod * MM)}  "
                     f"e = {fmt.minus(fmt.length(slider.offset * MM))}  H = {fmt.length(slider.stroke * MM)} mm")
    _notes(s, notes)
    return s


# ------------------------------------------------------------------ cams

def cam_diagram(c, info: TitleInfo, lang: str) -> Sheet:
    """A synthesised cam (stages.cam.CamResult) with its follower at δ = 0."""
    from .cam_sheet import _ProfileGeometry, divisions

    lab = LABELS[lang]
    g = _ProfileGeometry(c, divisions(c))
    pts = list(g.actual)
    B0 = g.B0
    if g.osc:
        A = complex(g.a)
        pts += [A, B0, A - 10.0j]
    else:
        top = g.outer + 35.0
        pts += [B0, complex(g.e, top)]
    for s, view, n, where in _tries(np.array(pts)):
        area, placer, first = _begin(s, info, n, lab["diagram"], LabelPlacer)
        view.polyline(np.append(g.actual, g.actual[:1]), "OUTLINE")
        view.circle(0j, g.r0, "CENTER")
        ground(view, 0j, 7.0)
        pin(view, 0j)
        placer.block(view.p(0j), 6.0)
        for z in g.actual[:: max(len(g.actual) // 120, 1)]:
            placer.block(view.p(complex(z)), 0.6)
        if g.osc:
            ground(view, A, 7.0)
            pin(view, A)
            u = (B0 - A) / abs(B0 - A)
            view.line(A + u * 1.2 / view.scale, B0, "OUTLINE")
            placer.block_segment(view.p(A), view.p(B0), 1.5)
            placer.place(view.p(A), sheet_point("A"), 3.5, prefer=1 + 1j, gap=3.0)
            stem_top = B0
        else:
            stem_top = complex(g.e, g.outer + 35.0)
            view.line(B0, stem_top, "OUTLINE")
            placer.block_segment(view.p(B0), view.p(stem_top), 1.5)
            yc = g.outer + 22.0
            half = 7.0
            for side in (-1, 1):
                xw = g.e + side * 2.5 / view.scale
                hatched_line(view, complex(xw, yc - half), complex(xw, yc + half),
                             side=(-1j if side < 0 else 1j))
                placer.block_box((view.p(complex(xw, yc)).real - 4, view.p(complex(xw, yc - half)).imag,
                                  view.p(complex(xw, yc)).real + 4, view.p(complex(xw, yc + half)).imag))
            placer.place(view.p(complex(g.e, yc)), lab["guide"], 3.0, prefer=1, gap=6.0)
        if g.kind == "roller":
            view.circle(B0, g.rr, "OUTLINE")
            pin(view, B0)
        roller = max(g.rr * view.scale, 1.5)
        placer.block(view.p(B0), roller)
        # beside the roller, not on it
        placer.place(view.p(B0), sheet_point("B"), 3.5, prefer=(-1 + 0.3j) if not g.osc else -1j,
                     gap=roller + 1.5)
        placer.place(view.p(0j), sheet_point("O"), 3.5, prefer=-1 - 1j, gap=3.0)
        _omega_arrow(s, view, 0j, float(np.max(np.abs(g.actual))), g.sigma > 0, placer, lab)
        # link numbers: cam 1, follower 2
        placer.place(view.p(complex(g.actual[len(g.actual) // 2])), "1", 3.5,
                     prefer=complex(g.actual[len(g.actual) // 2]), gap=2.5)
        mid_f = (B0 + stem_top) / 2 if not g.osc else (A + B0) / 2
        placer.place(view.p(mid_f), "2", 3.5, prefer=1, gap=3.0)
        _ = tr(lang)
        kinds = {"roller": pgettext("kinematic sheet", "roller"),
                 "knife": pgettext("kinematic sheet", "knife-edge"),
                 "flat": pgettext("kinematic sheet", "flat-face")}
        kind = translated(kinds[g.kind], _) if g.kind in kinds else g.kind
        motion = (_.pgettext("kinematic sheet", "oscillating") if g.osc
                  else _.pgettext("kinematic sheet", "translating"))
        legend = _.pgettext("kinematic sheet", "1 cam  2 {motion} {kind} follower", motion=motion, kind=kind)
        if drawing_fits(s.entities[first:], regions(s)[where]):
            break
    _notes(s, [_scale_note(lab, n), lab["links"] + legend,
               f"{sub('r', '0')} = {fmt.length(g.r0)} mm"
               + (f"  {sub('r', 'r')} = {fmt.length(g.rr)} mm" if g.rr else "")
               + (f"  e = {fmt.minus(fmt.length(g.e))} mm" if g.e else "")], where)
    return s


def disc_diagram(disc, info: TitleInfo, lang: str) -> Sheet:
    """The eccentric disc cam (eccentric_cam brief) at δ = 0, once per follower, side by
    side: disc, pivot O, centre C, the follower in its guide."""
    lab = LABELS[lang]
    p = disc.params
    R = p.radius * MM
    cases = []
    for j, (label, fol) in enumerate(p.followers):
        m = disc.motions[j]
        centre = complex(np.asarray(m.centre)[0]) * MM
        x, y = fol.offset * MM, float(np.asarray(m.y)[0]) * MM
        top = y + R + 10.0
        cases.append((label, fol, centre, x, y, top))
    width = 2.0 * (R + abs(p.eccentricity * MM)) + 30.0
    pts = []
    for j, (label, fol, centre, x, y, top) in enumerate(cases):
        sh = j * width
        pts += [sh + centre + R * np.exp(1j * t) for t in np.linspace(0, 2 * np.pi, 37)]
        pts += [sh + complex(x, top), sh - 10.0j]
    for s, view, n, where in _tries(np.array(pts)):
        area, placer, first = _begin(s, info, n, lab["diagram"], LabelPlacer)
        ccw = getattr(p, "rotation", 1) > 0
        for j, (label, fol, centre, x, y, top) in enumerate(cases):
            sh = j * width
            c = sh + centre
            view.circle(c, R, "OUTLINE")
            view.line(sh, c, "OUTLINE")
            # the frame symbol away from the centre C and the follower (below O it ran through
            # C: page review 48)
            side = free_side(view, sh + 0j, (c, sh + complex(x, y)))
            ground(view, sh + 0j, 7.0, side)
            pin(view, sh + 0j)
            pin(view, c)
            placer.block(view.p(sh + 0j) + 3.5 * np.exp(1j * side), 6.0)
            for t in np.linspace(0, 2 * np.pi, 60)[:-1]:
                placer.block(view.p(c + R * np.exp(1j * t)), 0.6)
            placer.block_segment(view.p(sh + 0j), view.p(c), 1.5)
            base = sh + complex(x, y)
            rr = fol.roller_radius * MM
            if fol.kind == "roller":
                view.circle(base, rr, "OUTLINE")
                pin(view, base)
            elif fol.kind == "flat":
                view.line(base - 0.5 * R, base + 0.5 * R, "OUTLINE")
            else:
                view.polyline([base + complex(-1.8, 5.0) / view.scale, base, base + complex(1.8, 5.0) / view.scale], "OUTLINE")
            view.line(base + 1j * (rr if fol.kind == "roller" else 0.0), sh + complex(x, top), "OUTLINE")
            placer.block_segment(view.p(base), view.p(sh + complex(x, top)), 1.5)
            yc = top - 8.0
            for side in (-1, 1):
                xw = sh + x + side * 2.5 / view.scale
                hatched_line(view, complex(xw, yc - 6.0), complex(xw, yc + 6.0), side=(-1j if side < 0 else 1j))
                placer.block_box((view.p(complex(xw, yc)).real - 4.0, view.p(complex(xw, yc - 6)).imag,
                                  view.p(complex(xw, yc)).real + 4.0, view.p(complex(xw, yc + 6)).imag))
            placer.place(view.p(sh + 0j), sheet_point("O"), 3.5, prefer=-1 - 0.2j, gap=4.0)
            placer.place(view.p(c), sheet_point("C"), 3.5, prefer=-1 + 0.3j, gap=2.0)
            placer.place(view.p(sh + complex(x, top)), str(label), 3.5, prefer=1j, gap=2.0)
            _omega_arrow(s, view, c, R, ccw, placer, lab)
        if drawing_fits(s.entities[first:], regions(s)[where]):
            break
    _notes(s, [_scale_note(lab, n), f"R = {fmt.length(R)} mm  OC = {fmt.length(p.eccentricity * MM)} mm"], where)
    return s


# ------------------------------------------------------------------ the drive

def _schematic_radius(stage, which: int) -> float:
    """Relative size of a stage's wheel (pulley datum diameter; gear teeth count)."""
    if stage.type in ("belt", "chain") and stage.d1:
        return (stage.d1 if which == 1 else stage.d2) * MM / 10.0
    z = stage.z1 if which == 1 else stage.z2
    return float(z or 20)


def _overlap(c: complex, R: float, placed, skip=()) -> float:
    """How far a circle (c, R) reaches into the circles ``placed`` (centre, radius), 3 units
    of clearance asked, those centred on a point of ``skip`` (its own shaft) left out."""
    return sum(max(0.0, R + rr + 3.0 - abs(c - cc)) for cc, rr in placed
               if all(abs(cc - z) > 1e-9 for z in skip))


def _layout_drive(stages, r, beside: bool = False, rims=None) -> tuple[list, list]:
    """Shaft centres (schematic units) and the items to draw: each stage's next shaft is
    put where its wheel overlaps the wheels already placed least (directions tried from
    straight right, turning up and down in steps of 30°); a worm's wheel sits above the
    worm, a belt's pulleys 1.5 (r1 + r2) + 16 apart.

    ``beside``: a stage whose wheels would still cover a wheel already drawn has its driving
    wheel drawn beside the shaft's other wheel instead of on it — the shaft drawn a second
    time (an item ("shaft", first centre, second centre, 0, 0, index of the shaft)), so no
    wheel covers a wheel of another stage. ``rims``: {shaft index: radius} of other circles
    on a shaft (a flywheel) the wheels are kept clear of."""
    centres = [0j]
    items = []
    placed: list[tuple[complex, float]] = []          # circles already drawn (centre, radius)
    rims = dict(rims or {})
    if 0 in rims:
        placed.append((0j, rims[0]))
    z = 0j
    dirs = (0, 30, -30, 60, -60, 90, -90, 120, -120)
    for j, st in enumerate(stages):
        r1, r2 = r[j]
        if st.type == "coupling":
            items.append(("coupling", z, z, 0.0, 0.0, j))
            centres.append(z)
            continue
        if st.type == "worm":
            nxt = z + 1j * (r1 + r2)
            items.append(("worm", z, nxt, r1, r2, j))
            placed += [(z, 1.3 * r1), (nxt, r2)]
            z = nxt
            centres.append(z)
            if len(centres) - 1 in rims:
                placed.append((z, rims[len(centres) - 1]))
            continue
        dist = (r1 + r2) * 1.5 + 16.0 if st.type in ("belt", "chain") else r1 + r2
        best = None
        for rank, deg in enumerate(dirs):
            cand = z + dist * np.exp(1j * np.radians(deg))
            over = _overlap(cand, r2, placed, () if beside else (z,))
            if beside:      # the driving wheel on the shaft: only its own shaft's wheels
                over += _overlap(z, r1, placed, (z,))
            cost = over + 0.01 * rank
            if best is None or cost < best[0]:
                best = (cost, cand, z)
        if beside and best[0] >= 0.5 and any(abs(c - z) < 1e-9 for c, _r in placed):
            # the shaft drawn again beside its wheel (and clear of every wheel), this
            # stage's wheels from there
            own = max(rr for c, rr in placed if abs(c - z) < 1e-9)
            for rank, deg in enumerate(dirs + (150, -150, 180)):
                for far in (own + r1 + 6.0, own + r1 + 16.0, own + r1 + 30.0):
                    start = z + far * np.exp(1j * np.radians(deg))
                    for rank2, deg2 in enumerate(dirs):
                        cand = start + dist * np.exp(1j * np.radians(deg2))
                        cost = (_overlap(start, r1, placed) + _overlap(cand, r2, placed + [(start, r1)], (start,))
                                + 0.01 * (rank + rank2) + 0.001 * far)
                        if cost < best[0]:
                            best = (cost, cand, start)
        nxt, start = best[1], best[2]
        if start != z:
            items.append(("shaft", z, start, 0.0, 0.0, len(centres) - 1))
        items.append(("belt" if st.type in ("belt", "chain") else "gear", start, nxt, r1, r2, j))
        placed += [(start, r1), (nxt, r2)]
        z = nxt
        centres.append(z)
        if len(centres) - 1 in rims:
            placed.append((z, rims[len(centres) - 1]))
    return centres, items


def flywheel_shaft(drive, flywheel) -> int | None:
    """Index in ``drive.shafts`` of the shaft carrying ``flywheel`` (its ``shaft``: a drive
    shaft's index, or "pinion" — the last stage's driving shaft, as the guide-bar stage
    counts it — or "crank", the drive's output), None when there is none or it lies
    outside the drive."""
    shaft = getattr(flywheel, "shaft", None)
    n = len(getattr(drive, "stages", ()) or ())
    if isinstance(shaft, bool) or shaft is None:
        return None
    if isinstance(shaft, (int, np.integer)):
        idx = int(shaft)
    elif shaft == "pinion":
        idx = n - 1
    elif shaft == "crank":
        idx = n
    else:
        return None
    return idx if 0 <= idx <= n else None


def _flywheel_radius(stages, r, idx: int, flywheel) -> float:
    """The flywheel's rim radius on a schematic whose wheels have the radii ``r`` (per stage,
    driving and driven): in proportion to a pulley on its shaft ``idx`` (rim mean diameter :
    datum diameter), else a little larger than the shaft's wheels."""
    on_shaft = ([(stages[idx - 1], r[idx - 1][1], 2)] if idx >= 1 else []) + \
               ([(stages[idx], r[idx][0], 1)] if idx < len(r) else [])
    rim = getattr(flywheel, "rim", None)
    pulleys = [(rr, st.d1 if w == 1 else st.d2) for st, rr, w in on_shaft
               if st.type in ("belt", "chain") and st.d1 and st.d2]
    if rim is not None and pulleys:
        return pulleys[0][0] * rim.diameter / pulleys[0][1]
    return 1.3 * max([rr for _st, rr, _w in on_shaft] + [8.0])


def _flywheel_rim(view, placer: LabelPlacer, c, radius: float, text: str) -> None:
    """A flywheel seen end-on: its rim as two concentric circles, named by a leader; dashed,
    as hidden lines: it sits behind the wheel on its shaft, whose belt runs cross it (drawn
    solid, the belt's runs crossed the rim: page review 48, the shaper's transmission sheet)."""
    view.circle(c, radius, "HIDDEN", 0.5)
    view.circle(c, radius - 2.0 / view.scale, "HIDDEN", 0.35)
    for t in np.linspace(0, 2 * np.pi, 48)[:-1]:
        placer.block(view.p(c + (radius - 1.0 / view.scale) * np.exp(1j * t)), 1.6)
    placer.leader(view.p(c + radius * np.exp(0.75j * np.pi)), text, 3.5, prefer=-1 + 1j)


def drive_schematic(drive, info: TitleInfo, lang: str, flywheel=None) -> Sheet:
    """The drive's transmission schematic: the shafts seen end-on (front view), a motor,
    each belt or chain as its two wheels and the belt's straight runs, each gear pair as
    tangent pitch circles (and tip circles), a worm as a rectangle tangent to its wheel on
    the worm's axis (the worm's shaft then a line, the motor beside it seen from the side);
    the shafts numbered 0 (motor), I, II, …, the stages 1, 2, … by leaders; a table of n, P,
    T and one of the stages with their ratios, teeth and diameters. A ``flywheel`` (the
    flywheel stage's result) is drawn on its shaft (:func:`flywheel_shaft`) as a rim, two
    circles larger than the shaft's wheels, named by a leader, its J_F and rim in the notes."""
    gt = tr(lang)
    lab = LABELS[lang]
    s = Sheet(SIZE)
    area = _area(s)
    frame(s, replace(info, scale="—"))
    tb = title_block_box(s)
    ax0, ay0, ax1, ay1 = area
    _title(s, lab["drive"], area)
    stages = list(drive.stages)
    # each stage's two wheels in proportion; the largest wheel of the drive 34 units
    r = [(_schematic_radius(st, 1), _schematic_radius(st, 2)) for st in stages]
    biggest = max([max(a, b) for a, b in r] + [1.0])
    k = 34.0 / biggest
    r = [(max(a * k, 4.0 if st.type == "worm" else 6.0), max(b * k, 8.0)) for (a, b), st in zip(r, stages)]
    side_motor = bool(stages) and stages[0].type in ("coupling", "worm")
    fw_idx = flywheel_shaft(drive, flywheel)
    if fw_idx is not None and side_motor and fw_idx == 0:
        fw_idx = None                            # the motor's shaft drawn from the side
    r_fw = _flywheel_radius(stages, r, fw_idx, flywheel) if fw_idx is not None else 0.0
    centres, items = _layout_drive(stages, r, beside=True,
                                   rims={fw_idx: r_fw} if fw_idx is not None else None)
    pts = list(centres)
    if fw_idx is not None:
        pts += [centres[fw_idx] + (r_fw + 2.0) * (1 + 1j), centres[fw_idx] - (r_fw + 2.0) * (1 + 1j)]
    for kind, a, b, r1, r2, _ in items:
        if kind in ("coupling", "shaft"):
            continue
        for c0, rr in ((a, r1), (b, r2)):
            pts += [c0 + (rr + 2.0) * (1 + 1j), c0 - (rr + 2.0) * (1 + 1j)]
        if kind == "worm":
            pts += [a + 2.0 * r1]
    pts = np.array(pts)
    lo = complex(pts.real.min(), pts.imag.min())
    hi = complex(pts.real.max(), pts.imag.max())
    # the tables first, top right: the drawing takes the larger of the strip left of them
    # (the whole height) and the one under them (the whole width)
    table_w = 175.0
    tx = ax1 - table_w
    rows = [[shaft_numeral(sh.index), fmt.rpm(sh.speed_rpm), fmt.sig(sh.power / 1e3),
             fmt.sig(sh.torque)] for sh in drive.shafts]
    ybot = table(s, tx, ay1 - 6.0, [25, 50, 50, 50], rows, head=[lab["shaft"], lab["n"], lab["P"], lab["T"]],
                 title=lab["shafts"], title_height=3.5, height=3.0, row_h=6.0)
    srows = []
    for j, st in enumerate(stages):
        data = (f"{sub('d', '1')}={fmt.f(st.d1 * MM, 0)}, {sub('d', '2')}={fmt.f(st.d2 * MM, 0)} mm"
                if st.d1 else (f"{sub('z', '1')}={st.z1}, {sub('z', '2')}={st.z2}" if st.z1 else "—"))
        srows.append([str(j + 1), st.name(lang), fmt.sig(st.ratio), data])
    ybot = table(s, tx, ybot - 8.0, [12, 58, 25, 80], srows,
                 head=[tr(lang).pgettext("kinematic sheet", "No."), lab["stage"], lab["ratio"], lab["data"]],
                 title=lab["stages"], title_height=3.5, height=3.0, row_h=6.0)
    motor_room = 62.0
    span = complex(max(hi.real - lo.real, 1.0), max(hi.imag - lo.imag, 1.0))
    boxes = [(ax0 + 8.0 + motor_room, tb[3] + 10.0, tx - 14.0, ay1 - 10.0),
             (ax0 + 8.0 + motor_room, tb[3] + 10.0, ax1 - 10.0, ybot - 10.0)]
    fits = [min((bx1 - bx0) / span.real, (by1 - by0) / span.imag, 2.5) for bx0, by0, bx1, by1 in boxes]
    dx0, dy0, dx1, dy1 = boxes[int(np.argmax(fits))]
    sc = max(fits)
    view = s.view(complex((dx0 + dx1) / 2, (dy0 + dy1) / 2) - sc * (lo + hi) / 2, sc)
    placer = LabelPlacer(s, area=(ax0, tb[3] + 4, dx1 + 6, ay1))
    placer.block_box((tb[0] - 2, tb[1], tb[2], tb[3] + 2))
    placer.block_box((tx - 2, ybot - 2, ax1, ay1))
    # every shaft's centre (and a shaft drawn twice) kept clear of the labels
    for c0 in list(centres) + [it[2] for it in items if it[0] == "shaft"]:
        placer.block(view.p(c0), 3.0)

    def ring(c0, rr, size=1.2):
        for t in np.linspace(0, 2 * np.pi, 48)[:-1]:
            placer.block(view.p(c0 + rr * np.exp(1j * t)), size)

    # the motor: seen from the side on the worm's (or coupling's) axis, else end-on
    p0 = view.p(centres[0])
    if side_motor:
        worm = next((it for it in items if it[0] == "worm"), None)
        left = p0 - ((worm[3] * 1.3 * sc + 6.0) if worm is not None else 0.0)
        box = [left - 50.0 - 11.0j, left - 20.0 - 11.0j, left - 20.0 + 11.0j, left - 50.0 + 11.0j]
        s.polyline(box, "OUTLINE", closed=True, weight=0.5)
        s.line(left - 20.0, p0 if worm is None else left, "OUTLINE")
        s.text(left - 35.0, "M", 5.0, "TEXT", "center", "middle")
        hatched_line(s, left - 52.0 - 12.5j, left - 18.0 - 12.5j)
        placer.block_box((left.real - 54.0, left.imag - 16.0, left.real, left.imag + 11.0))
        for dx in (-14.0, -11.0):                       # the coupling: two short bars
            s.line(left + dx - 5.0j, left + dx + 5.0j, "OUTLINE", 0.5)
        placer.block_box((left.real - 15.0, left.imag - 5.5, left.real - 10.0, left.imag + 5.5))
        if stages[0].type == "coupling":                # its stage number
            placer.leader(left - 12.5 - 5.0j, "1", 3.5, prefer=1 - 1j)
        motor_at = left - 35.0 + 13.0j
    else:
        c = p0 - 32.0
        s.polyline([c - 12 - 12j, c + 12 - 12j, c + 12 + 12j, c - 12 + 12j], "OUTLINE", closed=True,
                   weight=0.5)
        s.text(c, "M", 5.0, "TEXT", "center", "middle")
        s.line(c + 12.0, p0, "OUTLINE", 0.35)
        hatched_line(s, c - 14 - 13.5j, c + 14 - 13.5j)
        placer.block_box((c.real - 14.0, c.imag - 17.0, p0.real, c.imag + 12.0))
        motor_at = c + 14.0j
    text = lab["motor"].format(m=drive.motor.designation)
    placer.text(motor_at, text, 3.0, "center", "bottom")
    for kind, a, b, r1, r2, j in items:
        if kind == "shaft":                      # a shaft drawn twice: a chain line joins them
            view.line(a, b, "CENTER")
            placer.block_segment(view.p(a), view.p(b), 1.0)
            continue
        st = stages[j]
        if kind == "coupling":
            continue
        if kind == "belt":
            view.circle(a, r1, "OUTLINE", 0.5)
            view.circle(b, r2, "OUTLINE", 0.5)
            for u0, u1 in _tangent_runs(a, r1, b, r2):
                view.line(u0, u1, "OUTLINE", 0.35)
                placer.block_segment(view.p(u0), view.p(u1), 1.5)
            ring(a, r1)
            ring(b, r2)
            u = (b - a) / abs(b - a)
            anchor = view.p((a + b) / 2 + 1j * u * (r1 + r2) / 2)
        elif kind == "gear":
            for c0, rr in ((a, r1), (b, r2)):
                view.circle(c0, rr, "CENTER")
                view.circle(c0, rr + 1.5 / sc, "OUTLINE", 0.35)
                ring(c0, rr + 0.75 / sc, 1.4)
            anchor = view.p(a + (b - a) * r1 / (r1 + r2))
        else:                                    # worm: rectangle on its axis, wheel above
            p = view.p(a)
            w, h = 2.6 * r1 * sc, 2.0 * r1 * sc
            s.polyline([p - w / 2 - h / 2 * 1j, p + w / 2 - h / 2 * 1j, p + w / 2 + h / 2 * 1j,
                        p - w / 2 + h / 2 * 1j], "OUTLINE", closed=True, weight=0.5)
            for t in np.linspace(-w / 2 + 0.2 * w, w / 2 - 0.3 * w, 4):
                s.line(p + t - h / 2 * 1j, p + t + 0.1 * w + h / 2 * 1j, "CONSTRUCTION")
            s.line(p - w / 2 - 8.0, p + w / 2 + 6.0, "CENTER")
            placer.block_box((p.real - w / 2 - 8, p.imag - h / 2 - 1, p.real + w / 2 + 6, p.imag + h / 2 + 1))
            view.circle(b, r2, "CENTER")
            view.circle(b, r2 + 1.5 / sc, "OUTLINE", 0.35)
            ring(b, r2 + 0.75 / sc, 1.4)
            anchor = p + w / 2 - 0.5 * h * 1j
        placer.leader(anchor, str(j + 1), 3.5, prefer=-1 + 1j if kind != "worm" else 1 - 1j)
    if fw_idx is not None:
        # the flywheel: a rim (two concentric circles) on its shaft, named by a leader
        _flywheel_rim(view, placer, centres[fw_idx], r_fw, gt.pgettext("kinematic sheet", "flywheel"))
    # shafts: a small circle (end view) and the shaft's number
    for idx, c0 in enumerate(centres):
        if idx == 0 and side_motor:
            continue
        if idx > 0 and stages[idx - 1].type == "coupling":
            continue                               # the coupled shaft is the next one's
        p = view.p(c0)
        copies = [p] + [view.p(it[2]) for it in items if it[0] == "shaft" and it[5] == idx]
        for q in copies:
            s.circle(q, 1.6, "OUTLINE", 0.35)
            placer.block(q, 2.0)
            placer.place_best(q, shaft_numeral(idx), 3.5, prefer=1 + 1j,
                              gaps=(1.5, 3.0, 5.0))
    # the pulleys' datum circles named only where there is a belt (the furnace drives have
    # none: page review 48)
    belt = any(getattr(st, "type", None) == "belt" for st in drive.stages)
    notes = [lab["not_scale" if belt else "not_scale_nobelt"], lab["motor"].format(m=drive.motor.designation)
             + f"  P = {fmt.f(drive.motor.power / 1e3, 2)} kW  n = {fmt.f(drive.motor.full_load_rpm, 0)} r/min"]
    if any(it[0] == "shaft" for it in items):
        notes.append(gt.pgettext("kinematic sheet", "a shaft's numeral written twice: the shaft drawn "
                                 "again beside its other wheel (joined by a chain line)"))
    if fw_idx is not None:
        rim = getattr(flywheel, "rim", None)
        notes.append(with_subscripts(gt.pgettext("kinematic sheet", "flywheel on shaft {s}: JF = {J} kg·m²"),
                                     "J_F").format(s=shaft_numeral(fw_idx), J=fmt.sig(flywheel.inertia))
                     + (f", D = {fmt.length(rim.diameter * MM)} mm" if rim is not None else "")
                     + gt.pgettext("kinematic sheet", " (dashed: behind the wheel on its shaft)"))
    _notes(s, notes)
    return s
