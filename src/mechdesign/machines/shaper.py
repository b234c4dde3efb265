"""Shaper (牛头刨床): crank + RPR dyad (guide bar) + RRP dyad (ram), composed from shared stages.

Coordinates: O3 (guide-bar pivot) at the origin, O2 (crank pivot) at (0, L_O2O3) above
it, the ram guide horizontal at y = L_O3M. Links: 2 crank O2A, 3 slider at A, 4 guide
bar O3B, 5 rod BF, 6 ram, 7 frame (the course's numbering).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..brief.shaper import ShaperParams
from ..core import flywheel as fw
from ..core.kinetostatics import Body, PointLoad, power_residual, solve_forces
from ..core.mechanism import RPR, RRP, AssemblyError, Crank, LinkPoint, Mechanism
from ..core.synthesis import GuideBarDesign, guide_bar_quick_return
from ..pipeline import Stage
from .cam import cam_document
from .drive import drive_document
from .gear import gear_document
from .positions import Positions, textbook_positions

FRAME = "7"


@dataclass(frozen=True)
class Synthesis:
    """Stage 导杆机构设计: the link lengths [m] and angles [rad]."""

    design: GuideBarDesign
    extreme_angle: float        # θ [rad]
    guide_height_above_O2: float  # L_O2M = L_O3M − L_O2O3 [m]


@dataclass(frozen=True)
class Kinematics:
    """Stage 机构运动分析 on the grid and at the textbook positions.

    Arrays have one entry per crank phase; phase = crank angle from position 1 in the
    sense of rotation [rad]. Ram quantities are along the working-stroke direction.
    """

    positions: Positions
    phase: np.ndarray           # [rad]
    crank_angle: np.ndarray     # crank angle CCW from +x [rad]
    ram_s: np.ndarray           # ram displacement from position 1 [m]
    ram_v: np.ndarray           # [m/s]
    ram_a: np.ndarray           # [m/s²]
    omega4: np.ndarray          # guide-bar angular velocity, CCW + [rad/s]
    alpha4: np.ndarray          # guide-bar angular acceleration, CCW + [rad/s²]
    slide_v: np.ndarray         # sliding velocity of slider 3 on the bar, v_A4A3 [m/s]
    coriolis: np.ndarray        # Coriolis acceleration 2·ω4·v_A4A3 [m/s²]
    omega5: np.ndarray          # rod angular velocity [rad/s]
    alpha5: np.ndarray          # rod angular acceleration [rad/s²]
    points: dict                # name → complex positions [m] (for drawings)
    working_span: float         # crank angle of the working stroke [rad]
    stroke_direction: float     # +1 when the working stroke moves the ram towards +x
    grid_size: int


@dataclass(frozen=True)
class Forces:
    """Stage 动态静力分析: loads and reactions (arrays as in :class:`Kinematics`)."""

    cutting_force: np.ndarray   # resistance on the ram along −working direction [N] (≥ 0)
    inertia_force4: np.ndarray  # |P_I4| = m4·|a_S4| [N]
    inertia_couple4: np.ndarray  # M_I4 = −J_S4·α4, CCW + [N·m]
    inertia_force6: np.ndarray  # P_I6 = −m6·a_6 along +x [N]
    reactions: dict             # name (R72, R23, ...) → complex force of a on b [N]
    couples: dict               # prismatic-pair couples by name [N·m]
    balancing_torque: np.ndarray  # M_b in the sense of rotation [N·m]
    power_residual: np.ndarray  # Σ power of all loads incl. M_b [W]


@dataclass(frozen=True)
class Flywheel:
    """Stage 飞轮设计."""

    shaft: str                  # "pinion" (O1) or "crank" (O2)
    ratio_to_crank: float       # i = shaft speed / crank speed
    shaft_speed_rpm: float
    resistance_torque: np.ndarray  # M_r on the flywheel shaft over the crank phase [N·m]
    driving_torque: float       # constant M_d on the flywheel shaft [N·m]
    energy: np.ndarray          # ΔE over the crank phase [J]
    max_energy_swing: float     # ΔW_max [J]
    phase_at_min: float         # [rad]
    phase_at_max: float         # [rad]
    inertia: float              # J_F [kg·m²]
    rim: fw.RimFlywheel
    mean_power: float           # mean power the drive delivers to the crank [W]


def synthesize(p: ShaperParams) -> Synthesis:
    d = guide_bar_quick_return(p.stroke, p.time_ratio_K, p.frame, p.rod_ratio, p.com_ratio)
    return Synthesis(d, d.swing_angle, d.guide_height - d.frame)


def build_mechanism(d: GuideBarDesign, p: ShaperParams) -> Mechanism:
    """The six-bar as Assur groups; F to the left of B (branch −1), as the course draws it."""
    m = Mechanism(FRAME, {"O3": 0j, "O2": 1j * d.frame})
    m.add(Crank("crank O2A", "2", "O2", "A", d.crank, p.crank_omega))
    m.add(RPR("guide bar (RPR)", "3", "4", "A", "O3", branch=+1))
    m.add(LinkPoint("B", "4", "O3", d.guide_bar))
    m.add(LinkPoint("S4", "4", "O3", d.bar_com))
    m.add(RRP("ram (RRP)", "5", "6", "B", "F", d.rod, 1j * d.guide_height, 0.0,
              branch=-1, frame=FRAME))
    m.add(LinkPoint("S6", "6", "F", p.ram_com_x))
    # Point P on the cutting-force line, vertically below F (the ram translates).
    drop = d.guide_height - (d.frame + p.cutting_height)
    m.add(LinkPoint("P", "6", "F", abs(drop), -np.pi / 2 if drop >= 0 else np.pi / 2))
    return m


def _extremes(d: GuideBarDesign) -> tuple[float, float]:
    """Crank angles [rad] where the crank is perpendicular to the guide bar (ram extremes).

    With O2 above O3 these are π + ψ/2 (bar leaning left) and 2π − ψ/2 (leaning right).
    """
    half = d.swing_angle / 2.0
    return np.pi + half, 2.0 * np.pi - half


def kinematics(syn: Synthesis, p: ShaperParams) -> tuple[Kinematics, Mechanism, object]:
    d = syn.design
    mech = build_mechanism(d, p)
    sense = np.sign(p.crank_omega)
    left, right = _extremes(d)
    # Position 1 starts the working (slow) stroke: the extreme from which the crank
    # needs 180° + θ to reach the other one in its sense of rotation.
    span_from_left = (sense * (right - left)) % (2 * np.pi)
    start, end = (left, right) if span_from_left > np.pi else (right, left)
    working_span = (sense * (end - start)) % (2 * np.pi)
    vertical = [np.pi / 2, 3 * np.pi / 2]
    specials = [(sense * (a - start)) % (2 * np.pi) for a in vertical]
    pos = textbook_positions(p.position_step, working_span, specials)

    grid = np.arange(p.grid_points) * (2 * np.pi / p.grid_points)
    phase = np.concatenate([grid, pos.phase])
    crank_angle = start + sense * phase
    try:
        motion = mech.solve(crank_angle)
    except AssemblyError as exc:
        # The ram's rod must bridge half the sagitta of B's arc: L_BF ≥ L_O3B(1 − cos(ψ/2))/2.
        need = (1.0 - np.cos(d.swing_angle / 2.0)) / 2.0
        raise exc.with_hint(
            f"(Brief field: linkage.rod_ratio_BF_O3B = {p.rod_ratio:g} must be at least "
            f"(1 − cos(ψ/2))/2 = {need:.6g}.)",
            f"（任务书字段：linkage.rod_ratio_BF_O3B = {p.rod_ratio:g}，须不小于 "
            f"(1 − cos(ψ/2))/2 = {need:.6g}。）") from None
    x_pos = motion.points["F"].pos.real[len(grid):]
    x0 = x_pos[0]  # position 1
    x_end = x_pos[int(np.argmin(np.abs(pos.phase - working_span)))]  # the other extreme
    direction = float(np.sign(x_end - x0))
    F = motion.points["F"]
    slide = motion.slides["3"]
    k = Kinematics(
        positions=pos, phase=phase, crank_angle=crank_angle,
        ram_s=direction * (F.pos.real - x0), ram_v=direction * F.vel.real,
        ram_a=direction * F.acc.real,
        omega4=motion.links["4"].omega, alpha4=motion.links["4"].alpha,
        slide_v=slide.ds, coriolis=2.0 * motion.links["4"].omega * slide.ds,
        omega5=motion.links["5"].omega, alpha5=motion.links["5"].alpha,
        points={n: motion.points[n].pos for n in ("O2", "O3", "A", "B", "F", "S4", "S6")},
        working_span=float(working_span), stroke_direction=direction, grid_size=len(grid))
    return k, mech, motion


def cutting_force(k: Kinematics, p: ShaperParams) -> np.ndarray:
    """Fc [N] while the ram is in the working stroke and inside its idle-travel limits."""
    idle = p.idle_travel_ratio * p.stroke
    tol = 1e-9
    working = k.phase <= k.working_span + tol
    inside = (k.ram_s >= idle - tol) & (k.ram_s <= p.stroke - idle + tol)
    return np.where(working & inside, p.cutting_force, 0.0)


def kinetostatics(k: Kinematics, mech: Mechanism, motion, p: ShaperParams) -> Forces:
    bodies = [Body("4", p.m4, "S4", p.J_S4), Body("6", p.m6, "S6", 0.0),
              Body("2", p.G2 / p.gravity, "O2", 0.0)]
    fc = cutting_force(k, p)
    loads = [PointLoad("6", "P", -k.stroke_direction * fc + 0j)]
    fa = solve_forces(mech, motion, bodies, loads, p.gravity)
    sense = np.sign(p.crank_omega)
    mb = sense * fa.driving_torque
    residual = power_residual(mech, motion, bodies, loads, fa.driving_torque, p.gravity)
    zero = np.zeros_like(mb)  # a massless link has no entry in the inertia loads
    return Forces(
        cutting_force=fc,
        inertia_force4=np.abs(fa.inertia_force.get("4", zero)),
        inertia_couple4=fa.inertia_couple.get("4", zero),
        inertia_force6=fa.inertia_force.get("6", zero).real,
        reactions={n: r.force for n, r in fa.reactions.items()},
        couples={n: r.couple for n, r in fa.reactions.items() if r.couple is not None},
        balancing_torque=mb, power_residual=residual)


def flywheel(k: Kinematics, f: Forces, p: ShaperParams) -> Flywheel:
    n = k.grid_size
    phase, mb = k.phase[:n], f.balancing_torque[:n]
    cycle = fw.energy_cycle(phase, mb)
    ratio = p.z2 / p.z1 if p.flywheel_shaft == "pinion" else 1.0
    speed = p.crank_speed_rpm * ratio
    inertia = fw.flywheel_inertia(cycle.max_energy_swing, speed, p.fluctuation)
    rim = fw.rim_dimensions(inertia, p.rim_diameter, p.rim_height_to_width,
                            p.specific_weight, speed, p.gravity)
    return Flywheel(
        shaft=p.flywheel_shaft, ratio_to_crank=ratio, shaft_speed_rpm=speed,
        resistance_torque=mb / ratio, driving_torque=cycle.driving_torque / ratio,
        energy=cycle.energy, max_energy_swing=cycle.max_energy_swing,
        phase_at_min=cycle.angle_at_min, phase_at_max=cycle.angle_at_max,
        inertia=inertia, rim=rim, mean_power=cycle.driving_torque * abs(p.crank_omega))


def simulated_stroke_and_K(mech: Mechanism, k: Kinematics) -> tuple[float, float]:
    """Stroke [m] and time ratio K found by simulating the linkage alone.

    The extremes of the ram are the zeros of its velocity: Newton's method on
    dx_F/dφ = v_F/ω with the analytic acceleration as its derivative (d²x_F/dφ² = a_F/ω²),
    both extremes at once, started at the grid's extremes and each step solving the
    linkage afresh at the new angles — independent of the synthesis formulas.
    """
    n = k.grid_size
    phase, s = k.phase[:n], k.ram_s[:n]
    start, sense = k.crank_angle[0], np.sign(k.crank_angle[1] - k.crank_angle[0])
    omega = next(g.omega for g in mech.groups if getattr(g, "kind", "") == "crank")
    h = phase[1] - phase[0]
    ph0 = phase[[int(np.argmin(s)), int(np.argmax(s))]]
    ph = ph0.copy()
    for _ in range(20):
        f = mech.solve(start + sense * ph).points["F"]
        slope = f.vel.real * sense / omega           # dx_F/dφ (phase runs with the crank)
        curvature = f.acc.real / omega**2            # d²x_F/dφ² (ω constant)
        step = np.clip(slope / curvature, -h, h)     # never leave the grid's bracket
        ph = np.clip(ph - step, ph0 - h, ph0 + h)
        if np.max(np.abs(step)) < 1e-14:
            break
    x = mech.solve(start + sense * ph).points["F"].pos.real
    s_min, s_max = k.stroke_direction * x
    work = (ph[1] - ph[0]) % (2 * np.pi)
    return s_max - s_min, work / (2 * np.pi - work)


@dataclass(frozen=True)
class Verification:
    """Residuals of the run's self-checks (shown at the end of the report)."""

    closure_residual: float     # max |constraint violation| over the grid [m]
    velocity_fd_error: float    # max |v − dx/dt (central differences)| / max|v|
    acceleration_fd_error: float  # max |a − dv/dt| / max|a|
    stroke_error: float         # simulated stroke − H [m]
    time_ratio_simulated: float  # K from the simulated extreme positions
    power_balance_residual: float  # max |Σ P| / max |M_b·ω| (dimensionless)
    fd_step: float              # crank-angle step of the differences [rad]


def verify(syn: Synthesis, k: Kinematics, mech: Mechanism, motion, f: Forces,
           p: ShaperParams) -> Verification:
    d = syn.design
    n = k.grid_size
    pts = {name: motion.points[name].pos[:n] for name in ("A", "B", "F", "O2", "O3")}
    u4 = np.exp(1j * motion.links["4"].angle[:n])
    closure = max(
        np.max(np.abs(np.abs(pts["A"] - pts["O2"]) - d.crank)),
        np.max(np.abs(((np.conj(u4) * (pts["A"] - pts["O3"])).imag))),  # A on the bar line
        np.max(np.abs(np.abs(pts["F"] - pts["B"]) - d.rod)),
        np.max(np.abs(pts["F"].imag - d.guide_height)))
    dt = (2 * np.pi / n) / abs(p.crank_omega)
    s, v, a = k.ram_s[:n], k.ram_v[:n], k.ram_a[:n]
    # Central differences on the periodic grid: error O(h²).
    v_fd = (np.roll(s, -1) - np.roll(s, 1)) / (2 * dt)
    a_fd = (np.roll(v, -1) - np.roll(v, 1)) / (2 * dt)
    w4 = k.omega4[:n]
    th4 = motion.links["4"].angle[:n]
    w4_fd = np.angle(np.exp(1j * (np.roll(th4, -1) - np.roll(th4, 1)))) / (2 * dt)
    vel_err = max(np.max(np.abs(v - v_fd)) / np.max(np.abs(v)),
                  np.max(np.abs(w4 - w4_fd)) / np.max(np.abs(w4)))
    acc_err = np.max(np.abs(a - a_fd)) / np.max(np.abs(a))
    stroke, k_sim = simulated_stroke_and_K(mech, k)
    power = f.power_residual[:n]
    scale = np.max(np.abs(f.balancing_torque[:n] * p.crank_omega))
    return Verification(float(closure), float(vel_err), float(acc_err), stroke - p.stroke,
                        float(k_sim), float(np.max(np.abs(power)) / scale), float(2 * np.pi / n))




STAGES = [
    Stage("synthesis", "导杆机构设计 / linkage synthesis",
          lambda r: synthesize(r["params"])),
    Stage(("kinematics", "mechanism", "motion"), "机构运动分析 / kinematics",
          lambda r: kinematics(r["synthesis"], r["params"])),
    Stage("forces", "动态静力分析 / kinetostatics",
          lambda r: kinetostatics(r["kinematics"], r["mechanism"], r["motion"], r["params"])),
    Stage("flywheel", "飞轮设计 / flywheel",
          lambda r: flywheel(r["kinematics"], r["forces"], r["params"])),
    Stage("verification", "校核 / verification",
          lambda r: verify(r["synthesis"], r["kinematics"], r["mechanism"], r["motion"],
                           r["forces"], r["params"])),
]


def _drive(r: dict):
    """The drive delivers the crank's mean power at the crank speed. The flywheel evens out
    the torque upstream of its shaft only: the stages after it carry the peak of M_b."""
    from .drive import design_drive

    p, f, fl = r["params"], r["forces"], r["flywheel"]
    n = r["kinematics"].grid_size
    mb = f.balancing_torque[:n]
    mean = float(np.mean(mb))
    peak = float(np.max(np.abs(mb)) / mean) if mean > 0 else float("inf")  # inf: no load
    shafts = len(p.drive.stages)          # the crank shaft's index
    flywheel_shaft = shafts - 1 if p.flywheel_shaft == "pinion" else shafts
    from dataclasses import replace

    result = design_drive(p.drive, fl.mean_power, p.crank_speed_rpm, "mechanism",
                          peak, flywheel_shaft if flywheel_shaft < shafts else None)
    # The last stage is gear_pair, whose undercut the gear stage reports with its own fields.
    last = f"drive.stages[{shafts - 1}]"
    return replace(result, warnings=tuple(w for w in result.warnings
                                          if not (w.code == "undercut" and last in w.en)))


def stages(params: ShaperParams) -> list[Stage]:
    """The shaper's stages; gear, drive and cam stages when the brief has those sections."""
    out = list(STAGES)
    if params.gear is not None:
        from .gear import gear_stage

        out.append(gear_stage())
    if params.drive is not None:
        out.append(Stage("drive", "传动装置设计 / drive", _drive))
    if params.cam is not None:
        from .cam import cam_stage

        out.append(cam_stage())
    return out


def results_document(r: dict) -> dict:
    """Everything computed, in SI units, for ``results.json`` (see docs/results.md)."""
    syn, k, f, fl, v = (r[key] for key in ("synthesis", "kinematics", "forces", "flywheel",
                                            "verification"))
    n = k.grid_size
    per_position = []
    for i, label in enumerate(k.positions.labels):
        j = n + i
        per_position.append({
            "label": label,
            "phase": k.phase[j], "crank_angle": k.crank_angle[j] % (2 * np.pi),
            "ram_s": k.ram_s[j], "ram_v": k.ram_v[j], "ram_a": k.ram_a[j],
            "omega4": k.omega4[j], "alpha4": k.alpha4[j],
            "slide_v": k.slide_v[j], "coriolis": k.coriolis[j],
            "cutting_force": f.cutting_force[j],
            "inertia_force4": f.inertia_force4[j], "inertia_couple4": f.inertia_couple4[j],
            "inertia_force6": f.inertia_force6[j],
            "reactions": {name: force[j] for name, force in f.reactions.items()},
            "prismatic_couples": {name: c[j] for name, c in f.couples.items()},
            "balancing_torque": f.balancing_torque[j],
        })
    d = syn.design
    return {
        "schema": "mechdesign.results/1",
        "machine": "shaper",
        "units": "SI: m, s, rad, kg, N, N·m, J, W; complex vectors as [x, y]",
        "synthesis": {
            "extreme_angle": syn.extreme_angle, "swing_angle": d.swing_angle,
            "crank": d.crank, "frame": d.frame, "guide_bar": d.guide_bar, "rod": d.rod,
            "guide_height": d.guide_height, "bar_com": d.bar_com,
            "guide_height_above_O2": syn.guide_height_above_O2,
        },
        "positions": per_position,
        "grid": {
            "phase": k.phase[:n], "ram_s": k.ram_s[:n], "ram_v": k.ram_v[:n],
            "ram_a": k.ram_a[:n], "omega4": k.omega4[:n], "alpha4": k.alpha4[:n],
            "balancing_torque": f.balancing_torque[:n], "energy": fl.energy,
        },
        "working_stroke_crank_angle": k.working_span,
        "flywheel": {
            "shaft": fl.shaft, "ratio_to_crank": fl.ratio_to_crank,
            "shaft_speed_rpm": fl.shaft_speed_rpm, "driving_torque": fl.driving_torque,
            "max_energy_swing": fl.max_energy_swing, "inertia": fl.inertia,
            "phase_at_min": fl.phase_at_min, "phase_at_max": fl.phase_at_max,
            "mean_power": fl.mean_power, "rim": fl.rim,
        },
        "verification": v,
        "cam": None if r.get("cam") is None else cam_document(r["cam"]),
        "gear": None if r.get("gear") is None else gear_document(r["gear"]),
        "drive": None if r.get("drive") is None else drive_document(r["drive"]),
    }
