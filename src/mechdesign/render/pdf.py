"""Markdown -> typst (pandoc) -> PDF (typst) rendering of the report.

Metadata keys understood by ``templates/report.typ`` (all optional):
``title``, ``subtitle``, ``student``, ``student_id``, ``class``, ``teacher``,
``date``, ``lang`` ("zh" or "en", default "zh"), ``mainfont``/``sansfont``
(family name or list; default: the CJK families from :mod:`fonts`),
``toc-depth`` and a nested ``labels`` mapping with ``student``, ``student_id``,
``class``, ``teacher``, ``date``, ``contents`` (defaults depend on ``lang``).
Metadata values are pandoc Markdown: user text comes escaped
(:func:`mechdesign.render.report.pdf_metadata`).

Reproducible output: the PDF's creation date is :func:`source_timestamp` (the
``SOURCE_DATE_EPOCH`` environment variable, else the brief's date, else a fixed date), so
the same Markdown and metadata give the same bytes.
"""

from __future__ import annotations

import datetime as _dt
import json
import os
import re
import tempfile
import warnings
from functools import lru_cache
from pathlib import Path

from ..fileio import write_bytes
from ..i18n import N_
from .fonts import cjk_families, font_dirs
from .labels import LabelTable
from .mathbreak import break_display_math
from .unitjoin import LUA_FILTER as _UNIT_FILTER

MARKDOWN_FORMAT = (
    "markdown+pipe_tables+tex_math_dollars+implicit_figures"
    "+yaml_metadata_block+east_asian_line_breaks"
)

DEFAULT_LABELS = LabelTable({
    "student": N_("Name"),
    "student_id": N_("Student No."),
    "class": N_("Class"),
    "teacher": N_("Supervisor"),
    "date": N_("Date"),
    "group": N_("Data group"),
    "contents": N_("Contents"),
})


# Pandoc turns a bare ``@label`` into a citation; typst needs a reference.
_PROSE_CITE = re.compile(r'#cite\(<([^>]+)>, form: "prose"\)')
# Markdown needs a space before "@label"; between CJK characters it must go.
# (escapes read by the regular expression engine: the module holds no CJK literal)
_CJK = r"\u3000-\u303f\u3400-\u9fff\uff00-\uffef"
_SPACE_BEFORE_REF = re.compile(rf"(?<=[{_CJK}]) (?=#ref\(<[^>]+>\))")
_SPACE_AFTER_REF = re.compile(rf"(#ref\(<[^>]+>\)) (?=[{_CJK}])")


#: Creation date written when neither SOURCE_DATE_EPOCH nor the brief gives one:
#: 1980-01-01 00:00 UTC, the earliest date a ZIP file (a .docx) can hold.
FALLBACK_TIMESTAMP = 315532800

# separators - . / or 年 (\u5e74) and 月 (\u6708)
_DATE = re.compile(r"^\s*(\d{4})\s*[-./\u5e74]\s*(\d{1,2})\s*[-./\u6708]\s*(\d{1,2})")


def source_timestamp(date_text: str | None = None) -> int:
    """The creation time (Unix seconds, UTC) written into the PDF and the Word file.

    ``SOURCE_DATE_EPOCH`` (the reproducible-builds convention) if set to a number; else
    the brief's date (``2026-11-22``, ``2026.11.22``, ``2026年11月22日``) at 00:00 UTC; else
    :data:`FALLBACK_TIMESTAMP`. Never the clock: the same brief gives the same bytes."""
    env = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    if env.isdigit():
        return max(int(env), FALLBACK_TIMESTAMP)
    match = _DATE.match(str(date_text or ""))
    if match:
        try:
            day = _dt.datetime(*map(int, match.groups()), tzinfo=_dt.timezone.utc)
        except ValueError:
            return FALLBACK_TIMESTAMP
        return max(int(day.timestamp()), FALLBACK_TIMESTAMP)
    return FALLBACK_TIMESTAMP


# pandoc Lua filter for the typst writer: what the writer leaves unescaped in user text.
# * typst shorthands inside a word: "..." (an ellipsis) and "-?" (a soft hyphen);
# * a block marker starting a content block ("- ", "+ ", "/ ", "= ", "1. "): the writer
#   escapes it at the start of a line, but not at the start of a table cell, a caption
#   or a title-page field, where typst would make a list or a heading of it.
_TYPST_FILTER = r"""
local function split_shorthands(el)
  local text = el.text
  if not (text:find("...", 1, true) or text:find("-?", 1, true)) then return nil end
  local out = pandoc.Inlines {}
  local buf = ""
  local i = 1
  while i <= #text do
    if text:sub(i, i + 2) == "..." then
      if buf ~= "" then out:insert(pandoc.Str(buf)); buf = "" end
      out:insert(pandoc.RawInline("typst", "..\\."))
      i = i + 3
    elseif text:sub(i, i + 1) == "-?" then
      if buf ~= "" then out:insert(pandoc.Str(buf)); buf = "" end
      out:insert(pandoc.RawInline("typst", "-\\?"))
      i = i + 2
    else
      buf = buf .. text:sub(i, i)
      i = i + 1
    end
  end
  if buf ~= "" then out:insert(pandoc.Str(buf)) end
  return out
end

local function is_break(el)
  return el == nil or el.t == "Space" or el.t == "SoftBreak" or el.t == "LineBreak"
end

local function escape_marker(inlines)
  local first = inlines[1]
  if first and first.t == "Str" and is_break(inlines[2]) then
    local t = first.text
    if t:match("^[-+/]$") or t:match("^=+$") or t:match("^%d+%.$") then
      inlines[1] = pandoc.RawInline("typst", "\\" .. t)
      return inlines
    end
  end
  return nil
end

return {
  { Str = split_shorthands },
  { Inlines = escape_marker },
}
"""


class PdfRenderError(RuntimeError):
    """Pandoc or typst failed while rendering the report."""


def _full_metadata(metadata: dict) -> dict:
    """Return ``metadata`` completed with defaults for lang, fonts and labels."""
    meta = dict(metadata)
    lang = str(meta.get("lang") or "zh")
    # pandoc has no "zh" translations (it warns) but knows "zh-Hans"; typst gets lang "zh".
    meta["lang"] = "zh-Hans" if lang.lower() in ("zh", "zh-cn") else lang
    families = cjk_families()
    meta.setdefault("mainfont", [families["serif"]])
    meta.setdefault("sansfont", [families["sans"]])
    base = DEFAULT_LABELS["zh" if lang.lower().startswith("zh") else "en"]
    meta["labels"] = {**base, **(meta.get("labels") or {})}
    return meta


def markdown_to_typst(md_text: str, template: Path, metadata: dict, resource_dir: Path) -> str:
    """Convert Markdown to a standalone typst document with pandoc.

    Inputs: the Markdown text, the pandoc typst template, the metadata mapping
    (see the module docstring; completed with defaults) and the directory that
    relative resources (images) are resolved against.  Metadata from a YAML
    block inside ``md_text`` takes precedence over ``metadata``.  A bare
    ``@label`` naming a figure/table/heading label of the document (or any
    ``@key`` when there is no bibliography) becomes a typst reference
    (e.g. "图 1") instead of a citation.
    Output: the typst source.  Raises PdfRenderError if pandoc fails.
    """
    return PendingTypst(md_text, template, metadata, resource_dir).result()


class PendingTypst:
    """pandoc converting Markdown to typst in its own process, started at once;
    :meth:`result` waits for it (see :func:`markdown_to_typst`). The report starts it
    while the last figures are still being written. pandoc is run directly (the binary
    pypandoc ships), reading and writing files, so nothing blocks on a pipe."""

    def __init__(self, md_text: str, template: Path, metadata: dict, resource_dir: Path):
        import subprocess

        import pypandoc

        self._meta = _full_metadata(metadata)
        self._tmp = tempfile.TemporaryDirectory(prefix="mechdesign-pandoc-")
        tmp = Path(self._tmp.name)
        # JSON is valid YAML, which is what --metadata-file expects.
        (tmp / "metadata.json").write_text(json.dumps(self._meta, ensure_ascii=False, default=str),
                                           encoding="utf-8")
        (tmp / "typst-literal.lua").write_text(_TYPST_FILTER, encoding="utf-8")
        # a number and its unit kept on one line (render/unitjoin.py)
        (tmp / "unit-join.lua").write_text(_UNIT_FILTER, encoding="utf-8")
        # long display formulas set on several aligned lines (mathbreak)
        (tmp / "in.md").write_text(break_display_math(md_text), encoding="utf-8")
        self._out, self._err = tmp / "out.typ", tmp / "pandoc.err"
        args = [pypandoc.get_pandoc_path(), f"--from={MARKDOWN_FORMAT}", "--to=typst",
                str(tmp / "in.md"), f"--output={self._out}",
                "--standalone",
                f"--template={Path(template).resolve()}",
                f"--metadata-file={tmp / 'metadata.json'}",
                f"--lua-filter={tmp / 'unit-join.lua'}",
                f"--lua-filter={tmp / 'typst-literal.lua'}",
                f"--resource-path={Path(resource_dir).resolve()}",
                "--wrap=none",
                # wide pipe tables keep natural (auto) column widths; typst shrinks
                # them to the text width only when needed
                "--columns=10000"]
        try:
            with open(self._err, "wb") as err:
                self._proc = subprocess.Popen(args, stdin=subprocess.DEVNULL,
                                              stdout=subprocess.DEVNULL, stderr=err)
        except OSError as exc:
            self._tmp.cleanup()
            raise PdfRenderError(f"pandoc could not be started: {exc}") from exc

    def result(self) -> str:
        """The typst source (waits for pandoc). Raises PdfRenderError if pandoc failed."""
        try:
            code = self._proc.wait()
            if code != 0:
                message = self._err.read_text(encoding="utf-8", errors="replace").strip()
                raise PdfRenderError(f"pandoc failed to convert Markdown to typst "
                                     f"(exit {code}): {message}")
            source = self._out.read_text(encoding="utf-8")
        finally:
            self.cancel()
        return _typst_references(source, self._meta)

    def cancel(self) -> None:
        """Stop pandoc if it still runs and remove its files."""
        if self._proc.poll() is None:
            self._proc.kill()
            self._proc.wait()
        self._tmp.cleanup()


def _typst_references(source: str, meta: dict) -> str:
    """pandoc's typst with references and the cells typst would misread mended."""
    defined = set(re.findall(r"^<([^>\s]+)>$", source, flags=re.MULTILINE))
    has_bibliography = bool(meta.get("bibliography"))

    def to_ref(match: re.Match) -> str:
        key = match.group(1)
        return f"#ref(<{key}>)" if key in defined or not has_bibliography else match.group(0)

    # pandoc writes a table cell "= 5" as [= 5], which typst reads as a heading.
    source = re.sub(r"(?<=\[)(=+ )", r"\\\1", source)
    source = _PROSE_CITE.sub(to_ref, source)
    source = _SPACE_BEFORE_REF.sub("", source)
    source = _SPACE_AFTER_REF.sub(r"\1", source)
    return _TABLE.sub(_mend_table, source)


# A table as pandoc's typst writer prints it: one line per argument, one line per row.
_TABLE = re.compile(r"^(?P<indent>[ \t]*)(?P<open>(?:align\(center\)\[)?#table\(\n)"
                    r"(?P<body>(?:(?!(?P=indent)\)).*\n)*?)(?P=indent)\)", re.MULTILINE)
_COLUMNS = re.compile(r"^(\s*)columns: (?:(\d+)|\(([^()]*)\)),$")
_ALIGN = re.compile(r"^(\s*)align: \(([^()]*)\),$")
_HEADER = re.compile(r"^(\s*)table\.header\((.*)\),$")

#: A table of at most this many rows is never split across pages; a longer one keeps at
#: least :data:`KEEP_ROWS` rows on each side of a page break.
UNBREAKABLE_ROWS = 6
KEEP_ROWS = 3


def _mend_table(match: re.Match) -> str:
    """A pandoc table made ready to break across pages (templates/report.typ):
    * the header's cells passed through ``table-head`` (the header font: the header is
      now the table's second row);
    * a first header row spanning all columns whose content is ``#table-continued()``
      (nothing on the table's first page, "续表 N" / "Table N (continued)" on later ones;
      the header repeats on every page);
    * rows never split so that fewer than KEEP_ROWS rows stand on a page: an extra column
      of zero width holds one unbreakable cell spanning the first KEEP_ROWS rows and one
      spanning the last KEEP_ROWS rows (typst moves such a group to the next page whole);
      a table of UNBREAKABLE_ROWS rows or fewer is one unbreakable group.
    Tables not in the expected shape are left as they are."""
    lines = match.group("body").splitlines()
    cols_at = next((n for n, line in enumerate(lines) if _COLUMNS.match(line)), None)
    head_at = next((n for n, line in enumerate(lines) if _HEADER.match(line)), None)
    if cols_at is None or head_at is None:
        return match.group(0)
    cm = _COLUMNS.match(lines[cols_at])
    rows = [n for n in range(head_at + 1, len(lines)) if lines[n].lstrip().startswith("[")]
    others = [n for n in range(head_at + 1, len(lines))
              if n not in rows and lines[n].strip() not in ("table.hline(),", "")]
    if others or not rows:
        return match.group(0)
    ncols = int(cm.group(2)) if cm.group(2) else len([c for c in cm.group(3).split(",") if c.strip()])
    widths = ["auto"] * ncols if cm.group(2) else [c.strip() for c in cm.group(3).split(",") if c.strip()]
    lines[cols_at] = f"{cm.group(1)}columns: ({', '.join(widths + ['0pt'])}),"
    for n, line in enumerate(lines):
        am = _ALIGN.match(line)
        if am:
            lines[n] = f"{am.group(1)}align: ({am.group(2).rstrip(',')},left,),"
    hm = _HEADER.match(lines[head_at])
    lines[head_at] = (f"{hm.group(1)}table.header(table.cell(colspan: {ncols + 1}, inset: 0pt)"
                      f"[#table-continued()], ..table-head({hm.group(2)}), [],),")
    groups = ([(0, len(rows))] if len(rows) <= UNBREAKABLE_ROWS
              else [(0, KEEP_ROWS), (len(rows) - KEEP_ROWS, KEEP_ROWS)])
    starts = {first: span for first, span in groups}
    covered = {k for first, span in groups for k in range(first + 1, first + span)}
    for k, n in enumerate(rows):
        if k in starts:
            lines[n] += f" table.cell(rowspan: {starts[k]}, inset: 0pt, breakable: false)[],"
        elif k not in covered:
            lines[n] += " table.cell(inset: 0pt)[],"
    body = "\n".join(lines) + "\n"
    return match.group("indent") + match.group("open") + body + match.group("indent") + ")"


@lru_cache(maxsize=1)
def typst_fonts():
    """The fonts typst is given, found once per process: the shipped CJK fonts (render/fonts.py),
    typst's embedded ones (New Computer Modern, its math font, DejaVu Sans Mono) and the
    system's, scanned once here instead of on each of a run's ~7 compilations (~40 ms
    each). The system fonts stay for the glyphs the shipped ones lack (an emoji in a
    student's name: tests/test_user_text.py renders user text literally)."""
    import typst

    dirs = [str(d) for d in font_dirs()]
    return typst.Fonts(include_system_fonts=True, include_embedded_fonts=True,
                       font_paths=dirs)


# --- warm typst processes (mechdesign watch) -------------------------------------------
#
# typst memoises its work in the process (parsed fonts, the layout of each paragraph,
# table and figure) and re-uses it for a later compilation of a source of the same name
# (:func:`_source_file`). Measured on the shaper's 38-page report (CPU seconds, typst
# 0.15.2 binding): ~3.1 laid out cold; ~0.1 for the same source again; ~0.8 after an edit
# that moves nothing (one cell, one number in a paragraph); ~2.7–3.3 again after an edit
# that moves something (a cell grown wider, a formula wrapped onto a second line: a load
# edit does both) or that changes a set rule every page depends on (the student is in
# ``#set document``: a changed name alone costs the whole layout).
# The binding drops what a compilation memoised once about ten later compilations of the
# same process have not used it (the shaper's report compiled again after 8 small
# documents: 0.3; after 9: 1.0; after 10: 3.4 — the whole layout): a run compiles up to
# six drawing sheets, each as a PDF and a PNG preview, so the report and the sheets get a
# compiling process each, and the report's process compiles nothing but one report per run.
# The binding's ``typst.Compiler`` (a world kept between compilations) is no better (the
# memo is process-wide; it measured worse after an edit and back), so it is not used.
# A long-lived process (the watch) starts the compiling processes with
# :func:`start_service` before it runs anything; this process and the children it forks
# then send their compilations there (:func:`_service_compile`) and stay free of typst's
# threads, so they may go on forking.

#: what goes where: "file" (a report, :func:`compile_pdf`) and "bytes" (a self-contained
#: source, :func:`cached_compile`: the drawing sheets) → the socket of its compiling process
_service_address: dict[str, str] = {}


def start_service():
    """Start the compiling processes (Linux: forked; they never fork themselves), one for
    the reports and one for the self-contained sources (the sheets). Returns a function
    that stops them. Compilations fall back to this process when one is gone; a process
    that has already run typst starts none (it cannot fork one safely)."""
    global _service_address
    import select
    import shutil
    import signal

    from .parallel import typst_used

    if typst_used() or not hasattr(os, "fork"):
        # typst's threads do not survive a fork: a process that has compiled keeps
        # compiling itself
        return lambda: None
    folder = tempfile.mkdtemp(prefix="mechdesign-typst-")
    started = []                         # (kind, address, pid, read end of its ready pipe)
    for kind in ("file", "bytes"):
        address = os.path.join(folder, f"{kind}.socket")
        read_end, write_end = os.pipe()
        pid = os.fork()
        if pid == 0:                     # a compiling process
            code = 0
            try:
                os.close(read_end)
                for *_, other in started:
                    os.close(other)
                signal.signal(signal.SIGINT, signal.SIG_IGN)   # the watch's Ctrl-C stops it
                signal.signal(signal.SIGTERM, signal.SIG_DFL)
                _end_with_parent()
                _serve(address, write_end)
            except BaseException:  # noqa: BLE001 - a dead service only means local compiles
                code = 1
            finally:
                os._exit(code)
        os.close(write_end)
        started.append((kind, address, pid, read_end))
    ready = {}
    for kind, address, _pid, read_end in started:
        with os.fdopen(read_end, "rb") as pipe:
            if select.select([pipe], [], [], 120)[0] and pipe.read(1) == b"1":
                ready[kind] = address
    _service_address = ready

    def stop() -> None:
        global _service_address
        _service_address = {}
        for _kind, _address, pid, _ in started:
            try:
                os.kill(pid, signal.SIGTERM)
                os.waitpid(pid, 0)
            except (ProcessLookupError, ChildProcessError):
                pass
        shutil.rmtree(folder, ignore_errors=True)

    if not ready:       # none started: compile here
        stop()
        return lambda: None
    return stop


def _end_with_parent() -> None:
    """Linux: this process gets SIGKILL when its parent ends, however it ends."""
    try:
        import ctypes
        import signal

        ctypes.CDLL(None, use_errno=True).prctl(1, int(signal.SIGKILL))  # PR_SET_PDEATHSIG
    except Exception:  # noqa: BLE001 - without it, the parent's stop() still ends it
        pass


def _serve(address: str, ready_fd: int) -> None:
    from multiprocessing.connection import Listener

    import typst

    listener = Listener(address, family="AF_UNIX")
    fonts = typst_fonts()
    try:      # the CJK fonts parsed once, before the first report asks for them
        families = cjk_families()
        sample = "x " + chr(0x4E2D)            # a Latin and a CJK glyph
        typst.compile(f'#set text(font: ("{families["serif"]}", "{families["sans"]}"))\n'
                      f'{sample}'.encode("utf-8"), font_paths=fonts)
    except Exception:  # noqa: BLE001 - a warm-up only
        pass
    os.write(ready_fd, b"1")
    os.close(ready_fd)
    while True:
        with listener.accept() as conn:
            try:
                kind, args, options = conn.recv()
            except EOFError:
                continue
            try:
                if kind == "file":
                    out, found = typst.compile_with_warnings(*args, font_paths=fonts, **options)
                    conn.send(("ok", out, [_typst_message(w) for w in found]))
                elif kind == "query":
                    conn.send(("ok", typst.query(*args, font_paths=fonts, **options), []))
                else:
                    conn.send(("ok", typst.compile(*args, font_paths=fonts, **options), []))
            except typst.TypstError as exc:
                conn.send(("error", _typst_message(exc), []))
            except Exception as exc:  # noqa: BLE001 - the client compiles itself
                conn.send(("failed", repr(exc), []))


class _TypstFailed(Exception):
    def __init__(self, message: str):
        super().__init__(message)
        self.message = message


def _service_compile(kind: str, args: tuple, options: dict):
    """(output, warnings) from the compiling process of ``kind`` ("file" or "bytes"; "query":
    a query of a report, answered by the reports' process, whose memo holds the layout it
    has just compiled), or None (no service, or it failed: compile here). Raises
    _TypstFailed with typst's message for an error in the source."""
    address = _service_address.get("file" if kind == "query" else kind)
    if address is None:
        return None
    from multiprocessing.connection import Client

    try:
        with Client(address, family="AF_UNIX") as conn:
            conn.send((kind, args, options))
            status, out, found = conn.recv()
    except (OSError, EOFError):
        return None
    if status == "error":
        raise _TypstFailed(out)
    if status != "ok":
        return None
    return out, found


def cached_compile(source: bytes, **options):
    """``typst.compile(source, **options)`` of a self-contained source (it reads no file),
    from the cache when compiled before (render/cache.py; ``font_paths`` is not part of
    the key: the fonts' identity is)."""
    import typst

    from . import cache

    key = cache.typst_key(source, None, **{k: v for k, v in options.items()
                                            if k != "font_paths"})
    stored = cache.fetch_bytes(key)
    if stored is not None:
        return stored
    try:
        served = _service_compile("bytes", (source,), {k: v for k, v in options.items()
                                                        if k != "font_paths"})
    except _TypstFailed as exc:
        raise typst.TypstError(exc.message) from None
    out = typst.compile(source, **options) if served is None else served[0]
    if isinstance(out, bytes):
        cache.store(key, out)
    return out


def _typst_message(exc: Exception) -> str:
    """Readable text of a typst.TypstError (message, diagnostic and hints)."""
    parts = [getattr(exc, "diagnostic", "") or getattr(exc, "message", "") or str(exc)]
    parts += [f"hint: {hint}" for hint in getattr(exc, "hints", None) or []]
    return "\n".join(part.rstrip() for part in parts if part)


def _use_vector_images(source: str, substitutes: dict[str, str]) -> str:
    """Point typst's image() calls at the vector files that ``substitutes`` maps the
    Markdown's raster previews to (a drawing sheet's PDF for its PNG preview)."""
    for raster, vector in substitutes.items():
        source = source.replace(f"image({json.dumps(raster)}", f"image({json.dumps(vector)}")
    return source


def render_pdf(md_path: Path, pdf_path: Path, metadata: dict, template: Path,
               substitutes: dict[str, str] | None = None) -> None:
    """Render a Markdown file to PDF via pandoc and typst.

    Inputs: the Markdown file (images referenced relative to its directory), the
    output PDF path, the metadata mapping (see module docstring), the pandoc typst
    template and ``substitutes`` (see :func:`compile_pdf`). The PDF is dated
    :func:`source_timestamp` of ``metadata["date"]``: the same input gives the same
    bytes. Raises PdfRenderError if pandoc or typst fails."""
    md_path = Path(md_path).resolve()
    compile_pdf(typst_source(md_path, metadata, template).result(), md_path.parent, pdf_path,
                metadata, substitutes, stem=md_path.stem)


def typst_source(md_path: Path, metadata: dict, template: Path) -> "PendingTypst":
    """pandoc converting a Markdown file to typst, started now (images are not read, so
    the figures may still be being written); ``.result()`` is the source."""
    md_path = Path(md_path).resolve()
    return PendingTypst(md_path.read_text(encoding="utf-8"), template, metadata, md_path.parent)


def _source_file(root: Path, stem: str) -> tuple[int, str]:
    """A new file in ``root`` for the typst source: ``.<stem>.typ`` when free (a report's
    staging folder), else a temporary name. The name matters for speed: typst memoises
    its work by file identity (the path relative to the root), so a warm compiling
    process (the watch) re-uses the layout of what an edit did not change only when the
    source keeps its name from one run to the next (a new name: the whole report laid
    out again, ~2.5 s of CPU for the shaper's instead of ~0.3 s)."""
    path = os.path.join(root, f".{stem}.typ")
    try:
        return os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600), path
    except FileExistsError:
        return tempfile.mkstemp(prefix=f".{stem}-", suffix=".typ", dir=root)


FIGURE_RULES_ON = "#let figure-hold = true\n"
FIGURE_RULES_OFF = "#let figure-hold = false\n"
#: compilations with the held figures given (templates/report.typ: held-given) after the
#: first, at most: the held figures only grow, and the reports need one (slotter, press …)
FIGURE_ROUNDS = 3
#: the warning of a report set by the fallback (its text says "converge": the e2e tests
#: count it as a layout that did not settle)
FELL_BACK = "the figure plan did not converge"


def _compile_report(typ_name: str, root: Path, timestamp: int, stem: str,
                    inputs: dict[str, str]) -> tuple[bytes, list[str]]:
    """(PDF, typst's warnings) of the source file ``typ_name``, compiled once with
    ``inputs`` (typst's sys.inputs) by the compiling process or here."""
    import typst

    from .parallel import note_typst_used

    options = {"root": str(root), "timestamp": timestamp}
    if inputs:
        options["sys_inputs"] = inputs
    try:
        served = _service_compile("file", (typ_name,), options)
    except _TypstFailed as exc:
        raise PdfRenderError(f"typst failed to compile {stem}.md:\n{exc.message}") from None
    if served is not None:
        return served
    note_typst_used()
    try:
        pdf_bytes, found = typst.compile_with_warnings(typ_name, font_paths=typst_fonts(), **options)
    except typst.TypstError as exc:
        raise PdfRenderError(f"typst failed to compile {stem}.md:\n{_typst_message(exc)}") from exc
    return pdf_bytes, [_typst_message(w) for w in found]


def _held_next(typ_name: str, root: Path, inputs: dict[str, str]) -> dict | None:
    """What the last pass of the compilation with ``inputs`` read of its layout
    (templates/report.typ: `<figure-held-next>`): ``held``, the figures it would hold back
    past a table (figure number -> ordinal of the table) or past a derivation ("d" + figure
    number -> the derivation's number, a string: never taken for a table's), and ``far``, the held figures that
    landed more than a page after their text or under a hole; None where it cannot be read."""
    import typst

    options = {"root": str(root), "field": "value", "one": True}
    if inputs:
        options["sys_inputs"] = inputs
    try:
        served = _service_compile("query", (typ_name, "<figure-held-next>"), options)
        if served is None:
            from .parallel import note_typst_used

            note_typst_used()
        found = served[0] if served is not None else typst.query(
            typ_name, "<figure-held-next>", font_paths=typst_fonts(), **options)
        value = json.loads(found)
    except (_TypstFailed, typst.TypstError, ValueError):
        return None
    if not (isinstance(value, dict) and isinstance(value.get("held"), dict)
            and isinstance(value.get("far"), list)):
        return None
    return value


def _settle(typ_name: str, root: Path, timestamp: int, stem: str,
            source: str) -> tuple[bytes, list[str], list[dict]]:
    """(PDF, warnings, rounds) of the report source in ``typ_name``: the fixed point of its
    held figures (templates/report.typ: figure-held).

    Typst lays a document out at most five times; the figure rules read the pass before,
    and a figure held back past a table moves the figures after it, one of which may then
    land between the parts of another table and be held in the next pass: in some reports
    the holds still grow in the fifth pass (slotter zh: figure 14 in the third, figures 1
    and 2 in the fourth, figure 14 past one more table in the fifth) and typst stops
    unsettled. The fixed point is then carried on here, in rounds: the figures the last pass
    would hold (the held ones and those its layout shows between a table's parts) are read
    (`typst query`) and the source is compiled again with them given, standing in every pass
    (so the layout settles as that of a report that holds nothing new), until a round's
    layout settles and holds no figure more. A held figure that landed more than a page after
    its text, or at a page's foot under a blank band, is let go, with the figures held past
    the same table, for good (templates/report.typ: far-figures, hole-figures).
    The holds only grow (a figure is held past a later table only) but for those let go,
    which are never held again, so the rounds end; there are at most FIGURE_ROUNDS of them
    after the first, each a full compilation (about as long as the first). Where they do not
    reach it (a round unsettled without new holds, or the last round still holds more):
    the last settled round's layout, where one settled (its figures held out of the
    tables its holds name); else the source set without the figure rules (nothing held).
    Either is reported as a warning, FELL_BACK. Each round is a dict: held (given), settled.
    Each round is also given the chapters' close plan read from the first compilation
    (templates/report.typ: current-close, `figure-close`), so that it stands in every round
    (textbook_guide_bar zh: planned from typst's third pass, it keeps the fifth from settling).
    At the first fixed point the close plan is read once more from its layout (close-again:
    the held figures moved the chapters' ends; die_cutter en); where it sets a figure smaller,
    the rounds go on with it, and where they reach no fixed point the first one stands."""
    pdf_bytes, found = _compile_report(typ_name, root, timestamp, stem, {})
    rounds = [{"held": None, "settled": not _unsettled(found)}]
    if rounds[0]["settled"] or FIGURE_RULES_ON not in source:
        return pdf_bytes, found, rounds
    given = None                           # the held figures of the last round
    let_go: set[str] = set()               # figures never to hold again
    settled = None                         # (pdf, warnings) of the last settled round
    close = None                           # the close plan, read from the first compilation
                                           # (report.typ: current-close) and once more at the
                                           # first fixed point (close-again)
    fixed = None                           # (pdf, warnings) of a fixed point before close-again
    while True:
        found_next = _held_next(typ_name, root, _inputs(given, close))
        if found_next is None:
            break                                    # nothing read
        if close is None and isinstance(found_next.get("close"), list):
            close = found_next["close"]
        held = {k: t for k, t in found_next["held"].items() if k not in let_go}
        if given is not None:
            # a held figure that landed more than a page after its text (a second table held
            # it on into the next chapter: slotter figure 14) or at a page's foot under a
            # blank band (slotter figure 1) is let go with the figures that wait for the same
            # table: a figure far from its text, or a hole, is the worse defect. So also where
            # the round did not settle (die_cutter zh: figures 17 and 18 held past table 47
            # kept typst's passes from settling and went on far from their text; figure 2
            # held alone settles)
            far = {str(n) for n in found_next["far"]} & set(given)
            tables = {given[k] for k in far}
            let_go |= {k for k, t in given.items() if t in tables}
            held = {k: t for k, t in held.items() if k not in let_go}
            if rounds[-1]["settled"] and not far and held == given:
                if fixed is None and _smaller(close, found_next.get("close-next")):
                    # the close plan read again from this layout sets a chapter's last
                    # figure smaller (templates/report.typ: close-again): once more with it,
                    # the rounds going on from there; where they do not reach a fixed point
                    # this one stands
                    fixed = (pdf_bytes, found)
                    close = found_next["close-next"]
                    pdf_bytes, found = _compile_report(typ_name, root, timestamp, stem, _inputs(given, close))
                    rounds.append({"held": given, "settled": not _unsettled(found), "close": "again"})
                    continue
                return pdf_bytes, found, rounds      # the fixed point
        if held == given or len(rounds) > FIGURE_ROUNDS + (fixed is not None):
            break                                    # nothing new, or no round left
        given = held
        pdf_bytes, found = _compile_report(typ_name, root, timestamp, stem, _inputs(given, close))
        rounds.append({"held": given, "settled": not _unsettled(found)})
        if rounds[-1]["settled"]:
            settled = (pdf_bytes, found)
    if fixed is not None:
        return fixed[0], fixed[1], rounds
    fell = f"{FELL_BACK} in {len(rounds)} compilations"
    if settled is not None:
        return settled[0], settled[1] + [fell + "; set with the held figures of its last settled one"], rounds
    with open(typ_name, "w", encoding="utf-8") as handle:
        handle.write(source.replace(FIGURE_RULES_ON, FIGURE_RULES_OFF, 1))
    pdf_bytes, found = _compile_report(typ_name, root, timestamp, stem, {})
    return pdf_bytes, found + [fell + "; set without the figure rules"], rounds


def _smaller(close: list | None, close_next) -> bool:
    """Whether the close plan read again (templates/report.typ: close-again) sets a figure
    smaller than the plan given."""
    return (isinstance(close, list) and isinstance(close_next, list) and len(close_next) == len(close)
            and any(b < a - 0.5 for a, b in zip(close, close_next)))


def _inputs(given: dict | None, close: list | None) -> dict[str, str]:
    """typst's sys.inputs of a round: the held figures given, and the close plan read from the
    first compilation (templates/report.typ: figure-held, figure-close), the same in every
    round."""
    inputs = {} if given is None else {"figure-held": json.dumps(given, sort_keys=True)}
    if close is not None:
        inputs["figure-close"] = json.dumps(close)
    return inputs


def _unsettled(found: list[str]) -> bool:
    return any("converge" in text for text in found)


def compile_pdf(source: str, root: Path, pdf_path: Path, metadata: dict,
                substitutes: dict[str, str] | None = None, stem: str = "report") -> list[dict]:
    """Compile typst ``source`` (images relative to ``root``) in-process to ``pdf_path``.

    The source is written under a temporary name into ``root`` (the typst root) and
    deleted afterwards; the PDF is written atomically. ``substitutes`` maps images of
    the document (paths relative to ``root``) to vector files placed instead where they
    exist: the drawing sheets' PDFs for their PNG previews. Typst warnings are re-emitted
    as Python warnings. Where typst's layout does not settle with the template's figure rules
    that read the pass before (``#let figure-hold = true``), the held figures are settled in
    rounds (:func:`_settle`). Returns the rounds ([] when the PDF came from the cache).
    Raises PdfRenderError if typst fails."""
    root, pdf_path = Path(root).resolve(), Path(pdf_path).resolve()
    source = _use_vector_images(source, {k: v for k, v in (substitutes or {}).items()
                                         if (root / v).is_file()})
    from . import cache

    timestamp = source_timestamp(metadata.get("date"))
    fd, typ_name = _source_file(root, stem)
    rounds: list[dict] = []
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            handle.write(source)
        # the same source, images and options compiled before: the PDF from the cache
        # (render/cache.py; the typst warnings are stored with it)
        key = cache.typst_key(source, root, skip=Path(typ_name), timestamp=timestamp,
                              format="pdf")
        stored = cache.fetch_bytes(key)
        if stored is not None:
            head, pdf_bytes = stored.split(b"\n", 1)
            typst_warnings = json.loads(head.decode("utf-8"))
        else:
            pdf_bytes, typst_warnings, rounds = _settle(typ_name, root, timestamp, stem, source)
            cache.store(key, json.dumps(typst_warnings).encode("utf-8") + b"\n" + pdf_bytes)
    finally:
        Path(typ_name).unlink(missing_ok=True)

    for text in typst_warnings:
        warnings.warn(f"typst: {text}", stacklevel=3)

    write_bytes(pdf_path, pdf_bytes)
    return rounds
