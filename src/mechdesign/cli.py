"""Command line: ``mechdesign run BRIEF``, ``check``, ``schema``, ``new``.

Exit codes: 0 success; 1 the report could not be rendered (toolchain or file-system
problem); 2 the brief or the command line is invalid (including a mechanism that
cannot be assembled with the brief's data).
"""
from __future__ import annotations

import importlib
import sys
import time
import traceback
from enum import Enum
from pathlib import Path
from typing import Optional

import typer

from . import __version__

app = typer.Typer(add_completion=False, no_args_is_help=True,
                  help="Mechanism course design (机械原理课程设计): from a YAML design brief "
                       "to a bilingual report (Markdown + PDF).")

EXIT_OK, EXIT_FAILED, EXIT_INVALID = 0, 1, 2


class Lang(str, Enum):
    zh = "zh"
    en = "en"


def _version(value: bool):
    if value:
        typer.echo(f"mechdesign {__version__}")
        raise typer.Exit()


@app.callback()
def main(version: Optional[bool] = typer.Option(None, "--version", callback=_version,
                                                is_eager=True, help="Show the version and exit.")):
    """Mechanism course design reports from YAML briefs."""


def _err(msg: str) -> None:
    typer.echo(msg, err=True)


def _parse_formats(text: str) -> tuple[str, ...]:
    from .render.report import FORMATS

    formats = tuple(dict.fromkeys(x.strip().lower() for x in text.split(",") if x.strip()))
    bad = [x for x in formats if x not in FORMATS]
    if bad or not formats:
        raise typer.BadParameter(f"{text!r}: allowed formats are {', '.join(FORMATS)} "
                                 "(comma-separated, e.g. md,pdf)", param_hint="--format")
    return formats


@app.command()
def run(
    brief: Path = typer.Argument(..., exists=True, dir_okay=False, readable=True,
                                 help="Design brief (YAML), e.g. designs/shaper.yaml."),
    out: Optional[Path] = typer.Option(None, "--out", "-o", file_okay=False,
                                       help="Output folder (default: out/BRIEF-NAME/)."),
    lang: Optional[Lang] = typer.Option(None, "--lang", help="Report language "
                                        "(default: the brief's report.language, zh)."),
    formats: str = typer.Option("md,pdf", "--format", "-f",
                                help="Comma-separated output formats: md, pdf, docx, dxf, gif "
                                     "(pdf and dxf include the drawing sheets)."),
    templates: Optional[Path] = typer.Option(None, "--templates", exists=True, file_okay=False,
                                             help="Folder of report templates to use instead "
                                                  "of the shipped ones."),
    debug: bool = typer.Option(False, "--debug", help="Show Python tracebacks on errors."),
):
    """Run every stage for BRIEF and write report.md, report.pdf, results.json and figures."""
    from .brief.loader import BriefError, load_brief
    from .core.cam import CamDesignError
    from .core.cycle import CycleError
    from .core.drive import DriveDesignError
    from .core.fourbar import SynthesisError
    from .core.intermittent import IntermittentDesignError
    from .core.mechanism import AssemblyError
    from .machines import get_machine, stages_for
    from .pipeline import run_stages
    from .render.report import write_report

    fmt = _parse_formats(formats)
    try:
        b = load_brief(brief)
    except BriefError as exc:
        _err(str(exc))
        raise typer.Exit(EXIT_INVALID)
    language = (lang.value if lang else b.report.language)
    out_dir = out if out is not None else Path("out") / brief.stem
    machine = get_machine(b.machine)

    def stage_progress(i: int, total: int, title: str) -> None:
        _err(f"[{i}/{total}] {title}")

    start = time.perf_counter()
    try:
        params = machine.to_params(b)
        results, _ = run_stages(stages_for(machine, params), {"params": params, "brief": b},
                                stage_progress)
    except (AssemblyError, CamDesignError, DriveDesignError, SynthesisError, CycleError,
            IntermittentDesignError) as exc:
        if debug:
            traceback.print_exc()
        what = next(text for kind, text in (
            (AssemblyError, "the mechanism cannot be assembled"),
            (CamDesignError, "the cam cannot be designed"),
            (DriveDesignError, "the drive cannot be designed"),
            (SynthesisError, "the linkage cannot be synthesised"),
            (CycleError, "the motion cycle diagram is inconsistent"),
            (IntermittentDesignError, "the intermittent drive cannot be designed"))
            if isinstance(exc, kind))
        _err(f"{brief}: {what} with the brief's data:\n  {exc}")
        raise typer.Exit(EXIT_INVALID)
    for value in results.values():
        for finding in getattr(value, "warnings", None) or ():
            _err(f"warning: {finding.text(language)}")
    computed = time.perf_counter() - start
    report = importlib.import_module(machine.report_module)

    def render_progress(what: str) -> None:
        _err(f"      rendering {what}")

    from .render.sheets import make_sheets

    animate = None
    if "gif" in fmt:
        if hasattr(report, "animate"):
            def animate(path):
                return report.animate(results, path, language)
        else:
            _err(f"warning: gif: the {machine.name} machine has no linkage to animate; no GIF written")

    try:
        written = write_report(
            out_dir, machine=machine.name, lang=language, formats=fmt,
            make_figures=lambda d: report.make_figures(results, d, language),
            make_context=lambda figs: report.context(results, b, figs, language),
            document=machine.document(results), meta=b.report, templates=templates,
            progress=render_progress,
            make_sheets=lambda folder, figs: make_sheets(results, b, folder, figs, language, fmt,
                                                         render_progress),
            animate=animate,
            write_data=(None if not hasattr(report, "write_data")
                        else lambda d: report.write_data(results, d)))
    except Exception as exc:  # noqa: BLE001 - any rendering failure gets a clean message
        if debug:
            traceback.print_exc()
        _err(f"error: the report could not be rendered: {exc}\n"
             "(nothing was written; run with --debug for the traceback)")
        raise typer.Exit(EXIT_FAILED)
    total = time.perf_counter() - start
    _err(f"done in {total:.1f} s (computation {computed:.2f} s)")
    for path in written:
        typer.echo(str(path))


#: The example brief each machine's starter (`mechdesign new`) is copied from.
EXAMPLES = {
    "shaper": "shaper.yaml", "furnace_pusher": "furnace_pusher.yaml", "lockbeam": "lockbeam.yaml",
    "die_cutter": "die_cutter.yaml", "crank_rocker": "crank_rocker.yaml",
    "linkage": "linkage_sixbar.yaml", "cam": "cam_7_3.yaml", "eccentric_cam": "cam_7_1.yaml",
    "drive": "furnace_drive.yaml"}


@app.command()
def check(
    briefs: list[Path] = typer.Argument(..., help="Design briefs (YAML) to validate."),
):
    """Validate briefs without computing anything (fast: for editors and pre-commit).

    Prints one line per brief; exit 0 when all are valid, 2 when any is not."""
    from .brief.loader import BriefError, load_brief
    from .machines import get_machine

    bad = 0
    for path in briefs:
        try:
            b = load_brief(path)
            get_machine(b.machine).to_params(b)
        except BriefError as exc:
            bad += 1
            _err(str(exc))
            continue
        except ValueError as exc:  # a conversion found the data inconsistent
            bad += 1
            _err(f"{path}: {exc}")
            continue
        typer.echo(f"ok: {path} ({b.machine})")
    if bad:
        _err(f"{bad} of {len(briefs)} brief{'s' if len(briefs) != 1 else ''} invalid")
        raise typer.Exit(EXIT_INVALID)


@app.command()
def schema(
    machine: Optional[str] = typer.Argument(None, help="Only this machine's brief "
                                            "(default: all, chosen by the `machine` field)."),
):
    """Print the JSON Schema of the design brief (for editors, e.g. VS Code's YAML extension)."""
    import json

    from .brief.loader import BRIEF_MODELS, brief_schema

    if machine is not None and machine not in BRIEF_MODELS:
        _err(f"machine {machine!r}: one of {', '.join(sorted(BRIEF_MODELS))}")
        raise typer.Exit(EXIT_INVALID)
    typer.echo(json.dumps(brief_schema(machine), ensure_ascii=False, indent=1))


@app.command()
def new(
    machine: str = typer.Argument(..., help="Machine of the starter brief, e.g. shaper."),
    out: Optional[Path] = typer.Option(None, "--out", "-o", dir_okay=False,
                                       help="File to write (default: MACHINE.yaml here)."),
):
    """Write a commented starter brief for MACHINE (the shipped example, to edit)."""
    from importlib import resources

    if machine not in EXAMPLES:
        _err(f"machine {machine!r}: one of {', '.join(sorted(EXAMPLES))}")
        raise typer.Exit(EXIT_INVALID)
    target = out if out is not None else Path(f"{machine}.yaml")
    if target.exists():
        _err(f"{target} exists; choose another name with --out (nothing was written)")
        raise typer.Exit(EXIT_INVALID)
    text = resources.files("mechdesign.designs").joinpath(EXAMPLES[machine]).read_text(encoding="utf-8")
    try:
        target.write_text(text, encoding="utf-8")
    except OSError as exc:
        _err(f"{target}: cannot be written: {exc.strerror}")
        raise typer.Exit(EXIT_FAILED)
    typer.echo(str(target))
    _err(f"wrote a starter {machine} brief; edit it, then: mechdesign check {target} && "
         f"mechdesign run {target}")


if __name__ == "__main__":  # pragma: no cover
    sys.exit(app())
