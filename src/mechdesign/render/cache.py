"""A content-addressed cache of rendered files (figure PNGs, typst outputs).

Drawing a report is mostly matplotlib laying out text and encoding PNGs, and typst laying
out pages; a re-run of a brief (``mechdesign watch`` after an edit, or ``run`` again)
mostly draws what it drew before. Each rendered file is therefore stored under the hash of
everything that determines its bytes, and a later render with the same hash copies the
stored file instead of drawing it again:

- a figure: its complete state just before it is laid out and saved (the pickled
  matplotlib Figure: artists, data, text, font properties, sizes), matplotlib's rcParams,
  the versions of matplotlib, Pillow and FreeType, the registered font files and the save
  settings (:func:`figure_key`);
- a figure drawn by a function marked :func:`mechdesign.render.figures.cached`: also, before
  anything is drawn, the function's name and arguments (its data, the language) with the
  source of the whole package and the catalogues (:func:`call_key`) — a hit then skips
  building the figure too;
- a typst output: the typst source, every file under the compilation's root folder (the
  images it may place), the options (format, resolution, timestamp), typst's version and
  the font files given to it (:func:`typst_key`).

A hit gives the same bytes as drawing (the renderers are deterministic: the snapshot
comparison of tools/snapshot_reports.py holds with the cache cold or warm); whatever
cannot be hashed (an object pickle refuses) is simply drawn. The key never depends on
object addresses, the hash seed or the process.

Where: ``$MECHDESIGN_CACHE`` (a folder), else ``$XDG_CACHE_HOME/mechdesign/render``, else
``~/.cache/mechdesign/render``. ``MECHDESIGN_CACHE=off`` (or 0/no/false) disables it.
Files are written atomically (a temporary name, then :func:`os.replace`), so concurrent
runs share the folder safely; once per process, after the first store, the folder is
trimmed to :data:`LIMIT_BYTES` (least recently used first).
"""
from __future__ import annotations

import hashlib
import io
import os
import re
import pickle
import types
from functools import lru_cache
from pathlib import Path

#: the cache is trimmed to this size (least recently used entries go first)
LIMIT_BYTES = 300 * 2**20
#: bumped whenever what is stored, or how a figure is saved, changes
FORMAT = "1"

_trimmed = False
_ENTRY_DIR = re.compile(r"[0-9a-f]{2}")
_ENTRY = re.compile(r"[0-9a-f]{64}")
_stats = {"hit": 0, "miss": 0}


def folder() -> Path | None:
    """The cache folder, or None when caching is off."""
    value = os.environ.get("MECHDESIGN_CACHE", "").strip()
    if value.lower() in ("0", "off", "no", "false"):
        return None
    if value:
        return Path(value)
    base = os.environ.get("XDG_CACHE_HOME", "").strip() or str(Path.home() / ".cache")
    return Path(base) / "mechdesign" / "render"


def stats() -> dict[str, int]:
    """Hits and misses of this process (for --timings and the benchmarks)."""
    return dict(_stats)


def fetch(key: str | None, target: Path) -> bool:
    """Copy the entry ``key`` to ``target`` (atomically); False if there is none."""
    data = fetch_bytes(key)
    if data is None:
        return False
    from ..fileio import write_bytes

    write_bytes(target, data, fsync=False)
    return True


def fetch_bytes(key: str | None) -> bytes | None:
    """The bytes of entry ``key``, or None."""
    where = folder()
    if key is None or where is None:
        return None
    entry = where / key[:2] / key
    try:
        data = entry.read_bytes()
    except OSError:
        _stats["miss"] += 1
        return None
    try:
        os.utime(entry)             # recently used: trimmed last
    except OSError:
        pass
    _stats["hit"] += 1
    return data


def store(key: str | None, data: bytes) -> None:
    """Keep ``data`` as entry ``key`` (errors are ignored: a cache is never a failure)."""
    where = folder()
    if key is None or where is None:
        return
    from ..fileio import write_bytes

    try:
        write_bytes(where / key[:2] / key, data, fsync=False)     # atomic, parents made
    except OSError:
        return
    _trim_once(where)


def store_file(key: str | None, path: Path) -> None:
    if key is None or folder() is None:
        return
    try:
        store(key, Path(path).read_bytes())
    except OSError:
        pass


def _trim_once(where: Path) -> None:
    global _trimmed
    if _trimmed:
        return
    _trimmed = True
    try:
        entries = []
        for sub in where.iterdir():
            if sub.is_dir() and _ENTRY_DIR.fullmatch(sub.name):
                for f in sub.iterdir():
                    # only the entries the cache wrote (<2 hex>/<that prefix + 62 hex>): a
                    # cache pointed at a folder holding other files never removes them
                    if _ENTRY.fullmatch(f.name) and f.name[:2] == sub.name and f.is_file():
                        st = f.stat()
                        entries.append((st.st_mtime, st.st_size, f))
        total = sum(size for _, size, _ in entries)
        for _, size, f in sorted(entries):
            if total <= LIMIT_BYTES:
                break
            f.unlink(missing_ok=True)
            total -= size
    except OSError:
        pass


def _digest(*parts: bytes | str) -> str:
    h = hashlib.sha256()
    for part in parts:
        data = part.encode("utf-8") if isinstance(part, str) else part
        h.update(len(data).to_bytes(8, "little"))
        h.update(data)
    return h.hexdigest()


def _file_identity(path: Path) -> str:
    try:
        st = Path(path).stat()
        return f"{path}:{st.st_size}:{st.st_mtime_ns}"
    except OSError:
        return f"{path}:-"


# --- figures -------------------------------------------------------------------------

class _FigurePickler(pickle.Pickler):
    """Pickles a figure deterministically: without pyplot's registration, a transform
    without its parents (weak references matplotlib keys by id(), alive or not as the
    garbage collector left them); a function (a tick formatter, a secondary axis'
    conversion) by its name, code, constants, defaults and closure."""

    def reducer_override(self, obj):
        from matplotlib.figure import Figure
        from matplotlib.transforms import TransformNode

        if isinstance(obj, Figure):
            # whether pyplot still holds the figure (it has been closed by the time a
            # background save runs) does not change the drawing
            state = obj.__getstate__()
            state.pop("_restore_to_pylab", None)
            return (type(obj), (), state)
        if isinstance(obj, TransformNode):
            # a node's parents (weak references, kept for invalidation) are those the
            # garbage collector has not yet freed: they do not change the node's value
            state = obj.__getstate__()
            state.pop("_parents", None)
            return (type(obj), (), state)
        if isinstance(obj, types.FunctionType) and obj is not _function:
            code = obj.__code__
            consts = tuple(c for c in code.co_consts if not isinstance(c, types.CodeType))
            cells = tuple(c.cell_contents for c in (obj.__closure__ or ()))
            # the closure as the reduction's state: pickled after the function is
            # memoised, so a closure that refers back to it ends there
            return (_function, (f"{obj.__module__}.{obj.__qualname__}", code.co_code, consts),
                    (obj.__defaults__, cells))
        return NotImplemented


def _function(*_args):     # never called: the figure pickle is hashed, never loaded
    raise RuntimeError("a figure key is not loaded")


@lru_cache(maxsize=1)
def _figure_environment() -> str:
    import matplotlib
    import PIL
    from matplotlib import font_manager, ft2font

    from .fonts import configure_matplotlib

    configure_matplotlib()       # the CJK font registered before the fonts are listed
    fonts = sorted(_file_identity(Path(f.fname)) for f in font_manager.fontManager.ttflist)
    return "|".join([FORMAT, matplotlib.__version__, PIL.__version__,
                     getattr(ft2font, "__freetype_version__", "?"), *fonts])


def figure_key(fig, save: str) -> str | None:
    """The cache key of ``fig`` as it is now (before layout), saved as ``save`` describes
    (a text naming the layout, resolution and encoding); None if it cannot be hashed."""
    if folder() is None:
        return None
    import matplotlib

    try:
        buf = io.BytesIO()
        _FigurePickler(buf, protocol=5).dump((fig, dict(matplotlib.rcParams)))
    except Exception:  # noqa: BLE001 - an object pickle refuses: the figure is drawn
        return None
    return _digest("figure", save, _figure_environment(), buf.getvalue())


@lru_cache(maxsize=1)
def _code_fingerprint() -> str:
    """The source of everything a figure function may run: every module of the package
    and the catalogues (labels) — an edited program never gets an old figure."""
    package = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    for path in sorted([*package.rglob("*.py"), *package.rglob("*.mo")]):
        h.update(path.relative_to(package).as_posix().encode())
        h.update(hashlib.sha256(path.read_bytes()).digest())
    return h.hexdigest()


def call_key(function, args: tuple, kwargs: dict) -> str | None:
    """The cache key of ``function(path, *args, **kwargs)`` drawing one figure: its name,
    its arguments but the path, the language variant in use, the package's code and
    catalogues, matplotlib's set-up;
    None if an argument cannot be hashed."""
    if folder() is None:
        return None
    import matplotlib

    from ..i18n import variant

    try:
        buf = io.BytesIO()
        # the language variant set for the run (zh_TW: zh with its own catalogue)
        _FigurePickler(buf, protocol=5).dump((variant(), args, sorted(kwargs.items())))
    except Exception:  # noqa: BLE001 - an argument pickle refuses: no call key
        return None
    return _digest("call", f"{function.__module__}.{function.__qualname__}",
                   _code_fingerprint(), _figure_environment(),
                   _file_identity(Path(matplotlib.matplotlib_fname())), buf.getvalue())


# --- typst ---------------------------------------------------------------------------

@lru_cache(maxsize=1)
def _typst_environment() -> str:
    import typst

    from .fonts import font_dirs

    files = []
    for d in font_dirs():
        files += sorted(_file_identity(p) for p in Path(d).iterdir() if p.is_file())
    return "|".join([FORMAT, getattr(typst, "__version__", "?"), *files])


def typst_key(source: bytes | str, root: Path | None, skip: Path | None = None,
              **options) -> str | None:
    """The cache key of compiling ``source`` with ``options``; every file under ``root``
    (the images the source may place) but ``skip`` (the source's own file) is hashed
    with it."""
    if folder() is None:
        return None
    parts: list[bytes | str] = ["typst", _typst_environment(), repr(sorted(options.items())),
                                source]
    if root is not None:
        root = Path(root)
        for path in sorted(p for p in root.rglob("*") if p.is_file()):
            rel = path.relative_to(root).as_posix()
            if skip is not None and path == Path(skip):
                continue
            parts += [rel, hashlib.sha256(path.read_bytes()).digest()]
    return _digest(*parts)
