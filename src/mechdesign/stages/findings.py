"""Findings: design problems a stage found that leave the design computable but poor.

Their words live in the catalogues (``locale/*.po``): a stage builds a finding with
:func:`finding` from an English msgid and its fields; :func:`en_zh` gives the same pair of
texts for a design error (``DesignError(en, zh)``)."""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from ..core.fields import q
from ..i18n import Msg, Pair, _field_text, base, tr  # noqa: F401  (Msg, Pair: i18n's message)


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
    field may be a :class:`~mechdesign.i18n.Msg` (translated too) or a
    :class:`~mechdesign.i18n.Pair` (a value per language)."""
    msg = Msg(msgid, context, **fields)
    return msg.text("en"), msg.text("zh")


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
