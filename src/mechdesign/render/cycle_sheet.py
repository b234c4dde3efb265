"""The motion cycle diagram sheet (运动循环图, A3): the linear (rectangular) diagram of a
machine's :class:`~mechdesign.core.cycle.CycleDiagram` against the main-shaft angle φ —
one bar per actuator, each phase a box from its start to its end with its name, the
phase boundaries' angles written under the bar, φ from the diagram's origin over one
turn at a stated scale μφ (°/mm) — across the upper part of the sheet; under it the
circular diagram (one ring per actuator, the first innermost, each phase an arc of its
ring from its start to its end, φ = 0 at the top and increasing clockwise, as the
report's), the table of the phases and the table of the timing checks. Only reads the
result."""
from __future__ import annotations

import unicodedata
from dataclasses import replace

import numpy as np

from ..i18n import N_
from . import fmt
from .labels import LabelTable, pgettext
from .sheet import (LABEL_CLEAR, Sheet, TitleInfo, fit_height, frame, heading,
                    sub, table, text_width, title_block_box, with_subscripts)

DEG = 180.0 / np.pi
MU_PHI = (1.0, 1.25, 1.5, 2.0)          # angle scales [°/mm], preferred first
STATE_NAMES = LabelTable({
    "rise": pgettext("cycle sheet", "rise"),
    "return": pgettext("cycle sheet", "return"),
    "dwell_high": N_("dwell (high)"),
    "dwell_low": N_("dwell (low)"),
    "move": N_("move"),
    "dwell": pgettext("cycle sheet", "dwell"),
    "work": N_("moving, work zone"),
    "clear": N_("moving, clear zone"),
})
LABELS = LabelTable({
    "title": N_("Motion cycle diagram (linear)"),
    "phi": pgettext("cycle sheet", "main-shaft angle φ (°)"),
    "scale": N_("angle scale μφ = {m}°/mm"),
    "table": N_("Phases of the actuators"),
    "actuator": N_("Actuator"),
    "phase": N_("Phase"),
    "start": N_("start φ (°)"),
    "end": N_("end φ (°)"),
    "span": N_("span Δφ (°)"),
    "period": N_("period T = {t} s"),
    "circular": N_("Circular motion cycle diagram (actuators from the inside out; φ measured clockwise from the top)"),
    "checks": N_("Timing checks"),
    "no": N_("No."),
    "requirement": N_("Requirement"),
    "slack_deg": N_("Slack/°"),
    "slack_s": N_("Slack/s"),
    "result": N_("Result"),
    "pass": N_("PASS"),
    "fail": N_("FAIL"),
})


def pieces(start: float, span: float, origin: float) -> list[tuple[float, float]]:
    """A phase [start, start + span) [°] as pieces inside [origin, origin + 360)."""
    s = origin + np.mod(start - origin, 360.0)
    if s >= origin + 360.0 - 1e-9:
        s -= 360.0
    end = s + span
    if end <= origin + 360.0 + 1e-9:
        return [(s, end)]
    return [(s, origin + 360.0), (origin, end - 360.0)]


def phase_name(ph, lang: str) -> str:
    if getattr(ph, "label_msg", None) is not None:       # a label the program gives
        return ph.label_msg.text(lang)
    text = ph.label_zh if lang == "zh" else ph.label_en
    return text or STATE_NAMES[lang].get(ph.state, ph.state)


# clear space between a phase's name and the lines of its bar (the transition lines, the
# outline, a rise's or return's diagonal) [mm]
GAP = 1.5
# the height a name takes, ascender to descender, in text heights (a CJK glyph reaches
# below the baseline; the sheet's text box is ascender to baseline)
_EXTENT = 1.2
# the width a name takes, in estimated widths (sheet.text_width is ~5 % short for some
# Latin words: "down" in Noto Sans)
_WIDTH = 1.1


def label_box(text: str, state: str, h: float, xa: float, xb: float, yb: float, yt: float
              ) -> tuple[float, float, float, float]:
    """(x0, y0, x1, y1) of a phase's name of height ``h`` in its box [xa, xb] × [yb, yt]: a
    dwell's centred; a rise's (return's) in the upper left (right) corner, :data:`GAP` from
    the transition line and the outline."""
    w, th = _WIDTH * text_width(text, h), _EXTENT * h
    if state in ("rise", "move"):
        return xa + GAP, yt - GAP - th, xa + GAP + w, yt - GAP
    if state == "return":
        return xb - GAP - w, yt - GAP - th, xb - GAP, yt - GAP
    xm, ym = (xa + xb) / 2, (yt + yb) / 2
    return xm - w / 2, ym - th / 2, xm + w / 2, ym + th / 2


def _clear(box, state: str, xa: float, xb: float, yb: float, yt: float) -> bool:
    """``box`` lies inside the phase's box, :data:`GAP` from its lines, and (a rise or a
    return) :data:`GAP` from its diagonal (measured square to it, from the box's corner
    nearest to it)."""
    x0, y0, x1, y1 = box
    if x0 < xa + GAP - 1e-9 or x1 > xb - GAP + 1e-9 or y0 < yb + GAP - 1e-9 or y1 > yt - GAP + 1e-9:
        return False
    if state in ("rise", "move"):        # the diagonal (xa, yb) → (xb, yt); the box above it
        a, b, corner = complex(xa, yb), complex(xb, yt), complex(x1, y0)
    elif state == "return":              # the diagonal (xa, yt) → (xb, yb); the box above it
        a, b, corner = complex(xa, yt), complex(xb, yb), complex(x0, y0)
    else:
        return True
    u = (b - a) / abs(b - a)
    return (np.conj(u) * (corner - a)).imag >= GAP       # left of a → b, at least GAP


def _tent(up: bool, a: float, span: float, p0: float, p1: float, xa: float, xb: float,
          yb: float, yt: float) -> list[complex]:
    """The piece [p0, p1]° of a phase that moves all the time (starting at a°, span°): up to
    the bar's top and back (``up``: at the working end) or down to its foot and back (clear
    of the work), the turn at the phase's middle, drawn over the piece's x range xa…xb."""
    u0 = ((p0 - a) % 360.0) / span
    u1 = u0 + (p1 - p0) / span
    us = [u0] + ([0.5] if u0 < 0.5 < u1 else []) + [u1]

    def y(u):
        t = 1.0 - abs(2.0 * u - 1.0)
        return yb + (yt - yb) * t if up else yt - (yt - yb) * t

    return [complex(xa + (xb - xa) * (u - u0) / (u1 - u0), y(u)) for u in us]


def _tent_label(s: Sheet, text: str, up: bool, pts: list[complex], xa: float, xb: float,
                yb: float, yt: float) -> bool:
    """The name of a phase drawn as a tent (:func:`_tent`) where the tent leaves room: under
    its highest point (``up``) or over its lowest, :data:`GAP` clear of the outline and of
    the tent's lines — as large as fits (3 mm down to 1.8 mm), else left out (the table
    names every phase)."""
    xs = np.array([p.real for p in pts])
    ys = np.array([p.imag for p in pts])
    xc = float(xs[np.argmax(ys)] if up else xs[np.argmin(ys)])
    for h in (3.0, 2.5, 2.0, 1.8):
        w, th = _WIDTH * text_width(text, h), _EXTENT * h
        x0 = min(max(xc - w / 2, xa + GAP), xb - GAP - w)
        x1 = x0 + w
        y0, y1 = (yb + GAP, yb + GAP + th) if up else (yt - GAP - th, yt - GAP)
        if x0 < xa + GAP - 1e-9 or y1 > yt - GAP + 1e-9:
            continue
        line = np.interp([x0, x1], xs, ys)      # a tent's extreme over [x0, x1] is at an end
        if (up and np.all(line >= y1 + GAP)) or (not up and np.all(line <= y0 - GAP)):
            s.text(complex((x0 + x1) / 2, y1), text, h, "TEXT", "center", "top")
            return True
    return False


def _phase_label(s: Sheet, text: str, state: str, xa: float, xb: float, yb: float,
                 yt: float) -> bool:
    """A phase's name inside its box (see :func:`label_box`), :data:`GAP` clear of the
    transition lines, the outline and the diagonal — as large as fits (3 mm down to 1.8 mm),
    else not drawn (:func:`_outside_labels` writes it above the bar); whether it was drawn."""
    for h in (3.0, 2.5, 2.0, 1.8):
        box = label_box(text, state, h, xa, xb, yb, yt)
        if _clear(box, state, xa, xb, yb, yt):
            # anchored on the side of the transition line (the back end measures the real
            # width); the sheet's text box is ascender to baseline, the descent below it
            if state == "return":
                s.text(complex(box[2], box[3]), text, h, "TEXT", "right", "top")
            elif state in ("rise", "move"):
                s.text(complex(box[0], box[3]), text, h, "TEXT", "left", "top")
            else:
                s.text(complex((box[0] + box[2]) / 2, box[3]), text, h, "TEXT", "center", "top")
            return True
    return False


OUTSIDE_H = 2.5          # a name written outside its short piece [mm]


def _outside_labels(s: Sheet, items: list[tuple[float, str]], left: float, right: float,
                    yt: float) -> None:
    """The names of a bar's pieces too short to hold them (``items``: the piece's middle x,
    the name), in a row above the bar, each on a leader from its piece's top edge, side by
    side in the order of their pieces :data:`LABEL_CLEAR` × the height apart, kept over the
    bar (the lock-beam's bending wheel: its 342–348° far dwell and the 348–360° piece of its
    return, 7 mm and 15 mm long, were not named on the bar)."""
    if not items:
        return
    h = OUTSIDE_H
    items = sorted(items)
    widths = [_WIDTH * text_width(t, h) for _, t in items]
    space = LABEL_CLEAR * h + 0.5
    # left to right, each as near its piece as the one before allows; then the row pulled
    # back left where it runs past the bar's right end
    xs, end = [], left - 1e9
    for (xm, _), w in zip(items, widths):
        x = max(xm - w / 2, end + space)
        xs.append(x)
        end = x + w
    over = end - right
    if over > 0:
        xs = [x - over for x in xs]
        for k in range(len(xs) - 2, -1, -1):
            xs[k] = min(xs[k], xs[k + 1] - space - widths[k])
    base = yt + 2.8
    for (xm, text), w, x in zip(items, widths, xs):
        xc = x + w / 2
        s.line(complex(xm, yt), complex(min(max(xm, x), x + w), base - 1.0), "CONSTRUCTION")
        s.text(complex(xc, base + h), text, h, "TEXT", "center", "top")
        s.labels.append(s.entities[-1])


def polar(c: complex, r: float, phi_deg: float) -> complex:
    """The point at radius ``r`` from ``c`` at the shaft angle φ [°] of the circular diagram:
    φ = 0 at the top, increasing clockwise."""
    return c + r * np.exp(1j * np.radians(90.0 - phi_deg))


def _in_ring(box, c: complex, r_in: float, r_out: float, a0: float, a1: float) -> bool:
    """``box`` lies inside the ring r_in…r_out between the shaft angles a0…a1 [°] (a0 < a1,
    clockwise), :data:`GAP` from its circles and its radial boundaries."""
    x0, y0, x1, y1 = box
    pts = [complex(x, y) for x in np.linspace(x0, x1, 5) for y in (y0, y1)] + \
          [complex(x, y) for x in (x0, x1) for y in np.linspace(y0, y1, 3)]
    for z in pts:
        d = z - c
        if not (r_in + GAP <= abs(d) <= r_out - GAP):
            return False
        phi = (90.0 - np.degrees(np.angle(d))) % 360.0
        rel = (phi - a0) % 360.0
        if rel > a1 - a0:
            return False
        # the distance to the two radial boundaries, square to them
        arm = abs(d) * np.sin(np.radians(min(rel, a1 - a0 - rel)))
        if min(rel, a1 - a0 - rel) < 90.0 and arm < GAP:
            return False
    return True


def circular_diagram(s: Sheet, acts, c: complex, r0: float, w: float, origin: float,
                     lang: str, keep_out=()) -> list:
    """The circular cycle diagram centred at ``c``: actuator i's ring r0 + i·w … r0 + (i+1)·w,
    each phase the arc of the ring's outer circle from its start to its end (clockwise from
    the top) and the radial lines at its boundaries, its name inside where it fits; the
    rings numbered, φ ticks every 30° outside, the origin's radius dash-dotted; a name that
    does not fit its arc outside the rings on a leader (:func:`_outside_arc_label`), clear
    of the boxes ``keep_out`` (the caption and the legend drawn later). Returns the text
    boxes it drew (for the legend beside it)."""
    outer = r0 + len(acts) * w
    s.circle(c, r0, "OUTLINE", 0.35)
    boxes = []
    missing = []                          # (angle, radius, name) of the arcs too short
    for i, act in enumerate(acts):
        r_in, r_out = r0 + i * w, r0 + (i + 1) * w
        bounds = []
        for ph in act.phases:
            a, span = (float(ph.start) * DEG) % 360.0, float(ph.span) * DEG
            # the arc of the phase on the ring's outer circle: counter-clockwise from the
            # phase's end to its start
            s.arc(c, r_out, np.radians(90.0 - (a + span)), np.radians(90.0 - a), "OUTLINE", 0.5)
            s.line(polar(c, r_in, a), polar(c, r_out, a), "OUTLINE", 0.5)
            bounds.append(a)
            name = phase_name(ph, lang)
            mid = polar(c, r_in + w / 2, a + span / 2)
            for h in (3.0, 2.5, 2.0, 1.8):
                wd, th = _WIDTH * text_width(name, h), _EXTENT * h
                box = (mid.real - wd / 2, mid.imag - th / 2, mid.real + wd / 2, mid.imag + th / 2)
                if _in_ring(box, c, r_in, r_out, a, a + span):
                    s.text(complex(mid.real, box[3]), name, h, "TEXT", "center", "top")
                    boxes.append(box)
                    break
            else:
                missing.append((a + span / 2, (r_in + r_out) / 2, name))
        # the ring's number where it is farthest from the boundaries and the names
        best = None
        for phi in np.arange(0.0, 360.0, 2.0):
            z = polar(c, r_in + w / 2, phi)
            nb = (z.real - 2.4, z.imag - 2.4, z.real + 2.4, z.imag + 2.4)
            if any(not (nb[2] + 1 <= b[0] or b[2] + 1 <= nb[0] or nb[3] + 1 <= b[1] or b[3] + 1 <= nb[1])
                   for b in boxes):
                continue
            room = min(abs(((phi - b + 180.0) % 360.0) - 180.0) for b in bounds)
            if best is None or room > best[0]:
                best = (room, z, nb)
        if best is not None:
            s.circle(best[1], 2.2, "OUTLINE", 0.25)
            s.text(best[1], str(i + 1), 2.5, "TEXT", "center", "middle")
            boxes.append(best[2])
    for deg in range(0, 360, 30):
        s.line(polar(c, outer, deg), polar(c, outer + 2.0, deg), "OUTLINE", 0.35)
        s.text(polar(c, outer + 5.0, deg), f"{deg}°", 2.5, "TEXT", "center", "middle")
    ticks = [_box_at(polar(c, outer + 5.0, deg), f"{deg}°", 2.5, "center", -0.5)
             for deg in range(0, 360, 30)]
    for phi, r_mid, name in missing:
        boxes += _outside_arc_label(s, c, outer, phi, r_mid, name, boxes + ticks + list(keep_out))
    # the diagram's origin: its radius inside the rings; the sense of φ: an arrow clockwise
    s.line(c, polar(c, r0, origin), "CENTER")
    ra = 0.55 * r0
    s.arc(c, ra, np.radians(90.0 - 150.0), np.radians(90.0 - 60.0), "OUTLINE", 0.35)
    tip, u = polar(c, ra, 150.0), np.exp(1j * np.radians(90.0 - 150.0 - 90.0))   # clockwise tangent
    s.fill([tip, tip - 3.0 * u + 1.0j * u, tip - 3.0 * u - 1.0j * u])
    s.text(polar(c, 0.25 * r0, 105.0), "φ", 3.5, "TEXT", "center", "middle")
    return boxes


def _box_at(p: complex, text: str, h: float, halign: str, grow: float = 0.0):
    """The box of a text of height ``h`` centred vertically on ``p``, aligned ``halign``
    there, grown by ``grow`` on every side."""
    w = _WIDTH * text_width(text, h)
    x0 = {"left": p.real, "right": p.real - w}.get(halign, p.real - w / 2)
    return (x0 - grow, p.imag - 0.6 * h - grow, x0 + w + grow, p.imag + 0.6 * h + grow)


def _outside_arc_label(s: Sheet, c: complex, outer: float, phi: float, r_mid: float, name: str,
                       taken: list) -> list:
    """The name of an arc too short to hold it (its middle at shaft angle ``phi``, radius
    ``r_mid``), outside the rings beyond the φ ticks, on a leader from the arc's middle: at
    the nearest angle (±40°) and radius where its box keeps :data:`LABEL_CLEAR` × its height
    from the ``taken`` boxes and the leader crosses none of them. Returns its box."""
    from .sheet import boxes_overlap, clip_segment

    h = OUTSIDE_H
    start = polar(c, r_mid, phi)
    for dr in (11.0, 15.0, 19.0):
        for dphi in (0, 4, -4, 8, -8, 12, -12, 16, -16, 20, -20, 25, -25, 30, -30, 35, -35, 40, -40):
            p = polar(c, outer + dr, phi + dphi)
            halign = "left" if p.real > c.real + 2.0 else "right" if p.real < c.real - 2.0 else "center"
            box = _box_at(p + (0.8 if halign == "left" else -0.8 if halign == "right" else 0.0), name, h,
                          halign)
            if box[0] < s.inner[0] + 2.0 or box[2] > s.inner[2] - 2.0:
                continue
            if any(boxes_overlap(box, b, LABEL_CLEAR * h) for b in taken):
                continue
            if any(clip_segment(start, p, b) is not None for b in taken):
                continue
            s.line(start, p, "CONSTRUCTION")
            x = {"left": box[0], "right": box[2]}.get(halign, (box[0] + box[2]) / 2)
            s.text(complex(x, box[3] - 0.1 * h), name, h, "TEXT", halign, "top")
            s.labels.append(s.entities[-1])
            return [box]
    return []


def cycle_sheet(diagram, info: TitleInfo, lang: str, checks=()) -> Sheet:
    """The A3 cycle sheet of ``diagram`` (core.cycle.CycleDiagram) at the smallest angle
    scale μφ of 1, 1.25, 1.5, 2 °/mm whose 360° fit the sheet beside the actuators' names;
    under it the circular diagram, the phases and the timing ``checks``
    (core.cycle.ConstraintCheck) as tables."""
    lab = LABELS[lang]
    s = Sheet("A3")
    x0, y0, x1, y1 = s.inner
    acts = list(diagram.actuators)
    names = [a.name(lang) for a in acts]
    name_w = max(text_width(nm, 3.5) for nm in names) + 8.0
    left = x0 + 8.0 + name_w
    mu = next((m for m in MU_PHI if 360.0 / m <= x1 - 14.0 - left), MU_PHI[-1])
    frame(s, replace(info, scale=f"{sub('μ', 'φ')} = {fmt.exact(mu)}°/mm"))
    tb = title_block_box(s)
    origin = float(diagram.origin) * DEG
    width = 360.0 / mu
    right = left + width
    heading(s, complex((left + right) / 2, y1 - 12.0), lab["title"], 5.0)
    bar_h, gap = (14.0, 11.0) if len(acts) <= 4 else (10.0, 9.0)
    top = y1 - 22.0
    lowest = np.inf                       # the lowest angle written under a bar
    for r, (act, nm) in enumerate(zip(acts, names)):
        yt = top - r * (bar_h + gap)
        yb = yt - bar_h
        s.text(complex(left - 4.0, (yt + yb) / 2), nm, fit_height(nm, name_w - 6, 3.5), "TEXT",
               "right", "middle")
        s.polyline([complex(left, yb), complex(right, yb), complex(right, yt), complex(left, yt)],
                   "OUTLINE", closed=True, weight=0.5)
        marks = set()
        outside = []                      # (x middle, name) of the pieces too short for it
        for ph in act.phases:
            a, span = float(ph.start) * DEG, float(ph.span) * DEG
            for p0, p1 in pieces(a, span, origin):
                xa, xb = left + (p0 - origin) / mu, left + (p1 - origin) / mu
                for xv, val in ((xa, p0), (xb, p1)):
                    if left + 1e-6 < xv < right - 1e-6:
                        s.line(complex(xv, yb), complex(xv, yt), "OUTLINE", 0.5)
                        marks.add(round(val % 360.0, 6))
                if ph.state in ("rise", "move"):
                    s.line(complex(xa, yb), complex(xb, yt), "CONSTRUCTION")
                elif ph.state == "return":
                    s.line(complex(xa, yt), complex(xb, yb), "CONSTRUCTION")
                elif ph.state in ("work", "clear"):
                    pts = _tent(ph.state == "work", a, span, p0, p1, xa, xb, yb, yt)
                    s.polyline(pts, "CONSTRUCTION")
                    if not _tent_label(s, phase_name(ph, lang), ph.state == "work", pts, xa, xb, yb, yt):
                        outside.append(((xa + xb) / 2, phase_name(ph, lang)))
                    continue
                if not _phase_label(s, phase_name(ph, lang), ph.state, xa, xb, yb, yt):
                    outside.append(((xa + xb) / 2, phase_name(ph, lang)))
        _outside_labels(s, outside, left, right, yt)
        # the boundaries' angles under the bar to 0.1° (as the table), one that would come
        # nearer the one before it than the labels' space (LABEL_CLEAR) a row lower, that
        # space under the first row
        right_end = [-np.inf, -np.inf]
        pitch = 2.5 * (1.0 + LABEL_CLEAR)
        for val in sorted(marks, key=lambda v: (v - origin) % 360.0):
            xv = left + ((val - origin) % 360.0) / mu
            text = fmt.f(val, 1)
            half = text_width(text, 2.5) / 2
            row = 0 if xv - half >= right_end[0] + LABEL_CLEAR * 2.5 else 1
            right_end[row] = xv + half
            s.text(complex(xv, yb - 1.0 - pitch * row), text, 2.5, "TEXT", "center", "top")
            s.labels.append(s.entities[-1])
            lowest = min(lowest, yb - 1.0 - pitch * row - 2.5)
    # the φ axis under the bars (and under their angles)
    ybar = min(top - len(acts) * (bar_h + gap) + gap - 8.0, lowest - 3.0)
    s.line(complex(left, ybar), complex(right + 6.0, ybar), "OUTLINE", 0.35)
    s.fill([complex(right + 8.0, ybar), complex(right + 5.0, ybar + 1.0), complex(right + 5.0, ybar - 1.0)])
    for t in np.arange(0.0, 361.0, 30.0):
        xv = left + t / mu
        s.line(complex(xv, ybar), complex(xv, ybar + 1.5), "OUTLINE", 0.35)
        s.text(complex(xv, ybar - 1.5), fmt.exact((origin + t) % 360.0 if t < 360 else (origin % 360.0 or 360.0), decimals=2),
               2.5, "TEXT", "center", "top")
    s.text(complex((left + right) / 2, ybar - 7.0), lab["phi"], 3.5, "TEXT", "center", "top")
    period = 2 * np.pi / float(diagram.shaft_speed)
    s.text(complex(right, ybar - 7.0), with_subscripts(lab["scale"], "μ_φ").format(m=fmt.exact(mu)) + "   "
           + lab["period"].format(t=fmt.sig(period)), 3.0, "TEXT", "right", "top")
    ytop = ybar - 16.0                    # the lower part: circular diagram | tables
    # the circular diagram, left, as large as the lower part allows
    caption = lab["circular"]          # "… diagram (from the inside out; …)": two lines
    cut = next((k for k, ch in enumerate(caption) if k > 0 and unicodedata.normalize("NFKC", ch) == "("),
               len(caption))              # at the bracket, half- or full-width
    cap1, cap2 = caption[:cut].strip(), caption[cut:].strip()
    cap_h = fit_height(cap1, 150.0, 4.0) + (fit_height(cap2, 150.0, 3.0) + 1.5 if cap2 else 0.0)
    room = min(ytop - cap_h - 6.0 - (y0 + 6.0), 160.0)
    outer = room / 2 - 9.0                # the tick angles outside the rings
    cx = x0 + 8.0 + outer + 9.0
    if outer >= 12.0 * len(acts):         # (many actuators leave no room: the tables only)
        c = complex(cx, ytop - cap_h - 6.0 - room / 2)
        r0 = 0.3 * outer
        legend_y = ytop - cap_h - 4.0
        keep_out = [(cx - 80.0, ytop - cap_h - 1.0, cx + 80.0, ytop)]     # the caption
        keep_out += [(x0 + 6.0, legend_y - 4.5 * i - 3.6, x0 + 6.0 + text_width(f"{i + 1}  {nm}", 3.0),
                      legend_y - 4.5 * i) for i, nm in enumerate(names)]
        circular_diagram(s, acts, c, r0, (outer - r0) / len(acts), origin, lang, keep_out)
        s.text(complex(cx, ytop), cap1, fit_height(cap1, 150.0, 4.0), "TEXT", "center", "top")
        if cap2:
            s.text(complex(cx, ytop - fit_height(cap1, 150.0, 4.0) - 1.5), cap2, fit_height(cap2, 150.0, 3.0),
                   "TEXT", "center", "top")
        for i, nm in enumerate(names):    # the rings' numbers, upper left of the circle
            s.text(complex(x0 + 6.0, legend_y - 4.5 * i), f"{i + 1}  {nm}", 3.0, "TEXT", "left", "top")
    else:
        cx, outer = x0 - 10.0, 0.0        # the tables from the left edge
    # the phases and the timing checks as tables, right of the circle, above the title block
    rows = []
    for act, nm in zip(acts, names):
        for ph in act.phases:
            a = float(ph.start) * DEG
            rows.append([nm, phase_name(ph, lang), fmt.f(a % 360.0, 1),
                         fmt.f((a + float(ph.span) * DEG) % 360.0, 1),
                         fmt.f(float(ph.span) * DEG, 1)])
    crows = []
    if checks:
        from .components_report import constraint_text
        for k, chk in enumerate(checks, 1):
            crows.append([str(k), constraint_text(diagram, chk.constraint, lang),
                          fmt.f(chk.slack * DEG, 2), fmt.f(chk.slack / float(diagram.shaft_speed), 3),
                          lab["pass"] if chk.ok else lab["fail"]])
    tx = cx + outer + 18.0
    tw = x1 - 6.0 - tx
    lines = len(rows) + 2 + (len(crows) + 2 if crows else 0)
    row_h = min(6.5, (ytop - (tb[3] + 6.0) - (8.0 if crows else 0.0)) / lines)
    yb = table(s, tx, ytop, [tw * f for f in (0.24, 0.28, 0.16, 0.16, 0.16)], rows,
               head=[lab["actuator"], lab["phase"], lab["start"], lab["end"], lab["span"]],
               title=lab["table"], title_height=3.5, height=min(3.0, row_h * 0.55), row_h=row_h)
    if crows:
        table(s, tx, yb - 8.0, [tw * f for f in (0.06, 0.64, 0.11, 0.10, 0.09)], crows,
              head=[lab["no"], lab["requirement"], lab["slack_deg"], lab["slack_s"], lab["result"]],
              aligns=["center", "left", "center", "center", "center"],
              title=lab["checks"], title_height=3.5, height=min(3.0, row_h * 0.55), row_h=row_h)
    return s
