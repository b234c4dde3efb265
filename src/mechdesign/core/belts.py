"""Ordinary V-belt drives designed by the standard procedure of 濮良贵《机械设计》(9th ed.)
ch.8 (§8-4, 普通V带传动的设计计算): P_ca = K_A·P, the section from the selection chart,
d_d1 ≥ d_dmin, the belt speed, d_d2, the centre distance and datum length, α1, the number
of belts z, the initial tension F0 and the load on the shafts F_p.

Pure: the tables come in as a plain mapping (the layout of ``data/belts.yaml``); SI in and
out (W, rpm where named ``n1_rpm``, m, N, rad). The textbook's formulas are in kW and mm;
each function says which it converts.
"""
from __future__ import annotations

import math
from bisect import bisect_right
from dataclasses import dataclass

from .errors import N_, DesignError
from .fields import q
from .strength import Check, check


class BeltDesignError(DesignError):
    """The belt cannot be designed with the shipped tables (a catalogue message: ``.en``, ``.zh``, ``.text(lang)``)."""


@dataclass(frozen=True)
class VBeltDesign:
    """One V-belt drive designed by 濮良贵 ch.8."""

    section: str = q("", "belt section (Z, A, B)")
    section_given: bool = q("", "the brief gives the section")
    section_chart: str = q("", "the section the selection chart gives (a larger one is used when "
                           "the chart's fails its checks)")
    KA: float = q("1", "application factor K_A (table 8-8)")
    power: float = q("W", "P transmitted by the small pulley")
    power_design: float = q("W", "P_ca = K_A·P")
    n1_rpm: float = q("rpm", "speed of the small pulley")
    d1: float = q("m", "small datum diameter d_d1")
    d2: float = q("m", "large datum diameter d_d2")
    d_min: float = q("m", "smallest datum diameter of the section d_dmin (table 8-7)")
    slip: float = q("1", "elastic slip ε")
    v: float = q("m/s", "belt speed v = π d_d1 n1 / 60")
    a0: float = q("m", "initial centre distance a0")
    a0_min: float = q("m", "0.7 (d_d1 + d_d2)")
    a0_max: float = q("m", "2 (d_d1 + d_d2)")
    L_d0: float = q("m", "L_d0 = 2a0 + π(d1 + d2)/2 + (d2 − d1)²/(4 a0)")
    L_d: float = q("m", "standard datum length (table 8-2), the nearest to L_d0")
    a: float = q("m", "centre distance a = a0 + (L_d − L_d0)/2")
    a_min: float = q("m", "a − 0.015 L_d (fitting range)")
    a_max: float = q("m", "a + 0.03 L_d (take-up range)")
    alpha1: float = q("rad", "wrap angle on the small pulley α1 = π − (d2 − d1)/a")
    P0: float = q("W", "basic rated power of one belt (table 8-4, bilinear in n1 and d_d1)")
    dP0: float = q("W", "power increment ΔP0 (table 8-5, linear in n1)")
    K_alpha: float = q("1", "wrap-angle factor Kα (table 8-6, linear)")
    K_L: float = q("1", "length factor K_L (table 8-2)")
    P_r: float = q("W", "rated power of one belt (P0 + ΔP0)·Kα·K_L")
    z_exact: float = q("1", "P_ca / P_r")
    z: int = q("1", "number of belts (z_exact rounded up)")
    q_mass: float = q("kg/m", "mass per metre q (table 8-3)")
    F0: float = q("N", "initial tension of one belt 500 (2.5 − Kα) P_ca/(Kα z v) + q v² (kW, m/s)")
    Fp: float = q("N", "load on the shafts F_p = 2 z F0 sin(α1/2)")
    checks: tuple[Check, ...] = q("", "belt speed, wrap angle, number of belts")


def datum_length(a0: float, d1: float, d2: float) -> float:
    """L_d0 = 2a0 + π(d1 + d2)/2 + (d2 − d1)²/(4a0) (eq. 8-22), any consistent length unit."""
    return 2 * a0 + math.pi * (d1 + d2) / 2 + (d2 - d1) ** 2 / (4 * a0)


def center_distance(a0: float, L_d: float, L_d0: float) -> float:
    """a ≈ a0 + (L_d − L_d0)/2 (eq. 8-23)."""
    return a0 + (L_d - L_d0) / 2


def wrap_angle(d1: float, d2: float, a: float) -> float:
    """α1 = π − (d2 − d1)/a [rad] (the textbook's 180° − (d2 − d1)·57.3°/a)."""
    return math.pi - (d2 - d1) / a


def belt_speed(d1: float, n1_rpm: float) -> float:
    """v = π d1 n1 / 60 [m/s] with d1 in m."""
    return math.pi * d1 * n1_rpm / 60.0


def initial_tension(P_ca: float, K_alpha: float, z: int, v: float, q_mass: float) -> float:
    """F0 = 500 (2.5 − Kα) P_ca/(Kα z v) + q v² [N] (eq. 8-27, P_ca in kW): in W the
    factor 500 becomes 0.5."""
    return 0.5 * (2.5 - K_alpha) * P_ca / (K_alpha * z * v) + q_mass * v ** 2


def shaft_load(z: int, F0: float, alpha1: float) -> float:
    """F_p = 2 z F0 sin(α1/2) [N] (eq. 8-28)."""
    return 2 * z * F0 * math.sin(alpha1 / 2)


def _lin(xs, ys, x: float) -> float:
    """Linear interpolation, the end values outside."""
    if x <= xs[0]:
        return float(ys[0])
    if x >= xs[-1]:
        return float(ys[-1])
    k = bisect_right(xs, x) - 1
    t = (x - xs[k]) / (xs[k + 1] - xs[k])
    return float(ys[k] + t * (ys[k + 1] - ys[k]))


def rated_power(tables, section: str, d1: float, n1_rpm: float) -> float:
    """P0 [W] of table 8-4, bilinear in n1 and d_d1 (the nearest row/column outside)."""
    rows = {float(k): v for k, v in tables["rated_power"][section].items()}
    ds = sorted(rows)
    ns = tables["rated_power"]["n1_rpm"]
    by_d = [_lin(ns, rows[d], n1_rpm) for d in ds]
    return _lin(ds, by_d, d1 * 1e3) * 1e3


def power_increment(tables, section: str, ratio: float, n1_rpm: float) -> float:
    """ΔP0 [W] of table 8-5: the column of the ratio's range, linear in n1."""
    t = tables["power_increment"]
    col = max(0, bisect_right(t["ratio_from"], ratio + 1e-12) - 1)
    return _lin(t["n1_rpm"], [row[col] for row in t[section]], n1_rpm) * 1e3


def wrap_factor(tables, alpha1: float) -> float:
    """Kα of table 8-6, linear in α1."""
    t = tables["wrap_factor"]
    return _lin(t["alpha1_deg"], t["K_alpha"], math.degrees(alpha1))


def standard_length(tables, section: str, L_d0: float) -> tuple[float, float]:
    """(L_d [m], K_L): the datum length of table 8-2 nearest to L_d0."""
    t = tables["datum_lengths"][section]
    k = min(range(len(t["L_d_mm"])), key=lambda j: abs(t["L_d_mm"][j] - L_d0 * 1e3))
    return t["L_d_mm"][k] * 1e-3, float(t["K_L"][k])


def choose_section(tables, P_ca: float, n1_rpm: float) -> str | None:
    """The section of the selection chart (fig. 8-11, its boundaries as lines P ∝ n1 in
    the data); None above the largest shipped section."""
    for row in tables["selection_chart"]:
        if P_ca <= row["P_upper_at_1000rpm_kW"] * 1e3 * n1_rpm / 1000.0:
            return row["section"]
    return None


def design_vbelt(tables, P: float, n1_rpm: float, KA: float, d1: float, d2: float,
                 slip: float = 0.0, section: str | None = None, a0: float | None = None) -> VBeltDesign:
    """The whole procedure for datum diameters already chosen (the drive's ratio step picks
    them: d_d1 ≥ d_dmin, d_d2 = i·d_d1·(1 − ε) rounded to the series). ``a0`` defaults to
    d1 + d2 rounded up to 10 mm (inside 0.7…2 (d1 + d2)), raised by 10 mm steps while the
    wrap angle α1 (after rounding L_d to the series) is below 120°."""
    P_ca = KA * P
    if section is not None:
        return _design(tables, P, n1_rpm, KA, d1, d2, slip, section, True, a0, section)
    chart = choose_section(tables, P_ca, n1_rpm)
    if chart is None:
        raise BeltDesignError(
            N_("the V-belt needs a section larger than B (P_ca = {p_kw:.3g} kW at "
               "{n1:.0f} rpm): the shipped tables hold Z, A and B only"), p_kw=P_ca / 1e3, n1=n1_rpm)
    # The chart's section; when it fails (the wrap angle beyond its longest belt, too many
    # belts), the next larger section that passes (its d_dmin still met by d_d1).
    order = [r["section"] for r in tables["selection_chart"]]
    first = _design(tables, P, n1_rpm, KA, d1, d2, slip, chart, False, a0, chart)
    if all(c.passed for c in first.checks):
        return first
    for other in order[order.index(chart) + 1:]:
        b = _design(tables, P, n1_rpm, KA, d1, d2, slip, other, False, a0, chart)
        if all(c.passed for c in b.checks):
            return b
    return first


def _design(tables, P, n1_rpm, KA, d1, d2, slip, section: str, given: bool, a0, chart: str) -> VBeltDesign:
    P_ca = KA * P
    sec = tables["sections"][section]
    d_min = sec["d_min_mm"] * 1e-3
    v = belt_speed(d1, n1_rpm)
    lo, hi = 0.7 * (d1 + d2), 2 * (d1 + d2)
    lim = tables["limits"]
    alpha_min = math.radians(lim["alpha1_min_deg"])
    a0_given = a0 is not None
    if a0 is None:
        a0 = math.ceil((d1 + d2) * 100 - 1e-9) / 100
    while True:
        L_d0 = datum_length(a0, d1, d2)
        L_d, K_L = standard_length(tables, section, L_d0)
        a = center_distance(a0, L_d, L_d0)
        alpha1 = wrap_angle(d1, d2, a)
        # a0 not given: raised by 10 mm steps (up to 2 (d1 + d2)) until α1 ≥ 120°
        if a0_given or alpha1 >= alpha_min or a0 + 0.01 > hi + 1e-9:
            break
        a0 = round(a0 + 0.01, 6)
    ratio = d2 / (d1 * (1 - slip))
    P0 = rated_power(tables, section, d1, n1_rpm)
    dP0 = power_increment(tables, section, ratio, n1_rpm)
    Ka = wrap_factor(tables, alpha1)
    P_r = (P0 + dP0) * Ka * K_L
    z_exact = P_ca / P_r
    z = max(1, math.ceil(z_exact - 1e-9))
    qm = sec["q_kg_per_m"]
    F0 = initial_tension(P_ca, Ka, z, v, qm)
    Fp = shaft_load(z, F0, alpha1)
    checks = (
        check("belt_d_min", N_("Small datum diameter"), "d_{d1}", d1, d_min, "mm", "ge"),
        check("belt_speed_min", N_("Belt speed (lower limit)"), "v", v, lim["v_min_m_s"], "m/s",
               "ge", d1=d1, n_rpm=n1_rpm),
        check("belt_speed_max", N_("Belt speed (upper limit)"), "v", v, lim["v_max_m_s"], "m/s",
               "le", d1=d1, n_rpm=n1_rpm),
        check("belt_wrap", N_("Wrap angle of the small pulley"), "\\alpha_1", alpha1,
               math.radians(lim["alpha1_min_deg"]), "°", "ge", d1=d1, d2=d2, a=a),
        check("belt_count", N_("Number of belts"), "z", z, lim["belts_max"], "1", "le",
               z_exact=z_exact),
    )
    return VBeltDesign(section, given, chart, KA, P, P_ca, n1_rpm, d1, d2, d_min, slip, v, a0, lo, hi, L_d0,
                       L_d, a, a - 0.015 * L_d, a + 0.03 * L_d, alpha1, P0, dP0, Ka, K_L, P_r,
                       z_exact, z, qm, F0, Fp, checks)
