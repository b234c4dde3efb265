"""Prepare the cam section of any report (figures, strings, rows, formulas, CSV) and the
stand-alone cam report (``machine: cam``). Course units: mm, °, rpm, mm/s, rad/s."""
from __future__ import annotations

import csv
import unicodedata
from pathlib import Path

import numpy as np

from ..core.cam import DWELL, RISE, TranslatingFollower
from ..fileio import atomic_open
from ..i18n import N_, tr
from ..core.motion_laws import LAWS
from . import cam_figures as cf
from .fmt import e, f, length, md_text, sig, verdict
from .labels import LabelTable, md_symbols, pgettext

DEG = 180.0 / np.pi
MM = 1e3


_KIND = LabelTable({"rise": N_("rise"), "return": N_("return"), "far": N_("far dwell"),
                    "near": N_("near dwell"), "dwell": N_("dwell")})
_IMPACT = LabelTable({"none": pgettext("impact", "none"), "soft": N_("soft impact"),
                      "rigid": N_("rigid impact")})
CONTACT = LabelTable({"knife": N_("knife-edge"), "roller": N_("roller"), "flat": N_("flat-faced")})
#: the quantities of the displacement diagrams (translating, oscillating follower)
_DIAGRAM_NAMES = LabelTable({
    "translating": [N_("displacement"), N_("velocity"), N_("acceleration"), N_("jerk")],
    "oscillating": [pgettext("follower motion", "swing"), N_("angular velocity"),
                    N_("angular acceleration"), N_("angular jerk")],
})


def _segment_name(c, i, lang):
    seg = c.params.programme.segments[i]
    if seg.kind != DWELL:
        return _KIND[lang][seg.kind]
    level = c.params.programme.levels[i]
    if level <= 1e-12:
        return _KIND[lang]["near"]
    if abs(level - c.params.programme.stroke) <= 1e-12 * c.params.programme.stroke:
        return _KIND[lang]["far"]
    return _KIND[lang]["dwell"]


class _Units:
    """Display scaling of displacement and its derivatives (time or per-radian)."""

    def __init__(self, c):
        p = c.params
        self.osc = p.oscillating
        self.omega = p.omega
        w = p.omega or 1.0
        if self.osc:
            self.s_scale, self.s_unit, self.s_sym = DEG, "°", "φ"
            if p.omega:
                self.scales = [w, w * w, w ** 3]
                self.units = ["rad/s", "rad/s²", "rad/s³"]
                self.syms = ["dφ/dt", "d²φ/dt²", "d³φ/dt³"]
                self.tex = [r"\dot{\varphi}", r"\ddot{\varphi}", r"\dddot{\varphi}"]
            else:
                self.scales = [1.0, 1.0, 1.0]
                self.units = ["—", "1/rad", "1/rad²"]
                self.syms = ["dφ/dδ", "d²φ/dδ²", "d³φ/dδ³"]
        else:
            self.s_scale, self.s_unit, self.s_sym = MM, "mm", "s"
            if p.omega:
                self.scales = [MM * w, MM * w * w, MM * w ** 3]
                self.units = ["mm/s", "mm/s²", "mm/s³"]
                self.syms = ["v", "a", "j"]
                self.tex = ["v", "a", "j"]
            else:
                self.scales = [MM, MM, MM]
                self.units = ["mm/rad", "mm/rad²", "mm/rad³"]
                self.syms = ["ds/dδ", "d²s/dδ²", "d³s/dδ³"]

    def derivs(self, m):
        return [m.ds * self.scales[0], m.d2s * self.scales[1], m.d3s * self.scales[2]]


def _ylabels(u: _Units, lang: str):
    names = _DIAGRAM_NAMES[lang]["oscillating" if u.osc else "translating"]
    syms = [u.s_sym] + u.syms
    units = [u.s_unit] + u.units
    return [f"{n} {s} ({un})" for n, s, un in zip(names, syms, units)]


def _segments_deg(c, lang="en"):
    prog = c.params.programme
    return [(float(prog.starts[i] * DEG), float((prog.starts[i] + prog.spans[i]) * DEG), seg.kind,
             _segment_name(c, i, lang)) for i, seg in enumerate(prog.segments)]


def _impulses(c):
    """Where a derivative is infinite: (δ [°], panel, sign). A velocity jump makes the
    acceleration (panel 2) and jerk (panel 3) infinite; an acceleration jump the jerk."""
    out = []
    for b in c.boundaries + list(c.drawing.internal_jumps):
        if b.impact == "rigid":
            out += [(b.delta * DEG, 2, np.sign(b.velocity_jump)), (b.delta * DEG, 3, 0.0)]
        elif b.impact == "soft":
            out.append((b.delta * DEG, 3, np.sign(b.acceleration_jump)))
    return out


def make_cam_figures(c, fig_dir: Path, lang: str, prefix: str = "cam") -> dict[str, str]:
    """Draw the cam figures; return name → path relative to the report folder."""
    paths = {}

    def out(name):
        paths[name] = f"{fig_dir.name}/{prefix}_{name}.png"
        return fig_dir / f"{prefix}_{name}.png"

    g = c.grid
    u = _Units(c)
    # Close the curves at 360°, and add each segment's left-hand limit at its end (stored by
    # the cam stage) so that velocity and acceleration jumps plot as vertical steps.
    ends = c.drawing.segment_ends
    delta = np.concatenate([g.delta, [2 * np.pi], [d for d, _ in ends]])
    first = [g.motion.s[0], g.motion.ds[0], g.motion.d2s[0], g.motion.d3s[0]]
    ys = [np.concatenate([col, [first[k]], [v[k] for _, v in ends]])
          for k, col in enumerate((g.motion.s, g.motion.ds, g.motion.d2s, g.motion.d3s))]
    scales = [u.s_scale] + u.scales
    order = np.argsort(delta, kind="stable")
    d_plot, ys = delta[order], [y[order] * sc for y, sc in zip(ys, scales)]
    segs = _segments_deg(c, lang)
    cf.svaj(out("svaj"), lang, d_plot * DEG, ys, _ylabels(u, lang), segs, _impulses(c))
    limits = [None if s.limit is None else s.limit * DEG for s in c.segments]
    clip = 6 * c.base_radius * MM
    cf.pressure_and_curvature(out("alpha"), lang, g.delta * DEG, g.pressure_angle * DEG, limits,
                              segs, g.rho_pitch * MM, g.rho_actual * MM, g.roller_radius * MM, clip)
    n = len(g.delta)
    step = max(1, int(round(np.radians(30) / (2 * np.pi / n))))
    marks = [(f"{int(round(g.delta[i] * DEG))}°", i) for i in range(0, n, step)]
    pivot = None
    if "pivot" in g.extras:
        pivot = complex(g.extras["pivot"]) * MM
    outline = g.actual if getattr(c, "outline", None) is None else c.outline
    cf.profile(out("profile"), lang, g.pitch * MM, outline * MM, c.base_radius * MM,
               g.roller_radius * MM, marks, g.rotation, g.follower_point[0] * MM, pivot,
               flat=c.params.follower.kind == "flat")
    return paths


def _law_eqs(c, i, u: _Units, lang):
    """LaTeX lines of one rise/return with the numbers substituted."""
    prog = c.params.programme
    seg = prog.segments[i]
    law = LAWS[seg.law]
    start, span = prog.starts[i] * DEG, prog.spans[i] * DEG
    lift = prog.lifts[i] * u.s_scale
    level = prog.levels[i] * u.s_scale
    S, S1, S2 = law.latex
    sym = "\\varphi" if u.osc else "s"
    unit = "°" if u.osc else "\\text{mm}"
    numerator = r"\delta" if f(start, 1) == f(0.0, 1) else rf"\delta - {f(start, 1)}°"
    head = (rf"u = \frac{{{numerator}}}{{\Phi}},\quad \Phi = {f(span, 1)}°"
            rf" = {sig(np.radians(span), group=False)}\ \text{{rad}}")
    if seg.kind == RISE and level > 1e-9:
        s_eq = rf"{sym} = {f(level, 2)} + {f(abs(lift), 2)}\,S(u)"
    elif seg.kind == RISE:
        s_eq = rf"{sym} = {f(abs(lift), 2)}\,S(u)"
    else:
        s_eq = rf"{sym} = {f(level, 2)} - {f(abs(lift), 2)}\,S(u)"
    s_eq += rf"\quad ({unit.strip()})"
    # Derivatives in SI: rad for an oscillating follower, mm for a translating one.
    amp = sig(abs(prog.lifts[i]), 4, group=False) if u.osc else f(abs(prog.lifts[i]) * MM, 2)
    sign = "" if seg.kind == RISE else "-"
    phi_rad = prog.spans[i]
    if u.omega:
        w = sig(u.omega, group=False)
        v_eq = (rf"{u.tex[0]} = {sign}\frac{{{amp}\,\omega}}{{\Phi}} S'(u) = {sign}"
                rf"\frac{{{amp} \times {w}}}{{{sig(phi_rad, group=False)}}} S'(u)")
        a_eq = (rf"{u.tex[1]} = {sign}\frac{{{amp}\,\omega^2}}{{\Phi^2}} S''(u) = {sign}"
                rf"\frac{{{amp} \times {w}^2}}{{{sig(phi_rad, group=False)}^2}} S''(u)")
    else:
        v_eq = (rf"\frac{{d{sym}}}{{d\delta}} = {sign}\frac{{{amp}}}{{\Phi}} S'(u)")
        a_eq = (rf"\frac{{d^2{sym}}}{{d\delta^2}} = {sign}\frac{{{amp}}}{{\Phi^2}} S''(u)")
    name = law.name(lang)
    _ = tr(lang)
    return {"title": _("{kind} {start}°–{end}°: {law}", kind=_KIND[lang][seg.kind], start=f(start, 0),
                       end=f(start + span, 0), law=name),
            "head": head, "S": rf"S(u) = {S}", "S1": rf"S'(u) = {S1}", "S2": rf"S''(u) = {S2}",
            "s": s_eq, "v": v_eq, "a": a_eq,
            "peaks": (f"C_v = {sig(law.cv, group=False)}, C_a = "
                      + (sig(law.ca, group=False) if np.isfinite(law.ca) else "∞")
                      + ", C_j = " + (sig(law.cj, group=False) if np.isfinite(law.cj) else "∞"))}


def purpose_line(section, lang: str) -> str:
    """The cam's purpose as the brief's designer wrote it (``purpose_zh`` / ``purpose_en`` of
    its :class:`~mechdesign.brief.cam.CamSection`, the report's language first, else the
    other), as the cam chapter's first paragraph; "" when the brief gives none."""
    if section is None:
        return ""
    zh, en = getattr(section, "purpose_zh", ""), getattr(section, "purpose_en", "")
    text = (zh or en) if lang.startswith("zh") else (en or zh)
    text = text.strip()
    if not text:
        return ""
    _ = tr(lang)
    if not _.zh:
        text = text[0].upper() + text[1:]
    last = unicodedata.name(text[-1], "")
    if unicodedata.category(text[-1]) != "Po" or "COMMA" in last or "COLON" in last:
        # a sentence's stop in the text's own language (the user's Chinese in an en report)
        text += tr("zh" if unicodedata.east_asian_width(text[-1]) in "WF" else "en")(".")
    return _("**Purpose:** {text}", text=md_text(text))


def cam_context(c, lang: str, figs: dict[str, str], csv_name: str, section=None) -> dict:
    """Strings, rows and formulas of the cam section (``section``: the brief's cam section,
    for the designer's statement of the cam's purpose)."""
    p = c.params
    fol = p.follower
    prog = p.programme
    u = _Units(c)
    _ = tr(lang)
    translating = isinstance(fol, TranslatingFollower)
    motion = _("translating") if translating else _("oscillating")
    contact = CONTACT[lang][fol.kind]
    follower_name = _("{motion} {contact} follower", motion=motion, contact=contact)
    rot = _("counter-clockwise") if p.rotation > 0 else _("clockwise")
    data = []

    def row(sym, name, value, unit):
        data.append([sym, name, value, unit])

    row("—", _("follower"), follower_name, "—")
    row("—", _("cam rotation"), rot, "—")
    if p.speed_rpm:
        row("$n$", _("cam speed"), f(p.speed_rpm, 2), _("rpm"))
    if translating:
        row("$h$", _("stroke"), f(prog.stroke * MM, 2), "mm")
    else:
        row("$\\varphi_{max}$", _("maximum swing"), f(prog.stroke * DEG, 2), "°")
        row("$a$", _("centre distance $L_{OA}$"), f(fol.pivot_distance * MM, 2), "mm")
        if fol.kind != "flat":
            row("$L$", _("arm length"), f(fol.arm_length * MM, 2), "mm")
    row("$r_0$", _("base radius (designed for the allowed pressure angle)") if c.base_radius_designed
        else _("base radius"), f(c.base_radius * MM, 2), "mm")
    if fol.kind == "roller":
        row("$r_r$", _("roller radius"), f(fol.roller_radius * MM, 2), "mm")
    if translating and fol.kind != "flat":
        fav = c.drawing.offset_favourable
        side = _("right") if c.offset > 0 else _("left")
        kind = _("favourable") if fav else _("unfavourable")
        value = f(abs(c.offset) * MM, 2)
        if abs(c.offset) > 0:
            value += _(" ({side}, {kind})", side=side, kind=kind)
        row("$e$", _("offset"), value, "mm")
    limit_rise = f(p.alpha_rise * DEG, 0)
    row("$[\\alpha]$", _("allowed pressure angle, rise"), limit_rise, "°")
    row("$[\\alpha']$", _("allowed pressure angle, return"), f(p.alpha_return * DEG, 0), "°")

    prog_rows = []
    for i, (seg, chk) in enumerate(zip(prog.segments, c.segments)):
        law = "—" if seg.law is None else LAWS[seg.law].name(lang)
        lift = "—" if seg.kind == DWELL else f(abs(prog.lifts[i]) * u.s_scale, 2)
        prog_rows.append([str(i + 1), _segment_name(c, i, lang),
                          f"{f(prog.starts[i] * DEG, 1)} – {f((prog.starts[i] + prog.spans[i]) * DEG, 1)}",
                          f(prog.spans[i] * DEG, 1), law, lift,
                          "—" if seg.kind == DWELL else _IMPACT[lang][chk.impact]])
    impacts = _IMPACT[lang]
    # Every point with an impact in order of cam angle: the joints where the velocity or the
    # acceleration jumps, and the jumps inside a law (the parabolic law's middle: 孙桓 names
    # soft impacts at the start, middle and end of such a segment).
    points = [(b.delta, _("{delta}° ({impact})", delta=f(b.delta * DEG, 1),
                          impact=impacts[b.impact]))
              for b in c.boundaries if b.impact != "none"]
    for b in c.drawing.internal_jumps:
        i = int(np.searchsorted(prog.starts, b.delta, side="right") - 1)
        mid = abs((b.delta - prog.starts[i]) / prog.spans[i] - 0.5) < 1e-9
        at = dict(delta=f(b.delta * DEG, 1), impact=impacts[b.impact],
                  motion=_segment_name(c, i, lang))
        points.append((b.delta, _("{delta}° ({impact}, middle of the {motion})", **at) if mid
                       else _("{delta}° ({impact}, inside the {motion})", **at)))
    joints = [text for _d, text in sorted(points, key=lambda p: p[0])]
    laws = [_law_eqs(c, i, u, lang) for i, seg in enumerate(prog.segments) if seg.kind != DWELL]

    # Geometry formulas (pitch curve by inversion, envelope, pressure angle).
    if translating:
        s0 = c.grid.initial_angle
        geo = {
            "s0": (rf"s_0 = \sqrt{{r_0^2 - e^2}} = \sqrt{{{f(c.base_radius * MM, 2)}^2 - "
                   rf"{f(abs(c.offset) * MM, 2)}^2}} = {f(s0 * MM, 2)}\ \text{{mm}}"),
            # exp(), not e^{…}: e is the offset here
            "pitch": (rf"\mathbf{{B}}(\delta) = \exp({'-' if p.rotation > 0 else ''}i\delta)"
                      rf"\left[e + i\,(s_0 + s)\right],\quad e = {f(c.offset * MM, 2)}\ \text{{mm}}"),
            # ds/dδ = v/ω where the table lists the velocity v (page review 48: eq. (18) re-
            # evaluated with the table's v gave 22.62° against its 21.70°)
            "alpha": (rf"\tan\alpha = \frac{{\left|{'' if p.rotation > 0 else '-'}\,ds/d\delta - e\right|}}"
                      rf"{{s_0 + s}}" + (rf",\quad \frac{{ds}}{{d\delta}} = \frac{{v}}{{\omega}},\ "
                                         rf"\omega = {sig(p.omega, group=False)}\ \text{{rad/s}}"
                                         if p.omega else "")) if fol.kind != "flat" else r"\alpha = 0",
        }
        if fol.kind == "flat":
            geo["pitch"] = (rf"\mathbf{{B}}(\delta) = \exp({'-' if p.rotation > 0 else ''}i\delta)"
                            rf"\left[{'' if p.rotation > 0 else '-'}\frac{{ds}}{{d\delta}} + i\,(r_0 + s)\right]")
            geo["s0"] = r"\rho = r_0 + s + \frac{d^2 s}{d\delta^2} > 0"
    else:
        phi0 = c.grid.initial_angle
        a, L, r0 = fol.pivot_distance * MM, fol.arm_length * MM, c.base_radius * MM
        geo = {
            "s0": (rf"\varphi_0 = \arccos\frac{{a^2 + L^2 - r_0^2}}{{2aL}} = \arccos\frac{{{f(a, 1)}^2 + "
                   rf"{f(L, 1)}^2 - {f(r0, 1)}^2}}{{2 \times {f(a, 1)} \times {f(L, 1)}}} = "
                   rf"{f(phi0 * DEG, 2)}°") if fol.kind != "flat" else
                  (rf"\varphi_0 = \arcsin\frac{{r_0}}{{a}} = {f(phi0 * DEG, 2)}°"),
            "pitch": (rf"x = a\cos\delta - L\cos(\delta - \varphi - \varphi_0),\quad "
                      rf"y = a\sin\delta - L\sin(\delta - \varphi - \varphi_0)")
            if (p.rotation < 0 and fol.rise_sense == "same") else
            (rf"\mathbf{{B}}(\delta) = \exp({'-' if p.rotation > 0 else ''}i\delta)\left[a + L\,"
             rf"\exp\left[i(\pi - k(\varphi_0 + \varphi))\right]\right],\quad k = {c.drawing.arm_side:+d}"),
            "alpha": r"\alpha = \angle(\mathbf{n},\ \mathbf{v}_B),\quad \mathbf{v}_B \perp AB",
        }
    geo["envelope"] = (r"\mathbf{B}_a = \mathbf{B} - r_r\,\mathbf{n},\quad \mathbf{n} = "
                       r"\frac{\pm i\,\mathbf{B}'}{|\mathbf{B}'|}")
    geo["rho"] = (r"\rho = \frac{|\mathbf{B}'|^3}{\mathbf{B}' \times \mathbf{B}''},\quad "
                  r"\rho_a = \rho - r_r")

    # Checks
    checks = []
    for i, chk in enumerate(c.segments):
        if chk.limit is None:
            continue
        ok = verdict(chk.ok, lang)
        # the segment's number only where its kind repeats (review45: "rise 2" read as a typo)
        name = _segment_name(c, i, lang)
        if sum(1 for sg in c.segments if sg.kind == chk.kind) > 1:
            name = _("{kind} (segment {n})", kind=name, n=i + 1)
        checks.append([_("max pressure angle, {segment}", segment=name),
                       f"{f(chk.max_pressure_angle * DEG, 2)}° ($\\delta$ = {f(chk.at * DEG, 1)}°)",
                       f"≤ {f(chk.limit * DEG, 0)}°", ok])
    # the profile's curvature checks, as the cam stage judged them
    from .summary import CURVATURE_NAMES

    check_names = {key: _(msgid) for key, msgid in CURVATURE_NAMES.items()}
    for chk in c.curvature_checks:
        if chk.key == "pitch_curvature":
            limit = f"> $r_r$ = {f(chk.limit * MM, 2)} mm"
        elif chk.key == "actual_curvature":
            limit = f"≥ {length(chk.limit * MM)} mm"
        else:
            limit = "> 0"
        checks.append([check_names[chk.key], f"{f(chk.value * MM, 2)} mm", limit, verdict(chk.ok, lang)])
    design_rows = []
    if c.min_base_radius is not None:
        what = (_("smallest base radius for a convex profile (ρ ≥ ρa,min)") if fol.kind == "flat" else
                _("smallest base radius for the allowed pressure angles"))
        design_rows.append([what
                            + (_(" ($e$ = {e} mm)", e=f(c.offset * MM, 2))
                               if translating and fol.kind != "flat" else ""),
                            f"{f(c.min_base_radius * MM, 2)} mm"])
    if c.best_offset is not None:
        r0b, eb = c.best_offset
        side = _.pgettext("side, short", "right") if eb > 0 else _.pgettext("side, short", "left")
        design_rows.append([_("best offset and its smallest base radius"),
                            _("$e$ = {e} mm ({side}), $r_0$ = {r0} mm", e=f(abs(eb) * MM, 2),
                              side=side, r0=f(r0b * MM, 2))])
    if c.face_extent is not None:
        lo, hi = c.face_extent
        if translating:
            width = 2 * max(abs(lo), abs(hi)) * MM
            design_rows.append([_("farthest contact from the axis (face width ≥ 2× this + 5–7 mm)"),
                                f"{f(max(abs(lo), abs(hi)) * MM, 2)} mm → {f(width + 7, 1)} mm"])
        else:
            design_rows.append([_("contact along the face from the pivot"),
                                f"{f(lo * MM, 2)} – {f(hi * MM, 2)} mm"])

    t = c.table
    tu = u.derivs(t.motion)
    table_rows = []
    for i in range(len(t.delta)):
        table_rows.append([f(t.delta[i] * DEG, 1), f(t.motion.s[i] * u.s_scale, 3),
                           f(tu[0][i], 3), f(t.pitch[i].real * MM, 3), f(t.pitch[i].imag * MM, 3),
                           f(t.actual[i].real * MM, 3), f(t.actual[i].imag * MM, 3),
                           f(t.pressure_angle[i] * DEG, 2)])
    # the exact largest pressure angle (each segment's, found by the cam stage), not a sample
    alpha_max = max((sg.max_pressure_angle for sg in c.segments),
                    default=float(np.max(c.grid.pressure_angle)))
    return {
        "purpose": purpose_line(section, lang),
        "follower": follower_name, "rotation": rot, "data_rows": data, "prog_rows": prog_rows, "s_unit": u.s_unit,
        "joints": _.pgettext("list", ", ").join(joints),
        "laws": laws, "geo": geo, "checks": checks, "design_rows": design_rows,
        "table_rows": table_rows, "table_step": f(p.table_step * DEG, 1),
        "table_head": [md_symbols(h) for h in (
            "δ/°", f"{u.s_sym}/{u.s_unit}", f"{u.syms[0]}/({u.units[0]})",
            "$x$/mm", "$y$/mm", "$x_a$/mm", "$y_a$/mm", "α/°")],
        "fig": figs, "csv": csv_name, "roller": fol.kind == "roller", "flat": fol.kind == "flat",
        "translating": translating,
        "warnings": [md_text(w.text(lang)) for w in c.warnings],
        "alpha_max": f(alpha_max * DEG, 2),
        "rr": f(c.grid.roller_radius * MM, 2), "r0": f(c.base_radius * MM, 2),
        "time_derivs": bool(p.omega),
        "omega": sig(p.omega) if p.omega else "",
    }


def write_cam_csv(c, folder: Path, name: str = "cam_profile") -> list[Path]:
    """Profile coordinates for CNC/CAD: at the report table's step and on the fine grid."""
    paths = []
    for prof, suffix in ((c.table, ""), (c.grid, "_fine")):
        path = folder / f"{name}{suffix}.csv"
        osc = c.params.oscillating
        with atomic_open(path, "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh)
            w.writerow(["delta_deg", "phi_deg" if osc else "s_mm", "pitch_x_mm", "pitch_y_mm",
                        "actual_x_mm", "actual_y_mm", "pressure_angle_deg", "rho_pitch_mm",
                        "rho_actual_mm"])
            s = prof.motion.s * (DEG if osc else MM)
            for i in range(len(prof.delta)):
                w.writerow([f"{prof.delta[i] * DEG:.4f}", f"{s[i]:.6f}",
                            f"{prof.pitch[i].real * MM:.6f}", f"{prof.pitch[i].imag * MM:.6f}",
                            f"{prof.actual[i].real * MM:.6f}", f"{prof.actual[i].imag * MM:.6f}",
                            f"{prof.pressure_angle[i] * DEG:.6f}",
                            f"{prof.rho_pitch[i] * MM:.6f}", f"{prof.rho_actual[i] * MM:.6f}"])
        paths.append(path)
    env = getattr(c, "envelope", None)
    if env is not None and (env.corners or env.edges):
        # the actual profile as it is cut, with the roller arcs and edges at the corners
        path = folder / f"{name}_outline.csv"
        with atomic_open(path, "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh)
            w.writerow(["actual_x_mm", "actual_y_mm"])
            for z in c.outline:
                w.writerow([f"{z.real * MM:.6f}", f"{z.imag * MM:.6f}"])
        paths.append(path)
    return paths


# --------------------------------------------------------------------------- machine: cam


# --------------------------------------------------------------------------- verification


def _verdict(ok, lang: str) -> str:
    if ok is None:
        return "—"
    return verdict(ok, lang)


def _sci(x: float, unit: str = "") -> str:
    return e(x) + (f" {unit}" if unit else "")


def cam_verification_rows(v, c, lang: str) -> list[list[str]]:
    """The cam self-checks as [item, result, reference / limit, verdict] rows."""
    from ..stages.cam import CAM_CHECK_NAMES

    _ = tr(lang)
    osc = c.params.oscillating
    s_scale, s_unit = (DEG, "°") if osc else (MM, "mm")
    step = f(v.fd_step * DEG, 1)
    rr = f(c.grid.roller_radius * MM, 2)
    rows = []
    for k in v.checks:
        name = _(CAM_CHECK_NAMES[k.key][1]).replace("r_r", "$r_r$")   # English msgid; plain in warnings
        ok = _verdict(k.passed, lang)
        if k.key == "angle_sum":
            rows.append([name, f"{f(k.detail['sum'] * DEG, 3)}°", "360°", ok])
        elif k.key == "closure":
            rows.append([name, _sci(k.value * s_scale, s_unit), f"≤ {e(k.limit * s_scale)} {s_unit}", ok])
        elif k.key == "stroke":
            rows.append([name, f"{f(k.detail['max'] * s_scale, 3)} {s_unit}",
                         _("stroke {value} {unit}", value=f(k.reference * s_scale, 3), unit=s_unit), ok])
        elif k.key in ("velocity_fd", "acceleration_fd", "curvature_fd"):
            rows.append([name, e(k.value), _("≤ {limit} (O(h²), h = {step}°)", limit=e(k.limit), step=step),
                         ok])
        elif k.key == "pressure_angle":
            rows.append([name, f"{e(k.value * DEG)}°", f"≤ {f(k.limit * DEG, 2)}°", ok])
        elif k.key in ("envelope", "interference", "gap", "face_support"):
            ref = f"≤ {f(k.limit * MM, 3)} mm" + _(" ($r_r$ = {rr} mm)", rr=rr) \
                if k.key != "face_support" else f"≤ {f(k.limit * MM, 3)} mm"
            rows.append([name, f"{e(k.value * MM)} mm", ref, ok])
        # "offset_curve" and "corner" carry no verdict: they say why the actual profile is the
        # envelope, not the plain offset curve; envelope_note states them in its paragraph
    return rows


def envelope_note(c, lang: str, verification=None) -> str:
    """A paragraph on the actual profile at the pitch curve's corners ('' when there are none);
    with the cam ``verification``, it also states how far the plain offset curve is off."""
    env = getattr(c, "envelope", None)
    if env is None or not (env.corners or env.edges):
        return ""
    _ = tr(lang)
    rr = f(env.roller_radius * MM, 2)
    edges = [k for k in env.corners if k.kind == "edge"]
    arcs = [k for k in env.corners if k.kind == "arc"]
    sep = _.pgettext("list", ", ")
    deg = lambda ks: sep.join(f"{f(k.delta * DEG, 1)}°" for k in ks)  # noqa: E731
    text = _("Where the follower's velocity jumps (rigid impact) the pitch curve has a corner, and the curve "
             "offset by $r_r$ along the normal is broken there: it is not the envelope of the roller circles. "
             "The actual profile is corrected to that envelope: ")
    parts = []
    if edges:
        parts.append(_("at $\\delta$ = {at} the two offset branches cross in a small loop whose points lie closer "
                       "than $r_r$ to the pitch curve (the roller would cut them away); the profile stops at "
                       "the crossing, a sharp edge, and there the roller centre leaves its designed path by "
                       "at most {d} mm", at=deg(edges), d=f(env.stand_off * MM, 3)))
    if arcs:
        parts.append(_("at $\\delta$ = {at} the offset branches leave a gap, filled by the arc of radius $r_r$ = {rr} mm "
                       "about the corner; there the follower moves as designed", at=deg(arcs), rr=rr))
    text += _.pgettext("clause separator", "; ").join(parts) + _.pgettext("sentence end", ". ")
    off = [k for k in getattr(verification, "checks", ()) if k.key == "offset_curve"]
    if off:
        from ..stages.cam import DIST_LIMIT

        held = [k.limit for k in verification.checks if k.key == "envelope"]
        text += _("The plain offset curve departs from the distance $r_r$ to the pitch curve by up to {d} mm, "
                  "where the actual profile is held to {limit} mm; it is therefore not used. ",
                  d=length(off[0].value * MM), limit=length((held[0] if held else DIST_LIMIT) * MM))
    # the files by what they hold, not by their names (delivered beside the report)
    text += _("The cut-away points in the coordinate table and in the cam profile coordinates "
              "delivered with the report are replaced by the edge; the whole actual profile (with "
              "the arcs) is delivered as the actual profile's outline coordinates and drawn in "
              "[@fig:cam-profile].")
    return text


