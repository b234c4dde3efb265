"""`mechdesign check` of every example brief (every group): time per brief, in-process and
as a fresh process.

Run:  python benchmarks/bench_check.py [--repeat 5]

in-process   the `check` command invoked in this process (the CLI already imported), one
             fresh interpreter per brief so each pays for its own machine's brief models:
             the first call (cold: the brief models imported and built) and the best of
             the following ones (warm)
fresh        `python -m mechdesign check BRIEF` as a user starts it: interpreter start-up
             and every import included (median of --repeat runs), wall and CPU time
             (CPU: user + system, less sensitive to other work on a shared machine)
start-up     `python -c "import mechdesign.cli"`: the floor every fresh run pays

Targets: issue 17, `mechdesign check` of any example under 0.3 s; issue 22, ≤ 1.5× the
start-up (printed against both the CLI's import and the bare interpreter, CPU time). Validation never runs
a synthesis or the linkage engine (the machines' feasibility checks run in `mechdesign
run`), and it imports no `mechdesign.machines` module: the table says which engine
modules a check loaded. Prints a table; never fails on time.
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

_IN_PROCESS = r"""
import json, sys, time
from typer.testing import CliRunner
from mechdesign.cli import app
runner = CliRunner()
times = []
for _ in range(int(sys.argv[2])):
    t = time.perf_counter()
    result = runner.invoke(app, ["check", sys.argv[1]])
    times.append(time.perf_counter() - t)
    assert result.exit_code == 0, result.output
engine = sorted(m for m in sys.modules
                if m.startswith(("mechdesign.machines", "mechdesign.core.mechanism",
                                 "mechdesign.core.kinematics", "mechdesign.core.kinetostatics")))
print(json.dumps({"times": times, "engine": engine}))
"""


def _fresh(args: list[str], repeat: int) -> tuple[float, float]:
    """Median wall time and median CPU time (user + system: what the process itself
    needs, whatever else the machine is doing) of ``repeat`` fresh processes."""
    walls, cpus = [], []
    for _ in range(repeat):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t = time.perf_counter()
        subprocess.run([sys.executable, *args], cwd=ROOT, check=True, capture_output=True)
        walls.append(time.perf_counter() - t)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpus.append(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)
    return statistics.median(walls), statistics.median(cpus)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    briefs = sorted((ROOT / "designs").glob("*.yaml"))
    bare = _fresh(["-c", "pass"], args.repeat)
    floor = _fresh(["-c", "import mechdesign.cli"], args.repeat)
    print(f"{'brief':22s} {'cold [s]':>9s} {'warm [s]':>9s} {'fresh [s]':>10s} "
          f"{'fresh CPU [s]':>14s}  engine modules")
    worst = worst_cpu = 0.0
    for brief in briefs:
        out = subprocess.run([sys.executable, "-c", _IN_PROCESS, str(brief),
                              str(max(2, args.repeat))],
                             cwd=ROOT, check=True, capture_output=True, text=True)
        data = json.loads(out.stdout.strip().splitlines()[-1])
        cold, warm = data["times"][0], min(data["times"][1:])
        fresh, cpu = _fresh(["-m", "mechdesign", "check", str(brief)], args.repeat)
        worst, worst_cpu = max(worst, fresh), max(worst_cpu, cpu)
        print(f"{brief.name:22s} {cold:9.3f} {warm:9.3f} {fresh:10.3f} {cpu:14.3f}  "
              f"{', '.join(data['engine']) or 'none'}")
    print(f"interpreter start-up (python -c pass): {bare[0]:.3f} s wall, {bare[1]:.3f} s CPU")
    print(f"CLI start-up (python -c 'import mechdesign.cli'): {floor[0]:.3f} s wall, "
          f"{floor[1]:.3f} s CPU")
    print(f"slowest fresh check {worst:.3f} s wall, {worst_cpu:.3f} s CPU (load average "
          f"{os.getloadavg()[0]:.2f} on {os.cpu_count()} CPUs)")
    for label, ref in (("the CLI's start-up", floor), ("the bare interpreter's", bare)):
        ratio = worst_cpu / max(ref[1], 1e-3)
        print(f"  = {ratio:.1f}× {label} in CPU time (issue 22's target ≤ 1.5× start-up: "
              f"{'met' if ratio <= 1.5 else 'MISSED'})")


if __name__ == "__main__":
    main()
