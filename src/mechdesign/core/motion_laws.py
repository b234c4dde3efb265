"""Dimensionless follower motion laws of a cam (从动件运动规律).

Textbook: 孙桓《机械原理》, chapter "凸轮机构及其设计" (follower motion laws, table of
v_max / a_max and impact types); the modified trapezoid and modified sine laws follow the
standard cam-design literature (Hrones & Nelson; Rothbart, *Cam Design Handbook*).

Every law is written in the normalised variable u = φ/Φ ∈ [0, 1] (cam angle over the
rise angle) as S(u) = s/h ∈ [0, 1], with exact derivatives S', S'', S''' w.r.t. u.
Physical values follow as s = h·S, v = h·ω/Φ·S', a = h·(ω/Φ)²·S'', j = h·(ω/Φ)³·S'''.

Peak coefficients Cv = max|S'|, Ca = max|S''|, Cj = max|S'''| are those of the rise
joined to dwells at both ends (as in the textbook table): a law whose S' (S'') does not
vanish at u = 0 or 1, or that jumps inside, has an infinite acceleration (jerk) there,
so Ca (Cj) is ``math.inf``. Constant velocity: Ca = Cj = inf (rigid impact 刚性冲击);
parabolic and harmonic: Cj = inf (soft impact 柔性冲击). Where S''' is undefined
pointwise (a Dirac spike) the returned S''' is the finite part (0 for those laws).

Modified trapezoid, k = 1/(π+2) (acceleration: sine quarter-waves of period 1/2 on
[0,1/8], [3/8,5/8], [7/8,1] and plateaus ±8πk on [1/8,3/8], [5/8,7/8]); and modified sine,
m = 1/(π+4) (sine quarter-wave on [0,1/8] and [7/8,1], a cosine of period 3/2 between).
The pieces were integrated by hand with S, S' continuous and S(1) = 1, which gives
Cv = 2, Ca = 8π/(π+2) ≈ 4.888, Cj = 32π²/(π+2) ≈ 61.43 and
Cv = 4π/(π+4) ≈ 1.760, Ca = 4π²/(π+4) ≈ 5.528, Cj = 16π³/(π+4) ≈ 69.47.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from .errors import pgettext

PI = math.pi
Quad = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]


@dataclass(frozen=True)
class MotionLaw:
    """One dimensionless motion law; call it with u to get (S, S', S'', S''')."""

    key: str
    name_en: str                          # a msgid (context "motion law"): see :meth:`name`
    latex: tuple[str, str, str]          # S(u), S'(u), S''(u), no $ delimiters
    internal_acceleration_jump: bool      # S'' jumps at an interior u
    breakpoints: tuple[float, ...]        # interior u where the definition changes
    cv: float                             # max |S'|
    ca: float                             # max |S''| (inf for rigid impact)
    cj: float                             # max |S'''| (inf where S'' jumps)
    _func: Callable[[np.ndarray], tuple] = field(repr=False, compare=False)

    def name(self, lang: str) -> str:
        """The law's name in ``lang`` (from the catalogue)."""
        return pgettext("motion law", self.name_en).text(lang)

    @property
    def name_zh(self) -> str:
        """The law's name in Chinese."""
        return self.name("zh")

    def __call__(self, u) -> Quad:
        """S(u), S'(u), S''(u), S'''(u) as float arrays with the shape of ``u`` (u ∈ [0, 1])."""
        u = np.asarray(u, dtype=float)
        return tuple(np.broadcast_to(np.asarray(x, dtype=float), u.shape).copy()
                     for x in self._func(u))


def _pieces(u: np.ndarray, edges: tuple[float, ...], branches: list[Callable]) -> tuple:
    """Evaluate piece i where edges[i-1] < u <= edges[i] (last piece for the rest)."""
    conds = [u <= e for e in edges]
    values = [[np.broadcast_to(np.asarray(x, dtype=float), u.shape) for x in f(u)]
              for f in branches]
    return tuple(np.select(conds, [v[i] for v in values[:-1]], default=values[-1][i])
                 for i in range(4))


def _constant_velocity(u):
    return u, 1.0, 0.0, 0.0


def _parabolic(u):
    return _pieces(u, (0.5,), [
        lambda u: (2 * u**2, 4 * u, 4.0, 0.0),
        lambda u: (1 - 2 * (1 - u)**2, 4 * (1 - u), -4.0, 0.0),
    ])


def _harmonic(u):
    x = PI * u
    return (1 - np.cos(x)) / 2, PI / 2 * np.sin(x), PI**2 / 2 * np.cos(x), -PI**3 / 2 * np.sin(x)


def _cycloidal(u):
    x = 2 * PI * u
    return u - np.sin(x) / (2 * PI), 1 - np.cos(x), 2 * PI * np.sin(x), 4 * PI**2 * np.cos(x)


def _poly345(u):
    return (10 * u**3 - 15 * u**4 + 6 * u**5, 30 * u**2 - 60 * u**3 + 30 * u**4,
            60 * u - 180 * u**2 + 120 * u**3, 60 - 360 * u + 360 * u**2)


def _poly4567(u):
    return (35 * u**4 - 84 * u**5 + 70 * u**6 - 20 * u**7,
            140 * u**3 - 420 * u**4 + 420 * u**5 - 140 * u**6,
            420 * u**2 - 1680 * u**3 + 2100 * u**4 - 840 * u**5,
            840 * u - 5040 * u**2 + 8400 * u**3 - 4200 * u**4)


_K = 1 / (PI + 2)   # modified trapezoid scale


def _mtrap_end(u, offset):   # pieces on [0,1/8] (offset 0) and [7/8,1] (offset π)
    x = 4 * PI * u
    return (_K * (2 * u + offset - np.sin(x) / (2 * PI)), _K * (2 - 2 * np.cos(x)),
            8 * PI * _K * np.sin(x), 32 * PI**2 * _K * np.cos(x))


def _modified_trapezoid(u):
    return _pieces(u, (1 / 8, 3 / 8, 5 / 8, 7 / 8), [
        lambda u: _mtrap_end(u, 0.0),
        lambda u: (_K * (4 * PI * u**2 + (2 - PI) * u + PI / 16 - 1 / (2 * PI)),
                   _K * (8 * PI * u + 2 - PI), 8 * PI * _K, 0.0),
        lambda u: (_K * ((2 + 2 * PI) * u - PI / 2 + np.sin(4 * PI * u) / (2 * PI)),
                   _K * (2 + 2 * PI + 2 * np.cos(4 * PI * u)),
                   -8 * PI * _K * np.sin(4 * PI * u), -32 * PI**2 * _K * np.cos(4 * PI * u)),
        lambda u: (_K * (-4 * PI * u**2 + (7 * PI + 2) * u - 33 * PI / 16 + 1 / (2 * PI)),
                   _K * (-8 * PI * u + 7 * PI + 2), -8 * PI * _K, 0.0),
        lambda u: _mtrap_end(u, PI),
    ])


_M = 1 / (PI + 4)   # modified sine scale


def _msine_end(u, offset):   # pieces on [0,1/8] (offset 0) and [7/8,1] (offset 4)
    x = 4 * PI * u
    return (_M * (PI * u + offset - np.sin(x) / 4), PI * _M * (1 - np.cos(x)),
            4 * PI**2 * _M * np.sin(x), 16 * PI**3 * _M * np.cos(x))


def _msine_mid(u):
    t = 4 * PI * u / 3 - PI / 6
    return (_M * (PI * u + 2 - 9 / 4 * np.cos(t)), PI * _M * (1 + 3 * np.sin(t)),
            4 * PI**2 * _M * np.cos(t), -16 * PI**3 / 3 * _M * np.sin(t))


def _modified_sine(u):
    return _pieces(u, (1 / 8, 7 / 8), [lambda u: _msine_end(u, 0.0), _msine_mid,
                                       lambda u: _msine_end(u, 4.0)])


def _cases(*rows: tuple[str, str]) -> str:
    return r"\begin{cases} " + r" \\ ".join(f"{e}, & {c}" for e, c in rows) + r" \end{cases}"


_H1, _H2 = r"0 \le u \le \frac{1}{2}", r"\frac{1}{2} < u \le 1"
_E = [r"0 \le u \le \frac{1}{8}", r"\frac{1}{8} < u \le \frac{3}{8}",
      r"\frac{3}{8} < u \le \frac{5}{8}", r"\frac{5}{8} < u \le \frac{7}{8}",
      r"\frac{7}{8} < u \le 1"]
_KT, _MT = r"\frac{1}{\pi+2}", r"\frac{1}{\pi+4}"
_T = r"\left(\frac{4\pi u}{3}-\frac{\pi}{6}\right)"
_MS_MID = _E[1].replace(r"\le \frac{3}{8}", r"\le \frac{7}{8}")

_LAWS = [
    MotionLaw("constant_velocity", pgettext("motion law", "constant velocity").msgid,
              ("u", "1", "0"), False, (), 1.0, math.inf, math.inf, _constant_velocity),
    MotionLaw("parabolic",
              pgettext("motion law", "constant acceleration and deceleration (parabolic)").msgid,
              (_cases(("2u^2", _H1), ("1-2(1-u)^2", _H2)),
               _cases(("4u", _H1), ("4(1-u)", _H2)),
               _cases(("4", _H1), ("-4", _H2))),
              True, (0.5,), 2.0, 4.0, math.inf, _parabolic),
    MotionLaw("harmonic", pgettext("motion law", "simple harmonic (cosine acceleration)").msgid,
              (r"\frac{1-\cos \pi u}{2}", r"\frac{\pi}{2}\sin \pi u",
               r"\frac{\pi^2}{2}\cos \pi u"),
              False, (), PI / 2, PI**2 / 2, math.inf, _harmonic),
    MotionLaw("cycloidal", pgettext("motion law", "cycloidal (sine acceleration)").msgid,
              (r"u-\frac{\sin 2\pi u}{2\pi}", r"1-\cos 2\pi u", r"2\pi\sin 2\pi u"),
              False, (), 2.0, 2 * PI, 4 * PI**2, _cycloidal),
    MotionLaw("poly345", pgettext("motion law", "3-4-5 polynomial").msgid,
              ("10u^3-15u^4+6u^5", "30u^2-60u^3+30u^4", "60u-180u^2+120u^3"),
              False, (), 15 / 8, 10 / math.sqrt(3), 60.0, _poly345),
    MotionLaw("poly4567", pgettext("motion law", "4-5-6-7 polynomial").msgid,
              ("35u^4-84u^5+70u^6-20u^7", "140u^3-420u^4+420u^5-140u^6",
               "420u^2-1680u^3+2100u^4-840u^5"),
              False, (), 35 / 16, 84 * math.sqrt(5) / 25, 52.5, _poly4567),
    MotionLaw("modified_trapezoid",
              pgettext("motion law", "modified trapezoidal acceleration").msgid,
              (_cases((_KT + r"\left(2u-\frac{\sin 4\pi u}{2\pi}\right)", _E[0]),
                      (_KT + r"\left(4\pi u^2+(2-\pi)u+\frac{\pi}{16}-\frac{1}{2\pi}\right)", _E[1]),
                      (_KT + r"\left((2+2\pi)u-\frac{\pi}{2}+\frac{\sin 4\pi u}{2\pi}\right)", _E[2]),
                      (_KT + r"\left(-4\pi u^2+(7\pi+2)u-\frac{33\pi}{16}+\frac{1}{2\pi}\right)", _E[3]),
                      (_KT + r"\left(2u+\pi-\frac{\sin 4\pi u}{2\pi}\right)", _E[4])),
               _cases((_KT + r"\left(2-2\cos 4\pi u\right)", _E[0]),
                      (_KT + r"\left(8\pi u+2-\pi\right)", _E[1]),
                      (_KT + r"\left(2+2\pi+2\cos 4\pi u\right)", _E[2]),
                      (_KT + r"\left(7\pi+2-8\pi u\right)", _E[3]),
                      (_KT + r"\left(2-2\cos 4\pi u\right)", _E[4])),
               _cases((r"\frac{8\pi}{\pi+2}\sin 4\pi u", _E[0]), (r"\frac{8\pi}{\pi+2}", _E[1]),
                      (r"-\frac{8\pi}{\pi+2}\sin 4\pi u", _E[2]), (r"-\frac{8\pi}{\pi+2}", _E[3]),
                      (r"\frac{8\pi}{\pi+2}\sin 4\pi u", _E[4]))),
              False, (1 / 8, 3 / 8, 5 / 8, 7 / 8), 2.0, 8 * PI / (PI + 2),
              32 * PI**2 / (PI + 2), _modified_trapezoid),
    MotionLaw("modified_sine", pgettext("motion law", "modified sine acceleration").msgid,
              (_cases((_MT + r"\left(\pi u-\frac{\sin 4\pi u}{4}\right)", _E[0]),
                      (_MT + r"\left(\pi u+2-\frac{9}{4}\cos" + _T + r"\right)", _MS_MID),
                      (_MT + r"\left(\pi u+4-\frac{\sin 4\pi u}{4}\right)", _E[4])),
               _cases((r"\frac{\pi}{\pi+4}\left(1-\cos 4\pi u\right)", _E[0]),
                      (r"\frac{\pi}{\pi+4}\left(1+3\sin" + _T + r"\right)", _MS_MID),
                      (r"\frac{\pi}{\pi+4}\left(1-\cos 4\pi u\right)", _E[4])),
               _cases((r"\frac{4\pi^2}{\pi+4}\sin 4\pi u", _E[0]),
                      (r"\frac{4\pi^2}{\pi+4}\cos" + _T, _MS_MID),
                      (r"\frac{4\pi^2}{\pi+4}\sin 4\pi u", _E[4]))),
              False, (1 / 8, 7 / 8), 4 * PI / (PI + 4), 4 * PI**2 / (PI + 4),
              16 * PI**3 / (PI + 4), _modified_sine),
]

LAWS: dict[str, MotionLaw] = {law.key: law for law in _LAWS}


def law_names() -> list[str]:
    """Keys of :data:`LAWS` in their canonical order."""
    return list(LAWS)
