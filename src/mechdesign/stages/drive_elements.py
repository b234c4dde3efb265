"""Drive elements designed beside the gear strength (issue 20): the V-belt by the standard
procedure (濮良贵《机械设计》9th ed. ch.8, :mod:`mechdesign.core.belts`), the geometric checks
of every drive gear stage (pointed tips, undercut, contact ratio) and the worm shaft's
deflection (ch.11). Called from :mod:`.drive_strength` and :mod:`.drive`.

Assumptions stated in the report:
- the belt's K_A from table 8-8 (an electric motor, light start) by the drive's gear K_A
  (its load class) and the hours per day; the brief's ``application_factor_KA`` overrides;
- the section from the selection chart (fig. 8-11, its boundaries read off the chart),
  the brief's ``section`` overrides; d_d1 = 100 mm (the program's default), raised to the
  section's d_dmin (table 8-7, then the next datum diameter of the series) when smaller;
- a0 = d_d1 + d_d2 rounded up to 10 mm (raised by 10 mm steps while α1 < 120°, at most
  2 (d_d1 + d_d2)) unless the brief gives ``center_distance_mm``;
- P0 interpolated bilinearly in n1 and d_d1, ΔP0 linearly in n1 (nearest row/column
  outside the tables);
- tips: s_a ≥ 0.25 m (through-hardened), 0.4 m (surface-hardened, carburised, nitrided);
  undercut: x ≥ x_min = h_a*(z_min − z)/z_min with z_min = 17 at α = 20°, h_a* = 1 (孙桓:
  2h_a*/sin²α = 17.10 rounded; core.gears.least_teeth, the number of the gear geometry and of
  the undercut warning; helical: z_v);
  contact ratio ε_α ≥ 1.2;
- worm shaft: y = √(F_t1² + F_r1²) L³/(48 E I) ≤ [y] = d1/1000 with I = π d_f1⁴/64,
  d_f1 = d1 − 2.4 m, E = 206 GPa, L the span the brief gives for the worm's shaft, else
  L ≈ 0.9 d2 (濮良贵 ch.11).
"""
from __future__ import annotations

import math
from functools import lru_cache

from ..core import belts, chains, gears
from ..core.drive import PULLEY_DIAMETERS_MM
from ..core.strength import Check, check
from ..data import load_yaml
from ..i18n import N_

E_STEEL = 206e9          # Pa
EPS_ALPHA_MIN = 1.2
D1_DEFAULT = 0.100       # m, the program's default small datum diameter

#: What to change when one of these checks fails: (catalogue msgid, the brief field of the
#: stage it is about, "" for the stage itself), or such pairs by the stage's type. The text
#: says it in words; the finding holds the field (``drive.stages[i].<field>``), which the
#: terminal prints after the text.
FIXES = {
    "belt_d_min": (N_("give a larger small pulley diameter d1"), "d1_mm"),
    "belt_speed_min": (N_("give a larger small pulley diameter d1 (v grows with d1)"), "d1_mm"),
    "belt_speed_max": (N_("give a smaller small pulley diameter d1"), "d1_mm"),
    "belt_wrap": (N_("give a larger centre distance or a smaller ratio"), "center_distance_mm"),
    "belt_count": (N_("use a larger belt section or a larger small pulley diameter d1"), "section"),
    "tooth_tip": (N_("reduce the shifts x1, x2 or use more teeth"), "x1"),
    "undercut": {"spur": (N_("give a positive shift x1, x2 at least the least shift, or more teeth"), "x1"),
                 "helical": (N_("give more teeth or a larger helix angle"), "z1")},
    "contact_ratio": (N_("use more teeth (a smaller module) or smaller shifts"), ""),
    "chain_z1": (N_("give the small sprocket more teeth z1 (at least 17)"), "z1"),
    "chain_z2": (N_("give the chain a smaller ratio or fewer teeth z1"), ""),
    "chain_power": (N_("give a larger chain or more rows"), "chain"),
    "chain_speed": (N_("give a smaller chain or fewer teeth z1"), ""),
    "chain_static": (N_("give a larger chain or more rows"), "chain"),
    "worm_deflection": (N_("give a shorter bearing span or a larger worm diameter factor q"), ""),
}


@lru_cache(maxsize=1)
def belt_tables() -> dict:
    return load_yaml("belts.yaml")


def belt_application_factor(drive_KA: float, hours_per_day: float) -> tuple[float, dict]:
    """K_A of table 8-8 (electric motor, light start) for the drive's load class and the
    hours per day; returns (K_A, the table row)."""
    t = belt_tables()["application_factor"]
    row = next(r for r in t["rows"] if drive_KA <= r["drive_KA_upto"] + 1e-12)
    col = sum(1 for h in t["hours_upto"] if hours_per_day > h)
    return float(row["K_A"][col]), row


def belt_KA(s, dp) -> float:
    if s.belt_KA is not None:
        return s.belt_KA
    return belt_application_factor(dp.KA, dp.hours_per_day)[0]


def belt_section(s, P: float, n1_rpm: float, KA: float) -> str | None:
    return s.section or belts.choose_section(belt_tables(), KA * P, n1_rpm)


def belt_small_diameter(s, P: float, n1_rpm: float, KA: float) -> float:
    """d_d1 when the brief gives none: 100 mm, raised to the section's d_dmin (table 8-7)
    and to the diameter giving the belt speed v ≥ 5 m/s, each rounded up to the datum
    series (table 8-9)."""
    section = belt_section(s, P, n1_rpm, KA)
    t = belt_tables()
    need = D1_DEFAULT * 1e3
    if section is not None:
        need = max(need, t["sections"][section]["d_min_mm"])
    need = max(need, t["limits"]["v_min_m_s"] * 60e3 / (math.pi * n1_rpm))
    if need <= D1_DEFAULT * 1e3:
        return D1_DEFAULT
    bigger = [d for d in PULLEY_DIAMETERS_MM if d >= need - 1e-9]
    return (min(bigger) if bigger else PULLEY_DIAMETERS_MM[-1]) * 1e-3


def belt_design(s, r, shaft, dp) -> belts.VBeltDesign:
    """The V-belt of stage ``s`` (realised as ``r``) on ``shaft`` (its power and speed)."""
    KA = belt_KA(s, dp)
    return belts.design_vbelt(belt_tables(), shaft.power, shaft.speed_rpm, KA, r.d1, r.d2, r.slip,
                              s.section, s.center_distance)


@lru_cache(maxsize=1)
def chain_tables() -> dict:
    return load_yaml("chains.yaml")


def chain_design(s, r, shaft, dp) -> chains.ChainDesign:
    """The roller chain of stage ``s`` (realised teeth ``r.z1``, ``r.z2``) on ``shaft``."""
    t = chain_tables()
    if s.belt_KA is not None:
        KA = s.belt_KA
    else:
        KA = float(next(row["K_A"] for row in t["application_factor"] if dp.KA <= row["drive_KA_upto"] + 1e-12))
    return chains.design_chain(t, shaft.power, shaft.speed_rpm, KA, r.z1, r.z2, getattr(s, "chain", None),
                               getattr(s, "rows", 1), s.center_distance, shocks=dp.KA > 1.25)


# ----------------------------------------------------------------------------- gear stages

def _hardened(material: str) -> bool:
    key = material.lower()
    return any(w in key for w in ("surface", "carbur", "nitrid", "hardened"))   # keys are English


def gear_geometry_checks(design, s) -> tuple[Check, ...]:
    """Tip thickness, undercut (each gear) and the contact ratio of a spur or helical stage.
    Helical stages: the equivalent spur gears z_v = z/cos³β in the normal section."""
    g = design.geometry
    if design.kind != "gear" or g is None:
        return ()
    helical = isinstance(g, gears.HelicalPair)   # the geometry's type (s may be None for a spur pair)
    if not helical:
        pair, m, zs = g, g.m, (g.g1.z, g.g2.z)
    else:
        zs = tuple(z / math.cos(g.beta) ** 3 for z in (s.z1, s.z2))
        pair, m = gears.spur_pair(g.mn, zs[0], zs[1]), g.mn
    ha_star = pair.ha_star
    # z_min = 17 at α = 20°, h_a* = 1 (core.gears.least_teeth): the number the gear geometry and the
    # undercut warning (stages.drive.undercut_findings) use, so check and warning agree
    z_min = float(pair.z_min)
    out = []
    for k, (gd, mat) in enumerate(((pair.g1, design.materials[0]), (pair.g2, design.materials[1]))):
        factor = 0.4 if _hardened(mat) else 0.25
        out.append(check("tooth_tip", N_("Pinion tip thickness") if k == 0 else N_("Gear tip thickness"),
                         "s_a", gd.sa, factor * m, "mm", "ge", m=m, factor=factor, z=float(gd.z), x=gd.x))
        # x ≥ x_min = h_a*(z_min − z)/z_min, checked as z ≥ z_min (1 − x/h_a*) (a positive
        # quantity, so the margin 1 − allowable/value is defined)
        x_min = ha_star * (z_min - zs[k]) / z_min
        z_need = z_min * (1 - gd.x / ha_star)
        # a helical gear's undercut is that of its equivalent spur gear z_v = z/cos³β
        out.append(check("undercut", N_("Pinion free of undercut") if k == 0 else N_("Gear free of undercut"),
                         "z", float(zs[k]), z_need, "1", "ge", x=gd.x, x_min=x_min, z_min=z_min,
                         ha_star=ha_star, **({"z": float((s.z1, s.z2)[k]), "beta": g.beta}
                                             if helical else {})))
    eps = design.extra["eps_alpha"]
    # a helical pair's ε_α is the textbook's estimate [1.88 − 3.2(1/z1 + 1/z2)] cos β
    # (stages.drive_strength): its numbers go with it to the report
    out.append(check("contact_ratio", N_("Contact ratio"), "\\varepsilon_\\alpha",
                     eps, EPS_ALPHA_MIN, "1", "ge",
                     **({"z1": float(s.z1), "z2": float(s.z2), "beta": g.beta} if helical else {})))
    return tuple(out)


# ----------------------------------------------------------------------------- worm shaft

def worm_span(g) -> float:
    """The worm shaft's bearing span where the brief gives none: L ≈ 0.9 d2 (濮良贵 ch.11) [m];
    the shaft's design (bending, bearings) and its deflection check take the same span."""
    return 0.9 * g.d2


def worm_root_diameter(g) -> float:
    """The worm's root circle d_f1 = d1 − 2(h_a* + c*)m = d1 − 2.4 m (GB/T 10085, h_a* = 1,
    c* = 0.2) [m]."""
    return g.d1 - 2.4 * g.m


def worm_deflection_check(design, span: float | None) -> Check:
    """y = √(F_t1² + F_r1²) L³/(48 E I) ≤ [y] = d1/1000 (濮良贵 ch.11, eq. 11-?: the worm
    as a simply supported beam loaded at mid-span), I = π d_f1⁴/64."""
    g = design.geometry
    f = design.forces
    d1, m = g.d1, g.m
    df1 = worm_root_diameter(g)
    L = span if span else worm_span(g)
    inertia = math.pi * df1 ** 4 / 64
    y = math.hypot(f["Ft"], f["Fr"]) * L ** 3 / (48 * E_STEEL * inertia)
    allow = d1 / 1000
    return check("worm_deflection", N_("Worm shaft stiffness (deflection)"), "y", y, allow, "μm",
                 "le", Ft1=f["Ft"], Fr1=f["Fr"], L=L, E=E_STEEL, I=inertia, df1=df1, d1=d1,
                 span_given=1.0 if span else 0.0)
