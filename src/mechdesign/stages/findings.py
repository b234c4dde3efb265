"""Findings: design problems a stage found that leave the design computable but poor.

Their words live in the catalogues (``locale/*.po``): a stage builds a finding with
:func:`finding` from an English msgid and its fields; :func:`en_zh` gives the same pair of
texts for a design error (``DesignError(en, zh)``)."""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from ..core.fields import q
from ..i18n import base, tr


@dataclass(frozen=True)
class Finding:
    """A design problem found by a check: ``code`` names it, the messages say what to change."""

    code: str = q("", "the problem's name")
    zh: str = q("", "what it is and what to change (Chinese)")
    en: str = q("", "what it is and what to change (English)")
    field: str = q("", "the brief field it is about, when it is about one", default="")

    def text(self, lang: str) -> str:
        return self.zh if base(lang) == "zh" else self.en


def en_zh(msgid: str, /, context: str | None = None, **fields) -> tuple[str, str]:
    """(English, Chinese) of the catalogue message ``msgid`` with its ``{fields}`` filled in
    (the Chinese of the run's catalogue variant, see :func:`mechdesign.i18n.set_variant`); a
    field may be a :class:`Msg` (translated too) or a :class:`Pair` (a value per language)."""
    return tuple(Msg(msgid, context, **fields).text(tr(lang)) for lang in ("en", "zh"))


def finding(code: str, msgid: str, /, field: str = "", **fields) -> Finding:
    """The finding ``code`` whose texts are the catalogue message ``msgid`` (English, marked
    with N_ where written) with ``fields`` filled in (``field``, the brief field, is one too)."""
    en, zh = en_zh(msgid, field=field, **fields)
    return Finding(code, zh, en, field=field)


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


class Msg:
    """A catalogue message used as a field of another one, translated in each language:
    ``finding("pointed", N_("…; {fix}."), fix=Msg(N_("reduce {field}"), field=f))``."""

    __slots__ = ("msgid", "context", "fields")

    def __init__(self, msgid: str, /, context: str | None = None, **fields):
        self.msgid, self.context, self.fields = msgid, context, fields

    def text(self, t) -> str:
        """The message in the language of the translator ``t`` (``tr(lang)``)."""
        fields = _resolved(self.fields, t)
        if self.context is None:
            return t(self.msgid, **fields)
        return t.pgettext(self.context, self.msgid, **fields)


class Pair:
    """A field whose value differs by language (a name the data give in both, e.g. a drive
    stage's name_zh / name_en)."""

    __slots__ = ("zh", "en")

    def __init__(self, zh, en):
        self.zh, self.en = zh, en


class Cat:
    """Parts (messages, pairs, text) written one after the other, e.g. a fix and the
    alternatives appended to it."""

    __slots__ = ("parts",)

    def __init__(self, *parts):
        self.parts = parts

    def __add__(self, other) -> "Cat":
        return Cat(*self.parts, other)

    def text(self, t) -> str:
        return "".join(_one(v, t) for v in self.parts)


def _one(v, t):
    if isinstance(v, (Msg, Cat)):
        return v.text(t)
    if isinstance(v, Pair):
        return v.zh if t.zh else v.en
    return v


def _resolved(fields: dict, t) -> dict:
    return {k: _one(v, t) for k, v in fields.items()}


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
