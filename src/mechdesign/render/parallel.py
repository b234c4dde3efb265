"""Save figures in a second process while the next one is drawn.

Drawing a report is mostly matplotlib laying out text and encoding images, one figure
after another on one core. Inside :func:`background_saves`, :func:`save` hands a
finished figure to a forked child process (it inherits the figure as it is, nothing is
pickled), so this process goes on building the next one; while the child is busy this
process holds the figures back and saves them once the Markdown is rendered and pandoc
runs (or while it waits for the sheets), so pandoc's conversion overlaps the figures'
saving. Work that uses typst (the drawing sheets) gets a child of its own
(:func:`save_apart`; the sheets' previews: :func:`start_apart`). Two cores are then
both at work, whatever a machine's report module draws, and every figure is drawn once.

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
_held: list[tuple[Callable[[], None], str]] = []   # figures held back, oldest first


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

#: figures held back, drawn but not yet saved, before this process saves one itself
MAX_HELD = 64


@contextmanager
def background_saves(enabled: bool = True, on_save: Callable[[str], None] | None = None):
    """Within the block, :func:`save` may run in a child process, or a little later; on
    leaving, every save has finished (or its error is raised). ``on_save(label)`` is called
    as each figure is handed over (for progress lines)."""
    global _enabled, _on_save
    previous, previous_hook = _enabled, _on_save
    _enabled = bool(enabled) and can_fork()
    _on_save = on_save
    try:
        yield
        drain()
    finally:
        _kill()
        _held.clear()
        _enabled, _on_save = previous, previous_hook
        if gc.get_freeze_count():
            gc.unfreeze()


def save(action: Callable[[], None], label: str) -> None:
    """Run ``action`` (which writes the files of a figure that is complete) now, in the
    background, or a little later. ``label`` names the figure in an error message.

    One child at a time takes these saves; this process is the other worker. While it
    draws, it only holds the figures back (up to :data:`MAX_HELD`): the helper takes the
    oldest whenever it is free, and this process saves the rest once the Markdown is
    made and pandoc runs (:func:`pump`, :func:`drain`), so pandoc's conversion overlaps
    the figures instead of following them."""
    if _on_save is not None:
        _on_save(label)
    if not _enabled:
        action()
        return
    _held.append((action, label))
    pump()                          # a free helper takes the oldest figure
    if len(_held) > MAX_HELD:       # else this process saves it
        _held.pop(0)[0]()


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

    def wait() -> None:
        # while the child works, this process saves the figures it holds back
        while any(c[0] == pid for c in _children):
            pump()
            if not _held:
                _reap(block=True, only=pid)
                return
            _held.pop(0)[0]()
            _reap(block=False)

    return wait


def start_apart(action: Callable[[], None], label: str) -> Callable[..., None]:
    """Run ``action`` in a child of its own now, also outside :func:`background_saves`,
    when this process may fork (:func:`can_fork`: it has not run typst itself), else here
    and now. Returns ``finish(kill=False)``: waits for the child (raising its error), or
    with ``kill`` stops it. For the work that may run while this process compiles the
    report's PDF (the sheets' previews)."""
    if not can_fork():
        action()
        return lambda kill=False: None
    pid = _fork(action, label, apart=True)

    def finish(kill: bool = False) -> None:
        try:
            if kill:
                for child in [c for c in _children if c[0] == pid]:
                    _children.remove(child)
                    try:
                        os.kill(pid, signal.SIGKILL)
                        os.waitpid(pid, 0)
                    except (ProcessLookupError, ChildProcessError):
                        pass
                    os.close(child[1])
            else:
                _reap(block=True, only=pid)
        finally:
            if not _children and gc.get_freeze_count():
                gc.unfreeze()

    return finish


def pump() -> None:
    """Hand the oldest figure held back to the helper if it is free (also to call when
    drawing is over and other work follows)."""
    if _enabled and _held:
        _reap(block=False)
        if _helper_free():
            _fork(*_held.pop(0), apart=False)


def drain() -> None:
    """Write the figures held back (the helper takes one when it is free, this process
    the rest), then wait for every child."""
    while _held:
        pump()
        if _held:
            _held.pop(0)[0]()
    _reap(block=True)


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
        _held.clear()
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
