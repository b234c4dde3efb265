"""Issue 19 point 8: the A1 analysis sheet writes the crank's balancing torque M_b and the
balancing force P_b in one stated sign convention. The crank's force-polygon cell wrote P_b
unsigned ("Pb = 2511 N") beside a signed M_b ("Mb = −232.3 N·m", counter-clockwise
positive), while the table's M_b column gave +232.3 at the same position (positive in the
crank's sense of rotation; the shaper's crank turns clockwise). Now both write M_b
counter-clockwise positive, as the force polygons and the report's graphical method do, and
P_b = M_b/l with M_b's sign (the report: "P_b = M_b/l = −227/0.0925 = −2457 N" at the
shaper's position 4); the notes state the convention.

Checked against the results: the forces stage's balancing torque (positive in the crank's
sense, i.e. the direction of ω: counter-clockwise positive is that times the sign of ω), the
crank's length, and the sign of the graphical method's P_b."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]


def _number(text: str) -> float:
    return float(re.sub(r"[\s\u00a0\u202f\u2009]", "", text).replace("\u2212", "-"))


def _texts(sheet):
    from mechdesign.render.sheet import Text, plain

    return [(plain(e.text), e.position) for e in sheet.entities if isinstance(e, Text)]


@pytest.mark.parametrize("name", ["shaper", "textbook_guide_bar"])
def test_cell_and_table_sign_mb_and_pb_alike(example_results, name):
    from mechdesign.brief.loader import load_brief
    from mechdesign.render.sheets import _builders, linkage_results, title_info

    brief = load_brief(ROOT / "designs" / f"{name}.yaml")
    r = example_results(name)
    found = linkage_results(r)
    build = dict(_builders(r, brief))["analysis"]
    sheet = build(title_info(brief.report, "analysis", "MD-01", 1, 1, "en"), "en")
    texts = _texts(sheet)

    model, k, forces = found.model, found.motion, found.forces
    crank = model.crank
    sense = np.sign(crank.omega)                      # +1: the crank turns counter-clockwise
    labels = list(k.positions.labels)
    n = k.grid_size
    # the convention is stated once, in the notes
    assert any("counter-clockwise positive" in t and "Mb" in t and "Pb" in t for t, _ in texts)

    # the crank's cells, one per chosen position, left to right
    mb_cells = sorted((p.real, _number(t.split("=")[1].replace("N·m", ""))) for t, p in texts
                      if re.fullmatch(r"Mb = \S+ N·m", t))
    pb_cells = sorted((p.real, _number(t.split("=")[1].replace("N", ""))) for t, p in texts
                      if re.fullmatch(r"Pb = \S+ N", t))
    chosen = [str(c) for c in found.polygons.positions]
    assert len(mb_cells) == len(pb_cells) == len(chosen)
    graphical = {str(p.label): p for p in found.graphical.positions}
    for label, (_, mb_cell), (_, pb_cell) in zip(chosen, mb_cells, pb_cells):
        i = n + labels.index(label)
        want = sense * forces.balancing_torque[i]     # counter-clockwise positive
        assert mb_cell == pytest.approx(want, rel=2e-3), (label, mb_cell, want)
        # P_b = M_b / l, with M_b's sign
        assert pb_cell == pytest.approx(want / crank.length, rel=2e-3), (label, pb_cell)
        # the same sign as the report's graphical P_b (the equation's result)
        pb_report = [m.result for fg in graphical[label].forces for m in fg.moments if m.unknown == "Pb"]
        assert pb_report and np.sign(pb_cell) == np.sign(pb_report[0]), (label, pb_cell, pb_report)
        # the table's row of this position: its last column is M_b, as the cell writes it
        # (the table is at the sheet's foot under the skeleton: the lowest text of the label)
        row_y = min((p.imag for t, p in texts if t == label and p.real < 300.0), default=None)
        assert row_y is not None, label
        row = sorted((p.real, t) for t, p in texts if abs(p.imag - row_y) < 0.1 and p.real < 300.0)
        mb_table = _number(row[-1][1])
        assert mb_table == pytest.approx(want, rel=2e-3, abs=0.06), (label, row)
        assert np.sign(mb_table) == np.sign(mb_cell)


@pytest.mark.parametrize("name", ["shaper", "textbook_guide_bar"])
def test_curve_signs_mb_as_the_table(example_results, name):
    """The M_b curve and its mean M_d are counter-clockwise positive too, as the table and the
    cells: one convention on the sheet, stated in one short notes line (the sheet wrote the
    curve positive in the crank's sense of rotation, a second convention in the notes). The
    mean line's value is the flywheel's driving torque (positive: it drives the crank) times
    the sign of ω; the shaper's crank turns clockwise, so its M_d is written negative."""
    from mechdesign.brief.loader import load_brief
    from mechdesign.render.sheets import _builders, linkage_results, title_info

    brief = load_brief(ROOT / "designs" / f"{name}.yaml")
    r = example_results(name)
    found = linkage_results(r)
    build = dict(_builders(r, brief))["analysis"]
    sheet = build(title_info(brief.report, "analysis", "MD-01", 1, 1, "en"), "en")
    texts = [t for t, _ in _texts(sheet)]
    assert not any("sense of rotation" in t for t in texts)
    assert any(re.fullmatch(r"Signs: Mb, Md and Pb counter-clockwise positive", t) for t in texts)
    md = [_number(m.group(1)) for t in texts
          for m in [re.search(r"(?:driving torque Md|mean Mb) = (\S+) N·m", t)] if m]
    sense = np.sign(found.model.crank.omega)
    mean = float(np.mean(found.forces.balancing_torque[:found.motion.grid_size]))
    assert mean > 0                                   # it drives, in the crank's sense
    assert len(md) == 1 and md[0] == pytest.approx(sense * mean, rel=2e-3), (md, sense * mean)
