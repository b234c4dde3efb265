"""Peer benchmark: linkage kinematics (and four-bar kinetostatics) against other libraries.

Rerun from a clean clone (the peers are an optional extra, never a run-time dependency):

    python -m venv .venv-peers && .venv-peers/bin/pip install -e ".[peers]" \
        && .venv-peers/bin/python benchmarks/peers.py            # add --markdown for the README

Options: --sizes 360,3600,100000  --repeat 5 (best of)  --quick (sizes 360,3600: smoke run)
--markdown. A full run takes about a minute (mechanism's fsolve dominates).
A peer that is not installed is reported as "not installed"; the script also runs in the plain
dev venv (ours + the hand-written closed form only).

Linkages (SI units; angles counter-clockwise from +x; crank at +10 rad/s constant):
* four-bar crank-rocker: crank a = 5, coupler b = 8, rocker c = 8, frame d = 9 [m],
  pivots A = (0, 0), D = (9, 0). Branch: C to the LEFT of B→D (above the line B→D, the open
  branch here): our RRR branch +1, the "−" root of Freudenstein's quadratic below, kinepy sign
  −1 for its "RRR" group, pylinkage / mechanism seeded there (they then follow continuously).
  Output point C (coupler–rocker joint); angles θ3 (B→C) and θ4 (D→C).
* offset slider-crank: crank 0.05, rod 0.2 [m], pivot A = (0, 0), the slider C on a guide along
  +x at y = e = +0.01 (the guide is offset, the pivot is on the x axis), C ahead of the crank
  pin (x_C > x_B): our RRP branch +1. Output point C; angle θ3 (B→C).
Crank angles φ_k = 2πk/N, k = 0..N−1 (one revolution, no repeated end point).

What each solver does
* ours: mechdesign.core.mechanism.Mechanism.solve (closed-form Assur groups, vectorised numpy).
  There is no positions-only API, so both the "pos" and "pos+vel+acc" columns time the same
  full m.solve call.
* hand: closed forms written below (Freudenstein's quadratic for θ3, θ4; arcsin for the slider-
  crank; velocities and accelerations from the differentiated loop equations by Cramer's rule),
  vectorised numpy; "pos" times the position functions only.
* pylinkage 1.3.0: numba path `Linkage.step_fast` (positions) and
  `Linkage.step_fast_with_kinematics` (positions + analytic velocity/acceleration, numba
  solver/{joints,velocity,acceleration}.py); pure-Python path `Linkage.step` /
  `Linkage.step_with_derivatives`. It steps the crank by a fixed increment per step (its crank
  is "angular_velocity = rad per step"; physical ω is set with set_input_velocity) and picks
  the circle intersection nearest the previous position. First numba call (compile, or load
  from numba's on-disk cache) is reported separately and excluded from throughput.
* mechanism 1.1.10: vector-loop equations solved by scipy.optimize.fsolve per crank position,
  three fsolve calls per position for pos+vel+acc (default xtol = 1.49e-8, relative step).
* kinepy 0.1.7: closed-form positions, vectorised over all inputs (System.solve_kinematics).
  It has no velocity/acceleration API: its dynamics differentiates positions with central
  finite differences (kinepy.math.calculus.derivative*_vec, first/last sample NaN); the
  pos+vel+acc row uses exactly those functions (error O(h²), h = 2π/N).

Deviations are against OURS: position of the output point max|ΔC| / max|C|, angles max|Δθ|
[rad], velocity and acceleration of C max|Δv| / max|v| (so a zero crossing is no division by 0).
Runs that would take minutes are measured at a smaller size and extrapolated (constant
throughput), marked "~".

Kinetostatics (four-bar): crank 1 kg at its mid-point, coupler 2 kg and rocker 3 kg at their
mid-points, J = m·l²/12 about the centre of mass, gravity 9.81 m/s² along −y, no external load.
Balancing (driving) torque on the crank, CCW+: ours `solve_forces` vs the power balance
M_b·ω = Σ(m·a_S·v_S + m·g·v_Sy + J·α·ω_link) computed from the hand kinematics (needs no
reaction) vs kinepy's `solve_dynamics` (inertia by central finite differences of positions).
pylinkage and mechanism have no force analysis.
"""
from __future__ import annotations

import argparse
import contextlib
import io
import math
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

# ---------------------------------------------------------------- cases
FOURBAR = dict(a=5.0, b=8.0, c=8.0, d=9.0, omega=10.0)
SLIDER = dict(r=0.05, l=0.2, e=0.01, omega=10.0)
GRAVITY = 9.81
# (link, mass [kg], distance of the centre of mass from the link's first point / length)
FB_MASSES = {"2": 1.0, "3": 2.0, "4": 3.0}
MECHANISM_XTOL = 1.49012e-8      # scipy.optimize.fsolve default
EXACT_TOL = 1e-9
SLOW_LIMIT = {"pylinkage (pure Python)": 100_000, "mechanism (fsolve)": 3600}


PEER_NOTES = (
    "pylinkage's Crank.angular_velocity is radians per step (physical ω only via "
    "set_input_velocity); the crank angle is re-derived each step as atan2(last position) + "
    "increment, so it drifts slowly with the number of steps (and across repeated runs of "
    "one linkage); branches are kept by 'nearest to the previous position'.",
    "kinepy's default length unit is the millimetre (set_unit_system(SI) here); its RRR sign "
    "+1 is C below B→D for this four-bar (we use −1); the piloted revolute's torque is the "
    "opposite of our driving torque; it has no velocity/acceleration solver (its dynamics "
    "differentiates positions numerically), and its arccos-based angles lose digits near "
    "collinear positions (four-bar φ ≈ 180°, slider-crank rod ∥ guide at φ ≈ 168°), which 1/h² amplifies at large N.",
    "mechanism solves three fsolve problems per crank position (position, velocity, "
    "acceleration), each seeded with the previous solution; no force analysis for linkages.",
)


def crank_angles(n: int) -> np.ndarray:
    return 2.0 * np.pi * np.arange(n) / n


# ---------------------------------------------------------------- hand-written closed forms
def fourbar_angles(phi, a, b, c, d):
    """θ3 (B→C), θ4 (D→C) of the four-bar A-B-C-D (A at 0, D at d on +x), C left of B→D.

    Freudenstein: the loop a·e^{iθ2} + b·e^{iθ3} − c·e^{iθ4} − d = 0 gives, with t = tan(θ/2),
    A·t² + B·t + C = 0 for θ4 (K1 = d/a, K2 = d/c, K3 = (a² − b² + c² + d²)/(2ac)) and for θ3
    (K4 = d/b, K5 = (c² − d² − a² − b²)/(2ab)). The "−" root is the branch above B→D.
    """
    cos2, sin2 = np.cos(phi), np.sin(phi)
    k1, k2, k3 = d / a, d / c, (a * a - b * b + c * c + d * d) / (2 * a * c)
    k4, k5 = d / b, (c * c - d * d - a * a - b * b) / (2 * a * b)
    qa = cos2 - k1 - k2 * cos2 + k3
    qb = -2.0 * sin2
    qc = k1 - (k2 + 1.0) * cos2 + k3
    th4 = 2.0 * np.arctan2(-qb - np.sqrt(qb * qb - 4 * qa * qc), 2 * qa)
    qd = cos2 - k1 + k4 * cos2 + k5
    qf = k1 + (k4 - 1.0) * cos2 + k5
    th3 = 2.0 * np.arctan2(-qb - np.sqrt(qb * qb - 4 * qd * qf), 2 * qd)
    return th3, th4


def fourbar_positions(phi, a, b, c, d, **_):
    th3, th4 = fourbar_angles(phi, a, b, c, d)
    return dict(th3=th3, th4=th4, C=d + c * np.exp(1j * th4))


def fourbar_closed_form(phi, a, b, c, d, omega, alpha2=0.0):
    """Positions, velocities, accelerations of the four-bar, all vectorised."""
    th3, th4 = fourbar_angles(phi, a, b, c, d)
    w2 = omega
    s34 = np.sin(th3 - th4)
    w3 = a * w2 * np.sin(th4 - phi) / (b * s34)
    w4 = a * w2 * np.sin(phi - th3) / (c * -s34)
    c2, s2, c3, s3, c4, s4 = (np.cos(phi), np.sin(phi), np.cos(th3), np.sin(th3),
                              np.cos(th4), np.sin(th4))
    # second derivative of the loop, real and imaginary parts, unknowns α3, α4:
    #   −b·s3·α3 + c·s4·α4 = r1,   b·c3·α3 − c·c4·α4 = r2
    r1 = a * alpha2 * s2 + a * w2 * w2 * c2 + b * w3 * w3 * c3 - c * w4 * w4 * c4
    r2 = -a * alpha2 * c2 + a * w2 * w2 * s2 + b * w3 * w3 * s3 - c * w4 * w4 * s4
    det = b * c * s34
    al3 = -c * (r1 * c4 + r2 * s4) / det
    al4 = -b * (r2 * s3 + r1 * c3) / det
    u4 = c * np.exp(1j * th4)
    return dict(th3=th3, th4=th4, w3=w3, w4=w4, al3=al3, al4=al4,
                C=d + u4, vC=1j * w4 * u4, aC=(1j * al4 - w4 * w4) * u4,
                B=a * np.exp(1j * phi), vB=1j * w2 * a * np.exp(1j * phi),
                aB=(1j * alpha2 - w2 * w2) * a * np.exp(1j * phi))


def slider_positions(phi, r, l, e, **_):
    th3 = np.arcsin((e - r * np.sin(phi)) / l)
    return dict(th3=th3, C=r * np.cos(phi) + l * np.cos(th3) + 1j * e)


def slider_closed_form(phi, r, l, e, omega, alpha2=0.0):
    """Offset slider-crank (guide y = e, slider ahead of the pin): r·sinφ + l·sinθ3 = e."""
    s2, c2 = np.sin(phi), np.cos(phi)
    s3 = (e - r * s2) / l
    th3 = np.arcsin(s3)
    c3 = np.cos(th3)
    w2 = omega
    w3 = -r * w2 * c2 / (l * c3)
    al3 = (r * w2 * w2 * s2 + l * w3 * w3 * s3 - r * alpha2 * c2) / (l * c3)
    x = r * c2 + l * c3
    v = -r * w2 * s2 - l * w3 * s3
    acc = -r * alpha2 * s2 - r * w2 * w2 * c2 - l * al3 * s3 - l * w3 * w3 * c3
    return dict(th3=th3, w3=w3, al3=al3, C=x + 1j * e, vC=v + 0j, aC=acc + 0j)


def fourbar_power_balance_torque(phi, a, b, c, d, omega, g=GRAVITY, masses=FB_MASSES):
    """Balancing torque on the crank from the power balance (virtual work), hand kinematics."""
    k = fourbar_closed_form(phi, a, b, c, d, omega)
    e2, e3, e4 = np.exp(1j * phi), np.exp(1j * k["th3"]), np.exp(1j * k["th4"])
    # centres of mass at the mid-points: S2 = A + a/2·e2, S3 = B + b/2·e3, S4 = D + c/2·e4
    links = {
        "2": (a, omega, 0.0, (a / 2) * 1j * omega * e2, (a / 2) * (-omega**2) * e2),
        "3": (b, k["w3"], k["al3"], k["vB"] + (b / 2) * 1j * k["w3"] * e3,
              k["aB"] + (b / 2) * (1j * k["al3"] - k["w3"] ** 2) * e3),
        "4": (c, k["w4"], k["al4"], (c / 2) * 1j * k["w4"] * e4,
              (c / 2) * (1j * k["al4"] - k["w4"] ** 2) * e4),
    }
    power = np.zeros_like(phi)
    for name, (length, w, al, v, acc) in links.items():
        m = masses[name]
        j = m * length**2 / 12.0
        power += m * (np.conj(acc) * v).real + m * g * v.imag + j * al * w
    return power / omega


# ---------------------------------------------------------------- ours
def _import_mechdesign():
    try:
        import mechdesign.core.mechanism  # noqa: F401
    except ImportError:                   # run from a clone without installing it
        sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))
    from mechdesign.core import mechanism as mm
    return mm


def ours_fourbar(with_masses=False):
    mm = _import_mechdesign()
    p = FOURBAR
    m = mm.Mechanism("1", {"A": 0j, "D": p["d"] + 0j})
    m.add(mm.Crank("crank", "2", "A", "B", p["a"], p["omega"]))
    m.add(mm.RRR("g", "3", "4", "B", "D", "C", p["b"], p["c"], 1))
    if with_masses:
        m.add(mm.LinkPoint("S2", "2", "A", p["a"] / 2))
        m.add(mm.LinkPoint("S3", "3", "B", p["b"] / 2))
        m.add(mm.LinkPoint("S4", "4", "D", p["c"] / 2))
    return m


def ours_slider():
    mm = _import_mechdesign()
    p = SLIDER
    m = mm.Mechanism("1", {"A": 0j})
    m.add(mm.Crank("crank", "2", "A", "B", p["r"], p["omega"]))
    m.add(mm.RRP("g", "3", "4", "B", "C", p["l"], 1j * p["e"], 0.0, 1, "1"))
    return m


def ours_result(motion, fourbar):
    c = motion.points["C"]
    out = dict(C=c.pos, vC=c.vel, aC=c.acc, th3=motion.links["3"].angle)
    if fourbar:
        out["th4"] = motion.links["4"].angle
    return out


# ---------------------------------------------------------------- solver registry
@dataclass
class Solver:
    name: str
    pos: object = None            # callable(phi) -> result dict (positions)
    full: object = None           # callable(phi) -> result dict (pos, vel, acc)
    available: bool = True
    missing: str = ""
    notes: list = field(default_factory=list)
    kind: str = "exact"           # "exact" | "fsolve" | "fd" (vel/acc by finite differences)
    slow: bool = False
    first_call_s: float | None = None
    check: object = None          # callable(phi) -> result for the deviations (default: full)


def _quiet(fn, *args, **kwargs):
    with contextlib.redirect_stdout(io.StringIO()):
        return fn(*args, **kwargs)


def _pylinkage_build(n, fourbar):
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import RRPDyad, RRRDyad
    from pylinkage.simulation import Linkage
    h = 2 * np.pi / n
    if fourbar:
        p = FOURBAR
        # seed C on our branch at the crank angle before the first step (−h)
        k = fourbar_positions(np.array([-h]), **p)
        A, D = Ground(0.0, 0.0, name="A"), Ground(p["d"], 0.0, name="D")
        crank = Crank(anchor=A, radius=p["a"], angular_velocity=h, initial_angle=-h, name="B")
        dyad = RRRDyad(crank.output, D, distance1=p["b"], distance2=p["c"],
                       x=float(k["C"][0].real), y=float(k["C"][0].imag), name="C")
        link = Linkage([A, D, crank, dyad], name="four-bar")
        omega = p["omega"]
    else:
        p = SLIDER
        k = slider_positions(np.array([-h]), **p)
        A = Ground(0.0, 0.0, name="A")
        L1, L2 = Ground(0.0, p["e"], name="L1"), Ground(1.0, p["e"], name="L2")
        crank = Crank(anchor=A, radius=p["r"], angular_velocity=h, initial_angle=-h, name="B")
        dyad = RRPDyad(revolute_anchor=crank.output, line_anchor1=L1, line_anchor2=L2,
                       distance=p["l"], x=float(k["C"][0].real), y=float(k["C"][0].imag),
                       name="C")
        link = Linkage([A, L1, L2, crank, dyad], name="slider-crank")
        omega = p["omega"]
    link.set_input_velocity(crank, omega=omega, alpha=0.0)
    ib, ic = link.components.index(crank), link.components.index(dyad)
    return link, ib, ic


def _pyl_result(pos, vel, acc, ib, ic, fourbar):
    C = pos[:, ic, 0] + 1j * pos[:, ic, 1]
    B = pos[:, ib, 0] + 1j * pos[:, ib, 1]
    out = dict(C=C, th3=np.angle(C - B))
    if fourbar:
        out["th4"] = np.angle(C - FOURBAR["d"])
    if vel is not None:
        out["vC"] = vel[:, ic, 0] + 1j * vel[:, ic, 1]
        out["aC"] = acc[:, ic, 0] + 1j * acc[:, ic, 1]
    return out


def pylinkage_solvers(fourbar):
    try:
        import pylinkage  # noqa: F401
        from pylinkage._numba_compat import HAS_NUMBA
    except ImportError:
        return [Solver("pylinkage (numba)", available=False, missing="not installed"),
                Solver("pylinkage (pure Python)", available=False, missing="not installed")]
    cache = {}

    def get(n):              # one linkage per size, reused by the timing repeats
        if n not in cache:
            cache[n] = _pylinkage_build(n, fourbar)
        return cache[n]

    def fast_pos(phi):
        link, ib, ic = get(len(phi))
        return _pyl_result(link.step_fast(iterations=len(phi)), None, None, ib, ic, fourbar)

    def fast_full(phi, fresh=False):
        link, ib, ic = _pylinkage_build(len(phi), fourbar) if fresh else get(len(phi))
        pos, vel, acc = link.step_fast_with_kinematics(iterations=len(phi))
        return _pyl_result(pos, vel, acc, ib, ic, fourbar)

    def py_pos(phi):
        link, ib, ic = _pylinkage_build(len(phi), fourbar)
        pos = np.array([[(x, y) for x, y in step] for step in link.step(iterations=len(phi))],
                       dtype=float)
        return _pyl_result(pos, None, None, ib, ic, fourbar)

    def py_full(phi):
        link, ib, ic = _pylinkage_build(len(phi), fourbar)
        ps, vs, as_ = [], [], []
        for p, v, a in link.step_with_derivatives(iterations=len(phi)):
            ps.append(p)
            vs.append([x or (np.nan, np.nan) for x in v])
            as_.append([x or (np.nan, np.nan) for x in a])
        return _pyl_result(np.array(ps, float), np.array(vs, float), np.array(as_, float),
                           ib, ic, fourbar)

    # the timing repeats reuse one linkage whose crank keeps stepping (and drifting: the
    # crank angle is atan2 of the last position + increment), so deviations come from a
    # freshly built linkage, as the pure-Python path does on every call
    fast = Solver("pylinkage (numba)", fast_pos, fast_full,
                  check=lambda phi: fast_full(phi, fresh=True))
    slow = Solver("pylinkage (pure Python)", py_pos, py_full, slow=True)
    if not HAS_NUMBA:
        fast.available, fast.missing = False, "numba not installed (pip install numba)"
    else:
        t = time.perf_counter()
        fast_full(crank_angles(8))
        fast_pos(crank_angles(8))
        fast.first_call_s = time.perf_counter() - t
    return [fast, slow]


def mechanism_solver(fourbar):
    try:
        import mechanism as mech_lib
    except ImportError:
        return Solver("mechanism (fsolve)", available=False, missing="not installed")
    from mechanism import Mechanism as MMech, Vector, get_joints

    def build(phi, full):
        n = len(phi)
        w = np.full(n, FOURBAR["omega"] if fourbar else SLIDER["omega"])
        kw = dict(vel=w, acc=np.zeros(n)) if full else {}
        if fourbar:
            p = FOURBAR
            A, B, C, D = get_joints("A B C D")
            a = Vector((A, B), r=p["a"])
            b = Vector((B, C), r=p["b"])
            c = Vector((D, C), r=p["c"])
            d = Vector((A, D), r=p["d"], theta=0.0, style="ground")

            def loop(x, i):
                return a(i) + b(x[0]) - c(x[1]) - d()
            k = fourbar_closed_form(phi[:1], **p)
            guess = (np.array([k["th3"][0], k["th4"][0]]), np.array([1.0, 1.0]),
                     np.array([1.0, 1.0]))
            m = MMech(vectors=(a, b, c, d), origin=A, loops=loop, pos=phi, guess=guess, **kw)
            return m, (B, C)
        p = SLIDER
        A, B, G, C = get_joints("A B G C")
        a = Vector((A, B), r=p["r"])
        b = Vector((B, C), r=p["l"])
        e = Vector((A, G), r=p["e"], theta=np.pi / 2, style="ground")
        s = Vector((G, C), theta=0.0, style="ground")

        def loop(x, i):
            return a(i) + b(x[1]) - s(x[0]) - e()
        k = slider_closed_form(phi[:1], **p)
        guess = (np.array([k["C"][0].real, k["th3"][0]]), np.array([1.0, 1.0]),
                 np.array([1.0, 1.0]))
        m = MMech(vectors=(a, b, s, e), origin=A, loops=loop, pos=phi, guess=guess, **kw)
        return m, (B, C)

    def run(phi, full):
        m, (B, C) = build(phi, full)
        m.iterate()
        Cp = C.x_positions + 1j * C.y_positions
        Bp = B.x_positions + 1j * B.y_positions
        out = dict(C=Cp, th3=np.angle(Cp - Bp))
        if fourbar:
            out["th4"] = np.angle(Cp - FOURBAR["d"])
        if full:
            out["vC"] = C.x_velocities + 1j * C.y_velocities
            out["aC"] = C.x_accelerations + 1j * C.y_accelerations
        return out

    del mech_lib
    return Solver("mechanism (fsolve)", lambda phi: run(phi, False), lambda phi: run(phi, True),
                  kind="fsolve", slow=True)


def _kinepy_system(fourbar, masses=False):
    import kinepy as kp
    from kinepy.units import SI, set_unit_system
    set_unit_system(SI)                          # kinepy's default length unit is the mm
    s = kp.System()
    if fourbar:
        p = FOURBAR
        mass = FB_MASSES if masses else {"2": 0.0, "3": 0.0, "4": 0.0}

        def solid(name, key, length):
            m = mass[key]
            return s.add_solid(name, m, m * length**2 / 12.0, (length / 2, 0.0))
        crank = solid("crank", "2", p["a"])
        coupler = solid("coupler", "3", p["b"])    # local frame: B at 0, C at (b, 0)
        rocker = solid("rocker", "4", p["c"])      # local frame: D at 0, C at (c, 0)
        rev_a = s.add_revolute(0, "crank", (0.0, 0.0), (0.0, 0.0))
        s.add_revolute("crank", "coupler", (p["a"], 0.0), (0.0, 0.0))
        s.add_revolute("coupler", "rocker", (p["b"], 0.0), (p["c"], 0.0))
        s.add_revolute("rocker", 0, (0.0, 0.0), (p["d"], 0.0))
        if masses:
            s.add_gravity((0.0, -GRAVITY))
        _quiet(s.pilot, rev_a)
        _quiet(s.compile)
        parts = dict(crank=crank, coupler=coupler, rocker=rocker, rev_a=rev_a)
        tip = (p["b"], 0.0)
    else:
        p = SLIDER
        crank = s.add_solid("crank")
        rod = s.add_solid("rod")                   # local frame: B at 0, C at (l, 0)
        slider = s.add_solid("slider")
        rev_a = s.add_revolute(0, "crank", (0.0, 0.0), (0.0, 0.0))
        s.add_revolute("crank", "rod", (p["r"], 0.0), (0.0, 0.0))
        s.add_revolute("rod", "slider", (p["l"], 0.0), (0.0, 0.0))
        s.add_prismatic(0, "slider", 0.0, p["e"], 0.0, 0.0)    # guide y = e along +x
        _quiet(s.pilot, rev_a)
        _quiet(s.compile)
        parts = dict(crank=crank, coupler=rod, rev_a=rev_a)
        tip = (p["l"], 0.0)
    # choose the sign (branch) that puts C on our branch at φ = 0
    phi0 = np.array([0.0, 0.1])
    ref = (fourbar_positions(phi0, **FOURBAR) if fourbar else slider_positions(phi0, **SLIDER))
    for sign in (1, -1):
        _quiet(s.change_signs, [sign])
        s.solve_kinematics([phi0])
        C = parts["coupler"].get_point(tip)
        if abs(C[0][0] + 1j * C[1][0] - ref["C"][0]) < 1e-6:
            parts["sign"] = sign
            break
    else:
        raise RuntimeError("kinepy: no sign reproduces our branch")
    return s, parts, tip


def kinepy_solver(fourbar):
    try:
        import kinepy  # noqa: F401
        from kinepy.math.calculus import derivative2_vec, derivative_vec
    except ImportError:
        return Solver("kinepy", available=False, missing="not installed")
    s, parts, tip = _quiet(_kinepy_system, fourbar)
    omega = FOURBAR["omega"] if fourbar else SLIDER["omega"]

    def pos(phi):
        s.solve_kinematics([phi])
        cp = parts["coupler"].get_point(tip)                     # (2, n)
        C = cp[0] + 1j * cp[1]
        out = dict(C=C, th3=np.array(parts["coupler"].angle))
        if fourbar:
            out["th4"] = np.array(parts["rocker"].angle)
        return out, cp

    def full(phi):
        out, cp = pos(phi)
        dt = (phi[1] - phi[0]) / omega                           # as in its solve_dynamics
        v, a = derivative_vec(cp, dt), derivative2_vec(cp, dt)
        out["vC"], out["aC"] = v[0] + 1j * v[1], a[0] + 1j * a[1]
        return out

    sv = Solver("kinepy", lambda phi: pos(phi)[0], full, kind="fd")
    sv.notes.append(f"kinepy branch sign {parts['sign']:+d}")
    return sv


def ours_solver(fourbar):
    m = ours_fourbar() if fourbar else ours_slider()

    def run(phi):
        return ours_result(m.solve(phi), fourbar)
    return Solver("ours (mechdesign)", run, run)


def hand_solver(fourbar):
    p = FOURBAR if fourbar else SLIDER
    if fourbar:
        return Solver("hand closed form (numpy)", lambda phi: fourbar_positions(phi, **p),
                      lambda phi: fourbar_closed_form(phi, **p))
    return Solver("hand closed form (numpy)", lambda phi: slider_positions(phi, **p),
                  lambda phi: slider_closed_form(phi, **p))


# ---------------------------------------------------------------- timing and comparison
def timed(fn, phi, repeat):
    """Best (minimum) seconds per call of ``repeat`` samples after one warm-up call; short
    calls are looped to ≥ 20 ms a sample. Best, not median: the machine is shared, and the
    minimum is the least disturbed estimate of each solver's own cost."""
    t = time.perf_counter()
    out = fn(phi)
    first = time.perf_counter() - t
    loops = max(1, int(0.02 / max(first, 1e-7)))
    samples = []
    for _ in range(repeat):
        t = time.perf_counter()
        for _ in range(loops):
            fn(phi)
        samples.append((time.perf_counter() - t) / loops)
    return min(samples), out


def deviation(res, ref):
    """max|ΔC|/max|C|, max|Δθ| over the coupler (and rocker) angle, rel. vel, rel. acc."""
    ok = np.isfinite(res["C"])
    if "vC" in res:
        ok &= np.isfinite(res["vC"]) & np.isfinite(res["aC"])
    pos = np.max(np.abs(res["C"][ok] - ref["C"][ok])) / np.max(np.abs(ref["C"]))
    ang = 0.0
    for k in ("th3", "th4"):
        if k in res:
            d = np.angle(np.exp(1j * (res[k][ok] - ref[k][ok])))
            ang = max(ang, float(np.max(np.abs(d))))
    vel = acc = None
    if "vC" in res:
        vel = np.max(np.abs(res["vC"][ok] - ref["vC"][ok])) / np.max(np.abs(ref["vC"]))
        acc = np.max(np.abs(res["aC"][ok] - ref["aC"][ok])) / np.max(np.abs(ref["aC"]))
    return dict(pos=float(pos), ang=ang, vel=vel, acc=acc, dropped=int((~ok).sum()))


@dataclass
class Row:
    linkage: str
    solver: str
    n: int
    t_pos: float | None = None
    t_full: float | None = None
    est: bool = False
    dev: dict | None = None
    note: str = ""


def run_linkage(label, fourbar, sizes, repeat, log):
    solvers = [ours_solver(fourbar), hand_solver(fourbar), *pylinkage_solvers(fourbar),
               mechanism_solver(fourbar), kinepy_solver(fourbar)]
    rows, compile_notes = [], []
    for s in solvers:
        if s.first_call_s is not None:
            compile_notes.append(f"{label}: {s.name} first call (numba compile or cache load) "
                                 f"{s.first_call_s:.2f} s, excluded")
    measured = {}
    for n in sizes:
        phi = crank_angles(n)
        log(f"  {label}: N = {n}")
        ref_t, ref = timed(solvers[0].full, phi, repeat)
        for s in solvers:
            if not s.available:
                rows.append(Row(label, s.name, n, note=s.missing))
                continue
            limit = SLOW_LIMIT.get(s.name) if s.slow else None
            if limit is not None and n > limit:
                base = measured.get(s.name)
                if base is None:
                    rows.append(Row(label, s.name, n, note="not measured"))
                    continue
                nb, tp, tf = base
                rows.append(Row(label, s.name, n, tp * n / nb, tf * n / nb, est=True,
                                note=f"extrapolated from N = {nb}"))
                continue
            rep = 1 if s.slow and n > 360 else (2 if s.slow else repeat)
            if s is solvers[0]:
                t_full, res = ref_t, ref
                t_pos = t_full
            else:
                t_pos, _ = timed(s.pos, phi, rep)
                t_full, res = timed(s.full, phi, rep)
                if s.check is not None:
                    res = s.check(phi)
            measured[s.name] = (n, t_pos, t_full)
            rows.append(Row(label, s.name, n, t_pos, t_full, dev=deviation(res, ref),
                            note="; ".join(s.notes)))
    return rows, compile_notes, solvers


def kinetostatics(sizes, repeat, log):
    """Balancing torque on the four-bar crank: ours vs power balance vs kinepy."""
    mm = _import_mechdesign()
    from mechdesign.core.kinetostatics import Body, solve_forces
    p = FOURBAR
    m = ours_fourbar(with_masses=True)
    lengths = {"2": p["a"], "3": p["b"], "4": p["c"]}
    bodies = [Body(k, FB_MASSES[k], f"S{k}", FB_MASSES[k] * lengths[k] ** 2 / 12.0)
              for k in ("2", "3", "4")]
    del mm

    def ours(phi):
        return solve_forces(m, m.solve(phi), bodies, [], gravity=GRAVITY).driving_torque

    def power(phi):
        return fourbar_power_balance_torque(phi, **p)

    try:
        import kinepy  # noqa: F401
        s, parts, _ = _quiet(_kinepy_system, True, masses=True)

        def kin(phi):
            _quiet(s.solve_dynamics, [phi], t=2 * np.pi / p["omega"])
            return np.array(parts["rev_a"].torque, dtype=float)
    except ImportError:
        kin = None
    rows = []
    for n in sizes:
        phi = crank_angles(n)
        log(f"  kinetostatics: N = {n}")
        t_ours, mo = timed(ours, phi, repeat)
        t_pow, mp = timed(power, phi, repeat)
        scale = np.max(np.abs(mp))
        rows.append(("ours solve + solve_forces", n, t_ours,
                     float(np.max(np.abs(mo - mp)) / scale), None))
        rows.append(("power balance (hand kinematics)", n, t_pow, 0.0, None))
        if kin is None:
            rows.append(("kinepy solve_dynamics", n, None, None, "not installed"))
        else:
            t_k, mk = timed(kin, phi, repeat)
            ok = np.isfinite(mk)
            # kinepy's Rev.torque is the torque of the crank on the frame: minus ours
            dev = float(np.max(np.abs(-mk[ok] - mp[ok])) / scale)
            rows.append(("kinepy solve_dynamics", n, t_k, dev,
                         f"−Rev.torque; inertia by central FD, {int((~ok).sum())} end "
                         "samples NaN"))
    return rows, float(np.max(np.abs(power(crank_angles(3600)))))


# ---------------------------------------------------------------- printing
def fmt_rate(t, n, est):
    if t is None:
        return "—"
    r = n / t
    s = f"{r:,.0f}" if r >= 100 else f"{r:.3g}"
    return ("~" + s) if est else s


def fmt_e(x):
    return "—" if x is None else (f"{x:.1e}" if x else "0")


def table(headers, body, markdown):
    if markdown:
        def esc(row):
            return " | ".join(c.replace("|", "\\|") for c in row)
        out = ["| " + esc(headers) + " |", "|" + "|".join("---" for _ in headers) + "|"]
        out += ["| " + esc(r) + " |" for r in body]
        return "\n".join(out)
    widths = [max(len(h), *(len(r[i]) for r in body)) if body else len(h)
              for i, h in enumerate(headers)]
    line = "  ".join(h.ljust(w) for h, w in zip(headers, widths))
    out = [line, "-" * len(line)]
    out += ["  ".join(c.ljust(w) for c, w in zip(r, widths)) for r in body]
    return "\n".join(out)


def verdict(ok):
    return "PASS" if ok else "MISS"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", default="360,3600,100000",
                    help="comma-separated numbers of crank angles (default 360,3600,100000)")
    ap.add_argument("--repeat", type=int, default=5, help="timing samples per case (best of)")
    ap.add_argument("--quick", action="store_true", help="sizes 360,3600, repeat 3 (smoke run)")
    ap.add_argument("--markdown", action="store_true", help="print the tables as Markdown")
    args = ap.parse_args(argv)
    sizes = [360, 3600] if args.quick else [int(x) for x in args.sizes.split(",") if x.strip()]
    repeat = 3 if args.quick else max(1, args.repeat)
    t_start = time.perf_counter()

    def log(msg):
        print(msg, file=sys.stderr, flush=True)

    versions = []
    for mod in ("numpy", "scipy", "pylinkage", "numba", "mechanism", "kinepy"):
        try:
            from importlib.metadata import version
            versions.append(f"{mod} {version(mod)}")
        except Exception:
            versions.append(f"{mod} not installed")

    all_rows, notes, targets = [], [], []
    for label, fourbar in (("four-bar", True), ("slider-crank", False)):
        rows, cn, solvers = run_linkage(label, fourbar, sizes, repeat, log)
        all_rows += rows
        notes += cn
        # targets at the largest size
        n = max(sizes)
        by = {r.solver: r for r in rows if r.n == n}
        ours = by["ours (mechdesign)"]
        hand = by["hand closed form (numpy)"]

        def ratio_target(name, need, what):
            r = by.get(name)
            if r is None or r.t_full is None:
                targets.append((label, what, "—", f"≥ {need}×",
                                "n/a (" + (r.note if r else "missing") + ")"))
                return
            ratio = r.t_full / ours.t_full
            mark = "~" if r.est else ""
            targets.append((label, what, f"{mark}{ratio:,.1f}×", f"≥ {need:g}×",
                            verdict(ratio >= need)))
        ratio_target("pylinkage (numba)", 3, f"ours / pylinkage numba, pos+vel+acc, N={n}")
        ratio_target("mechanism (fsolve)", 1000, f"ours / mechanism, pos+vel+acc, N={n}")
        q = ours.t_full / hand.t_full
        targets.append((label, f"ours time / hand closed form time, pos+vel+acc, N={n}",
                        f"{q:.2f}×", "≤ 2×", verdict(q <= 2.0)))
        # agreement, at the largest measured size of each solver
        for s in solvers[1:]:
            meas = [r for r in rows if r.solver == s.name and r.dev is not None]
            if not meas:
                targets.append((label, f"agreement {s.name}", "—", "—",
                                "n/a (" + (s.missing or "not measured") + ")"))
                continue
            r = meas[-1]
            d = r.dev
            if s.kind == "exact":
                worst = max(d["pos"], d["ang"], d["vel"] or 0.0, d["acc"] or 0.0)
                targets.append((label, f"agreement {s.name} (exact), N={r.n}", fmt_e(worst),
                                f"≤ {EXACT_TOL:g}", verdict(worst <= EXACT_TOL)))
            elif s.kind == "fsolve":
                worst = max(d["pos"], d["ang"], d["vel"] or 0.0, d["acc"] or 0.0)
                tol = 10 * MECHANISM_XTOL
                targets.append((label, f"agreement {s.name}, N={r.n} (fsolve xtol "
                                f"{MECHANISM_XTOL:.3g} relative; tol 10·xtol)", fmt_e(worst),
                                f"≤ {tol:.1e}", verdict(worst <= tol)))
            else:
                worst = max(d["pos"], d["ang"])
                targets.append((label, f"agreement {s.name} positions (closed form), N={r.n}",
                                fmt_e(worst), f"≤ {EXACT_TOL:g}", verdict(worst <= EXACT_TOL)))
                # central differences of its own positions: truncation ~h², plus the
                # round-off of its positions divided by h² (dominant at large N); no exact
                # target applies, the number is shown for information
                h = 2 * np.pi / r.n
                worst = max(d["vel"], d["acc"])
                targets.append((label, f"agreement {s.name} vel/acc (its central FD, h = 2π/N"
                                f" = {h:.2g} rad), N={r.n}", fmt_e(worst),
                                "none (FD: ~h² + δpos/h²)", "n/a"))

    kin_rows, _ = kinetostatics(sizes, repeat, log)
    elapsed = time.perf_counter() - t_start

    md = args.markdown
    print(("## " if md else "") + "Peer benchmark: planar linkage kinematics")
    print()
    print("Versions: " + ", ".join(versions) + f"; Python {sys.version.split()[0]}; "
          f"best of {repeat} timing samples after a warm-up, sizes {', '.join(map(str, sizes))}")
    print()
    head = ["linkage", "solver", "N", "pos only [crank pos/s]", "pos+vel+acc [crank pos/s]",
            "max|ΔC|/max|C|", "max|Δθ| [rad]", "rel Δvel C", "rel Δacc C", "notes"]
    body = []
    for r in all_rows:
        d = r.dev or {}
        note = r.note
        if r.solver == "ours (mechdesign)":
            note = "reference; both columns time m.solve (no positions-only API)"
        elif r.solver.startswith("pylinkage (numba)") and r.t_full is not None:
            note = (note + "; " if note else "") + "analytic vel/acc (numba)"
        elif r.solver.startswith("pylinkage (pure") and r.t_full is not None and not r.est:
            note = (note + "; " if note else "") + "step / step_with_derivatives"
        elif r.solver == "kinepy" and r.t_full is not None and not r.est:
            note = (note + "; " if note else "") + \
                f"vel/acc: its central FD, {d.get('dropped', 0)} end samples NaN"
        elif r.solver.startswith("mechanism") and r.t_full is not None and not r.est:
            note = (note + "; " if note else "") + "3 fsolve per position"
        if r.est:
            d = {}
            note = (note + "; " if note else "") + "deviation: see measured row"
        body.append([r.linkage, r.solver, f"{r.n:,}", fmt_rate(r.t_pos, r.n, r.est),
                     fmt_rate(r.t_full, r.n, r.est), fmt_e(d.get("pos")), fmt_e(d.get("ang")),
                     fmt_e(d.get("vel")), fmt_e(d.get("acc")), note])
    print(table(head, body, md))
    print()
    foot = ["~ extrapolated from the largest measured size at constant throughput (the slow "
            "path would take minutes); its deviations are those of the measured row.",
            "Deviations are against ours: output point C relative to max|C|, angles θ3 (and θ4) "
            "in rad, velocity/acceleration of C relative to their maxima.",
            *notes,
            "pylinkage's numba code is cached on disk (cache=True): only the first run ever "
            "compiles (a few seconds); later runs load it."]
    foot += [f"Peer convention: {x}" for x in PEER_NOTES]
    print("\n".join(("* " if md else "") + x for x in foot))
    print()
    print(("### " if md else "") + "Four-bar balancing torque (kinetostatics)")
    print()
    kbody = [[name, f"{n:,}", "—" if t is None else fmt_rate(t, n, False),
              fmt_e(dev), note or ""] for name, n, t, dev, note in kin_rows]
    print(table(["solver", "N", "crank pos/s", "max|ΔM_b| / max|M_b| vs power balance",
                 "notes"], kbody, md))
    print()
    print("Masses: crank 1 kg, coupler 2 kg, rocker 3 kg at mid-link, J = m·l²/12, "
          "g = 9.81 m/s² along −y; kinepy's error is its O(h²) finite-difference inertia.")
    print()
    print(("### " if md else "") + "Targets (issue 8), measured in this run")
    print()
    print(table(["linkage", "target", "measured", "needed", "result"],
                [list(t) for t in targets], md))
    print()
    print(f"Total benchmark time: {elapsed:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
