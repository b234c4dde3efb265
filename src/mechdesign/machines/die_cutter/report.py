"""Prepare the die-cutter report (半自动平压模切机): figures and the template context.

All formatting and unit conversion for display happens here (course units: mm, °, rpm, N,
kN, N·m, J, kg·m²); the templates only place prepared strings, rows and LaTeX formulas
with the numbers substituted. The shared pieces (linkage, cam, incomplete gear, cycle
diagram, drive, verification) come from their own report modules.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ...i18n import N_, tr
from ...render import figures as fig
from ...render.legends import legend
from ...render.fmt import e, f, length, md_meta, md_text, sig, fluctuation, factor_for, gives
from ...render.fmt import number, product, residue, time_ratio, verdict
from ...render.labels import pgettext, translated
from ...render.linkage_report import rim_width_equation
from ...render.fmt import sentences
from ...render.linkage_report import (carried_note, flywheel_carried, flywheel_equation, realised_flywheel,
                                       rim_inertia_factor)
from ...stages.drive import shaft_numeral

DEG = 180.0 / np.pi
MM = 1e3

_TXT = {"phase": N_("shaft (crank) angle $\\varphi$ (°)"),
        "s": N_("platen displacement s (mm)"),
        "fm": "F/M (kN/(kN·m))",
        "torque": N_("crank torque (N·m)"),
        "mb": N_("balancing torque $M_b$"),
        "req": N_("cut alone $F_c\\,M/F$"),
        "press": pgettext("die cutter", "cutting"),      # 模切区, not the shaper's 切削区
        "clear": N_("clear"),
        "level_p": N_("cutting starts"),
        "level_c": N_("clearance level"),
        "top": N_("top")}


# --------------------------------------------------------------------------- figures


def _amplification_figure(path: Path, lang: str, k, amp, p, f_):
    """Platen near its top, the force per unit torque F/M (log) and the torque the cut needs."""
    _ = tr(lang)
    t = {key: translated(text, _) for key, text in _TXT.items()}
    n = k.grid_size
    ph = k.phase[:n] * DEG
    tm = amp.timing
    lo, hi = tm.clear_up * DEG - 15, tm.clear_down * DEG + 15
    view = (ph >= lo) & (ph <= hi)
    H = k.stroke * MM
    with fig.figure(path, 3, (7.0, 7.4)) as (ax1, ax2, ax3):
        for ax in (ax1, ax2, ax3):
            ax.set_xlim(lo, hi)
            ax.grid(True, lw=0.4, color="0.82")
            ax.axvspan(tm.press_up * DEG, tm.top * DEG, color="C1", alpha=0.12, lw=0)
            ax.axvline(tm.top * DEG, color="0.4", lw=0.7, ls=":")
        ax1.plot(ph[view], k.s[:n][view] * MM, color="C0", lw=1.4)
        ax1.axhline(H - p.pressing_travel * MM, color="C1", lw=0.9, ls="--",
                    label=f"{t['level_p']} H − t = {f(H - p.pressing_travel * MM, 1)} mm")
        ax1.axhline(H - p.clearance * MM, color="C2", lw=0.9, ls="-.",
                    label=f"{t['level_c']} H − c = {f(H - p.clearance * MM, 1)} mm")
        ax1.set_ylim(H - p.clearance * MM - 12, H + 3)
        ax1.set_ylabel(t["s"])
        legend(ax1, fontsize=7, loc="lower center")
        rising = (k.v[:n] > 1e-9 * np.max(k.v[:n])) & view
        fm = 1.0 / amp.unit_torque[:n][rising]          # N per N·m = kN per kN·m
        ax2.semilogy(ph[rising], fm, color="C3", lw=1.4)
        ax2.set_ylim(0.7 * float(np.min(fm)), min(float(np.max(fm)) * 1.5, 1e3 * float(np.min(fm))))
        ax2.set_ylabel(t["fm"])
        ax3.plot(ph[view], f_.balancing_torque[:n][view], color="C0", lw=1.3, label=t["mb"])
        act = amp.required_torque[:n] > 0
        ax3.plot(ph[act], amp.required_torque[:n][act], color="C1", lw=1.3, ls="--", label=t["req"])
        ax3.axhline(0, color="0.4", lw=0.6)
        ax3.set_ylabel(t["torque"])
        ax3.set_xlabel(t["phase"])
        legend(ax3, fontsize=7, loc="upper right")


def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    """Draw every figure into ``fig_dir``; return name → relative path."""
    from ...render.cam_report import make_cam_figures
    from ...render.components_report import make_cycle_figures, make_intermittent_figures
    from ...render.linkage_report import make_linkage_figures

    model, k, f_ = r["press_model"], r["press"], r["press_forces"]
    paths = make_linkage_figures(model, k, f_, None, fig_dir, lang, prefix="press")

    def out(name):
        paths[name] = f"{fig_dir.name}/{name}.png"
        return fig_dir / f"{name}.png"

    _amplification_figure(out("dc_amplification"), lang, k, r["amplification"], r["params"], f_)
    fl = r["press_flywheel"]
    n = k.grid_size
    fig.energy(out("dc_energy"), lang, k.phase[:n] * DEG, fl.energy, fl.phase_at_min * DEG,
               fl.phase_at_max * DEG, fl.max_energy_swing, k.working_span * DEG)
    paths.update(make_cam_figures(r["cam"], fig_dir, lang, prefix="cam"))
    for key, path in make_intermittent_figures(r["feed"].gear, r["feed"].curves, fig_dir, lang,
                                               prefix="dc_feed").items():
        paths[f"ig_{key}"] = path
    cyc = r["cycle"]
    for key, path in make_cycle_figures(cyc.diagram, fig_dir, lang, cyc.checks, prefix="dc_cycle").items():
        paths[f"cycle_{key}"] = path
    return paths


def animate(r: dict, path: Path, lang: str) -> Path:
    """GIF of the toggle press over one revolution."""
    from ...render.animation import linkage_gif

    return linkage_gif(r["press_model"], r["press"], path, lang)


def write_data(r: dict, folder: Path) -> list[Path]:
    """The gripper cam's profile coordinates as CSV."""
    from ...render.cam_report import write_cam_csv

    return write_cam_csv(r["cam"], folder)


# --------------------------------------------------------------------------- context


def _deg(x: float, digits: int = 2) -> str:
    return f(x * DEG, digits)


def _data_rows(b, p, r, _) -> list[list[str]]:
    """The task's data (seed 001b); the motor speed is the task's nominal one, the drive
    design's motor and its full-load speed named beside it."""
    motor = r["drive"].motor
    rows = [
        [_("output"), f"{f(b.production.sheets_per_hour, 0)} " + _("sheets/h"),
         _("one sheet per turn of the distribution shaft: n = {shaft_rpm} rpm",
            shaft_rpm=f(p.shaft_rpm, 2))],
        [_("motor speed"), _("1450 rpm"),
         _("the task's nominal speed of a 4-pole Y motor ({sync} rpm synchronous); the drive "
           "design chooses the size from the power: {motor}, {n} rpm at full load, the speed "
           "the drive is designed with", sync=f(motor.synchronous_rpm, 0),
           motor=motor.designation, n=f(motor.full_load_rpm, 0))],
        [_("table height"), f"≈ {f(b.production.table_height_mm, 0)} mm",
         _("layout datum")],
        [_("board thickness"), f"≤ {f(b.production.board_thickness_mm, 1)} mm",
         _("corrugated board, white board and prints")],
        [_("drive"), _("V-belt → two-stage helical reducer → coupling → distribution shaft"),
         # review45: the task's coupling is not in the design, which said nothing of it
         _("the task's route; this design carries the cranks on the reducer's output shaft, "
           "which is the distribution shaft (no coupling: chapter \"Drive design\")")
         if not any(st.kind == "coupling" for st in r["drive"].stages) else "—"],
        [_("actuators"),
         _("fixed upper die, lower platen lifted by a six-bar toggle linkage; a cam opens "
           "the spring grippers; an incomplete gear drives the gripper chain "
           "intermittently"), "—"],
    ]
    return rows


def _choice_rows(b, p, r, _) -> list[list[str]]:
    from ...stages.flywheel import CAST_IRON_RIM_SPEED

    """Values this design chooses where the task is silent, with the reasons."""
    pr, ms, ct = b.press, b.masses, b.cutting
    from ...core.motion_laws import LAWS

    cam = b.gripper_cam
    ig = r["feed"].gear
    seg = cam.programme
    F_kN = f(p.cutting_force / 1e3, 0)
    t_mm = f(p.pressing_travel * MM, 1)
    given = pr.dimensions is not None
    g = p.geometry
    H_mm = g.stroke * MM
    sub = _(" (derived)") if given else ""
    rows = [
        ["$H$", _("platen stroke") + sub,
         f"{f(H_mm, 2) if given else f(pr.stroke_H_mm, 1)} mm",
         _("the gripper bar and the sheet pass between die and platen; at the bottom the "
            "gap is H − t = {H_mm} mm", H_mm=f(H_mm - b.production.board_thickness_mm, 1))],
        ["$c$", _("clearance level"), f"{f(pr.clearance_mm, 1)} mm",
         _("the platen must be at least c below its top for the gripper bar (about 12 mm) "
           "and the sheet to pass, with some margin")],
        ["$K$", _("time ratio") + sub, f(g.K, 4) if given else f(pr.time_ratio_K, 2),
         _("slow rise (cutting), quick fall: the cut takes more crank angle, so the "
           "torque peak is lower")],
    ]
    if given:
        dm = pr.dimensions
        rows.append(["$a, b, d$", _("crank $O_1A$, coupler $AB$, frame $O_1C$ (given)"),
                     f"{f(dm.crank_O1A_mm, 2)}, {f(dm.coupler_AB_mm, 2)}, {f(dm.frame_O1C_mm, 2)} mm",
                     _("the brief's dimensions, no synthesis; $\\theta$, $\\psi$, K and H are derived from them "
                       "(see the toggle press chapter)")])
    rows += [
        ["$l_{CB}, l_{BD}$", _("toggle links"),
         f"{f(pr.toggle_CB_mm, 0)}, {f(pr.toggle_BD_mm, 0)} mm",
         _("longer toggles need less swing for the stroke; $BD$ longer than $CB$ never lies "
           "flat and keeps the slider's pressure angle small at the bottom")],
        ["$\\varepsilon$", _("toggle angle at the top"),
         f"{f(pr.toggle_angle_at_top_deg, 1)}°",
         _("toggle straight at the top, which is also the crank-rocker's extreme: $v_D "
           "\\to 0$ faster ($H - s \\propto \\Delta\\varphi^4$ near the top), the cutting "
           "force goes straight through the toggle into the frame")],
        ["—", _("crank-rocker extreme at the top"),
         {"extended": _("extended"), "folded": _("folded")}[pr.top_position],
         _("the rocker is slow near its extreme; with the straight toggle the platen all "
           "but dwells near the top")],
        ["—", _("toggle linkages side by side"), f"{pr.linkages}",
         _("one at each side of the platen, in phase: the planar analysis below is that of one "
           "linkage carrying the whole resistance (the sum of both); each crank on the "
           "distribution shaft takes half of its force and of the torque") if pr.linkages == 2 else
         _("the planar analysis below carries the whole resistance")],
        ["$F_c$", _("cutting force"), f"{F_kN} kN",
         _("total rule length L = {cut_length_m} m (estimate) × resistance per mm of rule "
            "q = {specific_resistance_N_per_mm} N/mm (assumed)", cut_length_m=f(ct.cut_length_m, 1),
            specific_resistance_N_per_mm=f(ct.specific_resistance_N_per_mm, 0))],
        ["$t$", _("pressing travel"), f"{t_mm} mm",
         _("the board thickness; $F_c$ is taken constant over it (on the safe side: the "
           "real force builds up as the rule cuts in)")],
        ["$m_6$", _("platen and slide mass"), f"{f(ms.platen_kg, 0)} kg",
         _("cast-iron platen about 750 × 520 × 70 mm")],
        ["$m_3, m_4, m_5$", _("coupler and toggle masses (uniform bars)"),
         f"{f(ms.coupler_AB_kg, 0)}, {f(ms.toggle_CB_kg, 0)}, {f(ms.toggle_BD_kg, 0)} kg",
         _("estimated from the sections")],
        ["$[\\delta]$", _("allowed speed fluctuation"),
         fluctuation(p.fluctuation),
         _("presses 1/7–1/20 (textbook table); die cutting is not sensitive to the speed "
           "fluctuation")],
        ["—", _("flywheel"), _shaft(p.flywheel_shaft, len(b.drive.stages), _),
         _("a fast shaft needs far less inertia ($J \\propto 1/n^2$)")],
        # the rim's mean diameter, which chapter 7 calls the brief's (page review 48: in
        # neither table)
        ["$D$", _("flywheel rim mean diameter"), f"{f(p.rim_diameter * 1e3, 0)} mm",
         _("rim speed {v} m/s ≤ {limit} m/s (cast iron)",
           v=f(r["press_flywheel"].rim.rim_speed, 2), limit=f(CAST_IRON_RIM_SPEED, 0))]
        if r["press_flywheel"].rim is not None else None,
        (["$h$", _("gripper cam lift"), f"{f(cam.follower.stroke_h_mm, 1)} mm",
          _("push-rod travel that opens the grippers")]
         if cam.follower.motion == "translating" else
         ["$\\varphi_{max}$", _("gripper cam lever swing"),
          f"{f(cam.follower.max_swing_deg, 1)}°",
          _("lever swing that opens the grippers")]),
        ["—", _("gripper cam angles"),
         " / ".join(f"{f(s_.angle_deg, 0)}°" for s_ in seg),
         _("{name_en} rise and return: velocity and acceleration continuous at the ends, "
            "neither rigid nor soft impact", name_en=LAWS[seg[0].law].name_en,
            name_zh=LAWS[seg[0].law].name_zh)],
        ["$m; z_1, z_1', z_2$", _("incomplete gear"),
         f"{f(ig.module * MM, 1)} mm; {ig.z1}, {ig.teeth}, {ig.z2}",
         _("the motion angle {motion_angle}° fits in the platen's clear arc; the driven "
            "wheel turns $z_1'/z_2$ of a turn per cycle", motion_angle=_deg(ig.motion_angle, 0))],
        ["$p, z_s$", _("chain pitch, sprocket teeth"),
         f"{f(b.chain.pitch_mm, 2)} mm, {b.chain.sprocket_teeth}",
         _("one gripper-bar spacing {bar_spacing_mm} mm per cycle (sheet length plus the "
            "bar and a gap)", bar_spacing_mm=f(b.chain.bar_spacing_mm, 1))],
        ["$K_A$", _("application factor"), f(b.drive.service.application_factor_KA, 2),
         _("shock load")],
    ]
    return [row for row in rows if row is not None]


def _shaft(index: int, stages: int, _) -> str:
    if index == 0:
        return _("motor shaft")
    if index == stages:
        return _("distribution shaft")
    return _("shaft {index}", index=shaft_numeral(index))


def _shaft_in_text(index: int, stages: int, _) -> str:
    """The shaft as a sentence names it: "shaft Ⅰ" (no article before a numbered shaft), "the
    distribution shaft", "the motor shaft"."""
    if index == 0:
        return _("the motor shaft")
    if index == stages:
        return _("the distribution shaft")
    return _shaft(index, stages, _)


def _synthesis(d, p, _) -> dict:
    g = d.geometry
    lt, ld = g.toggle_CB * MM, g.toggle_BD * MM
    eps, psi = g.top_angle, d.swing
    fb = d.four
    K = g.K
    theta = d.theta * DEG
    given = None
    if g.given is not None:
        a, b, c, d_ = fb.crank * MM, fb.coupler * MM, lt, fb.frame * MM

        def ang(x, y, z):       # angle opposite z [°]
            return float(np.degrees(np.arccos(np.clip((x * x + y * y - z * z) / (2 * x * y), -1, 1))))
        given = {
            "cosines": (r"\angle O_1CB_{1,2} = \arccos\frac{d^2 + c^2 - (b \mp a)^2}{2dc},\qquad "
                        r"\angle CO_1B_{1,2} = \arccos\frac{(b \mp a)^2 + d^2 - c^2}{2(b \mp a)d}"),
            "psi": (rf"\psi = \angle O_1CB_2 - \angle O_1CB_1 = {f(ang(d_, c, b + a), 2)}° - "
                    rf"{f(ang(d_, c, b - a), 2)}° = {_deg(psi, 2)}°"),
            "theta": (rf"\theta = \lvert\angle CO_1B_1 - \angle CO_1B_2\rvert = \lvert {f(ang(b - a, d_, c), 2)}° - "
                      rf"{f(ang(b + a, d_, c), 2)}°\rvert = {f(theta, 2)}°"),
            "K": (rf"K = \frac{{180° + \theta}}{{180° - \theta}} = \frac{{180° + {f(theta, 2)}°}}"
                  rf"{{180° - {f(theta, 2)}°}} = {time_ratio(K)}"),
            "H": (rf"H = y_D(\varepsilon) - y_D(\varepsilon + \psi) = {f(d.top_height * MM, 2)} - "
                  rf"{f(d.bottom_height * MM, 2)} = {f(g.stroke * MM, 2)}\ \text{{mm}}"),
            "lengths": (rf"a = {f(a, 2)},\quad b = {f(b, 2)},\quad c = l_{{CB}} = {f(c, 2)},\quad "
                        rf"d = {f(d_, 2)}\ \text{{mm}}"),
        }
    eq = {
        "height": (r"y_D(\beta) = l_{CB}\cos\beta + \sqrt{l_{BD}^2 - l_{CB}^2\sin^2\beta}"),
        "stroke": (rf"H = y_D(\varepsilon) - y_D(\varepsilon + \psi) = {f(d.top_height * MM, 2)} - "
                   rf"{f(d.bottom_height * MM, 2)} = {f(g.stroke * MM, 2)}\ \text{{mm}}"
                   rf"\ \Rightarrow\ \psi = {_deg(psi, 2)}°"),
        "theta": (rf"\theta = 180° \times \frac{{K-1}}{{K+1}} = 180° \times \frac{{{f(K, 3)}-1}}"
                  rf"{{{f(K, 3)}+1}} = {f(theta, 2)}°"),
        "links": (rf"a = \frac{{AC_2 - AC_1}}{{2}} = {f(fb.crank * MM, 2)}\ \text{{mm}},\quad "
                  rf"b = \frac{{AC_2 + AC_1}}{{2}} = {f(fb.coupler * MM, 2)}\ \text{{mm}},\quad "
                  rf"d = {f(fb.frame * MM, 2)}\ \text{{mm}}"),
        "gamma": (rf"\cos\delta = \frac{{b^2 + c^2 - (d \mp a)^2}}{{2bc}}\ \Rightarrow\ "
                  rf"\gamma_{{min}} = {_deg(d.gamma_min, 2)}°"),
        "virtual": r"M\,\omega = F\,v_D\ \Rightarrow\ F = \frac{M\,\omega}{v_D} = \frac{M}{dy_D/d\varphi}",
        "chain_rule": (r"\frac{dy_D}{d\varphi} = \frac{dy_D}{d\theta_4}\,\frac{\omega_4}{\omega_2},\quad "
                       r"\frac{\omega_4}{\omega_2} = \frac{a\sin(\theta_2 - \theta_3)}{c\sin(\theta_4 - \theta_3)},"
                       r"\quad \frac{dy_D}{d\theta_4} = l_{CB}\cos\theta_4 + "
                       r"\frac{l_{CB}^2\sin\theta_4\cos\theta_4}{\sqrt{l_{BD}^2 - l_{CB}^2\cos^2\theta_4}}"),
    }
    der = _.pgettext("die_cutter", " (derived)") if given else ""
    giv = _(" (given)") if given else ""
    dig = 3 if given else 2
    rows = [
        ["$\\psi$", _("swing of $CB$") + der, _deg(psi, dig), "°"],
        ["$\\theta$", _("extreme-position angle") + der, f(theta, dig), "°"],
        ["$a = l_{O_1A}$", _("crank") + giv, f(fb.crank * MM, dig), "mm"],
        ["$b = l_{AB}$", _("coupler") + giv, f(fb.coupler * MM, dig), "mm"],
        ["$c = l_{CB}$", _("toggle (rocker)"), f(lt, 2), "mm"],
        ["$l_{BD}$", _("toggle"), f(ld, 2), "mm"],
        ["$d = l_{O_1C}$", _("frame") + giv, f(fb.frame * MM, dig), "mm"],
        ["$O_1$", _("crank pivot ($C$ at the origin)"),
         f"({f(d.O1.real * MM, 2)}, {f(d.O1.imag * MM, 2)})", "mm"],
        ["$y_D$", _("height of $D$ (top / bottom)"),
         f"{f(d.top_height * MM, 2)} / {f(d.bottom_height * MM, 2)}", "mm"],
        ["$\\gamma_{min}$", _("minimum transmission angle"),
         _deg(d.gamma_min, 2), "°"],
        ["$\\varphi_{rise}$", _("crank angle of the rise"),
         _deg(d.rising_span, 2), "°"],
    ]
    if given:
        rows[2:2] = [["$K$", _("time ratio") + der, f(K, 4), "—"],
                     ["$H$", _("platen stroke") + der, f(g.stroke * MM, 4), "mm"]]
    pivot = _("the point of the $\\theta$-circle at the given frame $O_1C$") \
        if g.frame is not None else \
        _("searched along the allowed arc of the $\\theta$-circle for the largest minimum "
           "transmission angle")
    mirrored = _("The drawing is mirrored about the guide so that the rise is the slow stroke "
                  "($K$ > 1).") \
        if d.mirrored else ""
    return {"eq": eq, "rows": rows, "pivot": pivot, "mirrored": mirrored, "given": given,
            "psi": _deg(psi, 2), "eps": _deg(eps, 2), "theta": f(theta, 2),
            "top": {"extended": _("extended position ($AC = b + a$)"), "folded": _("folded position ($AC = b - a$)")}[g.top_position]}


def _amplification(r, p, _) -> dict:
    amp, k, f_ = r["amplification"], r["press"], r["press_forces"]
    d = r["toggle"]
    n = k.grid_size
    tm = amp.timing
    a = d.four.crank
    rows = []
    for gap, ph, u, fpt, ratio in amp.table:
        # gap to 0.01 mm, φ to 0.01°; the torque F_c·M/F and F/M to 4 significant digits
        # (README "Conventions"); M/F (v_D/ω, over two decades) to 4, or 5 where the torque
        # needs them (F_c × 12.712 = 12 712, where 12.71 gives 12 710; as in M_req below)
        torque = sig(p.cutting_force * u, 4, group=False)
        mf = factor_for(u * MM, lambda x: gives(p.cutting_force / 1e3 * x, torque))
        rows.append([length(gap * MM), _deg(ph, 2), mf, sig(fpt, 4), f(ratio, 2),
                     sig(p.cutting_force * u, 4)])
    top = "∞" if not np.isfinite(amp.top_ratio) else f(amp.top_ratio, 2)
    rows.append(["0", _deg(tm.top, 2), "0" if not np.isfinite(amp.top_ratio) else
                 f(a / amp.top_ratio * MM, 2), "∞" if not np.isfinite(amp.top_ratio) else
                 sig(amp.top_ratio / a, 4), top, "0"])
    drive = r["drive"]
    motor = drive.motor
    # the motor alone: its rated torque brought to the distribution shaft
    t_motor = motor.power * drive.efficiency / abs(p.crank_omega)
    u0 = amp.table[0][2]
    f_motor = t_motor / u0
    i_peak = int(np.argmax(f_.balancing_torque[:n]))
    eq = {
        "force": (rf"F_c = L\,q = {f(p.cut_length, 2)}\ \text{{m}} \times {f(p.specific_resistance / 1e3, 1)}"
                  rf"\ \text{{N/mm}} = {f(p.cutting_force / 1e3, 1)}\ \text{{kN}}"),
        "work": (rf"W_c = F_c\,t = {f(p.cutting_force / 1e3, 1)}\ \text{{kN}} \times "
                 rf"{f(p.pressing_travel * MM, 2)}\ \text{{mm}} = {f(amp.cut_work, 1)}\ \text{{J}}"),
        "power": (rf"\bar P = \frac{{W_c}}{{T}} = \frac{{{f(amp.cut_work, 1)}}}{{{f(60 / p.shaft_rpm, 3)}}}"
                  rf" = {f(amp.cut_work * p.shaft_rpm / 60, 1)}\ \text{{W}},\qquad \bar M_b = \frac{{\bar P}}{{\omega}} = "
                  rf"\frac{{{f(amp.cut_work * p.shaft_rpm / 60, 1)}}}{{{sig(abs(p.crank_omega), group=False)}}}"
                  rf" = {sig(f_.mean_torque, group=False)}\ \text{{N·m}}"),
        "required": (rf"M_{{req}} = F_c\,\frac{{v_D}}{{\omega}} = {f(p.cutting_force / 1e3, 1)}\ "
                     rf"\text{{kN}} \times {rows[0][2]}\ \text{{mm}} = {f(p.cutting_force * u0, 0)}"
                     rf"\ \text{{N·m}}"),
        "motor": (rf"T = \frac{{P_{{ed}}\,\eta}}{{\omega}} = \frac{{{f(motor.power, 0)} \times "
                  rf"{f(drive.efficiency, 4)}}}{{{sig(abs(p.crank_omega), group=False)}}} = {f(t_motor, 1)}\ "
                  rf"\text{{N·m}},\qquad F = \frac{{T}}{{M/F}} = {f(f_motor / 1e3, 1)}\ \text{{kN}}"),
    }
    return {
        "eq": eq, "rows": rows,
        "press_up": _deg(tm.press_up, 2), "top": _deg(tm.top, 2), "press_span": _deg(tm.press_span, 2),
        "press_time": f(amp.press_time * 1e3, 1),
        "clear_up": _deg(tm.clear_up, 2), "clear_down": _deg(tm.clear_down, 2),
        "clear_span": _deg(tm.clear_span, 2), "press_down": _deg(tm.press_down, 2),
        "peak_req": f(amp.peak_required, 1), "peak_phase": _deg(amp.peak_phase, 2),
        # the exact peak (refined between the samples; the factor below uses it too), at about
        # the phase of the largest sample
        "mb_peak": sig(f_.peak_torque), "mb_peak_phase": _deg(k.phase[i_peak], 1),
        "mb_mean": sig(f_.mean_torque), "peak_factor": f(f_.peak_torque / f_.mean_torque, 2),
        "f_motor": f(f_motor / 1e3, 1), "t_motor": f(t_motor, 1), "motor": motor.designation,
        "F": f(p.cutting_force / 1e3, 1), "t": f(p.pressing_travel * MM, 2),
        "c": f(p.clearance * MM, 1), "ratio_start": f(amp.table[0][4], 2),
    }


def _flywheel(r, p, b, _) -> dict:
    fl = r["press_flywheel"]
    crank_shaft = _("distribution shaft")
    stages = len(b.drive.stages)
    shaft = _shaft(fl.shaft, stages, _)
    drive = r["drive"]
    designs = {sd.index: sd for sd in drive.shaft_designs}
    # each column what its header says: the torsion estimate A0·∛(P/n)(1 + 5 %) of the mean
    # power (the drive stage's d_min), the same of the peak power, and the seat diameter the
    # drive design reached with its strength checks at the peak torque
    rows = [[_shaft(s.index, stages, _), f(s.speed_rpm, 2), sig(s.torque),
             sig(s.peak_torque), f(designs[s.index].d_min * MM, 1),
             f(s.d_peak * MM, 1), f(s.d_seat * MM, 0)]
            for s in r["peak_shafts"]]
    # the distribution shaft's peak in the table is the drive's torque there (the mean power
    # at the realised speed, through the losses after that shaft) × the peak factor; the
    # mechanism's own max|M_b| (the analysis chapter) is at the nominal speed: say which is which
    last = [s for s in r["peak_shafts"] if s.index == stages]
    peak_note = (_("On the distribution shaft the table's peak torque {T} N·m is the drive's torque "
                   "there ({Tm} N·m: the mean power at the realised {n} rpm and the losses after "
                   "that shaft) × the peak factor {k}; the mechanism's own largest $|M_b|$ of the "
                   "force analysis, at the nominal {n0} rpm, is {Mb} N·m.",
                   T=sig(last[0].peak_torque), Tm=sig(last[0].torque), n=f(last[0].speed_rpm, 2),
                   k=f(drive.peak_factor, 2), n0=f(p.shaft_rpm, 2),
                   Mb=sig(r["press_forces"].peak_torque))
                 if last and drive.peak_factor > 0 else "")
    # the flywheel is sized at the nominal speed (the distribution shaft's n, at which M_b and
    # ΔW_max are computed, × the realised ratios after the flywheel); the drive realises the
    # motor's full-load speed through its realised ratios: the same flywheel there gives
    # δ = [δ]·(n_nominal/n_realised)²
    real = realised_flywheel(fl, drive.shafts[fl.shaft].speed_rpm, _)
    if real:
        real = sentences(_, real, _("(The distribution shaft: nominal {n_crank} rpm, realised "
                                    "{n_crank_real} rpm.)", n_crank=f(p.shaft_rpm, 2),
                                    n_crank_real=f(drive.output_speed, 2)))
    speeds = {"real": real, "n_crank": f(p.shaft_rpm, 2)}
    # the speed ratio with the digits that give the printed J_F' (14.118: 6.404 × 14.118²)
    def fl_ratio_ok(x):
        return gives(float(f(fl.inertia, 3)) * x * x, f(fl.inertia_on_crank, 1))

    j_mass = rim_inertia_factor(fl.inertia, fl.rim)
    ratio_factor = factor_for(fl.speed_ratio, fl_ratio_ok)
    energy_digits = len(f(fl.max_energy_swing, 1).replace(".", "").lstrip("0"))
    eq = {
        "md": (rf"M_d = \frac{{1}}{{2\pi}}\oint M_b\,d\varphi = {sig(fl.mean_torque, group=False)}\ \text{{N·m}}"
               rf"\ (\text{{{crank_shaft}}})"),
        # ΔW_max with the text's digits (3499.5) or more
        "jf": flywheel_equation(fl.max_energy_swing, fl.shaft_speed_rpm, fl.fluctuation,
                                f(fl.inertia, 3), energy_digits),
        "jf_note": carried_note(_, flywheel_carried(
            fl.max_energy_swing, fl.shaft_speed_rpm, fl.fluctuation, f(fl.inertia, 3),
            f(fl.shaft_speed_rpm, 2), f(fl.max_energy_swing, 1), energy_digits)),
        "crank": (rf"J_F' = J_F\,i^2 = {f(fl.inertia, 3)} \times {ratio_factor}^2 = "
                  rf"{f(fl.inertia_on_crank, 1)}\ \text{{kg·m}}^2"),
        "crank_note": carried_note(_, [("i", sig(fl.speed_ratio), ratio_factor)]),
        "mass": (rf"m = \frac{{4 J_F}}{{D^2}} = \frac{{4 \times {j_mass}}}"
                 rf"{{{f(fl.rim.diameter, 3)}^2}} = {f(fl.rim.rim_mass, 2)}\ \text{{kg}}"),
        "mass_note": carried_note(_, [("J_F", f(fl.inertia, 3), j_mass)]),
        "width": rim_width_equation(p.gravity, f(fl.inertia, 3), fl.rim.diameter,
                                    p.rim_height_to_width, p.specific_weight, fl.rim.width),
    }
    return {"eq": eq, "shaft": shaft, "shaft_on": _shaft_in_text(fl.shaft, stages, _),
            "n": f(fl.shaft_speed_rpm, 2), "ratio": sig(fl.speed_ratio),
            "dw": f(fl.max_energy_swing, 1), "at_min": _deg(fl.phase_at_min, 1),
            "at_max": _deg(fl.phase_at_max, 1), "delta": fluctuation(fl.fluctuation),
            "jf": f(fl.inertia, 3), "jf_crank": f(fl.inertia_on_crank, 1),
            "D": f(fl.rim.diameter * MM, 0), "b": f(fl.rim.width * MM, 1),
            # the rim's H/b and γ from the brief, said where the formula uses them (page
            # review 47: "H/b = 1.5" was typed in the text and γ = 70000 never introduced)
            "hb": f(p.rim_height_to_width, 2), "gamma": f(p.specific_weight, 0, group=True),
            "Hr": f(fl.rim.height * MM, 1), "m": f(fl.rim.rim_mass, 2),
            "speed": f(fl.rim.rim_speed, 2), "peak_rows": rows, "peak_note": peak_note, **speeds,
            "share": f(fl.max_energy_swing / r["amplification"].cut_work * 100, 1),
            "place": _placement(r, p, b, _)}


def _inertia(J: float) -> str:
    """J_F as the flywheel chapter writes it: three decimals, one from 100 kg·m² on."""
    return f(J, 3 if J < 100 else 1, group=True)


def _placement(r, p, b, _) -> dict:
    """The brief's flywheel placement against the other one, both designed (stage
    flywheel_placement): flywheel, gear stages, shafts, masses."""
    cmp_ = r["flywheel_placement"]
    stages = len(b.drive.stages)
    a, o = cmp_.chosen, cmp_.other
    rows = [[_("flywheel shaft speed $n$ (nominal) /rpm"), f(a.speed_rpm, 2), f(o.speed_rpm, 2)],
            [_("flywheel $J_F$ /kg·m²"), _inertia(a.inertia), _inertia(o.inertia)],
            [_("rim $D$ × $b$ × $H_F$ /mm"), " × ".join(f(x * MM, 0) for x in (a.rim.diameter, a.rim.width, a.rim.height)),
             " × ".join(f(x * MM, 0) for x in (o.rim.diameter, o.rim.width, o.rim.height))],
            [_("rim mass /kg"), f(a.rim.rim_mass, 1, group=True), f(o.rim.rim_mass, 1, group=True)]]
    for ga, go in zip(a.gears, o.gears):
        rows.append([_("stage {k}: $m_n$ / $d_2$ / $b$ /mm", k=ga.index + 1),
                     f"{f(ga.module * MM, 0)} / {f(ga.d2 * MM, 1)} / {f(ga.face_width * MM, 0)}",
                     f"{f(go.module * MM, 0)} / {f(go.d2 * MM, 1)} / {f(go.face_width * MM, 0)}"])
    rows.append([_("hub seats, {names} /mm",
                   names=" / ".join(_shaft(k + 1, stages, _) for k in range(len(a.shaft_seats)))),
                 " / ".join(f(x * MM, 0) for x in a.shaft_seats),
                 " / ".join(f(x * MM, 0) for x in o.shaft_seats)])
    rows.append([_("gear wheels (solid discs $\\rho\\pi d_2^2 b/4$) /kg"), f(a.gear_mass, 1, group=True),
                 f(o.gear_mass, 1, group=True)])
    total_a, total_o = a.rim.rim_mass + a.gear_mass, o.rim.rim_mass + o.gear_mass
    rows.append([_("rim and gear wheels /kg"), f(total_a, 1, group=True), f(total_o, 1, group=True)])
    return {"rows": rows, "chosen": _shaft(a.shaft, stages, _), "other": _shaft(o.shaft, stages, _),
            "chosen_on": _shaft_in_text(a.shaft, stages, _), "other_on": _shaft_in_text(o.shaft, stages, _),
            "j_ratio": f(o.inertia / a.inertia, 1), "n_ratio2": f((a.speed_rpm / o.speed_rpm) ** 2, 1),
            "n_a": f(a.speed_rpm, 2), "n_o": f(o.speed_rpm, 2),
            "gear_ratio": f(a.gear_mass / o.gear_mass, 1) if o.gear_mass > 0 else "—",
            "lighter": total_a <= total_o, "total_a": f(total_a, 0, group=True),
            "total_o": f(total_o, 0, group=True), "stages": stages,
            "peak": f(r["drive"].peak_factor, 2), "KA": f(r["drive"].KA, 2),
            "other_upstream": o.shaft > a.shaft}


def _feed(r, b, p, _) -> dict:
    """The chain, and the incomplete gear's motion angle against the platen's clear arc."""
    fd = r["feed"]
    g = fd.gear
    t = g.times()
    rows = [
        ["$p$", _("chain pitch"), f(p.chain_pitch * MM, 2), "mm"],
        ["$z_s$", _("sprocket teeth"), str(p.sprocket_teeth), "—"],
        ["$R_s$", _("sprocket pitch radius $p/(2\\sin(180°/z_s))$"),
         f(fd.sprocket_radius * MM, 2), "mm"],
        ["$L$", _("feed per cycle $(z_1'/z_2)\\,z_s\\,p$"),
         f(fd.feed * MM, 2), "mm"],
        ["$L_0$", _("gripper-bar spacing (required)"), f(p.bar_spacing * MM, 2), "mm"],
        ["$t_m$", _("feed time"), f(t[1], 3), "s"],
        ["$\\bar v_c$", _("mean chain speed while feeding $L/t_m$"),
         f(fd.chain_speed, 3), "m/s"],
        ["$\\Delta v_c$", _("chain speed jump at engagement $R_s\\,\\Delta\\omega_2$"), f(fd.chain_jump, 3), "m/s"],
    ]
    eq = (rf"L = \frac{{z_1'}}{{z_2}}\,z_s\,p = \frac{{{g.teeth}}}{{{g.z2}}} \times {p.sprocket_teeth} "
          rf"\times {f(p.chain_pitch * MM, 2)} = {f(fd.feed * MM, 2)}\ \text{{mm}}")
    clear = r["amplification"].timing.clear_span
    available = clear - 2 * p.margin
    rel = r"\le" if g.motion_angle <= available else ">"
    eq_timing = (rf"\varphi_m = 360° \times \frac{{z_1'}}{{z_1}} = 360° \times \frac{{{g.teeth}}}{{{g.z1}}} = "
                 rf"{_deg(g.motion_angle, 2)}° {rel} "
                 rf"{_deg(clear, 2)}° - 2 \times {_deg(p.margin, 1)}° = {_deg(available, 2)}°")
    eq_ratio = (rf"k = \frac{{\varphi_m}}{{360° - \varphi_m}} = \frac{{{_deg(g.motion_angle, 2)}}}"
                rf"{{{_deg(g.dwell_angle, 2)}}} = {f(g.motion_dwell_ratio, 4)}")
    return {"rows": rows, "eq": eq, "auto": fd.start_auto, "start": _deg(g.motion_start, 1),
            "feed": f(fd.feed * MM, 2), "jump": f(fd.chain_jump, 3), "eq_timing": eq_timing,
            "eq_ratio": eq_ratio, "fits": bool(g.motion_angle <= available), "clear_span": _deg(clear, 2),
            "margin": _deg(p.margin, 1)}


def _ok(_, good: bool) -> str:
    return verdict(good, _.lang)


def _verify_rows(r, p, _) -> list[list[str]]:
    from ...render.linkage_report import verification_rows

    v, k, amp = r["verification"], r["press"], r["amplification"]
    f_ = r["press_forces"]
    g = r["toggle"].geometry
    step = v.grid_step
    rows = verification_rows(r["press_verification"], _.lang, k)
    # The top is flat to order n: a position search places it only within δφ, so the
    # K it finds carries that uncertainty (the velocity zeros are exact).
    vk = r["press_verification"]
    for row in rows:
        if row[0] == _("$K$ by position search"):
            row[2] = _("{time_ratio} ± {K_search_tol} (top flat as $H - s \\propto \\Delta\\varphi^n$, n "
                        "= {top_order}: a position search resolves about {search_angle_tol} rad)",
                        time_ratio=f(k.time_ratio, 4), K_search_tol=e(v.K_search_tol),
                        top_order=f(v.top_order, 2), search_angle_tol=e(v.search_angle_tol))
            row[3] = _ok(_, abs(vk.time_ratio - k.time_ratio) <= v.K_search_tol + 1e-6)
    # the switch-on of F_c falls between grid points: the mean of M_b is off by at most
    # one jump × one step / 2π
    bound = float(amp.peak_required * step / (2 * np.pi) / f_.mean_torque)
    rows += [
        [_("simulated stroke − $H$ /mm"), residue(v.stroke_error * MM, g.stroke * MM),
         f"H = {f(g.stroke * MM, 2)} mm", _ok(_, abs(v.stroke_error) < 1e-9)],
        [_("simulated $K$ (zeros of the output speed)"),
         f(k.time_ratio, 4), f"K = {f(g.K, 4)} ± {e(v.K_velocity_tol)}",
         _ok(_, abs(k.time_ratio - g.K) <= v.K_velocity_tol)],
        [_("toggle angle at the simulated top /°"),
         e(v.top_toggle_angle * DEG), f"ε = {f(g.top_angle * DEG, 2)}°",
         _ok(_, abs(v.top_toggle_angle - g.top_angle) <= max(v.search_angle_tol, 1e-8))],
        [_("order $n$ of $H - s \\propto \\Delta\\varphi^n$ near the top"), f(v.top_order, 3),
         "4 (ε = 0) / 2 (ε > 0)", _ok(_, abs(v.top_order - (4 if g.top_angle == 0 else 2)) < 0.05)],
        [_("force amplification: kinetostatics vs virtual-work closed form (relative)"),
         e(v.amplification_error), "≤ 10⁻⁹", _ok(_, v.amplification_error < 1e-9)],
        [_("energy balance $\\oint M_b d\\varphi / (F_c t)$"),
         f(v.energy_ratio, 4), f"1 ± {f(bound, 4)}", _ok(_, abs(v.energy_ratio - 1) <= bound)],
        [_("platen row vs simulated $s$: disagreeing angle /°"),
         f(v.platen_mismatch * DEG, 2), f"≤ {f(2 * step * DEG, 2)}", _ok(_, v.platen_mismatch <= 2 * step + 1e-12)],
        [_("gripper row vs cam lift: disagreeing angle /°"),
         f(v.gripper_mismatch * DEG, 2), f"≤ {f(2 * step * DEG, 2)}", _ok(_, v.gripper_mismatch <= 2 * step + 1e-12)],
        [_("chain row vs incomplete gear motion: disagreeing angle /°"),
         f(v.chain_mismatch * DEG, 2), f"≤ {f(2 * step * DEG, 2)}", _ok(_, v.chain_mismatch <= 2 * step + 1e-12)],
        [_("chain feed − gripper-bar spacing /mm"),
         residue(v.feed_error * MM, p.bar_spacing * MM), "0", _ok(_, abs(v.feed_error) < 1e-8)],
    ]
    return rows


def _findings(r, lang: str) -> list[str]:
    """Every stage's findings; the drive's (listed in its own chapter) as one summary line."""
    _ = tr(lang)
    out = []
    for key in ("press_verification", "press_flywheel", "cam", "feed", "cycle"):
        for w in getattr(r.get(key), "warnings", None) or ():
            text = md_text(w.text(lang))
            if text not in out:
                out.append(text)
    drive = r["drive"].warnings
    if drive:
        peak = r["peak_shafts"]
        text = _("{n} checks of the drive design fail (listed in the drive chapter's problems)",
                 n=len(drive))
        if peak:
            text += _("; the shafts, bearings and keys after the flywheel carry the peak torque (table "
                      "\"shafts after the flywheel\"); the shaft design enlarges each section until its checks "
                      "pass or the bearing catalogue ends: what still fails needs the remedy the problems "
                      "name")
        out.append(text + _("."))
    return out


def _cells(rows: list[list[str]]) -> list[list[str]]:
    """Escape the pipes inside table cells (e.g. max|M_b ω|), which would split the cell."""
    return [[c.replace("|", "\\|") for c in row] for row in rows]


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    """Strings, rows and formulas for the templates."""
    from ...render.cam_report import cam_context
    from ...render.components_report import cycle_context, intermittent_context
    from ...render.drive_report import drive_context
    from ...render.linkage_report import linkage_context

    _ = tr(lang)
    p = r["params"]
    k, f_ = r["press"], r["press_forces"]
    lk = linkage_context(r["press_model"], k, f_, None, r["press_verification"], figures, lang,
                         prefix="press",
                         title=_("Toggle press: kinematics and kinetostatics"))
    cam = cam_context(r["cam"], lang, figures, "cam_profile.csv", brief.gripper_cam)
    ig = intermittent_context(r["feed"].gear, r["feed"].curves, lang, {"motion": figures["ig_motion"]}, level=2,
                              label="dc-ig")
    cyc = r["cycle"]
    cycle = cycle_context(cyc.diagram, lang, {"linear": figures["cycle_linear"],
                                             "circular": figures["cycle_circular"]},
                          cyc.checks, level=2, label="dc-cycle")
    # the power as the flywheel chapter writes it (636.6 × 5.236 = 3333 W: one value one way)
    pw_text = sig(f_.mean_power, 4, group=False)
    pw = (rf"P_w = \bar M_b\,\omega = {product((f_.mean_torque, abs(p.crank_omega)), pw_text)} = "
          rf"{pw_text}\ \text{{W}}")
    drive = drive_context(r["drive"], lang, figures, pw)
    verify = _verify_rows(r, p, _)
    for row in cycle["verify"] + ig["verify"]:
        value = number(row[1])
        verify.append([row[0], row[1], "0", _ok(_, abs(value) < 1e-6)])
    gear = r["feed"].gear
    return {
        "meta": md_meta(brief.report, lang), "fig": figures,
        "rpm": f(p.shaft_rpm, 2), "period": f(60 / p.shaft_rpm, 3), "omega": sig(abs(p.crank_omega)),
        "sense": _("clockwise") if p.crank_omega < 0 else _("counter-clockwise"),
        "data_rows": _data_rows(brief, p, r, _), "choice_rows": _choice_rows(brief, p, r, _),
        "syn": _synthesis(r["toggle"], p, _), "amp": _amplification(r, p, _),
        "fly": _flywheel(r, p, brief, _), "feed": _feed(r, brief, p, _),
        "linkage": lk, "cam": cam, "ig": ig, "cycle": cycle, "drive": drive,
        "gripper_start": _deg(cyc.gripper_start, 1), "gripper_auto": cyc.gripper_auto,
        "feed_start": _deg(gear.motion_start, 1),
        "verify_rows": _cells(verify), "findings": _findings(r, lang),
    }
