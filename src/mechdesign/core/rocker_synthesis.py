"""Two-position synthesis of a four-bar whose input and output links both rock
(双摇杆机构按两连架杆的两组对应位置设计), and the position analysis that checks it.

Textbook method (孙桓《机械原理》 §8 平面连杆机构的设计, 按给定两连架杆对应位置设计四杆机构;
graphically by inversion, 刚化反转法), written analytically.

Coordinates: the input pivot A0 at the origin, the output pivot B0 at (d, 0); angles CCW
from the line A0→B0. The input rocker A0A (length a) turns from α1 to α2 = α1 + Δα, the
output rocker B0B (length c, given) from β1 to β2 = β1 + Δβ. The coupler AB (length b)
is rigid, so the loop-closure equation holds in both positions:

    |a·e^{iα_k} − B_k| = b,   B_k = d + c·e^{iβ_k},   k = 1, 2.

Squaring (|a u_k − B_k|² = a² − 2a·Re(u_k B̄_k) + |B_k|², u_k = e^{iα_k}) and subtracting
the two equations removes a² and b² and leaves an equation linear in a:

    a = (|B1|² − |B2|²) / (2·Re(u1 B̄1 − u2 B̄2)),   then b = |a u1 − B1|.

(In the inversion construction, A1 is where the perpendicular bisector of B1 and B2
turned back by −Δα about A0 meets the input rocker's first position.)

The start angles α1, β1 are the designer's choice (the seed: "先设定一个起始位置").
:func:`best_start` chooses them to maximise the smallest transmission angle over the
stroke, the lengths kept within bounds. A design is valid only if both positions lie on
one assembly branch and the output turns one way without a dead point between them; the
analysis (:func:`sweep`) solves the position for the whole swing on the start's branch.

Transmission angle γ: the acute angle between the coupler AB and the output rocker B0B
(the output is driven through the coupler), γ = min(δ, π − δ).

Velocity ratio: differentiating the closure a e^{iα} + b e^{iθ} = d + c e^{iβ} (θ the
coupler's angle) and eliminating dθ gives

    dβ/dα = a·sin(α − θ) / (c·sin(β − θ)),

which is also the torque ratio T_in/T_out (virtual work, no friction). Its mean over the
stroke is fixed, Δβ/Δα; its peak sets the largest input torque for a given output torque
(the cam's largest force when the bending torque is constant), so :func:`best_start` can
bound it.

Everything is SI (metres) and radians; nothing here does I/O.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import Msg, N_
from .fourbar import SynthesisError

TWO_PI = 2.0 * np.pi


@dataclass(frozen=True)
class RockerDesign:
    """A double-rocker four-bar A0-A-B-B0 [m, rad]: frame d, input rocker a, coupler b,
    output rocker c; the input turns α1 → α1 + Δα while the output turns β1 → β1 + Δβ on
    assembly branch ``branch`` (+1: B to the left of A→B0, counter-clockwise; −1 right)."""

    frame: float
    input_rocker: float
    coupler: float
    output_rocker: float
    alpha1: float
    dalpha: float
    beta1: float
    dbeta: float
    branch: int


@dataclass(frozen=True)
class Sweep:
    """Position analysis over the input swing (arrays over ``alpha``)."""

    alpha: np.ndarray           # input angle [rad]
    beta: np.ndarray            # output angle [rad], continuous (unwrapped); nan if not assembled
    gamma: np.ndarray           # transmission angle at B [rad]
    assembled: bool             # every input angle can be assembled
    monotonic: bool             # the output turns one way only
    swing: float                # β(end) − β(start) [rad] (nan if not assembled)
    ratio: np.ndarray           # velocity ratio dβ/dα [–]

    @property
    def ratio_peak(self) -> float:
        """Largest |dβ/dα| over the stroke."""
        return float(np.max(np.abs(self.ratio))) if self.assembled else float("inf")

    @property
    def gamma_min(self) -> float:
        return float(np.min(self.gamma)) if self.assembled else 0.0

    @property
    def gamma_max(self) -> float:
        return float(np.max(self.gamma)) if self.assembled else 0.0


# ----------------------------------------------------------------------------- closed form

def two_position(frame: float, output_rocker: float, alpha1, dalpha, beta1, dbeta):
    """(a, b) [m] from the two loop-closure equations (vectorised over the angles).

    a may come out ≤ 0 or infinite (the two conditions are incompatible for these angles:
    the denominator vanishes); callers check it."""
    d, c = frame, output_rocker
    a1 = np.asarray(alpha1, dtype=float)
    b1 = np.asarray(beta1, dtype=float)
    u1, u2 = np.exp(1j * a1), np.exp(1j * (a1 + dalpha))
    B1, B2 = d + c * np.exp(1j * b1), d + c * np.exp(1j * (b1 + dbeta))
    den = 2.0 * (np.real(u1 * np.conj(B1)) - np.real(u2 * np.conj(B2)))
    with np.errstate(divide="ignore", invalid="ignore"):
        a = (np.abs(B1) ** 2 - np.abs(B2) ** 2) / den
    b = np.abs(a * u1 - B1)
    return a, b


def output_angle(frame, a, b, c, alpha, branch):
    """Output angle β [rad] for input angles ``alpha`` on ``branch`` (vectorised; nan where
    the coupler cannot reach). β = arg(A − B0) − σ·arccos((c² + r² − b²)/(2cr)), r = |A − B0|:
    σ = +1 puts B to the left of A→B0."""
    A = a * np.exp(1j * np.asarray(alpha, dtype=float))
    AB0 = A - frame
    r = np.abs(AB0)
    with np.errstate(divide="ignore", invalid="ignore"):
        cosg = (c * c + r * r - b * b) / (2.0 * c * r)
    g = np.arccos(np.where(np.abs(cosg) <= 1.0 + 1e-12, np.clip(cosg, -1.0, 1.0), np.nan))
    return np.angle(AB0) - branch * g


def branch_of(design_or_lengths, alpha1: float | None = None, beta1: float | None = None) -> int:
    """The branch (+1/−1) on which the configuration (α1, β1) lies: the side of the line
    A→B0 that B is on."""
    if isinstance(design_or_lengths, RockerDesign):
        ds = design_or_lengths
        d, a, c = ds.frame, ds.input_rocker, ds.output_rocker
        alpha1, beta1 = ds.alpha1, ds.beta1
    else:
        d, a, c = design_or_lengths
    A = a * np.exp(1j * alpha1)
    B = d + c * np.exp(1j * beta1)
    side = np.imag(np.conj(d - A) * (B - A))
    return 1 if side > 0 else -1


def transmission_angle(frame, a, c, alpha, beta):
    """γ [rad] at B between the coupler AB and the output rocker B0B (vectorised)."""
    A = a * np.exp(1j * np.asarray(alpha, dtype=float))
    B = frame + c * np.exp(1j * np.asarray(beta, dtype=float))
    delta = np.abs(np.angle((B - A) * np.conj(B - frame)))
    return np.minimum(delta, np.pi - delta)


def velocity_ratio(frame, a, c, alpha, beta):
    """dβ/dα = a·sin(α − θ)/(c·sin(β − θ)), θ the coupler's angle (vectorised)."""
    alpha = np.asarray(alpha, dtype=float)
    beta = np.asarray(beta, dtype=float)
    A = a * np.exp(1j * alpha)
    B = frame + c * np.exp(1j * beta)
    theta = np.angle(B - A)
    with np.errstate(divide="ignore", invalid="ignore"):
        return a * np.sin(alpha - theta) / (c * np.sin(beta - theta))


def sweep(ds: RockerDesign, n: int = 721, alpha=None) -> Sweep:
    """Position analysis of the design over its input swing (``n`` points) or over the
    input angles ``alpha``, on the start's branch."""
    if alpha is None:
        alpha = ds.alpha1 + ds.dalpha * np.linspace(0.0, 1.0, n)
    alpha = np.asarray(alpha, dtype=float)
    raw = output_angle(ds.frame, ds.input_rocker, ds.coupler, ds.output_rocker, alpha, ds.branch)
    assembled = bool(np.all(np.isfinite(raw)))
    if not assembled:
        nan = np.full_like(alpha, np.nan)
        return Sweep(alpha, nan, nan, False, False, float("nan"), nan)
    # Continuous output angle measured from β1 (the first point is β1 up to rounding).
    beta = ds.beta1 + np.unwrap(np.angle(np.exp(1j * (raw - ds.beta1))))
    steps = np.diff(beta)
    monotonic = bool(np.all(steps > 0) or np.all(steps < 0)) if len(steps) else True
    gamma = transmission_angle(ds.frame, ds.input_rocker, ds.output_rocker, alpha, beta)
    ratio = velocity_ratio(ds.frame, ds.input_rocker, ds.output_rocker, alpha, beta)
    return Sweep(alpha, beta, gamma, True, monotonic, float(beta[-1] - beta[0]), ratio)


# ----------------------------------------------------------------------------- designs

def _check_data(frame, output_rocker, dalpha, dbeta):
    if not (np.isfinite(frame) and frame > 0):
        raise SynthesisError(N_("frame length {frame} must be positive"), frame=frame)
    if not (np.isfinite(output_rocker) and output_rocker > 0):
        raise SynthesisError(N_("output rocker length {output_rocker} must be positive"),
                             output_rocker=output_rocker)
    for name, x in ((N_("input swing {x_deg:.6g}°"), dalpha),
                    (N_("output swing {x_deg:.6g}°"), dbeta)):
        if not (np.isfinite(x) and 0.0 < abs(x) < np.pi):
            raise SynthesisError(N_("{swing} must be between 0° and 180° (a rocker)"),
                                 swing=Msg(name, x_deg=np.degrees(x)))


def design_two_position(frame: float, output_rocker: float, alpha1: float, dalpha: float,
                        beta1: float, dbeta: float, n: int = 721) -> RockerDesign:
    """The design for the given start angles; raises SynthesisError (naming what is wrong)
    when the lengths come out non-positive or the two positions are not joined by a
    continuous one-way motion on one branch."""
    _check_data(frame, output_rocker, dalpha, dbeta)
    a, b = (float(x) for x in two_position(frame, output_rocker, alpha1, dalpha, beta1, dbeta))
    where = Msg(N_("with the input rocker starting at {alpha1_deg:.6g}° and the output at "
                   "{beta1_deg:.6g}°"), alpha1_deg=np.degrees(alpha1), beta1_deg=np.degrees(beta1))
    if not (np.isfinite(a) and a > 0):
        raise SynthesisError(N_("{where} the loop equations give an input rocker of "
                                "{a_mm:.6g} mm (not a positive length): choose other start "
                                "angles"), where=where, a_mm=a * 1e3)
    branch = branch_of((frame, a, output_rocker), alpha1, beta1)
    ds = RockerDesign(frame, a, b, output_rocker, float(alpha1), float(dalpha), float(beta1),
                      float(dbeta), branch)
    sw = sweep(ds, n)
    if not sw.assembled:
        raise SynthesisError(N_("{where} (a = {a_mm:.6g} mm, b = {b_mm:.6g} mm) the linkage "
                                "cannot be assembled over the whole input swing"),
                             where=where, a_mm=a * 1e3, b_mm=b * 1e3)
    if abs(sw.beta[0] - beta1) > 1e-9 or not sw.monotonic or abs(sw.swing - dbeta) > 1e-7:
        raise SynthesisError(
            N_("{where} (a = {a_mm:.6g} mm, b = {b_mm:.6g} mm) the two positions are not "
               "joined by a one-way motion on one assembly branch (the output turns "
               "{swing_deg:.6g}° instead of {dbeta_deg:.6g}°, or reverses): choose other "
               "start angles"), where=where, a_mm=a * 1e3, b_mm=b * 1e3,
            swing_deg=np.degrees(sw.swing), dbeta_deg=np.degrees(dbeta))
    return ds


def _scan(frame, c, dalpha, dbeta, alpha1, beta1, bounds, n, ratio_limit=None):
    """Vectorised over the (α1, β1) arrays: γ_min (−1 where the design is invalid or its peak
    velocity ratio exceeds ``ratio_limit``), the lengths a, b and the peak |dβ/dα|."""
    a, b = two_position(frame, c, alpha1, dalpha, beta1, dbeta)
    lo, hi = bounds
    ok = np.isfinite(a) & (a >= lo) & (a <= hi) & (b >= lo) & (b <= hi)
    A1 = a * np.exp(1j * alpha1)
    B1 = frame + c * np.exp(1j * beta1)
    branch = np.where(np.imag(np.conj(frame - A1) * (B1 - A1)) > 0, 1.0, -1.0)
    t = np.linspace(0.0, 1.0, n)
    al = alpha1[..., None] + dalpha * t
    raw = output_angle(frame, a[..., None], b[..., None], c, al, branch[..., None])
    rel = np.unwrap(np.angle(np.exp(1j * (raw - beta1[..., None]))), axis=-1)
    steps = np.diff(rel, axis=-1)
    with np.errstate(invalid="ignore"):
        mono = np.all(steps * np.sign(dbeta) > 0, axis=-1)
        reach = np.abs(rel[..., -1] - dbeta) < 1e-6
    finite = np.all(np.isfinite(raw), axis=-1)
    valid = ok & finite & mono & reach
    beta = beta1[..., None] + rel
    gam = transmission_angle(frame, a[..., None], c, al, beta)
    ratio = np.abs(velocity_ratio(frame, a[..., None], c, al, beta))
    with np.errstate(invalid="ignore"):
        peak = np.nanmax(np.where(np.isfinite(ratio), ratio, np.inf), axis=-1)
        if ratio_limit is not None:
            valid &= peak <= ratio_limit
    gmin = np.where(valid, np.nanmin(np.where(np.isfinite(gam), gam, np.inf), axis=-1), -1.0)
    return gmin, a, b, peak


def best_start(frame: float, output_rocker: float, dalpha: float, dbeta: float,
               length_bounds: tuple[float, float], ratio_limit: float | None = None,
               step: float = np.radians(2.0), samples: int = 61) -> tuple[RockerDesign, float]:
    """(design, γ_min [rad]) with the start angles that maximise the smallest transmission
    angle over the stroke, the input rocker and the coupler within ``length_bounds`` [m] and,
    if given, the peak velocity ratio |dβ/dα| at most ``ratio_limit``.

    A scan of every (α1, β1) on a grid of ``step`` (vectorised, ``samples`` points along the
    swing), then a pattern search: 9 × 9 local grids, each a quarter of the previous spacing,
    on 721 points along the swing, down to 1e-7 rad (the constraint makes the optimum lie on
    its boundary, where a derivative-free grid refinement is robust). Raises SynthesisError
    when no start on the grid gives a valid design."""
    _check_data(frame, output_rocker, dalpha, dbeta)
    lo, hi = length_bounds
    if not (0 < lo < hi):
        raise SynthesisError(N_("length bounds {lo_mm:.6g} … {hi_mm:.6g} mm are not an "
                                "interval"), lo_mm=lo * 1e3, hi_mm=hi * 1e3)
    grid = np.arange(0.0, TWO_PI, step)
    best = (-1.0, None)
    for a1 in np.array_split(grid, max(1, len(grid) // 30)):
        A1, B1 = np.meshgrid(a1, grid, indexing="ij")
        g, _, _, _ = _scan(frame, output_rocker, dalpha, dbeta, A1, B1, (lo, hi), samples,
                           ratio_limit)
        k = np.unravel_index(int(np.argmax(g)), g.shape)
        if g[k] > best[0]:
            best = (float(g[k]), (float(A1[k]), float(B1[k])))
    if best[1] is None or best[0] <= 0:
        extra = ("" if ratio_limit is None else
                 Msg(N_(" and a peak velocity ratio |dβ/dα| ≤ {ratio:.6g}"), ratio=ratio_limit))
        raise SynthesisError(
            N_("no start position gives a valid linkage with the input rocker and the coupler "
               "between {lo_mm:.6g} and {hi_mm:.6g} mm{extra} (frame {frame_mm:.6g} mm, output "
               "rocker {rocker_mm:.6g} mm, swings {dalpha_deg:.6g}° and {dbeta_deg:.6g}°): widen "
               "the length range or relax the ratio limit"),
            lo_mm=lo * 1e3, hi_mm=hi * 1e3, extra=extra, frame_mm=frame * 1e3,
            rocker_mm=output_rocker * 1e3, dalpha_deg=np.degrees(dalpha),
            dbeta_deg=np.degrees(dbeta))
    g_best, x = best[0], np.array(best[1])
    h = step
    offsets = np.arange(-4, 5)
    while h > 1e-7:
        h /= 4.0
        da, db = np.meshgrid(x[0] + offsets * h, x[1] + offsets * h, indexing="ij")
        g, _, _, _ = _scan(frame, output_rocker, dalpha, dbeta, da, db, (lo, hi), 721,
                           ratio_limit)
        k = np.unravel_index(int(np.argmax(g)), g.shape)
        if g[k] > g_best:
            g_best, x = float(g[k]), np.array([da[k], db[k]])
    a1, b1 = float(np.mod(x[0], TWO_PI)), float(np.mod(x[1], TWO_PI))
    ds = design_two_position(frame, output_rocker, a1, dalpha, b1, dbeta)
    return ds, sweep(ds).gamma_min


# ----------------------------------------------------------------------------- given lengths

@dataclass(frozen=True)
class LengthCheck:
    """What a four-bar of given lengths does with the given input swing, whatever its start.

    Only branch +1 is scanned: the mirror image of the linkage about the frame line is the
    branch −1 assembly, and it traverses the mirrored positions in the opposite order, so it
    gives the same swings. ``starts``: the start positions (α1, β1, γ_min) at which the
    output swing |Δβ| is exactly the target; ``swing_range``: the smallest and largest |Δβ|
    over every start from which the linkage moves through the whole input swing one way
    [rad]; ``alpha``/``swing`` the scan itself (nan where not valid)."""

    target: float
    starts: tuple[tuple[float, float, float], ...]
    swing_range: tuple[float, float]
    alpha: np.ndarray
    swing: np.ndarray


def check_lengths(frame: float, input_rocker: float, coupler: float, output_rocker: float,
                  dalpha: float, target: float, n: int = 1441, samples: int = 181) -> LengthCheck:
    """Scan the input's start angle α1 over a revolution: the output swing |Δβ| produced by
    the input swing Δα (nan where the linkage cannot move through the whole swing one way),
    and the starts where |Δβ| equals ``target`` (Brent's method between scan points)."""
    from .extremes import brentq

    d, a, b, c = frame, input_rocker, coupler, output_rocker
    alpha = np.linspace(0.0, TWO_PI, n)
    t = np.linspace(0.0, 1.0, samples)

    def swings(a1):
        a1 = np.atleast_1d(np.asarray(a1, dtype=float))
        al = a1[:, None] + dalpha * t
        raw = output_angle(d, a, b, c, al, 1)
        rel = np.unwrap(raw - raw[:, :1], axis=-1)
        steps = np.diff(rel, axis=-1)
        with np.errstate(invalid="ignore"):
            mono = np.all(steps > 0, axis=-1) | np.all(steps < 0, axis=-1)
        ok = np.all(np.isfinite(raw), axis=-1) & mono
        return np.where(ok, np.abs(rel[:, -1]), np.nan), raw[:, 0]

    sw, _ = swings(alpha)
    f = sw - target
    starts = []
    for i in range(n - 1):
        if np.isfinite(f[i]) and np.isfinite(f[i + 1]) and f[i] * f[i + 1] < 0:
            root = brentq(lambda x: float(swings(x)[0][0] - target), alpha[i], alpha[i + 1],
                          xtol=1e-14)
            beta1 = float(swings(root)[1][0])
            ds = RockerDesign(d, a, b, c, float(root % TWO_PI), dalpha, beta1, 0.0, 1)
            starts.append((float(root % TWO_PI), beta1 % TWO_PI, sweep(ds, samples).gamma_min))
    vals = sw[np.isfinite(sw)]
    rng = (float(np.min(vals)), float(np.max(vals))) if len(vals) else (float("nan"), float("nan"))
    return LengthCheck(target, tuple(starts), rng, alpha, sw)
