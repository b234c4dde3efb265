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

from .errors import DesignError, Join, Msg, N_, pgettext
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

    def __init__(self, msg, zh: str | None = None, /, field: str | None = None, **fields):
        super().__init__(msg, zh, **fields)
        self.field = field


@dataclass(frozen=True)
class DesignNote:
    """A problem that leaves the design computable (a machine turns it into a Finding:
    ``finding_of(note.code, note.message)``): a code and a message, translated where shown."""

    code: str
    message: Msg

    @property
    def en(self) -> str:
        return self.message.text("en")

    @property
    def zh(self) -> str:
        return self.message.text("zh")

    def text(self, lang: str) -> str:
        return self.message.text(lang)


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
        raise IntermittentDesignError(N_("the module must be positive, not {module!r}"),
                                      module=module,
                                      field="module")
    for name, z in (("z1", z1), ("z2", z2), ("teeth", teeth)):
        if z is not None and (isinstance(z, bool) or int(z) != z or z < 1):
            raise IntermittentDesignError(N_("{name} must be a whole number ≥ 1, not {z!r}"),
                                          name=name, z=z,
                                          field=name)
    z1 = None if z1 is None else int(z1)
    z2 = None if z2 is None else int(z2)
    teeth = None if teeth is None else int(teeth)
    if motion_span is not None and not 0 < motion_span < TWO_PI:
        raise IntermittentDesignError(N_("the motion span must lie between 0° and 360°, not "
                                         "{motion_span_deg:g}°"),
                                      motion_span_deg=motion_span * DEG,
                                      field="motion_span")
    if feed is not None:
        if sprocket_radius is None or not sprocket_radius > 0:
            raise IntermittentDesignError(N_("a chain feed needs the sprocket's pitch radius"),
                                          field="sprocket_radius")
        from_feed = feed / sprocket_radius
        if advance is not None and abs(from_feed - advance) > tol:
            raise IntermittentDesignError(
                N_("the feed {feed_mm:g} mm on a sprocket of pitch radius "
                   "{sprocket_radius_mm:g} mm is an advance of {from_feed_deg:.4g}°, not the "
                   "{advance_deg:g}° also given: give one of them"),
                feed_mm=feed * 1e3, sprocket_radius_mm=sprocket_radius * 1e3,
                from_feed_deg=from_feed * DEG, advance_deg=advance * DEG,
                field="feed")
        advance = from_feed
    if advance is not None and not advance > 0:
        raise IntermittentDesignError(N_("the advance must be positive, not {advance_deg:g}°"),
                                      advance_deg=advance * DEG,
                                      field="advance")

    def adv_text(angle: float, extra=""):
        """The advance in degrees, with the feed when the brief gave a feed (a message)."""
        parts = ([Msg(N_("feed {feed_mm:.4g} mm"), feed_mm=angle * sprocket_radius * 1e3)]
                 if feed is not None else []) + ([extra] if extra else [])
        if not parts:
            return f"{angle * DEG:.4g}°"
        return Msg(N_("{angle:.4g}° ({details})"), angle=angle * DEG,
                   details=Join(pgettext("separator", ", "), parts))

    def options(items):
        """The whole-tooth alternatives joined by "or", or "no usable value"."""
        return Join(pgettext("separator", " or "), items) if items else \
            Msg(N_("no usable value"))

    # --- the teeth present
    if teeth is None:
        if z1 is not None and motion_span is not None:
            exact = z1 * motion_span / TWO_PI
            teeth = int(round(exact))
            if teeth < 1 or abs(TWO_PI * teeth / z1 - motion_span) > tol:
                lo, hi = _whole(exact)
                raise IntermittentDesignError(
                    N_("the motion span {span_deg:g}° needs z1·φm/360° = {exact:.4g} teeth on the "
                       "driver (z1 = {z1}), not a whole number; whole teeth give {options}: "
                       "change the motion span or z1"),
                    span_deg=motion_span * DEG, exact=exact, z1=z1,
                    options=options([Msg(N_("{angle:.4g}° ({n} teeth)"),
                                         angle=TWO_PI * n / z1 * DEG, n=n)
                                     for n in (lo, hi) if 1 <= n < z1]),
                    field="motion_span")
        elif z2 is not None and advance is not None:
            exact = z2 * advance / TWO_PI
            teeth = int(round(exact))
            if teeth < 1 or abs(TWO_PI * teeth / z2 - advance) > tol:
                lo, hi = _whole(exact)
                raise IntermittentDesignError(
                    N_("the advance {advance} needs z2·Δφ2/360° = {exact:.4g} teeth on the driver "
                       "(z2 = {z2}), not a whole number; whole teeth give {options}: change the "
                       "advance or z2"),
                    advance=adv_text(advance), exact=exact, z2=z2,
                    options=options([adv_text(TWO_PI * n / z2, Msg(N_("{n} teeth"), n=n))
                                     for n in (lo, hi) if n >= 1 and (z1 is None or n < z1)]),
                    field="advance")
        else:
            raise IntermittentDesignError(
                N_("the teeth on the driver are not fixed: give them, or z1 with the motion "
                   "span, or z2 with the advance (or feed)"),
                field="teeth")
    # --- the driver's notional full count
    if z1 is None:
        if motion_span is None:
            raise IntermittentDesignError(N_("give z1 (the driver's full tooth count) or the "
                                             "driver's motion span"),
                                          field="z1")
        exact = TWO_PI * teeth / motion_span
        z1 = int(round(exact))
        if z1 < 1 or abs(TWO_PI * teeth / z1 - motion_span) > tol:
            lo, hi = _whole(exact)
            raise IntermittentDesignError(
                N_("with {teeth} teeth the motion span {span_deg:g}° needs z1 = 360°·z1'/φm = "
                   "{exact:.4g}, not a whole number; whole z1 give {options}: change the motion "
                   "span or the teeth"),
                teeth=teeth, span_deg=motion_span * DEG, exact=exact,
                options=options([Msg(N_("{angle:.4g}° (z1 = {z})"),
                                     angle=TWO_PI * teeth / z * DEG, z=z)
                                 for z in (lo, hi) if z > teeth]),
                field="motion_span")
    # --- the driven wheel
    if z2 is None:
        if advance is None:
            raise IntermittentDesignError(N_("give z2 (the driven wheel's teeth) or the "
                                             "advance"),
                                          field="z2")
        exact = TWO_PI * teeth / advance
        z2 = int(round(exact))
        if z2 < 1 or abs(TWO_PI * teeth / z2 - advance) > tol:
            lo, hi = _whole(exact)
            raise IntermittentDesignError(
                N_("with {teeth} teeth the advance {advance} needs z2 = 360°·z1'/Δφ2 = {exact:.4g}, "
                   "not a whole number; whole z2 give {options}: change the advance or the teeth"),
                teeth=teeth, advance=adv_text(advance), exact=exact,
                options=options([adv_text(TWO_PI * teeth / z, f"z2 = {z}")
                                 for z in (lo, hi) if z >= 1]),
                field="advance")
    # --- consistency of everything given
    if teeth >= z1:
        raise IntermittentDesignError(
            N_("{teeth} teeth on a driver of z1 = {z1} leave no toothless arc for the dwell: "
               "the driver needs fewer teeth than z1"), teeth=teeth, z1=z1,
            field="teeth")
    phi_m = TWO_PI * teeth / z1
    if motion_span is not None and abs(phi_m - motion_span) > tol:
        raise IntermittentDesignError(
            N_("{teeth} teeth on a driver of z1 = {z1} mesh over 360°·{teeth}/{z1} = "
               "{phi_m_deg:.4g}°, not the motion span {motion_span_deg:g}° given"),
            teeth=teeth, z1=z1, phi_m_deg=phi_m * DEG, motion_span_deg=motion_span * DEG,
            field="motion_span")
    adv = TWO_PI * teeth / z2
    if advance is not None and abs(adv - advance) > tol:
        raise IntermittentDesignError(
            N_("{teeth} teeth advance a driven wheel of z2 = {z2} by 360°·{teeth}/{z2} = "
               "{got}, not the required {required}"), teeth=teeth, z2=z2,
            got=adv_text(adv), required=adv_text(advance), field="advance")
    if z1 < 3 or z2 < 3:
        raise IntermittentDesignError(N_("z1 = {z1} and z2 = {z2}: a gear needs at least 3 "
                                         "teeth"), z1=z1, z2=z2,
                                      field="z1" if z1 < 3 else "z2")

    notes = []
    zmin = _z_min(alpha, ha_star)
    small = [f"z{i} = {z}" for i, z in ((1, z1), (2, z2)) if z < zmin - 1e-9]
    if small:
        notes.append(DesignNote("undercut", Msg(
            N_("{gears} is below the smallest tooth number without undercut ({zmin:.1f}): a "
               "standard gear is undercut; use more teeth or a positive shift."),
            gears=Join(pgettext("list", ", "), small), zmin=zmin)))
    if z2 % teeth:
        g = gcd(z2, teeth)
        notes.append(DesignNote("stations", Msg(
            N_("z2 = {z2} is not a multiple of z1' = {teeth}: the driven wheel stops at different "
               "places in successive cycles (it repeats only every {cycles} cycles), so it cannot "
               "carry concave locking arcs at fixed places; make it a complete gear with a "
               "separate detent, or make z2 a multiple of z1'."),
            z2=z2, teeth=teeth, cycles=teeth // g)))
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
    motion_dwell_ratio: float = q("1", "k = t_m/t_d (motion–dwell ratio)")
    tau: float = q("1", "τ = t_m/T (motion coefficient)")
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
