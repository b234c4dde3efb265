"""The base of every design error: a design the brief's data make infeasible.

A :class:`DesignError` carries its message in English (``str(exc)``, what logs and
tests read) and in Chinese; :meth:`DesignError.text` picks the report's language. The
message names the problem, gives the numbers and says what to change. The machines'
errors (assembly, synthesis, cam, drive, cycle, intermittent gear) subclass it.
"""
from __future__ import annotations

from collections import OrderedDict

#: English → Chinese text of the design errors raised lately in this process, so a brief
#: validator that wrapped one in a plain ValueError (English) can still be shown in Chinese.
_RECENT: "OrderedDict[str, str]" = OrderedDict()
_RECENT_MAX = 256


class DesignError(ValueError):
    """An infeasible design. ``en`` is ``str(exc)``; ``zh`` the same in Chinese (falls back
    to the English text when a raise site has none)."""

    def __init__(self, en: str, zh: str | None = None):
        super().__init__(en)
        self.en = en
        self.zh = zh
        if zh and en:
            _RECENT[en] = zh
            _RECENT.move_to_end(en)
            while len(_RECENT) > _RECENT_MAX:
                _RECENT.popitem(last=False)

    def __reduce__(self):   # picklable with both texts (worker processes)
        return (type(self), (self.en, self.zh))

    def text(self, lang: str) -> str:
        """The message in ``lang`` ("zh" or "en")."""
        if lang == "zh" and self.zh:
            return self.zh
        return self.en


def chinese_of(text: str, exc: BaseException | None = None) -> str | None:
    """``text`` (an English message that quotes a design error, e.g. a brief validator's
    "frame_length_mm = 60: <error>") with the error's text in Chinese, or None when it
    quotes none. ``exc`` is the exception that carried ``text``: its chain is searched
    first, then the design errors raised lately in this process."""
    seen = 0
    while exc is not None and seen < 8:
        if isinstance(exc, DesignError) and exc.zh and exc.en in text:
            return text.replace(exc.en, exc.zh)
        exc = exc.__cause__ or exc.__context__
        seen += 1
    for en in reversed(_RECENT):
        if en in text:
            return text.replace(en, _RECENT[en])
    return None


def mm(x: float) -> str:
    """A length [m] in mm with up to 6 significant digits, as the messages print it."""
    return f"{x * 1e3:.6g}"
