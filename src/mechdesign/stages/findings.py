"""Findings: design problems a stage found that leave the design computable but poor.

A finding holds codes and numbers, never prose (issue 22 point 3): its ``code``, the
catalogue message that says it (``msgid``: the English text of ``locale/*.po``, with an
optional message ``context``), the message's fields as plain JSON data (``args``: numbers,
brief field paths, nested messages as ``{"msgid", "context", "args"}``) and the brief
``field`` it is about. Its text is made where it is shown, in the report's language:
``finding.text(lang)`` (zh, en or a variant such as zh_TW). A stage builds one with
:func:`finding` from an English msgid (marked ``N_``) and its fields; a field may be a
:class:`~mechdesign.i18n.Msg`, a :class:`Cat`, a :class:`~mechdesign.core.errors.Join`, a
:class:`Named` (a name from a data table) or a :class:`~mechdesign.i18n.Pair` (a text the
data give in both languages; one whose English is a catalogue msgid with that Chinese is
stored as the msgid).

Design errors raised by the stages take the same kind of message (``DesignError(Msg(msgid,
**fields))``: translated when shown, see :mod:`mechdesign.core.errors`); :func:`en_zh`
still gives the (English, Chinese) texts of a message for the few callers that hold both
(a brief check's problem rows)."""
from __future__ import annotations

import json
from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache

from ..core.fields import q
from ..i18n import Given, Msg, Pair, _field_text, base, catalogue, data_text, gettext, tr  # noqa: F401


@dataclass(frozen=True)
class Finding:
    """A design problem found by a check: ``code`` names it; ``msgid`` with ``args`` says what
    it is and what to change, translated when shown (:meth:`text`)."""

    code: str = q("", "the problem's name (a stable code: undercut, strength, pressure_angle …)")
    msgid: str = q("", "its message: the English msgid of the catalogues (locale/*.po), a "
                   "str.format template whose fields are args (and field)")
    args: dict = q("", "the message's fields as data: numbers, brief field paths and values, "
                   "nested messages as {msgid, context, args}, a list of parts as {cat: […]}, "
                   "a name from a data table as {table, key}, a text the data give in both "
                   "languages as {en, zh}", default_factory=dict)
    context: str | None = q("", "the msgid's message context (msgctxt), null for none", default=None)
    field: str = q("", "the brief field it is about, when it is about one", default="")

    #: keys results.json adds to the fields (results.to_plain, results_docs)
    PLAIN_EXTRA = (("text", "", "the message rendered in English (the msgid's language), for "
                                "readers of this file; the report renders it in its own language"),)

    def message(self) -> Msg:
        """The finding's message (translated where shown)."""
        fields = {k: decode(v) for k, v in self.args.items()}
        fields.setdefault("field", self.field)
        return Msg(self.msgid, self.context, **fields)

    def text(self, lang: str) -> str:
        """What it is and what to change, in ``lang`` (zh, en, zh_TW …)."""
        return self.message().text(lang)

    @property
    def en(self) -> str:
        return self.text("en")

    @property
    def zh(self) -> str:
        return self.text("zh")

    def __plain__(self) -> dict:
        return {"code": self.code, "msgid": self.msgid, "args": self.args,
                "context": self.context, "field": self.field, "text": self.text("en")}

    def __hash__(self) -> int:
        return hash((self.code, self.msgid, self.context, self.field,
                     json.dumps(self.args, sort_keys=True, default=str)))


class Named:
    """A name a data table gives in both languages (``name_zh``/``name_en`` of a row of
    ``data/<table>.yaml``; ``<file>.<section>`` for a row of one section of a file, e.g.
    ``materials.shaft``), stored as the table and the row's key."""

    __slots__ = ("table", "key")

    def __init__(self, table: str, key: str):
        self.table, self.key = table, key

    def text(self, lang="en") -> str:
        from ..data import load_yaml

        lang = getattr(lang, "lang", lang)
        file, _, section = self.table.partition(".")
        rows = load_yaml(f"{file}.yaml")
        row = (rows[section] if section else rows)[self.key]
        return data_text(row["name_zh"], lang) if base(lang) == "zh" else row["name_en"]

    def __reduce__(self):
        return (Named, (self.table, self.key))


@lru_cache(maxsize=1)
def _contexts() -> dict:
    """msgid → the message contexts the zh catalogue holds it under (None: no context)."""
    out: dict = {}
    for context, msgid in catalogue("zh"):
        out.setdefault(msgid, []).append(context)
    return out


def _pair(zh, en):
    """A :class:`Pair` as data: the English alone when both are the same, the catalogue
    message when the English is a msgid whose Chinese (in the run's catalogue) is ``zh``,
    else both texts (a text the data give in both languages, e.g. a brief's)."""
    zh, en = encode(zh), encode(en)
    if not isinstance(zh, str) or not isinstance(en, str):
        return {"en": en, "zh": zh}
    if zh == en or not zh:
        return en
    for context in _contexts().get(en, ()):
        if gettext(en, "zh", context) == zh:
            return {"msgid": en} if context is None else {"msgid": en, "context": context}
    return {"en": en, "zh": zh}


def encode(value):
    """A message field as JSON data (see :class:`Finding`)."""
    import numpy as np

    from ..core.errors import Join

    if isinstance(value, Given):
        return _pair(value.zh, value.en) if value.zh else str.__str__(value)
    if isinstance(value, Msg):
        out = {"msgid": value.msgid}
        if value.context is not None:
            out["context"] = value.context
        if value.fields:
            out["args"] = {k: encode(v) for k, v in value.fields.items()}
        return out
    if isinstance(value, Cat):
        return {"cat": [encode(v) for v in value.parts]}
    if isinstance(value, Join):
        return {"join": encode(value.sep), "items": [encode(v) for v in value.items]}
    if isinstance(value, Pair):
        return _pair(value.zh, value.en)
    if isinstance(value, Named):
        return {"table": value.table, "key": value.key}
    if value is None or isinstance(value, (bool, np.bool_)):
        return None if value is None else bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return float(value)
    if isinstance(value, str):
        return str.__str__(value)
    raise TypeError(f"a finding's field is a number, a text or a message, not {type(value).__name__}")


def decode(value):
    """The message field that :func:`encode` stored as ``value``."""
    if not isinstance(value, dict):
        return value
    if "msgid" in value:
        return Msg(value["msgid"], value.get("context"),
                   **{k: decode(v) for k, v in (value.get("args") or {}).items()})
    if "cat" in value:
        return Cat(*(decode(v) for v in value["cat"]))
    if "join" in value:
        from ..core.errors import Join

        return Join(decode(value["join"]), [decode(v) for v in value["items"]])
    if "table" in value:
        return Named(value["table"], value["key"])
    if "en" in value:
        return Pair(decode(value.get("zh")), decode(value["en"]))
    return value


def check_name(name: str, args: Mapping | None = None) -> Msg:
    """A strength check's name as a message: its msgid ``name`` (core.strength.Check.name)
    with its fields ``args`` (``name_args``: texts, or a name from a data table stored as
    ``{table, key}``); pass a Check, or a check's plain dict from results.json, alone."""
    if not isinstance(name, str):
        name, args = ((name["name"], name.get("name_args")) if isinstance(name, Mapping)
                      else (name.name, name.name_args))
    return Msg(name, **{k: decode(v) for k, v in (args or {}).items()})


def en_zh(msgid: str, /, context: str | None = None, **fields) -> tuple[str, str]:
    """(English, Chinese) of the catalogue message ``msgid`` with its ``{fields}`` filled in
    (the Chinese of the run's catalogue variant, see :func:`mechdesign.i18n.set_variant`); a
    field may be a :class:`~mechdesign.i18n.Msg` (translated too) or a
    :class:`~mechdesign.i18n.Pair` (a value per language)."""
    msg = Msg(msgid, context, **fields)
    return msg.text("en"), msg.text("zh")


def finding(code: str, msgid: str, /, field: str = "", context: str | None = None,
            **fields) -> Finding:
    """The finding ``code`` whose message is the catalogue message ``msgid`` (English, marked
    with N_ where written) with ``fields`` (``field``, the brief field, is one too)."""
    return Finding(code, msgid, {k: encode(v) for k, v in fields.items()}, context, field)


def finding_of(code: str, message, field: str = "") -> Finding:
    """The finding ``code`` saying ``message`` (a :class:`~mechdesign.i18n.Msg`, e.g. a
    core design note's)."""
    data = encode(message)
    if not isinstance(data, dict) or "msgid" not in data:
        data = {"msgid": "{text}", "args": {"text": data}}
    return Finding(code, data["msgid"], data.get("args", {}), data.get("context"), field)


class CheckNames(Mapping):
    """The names of self-checks, key → (zh, en) as the report modules read them; held as
    English msgids (marked N_) and translated when looked up."""

    def __init__(self, names: dict[str, str]):
        self._names = dict(names)

    def __getitem__(self, key: str) -> tuple[str, str]:
        en = self._names[key]
        return tr("zh")(en), en

    def __iter__(self):
        return iter(self._names)

    def __len__(self) -> int:
        return len(self._names)


class Cat:
    """Parts (messages, pairs, text) written one after the other, e.g. a fix and the
    alternatives appended to it."""

    __slots__ = ("parts",)

    def __init__(self, *parts):
        self.parts = parts

    def __add__(self, other) -> "Cat":
        return Cat(*self.parts, other)

    def text(self, lang) -> str:
        """The parts in ``lang`` (a language or a :class:`~mechdesign.i18n.Translator`)."""
        return "".join(str(_field_text(v, lang)) for v in self.parts)


class _ZhEn:
    """``zh_en.gettext(msgid)``, ``zh_en.pgettext(context, msgid)``: (Chinese, English) of a
    catalogue name, for the tables that hold names as (zh, en) pairs (the linkage engine's
    link names and group labels, advice). Marked for the catalogue by these names."""

    @staticmethod
    def gettext(msgid: str, /, **fields) -> tuple[str, str]:
        return tr("zh")(msgid, **fields), tr("en")(msgid, **fields)

    @staticmethod
    def pgettext(context: str, msgid: str, /, **fields) -> tuple[str, str]:
        return tr("zh").pgettext(context, msgid, **fields), tr("en").pgettext(context, msgid, **fields)


zh_en = _ZhEn()
