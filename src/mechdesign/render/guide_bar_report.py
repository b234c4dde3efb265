"""The guide-bar (quick-return) synthesis section shared by the shaper and the slotter:
formulas with the numbers substituted and the link-length table (strings only)."""
from __future__ import annotations

import math

import numpy as np

from ..i18n import N_, Msg, tr
from .fmt import f, factor_for, fluctuation, gives, product, sig, time_ratio
from .labels import InContext, pgettext

DEG = 180.0 / np.pi


def _both(entry, en: str | None = None, **fields) -> str:
    """A cell of the guide-bar tables, which show both languages in either report:
    Chinese / English (``entry``, a msgid or ``pgettext(context, msgid)``, in Chinese from
    the catalogue, then ``en`` or the msgid)."""
    zh = tr("zh")
    if isinstance(entry, InContext):
        text, msgid = zh.pgettext(entry.context, entry.msgid, **fields), entry.msgid
    else:
        text, msgid = zh(entry, **fields), entry
    return f"{text} / {msgid if en is None else en}"


def _ram_zh() -> str:
    """The shaper's ram (刨头) in Chinese, the default name of the ram."""
    _ = tr("zh")
    return _.pgettext("shaper", "ram")


def guide_bar_context(syn, p, rod: str = "BF", ram_zh: str | None = None,
                      extra_rows: list | None = None) -> dict:
    """``syn``: the synthesis stage (design, extreme angle, H, K, whether the lengths were
    given); ``p``: the SI parameters (rod and CoM ratios); ``rod``: the rod's joint letters.
    Synthesis from H, K: the lengths follow; given dimensions: θ = ψ, K and H follow."""
    ram_zh = _ram_zh() if ram_zh is None else ram_zh
    d = syn.design
    mm = 1e3
    K, H = syn.time_ratio, syn.stroke * mm
    theta = syn.extreme_angle * DEG
    half = theta / 2
    sin_half = np.sin(np.radians(half))
    def g(x):   # a given length [m] as the brief wrote it [mm]
        return f"{x * mm:.10g}"

    if syn.given_dimensions:
        eq = {
            "theta": (rf"\theta = \psi = 2\arcsin\frac{{L_{{O_2A}}}}{{L_{{O_2O_3}}}} = "
                      rf"2\arcsin\frac{{{g(d.crank)}}}{{{g(d.frame)}}} = {f(theta, 2)}°"),
            "K": (rf"K = \frac{{180° + \theta}}{{180° - \theta}} = \frac{{180° + {f(theta, 2)}°}}"
                  rf"{{180° - {f(theta, 2)}°}} = {time_ratio(K)}"),
            "H": (rf"H = 2 L_{{O_3B}} \sin(\psi/2) = 2 \times {g(d.guide_bar)} \times "
                  rf"\frac{{{g(d.crank)}}}{{{g(d.frame)}}} = {f(H, 2)}\ \text{{mm}}"),
        }
    else:
        # ψ/2 with the decimals that give the printed L_O3B (320/(2 sin 8.18°) is 1124.6, not
        # 1124.27: 0.01° of ψ/2 moves the bar by 1.4 mm)
        half_txt = factor_for(half, lambda t: gives(float(f(H, 0)) / (2 * np.sin(np.radians(t))),
                                                    f(d.guide_bar * mm, 2)), 2, decimals=True, most=4)
        eq = {
            "theta": (rf"\theta = 180° \times \frac{{K-1}}{{K+1}} = 180° \times "
                      rf"\frac{{{f(K, 2)}-1}}{{{f(K, 2)}+1}} = {f(theta, 2)}°"),
            "bar": (rf"L_{{O_3B}} = \frac{{H}}{{2\sin(\psi/2)}} = \frac{{{f(H, 0)}}}"
                    rf"{{2\sin {half_txt}°}} = {f(d.guide_bar * mm, 2)}\ \text{{mm}}"),
            "crank": (rf"L_{{O_2A}} = L_{{O_2O_3}} \sin(\psi/2) = {f(d.frame * mm, 0)} \times "
                      rf"{sig(sin_half, 4, group=False)} = {f(d.crank * mm, 2)}\ \text{{mm}}"),
        }
    eq["rod"] = (rf"L_{{{rod}}} = {f(p.rod_ratio, 2)}\, L_{{O_3B}} = {f(p.rod_ratio, 2)} \times "
                 rf"{f(d.guide_bar * mm, 2)} = {f(d.rod * mm, 2)}\ \text{{mm}}") if p.rod is None else \
        rf"L_{{{rod}}} = {f(d.rod * mm, 2)}\ \text{{mm}}"
    # (1 + cos)/2 = 1 - (1 - cos)/2: 1 - cos(ψ/2) to 4 significant digits carries the
    # result to 0.01 mm, where cos(ψ/2) itself would need five or six decimals
    bar_mm = f(d.guide_bar * mm, 2)
    eq["guide"] = (rf"L_{{O_3M}} = L_{{O_3B}}\,\frac{{1+\cos(\psi/2)}}{{2}} = L_{{O_3B}} - "
                   rf"\frac{{L_{{O_3B}}\,(1-\cos(\psi/2))}}{{2}} = {bar_mm} - \frac{{{bar_mm} \times "
                   rf"{sig(1 - np.cos(np.radians(half)), 4, group=False)}}}{{2}}"
                   rf" = {f(d.guide_height * mm, 2)}\ \text{{mm}}") if not syn.guide_given else None
    eq["com"] = rf"L_{{O_3S_4}} = {f(p.com_ratio, 2)}\, L_{{O_3B}} = {f(d.bar_com * mm, 2)}\ \text{{mm}}"
    # lengths the brief gives are shown as given (all their digits), derived ones to 0.01 mm
    given = syn.given_dimensions

    def length(x, exact):
        return f"{x * mm:.10g}" if exact else f(x * mm, 2)

    rows = [
        # the text's digits (render/fmt.py's rule): angles to 0.01°, K to 0.001
        ["$\\theta = \\psi$", _both(N_("extreme angle = swing")), f(theta, 2), "°"],
        *([["$K$", _both(N_("time ratio")), time_ratio(K), "—"],
           ["$H$", _both(N_("stroke")), f(H, 2), "mm"]] if given else []),
        ["$L_{O_2A}$", _both(N_("crank")), length(d.crank, given), "mm"],
        ["$L_{O_3B}$", _both(N_("guide bar")), length(d.guide_bar, given), "mm"],
        [f"$L_{{{rod}}}$", _both(N_("rod")), length(d.rod, p.rod is not None), "mm"],
        ["$L_{O_3M}$", _both(N_("guide line from $O_3$")), length(d.guide_height, syn.guide_given), "mm"],
        *(extra_rows or []),
        ["$L_{O_3S_4}$", _both(N_("bar CoM")), f(d.bar_com * mm, 2), "mm"],
    ]
    return {"eq": eq, "rows": rows, "ram_zh": ram_zh, "theta": f(theta, 2), "given": given,
            "guide_given": syn.guide_given}


def task_words(p, syn) -> dict:
    """The task paragraph's words that depend on what the brief gives: the gear pair
    driving the crank, the ram guide by the rule or given."""
    gear = p.z1 is not None
    driven = N_(", driven by gear $z_2$,")
    guide = (N_("the ram guide's distance $L_{O_3M}$ is given.") if syn.guide_given else
             N_("the ram guide passes through the mid-point of the sagitta of the arc "
                "described by the bar's end $B$."))
    # all the link lengths given: nothing is synthesised (shaper_lengths; page review 41)
    task = (N_("kinematics and kinetostatics") if syn.given_dimensions
            else N_("synthesis and analysis"))
    zh = tr("zh")
    return {
        "task_zh": zh(task),
        "task_en": task,
        "driven_zh": zh(driven) if gear else "",
        "driven_en": driven if gear else "",
        "guide_zh": zh(guide),
        "guide_en": guide,
    }


def data_rows(b, p, ram_zh: str, rod: str, rod_ratio: float, ram_com: list,
              cut_zh: str, cut_line: list) -> list[list[str]]:
    """The design-data table of a guide-bar machine's brief ``b`` (course units); the
    machine names its ram, its rod, the ram's centre of mass and the cutting-force line.
    Only what the brief gives: H and K or the link lengths, masses or weights, the rod as
    a ratio or a length, the gear teeth when there is a gear pair."""
    lk, ms, ld = b.linkage, b.masses, b.loads
    if lk.crank_O2A_mm is not None:
        form = [["$L_{O_2A}$", _both(pgettext("length", "crank")), f"{lk.crank_O2A_mm:g}", "mm"],
                ["$L_{O_3B}$", _both(pgettext("length", "guide bar")), f"{lk.guide_bar_O3B_mm:g}", "mm"]]
    else:
        form = [["$H$", _both(N_("{ram} stroke"), "ram stroke", ram=ram_zh), f(lk.stroke_H_mm, 0), "mm"],
                ["$K$", _both(N_("time ratio")), f(p.time_ratio_K, 2), "—"]]
    rod_mm = getattr(lk, f"rod_{rod}_mm")
    rod_row = ([f"$L_{{{rod}}}$", _both(pgettext("length", "rod")), f"{rod_mm:g}", "mm"] if rod_mm is not None else
               [f"$L_{{{rod}}}/L_{{O_3B}}$", _both(N_("rod ratio")), f(rod_ratio, 2), "—"])

    def load(mass, weight, sym, zh, en, digits=1):
        m, w = getattr(ms, mass), getattr(ms, weight)
        if w is not None and (m is None or weight in ms.model_fields_set):
            return [f"$G_{{{sym}}}$", _both(N_("{name} weight"), f"{en} weight", name=zh), f(w, 0), "N"]
        return [f"$m_{{{sym}}}$", _both(N_("{name} mass"), f"{en} mass", name=zh), f(m, digits), "kg"]

    return [
        *form,
        ["$L_{O_2O_3}$", _both(pgettext("length", "frame")), f(lk.frame_O2O3_mm, 0), "mm"],
        rod_row,
        *([["$L_{O_3M}$", _both(N_("guide line from $O_3$")), f"{lk.guide_O3M_mm:g}", "mm"]]
          if lk.guide_O3M_mm is not None else []),
        ["$L_{O_3S_4}/L_{O_3B}$", _both(N_("bar CoM ratio")), f(lk.com_ratio_O3S4_O3B, 2), "—"],
        *(ram_com if ram_com and isinstance(ram_com[0], list) else [ram_com]),
        ["$n_2$", _both(N_("crank speed")), f(lk.crank_speed_n2_rpm, 0), Msg(N_("rpm"))],   # r/min in zh (fmt.in_lang)
        load("guide_bar_m4_kg", "guide_bar_G4_N", "4", tr("zh")(N_("guide bar")), "guide-bar"),
        ["$J_{S_4}$", _both(N_("guide-bar inertia")), f(ms.guide_bar_J_S4_kgm2, 2), "kg·m²"],
        load("ram_m6_kg", "ram_G6_N", "6", ram_zh, "ram"),
        *([["$m_2$", _both(N_("gear 2 mass")), f(ms.gear2_m2_kg, 1), "kg"]] if ms.gear2_m2_kg is not None
          else [["$G_2$", _both(N_("gear 2 weight")), f(ms.gear2_weight_G2_N, 0), "N"]]
          if "gear2_weight_G2_N" in ms.model_fields_set else []),
        ["$F_c$", f"{cut_zh} / cutting force", f(ld.cutting_force_Fc_N, 0), "N"],
        cut_line,
        *([["$z_1, z_2$", _both(N_("gear teeth")), f"{p.z1}, {p.z2}", "—"]] if p.z1 is not None else []),
        ["$[\\delta]$", _both(N_("speed fluctuation")), fluctuation(p.fluctuation), "—"],
    ]


def cam_phase(ph, lang: str) -> tuple[list[str], list[str]]:
    """The feed cam's phase to the crank (stages.guide_bar.CamPhase): the crank angle of
    δ = 0 as a row of the cam's data table, the return-stroke check as a row of its checks."""
    from .fmt import verdict

    _ = tr(lang)
    deg = 180 / math.pi
    # (not φ0: the oscillating follower's cam section names its initial angle so, eq. "φ0 =
    # arccos …": one symbol, two meanings; page review 51)
    data = ["$\\varphi_{\\delta=0}$", _("crank angle at $\\delta$ = 0 (the return stroke begins)"),
            f(ph.crank_angle * deg, 2), "°"]
    check = [_("follower's motion within the return stroke"), f"{f(ph.motion * deg, 2)}°",
             f"≤ {f(ph.return_span * deg, 2)}°", verdict(ph.passed, lang)]
    return data, check


def optional_sections(r: dict, lang: str, figures: dict, brief=None) -> dict:
    """The cam, gear and drive sections' contexts (None where the brief has no such
    section); the drive's load is the crank's mean power P_w = M̄_b ω2."""
    out = {"cam": None, "gear": None, "drive": None}
    if r.get("cam") is not None:
        from .cam_report import cam_context

        out["cam"] = cam_context(r["cam"], lang, figures, "cam_profile.csv",
                                 getattr(brief, "cam", None))
        if r.get("cam_phase") is not None:
            data, check = cam_phase(r["cam_phase"], lang)
            out["cam"]["data_rows"] = [*out["cam"]["data_rows"], data]
            out["cam"]["checks"] = [*out["cam"]["checks"], check]
    if r.get("gear") is not None:
        from .gear_report import gear_context

        out["gear"] = gear_context(r["gear"], lang, figures)
    if r.get("drive") is not None:
        from .drive_report import drive_context

        fl, p = r["linkage_flywheel"], r["params"]
        pw = (rf"P_w = \bar M_b\,\omega_2 = {product((fl.mean_torque, abs(p.crank_omega)), sig(fl.mean_power, group=False))}"
              rf" = {sig(fl.mean_power, group=False)}\ \text{{W}}")
        out["drive"] = drive_context(r["drive"], lang, figures, pw, gear_pair_last="gear" in out)
    return out


def optional_figures(r: dict, fig_dir, lang: str) -> dict[str, str]:
    """The cam's and the gear pair's figures, when the results have them."""
    paths = {}
    if r.get("cam") is not None:
        from .cam_report import make_cam_figures

        paths.update(make_cam_figures(r["cam"], fig_dir, lang))
    if r.get("gear") is not None:
        from .gear_report import make_gear_figures

        paths.update(make_gear_figures(r["gear"], fig_dir, lang))
    return paths


def write_data(r: dict, folder) -> list:
    """Cam profile coordinates as CSV when the brief has a cam."""
    if r.get("cam") is None:
        return []
    from .cam_report import write_cam_csv

    return write_cam_csv(r["cam"], folder)


def make_figures(r: dict, fig_dir, lang: str) -> dict[str, str]:
    """The figures of a machine built on the linkage engine with optional cam/gear/drive
    sections (the slotter, the press): the linkage's figures and the optional ones."""
    from .linkage_report import make_linkage_figures

    paths = make_linkage_figures(r["model"], r["linkage"], r["linkage_forces"],
                                 r["linkage_flywheel"], fig_dir, lang)
    paths.update(optional_figures(r, fig_dir, lang))
    return paths


def animate(r: dict, path, lang: str):
    """The linkage's animation (format gif)."""
    from .animation import linkage_gif

    return linkage_gif(r["model"], r["linkage"], path, lang)

