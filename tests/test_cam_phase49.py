"""The feed cam on a guide-bar machine's crank shaft is phased to the crank: its motion must
lie in the return stroke (shaper: "进给须在刨头空回行程中完成"; page review 48: never shown).
Independent reference: the guide-bar mechanism's return stroke spans 180° − θ of crank angle,
θ = 180°(K − 1)/(K + 1) (孙桓, 机械原理, the time-ratio coefficient)."""
from types import SimpleNamespace

import pytest

from mechdesign.render.guide_bar_report import cam_phase


def _return_span(K):
    return 180.0 - 180.0 * (K - 1) / (K + 1)


@pytest.mark.parametrize("name, K, motion", [("shaper", 1.2, 150.0), ("slotter", 1.8, 120.0)])
def test_the_cams_motion_lies_in_the_return_stroke(example_results, name, K, motion):
    r = example_results(name)
    text = cam_phase(r["cam"], r["linkage"], "en")
    ret = _return_span(K)
    start = 360.0 - ret
    assert f"$\\varphi$ = {start:.2f}°, where the return stroke begins" in text
    assert f"ends at $\\varphi$ = {start + motion:.2f}°" in text
    assert f"{360.0 - start - motion:.2f}° before the next working stroke" in text
    assert f"within the return stroke ({ret:.2f}°)" in text


def test_a_motion_longer_than_the_return_stroke_is_reported(example_results):
    r = example_results("slotter")
    seg = SimpleNamespace
    rad = 3.141592653589793 / 180
    cam = SimpleNamespace(segments=[seg(kind="rise", start=0.0, span=70 * rad),
                                    seg(kind="dwell", start=70 * rad, span=10 * rad),
                                    seg(kind="return", start=80 * rad, span=70 * rad),
                                    seg(kind="dwell", start=150 * rad, span=210 * rad)])
    text = cam_phase(cam, r["linkage"], "en")
    ret = _return_span(1.8)
    assert f"{150.0 - ret:.2f}° after the next working stroke has begun" in text
    assert f"shorten it to at most {ret:.2f}°" in text
    zh = cam_phase(cam, r["linkage"], "zh")
    assert "应缩短到不大于" in zh and "shorten" not in zh
