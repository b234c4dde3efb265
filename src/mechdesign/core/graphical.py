"""The graphical method (图解法) as a construction, not a relabelling of the analytic values.

At one position of a mechanism (its kinematic diagram: the joint positions, drawn at μl),
the velocity and acceleration polygons are built group by group as on paper: a vector whose
magnitude is known is drawn at its scale with its length rounded to the drawing's accuracy
(0.5 mm) — a given one (the crank's ω·l and ω²·l, its ω the brief's) and a known force at
their exact length, so that they are listed at their own value; a vector whose direction only is known is a line through a drawn point; the
unknown point of the polygon is where two such lines meet (:func:`intersect`). Its lengths
are then *measured* (rounded to 0.5 mm) and read back at the scale, and the angular
velocities and accelerations found from them (ω = v_CB / l_CB) are what the later groups
use. Inertia forces follow from the accelerations read; the force analysis goes from the
last group to the crank: the moment equations about the inner pin (arms measured at μl,
rounded) give the tangential components, the force polygon closes with the two remaining
directions (another intersection), and the crank's moment equation gives the balancing
torque M_b and the balancing force P_b = M_b / l at the crank pin.

All values SI (complex x + iy for vectors); drawing coordinates in mm (pole at 0).
The analytic (engine) values are never read here: the caller compares afterwards.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .fields import q
from .mechanism import RPR, RRP, RRR, Crank, LinkPoint

#: Drawing accuracy: every length drawn or measured is rounded to this [mm].
STEP_MM = 0.5
_NICE = (1.0, 2.0, 2.5, 5.0, 10.0)


def nice_scale(per_mm: float) -> float:
    """The smallest value 1, 2, 2.5 or 5 × 10^k not below ``per_mm`` (a drawing scale)."""
    if not per_mm > 0:
        return 1.0
    k = math.floor(math.log10(per_mm))
    for m in _NICE:
        if m * 10 ** k >= per_mm * (1 - 1e-12):
            return m * 10 ** k
    return 10 ** (k + 1)


def rounded(mm: float, step: float | None = None) -> float:
    """A length as a drawing gives it: to ``step`` mm."""
    step = STEP_MM if step is None else step
    return round(mm / step) * step


def unit(z: complex) -> complex:
    return z / abs(z) if abs(z) > 0 else 0j


def cross(a: complex, b: complex) -> float:
    return a.real * b.imag - a.imag * b.real


def intersect(p1: complex, d1: complex, p2: complex, d2: complex) -> complex:
    """The point where the line through ``p1`` along ``d1`` meets the line through ``p2``
    along ``d2`` (the two direction lines of a vector equation). Parallel lines (a
    degenerate position, e.g. a limit position where the unknown is zero) give ``p1``."""
    den = cross(d1, d2)
    if abs(den) < 1e-12 * abs(d1) * abs(d2):
        return p1
    t = cross(p2 - p1, d2) / den
    return p1 + t * d1


# ---------------------------------------------------------------- data

@dataclass(frozen=True)
class Term:
    """One vector of a vector equation (a column of its 大小/方向 table) or of a force
    polygon. ``direction`` codes: "perp:BC" (⊥ BC), "to:CB" (from C towards B), "sum" (a
    resultant: its direction is the polygon's segment), "guide:θ"
    (∥ the fixed guide at angle θ [rad]), "bar:4" (∥ guide bar 4), "rot:4" (v_r turned 90°
    in the sense of ω4), "known" (from the polygon drawn before)."""

    symbol: str = q("", "v_C, v_CB, a^n_CB, a^k_A4A3, G4, FI4, R54, R54^t, Pb …")
    known: bool = q("", "magnitude known before the construction (else measured)")
    direction: str = q("", "direction code (see the class doc)")
    tail: str = q("", "polygon point at its tail")
    head: str = q("", "polygon point at its head")
    value: complex = q("m/s, m/s² or N", "the vector as constructed (length × μ along it)")
    length: float = q("mm", "length on the drawing, drawn or measured to 0.5 mm")
    read: float = q("m/s, m/s² or N", "magnitude read: length × μ")
    kind: str = q("", "absolute | relative | normal | tangential | sliding | coriolis | known | "
                      "reaction | total | internal | balancing")
    computed: float | None = q("m/s, m/s² or N", "a known vector's magnitude as computed before it "
                               "is drawn (ω²·l with the ω read; None: measured)", default=None)


@dataclass(frozen=True)
class VectorEquation:
    """``left`` = ``right`` (terms), as written in the report."""

    group: str = q("", "the Assur group")
    left: tuple[Term, ...] = q("", "terms of the left side")
    right: tuple[Term, ...] = q("", "terms of the right side")


@dataclass
class KinDrawing:
    """A velocity (``prime`` "") or acceleration (``prime`` "'") polygon being drawn."""

    kind: str
    scale: float                      # μ: (m/s)/mm or (m/s²)/mm
    prime: str = ""
    points: dict = field(default_factory=dict)       # polygon point → mm (complex)
    equations: list = field(default_factory=list)
    omega: dict = field(default_factory=dict)        # link → ω read [rad/s]
    alpha: dict = field(default_factory=dict)        # link → α read [rad/s²]
    slide: dict = field(default_factory=dict)        # slider link → relative vector read (SI)
    # points reached from the pole by given vectors only (the crank pin: v_A = ω·l, a_A = ω²·l
    # with ω the brief's): drawn at their exact length and listed at their computed value
    exact: set = field(default_factory=set)

    def __post_init__(self):
        self.points.setdefault(self.pole, 0j)

    @property
    def pole(self) -> str:
        return "p" + self.prime

    def drawn(self, symbol, tail, value: complex, head, direction, kind, given=False) -> Term:
        """A vector of known magnitude and direction, drawn at its rounded length; a
        ``given`` one (ω·l of the crank, whose ω is the brief's) at its exact length."""
        given = given and (tail == self.pole or tail in self.exact)
        length = abs(value) / self.scale if given else rounded(abs(value) / self.scale)
        if given:
            self.exact.add(head)
        self.points[head] = self.points[tail] + length * unit(value)
        return Term(symbol, True, direction, tail, head, length * self.scale * unit(value),
                    length, length * self.scale, kind, abs(value))

    def measured(self, symbol, tail, head, direction, kind, known=False) -> Term:
        """A vector of the drawing between two points, measured (0.5 mm)."""
        d = self.points[head] - self.points[tail]
        length = rounded(abs(d))
        return Term(symbol, known, direction, tail, head, length * self.scale * unit(d),
                    length, length * self.scale, kind)

    def length(self, name: str) -> float:
        """The length pole → ``name`` [mm]: measured (0.5 mm), exact for a given point."""
        d = abs(self.points[name])
        return d if name in self.exact else rounded(d)

    def read(self, name: str) -> complex:
        """The absolute vector of polygon point ``name`` as measured from the pole (a
        given point's as computed)."""
        return self.length(name) * self.scale * unit(self.points[name])


@dataclass(frozen=True)
class Force:
    """A force on a link: ``name`` (G4, FI4, Fr, R54, …) acting at ``at``."""

    name: str = q("", "G (weight), FI (inertia force), Fr (resistance), R{a}{b} (reaction)")
    value: complex = q("N", "the force")
    at: complex = q("m", "a point of its line of action")
    kind: str = q("", "known | reaction", default="known")


@dataclass(frozen=True)
class Moment:
    """One term of a moment equation: force ``name`` (or a couple) of magnitude ``force``
    with arm ``arm`` measured on the drawing, turning ``sign`` (+1 CCW)."""

    name: str = q("", "the force or couple")
    force: float = q("N", "its magnitude (0 for a couple)")
    arm: float = q("mm", "arm measured at μl, to 0.5 mm (0 for a couple)")
    sign: int = q("1", "+1 counter-clockwise, −1 clockwise")
    value: float = q("N·m", "the moment: sign × force × arm × μl (a couple: itself)")


@dataclass(frozen=True)
class MomentEquation:
    """ΣM_point = 0 on ``link``: the known terms and the unknown found from them."""

    link: str = q("", "the link")
    point: str = q("", "the point the moments are taken about")
    terms: tuple[Moment, ...] = q("", "the known moments")
    unknown: str = q("", "the unknown: R{a}{b}^t, R{a}{b} (normal force), M{a}{b}, Mb, Pb")
    arm: float = q("mm", "the unknown's arm on the drawing (0 for a couple)")
    result: float = q("N or N·m", "the unknown, signed (+: CCW moment about the point)")


@dataclass(frozen=True)
class ForceGroup:
    """The force construction of one group at one position: its loads per link, the moment
    equations, the force polygon (points in mm, vectors as :class:`Term`) and the reactions
    found."""

    group: str = q("", "the group")
    links: tuple[str, ...] = q("", "its links")
    loads: dict[str, tuple[Force, ...]] = q("", "link → its known loads")
    moments: tuple[MomentEquation, ...] = q("", "the moment equations, in order")
    scale: float = q("N/mm", "μF of the force polygon")
    points: dict[str, complex] = q("mm", "the force polygon's points on the drawing")
    vectors: tuple[Term, ...] = q("", "the force polygon's vectors")
    reactions: dict[str, complex] = q("N", "R{a}{b} (force of a on b) read from the polygon")
    balancing_torque: float | None = q("N·m", "the crank: M_b, CCW +", default=None)
    balancing_force: complex | None = q("N", "the crank: P_b at the crank pin ⊥ the crank",
                                        default=None)
    reaction_points: dict[str, complex] = q("m", "the joint where each reaction acts",
                                            default_factory=dict)


# ---------------------------------------------------------------- kinematics

def img(point: str, frame: set, prime: str) -> str:
    return "p" + prime if point in frame else (f"p({point})" if point.lower() == "p"
                                               else point.lower()) + prime


def _sym(x: str, sub: str) -> str:
    return f"{x}_{sub}"


def kinematic_drawing(mech, pos: dict, omega2: float, kind: str, scale: float,
                      velocities: KinDrawing | None = None) -> KinDrawing:
    """The velocity (``kind`` "velocity") or acceleration polygon of ``mech`` at the joint
    positions ``pos`` (point → complex [m]) with crank speed ``omega2`` [rad/s, CCW +],
    drawn at ``scale``. The acceleration polygon needs the velocity drawing (ω and the
    sliding velocities read from it)."""
    acc = kind == "acceleration"
    d = KinDrawing(kind, scale, "'" if acc else "")
    pr, frame = d.prime, set(mech.frame_points)
    x = "a" if acc else "v"
    w = velocities.omega if acc else d.omega
    if acc:
        d.omega = dict(w)

    def I(p):     # noqa: E743 - the polygon image of p
        return img(p, frame, pr)

    # the crank's ω and α are the brief's: its vectors ω·l, ω²·l are given, not measured
    given = {g.link for g in mech.groups if isinstance(g, Crank)}

    def rot(tail_pt, head_pt, link, head_img=None, rel_sym=None):
        """Known rotation terms of head relative to tail on ``link`` (ω, α known)."""
        r = pos[head_pt] - pos[tail_pt]
        sub = rel_sym or f"{head_pt}{tail_pt}"
        t0 = I(tail_pt)
        ex = link in given
        if not acc:
            return [d.drawn(_sym("v", sub), t0, 1j * w[link] * r, head_img or I(head_pt),
                            f"perp:{tail_pt}{head_pt}", "relative", ex)]
        out = []
        n = -w[link] ** 2 * r
        a_t = 1j * d.alpha.get(link, 0.0) * r
        mid = (head_img or I(head_pt)) if abs(a_t) == 0 else f"n{head_pt.lower()}{pr}"
        out.append(d.drawn(_sym("a^n", sub), t0, n, mid, f"to:{head_pt}{tail_pt}", "normal", ex))
        if abs(a_t) > 0:
            out.append(d.drawn(_sym("a^t", sub), mid, a_t, head_img or I(head_pt),
                               f"perp:{tail_pt}{head_pt}", "tangential", ex))
        return out

    def known(p):
        return [] if p in frame else [Term(_sym(x, p), True, "known", d.pole, I(p),
                                           d.read(I(p)), d.length(I(p)),
                                           d.length(I(p)) * scale, "absolute")]

    def signed_rate(r: complex, v: Term) -> float:
        """ω (or α) of a link from the measured relative vector v ⊥ r: |v|/|r| with the
        sign of r × v."""
        return math.copysign(v.read / abs(r), cross(r, v.value)) if v.read else 0.0

    for g in mech.groups:
        name = g.name
        if isinstance(g, Crank):
            if not acc:
                d.omega[g.link] = omega2
                d.alpha[g.link] = 0.0
                terms = rot(g.pivot, g.tip, g.link)
            else:
                d.alpha[g.link] = 0.0
                terms = rot(g.pivot, g.tip, g.link)
            left = Term(_sym(x, g.tip), True, terms[0].direction, d.pole, I(g.tip),
                        d.read(I(g.tip)), d.length(I(g.tip)), d.length(I(g.tip)) * scale,
                        "absolute")
            d.equations.append(VectorEquation(name, (left,), tuple(terms)))
        elif isinstance(g, LinkPoint):
            terms = rot(g.origin, g.name, g.link)
            # about a fixed pivot: v ⊥ the radius, and a along it only without a tangential
            # part; a^n + a^t is a resultant whose direction the polygon gives ("sum"); so is
            # a point of a moving link (v_S3 = v_A + v_S3A: the image method's segment p s3,
            # measured — review 48: it stood "√ known" with no segment nor value)
            left = _abs_term(d, x, g.name, I(g.name),
                             direction=("sum" if g.origin not in frame or len(terms) > 1
                                        else terms[0].direction))
            d.equations.append(VectorEquation(name, (left,), tuple(known(g.origin) + terms)))
        elif isinstance(g, RRR):
            B, D, C, l1, l2 = g.b, g.d, g.c, g.link1, g.link2
            r1, r2 = pos[C] - pos[B], pos[C] - pos[D]
            c = I(C)
            if not acc:
                d.points[c] = intersect(d.points[I(B)], 1j * r1, d.points[I(D)], 1j * r2)
                t1 = d.measured(_sym("v", C + B), I(B), c, f"perp:{B}{C}", "relative")
                t2 = d.measured(_sym("v", C + D), I(D), c, f"perp:{D}{C}", "relative")
                d.omega[l1], d.omega[l2] = signed_rate(r1, t1), signed_rate(r2, t2)
                s1, s2 = [t1], [t2]
            else:
                n1 = d.drawn(_sym("a^n", C + B), I(B), -w[l1] ** 2 * r1, f"n{l1}{pr}",
                             f"to:{C}{B}", "normal")
                n2 = d.drawn(_sym("a^n", C + D), I(D), -w[l2] ** 2 * r2, f"n{l2}{pr}",
                             f"to:{C}{D}", "normal")
                d.points[c] = intersect(d.points[n1.head], 1j * r1, d.points[n2.head], 1j * r2)
                t1 = d.measured(_sym("a^t", C + B), n1.head, c, f"perp:{B}{C}", "tangential")
                t2 = d.measured(_sym("a^t", C + D), n2.head, c, f"perp:{D}{C}", "tangential")
                d.alpha[l1], d.alpha[l2] = signed_rate(r1, t1), signed_rate(r2, t2)
                s1, s2 = [n1, t1], [n2, t2]
            left = _abs_term(d, x, C, c, known=False,
                             direction=f"perp:{D}{C}" if D in frame and not acc else "")
            if D in frame:        # a rocker on the frame: v_C ⊥ DC (a_C = a^n + a^t)
                d.equations.append(VectorEquation(name, tuple(s2) if acc else (left,),
                                                  tuple(known(B) + s1)))
            else:
                d.equations.append(VectorEquation(name, tuple(known(B) + s1),
                                                  tuple(known(D) + s2)))
        elif isinstance(g, RRP):
            B, C = g.b, g.c
            r = pos[C] - pos[B]
            c, u = I(C), complex(np.exp(1j * g.guide_angle))
            if not acc:
                d.points[c] = intersect(0j, u, d.points[I(B)], 1j * r)
                t = d.measured(_sym("v", C + B), I(B), c, f"perp:{B}{C}", "relative")
                d.omega[g.rod] = signed_rate(r, t)
                d.omega[g.slider] = 0.0
                s = [t]
            else:
                n = d.drawn(_sym("a^n", C + B), I(B), -w[g.rod] ** 2 * r, f"n{g.rod}{pr}",
                            f"to:{C}{B}", "normal")
                d.points[c] = intersect(0j, u, d.points[n.head], 1j * r)
                t = d.measured(_sym("a^t", C + B), n.head, c, f"perp:{B}{C}", "tangential")
                d.alpha[g.rod] = signed_rate(r, t)
                d.alpha[g.slider] = 0.0
                s = [n, t]
            left = _abs_term(d, x, C, c, known=False, direction=f"guide:{g.guide_angle:.6f}")
            d.equations.append(VectorEquation(name, (left,), tuple(known(B) + s)))
        elif isinstance(g, RPR):
            A, O, bar, sl = g.a, g.pivot, g.bar, g.slider
            r = pos[A] - pos[O]
            ub = unit(r) * complex(np.exp(-1j * math.asin(g.offset / abs(r))))   # the bar's axis
            a3, a4 = I(A), f"{A.lower()}{bar}{pr}"
            sub4, sub43 = f"{A}{bar}", f"{A}{bar}{A}{sl}"
            if not acc:
                d.points[a4] = intersect(d.points[I(O)], 1j * r, d.points[a3], ub)
                t = d.measured(_sym("v", f"{A}{bar}{O}"), I(O), a4, f"perp:{O}{A}", "relative")
                d.omega[bar] = d.omega[sl] = signed_rate(r, t)
                vr = d.measured(_sym("v", sub43), a3, a4, f"bar:{bar}", "sliding")
                d.slide[sl] = vr.value
                right = [_abs_term(d, x, f"{A}{sl}", a3)] + [vr]
                left_terms = known(O) + [t]
            else:
                n = d.drawn(_sym("a^n", f"{A}{bar}{O}"), I(O), -w[bar] ** 2 * r, f"n{bar}{pr}",
                            f"to:{A}{O}", "normal")
                vrel = velocities.slide[sl]
                k = d.drawn(_sym("a^k", sub43), a3, 2j * w[bar] * vrel, f"k{pr}", f"rot:{bar}",
                            "coriolis")
                d.points[a4] = intersect(d.points[n.head], 1j * r, d.points[k.head], ub)
                t = d.measured(_sym("a^t", f"{A}{bar}{O}"), n.head, a4, f"perp:{O}{A}",
                               "tangential")
                d.alpha[bar] = d.alpha[sl] = signed_rate(r, t)
                ar = d.measured(_sym("a^r", sub43), k.head, a4, f"bar:{bar}", "sliding")
                right = [_abs_term(d, x, f"{A}{sl}", a3), k, ar]
                left_terms = known(O) + [n, t]
            left = _abs_term(d, x, sub4, a4, known=False, direction=f"perp:{O}{A}")
            if O in frame:     # v_A4 ⊥ O3A (a_A4 = a^n + a^t) = v_A3 + v_A4A3 …
                left_terms = [left] if not acc else left_terms
            d.equations.append(VectorEquation(name, tuple(left_terms), tuple(right)))
        else:                           # pragma: no cover - every group type is above
            raise TypeError(f"no graphical construction for group {g!r}")
    return d


def _abs_term(d: KinDrawing, x, sub, point, known=True, direction="") -> Term:
    length = d.length(point)
    return Term(_sym(x, sub), known, direction or "known", d.pole, point,
                length * d.scale * unit(d.points[point]), length, length * d.scale, "absolute")


def point_acceleration(mech, pos: dict, vel: KinDrawing, acc: KinDrawing, point: str) -> complex:
    """The acceleration of ``point`` read from the acceleration polygon (its image), or,
    for a point not drawn, by the image of its link from a drawn point of that link."""
    frame = set(mech.frame_points)
    name = img(point, frame, "'")
    if name in acc.points:
        return acc.read(name)
    for g in mech.groups:
        carried, _ = g.members()
        for link, pts in carried:
            if point in pts:
                for o in pts:
                    if img(o, frame, "'") in acc.points:
                        r = pos[point] - pos[o]
                        return acc.read(img(o, frame, "'")) + (
                            1j * acc.alpha.get(link, 0.0) - vel.omega.get(link, 0.0) ** 2) * r
    raise KeyError(point)


# ---------------------------------------------------------------- forces

def _moment_terms(forces, about: complex, mu_l: float, couples=()) -> tuple[list, float]:
    """Moment terms about ``about`` with arms measured at μl (0.5 mm); the sum [N·m]."""
    out, total = [], 0.0
    for f in forces:
        if abs(f.value) == 0:
            continue
        c = cross(f.at - about, f.value)
        arm = rounded(abs(c) / abs(f.value) / mu_l)
        if arm == 0:
            continue
        sign = 1 if c > 0 else -1
        v = sign * abs(f.value) * arm * mu_l
        out.append(Moment(f.name, abs(f.value), arm, sign, v))
        total += v
    for name, m in couples:
        if m:
            out.append(Moment(name, 0.0, 0.0, 1 if m > 0 else -1, m))
            total += m
    return out, total


class _ForcePolygon:
    def __init__(self, scale: float):
        self.scale, self.points, self.vectors = scale, {"0": 0j}, []

    def add(self, name, value: complex, kind="known", known=True) -> Term:
        """A known force (a load, P_b, a force a moment equation gave): drawn at its exact
        length |F|/μF and read as its own value, so that its length × μF is the value its
        table lists (drawn to the nearest 0.5 mm it gave 33.0 mm × 50 = 1650 for 1662.5 N)."""
        tail = list(self.points)[-1]
        length = abs(value) / self.scale
        head = str(len(self.points))
        self.points[head] = self.points[tail] + length * unit(value)
        t = Term(name, known, "", tail, head, length * self.scale * unit(value), length,
                 abs(value), kind)
        self.vectors.append(t)
        return t

    def measure(self, name, tail, head, kind="reaction") -> Term:
        d = self.points[head] - self.points[tail]
        length = rounded(abs(d))
        t = Term(name, False, "", tail, head, length * self.scale * unit(d), length,
                 length * self.scale, kind)
        self.vectors.append(t)
        return t


def force_drawing(mech, pos: dict, loads: dict, couples: dict, mu_l: float, mu_f: dict):
    """The force analysis group by group, last group first, down to the crank.

    ``loads[link]``: the known :class:`Force` list of each link (weights, inertia forces read
    from the acceleration polygon, external loads); ``couples[link]``: the inertia couple
    [N·m]; ``mu_f[group name]``: the force polygon's scale [N/mm]. Returns the
    :class:`ForceGroup` of every group with links, in the order solved (the crank last)."""
    loads = {k: list(v) for k, v in loads.items()}
    out = []
    for g in reversed(mech.groups):
        if not g.links:
            continue
        joints = mech.joints[g.name]
        links = list(g.links)
        mu = mu_f[g.name]
        fp = _ForcePolygon(mu)
        found, moments = {}, []
        if isinstance(g, Crank):
            j = joints[0]
            O = pos[g.pivot]
            known = loads.get(g.link, [])
            terms, m = _moment_terms(known, O, mu_l, [(f"MI{g.link}", couples.get(g.link, 0.0))])
            mb = -m
            # the crank's length is a known dimension, not a measured arm: P_b = M_b / l_OA
            # with the true length (its drawn length, l_OA/mu_l, kept unrounded as the arm)
            l_mm = abs(pos[g.tip] - O) / mu_l
            pb_mag = mb / (l_mm * mu_l)
            pb = pb_mag * 1j * unit(pos[g.tip] - O)      # its moment about O is M_b
            moments.append(MomentEquation(g.link, g.pivot, tuple(terms), "Mb", 0.0, mb))
            moments.append(MomentEquation(g.link, g.pivot + g.tip, (), "Pb", l_mm, pb_mag))
            for f in known:
                if abs(f.value) > 0:
                    fp.add(f.name, f.value)
            end = list(fp.points)[-1]
            fp.add("Pb", pb, "balancing")
            # with P_b at the pin the frame reaction closes the polygon (R'); with M_b as a
            # couple (the analytic model) it closes the known loads alone (R)
            r = fp.measure(j.name + "'", list(fp.points)[-1], "0")
            found[j.name + "'"] = r.value
            found[j.name] = fp.measure(j.name, end, "0", "total").value
            out.append(ForceGroup(g.name, tuple(links), {g.link: tuple(known)}, tuple(moments),
                                  mu, dict(fp.points), tuple(fp.vectors), found, mb, pb,
                                  {j.name: pos[j.point]}))
            continue
        inner = next(j for j in joints if j.link_a in links and j.link_b in links)
        outer = {j.link_b: j for j in joints if j.link_a not in links}
        L0, L1 = links
        if inner.kind == "R":
            C = pos[inner.point]
            tang, unknown_dir = {}, {}
            for lk in links:
                j = outer[lk]
                terms, m = _moment_terms(loads.get(lk, []), C, mu_l,
                                         [(f"MI{lk}", couples.get(lk, 0.0))])
                if j.kind == "R":
                    r = pos[j.point] - C
                    l_mm = rounded(abs(r) / mu_l)
                    t = -m / (l_mm * mu_l)
                    tang[lk] = t * 1j * unit(r)
                    unknown_dir[lk] = unit(r)
                    moments.append(MomentEquation(lk, inner.point, tuple(terms), f"{j.name}^t",
                                                  l_mm, t))
                else:   # a slider on a fixed guide: the normal force ⊥ the guide
                    unknown_dir[lk] = 1j * complex(np.exp(1j * j.guide_angle))
            first = {}
            if L0 in tang:
                first[L0] = fp.add(f"{outer[L0].name}^t", tang[L0], "tangential", True)
            start0 = "0"
            for f in loads.get(L0, []):
                if abs(f.value) > 0:
                    fp.add(f.name, f.value)
            end0 = list(fp.points)[-1]
            for f in loads.get(L1, []):
                if abs(f.value) > 0:
                    fp.add(f.name, f.value)
            if L1 in tang:
                first[L1] = fp.add(f"{outer[L1].name}^t", tang[L1], "tangential", True)
            E = list(fp.points)[-1]
            X = intersect(fp.points[E], unknown_dir[L1], 0j, unknown_dir[L0])
            fp.points["X"] = X
            for lk, a, b in ((L1, E, "X"), (L0, "X", start0)):
                j = outer[lk]
                nm = f"{j.name}^n" if lk in tang else j.name
                fp.measure(nm, a, b, "normal" if lk in tang else "reaction")
            # the whole outer reactions: R0 from X to the end of R0^t; R1 from the start of
            # R1^t to X
            r0_tail = "X"
            r0_head = first[L0].head if L0 in first else start0
            r1_tail = first[L1].tail if L1 in first else E
            r0 = fp.measure(outer[L0].name, r0_tail, r0_head, "total") if L0 in first else None
            r1 = fp.measure(outer[L1].name, r1_tail, "X", "total") if L1 in first else None
            for lk, tm in ((L0, r0), (L1, r1)):
                if tm is None:
                    tm = next(v for v in fp.vectors if v.symbol == outer[lk].name)
                found[outer[lk].name] = tm.value
            # the inner reaction: on L0 from L1 closes L0's polygon (end of its loads → X)
            ri = fp.measure(f"R{L1}{L0}", end0, "X", "internal")
            found[inner.name] = ri.value if inner.link_b == L0 else -ri.value
        else:        # RPR: slider (pin A to an earlier link) on a guide bar (pin O to frame)
            sl = next(lk for lk in links if outer[lk].point == inner.point)
            bar = next(lk for lk in links if lk != sl)
            A, O = pos[inner.point], pos[outer[bar].point]
            ts, cs = _moment_terms(loads.get(sl, []), A, mu_l, [(f"MI{sl}", couples.get(sl, 0.0))])
            couple = -cs                       # the couple of the bar on the slider
            tb, mb_ = _moment_terms(loads.get(bar, []), O, mu_l,
                                    [(f"MI{bar}", couples.get(bar, 0.0)),
                                     (f"M{sl}{bar}", -couple)])
            u = unit(A - O)
            l_mm = rounded(abs(A - O) / mu_l)
            nu = -mb_ / (l_mm * mu_l)          # the slider's normal force on the bar, along iu
            n_bar = nu * 1j * u
            moments.append(MomentEquation(bar, outer[bar].point, tuple(tb), f"R{sl}{bar}",
                                          l_mm, nu))
            for f in loads.get(bar, []):
                if abs(f.value) > 0:
                    fp.add(f.name, f.value)
            # the slider's force on the bar is known from the bar's moment equation: drawn
            # at that value, the polygon solves the frame's reaction
            t_sb = fp.add(f"R{sl}{bar}", n_bar, "reaction")
            r_fb = fp.measure(outer[bar].name, t_sb.head, "0", "reaction")
            found[outer[bar].name] = r_fb.value
            # the slider: R_bar→slider (= −n_bar, back along the same vector), its loads,
            # and the pin's reaction closes back to the start
            fp.vectors.append(Term(f"R{bar}{sl}", True, "", t_sb.head, t_sb.tail, -t_sb.value,
                                   t_sb.length, t_sb.read, "reaction"))
            last = t_sb.tail
            for f in loads.get(sl, []):
                if abs(f.value) > 0:
                    length = abs(f.value) / mu        # a known force: exact, as in add()
                    head = f"s{len(fp.points)}"
                    fp.points[head] = fp.points[last] + length * unit(f.value)
                    fp.vectors.append(Term(f.name, True, "", last, head,
                                           length * mu * unit(f.value), length, abs(f.value),
                                           "known"))
                    last = head
            if last == t_sb.tail:
                # a slider with no load of its own: its pin carries the bar's force back,
                # the equation's value (nothing to measure: known, as the bar's force is)
                r_ps = Term(outer[sl].name, True, "", last, t_sb.head, n_bar, t_sb.length,
                            abs(n_bar), "reaction")
                fp.vectors.append(r_ps)
            else:
                r_ps = fp.measure(outer[sl].name, last, t_sb.head, "reaction")
            found[outer[sl].name] = r_ps.value
            found[inner.name] = -n_bar if inner.link_b == sl else n_bar
            moments.insert(0, MomentEquation(sl, inner.point, tuple(ts), f"M{bar}{sl}", 0.0,
                                             couple))
        # pass the outer reactions on to the earlier links
        for lk in links:
            j = outer[lk]
            if j.link_a in mech_frame(mech):
                continue
            loads.setdefault(j.link_a, []).append(
                Force(f"R{j.link_b}{j.link_a}", -found[j.name], pos[j.point], "reaction"))
        out.append(ForceGroup(g.name, tuple(links), {lk: tuple(loads.get(lk, [])) for lk in links},
                              tuple(moments), mu, dict(fp.points), tuple(fp.vectors), found,
                              reaction_points={outer[lk].name: pos[outer[lk].point]
                                               for lk in links}))
    return out


def mech_frame(mech) -> set:
    return {mech.frame}
