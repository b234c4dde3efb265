"""Peer benchmark: linkage kinematics (and four-bar kinetostatics) against other libraries.

Rerun from a clean clone (the peers are an optional extra, never a run-time dependency):

    python -m venv .venv-peers && .venv-peers/bin/pip install -e ".[peers]" \
        && .venv-peers/bin/python benchmarks/peers.py            # add --markdown for the README

Options: --sizes 360,3600,100000  --rounds 9  --quick (sizes 360,3600, 3 rounds: smoke run)
--no-fresh  --clock cpu|wall  --markdown. A full run takes a few minutes (mechanism's fsolve
and the fresh processes dominate).

How it is timed (issue 22: figures a sceptic accepts)
* every solver is timed on exactly the work asked of it, returning its own natural output;
  turning that into the comparison's arrays (complex C, angles) happens outside the clock;
* the clock (--clock): cpu (default) times a sample by time.process_time, the process's own
  user + system CPU time, which other work on a shared machine disturbs far less than the
  wall clock (it still slows every CPU-bound program somewhat: caches, memory bandwidth);
  wall times it by time.perf_counter;
* interleaved rounds: round r times every solver once, the order rotated by r, so none is
  always first and a disturbance of the shared machine hits all alike; a sample loops the
  call to ≥ 20 ms; medians with the first and third quartiles;
* each fast solver is also timed alone in fresh processes: in a shared process another
  library's freed arrays spare the next one its page faults, which flatters whoever runs
  second. Round r starts one fresh process per solver (the order rotated by r; it imports
  only that solver's library, makes one warm-up call and times one sample), so the "alone"
  column is also a median [quartiles] over interleaved rounds; the kernel's resource usage
  of each child (its whole CPU time: start-up, imports, warm-up, sample) is printed too;
* the reference is the strongest plain closed form we could write (real arithmetic, one
  sqrt and two arctan2 for the four-bar, no complex exponentials), not a slow one.
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
  full m.solve call. It returns more than the plain closed form: position, velocity and
  acceleration of every point (B and C, complex arrays) and of every link and slider, checked
  for assembly (one pass per group); the slider-crank's plain form returns six real arrays.
  At N = 100 000 the time is mostly memory: every new array of that size is fresh pages to
  fault in, so the solver's cost follows the number of temporaries it makes (kin.rrp was
  rewritten with ~20 fewer, bit for bit the same, issue 22).
* plain closed form: written below (C as the intersection of two circles, one sqrt; θ3, θ4 by
  arctan2 of the unit vectors; sinθ3 from the guide and cosθ3 by sqrt for the slider-crank;
  velocities and accelerations from the differentiated loop equations by Cramer's rule), real
  arithmetic, vectorised numpy; "pos" times the position functions only. (Freudenstein's
  quadratic, fourbar_closed_form, stays as the kinetostatics' independent power balance.)
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
import json
import math
import os
import statistics
import subprocess
import sys
import time

try:
    import resource                  # the children's CPU time (POSIX)
except ImportError:                  # pragma: no cover - Windows
    resource = None
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


def fourbar_plain(phi, a, b, c, d, omega, alpha2=0.0):
    """The strongest plain closed form we could write (the timing reference): real
    arithmetic only, no complex exponentials. C as the intersection of the circles about B
    (radius b) and D (radius c) on the left of B→D (one sqrt), θ3 and θ4 by two arctan2 of
    the unit vectors already at hand, ω and α by Cramer's rule on the differentiated loop.
    Outputs the same quantities as ours: θ3, θ4, ω3, ω4, α3, α4 and C's x, y, v, a."""
    c2, s2 = np.cos(phi), np.sin(phi)
    bx, by = a * c2, a * s2
    dx, dy = d - bx, -by
    l2 = dx * dx + dy * dy
    f = 0.5 + (b * b - c * c) / (2.0 * l2)                 # foot of C along B→D
    h = np.sqrt(b * b / l2 - f * f)                        # C's offset, left of B→D
    cx = bx + f * dx - h * dy
    cy = by + f * dy + h * dx
    c3, s3 = (cx - bx) / b, (cy - by) / b
    c4, s4 = (cx - d) / c, cy / c
    th3, th4 = np.arctan2(s3, c3), np.arctan2(s4, c4)
    s34 = s3 * c4 - c3 * s4
    w2 = omega
    w3 = a * w2 * (s4 * c2 - c4 * s2) / (b * s34)
    w4 = a * w2 * (s3 * c2 - c3 * s2) / (c * s34)
    rx = -c * w4 * w4 * c4 + b * w3 * w3 * c3 + a * w2 * w2 * c2 + a * alpha2 * s2
    ry = -c * w4 * w4 * s4 + b * w3 * w3 * s3 + a * w2 * w2 * s2 - a * alpha2 * c2
    al3 = -(rx * c4 + ry * s4) / (b * s34)
    al4 = -(rx * c3 + ry * s3) / (c * s34)
    vcx, vcy = -w4 * c * s4, w4 * c * c4
    acx = -al4 * c * s4 - w4 * w4 * c * c4
    acy = al4 * c * c4 - w4 * w4 * c * s4
    return th3, th4, w3, w4, al3, al4, cx, cy, vcx, vcy, acx, acy


def fourbar_plain_positions(phi, a, b, c, d, **_):
    c2, s2 = np.cos(phi), np.sin(phi)
    bx, by = a * c2, a * s2
    dx, dy = d - bx, -by
    l2 = dx * dx + dy * dy
    f = 0.5 + (b * b - c * c) / (2.0 * l2)
    h = np.sqrt(b * b / l2 - f * f)
    cx, cy = bx + f * dx - h * dy, by + f * dy + h * dx
    return np.arctan2(cy - by, cx - bx), np.arctan2(cy, cx - d), cx, cy


def slider_plain(phi, r, l, e, omega, alpha2=0.0):
    """Offset slider-crank in real arithmetic: sinθ3 from the guide, cosθ3 by sqrt."""
    s2, c2 = np.sin(phi), np.cos(phi)
    s3 = (e - r * s2) / l
    c3 = np.sqrt(1.0 - s3 * s3)
    th3 = np.arctan2(s3, c3)
    w2 = omega
    w3 = -r * w2 * c2 / (l * c3)
    al3 = (r * w2 * w2 * s2 + l * w3 * w3 * s3 - r * alpha2 * c2) / (l * c3)
    x = r * c2 + l * c3
    v = -r * w2 * s2 - l * w3 * s3
    acc = -r * alpha2 * s2 - r * w2 * w2 * c2 - l * al3 * s3 - l * w3 * w3 * c3
    return th3, w3, al3, x, v, acc


def slider_plain_positions(phi, r, l, e, **_):
    s3 = (e - r * np.sin(phi)) / l
    c3 = np.sqrt(1.0 - s3 * s3)
    return np.arctan2(s3, c3), r * np.cos(phi) + l * c3


def _plain_result(raw, fourbar, full):
    """The plain closed form's arrays as the comparison's dict (outside the clock)."""
    if fourbar:
        if full:
            th3, th4, w3, w4, al3, al4, cx, cy, vx, vy, ax, ay = raw
            return dict(th3=th3, th4=th4, C=cx + 1j * cy, vC=vx + 1j * vy, aC=ax + 1j * ay)
        th3, th4, cx, cy = raw
        return dict(th3=th3, th4=th4, C=cx + 1j * cy)
    e = SLIDER["e"]
    if full:
        th3, w3, al3, x, v, acc = raw
        return dict(th3=th3, C=x + 1j * e, vC=v + 0j, aC=acc + 0j)
    th3, x = raw
    return dict(th3=th3, C=x + 1j * e)


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
    # raw output of pos/full → the comparison's dict, outside the clock (each solver is
    # timed on exactly the work asked of it, returning its own natural output)
    convert_pos: object = None
    convert_full: object = None


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
    _, ib0, ic0 = _pylinkage_build(8, fourbar)       # the joints' indices (any size)

    def convert_full(raw):
        return _pyl_result(*raw, ib0, ic0, fourbar)

    def convert_pos(raw):
        return _pyl_result(np.asarray(raw, dtype=float), None, None, ib0, ic0, fourbar)

    def get(n):              # one linkage per size, reused by the timing repeats
        if n not in cache:
            cache[n] = _pylinkage_build(n, fourbar)
        return cache[n]

    def fast_pos(phi):                   # its output as it gives it: an (n, joints, 2) array
        link, ib, ic = get(len(phi))
        return link.step_fast(iterations=len(phi))

    def fast_full(phi, fresh=False):
        link, ib, ic = _pylinkage_build(len(phi), fourbar) if fresh else get(len(phi))
        return link.step_fast_with_kinematics(iterations=len(phi))

    def py_pos(phi):                     # its output as it gives it: lists of (x, y)
        link, ib, ic = _pylinkage_build(len(phi), fourbar)
        return [list(step) for step in link.step(iterations=len(phi))]

    def py_full(phi):
        link, ib, ic = _pylinkage_build(len(phi), fourbar)
        return list(link.step_with_derivatives(iterations=len(phi)))

    def py_convert_full(raw):
        ps = [p for p, _, _ in raw]
        vs = [[x or (np.nan, np.nan) for x in v] for _, v, _ in raw]
        as_ = [[x or (np.nan, np.nan) for x in a] for _, _, a in raw]
        return _pyl_result(np.array(ps, float), np.array(vs, float), np.array(as_, float),
                           ib0, ic0, fourbar)

    # the timing repeats reuse one linkage whose crank keeps stepping (and drifting: the
    # crank angle is atan2 of the last position + increment), so deviations come from a
    # freshly built linkage, as the pure-Python path does on every call
    fast = Solver("pylinkage (numba)", fast_pos, fast_full,
                  check=lambda phi: convert_full(fast_full(phi, fresh=True)),
                  convert_pos=convert_pos, convert_full=convert_full)
    slow = Solver("pylinkage (pure Python)", py_pos, py_full, slow=True,
                  convert_pos=convert_pos, convert_full=py_convert_full)
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
        return B, C

    def convert(raw, full):
        B, C = raw
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
                  kind="fsolve", slow=True, convert_pos=lambda r: convert(r, False),
                  convert_full=lambda r: convert(r, True))


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

    def pos(phi):                        # its output: C (2, n) and the links' angles
        s.solve_kinematics([phi])
        cp = parts["coupler"].get_point(tip)                     # (2, n)
        return cp, parts["coupler"].angle, (parts["rocker"].angle if fourbar else None)

    def full(phi):
        cp, a3, a4 = pos(phi)
        dt = (phi[1] - phi[0]) / omega                           # as in its solve_dynamics
        return cp, a3, a4, derivative_vec(cp, dt), derivative2_vec(cp, dt)

    def convert(raw):
        cp, a3, a4 = raw[:3]
        out = dict(C=cp[0] + 1j * cp[1], th3=np.array(a3))
        if fourbar:
            out["th4"] = np.array(a4)
        if len(raw) > 3:
            v, a = raw[3], raw[4]
            out["vC"], out["aC"] = v[0] + 1j * v[1], a[0] + 1j * a[1]
        return out

    sv = Solver("kinepy", pos, full, kind="fd", convert_pos=convert, convert_full=convert)
    sv.notes.append(f"kinepy branch sign {parts['sign']:+d}")
    return sv


def ours_solver(fourbar):
    m = ours_fourbar() if fourbar else ours_slider()

    def convert(raw):
        return ours_result(raw, fourbar)
    return Solver(OURS, m.solve, m.solve, convert_pos=convert, convert_full=convert)


PLAIN = "plain closed form (numpy)"
OURS = "ours (mechdesign)"


def hand_solver(fourbar):
    p = FOURBAR if fourbar else SLIDER
    if fourbar:
        return Solver(PLAIN, lambda phi: fourbar_plain_positions(phi, **p),
                      lambda phi: fourbar_plain(phi, **p),
                      convert_pos=lambda r: _plain_result(r, True, False),
                      convert_full=lambda r: _plain_result(r, True, True))
    return Solver(PLAIN, lambda phi: slider_plain_positions(phi, **p),
                  lambda phi: slider_plain(phi, **p),
                  convert_pos=lambda r: _plain_result(r, False, False),
                  convert_full=lambda r: _plain_result(r, False, True))


# ---------------------------------------------------------------- timing and comparison
#: the clock of every sample: "cpu" (time.process_time: this process's user + system CPU time,
#: every thread; what other work on a shared machine disturbs least) or "wall"
#: (time.perf_counter); --clock sets it (default cpu)
CLOCKS = {"cpu": time.process_time, "wall": time.perf_counter}
clock = CLOCKS["cpu"]


def _calibrate(fn, phi):
    """One warm-up call (its output is kept for the comparison) and the number of calls per
    sample so that a sample lasts ≥ 20 ms."""
    t = clock()
    out = fn(phi)
    first = clock() - t
    return out, max(1, int(0.02 / max(first, 1e-7)))


def _sample(fn, phi, loops):
    t = clock()
    for _ in range(loops):
        fn(phi)
    return (clock() - t) / loops


def spread(samples):
    """(median, first quartile, third quartile) of timing samples [s]."""
    xs = sorted(samples)
    if len(xs) == 1:
        return xs[0], xs[0], xs[0]
    q1, q2, q3 = statistics.quantiles(xs, n=4, method="inclusive")
    return statistics.median(xs), q1, q3


def interleaved(jobs, phi, rounds):
    """Time every ``(key, fn)`` of ``jobs`` in interleaved rounds: round r times each once,
    starting with the job r places further down the list (so none is always first, and a
    disturbance of the machine hits all alike). Returns key → (samples, warm-up output)."""
    prepared = []
    for key, fn in jobs:
        out, loops = _calibrate(fn, phi)
        prepared.append((key, fn, loops, out))
    samples = {key: [] for key, *_ in prepared}
    k = len(prepared)
    for r in range(rounds):
        for i in range(k):
            key, fn, loops, _ = prepared[(r + i) % k]
            samples[key].append(_sample(fn, phi, loops))
    return {key: (samples[key], out) for key, _, _, out in prepared}


def alone(fourbar, names, n, rounds, clock_name):
    """Each solver of ``names`` timed alone in fresh processes, in interleaved rounds: round r
    starts one fresh process per solver (the order rotated by r), which imports only that
    solver's library, makes one warm-up call and times one sample (calls looped to ≥ 20 ms)
    of pos+vel+acc at ``n`` crank angles with ``clock_name``. Returns name → (median, q1,
    q3) [s per call] over the rounds, and name → the children's own CPU time [s] (user +
    system from the kernel's resource usage: imports, warm-up and sample), or None where a
    child failed."""
    samples = {name: [] for name in names}
    child_cpu = {name: [] for name in names}
    failed = set()
    for r in range(rounds):
        for i in range(len(names)):
            name = names[(r + i) % len(names)]
            if name in failed:
                continue
            before = resource.getrusage(resource.RUSAGE_CHILDREN) if resource else None
            out = subprocess.run([sys.executable, __file__, "--alone", name, "--linkage",
                                  "four-bar" if fourbar else "slider-crank", "--n", str(n),
                                  "--clock", clock_name], capture_output=True, text=True)
            if resource:
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                child_cpu[name].append(after.ru_utime + after.ru_stime
                                       - before.ru_utime - before.ru_stime)
            if out.returncode != 0:
                failed.add(name)
                continue
            samples[name].append(json.loads(out.stdout.strip().splitlines()[-1]))
    return ({name: spread(v) if v and name not in failed else None for name, v in samples.items()},
            {name: statistics.median(v) if v and name not in failed else None
             for name, v in child_cpu.items()})


def _alone_child(linkage, name, n):
    fourbar = linkage == "four-bar"
    build = {OURS: ours_solver, PLAIN: hand_solver, "kinepy": kinepy_solver,
             "mechanism (fsolve)": mechanism_solver,
             "pylinkage (numba)": lambda f: pylinkage_solvers(f)[0],
             "pylinkage (pure Python)": lambda f: pylinkage_solvers(f)[1]}[name]
    s = build(fourbar)                   # only this solver's library is imported
    phi = crank_angles(n)
    _, loops = _calibrate(s.full, phi)
    print(json.dumps(_sample(s.full, phi, loops)))


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
    t_pos: float | None = None          # medians [s per call]
    t_full: float | None = None
    est: bool = False
    dev: dict | None = None
    note: str = ""
    pos_spread: tuple | None = None     # (median, q1, q3)
    full_spread: tuple | None = None
    full_alone: tuple | None = None     # pos+vel+acc alone in a fresh process
    alone_process_cpu: float | None = None   # median CPU [s] of its whole fresh process


def run_linkage(label, fourbar, sizes, rounds, log, fresh=True, clock_name="cpu"):
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
        fast = [s for s in solvers if s.available and not s.slow]
        jobs = [((s.name, "pos"), s.pos) for s in fast] + [((s.name, "full"), s.full) for s in fast]
        got = interleaved(jobs, phi, rounds)
        ref = solvers[0].convert_full(got[(solvers[0].name, "full")][1])
        lone, lone_cpu = (alone(fourbar, [s.name for s in fast], n, rounds, clock_name)
                          if fresh else ({}, {}))
        for s in solvers:
            if not s.available:
                rows.append(Row(label, s.name, n, note=s.missing))
                continue
            if s.slow:
                limit = SLOW_LIMIT.get(s.name)
                if limit is not None and n > limit:
                    base = measured.get(s.name)
                    if base is None:
                        rows.append(Row(label, s.name, n, note="not measured"))
                        continue
                    nb, tp, tf = base
                    rows.append(Row(label, s.name, n, tp * n / nb, tf * n / nb, est=True,
                                    note=f"extrapolated from N = {nb}"))
                    continue
                # minutes per call at large N: a few samples of its own, not interleaved
                slow_rounds = 1 if n > 360 else 2
                g = interleaved([("pos", s.pos), ("full", s.full)], phi, slow_rounds)
                ps, fs, out = spread(g["pos"][0]), spread(g["full"][0]), g["full"][1]
            else:
                ps = spread(got[(s.name, "pos")][0])
                fs = spread(got[(s.name, "full")][0])
                out = got[(s.name, "full")][1]
            res = s.check(phi) if s.check is not None else s.convert_full(out)
            measured[s.name] = (n, ps[0], fs[0])
            rows.append(Row(label, s.name, n, ps[0], fs[0], dev=deviation(res, ref),
                            note="; ".join(s.notes), pos_spread=ps, full_spread=fs,
                            full_alone=lone.get(s.name), alone_process_cpu=lone_cpu.get(s.name)))
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
        got = interleaved([("ours", ours), ("power", power)] + ([("kin", kin)] if kin else []),
                          phi, repeat)
        t_ours, mo = spread(got["ours"][0])[0], got["ours"][1]
        t_pow, mp = spread(got["power"][0])[0], got["power"][1]
        scale = np.max(np.abs(mp))
        rows.append(("ours solve + solve_forces", n, t_ours,
                     float(np.max(np.abs(mo - mp)) / scale), None))
        rows.append(("power balance (hand kinematics)", n, t_pow, 0.0, None))
        if kin is None:
            rows.append(("kinepy solve_dynamics", n, None, None, "not installed"))
        else:
            t_k, mk = spread(got["kin"][0])[0], got["kin"][1]
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


def fmt_ms(sp, est=False):
    """median [q1–q3] of a time per call, in ms."""
    if sp is None:
        return "—"
    m, q1, q3 = sp

    def f(x):
        x *= 1e3
        return f"{x:.3g}" if x < 100 else f"{x:,.0f}"
    return ("~" if est else "") + (f"{f(m)} [{f(q1)}–{f(q3)}]" if q1 != q3 else f(m))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", default="360,3600,100000",
                    help="comma-separated numbers of crank angles (default 360,3600,100000)")
    ap.add_argument("--rounds", "--repeat", type=int, default=9, dest="rounds",
                    help="interleaved timing rounds (samples per solver and size)")
    ap.add_argument("--quick", action="store_true", help="sizes 360,3600, 3 rounds (smoke run)")
    ap.add_argument("--no-fresh", action="store_true",
                    help="skip the timings of each solver alone in a fresh process")
    ap.add_argument("--markdown", action="store_true", help="print the tables as Markdown")
    ap.add_argument("--clock", choices=sorted(CLOCKS), default="cpu",
                    help="what a sample measures: cpu = time.process_time (user + system CPU "
                         "of the process; default: least disturbed by other work on a shared "
                         "machine) or wall = time.perf_counter")
    ap.add_argument("--alone", help=argparse.SUPPRESS)       # child: one solver, fresh process
    ap.add_argument("--linkage", help=argparse.SUPPRESS)
    ap.add_argument("--n", type=int, help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    global clock
    clock = CLOCKS[args.clock]
    if args.alone:
        _alone_child(args.linkage, args.alone, args.n)
        return 0
    sizes = [360, 3600] if args.quick else [int(x) for x in args.sizes.split(",") if x.strip()]
    rounds = 3 if args.quick else max(1, args.rounds)
    t_start = time.perf_counter()
    load_start = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")

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
        rows, cn, solvers = run_linkage(label, fourbar, sizes, rounds, log,
                                        fresh=not args.no_fresh, clock_name=args.clock)
        all_rows += rows
        notes += cn
        n = max(sizes)
        by = {r.solver: r for r in rows if r.n == n}
        ours, plain = by[OURS], by[PLAIN]

        def ratio(name, what, need=None, inverse=False):
            r = by.get(name)
            if r is None or r.t_full is None:
                targets.append((label, what, "—", "—", "—",
                                "n/a (" + (r.note if r else "missing") + ")"))
                return
            a, b = (ours, r) if inverse else (r, ours)
            inter = a.t_full / b.t_full
            lone = (a.full_alone[0] / b.full_alone[0]
                    if a.full_alone and b.full_alone else None)
            mark = "~" if r.est else ""
            needed = "—" if need is None else (f"≤ {need:g}×" if inverse else f"≥ {need:g}×")
            ok = "" if need is None else verdict(
                (inter <= need if inverse else inter >= need)
                and (lone is None or (lone <= need if inverse else lone >= need)))
            targets.append((label, what, f"{mark}{inter:,.2f}×",
                            "—" if lone is None else f"{lone:,.2f}×", needed, ok))
        ratio(PLAIN, f"ours time / plain closed form time, pos+vel+acc, N={n}", 2.0,
              inverse=True)
        ratio("pylinkage (numba)", f"pylinkage numba time / ours, pos+vel+acc, N={n}", 1.0)
        ratio("mechanism (fsolve)", f"mechanism time / ours, pos+vel+acc, N={n}", 1000)
        ratio("kinepy", f"kinepy time / ours, pos + its FD vel/acc, N={n}")
        for s in solvers[1:]:
            meas = [r for r in rows if r.solver == s.name and r.dev is not None]
            if not meas:
                targets.append((label, f"agreement {s.name}", "—", "—", "—",
                                "n/a (" + (s.missing or "not measured") + ")"))
                continue
            r = meas[-1]
            d = r.dev
            if s.kind == "exact":
                worst = max(d["pos"], d["ang"], d["vel"] or 0.0, d["acc"] or 0.0)
                targets.append((label, f"agreement {s.name} (exact), N={r.n}", fmt_e(worst),
                                "", f"≤ {EXACT_TOL:g}", verdict(worst <= EXACT_TOL)))
            elif s.kind == "fsolve":
                worst = max(d["pos"], d["ang"], d["vel"] or 0.0, d["acc"] or 0.0)
                tol = 10 * MECHANISM_XTOL
                targets.append((label, f"agreement {s.name}, N={r.n} (fsolve xtol "
                                f"{MECHANISM_XTOL:.3g} relative; tol 10·xtol)", fmt_e(worst),
                                "", f"≤ {tol:.1e}", verdict(worst <= tol)))
            else:
                worst = max(d["pos"], d["ang"])
                targets.append((label, f"agreement {s.name} positions (closed form), N={r.n}",
                                fmt_e(worst), "", f"≤ {EXACT_TOL:g}",
                                verdict(worst <= EXACT_TOL)))
                h = 2 * np.pi / r.n
                worst = max(d["vel"], d["acc"])
                targets.append((label, f"agreement {s.name} vel/acc (its central FD, h = 2π/N"
                                f" = {h:.2g} rad), N={r.n}", fmt_e(worst), "",
                                "none (FD: ~h² + δpos/h²)", "n/a"))

    kin_rows, _ = kinetostatics(sizes, rounds, log)
    elapsed = time.perf_counter() - t_start

    md = args.markdown
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(("## " if md else "") + "Peer benchmark: planar linkage kinematics")
    print()
    print("Versions: " + ", ".join(versions) + f"; Python {sys.version.split()[0]}; "
          f"{os.cpu_count()} CPUs, load average {load_start:.2f} at the start, {load:.2f} at "
          f"the end; {rounds} interleaved rounds per size (each solver once per round, the "
          f"order rotating), sizes {', '.join(map(str, sizes))}; clock: {args.clock} ("
          + ("time.process_time: CPU time of the process, user + system"
             if args.clock == "cpu" else "time.perf_counter: wall time") + ")")
    print()
    unit = "ms"         # of the clock named above (CPU time by default)
    head = ["linkage", "solver", "N", f"pos only [{unit}]", f"pos+vel+acc [{unit}]",
            f"pos+vel+acc alone [{unit}]", "alone: process CPU [s]", "max|ΔC|/max|C|",
            "max|Δθ| [rad]", "rel Δvel C", "rel Δacc C", "notes"]
    body = []
    for r in all_rows:
        d = r.dev or {}
        note = r.note
        if r.solver == OURS:
            note = "reference; both columns time m.solve (no positions-only API)"
        elif r.solver == PLAIN:
            note = "real arithmetic, no complex exponentials (timing reference)"
        elif r.solver.startswith("pylinkage (numba)") and r.t_full is not None:
            note = (note + "; " if note else "") + "analytic vel/acc (numba)"
        elif r.solver.startswith("pylinkage (pure") and r.t_full is not None and not r.est:
            note = (note + "; " if note else "") + "step / step_with_derivatives"
        elif r.solver == "kinepy" and r.t_full is not None and not r.est:
            note = (note + "; " if note else "") + \
                f"vel/acc: its central FD, {d.get('dropped', 0)} end samples NaN"
        elif r.solver.startswith("mechanism") and r.t_full is not None and not r.est:
            note = (note + "; " if note else "") + "3 fsolve per position; few samples"
        if r.est:
            d = {}
            note = (note + "; " if note else "") + "deviation: see measured row"
        pos = r.pos_spread or ((r.t_pos,) * 3 if r.t_pos is not None else None)
        full = r.full_spread or ((r.t_full,) * 3 if r.t_full is not None else None)
        body.append([r.linkage, r.solver, f"{r.n:,}", fmt_ms(pos, r.est), fmt_ms(full, r.est),
                     fmt_ms(r.full_alone),
                     "—" if r.alone_process_cpu is None else f"{r.alone_process_cpu:.2f}",
                     fmt_e(d.get("pos")), fmt_e(d.get("ang")),
                     fmt_e(d.get("vel")), fmt_e(d.get("acc")), note])
    print(table(head, body, md))
    print()
    foot = [f"Times are {'CPU time (time.process_time)' if args.clock == 'cpu' else 'wall time'} "
            "per call: median [first–third quartile] of the rounds; a sample loops "
            "the call to ≥ 20 ms. Each solver returns its own natural output (ours a Motion, "
            "pylinkage its arrays or lists, kinepy its point array); turning it into the "
            "comparison's arrays happens outside the clock.",
            "\"alone\": the same pos+vel+acc call timed in fresh processes that run only "
            "that solver (no other library's freed arrays to reuse): one process per solver "
            "and round, the rounds interleaved (the order rotating), each timing one sample "
            "after a warm-up call; median [quartiles] over the rounds. \"process CPU\": the "
            "median CPU time (user + system, the kernel's resource usage of the child) of such "
            "a whole process: interpreter, imports, warm-up and the sample. The interleaved "
            "columns share one process.",
            "~ extrapolated from the largest measured size at constant throughput (the slow "
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
    kbody = [[name, f"{n:,}", "—" if t is None else f"{t * 1e3:.3g}",
              fmt_e(dev), note or ""] for name, n, t, dev, note in kin_rows]
    print(table(["solver", "N", f"median {unit} per call", "max|ΔM_b| / max|M_b| vs power balance",
                 "notes"], kbody, md))
    print()
    print("Masses: crank 1 kg, coupler 2 kg, rocker 3 kg at mid-link, J = m·l²/12, "
          "g = 9.81 m/s² along −y; kinepy's error is its O(h²) finite-difference inertia.")
    print()
    print(("### " if md else "") + "Targets, measured in this run")
    print()
    print(table(["linkage", "target", "interleaved", "alone (fresh process)", "needed",
                 "result"], [list(t) for t in targets], md))
    print()
    print(f"Total benchmark time: {elapsed:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
