"""Formatting shared by every report context (the templates get strings only).

Numbers, as an engineer writes them (one rule for every report, table and sheet):

* lengths in mm and angles in degrees: two decimals (0.01 mm, 0.01°) — :func:`f` with its
  default ``digits=2`` — in running text and in the synthesis formulas alike (``a = 57.04 mm``,
  never ``57.041 mm``), a length below 0.1 mm (a deflection limit, a cam's stand-off) with two
  significant digits (``0.025 mm``), a value quoted from a source as the source writes it
  (the lock-beam seed's lift ``h = 14.904 mm``); speeds in rpm to 0.01 rpm — :func:`rpm` (``n_w = 50.00 rpm``, never
  ``50.000``); teeth and other design data as the design gives them;
* the time-ratio coefficient K to 0.001 — :func:`time_ratio` (``K = 1.250``; the textbook
  writes K = 1.4, K = 1.25);
* forces, torques, powers, energies, stresses, moments of inertia, lives, cycle counts, angular
  velocities and accelerations (``ω = 5.236 rad/s``, ``12.29 m/s²``, ``73.26 rad/s²``), angles
  in radians, gear ratios of a formula (``i = 28.80``) and other quantities whose size varies
  over decades: 4 significant digits — :func:`sig` (``636.6 N·m``, ``0.6599 kW``,
  ``48 000 h``); a value with five or more integer digits keeps all of them, rounded to a
  unit (``12 738 N·m``, never ``12 740 N·m``); where a table keeps fixed decimals for such a
  quantity (forces to 0.1 N), :func:`f` with ``group=True``; in running text and formulas such
  a value never has more digits than both allow — ``12 738 N·m`` or ``12 738.2 N·m``,
  ``636.6 N·m``, ``3333 W``, ``3.803 kW``, ``190.3 J``, never ``12 738.160 N·m``,
  ``636.620 N·m`` or ``3333.33 W``;
* percentages to 0.1 %, below 1 % two significant digits — :func:`percent` (``2.6 %``,
  ``0.54 %``);
* outside the tables no number has five or more significant digits and three or more
  decimals (``5.2360``, ``50.000``, ``1.2000``, ``12.290``): no quantity of this rule has both;
* derived values of given dimensions (the given-dimensions path: H, K, θ, ψ from the brief's
  lengths) as any other length, angle or K (``θ = |111.37° − 91.40°| = 19.97°``,
  ``K = 1.250``), a sine or cosine of a formula to 4 significant digits; the verification
  tables keep the decimals of their columns;
* a displayed chain (``a × b + c × d = r``, ``(a − b)/b = p %``) gives its printed result
  from its printed numbers, to the result's last digit: a factor is written with the digits
  that make it so (a weight of 156.96 N, a reaction read as 1662.5 N: render/graphical_report
  ``_moment_tex``), or the result is computed from the factors as printed (the drive's speed
  deviation from the speeds to 0.01 rpm); :func:`factors_for` (mechdesign/numbers.py) finds
  the fewest more digits; tests/test_displayed_arithmetic.py re-evaluates the reviewed shapes,
  tests/test_every_chain.py every formula of numbers of every example report;
* numbers in finding and error messages (``{x:.2f}`` in the msgid) by the same rule; three
  decimals only where a value is compared with a limit it may miss by less than 0.01;
* other dimensionless ratios (efficiencies, safety factors, velocity ratios): 4 significant
  digits, or the fixed decimals a table states;
* a magnitude of a million or more (seven digits: a bearing life of 40 680 894 h) with a power
  of ten, 4 significant digits — :func:`sci` (``4.068 × 10⁷ h``; in a formula
  ``4.068\\times10^{7}``) — unless a larger unit (kN for a press load of 1 000 000 N, the
  forces' table and plot then in kN) keeps it below a million;
* residuals, relative errors and other tiny magnitudes in the verification tables: two
  significant digits times a power of ten — :func:`e` (``2.2 × 10⁻¹⁶``), an exact zero ``0``;
* never E-notation (``4.8e+04``), never a negative zero (``-0.00`` → ``0.00``); in text
  and tables an integer part of five or more digits is grouped by threes with a narrow
  no-break space (``1 000 000``), as GB 3101 / ISO 80000-1 write it; inside a formula the
  digits stay together (``99480``).

On the drawing sheets the same functions write every number (:mod:`.sheet` and the sheet
modules call them, nothing else), with the true minus sign ``−`` (:func:`minus`: the sheets
print their text as written, the report gets its minus from typst and Word) and, where
the rule groups digits, a no-break space (the sheet font has no narrow one); a value the
design chose (a scale, a chart's graduation, a programme angle) as :func:`exact` writes it.

Verdicts: :func:`verdict` — 合格/不合格 in Chinese, PASS/FAIL in English, everywhere.

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

from ..i18n import tr
from ..numbers import GROUP, fixed as f, grouped_digits as _group, mantissa_exponent, sig  # noqa: F401  (the rule's digits: mechdesign/numbers.py)
from ..numbers import column_decimals, factor_text, factors_for, gives  # noqa: F401  (a displayed chain's digits)


def grouped(text: str) -> str:
    """A number already written (``"72441"``, ``"-12698.4"``) with the rule's grouping for
    text and table cells: an integer part of five or more digits grouped by threes with a
    narrow no-break space, four digits or fewer left together; anything that is not a plain
    number (a designation such as ``6204`` is never passed here) is returned unchanged."""
    return _group(text) if re.fullmatch(r"-?\d+(\.\d+)?", text) else text


def time_ratio(K: float) -> str:
    """The time-ratio coefficient K (行程速比系数) to 0.001, as the textbook writes it
    (K = 1.4, K = 1.25): ``1.2496`` → ``1.250``."""
    return f(K, 3)


def rpm(n: float) -> str:
    """A rotational speed in rpm to 0.01 rpm (``50.00``, ``705.90``), never ``50.000``."""
    return f(n, 2)


def length(x: float) -> str:
    """A length in mm by the rule above: 0.01 mm, below 0.1 mm two significant digits
    without a trailing zero (``0.11``, ``0.028``, ``0.001``)."""
    if abs(x) >= 0.1:
        return f(x, 2)
    return f"{x:.2g}" if abs(x) >= 1e-4 else e(x)


def percent(x: float) -> str:
    """A percentage (``x`` in per cent, without the sign) to 0.1 %, below 1 % with two
    significant digits: ``2.634`` → ``2.6``, ``0.5419`` → ``0.54``, ``87.46`` → ``87.5``."""
    return sig(x, 2) if abs(x) < 1 else f(x, 1)


def fluctuation(delta: float) -> str:
    """The allowed speed fluctuation [δ] as the course writes it: ``1/N`` where 1/δ is a whole
    number (0.025 → ``1/40``), else the decimal as given (0.15 → ``0.15``, never
    ``1/6.667``)."""
    inv = 1.0 / delta
    if abs(inv - round(inv)) < 1e-9 * inv:
        return f"1/{round(inv)}"
    return f"{delta:.4g}"


_SUPERSCRIPT = str.maketrans("-0123456789", "\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079")


def e(x: float) -> str:
    """A residual or other tiny magnitude for the verification tables: two significant
    digits times a power of ten, ``2.2 × 10⁻¹⁶``; an exact zero is ``0``; a magnitude
    between 0.001 and 10 000 is written plainly (:func:`sig`, 2 digits)."""
    if x != x:
        return "—"
    if x == 0:
        return "0"
    if 1e-3 <= abs(x) < 1e4:
        return sig(x, 2)
    mant, _, exp = f"{x:.1e}".partition("e")
    return f"{mant} × 10{str(int(exp)).translate(_SUPERSCRIPT)}"


#: Rounding noise of a double computation: a residue within this many units in the last
#: place of the compared magnitude is no difference a teacher can see.
ROUNDING_ULPS = 64


def residue(x: float, scale: float = 1.0) -> str:
    """A difference that should be 0 (a simulated value minus its closed form, a loop's
    closure) for a verification table: ``0`` when it is rounding noise, within
    :data:`ROUNDING_ULPS` units in the last place of ``max(1, |scale|)`` (1.7 × 10⁻¹⁶ of an
    angle of 0.26 rad), else as :func:`e`. Only the text: the check compares the real value."""
    if x == x and abs(x) <= ROUNDING_ULPS * 2.0 ** -52 * max(1.0, abs(scale)):
        return "0"
    return e(x)


def sci_tex(x: float, n: int = 4) -> str:
    """``x`` in a formula with ``n`` significant digits times a power of ten
    (``2.043\\times10^{9}``; a stress-cycle count, a moment of a million N·mm)."""
    mant, exp = mantissa_exponent(x, n)
    return f"{mant}\\times10^{{{exp}}}"


def sci(x: float, n: int = 4) -> str:
    """A magnitude of a million or more (a bearing life of 40 680 894 h) with ``n``
    significant digits times a power of ten, ``4.068 × 10⁷``, never seven digits or more;
    smaller magnitudes as :func:`sig`."""
    if x != x or abs(x) == float("inf"):
        return "—"
    if abs(x) < 1e6:
        return sig(x, n)
    mant, exp = mantissa_exponent(x, n)
    return f"{mant} × 10{str(exp).translate(_SUPERSCRIPT)}"


MINUS = "\u2212"     # the minus sign (GB 3102.11, ISO 80000-2), not the hyphen-minus "-"
_HYPHEN_MINUS = re.compile(r"(?<![\w.])-(?=\.?\d)")


def minus(text: str) -> str:
    """A text holding numbers written by this module with the true minus sign (U+2212) for
    the hyphen-minus before a digit (``-4.086`` → ``−4.086``), for a medium that prints the
    characters as written: the drawing sheets (typst strings, DXF text; the sheet font,
    Noto Sans SC, has the glyph). A hyphen after a letter or digit (``Y90S-6``,
    ``2026-11-26``) stays. The report's Markdown keeps "-": typst and Word set its minus."""
    return _HYPHEN_MINUS.sub(MINUS, text)


def exact(x: float, digits: int | None = 6, decimals: int | None = None,
          group: bool = True) -> str:
    """A value the design chose rather than computed, written as it is (the rule's "design
    data as the design gives them"): a drawing's scale (``μL = 0.005 m/mm``, ``1:2.5``), a
    chart's graduation (``-30``, ``0.25``), a cam programme's angle (``120``), a module:
    at most ``digits`` significant digits, no trailing zeros, never E-notation (``1e-05`` →
    ``0.00001``), a negative zero or a rounding residue below 10⁻⁹ as ``0``; ``decimals``:
    at most that many (a programme angle to 0.01°, as :func:`f` would write it);
    ``digits=None``: no limit but ``decimals`` (a brief's given number to 10⁻⁶: ``1234.5678``,
    ``0.004``); an integer part of five or more digits grouped (``15 000``) unless
    ``group=False``."""
    if x != x or abs(x) == float("inf"):
        return "—"
    if decimals is not None:
        x = round(x, decimals)
    if abs(x) < 1e-9:
        return "0"
    text = sig(x, digits, group=False) if digits is not None else f(x, decimals)
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    if float(text) == 0:
        return "0"
    return _group(text) if group else text


def force_unit(peak: float) -> tuple[float, str]:
    """The unit of a table or plot of forces whose largest magnitude is ``peak`` [N]: kN
    (divisor 1000) from a million newtons on (a press load of 1 000 000 N is 1000 kN, no
    seven-digit numbers and no "1e6" axis offset), else N."""
    return (1e3, "kN") if abs(peak) >= 1e6 else (1.0, "N")


def number(text: str) -> float:
    """The value of a number written by :func:`f`, :func:`sig` or :func:`e` (for rows
    that are judged after formatting)."""
    text = text.replace(GROUP, "").replace("\u2212", "-").strip()
    mant, times, power = text.partition(" × 10")
    if not times:
        return float(mant)
    digits = power.translate(str.maketrans("\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079",
                                           "-0123456789"))
    return float(mant) * 10.0 ** int(digits)


_CJK = re.compile(r"[\u3000-\u303f\u3400-\u9fff\uff00-\uffef]")


def in_lang(text, lang: str):
    """The part of a '中文 / English' label for ``lang`` ('导杆 / guide bar' → '导杆' or
    'guide bar'); a stage title (``stages.titles.Title``: an English msgid with its context)
    translated through the catalogue; other text as it is. Lists (table rows) are mapped
    cell by cell."""
    if isinstance(text, (list, tuple)):
        return [in_lang(t, lang) for t in text]
    if isinstance(text, str) and hasattr(text, "context"):      # a stage title
        from ..i18n import gettext

        return gettext(str(text), lang, text.context)
    if not isinstance(text, str) or " / " not in text:
        return text
    zh, en = text.split(" / ", 1)
    if not _CJK.search(zh) or _CJK.search(en):
        return text
    return zh if lang == "zh" else en


class Verdict(str):
    """A verdict cell: the word of :func:`verdict` that also carries the boolean it was made
    from (``passed``), so that a reader of the tables (the summary) takes the boolean, never
    the word. Escaping with :meth:`replace` keeps it a Verdict."""

    passed: bool

    def __new__(cls, text: str, passed: bool) -> "Verdict":
        obj = super().__new__(cls, text)
        obj.passed = bool(passed)
        return obj

    def replace(self, *args, **kwargs) -> "Verdict":        # type: ignore[override]
        return Verdict(str.replace(self, *args, **kwargs), self.passed)


def verdict(ok: bool, lang: str) -> Verdict:
    """The one verdict vocabulary: 合格/不合格 (zh), PASS/FAIL (en), as a :class:`Verdict`
    carrying ``ok``."""
    _ = tr(lang)
    return Verdict(_("PASS") if ok else _("FAIL"), ok)


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


def meta_text(meta, name: str, lang: str) -> str:
    """``meta.title`` or ``meta.subtitle`` for a report in ``lang``: the ``…_en`` variant
    in English where the brief gives one, else the text as written."""
    english = getattr(meta, f"{name}_en", "") if lang == "en" else ""
    return english or getattr(meta, name, "")


def md_meta(meta, lang: str | None = None) -> dict[str, str]:
    """The brief's ``report`` section (:class:`~mechdesign.brief.common.ReportMeta`) for a
    template (``meta.title``, …) in ``lang`` (default: the brief's language): every text
    field escaped by :func:`md_text`; the title and subtitle in English where the brief
    gives ``title_en`` / ``subtitle_en`` and the report is in English."""
    lang = lang or str(getattr(meta, "language", "zh"))
    fields = ("student", "student_id", "class_name", "teacher", "date")
    out = {name: md_text(getattr(meta, name, "")) for name in fields}
    out["title"] = md_text(meta_text(meta, "title", lang))
    out["subtitle"] = md_text(meta_text(meta, "subtitle", lang))
    out["language"] = str(getattr(meta, "language", ""))
    return out


def sentences(_, *texts: str) -> str:
    """Sentences of one paragraph: a space between them in English, none in Chinese."""
    return ("" if _.zh else " ").join(t for t in texts if t)


def factor_for(x: float, ok, sig_digits: int = 4, write=None, decimals: bool = False,
               most: int = 3) -> str:
    """``x`` as a factor of a displayed chain: :func:`sig`'s ``sig_digits`` significant
    digits (or ``write(x, digits)``'s, a formula's number writer), one more at a time (up to
    ``most``) until ``ok(printed factor)`` holds — the printed factors give the printed result
    (6.404 × 14.118² = 1276.5, where 14.12 gives 1276.8); where none does, the last tried.
    ``decimals``: the digits are decimals (ψ/2 to 0.01° or finer), not significant digits
    (:func:`mechdesign.numbers.factor_text`). A number the writer prints with a power of ten
    or in parentheses is taken as it is."""
    for extra in range(most + 1):
        text = write(x, sig_digits + extra) if write else factor_text(x, sig_digits + extra, decimals)
        if "times" in text or "(" in text or ok(float(text)):
            return text
    return text


def product(xs, printed: str, sig_digits: int = 4) -> str:
    """The factors ``xs`` of a displayed product "a \\times b = printed", written with
    :func:`factors_for`'s digits: the printed factors give the printed product."""
    import math

    return r" \times ".join(factors_for(xs, lambda *v: math.prod(v), printed, sig_digits))
