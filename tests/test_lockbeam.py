"""Lock-beam bender (seed 002): every number checked against an independent reference —
closed forms worked by hand, a separate numerical solution of the loop equation, the
Assur-group simulation, finite differences — never against the program's own output."""
from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import yaml
from scipy.optimize import brentq
from typer.testing import CliRunner

from mechdesign.brief.loader import BriefError, parse_brief
from mechdesign.cli import app
from mechdesign.core import cycle as cy
from mechdesign.core import rocker_synthesis as rs
from mechdesign.core.fourbar import SynthesisError
from mechdesign.core.mechanism import RRR, Crank, Mechanism
from mechdesign.machines import get_machine

ROOT = Path(__file__).resolve().parents[1]
BRIEF = ROOT / "designs" / "lockbeam.yaml"
DEG = np.pi / 180


def _data():
    return yaml.safe_load(BRIEF.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def run(example_results):
    return example_results("lockbeam")                   # = parse_brief(_data()), computed


def _output_by_root_finding(d, a, b, c, alpha, beta_guess):
    """β with |a e^{iα} − (d + c e^{iβ})| = b, solved by Brent's method near a guess: an
    independent solution of the loop equation (no closed form, no Assur groups)."""
    A = a * np.exp(1j * alpha)

    def g(beta):
        return abs(A - (d + c * np.exp(1j * beta))) - b

    lo, hi = beta_guess - 0.05, beta_guess + 0.05
    return brentq(g, lo, hi, xtol=1e-14)


# ----------------------------------------------------------------------------- synthesis


def test_parallelogram_is_reproduced():
    """Equal swings from equal start angles: the textbook parallelogram, a = c, b = d."""
    a, b = rs.two_position(0.2, 0.05, 0.7, 0.3, 0.7, 0.3)
    assert a == pytest.approx(0.05, rel=1e-12)
    assert b == pytest.approx(0.2, rel=1e-12)


def test_two_position_closes_both_loops_and_matches_inversion():
    d, c = 0.2, 0.04
    a1, da, b1, db = np.radians(300.0), np.radians(24.4), np.radians(150.0), np.radians(-50.0)
    a, b = (float(x) for x in rs.two_position(d, c, a1, da, b1, db))
    for al, be in ((a1, b1), (a1 + da, b1 + db)):
        assert abs(a * np.exp(1j * al) - (d + c * np.exp(1j * be))) == pytest.approx(b, rel=1e-12)
    # Inversion (刚化反转法): A1 is equidistant from B1 and from B2 turned back by −Δα about A0.
    B1 = d + c * np.exp(1j * b1)
    B2r = (d + c * np.exp(1j * (b1 + db))) * np.exp(-1j * da)
    A1 = a * np.exp(1j * a1)
    assert abs(A1 - B1) == pytest.approx(abs(A1 - B2r), rel=1e-12)


def test_design_is_reproduced_by_assur_group_simulation():
    """The synthesised four-bar, solved by core.mechanism (crank unit + RRR dyad) and by
    root-finding on the loop equation, turns the output exactly Δβ."""
    d, c, da, db = 0.2, 0.04, np.radians(24.398), np.radians(-50.0)
    ds = rs.design_two_position(d, c, np.radians(296.0), da, np.radians(148.7), db)
    mech = Mechanism("1", {"A0": 0j, "B0": complex(d, 0)})
    mech.add(Crank("in", "2", "A0", "A", ds.input_rocker, 1.0))
    mech.add(RRR("out", "3", "4", "A", "B0", "B", ds.coupler, c, ds.branch))
    alpha = ds.alpha1 + da * np.linspace(0, 1, 201)
    m = mech.solve(alpha)
    beta = np.unwrap(m.links["4"].angle)
    assert np.angle(np.exp(1j * (beta[0] - ds.beta1))) == pytest.approx(0, abs=1e-12)
    assert beta[-1] - beta[0] == pytest.approx(db, abs=1e-10)
    # independent: Brent on |A − B| = b at a few input angles
    for j in (0, 57, 133, 200):
        ref = _output_by_root_finding(d, ds.input_rocker, ds.coupler, c, alpha[j], beta[j])
        assert ref == pytest.approx(beta[j], abs=1e-11)
    # velocity ratio formula against the mechanism's ω4 (input ω = 1) and finite differences
    sw = rs.sweep(ds, alpha=alpha)
    assert np.allclose(sw.ratio, m.links["4"].omega, rtol=1e-9, atol=1e-12)
    fd = np.gradient(beta, alpha)
    assert np.allclose(sw.ratio[1:-1], fd[1:-1], rtol=1e-3)


def test_infeasible_start_is_an_error_naming_the_start():
    with pytest.raises(SynthesisError, match="start"):
        # both rockers turning through the same arc far from each other: no positive a
        rs.design_two_position(0.2, 0.04, np.radians(90.0), np.radians(10.0), np.radians(90.0),
                               np.radians(-60.0))


def test_best_start_meets_its_constraints_and_is_locally_optimal():
    d, c, da, db = 0.2, 0.04, np.radians(24.398), np.radians(-50.0)
    limit = 1.05 * abs(db) / da
    ds, g = rs.best_start(d, c, da, db, (0.02, 0.3), limit)
    sw = rs.sweep(ds, 2001)
    assert sw.swing == pytest.approx(db, abs=1e-9)
    assert sw.ratio_peak <= limit * (1 + 1e-6)
    assert 0.02 <= ds.input_rocker <= 0.3 and 0.02 <= ds.coupler <= 0.3
    assert g == pytest.approx(sw.gamma_min, abs=1e-6)
    # no feasible neighbour within ±0.05° is better (checked by an independent sweep)
    for dx in (-0.05, 0.05):
        for dy in (-0.05, 0.0, 0.05):
            try:
                nb = rs.design_two_position(d, c, ds.alpha1 + np.radians(dx), da,
                                            ds.beta1 + np.radians(dy), db)
            except SynthesisError:
                continue
            ns = rs.sweep(nb, 2001)
            if ns.ratio_peak <= limit and 0.02 <= nb.input_rocker <= 0.3 and 0.02 <= nb.coupler <= 0.3:
                assert ns.gamma_min <= sw.gamma_min + 1e-4


def test_seed_lengths_checked_by_simulation():
    """The seed's 90/150 mm: wherever check_lengths says the swing is 50°, a separate
    simulation from that start gives 50°; 90 + 150 = 40 + 200 (change point)."""
    d, c, da = 0.2, 0.04, np.radians(24.398)
    lc = rs.check_lengths(d, 0.09, 0.15, c, da, np.radians(50.0))
    assert lc.starts
    for a1, b1, _ in lc.starts:
        mech = Mechanism("1", {"A0": 0j, "B0": complex(d, 0)})
        mech.add(Crank("in", "2", "A0", "A", 0.09, 1.0))
        mech.add(RRR("out", "3", "4", "A", "B0", "B", 0.15, c, 1))
        beta = np.unwrap(mech.solve(a1 + da * np.linspace(0, 1, 301)).links["4"].angle)
        assert abs(beta[-1] - beta[0]) == pytest.approx(np.radians(50.0), abs=1e-9)
    assert lc.swing_range[0] < np.radians(50) < lc.swing_range[1]


# ----------------------------------------------------------------------------- the machine


def test_transmission_ratio_is_exactly_70(run):
    tr = run["transmission"]
    assert tr.ratio_exact == Fraction(70)
    assert tr.output_rpm == pytest.approx(10.0, rel=1e-15)
    # centre distances by hand: a = m (z1 + z2)/2
    assert tr.stages[1].pair.a == pytest.approx(0.006 * (18 + 90) / 2, rel=1e-12)
    assert tr.stages[2].pair.a == pytest.approx(0.006 * (18 + 126) / 2, rel=1e-12)
    assert not tr.warnings
    assert all(s.torque is None for s in tr.shafts)       # no power in the seed


def test_torques_when_the_power_is_given():
    data = _data()
    data["transmission"]["motor_power_kW"] = 1.5
    b = parse_brief(data)
    m = get_machine("lockbeam")
    p = m.to_params(b)
    from mechdesign.machines.lockbeam.stages import transmission

    tr = transmission(p)
    # main shaft: P = 1500 · 0.96 · 0.97², T = P / (2π·10/60)
    P = 1500 * 0.96 * 0.97 ** 2
    assert tr.shafts[-1].power == pytest.approx(P, rel=1e-12)
    assert tr.shafts[-1].torque == pytest.approx(P / (2 * np.pi * 10 / 60), rel=1e-12)


def test_bending_wheel_turns_180_by_simulation(run):
    b = run["bending"]
    # wheel swing 180° × 40/144 = 50° by the Assur-group simulation
    assert abs(b.swing_simulated) == pytest.approx(np.radians(50.0), abs=1e-10)
    # the whole chain cam → rocker → four-bar → chain: 180° at the far dwell
    assert b.bend_simulated == pytest.approx(np.pi, abs=1e-9)
    # independent: input angle from the cam programme, output by root-finding on the loop
    p = run["params"]
    prog = run["bending_cam"].params.programme
    far = prog.starts[2] + 0.5 * prog.spans[2]              # middle of the far dwell
    phi = p.bend_cam_start + far
    psi = float(prog.evaluate(np.array([far])).s[0])
    # the cycle drives the four-bar as drawn (rounded lengths, same input start)
    ds, rc = b.design, b.rounded
    beta1 = _output_by_root_finding(ds.frame, rc.input_rocker, rc.coupler, ds.output_rocker,
                                    ds.alpha1, ds.beta1)
    beta = beta1
    for al in ds.alpha1 + psi * np.linspace(0.0, 1.0, 201)[1:]:
        beta = _output_by_root_finding(ds.frame, rc.input_rocker, rc.coupler, ds.output_rocker,
                                       al, beta)
    assert b.ratio * abs(beta - beta1) == pytest.approx(np.pi, abs=1e-9)
    assert np.isfinite(phi)
    assert b.gamma_min >= np.radians(40.0)
    # wheel speed against central differences of the wheel angle (smooth parts)
    assert b.fd_velocity < 1e-3 and b.fd_acceleration < 1e-3


def test_bending_cam_swing_is_what_the_drawn_lengths_need(run):
    """small34: the four-bar is synthesised for the brief's swing 24.398° (the seed's
    14.904 mm / 35 mm), but it is built with its lengths rounded (a = 80, b = 161 mm), which
    bend only 179.82° with that swing. The bending cam is designed for the swing the drawn
    lengths need for exactly 180°, found here independently: the wheel swing by root-finding
    on the loop equation marched along the input swing, and that swing solved by Brent's
    method for a bend of 180°."""
    b = run["bending"]
    ds, rc = b.design, b.rounded
    target = np.pi / b.ratio                                    # 50° of the large wheel

    def miss(x):
        return _swing_by_marching(ds.frame, rc.input_rocker, rc.coupler, ds.output_rocker,
                                  ds.alpha1, x, ds.beta1, n=200) - target

    needed = brentq(miss, np.radians(20.0), np.radians(30.0), xtol=1e-13)
    stroke = run["bending_cam"].params.programme.stroke
    assert stroke == pytest.approx(needed, abs=1e-9)
    assert np.degrees(stroke) == pytest.approx(24.42, abs=0.005)
    # the synthesis keeps the brief's swing; with it the drawn lengths bend short of 180°
    assert abs(ds.dalpha) == pytest.approx(np.radians(24.398), abs=1e-12)
    assert b.ratio * _swing_by_marching(ds.frame, rc.input_rocker, rc.coupler, ds.output_rocker,
                                        ds.alpha1, ds.dalpha, ds.beta1) < np.pi - np.radians(0.1)
    # the cam's table and both of its motion segments reach that swing
    lifts = [s.lift for s in run["bending_cam"].params.programme.segments if s.lift is not None]
    assert all(lift == pytest.approx(stroke, abs=1e-15) for lift in lifts)


def _swing_by_marching(d, a, b, c, alpha1, dalpha, beta_guess, n=400):
    """|Δβ| of lengths a, b over the input swing, marching the root-finding solution from
    the start (None when the linkage does not assemble along the way)."""
    A = a * np.exp(1j * alpha1)

    def g(beta):
        return abs(A - (d + c * np.exp(1j * beta))) - b

    grid = beta_guess + np.linspace(-np.pi, np.pi, 3601)
    vals = np.array([g(x) for x in grid])
    roots = [brentq(g, grid[i], grid[i + 1], xtol=1e-14)
             for i in np.nonzero(vals[:-1] * vals[1:] < 0)[0]]
    if not roots:
        return None
    try:
        beta = min(roots, key=lambda x: abs(x - beta_guess))     # the same assembly branch
        beta0 = beta
        for al in alpha1 + dalpha * np.linspace(0.0, 1.0, n)[1:]:
            beta = _output_by_root_finding(d, a, b, c, al, beta)
    except ValueError:
        return None
    return abs(beta - beta0)


@pytest.mark.parametrize("step_mm", [0.5, 1.0, 2.0, 5.0])
def test_drawn_lengths_never_a_change_point(run, step_mm):
    """Brute force over the four floor/ceiling roundings of a and b: the drawn pair keeps
    s + l < p + q (the synthesis is Grashof) by at least half a step, and of those that do, it
    misses the required wheel swing least (swing by independent root-finding)."""
    from mechdesign.machines.lockbeam.stages import rounded_check

    ds, ratio = run["bending"].design, run["bending"].ratio
    step = step_mm * 1e-3
    target = abs(ds.dbeta)

    def margin(*lengths):
        s_, p_, q_, l_ = sorted(lengths)
        return (p_ + q_) - (s_ + l_)

    assert margin(ds.input_rocker, ds.coupler, ds.output_rocker, ds.frame) > 0
    best, best_err = None, np.inf
    for a in (np.floor(ds.input_rocker / step) * step, np.ceil(ds.input_rocker / step) * step):
        for b in (np.floor(ds.coupler / step) * step, np.ceil(ds.coupler / step) * step):
            if margin(a, b, ds.output_rocker, ds.frame) < 0.5 * step - 1e-12:
                continue
            sw = _swing_by_marching(ds.frame, a, b, ds.output_rocker, ds.alpha1, ds.dalpha, ds.beta1)
            if sw is not None and abs(sw - target) < best_err:
                best, best_err = (a, b), abs(sw - target)
    rc = rounded_check(ds, step, ratio)
    assert best is not None and rc is not None
    assert (rc.input_rocker, rc.coupler) == pytest.approx(best, abs=1e-12)
    assert rc.margin == pytest.approx(margin(*best, ds.output_rocker, ds.frame), abs=1e-12)
    assert rc.margin >= 0.5 * step - 1e-12
    assert abs(rc.swing - target) == pytest.approx(best_err, abs=1e-7)


def test_example_drawn_lengths(run):
    """The example's synthesis has a + b only 0.38 mm over s + l = 240 mm: plain rounding to
    80/160 mm would make s + l = p + q (a change-point linkage); the drawn lengths do not."""
    rc = run["bending"].rounded
    assert rc.nearest is not None
    a0, b0, m0 = rc.nearest
    assert (a0, b0) == pytest.approx((0.080, 0.160), abs=1e-12) and abs(m0) < 1e-12
    assert rc.input_rocker + rc.coupler > 0.040 + 0.200 + 0.5e-3


def test_cycle_diagram_matches_the_cams(run):
    """Sample both cams along the main shaft: near dwell ⇒ follower down, far dwell ⇒ up,
    rise ⇒ rising, return ⇒ falling, exactly where the brief's cycle diagram says."""
    p, c = run["params"], run["cycle"]
    acts = {a.key: a for a in c.diagram.actuators}
    phi = np.linspace(0, 2 * np.pi, 7201)[:-1] + 1e-7
    for key, cam, start in (("pin", run["cam"], p.pin_cam_start),
                            ("bend", run["bending_cam"], p.bend_cam_start)):
        prog = cam.params.programme
        fm = prog.evaluate(phi - start)
        states = cy.state_at(acts[key], phi)
        assert np.all(np.abs(fm.s[states == "dwell_low"]) < 1e-15)
        assert np.all(np.abs(fm.s[states == "dwell_high"] - prog.stroke) < 1e-12 * prog.stroke)
        assert np.all(fm.ds[states == "rise"] >= 0) and np.all(fm.ds[states == "return"] <= 0)
        inner = (states == "rise") & (fm.s > 1e-6 * prog.stroke) & (fm.s < (1 - 1e-6) * prog.stroke)
        assert np.all(fm.ds[inner] > 0)
    assert all(ch.ok for ch in c.checks)
    # the pin is fully up whenever the bending wheel moves (simulation of both)
    assert c.pin_lift_while_bending == pytest.approx(0.010, abs=1e-15)


def test_feed_stroke_and_K_against_closed_forms(run):
    """Guide bar: θ = 2 arcsin(50/100) = 60° ⇒ K = 240/120 = 2; symmetric layout ⇒
    H = 2·250·50/100 = 250 mm. The feed takes 240° of the main shaft."""
    k = run["feed"]
    assert k.time_ratio == pytest.approx(2.0, abs=1e-9)
    assert k.stroke == pytest.approx(0.250, abs=1e-12)
    assert k.working_span == pytest.approx(np.radians(240.0), abs=1e-9)
    assert run["cycle"].feed_span_simulated == pytest.approx(run["cycle"].feed_span_cycle, abs=1e-9)


def test_feed_positions_by_hand(run):
    """Two of the seed's positions worked by hand. φ1 = 90°: A = (0, 50), the bar is
    vertical, D = (0, 150), E = 0 + √(80² − 6.7²). φ1 = 0°: A = (50, 0), the bar's direction
    (50, 100)/√12500, D = O3 + 250·that, E = x_D + √(80² − (156.7 − y_D)²)."""
    ft = run["feed_table"]
    i90 = int(np.argmin(np.abs(ft.crank_angle - np.pi / 2)))
    assert ft.x[i90] == pytest.approx(np.sqrt(0.08 ** 2 - 0.0067 ** 2), abs=1e-12)
    u = np.array([0.05, 0.10]) / np.hypot(0.05, 0.10)
    xd, yd = 0.25 * u[0], -0.1 + 0.25 * u[1]
    assert ft.x[0] == pytest.approx(xd + np.sqrt(0.08 ** 2 - (0.1567 - yd) ** 2), abs=1e-12)
    # the seed's abs() is wrong exactly where the slider is left of x = 0
    assert np.array_equal(np.abs(ft.seed_x - ft.x) > 1e-12, ft.x < 0)


def test_pin_lift_requirement(run):
    pc = run["pin_check"]
    assert pc.required == pytest.approx((0.010 - 0.007) / 2, abs=1e-15)
    assert pc.lift > pc.required and not pc.warnings


# ----------------------------------------------------------------------------- bad input


def _invoke(tmp_path, data, *extra):
    tmp_path.mkdir(parents=True, exist_ok=True)
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    return CliRunner().invoke(app, ["run", str(path), "-o", str(tmp_path / "out"), "-f", "md", *extra])


def test_cycle_that_differs_from_the_cam_is_rejected():
    data = _data()
    pin = next(a for a in data["cycle"]["actuators"] if a["key"] == "pin")
    pin["phases"][0]["span_deg"] = 160
    pin["phases"][2]["span_deg"] = 80
    with pytest.raises(BriefError) as exc:
        parse_brief(data)
    text = str(exc.value)
    assert "cycle.actuators" in text and "cam.programme" in text


def test_members_of_the_main_shaft_turn_one_way():
    """The feed crank and both cams are keyed on the one main shaft: the example gives them
    one sense, and a brief that turns any of them the other way is refused naming both fields."""
    data = _data()
    senses = {data["feed_linkage"]["crank"]["rotation"], data["cam"]["rotation"],
              data["bending_cam"]["rotation"]}
    assert len(senses) == 1
    for section in ("cam", "bending_cam"):
        d = _data()
        d[section]["rotation"] = "cw" if d[section]["rotation"] == "ccw" else "ccw"
        with pytest.raises(BriefError) as exc:
            parse_brief(d)
        text = str(exc.value)
        assert f"{section}.rotation" in text and "feed_linkage.crank.rotation" in text, text
    d = _data()
    d["feed_linkage"]["crank"]["rotation"] = "cw"          # against both cams: two problems
    with pytest.raises(BriefError) as exc:
        parse_brief(d)
    text = str(exc.value)
    assert "cam.rotation" in text and "bending_cam.rotation" in text, text


def test_bad_inputs_exit_2_naming_the_field(tmp_path):
    cases = []
    d = _data()
    d["feed_linkage"]["crank"]["speed_rpm"] = 12
    cases.append((d, "feed_linkage.crank.speed_rpm"))
    d = _data()
    d["bending"]["link_length_range_mm"] = [20, 25]
    cases.append((d, "bending"))
    d = _data()
    d["cam"]["follower"] = {"motion": "oscillating", "contact": "roller", "roller_radius_mm": 5,
                            "max_swing_deg": 10, "arm_length_mm": 30, "pivot_distance_mm": 60}
    cases.append((d, "cam.follower.motion"))
    d = _data()
    d["bending"]["bending_wheel_diameter_mm"] = 160
    cases.append((d, "driving_wheel_diameter_mm"))
    d = _data()
    d["cycle"]["actuators"] = [a for a in d["cycle"]["actuators"] if a["key"] != "bend"]
    d["cycle"]["constraints"] = []
    cases.append((d, "'bend'"))
    d = _data()
    d["bending_cam"]["rotation"] = "cw" if d["bending_cam"]["rotation"] == "ccw" else "ccw"
    cases.append((d, "feed_linkage.crank.rotation"))
    for i, (data, field) in enumerate(cases):
        res = _invoke(tmp_path / str(i), data)
        assert res.exit_code == 2, res.output
        assert field in res.output, res.output
        assert "Traceback" not in res.output


@pytest.mark.e2e
def test_small_pin_lift_is_a_warning_not_an_error(tmp_path):
    d = _data()
    d["cam"]["follower"]["stroke_h_mm"] = 1.2
    res = _invoke(tmp_path, d)
    assert res.exit_code == 0, res.output
    assert "groove" in res.output or "槽" in res.output


@pytest.mark.e2e
def test_english_report_and_gif(tmp_path):
    res = CliRunner().invoke(app, ["run", str(BRIEF), "-o", str(tmp_path / "en"), "--lang", "en",
                                   "-f", "md,gif"])
    assert res.exit_code == 0, res.output
    md = (tmp_path / "en" / "report.md").read_text(encoding="utf-8")
    assert "Bending mechanism" in md and "Motion cycle diagram" in md
    assert (tmp_path / "en" / "animation.gif").stat().st_size > 1000
    assert (tmp_path / "en" / "bending_cam_profile.csv").exists()


def test_summary_and_checks_state_the_linkage_as_drawn(run):
    """review33: the summary gave "bend (simulated) 180.00°, γmin 64.26°" of the unrounded
    synthesis while the drawn and built linkage (a = 80, b = 161 mm) bends less; "大链轮摆角
    −50.00°（要求 50.00°）" read as a failure; the check table printed 180.0000. The summary
    names the drawn a, b and states their bend and γ_min, here found independently: the
    drawn lengths' wheel swing by root-finding along the input swing, times the chain ratio;
    γ_min from the triangle G B B0 at the swing's positions."""
    from mechdesign.render.summary import key_rows
    from mechdesign.results import to_plain
    from tests.test_report_prose import _markdown

    b = run["bending"]
    ds, rc = b.design, b.rounded
    a_, b_ = rc.input_rocker, rc.coupler
    # small34: the bending cam is designed for the drawn lengths' swing (its stroke)
    dalpha = run["bending_cam"].params.programme.stroke
    swing = _swing_by_marching(ds.frame, a_, b_, ds.output_rocker, ds.alpha1, dalpha, ds.beta1)
    bend = b.ratio * swing
    short = b.ratio * _swing_by_marching(ds.frame, a_, b_, ds.output_rocker, ds.alpha1,
                                         ds.dalpha, ds.beta1)
    assert abs(short - np.pi) > np.radians(0.05)   # with the synthesis's swing it bends short
    beta = ds.beta1
    gmin = np.inf
    for al in ds.alpha1 + dalpha * np.linspace(0.0, 1.0, 2001):
        beta = _output_by_root_finding(ds.frame, a_, b_, ds.output_rocker, al, beta)
        G, B = a_ * np.exp(1j * al), ds.frame + ds.output_rocker * np.exp(1j * beta)
        ang = abs(np.angle((G - B) / (ds.frame - B)))    # angle GB·BB0 at B
        gmin = min(gmin, min(ang, np.pi - ang))
    doc = to_plain(get_machine("lockbeam").document(run))
    for lang in ("en", "zh"):
        rows = {r[0]: r[1] for r in key_rows("lockbeam", doc, lang)}
        values = list(rows.values())
        assert f"{a_ * 1e3:.2f}" in values and f"{b_ * 1e3:.2f}" in values
        assert f"{np.degrees(bend):.2f}" in values
        assert f"{np.degrees(gmin):.2f}" in values
        assert f"{np.degrees(b.gamma_min):.2f}" not in values      # the unrounded linkage's
    md_en, _ = _markdown(lambda n: run, "lockbeam", "en")
    assert "swings 50.00° clockwise (required 50.00°)" in md_en
    assert "| 50.00 (clockwise) | ° |" in md_en and "-50.000" not in md_en.split("wheel swing |")[1][:20]
    check = [ln for ln in md_en.splitlines() if ln.startswith("| simulation")]
    assert any("four-bar as drawn" in ln and "| 180.00 | 180.00 |" in ln for ln in check)
    assert f"{np.degrees(bend):.2f}" == "180.00"
    assert f"| {np.degrees(gmin):.2f} | ≥ 40 |" in md_en
    assert f"designed for a swing of {np.degrees(dalpha):.2f}°" in md_en
