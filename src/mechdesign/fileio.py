"""Atomic writing of output files: the one helper every output of mechdesign goes through.

A file is written under a temporary name in its own folder, flushed and fsync'ed, then
moved over the target with :func:`os.replace` (atomic on POSIX and Windows within one
file system). A reader therefore sees either the old file or the complete new one, never a
partial file; if the writer fails — any exception, KeyboardInterrupt included — the
temporary file is removed and the old file is left untouched.

- :func:`write_bytes`, :func:`write_text`: the whole content at once;
- :func:`atomic_open`: a file object to write into (e.g. for :mod:`csv`);
- :func:`atomic_path`: a temporary path for libraries that write to a path themselves
  (matplotlib, ezdxf, Pillow, pandoc). The temporary name keeps the target's suffix, since
  some of them choose the format by it.

The temporary name is ``.<stem>.<random>.tmp<suffix>`` (hidden, unique per call, so
threads and forked processes writing the same target do not collide). A new file gets the
ordinary permissions (0o666 less the umask); a replaced file keeps its mode.
"""
from __future__ import annotations

import contextlib
import os
import stat
from pathlib import Path
from typing import IO, Iterator

__all__ = ["write_bytes", "write_text", "atomic_open", "atomic_path", "temporary_name"]


def temporary_name(path: Path) -> Path:
    """A fresh temporary name next to ``path`` (not created)."""
    return path.with_name(f".{path.stem}.{os.urandom(6).hex()}.tmp{path.suffix}")


def _reserve(path: Path) -> Path:
    """Create an empty temporary file next to ``path`` (exclusively) and return its name."""
    for _ in range(100):
        tmp = temporary_name(path)
        try:
            fd = os.open(tmp, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o666)
        except FileExistsError:
            continue
        os.close(fd)
        return tmp
    raise FileExistsError(f"no free temporary name next to {path}")


def _sync_file(tmp: Path) -> None:
    fd = os.open(tmp, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _publish(tmp: Path, path: Path) -> None:
    """Give ``tmp`` the mode of the file it replaces (if any) and move it over ``path``."""
    try:
        mode = stat.S_IMODE(os.stat(path).st_mode)
    except FileNotFoundError:
        pass
    else:
        os.chmod(tmp, mode)
    os.replace(tmp, path)


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike, *, parents: bool = True,
                fsync: bool = True) -> Iterator[Path]:
    """Yield a temporary path next to ``path`` for a library to write; when the block
    ends without an exception the file is fsync'ed and moved over ``path``.

    The temporary file exists (empty) when the block starts; the writer may overwrite or
    recreate it. On any exception (KeyboardInterrupt included) it is removed and ``path``
    is left as it was. ``parents`` creates missing parent folders first."""
    path = Path(path)
    if parents:
        path.parent.mkdir(parents=True, exist_ok=True)
    tmp = _reserve(path)
    try:
        yield tmp
        if fsync:
            _sync_file(tmp)
        _publish(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


@contextlib.contextmanager
def atomic_open(path: str | os.PathLike, mode: str = "w", *, encoding: str | None = None,
                newline: str | None = None, parents: bool = True,
                fsync: bool = True) -> Iterator[IO]:
    """Open a temporary file next to ``path`` for writing (``mode`` "w" or "wb", text
    mode defaults to UTF-8) and move it over ``path`` when the block ends without an
    exception; see :func:`atomic_path`."""
    if mode not in ("w", "wb", "wt"):
        raise ValueError(f"atomic_open: mode {mode!r} is not a write mode ('w' or 'wb')")
    binary = "b" in mode
    if binary and (encoding is not None or newline is not None):
        raise ValueError("atomic_open: binary mode takes no encoding or newline")
    with atomic_path(path, parents=parents, fsync=False) as tmp:
        kwargs = {} if binary else {"encoding": encoding or "utf-8", "newline": newline}
        with open(tmp, mode, **kwargs) as handle:
            yield handle
            handle.flush()
            if fsync:
                os.fsync(handle.fileno())


def write_bytes(path: str | os.PathLike, data: bytes, *, parents: bool = True,
                fsync: bool = True) -> Path:
    """Write ``data`` to ``path`` atomically. Returns the path."""
    if not isinstance(data, (bytes, bytearray, memoryview)):
        raise TypeError(f"write_bytes: data must be bytes, not {type(data).__name__}")
    with atomic_open(path, "wb", parents=parents, fsync=fsync) as handle:
        handle.write(data)
    return Path(path)


def write_text(path: str | os.PathLike, text: str, *, encoding: str = "utf-8",
               newline: str | None = None, parents: bool = True, fsync: bool = True) -> Path:
    """Write ``text`` to ``path`` atomically in ``encoding`` (UTF-8 by default; ``newline``
    as for :func:`open`). Returns the path."""
    if not isinstance(text, str):
        raise TypeError(f"write_text: text must be str, not {type(text).__name__}")
    with atomic_open(path, "w", encoding=encoding, newline=newline, parents=parents,
                     fsync=fsync) as handle:
        handle.write(text)
    return Path(path)
