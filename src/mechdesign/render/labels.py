"""Module-level tables of texts in the catalogues: ``LABELS = LabelTable({"x": N_("…")})``
is written once in English and read as ``LABELS[lang]["x"]`` — the table in ``lang``
(a dict, built on each lookup from the catalogue; str values, ``pgettext(context, msgid)``
entries and tuples of them are translated, anything else is passed through)."""
from __future__ import annotations

from collections.abc import Mapping
from typing import NamedTuple

from ..i18n import LANGUAGES, tr


class InContext(NamedTuple):
    """A table entry with a message context (msgctxt)."""
    context: str
    msgid: str


def pgettext(context: str, msgid: str) -> InContext:
    """Mark ``msgid`` with a ``context`` in a table (one English text, two Chinese ones);
    translated where the table is read. Named like gettext's function so that the
    catalogue tools find it."""
    return InContext(context, msgid)


def translated(value, _):
    """``value`` (a str, a tuple/list of str or nested ones) through the translator ``_``."""
    if isinstance(value, InContext):
        return _.pgettext(value.context, value.msgid)
    if isinstance(value, str):
        return _(value) if value else value
    if isinstance(value, tuple):
        return tuple(translated(v, _) for v in value)
    if isinstance(value, list):
        return [translated(v, _) for v in value]
    return value


class LabelTable(Mapping):
    """{language: {key: text}} of a table of English texts marked with ``N_``."""

    def __init__(self, english: dict):
        self.english = english

    def __getitem__(self, lang: str) -> dict:
        _ = tr(lang)
        return {k: translated(v, _) for k, v in self.english.items()}

    def __iter__(self):
        return iter(LANGUAGES)

    def __len__(self) -> int:
        return len(LANGUAGES)

    def __contains__(self, lang) -> bool:
        return isinstance(lang, str)
