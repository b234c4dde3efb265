"""Data groups (分组 / 方案): one brief, several parameter sets.

A course table gives each student one set of data for the same machine. A brief may
carry the table as a top-level ``groups`` section::

    groups:
      default: 1                    # the group `mechdesign run` uses without --group
      variants:
        1: {}                       # the brief as written
        2: {pusher.stroke_H_mm: 200, pusher.time_ratio_K: 1.3}
        III:                        # labels may be numbers or text (方案 I, II, III)
          pusher: {stroke_H_mm: 240}

or, for a whole class, ``groups: {file: class.csv}``: the same table as a CSV or XLSX file
next to the brief, one row per group (see :mod:`mechdesign.brief.class_table`).

A variant overrides fields of the brief: a key is a dotted path (``section.field``,
list items by index: ``cam.programme.0.angle_deg``) or a nested mapping merged into
the section. Overrides are applied to the YAML data *before* validation, so a wrong
value in a group is reported at ``groups.variants.LABEL.path``.
"""
from __future__ import annotations

import copy
from dataclasses import dataclass, field
from typing import Any

#: Top-level key of the groups table in a brief.
GROUPS_KEY = "groups"


class GroupError(ValueError):
    """A malformed groups table or an unknown group; ``path``, ``value`` and ``allowed``
    say which field, what was found and what is allowed."""

    def __init__(self, path: str, value: str, allowed: str):
        self.path, self.value, self.allowed = path, value, allowed
        super().__init__(f"{path}: {value} — {allowed}")


@dataclass(frozen=True)
class GroupTable:
    default: str | None
    variants: dict[str, dict]      # label (as text) → overrides
    #: label → field path → where a class table file sets it ("class.csv line 4 (group 3),
    #: column pusher.stroke_H_mm"); empty for an inline table (``groups.variants.…``)
    origin: dict[str, dict[str, str]] = field(default_factory=dict)

    @property
    def labels(self) -> list[str]:
        return list(self.variants)

    def where(self, label: str, path: str) -> str:
        """Where group ``label`` sets the field at dotted ``path``, for messages."""
        found = self.origin.get(label, {}).get(path)
        return found if found is not None else f"{GROUPS_KEY}.variants.{label}.{path}"


def _label(value: Any) -> str | None:
    if isinstance(value, bool) or not isinstance(value, (int, str)):
        return None
    text = str(value).strip()
    return text or None


def parse_groups(raw: Any) -> GroupTable:
    """Check the shape of a ``groups`` section; return it with labels as text."""
    where = GROUPS_KEY
    if not isinstance(raw, dict):
        raise GroupError(where, type(raw).__name__,
                         "a mapping with `variants` (label → overrides) and an optional `default`")
    extra = sorted(str(k) for k in raw if k not in ("default", "variants"))
    if extra:
        raise GroupError(f"{where}.{extra[0]}", "unknown field", "allowed here: default, variants (or file, sheet, default for a "
                         "class table file)")
    variants = raw.get("variants")
    if not isinstance(variants, dict) or not variants:
        raise GroupError(f"{where}.variants", "missing" if variants is None else repr(variants)[:60],
                         "a non-empty mapping: group label → mapping of overridden fields "
                         "(or `file: class.csv`, a class table next to the brief)")
    table: dict[str, dict] = {}
    for key, overrides in variants.items():
        label = _label(key)
        if label is None:
            raise GroupError(f"{where}.variants", repr(key)[:60], "a group label is a number or text")
        if label in table:
            raise GroupError(f"{where}.variants.{label}", "given twice", "labels must be unique")
        if overrides is None:
            overrides = {}
        if not isinstance(overrides, dict):
            raise GroupError(f"{where}.variants.{label}", repr(overrides)[:60],
                             "a mapping of overridden fields, e.g. {pusher.stroke_H_mm: 200}")
        table[label] = overrides
    default = None
    if "default" in raw and raw["default"] is not None:
        default = _label(raw["default"])
        if default not in table:
            raise GroupError(f"{where}.default", repr(raw["default"])[:60],
                             f"one of the groups: {', '.join(table)}")
    return GroupTable(default, table)


def _flatten(overrides: dict, prefix: tuple = ()) -> list[tuple[tuple, Any]]:
    """(path, value) pairs; dotted keys split; nested mappings recurse."""
    out = []
    for key, value in overrides.items():
        if not isinstance(key, (str, int)) or isinstance(key, bool):
            raise GroupError(".".join(map(str, prefix)) or "(group)", repr(key)[:60],
                             "a field name or dotted path")
        parts = tuple(p for p in str(key).split(".")) if isinstance(key, str) else (key,)
        if any(p == "" for p in parts):
            raise GroupError(".".join(map(str, prefix + parts)), repr(key)[:60],
                             "a dotted path of field names, e.g. pusher.stroke_H_mm")
        if isinstance(value, dict) and value:
            out += _flatten(value, prefix + parts)
        else:
            out.append((prefix + parts, value))
    return out


def apply_group(data: dict, table: GroupTable, label: str) -> tuple[dict, dict[str, str]]:
    """The brief's data with group ``label``'s overrides applied, and a map from each
    overridden field path (``pusher.stroke_H_mm``) to where it was set
    (``groups.variants.2.pusher.stroke_H_mm``)."""
    result = copy.deepcopy(data)
    located: dict[str, str] = {}
    base = f"{GROUPS_KEY}.variants.{label}"
    for path, value in _flatten(table.variants[label]):
        dotted = ".".join(map(str, path))
        here = table.where(label, dotted)
        if path[0] in ("machine", GROUPS_KEY):
            raise GroupError(here, repr(value)[:60],
                             "a group cannot change the machine or the groups table")
        node: Any = result
        for i, part in enumerate(path[:-1]):
            node = _step(node, part, where=here if dotted in table.origin.get(label, {})
                         else f"{base}.{'.'.join(map(str, path[:i + 1]))}")
        last = path[-1]
        if isinstance(node, list):
            index = _index(node, last, here)
            node[index] = copy.deepcopy(value)
        elif isinstance(node, dict):
            node[last] = copy.deepcopy(value)
        else:
            raise GroupError(here, repr(node)[:60],
                             f"{'.'.join(map(str, path[:-1]))} is a value, not a section")
        located[dotted] = here
    return result, located


def _index(node: list, part: Any, where: str) -> int:
    try:
        index = int(part)
    except (TypeError, ValueError):
        raise GroupError(where, repr(part), "a list item is addressed by its index (0, 1, …)") from None
    if not 0 <= index < len(node):
        raise GroupError(where, str(index), f"an index from 0 to {len(node) - 1}")
    return index


def _step(node: Any, part: Any, *, where: str) -> Any:
    """One step down a group's path; a section the brief lacks is created."""
    if isinstance(node, list):
        return node[_index(node, part, where)]
    if isinstance(node, dict):
        if part not in node or node[part] is None:
            node[part] = {}
        return node[part]
    raise GroupError(where, repr(node)[:60], "this is a value, not a section")


def choose(table: GroupTable | None, group: str | None) -> str | None:
    """The group to run: ``group`` if given (it must exist), else the table's default."""
    if group is not None:
        group = str(group).strip()
        if table is None:
            raise GroupError("--group", repr(group), "this brief has no `groups` table")
        if group not in table.variants:
            raise GroupError("--group", repr(group), f"one of the brief's groups: {', '.join(table.labels)}")
        return group
    return None if table is None else table.default
