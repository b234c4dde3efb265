"""The base of every design error: a design the brief's data make infeasible.

The core holds no prose: a raise site gives an English message id and its fields (numbers,
preformatted numbers, or other messages), e.g.::

    raise AssemblyError(N_("group '{group}' ({kind}) cannot be assembled at crank angle "
                           "{angle:.2f}°"), group=g, kind=k, angle=deg)

``str(exc)`` is the English text (what logs and tests read); :meth:`DesignError.text` gives
it in a report language, translated through :mod:`mechdesign.i18n` (imported when a text is
asked for, so the core reads no catalogue at import). The message names the problem, gives
the numbers and says what to change. The machines' errors (assembly, synthesis, cam, drive,
cycle, intermittent gear) subclass it.

A message is a :class:`mechdesign.i18n.Msg` (msgid + fields, a field may itself be a
message: the program's one message class, numpy-free, reading no catalogue until a text is
asked for), a :class:`Join` (messages joined by a translated separator) or, for raise sites
outside the core that still write both languages, a :class:`Text` (``i18n.Given``: an English
and a Chinese text).
"""
from __future__ import annotations

from collections import OrderedDict

from ..i18n import N_, Given, Msg  # noqa: F401  (N_ and Msg are imported from here too)


def pgettext(context: str, msgid: str, /, **fields) -> Msg:
    """A :class:`Msg` with a message context (msgctxt), for a short word that another part
    of the program may translate differently ("link" → "crank")."""
    return Msg(msgid, context, **fields)


def _render(value, lang: str):
    return value.text(lang) if isinstance(value, (Msg, Join)) else value


class Join:
    """Messages (or plain strings such as numbers) joined by a separator that is itself a
    message (``pgettext("separator", "; or ")`` → "；或")."""

    __slots__ = ("sep", "items")

    def __init__(self, sep: Msg, items):
        self.sep = sep
        self.items = tuple(items)

    def text(self, lang: str = "en") -> str:
        return self.sep.text(lang).join(str(_render(x, lang)) for x in self.items)

    def __str__(self) -> str:
        return self.text("en")

    def __bool__(self) -> bool:
        return bool(self.items)

    def __reduce__(self):
        return (Join, (self.sep, self.items))


#: the two-language form of raise sites outside the core: ``Text(en, zh)``
Text = Given


def message(msg, zh: str | None = None, /, **fields):
    """``msg`` as a message object: a Msg/Join/Text as it is, an English text with its
    Chinese (the two-language form) as a :class:`Text`, else a msgid with ``fields``."""
    if isinstance(msg, (Msg, Join)):
        return msg
    if zh is not None:
        return Text(msg, zh)
    return Msg(msg, **fields)


#: English text → message of the design errors raised lately in this process, so a brief
#: validator that wrapped one in a plain ValueError (English) can still be shown in Chinese.
_RECENT: "OrderedDict[str, object]" = OrderedDict()
_RECENT_MAX = 256


class DesignError(ValueError):
    """An infeasible design. ``DesignError(N_("msgid {x}"), x=…)`` (or a :class:`Msg`);
    ``str(exc)`` and ``exc.en`` are the English text, ``exc.text(lang)`` the message in a
    report language, ``exc.zh`` in Chinese. The two-language form ``DesignError(en, zh)``
    of raise sites outside the core still works (``zh`` None: English in every language)."""

    def __init__(self, msg, zh: str | None = None, /, **fields):
        if zh is None and isinstance(msg, str) and "zh" in fields and "{zh" not in msg:
            zh = fields.pop("zh")          # the two-language form written with a keyword
        self.message = message(msg, zh, **fields)
        en = self.message.text("en")
        super().__init__(en)
        if en and not (isinstance(self.message, Text) and not self.message.zh):
            _RECENT[en] = self.message
            _RECENT.move_to_end(en)
            while len(_RECENT) > _RECENT_MAX:
                _RECENT.popitem(last=False)

    @property
    def en(self) -> str:
        """The message in English (``str(exc)``)."""
        return self.args[0] if self.args else ""

    @property
    def zh(self) -> str | None:
        """The message in Chinese (None for a two-language raise site that gave none)."""
        if isinstance(self.message, Text) and not self.message.zh:
            return None
        return self.message.text("zh")

    def __reduce__(self):   # picklable (worker processes) with the message and every attribute
        state = {k: v for k, v in self.__dict__.items()}
        return (_restore, (type(self), self.message, state))

    def text(self, lang: str) -> str:
        """The message in ``lang`` ("zh", "en" or a variant such as "zh_TW")."""
        return self.message.text(lang)


def _restore(cls, msg, state: dict) -> DesignError:
    err = cls.__new__(cls)
    DesignError.__init__(err, msg)
    err.__dict__.update(state)
    return err


def chinese_of(text: str, exc: BaseException | None = None) -> str | None:
    """``text`` (an English message that quotes a design error, e.g. a brief validator's
    "frame_length_mm = 60: <error>") with the error's text in Chinese, or None when it
    quotes none. ``exc`` is the exception that carried ``text``: its chain is searched
    first, then the design errors raised lately in this process."""
    seen = 0
    while exc is not None and seen < 8:
        if isinstance(exc, DesignError) and exc.en and exc.en in text:
            zh = exc.zh
            if zh and zh != exc.en:
                return text.replace(exc.en, zh)
        exc = exc.__cause__ or exc.__context__
        seen += 1
    for en in reversed(_RECENT):
        if en in text:
            zh = _RECENT[en].text("zh")
            if zh != en:            # a message the catalogue does not translate quotes nothing
                return text.replace(en, zh)
    return None


def mm(x: float) -> str:
    """A length [m] in mm with up to 6 significant digits, as the messages print it."""
    return f"{x * 1e3:.6g}"
