"""Prepare the shaper report: figures and the template context (strings only).

All formatting and unit conversion for display happens here, so the templates
contain no logic: they place prepared strings, tables (lists of rows) and LaTeX
formulas with the numbers already substituted. Report units are the course's
(mm, °, rpm, N, N·m, J, kg·m²).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ...render import figures as fig
from ...render import guide_bar_report as gb_report
from ...i18n import N_, tr
from ...render.fmt import e, f, in_lang, md_meta, sig, time_ratio, verdict, fluctuation
from ...render.linkage_report import (carried_note, flywheel_carried, flywheel_equation, rim_inertia_factor,
                                      rim_width_equation)

DEG = 180.0 / np.pi


def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    """Draw every figure into ``fig_dir``; return name → relative path for the template."""
    k, frc, fl, syn = r["kinematics"], r["forces"], r["linkage_flywheel"], r["synthesis"]
    n = k.grid_size
    ph = k.phase[:n] * DEG
    span = k.working_span * DEG
    pos_ph = k.phase[n:] * DEG
    labels = list(k.positions.labels)
    paths = {}

    def out(name):
        paths[name] = f"{fig_dir.name}/{name}.png"
        return fig_dir / f"{name}.png"

    lab = fig.LABELS[lang]
    fig.curves_vs_phase(out("ram_motion"), lang, ph,
                        [k.ram_s[:n] * 1e3, k.ram_v[:n], k.ram_a[:n]],
                        [lab["s"], lab["v"], lab["a"]], span,
                        (labels, pos_ph, [k.ram_s[n:] * 1e3, k.ram_v[n:], k.ram_a[n:]]))
    fig.curves_vs_phase(out("guide_bar"), lang, ph, [k.omega4[:n], k.alpha4[:n]],
                        [lab["w4"], lab["a4"]], span,
                        (labels, pos_ph, [k.omega4[n:], k.alpha4[n:]]), size=(7.0, 4.4))
    fig.balancing_torque(out("balancing_torque"), lang, ph, frc.balancing_torque[:n],
                         fl.mean_torque, frc.cutting_force[:n], span,
                         (labels, pos_ph, frc.balancing_torque[n:]))
    fig.energy(out("energy"), lang, ph, fl.energy, fl.phase_at_min * DEG,
               fl.phase_at_max * DEG, fl.max_energy_swing, span)
    fig.reactions(out("reactions"), lang, ph,
                  {f"$F_{{{name}}}$": np.abs(frc.reactions[key][:n]) for name, key in _REACTIONS}, span)
    regular = [i for i, s in enumerate(k.positions.special) if not s]
    pts = {name: k.points[name][n:][regular] * 1e3 for name in ("O2", "O3", "A", "B", "F")}
    fig.mechanism(out("mechanism"), lang, pts, [labels[i] for i in regular],
                  syn.design.guide_height * 1e3, syn.design.crank * 1e3)
    paths.update(gb_report.optional_figures(r, fig_dir, lang))
    return paths


TITLE = N_("Shaper linkage in motion")


def animation_args(results: dict, lang: str) -> dict:
    """Arguments of :func:`~mechdesign.render.animation.write_mechanism_gif` (mm): the crank,
    the guide bar, the rod, the slider blocks at A and F, the ram guide, F's trace."""
    k = results["kinematics"]
    d = results["synthesis"].design
    n = k.grid_size
    pts = {name: np.asarray(k.points[name][:n], dtype=complex) * 1e3
           for name in ("O2", "O3", "A", "B", "F")}
    bar_angle = np.angle(pts["B"] - pts["O3"])
    y = float(d.guide_height) * 1e3
    fx = pts["F"].real
    extra = 0.3 * max(float(np.ptp(fx)), 1.0)  # the guide reaches past the ram's travel
    guide = (complex(fx.min() - extra, y), complex(fx.max() + extra, y))
    return dict(points=pts, bars=[("O2", "A"), ("O3", "B"), ("B", "F")], pivots=["O2", "O3"],
                sliders=[("A", bar_angle), ("F", 0.0)], guides=[guide], trace="F",
                title=tr(lang)(TITLE))


def animate(r: dict, path: Path, lang: str, **kwargs) -> Path:
    """The GIF of the linkage turning through one revolution (format gif); ``kwargs``
    (frames, fps, size_px) pass through to the GIF writer."""
    from ...render.animation import write_mechanism_gif

    args = animation_args(r, lang)
    return write_mechanism_gif(path, args.pop("points"), args.pop("bars"), **args, **kwargs)


write_data = gb_report.write_data   # the cam profile as CSV


# Reaction symbols shown in the report (force of the first link on the second).
_REACTIONS = [("R72", "R72"), ("R23", "R23"), ("R43", "R43"), ("R74", "R74"),
              ("R45", "R45"), ("R56", "R56"), ("R76", "R76")]


def _verify_rows(v, syn, lang: str) -> list[list[str]]:
    """The verification table: [check, result, limit, verdict]; every verdict is the
    ``passed`` of a check of :func:`~mechdesign.machines.shaper.stages.self_checks`."""
    from ...render.fmt import e as fmt_e, residue
    from .stages import self_checks

    _ = tr(lang)
    c = {chk.key: chk for chk in self_checks(v, syn)}
    mm = 1e3

    def e(x: float) -> str:      # a limit that is a power of ten as 10⁻⁹ (the linkage table's form)
        power = round(np.log10(x)) if x > 0 else None
        if power is not None and abs(x - 10.0 ** power) < 1e-12 * x:
            return "10" + str(power).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))
        return fmt_e(x)

    def row(name, result, limit, key):
        return [name, result, limit, verdict(c[key].passed, lang)]

    return [
        row(_("Vector-loop closure residual (max) /m"), fmt_e(v.closure_residual),
            f"≤ {e(c['closure'].limit)}", "closure"),
        row(_("Velocity vs. central differences of position (relative, step %(step)s°)")
            % {"step": f(v.fd_step * DEG, 3)}, fmt_e(v.velocity_fd_error),
            f"≤ {e(c['velocity_fd'].limit)}", "velocity_fd"),
        row(_("Acceleration vs. central differences of velocity (relative)"),
            fmt_e(v.acceleration_fd_error), f"≤ {e(c['acceleration_fd'].limit)}", "acceleration_fd"),
        row(_("Simulated stroke − $H$ /mm"), residue(v.stroke_error * mm, syn.stroke * mm),
            f"± {e(c['stroke'].limit * mm)}", "stroke"),
        # K to 0.001 (review45: "1.2000 | 1.2000 ± 10⁻⁶"); the tolerance and the verdict
        # say how closely it agrees
        row(_("Time ratio $K$ of the simulated linkage"), time_ratio(v.time_ratio_simulated),
            f"{time_ratio(c['time_ratio'].reference)} ± {e(c['time_ratio'].limit)}", "time_ratio"),
        row(_("Power balance residual $\\Sigma P / \\max\\lvert M_b\\,\\omega\\rvert$"),
            fmt_e(v.power_balance_residual), f"≤ {e(c['power_balance'].limit)}", "power_balance"),
    ]


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    """Strings, rows and formulas for the templates."""
    p, syn, k, frc, fl, v = (r[key] for key in ("params", "synthesis", "kinematics", "forces",
                                               "linkage_flywheel", "verification"))
    _ = tr(lang)
    zh_words = tr("zh")     # the guide-bar tables take the ram's and the load's Chinese names
    d = syn.design
    n = k.grid_size
    mm = 1e3
    K, H = syn.time_ratio, syn.stroke * mm
    theta = syn.extreme_angle * DEG
    lk, ld = brief.linkage, brief.loads

    data_rows = gb_report.data_rows(
        brief, p, zh_words.pgettext("shaper", "ram"), "BF", lk.rod_ratio_BF_O3B,
        [["$x_{S_6}$", _.pgettext("shaper", "ram CoM from $F$"), f(lk.ram_com_x_S6_mm, 0), "mm"],
         *([["$y_{S_6}$", _.pgettext("shaper", "ram CoM above $F$"), f(lk.ram_com_y_S6_mm, 0), "mm"]]
           if "ram_com_y_S6_mm" in lk.model_fields_set else [])],
        zh_words.pgettext("shaper", "cutting resistance"),
        ["$y_P$", _("cutting line above $O_2$"), f(ld.cutting_height_yP_mm, 0), "mm"])
    guide_bar = gb_report.guide_bar_context(syn, p, "BF", zh_words.pgettext("shaper", "ram"), [
        ["$L_{O_2M}$", _("guide line above $O_2$"), f(syn.guide_height_above_O2 * mm, 2), "mm"]])
    # Course typography: primes, not apostrophes (8′).
    labels = [lab.replace("'", "′") for lab in k.positions.labels]
    kin_rows, load_rows, reaction_rows = [], [], []
    for i, label in enumerate(labels):
        j = n + i
        kin_rows.append([label, f(k.phase[j] * DEG, 2), f((k.crank_angle[j] * DEG) % 360, 2),
                         f(k.ram_s[j] * mm, 2), f(k.ram_v[j], 3), f(k.ram_a[j], 3),
                         f(k.omega4[j], 3), f(k.alpha4[j], 3), f(k.slide_v[j], 3),
                         f(k.coriolis[j], 3)])
        load_rows.append([label, f(frc.cutting_force[j], 0), f(frc.inertia_force4[j], 1),
                          f(frc.inertia_couple4[j], 2), f(frc.inertia_force6[j], 1),
                          f(frc.balancing_torque[j], 2)])
        reaction_rows.append([label] + [f(abs(frc.reactions[key][j]), 1, group=True) for _name, key in _REACTIONS])
    # Worked example at one position with the analytic formulas of the guide-bar group.
    ex = labels.index("4") if "4" in labels else 1  # the course's usual worked position
    j = n + ex
    phi2 = k.crank_angle[j]
    phi4 = r["linkage_raw"].links["4"].angle[j]
    w2 = p.crank_omega
    S = np.sqrt(d.frame**2 + d.crank**2 + 2 * d.frame * d.crank * np.sin(phi2))
    w4_formula = d.crank * w2 * np.cos(phi2 - phi4) / S
    vr_formula = -d.crank * w2 * np.sin(phi2 - phi4)
    worked = {
        "label": labels[ex],
        "S": (rf"S = \sqrt{{{f(d.frame, 4)}^2 + {f(d.crank, 4)}^2 + 2 \times {f(d.frame, 4)} \times "
              rf"{f(d.crank, 4)} \sin {f(phi2 * DEG % 360, 2)}°}} = {f(S, 4)}\ \text{{m}}"),
        "w4": (rf"\omega_4 = \frac{{L_2\,\omega_2\cos(\varphi_2-\varphi_4)}}{{S}} = "
               rf"\frac{{{f(d.crank, 4)} \times ({sig(w2, group=False)}) \cos({f(phi2 * DEG % 360, 2)}° - "
               rf"{f(phi4 * DEG, 2)}°)}}{{{f(S, 4)}}} = {sig(w4_formula, group=False)}\ \text{{rad/s}}"),
        "vr": (rf"v_{{A_4A_3}} = -L_2\,\omega_2\sin(\varphi_2-\varphi_4) = {sig(vr_formula, group=False)}\ "
               rf"\text{{m/s}}, \quad a^k_{{A_4A_3}} = 2\,\omega_4\, v_{{A_4A_3}} = "
               rf"{sig(2 * w4_formula * vr_formula, group=False)}\ \text{{m/s}}^2"),
        "vf": (rf"v_F = {sig(k.ram_v[j], group=False)}\ \text{{m/s}}, \quad a_F = {sig(k.ram_a[j], group=False)}\ "
               rf"\text{{m/s}}^2"),
    }
    i_ratio = fl.speed_ratio
    j_mass = rim_inertia_factor(fl.inertia, fl.rim)
    fly_eq = {
        "mr": (rf"M_r = \frac{{M_b}}{{i}}, \quad i = \frac{{z_2}}{{z_1}} = \frac{{{p.z2}}}{{{p.z1}}}"
               rf" = {sig(i_ratio, group=False)}") if fl.shaft == "pinion" else r"M_r = M_b",
        "md": (rf"M_d = \frac{{1}}{{2\pi}}\int_0^{{2\pi}} M_r\,d\varphi = {sig(fl.shaft_torque, group=False)}"
               rf"\ \text{{N·m}}"),
        "jf": flywheel_equation(fl.max_energy_swing, fl.shaft_speed_rpm, p.fluctuation,
                                sig(fl.inertia, group=False)),
        "jf_note": carried_note(_, flywheel_carried(
            fl.max_energy_swing, fl.shaft_speed_rpm, p.fluctuation, sig(fl.inertia, group=False),
            f(fl.shaft_speed_rpm, 2), sig(fl.max_energy_swing))),
        "mass": (rf"m = \frac{{4 J_F}}{{D^2}} = \frac{{4 \times {j_mass}}}"
                 rf"{{{f(fl.rim.diameter, 3)}^2}} = {f(fl.rim.rim_mass, 2)}\ \text{{kg}}"),
        "mass_note": carried_note(_, [("J_F", sig(fl.inertia), j_mass)]),
        "width": rim_width_equation(p.gravity, sig(fl.inertia, group=False), fl.rim.diameter,
                                    p.rim_height_to_width, p.specific_weight, fl.rim.width),
    }
    sense = N_("clockwise") if p.crank_omega < 0 else N_("counter-clockwise")
    sense_zh, sense_en = zh_words(sense), sense
    shaft = N_("the pinion shaft $O_1$ ($z_1$)") if fl.shaft == "pinion" else N_("the crank shaft $O_2$")
    return {
        **gb_report.optional_sections(r, lang, figures, brief),
        **gb_report.task_words(p, syn),
        "meta": md_meta(brief.report, lang),
        "fig": figures,
        "data_rows": in_lang(data_rows, lang),
        "guide_bar": {**guide_bar, "rows": in_lang(guide_bar["rows"], lang)},
        "kin_rows": kin_rows,
        "load_rows": load_rows,
        "reaction_rows": reaction_rows,
        "reaction_names": [f"$F_{{{name}}}$" for name, _key in _REACTIONS],
        "worked": worked,
        "fly_eq": fly_eq,
        "sense_zh": sense_zh, "sense_en": sense_en,
        "n2": f(p.crank_speed_rpm, 0), "omega2": sig(abs(p.crank_omega)),
        "theta": f(theta, 2), "K": time_ratio(K) if syn.given_dimensions else f(K, 2),
        "H": f(H, 2 if syn.given_dimensions else 0),
        "working_span": f(k.working_span * DEG, 2),
        "return_span": f(360 - k.working_span * DEG, 2),
        "idle_mm": f(p.idle_travel_ratio * H, 1), "idle_ratio": f(p.idle_travel_ratio, 2),
        "cut_from": f(p.idle_travel_ratio * H, 1), "cut_to": f((1 - p.idle_travel_ratio) * H, 1),
        "grid_points": str(n),
        "max_v": sig(k.linkage.speed_peak),
        "max_a": sig(k.linkage.accel_peak),
        "mb_max": sig(r["linkage_forces"].torque_max, ref=r["linkage_forces"].peak_torque),
        "mb_min": sig(r["linkage_forces"].torque_min, ref=r["linkage_forces"].peak_torque),
        "mb_mean": sig(fl.mean_torque),
        "power": sig(fl.mean_power),
        "fly": {
            # a name ending in a formula ("曲柄轴 $O_2$") is spaced from the 上 after it
            "shaft_zh": zh_words(shaft) + (" " if zh_words(shaft).endswith("$") else ""),
            "shaft_en": shaft,
            "n": f(fl.shaft_speed_rpm, 2), "md": sig(fl.shaft_torque),
            # the flywheel is designed for the nominal speed; the drive's shafts turn at the
            # speeds its motor and chosen ratios give: say which is which where both appear
            "n_note": ("" if r.get("drive") is None else
                       _(", the nominal speed: the crank speed times the gear ratio; the drive "
                         "chapter's shaft speeds are the realised ones, the motor speed divided by the "
                         "chosen ratios, and differ from it by the ratio error")),
            # ΔE over the crank angle φ: M_r = M_b/i acts on the pinion shaft, which turns
            # through φ₁ = iφ, so the same work is ∫(i M_d − M_b)dφ (review36: ∫(M_d − M_r)dφ
            # over φ was ΔW/i)
            "de": (r"$\Delta E(\varphi) = \int (M_d - M_r)\,d\varphi_1 = \int (i M_d - M_b)\,d\varphi$"
                   + _(r" ($\varphi_1 = i\varphi$: the flywheel shaft's angle)")
                   if fl.shaft == "pinion" else r"$\Delta E(\varphi) = \int (M_d - M_r)\,d\varphi$"),
            "dw": sig(fl.max_energy_swing), "jf": sig(fl.inertia),
            "at_min": f(fl.phase_at_min * DEG, 1), "at_max": f(fl.phase_at_max * DEG, 1),
            "D": f(fl.rim.diameter * mm, 0), "b": f(fl.rim.width * mm, 1),
            # the rim's H/b and γ from the brief, said where the formula uses them (page
            # review 47: "H/b = 1.5" was typed in the text and γ = 70000 never introduced)
            "hb": f(p.rim_height_to_width, 2), "gamma": f(p.specific_weight, 0, group=True),
            "Hr": f(fl.rim.height * mm, 1), "m": f(fl.rim.rim_mass, 2),
            "speed": f(fl.rim.rim_speed, 2), "delta": fluctuation(p.fluctuation),
        },
        "verify_rows": _verify_rows(v, syn, lang),
    }
