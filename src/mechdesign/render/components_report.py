"""Report pieces of the motion-scheme components, for any machine report: the motion cycle
diagram, the morphological matrix and the incomplete gear. Each ``*_context`` returns the
strings and rows its template section (``templates/<name>_section.<lang>.md.j2``) shows;
each ``make_*_figures`` draws the section's figures and returns name → path relative to
the report folder.

Heading level: the sections start with ``level`` hashes (default 2, ``##``: a section under
the machine's chapter such as "# 运动方案设计"); their sub-headings use one more. Labels of
figures and tables begin with ``label`` so that a report may hold two of the same kind.
Course units in the report: °, s, mm, rpm, rad/s.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..core.cycle import STATES, TWO_PI, Constraint, CycleDiagram, PhaseRef, resolve
from . import cycle_figures as cf
from ..i18n import N_, tr
from .fmt import e, f, md_paragraphs, md_text, mpl_text, residue, sig

DEG = 180.0 / np.pi
MM = 1e3
_OK = (N_("PASS"), N_("FAIL"))


def _heads(level: int) -> tuple[str, str]:
    if not 1 <= level <= 5:
        raise ValueError(f"heading level must be 1 … 5, not {level}")
    return "#" * level, "#" * (level + 1)


def _deg(x: float, digits: int = 1) -> str:
    return f(x * DEG, digits)


# --------------------------------------------------------------------------- cycle diagram


def _phase_rows(cycle: CycleDiagram, lang: str):
    """Per actuator: (name, [(start°, span°, state, label), …]), names as figure text."""
    return [(mpl_text(a.name(lang)),
             [(p.start * DEG, p.span * DEG, p.state, mpl_text(p.name(lang))) for p in a.phases])
            for a in cycle.actuators]


def _states_used(cycle: CycleDiagram, lang: str) -> dict[str, str]:
    used = []
    for a in cycle.actuators:
        for p in a.phases:
            if p.state not in used:
                used.append(p.state)
    return {s: STATES[s].name(lang) for s in STATES if s in used}


def _ref_text(cycle: CycleDiagram, ref: PhaseRef, lang: str) -> str:
    act = cycle.actuator(ref.actuator)
    ph = resolve(cycle, ref)
    _ = tr(lang)
    return _("{actuator} {phase}", actuator=act.name(lang), phase=ph.name(lang))


def constraint_text(cycle: CycleDiagram, c: Constraint, lang: str) -> str:
    """The requirement in words: the brief's text, or one made from the references."""
    if c.text(lang):
        return c.text(lang)
    a, b = _ref_text(cycle, c.a, lang), _ref_text(cycle, c.b, lang)
    m = _deg(c.margin, 1)
    _ = tr(lang)
    return (_("{a} ends at least {m}° before {b} starts", a=a, b=b, m=m) if c.kind == "before" else
            _("{a} lies within {b} (≥ {m}° to spare at both ends)", a=a, b=b, m=m))


def _links(cycle: CycleDiagram, checks):
    rows = {a.key: i for i, a in enumerate(cycle.actuators)}
    out = []
    for chk in checks:
        c = chk.constraint
        pa, pb = resolve(cycle, c.a), resolve(cycle, c.b)
        pieces_a = cf.window_pieces(pa.start * DEG, pa.span * DEG, cycle.origin * DEG)
        pieces_b = cf.window_pieces(pb.start * DEG, pb.span * DEG, cycle.origin * DEG)
        a0, b0 = pieces_a[0][0], pieces_b[0][0]
        a1 = pieces_a[-1][0] + pieces_a[-1][1]
        out.append((c.kind, (rows[c.a.actuator], a0, a1),
                    (rows[c.b.actuator], b0, b0 + pieces_b[0][1]), chk.ok))
    return out


def make_cycle_figures(cycle: CycleDiagram, fig_dir: Path, lang: str, checks,
                       prefix: str = "cycle") -> dict[str, str]:
    """The linear and the circular cycle diagrams: keys ``linear``, ``circular``; ``checks``
    are the stage's constraint checks (core.cycle.ConstraintCheck)."""
    rows = _phase_rows(cycle, lang)
    states = _states_used(cycle, lang)
    paths = {}
    for name, draw in (("linear", lambda p: cf.linear(p, lang, rows, cycle.origin * DEG,
                                                        _links(cycle, checks), states)),
                       ("circular", lambda p: cf.circular(p, lang, rows, cycle.origin * DEG, states))):
        draw(fig_dir / f"{prefix}_{name}.png")
        paths[name] = f"{fig_dir.name}/{prefix}_{name}.png"
    return paths


def cycle_context(cycle: CycleDiagram, lang: str, figs: dict[str, str], checks,
                  level: int = 2, label: str = "cycle") -> dict:
    """Strings and rows of ``cycle_section``: the phase table (degrees and seconds), the
    period formula, the stage's constraint checks with their slack, the verification rows."""
    _ = tr(lang)
    h, h3 = _heads(level)
    T, rpm = cycle.period, cycle.speed_rpm
    rows = []
    for a in cycle.actuators:
        for i, (ph, t0, dt) in enumerate(cycle.phase_times(a.key)):
            end = np.mod(ph.end, TWO_PI) * DEG
            end = 360.0 if end < 1e-6 else end
            rows.append([md_text(a.name(lang)) if i == 0 else "", md_text(ph.name(lang)),
                         f"{_deg(ph.start)} – {f(end, 1)}", _deg(ph.span), f(t0, 3), f(dt, 3)])
    ok_word, bad_word = (_(word) for word in _OK)
    check_rows, failed = [], []
    for i, chk in enumerate(checks, 1):
        text = md_text(constraint_text(cycle, chk.constraint, lang))
        check_rows.append([str(i), text, _deg(chk.slack, 2), f(chk.slack / cycle.shaft_speed, 3),
                           ok_word if chk.ok else f"**{bad_word}**"])
        if not chk.ok:
            failed.append(text)
    spans = [abs(sum(p.span for p in a.phases) - TWO_PI) for a in cycle.actuators]
    durations = [abs(sum(dt for _ph, _t0, dt in cycle.phase_times(a.key)) - T) for a in cycle.actuators]
    verify = [
        [_("sum of each actuator's phase angles − 360° (largest) /°"), residue(max(spans) * DEG, 360.0)],
        [_("sum of each actuator's phase durations − T (largest) /s"), residue(max(durations), T)],
    ]
    return {
        "h": h, "h3": h3, "label": label,
        "rpm": f(rpm, 2), "period": f(T, 3), "origin": _deg(cycle.origin, 1),
        "eq_period": rf"T = \frac{{60}}{{n}} = \frac{{60}}{{{f(rpm, 2)}}} = {f(T, 3)}\ \text{{s}}",
        "eq_duration": (r"t_i = \frac{\Delta\varphi_i}{360°}\,T = \frac{\Delta\varphi_i}{360°}"
                        rf"\times {f(T, 3)}\ \text{{s}}"),
        "rows": rows, "checks": check_rows, "failed": failed,
        "all_ok": all(c.ok for c in checks), "fig": figs, "verify": verify,
        "n_actuators": str(len(cycle.actuators)),
    }


# --------------------------------------------------------------------------- morphology


def morphology_context(m, lang: str, level: int = 2, label: str = "morph") -> dict:
    """Strings and rows of ``morphology_section`` for a
    :class:`mechdesign.brief.components.Morphology`: the matrix (functions × options, the
    chosen one bold), the count of schemes N = Π k_i as a formula, the chosen scheme."""
    _ = tr(lang)
    h, h3 = _heads(level)
    width = max(m.counts)
    head = [_("function")] + [_("option {j}", j=j + 1)
                                             for j in range(width)]
    align = "|:--|" + ":--|" * width
    rows, chosen = [], []
    for i, fn in enumerate(m.functions):
        name = md_text(fn.name_zh if _.zh else fn.name_en)
        cells = []
        for j in range(width):
            if j >= len(fn.options):
                cells.append("—")
                continue
            text = md_text(fn.options[j][0 if _.zh else 1])
            cells.append(f"**{text}** ✓" if j == fn.chosen else text)
        rows.append([f"{chr(ord('A') + i)}. {name}" if i < 26 else name] + cells)
        chosen.append([f"{chr(ord('A') + i)}{fn.chosen + 1}" if i < 26 else str(fn.chosen + 1),
                       name, md_text(fn.options[fn.chosen][0 if _.zh else 1])])
    counts = m.counts
    product = r" \times ".join(str(k) for k in counts)
    if len(set(counts)) == 1 and len(counts) > 1:
        eq = rf"N = {product} = {counts[0]}^{{{len(counts)}}} = {m.scheme_count}"
    else:
        eq = rf"N = \prod_i k_i = {product} = {m.scheme_count}"
    code = " + ".join(c[0] for c in chosen)
    reasons = md_paragraphs(m.reasons_zh if _.zh else m.reasons_en)
    return {"h": h, "h3": h3, "label": label, "head": head, "align": align, "rows": rows,
            "eq_count": eq, "count": str(m.scheme_count), "n_functions": str(len(counts)),
            "chosen": chosen, "code": code, "reasons": reasons}


# --------------------------------------------------------------------------- incomplete gear


def _motion_arcs_deg(g):
    s = g.motion_start * DEG
    e_ = s + g.motion_angle * DEG
    return [(s, min(e_, 360.0))] + ([(0.0, e_ - 360.0)] if e_ > 360.0 else [])


def make_intermittent_figures(g, curves, fig_dir: Path, lang: str,
                              prefix: str = "intermittent") -> dict[str, str]:
    """The driven wheel's angle and velocity against the driver angle (``curves``: the
    stage's core.intermittent.IntermittentCurves of the gear ``g``): key ``motion``."""
    theta, dm = curves.theta, curves.motion
    _ = tr(lang)
    jump = curves.jump
    if dm.omega is not None:
        vel = dm.omega
        vel_label = _("driven speed $\\omega_2$ (rad/s)")
        jump_text = rf"$\Delta\omega_2$ = {f(jump.omega2, 3)} rad/s"
    else:
        vel, vel_label = dm.ratio, r"$d\varphi_2/d\theta$"
        jump_text = rf"$\Delta(d\varphi_2/d\theta)$ = {f(jump.omega2, 3)}"
    path = fig_dir / f"{prefix}_motion.png"
    cf.intermittent_motion(path, lang, theta * DEG, dm.angle * DEG, vel, vel_label,
                           _motion_arcs_deg(g), jump_text,
                           None if dm.travel is None else dm.travel * MM)
    return {"motion": f"{fig_dir.name}/{prefix}_motion.png"}


def intermittent_context(g, curves, lang: str, figs: dict[str, str], level: int = 2,
                         label: str = "intermittent") -> dict:
    """Strings, rows and formulas (numbers substituted) of ``intermittent_section`` for a
    :class:`mechdesign.core.intermittent.IncompleteGear` and the stage's ``curves``
    (core.intermittent.IntermittentCurves)."""
    _ = tr(lang)
    h, h3 = _heads(level)
    m = g.module * MM
    z1, z2, n = g.z1, g.z2, g.teeth
    rows = []

    def row(name, sym, formula, value, unit):
        rows.append([_(name), sym, formula, value, unit])

    row(N_("module"), "$m$", "—", f(m, 2), "mm")
    row(N_("driver's notional full tooth count"), "$z_1$", "—", str(z1), "—")
    row(N_("teeth present on the driver"), "$z_1'$", "—", str(n), "—")
    row(N_("driven wheel teeth"), "$z_2$", "—", str(z2), "—")
    row(N_("driver pitch radius"), "$r_1$", f"$m z_1/2 = {f(m, 2)}\\times{z1}/2$",
        f(g.r1 * MM, 2), "mm")
    row(N_("driven pitch radius"), "$r_2$", f"$m z_2/2 = {f(m, 2)}\\times{z2}/2$",
        f(g.r2 * MM, 2), "mm")
    row(N_("driver tip radius"), "$r_{a1}$",
        f"$r_1 + h_a^* m = {f(g.r1 * MM, 2)} + {f(g.ha_star, 2)}\\times{f(m, 2)}$", f(g.ra1 * MM, 2), "mm")
    row(N_("driven tip radius"), "$r_{a2}$",
        f"$r_2 + h_a^* m = {f(g.r2 * MM, 2)} + {f(g.ha_star, 2)}\\times{f(m, 2)}$", f(g.ra2 * MM, 2), "mm")
    row(N_("centre distance"), "$a$", f"$m(z_1 + z_2)/2 = {f(m, 2)}\\times({z1} + {z2})/2$",
        f(g.centre_distance * MM, 2), "mm")
    row(N_("locking-arc radius"), "$R_L$", "$R_L = r_{a1}$", f(g.locking_radius * MM, 2), "mm")
    row(N_("driver's motion angle"), "$\\varphi_m$",
        f"$360°\\,z_1'/z_1 = 360°\\times{n}/{z1}$", _deg(g.motion_angle, 2), "°")
    row(N_("dwell angle"), "$\\varphi_d$", "$360° - \\varphi_m$", _deg(g.dwell_angle, 2), "°")
    row(N_("driven advance per cycle"), "$\\Delta\\varphi_2$",
        f"$360°\\,z_1'/z_2 = 360°\\times{n}/{z2}$", _deg(g.advance, 2), "°")
    if g.feed is not None:
        row(N_("sprocket pitch radius"), "$R_s$", "—", f(g.sprocket_radius * MM, 2), "mm")
        row(N_("feed per cycle"), "$L$",
            f"$R_s\\,\\Delta\\varphi_2 = {f(g.sprocket_radius * MM, 2)}\\times{f(g.advance, 4)}$",
            f(g.feed * MM, 2), "mm")
    row(N_("ratio while meshing"), "$i_{12}$", f"$z_2/z_1 = {z2}/{z1}$", f(z2 / z1, 4), "—")
    row(N_("motion/dwell ratio"), "$k$", "$\\varphi_m/\\varphi_d$", f(g.motion_dwell_ratio, 4), "—")
    row(N_("kinematic coefficient"), "$\\tau$", "$t_m/T = \\varphi_m/360°$", f(g.tau, 4), "—")
    if g.stations is not None:
        row(N_("dwells per driven revolution"), "$z_2/z_1'$", f"${z2}/{n}$",
            str(g.stations), "—")
    times = curves.times
    if times is not None:
        T, tm, td = times
        rpm = g.driver_speed * 60 / TWO_PI
        row(N_("cycle time"), "$T$", f"$60/n_1 = 60/{f(rpm, 2)}$", f(T, 3), "s")
        row(N_("motion time"), "$t_m$", "$\\tau T$", f(tm, 3), "s")
        row(N_("dwell time"), "$t_d$", "$T - t_m$", f(td, 3), "s")
    jump = curves.jump
    per_rad = g.driver_speed is None
    if per_rad:
        row(N_("jump of $d\\varphi_2/d\\theta$ at engagement"), "$\\Delta(d\\varphi_2/d\\theta)$",
            f"$z_1/z_2 = {z1}/{z2}$", sig(jump.omega2, 4), "—")
    else:
        row(N_("jump of the driven speed at engagement"), "$\\Delta\\omega_2$",
            f"$\\omega_1 z_1/z_2 = {sig(g.driver_speed, 4, group=False)}\\times{z1}/{z2}$", sig(jump.omega2, 4), "rad/s")
        row(N_("jump of the pitch-line speed"), "$\\Delta v$",
            "$\\omega_1 r_1$", f(jump.pitch_speed * MM, 2), "mm/s")
        if jump.chain_speed is not None:
            row(N_("jump of the chain speed"), "$\\Delta v_c$", "$R_s\\,\\Delta\\omega_2$",
                f(jump.chain_speed * MM, 2), "mm/s")

    eqs = {
        "motion": (rf"\varphi_m = \frac{{360°\,z_1'}}{{z_1}} = \frac{{360° \times {n}}}{{{z1}}} = "
                   rf"{_deg(g.motion_angle, 2)}°,\qquad \varphi_d = 360° - \varphi_m = {_deg(g.dwell_angle, 2)}°"),
        "advance": (rf"\Delta\varphi_2 = \frac{{360°\,z_1'}}{{z_2}} = \frac{{360° \times {n}}}{{{z2}}} = "
                    rf"{_deg(g.advance, 2)}°"
                    + (rf",\qquad L = R_s\,\Delta\varphi_2 = {f(g.sprocket_radius * MM, 2)} \times "
                       rf"{f(g.advance, 4)} = {f(g.feed * MM, 2)}\ \text{{mm}}" if g.feed is not None else "")),
        "ratios": (rf"k = \frac{{t_m}}{{t_d}} = \frac{{\varphi_m}}{{\varphi_d}} = \frac{{{_deg(g.motion_angle, 2)}}}"
                   rf"{{{_deg(g.dwell_angle, 2)}}} = {f(g.motion_dwell_ratio, 4)},\qquad "
                   rf"\tau = \frac{{t_m}}{{T}} = \frac{{\varphi_m}}{{360°}} = {f(g.tau, 4)}"),
        "centre": (rf"a = \frac{{m (z_1 + z_2)}}{{2}} = \frac{{{f(m, 2)} \times ({z1} + {z2})}}{{2}} = "
                   rf"{f(g.centre_distance * MM, 2)}\ \text{{mm}}"),
        "jump": ((rf"\Delta\left(\frac{{d\varphi_2}}{{d\theta}}\right) = \frac{{z_1}}{{z_2}} = "
                  rf"\frac{{{z1}}}{{{z2}}} = {sig(jump.omega2, group=False)}") if per_rad else
                 (rf"\Delta\omega_2 = \omega_1 \frac{{z_1}}{{z_2}} = {sig(g.driver_speed, group=False)} \times "
                  rf"\frac{{{z1}}}{{{z2}}} = {sig(jump.omega2, group=False)}\ \text{{rad/s}}")),
    }
    required = []
    if g.requested_motion_angle is not None:
        required.append([_("driver's motion angle"),
                         _deg(g.requested_motion_angle, 2) + "°", _deg(g.motion_angle, 2) + "°",
                         e((g.motion_angle - g.requested_motion_angle) * DEG)])
    if g.requested_advance is not None:
        if g.sprocket_radius is not None and g.feed is not None:
            required.append([_("feed per cycle"),
                             f(g.requested_advance * g.sprocket_radius * MM, 2) + " mm",
                             f(g.feed * MM, 2) + " mm",
                             e((g.advance - g.requested_advance) * g.sprocket_radius * MM)])
        else:
            required.append([_("driven advance per cycle"),
                             _deg(g.requested_advance, 2) + "°", _deg(g.advance, 2) + "°",
                             e((g.advance - g.requested_advance) * DEG)])

    # Verification: equal pitch arcs rolled on both wheels, and the simulated motion.
    integral = curves.advance_integral
    arc = n * np.pi * g.module
    verify = [
        [_("pitch arc rolled by the driver $r_1\\varphi_m - z_1'\\pi m$ /mm"),
         residue((g.r1 * g.motion_angle - arc) * MM, arc * MM)],
        [_("pitch arc rolled by the driven wheel $r_2\\Delta\\varphi_2 - z_1'\\pi m$ /mm"),
         residue((g.r2 * g.advance - arc) * MM, arc * MM)],
        [_("simulation: $\\int_0^{2\\pi} (d\\varphi_2/d\\theta)\\,d\\theta - \\Delta\\varphi_2$ /°"),
         e((integral - g.advance) * DEG)],
        [_("simulation: largest driven speed in the dwell /(rad/s)"),
         e(curves.dwell_speed_max)],
    ]
    return {"h": h, "h3": h3, "label": label, "rows": rows, "eq": eqs, "required": required,
            "fig": figs, "notes": [note.zh if _.zh else note.en for note in g.notes],
            "verify": verify, "z1": str(z1), "z2": str(z2), "teeth": str(n),
            "motion_start": _deg(g.motion_start, 1),
            "motion_end": f(np.mod(g.motion_start + g.motion_angle, TWO_PI) * DEG, 1),
            "per_radian": per_rad}
