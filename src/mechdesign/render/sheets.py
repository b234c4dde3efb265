"""The drawing sheets of a run: which sheets a machine's results give, their title
blocks, and the files (vector PDF, DXF, PNG preview for the report).

Sheets: the analysis sheet (A1) for any linkage run through the shared linkage stages
(the shaper, the slotter, the furnace pusher, the die-cutter press, the lock-beam feed,
``linkage`` briefs), the cam sheet (A2) when they have a synthesised cam, the gear meshing
sheet when they have a gear pair. Files go to ``sheets/`` (``NAME.pdf`` with the pdf
format, ``NAME.dxf`` with dxf); the previews to the figures folder.
"""
from __future__ import annotations

import json
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Callable

from ..fileio import write_text
from .fmt import meta_text, plain_line
from .sheet import Sheet, TitleInfo

TITLES = {
    "analysis": {"zh": "机构运动及动力分析图", "en": "Linkage: kinematic and force analysis"},
    "cam": {"zh": "凸轮机构设计图", "en": "Cam mechanism design"},
    "gear": {"zh": "齿轮啮合图", "en": "Gear meshing drawing"},
}


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


@dataclass(frozen=True)
class LinkageResults:
    """What the analysis sheet reads from a run: the engine's model, motion, forces (or
    None), flywheel (or None) and the polygons stage's polygons."""

    model: object
    motion: object
    forces: object
    flywheel: object
    polygons: object


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
                                  results.get(f"{prefix}_flywheel"), polygons)
    return None


def _builders(results: dict, brief) -> list[tuple[str, Callable[[TitleInfo, str], Sheet]]]:
    out = []
    found = linkage_results(results)
    if found is not None:
        def analysis(info, lang):
            from .analysis_sheet import analysis_sheet

            return analysis_sheet(found, info, lang)[0]

        out.append(("analysis", analysis))
    cam = results.get("cam")
    if cam is not None and hasattr(cam, "grid"):
        def cam_builder(info, lang):
            from .cam_sheet import cam_sheet

            return cam_sheet(cam, info, lang)

        out.append(("cam", cam_builder))
    gear = results.get("gear")
    if gear is not None:
        def gear_builder(info, lang):
            from .gear_sheet import gear_sheet

            return gear_sheet(gear.drawing, info, lang)

        out.append(("gear", gear_builder))
    return out


def title_info(meta, drawing: str, number: str, index: int, count: int, lang: str) -> TitleInfo:
    """The title block's strings; the brief's text as one line each (a title block cell
    holds one line; the backends print the text as written)."""
    return TitleInfo(drawing=drawing, project=plain_line(meta_text(meta, "title", lang)),
                     student=plain_line(meta.student), student_id=plain_line(meta.student_id),
                     class_name=plain_line(meta.class_name), teacher=plain_line(meta.teacher),
                     date=plain_line(meta.date), number=plain_line(number), sheet_no=index,
                     sheets=count, lang=lang)


def make_sheets(results: dict, brief, folder: Path, fig_dir: Path, lang: str,
                formats: tuple[str, ...], progress: Callable[[str], None] | None = None
                ) -> Callable[[], list[SheetFiles]]:
    """Build and write every sheet of ``results``: in a helper process when the report is
    rendered with background saves (:mod:`.parallel`), the whole of it, models included,
    while this process draws the figures. Returns a function that gives what was written
    (waiting for the helper); the helper hands the list over in a small JSON file."""
    from .parallel import save_apart

    builders = _builders(results, brief)
    if not builders:
        return lambda: []
    manifest = Path(folder) / ".sheets.json"

    def work():
        files = write_all(builders, brief, folder, fig_dir, lang, formats, progress)
        write_text(manifest, json.dumps([asdict(f) for f in files], ensure_ascii=False),
                   encoding="utf-8")

    wait = save_apart(work, "the drawing sheets")
    done: list[SheetFiles] = []

    def collect() -> list[SheetFiles]:
        if not done:
            wait()
            done.extend(SheetFiles(**row) for row in json.loads(manifest.read_text(encoding="utf-8")))
            manifest.unlink()
        return done

    return collect


def write_all(builders: list, brief, folder: Path, fig_dir: Path, lang: str,
              formats: tuple[str, ...], progress: Callable[[str], None] | None = None
              ) -> list[SheetFiles]:
    """Build and write the sheets of ``builders`` (see :func:`_builders`) here and now;
    return what was written."""
    from .sheet_typst import write_sheets

    say = progress or (lambda _m: None)
    settings = getattr(brief, "sheets", None)
    prefix = settings.drawing_number if settings is not None else "MD"
    out, jobs = [], []
    sheet_dir = Path(folder) / "sheets"
    for k, (name, build) in enumerate(builders, start=1):
        say(f"sheet {k}/{len(builders)}: {name}")
        info = title_info(brief.report, TITLES[name][lang], f"{prefix}-{k:02d}" if prefix else "",
                          k, len(builders), lang)
        sheet = build(info, lang)
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
                              sheet.info.scale if sheet.info is not None else "",
                              preview.relative_to(rel).as_posix(),
                              None if pdf is None else pdf.relative_to(rel).as_posix(),
                              None if dxf is None else dxf.relative_to(rel).as_posix()))
    write_sheets(jobs)
    return out
