"""Shaper benchmark: the core pipeline's time and memory, and our kinematics against
hand-written closed forms.

Run:  python benchmarks/bench_shaper.py  [--repeat 20] [--big 1000000] [--angles 100000]

Targets (issues 2 and 8, 2-core machine): core pipeline (kinematics + kinetostatics +
flywheel) at 3600 crank positions <= 50 ms, and at 1,000,000 positions <= 2 s with a
peak memory below 2 GB; the kinematics of a four-bar and of an offset slider-crank
(positions, velocities, accelerations) at 100,000 crank angles within 2x of a
hand-written closed-form numpy solution of the same linkage. Prints a table; it is not a
test and never fails on time. The whole `mechdesign run` by phase (imports, figures, PDF)
is benchmarks/bench_run.py; the peer libraries are benchmarks/peers.py.

The 1,000,000-position case runs in a fresh subprocess (one call, as a run with that
grid would): its time is that call's, and its peak memory is the subprocess's maximum
resident set size (its getrusage ru_maxrss at the end, so it includes the interpreter
and the imported modules, ~100 MB). It is measured as the command line runs it, with
glibc serving large arrays from the heap (mechdesign.allocator.prefer_heap), and once
without that setting (the default allocator), for comparison.
"""
from __future__ import annotations

import argparse
import dataclasses
import json
import os
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def _median_ms(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append((time.perf_counter() - start) * 1e3)
    return statistics.median(times)


def _core(brief_path: str, grid_points: int | None = None):
    """The shaper's core pipeline for a brief, as a function to time."""
    from mechdesign.brief.loader import load_brief
    from mechdesign.machines import get_machine
    from mechdesign.machines.shaper import stages as shaper

    brief = load_brief(brief_path)
    params = get_machine(brief.machine).to_params(brief)
    if grid_points is not None:
        params = dataclasses.replace(params, grid_points=grid_points)
    syn = shaper.synthesize(params)

    def core():
        k, mech, motion = shaper.kinematics(syn, params)
        f = shaper.kinetostatics(k, mech, motion, params)
        return shaper.flywheel(k, f, params)
    return core, params


def _big_child(brief_path: str, grid_points: int, heap: bool) -> None:
    """In the subprocess: one core call at a large grid; prints its time as JSON."""
    if heap:
        from mechdesign.allocator import prefer_heap

        prefer_heap()
    core, _ = _core(brief_path, grid_points)
    start = time.perf_counter()
    fl = core()
    ms = (time.perf_counter() - start) * 1e3
    print(json.dumps({"ms": ms, "J": fl.inertia,
                      "maxrss_kb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss}))


def _big_case(brief_path: str, grid_points: int, heap: bool) -> tuple[float, float]:
    """Time [ms] and peak memory [MB] of one core call at ``grid_points``, in a subprocess."""
    out = subprocess.run([sys.executable, __file__, "--child", str(grid_points),
                          "--brief", brief_path] + ([] if heap else ["--no-heap"]),
                         capture_output=True, text=True, check=True)
    data = json.loads(out.stdout)
    return data["ms"], data["maxrss_kb"] / 1024.0


# ------------------------------------------------------------------ hand-written references
# Textbook closed forms for one linkage each, in real arithmetic, computing the same
# quantities as Mechanism.solve (every moving point's position, velocity and acceleration,
# every moving link's angle, ω and α). Written for this benchmark, independent of
# mechdesign.core.

def four_bar_by_hand(phi, a, b, c, d, w2):
    """Crank a about (0, 0), coupler b (B→C), rocker c (D→C), D = (d, 0); C left of B→D."""
    c2, s2 = np.cos(phi), np.sin(phi)
    bx, by = a * c2, a * s2
    vbx, vby = -w2 * by, w2 * bx
    abx, aby = -w2 * w2 * bx, -w2 * w2 * by
    dx, dy = d - bx, -by
    dist2 = dx * dx + dy * dy
    beta = np.arccos((b * b + dist2 - c * c) / (2.0 * b * np.sqrt(dist2)))
    th3 = np.arctan2(dy, dx) + beta
    c3, s3 = np.cos(th3), np.sin(th3)
    cx, cy = bx + b * c3, by + b * s3
    c4, s4 = (cx - d) / c, cy / c
    th4 = np.arctan2(s4, c4)
    s34 = s3 * c4 - c3 * s4                                # sin(θ3 − θ4)
    w3 = a * w2 * (s4 * c2 - c4 * s2) / (b * s34)          # a·ω2·sin(θ4 − θ2) / (b·sin(θ3 − θ4))
    w4 = a * w2 * (s3 * c2 - c3 * s2) / (c * s34)
    rx = -c * w4 * w4 * c4 + b * w3 * w3 * c3 + a * w2 * w2 * c2
    ry = -c * w4 * w4 * s4 + b * w3 * w3 * s3 + a * w2 * w2 * s2
    al3 = -(rx * c4 + ry * s4) / (b * s34)
    al4 = -(rx * c3 + ry * s3) / (c * s34)
    vcx, vcy = vbx - w3 * b * s3, vby + w3 * b * c3
    acx = abx - al3 * b * s3 - w3 * w3 * b * c3
    acy = aby + al3 * b * c3 - w3 * w3 * b * s3
    return (bx, by, vbx, vby, abx, aby, cx, cy, vcx, vcy, acx, acy,
            th3, w3, al3, th4, w4, al4)


def slider_crank_by_hand(phi, r, l, e, w2):
    """Crank r about (0, 0), rod l to the slider C on the guide y = e, C ahead (+x)."""
    c2, s2 = np.cos(phi), np.sin(phi)
    bx, by = r * c2, r * s2
    vbx, vby = -w2 * by, w2 * bx
    abx, aby = -w2 * w2 * bx, -w2 * w2 * by
    h = e - by
    x = bx + np.sqrt(l * l - h * h)
    c3, s3 = (x - bx) / l, h / l
    th3 = np.arctan2(s3, c3)
    w3 = -r * w2 * c2 / (l * c3)                           # from r·sinφ + l·sinθ3 = e
    v = -r * w2 * s2 - l * w3 * s3
    al3 = (r * w2 * w2 * s2 + l * w3 * w3 * s3) / (l * c3)
    a = -r * w2 * w2 * c2 - l * al3 * s3 - l * w3 * w3 * c3
    return bx, by, vbx, vby, abx, aby, x, v, a, th3, w3, al3


def _linkage_rows(n: int, repeat: int) -> list:
    """(what, ours ms, hand ms, max relative difference) for the two linkages."""
    from mechdesign.core.mechanism import RRP, RRR, Crank, Mechanism

    phi = np.linspace(0.0, 2 * np.pi, n, endpoint=False) + 1e-3
    four = (Mechanism("1", {"A": 0j, "D": 9 + 0j})
            .add(Crank("crank", "2", "A", "B", 5.0, 10.0))
            .add(RRR("g", "3", "4", "B", "D", "C", 8.0, 8.0, 1)))
    slider = (Mechanism("1", {"O": 0j})
              .add(Crank("crank", "2", "O", "B", 0.05, 10.0))
              .add(RRP("g", "3", "4", "B", "C", 0.2, 0.01j, 0.0, 1, "1")))

    def rel(ours, hand):
        return max(float(np.max(np.abs(o - h)) / np.max(np.abs(h))) for o, h in zip(ours, hand))

    m = four.solve(phi)
    B, C, l3, l4 = m.points["B"], m.points["C"], m.links["3"], m.links["4"]
    ours = [f(p) for p in (B, C) for q in ("pos", "vel", "acc") for f in
            (lambda p: getattr(p, q).real, lambda p: getattr(p, q).imag)]
    ours += [getattr(l, q) for l in (l3, l4) for q in ("angle", "omega", "alpha")]
    err4 = rel(ours, four_bar_by_hand(phi, 5.0, 8.0, 8.0, 9.0, 10.0))
    m = slider.solve(phi)
    B, C, l3 = m.points["B"], m.points["C"], m.links["3"]
    ours = [f(p) for p in (B,) for q in ("pos", "vel", "acc") for f in
            (lambda p: getattr(p, q).real, lambda p: getattr(p, q).imag)]
    ours += [C.pos.real, C.vel.real, C.acc.real, l3.angle, l3.omega, l3.alpha]
    errs = rel(ours, slider_crank_by_hand(phi, 0.05, 0.2, 0.01, 10.0))

    def timed(fn):
        fn()
        return _median_ms(fn, repeat)
    return [(f"four-bar kinematics, {n} angles", timed(lambda: four.solve(phi)),
             timed(lambda: four_bar_by_hand(phi, 5.0, 8.0, 8.0, 9.0, 10.0)), err4),
            (f"slider-crank kinematics, {n} angles", timed(lambda: slider.solve(phi)),
             timed(lambda: slider_crank_by_hand(phi, 0.05, 0.2, 0.01, 10.0)), errs)]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=20, help="repetitions of the core timing")
    parser.add_argument("--brief", default=str(ROOT / "designs" / "shaper.yaml"))
    parser.add_argument("--big", type=int, default=1_000_000,
                        help="crank positions of the large core case (0: skip it)")
    parser.add_argument("--angles", type=int, default=100_000,
                        help="crank angles of the four-bar / slider-crank rows")
    parser.add_argument("--child", type=int, help=argparse.SUPPRESS)
    parser.add_argument("--no-heap", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        _big_child(args.brief, args.child, heap=not args.no_heap)
        return

    core, params = _core(args.brief)
    core()  # warm-up (imports, caches)
    core_ms = _median_ms(core, args.repeat)

    rows = [("core pipeline, %d crank positions (median of %d)" % (params.grid_points, args.repeat),
             core_ms, 50.0, None)]
    if args.big:
        for heap in (False, True):
            ms, mb = _big_case(args.brief, args.big, heap)
            how = "as the CLI runs it" if heap else "default allocator"
            rows.append((f"core pipeline, {args.big} positions ({how})", ms, 2000.0, mb))
    linkage_rows = _linkage_rows(args.angles, args.repeat) if args.angles else []

    print(f"mechdesign shaper benchmark  ({os.cpu_count()} CPUs, Python {sys.version.split()[0]})")
    print(f"{'what':62s} {'ms':>9s} {'target':>7s}  ok  {'peak MB':>7s}")
    for what, ms, target, mb in rows:
        ok = "yes" if ms <= target else "NO"
        mem = "" if mb is None else f"{mb:7.0f}" + ("" if mb < 2048 else " (> 2048: NO)")
        print(f"{what:62s} {ms:9.1f} {target:7.0f}  {ok:3s} {mem}")
    if linkage_rows:
        print()
        print(f"{'kinematics (pos+vel+acc), median of %d' % args.repeat:40s} {'ours ms':>8s} "
              f"{'hand ms':>8s} {'ratio':>6s} {'target':>6s}  ok  max rel diff")
        for what, ours, hand, err in linkage_rows:
            ratio = ours / hand
            print(f"{what:40s} {ours:8.2f} {hand:8.2f} {ratio:6.2f} {2.0:6.1f}  "
                  f"{'yes' if ratio <= 2.0 else 'NO ':3s} {err:.1e}")


if __name__ == "__main__":
    main()
