"""The flywheel's numbers as every line of a report (and its summary and sheet) prints them.

ΔW_max and J_F are each substituted into a later formula (J_F = 900ΔW_max/(π²n²[δ]), the
rim mass m = 4J_F/D²) whose printed result must follow from the printed factors; a value
printed with fewer digits in the text than in the formula beside it reads as two values of
one quantity (review 38: shaper_lengths' "J_F = 204.1" above "4 × 204.13"). So J_F is
written with the digits its rim mass needs, ΔW_max with the digits that J_F needs, and the
text, the summary table and the analysis sheet print those same strings."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .fmt import f, factor_for, factors_for, fluctuation, gives, grouped, sig


@dataclass(frozen=True)
class FlywheelTexts:
    """ΔW_max (J) and J_F (kg·m²) as printed, ungrouped (a formula's factors); :attr:`dw_text`
    and :attr:`jf_text` group an integer part of five or more digits for text and tables."""

    dw: str
    jf: str

    @property
    def dw_text(self) -> str:
        return grouped(self.dw)

    @property
    def jf_text(self) -> str:
        return grouped(self.jf)


def rim_factor(inertia: float, diameter: float, rim_mass: float) -> str:
    """J_F as the factor of the rim mass m = 4 J_F/D², with the digits that give the printed
    mass (4 × 204.13/1.000² = 816.52)."""
    return factor_for(inertia, lambda x: gives(4 * x / float(f(diameter, 3)) ** 2, f(rim_mass, 2)))


def flywheel_factors(energy_swing: float, speed_rpm: float, delta: float, jf: str,
                     energy_digits: int = 4) -> tuple[str, str, str]:
    """J_F = 900ΔW_max/(π²n²[δ]) with its factors substituted so that they give the printed
    ``jf``: [δ] as the course writes it (1/30, never 0.0333); n to 0.01 rpm and ΔW_max to
    ``energy_digits`` significant digits (the text's), each with the fewest more digits
    that give ``jf`` (shaper: 266.667 and 278.04, where 266.67 and 278.0 give 8.912 for
    8.914), ΔW_max's first."""
    d_text = fluctuation(delta)
    num, _slash, den = d_text.partition("/")
    d_value = float(num) / float(den) if den else float(num)
    d_tex = rf"({num}/{den})" if den else d_text

    def jf_of(n: float, dw: float) -> float:
        denominator = np.pi ** 2 * n ** 2 * d_value
        return 900 * dw / denominator if denominator > 0 else float("nan")

    # n to 0.01 rpm (up to 0.0001); a speed below 1 rpm (a careless brief's 1e-9) to
    # significant digits, which 0.01 rpm would print as 0.00 (a division by zero)
    to_decimals = speed_rpm >= 1
    n_text, dw_text = factors_for((speed_rpm, energy_swing), jf_of, jf,
                                  (2 if to_decimals else 4, energy_digits), most=(2, 4),
                                  decimals=(to_decimals, False))
    return n_text, dw_text, d_tex


def flywheel_equation(energy_swing: float, speed_rpm: float, delta: float, jf: str,
                      energy_digits: int = 4) -> str:
    """J_F = 900ΔW_max/(π²n²[δ]) with its factors (:func:`flywheel_factors`) substituted."""
    n_text, dw_text, d_tex = flywheel_factors(energy_swing, speed_rpm, delta, jf, energy_digits)
    return (rf"J_F = \frac{{900\,\Delta W_{{max}}}}{{\pi^2 n^2 [\delta]}} = \frac{{900 \times "
            rf"{dw_text}}}{{\pi^2 \times {n_text}^2 \times {d_tex}}} = {jf}\ \text{{kg·m}}^2")


def flywheel_texts(energy_swing: float, speed_rpm: float, delta: float, inertia: float,
                   rim_diameter: float | None = None, rim_mass: float | None = None,
                   energy_digits: int = 4) -> FlywheelTexts:
    """ΔW_max and J_F as the report prints them wherever they appear: J_F with the digits
    its rim's mass needs (4 significant digits or more), ΔW_max with the digits that J_F's
    equation needs (``energy_digits`` significant digits or more)."""
    if rim_diameter is not None and rim_mass is not None:
        jf = rim_factor(inertia, rim_diameter, rim_mass)
    else:
        jf = sig(inertia, group=False)
    _n, dw, _d = flywheel_factors(energy_swing, speed_rpm, delta, jf, energy_digits)
    return FlywheelTexts(dw=dw, jf=jf)


def texts_of(fly, delta: float | None = None, energy_digits: int = 4) -> FlywheelTexts:
    """:func:`flywheel_texts` of a flywheel result (its fluctuation unless ``delta``)."""
    rim = getattr(fly, "rim", None)
    return flywheel_texts(fly.max_energy_swing, fly.shaft_speed_rpm,
                          fly.fluctuation if delta is None else delta, fly.inertia,
                          rim.diameter if rim is not None else None,
                          rim.rim_mass if rim is not None else None, energy_digits)
