"""A planar linkage described directly: frame points, a crank and a chain of Assur groups.

The ``linkage:`` section is what ``machine: linkage`` briefs carry, and what machine
briefs embed for a mechanism they do not synthesise (the lock-beam bender's feed).
:func:`linkage_to_model` converts it once to the SI :class:`~mechdesign.stages.linkage.LinkageModel`.

Link directions (for ``point`` groups and the ``angle_deg`` of a point on a link): the
crank points from its pivot to its tip; an RRR group's first link from its first end
to the joint, the second from its second end to the joint; an RRP rod from its end to
the joint, the slider along the guide; an RPR bar from its pivot towards the slider.
"""
from __future__ import annotations

import re
from typing import Annotated, Literal, Optional, Union

from ..lazy import np
from pydantic import BeforeValidator, Field, model_validator

from .common import (MISSING, AnalysisSettings, Listed, Problems, RimHeightToWidth, RimSpecificWeight,
                     StrictModel, invalid, parse_fraction)
from ..i18n import N_

_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_']{0,15}$")


def _name(value):
    if not isinstance(value, str) or not _NAME.match(value):
        raise invalid(N_("a point name is a letter followed by up to 15 letters, digits, _ or ', "
                         "e.g. A, B2, S3"))
    return value


def _link_id(value):
    # Links are numbered as in the course (2 the crank, 3, 4 …): accept 3 or "3".
    if isinstance(value, int) and not isinstance(value, bool):
        value = str(value)
    if not isinstance(value, str) or not re.match(r"^[A-Za-z0-9_]{1,8}$", value):
        raise invalid(N_("a link id is a number or a short name, e.g. 3"))
    return value


#: Link id of the frame (机架); moving links are numbered from 2.
FRAME_LINK = "1"

PointName = Annotated[str, BeforeValidator(_name)]
LinkId = Annotated[str, BeforeValidator(_link_id)]
XY = Annotated[list[Annotated[float, Field(ge=-100000, le=100000)]], Field(min_length=2, max_length=2)]


class CrankSpec(StrictModel):
    """The driving crank (原动件), turning at constant speed."""

    link: LinkId = Field("2", description="Link id of the crank (the course numbers it 2)")
    pivot: PointName = Field(description="Frame point the crank turns about")
    tip: PointName = Field(description="Name of the crank pin (new point)")
    length_mm: float = Field(gt=0, le=10000, description="Crank length [mm]")
    speed_rpm: float = Field(gt=0, le=10000, description="Crank speed [rpm]")
    rotation: Literal["cw", "ccw"] = Field("ccw", description="Sense of rotation: cw (顺时针) or ccw")


class RRRGroup(StrictModel):
    """RRR dyad (RRR 杆组): two links joined at ``joint``, their other ends at known points."""

    type: Literal["RRR"]
    name: str = Field("", max_length=40, description="Name shown in the report (default: the joint)")
    name_en: str = Field("", max_length=40, description=(
        "The name in an English report, when ``name`` is Chinese (default: ``name``)"))
    links: list[LinkId] = Field(min_length=2, max_length=2, description="Link ids [first, second]")
    ends: list[PointName] = Field(min_length=2, max_length=2,
                                  description="Known points the two links are pinned at [B, D]")
    joint: PointName = Field(description="The joint between the two links (new point C)")
    lengths_mm: list[Annotated[float, Field(gt=0, le=100000)]] = Field(min_length=2, max_length=2,
                                    description="Lengths [BC, DC] [mm], each > 0")
    branch: Literal[1, -1] = Field(1, description="+1: C left of B→D (counter-clockwise), −1: right")


class RRPGroup(StrictModel):
    """RRP dyad (RRP 杆组): a rod from a known point to a slider on a fixed guide."""

    type: Literal["RRP"]
    name: str = Field("", max_length=40, description="Name shown in the report (default: the joint)")
    name_en: str = Field("", max_length=40, description=(
        "The name in an English report, when ``name`` is Chinese (default: ``name``)"))
    links: list[LinkId] = Field(min_length=2, max_length=2, description="Link ids [rod, slider]")
    end: PointName = Field(description="Known point the rod is pinned at (B)")
    joint: PointName = Field(description="Slider pin (new point C)")
    length_mm: float = Field(gt=0, le=100000, description="Rod length BC [mm]")
    guide_point_mm: XY = Field(description="A point of the guide line [x, y] [mm]")
    guide_angle_deg: float = Field(0.0, ge=-360, le=360, description="Direction of the guide [°] from +x")
    branch: Literal[1, -1] = Field(1, description=(
        "+1: C ahead of B's foot on the guide (along its direction), −1: behind it"))


class RPRGroup(StrictModel):
    """RPR dyad (RPR 杆组): a slider pinned at a known point slides on a bar turning about a
    known pivot (the guide bar, 导杆)."""

    type: Literal["RPR"]
    name: str = Field("", max_length=40, description="Name shown in the report (default: the slider point)")
    name_en: str = Field("", max_length=40, description=(
        "The name in an English report, when ``name`` is Chinese (default: ``name``)"))
    links: list[LinkId] = Field(min_length=2, max_length=2, description="Link ids [slider, bar]")
    slider_at: PointName = Field(description="Known point the slider is pinned at (A)")
    pivot: PointName = Field(description="Known point the bar turns about")
    offset_mm: float = Field(0.0, ge=-10000, le=10000,
                             description="Offset of the slider's path from the bar's axis [mm]")
    branch: Literal[1, -1] = Field(1, description="+1: bar points from the pivot towards A, −1: away")


class PointOnLink(StrictModel):
    """A named point fixed on a link (an extension, a centre of mass, a load point)."""

    type: Literal["point"]
    name: PointName = Field(description="New point name")
    link: LinkId = Field(description="Link that carries the point")
    origin: PointName = Field(description="A point of that link to measure from")
    distance_mm: float = Field(ge=0, le=100000, description="Distance from the origin [mm]")
    angle_deg: float = Field(0.0, ge=-360, le=360,
                             description="Direction from the link's direction [°], CCW +")


Group = Annotated[Union[RRRGroup, RRPGroup, RPRGroup, PointOnLink], Field(discriminator="type")]


class OutputSpec(StrictModel):
    """The output (执行构件) whose extremes define the strokes and position 1."""

    point: Optional[PointName] = Field(None, description="Output point (a slider pin); or give link")
    link: Optional[LinkId] = Field(None, description="Output link (a rocker); or give point")
    direction_deg: float = Field(0.0, ge=-360, le=360,
                                 description="Direction a point output is measured along [°]")
    working: Literal["increasing", "decreasing"] = Field(
        "increasing", description="The working stroke is the one in which the coordinate increases "
                                  "(or decreases)")

    @model_validator(mode="after")
    def _one(self):
        if (self.point is None) == (self.link is None):
            out = Problems(self)
            out.add(("point",), self.point if self.point is not None else MISSING,
                    N_("give exactly one of point (a slider's point) or link (a rocker's link)"))
            out.raise_any()
        return self


class MassSpec(StrictModel):
    """Mass properties of one link (质量参数); links not listed are massless."""

    link: LinkId = Field(description="Link id")
    mass_kg: float = Field(0.0, ge=0, le=1e6, description="Mass [kg]")
    com: PointName = Field(description="Centre of mass: a point of the link")
    J_kgm2: float = Field(0.0, ge=0, le=1e6, description="Moment of inertia about the centre of mass [kg·m²]")


class ResistanceSpec(StrictModel):
    """Resistance on a point (工作阻力), opposing its motion along a line."""

    link: LinkId = Field(description="Link the force acts on")
    point: PointName = Field(description="Point of application (on that link)")
    direction_deg: float = Field(0.0, ge=-360, le=360, description="Line of action [°] from +x")
    working_N: float = Field(ge=0, le=1e7, description="Resistance in the working stroke [N]")
    return_N: float = Field(0.0, ge=0, le=1e7, description="Resistance in the return stroke [N]")
    active_mm: Optional[list[Annotated[float, Field(ge=-100000, le=100000)]]] = Field(None, min_length=2, max_length=2, description=(
        "Window [from, to] of the output displacement from position 1 where the working resistance "
        "acts [mm] (point output); default: the whole working stroke"))
    active_deg: Optional[list[Annotated[float, Field(ge=-3600, le=3600)]]] = Field(None, min_length=2, max_length=2, description=(
        "The same window for a link output [°]"))


def _fraction(value):
    return parse_fraction(value, N_("write the fluctuation as a number or a fraction such as 1/20"))


class LinkageFlywheelSpec(StrictModel):
    """Flywheel (飞轮) that evens out the crank torque."""

    fluctuation_delta: Annotated[float, BeforeValidator(_fraction)] = Field(
        gt=0, lt=1, description="Allowed coefficient of speed fluctuation [δ], e.g. 0.05 or 1/20")
    speed_ratio: float = Field(1.0, gt=0, le=1000, description=(
        "Flywheel shaft speed / crank speed (1: on the crank shaft)"))
    rim_diameter_mm: Optional[float] = Field(None, gt=0, le=10000, description=(
        "Mean diameter D of a cast rim to size [mm]; without it the flywheel stops at its "
        "moment of inertia J_F"))
    rim_height_to_width: RimHeightToWidth = 1.5
    specific_weight_N_m3: RimSpecificWeight = 7.0e4


class LinkageSection(StrictModel):
    """A planar linkage: frame points, the crank, Assur groups in solving order."""

    frame_points_mm: dict[str, XY] = Field(min_length=1, max_length=40, description="Frame points {name: [x, y]} [mm]")
    crank: CrankSpec
    groups: list[Group] = Field(min_length=1, max_length=40,
                                description="Assur groups and points in solving order")
    output: OutputSpec
    masses: list[MassSpec] = Field(default_factory=list, max_length=40,
                                   description="Mass properties; unlisted links are massless")
    resistances: list[ResistanceSpec] = Field(default_factory=list, max_length=20,
                                              description="Working resistances")
    pressure_angle_max_deg: Optional[float] = Field(None, gt=0, lt=90, description=(
        "Allowed pressure angle of the sliders in the working stroke [°]"))
    transmission_angle_min_deg: Optional[float] = Field(None, gt=0, lt=90, description=(
        "Allowed minimum transmission angle of the RRR groups [°] (textbook: 40)"))
    flywheel: Optional[LinkageFlywheelSpec] = None

    @model_validator(mode="after")
    def _references(self):
        check_references(self)       # every problem at its field, at once
        return self


def _group_io(g) -> tuple[list[str], list[str], list[tuple[str, list[str]]]]:
    """(points needed, points produced, [(link, its points)]) of a group."""
    if g.type == "RRR":
        return (list(g.ends), [g.joint],
                [(g.links[0], [g.ends[0], g.joint]), (g.links[1], [g.ends[1], g.joint])])
    if g.type == "RRP":
        return [g.end], [g.joint], [(g.links[0], [g.end, g.joint]), (g.links[1], [g.joint])]
    if g.type == "RPR":
        return ([g.slider_at, g.pivot], [],
                [(g.links[0], [g.slider_at]), (g.links[1], [g.pivot, g.slider_at])])
    return [g.origin], [g.name], [(g.link, [g.origin, g.name])]


def _display_name(g) -> str:
    """The name a group is shown (and kept) under: its ``name`` or its new point."""
    if g.type == "point":
        return g.name
    return g.name or (g.slider_at if g.type == "RPR" else g.joint)


def check_references(s: LinkageSection, out: Problems | None = None) -> dict[str, list[str]]:
    """Every name used is defined before it, and no name is used twice; returns link → the
    points it carries. Every problem goes to ``out`` (at its field, English and Chinese;
    without ``out`` they are raised at once)."""
    own = out is None
    if own:
        out = Problems(s)
    for name in s.frame_points_mm:
        _name(name)
    known = set(s.frame_points_mm)
    if s.crank.pivot not in known:
        out.add(("crank", "pivot"), s.crank.pivot,
                N_("crank.pivot '{pivot}' is not a frame point; frame points: {names}"),
                pivot=s.crank.pivot, names=Listed(sorted(known)))
    if s.crank.tip in known:
        out.add(("crank", "tip"), s.crank.tip,
                N_("crank.tip '{tip}' is already a point; choose a new name"), tip=s.crank.tip)
    known.add(s.crank.tip)
    members: dict[str, list[str]] = {s.crank.link: [s.crank.pivot, s.crank.tip]}
    shown: dict[str, int] = {}
    for i, g in enumerate(s.groups):
        where = f"groups[{i}] ({g.type})"
        needs, makes, links = _group_io(g)
        label = _display_name(g)
        if g.type != "point" and label:
            if label in shown:
                j = shown[label]
                out.add(("groups", i, "name"), label,
                        N_("{where}: the name '{label}' is already used by groups[{j}]; every "
                           "group needs its own name (it labels its links and forces)"),
                        where=where, label=label, j=j)
            else:
                shown[label] = i
        missing = [p for p in needs if p not in known]
        if missing:
            field = {"RRR": "ends", "RRP": "end", "point": "origin"}.get(g.type)
            if g.type == "RPR":
                field = "slider_at" if g.slider_at in missing else "pivot"
            listed = ", ".join(repr(p) for p in missing)
            out.add(("groups", i, field), ", ".join(missing),
                    N_("{where}: point {listed} is not defined before this group; defined so far: "
                       "{names}"), where=where, listed=listed, names=Listed(sorted(known)))
        for p in makes:
            if p in known:
                out.add(("groups", i, "name" if g.type == "point" else "joint"), p,
                        N_("{where}: point '{p}' is already defined; choose a new name"),
                        where=where, p=p)
        if g.type == "point":
            if g.link not in members:
                out.add(("groups", i, "link"), g.link,
                        N_("{where}: link '{link}' is not defined before this point; links so "
                           "far: {names}"), where=where, link=g.link, names=Listed(members))
            elif g.origin not in members[g.link]:
                out.add(("groups", i, "origin"), g.origin,
                        N_("{where}: origin '{origin}' is not a point of link '{link}' (its "
                           "points: {names})"),
                        where=where, origin=g.origin, link=g.link, names=Listed(members[g.link]))
        else:
            if len(set(g.links)) != 2:
                out.add(("groups", i, "links"), ", ".join(g.links),
                        N_("{where}: the two links need different ids"), where=where)
            for link in g.links:
                if link in members:
                    out.add(("groups", i, "links"), ", ".join(g.links),
                            N_("{where}: link '{link}' is already used; each group adds two new "
                               "links"), where=where, link=link)
                    break
        for link, pts in links:
            lst = members.setdefault(link, [])
            lst.extend(p for p in pts if p not in lst)
        known.update(makes)
    if FRAME_LINK in members:
        where = ("crank", "link")
        if s.crank.link != FRAME_LINK:
            where = next((("groups", i, "links") for i, g in enumerate(s.groups)
                          if g.type != "point" and FRAME_LINK in g.links), where)
        out.add(where, FRAME_LINK,
                N_("link '{FRAME_LINK}' is the frame (the course numbers it 1); number the moving "
                   "links from 2 (the crank) on"), FRAME_LINK=FRAME_LINK)
    o = s.output
    if o.point is not None and o.point not in known:
        out.add(("output", "point"), o.point,
                N_("output.point '{point}' is not a point of the linkage; its points: {names}"),
                point=o.point, names=Listed(sorted(known)))
    if o.link is not None and o.link not in members:
        out.add(("output", "link"), o.link,
                N_("output.link '{link}' is not a moving link; links: {names}"),
                link=o.link, names=Listed(members))
    for i, m in enumerate(s.masses):
        if m.link not in members:
            out.add(("masses", i, "link"), m.link,
                    N_("masses[{i}].link '{link}' is not a moving link; links: {names}"),
                    i=i, link=m.link, names=Listed(members))
        elif m.com not in members[m.link]:
            out.add(("masses", i, "com"), m.com,
                    N_("masses[{i}].com '{com}' is not a point of link '{link}' (its points: "
                       "{names}); add it with a `point` group"),
                    i=i, com=m.com, link=m.link, names=Listed(members[m.link]))
    for i, r in enumerate(s.resistances):
        if r.link not in members or r.point not in members[r.link]:
            field = "link" if r.link not in members else "point"
            out.add(("resistances", i, field), r.point if field == "point" else r.link,
                    N_("resistances[{i}]: point '{point}' is not a point of link '{link}'"),
                    i=i, point=r.point, link=r.link)
        if r.active_mm is not None and o.link is not None:
            out.add(("resistances", i, "active_mm"), r.active_mm,
                    N_("resistances[{i}]: the output is a link (output.link): give its window as "
                       "active_deg, not active_mm"), i=i)
        if r.active_deg is not None and o.point is not None:
            out.add(("resistances", i, "active_deg"), r.active_deg,
                    N_("resistances[{i}]: the output is a point (output.point): give its window "
                       "as active_mm, not active_deg"), i=i)
        for key, window in (("active_mm", r.active_mm), ("active_deg", r.active_deg)):
            if window is not None and not window[0] < window[1]:
                out.add(("resistances", i, key), window,
                        N_("resistances[{i}]: the active window needs from < to"), i=i)
    if own:
        out.raise_any()
    return members


def point_names(s: LinkageSection) -> list[str]:
    """Every point of the section's linkage in definition order (frame points, the crank
    pin, the groups' new points), read from the data alone."""
    names = list(s.frame_points_mm) + [s.crank.tip]
    for g in s.groups:
        names += [p for p in _group_io(g)[1] if p not in names]
    return names


def link_ids(s: LinkageSection) -> list[str]:
    """The moving links' ids (the crank first)."""
    out = [s.crank.link]
    for g in s.groups:
        out += [link for link, _ in _group_io(g)[2] if link not in out]
    return out


def check_requests(s: LinkageSection, analysis: AnalysisSettings, out, prefix: str = "analysis"
                   ) -> None:
    """The analysis section's named points and link events against the linkage's data:
    each problem added to ``out`` (:class:`~.common.Problems`) at its field."""
    points = point_names(s)
    for i, name in enumerate(analysis.points):
        if name not in points:
            out.add((prefix, "points", i), name,
                    N_("{name!r} is not a point of the linkage; its points: {names}"),
                    name=name, names=Listed(points))
    links = link_ids(s)
    for i, code in enumerate(analysis.events):
        link = code.partition(":")[2]
        if link and link not in links:
            out.add((prefix, "events", i), code,
                    N_("link {link!r} is not a moving link; links: {names}"),
                    link=link, names=Listed(links))


def linkage_to_model(s: LinkageSection, analysis: AnalysisSettings, names: dict | None = None):
    """The SI linkage model (m, rad, rad/s, kg, N) of the section: the only conversion."""
    from ..core.kinetostatics import Body
    from ..core.mechanism import RPR, RRP, RRR, Crank, LinkPoint, Mechanism
    from ..stages.flywheel import FlywheelSpec, RimSpec
    from ..stages.linkage import LinkageModel, Output, Resistance

    mm, rad = 1e-3, np.radians
    frame = FRAME_LINK
    mech = Mechanism(frame, {n: complex(x, y) * mm for n, (x, y) in s.frame_points_mm.items()})
    sense = -1.0 if s.crank.rotation == "cw" else 1.0
    omega = sense * s.crank.speed_rpm * np.pi / 30.0
    mech.add(Crank(f"crank {s.crank.pivot}{s.crank.tip}", s.crank.link, s.crank.pivot,
                   s.crank.tip, s.crank.length_mm * mm, omega))
    for g in s.groups:
        if g.type == "RRR":
            mech.add(RRR(g.name or f"RRR {g.joint}", g.links[0], g.links[1], g.ends[0], g.ends[1],
                         g.joint, g.lengths_mm[0] * mm, g.lengths_mm[1] * mm, g.branch))
        elif g.type == "RRP":
            x, y = g.guide_point_mm
            mech.add(RRP(g.name or f"RRP {g.joint}", g.links[0], g.links[1], g.end, g.joint,
                         g.length_mm * mm, complex(x, y) * mm, rad(g.guide_angle_deg), g.branch,
                         frame))
        elif g.type == "RPR":
            mech.add(RPR(g.name or f"RPR {g.slider_at}", g.links[0], g.links[1], g.slider_at,
                         g.pivot, g.branch, g.offset_mm * mm))
        else:
            mech.add(LinkPoint(g.name, g.link, g.origin, g.distance_mm * mm, rad(g.angle_deg)))
    o = s.output
    output = Output("point", o.point, rad(o.direction_deg), 1 if o.working == "increasing" else -1) \
        if o.point is not None else Output("link", o.link, 0.0, 1 if o.working == "increasing" else -1)
    bodies = tuple(Body(m.link, m.mass_kg, m.com, m.J_kgm2) for m in s.masses)
    res = []
    for r in s.resistances:
        window = None
        if r.active_mm is not None:
            window = (r.active_mm[0] * mm, r.active_mm[1] * mm)
        elif r.active_deg is not None:
            window = (rad(r.active_deg[0]), rad(r.active_deg[1]))
        res.append(Resistance(r.link, r.point, rad(r.direction_deg), r.working_N, r.return_N, window))
    fw = s.flywheel
    rim = None if fw is None or fw.rim_diameter_mm is None else RimSpec(
        fw.rim_diameter_mm * mm, fw.rim_height_to_width, fw.specific_weight_N_m3,
        "linkage.flywheel.rim_diameter_mm")
    fly = None if fw is None else FlywheelSpec(fw.fluctuation_delta, fw.speed_ratio, rim=rim)
    return LinkageModel(
        mechanism=mech, crank_omega=omega, output=output, bodies=bodies, resistances=tuple(res),
        grid_points=analysis.grid_points, position_step=rad(analysis.position_step_deg),
        gravity=analysis.gravity, flywheel=fly,
        pressure_angle_limit=None if s.pressure_angle_max_deg is None else rad(s.pressure_angle_max_deg),
        transmission_angle_min=None if s.transmission_angle_min_deg is None
        else rad(s.transmission_angle_min_deg),
        names=names or {},
        group_labels={g.name: (g.name, g.name_en) for g in s.groups
                      if g.type != "point" and g.name and g.name_en})
