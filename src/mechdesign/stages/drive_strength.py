"""Geometry and strength of the drive's stages, shafts, bearings and keys, by the method
of 《机械设计》 (濮良贵) and 《机械设计课程设计》. Called by :mod:`.drive` once the motor,
the ratios and the shaft table are known.

Assumptions stated in the report (the brief may override the materials, modules, face
width factors and spans):
- load factor K = K_A K_V K_α K_β with K_V = 1.1, K_α = 1.0 (spur) / 1.2 (helical),
  K_β = 1.1 (8-grade gears, moderate speed); worm K = K_A · 1.1;
- S_H = 1.0, S_F = 1.4; open gears: module by bending × 1.15 for wear, no contact check;
  a designed module is at least 2 mm (gears that transmit power);
- shafts of 45 steel (调质), A0 = 112, +5 % for a keyway; journal = d rounded up to 5 mm
  (bearing bore), gear seat = journal + 5 mm; reducer gears between the bearings,
  belt pulleys, couplings and open gears overhung by 80 mm;
- bearings: tapered roller 302xx on worm-reducer shafts, deep-groove 62xx (63xx if
  62xx is too short-lived) elsewhere, f_p = 1.2; flat keys form A, steel hubs
  (cast-iron for pulleys), [σp] of light shocks.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace


from ..core import belts, chains, gears, strength as st
from ..core.fields import q
from ..data import catalogues as cat
from . import drive_elements as de

K_V, K_BETA, S_H, S_F = 1.1, 1.1, 1.0, 1.4
A0, KEYWAY = 112.0, 0.05
OVERHANG, CLEARANCE = 0.080, 0.060       # [m]
KD_WORM = 15.0                             # W/(m²·°C), natural ventilation (8.15–17.45)
FP = 1.2
M_MIN_POWER = 0.002                        # gears transmitting power: m ≥ 1.5–2 mm (textbook)


@dataclass(frozen=True)
class StageDesign:
    """Strength design of one stage (gear pair, worm pair; belts, chains and couplings
    carry only their torques and, for a belt, the pressure on the shafts)."""

    kind: str = q("", "'gear' | 'worm' | 'belt' | 'chain' | 'coupling'")
    geometry: (gears.SpurPair | gears.HelicalPair | gears.WormPair | belts.VBeltDesign
               | chains.ChainDesign | None) = q(
        "", "the pair's geometry (as the gear section's pair); a belt's or chain's design "
        "(濮良贵 ch.8, ch.9); null for couplings")
    materials: tuple[str, ...] = q("", "material keys (pinion, gear) or (worm, wheel)")
    module: float | None = q("m", "module used (normal module of a helical pair)")
    module_min: float | None = q("m", "module from the design formula (null when the brief gives it)")
    module_given: bool = q("", "the brief gives the module")
    face_width: float | None = q("m", "face width b = φ_d·d1 rounded up to 1 mm")
    K: float = q("1", "load factor K = K_A·K_V·K_α·K_β (worm: K_A·1.1)")
    T1: float = q("N·m", "design torque on the driving member")
    T2: float = q("N·m", "design torque on the driven member")
    forces: dict[str, float] = q("N (d1, d2: m)", "F_t, F_r, F_a on the driving member (worm: "
                                 "F_t1, F_a1 = F_t2, F_r; belt: Q on the shafts); d1, d2 the "
                                 "diameters they act at")
    allowables: dict[str, float] = q("Pa (K_HN, K_FN, N: 1)", "[σ_H], [σ_F1], [σ_F2], the limits "
                                     "σ_Hlim, σ_FE, and the life factors and stress cycles that gave them")
    checks: tuple[st.Check, ...] = q("", "contact, bending (and the worm's thermal balance)")
    extra: dict = q("SI", "v [m/s], φ_d, Z_E [√Pa], Z_H, Z_ε, Y_ε, ε_α, ε_β, Y_Fa, Y_Sa, β [rad]; "
                    "worm: a [m], γ, φ_v [rad], v_s [m/s], η, area [m²], k_d [W/(m²·°C)]")


@dataclass(frozen=True)
class ShaftDesign:
    """One shaft after the motor: diameters, loads and statics, bearings, keys and checks."""

    index: int = q("1", "shaft number (1 = first after the motor)")
    speed_rpm: float = q("rpm", "n")
    power: float = q("W", "P")
    torque: float = q("N·m", "design torque (× the peak factor where it applies)")
    d_min: float = q("m", "A_0·∛(P/n) with the keyway allowance")
    d_journal: float = q("m", "bearing journal (d rounded up to 5 mm)")
    d_seat: float = q("m", "hub seat = journal + 5 mm")
    span: float = q("m", "bearing span")
    loads: tuple[st.PointLoad, ...] = q("", "the loads of the elements it carries")
    names: tuple[tuple[str, str], ...] = q("", "what sits at each load, (zh, en)")
    result: st.ShaftResult = q("", "reactions and moments (bending–torsion check)")
    bearing: cat.Bearing | None = q("", "the bearing chosen (null: none in the catalogue)")
    bearing_loads: tuple[float, float] = q("N", "equivalent dynamic loads (P_A, P_B)")
    checks: tuple[st.Check, ...] = q("", "diameter, bending–torsion, bearing life, keys")


def _phi_d(s, is_open: bool) -> float:
    return s.face_width_factor if s.face_width_factor else (0.5 if is_open else 1.0)


def _gear_stage(s, n1: float, T1: float, T2: float, hours: float, KA: float) -> StageDesign:
    helical = s.type == "helical"
    is_open = s.type == "spur" and s.open
    z1, z2 = s.z1, s.z2
    u = z2 / z1
    beta = s.helix_angle if helical else 0.0
    mat1 = cat.gear_material(s.pinion_material or "40Cr_QT")
    mat2 = cat.gear_material(s.gear_material or "45_QT")
    K = KA * K_V * (1.2 if helical else 1.0) * K_BETA
    N1 = st.stress_cycles(n1, hours)
    N2 = N1 / u
    khn = [st.life_factor_contact(N, m.life_curve_contact) for N, m in ((N1, mat1), (N2, mat2))]
    kfn = [st.life_factor_bending(N, m.life_curve_bending) for N, m in ((N1, mat1), (N2, mat2))]
    sH = min(st.allowable_stress(m.sigma_Hlim, k, S_H) for m, k in ((mat1, khn[0]), (mat2, khn[1])))
    sF = [st.allowable_stress(m.sigma_FE, k, S_F) for m, k in ((mat1, kfn[0]), (mat2, kfn[1]))]
    phi_d = _phi_d(s, is_open)
    # Transverse geometry for the contact ratio (independent of the module).
    alpha_t = math.atan(math.tan(math.radians(20)) / math.cos(beta))
    zv = [z / math.cos(beta) ** 3 for z in (z1, z2)]
    yf = [cat.tooth_factors(max(z, 17.0)) for z in zv]
    # ε_α does not depend on the module: the pair itself for spur gears (with its shift),
    # the textbook's estimate for helical ones.
    eps_a = ((1.88 - 3.2 * (1 / z1 + 1 / z2)) * math.cos(beta) if helical
             else gears.spur_pair(1.0, z1, z2, x1=s.x1, x2=s.x2).contact_ratio)
    eps_b = phi_d * z1 * math.tan(beta) / math.pi
    beta_b = math.atan(math.tan(beta) * math.cos(alpha_t))
    ZE = st.elastic_coefficient(mat1.E, mat1.nu, mat2.E, mat2.nu)
    ZH = st.zone_factor(alpha_t, alpha_t, beta_b)
    Ze = st.contact_ratio_factor(eps_a, eps_b)
    Ye = st.bending_ratio_factor(eps_a, beta_b)
    Zb, Yb = st.helix_factors(beta, eps_b) if helical else (1.0, 1.0)
    # The gear with the larger Y_Fa Y_Sa / [σF] governs bending.
    worst = max(range(2), key=lambda i: yf[i][0] * yf[i][1] / sF[i])
    module_min = None
    if s.module is None:
        if is_open:
            module_min = st.design_module_bending(T1, K, phi_d, z1, *yf[worst], Ye, sF[worst], Yb, beta) * 1.15
        else:
            d1 = st.design_d1_contact(T1, K, phi_d, u, ZH, ZE, Ze, sH, Zb)
            module_min = max(d1 * math.cos(beta) / z1,
                             st.design_module_bending(T1, K, phi_d, z1, *yf[worst], Ye, sF[worst], Yb, beta))
        m = max(st.standard_module(module_min), M_MIN_POWER)
    else:
        m = s.module
    if helical:
        geo = gears.helical_pair(m, z1, z2, beta)
        d1 = geo.d1
    else:
        geo = gears.spur_pair(m, z1, z2, x1=s.x1, x2=s.x2)
        d1 = geo.g1.d
    b = math.ceil(phi_d * d1 * 1e3) * 1e-3
    checks = []
    if not is_open:
        c = st.gear_contact_check(T1, K, b, d1, u, ZE, ZH, Ze, Zb, sH)
        checks.append(replace(c, name_zh="齿面接触疲劳强度", name_en="Contact fatigue (flanks)"))
    for i, who in enumerate(("小齿轮", "大齿轮")):
        c = st.gear_bending_check(T1, K, b, d1, m, yf[i][0], yf[i][1], Ye, Yb, sF[i])
        checks.append(replace(c, name_zh=f"{who}齿根弯曲疲劳强度",
                              name_en=f"{'Pinion' if i == 0 else 'Gear'} root bending fatigue"))
    Ft = 2 * T1 / d1
    forces = {"Ft": Ft, "Fr": Ft * math.tan(math.radians(20)) / math.cos(beta), "Fa": Ft * math.tan(beta),
              "d1": d1, "d2": d1 * u}
    v = math.pi * d1 * n1 / 60
    return StageDesign(
        "gear", geo, (mat1.key, mat2.key), m, module_min, s.module is not None, b, K, T1, T2, forces,
        {"sigma_H": sH, "sigma_F1": sF[0], "sigma_F2": sF[1], "KHN1": khn[0], "KHN2": khn[1],
         "KFN1": kfn[0], "KFN2": kfn[1], "N1": N1, "N2": N2, "sigma_Hlim1": mat1.sigma_Hlim,
         "sigma_Hlim2": mat2.sigma_Hlim, "sigma_FE1": mat1.sigma_FE, "sigma_FE2": mat2.sigma_FE},
        tuple(checks),
        {"v": v, "phi_d": phi_d, "ZE": ZE, "ZH": ZH, "Zeps": Ze, "Yeps": Ye, "eps_alpha": eps_a,
         "eps_beta": eps_b, "YFa1": yf[0][0], "YSa1": yf[0][1], "YFa2": yf[1][0], "YSa2": yf[1][1],
         "open": is_open, "beta": beta})


def _worm_stage(s, n1: float, P1: float, T1: float, T2: float, hours: float, KA: float) -> StageDesign:
    z1, z2, q = s.z1, s.z2, s.q
    wheel = cat.worm_wheel_material(s.wheel_material or "ZCuSn10P1_sand")
    K = KA * 1.1
    n2 = n1 * z1 / z2
    N = st.stress_cycles(n2, hours)
    sH = wheel.contact_base(None) * st.worm_life_factor_contact(N) if wheel.life_dependent else None
    sF = wheel.sigma_F_base_one_way * st.worm_life_factor_bending(N)
    module_min = None
    if s.module is None:
        zr = st.worm_contact_coefficient(q / (q + z2))          # d1/a of the standard pair
        a_min = st.design_worm_center_distance(T2, K, wheel.ZE, zr, sH if sH else wheel.contact_base(1.0))
        module_min = 2 * a_min / (q + z2 + 2 * s.x2)
        m = st.standard_module(module_min)
    else:
        m = s.module
    geo = gears.worm_pair(m, q, z1, z2)
    a = m * (q + z2 + 2 * s.x2) / 2
    gamma = geo.lead_angle
    vs = st.sliding_speed(geo.d1, n1, gamma)
    phi_v = st.equivalent_friction_angle(vs, wheel.friction_pair)
    eta = st.worm_drive_efficiency(gamma, phi_v)
    if sH is None:
        sH = wheel.contact_base(vs)
    zr = st.worm_contact_coefficient(geo.d1 / a)
    zv2 = z2 / math.cos(gamma) ** 3
    YFa2 = cat.tooth_factors(max(zv2, 17.0))[0]
    area = st.worm_housing_area(a)
    checks = (
        replace(st.worm_contact_check(T2, K, a, wheel.ZE, zr, sH), name_zh="蜗轮齿面接触疲劳强度",
                name_en="Worm-wheel contact fatigue"),
        replace(st.worm_bending_check(T2, K, geo.d1, geo.d2, m, YFa2, gamma, sF), name_zh="蜗轮齿根弯曲疲劳强度",
                name_en="Worm-wheel root bending fatigue"),
        st.worm_thermal(P1, eta, KD_WORM, area),
    )
    Ft1 = 2 * T1 / geo.d1
    Ft2 = 2 * T2 / geo.d2
    forces = {"Ft": Ft1, "Fa": Ft2, "Fr": Ft2 * math.tan(math.radians(20)), "d1": geo.d1, "d2": geo.d2,
              "Ft2": Ft2}
    return StageDesign(
        "worm", geo, ("45_surface_hardened", wheel.key), m, module_min, s.module is not None, None, K, T1, T2,
        forces, {"sigma_H": sH, "sigma_F": sF, "N": N},
        checks, {"a": a, "gamma": gamma, "vs": vs, "phi_v": phi_v, "eta": eta, "Zrho": zr, "YFa2": YFa2,
                 "zv2": zv2, "area": area, "kd": KD_WORM, "sliding_max": wheel.sliding_speed_max})


def stage_designs(dp, results, shafts, peak_factor, peak_from_shaft) -> tuple[list, dict[int, float]]:
    """Designs for every stage; returns (designs by position, new worm efficiencies)."""
    out, worm_eff = [], {}
    for k, (s, r) in enumerate(zip(dp.stages, results)):
        boost = peak_factor if peak_from_shaft is not None and k >= peak_from_shaft else 1.0
        T1, T2 = shafts[k].torque * boost, shafts[k + 1].torque * boost
        s = replace(s, z1=r.z1, z2=r.z2)
        if s.type in ("spur", "helical"):
            d = _gear_stage(s, shafts[k].speed_rpm, T1, T2, dp.service_hours, dp.KA)
            out.append(replace(d, checks=d.checks + de.gear_geometry_checks(d, s)))
        elif s.type == "worm":
            d = _worm_stage(s, shafts[k].speed_rpm, shafts[k].power, T1, T2, dp.service_hours, dp.KA)
            d = replace(d, checks=d.checks + (de.worm_deflection_check(d, dp.stages[k - 1].span if k else None),))
            if s.efficiency is None:
                worm_eff[s.index] = d.extra["eta"]
            out.append(d)
        elif s.type == "belt":    # 濮良贵 ch.8: the load on the shafts is F_p = 2 z F0 sin(α1/2)
            try:
                b = de.belt_design(s, r, shafts[k], dp)
            except belts.BeltDesignError as e:
                from ..core.drive import DriveDesignError
                raise DriveDesignError(f"drive.stages[{s.index}]: {e.en}", f"drive.stages[{s.index}]：{e.zh}") from None
            out.append(StageDesign("belt", b, (), None, None, False, None, b.KA, T1, T2, {"Q": b.Fp}, {},
                                   b.checks, {"v": b.v}))
        elif s.type == "chain":   # 濮良贵 ch.9: F_Q ≈ (1.2…1.3) F_e on the shafts
            try:
                c = de.chain_design(s, r, shafts[k], dp)
            except chains.ChainDesignError as e:
                from ..core.drive import DriveDesignError
                raise DriveDesignError(f"drive.stages[{s.index}]: {e.en}", f"drive.stages[{s.index}]：{e.zh}") from None
            out.append(StageDesign("chain", c, (), None, None, False, None, c.KA, T1, T2, {"Q": c.FQ}, {},
                                   c.checks, {"v": c.v}))
        else:
            out.append(StageDesign(s.type, None, (), None, None, False, None, 1.0, T1, T2, {}, {}, (), {}))
    return out, worm_eff


def _round_up(x: float, step: float) -> float:
    return math.ceil(x / step - 1e-9) * step


def _element_loads(design: StageDesign, driving: bool):
    """(inside the housing?, PointLoad fields without x, hub length, hub material, name)."""
    f = design.forces
    if design.kind == "gear":
        r = (f["d1"] if driving else f["d2"]) / 2
        inside = not design.extra.get("open", False)
        return inside, dict(Fh=f["Ft"], Fv=f["Fr"], Fa=f["Fa"], r=r), design.face_width, "steel"
    if design.kind == "worm":
        if driving:   # the worm: its tangential force Ft1, axial force Fa1 = Ft2
            return True, dict(Fh=f["Ft"], Fv=f["Fr"], Fa=f["Fa"], r=f["d1"] / 2), None, "steel"
        return True, dict(Fh=f["Ft2"], Fv=f["Fr"], Fa=f["Ft"], r=f["d2"] / 2), None, "steel"
    if design.kind in ("belt", "chain"):     # F_p of the belt, F_Q of the chain (issue 20)
        return False, dict(Fh=f["Q"]), None, "cast_iron" if design.kind == "belt" else "steel"
    return False, {}, None, "steel"


def shaft_designs(dp, designs, shafts, peak_factor, peak_from_shaft, names) -> tuple[ShaftDesign, ...]:
    mat = cat.shaft_material("45_QT")
    worm_shafts = {k for k, d in enumerate(designs) if d.kind == "worm"} | \
                  {k + 1 for k, d in enumerate(designs) if d.kind == "worm"}
    sp_lo, _ = cat.key_allowable_stress("steel", "light_shock")
    ci_lo, _ = cat.key_allowable_stress("cast_iron", "light_shock")
    out = []
    for j in range(1, len(shafts)):
        sh = shafts[j]
        boost = peak_factor if peak_from_shaft is not None and j >= peak_from_shaft else 1.0
        T = sh.torque * boost
        d_min = st.shaft_min_diameter(sh.power, sh.speed_rpm, A0, KEYWAY)
        d_j = max(_round_up(d_min + 0.003, 0.005), 0.020)
        d_seat = d_j + 0.005
        elems = [(designs[j - 1], False, names[j - 1])]
        if j < len(designs):
            elems.append((designs[j], True, names[j]))
        info = [(_element_loads(d, drv), nm, d) for d, drv, nm in elems]
        widths = [i[0][2] or (0.06 if i[2].kind == "worm" else 0.0) for i in info]
        inside = [i for i in info if i[0][0]]
        inside_width = sum(w for i, w in zip(info, widths) if i[0][0]) or 0.05
        span = dp.stages[j - 1].span or inside_width + 2 * CLEARANCE
        loads, where = [], []
        for n, i in enumerate(inside):
            x = span * (n + 1) / (len(inside) + 1)
            loads.append(st.PointLoad(x, **i[0][1]))
            where.append(i[1])
        side = [-OVERHANG, span + OVERHANG]
        for i in info:
            if not i[0][0]:
                x = side.pop(0) if side else span + OVERHANG
                loads.append(st.PointLoad(x, **i[0][1]))
                where.append(i[1])
        xs = [p.x for p in loads] or [0.0, span]
        res = st.shaft_check(span, loads, T, d_seat, mat.sigma_minus1b_allow, 0.6,
                             (min(xs), max(xs)) if len(xs) > 1 else None)
        checks = [st.shaft_diameter_check(d_seat, sh.power, sh.speed_rpm, A0, KEYWAY), res.check]
        # Bearings
        bearing, pl = None, (0.0, 0.0)
        Fa = abs(res.Fa_total)
        series = ("302",) if j in worm_shafts else ("62", "63")
        for ser in series:
            try:
                bearing = cat.smallest_bearing(ser, d_j)
            except ValueError:
                bearing = None
                continue
            if bearing.ball:
                FrA, FrB = max(res.FrA, 1e-9), max(res.FrB, 1e-9)
                e, X, Y = cat.deep_groove_factors(Fa, bearing.C0r)
                pA = st.bearing_equivalent_load(FrA, Fa, e, X, Y, FP)   # A takes the axial load
                pB = FP * FrB
            else:
                ax = st.tapered_pair_axial_loads(max(res.FrA, 1e-9), max(res.FrB, 1e-9), res.Fa_total, bearing.Y)
                pA = st.bearing_equivalent_load(max(res.FrA, 1e-9), ax.Fa1, bearing.e, 0.4, bearing.Y, FP)
                pB = st.bearing_equivalent_load(max(res.FrB, 1e-9), ax.Fa2, bearing.e, 0.4, bearing.Y, FP)
            pl = (pA, pB)
            life = st.bearing_life_check(bearing.Cr, max(pA, pB), sh.speed_rpm, dp.service_hours, bearing.ball)
            if life.passed or ser == series[-1]:
                checks.append(replace(life, name_zh=f"轴承 {bearing.designation} 寿命",
                                      name_en=f"Bearing {bearing.designation} life"))
                break
        # Keys at every hub on the shaft
        for (ld, nm, d), w in zip(info, widths):
            key = cat.key_for_shaft(d_seat)
            hub = max(w or 0.0, 1.2 * d_seat, 1.5 * d_seat if d.kind in ("belt", "coupling") else 0.0)
            try:
                L = cat.standard_key_length(hub - 0.008, key)
            except ValueError:
                continue
            allow = ci_lo if ld[3] == "cast_iron" else sp_lo
            # On the flywheel's shaft the incoming element sees the mean torque only.
            t_key = sh.torque if (j == peak_from_shaft and d is designs[j - 1]) else T
            c = st.key_check(t_key, d_seat, key.h, st.key_working_length(L, key.b, "A"), allow)
            checks.append(replace(c, name_zh=f"平键 {key.label}×{L * 1e3:g}（{nm[0]}）",
                                  name_en=f"Key {key.label}×{L * 1e3:g} ({nm[1]})"))
        out.append(ShaftDesign(j, sh.speed_rpm, sh.power, T, d_min, d_j, d_seat, span, tuple(loads),
                               tuple(where), res, bearing, pl, tuple(checks)))
    return tuple(out)
