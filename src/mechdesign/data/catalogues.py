"""Typed, SI access to the shipped strength tables (materials, gear factors, bearings, keys).

The YAML files are in course units with the unit in each key name; everything returned here
is SI (Pa, m, N, m/s, √Pa). Unknown names raise ``KeyError`` listing the allowed ones.
Material look-ups accept the table key (``"45_QT"``) or the Chinese name without spaces
(``"45调质"``, ``"40Cr表面淬火"``).
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache
from types import MappingProxyType

from ..lazy import np  # numpy on first use: validation reads names only

from . import load_yaml
from ..core.fields import q

MPA = 1e6
MM = 1e-3
KN = 1e3


def _norm(text: str) -> str:
    return "".join(ch for ch in str(text).casefold() if ch not in " _-·钢")


def _lookup(table: dict, key: str, what: str) -> tuple[str, dict]:
    if key in table:
        return key, table[key]
    wanted = _norm(key)
    for k, row in table.items():
        if wanted in (_norm(k), _norm(row.get("name_zh", ""))):
            return k, row
    raise KeyError(f"unknown {what} {key!r}; allowed: {', '.join(table)}")


def _hardness(row: dict) -> tuple[str, float | None, float | None, float | None]:
    for scale in ("HBW", "HRC"):
        rng = row.get(f"hardness_{scale}_range")
        if rng:
            return scale, float(rng[0]), float(rng[1]), row.get(f"hardness_design_{scale}")
    return "", None, None, None


# ----------------------------------------------------------------------------- materials

@dataclass(frozen=True)
class GearMaterial:
    key: str
    name_zh: str
    name_en: str
    hardness_scale: str         # "HBW" or "HRC"
    hardness_min: float         # in hardness_scale
    hardness_max: float
    hardness_design: float      # hardness the limits below were read at
    sigma_Hlim: float           # contact fatigue limit σHlim, Pa
    sigma_FE: float             # bending fatigue limit σFE (= 2 σFlim), Pa
    E: float                    # Young's modulus, Pa
    nu: float                   # Poisson's ratio
    life_curve_contact: str     # key of strength.CONTACT_LIFE_CURVES
    life_curve_bending: str     # key of strength.BENDING_LIFE_CURVES


def gear_material_keys() -> tuple[str, ...]:
    return tuple(load_yaml("materials.yaml")["gear"])


def gear_material(key: str) -> GearMaterial:
    """Gear material ``key`` (see :func:`gear_material_keys`)."""
    k, r = _lookup(load_yaml("materials.yaml")["gear"], key, "gear material")
    scale, hmin, hmax, hdes = _hardness(r)
    return GearMaterial(k, r["name_zh"], r["name_en"], scale, hmin, hmax, float(hdes),
                        r["sigma_Hlim_MPa"] * MPA, r["sigma_FE_MPa"] * MPA, r["E_GPa"] * 1e9, float(r["nu"]),
                        r["life_curve_contact"], r["life_curve_bending"])


@dataclass(frozen=True)
class WormWheelMaterial:
    key: str
    name_zh: str
    name_en: str
    sigma_H_base_hard_worm: float | None    # [σH]' at N = 1e7, worm flank > 45 HRC, Pa (tin bronzes)
    sigma_H_base_soft_worm: float | None    # [σH]' at N = 1e7, worm flank ≤ 45 HRC, Pa
    sigma_H_table: tuple[tuple[float, float], ...]   # ((v_s m/s, [σH] Pa), ...) for Al bronze / cast iron
    sigma_F_base_one_way: float             # [σF]' at N = 1e6, one-way loading, Pa
    sigma_F_base_reversed: float            # [σF]' at N = 1e6, reversed loading, Pa
    sliding_speed_max: float                # m/s
    friction_pair: str                      # key of strength.FRICTION_TABLES
    ZE: float                               # elastic coefficient with a steel worm, √Pa

    @property
    def life_dependent(self) -> bool:
        """True for tin bronzes ([σH] = K_HN [σH]'); False where [σH] depends on v_s instead."""
        return not self.sigma_H_table

    def contact_base(self, sliding_speed: float | None = None, hard_worm: bool = True) -> float:
        """[σH]' (tin bronzes; multiply by the life factor) or [σH] at ``sliding_speed`` m/s
        (aluminium bronze, cast iron: linear interpolation in the table, kept flat below its
        first speed), Pa."""
        if self.life_dependent:
            value = self.sigma_H_base_hard_worm if hard_worm else self.sigma_H_base_soft_worm
            return float(value)
        if sliding_speed is None:
            raise ValueError(f"{self.key}: [σH] depends on the sliding speed; pass sliding_speed")
        vs, s = zip(*self.sigma_H_table)
        if sliding_speed > vs[-1]:
            raise ValueError(f"{self.key}: sliding speed {sliding_speed:.2f} m/s beyond the table ({vs[-1]} m/s)")
        return float(np.interp(sliding_speed, vs, s))


def worm_wheel_material_keys() -> tuple[str, ...]:
    return tuple(load_yaml("materials.yaml")["worm_wheel"])


def worm_wheel_material(key: str) -> WormWheelMaterial:
    """Worm-wheel material ``key`` (see :func:`worm_wheel_material_keys`)."""
    k, r = _lookup(load_yaml("materials.yaml")["worm_wheel"], key, "worm-wheel material")
    hard, soft = r.get("sigma_H_base_MPa_hard_worm"), r.get("sigma_H_base_MPa_soft_worm")
    table = tuple((float(v), s * MPA) for v, s in zip(r.get("sigma_H_table_sliding_speed_m_s", ()),
                                                        r.get("sigma_H_table_MPa", ())))
    return WormWheelMaterial(k, r["name_zh"], r["name_en"], None if hard is None else hard * MPA,
                             None if soft is None else soft * MPA, table, r["sigma_F_base_MPa_one_way"] * MPA,
                             r["sigma_F_base_MPa_reversed"] * MPA, float(r["sliding_speed_max_m_s"]),
                             r["friction_pair"], r["ZE_sqrtMPa"] * 1e3)


@dataclass(frozen=True)
class ShaftMaterial:
    key: str
    name_zh: str
    name_en: str
    diameter_max: float         # blank diameter the properties hold for, m
    sigma_B: float              # tensile strength, Pa
    sigma_s: float              # yield strength, Pa
    sigma_minus1: float         # bending fatigue limit σ-1, Pa
    tau_minus1: float           # torsional fatigue limit τ-1, Pa
    sigma_minus1b_allow: float  # allowable bending stress [σ-1b] of the bending–torsion check, Pa
    A0_min: float               # A0 of d ≥ A0 ∛(P/n) (mm, kW, rpm form), dimensionless
    A0_max: float
    tau_T_allow_min: float      # [τT] range, Pa
    tau_T_allow_max: float


def shaft_material_keys() -> tuple[str, ...]:
    return tuple(load_yaml("materials.yaml")["shaft"])


def shaft_material(key: str) -> ShaftMaterial:
    """Shaft material ``key`` (see :func:`shaft_material_keys`)."""
    k, r = _lookup(load_yaml("materials.yaml")["shaft"], key, "shaft material")
    return ShaftMaterial(k, r["name_zh"], r["name_en"], r["diameter_max_mm"] * MM, r["sigma_B_MPa"] * MPA,
                         r["sigma_s_MPa"] * MPA, r["sigma_minus1_MPa"] * MPA, r["tau_minus1_MPa"] * MPA,
                         r["sigma_minus1b_allow_MPa"] * MPA, float(r["A0_range"][0]), float(r["A0_range"][1]),
                         r["tau_T_allow_MPa_range"][0] * MPA, r["tau_T_allow_MPa_range"][1] * MPA)


def shaft_diameter_series() -> tuple[float, ...]:
    """Standard shaft diameters (GB/T 2822 as printed in the course handbook), m."""
    return tuple(v * MM for v in load_yaml("materials.yaml")["shaft_diameter_series_mm"])


def unconfirmed(name: str) -> frozenset[str]:
    """The entries of the shipped data file ``name`` (e.g. ``"belts.yaml"``) that could not be
    confirmed against a public copy of their source (the file's ``unconfirmed`` list; each
    file's header says what the others were checked against)."""
    return frozenset(load_yaml(name).get("unconfirmed", ()))


def motor_confirmed(designation: str) -> bool:
    """True when the motor's row of motors.csv was confirmed against a public copy (its
    ``# confirmed:`` comment line)."""
    from importlib import resources

    text = resources.files("mechdesign.data").joinpath("motors.csv").read_text(encoding="utf-8")
    names = [ln.split(":", 1)[1].split() for ln in text.splitlines() if ln.startswith("# confirmed:")]
    return any(designation in n for n in names)


def bearing_confirmed(designation: str) -> bool:
    """True when the bearing's ratings were confirmed against a public copy of the table
    (bearings.yaml ``confirmed``); the others are transcribed and named as an assumption."""
    return str(designation) in load_yaml("bearings.yaml").get("confirmed", ())


# ----------------------------------------------------------------------------- gear factors

def tooth_factors(z: float) -> tuple[float, float]:
    """(Y_Fa, Y_Sa) of a standard 20° external gear with z (or z_v) teeth: linear
    interpolation in the textbook table (17 ≤ z ≤ 200); above 200 linear in 1/z towards the
    rack values."""
    t = load_yaml("gear_factors.yaml")
    zs, yfa, ysa = t["tooth_form"]["z"], t["tooth_form"]["YFa"], t["tooth_form"]["YSa"]
    if z < zs[0]:
        raise ValueError(f"z = {z:g} < {zs[0]}: the table holds for gears without undercut only")
    if z <= zs[-1]:
        return float(np.interp(z, zs, yfa)), float(np.interp(z, zs, ysa))
    w = zs[-1] / z                      # 1 at z = 200, 0 for the rack
    rack = t["rack"]
    return (float(w * yfa[-1] + (1 - w) * rack["YFa"]), float(w * ysa[-1] + (1 - w) * rack["YSa"]))


# ----------------------------------------------------------------------------- bearings

@dataclass(frozen=True)
class Bearing:
    designation: str = q("", "e.g. 6205, 30206")
    kind: str = q("", "'deep_groove_ball' or 'tapered_roller'")
    d: float = q("m", "bore")
    D: float = q("m", "outside diameter")
    B: float = q("m", "(inner-ring) width")
    Cr: float = q("N", "basic dynamic load rating C_r")
    C0r: float = q("N", "basic static load rating C_0r")
    T: float | None = q("m", "overall width of a tapered roller bearing", default=None)
    e: float | None = q("1", "tapered: limit of F_a/F_r", default=None)
    Y: float | None = q("1", "tapered: axial factor for F_a/F_r > e (X = 0.4)", default=None)
    Y0: float | None = q("1", "tapered: static axial factor", default=None)

    @property
    def ball(self) -> bool:
        return self.kind == "deep_groove_ball"


@lru_cache(maxsize=None)
def _bearing_rows() -> Mapping[str, Bearing]:
    """The catalogue by designation (built once; read-only)."""
    t = load_yaml("bearings.yaml")
    out = {}
    for kind in ("deep_groove_ball", "tapered_roller"):
        for r in t[kind]:
            out[str(r["designation"])] = Bearing(
                str(r["designation"]), kind, r["d_mm"] * MM, r["D_mm"] * MM, r["B_mm"] * MM, r["Cr_kN"] * KN,
                r["C0r_kN"] * KN, r["T_mm"] * MM if "T_mm" in r else None, r.get("e"), r.get("Y"), r.get("Y0"))
    return MappingProxyType(out)


def bearing_designations(series: str | None = None) -> tuple[str, ...]:
    """All catalogue designations, or those of a series ("62", "63", "302", "320")."""
    rows = _bearing_rows()
    return tuple(k for k in rows if series is None or _series(k) == series)


def _series(designation: str) -> str:
    return designation[:-2]


def bearing(designation: str) -> Bearing:
    rows = _bearing_rows()
    try:
        return rows[str(designation).strip()]
    except KeyError:
        raise KeyError(f"unknown bearing {designation!r}; allowed: {', '.join(rows)}") from None


def smallest_bearing(series: str, d_min: float) -> Bearing:
    """The bearing of ``series`` ("62", "63", "302", "320") with the smallest bore ≥ d_min (m)."""
    rows = [bearing(k) for k in bearing_designations(series)]
    if not rows:
        series_all = sorted({_series(k) for k in _bearing_rows()})
        raise KeyError(f"unknown bearing series {series!r}; allowed: {', '.join(series_all)}")
    fit = [b for b in sorted(rows, key=lambda b: b.d) if b.d >= d_min * (1 - 1e-9)]
    if not fit:
        raise ValueError(f"no {series} bearing in the catalogue has a bore ≥ {d_min * 1e3:.1f} mm")
    return fit[0]


def deep_groove_factors(Fa: float, C0r: float) -> tuple[float, float, float]:
    """(e, X, Y) of a deep-groove ball bearing for the relative axial load Fa/C0r (linear
    interpolation in the textbook table, clamped at its ends). Use X, Y when Fa/Fr > e."""
    t = load_yaml("bearings.yaml")["radial_factors_deep_groove"]
    r = Fa / C0r
    return (float(np.interp(r, t["Fa_over_C0r"], t["e"])), float(t["X"]),
            float(np.interp(r, t["Fa_over_C0r"], t["Y"])))


def temperature_factor(t_C: float) -> float:
    """Temperature factor f_t of the bearing life (1.0 up to 120 °C)."""
    t = load_yaml("bearings.yaml")["temperature_factor_ft"]
    return float(np.interp(t_C, t["temperature_C"], t["ft"]))


def load_factor_range(condition: str) -> tuple[float, float]:
    """Range of the load factor f_p for "none_or_light_shock", "moderate_shock", "heavy_shock"."""
    t = load_yaml("bearings.yaml")["load_factor_fp"]
    if condition not in t:
        raise KeyError(f"unknown load condition {condition!r}; allowed: {', '.join(t)}")
    return tuple(float(v) for v in t[condition])


# ----------------------------------------------------------------------------- keys

@dataclass(frozen=True)
class KeySize:
    b: float        # key width, m
    h: float        # key height, m
    t: float        # keyway depth in the shaft, m
    t1: float       # keyway depth in the hub, m
    d_over: float   # shaft diameter range d_over < d ≤ d_upto, m
    d_upto: float
    L_min: float    # key length range, m
    L_max: float

    @property
    def label(self) -> str:
        return f"{self.b * 1e3:g}×{self.h * 1e3:g}"


def key_for_shaft(d: float) -> KeySize:
    """The flat key for a shaft of diameter d (m), by the handbook's diameter ranges."""
    d_mm = d / MM
    rows = load_yaml("keys.yaml")["flat_keys"]
    for r in rows:
        if r["d_over_mm"] < d_mm <= r["d_upto_mm"] + 1e-9:
            return KeySize(r["b_mm"] * MM, r["h_mm"] * MM, r["t_shaft_mm"] * MM, r["t1_hub_mm"] * MM,
                           r["d_over_mm"] * MM, r["d_upto_mm"] * MM, r["L_min_mm"] * MM, r["L_max_mm"] * MM)
    raise ValueError(f"shaft diameter {d_mm:.1f} mm outside the key table "
                     f"({rows[0]['d_over_mm']}–{rows[-1]['d_upto_mm']} mm)")


def key_length_series() -> tuple[float, ...]:
    """Standard key lengths L (GB/T 1096), m."""
    return tuple(L * MM for L in load_yaml("keys.yaml")["length_series_mm"])


def standard_key_length(l_max: float, key: KeySize | None = None) -> float:
    """The longest standard key length ≤ ``l_max`` (m; usually the hub length less 5–10 mm),
    within the length range of ``key`` if given."""
    top = l_max if key is None else min(l_max, key.L_max)
    fit = [L for L in key_length_series() if L <= top * (1 + 1e-9)]
    if not fit or (key is not None and fit[-1] < key.L_min * (1 - 1e-9)):
        raise ValueError(f"no standard key length ≤ {l_max * 1e3:.1f} mm"
                         + ("" if key is None else f" for key {key.label} (L ≥ {key.L_min * 1e3:g} mm)"))
    return fit[-1]


def key_allowable_stress(hub: str = "steel", load: str = "light_shock") -> tuple[float, float]:
    """Range of the allowable crushing stress [σp] of a static key joint, Pa; ``hub`` "steel" or
    "cast_iron", ``load`` "static", "light_shock" or "shock"."""
    t = load_yaml("keys.yaml")["allowable_crushing_MPa"]
    if hub not in t:
        raise KeyError(f"unknown hub material {hub!r}; allowed: {', '.join(t)}")
    if load not in t[hub]:
        raise KeyError(f"unknown load kind {load!r}; allowed: {', '.join(t[hub])}")
    lo, hi = t[hub][load]
    return lo * MPA, hi * MPA


# ----------------------------------------------------------------------------- couplings

@dataclass(frozen=True)
class Coupling:
    """One size of an elastic sleeve pin coupling (LT, GB/T 4323), SI."""

    size: str
    Tn: float                    # nominal torque T_n, N·m
    n_max: float                 # largest speed [n] (steel), rpm
    bores: tuple[float, ...]     # the shaft-hole diameters a half coupling is bored to, m


def couplings() -> tuple[Coupling, ...]:
    """The LT sizes of data/couplings.yaml, smallest first."""
    return tuple(Coupling(r["size"], float(r["Tn_Nm"]), float(r["n_max_rpm"]),
                          tuple(b * MM for b in r["bores_mm"])) for r in load_yaml("couplings.yaml")["LT"])


def coupling_application_factor(drive_KA: float) -> float:
    """K_A of a motor-driven coupling (濮良贵 表14-1) for the drive's load class (its gear K_A)."""
    rows = load_yaml("couplings.yaml")["application_factor"]
    return float(next(r["K_A"] for r in rows if drive_KA <= r["drive_KA_upto"] + 1e-12))


def motor_end_ratio() -> tuple[float, float]:
    """The course guides' range of d/D for a shaft end coupled to the motor shaft D."""
    lo, hi = load_yaml("couplings.yaml")["motor_end_ratio"]
    return float(lo), float(hi)


def has_bore(bores, d: float) -> bool:
    """True when ``d`` (m) is one of a coupling size's ``bores``."""
    return any(abs(b - d) < 1e-7 for b in bores)


def coupling_for(motor_d: float, need: float, Tc: float, n_rpm: float) -> tuple[Coupling, float] | None:
    """(size, shaft-end bore) of the smallest LT coupling whose bores hold the motor shaft
    ``motor_d`` and a bore ≥ ``need`` (m), with T_c ≤ T_n and n ≤ [n]; the bore is the smallest
    such one. None when no size fits."""
    for c in couplings():
        if Tc > c.Tn * (1 + 1e-12) or n_rpm > c.n_max or not has_bore(c.bores, motor_d):
            continue
        fit = [b for b in c.bores if b >= need * (1 - 1e-9)]
        if fit:
            return c, min(fit)
    return None


def coupling_bores_for(motor_d: float, d: float) -> Coupling | None:
    """The smallest LT size with bores for both ``motor_d`` and ``d`` (m), whatever its torque."""
    return next((c for c in couplings() if has_bore(c.bores, motor_d) and has_bore(c.bores, d)), None)


def motor_shaft_confirmed(frame_height: float) -> bool:
    """True when the shaft extension of the frame (its centre height, m) was confirmed against a
    public copy (motors.csv's ``# shaft confirmed:`` line)."""
    from importlib import resources

    text = resources.files("mechdesign.data").joinpath("motors.csv").read_text(encoding="utf-8")
    frames = [ln.split(":", 1)[1].split() for ln in text.splitlines() if ln.startswith("# shaft confirmed:")]
    return any(f"{frame_height / MM:g}" in f for f in frames)
