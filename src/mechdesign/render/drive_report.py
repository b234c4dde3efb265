"""Drive section of a report (传动装置设计): power, efficiency chain, motor choice, ratio
allocation, the shaft table, each stage's geometry and strength checks."""
from __future__ import annotations

import math


import numpy as np

from ..stages.drive import shaft_numeral
from ..i18n import N_, data_text, tr
from ..stages.findings import Named, decode
from .fmt import exact, f, factor_for, grouped, md_text, percent, rpm, sci_tex, sentences, sig

MM = 1e3



# A shaft design step as results.json stores it (stages/drive_strength.py: its msgid, the
# same since session 30) → the words the report prints, its quantity letters as math
# ("$h$ ≈ 0.07 $d$", "$L$ ≤ hub − 8 mm", "$d$ = 24"; issue 19: GB 3102 sets a quantity
# symbol in italic in the text too). results.json keeps its messages unchanged.
_STEP_SHOWN = {
    "design torque T = 9549 P/n = {T} N·m (bearing life: the same load × $f_p$ = {fp})":
        N_("design torque $T$ = 9549 $P/n$ = {T} N·m (bearing life: the same load × $f_p$ = {fp})"),
    "collar {d} (h ≈ 0.07 d)": N_("collar {d} ($h$ ≈ 0.07 $d$)"),
    "{name_en}: d = {d}, key {b}×{h}, hub {hub}, L = {L}":
        N_("{name_en}: $d$ = {d}, key {b}×{h}, hub {hub}, $L$ = {L}"),
    "{name_en}: d = {d}, key {b}×{h}, hub {hub}, L = {L}, two keys at 180°":
        N_("{name_en}: $d$ = {d}, key {b}×{h}, hub {hub}, $L$ = {L}, two keys at 180°"),
    "keys (GB/T 1096, form A, L ≤ hub − 8 mm; a longer hub up to 1.5 d, then two keys when one "
    "fails): {keys}":
        # the hub rule in full: a worm wheel's hub of 60 mm on a 30 mm seat (its face width)
        # read as beyond "a longer hub up to 1.5 d" (page review 41)
        N_("keys (GB/T 1096, form A; hub: the part's width, at least 1.2 $d$, 1.5 $d$ for a pulley, "
           "coupling, sprocket or crank; $L$ ≤ hub − 8 mm; where a key is crushed, a hub up to "
           "1.5 $d$, then two keys): {keys}"),
}


def _shown(value):
    """An encoded step message (``{msgid, args}``, nested) with the report's wording of the
    messages :data:`_STEP_SHOWN` names."""
    if isinstance(value, list):
        return [_shown(v) for v in value]
    if not isinstance(value, dict):
        return value
    out = {k: _shown(v) for k, v in value.items()}
    if isinstance(out.get("msgid"), str):
        out["msgid"] = _STEP_SHOWN.get(out["msgid"], out["msgid"])
    return out

def _num_giving(x: float, fn, printed: str, write) -> str:
    """``x`` as ``write`` (a formula's number writer) prints it, with the digits that make
    ``fn(printed x)`` give ``printed`` (:func:`.fmt.factor_for`; 1.2 × 0.1812 = 0.2174,
    printed 0.2175 — P = 0.18124)."""
    from ..numbers import gives

    return factor_for(x, lambda v: gives(fn(v), printed), write=write)


def _fp_texts(z: int, F0: float, alpha1_deg: float, Fp: float) -> tuple[str, str, str]:
    """F₀ as the table and the F₀ formula print it, F₀ as the factor of "F_p = 2 z F₀
    sin(α₁/2)", and F_p as the table and that formula print it.

    One value prints one way (review 38: F₀ was 151.0 in the table, 151 in its formula and
    150.964 in F_p's): F₀ and F_p to 0.1 N, or to 1 N where F₀ to 0.1 N does not give F_p
    to 0.1 N (2 × 3 × 151.0 × sin 81.05° = 895.0 where F_p = 894.8; to 1 N: 151 and 895);
    α₁ as the α₁ formula prints it. Where neither does, F₀'s factor has the fewest more
    digits that give F_p (:func:`strength_tex._giving`)."""
    from ..numbers import gives
    from .strength_tex import _giving, num

    alpha_txt = num(alpha1_deg)

    def fp_of(f0: float, a: float = float(alpha_txt)) -> float:
        return 2 * z * f0 * math.sin(math.radians(a) / 2)

    for dp in (1, 0):
        f0_txt, fp_txt = f(F0, dp), f(Fp, dp)
        if gives(fp_of(float(f0_txt)), fp_txt):
            return f0_txt, f0_txt, fp_txt
    _alpha, f0_factor = _giving((alpha1_deg, F0), lambda a, f0: fp_of(f0, a), num(Fp), most=4)
    return f(F0, 1), f0_factor, num(Fp)


def _pw_for(d) -> str:
    """"{P_w}{η}" (P_w in kW) with the digits that give the printed P_d = P_w/η (0.04400/0.6988
    gives 0.06297, printed 0.06296: η = 0.69883; a factor carries the digits the result was
    computed from)."""
    from ..numbers import factors_for, significant

    pw, eta = factors_for((d.machine_power / 1e3, d.efficiency), lambda p, e: p / e,
                          sig(d.power_required / 1e3, group=False), (4, significant(f(d.efficiency, 4))))
    return f"{pw}}}{{{eta}"


def _stage_label(st, _) -> str:
    name = st.name(_)
    if st.z1 is not None:
        return f"{name} (z₁ = {st.z1}, z₂ = {st.z2})"
    if st.d1 is not None:
        return f"{name} (d₁ = {f(st.d1 * MM, 0)}, d₂ = {f(st.d2 * MM, 0)} mm)"
    return name


def _stage_name(kind: str, lang) -> str:
    """A drive stage's name (of its kind: a row of data/transmissions.yaml) in ``lang``."""
    return Named("transmissions", kind).text(lang)


def _part(part: str, kind: str, d, lang) -> str:
    """A part on a shaft ("the pinion of stage 3", the flywheel) in ``lang``: by its stage
    and its role where the shaft design records them, else by its stage's kind."""
    from ..stages.drive_strength import part_message

    msg = part_message(part, [s.design for s in d.stages])
    return msg.text(lang) if msg is not None else _stage_name(kind, lang)


def _shaft_name(i: int, last: int, zh: bool) -> str:
    _ = tr("zh" if zh else "en")
    if i == 0:
        return _("motor shaft 0")
    tail = _(" (machine input)") if i == last else ""
    return _("shaft {i}", i=shaft_numeral(i)) + tail


#: why the motor was chosen (DriveResults.choice.reason; core.drive.choose_motor)
_REASONS = {
    "recommended": N_("the motor of least rated power among the smallest motors with $P_{ed} \\ge "
                      "P_d$ at 1500, 1000, 3000 and 750 rpm whose total ratio the stages can "
                      "give; its ratio lies within their recommended ranges"),
    "maximum": N_("the motor of least rated power among the smallest motors with $P_{ed} \\ge P_d$ "
                  "at 1500, 1000, 3000 and 750 rpm whose total ratio the stages can give; its "
                  "ratio lies beyond their recommended ranges, within their maximum ranges"),
    "given": N_("the synchronous speed the brief gives"),
}


#: A motor whose rated power exceeds P_d by more than this factor is explained: which
#: smaller motors the choice passed over and why.
OVERSIZE = 2.0


def _ranges(d):
    """The free stages, the product of the fixed ratios and the free stages' recommended
    (lo, hi) and largest ratio (data/transmissions.yaml); None without a free stage."""
    from ..data import load_yaml

    table = load_yaml("transmissions.yaml")
    free = [st for st in d.stages if not st.fixed and st.type != "coupling"]
    if not free:
        return None
    fixed = float(np.prod([st.ratio for st in d.stages if st.fixed])) if d.stages else 1.0
    rec = (float(np.prod([table[st.kind]["ratio_recommended"][0] for st in free])),
           float(np.prod([table[st.kind]["ratio_recommended"][1] for st in free])))
    top = float(np.prod([table[st.kind]["ratio_max"] for st in free]))
    return free, fixed, rec, top


def _motor_note(d, _) -> str | None:
    """Why this motor, where a reader would ask. A ratio beyond the recommended ranges
    ("maximum"): what the free stages must make against their ranges, and the motor the
    recommended ranges would have taken, with its power against P_d. A motor much larger
    than P_d: the smaller motors of the other synchronous speeds, each with the ratio the
    free stages would need against their ranges. None otherwise."""
    m = d.motor
    ranges = _ranges(d) if d.power_required > 0 else None
    if ranges is None:
        return None
    free, fixed, rec, top = ranges
    names = _("; ").join(_stage_name(st.kind, _) for st in free)
    if d.choice.reason == "maximum":
        need = d.choice.total_ratio / fixed
        text = _("The stages with a given ratio give {fixed}, so the other stages ({names}) must "
                 "make $i/{fixed}$ = {need}, beyond the recommended {lo}–{hi}, within the maximum "
                 "{top}.", fixed=f(fixed, 2), names=names, need=f(need, 2), lo=f(rec[0], 0),
                 hi=f(rec[1], 0), top=f(top, 0))
        alt = min((c for c in d.choice.candidates if c.motor and c.recommended),
                  key=lambda c: c.motor.power, default=None)
        if alt is not None:
            text = sentences(_, text, _(
                "The recommended ranges would take {motor} ({P} kW, synchronous {sync} rpm), "
                "{times} times $P_d$.", motor=alt.motor.designation, P=f(alt.motor.power / 1e3, 2),
                sync=f(alt.synchronous_rpm, 0), times=f(alt.motor.power / d.power_required, 1)))
        return text
    if m.power < OVERSIZE * d.power_required:
        return None
    tried = []
    for c in d.choice.candidates:
        if c.motor is None or c.motor.designation == m.designation or c.motor.power >= m.power:
            continue
        need = c.total_ratio / fixed
        # a smaller motor the stages could drive would have been chosen (core.drive.
        # choose_motor): a smaller one passed over lies outside the maximum ranges
        why = (_("above the maximum {top}", top=f(top, 0)) if need > top else
               _("below the recommended range"))
        tried.append(dict(c=c, need=need, why=why))
    if not tried:
        return None
    items = _("; ").join(_("{motor} ({P} kW, {n} rpm): i = {i}, {names} {need}, {why}",
                           motor=t["c"].motor.designation, P=f(t["c"].motor.power / 1e3, 2),
                           n=f(t["c"].motor.full_load_rpm, 0), i=f(t["c"].total_ratio, 2),
                           names=names, need=f(t["need"], 2), why=t["why"]) for t in tried)
    return _("Its rated power is {times} times $P_d$: not the power but the ratio ruled out the "
             "smaller motors. The stages with a given ratio give {fixed}, so the other stages "
             "({names}) must make $i/{fixed}$, recommended {lo}–{hi}: {items}.",
             times=f(m.power / d.power_required, 1), fixed=f(fixed, 2), names=names,
             lo=f(rec[0], 0), hi=f(rec[1], 0), items=items)


def _printed_deviation(n: float, n_req: float) -> float:
    """(n - n_req)/n_req in per cent from the speeds as the equation prints them (to
    0.01 rpm): the printed chain gives its printed result (80.29 and 80.00 rpm give 0.36 %,
    where the unrounded speeds would give 0.37 %)."""
    a, b = float(rpm(n)), float(rpm(n_req))
    return 100 * (a - b) / b


def _eta_factors(etas, eta_b: float, eta_w: float, n_b: int, printed: str):
    """The efficiency chain's factors, 3 decimals or more where the product needs them to give
    its printed result (a worm's 0.7977 printed 0.798 gave 0.6991 for 0.6988); the trailing
    zeros beyond 3 decimals dropped."""
    def text(x, extra):
        t = f(x, 3 + extra)
        return t[:5] + t[5:].rstrip("0") if "." in t else t
    for extra in range(4):
        ts = [text(e, extra) for e in etas]
        tb, tw = text(eta_b, extra), text(eta_w, extra)
        value = math.prod(float(t) for t in ts) * float(tb) ** n_b * float(tw)
        if abs(value - float(printed)) <= 0.5e-4 * (1 + 1e-9):
            break
    return " \\times ".join(ts), tb, tw


def drive_context(d, lang: str, figures: dict[str, str], machine_power_eq: str | None = None,
                  gear_pair_last: bool = False) -> dict:
    """The drive chapter's context. ``gear_pair_last``: the last stage is the mechanism's
    gear pair, designed in its own chapter (the guide-bar machines), which gives its module."""
    _ = tr(lang)
    m = d.motor
    etas = [st.efficiency for st in d.stages]
    n_b = len(d.stages)
    eta_terms, eta_b, eta_w = _eta_factors(etas, d.bearing_eff, d.machine_eff, n_b,
                                           f(d.efficiency, 4))
    eq = {
        "eta": (rf"\eta = \prod \eta_i \cdot \eta_b^{{{n_b}}} \cdot \eta_w = {eta_terms} \times "
                rf"{eta_b}^{{{n_b}}} \times {eta_w} = {f(d.efficiency, 4)}"),
        "pd": (rf"P_d = \frac{{P_w}}{{\eta}} = \frac{{{_pw_for(d)}}}"
               rf" = {sig(d.power_required / 1e3, group=False)}\ \text{{kW}}"),
        "i": (rf"i = \frac{{n_m}}{{n_w}} = \frac{{{f(m.full_load_rpm, 0)}}}{{{rpm(d.output_speed_required)}}}"
              rf" = {sig(d.choice.total_ratio, group=False)}"),
        "err": (rf"\Delta n = \frac{{n_w' - n_w}}{{n_w}} = \frac{{{rpm(d.output_speed)} - "
                rf"{rpm(d.output_speed_required)}}}{{{rpm(d.output_speed_required)}}} = "
                rf"{percent(_printed_deviation(d.output_speed, d.output_speed_required))}\%"),
        "pw": machine_power_eq,
    }
    yes, no = (_("yes"), _("no"))
    cand_rows = []
    for c in d.choice.candidates:
        if c.motor is None:
            cand_rows.append([f(c.synchronous_rpm, 0), "—", "—", "—", "—", no, no])
            continue
        # both ranges (review45: the slotter's chosen Y90S-6 and the lighter Y801-4 both read
        # "no" with no word why the Y801-4, i = 23.17, was passed over: beyond the maximum)
        cand_rows.append([f(c.synchronous_rpm, 0), c.motor.designation, f(c.motor.power / 1e3, 2),
                          f(c.motor.full_load_rpm, 0), f(c.total_ratio, 2),
                          yes if c.recommended else no, yes if c.possible else no])
    stage_rows = []
    for st in d.stages:
        stage_rows.append([str(st.index + 1), _stage_label(st, _), f(st.ratio_allocated, 3),
                           f(st.ratio, 3), f(st.efficiency, 3)])
    shaft_rows = [[_shaft_name(s.index, len(d.shafts) - 1, _.zh), f(s.speed_rpm, 2),
                   sig(s.power / 1e3, 4), sig(s.torque, 4)] for s in d.shafts]   # powers, torques: 4 significant digits
    reason = _(_REASONS[d.choice.reason])
    # the allocation's rules that apply to this drive's free stages (core.drive.allocate_ratios)
    free = [st for st in d.stages if not st.fixed and st.type != "coupling"]
    notes = []
    if any(st.type == "belt" for st in free) and any(st.type in ("spur", "helical", "worm") for st in free):
        notes.append(_("a belt below the gear stage it drives"))
    if any(b.index == a.index + 1 and a.type in ("spur", "helical") and b.type in ("spur", "helical")
           for a, b in zip(free, free[1:])):
        notes.append(_("a two-stage expanded reducer splits by $i_1 = \\sqrt{1.4 i}$"))
    alloc_notes = _(" ({notes})", notes=_("; ").join(notes)) if notes else ""
    # standard pulleys only where there is a belt (the furnace drives have none: page review 48)
    rounding = (_("whole teeth or standard pulleys") if any(st.type == "belt" for st in d.stages)
                else _("whole teeth"))
    worm = _("; the worm's from its lead angle and friction angle") \
        if any(st.type == "worm" for st in d.stages) else ""
    return {
        "alloc_notes": alloc_notes, "rounding": rounding, "worm_eff": worm,
        "eq": eq, "cand_rows": cand_rows, "stage_rows": stage_rows, "shaft_rows": shaft_rows,
        "reason": reason, "oversize": _motor_note(d, _),
        "motor": {"name": m.designation, "P": f(m.power / 1e3, 2), "sync": f(m.synchronous_rpm, 0),
                  "n": f(m.full_load_rpm, 0), "H": f(m.frame_height * MM, 0),
                  "tst": f(m.starting_torque_ratio, 1), "tmax": f(m.max_torque_ratio, 1)},
        "pw": sig(d.machine_power / 1e3), "pd": sig(d.power_required / 1e3),
        "eta": f(d.efficiency, 4), "i": sig(d.choice.total_ratio),
        "nw": rpm(d.output_speed_required), "nw_real": rpm(d.output_speed),
        "err": f(d.speed_error * 100, 2), "tol": f(d.speed_tolerance * 100, 1),
        "speed_ok": abs(d.speed_error) <= d.speed_tolerance,
        "hours": f(d.service_hours, 0), "KA": f(d.KA, 2),
        # a gear (or worm) stage upstream of the flywheel keeps K_A (a belt there has its own)
        "gears_before": d.peak_from_shaft is not None and any(
            st.index < d.peak_from_shaft and st.type in ("spur", "helical", "worm") for st in d.stages),
        "peak": sig(d.peak_factor) if d.peak_from_shaft is not None else None,
        "peak_shaft": _shaft_name(d.peak_from_shaft, len(d.shafts) - 1, _.zh) if d.peak_from_shaft is not None else "",
        "warnings": [md_text(w.text(lang)) for w in d.warnings],
        "stage_designs": stage_designs(d, lang, gear_pair_last),
        "assumptions": data_assumption_rows(getattr(d, "data_assumptions", ()), lang),
        "fig": figures,
    }


# The catalogue entries a design used without a confirmed source (DriveResult.data_assumptions):
# code (before ':') → what is assumed; {x} the key after ':' (a material, bearing or motor).
_ASSUMED = {
    "motor": N_("motor {x}: the rated data of the handbook's Y-series table"),
    "ratio_ranges": N_("the recommended and largest ratio of each kind of stage (the ratio allocation)"),
    "belt_chart": N_("the V-belt section from the selection chart (fig. 8-11, its boundaries read as "
                     "straight lines)"),
    "chain_rating": N_("the roller chain's rated power (the ANSI formulas stand in for the chart, "
                       "fig. 9-11)"),
    "chain_table": N_("the chain's mass per metre and tensile load (table 9-1, static safety)"),
    "gear_material": N_("the limits $\\sigma_{{Hlim}}$ and $\\sigma_{{FE}}$ of {x} (read off the textbook's charts, ±5 %)"),
    "worm_wheel": N_("the allowable stresses of the worm wheel's {x}"),
    "worm_Zrho": N_("the worm's contact coefficient $Z_\\rho$ (a quadratic fit of fig. 11-18)"),
    "shaft_A0": N_("$A_0$ and $[\\tau_T]$ of the shaft materials (table 15-3)"),
    "shaft_series": N_("the standard diameters the shaft sections are rounded up to (GB/T 2822)"),
    "shaft_material": N_("the allowable bending stress $[\\sigma_{{-1b}}]$ of {x}"),
    "bearing": N_("bearing {x}: $C_r$ and $C_{{0r}}$ of the handbook table"),
    "key_lengths": N_("the length range of each flat key (GB/T 1096)"),
    "key_cast_iron": N_("the allowable crushing stress of keys in cast-iron hubs (table 6-2)"),
    "motor_shaft": N_("motor {x}: the shaft extension D × E of its frame"),
    "coupling_table": N_("the LT couplings' nominal torques, speeds and bores (GB/T 4323)"),
    "coupling_KA": N_("the coupling's working factor $K_A$ (table 14-1)"),
}


def data_assumption_rows(codes, lang: str) -> list[str]:
    """One line per unconfirmed catalogue entry the design used, in the report's language."""
    from ..data import catalogues as cat

    _ = tr(lang)
    out = []
    for code in codes:
        kind, _sep, key = code.partition(":")
        x = key
        if kind in ("gear_material", "worm_wheel"):
            x = _mat_name(key, _)
        elif kind == "shaft_material":
            m = cat.shaft_material(key)
            x = data_text(m.name_zh) if _.zh else m.name_en
        out.append(_(_ASSUMED[kind], x=md_text(x)) if kind in _ASSUMED else md_text(code))
    return out


def _mat_name(key: str, _) -> str:
    from ..data import catalogues as cat

    for get in (cat.gear_material, cat.worm_wheel_material):
        try:
            m = get(key)
            return data_text(m.name_zh) if _.zh else m.name_en
        except KeyError:
            continue
    return key


def _rows(rows: list[list[str]], _) -> list[list[str]]:
    """Keep the check name in the report's language only; value and allowable grouped by
    render/fmt.py's rule (a life of 72 441 h)."""
    return [[r[0] if _.zh else r[1], grouped(r[2]), grouped(r[3]), *r[4:]] for r in rows]


def stage_designs(d, lang: str, gear_pair_last: bool = False) -> list[dict]:
    """Per stage and per shaft: title, text, dimension rows, formulas and check rows.
    ``gear_pair_last``: see :func:`drive_context`."""
    from .strength_tex import check_formulas, check_rows

    _ = tr(lang)
    out = []
    for r in d.stages:
        g = r.design
        if g is None or g.kind not in ("gear", "worm", "belt", "chain"):
            continue
        title = _("Stage {index}: {name_en}", index=r.index + 1, name_en=r.name("en"),
                   name_zh=r.name("zh"))
        text, rows = [], []
        if g.kind == "belt":
            out.append(_belt_design(r, g, title, _))
            continue
        if g.kind == "chain":
            out.append(_chain_design(g, title, _))
            continue
        m_text = (f"{f(g.module * MM, 2)} mm" + ("" if g.module_given else
                  (_(" (the design formula gives {module_min} mm; next standard value)",
                     module_min=f(g.module_min * MM, 2)))))
        a = g.allowables
        if g.kind == "gear":
            e = g.extra
            mats = " / ".join(_mat_name(k, _) for k in g.materials)
            text.append(_("Materials (pinion / gear): {mats}. Load factor $K = K_A K_V K_\\alpha K_\\beta "
                          "= {K}$, design torque $T_1 = {T1}$ N·m, face width factor $\\phi_d = {phi_d}$, "
                          "module $m$ = {m_text}.", mats=mats, K=f(g.K, 3), T1=sig(g.T1, group=False),
                          phi_d=f(e['phi_d'], 2), m_text=m_text))
            if e["open"] and not g.module_given:
                text.append(_("Open gears fail by wear: designed by root bending with the module raised 15 % "
                              "for wear; no contact check."))
            elif e["open"]:
                # the module is the task's: the stage is checked, not designed (review36: a
                # module of 12 mm "designed by bending" at 2 % of the allowable stress)
                given = (_("The module is that of the mechanism's gear pair (chapter \"Gear pair and "
                           "meshing drawing\"), given by the task")
                         if gear_pair_last and r is d.stages[-1] else _("The module is given by the task"))
                text.append(_("{given}: this stage is not designed but checked. Open gears fail by wear; "
                              "root bending is checked below, with no contact check.", given=given))
            text.append(_("Stress cycles $N_1 = {N1}$, life factors $K_{{HN}} = "
                          "{KHN1}/{KHN2}$, $K_{{FN}} = {KFN1}/{KFN2}$; allowable $[\\sigma_H] = "
                          "{sigma_H}$ MPa, $[\\sigma_F] = {sigma_F1}/{sigma_F2}$ MPa ($S_H = 1$, $S_F = "
                          "1.4$).", N1=sci_tex(a['N1']), KHN1=f(a['KHN1'], 3),
                          KHN2=f(a['KHN2'], 3), KFN1=f(a['KFN1'], 3), KFN2=f(a['KFN2'], 3),
                          sigma_H=f(a['sigma_H'] / 1e6, 1), sigma_F1=f(a['sigma_F1'] / 1e6, 1),
                          sigma_F2=f(a['sigma_F2'] / 1e6, 1)))
            geo = g.geometry
            d1 = g.forces["d1"]
            # a helical pair: its normal module and helix angle (review38: β was in no table)
            helical = r.type == "helical"
            if helical and e.get("a0") is not None:
                text.extend(_helix_correction(r, g, _))
            rows = [["$z_1 / z_2$", f"{r.z1} / {r.z2}", "—"],
                    ["$m_n$" if helical else "$m$", f(g.module * MM, 2), "mm"],
                    *([["$\\beta$", f(math.degrees(geo.beta), 2), "°"]] if helical else []),
                    ["$d_1 / d_2$", f"{f(d1 * MM, 2)} / {f(g.forces['d2'] * MM, 2)}", "mm"],
                    ["$a$", f((geo.a_work if hasattr(geo, 'a_work') else geo.a) * MM, 2), "mm"],
                    ["$b$", f(g.face_width * MM, 0), "mm"], ["$v$", f(e["v"], 3), "m/s"],
                    ["$\\varepsilon_\\alpha$", f(e["eps_alpha"], 3), "—"],
                    ["$Y_{Fa}, Y_{Sa}$", f"{f(e['YFa1'], 3)}, {f(e['YSa1'], 3)} / {f(e['YFa2'], 3)}, {f(e['YSa2'], 3)}", "—"],
                    ["$F_t / F_r / F_a$", f"{f(g.forces['Ft'], 1, group=True)} / {f(g.forces['Fr'], 1, group=True)} / {f(g.forces['Fa'], 1, group=True)}", "N"]]
        else:
            e = g.extra
            geo = g.geometry
            text.append(_("Worm of surface-hardened 45 steel (>45 HRC), wheel {materials}. $K = K_A "
                          "\\times 1.1 = {K}$, wheel torque $T_2 = {T2}$ N·m, module $m$ = {m_text}, $q$ = "
                          "{q}. Allowable $[\\sigma_H] = {sigma_H}$ MPa, $[\\sigma_F] = {sigma_F}$ MPa ($N "
                          "= {N}$).", materials=_mat_name(g.materials[1], _),
                          K=f(g.K, 3), T2=sig(g.T2, group=False), m_text=m_text, q=f(geo.q, 0),
                          sigma_H=f(a['sigma_H'] / 1e6, 1), sigma_F=f(a['sigma_F'] / 1e6, 1),
                          N=sci_tex(a['N'])))
            # the efficiency relation displayed: inline, its unbreakable run spread the line
            # before it to 15 pt word spaces (tests/test_typeset.py wide_word_gaps)
            text.append(_("Sliding speed $v_s = {vs}$ m/s, equivalent friction angle $\\varphi_v = "
                          "{phi_v}°$; worm-drive efficiency:", vs=f(e['vs'], 3),
                          phi_v=f(np.degrees(e['phi_v']), 2)))
            text.append(rf"$$ \eta = 0.95\,\frac{{\tan\gamma}}{{\tan(\gamma+\varphi_v)}} = {f(e['eta'], 4)} $$")
            for c in g.checks:
                if c.key == "worm_deflection":    # issue 20: 濮良贵 ch.11 stiffness check
                    i = c.inputs
                    span = (_("bearing span L = {L} mm (given in the brief)", L=f(i['L'] * MM, 1)) if i["span_given"] else
                            (_("bearing span estimated as $L$ ≈ 0.9 $d_2$ = {L} mm",
                               L=f(i['L'] * MM, 1))))
                    text.append(_("Worm shaft stiffness: the worm as a simply supported beam loaded by "
                                  "$F_{{t1}}$ and $F_{{r1}}$ at mid-span, {span}, $I = \\pi d_{{f1}}^4/64$ "
                                  "($d_{{f1}} = d_1 - 2.4m = {df1}$ mm), $E$ = 206 GPa, allowed deflection [$y$] = "
                                  "$d_1$/1000.", span=span, df1=f(i['df1'] * MM, 2)))
            rows = [["$z_1 / z_2$", f"{r.z1} / {r.z2}", "—"], ["$m$", f(g.module * MM, 2), "mm"],
                    ["$q$", f(geo.q, 1), "—"], ["$d_1 / d_2$", f"{f(geo.d1 * MM, 2)} / {f(geo.d2 * MM, 2)}", "mm"],
                    ["$\\gamma$", f(np.degrees(geo.lead_angle), 3), "°"], ["$a$", f(e["a"] * MM, 2), "mm"],
                    ["$Z_\\rho$", f(e["Zrho"], 3), "—"], ["$z_{v2}, Y_{Fa2}$", f"{f(e['zv2'], 2)}, {f(e['YFa2'], 3)}", "—"],
                    ["$A$", f(e["area"], 3), "m²"]]
        out.append({"title": title, "text": text, "rows": rows,
                    "formulas": [eq for c in g.checks for eq in check_formulas(c)], "checks": _rows(check_rows(g.checks, lang), _),
                    # the sources of the method and tables (data/references.yaml)
                    "refs": ("pu8", "gb1357") if g.kind == "gear" else ("pu9",)})
    for sh in d.shaft_designs:
        title = _("Design and checks of {index}",
                   index=_shaft_name(sh.index, len(d.shafts) - 1, _.zh))
        res = sh.result
        parts = sh.element_parts or sh.elements
        where = _.pgettext("list", ", ").join(_part(p, kind, d, _) for p, kind in zip(parts, sh.elements))
        text = [_("On the shaft: {where}. Designed by the procedure of PU Lianggui, Machine "
                  "Design, ch. 15 (each step's rule and numbers below); any failed check "
                  "enlarges that section and everything is checked again.", where=where)]
        for k, step in enumerate(sh.steps, 1):
            said = decode(_shown(step)).text(_)
            text.append(_("Step {k}: {sen}.", k=k, sen=said, szh=said))
        # the reactions displayed: four "R = … N" runs in a justified line spread its few word
        # spaces (tests/test_typeset.py wide_word_gaps)
        # where x is measured from, said once, at the first shaft (stages/drive_strength._place:
        # bearing A at x = 0, B at the span, overhung parts outside them)
        origin = _(" ($x$ is measured along the shaft from bearing $A$, bearing $B$ at $x = L$, the "
                   "span; overhung parts sit outside the bearings, at $x < 0$ or $x > L$)"
                   ) if sh is d.shaft_designs[0] else ""
        text.append(_("Largest equivalent moment $M$ = {M} N·m at $x$ = {x} mm{origin}; bearing reactions "
                      "(strength case):", x=f(res.critical.x * MM, 0), M=sig(res.critical.M),
                      origin=origin))
        text.append("$$ " + r",\quad ".join(
            rf"R_{{{k}}} = {_newtons(v)}\ \mathrm{{N}}"
            for k, v in (("AH", res.RAh), ("AV", res.RAv), ("BH", res.RBh), ("BV", res.RBv))) + " $$")
        if sh.bearing is not None:
            b = sh.bearing
            # the static strength is checked at the peak only after the flywheel (a check of
            # its own); without it the sentence named a check the report did not make
            # (page review 48, furnace_drive)
            static = any(c.key == "bearing_static" for c in sh.checks)
            args = dict(designation=b.designation, d=f(b.d * MM, 0), Cr=f(b.Cr / 1e3, 1),
                        bearing_loads=_newtons(sh.bearing_loads[0]),
                        bearing_loads2=_newtons(sh.bearing_loads[1]),
                        life_torque_factor=f(sh.life_torque_factor, 3))
            text.append(_("Bearings {designation} ($d$ = {d} mm, $C_r$ = {Cr} kN); the life takes the "
                          "fatigue load: equivalent loads $P_A = {bearing_loads}$ N, $P_B = "
                          "{bearing_loads2}$ N ($f_p$ = 1.2, the loads {life_torque_factor} × those of "
                          "the strength case); the static strength the peak.", **args) if static else
                        _("Bearings {designation} ($d$ = {d} mm, $C_r$ = {Cr} kN); the life takes the "
                          "fatigue load: equivalent loads $P_A = {bearing_loads}$ N, $P_B = "
                          "{bearing_loads2}$ N ($f_p$ = 1.2, the loads {life_torque_factor} × those of "
                          "the strength case).", **args))
            if "crank" in sh.elements:
                # review39: the factor scales the gear's loads, not the crank's force
                text.append(_("The crank's frame reaction is not scaled by that factor: the life "
                              "case takes its cube mean over the cycle (the crank step above)."))
            if "flywheel" in sh.elements:
                w = -sum(ld.Fv for ld, nm in zip(sh.loads, sh.elements) if nm == "flywheel")
                text.append(_("The flywheel's rim weight {W} N acts between the bearings in both "
                              "cases, unscaled.", W=f(w, 1)))
        unit_mm = "mm"
        rows = [["$d_{min}$", f(sh.d_min * MM, 2), unit_mm]]
        if sh.d_end is not None:
            rows.append([_("overhung end") + " $d_1$", f(sh.d_end * MM, 0), unit_mm])
        if sh.d_seal is not None:
            rows.append([_("seal section") + " $d_2$", f(sh.d_seal * MM, 0), unit_mm])
        rows += [[_("journal") + " $d_j$", f(sh.d_journal * MM, 0), unit_mm],
                 [_("worm root circle") + " $d_{f1}$" if sh.worm_integral else _("hub seat") + " $d_s$",
                  _dia(sh.d_seat), unit_mm],
                 [_("collar") + " $d_c$", f(sh.d_shoulder * MM, 0), unit_mm],
                 [_("bearing span") + " $L$", f(sh.span * MM, 0), unit_mm],
                 [_("design torque") + " $T$", f(sh.torque, 1, group=True), "N·m"]]
        if sh.bearing is not None:
            rows.append([_("bearing"), sh.bearing.designation, "—"])
        for k in sh.keys:
            lab = f"{f(k.b * MM, 0)}×{f(k.h * MM, 0)}×{f(k.L * MM, 0)}" + (" ×2" if k.count == 2 else "")
            rows.append([_("key ({element})", element=_part(k.part, k.element, d, _)), lab, unit_mm])
        bearing_std = () if sh.bearing is None else (
            ("gb297",) if sh.bearing.designation.startswith("3") else ("gb276",))
        formulas = []
        for c in sh.checks:
            if c.key == "shaft_bending":
                formulas.append({"text": _critical_section(sh, c, _)})
            formulas += check_formulas(c)
        out.append({"title": title, "text": text, "rows": rows,
                    "formulas": formulas, "checks": _rows(check_rows(sh.checks, lang), _),
                    "refs": ("pu8", "gb1096", *bearing_std)})
    return out


def _critical_section(sh, c, _) -> str:
    """The sentence before a shaft's σ_ca line: the section it checks (the shaft design's own
    choice, the largest σ_ca over the load and bearing sections, each with its diameter) and,
    where that is not the section of the largest equivalent moment the text names, why (a
    smaller diameter: the shaper's shaft Ⅰ, 20 mm at its overhung end, not 30 mm at x = 106 mm)."""
    from .fmt import minus

    x, d = c.inputs["x"], c.inputs["d"]
    kind = sh.section_at(x)
    at_load = any(abs(x - ld.x) < 1e-12 for ld in sh.loads)
    where = {"journal": _("journal"),
             "seat": _("worm root circle") if sh.worm_integral else _("hub seat"),
             "seal": _("seal section, at the bearing's outer face"),
             "end": _("overhung end") if at_load else _("overhung end, at the hub's inner edge")}[kind]
    text = _("Critical section (where $\\sigma_{{ca}}$, evaluated at every load and bearing section and "
             "where an overhung end steps, with the diameter there, is largest): $x$ = {x} mm ({where}), "
             "$d$ = {d} mm.",
             x=minus(f(x * MM, 0)), where=where, d=_dia(d))
    crit = sh.result.critical
    dm = sh.diameter_at(crit.x)
    if abs(x - crit.x) > 1e-9 and d < dm - 1e-12:
        moment = c.inputs["M"] if abs(c.inputs["M"]) > 1e-9 * max(abs(crit.M), 1.0) else 0.0
        text += ("" if _.zh else " ") + _("Its bending moment ({M} N·m) is smaller than at $x$ = {xm} mm ({Mm} N·m), "
                        "but its diameter is smaller ({d} mm < {dm} mm), so $\\sigma_{{ca}}$ is larger.",
                        M=sig(moment) if moment else "0", xm=minus(f(crit.x * MM, 0)), Mm=sig(crit.M),
                        d=_dia(d), dm=_dia(dm))
    return text


def _dia(d: float) -> str:
    """A section's diameter [m] in mm as the design chose it (fmt.exact): whole from the
    standard series, a worm's root circle with its decimal (d_f1 = 30.4 mm; page review 41:
    the table said 30 beside 30.4 in the design step and in the σ_ca line)."""
    return exact(d * MM, None, 2)


def _helix_correction(r, g, _) -> list[str]:
    """A helical pair's centre distance rounded to a whole millimetre and its β corrected
    (the stage's design; PU Lianggui, Machine Design, ch. 10)."""
    from .strength_tex import num

    e, geo = g.extra, g.geometry
    m, zs = num(g.module * MM), f"{r.z1} + {r.z2}"
    a = geo.a * MM
    beta0 = num(math.degrees(e["beta0"]))
    return [_("The centre distance is rounded to a whole millimetre and the helix angle corrected "
              "to it; the checks below use the corrected $\\beta$:"),
            rf"$$ a_0 = \frac{{m_n (z_1 + z_2)}}{{2\cos\beta_0}} = \frac{{{m} \times ({zs})}}"
            rf"{{2\cos {beta0}^\circ}} = {f(e['a0'] * MM, 2)}\ \text{{mm}} \rightarrow "
            rf"a = {f(a, 0)}\ \text{{mm}} $$",
            rf"$$ \beta = \arccos\frac{{m_n (z_1 + z_2)}}{{2a}} = \arccos\frac{{{m} \times "
            rf"{r.z1 + r.z2}}}{{2 \times {f(a, 0)}}} = {f(math.degrees(geo.beta), 2)}^\circ $$"]


def _belt_design(r, g, title: str, _) -> dict:
    """The V-belt subsection: each step of 濮良贵 ch.8 with its rule and its numbers."""
    from .strength_tex import check_rows, num

    b = g.geometry
    deg = np.degrees
    P, Pca = b.power / 1e3, b.power_design / 1e3
    d1, d2, a0 = b.d1 * MM, b.d2 * MM, b.a0 * MM
    d2_calc = r.ratio_allocated * d1 * (1 - b.slip)
    if b.section_given:
        how = _(" (given in the brief)")
    elif b.section_chart == b.section:
        how = _(" (from the selection chart, fig. 8-11)")
    else:
        how = _(" (the selection chart, fig. 8-11, gives {section_chart}, which fails the "
                 "wrap-angle or belt-count check; {section} is used)", section_chart=b.section_chart,
                 section=b.section)
    sec = f"{b.section}{how}"
    text = [_("Ordinary V-belts designed by PU Lianggui, Machine Design, ch.8: application "
              "factor $K_A = {KA}$ (table 8-8), design power $P_{{ca}} = {Pca}$ kW, small "
              "pulley speed $n_1 = {n1_rpm}$ rpm, section {sec}; small datum diameter "
              "$d_{{d1}} = {d1}$ mm ≥ $d_{{dmin}} = {d_min}$ mm (table 8-7, and a belt speed "
              "of at least 5 m/s), the large one from the datum series (table 8-9).", KA=f(b.KA, 2),
              Pca=f(Pca, 3), n1_rpm=f(b.n1_rpm, 0), sec=sec, d1=f(d1, 0), d_min=f(b.d_min * MM, 0)),
            _("Initial centre distance $a_0 = {a0}$ mm ($0.7(d_{{d1}}+d_{{d2}}) = {a0_min}$ "
              "… $2(d_{{d1}}+d_{{d2}}) = {a0_max}$ mm); fitting and take-up range $a_{{min}} "
              "… a_{{max}} = {a_min} … {a_max}$ mm. $P_0$ interpolated bilinearly in $n_1$ "
              "and $d_{{d1}}$ (table 8-4), $\\Delta P_0$ linearly in $n_1$ (table 8-5), "
              "$K_\\alpha$ and $K_L$ from tables 8-6 and 8-2; the selection chart's "
              "boundaries are read off the figure: check the section and these table values "
              "in the handbook before handing in.", a0=f(a0, 0),
              a0_min=f(b.a0_min * MM, 0), a0_max=f(b.a0_max * MM, 0), a_min=f(b.a_min * MM, 0),
              a_max=f(b.a_max * MM, 0))]
    F0_row, F0_txt, Fp_txt = _fp_texts(b.z, b.F0, deg(b.alpha1), b.Fp)
    # v to 0.01 m/s in the table, the formulas and the checks (one value one way, review 38)
    rows = [[_("Section"), b.section, "—"],
            ["$d_{d1} / d_{d2}$", f"{f(d1, 0)} / {f(d2, 0)}", "mm"], ["$v$", f(b.v, 2), "m/s"],
            ["$L_d$", f(b.L_d * MM, 0), "mm"], ["$a$", f(b.a * MM, 1), "mm"],
            ["$\\alpha_1$", f(deg(b.alpha1), 2), "°"], ["$z$", str(b.z), "—"],
            ["$F_0$", F0_row, "N"], ["$F_p$", Fp_txt, "N"]]
    i_txt = _num_giving(r.ratio_allocated, lambda i: i * float(num(d1)) * (1 - float(num(b.slip))),
                        num(d2_calc), num)
    d2_eq = (rf"d_{{d2}} = i\,d_{{d1}}(1-\varepsilon) = {i_txt} \times {num(d1)} \times "
             rf"(1-{num(b.slip)}) = {num(d2_calc)}\ \text{{mm}} \rightarrow {num(d2)}\ \text{{mm}}"
             if not r.fixed else rf"d_{{d2}} = {num(d2)}\ \text{{mm}}")
    # L_d0 with the digits that give the printed a (1697.2: 470 + (1600 − 1697.2)/2 = 421.4)
    a_txt = num(b.a * MM)
    # (a half unit rounded down is no match: 380 + (1400 − 1359.3)/2 = 400.35, printed 400.3)
    from ..numbers import gives as _gives_printed
    ld0 = next(t for t in (num(b.L_d0 * MM, k) for k in (4, 5, 6, 7)) if _gives_printed(
        float(num(a0)) + (float(num(b.L_d * MM)) - float(t)) / 2, a_txt)
        or t == num(b.L_d0 * MM, 7))
    formulas = [
        rf"P_{{ca}} = K_A P = {num(b.KA)} \times {_num_giving(P, lambda x: float(num(b.KA)) * x, num(Pca), num)}"
        rf" = {num(Pca)}\ \text{{kW}}",
        rf"v = \frac{{\pi d_{{d1}} n_1}}{{60 \times 1000}} = \frac{{\pi \times {num(d1)} \times {num(b.n1_rpm)}}}"
        rf"{{60000}} = {f(b.v, 2)}\ \text{{m/s}}",
        d2_eq,
        rf"L_{{d0}} = 2a_0 + \frac{{\pi}}{{2}}(d_{{d1}}+d_{{d2}}) + \frac{{(d_{{d2}}-d_{{d1}})^2}}{{4a_0}} = "
        rf"2 \times {num(a0)} + \frac{{\pi}}{{2}} \times {num(d1 + d2)} + \frac{{{num(d2 - d1)}^2}}{{4 \times {num(a0)}}}"
        rf" = {ld0}\ \text{{mm}} \rightarrow L_d = {num(b.L_d * MM)}\ \text{{mm}},\ K_L = {num(b.K_L)}",
        rf"a = a_0 + \frac{{L_d - L_{{d0}}}}{{2}} = {num(a0)} + \frac{{{num(b.L_d * MM)} - {ld0}}}{{2}}"
        rf" = {num(b.a * MM)}\ \text{{mm}}",
        rf"\alpha_1 = 180^\circ - \frac{{d_{{d2}} - d_{{d1}}}}{{a}} \times \frac{{180^\circ}}{{\pi}} = 180^\circ - "
        rf"\frac{{{num(d2 - d1)}}}{{{num(b.a * MM)}}} \times \frac{{180^\circ}}{{\pi}} = {num(deg(b.alpha1))}^\circ",
        rf"z = \frac{{P_{{ca}}}}{{(P_0 + \Delta P_0) K_\alpha K_L}} = \frac{{{num(Pca)}}}{{({num(b.P0 / 1e3)} + "
        rf"{num(b.dP0 / 1e3)}) \times {num(b.K_alpha)} \times {num(b.K_L)}}} = {num(b.z_exact)} \rightarrow z = {b.z}",
        rf"F_0 = 500 \frac{{(2.5 - K_\alpha) P_{{ca}}}}{{K_\alpha z v}} + q v^2 = 500 \times \frac{{(2.5 - "
        rf"{num(b.K_alpha)}) \times {num(Pca)}}}{{{num(b.K_alpha)} \times {b.z} \times {f(b.v, 2)}}} + {num(b.q_mass)}"
        rf" \times {f(b.v, 2)}^2 = {F0_row}\ \text{{N}}",
        rf"F_p = 2 z F_0 \sin\frac{{\alpha_1}}{{2}} = 2 \times {b.z} \times {F0_txt} \times \sin"
        rf"\frac{{{num(deg(b.alpha1))}^\circ}}{{2}} = {Fp_txt}\ \text{{N}}",
    ]
    return {"title": title, "text": text, "rows": rows, "formulas": formulas,
            "checks": _rows(check_rows(g.checks, _.lang), _), "refs": ("pu9", "gb13575")}


def _chain_design(g, title: str, _) -> dict:
    """The roller-chain subsection: each step of 濮良贵 ch.9 §9-5 with its numbers."""
    from .strength_tex import check_rows, num

    c = g.geometry
    p = c.pitch * MM
    P, Pca = c.power / 1e3, c.power_design / 1e3
    how = ((_("the chain given in the brief")) if c.chain_given else
           (_("the smallest chain whose rated power carries $P_{ca}$")))
    text = [_("Roller chain (A series, {rows} row(s)) designed by PU Lianggui, Machine "
              "Design, ch.9: application factor $K_A = {KA}$ (table 9-6), tooth factor $K_z "
              "= (19/z_1)^{{1.08}} = {Kz}$, row factor $K_p = {Kp}$; {how}: {chain} (p = {p} "
              "mm), rated power of one strand {rated_power} kW.", rows=c.rows, KA=f(c.KA, 2),
              Kz=f(c.Kz, 3), Kp=f(c.Kp, 2), how=how, chain=c.chain, p=f(p, 3),
              rated_power=f(c.rated_power / 1e3, 3)),
            _("The rated-power chart (fig. 9-11) could not be typed from the book: the ANSI "
              "B29.1 rating formulas (Shigley eqs. 17-32, 17-33, at $z_1 = 19$) stand in for "
              "it (an assumption, see data/chains.yaml); the centre distance is the exact "
              "inverse of the link count; the load on the shafts $F_Q = {FQ_factor} F_e$.",
              FQ_factor=f(c.FQ_factor, 1))]
    rows = [[_("Chain"), c.chain, "—"], ["$z_1 / z_2$", f"{c.z1} / {c.z2}", "—"],
            ["$p$", f(p, 3), "mm"], ["$L_p$", str(c.L_p), "—"], ["$a$", f(c.a * MM, 1), "mm"],
            ["$v$", f(c.v, 3), "m/s"], ["$F_e$", f(c.Fe, 1), "N"], ["$F_Q$", f(c.FQ, 1), "N"]]
    formulas = [
        rf"P_{{ca}} = \frac{{K_A K_z P}}{{K_p}} = \frac{{{num(c.KA)} \times {num(c.Kz)} \times "
        rf"{_num_giving(P, lambda x: float(num(c.KA)) * float(num(c.Kz)) * x / float(num(c.Kp)), num(Pca), num)}}}"
        rf"{{{num(c.Kp)}}} = {num(Pca)}\ \text{{kW}}",
        rf"L_{{p0}} = \frac{{2a_0}}{{p}} + \frac{{z_1 + z_2}}{{2}} + \frac{{p}}{{a_0}}\left(\frac{{z_2 - z_1}}"
        rf"{{2\pi}}\right)^2 = \frac{{2 \times {num(c.a0 * MM)}}}{{{num(p)}}} + \frac{{{c.z1 + c.z2}}}{{2}} + "
        rf"\frac{{{num(p)}}}{{{num(c.a0 * MM)}}}\left(\frac{{{c.z2 - c.z1}}}{{2\pi}}\right)^2 = {num(c.L_p0)}"
        rf" \rightarrow L_p = {c.L_p}",
        rf"a = \frac{{p}}{{4}}\left[\left(L_p - \frac{{z_1 + z_2}}{{2}}\right) + \sqrt{{\left(L_p - "
        rf"\frac{{z_1 + z_2}}{{2}}\right)^2 - 8\left(\frac{{z_2 - z_1}}{{2\pi}}\right)^2}}\right] = "
        rf"{num(c.a * MM)}\ \text{{mm}}",
        rf"v = \frac{{z_1 n_1 p}}{{60 \times 1000}} = \frac{{{c.z1} \times {num(c.n1_rpm)} \times {num(p)}}}"
        rf"{{60000}} = {num(c.v)}\ \text{{m/s}}",
        rf"F_Q = {num(c.FQ_factor)} F_e = {num(c.FQ_factor)} \times \frac{{1000 P}}{{v}} = {num(c.FQ_factor)} "
        rf"\times \frac{{1000 \times {num(P)}}}{{{num(c.v)}}} = {num(c.FQ)}\ \text{{N}}",
    ]
    return {"title": title, "text": text, "rows": rows, "formulas": formulas,
            "checks": _rows(check_rows(g.checks, _.lang), _), "refs": ("pu9",)}


# --------------------------------------------------------------------------- machine: drive


def _newtons(x: float) -> str:
    """A shaft's reaction or bearing load in a formula: to 0.1 N below 1000 N, else to 1 N."""
    return f(x, 1 if abs(x) < 1000 else 0)
