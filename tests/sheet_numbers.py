"""The number rule of render/fmt.py as a scan of printed text (used by test_sheet_numbers.py).

:func:`rule_breaks` lists every number in a line of text that the rule forbids, whatever
the quantity (E-notation, a hyphen-minus before a digit, a negative zero, five or more
significant digits with three or more decimals, an integer part of five or more digits
not grouped by threes, a round-off below 10⁻⁹ written out: it is 0), and, where the unit
printed after the number names the quantity, what the rule says of it: lengths in mm and
angles in degrees to 0.01 (a length below 0.1 mm with two significant digits), forces,
torques, powers, energies, speeds, accelerations and moments of inertia with at most 4
significant digits (all integer digits, no decimals, from five integer digits on).
"""
from __future__ import annotations

import re

# a space that groups digits: the rule's narrow no-break space, or the no-break space the
# sheets print it as (the sheet font has no U+202F)
_GROUP = "[\u202f\u00a0]"
NUMBER = re.compile(rf"(?<![\w.\u2032'])(?P<sign>[-\u2212]?)(?P<num>\d{{1,4}}(?:{_GROUP}\d{{3}})+(?:\.\d+)?"
                    rf"|\d+(?:\.\d+)?)(?![\w.]*\d)")
RADIUS = re.compile(r"(?<![A-Za-z0-9_])R(\d+(?:\.\d+)?)(?![\w.])")
E_NOTATION = re.compile(r"\d(?:\.\d+)?[eE][-+]?\d")
HYPHEN_MINUS = re.compile(r"(?<![\w.)\]}'\u2032])-(?=\.?\d)")
# units after a number (a space or none between): what quantity it is
_LENGTH = re.compile(r"\s?mm(?![/\w²³])")
_ANGLE = re.compile(r"\s?°")
_SIG4 = re.compile(r"\s?(?:N·m|N|kN|J|kJ|W|kW|m/s²|m/s|rad/s²|rad/s|kg·m²|s)(?![\w/·²])")


def _digits(num: str) -> tuple[str, str]:
    head, _, tail = re.sub(_GROUP, "", num).partition(".")
    return head, tail


def significant(num: str) -> int:
    head, tail = _digits(num)
    digits = (head + tail).lstrip("0")
    return len(digits) if digits else 1


def rule_breaks(text: str) -> list[str]:
    """What in ``text`` breaks the number rule, one entry per finding."""
    out = [f"E-notation: {m.group(0)}" for m in E_NOTATION.finditer(text)]
    out += [f"hyphen-minus: {text[max(m.start() - 8, 0):m.end() + 8]!r}" for m in HYPHEN_MINUS.finditer(text)]
    for m in NUMBER.finditer(text):
        num, rest = m["num"], text[m.end():]
        head, tail = _digits(num)
        value = float(head + "." + (tail or "0"))
        where = f"{m.group(0)!r} in {text[:80]!r}"
        if m["sign"] and value == 0:
            out.append(f"negative zero: {where}")
        if significant(num) >= 5 and len(tail) >= 3:
            out.append(f"five significant digits and three decimals: {where}")
        if re.fullmatch(r"0\.000000000\d*", num) and value:
            out.append(f"a round-off below 10⁻⁹ written out (it is 0): {where}")
        if len(head) >= 5 and not re.search(_GROUP, num):
            out.append(f"five integer digits not grouped: {where}")
        if _LENGTH.match(rest):
            out += _length_breaks(num, where)
        elif _ANGLE.match(rest):
            if len(tail) > 2:
                out.append(f"angle not to 0.01°: {where}")
        elif _SIG4.match(rest):
            if len(head.lstrip("0")) >= 5 and tail or len(head.lstrip("0")) < 5 and significant(num) > 4:
                out.append(f"more than 4 significant digits: {where}")
    for m in RADIUS.finditer(text):           # a radius dimension: R92.51
        out += _length_breaks(m[1], f"{m.group(0)!r} in {text[:80]!r}")
    return out


def _length_breaks(num: str, where: str) -> list[str]:
    head, tail = _digits(num)
    value = float(head + "." + (tail or "0"))
    if value >= 0.1 and len(tail) > 2 or 0 < value < 0.1 and significant(num) > 2:
        return [f"length not to 0.01 mm: {where}"]
    return []


def dxf_plain(text: str) -> str:
    """The characters an MTEXT shows: AutoCAD's stacked subscript ``\\S^ v;`` as ``v``,
    escaped braces as braces; ``%%%`` as %."""
    text = re.sub(r"\\S\^ ?([^;]*);", r"\1", text)
    text = re.sub(r"\\S([^;^]*)\^ ?;", r"\1", text)          # a superscript
    text = text.replace("\\{", "{").replace("\\}", "}").replace("%%%", "%")
    return re.sub(r"\\[A-Za-z][^;\\]*;", "", text)
