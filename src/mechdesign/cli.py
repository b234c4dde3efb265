"""Command line: ``mechdesign run BRIEF``, ``batch``, ``merge``, ``watch``, ``check``,
``schema``, ``new``.

Output: progress, warnings and errors on stderr through :mod:`mechdesign.console` (rich on a
terminal, plain lines in CI logs and pipes); the files written on stdout. No Python
traceback without ``--debug`` (``MECHDESIGN_DEBUG=1``): :func:`entry` is the console script.

Exit codes: 0 success; 1 the report could not be rendered (toolchain or file-system
problem); 2 the brief or the command line is invalid (including a mechanism that
cannot be assembled with the brief's data).
"""
from __future__ import annotations

import os
import sys
import time
from contextlib import contextmanager
from enum import Enum
from pathlib import Path
from typing import Optional

import typer
from typer.core import TyperCommand, TyperGroup

from . import __version__
from .i18n import LANGUAGES, N_
from .registry import Lookup

#: metavar of a flag: nothing (typer would print <bool>)
FLAG = ""


def _one_paragraph_per_line(func):
    """The command's docstring with each paragraph on one line, so --help wraps it to the
    terminal instead of at the source's line breaks."""
    import inspect

    paragraphs = inspect.cleandoc(func.__doc__ or "").split("\n\n")
    func.__doc__ = "\n\n".join(" ".join(p.split()) for p in paragraphs)
    return func


def _for_people(command, ctx):
    """Help written for people: flags show no type (typer prints ``<bool>``), arguments
    show their metavar alone (BRIEF, not ``{BRIEF}`` or ``<list[Path]>``); the help
    option of ``command``, as click asks for it."""
    for param in command.params:
        if getattr(param, "is_flag", False) and param.metavar is None:
            param.metavar = FLAG
        if param.param_type_name == "argument" and param.metavar:
            name = param.metavar if param.required else f"[{param.metavar}]"
            param._usage_display_name = lambda name=name: name
            param.display_type_rich = lambda ctx: None
    option = command._help_option_for(ctx)
    if option is not None:
        option.metavar = FLAG
    return option


class _Command(TyperCommand):
    def _help_option_for(self, ctx):
        return super().get_help_option(ctx)

    def get_help_option(self, ctx):
        return _for_people(self, ctx)


class _Group(TyperGroup):
    def _help_option_for(self, ctx):
        return super().get_help_option(ctx)

    def get_help_option(self, ctx):
        return _for_people(self, ctx)


app = typer.Typer(cls=_Group, add_completion=True, no_args_is_help=True,
                  pretty_exceptions_enable=False,
                  help="Mechanism course design (机械原理课程设计): from a YAML design brief "
                       "to a bilingual report (Markdown + PDF).",
                  epilog="Examples:\n\n"
                         "  mechdesign new shaper                    # a starter brief, shaper.yaml\n"
                         "  mechdesign run shaper.yaml               # its report in out/shaper/\n"
                         "  mechdesign watch shaper.yaml             # re-run on every save\n"
                         "  mechdesign batch designs/ --shard 1/2    # half of a class, for CI\n"
                         "  mechdesign --install-completion          # tab completion in your shell")

from .runner import EXIT_FAILED, EXIT_INVALID, EXIT_OK  # noqa: F401


#: --lang: zh, en and every shipped catalogue (src/mechdesign/locale/<lang>.po)
Lang = Enum("Lang", {name: name for name in LANGUAGES}, type=str)


def _index_lang(lang: "Lang | None", jobs) -> str:
    """The language of a batch's index and answer table: --lang, else the report.language the
    briefs share (each brief's language when they all agree), else zh."""
    if lang or not jobs:
        return _base_lang(lang)
    from .i18n import use
    from .runner import brief_language

    found = {brief_language(Path(b)) for b in dict.fromkeys(str(j.brief) for j in jobs)}
    return found.pop() if len(found) == 1 else use("zh")


def _base_lang(lang: "Lang | None") -> str:
    """The base language (zh or en) of --lang for what the command writes itself (an
    index); a variant such as zh_TW also sets its catalogue (:func:`mechdesign.i18n.use`)."""
    from .i18n import use

    return use(lang.value) if lang else "zh"


def _version(value: bool):
    if value:
        typer.echo(f"mechdesign {__version__}")
        raise typer.Exit()


@app.callback()
def main(version: Optional[bool] = typer.Option(None, "--version", callback=_version,
                                                is_eager=True, help="Show the version and exit.")):
    """Mechanism course design reports from YAML briefs."""


def _since_process_start() -> float:
    """Seconds since this process started (the interpreter's start-up and every import
    included), from the kernel's process start time where it tells, else 0."""
    try:
        with open("/proc/self/stat", encoding="ascii") as handle:
            start_ticks = int(handle.read().rsplit(")", 1)[1].split()[19])
        with open("/proc/uptime", encoding="ascii") as handle:
            uptime = float(handle.read().split()[0])
        return max(0.0, uptime - start_ticks / os.sysconf("SC_CLK_TCK"))
    except (OSError, ValueError, IndexError, AttributeError):
        return 0.0


_TERMINAL = None


def _terminal():
    """The stderr terminal of this command (rich on a terminal, plain lines otherwise),
    made on first use: CliRunner swaps sys.stderr per invocation."""
    global _TERMINAL
    from .console import Terminal

    if _TERMINAL is None or _TERMINAL.stream is not sys.stderr:
        _TERMINAL = Terminal(sys.stderr)
    return _TERMINAL


def _err(msg: str) -> None:
    """An error (red on a terminal)."""
    _terminal().error(msg)


def _info(msg: str) -> None:
    _terminal().line(msg)


def _warn(msg: str) -> None:
    _terminal().warning(msg)


# What `run` says on the terminal, in the report's language (the brief's report.language or
# --lang): progress, warnings, the closing line, an interruption.
_SAY = {
    "rendering": N_("      rendering {what}"), "warning": N_("warning: {text}"),
    "done": N_("done in {total:.1f} s (computation {compute:.2f} s)"),
    "interrupted_after": N_("\ninterrupted after the report was written: {path} holds the new, "
                            "complete report"),
    "interrupted": N_("\ninterrupted: nothing was written; an earlier report in the output "
                      "folder is unchanged"),
    "nothing": N_("(nothing was written; run with --debug for the traceback)"),
}


def _words(lang: str) -> dict[str, str]:
    """_SAY in ``lang`` (templates: the caller fills in the fields)."""
    from .i18n import tr

    _ = tr(lang)
    return {key: _(text) for key, text in _SAY.items()}


def _step(what: str, lang: str) -> str:
    """A rendering step's name in ``lang`` ('sheet 1/3: analysis' → '图纸 1/3：机构分析图')."""
    from .i18n import tr

    _ = tr(lang)
    if not _.zh:
        return what
    if what.startswith("sheet "):
        head, _sep, name = what.partition(": ")
        sheets = {"analysis": _.pgettext("sheet", "analysis"), "cam": _.pgettext("sheet", "cam"),
                  "gear": _.pgettext("sheet", "gear"), "kinematic": _.pgettext("sheet", "kinematic"),
                  "cycle": _.pgettext("sheet", "cycle"),
                  "transmission": _.pgettext("sheet", "transmission")}
        # one cam sheet per cam of a machine with several: named by its result key
        word = sheets.get(name, sheets["cam"] if name.endswith("_cam") else name)
        return _.pgettext("rendering step", "sheet {n}: {name}", n=head[6:], name=word)
    if what.startswith("figures: "):            # a long figures step: the figure at hand
        return _.pgettext("rendering step", "figures: {what}", what=what[9:])
    # the rendering steps' names (render/report.py, render/sheets.py)
    steps = {"figures": _.pgettext("rendering step", "figures"),
             "Markdown": _.pgettext("rendering step", "Markdown"),
             "data files (CSV)": _.pgettext("rendering step", "data files (CSV)"),
             "figures and sheets: the last ones":
                 _.pgettext("rendering step", "figures and sheets: the last ones"),
             "figures and sheets: all written":
                 _.pgettext("rendering step", "figures and sheets: all written"),
             "PDF: Markdown → typst (pandoc, in the background)":
                 _.pgettext("rendering step", "PDF: Markdown → typst (pandoc, in the background)"),
             "PDF: typst → report.pdf": _.pgettext("rendering step", "PDF: typst → report.pdf"),
             "Word (pandoc → docx)": _.pgettext("rendering step", "Word (pandoc → docx)")}
    return steps.get(what, what)


def _title(title: str, lang: str) -> str:
    """A stage title '导杆机构设计 / linkage synthesis' in ``lang``."""
    from .render.fmt import in_lang

    return in_lang(title, lang)


@contextmanager
def _terminate_as_interrupt():
    """SIGTERM (a CI job cancelled, `kill`) unwinds like Ctrl-C, so the staging folder is
    removed and the previous report stays as it was."""
    import signal

    def handler(signum, frame):
        raise KeyboardInterrupt

    try:
        previous = signal.signal(signal.SIGTERM, handler)
    except ValueError:  # not the main thread (e.g. inside a test runner's thread)
        yield
        return
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def _parse_formats(text: str) -> tuple[str, ...]:
    from .render.report import FORMATS

    formats = tuple(dict.fromkeys(x.strip().lower() for x in text.split(",") if x.strip()))
    bad = [x for x in formats if x not in FORMATS]
    if bad or not formats:
        raise typer.BadParameter(f"{text!r}: allowed formats are {', '.join(FORMATS)} "
                                 "(comma-separated, e.g. md,pdf; any case)", param_hint="--format")
    return formats


# Options shared by the commands (metavars for people: BRIEF, DIR, N, i/n, LANG, FORMATS).
def _parse_lang(text) -> "Lang":
    """--lang as a :data:`Lang`, case- and separator-insensitive (zh-tw, ZH_TW → zh_TW; EN → en)."""
    from .i18n import canonical

    if isinstance(text, Lang):
        return text
    name = canonical(text)
    if name is None:
        raise typer.BadParameter(f"{text!r}: allowed languages are {', '.join(LANGUAGES)} "
                                 "(any case, - or _)", param_hint="--lang")
    return Lang(name)


def _lang_option(help_text: str):
    return typer.Option(None, "--lang", metavar="LANG", parser=_parse_lang,
                        autocompletion=lambda incomplete: [n for n in LANGUAGES if n.lower().startswith(
                            incomplete.replace("-", "_").lower())],
                        help=f"{help_text} {', '.join(LANGUAGES)} (any case, - or _).")


def _format_option(default: str = "md,pdf", extra: str = ""):
    return typer.Option(default, "--format", "-f", metavar="FORMATS",
                        help="Output formats, comma-separated: md, pdf, docx, dxf, gif (any case)"
                             f"{extra}.")


def _templates_option():
    return typer.Option(None, "--templates", exists=True, file_okay=False, metavar="DIR",
                        help="Folder of report templates to use instead of the shipped ones.")


@app.command(cls=_Command, epilog="Examples:\n\n"
             "  mechdesign run designs/shaper.yaml\n"
             "  mechdesign run designs/shaper.yaml --lang en --format md,pdf,docx -o out/en\n"
             "  mechdesign run designs/class/class.yaml --group 3\n"
             "  mechdesign run designs/shaper.yaml --format md,pdf,dxf --timings")
@_one_paragraph_per_line
def run(
    brief: Path = typer.Argument(..., exists=True, dir_okay=False, readable=True, metavar="BRIEF",
                                 help="Design brief (YAML), e.g. designs/shaper.yaml."),
    out: Optional[Path] = typer.Option(None, "--out", "-o", file_okay=False, metavar="DIR",
                                       help="Output folder (default: out/BRIEF-NAME/, "
                                            "out/BRIEF-NAME-gGROUP/ for a group)."),
    group: Optional[str] = typer.Option(None, "--group", "-g", metavar="GROUP",
                                        help="Data group (分组) of the brief's `groups` table "
                                             "(default: the table's default)."),
    lang: Optional[Lang] = _lang_option("Report language (default: the brief's "
                                        "report.language):"),
    formats: str = _format_option(extra="; pdf and dxf include the drawing sheets"),
    templates: Optional[Path] = _templates_option(),
    debug: bool = typer.Option(False, "--debug", metavar=FLAG,
                               help="Show Python tracebacks on errors."),
    timings: bool = typer.Option(False, "--timings", metavar=FLAG,
                                 help="Start every progress line with the seconds since the "
                                      "program started (imports included)."),
):
    """Compute BRIEF and write its report, results.json, figures and drawing sheets."""
    from .runner import run_one

    from .allocator import prefer_heap

    prefer_heap()
    fmt = _parse_formats(formats)
    # the process's start on the monotonic clock (the same in a forked helper process)
    started = time.perf_counter() - _since_process_start() if timings else 0.0
    term = _terminal()

    def say(text: str) -> None:
        term.line(f"{time.perf_counter() - started:6.2f} s  {text}" if timings else text)

    from .runner import brief_language

    language = brief_language(brief, lang.value if lang else None)
    words = _words(language)

    from .publish import journal_mark, published_since

    mark = journal_mark()
    try:
        with _terminate_as_interrupt(), term.bar(0, brief.name) as bar:
            stages = [0]     # the number of stages (the bar's last step is the rendering)

            def stage_progress(i: int, total: int, title: str) -> None:
                say(f"[{i}/{total}] {_title(title, language)}")
                stages[0] = total
                bar.update(completed=i - 1, total=total + 1, description=_title(title, language))

            def render_progress(what: str) -> None:
                text = words["rendering"].format(what=_step(what, language))
                say(text)
                bar.update(completed=stages[0], description=text.strip())

            outcome = run_one(brief, out_dir=out, lang=lang.value if lang else None, formats=fmt,
                              group=group, templates=templates, stage_progress=stage_progress,
                              render_progress=render_progress,
                              on_warning=lambda text: term.warning(words["warning"].format(text=text)),
                              parallel=True)
    except KeyboardInterrupt:
        done = published_since(mark)
        if done:    # the interrupt came after the new report was complete and in place
            _err(words["interrupted_after"].format(path=done[-1]))
        else:
            _err(words["interrupted"])
        raise typer.Exit(130)
    if outcome.status != "ok":
        if debug and outcome.traceback:
            _err(outcome.traceback.rstrip())
        _err(outcome.message)
        if outcome.status == "failed":
            _err(words["nothing"])
        raise typer.Exit(outcome.exit_code)
    text = words["done"].format(total=outcome.seconds, compute=outcome.compute_seconds)
    if timings:
        say(text)
    else:
        term.success(text)
    for path in outcome.files:
        typer.echo(path)


@app.command(cls=_Command, epilog="Examples:\n\n"
             "  mechdesign batch designs/                       # every example brief\n"
             "  mechdesign batch designs/class/ --answers -o out/class\n"
             "  mechdesign batch designs/ --shard 2/4 -o out     # CI: then mechdesign merge out\n"
             "  mechdesign batch designs/ --groups all --jobs 2 --format md")
@_one_paragraph_per_line
def batch(
    paths: list[Path] = typer.Argument(..., metavar="BRIEF_OR_DIR...",
                                       help="Briefs and folders of briefs (*.yaml, searched "
                                            "recursively), e.g. designs/ or class/*.yaml."),
    groups: Optional[str] = typer.Option(None, "--groups", metavar="GROUPS",
                                         help="Which data groups to run: default (each brief's "
                                              "default), all, or labels such as 1,3,III "
                                              "(default: default; all with --answers)."),
    answers: bool = typer.Option(False, "--answers", metavar=FLAG,
                                 help="Also write answers.md and answers.csv: every group's "
                                      "headline results with the student's name and number."),
    jobs: Optional[int] = typer.Option(None, "--jobs", "-j", metavar="N",
                                       help="Runs at once, in worker processes, N ≥ 1 "
                                            "(default: the number of CPUs)."),
    shard_text: Optional[str] = typer.Option(None, "--shard", metavar="i/n",
                                             help="Run only shard i of n (deterministic), to "
                                                  "split a class across CI machines."),
    out: Path = typer.Option(Path("out"), "--out", "-o", file_okay=False, metavar="DIR",
                             help="Output folder: one sub-folder per run, plus index.md and "
                                  "index.json."),
    lang: Optional[Lang] = _lang_option("Report language (default: each brief's "
                                        "report.language):"),
    formats: str = _format_option(),
    templates: Optional[Path] = _templates_option(),
):
    """Run many briefs (and their groups) in parallel and write an index of the reports.

    With --answers also the answer table of every group. Continues past failing briefs;
    exit 0 when every run succeeded, 2 when a brief was invalid (or its design
    infeasible), 1 when a report failed otherwise."""
    from .allocator import prefer_heap
    from .i18n import tr
    from .batch import (BatchError, Progress, answers_document, collect_briefs, default_jobs,
                        exit_code, index_document, parse_shard, plan_jobs, run_batch, shard,
                        write_answers, write_index)

    if jobs is not None and jobs < 1:
        raise typer.BadParameter(f"{jobs}: N must be at least 1", param_hint="--jobs")
    prefer_heap()   # inherited by the forked workers
    fmt = _parse_formats(formats)
    try:
        which = parse_shard(shard_text)
        planned = plan_jobs(collect_briefs(paths), groups or ("all" if answers else "default"))
    except BatchError as exc:
        _err(f"error: {exc}")
        raise typer.Exit(EXIT_INVALID)
    selected = shard(planned, which)
    n_jobs = jobs or default_jobs()
    index_lang = _index_lang(lang, selected)
    _ = tr(index_lang)
    where = _(" (shard {i}/{n} of {total})", i=which[0], n=which[1],
              total=len(planned)) if which else ""
    fields = dict(n=len(selected), where=where, k=min(n_jobs, max(len(selected), 1)), out=out)
    if len(selected) == 1:
        _info(_("{n} run{where}, {k} at a time → {out}/", **fields))
    else:
        _info(_("{n} runs{where}, {k} at a time → {out}/", **fields))
    progress = Progress(len(selected), sys.stderr, lang=index_lang)
    start = time.perf_counter()
    try:
        results = run_batch(selected, out, jobs_n=n_jobs, lang=lang.value if lang else None,
                            formats=fmt, templates=templates, on_result=progress.update)
    except KeyboardInterrupt:
        progress.close()
        _err(_("\ninterrupted: finished reports are in place; unfinished ones were not written"))
        raise typer.Exit(130)
    finally:
        progress.close()
    doc = index_document(selected, results, out, which)
    stem = "index" if which is None else f"index.shard-{which[0]}-of-{which[1]}"
    written = write_index(doc, out, index_lang, stem)
    if answers:
        written += write_answers(answers_document(doc), out, index_lang,
                                 "answers" if which is None else
                                 f"answers.shard-{which[0]}-of-{which[1]}")
    t = doc["totals"]
    summary = _("{ok} ok, {invalid} invalid, {failed} failed in {seconds:.1f} s", ok=t["ok"],
                invalid=t["invalid"], failed=t["failed"], seconds=time.perf_counter() - start)
    (_terminal().success if t["ok"] == t["runs"] else _err)(summary)
    for path in written:
        typer.echo(str(path))
    raise typer.Exit(exit_code(results))


@app.command(cls=_Command, epilog="Examples:\n\n"
             "  mechdesign merge out                 # index.shard-*-of-n.* → index.md, index.json\n"
             "  mechdesign merge out --lang en")
@_one_paragraph_per_line
def merge(
    folder: Path = typer.Argument(..., exists=True, file_okay=False, metavar="DIR",
                                  help="The batch output folder holding every shard's "
                                       "index.shard-i-of-n.json (and the run folders)."),
    lang: Optional[Lang] = _lang_option("Language of index.md (default zh):"),
):
    """Merge the indexes of a sharded batch (--shard i/n) into the one an unsharded run writes.

    Writes index.md and index.json (and answers.md/answers.csv when the shards wrote
    answers) into DIR; every shard 1…n must be there. Exit code as `batch` would give for
    all the runs together (0 all ok, 2 an invalid brief, 1 a failed report)."""
    from .batch import BatchError, merge_shards

    try:
        written, totals, code = merge_shards(folder, _base_lang(lang))
    except BatchError as exc:
        _err(f"error: {exc}")
        raise typer.Exit(EXIT_INVALID)
    _info(f"merged {totals['runs']} runs: {totals['ok']} ok, {totals['invalid']} invalid, "
          f"{totals['failed']} failed")
    for path in written:
        typer.echo(str(path))
    raise typer.Exit(code)


@app.command(cls=_Command, epilog="Examples:\n\n"
             "  mechdesign watch designs/shaper.yaml                 # md and pdf into out/shaper/\n"
             "  mechdesign watch my.yaml --format md --lang en -o out/my\n"
             "  mechdesign watch designs/class/class.yaml --group 3 --templates my-templates/")
@_one_paragraph_per_line
def watch(
    brief: Path = typer.Argument(..., exists=True, dir_okay=False, readable=True, metavar="BRIEF",
                                 help="Design brief (YAML) to watch."),
    out: Optional[Path] = typer.Option(None, "--out", "-o", file_okay=False, metavar="DIR",
                                       help="Output folder (default as for run)."),
    group: Optional[str] = typer.Option(None, "--group", "-g", metavar="GROUP",
                                        help="Data group of the brief's `groups` table."),
    lang: Optional[Lang] = _lang_option("Report language (default: the brief's "
                                        "report.language):"),
    formats: str = _format_option(),
    templates: Optional[Path] = _templates_option(),
):
    """Re-run BRIEF on every save of it, its class table or the templates (Ctrl-C ends).

    The program stays loaded, so a re-run costs only the computation and the rendering.
    After each run it prints which headline results changed (old → new); an invalid
    edit prints its messages and the watch goes on. The report is replaced only when
    complete, as by `run`."""
    from .allocator import prefer_heap
    from .watch import watch_brief

    prefer_heap()
    fmt = _parse_formats(formats)
    with _terminate_as_interrupt():     # SIGTERM ends the watch as Ctrl-C does
        code = watch_brief(brief, out=out, group=group, lang=lang.value if lang else None,
                           formats=fmt, templates=templates, terminal=_terminal(),
                           echo=typer.echo)
    raise typer.Exit(code)


#: The example brief each machine's starter (`mechdesign new`) is copied from (registry).
EXAMPLES = Lookup(lambda e: e.example)


@app.command(cls=_Command, epilog="Examples:\n\n"
             "  mechdesign check designs/*.yaml\n"
             "  mechdesign check my.yaml --lang en")
@_one_paragraph_per_line
def check(
    briefs: list[Path] = typer.Argument(..., metavar="BRIEF...",
                                        help="Design briefs (YAML) to validate."),
    lang: Optional[Lang] = _lang_option("Language of the messages (default: each brief's "
                                        "report.language):"),
):
    """Validate briefs without computing anything (fast: for editors and pre-commit).

    A brief with a `groups` table is checked with every group applied. Prints one line
    per brief; exit 0 when all are valid, 2 when any is not. Only the brief is checked
    (fields and the rules between them): whether its data admit a design (a linkage
    synthesis, an assembly) is asked by `mechdesign run`."""
    from .brief.loader import BriefError, brief_groups, load_variant, read_brief_data
    from .runner import brief_language

    bad = 0
    for path in briefs:
        try:
            data = read_brief_data(path)       # read once: its language, every group checked on it
        except BriefError as exc:
            bad += 1
            _err(exc.text(brief_language(path, lang.value if lang else None)))
            continue
        language = brief_language(path, lang.value if lang else None, data=data)
        try:
            labels = brief_groups(path, data=data)
        except BriefError as exc:
            bad += 1
            _err(exc.text(language))
            continue
        variant, shown = None, []
        for label in (None, *labels):          # as run by default, then every group
            if variant is not None and label == variant.group:
                continue
            try:
                checked = load_variant(path, label, data=data)
                variant = variant or checked
            except BriefError as exc:          # each group's problems, each message once
                text = exc.text(language)
                if text not in shown:
                    shown.append(text)
                    _err(text)
        if shown or variant is None:
            bad += 1
            continue
        groups = f", groups {', '.join(labels)}" if labels else ""
        typer.echo(f"ok: {path} ({variant.brief.machine}{groups})")
    if bad:
        _err(f"{bad} of {len(briefs)} brief{'s' if len(briefs) != 1 else ''} invalid")
        raise typer.Exit(EXIT_INVALID)


@app.command(cls=_Command, epilog="Examples:\n\n"
             "  mechdesign schema > brief.schema.json\n"
             "  mechdesign schema cam")
@_one_paragraph_per_line
def schema(
    machine: Optional[str] = typer.Argument(None, metavar="MACHINE",
                                            help="Only this machine's brief (default: all, "
                                                 "chosen by the `machine` field)."),
):
    """Print the JSON Schema of the design brief (for editors, e.g. VS Code's YAML extension)."""
    import json

    from .brief.loader import BRIEF_MODELS, brief_schema

    if machine is not None and machine not in BRIEF_MODELS:
        _err(f"machine {machine!r}: one of {', '.join(sorted(BRIEF_MODELS))}")
        raise typer.Exit(EXIT_INVALID)
    typer.echo(json.dumps(brief_schema(machine), ensure_ascii=False, indent=1))


def starter_text(text: str, example: str, target: Path) -> str:
    """The example brief's text as a starter at ``target``: its comments' commands
    (`mechdesign run designs/shaper.yaml`, `mechdesign run shaper.yaml --group II`) name
    the file written."""
    import re
    import shlex

    where = shlex.quote(str(target))
    return re.sub(rf"(mechdesign (?:run|check|watch)) (?:designs/)?{re.escape(example)}\b",
                  lambda m: f"{m.group(1)} {where}", text)


@app.command(cls=_Command, epilog="Examples:\n\n"
             "  mechdesign new shaper                 # writes ./shaper.yaml\n"
             "  mechdesign new cam -o briefs/my_cam.yaml")
@_one_paragraph_per_line
def new(
    machine: str = typer.Argument(..., metavar="MACHINE",
                                  help="Machine of the starter brief, e.g. shaper, cam, drive."),
    out: Optional[Path] = typer.Option(None, "--out", "-o", dir_okay=False, metavar="FILE",
                                       help="File to write (default: MACHINE.yaml here)."),
):
    """Write a commented starter brief for MACHINE (the shipped example, to edit)."""
    from importlib import resources

    from .fileio import write_text

    if machine not in EXAMPLES:
        _err(f"machine {machine!r}: one of {', '.join(sorted(EXAMPLES))}")
        raise typer.Exit(EXIT_INVALID)
    target = out if out is not None else Path(f"{machine}.yaml")
    if target.exists():
        _err(f"{target} exists; choose another name with --out (nothing was written)")
        raise typer.Exit(EXIT_INVALID)
    text = resources.files("mechdesign.designs").joinpath(EXAMPLES[machine]).read_text(encoding="utf-8")
    try:
        write_text(target, starter_text(text, EXAMPLES[machine], target), encoding="utf-8",
                   parents=False)
    except OSError as exc:
        _err(f"{target}: cannot be written: {exc.strerror}")
        raise typer.Exit(EXIT_FAILED)
    typer.echo(str(target))
    import shlex

    where = shlex.quote(str(target))
    _info(f"wrote a starter {machine} brief to {target}; edit it, then: "
          f"mechdesign check {where} && mechdesign run {where}")


def entry() -> None:
    """The `mechdesign` console script: the app, with an unexpected error shown as one line
    (its type and text; the traceback with --debug or MECHDESIGN_DEBUG=1), exit 1."""
    try:
        app(prog_name="mechdesign")
    except SystemExit:
        raise
    except KeyboardInterrupt:
        _err("interrupted")
        sys.exit(130)
    except Exception as exc:  # noqa: BLE001 - the last guard: never a bare traceback
        if "--debug" in sys.argv[1:] or os.environ.get("MECHDESIGN_DEBUG"):
            raise
        _err(f"internal error: {type(exc).__name__}: {exc} (run with --debug, or "
             "MECHDESIGN_DEBUG=1, for the traceback)")
        sys.exit(EXIT_FAILED)


if __name__ == "__main__":  # pragma: no cover
    entry()
