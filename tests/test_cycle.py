"""Motion cycle diagram (mechdesign.core.cycle) and its brief section.

References: the lock-beam bender of seed 002 (main shaft 10 rpm, so T = 60/10 = 6 s; the
positioning cam's programme near dwell 170°, rise 60°, far dwell 70°, return 60°), with a
feed slider and a bending arm timed by hand; every slack below is worked out by hand from
the phase angles, every time from t = Δφ/360° × T.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from pydantic import ValidationError

from mechdesign.brief.cam import cam_to_si
from mechdesign.brief.components import CycleSection, cycle_to_si
from mechdesign.brief.loader import load_brief
from mechdesign.core import cycle as cy
from mechdesign.core.cam import Programme, Segment

R = np.radians
LOCKBEAM_CAM = Path(__file__).parents[1] / "designs" / "lockbeam_cam.yaml"
W10 = 10 * 2 * np.pi / 60          # 10 rpm in rad/s


def pin(start=0.0):
    return cy.make_actuator("pin", "定位销", "positioning pin", R(start),
                            [("dwell_low", R(170)), ("rise", R(60)), ("dwell_high", R(70)),
                             ("return", R(60))])


def feed():
    return cy.make_actuator("feed", "送料滑块", "feed slider", 0.0,
                            [("rise", R(90)), ("return", R(70)), ("dwell_low", R(200))])


def bender(start=235.0):
    return cy.make_actuator("bender", "扳弯架", "bending arm", R(start),
                            [("rise", R(30), "扳弯", "bend"), ("return", R(30)), ("dwell_low", R(300))])


def lockbeam(constraints=(), origin=0.0):
    return cy.build_cycle([feed(), pin(), bender()], W10, R(origin), constraints)


# --------------------------------------------------------------------------- coverage


def test_spans_must_cover_360_and_the_error_names_the_actuator():
    with pytest.raises(cy.CycleError, match=r"'pin'.*350°.*360°"):
        cy.make_actuator("pin", "定位销", "pin", 0.0, [("dwell_low", R(170)), ("rise", R(60)),
                                                     ("dwell_high", R(60)), ("return", R(60))])
    with pytest.raises(cy.CycleError, match=r"'feed'.*370°"):
        cy.build_cycle([("feed", "送料", "feed", 0.0, [("rise", R(190)), ("return", R(180))])], W10)


def test_bad_phases_are_errors():
    with pytest.raises(cy.CycleError, match="no phases"):
        cy.make_actuator("a", "甲", "a", 0.0, [])
    with pytest.raises(cy.CycleError, match="'jump' is not one of"):
        cy.make_actuator("a", "甲", "a", 0.0, [("jump", R(360))])
    with pytest.raises(cy.CycleError, match="positive"):
        cy.make_actuator("a", "甲", "a", 0.0, [("rise", R(400)), ("return", R(-40))])
    with pytest.raises(cy.CycleError, match="more than once"):
        cy.build_cycle([pin(), pin()], W10)
    with pytest.raises(cy.CycleError, match="positive"):
        cy.build_cycle([pin()], 0.0)


def test_degree_rounding_is_closed_exactly():
    a = cy.make_actuator("a", "甲", "a", R(10), [("rise", R(100.0)), ("dwell", R(260.0))])
    assert sum(p.span for p in a.phases) == pytest.approx(2 * np.pi, abs=1e-15)
    assert a.phases[1].start == pytest.approx(R(110), abs=1e-15)


# --------------------------------------------------------------------------- state_at


def test_state_at_boundaries_belongs_to_the_phase_that_starts_there():
    p = pin()
    eps = 1e-6
    angles = R(np.array([0.0, 170.0, 230.0, 300.0, 360.0]))
    assert list(cy.state_at(p, angles)) == ["dwell_low", "rise", "dwell_high", "return", "dwell_low"]
    assert list(cy.state_at(p, angles[1:] - eps)) == ["dwell_low", "rise", "dwell_high", "return"]
    assert cy.state_at(p, -eps) == "return"                        # just before 0 = just before 360°
    assert cy.state_at(p, R(720 + 200)) == "rise"                  # two turns later, 200°


def test_state_at_with_a_phase_through_zero_and_vectorised_shape():
    b = bender()            # rise 235–265, return 265–295, dwell_low 295–235 (through 0°)
    grid = R(np.array([[0.0, 234.999, 235.0], [264.0, 265.0, 294.9]]))
    states = cy.state_at(b, grid)
    assert states.shape == (2, 3)
    assert states.tolist() == [["dwell_low", "dwell_low", "rise"], ["rise", "return", "return"]]
    assert cy.moving_at(b, grid).tolist() == [[False, False, True], [True, True, True]]


def test_state_at_agrees_with_a_plain_loop_on_a_fine_grid():
    p = pin(start=37.0)
    phi = np.linspace(0, 4 * np.pi, 2001)
    edges = np.cumsum([0, 170, 60, 70, 60])
    names = ["dwell_low", "rise", "dwell_high", "return"]
    expected = []
    for x in np.degrees(phi):
        rel = (x - 37.0) % 360.0
        expected.append(names[int(np.searchsorted(edges, rel + 1e-7, side="right")) - 1])
    assert list(cy.state_at(p, phi)) == expected


def test_interval_of():
    p = pin()
    rise = cy.interval_of(p, "rise")
    assert (np.degrees(rise.start), np.degrees(rise.end)) == pytest.approx((170.0, 230.0))
    b = cy.make_actuator("t", "台", "table", 0.0, [("move", R(60)), ("dwell", R(120)),
                                                  ("move", R(60)), ("dwell", R(120))])
    with pytest.raises(cy.CycleError, match="2 'move' phases"):
        cy.interval_of(b, "move")
    assert np.degrees(cy.interval_of(b, "move", 2).start) == pytest.approx(180.0)
    with pytest.raises(cy.CycleError, match="occurrence 3"):
        cy.interval_of(b, "move", 3)
    with pytest.raises(cy.CycleError, match="no 'rise' phase"):
        cy.interval_of(b, "rise")


# --------------------------------------------------------------------------- times


def test_period_and_phase_durations_at_10_rpm():
    c = lockbeam()
    assert c.period == pytest.approx(6.0)
    assert c.speed_rpm == pytest.approx(10.0)
    rows = c.phase_times("pin")
    # (start time, duration): Δφ/360° × 6 s
    assert [x for _, t0, dt in rows for x in (t0, dt)] == pytest.approx(
        [0.0, 170 / 60, 170 / 60, 1.0, 230 / 60, 70 / 60, 5.0, 1.0])
    assert c.duration(R(90)) == pytest.approx(1.5)
    assert c.time_at(R(-30)) == pytest.approx(5.5)


# --------------------------------------------------------------------------- constraints


def test_constraint_slack_by_hand():
    cons = [
        # feed rise ends 90°, pin rise starts 170°: 170 − 90 − 5 = 75°
        cy.Constraint("before", ("feed", "rise"), ("pin", "rise"), R(5)),
        # bending 235–265 inside far dwell 230–300: min(5, 35) − 2 = 3°
        cy.Constraint("during", ("bender", "rise"), ("pin", "dwell_high"), R(2)),
        # bender returns by 295°, pin return starts 300°: 300 − 295 − 10 = −5°
        cy.Constraint("before", ("bender", "return"), ("pin", "return"), R(10)),
        # bender return 265–295 inside far dwell 230–300: min(35, 5) − 0 = 5°
        cy.Constraint("during", ("bender", "return"), ("pin", "dwell_high")),
    ]
    checks = cy.check_constraints(lockbeam(cons))
    assert [np.degrees(c.slack) for c in checks] == pytest.approx([75.0, 3.0, -5.0, 5.0])
    assert [c.ok for c in checks] == [True, True, False, True]
    con, ok, slack = checks[0]                        # unpacks as (constraint, ok, slack)
    assert con is cons[0] and ok


def test_during_slack_when_starting_a_little_early():
    # bending moved to 225–255: it starts 5° before the far dwell (230°): slack −5 (not −290)
    c = cy.build_cycle([pin(), bender(225.0)], W10, 0.0,
                       [cy.Constraint("during", ("bender", "rise"), ("pin", "dwell_high"))])
    (chk,) = cy.check_constraints(c)
    assert np.degrees(chk.slack) == pytest.approx(-5.0)
    assert not chk.ok


def test_before_is_read_from_the_origin():
    # pin return 300–360, feed rise 0–90: from φ = 0 the return is last (360 − 0 … not before);
    # from φ = 180° the window is 180 … 540 and the return ends exactly where the feed begins.
    con = [cy.Constraint("before", ("pin", "return"), ("feed", "rise"))]
    (at0,) = cy.check_constraints(cy.build_cycle([feed(), pin()], W10, 0.0, con))
    (at180,) = cy.check_constraints(cy.build_cycle([feed(), pin()], W10, R(180), con))
    assert np.degrees(at0.slack) == pytest.approx(-360.0)
    assert np.degrees(at180.slack) == pytest.approx(0.0, abs=1e-9)
    assert at180.ok and not at0.ok


def test_constraint_references_are_checked():
    with pytest.raises(cy.CycleError, match="no actuator 'arm'"):
        lockbeam([cy.Constraint("before", ("arm", "rise"), ("pin", "rise"))])
    with pytest.raises(cy.CycleError, match="'feed' has no 'dwell_high'"):
        lockbeam([cy.Constraint("during", ("feed", "dwell_high"), ("pin", "rise"))])
    with pytest.raises(cy.CycleError, match="kind"):
        cy.Constraint("after", ("feed", "rise"), ("pin", "rise"))


# --------------------------------------------------------------------------- cams


def test_cycle_matches_the_lockbeam_cam_programme():
    cam = cam_to_si(load_brief(LOCKBEAM_CAM).cam)
    from_cam = cy.actuator_from_cam_programme("pin", "定位销", "pin", cam.programme, start=0.0)
    assert [p.state for p in from_cam.phases] == ["dwell_low", "rise", "dwell_high", "return"]
    assert cy.timing_disagreement(pin(), from_cam) == pytest.approx(0.0, abs=1e-12)
    # keyed 5° late: each of the 4 boundaries is 5° off → 20° of shaft angle disagree
    late = cy.actuator_from_cam_programme("pin", "定位销", "pin", cam.programme, start=R(5))
    assert np.degrees(cy.timing_disagreement(pin(), late)) == pytest.approx(20.0)


def test_cam_forms_accepted_and_intermediate_dwell():
    segs = [Segment("rise", R(60), "cycloidal", 0.005), Segment("dwell", R(30)),
            Segment("rise", R(60), "cycloidal", 0.005), Segment("dwell", R(90)),
            Segment("return", R(60), "poly345"), Segment("dwell", R(60))]
    prog = Programme(segs, 0.010)
    for form in (prog, segs):
        a = cy.actuator_from_cam_programme("c", "凸轮", "cam", form, R(100))
        assert [p.state for p in a.phases] == ["rise", "dwell", "rise", "dwell_high", "return",
                                               "dwell_low"]
        assert np.degrees(a.phases[1].start) == pytest.approx(160.0)
    pairs = cy.actuator_from_cam_programme("c", "凸轮", "cam", [("dwell", R(170)), ("rise", R(60)),
                                                              ("dwell", R(70)), ("return", R(60))])
    assert cy.timing_disagreement(pin(), pairs) == pytest.approx(0.0, abs=1e-12)
    with pytest.raises(cy.CycleError, match="300°"):
        cy.actuator_from_cam_programme("c", "凸轮", "cam", [("rise", R(150)), ("return", R(150))])


def test_disagreement_by_motion_only():
    generic = cy.make_actuator("pin", "定位销", "pin", 0.0, [("dwell", R(170)), ("move", R(60)),
                                                           ("dwell", R(70)), ("move", R(60))])
    assert np.degrees(cy.timing_disagreement(pin(), generic)) == pytest.approx(360.0)
    assert cy.timing_disagreement(pin(), generic, by="motion") == pytest.approx(0.0, abs=1e-12)


# --------------------------------------------------------------------------- brief section


def section(**over):
    data = {"shaft_speed_rpm": 10, "actuators": [
        {"key": "feed", "name_zh": "送料滑块", "name_en": "feed slider",
         "phases": [{"state": "rise", "span_deg": 90}, {"state": "return", "span_deg": 70},
                    {"state": "dwell_low", "span_deg": 200}]},
        {"key": "pin", "name_zh": "定位销", "name_en": "positioning pin",
         "phases": [{"state": "dwell_low", "span_deg": 170}, {"state": "rise", "span_deg": 60},
                    {"state": "dwell_high", "span_deg": 70}, {"state": "return", "span_deg": 60}]}],
        "constraints": [{"kind": "before", "a": {"actuator": "feed", "state": "rise"},
                         "b": {"actuator": "pin", "state": "rise"}, "margin_deg": 5}]}
    data.update(over)
    return data


def test_section_converts_to_the_same_diagram():
    c = cycle_to_si(CycleSection.model_validate(section()))
    assert c.shaft_speed == pytest.approx(W10)
    assert cy.timing_disagreement(c.actuator("pin"), pin()) == pytest.approx(0.0, abs=1e-12)
    (chk,) = cy.check_constraints(c)
    assert np.degrees(chk.slack) == pytest.approx(75.0)
    # the machine supplies the speed when the section has none
    d = section()
    del d["shaft_speed_rpm"]
    assert cycle_to_si(CycleSection.model_validate(d), 20.0).period == pytest.approx(3.0)
    with pytest.raises(ValueError, match="shaft_speed_rpm"):
        cycle_to_si(CycleSection.model_validate(d))


def test_section_errors_name_the_place():
    bad = section()
    bad["actuators"][1]["phases"][0]["span_deg"] = 160
    with pytest.raises(ValidationError) as exc:
        CycleSection.model_validate(bad)
    err = exc.value.errors()[0]
    assert err["loc"] == ("actuators", 1, "phases", 3, "span_deg")     # was: ("actuators", 1)
    assert "'pin'" in err["msg"] and "350°" in err["msg"]

    bad = section(constraints=[{"kind": "before", "a": {"actuator": "feed", "state": "dwell_high"},
                                "b": {"actuator": "pin", "state": "rise"}}])
    with pytest.raises(ValidationError, match=r"actuator 'feed' has no 'dwell_high'") as exc:
        CycleSection.model_validate(bad)
    # the path was written into the text; it is now the error's location
    assert exc.value.errors()[0]["loc"] == ("constraints", 0, "a", "state")
    bad = section(constraints=[{"kind": "before", "a": {"actuator": "arm", "state": "rise"},
                                "b": {"actuator": "pin", "state": "rise"}}])
    with pytest.raises(ValidationError, match="no actuator 'arm'; actuators: feed, pin"):
        CycleSection.model_validate(bad)
    bad = section()
    bad["actuators"][1]["key"] = "feed"
    with pytest.raises(ValidationError, match="more than once"):
        CycleSection.model_validate(bad)
    bad = section()
    bad["actuators"][0]["phases"][0]["state"] = "jump"
    with pytest.raises(ValidationError):
        CycleSection.model_validate(bad)


def test_a_brief_may_use_the_states_work_and_clear():
    """The die-cutter's platen (a crank-driven output that never stops) is drawn in the
    windows work (工作区运动: near its working end) and clear (让开区运动); a user's brief may
    name them too (issue 19: the brief offered only rise … dwell). Both are motions: a
    "during" constraint against a dwell reads them as such, and they are named in each
    language as the core's catalogue names them."""
    from mechdesign.i18n import tr

    d = section()
    d["actuators"].append({"key": "platen", "name_zh": "压板", "name_en": "platen", "start_deg": 240,
                           "phases": [{"state": "work", "span_deg": 40},
                                      {"state": "clear", "span_deg": 320}]})
    d["constraints"] = [{"kind": "during", "a": {"actuator": "platen", "state": "work"},
                         "b": {"actuator": "pin", "state": "dwell_high"}, "margin_deg": 5}]
    c = cycle_to_si(CycleSection.model_validate(d))
    platen = c.actuator("platen")
    assert [p.state for p in platen.phases] == ["work", "clear"]
    assert all(p.moving for p in platen.phases)
    # the pin holds from 170 + 60 = 230° to 300°, the work window is 240°–280°: 10° after
    # the hold begins, 20° before it ends; less the 5° margin the slack is 5°
    (chk,) = cy.check_constraints(c)
    assert chk.ok and np.degrees(chk.slack) == pytest.approx(5.0)
    assert cy.STATES["work"].name("zh") == "工作区运动" and cy.STATES["clear"].name("en") == "moving, clear zone"
    assert tr("zh").pgettext("cycle state", "moving, clear zone") == "让开区运动"


def test_document():
    c = lockbeam([cy.Constraint("before", ("feed", "rise"), ("pin", "rise"), R(5))])
    doc = cy.cycle_document(c)
    assert doc.period == pytest.approx(6.0)
    assert doc.actuators[1].phases[1].duration == pytest.approx(1.0)
    assert doc.constraints[0].a == "feed.rise" and doc.constraints[0].ok is True


def _cam_section(motion, segments, stroke=40.0):
    from mechdesign.brief.cam import CamSection
    follower = ({"motion": "translating", "contact": "roller", "stroke_h_mm": stroke,
                 "roller_radius_mm": 5}
                if motion == "translating" else
                {"motion": "oscillating", "contact": "roller", "max_swing_deg": stroke,
                 "pivot_distance_mm": 80,
                 "arm_length_mm": 60, "roller_radius_mm": 5})
    unit = "lift_mm" if motion == "translating" else "lift_deg"
    prog = []
    for kind, span, lift in segments:
        seg = {"motion": kind, "angle_deg": span}
        if kind != "dwell":
            seg["law"] = "poly345"
            if lift is not None:
                seg[unit] = lift
        prog.append(seg)
    return CamSection(follower=follower, programme=prog, base_radius_mm=50, speed_rpm=60)


@pytest.mark.parametrize("motion, segments", [
    ("translating", [("rise", 120, None), ("dwell", 60, None), ("return", 120, None),
                     ("dwell", 60, None)]),
    ("oscillating", [("rise", 90, 20), ("dwell", 30, None), ("rise", 60, 20),
                     ("dwell", 30, None), ("return", 100, None), ("dwell", 50, None)]),
    ("translating", [("dwell", 100.5, None), ("rise", 80.25, 30), ("dwell", 20, None),
                     ("return", 80.25, 15), ("dwell", 30, None), ("rise", 20, 25),
                     ("return", 29, None)]),
])
def test_follower_phases_in_the_brief_match_the_engine(motion, segments):
    """The validator's plain-arithmetic phases (brief.cam.follower_phases_deg) agree with the
    engine's cycle-diagram actuator built from the cam's Programme: same states (a dwell at
    the bottom, at the stroke, in between) and the same spans."""
    from mechdesign.brief.cam import follower_phases_deg
    section = _cam_section(motion, segments)
    mine = follower_phases_deg(section)
    act = cy.actuator_from_cam_programme("x", "", "", cam_to_si(section).programme, 0.0)
    assert [s for s, _ in mine] == [p.state for p in act.phases]
    assert np.allclose([w for _, w in mine], np.degrees([p.span for p in act.phases]),
                       rtol=0, atol=1e-9)
    assert {s for s, _ in mine} >= ({"dwell_low"} if motion == "translating" else set())
