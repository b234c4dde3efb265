"""The drive stage (传动装置设计), shared by every machine brief with a ``drive:`` section,
and the stand-alone ``drive`` machine.

Order of the design, as 《机械设计课程设计》 does it: the power the machine needs (from the
computed crank torque where a mechanism exists), the efficiency chain, the motor, the
total ratio and its allocation, whole teeth and standard pulleys, the table of speed,
power and torque on every shaft, then each stage's geometry and strength, the shafts,
bearings and keys, and the check of the machine's speed against the tolerance.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..core import drive as core, gears
from ..core.fields import q
from ..data import load_csv, load_yaml
from . import drive_elements as de, drive_strength as ds
from ..i18n import N_
from .findings import CheckNames, Finding, Msg, Named, check_name, decode, finding


@dataclass(frozen=True)
class StageResult:
    """One stage of the drive: its ratio as allocated and as realised, and its design."""

    index: int = q("1", "stage number from the motor, 0-based (drive.stages[index] of the brief)")
    type: str = q("", "coupling | belt | chain | spur | helical | worm")
    kind: str = q("", "key into transmissions.yaml (open_spur for open gears): its row's name_zh/"
                  "name_en name the stage in the report's language")
    ratio_allocated: float = q("1", "what the allocation asked for (or the fixed ratio)")
    ratio: float = q("1", "the realised ratio i (whole teeth, standard pulleys)")
    fixed: bool = q("", "the brief fixes the ratio")
    efficiency: float = q("1", "η of the stage")
    z1: int | None = q("1", "driving teeth (worm: starts)", default=None)
    z2: int | None = q("1", "driven teeth", default=None)
    d1: float | None = q("m", "small pulley datum diameter", default=None)
    d2: float | None = q("m", "large pulley datum diameter", default=None)
    slip: float = q("1", "belt's elastic slip ε", default=0.0)
    design: ds.StageDesign | None = q("", "geometry, strength design and checks", default=None)

    def name(self, lang) -> str:
        """The stage's name in ``lang`` (zh, en, a variant, or a translator): the row
        ``kind`` of data/transmissions.yaml."""
        return Named("transmissions", self.kind).text(lang)


@dataclass(frozen=True)
class DriveResult:
    """Stage 传动装置设计 (the document is :class:`DriveDocument`)."""

    output_speed_required: float = q("rpm", "n_w")
    machine_power: float = q("W", "P_w at the machine's input shaft")
    power_source: str = q("", "'mechanism' | 'power' | 'torque' | 'stroke'")
    efficiency: float = q("1", "η of the whole chain")
    power_required: float = q("W", "P_d = P_w / η")
    choice: core.MotorChoice = q("", "the motor and the candidates")
    stages: tuple[StageResult, ...] = q("", "from the motor to the machine")
    shafts: tuple[core.ShaftState, ...] = q("", "speed, power, torque of every shaft")
    output_speed: float = q("rpm", "realised machine speed n_w′")
    speed_error: float = q("1", "(n_w′ − n_w)/n_w")
    speed_tolerance: float = q("1", "allowed |speed error|")
    service_hours: float = q("h", "service life L_h")
    KA: float = q("1", "application factor K_A")
    bearing_eff: float = q("1", "η of one pair of rolling bearings")
    machine_eff: float = q("1", "η of the machine's input")
    peak_factor: float = q("1", "design torque / mean torque downstream of the flywheel")
    peak_from_shaft: int | None = q("1", "first shaft carrying the peak torque (None: none)")
    warnings: tuple[Finding, ...] = q("", "speed error, stage ratios, undercut, failed checks")
    shaft_designs: tuple[ds.ShaftDesign, ...] = q("", "one per shaft after the motor")
    data_assumptions: tuple[str, ...] = q("", "the unconfirmed catalogue entries the design used "
                                          "(see data_assumptions())", default=())

    @property
    def motor(self) -> core.Motor:
        return self.choice.motor


@dataclass(frozen=True)
class DriveDocument:
    """The drive (传动装置) as results.json holds it: the power and efficiency chain, the
    motor and its choice, the stages with their designs, the table of speed, power and
    torque on every shaft (shaft 0 is the motor's), and the shafts' designs."""

    output_speed_required_rpm: float = q("rpm", "n_w the machine needs")
    machine_power: float = q("W", "P_w at the machine's input shaft")
    power_source: str = q("", "where P_w comes from: 'mechanism' (the computed crank torque), "
                          "'power', 'torque' or 'stroke' (the brief's load)")
    efficiency: float = q("1", "η of the whole chain")
    power_required: float = q("W", "P_d = P_w / η")
    motor: core.Motor = q("", "the motor chosen")
    total_ratio: float = q("1", "i = n_m / n_w")
    motor_choice: str = q("", "'given' (the brief's synchronous speed), 'recommended' or 'maximum' "
                          "(the ratio ranges that admitted it)")
    motor_candidates: tuple[core.MotorCandidate, ...] = q("", "one per synchronous speed tried")
    stages: tuple[StageResult, ...] = q("", "from the motor to the machine")
    shafts: tuple[core.ShaftState, ...] = q("", "speed, power, torque of every shaft, 0 = motor")
    output_speed_rpm: float = q("rpm", "realised machine speed n_w′")
    speed_error: float = q("1", "(n_w′ − n_w)/n_w")
    speed_tolerance: float = q("1", "allowed |speed error|")
    service_hours: float = q("h", "service life L_h")
    peak_factor: float = q("1", "design torque / mean torque on the shafts that carry the peak")
    shaft_designs: tuple[ds.ShaftDesign, ...] = q("", "one per shaft after the motor")
    warnings: tuple[Finding, ...] = q("", "findings: speed error, stage ratios, undercut, failed checks")
    data_assumptions: tuple[str, ...] = q("", "catalogue entries the design used that could not be "
                                          "confirmed against a public copy of their source: 'kind' "
                                          "or 'kind:key' (e.g. 'bearing:6219', 'gear_material:HT300')",
                                          default=())


def motor_catalogue() -> list[core.Motor]:
    """The Y-series motors of data/motors.csv (SI); a row whose number cannot be read is a
    :class:`~mechdesign.core.drive.DriveDesignError` naming the row, the column and the value."""
    out = []
    for r in load_csv("motors.csv"):
        def num(col, scale=1.0, r=r):
            raw = r.get(col)
            try:
                v = float(raw)
            except (TypeError, ValueError):
                v = float("nan")
            if not (np.isfinite(v) and v > 0):
                raise core.DriveDesignError(Msg(
                    N_("the motor catalogue (data/motors.csv) row {row}: column {col} is '{value}', "
                       "not a positive number; correct the data file"),
                    row=r.get("designation", "?"), col=col, value=raw))
            return v * scale
        out.append(core.Motor(r["designation"], num("power_kW", 1e3), num("synchronous_rpm"),
                              num("full_load_rpm"), num("frame_height_mm", 1e-3), num("Tst_Tn"),
                              num("Tmax_Tn"), num("shaft_D_mm", 1e-3), num("shaft_E_mm", 1e-3)))
    return out


def _kind(s) -> str:
    return "open_spur" if s.type == "spur" and s.open else s.type


# Worm efficiency before the geometry is known, by starts (textbook table 11-7 midpoints).
_WORM_EFF_BY_STARTS = {1: 0.72, 2: 0.80, 4: 0.87, 6: 0.90}


def _fixed_ratio(s) -> float | None:
    if s.type == "coupling":
        return 1.0
    if s.ratio is not None:
        return s.ratio
    if s.z1 is not None and s.z2 is not None:
        return s.z2 / s.z1
    if s.d1 is not None and s.d2 is not None:
        return core.belt_ratio(s.d1, s.d2, s.slip)
    return None


def _elements(stages, worm_eff: dict[int, float]) -> list[core.Element]:
    table = load_yaml("transmissions.yaml")
    out = []
    for s in stages:
        row = table[_kind(s)]
        eff = s.efficiency if s.efficiency is not None else worm_eff.get(s.index, row["efficiency"])
        out.append(core.Element(_kind(s), eff, tuple(row["ratio_recommended"]), row["ratio_max"],
                                _fixed_ratio(s)))
    return out


def _realise(s, target: float, d1_default: float = 0.100) -> dict:
    """Whole teeth / a standard pulley for a free stage aiming at ``target``."""
    if s.type == "belt":
        d1 = s.d1 if s.d1 is not None else d1_default
        d2 = s.d2 if s.d2 is not None else core.standard_pulley(target * d1 * (1 - s.slip) * 1e3) * 1e-3
        return {"d1": d1, "d2": d2, "slip": s.slip, "ratio": core.belt_ratio(d1, d2, s.slip)}
    if s.type == "coupling":
        return {"ratio": 1.0}
    if s.type == "worm":
        z1 = s.z1 if s.z1 is not None else core.worm_starts(target)
    elif s.type == "chain":
        z1 = s.z1 if s.z1 is not None else max(17, int(round(29 - 2 * target)) | 1)   # odd, z1 = 29 − 2i
    else:
        z1 = s.z1 if s.z1 is not None else (20 if s.open else 24)
    z2 = s.z2 if s.z2 is not None else max(int(round(target * z1)), z1)
    return {"z1": z1, "z2": z2, "ratio": z2 / z1}


def design_ratios(stages, elements, total: float, belt_d1: dict | None = None) -> list[dict]:
    """Allocate ``total`` and realise the stages in order; each free stage aims at what is
    left after the stages already realised, so rounding errors do not add up. ``belt_d1``:
    small datum diameters by stage index where the belt's section needs more than 100 mm."""
    alloc = core.allocate_ratios(total, elements)
    done, out = 1.0, []
    for k, (s, el) in enumerate(zip(stages, elements)):
        ahead = float(np.prod(alloc[k + 1:]))
        target = el.ratio if el.ratio is not None else total / done / ahead
        real = _realise(s, target, (belt_d1 or {}).get(s.index, 0.100))
        real["allocated"] = alloc[k]
        done *= real["ratio"]
        out.append(real)
    return out


def design_drive(dp, machine_power: float, output_rpm: float, source: str,
                 peak_factor: float = 1.0, peak_from_shaft: int | None = None,
                 life_factor: float | None = None,
                 weights=None, crank=None) -> DriveResult:
    """The whole drive for a machine needing ``machine_power`` [W] at ``output_rpm``.
    ``peak_factor``: the machine's peak torque / its mean, carried by the shafts from
    ``peak_from_shaft`` on (after the flywheel; None: none); ``life_factor``: the cycle's
    cube-mean torque / its mean, the equivalent load of the bearing life there (None: the
    mean); ``weights``: {shaft: (weight [N], width [m])} of a heavy part that carries no
    drive stage (a flywheel), a vertical load between that shaft's bearings, or a function
    of the shaft table (:func:`core.shaft_table`'s rows) giving it (a flywheel sized at the
    speed the drive realises on its shaft: the motor, the ratios and the shaft table do not
    depend on the weights); ``crank``: {shaft: CrankLoad}, the crank's largest load on the
    shaft that carries it (:mod:`.crank_load`)."""
    # A machine without working resistance takes (almost) no mean power: its torque only
    # swings about zero, the peak factor peak/mean is unbounded and nothing sizes the drive.
    if not (machine_power > 0 and np.isfinite(machine_power) and 0 < peak_factor < 1e6):
        raise core.DriveDesignError(Msg(
            N_("the machine takes (almost) no mean power ({P:.3g} W at its input shaft, peak "
               "torque {peak:.3g} × the mean): without working resistance nothing sizes the drive; "
               "give the machine a load, or leave the drive section out"),
            P=machine_power, peak=peak_factor))
    catalogue = motor_catalogue()
    stages = dp.stages
    worm_eff = {s.index: _WORM_EFF_BY_STARTS.get(s.z1 or 2, 0.8) for s in stages
                if s.type == "worm" and s.efficiency is None}
    for _ in range(4):    # the worm's efficiency follows from its geometry: iterate
        elements = _elements(stages, worm_eff)
        eta = core.chain_efficiency([el.efficiency for el in elements], dp.bearing_eff, dp.machine_eff)
        p_d = machine_power / eta
        choice = core.choose_motor(catalogue, p_d, output_rpm, elements, dp.synchronous_rpm,
                                    dp.speed_tolerance)
        belt_d1: dict[int, float] = {}
        for _pass in range(2):   # a belt whose section needs d_dmin > 100 mm: once more with it
            real = design_ratios(stages, elements, choice.total_ratio, belt_d1)
            ratios = [r["ratio"] for r in real]
            shafts = core.shaft_table(choice.motor.full_load_rpm, p_d, ratios,
                                      [el.efficiency for el in elements], dp.bearing_eff)
            need = {s.index: de.belt_small_diameter(s, shafts[k].power, shafts[k].speed_rpm, de.belt_KA(s, dp))
                    for k, s in enumerate(stages) if s.type == "belt" and s.d1 is None}
            need = {i: d for i, d in need.items() if d != 0.100}
            if need == belt_d1:
                break
            belt_d1 = need
        results = []
        for s, el, r in zip(stages, elements, real):
            results.append(StageResult(
                s.index, s.type, el.kind, r["allocated"], r["ratio"], el.ratio is not None,
                el.efficiency, r.get("z1"), r.get("z2"), r.get("d1"), r.get("d2"), r.get("slip", 0.0)))
        results, new_eff = _strength(dp, results, shafts, peak_factor, peak_from_shaft)
        changed = {k: v for k, v in new_eff.items() if abs(v - worm_eff.get(k, v)) > 1e-4}
        if not changed:
            break
        worm_eff.update(changed)
    if callable(weights):
        weights = weights(shafts)
    shaft_designs = _shafts(dp, results, shafts, peak_factor, peak_from_shaft, life_factor, weights,
                            choice.motor, crank)
    n_out = shafts[-1].speed_rpm
    error = (n_out - output_rpm) / output_rpm
    warnings = []
    if abs(error) > dp.speed_tolerance:
        warnings.append(finding(
            "speed_error",
            N_("the machine's speed error {err:+.2f}% exceeds ±{tol:g}%: change the teeth or "
               "pulley diameters."), err=error * 100, tol=dp.speed_tolerance * 100))
    for st, el in zip(results, elements):
        lo, hi = el.recommended
        if st.type != "coupling" and st.ratio > el.ratio_max:
            warnings.append(finding(
                "stage_ratio",
                N_("stage {n} ({name}) ratio {i:.3f} exceeds its maximum {imax:g}: give it a "
                   "smaller ratio (another stage, or more ratio to the others)."),
                field=f"drive.stages[{st.index}]", n=st.index + 1,
                name=Named("transmissions", st.kind), i=st.ratio, imax=el.ratio_max))
        elif st.type != "coupling" and st.ratio < lo:
            warnings.append(finding(
                "stage_ratio",
                N_("stage {n} ({name}) ratio {i:.3f} is below its recommended range {lo:g}–{hi:g}: "
                   "it hardly reduces the speed; give it a larger ratio or leave the stage out."),
                field=f"drive.stages[{st.index}]", n=st.index + 1,
                name=Named("transmissions", st.kind), i=st.ratio, lo=lo, hi=hi))
        elif st.type != "coupling" and st.ratio > hi * (1 + 1e-9):
            # allowed (within the maximum), yet the drive chapter says it is beyond the
            # recommended range: the summary names it (page review 41, the slotter's belt 5.06)
            warnings.append(finding(
                "stage_ratio",
                N_("stage {n} ({name}) ratio {i:.3f} is beyond its recommended range {lo:g}–{hi:g}, "
                   "within its maximum {imax:g}: the stage is larger than usual; the drive chapter "
                   "says why this motor was chosen."),
                field=f"drive.stages[{st.index}]", n=st.index + 1,
                name=Named("transmissions", st.kind), i=st.ratio, lo=lo, hi=hi, imax=el.ratio_max))
    warnings.extend(undercut_findings(results))
    warnings.extend(tooth_findings(results))
    return DriveResult(output_rpm, machine_power, source, eta, p_d, choice, tuple(results),
                       tuple(shafts), n_out, error, dp.speed_tolerance, dp.service_hours, dp.KA,
                       dp.bearing_eff, dp.machine_eff, peak_factor, peak_from_shaft,
                       tuple(warnings) + _strength_warnings(results, shaft_designs), shaft_designs,
                       data_assumptions(choice.motor, results, shaft_designs))


def data_assumptions(motor, stages, shaft_designs) -> tuple[str, ...]:
    """The catalogue entries this drive used that could not be confirmed against a public copy
    of their source (each data file's ``unconfirmed`` list, bearings.yaml's and motors.csv's
    ``confirmed``), in the order the design uses them: 'motor:<designation>', 'ratio_ranges',
    'belt_chart' (section from the chart), 'chain_rating', 'chain_table' (q, Q: static
    safety), 'gear_material:<key>', 'worm_wheel:<key>', 'worm_Zrho' (the fitted Z_ρ curve),
    'shaft_A0', 'shaft_series', 'shaft_material:<key>', 'bearing:<designation>',
    'key_lengths', 'key_cast_iron'; where a coupling joins the motor: 'motor_shaft:<designation>'
    (the frame's shaft extension), 'coupling_table' (the LT sizes), 'coupling_KA' (table 14-1)."""
    from ..data import catalogues as cat

    out: list[str] = []

    def add(code):
        if code not in out:
            out.append(code)

    mats, belts_u, chains_u = cat.unconfirmed("materials.yaml"), cat.unconfirmed("belts.yaml"), \
        cat.unconfirmed("chains.yaml")
    if motor is not None and not cat.motor_confirmed(motor.designation):
        add(f"motor:{motor.designation}")
    if {"ratio_recommended", "ratio_max"} & cat.unconfirmed("transmissions.yaml"):
        add("ratio_ranges")
    for st in stages:
        d = st.design
        if d is None:
            continue
        g = d.geometry
        if d.kind == "belt" and g is not None and not g.section_given and "selection_chart" in belts_u:
            add("belt_chart")
        elif d.kind == "chain" and g is not None:
            if "rated_power_formula" in chains_u:
                add("chain_rating")
            if g.S is not None and "chains.q_Q" in chains_u:
                add("chain_table")
        elif d.kind == "gear":
            for m in d.materials:
                if f"gear.{m}" in mats:
                    add(f"gear_material:{m}")
        elif d.kind == "worm":
            # the wheel's allowable stresses govern (the worm's material enters only through the
            # wheel tables' "worm flank > 45 HRC" column)
            for m in d.materials[1:]:
                if f"worm_wheel.{m}" in mats:
                    add(f"worm_wheel:{m}")
            add("worm_Zrho")
    for sd in shaft_designs:
        c = getattr(sd, "coupling", None)
        if c is None:
            continue
        if motor is not None and not cat.motor_shaft_confirmed(motor.frame_height):
            add(f"motor_shaft:{motor.designation}")
        if c.size is not None and "LT" in cat.unconfirmed("couplings.yaml"):
            add("coupling_table")
        if not (c.KA_given or c.peak) and "application_factor" in cat.unconfirmed("couplings.yaml"):
            add("coupling_KA")
    keys_u = cat.unconfirmed("keys.yaml")
    steel_lo, _hi = cat.key_allowable_stress("steel", "light_shock")
    for sd in shaft_designs:
        if "shaft.A0_tauT" in mats:
            add("shaft_A0")
        if "shaft_diameter_series_mm" in mats:
            add("shaft_series")
        if f"shaft.{sd.material}.allowable_bending" in mats:
            add(f"shaft_material:{sd.material}")
        if sd.bearing is not None and not cat.bearing_confirmed(sd.bearing.designation):
            add(f"bearing:{sd.bearing.designation}")
        if sd.keys and "L_range" in keys_u:
            add("key_lengths")
        if any(k.check.allowable < steel_lo for k in sd.keys) and "allowable_crushing_MPa.cast_iron" in keys_u:
            add("key_cast_iron")
    return tuple(out)


def resized(drive: DriveResult, dp, peak_factor: float, peak_from_shaft: int | None,
            life_factor: float | None = None,
            weights: dict[int, tuple[float, float]] | None = None, crank=None) -> tuple[tuple, tuple] | None:
    """The stages and shaft designs of ``drive`` sized again for another peak assignment
    (another flywheel placement: the shafts from ``peak_from_shaft`` on carry the peak):
    the motor, the realised ratios and the shaft table do not depend on it and are reused;
    only the geometry and strength of the stages and the shafts are designed again, as
    :func:`design_drive` designs them. None when a worm's efficiency, which follows from
    its geometry, would move (then the whole drive must be designed again)."""
    bare = [replace(st, design=None) for st in drive.stages]
    results, worm_eff = _strength(dp, bare, drive.shafts, peak_factor, peak_from_shaft)
    if any(abs(v - drive.stages[k].efficiency) > 1e-4 for k, v in worm_eff.items()):
        return None
    return tuple(results), tuple(_shafts(dp, results, drive.shafts, peak_factor, peak_from_shaft,
                                         life_factor, weights, drive.motor, crank))


def _strength(dp, results, shafts, peak_factor, peak_from_shaft):
    """Geometry and strength of each stage (see :mod:`.drive_strength`)."""
    designs, worm_eff = ds.stage_designs(dp, results, shafts, peak_factor, peak_from_shaft)
    results = [replace(r, design=d) for r, d in zip(results, designs)]
    return results, worm_eff


def _shafts(dp, results, shafts, peak_factor, peak_from_shaft, life_factor=None, weights=None,
            motor=None, crank=None):
    kinds = [r.kind for r in results]
    return ds.shaft_designs(dp, [r.design for r in results], shafts, peak_factor, peak_from_shaft, kinds,
                            life_factor, weights, motor, crank)


def undercut_findings(results) -> list[Finding]:
    """Undercut gear stages (根切): a spur pinion or wheel below z_min (2h_a*/sin²α rounded,
    孙桓: 17 at α = 20°, core.gears.least_teeth) with a shift x below
    x_min = h_a*(z_min − z)/z_min, a helical one whose equivalent tooth number z/cos³β is
    below z_min (the drive's helical gears are not shifted)."""
    import math

    out = []
    for r in results:
        d = r.design
        if d is None or d.kind != "gear" or d.geometry is None:
            continue
        here = f"drive.stages[{r.index}]"
        g = d.geometry
        if hasattr(g, "x_min1"):
            for gd, x_min, key in ((g.g1, g.x_min1, "1"), (g.g2, g.x_min2, "2")):
                if gd.x < x_min - 1e-9:
                    # the limits in words, no brief field in the text: the finding's field
                    # (the terminal prints it after the text)
                    out.append(finding(
                        "undercut",
                        N_("stage {n} ({name}): the {who} (z = {z}) is undercut: it has fewer teeth "
                           "than the least number without undercut, {z_min:g}, and its shift x = "
                           "{x:g} is below the least shift {x_min:.3f}; use a positive shift x ≥ "
                           "{x_min:.3f} or at least {need} teeth."), field=f"{here}.x{key}",
                        n=r.index + 1, name=Named("transmissions", r.kind), who=_gear(key), z=gd.z,
                        z_min=g.z_min, x=gd.x, x_min=x_min, need=math.ceil(g.z_min - 1e-9)))
        elif hasattr(g, "beta"):
            z_min = gears.least_teeth(math.radians(20.0), 1.0)
            for key, z in (("1", r.z1), ("2", r.z2)):
                if z is None:
                    continue
                zv = z / math.cos(g.beta) ** 3
                if zv < z_min - 1e-9:
                    need = math.ceil(z_min * math.cos(g.beta) ** 3 - 1e-9)
                    out.append(finding(
                        "undercut",
                        N_("stage {n} ({name}): the {who} (z = {z}) is undercut: its equivalent tooth "
                           "number z_v = z/cos³β = {zv:.2f} is below the least number without "
                           "undercut, {z_min:g}; give it at least {need} teeth or use a larger "
                           "helix angle."), field=f"{here}.z{key}",
                        n=r.index + 1, name=Named("transmissions", r.kind), who=_gear(key), z=z,
                        zv=zv, z_min=z_min, need=need))
    return out


def tooth_findings(results) -> list[Finding]:
    """Spur stages whose teeth cannot be cut as given: a tip thickness s_a ≤ 0 (the flanks
    meet below the tip circle) is an error (:class:`~mechdesign.core.drive.DriveDesignError`),
    s_a < 0.25 m a pointed tooth, a negative dedendum h_f = (h_a* + c* − x)·m < 0 (the root
    circle outside the pitch circle) a named warning, each at the stage's field."""
    from ..core.drive import DriveDesignError
    from .gear import MIN_TIP_THICKNESS

    out = []
    for r in results:
        d = r.design
        if d is None or d.kind != "gear" or d.geometry is None or not hasattr(d.geometry, "x_min1"):
            continue
        here = f"drive.stages[{r.index}]"
        g = d.geometry
        for key, gd in (("1", g.g1), ("2", g.g2)):
            head = Msg(N_("stage {n} ({name}): the {who} (z{key} = {z}, x{key} = {x:g})"),
                       n=r.index + 1, name=Named("transmissions", r.kind), who=_gear(key), key=key,
                       z=gd.z, x=gd.x)
            # the fix in words; the brief field is the finding's (the error names it first)
            fix, fld = ((Msg(N_("reduce its shift")), f"{here}.x{key}") if gd.x > 0
                        else (Msg(N_("use more teeth")), f"{here}.z{key}"))
            if gd.sa <= 0:
                raise DriveDesignError(Msg(
                    N_("{here}.x{key} = {x:g}: {head} has a tip thickness s_a = {sa:.2f} mm ≤ 0: its "
                       "flanks meet below the tip circle, the tooth cannot be cut; {fix}"),
                    here=here, key=key, x=gd.x, head=head, sa=gd.sa * 1e3, fix=fix))
            if gd.sa < MIN_TIP_THICKNESS * g.m:
                out.append(finding(
                    "pointed",
                    N_("{head} has a tip thickness s_a = {sa:.3g} mm < 0.25 m = {least:.2f} mm "
                       "(pointed tooth); {fix}."), field=fld, head=head, sa=gd.sa * 1e3,
                    least=0.25 * g.m * 1e3, fix=fix))
            if gd.hf < 0:
                out.append(finding(
                    "dedendum",
                    N_("{head} has a negative dedendum h_f = (h_a* + c* − x)·m = {hf:.2f} mm: its "
                       "root circle lies outside the pitch circle; reduce its shift."),
                    field=f"{here}.x{key}", head=head, hf=gd.hf * 1e3))
    return out


def _strength_warnings(results, shaft_designs) -> tuple[Finding, ...]:
    out = []
    for r in results:
        for c in r.design.checks if r.design else ():
            if not c.passed:
                out.append(_failed(c, _stage(r), stage=r.index, stage_type=r.type))
    for s in shaft_designs:
        name = shaft_numeral(s.index)
        advice = {a["check"]: a for a in s.advice}
        for c in s.checks:
            if not c.passed:
                out.append(_failed(c, Msg(N_("shaft {name}"), name=name), advice.get(c.key)))
    return tuple(out)


_NUMERALS = "0 Ⅰ Ⅱ Ⅲ Ⅳ Ⅴ Ⅵ Ⅶ Ⅷ Ⅸ".split()


def shaft_numeral(index: int) -> str:
    """The drive's shaft number as tables, warnings and sheets write it: 0 (the motor's), Ⅰ, Ⅱ, …"""
    return _NUMERALS[index] if index < len(_NUMERALS) else str(index)


def _stage(r) -> Msg:
    """"stage 2 (V belt)": a drive stage as findings and self-checks name it."""
    return Msg(N_("stage {n} ({name})"), n=r.index + 1, name=Named("transmissions", r.kind))


def _gear(key: str) -> Msg:
    """The pinion (key "1") or the wheel of a gear stage, by name."""
    return Msg.pgettext("gear", "pinion") if key == "1" else Msg.pgettext("gear", "wheel")


#: The remedy of a failed shaft, bearing or key check, by the check's key (None: any other).
_GENERIC_FIX = {
    "shaft_bending": N_("a larger diameter or a stronger shaft material"),
    "bearing_life": N_("a bearing of a heavier series or a larger bore, or the load nearer the bearings"),
    "bearing_static": N_("a bearing of a heavier series or a larger bore, or the load nearer the bearings"),
    "key_crushing": N_("a longer hub, two keys or a larger diameter"),
    None: N_("enlarge it or use a better material"),
}


def _failed(c, where: Msg, advice=None, stage: int | None = None, stage_type: str = "") -> Finding:
    """A failed check of the drive stage or shaft ``where`` as a named finding; ``advice``:
    an entry of :attr:`~.drive_strength.ShaftDesign.advice` ({check, field, fix}: the
    override that fails and what to change, as a catalogue message); ``stage``: the drive
    stage whose check it is (belts, gear geometry and the worm's deflection name their own
    fix); else the generic advice. The text names no brief field: the finding's ``field``
    does (the terminal prints it after the text)."""
    from ..core.strength import COURSE_SCALE

    v, a = c.value * COURSE_SCALE[c.unit], c.allowable * COURSE_SCALE[c.unit]
    v, a = _sig4(v), _sig4(a)
    rel = ">" if c.sense == "le" else "<"
    unit = "" if c.unit == "1" else f" {c.unit}"
    if advice is not None:
        return finding("strength",
                       N_("{where}: {check} fails ({v} {rel} {a}{unit}) with the size the brief "
                          "gives: {advice}."), field=advice["field"], where=where,
                       check=check_name(c), v=v, rel=rel, a=a, unit=unit,
                       advice=decode(advice["fix"]))
    # the remedy of the check that fails (a better material does not lengthen a bearing's
    # life: review of session 41)
    fix = Msg(_GENERIC_FIX.get(c.key, _GENERIC_FIX[None]))
    extra = {}
    if stage is not None and c.key in de.FIXES:      # belts, gear geometry, worm deflection
        fixes = de.FIXES[c.key]
        msgid, name = fixes.get(stage_type, next(iter(fixes.values()))) if isinstance(fixes, dict) else fixes
        fix = Msg(msgid)
        extra = {"field": f"drive.stages[{stage}]" + (f".{name}" if name else "")}
    return finding("strength", N_("{where}: {check} fails ({v} {rel} {a}{unit}): {fix}."),
                   where=where, check=check_name(c), v=v, rel=rel, a=a, unit=unit,
                   fix=fix, **extra)


def _sig4(x: float) -> str:
    """4 significant digits, the number rule's (:func:`mechdesign.numbers.sig`) for forces,
    stresses and lives, without its digit grouping: a finding is also a terminal line."""
    from ..numbers import sig

    return sig(x, 4, group=False)


# ------------------------------------------------------------------------------------
# Self-checks (计算校核)

DRIVE_CHECK_NAMES = CheckNames({
    "shaft_speed": N_("shaft speeds $n_{k+1} = n_k / i_k$ (relative error)"),
    "shaft_power": N_("shaft powers $P_{k+1} = P_k\\eta_k\\eta_b$ (relative error)"),
    "shaft_torque": N_("shaft torques T = 9549.3 P/n (relative error)"),
    "power_balance": N_("power balance $P_{last}\\eta_b\\eta_w = P_w$ (relative error)"),
    "ratio_product": N_("product of the stage ratios $\\prod i_k$ vs $n_m / n_w'$ (relative error)"),
    "stage_ratio": N_("stage ratios vs teeth and pulley ratios (relative error)"),
    "speed_error": N_("machine speed error $(n_w' - n_w) / n_w$"),
    "motor_power": N_("motor rating margin $1 - P_d / P_{ed}$"),
    "margin": N_("strength margin 1 − utilisation (smallest)"),
    "verdicts": N_("strength verdicts that disagree with their margin"),
    "reactions": N_("bearing reactions $\\Sigma F = 0$, $\\Sigma M_B = 0$ (relative residual)"),
})

DRIVE_REL_LIMIT = 1e-9


@dataclass(frozen=True)
class DriveVerification:
    checks: tuple
    warnings: tuple[Finding, ...] = ()


def _rel_err(value, reference) -> float:
    value, reference = np.asarray(value, dtype=float), np.asarray(reference, dtype=float)
    if value.size == 0:
        return 0.0
    return float(np.max(np.abs(value - reference) / np.maximum(np.abs(reference), 1e-300)))


def _margin(c) -> float:
    """1 − utilisation, recomputed from the check's value and allowable (≥ 0 passes)."""
    if c.sense == "le":
        return 1.0 - c.value / c.allowable
    return 1.0 - c.allowable / c.value


def verify_drive(d: DriveResult) -> DriveVerification:
    """The drive recomputed by its definitions: the shaft table stage by stage (n_{k+1} =
    n_k/i_k, P_{k+1} = P_k·η_k·η_b with no bearing loss charged to the motor shaft, T = P/ω),
    the power delivered against the machine's need, the ratios against the teeth, the speed
    error against the tolerance, every strength check's margin and every shaft's statics."""
    from .cam import SelfCheck, failed_findings

    sh = d.shafts
    ratios = np.array([st.ratio for st in d.stages])
    etas = np.array([st.efficiency for st in d.stages])
    n = np.array([s.speed_rpm for s in sh])
    P = np.array([s.power for s in sh])
    T = np.array([s.torque for s in sh])
    bearing = np.array([1.0] + [d.bearing_eff] * (len(d.stages) - 1))
    checks = [
        SelfCheck("shaft_speed", _rel_err(n[1:], n[:-1] / ratios), DRIVE_REL_LIMIT),
        SelfCheck("shaft_power", _rel_err(np.concatenate([[P[0]], P[1:]]),
                                          np.concatenate([[d.power_required], P[:-1] * etas * bearing])),
                  DRIVE_REL_LIMIT),
        SelfCheck("shaft_torque", _rel_err(T, 30000.0 / np.pi * (P / 1e3) / n), DRIVE_REL_LIMIT),
        SelfCheck("power_balance", _rel_err(P[-1] * d.bearing_eff * d.machine_eff, d.machine_power),
                  DRIVE_REL_LIMIT, reference=d.machine_power),
        SelfCheck("ratio_product", _rel_err(np.prod(ratios), n[0] / n[-1]), DRIVE_REL_LIMIT,
                  reference=float(n[0] / n[-1]), detail={"product": float(np.prod(ratios))}),
    ]
    geo_ratio, real_ratio = [], []
    for st in d.stages:
        if st.type == "coupling":
            geo_ratio.append(1.0)
        elif st.z1 is not None and st.z2 is not None:
            geo_ratio.append(st.z2 / st.z1)
        elif st.d1 is not None and st.d2 is not None:
            geo_ratio.append(st.d2 / (st.d1 * (1.0 - st.slip)))
        else:
            continue
        real_ratio.append(st.ratio)
    checks.append(SelfCheck("stage_ratio", _rel_err(real_ratio, geo_ratio), DRIVE_REL_LIMIT,
                            detail={"stages": len(real_ratio)}))
    err = abs(n[-1] - d.output_speed_required) / d.output_speed_required
    signed = float((n[-1] - d.output_speed_required) / d.output_speed_required)
    checks.append(SelfCheck("speed_error", float(err), d.speed_tolerance, reference=d.speed_tolerance,
                            detail={"signed": signed}, requirement=True))
    checks.append(SelfCheck("motor_power", 1.0 - d.power_required / d.motor.power, 0.0, sense="ge",
                            requirement=True, detail={"rated": d.motor.power, "required": d.power_required}))
    mismatches = 0
    groups = [({"stage": st.index}, st.design.checks if st.design else ()) for st in d.stages]
    groups += [({"shaft": s.index}, s.checks) for s in d.shaft_designs]
    for which, cs in groups:
        if not cs:
            continue
        margins = [_margin(c) for c in cs]
        k = int(np.argmin(margins))
        mismatches += sum(1 for c, m in zip(cs, margins) if c.passed != (m >= 0))
        checks.append(SelfCheck("margin", float(margins[k]), 0.0, sense="ge", requirement=True,
                                detail={**which, "checks": len(cs), "check": cs[k].name,
                                        "check_args": dict(cs[k].name_args)}))
    checks.append(SelfCheck("verdicts", float(mismatches), 0.0))
    for s in d.shaft_designs:
        checks.append(SelfCheck("reactions", _statics_residual(s), DRIVE_REL_LIMIT,
                                detail={"shaft": s.index}))
    return DriveVerification(tuple(checks), tuple(failed_findings(checks, DRIVE_CHECK_NAMES)))


def _statics_residual(s) -> float:
    """max(|ΣF|/ΣF_abs, |ΣM_B|/(ΣF_abs·L)) in both planes for the loads and the bearing
    reactions (A at x = 0, B at the span; the axial force at radius r adds the couple −r·F_a
    in the vertical plane), moments taken about bearing B."""
    res = s.result
    L = s.span
    xs = np.array([p.x for p in s.loads] + [0.0, L])
    Fh = np.array([p.Fh for p in s.loads] + [res.RAh, res.RBh])
    Fv = np.array([p.Fv for p in s.loads] + [res.RAv, res.RBv])
    couple = np.array([-p.r * p.Fa for p in s.loads] + [0.0, 0.0])
    scale = float(np.sum(np.abs(Fh)) + np.sum(np.abs(Fv)) + np.sum(np.abs(couple)) / L)
    if scale == 0:
        return 0.0
    sums = [abs(np.sum(Fh)) / scale, abs(np.sum(Fv)) / scale,
            abs(np.sum((xs - L) * Fh)) / (scale * L), abs(np.sum((xs - L) * Fv + couple)) / (scale * L)]
    return float(max(sums))


# ------------------------------------------------------------------------------------
# The stand-alone drive machine


def drive_document(d: DriveResult) -> DriveDocument:
    return DriveDocument(
        output_speed_required_rpm=d.output_speed_required, machine_power=d.machine_power,
        power_source=d.power_source, efficiency=d.efficiency, power_required=d.power_required,
        motor=d.motor, total_ratio=d.choice.total_ratio, motor_choice=d.choice.reason,
        motor_candidates=d.choice.candidates, stages=d.stages, shafts=d.shafts,
        output_speed_rpm=d.output_speed, speed_error=d.speed_error,
        speed_tolerance=d.speed_tolerance, service_hours=d.service_hours,
        peak_factor=d.peak_factor, shaft_designs=d.shaft_designs,
        warnings=tuple(d.warnings), data_assumptions=d.data_assumptions)


