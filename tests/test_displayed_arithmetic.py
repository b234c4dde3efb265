"""A displayed chain's printed numbers give its printed result (issue 19, review 34).

A teacher re-evaluates a displayed equation from the numbers it prints. The graphical
method's moment equations printed rounded factors beside the unrounded sum (shaper
"157 × 1.0 + 12.0 × 33.5 + 1662 × 112.5" with 187590, where the printed factors give
187534: F_R54 = 1662.5); the drive's speed deviation printed the deviation of the unrounded
speeds ("(80.29 − 80.00)/80.00 = 0.37 %", the printed speeds give 0.36 %). The rule: the
printed factors reproduce the printed result to the result's last digit.

This scans every example report (both languages) for the shapes the report displays:

* a moment equation ``ΣM = F × h + (a × b + c × d …) ± M/μ = 0 ⇒ F = −(r ± M/μ)/h = x``:
  the products' sum gives ``r``, and ``−(r ± M/μ)/h`` gives ``x``; the crank's
  ``ΣM = M_b + (a × b) × μ ± M = 0 ⇒ M_b = x`` gives ``x``;
* a relative deviation ``\\frac{a - b}{b} = p\\%`` (and ``(a − b)/b = p %``).
"""
from __future__ import annotations

import math
import re

import pytest

from tests.test_report_prose import EXAMPLES, _markdown

_N = r"-?\d+(?:\.\d+)?"
_COUPLE = rf"(?: ([+-]) ({_N}) / ({_N}))?"
# F × h + (products) ± M/μ = 0 ⇒ F = −(r ± M/μ)/h = x
MOMENT = re.compile(
    rf"\\times ({_N}) \+ \(([^()]*)\){_COUPLE} = 0 \\;\\Rightarrow\\; [^=]+ = "
    rf"-\\frac\{{({_N}){_COUPLE}\}}\{{({_N})\}} = ({_N})")
# M_b + (products) × μ ± M = 0 ⇒ M_b = x
CRANK = re.compile(
    rf"= M_b \+ \(([^()]*)\) \\times ({_N})(?: ([+-]) ({_N}))? = 0 \\;\\Rightarrow\\; M_b = ({_N})")
PRODUCT = re.compile(rf"(^|[+-])\s*({_N}) \\times ({_N})")
_P = rf"{_N}(?:\^\{{?\d+\}}?)?"          # a factor, perhaps with a power: 0.990^{3}, 14.12^2
# a chain of factors: the drive's efficiency η = … η_w = a × b × c^{3} = r, J_F' = J_F i² = a × b²
CHAIN = re.compile(rf"(?:\\eta_w|i\^2) = ({_P}(?: \\times {_P})+) = ({_N})(?![\d.])")
# a quotient: P_b = M_b/l_OA = a/b, the lock beam's Δα = h/L = a/b; m = 4 J_F/D²
QUOTIENT = re.compile(rf"(?:\{{l_\{{[^{{}}]*\}}\}}|\{{h\}}\{{L\}}) = \\frac\{{({_N})\}}\{{({_N})\}} = ({_N})(?![\d.])")
MASS = re.compile(rf"= \\frac\{{({_N}) \\times ({_N})\}}\{{({_N})\^2\}} = ({_N})(?![\d.])")
# the belt's centre distance a = a0 + (L_d − L_d0)/2, the guide bar H/(2 sin(ψ/2))
BELT = re.compile(rf"= ({_N}) \+ \\frac\{{({_N}) - ({_N})\}}\{{2\}} = ({_N})(?![\d.])")
SINE = re.compile(rf"= \\frac\{{({_N})\}}\{{2\\sin ({_N})°\}} = ({_N})(?![\d.])")
# a row of the die cutter's table | gap | φ | M/F | F/M | Π | F_c·M/F | (gap > 0)
AMPLIFICATION = re.compile(rf"^\| (?!0 )[\d.]+ \| [\d.]+ \| ({_N}) \| [\d.\u202f]+ \| [\d.]+ \| "
                           rf"([\d.\u202f]+) \|$", re.M)
PERCENT = re.compile(rf"\\frac\{{({_N}) - ({_N})\}}\{{({_N})\}} = ({_N})\s*\\?%"
                     rf"|\(({_N}) [-−] ({_N})\)\s*/\s*({_N}) = ({_N})\s*\\?%")


def _value(text: str) -> float:
    return float(text.replace("\u202f", "").replace("−", "-"))


def _half_unit(text: str) -> float:
    """Half a unit of the last digit ``text`` prints (``187590`` → 0.5, ``-22.3`` → 0.05)."""
    _, _, decimals = text.partition(".")
    return 0.5 * 10.0 ** -len(decimals)


def _agrees(computed: float, printed: str) -> bool:
    return abs(computed - _value(printed)) <= _half_unit(printed) * (1 + 1e-9) + 1e-12 * abs(computed)


def _products(text: str) -> float:
    total, consumed = 0.0, 0
    for m in PRODUCT.finditer(text):
        sign = -1.0 if m.group(1) == "-" else 1.0
        total += sign * _value(m.group(2)) * _value(m.group(3))
        consumed += 1
    assert consumed == text.count("\\times"), text
    return total


def _couple(sign, value, scale) -> float:
    if not sign:
        return 0.0
    return (-1.0 if sign == "-" else 1.0) * _value(value) / _value(scale)


def chain_faults(md: str) -> list[str]:
    """Every displayed chain of ``md`` whose printed numbers do not give its printed result."""
    out = []
    for m in MOMENT.finditer(md):
        products, numerator = m.group(2), m.group(6)
        if not _agrees(_products(products), numerator):
            out.append(f"({products}) = {_products(products):.4f}, printed {numerator}")
        x = -(_value(numerator) + _couple(*m.group(7, 8, 9))) / _value(m.group(10))
        if not _agrees(x, m.group(11)):
            out.append(f"-({numerator} {m.group(7) or ''} …)/{m.group(10)} = {x:.4f}, printed {m.group(11)}")
        assert m.group(3, 4, 5) == m.group(7, 8, 9), m.group(0)     # the same couple twice
    for m in CRANK.finditer(md):
        x = -(_products(m.group(1)) * _value(m.group(2)) + _couple(m.group(3), m.group(4), "1"))
        if not _agrees(x, m.group(5)):
            out.append(f"M_b = -({m.group(1)}) × {m.group(2)} = {x:.4f}, printed {m.group(5)}")
    for m in CHAIN.finditer(md):
        x = 1.0
        for factor in m.group(1).split(" \\times "):
            base, _, power = factor.partition("^")
            x *= _value(base) ** (int(power.strip("{}")) if power else 1)
        if not _agrees(x, m.group(2)):
            out.append(f"{m.group(1)} = {x:.6g}, printed {m.group(2)}")
    checks = [(QUOTIENT, lambda a, b: _value(a) / _value(b), "{}/{}"),
              (MASS, lambda a, j, d: _value(a) * _value(j) / _value(d) ** 2, "{} × {}/{}²"),
              (BELT, lambda a0, ld, ld0: _value(a0) + (_value(ld) - _value(ld0)) / 2, "{} + ({} - {})/2"),
              (SINE, lambda h, half: _value(h) / (2 * math.sin(math.radians(_value(half)))),
               "{}/(2 sin {}°)")]
    for pattern, fn, shape in checks:
        for m in pattern.finditer(md):
            *args, printed = m.groups()
            x = fn(*args)
            if not _agrees(x, printed):
                out.append(f"{shape.format(*args)} = {x:.6g}, printed {printed}")
    # the die cutter's force-amplification table: F_c·M/F from the printed F_c and M/F
    force = re.search(rf"F_c = L\\,q = [^$]*= ({_N})\\ \\text\{{kN\}}", md)
    for m in AMPLIFICATION.finditer(md):
        if force:
            x = _value(force.group(1)) * _value(m.group(1))
            if not _agrees(x, m.group(2)):
                out.append(f"F_c·M/F = {force.group(1)} × {m.group(1)} = {x:.6g}, printed {m.group(2)}")
    for m in PERCENT.finditer(md):
        a, b, c, p = (g for g in m.groups() if g is not None)
        x = 100 * (_value(a) - _value(b)) / _value(c)
        if not _agrees(x, p):
            out.append(f"({a} - {b})/{c} = {x:.4f} %, printed {p} %")
    return out


def test_the_scan_finds_the_reviewed_faults():
    """The lines the review recomputed (old reports), and the same lines written right."""
    shaper = (r"$$ \Sigma M_{O3}(4) = F_{R34} \times 74.0 + (157 \times 1.0 + 12.0 \times 33.5 + "
              r"1662 \times 112.5) + 1.29 / 0.01 = 0 \;\Rightarrow\; F_{R34} = -\frac{187590 + "
              r"1.29 / 0.01}{74.0} = -2537\ \mathrm{N} $$")
    die = (r"$$ \Sigma M_{D}(5) = F_{R35}^{t} \times 70.0 + (245 \times 8.0 - 8.75 \times 35.0) - "
           r"0.459 / 0.005 = 0 \;\Rightarrow\; F_{R35}^{t} = -\frac{1656 - 0.459 / 0.005}{70.0} = "
           r"-22.3\ \mathrm{N} $$")
    percent = r"$$ \Delta n = \frac{80.29 - 80.00}{80.00} = 0.37\% $$"
    assert len(chain_faults(shaper)) == 1 and "187534" in chain_faults(shaper)[0]
    assert len(chain_faults(die)) == 1 and "1653.75" in chain_faults(die)[0]
    assert len(chain_faults(percent)) == 1
    assert chain_faults("(50.23 − 50.00)/50.00 = 0.47 %")
    assert not chain_faults(shaper.replace("157 ", "156.96 ").replace("1662 ", "1662.5 "))
    assert not chain_faults(die.replace("245 ", "245.25 "))
    assert not chain_faults(percent.replace("0.37", "0.36"))
    # a wrong quotient is found too, and the crank's M_b line
    assert chain_faults(shaper.replace("156.96", "157").replace("1662 ", "1662.5 ")
                        .replace("-2537", "-2540"))
    assert chain_faults(r"= M_b + (1225 \times 10.5) \times 0.005 = 0 \;\Rightarrow\; M_b = -64.1")
    assert not chain_faults(r"= M_b + (1225 \times 10.5) \times 0.005 = 0 \;\Rightarrow\; M_b = -64.3")


def test_the_scan_finds_the_chains_of_review35():
    """Products, quotients and P_b lines the review recomputed (old reports), and written right:
    the printed factors give the printed result."""
    old = [r"$$ P_b = \frac{M_b}{l_{O2A}} = \frac{-227}{0.0925} = -2457\ \mathrm{N} $$",
           r"\eta_w = 0.990 \times 0.798 \times 0.950 \times 0.990^{3} \times 0.960 = 0.6988 $$",
           r"J_F' = J_F\,i^2 = 6.404 \times 14.12^2 = 1276.5\ \text{kg·m}^2",
           r"a = a_0 + \frac{L_d - L_{d0}}{2} = 470 + \frac{1600 - 1697}{2} = 421.4\ \text{mm}",
           r"m = \frac{4 J_F}{D^2} = \frac{4 \times 204.1}{1.000^2} = 816.52\ \text{kg}",
           r"\Delta\alpha = \frac{h}{L} = \frac{14.90}{35} = 0.4258\ \text{rad}",
           r"L_{O_3B} = \frac{H}{2\sin(\psi/2)} = \frac{320}{2\sin 8.18°} = 1124.27\ \text{mm}",
           "F_c = L\\,q = 20.00\\ \\text{m} = 1000.0\\ \\text{kN} $$\n\n"
           "| 0.01 | 184.80 | 0.19 | 5168 | 294.79 | 193.5 |"]
    new = [r"$$ P_b = \frac{M_b}{l_{O2A}} = \frac{-227.3}{0.0925} = -2457\ \mathrm{N} $$",
           r"\eta_w = 0.990 \times 0.7977 \times 0.950 \times 0.990^{3} \times 0.960 = 0.6988 $$",
           r"J_F' = J_F\,i^2 = 6.404 \times 14.1181^2 = 1276.5\ \text{kg·m}^2",
           r"a = a_0 + \frac{L_d - L_{d0}}{2} = 470 + \frac{1600 - 1697.2}{2} = 421.4\ \text{mm}",
           r"m = \frac{4 J_F}{D^2} = \frac{4 \times 204.13}{1.000^2} = 816.52\ \text{kg}",
           r"\Delta\alpha = \frac{h}{L} = \frac{14.903}{35} = 0.4258\ \text{rad}",
           r"L_{O_3B} = \frac{H}{2\sin(\psi/2)} = \frac{320}{2\sin 8.1818°} = 1124.27\ \text{mm}",
           "F_c = L\\,q = 20.00\\ \\text{m} = 1000.0\\ \\text{kN} $$\n\n"
           "| 0.01 | 184.80 | 0.1935 | 5168 | 294.79 | 193.5 |"]
    for line in old:
        assert len(chain_faults(line)) == 1, line
    for line in new:
        assert not chain_faults(line), (line, chain_faults(line))


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_displayed_chains_give_their_printed_results(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    faults = chain_faults(md)
    assert not faults, "\n".join(faults)


# the known-loads line of a group's section: "$F_{R54}$ (link 4) = 1662.5 N" / "（构件 4）= …"
LOAD = re.compile(r"\$([^$]+)\$ ?(?:\(link \d+\)|（构件 \d+）) ?= (-?[\d.\u202f ]+?) N")


def load_faults(md: str) -> list[str]:
    """A known load printed in its group's known-loads line with other digits than the
    same force as a factor of the group's moment equations (review 34: "F_R54 = 1662 N"
    above "1662.5 × 112.5"): one value of one quantity in one section. A factor is the
    load's when the two agree to the coarser one's last digit and no other load of the line
    is nearer (two forces of nearly one magnitude: F_I2 = 127.83, F_I3 = 127.8)."""
    out = []
    for section in re.split(r"\n#### ", md):
        line = next((x for x in section.splitlines() if LOAD.search(x)), None)
        if line is None:
            continue
        loads = [(name, v.replace("\u202f", "").replace(" ", "")) for name, v in LOAD.findall(line)]
        for m in PRODUCT.finditer(section):
            x = m.group(2)
            name, printed = min(loads, key=lambda ld: abs(_value(ld[1]) - _value(x)))
            half = max(_half_unit(x), _half_unit(printed))
            if x != printed and abs(_value(x) - _value(printed)) <= half * (1 + 1e-9):
                out.append(f"{name} = {printed} N in the known loads, {x} in an equation")
    return out


def test_the_scan_finds_a_load_printed_with_other_digits():
    loads = r"Known loads: $G_{4}$ (link 4) = 157 N, $F_{R54}$ (link 4) = 1662 N. Moment equations:"
    eq = r"$$ \Sigma M_{O3}(4) = F_{R34} \times 74.0 + (157 \times 1.0 + 1662.5 \times 112.5) = 0 $$"
    zh = r"已知力：$G_{4}$（构件 4）= 157 N，$F_{R54}$（构件 4）= 1662 N。力矩方程："
    assert load_faults(f"#### Group 3–4\n\n{loads}\n\n{eq}\n") == [
        "F_{R54} = 1662 N in the known loads, 1662.5 in an equation"]
    assert len(load_faults(f"#### 杆组 3–4\n\n{zh}\n\n{eq}\n")) == 1
    assert not load_faults(f"#### Group 3–4\n\n{loads.replace('1662 N', '1662.5 N')}\n\n{eq}\n")


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_known_loads_print_the_digits_of_their_equations(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    faults = load_faults(md)
    assert not faults, "\n".join(faults)
