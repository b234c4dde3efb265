"""``mechdesign watch BRIEF``: re-run a brief on every save, with the program kept loaded.

The watcher polls the modification times (and sizes) of the brief, its class table
(``groups: {file: class.csv}``) and every file under ``--templates`` ten times a second
(plain ``os.stat``: no dependency, works on every file system, including network and
container mounts where inotify events do not arrive). A change that has settled (two polls
alike) starts a run.

Every run happens in a child forked from this process (Linux): the imports, done once here
before the first run, are inherited, and this process never runs typst itself, so each run
may fork its figure helpers as ``mechdesign run`` does (typst's threads do not survive a
fork; see render/parallel.py): typst runs in two compiling processes started before the
first run and kept warm, one for the report and one for the drawing sheets (render/pdf.py
``start_service``: typst forgets a layout once ~10 later compilations of its process have
not used it), so a re-run's PDF re-uses the layout of what the edit did not move (an edit that moves page content, or the title and
the student, which every page's set rules hold, is laid out whole again), and every figure
and sheet unchanged by the edit is copied from the render cache (render/cache.py). The
modules a run imported are imported here after it, so the next run inherits them too.
Off Linux the runs happen in this process. A run writes
exactly as ``run`` does (staging folder, moved into place when complete: a failed or
interrupted run leaves the previous report as it was). After a run the watcher prints the
headline results (the machine's summary rows) that changed, old → new; an invalid brief or an
infeasible design prints its messages and the watch goes on. Ctrl-C ends the watch (exit 0).
"""
from __future__ import annotations

import os
import sys
import time
from pathlib import Path
from typing import Callable

from .i18n import N_, tr

POLL_SECONDS = 0.1

_SAY = {
    "watching": N_("watching {files} (save to re-run; Ctrl-C ends)"),
    "changed": N_("{name} changed, re-running …"),
    "done": N_("report updated in {seconds:.1f} s"),
    "same": N_("no headline result changed"),
    "first": N_("headline results:"),
    "changes": N_("headline results changed:"),
    "failed": N_("report not updated (the previous one is unchanged); save a fix to retry"),
    "missing": N_("{name} is missing; waiting for it …"),
    "end": N_("watch ended"),
}


def _words(lang: str) -> dict[str, str]:
    """_SAY in ``lang`` (templates: the caller fills in the fields)."""
    _ = tr(lang)
    return {key: _(text) for key, text in _SAY.items()}


def watched_files(brief: Path, templates: Path | None) -> list[Path]:
    """The brief, its class table (if it names one) and every file under ``templates``."""
    files = [brief]
    try:
        from .brief.loader import read_brief_data

        data = read_brief_data(brief)
        groups = data.get("groups") if isinstance(data, dict) else None
        if isinstance(groups, dict) and isinstance(groups.get("file"), str):
            files.append(brief.parent / groups["file"].strip())
    except Exception:  # noqa: BLE001 - an unreadable brief is watched alone; its run says why
        pass
    if templates is not None and templates.is_dir():
        files += sorted(p for p in templates.rglob("*") if p.is_file())
    return files


def snapshot(files: list[Path]) -> dict[Path, tuple[int, int] | None]:
    """(mtime in ns, size) of each file, None for a missing one."""
    state = {}
    for path in files:
        try:
            st = path.stat()
            state[path] = (st.st_mtime_ns, st.st_size)
        except OSError:
            state[path] = None
    return state


def summary_changes(before: dict[str, str], after: dict[str, str]) -> list[str]:
    """``label: old → new`` for every headline result that changed, appeared or went."""
    lines = []
    for label, value in after.items():
        old = before.get(label)
        if old != value:
            lines.append(f"  {label}: {old if old is not None else '—'} → {value}")
    for label, old in before.items():
        if label not in after:
            lines.append(f"  {label}: {old} → —")
    return lines


def _preload(brief: Path, group: str | None) -> None:
    """Import what a run of this brief needs, once, before the first run (the children
    inherit it). Never runs typst."""
    import importlib

    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot  # noqa: F401

        from . import runner  # noqa: F401
        from .brief.loader import load_variant
        from .machines import get_machine
        from .render import report, sheets  # noqa: F401

        machine = get_machine(load_variant(brief, group).brief.machine)
        importlib.import_module(machine.report_module)
    except Exception:  # noqa: BLE001 - a brief invalid for now: its run reports it
        pass


def _warm_caches() -> None:
    """Compute, once here, what every run's render cache keys need and would otherwise
    compute again in each forked run (render/cache.py: the package's code fingerprint,
    ~0.1 s; the figure and typst environments, a stat of every font file)."""
    try:
        from .render import cache

        if cache.folder() is not None:
            cache._code_fingerprint()
            cache._figure_environment()
            cache._typst_environment()
    except Exception:  # noqa: BLE001 - a warm-up only
        pass


#: modules a run may import that this process must not (typst's threads do not survive a
#: fork: it stays in the compiling process and the runs)
_NOT_HERE = ("typst",)


def _adopt_imports(names: list[str]) -> None:
    """Import here the modules the last run imported (its figures' and stages' modules,
    scipy.spatial for a cam …), so the next runs inherit them instead of importing them
    again (~0.3–0.5 s of each re-run otherwise)."""
    import importlib

    for name in names:
        if name in sys.modules or name.split(".")[0] in _NOT_HERE or name == "__main__":
            continue
        try:
            importlib.import_module(name)
        except Exception:  # noqa: BLE001 - a module that will not import here: skip it
            pass


def _can_fork() -> bool:
    return sys.platform.startswith("linux") and hasattr(os, "fork")


def _run_in_child(kwargs: dict):
    """One run in a forked child: its Outcome (None if the child died) and the names of
    the modules it imported."""
    import multiprocessing as mp

    from .runner import run_one

    ctx = mp.get_context("fork")
    recv, send = ctx.Pipe(duplex=False)
    before = set(sys.modules)

    def child():
        try:
            outcome = run_one(**kwargs)
        except KeyboardInterrupt:
            os._exit(130)
        send.send(outcome)
        send.send(sorted(set(sys.modules) - before))
        send.close()
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(0)

    proc = ctx.Process(target=child, daemon=True)
    proc.start()
    send.close()
    outcome, imported = None, []
    try:
        outcome = recv.recv()
        imported = recv.recv()
    except EOFError:
        pass
    finally:
        proc.join()
    return outcome, imported


def watch_brief(brief: Path, *, out: Path | None = None, group: str | None = None,
                lang: str | None = None, formats: tuple[str, ...] = ("md", "pdf"),
                templates: Path | None = None, terminal=None,
                echo: Callable[[str], None] = print, max_runs: int | None = None,
                poll: float = POLL_SECONDS) -> int:
    """Watch ``brief`` and re-run it on every change until Ctrl-C (or ``max_runs`` runs,
    for tests); return the exit code (0)."""
    from .console import Terminal
    from .runner import brief_language, run_one

    term = terminal or Terminal()
    brief = Path(brief)
    kwargs = dict(brief=brief, out_dir=out, lang=lang, formats=formats, group=group,
                  templates=templates, parallel=True)
    runs = 0
    summary: dict[str, str] | None = None
    language = brief_language(brief, lang)
    words = _words(language)
    stop_typst = None
    try:
        _preload(brief, group)
        _warm_caches()
        if _can_fork():
            # warm typst processes for every run (render/pdf.py): a re-run lays out only
            # what changed; started before any run, so this process stays fork-safe
            from .render.pdf import start_service

            stop_typst = start_service()
        files = watched_files(brief, templates)
        shown = [str(p) for p in files[:2]] + ([f"{templates}/"] if templates else [])
        term.line(words["watching"].format(files=", ".join(shown)))
        state = snapshot(files)
        reason = None
        while True:
            if state.get(brief) is None:
                term.warning(words["missing"].format(name=brief))
            else:
                if reason is not None:
                    term.line(words["changed"].format(name=reason.name))
                language = brief_language(brief, lang)
                words = _words(language)
                start = time.perf_counter()
                imported: list[str] = []
                if _can_fork():
                    outcome, imported = _run_in_child(kwargs)
                else:
                    outcome = run_one(**kwargs)
                runs += 1
                summary = _report(outcome, summary, term, echo, words,
                                  time.perf_counter() - start)
                _adopt_imports(imported)       # for the next run, while the user edits
                if max_runs is not None and runs >= max_runs:
                    return 0
            # wait for the next settled change
            files = watched_files(brief, templates)
            state = {**snapshot(files), **{p: v for p, v in state.items() if p in files}}
            while True:
                time.sleep(poll)
                now = snapshot(files)
                if now != state:
                    time.sleep(poll / 2)     # an editor may write in several steps
                    if snapshot(files) == now:
                        changed = [p for p in files if now.get(p) != state.get(p)]
                        reason = changed[0] if changed else brief
                        state = now
                        break
    except KeyboardInterrupt:
        term.line("\n" + words["end"])
        return 0
    finally:
        if stop_typst is not None:
            stop_typst()


def _report(outcome, summary, term, echo, words, seconds) -> dict[str, str] | None:
    """Print what a run did: the messages of a failed one, else the files and the headline
    results (all after the first run, then only those that changed)."""
    if outcome is None:
        term.error("the run's process died; save again to retry")
        term.warning(words["failed"])
        return summary
    for text in outcome.warnings:
        term.warning(text)
    if outcome.status != "ok":
        term.error(outcome.message)
        term.warning(words["failed"])
        return summary
    now = {label: value for label, value in outcome.summary}
    term.success(words["done"].format(seconds=seconds))
    if summary is None:
        if now:
            term.line(words["first"])
            for label, value in now.items():
                term.line(f"  {label}: {value}")
        for path in outcome.files:
            echo(path)
    else:
        lines = summary_changes(summary, now)
        if lines:
            term.line(words["changes"])
            for text in lines:
                term.line(text, "bold")
        else:
            term.line(words["same"])
    return now
