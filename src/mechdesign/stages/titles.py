"""Stage titles: an English msgid of the catalogues with its message context, translated
where it is shown (``render.fmt.in_lang(title, lang)``: the command line's progress).

``titles.pgettext("stage", "drive")`` marks the title for the catalogue (tools/i18n.py
extracts it like ``_.pgettext``) and returns it as a :class:`Title`, a ``str`` (its English
text, what logs and timings show) that remembers its context. Every stage title has the
context "stage", so that it cannot clash with the same English word elsewhere; one English
title with two Chinese ones gets a more precise context ("stage: self-checks")."""
from __future__ import annotations


class Title(str):
    """A stage title: the English text, with ``context`` the message context of its msgid."""

    context: str | None = None

    def __reduce__(self):        # picklable (worker processes) with its context
        return (pgettext, (self.context, str(self)))


def pgettext(context: str | None, msgid: str) -> Title:
    """The title ``msgid`` (English) with the message context ``context``."""
    title = Title(msgid)
    title.context = context
    return title
