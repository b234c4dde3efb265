"""Module-level tables of texts in the catalogues: ``LABELS = LabelTable({"x": N_("…")})``
is written once in English and read as ``LABELS[lang]["x"]`` — the table in ``lang``
(a dict, built on each lookup from the catalogue; str values, ``pgettext(context, msgid)``
entries and tuples of them are translated, anything else is passed through)."""
from __future__ import annotations

import re
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


# -- point names typeset -------------------------------------------------------------------
# The textbook writes a point name's digits as a subscript: O₁, S₃, B₁B₂, A₄O₃ (letters and
# primes as they are). A name becomes text in one of three media — Markdown (pandoc math
# ``$O_1$``), a matplotlib figure (mathtext ``$O_1$``) or a drawing sheet (the sheet's
# subscript markers, :func:`~mechdesign.render.sheet.sub`) — and each has one function here
# for a name (or a run of names such as "O1A") and one for a text holding names ("crank O1A",
# "导杆 O3D"). A name inside a subscript (``v_{S4}``, ``F_{R12}``, ``l_{O2A}``) is already
# lowered and stays as written.

_NAMES = re.compile(r"(?:[A-Z][0-9]*'*)+")
_DIGITS = re.compile(r"([A-Z])([0-9]+)")
# a run of point names with a digit standing as a word (not inside "Y90S-6"-like codes:
# callers pass only texts that hold point names)
_NAME_WORD = re.compile(r"(?<![A-Za-z0-9_\\$'{])((?:[A-Z][0-9]*'*)*[A-Z][0-9]+'*(?:[A-Z][0-9]*'*)*)"
                        r"(?![A-Za-z0-9_$}]|'(?![a-z]))")


def subscripted(name: str) -> bool:
    """True when ``name`` is a point name (or a run of them, "O1A") with a digit to lower."""
    name = str(name)
    return bool(_NAMES.fullmatch(name)) and any(ch.isdigit() for ch in name)


def point_tex(name: str) -> str:
    r"""A point name, or a run of them, in TeX (LaTeX, pandoc, mathtext) with its digits a
    subscript: "O1" → "O_1", "O1A" → "O_1A", "A4O3" → "A_4O_3", "S12'" → "S_{12}'"; another
    form as :func:`~mechdesign.render.fmt.tex_name` writes it."""
    from .fmt import tex_name

    name = str(name)
    if not _NAMES.fullmatch(name):
        return tex_name(name)
    return _DIGITS.sub(lambda m: f"{m[1]}_{m[2]}" if len(m[2]) == 1 else f"{m[1]}_{{{m[2]}}}", name)


def md_point(name: str) -> str:
    """A point name (or a run of them) for Markdown, in math italic as the textbook sets
    point names, with or without a digit: "$O_1$", "$O_1A$", "$AB$", "$C'$"; anything else
    escaped as written."""
    from .fmt import md_text

    return f"${point_tex(name)}$" if _NAMES.fullmatch(str(name)) else md_text(name)


def _mpl_math(name: str) -> str:
    # mathtext as the report's math: its letters math italic (DejaVu Sans Oblique, see
    # render/fonts.py), the digits upright subscripts; a prime "′" (U+2032), since mathtext
    # draws "'" as a superscript \prime that the shipped fonts render as a small "0"
    return "$" + point_tex(name).replace("'", "′") + "$"


def mpl_point(name: str) -> str:
    """A point name (or a run of them) for a matplotlib text, in math italic as the report and
    the sheets set it, with or without a digit: "$O_1$", "$A$", "$O_1A$", "$C′$"; anything
    else as written."""
    from .fmt import mpl_text

    plain = str(name).replace("′", "'")
    return _mpl_math(plain) if _NAMES.fullmatch(plain) else mpl_text(name)


# A sheet text marks a subscript with two private-use characters (never in user text):
# "μ" + SUB_ON + "v" + SUB_OFF is μ with the subscript v (render/sheet.py draws them).
SUB_ON, SUB_OFF = "\ue000", "\ue001"


# a superscript (the n, t, k, r of a^n_BO3) likewise: "a" + SUP_ON + "n" + SUP_OFF
SUP_ON, SUP_OFF = "\ue002", "\ue003"


# italic letters (a point name, as the report sets it): IT_ON + "B" + IT_OFF; the typst back
# end slants them (the sheet font, Noto Sans SC, has no italic), the DXF's MTEXT obliques
# them by 15° (\\Q15;)
IT_ON, IT_OFF = "\ue004", "\ue005"
MARKERS = (SUB_ON, SUB_OFF, SUP_ON, SUP_OFF, IT_ON, IT_OFF)


def italic(text: str) -> str:
    """``text`` set in italic on a sheet."""
    return f"{IT_ON}{text}{IT_OFF}" if text else text


def sup(base: str, index: str) -> str:
    """``base`` with the superscript ``index`` (e.g. ``sup("a", "n")``) for a sheet text."""
    return f"{base}{SUP_ON}{index}{SUP_OFF}"


def sub(base: str, index: str) -> str:
    """``base`` with the subscript ``index`` (e.g. ``sub("φ", "max")``) for a sheet text."""
    return f"{base}{SUB_ON}{index}{SUB_OFF}"


_LETTER = re.compile(r"([A-Z]'*)([0-9]*)('*)")


def sheet_point(name: str) -> str:
    """A point name (or a run of them) for a sheet text, as the report sets it: its letters
    italic, its digits marked as subscripts ("O1A": italic O, subscript 1, italic A);
    another text as written."""
    name = str(name)
    if not _NAMES.fullmatch(name):
        return name
    return _LETTER.sub(lambda m: italic(m[1]) + (sub("", m[2]) if m[2] else "") + m[3], name)


# a run of point names standing as a word, with or without a digit ("O1A", "DBC", "E"), for
# Markdown, where every point name is math italic; an Assur group's code (RRR, RRP, RPR)
# names no point
_ANY_NAME_WORD = re.compile(r"(?<![A-Za-z0-9_\\$'{])((?:[A-Z][0-9]*'*)+)(?![A-Za-z0-9_$}]|'(?![a-z]))")
_GROUP_CODE = re.compile(r"[RP]{3}")


def md_names(text: str) -> str:
    """A text holding point names ("crank O1A", "导杆 O3D", "rocker DBC", "RRR ABD") for
    Markdown: escaped, each run of names as math ("crank $O_1A$", "rocker $DBC$"; the group
    code RRR stays a word)."""
    from .fmt import md_text

    return _ANY_NAME_WORD.sub(lambda m: m[1] if _GROUP_CODE.fullmatch(m[1]) else f"${point_tex(m[1])}$",
                              md_text(text))


# a run of point names standing as a word in a figure's text, with or without a digit, primes
# written ' or ′ ("A", "O4B", "A′"); an Assur group's code (RRR) and a Roman numeral (II) name
# no point
_MPL_NAME_WORD = re.compile(r"(?<![A-Za-z0-9_\\$'′{])((?:[A-Z][0-9]*['′]*)+)(?![A-Za-z0-9_$}])")
_NOT_A_NAME = re.compile(r"[RP]{3}|[IVX]{2,}")


def _mpl_names_outside_math(text: str) -> str:
    return _MPL_NAME_WORD.sub(lambda m: m[1] if _NOT_A_NAME.fullmatch(m[1])
                              else _mpl_math(m[1].replace("′", "'")), text)


def mpl_names(text: str) -> str:
    """A text holding point names (a user's or a catalogue's plain text, "rocker O4B",
    "A (folded)", "RRR A-B-C") for a matplotlib text: escaped, each run of names as
    :func:`mpl_point` sets it ("rocker $O_4B$", "$A$ (folded)"; the group code RRR stays a
    word)."""
    from .fmt import mpl_text

    return _mpl_names_outside_math(mpl_text(text))


def mpl_label(text: str) -> str:
    """A figure's own label that may hold mathtext ("arc about D of radius $l_4$", a
    catalogue text): each run of point names outside its formulas as :func:`mpl_point` sets
    it, the formulas as written."""
    parts = re.split(r"((?<!\\)\$[^$]*(?<!\\)\$)", str(text))
    return "".join(p if k % 2 else _mpl_names_outside_math(p) for k, p in enumerate(parts))


def sheet_names(text: str) -> str:
    """A text holding point names for a sheet, set as the report sets them (:func:`md_names`):
    each run of names italic, its digits subscripts ("crank O1A", "rod BF"; the group code
    RRR stays a word)."""
    return _ANY_NAME_WORD.sub(lambda m: m[1] if _GROUP_CODE.fullmatch(m[1]) else sheet_point(m[1]),
                              str(text))


def tex_names(text: str) -> str:
    """A TeX fragment holding point names at the baseline ("\\perp O2A", "S4 \\to O3"): each
    run of names with a digit lowered ("\\perp O_2A")."""
    return _NAME_WORD.sub(lambda m: point_tex(m[1]), str(text))


# Quantity symbols written as text in a figure ("crank angle φ (°)", "energy change ΔE (J)",
# "H − t = 55.0 mm", "F/M (kN/(kN·m))"): set as mathtext, italic as the report's formulas and
# its text set them (ISO 80000-1; the report's unit filter, render/unitjoin.py, italicises a
# symbol before a relation and a lone lowercase or Greek letter between words).
_GREEK_TEX = dict(zip(
    "αβγδεζηθικλμνξπρστυφχψωΓΔΘΛΞΠΣΦΨΩ",
    r"\alpha \beta \gamma \delta \varepsilon \zeta \eta \theta \iota \kappa \lambda \mu \nu \xi "
    r"\pi \rho \sigma \tau \upsilon \varphi \chi \psi \omega \Gamma \Delta \Theta \Lambda \Xi "
    r"\Pi \Sigma \Phi \Psi \Omega".split()))
_GR = "".join(_GREEK_TEX)
_WORD_CH = rf"A-Za-z0-9{_GR}_²³¹⁰⁴-⁹₀-₉′'\\$"
# a symbol: a Greek letter (with Δ, or with one lowercase letter or digit as its subscript:
# "ρa" is ρ_a; after an upright differential d: "dβ/dα"; before a hyphen: "θ-circle"), or Δ
# and a Latin letter, or one Latin letter (not before a hyphen: "V-belt"), each with its
# primes ("α′"); never inside a longer word or after "." or "·" (a unit "kN·m")
_SYMBOL = re.compile(
    rf"(?<![{_WORD_CH}.·\-])(?P<d>d(?=[{_GR}]))?"
    rf"(?:(?P<sym>Δ?[{_GR}](?P<sub>[a-z0-9])?|Δ[A-Za-z])(?P<p1>′*)(?![{_WORD_CH}])"
    rf"|(?P<latin>[A-Za-z])(?P<p2>′*)(?![{_WORD_CH}\-]))")
# a derivative "ds/dδ", "d²φ/dt²": d upright, the quantities italic
_DERIVATIVE = re.compile(
    rf"(?<![{_WORD_CH}.·\-])d(?P<n>[²³]?)(?P<f>[A-Za-z{_GR}])/d(?P<x>[A-Za-z{_GR}])(?P<m>[²³]?)"
    rf"(?![{_WORD_CH}])")
_POWER = {"": "", "²": "^{2}", "³": "^{3}"}
_RELATION = r"(?:=|≈|<|>|≤|≥|−|\+)"
# a parenthesised group without a relation (a unit: "(mm)", "(m/s²)", "(kN/(kN·m))") is left
_UNIT_GROUP = re.compile(r"\((?:[^()]|\([^()]*\))*\)")


def _symbol_tex(sym: str, sub: str | None) -> str:
    base = sym[:-1] if sub else sym
    tex = "".join(_GREEK_TEX.get(c, c) + (" " if c in _GREEK_TEX and len(base) > 1 else "")
                  for c in base).strip()
    return "$" + tex + (f"_{{{sub}}}" if sub else "") + "$"


def _latin_is_symbol(text: str, start: int, end: int) -> bool:
    """The rules for one Latin letter at text[start:end] (Greek letters always are symbols)."""
    before, after = text[:start], text[end:]
    if re.search(r"[0-9][ \u00a0]*$", before):       # a unit after a number: "5 s"
        return False
    if re.match(rf"\s*{_RELATION}", after) or re.search(rf"{_RELATION}\s*$", before):
        return True                                  # "K = 1.4", "H − t"
    if re.match(r"/(?:Δ?[A-Za-z])(?![A-Za-z0-9])", after) or re.search(r"(?<![A-Za-z])Δ?[A-Za-z]/$", before):
        return True                                  # "F/M" (two single letters)
    if re.fullmatch(r"\s+\((?:[^()]|\([^()]*\))*\)\s*", after):
        return True                                  # an axis label: "displacement s (mm)"
    # the report's rule: a lone lowercase letter between spaces, not the article "a"
    return text[start:end] != "a" and text[start:end].islower() and before.endswith(" ") \
        and after.startswith(" ")


def _derivative_tex(m) -> str:
    def q(c):
        return _GREEK_TEX.get(c, c)
    return (rf"$\mathrm{{d}}{_POWER[m['n']]}{q(m['f'])}/\mathrm{{d}}{q(m['x'])}{_POWER[m['m']]}$")


def _symbols_in_plain(text: str) -> str:
    if _DERIVATIVE.search(text):
        parts = _DERIVATIVE.split(text)
        # split with 4 groups: text, n, f, x, m, text, …
        out = []
        for i in range(0, len(parts), 5):
            out.append(_symbols_in_plain(parts[i]))
            if i + 4 < len(parts):
                n, f_, x, m_ = parts[i + 1:i + 5]
                out.append(_derivative_tex({"n": n, "f": f_, "x": x, "m": m_}))
        return "".join(out)
    lone = re.fullmatch(rf"(Δ?[a-z{_GR}])(′*)", text)
    if lone:                                         # a dimension's lone symbol ("e")
        return _symbol_tex(lone[1], None)[:-1] + lone[2] + "$"
    out, last = [], 0
    keep = [m.span() for m in _UNIT_GROUP.finditer(text) if not re.search(_RELATION, m[0])]
    for m in _SYMBOL.finditer(text):
        if any(a <= m.start() < b for a, b in keep):
            continue
        if m["latin"] and not _latin_is_symbol(text, m.start(), m.end()):
            continue
        out.append(text[last:m.start()] + (m["d"] or ""))
        tex = _symbol_tex(m["sym"] or m["latin"], m["sub"])
        primes = m["p1"] or m["p2"] or ""
        out.append(tex[:-1] + primes + "$")
        last = m.end()
    out.append(text[last:])
    return "".join(out)


def md_symbols(text) -> str:
    """:func:`mpl_symbols`'s rule for a cell of the report's Markdown tables (a check's or a
    result's label: "stroke H" → "stroke $H$", "[γ]" → "[$\\gamma$]"): pandoc reads the same
    TeX as mathtext."""
    return mpl_symbols(str(text))


def mpl_symbols(text: str) -> str:
    """A figure's text with the quantity symbols written in it as text set as mathtext (math
    italic): "crank angle φ (°)" → "crank angle $\\varphi$ (°)", "H − t = 55.0 mm" →
    "$H$ − $t$ = 55.0 mm", "F/M (kN/(kN·m))" → "$F$/$M$ (kN/(kN·m))", "ΔE" → "$\\Delta E$",
    "ρa" → "$\\rho_{a}$", "dβ/dα" → "d$\\beta$/d$\\alpha$". Formulas ($…$) are left as written, and so are units: a
    parenthesised group without a relation, a letter after a number ("5 s"), inside a word
    or after "·"."""
    parts = re.split(r"((?<!\\)\$[^$]*(?<!\\)\$)", str(text))
    return "".join(p if k % 2 else _symbols_in_plain(p) for k, p in enumerate(parts))
