"""Animations of a planar mechanism over one crank revolution (GIF).

The drawing is generic: named points (complex positions in mm, one sample per equal
crank-angle step over a revolution), links drawn as polylines of point names, frame
pivots with the ground-hatch symbol, slider blocks, fixed straight guides and the
trace of one point. :func:`linkage_gif` adapts any linkage of the shared stages; a
machine may give its own arguments (the shaper's report does).

Rendering uses matplotlib's Agg canvas directly (no pyplot): the static parts are
drawn once and every frame restores that background and redraws only the moving
artists (blitting). The frames share one palette: exact design colours plus an
adaptive part, applied without dithering, so the GIF stays small.
Computation never imports this module.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Iterator, Mapping, Sequence

import numpy as np

from ..fileio import atomic_path
from ..i18n import tr
from .fonts import configure_matplotlib

DPI = 100
PAD_PX = 30            # free border around the drawing [px]
TITLE_PX = 34          # height of the title band [px] (0 without a title)
MIN_WIDTH_FRAC = 0.6   # the image is at least this fraction of size_px wide
BLOCK_PX = (26.0, 14.0)  # slider block length × height [px]
PIVOT_PX = (8.0, 13.0)   # ground triangle half-width × height [px]
PALETTE_COLORS = 64

# Link colours by the order of ``bars``; the first is the crank.
BAR_COLORS = ("#c0392b", "#1f5fa8", "#2e8b57", "#8e44ad", "#b8860b", "#16a085")
TRACE_COLOR = "#e67e22"
TRACE_PATH_COLOR = "#b4b4b4"
BLOCK_FACE = "#f2d7a0"
INK = "#222222"
GUIDE_COLOR = "#707070"
BACKGROUND = "#ffffff"
BAR_LW = 3.2           # [pt]

def _rgb(color: str) -> tuple[int, int, int]:
    from matplotlib.colors import to_rgb

    return tuple(int(round(255 * c)) for c in to_rgb(color))


@dataclass(frozen=True)
class FrameLayout:
    """Image size and the fixed data → pixel mapping shared by every frame.

    The axes fill the image below the title band; one pixel is ``mm_per_px`` in both
    directions (equal aspect). Pixel columns count from the left edge, rows from the
    top edge of the image (as in ``numpy.asarray(PIL image)``).
    """

    width: int
    height: int
    title_px: int
    xlim: tuple[float, float]
    ylim: tuple[float, float]
    mm_per_px: float

    @property
    def axes_rect(self) -> tuple[float, float, float, float]:
        """Axes position in figure fractions (left, bottom, width, height)."""
        return (0.0, 0.0, 1.0, (self.height - self.title_px) / self.height)

    def to_pixel(self, z) -> tuple[np.ndarray, np.ndarray]:
        """(column, row) pixel coordinates of data points ``z`` (complex, mm)."""
        z = np.asarray(z, dtype=complex)
        col = (z.real - self.xlim[0]) / self.mm_per_px
        row = self.height - (z.imag - self.ylim[0]) / self.mm_per_px
        return col, row


def _even(x: float) -> int:
    return int(2 * np.ceil(x / 2.0))


def mechanism_layout(points: Mapping[str, np.ndarray], *, guides: Sequence = (),
                     title: str = "", size_px: int = 520) -> FrameLayout:
    """Fixed limits covering every point over the revolution (and the guides) with a
    margin; the longer side of the image is about ``size_px``."""
    zs = [np.ravel(np.asarray(v, dtype=complex)) for v in points.values()]
    zs += [np.asarray([a, b], dtype=complex) for a, b in guides]
    z = np.concatenate(zs) if zs else np.zeros(1, complex)
    x0, x1, y0, y1 = z.real.min(), z.real.max(), z.imag.min(), z.imag.max()
    span_x, span_y = x1 - x0, y1 - y0
    floor = max(span_x, span_y, 1.0) * 1e-3  # a degenerate (straight-line) drawing
    span_x, span_y = max(span_x, floor), max(span_y, floor)
    title_px = TITLE_PX if title else 0
    inner_w = size_px - 2 * PAD_PX
    inner_h = size_px - title_px - 2 * PAD_PX
    if inner_w <= 0 or inner_h <= 0:
        raise ValueError(f"size_px={size_px} is too small")
    s = max(span_x / inner_w, span_y / inner_h)
    width = _even(max(span_x / s + 2 * PAD_PX, MIN_WIDTH_FRAC * size_px))
    axes_h = _even(max(span_y / s + 2 * PAD_PX, 0.35 * size_px))
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    return FrameLayout(width, axes_h + title_px, title_px,
                       (cx - width * s / 2, cx + width * s / 2),
                       (cy - axes_h * s / 2, cy + axes_h * s / 2), float(s))


# ---------------------------------------------------------------------------------
# input checks


def _prepare(points, bars, pivots, sliders, trace, frames):
    """Validate names and lengths; return (used points as (N,) arrays, N, frame indices,
    slider angles as (N,) arrays)."""
    names: list[str] = []
    for group in (*bars, pivots, [p for p, _ in sliders], [trace] if trace else []):
        for n in group:
            if n not in names:
                names.append(n)
    if not names:
        raise ValueError("nothing to draw: give bars, pivots, sliders or a trace")
    missing = [n for n in names if n not in points]
    if missing:
        raise KeyError(f"points missing: {', '.join(missing)}")
    arrays = {n: np.atleast_1d(np.asarray(points[n], dtype=complex)) for n in names}
    lengths = {a.size for a in arrays.values() if a.size > 1}
    if len(lengths) > 1:
        raise ValueError(f"point arrays differ in length: {sorted(lengths)}")
    n_samples = lengths.pop() if lengths else 1
    arrays = {n: np.broadcast_to(a.ravel(), (n_samples,)) for n, a in arrays.items()}
    if frames < 1:
        raise ValueError("frames must be ≥ 1")
    frames = min(frames, n_samples)
    idx = (np.arange(frames) * n_samples) // frames
    angles = []
    for name, ang in sliders:
        a = np.atleast_1d(np.asarray(ang, dtype=float)).ravel()
        if a.size not in (1, n_samples):
            raise ValueError(f"slider {name}: angle has {a.size} values, expected 1 or {n_samples}")
        angles.append(np.broadcast_to(a, (n_samples,)))
    for bar in bars:
        if len(bar) < 2:
            raise ValueError(f"a bar needs at least two points: {bar!r}")
    return arrays, n_samples, idx, angles


def animation_layout(points: dict[str, np.ndarray], bars: list[tuple[str, ...]], *,
                     pivots: list[str], sliders: list[tuple[str, float]] = (),
                     guides: list[tuple[complex, complex]] = (), trace: str | None = None,
                     title: str = "", size_px: int = 520, **_ignored) -> FrameLayout:
    """The exact layout :func:`write_mechanism_gif` uses for these arguments (only the
    drawn points count towards the limits)."""
    arrays, *_ = _prepare(points, bars, pivots, list(sliders), trace, 1)
    return mechanism_layout(arrays, guides=list(guides), title=title, size_px=size_px)


# ---------------------------------------------------------------------------------
# drawing


def _ground_symbol(p: complex, s: float):
    """Triangle (closed polyline) and base line + hatch (NaN-separated) under pivot p."""
    hw, h = PIVOT_PX[0] * s, PIVOT_PX[1] * s
    tri = np.array([p, p + complex(-hw, -h), p + complex(hw, -h), p])
    base_y = p.imag - h
    xs = np.linspace(p.real - 1.5 * hw, p.real + 1.5 * hw, 6)
    seg = [complex(p.real - 1.6 * hw, base_y), complex(p.real + 1.6 * hw, base_y), complex(np.nan, np.nan)]
    for x in xs:
        seg += [complex(x, base_y), complex(x - 0.6 * hw, base_y - 0.75 * hw), complex(np.nan, np.nan)]
    return tri, np.array(seg)


def _block(p: complex, angle: float, s: float) -> np.ndarray:
    """Corners of a slider block centred on p, its long side along ``angle``."""
    hl, hh = BLOCK_PX[0] / 2 * s, BLOCK_PX[1] / 2 * s
    u = np.exp(1j * angle)
    c = p + u * np.array([complex(-hl, -hh), complex(hl, -hh), complex(hl, hh), complex(-hl, hh)])
    return np.column_stack([c.real, c.imag])


def _readout_corner(layout: FrameLayout, arrays, guides) -> tuple[float, float, str, str]:
    """Axes-fraction position and alignment of the φ readout: the corner with the
    fewest drawn points (and guide-line samples) nearby."""
    box_w, box_h = 96.0, 26.0
    axes_h = layout.height - layout.title_px
    t = np.linspace(0.0, 1.0, 64)
    z = np.concatenate([*arrays.values(), *(a + (b - a) * t for a, b in guides)])
    col, row = layout.to_pixel(z)
    row = row - layout.title_px  # rows within the axes
    best, best_count = None, None
    for fx, fy, ha, va in ((0.02, 0.02, "left", "bottom"), (0.98, 0.02, "right", "bottom"),
                           (0.02, 0.98, "left", "top"), (0.98, 0.98, "right", "top")):
        c0 = 0 if ha == "left" else layout.width - box_w
        r0 = axes_h - box_h if va == "bottom" else 0
        count = int(np.count_nonzero((col >= c0) & (col <= c0 + box_w) & (row >= r0) & (row <= r0 + box_h)))
        if best_count is None or count < best_count:
            best, best_count = (fx, fy, ha, va), count
    return best


def _render_frames(points, bars, *, pivots, sliders, guides, trace, title, frames,
                   size_px) -> tuple[FrameLayout, Iterator[np.ndarray]]:
    """Set up the figure; return the layout and an iterator over RGBA frames (H×W×4)."""
    configure_matplotlib()
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D
    from matplotlib.patches import Polygon

    arrays, n_samples, idx, angles = _prepare(points, bars, pivots, sliders, trace, frames)
    layout = mechanism_layout(arrays, guides=guides, title=title, size_px=size_px)
    s = layout.mm_per_px

    # +0.01 px so that int(width·dpi) never rounds down
    fig = Figure(figsize=((layout.width + 0.01) / DPI, (layout.height + 0.01) / DPI), dpi=DPI,
                 facecolor=BACKGROUND)
    canvas = FigureCanvasAgg(fig)
    ax = fig.add_axes(layout.axes_rect)
    ax.set_axis_off()
    ax.set_xlim(*layout.xlim)
    ax.set_ylim(*layout.ylim)
    ax.set_aspect("auto")  # equal by construction of the limits
    ax.set_autoscale_on(False)
    if title:
        fig.text(0.5, 1.0 - layout.title_px / 2 / layout.height, title, ha="center",
                 va="center", fontsize=12, color=INK)

    # static: guides, full trace, ground symbols
    for a, b in guides:
        ax.add_line(Line2D([a.real, b.real], [a.imag, b.imag], color=GUIDE_COLOR, lw=0.8,
                           ls="-.", zorder=1))
    if trace:
        path = np.append(arrays[trace], arrays[trace][:1])
        ax.add_line(Line2D(path.real, path.imag, color=TRACE_PATH_COLOR, lw=1.0, zorder=2))
    for name in pivots:
        tri, hatch = _ground_symbol(complex(arrays[name][0]), s)
        ax.add_patch(Polygon(np.column_stack([tri.real, tri.imag]), closed=True,
                             facecolor="#dddddd", edgecolor=INK, lw=0.9, zorder=3))
        ax.add_line(Line2D(hatch.real, hatch.imag, color=INK, lw=0.9, zorder=3))

    # moving: drawn in this order every frame
    moving = []
    travelled = None
    if trace:
        travelled = Line2D([], [], color=TRACE_COLOR, lw=1.8, animated=True)
        moving.append(travelled)
    bar_lines = []
    for i, bar in enumerate(bars):
        line = Line2D([], [], color=BAR_COLORS[i % len(BAR_COLORS)], lw=BAR_LW,
                      solid_capstyle="round", solid_joinstyle="round", animated=True)
        bar_lines.append((bar, line))
        moving.append(line)
    blocks = []
    for (name, _), ang in zip(sliders, angles):
        patch = Polygon(np.zeros((4, 2)), closed=True, facecolor=BLOCK_FACE, edgecolor=INK,
                        lw=1.0, animated=True)
        blocks.append((name, ang, patch))
        moving.append(patch)
    joint_names = []
    for group in (*bars, [p for p, _ in sliders], pivots):
        for n in group:
            if n not in joint_names:
                joint_names.append(n)
    joints = Line2D([], [], ls="none", marker="o", ms=4.5, mfc="white", mec=INK, mew=1.0,
                    animated=True)
    moving.append(joints)
    fx, fy, ha, va = _readout_corner(layout, arrays, guides)
    readout = ax.text(fx, fy, "", transform=ax.transAxes, ha=ha, va=va, fontsize=10,
                      color=INK, animated=True)
    moving.append(readout)
    for artist in moving:
        if artist is not readout:
            (ax.add_line if isinstance(artist, Line2D) else ax.add_patch)(artist)

    canvas.draw()
    background = canvas.copy_from_bbox(fig.bbox)
    w, h = canvas.get_width_height()
    if (w, h) != (layout.width, layout.height):  # pragma: no cover - defensive
        raise RuntimeError(f"canvas is {w}×{h}, expected {layout.width}×{layout.height}")

    def frames_iter() -> Iterator[np.ndarray]:
        for k in idx:
            canvas.restore_region(background)
            if travelled is not None:
                part = arrays[trace][: k + 1]
                travelled.set_data(part.real, part.imag)
            for bar, line in bar_lines:
                z = np.array([arrays[n][k] for n in bar])
                line.set_data(z.real, z.imag)
            for name, ang, patch in blocks:
                patch.set_xy(_block(complex(arrays[name][k]), float(ang[k]), s))
            zj = np.array([arrays[n][k] for n in joint_names])
            joints.set_data(zj.real, zj.imag)
            readout.set_text(f"φ = {360.0 * k / n_samples:.0f}°")
            for artist in moving:
                ax.draw_artist(artist)
            yield np.asarray(canvas.buffer_rgba()).copy()

    return layout, frames_iter()


def _pil_constants():
    from PIL import Image

    quantize = getattr(Image, "Quantize", Image)  # enums since Pillow 9.1
    dither = getattr(Image, "Dither", Image)
    return quantize.MEDIANCUT, dither.NONE


def _palette_image(sample_rgb: np.ndarray):
    """A P-mode image whose palette holds the design colours exactly, then an adaptive
    palette of ``sample_rgb`` (the antialiasing shades) up to PALETTE_COLORS entries."""
    from PIL import Image

    mediancut, _ = _pil_constants()
    fixed = [_rgb(c) for c in (BACKGROUND, INK, *BAR_COLORS, TRACE_COLOR, TRACE_PATH_COLOR,
                               BLOCK_FACE, GUIDE_COLOR, "#dddddd")]
    fixed = list(dict.fromkeys(fixed))
    adaptive = Image.fromarray(sample_rgb).quantize(
        colors=PALETTE_COLORS - len(fixed), method=mediancut)
    extra = np.asarray(adaptive.getpalette()[: 3 * (PALETTE_COLORS - len(fixed))],
                       dtype=np.uint8).reshape(-1, 3)
    colors = fixed + [tuple(int(v) for v in c) for c in extra if tuple(int(v) for v in c) not in fixed]
    colors = colors[:PALETTE_COLORS]
    flat = [v for c in colors for v in c]
    flat += flat[-3:] * (256 - len(colors))  # pad by repeating the last colour
    pal = Image.new("P", (1, 1))
    pal.putpalette(flat)
    return pal


def write_mechanism_gif(path, points: dict[str, np.ndarray], bars: list[tuple[str, ...]], *,
                        pivots: list[str], sliders: list[tuple[str, float]] = (),
                        guides: list[tuple[complex, complex]] = (), trace: str | None = None,
                        title: str = "", frames: int = 72, fps: int = 18,
                        size_px: int = 520) -> Path:
    """Write an animated GIF of the mechanism turning through one revolution.

    ``points`` maps names to complex positions [mm] over one crank revolution at equal
    crank-angle steps (N samples; a scalar is a fixed point); they are subsampled
    evenly to ``frames`` (at most N). ``bars`` are polylines of point names;
    ``pivots`` get the ground symbol; ``sliders`` are (point, angle [rad]) with the
    angle a float or an (N,) array; ``guides`` are fixed lines (start, end) [mm];
    ``trace`` is the point whose path is drawn. The longer image side is about
    ``size_px``; the file is written atomically. Returns the path.
    """
    from PIL import Image

    path = Path(path)
    layout, it = _render_frames(points, bars, pivots=pivots, sliders=list(sliders),
                                guides=list(guides), trace=trace, title=title,
                                frames=frames, size_px=size_px)
    rgb = [f[:, :, :3] for f in it]
    sample = np.concatenate([rgb[i] for i in sorted({0, len(rgb) // 4, len(rgb) // 2,
                                                     3 * len(rgb) // 4, len(rgb) - 1})], axis=0)
    pal = _palette_image(np.ascontiguousarray(sample))
    _, no_dither = _pil_constants()
    images = [Image.fromarray(np.ascontiguousarray(f)).quantize(palette=pal, dither=no_dither)
              for f in rgb]
    with atomic_path(path) as tmp:
        images[0].save(tmp, format="GIF", save_all=True, append_images=images[1:], loop=0,
                       optimize=True, duration=1000.0 / fps, disposal=2)
    return path


def linkage_animation_args(model, k, title: str = "") -> dict:
    """Arguments of :func:`write_mechanism_gif` for any linkage of the shared stages (mm)."""
    from ..stages.linkage import link_members

    n = k.grid_size
    members, sliders = link_members(model.mechanism)
    pts = {name: np.asarray(z[:n], dtype=complex) * 1e3 for name, z in k.points.items()}
    bars = [tuple(p) for p in members.values() if len(p) >= 2]
    blocks, guides = [], []
    for _slider, p, guide, gp in sliders:
        if isinstance(guide, float):
            u = np.exp(1j * guide)
            along = (np.conj(u) * (pts[p] - gp * 1e3)).real
            extra = 0.3 * max(float(np.ptp(along)), 1.0)
            guides.append((gp * 1e3 + (along.min() - extra) * u, gp * 1e3 + (along.max() + extra) * u))
            blocks.append((p, guide))
        else:
            blocks.append((p, np.asarray(k.link_angle[guide][:n])))
    trace = model.output.name if model.output.kind == "point" else None
    return dict(points=pts, bars=bars, pivots=list(model.mechanism.frame_points), sliders=blocks,
                guides=guides, trace=trace, title=title)


def linkage_gif(model, k, path, lang: str, **kwargs) -> Path:
    """Animate a linkage of the shared stages over one crank revolution as a GIF."""
    _ = tr(lang)
    args = linkage_animation_args(model, k, _("Linkage motion"))
    return write_mechanism_gif(path, args.pop("points"), args.pop("bars"), **args, **kwargs)
