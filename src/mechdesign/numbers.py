"""The digits of the number rule (README "Conventions", :mod:`mechdesign.render.fmt`): one
home for the functions that turn a value into its digits, importable by the stages (which
write numbers into design steps and findings) and by render (which may not be imported by
the stages). Standard library only: no prose, no units, no I/O.

* :func:`fixed` — a fixed number of decimals, never a negative zero;
* :func:`sig` — ``n`` significant digits, never E-notation, all integer digits kept;
* :func:`grouped_digits` — an integer part of five or more digits grouped by threes with a
  narrow no-break space (for text and table cells, never inside a formula).
"""
from __future__ import annotations

from decimal import Decimal

GROUP = "\u202f"      # narrow no-break space between digit groups (GB 3101, ISO 80000-1)


def grouped_digits(text: str) -> str:
    """Digits of the integer part grouped by threes when it has five or more digits."""
    sign = "-" if text.startswith("-") else ""
    head, dot, tail = text[len(sign):].partition(".")
    if len(head) >= 5 and head.isdigit():
        head = f"{int(head):,}".replace(",", GROUP)
    return sign + head + dot + tail


def fixed(x: float, digits: int = 2, group: bool = False) -> str:
    """Fixed-point number with ``digits`` decimals; a rounded zero never shows as '-0.00'.
    ``group``: an integer part of five or more digits grouped by threes (``12 698.4``) —
    for text and table cells, not inside a formula (``$…$``), where digits stay together."""
    text = f"{x:.{digits}f}"
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
    rounded = Decimal(f"{x:.{n - 1}e}")
    decimals = max(n - 1 - rounded.adjusted(), 0)
    return fixed(float(rounded), decimals, group=group)
