"""Report material for the strength checks of :mod:`mechdesign.core.strength`.

``check_formula(check)`` gives the textbook formula with the numbers substituted in course
units (N·mm, mm, MPa, kW, h, °C) as plain LaTeX that pandoc turns into Typst math (``\\frac``,
``\\sqrt``, ``\\times``, ``\\le``, ``\\text{}`` only). ``check_rows(checks, lang)`` gives the
summary-table rows ``[item_zh, item_en, value, allowable, unit, verdict]``.
"""
from __future__ import annotations

import math
from typing import Iterable

from ..core.strength import COURSE_SCALE, Check
from ..i18n import tr
from .fmt import f, sci
from .fmt import sig as rule_sig

#: Decimals of the value and allowable columns per course unit.
DIGITS = {"MPa": 1, "h": 0, "°C": 1, "mm": 2, "m/s": 2, "°": 1, "1": 2, "kW": 3, "μm": 2}

N_MM = 1e3      # N·m → N·mm
MM = 1e3        # m → mm
SQRT_MPA = 1e-3  # √Pa → √MPa


def num(x: float, sig: int = 4) -> str:
    """A number for a formula: ``sig`` significant digits, trailing zeros dropped, powers of
    ten as ``\\times10^{k}`` outside 10⁻³…10⁵; negative numbers in parentheses."""
    if x == 0 or not math.isfinite(x):
        return "0" if x == 0 else str(x)
    if x < 0:
        return f"({'-' + num(-x, sig)})"
    k = math.floor(math.log10(x))
    if k >= 5 or k < -3:
        mant = x / 10 ** k
        if round(mant, sig - 1) >= 10:
            mant, k = mant / 10, k + 1
        return f"{_trim(f(mant, sig - 1))}\\times10^{{{k}}}"
    return _trim(f(x, max(0, sig - 1 - k)))


def lone(x: float, sig: int = 4) -> str:
    """:func:`num` for a number that follows a relation (``x_{min} = -0.537``), not an
    operator: a negative number alone needs no parentheses."""
    return num(x, sig) if x >= 0 or not math.isfinite(x) else "-" + num(-x, sig)


def _trim(text: str) -> str:
    return text.rstrip("0").rstrip(".") if "." in text else text


def _counts(check: Check) -> bool:
    """A check of counts (belts, teeth): a pure number whose value and limit are whole."""
    return check.unit == "1" and all(float(x).is_integer()
                                     for x in (check.course_value, check.course_allowable))


#: From this magnitude on a value is written with a power of ten (render/fmt.py's rule: no
#: seven-digit numbers; a bearing life of 40 680 894 h is 4.068 × 10⁷ h).
BIG = 1e6


def _fixed(x: float, check: Check) -> str:
    return f(x, 0 if _counts(check) else DIGITS.get(check.unit, 2))


#: Significant digits of an estimate printed as one (a bearing life L_10h: its catalogue
#: rating C and the load factors are good to a few per cent; 4 digits, the rest rounded
#: off and the value written "≈": 199 597 h → ≈ 199 600 h; 6.157 × 10⁶ h from 10⁶ on).
ESTIMATE_DIGITS = 4


def _estimate(check: Check) -> bool:
    """A check whose value is an estimate printed to :data:`ESTIMATE_DIGITS` (a life)."""
    return check.unit == "h"


def _rounded(x: float) -> tuple[str, str]:
    """An estimate ``x`` below 10⁶ to :data:`ESTIMATE_DIGITS` significant digits in fixed
    notation, ungrouped (199600, 950.4), and the same as "a\\times10^{n}" (1.996\\times10^{5}):
    what its chain must give, to the mantissa's last digit."""
    if x == 0 or not math.isfinite(x):
        return num(x), num(x)
    power = int(math.floor(math.log10(abs(x))))
    mant = f"{x / 10.0 ** power:.{ESTIMATE_DIGITS - 1}f}"
    if abs(float(mant)) >= 10:          # 9.9996 → 10.000: one power up
        power += 1
        mant = f"{x / 10.0 ** power:.{ESTIMATE_DIGITS - 1}f}"
    decimals = max(0, ESTIMATE_DIGITS - 1 - power)
    return f"{float(mant) * 10.0 ** power:.{decimals}f}", f"{mant}\\times10^{{{power}}}"


def _value(check: Check) -> str:
    x = check.course_value
    if _estimate(check):            # 4 significant digits, trailing zeros kept (8.700 × 10⁶)
        return _rounded(x)[0 if abs(x) < BIG else 1]
    return num(x) if abs(x) >= BIG else _fixed(x, check)


def _allowable(check: Check) -> str:
    x = check.course_allowable
    return num(x) if abs(x) >= BIG else _fixed(x, check)


def _cell(x: float, check: Check) -> str:
    """A value or allowable for the check table: as in the formula, a power of ten as
    ``4.068 × 10⁷`` (render/fmt.py's :func:`~mechdesign.render.fmt.sci`); an estimate's
    value (not its allowable) to :data:`ESTIMATE_DIGITS` significant digits, grouped."""
    if abs(x) >= BIG:
        return sci(x)
    if _estimate(check) and x == check.course_value:
        text = _rounded(x)[0]
        return f(float(text), len(text.partition(".")[2]), group=True)
    return _fixed(x, check)


def _unit(unit: str) -> str:
    return "" if unit == "1" else rf"\text{{{unit}}}"


def _relation(check: Check) -> str:
    """≤ / ≥ when the check passes, > / < when it fails."""
    if check.sense == "le":
        return r"\le" if check.passed else ">"
    return r"\ge" if check.passed else "<"


def _tail(check: Check, allow_symbol: str) -> str:
    u = _unit(check.unit)
    rel = _relation(check)
    return f" = {_value(check)}\\ {u} {rel} {allow_symbol} = {_allowable(check)}\\ {u}"


def _prod(*factors: float) -> str:
    return r" \times ".join(num(v) for v in factors)


def _gear_contact(c: Check) -> str:
    i = c.inputs
    zb = i.get("Zbeta", 1.0) != 1.0
    sym = r"\sqrt{\frac{2 K T_1}{b d_1^2} \times \frac{u+1}{u}} Z_H Z_E Z_\varepsilon" + (r" Z_\beta" if zb else "")
    factors = [i["ZH"], i["ZE"] * SQRT_MPA, i["Zeps"]] + ([i["Zbeta"]] if zb else [])
    z = math.prod(_float(num(x)) for x in factors)
    K, b, u = (_float(num(x)) for x in (i["K"], i["b"] * MM, i["u"]))
    # d₁ as the gear table prints it (0.01 mm), in both checks (one value one way: 123.67
    # in the table and the contact check, 123.7 in the bending check, review 38); T₁ with
    # the digits that give the printed stress
    d1 = f(i["d1"] * MM, 2)
    t1, = _giving((i["T1"] * N_MM,), lambda t: math.sqrt(2 * K * t / (b * float(d1) ** 2) * (u + 1) / u) * z,
                  _value(c), most=4)
    numbers = (rf"\sqrt{{\frac{{2 \times {num(i['K'])} \times {t1}}}{{{num(i['b'] * MM)} \times "
               rf"{d1}^2}} \times \frac{{{num(i['u'])}+1}}{{{num(i['u'])}}}}} \times {_prod(*factors)}")
    return rf"\sigma_H = {sym} = {numbers}" + _tail(c, r"[\sigma_H]")


def _gear_bending(c: Check) -> str:
    i = c.inputs
    yb = i.get("Ybeta", 1.0) != 1.0
    sym = r"\frac{2 K T_1 Y_{Fa} Y_{Sa} Y_\varepsilon" + (r" Y_\beta" if yb else "") + "}{b d_1 m}"
    top = [i["K"], i["T1"] * N_MM, i["YFa"], i["YSa"], i["Yeps"]] + ([i["Ybeta"]] if yb else [])
    # d₁ as the gear table prints it (see _gear_contact), Y_Fa and Y_Sa as it prints them; K,
    # T₁, Y_ε and Y_β (not in the table) with the digits that give the printed stress
    free = [0, 1, 4] + ([5] if yb else [])
    rest = math.prod(_float(num(x)) for k, x in enumerate(top) if k not in free)
    b, m = _float(num(i["b"] * MM)), _float(num(i["m"] * MM))
    d1 = f(i["d1"] * MM, 2)
    texts = _giving([top[k] for k in free], lambda *v: 2 * rest * math.prod(v) / (b * float(d1) * m),
                    _value(c), most=3)
    from ..numbers import gives
    if not gives(2 * rest * math.prod(_float(t) for t in texts) / (b * float(d1) * m), _value(c)):
        # a stress at a rounding edge (die_cutter stage 2: 87.0497 MPa, which the table's
        # d₁ = 123.67 and Y_Fa, Y_Sa cannot give): K, T₁ and d₁ with the digits that give it
        rest = math.prod(_float(num(x)) for k, x in enumerate(top) if k not in (0, 1))
        k_txt, t1, d1 = _giving((i["K"], i["T1"] * N_MM, i["d1"] * MM),
                                lambda k_, t, d: 2 * rest * k_ * t / (b * d * m), _value(c))
        texts = [k_txt, t1] + [num(top[k]) for k in free[2:]]
    shown = [num(x) for x in top]
    for k, t in zip(free, texts):
        shown[k] = t
    top_txt = r" \times ".join(shown)
    numbers = (rf"\frac{{2 \times {top_txt}}}"
               rf"{{{num(i['b'] * MM)} \times {d1} \times {num(i['m'] * MM)}}}")
    return rf"\sigma_F = {sym} = {numbers}" + _tail(c, r"[\sigma_F]")


def _worm_contact(c: Check) -> str:
    i = c.inputs
    numbers = (rf"{_prod(i['ZE'] * SQRT_MPA, i['Zrho'])} \times "
               rf"\sqrt{{\frac{{{_prod(i['K'], i['T2'] * N_MM)}}}{{{num(i['a'] * MM)}^3}}}}")
    return rf"\sigma_H = Z_E Z_\rho \sqrt{{\frac{{K T_2}}{{a^3}}}} = {numbers}" + _tail(c, r"[\sigma_H]")


def _worm_bending(c: Check) -> str:
    i = c.inputs
    numbers = (rf"\frac{{1.53 \times {_prod(i['K'], i['T2'] * N_MM)}}}{{{_prod(i['d1'] * MM, i['d2'] * MM, i['m'] * MM)}}}"
               rf" \times {_prod(i['YFa2'], i['Ybeta'])}")
    return rf"\sigma_F = \frac{{1.53 K T_2}}{{d_1 d_2 m}} Y_{{Fa2}} Y_\beta = {numbers}" + _tail(c, r"[\sigma_F]")


def _worm_thermal(c: Check) -> str:
    i = c.inputs
    numbers = (rf"{num(i['t0'])} + \frac{{1000 \times {num(i['P1'] / 1e3)} \times (1-{num(i['eta'])})}}"
               rf"{{{_prod(i['kd'], i['A'])}}}")
    return rf"t = t_0 + \frac{{1000 P_1 (1-\eta)}}{{\alpha_d A}} = {numbers}" + _tail(c, "[t]")


def _sq(t: str) -> str:
    """A number about to be squared: in parentheses when it is written with a power of ten."""
    return f"({t})" if "^" in t else t


def _shaft_bending(c: Check) -> str:
    i = c.inputs
    # the section's bending moment; a rounding residue of zero beside the torque (an
    # overhung end, where M is 0: "7.105 × 10⁻¹²") is written 0
    M = i["M"] if abs(i["M"]) > 1e-9 * abs(i["alpha"] * i["T"]) else 0.0
    a, d = _float(num(i["alpha"])), _float(num(i["d"] * MM))
    m_txt, t_txt = _giving((M * N_MM, i["T"] * N_MM),
                           lambda m, t: math.sqrt(m * m + (a * t) ** 2) / (0.1 * d ** 3), _value(c))
    numbers = (rf"\frac{{\sqrt{{{_sq(m_txt)}^2 + ({num(i['alpha'])} \times {t_txt})^2}}}}"
               rf"{{0.1 \times {num(i['d'] * MM)}^3}}")
    return rf"\sigma_{{ca}} = \frac{{\sqrt{{M^2 + (\alpha T)^2}}}}{{0.1 d^3}} = {numbers}" + _tail(c, r"[\sigma_{-1b}]")


def _shaft_min_diameter(c: Check) -> str:
    i = c.inputs
    k = i.get("keyway_increase", 0.0)
    sym = r"A_0 \sqrt[3]{\frac{P}{n}}" + (r" (1 + k)" if k else "")
    # the power to 4 significant digits as the shaft table and the design step write it
    # (0.04630 kW, not 0.0463: the number rule's sig, trailing zeros kept)
    numbers = (rf"{num(i['A0'])} \times \sqrt[3]{{\frac{{{rule_sig(i['P'] / 1e3, 4, group=False)}}}"
               rf"{{{num(i['n_rpm'])}}}}}")
    numbers += rf" \times (1 + {num(k)})" if k else ""
    rel = _relation(c)
    u = _unit(c.unit)
    return (rf"d_{{\text{{min}}}} = {sym} = {numbers} = {_allowable(c)}\ {u}, \quad d = {_value(c)}\ {u} {rel} d_{{\text{{min}}}}")


def _giving(xs, fn, printed: str, most: int = 3) -> list[str]:
    """The numbers ``xs`` of a formula as :func:`num` writes them, with the fewest more
    significant digits (up to ``most`` each, fewest in all first) that make ``fn(*printed
    numbers)`` give ``printed`` to its last digit (a displayed chain computes from what it
    prints: 15200/1109 = 13.706, printed 13.70 — P_0 = 1109.5)."""
    from itertools import product

    from ..numbers import gives

    mantissa, _, power = printed.partition("\\times10^{")
    power = int(power.rstrip("}") or 0)
    for total in range(most * len(xs) + 1):
        for extras in product(range(most + 1), repeat=len(xs)):
            if sum(extras) != total:
                continue
            texts = [num(x, 4 + e) for x, e in zip(xs, extras)]
            if any("(" in t for t in texts):
                return [num(x) for x in xs]
            if gives(fn(*(_float(t) for t in texts)) / 10.0 ** power, mantissa):
                return texts
    return [num(x) for x in xs]


def _float(text: str) -> float:
    """The value of a number :func:`num` wrote (``1.1\\times10^{5}`` too)."""
    mant, _, power = text.partition("\\times10^{")
    return float(mant) * 10.0 ** int(power.rstrip("}") or 0)


def _bearing_life(c: Check) -> str:
    i = c.inputs
    eps = r"\frac{10}{3}" if abs(i["epsilon"] - 10 / 3) < 1e-9 else num(i["epsilon"])
    e_val = 10 / 3 if abs(i["epsilon"] - 10 / 3) < 1e-9 else float(num(i["epsilon"]))
    ft = i.get("ft", 1.0)
    # a life is an estimate: to 4 significant digits ("≈ 199600 h"), n and P with the digits
    # that give those 4 (267.6 and 949.5, not 267.643 and 949.528 for the six digits of
    # 199 597 h); from 10⁶ h on a power of ten, as every number (≈ 6.157 × 10⁶ h): "≈" for
    # every life, one relation for one kind of result
    x = c.course_value
    target = _rounded(x)[1]
    n_txt, p_txt = _giving((i["n_rpm"], i["P"]), lambda n, p: 1e6 / (60 * n) * (
        _float(num(ft)) * _float(num(i["C"])) / p) ** e_val, target)
    ratio = rf"\frac{{{_prod(ft, i['C'])}}}{{{p_txt}}}"
    numbers = rf"\frac{{10^6}}{{60 \times {n_txt}}} \times ({ratio})^{{{eps}}}"
    tail = _tail(c, r"L_h'").replace(" = ", r" \approx ", 1)
    return (rf"L_{{10h}} = \frac{{10^6}}{{60 n}} (\frac{{f_t C}}{{P}})^{{\varepsilon}} = {numbers}"
            + tail)


def _key_crushing(c: Check) -> str:
    i = c.inputs
    kld = math.prod(_float(num(x)) for x in (0.5 * i["h"] * MM, i["l"] * MM, i["d"] * MM))
    keys = 1.5 if i.get("keys") == 2 else 1.0
    t_txt = _giving((i["T"] * N_MM,), lambda t: 2 * t / (keys * kld), _value(c))[0]
    if i.get("keys") == 2:      # two keys at 180°, counted as 1.5 keys
        numbers = (rf"\frac{{2 \times {t_txt}}}{{1.5 \times "
                   rf"{_prod(0.5 * i['h'] * MM, i['l'] * MM, i['d'] * MM)}}}")
        return rf"\sigma_p = \frac{{2 T}}{{1.5 k l d}} = {numbers}" + _tail(c, r"[\sigma_p]")
    numbers = (rf"\frac{{2 \times {t_txt}}}{{{_prod(0.5 * i['h'] * MM, i['l'] * MM, i['d'] * MM)}}}")
    return rf"\sigma_p = \frac{{2 T}}{{k l d}} = {numbers}" + _tail(c, r"[\sigma_p]")


def _bearing_static(c: Check) -> str:
    i = c.inputs
    c0, p0 = _giving((i["C0"], i["P0"]), lambda a, b: a / b, _value(c))
    return (rf"\frac{{C_0}}{{P_0}} = \frac{{{c0}}}{{{p0}}}" + _tail(c, r"S_0"))


def _rel(check: Check) -> str:
    return _relation(check)


def _tooth_tip(c: Check) -> str:
    i = c.inputs
    return (rf"s_a = {f(c.value * MM, 2)}\ \text{{mm}} {_rel(c)} {num(i['factor'])} m = {num(i['factor'])} \times "
            rf"{num(i['m'] * MM)} = {num(c.allowable * MM)}\ \text{{mm}}")


def _undercut(c: Check) -> str:
    i = c.inputs
    # a helical gear: its equivalent spur gear's teeth z_v = z/cos³β (review38: 26.27 stood
    # under the symbol z, with z = 24 in the table)
    z = "z_v" if "beta" in i else "z"
    zv = ""
    if "beta" in i:
        b = math.degrees(i["beta"])
        cos_b = _giving((math.cos(i["beta"]),), lambda c3: i["z"] / c3 ** 3, num(c.value))[0]
        zv = (rf", \quad z_v = \frac{{z}}{{\cos^3\beta}} = \frac{{{num(i['z'])}}}{{\cos^3 {num(b)}°}} = "
              rf"\frac{{{num(i['z'])}}}{{{cos_b}^3}} = {num(c.value)}")
    return (rf"x = {lone(i['x'], 3) if i['x'] else '0'} {_rel(c)} x_{{min}} = \frac{{h_a^*(z_{{min}} - {z})}}{{z_{{min}}}} = "
            rf"\frac{{{num(i['ha_star'])} \times ({num(i['z_min'])} - {num(c.value)})}}{{{num(i['z_min'])}}} = "
            rf"{lone(i['x_min'], 3) if abs(i['x_min']) > 1e-12 else '0'}{zv}")


def _contact_ratio(c: Check) -> str:
    i = c.inputs
    if "beta" not in i:
        # no chain: the value and the limit as the check table prints them (1.66 ≥ 1.20, never
        # 1.657 above a table row of 1.66: one value one way, review 38)
        return rf"\varepsilon_\alpha = {_value(c)} {_rel(c)} [\varepsilon_\alpha] = {_allowable(c)}"
    # a helical pair: the textbook's estimate, with β to the digits that give the value
    z1, z2 = num(i["z1"]), num(i["z2"])
    beta = _giving((math.degrees(i["beta"]),), lambda b: (1.88 - 3.2 * (1 / i["z1"] + 1 / i["z2"]))
                   * math.cos(math.radians(b)), num(c.value))[0]
    return (rf"\varepsilon_\alpha = \left(1.88 - 3.2\left(\frac{{1}}{{z_1}} + \frac{{1}}{{z_2}}\right)\right)\cos\beta"
            rf" = \left(1.88 - 3.2 \times \left(\frac{{1}}{{{z1}}} + \frac{{1}}{{{z2}}}\right)\right) \times "
            rf"\cos {beta}° = {num(c.value)} {_rel(c)} [\varepsilon_\alpha] = {num(c.allowable)}")


def _worm_deflection(c: Check) -> str:
    i = c.inputs
    return (rf"y = \frac{{\sqrt{{F_{{t1}}^2 + F_{{r1}}^2}}\, L^3}}{{48 E I}} = \frac{{\sqrt{{{_sq(num(i['Ft1']))}^2 + "
            rf"{_sq(num(i['Fr1']))}^2}} \times {num(i['L'] * MM)}^3}}{{48 \times {num(i['E'] * 1e-6)} \times "
            rf"{num(i['I'] * 1e12)}}} = {num(c.value * MM)}\ \text{{mm}} {_rel(c)} [y] = \frac{{d_1}}{{1000}} = "
            rf"{num(c.allowable * MM)}\ \text{{mm}}\ (\text{{mm}}, \text{{N}}, \text{{MPa}})")


def _motor_end(c: Check) -> str:
    """The course guides' rule for a shaft end coupled to the motor: d ≥ 0.8 D."""
    i = c.inputs
    u, rel = _unit(c.unit), _relation(c)
    return (rf"d = {_value(c)}\ {u} {rel} {num(i['ratio'])} D = {num(i['ratio'])} \times "
            rf"{num(i['D'] * MM)} = {_allowable(c)}\ {u}")


def _coupling_torque(c: Check) -> str:
    """T_c = K_A T ≤ T_n (GB/T 12458 terms; 濮良贵 ch.14)."""
    i = c.inputs
    # T_c with T's digits (1 × 0.9983 = 0.9983, not 1.00: one value one way)
    u = _unit(c.unit)
    return (rf"T_c = K_A T = {num(i['KA'])} \times {num(i['T'])} = {num(c.value)}\ {u} {_relation(c)} "
            rf"T_n = {_allowable(c)}\ {u}")


_FORMULAS = {
    "motor_end": _motor_end,
    "coupling_torque": _coupling_torque,
    "bearing_static": _bearing_static,
    "gear_contact": _gear_contact,
    "gear_bending": _gear_bending,
    "worm_contact": _worm_contact,
    "worm_bending": _worm_bending,
    "worm_thermal": _worm_thermal,
    "shaft_bending": _shaft_bending,
    "shaft_min_diameter": _shaft_min_diameter,
    "bearing_life": _bearing_life,
    "key_crushing": _key_crushing,
    "tooth_tip": _tooth_tip,
    "undercut": _undercut,
    "contact_ratio": _contact_ratio,
    "worm_deflection": _worm_deflection,
}


def check_formula(check: Check) -> str:
    """The check's textbook formula with its numbers (course units) and the verdict relation.
    Checks of an unknown key fall back to ``symbol = value ≤ allowable``."""
    render = _FORMULAS.get(check.key)
    if render is None:
        return check.symbol + _tail(check, f"[{check.symbol}]")
    return render(check)


#: A formula longer than this (TeX source characters) is set on two lines: the formula with
#: its numbers, then the result against the allowable (one line would pass the margin).
ONE_LINE = 180


def check_formulas(check: Check) -> list[str]:
    """:func:`check_formula` as display lines: one, or — when it is long — the formula with
    its numbers and, on a second line, ``symbol = value ≤ [symbol] = allowable``."""
    text = check_formula(check)
    render = _FORMULAS.get(check.key)
    if render is None or len(text) <= ONE_LINE:
        return [text]
    head, _, _ = text.partition(" = ")
    allow = text[text.rfind(_relation(check)):]
    # an estimate's value follows "≈" (a life to 4 significant digits), the others "="
    sep = r" \approx " if rf"\approx {_value(check)}\ " in text else " = "
    tail = f"{sep}{_value(check)}\\ {_unit(check.unit)} {allow}"
    if not text.endswith(tail[len(sep):]) or tail in head:
        return [text]
    body = text[: len(text) - len(tail)]
    return [body, head + tail]


def verdict(check: Check, lang: str = "zh") -> str:
    _ = tr(lang)
    return _("PASS") if check.passed else _("FAIL")


def check_rows(checks: Iterable[Check], lang: str = "zh") -> list[list[str]]:
    """Summary rows ``[item_zh, item_en, value, allowable, unit, verdict]`` (course units;
    the allowable is a minimum for lives and diameters, a maximum otherwise; a ratio's unit "1"
    shows as "—")."""
    from ..stages.findings import check_name

    zh, en = tr("zh"), tr("en")
    return [[check_name(c).text(zh), check_name(c).text(en), _cell(c.course_value, c),
             _cell(c.course_allowable, c),
             "—" if c.unit == "1" else c.unit, verdict(c, lang)] for c in checks]


#: A value or allowable as the check tables print it.
cell = _cell

__all__ = ["check_formula", "check_rows", "verdict", "num", "COURSE_SCALE", "cell"]
