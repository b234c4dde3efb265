"""The graphical method in the report (图解法): figures and template context from the
graphical stage's results (:mod:`mechdesign.stages.graphical`), for every linkage that runs
through the shared linkage stages. ``templates/graphical_section.*.md.j2`` places them.

:func:`graphical_figures` draws, per position, the velocity and acceleration polygons side by
side and, per group, the free body with its loads beside its force polygon, at the scales
the construction used; :func:`graphical_context` gives every vector equation with its
大小/方向 table, the measured lengths and the values read, the moment equations with their
numbers and the graphical results beside the analytic ones.
"""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np

from . import figures as fig
from ..core.polygons import spread
from ..i18n import N_, tr
from ..numbers import significant
from .fmt import GROUP, exact, f, factor_for, force_unit, gives, grouped, mpl_text, sci, sci_tex, sig, tex_name
from .label_layout import Label, place
from .labels import LabelTable, mpl_point, pgettext, point_tex, tex_names

_T = LabelTable({
    "vel": N_("velocity polygon"), "acc": N_("acceleration polygon"), "fbd": N_("free body"),
    "force": N_("force polygon"), "guide": N_("∥ guide"), "bar": N_("∥ bar {}"),
    "rot": N_("$v_r$ turned 90° with $\\omega_{{{}}}$"), "known": pgettext("graphical", "known"),
    "mag": pgettext("graphical", "magnitude"), "dir": pgettext("graphical", "direction"),
    "pos": pgettext("graphical", "position"), "group": pgettext("graphical", "group"),
    "crank": N_("crank"), "doc": "{}", "links": pgettext("graphical", "links"),
    "flat": N_("nearly flat polygon (width {w} mm): the forces are almost collinear"),
})


def documents(results: dict) -> list[tuple[str, object]]:
    """(prefix, GraphicalDocument) of every linkage in the results, in a stable order."""
    from ..stages.graphical import GraphicalDocument

    return [(key[: -len("_graphical")], v) for key, v in results.items()
            if key.endswith("_graphical") and isinstance(v, GraphicalDocument) and v.positions]


# ---------------------------------------------------------------- text helpers

def sym(s: str) -> str:
    """"a^n_CB" → "a^{n}_{CB}", "R23^t" → "F_{R23}^{t}", "FI4" → "F_{I4}", "G4" → "G_{4}"."""
    s = str(s)
    prime = ""
    if s.endswith("'"):
        s, prime = s[:-1], "'"
    sup = ""
    if s.startswith(("R", "FI", "Fr", "Fc", "G", "Pb", "Mb", "M")) and "_" not in s:
        if "^" in s:
            s, sup = s.split("^", 1)
            sup = f"^{{{sup}}}"
        if s.startswith("R"):
            return f"F_{{{s}}}{sup}{prime}"
        if s.startswith("FI"):
            return f"F_{{I{s[2:]}}}{sup}"
        if s.startswith(("Fr", "Fc")):     # a resistance (stages.linkage.Resistance.symbol)
            return f"F_{{{s[1:]}}}" if len(s) > 2 else f"F_{s[1]}"
        if s.startswith("MI"):
            return f"M_{{I{s[2:]}}}"
        if s in ("Pb", "Mb"):
            return f"{s[0]}_b"
        if s.startswith("M"):
            return f"M_{{{s[1:]}}}"
        return f"{s[0]}_{{{s[1:]}}}"
    if "_" in s:
        head, sub = s.split("_", 1)
        if "^" in head:
            base, sp = head.split("^", 1)
            return f"{base}^{{{sp}}}_{{{sub}}}{prime}"
        return f"{head}_{{{sub}}}{prime}"
    return s + prime


_VERTEX = re.compile(r"([A-Za-z])([A-Za-z0-9]*)('*)")


def vertex(name: str) -> str | None:
    """A polygon vertex in TeX (LaTeX, pandoc and mathtext), its digits and the letters after
    the first one a subscript: "n4'" → "n_{4}'", "ns3'" → "n_{s3}'", "a4" → "a_{4}",
    "p'" → "p'"; None for a name of another form (drawn as written)."""
    m = _VERTEX.fullmatch(str(name))
    if m is None:
        return None
    base, sub, prime = m.groups()
    return f"{base}_{{{sub}}}{prime}" if sub else base + prime


def segment(tail: str, head: str) -> str:
    """A polygon's segment as a table cell, typeset: "$p'n_{4}'$" (p'n4' as written when a
    vertex has another form)."""
    a, b = vertex(tail), vertex(head)
    return f"{tail}{head}" if a is None or b is None else f"${a}{b}$"


def mpl_math(tex: str, vertex: bool = False) -> str:
    """A TeX fragment of :func:`vertex` or :func:`sym` for matplotlib's mathtext, its primes
    written "′" (U+2032): mathtext draws "'" as a superscript \\prime that the shipped
    fonts render as a small "0" ("p⁰", "a⁰₄" in the polygons). A vertex's prime goes
    before its subscript ("a′₄"), a force's stays where the text has it ("F_R72′")."""
    m = re.fullmatch(r"([A-Za-z])_\{([^{}]*)\}('+)", tex) if vertex else None
    if m:
        return f"{m[1]}{'′' * len(m[3])}_{{{m[2]}}}"
    return tex.replace("'", "′")


# the image of a point named P on the polygon, "p(P)" (its lower-case letter is the pole's)
_POLE_OF = re.compile(r"([a-z])\(([A-Z][0-9]*)\)('*)")


def vertex_label(name: str) -> str:
    """A polygon vertex as a matplotlib label (mathtext when :func:`vertex` typesets it)."""
    tex = vertex(name)
    if tex is None and (m := _POLE_OF.fullmatch(str(name))):      # p(P): P's image on the pole
        return f"${m[1]}({point_tex(m[2])}){'′' * len(m[3])}$"
    return mpl_text(str(name).replace("'", "′")) if tex is None else f"${mpl_math(tex, vertex=True)}$"


def direction(code: str, lang: str) -> str:
    t = _T[lang]
    kind, _, arg = code.partition(":")
    if kind == "perp":
        return f"$\\perp {tex_names(arg)}$"
    if kind == "to":
        return f"${_split_to(arg)}$"
    if kind == "guide":
        return t["guide"]
    if kind == "bar":
        return t["bar"].format(arg)
    if kind == "rot":
        return t["rot"].format(arg)
    return t["known"]


def _split_to(arg: str) -> str:
    """"CB" → "C \\to B"; "A4O3" style names: split before the last point name."""
    import re

    parts = re.findall(r"[A-Z][a-z0-9']*", arg)
    if len(parts) == 2:
        return f"{point_tex(parts[0])} \\to {point_tex(parts[1])}"
    return tex_names(arg)


def _num(x: float) -> str:
    """A value read from a drawing: 3 significant digits (no E-notation); a million or more
    (a moment in N·mm) with a power of ten, 4 significant digits (render/fmt.py's rule)."""
    if x == 0:
        return "0"
    if abs(x) >= 1e6:
        return sci_tex(x, 4)
    d = max(0, 2 - int(math.floor(math.log10(abs(x)))))
    return f(x, min(d, 4))


def _numg(x: float) -> str:
    """:func:`_num` for a table cell or running text: five or more integer digits grouped
    (render/fmt.py's rule); inside a formula :func:`_num` keeps them together."""
    return sci(x) if abs(x) >= 1e6 else grouped(_num(x))


def _mm(x: float) -> str:
    return f"{x:.1f}"


def _len(x: float, scale: float | None = None, value: str | None = None) -> str:
    """A length of a polygon's table: a measured one (0.5 mm) to 0.1 mm; a known vector
    drawn at its exact length (the crank's ω·l, a known force |F|/μF): one of a millimetre or
    more to 0.01 mm — a drawing is not more exact (shaper_lengths' F_I4 was written
    "10.3466 mm" so that × 20 gave its 206.93 N; page review 41) — a shorter one with the
    digits that make length × ``scale`` give the ``value`` listed (0.998 mm × 50 = 49.9 N,
    not 1.00 mm)."""
    if abs(x * 2 - round(x * 2)) < 1e-9:
        return _mm(x)
    for d in ((2,) if abs(x) >= 1 else (2, 3, 4)):
        text = f"{x:.{d}f}"
        if scale is None or value is None or "times" in value or "×" in value or gives(
                float(text) * scale, value.replace(GROUP, "")):
            break
    return text


def _measured(x: float) -> str:
    """A force read off a polygon, length (0.5 mm) × μF, as that product gives it (66.5 ×
    25 = 1662.5 N, not 1662: its reaction is listed at 1662.5 where it is a known force),
    with at least :func:`_num`'s digits; ungrouped (a million or more: :func:`_num`)."""
    text = _num(x)
    if "times" in text:
        return text
    full = exact(x, digits=7, group=False)
    return full if _digits(full) > _digits(text) else text


_PAIR = re.compile(r"R([0-9A-Za-z])([0-9A-Za-z])")


def _pair(name: str) -> str | None:
    """The reaction's counterpart: "R45" → "R54" (the force of 5 on 4 and of 4 on 5)."""
    m = _PAIR.fullmatch(str(name))
    return f"R{m[2]}{m[1]}" if m else None


def _polygon_sum(vectors) -> tuple[str, str | None, str | None]:
    """The force polygon's closing equation; in a guide-bar group (RPR) the bar's polygon
    alone and the slider's apart (孙桓: link 4: G⃗4 + F⃗I4 + F⃗R54 + F⃗R34 + F⃗R74 = 0; slider 3:
    F⃗R23 = −F⃗R43 = F⃗R34), not one sum that adds the pair F_R34 + F_R43 (= 0).
    Returns (the polygon's equation, the slider's equation or None, the slider's link)."""
    def vec(v):
        return r"\vec " + sym(v.symbol)

    vs = list(vectors)
    names = [v.symbol for v in vs]
    cut = next((i for i, v in enumerate(vs) if _pair(v.symbol) in names[:i]), None)
    if cut is None:
        return " + ".join(vec(v) for v in vs) + " = 0", None, None
    bar, slider = vs[:cut], vs[cut:]
    back = slider[0]                       # F_R43: the bar's force on the slider
    link = back.symbol[2]
    if len(slider) == 2:                   # no load of its own: its pin carries it back
        pin = slider[1]
        second = f"{vec(pin)} = -{vec(back)} = \\vec {sym(_pair(back.symbol))}"
    else:
        second = " + ".join(vec(v) for v in slider) + " = 0"
    return " + ".join(vec(v) for v in bar) + " = 0", second, link


def _scale(x: float) -> str:
    return f"{x:g}"


def _title_scale(x: float) -> str:
    """A scale in a figure's title, grouped as in the text (20 000) with a plain space: the
    figures' font has no narrow no-break space (it printed a box, "20□000")."""
    return grouped(_scale(x)).replace(GROUP, " ")


# ---------------------------------------------------------------- figures

#: Font size of the labels of the free-body diagrams and force polygons [pt].
LABEL_SIZE = 8.5
#: Size of the arrow heads (matplotlib's mutation scale) [pt].
HEAD = 9


def _arrow(ax, a: complex, b: complex, color="k", lw=1.2, label=None, ls="-", labels=None):
    """An arrow a → b; its label beside the middle — drawn at once, or, when ``labels`` is a
    list, collected there for :func:`.label_layout.place` (offered the arrow's normal on
    either side first)."""
    if abs(b - a) < 1e-9:
        return
    # an annotation whose head lies outside the data limits is not drawn at all (shaper
    # Fig. 7: F_r, F_R76, F_R45 named without arrows): the arrow widens the limits
    ax.update_datalim([(a.real, a.imag), (b.real, b.imag)])
    ax.annotate("", xy=(b.real, b.imag), xytext=(a.real, a.imag), annotation_clip=False,
                arrowprops=dict(arrowstyle="-|>", color=color, lw=lw, ls=ls,
                                shrinkA=0, shrinkB=0, mutation_scale=HEAD))
    if label and labels is not None:
        n = 1j * (b - a) / abs(b - a)
        labels.append(Label(f"${mpl_math(label)}$", (a + b) / 2, (n, -n),
                            {"fontsize": LABEL_SIZE, "color": color}))
    elif label:
        m = (a + b) / 2
        n = 1j * (b - a) / abs(b - a)
        ax.text((m + 0.04 * abs(b - a) * n).real, (m + 0.04 * abs(b - a) * n).imag,
                f"${label}$", fontsize=7, color=color, ha="center", va="center")


def _heads(ax) -> list[tuple[complex, complex]]:
    """The arrows drawn in ``ax`` (tail, tip), whose heads a label must keep clear of."""
    from matplotlib.text import Annotation

    return [(complex(*t.xyann), complex(*t.xy)) for t in ax.texts
            if isinstance(t, Annotation) and t.arrow_patch is not None]


_COLORS = {"absolute": "k", "relative": "tab:blue", "normal": "tab:green",
           "tangential": "tab:red", "sliding": "tab:purple", "coriolis": "tab:orange",
           "known": "k", "reaction": "tab:red", "total": "tab:blue", "internal": "tab:purple",
           "normal_f": "tab:green", "tangential_f": "tab:orange", "balancing": "tab:brown"}


#: Vertices (or vectors) closer than this fraction of the polygon's extent are one spot on
#: the drawing: they get one label naming them all ("b, b₅"), not labels printed over each
#: other (issue 19).
COINCIDENT = 0.012


def _coincident(points: dict, span: float) -> list[tuple[complex, list[str]]]:
    """The polygon's vertices grouped by the spot they are drawn on: (spot, names) in the
    order of the first name of each group."""
    groups: list[tuple[complex, list[str]]] = []
    for name, z in points.items():
        for spot, names in groups:
            if abs(z - spot) <= COINCIDENT * span:
                names.append(name)
                break
        else:
            groups.append((z, [name]))
    return groups


def _extent(ax, zs, minor: float = 0.3, pad: float = 0.12) -> float:
    """Set the axes to the extent of the points ``zs`` at equal aspect (the axes box, not
    the data limits, takes the aspect: no empty panel round a flat polygon); a flat extent is
    widened to ``minor`` of the long one so that its labels have room. Returns the span."""
    xs, ys = [z.real for z in zs], [z.imag for z in zs]
    dx, dy = max(xs) - min(xs), max(ys) - min(ys)
    span = max(dx, dy, 1e-9)
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    hx, hy = max(dx, minor * span) / 2 + pad * span, max(dy, minor * span) / 2 + pad * span
    ax.set_xlim(cx - hx, cx + hx)
    ax.set_ylim(cy - hy, cy + hy)
    ax.set_aspect("equal", adjustable="box")
    return span


#: A velocity or acceleration polygon's panel: its short extent at least this fraction of
#: the long one (room for the vertex names beside a steep sliver, slotter position 5).
KIN_MINOR = 0.45


def _kin_axes(ax, poly, title: str, mu_unit: str, lang: str):
    """One polygon; returns its vertex labels (coincident vertices named together) and the
    segments they must keep clear of, for :func:`.label_layout.place`."""
    seen = set()
    lines: list[tuple[complex, complex]] = []
    for eq in poly.equations:
        for t in eq.left + eq.right:
            key = (t.tail, t.head)
            if key in seen or t.tail not in poly.points or t.head not in poly.points:
                continue
            seen.add(key)
            a, b = poly.points[t.tail], poly.points[t.head]
            _arrow(ax, a, b, _COLORS.get(t.kind, "k"), lw=1.4 if t.kind == "absolute" else 1.0)
            if abs(b - a) > 1e-9:
                lines.append((a, b))
    zs = list(poly.points.values()) or [0j]
    span = _extent(ax, zs, minor=KIN_MINOR)
    centre = complex(np.mean([z.real for z in zs]), np.mean([z.imag for z in zs]))
    labels: list[Label] = []
    for spot, names in _coincident(poly.points, span):
        ax.plot([spot.real], [spot.imag], "k.", ms=3)
        lines.append((spot, spot))
        away = spot - centre
        prefer = (away / abs(away),) if abs(away) > 1e-9 * span else ()
        # three or more names of one spot on two lines (a long row ran past the frame)
        row = [vertex_label(n) for n in names]
        text = ", ".join(row) if len(row) < 3 else (", ".join(row[:2]) + ",\n" + ", ".join(row[2:]))
        labels.append(Label(text, spot, prefer,
                            {"fontsize": 7}))
    ax.set_title(f"{title}  μ = {_title_scale(poly.scale)} {mu_unit}", fontsize=8)
    ax.tick_params(labelsize=6)
    ax.set_xlabel("mm", fontsize=6)
    ax.grid(True, lw=0.3, alpha=0.4)
    return labels, lines


@fig.cached
def _kin_figure(path: Path, label: str, velocity, acceleration, lang: str) -> None:
    """The velocity and acceleration polygons of the position ``label``. It is given what
    it draws and no more (not the whole position, whose forces change with a load): the
    render cache keys a figure by its call (render/cache.py), so an edit that leaves
    these polygons as they were copies the figure without building it."""
    t = _T[lang]
    with fig.figure(path, 1, (7.0, 3.6), sharex=False) as axes:
        f_ = axes[0].figure
        f_.clf()
        a1, a2 = f_.add_subplot(1, 2, 1), f_.add_subplot(1, 2, 2)
        l1 = _kin_axes(a1, velocity, f"{t['pos']} {label}: {t['vel']}", "(m/s)/mm", lang)
        l2 = _kin_axes(a2, acceleration, f"{t['acc']}", "(m/s²)/mm", lang)
        # labels last, clear of each other and of the polygon's vectors (issue 19)
        place(a1, *l1, heads=_heads(a1), head_size=HEAD)
        place(a2, *l2, heads=_heads(a2), head_size=HEAD)


@fig.cached
def _force_figure(path: Path, points: dict, length_scale: float, fg, members: dict,
                  lang: str) -> None:
    """Left: the group's links at μl with their loads (arrows of a common length, named);
    right: the force polygon at μF. ``points`` and ``length_scale``: the position's joints
    and μl (what it draws of the position, see :func:`_kin_figure`)."""
    t = _T[lang]
    with fig.figure(path, 1, (6.4, 2.6), sharex=False) as axes:
        f_ = axes[0].figure
        f_.clf()
        a1, a2 = f_.add_subplot(1, 2, 1), f_.add_subplot(1, 2, 2)
        P = points
        pts: dict = {}          # ordered (a set's order would change between processes)
        labels1: list[Label] = []
        lines1: list[tuple[complex, complex]] = []      # what a label must not lie on
        for link in fg.links:
            chain = members.get(link, ())
            zs = [P[p] / length_scale for p in chain if p in P]
            if len(zs) >= 2:
                a1.plot([z.real for z in zs], [z.imag for z in zs], "-", color="0.3", lw=2.5,
                        solid_capstyle="round")
                lines1 += list(zip(zs[:-1], zs[1:]))
            pts.update((p, None) for p in chain if p in P)
        centre = np.mean([P[p] for p in pts]) / length_scale if pts else 0j
        for p in pts:
            z = P[p] / length_scale
            a1.plot([z.real], [z.imag], "o", mfc="w", mec="k", ms=4)
            lines1.append((z, z))
            away = (z - centre) / abs(z - centre) if abs(z - centre) > 1e-12 else 1
            labels1.append(Label(mpl_point(p), z, (away,), {"fontsize": LABEL_SIZE}))
        span = max([abs(P[a] - P[b]) for a in pts for b in pts] + [1e-9]) / length_scale
        L = 0.25 * span
        for link, loads in fg.loads.items():
            for ld in loads:
                if abs(ld.value) == 0:
                    continue
                z = ld.at / length_scale
                u = ld.value / abs(ld.value)
                _arrow(a1, z, z + L * u, "tab:red" if ld.kind == "reaction" else "tab:blue",
                       label=sym(ld.name), labels=labels1)
                lines1.append((z, z + L * u))
        for name, at in fg.reaction_points.items():
            value = fg.reactions.get(name, 0j)
            if abs(value) > 0:
                z = at / length_scale
                _arrow(a1, z, z + L * value / abs(value), "tab:red", label=sym(name),
                       labels=labels1)
                lines1.append((z, z + L * value / abs(value)))
        # the couples as curved arrows in their sense: the inertia couples M_I (terms of the
        # moment equations) on their links, and the crank's balancing torque M_b at its pivot
        # (review38: the crank's free body showed F_R32 and no M_b, not in equilibrium)
        couples: dict[str, tuple[complex, float, str]] = {}
        for m in fg.moments:
            for term in m.terms:
                link = re.fullmatch(r"MI(\w+)", term.name)
                chain = [P[p] for p in members.get(link[1] if link else m.link, ()) if p in P]
                if not term.arm and term.value and chain and term.name not in couples:
                    couples[term.name] = (np.mean(chain) / length_scale, term.value, "tab:blue")
            if m.unknown == "Mb" and fg.balancing_torque and m.point in P:
                couples["Mb"] = (P[m.point] / length_scale, fg.balancing_torque, "tab:red")
        for name, (z, value, colour) in couples.items():
            lines1 += _couple_arrow(a1, z, COUPLE_RADIUS * span, value > 0, colour, sym(name),
                                    labels1)
        # room round the links and arrows for the names of the outermost points
        ends = [z for seg in lines1 for z in seg] or [0j]
        lo = complex(min(z.real for z in ends), min(z.imag for z in ends))
        hi = complex(max(z.real for z in ends), max(z.imag for z in ends))
        m = FBD_MARGIN * max(hi.real - lo.real, hi.imag - lo.imag, 1e-9)
        a1.update_datalim([(lo.real - m, lo.imag - m), (hi.real + m, hi.imag + m)])
        a1.set_aspect("equal", adjustable="datalim")
        a1.set_title(f"{t['fbd']} ({t['links']} {', '.join(fg.links)})  "
                     f"$\\mu_l$ = {_scale(length_scale)} m/mm", fontsize=8)
        a1.tick_params(labelsize=6)
        lines2: list[tuple[complex, complex]] = []
        zs2 = list(fg.points.values()) or [0j]
        span2 = max([abs(a - b) for a in zs2 for b in zs2] + [1e-9])
        drawn: list[tuple] = []   # one label per segment: a, b, names, colour, symbols, pair
        for v in fg.vectors:
            if v.tail in fg.points and v.head in fg.points:
                c = _COLORS.get({"normal": "normal_f", "tangential": "tangential_f"}.get(v.kind, v.kind), "k")
                a, b = fg.points[v.tail], fg.points[v.head]
                _arrow(a2, a, b, c, ls="--" if v.kind in ("total", "internal") else "-")
                if abs(b - a) < 1e-9:
                    continue
                lines2.append((a, b))
                for seg in drawn:       # the same segment either way: one label naming all
                    if (abs(seg[0] - a) + abs(seg[1] - b) <= COINCIDENT * span2
                            or abs(seg[0] - b) + abs(seg[1] - a) <= COINCIDENT * span2):
                        # the guide bar's force on the slider back along the slider's force on
                        # the bar (F_R43 = −F_R34) is not a second name of that side: the side
                        # is F_R34, equal to the slider's pin force (F_R34 = F_R23)
                        if _pair(v.symbol) in seg[4]:
                            seg[5].append(True)
                        else:
                            seg[2].append(sym(v.symbol))
                        break
                else:
                    drawn.append((a, b, [sym(v.symbol)], c, [v.symbol], []))
                    continue
                seg[4].append(v.symbol)
        labels2 = []
        # each side's name offered on the polygon's outside first (its normal away from the
        # middle of the polygon's vertices), then inside
        middle = complex(np.mean([z.real for z in zs2]), np.mean([z.imag for z in zs2]))
        for a, b, names, c, _symbols, pair in drawn:
            n = 1j * (b - a) / abs(b - a)
            if (n.conjugate() * ((a + b) / 2 - middle)).real < 0:
                n = -n
            # the names of one segment stacked beside a steep one, in a row beside a flat one
            sep = ",\n" if abs((b - a).imag) > abs((b - a).real) else ", "
            sep = " = " if pair else sep
            labels2.append(Label(sep.join(f"${mpl_math(s)}$" for s in names), (a + b) / 2, (n, -n),
                                 {"fontsize": LABEL_SIZE, "color": c},
                                 along=tuple(a + t * (b - a) for t in ALONG_SIDE)))
        for name, z in fg.points.items():
            a2.plot([z.real], [z.imag], "k.", ms=2)
        _extent(a2, zs2, minor=FORCE_MINOR, pad=FORCE_PAD)
        flat = _flatness(zs2)
        a2.set_title(f"{t['force']}  $\\mu_F$ = {_title_scale(fg.scale)} N/mm", fontsize=8)
        a2.tick_params(labelsize=6)
        a2.set_xlabel("mm", fontsize=6)
        # a polygon whose forces are almost collinear closes on a line: say so (issue 19),
        # in a note of its own under the axis label, NOTE_GAP clear of it (as a second
        # line of the label it touched "mm", shaper Fig. 8, slotter Fig. 9)
        if flat is not None:
            note = re.sub(r"([:\uff1a])\s*", "\\1\n", t["flat"].format(w=_mm(flat)), count=1)
            a2.annotate(note, xy=(0.5, 0.0), xycoords=a2.xaxis.label, xytext=(0, -NOTE_GAP),
                        textcoords="offset points", ha="center", va="top", fontsize=6,
                        gid="flat_note")
        a2.grid(True, lw=0.3, alpha=0.4)
        # labels last, clear of each other and of the links and vectors (issue 19)
        place(a1, labels1, lines1, heads=_heads(a1), head_size=HEAD)
        place(a2, labels2, lines2, heads=_heads(a2), head_size=HEAD, gap=FORCE_LABEL_GAP,
              sight=True)


#: Margin round the free-body diagram's links and arrows (fraction of the data extent).
FBD_MARGIN = 0.16

#: The radius of a couple's curved arrow in a free-body diagram (fraction of the links' span).
COUPLE_RADIUS = 0.09


def _couple_arrow(ax, z: complex, r: float, ccw: bool, color: str, label: str,
                  labels: list) -> list[tuple[complex, complex]]:
    """A couple as a curved arrow round ``z`` (three quarters of a circle of radius ``r``,
    its head in the couple's sense), its name outside the arc's middle (collected in
    ``labels``); returns the arc's chords, which other labels keep clear of."""
    from matplotlib.patches import FancyArrowPatch
    from matplotlib.path import Path as MplPath

    t = np.linspace(np.radians(135), np.radians(135 + 270), 37)
    arc = z + r * np.exp(1j * (t if ccw else t[::-1]))
    ax.add_patch(FancyArrowPatch(path=MplPath(np.column_stack([arc.real, arc.imag])),
                                 arrowstyle="-|>", color=color, lw=1.0, mutation_scale=HEAD))
    ax.update_datalim([(z.real - r, z.imag - r), (z.real + r, z.imag + r)])
    out = np.exp(1j * np.radians(135 + 135))
    labels.append(Label(f"${mpl_math(label)}$", z + r * out, (out, out * 1j, -out * 1j),
                        {"fontsize": LABEL_SIZE, "color": color}))
    return list(zip(arc[:-1], arc[1:]))


#: The force polygon's panel: its short extent at least this fraction of the long one, and
#: this margin round it (of the long extent) — room for the force names, which are longer
#: than a vertex's (a tall polygon in a narrow panel pushed "F_R34, F_R43, F_R23" over the
#: tick labels, slotter and press, issue 19 point 6).
FORCE_MINOR, FORCE_PAD = 0.6, 0.18

#: The least gap [pt] between two force names of a force polygon: names two points apart
#: read as one stack of text on the page, where the figure is printed at about 70 %
#: (page review of session 43: press Fig. 9, furnace_pusher Figs 9–10). More spreads the
#: names of a cluster of short sides away from them (press Fig. 9's G₂, G₃, F_I2, F_I3).
FORCE_LABEL_GAP = 4.2

#: Where else along its side (fractions from its tail) a force polygon's name may stand
#: than at the side's middle, where the names of the sides beside it leave no room.
ALONG_SIDE = (0.35, 0.65, 0.25, 0.75)

#: The gap [pt] between the force polygon's axis label "mm" and the flat-polygon note under it.
NOTE_GAP = 4.0

#: A force polygon narrower than this fraction of its length is called nearly flat in its
#: figure (its forces almost collinear; the directions read from it are uncertain).
FLAT = 0.08


def _flatness(zs) -> float | None:
    """The width [mm] of a nearly flat polygon (across its longest direction), else None."""
    if len(zs) < 3:
        return None
    length, width = spread(zs)
    return width if length > 0 and width < FLAT * length else None


def graphical_figures(results: dict, fig_dir: Path, lang: str) -> dict[str, str]:
    """Every polygon figure of every linkage's graphical method; name → relative path."""
    from ..stages.linkage import link_members

    paths = {}
    for prefix, doc in documents(results):
        model = _model_of(results, prefix)
        members = link_members(model.mechanism)[0] if model is not None else {}
        for pos in doc.positions:
            key = f"{prefix}_graph_{_safe(pos.label)}_kin"
            _kin_figure(fig_dir / f"{key}.png", pos.label, pos.velocity, pos.acceleration, lang)
            paths[key] = f"{fig_dir.name}/{key}.png"
            for n, fg in enumerate(pos.forces):
                key = f"{prefix}_graph_{_safe(pos.label)}_f{n}"
                _force_figure(fig_dir / f"{key}.png", pos.points, pos.length_scale, fg,
                              members, lang)
                paths[key] = f"{fig_dir.name}/{key}.png"
    return paths


def _safe(label: str) -> str:
    return str(label).replace("'", "p").replace("′", "p")


def _model_of(results: dict, prefix: str):
    from ..stages.polygons import LinkagePolygons

    for v in results.values():
        if isinstance(v, LinkagePolygons) and v.prefix == prefix:
            return results.get(v.model_key)
    return None


# ---------------------------------------------------------------- context

def _eq_tex(eq) -> str:
    left = " + ".join(r"\vec " + sym(t.symbol) for t in eq.left)
    right = " + ".join(r"\vec " + sym(t.symbol) for t in eq.right)
    return f"{left} = {right}" if left else right


def _group_title(name: str, links: dict, lang: str) -> str:
    """"crank 2" / "group 3–4" (曲柄 2 / 杆组 3–4) of a mechanism group, by its links."""
    _ = tr(lang)
    ids = links.get(name)
    if not ids:
        return name
    if ids.get("crank"):
        return _("crank {links}", links="–".join(ids["links"]))
    return _("group {links}", links="–".join(ids["links"]))


def _link_order(link: str):
    """Links by their number (ω2, ω3, ω4 …, not the order the groups were solved in)."""
    return (0, int(link), "") if link.isdigit() else (1, 0, link)


def _kin(poly, lang: str, unit: str, rate_name: str, links: dict | None = None,
         still: frozenset = frozenset()) -> dict:
    """The polygon's vector equations group by group: per group its equations and ONE table,
    a row per vector (大小 and 方向 as the construction knows them: "?" unknown, "√" found
    before, else the value drawn; then the polygon's segment, its length and the value read);
    each table is titled by its group (``links``: group name → its link ids)."""
    groups: list[dict] = []
    for eq in poly.equations:
        rel = [t for t in eq.left + eq.right if t.kind != "absolute"]
        if rel and all(t.known and t.length == 0 and not t.computed for t in rel):
            continue        # a point of a link in translation: the same vector as its origin
        # (a link turning so slowly that its relative vector rounds to no length on the
        # drawing keeps its equation: the point's vector is measured and compared later;
        # page review 51, press position 10: v_S2 compared in Table 25, never constructed)
        # a new table for each group whose equation has unknowns; a further point of a link
        # already solved (every magnitude known: v_B = v_BO3) joins the table before it
        solved = all(t.known for t in eq.left + eq.right)
        if not groups or (groups[-1]["group"] != eq.group and not solved):
            groups.append({"group": eq.group, "eqs": [], "rows": [], "seen": set(),
                           "title": _group_title(eq.group, links or {}, lang)})
        g = groups[-1]
        g["eqs"].append(_eq_tex(eq))
        # a point of a solved link (v_D = v_DO3 = ω3·l_O3D): one vector, one magnitude — the
        # relative term's ω·l (page review 41: v_D 0.0870 printed beside v_DO3 0.0867)
        same = (eq.right[0] if solved and len(eq.left) == 1 and len(eq.right) == 1
                and eq.right[0].computed is not None else None)
        for t in list(eq.left) + list(eq.right):
            if t.symbol in g["seen"]:
                continue
            g["seen"].add(t.symbol)
            # a resultant (a^n + a^t of a point about a fixed pivot) is found by the polygon:
            # magnitude and direction "?" in the construction, its segment measured
            resultant = t.direction == "sum"
            # a known magnitude as computed (ω²·l = 0.0312), drawn at the drawing's accuracy
            # (3.0 mm) and read back (0.0300) in the last column (review39: 0.0300 stood as
            # the magnitude a teacher recomputes as 0.0312)
            shown = same.computed if same is not None and t is eq.left[0] else t.computed
            mag = "?" if not t.known or resultant else ("√" if t.direction == "known" else _numg(
                t.read if shown is None else shown))
            dirs = direction(t.direction, lang) if t.direction and not resultant else "?"
            if t.known and (t.direction == "known" or t.length == 0):
                seg = length = value = "—"
            else:
                value = _numg(t.read)
                seg, length = segment(t.tail, t.head), _len(t.length, poly.scale, value)
            g["rows"].append([f"${sym(t.symbol)}$", mag, dirs, seg, length, value])
    for g in groups:
        del g["seen"]
    rates = [[f"${rate_name}_{{{link}}}$", _numg(poly.rates[link])]
             for link in sorted(poly.rates, key=_link_order) if link not in still]
    coriolis = any(t.kind == "coriolis" for eq in poly.equations for t in eq.left + eq.right)
    return {"mu": _scale(poly.scale), "groups": groups, "rates": rates, "coriolis": coriolis}


def _digits(text: str) -> int:
    return len(text.partition(".")[2])


def _factor(x: float, extra: int = 0) -> str:
    """A factor of a displayed chain: :func:`_num`'s digits, with ``extra`` more decimals
    where the chain needs them to give its printed result (trailing zeros beyond
    :func:`_num`'s decimals dropped: a weight of 156.96 N, a reaction of 1662.5 N)."""
    text = _num(x)
    if not extra or "times" in text:
        return text
    base = _digits(text)
    head, _dot, dec = f(x, base + extra).partition(".")
    dec = dec.rstrip("0").ljust(base, "0")
    return head + ("." + dec if dec else "")


def _gives(value: float, printed: str) -> bool:
    """``value`` (a chain evaluated from its printed factors) rounds to ``printed``, to the
    last digit printed (a value with a power of ten is not re-evaluated)."""
    return "times" in printed or gives(value, printed)


def _moment_tex(m, gives=None, least=None, shown=None) -> tuple[str, float, float, float]:
    """The known forces' moments "F × h" (h in mm on the drawing) as one sum, their value
    [N·mm of the drawing], the couples' sum [N·m] and the sum of the products as printed.
    The forces are written with the digits that make ``gives(printed sum)`` true — by
    default, the printed products give the sum as the equation prints it, to its last digit
    (the rule of every displayed chain: its printed factors reproduce its printed result) —
    and with at least ``least[name]`` extra decimals; ``shown[name]`` collects each force as
    printed (the most decimals any equation gave it)."""
    arms = [t for t in m.terms if t.arm]
    total = sum(t.force * t.arm * t.sign for t in arms)
    couples = sum(t.value for t in m.terms if not t.arm)
    gives = gives or (lambda s: _gives(s, _num(total)))
    least = least or {}
    for extra in range(6):
        printed = [_factor(t.force, max(extra, least.get(t.name, 0))) for t in arms]
        if any("times" in p for p in printed):
            psum = total
            break
        psum = sum(float(p) * t.arm * t.sign for p, t in zip(printed, arms))
        if gives(psum):
            break
    terms = [f"{'+' if t.sign > 0 else '-'} {p} \\times {_mm(t.arm)}" for p, t in zip(printed, arms)]
    if shown is not None:
        for p, t in zip(printed, arms):
            if _digits(p) >= _digits(shown.get(t.name, "")):
                shown[t.name] = p
    known = " ".join(terms)
    known = known[2:] if known.startswith("+ ") else ("-" + known[2:] if known else "0")
    return known, total, couples, psum


def _sum_text(total: float, psum: float) -> str:
    """The sum of a moment equation's printed products as it is printed (:func:`_num`'s
    digits of the unrounded ``total``), with one more decimal where the printed products
    ``psum`` end exactly in a half unit of its last digit: a reader adding "2.50 × 57.0"
    writes 142.5 and rounds it up, never to 142 (review 38, linkage_sixbar position 10)."""
    num = _num(total)
    if "times" in num:
        return num
    unit = 10.0 ** -len(num.partition(".")[2])
    if abs(abs(psum - float(num)) - 0.5 * unit) <= 1e-9 * max(1.0, abs(psum)):
        return f(psum, len(num.partition(".")[2]) + 1)
    return num


def _mantissa_for(x: float, ok) -> tuple[str, float]:
    """``x`` (a million or more) as "a\\times10^{n}" with 4 significant digits, more (up to 8)
    until ``ok(printed value)`` holds; the text and the value it prints."""
    power = int(math.floor(math.log10(abs(x))))
    for digits in range(4, 9):
        mant = f(x / 10.0 ** power, digits - 1)
        value = float(mant) * 10.0 ** power
        if ok(value):
            break
    return f"{mant}\\times10^{{{power}}}", value


def _couple(c: float, extra: int = 0) -> str:
    return f" {'+' if c >= 0 else '-'} {_factor(abs(c), extra)}" if c else ""


def _couple_for(c: float, chain) -> str:
    """The couple's term with the digits that make ``chain(printed couple)`` true."""
    for extra in range(6):
        text = _couple(c, extra)
        if not c or chain(float(text.replace(" ", "").replace("+", "")) if "times" not in text else c):
            return text
    return text


def _sum_for(num: str, psum: float, couples: float, mu_l: float, arm: float,
             res: str) -> tuple[str, float]:
    """The printed sum of a moment equation with a couple: ``num`` or, where the couple would
    need more than two extra digits to give the printed result ``res``, the printed products'
    sum ``psum`` with up to three more decimals (the first that lets a couple of at most two
    extra digits give it); the text and its value."""
    def fits(value: float) -> bool:
        for extra in range(3):
            text = _couple(couples, extra)
            c = float(text.replace(" ", "").replace("+", "")) if "times" not in text else couples
            if _gives(-(value + c / mu_l) / arm, res):
                return True
        return False

    if fits(float(num)):
        return num, float(num)
    places = len(num.partition(".")[2])
    for k in range(places + 1, places + 4):
        text = f(psum, k)
        if fits(float(text)):
            return text, float(text)
    return num, float(num)


def _signed_pb(fg) -> float:
    """P_b = M_b/l at the crank pin with M_b's sign (counter-clockwise positive): the
    value of the P_b equation (the moment whose unknown is P_b)."""
    found = [m.result for m in fg.moments if m.unknown == "Pb"]
    if found:
        return float(found[0])
    return float(np.copysign(abs(fg.balancing_force), fg.balancing_torque or 0.0))


def _is_weight(name: str) -> bool:
    """A weight G_i (a given load of one value at every position)."""
    return bool(re.fullmatch(r"G\d+", str(name)))


def _weight_decimals(sections) -> dict[str, int]:
    """The extra decimals of each weight G_i over the whole document: the most any position's
    equations need (slotter G₄: 117.7 at position 5, 117.72 at position 11 → 117.72 at every
    position), read off every position's force groups laid out without them
    (``sections``: (position, :func:`_forces` of it), in order). A given quantity prints one
    way throughout a report (review37 Top 8); a chain that needs fewer digits still computes
    with more (the seed is only a floor)."""
    most: dict[str, int] = {}
    for pos, forces in sections:
        for fc, fg in zip(forces, pos.forces):
            value = {ld.name: abs(ld.value) for lds in fg.loads.values() for ld in lds}
            for name, _link, text in fc["known"]:
                if _is_weight(name) and "times" not in text:
                    extra = _digits(text.replace(GROUP, "")) - _digits(_num(value[name]))
                    most[name] = max(most.get(name, 0), extra)
    return most


def _force_sections(doc, lang: str) -> list[list[dict]]:
    """Every position's force groups (:func:`_forces`), each weight with one number of
    decimals throughout (:func:`_weight_decimals`). The groups are laid out once, and again
    with the weights' decimals only where some weight needs extra ones (its seed changes the
    chains): a seed of 0 is no seed (``least.get(name, 0)`` in :func:`_moment_tex`, and a
    weight of no extra decimals prints by :func:`_numg` in ``known``)."""
    first = [_forces(pos, lang) for pos in doc.positions]
    weights = _weight_decimals(zip(doc.positions, first))
    if any(weights.values()):
        first = [_forces(pos, lang, weights) for pos in doc.positions]
    for pos, forces in zip(doc.positions, first):
        _in_force_unit(pos, forces)
    return first


def force_divisor(pos) -> tuple[float, str]:
    """The unit of the forces a position's force section prints (render/fmt.force_unit):
    kN where its largest force — a load, a side of a force polygon, a compared reaction
    (graphical or analytic) — reaches a million newtons (the die-cutter's cutting force of
    1000 kN), else N."""
    peak = [abs(ld.value) for fg in pos.forces for lds in fg.loads.values() for ld in lds]
    peak += [abs(v.read) for fg in pos.forces for v in fg.vectors]
    peak += [abs(x) for c in pos.comparison if c.unit == "N" for x in (c.graphical, c.analytic)]
    return force_unit(max(peak, default=0.0))


def kn_text(n_text: str, value: float) -> str:
    """A force printed in N (``n_text``, the digits its N text has) written in kN: 3 or 4
    significant digits as that text has them (245.3 N → 0.2453, 120 N → 0.120, 1662.5 N →
    1.663, 1.000 × 10⁶ N → 1000, 960 000 N → 960), grouped as text is; no power of ten."""
    digits = n_text.replace(GROUP, "").replace(" ", "").lstrip("-−")
    if "×" in digits or "times" in digits:
        n = 4
    else:
        body = digits.replace(".", "").lstrip("0")
        n = len(body if "." in digits else body.rstrip("0"))
    return sig(value / 1e3, min(max(n, 3), 4))


def _in_force_unit(pos, forces: list[dict]) -> None:
    """A position whose largest force reaches a million newtons (:func:`force_divisor`)
    writes its known loads and its force polygons' values in kN (their lengths with the
    scale in kN/mm); its moment equations keep N (their text says so). Every group's
    ``unit`` is set."""
    div, unit = force_divisor(pos)
    for fc, fg in zip(forces, pos.forces):
        fc["unit"] = unit
        if div == 1.0:
            continue
        given = [ld for lds in fg.loads.values() for ld in lds if abs(ld.value) > 0]
        fc["loads"] = [[a, b, kn_text(t, abs(ld.value))] for (a, b, t), ld in zip(fc["loads"], given)]
        fc["known"] = [(a, b, kn_text(t, abs(ld.value))) for (a, b, t), ld in zip(fc["known"], given)]
        for row, v in zip(fc["rows"], _sides(fg)):
            row[3] = kn_text(row[3], v.read)
            if v.known and row[2] != "—":
                row[2] = _len(v.length, fg.scale / div, row[3])


def _forces(pos, lang: str, weights: dict[str, int] | None = None) -> list[dict]:
    """The force groups of one position; ``weights``: each weight's extra decimals for the
    whole document (:func:`_weight_decimals`), printed alike at every position."""
    weights = weights or {}
    out = []
    mu_l = pos.length_scale
    # a reaction read off an earlier group's polygon, as its table prints it: the later
    # group's known force of the pair (F_R54 of F_R45) prints the same digits (issue 19)
    measured: dict[str, str] = {}
    floors = []         # each group's digit floors and the known forces' texts they gave
    for n, fg in enumerate(pos.forces):
        pairs = {ld.name: measured[_pair(ld.name)] for lds in fg.loads.values() for ld in lds
                 if _pair(ld.name) in measured}
        # a known force prints with one number of decimals in the group's whole section (the
        # known-loads line, its equations, its polygon row): the most any of its equations
        # needs, fed back until no equation needs more
        seed = {**weights, **{k: _digits(v) - _digits(_num(float(v))) for k, v in pairs.items()}}
        least: dict[str, int] = {}
        for _pass in range(4):
            shown: dict[str, str] = {}
            moments, couple = _group_moments(fg, mu_l, lang, {**seed, **least}, shown)
            need = {k: _digits(v) - _digits(_num(_force_of(fg, k))) for k, v in shown.items()}
            if need == least:
                break
            least = need
        floors.append(({**seed, **least}, shown))
        # a force known to be zero (a tangential component no known force calls for, its
        # moment equation said so) is no side of the polygon: left out of its vector
        # equation and its table, as the figure leaves it out (issue 19)
        sides = _sides(fg)
        closing, slider, slider_link = _polygon_sum(v for v in sides
                                                    if v.kind not in ("total", "internal"))
        # a given force (a weight, an inertia force, the resistance) is listed with its given
        # value, drawn at its exact length |F|/μF; what is read off the polygon is the rest
        given = {ld.name: abs(ld.value) for lds in fg.loads.values() for ld in lds}

        def known(name, value, shown=shown, pairs=pairs):
            return grouped(shown[name]) if name in shown else (
                grouped(pairs[name]) if name in pairs else
                grouped(_factor(value, weights[name])) if weights.get(name) else _numg(value))

        def read(v):
            return _numg(v.read) if v.known or abs(v.read) >= 1e6 else grouped(_measured(v.read))

        rows = [[f"${sym(v.symbol)}$", "√" if v.known else "?", _len(v.length),
                 known(v.symbol, given[v.symbol]) if v.known and v.symbol in given else
                 read(v)] for v in sides]
        measured.update((v.symbol, _measured(v.read)) for v in fg.vectors
                        if not v.known and _pair(v.symbol) and abs(v.read) < 1e6)
        loads = [[f"${sym(ld.name)}$", link, known(ld.name, abs(ld.value))]
                 for link, lds in fg.loads.items() for ld in lds if abs(ld.value) > 0]
        known_texts = [(ld.name, link, known(ld.name, abs(ld.value)))
                       for link, lds in fg.loads.items() for ld in lds if abs(ld.value) > 0]
        out.append({"known": known_texts,
                    "name": "–".join(fg.links), "links": ", ".join(fg.links), "crank": fg.balancing_torque
                    is not None, "mu": grouped(_scale(fg.scale)), "moments": moments, "rows": rows,
                    "loads": loads, "sum": closing, "slider": slider, "slider_link": slider_link,
                    "n": n, "couple": couple,
                    # whether a numeric moment equation follows (the shaper's link 5 has only
                    # "no known force has a moment about E: F_R45^t = 0"): the lead-in
                    # "Moment equations (…):" is said only then
                    "equations": any(not m[2] for m in moments),
                    "mb": None if fg.balancing_torque is None else _numg(fg.balancing_torque),
                    # P_b = M_b/l, signed as M_b (counter-clockwise positive) in the equation and
                    # the text alike; its magnitude is the length drawn in the polygon
                    "pb": None if fg.balancing_force is None else _numg(_signed_pb(fg)),
                    "pb_abs": None if fg.balancing_force is None else _numg(abs(fg.balancing_force))})
    # one known force, one number: a force known in several groups (the guide bar's F_R34,
    # F_R43, the slider's F_R23 and the crank's F_R32 of one magnitude) prints in every row
    # with the most digits any of its equations needed (slotter: 1137 and 1137.3)
    same: dict[float, list] = {}
    for fc, fg in zip(out, pos.forces):
        for row, v in zip(fc["rows"], _sides(fg)):
            if v.known and abs(v.read) < 1e6:
                same.setdefault(float(f"{v.read:.9g}"), []).append(row)
    for rows in same.values():
        best = max((r[3] for r in rows), key=lambda t: _digits(t))
        for r in rows:
            r[3] = best
    # the moment equation that finds such a force gives it with those digits too
    # (textbook_guide_bar φ45: "F_R34 = … = 123 N", then 123.5 in its rows and in the crank's
    # equation; review38), where its printed chain still gives them and the known forces
    # keep their texts
    for fc, fg, (floor, shown) in zip(out, pos.forces, floors):
        results = {}
        for m in fg.moments:
            key = float(f"{abs(m.result):.9g}")
            if m.arm and m.unknown != "Pb" and key in same and abs(m.result) < 1e6:
                best = same[key][0][3].replace(GROUP, "")
                if _digits(best) > _digits(_num(m.result)):
                    results[m.unknown] = ("-" if m.result < 0 else "") + best
        if results:
            again: dict[str, str] = {}
            moments, couple = _group_moments(fg, mu_l, lang, floor, again, results)
            if again == shown:
                fc["moments"], fc["couple"] = moments, couple
    # a known force's length, drawn at |F|/μF: with the digits that give its value; one
    # shorter than the drawing's accuracy (0.05 mm) is a point of the polygon, no length
    # (review39: "0.0225 mm" for a 0.45 N inertia force; the die-cutter's 15.5 N at
    # μF = 20 000 N/mm would need "0.000775")
    for fc, fg in zip(out, pos.forces):
        for row, v in zip(fc["rows"], _sides(fg)):
            if v.known:
                row[2] = "—" if abs(v.length) < TOO_SHORT else _len(v.length, fg.scale, row[3])
    return out


#: A known force drawn shorter than this [mm] is a point of its polygon: no length listed.
TOO_SHORT = 0.05


def _sides(fg) -> list:
    """The vectors of a force polygon that are its sides, in the order of its table's rows
    (a force known to be zero is none)."""
    return [v for v in fg.vectors if not known_zero(v)]


def known_zero(v) -> bool:
    """A force polygon's vector known before the construction to be zero (a moment equation
    gave it 0): it has no length, no direction and no side in the polygon."""
    return v.known and v.read == 0


def _force_of(fg, name: str) -> float:
    """The magnitude of known force ``name`` in the group's moment equations."""
    return next(t.force for m in fg.moments for t in m.terms if t.name == name and t.arm)


def _group_moments(fg, mu_l, lang: str, least: dict, shown: dict,
                   results: dict | None = None) -> tuple[list, str | None]:
    """The group's moment equations as (equation, result, note) and the couple's symbol;
    ``results``: a force's result as it is to print (its carried digits), by default
    :func:`_num`'s."""
    moments, couple = [], None
    # M_b as the P_b equation substitutes it (its decimals give the printed P_b); where M_b's
    # own equation, its forces as printed, gives that text too, also as that equation's
    # result: one value printed one way (review 38: "M_b = −169 N·m" above "P_b =
    # −168.6/0.1"; −44.35, not −44.4 above −44.36: the forces keep their digits)
    mb_text = {}
    for m in fg.moments:
        if m.unknown == "Pb":
            # the crank's length with the decimals the chain needs: 5, more for a P_b of six
            # digits (−7600/0.0570412 = −133 237, where 0.05704 gives −133 240; review40)
            for places in range(5, 9):
                arm = exact(m.arm * mu_l, decimals=places)
                mb_text["Pb_arm"] = arm
                mb_text["Pb"] = factor_for(fg.balancing_torque,
                                           lambda v, a=float(arm), r=_num(m.result): _gives(v / a, r),
                                           0, write=_factor, most=6)
                done = "times" in mb_text["Pb"] or _gives(float(mb_text["Pb"]) / float(arm),
                                                          _num(m.result))
                own = [k for k in fg.moments if k.unknown == "Mb" and not k.arm]
                if own:
                    # its forces with the digits whose products give the M_b the text and the
                    # comparison table print (_num: −44.4), not fewer (the slotter's 1137 ×
                    # 19.5 gave −44.343 beside −44.4 in the text; page review 41)
                    c0 = sum(t.value for t in own[0].terms if not t.arm)
                    text_mb = _num(fg.balancing_torque)
                    _l, _t, cpls, psum0 = _moment_tex(
                        own[0], lambda s_: _gives(-(s_ * mu_l + c0), text_mb), least, None)
                    # M_b as its own equation's printed forces give it, with the decimals that
                    # give the printed P_b (−44.35, where M_b = −44.36: the forces are printed)
                    by_forces = -(psum0 * mu_l + cpls)
                    for value in (fg.balancing_torque, by_forces):
                        t = next((t for t in (_factor(value, extra) for extra in range(7)) if "times" not in t
                                  and _gives(float(t) / float(arm), _num(m.result)) and _gives(by_forces, t)), None)
                        if t is not None:
                            mb_text["Pb"] = t
                            results = {**(results or {}), "Mb": t}
                            done = True
                            break
                if done:
                    break
    for m in fg.moments:
        u = sym(m.unknown)
        if m.unknown == "Pb":
            # a definition evaluated (no equation solved): one chain, no "=>"; the crank's
            # length is known (m.arm x mu_l in m), not measured
            # M_b with the decimals that give the printed P_b (−227.3/0.0925 = −2457):
            # _factor's digits are decimals more than _num's
            arm = mb_text.get("Pb_arm") or exact(m.arm * mu_l, decimals=5)
            mb = mb_text["Pb"]
            moments.append((f"P_b = \\frac{{M_b}}{{l_{{{m.point}}}}} = \\frac{{{mb}}}"
                            f"{{{arm}}} = {_num(m.result)}" r"\ \mathrm{N}", None, None))
            continue
        where = f"\\Sigma M_{{{m.point}}}" + ("" if m.unknown == "Mb" else f"({m.link})")
        res = (results or {}).get(m.unknown) or _num(m.result)
        couples = sum(t.value for t in m.terms if not t.arm)
        if not m.arm:
            # a moment unknown (M_b, a slider's couple): -(products x mu_l + couples)
            lhs, total, couples, psum = _moment_tex(
                m, lambda s: _gives(-(s * mu_l + couples), res), least, shown)
            cpl = _couple_for(couples, lambda c: _gives(-(psum * mu_l + c), res))
        if m.unknown == "Mb":
            moments.append((f"{where} = M_b + ({lhs}) \\times {_scale(mu_l)}{cpl} = 0",
                            f"M_b = {res}" r"\ \text{N·m}", None))
        elif not any(t.arm for t in m.terms) and not couples and m.result == 0:
            # no known force has a moment about the point: no equation of zeros (issue 19)
            _ = tr(lang)
            point = "$" + tex_name(m.point) + "$"
            result = "$" + u + " = 0$"
            note = _("No known force on link {link} has a moment about {point}: {result}.",
                     link=m.link, point=point, result=result)
            moments.append((None, f"{u} = 0", note))
        elif m.arm:
            # the printed sum, and the couple (N·m, divided by mu_l to N·mm of the drawing)
            # with the digits that give the printed unknown
            lhs, total, _c, psum = _moment_tex(m, None, least, shown)
            num = _sum_text(total, psum)
            value = float(num) if "times" not in num else total
            if "times" in num:
                # a sum of a million or more (N·mm of the drawing) with a power of ten: its
                # mantissa with the digits that give the printed unknown (1.059 × 10⁶ gave
                # −12 105.7 for the printed −12 107: 1.059138 × 10⁶)
                num, value = _mantissa_for(psum, lambda v: _gives(-(v + couples / mu_l) / m.arm, res))
            if couples and "times" not in num:
                # the sum with more decimals (its printed products' sum) before the couple
                # with many: −269.7, not "−270" and a couple of 0.36666667 (review40: the
                # die-cutter's position 6, group 3–4)
                num, value = _sum_for(num, psum, couples, mu_l, m.arm, res)
            cpl = (f"{_couple_for(couples, lambda c: _gives(-(value + c / mu_l) / m.arm, res))}"
                   f" / {_scale(mu_l)}") if couples else ""
            if couples and couple is None:
                couple = sym(next(t.name for t in m.terms if not t.arm and t.value))
            # a negative sum without a couple: its minus and the one before the fraction
            # cancel ("= − −5750/57.5" read as a slip: furnace_pusher eq. 43, page review 41)
            solved = (f"\\frac{{{num[1:]}}}{{{_mm(m.arm)}}}" if not cpl and num.startswith("-")
                      else f"-\\frac{{{num}{cpl}}}{{{_mm(m.arm)}}}")
            moments.append((f"{where} = {u} \\times {_mm(m.arm)} + ({lhs}){cpl} = 0",
                            f"{u} = {solved} = {res}"
                            r"\ \mathrm{N}", None))
        else:
            moments.append((f"{where} = {u} + ({lhs}) \\times {_scale(mu_l)}{cpl} = 0",
                            f"{u} = {res}" r"\ \text{N·m}", None))
    return moments, couple


def _printed(pos, forces: list[dict]) -> dict[str, str]:
    """Each force of the position's polygon tables as its row prints it (the first row that
    lists it), by its symbol ("R45")."""
    out: dict[str, str] = {}
    for fc, fg in zip(forces, pos.forces):
        for row, v in zip(fc["rows"], _sides(fg)):
            out.setdefault(v.symbol, row[3])
    return out


def _printed_difference(graphical: str, analytic: str, exact: float) -> float:
    """(graphical − analytic)/|analytic| of two printed values; ``exact`` (the unrounded
    values' difference) where one has a power of ten or the analytic one prints as 0."""
    def value(text: str) -> float | None:
        text = text.replace(GROUP, "").replace(" ", "").replace("−", "-")
        try:
            return float(text)
        except ValueError:
            return None
    g, a = value(graphical), value(analytic)
    if g is None or a is None or a == 0:
        return exact
    return (g - a) / abs(a)


def _beside(analytic: float, text: str, graphical: str) -> str:
    """The analytic value of a comparison row (the reference) with at least the decimals of
    the graphical reading beside it, and one more where that reading has fewer than 4
    significant digits (at most 4 decimals), so that the difference computed from the printed
    pair is close to the values' (tgb's F_R23: 123.5 against "123" read 0.4 %, against 123.2
    0.2 %; ω4 1.99 against "2.00" −0.5 %, against 1.996 −0.3 %; page review 47). ``text`` is the row's value as it prints otherwise (in the row's unit; one with a
    power of ten stays so); ``analytic`` the value in that unit."""
    if text == "0" or any(m in t for m in ("×", "times") for t in (text, graphical)):
        return text
    d = min(4, _digits(graphical) + (significant(graphical) < 4))
    return text if _digits(text) >= d else grouped(f(analytic, d))


def _compare_caption(rows: list[list[str]], label: str, lang: str) -> str:
    """The comparison table's caption: how the allowance is set, and the sign of M_b where
    the table has it."""
    _ = tr(lang)
    if any(row[0] == "$M_b$" for row in rows):
        return _("Graphical and analytic results at position {p_label} ($M_b$ positive in the "
                 "crank's sense of rotation; allowed, in {pct} of the analytic value: 2 {pct} plus "
                 "what 1 mm of the velocity polygon, 2 mm of the acceleration and force polygons "
                 "stand for; “—”: the value is less than twice the drawing accuracy, its relative "
                 "difference means little)", p_label=label, pct="%")
    return _("Graphical and analytic results at position {p_label} (allowed, in {pct} of the "
             "analytic value: 2 {pct} plus what 1 mm of the velocity polygon, 2 mm of the "
             "acceleration and force polygons stand for; “—”: the value is less than twice the "
             "drawing accuracy, its relative difference means little)", p_label=label, pct="%")


def comparison_name(quantity: str) -> str:
    """A compared quantity's symbol as the comparison table and the summary write it
    (ω3 → $\\omega_{3}$, v_rA4A3 → $v_{rA4A3}$, R12 → $F_{R12}$)."""
    q = quantity
    return (f"$\\omega_{{{q[1:]}}}$" if q.startswith("ω") else
            f"$\\alpha_{{{q[1:]}}}$" if q.startswith("α") else
            f"$v_{{r{q[3:]}}}$" if q.startswith("v_r") else
            f"${sym(q)}$")


def _compare(pos, lang: str, printed: dict[str, str] | None = None) -> list[list[str]]:
    """The comparison table's rows; a force listed in the polygon tables (``printed``, by
    symbol: itself or its reaction) with the digits it is listed with there (one measured
    value, one number: F_R45 = 66.5 mm × 25 N/mm = 1662.5 N in both tables, issue 19)."""
    printed = printed or {}
    rows = []
    div, force = force_divisor(pos)
    for c in pos.comparison:
        q = c.quantity
        name = comparison_name(q)
        _ = tr(lang)
        mark = _("PASS") if c.passed else _.pgettext("graphical", "beyond")
        shown = printed.get(q, printed.get(_pair(q) or "", _numg(c.graphical)))
        analytic = _numg(c.analytic)
        unit, scale = c.unit, 1.0
        if c.unit == "N" and div != 1.0:
            # the position's forces in kN (its polygon tables): the compared forces too
            unit, scale = force, div
            if q not in printed and (_pair(q) or "") not in printed:
                shown = kn_text(shown, c.graphical)
            analytic = kn_text(analytic, c.analytic)
        analytic = _beside(c.analytic / scale, analytic, shown)
        # a value smaller than the drawing's resolution has no meaningful relative error; the
        # difference is the printed values' (a teacher recomputes it from the row: "1.17 |
        # 1.17 | 0.0", not the 0.4 of the unrounded values; review38), a value with a power
        # of ten aside
        # nor one within twice that resolution: its allowance would exceed 50 % of it (the
        # shaper's ω3 = 0.0736 rad/s was "allowed 98.7 %", which reads as lax; smoke run 43)
        small = abs(c.analytic) < 2 * c.tolerance
        diff = "—" if small else f(100 * _printed_difference(shown, analytic, c.difference), 1)
        # the allowance in % of the analytic value, like the difference beside it (an absolute
        # allowance next to a difference in % read as a false PASS: page review 41)
        allowed = "—" if small else f(100 * c.tolerance / abs(c.analytic), 1)
        rows.append([name, unit, shown, analytic, diff, allowed, mark])
    return rows


def graphical_context(results: dict, figures: dict, lang: str) -> list[dict]:
    """The template context: one entry per linkage (most machines have one)."""
    out = []
    for prefix, doc in documents(results):
        model = _model_of(results, prefix)
        links = {}
        if model is not None:
            mech = model.mechanism
            for n, g in enumerate(mech.groups):
                ids = tuple(g.links) or ((g.link,) if getattr(g, "link", None) else ())
                if ids:
                    links[g.name] = {"links": ids, "crank": n == 0}
        cranks = frozenset(k for v in links.values() if v["crank"] for k in v["links"])
        positions = []
        couple_said = False
        for pos, forces in zip(doc.positions, _force_sections(doc, lang)):
            key = f"{prefix}_graph_{_safe(pos.label)}"
            for fc in forces:
                # the couple term "M_I/mu_l" of a force equation is explained once, where it
                # first appears
                if couple_said:
                    fc["couple"] = None
                couple_said = couple_said or bool(fc["couple"])
            for fc in forces:
                fc["fig"] = figures.get(f"{key}_f{fc['n']}", "")
            crank = next((fc for fc in forces if fc["crank"]), None)
            # a link in translation (a ram, a slider): its ω and α are zero by construction,
            # nothing measured — left out of the lists of rates
            still = frozenset(k for k, w in pos.velocity.rates.items()
                              if w == 0 and pos.acceleration.rates.get(k, 0.0) == 0)
            # the crank's ω and α are the brief's (given), not measured: said apart
            given = [(f"$\\omega_{{{k}}}$ = {sig(pos.velocity.rates[k], 4)} rad/s",
                      f"$\\alpha_{{{k}}}$ = {_numg(pos.acceleration.rates.get(k, 0.0))} rad/s²")
                     for k in sorted(cranks, key=_link_order) if k in pos.velocity.rates]
            still = still | cranks
            positions.append({
                "label": str(pos.label).replace("'", "′"),
                "angle": f(np.degrees(pos.crank_angle), 1),
                "mu_l": _scale(pos.length_scale),
                "vel": _kin(pos.velocity, lang, "m/s", r"\omega", links, still),
                "acc": _kin(pos.acceleration, lang, "m/s²", r"\alpha", links, still),
                "fig": figures.get(f"{key}_kin", ""), "given": given,
                "forces": forces, "crank": crank, "force_unit": force_divisor(pos)[1],
                "mb": None if pos.balancing_torque is None else _numg(pos.balancing_torque),
                "compare": (rows := _compare(pos, lang, _printed(pos, forces))),
                "caption": _compare_caption(rows, str(pos.label).replace("'", "′"), lang),
                "beyond": sum(1 for c in pos.comparison if not c.passed),
            })
        out.append({"prefix": prefix, "step": _mm(doc.step), "positions": positions,
                    "forces": any(p["forces"] for p in positions),
                     "labels": tr(lang).pgettext("list", ", ").join(p["label"] for p in positions)})
    return out


__all__ = ["graphical_figures", "graphical_context", "documents", "sym", "direction"]
