"""Save figures in a second process while the next one is drawn.

Drawing a report is mostly matplotlib laying out text and encoding images, one figure
after another on one core. Inside :func:`background_saves`, :func:`save` hands a
finished figure to a forked child process (it inherits the figure as it is, nothing is
pickled), so this process goes on building the next one; a figure finished while the
child is busy is saved by this process itself. Work that uses typst (the drawing sheets)
gets a child of its own (:func:`save_apart`). Two cores are then both at work, whatever a
machine's report module draws, and every figure is drawn once.

A child never returns into the caller's stack: it saves, reports a failure through a
pipe and leaves with ``os._exit``, so no ``finally`` of the parent (the staging folder's
cleanup) runs twice. Leaving the context waits for the children and raises their
errors; an exception or an interrupt in the parent kills them first. Nothing here is
used outside rendering. Off Linux (Windows has no ``fork``; macOS's system libraries are
not fork-safe), with one usable CPU, with ``MECHDESIGN_SERIAL=1``, or once typst has run
in this process (its worker threads do not survive a fork), every save simply happens
in place.
"""
from __future__ import annotations

import gc
import os
import signal
import sys
import traceback
from contextlib import contextmanager
from typing import Callable


class BackgroundSaveError(RuntimeError):
    """A figure could not be written by the helper process: the message names it and the
    error; ``detail`` holds the helper's traceback (shown with ``--debug``)."""

    def __init__(self, message: str, detail: str = ""):
        super().__init__(message)
        self.detail = detail


_enabled = False
# (pid, read end of its error pipe, label, a child of its own (save_apart))
_children: list[tuple[int, int, str, bool]] = []
_typst_used = False


def note_typst_used() -> None:
    """Called before every typst compilation: from then on this process does not fork."""
    global _typst_used
    _typst_used = True


def typst_used() -> bool:
    """Whether this process has run typst (and so must not fork a process that will)."""
    return _typst_used


def usable_cpus() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def can_fork() -> bool:
    # Linux only: macOS's system libraries are not safe to use in a forked child.
    return (sys.platform.startswith("linux") and usable_cpus() >= 2 and not _typst_used
            and os.environ.get("MECHDESIGN_SERIAL", "") not in ("1", "true", "yes"))


_on_save: Callable[[str], None] | None = None     # told each figure's name (progress)


@contextmanager
def background_saves(enabled: bool = True, on_save: Callable[[str], None] | None = None):
    """Within the block, :func:`save` may run in a child process; on leaving, every save
    has finished (or its error is raised). ``on_save(label)`` is called as each figure is
    handed over (for progress lines)."""
    global _enabled, _on_save
    previous, previous_hook = _enabled, _on_save
    _enabled = bool(enabled) and can_fork()
    _on_save = on_save
    try:
        yield
        _reap(block=True)
    finally:
        _kill()
        _enabled, _on_save = previous, previous_hook
        if gc.get_freeze_count():
            gc.unfreeze()


def save(action: Callable[[], None], label: str) -> None:
    """Run ``action`` (which writes the files of a figure that is complete) now, here or
    in the background. ``label`` names the figure in an error message.

    One child at a time takes these saves: a figure finished while it is free goes to a
    new child, one finished while it is busy is saved here (this process is the other
    worker)."""
    if _on_save is not None:
        _on_save(label)
    if _enabled:
        _reap(block=False)
        if _helper_free():
            _fork(action, label, apart=False)
            return
    action()


def save_apart(action: Callable[[], None], label: str) -> Callable[[], None]:
    """Run ``action``, which uses typst, in a child process of its own when saves go to
    the background (this process must stay free of typst's threads to go on forking),
    else here and now. Returns a function that waits until it is done (raising its
    error)."""
    if not _enabled:
        note_typst_used()
        action()
        return lambda: None
    pid = _fork(action, label, apart=True)
    return lambda: _reap(block=True, only=pid)


def _helper_free() -> bool:
    return not any(not apart for *_, apart in _children)


def _fork(action: Callable[[], None], label: str, apart: bool) -> int:
    global _enabled
    _flush_std()
    # The objects that exist now are the parent's and the child's alike: kept out of the
    # cyclic garbage collector's scans, their memory pages stay shared instead of being
    # copied by either process (copy-on-write); the child, short-lived, collects nothing.
    gc.freeze()
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:   # the child: save, report, leave without unwinding the caller
        code = 1
        gc.disable()
        _enabled = False          # what the action saves, it saves itself
        _children.clear()         # the parent's other children are not its own
        try:
            os.close(read_end)
            signal.signal(signal.SIGINT, signal.SIG_DFL)
            signal.signal(signal.SIGTERM, signal.SIG_DFL)
            action()
            code = 0
        except BaseException:  # noqa: BLE001 - reported to the parent
            try:
                os.write(write_end, traceback.format_exc().encode("utf-8", "replace")[-60000:])
            except BaseException:  # noqa: BLE001
                pass
        finally:
            _flush_std()
            os._exit(code)
    os.close(write_end)
    _children.append((pid, read_end, label, apart))
    return pid


def _flush_std() -> None:
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except Exception:  # noqa: BLE001 - a closed stream is no reason to fail a save
            pass


def _reap(block: bool, only: int | None = None) -> None:
    """Collect the children that have finished (all of them, or the one ``only``, when
    ``block``); raise their errors."""
    errors, details = [], []
    for child in list(_children):
        pid, read_end, label, _ = child
        if only is not None and pid != only:
            continue
        done, status = os.waitpid(pid, 0 if block else os.WNOHANG)
        if done == 0:
            continue
        _children.remove(child)
        with os.fdopen(read_end, "rb") as pipe:
            message = pipe.read().decode("utf-8", "replace")
        code = os.waitstatus_to_exitcode(status)
        if code != 0:
            lines = [x for x in message.strip().splitlines() if x.strip()]
            errors.append(f"writing {label} failed (helper process exit {code})"
                          + (f": {lines[-1].strip()}" if lines else ""))
            details.append(message)
    if errors:
        raise BackgroundSaveError("\n".join(errors), "\n".join(details))


def _kill() -> None:
    """Stop the children still running (the parent failed or was interrupted)."""
    while _children:
        pid, read_end, _, _ = _children.pop()
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        try:
            os.waitpid(pid, 0)
        except ChildProcessError:
            pass
        os.close(read_end)
