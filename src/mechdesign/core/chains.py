"""Roller-chain drives designed by the procedure of 濮良贵《机械设计》(9th ed.) ch.9 §9-5:
P_ca = K_A K_z P / K_p, the chain (pitch) from the rated power at n1, the links, the centre
distance, the chain speed, the load on the shafts F_Q and the checks.

Pure: the tables come in as a mapping (the layout of ``data/chains.yaml``); SI in and out
(W, rpm where named ``n1_rpm``, m, N). The textbook's formulas are in kW and mm.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import N_, DesignError
from .fields import q
from .strength import Check, check

INCH = 0.0254


class ChainDesignError(DesignError):
    """No shipped chain carries the power (a catalogue message: ``.en``, ``.zh``, ``.text(lang)``)."""


@dataclass(frozen=True)
class ChainDesign:
    """One roller-chain drive designed by 濮良贵 ch.9."""

    chain: str = q("", "chain number (A series, GB/T 1243), e.g. 10A")
    chain_given: bool = q("", "the brief gives the chain")
    rows: int = q("1", "number of rows (strands)")
    pitch: float = q("m", "pitch p")
    z1: int = q("1", "teeth of the small sprocket")
    z2: int = q("1", "teeth of the large sprocket")
    KA: float = q("1", "application factor K_A (table 9-6)")
    Kz: float = q("1", "tooth factor K_z = (19/z1)^1.08")
    Kp: float = q("1", "multi-row factor K_p")
    power: float = q("W", "P on the small sprocket")
    power_design: float = q("W", "P_ca = K_A K_z P / K_p")
    rated_power: float = q("W", "rated power of one strand of the chain at n1 (the chart's stand-in)")
    n1_rpm: float = q("rpm", "speed of the small sprocket")
    a0: float = q("m", "initial centre distance a0")
    L_p0: float = q("1", "links from a0: 2a0/p + (z1 + z2)/2 + (p/a0)((z2 − z1)/2π)²")
    L_p: int = q("1", "links, L_p0 rounded up to an even number")
    a: float = q("m", "centre distance for L_p links")
    v: float = q("m/s", "mean chain speed z1 n1 p / 60")
    d1: float = q("m", "pitch diameter of the small sprocket p / sin(180°/z1)")
    d2: float = q("m", "pitch diameter of the large sprocket")
    Fe: float = q("N", "effective pull F_e = P / v")
    FQ_factor: float = q("1", "F_Q / F_e (1.2, 1.3 with shocks)")
    FQ: float = q("N", "load on the shafts F_Q")
    S: float | None = q("1", "static safety factor Q / (K_A F_1) (chains slower than 0.6 m/s)")
    checks: tuple[Check, ...] = q("", "teeth, rated power, speed (and static safety)")


def tooth_factor(z1: int) -> float:
    """K_z = (19/z1)^1.08 (the chart is drawn for z1 = 19)."""
    return (19.0 / z1) ** 1.08


def rated_power_one_strand(p: float, n1_rpm: float, z1: float = 19, K_r: float = 17.0,
                           hp_to_W: float = 745.7) -> float:
    """min(link-plate, roller-bushing) rating [W] by the ANSI formulas (Shigley eqs. 17-32,
    17-33): H1 = 0.004 z1^1.08 n1^0.9 p^(3 − 0.07p), H2 = 1000 K_r z1^1.5 p^0.8 / n1^1.5 [hp,
    p in inches]."""
    pin = p / INCH
    h1 = 0.004 * z1 ** 1.08 * n1_rpm ** 0.9 * pin ** (3 - 0.07 * pin)
    h2 = 1000 * K_r * z1 ** 1.5 * pin ** 0.8 / n1_rpm ** 1.5
    return min(h1, h2) * hp_to_W


def links(a0: float, p: float, z1: int, z2: int) -> float:
    """L_p0 = 2a0/p + (z1 + z2)/2 + (p/a0)((z2 − z1)/2π)² (eq. 9-17)."""
    return 2 * a0 / p + (z1 + z2) / 2 + (p / a0) * ((z2 - z1) / (2 * math.pi)) ** 2


def even_links(L_p0: float) -> int:
    n = math.ceil(L_p0 - 1e-9)
    return n + (n % 2)


def center_distance(p: float, L_p: int, z1: int, z2: int) -> float:
    """a = (p/4)[(L_p − (z1+z2)/2) + √((L_p − (z1+z2)/2)² − 8((z2 − z1)/2π)²)], the exact
    inverse of :func:`links` (the textbook's a = f1 p [2L_p − (z1 + z2)] tabulates it)."""
    s = L_p - (z1 + z2) / 2
    k = (z2 - z1) / (2 * math.pi)
    return p / 4 * (s + math.sqrt(s * s - 8 * k * k))


def chain_speed(z1: int, n1_rpm: float, p: float) -> float:
    """v = z1 n1 p / 60 [m/s], p in m (the textbook's z1 n1 p / (60 × 1000), p in mm)."""
    return z1 * n1_rpm * p / 60.0


def sprocket_diameter(p: float, z: int) -> float:
    """d = p / sin(180°/z)."""
    return p / math.sin(math.pi / z)


def design_chain(tables, P: float, n1_rpm: float, KA: float, z1: int, z2: int, chain: str | None = None,
                 rows: int = 1, a0: float | None = None, shocks: bool = False) -> ChainDesign:
    lim = tables["limits"]
    f = tables["rated_power_formula"]
    Kz = tooth_factor(z1)
    Kp = float(tables["row_factor"][rows])
    P_ca = KA * Kz * P / Kp
    rated = {k: rated_power_one_strand(c["p_mm"] * 1e-3, n1_rpm, f["z1_chart"], f["K_r"], f["hp_to_kW"] * 1e3)
             for k, c in tables["chains"].items()}
    given = chain is not None
    if chain is None:
        fit = [k for k in tables["chains"] if rated[k] >= P_ca]
        if not fit:
            raise ChainDesignError(
                N_("no shipped roller chain (08A … 32A, {rows} row(s)) carries P_ca = {p_kw:.3g} kW at "
                   "{n1:.0f} rpm; use more rows or another drive"), rows=rows, p_kw=P_ca / 1e3, n1=n1_rpm)
        chain = fit[0]
    c = tables["chains"][chain]
    p = c["p_mm"] * 1e-3
    if a0 is None:
        a0 = lim["a0_pitches"] * p
    L_p0 = links(a0, p, z1, z2)
    L_p = even_links(L_p0)
    a = center_distance(p, L_p, z1, z2)
    v = chain_speed(z1, n1_rpm, p)
    Fe = P / v
    kq = lim["FQ_factor_shock"] if shocks else lim["FQ_factor"]
    FQ = kq * Fe
    checks = [
        check("chain_z1", N_("Teeth of the small sprocket"), "z_1", z1, lim["z1_min"], "1", "ge"),
        check("chain_z2", N_("Teeth of the large sprocket"), "z_2", z2, lim["z2_max"], "1", "le"),
        check("chain_power", N_("Rated power of the chain"), "P_{ca}", P_ca, rated[chain], "kW",
               "le", Kz=Kz, Kp=Kp, KA=KA),
        check("chain_speed", N_("Chain speed"), "v", v, lim["v_max_m_s"], "m/s", "le"),
    ]
    S = None
    if v < lim["v_static_m_s"]:
        F1 = Fe + c["q_kg_per_m"] * v ** 2
        S = c["Q_kN"] * 1e3 * rows / (KA * F1)
        checks.append(check("chain_static", N_("Static safety of the chain"), "S", S,
                             lim["S_min"], "1", "ge", F1=F1))
    return ChainDesign(chain, given, rows, p, z1, z2, KA, Kz, Kp, P, P_ca, rated[chain], n1_rpm, a0, L_p0, L_p,
                       a, v, sprocket_diameter(p, z1), sprocket_diameter(p, z2), Fe, kq, FQ, S, tuple(checks))
