"""The cam stage, shared by every machine with a disc cam, and the two cam-only machines:
``cam`` (synthesis of a disc cam) and ``eccentric_cam`` (analysis of an eccentric disc).

The stage designs the cam on a fine grid, tabulates it at the brief's step, designs the
smallest base circle for the allowed pressure angles and checks the result: pressure angle
per segment, convex radius of curvature against the roller (undercut, pointed profile) and,
for a flat face, convexity. Problems that leave the cam computable but unusable become
:class:`Finding` entries, which the report prints and the command line shows as warnings.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..core import cam as core
from ..pipeline import Stage
from .findings import Finding

GRID_POINTS = 3600


@dataclass(frozen=True)
class SegmentCheck:
    kind: str
    law: str | None
    start: float                 # [rad]
    span: float                  # [rad]
    lift: float                  # signed [m] or [rad]
    impact: str
    max_pressure_angle: float    # [rad]
    at: float                    # cam angle of the maximum [rad]
    limit: float | None          # [rad], None for dwells
    ok: bool


@dataclass(frozen=True)
class CamResult:
    params: object
    base_radius: float               # used [m]
    offset: float                    # signed x of the translating follower's axis [m] (0 otherwise)
    base_radius_designed: bool
    min_base_radius: float | None    # smallest r0 for the limits with this follower [m]
    best_offset: tuple | None        # (r0, e) with the best offset, translating knife/roller [m]
    grid: core.CamProfile
    table: core.CamProfile
    segments: list[SegmentCheck]
    boundaries: list[core.Boundary]
    rho_pitch_min_convex: float      # [m] (inf if none convex)
    rho_actual_min_convex: float     # [m]
    face_extent: tuple | None        # flat face: (min, max) contact position along the face [m]
    warnings: list[Finding]


def design(p) -> CamResult:
    """Run the cam stage for the SI cam parameters ``p`` (brief.cam.CamParams)."""
    prog, fol = p.programme, p.follower
    translating = isinstance(fol, core.TranslatingFollower)
    best = None
    min_r0 = None
    if translating:
        if fol.kind != "flat":
            best = core.min_base_radius_translating(prog, fol, p.alpha_rise, p.alpha_return,
                                                    None, p.rotation)
        # an automatic offset is kept to a whole tenth of a millimetre
        offset = float(np.round(best[1], 4)) if (p.auto_offset and best) else fol.offset
        fol = replace(fol, offset=offset)
        min_r0 = core.min_base_radius_translating(
            prog, fol, p.alpha_rise, p.alpha_return, offset, p.rotation,
            min_curvature=p.min_actual_curvature)[0]
    else:
        offset = 0.0
        if fol.kind != "flat":
            try:
                min_r0 = core.min_base_radius_oscillating(prog, fol, p.alpha_rise, p.alpha_return,
                                                          p.rotation)
            except core.CamDesignError:
                min_r0 = None
        else:
            min_r0 = None
    designed = p.base_radius is None
    if designed:
        if min_r0 is None:
            raise core.CamDesignError("cam.base_radius_mm: 'auto' cannot be met: no base radius keeps "
                                      "the pressure angle within the limits; give a base radius")
        r0 = float(np.ceil(min_r0 * 1e3 - 1e-9) / 1e3)          # whole millimetres, upwards
        if fol.kind == "roller":
            r0 = max(r0, float(np.ceil((fol.roller_radius + p.min_actual_curvature) * 1e3) / 1e3))
    else:
        r0 = p.base_radius
    grid = core.design_cam(prog, fol, r0, p.rotation, GRID_POINTS)
    n_table = int(round(2 * np.pi / p.table_step))
    table = core.design_cam(prog, fol, r0, p.rotation,
                            delta=np.arange(n_table) * (2 * np.pi / n_table))
    impacts = prog.impacts()
    segs = []
    seg_of = grid.motion.segment
    for i, seg in enumerate(prog.segments):
        mask = seg_of == i
        alpha = grid.pressure_angle[mask]
        j = int(np.argmax(alpha))
        limit = None if seg.kind == core.DWELL else (
            p.alpha_rise if seg.kind == core.RISE else p.alpha_return)
        amax = float(alpha[j])
        segs.append(SegmentCheck(seg.kind, seg.law, float(prog.starts[i]), float(seg.span),
                                 float(prog.lifts[i]), impacts[i], amax,
                                 float(grid.delta[mask][j]), limit,
                                 limit is None or amax <= limit + 1e-12))
    convex = grid.rho_pitch > 0
    rho_p = float(np.min(grid.rho_pitch[convex])) if np.any(convex) else float("inf")
    rho_a = float(np.min(grid.rho_actual[convex])) if np.any(convex) else float("inf")
    face = None
    if fol.kind == "flat":
        along = _face_positions(grid, fol)
        face = (float(np.min(along)), float(np.max(along)))
    warnings = _checks(p, fol, r0, segs, rho_p, rho_a, grid, min_r0, best)
    return CamResult(p, r0, offset, designed, min_r0, best, grid, table, segs,
                     prog.boundaries(), rho_p, rho_a, face, warnings)


def _face_positions(prof: core.CamProfile, fol) -> np.ndarray:
    """Contact position along a flat face: from the follower axis (translating, signed x) or
    the distance from the pivot (oscillating)."""
    if "pivot" in prof.extras:
        return np.abs(prof.contact - prof.extras["pivot"])
    return prof.contact.real - fol.offset


def _mm(x: float) -> str:
    return f"{x * 1e3:.2f} mm"


def _checks(p, fol, r0, segs, rho_p, rho_a, grid, min_r0, best) -> list[Finding]:
    """``min_r0``: smallest base radius for the limits (convexity for a flat face) with this
    follower; ``best``: (r0, e) with the best offset (translating knife/roller), or None."""
    out = []
    bad = [s for s in segs if not s.ok]
    if bad:
        worst = max(bad, key=lambda s: s.max_pressure_angle - s.limit)
        which_zh = "推程" if worst.kind == core.RISE else "回程"
        which_en = worst.kind
        fix_zh = f"把基圆半径增大到至少 {_mm(min_r0)}" if min_r0 else "增大基圆半径"
        fix_en = f"increase the base radius to at least {_mm(min_r0)}" if min_r0 else "increase the base radius"
        if best is not None and best[0] < r0:
            side_zh = "右" if best[1] > 0 else "左"
            side_en = "right" if best[1] > 0 else "left"
            fix_zh += f"，或把偏距改为 e = {_mm(abs(best[1]))}（{side_zh}侧，此时最小基圆半径 {_mm(best[0])}）"
            fix_en += (f", or change the offset to e = {_mm(abs(best[1]))} on the {side_en} "
                       f"(then the smallest base radius is {_mm(best[0])})")
        out.append(Finding(
            "pressure_angle",
            f"压力角超限：{which_zh}最大压力角 {np.degrees(worst.max_pressure_angle):.2f}° "
            f"(δ = {np.degrees(worst.at):.1f}°) 大于许用值 {np.degrees(worst.limit):.0f}°；"
            f"基圆半径 r0 = {_mm(r0)} 太小，{fix_zh}。",
            f"pressure angle too large: the {which_en}'s maximum {np.degrees(worst.max_pressure_angle):.2f}° "
            f"(at δ = {np.degrees(worst.at):.1f}°) exceeds the allowed {np.degrees(worst.limit):.0f}°; "
            f"the base radius r0 = {_mm(r0)} is too small: {fix_en}."))
    if fol.kind == "roller" and np.isfinite(rho_p):
        rr = fol.roller_radius
        if rr >= rho_p:
            out.append(Finding(
                "undercut",
                f"运动失真（实际廓线根切/自交）：滚子半径 r_r = {_mm(rr)} 不小于理论廓线外凸部分的"
                f"最小曲率半径 ρmin = {_mm(rho_p)}；减小滚子半径到 {_mm(rho_p - p.min_actual_curvature)} "
                f"以下，或增大基圆半径。",
                f"undercut (the actual profile intersects itself, the follower motion is distorted): "
                f"the roller radius r_r = {_mm(rr)} is not smaller than the smallest convex radius of "
                f"curvature of the pitch curve ρmin = {_mm(rho_p)}; use a roller below "
                f"{_mm(rho_p - p.min_actual_curvature)} or a larger base circle."))
        elif rho_a < p.min_actual_curvature:
            out.append(Finding(
                "pointed",
                f"实际廓线变尖：最小曲率半径 ρa = {_mm(rho_a)} 小于 {_mm(p.min_actual_curvature)}，"
                f"易磨损；减小滚子半径或增大基圆半径。",
                f"pointed profile: the actual profile's smallest radius of curvature ρa = {_mm(rho_a)} "
                f"is below {_mm(p.min_actual_curvature)} and will wear quickly; use a smaller roller "
                "or a larger base circle."))
    if fol.kind == "flat":
        rho_min = float(np.min(grid.rho_actual))
        if rho_min <= 0:
            fix_zh = f"基圆半径至少取 {_mm(min_r0)}" if min_r0 else "增大基圆半径"
            fix_en = f"use a base radius of at least {_mm(min_r0)}" if min_r0 else "increase the base radius"
            out.append(Finding(
                "concave_flat",
                f"平底从动件要求凸轮廓线处处外凸，但最小曲率半径为 {_mm(rho_min)}（廓线内凹，运动失真）；{fix_zh}。",
                f"a flat-faced follower needs a convex cam everywhere, but the smallest radius of "
                f"curvature is {_mm(rho_min)} (concave: the motion is distorted); {fix_en}."))
    return out


def cam_stage() -> Stage:
    """The cam stage of any machine whose parameters carry ``.cam`` (brief.cam.CamParams)."""
    return Stage("cam", "凸轮机构设计 / cam design", lambda r: design(r["params"].cam))


# --------------------------------------------------------------------------- eccentric disc


@dataclass(frozen=True)
class DiscResult:
    params: object
    grid_delta: np.ndarray
    motions: list[core.DiscMotion]          # fine grid, one per follower
    table_delta: np.ndarray
    tables: list[core.DiscMotion]
    queries: list[core.DiscMotion]
    warnings: list[Finding]


def analyse_disc(p) -> DiscResult:
    grid = np.arange(GRID_POINTS + 1) * (2 * np.pi / GRID_POINTS)
    n_table = int(round(2 * np.pi / p.table_step))
    tdelta = np.arange(n_table + 1) * (2 * np.pi / n_table)
    motions, tables, queries = [], [], []
    for _, fol in p.followers:
        motions.append(core.eccentric_disc(grid, p.radius, p.eccentricity, fol, p.rotation))
        tables.append(core.eccentric_disc(tdelta, p.radius, p.eccentricity, fol, p.rotation))
        queries.append(core.eccentric_disc(p.query_angles, p.radius, p.eccentricity, fol, p.rotation))
    return DiscResult(p, grid, motions, tdelta, tables, queries, [])


CAM_STAGES = [cam_stage()]
DISC_STAGES = [Stage("disc", "偏心圆盘凸轮分析 / eccentric disc analysis",
                     lambda r: analyse_disc(r["params"]))]


def _c(z):
    return [float(np.real(z)), float(np.imag(z))]


def cam_document(c: CamResult) -> dict:
    """The cam stage in ``results.json`` (SI: m, rad; derivatives per radian of cam angle)."""
    t = c.table
    return {
        "base_radius": c.base_radius, "base_radius_designed": c.base_radius_designed,
        "min_base_radius": c.min_base_radius,
        "best_offset": None if c.best_offset is None else {"base_radius": c.best_offset[0],
                                                             "offset": c.best_offset[1]},
        "offset": c.offset, "roller_radius": c.grid.roller_radius, "rotation": c.grid.rotation,
        "initial": c.grid.initial_angle,
        "segments": [s.__dict__ for s in c.segments],
        "boundaries": [b.__dict__ for b in c.boundaries],
        "rho_pitch_min_convex": c.rho_pitch_min_convex,
        "rho_actual_min_convex": c.rho_actual_min_convex,
        "face_extent": c.face_extent,
        "warnings": [w.code for w in c.warnings],
        "table": {"delta": t.delta, "s": t.motion.s, "ds": t.motion.ds, "d2s": t.motion.d2s,
                  "d3s": t.motion.d3s, "pitch": t.pitch, "actual": t.actual,
                  "pressure_angle": t.pressure_angle, "rho_pitch": t.rho_pitch,
                  "rho_actual": t.rho_actual},
    }


def cam_results_document(r: dict) -> dict:
    return {"schema": "mechdesign.results/1", "machine": "cam",
            "units": "SI: m, rad; derivatives per radian of cam angle; complex points as [x, y]",
            "cam": cam_document(r["cam"])}


def disc_results_document(r: dict) -> dict:
    d = r["disc"]
    return {"schema": "mechdesign.results/1", "machine": "eccentric_cam",
            "units": "SI: m, rad", "radius": d.params.radius, "eccentricity": d.params.eccentricity,
            "followers": [{"label": label, "kind": f.kind, "offset": f.offset,
                           "roller_radius": f.roller_radius, "y_min": m.y_min, "y_max": m.y_max,
                           "stroke": m.stroke, "table": {"delta": t.delta, "s": t.s,
                                                         "pressure_angle": t.pressure_angle},
                           "queries": {"delta": q.delta, "s": q.s, "pressure_angle": q.pressure_angle}}
                          for (label, f), m, t, q in zip(d.params.followers, d.motions, d.tables,
                                                         d.queries)]}
