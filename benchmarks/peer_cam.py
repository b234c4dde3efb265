"""Peer check of the translating roller-follower cam against PyPI `mechanism` 1.1.10.

Run (on demand, not a test; `mechanism` lives in its own venv, never in the dev one):
    python3 -m venv /tmp/peer && /tmp/peer/bin/pip install mechanism==1.1.10 -e .
    /tmp/peer/bin/python benchmarks/peer_cam.py          # or: pip install -e '.[peers]'

Case (textbook exercise 7-3): offset translating roller follower, cycloidal rise 120°
h = 30 mm, dwell 30°, return 150°, dwell 60°, roller 10 mm, offset 12 mm on the
favourable side (cam ccw), [α] = 30°; also the centred follower (offset 0).

What each side computes
* mechanism `Cam.get_base_circle(kind, 'roller', roller_radius, eccentricity,
  max_pressure_angle)`: φ = max|atan((y' − ε)/(y + √((Rb + Rf)² + ε²)))| over a
  0.0062 rad grid with analytic y = s, y' = ds/dθ, solved for Rb with fsolve (guess 0.1).
  Its Rb is the ACTUAL (profile) base circle; its pitch circle is Rb + Rf, which is what we
  print. Geometry needs √(Rp² − ε²) (distance along the follower axis at s = 0): the
  "+ε²" is a bug that lowers φ, hence a smaller Rb, whenever ε ≠ 0. The column
  "theirs, −ε²" re-solves their expression with the sign fixed to attribute the gap.
  One law per cam ('naive' = constant velocity, 'harmonic', 'cycloidal'), one [α] for
  rise and fall, ε > 0 always favours the rise (rotation only affects plots).
  No call returns φ at a given radius: we evaluate their own expression (copied from
  get_base_circle) on their arrays, and round-trip it through get_base_circle.
* ours `min_base_radius_translating`: closed form on a 7200-point grid,
  tan α = |σ·ds/dδ − e| / (√(r0² − e²) + s); r0 is the PITCH (theoretical) base radius.
  `design_cam(...).pressure_angle`: angle between the exact pitch-curve normal and the
  follower's velocity (complex-number inversion, exact derivatives), 3600 points.
* SPLICED rows: `mechanism` cannot mix laws, so for "cycloidal rise + uniform return"
  we overwrite the return part of its cycloidal S, V, A arrays with its 'naive' arrays and
  call its solver on that: outside its public API, marked "*".
"""
from __future__ import annotations

import statistics
import sys
import time

import numpy as np

H, RF, ALPHA, R0_CHECK = 30.0, 10.0, 30.0, 50.0          # mm, mm, deg, mm (pitch)
SPANS = (120, 30, 150, 60)                                 # rise, dwell, return, dwell [deg]


def median_ms(fn, repeat=20):
    out = []
    for _ in range(repeat):
        t = time.perf_counter()
        value = fn()
        out.append((time.perf_counter() - t) * 1e3)
    return value, statistics.median(out)


# ------------------------------------------------------------------ theirs (mechanism)
def theirs(e, ret_law):
    from mechanism import Cam

    def build():
        motion = [("Rise", H, SPANS[0]), ("Dwell", SPANS[1]), ("Fall", H, SPANS[2]), ("Dwell", SPANS[3])]
        # mm on purpose: get_base_circle's fsolve starts at 0.1, and in metres it lands on the
        # mirror root Rb' = −2Rf − Rb for the naive/harmonic laws. omega is needed for V, A.
        cam = Cam(motion=motion, degrees=True, omega=1.0, rotation="ccw")
        if ret_law == "constant_velocity":                                   # splice, see header
            c, n = cam.cycloidal, cam.naive
            ret = cam.thetas >= cam.shifts[1]
            c.S, c.V, c.A = (np.where(ret, getattr(n, k), getattr(c, k)) for k in "SVA")
        return cam

    def solve():
        cam = build()
        return cam, cam.get_base_circle(kind="cycloidal", follower="roller", roller_radius=RF,
                                        eccentricity=e, max_pressure_angle=ALPHA)["Rb"]

    (cam, rb), t_r0 = median_ms(solve)
    y, y1 = cam.cycloidal.S, cam.cycloidal.V / cam.omega
    rb_check = R0_CHECK - RF

    def phi_at():                                  # their expression, at Rb = r0 − Rf
        return np.degrees(np.max(np.abs(np.arctan((y1 - e) / (y + np.sqrt((rb_check + RF)**2 + e**2))))))

    phi, t_phi = median_ms(phi_at)
    rb_round = cam.get_base_circle(kind="cycloidal", follower="roller", roller_radius=RF,
                                   eccentricity=e, max_pressure_angle=phi)["Rb"]
    if abs(rb_round - rb_check) > 1e-6:            # our copy of their formula must be theirs
        print(f"WARNING e={e:g}: round trip gave Rb = {rb_round:.6f}, expected {rb_check:.6f}")
    d0 = np.max(np.abs(y1 - e) / np.tan(np.radians(ALPHA)) - y)  # same data, √(Rp² − ε²)
    return dict(rp=rb + RF, rb=rb, fixed=float(np.hypot(max(d0, 0.0), e)), phi=phi,
                t_r0=t_r0, t_phi=t_phi, mirror=rb < 0)


# ------------------------------------------------------------------ ours (mechdesign)
def ours(e, ret_law, alpha_return=ALPHA):
    from mechdesign.core.cam import (Programme, Segment, TranslatingFollower, design_cam,
                                     min_base_radius_translating)

    def programme():
        r, d1, f, d2 = np.radians(SPANS)
        return Programme([Segment("rise", r, "cycloidal", H / 1e3), Segment("dwell", d1),
                          Segment("return", f, ret_law, H / 1e3), Segment("dwell", d2)])

    fol = TranslatingFollower(kind="roller", offset=e / 1e3, roller_radius=RF / 1e3)
    r0, t_r0 = median_ms(lambda: min_base_radius_translating(
        programme(), fol, alpha_rise=np.radians(ALPHA), alpha_return=np.radians(alpha_return),
        offset=e / 1e3)[0])
    prof, t_phi = median_ms(lambda: design_cam(programme(), fol, base_radius=R0_CHECK / 1e3,
                                               rotation=+1, points=3600))
    return dict(rp=r0 * 1e3, phi=float(np.degrees(prof.pressure_angle.max())), t_r0=t_r0, t_phi=t_phi)


def main() -> int:
    import matplotlib
    matplotlib.use("Agg")                          # mechanism imports pyplot at import time
    try:
        import mechanism  # noqa: F401
        from importlib.metadata import version
        peer = f"mechanism {version('mechanism')}"
    except ImportError:
        print("mechanism is not installed here: pip install 'mechanism==1.1.10' (see header)")
        peer = None
    try:
        import mechdesign.core.cam  # noqa: F401
        have_ours = True
    except ImportError as exc:
        print(f"mechdesign.core.cam not importable ({exc}): printing the peer only")
        have_ours = False

    print(f"\nTranslating roller follower, h = {H:g} mm, roller {RF:g} mm, cam ccw, "
          f"[α] = {ALPHA:g}° on rise and return; α_max checked at pitch r0 = {R0_CHECK:g} mm")
    print("r0 = PITCH base radius (theirs: Rb + Rf). Times: median of 20 calls, ms.\n")
    head = (f"{'case':<34}{'library':<20}{'r0 [α]=30° (mm)':>16}{'theirs, −ε² (mm)':>18}"
            f"{'α_max @50 (deg)':>17}{'t r0':>9}{'t α':>9}")
    print(head)
    print("-" * len(head))
    cases = [(12.0, "cycloidal"), (12.0, "constant_velocity"), (0.0, "cycloidal"), (0.0, "constant_velocity")]
    for e, law in cases:
        star = "*" if law == "constant_velocity" else " "
        name = f"e={e:+.0f} mm, {'cycloidal' if law == 'cycloidal' else 'uniform'} return{star}"
        t = theirs(e, law) if peer else None
        o = ours(e, law) if have_ours else None
        if t:
            note = "  (fsolve took the mirror root Rb' = −2Rf − Rb)" if t["mirror"] else ""
            print(f"{name:<34}{peer:<20}{t['rp']:>16.4f}{t['fixed']:>18.4f}{t['phi']:>16.4f}†"
                  f"{t['t_r0']:>9.3f}{t['t_phi']:>9.3f}{note}")
        if o:
            print(f"{'' if t else name:<34}{'mechdesign (ours)':<20}{o['rp']:>16.4f}{'':>18}{o['phi']:>17.4f}"
                  f"{o['t_r0']:>9.3f}{o['t_phi']:>9.3f}")
        if t and o:
            print(f"{'':<34}{'|ours − theirs|':<20}{abs(o['rp'] - t['rp']):>16.4f}"
                  f"{abs(o['rp'] - t['fixed']):>18.4f}{abs(o['phi'] - t['phi']):>17.4f}")
        print()
    if have_ours:                                  # no peer value: mechanism has one [α] only
        o = ours(12.0, "constant_velocity", alpha_return=70.0)
        print(f"ours only (no peer equivalent), textbook limits [α]rise 30° / [α]return 70°, "
              f"e=+12 mm, uniform return: r0 = {o['rp']:.4f} mm\n  (set by the rise start, "
              f"ds/dδ = 0: tan α = e/√(r0² − e²) ≤ tan 30° gives r0 ≥ 2e)")
    print("* spliced: cycloidal rise + 'naive' (constant-velocity) return arrays fed to "
          "mechanism's solver, outside its public API.")
    print("† their φ expression evaluated by us on their arrays (no public call; round-trip "
          "through get_base_circle checked).")
    print("'theirs, −ε²': their data and limit with √(Rp² − ε²); |Δ| there is ours vs. that.")
    print("t r0: theirs = Cam() (all 3 laws) + get_base_circle; ours = Programme + "
          "min_base_radius_translating. t α: theirs = one numpy expression on ready arrays; "
          "ours = full design_cam (profile, normals, curvature), not like for like.")
    return 0


if __name__ == "__main__":
    sys.exit(main())
