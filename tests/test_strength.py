"""Strength checks (core/strength.py), their data (data/catalogues.py) and report formulas
(render/strength_tex.py) against independent references.

References
----------
* 濮良贵《机械设计》例题10-1 (closed spur-gear pair of a belt conveyor: P = 10 kW,
  n1 = 960 rpm, u = 3.2, 15 years × 300 days × 2 shifts, z1 = 24, z2 = 77, pinion 40Cr 调质
  280 HBS, wheel 45 调质 240 HBS). Printed numbers used: N1 = 4.147e9, N2 = 1.296e9,
  σHlim = 600/550 MPa, K_HN = 0.90/0.95, [σH]2 = 522.5 MPa, d1t ≥ 65.396 mm (Kt = 1.3, its
  2.32∛ form), σFE = 500/380 MPa, K_FN = 0.85/0.88, S = 1.4, [σF] = 303.57/238.86 MPa,
  Y_Fa·Y_Sa at z = 24 and the interpolated 77 (2.65·1.58, 2.226·1.764) and their ratios to
  [σF], 0.01379 and 0.01644. Anything else from the example is re-derived by hand in the
  test's docstring.
* 9th-ed. worm example (P = 9 kW, n1 = 1450 rpm, i ≈ 20, z1 = 2, z2 = 41, m = 8, d1 = 80,
  a = 200 mm, ZCuSn10P1 metal mould, 12000 h): its intermediate values as reproduced by the
  mechtool.cn worm calculator (K = 1.2075, T2 = 948.4 N·m, [σH] = 217.98 MPa, a ≥ 173.13 mm,
  v_s = 6.194 m/s, φ_v = 1.169°, η = 0.859, Y_Fa2 = 2.87, σF = 22.02 MPa, [σF] = 36.09 MPa);
  re-derived by hand below.
* Closed forms: Z_E of steel pairs (textbook Z_E table 189.8 / 188.9 / 162.0 √MPa),
  Z_H ≈ 2.5, Z_ε = sqrt((4 − ε_α)/3), bearing life ∝ (C/P)^ε, statics of a beam, the thermal
  balance solved both ways, σp = 2T/(k l d), tapered-bearing geometry e·Y = 0.6.
"""
from __future__ import annotations

import math
import re
from dataclasses import replace

import pytest

from mechdesign.core import strength as s
from mechdesign.data import catalogues as cat
from mechdesign.render import strength_tex as tex

MPa = 1e6
mm = 1e-3
D = math.radians


# ----------------------------------------------------------------------------- allowables

def test_example_10_1_cycles_and_allowable_stresses():
    """N = 60 n j L_h with L_h = 2·8·300·15 = 72000 h; [σ] = K_N σlim / S."""
    N1 = s.stress_cycles(960, 2 * 8 * 300 * 15)
    assert N1 == pytest.approx(4.147e9, rel=1e-3)
    assert s.stress_cycles(960 / 3.2, 72000) == pytest.approx(1.296e9, rel=1e-3)
    pinion, wheel = cat.gear_material("40Cr_QT"), cat.gear_material("45_QT")
    assert (pinion.sigma_Hlim, wheel.sigma_Hlim) == (600 * MPa, 550 * MPa)
    assert (pinion.sigma_FE, wheel.sigma_FE) == (500 * MPa, 380 * MPa)
    assert s.allowable_stress(wheel.sigma_Hlim, 0.95, 1.0) == pytest.approx(522.5 * MPa)
    assert s.allowable_stress(pinion.sigma_FE, 0.85, 1.4) == pytest.approx(303.57 * MPa, abs=0.01 * MPa)
    assert s.allowable_stress(wheel.sigma_FE, 0.88, 1.4) == pytest.approx(238.86 * MPa, abs=0.01 * MPa)
    with pytest.raises(ValueError):
        s.allowable_stress(500 * MPa, 1.0, 0.0)


def test_life_factor_curves():
    """ISO 6336 / GB/T 3480 corner values behind the textbook charts, and the example's
    chart readings (K_HN 0.90 / 0.95, K_FN 0.85 / 0.88 at N = 4.147e9 / 1.296e9) within the
    accuracy of reading a log chart."""
    assert s.life_factor_contact(1e4) == pytest.approx(1.6)                 # static plateau
    assert s.life_factor_contact(1e7) == pytest.approx(1.3)
    assert s.life_factor_contact(1e9) == pytest.approx(1.0)
    # ISO: (3e8/N)^0.0756 between 6e5 and 1e7, (1e9/N)^0.057 between 1e7 and 1e9
    assert s.life_factor_contact(3e6) == pytest.approx((3e8 / 3e6) ** 0.0756, rel=0.01)
    assert s.life_factor_contact(1e8) == pytest.approx((1e9 / 1e8) ** 0.057, rel=0.01)
    assert s.life_factor_contact(5e7, "no_pitting") == pytest.approx(1.0)
    assert s.life_factor_bending(1e3) == pytest.approx(2.5)
    assert s.life_factor_bending(3e6) == pytest.approx(1.0)
    assert s.life_factor_bending(3e5) == pytest.approx((3e6 / 3e5) ** 0.16, rel=0.01)   # ISO St/V
    assert s.life_factor_bending(1e3, "nitrided") == pytest.approx(1.6)
    assert s.life_factor_contact(4.147e9) == pytest.approx(0.90, abs=0.02)
    assert s.life_factor_contact(1.296e9) == pytest.approx(0.95, abs=0.04)
    assert s.life_factor_bending(4.147e9) == pytest.approx(0.85, abs=0.02)
    assert s.life_factor_bending(1.296e9) == pytest.approx(0.88, abs=0.02)
    Ns = [10 ** k for k in range(3, 12)]
    for curve in s.CONTACT_LIFE_CURVES:
        ks = [s.life_factor_contact(N, curve) for N in Ns]
        assert all(a >= b for a, b in zip(ks, ks[1:]))
    with pytest.raises(KeyError, match="pitting_allowed"):
        s.life_factor_contact(1e8, "bogus")


# ----------------------------------------------------------------------------- gear factors

def test_tooth_factor_table_and_interpolation():
    assert cat.tooth_factors(24) == pytest.approx((2.65, 1.58))        # table points exactly
    assert cat.tooth_factors(17) == pytest.approx((2.97, 1.52))
    assert cat.tooth_factors(35) == pytest.approx((2.45, 1.65))
    assert cat.tooth_factors(200) == pytest.approx((2.12, 1.865))
    assert cat.tooth_factors(77) == pytest.approx((2.226, 1.764))     # 例题10-1 interpolation
    assert cat.tooth_factors(1e9) == pytest.approx((2.06, 1.97), abs=1e-6)   # rack
    yfa, ysa = cat.tooth_factors(400)
    assert 2.06 < yfa < 2.12 and 1.865 < ysa < 1.97
    # the example's comparison of Y_Fa Y_Sa / [σF] for pinion and wheel
    r1 = math.prod(cat.tooth_factors(24)) / 303.57
    r2 = math.prod(cat.tooth_factors(77)) / 238.86
    assert r1 == pytest.approx(0.01379, abs=1e-5) and r2 == pytest.approx(0.01644, abs=1e-5)
    with pytest.raises(ValueError):
        cat.tooth_factors(14)


def test_elastic_zone_and_ratio_factors():
    steel = cat.gear_material("45_QT")
    ze = s.elastic_coefficient(steel.E, steel.nu, steel.E, steel.nu)
    assert ze / 1e3 == pytest.approx(189.8, abs=0.05)                 # textbook Z_E table
    cast = cat.gear_material("ZG310-570_normalized")
    assert s.elastic_coefficient(steel.E, 0.3, cast.E, cast.nu) / 1e3 == pytest.approx(188.9, abs=0.1)
    iron = cat.gear_material("HT300")
    assert s.elastic_coefficient(steel.E, 0.3, iron.E, iron.nu) / 1e3 == pytest.approx(162.0, abs=0.2)
    assert s.zone_factor() == pytest.approx(2.5, abs=0.01)              # standard spur gears
    # helical, β = 15°: Z_H falls below the spur value
    assert s.zone_factor(math.atan(math.tan(D(20)) / math.cos(D(15))), None, D(14.076)) < 2.5
    # Z_ε = sqrt((4 − ε_α)/3); ε_α = 1.723 → 0.8712; Y_ε = 0.25 + 0.75/1.723 = 0.6853
    assert s.contact_ratio_factor(1.723) == pytest.approx(0.8712, abs=1e-4)
    assert s.contact_ratio_factor(1.0) == pytest.approx(1.0)
    assert s.bending_ratio_factor(1.723) == pytest.approx(0.6853, abs=1e-4)
    # helical Z_ε is continuous at ε_β = 1
    assert s.contact_ratio_factor(1.6, 1 - 1e-12) == pytest.approx(s.contact_ratio_factor(1.6, 1.0))
    assert s.contact_ratio_factor(1.6, 1.0) == pytest.approx(1 / math.sqrt(1.6))
    zb, yb = s.helix_factors(D(15), 1.5)                               # ε_β taken as 1
    assert zb == pytest.approx(0.98282, abs=1e-5) and yb == pytest.approx(0.875)
    assert s.helix_factors(D(15), 0.5)[1] == pytest.approx(1 - 0.5 * 15 / 120)
    assert s.helix_factors(D(40), 2.0)[1] == pytest.approx(0.75)       # lower bound


def test_example_10_1_design_and_check():
    """Contact design: the example's d1t ≥ 65.396 mm used 2.32∛(K T1 (u+1)/u (ZE/[σH])²/φd),
    2.32 ≈ ∛(2·2.5²) = 2.3208, so the exact form gives 65.42 mm (Z_ε = 1 in the 8th ed.).

    Hand calculation of the final pair (d1 = 70 mm, b = 70 mm, m = 2.5 mm, z1 = 28, z2 = 90;
    K_H = 1·1.12·1·1.417 = 1.587, K_F = 1·1.12·1·1.33 = 1.4896, T1 = 99480 N·mm):
    σH = sqrt(2·1.587·99480/(70·70²)·4.2/3.2)·2.5·189.8 = sqrt(1.20822)·474.5 = 521.6 MPa;
    m ≥ ∛(2·1.4896·99480/24² · 0.01644) = ∛8.458 = 2.037 mm;
    σF1 = 2·1.4896·99480·2.55·1.61/(70·70·2.5) = 99.4 MPa (z1 = 28: Y_Fa 2.55, Y_Sa 1.61).
    """
    T1 = 9.55e6 * 10 / 960 * 1e-3                                      # N·m
    assert T1 == pytest.approx(99.48, abs=0.01)
    d1t = s.design_d1_contact(T1, 1.3, 1.0, 3.2, 2.5, 189.8e3, 1.0, 522.5 * MPa)
    assert d1t / mm == pytest.approx(65.396 * 2.3208 / 2.32, rel=2e-4)
    # the book's correction d1 = d1t ∛(K/Kt) = 69.995 mm equals designing with K directly
    assert s.design_d1_contact(T1, 1.587, 1.0, 3.2, 2.5, 189.8e3, 1.0, 522.5 * MPa) == pytest.approx(
        d1t * (1.587 / 1.3) ** (1 / 3))
    m = s.design_module_bending(T1, 1.4896, 1.0, 24, 2.226, 1.764, 1.0, 238.86 * MPa)
    assert m / mm == pytest.approx(2.037, abs=0.002)
    assert s.standard_module(m) == pytest.approx(2.5 * mm)              # the example's m = 2.5

    hc = s.gear_contact_check(T1, 1.587, 70 * mm, 70 * mm, 90 / 28, 189.8e3, 2.5, 1.0, allowable=522.5 * MPa)
    # u = 90/28 = 3.214 (actual) instead of 3.2: σH = 521.1 MPa
    assert hc.value / MPa == pytest.approx(521.1, abs=0.3) and hc.passed and hc.sense == "le"
    assert s.gear_contact_stress(T1, 1.587, 70 * mm, 70 * mm, 3.2, 189.8e3, 2.5, 1.0) / MPa == pytest.approx(521.6, abs=0.2)
    yfa, ysa = cat.tooth_factors(28)
    fc = s.gear_bending_check(T1, 1.4896, 70 * mm, 70 * mm, 2.5 * mm, yfa, ysa, 1.0, allowable=303.57 * MPa)
    assert fc.value / MPa == pytest.approx(99.4, abs=0.1) and fc.passed
    # the textbook's φd-form 2KT1YFaYSa/(φd m³ z1²) is the same number
    assert fc.value == pytest.approx(2 * 1.4896 * T1 * yfa * ysa / (1.0 * (2.5 * mm) ** 3 * 28 ** 2))


def test_design_and_check_are_inverse():
    """A pair sized exactly by the design formulas sits exactly at the allowable stress."""
    T1, K, phi, u, ZH, ZE, Ze, allow = 150.0, 1.5, 0.9, 4.0, 2.45, 189.8e3, 0.88, 560 * MPa
    d1 = s.design_d1_contact(T1, K, phi, u, ZH, ZE, Ze, allow, Zbeta=0.98)
    c = s.gear_contact_check(T1, K, phi * d1, d1, u, ZE, ZH, Ze, 0.98, allow)
    assert c.value == pytest.approx(allow)
    m = s.design_module_bending(T1, K, phi, 23, 2.69, 1.575, 0.7, 300 * MPa)
    b = s.gear_bending_check(T1, K, phi * 23 * m, 23 * m, m, 2.69, 1.575, 0.7, allowable=300 * MPa)
    assert b.value == pytest.approx(300 * MPa)


def test_overloaded_gear_fails():
    """Doubling the torque on the example's pair: σH ∝ √T → 521.6·√2 = 737.7 MPa > 522.5;
    σF ∝ T → 198.8 MPa, still below 303.6 (bending has the larger margin in soft gears)."""
    T1 = 99.48 * 2
    hc = s.gear_contact_check(T1, 1.587, 70 * mm, 70 * mm, 3.2, 189.8e3, 2.5, 1.0, allowable=522.5 * MPa)
    assert hc.value / MPa == pytest.approx(737.7, abs=0.5)
    assert not hc.passed and hc.utilisation > 1
    fc = s.gear_bending_check(T1, 1.4896, 70 * mm, 70 * mm, 2.5 * mm, 2.55, 1.61, 1.0, allowable=303.57 * MPa)
    assert fc.passed
    fc = s.gear_bending_check(T1 * 2, 1.4896, 70 * mm, 70 * mm, 2.5 * mm, 2.55, 1.61, 1.0, allowable=303.57 * MPa)
    assert not fc.passed
    with pytest.raises(TypeError):
        s.gear_contact_check(T1, 1.587, 70 * mm, 70 * mm, 3.2, 189.8e3, 2.5, 1.0)   # no allowable


def test_standard_module_and_open_gears():
    assert s.standard_module(2.0 * mm) == pytest.approx(2.0 * mm)
    assert s.standard_module(2.0001 * mm) == pytest.approx(2.5 * mm)
    assert s.standard_module(0.3 * mm) == pytest.approx(1.0 * mm)
    assert s.standard_module(13 * mm) == pytest.approx(16 * mm)
    with pytest.raises(ValueError):
        s.standard_module(51 * mm)
    # a pair whose bending module is 1.8 mm: closed → 2, open (+15 % = 2.07) → 2.5
    args = (50.0, 1.3, 0.5, 20, 2.8, 1.55, 1.0)
    allow = 2 * 1.3 * 50.0 * 2.8 * 1.55 / (0.5 * 20 ** 2 * (1.8 * mm) ** 3)
    assert s.design_module_bending(*args, allow) == pytest.approx(1.8 * mm)
    assert s.standard_module(s.design_module_bending(*args, allow)) == pytest.approx(2 * mm)
    assert s.design_module_open(*args, allow, wear_allowance=0.15) == pytest.approx(2.5 * mm)
    assert s.design_module_open(*args, allow, wear_allowance=0.10) == pytest.approx(2 * mm)   # 1.98 mm


# ----------------------------------------------------------------------------- worm pair

def test_worm_example_efficiency_chain():
    """γ = arctan(z1 m/d1) = arctan(0.2) = 11.31°; v_s = π·80·1450/(60000·cos γ) = 6.194 m/s;
    f_v between 5 m/s (0.022) and 8 m/s (0.018): 0.022 − 1.194/3·0.004 = 0.02041,
    φ_v = 1.169°; η = 0.95 tan 11.31°/tan 12.479° = 0.859."""
    gamma = math.atan(2 * 8 / 80)
    assert math.degrees(gamma) == pytest.approx(11.31, abs=0.005)
    vs = s.sliding_speed(80 * mm, 1450, gamma)
    assert vs == pytest.approx(6.194, abs=0.001)
    phi = s.equivalent_friction_angle(vs)
    assert math.degrees(phi) == pytest.approx(1.169, abs=0.001)
    assert s.worm_drive_efficiency(gamma, phi) == pytest.approx(0.859, abs=0.001)
    # the table's φ_v column is arctan f_v: 1 m/s → 2°35', 4 m/s → 1°22', 0.01 m/s → 6°17'
    for v, deg, minutes in ((1.0, 2, 35), (4.0, 1, 22), (0.01, 6, 17), (0.25, 3, 43)):
        assert math.degrees(s.equivalent_friction_angle(v)) == pytest.approx(deg + minutes / 60, abs=1 / 60)
    assert s.equivalent_friction_angle(1.0, "aluminium_bronze") == pytest.approx(math.atan(0.07))
    with pytest.raises(ValueError):
        s.equivalent_friction_angle(3.0, "grey_iron")                  # cast iron only to 2 m/s


def test_worm_example_strength():
    """N = 60·72.5·12000 = 5.22e7; K_HN = (1e7/N)^(1/8) = 0.8134 → [σH] = 268·0.8134 = 218.0;
    a ≥ ∛(1.2075·948400·(160·2.9/217.98)²) = ∛(1145193·4.5311) = 173.1 mm;
    K_FN = (1e6/N)^(1/9) = 0.644 → [σF] = 56·0.644 = 36.09 MPa;
    σF = 1.53·1.2075·948400/(80·328·8)·2.87·(1 − 11.31/140) = 8.347·2.638 = 22.02 MPa."""
    wheel = cat.worm_wheel_material("ZCuSn10P1_metal")
    N = s.stress_cycles(1450 / 20, 12000)
    assert N == pytest.approx(5.22e7)
    sH = wheel.contact_base() * s.worm_life_factor_contact(N)
    assert sH / MPa == pytest.approx(217.98, abs=0.02)
    assert wheel.ZE == pytest.approx(160e3)
    a = s.design_worm_center_distance(948.4, 1.2075, wheel.ZE, 2.9, 217.98 * MPa)
    assert a / mm == pytest.approx(173.13, abs=0.01)
    sF = wheel.sigma_F_base_one_way * s.worm_life_factor_bending(N)
    assert sF / MPa == pytest.approx(36.09, abs=0.01)
    fc = s.worm_bending_check(948.4, 1.2075, 80 * mm, 328 * mm, 8 * mm, 2.87, math.atan(0.2), sF)
    assert fc.value / MPa == pytest.approx(22.02, abs=0.02) and fc.passed
    assert fc.inputs["Ybeta"] == pytest.approx(1 - 11.31 / 140, abs=1e-4)
    # contact at the chosen a = 200 mm, d1/a = 0.4: σH = 160·Zρ·sqrt(1.2075·948400/200³)
    zr = s.worm_contact_coefficient(0.4)
    assert zr == pytest.approx(2.75, abs=0.03)                          # chart: 2.74 at d1/a ≈ 0.39
    hc = s.worm_contact_check(948.4, 1.2075, 200 * mm, wheel.ZE, zr, sH)
    assert hc.value / MPa == pytest.approx(160 * zr * math.sqrt(1.2075 * 948400 / 200 ** 3), rel=1e-9)
    assert hc.passed
    # an undersized pair fails: a = 150 mm < 173 mm with the same Zρ = 2.9
    assert not s.worm_contact_check(948.4, 1.2075, 150 * mm, wheel.ZE, 2.9, sH).passed


def test_worm_factors_and_material_table():
    assert s.worm_contact_coefficient(0.35) == pytest.approx(2.9, abs=0.01)   # textbook reading
    zr = [s.worm_contact_coefficient(x) for x in (0.2, 0.3, 0.4, 0.5)]
    assert all(a > b for a, b in zip(zr, zr[1:]))
    with pytest.raises(ValueError):
        s.worm_contact_coefficient(0.7)
    assert s.worm_life_factor_contact(1e7) == 1.0 and s.worm_life_factor_bending(1e6) == 1.0
    assert s.worm_life_factor_bending(2.5e9) == pytest.approx(0.541, abs=1e-3)   # clamped at 2.5e8
    assert s.worm_life_factor_bending(5e4) == pytest.approx(10 ** (1 / 9))        # clamped at 1e5
    assert s.worm_helix_factor(D(14)) == pytest.approx(0.9)
    al = cat.worm_wheel_material("ZCuAl10Fe3_sand")
    assert not al.life_dependent
    assert al.contact_base(2.0) == pytest.approx(210 * MPa)
    assert al.contact_base(2.5) == pytest.approx(195 * MPa)
    with pytest.raises(ValueError):
        al.contact_base()
    sn = cat.worm_wheel_material("ZCuSn10P1_sand")
    assert sn.contact_base() == pytest.approx(180 * MPa) and sn.contact_base(hard_worm=False) == pytest.approx(150 * MPa)


def test_worm_thermal_balance_both_ways():
    """P1 = 9 kW, η = 0.86, α_d = 15 W/(m²·°C), A = 1.3 m², t0 = 20 °C:
    t = 20 + 9000·0.14/(15·1.3) = 84.6 °C > 80 °C (fails); the area for 70 °C is
    9000·0.14/(15·50) = 1.68 m²."""
    c = s.worm_thermal(9000, 0.86, 15, 1.3, 20, allowable=80)
    assert c.value == pytest.approx(84.615, abs=1e-3) and not c.passed and c.unit == "°C"
    A = s.worm_required_area(9000, 0.86, 15, 70, 20)
    assert A == pytest.approx(1.68)
    assert s.worm_oil_temperature(9000, 0.86, 15, A, 20) == pytest.approx(70)
    assert s.worm_thermal(9000, 0.86, 15, A, 20, allowable=70).passed
    # housing estimate A = 9e-5·a^1.88 (a in mm): a = 200 mm → 9e-5·21164 = 1.905 m²
    assert s.worm_housing_area(200 * mm) == pytest.approx(1.905, abs=0.002)
    with pytest.raises(ValueError):
        s.worm_required_area(9000, 0.86, 15, 15, 20)


# ----------------------------------------------------------------------------- shafts

def _equilibrium(res: s.ShaftResult, loads, span):
    for plane in ("h", "v"):
        F = [getattr(p, "F" + plane) for p in loads]
        RA, RB = getattr(res, "RA" + plane), getattr(res, "RB" + plane)
        assert sum(F) + RA + RB == pytest.approx(0, abs=1e-9)
        couples = [-p.r * p.Fa for p in loads] if plane == "v" else [0.0] * len(loads)
        for xo in (0.0, 0.123, span):          # moments about any point vanish
            total = sum((p.x - xo) * f for p, f in zip(loads, F)) + sum(couples)
            total += (0 - xo) * RA + (span - xo) * RB
            assert total == pytest.approx(0, abs=1e-9)


def test_shaft_simply_supported_closed_form():
    """Central load P on span L: reactions −P/2, M_max = PL/4; with T = 0 the equivalent
    stress is pure bending M/(0.1 d³): P = 4000 N, L = 0.2 m → M = 200 N·m, d = 40 mm →
    σ = 200/(0.1·0.04³) = 31.25 MPa."""
    res = s.shaft_check(0.2, [s.PointLoad(0.1, Fv=4000)], 0.0, 40 * mm, 60 * MPa)
    assert (res.RAv, res.RBv) == pytest.approx((-2000, -2000))
    assert (res.FrA, res.FrB) == pytest.approx((2000, 2000))
    assert res.critical.x == pytest.approx(0.1) and res.critical.M == pytest.approx(200)
    assert res.check.value / MPa == pytest.approx(31.25) and res.check.passed
    # torque alone: Mca = αT at every station
    t = s.shaft_check(0.2, [], 300.0, 40 * mm, 60 * MPa, alpha=0.6)
    assert t.check.value == pytest.approx(0.6 * 300 / (0.1 * 0.04 ** 3))
    # the resultant of the two planes: equal loads in both → M = √2 · PL/4
    both = s.shaft_check(0.2, [s.PointLoad(0.1, 4000, 4000)], 0.0, 40 * mm, 60 * MPa)
    assert both.critical.M == pytest.approx(200 * math.sqrt(2))


def test_shaft_overhung_and_axial_couple():
    """Overhung load P at x = −c: bearing B pulls back with P c/L, bearing A carries
    P(1 + c/L), the moment at A is P c. Axial force F_a at radius r at mid-span (alone):
    reactions ∓F_a r/L, the moment jumps from −F_a r/2 to +F_a r/2."""
    P, c, L = 1500.0, 0.06, 0.18
    res = s.shaft_check(L, [s.PointLoad(-c, Fh=P)], 50.0, 30 * mm, 60 * MPa)
    assert res.RBh == pytest.approx(P * c / L) and res.RAh == pytest.approx(-P * (1 + c / L))
    at_A = next(sec for sec in res.sections if sec.x == 0.0)
    assert abs(at_A.M) == pytest.approx(P * c)
    assert res.critical.x == 0.0
    Fa, r = 800.0, 0.1
    res = s.shaft_check(L, [(L / 2, 0.0, 0.0, Fa, r)], 0.0, 30 * mm, 60 * MPa)
    assert res.RBv == pytest.approx(Fa * r / L) and res.RAv == pytest.approx(-Fa * r / L)
    assert res.critical.M == pytest.approx(Fa * r / 2)
    assert res.Fa_total == pytest.approx(Fa)


def test_shaft_equilibrium_general():
    loads = [s.PointLoad(0.05, 1200, -500, 300, 0.08), s.PointLoad(0.14, -700, 900, -150, -0.04),
             s.PointLoad(-0.04, 0, 650), s.PointLoad(0.25, 400, 0)]
    res = s.shaft_check(0.2, loads, 120.0, 35 * mm, 60 * MPa, torque_span=(-0.04, 0.05))
    _equilibrium(res, loads, 0.2)
    # beyond the last load the shaft is unloaded; torque only inside its span
    ends = {sec.x: sec for sec in res.sections}
    assert ends[0.25].M == pytest.approx(0, abs=1e-9)
    assert ends[0.14].T == 0.0 and ends[0.05].T == 120.0
    assert res.check.inputs["M"] == pytest.approx(res.critical.M)
    assert res.check.value == pytest.approx(res.critical.Mca / (0.1 * 0.035 ** 3))


def test_undersized_shaft_fails():
    """M = PL/4 = 200 N·m, T = 300 N·m, α = 0.6: Mca = sqrt(200² + 180²) = 269.1 N·m; d = 30
    mm → σca = 269.1/(0.1·0.03³) = 99.7 MPa > [σ-1b] = 60 MPa of 45 调质; d = 40 mm → 42.0 MPa."""
    shaft = cat.shaft_material("45_QT")
    assert shaft.sigma_minus1b_allow == 60 * MPa
    small = s.shaft_check(0.2, [s.PointLoad(0.1, Fv=4000)], 300.0, 30 * mm, shaft.sigma_minus1b_allow)
    assert small.check.value / MPa == pytest.approx(99.7, abs=0.1) and not small.check.passed
    big = s.shaft_check(0.2, [s.PointLoad(0.1, Fv=4000)], 300.0, 40 * mm, shaft.sigma_minus1b_allow)
    assert big.check.value / MPa == pytest.approx(42.0, abs=0.1) and big.check.passed


def test_shaft_min_diameter():
    """d ≥ A0 ∛(P/n): P = 4 kW, n = 960 rpm, A0 = 112 → 112·0.16091 = 18.02 mm; +5 % keyway
    → 18.92 mm."""
    assert s.shaft_min_diameter(4000, 960, 112) / mm == pytest.approx(18.02, abs=0.01)
    assert s.shaft_min_diameter(4000, 960, 112, 0.05) / mm == pytest.approx(18.92, abs=0.01)
    assert s.shaft_diameter_check(20 * mm, 4000, 960, 112, 0.05).passed
    c = s.shaft_diameter_check(18 * mm, 4000, 960, 112, 0.05)
    assert not c.passed and c.sense == "ge"
    m = cat.shaft_material("45调质")
    assert (m.A0_min, m.A0_max) == (103, 126)
    assert cat.shaft_material("40Cr_QT").sigma_minus1b_allow == 70 * MPa


# ----------------------------------------------------------------------------- bearings

def test_bearing_life_scaling():
    """L10h ∝ (C/P)^ε; at P = C the life is 10⁶ revolutions."""
    base = s.bearing_life_hours(20e3, 4e3, 1000, ball=True)
    assert s.bearing_life_hours(40e3, 4e3, 1000, ball=True) == pytest.approx(8 * base)
    assert s.bearing_life_hours(40e3, 4e3, 1000, ball=False) == pytest.approx(
        2 ** (10 / 3) * s.bearing_life_hours(20e3, 4e3, 1000, ball=False))
    assert s.bearing_life_hours(5e3, 5e3, 500, ball=True) == pytest.approx(1e6 / (60 * 500))
    assert s.bearing_life_hours(20e3, 4e3, 2000, ball=True) == pytest.approx(base / 2)
    # f_t = 0.9 is the same as a 10 % smaller C
    assert s.bearing_life_hours(20e3, 4e3, 1000, True, ft=0.9) == pytest.approx(
        s.bearing_life_hours(18e3, 4e3, 1000, True))
    C = s.required_dynamic_load(4e3, 1000, 12000, ball=False)
    assert s.bearing_life_hours(C, 4e3, 1000, ball=False) == pytest.approx(12000)
    ok = s.bearing_life_check(43.2e3, 3000, 960, 20000, ball=False)
    assert ok.passed and ok.sense == "ge" and ok.course_value == pytest.approx(
        1e6 / (60 * 960) * (43.2 / 3) ** (10 / 3))
    assert not s.bearing_life_check(12.8e3, 3000, 960, 20000, ball=True).passed   # 6204: 2.4e3 h


def test_equivalent_load_and_tapered_pair():
    """Hand example, Y = 1.6: F_d = F_r/(2Y) → 937.5 N and 468.75 N.
    Face to face, F_ae = 500 N towards 2: 500 + 937.5 > 468.75 → 2 pressed, F_a2 = 1437.5,
    F_a1 = 937.5. F_ae = −1000 N: 1 pressed, F_a1 = 468.75 + 1000 = 1468.75, F_a2 = 468.75.
    Back to back, F_ae = 500: 500 + 468.75 > 937.5 → 1 pressed, F_a1 = 968.75, F_a2 = 468.75."""
    r = s.tapered_pair_axial_loads(3000, 1500, 500, 1.6)
    assert (r.Fd1, r.Fd2, r.Fa1, r.Fa2, r.pressed) == pytest.approx((937.5, 468.75, 937.5, 1437.5, 2))
    r = s.tapered_pair_axial_loads(3000, 1500, -1000, 1.6)
    assert (r.Fa1, r.Fa2, r.pressed) == pytest.approx((1468.75, 468.75, 1))
    r = s.tapered_pair_axial_loads(3000, 1500, 500, 1.6, "back_to_back")
    assert (r.Fa1, r.Fa2, r.pressed) == pytest.approx((968.75, 468.75, 1))
    # mirror symmetry (swap the bearings, reverse F_ae) and axial equilibrium
    for arr, (s1, s2) in (("face_to_face", (-1, 1)), ("back_to_back", (1, -1))):
        for fae in (-2000, -300, 0, 250, 1800):
            a = s.tapered_pair_axial_loads(2500, 4000, fae, (1.6, 1.4), arr)
            b = s.tapered_pair_axial_loads(4000, 2500, -fae, (1.4, 1.6), arr)
            assert (a.Fa1, a.Fa2) == pytest.approx((b.Fa2, b.Fa1))
            assert fae - s1 * a.Fa1 - s2 * a.Fa2 == pytest.approx(0, abs=1e-9)
            assert a.Fa1 >= a.Fd1 - 1e-9 and a.Fa2 >= a.Fd2 - 1e-9
    with pytest.raises(ValueError):
        s.tapered_pair_axial_loads(1, 1, 0, 1.6, "tandem")
    b = cat.bearing("30206")
    assert s.bearing_equivalent_load(3000, 900, b.e, 0.4, b.Y) == pytest.approx(3000)          # 0.3 ≤ e
    assert s.bearing_equivalent_load(3000, 1500, b.e, 0.4, b.Y, fp=1.2) == pytest.approx(1.2 * (1200 + 2400))
    assert s.bearing_equivalent_load(0, 1000, b.e, 0.4, b.Y) == pytest.approx(1600)


def test_bearing_catalogue():
    b = cat.bearing("32006")
    assert (b.d, b.D, b.Cr) == pytest.approx((30 * mm, 55 * mm, 35.8e3)) and not b.ball
    for des in (cat.bearing_designations("302") + cat.bearing_designations("303")
                + cat.bearing_designations("320")):
        t = cat.bearing(des)
        assert t.e * t.Y == pytest.approx(0.6, abs=0.03), des      # e = 1.5 tan α, Y = 0.4 cot α
        assert t.T >= t.B
    # issue 20: the 62/63 series reach 130 mm (6222, 6224, 6226), 302 and 303 go on to 100/80 mm
    for k in list(range(4, 23)) + [24, 26]:
        b62, b63 = cat.bearing(f"62{k:02d}"), cat.bearing(f"63{k:02d}")
        assert b62.d == b63.d == 5 * k * mm and b63.D > b62.D and b63.Cr > b62.Cr and b62.ball
        assert b62.C0r < b62.Cr and b63.C0r <= b63.Cr * 1.0 + 1e-9
    for k in range(5, 17):          # the 303 (medium) series is heavier than 302 at every bore
        if f"302{k:02d}" in cat.bearing_designations("302"):
            assert cat.bearing(f"303{k:02d}").Cr > cat.bearing(f"302{k:02d}").Cr
    assert cat.smallest_bearing("62", 32 * mm).designation == "6207"
    assert cat.smallest_bearing("302", 30 * mm).designation == "30206"
    with pytest.raises(ValueError):
        cat.smallest_bearing("63", 140 * mm)
    with pytest.raises(KeyError, match="320"):
        cat.smallest_bearing("72", 30 * mm)
    with pytest.raises(KeyError, match="6204"):
        cat.bearing("6223")
    e, X, Y = cat.deep_groove_factors(0.056 * 15.2e3, 15.2e3)      # table point
    assert (e, X, Y) == pytest.approx((0.26, 0.56, 1.71))
    assert cat.temperature_factor(100) == 1.0 and cat.temperature_factor(150) == pytest.approx(0.9)
    assert cat.load_factor_range("moderate_shock") == (1.2, 1.8)


# ----------------------------------------------------------------------------- keys

def test_key_selection_and_crushing():
    """d = 35 mm → key 10×8 (t = 5.0, t1 = 3.3); hub 60 mm → L ≤ 52 → 50 mm; form A:
    l = 50 − 10 = 40 mm; k = h/2 = 4 mm; T = 120 N·m: σp = 2·120000/(4·40·35) = 42.86 MPa."""
    k = cat.key_for_shaft(35 * mm)
    assert (k.b, k.h, k.t, k.t1) == pytest.approx((10 * mm, 8 * mm, 5 * mm, 3.3 * mm)) and k.label == "10×8"
    assert cat.key_for_shaft(30 * mm).label == "8×7"                   # 22 < d ≤ 30
    assert cat.key_for_shaft(30.5 * mm).label == "10×8"
    L = cat.standard_key_length(52 * mm, k)
    assert L == pytest.approx(50 * mm)
    assert cat.standard_key_length(500 * mm, k) == pytest.approx(110 * mm)     # key's own range
    with pytest.raises(ValueError):
        cat.standard_key_length(20 * mm, k)                             # 10×8 starts at 22 mm
    l = s.key_working_length(L, k.b, "A")
    assert l == pytest.approx(40 * mm)
    assert s.key_working_length(L, k.b, "B") == pytest.approx(50 * mm)
    assert s.key_working_length(L, k.b, "c") == pytest.approx(45 * mm)
    lo, hi = cat.key_allowable_stress("steel", "static")
    assert (lo, hi) == (120 * MPa, 150 * MPa)
    c = s.key_check(120.0, 35 * mm, k.h, l, lo)
    assert c.value / MPa == pytest.approx(42.857, abs=1e-3) and c.passed
    assert not s.key_check(500.0, 35 * mm, k.h, l, lo).passed          # 178.6 MPa
    with pytest.raises(ValueError):                # the table ends at 200 mm (was 130 mm before
        cat.key_for_shaft(250 * mm)                # i20 added the GB/T 1096 rows 130–200 mm)
    assert cat.key_for_shaft(150 * mm).label == "36×20"
    with pytest.raises(KeyError, match="light_shock"):
        cat.key_allowable_stress("steel", "heavy")


# ----------------------------------------------------------------------------- catalogues

def test_catalogue_keys_and_errors():
    required = {"45_normalized", "45_QT", "40Cr_QT", "40Cr_surface_hardened", "20CrMnTi_carburized",
                "35SiMn_QT", "ZG310-570_normalized", "HT300"}
    assert required <= set(cat.gear_material_keys())
    for key in cat.gear_material_keys():
        m = cat.gear_material(key)
        assert m.hardness_min <= m.hardness_design <= m.hardness_max
        assert m.life_curve_contact in s.CONTACT_LIFE_CURVES and m.life_curve_bending in s.BENDING_LIFE_CURVES
        assert 0 < m.sigma_FE < m.sigma_Hlim
    for key in cat.worm_wheel_material_keys():
        w = cat.worm_wheel_material(key)
        assert w.friction_pair in s.FRICTION_TABLES and w.sigma_F_base_reversed < w.sigma_F_base_one_way
    assert {"45_QT", "45_normalized", "40Cr_QT", "Q235"} <= set(cat.shaft_material_keys())
    assert cat.gear_material("40Cr表面淬火").key == "40Cr_surface_hardened"
    with pytest.raises(KeyError, match="45_QT"):
        cat.gear_material("42CrMo")
    with pytest.raises(KeyError, match="ZCuSn10P1_sand"):
        cat.worm_wheel_material("brass")
    with pytest.raises(KeyError, match="Q235"):
        cat.shaft_material("1045")


# ----------------------------------------------------------------------------- report

def _all_checks():
    return [
        s.gear_contact_check(99.48, 1.587, 70 * mm, 70 * mm, 3.2, 189.8e3, 2.5, 0.87, allowable=522.5 * MPa),
        s.gear_bending_check(99.48, 1.4896, 70 * mm, 70 * mm, 2.5 * mm, 2.55, 1.61, 0.68, 0.9, 303.57 * MPa),
        s.worm_contact_check(948.4, 1.2075, 200 * mm, 160e3, 2.74, 217.98 * MPa),
        s.worm_bending_check(948.4, 1.2075, 80 * mm, 328 * mm, 8 * mm, 2.87, math.atan(0.2), 36.09 * MPa),
        s.worm_thermal(9000, 0.86, 15, 1.3, 20),
        s.shaft_check(0.2, [s.PointLoad(0.1, Fv=4000)], 300.0, 30 * mm, 60 * MPa).check,
        s.shaft_diameter_check(20 * mm, 4000, 960, 112, 0.05),
        s.bearing_life_check(43.2e3, 3000, 960, 20000, ball=False),
        s.key_check(120.0, 35 * mm, 8 * mm, 40 * mm, 120 * MPa),
    ]


def test_formulas_show_course_units_and_verdict():
    gear_f = _all_checks()[1]
    text = tex.check_formula(gear_f)
    # 2·1.4896·99480·2.55·1.61·0.68·0.9/(70·70·2.5) = 99.4·0.612 = 60.8 MPa
    assert gear_f.value / MPa == pytest.approx(60.8, abs=0.05)
    assert r"\frac{2 \times 1.49 \times 99480 \times 2.55 \times 1.61 \times 0.68 \times 0.9}{70 \times 70.00 \times 2.5}" in text
    assert text.endswith(r"= 60.8\ \text{MPa} \le [\sigma_F] = 303.6\ \text{MPa}")
    key = tex.check_formula(_all_checks()[-1])
    assert r"\frac{2 \times 1.2\times10^{5}}{4 \times 40 \times 35}" in key and "42.9" in key
    hot = tex.check_formula(_all_checks()[4])
    assert "84.6" in hot and "> [t] = 80.0" in hot                      # failing relation shown
    life = tex.check_formula(_all_checks()[7])
    assert r"\frac{10}{3}" in life and r"\ge" in life
    for c in _all_checks():
        f = tex.check_formula(c)
        assert not re.search(r"\\dfrac|\\left|\\right|\\text\{[^}]*\\,", f), f
        assert f.count("{") == f.count("}"), f
        assert tex._value(c) in f


def test_rows_bilingual():
    checks = _all_checks()
    zh = tex.check_rows(checks, "zh")
    en = tex.check_rows(checks, "en")
    assert zh[0][:2] == ["齿面接触疲劳强度", "Tooth-flank contact fatigue"] and zh[0][4] == "MPa"
    assert [r[5] for r in zh] == ["合格" if c.passed else "不合格" for c in checks]
    assert [r[5] for r in en] == ["PASS" if c.passed else "FAIL" for c in checks]
    assert "不合格" in [r[5] for r in zh] and "合格" in [r[5] for r in zh]
    life = en[7]
    assert life[4] == "h" and life[3] == "20000"
    renamed = replace(checks[0], name="Contact fatigue (flanks)")      # a name of the catalogue
    assert tex.check_rows([renamed], "en")[0][:2] == ["齿面接触疲劳强度", "Contact fatigue (flanks)"]
    keyed = replace(checks[0], name="Key {label} ({element_en})",
                    name_args={"label": "8×7×40", "element_zh": "弹性联轴器", "element_en": "flexible coupling"})
    assert tex.check_rows([keyed], "zh")[0][:2] == ["平键 8×7×40（弹性联轴器）", "Key 8×7×40 (flexible coupling)"]


def test_formulas_convert_with_pandoc():
    """Every formula parses as TeX math in pandoc (no raw-TeX fallback in the Typst output)."""
    pypandoc = pytest.importorskip("pypandoc")
    try:
        pypandoc.get_pandoc_version()
    except OSError:
        pytest.skip("pandoc not available")
    for c in _all_checks():
        out = pypandoc.convert_text(f"${tex.check_formula(c)}$", "typst", format="markdown")
        assert out.strip().startswith("$") and "\\frac" not in out and "\\sqrt" not in out, out


def test_shaft_bending_formula_writes_a_rounding_residue_of_the_moment_as_zero():
    """An overhung end carries the torque and no bending moment; the statics leave a residue
    (7.1e-12 N·m) that the formula wrote as "(7.105 × 10⁻¹²)²" (slotter, shaper reviews). The
    σ_ca formula writes it 0; a real moment stays."""
    import math

    from mechdesign.core.strength import Check
    from mechdesign.render.strength_tex import check_formula

    def formula(M):
        T, d = 22.966, 0.014
        s = math.sqrt(M ** 2 + (0.6 * T) ** 2) / (0.1 * d ** 3)
        return check_formula(Check(key="shaft_bending", name="shaft", symbol="\\sigma_{ca}", value=s,
                                   allowable=60e6, unit="MPa", sense="le", passed=s <= 60e6,
                                   inputs={"M": M, "T": T, "alpha": 0.6, "d": d}))

    assert "{0^2 +" in formula(7.105e-15) and "10^{-" not in formula(7.105e-15)
    assert "{36.21^2 +" in formula(36.21) or "36210" in formula(36.21)


def test_undercut_result_is_written_without_brackets():
    """A negative x_min follows "=", not an operator: "= -0.537", not "= (-0.537)" (issue 19
    point 1); the closed form x_min = h_a*(z_min − z)/z_min gives the number."""
    from mechdesign.core.strength import Check
    from mechdesign.render.strength_tex import check_formula

    z, z_min = 26.27, 17.1
    x_min = (z_min - z) / z_min
    c = Check(key="undercut", name="undercut", symbol="x", value=z, allowable=x_min, unit="1",
              sense="ge", passed=True, inputs={"x": 0.0, "x_min": x_min, "ha_star": 1.0,
                                              "z_min": z_min})
    out = check_formula(c)
    assert out.rstrip().endswith(f"= {x_min:.3f}"), out
    assert f"({x_min:.3f})" not in out


def test_a_small_power_keeps_four_significant_digits_in_the_formula():
    """Powers are written to 4 significant digits (render/fmt.py), in the shaft table, the
    design step and the check's formula alike: the furnace drive's last shaft carries
    46.30 W, whose d_min formula read "∛(0.0463/20.11)" beside the table's 0.04630 kW."""
    from mechdesign.render.strength_tex import check_formula

    c = s.shaft_diameter_check(16 * mm, 46.30, 20.11, 112, 0.05)
    out = check_formula(c)
    assert r"\frac{0.04630}{20.11}" in out, out
    c = s.shaft_diameter_check(16 * mm, 659.87, 267.6, 112, 0.05)
    assert r"\frac{0.6599}{267.6}" in check_formula(c)


def test_the_motor_rating_margin_writes_the_power_needed_to_four_significant_digits(example_results):
    """The drive's verification row "motor rating margin": the furnace drive's P_d, below
    0.1 kW, to 4 significant digits as in the shaft table (0.06296 kW; it read 0.0630)."""
    from mechdesign.machines.drive.report import verification_context

    r = example_results("furnace_drive")
    rows = verification_context(r["drive"], r["drive_verification"], "en")["verify_rows"]
    row = next(row for row in rows if row[0].startswith("motor rating margin"))
    need = r["drive"].power_required / 1e3
    assert need < 0.1 and f"({need:.4g} / " in row[1], row       # 4 digits, the last one too
    assert len(f"{need:.4g}".split(".")[1].lstrip("0")) == 4
