"""A brief's groups table read from a CSV or XLSX file next to it (a teacher's class table).

::

    groups: {file: class.csv, default: 1}       # or class.xlsx (first sheet, or `sheet: NAME`)

One row per group, one column per overridden field, named by its dotted brief path as an
inline group writes it (``linkage.stroke_H_mm``, ``cam.programme.0.angle_deg``). The column
``group`` (or ``label``) holds each row's label; ``report.student``, ``report.student_id`` and
``report.class`` put the student's name, number and class on the title page and in the
sheets' title blocks. A column whose name starts with ``#`` is a note and ignored.

A cell is read as YAML would read it: ``300`` an integer, ``1.25`` or ``7.0e4`` a number,
``true``/``false`` a truth value, anything else text; a field that only takes text
(``report.student_id``) keeps the cell's text as written, and an empty cell sets nothing.
XLSX cells keep their type (a number stays a number).

Every problem of the file (its columns, labels and rows) is found at once and named by the
file, the row (line number and group label) and the column; a value the brief's model then
rejects is reported at the same place (``class.csv line 4 (group 3), column
linkage.stroke_H_mm: -5 — …``). Reading is plain Python (csv, openpyxl): no numpy.
"""
from __future__ import annotations

import csv
import datetime as _dt
import difflib
import io
import re
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any, Literal, Union, get_args, get_origin

from pydantic import BaseModel

from .groups import GROUPS_KEY, GroupTable

#: Names of the label column (the first one present is used).
LABEL_COLUMNS = ("group", "label")
#: Fields of ``groups`` when the table is a file.
FILE_FIELDS = ("file", "sheet", "default")
SUFFIXES = (".csv", ".xlsx")
MAX_BYTES = 2 * 1024 * 1024   # far above a class table (6 columns × 200 students is ~20 kB)
MAX_ROWS = 1000
MAX_COLUMNS = 200


@dataclass(frozen=True)
class TableProblem:
    path: str
    value: str
    allowed: str


class TableError(ValueError):
    """Every problem found in a class table file (each a :class:`TableProblem`)."""

    def __init__(self, problems: list[TableProblem]):
        self.problems = problems
        super().__init__("\n".join(f"{p.path}: {p.value} — {p.allowed}" for p in problems))


def _fail(path: str, value: str, allowed: str) -> TableError:
    return TableError([TableProblem(path, value, allowed)])


# ------------------------------------------------------------------------ reading the file
def _decode(raw: bytes, name: str) -> str:
    """UTF-8 (with or without the BOM Excel writes), else GB 18030 (Excel's "CSV" on a
    Chinese Windows)."""
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        pass
    try:
        return raw.decode("gb18030")
    except UnicodeDecodeError as exc:
        raise _fail(name, f"byte 0x{raw[exc.start]:02x} at byte {exc.start}",
                    "a CSV file is UTF-8 (or GBK) text; save it as 'CSV UTF-8'") from None


def _read_csv(raw: bytes, name: str) -> tuple[str, list[tuple[int, list[Any]]]]:
    """Rows of a CSV file as (line number, cells); the delimiter is , or ; or tab (as the
    header line uses)."""
    text = _decode(raw, name)
    if "\x00" in text:
        raise _fail(name, "a NUL character", "a CSV file is text; is this the right file?")
    first = text.split("\n", 1)[0]
    delimiter = max((",", ";", "\t"), key=first.count)
    reader = csv.reader(io.StringIO(text, newline=""), delimiter=delimiter)
    rows, start = [], 1
    try:
        for cells in reader:
            rows.append((start, cells))
            start = reader.line_num + 1
    except csv.Error as exc:
        raise _fail(f"{name} line {reader.line_num}", "malformed CSV", str(exc)) from None
    return "line", rows


def _import_openpyxl():
    """openpyxl, imported without numpy when numpy is not loaded yet: openpyxl only uses it
    to recognise numpy numbers when *writing*, and `mechdesign check` stays numpy-free."""
    if "numpy" in sys.modules:
        import openpyxl
        return openpyxl
    sys.modules["numpy"] = None  # type: ignore[assignment]  # `import numpy` → ImportError
    try:
        import openpyxl
    finally:
        del sys.modules["numpy"]
    return openpyxl


def _read_xlsx(path: Path, name: str, sheet: str | None) -> tuple[str, list[tuple[int, list[Any]]]]:
    openpyxl = _import_openpyxl()
    try:
        book = openpyxl.load_workbook(path, read_only=True, data_only=True)
    except Exception as exc:  # noqa: BLE001 - zip, XML and format errors of a broken file
        raise _fail(name, f"cannot be read as XLSX ({type(exc).__name__})",
                    "an Excel workbook saved as .xlsx") from None
    try:
        if sheet is None:
            ws = book.worksheets[0]
        elif sheet in book.sheetnames:
            ws = book[sheet]
        else:
            raise _fail(f"{GROUPS_KEY}.sheet", repr(sheet), f"one of the sheets of {name}: "
                        f"{', '.join(book.sheetnames)}")
        rows = []
        for i, cells in enumerate(ws.iter_rows(values_only=True), start=1):
            if i > MAX_ROWS + 1:
                raise _fail(name, f"more than {MAX_ROWS} rows", "a class table has one row per group")
            rows.append((i, list(cells)))
    finally:
        book.close()
    return "row", rows


# ------------------------------------------------------------------------ the brief's paths
def _options(annotation: Any) -> list[Any]:
    """The alternatives of a field's type (unions flattened, Annotated unwrapped)."""
    if get_origin(annotation) is Annotated:
        return _options(get_args(annotation)[0])
    if get_origin(annotation) is Union or type(annotation).__name__ == "UnionType":
        return [o for a in get_args(annotation) for o in _options(a)]
    return [annotation]


def _is_model(a: Any) -> bool:
    return isinstance(a, type) and issubclass(a, BaseModel)


def _field(model: type[BaseModel], name: str):
    return next((f for k, f in model.model_fields.items() if name in (k, f.alias)), None)


def _children(a: Any, part: str) -> list[Any]:
    """The types one step down ``part`` from type ``a`` (none: no such field)."""
    if _is_model(a):
        f = _field(a, part)
        return [] if f is None else _options(f.annotation)
    origin, args = get_origin(a), get_args(a)
    if origin in (list, tuple) and part.isdigit():
        if origin is tuple and args and args[-1] is not Ellipsis:
            return _options(args[int(part)]) if int(part) < len(args) else []
        return _options(args[0]) if args else [Any]
    if origin is dict and args:
        return _options(args[1])
    return []


def _is_leaf(a: Any) -> bool:
    return not _is_model(a) and get_origin(a) not in (list, tuple, dict)


def target_types(model: type[BaseModel], path: str) -> list[Any] | None:
    """The possible types of the value at dotted ``path`` of a brief (None: no such field,
    or a whole section rather than one value)."""
    types: list[Any] = [model]
    for part in path.split("."):
        types = [c for t in types for c in _children(t, part)]
        if not types:
            return None
    leaves = [t for t in types if _is_leaf(t)]
    return leaves or None


def _text_only(types: list[Any]) -> bool:
    """A field that takes text only (a name, a student number): its cells stay text."""
    def text(t):
        if t is str:
            return True
        return get_origin(t) is Literal and all(isinstance(v, str) for v in get_args(t))
    kinds = [t for t in types if t is not type(None)]
    return bool(kinds) and all(text(t) for t in kinds)


def field_paths(model: type[BaseModel], prefix: str = "", depth: int = 0) -> list[str]:
    """Every value's dotted path in a brief model (list items as index 0)."""
    out: list[str] = []
    if depth > 6:
        return out
    for k, f in model.model_fields.items():
        name = f"{prefix}{f.alias or k}"
        for t in _options(f.annotation):
            if _is_model(t):
                out += field_paths(t, name + ".", depth + 1)
            elif get_origin(t) is list and get_args(t) and _is_model(get_args(t)[0]):
                out += field_paths(get_args(t)[0], name + ".0.", depth + 1)
            elif _is_leaf(t) and name not in out:
                out.append(name)
    return list(dict.fromkeys(out))


def nearest_paths(model: type[BaseModel], column: str, n: int = 3) -> list[str]:
    """The brief paths a mistyped column most likely meant: those ending in the same field
    name, then the closest by spelling."""
    paths = field_paths(model)
    leaf = {p: p.rsplit(".", 1)[-1].lower() for p in paths}
    last = column.rsplit(".", 1)[-1].lower()
    same = [p for p in paths if leaf[p] == last]
    close = difflib.get_close_matches(column, paths, n=n, cutoff=0.5)
    names = set(difflib.get_close_matches(last, sorted(set(leaf.values())), n=n, cutoff=0.6))
    by_name = [p for p in paths if leaf[p] in names]
    return list(dict.fromkeys(same + close + by_name))[:n]


# ------------------------------------------------------------------------ cells
_INT = re.compile(r"^[-+]?[0-9]+$")
_FLOAT = re.compile(r"^[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?$")


def cell_value(value: Any, types: list[Any] | None) -> Any:
    """A cell as the brief's value: None (empty: not set), a number, true/false or text."""
    if value is None:
        return None
    text_only = types is not None and _text_only(types)
    if isinstance(value, (_dt.datetime, _dt.date)):
        day = value.date() if isinstance(value, _dt.datetime) and value.time() == _dt.time() else value
        return day.isoformat()
    if isinstance(value, bool):
        return value
    if isinstance(value, (int, float)):
        if text_only:   # a student number stored as a number in Excel
            return str(int(value)) if float(value).is_integer() else str(value)
        return value
    text = str(value).strip()
    if not text:
        return None
    if text_only:
        return text
    if _INT.match(text):
        return int(text)
    if _FLOAT.match(text):
        return float(text)
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    return text


def _label(value: Any) -> str | None:
    if value is None or isinstance(value, bool):
        return None
    if isinstance(value, float) and value.is_integer():
        value = int(value)
    text = str(value).strip()
    return text or None


# ------------------------------------------------------------------------ the table
def read_group_file(raw: dict, brief_path: str | Path, model: type[BaseModel] | None) -> GroupTable:
    """The groups table of ``groups: {file: …}`` (``raw``) of the brief at ``brief_path``;
    ``model``: the brief's model, to check the columns and read the cells by the fields'
    types (None when the brief's machine is unknown: the brief reports that itself).
    Raises :class:`TableError` with every problem found."""
    extra = [str(k) for k in raw if k not in FILE_FIELDS and k != "variants"]
    if extra:
        raise _fail(f"{GROUPS_KEY}.{extra[0]}", "unknown field",
                    f"allowed here: {', '.join(FILE_FIELDS)}")
    if "variants" in raw:
        raise _fail(f"{GROUPS_KEY}.variants", "given with `file`",
                    "the groups come either from `file` (a class table) or from `variants`")
    file, sheet = raw.get("file"), raw.get("sheet")
    if not isinstance(file, str) or not file.strip():
        raise _fail(f"{GROUPS_KEY}.file", repr(file)[:60],
                    "the name of a .csv or .xlsx file next to the brief, e.g. class.csv")
    if sheet is not None and not isinstance(sheet, str):
        raise _fail(f"{GROUPS_KEY}.sheet", repr(sheet)[:60], "the name of a sheet of the .xlsx file")
    name = file.strip()
    path = Path(brief_path).parent / name
    suffix = path.suffix.lower()
    if suffix not in SUFFIXES:
        raise _fail(f"{GROUPS_KEY}.file", repr(name),
                    "a .csv or .xlsx file (save an .xls or .ods table as .xlsx or CSV)")
    if sheet is not None and suffix != ".xlsx":
        raise _fail(f"{GROUPS_KEY}.sheet", repr(sheet), "only an .xlsx file has sheets")
    try:
        size = path.stat().st_size if path.is_file() else None
    except OSError:
        size = None
    if size is None:
        raise _fail(f"{GROUPS_KEY}.file", repr(name),
                    f"no such file next to the brief (looked for {path})")
    if size > MAX_BYTES:
        raise _fail(name, f"more than {MAX_BYTES} bytes", "a class table is a few kB; is this the right file?")
    if suffix == ".csv":
        try:
            raw_bytes = path.read_bytes()
        except OSError as exc:
            raise _fail(name, "cannot be read", exc.strerror or str(exc)) from None
        word, rows = _read_csv(raw_bytes, name)
    else:
        word, rows = _read_xlsx(path, name, sheet)
    table = _table(rows, name, word, model)
    default = raw.get("default")
    if default is not None:
        label = _label(default)
        if label not in table.variants:
            raise _fail(f"{GROUPS_KEY}.default", repr(default)[:60],
                        f"one of the groups of {name}: {', '.join(table.variants)}")
        table = GroupTable(label, table.variants, table.origin)
    return table


def _table(rows: list[tuple[int, list[Any]]], name: str, word: str,
           model: type[BaseModel] | None) -> GroupTable:
    rows = [(n, cells) for n, cells in rows if any(_label(c) is not None for c in cells)]
    if not rows:
        raise _fail(name, "empty", "a header row of column names, then one row per group")
    if len(rows) > MAX_ROWS + 1:
        raise _fail(name, f"more than {MAX_ROWS} rows", "a class table has one row per group")
    head_line, head = rows[0]
    where_head = f"{name} {word} {head_line}"
    problems: list[TableProblem] = []
    columns: dict[int, str] = {}
    for i, cell in enumerate(head):
        col = _label(cell)
        if col is None:
            if any(i < len(c) and _label(c[i]) is not None for _, c in rows[1:]):
                problems.append(TableProblem(f"{where_head}, column {i + 1}", "no name",
                                             "every column with values needs a name in the header "
                                             "row (a dotted brief path such as linkage.stroke_H_mm)"))
            continue
        if col.startswith("#"):
            continue
        if col in columns.values():
            problems.append(TableProblem(f"{where_head}, column {col}", "given twice",
                                         "each column once"))
            continue
        columns[i] = col
    if len(columns) > MAX_COLUMNS:
        raise _fail(where_head, f"{len(columns)} columns", f"at most {MAX_COLUMNS}")
    label_col = next((i for i, c in columns.items() if c.lower() in LABEL_COLUMNS), None)
    if label_col is None:
        problems.append(TableProblem(where_head, f"columns {', '.join(columns.values())}"[:120],
                                     "a column named `group` (or `label`) with each row's group label"))
    types: dict[int, list[Any] | None] = {}
    for i, col in columns.items():
        if i == label_col:
            continue
        parts = col.split(".")
        if parts[0] in ("machine", GROUPS_KEY) or any(p == "" for p in parts):
            problems.append(TableProblem(f"{where_head}, column {col}", repr(col),
                                         "a column is a dotted brief path (not machine or groups), "
                                         "e.g. linkage.stroke_H_mm"))
            continue
        if model is not None:
            types[i] = target_types(model, col)
            if types[i] is None:
                near = nearest_paths(model, col)
                hint = f"; nearest: {', '.join(near)}" if near else ""
                problems.append(TableProblem(
                    f"{where_head}, column {col}", "not a field of the brief",
                    f"a column is a dotted path to one value of the brief{hint}"))
                continue
        else:
            types[i] = None
    variants: dict[str, dict] = {}
    origin: dict[str, dict[str, str]] = {}
    first_line: dict[str, int] = {}
    for line, cells in rows[1:]:
        extra = [c for c in cells[len(head):] if _label(c) is not None]
        if extra:
            problems.append(TableProblem(f"{name} {word} {line}", f"{len(cells)} cells",
                                         f"at most {len(head)}, one per column of the header"))
        label = _label(cells[label_col]) if label_col is not None and label_col < len(cells) else None
        if label_col is not None and label is None:
            problems.append(TableProblem(f"{name} {word} {line}, column {columns[label_col]}",
                                         "empty", "every row needs its group label"))
            continue
        if label is None:
            continue
        if label in variants:
            problems.append(TableProblem(f"{name} {word} {line}, column {columns[label_col]}",
                                         repr(label), f"labels must be unique (also on "
                                                      f"{word} {first_line[label]})"))
            continue
        first_line[label] = line
        overrides, where = {}, {}
        for i, col in columns.items():
            if i == label_col or i not in types or i >= len(cells):
                continue
            value = cell_value(cells[i], types[i])
            if value is None:
                continue
            overrides[col] = value
            where[col] = f"{name} {word} {line} (group {label}), column {col}"
        variants[label] = overrides
        origin[label] = where
    if problems:
        raise TableError(problems)
    if not variants:
        raise _fail(name, "no rows", "one row per group below the header")
    return GroupTable(None, variants, origin)
