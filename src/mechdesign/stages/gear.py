"""The gear stage (齿轮设计及啮合图): geometry of an external spur pair and its checks.

Findings (computable but poor designs): ``undercut`` (z below z_min without enough
shift), ``pointed`` (tip thickness below 0.25 m), ``contact_ratio`` (ε below 1.2),
``clearance`` (the tips reach the other gear's root).
"""
from __future__ import annotations

from dataclasses import dataclass

from ..core import gears
from ..core.fields import q
from ..pipeline import Stage
from ..i18n import N_
from .findings import Finding, Msg, finding
from . import titles

MIN_CONTACT_RATIO = 1.2      # textbook: [ε] ≥ 1.1–1.4 for general machinery
MIN_TIP_THICKNESS = 0.25     # × m: s_a ≥ (0.25–0.4) m


MM = 1e3
SHEET_TOOTH_POINTS = 48      # samples per fillet and per involute flank of a tooth on the sheet
FIGURE_TOOTH_POINTS = 60     # the same for the whole gears of the report's figure


@dataclass(frozen=True)
class GearDrawing:
    """What the meshing figure and the gear sheet draw, computed by the stage: the pair in
    millimetres (both drawings are made in mm) and its meshing layout."""

    pair: gears.SpurPair         # the pair with every length in [mm] (angles [rad])
    layout: gears.MeshLayout     # mesh_layout of that pair: points and radii [mm]
    teeth: tuple                 # one generated tooth of gear 1 and of gear 2, own frame [mm]
    outlines: tuple              # both gears' closed outlines placed in the layout [mm]
    interference: bool           # B1B2 runs beyond N1N2 (layout.interference)
    action_length: float         # |B1B2| measured on the line of action of the pair [m]


@dataclass(frozen=True)
class GearResult:
    pair: gears.SpurPair
    warnings: tuple[Finding, ...]
    drawing: GearDrawing | None = None     # what the figure and the sheet draw


def gear_drawing(pair: gears.SpurPair) -> GearDrawing:
    """The drawing data of ``pair`` (lengths in metres)."""
    mm = gears.spur_pair(pair.m * MM, pair.g1.z, pair.g2.z, pair.alpha, pair.ha_star,
                         pair.c_star, pair.g1.x, pair.g2.x)
    lay = gears.mesh_layout(mm)
    teeth = tuple(gears.tooth_outline(g, mm.m, mm.alpha, mm.c_star, SHEET_TOOTH_POINTS)
                  for g in (mm.g1, mm.g2))
    return GearDrawing(mm, lay, teeth, lay.outlines(FIGURE_TOOTH_POINTS), lay.interference,
                       float(gears.mesh_layout(pair).action_length))


def gear_findings(g: gears.SpurPair, prefix: str = "gear_pair") -> tuple[Finding, ...]:
    """The pair's findings; ``prefix`` is the brief section the fields to change are in."""
    import math

    out = []
    for name, gd, x_min in (("1", g.g1, g.x_min1), ("2", g.g2, g.x_min2)):
        if gd.x < x_min - 1e-9:
            need = math.ceil(g.z_min - 1e-9)
            # the report's text names no brief field (the terminal shows ``field``) and
            # writes the limits in words: the formulas stand in the report above it
            out.append(finding(
                "undercut",
                N_("gear {name} (z = {z}) is undercut: it has fewer teeth than the least number "
                   "without undercut, {z_min:g}, and its shift x = {x:g} is below the least "
                   "shift {x_min:.3f}; use a positive shift x ≥ {x_min:.3f} or at least {need} teeth."),
                field=f"{prefix}.x{name}", name=name, z=gd.z, z_min=g.z_min, x=gd.x, x_min=x_min,
                need=need))
        if gd.sa < MIN_TIP_THICKNESS * g.m:
            fix, field = ((Msg(N_("reduce its shift")), f"{prefix}.x{name}") if gd.x > 0
                          else (Msg(N_("use more teeth")), f"{prefix}.z{name}"))
            out.append(finding(
                "pointed",
                N_("gear {name} tip thickness s_a = {sa:.2f} mm < 0.25 m (pointed tooth); {fix}."),
                field=field, name=name, sa=gd.sa * 1e3, fix=fix))
    if g.contact_ratio < MIN_CONTACT_RATIO:
        out.append(finding(
            "contact_ratio",
            N_("contact ratio ε = {eps:.3f} < {least}: use more teeth or a smaller working "
               "pressure angle."), eps=g.contact_ratio, least=MIN_CONTACT_RATIO))
    if g.clearance < -1e-12:
        out.append(finding("clearance", N_("negative clearance: the tips touch the other gear's root.")))
    return tuple(out)


def design_gear(gp) -> GearResult:
    pair = gears.spur_pair(gp.m, gp.z1, gp.z2, gp.alpha, gp.ha_star, gp.c_star, gp.x1, gp.x2)
    return GearResult(pair, gear_findings(pair), gear_drawing(pair))


def gear_stage() -> Stage:
    return Stage("gear", titles.pgettext("stage", "gear pair"), lambda r: design_gear(r["params"].gear))


@dataclass(frozen=True)
class GearDocument:
    """The gear stage (齿轮设计): an external involute spur pair, standard or profile-shifted,
    without backlash (孙桓《机械原理》). Gear 1 is the pinion z1."""

    pair: gears.SpurPair = q("", "the pair's geometry")
    warnings: tuple[Finding, ...] = q("",
        "the pair's findings: undercut, pointed tooth, ε, clearance")


def gear_document(g: GearResult) -> GearDocument:
    return GearDocument(g.pair, tuple(g.warnings))
