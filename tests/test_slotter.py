"""The slotting machine (插床), the proof of the one-engine design (issue 17 point 7),
against independent references: the guide-bar closed forms (stroke H = 2·L_O3B·sin(ψ/2),
K = (180° + θ)/(180° − θ), ω4 = L2·ω2·cos(φ2 − φ4)/S), the work of the cutting force per
revolution (the only load doing net work: weights and inertia forces do none over a
cycle), the power balance, and the mirror image of the machine (counter-clockwise crank)."""
from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from mechdesign.cli import app
from mechdesign.machines import get_machine, stages_for
from mechdesign.pipeline import run_stages

ROOT = Path(__file__).parents[1]


@pytest.fixture(scope="module")
def r(example_results):
    return example_results("slotter")


def test_stroke_and_time_ratio_from_the_simulated_linkage(r):
    p, syn, k, v = r["params"], r["synthesis"], r["linkage"], r["linkage_verification"]
    d = syn.design
    theta = np.pi * (p.time_ratio_K - 1) / (p.time_ratio_K + 1)
    assert d.guide_bar == pytest.approx(p.stroke / (2 * np.sin(theta / 2)), rel=1e-12)
    assert d.crank == pytest.approx(p.frame * np.sin(theta / 2), rel=1e-12)
    assert v.stroke == pytest.approx(p.stroke, abs=1e-9)       # bounded search, not the formulas
    assert k.stroke == pytest.approx(p.stroke, abs=1e-9)       # zeros of the velocity
    assert v.time_ratio == pytest.approx(p.time_ratio_K, abs=1e-6)
    assert k.time_ratio == pytest.approx(p.time_ratio_K, abs=1e-9)


def test_the_slow_stroke_cuts_downwards(r):
    k, f, raw = r["linkage"], r["linkage_forces"], r["linkage_raw"]
    n = k.grid_size
    working = k.phase[:n] < k.working_span
    vy = raw.points["C"].vel.imag[:n]
    assert np.all(vy[working][1:-1] < 0)                      # the ram goes down …
    assert np.all(vy[~working][1:-1] > 0)                     # … and comes back up
    fy = -f.resistance["R1"][:n]     # R1 is signed along DOWN = −π/2: its y component is −R1
    cutting = np.abs(fy) > 0
    assert cutting.any() and np.all(fy[cutting] > 0)          # the cut pushes the tool up
    assert np.all(working[cutting])                           # only on the working stroke


def test_guide_bar_angular_velocity_closed_form(r):
    p, raw, model = r["params"], r["linkage_raw"], r["model"]
    a, o3 = raw.points["A"].pos, raw.points["O3"].pos
    phi2 = np.angle(a - raw.points["O2"].pos)
    phi4 = raw.links["4"].angle
    S = np.abs(a - o3)
    w4 = model.crank.length * p.crank_omega * np.cos(phi2 - phi4) / S
    np.testing.assert_allclose(raw.links["4"].omega, w4, rtol=0, atol=1e-10 * np.max(np.abs(w4)))


def test_mean_power_is_the_cutting_work_per_revolution(r):
    p, f = r["params"], r["linkage_forces"]
    cut = p.cutting_force * p.stroke * (1 - 2 * p.idle_travel_ratio)   # J per revolution
    per_second = cut * p.crank_speed_rpm / 60.0
    # The force switches on and off inside grid steps: the grid mean carries O(h) of it.
    assert f.mean_power == pytest.approx(per_second, rel=2e-3)
    assert r["linkage_verification"].power_balance_residual < 1e-9
    fl = r["linkage_flywheel"]
    assert fl.mean_power == pytest.approx(f.mean_power, rel=1e-12)
    assert fl.inertia == pytest.approx(900 * fl.max_energy_swing /
                                       (np.pi ** 2 * fl.shaft_speed_rpm ** 2 * p.fluctuation))


def test_counter_clockwise_crank_mirrors_the_machine(r):
    """O2 on the other side of O3 and the crank turning the other way: the mirror image,
    the same motion of the ram and the same balancing torque at every phase."""
    p = r["params"]
    q = dataclasses.replace(p, crank_omega=-p.crank_omega, grid_points=720, cam=None,
                            drive=None, gear=None)
    pc = dataclasses.replace(p, grid_points=720, cam=None, drive=None, gear=None)
    m = get_machine("slotter")
    out = [run_stages(stages_for(m, x), {"params": x, "brief": r["brief"]})[0] for x in (pc, q)]
    (a, b) = out
    assert b["linkage"].time_ratio == pytest.approx(a["linkage"].time_ratio, abs=1e-9)
    np.testing.assert_allclose(b["linkage"].s, a["linkage"].s, atol=1e-12)
    np.testing.assert_allclose(b["linkage_raw"].points["C"].pos, -np.conj(a["linkage_raw"].points["C"].pos),
                               atol=1e-12)
    mb = a["linkage_forces"].balancing_torque
    np.testing.assert_allclose(b["linkage_forces"].balancing_torque, mb, atol=1e-9 * np.max(np.abs(mb)))


def test_a_rod_too_short_to_reach_the_guide_names_its_field(tmp_path):
    text = (ROOT / "designs" / "slotter.yaml").read_text(encoding="utf-8")
    bad = tmp_path / "slotter.yaml"
    bad.write_text(text.replace("rod_ratio_BC_O3B: 0.8", "rod_ratio_BC_O3B: 0.01"), encoding="utf-8")
    res = CliRunner().invoke(app, ["run", str(bad), "--out", str(tmp_path / "out"), "--format", "md",
                                   "--lang", "en"])
    assert res.exit_code == 2, res.output
    assert "linkage.rod_ratio_BC_O3B" in res.output and "0.01" in res.output
    assert "Traceback" not in res.output
    assert not (tmp_path / "out" / "report.md").exists()


# ----------------------------------------------------------------------------- issue 19: the
# flywheel rim's weight on its shaft, the realised speed, the motor choice explained


def test_flywheel_weight_loads_its_shaft_by_the_beam_closed_form(r):
    """The rim (m = 4J_F/D², closed form) hangs between the bearings of shaft Ⅰ: a load −m·g in
    the vertical plane at mid-span; the vertical reactions and the moment at the flywheel
    from the beam's closed form R_A = Σ F_i (L − x_i)/L (B at x = L), M(a) = R_A·a + Σ_{x_i<a} F_i (a − x_i)."""
    fl, d, p = r["linkage_flywheel"], r["drive"], r["params"]
    m = 4 * fl.inertia / fl.rim.diameter ** 2
    W = m * p.gravity
    sd = d.shaft_designs[0]
    assert sd.index == 1 and "flywheel" in sd.elements
    fw = [ld for ld, nm in zip(sd.loads, sd.elements) if nm == "flywheel"]
    assert len(fw) == 1
    a, L = fw[0].x, sd.span
    assert fw[0].Fv == pytest.approx(-W) and fw[0].Fh == 0
    assert a == pytest.approx(L / 2)
    # the bearing span holds the rim's width: inside elements + 2 × 60 mm clearance
    assert L == pytest.approx(fl.rim.width + 0.12)
    RA = -sum(ld.Fv * (L - ld.x) for ld in sd.loads) / L      # reactions balance the loads
    RB = -sum(ld.Fv * ld.x for ld in sd.loads) / L
    assert all(ld.Fa == 0 for ld in sd.loads)                 # spur gears, belt: no couples
    assert sd.result.RAv == pytest.approx(RA, rel=1e-9)
    assert sd.result.RBv == pytest.approx(RB, rel=1e-9)
    Mv = RA * a + sum(ld.Fv * (a - ld.x) for ld in sd.loads if ld.x < a - 1e-12)
    at = [s for s in sd.result.sections if abs(s.x - a) < 1e-12]
    assert at and abs(at[0].Mv) == pytest.approx(abs(Mv), rel=1e-9)
    # the weight alone would give W/2 at each bearing: the difference is that
    assert RA + RB == pytest.approx(W - sum(ld.Fv for ld in sd.loads if ld.x != a))


def test_flywheel_speed_note_and_the_motor_choice(r):
    """The drive turns shaft Ⅰ at n′ = 910/i_belt, below the nominal 180 rpm (60 rpm × z2/z1):
    J_F = 900·ΔW_max/(π²·n²·[δ]) grows as 1/n², so the flywheel is sized at n′ (sized at 180
    rpm it would let δ reach [δ](n/n′)² > [δ], review35); the motor is the 0.75 kW Y90S-6
    whose belt makes 910/(60·3) = 5.06, beyond the belt's recommended 2–4 but within its
    maximum 7; the report says so and names the 2.2 kW motor the recommended ranges would take."""
    from mechdesign.i18n import tr
    from mechdesign.render.drive_report import _motor_note
    from mechdesign.render.linkage_report import realised_flywheel

    fl, d, p = r["linkage_flywheel"], r["drive"], r["params"]
    n_real = d.motor.full_load_rpm / d.stages[0].ratio
    assert n_real == pytest.approx(d.shafts[1].speed_rpm, rel=1e-12) and n_real < 180
    assert fl.nominal_speed_rpm == pytest.approx(60 * 54 / 18)
    assert fl.shaft_speed_rpm == pytest.approx(n_real, rel=1e-12)
    jf = 900 * fl.max_energy_swing / (np.pi ** 2 * n_real ** 2 * p.fluctuation)
    assert fl.inertia == pytest.approx(jf, rel=1e-12)
    # δ = 900·ΔW/(π² n′² J_F) at the realised speed: within [δ]
    assert 900 * fl.max_energy_swing / (np.pi ** 2 * n_real ** 2 * fl.inertia) <= p.fluctuation * (1 + 1e-12)
    assert fl.rim.rim_mass == pytest.approx(4 * jf / fl.rim.diameter ** 2, rel=1e-12)
    text = realised_flywheel(fl, n_real, tr("en"))
    assert f"{n_real:.2f}" in text and f"{fl.fluctuation * (180 / n_real) ** 2:.4f}" in text
    assert "[δ](n/n′)" not in text          # as math: pandoc read "[δ](n/n′)" as a link
    assert d.motor.designation == "Y90S-6" and d.choice.reason == "maximum"
    note = _motor_note(d, tr("en"))
    assert note is not None and f"{910 / 60 / 3:.2f}" in note and "maximum 7" in note
    assert f"Y132S-8 (2.20 kW, synchronous 750 rpm), {2200 / d.power_required:.1f} times" in note
    assert "synchronous_rpm" not in note


def test_the_drive_is_designed_once_and_its_shaft_carries_the_resized_rim(r, monkeypatch):
    """The drive turns shaft Ⅰ below the nominal speed (test above), so the flywheel is sized
    again there (J_F ∝ 1/n²) and its rim's weight, the resized one, loads the shaft. The
    motor, the ratios and the speeds do not depend on that weight: guide_bar._drive designs
    the drive once (it designed it at the nominal rim, then again at the resized one)."""
    from mechdesign.stages import drive, guide_bar

    stages = stages_for(get_machine("slotter"), r["params"])
    nominal = next(s for s in stages if s.key == "linkage_flywheel").run(r)
    assert nominal.nominal_speed_rpm is None and nominal.rim is not None
    calls = []
    design = drive.design_drive

    def counted(*args, **kwargs):
        calls.append(args)
        return design(*args, **kwargs)

    monkeypatch.setattr(drive, "design_drive", counted)
    d, fl = guide_bar._drive({**r, "linkage_flywheel": nominal}, flywheel_weight=True)
    assert len(calls) == 1
    n_real = d.shafts[1].speed_rpm
    assert fl.nominal_speed_rpm == pytest.approx(nominal.shaft_speed_rpm) and n_real < nominal.shaft_speed_rpm
    # the resized rim: J_F at n′ = J_F at n × (n/n′)², m = 4J_F/D²
    jf = nominal.inertia * (nominal.shaft_speed_rpm / n_real) ** 2
    assert fl.inertia == pytest.approx(jf, rel=1e-12)
    [load] = [ld for ld, nm in zip(d.shaft_designs[0].loads, d.shaft_designs[0].elements) if nm == "flywheel"]
    assert load.Fv == pytest.approx(-4 * jf / fl.rim.diameter ** 2 * r["params"].gravity, rel=1e-12)
