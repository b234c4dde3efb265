"""The die-cutter (seed 001b) against independent references: the toggle's closed-form
geometry, the crank-rocker's law-of-cosines extremes, finite differences of the simulated
platen, virtual work, the work of the cutting force per cycle, the textbook formulas of the
incomplete gear and the cam's own lift table."""
from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.brief.loader import BriefError, _UniqueKeyLoader, parse_brief
from mechdesign.cli import app
from mechdesign.core import cycle as cy
from mechdesign.core import fourbar
from mechdesign.machines import get_machine, stages_for
from mechdesign.pipeline import run_stages

ROOT = Path(__file__).resolve().parents[1]
BRIEF = ROOT / "designs" / "die_cutter.yaml"
TWO_PI = 2 * np.pi


def base() -> dict:
    # the brief loader's YAML reading (7.0e4 is a number, as in YAML 1.2)
    return yaml.load(BRIEF.read_text(encoding="utf-8"), Loader=_UniqueKeyLoader)  # noqa: S506


def run(data: dict) -> dict:
    b = parse_brief(data)
    m = get_machine(b.machine)
    p = m.to_params(b)
    return run_stages(stages_for(m, p), {"params": p, "brief": b})[0]


@pytest.fixture(scope="module")
def shipped(example_results):
    return example_results("die_cutter")                 # = run(base())


def edited(**changes) -> dict:
    """The shipped brief with ``section.field`` values replaced."""
    data = copy.deepcopy(base())
    for path, value in changes.items():
        node = data
        *parents, leaf = path.split("__")
        for key in parents:
            node = node[key]
        node[leaf] = value
    return data


# ----------------------------------------------------------------------------- geometry


def test_stroke_and_top_height_by_the_toggle_closed_form(shipped):
    r = shipped
    p, k = r["params"], r["press"]
    lt, ld = p.geometry.toggle_CB, p.geometry.toggle_BD
    n = k.grid_size
    y = k.points["D"][:n].imag
    # Straight toggle at the top: D is CB + BD above C; the stroke is the brief's H.
    assert np.max(y) == pytest.approx(lt + ld, abs=1e-12)
    assert r["press_verification"].stroke == pytest.approx(p.geometry.stroke, abs=1e-12)
    # At the bottom B is ψ off the guide: y = l_CB cos ψ + √(l_BD² − l_CB² sin² ψ).
    psi = r["toggle"].swing
    bottom = lt * np.cos(psi) + np.sqrt(ld ** 2 - (lt * np.sin(psi)) ** 2)
    assert np.min(y) == pytest.approx(bottom, abs=1e-12)
    assert lt + ld - bottom == pytest.approx(p.geometry.stroke, abs=1e-12)
    # D stays on the vertical guide through C, and B on its circle about C.
    assert np.max(np.abs(k.points["D"][:n].real)) < 1e-12
    assert np.max(np.abs(np.abs(k.points["B"][:n]) - lt)) < 1e-12


def test_crank_rocker_extremes_by_the_law_of_cosines(shipped):
    """θ and ψ of the synthesised four-bar O1ABC from its lengths alone (triangles O1CB at the
    folded and extended positions) are the K and the swing the design asked for."""
    d = shipped["toggle"]
    theta, psi = fourbar.crank_rocker_extremes(d.four)
    K = shipped["params"].geometry.K
    assert theta == pytest.approx(np.pi * (K - 1) / (K + 1), abs=1e-10)
    assert psi == pytest.approx(d.swing, abs=1e-10)
    ok, kind = fourbar.grashof(d.four)
    assert ok and kind == "crank-rocker"
    # the pivot positions reproduce the frame length
    assert abs(d.O1) == pytest.approx(d.four.frame, abs=1e-12)


def test_time_ratio_and_rise_span_from_the_simulation(shipped):
    k = shipped["press"]
    K = shipped["params"].geometry.K
    # The rise (platen up) is the slow stroke: 180° + θ of crank angle.
    tol = shipped["verification"].K_velocity_tol
    assert k.time_ratio == pytest.approx(K, abs=tol)
    assert k.working_span == pytest.approx(np.pi * 2 * K / (K + 1), abs=tol)
    # position 1 is the bottom: the platen rises from there
    assert k.s[0] == 0.0 and k.v[1] > 0


@pytest.mark.parametrize("rotation", ["cw", "ccw"])
@pytest.mark.parametrize("top", ["extended", "folded"])
def test_every_placement_keeps_stroke_K_and_the_slow_rise(rotation, top):
    r = run(edited(press__crank_rotation=rotation, press__top_position=top,
                   gripper_cam__rotation=rotation))
    k, g, v = r["press"], r["params"].geometry, r["verification"]
    assert r["press_verification"].stroke == pytest.approx(g.stroke, abs=1e-12)
    # the top is flat to fourth order: the speed's zero is found to about (ε/c)^(1/3) in angle
    assert v.K_velocity_tol < 1e-4
    assert k.time_ratio == pytest.approx(g.K, abs=v.K_velocity_tol)
    assert np.sign(r["params"].crank_omega) == (1 if rotation == "ccw" else -1)


def test_rotation_sense_mirrors_the_drawing():
    cw, ccw = run(edited()), run(edited(press__crank_rotation="ccw", gripper_cam__rotation="ccw"))
    a, b = cw["toggle"].O1, ccw["toggle"].O1
    assert a.real == pytest.approx(-b.real, abs=1e-12) and a.imag == pytest.approx(b.imag, abs=1e-12)


def test_folded_top_spends_more_crank_angle_cutting_but_less_clear():
    """The YAML's reason for the extended top: the folded one gives a longer cut (lower torque
    peak) but a shorter clear arc for the feed."""
    ext = run(edited())["amplification"]
    fol = run(edited(press__top_position="folded", timing__feed_start_deg=0,
                     timing__gripper_open_deg=0))["amplification"]
    assert fol.timing.press_span > ext.timing.press_span
    assert fol.timing.clear_span < ext.timing.clear_span
    assert fol.peak_required < ext.peak_required


@pytest.mark.parametrize("eps, order", [(0.0, 4.0), (3.0, 2.0)])
def test_top_is_flat_to_fourth_order_only_with_the_straight_toggle(eps, order):
    """With the toggle straight at the crank-rocker's dead centre H − s ∝ Δφ⁴ (both dy/dβ and
    dβ/dφ vanish); a toggle stopping short of straight gives the ordinary Δφ²."""
    r = run(edited(press__toggle_angle_at_top_deg=eps))
    v = r["verification"]
    assert v.top_order == pytest.approx(order, abs=0.05)
    assert v.top_toggle_angle == pytest.approx(np.radians(eps), abs=max(v.search_angle_tol, 1e-8))


# ----------------------------------------------------------------------------- forces


def test_force_amplification_against_finite_differences_of_the_platen(shipped):
    """F = M ω / v_D: the crank torque per newton of pressing force (kinetostatics, links
    massless) equals dy_D/dφ from central differences of the simulated positions."""
    k, amp = shipped["press"], shipped["amplification"]
    n = k.grid_size
    h = TWO_PI / n
    y = k.points["D"][:n].imag
    dy = (np.roll(y, -1) - np.roll(y, 1)) / (2 * h)
    scale = np.max(np.abs(dy))
    assert np.max(np.abs(amp.unit_torque[:n] - dy)) / scale < 1e-5      # O(h²)
    # and the virtual-work closed form (four-bar ω ratio × toggle derivative) to rounding
    assert np.max(np.abs(amp.unit_torque[:n] - amp.closed_form[:n])) / scale < 1e-12


def test_amplification_table_matches_the_platen_gap(shipped):
    """Each row's phase puts the platen the stated gap below its top, and its F/M is the
    reciprocal of M/F; Π = a/(M/F)."""
    r = shipped
    k, amp, model = r["press"], r["amplification"], r["press_model"]
    a = r["toggle"].four.crank
    for gap, ph, u, fpt, ratio in amp.table:
        z = model.mechanism.solve(np.array([k.start_angle + k.sense * ph])).points["D"].pos[0]
        assert k.stroke - (z.imag - k.points["D"][0].imag) == pytest.approx(gap, abs=1e-12)
        assert fpt * u == pytest.approx(1.0)
        assert ratio == pytest.approx(a / u)
    gaps = [row[0] for row in amp.table]
    forces = [row[3] for row in amp.table]
    assert gaps == sorted(gaps, reverse=True) and forces == sorted(forces)   # grows to the top


def test_mean_crank_power_is_the_cutting_work_per_cycle(shipped):
    """Gravity and inertia do no net work over a cycle, so ∮ M_b dφ = F_c·t exactly; the grid's
    mean is off by at most the torque jump at switch-on times one step / 2π."""
    r = shipped
    p, f, amp = r["params"], r["press_forces"], r["amplification"]
    work = p.cut_length * p.specific_resistance * p.pressing_travel    # L q t
    assert amp.cut_work == pytest.approx(work)
    h = TWO_PI / r["press"].grid_size
    bound = amp.peak_required * h / TWO_PI
    assert abs(f.mean_torque * TWO_PI - work) / TWO_PI <= bound
    period = 60.0 / p.shaft_rpm
    assert f.mean_power == pytest.approx(work / period, rel=bound / f.mean_torque)


def test_mean_power_converges_with_the_grid():
    r = run(edited(analysis__grid_points=36000))
    p, f = r["params"], r["press_forces"]
    work = p.cut_length * p.specific_resistance * p.pressing_travel
    assert f.mean_torque * TWO_PI == pytest.approx(work, rel=3e-4)


def test_required_torque_peaks_where_cutting_starts(shipped):
    r = shipped
    amp, p = r["amplification"], r["params"]
    assert amp.peak_phase == pytest.approx(amp.timing.press_up, abs=TWO_PI / r["press"].grid_size)
    # the supremum is at the window's start (table row 1); the grid's first point inside it is
    # less than one step later, where the torque has fallen by at most one step's slope
    sup = p.cutting_force * amp.table[0][2]
    assert sup * (1 - 5e-3) <= amp.peak_required <= sup


# ----------------------------------------------------------------------------- flywheel, drive


def test_flywheel_inertia_in_si_form(shipped):
    """J = ΔW/(ω² [δ]) with ω in rad/s on the flywheel's shaft; on the distribution shaft the
    same flywheel would need i² times more."""
    fl = shipped["press_flywheel"]
    omega = fl.shaft_speed_rpm * np.pi / 30
    assert fl.inertia == pytest.approx(fl.max_energy_swing / (omega ** 2 * fl.fluctuation))
    assert fl.inertia_on_crank == pytest.approx(fl.inertia * fl.speed_ratio ** 2)
    # the energy swing cannot exceed the work of one cut (the cut is the only net load)
    assert 0.5 * fl.max_energy_swing < shipped["amplification"].cut_work
    assert fl.max_energy_swing < shipped["amplification"].cut_work


def test_drive_meets_the_speed_and_the_power(shipped):
    d, p = shipped["drive"], shipped["params"]
    assert abs(d.output_speed - p.shaft_rpm) / p.shaft_rpm <= 0.05
    assert d.motor.power >= d.power_required
    assert d.machine_power == pytest.approx(shipped["press_forces"].mean_power)
    assert [s.type for s in d.stages] == ["belt", "helical", "helical"]
    # the flywheel on shaft Ⅰ: the stages after it carry the peak torque
    assert d.peak_from_shaft == 1
    assert d.peak_factor == pytest.approx(shipped["press_forces"].peak_torque /
                                          shipped["press_forces"].mean_torque)


# ----------------------------------------------------------------------------- feed and cycle


def test_incomplete_gear_by_the_textbook_formulas(shipped):
    r = shipped
    g, fd, p = r["feed"].gear, r["feed"], r["params"]
    assert (g.z1, g.teeth, g.z2) == (45, 18, 18)
    assert g.motion_angle == pytest.approx(np.radians(360 * 18 / 45))
    # the chain advances (z1'/z2) z_s p per cycle = one gripper-bar spacing
    assert fd.feed == pytest.approx(18 / 18 * 24 * 25.4e-3)
    assert fd.feed == pytest.approx(p.bar_spacing)
    # integrating the driven wheel's speed ratio over one driver turn gives the advance
    theta = np.linspace(0, TWO_PI, 200001)
    ratio = g.driven_motion(theta).ratio
    advance = np.sum(0.5 * (ratio[1:] + ratio[:-1]) * np.diff(theta))
    assert advance == pytest.approx(g.advance, rel=1e-4)


def test_cycle_rows_match_the_cam_the_gear_and_the_simulated_platen(shipped):
    """Sampled over the shaft angle: the gripper row is open exactly where the designed cam
    lifts its follower, the chain row moves exactly where the incomplete gear meshes, the
    platen row is 'clear' exactly where the simulated platen is c below its top."""
    r = shipped
    k, cam, g, cyc, p = r["press"], r["cam"], r["feed"].gear, r["cycle"], r["params"]
    n = k.grid_size
    phase = k.phase[:n]
    step = TWO_PI / n
    diagram = cyc.diagram
    # the cam's own table on its fine grid (δ from the cam stage), shifted by its mounting angle
    lift = np.interp(np.mod(phase - cyc.gripper_start, TWO_PI), cam.grid.delta, cam.grid.motion.s,
                     period=TWO_PI)
    open_cam = lift > 1e-6 * cam.params.programme.stroke
    open_row = cy.state_at(diagram.actuator("gripper"), phase) != "dwell_low"
    assert np.sum(open_cam != open_row) <= 4          # only samples next to the boundaries
    moving = g.driven_motion(phase).moving
    assert np.array_equal(moving, cy.moving_at(diagram.actuator("chain"), phase))
    clear = k.s[:n] < k.stroke - p.clearance
    assert np.sum(clear != (cy.state_at(diagram.actuator("platen"), phase) == "clear")) <= 2
    # the chain row's motion angle is the incomplete gear's 360° z1'/z1
    move = cy.interval_of(diagram.actuator("chain"), "move")
    assert move.span == pytest.approx(TWO_PI * g.teeth / g.z1)
    # the gripper's open arc is the cam's rise + far dwell + return
    spans = [s["angle_deg"] for s in base()["gripper_cam"]["programme"]]
    opened = sum(ph.span for ph in diagram.actuator("gripper").phases if ph.state != "dwell_low")
    assert opened == pytest.approx(np.radians(sum(spans[:3])))
    assert step > 0


def test_timing_requirements_hold_by_sampling(shipped):
    """Checked without the constraint machinery: while the chain moves the simulated platen is
    more than c below its top; while the cam lifts the follower the chain stands still."""
    r = shipped
    k, cam, g, cyc, p = r["press"], r["cam"], r["feed"].gear, r["cycle"], r["params"]
    n = k.grid_size
    phase = k.phase[:n]
    moving = g.driven_motion(phase).moving
    assert np.all(k.s[:n][moving] < k.stroke - p.clearance)
    lift = np.interp(np.mod(phase - cyc.gripper_start, TWO_PI), cam.grid.delta, cam.grid.motion.s,
                     period=TWO_PI)
    assert not np.any(moving & (lift > 0))
    assert all(c.ok for c in cyc.checks) and not cyc.warnings


def test_feed_placed_in_the_cutting_zone_is_a_finding_not_an_error():
    r = run(edited(timing__feed_start_deg=150))
    codes = {w.code for w in r["cycle"].warnings}
    assert codes == {"timing"}
    assert not all(c.ok for c in r["cycle"].checks)


# ----------------------------------------------------------------------------- the brief


@pytest.mark.parametrize("changes, where, says", [
    ({"chain__bar_spacing_mm": 600}, "chain.bar_spacing_mm", "609.60"),
    ({"press__clearance_mm": 3}, "press.clearance_mm", "pressing travel"),
    ({"press__clearance_mm": 60}, "press.clearance_mm", "stroke"),
    ({"incomplete_gear__motion_start_deg": 10}, "incomplete_gear.motion_start_deg",
     "timing.feed_start_deg"),
    ({"gripper_cam__rotation": "ccw"}, "gripper_cam.rotation", "distribution shaft"),
    ({"flywheel__shaft": 5}, "flywheel.shaft", "0 (motor) … 3"),
    ({"timing__feed_start_deg": 400}, "timing", "0 ≤ value < 360"),
])
def test_bad_briefs_name_the_field(changes, where, says):
    with pytest.raises(BriefError) as exc:
        parse_brief(edited(**changes))
    text = str(exc.value)
    assert where in text and says in text


def test_press_that_cannot_be_built_is_rejected_by_run_not_by_validation(tmp_path):
    """H = 400 mm is beyond what CB and BD can lift: the synthesis (run once, in the run's
    feasibility checks) says so at press.stroke_H_mm; validation runs no synthesis."""
    data = edited(press__stroke_H_mm=400)
    parse_brief(data)
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    result = CliRunner().invoke(app, ["run", str(path), "-o", str(tmp_path / "out"), "-f", "md",
                                      "--lang", "en"])
    assert result.exit_code == 2
    text = result.output
    assert "press" in text and "cannot be reached" in text
    assert "press.stroke_H_mm: 400 — stroke_H_mm = 400 cannot be reached" in text
    assert "Traceback" not in text and not (tmp_path / "out").exists()


def test_cam_programme_must_open_hold_close_rest():
    data = edited()
    prog = data["gripper_cam"]["programme"]
    data["gripper_cam"]["programme"] = [prog[3], prog[0], prog[1], prog[2]]
    with pytest.raises(BriefError) as exc:
        parse_brief(data)
    assert "rise, dwell, return, dwell" in str(exc.value)


def test_cli_bad_brief_exits_2_without_traceback(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(edited(chain__bar_spacing_mm=600), allow_unicode=True),
                    encoding="utf-8")
    result = CliRunner().invoke(app, ["run", str(path), "-o", str(tmp_path / "out"), "-f", "md"])
    assert result.exit_code == 2
    assert "chain.bar_spacing_mm" in result.output and "Traceback" not in result.output


@pytest.mark.e2e
def test_cli_writes_the_english_report(tmp_path):
    out = tmp_path / "en"
    result = CliRunner().invoke(app, ["run", str(BRIEF), "-o", str(out), "-f", "md", "--lang", "en"])
    assert result.exit_code == 0, result.output
    md = (out / "report.md").read_text(encoding="utf-8")
    assert "{{" not in md and "{%" not in md
    for heading in ("# Toggle press synthesis", "# Cutting force and force amplification",
                    "# Flywheel", "# Drive design", "# Cam mechanism", "## Incomplete gear drive",
                    "## Motion cycle diagram", "# Verification"):
        assert heading in md
    assert (out / "cam_profile.csv").exists() and (out / "results.json").exists()


# ----------------------------------------------------------------------------- issue 19: the
# flywheel's placement, the table of the shafts after it, speeds, summary, P_b, cycle colours


def test_both_flywheel_placements_are_designed(shipped):
    """The other placement (the distribution shaft) by the same rules: J_F ∝ 1/n² (900ΔW/(π²n²[δ])
    on each shaft), its reducer carries the mean torque while this design's carries the peak
    (T2 in the ratio of the peak factor, K_A apart), the wheels' solid-disc masses ρπd²b/4."""
    r = shipped
    cmp_, fl, d = r["flywheel_placement"], r["press_flywheel"], r["drive"]
    a, o = cmp_.chosen, cmp_.other
    assert (a.shaft, o.shaft) == (1, 3)
    assert a.inertia == pytest.approx(fl.inertia)
    assert o.speed_rpm == pytest.approx(r["params"].shaft_rpm)
    # the same ΔW_max and [δ]: J ∝ 1/n²
    assert o.inertia == pytest.approx(a.inertia * (a.speed_rpm / o.speed_rpm) ** 2, rel=1e-9)
    assert o.inertia == pytest.approx(900 * fl.max_energy_swing
                                      / (np.pi ** 2 * o.speed_rpm ** 2 * fl.fluctuation))
    # the other rim: a thin rim (H ≤ D/2) and m = 4J/D²
    assert o.rim.height <= o.rim.diameter / 2 + 1e-12
    assert o.rim.rim_mass == pytest.approx(4 * o.inertia / o.rim.diameter ** 2)
    # the last gear stage: this design's wheel torque is the peak, the other's the mean
    mean_T2 = d.shafts[-1].torque
    assert a.gears[-1].torque == pytest.approx(d.peak_factor * mean_T2, rel=1e-9)
    assert o.gears[-1].torque == pytest.approx(mean_T2, rel=1e-9)
    for g in a.gears + o.gears:
        assert g.wheel_mass == pytest.approx(7850 * np.pi / 4 * g.d2 ** 2 * g.face_width)
    # smaller wheels for the mean torque
    assert all(go.d2 < ga.d2 for ga, go in zip(a.gears, o.gears))
    # the chosen placement is this design's drive
    assert a.shaft_seats == tuple(sd.d_seat for sd in d.shaft_designs)


def test_flywheel_comparison_reuses_the_designed_drive(shipped, monkeypatch):
    """small34: the comparison designed the whole drive a second time (motor, ratios, shaft
    table) for the other placement, though only the sizes after the flywheel depend on it.
    It now sizes the designed drive's stages and shafts again, without design_drive; the
    reference is that full second design, whose gears and shaft seats it must give."""
    import mechdesign.stages.drive as D
    from mechdesign.machines.die_cutter import stages as S

    r = dict(shipped)
    p = r["params"]
    other = len(p.drive.stages) if p.flywheel_shaft < len(p.drive.stages) else 1
    full = S._drive(r, other)                             # the whole drive designed again

    def refuse(*args, **kwargs):
        raise AssertionError("the comparison designs the drive again")

    monkeypatch.setattr(D, "design_drive", refuse)
    c = S.compare_placements(r)
    gears = [st.design for st in full.stages if st.design is not None and st.design.kind == "gear"]
    assert len(gears) == 2 and len(c.other.gears) == 2
    for g, d in zip(c.other.gears, gears):
        assert (g.module, g.face_width, g.torque) == (float(d.module), float(d.face_width),
                                                      float(d.T2))
    assert c.other.shaft_seats == tuple(float(sd.d_seat) for sd in full.shaft_designs)
    assert c.chosen == shipped["flywheel_placement"].chosen
    assert c.other == shipped["flywheel_placement"].other


def test_shafts_after_the_flywheel_table_holds_what_its_headers_say(shipped):
    """Columns: the torsion estimate A0·∛(P/n)·1.05 of the mean power (≈ 20 mm for shaft Ⅰ,
    not the enlarged seat), of the peak power, and the designed seat (≥ both)."""
    from mechdesign.i18n import tr
    from mechdesign.machines.die_cutter.report import _flywheel

    r = shipped
    ctx = _flywheel(r, r["params"], r["brief"], tr("en"))
    d = r["drive"]
    for row, sh in zip(ctx["peak_rows"], d.shaft_designs):
        s = d.shafts[sh.index]
        mean_est = 112 * (s.power / 1e3 / s.speed_rpm) ** (1 / 3) * 1.05
        peak_est = 112 * (s.power * d.peak_factor / 1e3 / s.speed_rpm) ** (1 / 3) * 1.05
        assert float(row[1]) == pytest.approx(s.speed_rpm, abs=0.005)        # realised
        assert float(row[4]) == pytest.approx(mean_est, abs=0.05)
        assert float(row[5]) == pytest.approx(peak_est, abs=0.05)
        assert float(row[6]) == pytest.approx(sh.d_seat * 1e3)
        assert float(row[6]) >= float(row[5]) > float(row[4])
    assert float(ctx["peak_rows"][0][4]) < 25                                # shaft Ⅰ ≈ 20 mm


def test_nominal_and_realised_flywheel_speed_named(shipped):
    """J_F at the nominal speed (50 rpm × the ratios after shaft Ⅰ); the realised 709.2 rpm
    keeps δ = [δ](n/n′)² (J ∝ 1/n²)."""
    from mechdesign.i18n import tr
    from mechdesign.render.linkage_report import realised_flywheel

    r = shipped
    fl, d = r["press_flywheel"], r["drive"]
    n_real = d.shafts[1].speed_rpm
    assert n_real == pytest.approx(1440 * (1 - d.stages[0].slip) * 125 / 250)
    assert fl.shaft_speed_rpm == pytest.approx(50 * d.stages[1].ratio * d.stages[2].ratio)
    text = realised_flywheel(fl, n_real, tr("en"))
    assert f"$n$ = {fl.shaft_speed_rpm:.2f} rpm" in text and f"$n'$ = {n_real:.2f} rpm" in text
    assert f"{fl.fluctuation * (fl.shaft_speed_rpm / n_real) ** 2:.4f}" in text and "0.47%" in text
    assert realised_flywheel(fl, fl.shaft_speed_rpm, tr("en")) is None


def test_summary_names_the_press_analysis_and_the_chain_feed(shipped, example_results):
    from mechdesign.machines.die_cutter.stages import results_document
    from mechdesign.render.summary import _designed
    from mechdesign.results import to_plain as to_jsonable

    parts = _designed(to_jsonable(results_document(shipped)), "en")
    assert "incomplete-gear chain feed design" in parts
    assert "kinematic and kinetostatic analysis" in parts
    assert "kinematic analysis of the feed linkage" not in parts
    from mechdesign.machines.lockbeam.stages import results_document as lock_doc
    lock = _designed(to_jsonable(lock_doc(example_results("lockbeam"))), "en")
    assert "kinematic analysis of the feed linkage" in lock


def test_platen_phases_are_motions_not_dwells(shipped):
    """The platen never stops (a crank drives it): its windows near the top (cutting) and
    clear of the die are motions, coloured as such; the grippers' dwells stay rests."""
    from mechdesign.render.cycle_figures import COLOURS

    diagram = shipped["cycle"].diagram
    assert all(ph.moving for ph in diagram.actuator("platen").phases)
    assert {ph.state for ph in diagram.actuator("gripper").phases} >= {"dwell_high", "dwell_low"}
    rests = {COLOURS[s] for s in ("dwell_high", "dwell_low", "dwell")}
    assert not {COLOURS[s] for s in ("work", "clear")} & rests


def test_balancing_force_signed_as_in_its_equation(shipped):
    """P_b = M_b/l with M_b's sign (counter-clockwise positive) in the text as in the equation
    (the base printed −1118 N in the equation and 1118 N in the text)."""
    from mechdesign.render.graphical_report import _forces

    doc = shipped["press_graphical"]
    seen = 0
    for pos in doc.positions:
        for ctx, fg in zip(_forces(pos, "en"), pos.forces):
            if fg.balancing_torque is None:
                continue
            # the text groups five or more digits (−133 237 N), the equation does not
            plain = ctx["pb"].replace(" ", "").replace("\u202f", "")
            pb = float(plain.replace("−", "-"))
            # the P_b equation: one chain "P_b = M_b/l = … = value N" (no "⇒" result part)
            eq = [m[0] for m in ctx["moments"] if m[0] and m[0].startswith("P_b =")]
            assert eq and np.sign(pb) == np.sign(fg.balancing_torque)
            assert eq[0].replace(" ", "").replace("\\", "").endswith(
                f"={plain}mathrm{{N}}"), eq[0]
            assert abs(pb) == pytest.approx(abs(fg.balancing_force), rel=5e-3)
            seen += 1
    assert seen >= 2


def test_flywheel_on_the_distribution_shaft_leaves_that_shaft_the_peak():
    """With the flywheel on the distribution shaft the reducer carries the mean torque, but the
    shaft itself still carries the peak between the flywheel and the crank (the base sized it
    for the mean); the comparison then puts the flywheel on shaft Ⅰ."""
    r = run(edited(flywheel__shaft=3, flywheel__rim_diameter_mm=1100))
    d = r["drive"]
    assert d.peak_from_shaft == 3
    torques = {sd.index: sd.torque for sd in d.shaft_designs}
    assert torques[1] == pytest.approx(d.shafts[1].torque)
    assert torques[2] == pytest.approx(d.shafts[2].torque)
    assert torques[3] == pytest.approx(d.peak_factor * d.shafts[3].torque)
    assert [s.index for s in r["peak_shafts"]] == [3]
    cmp_ = r["flywheel_placement"]
    assert (cmp_.chosen.shaft, cmp_.other.shaft) == (3, 1)
    assert cmp_.chosen.inertia == pytest.approx(cmp_.other.inertia * (cmp_.other.speed_rpm
                                                                       / cmp_.chosen.speed_rpm) ** 2)


def test_amplification_table_writes_f_per_m_to_four_significant_digits(shipped):
    """Table "Force amplification near the top" (zh/en table 27): F/M, a force per torque
    spanning two decades (79 to 5168 kN/(kN·m)), follows the number rule of forces and
    torques (render/fmt.py): 4 significant digits, a value of five or more integer digits
    with all of them; it was written to 0.1 (78.7, 5168.0). Its value is 1/(M/F)."""
    import re

    from mechdesign.i18n import tr
    from mechdesign.machines.die_cutter.report import _amplification

    r = shipped
    rows = _amplification(r, r["params"], tr("en"))["rows"]
    cells = [row[3] for row in rows if row[3] != "∞"]
    assert len(cells) == len(r["amplification"].table)
    for cell, (_gap, _ph, u, _fpt, _ratio) in zip(cells, r["amplification"].table):
        plain = re.sub(r"[\u202f\u00a0 ]", "", cell)
        integer, _, decimals = plain.partition(".")
        if len(integer) >= 5:
            assert not decimals, cell
        else:
            digits = (integer + decimals).lstrip("0")
            assert len(digits) == 4, cell
        assert float(plain) == pytest.approx(float(f"{1 / u:.4g}"), rel=1e-12), cell


def test_two_peak_torques_of_the_distribution_shaft_are_told_apart(shipped):
    """Issue 19 point 5: the table of the shafts after the flywheel gives the distribution
    shaft a peak torque 0.5 % above the force analysis's max|M_b| (the drive's torque at the
    realised speed, with the losses after that shaft, × the peak factor); the report says
    which is which, with both values: the table's (its mean × the factor) and the largest
    |M_b| of the analysis's own torque curve (read here from the samples: a bound the exact
    extreme may only exceed by the grid's resolution). Torques to 4 significant digits."""
    from mechdesign.i18n import tr
    from mechdesign.machines.die_cutter.report import _flywheel
    from mechdesign.numbers import sig

    r = shipped
    ctx = _flywheel(r, r["params"], r["brief"], tr("en"))
    last = r["peak_shafts"][-1]
    assert last.index == len(r["brief"].drive.stages)
    assert last.peak_torque == pytest.approx(last.torque * r["drive"].peak_factor, rel=1e-12)
    note = ctx["peak_note"]
    assert sig(last.peak_torque) in note and sig(last.torque) in note
    sampled = float(np.max(np.abs(r["press_forces"].balancing_torque)))
    stated = float(note.split("is ")[-1].split(" N")[0].replace(" ", "").replace("\u202f", ""))
    assert sampled <= stated * (1 + 1e-4) and stated <= sampled * 1.01      # exact ≥ sampled
    assert abs(last.peak_torque / stated - 1) > 1e-3          # two values: both named
    for row in ctx["peak_rows"]:
        for cell in row[2:4]:
            cell = cell.replace("\u202f", "").replace(" ", "")
            digits = cell.replace(".", "").lstrip("0")
            assert len(digits) <= max(4, len(cell.split(".")[0])), row
