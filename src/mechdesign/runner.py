"""Run one brief (one group) from file to report, without printing or exiting.

Used by ``mechdesign run`` (which prints as it goes) and ``mechdesign batch`` (which runs
many in worker processes and collects the outcomes into an index).
"""
from __future__ import annotations

import importlib
import time
import traceback
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

#: Exit codes shared by the commands.
EXIT_OK, EXIT_FAILED, EXIT_INVALID = 0, 1, 2


@dataclass(frozen=True)
class Outcome:
    """What became of one run: ``status`` is ok, invalid (bad brief or infeasible design:
    exit 2) or failed (rendering or an unexpected error: exit 1)."""

    brief: str
    group: str | None
    status: str
    exit_code: int
    message: str = ""
    machine: str = ""
    out_dir: str = ""
    files: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()
    summary: tuple[tuple[str, str], ...] = ()
    #: the student's name, number and class (the brief's ``report`` section, per group)
    student: tuple[str, str, str] = ("", "", "")
    seconds: float = 0.0
    compute_seconds: float = 0.0
    traceback: str = ""


def design_error_kinds() -> dict[type, str]:
    """Design errors (infeasible with the brief's data) → what cannot be done (a msgid)."""
    from .core.cam import CamDesignError
    from .core.cycle import CycleError
    from .core.drive import DriveDesignError
    from .core.fourbar import SynthesisError
    from .core.intermittent import IntermittentDesignError
    from .core.mechanism import AssemblyError
    from .i18n import N_

    return {
        AssemblyError: N_("the mechanism cannot be assembled"),
        CamDesignError: N_("the cam cannot be designed"),
        DriveDesignError: N_("the drive cannot be designed"),
        SynthesisError: N_("the linkage cannot be synthesised"),
        CycleError: N_("the motion cycle diagram is inconsistent"),
        IntermittentDesignError: N_("the intermittent drive cannot be designed"),
    }


def describe_design_error(exc: Exception, lang: str) -> str | None:
    """A user-language line for a design error, or None if ``exc`` is not one: what cannot
    be done, then the error's own text in ``lang`` (the problem by name, its numbers and
    what to change; see :class:`mechdesign.core.errors.DesignError`)."""
    from .core.errors import DesignError
    from .i18n import N_, tr

    for kind, what in design_error_kinds().items():
        if isinstance(exc, kind):
            break
    else:
        if not isinstance(exc, DesignError):
            return None
        what = N_("the design is infeasible")
    _ = tr(lang)
    detail = exc.text(lang)           # every design error is a DesignError (zh + en)
    return _("{what} with the brief's data:\n  {detail}", what=_(what), detail=detail)


def brief_language(path: Path, lang: str | None = None, *, data: Any = ...) -> str:
    """The language of messages about a brief: ``lang`` (--lang) if given, else the brief's
    ``report.language`` when the file reads as YAML (even if other fields are invalid),
    else zh (the default of report.language). ``data``: the file's YAML data when already
    read."""
    from .i18n import canonical, use

    if canonical(lang):
        return use(canonical(lang))
    from .brief.loader import BriefError, read_brief_data

    try:
        data = read_brief_data(path) if data is ... else data
    except BriefError:
        return "zh"
    report = data.get("report") if isinstance(data, dict) else None
    value = report.get("language") if isinstance(report, dict) else None
    return use(canonical(value) or "zh")


def run_one(brief: Path, *, out_dir: Path | None = None, lang: str | None = None,
            formats: tuple[str, ...] = ("md", "pdf"), group: str | None = None,
            templates: Path | None = None,
            stage_progress: Callable[[int, int, str], None] | None = None,
            render_progress: Callable[[str], None] | None = None,
            on_warning: Callable[[str], None] | None = None,
            parallel: bool = False) -> Outcome:
    """Validate, compute and render ``brief`` (group ``group``) into ``out_dir``.

    Never raises for a bad brief, an infeasible design or a rendering failure: the
    Outcome says what happened. The report is written to a staging folder and moved
    into place only when complete, so a failure leaves an earlier report as it was.
    ``parallel``: figures and sheets may be written by a helper process (a single run;
    a batch already keeps every core busy)."""
    from .brief.loader import BriefError, load_variant, student_of
    from .machines import get_machine, stages_for
    from .publish import ForeignFiles, foreign
    from .pipeline import run_stages
    from .render.report import write_report

    brief = Path(brief)
    start = time.perf_counter()
    base = {"brief": str(brief), "group": group}
    try:
        variant = load_variant(brief, group)
    except BriefError as exc:
        return Outcome(**base, status="invalid", exit_code=EXIT_INVALID,
                       message=exc.text(brief_language(brief, lang)),
                       student=student_of(brief, group))
    b, label = variant.brief, variant.group
    base["group"] = label
    base["student"] = (b.report.student, b.report.student_id, b.report.class_name)
    from .i18n import canonical, use

    language = use(canonical(lang) or b.report.language)   # zh_TW → zh, its catalogue set
    if out_dir is None:
        # a group asked for by name gets its own folder; the default group keeps the brief's
        out_dir = Path("out") / (brief.stem if group is None else f"{brief.stem}-g{safe_label(label)}")
    machine = get_machine(b.machine)
    common = dict(base, machine=machine.name, out_dir=str(out_dir))
    fixed = ["results.json"] + [f"report.{f}" for f in formats if f in ("md", "pdf", "docx")]
    clash = foreign(Path(out_dir), fixed)
    if clash:   # before any computation is spent: the folder holds someone else's report
        return Outcome(**common, status="invalid", exit_code=EXIT_INVALID,
                       message=ForeignFiles(Path(out_dir), clash).text(language))
    try:
        params = machine.to_params(b)
    except ValueError as exc:  # a conversion found the data inconsistent
        return Outcome(**common, status="invalid", exit_code=EXIT_INVALID, message=f"{brief}: {exc}")
    except Exception as exc:  # noqa: BLE001 - a bug, but never a bare traceback
        return Outcome(**common, status="failed", exit_code=EXIT_FAILED,
                       message=f"{brief}: internal error while reading the brief: "
                               f"{type(exc).__name__}: {exc}", traceback=traceback.format_exc())
    try:
        problems, checked = feasibility(machine, params, variant)
    except Exception as exc:  # noqa: BLE001 - a bug in a check, but never a bare traceback
        return Outcome(**common, status="failed", exit_code=EXIT_FAILED,
                       message=f"{brief}: internal error while checking the design: "
                               f"{type(exc).__name__}: {exc}", traceback=traceback.format_exc())
    if problems:
        from .brief.loader import FeasibilityError

        source = str(brief) if label is None else f"{brief} (group {label})"
        return Outcome(**common, status="invalid", exit_code=EXIT_INVALID,
                       message=FeasibilityError(source, problems).text(language))
    try:
        stage_list = stages_for(machine, params)
        results, _ = run_stages(stage_list,
                                {"params": params, "brief": b, "checked": checked},
                                stage_progress)
    except Exception as exc:  # noqa: BLE001 - classified below; never a bare traceback
        message = describe_design_error(exc, language)
        if message is not None:
            return Outcome(**common, status="invalid", exit_code=EXIT_INVALID,
                           message=f"{brief}: {message}")
        return Outcome(**common, status="failed", exit_code=EXIT_FAILED,
                       message=f"{brief}: internal error while computing: "
                               f"{type(exc).__name__}: {exc}",
                       traceback=traceback.format_exc())
    warnings = []
    for value in results.values():
        for finding in getattr(value, "warnings", None) or ():
            text = finding.text(language)
            field = getattr(finding, "field", "")
            if field and field not in text:     # the terminal names the brief field to change
                text = f"{text} [{field}]"
            warnings.append(text)
            if on_warning is not None:
                on_warning(text)
    computed = time.perf_counter() - start

    def sheet_warning(text: str) -> None:   # a sheet left out: a warning of the run
        warnings.append(text)
        if on_warning is not None:
            on_warning(text)

    report = importlib.import_module(machine.report_module)
    from .render.sheets import make_sheets

    from .results import to_plain

    document = _with_group(to_plain(machine.document(results)), label)
    requested = _requests_document(results)
    if requested is not None:
        document["analysis_requests"] = to_plain(requested)

    # the seed hands in its analysis program: the appendix lists it (its flow chart, steps,
    # and the brief's numbers it is written with)
    program = report.program_appendix(results) if hasattr(report, "program_appendix") else None
    animate = None
    if "gif" in formats:
        if hasattr(report, "animate"):
            def animate(path):
                return report.animate(results, path, language)
        elif on_warning is not None:
            on_warning(f"gif: the {machine.name} machine has no linkage to animate; no GIF written")
    try:
        written = write_report(
            Path(out_dir), machine=machine.name, lang=language, formats=formats,
            make_figures=lambda d: _with_requested_figures(report, results, d, language),
            make_context=lambda figs: _with_requested(report.context(results, b, figs, language),
                                                      results, b, figs, language),
            document=document, meta=b.report,
            templates=templates, progress=render_progress, group=label,
            make_sheets=lambda folder, figs: make_sheets(results, b, folder, figs, language,
                                                         formats, render_progress, sheet_warning),
            animate=animate, parallel=parallel, program=program,
            write_data=(None if not hasattr(report, "write_data")
                        else lambda d: report.write_data(results, d)))
    except ForeignFiles as exc:   # a figure or sheet name clashes with a file not ours
        return Outcome(**common, status="invalid", exit_code=EXIT_INVALID,
                       message=exc.text(language))
    except Exception as exc:  # noqa: BLE001 - any rendering failure gets a clean message
        return Outcome(**common, status="failed", exit_code=EXIT_FAILED,
                       message=f"{brief}: the report could not be rendered: {exc}",
                       warnings=tuple(warnings),
                       traceback=traceback.format_exc() + getattr(exc, "detail", ""))
    from .machines.summary import summary_rows

    return Outcome(**common, status="ok", exit_code=EXIT_OK, files=tuple(str(p) for p in written),
                   warnings=tuple(warnings),
                   summary=tuple(summary_rows(machine.name, document, language)),
                   seconds=time.perf_counter() - start, compute_seconds=computed)


def feasibility(machine, params, variant) -> tuple[list, dict]:
    """Run the machine's feasibility checks once (after validation): every problem, each
    at its brief field with its value (where a data group sets the field, reported there),
    and what the checks computed for the stages (``results["checked"]``)."""
    from .brief.loader import located_problems

    checked: dict = {}
    if machine.checks is None:
        return [], checked
    problems = machine.checks(params, checked)
    return located_problems(problems, variant.brief, variant.located), checked


def _requests_document(results: dict):
    """The brief's analysis requests (positions by angle and event, named points) of the
    run's linkage, for results.json (every linkage machine), or None."""
    from .render.sheets import linkage_results
    from .stages.linkage import requests_document

    found = linkage_results(results)
    return None if found is None else requests_document(found.motion)


def _with_requested_figures(report, results: dict, fig_dir, lang: str) -> dict:
    from .render.requests_report import requests_figures

    from .render.graphical_report import graphical_figures

    figures = report.make_figures(results, fig_dir, lang)
    return {**figures, **requests_figures(results, fig_dir, lang),
            **graphical_figures(results, fig_dir, lang)}


def _with_requested(context: dict, results: dict, brief, figures: dict, lang: str) -> dict:
    """A machine's template context plus ``requested`` (the shared requests section) and
    ``graphical`` (the graphical method of every linkage, see render/graphical_report)."""
    from .render.graphical_report import graphical_context
    from .render.requests_report import requests_context

    found = requests_context(results, brief, figures, lang)
    context = {**context, "graphical": graphical_context(results, figures, lang)}
    return context if found is None else {**context, "requested": found}


def _with_group(document: dict, label: str | None) -> dict:
    if label is None:
        return document
    out = dict(document)
    out["data_group"] = label
    return out


def safe_label(label: str) -> str:
    """A group label as a file-name part: letters, digits, - and _ kept, anything else
    (path separators, dots, CJK, spaces) replaced, so a label never leaves the folder."""
    import re

    text = re.sub(r"[^A-Za-z0-9_-]+", "_", label).strip("_")
    if text == label:
        return text
    import hashlib

    return f"{text[:20] or 'group'}-{hashlib.sha1(label.encode()).hexdigest()[:6]}"
