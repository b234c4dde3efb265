"""Many briefs (and their data groups) at once, in parallel worker processes.

``mechdesign batch designs/ --groups all --jobs 4`` plans one run per brief and group,
optionally keeps one deterministic shard of them (``--shard 2/5`` for a CI matrix),
runs them in a process pool (each run exactly as ``mechdesign run`` would, into its
own folder), shows progress, and writes an index (``index.md`` and ``index.json``) with
every run's status, key results and links to its report. A failing brief does not stop
the others.
"""
from __future__ import annotations

import json
import os
import sys
import time
import warnings
from collections import Counter
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import Callable, Iterable

from .fileio import write_text
from .i18n import tr
from .runner import EXIT_FAILED, EXIT_INVALID, EXIT_OK, Outcome, run_one, safe_label

BRIEF_SUFFIXES = (".yaml", ".yml")


@dataclass(frozen=True)
class Job:
    """One run of the batch: a brief, a group of it (None: its default / as written) and
    the folder name of its report inside the batch's output folder."""

    brief: str
    group: str | None
    run_id: str


class BatchError(ValueError):
    """A bad batch command line (no briefs, a bad --shard or --groups)."""


def collect_briefs(paths: Iterable[str | Path]) -> list[Path]:
    """Brief files named or found (recursively, sorted) in the folders named; each once."""
    found: list[Path] = []
    for raw in paths:
        path = Path(raw)
        if path.is_dir():
            found += sorted(p for p in path.rglob("*") if p.suffix in BRIEF_SUFFIXES and p.is_file()
                            and not any(part.startswith(".") for part in p.relative_to(path).parts))
        elif path.exists():
            found.append(path)
        else:
            raise BatchError(f"{raw}: no such file or folder")
    unique = list(dict.fromkeys(found))
    if not unique:
        raise BatchError(f"no briefs (*.yaml) in {', '.join(map(str, paths))}")
    return unique


def parse_shard(text: str | None) -> tuple[int, int] | None:
    """``"i/n"`` (1 ≤ i ≤ n) → (i, n)."""
    if text is None:
        return None
    try:
        i, n = (int(x) for x in text.split("/"))
    except ValueError:
        raise BatchError(f"--shard {text!r}: write i/n, e.g. 2/5 (the second of five shards)") from None
    if not (n >= 1 and 1 <= i <= n):
        raise BatchError(f"--shard {text!r}: i must be between 1 and n, and n at least 1")
    return i, n


def plan_jobs(briefs: list[Path], groups: str = "default") -> list[Job]:
    """One job per brief, or per group (``groups``: default, all, or labels "1,3,III").

    A brief without a groups table runs once as written; with ``groups`` a list of labels,
    a brief that has none of them runs not at all. A brief whose groups table cannot be
    read runs once, so its run reports the problem."""
    from .brief.loader import BriefError, brief_groups

    wanted = None if groups in ("default", "all") else [g.strip() for g in groups.split(",") if g.strip()]
    if wanted is not None and not wanted:
        raise BatchError(f"--groups {groups!r}: all, default, or labels such as 1,3,III")
    jobs: list[tuple[Path, str | None]] = []
    for brief in briefs:
        try:
            labels = brief_groups(brief)
        except BriefError:
            labels = ()
        if groups == "all" and labels:
            jobs += [(brief, label) for label in labels]
        elif wanted is not None:
            jobs += [(brief, label) for label in labels if label in wanted]
            if not labels:
                jobs.append((brief, None))
        else:
            jobs.append((brief, None))
    return _name_jobs(jobs)


def _name_jobs(jobs: list[tuple[Path, str | None]]) -> list[Job]:
    """Folder names: the brief's stem (+ -gLABEL); briefs of the same name in different
    folders are told apart by their parent folders."""
    def name(brief: Path, group: str | None, depth: int) -> str:
        parts = [p for p in brief.parent.parts[len(brief.parent.parts) - depth:] if p not in ("", ".", "/")]
        stem = "_".join(safe_label(p) for p in parts + [brief.stem]) if depth else safe_label(brief.stem)
        return stem if group is None else f"{stem}-g{safe_label(group)}"

    depth = {job: 0 for job in jobs}
    for _ in range(8):
        names = Counter(name(b, g, depth[(b, g)]) for b, g in jobs)
        clashes = [(b, g) for b, g in jobs if names[name(b, g, depth[(b, g)])] > 1]
        if not clashes:
            break
        for job in clashes:
            depth[job] += 1
    out, used = [], Counter()
    for b, g in jobs:
        run_id = name(b, g, depth[(b, g)])
        used[run_id] += 1
        out.append(Job(str(b), g, run_id if used[run_id] == 1 else f"{run_id}-{used[run_id]}"))
    return out


def shard(jobs: list[Job], which: tuple[int, int] | None) -> list[Job]:
    """Shard i of n: every n-th job starting at the i-th (deterministic, balanced)."""
    if which is None:
        return jobs
    i, n = which
    return jobs[i - 1::n]


def _work(job: Job, out_root: str, lang: str | None, formats: tuple[str, ...],
          templates: str | None) -> dict:
    """Worker: one run, never raising; warnings (e.g. typst's) go into the outcome."""
    start = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            outcome = run_one(Path(job.brief), out_dir=Path(out_root) / job.run_id, lang=lang,
                              formats=formats, group=job.group,
                              templates=Path(templates) if templates else None)
        except Exception as exc:  # noqa: BLE001 - an internal error must not stop the batch
            outcome = Outcome(brief=job.brief, group=job.group, status="failed",
                              exit_code=EXIT_FAILED,
                              message=f"{job.brief}: internal error: {type(exc).__name__}: {exc}")
    extra = tuple(str(w.message) for w in caught if "typst" in str(w.message))
    outcome = replace(outcome, warnings=outcome.warnings + extra,
                      seconds=outcome.seconds or time.perf_counter() - start)
    return asdict(outcome)


class Progress:
    """Progress of a batch: on a terminal a live rich bar (runs done of all, elapsed time,
    failures, the last run) with every failed run printed above it; one plain line per
    finished run otherwise (CI logs), ``[i/n] status run-id (s)`` and the first lines of a
    failure's message indented."""

    def __init__(self, total: int, stream=None, tty: bool | None = None, lang: str = "en"):
        from .console import Terminal
        from .i18n import tr

        self._ = tr(lang)
        self.total, self.done, self.failed = total, 0, 0
        self.terminal = Terminal(stream, rich=tty)
        self.stream = self.terminal.stream
        self.tty = self.terminal.rich
        self.start = time.perf_counter()
        self._live = None
        if self.tty and total:
            from rich.progress import (BarColumn, MofNCompleteColumn, Progress as Bar,
                                       TextColumn, TimeElapsedColumn)

            self._live = Bar(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                             TimeElapsedColumn(), TextColumn("{task.fields[status]}"),
                             console=self.terminal.console, auto_refresh=False,
                             redirect_stdout=False, redirect_stderr=False)
            self._task = self._live.add_task("batch", total=total, status="")
            self._live.start()

    def update(self, job: Job, result: dict) -> None:
        self.done += 1
        ok = result["status"] == "ok"
        self.failed += not ok
        secs = result.get("seconds") or 0.0
        _ = self._
        word = {"ok": _.pgettext("batch terminal", "ok"),
                "invalid": _.pgettext("batch terminal", "invalid"),
                "failed": _.pgettext("batch terminal", "failed")}.get(result["status"], result["status"])
        line = f"{word:{6 if word.isascii() else 3}s} {job.run_id} ({secs:.1f} s)"
        first = [] if ok else (result.get("message") or "").strip().splitlines()[:6]
        if self._live is not None:
            if not ok:
                from rich.text import Text

                self._live.console.print(Text(line, style="bold red"))
                for text in first:
                    self._live.console.print(Text(f"    {text}"))
            self._live.update(self._task, completed=self.done,
                              status=_("{failed} failed  last: {run}", failed=self.failed,
                                       run=job.run_id))
            self._live.refresh()
            if self.done >= self.total:
                self.close()
            return
        self.stream.write(f"[{self.done}/{self.total}] {line}\n")
        for text in first:
            self.stream.write(f"    {text}\n")
        self.stream.flush()

    def close(self) -> None:
        """Stop the live bar (it stays on the screen at its last state)."""
        if self._live is not None:
            self._live.stop()
            self._live = None


def run_batch(jobs: list[Job], out_root: Path, *, jobs_n: int = 1, lang: str | None = None,
              formats: tuple[str, ...] = ("md", "pdf"), templates: Path | None = None,
              on_result: Callable[[Job, dict], None] | None = None) -> list[dict]:
    """Run ``jobs`` (``jobs_n`` at a time in worker processes; 1: in this process);
    return their outcomes (as dicts) in the order of ``jobs``."""
    out_root = Path(out_root)
    out_root.mkdir(parents=True, exist_ok=True)
    args = (str(out_root), lang, formats, str(templates) if templates else None)
    results: dict[int, dict] = {}
    if jobs_n <= 1 or len(jobs) <= 1:
        for i, job in enumerate(jobs):
            results[i] = _work(job, *args)
            if on_result:
                on_result(job, results[i])
    else:
        _pooled(jobs, args, jobs_n, results, on_result)
    return [results[i] for i in range(len(jobs))]


# ----------------------------------------------------------------------------- workers
#
# A worker process that dies (killed, out of memory, a crash in a C library) breaks a
# ProcessPoolExecutor: every run still pending in it fails with BrokenProcessPool. So the
# pool reports which runs started (a queue the workers write to); when it breaks, the runs
# that had not started go into a fresh pool untouched, and each run that was running is
# retried once alone, in a process of its own, where its death is its own: then it is
# marked failed with the cause (the signal or exit code).

_STARTED = None


def _context():
    """The start method of the worker processes: a fork server where there is one (a clean,
    single-threaded process the workers are forked from: forking a process that has run
    typst, whose runtime keeps threads, would hang the child), else the platform's default."""
    import multiprocessing as mp

    if "forkserver" in mp.get_all_start_methods():
        ctx = mp.get_context("forkserver")
        ctx.set_forkserver_preload(["mechdesign.batch"])
        return ctx
    return mp.get_context()


def _init_worker(queue) -> None:
    global _STARTED
    _STARTED = queue


def _pool_work(i: int, job: Job, *args) -> dict:
    if _STARTED is not None:
        _STARTED.put(i)
    return _work(job, *args)


def _child(conn, job: Job, args) -> None:
    conn.send(_work(job, *args))
    conn.close()


def _died(job: Job, exitcode: int | None) -> dict:
    import signal

    if exitcode is not None and exitcode < 0:
        try:
            cause = f"killed by {signal.Signals(-exitcode).name}"
        except ValueError:
            cause = f"killed by signal {-exitcode}"
    else:
        cause = f"exit code {exitcode}"
    return asdict(Outcome(
        brief=job.brief, group=job.group, status="failed", exit_code=EXIT_FAILED,
        message=f"{job.brief}: the worker process died twice running it ({cause}; retried once "
                "in a fresh process); the other runs are not affected"))


def _alone(job: Job, args) -> dict:
    """One run in a process of its own: its outcome, or how the process died."""
    ctx = _context()
    recv, send = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=_child, args=(send, job, args), daemon=True)
    proc.start()
    send.close()
    try:
        result = recv.recv()
    except EOFError:
        result = None
    proc.join()
    if result is None:
        from .publish import clean_dead_staging

        clean_dead_staging(Path(args[0]) / job.run_id)
        return _died(job, proc.exitcode)
    return result


def _pooled(jobs: list[Job], args, jobs_n: int, results: dict,
            on_result: Callable[[Job, dict], None] | None) -> None:
    import queue as queue_mod

    ctx = _context()
    pending = list(range(len(jobs)))
    while pending:
        started_q = ctx.SimpleQueue()
        started: set[int] = set()
        broken = False
        with ProcessPoolExecutor(max_workers=min(jobs_n, len(pending)), mp_context=ctx,
                                 initializer=_init_worker, initargs=(started_q,)) as pool:
            futures = {pool.submit(_pool_work, i, jobs[i], *args): i for i in pending}
            try:
                for future in as_completed(futures):
                    i = futures[future]
                    try:
                        results[i] = future.result()
                    except BrokenProcessPool:    # a worker died: sorted out below
                        broken = True
                        continue
                    if on_result:
                        on_result(jobs[i], results[i])
            except KeyboardInterrupt:
                for future in futures:
                    future.cancel()
                raise
        while not started_q.empty():
            try:
                started.add(started_q.get())
            except (EOFError, OSError, queue_mod.Empty):
                break
        left = [i for i in pending if i not in results]
        if not broken or not left:
            break
        running = [i for i in left if i in started]
        # running when the pool broke (none known: every one left, alone, so it ends)
        for i in running or left:
            results[i] = _alone(jobs[i], args)
            if on_result:
                on_result(jobs[i], results[i])
        pending = [i for i in left if i not in results]


def exit_code(results: list[dict]) -> int:
    """0 when every run succeeded; 2 when any brief was invalid; else 1."""
    codes = {r["exit_code"] for r in results}
    if codes <= {EXIT_OK}:
        return EXIT_OK
    return EXIT_INVALID if EXIT_INVALID in codes else EXIT_FAILED


# ----------------------------------------------------------------------------- index
def _relative(path: str, root: Path) -> str:
    try:
        return Path(os.path.relpath(Path(path).resolve(), root.resolve())).as_posix()
    except ValueError:
        return Path(path).as_posix()


def index_document(jobs: list[Job], results: list[dict], out_root: Path,
                   shard_of: tuple[int, int] | None = None) -> dict:
    """The index as plain data (index.json): every run with status, key results, links."""
    runs = []
    for job, r in zip(jobs, results, strict=True):
        files = [_relative(p, out_root) for p in r.get("files", ())]
        links = {Path(f).name: f for f in files if Path(f).suffix in (".pdf", ".md", ".docx", ".json", ".gif")}
        runs.append({
            "id": job.run_id, "brief": Path(job.brief).as_posix(), "group": r.get("group", job.group),
            "machine": r.get("machine") or "", "status": r["status"], "exit_code": r["exit_code"],
            "message": r.get("message") or "", "folder": job.run_id if r["status"] == "ok" else None,
            "links": links, "summary": [list(x) for x in r.get("summary", ())],
            "student": dict(zip(("name", "number", "class"), r.get("student") or ("", "", ""))),
            "warnings": list(r.get("warnings", ())), "seconds": round(r.get("seconds") or 0.0, 2)})
    totals = Counter(r["status"] for r in runs)
    return {"schema": "mechdesign.batch/1", "shard": list(shard_of) if shard_of else None,
            "runs": runs, "totals": {"runs": len(runs), "ok": totals.get("ok", 0),
                                     "invalid": totals.get("invalid", 0),
                                     "failed": totals.get("failed", 0)}}


def _cell(text: str) -> str:
    """Text safe inside a Markdown table cell (shown literally by any Markdown reader)."""
    from .render.fmt import md_text

    return md_text(str(text))


def _student_cell(run: dict) -> str:
    student = run.get("student") or {}
    name, number = student.get("name") or "", student.get("number") or ""
    if not name and not number:
        return "—"
    return _cell(f"{name} ({number})" if number else name)


def index_markdown(doc: dict, lang: str = "zh") -> str:
    """index.md: a table of every run (status, brief, group, key results, links)."""
    _ = tr(lang)
    t = doc["totals"]
    head = (_("# Batch index") + "\n\n" +
            _("{runs} runs: {ok} ok, {invalid} invalid brief or infeasible design, {failed} failed.",
              runs=t["runs"], ok=t["ok"], invalid=t["invalid"], failed=t["failed"]) + "\n\n")
    if doc.get("shard"):
        i, n = doc["shard"]
        head += _("This index is shard {i} of {n}.", i=i, n=n) + "\n\n"
    status_text = {"ok": _.pgettext("batch status", "✓ ok"),
                   "invalid": _.pgettext("batch status", "✗ invalid"),
                   "failed": _.pgettext("batch status", "✗ failed")}
    cols = [_.pgettext("batch column", "Status"), _.pgettext("batch column", "Brief"),
            _.pgettext("batch column", "Group"), _.pgettext("batch column", "Student (number)"),
            _.pgettext("batch column", "Machine"), _.pgettext("batch column", "Key results"),
            _.pgettext("batch column", "Report"), _.pgettext("batch column", "Time [s]")]
    lines = ["| " + " | ".join(cols) + " |", "|" + "|".join([":--"] * 7 + ["--:"]) + "|"]
    problems = []
    for run in doc["runs"]:
        summary = "; ".join(f"{_cell(k)} = {_cell(v)}" for k, v in run["summary"]) or "—"
        links = " ".join(f"[{name.rsplit('.', 1)[-1].upper()}](<{path}>)"
                         for name, path in sorted(run["links"].items())
                         if name in ("report.pdf", "report.md", "report.docx")) or "—"
        warn = f" ({len(run['warnings'])} ⚠)" if run["warnings"] else ""
        lines.append("| " + " | ".join([
            status_text.get(run["status"], run["status"]) + warn, _cell(run["brief"]),
            _cell(run["group"]) if run["group"] is not None else "—", _student_cell(run),
            _cell(run["machine"] or "—"),
            summary, links, f"{run['seconds']:.1f}"]) + " |")
        if run["status"] != "ok":
            problems.append(f"### {_cell(run['id'])}\n\n```\n{run['message'].replace('```', '`​``')}\n```\n")
    body = head + "\n".join(lines) + "\n"
    if problems:
        body += "\n" + _("## Problems") + "\n\n" + "\n".join(problems)
    return body


def write_index(doc: dict, out_root: Path, lang: str = "zh", stem: str = "index") -> list[Path]:
    """Write ``stem``.json and ``stem``.md into ``out_root`` (each atomically)."""
    paths = []
    for name, text in ((f"{stem}.json", json.dumps(doc, ensure_ascii=False, indent=1) + "\n"),
                       (f"{stem}.md", index_markdown(doc, lang))):
        paths.append(write_text(out_root / name, text, encoding="utf-8"))
    return paths


def default_jobs() -> int:
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


# ----------------------------------------------------------------------------- answers
def answers_document(index: dict) -> dict:
    """The teacher's answer table from a batch index: one row per run with its group, the
    student's name, number and class, its status and the headline results (the machines'
    registry ``summary`` rows, as the index shows them), columns in first-seen order."""
    columns: list[str] = []
    rows = []
    for run in index["runs"]:
        values = {}
        for label, value in run["summary"]:
            if label not in columns:
                columns.append(label)
            values[label] = value
        student = run.get("student") or {}
        rows.append({"group": run["group"], "name": student.get("name", ""),
                     "number": student.get("number", ""), "class": student.get("class", ""),
                     "brief": run["brief"], "status": run["status"], "results": values})
    return {"columns": columns, "rows": rows}


def answers_markdown(doc: dict, lang: str = "zh") -> str:
    """answers.md: the answer table (Markdown)."""
    _ = tr(lang)
    head = [_.pgettext("batch column", "Group"), _.pgettext("batch column", "Name"),
            _.pgettext("batch column", "Number"), _.pgettext("batch column", "Class"),
            _.pgettext("batch column", "Brief"), _.pgettext("batch column", "Status")]
    status_text = {"ok": "✓", "invalid": _.pgettext("batch status", "✗ invalid"),
                   "failed": _.pgettext("batch status", "✗ failed")}
    lines = [_("# Answer table") + "\n",
             _("The headline results of every group, to check the students' work against.") + "\n",
             "| " + " | ".join(head + [_cell(c) for c in doc["columns"]]) + " |",
             "|" + "|".join([":--"] * len(head) + ["--:"] * len(doc["columns"])) + "|"]
    for row in doc["rows"]:
        cells = [row["group"] if row["group"] is not None else "—", row["name"] or "—",
                 row["number"] or "—", row["class"] or "—", row["brief"]]
        lines.append("| " + " | ".join([_cell(c) for c in cells]
                                       + [status_text.get(row["status"], row["status"])]
                                       + [_cell(row["results"].get(c, "—")) for c in doc["columns"]])
                     + " |")
    return "\n".join(lines) + "\n"


def write_answers(doc: dict, out_root: Path, lang: str = "zh", stem: str = "answers") -> list[Path]:
    """Write ``stem``.md and ``stem``.csv (UTF-8 with a BOM, so Excel reads the Chinese)
    into ``out_root``, each atomically."""
    import csv

    from .fileio import atomic_open

    md = write_text(out_root / f"{stem}.md", answers_markdown(doc, lang), encoding="utf-8")
    path = out_root / f"{stem}.csv"
    _ = tr(lang)
    head = [_.pgettext("answers csv", "group"), _.pgettext("answers csv", "name"),
            _.pgettext("answers csv", "number"), _.pgettext("answers csv", "class"),
            _.pgettext("answers csv", "brief"), _.pgettext("answers csv", "status")]
    with atomic_open(path, "w", encoding="utf-8-sig", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(head + doc["columns"])
        for row in doc["rows"]:
            writer.writerow([row["group"] or "", row["name"], row["number"], row["class"],
                             row["brief"], row["status"]]
                            + [row["results"].get(c, "") for c in doc["columns"]])
    return [md, path]


# ----------------------------------------------------------------------------- merge
def _shard_indexes(folder: Path) -> tuple[int, dict[int, dict]]:
    """The shard indexes ``index.shard-i-of-n.json`` in ``folder``: n and {i: index}."""
    import re

    found: dict[int, dict[int, Path]] = {}
    for path in sorted(Path(folder).glob("index.shard-*-of-*.json")):
        match = re.fullmatch(r"index\.shard-(\d+)-of-(\d+)\.json", path.name)
        if match:
            found.setdefault(int(match.group(2)), {})[int(match.group(1))] = path
    if not found:
        raise BatchError(f"{folder}: no shard indexes (index.shard-i-of-n.json) to merge")
    if len(found) > 1:
        raise BatchError(f"{folder}: shard indexes of different counts n ({', '.join(map(str, sorted(found)))}); "
                         "keep the shards of one batch only")
    (n, paths), = found.items()
    missing = [i for i in range(1, n + 1) if i not in paths]
    if missing:
        raise BatchError(f"{folder}: shard{'s' if len(missing) > 1 else ''} "
                         f"{', '.join(f'{i}/{n}' for i in missing)} missing "
                         f"(index.shard-{missing[0]}-of-{n}.json); run them or copy their output here")
    docs = {}
    for i, path in paths.items():
        try:
            docs[i] = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            raise BatchError(f"{path}: cannot be read as a batch index: {exc}") from None
        if docs[i].get("schema") != "mechdesign.batch/1" or docs[i].get("shard") != [i, n]:
            raise BatchError(f"{path}: not the index of shard {i}/{n} of a mechdesign batch")
    return n, docs


def merge_index(docs: dict[int, dict], n: int) -> dict:
    """The index an unsharded batch writes, from its n shards' indexes: shard i holds the
    runs i, i + n, i + 2n, … of the plan (:func:`shard`), so the plan's order is rebuilt by
    taking the k-th run of every shard in turn."""
    runs = []
    for k in range(max(len(d["runs"]) for d in docs.values())):
        for i in range(1, n + 1):
            if k < len(docs[i]["runs"]):
                runs.append(docs[i]["runs"][k])
    totals = Counter(r["status"] for r in runs)
    return {"schema": "mechdesign.batch/1", "shard": None, "runs": runs,
            "totals": {"runs": len(runs), "ok": totals.get("ok", 0),
                       "invalid": totals.get("invalid", 0), "failed": totals.get("failed", 0)}}


def merge_shards(folder: Path, lang: str = "zh") -> tuple[list[Path], dict, int]:
    """Merge ``folder``'s shard indexes into index.json/index.md (and, when the shards
    wrote answers, answers.md/answers.csv); return the files written, the totals and the
    exit code the unsharded batch would have had."""
    folder = Path(folder)
    n, docs = _shard_indexes(folder)
    doc = merge_index(docs, n)
    written = write_index(doc, folder, lang, "index")
    if any((folder / f"answers.shard-{i}-of-{n}.md").exists() for i in docs):
        written += write_answers(answers_document(doc), folder, lang, "answers")
    return written, doc["totals"], exit_code(doc["runs"])
