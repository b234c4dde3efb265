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

from ..i18n import N_, tr
from ..registry import Lookup, resolve
from .class_table import TableError, read_group_file
from .common import Given, Msg
from .groups import GROUPS_KEY, GroupError, GroupTable, apply_group, choose, parse_groups


#: Machine name → brief model (machines register in :mod:`mechdesign.registry`).
BRIEF_MODELS: Mapping[str, type[BaseModel]] = Lookup(lambda e: resolve(e.brief))


@dataclass(frozen=True)
class BriefProblem:
    """One problem: the field ``path``, the ``value`` found and what is ``allowed`` there:
    English text, a :class:`~mechdesign.brief.common.Msg` (msgid and fields) when it can be
    shown in other languages; ``_zh`` the Chinese text a caller wrote itself (modules not yet
    converted to the catalogue)."""

    path: str
    value: str
    allowed: str
    _zh: str | None = None

    @property
    def allowed_zh(self) -> str | None:
        """What is allowed, in Chinese (None when only English is known)."""
        if isinstance(self.allowed, Msg):
            return self.allowed.text("zh")
        return self._zh

    def __str__(self) -> str:
        return self.text("en")

    def text(self, lang: str) -> str:
        """The line in ``lang``; the values "missing", "empty" … are translated too."""
        _ = tr(lang)
        if not _.zh:
            value, allowed = self.value, str.__str__(self.allowed)
        else:
            value = _value_word(_, self.value)
            allowed = self.allowed.text(lang) if isinstance(self.allowed, Msg) else \
                (self._zh or self.allowed)
        if not value:
            return _("{path}: {allowed}", path=self.path, allowed=allowed)
        return _("{path}: {value} — {allowed}", path=self.path, value=value, allowed=allowed)


def _value_word(_, value: str) -> str:
    """A problem's value in the reader's language: the words the loader shows for a value
    (missing, empty …) translated, anything else as found."""
    if value == "missing":
        return _.pgettext("problem value", "missing")
    if value == "empty":
        return _.pgettext("problem value", "empty")
    if value == "the whole section":
        return _.pgettext("problem value", "the whole section")
    if value == "a mapping (section)":
        return _.pgettext("problem value", "a mapping (section)")
    return value


class BriefError(ValueError):
    """One or more problems in a brief; ``str()`` lists them in English, one per line,
    :meth:`text` in the report's language."""

    def __init__(self, source: str, problems: list[BriefProblem]):
        self.source, self.problems = source, problems
        super().__init__(self.text("en"))

    def _head(self, _) -> str:
        n = len(self.problems)
        if n == 1:
            return _("{source}: {n} problem in the brief", source=self.source, n=n)
        return _("{source}: {n} problems in the brief", source=self.source, n=n)

    def text(self, lang: str) -> str:
        _ = tr(lang)
        return "\n".join([self._head(_)] + [f"  {p.text(lang)}" for p in self.problems])


class FeasibilityError(BriefError):
    """The brief is valid but its data admit no design: every problem the machine's
    feasibility checks found (run once per run, after validation), each at its field."""

    def _head(self, _) -> str:
        n = len(self.problems)
        if n == 1:
            return _("{source}: the design is infeasible with the brief's data ({n} problem)",
                     source=self.source, n=n)
        return _("{source}: the design is infeasible with the brief's data ({n} problems)",
                 source=self.source, n=n)

    def __str__(self) -> str:
        return self.args[0]


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

    def __init__(self, path: list[str], value: str, msgid: str, /, **fields):
        allowed = msgid if isinstance(msgid, Msg) else Msg(msgid, **fields)
        super().__init__(f"{value}: {allowed}")
        self.path = ".".join(path) or "(top level)"
        self.value, self.allowed = value, allowed


class _Limits:
    """Composition and construction of a safe loader that rejects a key given twice in one
    mapping (YAML keeps the last) and enforces the limits above while the file is
    composed, naming the field path (mixed into :class:`_UniqueKeyLoader` and
    :class:`_FastLoader`)."""

    _path: list[str]
    _values: int

    def _count(self, n: int) -> None:
        self._values += n
        if self._values > MAX_VALUES:
            raise _LimitError(self._path, f"more than {MAX_VALUES} values",
                              N_("a brief holds at most that many values (anchors/aliases counted "
                                 "each time they are used)"), MAX_VALUES=MAX_VALUES)

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            anchor = self.peek_event().anchor
            node = self.anchors.get(anchor)
            if node is not None:
                size = getattr(node, "_md_size", None)
                if size is None:
                    raise _LimitError(self._path, f"*{anchor}",
                                      N_("an alias cannot refer to the list or mapping that "
                                         "contains it"))
                self._count(size)
            return super().compose_node(parent, index)  # an undefined alias: YAML's error
        if self.check_event(yaml.SequenceStartEvent, yaml.MappingStartEvent) \
                and len(self._path) >= MAX_DEPTH:
            raise _LimitError(self._path, f"lists or mappings nested more than {MAX_DEPTH} deep",
                              Msg.pgettext("nesting limit", "a brief nests sections a few levels deep",
                                           MAX_DEPTH=MAX_DEPTH))
        self._count(1)
        return super().compose_node(parent, index)

    def compose_scalar_node(self, anchor):
        node = super().compose_scalar_node(anchor)
        node._md_size = 1
        return node

    def _too_many(self, what: str):
        if what == "list":
            allowed = Msg(N_("no list in a brief is that long"), MAX_ITEMS=MAX_ITEMS)
        else:
            allowed = Msg(N_("no mapping in a brief is that long"), MAX_ITEMS=MAX_ITEMS)
        return _LimitError(self._path, f"a {what} of more than {MAX_ITEMS} items", allowed)

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
                raise self._too_many("list")
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
                raise self._too_many("mapping")
            key = self.compose_node(node, None)
            if not isinstance(key, yaml.ScalarNode):
                raise _LimitError(self._path, "a list or mapping used as a key",
                                  N_("a key is a field name (or a group label)"))
            if len(key.value) > MAX_KEY_CHARS:
                raise _LimitError(self._path, f"a key of {len(key.value)} characters "
                                  f"({key.value[:20]!r}…)", N_("a key has at most {MAX_KEY_CHARS} "
                                                                 "characters"),
                                                              MAX_KEY_CHARS=MAX_KEY_CHARS)
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


def _construct_mapping(loader: _Limits, node: yaml.MappingNode, deep: bool = False):
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


class _UniqueKeyLoader(_Limits, yaml.SafeLoader):
    """The brief's loader (:class:`_Limits`), in pure Python: the reference, and the one
    whose errors the user sees."""

    def __init__(self, stream):
        super().__init__(stream)
        self._path, self._values = [], 0


try:
    from yaml._yaml import CParser as _CParser
except ImportError:      # PyYAML built without libyaml
    _CParser = None

#: Text libyaml reads where PyYAML refuses it (found by tests/test_brief_yaml_fast.py's
#: differential fuzzing): a tab (PyYAML refuses it where libyaml takes it as a space), a
#: ``?`` (PyYAML refuses it inside a flow collection's plain scalar), a byte-order mark
#: after the start and the control characters (both refuse them, in other words): such a
#: file is read by PyYAML alone.
_PYYAML_ONLY = re.compile("[\t?\ufeff]|" + yaml.reader.Reader.NON_PRINTABLE.pattern)

if _CParser is not None:
    class _FastLoader(_Limits, yaml.composer.Composer, _CParser, yaml.constructor.SafeConstructor,
                      yaml.resolver.Resolver):
        """:class:`_UniqueKeyLoader` with libyaml's scanner and parser (C) in place of
        PyYAML's (Python; ~85 % of the time a brief takes to read): composition (the
        limits), resolution and construction are the same Python code, so a file both
        read gives the same data. Used for files that read without error; any error is
        reported by :class:`_UniqueKeyLoader` reading the file again (its messages)."""

        def __init__(self, stream):
            _CParser.__init__(self, stream)
            yaml.composer.Composer.__init__(self)
            yaml.constructor.SafeConstructor.__init__(self)
            yaml.resolver.Resolver.__init__(self)
            self._path, self._values = [], 0

        # the Python composer's, not libyaml's (which would skip the limits)
        check_node = yaml.composer.Composer.check_node
        get_node = yaml.composer.Composer.get_node
        get_single_node = yaml.composer.Composer.get_single_node
else:
    _FastLoader = None

for _loader in (_UniqueKeyLoader, _FastLoader):
    if _loader is None:
        continue
    _loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)
    _loader.add_constructor("tag:yaml.org,2002:int", _Limits.construct_yaml_int)
    _loader.add_constructor("tag:yaml.org,2002:timestamp", _Limits.construct_yaml_timestamp)
    # YAML 1.1 (PyYAML) reads 7.0e4 or 1e5 as strings; read them as numbers, as YAML 1.2 does.
    _loader.add_implicit_resolver(
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


#: pydantic error type → what is allowed, in the project's English words (the msgid: the
#: catalogue gives its other languages, the {…} fields from the error's context). The kinds
#: of _OWN_WORDS are shown in these words in English too; the others in pydantic's message
#: with "Input should be" said as "must be" (the msgid then only names it for translation).
_ALLOWED = {
    "greater_than": N_("must be greater than {gt}"),
    "greater_than_equal": N_("must be greater than or equal to {ge}"),
    "less_than": N_("must be less than {lt}"),
    "less_than_equal": N_("must be less than or equal to {le}"),
    "multiple_of": N_("must be a multiple of {multiple_of}"),
    "int_type": N_("must be a valid integer"),
    "int_parsing": N_("must be a valid integer, unable to parse string as an integer"),
    "int_from_float": N_("must be a whole number (no decimals)"),
    "float_type": N_("must be a valid number"),
    "float_parsing": N_("must be a valid number, unable to parse string as a number"),
    "finite_number": N_("must be a finite number (not inf or nan)"),
    "string_type": N_("must be text (a string)"), "bool_type": N_("must be true or false"),
    "bool_parsing": N_("must be true or false"),
    "literal_error": N_("must be one of: {expected}"),
    "too_short": N_("must have at least {min_length} item(s) (it has {actual_length})"),
    "too_long": N_("must have at most {max_length} item(s) (it has {actual_length})"),
    "string_too_short": N_("must have at least {min_length} character(s)"),
    "string_too_long": N_("must have at most {max_length} character(s)"),
    "string_pattern_mismatch": N_("does not have the required form (it must match {pattern})"),
    "dict_type": N_("must be a mapping (key: value)"),
    "model_type": N_("must be a section: a mapping of key: value"),
    "model_attributes_type": N_("must be a section: a mapping of key: value"),
    "list_type": N_("must be a list"), "tuple_type": N_("must be a list"),
    "date_type": N_("must be a valid date"), "date_parsing": N_("must be a valid date"),
    "date_from_datetime_parsing": N_("must be a valid date"),
    "union_tag_invalid": N_("type {tag} does not exist; allowed: {expected_tags}"),
    "union_tag_not_found": N_("the field {discriminator} is needed to tell the kind"),
    "enum": N_("must be one of: {expected}"),
}
#: the kinds shown in the words of _ALLOWED in English too (and one without a translation)
_OWN_WORDS = {"int_from_float", "finite_number", "dict_type", "model_type", "model_attributes_type",
              "union_tag_invalid", "union_tag_not_found", "too_short", "too_long",
              "string_too_short", "string_too_long", "string_pattern_mismatch", "literal_error",
              "enum", "list_type", "tuple_type", "string_type", "bool_type", "bool_parsing"}
_EN_ONLY = {"mapping_type": "must be a mapping (key: value)"}
_PYDANTIC_WORDS = (("Input should be", "must be"), ("Input should", "must"),
                   ("String should", "must"), ("Value should", "must"), ("should be", "must be"),
                   ("Field required", "required"), ("Input tag", "tag"))


def _en_allowed(kind: str, err: dict, msg: str) -> str:
    """What is allowed in English, in the project's words (never pydantic's wording or URL)."""
    template = _ALLOWED.get(kind) if kind in _OWN_WORDS else _EN_ONLY.get(kind)
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


class _Shown(Msg):
    """A message shown in English as ``en`` (as the loader words it) and in other languages
    as the message ``inner``."""

    def __new__(cls, en: str, inner: Msg | None = None):
        self = str.__new__(cls, en)
        self.msgid, self.context, self.fields, self.inner = en, None, {}, inner
        return self

    def text(self, lang: str) -> str:
        return self.inner.text(lang) if self.inner is not None and tr(lang).zh else str.__str__(self)


class _Alternatives(Msg):
    """A pydantic list of alternatives ("'a', 'b' or 'c'"): its last " or " said with the
    catalogue's list separator in other languages ('a', 'b'、'c')."""

    def __new__(cls, text: str):
        self = str.__new__(cls, text)
        self.msgid, self.context, self.fields = text, None, {}
        return self

    def text(self, lang: str) -> str:
        _ = tr(lang)
        plain = str.__str__(self)
        return plain if not _.zh else \
            plain.replace("' or '", "'" + _.pgettext("list", ", ") + "'")


def _translatable(kind: str, err: dict, msg: str) -> Msg | None:
    """What is allowed as a message that has its other languages (None when only the English
    is known)."""
    if kind in ("value_error", "assertion_error"):
        from ..core.errors import chinese_of

        ctx = err.get("ctx") or {}
        if isinstance(ctx.get("msg"), Msg):     # a check that wrote a message (Problems, invalid)
            return ctx["msg"]
        zh = chinese_of(msg, ctx.get("error") if isinstance(ctx.get("error"), BaseException)
                        else None)
        return None if zh is None else Given(msg, zh)
    template = _ALLOWED.get(kind)
    if template is None:
        return None
    ctx = {k: (_Alternatives(v) if isinstance(v, str) else v)
           for k, v in (err.get("ctx") or {}).items()}
    try:
        template.format(**ctx)
    except (KeyError, IndexError, ValueError):
        return None
    return Msg(template, **ctx)


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
            or isinstance((err.get("ctx") or {}).get("msg"), Msg):
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
    description = info.description if info is not None and info.description else ""
    if kind == "extra_forbidden":
        allowed = ", ".join((f.alias or k) for k, f in parent.model_fields.items()) if parent else ""
        return BriefProblem(path, _value_of(kind, err.get("input")),
                            Msg(N_("unknown field; allowed here: {allowed}"), allowed=allowed))
    if kind == "missing":
        return BriefProblem(path, "missing",
                            Msg(N_("required ({description})"), description=description)
                            if description else Msg.pgettext("brief field", "required"))
    msg = err["msg"].removeprefix("Value error, ")
    en = _en_allowed(kind, err, msg)
    message = _translatable(kind, err, msg)
    if message is None:
        return BriefProblem(path, _value_of(kind, err.get("input")),
                            f"{en} ({description})" if description else en)
    if str.__str__(message) != en:
        message = _Shown(en, message)
    if description:
        message = Msg(N_("{allowed} ({description})"), allowed=message, description=description)
    return BriefProblem(path, _value_of(kind, err.get("input")), message)


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
    # the unit as the message's language writes it: rpm is r/min in Chinese (GB 3102)
    words = (unit, "r/min") if unit == "rpm" else (unit,)
    whole = err["type"].startswith("int")
    if not written:
        allowed = Msg(N_("a whole number, not text: write {number} without quotes"), number=number) \
            if whole else Msg(N_("a number, not text: write {number} without quotes"), number=number)
    elif unit is None:
        allowed = Msg(N_("a whole number without a unit: write {number}"), number=number) if whole \
            else Msg(N_("a number without a unit: write {number}"), number=number)
    elif written in words:
        unit = Msg(N_("rpm")) if unit == "rpm" else unit
        allowed = Msg(N_("a whole number in {unit}, without the unit: write {number}"),
                      unit=unit, number=number) if whole else \
            Msg(N_("a number in {unit}, without the unit: write {number}"), unit=unit, number=number)
    else:
        unit = Msg(N_("rpm")) if unit == "rpm" else unit
        given = value.strip()
        allowed = Msg(N_("a whole number in {unit}, without the unit: convert {given!r} to {unit} "
                         "and write the number alone"), unit=unit, given=given) if whole else \
            Msg(N_("a number in {unit}, without the unit: convert {given!r} to {unit} and write the "
                   "number alone"), unit=unit, given=given)
    return replace(problem, allowed=allowed, _zh=None)


def _merge_alternatives(problems: list[BriefProblem]) -> list[BriefProblem]:
    """One line per field: a value that fits no member of a union (a number or 'auto')
    gets one problem listing what each member allows."""
    merged: dict[tuple[str, str], BriefProblem] = {}
    for p in problems:
        key = (p.path, p.value)
        if key in merged:
            first = merged[key]
            if isinstance(first.allowed, Msg) or isinstance(p.allowed, Msg):
                allowed = Msg(N_("{first}; or: {other}"), first=first.allowed, other=p.allowed)
            else:
                allowed = f"{first.allowed}; or: {p.allowed}"
            merged[key] = replace(first, allowed=allowed)
        else:
            merged[key] = p
    return list(merged.values())


def _top_level_problem(data: Any) -> BriefProblem:
    allowed = Msg(N_("a brief is a YAML mapping of sections: machine: …, report: …, then the "
                     "machine's data"))
    name = type(data).__name__
    if data is None:
        shown = f"an empty file ({name})"
    elif isinstance(data, list):
        shown = f"a {name}"
    else:
        shown = f"{'text' if isinstance(data, str) else 'a value'} ({name}) {_show(data)}"
    return BriefProblem("(top level)", shown, allowed)


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
            Msg(N_("one of: {names}"), names=names))])
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


def _file_problem(source: str, value: str, msgid: str, /, **fields) -> BriefError:
    allowed = msgid if isinstance(msgid, Msg) else Msg(msgid, **fields)
    return BriefError(source, [BriefProblem("(file)", value, allowed)])


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
        raise _file_problem(source, repr(source)[:60], N_("not a valid file path")) from None
    if kind == "folder":
        raise _file_problem(source, "a folder", N_("give a brief file (.yaml), not a folder"))
    if kind == "missing":
        raise _file_problem(source, "no such file", N_("give the path of an existing brief file"))
    if kind == "other":   # a pipe or a device would block or never end
        raise _file_problem(source, "not a regular file", N_("a brief is a text file (.yaml)"))
    try:
        with path.open("rb") as f:
            raw = f.read(MAX_BYTES + 1)
    except OSError as exc:
        raise _file_problem(source, source, N_("cannot be read: {strerror}"),
                                            strerror=exc.strerror) from None
    if len(raw) > MAX_BYTES:
        raise _file_problem(source, f"more than {MAX_BYTES} bytes",
                            N_("a brief is at most {MAX_BYTES} bytes (the examples have about 10 "
                               "kB); is this the right file?"), MAX_BYTES=MAX_BYTES)
    if raw.startswith((b"\xff\xfe", b"\xfe\xff")):
        raise _file_problem(source, "UTF-16 text", N_("save the brief as UTF-8 text"))
    raw = raw.removeprefix(b"\xef\xbb\xbf")   # a byte-order mark some editors write
    nul = raw.find(b"\x00")
    if nul >= 0:
        raise _file_problem(source, f"a NUL byte at {_line_col(raw, nul)}",
                            N_("a brief is YAML text; this looks like a binary file"))
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise _file_problem(source, f"byte 0x{raw[exc.start]:02x} at {_line_col(raw, exc.start)}",
                            N_("a brief is UTF-8 text; save it as UTF-8")) from None
    if _FastLoader is not None and not _PYYAML_ONLY.search(text):
        # libyaml's scanner where it reads as PyYAML's does; an error is reported as
        # PyYAML's reader states it
        try:
            return yaml.load(text, Loader=_FastLoader)  # noqa: S506 - a safe loader
        except Exception:  # noqa: BLE001,S110 - read again below, which says what is wrong
            pass
    try:
        return yaml.load(text, Loader=_UniqueKeyLoader)  # noqa: S506 - a SafeLoader subclass
    except _LimitError as exc:
        raise BriefError(source, [BriefProblem(exc.path, exc.value, exc.allowed)]) from None
    except yaml.YAMLError as exc:
        raise BriefError(source, [_yaml_problem(exc, text)]) from None
    except RecursionError:  # not reached within MAX_DEPTH; kept as a last guard
        raise _file_problem(source, "nested too deeply",
                            N_("a brief nests sections a few levels deep")) from None


def _yaml_problem(exc: yaml.YAMLError, text: str) -> BriefProblem:
    if isinstance(exc, yaml.reader.ReaderError):   # a control character
        return BriefProblem(_line_col(text, exc.position), f"character #x{exc.character:04x}"
                            if isinstance(exc.character, int) else "a control character",
                            Msg(N_("a brief is YAML text; control characters are not allowed")))
    mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
    where = f"line {mark.line + 1}, column {mark.column + 1}" if mark else "(file)"
    problem = getattr(exc, "problem", None) or str(exc)
    if "another document" in problem:
        return BriefProblem(where, "a second YAML document",
                            Msg(N_("a brief is one YAML document: remove the `---` line and "
                                   "what follows")))
    # the Chinese names the kind of problem before PyYAML's English text
    return BriefProblem(where, "invalid YAML",
                        Msg.pgettext("invalid YAML", "{problem}", problem=problem))


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
    **dict(description="Data groups (分组/方案): the brief's fields each group overrides; "
                       "`mechdesign run BRIEF --group LABEL`, `mechdesign batch --groups all`"),
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
