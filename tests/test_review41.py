"""Findings mended in session 41, each checked on the computed results or on the example
reports' Markdown (tests/conftest.py's ``handin_reports``).

- A worm is cut integral with its shaft (review39a Top 3: furnace_drive's worm, root circle
  d_f1 = 19 mm, sat between 20 mm journals on a "hub seat" of 25 mm, as if it were a hub).
  濮良贵《机械设计》 ch.11: the worm is almost always made in one piece with its shaft; the
  section between the bearings is then its root circle d_f1 = d1 − 2(h_a* + c*)m = d1 − 2.4m
  (GB/T 10085: h_a* = 1, c* = 0.2), where the bending–torsion check is made.
"""
from __future__ import annotations

import math

import pytest

LANGS = ("zh", "en")


def _worm_shafts(r):
    """(shaft design, worm stage design) of every shaft that drives a worm."""
    drive = r["drive"]
    out = []
    for sd in drive.shaft_designs:
        k = sd.index                       # the stage after shaft k is stages[k]
        if k < len(drive.stages) and drive.stages[k].design is not None \
                and drive.stages[k].design.kind == "worm":
            out.append((sd, drive.stages[k].design))
    return out


@pytest.mark.parametrize("name", ["furnace_drive", "furnace_pusher"])
def test_a_worm_is_its_shafts_section_between_the_bearings(example_results, name):
    r = example_results(name)
    found = _worm_shafts(r)
    assert found, name
    for sd, worm in found:
        g = worm.geometry
        df1 = g.m * g.q - 2.4 * g.m            # GB/T 10085 tooth proportions
        assert sd.worm_integral
        assert sd.d_seat == pytest.approx(df1, abs=1e-9)
        # the bending–torsion check between the bearings takes the root circle
        bend = next(c for c in sd.checks if c.key == "shaft_bending")
        x, d = bend.inputs["x"], bend.inputs["d"]
        if 0 < x < sd.span:
            assert d == pytest.approx(df1, abs=1e-9)
        # σ_ca = √(M² + (αT)²)/(0.1 d³) (濮良贵 eq. 15-5) from the check's own inputs
        M, T, a = bend.inputs["M"], bend.inputs["T"], bend.inputs["alpha"]
        assert bend.value == pytest.approx(math.hypot(M, a * T) / (0.1 * d ** 3), rel=1e-9)
        # no hub and no key for the worm; the collar locates the bearings (larger than the journal)
        assert not any(k.element == "worm" for k in sd.keys)
        assert sd.d_shoulder > sd.d_journal


def test_a_hub_between_the_bearings_keeps_its_seat(example_results):
    """Shaft Ⅱ of the furnace drive carries the worm wheel (a hub): seat = journal + 5 mm."""
    r = example_results("furnace_drive")
    worm_shafts = {sd.index for sd, _ in _worm_shafts(r)}
    others = [sd for sd in r["drive"].shaft_designs if sd.index not in worm_shafts]
    assert others
    for sd in others:
        assert not sd.worm_integral
        assert sd.d_seat == pytest.approx(sd.d_journal + 0.005, abs=1e-9)


@pytest.mark.parametrize("lang", LANGS)
def test_the_report_names_the_worm_root_circle(handin_reports, lang):
    md, _ = handin_reports("furnace_drive", lang)
    row = "蜗杆齿根圆 $d_{f1}$ | 19 | mm" if lang == "zh" else "worm root circle $d_{f1}$ | 19 | mm"
    assert row in md
    assert ("蜗杆与轴制成一体" if lang == "zh" else "the worm is cut integral with the shaft") in md
    assert "2.4 \\times 2.5 = 19$" in md


@pytest.mark.parametrize("name", ["furnace_drive", "furnace_pusher"])
def test_the_worm_shaft_is_designed_on_the_span_its_deflection_is_checked_on(example_results, name):
    """The worm shaft's bending and bearings took a span of the worm's width + 2 × 60 mm
    (180 mm) while its deflection check took L ≈ 0.9 d2 (濮良贵 ch.11; 79 mm): one span."""
    r = example_results(name)
    for sd, worm in _worm_shafts(r):
        defl = next(c for c in worm.checks if c.key == "worm_deflection")
        assert sd.span == pytest.approx(defl.inputs["L"], rel=1e-12)
        if not defl.inputs["span_given"]:
            assert sd.span == pytest.approx(0.9 * worm.geometry.m * worm.geometry.z2, rel=1e-12)


def test_a_failed_check_names_its_own_remedy(tmp_path):
    """Session 41's page review: the die-cutter's bearing 6326 life fails and the report said
    "enlarge it or use a better material" (a material does not lengthen a bearing's life). Each
    failed shaft, bearing or key check names the remedy of its kind. The example now lifts its
    platen with two linkages; with one (the whole 1000 kN on one crank) shaft Ⅲ fails as it did."""
    from mechdesign.brief.loader import load_brief
    from mechdesign.machines import get_machine, stages_for
    from mechdesign.pipeline import run_stages
    from tests.conftest import DESIGNS

    text = (DESIGNS / "die_cutter.yaml").read_text(encoding="utf-8")
    assert "\n  linkages: 2 " in text
    one = tmp_path / "die_cutter.yaml"
    one.write_text(text.replace("\n  linkages: 2 ", "\n  linkages: 1 "), encoding="utf-8")
    brief = load_brief(one)
    machine = get_machine(brief.machine)
    params = machine.to_params(brief)
    r, _ = run_stages(stages_for(machine, params), {"params": params, "brief": brief})
    lines = [w.text("en") for w in r["drive"].warnings]
    life = [t for t in lines if " life fails" in t]
    assert life and all("heavier series" in t and "material" not in t for t in life), life
    bending = [t for t in lines if "bending–torsion strength fails" in t]
    assert bending and all("stronger shaft material" in t for t in bending), bending
    keys = [t for t in lines if ": Key " in t]
    assert keys and all("two keys" in t for t in keys), keys


def test_the_return_limit_is_labelled_alpha_prime(monkeypatch, tmp_path):
    """Page review 41: the pressure-angle figures labelled the return's allowed angle "[α] = 70°"
    where the tables write [α′] (cam_7_3 fig. 3, die_cutter fig. 18)."""
    import numpy as np

    from mechdesign.render import cam_figures, figures

    kept = {}
    monkeypatch.setattr(figures, "save_png", lambda fig, path: kept.setdefault("fig", fig))
    delta = np.linspace(0, 360, 73)
    segments = [(0.0, 120.0, "rise", None), (120.0, 180.0, "far_dwell", None),
                (180.0, 300.0, "return", None), (300.0, 360.0, "near_dwell", None)]
    fn = getattr(cam_figures.pressure_and_curvature, "__wrapped__", cam_figures.pressure_and_curvature)
    fn(tmp_path / "a.png", "en", delta, 20 * np.sin(np.radians(delta)) ** 2, [30.0, None, 70.0, None],
       segments)
    texts = [t.get_text() for ax in kept["fig"].axes for t in ax.texts]
    assert "[α] = 30°" in texts and "[α′] = 70°" in texts, texts
