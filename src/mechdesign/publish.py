"""Publishing a run's files into its output folder: own only your files.

A run renders everything into a staging folder inside the output folder; :func:`publish`
then moves the finished files into place. The output folder may be any folder the user
names (``--out .``), so publishing follows three rules:

* **A manifest** (:data:`MANIFEST`, a small JSON file in the output folder) lists every
  file the last run published there. A new run replaces the files it writes again and
  removes the files of the manifest it does not write again (an ``md`` run after an
  ``md,pdf`` run removes the old report.pdf: no stale report beside a newer one). Nothing
  else in the folder is ever touched: a file or folder the run would have to replace but
  that the manifest does not list (the user's own report.md, a figures/ file of the same
  name) stops the run before anything moves (:class:`ForeignFiles`).
* **Interrupts wait.** SIGINT and SIGTERM that arrive while the files move are held back
  and raised when the move is complete, as :class:`InterruptedAfterPublish` (a
  KeyboardInterrupt), so an interrupt never leaves half an old and half a new report, and
  the message after it can say truthfully that the new report is complete
  (:func:`published_since` tells what a run published). A hard kill (SIGKILL, power loss)
  cannot be held back: the manifest is first written as the union of the old and the new
  files, so even then every file of either run stays known as the tool's own and the next
  run tidies it.
* **Dead runs' staging folders are removed** by the next run into the folder: their names
  carry the owning process id (:data:`STAGING_PREFIX` ``<pid>-…``), and a folder whose
  process no longer exists is deleted (one of an older version, without a pid, when it is
  more than an hour old).
"""
from __future__ import annotations

import contextlib
import json
import os
import re
import shutil
import signal
import tempfile
import threading
import time
from pathlib import Path, PurePosixPath
from typing import Iterator

from .fileio import write_text

#: The manifest of the files the last run published in an output folder.
MANIFEST = "mechdesign-files.json"
STAGING_PREFIX = ".mechdesign-staging-"
_LEGACY = (".mechdesign-staging-", ".mechdesign-old-")
_SCHEMA = "mechdesign.files/1"

#: Every folder a publish completed (in this process), in order: see :func:`published_since`.
_JOURNAL: list[Path] = []


class ForeignFiles(Exception):
    """Files in the output folder that the run would replace but did not write."""

    def __init__(self, out_dir: Path, paths: list[str]):
        self.out_dir, self.paths = Path(out_dir), paths
        shown = ", ".join(paths[:5]) + (f" (and {len(paths) - 5} more)" if len(paths) > 5 else "")
        self._fields = dict(out_dir=out_dir, shown=shown, manifest=MANIFEST)
        self.en = self.text("en")
        super().__init__(self.en)

    def text(self, lang: str) -> str:
        from .i18n import tr

        _ = tr(lang)
        if len(self.paths) == 1:
            return _("{out_dir}: {shown} already exists there and was not written by mechdesign "
                     "(not in {manifest}); nothing was changed: choose another --out folder, or "
                     "move those files away", **self._fields)
        return _("{out_dir}: {shown} already exist there and were not written by mechdesign (not "
                 "in {manifest}); nothing was changed: choose another --out folder, or move those "
                 "files away", **self._fields)


class InterruptedAfterPublish(KeyboardInterrupt):
    """An interrupt that arrived while the files moved: it was held back until the new
    report was complete, then raised."""


# --------------------------------------------------------------------------- manifest

def _safe(rel: object) -> str | None:
    """A manifest entry as a relative POSIX path inside the folder (None: refused)."""
    if not isinstance(rel, str) or not rel or "\\" in rel or "\0" in rel:
        return None
    p = PurePosixPath(rel)
    if p.is_absolute() or any(part in ("", ".", "..") for part in p.parts):
        return None
    if p.parts[0] == MANIFEST or p.parts[0].startswith(STAGING_PREFIX):
        return None
    return p.as_posix()


def read_manifest(out_dir: Path) -> set[str]:
    """The files the last run published in ``out_dir`` (empty: none, or an unreadable
    manifest — then nothing there counts as the tool's own)."""
    try:
        data = json.loads((Path(out_dir) / MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return set()
    files = data.get("files") if isinstance(data, dict) else None
    if not isinstance(files, list):
        return set()
    return {s for s in (_safe(f) for f in files) if s is not None}


def _write_manifest(out_dir: Path, files: set[str]) -> None:
    write_text(out_dir / MANIFEST, json.dumps(
        {"schema": _SCHEMA, "note": "files written by mechdesign; a later run into this folder "
                                    "replaces or removes exactly these",
         "files": sorted(files)}, ensure_ascii=False, indent=1) + "\n")


def staged_files(staging: Path) -> list[str]:
    """Every file under ``staging``, as relative POSIX paths."""
    return sorted(p.relative_to(staging).as_posix() for p in staging.rglob("*")
                  if p.is_file() or p.is_symlink())


def foreign(out_dir: Path, names: list[str], owned: set[str] | None = None) -> list[str]:
    """Of ``names`` (relative paths a run writes), those that exist in ``out_dir`` — or
    whose parent folders exist there as files — without being the tool's own."""
    out_dir = Path(out_dir)
    owned = read_manifest(out_dir) if owned is None else owned
    bad = []
    for rel in names:
        parts = PurePosixPath(rel).parts
        for i in range(1, len(parts)):      # a parent folder that is a file
            parent = "/".join(parts[:i])
            if (out_dir / parent).is_file() or (out_dir / parent).is_symlink():
                if parent not in owned:
                    bad.append(parent)
                break
        target = out_dir / rel
        if (target.exists() or target.is_symlink()) and (rel not in owned or target.is_dir()):
            bad.append(rel)
    return sorted(set(bad))


# --------------------------------------------------------------------------- staging

def _pid_alive(pid: int) -> bool:
    if pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    except OSError:
        return True
    return True


def clean_dead_staging(out_dir: Path, legacy_age: float = 3600.0) -> list[Path]:
    """Remove the staging folders of runs that died in ``out_dir`` (their process is gone;
    an older version's, without a pid in the name, after ``legacy_age`` seconds)."""
    removed = []
    try:
        entries = list(Path(out_dir).iterdir())
    except OSError:
        return removed
    for p in entries:
        if not p.is_dir() or p.is_symlink() or not p.name.startswith(_LEGACY):
            continue
        m = re.match(re.escape(STAGING_PREFIX) + r"(\d+)-", p.name)
        if m:
            dead = not _pid_alive(int(m.group(1)))
        else:
            try:
                dead = time.time() - p.stat().st_mtime > legacy_age
            except OSError:
                continue
        if dead:
            shutil.rmtree(p, ignore_errors=True)
            removed.append(p)
    return removed


def make_staging(out_dir: Path) -> Path:
    """A fresh staging folder in ``out_dir`` named after this process (dead runs' folders
    are removed first)."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    clean_dead_staging(out_dir)
    return Path(tempfile.mkdtemp(prefix=f"{STAGING_PREFIX}{os.getpid()}-", dir=out_dir))


# --------------------------------------------------------------------------- interrupts

@contextlib.contextmanager
def held_interrupts() -> Iterator[None]:
    """Hold SIGINT and SIGTERM back while the block runs; when it completes, raise
    :class:`InterruptedAfterPublish` if one arrived (outside the main thread, where
    handlers cannot be set, the block simply runs)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    arrived: list[int] = []

    def hold(signum, frame):
        arrived.append(signum)

    previous = {}
    try:
        for sig in (signal.SIGINT, signal.SIGTERM):
            previous[sig] = signal.signal(sig, hold)
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)
    if arrived:
        raise InterruptedAfterPublish()


# --------------------------------------------------------------------------- publish

def _prune_empty_parents(path: Path, stop: Path) -> None:
    parent = path.parent
    while parent != stop and stop in parent.parents:
        try:
            parent.rmdir()            # only when empty
        except OSError:
            return
        parent = parent.parent


def publish(staging: Path, out_dir: Path) -> list[Path]:
    """Move every file of ``staging`` into ``out_dir`` (see the module's rules) and return
    the top-level paths written (files, and the folders holding files)."""
    staging, out_dir = Path(staging), Path(out_dir)
    new = staged_files(staging)
    old = read_manifest(out_dir)
    clash = foreign(out_dir, new, old)
    if clash:
        raise ForeignFiles(out_dir, clash)
    with held_interrupts():
        _write_manifest(out_dir, old | set(new))
        for rel in new:
            target = out_dir / rel
            target.parent.mkdir(parents=True, exist_ok=True)
            os.replace(staging / rel, target)
        for rel in sorted(old - set(new)):
            target = out_dir / rel
            if target.is_file() or target.is_symlink():
                target.unlink()
                _prune_empty_parents(target, out_dir)
        _write_manifest(out_dir, set(new))
        _JOURNAL.append(out_dir)
    tops = dict.fromkeys(PurePosixPath(rel).parts[0] for rel in new)
    return [out_dir / name for name in tops]


def journal_mark() -> int:
    """A mark for :func:`published_since`."""
    return len(_JOURNAL)


def published_since(mark: int) -> list[Path]:
    """The output folders a publish completed in since ``mark`` (this process)."""
    return list(_JOURNAL[mark:])
