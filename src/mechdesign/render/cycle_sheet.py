"""The motion cycle diagram sheet (运动循环图, A3): the linear (rectangular) diagram of a
machine's :class:`~mechdesign.core.cycle.CycleDiagram` against the main-shaft angle φ —
one bar per actuator, each phase a box from its start to its end with its name, the
phase boundaries' angles written under the bar, φ from the diagram's origin over one
turn at a stated scale μφ (°/mm) — and a table of the phases. Only reads the result."""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..i18n import N_
from . import fmt
from .labels import LabelTable, pgettext
from .sheet import (LabelPlacer, Sheet, TitleInfo, fit_height, frame, heading,
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
    "scale": N_("angle scale μφ = {m} °/mm"),
    "table": N_("Phases of the actuators"),
    "actuator": N_("Actuator"),
    "phase": N_("Phase"),
    "start": N_("start φ (°)"),
    "end": N_("end φ (°)"),
    "span": N_("span Δφ (°)"),
    "period": N_("period T = {t} s"),
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
                yb: float, yt: float) -> None:
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
            return


def _phase_label(s: Sheet, text: str, state: str, xa: float, xb: float, yb: float,
                 yt: float) -> None:
    """A phase's name inside its box (see :func:`label_box`), :data:`GAP` clear of the
    transition lines, the outline and the diagonal — as large as fits (3 mm down to 1.8 mm),
    left out when it does not fit (the table under the diagram names every phase)."""
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
            return


def cycle_sheet(diagram, info: TitleInfo, lang: str) -> Sheet:
    """The A3 cycle sheet of ``diagram`` (core.cycle.CycleDiagram) at the smallest angle
    scale μφ of 1, 1.25, 1.5, 2 °/mm whose 360° fit the sheet beside the actuators' names."""
    lab = LABELS[lang]
    s = Sheet("A3")
    x0, y0, x1, y1 = s.inner
    acts = list(diagram.actuators)
    names = [a.name(lang) for a in acts]
    name_w = max(text_width(nm, 3.5) for nm in names) + 8.0
    left = x0 + 8.0 + name_w
    mu = next((m for m in MU_PHI if 360.0 / m <= x1 - 14.0 - left), MU_PHI[-1])
    frame(s, replace(info, scale=f"{sub('μ', 'φ')} = {fmt.exact(mu)} °/mm"))
    tb = title_block_box(s)
    origin = float(diagram.origin) * DEG
    width = 360.0 / mu
    right = left + width
    heading(s, complex((left + right) / 2, y1 - 12.0), lab["title"], 5.0)
    bar_h, gap = 10.0, 9.0
    top = y1 - 22.0
    placer = LabelPlacer(s)
    lowest = np.inf                       # the lowest angle written under a bar
    for r, (act, nm) in enumerate(zip(acts, names)):
        yt = top - r * (bar_h + gap)
        yb = yt - bar_h
        s.text(complex(left - 4.0, (yt + yb) / 2), nm, fit_height(nm, name_w - 6, 3.5), "TEXT",
               "right", "middle")
        s.polyline([complex(left, yb), complex(right, yb), complex(right, yt), complex(left, yt)],
                   "OUTLINE", closed=True, weight=0.5)
        marks = set()
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
                    _tent_label(s, phase_name(ph, lang), ph.state == "work", pts, xa, xb, yb, yt)
                    continue
                _phase_label(s, phase_name(ph, lang), ph.state, xa, xb, yb, yt)
        # the boundaries' angles under the bar to 0.1° (as the table), one that would run
        # into the one before it a line lower
        right_end = [-np.inf, -np.inf]
        for val in sorted(marks, key=lambda v: (v - origin) % 360.0):
            xv = left + ((val - origin) % 360.0) / mu
            text = fmt.f(val, 1)
            half = text_width(text, 2.5) / 2
            row = 0 if xv - half > right_end[0] + 1.0 else 1
            right_end[row] = xv + half
            s.text(complex(xv, yb - 1.0 - 3.0 * row), text, 2.5, "TEXT", "center", "top")
            lowest = min(lowest, yb - 1.0 - 3.0 * row - 2.5)
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
    # the phases as a table, under the diagram, left of the title block
    rows = []
    for act, nm in zip(acts, names):
        for ph in act.phases:
            a = float(ph.start) * DEG
            rows.append([nm, phase_name(ph, lang), fmt.f(a % 360.0, 1),
                         fmt.f((a + float(ph.span) * DEG) % 360.0, 1),
                         fmt.f(float(ph.span) * DEG, 1)])
    ytable = ybar - 15.0
    row_h = min(6.0, (ytable - y0 - 6.0) / (len(rows) + 2))
    table(s, x0 + 8.0, ytable, [40, 40, 30, 30, 30], rows,
          head=[lab["actuator"], lab["phase"], lab["start"], lab["end"], lab["span"]],
          title=lab["table"], title_height=3.5, height=min(3.0, row_h * 0.55), row_h=row_h)
    period = 2 * np.pi / float(diagram.shaft_speed)
    s.text(complex(tb[0], tb[3] + 8.0), with_subscripts(lab["scale"], "μ_φ").format(m=fmt.exact(mu)) + "   "
           + lab["period"].format(t=fmt.sig(period)), 3.5, "TEXT")
    return s
