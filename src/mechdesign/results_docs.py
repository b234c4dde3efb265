"""docs/results.md, generated from the typed results of every machine.

Each machine's registry entry names its results class (a frozen dataclass); every field
states its unit and meaning in its metadata (:func:`mechdesign.results.q`). This module
walks those classes and writes one table per machine:

    python -m mechdesign.results_docs > docs/results.md

A test keeps docs/results.md equal to this output, and another that every numeric field
states its unit.
"""
from __future__ import annotations

import dataclasses
import sys
import types
import typing
from typing import Any, Literal, Union

import numpy as np

from .results import SCHEMA, UNITS_NOTE

NUMERIC = (float, int, complex, np.ndarray)
LEAF = NUMERIC + (str, bool, type(None))


def _strip_optional(tp):
    origin = typing.get_origin(tp)
    if origin in (Union, types.UnionType):
        args = [a for a in typing.get_args(tp) if a is not type(None)]
        if len(args) == 1:
            return _strip_optional(args[0])
    return tp


def _kind(tp) -> str:
    tp = _strip_optional(tp)
    origin = typing.get_origin(tp)
    if dataclasses.is_dataclass(tp):
        return "dataclass"
    if origin in (list, tuple) or tp in (list, tuple):
        return "list"
    if origin is dict or tp is dict:
        return "dict"
    if origin is Literal:
        return "leaf"
    return "leaf"


def _item(tp):
    tp = _strip_optional(tp)
    args = [a for a in typing.get_args(tp) if a is not Ellipsis]
    return args[-1] if args else Any


def rows(cls, prefix: str = "", seen: tuple = ()) -> list[tuple[str, str, str, Any]]:
    """(key path, unit, meaning, type) of every field of ``cls``, nested ones included."""
    out = []
    hints = typing.get_type_hints(cls)
    for f in dataclasses.fields(cls):
        if f.metadata.get("skip"):
            continue
        tp = hints.get(f.name, Any)
        path = f"{prefix}{f.name}"
        unit, doc = f.metadata.get("unit"), f.metadata.get("doc", "")
        kind = _kind(tp)
        inner = _strip_optional(tp)
        if kind == "dataclass" and inner not in seen:
            if doc:
                out.append((path, "", doc, tp))
            out += rows(inner, path + ".", seen + (inner,))
        elif kind == "list" and dataclasses.is_dataclass(_strip_optional(_item(tp))):
            out.append((path + "[]", "", doc, tp))
            out += rows(_strip_optional(_item(tp)), path + "[].", seen)
        elif kind == "dict" and dataclasses.is_dataclass(_strip_optional(_item(tp))):
            out.append((path + ".‹name›", "", doc, tp))
            out += rows(_strip_optional(_item(tp)), path + ".‹name›.", seen)
        else:
            out.append((path, unit, doc, tp))
    for name, unit, doc in getattr(cls, "PLAIN_EXTRA", ()):   # keys its __plain__ adds
        out.append((f"{prefix}{name}", unit, doc, str))
    return out


def missing_units(cls) -> list[str]:
    """Numeric fields (numbers, arrays, lists/dicts of numbers) that state no unit."""
    bad = []
    for path, unit, _doc, tp in rows(cls):
        inner = _strip_optional(tp)
        leafs = [inner] + [_strip_optional(a) for a in typing.get_args(inner)]
        numeric = any(isinstance(t, type) and issubclass(t, NUMERIC) for t in leafs)
        if numeric and unit is None:
            bad.append(path)
    return bad


def _unit_cell(unit: str | None) -> str:
    if unit is None or unit == "":
        return "—"
    return unit


def markdown() -> str:
    from .registry import entry, names, resolve

    lines = [f"# `results.json` schema (`{SCHEMA}`)", "",
             "Written beside every report; generated from the typed results of each machine "
             "(`python -m mechdesign.results_docs > docs/results.md`).",
             f"Units: {UNITS_NOTE}. Angles are counter-clockwise from +x; angular velocities and "
             "accelerations counter-clockwise positive; `null` stands for a value that could "
             "not be computed. Arrays over the crank angle hold the uniform grid over one "
             "revolution unless the key says otherwise.", "",
             "Every document starts with `schema`, `machine`, `units` and, for a data group, "
             "`data_group`.", "",
             "A finding (the `warnings[]` entries, a verification's `failed[]`) holds codes and "
             "data, not prose: its `code`, the catalogue message `msgid` (the English text of "
             "`locale/*.po`, a `str.format` template) with its `context`, the message's fields "
             "`args` and the brief `field`; `text` is the message rendered in English. The file "
             "is the same whatever the report's language; "
             "`mechdesign.stages.findings.Finding(**{k: v for k, v in entry.items() if k != "
             "\"text\"}).text(\"zh\")` renders an entry in another language (zh, en, zh_TW).", ""]
    for name in names():
        e = entry(name)
        if not e.results:
            continue
        cls = resolve(e.results)
        doc = (cls.__doc__ or "").strip()
        lines += [f"## {name} (`\"machine\": \"{name}\"`)", ""]
        if doc:
            lines += [" ".join(doc.split()), ""]
        lines += ["| key | unit | meaning |", "|---|---|---|"]
        for path, unit, meaning, _tp in rows(cls):
            if path in ("schema", "machine", "units", "data_group"):
                continue
            text = ' '.join(meaning.split()).replace('|', '\\|')
            lines.append(f"| `{path}` | {_unit_cell(unit)} | {text} |")
        lines.append("")
    from .stages.linkage import AnalysisRequests

    lines += ["## Every linkage machine: `analysis_requests`", "",
              "Present when the brief's `analysis` section asks for positions by crank angle "
              "(`positions_deg`), by event (`events`) or for named points (`points`). "
              + " ".join((AnalysisRequests.__doc__ or "").split()), "",
              "| key | unit | meaning |", "|---|---|---|"]
    for path, unit, meaning, _tp in rows(AnalysisRequests, "analysis_requests."):
        text = ' '.join(meaning.split()).replace('|', '\\|')
        lines.append(f"| `{path}` | {_unit_cell(unit)} | {text} |")
    lines.append("")
    return "\n".join(lines)


if __name__ == "__main__":
    sys.stdout.write(markdown())
