"""Incomplete gear (不完全齿轮机构) intermittent drive, designed from the timing.

Method (孙桓《机械原理》第11章 其他常用机构, 不完全齿轮机构): the driver (主动轮 1) carries
teeth on part of its rim only and turns continuously, once per machine cycle; while its
teeth mesh, the driven wheel (从动轮 2) turns at the constant ratio of a complete gear pair;
while the toothless part passes, the driver's convex locking arc (凸锁止弧) slides in the
driven wheel's concave locking arc (凹锁止弧) and holds it still. The formulas used:

* pitch radii and centre distance of the standard external pair (module m, α = 20°,
  h_a* = 1, c* = 0.25 unless given): r = m z / 2, r_a = r + h_a* m,
  r_f = r − (h_a* + c*) m, a = m (z1 + z2) / 2;
* z1 is the driver's notional tooth count (the teeth it would have if complete), z1' the
  teeth actually cut on it; they occupy z1' pitches of the driver, so the driver's motion
  angle is φ_m = 2π z1'/z1 and the dwell angle φ_d = 2π − φ_m;
* the z1' teeth push the driven wheel through z1' of its pitches: its advance per cycle is
  Δφ2 = 2π z1'/z2 (a chain feed L = R_s Δφ2 through a sprocket of pitch radius R_s);
* motion/dwell ratio (动停比) k = t_m / t_d = φ_m / φ_d; kinematic coefficient (运动系数)
  τ = t_m / T = φ_m / 2π;
* while meshing ω2 = ω1 z1 / z2 (constant), in the dwell ω2 = 0: at the start and at the
  end of the meshing the driven wheel's speed jumps by ω1 z1 / z2 — in the ideal model an
  infinite acceleration, the rigid impact (刚性冲击) the textbook names; this limits the
  drive to low speeds and light driven masses (real drives shorten the first and last
  teeth (首末齿齿顶修短) or add an instant-centre link (瞬心线附加杆) to soften it);
* the locking-arc radius is taken as the driver's tip radius, R_L = r_a1 (the driven wheel's
  concave arcs are cut to the same radius about the driver's axis when it is locked).

The ideal constant-ratio model is used: the contact just before and after the toothed
arc (contact ratio > 1, the shortened end teeth) is neglected. SI units: m, rad, rad/s.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from math import gcd

from ..lazy import np     # the design from the timing is scalar arithmetic: validating a brief needs no numpy

from .errors import DesignError
from .fields import q

TWO_PI = 2.0 * math.pi
DEG = 180.0 / math.pi
#: Default allowed difference between a requested timing angle and the one whole teeth give [rad].
TIMING_TOL = 1e-6
#: Angles this close to the start or end of the meshing count as on it [rad].
BOUNDARY_TOL = 1e-9


class IntermittentDesignError(DesignError):
    """An incomplete gear that cannot meet the timing with whole teeth; the message says
    what to change. ``field`` names the input to change: module, z1, z2, teeth,
    motion_span, advance (or the feed that gave it), feed or sprocket_radius."""

    def __init__(self, en: str, zh: str | None = None, field: str | None = None):
        super().__init__(en, zh)
        self.field = field

    def __reduce__(self):
        return (type(self), (self.en, self.zh, self.field))


@dataclass(frozen=True)
class DesignNote:
    """A problem that leaves the design computable (a machine turns it into a Finding:
    ``Finding(note.code, note.zh, note.en)``)."""

    code: str
    zh: str
    en: str


@dataclass(frozen=True)
class DrivenMotion:
    """The driven wheel over the driver angle θ (arrays of the same shape as θ)."""

    theta: np.ndarray     # driver (shaft) angle [rad], as given
    angle: np.ndarray     # driven angle turned since the window's start (see driven_motion) [rad]
    ratio: np.ndarray     # dφ2/dθ: z1/z2 while meshing, exactly 0 in the dwell
    moving: np.ndarray    # True while meshing
    omega: np.ndarray | None = None    # driven angular velocity [rad/s] (needs the driver speed)
    travel: np.ndarray | None = None   # chain travel R_s·φ2 [m] (needs the sprocket radius)


@dataclass(frozen=True)
class EngagementJump:
    """Speed jump of the driven wheel at engagement (and back at disengagement)."""

    omega2: float          # jump of ω2 [rad/s], or of dφ2/dθ without a driver speed
    pitch_speed: float     # pitch-line speed ω1 r1 reached at once [m/s] (or r1 per rad)
    chain_speed: float | None   # chain speed jump R_s ω2 [m/s] (or per rad), with a sprocket


@dataclass(frozen=True)
class IncompleteGear:
    """A designed incomplete gear drive (all lengths in m, angles in rad)."""

    module: float
    z1: int                       # driver's notional full tooth count
    z2: int                       # driven wheel's tooth count (complete)
    teeth: int                    # teeth present on the driver z1'
    alpha: float                  # pressure angle
    ha_star: float
    c_star: float
    motion_start: float           # shaft angle where meshing begins [rad]
    driver_speed: float | None    # ω1 [rad/s]
    sprocket_radius: float | None # R_s [m]
    locking_radius: float         # R_L [m]
    requested_motion_angle: float | None
    requested_advance: float | None
    notes: tuple[DesignNote, ...] = ()

    # --- geometry
    @property
    def r1(self) -> float:
        return self.module * self.z1 / 2

    @property
    def r2(self) -> float:
        return self.module * self.z2 / 2

    @property
    def ra1(self) -> float:
        return self.r1 + self.ha_star * self.module

    @property
    def ra2(self) -> float:
        return self.r2 + self.ha_star * self.module

    @property
    def rf1(self) -> float:
        return self.r1 - (self.ha_star + self.c_star) * self.module

    @property
    def rf2(self) -> float:
        return self.r2 - (self.ha_star + self.c_star) * self.module

    @property
    def centre_distance(self) -> float:
        return self.module * (self.z1 + self.z2) / 2

    # --- timing
    @property
    def motion_angle(self) -> float:
        """φ_m = 2π z1'/z1 [rad]."""
        return TWO_PI * self.teeth / self.z1

    @property
    def dwell_angle(self) -> float:
        """φ_d = 2π − φ_m [rad]."""
        return TWO_PI - self.motion_angle

    @property
    def advance(self) -> float:
        """Δφ2 = 2π z1'/z2 [rad] per cycle."""
        return TWO_PI * self.teeth / self.z2

    @property
    def feed(self) -> float | None:
        """Chain feed per cycle L = R_s Δφ2 [m] (None without a sprocket)."""
        return None if self.sprocket_radius is None else self.sprocket_radius * self.advance

    @property
    def speed_ratio(self) -> float:
        """ω2/ω1 = z1/z2 while meshing."""
        return self.z1 / self.z2

    @property
    def motion_dwell_ratio(self) -> float:
        """k = t_m/t_d = φ_m/φ_d (动停比)."""
        return self.motion_angle / self.dwell_angle

    @property
    def tau(self) -> float:
        """τ = t_m/T = φ_m/2π (运动系数)."""
        return self.motion_angle / TWO_PI

    @property
    def stations(self) -> int | None:
        """Dwell positions per driven revolution z2/z1' (None when not whole)."""
        return self.z2 // self.teeth if self.z2 % self.teeth == 0 else None

    def times(self) -> tuple[float, float, float] | None:
        """(T, t_m, t_d) [s] at the driver speed, or None without one."""
        if self.driver_speed is None:
            return None
        w = self.driver_speed
        return TWO_PI / w, self.motion_angle / w, self.dwell_angle / w

    def cycle_phases(self) -> list[tuple[str, float]]:
        """The driven wheel's phases for a cycle diagram, from ``motion_start``
        (states of :mod:`mechdesign.core.cycle`)."""
        return [("move", self.motion_angle), ("dwell", self.dwell_angle)]

    # --- motion
    def driven_motion(self, theta, since: float | None = None) -> DrivenMotion:
        """The driven wheel at driver angles ``theta`` [rad] (vectorised). Meshing is the
        half-open arc [motion_start, motion_start + φ_m) (mod 2π; within 1e-9 rad of a
        boundary counts as on it). ``angle`` is the angle
        turned since the driver passed ``since`` [rad] (default: ``motion_start``), reading
        θ in the window [since, since + 2π): 0 … Δφ2."""
        theta = np.asarray(theta, dtype=float)
        since = self.motion_start if since is None else float(since)
        k, phi_m = self.speed_ratio, self.motion_angle
        # angles within BOUNDARY_TOL of a boundary count as on it (as in core.cycle)
        moving = np.mod(theta - self.motion_start + BOUNDARY_TOL, TWO_PI) < phi_m
        u = np.mod(theta - since, TWO_PI)                  # position in the window
        s = float(np.mod(self.motion_start - since, TWO_PI))   # meshing starts here
        # meshing arc [s, s + φm] and its part wrapped to the window's start [s − 2π, s − 2π + φm]
        turned = np.clip(u - s, 0.0, phi_m) + np.clip(np.minimum(u, s - TWO_PI + phi_m), 0.0, None)
        angle = k * turned
        ratio = np.where(moving, k, 0.0)
        omega = None if self.driver_speed is None else ratio * self.driver_speed
        travel = None if self.sprocket_radius is None else angle * self.sprocket_radius
        return DrivenMotion(theta, angle, ratio, moving, omega, travel)

    def engagement_jump(self) -> EngagementJump:
        """The speed jump at engagement: Δω2 = ω1 z1/z2 (per radian of driver angle without
        a driver speed), the pitch-line speed ω1 r1 and the chain speed R_s Δω2."""
        w = 1.0 if self.driver_speed is None else self.driver_speed
        dw2 = w * self.speed_ratio
        chain = None if self.sprocket_radius is None else self.sprocket_radius * dw2
        return EngagementJump(dw2, w * self.r1, chain)


@dataclass(frozen=True)
class IntermittentCurves:
    """What a report plots and prints of the drive over one driver turn."""

    theta: np.ndarray          # driver angle 0 … 2π with both one-sided values at the meshing
                               # boundaries (the velocity's jumps plot as steps) [rad]
    motion: DrivenMotion       # the driven wheel at ``theta``, angle read from θ = 0
    jump: EngagementJump       # the speed jump at engagement
    times: tuple | None        # (T, t_m, t_d) [s], None without a driver speed
    advance_integral: float    # ∫ dφ2/dθ dθ over the grid (trapezoids), to equal Δφ2 [rad]
    dwell_speed_max: float     # largest |ω2| in the dwell [rad/s] (|dφ2/dθ| [–] without a speed)


def intermittent_curves(g: IncompleteGear, n: int = 3600) -> IntermittentCurves:
    """The driven motion of ``g`` on a grid of ``n`` steps over 0 … 2π, with points just
    either side of the meshing boundaries, its engagement jump and its times."""
    theta = np.linspace(0.0, TWO_PI, n + 1)
    ends = np.mod([g.motion_start, g.motion_start + g.motion_angle], TWO_PI)
    eps = 1e-7          # well outside BOUNDARY_TOL
    extra = np.concatenate([ends - eps, ends + eps])
    theta = np.sort(np.concatenate([theta, np.clip(extra, 0.0, TWO_PI)]))
    dm = g.driven_motion(theta, since=0.0)
    rate = dm.ratio
    integral = float(np.sum(0.5 * (rate[1:] + rate[:-1]) * np.diff(theta)))
    speed = dm.omega if dm.omega is not None else dm.ratio
    dwell_max = float(np.max(np.abs(speed[~dm.moving]), initial=0.0))
    return IntermittentCurves(theta, dm, g.engagement_jump(), g.times(), integral, dwell_max)


def _z_min(alpha: float, ha_star: float) -> float:
    """Smallest tooth number of a standard gear without undercut, 2 h_a*/sin²α."""
    return 2 * ha_star / math.sin(alpha) ** 2


def _whole(value: float) -> tuple[int, int]:
    lo = math.floor(value + 1e-12)
    return lo, lo + 1


def design_incomplete_gear(module: float, z1: int | None = None, z2: int | None = None, *,
                           teeth: int | None = None, motion_span: float | None = None,
                           advance: float | None = None, feed: float | None = None,
                           sprocket_radius: float | None = None, motion_start: float = 0.0,
                           driver_speed: float | None = None, tol: float = TIMING_TOL,
                           alpha: float = math.radians(20.0), ha_star: float = 1.0,
                           c_star: float = 0.25, locking_radius: float | None = None
                           ) -> IncompleteGear:
    """Design an incomplete gear whose driver turns once per cycle.

    Give ``module`` [m] and enough of the timing to fix the teeth:

    * ``teeth`` z1' present on the driver, or it follows from ``z1`` and ``motion_span``
      (z1' = z1 φ_m / 2π) or from ``z2`` and the advance (z1' = z2 Δφ2 / 2π);
    * ``z1`` (driver's notional full count), or it follows from z1' and ``motion_span``;
    * ``z2`` (driven teeth), or it follows from z1' and the advance;
    * the advance [rad] of the driven wheel per cycle as ``advance``, or as a chain
      ``feed`` [m] through a sprocket of pitch radius ``sprocket_radius`` [m].

    Every timing value given must be met within ``tol`` [rad] with whole teeth, otherwise
    :class:`IntermittentDesignError` names the whole-teeth values nearest to it.
    ``motion_start``: shaft angle where meshing begins [rad]; ``driver_speed`` ω1 [rad/s].
    """
    if not (math.isfinite(module) and module > 0):
        raise IntermittentDesignError(f"the module must be positive, not {module!r}",
                                      f"模数须为正，而不是 {module!r}",
                                      field="module")
    for name, z in (("z1", z1), ("z2", z2), ("teeth", teeth)):
        if z is not None and (isinstance(z, bool) or int(z) != z or z < 1):
            raise IntermittentDesignError(f"{name} must be a whole number ≥ 1, not {z!r}",
                                          f"{name} 须为 ≥ 1 的整数，而不是 {z!r}",
                                          field=name)
    z1 = None if z1 is None else int(z1)
    z2 = None if z2 is None else int(z2)
    teeth = None if teeth is None else int(teeth)
    if motion_span is not None and not 0 < motion_span < TWO_PI:
        raise IntermittentDesignError(f"the motion span must lie between 0° and 360°, not "
                                      f"{motion_span * DEG:g}°",
                                      f"运动角须在 0° 与 360° 之间，而不是 {motion_span * DEG:g}°",
                                      field="motion_span")
    if feed is not None:
        if sprocket_radius is None or not sprocket_radius > 0:
            raise IntermittentDesignError("a chain feed needs the sprocket's pitch radius",
                                          "链条送进量需要链轮的分度圆半径",
                                          field="sprocket_radius")
        from_feed = feed / sprocket_radius
        if advance is not None and abs(from_feed - advance) > tol:
            raise IntermittentDesignError(
                f"the feed {feed * 1e3:g} mm on a sprocket of pitch radius "
                f"{sprocket_radius * 1e3:g} mm is an advance of {from_feed * DEG:.4g}°, not the "
                f"{advance * DEG:g}° also given: give one of them",
                f"送进量 {feed * 1e3:g} mm 在分度圆半径 {sprocket_radius * 1e3:g} mm 的链轮上相当于转过 "
                f"{from_feed * DEG:.4g}°，而不是同时给出的 {advance * DEG:g}°：两者只给一个",
                field="feed")
        advance = from_feed
    if advance is not None and not advance > 0:
        raise IntermittentDesignError(f"the advance must be positive, not {advance * DEG:g}°",
                                      f"从动轮转角须为正，而不是 {advance * DEG:g}°",
                                      field="advance")

    def adv_text(angle: float, extra: str = "") -> str:
        """The advance in degrees, with the feed when the brief gave a feed."""
        parts = ([f"feed {angle * sprocket_radius * 1e3:.4g} mm"] if feed is not None else []) + \
            ([extra] if extra else [])
        return f"{angle * DEG:.4g}°" + (f" ({', '.join(parts)})" if parts else "")

    def adv_zh(angle: float, extra: str = "") -> str:
        parts = ([f"送进量 {angle * sprocket_radius * 1e3:.4g} mm"] if feed is not None else []) + \
            ([extra] if extra else [])
        return f"{angle * DEG:.4g}°" + (f"（{'，'.join(parts)}）" if parts else "")

    # --- the teeth present
    if teeth is None:
        if z1 is not None and motion_span is not None:
            exact = z1 * motion_span / TWO_PI
            teeth = int(round(exact))
            if teeth < 1 or abs(TWO_PI * teeth / z1 - motion_span) > tol:
                lo, hi = _whole(exact)
                options = " or ".join(f"{TWO_PI * n / z1 * DEG:.4g}° ({n} teeth)"
                                      for n in (lo, hi) if 1 <= n < z1)
                opt_zh = " 或 ".join(f"{TWO_PI * n / z1 * DEG:.4g}°（{n} 齿）"
                                     for n in (lo, hi) if 1 <= n < z1)
                raise IntermittentDesignError(
                    f"the motion span {motion_span * DEG:g}° needs z1·φm/360° = {exact:.4g} teeth "
                    f"on the driver (z1 = {z1}), not a whole number; whole teeth give {options or 'no usable value'}: "
                    f"change the motion span or z1",
                    f"运动角 {motion_span * DEG:g}° 要求主动轮上有 z1·φm/360° = {exact:.4g} 个齿"
                    f"（z1 = {z1}），不是整数；整齿数可得 {opt_zh or '无可用值'}：应改变运动角或 z1",
                    field="motion_span")
        elif z2 is not None and advance is not None:
            exact = z2 * advance / TWO_PI
            teeth = int(round(exact))
            if teeth < 1 or abs(TWO_PI * teeth / z2 - advance) > tol:
                lo, hi = _whole(exact)
                options = " or ".join(adv_text(TWO_PI * n / z2, f"{n} teeth")
                                      for n in (lo, hi) if n >= 1 and (z1 is None or n < z1))
                opt_zh = " 或 ".join(adv_zh(TWO_PI * n / z2, f"{n} 齿")
                                     for n in (lo, hi) if n >= 1 and (z1 is None or n < z1))
                raise IntermittentDesignError(
                    f"the advance {adv_text(advance)} needs z2·Δφ2/360° = {exact:.4g} teeth on the "
                    f"driver (z2 = {z2}), not a whole number; whole teeth give {options or 'no usable value'}: change "
                    f"the advance or z2",
                    f"从动轮转角 {adv_zh(advance)} 要求主动轮上有 z2·Δφ2/360° = {exact:.4g} 个齿"
                    f"（z2 = {z2}），不是整数；整齿数可得 {opt_zh or '无可用值'}：应改变转角或 z2",
                    field="advance")
        else:
            raise IntermittentDesignError(
                "the teeth on the driver are not fixed: give them, or z1 with the motion span, "
                "or z2 with the advance (or feed)",
                "主动轮的齿数未确定：请直接给出，或给出 z1 与运动角，或给出 z2 与转角（或送进量）",
                field="teeth")
    # --- the driver's notional full count
    if z1 is None:
        if motion_span is None:
            raise IntermittentDesignError("give z1 (the driver's full tooth count) or the "
                                          "driver's motion span",
                                          "请给出 z1（主动轮的完整齿数）或主动轮的运动角",
                                          field="z1")
        exact = TWO_PI * teeth / motion_span
        z1 = int(round(exact))
        if z1 < 1 or abs(TWO_PI * teeth / z1 - motion_span) > tol:
            lo, hi = _whole(exact)
            options = " or ".join(f"{TWO_PI * teeth / z * DEG:.4g}° (z1 = {z})"
                                  for z in (lo, hi) if z > teeth)
            opt_zh = " 或 ".join(f"{TWO_PI * teeth / z * DEG:.4g}°（z1 = {z}）"
                                 for z in (lo, hi) if z > teeth)
            raise IntermittentDesignError(
                f"with {teeth} teeth the motion span {motion_span * DEG:g}° needs "
                f"z1 = 360°·z1'/φm = {exact:.4g}, not a whole number; whole z1 give {options or 'no usable value'}: "
                f"change the motion span or the teeth",
                f"齿数为 {teeth} 时运动角 {motion_span * DEG:g}° 要求 z1 = 360°·z1'/φm = {exact:.4g}，"
                f"不是整数；整数 z1 可得 {opt_zh or '无可用值'}：应改变运动角或齿数",
                field="motion_span")
    # --- the driven wheel
    if z2 is None:
        if advance is None:
            raise IntermittentDesignError("give z2 (the driven wheel's teeth) or the advance",
                                          "请给出 z2（从动轮齿数）或从动轮转角",
                                          field="z2")
        exact = TWO_PI * teeth / advance
        z2 = int(round(exact))
        if z2 < 1 or abs(TWO_PI * teeth / z2 - advance) > tol:
            lo, hi = _whole(exact)
            options = " or ".join(adv_text(TWO_PI * teeth / z, f"z2 = {z}")
                                  for z in (lo, hi) if z >= 1)
            opt_zh = " 或 ".join(adv_zh(TWO_PI * teeth / z, f"z2 = {z}")
                                 for z in (lo, hi) if z >= 1)
            raise IntermittentDesignError(
                f"with {teeth} teeth the advance {adv_text(advance)} needs z2 = 360°·z1'/Δφ2 = "
                f"{exact:.4g}, not a whole number; whole z2 give {options or 'no usable value'}: change the advance "
                f"or the teeth",
                f"齿数为 {teeth} 时从动轮转角 {adv_zh(advance)} 要求 z2 = 360°·z1'/Δφ2 = {exact:.4g}，"
                f"不是整数；整数 z2 可得 {opt_zh or '无可用值'}：应改变转角或齿数",
                field="advance")
    # --- consistency of everything given
    if teeth >= z1:
        raise IntermittentDesignError(
            f"{teeth} teeth on a driver of z1 = {z1} leave no toothless arc for the dwell: "
            f"the driver needs fewer teeth than z1",
            f"主动轮 z1 = {z1} 上有 {teeth} 个齿，没有留下停歇所需的无齿弧：齿数须少于 z1",
            field="teeth")
    phi_m = TWO_PI * teeth / z1
    if motion_span is not None and abs(phi_m - motion_span) > tol:
        raise IntermittentDesignError(
            f"{teeth} teeth on a driver of z1 = {z1} mesh over 360°·{teeth}/{z1} = "
            f"{phi_m * DEG:.4g}°, not the motion span {motion_span * DEG:g}° given",
            f"主动轮 z1 = {z1} 上的 {teeth} 个齿啮合 360°·{teeth}/{z1} = {phi_m * DEG:.4g}°，"
            f"而不是给定的运动角 {motion_span * DEG:g}°",
            field="motion_span")
    adv = TWO_PI * teeth / z2
    if advance is not None and abs(adv - advance) > tol:
        raise IntermittentDesignError(
            f"{teeth} teeth advance a driven wheel of z2 = {z2} by 360°·{teeth}/{z2} = "
            f"{adv_text(adv)}, not the required {adv_text(advance)}",
            f"{teeth} 个齿使 z2 = {z2} 的从动轮转过 360°·{teeth}/{z2} = {adv_zh(adv)}，"
            f"而不是要求的 {adv_zh(advance)}",
            field="advance")
    if z1 < 3 or z2 < 3:
        raise IntermittentDesignError(f"z1 = {z1} and z2 = {z2}: a gear needs at least 3 teeth",
                                      f"z1 = {z1}，z2 = {z2}：齿轮至少需要 3 个齿",
                                      field="z1" if z1 < 3 else "z2")

    notes = []
    zmin = _z_min(alpha, ha_star)
    small = [f"z{i} = {z}" for i, z in ((1, z1), (2, z2)) if z < zmin - 1e-9]
    if small:
        notes.append(DesignNote(
            "undercut",
            f"{'、'.join(small)} 少于不根切的最少齿数 {zmin:.1f}，标准齿轮将根切：增加齿数或采用正变位。",
            f"{', '.join(small)} is below the smallest tooth number without undercut "
            f"({zmin:.1f}): a standard gear is undercut; use more teeth or a positive shift."))
    if z2 % teeth:
        g = gcd(z2, teeth)
        notes.append(DesignNote(
            "stations",
            f"z2 = {z2} 不是 z1' = {teeth} 的整数倍：从动轮每转一周的停歇位置不重复，"
            f"无法在固定位置制出凹锁止弧（每 {teeth // g} 个循环才回到原位）；从动轮只能做成完整齿轮并另设定位装置，"
            f"或改 z2 为 z1' 的整数倍。",
            f"z2 = {z2} is not a multiple of z1' = {teeth}: the driven wheel stops at different "
            f"places in successive cycles (it repeats only every {teeth // g} cycles), so it cannot "
            f"carry concave locking arcs at fixed places; make it a complete gear with a separate "
            f"detent, or make z2 a multiple of z1'."))
    if locking_radius is None:
        locking_radius = module * z1 / 2 + ha_star * module
    return IncompleteGear(float(module), z1, z2, teeth, float(alpha), float(ha_star),
                          float(c_star), float(motion_start % TWO_PI),
                          None if driver_speed is None else float(driver_speed),
                          None if sprocket_radius is None else float(sprocket_radius),
                          float(locking_radius),
                          None if motion_span is None else float(motion_span),
                          None if advance is None else float(advance), tuple(notes))


@dataclass(frozen=True)
class IntermittentTimes:
    """Times at the driver speed."""

    period: float = q("s", "cycle time T = 2π/ω1")
    motion: float = q("s", "t_m = φ_m/ω1")
    dwell: float = q("s", "t_d = φ_d/ω1")


@dataclass(frozen=True)
class EngagementJumpDoc:
    """The speed jump at engagement (per radian of driver angle without a driver speed)."""

    omega2: float = q("rad/s or 1", "Δω2 = ω1·z1/z2 (dφ2/dθ without a driver speed)")
    pitch_speed: float = q("m/s or m", "pitch-line speed ω1·r1 reached at once")
    chain_speed: float | None = q("m/s or m", "chain speed jump R_s·Δω2, with a sprocket")
    per_radian: bool = q("", "true: no driver speed, the values are per radian of driver angle")


@dataclass(frozen=True)
class IntermittentDocument:
    """An incomplete gear (不完全齿轮) drive in ``results.json`` (SI: m, rad, rad/s, s)."""

    module: float = q("m", "module m")
    z1: int = q("1", "teeth the driver would have if complete")
    z2: int = q("1", "teeth of the driven wheel")
    teeth: int = q("1", "teeth present on the driver z1'")
    r1: float = q("m", "driver's pitch radius m·z1/2")
    r2: float = q("m", "driven wheel's pitch radius m·z2/2")
    ra1: float = q("m", "driver's tip radius")
    ra2: float = q("m", "driven wheel's tip radius")
    centre_distance: float = q("m", "a = m(z1 + z2)/2")
    locking_radius: float = q("m", "radius R_L of the locking arcs")
    motion_start: float = q("rad", "shaft angle where meshing begins")
    motion_angle: float = q("rad", "φ_m = 2π·z1'/z1")
    dwell_angle: float = q("rad", "φ_d = 2π − φ_m")
    advance: float = q("rad", "Δφ2 = 2π·z1'/z2 per cycle")
    feed: float | None = q("m", "chain feed per cycle R_s·Δφ2, with a sprocket")
    sprocket_radius: float | None = q("m", "R_s, with a sprocket")
    speed_ratio: float = q("1", "ω2/ω1 = z1/z2 while meshing")
    motion_dwell_ratio: float = q("1", "k = t_m/t_d (动停比)")
    tau: float = q("1", "τ = t_m/T (运动系数)")
    stations: int | None = q("1", "dwell positions per driven revolution z2/z1' (null: not whole)")
    driver_speed: float | None = q("rad/s", "ω1, when known")
    times: IntermittentTimes | None = q("", "times at the driver speed, when known")
    engagement_jump: EngagementJumpDoc = q("", "speed jump at engagement")
    notes: tuple[str, ...] = q("", "codes of the design notes (undercut, stations)")


def intermittent_document(g: IncompleteGear) -> IntermittentDocument:
    """The incomplete gear for ``results.json`` (SI: m, rad, rad/s, s)."""
    jump = g.engagement_jump()
    times = g.times()
    return IntermittentDocument(
        module=g.module, z1=g.z1, z2=g.z2, teeth=g.teeth, r1=g.r1, r2=g.r2, ra1=g.ra1,
        ra2=g.ra2, centre_distance=g.centre_distance, locking_radius=g.locking_radius,
        motion_start=g.motion_start, motion_angle=g.motion_angle, dwell_angle=g.dwell_angle,
        advance=g.advance, feed=g.feed, sprocket_radius=g.sprocket_radius,
        speed_ratio=g.speed_ratio, motion_dwell_ratio=g.motion_dwell_ratio, tau=g.tau,
        stations=g.stations, driver_speed=g.driver_speed,
        times=None if times is None else IntermittentTimes(*times),
        engagement_jump=EngagementJumpDoc(jump.omega2, jump.pitch_speed, jump.chain_speed,
                                          g.driver_speed is None),
        notes=tuple(n.code for n in g.notes))
