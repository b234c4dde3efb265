"""The digits of the number rule (README "Conventions", :mod:`mechdesign.render.fmt`): one
home for the functions that turn a value into its digits, importable by the stages (which
write numbers into design steps and findings) and by render (which may not be imported by
the stages). Standard library only: no prose, no units, no I/O.

* :func:`fixed` — a fixed number of decimals, never a negative zero;
* :func:`sig` — ``n`` significant digits, never E-notation, all integer digits kept;
* :func:`grouped_digits` — an integer part of five or more digits grouped by threes with a
  narrow no-break space (for text and table cells, never inside a formula);
* :func:`gives`, :func:`factors_for` — a displayed chain's printed factors give its printed
  result to its last digit (:func:`factor_text`: a factor's significant digits or decimals).
"""
from __future__ import annotations

import math
from decimal import ROUND_HALF_UP, Decimal

GROUP = "\u202f"      # narrow no-break space between digit groups (GB 3101, ISO 80000-1)


def grouped_digits(text: str) -> str:
    """Digits of the integer part grouped by threes when it has five or more digits."""
    sign = "-" if text.startswith("-") else ""
    head, dot, tail = text[len(sign):].partition(".")
    if len(head) >= 5 and head.isdigit():
        head = f"{int(head):,}".replace(",", GROUP)
    return sign + head + dot + tail


def _decimal(x: float) -> Decimal:
    """``x`` as the shortest decimal that reads back as it (Python's repr): the number a
    reader sees and rounds, not the binary fraction stored (2.675 is 2.67499999… in binary)."""
    return Decimal(repr(float(x)))


def mantissa_exponent(x: float, n: int = 4) -> tuple[str, int]:
    """``x`` as ``n`` significant digits times a power of ten, a half rounded away from zero
    as :func:`fixed` does: (``"2.043"``, 9) for 2 042 500 000."""
    exact = _decimal(x)
    rounded = exact.quantize(Decimal(1).scaleb(exact.adjusted() - n + 1), rounding=ROUND_HALF_UP)
    exp = rounded.adjusted()
    return f"{rounded.scaleb(-exp):.{n - 1}f}", exp


def fixed(x: float, digits: int = 2, group: bool = False) -> str:
    """Fixed-point number with ``digits`` decimals; a rounded zero never shows as '-0.00'.
    A half is rounded away from zero, as a reader rounds it and as :func:`gives` checks a
    chain (G5 = 245.25 N → 245.3, not Python's half-to-even 245.2; 2.675 → 2.68).
    ``group``: an integer part of five or more digits grouped by threes (``12 698.4``) —
    for text and table cells, not inside a formula (``$…$``), where digits stay together."""
    if x != x or abs(x) == float("inf"):
        text = f"{x:.{digits}f}"
    else:
        text = f"{_decimal(x).quantize(Decimal(1).scaleb(-digits), rounding=ROUND_HALF_UP):f}"
    if text.startswith("-") and float(text) == 0.0:
        text = text[1:]
    return grouped_digits(text) if group else text


def sig(x: float, n: int = 4, group: bool = True, ref: float = 0.0) -> str:
    """``x`` with ``n`` significant digits in fixed-point notation, never E-notation:
    ``0.065999`` → ``0.06600``, ``9999.5`` → ``10 000``, ``48000`` → ``48 000``; a value
    with more than ``n`` integer digits keeps all of them, rounded to a unit (``12738.16`` →
    ``12 738``, never ``12 740``: an engineer does not write a torque's units digit as a
    zero); the significant trailing zeros are kept; zero is ``0``; NaN or infinite is ``—``.
    ``group=False`` inside a formula and on a terminal line (digits together). ``ref``: the
    largest magnitude of the values written with ``x`` (a range, a mean); an ``x`` within
    10⁻⁹ of it of zero is a rounding residue of zero and written ``0`` (not
    ``0.0000000000000007194``)."""
    if x != x or abs(x) == float("inf"):
        return "—"
    if x == 0 or abs(x) <= 1e-9 * abs(ref):
        return "0"
    if abs(x) >= 10 ** n:                   # more integer digits than n: all of them kept
        return fixed(x, 0, group=group)
    exact = _decimal(x)
    rounded = exact.quantize(Decimal(1).scaleb(exact.adjusted() - n + 1), rounding=ROUND_HALF_UP)
    decimals = max(n - 1 - rounded.adjusted(), 0)
    return fixed(float(rounded), decimals, group=group)


def gives(value: float, printed: str) -> bool:
    """``value`` (a chain evaluated from its printed factors) rounds to ``printed``: within
    half a unit of its last printed digit (the rule of every displayed chain); a value exactly
    half a unit off (the printed factors end in a 5 there: 2.50 × 57.0 = 142.5) only where
    ``printed`` is its rounding away from zero, as a reader rounds it (143, never 142:
    review 38)."""
    digits = len(printed.replace(" ", "").partition(".")[2])
    shown = float(printed.replace(" ", ""))
    half = 0.5 * 10.0 ** -digits
    off = abs(value - shown)
    if off > half * (1 + 1e-9):
        return False
    return not (abs(off - half) <= 1e-9 * half and abs(shown) < abs(value))


def significant(text: str) -> int:
    """The significant digits a number is printed with (``0.0400`` → 3, ``266.67`` → 5)."""
    digits = text.replace(GROUP, "").replace(" ", "").lstrip("-").replace(".", "")
    return max(len(digits.lstrip("0")), 1)


def factor_text(x: float, n: int, decimals: bool = False) -> str:
    """``x`` as a formula's factor (digits together): ``n`` significant digits (:func:`sig`),
    or with ``decimals`` ``n`` decimals (:func:`fixed`; a speed to 0.01 rpm, an angle to
    0.01°)."""
    return fixed(x, n) if decimals else sig(x, n, group=False)


def factors_for(xs, fn, printed: str, sig_digits=4, most=3, decimals=False) -> list[str]:
    """The factors ``xs`` of a displayed chain whose printed result is ``printed``: :func:`sig`'s
    ``sig_digits`` significant digits (one number, or one for each factor), the fewest more
    digits (up to ``most`` a factor, one number or one for each; fewest in all first, the
    last factor's first) with which ``fn(*printed factors)`` gives ``printed`` to its last
    digit (636.62 × 5.236 = 3333.3, where 636.6 gives 3333.2); where none does, each factor
    with all its ``most`` more digits. ``decimals`` (one flag, or one for each factor): the
    factor's digits are counted as decimals (:func:`factor_text`), not significant digits."""
    from itertools import product

    result = printed.replace(" ", "").replace("\u202f", "")
    n = len(xs)

    def each(v):
        return [v] * n if isinstance(v, (int, bool)) else list(v)

    base, top, dec = each(sig_digits), each(most), each(decimals)
    for total in range(sum(top) + 1):
        for extras in product(*(range(m + 1) for m in top)):
            if sum(extras) != total:
                continue
            texts = [factor_text(x, b + e, d) for x, b, e, d in zip(xs, base, extras, dec)]
            if gives(fn(*(float(t) for t in texts)), result):
                return texts
    return [factor_text(x, b + m, d) for x, b, m, d in zip(xs, base, top, dec)]


def column_decimals(peak: float, n: int = 4, least: int = 0, most: int | None = None,
                    empty: int = 0) -> int:
    """The one decimal count of a table column (or a set of values printed together) whose
    largest magnitude is ``peak``: ``n`` significant digits of that value (7762.013 → 0
    decimals for 4), kept within ``least``…``most``; ``empty`` where the column is all zero."""
    if not peak > 0 or peak != peak or peak == float("inf"):
        return empty
    d = n - 1 - int(math.floor(math.log10(peak)))
    d = max(least, d)
    return d if most is None else min(most, d)


def half_sum_decimals(xs, digits: int = 2, most: int = 3) -> int:
    """The decimals to print the numbers ``xs`` with so that half the sum or difference of
    any two of them as printed, (a ± b)/2, is no tie at ``digits`` decimals (its result's): at
    ``digits`` (0.01 mm), one more at a time (up to ``most`` more) where a half sum of the
    printed numbers ends exactly in half a unit there (58.72 − 26.07 = 32.65: 16.325, which
    a reader rounds to 16.33 where l₁ = 16.3206 prints 16.32; to 0.001 mm 58.716 − 26.075 =
    32.641 gives 16.3205)."""
    xs = list(xs)
    for d in range(digits, digits + most + 1):
        p = [round(float(fixed(x, d)) * 10 ** d) for x in xs]
        unit = 10 ** (d - digits)               # a unit of the result's last digit, in 10^-d
        if not any((a + s * b) % (2 * unit) == unit for i, a in enumerate(p) for b in p[i + 1:] for s in (1, -1)):
            return d
    return digits + most
