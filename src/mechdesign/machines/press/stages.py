"""The press (压床) as a linkage model on the one engine, and its stages.

Coordinates: the rocker pivot D at the origin, the crank pivot A at (x1, −y), the ram guide
the vertical line x = x2. Links: 1 crank AB, 2 coupler BC, 3 rocker DE (C on it), 4 rod EF,
5 ram (slider F, below E), 6 frame. The ram presses on its downward stroke; the pressing
force Q_max acts upwards over the last part of that stroke.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core.fields import q
from ...core.kinetostatics import Body
from ...core.mechanism import RRP, RRR, AssemblyError, Crank, LinkPoint, Mechanism
from ...pipeline import Stage
from ...stages import guide_bar
from ...stages import linkage as lk
from ...stages.cam import CamDocument
from ...stages.drive import DriveDocument, drive_document
from ...stages.flywheel import Flywheel, brief_flywheel
from ...stages.gear import GearDocument
from .brief import PressParams
from ...i18n import N_
from ...stages import titles
from ...stages.findings import Msg, en_zh, zh_en

FRAME = "6"
DOWN = -np.pi / 2


@dataclass(frozen=True)
class PressSynthesis:
    """Stage 连杆机构设计: the six-bar's dimensions from the course data, in closed form."""

    rocker: float = q("m", "L_DE = H / (2 sin((ψ3″ − ψ3′)/2))")
    rocker_CD: float = q("m", "L_CD = L_DE / (1 + CE/CD)")
    rocker_CE: float = q("m", "L_CE = L_DE − L_CD")
    rod: float = q("m", "L_EF = (EF/DE) L_DE")
    crank: float = q("m", "L_AB = (AC″ − AC′)/2 (absolute value)")
    coupler: float = q("m", "L_BC = (AC′ + AC″)/2")
    frame: float = q("m", "L_AD = √(x1² + y²)")
    coupler_com: float = q("m", "L_BS2")
    rocker_com: float = q("m", "L_DS3")
    C_upper: complex = q("m", "C′, C at the rocker's upper extreme, [x, y] from D")
    C_lower: complex = q("m", "C″, at the lower extreme")
    AC_upper: float = q("m", "|AC′|")
    AC_lower: float = q("m", "|AC″|")
    extreme_angle: float = q("rad", "θ = ∠C′AC″, the crank's extreme-position angle")
    time_ratio: float = q("1", "K = (180° + θ)/(180° − θ)")
    sagitta_guide: float = q("m", "x of the mid-point of the sagitta of E's arc, L_DE(1 + cos(Δψ/2))/2")


def synthesize(p: PressParams) -> PressSynthesis:
    """The course's graphical construction written analytically: the rocker from the stroke
    (E′E″ ∥ guide, so H = E′E″ = 2 L_DE sin(Δψ/2)), C′ and C″ on it, and the crank-rocker
    from the crank pivot's distances to C′ and C″ (crank and coupler collinear at the
    rocker's extremes)."""
    dpsi = p.psi_lower - p.psi_upper
    de = p.stroke / (2.0 * np.sin(dpsi / 2.0))
    cd = de / (1.0 + p.ratio_CE_CD)
    a = complex(p.x1, -p.y)
    cu = cd * complex(np.sin(p.psi_upper), np.cos(p.psi_upper))
    cl = cd * complex(np.sin(p.psi_lower), np.cos(p.psi_lower))
    l_u, l_l = abs(cu - a), abs(cl - a)
    bc = (l_u + l_l) / 2.0
    theta = abs(float(np.angle((cu - a) / (cl - a))))
    return PressSynthesis(
        rocker=de, rocker_CD=cd, rocker_CE=de - cd, rod=p.ratio_EF_DE * de,
        crank=abs(l_l - l_u) / 2.0, coupler=bc, frame=abs(a),
        coupler_com=p.ratio_BS2_BC * bc, rocker_com=p.ratio_DS3_DE * de,
        C_upper=cu, C_lower=cl, AC_upper=l_u, AC_lower=l_l, extreme_angle=theta,
        time_ratio=(np.pi + theta) / (np.pi - theta),
        sagitta_guide=de * (1.0 + np.cos(dpsi / 2.0)) / 2.0)


def problems(p: PressParams, s: PressSynthesis) -> list[tuple[str, float, str, str]]:
    """(field, value, en, zh) for data that cannot make the press: no crank (Grashof), or
    a rod EF that cannot reach the guide over the rocker's swing."""
    out = []
    a, b, c, d = s.crank, s.coupler, s.rocker_CD, s.frame
    mm = 1e3
    if a <= 1e-9 * max(b, c, d):
        out.append(("linkage.pivot_y_mm", p.y * mm, *en_zh(
            N_("A (x1 = {x1:g}, y = {y:g} mm) is equally far from C′ and C″ (on the horizontal "
               "through D): the crank length (AC″ − AC′)/2 is zero; put A above or below D"),
            x1=p.x1 * mm, y=p.y * mm)))
    elif not (a < min(b, c, d) and a + max(b, c, d) <= sum((b, c, d)) - max(b, c, d) + 1e-12):
        out.append(("linkage.pivot_x1_mm", p.x1 * mm, *en_zh(
            N_("with A at x1 = {x1:g}, y = {y:g} mm the four-bar ABCD (a = {a:.4g}, b = {b:.4g}, "
               "c = {c:.4g}, d = {d:.4g} mm) is no crank-rocker: the crank must be the shortest "
               "link and a + l_max ≤ the sum of the other two (Grashof); move A (x1, y)"),
            x1=p.x1 * mm, y=p.y * mm, a=a * mm, b=b * mm, c=c * mm, d=d * mm)))
    reach = max(abs(s.rocker * np.sin(p.psi_upper) - p.x2), abs(s.rocker - p.x2))
    if reach >= s.rod:
        out.append(("linkage.ratio_EF_DE", p.ratio_EF_DE, *en_zh(
            N_("the rod EF = {rod:.4g} mm cannot reach the guide x2 = {x2:g} mm from E over the "
               "rocker's swing (needs more than {reach:.4g} mm): raise EF/DE above {ratio:.4g} or "
               "move the guide towards {sagitta:.4g} mm (linkage.guide_x2_mm)"),
            rod=s.rod * mm, x2=p.x2 * mm, reach=reach * mm, ratio=reach / s.rocker,
            sagitta=s.sagitta_guide * mm)))
    return out


def checks(p: PressParams, keep: dict | None = None) -> list:
    """The run's feasibility checks, each at its brief field (zh/en); the synthesis is kept
    for the stage."""
    from ...brief.loader import BriefProblem

    s = synthesize(p)
    if keep is not None:
        keep["synthesis"] = s
    return [BriefProblem(field, "", en, zh) for field, _, en, zh in problems(p, s)]


def build_mechanism(s: PressSynthesis, p: PressParams, rrr_branch: int = 1,
                    rrp_branch: int = 1) -> Mechanism:
    m = Mechanism(FRAME, {"D": 0j, "A": complex(p.x1, -p.y)})
    m.add(Crank("crank AB", "1", "A", "B", s.crank, p.crank_omega))
    m.add(RRR("coupler–rocker (RRR)", "2", "3", "B", "D", "C", s.coupler, s.rocker_CD, rrr_branch))
    m.add(LinkPoint("S2", "2", "B", s.coupler_com))
    m.add(LinkPoint("E", "3", "D", s.rocker))
    m.add(LinkPoint("S3", "3", "D", s.rocker_com))
    m.add(RRP("rod–ram (RRP)", "4", "5", "E", "F", s.rod, complex(p.x2, 0.0), np.pi / 2,
              rrp_branch, frame=FRAME))
    return m


def _extended_crank_angle(s: PressSynthesis, p: PressParams) -> tuple[float, complex]:
    """The crank angle where crank and coupler are stretched out, and the C found there."""
    far = s.C_lower if s.AC_lower >= s.AC_upper else s.C_upper
    a = complex(p.x1, -p.y)
    return float(np.angle(far - a)), far


def mechanism(s: PressSynthesis, p: PressParams) -> Mechanism:
    """The assembly branches that put C at the synthesis's C′/C″ and F below E."""
    angle, far = _extended_crank_angle(s, p)
    for rb in (1, -1):
        for pb in (1, -1):
            m = build_mechanism(s, p, rb, pb)
            try:
                mo = m.solve(np.array([angle]))
            except AssemblyError:       # the other branch of the coupler and rocker
                continue
            c, e, f_ = (mo.points[k].pos[0] for k in "CEF")
            if abs(c - far) < 1e-9 * s.coupler and f_.imag < e.imag:
                return m
    raise AssertionError("no assembly branch reproduces the synthesis")   # pragma: no cover


def model(s: PressSynthesis, p: PressParams) -> lk.LinkageModel:
    """Output: the ram F measured downwards (the working, pressing stroke); resistance:
    Q_max upwards over the last part of the downward stroke; bodies: coupler, rocker, ram."""
    press_from = (1.0 - p.pressing_ratio) * p.stroke
    fields = "linkage.guide_x2_mm, linkage.ratio_EF_DE"
    pivots = "linkage.pivot_x1_mm, linkage.pivot_y_mm"
    return lk.LinkageModel(
        mechanism=mechanism(s, p), crank_omega=p.crank_omega,
        output=lk.Output("point", "F", DOWN, 1),
        bodies=(Body("2", p.m2, "S2", p.J_S2), Body("3", p.m3, "S3", p.J_S3),
                Body("5", p.m5, "F", 0.0)),
        resistances=(lk.Resistance("5", "F", DOWN, p.pressing_force, 0.0,
                                   (press_from, p.stroke), symbol="Q"),),
        grid_points=p.grid_points, position_step=p.position_step, gravity=p.gravity,
        flywheel=brief_flywheel(p),
        pressure_angle_limit=p.pressure_angle_max, transmission_angle_min=p.transmission_angle_min,
        advice={"pressure": Msg(N_("brief fields {fields}"), fields=fields),
                "transmission": Msg(N_("brief fields {fields}"), fields=pivots)},
        names={"1": Msg.pgettext("link", "crank AB"), "2": Msg.pgettext("link", "coupler BC"),
               "3": Msg.pgettext("link", "rocker DE"), "4": Msg.pgettext("link", "rod EF"),
               "5": Msg.pgettext("link: press", "ram")},
        group_labels={"coupler–rocker (RRR)": Msg.pgettext("link", "coupler–rocker (RRR)"),
                      "rod–ram (RRP)": Msg.pgettext("link", "rod–ram (RRP)")})


def _synthesis(r: dict):
    p = r["params"]
    s = r.get("checked", {}).get("synthesis") or synthesize(p)
    return s, model(s, p)


def stages(p: PressParams) -> list[Stage]:
    return [Stage(("synthesis", "model"), titles.pgettext("stage", "linkage synthesis"), _synthesis),
            *lk.linkage_stages(model_key="model", prefix="linkage"),
            *guide_bar.optional_stages(p)]


@dataclass(frozen=True)
class PressResults:
    """Press (压床): a six-bar — crank AB, coupler BC, rocker DE (pivot D, C on it), rod EF,
    ram F on a vertical guide. Frame: D at the origin, A at (x1, −y), the guide x = x2. The
    linkage's output is the ram F measured downwards (the pressing stroke)."""

    schema: str = q("", "'mechdesign.results/2'")
    machine: str = q("", "'press'")
    units: str = q("", "reminder of the unit system")
    synthesis: PressSynthesis = q("", "the six-bar's dimensions")
    linkage: lk.LinkageDocument = q("", "the linkage engine's results")
    flywheel: Flywheel = q("", "the flywheel on the pinion or crank shaft")
    cam: CamDocument | None = q("", "the cam on the crank shaft (oil pump), when the brief has one")
    gear: GearDocument | None = q("", "the gear pair z1/z2, when the brief gives its module")
    drive: DriveDocument | None = q("", "the drive, when the brief has one")


def results_document(r: dict) -> PressResults:
    from ...results import SCHEMA, UNITS_NOTE
    from ...stages.cam import cam_document
    from ...stages.gear import gear_document

    fl = r["linkage_flywheel"]
    return PressResults(
        schema=SCHEMA, machine="press", units=UNITS_NOTE, synthesis=r["synthesis"],
        linkage=lk.linkage_document(r["model"], r["linkage"], r["linkage_forces"], fl,
                                    r["linkage_verification"], r.get("linkage_graphical")),
        flywheel=fl,
        cam=None if r.get("cam") is None else cam_document(r["cam"]),
        gear=None if r.get("gear") is None else gear_document(r["gear"]),
        drive=None if r.get("drive") is None else drive_document(r["drive"]))
