"""Shaper (牛头刨床): crank + RPR dyad (guide bar) + RRP dyad (ram) — a model on the one
linkage engine (:mod:`mechdesign.stages.linkage`) and the one flywheel stage.

Coordinates: O3 (guide-bar pivot) at the origin, O2 (crank pivot) at (0, L_O2O3) above
it, the ram guide horizontal at y = L_O3M. Links: 2 crank O2A, 3 slider at A, 4 guide
bar O3B, 5 rod BF, 6 ram, 7 frame (the course's numbering).

This module only says what the shaper is: its synthesis, its points, groups, bodies and
cutting force (:func:`model`), and the shaper's names for the engine's results (the ram's
s, v, a; ω4, α4; the Coriolis acceleration of the slider on the bar) as views.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .brief import ShaperParams
from ...core.kinetostatics import Body
from ...core.mechanism import RPR, RRP, Crank, LinkPoint, Mechanism
from ...core.synthesis import GuideBarDesign
from ...pipeline import Stage
from ...stages.flywheel import Flywheel, brief_flywheel
from ...stages import guide_bar
from ...stages.guide_bar import Synthesis, synthesize
from ...stages import linkage as lk
from ...stages.cam import CamDocument, SelfCheck, cam_document
from ...stages.drive import DriveDocument, drive_document
from ...stages.gear import GearDocument, gear_document
from ...stages.positions import Positions
from ...core.fields import q
from ...stages import titles
from ...stages.findings import Msg

FRAME = "7"


@dataclass(frozen=True)
class Kinematics:
    """The shaper's view of the engine's motion (机构运动分析), grid then textbook positions.

    Arrays have one entry per crank phase; phase = crank angle from position 1 in the
    sense of rotation [rad]. Ram quantities are along the working-stroke direction.
    """

    positions: Positions = q("")
    phase: np.ndarray = q("rad")
    crank_angle: np.ndarray = q("rad", "crank angle CCW from +x")
    ram_s: np.ndarray = q("m", "ram displacement from position 1")
    ram_v: np.ndarray = q("m/s")
    ram_a: np.ndarray = q("m/s²")
    omega4: np.ndarray = q("rad/s", "guide-bar angular velocity, CCW +")
    alpha4: np.ndarray = q("rad/s²", "guide-bar angular acceleration, CCW +")
    slide_v: np.ndarray = q("m/s", "sliding velocity of slider 3 on the bar, v_A4A3")
    coriolis: np.ndarray = q("m/s²", "Coriolis acceleration 2·ω4·v_A4A3")
    omega5: np.ndarray = q("rad/s", "rod angular velocity")
    alpha5: np.ndarray = q("rad/s²", "rod angular acceleration")
    points: dict = q("m", "name → complex positions  (for drawings)")
    working_span: float = q("rad", "crank angle of the working stroke")
    stroke_direction: float = q("1", "+1 when the working stroke moves the ram towards +x")
    grid_size: int = q("1", "entries of the uniform grid before the positions")
    model: object = q("", "the linkage model (not serialised)", default=None)
    linkage: object = q("", "the engine's LinkageMotion this view reads", default=None)


@dataclass(frozen=True)
class Forces:
    """The shaper's view of the engine's forces (动态静力分析), arrays as in :class:`Kinematics`."""

    cutting_force: np.ndarray = q("N", "resistance on the ram along −working direction  (≥ 0)")
    inertia_force4: np.ndarray = q("N", "|P_I4| = m4·|a_S4|")
    inertia_couple4: np.ndarray = q("N·m", "M_I4 = −J_S4·α4, CCW +")
    inertia_force6: np.ndarray = q("N", "P_I6 = −m6·a_6 along +x")
    reactions: dict = q("N", "name (R72, R23, ...) → complex force of a on b")
    couples: dict = q("N·m", "prismatic-pair couples by name")
    balancing_torque: np.ndarray = q("N·m", "M_b in the sense of rotation")
    power_residual: np.ndarray = q("W", "Σ power of all loads incl. M_b")
    linkage: object = q("", "the engine's LinkageForces this view reads", default=None)


def build_mechanism(d: GuideBarDesign, p: ShaperParams) -> Mechanism:
    """The six-bar as Assur groups; F to the left of B (branch −1), as the course draws it."""
    m = Mechanism(FRAME, {"O3": 0j, "O2": 1j * d.frame})
    m.add(Crank("crank O2A", "2", "O2", "A", d.crank, p.crank_omega))
    m.add(RPR("guide bar (RPR)", "3", "4", "A", "O3", branch=+1))
    m.add(LinkPoint("B", "4", "O3", d.guide_bar))
    m.add(LinkPoint("S4", "4", "O3", d.bar_com))
    m.add(RRP("ram (RRP)", "5", "6", "B", "F", d.rod, 1j * d.guide_height, 0.0,
              branch=-1, frame=FRAME))
    if p.ram_com_y == 0.0:
        m.add(LinkPoint("S6", "6", "F", p.ram_com_x))
    else:   # S6 above (or below) F: the ram's inertia force acts on that line
        m.add(LinkPoint("S6", "6", "F", float(np.hypot(p.ram_com_x, p.ram_com_y)),
                        float(np.arctan2(p.ram_com_y, p.ram_com_x))))
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


def model(syn: Synthesis, p: ShaperParams) -> lk.LinkageModel:
    """The shaper as a linkage model: groups, bodies, the cutting force, the flywheel.

    The working (slow) stroke starts at the extreme from which the crank needs 180° + θ to
    reach the other in its sense of rotation; from the left extreme (bar leaning left) the
    ram then moves towards +x. Position 1 starts it; the crank vertical (90°, 270°) gives
    the special positions 4′ and 10′.
    """
    d = syn.design
    sense = np.sign(p.crank_omega)
    left, right = _extremes(d)
    working = 1 if (sense * (right - left)) % (2 * np.pi) > np.pi else -1
    idle = p.idle_travel_ratio * p.stroke
    return lk.LinkageModel(
        mechanism=build_mechanism(d, p), crank_omega=p.crank_omega,
        output=lk.Output("point", "F", 0.0, working),
        bodies=(Body("4", p.m4, "S4", p.J_S4), Body("6", p.m6, "S6", 0.0),
                Body("2", p.G2 / p.gravity, "O2", 0.0)),
        resistances=(lk.Resistance("6", "P", 0.0, p.cutting_force, 0.0,
                                   (idle, p.stroke - idle), symbol="Fc"),),
        grid_points=p.grid_points, position_step=p.position_step, gravity=p.gravity,
        flywheel=brief_flywheel(p),
        special_crank_angles=(np.pi / 2, 3 * np.pi / 2),
        names={"2": Msg.pgettext("link", "crank O2A"), "3": Msg.pgettext("link", "slider A"),
               "4": Msg.pgettext("link", "guide bar O3B"), "5": Msg.pgettext("link", "rod BF"),
               "6": Msg.pgettext("link: shaper", "ram")},
        group_labels={"guide bar (RPR)": Msg.pgettext("link", "guide bar (RPR)"),
                      "ram (RRP)": Msg.pgettext("link: shaper", "ram (RRP)")})


def motion(m: lk.LinkageModel, syn: Synthesis, p: ShaperParams, requests=None):
    """The engine's motion stage, an assembly failure naming the brief's field."""
    return guide_bar.motion(m, syn, p, "BF", requests)


def kinematics_view(m: lk.LinkageModel, k: lk.LinkageMotion, raw) -> Kinematics:
    """The shaper's names for the engine's motion: the ram (F), the guide bar (4) with the
    slider's sliding velocity on it and its Coriolis acceleration, the rod (5)."""
    slide = raw.slides["3"]
    bar, rod = raw.links["4"], raw.links["5"]
    return Kinematics(
        positions=k.positions, phase=k.phase, crank_angle=k.crank_angle,
        ram_s=k.s, ram_v=k.v, ram_a=k.a, omega4=bar.omega, alpha4=bar.alpha,
        slide_v=slide.ds, coriolis=2.0 * bar.omega * slide.ds,
        omega5=rod.omega, alpha5=rod.alpha,
        points={n: raw.points[n].pos for n in ("O2", "O3", "A", "B", "F", "S4", "S6")},
        working_span=k.working_span, stroke_direction=float(m.output.working),
        grid_size=k.grid_size, model=m, linkage=k)


def kinematics(syn: Synthesis, p: ShaperParams) -> tuple[Kinematics, Mechanism, object]:
    """Model and motion in one call (for tests and benchmarks)."""
    m = model(syn, p)
    k, raw = motion(m, syn, p)
    return kinematics_view(m, k, raw), m.mechanism, raw


def forces_view(f: lk.LinkageForces) -> Forces:
    zero = np.zeros_like(f.balancing_torque)  # a massless link has no entry in the inertia loads
    return Forces(
        cutting_force=np.abs(f.resistance["R1"]),
        inertia_force4=np.abs(f.inertia_force.get("4", zero)),
        inertia_couple4=f.inertia_couple.get("4", zero),
        inertia_force6=f.inertia_force.get("6", zero).real,
        reactions=f.reactions, couples=f.couples,
        balancing_torque=f.balancing_torque, power_residual=f.power_residual, linkage=f)


def kinetostatics(k: Kinematics, mech: Mechanism, raw, p: ShaperParams) -> Forces:
    return forces_view(lk.forces(k.model, k.linkage, raw))


def flywheel(k: Kinematics, f: Forces, p: ShaperParams):
    return lk.flywheel(k.model, k.linkage, f.linkage)


@dataclass(frozen=True)
class Verification:
    """Residuals of the run's self-checks (shown at the end of the report)."""

    closure_residual: float = q("m", "max |constraint violation| over the grid")
    velocity_fd_error: float = q("1", "max |v − dx/dt (central differences)| / max|v|, every point and link")
    acceleration_fd_error: float = q("1", "max |a − dv/dt| / max|a|")
    stroke_error: float = q("m", "simulated stroke − H")
    time_ratio_simulated: float = q("1", "K from the simulated extreme positions")
    power_balance_residual: float = q("1", "max |Σ P| / max |M_b·ω|")
    fd_step: float = q("rad", "crank-angle step of the differences")


def verification_view(v: lk.LinkageVerification, p: ShaperParams) -> Verification:
    return Verification(v.closure_residual, v.velocity_fd_error, v.acceleration_fd_error,
                        v.stroke - p.stroke, v.time_ratio, v.power_balance_residual, v.fd_step)


#: Limits of the self-checks, as the generic linkage's verification table
#: (render/linkage_report.verification_rows) states them: round-off level for the closure,
#: the stroke, K and the power balance; O(h²) truncation for the central differences.
CLOSURE_LIMIT = 1e-9            # m
DIFFERENCE_LIMIT = 1e-3         # relative
POWER_LIMIT = 1e-9              # relative
STROKE_LIMIT = 1e-6             # relative to H
TIME_RATIO_LIMIT = 1e-6         # absolute


def self_checks(v: Verification, syn: Synthesis) -> tuple[SelfCheck, ...]:
    """The verification's residuals as checks with their limits (the report's verification
    table takes the verdicts from these, never writes one): stroke and K against the
    synthesis' H and K."""
    return (
        SelfCheck("closure", v.closure_residual, CLOSURE_LIMIT),
        SelfCheck("velocity_fd", v.velocity_fd_error, DIFFERENCE_LIMIT),
        SelfCheck("acceleration_fd", v.acceleration_fd_error, DIFFERENCE_LIMIT),
        SelfCheck("stroke", abs(v.stroke_error), STROKE_LIMIT * syn.stroke, reference=syn.stroke),
        SelfCheck("time_ratio", abs(v.time_ratio_simulated - syn.time_ratio), TIME_RATIO_LIMIT,
                  reference=syn.time_ratio),
        SelfCheck("power_balance", v.power_balance_residual, POWER_LIMIT),
    )


def verify(syn: Synthesis, k: Kinematics, mech: Mechanism, raw, f: Forces,
           p: ShaperParams) -> Verification:
    return verification_view(lk.verify(k.model, k.linkage, raw, f.linkage), p)


def _motion_stage(r: dict):
    m = r["model"]
    k, raw = motion(m, r["synthesis"], r["params"], lk.requests_of(r.get("brief")))
    return k, raw, kinematics_view(m, k, raw)


def _forces_stage(r: dict):
    f = lk.forces(r["model"], r["linkage"], r["linkage_raw"])
    return f, forces_view(f)


def _verify_stage(r: dict):
    v = lk.verify(r["model"], r["linkage"], r["linkage_raw"], r["linkage_forces"])
    return v, verification_view(v, r["params"])


def _synthesis_stage(r: dict):
    syn = synthesize(r["params"])
    return syn, model(syn, r["params"])


# The engine's stages (results under model, linkage, linkage_raw, linkage_forces,
# linkage_flywheel, linkage_verification, linkage_polygons), three of them also giving the
# shaper's views of their results (kinematics, forces, verification).
_ENGINE = lk.linkage_stages(model_key="model", prefix="linkage")
STAGES = [
    Stage(("synthesis", "model"), titles.pgettext("stage: guide bar", "linkage synthesis"), _synthesis_stage),
    Stage(("linkage", "linkage_raw", "kinematics"), _ENGINE[0].title, _motion_stage),
    Stage(("linkage_forces", "forces"), _ENGINE[1].title, _forces_stage),
    _ENGINE[2],                                              # the one flywheel stage
    Stage(("linkage_verification", "verification"), _ENGINE[3].title, _verify_stage),
    _ENGINE[4],                                              # the polygons of the A1 sheet
    _ENGINE[5],                                              # the graphical method
]


def stages(params: ShaperParams) -> list[Stage]:
    """The shaper's stages; gear, drive and cam stages when the brief has those sections.
    The flywheel rim (on the pinion or the crank shaft) loads its shaft with its weight, as
    the slotter's does."""
    return list(STAGES) + guide_bar.optional_stages(params, flywheel_weight=True, feed_cam=True)


@dataclass(frozen=True)
class ShaperPosition:
    """One textbook position; ram quantities along the working-stroke direction."""

    label: str = q("", "1, 2, …; 4′, 8′ (the other extreme), 10′ are special positions")
    phase: float = q("rad", "crank angle from position 1 in the sense of rotation")
    crank_angle: float = q("rad", "crank angle, CCW from +x")
    ram_s: float = q("m", "ram displacement from position 1")
    ram_v: float = q("m/s", "ram velocity")
    ram_a: float = q("m/s²", "ram acceleration")
    omega4: float = q("rad/s", "guide-bar angular velocity, CCW +")
    alpha4: float = q("rad/s²", "guide-bar angular acceleration, CCW +")
    slide_v: float = q("m/s", "sliding velocity v_A4A3 of slider 3 on the bar")
    coriolis: float = q("m/s²", "Coriolis acceleration 2·ω4·v_A4A3")
    cutting_force: float = q("N", "Fc (0 outside the cutting zone)")
    inertia_force4: float = q("N", "|F_I4| = m4·|a_S4|")
    inertia_couple4: float = q("N·m", "M_I4 = −J_S4·α4, CCW +")
    inertia_force6: float = q("N", "F_I6 = −m6·a_6 along +x")
    reactions: dict[str, complex] = q("N", "R{a}{b}: force of link a on link b, [x, y]")
    prismatic_couples: dict[str, float] = q("N·m", "couples of the prismatic pairs")
    balancing_torque: float = q("N·m", "M_b in the crank's sense of rotation")


@dataclass(frozen=True)
class ShaperGrid:
    """Arrays over one revolution on the uniform grid."""

    phase: np.ndarray = q("rad", "crank phase from position 1")
    ram_s: np.ndarray = q("m")
    ram_v: np.ndarray = q("m/s")
    ram_a: np.ndarray = q("m/s²")
    omega4: np.ndarray = q("rad/s")
    alpha4: np.ndarray = q("rad/s²")
    balancing_torque: np.ndarray = q("N·m")
    energy: np.ndarray = q("J", "ΔE of the flywheel cycle")


@dataclass(frozen=True)
class ShaperResults:
    """Shaper (牛头刨床). Frame: O3 (guide-bar pivot) at the origin, O2 (crank pivot) at (0,
    frame) above it, the ram guide horizontal at y = synthesis.guide_height. Links: 2 crank,
    3 slider, 4 guide bar, 5 rod BF, 6 ram, 7 frame."""

    schema: str = q("", "'mechdesign.results/2'")
    machine: str = q("", "'shaper'")
    units: str = q("", "reminder of the unit system")
    synthesis: guide_bar.GuideBarSynthesisDoc = q("", "the guide-bar mechanism's dimensions")
    positions: tuple[ShaperPosition, ...] = q("", "the textbook positions in crank order")
    grid: ShaperGrid = q("", "one revolution")
    working_stroke_crank_angle: float = q("rad", "crank rotation of the working stroke (π + θ)")
    flywheel: Flywheel = q("", "the flywheel (the one flywheel stage) on the pinion or crank shaft")
    verification: Verification = q("", "self-checks")
    cam: CamDocument | None = q("", "the cam on the crank shaft, when the brief has one")
    gear: GearDocument | None = q("", "the gear pair z1/z2, when the brief gives its module")
    drive: DriveDocument | None = q("", "the drive, when the brief has one")
    graphical: lk.GraphicalDocument | None = q("", "the graphical method at the polygon "
                                               "positions", default=None)
    cam_phase: guide_bar.CamPhase | None = q("", "the feed cam's phase to the crank and its "
                                             "check: its motion within the return stroke",
                                             default=None)


def results_document(r: dict) -> ShaperResults:
    """Everything computed, in SI units, for ``results.json`` (see docs/results.md)."""
    from ...results import SCHEMA, UNITS_NOTE

    syn, k, f, fl, v = (r[key] for key in ("synthesis", "kinematics", "forces", "linkage_flywheel",
                                            "verification"))
    n = k.grid_size
    per_position = []
    for i, label in enumerate(k.positions.labels):
        j = n + i
        per_position.append(ShaperPosition(
            label=label, phase=k.phase[j], crank_angle=k.crank_angle[j] % (2 * np.pi),
            ram_s=k.ram_s[j], ram_v=k.ram_v[j], ram_a=k.ram_a[j],
            omega4=k.omega4[j], alpha4=k.alpha4[j], slide_v=k.slide_v[j], coriolis=k.coriolis[j],
            cutting_force=f.cutting_force[j], inertia_force4=f.inertia_force4[j],
            inertia_couple4=f.inertia_couple4[j], inertia_force6=f.inertia_force6[j],
            reactions={name: force[j] for name, force in f.reactions.items()},
            prismatic_couples={name: c[j] for name, c in f.couples.items()},
            balancing_torque=f.balancing_torque[j]))
    return ShaperResults(
        schema=SCHEMA, machine="shaper", units=UNITS_NOTE,
        synthesis=guide_bar.synthesis_doc(syn),
        positions=tuple(per_position),
        grid=ShaperGrid(k.phase[:n], k.ram_s[:n], k.ram_v[:n], k.ram_a[:n], k.omega4[:n],
                        k.alpha4[:n], f.balancing_torque[:n], fl.energy),
        working_stroke_crank_angle=k.working_span, flywheel=fl, verification=v,
        cam=None if r.get("cam") is None else cam_document(r["cam"]),
        cam_phase=r.get("cam_phase"),
        gear=None if r.get("gear") is None else gear_document(r["gear"]),
        drive=None if r.get("drive") is None else drive_document(r["drive"]),
        graphical=r.get("linkage_graphical"))
