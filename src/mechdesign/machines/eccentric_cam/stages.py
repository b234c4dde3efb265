"""The `eccentric_cam` machine: analysis of an eccentric disc, its self-checks and its results document."""
from __future__ import annotations

from dataclasses import dataclass
import numpy as np
from ...core import cam as core
from ...core.fields import q
from ...pipeline import Stage
from ...i18n import N_
from ...stages.findings import CheckNames, Finding
from ...stages.cam import GRID_POINTS, SelfCheck, VerificationDocument, failed_findings, verification_document
from ...stages import titles


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


DISC_CHECK_NAMES = CheckNames({
    "disc_s": N_("displacement: line–disc intersection vs closed form"),
    "disc_alpha": N_("pressure angle: three-centre theorem vs closed form"),
    "disc_stroke": N_("stroke from the extremes of the displacement"),
    "disc_alpha_max": N_("largest pressure angle: three-centre theorem vs closed form"),
})


DISC_S_LIMIT = 1e-9             # [m]


DISC_ALPHA_LIMIT = np.radians(1e-4)


DISC_FD_STEP = 1e-4             # [rad]


@dataclass(frozen=True)
class DiscVerification:
    checks: tuple[SelfCheck, ...]
    warnings: tuple[Finding, ...] = ()


def disc_geometric(delta, radius: float, eccentricity: float, follower, rotation: int):
    """Height y of the follower point by inversion: the disc held still (centre −iε, as at
    δ = 0) and the follower's line turned by −σδ; the follower point is where that line leaves
    the disc circle (radius R + r_r for a roller: the circle its centre rolls on) on the
    follower's side, the root of |P + t·u − C|² = ρ². A flat face rests on the circle's
    highest point. Returns y [m]."""
    sigma = 1 if rotation > 0 else -1
    d = np.asarray(delta, dtype=float)
    turn = np.exp(-1j * sigma * d)
    C = -1j * eccentricity
    if follower.kind == "flat":
        return np.imag(C / turn) + radius
    rho = radius + (follower.roller_radius if follower.kind == "roller" else 0.0)
    P0, u = follower.offset * turn, 1j * turn          # the line x = e of the frame
    w = P0 - C
    b = np.real(np.conj(u) * w)
    q = np.abs(w) ** 2 - rho ** 2
    return -b + np.sqrt(b * b - q)                      # t = y, the upper crossing


def _vertex(values, k: int) -> float:
    """The extreme of the parabola through the periodic samples k − 1, k, k + 1."""
    n = len(values)
    a, b, c = values[(k - 1) % n], values[k], values[(k + 1) % n]
    den = a - 2 * b + c
    return float(b - (c - a) ** 2 / (8 * den)) if den != 0 else float(b)


def verify_disc(d: DiscResult) -> DiscVerification:
    """Each follower's displacement from the line–circle intersection (inversion), its
    pressure angle from the three-centre theorem (the normal passes through the relative
    pole P of cam and follower, x_P = σ·dy/dδ by central differences of the geometric y),
    the stroke from the geometric extremes, and the same at the brief's query angles."""
    p = d.params
    sigma = 1 if p.rotation > 0 else -1
    checks = []
    h = DISC_FD_STEP

    def geo(delta, fol):
        y = disc_geometric(delta, p.radius, p.eccentricity, fol, p.rotation)
        if fol.kind == "flat":
            return y, np.zeros_like(y)
        dy = (disc_geometric(delta + h, p.radius, p.eccentricity, fol, p.rotation)
              - disc_geometric(delta - h, p.radius, p.eccentricity, fol, p.rotation)) / (2 * h)
        x_pole = sigma * dy
        return y, np.arctan2(np.abs(x_pole - fol.offset), y)

    tops = []          # the largest pressure angles' checks, after the others (session 50)
    for (label, fol), mo, qy in zip(p.followers, d.motions, d.queries):
        # the fine grid and the brief's query angles together
        delta = np.concatenate([d.grid_delta, qy.delta])
        y, alpha = geo(delta, fol)
        # extremes over the periodic grid, refined by the parabola through the three points
        # about the grid extreme
        yy = y[:len(d.grid_delta) - 1]
        y_min, y_max = (_vertex(yy, int(np.argmin(yy))), _vertex(yy, int(np.argmax(yy))))
        s_ref = np.concatenate([mo.s, qy.s])
        a_ref = np.concatenate([mo.pressure_angle, qy.pressure_angle])
        checks.append(SelfCheck("disc_s", float(np.max(np.abs((y - y_min) - s_ref))), DISC_S_LIMIT,
                                detail={"label": label, "queries": len(qy.delta)}))
        checks.append(SelfCheck("disc_alpha", float(np.max(np.abs(alpha - a_ref))),
                                DISC_ALPHA_LIMIT, detail={"label": label, "queries": len(qy.delta)}))
        checks.append(SelfCheck("disc_stroke", abs((y_max - y_min) - mo.stroke), DISC_S_LIMIT,
                                reference=mo.stroke, detail={"label": label, "stroke": y_max - y_min}))
        # the largest pressure angle: the three-centre angles' largest over the grid, refined
        # by the parabola through the three points about it, against the closed form
        aa = alpha[:len(d.grid_delta) - 1]
        a_top = _vertex(aa, int(np.argmax(aa)))
        tops.append(SelfCheck("disc_alpha_max", abs(a_top - mo.alpha_max), DISC_ALPHA_LIMIT,
                              reference=mo.alpha_max, detail={"label": label, "top": float(a_top)}))
    checks += tops
    return DiscVerification(tuple(checks), tuple(failed_findings(checks, DISC_CHECK_NAMES)))


DISC_STAGES = [Stage("disc", titles.pgettext("stage", "eccentric disc analysis"),
                     lambda r: analyse_disc(r["params"])),
               Stage("disc_verification", titles.pgettext("stage: self-checks", "verification"),
                     lambda r: verify_disc(r["disc"]))]


DISC_UNITS = "SI: m, rad"


@dataclass(frozen=True)
class DiscTable:
    """A follower's motion at a set of cam angles."""

    delta: np.ndarray = q("rad", "cam angle δ")
    s: np.ndarray = q("m", "displacement from the lowest position")
    pressure_angle: np.ndarray = q("rad", "pressure angle α")


@dataclass(frozen=True)
class DiscFollower:
    """One follower on the eccentric disc."""

    label: str = q("", "the follower's label in the brief")
    kind: str = q("", "'knife' | 'roller' | 'flat'")
    offset: float = q("m", "signed x of the follower's axis (+ right of the disc's pivot)")
    roller_radius: float = q("m", "roller radius r_r (0 without a roller)")
    y_min: float = q("m", "lowest height of the follower point")
    y_max: float = q("m", "highest height of the follower point")
    stroke: float = q("m", "stroke h = y_max − y_min")
    max_pressure_angle: float = q("rad", "largest pressure angle over the turn, exact: "
                                  "sin α_max = (|e| + ε)/(R + r_r); 0 for a flat face")
    table: DiscTable = q("", "at the brief's table step, 0 … 360° inclusive")
    queries: DiscTable = q("", "at the brief's query angles")


@dataclass(frozen=True)
class EccentricCamResults:
    """Eccentric disc cam (偏心圆盘凸轮): a circular disc of radius R turning about a pivot
    at eccentricity ε from its centre, analysed for one or more translating followers.
    Frame: the disc's pivot at the origin, the followers above it; at δ = 0 the disc's
    centre lies at (0, −ε)."""

    schema: str = q("", "'mechdesign.results/2'")
    machine: str = q("", "'eccentric_cam'")
    units: str = q("", "reminder of the unit system")
    radius: float = q("m", "disc radius R")
    eccentricity: float = q("m", "eccentricity ε")
    followers: tuple[DiscFollower, ...] = q("", "one per follower of the brief")
    verification: VerificationDocument | None = q("", "self-checks")


def disc_results_document(r: dict) -> EccentricCamResults:
    from ...results import SCHEMA

    d = r["disc"]
    return EccentricCamResults(
        schema=SCHEMA, machine="eccentric_cam", units=DISC_UNITS, radius=d.params.radius,
        eccentricity=d.params.eccentricity,
        followers=tuple(
            DiscFollower(label, f.kind, f.offset, f.roller_radius, m.y_min, m.y_max, m.stroke,
                         m.alpha_max, DiscTable(t.delta, t.s, t.pressure_angle),
                         DiscTable(qm.delta, qm.s, qm.pressure_angle))
            for (label, f), m, t, qm in zip(d.params.followers, d.motions, d.tables, d.queries)),
        verification=(None if r.get("disc_verification") is None
                      else verification_document(r["disc_verification"])))
