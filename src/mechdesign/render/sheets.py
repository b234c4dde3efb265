"""The drawing sheets of a run: which sheets a machine's results give, their title
blocks, and the files (vector PDF, DXF, PNG preview for the report).

Sheets: the kinematic diagram (A3, :mod:`.kinematic_sheet`) of every machine with a
mechanism (a linkage, the crank-rocker brief, a cam, the eccentric disc), the
transmission schematic (A3) of a drive, the motion cycle diagram (A3, :mod:`.cycle_sheet`)
of a cycle result, the analysis sheet (A1) for any linkage run through the shared linkage stages
(the shaper, the slotter, the furnace pusher, the die-cutter press, the lock-beam feed,
``linkage`` briefs), a cam sheet (A2) for every synthesised cam, the gear meshing
sheet when they have a gear pair. Files go to ``sheets/`` (``NAME.pdf`` with the pdf
format, ``NAME.dxf`` with dxf); the previews to the figures folder.
"""
from __future__ import annotations

import json
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Callable

from ..fileio import write_text
from ..i18n import N_, tr
from .fmt import meta_text, plain_line
from .sheet import Sheet, TitleInfo, plain

TITLES = {
    "kinematic": N_("Kinematic diagram"),
    "transmission": N_("Transmission schematic"),
    "cycle": N_("Motion cycle diagram"),
    "analysis": N_("Linkage: kinematic and force analysis"),
    # the A1 sheet of a linkage without loads or masses: velocity and acceleration only
    "analysis_kinematic": N_("Linkage: kinematic analysis"),
    "cam": N_("Cam mechanism design"),
    "gear": N_("Gear meshing drawing"),
}


# the title of one cam's sheet where the machine designs several ("cam": the cam's name)
CAM_TITLE = N_("Cam mechanism design: {cam}")


NO_SHEETS = N_("this design has no drawing sheet (no mechanism, cam, drive or cycle "
               "results), so no DXF file is written")


# sheets added to the hand-in by the diagrams (issue 19): one that cannot be drawn for a
# user's brief (a geometry the layout does not handle) is left out with a printed line,
# the report and the other sheets are still written
OPTIONAL = {"kinematic", "transmission", "cycle"}
NOT_DRAWN = N_("the {t} could not be drawn ({e}); no PDF/DXF written for it")
# the prefix of these lines when no warning callback is given (printed to stderr)
NOTE = N_("note: ")


def _printer(lang: str) -> Callable[[str], None]:
    import sys

    return lambda text: print(tr(lang)(NOTE) + text, file=sys.stderr)


@dataclass(frozen=True)
class SheetFiles:
    """One written sheet: its name, title and files (relative to the report folder)."""

    name: str
    title: str
    size: str
    scale: str
    preview: str
    pdf: str | None
    dxf: str | None
    kinematic_only: bool = False   # an A1 analysis sheet without force analysis


@dataclass(frozen=True)
class LinkageResults:
    """What the analysis sheet reads from a run: the engine's model, motion, forces (or
    None), flywheel (or None) and the polygons stage's polygons."""

    model: object
    motion: object
    forces: object
    flywheel: object
    polygons: object
    graphical: object = None       # the graphical method's document (its vector symbols)

    @property
    def kinematic_only(self) -> bool:
        """No force analysis: no forces computed, or no load and no masses (every reaction
        and the balancing torque exactly zero). The A1 sheet then draws the velocity and
        acceleration polygons only and is titled a kinematic analysis."""
        import numpy as np

        f = self.forces
        return f is None or (not np.any(f.balancing_torque)
                             and not any(np.any(v) for v in f.reactions.values()))


def linkage_results(results: dict) -> LinkageResults | None:
    """The shared linkage stages' results in ``results`` (found through the polygons
    stage, which names its model and prefix), or None. The flywheel is ``{prefix}_flywheel``
    (a machine that sizes its flywheel elsewhere, as the die-cutter on a drive shaft, stores
    it under that key too)."""
    from ..stages.polygons import LinkagePolygons

    for polygons in list(results.values()):
        if not isinstance(polygons, LinkagePolygons):
            continue
        model_key, prefix = polygons.model_key, polygons.prefix
        model = results.get(model_key)
        if model is not None:
            return LinkageResults(model, results[prefix], results.get(f"{prefix}_forces"),
                                  results.get(f"{prefix}_flywheel"), polygons,
                                  results.get(f"{prefix}_graphical"))
    return None


def _builders(results: dict, brief) -> list[tuple[str, Callable[[TitleInfo, str], Sheet]]]:
    """(name, build(info, lang)) of each sheet of ``results``. The A1 analysis sheet of a
    linkage without force analysis has its builder's ``kinematic_only`` set: its title is
    :data:`TITLES`' "analysis_kinematic"."""
    out = []
    found = linkage_results(results)
    out.extend(_diagram_builders(results, found))
    if found is not None:
        def analysis(info, lang):
            from .analysis_sheet import analysis_sheet

            return analysis_sheet(found, info, lang)[0]

        analysis.kinematic_only = found.kinematic_only
        out.append(("analysis", analysis))
    out.extend(_cam_builders(results, brief))
    gear = results.get("gear")
    if gear is not None:
        def gear_builder(info, lang):
            from .gear_sheet import gear_sheet

            return gear_sheet(gear.drawing, info, lang)

        out.append(("gear", gear_builder))
    return out


def designed_cams(results: dict) -> list[tuple[str, object]]:
    """(result key, cam) of every cam ``results`` designs (stages.cam.CamResult), in the
    order of the stages; known by its type's name: render imports no stage module,
    tests/test_layers.py)."""
    return [(key, value) for key, value in results.items()
            if type(value).__name__ == "CamResult" and getattr(value, "grid", None) is not None]


def cam_names(results: dict, brief) -> dict[str, str]:
    """Result key → N_(name) of the cams of the brief's machine (its registry entry's
    ``cams``; empty for a machine with one cam)."""
    from ..registry import entry

    b = brief if brief is not None else results.get("brief")
    try:
        return dict(entry(getattr(b, "machine", "")).cams)
    except KeyError:
        return {}


def _cam_builders(results: dict, brief) -> list:
    """One A2 cam sheet per designed cam. A machine with one cam: the sheet "cam"; with
    several, each sheet is named by its cam's result key ("cam", "bending_cam") and titled
    with the cam's name (:data:`CAM_TITLE`, the machine's registry entry names them)."""
    cams = designed_cams(results)
    names = cam_names(results, brief) if len(cams) > 1 else {}
    out = []
    for key, cam in cams:
        def cam_builder(info, lang, cam=cam):
            from .cam_sheet import cam_sheet

            return cam_sheet(cam, info, lang)

        if len(cams) > 1:
            cam_builder.cam_name = names.get(key, key.replace("_", " "))
        out.append(("cam" if len(cams) == 1 else key, cam_builder))
    return out


def _diagram_builders(results: dict, found) -> list:
    """The kinematic diagram (linkage, crank-rocker, cam or eccentric disc), the
    transmission schematic (a drive) and the cycle diagram (a cycle result) of ``results``."""
    from . import kinematic_sheet as ks

    out = []
    cam = results.get("cam")
    bending = results.get("bending")
    if (found is not None and bending is not None and hasattr(bending, "design")
            and results.get("bending_cam") is not None and cam is not None):
        # the lock-beam machine: the feed linkage, both cams, the bending four-bar and chain
        out.append(("kinematic", lambda info, lang: ks.lockbeam_diagram(results, found, info, lang)))
    elif (found is not None and cam is not None and hasattr(cam, "grid")
          and hasattr(results.get("feed"), "sprocket_radius")):
        # the die-cutter: the toggle press, the gripper cam, the incomplete gear and the chain
        out.append(("kinematic", lambda info, lang: ks.die_cutter_diagram(results, found, info, lang)))
    elif results.get("optimum") is not None and hasattr(results["optimum"], "best"):
        # the crank-rocker (its optimum also runs through the linkage stages)
        opt, slider = results["optimum"], results.get("slider")
        out.append(("kinematic", lambda info, lang: ks.crank_rocker_diagram(opt, slider, info, lang)))
    elif found is not None:
        label = ks.diagram_position(found, results.get("brief"))
        out.append(("kinematic", lambda info, lang: ks.linkage_diagram(found, info, lang, label)))
    elif cam is not None and hasattr(cam, "grid"):
        out.append(("kinematic", lambda info, lang: ks.cam_diagram(cam, info, lang)))
    elif results.get("disc") is not None:
        disc = results["disc"]
        out.append(("kinematic", lambda info, lang: ks.disc_diagram(disc, info, lang)))
    drive = results.get("drive")
    if drive is not None and getattr(drive, "stages", None):
        fly = found.flywheel if found is not None else None
        out.append(("transmission", lambda info, lang: ks.drive_schematic(drive, info, lang, fly)))
    cycle = results.get("cycle")
    if cycle is not None and hasattr(cycle, "diagram"):
        def cycle_builder(info, lang):
            from .cycle_sheet import cycle_sheet

            return cycle_sheet(cycle.diagram, info, lang, tuple(getattr(cycle, "checks", ()) or ()))

        out.append(("cycle", cycle_builder))
    return out


def course_of(brief) -> str:
    """The course a brief belongs to, as the title block names it: "design" for a drive
    designed alone (machine ``drive``: the machine-design course), else "theory"."""
    return "design" if getattr(brief, "machine", "") == "drive" else "theory"


def title_info(meta, drawing: str, number: str, index: int, count: int, lang: str,
               course: str = "theory") -> TitleInfo:
    """The title block's strings; the brief's text as one line each (a title block cell
    holds one line; the backends print the text as written). ``course``: "theory" or
    "design" (a drive alone: the machine-design course)."""
    return TitleInfo(course=course, drawing=drawing, project=plain_line(meta_text(meta, "title", lang)),
                     student=plain_line(meta.student), student_id=plain_line(meta.student_id),
                     class_name=plain_line(meta.class_name), teacher=plain_line(meta.teacher),
                     date=plain_line(meta.date), number=plain_line(number), sheet_no=index,
                     sheets=count, lang=lang)


def make_sheets(results: dict, brief, folder: Path, fig_dir: Path, lang: str,
                formats: tuple[str, ...], progress: Callable[[str], None] | None = None,
                on_warning: Callable[[str], None] | None = None
                ) -> Callable[[], list[SheetFiles]]:
    """Build and write every sheet of ``results``: in a helper process when the report is
    rendered with background saves (:mod:`.parallel`), the whole of it, models included,
    while this process draws the figures. Returns a function that gives what was written
    (waiting for the helper); the helper hands the list over in a small JSON file, with the
    lines saying which sheet could not be drawn, given to ``on_warning`` here (the run's
    warnings, in the report's language; printed to stderr without a callback)."""
    from .parallel import save_apart

    warn = on_warning or _printer(lang)
    builders = _builders(results, brief)
    if not builders:
        if "dxf" in formats:
            warn(tr(lang)(NO_SHEETS))
        return lambda: []
    manifest = Path(folder) / ".sheets.json"

    def work():
        notes: list[str] = []
        files = write_all(builders, brief, folder, fig_dir, lang, formats, progress, notes.append)
        write_text(manifest, json.dumps({"files": [asdict(f) for f in files], "notes": notes},
                                        ensure_ascii=False), encoding="utf-8")

    wait = save_apart(work, "the drawing sheets")
    done: list[SheetFiles] = []

    def collect() -> list[SheetFiles]:
        if not done:
            wait()
            handed = json.loads(manifest.read_text(encoding="utf-8"))
            done.extend(SheetFiles(**row) for row in handed["files"])
            manifest.unlink()
            for text in handed["notes"]:
                warn(text)
        return done

    return collect


def sheet_title(name: str, build, lang: str) -> str:
    """The title of the sheet ``name`` drawn by ``build`` (one of :func:`_builders`), in
    ``lang``; a cam sheet of a machine with several cams names its cam."""
    cam = getattr(build, "cam_name", None)
    if cam is not None:
        _ = tr(lang)
        return _(CAM_TITLE, cam=_(cam))
    return tr(lang)(TITLES[f"{name}_kinematic" if getattr(build, "kinematic_only", False) else name])


def write_all(builders: list, brief, folder: Path, fig_dir: Path, lang: str,
              formats: tuple[str, ...], progress: Callable[[str], None] | None = None,
              on_warning: Callable[[str], None] | None = None) -> list[SheetFiles]:
    """Build and write the sheets of ``builders`` (see :func:`_builders`) here and now;
    return what was written. A diagram that cannot be drawn is left out with a line to
    ``on_warning`` (stderr without it)."""
    warn = on_warning or _printer(lang)
    from .sheet_typst import write_sheets

    say = progress or (lambda _m: None)
    settings = getattr(brief, "sheets", None)
    prefix = settings.drawing_number if settings is not None else "MD"
    out, jobs = [], []
    sheet_dir = Path(folder) / "sheets"
    for k, (name, build) in enumerate(builders, start=1):
        say(f"sheet {k}/{len(builders)}: {name}")
        kinematic_only = getattr(build, "kinematic_only", False)
        title = sheet_title(name, build, lang)
        info = title_info(brief.report, title, f"{prefix}-{k:02d}" if prefix else "",
                          k, len(builders), lang, course_of(brief))
        try:
            sheet = build(info, lang)
        except (ValueError, ArithmeticError) as exc:
            if name not in OPTIONAL:
                raise
            warn(tr(lang)(NOT_DRAWN, t=title, e=exc))
            continue
        preview = Path(fig_dir) / f"sheet_{name}.png"
        pdf = dxf = None
        if "pdf" in formats or "dxf" in formats:
            sheet_dir.mkdir(exist_ok=True)
        stem = f"{name}_{sheet.size}"
        if "pdf" in formats:
            pdf = sheet_dir / f"{stem}.pdf"
        jobs.append((sheet, pdf, preview, 2400))
        if "dxf" in formats:
            from .sheet_dxf import write_dxf

            dxf = write_dxf(sheet, sheet_dir / f"{stem}.dxf", info.drawing)
        rel = Path(folder)
        out.append(SheetFiles(name, info.drawing, sheet.size,
                              plain(sheet.info.scale) if sheet.info is not None else "",
                              preview.relative_to(rel).as_posix(),
                              None if pdf is None else pdf.relative_to(rel).as_posix(),
                              None if dxf is None else dxf.relative_to(rel).as_posix(),
                              kinematic_only))
    write_sheets(jobs)
    return out
