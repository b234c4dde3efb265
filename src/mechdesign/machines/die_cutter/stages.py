"""Semi-automatic flat die-cutter (半自动平压模切机, seed 001b), composed from shared stages.

Scheme: one distribution shaft (分配轴), one turn per sheet, drives

* the toggle press (肘杆机构): crank O1A (link 2), coupler AB (3), toggle links CB (4,
  pivot C on the frame) and BD (5), lower platen D (6) on a vertical guide through C;
  four-bar O1-A-B-C plus an RRP dyad. Near the top dead centre CB and BD are almost in
  line, so the platen's speed v_D tends to zero while the crank turns on: the pressing
  force the crank torque M can produce, F = M ω / v_D (virtual work), grows without bound;
* the gripper-opening cam (the shared cam stage);
* the incomplete gear (不完全齿轮) driving the gripper chain's sprocket.

Synthesis of the press (analytic, :func:`toggle_synthesis`): with C at the origin and the
platen guide the vertical through C, the platen height above C is
y(β) = l_CB cos β + √(l_BD² − l_CB² sin² β), β the angle of CB from the guide. The top
is at β = ε (0: the toggle straight), the bottom at β = ε + ψ, so the stroke
H = y(ε) − y(ε + ψ) fixes the rocker swing ψ (y falls monotonically on 0 … 90°, one root).
CB is the rocker of the crank-rocker O1ABC; K and ψ give it by the θ-circle construction
(:mod:`mechdesign.core.fourbar`): the crank pivot with the largest minimum transmission
angle, or the one at the given frame O1C. The extreme of the rocker at the platen's top is
the extended (crank and coupler in line) or the folded one; the drawing is mirrored when
needed so that the rise is the slow stroke (K > 1) in the brief's sense of rotation.

Stages: the synthesis, the shared linkage stages on the press (prefix ``press``), the force
amplification, the drive, the flywheel on the chosen drive shaft, the cam, the incomplete
gear with the chain, the motion cycle diagram, and this machine's own checks.
Coordinates: C at the origin, y up; SI units throughout.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from ...core.extremes import brentq

from .brief import DieCutterParams, PressGeometry
from ...core import cycle as cy
from ...core import fourbar
from ...core.kinetostatics import Body, PointLoad, solve_forces
from ...core.mechanism import RRP, RRR, Crank, LinkPoint, Mechanism
from ...core.synthesis import extreme_angle
from ...pipeline import Stage
from ...i18n import N_
from ...stages.findings import Finding, Msg, Pair, finding, finding_of, zh_en
from ...stages.flywheel import Flywheel, FlywheelSpec, RimSpec, brief_flywheel, design_flywheel
from ...core.cycle import CycleDocument
from ...core.fields import q
from ...core.intermittent import IntermittentDocument
from ...stages.linkage import (CycleIntegrals, LinkageDocument, LinkageModel, Output, Resistance,
                               linkage_stages)
from ...stages.cam import CamDocument
from ...stages.drive import DriveDocument
from ...stages import titles

TWO_PI = 2.0 * np.pi
DEG = 180.0 / np.pi
FRAME = "1"


# --------------------------------------------------------------------------- synthesis


def toggle_height(beta, l_cb: float, l_bd: float):
    """Platen height above C [m] with CB at ``beta`` [rad] from the vertical guide."""
    beta = np.asarray(beta, dtype=float)
    return l_cb * np.cos(beta) + np.sqrt(l_bd ** 2 - (l_cb * np.sin(beta)) ** 2)


def _max_beta(l_cb: float, l_bd: float) -> float:
    """Largest β the toggle reaches below the guide's end: 90°, or where BD would have to
    lie flat (l_BD < l_CB)."""
    return np.pi / 2 if l_bd >= l_cb else float(np.arcsin(l_bd / l_cb))


def toggle_swing(g: PressGeometry) -> float:
    """Rocker swing ψ [rad] giving the stroke: y(ε) − y(ε + ψ) = H (Brent's method)."""
    lt, ld, eps, H = g.toggle_CB, g.toggle_BD, g.top_angle, g.stroke
    beta_max = _max_beta(lt, ld)
    if eps >= beta_max:
        raise fourbar.SynthesisError(Msg(
            N_("toggle_angle_at_top_deg = {eps:g}° leaves no swing (the toggle lies flat at "
               "{flat:.3g}°): make it smaller than {flat:.3g}°"), eps=eps * DEG, flat=beta_max * DEG))
    top = float(toggle_height(eps, lt, ld))
    h_max = top - float(toggle_height(beta_max, lt, ld))
    # the rocker must swing less than the crank-rocker allows; keep ψ below 120° in any case
    psi_cap = min(beta_max - eps, np.radians(120.0))
    h_cap = top - float(toggle_height(eps + psi_cap, lt, ld))
    if not H < min(h_max, h_cap):
        raise fourbar.SynthesisError(Msg(
            N_("stroke_H_mm = {H:g} cannot be reached: toggle links CB = {CB:g} mm and BD = {BD:g} "
               "mm give at most {most:.4g} mm; lengthen CB or reduce the stroke"),
            H=H * 1e3, CB=lt * 1e3, BD=ld * 1e3, most=min(h_max, h_cap) * 1e3))
    return float(brentq(lambda psi: top - float(toggle_height(eps + psi, lt, ld)) - H,
                        1e-12, psi_cap, xtol=1e-15))


@dataclass(frozen=True)
class ToggleDesign:
    """Stage 肘杆机构设计: the toggle press's dimensions and placement (C at the origin) [m, rad]."""

    geometry: PressGeometry
    swing: float                # ψ of CB
    theta: float                # extreme-position angle θ of the crank-rocker
    four: fourbar.FourBar       # crank a = O1A, coupler b = AB, rocker c = CB, frame d = O1C
    gamma_min: float            # minimum transmission angle (closed form)
    gamma_max: float
    O1: complex                 # crank pivot
    B_top: complex              # B when the platen is at its top
    B_bottom: complex
    crank_top: float            # crank angle at the platen's top [rad, CCW from +x]
    crank_bottom: float
    branch: int                 # assembly branch of the RRR group (A, C → B)
    mirrored: bool              # the θ-circle drawing mirrored to make the rise the slow stroke
    top_height: float           # y_D at the top, above C
    bottom_height: float
    rising_span: float          # crank angle of the rise (π + θ)


def _place_given(g: PressGeometry) -> tuple[fourbar.FourBar, complex, complex, complex]:
    """The brief's crank-rocker O1ABC placed as the θ-circle construction would place it
    (C at the origin, the rocker's extremes B1 = (w, h) folded and B2 = (−w, h) extended,
    w = c sin(ψ/2), h = c cos(ψ/2)): O1 at the distance d from C and b − a from B1, on the
    side where O1B2 = b + a (law of cosines, no synthesis). Returns (four-bar, O1, B1, B2)."""
    a, b, d = g.given
    c = g.toggle_CB
    four = fourbar.FourBar(a, b, c, d)
    _, psi = fourbar.crank_rocker_extremes(four)
    w, h = c * np.sin(psi / 2.0), c * np.cos(psi / 2.0)
    b1, b2 = complex(w, h), complex(-w, h)
    t = np.arccos(np.clip((d * d + c * c - (b - a) ** 2) / (2.0 * d * c), -1.0, 1.0))  # ∠O1CB1
    cands = [complex(d * b1 / c * np.exp(1j * s * t)) for s in (+1.0, -1.0)]
    o1 = min(cands, key=lambda z: abs(abs(z - b2) - (b + a)))
    return four, o1, b1, b2


def toggle_synthesis(g: PressGeometry) -> ToggleDesign:
    """Dimensions and placement of the toggle press (see the module docstring).

    Raises :class:`~mechdesign.core.fourbar.SynthesisError` naming what to change."""
    lt, ld, eps = g.toggle_CB, g.toggle_BD, g.top_angle
    if g.given is not None:
        four, a_pt, c1, c2 = _place_given(g)
        a, b, d = four.crank, four.coupler, four.frame
        theta, psi = fourbar.crank_rocker_extremes(four)
        if not eps + psi < _max_beta(lt, ld):
            raise fourbar.SynthesisError(Msg(
                N_("dimensions.crank_O1A_mm = {a:g}: the swing ψ = {psi:.4g}° of CB takes it beyond "
                   "{beta:.4g}° from the guide at the bottom"),
                a=a * 1e3, psi=psi * DEG, beta=_max_beta(lt, ld) * DEG))
    else:
        psi = toggle_swing(g)
        theta = float(extreme_angle(g.K))
        cons = fourbar.circle_construction(g.K, psi, lt)
        if g.frame is None:
            p, _ = fourbar.optimal_position(g.K, psi, lt)
        else:
            p = fourbar.position_for_frame(cons, g.frame)
        a_pt = complex(cons.point(p))
        a, b, d = (float(x) for x in cons.designs(p))
        four = fourbar.FourBar(a, b, lt, d)
        c1, c2 = cons.c1, cons.c2
    ok, kind = fourbar.grashof(four)
    if not (ok and kind == "crank-rocker"):
        en, zh = fourbar.grashof_sums(four)
        raise fourbar.SynthesisError(Msg(
            N_("the crank cannot make a full turn (Grashof): the four-bar O1ABC comes out a {kind}, "
               "not a crank-rocker ({sums}); change K (time_ratio_K) or the toggle lengths "
               "(toggle_CB_mm), or give another frame"), kind=kind, sums=Pair(zh, en)))
    gmin, gmax = fourbar.transmission_angle_extremes(four)
    top, other = (c2, c1) if g.top_position == "extended" else (c1, c2)
    rot = np.exp(1j * (np.pi / 2 - np.angle(top)))
    side = 1.0 if (other * rot).real > 0 else -1.0
    rot *= np.exp(-1j * side * eps)             # CB leans ε towards the side it swings to
    o1, b_top, b_bot = a_pt * rot, top * rot, other * rot

    def crank_angles(o1, b_top, b_bot):
        ext = g.top_position == "extended"
        at_top = np.angle(b_top - o1) if ext else np.angle(o1 - b_top)
        at_bot = np.angle(o1 - b_bot) if ext else np.angle(b_bot - o1)
        return float(at_top), float(at_bot)

    c_top, c_bot = crank_angles(o1, b_top, b_bot)
    mirrored = (g.sense * (c_top - c_bot)) % TWO_PI < np.pi
    if mirrored:                                # x → −x reverses the timing
        o1, b_top, b_bot = (complex(-z.real, z.imag) for z in (o1, b_top, b_bot))
        c_top, c_bot = crank_angles(o1, b_top, b_bot)
    span = float((g.sense * (c_top - c_bot)) % TWO_PI)
    a_top = o1 + a * np.exp(1j * c_top)
    cross = ((np.conj(0j - a_top)) * (b_top - a_top)).imag
    return ToggleDesign(g, psi, theta, four, gmin, gmax, complex(o1), complex(b_top),
                        complex(b_bot), c_top, c_bot, 1 if cross > 0 else -1, bool(mirrored),
                        float(toggle_height(eps, lt, ld)), float(toggle_height(eps + psi, lt, ld)),
                        span)


def build_press(d: ToggleDesign, p: DieCutterParams) -> LinkageModel:
    """The press as a crank, an RRR dyad (AB, CB), an RRP dyad (BD, platen) and the centres
    of mass; the platen's mass and the die-cutting resistance over the last
    ``pressing_travel`` of the rise."""
    fb, g = d.four, d.geometry
    m = Mechanism(FRAME, {"C": 0j, "O1": d.O1})
    m.add(Crank("crank O1A", "2", "O1", "A", fb.crank, p.crank_omega))
    m.add(RRR("RRR A-B-C", "3", "4", "A", "C", "B", fb.coupler, fb.rocker, d.branch))
    m.add(RRP("RRP B-D", "5", "6", "B", "D", g.toggle_BD, 0j, np.pi / 2, 1, FRAME))
    m_ab, m_cb, m_bd = p.link_masses
    bodies = [Body("6", p.platen_mass, "D", 0.0)]
    for link, mass, origin, name, length in (("3", m_ab, "A", "S3", fb.coupler),
                                             ("4", m_cb, "C", "S4", fb.rocker),
                                             ("5", m_bd, "B", "S5", g.toggle_BD)):
        if mass > 0:
            m.add(LinkPoint(name, link, origin, length / 2))
            bodies.append(Body(link, mass, name, mass * length ** 2 / 12.0))
    H, t = g.stroke, p.pressing_travel
    cut = Resistance("6", "D", np.pi / 2, p.cutting_force, 0.0, (H - t, H), symbol="Fc")
    names = {"2": Msg.pgettext("link", "crank"), "3": Msg.pgettext("link", "coupler AB"),
             "4": Msg.pgettext("link", "toggle CB"), "5": Msg.pgettext("link", "toggle BD"),
             "6": Msg.pgettext("link", "platen")}
    return LinkageModel(
        mechanism=m, crank_omega=p.crank_omega, output=Output("point", "D", np.pi / 2, 1),
        bodies=tuple(bodies), resistances=(cut,), grid_points=p.grid_points,
        position_step=p.position_step, gravity=p.gravity, flywheel=None,
        pressure_angle_limit=p.pressure_angle_max, transmission_angle_min=p.transmission_angle_min,
        names=names, advice={
            "pressure": Msg(N_("brief fields: a longer press.toggle_BD_mm or a smaller "
                               "press.toggle_angle_at_top_deg")),
            "transmission": Msg(N_(
                "brief fields: a smaller press.time_ratio_K, a longer press.toggle_CB_mm (a smaller "
                "swing), or no press.frame_O1C_mm (the frame with the largest transmission angle)"))
            if g.given is None else Msg(N_(
                "brief fields: other press.dimensions (crank_O1A_mm, coupler_AB_mm, frame_O1C_mm), "
                "or synthesise from stroke_H_mm and time_ratio_K instead"))})


#: TogglePress fields a synthesis message may start with ("stroke_H_mm = 400 …").
_PRESS_FIELDS = ("stroke_H_mm", "time_ratio_K", "toggle_CB_mm", "toggle_BD_mm",
                 "toggle_angle_at_top_deg", "frame_O1C_mm")


def checks(p: DieCutterParams, keep: dict | None = None) -> list:
    """The feasibility checks of a run (after validation, once): can the toggle press be
    synthesised? Every problem as a :class:`~mechdesign.brief.loader.BriefProblem` at its
    brief field; the design is stored in ``keep["toggle"]`` for the synthesis stage."""
    from ...brief.loader import BriefProblem

    try:
        d = toggle_synthesis(p.geometry)
    except fourbar.SynthesisError as exc:
        name = exc.en.split(" = ", 1)[0] if " = " in exc.en else ""
        if name in _PRESS_FIELDS or name.startswith("dimensions."):
            path = f"press.{name}"
        elif exc.en.startswith("frame length") and p.geometry.frame is not None:
            path = "press.frame_O1C_mm"
        else:
            path = "press"
        return [BriefProblem(path, "", exc.en, exc.zh)]
    if keep is not None:
        keep["toggle"] = d
    return []


def synthesis(p: DieCutterParams, d: ToggleDesign | None = None) -> tuple[ToggleDesign, LinkageModel]:
    """The press (``d``: its design when the checks already made it)."""
    d = toggle_synthesis(p.geometry) if d is None else d
    return d, build_press(d, p)


# --------------------------------------------------------------------------- force amplification


@dataclass(frozen=True)
class PlatenTiming:
    """Crank phases (from position 1, the platen's bottom) where the platen crosses the
    clearance level H − c and the pressing level H − t, rising and falling [rad]."""

    clear_up: float = q("rad", "rising, the platen reaches the clearance level H − c")
    press_up: float = q("rad", "rising, it reaches the pressing level H − t (the cut begins)")
    top: float = q("rad", "its top (end of the rise)")
    press_down: float = q("rad", "falling, it leaves the pressing level")
    clear_down: float = q("rad", "falling, it is back below the clearance level")

    @property
    def clear_span(self) -> float:
        """Shaft angle during which the platen is at least c below its top [rad]."""
        return self.clear_up + TWO_PI - self.clear_down

    @property
    def press_span(self) -> float:
        """Rise through the pressing travel (force acting) [rad]."""
        return self.top - self.press_up


def _platen_s(model: LinkageModel, k, phase: float) -> float:
    z = model.mechanism.solve(np.array([k.start_angle + k.sense * phase])).points["D"].pos[0]
    return float(z.imag - k.points["D"][0].imag)


def platen_timing(model: LinkageModel, k, clearance: float, travel: float) -> PlatenTiming:
    """Level crossings of the platen by Brent's method on the solved linkage: s rises
    monotonically from position 1 (0) to the top (the working span) and falls back."""
    H, top = k.stroke, k.working_span

    def cross(level: float, lo: float, hi: float) -> float:
        return float(brentq(lambda ph: _platen_s(model, k, ph) - level, lo, hi, xtol=1e-13))

    return PlatenTiming(cross(H - clearance, 0.0, top), cross(H - travel, 0.0, top), top,
                        cross(H - travel, top, TWO_PI), cross(H - clearance, top, TWO_PI))


def unit_load_torque(model: LinkageModel, m) -> np.ndarray:
    """Crank torque [N·m per N] (in the sense of rotation) that balances a unit downward force
    on the platen, the links massless: kinetostatics group by group."""
    n = len(m.crank_angle)
    load = PointLoad("6", "D", np.full(n, -1j))
    fa = solve_forces(model.mechanism, m, [], [load], 0.0)
    return np.sign(model.crank_omega) * fa.driving_torque


def closed_form_unit_torque(d: ToggleDesign, m) -> np.ndarray:
    """The same by virtual work, M ω = F v_D, with v_D from closed forms: the four-bar's
    ω_CB/ω_2 = a sin(θ2 − θ3) / (c sin(θ4 − θ3)) and the toggle's
    dy/dθ4 = l_CB cos θ4 + l_CB² sin θ4 cos θ4 / √(l_BD² − l_CB² cos² θ4)."""
    a, c, ld = d.four.crank, d.four.rocker, d.geometry.toggle_BD
    th2, th3, th4 = (m.links[k].angle for k in ("2", "3", "4"))
    ratio = a * np.sin(th2 - th3) / (c * np.sin(th4 - th3))
    dy = c * np.cos(th4) + c ** 2 * np.sin(th4) * np.cos(th4) / np.sqrt(ld ** 2 - (c * np.cos(th4)) ** 2)
    omega = m.links["2"].omega
    return np.sign(omega) * dy * ratio


@dataclass(frozen=True)
class Amplification:
    """Stage 增力特性: the pressing force per unit crank torque and the torque the cut needs.

    Arrays over the press's phase array (grid then positions)."""

    timing: PlatenTiming
    unit_torque: np.ndarray       # M/F by kinetostatics (massless) [m]
    closed_form: np.ndarray       # M/F = v_D/|ω| by the closed forms [m]
    required_torque: np.ndarray   # F_c·M/F where the force acts, 0 elsewhere [N·m]
    peak_required: float          # [N·m]
    peak_phase: float             # [rad]
    table: tuple                  # rows (gap to the top [m], phase [rad], M/F [m], F/M [1/m], Π)
    max_error: float              # max |kinetostatics − closed form| / max |closed form| (rise)
    cut_work: float               # F_c·t [J]
    cycle_work: float             # ∮ M_b dφ [J]
    press_time: float             # time the force acts [s]
    top_ratio: float              # Π at the top (inf for a straight toggle)


def amplification(model: LinkageModel, d: ToggleDesign, k, raw, f, p: DieCutterParams) -> Amplification:
    n = k.grid_size
    timing = platen_timing(model, k, p.clearance, p.pressing_travel)
    unit = unit_load_torque(model, raw)
    closed = closed_form_unit_torque(d, raw)
    rising = k.phase[:n] <= k.working_span
    scale = float(np.max(np.abs(closed[:n][rising])))
    err = float(np.max(np.abs(unit[:n] - closed[:n])[rising]) / scale)
    acting = np.abs(f.resistance["R1"]) > 0
    required = np.where(acting, p.cutting_force * unit, 0.0)
    i = int(np.argmax(required[:n]))
    # The table: the platen's gap to its top, from the start of pressing to the top.
    a = d.four.crank
    gaps = [g for g in (p.pressing_travel, 2e-3, 1e-3, 0.5e-3, 0.1e-3, 0.01e-3)
            if g <= p.pressing_travel + 1e-15]
    phases = [float(brentq(lambda ph: _platen_s(model, k, ph) - (k.stroke - gap), 0.0,
                           k.working_span, xtol=1e-14)) for gap in gaps]
    at = model.mechanism.solve(k.start_angle + k.sense * np.array(phases + [k.working_span]))
    u_at = unit_load_torque(model, at)
    table = []
    for gap, ph, u in zip(gaps, phases, u_at[:-1]):
        table.append((gap, ph, float(u), 1.0 / float(u), a / float(u)))
    top_unit = float(abs(u_at[-1]))
    top_ratio = float("inf") if top_unit < 1e-12 * a else a / top_unit
    cycle_work = float(f.cycle_work)      # piece by piece between exact ends (= 2π·M̄_b)
    return Amplification(timing, unit, closed, required, float(required[i]), float(k.phase[i]),
                         tuple(table), err, p.cutting_force * p.pressing_travel, cycle_work,
                         timing.press_span / abs(p.crank_omega), top_ratio)


# --------------------------------------------------------------------------- drive and flywheel


def _peak_and_life(r: dict) -> tuple[float, float]:
    """The peak factor max|M_b| / mean M_b and the bearing life's equivalent load after the
    flywheel (the cycle's cube-mean torque / its mean)."""
    f = r["press_forces"]
    mb = f.balancing_torque[:r["press"].grid_size]
    return (float(f.peak_torque / f.mean_torque),
            float(np.mean(np.abs(mb) ** 3) ** (1 / 3) / f.mean_torque))


def _drive(r: dict, flywheel_shaft: int | None = None):
    """The drive delivers the crank's mean power at the distribution shaft's speed; the
    stages and shafts after the flywheel carry the peak of M_b (peak factor = peak / mean);
    with the flywheel on the distribution shaft, that shaft itself (between the flywheel and
    the crank). ``flywheel_shaft``: another placement than the brief's."""
    from ...stages.drive import design_drive

    p, f = r["params"], r["press_forces"]
    peak, life = _peak_and_life(r)
    j = p.flywheel_shaft if flywheel_shaft is None else flywheel_shaft

    # the flywheel's rim hangs on shaft j between its bearings (review 48 A: chapter 7 put the
    # 71 kg rim on shaft Ⅰ and the shaft carried nothing of it); its size follows from the
    # realised ratio down to the crank, which the shaft table gives
    def weights(table):
        if j < 1:
            return None
        ratio = table[j].speed_rpm / table[-1].speed_rpm
        return _rim_weight(_placed_flywheel(r, j, ratio), j, p)

    return design_drive(p.drive, f.mean_power, p.shaft_rpm, "mechanism", peak, j, life,
                        weights, crank=_crank(r))


def _rim_weight(fl: Flywheel, j: int, p) -> dict | None:
    """{shaft j: (the rim's weight [N], its width [m])}, None without a rim."""
    rim = fl.rim
    return {j: (rim.rim_mass * p.gravity, rim.width)} if rim is not None else None


def _placed_flywheel(r: dict, j: int, ratio: float) -> Flywheel:
    """The flywheel on drive shaft ``j`` turning ``ratio`` × the crank's speed: on the brief's
    shaft the brief's rim, on the other its rim diameter by :func:`other_rim_diameter`."""
    p, model, k, f = r["params"], r["press_model"], r["press"], r["press_forces"]
    n = k.grid_size
    exact = CycleIntegrals(model, k)
    if j == p.flywheel_shaft:
        spec = brief_flywheel(p, ratio)
    else:
        bare = design_flywheel(FlywheelSpec(p.fluctuation, ratio, j), k.phase[:n],
                               f.balancing_torque[:n], model.crank_omega, p.gravity, exact=exact)
        spec = FlywheelSpec(p.fluctuation, ratio, j, RimSpec(other_rim_diameter(bare.inertia, p),
                                                             p.rim_height_to_width,
                                                             p.specific_weight))
    return design_flywheel(spec, k.phase[:n], f.balancing_torque[:n], model.crank_omega,
                           p.gravity, exact=exact)


def _crank(r: dict) -> dict:
    """{the distribution shaft (the drive's last): the crank's largest load on it}."""
    from ...stages.crank_load import crank_load

    from ...i18n import N_, Msg

    # the gripper cam and the incomplete gear share the distribution shaft; the brief gives
    # no spring force nor feed resistance for them: named in the shaft's steps, not loaded
    others = (Msg(N_("the gripper cam")), Msg(N_("the incomplete gear")))
    load = crank_load(r["press_model"], r["press"], r["press_forces"], others)
    return {len(r["params"].drive.stages): replace(load, count=r["params"].linkages)}


@dataclass(frozen=True)
class PeakShaft:
    """A drive shaft after the flywheel, which carries the peak of M_b."""

    index: int = q("1", "drive shaft index (0 the motor shaft)")
    speed_rpm: float = q("rpm", "its speed")
    torque: float = q("N·m", "its torque from the mean power (the drive stage's)")
    peak_torque: float = q("N·m", "the same × the peak factor max|M_b| / mean M_b")
    d_seat: float = q("m", "seat diameter the drive design chose")
    d_peak: float = q("m", "torsion estimate A0·∛(P/n) with the peak power")


def peak_shafts(drive) -> tuple[PeakShaft, ...]:
    """The shafts after the flywheel carry the peak of M_b: their torsion estimate
    d ≥ A0 ∛(P/n) (the drive stage's, from the mean power) against the same estimate with the
    peak power T_peak·ω."""
    from ...core.strength import shaft_min_diameter
    from ...stages.drive_strength import A0, KEYWAY

    first = drive.peak_from_shaft
    if first is None:
        return ()
    out = []
    for sd in drive.shaft_designs:
        if sd.index < max(first, 1):
            continue
        sh = drive.shafts[sd.index]
        peak = sh.torque * drive.peak_factor
        d_peak = shaft_min_diameter(peak * sh.speed_rpm * np.pi / 30.0, sh.speed_rpm, A0, KEYWAY)
        out.append(PeakShaft(sd.index, sh.speed_rpm, sh.torque, peak, sd.d_seat, d_peak))
    return tuple(out)


def flywheel(r: dict) -> tuple[Flywheel, tuple]:
    """The one flywheel stage on drive shaft ``p.flywheel_shaft`` (its speed from the
    designed drive), and the shafts after it that carry the peak torque."""
    p, drive = r["params"], r["drive"]
    ratio = float(np.prod([st.ratio for st in drive.stages][p.flywheel_shaft:]))
    return _placed_flywheel(r, p.flywheel_shaft, ratio), peak_shafts(drive)


#: Density of steel [kg/m³] for the gear wheels' solid-disc mass estimate.
STEEL_DENSITY = 7850.0


@dataclass(frozen=True)
class GearStageSize:
    """A gear stage's size in one flywheel placement."""

    index: int = q("1", "drive stage index (0 from the motor)")
    module: float = q("m", "normal module m_n")
    d2: float = q("m", "wheel pitch diameter")
    face_width: float = q("m", "face width b")
    torque: float = q("N·m", "design torque on the wheel (the peak after the flywheel)")
    wheel_mass: float = q("kg", "solid-disc estimate ρ·π/4·d2²·b (an upper bound of the wheel)")


@dataclass(frozen=True)
class FlywheelPlacement:
    """The flywheel on one drive shaft: the flywheel and the drive downstream of it sized
    for that placement (the stages after the flywheel carry the peak of M_b)."""

    shaft: int = q("1", "drive shaft carrying the flywheel (the number of stages: the "
                   "distribution shaft)")
    speed_rpm: float = q("rpm", "flywheel shaft speed (the distribution shaft's nominal speed × "
                         "the realised ratios after it)")
    inertia: float = q("kg·m²", "J_F")
    rim: object = q("", "cast rim (mechdesign.core.flywheel.RimFlywheel)")
    gears: tuple[GearStageSize, ...] = q("", "the gear stages")
    shaft_seats: tuple[float, ...] = q("m", "hub-seat diameter of shafts 1 … n")
    gear_mass: float = q("kg", "the gear wheels' solid-disc estimates, summed")


@dataclass(frozen=True)
class PlacementComparison:
    """The brief's flywheel placement against the other one (the distribution shaft, or
    shaft 1 when the brief puts it there): both designed, nothing typed."""

    chosen: FlywheelPlacement = q("", "the brief's placement (the design of this report)")
    other: FlywheelPlacement = q("", "the other placement, designed the same way")


def _placement(fl: Flywheel, stages, shaft_designs) -> FlywheelPlacement:
    gears = []
    for sr in stages:
        d = sr.design
        if d is None or d.kind != "gear":
            continue
        d2 = float(d.forces["d2"])
        gears.append(GearStageSize(sr.index, float(d.module), d2, float(d.face_width), float(d.T2),
                                   float(STEEL_DENSITY * np.pi / 4 * d2 ** 2 * d.face_width)))
    return FlywheelPlacement(int(fl.shaft), fl.shaft_speed_rpm, fl.inertia, fl.rim, tuple(gears),
                             tuple(float(sd.d_seat) for sd in shaft_designs),
                             float(sum(g.wheel_mass for g in gears)))


def other_rim_diameter(inertia: float, p: DieCutterParams) -> float:
    """The brief's rim diameter when a rim of it can carry ``inertia`` as a thin rim
    (H ≤ D/2); else the smallest diameter that can, rounded up to 50 mm."""
    from ...stages.flywheel import smallest_rim_diameter

    rim = fw_rim(inertia, p.rim_diameter, p)
    if rim.height <= p.rim_diameter / 2:
        return p.rim_diameter
    d = smallest_rim_diameter(inertia, p.rim_height_to_width, p.specific_weight, p.gravity)
    return float(np.ceil(d / 0.05 - 1e-9) * 0.05)


def fw_rim(inertia: float, diameter: float, p: DieCutterParams):
    from ...core import flywheel as fw

    return fw.rim_dimensions(inertia, diameter, p.rim_height_to_width, p.specific_weight,
                             1.0, p.gravity)


def compare_placements(r: dict) -> PlacementComparison:
    """The flywheel on the other shaft — the distribution shaft, or shaft 1 when the brief
    puts it on the distribution shaft — with the drive's stages and shafts sized again for it
    (the motor, ratios and shaft table of the designed drive reused: they do not depend on
    the placement)."""
    from ...stages.drive import resized

    p = r["params"]
    shafts = len(p.drive.stages)
    other = shafts if p.flywheel_shaft < shafts else 1
    drive = r["drive"]
    peak, life = _peak_and_life(r)
    ratio = float(np.prod([st.ratio for st in drive.stages][other:]))
    fl = _placed_flywheel(r, other, ratio)
    sized = resized(drive, p.drive, peak, other, life, _rim_weight(fl, other, p), crank=_crank(r))
    if sized is None:                       # a worm's efficiency moved: design it all again
        again = _drive(r, other)
        sized = (again.stages, again.shaft_designs)
    return PlacementComparison(_placement(r["press_flywheel"], drive.stages, drive.shaft_designs),
                               _placement(fl, *sized))


# --------------------------------------------------------------------------- feed and cycle


@dataclass(frozen=True)
class Feed:
    """Stage 不完全齿轮送纸: the incomplete gear placed on the shaft, and the chain."""

    gear: object                # core.intermittent.IncompleteGear
    start_auto: bool
    sprocket_radius: float      # R_s = p / (2 sin(π/z_s)) [m]
    feed: float                 # chain travel per cycle = Δφ2/2π · z_s · p [m]
    chain_speed: float          # mean chain speed while moving = feed / t_m [m/s]
    chain_jump: float           # chain speed reached at once at engagement R_s Δω2 [m/s]
    warnings: tuple = ()
    curves: object = None       # core.intermittent.IntermittentCurves: what the report plots


def _wrap(x: float) -> float:
    return float(np.mod(x, TWO_PI))


def feed(amp: Amplification, p: DieCutterParams) -> Feed:
    from ...brief.components import incomplete_gear_to_si
    from ...core.intermittent import intermittent_curves

    free = incomplete_gear_to_si(p.gear_section, p.shaft_rpm)
    auto = p.feed_start is None
    if auto:
        t = amp.timing
        middle = t.clear_down + t.clear_span / 2
        start = _wrap(np.radians(np.round(np.degrees(middle - free.motion_angle / 2))))
    else:
        start = p.feed_start
    section = p.gear_section.model_copy(update={"motion_start_deg": float(np.degrees(start))})
    g = incomplete_gear_to_si(section, p.shaft_rpm)
    radius = p.chain_pitch / (2 * np.sin(np.pi / p.sprocket_teeth))
    travel = g.advance / TWO_PI * p.sprocket_teeth * p.chain_pitch
    times = g.times()
    jump = g.engagement_jump()
    notes = [finding_of(n.code, n.message) for n in g.notes]
    return Feed(g, auto, float(radius), float(travel), float(travel / times[1]),
                float(radius * jump.omega2), tuple(notes), intermittent_curves(g))


def _gripper_labels() -> dict[str, Msg]:
    """The grippers' phases by cam state (catalogue messages)."""
    return {"rise": Msg.pgettext("cycle phase", "opening"),
            "dwell_high": Msg.pgettext("cycle phase", "held open"),
            "return": Msg.pgettext("cycle phase", "closing"),
            "dwell_low": Msg.pgettext("cycle phase", "closed")}


@dataclass(frozen=True)
class CycleResult:
    """Stage 运动循环图: the diagram made from the three mechanisms and its checks."""

    diagram: cy.CycleDiagram
    checks: tuple
    gripper_start: float        # shaft angle where the cam's rise begins [rad]
    gripper_auto: bool
    warnings: tuple = ()


def platen_actuator(t: PlatenTiming) -> cy.Actuator:
    """The platen's phases from its simulated level crossings."""
    return cy.make_actuator("platen", Msg.pgettext("cycle", "lower platen"), "", t.clear_up, [
        ("rise", t.press_up - t.clear_up, Msg.pgettext("cycle phase", "rising")),
        ("work", t.press_down - t.press_up, Msg.pgettext("cycle phase", "die cutting")),
        ("return", t.clear_down - t.press_down, Msg.pgettext("cycle phase", "falling")),
        ("clear", t.clear_up + TWO_PI - t.clear_down, Msg.pgettext("cycle phase", "clear"))])


def gripper_actuator(programme, start: float) -> cy.Actuator:
    name = Msg.pgettext("cycle", "grippers")
    act = cy.actuator_from_cam_programme("gripper", name, "", programme, start)
    labels = _gripper_labels()
    return cy.make_actuator("gripper", name, "", start,
                            [(ph.state, ph.span) + ((labels[ph.state],) if ph.state in labels else ())
                             for ph in act.phases])


def chain_actuator(g) -> cy.Actuator:
    return cy.make_actuator("chain", Msg.pgettext("cycle", "chain feed"), "", g.motion_start,
                            [("move", g.motion_angle, Msg.pgettext("cycle phase", "feed")),
                             ("dwell", g.dwell_angle, Msg.pgettext("cycle phase", "dwell"))])


def timing_constraints(margin: float) -> list[cy.Constraint]:
    return [
        cy.Constraint("during", ("chain", "move"), ("platen", "clear"), margin,
                      *zh_en.gettext("the chain moves only while the platen is clear of the die "
                                     "(at least c below its top)")),
        cy.Constraint("during", ("platen", "work"), ("chain", "dwell"), margin,
                      *zh_en.gettext("the sheet and the chain stand still while the die cuts")),
        cy.Constraint("during", ("gripper", "rise"), ("chain", "dwell"), margin,
                      *zh_en.gettext("the grippers open only while the chain dwells")),
        cy.Constraint("during", ("gripper", "return"), ("chain", "dwell"), margin,
                      *zh_en.gettext("the grippers close before the chain moves again")),
    ]


def cycle(amp: Amplification, fd: Feed, cam, p: DieCutterParams) -> CycleResult:
    g = fd.gear
    programme = cam.params.programme
    auto = p.gripper_open is None
    if auto:
        open_span = float(sum(programme.spans[:3]))
        middle = g.motion_start + g.motion_angle + g.dwell_angle / 2
        start = _wrap(np.radians(np.round(np.degrees(middle - open_span / 2))))
    else:
        start = p.gripper_open
    acts = [platen_actuator(amp.timing), gripper_actuator(programme, start), chain_actuator(g)]
    diagram = cy.build_cycle(acts, abs(p.crank_omega), 0.0, timing_constraints(p.margin))
    checks = tuple(cy.check_constraints(diagram))
    warnings = []
    for c in checks:
        if not c.ok:
            con = c.constraint
            warnings.append(finding(
                "timing",
                N_("timing conflict: {text} (slack {slack:.2f}°, needs ≥ {margin:g}°); change the "
                   "placement in timing or the cam's or the incomplete gear's motion angle."),
                text=Pair(con.text_zh, con.text_en), slack=c.slack * DEG, margin=con.margin * DEG))
    return CycleResult(diagram, checks, start, auto, tuple(warnings))


# --------------------------------------------------------------------------- verification


@dataclass(frozen=True)
class DieVerification:
    """The machine's own checks (the shared linkage checks are in ``press_verification``)."""

    stroke_simulated: float = q("m", "stroke by the linkage engine's position search")
    stroke_error: float = q("m", "simulated stroke − H")
    K_position_search: float = q("1", "K from the position search (limited by the flat top, "
                                      "see K_search_tol)")
    top_toggle_angle: float = q("rad", "angle of CB from the guide at the simulated top")
    amplification_error: float = q("1", "max |kinetostatics − virtual-work closed form| / "
                                        "max |closed form| of M/F over the rise")
    energy_ratio: float = q("1", "∮ M_b dφ / (F_c·t)")
    platen_mismatch: float = q("rad", "shaft angle where the diagram's platen row disagrees "
                                      "with the simulated s(φ)")
    gripper_mismatch: float = q("rad", "… where its gripper row disagrees with the cam's lift")
    chain_mismatch: float = q("rad", "… where its chain row disagrees with the incomplete "
                                     "gear's motion")
    feed_error: float = q("m", "chain feed − bar spacing")
    grid_step: float = q("rad", "crank-angle step of the grid")
    top_order: float = q("1", "n in H − s ≈ c·Δφⁿ near the top (4: the toggle straight at the "
                              "dead centre)")
    search_angle_tol: float = q("rad", "how closely a position search can place such a top")
    K_search_tol: float = q("1", "the resulting uncertainty of K_position_search")
    K_velocity_tol: float = q("1", "the same for the zeros of v_D ∝ Δφⁿ⁻¹ (press.time_ratio)")


def verify(model: LinkageModel, d: ToggleDesign, k, v_link, amp: Amplification, fd: Feed,
           cam, cyc: CycleResult, p: DieCutterParams) -> DieVerification:
    from ...core.extremes import refine_extreme

    n = k.grid_size
    phase = k.phase[:n]
    step = TWO_PI / n
    # The simulated top (bounded search between grid points) and the toggle's angle there.
    ph_top, _ = refine_extreme(lambda ph: _platen_s(model, k, ph), phase, k.s[:n], largest=True)
    at_top = model.mechanism.solve(np.array([k.start_angle + k.sense * ph_top]))
    b_top = at_top.points["B"].pos[0]
    top_angle = float(abs(np.angle(b_top * np.exp(-1j * np.pi / 2))))
    diagram = cyc.diagram
    clear_sim = k.s[:n] < k.stroke - p.clearance
    clear_row = cy.state_at(diagram.actuator("platen"), phase) == "clear"
    prog = cam.params.programme
    open_cam = prog.evaluate(np.mod(phase - cyc.gripper_start, TWO_PI)).s > 1e-9 * prog.stroke
    open_row = cy.state_at(diagram.actuator("gripper"), phase) != "dwell_low"
    moving_gear = fd.gear.driven_motion(phase).moving
    moving_row = cy.moving_at(diagram.actuator("chain"), phase)
    # Flatness of the top: H − s = c Δφⁿ fitted through two small gaps (2·10⁻⁷ H and 2·10⁻⁹ H);
    # a search on s sees nothing below the rounding of y_D, 4 ε |y_D|.
    gaps = (2e-7 * k.stroke, 2e-9 * k.stroke)
    deltas = [amp.timing.top - float(brentq(lambda ph: _platen_s(model, k, ph) - (k.stroke - g_),
                                             0.0, amp.timing.top, xtol=1e-15)) for g_ in gaps]
    order = float(np.log(gaps[0] / gaps[1]) / np.log(deltas[0] / deltas[1]))
    c = gaps[1] / deltas[1] ** order
    eps_m = np.finfo(float).eps
    tol = float((4 * eps_m * abs(d.top_height) / c) ** (1 / order))
    # v_D/ω = n c Δφⁿ⁻¹ is computed to about 10 ε max|dy_D/dφ| (cancellation at the dead centre)
    slope = float(np.max(np.abs(k.v[:n]))) / abs(model.crank_omega)
    tol_v = float((10 * eps_m * slope / (order * c)) ** (1 / (order - 1)))
    back = TWO_PI - k.working_span
    return DieVerification(
        stroke_simulated=v_link.stroke, stroke_error=v_link.stroke - d.geometry.stroke,
        K_position_search=v_link.time_ratio, top_toggle_angle=top_angle,
        amplification_error=amp.max_error, energy_ratio=amp.cycle_work / amp.cut_work,
        platen_mismatch=float(np.sum(clear_sim != clear_row) * step),
        gripper_mismatch=float(np.sum(open_cam != open_row) * step),
        chain_mismatch=float(np.sum(moving_gear != moving_row) * step),
        feed_error=fd.feed - p.bar_spacing, grid_step=step, top_order=order,
        search_angle_tol=tol, K_search_tol=float(tol * TWO_PI / back ** 2),
        K_velocity_tol=float(max(tol_v * TWO_PI / back ** 2, 1e-12)))


def _verify(r: dict) -> DieVerification:
    return verify(r["press_model"], r["toggle"], r["press"], r["press_verification"],
                  r["amplification"], r["feed"], r["cam"], r["cycle"], r["params"])


# --------------------------------------------------------------------------- stages


def stages(params: DieCutterParams) -> list[Stage]:
    from ...stages.cam import cam_stage

    press = [s for s in linkage_stages(model_key="press_model", prefix="press")
             if s.key != "press_flywheel"]
    return [
        Stage(("toggle", "press_model"), titles.pgettext("stage", "toggle press synthesis"),
              lambda r: synthesis(r["params"], r.get("checked", {}).get("toggle"))),
        *press,
        Stage("amplification", titles.pgettext("stage", "force amplification"),
              lambda r: amplification(r["press_model"], r["toggle"], r["press"], r["press_raw"],
                                      r["press_forces"], r["params"])),
        Stage("drive", titles.pgettext("stage", "drive"), _drive),
        Stage(("press_flywheel", "peak_shafts"), titles.pgettext("stage", "flywheel"),
              flywheel),
        Stage("flywheel_placement", titles.pgettext("stage", "flywheel placement"),
              compare_placements),
        cam_stage(),
        Stage("feed", titles.pgettext("stage", "incomplete-gear feed"),
              lambda r: feed(r["amplification"], r["params"])),
        Stage("cycle", titles.pgettext("stage", "motion cycle diagram"),
              lambda r: cycle(r["amplification"], r["feed"], r["cam"], r["params"])),
        Stage("verification", titles.pgettext("stage", "verification"), _verify),
    ]


@dataclass(frozen=True)
class ToggleDoc:
    """The toggle press's dimensions and placement (C at the origin, y up)."""

    swing: float = q("rad", "ψ of the toggle CB (the four-bar's rocker)")
    theta: float = q("rad", "extreme-position angle θ = π(K − 1)/(K + 1)")
    crank: float = q("m", "L_O1A")
    coupler: float = q("m", "L_AB")
    toggle_CB: float = q("m", "L_CB")
    toggle_BD: float = q("m", "L_BD")
    frame_O1C: float = q("m", "L_O1C")
    O1: complex = q("m", "crank pivot O1")
    B_top: complex = q("m", "B with the platen at its top")
    B_bottom: complex = q("m", "B with the platen at its bottom")
    crank_top: float = q("rad", "crank angle at the platen's top, CCW from +x")
    crank_bottom: float = q("rad", "crank angle at the platen's bottom")
    branch: int = q("1", "assembly branch (±1) of the RRR group A, C → B")
    mirrored: bool = q("", "the θ-circle drawing mirrored so that the rise is the slow stroke")
    gamma_min: float = q("rad", "γ_min of the four-bar O1ABC (closed form)")
    top_height: float = q("m", "platen D above C at the top")
    bottom_height: float = q("m", "platen D above C at the bottom")
    top_position: str = q("", "'extended' or 'folded': the crank-rocker extreme at the top")
    given: bool = q("", "the crank-rocker's lengths are the brief's press.dimensions (no synthesis; "
                    "θ, ψ, K and the stroke derived from them)")


@dataclass(frozen=True)
class AmplificationRow:
    """The force amplification at a gap to the top."""

    gap: float = q("m", "platen's gap to its top")
    phase: float = q("rad", "crank phase from position 1 where the gap is reached")
    torque_per_force: float = q("m", "M/F, crank torque per newton on the platen")
    force_per_torque: float = q("1/m", "F/M")
    ratio: float = q("1", "Π = L_O1A·F/M")


@dataclass(frozen=True)
class AmplificationDoc:
    """Force amplification (增力特性): the pressing force per unit crank torque."""

    platen_timing: PlatenTiming = q("", "crank phases from position 1 (the platen's bottom) "
                                        "of the platen's level crossings")
    unit_torque_grid: np.ndarray = q("m", "M/F by kinetostatics (links massless) over the grid")
    required_torque_grid: np.ndarray = q("N·m", "F_c·M/F where the cutting force acts, 0 elsewhere")
    peak_required_torque: float = q("N·m", "max of required_torque_grid")
    peak_phase: float = q("rad", "crank phase of that peak")
    table: tuple[AmplificationRow, ...] = q("", "from the start of pressing to 0.01 mm below the top")
    cut_work: float = q("J", "F_c·t")
    cycle_work: float = q("J", "∮ M_b dφ")
    press_time: float = q("s", "time the cutting force acts")


@dataclass(frozen=True)
class FeedDoc:
    """The incomplete gear placed on the shaft, and the gripper chain it drives."""

    gear: IntermittentDocument = q("", "the incomplete gear")
    start_auto: bool = q("", "the gear's meshing start placed automatically (centred in "
                                  "the platen's clear span)")
    sprocket_radius: float = q("m", "R_s = p / (2 sin(π/z_s))")
    feed: float = q("m", "chain travel per cycle Δφ2/2π·z_s·p")
    chain_speed: float = q("m/s", "mean chain speed while it moves")
    chain_jump: float = q("m/s", "chain speed reached at once at engagement R_s·Δω2")


@dataclass(frozen=True)
class DieCutterCycle(CycleDocument):
    """The motion cycle diagram of the platen, the grippers and the chain."""

    gripper_start: float = q("rad", "shaft angle where the gripper cam's rise begins")
    gripper_auto: bool = q("", "that angle placed automatically (mid-dwell of the chain)")


@dataclass(frozen=True)
class DieCutterResults:
    """Semi-automatic flat die-cutter (半自动平压模切机). One distribution shaft drives the
    toggle press (crank O1A 2, coupler AB 3, toggle links CB 4 and BD 5, lower platen D 6 on
    a vertical guide through C), the gripper cam and the incomplete gear of the gripper
    chain. Frame: C at the origin, y up; crank phases from position 1, the platen's bottom;
    `press` is the linkage engine's result of the press with the platen rising (+y) as the
    working stroke."""

    schema: str = q("", "'mechdesign.results/2'")
    machine: str = q("", "'die_cutter'")
    units: str = q("", "reminder of the unit system")
    shaft_speed_rpm: float = q("rpm", "distribution shaft speed (one turn per sheet)")
    cutting_force: float = q("N", "die-cutting resistance F_c")
    pressing_travel: float = q("m", "last part t of the rise over which F_c acts")
    clearance: float = q("m", "gap c below the top the platen must reach before the sheet moves")
    toggle: ToggleDoc = q("", "the toggle press's synthesis")
    press: LinkageDocument = q("", "the press on the linkage engine (no flywheel here: see flywheel)")
    amplification: AmplificationDoc = q("", "force amplification")
    flywheel: Flywheel = q("", "the flywheel (the one flywheel stage) on the drive shaft chosen")
    peak_shafts: tuple[PeakShaft, ...] = q("", "shafts after the flywheel carrying the peak of M_b")
    flywheel_placement: PlacementComparison = q("", "the brief's flywheel placement against the "
                                                "other one, both designed")
    drive: DriveDocument = q("", "the drive (motor → … → distribution shaft)")
    cam: CamDocument = q("", "the gripper-opening cam")
    feed: FeedDoc = q("", "the incomplete-gear chain feed")
    cycle: DieCutterCycle = q("", "the motion cycle diagram")
    verification: DieVerification = q("", "the machine's own self-checks (the press's are in "
                                          "press.verification)")


def results_document(r: dict) -> DieCutterResults:
    """Everything computed, in SI units, for ``results.json``."""
    from ...core.intermittent import intermittent_document
    from ...results import SCHEMA, UNITS_NOTE
    from ...stages.cam import cam_document
    from ...stages.drive import drive_document
    from ...stages.linkage import linkage_document

    d, amp, fl, fd, cyc, v = (r[key] for key in ("toggle", "amplification", "press_flywheel",
                                                 "feed", "cycle", "verification"))
    p = r["params"]
    fb = d.four
    n = r["press"].grid_size
    return DieCutterResults(
        schema=SCHEMA, machine="die_cutter", units=UNITS_NOTE,
        shaft_speed_rpm=p.shaft_rpm, cutting_force=p.cutting_force,
        pressing_travel=p.pressing_travel, clearance=p.clearance,
        toggle=ToggleDoc(d.swing, d.theta, fb.crank, fb.coupler, fb.rocker, d.geometry.toggle_BD,
                         fb.frame, d.O1, d.B_top, d.B_bottom, d.crank_top, d.crank_bottom,
                         d.branch, d.mirrored, d.gamma_min, d.top_height, d.bottom_height,
                         d.geometry.top_position, d.geometry.given is not None),
        press=linkage_document(r["press_model"], r["press"], r["press_forces"], None,
                               r["press_verification"], r.get("press_graphical")),
        amplification=AmplificationDoc(
            amp.timing, amp.unit_torque[:n], amp.required_torque[:n], amp.peak_required,
            amp.peak_phase, tuple(AmplificationRow(*row) for row in amp.table), amp.cut_work,
            amp.cycle_work, amp.press_time),
        flywheel=fl, peak_shafts=r["peak_shafts"], flywheel_placement=r["flywheel_placement"],
        drive=drive_document(r["drive"]), cam=cam_document(r["cam"]),
        feed=FeedDoc(intermittent_document(fd.gear), fd.start_auto, fd.sprocket_radius, fd.feed,
                     fd.chain_speed, fd.chain_jump),
        cycle=cy.cycle_document(cyc.diagram, cyc.checks, DieCutterCycle,
                                gripper_start=cyc.gripper_start, gripper_auto=cyc.gripper_auto),
        verification=v)
