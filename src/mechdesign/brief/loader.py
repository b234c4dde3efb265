"""Load a YAML design brief safely and validate it completely before any computation.

Every problem becomes one :class:`BriefProblem` line naming the field path, the value
found and what is allowed; all problems are collected and raised together as a
:class:`BriefError`.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
import re
from typing import Any, get_args

import yaml
from pydantic import BaseModel, ValidationError

from .cam import CamBrief, EccentricCamBrief
from .crank_rocker import CrankRockerBrief
from .die_cutter import DieCutterBrief
from .drive import DriveBrief
from .furnace import FurnaceBrief
from .groups import GROUPS_KEY, GroupError, GroupTable, apply_group, choose, parse_groups
from .linkage import LinkageBrief
from .lockbeam import LockbeamBrief
from .shaper import ShaperBrief

#: Machine name → brief model. Later machines register here.
BRIEF_MODELS: dict[str, type[BaseModel]] = {
    "shaper": ShaperBrief, "furnace_pusher": FurnaceBrief, "lockbeam": LockbeamBrief,
    "die_cutter": DieCutterBrief, "crank_rocker": CrankRockerBrief, "linkage": LinkageBrief,
    "cam": CamBrief, "eccentric_cam": EccentricCamBrief, "drive": DriveBrief}


@dataclass(frozen=True)
class BriefProblem:
    """One problem: the field ``path``, the ``value`` found and what is ``allowed`` there
    (English; ``allowed_zh`` the same in Chinese, when known)."""

    path: str
    value: str
    allowed: str
    allowed_zh: str | None = None

    def __str__(self) -> str:
        return f"{self.path}: {self.value} — {self.allowed}"

    def text(self, lang: str) -> str:
        """The line in ``lang`` ("zh" or "en"); the value "missing" is said in Chinese too."""
        if lang != "zh":
            return str(self)
        value = "缺少" if self.value == "missing" else self.value
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


class _UniqueKeyLoader(yaml.SafeLoader):
    """Safe loader that rejects a key given twice in one mapping (YAML keeps the last)."""


def _construct_mapping(loader: _UniqueKeyLoader, node: yaml.MappingNode, deep: bool = False):
    seen: dict[Any, int] = {}
    for key_node, _ in node.value:
        key = loader.construct_object(key_node, deep=deep)
        if key in seen:
            raise yaml.constructor.ConstructorError(
                None, None, f"key '{key}' appears twice (lines {seen[key]} and "
                f"{key_node.start_mark.line + 1})", key_node.start_mark)
        seen[key] = key_node.start_mark.line + 1
    return loader.construct_mapping(node, deep=deep)


_UniqueKeyLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)
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


def _zh_allowed(kind: str, err: dict, msg: str) -> str | None:
    """Chinese text for pydantic error ``kind`` (None when unknown)."""
    if kind in ("value_error", "assertion_error"):
        from ..core.errors import chinese_of

        ctx = err.get("ctx") or {}
        return chinese_of(msg, ctx.get("error") if isinstance(ctx.get("error"), BaseException)
                          else None)
    template = _ZH.get(kind)
    if template is None:
        return None
    try:
        return template.format(**{k: v for k, v in (err.get("ctx") or {}).items()})
    except (KeyError, IndexError, ValueError):
        return None


def _problem(model: type[BaseModel], err: dict) -> BriefProblem:
    loc = tuple(err["loc"])
    path = ".".join(str(p) for p in loc) or "(top level)"
    kind = err["type"]
    parent, info = _field_info(model, loc)
    unit = f" ({info.description})" if info is not None and info.description else ""
    unit_zh = f"（{info.description}）" if unit else ""
    if kind == "extra_forbidden":
        allowed = ", ".join((f.alias or k) for k, f in parent.model_fields.items()) if parent else ""
        return BriefProblem(path, _show(err.get("input")), f"unknown field; allowed here: {allowed}",
                            f"未知字段；此处可用的字段：{allowed}")
    if kind == "missing":
        return BriefProblem(path, "missing", f"required{unit}", f"必填{unit_zh}")
    msg = err["msg"].removeprefix("Value error, ")
    zh = _zh_allowed(kind, err, msg)
    return BriefProblem(path, _show(err.get("input")), f"{msg}{unit}",
                        None if zh is None else f"{zh}{unit_zh}")


def parse_brief(data: Any, source: str = "brief", located: dict[str, str] | None = None) -> BaseModel:
    """Validate already-loaded YAML data; raise BriefError listing every problem.

    ``located`` maps field paths set by a group variant to where the group set them, so
    a bad value from a group is reported there."""
    if not isinstance(data, dict):
        raise BriefError(source, [BriefProblem("(top level)", _show(type(data).__name__),
                                               "a brief is a YAML mapping of sections")])
    if GROUPS_KEY in data:  # the brief as written; load_variant applies a group
        data, _ = _groups_of(data, source)
    machine = data.get("machine")
    model = BRIEF_MODELS.get(machine) if isinstance(machine, str) else None
    if model is None:
        raise BriefError(source, [BriefProblem(
            "machine", _show(machine) if "machine" in data else "missing",
            f"one of: {', '.join(sorted(BRIEF_MODELS))}")])
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        problems = [_problem(model, e) for e in exc.errors()]
        if located:
            problems = [_relocate(p, located) for p in problems]
        raise BriefError(source, problems) from None


def _relocate(problem: BriefProblem, located: dict[str, str]) -> BriefProblem:
    for path in sorted(located, key=len, reverse=True):
        if problem.path == path or problem.path.startswith(path + "."):
            return BriefProblem(located[path] + problem.path[len(path):], problem.value, problem.allowed)
    return problem


def read_brief_data(path: str | Path) -> Any:
    """The YAML data of a brief file (not yet validated); BriefError if unreadable."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise BriefError(str(path), [BriefProblem("(file)", str(path), f"cannot be read: {exc.strerror}")]) from None
    except UnicodeDecodeError:
        raise BriefError(str(path), [BriefProblem("(file)", str(path), "must be UTF-8 text")]) from None
    try:
        return yaml.load(text, Loader=_UniqueKeyLoader)  # noqa: S506 - a SafeLoader subclass
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
        where = f"line {mark.line + 1}, column {mark.column + 1}" if mark else "(file)"
        problem = getattr(exc, "problem", None) or str(exc)
        raise BriefError(str(path), [BriefProblem(where, "invalid YAML", problem)]) from None


@dataclass(frozen=True)
class Variant:
    """A validated brief, the group it was built for (None: the brief as written) and
    the labels of every group the brief carries."""

    brief: BaseModel
    group: str | None
    groups: tuple[str, ...]


def _groups_of(data: Any, source: str) -> tuple[Any, GroupTable | None]:
    if not isinstance(data, dict) or GROUPS_KEY not in data:
        return data, None
    data = dict(data)
    try:
        return data, parse_groups(data.pop(GROUPS_KEY))
    except GroupError as exc:
        raise BriefError(source, [BriefProblem(exc.path, exc.value, exc.allowed)]) from None


def brief_groups(path: str | Path) -> tuple[str, ...]:
    """The group labels a brief carries (empty when it has no ``groups`` table)."""
    _, table = _groups_of(read_brief_data(path), str(path))
    return tuple(table.labels) if table is not None else ()


def load_variant(path: str | Path, group: str | None = None) -> Variant:
    """Read a brief, apply group ``group`` (default: the table's ``default``, else the
    brief as written) and validate it; raise BriefError (never a bare traceback)."""
    source = str(path)
    data, table = _groups_of(read_brief_data(path), source)
    located: dict[str, str] = {}
    try:
        label = choose(table, group)
        if label is not None:
            data, located = apply_group(data, table, label)
    except GroupError as exc:
        raise BriefError(source, [BriefProblem(exc.path, exc.value, exc.allowed)]) from None
    brief = parse_brief(data, source, located)
    return Variant(brief, label, tuple(table.labels) if table is not None else ())


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
                     "additionalProperties": {"type": ["object", "null"]}}},
    "required": ["variants"]}
