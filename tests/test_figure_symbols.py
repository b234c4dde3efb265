"""Quantity symbols in the report's figures are math italic, as in its formulas and text
(issue 19, session 34): labels, legends and notes wrote "ΔE", "H − t", "F/M", "crank angle φ"
as upright text. render.figures.save_png sets every figure text through
render.labels.mpl_symbols; units, words and formulas are left as written."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from mechdesign.render.labels import mpl_symbols

CASES = [
    # the three named in the review, as the figures write them
    ("energy change ΔE (J)", r"energy change $\Delta E$ (J)"),
    ("cutting starts H − t = 55.0 mm", "cutting starts $H$ − $t$ = 55.0 mm"),
    ("F/M (kN/(kN·m))", "$F$/$M$ (kN/(kN·m))"),
    # axis labels: a Greek letter, a lone letter before the unit
    ("crank angle φ (°)", r"crank angle $\varphi$ (°)"),
    ("曲柄转角 φ (°)", r"曲柄转角 $\varphi$ (°)"),
    ("displacement s (mm)", "displacement $s$ (mm)"),
    ("acceleration a (m/s²)", "acceleration $a$ (m/s²)"),
    ("x (mm)", "$x$ (mm)"),
    ("actual profile ρa", r"actual profile $\rho_{a}$"),
    ("wheel angle |Δβ| (°)", r"wheel angle |$\Delta \beta$| (°)"),
    # derivatives: d upright, the quantities italic
    ("ratio |dβ/dα|", r"ratio |$\mathrm{d}\beta/\mathrm{d}\alpha$|"),
    ("angular acceleration d²φ/dt² (rad/s²)",
     r"angular acceleration $\mathrm{d}^{2}\varphi/\mathrm{d}t^{2}$ (rad/s²)"),
    # primes, a lone dimension symbol, a symbol in a compound word
    ("$m$ = 5 mm\na′ = 170.00 mm, α′ = 20.00°", "$m$ = 5 mm\n$a′$ = 170.00 mm, $\\alpha′$ = 20.00°"),
    ("e", "$e$"),
    ("four-bar θ-circle", r"four-bar $\theta$-circle"),
    ("(φ = 0.0°)", r"($\varphi$ = 0.0°)"),
    # left as written: units, words, formulas, point names, position labels, the article
    ("crank torque (N·m)", "crank torque (N·m)"),
    ("velocity (m/s)", "velocity (m/s)"),
    ("mean = 636.62 N·m", "mean = 636.62 N·m"),
    ("5 s", "5 s"),
    ("V-belt", "V-belt"),
    ("φ45", "φ45"),
    ("a bend of 3", "a bend of 3"),
    ("balancing torque $M_b$ (N·m)", "balancing torque $M_b$ (N·m)"),
    (r"$\omega_4$ (rad/s)", r"$\omega_4$ (rad/s)"),
    ("rocker $O_4B$", "rocker $O_4B$"),
    ("pivot A", "pivot A"),
]


@pytest.mark.parametrize("text, expected", CASES)
def test_quantity_symbols_become_math_italic(text, expected):
    assert mpl_symbols(text) == expected
    assert mpl_symbols(expected) == expected          # idempotent: formulas left alone


# an upright quantity symbol left in a figure's text: a Greek letter (not a position label
# "φ45"), or the review's "H − t", "F/M", "ΔE", outside the text's formulas and units
_UPRIGHT = re.compile(r"[α-ωΓΔΘΛΞΠΣΦΨΩ](?![0-9])|\bH − t\b|\bF/M\b")


def _plain(text: str) -> str:
    text = re.sub(r"(?<!\\)\$[^$]*(?<!\\)\$", "", text)
    return re.sub(r"\((?:[^()]|\([^()]*\))*\)", "", text)          # unit groups


def _figure_texts(r: dict, machine: str, monkeypatch, tmp_path: Path, lang: str) -> dict:
    """Every text of every figure the report draws, as save_png leaves it (nothing written)."""
    import importlib

    from matplotlib.text import Text

    from mechdesign.machines import get_machine
    from mechdesign.render import figures as F
    from mechdesign.render import parallel

    texts: dict = {}
    real = F.save_png
    monkeypatch.setattr(parallel, "save", lambda write, name: None)

    def save_png(fig, path):
        real(fig, path)
        texts[Path(path).name] = [t.get_text() for t in fig.findobj(Text) if t.get_text().strip()]

    monkeypatch.setattr(F, "save_png", save_png)
    from mechdesign.runner import _with_requested_figures

    report = importlib.import_module(get_machine(machine).report_module)
    _with_requested_figures(report, r, tmp_path, lang)     # the machine's, requested, graphical
    return texts


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_die_cutter_figures_write_no_upright_symbols(example_results, monkeypatch, tmp_path, lang):
    """The die-cutter's figures (review: "H − t" in the platen figure's legend, "F/M" on the
    amplification axis, "ΔE" on the energy axis) and every other text of them."""
    r = example_results("die_cutter")
    texts = _figure_texts(r, r["brief"].machine, monkeypatch, tmp_path, lang)
    assert len(texts) >= 10
    left = [(name, s) for name, ts in texts.items() for s in ts if _UPRIGHT.search(_plain(s))]
    assert not left, left
    every = "\n".join(s for ts in texts.values() for s in ts)
    for written in ("$H$ − $t$", "$F$/$M$", r"$\Delta E$"):
        assert written in every, written


EXAMPLES = sorted(p.stem for p in (Path(__file__).resolve().parents[1] / "designs").glob("*.yaml")
                  if p.stem not in ("die_cutter", "furnace_drive"))


@pytest.mark.parametrize("lang", ["zh", "en"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_no_upright_symbols_in_any_figure(example_results, monkeypatch, tmp_path, name, lang):
    """Every text of every figure of every example report, found by the rule above."""
    r = example_results(name)
    texts = _figure_texts(r, r["brief"].machine, monkeypatch, tmp_path, lang)
    left = [(n, s) for n, ts in texts.items() for s in ts if _UPRIGHT.search(_plain(s))]
    assert not left, left


def test_unit_dot_next_to_a_formula_has_a_glyph():
    """A text with a formula is drawn by mathtext, whose text font has no U+22C5: the narrow
    unit dot printed "kN¤m" beside "$F$/$M$" (and beside "$M_b$" before). There it is
    mathtext's \\cdot; a text without formulas keeps U+22C5."""
    import warnings

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from mechdesign.render import figures as F
    from mechdesign.render.fonts import configure_matplotlib

    configure_matplotlib()
    fig, ax = plt.subplots()
    ax.set_ylabel(mpl_symbols("F/M (kN/(kN·m))"))
    ax.set_xlabel("crank torque (N·m)")
    F.narrow_unit_dots(fig)
    assert ax.get_ylabel() == r"$F$/$M$ (kN/(kN$\cdot$m))"
    assert ax.get_xlabel() == "crank torque (N\u22c5m)"
    with warnings.catch_warnings():
        warnings.simplefilter("error")           # a missing glyph would warn
        fig.canvas.draw()
    plt.close(fig)
