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


@lru_cache(maxsize=None)
def data_names(name: str) -> dict:
    """The Chinese texts of the shipped data tables (``*_zh`` fields of ``data/*.yaml``:
    materials, transmissions …) in the Chinese variant ``name`` (``zh_TW``):
    ``locale/<name>.data.json``, written with the variant's catalogue by the same conversion
    (``python tools/i18n.py tw``); {} when the variant has none."""
    import json

    path = resources.files("mechdesign.locale") / f"{name}.data.json"
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (FileNotFoundError, OSError):
        return {}


def data_text(text: str, lang: str = "zh") -> str:
    """A Chinese text of a data table (a material's or a stage's ``name_zh``) in ``lang``:
    in a Chinese variant (``zh_TW``, or ``zh`` in a zh_TW run) its converted form, else the
    text itself (a text the conversion does not know is returned unchanged)."""
    lang = getattr(lang, "lang", lang)
    name = lang if lang not in ("zh", "en") else (_variant if lang == "zh" else None)
    if not name or base(name) != "zh" or not isinstance(text, str):
        return text
    return data_names(name).get(text, text)


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


# ------------------------------------------------------------------------------ messages

def _field_text(value, lang: str):
    """A message field in ``lang``: a message (anything with ``text(lang)``: :class:`Msg`,
    :class:`Pair`, a join of messages …) translated, any other value as it is."""
    text = getattr(value, "text", None)
    return text(lang) if callable(text) else value


class Msg(str):
    """A message translated where it is shown — the one message class of the program (the
    core's design errors, the brief's checks, the stages' findings): an English msgid (marked
    with ``N_`` where it is written), its ``str.format`` fields, filled in after translation,
    and an optional message context. A field that is a message itself (or a :class:`Pair`)
    is shown in the same language.

    The string itself is the English text (what logs, tests and pydantic read);
    :meth:`text` gives it in a report language::

        Msg(N_("take H ≥ {h} mm"), h=12)          # "take H ≥ 12 mm"
        Msg.pgettext("link", "crank").text("zh")   # "曲柄"

    Pure Python, no numpy and no catalogue read until a text is asked for: the core may
    import it."""

    def __new__(cls, msgid: str, /, context: str | None = None, **fields):
        en = msgid
        if fields:
            try:
                en = msgid.format(**{k: _field_text(v, "en") for k, v in fields.items()})
            except (KeyError, IndexError):   # a template whose other fields come later (the
                pass                         # core's "{where}" filled by the error): its msgid
        self = super().__new__(cls, en)
        self.msgid, self.context, self.fields = msgid, context, fields
        return self

    @classmethod
    def pgettext(cls, context: str, msgid: str, /, **fields) -> "Msg":
        """The message ``msgid`` with the message context ``context``."""
        return cls(msgid, context, **fields)

    def text(self, lang="en") -> str:
        """The message in ``lang`` (zh, en, a variant such as zh_TW, or a :class:`Translator`):
        its catalogue, then the base language's, then the English msgid."""
        if isinstance(lang, Translator):
            lang = lang.lang
        if lang == "en":
            return str.__str__(self)
        text = gettext(self.msgid, lang, self.context)
        if not self.fields:
            return text
        return text.format(**{k: _field_text(v, lang) for k, v in self.fields.items()})

    def __str__(self) -> str:
        return str.__str__(self)

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.msgid!r}, context={self.context!r}, **{self.fields!r})"

    def __reduce__(self):      # picklable (worker processes): the English, then the rest
        return (_rebuilt, (type(self), str.__str__(self), self.__dict__))


def _rebuilt(cls, en: str, state: dict) -> "Msg":
    self = str.__new__(cls, en)
    self.__dict__.update(state)
    return self


class Given(Msg):
    """A message whose texts were written elsewhere (a design error raised with its English
    and Chinese, a message translated already): ``Given(en, zh)``; English where ``zh`` is
    None."""

    def __new__(cls, en: str, zh: str | None = None):
        self = str.__new__(cls, en)
        self.msgid, self.context, self.fields, self.zh = en, None, {}, zh
        return self

    @property
    def en(self) -> str:
        return str.__str__(self)

    def text(self, lang="en") -> str:
        if isinstance(lang, Translator):
            lang = lang.lang
        return self.zh if self.zh and base(lang) == "zh" else str.__str__(self)


class Pair:
    """A message field whose value differs by language (a name the data give in both, e.g. a
    drive stage's name_zh / name_en): ``Pair(zh, en)``."""

    __slots__ = ("zh", "en")

    def __init__(self, zh, en):
        self.zh, self.en = zh, en

    def text(self, lang="en"):
        if isinstance(lang, Translator):
            lang = lang.lang
        return self.zh if base(lang) == "zh" else self.en

    def __reduce__(self):
        return (Pair, (self.zh, self.en))
