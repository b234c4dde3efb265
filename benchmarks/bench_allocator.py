"""glibc's allocator settings (mechdesign.allocator.prefer_heap) on repeated large calls.

Run:  python benchmarks/bench_allocator.py [--points 100000] [--calls 15] [--rounds 3]

Each setting runs in a fresh process (mallopt is process-wide and cannot be undone): the
shaper's core pipeline (kinematics + kinetostatics + flywheel) called ``--calls`` times at
``--points`` crank positions after one warm-up call, as a library user or `watch` would
call it; the median call time and the process's minor page faults per call.

  default     glibc untouched (dynamic mmap threshold, trim threshold 128 kB)
  mmap        the mmap threshold at 1 GiB only (what prefer_heap did before issue 22)
  mmap+trim   the mmap and the trim threshold at 1 GiB (prefer_heap now, the CLI's setting)

The settings are interleaved (round 1: default, mmap, mmap+trim; round 2: …) and the
median over rounds of the per-process medians is printed with the spread (min–max of the
rounds). Prints a table; never fails on time.
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MODES = ("default", "mmap", "mmap+trim")


def _child(mode: str, points: int, calls: int) -> None:
    from mechdesign.allocator import prefer_heap

    if mode == "mmap":
        prefer_heap(trim=False)
    elif mode == "mmap+trim":
        prefer_heap(trim=True)
    sys.path.insert(0, str(ROOT / "benchmarks"))
    from bench_shaper import _core

    core, _ = _core(str(ROOT / "designs" / "shaper.yaml"), points)
    core()                                                   # warm-up
    faults0 = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    times = []
    for _ in range(calls):
        t0 = time.perf_counter()
        core()
        times.append((time.perf_counter() - t0) * 1e3)
    faults = resource.getrusage(resource.RUSAGE_SELF).ru_minflt - faults0
    print(json.dumps({"ms": statistics.median(times), "faults": faults / calls}))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=100_000)
    ap.add_argument("--calls", type=int, default=15)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--child", choices=MODES)
    a = ap.parse_args()
    if a.child:
        _child(a.child, a.points, a.calls)
        return
    got: dict[str, list[dict]] = {m: [] for m in MODES}
    for _ in range(a.rounds):
        for mode in MODES:
            out = subprocess.run([sys.executable, __file__, "--child", mode, "--points",
                                  str(a.points), "--calls", str(a.calls)],
                                 capture_output=True, text=True, check=True)
            got[mode].append(json.loads(out.stdout))
    print(f"shaper core pipeline, {a.points:,} crank positions, {a.calls} calls per process, "
          f"{a.rounds} interleaved rounds; load average {os.getloadavg()[0]:.2f} "
          f"on {os.cpu_count()} CPUs")
    print(f"{'setting':<11} {'median ms/call':>15} {'spread (rounds)':>17} {'page faults/call':>17}")
    for mode in MODES:
        ms = [r["ms"] for r in got[mode]]
        faults = statistics.median(r["faults"] for r in got[mode])
        print(f"{mode:<11} {statistics.median(ms):15.1f} {min(ms):8.1f}–{max(ms):<8.1f} {faults:17.0f}")


if __name__ == "__main__":
    main()
