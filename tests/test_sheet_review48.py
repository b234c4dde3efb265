"""Page review 47, sheets and summary:

- the kinematic diagram of a linkage whose position 1 is the folded extreme position (the
  coupler lies back over the crank and its pivot: linkage_sixbar, crank-rocker-slider
  machines) is drawn at the graphical method's first position, where every link shows;
- a frame symbol is drawn on the side of its pivot that the links leave free (the lockbeam's
  G0 symbol ran across the rocker, the roller and the cam);
- the summary's unit column is set as units ("m/s"), not as quantity letters ("𝑚/𝑠").
"""
from __future__ import annotations

import re

import numpy as np
import pytest


def _on_segment(p: complex, a: complex, b: complex, tol: float) -> bool:
    """Whether ``p`` lies on the segment ab (within ``tol``): an independent test of 'the
    coupler runs over the crank's pivot'."""
    t = ((p - a) * np.conj(b - a)).real / abs(b - a) ** 2
    return 0.0 <= t <= 1.0 and abs(a + t * (b - a) - p) <= tol


def _found(example_results, name):
    from mechdesign.render.sheets import linkage_results

    return linkage_results(example_results(name))


@pytest.mark.parametrize("name,covered", [("linkage_sixbar", True), ("die_cutter", True),
                                          ("press", False), ("slotter", False), ("shaper", False)])
def test_position_1_covers_the_crank_where_the_coupler_runs_over_its_pivot(example_results, name, covered):
    from mechdesign.render import kinematic_sheet as ks
    from mechdesign.stages.linkage import link_members

    found = _found(example_results, name)
    model, k = found.model, found.motion
    crank = model.crank
    i = k.grid_size + ks.linkage_positions(found, "1")
    pts = {n: complex(np.asarray(z)[i]) for n, z in k.points.items()}
    pivot = complex(model.mechanism.frame_points[crank.pivot])
    members, _ = link_members(model.mechanism)
    tip = pts[crank.tip]
    # the geometric fact: some link through the tip passes over the crank's pivot
    over = any(_on_segment(pivot, tip, pts[n], 1e-3 * crank.length)
               for link, names in members.items() if link != crank.link and crank.tip in names
               for n in names if n in pts and n != crank.tip)
    assert over is covered
    assert ks.crank_covered(found, "1") is covered


def test_the_folded_sixbar_is_drawn_at_its_first_polygon_position(example_results):
    from mechdesign.render import kinematic_sheet as ks

    found = _found(example_results, "linkage_sixbar")
    brief = example_results("linkage_sixbar")["brief"]
    drawn = ks.diagram_position(found, brief)
    assert drawn == str(found.polygons.positions[0]) and drawn != "1"
    assert not ks.crank_covered(found, drawn)
    # a machine whose position 1 shows every link keeps it
    press = _found(example_results, "press")
    assert ks.diagram_position(press, example_results("press")["brief"]) == "1"


class _Identity:
    def p(self, z):
        return complex(z)


@pytest.mark.parametrize("neighbours", [[1, 1j], [-1j, -0.5 - 1j], [-1j, 1 - 0.2j, -1 - 0.2j],
                                        [np.exp(1j * a) for a in np.radians([-80, -100, 20, 160])]])
def test_a_frame_symbol_takes_the_freest_side(neighbours):
    from mechdesign.render.kinematic_sheet import free_side

    a = free_side(_Identity(), 0j, neighbours)
    dirs = np.angle(np.asarray(neighbours, dtype=complex))

    def clearance(x):
        return min(abs(np.angle(np.exp(1j * (x - d)))) for d in dirs)

    below = clearance(-np.pi / 2)
    if below >= np.radians(45):
        assert a == pytest.approx(-np.pi / 2)
    else:
        # brute force over every direction in 1° steps: within one 15° step of the best
        best = max(clearance(x) for x in np.radians(np.arange(360)))
        assert clearance(a) >= best - np.radians(7.5) - 1e-9


@pytest.mark.parametrize("lang", ["en", "zh"])
def test_the_summarys_units_are_not_set_as_symbols(tmp_path, lang):
    """The answers at the exercise's position (the brief's analysis_requests, written by a
    run) carry their units as units."""
    from pathlib import Path

    from typer.testing import CliRunner

    from mechdesign.cli import app

    root = Path(__file__).resolve().parents[1]
    r = CliRunner().invoke(app, ["run", str(root / "designs" / "textbook_guide_bar.yaml"), "--lang", lang,
                                 "--format", "md", "--out", str(tmp_path / "r")])
    assert r.exit_code == 0, r.output
    md = (tmp_path / "r" / "report.md").read_text(encoding="utf-8")
    at = md.index("{#summary}")
    key = md[at:md.index("{#tbl:summary-key}", at)]
    rows = [line for line in key.splitlines() if line.startswith("| ") and "φ45" in line]
    assert len(rows) == 6, key
    units = [line.rstrip(" |").rsplit("| ", 1)[1].strip() for line in rows]
    assert units == ["rad/s", "rad/s²", "m/s", "m/s²", "m/s", "m/s²"], units
