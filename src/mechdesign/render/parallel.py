"""Save figures in a second process while the next one is drawn.

Drawing a report is mostly matplotlib laying out text and encoding images, one figure
after another on one core. Inside :func:`background_saves`, :func:`save` hands the
finished figure to a forked child process (it inherits the figure as it is, nothing is
pickled) and returns at once, so the parent goes on building the next figure; when the
child is still busy, the parent saves the figure itself. Two cores are then both at
work, whatever the machine's report module draws, and every figure is drawn once.

The child never returns into the caller's stack: it saves, reports a failure through a
pipe and leaves with ``os._exit``, so no ``finally`` of the parent (the staging folder's
cleanup) runs twice. Leaving the context waits for the child and raises its error; an
exception or an interrupt in the parent kills it first. Nothing here is used outside
rendering, and without ``fork`` (Windows), with one usable CPU, with
``MECHDESIGN_SERIAL=1`` or once typst has run in this process (its worker threads do not
survive a fork) every save simply happens in place.
"""
from __future__ import annotations

import os
import signal
import sys
import traceback
from contextlib import contextmanager
from typing import Callable


class BackgroundSaveError(RuntimeError):
    """A figure could not be written by the helper process (its traceback follows)."""


_enabled = False
# (pid, read end of its error pipe, label, uses typst)
_children: list[tuple[int, int, str, bool]] = []
_typst_used = False


def note_typst_used() -> None:
    """Called before every typst compilation: from then on this process does not fork."""
    global _typst_used
    _typst_used = True


def usable_cpus() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def can_fork() -> bool:
    return (hasattr(os, "fork") and usable_cpus() >= 2 and not _typst_used
            and os.environ.get("MECHDESIGN_SERIAL", "") not in ("1", "true", "yes"))


@contextmanager
def background_saves(enabled: bool = True):
    """Within the block, :func:`save` may run in a child process; on leaving, every
    save has finished (or its error is raised)."""
    global _enabled
    previous = _enabled
    _enabled = bool(enabled) and can_fork()
    try:
        yield
        _wait()
    finally:
        _kill()
        _enabled = previous


def save(action: Callable[[], None], label: str, *, uses_typst: bool = False) -> None:
    """Run ``action`` (which writes the files of a figure that is complete) now or in the
    background. ``label`` names the figure in an error message.

    One child at a time takes ordinary saves (the parent is the other worker); when it
    is busy the parent saves in place. An action that ``uses_typst`` always gets a child
    of its own when forking is on, so that this process stays free of typst's threads
    and can go on forking."""
    if _enabled:
        _reap(block=False)
        if uses_typst or not any(not typ for *_, typ in _children):
            _fork(action, label, uses_typst)
            return
    if uses_typst:
        note_typst_used()
    action()


def _fork(action: Callable[[], None], label: str, uses_typst: bool) -> None:
    _flush_std()
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:   # the child: save, report, leave without unwinding the caller
        code = 1
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
    _children.append((pid, read_end, label, uses_typst))


def _flush_std() -> None:
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except Exception:  # noqa: BLE001 - a closed stream is no reason to fail a save
            pass


def _reap(block: bool) -> None:
    """Collect the children that have finished (all of them, when ``block``); raise the
    first error."""
    errors = []
    for child in list(_children):
        pid, read_end, label, _ = child
        done, status = os.waitpid(pid, 0 if block else os.WNOHANG)
        if done == 0:
            continue
        _children.remove(child)
        with os.fdopen(read_end, "rb") as pipe:
            message = pipe.read().decode("utf-8", "replace")
        code = os.waitstatus_to_exitcode(status)
        if code != 0:
            errors.append(f"writing {label} failed (helper process exit {code})"
                          + (f":\n{message}" if message else ""))
    if errors:
        raise BackgroundSaveError("\n".join(errors))


def _wait() -> None:
    _reap(block=True)


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
