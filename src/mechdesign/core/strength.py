"""Strength checks of machine elements by the textbook method (濮良贵《机械设计》9th/10th ed.,
《机械设计课程设计》): cylindrical gears, worm pairs, shafts, rolling bearings and flat keys.

Pure computation. **SI units inside**: N, m, Pa, N·m, W, °C; speeds in rpm only where a
name ends in ``_rpm``; lives in hours only where a name says ``hours``/``_h``; angles in
radians. ZE is in √Pa (189.8 √MPa = 1.898e5 √Pa). The textbook's course units (N·mm, mm,
MPa, kW, h) appear only in :mod:`mechdesign.render.strength_tex`, which converts with
:data:`COURSE_SCALE`.

Every check returns a :class:`Check`. Sizing ("design") functions return the SI minimum
(diameter, module, centre distance, area ...).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable, Literal

import numpy as np

from .drive import DriveDesignError
from .errors import N_
from .fields import q

Sense = Literal["le", "ge"]

#: Factor from the SI value of a :class:`Check` to its course display unit.
COURSE_SCALE: dict[str, float] = {"MPa": 1e-6, "h": 1.0 / 3600.0, "°C": 1.0, "mm": 1e3,
                                  "m/s": 1.0, "°": 180.0 / math.pi, "1": 1.0, "kW": 1e-3,
                                  "μm": 1e6, "N·m": 1.0}


@dataclass(frozen=True)
class Check:
    """One strength/life/temperature check.

    ``value`` and ``allowable`` are SI (Pa, s, °C, m); ``unit`` is the course display unit
    ("MPa", "h", "°C", "mm"), see :data:`COURSE_SCALE`. ``sense`` "le" means value ≤
    allowable passes (stresses, temperatures); "ge" means value ≥ allowable passes (lives,
    diameters). ``inputs`` holds every factor used, SI, keyed by the names the formula
    renderer expects. ``name`` is an English msgid of the catalogues (no prose in the core:
    the report translates it, ``_(c.name, **c.name_args)``); rename a check for the report
    with ``dataclasses.replace(c, name=N_("…{designation}…"), name_args={...})``.
    """
    key: str = q("", "the check's kind: gear_contact, gear_bending, shaft_bending, bearing_life, key_crushing …")
    name: str = q("", "its name: an English msgid of the catalogues (locale/*.po), translated where "
                  "shown with its {fields} filled in from name_args")
    symbol: str = q("", "LaTeX symbol of the checked quantity, e.g. \\sigma_H")
    value: float = q("Pa, s, °C or m", "the checked quantity, SI (stress Pa, life s, oil temperature °C, "
                     "diameter m; `unit` says which)")
    allowable: float = q("Pa, s, °C or m", "its allowable value, same unit")
    unit: str = q("", "course display unit of value/allowable: 'MPa', 'h', '°C', 'mm' (issue 20 also 'm/s', '°', 'kW', 'μm', '1')")
    sense: Sense = q("", "'le': value ≤ allowable passes; 'ge': value ≥ allowable passes")
    passed: bool = q("", "the verdict")
    inputs: dict[str, float] = q("SI", "every factor the formula used, each in its SI unit "
                                 "(N·m, m, Pa, √Pa, W, rpm where named n_rpm; factors 1)",
                                 default_factory=dict)
    name_args: dict[str, str] = q("", "the fields of name, e.g. a bearing's designation; a name "
                                  "given by the data in both languages is two fields, <x>_en "
                                  "(the msgid's) and <x>_zh (the Chinese text's)",
                                  default_factory=dict)

    @property
    def course_value(self) -> float:
        """``value`` in the course unit ``unit``."""
        return self.value * COURSE_SCALE[self.unit]

    @property
    def course_allowable(self) -> float:
        """``allowable`` in the course unit ``unit``."""
        return self.allowable * COURSE_SCALE[self.unit]

    @property
    def utilisation(self) -> float:
        """value/allowable for "le" checks, allowable/value for "ge" checks (≤ 1 passes)."""
        return self.value / self.allowable if self.sense == "le" else self.allowable / self.value


def check(key, name, symbol, value, allowable, unit, sense: Sense = "le", **inputs) -> Check:
    """A :class:`Check` whose verdict is derived from ``value``, ``allowable`` and ``sense``
    (never written by hand); ``name`` is an English msgid (marked with N_), ``inputs`` are
    the factors the formula used (SI)."""
    if allowable is None:
        raise TypeError(f"{key}: the allowable value is required")
    value, allowable = float(value), float(allowable)
    passed = value <= allowable if sense == "le" else value >= allowable
    return Check(key, name, symbol, value, allowable, unit, sense, bool(passed),
                 {k: float(v) for k, v in inputs.items()})


# ---------------------------------------------------------------------------------------
# Allowable stresses and life factors
# ---------------------------------------------------------------------------------------

def allowable_stress(limit: float, life_factor: float = 1.0, safety: float = 1.0) -> float:
    """[σ] = K_N σlim / S (Pa in, Pa out; K_N and S dimensionless)."""
    if safety <= 0:
        raise ValueError("the safety factor must be positive")
    return life_factor * limit / safety


def stress_cycles(n_rpm: float, hours: float, j: int = 1) -> float:
    """Number of stress cycles N = 60 n j L_h (n in rpm, L_h in hours, j meshes per turn)."""
    return 60.0 * n_rpm * j * hours


# Life-factor curves as (N, K) corner points, joined by straight lines in log-log axes and
# flat outside. They reproduce the closed forms of GB/T 3480 = ISO 6336-2/-3 (e.g. contact,
# limited pitting: (3e8/N)^0.0756 up to 1e7, (1e9/N)^0.057 up to 1e9, then 0.85 at 1e10),
# from which the textbook charts (8th ed. 图10-18 K_FN, 图10-19 K_HN) are drawn; the long-life
# tails use the lower ISO bound 0.85 at N = 1e10. A chart reading can differ by a few %
# (例题10-1 reads K_HN = 0.90/0.95 at N = 4.1e9/1.3e9; these curves give 0.90/0.98).
CONTACT_LIFE_CURVES: dict[str, tuple[tuple[float, float], ...]] = {
    # 1: structural, through-hardened (调质), case-hardened steel, nodular iron — some pitting allowed
    "pitting_allowed": ((6e5, 1.6), (1e7, 1.3), (1e9, 1.0), (1e10, 0.85)),
    # 2: the same materials, no pitting allowed
    "no_pitting": ((1e5, 1.6), (5e7, 1.0), (1e10, 0.85)),
    # 3: grey iron, ferritic nodular iron, nitrided steel
    "nitrided": ((1e5, 1.3), (2e6, 1.0), (1e10, 0.85)),
    # 4: nitrocarburised steel
    "nitrocarburized": ((1e5, 1.1), (2e6, 1.0), (1e10, 0.85)),
}
BENDING_LIFE_CURVES: dict[str, tuple[tuple[float, float], ...]] = {
    # 1: through-hardened (调质) / normalised steel, pearlitic nodular and malleable iron
    "through_hardened": ((1e4, 2.5), (3e6, 1.0), (1e10, 0.85)),
    # 2: case-carburised, flame or induction hardened
    "case_hardened": ((1e3, 2.5), (3e6, 1.0), (1e10, 0.85)),
    # 3: nitrided steel, ferritic nodular iron, grey iron
    "nitrided": ((1e3, 1.6), (3e6, 1.0), (1e10, 0.85)),
    # 4: nitrocarburised steel
    "nitrocarburized": ((1e3, 1.1), (3e6, 1.0), (1e10, 0.85)),
}


def _loglog(points, N: float) -> float:
    if N <= 0:
        raise ValueError("the number of cycles must be positive")
    n, k = np.log10([p[0] for p in points]), np.log10([p[1] for p in points])
    return float(10 ** np.interp(np.log10(N), n, k))


def life_factor_contact(N: float, curve: str = "pitting_allowed") -> float:
    """Contact life factor K_HN (Z_NT) for N stress cycles; ``curve`` one of
    :data:`CONTACT_LIFE_CURVES` (the textbook chart's curves 1–4). Log-log fit, see above."""
    try:
        return _loglog(CONTACT_LIFE_CURVES[curve], N)
    except KeyError:
        raise KeyError(f"unknown contact life curve {curve!r}; allowed: {sorted(CONTACT_LIFE_CURVES)}") from None


def life_factor_bending(N: float, curve: str = "through_hardened") -> float:
    """Bending life factor K_FN (Y_NT) for N stress cycles; ``curve`` one of
    :data:`BENDING_LIFE_CURVES`."""
    try:
        return _loglog(BENDING_LIFE_CURVES[curve], N)
    except KeyError:
        raise KeyError(f"unknown bending life curve {curve!r}; allowed: {sorted(BENDING_LIFE_CURVES)}") from None


# ---------------------------------------------------------------------------------------
# Cylindrical gears (closed and open)
# ---------------------------------------------------------------------------------------

def elastic_coefficient(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """Elastic coefficient Z_E = sqrt(1 / (π((1−ν1²)/E1 + (1−ν2²)/E2))) in √Pa (E in Pa).
    Steel on steel (206 GPa, 0.3) gives the textbook 189.8 √MPa."""
    return math.sqrt(1.0 / (math.pi * ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)))


def zone_factor(alpha_t: float = math.radians(20), alpha_t_work: float | None = None, beta_b: float = 0.0) -> float:
    """Zone factor Z_H = sqrt(2 cos β_b / (cos² α_t tan α_t')) (angles in rad; α_t' defaults
    to α_t for standard centre distance). Standard 20° spur gears: 2.495 ≈ 2.5."""
    aw = alpha_t if alpha_t_work is None else alpha_t_work
    return math.sqrt(2 * math.cos(beta_b) / (math.cos(alpha_t) ** 2 * math.tan(aw)))


def contact_ratio_factor(eps_alpha: float, eps_beta: float = 0.0) -> float:
    """Contact-ratio factor Z_ε (9th ed.): sqrt((4−ε_α)/3) for spur gears; helical
    sqrt((4−ε_α)(1−ε_β)/3 + ε_β/ε_α) for ε_β < 1, sqrt(1/ε_α) for ε_β ≥ 1."""
    if eps_beta >= 1:
        return math.sqrt(1 / eps_alpha)
    return math.sqrt((4 - eps_alpha) / 3 * (1 - eps_beta) + eps_beta / eps_alpha)


def bending_ratio_factor(eps_alpha: float, beta_b: float = 0.0) -> float:
    """Y_ε = 0.25 + 0.75/ε_αv with ε_αv = ε_α / cos² β_b (= ε_α for spur gears)."""
    return 0.25 + 0.75 * math.cos(beta_b) ** 2 / eps_alpha


def helix_factors(beta: float, eps_beta: float) -> tuple[float, float]:
    """(Z_β, Y_β) for helix angle β (rad) and overlap ratio ε_β: Z_β = sqrt(cos β);
    Y_β = 1 − ε_β β/120° with ε_β taken ≤ 1 and β ≤ 30° (so Y_β ≥ 0.75, as ISO 6336-3)."""
    zb = math.sqrt(math.cos(beta))
    yb = 1 - min(eps_beta, 1.0) * min(math.degrees(beta), 30.0) / 120.0
    return zb, yb


def gear_contact_stress(T1, K, b, d1, u, ZE, ZH, Zeps, Zbeta=1.0) -> float:
    """σ_H = sqrt(2 K T1 (u+1) / (b d1² u)) Z_H Z_E Z_ε Z_β in Pa (T1 N·m, b d1 m, Z_E √Pa)."""
    return math.sqrt(2 * K * T1 * (u + 1) / (b * d1 ** 2 * u)) * ZH * ZE * Zeps * Zbeta


def gear_contact_check(T1, K, b, d1, u, ZE, ZH, Zeps, Zbeta=1.0, allowable=None) -> Check:
    """Tooth-flank contact fatigue check σ_H ≤ [σ_H] (see :func:`gear_contact_stress`);
    ``allowable`` [σ_H] in Pa (the smaller of the pair's)."""
    s = gear_contact_stress(T1, K, b, d1, u, ZE, ZH, Zeps, Zbeta)
    return check("gear_contact", N_("Tooth-flank contact fatigue"), r"\sigma_H", s, allowable,
                  "MPa", T1=T1, K=K, b=b, d1=d1, u=u, ZE=ZE, ZH=ZH, Zeps=Zeps, Zbeta=Zbeta)


def gear_bending_check(T1, K, b, d1, m, YFa, YSa, Yeps, Ybeta=1.0, allowable=None) -> Check:
    """Tooth-root bending fatigue check σ_F = 2 K T1 Y_Fa Y_Sa Y_ε Y_β / (b d1 m) ≤ [σ_F]
    (T1 N·m on the gear whose d1 is given; b, d1, m in m, m the normal module for helical
    gears; Pa). With b = φ_d d1 and d1 = m z1 it is the textbook's 2KT1YFaYSaYε/(φd m³ z1²)."""
    s = 2 * K * T1 * YFa * YSa * Yeps * Ybeta / (b * d1 * m)
    return check("gear_bending", N_("Tooth-root bending fatigue"), r"\sigma_F", s, allowable,
                  "MPa", T1=T1, K=K, b=b, d1=d1, m=m, YFa=YFa, YSa=YSa, Yeps=Yeps, Ybeta=Ybeta)


def design_d1_contact(T1, K, phi_d, u, ZH, ZE, Zeps, allowable, Zbeta=1.0) -> float:
    """Minimum pinion diameter d1 ≥ ∛(2 K T1/φ_d · (u+1)/u · (Z_H Z_E Z_ε Z_β/[σ_H])²), m."""
    return (2 * K * T1 / phi_d * (u + 1) / u * (ZH * ZE * Zeps * Zbeta / allowable) ** 2) ** (1 / 3)


def design_module_bending(T1, K, phi_d, z1, YFa, YSa, Yeps, allowable, Ybeta=1.0, beta=0.0) -> float:
    """Minimum (normal) module m ≥ ∛(2 K T1 Y_ε Y_β cos²β / (φ_d z1²) · Y_Fa Y_Sa/[σ_F]), m.
    Pass the larger Y_Fa Y_Sa/[σ_F] of the pair (YFa·YSa with its own ``allowable``)."""
    return (2 * K * T1 * Yeps * Ybeta * math.cos(beta) ** 2 / (phi_d * z1 ** 2) * YFa * YSa / allowable) ** (1 / 3)


#: First-choice module series, GB/T 1357-2008, mm.
STANDARD_MODULES_MM = (1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 16, 20, 25, 32, 40, 50)


def standard_module(m_min: float) -> float:
    """The smallest first-choice standard module (GB/T 1357) ≥ ``m_min`` (m in, m out)."""
    for m in STANDARD_MODULES_MM:
        if m * 1e-3 >= m_min * (1 - 1e-9):
            return m * 1e-3
    raise ValueError(f"module {m_min * 1e3:.3g} mm exceeds the standard series (max 50 mm)")


def design_module_open(T1, K, phi_d, z1, YFa, YSa, Yeps, allowable, wear_allowance=0.15) -> float:
    """Open gears: bending module × (1 + wear allowance, textbook 10–20 %), rounded up to the
    standard series (m)."""
    if not 0.0 <= wear_allowance <= 0.5:
        raise ValueError("wear allowance is a fraction, typically 0.10–0.20")
    return standard_module(design_module_bending(T1, K, phi_d, z1, YFa, YSa, Yeps, allowable) * (1 + wear_allowance))


# ---------------------------------------------------------------------------------------
# Worm pair (ZA worm, hardened steel worm, bronze / cast-iron wheel)
# ---------------------------------------------------------------------------------------

def worm_contact_coefficient(d1_over_a: float) -> float:
    """Contact coefficient Z_ρ of the textbook chart (9th ed. 图11-18, curve I: ZA/ZN/ZI/ZK
    worms) as the quadratic fit 8.809524 x² − 9.583333 x + 5.177143, x = d1/a (the fit used by
    the mechtool.cn worm calculator; 2.9 at 0.35 as the textbook example reads). Approximate;
    valid for 0.2 ≤ d1/a ≤ 0.55."""
    x = d1_over_a
    if not 0.2 <= x <= 0.55:
        raise DriveDesignError(
            N_("worm pair: d1/a = {x:.3f} is outside the contact-coefficient chart (0.2–0.55); "
               "change the diameter factor q or the wheel's teeth z2 (d1/a = q/(q + z2) for x = 0), "
               "or the stage's ratio"), x=x)
    return 8.809524 * x * x - 9.583333 * x + 5.177143


def worm_life_factor_contact(N: float) -> float:
    """Tin-bronze wheel: K_HN = (10⁷/N)^(1/8), N clamped to [2.6e5, 2.5e8] (textbook).
    Aluminium bronze and cast iron: no life factor (their [σ_H] depends on v_s instead)."""
    return (1e7 / min(max(N, 2.6e5), 2.5e8)) ** (1 / 8)


def worm_life_factor_bending(N: float) -> float:
    """Wheel bending: K_FN = (10⁶/N)^(1/9), N clamped to [1e5, 2.5e8] (textbook)."""
    return (1e6 / min(max(N, 1e5), 2.5e8)) ** (1 / 9)


def worm_contact_check(T2, K, a, ZE, Zrho, allowable=None) -> Check:
    """Wheel contact check σ_H = Z_E Z_ρ sqrt(K T2 / a³) ≤ [σ_H] (T2 N·m, a m, Z_E √Pa; Pa).
    Steel worm on bronze/cast-iron wheel: Z_E = 160 √MPa."""
    s = ZE * Zrho * math.sqrt(K * T2 / a ** 3)
    return check("worm_contact", N_("Worm-wheel contact fatigue"), r"\sigma_H", s, allowable,
                  "MPa", T2=T2, K=K, a=a, ZE=ZE, Zrho=Zrho)


def design_worm_center_distance(T2, K, ZE, Zrho, allowable) -> float:
    """Minimum centre distance a ≥ ∛(K T2 (Z_E Z_ρ/[σ_H])²), m."""
    return (K * T2 * (ZE * Zrho / allowable) ** 2) ** (1 / 3)


def worm_helix_factor(gamma: float) -> float:
    """Y_β = 1 − γ/140° (γ the lead angle in rad)."""
    return 1 - math.degrees(gamma) / 140.0


def worm_bending_check(T2, K, d1, d2, m, YFa2, gamma, allowable=None) -> Check:
    """Wheel-tooth bending check σ_F = 1.53 K T2 Y_Fa2 Y_β / (d1 d2 m) ≤ [σ_F], Y_β = 1 − γ/140°
    (T2 N·m; d1, d2, m in m; Pa). Y_Fa2 from the chart against z_v2 = z2/cos³γ and x2."""
    yb = worm_helix_factor(gamma)
    s = 1.53 * K * T2 * YFa2 * yb / (d1 * d2 * m)
    return check("worm_bending", N_("Worm-wheel bending fatigue"), r"\sigma_F", s, allowable,
                  "MPa", T2=T2, K=K, d1=d1, d2=d2, m=m, YFa2=YFa2, Ybeta=yb, gamma=gamma)


def sliding_speed(d1: float, n1_rpm: float, gamma: float) -> float:
    """Sliding speed v_s = π d1 n1 / (60 cos γ), m/s (d1 in m)."""
    return math.pi * d1 * n1_rpm / (60.0 * math.cos(gamma))


# Equivalent friction coefficient f_v against sliding speed v_s (m/s), ordinary cylindrical
# worm pairs (textbook table 11-18 of the 8th ed.; φ_v = arctan f_v is the table's second
# column, e.g. 0.045 ↔ 2°35'). Linear interpolation in v_s.
FRICTION_TABLES: dict[str, tuple[tuple[float, ...], tuple[float, ...]]] = {
    # tin bronze wheel, worm flank ≥ 45 HRC (ground/polished)
    "tin_bronze": ((0.01, 0.05, 0.10, 0.25, 0.50, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 8.0, 10.0, 15.0, 24.0),
                   (0.110, 0.090, 0.080, 0.065, 0.055, 0.045, 0.040, 0.035, 0.030, 0.028, 0.024, 0.022,
                    0.018, 0.016, 0.014, 0.013)),
    # tin bronze wheel, softer worm
    "tin_bronze_soft_worm": ((0.01, 0.05, 0.10, 0.25, 0.50, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 8.0, 10.0, 15.0),
                             (0.120, 0.100, 0.090, 0.075, 0.065, 0.055, 0.050, 0.045, 0.040, 0.035, 0.031,
                              0.029, 0.026, 0.024, 0.020)),
    # aluminium bronze wheel (ZCuAl10Fe3), hardened worm
    "aluminium_bronze": ((0.01, 0.05, 0.10, 0.25, 0.50, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 8.0),
                         (0.180, 0.140, 0.130, 0.100, 0.090, 0.070, 0.065, 0.055, 0.050, 0.045, 0.040,
                          0.035, 0.030)),
    # grey cast iron wheel, hardened worm (same values as aluminium bronze, v_s ≤ 2 m/s)
    "grey_iron": ((0.01, 0.05, 0.10, 0.25, 0.50, 1.0, 1.5, 2.0),
                  (0.180, 0.140, 0.130, 0.100, 0.090, 0.070, 0.065, 0.055)),
}


def equivalent_friction_angle(vs: float, pair: str = "tin_bronze") -> float:
    """Equivalent friction angle φ_v = arctan f_v(v_s) in rad, f_v interpolated linearly in
    :data:`FRICTION_TABLES` (below the first speed its value is kept; above the last, error)."""
    try:
        v, fv = FRICTION_TABLES[pair]
    except KeyError:
        raise KeyError(f"unknown worm material pair {pair!r}; allowed: {sorted(FRICTION_TABLES)}") from None
    if vs > v[-1]:
        raise ValueError(f"sliding speed {vs:.2f} m/s exceeds the table range ({v[-1]} m/s) for {pair}")
    return math.atan(float(np.interp(vs, v, fv)))


def worm_drive_efficiency(gamma: float, phi_v: float, k: float = 0.95) -> float:
    """η = k tan γ / tan(γ + φ_v), the worm driving; k = 0.95–0.96 for the bearing and
    oil-churning losses."""
    return k * math.tan(gamma) / math.tan(gamma + phi_v)


def worm_housing_area(a: float) -> float:
    """Estimated cooling area of an ordinary (finless) worm-reducer housing,
    A ≈ 9×10⁻⁵ a^1.88 m² with a in mm (textbook estimate); here a in m, A in m²."""
    return 9e-5 * (a * 1e3) ** 1.88


def worm_oil_temperature(P1: float, eta: float, kd: float, area: float, t0: float = 20.0) -> float:
    """Thermal balance: t = t0 + P1 (1 − η)/(k_d A), °C (P1 W, k_d W/(m²·°C) = 8.15–17.45,
    A m², t0 ambient °C)."""
    return t0 + P1 * (1 - eta) / (kd * area)


def worm_required_area(P1: float, eta: float, kd: float, t: float, t0: float = 20.0) -> float:
    """The cooling area A = P1 (1 − η)/(k_d (t − t0)) that keeps the oil at t °C, m²."""
    if t <= t0:
        raise ValueError("the oil temperature must exceed the ambient temperature")
    return P1 * (1 - eta) / (kd * (t - t0))


def worm_thermal(P1, eta, kd, area, t0=20.0, allowable=80.0) -> Check:
    """Thermal-balance check: oil temperature t (see :func:`worm_oil_temperature`) ≤ [t]
    (°C; textbook 60–70 °C usual, 80 °C at most)."""
    t = worm_oil_temperature(P1, eta, kd, area, t0)
    return check("worm_thermal", N_("Thermal balance (oil temperature)"), "t", t, allowable, "°C",
                  P1=P1, eta=eta, kd=kd, A=area, t0=t0)


# ---------------------------------------------------------------------------------------
# Shafts
# ---------------------------------------------------------------------------------------

def shaft_min_diameter(P_W: float, n_rpm: float, A0: float, keyway_increase: float = 0.0) -> float:
    """Torsion estimate d ≥ A0 ∛(P/n) of the textbook (mm, kW, rpm form; A0 e.g. 103–126 for
    45 steel), × (1 + ``keyway_increase``) (one keyway: 0.05–0.07 for d ≤ 100 mm, 0.03
    above; two keyways: 0.10–0.15). P in W, result in m."""
    return A0 * (P_W / 1e3 / n_rpm) ** (1 / 3) * (1 + keyway_increase) * 1e-3


def shaft_diameter_check(d, P_W, n_rpm, A0, keyway_increase=0.0) -> Check:
    """Check a chosen diameter d (m) against :func:`shaft_min_diameter` (sense "ge", mm)."""
    dmin = shaft_min_diameter(P_W, n_rpm, A0, keyway_increase)
    return check("shaft_min_diameter", N_("Minimum shaft diameter (torsion)"), "d", d, dmin,
                  "mm", "ge", P=P_W, n_rpm=n_rpm, A0=A0, keyway_increase=keyway_increase)


@dataclass(frozen=True)
class PointLoad:
    """A load on the shaft at axial position ``x`` (m; bearing A at 0, bearing B at the span,
    overhung loads outside). ``Fh``/``Fv``: transverse forces in the horizontal/vertical
    plane (N, signed). ``Fa``: axial force (N, +x) acting at radius ``r`` (m, signed, measured
    in the vertical plane, e.g. the pitch radius); it adds the couple Fa·r in the vertical plane."""
    x: float = q("m", "axial position (bearing A at 0, B at the span)")
    Fh: float = q("N", "transverse force in the horizontal plane", default=0.0)
    Fv: float = q("N", "transverse force in the vertical plane", default=0.0)
    Fa: float = q("N", "axial force along +x", default=0.0)
    r: float = q("m", "radius at which Fa acts (vertical plane)", default=0.0)


@dataclass(frozen=True)
class ShaftSection:
    """Bending moments at one station (N·m; the side of the station with the larger M)."""
    x: float = q("m", "axial position of the station")
    Mh: float = q("N·m", "horizontal-plane moment M_H")
    Mv: float = q("N·m", "vertical-plane moment M_V")
    M: float = q("N·m", "resultant √(M_H² + M_V²)")
    T: float = q("N·m", "torque counted at this station")
    Mca: float = q("N·m", "equivalent moment M_ca = √(M² + (αT)²)")


@dataclass(frozen=True)
class ShaftResult:
    """Reactions are the forces the bearings exert on the shaft (N, signed like the loads)."""
    RAh: float = q("N", "reaction of bearing A, horizontal plane")
    RAv: float = q("N", "reaction of bearing A, vertical plane")
    RBh: float = q("N", "reaction of bearing B, horizontal plane")
    RBv: float = q("N", "reaction of bearing B, vertical plane")
    FrA: float = q("N", "resultant radial load on bearing A")
    FrB: float = q("N", "resultant radial load on bearing B")
    Fa_total: float = q("N", "net applied axial force ΣF_a (taken by the bearings)")
    sections: tuple[ShaftSection, ...] = q("", "moments at every load and bearing station")
    critical: ShaftSection = q("", "the station of the largest M_ca")
    check: Check = q("", "σ_ca at the critical station")


def _as_load(item) -> PointLoad:
    if isinstance(item, PointLoad):
        return item
    if isinstance(item, dict):
        return PointLoad(**item)
    return PointLoad(*item)


def shaft_check(span: float, loads: Iterable, torque: float, d: float, allowable_bending: float,
                alpha: float = 0.6, torque_span: tuple[float, float] | None = None,
                stations: Iterable[float] = ()) -> ShaftResult:
    """Bending–torsion check of a shaft on two bearings at x = 0 and x = ``span`` (m).

    ``loads``: :class:`PointLoad` (or tuples/dicts of its fields). Both planes are solved by
    statics; the moment is evaluated on both sides of every load and bearing station.
    σ_ca = sqrt(M² + (αT)²)/(0.1 d³) ≤ [σ_-1b] at the station of largest equivalent moment;
    α = 0.3 static torque, 0.6 pulsating (usual), 1 alternating. ``torque`` (N·m) acts between
    ``torque_span`` = (x1, x2) (default: everywhere); ``d`` (m) the diameter at the checked
    section; ``allowable_bending`` [σ_-1b] in Pa. ``stations``: further positions (m) where the
    moments are evaluated, e.g. where a stepped shaft changes its diameter.
    """
    if span <= 0:
        raise ValueError("the bearing span must be positive")
    loads = [_as_load(p) for p in loads]
    # moment balance about A (counter-clockwise positive in each plane); the axial force at
    # radius r contributes −r·Fa in the vertical plane
    RBh = -sum(p.x * p.Fh for p in loads) / span
    RBv = -sum(p.x * p.Fv - p.r * p.Fa for p in loads) / span
    RAh = -sum(p.Fh for p in loads) - RBh
    RAv = -sum(p.Fv for p in loads) - RBv
    everything = loads + [PointLoad(0.0, RAh, RAv), PointLoad(span, RBh, RBv)]

    def moments(x: float, inclusive: bool) -> tuple[float, float]:
        left = [p for p in everything if (p.x <= x if inclusive else p.x < x)]
        mh = sum((p.Fh * (x - p.x) for p in left), 0.0)
        mv = sum((p.Fv * (x - p.x) + p.r * p.Fa for p in left), 0.0)
        return mh, mv

    x1, x2 = torque_span if torque_span is not None else (-math.inf, math.inf)
    sections = []
    for x in sorted({p.x for p in everything} | {float(x) for x in stations}):
        sides = [moments(x, False), moments(x, True)]
        mh, mv = max(sides, key=lambda s: math.hypot(*s))
        m = math.hypot(mh, mv)
        t = abs(torque) if x1 <= x <= x2 else 0.0
        sections.append(ShaftSection(float(x), mh, mv, m, t, math.hypot(m, alpha * t)))
    crit = max(sections, key=lambda s: s.Mca)
    s = crit.Mca / (0.1 * d ** 3)
    verdict = check("shaft_bending", N_("Shaft bending–torsion strength"), r"\sigma_{ca}", s,
                    allowable_bending, "MPa", M=crit.M, T=crit.T, alpha=alpha, d=d, x=crit.x)
    return ShaftResult(RAh, RAv, RBh, RBv, math.hypot(RAh, RAv), math.hypot(RBh, RBv),
                       sum(p.Fa for p in loads), tuple(sections), crit, verdict)


def shaft_stepped_check(result: ShaftResult, diameter_at, allowable_bending: float,
                        alpha: float = 0.6, torque_at=None) -> tuple[Check, ShaftSection, float]:
    """The bending–torsion check of a stepped shaft: σ_ca = √(M² + (αT)²)/(0.1 d³) at every
    station of ``result`` (see :func:`shaft_check`) with the diameter ``diameter_at(x)`` (m)
    of the section there; the critical section is the one of the largest σ_ca (not always
    the largest M_ca: a bearing journal is thinner than the hub seat). Returns (the check,
    the critical station, its diameter). ``torque_at(x, T)``: the torque at a station where
    it differs from the one ``result`` counted there (e.g. the motor side of a flywheel)."""
    worst, worst_d, worst_s = None, None, -1.0
    for sec in result.sections:
        if torque_at is not None and sec.T > 0:
            t = torque_at(sec.x, sec.T)
            sec = ShaftSection(sec.x, sec.Mh, sec.Mv, sec.M, t, math.hypot(sec.M, alpha * t))
        d = diameter_at(sec.x)
        s = sec.Mca / (0.1 * d ** 3)
        if s > worst_s + 1e-12 * max(abs(worst_s), 1.0):
            worst, worst_d, worst_s = sec, d, s
    verdict = check("shaft_bending", N_("Shaft bending–torsion strength"), r"\sigma_{ca}",
                    worst_s, allowable_bending, "MPa", M=worst.M, T=worst.T, alpha=alpha, d=worst_d,
                    x=worst.x)
    return verdict, worst, worst_d


def standard_diameter(d_min: float, series) -> float:
    """The smallest value of ``series`` (m, ascending) that is ≥ d_min (m); ValueError above
    the series."""
    for v in series:
        if v >= d_min * (1 - 1e-9):
            return float(v)
    raise ValueError(f"no standard diameter ≥ {d_min * 1e3:.1f} mm (series up to {series[-1] * 1e3:g} mm)")


def cube_mean_factor(torque) -> float:
    """(mean |T|³)^(1/3) / mean T of a torque sampled uniformly over one cycle: the factor
    that turns the mean-torque bearing load into the equivalent constant load of the same
    rating life when the load is proportional to the torque (P_m = (∫P³dφ/2π)^(1/3), the
    textbook's mean equivalent load of a varying load with ε = 3)."""
    t = np.asarray(torque, dtype=float)
    mean = float(np.mean(t))
    if not mean > 0:
        raise ValueError("the cycle's mean torque must be positive")
    return float(np.mean(np.abs(t) ** 3) ** (1 / 3) / mean)


def double_key_check(T: float, d: float, h: float, l_working: float, allowable=None) -> Check:
    """Two flat keys at 180°: the load is shared unevenly, the textbook counts 1.5 keys:
    σ_p = 4T/(1.5 d h l) ≤ [σ_p]."""
    s = 4 * T / (1.5 * d * h * l_working)
    return check("key_crushing", N_("Key joint crushing strength (two keys)"), r"\sigma_p",
                  s, allowable, "MPa", T=T, d=d, h=h, l=l_working, keys=2)


# ---------------------------------------------------------------------------------------
# Rolling bearings
# ---------------------------------------------------------------------------------------

def bearing_equivalent_load(Fr: float, Fa: float, e: float, X: float, Y: float, fp: float = 1.0) -> float:
    """P = f_p (X F_r + Y F_a) with the given X, Y when F_a/F_r > e, else P = f_p F_r
    (X = 1, Y = 0). N in, N out. f_p: 1.0–1.2 no/slight shock, 1.2–1.8 moderate, 1.8–3.0 heavy."""
    if Fr > 0 and Fa / Fr <= e:
        return fp * Fr
    return fp * (X * Fr + Y * Fa)


@dataclass(frozen=True)
class TaperedAxialLoads:
    Fd1: float = q("N", "derived axial force of bearing 1, F_r1/(2Y)")
    Fd2: float = q("N", "derived axial force of bearing 2")
    Fa1: float = q("N", "axial load carried by bearing 1")
    Fa2: float = q("N", "axial load carried by bearing 2")
    pressed: int = q("1", "the pressed (clamped) bearing: 1 or 2 (0: exactly balanced)")


def tapered_pair_axial_loads(Fr1: float, Fr2: float, Fae: float, Y: float | tuple[float, float],
                             arrangement: str = "face_to_face") -> TaperedAxialLoads:
    """Axial loads of a pair of tapered roller bearings (derived force F_d = F_r/(2Y)).

    Bearing 1 is at the left, bearing 2 at the right; ``Fae`` is the external axial force on
    the shaft, positive pointing from bearing 1 towards bearing 2. "face_to_face" (正装, X):
    the derived forces on the shaft point towards each other (bearing 1 resists leftward,
    bearing 2 rightward motion); "back_to_back" (反装, O): they point apart. The pressed
    bearing carries the balance of the other forces, the released one its own F_d.
    """
    y1, y2 = (Y, Y) if np.isscalar(Y) else Y
    fd1, fd2 = Fr1 / (2 * y1), Fr2 / (2 * y2)
    if arrangement == "face_to_face":
        s1, s2 = -1, +1      # direction of shaft motion each bearing resists
    elif arrangement == "back_to_back":
        s1, s2 = +1, -1
    else:
        raise ValueError("arrangement must be 'face_to_face' (X) or 'back_to_back' (O)")
    # net force on the shaft along +x if both bearings carried only their derived forces
    push = Fae - s1 * fd1 - s2 * fd2
    if push * s2 > 0:        # the shaft is pushed the way bearing 2 resists: 2 is pressed
        return TaperedAxialLoads(fd1, fd2, fd1, abs(Fae - s1 * fd1), 2)
    if push * s1 > 0:
        return TaperedAxialLoads(fd1, fd2, abs(Fae - s2 * fd2), fd2, 1)
    return TaperedAxialLoads(fd1, fd2, fd1, fd2, 0)      # exactly balanced


def bearing_life_hours(C: float, P: float, n_rpm: float, ball: bool, ft: float = 1.0) -> float:
    """Basic rating life L10h = 10⁶/(60 n) (f_t C/P)^ε in hours; ε = 3 ball, 10/3 roller."""
    eps = 3.0 if ball else 10.0 / 3.0
    return 1e6 / (60.0 * n_rpm) * (ft * C / P) ** eps


def required_dynamic_load(P: float, n_rpm: float, hours: float, ball: bool, ft: float = 1.0) -> float:
    """Basic dynamic load rating needed for a life of ``hours``: C' = P/f_t (60 n L_h/10⁶)^(1/ε), N."""
    eps = 3.0 if ball else 10.0 / 3.0
    return P / ft * (60.0 * n_rpm * hours / 1e6) ** (1 / eps)


def bearing_life_check(C, P, n_rpm, required_hours, ball: bool, ft=1.0) -> Check:
    """Life check L10h ≥ L_h' (sense "ge"; value/allowable in s, displayed in h)."""
    life = bearing_life_hours(C, P, n_rpm, ball, ft)
    return check("bearing_life", N_("Bearing rating life"), r"L_{10h}", life * 3600.0, required_hours * 3600.0,
                  "h", "ge", C=C, P=P, n_rpm=n_rpm, ft=ft, epsilon=3.0 if ball else 10.0 / 3.0)


def bearing_static_load(Fr: float, Fa: float, X0: float, Y0: float) -> float:
    """Equivalent static load P0 = max(X0 F_r + Y0 F_a, F_r) (N); deep-groove ball X0 = 0.6,
    Y0 = 0.5; tapered roller X0 = 0.5 and the bearing's Y0."""
    return max(X0 * Fr + Y0 * Fa, Fr)


def bearing_static_check(C0: float, P0: float, S0: float) -> Check:
    """Static strength of a rolling bearing under the peak load: C0/P0 ≥ S0 (sense "ge";
    S0 of rotating bearings 0.8–1.2 normal, 1.2–2.5 with shocks)."""
    return check("bearing_static", N_("Bearing static strength"), r"C_0/P_0", C0 / P0, S0, "1", "ge",
                  C0=C0, P0=P0)


# ---------------------------------------------------------------------------------------
# Flat keys
# ---------------------------------------------------------------------------------------

def key_working_length(L: float, b: float, form: str = "A") -> float:
    """Working length of an ordinary flat key: A (round ends) L − b, B (square) L,
    C (one round end) L − b/2 (m)."""
    try:
        return {"A": L - b, "B": L, "C": L - b / 2}[form.upper()]
    except KeyError:
        raise ValueError(f"key form must be A, B or C, not {form!r}") from None


def key_check(T: float, d: float, h: float, l_working: float, allowable=None) -> Check:
    """Crushing check of a flat-key joint σ_p = 2T/(k l d) = 4T/(d h l) ≤ [σ_p], k = h/2
    (T N·m; d, h, l in m; Pa)."""
    s = 4 * T / (d * h * l_working)
    return check("key_crushing", N_("Key joint crushing strength"), r"\sigma_p", s, allowable,
                  "MPa", T=T, d=d, h=h, l=l_working)

