"""Issue 20: V-belts by 濮良贵《机械设计》ch.8, the geometric checks of every drive gear stage
and the worm shaft's deflection (core/belts.py, stages/drive_elements.py).

Worked examples (printed numbers, stored pages found with the search tool):
- [V1] a course design's V-belt by 濮良贵 ch.8 (https://m.qiqiwenku.com/zip/721484.html):
  P_ca = 3.35 kW, n_m = 1430 r/min, A section, d_d1 = 75 mm, d_d2 = 180 mm, a0 = 500 mm →
  L_d0 ≈ 1406 mm, L_d = 1430 mm (its table 8-2 is the GB/T 11544-1997 series), a ≈ 512 mm,
  α1 ≈ 168.2°, P0 = 0.67 kW, ΔP0 = 0.17 kW, Kα = 0.97, K_L = 0.96, z = 4.29 → 5,
  q = 0.105 kg/m, F0 = 97.49 N, F_p = 969.66 N, v = 5.61 m/s.
- [V2] a course design (https://m.qiqiwenku.com/doc/173029.html): P_ca = 6.6 kW at
  1440 r/min → A section; d_d1 = 112 mm → v = 8.445 m/s.
"""
from __future__ import annotations

import copy
import math
from types import SimpleNamespace

import pytest

from mechdesign.core import belts, gears
from mechdesign.stages import drive_elements as de

MM = 1e-3


def _tables_of_v1():
    """The shipped tables with the A lengths of the example's edition (GB/T 11544-1997:
    …, 1250 → 0.93, 1430 → 0.96, 1550 → 0.98, …)."""
    t = copy.deepcopy(de.belt_tables())
    t["datum_lengths"]["A"] = {"L_d_mm": [1100, 1250, 1430, 1550, 1640], "K_L": [0.91, 0.93, 0.96, 0.98, 0.99]}
    return t


def test_v1_closed_forms_with_the_printed_inputs():
    v = belts.belt_speed(75 * MM, 1430)
    assert v == pytest.approx(5.61, abs=0.006)
    L_d0 = belts.datum_length(500, 75, 180)
    assert L_d0 == pytest.approx(1406, abs=0.5)
    a = belts.center_distance(500, 1430, L_d0)
    assert a == pytest.approx(512, abs=0.5)
    # the printed α1 uses a = 512 mm: 180° − 105 × 57.3°/512
    assert math.degrees(belts.wrap_angle(75, 180, 512)) == pytest.approx(168.2, abs=0.05)
    # F0 with the printed (rounded) Kα = 0.97, z = 5, v = 5.61 m/s: 97.49 N
    assert belts.initial_tension(3.35e3, 0.97, 5, 5.61, 0.105) == pytest.approx(97.49, abs=0.01)
    # F_p = 2 z F0 sin(α1/2): 969.74 N with the printed F0 and α1; the page prints 969.66 N
    # (its unrounded intermediate values): agreement to 1e-4
    assert belts.shaft_load(5, 97.49, math.radians(168.2)) == pytest.approx(969.66, rel=1e-4)
    # z = P_ca / ((P0 + ΔP0) Kα K_L) = 3.35 / 0.78 = 4.29
    assert 3.35 / ((0.67 + 0.17) * 0.97 * 0.96) == pytest.approx(4.29, abs=0.01)


def test_v1_table_lookups():
    t = de.belt_tables()
    assert belts.choose_section(t, 3.35e3, 1430) == "A"
    assert belts.rated_power(t, "A", 75 * MM, 1430) / 1e3 == pytest.approx(0.67, abs=0.005)
    assert belts.power_increment(t, "A", 2.5, 1430) / 1e3 == pytest.approx(0.17, abs=0.005)
    assert belts.wrap_factor(t, math.radians(168.2)) == pytest.approx(0.97, abs=0.005)
    assert t["sections"]["A"]["q_kg_per_m"] == 0.105


def test_v1_whole_procedure():
    b = belts.design_vbelt(_tables_of_v1(), 3.35e3, 1430, 1.0, 75 * MM, 180 * MM, 0.0, None, 500 * MM)
    assert b.section == "A"
    assert b.L_d == pytest.approx(1.430)
    assert b.K_L == 0.96
    assert b.a * 1e3 == pytest.approx(512, abs=0.5)
    assert math.degrees(b.alpha1) == pytest.approx(168.2, abs=0.1)
    # 4.26: P0 = 0.674 kW interpolated between the 9th-ed. columns 1200 and 1450 r/min, Kα = 0.973
    # interpolated; the print's 4.29 is 3.35/0.78 with P_r rounded (3.35/0.7822 = 4.28 unrounded)
    assert b.z_exact == pytest.approx(4.29, abs=0.035)
    assert b.z == 5
    # Kα interpolated (0.9727) instead of the printed 0.97: F0 and F_p within 0.6 %
    assert b.F0 == pytest.approx(97.49, rel=6e-3)
    assert b.Fp == pytest.approx(969.66, rel=6e-3)
    assert all(c.passed for c in b.checks)


def test_v2_section_and_speed():
    t = de.belt_tables()
    assert belts.choose_section(t, 6.6e3, 1440) == "A"
    assert belts.belt_speed(112 * MM, 1440) == pytest.approx(8.445, abs=0.001)


def test_bilinear_p0_between_the_rows():
    t = de.belt_tables()
    # halfway between d = 90 and 100 mm and between 1200 and 1450 rpm (the 9th-ed. columns; the
    # table had 1460 before): the mean of four entries
    p = belts.rated_power(t, "A", 95 * MM, 1325) / 1e3
    assert p == pytest.approx((0.93 + 1.07 + 1.14 + 1.32) / 4, abs=1e-12)


def test_small_diameter_default_and_speed_rule():
    s = SimpleNamespace(section=None)
    # 0.825 kW at 910 rpm: section Z; 100 mm gives v = 4.76 m/s < 5 → the next datum diameter 106 mm
    assert de.belt_small_diameter(s, 0.6875e3, 910, 1.2) == pytest.approx(0.106)
    assert belts.belt_speed(0.106, 910) >= 5
    # 1440 rpm: 100 mm suffices (v = 7.5 m/s)
    assert de.belt_small_diameter(s, 3e3, 1440, 1.2) == pytest.approx(0.100)
    # section B (d_dmin = 125 mm) forced: 125 mm
    assert de.belt_small_diameter(SimpleNamespace(section="B"), 3e3, 1440, 1.2) == pytest.approx(0.125)


def test_belt_application_factor_table_8_8():
    assert de.belt_application_factor(1.25, 16)[0] == 1.2      # load varies little, two shifts
    assert de.belt_application_factor(1.0, 8)[0] == 1.0
    assert de.belt_application_factor(1.5, 24)[0] == 1.4


def test_too_much_power_for_the_shipped_sections():
    with pytest.raises(belts.BeltDesignError, match="larger than B"):
        belts.design_vbelt(de.belt_tables(), 60e3, 1440, 1.2, 0.2, 0.4)


# ------------------------------------------------------------------ gear-stage geometry


def _design(pair, eps, materials=("45_QT", "45_QT")):
    return SimpleNamespace(kind="gear", geometry=pair, materials=materials, extra={"eps_alpha": eps})


def test_tip_undercut_contact_ratio_closed_forms():
    pair = gears.spur_pair(2 * MM, 20, 60)
    # standard pair: s_a = d_a (π/(2z) + inv α − inv α_a), d_a = m(z + 2)
    inv = lambda a: math.tan(a) - a
    al = math.radians(20)
    da = 2 * MM * 22
    aa = math.acos(2 * MM * 20 * math.cos(al) / da)
    assert pair.g1.sa == pytest.approx(da * (math.pi / 40 + inv(al) - inv(aa)), rel=1e-9)
    # contact ratio ε = [z1(tan α_a1 − tan α) + z2(tan α_a2 − tan α)]/(2π)
    aa2 = math.acos(60 * math.cos(al) / 62)
    eps = (20 * (math.tan(aa) - math.tan(al)) + 60 * (math.tan(aa2) - math.tan(al))) / (2 * math.pi)
    assert pair.contact_ratio == pytest.approx(eps, rel=1e-9)
    checks = {c.name: c for c in de.gear_geometry_checks(_design(pair, pair.contact_ratio), None)}
    assert all(c.passed for c in checks.values())
    assert checks["Pinion tip thickness"].allowable == pytest.approx(0.5 * MM)


def test_undercut_x_min():
    """x_min = h_a*(z_min − z)/z_min with the textbook's z_min = 17 (孙桓: α = 20°, h_a* = 1),
    the number the undercut warning uses too (tests/test_diagnostics.py::
    test_undercut_gear_in_a_drive), so check and warning agree."""
    z_min = 17
    pair = gears.spur_pair(2 * MM, 14, 40)            # z = 14 < 17, no shift: undercut
    c = [c for c in de.gear_geometry_checks(_design(pair, pair.contact_ratio), None) if c.key == "undercut"]
    assert not c[0].passed and c[1].passed
    assert c[0].inputs["x_min"] == pytest.approx((z_min - 14) / z_min, rel=1e-9)   # 3/17 = 0.1765
    assert c[0].inputs["x_min"] == pytest.approx(pair.x_min1, rel=1e-12)            # = the warning's
    shifted = gears.spur_pair(2 * MM, 14, 40, x1=0.19, x2=-0.19)
    c = [c for c in de.gear_geometry_checks(_design(shifted, shifted.contact_ratio), None) if c.key == "undercut"]
    assert c[0].passed
    # just below x_min = 3/17: undercut
    short = gears.spur_pair(2 * MM, 14, 40, x1=0.17, x2=-0.17)
    c = [c for c in de.gear_geometry_checks(_design(short, short.contact_ratio), None) if c.key == "undercut"]
    assert not c[0].passed
    # a standard 17-tooth pinion: z = z_min, free of undercut (the textbook's limit)
    c = [c for c in de.gear_geometry_checks(_design(gears.spur_pair(2 * MM, 17, 40), 1.6), None)
         if c.key == "undercut"]
    assert c[0].passed and c[0].allowable == pytest.approx(z_min)


def test_x1_1_5_on_z1_20_fails_by_name():
    """Issue 20: x1 = 1.5 on z1 = 20 gets a pointed tooth: a named failure (tip thickness
    and contact ratio), not a silent pass."""
    pair = gears.spur_pair(2 * MM, 20, 60, x1=1.5)
    failed = {c.key for c in de.gear_geometry_checks(_design(pair, pair.contact_ratio), None) if not c.passed}
    assert {"tooth_tip", "contact_ratio"} <= failed


def test_hardened_tips_need_0_4_m():
    pair = gears.spur_pair(2 * MM, 20, 60)
    c = de.gear_geometry_checks(_design(pair, 1.6, ("40Cr_surface_hardened", "45_QT")), None)
    assert c[0].allowable == pytest.approx(0.4 * 2 * MM)
    assert c[2].allowable == pytest.approx(0.25 * 2 * MM)


def test_helical_stage_uses_the_equivalent_teeth():
    beta = math.radians(14)
    pair = gears.helical_pair(2 * MM, 15, 60, beta)
    c = [c for c in de.gear_geometry_checks(_design(pair, 1.6), SimpleNamespace(z1=15, z2=60))
         if c.key == "undercut"]
    zv = 15 / math.cos(beta) ** 3                       # 16.4 < 17: undercut
    assert c[0].value == pytest.approx(zv)
    assert not c[0].passed


# ------------------------------------------------------------------ worm shaft deflection


def test_worm_deflection_by_hand():
    """y = √(Ft1² + Fr1²) L³ / (48 E I), I = π d_f1⁴/64, [y] = d1/1000 (濮良贵 ch.11).
    m = 5 mm, q = 10 (d1 = 50 mm, d_f1 = 50 − 2.4·5 = 38 mm), z2 = 40 (d2 = 200 mm),
    Ft1 = 1000 N, Fr1 = 2000 N, L = 0.9 d2 = 180 mm:
    I = π·38⁴/64 = 102 353.9 mm⁴; y = 2236.07 × 180³ / (48 × 206 000 × 102 353.9)
    = 0.012 885 mm ≤ 0.05 mm."""
    g = gears.worm_pair(5 * MM, 10, 2, 40)
    d = SimpleNamespace(geometry=g, forces={"Ft": 1000.0, "Fr": 2000.0})
    c = de.worm_deflection_check(d, None)
    I_mm4 = math.pi * 38 ** 4 / 64
    assert I_mm4 == pytest.approx(102353.9, abs=0.1)
    y_mm = math.hypot(1000, 2000) * 180 ** 3 / (48 * 206000 * I_mm4)
    assert y_mm == pytest.approx(0.012885, abs=1e-6)
    assert c.value * 1e3 == pytest.approx(y_mm, rel=1e-9)
    assert c.allowable == pytest.approx(0.050 * MM)
    assert c.passed
    # a span given in the brief replaces 0.9 d2
    assert de.worm_deflection_check(d, 0.360).value == pytest.approx(8 * c.value, rel=1e-12)


# ------------------------------------------------------------------ roller chains (濮良贵 ch.9)


def test_chain_by_hand():
    """No printed chain example with all its numbers was found by the search tool; this is a
    hand calculation of the ch.9 procedure (P = 5 kW, n1 = 720 rpm, i = 3, K_A = 1):
    z1 = 29 − 2i = 23, z2 = 69; K_z = (19/23)^1.08 = 0.8135, P_ca = 4.067 kW.
    Ratings at z1 = 19 (ANSI, hp, p in inches): 08A (p = 0.5): 0.004·19^1.08·720^0.9·0.5^2.965
    = 4.59 hp = 3.42 kW < P_ca; 10A (p = 0.625): 0.004·24.03·372.9·0.625^2.956 = 8.93 hp
    = 6.66 kW (roller-bushing limit 1000·17·19^1.5·0.625^0.8/720^1.5 = 50.0 hp) → 10A.
    a0 = 40p: L_p0 = 80 + 46 + (1/40)(46/2π)² = 127.34 → 128 links;
    a = (15.875/4)[82 + √(82² − 8·(46/2π)²)] = 640.33 mm; v = 23·720·15.875/60000 = 4.3815 m/s;
    F_Q = 1.2 · 5000/4.3815 = 1369.4 N."""
    from mechdesign.core import chains

    t = de.chain_tables()
    c = chains.design_chain(t, 5e3, 720, 1.0, 23, 69)
    assert c.Kz == pytest.approx(0.8135, abs=1e-4)
    assert c.power_design == pytest.approx(4067, abs=1)
    assert chains.rated_power_one_strand(0.0127, 720) == pytest.approx(3424, rel=2e-3)
    assert c.chain == "10A" and c.rated_power == pytest.approx(6660, rel=2e-3)
    assert c.L_p0 == pytest.approx(127.34, abs=0.01) and c.L_p == 128
    assert c.a * 1e3 == pytest.approx(640.33, abs=0.01)
    # the centre distance is the exact inverse of the link count
    assert chains.links(c.a, c.pitch, 23, 69) == pytest.approx(128, rel=1e-12)
    assert c.v == pytest.approx(4.381, abs=1e-3)
    assert c.FQ == pytest.approx(1369.4, abs=0.1)
    assert c.S is None and all(ch.passed for ch in c.checks)


def test_chain_refusals_and_static_safety():
    from mechdesign.core import chains

    t = de.chain_tables()
    with pytest.raises(chains.ChainDesignError, match="no shipped roller chain"):
        chains.design_chain(t, 500e3, 1500, 1.0, 19, 57)
    slow = chains.design_chain(t, 2e3, 50, 1.4, 17, 51)      # v < 0.6 m/s: static safety checked
    assert slow.v < 0.6 and slow.S is not None
    F1 = slow.Fe + t["chains"][slow.chain]["q_kg_per_m"] * slow.v ** 2
    assert slow.S == pytest.approx(t["chains"][slow.chain]["Q_kN"] * 1e3 / (1.4 * F1))


# ------------------------------------------------------------------ through the drive


def _run_furnace_drive(tmp_path, **stage):
    import yaml
    from mechdesign.brief.loader import load_variant
    from mechdesign.machines import get_machine, stages_for
    from mechdesign.pipeline import run_stages

    d = yaml.safe_load(open("designs/furnace_drive.yaml", encoding="utf-8"))
    k = next(i for i, s in enumerate(d["drive"]["stages"]) if s["type"] == "spur")
    d["drive"]["stages"][k] = stage
    path = tmp_path / "brief.yaml"
    path.write_text(yaml.safe_dump(d, allow_unicode=True), encoding="utf-8")
    v = load_variant(path, None)
    m = get_machine(v.brief.machine)
    p = m.to_params(v.brief)
    res, _ = run_stages(stages_for(m, p), {"params": p, "brief": v.brief})
    doc = m.document(res)
    return doc.drive, k


def test_drive_spur_stage_x1_1_5_on_z1_20_is_a_named_failure(tmp_path):
    doc, k = _run_furnace_drive(tmp_path, type="spur", open=True, z1=20, x1=1.5)
    checks = {c.key: c for c in doc.stages[k].design.checks if not c.passed}
    assert {"tooth_tip", "contact_ratio"} <= set(checks)
    text = " ".join(w.text("en") for w in doc.warnings)   # findings: their English text
    # the fix in words; the brief field is the finding's (the terminal prints it after the text)
    assert "Pinion tip thickness" in text and "reduce the shifts x1, x2" in text
    assert f"drive.stages[{k}]" not in text
    assert any(w.field == f"drive.stages[{k}].x1" for w in doc.warnings)


def test_drive_chain_stage_is_designed_and_loads_its_shafts(tmp_path):
    doc, k = _run_furnace_drive(tmp_path, type="chain", ratio=5)
    c = doc.stages[k].design
    assert c.kind == "chain" and c.forces["Q"] == pytest.approx(c.geometry.FQ)
    assert c.geometry.z1 == 19                            # z1 = 29 − 2i, odd, ≥ 17
    # F_Q acts on both of the chain's shafts (k and k + 1)
    loads = [[ld.Fh for ld in sh.loads] for sh in doc.shaft_designs]
    assert any(f == pytest.approx(c.geometry.FQ) for f in loads[k - 1])
    assert any(f == pytest.approx(c.geometry.FQ) for f in loads[k])


def test_belt_fields_validated():
    from pydantic import ValidationError

    from mechdesign.brief.drive import DriveStage

    s = DriveStage(type="belt", d1_mm=125, d2_mm=250, section="B", center_distance_mm=400)
    assert s.section == "B"
    with pytest.raises(ValidationError, match="0.7"):
        DriveStage(type="belt", d1_mm=125, d2_mm=250, center_distance_mm=100)
    with pytest.raises(ValidationError, match="has no section"):
        DriveStage(type="spur", section="A")
    with pytest.raises(ValidationError):
        DriveStage(type="belt", section="C")                 # C and larger: not in the tables


def test_chart_section_that_cannot_wrap_gives_way_to_the_next():
    """d1 = 100, d2 = 560 mm: α1 ≥ 120° needs a ≥ 460/(π/3) = 439 mm, i.e. L_d ≈ 2·439 +
    (π/2)·660 + 460²/(4·439) = 2035 mm, beyond Z's longest belt (1800 mm): A is used."""
    t = de.belt_tables()
    b = belts.design_vbelt(t, 0.5e3, 1440, 1.2, 0.100, 0.560)
    assert b.section_chart == "Z" and b.section == "A"
    assert math.degrees(b.alpha1) >= 120 and all(c.passed for c in b.checks)
    # given, the section is kept (and its failure reported)
    z = belts.design_vbelt(t, 0.5e3, 1440, 1.2, 0.100, 0.560, section="Z")
    assert z.section == "Z" and not all(c.passed for c in z.checks)
