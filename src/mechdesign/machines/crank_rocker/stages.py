"""Crank-rocker synthesis machine (``machine: crank_rocker``, seed 001a).

Stages: the crank-rocker with the largest minimum transmission angle for K, ψ and the
rocker length (crank pivot searched over the allowed arc of the θ-circle); the textbook
design with a given frame; the offset slider-crank from K, H and e; the design chart
(optimum l3/l4 and γmin against ψ, one curve per θ); and the verification, which
simulates every design with :mod:`mechdesign.core.mechanism` (crank + RRR or RRP group)
and measures K, ψ (or the stroke) and γmin from the simulated motion.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core import fourbar as fb
from ...core.extremes import fminbound, grid_roots, refine_extreme
from ...core.fields import q
from ...i18n import N_, Msg
from ...core.mechanism import RRP, RRR, Crank, Mechanism
from ...pipeline import Stage
from ...stages.findings import Finding, Pair, encode, finding
from ...stages.linkage import LinkageDocument

DEG = 180.0 / np.pi


# ------------------------------------------------------------------------------ results

@dataclass(frozen=True)
class Design:
    """A crank-rocker placed in the construction's coordinates (D at the origin) [m]."""

    label: str                     # the brief's name ('zh / en'), or the program's as a Msg
    design: fb.FourBar
    a_pivot: complex               # crank pivot A
    position: float | None         # arc parameter of A (None for a compared design)
    gamma_min: float               # closed form [rad]
    gamma_max: float
    theta: float                   # closed-form θ, ψ [rad]
    swing: float
    grashof: str
    warnings: list[Finding]


@dataclass(frozen=True)
class OptimumResult:
    construction: fb.CircleConstruction
    best: Design
    far_side_gamma: float | None    # best γmin on the mirror circle (A beyond the chord) [rad]
    warnings: list[Finding]


@dataclass(frozen=True)
class SliderResult:
    construction: fb.SliderConstruction
    crank: float
    rod: float
    offset: float
    stroke: float
    K: float
    theta: float
    alpha_slow: float               # closed form [rad]
    alpha_fast: float
    alpha_allowed: float
    warnings: list[Finding]


@dataclass(frozen=True)
class ChartResult:
    thetas: tuple[float, ...]       # [rad]
    swings: np.ndarray              # [rad]
    ratio: np.ndarray               # l3/l4 at the optimum, shape (len(thetas), len(swings))
    gamma: np.ndarray               # γmin at the optimum [rad]


@dataclass(frozen=True)
class Simulation:
    """A design simulated over one revolution of the crank."""

    label: str
    phi: np.ndarray                 # crank angle from the frame line A→D [rad] (grid)
    rocker_angle: np.ndarray        # [rad], relative to the mean of the extremes
    omega3: np.ndarray              # the rocker's (link 3) [rad/s]
    alpha3: np.ndarray              # [rad/s²]
    gamma: np.ndarray               # transmission angle [rad]
    phi_extremes: tuple[float, float]   # crank angles of the rocker's extremes [rad]
    swing: float                    # simulated ψ [rad]
    theta: float                    # simulated θ [rad]
    K: float
    gamma_min: float                # simulated [rad]
    phi_gamma_min: float
    closure: float                  # largest |loop closure| residual [m]
    points: dict                    # positions at the two extremes (complex) for drawing


@dataclass(frozen=True)
class SliderSimulation:
    phi: np.ndarray
    s: np.ndarray                   # slider position along the guide [m]
    alpha: np.ndarray               # pressure angle [rad]
    slow: np.ndarray                # mask: grid points in the slow stroke
    stroke: float
    theta: float
    K: float
    alpha_slow: float
    alpha_fast: float
    closure: float


@dataclass(frozen=True)
class VerifyResult:
    sims: list[Simulation]          # optimum first, then textbook, then the compared designs
    slider: SliderSimulation | None
    optimum_neighbours: tuple[float, float]   # γmin at p* ∓ 1e-3·span [rad]
    optimum_scan: float             # largest γmin on a dense scan of the arc [rad]


# ------------------------------------------------------------------------------- stages

def _both(msgid: str, form: str = "{zh} / {en}") -> str:
    """'最优设计 / optimum': a name as the stages and results hold it, both languages (the
    Chinese of the run's catalogue)."""
    from ...i18n import tr

    return form.format(zh=tr("zh")(msgid), en=msgid)


def _place(label: str, cons: fb.CircleConstruction, p: float, gamma_allowed: float) -> Design:
    design = fb.design_at(cons, p)
    return _describe(label, design, complex(cons.point(p)), p, gamma_allowed)


def _describe(label, design, a_pivot, p, gamma_allowed) -> Design:
    ok, kind = fb.grashof(design)
    gmin, gmax = fb.transmission_angle_extremes(design)
    theta, swing = fb.crank_rocker_extremes(design) if ok and kind == "crank-rocker" else (np.nan, np.nan)
    warnings = []
    # the program's name (a catalogue message) or the brief's 'zh / en' text
    name = label if isinstance(label, Msg) else Pair(*(label.split(" / ", 1) if " / " in label else (label, label)))
    if not (ok and kind == "crank-rocker"):
        warnings.append(finding(
            "grashof", N_("{label}: the lengths fail Grashof's crank condition ({kind}; {sums}); the crank "
                          "cannot turn fully: the crank must be the shortest link and shortest + longest ≤ "
                          "the other two."), label=name, kind=kind, sums=fb.grashof_sums_message(design)))
    if gmin < gamma_allowed:
        warnings.append(finding(
            "transmission_angle",
            N_("{label}: the minimum transmission angle γmin = {g:.2f}° is below the allowed "
               "[γ] = {allowed:.0f}°; a smaller swing ψ (rocker_swing_deg) or time ratio "
               "K (time_ratio_K or extreme_angle_deg) raises γmin (see the design chart)."),
            label=name, g=gmin * DEG, allowed=gamma_allowed * DEG))
    return Design(label, design, a_pivot, p, gmin, gmax, theta, swing, kind, warnings)


def optimum_stage(r: dict) -> OptimumResult:
    p = r["params"]
    cons = fb.circle_construction_theta(p.theta, p.swing, p.rocker)
    pos, _ = fb.optimal_position_theta(p.theta, p.swing, p.rocker)
    best = _place(Msg(N_("optimum")), cons, pos, p.gamma_allowed)
    try:
        far = fb.optimal_position_theta(p.theta, p.swing, p.rocker, side=-1)[1]
    except fb.SynthesisError:
        far = None
    return OptimumResult(cons, best, far, list(best.warnings))


def textbook_stage(r: dict) -> Design:
    p = r["params"]
    cons = r["optimum"].construction
    pos = fb.position_for_frame(cons, p.frame)
    return _place(Msg(N_("given frame")), cons, pos, p.gamma_allowed)


def given_stage(r: dict) -> Design:
    """The brief's dimensions placed exactly (no synthesis) in the θ-circle construction of
    the θ, ψ and l3 they have: D at the origin, A at the distance l4 from D and l2 − l1 from
    C1 (law of cosines), on the side where AC2 = l2 + l1."""
    p = r["params"]
    g = p.given
    cons = r["optimum"].construction
    a, b, c, d = g.crank, g.coupler, g.rocker, g.frame
    u = cons.c1 / abs(cons.c1)
    cos_t = (d * d + c * c - (b - a) ** 2) / (2.0 * d * c)
    t = np.arccos(np.clip(cos_t, -1.0, 1.0))
    cands = [d * u * np.exp(1j * s * t) for s in (+1.0, -1.0)]
    pivot = min(cands, key=lambda x: abs(abs(x - cons.c2) - (b + a)))
    try:
        pos = fb.position_for_frame(cons, d)
    except fb.SynthesisError:
        pos = None
    return _describe(Msg(N_("given dimensions")), g, complex(pivot), pos, p.gamma_allowed)


def slider_stage(r: dict) -> SliderResult:
    sp = r["params"].slider
    allowed = np.pi / 2.0 - r["params"].gamma_allowed
    cons = fb.slider_crank_construction(sp.K, sp.stroke, sp.offset)
    if sp.crank is not None:
        a, b = sp.crank, sp.rod
    else:
        a, b = fb.offset_slider_crank(sp.K, sp.stroke, sp.offset)
    slow, fast = fb.slider_crank_pressure_angles(a, b, sp.offset)
    warnings = []
    if slow > allowed:
        warnings.append(finding(
            "pressure_angle",
            N_("offset slider-crank: the largest pressure angle of the working (slow) stroke, "
               "{slow:.2f}°, exceeds the allowed {allowed:.0f}°; change the offset e "
               "(slider_crank.offset_e_mm) or reduce K (slider_crank.time_ratio_K)."),
            slow=slow * DEG, allowed=allowed * DEG))
    return SliderResult(cons, a, b, sp.offset, sp.stroke, sp.K, sp.theta, slow, fast, allowed,
                        warnings)


def chart_stage(r: dict) -> ChartResult:
    p = r["params"]
    swings = np.linspace(p.chart_swing[0], p.chart_swing[1], p.chart_points)
    ratio = np.full((len(p.chart_thetas), len(swings)), np.nan)
    gamma = np.full_like(ratio, np.nan)
    for i, th in enumerate(p.chart_thetas):
        for j, ps in enumerate(swings):
            if th == 0.0:
                # A at infinity on the line C1C2: the supremum γmin = 90° − ψ/2, l3/l4 → 0
                ratio[i, j], gamma[i, j] = 0.0, np.pi / 2.0 - ps / 2.0
                continue
            try:
                pos, g = fb.optimal_position_theta(th, ps, 1.0, grid=241)
            except fb.SynthesisError:
                continue
            cons = fb.circle_construction_theta(th, ps, 1.0)
            ratio[i, j] = 1.0 / float(cons.designs(pos)[2])
            gamma[i, j] = g
    return ChartResult(tuple(p.chart_thetas), swings, ratio, gamma)


# ------------------------------------------------------------------------- verification

def folded_branch(design: fb.FourBar, a_pivot: complex, c1: complex) -> int:
    """RRR branch (+1: C left of B→D) that puts C at the folded extreme C1 (D at the origin)."""
    u = (c1 - a_pivot) / abs(c1 - a_pivot)
    b1 = a_pivot - design.crank * u
    return 1 if (np.conj(0j - b1) * (c1 - b1)).imag > 0 else -1


def _four_bar_mechanism(design: fb.FourBar, a_pivot: complex, branch: int, omega: float
                        ) -> Mechanism:
    """Crank AB (link 1) + RRR group BC (2) / DC (3), frame AD (4), as the textbook numbers a
    four-bar and as the synthesis names the lengths (l1 … l4); D at the origin."""
    mech = Mechanism("4", {"A": a_pivot, "D": 0j})
    mech.add(Crank("crank", "1", "A", "B", design.crank, omega))
    mech.add(RRR("RRR", "2", "3", "B", "D", "C", design.coupler, design.rocker, branch))
    return mech


def _refine_roots(fun, phi, values) -> list[float]:
    """Roots of fun(φ) between grid neighbours where ``values`` changes sign (periodic)."""
    return grid_roots(fun, phi, values)


def _min_refined(fun, phi, values, step) -> tuple[float, float]:
    """γ_min's crank angle and value: Brent between the grid's neighbours, the place of
    the (smooth) minimum polished to the zero of its slope (Brent alone fixes it only to
    √ε·|φ| ≈ 1e-8 rad, moved by the last bit of numpy's functions)."""
    from ...core.extremes import polish_minimum

    x, v = refine_extreme(fun, phi, values, keep_grid=True)
    x = polish_minimum(fun, x, x - step, x + step, 0.01 * step)
    return x, float(fun(x))


def _transmission(m) -> np.ndarray:
    u3 = m.points["C"].pos - m.points["B"].pos
    u4 = m.points["C"].pos - m.points["D"].pos
    delta = np.abs(np.angle(u3 / u4))
    return np.minimum(delta, np.pi - delta)


def simulate_four_bar(label: str, design: fb.FourBar, a_pivot: complex, branch: int,
                      omega: float, n: int) -> Simulation:
    """Simulate a crank-rocker with D at the origin and the crank pivot at ``a_pivot``: the
    rocker's extremes are the roots of ω3(φ) (bracketed on the grid, brentq); γmin by a
    bounded scalar search around the grid minimum. The crank angle φ is measured from the
    frame line A→D (φ = 0: crank along AD, pointing at D)."""
    mech = _four_bar_mechanism(design, a_pivot, branch, omega)
    phi = np.angle(-a_pivot) + np.arange(n) * (2.0 * np.pi / n)
    m = mech.solve(phi)
    th3 = m.links["3"].angle
    ref = float(th3[0])

    def rel(x):
        return np.angle(np.exp(1j * (x - ref)))

    w3 = m.links["3"].omega

    def w_at(x):
        return float(mech.solve(np.array([x])).links["3"].omega[0])
    roots = _refine_roots(w_at, phi, w3)
    if len(roots) != 2:
        raise fb.SynthesisError(N_("{label}: the simulated rocker has {n} extreme positions "
                                   "per revolution, not 2: it is not a crank-rocker"), label=label, n=len(roots))
    ends = mech.solve(np.array(roots))
    ang = rel(ends.links["3"].angle)
    i_max = int(np.argmax(ang))
    phi_max, phi_min = roots[i_max], roots[1 - i_max]
    swing = float(ang[i_max] - ang[1 - i_max])
    span = (phi_max - phi_min) % (2.0 * np.pi)
    slow, fast = max(span, 2 * np.pi - span), min(span, 2 * np.pi - span)
    theta = float(abs(np.pi - span))
    gam = _transmission(m)

    def g_at(x):
        return float(_transmission(mech.solve(np.array([x])))[0])
    phi_g, g_min = _min_refined(g_at, phi, gam, 2.0 * np.pi / n)
    # loop closure A + AB + BC − DC − AD = 0 with the simulated link angles
    loop = (a_pivot + design.crank * np.exp(1j * m.links["1"].angle)
            + design.coupler * np.exp(1j * m.links["2"].angle)
            - design.rocker * np.exp(1j * m.links["3"].angle))
    closure = float(np.max(np.abs(loop)))
    mid = 0.5 * (ang[0] + ang[1])
    pts = {k: ends.points[k].pos for k in ("A", "B", "C", "D")}
    base = np.angle(-a_pivot)
    return Simulation(label, phi - base, rel(th3) - mid, w3, m.links["3"].alpha, gam,
                      (float(roots[0] - base) % (2 * np.pi), float(roots[1] - base) % (2 * np.pi)),
                      swing, theta, slow / fast, g_min, float(phi_g - base) % (2 * np.pi), closure, pts)


def simulate_slider(res: SliderResult, omega: float, n: int) -> SliderSimulation:
    """Crank AB (1) + RRP group: rod BC (2), slider C (3) on the guide y = −e of the frame (4)
    (A at the origin, C ahead of B's foot), numbered as the kinematic sheet numbers them."""
    mech = Mechanism("4", {"A": 0j})
    mech.add(Crank("crank", "1", "A", "B", res.crank, omega))
    mech.add(RRP("RRP", "2", "3", "B", "C", res.rod, complex(0.0, -res.offset), 0.0, +1, "4"))
    phi = np.arange(n) * (2.0 * np.pi / n)
    m = mech.solve(phi)
    s = m.slides["3"].s
    ds = m.slides["3"].ds

    def ds_at(x):
        return float(mech.solve(np.array([x])).slides["3"].ds[0])
    roots = _refine_roots(ds_at, phi, ds)
    if len(roots) != 2:
        raise fb.SynthesisError(N_("the simulated slider has {n} dead centres, not 2"), n=len(roots))
    ends = mech.solve(np.array(roots)).slides["3"].s
    i_max = int(np.argmax(ends))
    phi_max, phi_min = roots[i_max], roots[1 - i_max]
    stroke = float(ends[i_max] - ends[1 - i_max])
    out_span = (phi_max - phi_min) % (2.0 * np.pi)       # crank turn of the outward stroke
    theta = float(abs(np.pi - out_span))
    K = max(out_span, 2 * np.pi - out_span) / min(out_span, 2 * np.pi - out_span)

    def alpha_of(mm):
        u = mm.points["C"].pos - mm.points["B"].pos
        return np.arcsin(np.abs(u.imag) / np.abs(u))
    alpha = alpha_of(m)
    outward = ((phi - phi_min) % (2.0 * np.pi)) < out_span
    slow = outward if out_span > np.pi else ~outward
    step = 2.0 * np.pi / n

    def alpha_at(x):
        return float(alpha_of(mech.solve(np.array([x])))[0])

    def stroke_max(start, length):
        """Largest α over the stroke that begins at the dead centre ``start`` [rad] and lasts
        ``length`` [rad] of crank turn; the search stays inside the stroke."""
        u = (phi - start) % (2.0 * np.pi)
        inside = u <= length
        k = int(np.argmax(np.where(inside, alpha, -np.inf)))
        lo, hi = max(0.0, u[k] - step), min(length, u[k] + step)
        _, f_min = fminbound(lambda v: -alpha_at(start + v), lo, hi, xatol=1e-12)
        return max(float(alpha[k]), -f_min, alpha_at(start), alpha_at(start + length))
    if out_span > np.pi:
        a_slow = stroke_max(phi_min, out_span)
        a_fast = stroke_max(phi_max, 2.0 * np.pi - out_span)
    else:
        a_fast = stroke_max(phi_min, out_span)
        a_slow = stroke_max(phi_max, 2.0 * np.pi - out_span)
    loop = (res.crank * np.exp(1j * m.links["1"].angle) + res.rod * np.exp(1j * m.links["2"].angle)
            - (complex(0.0, -res.offset) + s))
    return SliderSimulation(phi, s - ends[1 - i_max], alpha, slow, stroke, theta, K, a_slow,
                            a_fast, float(np.max(np.abs(loop))))


def verify_stage(r: dict) -> VerifyResult:
    p = r["params"]
    opt: OptimumResult = r["optimum"]
    cons = opt.construction
    branch = folded_branch(opt.best.design, opt.best.a_pivot, cons.c1)
    sims = [simulate_four_bar(opt.best.label, opt.best.design, opt.best.a_pivot, branch,
                              p.omega, p.grid_points)]
    if r.get("textbook") is not None:
        t = r["textbook"]
        sims.append(simulate_four_bar(t.label, t.design, t.a_pivot,
                                      folded_branch(t.design, t.a_pivot, cons.c1), p.omega,
                                      p.grid_points))
    # compared designs: the frame along our optimum's AD, the same assembly branch
    direction = opt.best.a_pivot / abs(opt.best.a_pivot)
    for cd in p.compare:
        sims.append(simulate_four_bar(cd.label, cd.design, direction * cd.design.frame, branch,
                                      p.omega, p.grid_points))
    slider = None
    if r.get("slider") is not None:
        slider = simulate_slider(r["slider"], p.omega, p.grid_points)
    span = cons.p_hi - cons.p_lo
    h = 1e-3 * span
    pos = opt.best.position
    neigh = (float(cons.gamma_min(pos - h)), float(cons.gamma_min(pos + h)))
    dense = cons.p_lo + span * (np.arange(1, 200_001) / 200_001)
    scan = float(np.max(cons.gamma_min(dense)))
    return VerifyResult(sims, slider, neigh, scan)


def compared_designs(r: dict) -> list[Design]:
    """The brief's compared designs with their closed-form θ, ψ, γ (report tables)."""
    p = r["params"]
    return [_describe(cd.label, cd.design, complex(-cd.design.frame, 0.0), None, p.gamma_allowed)
            for cd in p.compare]


def _kinds() -> dict:
    """Grashof's kinds of four-bar by name (fb.grashof), as messages."""
    from ...brief.common import Msg

    return {"crank-rocker": Msg.pgettext("linkage kind", "crank-rocker"),
            "double-crank": Msg.pgettext("linkage kind", "double-crank"),
            "double-rocker": Msg.pgettext("linkage kind", "double-rocker"),
            "triple-rocker": Msg.pgettext("linkage kind", "triple-rocker"),
            "change-point": Msg.pgettext("linkage kind", "change-point"),
            "rocker-crank": Msg.pgettext("linkage kind", "rocker-crank")}


def checks(p, keep: dict | None = None) -> list:
    """The feasibility checks of a run (after validation, once): can the θ-circle
    construction be made, does the given frame lie on its allowed arc, has the offset
    slider-crank a real solution, is every compared design a crank-rocker? Every problem as
    a :class:`~mechdesign.brief.loader.BriefProblem` at its brief field (the runner fills in
    the value)."""
    from ...brief.common import Given, Msg
    from ...brief.loader import BriefProblem

    out = []

    def problem(path: str, name: str, value: float, exc: fb.SynthesisError) -> None:
        out.append(BriefProblem(path, "", Msg(N_("{name} = {value:g}: {error}"), name=name, value=value,
                                              error=Given(exc.en, exc.zh))))

    try:
        cons = fb.circle_construction_theta(p.theta, p.swing, p.rocker)
    except fb.SynthesisError as exc:
        if p.given is not None:
            problem("dimensions", "ψ", p.swing * DEG, exc)
        else:
            problem("rocker_swing_deg", "rocker_swing_deg", p.swing * DEG, exc)
        cons = None
    if cons is not None and p.frame is not None and p.given is None:
        try:
            fb.position_for_frame(cons, p.frame)
        except fb.SynthesisError as exc:
            problem("frame_length_mm", "frame_length_mm", p.frame * 1e3, exc)
    if p.slider is not None:
        sp = p.slider
        try:
            if sp.crank is None:
                fb.offset_slider_crank(sp.K, sp.stroke, sp.offset)
            else:
                fb.slider_crank_construction(sp.K, sp.stroke, sp.offset)
        except fb.SynthesisError as exc:
            problem("slider_crank.offset_e_mm", "offset_e_mm", sp.offset * 1e3, exc)
    for i, cd in enumerate(p.compare):
        ok, kind = fb.grashof(cd.design)
        if not (ok and kind == "crank-rocker"):
            name = kind.split(" (", 1)[0]
            out.append(BriefProblem(
                f"compare.{i}", "",
                Msg(N_("compare.{i} ({label}): the lengths make a {kind}, not a crank-rocker; only "
                       "crank-rockers can be compared"), i=i, label=cd.label, kind=kind,
                    kind_name=_kinds().get(name, name))))
    return out


#: the links of the crank-rocker in the linkage engine (names shown on the sheets)
_LINK_NAMES = {"1": N_("crank AB"), "2": N_("coupler BC"), "3": N_("rocker CD")}
_MODEL_TITLE = N_("the crank-rocker as a linkage")


def linkage_model(r: dict):
    """The optimum crank-rocker as a model of the shared linkage engine
    (:mod:`mechdesign.stages.linkage`): crank AB (link 1) + RRR group BC (2) / DC (3), frame 4
    (the synthesis's l1 … l4 and the kinematic sheet's numbers), D at
    the origin, assembled on the branch of the simulation, the rocker's angle the output.
    Position 1 is the rocker extreme that starts the slow stroke (the working stroke of a
    crank-rocker with K > 1). No loads: the engine gives the kinematics, the analysis sheet's
    velocity and acceleration polygons and the graphical method."""
    from ...i18n import tr
    from ...stages import linkage as lk

    p = r["params"]
    opt: OptimumResult = r["optimum"]
    best = opt.best
    branch = folded_branch(best.design, best.a_pivot, opt.construction.c1)
    mech = _four_bar_mechanism(best.design, best.a_pivot, branch, p.omega)
    names = {k: Msg(v) for k, v in _LINK_NAMES.items()}      # translated where shown
    model = lk.LinkageModel(mech, p.omega, lk.Output("link", "3", 0.0, +1),
                            grid_points=p.grid_points,
                            transmission_angle_min=p.gamma_allowed, names=names)
    start, end = lk._strokes(model)[:2]
    span = (float(np.sign(p.omega)) * (end - start)) % (2.0 * np.pi)
    if span < np.pi:         # the rocker's angle falls in the slow stroke
        from dataclasses import replace

        model = replace(model, output=lk.Output("link", "3", 0.0, -1))
    return model


def stages(params) -> list[Stage]:
    out = [Stage("optimum", _both(N_("crank-rocker with the best transmission angle")), optimum_stage)]
    if params.given is not None:
        out.append(Stage("textbook", _both(N_("given dimensions → derived values")), given_stage))
    elif params.frame is not None:
        out.append(Stage("textbook", _both(N_("design from K with the given frame"), "{zh}/ {en}"),
                         textbook_stage))
    if params.slider is not None:
        out.append(Stage("slider", _both(N_("offset slider-crank")), slider_stage))
    out.append(Stage("chart", _both(N_("design chart")), chart_stage))
    out.append(Stage("compare", _both(N_("designs to compare")), compared_designs))
    out.append(Stage("verify", _both(N_("verification by simulation")), verify_stage))
    from ...stages.linkage import linkage_stages

    out.append(Stage("linkage_model", _both(_MODEL_TITLE), linkage_model))
    # no loads in the brief: no kinetostatics (the forces stage gives None, as the engine's
    # verification, polygons and graphical stages accept)
    out += [Stage(s.key, s.title, _no_forces) if s.key == "linkage_forces" else s
            for s in linkage_stages(model_key="linkage_model", prefix="linkage")]
    return out


def _no_forces(r: dict) -> None:
    return None


# ------------------------------------------------------------------------------ results

UNITS = "SI: m, rad; complex points as [x, y], rocker pivot D at the origin"


@dataclass(frozen=True)
class SpecDoc:
    """The design data of the brief (SI)."""

    K: float = q("1", "time ratio K")
    theta: float = q("rad", "extreme-position angle θ = π(K − 1)/(K + 1)")
    swing: float = q("rad", "rocker swing ψ")
    rocker: float = q("m", "rocker length L_CD")
    frame: float | None = q("m", "given frame L_AD (null: none given)")
    gamma_allowed: float = q("rad", "allowed transmission angle [γ]")


@dataclass(frozen=True)
class ConstructionDoc:
    """The θ-circle construction: the crank pivot A lies on the circle through C1 and C2."""

    C1: complex = q("m", "rocker tip at the folded extreme (AC1 = b − a)")
    C2: complex = q("m", "rocker tip at the extended extreme (AC2 = b + a)")
    centre: complex | None = q("m", "centre O of the θ-circle (null for θ = 0: the line C1C2)")
    radius: float = q("m", "R = C1C2 / (2 sin θ) (null for θ = 0)")
    arc: tuple[float, float] = q("rad", "allowed arc (p_lo, p_hi) of the crank pivot's parameter p")


@dataclass(frozen=True)
class DesignDoc:
    """A crank-rocker (closed forms)."""

    label: str | dict = q("", "the design's name: the brief's text ('zh / en'), or the program's as a "
                          "catalogue message {msgid} (translated where shown)")
    crank: float = q("m", "L_AB (a)")
    coupler: float = q("m", "L_BC (b)")
    rocker: float = q("m", "L_CD (c)")
    frame: float = q("m", "L_AD (d)")
    crank_pivot: complex = q("m", "crank pivot A")
    arc_position: float | None = q("rad", "arc parameter p of A (null for a compared design)")
    gamma_min: float = q("rad", "γ_min")
    gamma_max: float = q("rad", "γ_max")
    theta: float = q("rad", "extreme-position angle θ (null unless a crank-rocker)")
    swing: float = q("rad", "rocker swing ψ (null unless a crank-rocker)")
    classification: str = q("", "Grashof type, e.g. 'crank-rocker'")
    warnings: tuple[str, ...] = q("", "codes of the design findings")


@dataclass(frozen=True)
class ChartDoc:
    """The design chart: the optimum over the swing ψ, one curve per θ."""

    theta: tuple[float, ...] = q("rad", "θ of each curve")
    swing: np.ndarray = q("rad", "ψ along the curves")
    rocker_over_frame: np.ndarray = q("1", "l3/l4 at the optimum, one row per θ (null: none)")
    gamma_min: np.ndarray = q("rad", "γ_min at the optimum, one row per θ (null: none)")


@dataclass(frozen=True)
class SimulationDoc:
    """A design simulated over one revolution (crank + RRR group)."""

    label: str | dict = q("", "the design's name (as DesignDoc.label)")
    K: float = q("1", "simulated K")
    theta: float = q("rad", "simulated θ")
    swing: float = q("rad", "simulated ψ")
    gamma_min: float = q("rad", "simulated γ_min")
    crank_angle_at_gamma_min: float = q("rad", "crank angle of γ_min, from the frame line A→D")
    crank_angles_at_extremes: tuple[float, float] = q("rad",
        "crank angles of the rocker's extremes, from A→D")
    closure_residual: float = q("m", "largest |loop closure| residual")


@dataclass(frozen=True)
class SliderSimulated:
    """The offset slider-crank simulated over one revolution (crank + RRP group)."""

    stroke: float = q("m", "simulated stroke H")
    K: float = q("1", "simulated K")
    theta: float = q("rad", "simulated θ")
    pressure_angle_slow: float = q("rad", "largest α of the slow (working) stroke")
    pressure_angle_fast: float = q("rad", "largest α of the fast stroke")
    closure_residual: float = q("m", "largest |loop closure| residual")


@dataclass(frozen=True)
class SliderCrankDoc:
    """The offset slider-crank from K, H and e (closed forms)."""

    K: float = q("1", "time ratio K")
    theta: float = q("rad", "extreme-position angle θ")
    stroke: float = q("m", "stroke H")
    offset: float = q("m", "offset e")
    crank: float = q("m", "crank L_AB")
    rod: float = q("m", "connecting rod L_BC")
    pressure_angle_slow: float = q("rad", "largest α of the slow (working) stroke")
    pressure_angle_fast: float = q("rad", "largest α of the fast stroke")
    simulated: SliderSimulated = q("", "the same by simulation")


@dataclass(frozen=True)
class CrankRockerResults:
    """Crank-rocker synthesis (曲柄摇杆机构设计) from the time ratio K, the swing ψ and the
    rocker length: the crank-rocker with the largest minimum transmission angle (the crank
    pivot A searched over the allowed arc of the θ-circle), the textbook design with a given
    frame, the designs to compare, the design chart, optionally an offset slider-crank from
    K, H and e, and every design simulated. Frame: the rocker pivot D at the origin; crank
    AB, coupler BC, rocker CD, frame AD."""

    schema: str = q("", "'mechdesign.results/2'")
    machine: str = q("", "'crank_rocker'")
    units: str = q("", "reminder of the unit system")
    spec: SpecDoc = q("", "the design data")
    construction: ConstructionDoc = q("", "the θ-circle construction")
    optimum: DesignDoc = q("", "the crank-rocker with the largest γ_min")
    optimum_far_circle_gamma_min: float | None = q(
        "rad", "best γ_min with A on the mirror circle (beyond the chord); null if none")
    textbook: DesignDoc | None = q("", "the design with the given frame, if any")
    compare: tuple[DesignDoc, ...] = q("", "the brief's designs to compare")
    chart: ChartDoc = q("", "the design chart")
    simulation: tuple[SimulationDoc, ...] = q("", "optimum, textbook, compared designs simulated")
    slider_crank: SliderCrankDoc | None = q("", "the offset slider-crank, if the brief has one")
    linkage: LinkageDocument | None = q(
        "", "the optimum run through the shared linkage engine (kinematics at the textbook "
        "positions, the graphical method at the polygon positions); the output is the rocker's "
        "angle, position 1 the extreme that starts the slow stroke; the brief has no loads, so "
        "the balancing torque is zero and no reactions are listed", default=None)


def _design_doc(d: Design) -> DesignDoc:
    return DesignDoc(encode(d.label), d.design.crank, d.design.coupler, d.design.rocker, d.design.frame,
                     complex(d.a_pivot), d.position, d.gamma_min, d.gamma_max, d.theta, d.swing,
                     d.grashof, tuple(w.code for w in d.warnings))


def _sim_doc(s: Simulation) -> SimulationDoc:
    return SimulationDoc(encode(s.label), s.K, s.theta, s.swing, s.gamma_min, s.phi_gamma_min,
                         tuple(s.phi_extremes), s.closure)


def results_document(r: dict) -> CrankRockerResults:
    from ...results import SCHEMA

    p = r["params"]
    opt: OptimumResult = r["optimum"]
    cons = opt.construction
    slider = None
    if r.get("slider") is not None:
        sl: SliderResult = r["slider"]
        ss = r["verify"].slider
        slider = SliderCrankDoc(
            sl.K, sl.theta, sl.stroke, sl.offset, sl.crank, sl.rod, sl.alpha_slow, sl.alpha_fast,
            SliderSimulated(ss.stroke, ss.K, ss.theta, ss.alpha_slow, ss.alpha_fast, ss.closure))
    return CrankRockerResults(
        schema=SCHEMA, machine="crank_rocker", units=UNITS,
        spec=SpecDoc(p.K, p.theta, p.swing, p.rocker, p.frame, p.gamma_allowed),
        construction=ConstructionDoc(complex(cons.c1), complex(cons.c2),
                                     None if cons.centre is None else complex(cons.centre),
                                     cons.radius, (cons.p_lo, cons.p_hi)),
        optimum=_design_doc(opt.best), optimum_far_circle_gamma_min=opt.far_side_gamma,
        textbook=None if r.get("textbook") is None else _design_doc(r["textbook"]),
        compare=tuple(_design_doc(d) for d in r["compare"]),
        chart=ChartDoc(tuple(r["chart"].thetas), r["chart"].swings, r["chart"].ratio,
                       r["chart"].gamma),
        simulation=tuple(_sim_doc(s) for s in r["verify"].sims),
        slider_crank=slider, linkage=_linkage_doc(r))


def _linkage_doc(r: dict) -> LinkageDocument | None:
    """The shared engine's document of the optimum; without loads the kinetostatics is
    zero (no reactions, M_b = 0), written so rather than computed."""
    from ...stages.linkage import LinkageForces, linkage_document

    if r.get("linkage") is None:
        return None
    k = r["linkage"]
    zero = np.zeros_like(k.phase)
    none = LinkageForces({}, {}, {}, {}, {}, zero, zero, 0.0, 0.0, 0.0)
    return linkage_document(r["linkage_model"], k, none, r.get("linkage_flywheel"),
                            r["linkage_verification"], r.get("linkage_graphical"))


__all__ = ["stages", "results_document", "simulate_four_bar", "simulate_slider", "folded_branch"]
