"""Translations: gettext catalogues, one per language, loaded from their ``.po`` files.

The program's own text is English (the msgid); ``locale/zh.po`` holds its Chinese and
``locale/zh_TW.po`` its Traditional Chinese (generated from zh.po by conversion:
``python tools/i18n.py tw``). A report language is ``zh``, ``en`` or a *variant* of one of
them (``zh_TW``): the structure of a report (templates, number formats, punctuation)
follows the base language, the words follow the variant's catalogue, and a message the
variant's catalogue lacks falls back to the base catalogue, then to the English msgid.

Usage, in the rendering layer, the machines' report modules and the command line::

    from ..i18n import tr
    _ = tr(lang)
    _("crank length a = {a} mm", a=f(a_mm))     # → "曲柄长度 a = 12.5 mm" in zh
    _.pgettext("link", "frame")                  # with a context (msgctxt): 机架, not 框架

``N_("...")`` marks a string for the catalogue where it is defined (a module-level table)
and translated later; ``python tools/i18n.py check`` lists every marked string that a
catalogue lacks (tests/test_i18n.py fails on it).

The program reads the compiled catalogues (``<lang>.mo``, written beside each .po by
tools/i18n.py with Babel) with the standard library's gettext, the first time a language
needs them, once per process; Babel is a development tool only.
"""
from __future__ import annotations

from functools import lru_cache
from importlib import resources
from typing import Callable

def _discover() -> tuple[str, ...]:
    """zh and en, then every other catalogue shipped in locale/ (a directory listing only:
    adding a language is adding its ``<lang>.po``, compiled to ``<lang>.mo``)."""
    try:
        names = sorted(p.name[:-3] for p in resources.files("mechdesign.locale").iterdir()
                       if p.name.endswith(".mo"))
    except (ModuleNotFoundError, FileNotFoundError):      # pragma: no cover
        names = []
    return ("zh", "en") + tuple(n for n in names if n not in ("zh", "en"))


#: Report languages: the two base languages, then the catalogues of other languages.
#: A Chinese variant (zh_TW) is the zh report with its own words; any other language is
#: the en report (its templates, numbers, punctuation) with the words of its catalogue.
LANGUAGES = _discover()

_variant: str | None = None     # the catalogue variant of this run (set_variant)


def canonical(lang: str | None) -> str | None:
    """``lang`` as one of LANGUAGES, case and separator insensitive (zh-tw, ZH_TW → zh_TW);
    None when it is none of them."""
    if lang is None:
        return None
    key = str(lang).strip().replace("-", "_").lower()
    for name in LANGUAGES:
        if name.lower() == key:
            return name
    return None


def base(lang: str) -> str:
    """The base language (zh or en) of a report language."""
    return "zh" if str(lang).startswith("zh") else "en"


def _catalogues(lang: str) -> tuple[str, ...]:
    """The catalogues tried, in order, for a language: its own, then its base language's
    (English needs none: it is the msgid)."""
    own = () if lang == "en" else (lang,)
    return own + (("zh",) if base(lang) == "zh" and lang != "zh" else ())


def set_variant(lang: str | None) -> None:
    """Make ``lang``'s catalogue the one used for its base language in this process (the
    runner calls it with the report language: ``zh_TW`` → every ``tr("zh")`` reads
    zh_TW.po first). ``None`` or a base language resets it."""
    global _variant
    _variant = lang if lang in LANGUAGES and lang not in ("zh", "en") else None


def use(lang: str) -> str:
    """Set ``lang``'s catalogue for this process (:func:`set_variant`) and return its base
    language, the one the rest of the program is given (templates, numbers, ``tr``)."""
    set_variant(lang)
    return base(lang)


def variant() -> str | None:
    """The catalogue variant set for this process (None: the base catalogues)."""
    return _variant


def N_(msgid: str) -> str:
    """Mark ``msgid`` for the catalogues; return it unchanged (translated where used)."""
    return msgid


@lru_cache(maxsize=None)
def catalogue(name: str) -> dict:
    """The messages of ``locale/<name>.mo`` (compiled from ``<name>.po`` by Babel when the
    catalogue is written: tools/i18n.py; the standard library reads it, ~1 ms):
    {(context, msgid): msgstr}, translated ones only (a missing one falls back)."""
    import gettext as _gettext

    path = resources.files("mechdesign.locale") / f"{name}.mo"
    with path.open("rb") as fh:
        raw = _gettext.GNUTranslations(fh)._catalog
    out = {}
    for key, text in raw.items():
        if not isinstance(key, str) or not key:
            continue                                   # the header, plural entries
        context, sep, msgid = key.partition("\x04")
        out[(context, msgid) if sep else (None, key)] = text
    return out


def _chain(lang: str) -> tuple[str, ...]:
    if lang not in ("zh", "en"):
        return _catalogues(lang)
    if _variant is not None and base(_variant) == lang:
        return _catalogues(_variant)
    return _catalogues(lang)


def gettext(msgid: str, lang: str, context: str | None = None) -> str:
    """``msgid`` in ``lang`` (the English msgid itself when no catalogue has it)."""
    for name in _chain(lang):
        got = catalogue(name).get((context, msgid))
        if got is not None:
            return got
    return msgid


class Translator:
    """``_ = tr(lang)``: ``_(msgid, **fields)`` is the translation of ``msgid`` with the
    ``{fields}`` filled in (str.format); ``_.pgettext(context, msgid, **fields)`` the same with a
    message context. ``_.lang`` is the language, ``_.zh`` whether its base is Chinese."""

    __slots__ = ("lang", "zh")

    def __init__(self, lang: str):
        self.lang = lang
        self.zh = base(lang) == "zh"

    def __call__(self, msgid: str, /, **fields) -> str:
        text = gettext(msgid, self.lang)
        return text.format(**fields) if fields else text

    def pgettext(self, context: str, msgid: str, /, **fields) -> str:
        text = gettext(msgid, self.lang, context)
        return text.format(**fields) if fields else text


def tr(lang: str) -> Translator:
    """The translator of ``lang`` (see :class:`Translator`)."""
    return Translator(lang)


def jinja_callables(lang: str) -> dict[str, Callable]:
    """gettext/ngettext/pgettext for Jinja2's i18n extension (newstyle: ``{{ _("x %(n)s",
    n=v) }}``), in ``lang``."""
    def _gettext(msgid: str) -> str:
        return gettext(msgid, lang)

    def _ngettext(singular: str, plural: str, n: int) -> str:
        return gettext(singular if n == 1 else plural, lang)

    def _pgettext(context: str, msgid: str) -> str:
        return gettext(msgid, lang, context)

    return {"gettext": _gettext, "ngettext": _ngettext, "pgettext": _pgettext}
