"""One quantity, one symbol (page review 48, B): the graphical method named every machine's
resistance F_r while its data table and kinetostatics say F_c (shaper, shaper_lengths, slotter,
die_cutter) or Q_max (press), and the shaper's inertia force was P_I in its table beside F_I in
the force analysis (孙桓《机械原理》 writes F_I). The resistance now carries its symbol
(stages.linkage.Resistance.symbol). And reactions equal over the whole cycle are one curve
with one legend entry (figure 5 hid F_R72 and F_R23 under F_R43)."""
from __future__ import annotations

import re
from contextlib import contextmanager

import numpy as np
import pytest

from tests.test_report_prose import _markdown

LANGS = ["zh", "en"]
# machine → the resistance's symbol in its data table (Table 1) and in the graphical method
SYMBOLS = {"shaper": "F_c", "shaper_lengths": "F_c", "slotter": "F_c", "die_cutter": "F_c",
           "press": "Q"}


def _known_loads(md: str) -> list[str]:
    return re.findall(r"^(?:Known loads|作用在杆组上的已知力)[:：].*$", md, re.M)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", sorted(SYMBOLS))
def test_the_graphical_method_names_the_resistance_as_the_data_table_does(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    symbol = SYMBOLS[name]
    loads = _known_loads(md)
    assert loads, "no known-loads sentence"
    # the position in the working zone names the resistance with the table's symbol ...
    assert any(f"${symbol}$" in s for s in loads), loads
    # ... and F_r appears nowhere, as text or in an equation (a gear's radial force F_r in
    # the drive chapter is another quantity: written with F_t and F_a)
    assert "$F_r$" not in md and r"\vec F_r " not in md
    # the data table states the symbol (the press's as Q_max)
    table = "$Q_{max}$" if symbol == "Q" else f"${symbol}$"
    assert re.search(rf"^\| {re.escape(table)} \|", md, re.M), table


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", ["shaper", "shaper_lengths"])
def test_the_inertia_force_is_f_i_in_the_table_and_in_the_force_analysis(example_results, name, lang):
    md, _ = _markdown(example_results, name, lang)
    assert "P_I" not in md and "P_{I" not in md
    assert "$F_{I4}$/N" in md and "$F_{I6}$/N" in md       # the kinetostatics table
    assert re.search(r"\$F_\{I6\}\$ ?[（(](?:link |构件 )6[）)]", md)   # the graphical known loads


def _legend_of(named, monkeypatch, tmp_path):
    """The (label, curve) pairs figures.reactions draws for ``named``."""
    from mechdesign.render import figures

    drawn = []

    class Axes:
        def plot(self, x, y, **kw):
            drawn.append((kw.get("label"), np.asarray(y)))

        def __getattr__(self, name):
            return lambda *a, **k: None

    @contextmanager
    def fake(path, nrows=1, size=None, sharex=True):
        yield (Axes(),)

    monkeypatch.setattr(figures, "figure", fake)
    monkeypatch.setattr(figures, "legend", lambda *a, **k: None)
    monkeypatch.setattr(figures, "_phase_axis", lambda *a, **k: None)
    figures.reactions.__wrapped__(tmp_path / "r.png", "en", np.arange(4.0), named, (0, 180))
    return drawn


def test_equal_reactions_are_one_curve_with_their_names_joined(monkeypatch, tmp_path):
    a = np.array([1.0, 2.0, 3.0, 4.0]) * 1e3
    b = np.array([4.0, 3.0, 2.0, 1.0]) * 1e3
    named = {"$F_{R72}$": a, "$F_{R23}$": a.copy(), "$F_{R43}$": a * (1 + 1e-12),
             "$F_{R45}$": b, "$F_{R56}$": b + 1.0}       # 1 N apart: two curves
    drawn = _legend_of(named, monkeypatch, tmp_path)
    labels = [label for label, _ in drawn]
    assert labels == ["$F_{R72}$ = $F_{R23}$ = $F_{R43}$", "$F_{R45}$", "$F_{R56}$"]
    assert np.allclose(drawn[0][1], a) and np.allclose(drawn[2][1], b + 1.0)
