"""Prepare the lock-beam bender report (``machine: lockbeam``): figures and the template
context (strings, rows and LaTeX formulas with the numbers substituted).

Report units: mm, °, rpm, s, rad/s. The shared pieces come from the component reports
(morphological matrix, cycle diagram), the cam report (positioning cam; the bending cam
in a compact form) and the linkage report (feed mechanism).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ...i18n import N_, tr
from ...render import figures as fig
from ...render.legends import legend
from ...render.linkage_report import carried_note
from ...render.fmt import e, f, md_meta, md_text, rpm, sig, time_ratio
from ...render.fmt import verdict
from ...render.fmt import factor_for, gives
from ...render.labels import mpl_point
from .stages import grashof_margin

DEG = 180.0 / np.pi
MM = 1e3

#: The flow chart of the appendix's analysis program (:func:`program_appendix`): (kind, box,
#: what the step computes); "loop" is where "cond" returns to, "cond" has no table row.
PROGRAM_STEPS = (
    ("io", N_("input the brief's data"),
     N_("crank speed $n_1$; pivots $O_2$, $O_3$; lengths $O_2A$, $O_3D$, $DE$; guide line $y_E$")),
    ("loop", N_("crank angle $\\varphi_1$ = 0°, 10°, …, 350°"), N_("the crank angle of one row")),
    ("proc", N_("crank 2: crank()"), N_("position, velocity and acceleration of $A$")),
    ("proc", N_("RPR group 3–4: rpr()"),
     N_("$\\omega_4$, $\\varepsilon_4$ of the guide bar; position, velocity and acceleration of $D$")),
    ("proc", N_("RRP group 5–6: rrp()"),
     N_("$x_E$, $v_E$, $a_E$ of the slider; $\\omega_5$, $\\varepsilon_5$ of the rod")),
    ("io", N_("print one row"), N_("one row of the feed table in the original program's format")),
    ("cond", N_("$\\varphi_1$ < 350°?"), None),
)


def _literal(x: float) -> str:
    """A number of the brief as the program writes it (Python literal, m or rpm)."""
    return repr(round(float(x), 9))


def program_appendix(r: dict) -> dict | None:
    """The analysis program the seed (002) hands in, rewritten: the feed mechanism's
    kinematics by Assur groups (crank, RPR guide bar, RRP rod and slider) every 10° of the
    crank, printing the feed table in the seed's format. The report's appendix lists it
    (templates/lockbeam_program.py.j2) with the brief's numbers written in: ``data`` here.
    None when the feed linkage is not the guide-bar six-bar the program is written for (a
    guide bar through its pivot, D on the bar's line, a slider guide parallel to x)."""
    from ...core.mechanism import RPR, RRP, Crank, LinkPoint

    mech = r["params"].feed.mechanism
    groups = mech.groups
    crank = next((g for g in groups if isinstance(g, Crank)), None)
    rpr = next((g for g in groups if isinstance(g, RPR)), None)
    rrp = next((g for g in groups if isinstance(g, RRP)), None)
    if crank is None or rpr is None or rrp is None or rpr.a != crank.tip or rpr.offset != 0 \
            or abs(np.sin(rrp.guide_angle)) > 1e-12:
        return None
    d = next((g for g in groups if isinstance(g, LinkPoint) and g.name == rrp.b), None)
    if d is None or d.link != rpr.bar or d.origin != rpr.pivot or d.offset_angle != 0:
        return None
    m = mech.solve(np.array([0.0]))
    right = (m.points[rrp.c].pos[0] - m.points[rrp.b].pos[0]).real > 0
    o2, o3 = mech.frame_points[crank.pivot], mech.frame_points[rpr.pivot]
    data = {"rpm": _literal(abs(crank.omega) * 60 / (2 * np.pi)),
            "sense": "" if crank.omega > 0 else "-",
            "O2": f"{_literal(o2.real)}, {_literal(o2.imag)}", "crank": _literal(crank.length),
            "O3": f"{_literal(o3.real)}, {_literal(o3.imag)}", "bar": _literal(d.distance),
            "rod": _literal(rrp.length), "guide_y": _literal(rrp.guide_point.imag),
            "branch": "" if right else "-"}
    return {"template": "lockbeam_program.py.j2", "data": data, "steps": PROGRAM_STEPS,
            "table": "tbl:feed-seed"}


def grashof_sentence(a: float, b: float, c: float, d: float, lang: str) -> str:
    """Grashof's rule for the bending four-bar (a input rocker, b coupler, c arm on the
    wheel, d frame), with the numbers, in the report's language."""
    _ = tr(lang)
    names = {"a": a, "b": b, "c": c, "d": d}
    order = sorted(names, key=names.get)
    s_, l_ = order[0], order[-1]
    p_, q_ = order[1], order[2]
    lhs, rhs = names[s_] + names[l_], names[p_] + names[q_]
    # the list's comma in the report's language (a zh sentence had "mm, $p + q$")
    comma = _.pgettext("clause", ", ")
    nums = (f"$s + l = {s_} + {l_}$ = {f(names[s_] * MM, 2)} + {f(names[l_] * MM, 2)} = {f(lhs * MM, 2)} mm"
            f"{comma}$p + q = {p_} + {q_}$ = {f(rhs * MM, 2)} mm")
    tol = 1e-9 * max(names.values())
    if abs(lhs - rhs) <= tol:
        return (_("{nums}, equal: a change-point linkage, with a position where all four links "
                  "fall into line (the motion is uncertain there)", nums=nums))
    if lhs > rhs:
        return (_("{nums}; s + l > p + q: no link can turn fully (a triple rocker)", nums=nums))
    link = {"a": N_("the input rocker"), "b": N_("the coupler"),
            "c": N_("the arm on the wheel"), "d": N_("the frame")}[s_]
    return _("{nums}; $s$ + $l$ < $p$ + $q$: a Grashof linkage, whose shortest link ({link}) could "
             "turn fully relative to its neighbours", nums=nums, link=_(link))


def _ok(x: bool, lang: str) -> str:
    return verdict(x, lang)


# --------------------------------------------------------------------------- figures


def _timing_figure(path: Path, lang: str, r: dict):
    """Feed travel, pin lift and bending-wheel angle against the main-shaft angle, found by
    simulating the linkage and the two cams."""
    c = r["cycle"]
    _ = tr(lang)
    phi = c.shaft_angle * DEG
    order = np.argsort(phi)
    series = [(c.feed_s * MM, _("feed travel (mm)")),
              (c.pin_lift * MM, _("pin lift (mm)")),
              (c.wheel_angle * DEG, _("bending wheel (°)"))]
    with fig.figure(path, 3, (7.2, 5.6)) as axes:
        for ax, (y, label) in zip(axes, series):
            ax.plot(np.append(phi[order], 360.0), np.append(y[order], y[order][0]), lw=1.4, color="C0")
            ax.set_ylabel(label, fontsize=8)
            ax.set_xlim(0, 360)
            ax.set_xticks(np.arange(0, 361, 30))
            ax.grid(True, lw=0.4, color="0.85")
            for x in (c.pin_rise_angle * DEG, c.pin_down_angle * DEG):
                ax.axvline(x, color="C3", lw=0.7, ls="--")
        axes[-1].set_xlabel(_.pgettext("lockbeam", "main-shaft angle $\\varphi$ (°)"))


def _linkage_drawing(path: Path, lang: str, b, wheel_d: float):
    """The bending four-bar at its start (bold) and end positions, with the large wheel."""
    ds, dr = b.design, b.drawing
    _ = tr(lang)
    A, B = dr.A * MM, dr.B * MM
    B0 = ds.frame * MM
    with fig.figure(path, 1, (6.6, 4.4), sharex=False) as (ax,):
        t = np.linspace(0, 2 * np.pi, 200)
        ax.plot(B0 + wheel_d / 2 * MM * np.cos(t), wheel_d / 2 * MM * np.sin(t), color="0.6",
                lw=0.8, ls="--")
        ax.plot([0, B0], [0, 0], color="k", lw=0.8, ls="-.")
        for path in (dr.path_A, dr.path_B):
            z = path * MM
            ax.plot(z.real, z.imag, color="0.7", lw=0.6)
        for j in range(len(A)):
            bold = j in (0, len(A) - 1)
            col = ("C0" if j == 0 else "C3") if bold else "0.7"
            lw = 1.8 if bold else 0.6
            ax.plot([0, A[j].real, B[j].real, B0], [0, A[j].imag, B[j].imag, 0], color=col, lw=lw,
                    marker="o", ms=3 if bold else 1.5)
        for z, name in ((0j, "G0"), (complex(B0, 0), "B0")):
            ax.plot([z.real], [z.imag], "^", color="k", ms=7)
            ax.text(z.real, z.imag - 12, mpl_point(name), ha="center", va="top", fontsize=8)
        for j, tag in ((0, "1"), (len(A) - 1, "2")):
            ax.text(A[j].real, A[j].imag + 5, mpl_point(f"G{tag}"), fontsize=8, color="C0" if j == 0 else "C3")
            ax.text(B[j].real + 3, B[j].imag + 3, mpl_point(f"B{tag}"), fontsize=8, color="C0" if j == 0 else "C3")
        ax.set_aspect("equal")
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("y (mm)")
        ax.grid(True, lw=0.3, color="0.9")
        ax.set_title(_("large chain wheel Ø{d} (dashed)", d=f(wheel_d * MM, 0)), fontsize=8)


def _sweep_figure(path: Path, lang: str, b):
    _ = tr(lang)
    x = (b.sweep_input - b.design.alpha1) * DEG
    mean = b.output_swing / b.input_swing
    with fig.figure(path, 3, (7.0, 6.0)) as (ax1, ax2, ax3):
        ax1.plot(x, np.abs(b.sweep_output - b.design.beta1) * DEG, lw=1.4, color="C0")
        ax1.axhline(b.output_swing * DEG, color="C3", ls="--", lw=0.8)
        ax1.set_ylabel(_("wheel angle |$\\Delta\\beta$| (°)"), fontsize=8)
        ax2.plot(x, np.abs(b.velocity_ratio), lw=1.4, color="C1")
        ax2.axhline(mean, color="0.5", ls=":", lw=0.8)
        ax2.set_ylabel(_("ratio |$d\\beta/d\\alpha$|"), fontsize=8)
        ax3.plot(x, b.sweep_gamma * DEG, lw=1.4, color="C2")
        ax3.axhline(40.0, color="0.5", ls=":", lw=0.8)
        ax3.set_ylim(0, 90)
        ax3.set_ylabel(_("transmission angle $\\gamma$ (°)"), fontsize=8)
        ax3.set_xlabel(_("input rocker angle $\\Delta\\alpha$ (°)"))
        for ax in (ax1, ax2, ax3):
            ax.grid(True, lw=0.4, color="0.85")
            ax.set_xlim(0, b.input_swing * DEG)


def _wheel_figure(path: Path, lang: str, b, start: float, span: float):
    """Bending wheel angle, speed and acceleration over the bending window of the shaft."""
    _ = tr(lang)
    phi = np.mod(b.shaft_angle - start, 2 * np.pi) * DEG
    keep = phi <= span * DEG
    order = np.argsort(phi[keep])
    x = phi[keep][order] + start * DEG
    with fig.figure(path, 3, (7.0, 5.4)) as axes:
        for ax, y, lab in zip(axes, (b.wheel_angle * DEG, b.wheel_omega, b.wheel_alpha),
                              (N_("wheel angle $\\theta$ (°)"), N_("$\\omega$ (rad/s)"), N_("$\\varepsilon$ (rad/s²)"))):
            ax.plot(x, y[keep][order], lw=1.4, color="C0")
            ax.set_ylabel(_(lab), fontsize=8)
            ax.grid(True, lw=0.4, color="0.85")
            ax.axhline(0, color="0.4", lw=0.5)
        axes[0].axhline(b.bend_simulated * DEG, color="C3", ls="--", lw=0.8)
        axes[-1].set_xlabel(_.pgettext("lockbeam", "main-shaft angle $\\varphi$ (°)"))


def _seed_figure(path: Path, lang: str, b):
    s = b.seed
    _ = tr(lang)
    with fig.figure(path, 1, (7.0, 3.0)) as (ax,):
        ax.plot(s.check.alpha * DEG, s.check.swing * DEG, lw=1.4, color="C0",
                label=(f"{f(s.input_rocker * MM, 0)}/{f(s.coupler * MM, 0)} mm"))
        ax.axhline(b.output_swing * DEG, color="C3", ls="--", lw=0.8,
                   label=_("required") + f" {f(b.output_swing * DEG, 1)}°")
        for a1, _b1, _g in s.check.starts:
            ax.plot([a1 * DEG], [b.output_swing * DEG], "o", color="C3", ms=4)
        ax.set_xlim(0, 360)
        ax.set_xticks(np.arange(0, 361, 30))
        ax.set_xlabel(_("input rocker start angle $\\alpha_1$ (°)"))
        ax.set_ylabel(_("wheel swing (°)"))
        ax.grid(True, lw=0.4, color="0.85")
        legend(ax, fontsize=7, loc="best")


def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    from ...render.cam_report import make_cam_figures
    from ...render.components_report import make_cycle_figures
    from ...render.linkage_report import make_linkage_figures

    p = r["params"]
    paths: dict[str, str] = {}

    def out(name):
        paths[name] = f"{fig_dir.name}/{name}.png"
        return fig_dir / f"{name}.png"

    cyc = r["cycle"]
    for k, v in make_cycle_figures(cyc.diagram, fig_dir, lang, cyc.checks).items():
        paths[f"cycle_{k}"] = v
    _timing_figure(out("timing"), lang, r)
    paths.update(make_cam_figures(r["cam"], fig_dir, lang))
    for k, v in make_cam_figures(r["bending_cam"], fig_dir, lang, prefix="bcam").items():
        paths[f"bcam_{k}"] = v
    b = r["bending"]
    _linkage_drawing(out("bend_linkage"), lang, b, p.bending.driving_wheel)
    _sweep_figure(out("bend_sweep"), lang, b)
    prog = r["bending_cam"].params.programme
    rise = [i for i, s in enumerate(prog.segments) if s.kind == "rise"][0]
    start = p.bend_cam_start + prog.starts[rise] - np.radians(5)
    span = float(np.sum(prog.spans[rise:])) + np.radians(10)
    _wheel_figure(out("bend_wheel"), lang, b, start, min(span, 2 * np.pi))
    if b.seed is not None:
        _seed_figure(out("bend_seed"), lang, b)
    paths.update(make_linkage_figures(p.feed, r["feed"], r["feed_forces"], r["feed_flywheel"],
                                      fig_dir, lang, prefix="feed"))
    return paths


# --------------------------------------------------------------------------- context


def _c(z: complex, digits: int = 2) -> str:
    return f"({f(z.real * MM, digits)},\\ {f(z.imag * MM, digits)})"


def _data_rows(r: dict, brief, lang: str) -> list[list[str]]:
    _ = tr(lang)
    pr, t, bd = brief.production, brief.transmission, brief.bending
    rows = []

    def row(sym, name, value, unit):
        rows.append([sym, _(name), value, unit])

    row("—", N_("production rate"), f(pr.rate_per_min, 0), _("parts/min"))
    row("$n_m$", N_("motor speed"), f(pr.motor_speed_rpm, 0), _("rpm"))
    row("$l$", N_("unrolled length of the blank"), f(pr.part_length_mm, 0), "mm")
    row("$d_1$", N_("bar diameter"), f(pr.part_diameter_mm, 0), "mm")
    row("$d_2$", N_("groove diameter"), f(pr.groove_diameter_mm, 0), "mm")
    row("—", N_("bending angle"), f(bd.bending_angle_deg, 0), "°")
    row("$m$", N_("gear module"), f(t.module_mm, 0), "mm")
    row("$d_{b1}/d_{b2}$", N_("pulley diameters"),
        f"{f(t.belt.driver_diameter_mm, 0)}/{f(t.belt.driven_diameter_mm, 0)}", "mm")
    row("$z$", N_("gear teeth"),
        ", ".join(f"{g.driver_teeth}/{g.driven_teeth}" for g in t.gears), "—")
    row("$D_1/D_2$", N_("chain wheels (large/small)"),
        f"{f(bd.driving_wheel_diameter_mm, 0)}/{f(bd.bending_wheel_diameter_mm, 0)}", "mm")
    row("$d$", N_("input rocker pivot to wheel centre"), f(bd.frame_mm, 0), "mm")
    row("$c$", N_("arm on the large wheel"), f(bd.output_arm_mm, 0), "mm")
    c = brief.cam
    row("$r_0,\\ h$", N_("pin cam base radius, lift"),
        f"{f(c.base_radius_mm, 0)}, {f(c.follower.stroke_h_mm, 0)}", "mm")
    prog = ", ".join(f"{f(s.angle_deg, 0)}" for s in c.programme)
    row("—", N_("pin cam angles (dwell/rise/dwell/return)"), prog, "°")
    return rows


def _seed_notes(r: dict, lang: str) -> list[str]:
    _ = tr(lang)
    b, ft = r["bending"], r["feed_table"]
    notes = []
    notes.append(_("Production rate: the task data say 10 parts/min; one line of the original report's "
                   "requirements says 20. Its transmission 700 → 10 rpm is for 10, and so is this "
                   "design."))
    notes.append(_("The original report's morphological matrix (table 2.5) and cycle diagram (figure 9.1) are "
                   "not in the text this design starts from (they were images): the matrix is "
                   "rebuilt from the report's text, and the cycle diagram is drawn anew from the "
                   "cam data and the simulated feed linkage."))
    if b.seed is not None:
        notes.append(_("Bending four-bar: the original report found the lengths {rocker} mm and {coupler} mm "
                       "graphically without stating its start position", rocker=f(b.seed.input_rocker * MM, 0),
                       coupler=f(b.seed.coupler * MM, 0))
                     + (_("; they make a change-point linkage (all links can fall into line, and "
                          "the motion becomes uncertain)") if _change_point(b.seed) else "")
                     + _(". This report synthesises the linkage analytically from two corresponding "
                         "positions and checks the original report's lengths by simulation (chapter 5)."))
    if ft.seed_x is not None:
        wrong = int(np.sum(np.abs(ft.seed_x - ft.x) > 1e-9))
        notes.append(_("The original report's VB RRP routine takes the absolute value of the slider coordinate "
                       "(sr = abs(...)), which mirrors the slider to the right whenever it is left of "
                       "the guide's reference point $x$ = 0: {wrong} of its {n} positions at 10° steps "
                       "come out wrong. This report takes the signed root.", wrong=wrong, n=len(ft.x)))
    return notes


def _change_point(seed) -> bool:
    return seed.grashof.startswith("change-point")


def _seed_conclusion(b, lang: str) -> str:
    _ = tr(lang)
    s = b.seed
    a, c = f(s.input_rocker * MM, 0), f(s.coupler * MM, 0)
    if s.check.starts:
        g = max(x[2] for x in s.check.starts)
        worse = g < b.gamma_min
        text = (_("The original report's graphical result holds, but only from the start in the table, where "
                  "the least transmission angle is {g}°", g=f(g * DEG, 2))
                + (_(", below this design's {gamma_min}°", gamma_min=f(b.gamma_min * DEG, 2))
                   if worse else ""))
    else:
        text = _("The original report's lengths give the required {output_swing}° from no start position",
                  output_swing=f(b.output_swing * DEG, 2))
    if _change_point(s):
        d = b.design
        text += _("; and {a} + {c} = {output_rocker} + {frame} makes it a change-point linkage: "
                   "all links can fall into line, and the motion becomes uncertain", a=a, c=c,
                   output_rocker=f(d.output_rocker * MM, 0), frame=f(d.frame * MM, 0))
    return text + _(".")


def _transmission(r: dict, lang: str) -> dict:
    _ = tr(lang)
    trans = r["transmission"]
    p = r["params"]
    rows, gear_rows, pair_rows, gear = [], [], [], 0
    for i, s in enumerate(trans.stages, 1):
        if s.kind == "belt":
            kind = _("V-belt")
            # the pulleys as Table 1 names them (d_b1/d_b2): d_1, d_2 are the bar's and the
            # groove's diameters there (page review 47)
            drv = f"$d_{{b1}}$ = {f(s.driver * MM, 0)} mm"
            dvn = f"$d_{{b2}}$ = {f(s.driven * MM, 0)} mm"
            dist = "—"
        else:
            kind = _("spur gears")
            drv, dvn = f"$z_{gear + 1}$ = {int(s.driver)}", f"$z_{gear + 2}$ = {int(s.driven)}"
            gear += 2
            dist = f(s.pair.a * MM, 1)
        rows.append([str(i), kind, drv, dvn, str(s.ratio_exact), f(s.speed_in, 2), f(s.speed_out, 2), dist])
        if s.pair is not None:
            # the gears' diameters in one table, the pairs' centre distance, contact ratio and
            # least teeth in another (review 38: a table's rows hold one kind of data)
            pr = s.pair
            for k, g in ((gear - 1, pr.g1), (gear, pr.g2)):
                gear_rows.append([f"$z_{{{k}}}$", str(g.z), f(g.d * MM, 1), f(g.da * MM, 1),
                                  f(g.df * MM, 1), f(g.db * MM, 2)])
            pair_rows.append([str(i), f"$z_{{{gear - 1}}}$ – $z_{{{gear}}}$", f(pr.a * MM, 1),
                              f(pr.contact_ratio, 3), f(pr.z_min, 0)])
    # the train's ratio as the course writes it: driven over driving, the pulleys d_b1 → d_b2,
    # the gears numbered along the train (z_1 drives z_2, z_3 drives z_4, …)
    parts, symbols, gear = [], [], 0
    for s in trans.stages:
        if s.kind == "belt":
            parts.append(rf"\frac{{{f(s.driven * MM, 0)}}}{{{f(s.driver * MM, 0)}}}")
            symbols.append(r"\frac{d_{b2}}{d_{b1}}")
        else:
            parts.append(rf"\frac{{{int(s.driven)}}}{{{int(s.driver)}}}")
            symbols.append(rf"\frac{{z_{{{gear + 2}}}}}{{z_{{{gear + 1}}}}}")
            gear += 2
    vals = r" \times ".join(str(s.ratio_exact) for s in trans.stages)
    eq_ratio = ("i = " + r" \cdot ".join(symbols) + " = " + r" \times ".join(parts)
                + f" = {vals} = {trans.ratio_exact}")
    eq_speed = (rf"n = \frac{{n_m}}{{i}} = \frac{{{f(trans.motor_rpm, 0)}}}{{{trans.ratio_exact}}} = "
                rf"{rpm(trans.output_rpm)}\ \text{{r/min}}")
    slip = p.transmission.slip
    shafts = []
    if p.transmission.power is not None:
        for s in trans.shafts:
            shafts.append([str(s.index), f(s.speed_rpm, 2), f(s.power / 1e3, 3), f(s.torque, 2)])
    return {"rows": rows, "gear_rows": gear_rows, "pair_rows": pair_rows, "eq_ratio": eq_ratio, "eq_speed": eq_speed,
            "ratio": str(trans.ratio_exact), "required": f"{trans.required_ratio:.6g}",
            "n_gears": str(sum(1 for s in trans.stages if s.kind == "gear")),
            "motor": f(trans.motor_rpm, 0),
            "rate": f(trans.required_rpm, 0), "out": rpm(trans.output_rpm),
            "slip": f(slip, 3), "out_slip": rpm(trans.output_rpm_slip), "has_slip": slip > 0,
            "shafts": shafts, "warnings": [md_text(w.text(lang)) for w in trans.warnings],
            "eq_slip": (rf"n' = \frac{{n_m (1 - \varepsilon)}}{{i}} = \frac{{{f(trans.motor_rpm, 0)} \times "
                        rf"0.98}}{{{trans.ratio_exact}}} = {f(trans.motor_rpm * 0.98 / trans.ratio, 2)}\ \text{{r/min}}")}


def _bending(r: dict, lang: str, figures: dict) -> dict:
    from ...render.cam_report import cam_context

    _ = tr(lang)
    p, b = r["params"], r["bending"]
    bp, ds = p.bending, b.design
    bcam = r["bending_cam"]
    fo = bcam.params.follower
    arm = fo.arm_length
    h_arc = arm * b.input_swing
    u1, u2 = np.exp(1j * ds.alpha1), np.exp(1j * (ds.alpha1 + ds.dalpha))
    B1 = ds.frame + ds.output_rocker * np.exp(1j * ds.beta1)
    B2 = ds.frame + ds.output_rocker * np.exp(1j * (ds.beta1 + ds.dbeta))
    A1 = ds.input_rocker * u1
    num = abs(B1) ** 2 - abs(B2) ** 2
    den = 2 * (np.real(u1 * np.conj(B1)) - np.real(u2 * np.conj(B2)))
    ad = lambda x: f(np.mod(x, 2 * np.pi) * DEG, 3)  # noqa: E731
    # the arc h with the digits that give the printed Δα = h/L (14.903/35 = 0.4258)
    h_txt = factor_for(h_arc * MM, lambda x: gives(x / float(f(arm * MM, 0)),
                                                   sig(b.input_swing, 4, group=False)))
    eq = {
        "dbeta": (rf"\Delta\beta = \theta_b \frac{{D_2}}{{D_1}} = {f(bp.bending_angle * DEG, 0)}° \times "
                  rf"\frac{{{f(bp.bending_wheel * MM, 0)}}}{{{f(bp.driving_wheel * MM, 0)}}} = "
                  rf"{f(bp.output_swing * DEG, 2)}°"),
        "dalpha": (rf"\Delta\alpha = \frac{{h}}{{L}} = \frac{{{h_txt}}}{{{f(arm * MM, 0)}}} = "
                   rf"{sig(b.input_swing, 4, group=False)}\ \text{{rad}} = {f(b.input_swing * DEG, 2)}°"),
        "loop": (r"\left| a\,e^{i\alpha_k} - \left(d + c\,e^{i\beta_k}\right) \right| = b,\qquad "
                 r"k = 1, 2"),
        "lin": (r"a = \frac{|B_1|^2 - |B_2|^2}{2\,\mathrm{Re}\left(e^{i\alpha_1}\bar B_1 - "
                r"e^{i\alpha_2}\bar B_2\right)},\qquad b = \left|a\,e^{i\alpha_1} - B_1\right|"),
        "B": (rf"B_1 = {_c(B1)}\ \text{{mm}},\quad B_2 = {_c(B2)}\ \text{{mm}}"),
        "a": (rf"a = \frac{{{f(num * MM * MM, 2)}}}{{{f(den * MM, 2)}}} = {f(ds.input_rocker * MM, 2)}\ "
              r"\text{mm}"),
        "b": (rf"b = \left|{_c(A1)} - {_c(B1)}\right| = {f(ds.coupler * MM, 2)}\ \text{{mm}}"),
        "gamma": r"\gamma = \min\left(\delta,\ 180° - \delta\right),\qquad \delta = \angle(\overrightarrow{GB},\ \overrightarrow{B_0B})",
    }
    mean_ratio = bp.output_swing / bp.input_swing
    sense_name = {"same": N_("same way"), "opposite": N_("opposite way")}
    cand_rows = []
    for (sense, d_, g, msg), peak in zip(b.synthesis.candidates, b.candidate_ratio_peaks):
        name = _(sense_name[sense])
        if d_ is None:
            cand_rows.append([name, "—", "—", "—", "—", "—", "—", msg])
            continue
        chosen = d_ is ds
        mark = (" ✓" if chosen else "")
        note = [_("chosen") if chosen else (_("smaller $\\gamma$"))]
        for length, sym in ((d_.input_rocker, "a"), (d_.coupler, "b")):
            if any(abs(length - x) < 1e-6 for x in bp.length_bounds):
                note.append(_("{sym} at its bound", sym=sym))
        cand_rows.append([name + mark, ad(d_.alpha1), ad(d_.beta1), f(d_.input_rocker * MM, 2),
                          f(d_.coupler * MM, 2), f(g * DEG, 2), f(peak, 4),
                          _("; ").join(note)])
    design_rows = [
        ["$d$", _("frame $G_0B_0$"), f(ds.frame * MM, 2), "mm"],
        ["$a$", _("input rocker $G_0G$"), f(ds.input_rocker * MM, 2), "mm"],
        ["$b$", _("coupler GB"), f(ds.coupler * MM, 2), "mm"],
        ["$c$", _("arm on the wheel $B_0B$"), f(ds.output_rocker * MM, 2), "mm"],
        ["$\\alpha_1$", _("input start angle"), ad(ds.alpha1), "°"],
        ["$\\beta_1$", _("arm start angle"), ad(ds.beta1), "°"],
        ["$\\Delta\\alpha$", _("input swing"), _("{angle} ({sense})", angle=f(abs(ds.dalpha) * DEG, 2), sense=_sense(ds.dalpha, _)), "°"],
        ["$\\Delta\\beta$", _("wheel swing"), _("{angle} ({sense})", angle=f(abs(ds.dbeta) * DEG, 2), sense=_sense(ds.dbeta, _)), "°"],
        ["$\\gamma_{min}$", _("least transmission angle"), f(b.gamma_min * DEG, 2), "°"],
        ["$\\gamma_{max}$", _("largest transmission angle"), f(b.gamma_max * DEG, 2), "°"],
        ["$d\\beta/d\\alpha$", _("velocity ratio range (mean $\\Delta\\beta/\\Delta\\alpha$ = {mean})", mean=f(mean_ratio, 4)),
         f"{f(float(np.min(np.abs(b.velocity_ratio))), 4)} ~ {f(float(np.max(np.abs(b.velocity_ratio))), 4)}", "—"],
    ]
    seed = None
    if b.seed is not None:
        s = b.seed
        starts = []
        for (a1, b1, g), (lo, hi) in zip(s.check.starts, s.start_ratio_ranges):
            starts.append([ad(a1), ad(b1), f(g * DEG, 2), f"{f(lo, 4)} ~ {f(hi, 4)}"])
        seed = {"a": f(s.input_rocker * MM, 0), "b": f(s.coupler * MM, 0),
                "grashof": grashof_sentence(s.input_rocker, s.coupler, ds.output_rocker, ds.frame, lang),
                "lo": f(s.check.swing_range[0] * DEG, 2), "hi": f(s.check.swing_range[1] * DEG, 2),
                "starts": starts, "n_starts": str(len(starts)),
                "conclusion": _seed_conclusion(b, lang)}
    bfigs = {k.removeprefix("bcam_"): v for k, v in figures.items() if k.startswith("bcam_")}
    bc = cam_context(bcam, lang, bfigs, "bending_cam_profile.csv")
    sense = {"same": N_("same way as"), "opposite": N_("opposite way to")}[b.synthesis.sense]
    return {
        "eq": eq, "cand_rows": cand_rows, "design_rows": design_rows, "seed": seed,
        "sense": _(sense), "ratio": f(b.ratio, 3),
        "grashof": grashof_sentence(ds.input_rocker, ds.coupler, ds.output_rocker, ds.frame, lang),
        "dbeta": f(bp.output_swing * DEG, 2), "dalpha": f(b.input_swing * DEG, 2),
        # the lift by the rule (0.01 mm); the formula carries the digits that give its Δα, and
        # the sentence after it says so (page review 47: "h = 14.90 mm (the original report
        # prints 14.904 mm)" above "14.904/35" quoted a typed number as if it were not used)
        "arm": f(arm * MM, 0), "h": f(h_arc * MM, 2),
        "h_note": carried_note(_, [("h", f(h_arc * MM, 2), h_txt)]),
        "gmin": f(b.gamma_min * DEG, 2), "gmax": f(b.gamma_max * DEG, 2),
        "gmin_at": f(b.gamma_min_at * DEG, 2), "glim": f(bp.gamma_allowed * DEG, 0),
        "lo": f(bp.length_bounds[0] * MM, 0), "hi": f(bp.length_bounds[1] * MM, 0),
        "auto": bp.start is None,
        "swing_sim": f(abs(b.swing_simulated) * DEG, 2), "wheel_sense": _sense(b.swing_simulated, _),
        "bend_sim": f(b.bend_simulated * DEG, 2),
        # the cycle is simulated with the four-bar as built: the drawn lengths when the cam is
        # designed for their swing (stages.built_design)
        "sim_linkage": _("four-bar as drawn") if _built_is_drawn(b) else _("four-bar"),
        "bend": f(bp.bending_angle * DEG, 0),
        "wheel_w": sig(float(np.max(np.abs(b.wheel_omega)))),
        "wheel_a": sig(float(np.max(np.abs(b.wheel_alpha)))),
        "rocker_w": sig(float(np.max(np.abs(b.rocker_omega)))),
        "cam": bc, "warnings": [md_text(w.text(lang)) for w in b.warnings],
        "mean_ratio": sig(mean_ratio),
        "pin_hold": f(_pin_hold(r) * DEG, 1),
        "cam_motion": _cam_motion_text(bcam, lang),
        "cam_r0": (_("the base radius is designed for the allowed pressure angles")
                   if bcam.base_radius_designed else _("the base radius is given in the brief"))
        + _(" ($r_0$ = {r0} mm)", r0=f(bcam.base_radius * MM, 0)),
        "ratio_factor": None if bp.ratio_factor is None else f(bp.ratio_factor, 3),
        "ratio_limit": None if bp.ratio_factor is None else sig(bp.ratio_factor * mean_ratio),
        "ratio_lo": sig(float(np.min(np.abs(b.velocity_ratio)))),
        "ratio_hi": sig(float(np.max(np.abs(b.velocity_ratio)))),
        "rounded": _rounded(b, ds, bp.rounding, lang),
        "fig": {"linkage": figures.get("bend_linkage"), "sweep": figures.get("bend_sweep"),
                "wheel": figures.get("bend_wheel"), "seed": figures.get("bend_seed")},
    }


def _pin_hold(r: dict) -> float:
    """Total far dwell of the positioning pin [rad]."""
    prog = r["cam"].params.programme
    return float(sum(sp for seg, sp, lev in zip(prog.segments, prog.spans, prog.levels)
                     if seg.kind == "dwell" and abs(lev - prog.stroke) <= 1e-9 * prog.stroke))


def _cam_motion_text(c, lang: str) -> str:
    """'rise 30°, far dwell 6°, return 30°, 3-4-5 polynomial laws (no impact)' from the
    cam's programme and its impact check."""
    from ...core.motion_laws import LAWS
    from ...render.cam_report import _segment_name

    _ = tr(lang)
    prog = c.params.programme
    parts, laws = [], []
    for i, seg in enumerate(prog.segments):
        name = _segment_name(c, i, lang)
        if i == 0 and seg.kind == "dwell":
            continue
        parts.append(f"{name} {f(prog.spans[i] * DEG, 0)}°")
        if seg.law and seg.law not in laws:
            laws.append(seg.law)
    impacts = {s.impact for s in c.segments if s.kind != "dwell"}
    sep = _.pgettext("list", ", ")
    lw = sep.join(LAWS[x].name(_.lang) for x in laws)
    calm = impacts <= {"none"}
    return (sep.join(parts) + _(", with the {law} law", law=lw)
            + (_(" (zero velocity and acceleration at both ends: no impact)") if calm else ""))


def law_choice(c, lang: str) -> str:
    """Why the positioning cam's law (the seed names none): impacts and the peak
    acceleration coefficient against the cycloidal law, from the law table."""
    from ...core.motion_laws import LAWS

    _ = tr(lang)
    laws = []
    for seg in c.params.programme.segments:
        if seg.law and seg.law not in laws:
            laws.append(seg.law)
    impacts = {s.impact for s in c.segments if s.kind != "dwell"}
    names = _.pgettext("list", ", ").join(LAWS[x].name(_.lang) for x in laws)
    ca = max(LAWS[x].ca for x in laws)
    cyc = LAWS["cycloidal"].ca
    if impacts <= {"none"}:
        text = _("The original report names no follower motion law. Rise and return both lie between "
                  "dwells; the {names} law is chosen: its velocity and acceleration vanish at "
                  "both ends, so it joins the dwells with neither rigid nor soft impact",
                  names=names)
        if "cycloidal" not in laws and np.isfinite(ca):
            text += _("; its peak acceleration coefficient $C_a$ = {ca} is below that of the "
                       "cycloidal law ({cyc}), which is also impact-free, so the largest acceleration "
                       "is lower.", ca=f(ca, 3), cyc=f(cyc, 3))
        else:
            text += _(".")
        return text
    return (_("The chosen law(s) ({names}) have impacts at the joints (see the table); a "
              "3-4-5 polynomial or cycloidal law would avoid them.", names=names))


def _sense(angle: float, _) -> str:
    """The sense of a signed swing (angles counter-clockwise positive), in words: a signed
    −50.00° beside a required 50.00° reads as a failure."""
    return _("clockwise") if angle < 0 else _("counter-clockwise")


def _built_is_drawn(b) -> bool:
    """Whether the cycle simulation (and the bending cam) use the drawn lengths."""
    return b.rounded is not None and b.rounded.input_swing_needed is not None


def _rounded(b, ds, step: float, lang: str):
    rc = b.rounded
    if rc is None:
        return None
    return {"a": f(rc.input_rocker * MM, 2), "b": f(rc.coupler * MM, 2),
            # the input start kept, the arm's start it gives (page review 47: "the same input
            # start (β1 = 147.49°)" named the output's angle); angles in prose to 0.01°
            "alpha1": f(np.mod(ds.alpha1, 2 * np.pi) * DEG, 2),
            "beta1": f(np.mod(rc.beta1, 2 * np.pi) * DEG, 2), "swing": f(rc.swing * DEG, 2),
            "bend": f(rc.bend * DEG, 2), "gmin": f(rc.gamma_min * DEG, 2),
            "gmin_built": f((b.gamma_min_built if _built_is_drawn(b) else rc.gamma_min) * DEG, 2),
            # the swing the built linkage works over (the cam's), beside its γ_min (63.25° at
            # 24.42°, three lines after 63.29° at 24.40°: page review 41)
            "swing_built": f((rc.input_swing_needed if _built_is_drawn(b) else b.input_swing) * DEG, 2),
            "needed": None if rc.input_swing_needed is None else f(rc.input_swing_needed * DEG, 2),
            "grashof": grashof_sentence(rc.input_rocker, rc.coupler, ds.output_rocker, ds.frame, lang),
            "step": f(step * MM, 0) if float(step * MM).is_integer() else sig(step * MM),
            "need": f(abs(rc.margin_required) * MM, 2), "margin": f(rc.margin * MM, 2),
            "margin0": f(grashof_margin(ds.input_rocker, ds.coupler, ds.output_rocker, ds.frame)
                         * MM, 2),
            "rule": "$s + l < p + q$" if rc.margin_required > 0 else "$s + l > p + q$",
            "nearest": None if rc.nearest is None else {
                "a": f(rc.nearest[0] * MM, 2), "b": f(rc.nearest[1] * MM, 2),
                "margin": f(rc.nearest[2] * MM, 2),
                "change_point": abs(rc.nearest[2]) <= 1e-9 * ds.frame}}


def _feed(r: dict, lang: str, figures: dict) -> dict:
    from ...render.linkage_report import linkage_context

    _ = tr(lang)
    p = r["params"]
    k, ft = r["feed"], r["feed_table"]
    lk = linkage_context(p.feed, k, r["feed_forces"], r["feed_flywheel"], r["feed_verification"],
                         figures, lang, prefix="feed",
                         title=_("Feed mechanism: kinematics"))
    rows = []
    for i in range(len(ft.crank_angle)):
        seed_x = "—"
        if ft.seed_x is not None:
            wrong = abs(ft.seed_x[i] - ft.x[i]) > 1e-9
            seed_x = (f"{f(ft.seed_x[i] * MM, 2)} ✗" if wrong else f(ft.seed_x[i] * MM, 2))
        rows.append([f(ft.crank_angle[i] * DEG, 0), f(ft.x[i] * MM, 2), f(ft.v[i], 4), f(ft.a[i], 4),
                     f(ft.bar_omega[i], 4), f(ft.rod_omega[i], 4), f(ft.bar_alpha[i], 4),
                     f(ft.rod_alpha[i], 4), seed_x])
    cf = ft.closed
    closed = None
    if cf is not None:
        closed = {
            "theta": (rf"\theta = 2\arcsin\frac{{r}}{{d}} = 2\arcsin\frac{{{f(cf.crank * MM, 0)}}}"
                      rf"{{{f(cf.centres * MM, 0)}}} = {f(cf.theta * DEG, 2)}°"),
            "K": (rf"K = \frac{{180° + \theta}}{{180° - \theta}} = \frac{{{f(180 + cf.theta * DEG, 2)}}}"
                  rf"{{{f(180 - cf.theta * DEG, 2)}}} = {sig(cf.K, 4, group=False)}"),
            "H": None if cf.stroke is None else (
                rf"H = 2L\sin\frac{{\theta}}{{2}} = \frac{{2 L r}}{{d}} = \frac{{2 \times {f(cf.bar_point * MM, 0)} "
                rf"\times {f(cf.crank * MM, 0)}}}{{{f(cf.centres * MM, 0)}}} = {f(cf.stroke * MM, 2)}\ \text{{mm}}"),
        }
    bad = 0 if ft.seed_x is None else int(np.sum(np.abs(ft.seed_x - ft.x) > 1e-9))
    return {"lk": lk, "rows": rows, "closed": closed, "n_bad": str(bad), "n_rows": str(len(rows)),
            "stroke": f(k.stroke * MM, 2), "K": time_ratio(k.time_ratio)}


def verification_rows(r: dict, lang: str) -> list[list[str]]:
    from ...render.linkage_report import verification_rows as linkage_rows

    _ = tr(lang)
    p = r["params"]
    trans, b, c, pin = r["transmission"], r["bending"], r["cycle"], r["pin_check"]
    rows = []

    def add(item, value, ref, ok):
        rows.append([_(item), value, ref, _ok(ok, lang)])

    add(N_("train ratio (exact fraction)"), str(trans.ratio_exact),
        f"$n_m/n$ = {f(trans.required_ratio, 4)}", abs(trans.ratio - trans.required_ratio) < 1e-12)
    add(N_("main-shaft speed / rpm"), f(trans.output_rpm, 4),
        _("{rate} (production rate)", rate=f(p.rate, 0)),
        abs(trans.output_rpm - p.rate) < 1e-9 * p.rate)
    add(N_("pin lift / mm"), f(pin.lift * MM, 3), f"> $(d_1 - d_2)/2$ = {f(pin.required * MM, 2)}",
        pin.lift > pin.required)
    add(N_("simulation: large wheel swing / °"), f(abs(b.swing_simulated) * DEG, 2),
        f(b.output_swing * DEG, 2), abs(abs(b.swing_simulated) - b.output_swing) < 1e-9)
    # the cycle simulation drives the four-bar as built (the drawn lengths when the bending cam
    # is designed for their swing: stages.built_design)
    add(N_("simulation: bending wheel (cam → rocker → four-bar as drawn → chain) / °")
        if _built_is_drawn(b) else N_("simulation: bending wheel (cam → rocker → four-bar → chain) / °"),
        f(b.bend_simulated * DEG, 2), f(p.bending.bending_angle * DEG, 2),
        abs(b.bend_simulated - p.bending.bending_angle) < 1e-9)
    rc = b.rounded
    if rc is not None:      # the linkage as drawn and built (lengths rounded)
        drawn = _("linkage as drawn (a = {a} mm, b = {b} mm)", a=f(rc.input_rocker * MM, 2),
                  b=f(rc.coupler * MM, 2))
        if rc.input_swing_needed is None:
            # no cam swing makes the drawn linkage bend the required angle: it fails
            rows.append([_("simulation, {drawn}: bend / °", drawn=drawn), f(rc.bend * DEG, 2),
                         f(p.bending.bending_angle * DEG, 2), _ok(False, lang)])
        g = b.gamma_min_built if _built_is_drawn(b) else rc.gamma_min
        rows.append([_("{drawn}: least transmission angle / °", drawn=drawn), f(g * DEG, 2),
                     f"≥ {f(p.bending.gamma_allowed * DEG, 0)}",
                     _ok(g >= p.bending.gamma_allowed, lang)])
    add(N_("bending four-bar closure residual / m"), e(b.closure), "≤ 10⁻⁹",
        b.closure <= 1e-9)
    add(N_("bending four-bar least transmission angle / °"), f(b.gamma_min * DEG, 2),
        f"≥ {f(p.bending.gamma_allowed * DEG, 0)}", b.gamma_min >= p.bending.gamma_allowed)
    add(N_("bending wheel $\\omega$ vs central difference (relative)"), e(b.fd_velocity), "O(h²)", b.fd_velocity < 1e-3)
    add(N_("bending wheel $\\varepsilon$ vs central difference (relative)"), e(b.fd_acceleration), "O(h²)", b.fd_acceleration < 1e-3)
    for key, cam in (("pin", N_("pin cam")), ("bend", N_("bending cam"))):
        err = c.cam_timing_error[key]
        rows.append([_("cycle diagram vs the {cam} (largest deviation / stroke)", cam=_(cam)),
                     e(err), "0", _ok(err < 1e-9, lang)])
    add(N_("least pin lift while the bending wheel turns / mm"), f(c.pin_lift_while_bending * MM, 4), f"h = {f(c.pin_stroke * MM, 3)}",
        abs(c.pin_lift_while_bending - c.pin_stroke) < 1e-12)
    add(N_("feed stroke in shaft angle: diagram / simulation / °"), f"{f(c.feed_span_cycle * DEG, 3)} / {f(c.feed_span_simulated * DEG, 4)}", "±0.5",
        abs(c.feed_span_cycle - c.feed_span_simulated) <= np.radians(0.5))
    n_ok = sum(1 for ch in c.checks if ch.ok)
    add(N_("cycle diagram timing requirements"), f"{n_ok}/{len(c.checks)}",
        _("all PASS"), n_ok == len(c.checks))
    cf = r["feed_table"].closed
    k = r["feed"]
    if cf is not None:
        kk = k.time_ratio if k.time_ratio >= 1 else 1 / k.time_ratio
        add(N_("feed $K$: simulation / closed form"), f(kk, 4), f(cf.K, 4),
            abs(kk - cf.K) < 1e-9)
        if cf.stroke is not None:
            add(N_("feed stroke: simulation / closed form / mm"), f(k.stroke * MM, 4),
                f(cf.stroke * MM, 4), abs(k.stroke - cf.stroke) < 1e-12)
    rows.extend(linkage_rows(r["feed_verification"], lang, k))
    # A bare "|" inside a cell (e.g. max|M_b ω|) would split the pipe table.
    return [[cell.replace("\\|", "|").replace("|", "\\|") for cell in row] for row in rows]


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    from ...render.cam_report import cam_context
    from ...render.components_report import cycle_context, morphology_context

    p, c = r["params"], r["cycle"]
    cyc_figs = {k.removeprefix("cycle_"): v for k, v in figures.items() if k.startswith("cycle_")}
    _ = tr(lang)
    findings = []
    for key in ("transmission", "cam", "pin_check", "bending_cam", "bending", "cycle"):
        findings.extend(md_text(w.text(lang)) for w in getattr(r[key], "warnings", None) or ())
    findings.extend(md_text(w.text(lang)) for w in r["feed_verification"].warnings)
    bend_act = {a.key: a for a in c.diagram.actuators}
    pin_down_span = sum(ph.span for ph in bend_act["pin"].phases if ph.state == "dwell_low")
    timing = {
        "pin_rise": f(c.pin_rise_angle * DEG, 1), "pin_down": f(c.pin_down_angle * DEG, 1),
        "feed_rise": f(c.feed_at_pin_rise * MM, 2), "feed_down": f(c.feed_at_pin_down * MM, 2),
        "stroke": f(r["feed"].stroke * MM, 2),
        "rest": f((r["feed"].stroke - c.feed_at_pin_down) * MM, 2),
        "pin_start": f(p.pin_cam_start * DEG, 1), "bend_start": f(p.bend_cam_start * DEG, 1),
        "feed_start": f(bend_act["feed"].start * DEG, 1),
        "feed_span": f(c.feed_span_cycle * DEG, 1),
        "pin_dwell": f(pin_down_span * DEG, 1),
        "overlap": c.feed_span_cycle > pin_down_span + 1e-9,
    }
    return {
        "meta": md_meta(brief.report, lang), "fig": figures,
        "data_rows": _data_rows(r, brief, lang), "seed_notes": _seed_notes(r, lang),
        "morph": morphology_context(p.morphology, lang, level=2),
        "cycle": cycle_context(c.diagram, lang, cyc_figs, c.checks, level=2),
        "timing": timing,
        "trans": _transmission(r, lang),
        "cam": cam_context(r["cam"], lang, figures, "cam_profile.csv", brief.cam),
        "law_choice": law_choice(r["cam"], lang),
        "bend": _bending(r, lang, figures),
        "feed": _feed(r, lang, figures),
        "rate": f(p.rate, 0), "period": f(60.0 / p.rate, 2),
        "verify_rows": verification_rows(r, lang), "findings": findings,
        # no loads on the feed linkage: no power balance to explain (review39)
        "verify_note": "" if r["feed_verification"].power_balance_checked else _(
            "finite-difference errors scale with the square of the step (truncation error); the task "
            "gives the feed linkage no loads or masses, so its reactions and balancing torque are zero "
            "and no power balance is checked."),
    }


def write_data(r: dict, folder: Path) -> list[Path]:
    """Both cams' profile coordinates as CSV."""
    from ...render.cam_report import write_cam_csv

    return write_cam_csv(r["cam"], folder) + write_cam_csv(r["bending_cam"], folder,
                                                           name="bending_cam_profile")


def animate(r: dict, path: Path, lang: str) -> Path:
    """GIF of the feed linkage over one revolution."""
    from ...render.animation import linkage_gif

    return linkage_gif(r["params"].feed, r["feed"], path, lang)
