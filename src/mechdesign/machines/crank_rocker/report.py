"""Report of the crank-rocker synthesis (``machine: crank_rocker``): the design chart,
the θ-circle construction, γ(φ) from the simulation, the offset slider-crank, and the
context strings for ``templates/crank_rocker.md.j2``."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ...fileio import atomic_open
from ...render.figures import figure
from ...render.legends import legend
from ...render.fmt import e as fe
from ...render.fmt import residue, verdict
from ...render.fmt import f, md_meta, md_text, mpl_text, sig, time_ratio
from ...numbers import factors_for, half_sum_decimals, significant
from ...render.labels import LabelTable, mpl_label, mpl_point
from ...i18n import N_, Msg, tr

DEG = 180.0 / np.pi
MM = 1e3

LABELS = LabelTable({
    "psi": N_("rocker swing $\\psi$ (°)"),
    "ratio": N_(r"$l_3/l_4$ (optimum)"),
    "gamma_opt": N_(r"largest $\gamma_{min}$ (°)"),
    "theta": "θ",
    "ours": N_("this design"),
    "allowed": N_("allowed $[\\gamma]$"),
    "phi": N_("crank angle $\\varphi$ from the frame line AD (°)"),
    "phi_s": N_("crank angle $\\varphi$ from the guide direction (°)"),
    "gamma": N_("transmission angle $\\gamma$ (°)"),
    "rocker": N_("rocker angle (°)"),
    "w3": N_(r"rocker $\omega_3$ (rad/s)"),
    "a3": N_(r"rocker $\alpha_3$ (rad/s²)"),
    "x": "x (mm)",
    "y": "y (mm)",
    "circle": N_("$\\theta$-circle"),
    "arc": N_("allowed arc for A"),
    "frame_arc": N_(r"arc about D of radius $l_4$"),
    "textbook": N_("given-frame design A′"),
    "limit": N_(r"$\theta = 0$ is a limit (A at infinity)"),
    "alpha": N_("pressure angle α (°)"),
    "slow": N_("slow (working) stroke"),
    "fast": N_("fast (return) stroke"),
    "guide": N_("slider guide"),
    "optimum": N_("optimum"),
})


# ------------------------------------------------------------------------------ figures

def _chart(path: Path, lang: str, ch, mark, allowed_deg):
    lab = LABELS[lang]
    psi = ch.swings * DEG
    with figure(path, 2, (7.0, 6.4)) as (ax1, ax2):
        for i, th in enumerate(ch.thetas):
            ls = ":" if th == 0.0 else "-"
            name = f"θ = {th * DEG:g}°"
            ax1.plot(psi, ch.ratio[i], ls, lw=1.2, color=f"C{i % 10}", label=name)
            ax2.plot(psi, ch.gamma[i] * DEG, ls, lw=1.2, color=f"C{i % 10}", label=name)
        ax1.plot([mark[0]], [mark[1]], "k*", ms=9, zorder=5, label=lab["ours"])
        ax2.plot([mark[0]], [mark[2]], "k*", ms=9, zorder=5)
        ax2.axhline(allowed_deg, color="C3", lw=0.8, ls="--")
        ax2.text(psi[-1], allowed_deg + 1, f"{lab['allowed']} = {allowed_deg:g}°", color="C3",
                 fontsize=7, ha="right")
        ax1.set_ylabel(lab["ratio"])
        ax2.set_ylabel(lab["gamma_opt"])
        ax2.set_xlabel(lab["psi"])
        for ax in (ax1, ax2):
            ax.grid(True, lw=0.4, color="0.82")
            ax.set_xlim(psi[0], psi[-1])
        legend(ax1, fontsize=7, ncol=4, loc="lower right")
        if any(th == 0.0 for th in ch.thetas):
            ax1.text(0.01, 0.08, mpl_label(lab["limit"]), transform=ax1.transAxes, fontsize=7, color="0.35")


def _arc(ax, centre, radius, a0, a1, **kw):
    t = np.linspace(a0, a1, 120)
    z = centre + radius * np.exp(1j * t)
    ax.plot(z.real * MM, z.imag * MM, **kw)


def _label(ax, z, text, dx=0.0, dy=0.0, **kw):
    text = mpl_point(text)           # "B1" → B₁, "O" → O in math italic; "ψ" as written
    ax.text(z.real * MM + dx, z.imag * MM + dy, text, fontsize=8, **kw)


def _construction(path: Path, lang: str, opt, sim, textbook):
    lab = LABELS[lang]
    cons = opt.construction
    best = opt.best
    a_pt = best.a_pivot
    d_pt = 0j
    pts = sim.points
    # the folded extreme is the one with the shorter AC
    ac = np.abs(pts["C"] - pts["A"])
    i1, i2 = int(np.argmin(ac)), int(np.argmax(ac))
    with figure(path, 1, (6.6, 6.2)) as (ax,):
        ax.set_aspect("equal")
        # θ-circle and the allowed arc
        t = np.linspace(-np.pi, np.pi, 400)
        z = cons.point(t)
        ax.plot(z.real * MM, z.imag * MM, color="0.6", lw=0.8, label=lab["circle"])
        t = np.linspace(cons.p_lo, cons.p_hi, 200)
        z = cons.point(t)
        ax.plot(z.real * MM, z.imag * MM, color="C2", lw=2.4, alpha=0.6, label=mpl_label(lab["arc"]))
        ax.plot(cons.centre.real * MM, cons.centre.imag * MM, "+", color="0.4")
        _label(ax, cons.centre, "O", dx=1.0, dy=1.0, color="0.4")
        g = cons.point(cons.p_lo)
        ax.plot([cons.c2.real * MM, g.real * MM], [cons.c2.imag * MM, g.imag * MM], ":",
                color="0.5", lw=0.8)
        _label(ax, g, "G", dx=1.0, dy=-3.0, color="0.4")
        # chord, rocker arc, ψ
        ax.plot([cons.c1.real * MM, cons.c2.real * MM], [cons.c1.imag * MM, cons.c2.imag * MM],
                "--", color="0.4", lw=0.8)
        c = cons.rocker
        _arc(ax, d_pt, c, np.angle(cons.c1) - 0.1, np.angle(cons.c2) + 0.1, color="0.5", lw=0.6,
             ls="--")
        _arc(ax, d_pt, 0.25 * c, np.angle(cons.c1), np.angle(cons.c2), color="C3", lw=1.0)
        _label(ax, 0.3 * c * np.exp(1j * np.pi / 2), "ψ", color="C3", ha="center")
        # frame arc (textbook: arc about D of radius l4)
        ang_a = np.angle(a_pt)
        _arc(ax, d_pt, abs(a_pt), ang_a - 0.25, ang_a + 0.25, color="C4", lw=0.8, ls="-.",
             label=mpl_label(lab["frame_arc"]))
        # the linkage at its two extremes
        for k, col, suffix in ((i1, "C0", "1"), (i2, "C1", "2")):
            chain = np.array([pts["A"][k], pts["B"][k], pts["C"][k], pts["D"][k]])
            ax.plot(chain.real * MM, chain.imag * MM, "-o", color=col, lw=1.8, ms=3.5)
            _label(ax, pts["B"][k], f"B{suffix}", dx=1.2, dy=1.2, color=col)
            _label(ax, pts["C"][k], f"C{suffix}", dx=1.2, dy=1.2, color=col)
        # rays A–C1, A–C2 and the angle θ between them
        for cc in (cons.c1, cons.c2):
            ax.plot([a_pt.real * MM, cc.real * MM], [a_pt.imag * MM, cc.imag * MM], color="0.3",
                    lw=0.6)
        # the arc between the crank pin's circle (B₂ lies on the ray A–C₂) and C: its label
        # stood on B₂'s (page review 48)
        crank = best.design.crank
        r_th = crank + 0.5 * (min(abs(cons.c1 - a_pt), abs(cons.c2 - a_pt)) - crank)
        a1, a2 = np.angle(cons.c1 - a_pt), np.angle(cons.c2 - a_pt)
        lo, hi = min(a1, a2), max(a1, a2)
        _arc(ax, a_pt, r_th, lo, hi, color="C3", lw=1.0)
        mid = a_pt + 1.15 * r_th * np.exp(1j * (lo + hi) / 2)
        _label(ax, mid, "θ", color="C3", ha="center", va="center")
        # crank circle
        _arc(ax, a_pt, crank, 0, 2 * np.pi, color="0.6", lw=0.6, ls=":")
        ax.plot([a_pt.real * MM, 0.0], [a_pt.imag * MM, 0.0], color="k", lw=1.2)
        for zz, name in ((a_pt, "A"), (d_pt, "D")):
            ax.plot(zz.real * MM, zz.imag * MM, "ks", ms=5)
            _label(ax, zz, name, dx=1.5, dy=-4.0)
        if textbook is not None:
            tp = textbook.a_pivot
            ax.plot(tp.real * MM, tp.imag * MM, "^", color="C4", ms=6, label=mpl_label(lab["textbook"]))
        ax.set_xlabel(lab["x"])
        ax.set_ylabel(lab["y"])
        ax.grid(True, lw=0.3, color="0.88")
        legend(ax, fontsize=7, loc="lower left")


def _wrap(phi, *ys):
    """φ [rad] wrapped to [−180°, 180°) in degrees, sorted, with the series reordered."""
    x = (np.asarray(phi) * DEG + 180.0) % 360.0 - 180.0
    k = np.argsort(x)
    return (x[k],) + tuple(np.asarray(y)[k] for y in ys)


def _motion(path: Path, lang: str, sims, allowed_deg, with_speed: bool):
    lab = LABELS[lang]
    n = 3 if with_speed else 2
    opt = sims[0]
    with figure(path, n, (7.0, 2.4 * n + 0.6)) as axes:
        ax = axes[0]
        for i, s in enumerate(sims):
            x, y = _wrap(s.phi, s.gamma * DEG)
            ax.plot(x, y, lw=1.6 if i == 0 else 0.9, color=f"C{i}", label=mpl_text(_name(s.label, lang)))
        xg = float(_wrap([opt.phi_gamma_min])[0][0])
        ax.plot(xg, opt.gamma_min * DEG, "o", color="C3", ms=5)
        ax.annotate(f"$\\gamma_{{min}}$ = {opt.gamma_min * DEG:.2f}°", (xg, opt.gamma_min * DEG),
                    xytext=(8, -14), textcoords="offset points", fontsize=8, color="C3")
        ax.axhline(allowed_deg, color="C3", lw=0.8, ls="--")
        ax.set_ylabel(lab["gamma"])
        legend(ax, fontsize=7, loc="upper right")
        ax = axes[1]
        ax.plot(*_wrap(opt.phi, opt.rocker_angle * DEG), color="C0", lw=1.4)
        for x in _wrap(list(opt.phi_extremes))[0]:
            ax.axvline(x, color="0.5", lw=0.6, ls=":")
        ax.set_ylabel(lab["rocker"])
        if with_speed:
            axes[2].plot(*_wrap(opt.phi, opt.omega3), color="C0", lw=1.4)
            axes[2].set_ylabel(lab["w3"])
            axes[2].axhline(0, color="0.4", lw=0.6)
        for ax in axes:
            ax.set_xlim(-180, 180)
            ax.set_xticks(np.arange(-180, 181, 30))
            ax.grid(True, lw=0.4, color="0.82")
        axes[-1].set_xlabel(mpl_label(lab["phi"]))


def _slider(path: Path, lang: str, sl, ss, allowed_deg):
    lab = LABELS[lang]
    cons = sl.construction
    with figure(path, 2, (7.0, 7.4), sharex=False) as (ax, ax2):
        ax.set_aspect("equal")
        a_pt = 0j
        y_g = cons.c1.imag         # the guide through the slider's extremes (A is e below it)
        xs = np.array([min(cons.c1.real, -sl.crank) - 0.1 * sl.stroke, cons.c2.real + 0.15 * sl.stroke])
        ax.plot(xs * MM, [y_g * MM] * 2, color="0.3", lw=0.8, ls="-.", label=lab["guide"])
        t = np.linspace(0, 2 * np.pi, 400)
        z = cons.centre + cons.radius * np.exp(1j * t)
        ax.plot(z.real * MM, z.imag * MM, color="0.6", lw=0.8, label=lab["circle"])
        for cc, bb, col, name in ((cons.c1, -sl.crank * cons.c1 / abs(cons.c1), "C0", "1"),
                                  (cons.c2, sl.crank * cons.c2 / abs(cons.c2), "C1", "2")):
            ax.plot([0, bb.real * MM, cc.real * MM], [0, bb.imag * MM, cc.imag * MM], "-o",
                    color=col, lw=1.8, ms=3.5)
            ax.plot([cc.real * MM], [cc.imag * MM], "s", color=col, ms=7, mfc="none")
            _label(ax, bb, f"B{name}", dx=1.5, dy=1.5, color=col)
            _label(ax, cc, f"C{name}", dx=0.0, dy=-9.0, color=col, ha="center")
        _arc(ax, a_pt, sl.crank, 0, 2 * np.pi, color="0.6", lw=0.6, ls=":")
        r_th = 0.3 * abs(cons.c1)
        a1, a2 = np.angle(cons.c1), np.angle(cons.c2)
        _arc(ax, a_pt, r_th, min(a1, a2), max(a1, a2), color="C3", lw=1.0)
        _label(ax, 1.2 * r_th * np.exp(1j * (a1 + a2) / 2), "θ", color="C3", ha="center", va="center")
        ax.plot([0, 0], [0, y_g * MM], color="C4", lw=0.8, ls="--")
        _label(ax, complex(0, y_g / 2), "e", dx=1.5, color="C4")
        ax.plot(0, 0, "ks", ms=5)
        _label(ax, a_pt, "A", dx=-6, dy=2)
        pad = 0.25 * sl.stroke
        ax.set_xlim((min(cons.c1.real, -sl.crank) - pad) * MM, (cons.c2.real + pad) * MM)
        ax.set_ylim((min(-sl.crank, y_g) - pad) * MM, (max(sl.crank, y_g) + pad) * MM)
        ax.set_xlabel(lab["x"])
        ax.set_ylabel(lab["y"])
        ax.grid(True, lw=0.3, color="0.88")
        legend(ax, fontsize=7, loc="upper left")
        phi = ss.phi * DEG
        alpha = ss.alpha * DEG
        ax2.plot(phi, np.where(ss.slow, alpha, np.nan), color="C0", lw=1.6, label=lab["slow"])
        ax2.plot(phi, np.where(~ss.slow, alpha, np.nan), color="C1", lw=1.6, label=lab["fast"])
        ax2.axhline(allowed_deg, color="C3", lw=0.8, ls="--")
        ax2.text(355, allowed_deg + 1, f"[α] = {allowed_deg:g}°", color="C3", fontsize=7, ha="right")
        ax2.set_xlim(0, 360)
        ax2.set_xticks(np.arange(0, 361, 30))
        ax2.grid(True, lw=0.4, color="0.82")
        ax2.set_xlabel(lab["phi_s"])
        ax2.set_ylabel(lab["alpha"])
        legend(ax2, fontsize=7, loc="upper right")


def make_figures(r: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    p = r["params"]
    opt = r["optimum"]
    ver = r["verify"]
    out = {}
    mark = (p.swing * DEG, p.rocker / opt.best.design.frame, opt.best.gamma_min * DEG)
    _chart(fig_dir / "chart.png", lang, r["chart"], mark, p.gamma_allowed * DEG)
    out["chart"] = f"{fig_dir.name}/chart.png"
    _construction(fig_dir / "construction.png", lang, opt, ver.sims[0], r.get("textbook"))
    out["construction"] = f"{fig_dir.name}/construction.png"
    _motion(fig_dir / "motion.png", lang, ver.sims, p.gamma_allowed * DEG,
            p.crank_speed_rpm is not None)
    out["motion"] = f"{fig_dir.name}/motion.png"
    if r.get("slider") is not None:
        _slider(fig_dir / "slider.png", lang, r["slider"], ver.slider, 90 - p.gamma_allowed * DEG)
        out["slider"] = f"{fig_dir.name}/slider.png"
    return out


# ------------------------------------------------------------------------------ context

def _mm(x: float, d: int = 2) -> str:
    """A length in mm by the number rule (0.01 mm)."""
    return f(x * MM, d)


def _deg(x: float, d: int = 2) -> str:
    """An angle in degrees by the number rule (0.01°)."""
    return f(x * DEG, d)


def _cos(x: float) -> str:
    """A cosine in a formula: 4 significant digits (the rule's intermediate values)."""
    return sig(x, 4, group=False)


def _gamma_eqs(d) -> tuple[str, str, list[float]]:
    """LaTeX of the two collinear-position transmission angles with numbers, and the two
    angles δ′, δ″ [°] as they print.

    The lengths are substituted as the lines above print them (0.01 mm: l₂ = 42.40, never
    42.40 in one line and 42.395 in the next, review 38) and the cosine and the angle follow
    from them (a chain computes from what it prints): −0.1447 and 98.32°, where the unrounded
    lengths give 98.33°. Only where the angle that is γ_min would then print otherwise than
    γ_min does (the table and the text quote it) the lengths get the fewest more digits
    that give the cosine of the unrounded lengths."""
    a, b, c, l4 = (x * MM for x in (d.crank, d.coupler, d.rocker, d.frame))
    c1 = (b * b + c * c - (l4 - a) ** 2) / (2 * b * c)
    c2 = (b * b + c * c - (l4 + a) ** 2) / (2 * b * c)
    true = [float(np.degrees(np.arccos(np.clip(x, -1, 1)))) for x in (c1, c2)]
    binding = 0 if min(true[0], 180 - true[0]) <= min(true[1], 180 - true[1]) else 1
    out, angles = [], []
    for k, (sign, cos, name) in enumerate(((-1, c1, "'"), (1, c2, "''"))):
        def fn(b_, c_, l_, a_, s=sign):
            return (b_ * b_ + c_ * c_ - (l_ + s * a_) ** 2) / (2 * b_ * c_)
        texts = [f(x, 2) for x in (b, c, l4, a)]
        cos_txt = _cos(fn(*(float(t) for t in texts)))
        angle = float(np.degrees(np.arccos(np.clip(float(cos_txt), -1, 1))))
        if k == binding and f(angle, 2) != f(true[k], 2):
            texts = factors_for((b, c, l4, a), fn, _cos(cos),
                                tuple(significant(f(x, 2)) for x in (b, c, l4, a)))
            cos_txt, angle = _cos(cos), true[k]
        bb, cc, ll, aa = texts
        op = "-" if sign < 0 else "+"
        out.append(rf"\cos\delta{name} = \frac{{{bb}^2 + {cc}^2 - ({ll} {op} {aa})^2}}{{2 \times {bb} "
                   rf"\times {cc}}} = {cos_txt},\quad \delta{name} = {f(angle, 2)}^\circ")
        angles.append(angle)
    return out[0], out[1], angles


def _cosines(d) -> tuple[float, float]:
    a, b, c, l4 = d.crank, d.coupler, d.rocker, d.frame
    return ((b * b + c * c - (l4 - a) ** 2) / (2 * b * c), (b * b + c * c - (l4 + a) ** 2) / (2 * b * c))


def _name(label: str, lang: str) -> str:
    """A design's name in the report's language: the program's (a catalogue message), or the
    part of the brief's '中文 / english' label."""
    if isinstance(label, Msg):
        return label.text(lang)
    if " / " in label:
        zh, en = label.split(" / ", 1)
        return zh if lang == "zh" else en
    return label


def _kind(grashof: str, lang: str) -> str:
    """The Grashof type of a four-bar in the report's words (曲柄摇杆机构, crank-rocker)."""
    from .stages import _kinds

    kind = _kinds().get(grashof)
    return grashof if kind is None else kind.text(lang)


def _printed(design) -> dict | None:
    """A compared design's lengths as its source prints them (the brief's digits, ``16.2227``)
    when they have more decimals than the rule's 0.01 mm, else None."""
    out = {k: f"{getattr(design, a) * MM:.6g}" for k, a in (("l1", "crank"), ("l2", "coupler"),
                                                            ("l4", "frame"))}
    return out if any(len(v.partition(".")[2]) > 2 for v in out.values()) else None


def _with_diff(value: str, diff: float, lang: str) -> str:
    """A simulated value to 4 decimals with its difference from the reference (the verdict
    needs |Δ| < 10⁻⁹, which 4 decimals cannot show)."""
    _ = tr(lang)
    return _("{value} ($\\Delta$ = {diff})", value=value, diff=residue(diff))


def _verdict(ok: bool, lang: str) -> str:
    return verdict(ok, lang)


def context(r: dict, brief, figures: dict[str, str], lang: str) -> dict:
    _ = tr(lang)
    p = r["params"]
    opt = r["optimum"]
    cons = opt.construction
    best = opt.best
    tb = r.get("textbook")
    ver = r["verify"]
    th_deg = p.theta * DEG
    chord = abs(cons.c1 - cons.c2)
    eq = {}
    if p.K_given:
        eq["theta"] = (rf"\theta = 180^\circ\frac{{K - 1}}{{K + 1}} = 180^\circ \times "
                       rf"\frac{{{time_ratio(p.K)} - 1}}{{{time_ratio(p.K)} + 1}} = {f(th_deg, 2)}^\circ")
    else:
        eq["theta"] = (rf"K = \frac{{180^\circ + \theta}}{{180^\circ - \theta}} = "
                       rf"\frac{{180^\circ + {f(th_deg, 2)}^\circ}}{{180^\circ - {f(th_deg, 2)}^\circ}}"
                       rf" = {time_ratio(p.K)}")
    eq["chord"] = (rf"\overline{{C_1C_2}} = 2 l_3 \sin\frac{{\psi}}{{2}} = 2 \times {_mm(p.rocker, 2)}"
                   rf" \times \sin {f(p.swing * DEG / 2, 2)}^\circ = {_mm(chord)}\ \text{{mm}}")
    eq["radius"] = (rf"R = \frac{{\overline{{C_1C_2}}}}{{2\sin\theta}} = \frac{{{_mm(chord)}}}"
                    rf"{{2 \sin {f(th_deg, 2)}^\circ}} = {_mm(cons.radius)}\ \text{{mm}}")
    eq["centre"] = (rf"\overline{{OM}} = R\cos\theta = {_mm(cons.radius * np.cos(p.theta))}\ \text{{mm}}")
    eq["lengths"] = (r"l_1 = \frac{\overline{AC_2} - \overline{AC_1}}{2},\qquad "
                     r"l_2 = \frac{\overline{AC_2} + \overline{AC_1}}{2},\qquad l_4 = \overline{AD}")
    eq["gamma_min"] = r"\gamma_{min} = \min(\delta',\ 180^\circ - \delta'')"
    eq["gamma"] = (r"\cos\delta' = \frac{l_2^2 + l_3^2 - (l_4 - l_1)^2}{2 l_2 l_3},\quad "
                   r"\cos\delta'' = \frac{l_2^2 + l_3^2 - (l_4 + l_1)^2}{2 l_2 l_3}")
    eq["arc"] = (rf"A(t) = O + R\,(\sin t,\ -\cos t),\qquad t_G = {_deg(cons.p_lo)}^\circ < t"
                 rf" < 180^\circ - \theta = {_deg(cons.p_hi)}^\circ")
    eq["problem"] = (r"\max_{t_G < t < 180^\circ - \theta}\ \gamma_{min}(t) = "
                     r"\max_t\ \min\bigl(\delta'(t),\ 180^\circ - \delta''(t)\bigr)")
    g1, g2, opt_angles = _gamma_eqs(best.design)
    eq["opt_d1"], eq["opt_d2"] = g1, g2
    ac1 = abs(best.a_pivot - cons.c1)
    ac2 = abs(best.a_pivot - cons.c2)
    nd = half_sum_decimals((ac1 * MM, ac2 * MM))
    eq["opt_l1"] = (rf"l_1 = \frac{{{_mm(ac2, nd)} - {_mm(ac1, nd)}}}{{2}} = {_mm(best.design.crank)}\ \text{{mm}}")
    eq["opt_l2"] = (rf"l_2 = \frac{{{_mm(ac2, nd)} + {_mm(ac1, nd)}}}{{2}} = {_mm(best.design.coupler)}\ \text{{mm}}")
    textbook = None
    if tb is not None:
        t1 = abs(tb.a_pivot - cons.c1)
        t2 = abs(tb.a_pivot - cons.c2)
        d1, d2, _angles = _gamma_eqs(tb.design)
        nt = half_sum_decimals((t1 * MM, t2 * MM))
        textbook = {
            "frame": _mm(p.frame, 2), "ac1": _mm(t1, nt), "ac2": _mm(t2, nt),
            "t": "—" if tb.position is None else _deg(tb.position),
            "l1": (rf"l_1 = \frac{{{_mm(t2, nt)} - {_mm(t1, nt)}}}{{2}} = {_mm(tb.design.crank)}\ \text{{mm}}"),
            "l2": (rf"l_2 = \frac{{{_mm(t2, nt)} + {_mm(t1, nt)}}}{{2}} = {_mm(tb.design.coupler)}\ \text{{mm}}"),
            "d1": d1, "d2": d2, "gamma_min": _deg(tb.gamma_min),
            "kind": _kind(tb.grashof, lang),
        }
    given = None
    if p.given is not None:
        g = p.given
        a, b, c, d = (x * MM for x in (g.crank, g.coupler, g.rocker, g.frame))

        def ang(x, y, z):
            return float(np.degrees(np.arccos(np.clip((x * x + y * y - z * z) / (2 * x * y), -1, 1))))
        dac1, dac2 = ang(b - a, d, c), ang(b + a, d, c)
        adc1, adc2 = ang(d, c, b - a), ang(d, c, b + a)
        given = {
            "l1": f(a, 2), "l2": f(b, 2), "l3": f(c, 2), "l4": f(d, 2),
            "kind": _kind(tb.grashof, lang) if tb is not None else "",
            "eq_dac": (rf"\angle DAC_1 = \arccos\frac{{(l_2 - l_1)^2 + l_4^2 - l_3^2}}{{2(l_2 - l_1)l_4}}"
                       rf" = {f(dac1, 2)}^\circ"),
            "eq_dac2": (rf"\angle DAC_2 = \arccos\frac{{(l_2 + l_1)^2 + "
                        rf"l_4^2 - l_3^2}}{{2(l_2 + l_1)l_4}} = {f(dac2, 2)}^\circ"),
            "eq_adc": (rf"\angle ADC_1 = \arccos\frac{{l_4^2 + l_3^2 - (l_2 - l_1)^2}}{{2l_4l_3}}"
                       rf" = {f(adc1, 2)}^\circ,\quad \angle ADC_2 = {f(adc2, 2)}^\circ"),
            "eq_theta": (rf"\theta = \lvert\angle DAC_1 - \angle DAC_2\rvert = {f(th_deg, 2)}^\circ,"
                         rf"\qquad \psi = \angle ADC_2 - \angle ADC_1 = {_deg(p.swing)}^\circ"),
            "eq_K": (rf"K = \frac{{180^\circ + \theta}}{{180^\circ - \theta}} = {time_ratio(p.K)}"),
            "gamma_min": _deg(tb.gamma_min) if tb is not None else "",
        }
    # data table
    if given is not None:
        data_rows = [[s_, _(n), v, u] for s_, n, v, u in (
            ("$l_1$", N_("crank $AB$ (given)"), given["l1"], "mm"),
            ("$l_2$", N_("coupler $BC$ (given)"), given["l2"], "mm"),
            ("$l_3$", N_("rocker $CD$ (given)"), given["l3"], "mm"),
            ("$l_4$", N_("frame $AD$ (given)"), given["l4"], "mm"),
            ("$\\theta$", N_("extreme-position angle (derived)"), f(th_deg, 2), "°"),
            ("$K$", N_("time ratio (derived)"), time_ratio(p.K), "—"),
            ("$\\psi$", N_("rocker swing (derived)"), _deg(p.swing), "°"),
            ("$\\gamma_{min}$", N_("minimum transmission angle (derived)"), given["gamma_min"], "°"),
            ("$[\\gamma]$", N_("allowed minimum transmission angle"), _deg(p.gamma_allowed, 0), "°"))]
    else:
        data_rows = [["$K$", _("time ratio"), time_ratio(p.K), "—"],
                     ["$\\theta$", _("extreme-position angle"), f(th_deg, 2), "°"],
                     ["$\\psi$", _("rocker swing"), _deg(p.swing, 2), "°"], ["$l_3$", _.pgettext("given length", "rocker $CD$"), _mm(p.rocker, 2), "mm"]]
        if p.frame is not None:
            data_rows.append(["$l_4$", _("given frame $AD$ (textbook method)"), _mm(p.frame, 2), "mm"])
        data_rows.append(["$[\\gamma]$", _("allowed minimum transmission angle"), _deg(p.gamma_allowed, 0), "°"])
    if p.crank_speed_rpm is not None:
        data_rows.append(["$n_1$", _("crank speed (motion curves only)"), f(p.crank_speed_rpm, 1), _("rpm")])
    # comparison of designs: lengths and simulated θ, ψ, K, γmin
    designs = [best] + ([tb] if tb is not None else []) + list(r["compare"])
    cmp_rows = []
    for d, s in zip(designs, ver.sims):
        cmp_rows.append([md_text(_name(s.label, lang)), _mm(d.design.crank), _mm(d.design.coupler), _mm(d.design.rocker),
                         _mm(d.design.frame), _deg(s.theta), _deg(s.swing), time_ratio(s.K),
                         _deg(s.gamma_min)])
    spec_row = [_("specification"), "", "", _mm(p.rocker), "",
                f(th_deg, 2), _deg(p.swing), time_ratio(p.K), ""]
    paper_notes = []
    missing = []
    n_cmp = len(r["compare"])
    for cd, s in zip(p.compare, ver.sims[len(designs) - n_cmp:]):
        dth, dpsi = (s.theta - p.theta) * DEG, (s.swing - p.swing) * DEG
        dg = (best.gamma_min - s.gamma_min) * DEG
        if abs(dth) > 1e-6 or abs(dpsi) > 1e-6:
            missing.append(md_text(_name(s.label, lang)))
        name = md_text(_name(s.label, lang))
        printed = _printed(cd.design)
        if printed is not None:      # the table rounds the lengths to 0.01 mm: say what was printed
            name += _(" (the paper prints $l_1$ = {l1} mm, $l_2$ = {l2} mm, $l_4$ = {l4} mm)", **printed)
        paper_notes.append(_("{name}: $\\theta$ off by {dth}°, $\\psi$ off by {dpsi}°, $\\gamma_{{min}}$ {dg}° below the optimum",
                             name=name, dth=f(dth, 2), dpsi=f(dpsi, 2), dg=f(dg, 2)))
    # verification rows: [item, result, reference, verdict]
    tol = 1e-9
    vrows = []
    for d, s in zip(designs, ver.sims):
        if d is not best and d is not tb:
            continue
        name = md_text(_name(s.label, lang))
        for item, val, ref, err in (
                # by the number rule (K 0.001, angles 0.01°); the difference Δ beside the
                # value says how closely they agree
                (N_("simulated $K$"), f(s.K, 3), f(p.K, 3), s.K - p.K),
                (N_("simulated $\\theta$ /°"), _deg(s.theta), f(th_deg, 2), s.theta - p.theta),
                (N_("simulated $\\psi$ /°"), _deg(s.swing), _deg(p.swing), s.swing - p.swing),
                (N_("simulated $\\gamma_{min}$ /° (ref.: closed form)"),
                 _deg(s.gamma_min), _deg(d.gamma_min), s.gamma_min - d.gamma_min)):
            vrows.append([_("{name}: {item}", name=name, item=_(item)), _with_diff(val, err, lang), ref,
                          _verdict(abs(err) < tol, lang)])
        vrows.append([_("{name}: {item}", name=name, item=_("loop-closure residual /m")),
                      residue(s.closure), "0", _verdict(s.closure < 1e-12, lang)])
    # the design requirement itself, with its verdict (review45: [γ] = 40° was given and
    # never judged): the optimum's γ_min against [γ]
    vrows.append([_("{name}: {item}", name=md_text(_name(ver.sims[0].label, lang)),
                    item=_("$\\gamma_{min}$ against $[\\gamma]$ /°")),
                  _deg(best.gamma_min), f"≥ {_deg(p.gamma_allowed, 0)}",
                  _verdict(best.gamma_min >= p.gamma_allowed - 1e-12, lang)])
    n0, n1 = ver.optimum_neighbours
    vrows.append([_("$\\gamma_{min}(t^* \\mp 0.001\\,\\mathrm{arc}) - \\gamma_{min}^*$ /°"),
                  f"{fe((n0 - best.gamma_min) * DEG)}, {fe((n1 - best.gamma_min) * DEG)}", "< 0",
                  _verdict(n0 < best.gamma_min and n1 < best.gamma_min, lang)])
    vrows.append([_("largest $\\gamma_{min}$ of a 200 000-point scan − $\\gamma_{min}^*$ /°"),
                  fe((ver.optimum_scan - best.gamma_min) * DEG), "≤ 0",
                  _verdict(ver.optimum_scan <= best.gamma_min + 1e-12, lang)])
    slider = None
    if r.get("slider") is not None:
        sl, ss = r["slider"], ver.slider
        sc = sl.construction
        e_mm, h_mm = sl.offset * MM, sl.stroke * MM
        # x_A with R and R cos θ carrying the digits that give the printed x_A (e is given)
        xa = f(-np.sqrt(sc.radius ** 2 - (sc.radius * np.cos(sl.theta) - sl.offset) ** 2) * MM, 2)
        xa_r, xa_c = factors_for(
            (sc.radius * MM, sc.radius * np.cos(sl.theta) * MM),
            lambda r_, c_: -np.sqrt(r_ ** 2 - (c_ - float(f(e_mm, 2))) ** 2), xa,
            tuple(significant(_mm(x)) for x in (sc.radius, sc.radius * np.cos(sl.theta))))
        # AC₁, AC₂ with the decimals that make (AC₂ ± AC₁)/2 no half unit (review 38)
        ns = half_sum_decimals((abs(sc.c1) * MM, abs(sc.c2) * MM))
        slider = {
            "K": time_ratio(sl.K), "theta": _deg(sl.theta), "H": f(h_mm, 2), "e": f(e_mm, 2),
            "R": _mm(sc.radius), "ac1": _mm(abs(sc.c1), ns), "ac2": _mm(abs(sc.c2), ns),
            "a": _mm(sl.crank), "b": _mm(sl.rod),
            "eq_theta": (rf"\theta = 180^\circ\frac{{K - 1}}{{K + 1}} = 180^\circ \times "
                         rf"\frac{{{time_ratio(sl.K)} - 1}}{{{time_ratio(sl.K)} + 1}} = {_deg(sl.theta)}^\circ"),
            "eq_R": (rf"R = \frac{{H}}{{2\sin\theta}} = \frac{{{f(h_mm, 2)}}}{{2\sin {_deg(sl.theta)}^\circ}}"
                     rf" = {_mm(sc.radius)}\ \text{{mm}}"),
            "eq_x": (rf"x_A = -\sqrt{{R^2 - (R\cos\theta - e)^2}} = -\sqrt{{{xa_r}^2 - "
                     rf"({xa_c} - {f(e_mm, 2)})^2}} = {xa}"
                     r"\ \text{mm}"),
            "eq_limit": (rf"e < H\cot\theta = {f(h_mm / np.tan(sl.theta), 2)}\ \text{{mm}}"),
            "eq_a": (rf"a = \frac{{\overline{{AC_2}} - \overline{{AC_1}}}}{{2}} = \frac{{{_mm(abs(sc.c2), ns)} - "
                     rf"{_mm(abs(sc.c1), ns)}}}{{2}} = {_mm(sl.crank)}\ \text{{mm}}"),
            "eq_b": (rf"b = \frac{{\overline{{AC_2}} + \overline{{AC_1}}}}{{2}} = "
                      rf"\frac{{{_mm(abs(sc.c2), ns)} + {_mm(abs(sc.c1), ns)}}}{{2}} = {_mm(sl.rod)}\ \text{{mm}}"),
            "eq_alpha_fast": (rf"\alpha_{{max}} = \arcsin\frac{{a + e}}{{b}} = \arcsin\frac{{{_mm(sl.crank)} + "
                              rf"{f(e_mm, 2)}}}{{{_mm(sl.rod)}}} = {_deg(sl.alpha_fast)}^\circ"),
            "eq_alpha_slow": (rf"\alpha_{{w}} = \max\Bigl(\arcsin\frac{{e}}{{b - a}},\ \arcsin\frac{{|a - e|}}{{b}}\Bigr)"
                              rf" = {_deg(sl.alpha_slow)}^\circ"),
            "alpha_slow": _deg(sl.alpha_slow, 2), "alpha_fast": _deg(sl.alpha_fast, 2),
            "given": p.slider.crank is not None,
            "eq_H": (rf"H = \sqrt{{(b + a)^2 - e^2}} - \sqrt{{(b - a)^2 - e^2}} = {_mm(sl.stroke)}"
                     r"\ \text{mm}"),
            "eq_th": (rf"\theta = \arcsin\frac{{e}}{{b - a}} - \arcsin\frac{{e}}{{b + a}} = "
                      rf"{_deg(sl.theta)}^\circ,\qquad K = \frac{{180^\circ + \theta}}{{180^\circ - \theta}}"
                      rf" = {time_ratio(sl.K)}"),
            "allowed": _deg(sl.alpha_allowed, 0),
        }
        # the section's own data in the data table (page review 48: K, H, e came first in
        # section 4, in no table and not in the task)
        part = _.pgettext("data table", "offset slider-crank")
        data_rows += ([["$a, b$", _("{part}: crank, rod (given)", part=part),
                        f"{_mm(sl.crank)}, {_mm(sl.rod)}", "mm"]] if slider["given"] else
                      [["$K$", _("{part}: time ratio", part=part), time_ratio(sl.K), "—"],
                       ["$H$", _("{part}: stroke", part=part), f(h_mm, 2), "mm"]])
        data_rows.append(["$e$", _("{part}: offset", part=part), f(e_mm, 2), "mm"])
        slider_name = _.pgettext("verification item", "offset slider-crank")
        for item, val, ref, err in (
                (N_("simulated stroke $H$ /mm"), _mm(ss.stroke), f(h_mm, 2),
                 (ss.stroke - sl.stroke) / sl.stroke),
                (N_("simulated $K$"), f(ss.K, 3), f(sl.K, 3), ss.K - sl.K),
                (N_("simulated slow-stroke $\\alpha_{max}$ /° (ref.: closed form)"),
                 _deg(ss.alpha_slow), _deg(sl.alpha_slow), ss.alpha_slow - sl.alpha_slow),
                (N_("simulated fast-stroke $\\alpha_{max}$ /° (ref.: closed form)"),
                 _deg(ss.alpha_fast), _deg(sl.alpha_fast), ss.alpha_fast - sl.alpha_fast)):
            vrows.append([_("{name}: {item}", name=slider_name, item=_(item)),
                          _with_diff(val, err, lang), ref, _verdict(abs(err) < tol, lang)])
        vrows.append([_("{name}: {item}", name=slider_name, item=_("loop-closure residual /m")),
                      residue(ss.closure), "0", _verdict(ss.closure < 1e-12, lang)])
        vrows.append([_("{name}: {item}", name=slider_name,
                        item=_("working-stroke $\\alpha_{max}$ against $90° - [\\gamma]$ /°")),
                      _deg(sl.alpha_slow), f"≤ {_deg(sl.alpha_allowed, 0)}",
                      _verdict(sl.alpha_slow <= sl.alpha_allowed + 1e-12, lang)])
    findings = []
    for key in ("optimum", "textbook", "slider"):
        v = r.get(key)
        for w in getattr(v, "warnings", None) or ():
            text = md_text(w.text(lang))
            if text not in findings:
                findings.append(text)
    far = opt.far_side_gamma
    ch = r["chart"]
    d1, d2 = (np.degrees(x) for x in (np.arccos(np.clip(c, -1, 1)) for c in _cosines(best.design)))
    g1, g2 = min(d1, 180 - d1), min(d2, 180 - d2)
    # the other collinear position's angle as the optimum's equations print its δ
    other = max(min(x, 180 - x) for x in opt_angles)
    if abs(g1 - g2) < 1e-6:
        where = _("The transmission angles of both collinear positions are equal (the maximum of "
                  "$\\gamma_{min}(t)$ is the kink where the two curves cross).")
    else:
        where = (_("The minimum occurs where the crank overlaps the frame (the other collinear position "
                   "has {other}°): {gamma} has a smooth maximum at the optimum, not the kink where the "
                   "two collinear angles are equal.", other=f(other, 2), gamma="$\\gamma_{min}(t)$")
                 if g1 < g2 else
                 _("The minimum occurs where the crank extends the frame (the other collinear position "
                   "has {other}°): {gamma} has a smooth maximum at the optimum, not the kink where the "
                   "two collinear angles are equal.", other=f(other, 2), gamma="$\\gamma_{min}(t)$"))
    return {
        "meta": md_meta(brief.report, lang), "fig": figures, "data_rows": data_rows, "eq": eq,
        "K": time_ratio(p.K), "theta": f(th_deg, 2), "psi": _deg(p.swing, 2), "l3": _mm(p.rocker, 2),
        "K_given": p.K_given,
        "opt": {"l1": _mm(best.design.crank), "l2": _mm(best.design.coupler),
                "l3": _mm(best.design.rocker), "l4": _mm(best.design.frame),
                "ratio": sig(best.design.rocker / best.design.frame, 4),
                "gamma_min": _deg(best.gamma_min), "t": _deg(best.position),
                "ac1": _mm(ac1, nd), "ac2": _mm(ac2, nd), "kind": _kind(best.grashof, lang),
                "far": None if far is None else _deg(far, 2), "where": where},
        "with_speed": p.crank_speed_rpm is not None,
        "textbook": textbook, "given": given,
        # the offset slider-crank of its own section named in the task (page review 48)
        "slider_task": ("" if slider is None else ("" if _.zh else " ") + _(
            "Then design an offset slider-crank for the data of the table's last rows (section "
            "“Offset slider-crank”).")),
        "cmp_head": [_.pgettext("table head", "design"), "$l_1$/mm", "$l_2$/mm", "$l_3$/mm", "$l_4$/mm", "$\\theta$/°", "$\\psi$/°",
                     "$K$", "$\\gamma_{min}$/°"],
        "cmp_rows": cmp_rows + [spec_row], "cmp_align": "|".join([":--"] + ["--:"] * 8),
        "paper_notes": paper_notes, "compare_miss": _.pgettext("list", ", ").join(missing), "has_compare": bool(r["compare"]),
        "chart": {"thetas": ", ".join(f"{t * DEG:g}°" for t in ch.thetas),
                  "from": f(ch.swings[0] * DEG, 0), "to": f(ch.swings[-1] * DEG, 0),
                  "n": str(len(ch.swings))},
        "grid": str(p.grid_points), "slider": slider,
        "verify_rows": vrows, "findings": findings,
    }


def write_data(r: dict, folder: Path) -> list[Path]:
    """The design chart as CSV (one row per ψ, l3/l4 and γmin per θ)."""
    import csv

    ch = r["chart"]
    path = folder / "design_chart.csv"
    with atomic_open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(["psi_deg"] + [f"l3_over_l4[theta={t * DEG:g}]" for t in ch.thetas] +
                   [f"gamma_min_deg[theta={t * DEG:g}]" for t in ch.thetas])
        for j, ps in enumerate(ch.swings):
            w.writerow([f"{ps * DEG:.4f}"] + [f"{x:.6f}" for x in ch.ratio[:, j]] +
                       [f"{x * DEG:.6f}" for x in ch.gamma[:, j]])
    return [path]
