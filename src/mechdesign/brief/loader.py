"""Load a YAML design brief safely and validate it completely before any computation.

Every problem becomes one :class:`BriefProblem` line naming the field path, the value
found and what is allowed; all problems are collected and raised together as a
:class:`BriefError`.

A problem's path is a dotted path into the brief's data (``linkage.stroke_H_mm``,
``cam.programme.2.angle_deg``; a value set by a data group is reported where the group
sets it, ``groups.variants.2.pusher.stroke_H_mm``), or one of the special paths
``(file)`` (the file cannot be read as a brief: missing, a folder, too large, binary, not
UTF-8, empty), ``(top level)`` (the data are not a mapping, or a check of the whole
brief), ``line L, column C`` (invalid YAML) and ``--group`` (an unknown group).

Malformed or hostile files are rejected within a fraction of a second: the file size,
the number of values (aliases counted expanded: no "billion laughs"), the items of one
list or mapping, the nesting depth and the key length are limited while the YAML is
composed (see ``MAX_*``), before anything walks the data.
"""
from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, get_args

import yaml
from pydantic import BaseModel, ValidationError

from ..registry import Lookup, resolve
from .class_table import TableError, read_group_file
from .groups import GROUPS_KEY, GroupError, GroupTable, apply_group, choose, parse_groups


#: Machine name → brief model (machines register in :mod:`mechdesign.registry`).
BRIEF_MODELS: Mapping[str, type[BaseModel]] = Lookup(lambda e: resolve(e.brief))


@dataclass(frozen=True)
class BriefProblem:
    """One problem: the field ``path``, the ``value`` found and what is ``allowed`` there
    (English; ``allowed_zh`` the same in Chinese, when known)."""

    path: str
    value: str
    allowed: str
    allowed_zh: str | None = None

    def __str__(self) -> str:
        if not self.value:
            return f"{self.path}: {self.allowed}"
        return f"{self.path}: {self.value} — {self.allowed}"

    def text(self, lang: str) -> str:
        """The line in ``lang`` ("zh" or "en"); the value "missing" is said in Chinese too."""
        if lang != "zh":
            return str(self)
        value = {"missing": "缺少", "empty": "空（未填值）", "the whole section": "整节",
                 "a mapping (section)": "映射（一节）"}.get(self.value, self.value)
        if not value:
            return f"{self.path}：{self.allowed_zh or self.allowed}"
        return f"{self.path}：{value} — {self.allowed_zh or self.allowed}"


class BriefError(ValueError):
    """One or more problems in a brief; ``str()`` lists them in English, one per line,
    :meth:`text` in the report's language."""

    def __init__(self, source: str, problems: list[BriefProblem]):
        self.source, self.problems = source, problems
        head = f"{source}: {len(problems)} problem{'s' if len(problems) != 1 else ''} in the brief"
        super().__init__("\n".join([head] + [f"  {p}" for p in problems]))

    def text(self, lang: str) -> str:
        if lang != "zh":
            return str(self)
        head = f"{self.source}：任务书中有 {len(self.problems)} 处问题"
        return "\n".join([head] + [f"  {p.text('zh')}" for p in self.problems])


class FeasibilityError(BriefError):
    """The brief is valid but its data admit no design: every problem the machine's
    feasibility checks found (run once per run, after validation), each at its field."""

    def __init__(self, source: str, problems: list[BriefProblem]):
        super().__init__(source, problems)
        n = len(problems)
        head = (f"{source}: the design is infeasible with the brief's data "
                f"({n} problem{'s' if n != 1 else ''})")
        self.args = ("\n".join([head] + [f"  {p}" for p in problems]),)

    def __str__(self) -> str:
        return self.args[0]

    def text(self, lang: str) -> str:
        if lang != "zh":
            return str(self)
        head = f"{self.source}：按任务书数据无法完成设计（{len(self.problems)} 处问题）"
        return "\n".join([head] + [f"  {p.text('zh')}" for p in self.problems])


def value_at(brief: BaseModel, path: str) -> str:
    """The value at the dotted field ``path`` of a validated brief, as a problem line shows
    it ("" for a whole section or a path that is not there)."""
    node: Any = brief
    for part in path.split("."):
        if isinstance(node, BaseModel):
            fields = type(node).model_fields
            name = next((k for k, f in fields.items() if part in (k, f.alias)), None)
            if name is None:
                return ""
            node = getattr(node, name)
        elif isinstance(node, (list, tuple)) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        else:
            return ""
    if isinstance(node, (BaseModel, list, tuple, dict)):
        return ""
    return f"{node:g}" if isinstance(node, float) else _show(node)


def located_problems(problems: list[BriefProblem], brief: BaseModel,
                     located: dict[str, str] | None = None) -> list[BriefProblem]:
    """``problems`` found on a validated brief, each with its value filled in from the
    brief where the check left it empty and, when a data group set the field, reported
    where the group sets it (``groups.variants.3.pusher.stroke_H_mm``)."""
    out = []
    for p in problems:
        if not p.value:
            p = replace(p, value=value_at(brief, p.path))
        out.append(_relocate(p, located) if located else p)
    return out


#: Limits on a brief file, far above any real brief (the largest example has 11 kB and
#: about 600 values) and low enough that a malformed or hostile file is rejected in a
#: fraction of a second: a file of junk, an alias bomb, a huge list, deep nesting.
MAX_BYTES = 256 * 1024
MAX_VALUES = 5000          # values (numbers, texts, lists, mappings), aliases counted expanded
MAX_ITEMS = 500            # items of one list or mapping
MAX_DEPTH = 30             # lists and mappings inside each other
MAX_KEY_CHARS = 100        # characters of one key
MAX_DIGITS = 300           # digits of an integer; more is read as inf (beyond any float)


class _LimitError(yaml.YAMLError):
    """The YAML data break one of the limits above, at field ``path``."""

    def __init__(self, path: list[str], value: str, allowed: str, allowed_zh: str):
        super().__init__(f"{value}: {allowed}")
        self.path = ".".join(path) or "(top level)"
        self.value, self.allowed, self.allowed_zh = value, allowed, allowed_zh


class _UniqueKeyLoader(yaml.SafeLoader):
    """Safe loader that rejects a key given twice in one mapping (YAML keeps the last) and
    enforces the limits above while the file is composed, naming the field path."""

    def __init__(self, stream):
        super().__init__(stream)
        self._path: list[str] = []
        self._values = 0

    def _count(self, n: int) -> None:
        self._values += n
        if self._values > MAX_VALUES:
            raise _LimitError(self._path, f"more than {MAX_VALUES} values",
                              "a brief holds at most that many values (anchors/aliases counted "
                              "each time they are used)",
                              f"任务书至多 {MAX_VALUES} 个值（锚点/别名每用一次都计数）")

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            anchor = self.peek_event().anchor
            node = self.anchors.get(anchor)
            if node is not None:
                size = getattr(node, "_md_size", None)
                if size is None:
                    raise _LimitError(self._path, f"*{anchor}",
                                      "an alias cannot refer to the list or mapping that contains it",
                                      "别名不能引用包含它自身的列表或映射")
                self._count(size)
            return super().compose_node(parent, index)  # an undefined alias: YAML's error
        if self.check_event(yaml.SequenceStartEvent, yaml.MappingStartEvent) \
                and len(self._path) >= MAX_DEPTH:
            raise _LimitError(self._path, f"lists or mappings nested more than {MAX_DEPTH} deep",
                              "a brief nests sections a few levels deep",
                              f"列表或映射嵌套超过 {MAX_DEPTH} 层；任务书只有几层")
        self._count(1)
        return super().compose_node(parent, index)

    def compose_scalar_node(self, anchor):
        node = super().compose_scalar_node(anchor)
        node._md_size = 1
        return node

    def _too_many(self, what: str, zh: str):
        return _LimitError(self._path, f"a {what} of more than {MAX_ITEMS} items",
                           f"no {what} in a brief is that long",
                           f"{zh}超过 {MAX_ITEMS} 项；任务书中没有这么长的{zh}")

    def compose_sequence_node(self, anchor):
        start = self.get_event()
        tag = start.tag
        if tag is None or tag == "!":
            tag = self.resolve(yaml.SequenceNode, None, start.implicit)
        node = yaml.SequenceNode(tag, [], start.start_mark, None, flow_style=start.flow_style)
        if anchor is not None:
            self.anchors[anchor] = node
        size = 1
        while not self.check_event(yaml.SequenceEndEvent):
            index = len(node.value)
            if index >= MAX_ITEMS:
                raise self._too_many("list", "列表")
            self._path.append(str(index))
            child = self.compose_node(node, index)
            self._path.pop()
            node.value.append(child)
            size += child._md_size
        node.end_mark = self.get_event().end_mark
        node._md_size = size
        return node

    def compose_mapping_node(self, anchor):
        start = self.get_event()
        tag = start.tag
        if tag is None or tag == "!":
            tag = self.resolve(yaml.MappingNode, None, start.implicit)
        node = yaml.MappingNode(tag, [], start.start_mark, None, flow_style=start.flow_style)
        if anchor is not None:
            self.anchors[anchor] = node
        size = 1
        while not self.check_event(yaml.MappingEndEvent):
            if len(node.value) >= MAX_ITEMS:
                raise self._too_many("mapping", "映射")
            key = self.compose_node(node, None)
            if not isinstance(key, yaml.ScalarNode):
                raise _LimitError(self._path, "a list or mapping used as a key",
                                  "a key is a field name (or a group label)",
                                  "键须为字段名（或分组标签），不能是列表或映射")
            if len(key.value) > MAX_KEY_CHARS:
                raise _LimitError(self._path, f"a key of {len(key.value)} characters "
                                  f"({key.value[:20]!r}…)", f"a key has at most {MAX_KEY_CHARS} characters",
                                  f"键至多 {MAX_KEY_CHARS} 个字符")
            self._path.append(key.value)
            value = self.compose_node(node, key)
            self._path.pop()
            node.value.append((key, value))
            size += key._md_size + value._md_size
        node.end_mark = self.get_event().end_mark
        node._md_size = size
        return node

    def construct_object(self, node, deep=False):
        try:
            return super().construct_object(node, deep=deep)
        except yaml.YAMLError:
            raise
        except Exception as exc:  # noqa: BLE001 - e.g. `!!float abc`, `!!timestamp hello`
            what = node.value if isinstance(node, yaml.ScalarNode) else node.id
            raise yaml.constructor.ConstructorError(
                None, None, f"{str(what)[:40]!r} cannot be read as {node.tag.rsplit(':', 1)[-1]} "
                f"({type(exc).__name__}: {str(exc)[:80]})", node.start_mark) from None

    def construct_yaml_int(self, node):
        # Beyond any float: read as ±inf, which the fields refuse by name. Python itself
        # refuses to read (or print) a decimal integer of more than 4300 digits; 0x…, 0o…
        # and 0b… have no such limit, so their size is checked after reading.
        text = str(node.value)
        inf = float("-inf") if text.lstrip().startswith("-") else float("inf")
        if sum(c.isdigit() for c in text) > MAX_DIGITS:
            return inf
        value = super().construct_yaml_int(node)
        return inf if abs(value).bit_length() > MAX_DIGITS * 10 // 3 else value

    def construct_yaml_timestamp(self, node):
        try:
            return super().construct_yaml_timestamp(node)
        except (ValueError, AttributeError):  # 2026-13-45 looks like a date but is none: keep the text
            return self.construct_scalar(node)


_MERGE_TAG = "tag:yaml.org,2002:merge"


def _construct_mapping(loader: _UniqueKeyLoader, node: yaml.MappingNode, deep: bool = False):
    seen: dict[Any, int] = {}
    for key_node, _ in node.value:
        if key_node.tag == _MERGE_TAG:    # `<<: *base` merges a mapping (its keys may repeat)
            continue
        key = loader.construct_object(key_node, deep=deep)
        try:
            again = key in seen
        except TypeError:
            raise yaml.constructor.ConstructorError(
                None, None, f"the key {str(key)[:40]!r} is not a field name",
                key_node.start_mark) from None
        if again:
            raise yaml.constructor.ConstructorError(
                None, None, f"key '{key}' appears twice (lines {seen[key]} and "
                f"{key_node.start_mark.line + 1})", key_node.start_mark)
        seen[key] = key_node.start_mark.line + 1
    return loader.construct_mapping(node, deep=deep)


_UniqueKeyLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)
_UniqueKeyLoader.add_constructor("tag:yaml.org,2002:int", _UniqueKeyLoader.construct_yaml_int)
_UniqueKeyLoader.add_constructor("tag:yaml.org,2002:timestamp",
                                 _UniqueKeyLoader.construct_yaml_timestamp)
# YAML 1.1 (PyYAML) reads 7.0e4 or 1e5 as strings; read them as numbers, as YAML 1.2 does.
_UniqueKeyLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?(?:[0-9][0-9_]*)(?:\.[0-9_]*)?[eE][-+]?[0-9]+$"),
    list("-+0123456789"))


def _show(value: Any) -> str:
    text = repr(value) if isinstance(value, str) else str(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _model_of(annotation: Any) -> Any:
    """The brief section inside ``annotation``: itself, or the model in Optional[...],
    Union[...] or list[...]."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in get_args(annotation):
        found = _model_of(arg)
        if found is not None:
            return found
    return None


def _field_info(model: type[BaseModel], loc: tuple) -> tuple[type[BaseModel] | None, Any]:
    """Walk ``loc`` through nested models (list indices skipped); return (parent model,
    field info or None)."""
    current: Any = model
    parent, info = None, None
    for part in loc:
        if isinstance(part, int):
            continue
        if current is None:
            return parent, None
        fields = current.model_fields
        by_alias = {(f.alias or k): f for k, f in fields.items()}
        info = by_alias.get(part) or fields.get(part)
        parent = current
        current = _model_of(info.annotation) if info is not None else None
    return parent, info


#: pydantic error type → Chinese text of what is allowed ({…} from the error's context).
_ZH = {
    "greater_than": "须大于 {gt}", "greater_than_equal": "须不小于 {ge}",
    "less_than": "须小于 {lt}", "less_than_equal": "须不大于 {le}",
    "multiple_of": "须为 {multiple_of} 的整数倍",
    "int_type": "须为整数", "int_parsing": "须为整数", "int_from_float": "须为整数（不能带小数）",
    "float_type": "须为数值", "float_parsing": "须为数值",
    "finite_number": "须为有限数值（不能是 inf 或 nan）",
    "string_type": "须为文字（字符串）", "bool_type": "须为 true 或 false",
    "bool_parsing": "须为 true 或 false",
    "literal_error": "须为以下之一：{expected}",
    "too_short": "至少需 {min_length} 项（现有 {actual_length} 项）",
    "too_long": "至多 {max_length} 项（现有 {actual_length} 项）",
    "string_too_short": "至少 {min_length} 个字符", "string_too_long": "至多 {max_length} 个字符",
    "string_pattern_mismatch": "格式不符（须匹配 {pattern}）",
    "dict_type": "须为映射（键: 值）", "model_type": "须为映射（键: 值）的一节",
    "model_attributes_type": "须为映射（键: 值）的一节",
    "list_type": "须为列表", "tuple_type": "须为列表",
    "date_type": "须为日期（YYYY-MM-DD）", "date_parsing": "须为日期（YYYY-MM-DD）",
    "date_from_datetime_parsing": "须为日期（YYYY-MM-DD）",
    "union_tag_invalid": "类型 {tag} 不存在；可用：{expected_tags}",
    "union_tag_not_found": "缺少区分字段 {discriminator}",
    "enum": "须为以下之一：{expected}",
}


#: pydantic error type → English text of what is allowed, in the project's words (the
#: others: pydantic's message with "Input should be" said as "must be").
_EN = {
    "int_from_float": "must be a whole number (no decimals)",
    "finite_number": "must be a finite number (not inf or nan)",
    "dict_type": "must be a mapping (key: value)", "mapping_type": "must be a mapping (key: value)",
    "model_type": "must be a section: a mapping of key: value",
    "model_attributes_type": "must be a section: a mapping of key: value",
    "union_tag_invalid": "type {tag} does not exist; allowed: {expected_tags}",
    "union_tag_not_found": "the field {discriminator} is needed to tell the kind",
    "too_short": "must have at least {min_length} item(s) (it has {actual_length})",
    "too_long": "must have at most {max_length} item(s) (it has {actual_length})",
    "string_too_short": "must have at least {min_length} character(s)",
    "string_too_long": "must have at most {max_length} character(s)",
    "string_pattern_mismatch": "does not have the required form (it must match {pattern})",
    "literal_error": "must be one of: {expected}", "enum": "must be one of: {expected}",
    "list_type": "must be a list", "tuple_type": "must be a list",
    "string_type": "must be text (a string)", "bool_type": "must be true or false",
    "bool_parsing": "must be true or false",
}
_PYDANTIC_WORDS = (("Input should be", "must be"), ("Input should", "must"),
                   ("String should", "must"), ("Value should", "must"), ("should be", "must be"),
                   ("Field required", "required"), ("Input tag", "tag"))


def _en_allowed(kind: str, err: dict, msg: str) -> str:
    """What is allowed in English, in the project's words (never pydantic's wording or URL)."""
    template = _EN.get(kind)
    if template is not None:
        try:
            return template.format(**(err.get("ctx") or {}))
        except (KeyError, IndexError, ValueError):
            pass
    msg = msg.removeprefix("Value error, ").removeprefix("Assertion failed, ")
    for theirs, ours in _PYDANTIC_WORDS:
        msg = msg.replace(theirs, ours)
    msg = re.sub(r"\s*\[type=.*|\s*For further information visit \S+|https?://\S+", "", msg)
    return msg.strip() or "not allowed here"


def _zh_allowed(kind: str, err: dict, msg: str) -> str | None:
    """Chinese text for pydantic error ``kind`` (None when unknown)."""
    if kind in ("value_error", "assertion_error"):
        from ..core.errors import chinese_of

        ctx = err.get("ctx") or {}
        if isinstance(ctx.get("zh"), str):     # a check that wrote its Chinese text (Problems, invalid)
            return ctx["zh"]
        return chinese_of(msg, ctx.get("error") if isinstance(ctx.get("error"), BaseException)
                          else None)
    template = _ZH.get(kind)
    if template is None:
        return None
    ctx = {k: (v.replace("' or '", "'、'") if isinstance(v, str) else v)
           for k, v in (err.get("ctx") or {}).items()}
    try:
        return template.format(**ctx)
    except (KeyError, IndexError, ValueError):
        return None


def _value_of(kind: str, value: Any) -> str:
    """The value a problem line shows: as written, but never a whole section's repr (a
    check of a section names its field; a mapping or list of sections is described)."""
    if isinstance(value, (dict, BaseModel)) or (
            isinstance(value, (list, tuple)) and any(isinstance(v, (dict, list, BaseModel)) for v in value)):
        if kind in ("value_error", "assertion_error"):    # a check of the whole section
            return "the whole section"
        if isinstance(value, (list, tuple)):
            return f"a list of {len(value)} item{'s' if len(value) != 1 else ''}"
        return "a mapping (section)"
    if value is None and kind not in ("value_error", "assertion_error"):   # `key:` left empty
        return "empty"
    return _show(value)


_NAMED_PATH = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z0-9_]+|\[\d+\])*")


def _field_named(err: dict) -> dict:
    """A check of a whole section (or brief) that raised a plain ValueError (no field of
    its own): the error moved to the first field its message names that the section's data
    hold (``crank.pivot 'Z' is not …`` → ``linkage.crank.pivot``; a name with ``_``, ``.``
    or ``[i]``, not a plain word of the text), with that field's value.
    Checks written with :class:`~mechdesign.brief.common.Problems` name their field."""
    value = err.get("input")
    if err["type"] != "value_error" or not isinstance(value, dict) \
            or isinstance((err.get("ctx") or {}).get("zh"), str):
        return err
    for token in _NAMED_PATH.findall(err["msg"].removeprefix("Value error, ")):
        if not any(c in token for c in "_.["):     # a word of the text, not a field name
            continue
        parts = [int(p) if p.isdigit() else p for p in re.split(r"[.\[\]]", token) if p]
        node: Any = value
        for part in parts:
            if isinstance(node, dict) and part in node:
                node = node[part]
            elif isinstance(node, list) and isinstance(part, int) and part < len(node):
                node = node[part]
            else:
                break
        else:
            if not isinstance(node, dict):
                return dict(err, loc=tuple(err["loc"]) + tuple(parts), input=node)
    return err


def _problem(model: type[BaseModel], err: dict) -> BriefProblem:
    loc = tuple(err["loc"])
    path = ".".join(str(p) for p in loc) or "(top level)"
    kind = err["type"]
    parent, info = _field_info(model, loc)
    unit = f" ({info.description})" if info is not None and info.description else ""
    unit_zh = f"（{info.description}）" if unit else ""
    if kind == "extra_forbidden":
        allowed = ", ".join((f.alias or k) for k, f in parent.model_fields.items()) if parent else ""
        return BriefProblem(path, _value_of(kind, err.get("input")),
                            f"unknown field; allowed here: {allowed}",
                            f"未知字段；此处可用的字段：{allowed}")
    if kind == "missing":
        return BriefProblem(path, "missing", f"required{unit}", f"必填{unit_zh}")
    msg = err["msg"].removeprefix("Value error, ")
    zh = _zh_allowed(kind, err, msg)
    return BriefProblem(path, _value_of(kind, err.get("input")), f"{_en_allowed(kind, err, msg)}{unit}",
                        None if zh is None else f"{zh}{unit_zh}")


def _models_in(annotation: Any) -> list[type[BaseModel]]:
    """Every brief section inside ``annotation`` (the members of a union, the items of a list)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return [annotation]
    return [m for arg in get_args(annotation) for m in _models_in(arg)]


def _data_loc(model: type[BaseModel], data: Any, loc: tuple) -> tuple:
    """``loc`` of a pydantic error as a path into the brief's data: the union members
    pydantic names along the way (``float``, ``literal['auto']``, ``RRR``, ``BendingStart``)
    are dropped; a missing field's name stays at the end."""
    out: list = []
    node, models = data, [model]
    for part in loc:
        if isinstance(part, int):
            out.append(part)
            node = node[part] if isinstance(node, list) and 0 <= part < len(node) else None
            continue
        info = next((f for m in models for k, f in m.model_fields.items()
                     if part in (k, f.alias)), None)
        in_data = isinstance(node, dict) and part in node
        if info is None and not in_data:
            continue
        out.append(part)
        node = node.get(part) if in_data else None
        models = _models_in(info.annotation) if info is not None else []
    return tuple(out)


#: Unit of a field, from the suffix of its name (the briefs' convention).
_UNITS = (("_N_per_mm", "N/mm"), ("_N_m3", "N/m³"), ("_kgm2", "kg·m²"), ("_mm", "mm"),
          ("_deg", "°"), ("_rpm", "rpm"), ("_kW", "kW"), ("_Nm", "N·m"), ("_kg", "kg"),
          ("_pct", "%"), ("_N", "N"), ("_m", "m"))
_NUMBER_WITH_UNIT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


def _unit_hint(err: dict, problem: BriefProblem) -> BriefProblem:
    """A number written as text ("320 mm", "320"): say to write the number alone."""
    value = err.get("input")
    if err["type"] not in ("float_type", "int_type", "float_parsing", "int_parsing") \
            or not isinstance(value, str):
        return problem
    match = _NUMBER_WITH_UNIT.match(value)
    if match is None:
        return problem
    number, written = match.groups()
    name = next((p for p in reversed(err["loc"]) if isinstance(p, str)), "")
    unit = next((u for suffix, u in _UNITS if name.endswith(suffix)), None)
    kind = "a whole number" if err["type"].startswith("int") else "a number"
    kind_zh = "整数" if err["type"].startswith("int") else "数值"
    if not written:
        return replace(problem, allowed=f"{kind}, not text: write {number} without quotes",
                       allowed_zh=f"须为{kind_zh}而非文字：写作 {number}，不加引号")
    if unit is None:
        return replace(problem, allowed=f"{kind} without a unit: write {number}",
                       allowed_zh=f"须为{kind_zh}，不带单位：写作 {number}")
    if written == unit:
        return replace(problem, allowed=f"{kind} in {unit}, without the unit: write {number}",
                       allowed_zh=f"须为以 {unit} 计的{kind_zh}，不带单位：写作 {number}")
    return replace(problem, allowed=f"{kind} in {unit}, without the unit: convert {value.strip()!r} "
                                    f"to {unit} and write the number alone",
                   allowed_zh=f"须为以 {unit} 计的{kind_zh}，不带单位：请将 {value.strip()!r} 换算为 "
                              f"{unit} 后只写数字")


def _merge_alternatives(problems: list[BriefProblem]) -> list[BriefProblem]:
    """One line per field: a value that fits no member of a union (a number or 'auto')
    gets one problem listing what each member allows."""
    merged: dict[tuple[str, str], BriefProblem] = {}
    for p in problems:
        key = (p.path, p.value)
        if key in merged:
            first = merged[key]
            zh = None if first.allowed_zh is None and p.allowed_zh is None else \
                f"{first.allowed_zh or first.allowed}；或：{p.allowed_zh or p.allowed}"
            merged[key] = replace(first, allowed=f"{first.allowed}; or: {p.allowed}", allowed_zh=zh)
        else:
            merged[key] = p
    return list(merged.values())


def _top_level_problem(data: Any) -> BriefProblem:
    allowed = "a brief is a YAML mapping of sections: machine: …, report: …, then the machine's data"
    zh = "任务书须为由各节组成的 YAML 映射：machine: …、report: …，然后是机器的数据"
    name = type(data).__name__
    if data is None:
        shown = f"an empty file ({name})"
    elif isinstance(data, list):
        shown = f"a {name}"
    else:
        shown = f"{'text' if isinstance(data, str) else 'a value'} ({name}) {_show(data)}"
    return BriefProblem("(top level)", shown, allowed, zh)


def parse_brief(data: Any, source: str = "brief", located: dict[str, str] | None = None) -> BaseModel:
    """Validate already-loaded YAML data; raise BriefError listing every problem.

    ``located`` maps field paths set by a group variant to where the group set them, so
    a bad value from a group is reported there."""
    if not isinstance(data, dict):
        raise BriefError(source, [_top_level_problem(data)])
    if GROUPS_KEY in data:  # the brief as written; load_variant applies a group
        data, _ = _groups_of(data, source)
    machine = data.get("machine")
    model = BRIEF_MODELS.get(machine) if isinstance(machine, str) else None
    if model is None:
        names = ", ".join(sorted(BRIEF_MODELS))
        raise BriefError(source, [BriefProblem(
            "machine", _show(machine) if "machine" in data else "missing",
            f"one of: {names}", f"须为以下之一：{names}")])
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        problems = []
        for e in exc.errors():
            e = _field_named(dict(e, loc=_data_loc(model, data, tuple(e["loc"]))))
            problems.append(_unit_hint(e, _problem(model, e)))
        problems = _merge_alternatives(problems)
        if located:
            problems = [_relocate(p, located) for p in problems]
        raise BriefError(source, problems) from None


def _relocate(problem: BriefProblem, located: dict[str, str]) -> BriefProblem:
    for path in sorted(located, key=len, reverse=True):
        if problem.path == path or problem.path.startswith(path + "."):
            return replace(problem, path=located[path] + problem.path[len(path):])
    return problem


def _file_problem(source: str, value: str, allowed: str, allowed_zh: str) -> BriefError:
    return BriefError(source, [BriefProblem("(file)", value, allowed, allowed_zh)])


def _line_col(text: str | bytes, index: int) -> str:
    nl = "\n" if isinstance(text, str) else b"\n"
    line = text.count(nl, 0, index) + 1
    return f"line {line}, column {index - (text.rfind(nl, 0, index) + 1) + 1}"


def read_brief_data(path: str | Path) -> Any:
    """The YAML data of a brief file (not yet validated); BriefError if the file cannot
    be read, is not UTF-8 text, is too large or is not valid YAML within the limits."""
    path = Path(path)
    source = str(path)
    try:
        kind = "folder" if path.is_dir() else "file" if path.is_file() else \
            "other" if path.exists() else "missing"
    except (OSError, ValueError):  # e.g. a NUL character in the path
        raise _file_problem(source, repr(source)[:60], "not a valid file path",
                            "不是有效的文件路径") from None
    if kind == "folder":
        raise _file_problem(source, "a folder", "give a brief file (.yaml), not a folder",
                            "这是文件夹；请给出任务书文件（.yaml）")
    if kind == "missing":
        raise _file_problem(source, "no such file", "give the path of an existing brief file",
                            "文件不存在；请给出已有任务书文件的路径")
    if kind == "other":   # a pipe or a device would block or never end
        raise _file_problem(source, "not a regular file", "a brief is a text file (.yaml)",
                            "不是普通文件；任务书是文本文件（.yaml）")
    try:
        with path.open("rb") as f:
            raw = f.read(MAX_BYTES + 1)
    except OSError as exc:
        raise _file_problem(source, source, f"cannot be read: {exc.strerror}",
                            f"无法读取：{exc.strerror}") from None
    if len(raw) > MAX_BYTES:
        raise _file_problem(source, f"more than {MAX_BYTES} bytes",
                            f"a brief is at most {MAX_BYTES} bytes (the examples have about 10 kB); "
                            "is this the right file?",
                            f"任务书至多 {MAX_BYTES} 字节（示例约 10 kB）；文件是否选错？")
    if raw.startswith((b"\xff\xfe", b"\xfe\xff")):
        raise _file_problem(source, "UTF-16 text", "save the brief as UTF-8 text",
                            "请将任务书另存为 UTF-8 文本")
    raw = raw.removeprefix(b"\xef\xbb\xbf")   # a byte-order mark some editors write
    nul = raw.find(b"\x00")
    if nul >= 0:
        raise _file_problem(source, f"a NUL byte at {_line_col(raw, nul)}",
                            "a brief is YAML text; this looks like a binary file",
                            "任务书是 YAML 文本；此文件像是二进制文件")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise _file_problem(source, f"byte 0x{raw[exc.start]:02x} at {_line_col(raw, exc.start)}",
                            "a brief is UTF-8 text; save it as UTF-8",
                            "任务书须为 UTF-8 文本；请另存为 UTF-8") from None
    try:
        return yaml.load(text, Loader=_UniqueKeyLoader)  # noqa: S506 - a SafeLoader subclass
    except _LimitError as exc:
        raise BriefError(source, [BriefProblem(exc.path, exc.value, exc.allowed, exc.allowed_zh)]) from None
    except yaml.YAMLError as exc:
        raise BriefError(source, [_yaml_problem(exc, text)]) from None
    except RecursionError:  # not reached within MAX_DEPTH; kept as a last guard
        raise _file_problem(source, "nested too deeply", "a brief nests sections a few levels deep",
                            "嵌套过深；任务书只有几层") from None


def _yaml_problem(exc: yaml.YAMLError, text: str) -> BriefProblem:
    if isinstance(exc, yaml.reader.ReaderError):   # a control character
        return BriefProblem(_line_col(text, exc.position), f"character #x{exc.character:04x}"
                            if isinstance(exc.character, int) else "a control character",
                            "a brief is YAML text; control characters are not allowed",
                            "任务书是 YAML 文本，不能含控制字符")
    mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
    where = f"line {mark.line + 1}, column {mark.column + 1}" if mark else "(file)"
    problem = getattr(exc, "problem", None) or str(exc)
    if "another document" in problem:
        return BriefProblem(where, "a second YAML document",
                            "a brief is one YAML document: remove the `---` line and what follows",
                            "任务书只能是一个 YAML 文档：请删去 `---` 行及其后的内容")
    return BriefProblem(where, "invalid YAML", problem, f"YAML 格式错误：{problem}")


_MISSING = object()


@dataclass(frozen=True)
class Variant:
    """A validated brief, the group it was built for (None: the brief as written) and
    the labels of every group the brief carries."""

    brief: BaseModel
    group: str | None
    groups: tuple[str, ...]
    #: field path → where the group sets it (for problems found later, e.g. by the checks)
    located: dict[str, str] = field(default_factory=dict)


def _groups_of(data: Any, source: str) -> tuple[Any, GroupTable | None]:
    """The brief's data without its ``groups`` section, and the groups table (read from
    its class table file for ``groups: {file: …}``, relative to the brief at ``source``)."""
    if not isinstance(data, dict) or GROUPS_KEY not in data:
        return data, None
    data = dict(data)
    raw = data.pop(GROUPS_KEY)
    try:
        if isinstance(raw, dict) and "file" in raw:
            machine = data.get("machine")
            model = BRIEF_MODELS.get(machine) if isinstance(machine, str) else None
            return data, read_group_file(raw, source, model)
        return data, parse_groups(raw)
    except GroupError as exc:
        raise BriefError(source, [BriefProblem(exc.path, exc.value, exc.allowed)]) from None
    except TableError as exc:   # every problem of a class table file
        raise BriefError(source, [BriefProblem(p.path, p.value, p.allowed) for p in exc.problems]) from None


def brief_groups(path: str | Path, *, data: Any = _MISSING) -> tuple[str, ...]:
    """The group labels a brief carries (empty when it has no ``groups`` table).
    ``data``: the file's YAML data when already read."""
    _, table = _groups_of(read_brief_data(path) if data is _MISSING else data, str(path))
    return tuple(table.labels) if table is not None else ()


def _has(data: Any, parts: list[str]) -> bool:
    node = data
    for part in parts:
        if isinstance(node, dict):
            key = next((k for k in node if str(k) == part), _MISSING)
            if key is _MISSING:
                return False
            node = node[key]
        elif isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        else:
            return False
    return True



def _with_created(original: Any, located: dict[str, str]) -> dict[str, str]:
    """``located`` plus the sections a group created (``foo`` for an override ``foo.bar``
    the brief lacks), so a problem found on such a section is reported in the group."""
    created: dict[str, str] = {}
    for path, where in located.items():
        parts = path.split(".")
        for k in range(1, len(parts)):
            if not _has(original, parts[:k]):
                created.setdefault(".".join(parts[:k]), where)
                break
    return {**created, **located}


def load_variant(path: str | Path, group: str | None = None, *, data: Any = _MISSING) -> Variant:
    """Read a brief, apply group ``group`` (default: the table's ``default``, else the
    brief as written) and validate it; raise BriefError (never a bare traceback).
    ``data``: the file's YAML data when already read (:func:`read_brief_data`)."""
    source = str(path)
    data, table = _groups_of(read_brief_data(path) if data is _MISSING else data, source)
    located: dict[str, str] = {}
    try:
        label = choose(table, group)
        if label is not None:
            original = data
            data, located = apply_group(data, table, label)
            located = _with_created(original, located)
    except GroupError as exc:
        raise BriefError(source, [BriefProblem(exc.path, exc.value, exc.allowed)]) from None
    brief = parse_brief(data, source, located)
    return Variant(brief, label, tuple(table.labels) if table is not None else (), located)


def student_of(path: str | Path, group: str | None = None) -> tuple[str, str, str]:
    """(name, number, class) from the ``report`` section of group ``group`` of a brief, read
    without validating it (for the batch index of a brief that turned out invalid); empty
    texts where the brief or the group cannot be read."""
    try:
        data, table = _groups_of(read_brief_data(path), str(path))
        label = choose(table, group)
        if label is not None:
            data, _ = apply_group(data, table, label)
    except (BriefError, GroupError):
        return "", "", ""
    report = data.get("report") if isinstance(data, dict) else None
    report = report if isinstance(report, dict) else {}
    return tuple("" if report.get(k) is None else str(report.get(k))      # type: ignore[return-value]
                 for k in ("student", "student_id", "class"))


def load_brief(path: str | Path, group: str | None = None) -> BaseModel:
    """Read and validate a brief file (group ``group`` applied, see :func:`load_variant`)."""
    return load_variant(path, group).brief


def brief_schema(machine: str | None = None) -> dict:
    """JSON Schema of one machine's brief, or of any brief (one of them, by ``machine``)."""
    from typing import Annotated, Union

    from pydantic import Field, TypeAdapter

    if machine is not None:
        schema = BRIEF_MODELS[machine].model_json_schema(by_alias=True)
    else:
        models = tuple(BRIEF_MODELS.values())
        any_brief = Annotated[Union[models], Field(discriminator="machine")]
        schema = TypeAdapter(any_brief).json_schema(by_alias=True)
    # Every brief may carry a groups table (brief/groups.py); it is read before validation.
    defs = schema.setdefault("$defs", {})
    defs["Groups"] = GROUPS_SCHEMA
    for sub in [schema] + list(defs.values()):
        props = sub.get("properties", {})
        if "machine" in props and "report" in props:
            props[GROUPS_KEY] = {"$ref": "#/$defs/Groups"}
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema.setdefault("title", "mechdesign design brief")
    return schema


#: JSON Schema of the ``groups`` section (brief/groups.py).
GROUPS_SCHEMA = {
    "title": "Groups", "type": "object", "additionalProperties": False,
    "description": "Data groups (分组/方案): the brief's fields each group overrides; "
                   "`mechdesign run BRIEF --group LABEL`, `mechdesign batch --groups all`",
    "properties": {
        "default": {"type": ["integer", "string"],
                    "description": "Group used when --group is not given"},
        "variants": {"type": "object", "minProperties": 1,
                     "description": "Group label → overridden fields (dotted paths such as "
                                    "pusher.stroke_H_mm, or nested sections)",
                     "additionalProperties": {"type": ["object", "null"]}},
        "file": {"type": "string", "pattern": "\\.(csv|xlsx|CSV|XLSX)$",
                 "description": "A class table next to the brief (.csv or .xlsx): one row per "
                                "group, a `group` column and dotted brief paths as columns"},
        "sheet": {"type": "string", "description": "Sheet of the .xlsx file (default: the first)"}},
    "oneOf": [{"required": ["variants"], "not": {"required": ["file"]}},
              {"required": ["file"], "not": {"required": ["variants"]}}]}
