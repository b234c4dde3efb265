"""Formatting shared by every report context (the templates get strings only).

Numbers: :func:`f` and :func:`e`.

User text (titles, names, labels from the brief) is escaped once, at the boundary where it
enters an output format, so that it appears literally and cannot inject markup:

* :func:`md_text` / :func:`md_paragraphs`: pandoc Markdown (body, table cells, metadata);
* :func:`mpl_text`: matplotlib text (a ``$`` would start mathtext);
* :func:`tex_name`: a point name inside a formula (LaTeX or mathtext);
* :func:`dxf_text`: a DXF TEXT entity (``%%`` codes and caret notation);
* :func:`plain_line`: one line of plain text (no control characters, no line breaks).
"""
from __future__ import annotations

import re


def f(x: float, digits: int = 2) -> str:
    """Fixed-point number with ``digits`` decimals; a rounded zero never shows as '-0.00'."""
    text = f"{x:.{digits}f}"
    return text[1:] if text.startswith("-") and float(text) == 0.0 else text


def e(x: float) -> str:
    """Small residuals in scientific notation for the verification tables."""
    return f"{x:.1e}"


# -------------------------------------------------------------------------- user text

# C0/C1 control characters other than the ASCII white space (which is collapsed instead),
# and the Unicode line/paragraph separators: no output format shows them, XML forbids most.
_CONTROL = re.compile("[\x00-\x08\x0e-\x1f\x7f-\x9f\u2028\u2029]")
_SPACE = re.compile(r"[ \t\n\r\f\v]+")


def plain_line(s) -> str:
    """``s`` as one line of plain text: control characters dropped, runs of white space
    (line breaks included) collapsed to one space, no leading or trailing space."""
    return _SPACE.sub(" ", _CONTROL.sub("", str(s))).strip()


# Characters pandoc's Markdown reader gives a meaning somewhere in a line: emphasis, code,
# math, raw HTML/TeX, links and spans, citations, sub/superscript, entities, pipe-table
# cells, smart quotes; each is written as a backslash escape (pandoc: all_symbols_escapable).
_MD_SPECIAL = re.compile(r"""([\\`*_{}\[\]<>#$@|~^&"'])""")
# Smart punctuation: "--" and "---" become dashes, "..." an ellipsis.
_MD_DASHES = re.compile(r"-(?=-)")
_MD_DOTS = re.compile(r"\.(?=\.)")
# What a line may start with to open a block: list items (- + * 1. 1) a. (a) iv.), a
# definition or fenced div (:), a setext underline or table rule (=, -), a title block (%).
_MD_LEAD_MARK = re.compile(r"^[-+:=%]")
_MD_LEAD_ORDINAL = re.compile(r"^(\d+|[A-Za-z]|[ivxlcdmIVXLCDM]+)([.)])(?=\s|$)")
_MD_LEAD_PAREN = re.compile(r"^\((?=(\d+|[A-Za-z]|[ivxlcdmIVXLCDM]+)\)(\s|$))")


def md_text(s) -> str:
    """``s`` as pandoc Markdown that reads back as exactly this text (one line).

    Safe in running text, in a pipe-table cell, at the start of a line or list item, inside
    ``**…**`` and as a metadata value (pandoc parses those as Markdown too). Ordinary text
    (Chinese, letters, digits, spaces, ``,.;:/()-+%=°``) is returned unchanged, except
    ``--`` and ``..`` and what would open a block at the start (``-``, ``+``, ``:``, ``=``,
    ``%``, a list marker such as ``1.`` or ``(a)`` followed by a space)."""
    text = plain_line(s)
    text = _MD_SPECIAL.sub(r"\\\1", text)
    text = _MD_DASHES.sub(r"\\-", text)
    text = _MD_DOTS.sub(r"\\.", text)
    if _MD_LEAD_MARK.match(text):
        return "\\" + text
    text = _MD_LEAD_ORDINAL.sub(r"\1\\\2", text)
    return _MD_LEAD_PAREN.sub(r"\\(", text)


def md_paragraphs(s) -> str:
    """Several paragraphs of user text (blank lines between them) as pandoc Markdown:
    each line escaped as by :func:`md_text`, line breaks inside a paragraph kept (soft
    breaks; between Chinese characters pandoc drops them), paragraphs separated by one
    blank line. Insert it as a block of its own."""
    paragraphs = re.split(r"\n[ \t\f\v\r]*\n", _CONTROL.sub("", str(s).replace("\r\n", "\n")))
    out = []
    for para in paragraphs:
        lines = [md_text(line) for line in para.split("\n")]
        lines = [line for line in lines if line]
        if lines:
            out.append("\n".join(lines))
    return "\n\n".join(out)


def mpl_text(s) -> str:
    """``s`` for a matplotlib text or legend label, drawn as written: one line, every
    ``$`` escaped (it would start mathtext), and a leading ``_`` (which hides a legend
    entry) preceded by a zero-width space. Also safe next to mathtext in the same string."""
    text = plain_line(s).replace("$", r"\$")
    if text.endswith("\\"):
        text += "\u200b"          # keep a trailing backslash from escaping a following "$"
    return "\u200b" + text if text.startswith("_") else text


_TEX_SUB = re.compile(r"^([^_]*)_([A-Za-z0-9]+)(.*)$")


def tex_name(name: str) -> str:
    r"""A point name (letters, digits, ``_`` and ``'``, as the brief allows) inside a formula,
    e.g. ``$F_{{{tex_name(n)}}}$``, that LaTeX, pandoc and matplotlib's mathtext all accept:
    ``O2``, ``C'`` and ``S_3`` stay as written (S with subscript 3); a longer subscript is
    grouped (``S_12`` → ``S_{12}``, ``B_2_x`` → ``B_{2\_x}``); an underscore that opens no
    subscript (``B_``, ``B__2``) is a literal ``\_``."""
    name = str(name)
    m = _TEX_SUB.match(name)
    if m is None:
        return name.replace("_", r"\_")
    head, sub, rest = m.groups()
    if rest.strip("'") == "":                       # only primes after the subscript
        return f"{head}_{sub}{rest}" if len(sub) == 1 else f"{head}_{{{sub}}}{rest}"
    rest = rest.replace("_", r"\_")
    return f"{head}_{{{sub}{rest}}}"


def dxf_text(s) -> str:
    """``s`` for a DXF TEXT entity, shown as written by CAD programs: one line, ``%`` as the
    literal-percent code ``%%%`` (``%%d``, ``%%c``, ``%%p``, ``%%u`` are control codes), ``^``
    as ``^ `` (a caret followed by a character is a control character in DXF strings)."""
    return plain_line(s).replace("%", "%%%").replace("^", "^ ")


def md_meta(meta) -> dict[str, str]:
    """The brief's ``report`` section (:class:`~mechdesign.brief.common.ReportMeta`) for a
    template (``meta.title``, …): every text field escaped by :func:`md_text`."""
    fields = ("title", "subtitle", "student", "student_id", "class_name", "teacher", "date")
    out = {name: md_text(getattr(meta, name, "")) for name in fields}
    out["language"] = str(getattr(meta, "language", ""))
    return out
