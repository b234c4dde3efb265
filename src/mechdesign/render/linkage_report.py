"""Report pieces of any linkage (the shared linkage stages): figures, template context and
the verification rows; plus the report module of the stand-alone ``linkage`` machine.

Machines that analyse a linkage include ``templates/linkage_section.*.md.j2`` with
``{% with lk = … %}`` and pass :func:`linkage_context`'s dict; the verification rows of
:func:`verification_rows` go into ``templates/verification_section.*.md.j2`` together
with the machine's own checks.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..i18n import N_, tr
from . import figures as fig
from .fmt import column_decimals, e, f, residue, fluctuation, force_unit, md_text, percent, sentences, sig, tex_name, time_ratio
from .fmt import verdict as fmt_verdict
from .fmt import factor_for, factors_for, gives, product
from .label_layout import Label, place
from .legends import legend
from .labels import LabelTable, md_names, md_point, mpl_names, mpl_point, point_tex

DEG = 180.0 / np.pi

_TXT = LabelTable({
    "s": N_("displacement s"),
    "v": N_("velocity v"),
    "a": N_("acceleration a"),
    "swing": N_("angle $\\psi$"),
    "w": N_("angular velocity $\\omega$"),
    "al": N_("angular acceleration $\\alpha$"),
    "gamma": N_("transmission angle $\\gamma$"),
    "alpha": N_("pressure angle $\\alpha$"),
    "limit": N_("allowed"),
    "mb": N_("balancing torque $M_b$ (N·m)"),
    "mean": N_("mean"),
    "resist": N_("resistance acts"),
    "angle": N_("angle (°)"),
    "transmission": N_("transmission angle"),
    "pressure": N_("pressure angle"),
})


def _units(k):
    """Display scale and unit strings of the output (mm or °)."""
    if k.output_unit == "m":
        return 1e3, ("mm", "m/s", "m/s²")
    return DEG, ("°", "rad/s", "rad/s²")


def _with_unit(number: str, unit: str) -> str:
    """A number and its unit: the degree sign follows the number directly (34.92°), any
    other unit after a space (120.00 mm)."""
    return f"{number}{unit}" if unit == "°" else f"{number} {unit}"


def _labels(k):
    return [lab.replace("'", "′") for lab in k.positions.labels]


def make_linkage_figures(model, k, f_, fly, fig_dir: Path, lang: str,
                         prefix: str = "linkage") -> dict[str, str]:
    """Draw the linkage figures into ``fig_dir``; return name → relative path."""
    from ..stages.linkage import link_members

    t = _TXT[lang]
    n = k.grid_size
    ph = k.phase[:n] * DEG
    span = k.working_span * DEG
    pos_ph = k.phase[n:] * DEG
    labels = _labels(k)
    paths = {}

    def out(name):
        key = f"{prefix}_{name}"
        paths[key] = f"{fig_dir.name}/{key}.png"
        return fig_dir / f"{key}.png"

    scale, units = _units(k)
    point = k.output_unit == "m"
    names = ([t["s"], t["v"], t["a"]] if point else [t["swing"], t["w"], t["al"]])
    ylabels = [f"{nm} ({u})" for nm, u in zip(names, units)]
    fig.curves_vs_phase(out("motion"), lang, ph, [k.s[:n] * scale, k.v[:n], k.a[:n]], ylabels,
                        span, (labels, pos_ph, [k.s[n:] * scale, k.v[n:], k.a[n:]]))
    if k.quality:
        _quality_figure(out("angles"), lang, ph, span, k, model)
    _torque_figure(out("torque"), lang, ph, span, f_.balancing_torque[:n], f_.mean_torque,
                   f_.resistance, n, (labels, pos_ph, f_.balancing_torque[n:]))
    if fly is not None:
        fig.energy(out("energy"), lang, ph, fly.energy, fly.phase_at_min * DEG,
                   fly.phase_at_max * DEG, fly.max_energy_swing, span)
    if f_.reactions:
        fig.reactions(out("reactions"), lang, ph,
                      {f"$F_{{{tex_name(name)}}}$": np.abs(v[:n]) for name, v in f_.reactions.items()},
                      span)
    members, sliders = link_members(model.mechanism)
    skeleton(out("mechanism"), lang, model, k, members, sliders)
    return paths


def _quality_figure(path, lang, ph, span, k, model):
    t = _TXT[lang]
    n = k.grid_size
    with fig.figure(path, 1, (7.0, 3.2)) as (ax,):
        fig._phase_axis(ax, span)
        for q in k.quality:
            sym = "γ" if q.kind == "transmission" else "α"
            ax.plot(ph, q.values[:n] * DEG, lw=1.3, label=f"{sym} {mpl_names(_group_namer(model, lang)(q.group))}")
        if model.pressure_angle_limit is not None:
            ax.axhline(model.pressure_angle_limit * DEG, color="C3", ls="--", lw=0.9,
                       label=f"[α] = {model.pressure_angle_limit * DEG:.0f}°")
        if model.transmission_angle_min is not None:
            ax.axhline(model.transmission_angle_min * DEG, color="C2", ls=":", lw=0.9,
                       label=f"[γ] = {model.transmission_angle_min * DEG:.0f}°")
        # the axis to the curves (a 0–4° pressure angle is not drawn on a 0–90° axis, issue 19)
        hi = max([float(np.max(q.values[:n])) * DEG for q in k.quality]
                 + [x * DEG for x in (model.pressure_angle_limit, model.transmission_angle_min)
                    if x is not None])
        ax.set_ylim(0, 90 if hi > 50 else _nice_ceiling(1.25 * hi))
        ax.set_ylabel(t["angle"])
        ax.set_xlabel(fig.LABELS[lang]["phase"])
        legend(ax, fontsize=7, loc="upper right", ncol=2)


def _nice_ceiling(x: float) -> float:
    """The smallest of 1, 2, 2.5, 5 × 10^k not below x (x > 0)."""
    if x <= 0:
        return 1.0
    e = 10.0 ** np.floor(np.log10(x))
    return float(next(m * e for m in (1, 2, 2.5, 5, 10) if m * e >= x))


def _torque_figure(path, lang, ph, span, mb, mean, resistance, n, marks):
    t = _TXT[lang]
    with fig.figure(path, 1, (7.0, 3.4)) as (ax,):
        fig._phase_axis(ax, span, marks)
        if resistance:
            on = np.zeros(n, dtype=bool)
            for values in resistance.values():
                on |= np.abs(values[:n]) > 0
            ax.fill_between(ph, 0, 1, where=on, transform=ax.get_xaxis_transform(),
                            color="C1", alpha=0.10, lw=0, label=t["resist"])
        ax.plot(ph, mb, lw=1.4, color="C0", label=r"$M_b$")
        ax.axhline(mean, color="C2", lw=1.0, ls="--", label=f"{t['mean']} = {mean:.2f} N·m")
        ax.axhline(0, color="0.4", lw=0.6)
        ax.set_xlabel(fig.LABELS[lang]["phase"])
        ax.set_ylabel(t["mb"])
        legend(ax, fontsize=7, loc="best")


def _slider_outline(at: complex, angle: float, block: float) -> np.ndarray:
    """A slider's block centred on ``at``: 2·``block`` long along its guide (``angle``),
    1.2·``block`` across; its outline, closed (five corners)."""
    u = np.exp(1j * angle) * block
    return at + np.array([-u - 0.6j * u, u - 0.6j * u, u + 0.6j * u, -u + 0.6j * u, -u - 0.6j * u])


def skeleton(path: Path, lang: str, model, k, members: dict, sliders: list):
    """The linkage at its regular textbook positions (thin) and position 1 (bold), in mm."""
    from ..core.mechanism import Crank

    n = k.grid_size
    regular = [n + i for i, s in enumerate(k.positions.special) if not s]
    labels = [k.positions.labels[i - n] for i in regular]
    P = {name: z * 1e3 for name, z in k.points.items()}
    frame = model.mechanism.frame_points
    crank: Crank = model.crank
    allpts = np.concatenate([P[p][:n] for p in P])
    span = max(np.ptp(allpts.real), np.ptp(allpts.imag), 1e-9)
    block = 0.025 * span
    lines: list[tuple[complex, complex]] = []       # what a point's name must not lie on
    numbers = []                                    # the position numbers at the crank pin
    with fig.figure(path, 1, (6.4, 5.6), sharex=False) as (ax,):
        # Paths of every moving point over the cycle.
        for name, z in P.items():
            if name not in frame:
                ax.plot(z[:n].real, z[:n].imag, color="0.82", lw=0.5, zorder=1)
        for rank, j in enumerate(regular):
            bold = rank == 0
            color, lw = ("C0", 1.9) if bold else ("0.6", 0.6)
            for link, pts in members.items():
                zs = [P[p][j] for p in pts]
                c = "C3" if (bold and link == crank.link) else color
                if len(zs) >= 3:
                    poly = np.array(zs + [zs[0]])
                    ax.fill(poly.real, poly.imag, color=c, alpha=0.12 if bold else 0.04, lw=0)
                    ax.plot(poly.real, poly.imag, color=c, lw=lw)
                else:
                    ax.plot([z.real for z in zs], [z.imag for z in zs], color=c, lw=lw)
            # each slider's block at this position: drawn, and at position 1 a line a name avoids
            blocks = [_slider_outline(P[p][j], guide if isinstance(guide, float)
                                      else k.link_angle[guide][j], block)
                      for _slider, p, guide, _gp in sliders]
            for corners in blocks:
                ax.plot(corners.real, corners.imag, color=color, lw=lw)
            tip = P[crank.tip][j]
            o = complex(frame[crank.pivot]) * 1e3
            u = (tip - o) / abs(tip - o)
            numbers.append(ax.text((tip + 1.8 * block * u).real, (tip + 1.8 * block * u).imag,
                                   labels[rank], fontsize=6.5, ha="center", va="center"))
            if bold:        # the links of position 1: a point's name must not lie on them
                for link, pts in members.items():
                    zs = [P[p][j] for p in pts]
                    zs = zs + [zs[0]] if len(zs) >= 3 else zs
                    lines += list(zip(zs[:-1], zs[1:]))
                for corners in blocks:
                    lines += list(zip(corners[:-1], corners[1:]))
        for slider, p, guide, gp in sliders:
            if isinstance(guide, float):
                z = P[p][:n]
                u = np.exp(1j * guide)
                along = (np.conj(u) * (z - gp * 1e3)).real
                a, b = along.min() - 2 * block, along.max() + 2 * block
                ends = gp * 1e3 + np.array([a, b]) * u
                ax.plot(ends.real, ends.imag, color="0.4", lw=0.8, ls="-.")
        names: list[Label] = []
        for name, z in frame.items():
            z = complex(z) * 1e3
            ax.plot([z.real], [z.imag], "^", color="k", ms=6, zorder=4)
            lines.append((z, z))
            names.append(Label(mpl_point(name), z, (1 - 1j,), {"fontsize": 8.5}))
        j0 = regular[0]
        for name in P:
            if name not in frame:
                z = P[name][j0]
                ax.plot([z.real], [z.imag], "o", color="C0", ms=2.5, zorder=4)
                lines.append((z, z))
                names.append(Label(mpl_point(name), z, _away_from_links(z, lines),
                                   {"fontsize": 8.5, "color": "C0"}))
        ax.set_aspect("equal")
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("y (mm)")
        ax.grid(True, lw=0.3, color="0.88")
        # the point names clear of the links of position 1 and of each other (issue 19)
        place(ax, names, lines, fixed=numbers)


def _away_from_links(z: complex, lines) -> tuple:
    """Directions for a point's name: the bisector of the widest gap between the links that
    meet at ``z`` (so the name sits between them, off both), then the other gaps."""
    angles = sorted({float(np.angle(b - a if abs(a - z) < 1e-9 else a - b))
                     for a, b in lines if abs(a - b) > 1e-9 and (abs(a - z) < 1e-9 or abs(b - z) < 1e-9)})
    if not angles:
        return (1 + 1j,)
    gaps = [(angles[(i + 1) % len(angles)] - a) % (2 * np.pi) or 2 * np.pi for i, a in enumerate(angles)]
    order = sorted(range(len(angles)), key=lambda i: -gaps[i])
    return tuple(np.exp(1j * (angles[i] + gaps[i] / 2)) for i in order)


def _link_rows(model, lang: str) -> list[list[str]]:
    """Groups of the linkage with their dimensions, for the data table (names, point
    names and link ids come from the brief: escaped)."""
    from ..core.mechanism import RPR, RRP, RRR, Crank, LinkPoint
    from ..stages.linkage import link_name

    _ = tr(lang)
    m = md_point            # a point name or a run of them ("O1A"), its digits lowered
    gn = _group_namer(model, lang)

    def ids(*links):
        # The machine's names of its links, where it gives them (e.g. 4 摇杆).
        return ", ".join(md_names(f"{l_} {link_name(model.names, l_, lang)}" if l_ in model.names else l_)
                         for l_ in links)

    rows = []
    for g in model.mechanism.groups:
        if isinstance(g, Crank):
            bar = m(f"{g.pivot}{g.tip}")
            rows.append([_("crank"), ids(g.link), bar,
                         f"{bar} = {f(g.length * 1e3, 2)} mm"])
        elif isinstance(g, RRR):
            bc, dc = m(f"{g.b}{g.c}"), m(f"{g.d}{g.c}")
            rows.append([md_names(gn(g.name)), ids(g.link1, g.link2), f"{bc}, {dc}",
                         f"{bc} = {f(g.l1 * 1e3, 2)} mm, {dc} = {f(g.l2 * 1e3, 2)} mm"])
        elif isinstance(g, RRP):
            bc = m(f"{g.b}{g.c}")
            rows.append([md_names(gn(g.name)), ids(g.rod, g.slider), bc,
                         f"{bc} = {f(g.length * 1e3, 2)} mm; "
                         + _("guide through ({x}, {y}) mm, {angle}°", x=f(g.guide_point.real * 1e3, 1),
                             y=f(g.guide_point.imag * 1e3, 1), angle=f(g.guide_angle * DEG, 1))])
        elif isinstance(g, RPR):
            rows.append([md_names(gn(g.name)), ids(g.slider, g.bar), m(f"{g.pivot}{g.a}"),
                         _("offset {e} mm", e=f(g.offset * 1e3, 2))])
        elif isinstance(g, LinkPoint):
            bar = m(f"{g.origin}{g.name}")
            rows.append([_("point {name}", name=m(g.name)), ids(g.link), bar,
                         f"{bar} = {f(g.distance * 1e3, 2)} mm, "
                         f"{f(g.offset_angle * DEG, 1)}°"])
    return rows


def _group_namer(model, lang: str):
    """A group's name as an ``lang`` report shows it: from ``LinkageModel.group_labels``
    (the machine's names, or the brief's ``name`` and ``name_en``) where it has one, else
    the name as written."""
    from ..stages.linkage import link_name

    labels = getattr(model, "group_labels", None) or {}
    return lambda name: link_name(labels, name, lang) if name in labels else name


def _angles_caption(k, lang: str) -> str:
    """The caption of the angle figure, naming only the angles drawn (issue 19)."""
    _ = tr(lang)
    kinds = {q.kind for q in k.quality}
    if kinds == {"transmission"}:
        return _("Transmission angle against the crank angle")
    if kinds == {"pressure"}:
        return _("Pressure angle against the crank angle")
    return _("Transmission and pressure angles against the crank angle")


def rim_inertia_factor(inertia: float, rim) -> str:
    """J_F as the factor of the rim mass m = 4 J_F/D², with the digits that give the printed
    mass (4 × 204.13/1.000² = 816.52)."""
    return factor_for(inertia, lambda x: gives(4 * x / float(f(rim.diameter, 3)) ** 2,
                                               f(rim.rim_mass, 2)))


def carried_note(_, carried) -> str | None:
    """The sentence after a formula that substitutes a value with more digits than the text
    prints it (the shaper's J_F = 900 × 278.04/… beside "ΔW_max = 278.0 J"): the text keeps
    the rule's digits for the quantity (4 significant for an energy, 0.01 rpm for a speed), the
    formula carries the fewest more that give its printed result to the last digit, and the
    reader is told which is which (issue 19 point 5). ``carried``: (symbol as TeX, the text's
    string, the formula's string) of each factor; None when every factor is as in the text."""
    def plain(text: str) -> str:
        return text.replace("\u202f", "").replace(" ", "")

    names = [f"${symbol}$" for symbol, shown, used in carried if plain(shown) != plain(used)]
    if not names:
        return None
    # short, and set at the head of the paragraph after the formulas: a line more there moved
    # the pages after it and the shaper en's layout no longer settled (typst's five passes)
    # (with the gap to the sentence after it: a space in English, none after "。")
    gap = "" if _.zh else " "
    if len(names) == 1:
        return _("Here {a} carries more digits.", a=names[0]) + gap
    return _("Here {a} and {b} carry more digits.", a=", ".join(names[:-1]), b=names[-1]) + gap


def flywheel_carried(energy_swing: float, speed_rpm: float, delta: float, jf: str,
                     n_shown: str, dw_shown: str, energy_digits: int = 4) -> list[tuple[str, str, str]]:
    """n and ΔW_max as :func:`flywheel_equation` substitutes them beside the text's strings,
    for :func:`carried_note`."""
    n_text, dw_text, _d = _flywheel_factors(energy_swing, speed_rpm, delta, jf, energy_digits)
    return [("n", n_shown, n_text), (r"\Delta W_{max}", dw_shown, dw_text)]


def flywheel_equation(energy_swing: float, speed_rpm: float, delta: float, jf: str,
                      energy_digits: int = 4) -> str:
    """J_F = 900ΔW_max/(π²n²[δ]) with its factors (:func:`_flywheel_factors`) substituted."""
    n_text, dw_text, d_tex = _flywheel_factors(energy_swing, speed_rpm, delta, jf, energy_digits)
    return (rf"J_F = \frac{{900\,\Delta W_{{max}}}}{{\pi^2 n^2 [\delta]}} = \frac{{900 \times "
            rf"{dw_text}}}{{\pi^2 \times {n_text}^2 \times {d_tex}}} = {jf}\ \text{{kg·m}}^2")


def _flywheel_factors(energy_swing: float, speed_rpm: float, delta: float, jf: str,
                      energy_digits: int = 4) -> tuple[str, str, str]:
    """J_F = 900ΔW_max/(π²n²[δ]) with its factors substituted so that they give the printed
    ``jf``: [δ] as the course writes it (1/30, never 0.0333); n to 0.01 rpm and ΔW_max to
    ``energy_digits`` significant digits (the text's), each with the fewest more digits
    that give ``jf`` (shaper: 266.667 and 278.04, where 266.67 and 278.0 give 8.912 for
    8.914), ΔW_max's first."""
    d_text = fluctuation(delta)
    num, _slash, den = d_text.partition("/")
    d_value = float(num) / float(den) if den else float(num)
    d_tex = rf"({num}/{den})" if den else d_text

    def jf_of(n: float, dw: float) -> float:
        denominator = np.pi ** 2 * n ** 2 * d_value
        return 900 * dw / denominator if denominator > 0 else float("nan")

    # n to 0.01 rpm (up to 0.0001); a speed below 1 rpm (a careless brief's 1e-9) to
    # significant digits, which 0.01 rpm would print as 0.00 (a division by zero)
    to_decimals = speed_rpm >= 1
    n_text, dw_text = factors_for((speed_rpm, energy_swing), jf_of, jf,
                                  (2 if to_decimals else 4, energy_digits), most=(2, 4),
                                  decimals=(to_decimals, False))
    return n_text, dw_text, d_tex


def realised_flywheel(fly, n_real: float | None, _) -> str | None:
    """The flywheel sized at the nominal speed (the crank's, at which M_b and ΔW_max are
    computed, × the ratio to its shaft) against the speed ``n_real`` [rpm] the drive realises
    on its shaft: the same flywheel there gives δ = [δ](n/n′)² (J_F ∝ 1/n²); None when the
    two agree or no drive is designed. A flywheel sized at the slower realised speed
    (``fly.nominal_speed_rpm`` set) is told so. The sentences in the language of ``_``."""
    if fly.nominal_speed_rpm is not None:
        n0, n1 = fly.nominal_speed_rpm, fly.shaft_speed_rpm
        return _("The drive (chapter \"Drive design\") realises $n'$ = {n_real} rpm on this shaft, {slower}% "
                 "below the nominal $n$ = {n} rpm at which $M_b$ and $\\Delta W_{{max}}$ are computed. "
                 "$J_F$ grows as $1/n^2$, so it is sized at the slower $n'$ above: sized at $n$, the flywheel "
                 "would let the fluctuation reach $\\delta = [\\delta](n/n')^2$ = {delta_real} > $[\\delta]$.",
                 n_real=f(n1, 2), n=f(n0, 2), slower=percent(abs(n1 / n0 - 1) * 100),
                 delta_real=f(fly.fluctuation * (n0 / n1) ** 2, 4))
    if n_real is None or abs(n_real - fly.shaft_speed_rpm) < 5e-3:
        return None
    delta = fly.fluctuation * (fly.shaft_speed_rpm / n_real) ** 2
    n, nr = f(fly.shaft_speed_rpm, 2), f(n_real, 2)
    off = percent(abs(n_real / fly.shaft_speed_rpm - 1) * 100)
    if n_real > fly.shaft_speed_rpm:
        first = _("$J_F$ is sized at the nominal speed $n$ = {n} rpm, at which $M_b$ and $\\Delta W_{{max}}$ "
                  "are computed; the drive (chapter \"Drive design\") realises $n'$ = {n_real} rpm on "
                  "this shaft, {faster}% faster.", n=n, n_real=nr, faster=off)
    else:
        first = _("$J_F$ is sized at the nominal speed $n$ = {n} rpm, at which $M_b$ and $\\Delta W_{{max}}$ "
                  "are computed; the drive (chapter \"Drive design\") realises $n'$ = {n_real} rpm on "
                  "this shaft, {faster}% slower.", n=n, n_real=nr, faster=off)
    if delta <= fly.fluctuation * (1 + 1e-12):
        second = _("The same flywheel there keeps the fluctuation at $\\delta = [\\delta](n/n')^2$ = {delta_real}, "
                   "within $[\\delta]$: the nominal speed is the safe side.", delta_real=f(delta, 4))
    else:
        second = _("The same flywheel there lets the fluctuation reach $\\delta = [\\delta](n/n')^2$ = {delta_real}, "
                   "above $[\\delta]$: at n′ it would need $J_F$ = {jf_real} kg·m².", delta_real=f(delta, 4),
                   jf_real=sig(fly.inertia * (fly.shaft_speed_rpm / n_real) ** 2))
    return sentences(_, first, second)



def linkage_context(model, k, f_, fly, v, figures: dict, lang: str,
                    prefix: str = "linkage", title: str | None = None,
                    flywheel_realised_rpm: float | None = None, given: str | None = None) -> dict:
    """Strings and rows for ``linkage_section``; ``title`` is the chapter heading;
    ``flywheel_realised_rpm``: the flywheel shaft's speed as the drive realises it;
    ``given``: the label of chapter 1's data table where it already lists the frame points,
    lengths, masses and resistances (the section then refers to it instead of repeating them)."""
    _ = tr(lang)
    n = k.grid_size
    scale, units = _units(k)
    labels = _labels(k)
    frame = model.mechanism.frame_points
    frame_rows = [[md_point(name), f(complex(z).real * 1e3, 2), f(complex(z).imag * 1e3, 2)]
                  for name, z in frame.items()]
    point_names = [p for p in k.points if p not in frame]
    # γ_B, α_D: the angle's symbol with the point as its subscript
    qual_head = [f"$\\{'gamma' if q.kind == 'transmission' else 'alpha'}_{{{point_tex(q.point)}}}$"
                 for q in k.quality]
    kin_rows, force_rows, point_rows = [], [], []
    reaction_names = list(f_.reactions)
    # forces in kN when they reach a million newtons (render/fmt.py's force_unit)
    peak = max([float(np.max(np.abs(vals))) for vals in f_.reactions.values() if len(vals)]
               + [max(abs(r.working), abs(r.returning)) for r in model.resistances], default=0.0)
    kilo, force_unit_ = force_unit(peak)
    force_digits = 2 if force_unit_ == "kN" else 1
    # M_b to one decimal count per column: four significant digits of its largest value, at
    # least one decimal, at most three (die_cutter: 7 762.0 and 2.4, not 7762.013 and 2.384;
    # a crank-rocker's 0.518 keeps its three)
    mb_peak = float(np.max(np.abs(f_.balancing_torque))) if len(f_.balancing_torque) else 0.0
    mb_digits = column_decimals(mb_peak, 4, least=1, most=3, empty=3)
    for i, label in enumerate(labels):
        j = n + i
        kin_rows.append([label, f(k.phase[j] * DEG, 2), f((k.crank_angle[j] * DEG) % 360, 2),
                         f(k.s[j] * scale, 3), f(k.v[j], 4), f(k.a[j], 4)]
                        + [f(q.values[j] * DEG, 2) for q in k.quality])
        force_rows.append([label] + [f(abs(f_.reactions[nm][j]) / kilo, force_digits, group=True)
                                     for nm in reaction_names]
                          + [f(f_.balancing_torque[j], mb_digits, group=True)])
        point_rows.append([label] + [f"({f(k.points[p][j].real * 1e3, 1)}, "
                                     f"{f(k.points[p][j].imag * 1e3, 1)})" for p in point_names])
    link_speed_rows = []
    for i, label in enumerate(labels):
        j = n + i
        link_speed_rows.append([label] + [f"{f(k.link_omega[l_][j], 3)} / {f(k.link_alpha[l_][j], 2)}"
                                          for l_ in k.link_omega])
    qual_rows, gname = [], _group_namer(model, lang)
    for q in k.quality:
        kind = _("transmission angle $\\gamma$") if q.kind == "transmission" else _("pressure angle $\\alpha$")
        if q.kind == "transmission":
            extreme = _("min {angle}° at $\\varphi$ = {phase}°", angle=f(q.extreme * DEG, 2),
                        phase=f(q.extreme_phase * DEG, 1))
            work = f(q.working_extreme * DEG, 2) + "°"
            limit = "—" if model.transmission_angle_min is None else \
                f"≥ {f(model.transmission_angle_min * DEG, 0)}°"
        else:
            extreme = _("max {angle}° at $\\varphi$ = {phase}°", angle=f(q.extreme * DEG, 2),
                        phase=f(q.extreme_phase * DEG, 1))
            work = _("{angle}° at $\\varphi$ = {phase}°", angle=f(q.working_extreme * DEG, 2),
                     phase=f(q.working_extreme_phase * DEG, 1))
            limit = "—" if model.pressure_angle_limit is None else \
                _("≤ {limit}° (working stroke)", limit=f(model.pressure_angle_limit * DEG, 0))
        within = q.passed
        qual_rows.append([md_names(gname(q.group)), kind, md_point(q.point), extreme, work, limit]
                         + ([] if within is None else [fmt_verdict(within, lang)]))
    # a verdict column where the brief gives a limit (the die-cutter's [γ] and [α]; page review 45)
    judged = any(q.passed is not None for q in k.quality)
    angles_head = [_("Group"), _("Measure"), _("At"), _("Whole cycle"), _("Working stroke"), _("Allowed")]
    if judged:
        angles_head.append(_("Verdict"))
        qual_rows = [row if len(row) == 7 else row + ["—"] for row in qual_rows]
    angles_align = "|:--|:--|:-:|:--|:--|:--|" + (":-:|" if judged else "")
    res_rows = []
    for i, r in enumerate(model.resistances):
        window = "—"
        if r.active is not None:
            window = f"{f(r.active[0] * scale, 1)} – {_with_unit(f(r.active[1] * scale, 1), units[0])}"
        res_rows.append([f"R{i + 1}", md_point(r.point), md_text(r.link),
                         # a line's angle, in [0°, 180°): the force's sense is the motion's
                         # opposite (slotter: "−90.0" under "Direction" read as downwards while
                         # the cut is resisted upwards; page review 41)
                         f((r.direction * DEG) % 180.0, 1),
                         f(r.working / kilo, force_digits, group=True),
                         f(r.returning / kilo, force_digits, group=True), window])
    mass_rows = [[md_text(b.link), md_point(b.com), f(b.mass, 2), f(b.inertia, 4)]
                 for b in model.bodies]
    omega = abs(model.crank_omega)
    ctx = {
        "title": title or _("Linkage analysis"),
        "fig": {"mechanism": None, "motion": None, "angles": None, "torque": None,
                "energy": None, "reactions": None,
                **{key.removeprefix(prefix + "_"): path for key, path in figures.items()
                   if key.startswith(prefix + "_")}},
        "frame_rows": frame_rows, "link_rows": _link_rows(model, lang),
        "mass_rows": mass_rows, "res_rows": res_rows, "given": given,
        "speed": f(omega * 30 / np.pi, 2), "omega": sig(omega, group=False),
        "sense": _("clockwise") if model.crank_omega < 0 else _("counter-clockwise"),
        "output": md_names(model.output.name),
        "unit_s": units[0], "unit_v": units[1], "unit_a": units[2],
        # the table's symbols per quantity kind: a slider's s, v, a; a rocker's ψ, ω, α
        "sym_s": "$s$" if k.output_unit == "m" else "$\\psi$",
        "sym_v": "$v$" if k.output_unit == "m" else "$\\omega$",
        "sym_a": "$a$" if k.output_unit == "m" else "$\\alpha$",
        # a slider's stroke, a rocker's swing
        "stroke_word": _("Stroke") if k.output_unit == "m" else _("Swing"),
        "stroke": _with_unit(f(k.stroke * scale, 2), units[0]), "K": time_ratio(k.time_ratio),
        "theta": f(180 * (k.time_ratio - 1) / (k.time_ratio + 1), 2),
        "working_span": f(k.working_span * DEG, 2),
        "return_span": f(360 - k.working_span * DEG, 2),
        "start_angle": f((k.start_angle * DEG) % 360, 2),
        "grid_points": str(n),
        "kin_head": qual_head, "kin_rows": kin_rows,
        # the caption names the angle columns only where the table has them (review39)
        "kin_caption": _("Output motion, transmission and pressure angles at the positions") if qual_head
        else _("Output motion at the positions"),
        "angles_caption": _angles_caption(k, lang),
        "point_names": [md_point(p) for p in point_names], "point_rows": point_rows,
        "link_ids": [md_text(l_) for l_ in k.link_omega], "link_speed_rows": link_speed_rows,
        "qual_rows": qual_rows, "angles_head": angles_head, "angles_align": angles_align,
        # an angle the brief gives no limit for is listed unjudged: say so (page review 48:
        # slotter's pressure angle with "—" under "Allowed" and no word on it)
        "angles_note": ("" if all(row[5] != "—" for row in qual_rows) else
                        ("" if _.zh else " ") + _("An angle without an allowed value (“—”) is not "
                                                  "judged: the design brief gives none for it.")),
        "reaction_names": [f"$F_{{{tex_name(nm)}}}$" for nm in reaction_names],
        "force_rows": force_rows, "force_unit": force_unit_,
        "mb_max": sig(f_.torque_max, ref=f_.peak_torque),
        "mb_min": sig(f_.torque_min, ref=f_.peak_torque),
        "mb_mean": sig(f_.mean_torque), "mb_peak": sig(f_.peak_torque),
        "power": sig(f_.mean_power),
        "eq_power": (rf"P = \bar M_b\,\omega = {product((f_.mean_torque, omega), sig(f_.mean_power, group=False))} = "
                     rf"{sig(f_.mean_power, group=False)}\ \text{{W}}"),
        "has_forces": bool(model.bodies or model.resistances),
        "fly": None,
    }
    if fly is not None:
        ctx["fly"] = {
            "n": f(fly.shaft_speed_rpm, 2), "dw": sig(fly.max_energy_swing),
            "at_min": f(fly.phase_at_min * DEG, 1), "at_max": f(fly.phase_at_max * DEG, 1),
            "delta": fluctuation(fly.fluctuation), "jf": sig(fly.inertia),
            "eq": flywheel_equation(fly.max_energy_swing, fly.shaft_speed_rpm, fly.fluctuation,
                                    sig(fly.inertia, group=False)),
            "eq_note": carried_note(_, flywheel_carried(
                fly.max_energy_swing, fly.shaft_speed_rpm, fly.fluctuation, sig(fly.inertia, group=False),
                f(fly.shaft_speed_rpm, 2), sig(fly.max_energy_swing))),
            "rim": None, "real": realised_flywheel(fly, flywheel_realised_rpm, _),
            # the rim's findings (higher than its radius, too fast for cast iron): in the text
            # and, through the summary's findings, on its watch list
            "warnings": [md_text(w.text(lang)) for w in fly.warnings],
        }
        if fly.rim is not None:
            rim, spec = fly.rim, model.flywheel.rim
            j_mass = rim_inertia_factor(fly.inertia, rim)
            ctx["fly"]["rim"] = {
                "D": f(rim.diameter * 1e3, 0), "b": f(rim.width * 1e3, 1),
                "Hr": f(rim.height * 1e3, 1), "m": f(rim.rim_mass, 2), "speed": f(rim.rim_speed, 2),
                "hb": f(spec.height_to_width, 2), "gamma": f(spec.specific_weight, 0, group=True),
                "mass": (rf"m = \frac{{4 J_F}}{{D^2}} = \frac{{4 \times {j_mass}}}"
                         rf"{{{f(rim.diameter, 3)}^2}} = {f(rim.rim_mass, 2)}\ \text{{kg}}"),
                "mass_note": carried_note(_, [("J_F", sig(fly.inertia), j_mass)]),
                # the numbers substituted, as the shaper's chapter writes them (page review 41:
                # the press's γ, the rim material's specific weight, was never given a value)
                "width": rim_width_equation(model.gravity, sig(fly.inertia, group=False), rim.diameter,
                                            spec.height_to_width, spec.specific_weight, rim.width),
            }
    return ctx



def rim_width_equation(gravity: float, inertia: str, diameter: float, height_to_width: float,
                       specific_weight: float, width: float) -> str:
    """The cast rim's width with its numbers substituted (孙桓 §7: b = √(4 g J_F/(π D³ (H_F/b) γ)),
    SI inputs, b in mm); ``inertia`` is J_F as the report printed it. One equation for every
    machine's flywheel chapter (the linkage section, the shaper, the die-cutter)."""
    return (rf"b = \sqrt{{\frac{{4 g J_F}}{{\pi D^3 (H_F/b) \gamma}}}} = \sqrt{{\frac{{4 \times "
            rf"{f(gravity, 2)} \times {inertia}}}{{\pi \times {f(diameter, 3)}^3 \times "
            rf"{f(height_to_width, 2)} \times {f(specific_weight, 0)}}}}} = {f(width * 1e3, 1)}\ \text{{mm}}")


def verification_rows(v, lang: str, k=None) -> list[list[str]]:
    """The shared linkage checks as [item, result, reference, verdict] rows."""
    _ = tr(lang)

    def verdict(x, limit):
        return fmt_verdict(x <= limit, lang)

    rows = [
        [_("closure residual (max) / m"), e(v.closure_residual),
         "≤ 10⁻⁹", verdict(v.closure_residual, 1e-9)],
        [_("velocity vs central difference (relative)"),
         e(v.velocity_fd_error), f"O(h²), h = {f(v.fd_step * DEG, 3)}°",
         verdict(v.velocity_fd_error, 1e-3)],
        [_("acceleration vs central difference (relative)"),
         e(v.acceleration_fd_error), "O(h²)", verdict(v.acceleration_fd_error, 1e-3)],
    ]
    # no load and no mass: M_b ≡ 0 and the balance 0 = 0 checks nothing (review39: the lock-beam's
    # feed linkage showed "0, PASS", said to prove the reactions consistent)
    if v.power_balance_checked:
        rows.append([_(r"power balance $\Sigma P / \max\lvert M_b\,\omega\rvert$"),
                     e(v.power_balance_residual), "≤ 10⁻⁹", verdict(v.power_balance_residual, 1e-9)])
    if k is not None:
        scale, units = _units(k)
        # by the number rule (0.01 mm or °, K to 0.001), how closely they agree as the Δ beside
        # it (review45: "220.000 | 220.000", "1.2500 | 1.2500" showed digits, not the check)
        rows.append([_("stroke by position search / {unit}", unit=units[0]),
                     f"{f(v.stroke * scale, 2)} (Δ = {residue((v.stroke - k.stroke) * scale, k.stroke * scale)})",
                     f(k.stroke * scale, 2) + _(" (velocity zeros)"),
                     verdict(abs(v.stroke - k.stroke) / max(k.stroke, 1e-12), 1e-6)])
        rows.append([_("$K$ by position search"),
                     f"{time_ratio(v.time_ratio)} (Δ = {residue(v.time_ratio - k.time_ratio, k.time_ratio)})",
                     time_ratio(k.time_ratio), verdict(abs(v.time_ratio - k.time_ratio), 1e-6)])
    return rows


# ---------------------------------------------------------------- the `linkage` machine


