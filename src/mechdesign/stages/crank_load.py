"""The crank's load on the shaft that carries it: the frame reaction on the crank F_R12
(the force the shaft's bearings, through the shaft, exert on the crank; the crank presses
the shaft with −F_R12: the coupler's force on the crank pin plus the crank's own inertia
and weight), as a function of the crank angle, and its largest magnitude over the cycle,
found exactly.

The kinetostatics gives F_R12 on the crank-angle grid. The resistances are constant in
magnitude on pieces of the cycle whose ends are known exactly (:class:`CycleIntegrals`:
the working stroke's ends, an active window's ends, the zeros of the point's velocity along
its line); on a piece F_R12(φ) is a smooth function that the kinetostatics evaluates at any
φ (the mechanism solved at that angle, each resistance with the piece's magnitude). The
largest |F_R12| is therefore: on every piece, its one-sided values at both ends (the force
jumps there) and each interior local maximum of the samples refined by Brent's bounded
search between the sample's neighbours (``fminbound``, xatol 1e-12 rad) on that smooth
function — the same procedure as the exact extremes of M_b (:meth:`CycleIntegrals.extremes`).
A grid read would miss the peak between samples and could not give its angle.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.extremes import fminbound
from ..core.fields import q
from ..core.kinetostatics import PointLoad, solve_forces

_MERGE = 1e-12


@dataclass(frozen=True)
class CrankLoad:
    """The crank's load on its shaft at the crank angle of its largest magnitude."""

    joint: str = q("", "the frame joint of the crank, the reaction's name (R12: frame 1 on crank 2)")
    phase: float = q("rad", "crank phase φ from position 1 where |F_R12| is largest (exact)")
    Fx: float = q("N", "F_R12 there, x component (frame coordinates)")
    Fy: float = q("N", "F_R12 there, y component")
    F: float = q("N", "|F_R12| there: the radial force the crank puts on the shaft")
    torque: float = q("N·m", "M_b at that crank angle")
    grid_max: float = q("N", "the largest |F_R12| of the kinetostatics' samples")
    life: float = q("N", "cube mean of |F_R12| over the cycle (the bearing life's equivalent "
                         "load of the crank: (mean |F|³)^(1/3) over the uniform samples)")
    others: tuple = q("", "the other parts on the crank's shaft whose loads the brief does not give "
                      "(messages): named in the shaft's design steps", default=())
    count: int = q("1", "identical linkages side by side, in phase, each with its crank on this shaft "
                   "(2: one overhung beyond each bearing); each crank carries 1/count of F, of the "
                   "life load and of the torque", default=1)


def crank_joint(model) -> str:
    """The reaction name of the crank's frame joint (R{frame}{crank})."""
    mech = model.mechanism
    g = mech.groups[0]
    return f"R{mech.frame}{g.link}"


def _loads_on_piece(ci, m, piece: int) -> list[PointLoad]:
    """The resistances over motion ``m`` (all inside piece ``piece`` of ``ci.ends``): each
    the piece's constant magnitude, opposing its point's velocity along its line (the
    velocity's sign is constant on a piece: its zeros are piece ends)."""
    mid = 0.5 * (ci.ends[piece] + ci.ends[piece + 1])
    m_mid = ci.solve(np.array([mid]))
    out = []
    for r, ends, mags in zip(ci.model.resistances, ci._ends, ci._mags):
        j = int(np.clip(np.searchsorted(ends, mid, side="right") - 1, 0, len(mags) - 1))
        v_mid = float(ci._along(r, m_mid)[1][0])
        u = np.exp(1j * r.direction)
        sign = np.sign(v_mid) if v_mid != 0.0 else 0.0
        force = -sign * mags[j] * u * np.ones(len(m.crank_angle))
        out.append(PointLoad(r.link, r.point, force))
    return out


def reaction_at(ci, phase, piece: int, joint: str) -> tuple[np.ndarray, np.ndarray]:
    """(F_R12 complex [N], M_b [N·m]) at ``phase`` (array, rad from position 1) with the
    resistances of ``piece``: the kinetostatics solved at those angles."""
    phase = np.atleast_1d(np.asarray(phase, float))
    m = ci.solve(phase)
    fa = solve_forces(ci.model.mechanism, m, list(ci.model.bodies), _loads_on_piece(ci, m, piece),
                      ci.model.gravity)
    return fa.reactions[joint].force, ci.k.sense * fa.driving_torque


def crank_load(model, k, forces, others: tuple = ()) -> CrankLoad:
    """The largest |F_R12| over the cycle, exactly (see the module's docstring)."""
    from .linkage import CycleIntegrals

    joint = crank_joint(model)
    n = k.grid_size
    grid_f = np.abs(np.asarray(forces.reactions[joint])[:n])
    ci = CycleIntegrals(model, k)
    best = (-1.0, 0.0, 0)
    for i in range(len(ci.ends) - 1):
        a, b = float(ci.ends[i]), float(ci.ends[i + 1])
        inner = ci.grid[(ci.grid > a + _MERGE) & (ci.grid < b - _MERGE)]
        xs = np.concatenate(([a], inner, [b]))
        ys = np.abs(reaction_at(ci, xs, i, joint)[0])
        j0 = int(np.argmax(ys))
        if ys[j0] > best[0]:
            best = (float(ys[j0]), float(xs[j0]), i)
        if len(xs) < 3:
            continue
        for j in np.nonzero((ys[1:-1] >= ys[:-2]) & (ys[1:-1] >= ys[2:]))[0] + 1:
            x, fx = fminbound(lambda p, i=i: -float(np.abs(reaction_at(ci, [p], i, joint)[0][0])),
                              float(xs[j - 1]), float(xs[j + 1]))
            if -fx > best[0]:
                best = (-fx, float(x), i)
    F, phase, piece = best
    R, mb = reaction_at(ci, [phase], piece, joint)
    life = float(np.mean(grid_f ** 3) ** (1 / 3))
    return CrankLoad(joint, phase, float(R[0].real), float(R[0].imag), float(abs(R[0])),
                     float(mb[0]), float(grid_f.max()), life, tuple(others))
