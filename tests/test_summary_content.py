"""The summary states what the results hold: a linkage analysis is "kinetostatic" only when
forces (joint reactions) were computed; the crank angles a brief asks for get their answers
(the output link's ω, α and the requested points' v, a) in the key results."""
from __future__ import annotations



from mechdesign.render.summary import key_rows, summary_context


def _linkage(reactions):
    return {"output": {"kind": "link", "name": "4", "unit": "rad", "stroke": 0.5},
            "time_ratio": 1.5,
            "positions": [{"label": "1", "link_omega": {"4": 0.0}, "link_alpha": {"4": 1.0},
                           "reactions": reactions},
                          {"label": "φ45", "link_omega": {"4": 1.25}, "link_alpha": {"4": -7.5},
                           "reactions": reactions}]}


def test_no_forces_computed_means_kinematic_analysis_only():
    parts = summary_context("linkage", {"linkage": _linkage({})}, {}, "en", "t")["parts"]
    assert parts == ["kinematic analysis"]
    parts = summary_context("linkage", {"linkage": _linkage({"R12": [1.0, 2.0]})}, {}, "en",
                            "t")["parts"]
    assert parts == ["kinematic and kinetostatic analysis"]
    parts = summary_context("linkage", {"linkage": _linkage({})}, {}, "zh", "t")["parts"]
    assert parts == ["机构运动分析"]


def test_the_asked_crank_angle_gets_its_answers_in_the_key_results():
    doc = {"linkage": _linkage({}),
           "analysis_requests": {
               "positions": [{"asked": "φ45", "label": "φ45"},
                             {"asked": "link_vertical:4", "label": "1"}],   # an event: not
               "points": [{"name": "D", "positions": [
                   {"label": "φ45", "velocity": 0.75, "acceleration": 2.5},
                   {"label": "1", "velocity": 9.0, "acceleration": 9.0}]}]}}
    rows = {r[0]: (r[1], r[2]) for r in key_rows("linkage", doc, "en")}
    # 4 significant digits with their trailing zeros, as the body writes a speed (review33)
    assert rows["$\\omega_{4}$ at position φ45"] == ("1.250", "rad/s")
    assert rows["$\\alpha_{4}$ at position φ45"] == ("-7.500", "rad/s²")
    assert rows["$v_{D}$ at position φ45"] == ("0.7500", "m/s")
    assert rows["$a_{D}$ at position φ45"] == ("2.500", "m/s²")
    assert not any("position 1" in k for k in rows)


def test_crank_rocker_key_rows_name_their_mechanism():
    """Each key-results row of the crank-rocker report says which of its two designs it is."""
    from mechdesign.registry import entry

    rows = entry("crank_rocker").summary
    assert all(r[0].startswith(("crank-rocker:", "offset slider-crank:")) for r in rows)
    stroke = [r for r in rows if r[2].endswith(".stroke")]
    assert stroke and all(r[0].startswith("offset slider-crank:") for r in stroke)
    k_rows = {r[2]: r[0] for r in rows if r[0].endswith("time ratio K")}
    assert k_rows["slider_crank.K"].startswith("offset slider-crank:")
    assert k_rows["linkage.time_ratio"].startswith("crank-rocker:")


def test_the_crank_pin_is_not_a_key_answer():
    """The textbook exercise asks for B, D, S4 at φ1 = 45°: B is the crank pin, whose speed
    ωr and acceleration ω²r are the same at every position (given data, not results), so
    the key results give ω4, α4 and the bar's points only. A point whose speed is constant
    but whose acceleration is not (no uniform circular motion) stays."""
    def point(name, v, a, grid_v, grid_a):
        return {"name": name, "positions": [{"label": "φ45", "velocity": v, "acceleration": a}],
                "grid_velocity": grid_v, "grid_acceleration": grid_a}

    w, r = 10.0, 0.03                   # ω1 = 10 rad/s, l_AB = 30 mm: v_B = 0.3, a_B = 3
    doc = {"linkage": _linkage({}),
           "analysis_requests": {
               "positions": [{"asked": "φ45", "label": "φ45"}],
               "points": [point("B", w * r, w * w * r, [w * r] * 8, [w * w * r * (1 + 1e-15)] * 8),
                          point("D", 0.2993, 1.397, [0.0, 0.3, 0.64, 0.2], [1.0, 1.4, 3.0, 0.9]),
                          point("E", 0.5, 0.7, [0.5] * 4, [0.7, 0.8, 0.7, 0.6])]}}
    rows = {r_[0]: r_[1] for r_ in key_rows("linkage", doc, "en")}
    assert "$\\omega_{4}$ at position φ45" in rows and "$\\alpha_{4}$ at position φ45" in rows
    assert rows["$v_{D}$ at position φ45"] == "0.2993" and rows["$a_{D}$ at position φ45"] == "1.397"
    assert "$v_{E}$ at position φ45" in rows
    assert not [k for k in rows if "_{B}" in k], rows
