"""Figures of the shaper report (matplotlib, Agg). Computation never imports this.

Every plot runs inside :func:`figure` which creates the axes, saves a PNG and closes
the figure; plot functions take prepared arrays in course units and return nothing.
"""
from __future__ import annotations

import functools
import re
from contextlib import contextmanager
from contextvars import ContextVar
from pathlib import Path

import numpy as np

from ..fileio import atomic_path
from ..i18n import N_
from .fonts import configure_matplotlib
from .legends import legend, settle as settle_legends
from .labels import LabelTable, mpl_point

LABELS = LabelTable({
    "phase": N_("crank angle φ (°)"),
    "s": N_("displacement s (mm)"),
    "v": N_("velocity v (m/s)"),
    "a": N_("acceleration a (m/s²)"),
    "w4": N_(r"$\omega_4$ (rad/s)"),
    "a4": N_(r"$\alpha_4$ (rad/s²)"),
    "mb": N_("balancing torque $M_b$ (N·m)"),
    "md": N_("constant driving torque (on the crank)"),
    "cut": N_("cutting"),
    "energy": N_("energy change ΔE (J)"),
    "dwmax": r"$\Delta W_{max}$",
    "x": "x (mm)",
    "y": "y (mm)",
    "reaction": N_("joint reaction (N)"),
    "reaction_kn": N_("joint reaction (kN)"),
    "guide": N_("ram guide"),
    "working": N_("working stroke"),
    "return": N_("return stroke"),
})


@contextmanager
def figure(path: Path, nrows: int = 1, size: tuple[float, float] = (7.0, 3.2), sharex=True):
    """Create a figure with ``nrows`` axes, yield the axes, save to ``path`` and close."""
    configure_matplotlib()
    import matplotlib

    matplotlib.use("Agg", force=False)
    _share_mathtext_parses()
    import matplotlib.pyplot as plt

    # Created at the saving resolution: tight_layout then measures the text at the same
    # dpi as the drawing, and matplotlib's text-metrics cache serves both.
    fig, axes = plt.subplots(nrows, 1, figsize=size, sharex=sharex, squeeze=False, dpi=DPI)
    try:
        yield [ax for ax in axes[:, 0]]
        save_png(fig, path)
    finally:
        plt.close(fig)


DPI = 150

_MATHTEXT_CACHE: dict = {}
_MATHTEXT_CACHE_SIZE = 1024


def _share_mathtext_parses() -> None:
    """Let every figure reuse the typeset mathtext ($F_{R23}$, $\\mu_F$ …) of the figures
    drawn before it. matplotlib caches a parse per parser (its key holds the parser, and
    each figure's renderer has a parser of its own, in an LRU cache of 50 that measuring
    and drawing share), so each figure typesets every formula again, ~4 ms each; the
    result depends only on the output type, the text, dpi, font and rendering flags,
    which key this cache. Left alone when matplotlib's internals are not as expected."""
    from matplotlib import mathtext

    cls = mathtext.MathTextParser
    if getattr(cls, "_mechdesign_shared", False):
        return
    inner = getattr(cls._parse_cached, "__wrapped__", None)
    if inner is None or inner.__code__.co_varnames[:6] != (
            "self", "s", "dpi", "prop", "antialiased", "load_glyph_flags"):
        return

    def parse_cached(self, s, dpi, prop, antialiased, load_glyph_flags):
        key = (self._output_type, s, dpi, prop, antialiased, load_glyph_flags)
        found = _MATHTEXT_CACHE.get(key)
        if found is None:
            if len(_MATHTEXT_CACHE) >= _MATHTEXT_CACHE_SIZE:
                _MATHTEXT_CACHE.clear()
            found = _MATHTEXT_CACHE[key] = inner(self, s, dpi, prop, antialiased,
                                                 load_glyph_flags)
        return found

    cls._parse_cached = parse_cached
    cls._mechdesign_shared = True
    # a parse holds FT2Font objects, whose open font file (and its offset) a forked figure
    # worker would share with this process: matplotlib clears its own font cache in a
    # forked child for that reason (font_manager._get_font), so this cache is cleared too
    import os

    os.register_at_fork(after_in_child=_MATHTEXT_CACHE.clear)

# the call key (render/cache.py) of the cached figure function being run, if any
_call_key: ContextVar[str | None] = ContextVar("figure_call_key", default=None)


def cached(function):
    """Mark a function that draws one figure into ``path`` (its first argument) with
    :func:`figure` and returns nothing: when the cache holds the figure of the same call
    (the same arguments, rendering code and matplotlib set-up: :func:`.cache.call_key`),
    its PNG is copied and nothing is built or drawn."""
    from . import cache

    @functools.wraps(function)
    def run(path, *args, **kwargs):
        key = cache.call_key(function, args, kwargs)
        if key is not None and cache.fetch(key, Path(path)):
            return None
        token = _call_key.set(key)
        try:
            return function(path, *args, **kwargs)
        finally:
            _call_key.reset(token)

    return run


# "N·m", "kg·m²": the figures' CJK sans has a full-width U+00B7 ("N • m"); the dot operator
# U+22C5, which it lacks, comes from DejaVu Sans (the fallback of render/fonts.py), narrow.
# A text with mathtext ("$M_b$ (N·m)") is laid out by mathtext, which has no fallback: its
# plain parts take the CJK font, which drew U+22C5 as a dummy box; there the dot is the
# math "\cdot" of the mathtext font set (DejaVu Sans).
_UNIT_DOT = re.compile(r"(?<=[A-Za-z])\u00b7(?=[A-Za-z])")
_MATH = re.compile(r"(?<!\\)\$")


def _narrow(value: str) -> str:
    parts = _MATH.split(value)
    if len(parts) < 3 or len(parts) % 2 == 0:          # no mathtext (or an unpaired $)
        return _UNIT_DOT.sub("\u22c5", value)
    # even parts lie outside math, odd parts inside
    return "$".join(_UNIT_DOT.sub(r"$\\cdot$", p) if k % 2 == 0 else p
                    for k, p in enumerate(parts))


def narrow_unit_dots(fig) -> None:
    """Set the middle dot between two letters of every text of ``fig`` narrow: U+22C5 in
    plain text, "\\cdot" in a text with mathtext."""
    from matplotlib.text import Text

    for text in fig.findobj(Text):
        value = text.get_text()
        if "\u00b7" in value:
            text.set_text(_narrow(value))


def save_png(fig, path: Path) -> None:
    """Lay out and write a finished figure as PNG, in a helper process when the report
    is rendered with background saves (:mod:`.parallel`)."""
    from . import cache
    from .parallel import save

    call = _call_key.get()
    italic_symbols(fig)
    upright_subscript_words(fig)
    fit_ylabels(fig)

    def write():
        narrow_unit_dots(fig)
        # the legends off the curves, measured on the texts as printed (render/legends.py)
        laid_out = settle_legends(fig)
        # a figure drawn before with the same state is copied from the cache (render/cache.py)
        key = cache.figure_key(fig, f"tight_layout; png dpi={DPI} zlib=3")
        if not cache.fetch(key, Path(path)):
            if not laid_out:
                fig.tight_layout()
            # tight_layout leaves a placeholder layout engine behind, for which savefig
            # draws the whole figure once more before drawing it (to let a layout engine
            # run): the layout is done, so none is set (the same pixels, one draw less)
            fig.set_layout_engine(None)
            # zlib level 3 instead of 6: a third less time, files ~8 % larger
            with atomic_path(path) as tmp:
                fig.savefig(tmp, dpi=DPI, pil_kwargs={"compress_level": 3})
            cache.store_file(key, Path(path))
        cache.store_file(call, Path(path))

    save(write, Path(path).name)


def _split_label(text: str) -> str | None:
    """``text`` in two lines at the word space nearest its middle outside mathtext, or None
    where it has no such space."""
    inside, spaces = False, []
    for i, c in enumerate(text):
        if c == "$":
            inside = not inside
        elif c == " " and not inside:
            spaces.append(i)
    if not spaces:
        return None
    i = min(spaces, key=lambda k: abs(k - len(text) / 2))
    return text[:i] + "\n" + text[i + 1:]


def fit_ylabels(fig, room: float = 0.98) -> None:
    """A y-axis label longer than its panel is high (a stacked panel's "angular
    acceleration α (rad/s²)", tgb Fig. 2 and lockbeam Fig. 11: it ran into the label of the
    panel above) is set in two lines, broken at a word space; where it is still longer (or has
    no space), in a smaller size down to 6 pt. Measured on the texts as drawn."""
    renderer = None
    for ax in fig.get_axes():
        label = ax.yaxis.label
        if not label.get_text() or not label.get_visible():
            continue
        renderer = renderer or fig.canvas.get_renderer()
        limit = room * ax.get_window_extent(renderer).height
        if label.get_window_extent(renderer).height <= limit:
            continue
        two = _split_label(label.get_text())
        if two is not None:
            label.set_text(two)
        size = label.get_fontsize()
        while label.get_window_extent(renderer).height > limit and size > 6:
            size = max(6.0, size - 0.5)
            label.set_fontsize(size)


_WORD_SUBSCRIPT = re.compile(r"_\{(min|max)\}")


def italic_symbols(fig) -> None:
    """Set the quantity symbols written as text in the figure's labels, legends and notes
    ("crank angle φ (°)", "ΔE", "H − t", "F/M") as mathtext, italic like the report's
    formulas (:func:`~mechdesign.render.labels.mpl_symbols` states the rule)."""
    from matplotlib.text import Text

    from .labels import mpl_symbols

    for t in fig.findobj(Text):
        s = t.get_text()
        if s:
            new = mpl_symbols(s)
            if new != s:
                t.set_text(new)


def upright_subscript_words(fig) -> None:
    """Set the word subscripts of the figure's formulas upright ($\\gamma_{min}$ →
    $\\gamma_{\\mathrm{min}}$), as the report's text sets them (γ_min: the letters of a
    formula are math italic, a word is not)."""
    from matplotlib.text import Text

    for t in fig.findobj(Text):
        s = t.get_text()
        if "$" in s and "_{m" in s:
            t.set_text(_WORD_SUBSCRIPT.sub(r"_{\\mathrm{\1}}", s))


def _phase_axis(ax, working_span_deg: float, positions=None):
    """Crank-angle axis 0–360° with the working stroke shaded; ``positions`` =
    (labels, phases [°], values) marks the textbook positions."""
    ax.set_xlim(0, 360)
    ax.set_xticks(np.arange(0, 361, 30))
    ax.axvspan(0, working_span_deg, color="0.93", zorder=0)
    ax.grid(True, lw=0.4, color="0.8")
    if positions is not None:
        _, ph, values = positions
        ax.plot(ph, values, "o", ms=3, color="C3", zorder=3)


def _staggered(phases_deg, gap_deg: float = 9.0) -> list[int]:
    """The indices of the position labels to lift one row on the top axis: a label closer
    than ``gap_deg`` to the one before it on the lower row, so that "4′" and "5" do not print
    into each other as "4′5" (issue 19)."""
    up, last = [], None
    for i in sorted(range(len(phases_deg)), key=lambda i: phases_deg[i]):
        if last is not None and phases_deg[i] - last < gap_deg:
            up.append(i)
        else:
            last = phases_deg[i]
    return up


@cached
def curves_vs_phase(path: Path, lang: str, phase_deg, series, ylabels, working_span_deg,
                    position_marks=None, size=(7.0, 6.0)):
    """Stacked curves sharing the crank-angle axis; ``series`` is a list of arrays."""
    lab = LABELS[lang]
    with figure(path, len(series), size) as axes:
        for i, (ax, y, yl) in enumerate(zip(axes, series, ylabels)):
            marks = None
            if position_marks is not None:
                marks = (position_marks[0], position_marks[1], position_marks[2][i])
            _phase_axis(ax, working_span_deg, marks)
            ax.plot(phase_deg, y, lw=1.4, color="C0")
            ax.axhline(0, color="0.4", lw=0.6)
            ax.set_ylabel(yl)
        # Stroke names inside the first panel, clear of the position labels on top.
        for x, name in ((working_span_deg / 2, lab["working"]),
                        ((working_span_deg + 360) / 2, lab["return"])):
            axes[0].text(x, 0.09, name, transform=axes[0].get_xaxis_transform(),
                         ha="center", va="bottom", fontsize=8, color="0.35")
        if position_marks is not None:
            top = axes[0].secondary_xaxis("top")
            top.set_xticks(position_marks[1])
            top.set_xticklabels(position_marks[0], fontsize=6)
            top.tick_params(length=2, pad=8)
            ticks = top.xaxis.get_major_ticks()
            for i in _staggered(position_marks[1]):
                ticks[i].set_pad(18)
        axes[-1].set_xlabel(lab["phase"])


@cached
def balancing_torque(path: Path, lang: str, phase_deg, mb, mean_mb, cutting, working_span_deg,
                     position_marks):
    lab = LABELS[lang]
    with figure(path, 1, (7.0, 3.4)) as (ax,):
        _phase_axis(ax, working_span_deg, position_marks)
        on = cutting > 0
        ax.fill_between(phase_deg, 0, 1, where=on, transform=ax.get_xaxis_transform(),
                        color="C1", alpha=0.12, lw=0, label=lab["cut"])
        ax.plot(phase_deg, mb, lw=1.4, color="C0", label=r"$M_b$")
        ax.axhline(mean_mb, color="C2", lw=1.0, ls="--", label=f"{lab['md']} = {mean_mb:.1f} N·m")
        ax.axhline(0, color="0.4", lw=0.6)
        ax.set_xlabel(lab["phase"])
        ax.set_ylabel(lab["mb"])
        legend(ax, fontsize=7, loc="lower left")


@cached
def energy(path: Path, lang: str, phase_deg, energy_j, at_min_deg, at_max_deg, swing,
           working_span_deg):
    lab = LABELS[lang]
    with figure(path, 1, (7.0, 3.4)) as (ax,):
        _phase_axis(ax, working_span_deg)
        ax.plot(phase_deg, energy_j, lw=1.4, color="C0")
        lo, hi = float(np.min(energy_j)), float(np.max(energy_j))
        ax.axhline(lo, color="C3", lw=0.6, ls=":")
        ax.axhline(hi, color="C3", lw=0.6, ls=":")
        ax.plot([at_min_deg, at_max_deg], [lo, hi], "o", color="C3", ms=4)
        x = 0.5 * (at_min_deg + at_max_deg)
        ax.annotate("", xy=(x, hi), xytext=(x, lo), arrowprops=dict(arrowstyle="<->", color="C3"))
        ax.text(x + 4, 0.5 * (lo + hi), f"{lab['dwmax']} = {swing:.1f} J", color="C3", fontsize=8)
        ax.axhline(0, color="0.4", lw=0.6)
        ax.set_xlabel(lab["phase"])
        ax.set_ylabel(lab["energy"])


@cached
def reactions(path: Path, lang: str, phase_deg, named, working_span_deg):
    """The joint reactions [N] against the crank angle; in kN when they reach a million
    newtons (render/fmt.py's :func:`~mechdesign.render.fmt.force_unit`), so that the axis
    has no "1e6" offset."""
    from .fmt import force_unit

    lab = LABELS[lang]
    peak = max((float(np.max(np.abs(v))) for v in named.values() if len(v)), default=0.0)
    scale, unit = force_unit(peak)
    # reactions equal over the whole cycle (a two-force member, a massless block: F_R72 =
    # F_R23 = F_R43) are one curve with one legend entry naming them all; drawn apart, the
    # last hid the others (page review 48: shaper_lengths, slotter, linkage_sixbar Fig. 5)
    curves: list[list] = []
    for name, values in named.items():
        values = np.asarray(values, dtype=float)
        same = next((c for c in curves if c[1].shape == values.shape
                     and np.max(np.abs(c[1] - values), initial=0.0) <= 1e-6 * max(peak, 1e-300)), None)
        if same is None:
            curves.append([[name], values])
        else:
            same[0].append(name)
    with figure(path, 1, (7.0, 3.6)) as (ax,):
        _phase_axis(ax, working_span_deg)
        for names, values in curves:
            ax.plot(phase_deg, values / scale, lw=1.1, label=" = ".join(names))
        ax.set_xlabel(lab["phase"])
        ax.set_ylabel(lab["reaction_kn" if unit == "kN" else "reaction"])
        legend(ax, fontsize=7, ncol=4, loc="upper right")


@cached
def mechanism(path: Path, lang: str, pts: dict, labels, guide_y_mm: float, crank_mm: float):
    """Skeleton of the mechanism at the textbook positions (all in mm).

    ``pts`` maps point names to arrays over the positions (complex, mm); position 0 is
    drawn bold, the others thin with their labels at the crank pin A.
    """
    lab = LABELS[lang]
    with figure(path, 1, (6.2, 7.2), sharex=False) as (ax,):
        o2, o3 = pts["O2"][0], pts["O3"][0]
        t = np.linspace(0, 2 * np.pi, 200)
        ax.plot((o2 + crank_mm * np.exp(1j * t)).real, (o2 + crank_mm * np.exp(1j * t)).imag,
                color="0.6", lw=0.6, ls="--")
        xs = np.concatenate([pts["F"].real, pts["B"].real])
        ax.plot([xs.min() - 120, xs.max() + 120], [guide_y_mm] * 2, color="0.5", lw=0.8, ls="-.")
        ax.text(xs.max() + 120, guide_y_mm + 12, lab["guide"], fontsize=7, ha="right")
        for i, name in enumerate(labels):
            bold = i == 0
            c, lw = ("C0", 1.8) if bold else ("0.55", 0.6)
            a, b, f = pts["A"][i], pts["B"][i], pts["F"][i]
            ax.plot([o2.real, a.real], [o2.imag, a.imag], color="C3" if bold else c, lw=lw)
            ax.plot([o3.real, b.real], [o3.imag, b.imag], color=c, lw=lw)
            ax.plot([b.real, f.real], [b.imag, f.imag], color=c, lw=lw)
            ax.plot([f.real], [f.imag], "s", color=c, ms=5 if bold else 3)
            u = (a - o2) / abs(a - o2)
            ax.text((a + 18 * u).real, (a + 18 * u).imag, name, fontsize=6.5, ha="center", va="center")
        for name, p in (("O2", o2), ("O3", o3)):
            ax.plot([p.real], [p.imag], "^", color="k", ms=6)
            ax.text(p.real + 15, p.imag - 25, mpl_point(name), fontsize=8)
        for name in ("B", "F"):
            p = pts[name][0]
            ax.text(p.real + 10, p.imag + 15, mpl_point(name), fontsize=8, color="C0")
        ax.set_aspect("equal")
        ax.set_xlabel(lab["x"])
        ax.set_ylabel(lab["y"])
        ax.grid(True, lw=0.3, color="0.85")
