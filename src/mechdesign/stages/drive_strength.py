"""Geometry and strength of the drive's stages, shafts, bearings and keys, by the method
of 《机械设计》 (濮良贵) and 《机械设计课程设计》. Called by :mod:`.drive` once the motor,
the ratios and the shaft table are known.

Assumptions stated in the report (the brief may override the materials, modules, face
width factors and spans):
- load factor K = K_A K_V K_α K_β with K_V = 1.1, K_α = 1.0 (spur) / 1.2 (helical),
  K_β = 1.1 (8-grade gears, moderate speed); worm K = K_A · 1.1;
- S_H = 1.0, S_F = 1.4; open gears: module by bending × 1.15 for wear, no contact check;
  a designed module is at least 2 mm (gears that transmit power);
- shafts of 45 steel (调质; ``drive.shafts[].material`` overrides), A0 = 112, +5 % for a
  keyway; overhung end = the standard size ≥ d_min, journal = the bearing bore ≥ the seal
  section 1.14·d_end, seat = journal + 5 mm, collar ≈ 1.14·seat; reducer gears between the
  bearings, belt pulleys, sprockets, couplings and open gears overhung by 80 mm; σ_ca
  checked at every station with the diameter there; any failure upsizes that section;
- torques: after the flywheel the machine's peak torque for the strength checks (shaft,
  keys, bearing statics, S0 = 1.5), the cycle's cube-mean torque for the bearing life (a
  fatigue quantity); before it the motor side's torque; K_A enters the gear stages only, and
  only before the flywheel: after it the design torque is the cycle's peak, which contains the
  load variations K_A stands for, so K_A = 1 there (ISO 6336-1 / GB/T 3480);
- bearings: tapered roller 302xx → 303xx on worm-reducer shafts, deep-groove 62xx → 63xx
  elsewhere, the lightest series whose life reaches the service life at the journal, else
  a larger bore; f_p = 1.2; flat keys form A, steel hubs (cast-iron for pulleys), [σp] of
  light shocks, L ≤ hub − 8 mm, a longer hub (1.5 d), then two keys at 180° (1.5 keys).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace


from ..core import belts, chains, gears, strength as st
from ..core.fields import q
from ..data import catalogues as cat
from ..core.errors import Join
from ..i18n import N_, Msg
from ..numbers import factors_for, grouped_digits, sig
from . import drive_elements as de
from .findings import Named, encode

K_V, K_BETA, S_H, S_F = 1.1, 1.1, 1.0, 1.4
A0, KEYWAY = 112.0, 0.05
OVERHANG, CLEARANCE = 0.080, 0.060       # [m]
KD_WORM = 15.0                             # W/(m²·°C), natural ventilation (8.15–17.45)
FP = 1.2
JOURNAL_MAX = 0.130                        # [m] the largest bearing bore of the catalogue
M_MIN_POWER = 0.002                        # gears transmitting power: m ≥ 1.5–2 mm (textbook)


@dataclass(frozen=True)
class StageDesign:
    """Strength design of one stage (gear pair, worm pair; belts, chains and couplings
    carry only their torques and, for a belt, the pressure on the shafts)."""

    kind: str = q("", "'gear' | 'worm' | 'belt' | 'chain' | 'coupling'")
    geometry: (gears.SpurPair | gears.HelicalPair | gears.WormPair | belts.VBeltDesign
               | chains.ChainDesign | None) = q(
        "", "the pair's geometry (as the gear section's pair); a belt's or chain's design "
        "(Pu Lianggui, ch.8, ch.9); null for couplings")
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
class KeyDesign:
    """One flat-key joint (GB/T 1096, form A) at a hub on the shaft."""

    element: str = q("", "the element on the hub: its drive stage's kind (a row of "
                     "transmissions.yaml, which names it)")
    d: float = q("m", "shaft diameter under the hub")
    b: float = q("m", "key width")
    h: float = q("m", "key height")
    L: float = q("m", "key length (standard, ≤ hub − 8 mm)")
    l: float = q("m", "working length l = L − b")
    hub: float = q("m", "hub length")
    count: int = q("1", "keys at the hub (2: two keys at 180°, counted as 1.5)")
    torque: float = q("N·m", "torque through the hub (the peak after a flywheel)")
    check: st.Check = q("", "crushing check σ_p = 4T/(d h l) (÷ 1.5 for two keys)")
    part: str = q("", "the hub's part: 'driving:k' / 'driven:k' (the driving or driven element "
                  "of drive stage k, 0-based) or the element's own name", default="")


@dataclass(frozen=True)
class CouplingChoice:
    """The coupling joining the motor shaft to the first shaft (course guides: the shaft end
    d ≈ (0.8 … 1.2) D so that one coupling size has bores for both; LT, GB/T 4323)."""

    motor_d: float = q("m", "motor shaft extension diameter D")
    motor_e: float | None = q("m", "motor shaft extension length E")
    ratio_min: float = q("1", "least d/D of the rule d ≈ (0.8 … 1.2) D")
    d: float = q("m", "the shaft end, bored in the other half")
    size: str | None = q("", "LT size (null: no size has bores for both shafts)")
    Tn: float | None = q("N·m", "nominal torque T_n of the size")
    n_max: float | None = q("rpm", "largest speed [n] of the size (steel)")
    KA: float = q("1", "working factor K_A (Pu Lianggui table 14-1, or the brief's)")
    KA_given: bool = q("", "the brief gives K_A")
    torque: float = q("N·m", "torque through the coupling T")
    Tc: float = q("N·m", "computed torque T_c = K_A T")
    speed_rpm: float = q("rpm", "speed n")
    peak: bool = q("", "the coupling is after the flywheel: T is the cycle's peak, which contains the "
                   "load variations K_A stands for, so K_A = 1 (as for the gear stages there)",
                   default=False)


@dataclass(frozen=True)
class ShaftDesign:
    """One shaft after the motor: diameters, loads and statics, bearings, keys and checks."""

    index: int = q("1", "shaft number (1 = first after the motor)")
    speed_rpm: float = q("rpm", "n")
    power: float = q("W", "P")
    torque: float = q("N·m", "design torque (× the peak factor where it applies)")
    d_min: float = q("m", "A_0·∛(P/n) with the keyway allowance")
    d_journal: float = q("m", "bearing journal (the bearing bore)")
    d_seat: float = q("m", "the section between the bearings: a hub seat (journal + 5 mm) or, on a "
                      "shaft whose worm is cut integral with it, the worm's root circle d_f1")
    span: float = q("m", "bearing span")
    loads: tuple[st.PointLoad, ...] = q("", "the loads of the elements it carries (strength case)")
    elements: tuple[str, ...] = q("", "what sits at each load: its drive stage's kind (a row of "
                                  "transmissions.yaml, which names it)")
    result: st.ShaftResult = q("", "reactions and moments (bending–torsion check)")
    bearing: cat.Bearing | None = q("", "the bearing chosen (null: none in the catalogue)")
    bearing_loads: tuple[float, float] = q("N", "equivalent dynamic loads for the life (P_A, P_B)")
    checks: tuple[st.Check, ...] = q("", "diameter, bending–torsion, bearing life and statics, keys")
    material: str = q("", "shaft material key", default="45_QT")
    A0: float = q("1", "A_0 of the torsion estimate (mm, kW, rpm form)", default=A0)
    d_end: float | None = q("m", "overhung end under a pulley, sprocket or coupling (null: none)",
                            default=None)
    d_shoulder: float = q("m", "collar locating the hub: seat × 1.14 rounded up (h ≈ 0.07 d)",
                          default=0.0)
    life_torque_factor: float = q("1", "bearing life load / strength load of the elements after "
                                  "the flywheel (cube mean / peak of the cycle's torque)", default=1.0)
    life_reactions: tuple[float, float] = q("N", "radial bearing loads of the life case (F_rA, F_rB)",
                                            default=(0.0, 0.0))
    keys: tuple[KeyDesign, ...] = q("", "the key joints", default=())
    steps: tuple[dict, ...] = q("", "the design steps, each rule with its numbers: a catalogue "
                                "message {msgid, args} (see Finding.args), translated where shown",
                                default=())
    advice: tuple[dict, ...] = q(
        "", "what to change when an override fails, as codes: {check: the failing check's key, "
        "field: the brief field, fix: a catalogue message {msgid, args} (see Finding.args), "
        "translated where shown}", default=())
    coupling: CouplingChoice | None = q("", "the coupling from the motor (first shaft of a drive whose "
                                        "first stage is a coupling; null otherwise)", default=None)
    worm_integral: bool = q("", "the worm is cut integral with this shaft (a worm shaft): d_seat is its "
                            "root circle d_f1, checked for σ_ca; no hub, no key", default=False)
    d_seal: float | None = q("m", "the section between the overhung end's hub and its bearing (where the "
                             "seal sits): 1.14 d_end rounded up to the standard series, at most the "
                             "journal (null: no overhung end)", default=None)
    seal_reach: tuple[float, float] = q("m", "how far the seal section reaches outward from the centre of "
                                        "bearing A and of bearing B (to the overhung hub's inner edge; 0: "
                                        "no overhung end on that side)", default=(0.0, 0.0))
    element_parts: tuple[str, ...] = q("", "each element's part, as elements: 'driving:k' / 'driven:k' "
                                       "(the driving or driven element of drive stage k, 0-based) "
                                       "or the element's own name (flywheel, crank)", default=())

    def diameter_at(self, x: float) -> float:
        """The diameter [m] of the section at axial position ``x`` [m] (:func:`section_diameter`)."""
        return section_diameter(x, self.span, self.d_end, self.d_journal, self.d_seat, self.d_seal,
                                self.seal_reach)

    def section_at(self, x: float) -> str:
        """The kind of section at axial position ``x`` [m] (:func:`section_kind`)."""
        return section_kind(x, self.span, self.d_end, self.d_seal, self.seal_reach)


def section_diameter(x: float, span: float, d_end: float | None, dj: float, ds: float,
                     d_seal: float | None = None, reach: tuple[float, float] = (0.0, 0.0)) -> float:
    """The diameter [m] at axial position ``x`` of a shaft on bearings at 0 and ``span``: the
    journal at a bearing; outside the bearings the seal section within ``reach`` (m, outward
    from bearing A, from bearing B) of the bearing's centre, the overhung end beyond it (from
    the hub's inner edge on; the journal where there is no end); the hub seat between the
    bearings — the diameter the bending–torsion check takes there."""
    return {"journal": dj, "seal": d_seal, "end": d_end, "seat": ds}[
        section_kind(x, span, d_end, d_seal, reach)]


def section_kind(x: float, span: float, d_end: float | None, d_seal: float | None = None,
                 reach: tuple[float, float] = (0.0, 0.0)) -> str:
    """Which section is at axial position ``x`` (:func:`section_diameter`): "journal" at a
    bearing (and outside the bearings where there is no end), "seal", "end", or "seat"."""
    if any(abs(x - xb) < 1e-12 for xb in (0.0, span)):
        return "journal"
    if x < 0 or x > span:
        if d_end is None:
            return "journal"
        out, r = (-x, reach[0]) if x < 0 else (x - span, reach[1])
        return "seal" if d_seal is not None and out < r - 1e-12 else "end"
    return "seat"


def seal_diameter(d_end: float, dj: float | None = None) -> float:
    """The seal section next to an overhung end [m]: 1.14 d_end (a shoulder h ≈ 0.07 d that
    locates the hub) rounded up to the standard series, at most the journal ``dj``."""
    series = cat.shaft_diameter_series()
    d = st.standard_diameter(1.14 * d_end, series) if 1.14 * d_end <= series[-1] else 1.14 * d_end
    return min(d, dj) if dj is not None else d


def _phi_d(s, is_open: bool) -> float:
    return s.face_width_factor if s.face_width_factor else (0.5 if is_open else 1.0)


#: The helix angles a helical pair's corrected β may take (PU Lianggui: β = 8°…20°).
HELIX_RANGE = (math.radians(8.0), math.radians(20.0))


def rounded_helix(m: float, z1: int, z2: int, beta: float) -> float:
    """β corrected to the centre distance rounded to a whole millimetre,
    cos β = m_n (z1 + z2) / (2a): the nearest millimetre, else the next one up or down that
    keeps β within :data:`HELIX_RANGE` (β itself when none does)."""
    a0 = m * (z1 + z2) / (2 * math.cos(beta)) * 1e3          # [mm]
    for a_mm in sorted({math.floor(a0), math.ceil(a0)}, key=lambda a: abs(a - a0)):
        c = m * (z1 + z2) / (2 * a_mm * 1e-3)
        if c < 1 and HELIX_RANGE[0] - 1e-12 <= math.acos(c) <= HELIX_RANGE[1] + 1e-12:
            return math.acos(c)
    return beta


def _gear_stage(s, n1: float, T1: float, T2: float, hours: float, KA: float,
                factors: dict | None = None) -> StageDesign:
    f_ = factors or {}
    K_V, K_BETA = f_.get("K_V", globals()["K_V"]), f_.get("K_beta", globals()["K_BETA"])
    S_H, S_F = f_.get("S_H", globals()["S_H"]), f_.get("S_F", globals()["S_F"])
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

    def helix_factors(beta):
        """The factors that depend on the helix angle (all of them for a spur pair's β = 0)."""
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
        Zb, Yb = st.helix_factors(beta, eps_b) if helical else (1.0, 1.0)
        return (yf, eps_a, eps_b, st.zone_factor(alpha_t, alpha_t, beta_b),
                st.contact_ratio_factor(eps_a, eps_b), st.bending_ratio_factor(eps_a, beta_b), Zb, Yb)

    yf, eps_a, eps_b, ZH, Ze, Ye, Zb, Yb = helix_factors(beta)
    ZE = st.elastic_coefficient(mat1.E, mat1.nu, mat2.E, mat2.nu)
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
    a0 = None
    if helical:
        # the centre distance rounded to a whole millimetre and β corrected to it, the
        # checks then made with the corrected β (PU Lianggui, Machine Design, ch. 10, the
        # helical pair's design steps; page review 48: a = 337.53 mm printed unrounded)
        a0 = m * (z1 + z2) / (2 * math.cos(beta))
        beta = rounded_helix(m, z1, z2, beta)
        yf, eps_a, eps_b, ZH, Ze, Ye, Zb, Yb = helix_factors(beta)
        geo = gears.helical_pair(m, z1, z2, beta)
        d1 = geo.d1
    else:
        geo = gears.spur_pair(m, z1, z2, x1=s.x1, x2=s.x2)
        d1 = geo.g1.d
    b = math.ceil(phi_d * d1 * 1e3) * 1e-3
    checks = []
    if not is_open:
        c = st.gear_contact_check(T1, K, b, d1, u, ZE, ZH, Ze, Zb, sH)
        checks.append(replace(c, name=N_("Contact fatigue (flanks)")))
    for i in range(2):
        c = st.gear_bending_check(T1, K, b, d1, m, yf[i][0], yf[i][1], Ye, Yb, sF[i])
        checks.append(replace(c, name=N_("Pinion root bending fatigue") if i == 0
                              else N_("Gear root bending fatigue")))
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
         "open": is_open, "beta": beta, "a0": a0, "beta0": s.helix_angle if helical else 0.0})


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
        st.worm_contact_check(T2, K, a, wheel.ZE, zr, sH),
        replace(st.worm_bending_check(T2, K, geo.d1, geo.d2, m, YFa2, gamma, sF),
                name=N_("Worm-wheel root bending fatigue")),
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
        after = peak_from_shaft is not None and k >= peak_from_shaft
        boost = peak_factor if after else 1.0
        T1, T2 = shafts[k].torque * boost, shafts[k + 1].torque * boost
        # K_A scales a nominal torque for the working machine's load variations; after the
        # flywheel the design torque is the cycle's own peak, which contains them: K_A = 1
        # there (ISO 6336-1 / GB/T 3480: K_A = 1 when the known load cycle is used)
        KA = 1.0 if after else dp.KA
        s = replace(s, z1=r.z1, z2=r.z2)
        if s.type in ("spur", "helical"):
            d = _gear_stage(s, shafts[k].speed_rpm, T1, T2, dp.service_hours, KA,
                            dict(dp.factors))
            out.append(replace(d, checks=d.checks + de.gear_geometry_checks(d, s)))
        elif s.type == "worm":
            d = _worm_stage(s, shafts[k].speed_rpm, shafts[k].power, T1, T2, dp.service_hours, KA)
            d = replace(d, checks=d.checks + (de.worm_deflection_check(d, dp.stages[k - 1].span if k else None),))
            if s.efficiency is None:
                worm_eff[s.index] = d.extra["eta"]
            out.append(d)
        elif s.type == "belt":    # 濮良贵 ch.8: the load on the shafts is F_p = 2 z F0 sin(α1/2)
            try:
                b = de.belt_design(s, r, shafts[k], dp)
            except belts.BeltDesignError as e:
                raise _stage_error(s.index, e) from None
            out.append(StageDesign("belt", b, (), None, None, False, None, b.KA, T1, T2, {"Q": b.Fp}, {},
                                   b.checks, {"v": b.v}))
        elif s.type == "chain":   # 濮良贵 ch.9: F_Q ≈ (1.2…1.3) F_e on the shafts
            try:
                c = de.chain_design(s, r, shafts[k], dp)
            except chains.ChainDesignError as e:
                raise _stage_error(s.index, e) from None
            out.append(StageDesign("chain", c, (), None, None, False, None, c.KA, T1, T2, {"Q": c.FQ}, {},
                                   c.checks, {"v": c.v}))
        else:
            out.append(StageDesign(s.type, None, (), None, None, False, None, 1.0, T1, T2, {}, {}, (), {}))
    return out, worm_eff


def _step(msgid: str, /, **fields) -> dict:
    """A design step: the catalogue message ``msgid`` with its fields, as data."""
    return encode(Msg(msgid, **fields))


def _stage_error(index: int, e):
    """The design error of a belt or chain stage, prefixed with the stage's brief field."""
    from ..core.drive import DriveDesignError
    from ..core.errors import Msg

    return DriveDesignError(Msg(N_("drive.stages[{i}]: {error}"), i=index, error=e.message))


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



STATIC_S0 = 1.5            # 表13-8: rotating bearings under shock loads 1.2–2.5
HUB_MAX = 1.5              # hub length up to 1.5 d (gears, pulleys: 1.2–1.5 d usual, 2 d at most)
KEY_GAP = 0.008            # key length ≤ hub − 5…10 mm


def _mmf(x: float, digits: int = 1) -> str:
    return f"{x * 1e3:.{digits}f}".rstrip("0").rstrip(".") if digits else f"{x * 1e3:.0f}"


def _life_scale(designs, peak_factor, peak_from_shaft, life_factor):
    """Scale of each element's forces from the strength case to the life case: the
    elements after the flywheel carry the peak in the strength case and the cycle's cube-mean
    torque (life_factor × the mean; 1 = the mean) in the life case."""
    out = []
    for k, _ in enumerate(designs):
        boosted = peak_from_shaft is not None and k >= peak_from_shaft
        out.append((life_factor / peak_factor) if boosted and peak_factor > 0 else 1.0)
    return out


def _place(dp, j, designs, kinds, weight=None, crank=None):
    """The elements on shaft j and where they sit: those inside the housing evenly between
    the bearings, the overhung ones 80 mm outside (first left, then right). ``kinds``: the
    stages' kinds (transmissions.yaml keys), which name the elements. ``weight``: (W [N],
    width [m]) of a flywheel on the shaft: a load −W in the vertical plane between the
    bearings, after the stages' elements (it has no drive stage: no key is designed for it)."""
    elems = [(j - 1, designs[j - 1], False, kinds[j - 1])]
    if j < len(designs):
        elems.append((j, designs[j], True, kinds[j]))
    info = []
    for k, d, drv, nm in elems:
        inside, fields, width, hub_mat = _element_loads(d, drv)
        info.append(dict(k=k, design=d, driving=drv, name=nm, inside=inside, fields=fields,
                         part=f"{'driving' if drv else 'driven'}:{k}",
                         width=width or (0.06 if d.kind == "worm" else 0.0), hub_mat=hub_mat))
    if weight is not None and weight[0] > 0:
        info.append(dict(k=None, design=None, driving=False, name="flywheel", inside=True, part="flywheel",
                         fields=dict(Fv=-float(weight[0])), width=float(weight[1]),
                         hub_mat="cast_iron"))
    if crank is not None:
        # the crank on its shaft: its frame reaction, a radial load overhung beyond the
        # bearings (no drive stage: no key is designed for it); the plane is set by the caller
        # (two identical linkages side by side: a crank beyond each bearing, each with half)
        for _ in range(crank.count):
            info.append(dict(k=None, design=None, driving=False, name="crank", inside=False, part="crank",
                             fields=dict(Fh=float(crank.F) / crank.count),
                             life_fields=dict(Fh=float(crank.life) / crank.count),
                             width=0.0, hub_mat="steel"))
    inside_width = sum(i["width"] for i in info if i["inside"]) or 0.05
    # a worm's shaft: the span its deflection check takes (0.9 d2), not the worm's width + 2 ×
    # 60 mm (the furnace drive's 180 mm against the deflection check's 79 mm)
    worm = _driving_worm(info)
    span = dp.stages[j - 1].span or (de.worm_span(worm.geometry) if worm is not None
                                     else inside_width + 2 * CLEARANCE)
    ins = [i for i in info if i["inside"]]
    for n, i in enumerate(ins):
        i["x"] = span * (n + 1) / (len(ins) + 1)
    side = [-OVERHANG, span + OVERHANG]
    for i in info:
        if not i["inside"]:
            i["x"] = side.pop(0) if side else span + OVERHANG
    cranks = [i for i in info if i["name"] == "crank"]
    if len(cranks) > 1:       # two linkages side by side: named by the bearing each sits beyond
        for i in cranks:
            i["part"] = "crank:" + ("A" if i["x"] < 0 else "B")
    return info, span


def _driving_worm(info):
    """The design of the worm cut on this shaft (the driving member of a worm stage), or None."""
    return next((i["design"] for i in info if i["design"] is not None and i["design"].kind == "worm"
                 and i["driving"]), None)


def _statics(span, info, T, scale=None, stations=()):
    loads = []
    for i in _load_order(info):
        f = dict(i["fields"])
        if scale is not None and "life_fields" in i:     # the crank: its cube-mean force
            f = dict(i["life_fields"])
        elif scale is not None and i["k"] is not None:   # a weight is the same in both cases
            c = scale[i["k"]]
            f = {k: (v * c if k != "r" else v) for k, v in f.items()}
        loads.append(st.PointLoad(i["x"], **f))
    xs = [p.x for p in loads] or [0.0, span]
    res = st.shaft_check(span, loads, T, 1.0, 1.0, 0.6, (min(xs), max(xs)) if len(xs) > 1 else None,
                         stations)
    return loads, res


def _load_order(info):
    """The elements inside the housing first, then the overhung ones (the loads' order)."""
    return [i for i in info if i["inside"]] + [i for i in info if not i["inside"]]


def _bearing_life(b, res, life_res, n_rpm, hours, peak):
    """(equivalent loads for the life, life check, static check) of bearing b: the life from
    the life case's reactions × f_p, the static strength from the strength case (the peak)."""
    Fa, Fa_l = abs(res.Fa_total), abs(life_res.Fa_total)
    if b.ball:
        e, X, Y = cat.deep_groove_factors(Fa_l, b.C0r)
        pA = st.bearing_equivalent_load(max(life_res.FrA, 1e-9), Fa_l, e, X, Y, FP)  # A takes Fa
        pB = FP * max(life_res.FrB, 1e-9)
        p0 = max(st.bearing_static_load(res.FrA, Fa, 0.6, 0.5), res.FrB)
    else:
        ax = st.tapered_pair_axial_loads(max(life_res.FrA, 1e-9), max(life_res.FrB, 1e-9), life_res.Fa_total, b.Y)
        pA = st.bearing_equivalent_load(max(life_res.FrA, 1e-9), ax.Fa1, b.e, 0.4, b.Y, FP)
        pB = st.bearing_equivalent_load(max(life_res.FrB, 1e-9), ax.Fa2, b.e, 0.4, b.Y, FP)
        ax0 = st.tapered_pair_axial_loads(max(res.FrA, 1e-9), max(res.FrB, 1e-9), res.Fa_total, b.Y)
        p0 = max(st.bearing_static_load(res.FrA, ax0.Fa1, 0.5, b.Y0),
                 st.bearing_static_load(res.FrB, ax0.Fa2, 0.5, b.Y0))
    life = st.bearing_life_check(b.Cr, max(pA, pB), n_rpm, hours, b.ball)
    life = replace(life, name=N_("Bearing {designation} life"), name_args={"designation": b.designation})
    static = None
    if peak:
        static = replace(st.bearing_static_check(b.C0r, max(p0, 1e-9), STATIC_S0),
                         name=N_("Bearing {designation} static strength (peak load)"),
                         name_args={"designation": b.designation})
    return (pA, pB), life, static


def _hub_length(i, dk: float) -> float:
    """The hub's length by the rule on a ``dk`` shaft [m]: the element's width, at least 1.2 d,
    1.5 d for a pulley, a coupling, a sprocket or a crank (before a key asks for more)."""
    kind = i["design"].kind if i["design"] is not None else i["name"]
    return max(i["width"], 1.2 * dk, 1.5 * dk if kind in ("belt", "coupling", "chain", "crank") else 0.0)


#: The part a drive stage puts on a shaft: (the stage design's kind, driving) → its name.
PART_WORDS = {("gear", True): Msg.pgettext("shaft part", "pinion"),
              ("gear", False): Msg.pgettext("shaft part", "gear"),
              ("worm", True): Msg.pgettext("shaft part", "worm"),
              ("worm", False): Msg.pgettext("shaft part", "worm wheel"),
              ("belt", True): Msg.pgettext("shaft part", "driving pulley"),
              ("belt", False): Msg.pgettext("shaft part", "driven pulley"),
              ("chain", True): Msg.pgettext("shaft part", "driving sprocket"),
              ("chain", False): Msg.pgettext("shaft part", "driven sprocket")}


def part_name(kind: str, driving: bool, k: int | None) -> Msg | None:
    """"the pinion of stage 3": the part drive stage ``k`` (0-based) puts on a shaft, None
    for a stage without such parts (a coupling)."""
    word = PART_WORDS.get((kind, bool(driving)))
    if word is None or k is None:
        return None
    return Msg(N_("the {part} of stage {n}"), part=word, n=k + 1)


def part_message(code: str, designs) -> Msg | None:
    """The name of the part stored on a shaft as ``code`` (ShaftDesign.element_parts,
    KeyDesign.part): "driving:2" → "the pinion of stage 3" (``designs`` the drive stages'
    designs), "crank:A" → "the crank beyond bearing A" (two linkages side by side: the
    die-cutter's shaft Ⅲ listed "crank, crank", page review 48); None for a part its kind
    names (a single crank); "flywheel" → "the flywheel"."""
    role, _sep, rest = (code or "").partition(":")
    if role in ("driving", "driven") and rest.isdigit() and int(rest) < len(designs):
        design = designs[int(rest)]
        return part_name(design.kind, role == "driving", int(rest)) if design is not None else None
    if role == "crank" and rest in ("A", "B"):
        return Msg(N_("the crank beyond bearing {side}"), side=f"${rest}$")
    if role == "flywheel":
        return Msg.pgettext("shaft part", "the flywheel")
    return None


def _keys(info, d_end, d_seat, T_of, allow_of, key_length=None):
    """Flat keys at every hub: b × h by the diameter, L the longest standard ≤ hub − 8 mm;
    if the crushing check fails, a longer hub (up to 1.5 d), then two keys at 180°."""
    out = []
    for i in info:
        d = i["design"]
        # every hub has its key: a stage's wheel, a crank, the flywheel (it carries the
        # fluctuating torque J_F·ε through its hub; checked with the shaft's design torque,
        # which bounds it: note 49 found the flywheel on its shaft without a key)
        if d is not None and d.kind == "worm" and i["driving"]:
            continue                      # the worm is cut on its shaft: no key
        dk = d_seat if i["inside"] or d_end is None else d_end
        key = cat.key_for_shaft(dk)
        base = _hub_length(i, dk)
        T, allow = T_of(i), allow_of(i)
        choice = None
        if key_length is not None:
            hub = max(base, key_length + KEY_GAP)
            L = key_length
            lw = st.key_working_length(L, key.b, "A")
            c = st.key_check(T, dk, key.h, lw, allow)
            choice = (hub, L, lw, 1, c)
        else:
            for hub, count in ((base, 1), (max(base, HUB_MAX * dk), 1), (max(base, HUB_MAX * dk), 2)):
                try:
                    L = cat.standard_key_length(hub - KEY_GAP, key)
                except ValueError:
                    continue
                lw = st.key_working_length(L, key.b, "A")
                c = (st.key_check if count == 1 else st.double_key_check)(T, dk, key.h, lw, allow)
                choice = (hub, L, lw, count, c)
                if c.passed:
                    break
        if choice is None:
            continue
        hub, L, lw, count, c = choice
        nm = i["name"]
        lab = f"{key.label}×{L * 1e3:g}" + (" ×2" if count == 2 else "")
        # named in the report's language, by its part (page review 48: "Key 28×16×140
        # (closed helical gear pair)" twice on one shaft, which gear was which)
        element = encode((part_name(d.kind, i["driving"], i["k"]) if d is not None
                          else part_message(i["part"], ())) or Named("transmissions", nm))
        c = replace(c, name=N_("Key {label} ({element_en})"),
                    name_args={"label": lab, "element_zh": element, "element_en": element})
        out.append((KeyDesign(nm, dk, key.b, key.h, L, lw, hub, count, T, c, i["part"]),
                    i["inside"] or d_end is None))
    return out


def _evaluate(dp, j, sh, info, span, T, res, life_res, mat, dims, bearing_fixed, series, peak,
              T_of, allow_of, key_length):
    """Every check of shaft j with the diameters ``dims`` = (d_end, journal, seat)."""
    d_end, dj, ds = dims
    bearing = life = static = None
    pl = (0.0, 0.0)
    if bearing_fixed is not None:
        bearing = cat.bearing(bearing_fixed)
        pl, life, static = _bearing_life(bearing, res, life_res, sh.speed_rpm, dp.service_hours, peak)
    else:
        for ser in series:
            try:
                b = cat.smallest_bearing(ser, dj)
            except ValueError:
                continue
            if abs(b.d - dj) > 1e-9:
                continue
            pl_, life_, static_ = _bearing_life(b, res, life_res, sh.speed_rpm, dp.service_hours, peak)
            bearing, pl, life, static = b, pl_, life_, static_
            if life_.passed and (static_ is None or static_.passed):
                break
    flagged = _keys(info, d_end, ds, T_of, allow_of, key_length)
    keys = [k for k, _ in flagged]
    # the overhung end's steps (review41 B): between an overhung hub and its bearing the shaft
    # is the end (to the hub's inner edge) and then the seal section (to the bearing's outer
    # face), which carry almost the bearing's moment on a smaller diameter than the journal
    seal = seal_diameter(d_end, dj) if d_end is not None else None
    reach, stations, pre_x = _end_steps(info, keys, d_end, span, bearing, T_of, T)
    if stations:
        res = _statics(span, info, T, stations=stations)[1]

    def diameter_at(x):
        return section_diameter(x, span, d_end, dj, ds, seal, reach)

    pre = [i["x"] for i in info if T_of(i) < T] + pre_x    # on the motor side of the flywheel

    def torque_at(x, t):
        return min(t, sh.torque) if any(abs(x - xp) < 1e-12 for xp in pre) else t

    bend, crit, dcrit = st.shaft_stepped_check(res, diameter_at, mat.sigma_minus1b_allow, 0.6, torque_at)
    end_keys_ok = all(k.check.passed for k, inside in flagged if not inside)
    in_keys_ok = all(k.check.passed for k, inside in flagged if inside)
    outside = crit.x < 0 or crit.x > span
    return dict(bend=bend, crit=crit, dcrit=dcrit, bearing=bearing, pl=pl, life=life, static=static, keys=keys,
                res=res, seal=seal, reach=reach,
                bad_end=d_end is not None and ((not bend.passed and outside) or not end_keys_ok),
                bad_in=((not bend.passed and not outside) or bearing is None or not in_keys_ok
                        or (life is not None and not life.passed) or (static is not None and not static.passed)))


def _end_steps(info, keys, d_end, span, bearing, T_of, T):
    """The sections where an overhung end steps: (reach, stations, stations on the motor side
    of the flywheel). For each overhung hub, its inner edge (half the hub's length, the key
    joint's hub or the rule's 1.2 d, from its load towards the bearing) and the bearing's
    outer face (half its width from its centre); ``reach`` = (A side, B side): how far the
    seal section reaches outward from each bearing's centre (0: no overhung end there)."""
    if d_end is None:
        return (0.0, 0.0), [], []
    face = 0.5 * bearing.B if bearing is not None else 0.0
    reach = [0.0, 0.0]
    stations, pre = [], []
    hubs = {k.element: k.hub for k in keys}
    for i in info:
        if i["inside"]:
            continue
        hub = hubs.get(i["name"], _hub_length(i, d_end))
        left = i["x"] < 0
        xb = 0.0 if left else span
        a = abs(i["x"] - xb)
        edge = max(a - 0.5 * hub, face)
        side = 0 if left else 1
        reach[side] = edge if reach[side] == 0.0 else min(reach[side], edge)
        sign = -1.0 if left else 1.0
        xs = [xb + sign * edge] + ([xb + sign * face] if face < edge - 1e-12 else [])
        stations += xs
        if T_of(i) < T:
            pre += xs
    return (reach[0], reach[1]), stations, pre


def shaft_designs(dp, designs, shafts, peak_factor, peak_from_shaft, kinds,
                  life_factor: float | None = None,
                  weights: dict[int, tuple[float, float]] | None = None,
                  motor=None, crank: dict | None = None) -> tuple[ShaftDesign, ...]:
    """Each shaft designed by the handbook's procedure (濮良贵《机械设计》 ch.15, 《机械设计课程
    设计》): d_min = A0∛(P/n) (+5 % keyway); the sections laid out from the parts (overhung end
    → journal → seat → shoulder), each rounded up to the standard series; the bending–torsion
    check σ_ca = √(M² + (αT)²)/(0.1 d³) ≤ [σ_-1b] at every station with the diameter there;
    the bearing of the lightest series whose life reaches the service life at the journal;
    the keys by the diameter and the hub; any failure → the section grows (overhung end: the
    next standard size; journal and seat: +5 mm) and everything is re-checked.

    Torques: the shafts after the flywheel (``peak_from_shaft``) carry the machine's peak
    torque (mean × ``peak_factor``) for the strength checks (shaft, keys, bearing statics);
    the bearing life, a fatigue quantity, takes the cycle's equivalent load: the elements'
    forces at the cube-mean torque (``life_factor`` × the mean; None: the mean) × f_p.
    ``weights``: {shaft: (W [N], width [m])}, a flywheel's weight between that shaft's bearings.
    ``motor``: the motor (:class:`~mechdesign.core.drive.Motor`); where a coupling joins it to
    shaft Ⅰ, that shaft's end is at least the course guides' 0.8 D (D the motor's shaft
    extension) and a bore of the LT coupling that also bores D (:func:`_coupling`).
    ``crank``: {shaft: :class:`.crank_load.CrankLoad`}, the crank on that shaft: its largest
    force over the cycle a radial load overhung 80 mm beyond a bearing (the life case: the
    force's cube mean), in the plane and sense that give the largest equivalent moment (the
    reducer's orientation about the shaft is not in the brief: the worst of the four)."""
    choices = {c.shaft: c for c in dp.shafts}
    worm_shafts = {k for k, d in enumerate(designs) if d.kind == "worm"} | \
                  {k + 1 for k, d in enumerate(designs) if d.kind == "worm"}
    lf = 1.0 if life_factor is None else life_factor
    scale = _life_scale(designs, peak_factor, peak_from_shaft, lf)
    series_d = cat.shaft_diameter_series()
    out = []
    for j in range(1, len(shafts)):
        sh = shafts[j]
        ch = choices.get(j)
        peak = peak_from_shaft is not None and j >= peak_from_shaft
        boost = peak_factor if peak else 1.0
        T = sh.torque * boost
        mat_key = (ch.material if ch and ch.material else "45_QT")
        mat = cat.shaft_material(mat_key)
        a0 = A0 if mat_key.startswith("45") else 0.5 * (mat.A0_min + mat.A0_max)
        d_min = st.shaft_min_diameter(sh.power, sh.speed_rpm, a0, KEYWAY)
        cr = (crank or {}).get(j)
        info, span = _place(dp, j, designs, kinds, (weights or {}).get(j), cr)
        # the worm on this shaft, cut integral with it (濮良贵 ch.11: a worm is almost always
        # made in one piece with its shaft) where it is the only part between the bearings:
        # that section is its root circle, not a hub seat (review39a: d_f1 = 19 mm under
        # 20 mm journals, the shaft listed with a 25 mm seat)
        worm_here = _driving_worm(info)
        worm_root = (round(de.worm_root_diameter(worm_here.geometry), 9) if worm_here is not None and all(
            i["design"] is worm_here for i in info if i["inside"]) else None)
        # the torque the sections carry: two cranks (two linkages side by side, one beyond each
        # bearing, the drive's gear between them) take half of it each, and every section
        # carries half; the gear's hub the whole
        Tsec = T / cr.count if cr is not None else T
        if cr is not None:
            _worst_plane(span, info, Tsec)
        loads, res = _statics(span, info, Tsec)
        _, life_res = _statics(span, info, Tsec * lf / boost if peak else Tsec, scale)
        overhung = any(not i["inside"] for i in info)
        series = ("302", "303") if j in worm_shafts else ("62", "63")
        sp_lo, _ = cat.key_allowable_stress("steel", "light_shock")
        ci_lo, _ = cat.key_allowable_stress("cast_iron", "light_shock")

        def T_of(i, j=j, sh=sh, T=T, Tsec=Tsec):
            # the element before the flywheel sees the motor side's mean torque (the flywheel
            # itself, k None, the shaft's design torque; a crank its share)
            if i["name"] == "crank":
                return Tsec
            return sh.torque if (peak_from_shaft is not None and i["k"] is not None
                                 and i["k"] < peak_from_shaft) else T

        def allow_of(i):
            return ci_lo if i["hub_mat"] == "cast_iron" else sp_lo

        couple = None      # (D, K_A, T, T_c, n, the first end) where a coupling joins the motor
        if (j == 1 and designs[0].kind == "coupling" and motor is not None
                and getattr(motor, "shaft_diameter", None) and overhung):
            Dm = motor.shaft_diameter
            given_KA = getattr(dp.stages[0], "belt_KA", None)
            after = peak_from_shaft is not None and peak_from_shaft <= 0     # the coupling carries the peak
            KA_c = (given_KA if given_KA is not None else 1.0 if after
                    else cat.coupling_application_factor(dp.KA))
            hub = next(i for i in info if i["k"] == 0)
            Tcp = T_of(hub)
            lo_ratio = cat.motor_end_ratio()[0]
            need = max(d_min, lo_ratio * Dm)
            pick = cat.coupling_for(Dm, need, KA_c * Tcp, sh.speed_rpm)
            first = pick[1] if pick else st.standard_diameter(need, series_d)
            couple = (Dm, KA_c, Tcp, KA_c * Tcp, sh.speed_rpm, first, given_KA is not None, lo_ratio,
                      after and given_KA is None)

        def design(fixed):
            """The loop; ``fixed`` the overrides of this shaft (None: free)."""
            steps = []
            d_end = None
            if overhung:
                d_end = (fixed.end if fixed and fixed.end else couple[5] if couple
                         else st.standard_diameter(d_min, series_d))
            seal = seal_diameter(d_end) if d_end is not None else 0.0
            if fixed and fixed.bearing and not fixed.journal:
                dj = cat.bearing(fixed.bearing).d
            elif fixed and fixed.journal:
                dj = fixed.journal
            else:
                dj = round(max(_round_up(max(seal, d_min + 0.003), 0.005), 0.020), 6)
            ds = fixed.seat if fixed and fixed.seat else round(dj + 0.005, 6)
            free_end = not (fixed and fixed.end)
            free_j = not (fixed and (fixed.journal or fixed.bearing))
            free_s = not (fixed and fixed.seat)
            integral = worm_root is not None and free_s
            if integral:           # the worm's root circle: set by the worm, not by the loop
                ds, free_s = worm_root, False
            kl = fixed.key_length if fixed else None
            ev = None
            for it in range(60):
                ev = _evaluate(dp, j, sh, info, span, Tsec, res, life_res, mat, (d_end, dj, ds),
                               fixed.bearing if fixed else None, series, peak, T_of, allow_of, kl)
                bad_end, bad_in = ev["bad_end"], ev["bad_in"]
                if bad_end and free_end:
                    new = st.standard_diameter(d_end * (1 + 1e-6) + 1e-6, series_d)
                    if free_j and _round_up(seal_diameter(new), 0.005) > JOURNAL_MAX + 1e-9:
                        # the journal could not follow the end (its seal) within the catalogue
                        steps.append(("top", (dj, ds), (dj, ds), _kinds(ev)))
                        break
                    steps.append(("end", d_end, new, _kinds(ev)))
                    d_end = new
                    seal = seal_diameter(d_end)
                    if free_j and dj < seal:
                        dj = round(_round_up(seal, 0.005), 6)
                        # (an integral worm's root stays: the worm sets it, not the journal)
                        ds = round(dj + 0.005, 6) if free_s else ds if integral else max(ds, dj)
                    continue
                if (integral and not ev["bend"].passed and 0.0 < ev["crit"].x < span
                        and not any(abs(ev["crit"].x - xb) < 1e-12 for xb in (0.0, span))):
                    break          # the worm's root fails: a larger journal does not help
                if bad_in and (free_j or free_s):
                    old = (dj, ds)
                    nj = round(dj + 0.005, 6) if free_j else dj
                    ns = round(max(nj + 0.005, ds + 0.005 if not free_j else nj + 0.005), 6) if free_s else ds
                    if nj > JOURNAL_MAX + 1e-9 or (not free_j and ns > JOURNAL_MAX + 0.010 + 1e-9):
                        # the catalogue's largest bearing bore reached (a given journal: the seat
                        # grows no further than a free one): the sections stay at the last ones
                        # checked, and the checks that fail are reported as failing
                        steps.append(("top", old, old, _kinds(ev)))
                        break
                    dj, ds = nj, ns
                    steps.append(("in", old, (dj, ds), _kinds(ev)))
                    continue
                break
            return ev, (d_end, dj, ds), steps, integral

        ev, dims, loop_steps, integral = design(ch)
        advice = ()
        if ch is not None:
            free_ev, free_dims, _, _ = design(None)
            advice = _advice(ch, ev, dims, free_ev, free_dims)
        d_end, dj, ds = dims
        res = replace(ev["res"], check=ev["bend"])
        # the collar locates the hub; on a worm shaft the bearings (the worm is the shaft)
        seated = dj if integral else ds
        shoulder = (st.standard_diameter(1.14 * seated, series_d) if seated * 1.14 <= series_d[-1]
                    else seated * 1.14)
        checks = [st.shaft_diameter_check(min(d for d in (d_end, dj) if d is not None), sh.power, sh.speed_rpm,
                                          a0, KEYWAY), ev["bend"]]
        if ch is not None and not checks[0].passed:
            name = "end_mm" if d_end is not None else "journal_mm"
            need = st.standard_diameter(d_min, series_d)
            advice = advice + (_advice_entry(checks[0].key, f"drive.shafts[{ch.index}].{name}",
                                             Msg(_AT_LEAST[name], d=_mmf(need))),)
        coupling = None
        if couple is not None:
            coupling, more = _coupling(couple, d_end, motor)
            checks += more
            if ch is not None and ch.end and not more[0].passed:
                advice = advice + (_advice_entry(more[0].key, f"drive.shafts[{ch.index}].end_mm",
                                                 Msg(_AT_LEAST["end_mm"], d=_mmf(couple[5]))),)
        if ev["life"] is not None:
            checks.append(ev["life"])
        if ev["static"] is not None:
            checks.append(ev["static"])
        checks += [k.check for k in ev["keys"]]
        # peak_from_shaft 0: the peak reaches the motor's shaft, i.e. the drive has no flywheel
        head, tail = _steps(sh, mat, a0, d_min, dims, shoulder, T, peak, peak_factor, lf, ev, span, dp,
                            coupling, motor, flywheel=peak_from_shaft != 0,
                            worm=worm_here if integral else None)
        if cr is not None:
            head = head + [_crank_step(cr, info, span, Tsec)]
            if cr.others:
                names = Join(Msg.pgettext("list", ", "), list(cr.others))
                head.append(_step(N_("{names} on this shaft are not loaded in this check: the brief gives no "
                                     "force for them (a spring force, a feed resistance); a force of 1 % of "
                                     "the crank's, {lim} N, would change the largest moment by about 1 %"),
                                  names=names, lim=_text_num(round(0.01 * cr.F))))
        steps = head + _loop_text(loop_steps) + tail
        out.append(ShaftDesign(j, sh.speed_rpm, sh.power, T, d_min, dj, ds, span, tuple(loads),
                               tuple(i["name"] for i in _load_order(info)), res, ev["bearing"], ev["pl"], tuple(checks),
                               mat.key, a0, d_end, shoulder, (lf / peak_factor) if peak else 1.0,
                               (life_res.FrA, life_res.FrB), tuple(ev["keys"]), tuple(steps), advice,
                               coupling, integral, ev["seal"], ev["reach"],
                               tuple(i["part"] for i in _load_order(info))))
    return tuple(out)


def _coupling(couple, d_end: float, motor) -> tuple[CouplingChoice, list]:
    """The LT coupling for the motor shaft D and the shaft end ``d_end`` as designed, and its
    checks: the end against the course guides' rule d ≥ 0.8 D, the coupling's computed torque
    T_c = K_A T against T_n (the smallest size with bores for both, T_c ≤ T_n and n ≤ [n]; else
    the smallest with both bores, whose torque check then fails), or — when no size has both
    bores — the distance of the end from the nearest bore of a size that bores D (> 0: fails)."""
    Dm, KA_c, Tcp, Tc, n, _first, given, lo, peak = couple
    sizes = cat.couplings()
    both = [c for c in sizes if cat.has_bore(c.bores, Dm) and cat.has_bore(c.bores, d_end)]
    c = next((c for c in both if Tc <= c.Tn * (1 + 1e-12) and n <= c.n_max), both[0] if both else None)
    choice = CouplingChoice(Dm, getattr(motor, "shaft_length", None), lo, d_end, c.size if c else None,
                            c.Tn if c else None, c.n_max if c else None, KA_c, given, Tcp, Tc, n, peak)
    checks = [st.check("motor_end", N_("Shaft end against the motor shaft ($d \\ge 0.8D$)"), "d", d_end,
                       lo * Dm, "mm", "ge", D=Dm, ratio=lo)]
    if c is not None:
        checks.append(replace(st.check("coupling_torque", N_("Coupling {size} torque"), "T_c", Tc, c.Tn, "N·m",
                                       "le", KA=KA_c, T=Tcp, n=n, n_max=c.n_max),
                              name_args={"size": c.size}))
    else:
        near = min((abs(b - d_end) for s in sizes if cat.has_bore(s.bores, Dm) for b in s.bores), default=d_end)
        checks.append(st.check("coupling_bore", N_("Coupling bores for the motor shaft and the shaft end"),
                               "\\Delta d", near, 0.0, "mm", "le", D=Dm, d=d_end))
    return choice, checks


def _worst_plane(span, info, T):
    """Put the crank's force (and its life-case force) in the plane and sense — ±horizontal,
    ±vertical — that give the largest equivalent moment M_ca over the stations."""
    cranks = [i for i in info if i["name"] == "crank"]     # in phase: one plane and sense for all
    F, Fl = cranks[0]["fields"]["Fh"], cranks[0]["life_fields"]["Fh"]

    def put(plane, sign):
        for i in cranks:
            i["fields"], i["life_fields"] = {plane: sign * F}, {plane: sign * Fl}

    best = None
    for plane in ("Fh", "Fv"):
        for sign in (1.0, -1.0):
            put(plane, sign)
            m = _statics(span, info, T)[1].critical.Mca
            if best is None or m > best[0] + 1e-9 * max(m, 1.0):
                best = (m, plane, sign)
    put(best[1], best[2])


def _crank_step(cr, info, span, Tsec) -> dict:
    """The design step that states the crank's load: where it sits, the governing crank angle,
    the force and how it was found (with two linkages side by side: both cranks, each with half
    the force and of the torque, ``Tsec`` the sections' torque)."""
    xs = [i["x"] for i in info if i["name"] == "crank"]
    x = xs[0]
    side = "B" if x > span else "A"
    found = dict(a=_mmf(abs(x - (span if x > span else 0.0)), 0),
                 sigma="$\\sigma_{ca}$", F=f"$|F_{{{cr.joint}}}|$ = {_text_num(round(cr.F))}",
                 phi=f"{math.degrees(cr.phase):.2f}",
                 Fx=f"$F_x$ = {_text_num(round(cr.Fx))}".replace("-", "\u2212"),
                 Fy=f"$F_y$ = {_text_num(round(cr.Fy))}".replace("-", "\u2212"),
                 Mb=f"$M_b$ = {_sig(cr.torque if abs(cr.torque) > 1e-9 * max(abs(cr.F), 1.0) else 0.0, 4)}",
                 grid=_text_num(round(cr.grid_max)))
    if cr.count == 2:
        return _step(N_("the two cranks on this shaft (design assumption: two identical linkages side by side lift the "
                        "platen in phase, a crank overhung {a} mm beyond each bearing, at $x$ = {x} mm and {x2} mm) "
                        "load it with the frame reaction of the planar analysis, the sum of the two linkages', "
                        "half on each; {sigma} grows with it at every section, so its largest magnitude over the "
                        "cycle governs: {F} N at crank angle $\\varphi$ = {phi}° from position 1 ({Fx} N, {Fy} N; "
                        "{Mb} N·m there), found exactly (the kinetostatics solved at any $\\varphi$ between the "
                        "resistances' jumps, the samples' local maxima refined by Brent's bounded search, each "
                        "piece's ends taken one-sided; the largest sample: {grid} N): {half} N on each crank, taken "
                        "in the plane and sense of the largest moment (the reducer's orientation about the shaft is "
                        "not in the brief); the bearing life takes the cube mean over the cycle, {life} N on each; "
                        "each crank takes half the torque, so the sections carry {Th} N·m (the gear's hub the whole)"),
                     x=_mmf(min(xs), 0).replace("-", "\u2212"), x2=_mmf(max(xs), 0),
                     half=_text_num(round(cr.F / 2)), life=_text_num(round(cr.life / 2)),
                     Th=f"$T/2$ = {_sig(Tsec, 4)}", **found)
    return _step(N_("the crank on this shaft (design assumption: overhung {a} mm beyond bearing {side}, at "
                     "$x$ = {x} mm) loads it with the frame reaction on the crank; {sigma} grows with it at "
                     "every section, so its largest magnitude over the cycle governs: {F} N at crank angle "
                     "$\\varphi$ = {phi}° from position 1 ({Fx} N, {Fy} N; {Mb} N·m there), found exactly (the "
                     "kinetostatics solved at any $\\varphi$ between the resistances' jumps, the samples' local maxima "
                     "refined by Brent's bounded search, each piece's ends taken one-sided; the largest "
                     "sample: {grid} N); taken in the plane and sense of the largest moment (the reducer's "
                     "orientation about the shaft is not in the brief); the bearing life takes its cube mean "
                     "over the cycle, {life} N"),
                 side=f"${side}$", x=_mmf(x, 0).replace("-", "\u2212"),
                 life=_text_num(round(cr.life)), **found)


_KIND_TEXT = {"shaft_bending": N_("bending–torsion"), "bearing_life": N_("bearing life"),
              "bearing_static": N_("bearing statics"), "key_crushing": N_("key crushing"),
              "none": N_("no bearing of that bore")}


def _kinds(ev) -> tuple[str, ...]:
    """The kinds of check that fail (in a fixed order)."""
    bad = {c.key for c in [ev["bend"], ev["life"], ev["static"], *(k.check for k in ev["keys"])]
           if c is not None and not c.passed}
    if ev["bearing"] is None:
        bad.add("none")
    return tuple(k for k in _KIND_TEXT if k in bad)


def _loop_text(log) -> list[dict]:
    """The upsizing steps, runs of the same section merged: from → to, the number of 5 mm /
    standard steps and the checks that failed on the way."""
    runs = [e[0] for n, e in enumerate(log) if n == 0 or log[n - 1][0] != e[0]]
    if any(runs.count(kind) > 2 for kind in ("end", "in")):
        # the end and the journal failing in turn (a heavy overhung load): one line for each,
        # from its first size to its last, in the order they first grew (then the stop)
        order = [kind for n, kind in enumerate(runs) if kind not in runs[:n]]
        log = [e for kind in order for e in log if e[0] == kind]
    out, k = [], 0
    while k < len(log):
        kind = log[k][0]
        j = k
        while j + 1 < len(log) and log[j + 1][0] == kind:
            j += 1
        first, last = log[k], log[j]
        if kind == "top":
            why = Join(Msg.pgettext("list", ", "), [Msg(_KIND_TEXT[x]) for x in last[3]])
            out.append(_step(N_("the journal cannot grow beyond {d} mm, the largest bearing bore of the catalogue: "
                                 "the shaft is not enlarged further and still fails ({why}); the design does "
                                 "not pass as it stands (a stronger material, larger bearings, or the load "
                                 "closer to a bearing)"), d=_mmf(JOURNAL_MAX), why=why))
            k = j + 1
            continue
        kinds = [x for x in _KIND_TEXT if any(x in e[3] for e in log[k:j + 1])]
        why = Join(Msg.pgettext("list", ", "), [Msg(_KIND_TEXT[x]) for x in kinds])
        if kind == "end":
            out.append(_step(N_("overhung end enlarged: {a} → {b} mm (standard sizes; the smaller ones "
                                 "fail: {why})"), a=_mmf(first[1]), b=_mmf(last[2]), why=why))
        else:
            a, b = first[1], last[2]
            out.append(_step(N_("journal/seat enlarged: {a0}/{a1} → {b0}/{b1} mm (in steps of 5 mm; the "
                                 "smaller ones fail: {why})"), a0=_mmf(a[0]), a1=_mmf(a[1]), b0=_mmf(b[0]),
                             b1=_mmf(b[1]), why=why))
        k = j + 1
    return out


#: A shaft section the brief may give, and the fix that asks for at least a diameter.
_AT_LEAST = {"end_mm": N_("give the overhung end at least {d} mm"),
             "journal_mm": N_("give the journal at least {d} mm"),
             "seat_mm": N_("give the seat at least {d} mm")}


def _advice_entry(check: str, field: str, fix: Msg) -> dict:
    """An entry of :attr:`ShaftDesign.advice`: the failing check's key, the brief field and
    the fix as a catalogue message stored as data."""
    return {"check": check, "field": field, "fix": encode(fix)}


def _advice(ch, ev, dims, free_ev, free_dims):
    """For each failing check of an overridden shaft: the field to change and what the design
    would take there, in words (the field is not written in the text)."""
    out = []
    here = f"drive.shafts[{ch.index}]"
    fe, fj, fs = free_dims
    for c in [ev["bend"], ev["life"], ev["static"], *(k.check for k in ev["keys"])]:
        if c is None or c.passed:
            continue
        if c.key == "shaft_bending":
            parts = [(n, v) for n, v, given in (("end_mm", fe, ch.end), ("journal_mm", fj, ch.journal),
                                                ("seat_mm", fs, ch.seat)) if given and v is not None]
            fix = (Join(Msg.pgettext("list", "; "), [Msg(_AT_LEAST[n], d=_mmf(v)) for n, v in parts])
                   if parts else Msg(N_("use a stronger material")))
            field = f"{here}.{parts[0][0]}" if parts else f"{here}.material"
            if parts:
                fix = Msg("{fix}", fix=fix)
        elif c.key in ("bearing_life", "bearing_static"):
            b = free_ev["bearing"]
            field = f"{here}.bearing" if ch.bearing else f"{here}.journal_mm"
            fix = (Msg(N_("give bearing {designation}, the design's choice"), designation=b.designation)
                   if ch.bearing and b else Msg(_AT_LEAST["journal_mm"], d=_mmf(fj)))
        else:
            field = f"{here}.key_length_mm" if ch.key_length else f"{here}.seat_mm"
            fix = (Msg(N_("leave the key length to the design (it takes the longest key the hub "
                          "allows, or two keys)")) if ch.key_length
                   else Msg(_AT_LEAST["seat_mm"], d=_mmf(fs)))
        out.append(_advice_entry(c.key, field, fix))
    return tuple(out)


def _text_num(x: float) -> str:
    """A whole number for running text: five or more digits grouped by threes with a narrow
    no-break space (48 000), as the number rule writes numbers outside formulas."""
    return grouped_digits(f"{x:g}" if abs(x) < 1e5 else f"{x:.0f}")


def _sig(x: float, digits: int) -> str:
    """``digits`` significant digits, digits together (the design steps' formulas): the
    number rule's :func:`mechdesign.numbers.sig`."""
    return sig(x, digits, group=False)


def _peak_times(peak_factor: float, torque: float, printed: str) -> str:
    """"peak/mean × T" with the digits that give the printed peak torque (20.01 × 640.1 gave
    12 808, printed 12 807: a chain's printed factors give its printed result)."""
    return " \\times ".join(factors_for((peak_factor, torque), lambda a, b: a * b, printed))


def _steps(sh, mat, a0, d_min, dims, shoulder, T, peak, peak_factor, lf, ev, span, dp, coupling=None,
           motor=None, flywheel=True, worm=None):
    """The design steps of one shaft, each rule with its formula and numbers (messages as data)."""
    d_end, dj, ds = dims
    P, n = sh.power / 1e3, sh.speed_rpm
    raw = a0 * (P / n) ** (1 / 3)
    dmin = (f"$d_{{min}} = A_0\\sqrt[3]{{P/n}}(1 + 5\\%) = {a0:g}\\sqrt[3]{{{_sig(P, 4)}/{_sig(n, 4)}}} \\times 1.05 = "
            f"{raw * 1.05:.2f}$")
    material = Named("materials.shaft", mat.key)      # named in the report's language
    out = [_step(N_("material {material_en}, {sigma} = {allow} MPa (table 15-1); {dmin} mm (table 15-3, "
                     "+5 % for one keyway)"), material_zh=material, material_en=material,
                  sigma="$[\\sigma_{-1b}]$", allow=f"{mat.sigma_minus1b_allow / 1e6:g}", dmin=dmin)]
    if peak:
        # review39: "after the flywheel" in a drive without one (furnace_pusher)
        out.append(_step(N_("after the flywheel the shaft carries the machine's peak torque: the strength checks "
                             "use {torque} N·m (peak/mean); the bearing life, a fatigue quantity, takes the "
                             "cycle's equivalent load (cube-mean torque = {lf} × the mean), the static strength "
                             "the peak") if flywheel else
                         N_("with no flywheel the shaft carries the machine's peak torque: the strength checks "
                            "use {torque} N·m (peak/mean); the bearing life, a fatigue quantity, takes the "
                            "cycle's equivalent load (cube-mean torque = {lf} × the mean), the static strength "
                            "the peak"),
                          torque=f"$T = {_peak_times(peak_factor, sh.torque, _sig(T, 4))} = {_sig(T, 4)}$",
                          lf=_sig(lf, 3)))
    else:
        out.append(_step(N_("design torque T = 9549 P/n = {T} N·m (bearing life: the same load × $f_p$ = {fp})"),
                          T=_sig(T, 4), fp=f"{FP:g}"))
    if coupling is not None:
        out.append(_coupling_step(coupling, d_min, motor))
    if worm is not None:
        g = worm.geometry
        out.append(_step(N_("the worm is cut integral with the shaft (a worm shaft): no hub and no key; "
                             "between the bearings the section is its root circle {df1} mm, where "
                             "{sigma} is checked; the thread is milled, so the journals may be larger "
                             "than {d}"),
                          df1=(f"$d_{{f1}} = d_1 - 2.4m = {_mmf(g.d1)} - 2.4 \\times {_mmf(g.m)} = "
                               f"{_mmf(ds)}$"), sigma="$\\sigma_{ca}$", d="$d_{f1}$"))
    head, out = out, []
    lay = []
    if d_end is not None and coupling is not None:
        lay.append(Msg(N_("overhung end {d} (the coupling's bore, at least {dmin} and $0.8D$)"), d=_mmf(d_end),
                       dmin="$d_{min}$"))
    elif d_end is not None:
        lay.append(Msg(N_("overhung end {d} (the standard size ≥ {dmin})"), d=_mmf(d_end), dmin="$d_{min}$"))
    if d_end is not None:
        lay.append(Msg(N_("seal section {d} (1.14 × the end, the standard size)"), d=_mmf(ev["seal"])))
    lay += [Msg(N_("journals {d} (bearing bore, a multiple of 5)"), d=_mmf(dj)),
            Msg(N_("worm root circle {d}"), d=_mmf(ds)) if worm is not None else
            Msg(N_("seat {d} (journal + 5)"), d=_mmf(ds)), Msg(N_("collar {d} (h ≈ 0.07 d)"), d=_mmf(shoulder))]
    sections = Join(Msg.pgettext("separator", ", "), lay)
    out.append(_step(N_("result, the sections (mm): {sections}; bearing span {span} mm"), sections=sections,
                      span=_mmf(span, 0)))
    b = ev["bearing"]
    if b is not None:
        conf = "" if cat.bearing_confirmed(b.designation) else \
            Msg(N_(" (rating from the handbook table; to be confirmed in the handbook)"))
        out.append(_step(N_("bearings: at the journal, the lightest series whose life reaches {hours} h → "
                             "{designation}, $C_r$ = {cr} kN, {c0r} = {c0} kN{conf}"),
                          hours=_text_num(dp.service_hours), designation=b.designation, cr=f"{b.Cr / 1e3:g}",
                          c0r="$C_{0r}$", c0=f"{b.C0r / 1e3:g}", conf=conf))
    if ev["keys"]:
        keys = [Msg(N_("{name_en}: d = {d}, key {b}×{h}, hub {hub}, L = {L}, two keys at 180°") if k.count == 2
                    else N_("{name_en}: d = {d}, key {b}×{h}, hub {hub}, L = {L}"),
                    name_zh=_key_part(k), name_en=_key_part(k), d=_mmf(k.d), b=_mmf(k.b), h=_mmf(k.h), hub=_mmf(k.hub, 0), L=_mmf(k.L))
                for k in ev["keys"]]
        listed = Join(Msg.pgettext("list", "; "), keys)
        out.append(_step(N_("keys (GB/T 1096, form A, L ≤ hub − 8 mm; a longer hub up to 1.5 d, then two keys "
                             "when one fails): {keys}"), keys=listed))
    return head, out


def _key_part(k: KeyDesign):
    """The part a key joins, as its check names it ("the pinion of stage 3")."""
    from .findings import decode

    return decode(k.check.name_args["element_en"])


def _coupling_step(c: CouplingChoice, d_min: float, motor) -> dict:
    """The design step of the end joined to the motor: the motor's shaft, the rule, the end
    and the coupling with its torque check, each with its numbers."""
    rule = (f"$d \\ge \\max(d_{{min}}, {c.ratio_min:g}D) = \\max({d_min * 1e3:.2f}, {c.ratio_min:g} \\times "
            f"{_mmf(c.motor_d)}) = {max(d_min, c.ratio_min * c.motor_d) * 1e3:.2f}$")
    DE = _mmf(c.motor_d) + (f" × {_mmf(c.motor_e)}" if c.motor_e else "")
    ka = (Msg(N_("$K_A$ = {KA} (given in the brief)"), KA=f"{c.KA:g}") if c.KA_given
          else Msg(N_("$K_A$ = 1 ($T$ is the cycle's peak torque, which contains the load variations)"))
          if c.peak else Msg(N_("$K_A$ = {KA} (the coupling's working factor, table 14-1, not the "
                                 "gears' application factor)"), KA=f"{c.KA:g}"))
    if c.size is None:
        return _step(N_("the end joins the motor {motor} (shaft extension $D \\times E$ = {DE} mm) through a "
                        "coupling; the course guides take $d \\approx (0.8 \\ldots 1.2) D$ so that one "
                        "coupling has bores for both: {rule} mm; no LT coupling (GB/T 4323) has bores for "
                        "{D} mm and {d} mm: change the end"),
                     motor=getattr(motor, "designation", ""), DE=DE, rule=rule, D=_mmf(c.motor_d),
                     d=_mmf(c.d))
    tc = (f"$T_c = K_A T = {c.KA:g} \\times {_sig(c.torque, 4)} = {_sig(c.Tc, 4)}$ N·m "
          f"{'≤' if c.Tc <= c.Tn * (1 + 1e-12) else '>'} $T_n$ = {c.Tn:g} N·m")
    return _step(N_("the end joins the motor {motor} (shaft extension $D \\times E$ = {DE} mm) through a "
                    "coupling; the course guides take $d \\approx (0.8 \\ldots 1.2) D$ so that one "
                    "coupling has bores for both: {rule} mm → $d$ = {d} mm; elastic sleeve pin coupling "
                    "{size} (GB/T 4323), bores {D} mm (motor) and {d} mm; {ka}, {tc}, $n$ = {n} ≤ $[n]$ = "
                    "{nmax} rpm"),
                 motor=getattr(motor, "designation", ""), DE=DE, rule=rule, d=_mmf(c.d), size=c.size,
                 D=_mmf(c.motor_d), ka=ka, tc=tc, n=f"{c.speed_rpm:g}", nmax=f"{c.n_max:g}")
