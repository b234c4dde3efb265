"""A planar mechanism as a driving crank followed by Assur groups.

A :class:`Mechanism` knows frame points, groups added in solving order and the
joints between links; it solves the motion of every point and link for a whole array
of crank angles in one pass (one numpy call chain per group). Nothing here knows
about any particular machine.

Links and points are named by strings (the course numbers links: "2" the crank, ...);
each joint records which link is already known (``link_a``: frame or an earlier group)
and which belongs to the group (``link_b``), the order kinetostatics needs.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from . import kinematics as kin
from . import polygons as poly
from .errors import DesignError, Join, Msg, N_, _restore, message, pgettext
from .kinematics import AngleMotion, PointMotion, SlideMotion


class AssemblyError(DesignError):
    """A group cannot be assembled at some crank angle.

    ``code`` names the diagnosis: "grashof" (the crank of a four-bar cannot make a full
    turn), "slider_crank" (the crank of a slider-crank cannot), "guide_bar" (the slider of a
    guide bar is offset more than the crank pin's distance from the pivot) or "assembly"
    (a group further down the chain cannot close). The message gives the numbers and what to
    change (``str``: English; :meth:`text`: a report language). ``reason`` is the diagnosis
    as a message whose field ``{where}`` is filled with the group and the crank angle."""

    def __init__(self, group: str, kind: str, crank_angle_deg: float, count: int, *,
                 code: str = "assembly", reason: Msg | None = None, numbers: dict | None = None):
        self.group, self.kind = group, kind
        self.crank_angle_deg, self.count = crank_angle_deg, count
        self.code = code
        self.numbers = dict(numbers or {})
        where = Msg(N_("group '{group}' ({kind}) cannot be assembled at crank angle {angle:.2f}° "
                       "(and {more} more of the angles asked)"),
                    group=group, kind=kind, angle=crank_angle_deg, more=count - 1)
        if reason is None:
            reason = Msg(N_("{where}: the links are too short to close; check the lengths or the "
                            "branch"))
        super().__init__(Msg(reason.msgid, **reason.fields, where=where))

    def with_hint(self, en, zh: str | None = None) -> "AssemblyError":
        """The same error with a sentence appended (e.g. the brief fields to change): a
        message, or its English and Chinese texts."""
        hinted = Msg(N_("{message} {hint}"), message=self.message, hint=message(en, zh))
        return _restore(type(self), hinted, {**self.__dict__, "message": hinted})


@dataclass(frozen=True)
class Joint:
    """A kinematic pair between an already-known link ``link_a`` and a group's ``link_b``.

    kind "R": revolute at point ``point``; kind "P": prismatic, the slider reference
    point ``point`` moving along a guide whose direction is the angle of link
    ``guide_link`` (or the fixed ``guide_angle`` [rad]).
    """

    kind: str
    point: str
    link_a: str
    link_b: str
    guide_link: str | None = None
    guide_angle: float | None = None

    @property
    def name(self) -> str:
        """Course symbol of the reaction: force of link a on link b, F_R{a}{b}."""
        return f"R{self.link_a}{self.link_b}"


@dataclass
class Motion:
    """Motion of every named point, link and slider over the crank-angle array."""

    crank_angle: np.ndarray
    points: dict[str, PointMotion] = field(default_factory=dict)
    links: dict[str, AngleMotion] = field(default_factory=dict)
    slides: dict[str, SlideMotion] = field(default_factory=dict)


class Group(Protocol):
    name: str
    kind: str
    links: tuple[str, ...]
    driver: str | None

    @property
    def outer(self) -> tuple[str, ...]:
        """Points of earlier groups or the frame that this group attaches to."""
    @property
    def produced(self) -> dict[str, str]:
        """Points this group adds, each with the link that carries it."""
    def joints(self, owner: dict[str, str]) -> tuple[Joint, ...]:
        """The group's joints, given the carrying link of every known point."""
    def solve(self, m: Motion) -> None:
        """Add the group's links, sliders and points to ``m``."""


class _GroupGeometry:
    """What every group type provides besides ``solve`` (see each class for its own):

    - ``residual(points, motion, n)``: its closure equations' violations [m] (arrays);
    - ``members()``: the points each of its links carries and its sliders, for drawings;
    - ``quality(motion)``: its transmission or pressure angle, or None;
    - ``velocity_polygon(builder, motion)`` / ``acceleration_polygon(builder, motion)``:
      its vectors of the relative-motion method (:mod:`.polygons`);
    - ``force_polygon(...)``: its force polygon (known loads, then the reactions that
      close it)."""

    def members(self) -> tuple[tuple, tuple]:
        return (), ()

    def quality(self, m: "Motion"):
        return None

    def velocity_polygon(self, b: "poly.Builder", m: "Motion") -> None:
        self._kinematic(b, m)

    def acceleration_polygon(self, b: "poly.Builder", m: "Motion") -> None:
        self._kinematic(b, m)

    def force_polygon(self, joints: dict, loads: dict, reactions: dict, moments: dict,
                      position: str) -> "poly.Polygon":
        return poly.force_polygon(self, joints, loads, reactions, moments, position)

    @staticmethod
    def _rotate(b: "poly.Builder", m: "Motion", tail: str, head: str, link: str,
                head_name: str | None = None) -> list[str]:
        """Vectors of ``head`` relative to ``tail`` on ``link`` (both mechanism points)."""
        i = b.i
        r = m.points[head].pos[i] - m.points[tail].pos[i]
        return b.rotation(b.img(tail), head_name or b.img(head), m.links[link], r, link)

    @staticmethod
    def _symbol(b: "poly.Builder") -> str:
        return "v" if b.prime == "" else "a"


def _const_angle(angle: float, n: int) -> AngleMotion:
    zero = kin.constant(0.0, n)
    return AngleMotion(kin.constant(float(angle), n), zero, zero)


@dataclass(frozen=True)
class Crank(_GroupGeometry):
    """Driving link ``link`` turning about ``pivot`` at constant ``omega`` [rad/s]; tip ``tip``."""

    name: str
    link: str
    pivot: str
    tip: str
    length: float
    omega: float
    kind: str = "crank"

    @property
    def links(self): return (self.link,)

    @property
    def driver(self): return self.link

    @property
    def outer(self): return (self.pivot,)

    @property
    def produced(self): return {self.tip: self.link}

    def joints(self, owner):
        return (Joint("R", self.pivot, owner[self.pivot], self.link),)

    def solve(self, m):
        m.links[self.link], m.points[self.tip] = kin.crank(
            m.points[self.pivot], self.length, m.crank_angle, self.omega)

    def residual(self, P, m, n=None):
        return [np.abs(P[self.tip] - P[self.pivot]) - self.length]

    def members(self):
        return ((self.link, (self.pivot, self.tip)),), ()

    def _kinematic(self, b, m):
        """v_A = v_O + v_AO (v_AO = iω·OA ⊥ OA); a_A = a_O + a^n_AO (+ a^t_AO when α ≠ 0)."""
        x = self._symbol(b)
        b.put(b.img(self.tip), b.value(m.points[self.tip]))
        rot = self._rotate(b, m, self.pivot, self.tip, self.link)
        b.equation(f"{x}_{self.tip} = {x}_{self.pivot} + {x}_{self.tip}{self.pivot}",
                   b.path_to(b.img(self.tip)), b.path_to(b.img(self.pivot)) + rot)


@dataclass(frozen=True)
class RRR(_GroupGeometry):
    """RRR dyad: ``link1`` from B to C (l1), ``link2`` from D to C (l2)."""

    name: str
    link1: str
    link2: str
    b: str
    d: str
    c: str
    l1: float
    l2: float
    branch: int
    kind: str = "RRR"
    driver = None

    @property
    def links(self): return (self.link1, self.link2)

    @property
    def outer(self): return (self.b, self.d)

    @property
    def produced(self): return {self.c: self.link1}

    def joints(self, owner):
        return (Joint("R", self.b, owner[self.b], self.link1),
                Joint("R", self.c, self.link1, self.link2),
                Joint("R", self.d, owner[self.d], self.link2))

    def solve(self, m):
        l1, l2, c = kin.rrr(m.points[self.b], m.points[self.d], self.l1, self.l2, self.branch)
        m.links[self.link1], m.links[self.link2], m.points[self.c] = l1, l2, c

    def residual(self, P, m, n=None):
        return [np.abs(P[self.c] - P[self.b]) - self.l1, np.abs(P[self.c] - P[self.d]) - self.l2]

    def members(self):
        return ((self.link1, (self.b, self.c)), (self.link2, (self.d, self.c))), ()

    def quality(self, m):
        """Transmission angle γ at C: the acute angle between the two links."""
        u1 = np.exp(1j * m.links[self.link1].angle)
        u2 = np.exp(1j * m.links[self.link2].angle)
        delta = np.abs(np.angle(u1 * np.conj(u2)))
        return "transmission", self.c, np.minimum(delta, np.pi - delta)

    def _kinematic(self, b, m):
        """v_C = v_B + v_CB = v_D + v_CD (each relative vector ⊥ its link); for
        accelerations each relative term is a normal plus a tangential component."""
        x = self._symbol(b)
        c = b.put(b.img(self.c), b.value(m.points[self.c]))
        r1 = self._rotate(b, m, self.b, self.c, self.link1)
        r2 = self._rotate(b, m, self.d, self.c, self.link2)
        b.equation(f"{x}_{self.c} = {x}_{self.b} + {x}_{self.c}{self.b} = "
                   f"{x}_{self.d} + {x}_{self.c}{self.d}",
                   b.path_to(b.img(self.b)) + r1, b.path_to(b.img(self.d)) + r2)
        b.path_to(c)


@dataclass(frozen=True)
class RRP(_GroupGeometry):
    """RRP dyad: rod ``rod`` from B to C, slider ``slider`` at C on a frame guide."""

    name: str
    rod: str
    slider: str
    b: str
    c: str
    length: float
    guide_point: complex
    guide_angle: float
    branch: int
    frame: str
    kind: str = "RRP"
    driver = None

    @property
    def links(self): return (self.rod, self.slider)

    @property
    def outer(self): return (self.b,)

    @property
    def produced(self): return {self.c: self.slider}

    def joints(self, owner):
        return (Joint("R", self.b, owner[self.b], self.rod),
                Joint("R", self.c, self.rod, self.slider),
                Joint("P", self.c, self.frame, self.slider, guide_angle=self.guide_angle))

    def solve(self, m):
        rod, slide, c = kin.rrp(m.points[self.b], self.length, self.guide_point,
                                self.guide_angle, self.branch)
        m.links[self.rod], m.slides[self.slider], m.points[self.c] = rod, slide, c
        m.links[self.slider] = _const_angle(self.guide_angle, len(m.crank_angle))

    def residual(self, P, m, n=None):
        return [np.abs(P[self.c] - P[self.b]) - self.length,
                (np.exp(-1j * self.guide_angle) * (P[self.c] - self.guide_point)).imag]

    def members(self):
        return ((self.rod, (self.b, self.c)),), \
            ((self.slider, self.c, self.guide_angle, self.guide_point),)

    def quality(self, m):
        """Pressure angle α at C: between the rod and the guide."""
        u = np.exp(1j * m.links[self.rod].angle)
        delta = np.abs(np.angle(u * np.exp(-1j * self.guide_angle)))
        return "pressure", self.c, np.minimum(delta, np.pi - delta)

    def _kinematic(self, b, m):
        """v_C = v_B + v_CB with v_C along the guide and v_CB ⊥ BC (accelerations: a_C =
        a_B + a^n_CB + a^t_CB, a_C along the guide)."""
        x = self._symbol(b)
        c = b.put(b.img(self.c), b.value(m.points[self.c]))
        rot = self._rotate(b, m, self.b, self.c, self.rod)
        b.equation(f"{x}_{self.c} = {x}_{self.b} + {x}_{self.c}{self.b}",
                   b.path_to(c), b.path_to(b.img(self.b)) + rot)


@dataclass(frozen=True)
class RPR(_GroupGeometry):
    """RPR dyad: ``slider`` pinned at A slides on guide bar ``bar`` pinned at ``pivot``."""

    name: str
    slider: str
    bar: str
    a: str
    pivot: str
    branch: int
    offset: float = 0.0
    kind: str = "RPR"
    driver = None

    @property
    def links(self): return (self.slider, self.bar)

    @property
    def outer(self): return (self.a, self.pivot)

    @property
    def produced(self): return {}

    def joints(self, owner):
        return (Joint("R", self.a, owner[self.a], self.slider),
                Joint("P", self.a, self.bar, self.slider, guide_link=self.bar),
                Joint("R", self.pivot, owner[self.pivot], self.bar))

    def solve(self, m):
        bar, slide = kin.rpr(m.points[self.a], m.points[self.pivot], self.branch, self.offset)
        m.links[self.bar] = m.links[self.slider] = bar
        m.slides[self.slider] = slide

    def residual(self, P, m, n=None):
        u = np.exp(1j * m.links[self.bar].angle[:n])
        return [(np.conj(u) * (P[self.a] - P[self.pivot])).imag - self.offset]

    def members(self):
        return ((self.bar, (self.pivot, self.a)),), ((self.slider, self.a, self.bar, None),)

    def _kinematic(self, b, m):
        """The bar's point A4 coinciding with the slider's pin A (A3):
        v_A4 = v_O + v_A4O (⊥ the bar) = v_A3 + v_A4A3 (along the bar);
        a_A4 = a_O + a^n_A4O + a^t_A4O = a_A3 + a^k_A4A3 + a^r_A4A3 with the Coriolis
        term a^k = 2ω·v_A4A3 turned 90° in the sense of ω."""
        i, x, A = b.i, self._symbol(b), self.a
        r = m.points[A].pos[i] - m.points[self.pivot].pos[i]
        u = np.exp(1j * m.links[self.bar].angle[i])
        bar, slide = m.links[self.bar], m.slides[self.slider]
        w = float(bar.omega[i])
        ds, dds = float(slide.ds[i]), float(slide.dds[i])
        o = b.value(m.points[self.pivot])
        a4 = b.put(f"{A.lower()}{self.bar}{b.prime}",
                   o + (1j * w * r if b.prime == "" else (1j * float(bar.alpha[i]) - w * w) * r))
        rot = self._rotate(b, m, self.pivot, A, self.bar, head_name=a4)
        v_rel = -ds * u                         # v_A4A3: the bar's point relative to the slider
        if b.prime == "":
            right = [b.vec(b.img(A), a4, v_rel, "sliding")]
        else:
            cor = 2j * w * v_rel
            k = b.put(b.fresh("k"), b.points[b.img(A)] + cor)
            right = [b.vec(b.img(A), k, cor, "coriolis"), b.vec(k, a4, -dds * u, "sliding")]
        sub = f"{A}{self.bar}"
        b.equation(f"{x}_{sub} = {x}_{self.pivot} + {x}_{sub}{self.pivot} = "
                   f"{x}_{A}{self.slider} + {x}_{sub}{A}{self.slider}",
                   b.path_to(b.img(self.pivot)) + rot, b.path_to(b.img(A)) + right)
        b.path_to(a4)


@dataclass(frozen=True)
class LinkPoint(_GroupGeometry):
    """A named point fixed on ``link``: ``distance`` [m] from its point ``origin`` at
    ``offset_angle`` [rad] from the link's direction. Adds no joint."""

    name: str
    link: str
    origin: str
    distance: float
    offset_angle: float = 0.0
    kind: str = "point"
    links = ()
    driver = None

    @property
    def outer(self): return (self.origin,)

    @property
    def produced(self): return {self.name: self.link}

    def joints(self, owner):
        return ()

    def solve(self, m):
        m.points[self.name] = kin.point_on_link(
            m.points[self.origin], m.links[self.link], self.distance, self.offset_angle)

    def residual(self, P, m, n=None):
        return [np.abs(P[self.name] - P[self.origin]) - self.distance]

    def members(self):
        return ((self.link, (self.origin, self.name)),), ()

    def _kinematic(self, b, m):
        """By the image of the link: v_X = v_O + v_XO (accelerations: + a^n_XO + a^t_XO)."""
        x = self._symbol(b)
        p = b.put(b.img(self.name), b.value(m.points[self.name]))
        rot = self._rotate(b, m, self.origin, self.name, self.link)
        b.equation(f"{x}_{self.name} = {x}_{self.origin} + {x}_{self.name}{self.origin}",
                   b.path_to(p), b.path_to(b.img(self.origin)) + rot)


class Mechanism:
    """Frame points plus groups in solving order (the crank first)."""

    def __init__(self, frame: str, frame_points: dict[str, complex]):
        self.frame = frame
        self.frame_points = dict(frame_points)
        self.groups: list = []
        self.joints: dict[str, tuple[Joint, ...]] = {}
        self._owner = {p: frame for p in frame_points}

    def add(self, group) -> "Mechanism":
        """Append a group; its outer points must already exist."""
        missing = [p for p in group.outer if p not in self._owner]
        if missing:
            raise ValueError(f"group '{group.name}' needs points {missing} defined before it")
        self.joints[group.name] = group.joints(self._owner)
        self._owner.update(group.produced)
        self.groups.append(group)
        return self

    def solve(self, crank_angle: np.ndarray) -> Motion:
        """Motion of everything for crank angles [rad] (array). Raises AssemblyError."""
        phi = np.atleast_1d(np.asarray(crank_angle, dtype=float))
        m = Motion(phi)
        for name, xy in self.frame_points.items():
            m.points[name] = kin.fixed_point(xy, len(phi))
        for g in self.groups:
            g.solve(m)
            _check_assembled(g, m, g.produced, phi, self)
        return m


def _check_assembled(group, m: Motion, produced: dict[str, str], phi: np.ndarray,
                     mech: "Mechanism | None" = None) -> None:
    arrays = [m.links[link].angle for link in group.links] + [m.points[p].pos for p in produced]
    # A finite sum has no NaN or infinity in it (one pass, no temporary); only a sum that is
    # not finite (a NaN, or an overflow of finite values) is looked at element by element.
    if all(np.isfinite(np.add.reduce(a)) for a in arrays):
        return
    bad = np.zeros(len(phi), dtype=bool)
    for a in arrays:
        bad |= ~np.isfinite(a)
    if bad.any():
        first = float(np.degrees(phi[bad][0]) % 360.0)
        count = int(bad.sum())
        found = None if mech is None else _diagnose(group, m, bad, mech)
        if found is None:
            raise AssemblyError(group.name, group.kind, first, count)
        code, reason, numbers = found
        raise AssemblyError(group.name, group.kind, first, count, code=code, reason=reason,
                            numbers=numbers)


def _mm(x: float) -> str:
    return f"{x * 1e3:.6g}"


def _diagnose(group, m: Motion, bad: np.ndarray, mech: "Mechanism"):
    """Why ``group`` does not close where ``bad``: (code, message, numbers), the message's
    field ``{where}`` standing for the group and the crank angle, or None for a group of
    another kind."""
    crank = mech.groups[0] if mech.groups and isinstance(mech.groups[0], Crank) else None
    frame = mech.frame_points

    def on_crank(tip: str, fixed: str) -> bool:
        return crank is not None and tip == crank.tip and fixed in frame

    if isinstance(group, RRR):
        for tip, fixed, b, c in ((group.b, group.d, group.l1, group.l2),
                                 (group.d, group.b, group.l2, group.l1)):
            if on_crank(tip, fixed):
                return _grashof(group, crank, fixed, b, c, abs(frame[fixed] - frame[crank.pivot]))
        dist = np.abs(m.points[group.b].pos - m.points[group.d].pos)
        return _rrr_reach(group, dist, bad)
    if isinstance(group, RRP):
        u = np.exp(-1j * group.guide_angle)
        h = (u * (m.points[group.b].pos - group.guide_point)).imag
        if crank is not None and group.b == crank.tip:
            e = float((u * (frame[crank.pivot] - group.guide_point)).imag)
            return _slider_crank(group, crank, e)
        return _rrp_reach(group, np.abs(h), bad)
    if isinstance(group, RPR):
        dist = np.abs(m.points[group.a].pos - m.points[group.pivot].pos)
        if on_crank(group.a, group.pivot):
            d = abs(frame[group.pivot] - frame[crank.pivot])
            return _guide_bar(group, crank, d, float(np.min(dist)))
        return _rpr_reach(group, dist, bad)
    return None


#: the links of a four-bar by their role, as the messages name them
_FOUR = {"crank": pgettext("link", "crank"), "coupler": pgettext("link", "coupler"),
         "rocker": pgettext("link", "rocker"), "frame": pgettext("link", "frame")}


def _grashof(group, crank, fixed: str, b: float, c: float, d: float):
    """The RRR right after the crank, with one end on the frame: a four-bar whose crank
    turns fully iff a + d ≤ b + c and |d − a| ≥ |b − c| (Grashof's rule with the crank or
    the frame shortest)."""
    a = crank.length
    lengths = {"crank": a, "coupler": b, "rocker": c, "frame": d}
    order = sorted(lengths, key=lengths.get)
    s_, l_ = lengths[order[0]], lengths[order[-1]]
    p_, q_ = lengths[order[1]], lengths[order[2]]
    name = f"{crank.pivot}{crank.tip}{group.c}{fixed}"
    rel = ">" if s_ + l_ > p_ + q_ else "≤"
    if s_ + l_ > p_ + q_:
        why = Msg(N_("the Grashof condition fails"))
    else:
        why = Msg(N_("the Grashof sums hold but the shortest link is the {link}, not the crank "
                     "or the frame"), link=_FOUR[order[0]])
    fixes = []
    short1 = a + d - (b + c)           # the folded/extended position: BD = d + a > b + c
    if short1 > _LENGTH_TOL:
        shorter = Msg(N_(" or shorten the crank by {short} mm"), short=_mm(short1)) \
            if short1 < a else ""
        fixes.append(Msg(N_("make coupler + rocker at least a + d = {ad} mm (lengthen them by "
                            "{short} mm in total){crank}"),
                         ad=_mm(a + d), short=_mm(short1), crank=shorter))
    short2 = abs(b - c) - abs(d - a)   # BD = |d − a| < |b − c|
    if short2 > _LENGTH_TOL:
        longer = _FOUR["coupler"] if b > c else _FOUR["rocker"]
        fixes.append(Msg(N_("make |b − c| = {bc} mm at most |d − a| = {da} mm (shorten the "
                            "{longer} by {short} mm, or lengthen the other)"),
                         bc=_mm(abs(b - c)), da=_mm(abs(d - a)), longer=longer, short=_mm(short2)))
    if not fixes:   # a rounding edge: the closure fails by a hair (a change-point linkage)
        fixes.append(Msg(N_("the lengths sit exactly at the limit (a change-point linkage): "
                            "change one link by at least 0.01 mm")))
    reason = Msg(N_("the crank cannot make a full turn (Grashof): four-bar {name} with crank a = "
                    "{a} mm, coupler b = {b} mm, rocker c = {c} mm, frame d = {d} mm: shortest + "
                    "longest = {s} + {l} = {sl} mm {rel} {p} + {q} = {pq} mm (the other two); "
                    "{why}, so {where}. To let the crank turn: {fixes}"),
                 name=name, a=_mm(a), b=_mm(b), c=_mm(c), d=_mm(d), s=_mm(s_), l=_mm(l_),
                 sl=_mm(s_ + l_), rel=rel, p=_mm(p_), q=_mm(q_), pq=_mm(p_ + q_), why=why,
                 fixes=Join(pgettext("separator", "; or "), fixes))
    return "grashof", reason, {"a": a, "b": b, "c": c, "d": d, "s_plus_l": s_ + l_,
                               "p_plus_q": p_ + q_}


#: A length change below this [m] is round-off, never advice.
_LENGTH_TOL = 1e-8


def _slider_crank(group, crank, e: float):
    """The RRP right after the crank: the crank turns fully iff rod ≥ crank + |offset|."""
    a, L = crank.length, group.length
    need = a + abs(e)
    reason = Msg(N_("the crank cannot make a full turn: slider-crank with crank a = {a} mm, offset "
                    "e = {e} mm (pivot {pivot} from the guide) and rod b = {b} mm needs "
                    "b ≥ a + e = {need} mm, so {where}. Lengthen the rod by at least {more} mm (to "
                    "{need} mm), or reduce the crank and the offset by that much together"),
                 a=_mm(a), e=_mm(abs(e)), pivot=crank.pivot, b=_mm(L), need=_mm(need),
                 more=_mm(need - L))
    return "slider_crank", reason, {"a": a, "b": L, "e": abs(e), "needed": need}


def _guide_bar(group, crank, d: float, closest: float):
    """The RPR right after the crank: the slider's offset cannot exceed the crank pin's
    least distance from the bar's pivot, |d − a|."""
    a, off = crank.length, abs(group.offset)
    gap = abs(d - a)
    reason = Msg(N_("guide bar {pivot}{pin}: the slider's path is offset {off} mm from the bar's "
                    "axis, but the crank pin {pin} comes within |d − a| = {gap} mm of the pivot "
                    "{pivot} (crank a = {a} mm, frame d = {d} mm), so {where}. Reduce the offset "
                    "to at most {gap} mm, or make |d − a| ≥ {off} mm"),
                 pivot=group.pivot, pin=group.a, off=_mm(off), gap=_mm(gap), a=_mm(a), d=_mm(d))
    return "guide_bar", reason, {"a": a, "d": d, "offset": off, "closest": closest}


def _rrr_reach(group, dist: np.ndarray, bad: np.ndarray):
    l1, l2 = group.l1, group.l2
    lo, hi = float(np.min(dist)), float(np.max(dist))
    at = float(dist[bad][0])
    fixes = []
    if hi > l1 + l2 + _LENGTH_TOL:
        fixes.append(Msg(N_("make {b}{c} + {d}{c} at least {hi} mm (lengthen them by {more} mm in "
                            "total)"), b=group.b, c=group.c, d=group.d, hi=_mm(hi),
                         more=_mm(hi - l1 - l2)))
    if lo < abs(l1 - l2) - _LENGTH_TOL:
        fixes.append(Msg(N_("make their difference at most {lo} mm (now {diff} mm)"),
                         lo=_mm(lo), diff=_mm(abs(l1 - l2))))
    if not fixes:   # closes by a hair only: round-off at a limit position
        fixes.append(Msg(N_("the lengths sit exactly at the limit: change one link by at least "
                            "0.01 mm")))
    reason = Msg(N_("{where}: links {b}{c} = {l1} mm and {d}{c} = {l2} mm close only while "
                    "|{b}{d}| lies between {diff} and {sum} mm, but it is {at} mm there and ranges "
                    "{lo} … {hi} mm over the angles asked: {fixes}"),
                 b=group.b, c=group.c, d=group.d, l1=_mm(l1), l2=_mm(l2), diff=_mm(abs(l1 - l2)),
                 sum=_mm(l1 + l2), at=_mm(at), lo=_mm(lo), hi=_mm(hi),
                 fixes=Join(pgettext("separator", "; "), fixes))
    return "assembly", reason, {"l1": l1, "l2": l2, "min": lo, "max": hi}


def _rrp_reach(group, h: np.ndarray, bad: np.ndarray):
    L, hi = group.length, float(np.max(h))
    reason = Msg(N_("{where}: the rod {b}{c} = {L} mm cannot reach the guide, from which {b} is "
                    "{at} mm away there (up to {hi} mm over the angles asked): lengthen the rod to "
                    "at least {hi} mm or move the guide closer"),
                 b=group.b, c=group.c, L=_mm(L), at=_mm(float(h[bad][0])), hi=_mm(hi))
    return "assembly", reason, {"length": L, "max": hi}


def _rpr_reach(group, dist: np.ndarray, bad: np.ndarray):
    off, lo = abs(group.offset), float(np.min(dist))
    reason = Msg(N_("{where}: the slider's path is offset {off} mm from the bar's axis, but {a} "
                    "comes within {lo} mm of the pivot {pivot}: reduce the offset to at most "
                    "{lo} mm"), off=_mm(off), a=group.a, lo=_mm(lo), pivot=group.pivot)
    return "assembly", reason, {"offset": off, "min": lo}
