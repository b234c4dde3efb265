"""The feed cam on a guide-bar machine's crank shaft is phased to the crank: its motion must
lie in the return stroke (shaper: "进给须在刨头空回行程中完成"; page review 48: never shown).
Independent reference: the guide-bar mechanism's return stroke spans 180° − θ of crank angle,
θ = 180°(K − 1)/(K + 1) (孙桓, 机械原理, the time-ratio coefficient)."""
from types import SimpleNamespace

import pytest

from mechdesign.render.guide_bar_report import cam_phase as phase_rows
from mechdesign.stages.guide_bar import cam_phase


def _return_span(K):
    return 180.0 - 180.0 * (K - 1) / (K + 1)


@pytest.mark.parametrize("name, K, motion", [("shaper", 1.2, 150.0), ("slotter", 1.8, 120.0)])
def test_the_cams_motion_lies_in_the_return_stroke(example_results, handin_reports, name, K, motion):
    r = example_results(name)
    ph = r["cam_phase"]
    assert ph.passed and ph == cam_phase(r["cam"], r["linkage"])
    data, check = phase_rows(ph, "en")
    ret = _return_span(K)
    assert data[2] == f"{360.0 - ret:.2f}"                   # δ = 0 where the return begins
    assert check[1:] == [f"{motion:.2f}°", f"≤ {ret:.2f}°", "PASS"]
    md, _ = handin_reports(name, "en")
    assert f"| follower's motion within the return stroke | {motion:.2f}° | ≤ {ret:.2f}° | PASS |" in md
    assert f"(the return stroke begins) | {360.0 - ret:.2f} | ° |" in md


def test_a_motion_longer_than_the_return_stroke_fails(example_results):
    r = example_results("slotter")
    seg = SimpleNamespace
    rad = 3.141592653589793 / 180
    cam = SimpleNamespace(segments=[seg(kind="rise", start=0.0, span=70 * rad),
                                    seg(kind="dwell", start=70 * rad, span=10 * rad),
                                    seg(kind="return", start=80 * rad, span=70 * rad),
                                    seg(kind="dwell", start=150 * rad, span=210 * rad)])
    ph = cam_phase(cam, r["linkage"])
    assert not ph.passed
    _data, check = phase_rows(ph, "en")
    assert check[1:] == ["150.00°", f"≤ {_return_span(1.8):.2f}°", "FAIL"]
    _data, check = phase_rows(ph, "zh")
    assert check[0] == "从动件运动在回程之内完成" and check[3] == "不合格"


def test_the_press_oil_pump_cam_is_not_phased(example_results):
    """The press's cam drives the oil pump: nothing ties it to the return stroke."""
    assert example_results("press").get("cam_phase") is None


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_phase_symbol_is_not_the_followers_initial_angle(handin_reports, lang):
    # page review 51: the cam data table named the crank angle at δ = 0 "φ0", which the
    # oscillating follower's equations use for its initial angle (φ0 = arccos …, 21.37°)
    md, _ = handin_reports("shaper", lang)
    assert "\\varphi_0 = \\arccos" in md                 # the follower's initial angle
    rows = [line for line in md.splitlines() if "= 0" in line and line.startswith("| $\\varphi")]
    assert rows and all(row.startswith("| $\\varphi_{\\delta=0}$ |") for row in rows), rows
