"""Batch throughput: `mechdesign batch` against the same briefs run one by one.

Run:  python benchmarks/bench_batch.py [--briefs 40] [--jobs 2] [--format md,pdf] [--rounds 2]

Target (issue 7, 2-core machine): 40 briefs through `mechdesign batch --jobs 2` in at
most 0.6 x the time of 40 sequential `mechdesign run` commands (each a new process, as a
teacher's shell loop would do). The 40 briefs are the shipped examples and their data
groups, repeated in order until there are 40, each written as its own brief file (a
group applied as `default`), so both sides do exactly the same work. The two are alternated
(round 1: sequential then batch, round 2: batch then sequential, …) so a change in the
shared machine's load does not favour one; each is timed to the exit of its last process.
Prints every round, the medians and the load average; it is not a test and never fails on
time.
"""
from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]


def make_briefs(folder: Path, count: int) -> list[Path]:
    """``count`` brief files: every shipped example and each of its groups, in turn."""
    variants = []
    for path in sorted((ROOT / "designs").glob("*.yaml")):
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
        labels = list((data.get("groups") or {}).get("variants") or {None: None})
        variants += [(path, label) for label in labels]
    briefs = []
    for i in range(count):
        path, label = variants[i % len(variants)]
        text = path.read_text(encoding="utf-8")
        if label is not None:
            data = yaml.safe_load(text)
            data["groups"]["default"] = label
            text = yaml.safe_dump(data, allow_unicode=True, sort_keys=False)
        target = folder / f"b{i:02d}_{path.stem}.yaml"
        target.write_text(text, encoding="utf-8")
        briefs.append(target)
    return briefs


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--briefs", type=int, default=40)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--format", default="md,pdf")
    ap.add_argument("--rounds", type=int, default=2, help="alternated rounds")
    args = ap.parse_args()
    env = dict(os.environ, PYTHONWARNINGS="ignore")
    with tempfile.TemporaryDirectory(prefix="mechdesign-bench-") as tmp:
        tmp = Path(tmp)
        (tmp / "briefs").mkdir()
        briefs = make_briefs(tmp / "briefs", args.briefs)
        print(f"{len(briefs)} briefs, formats {args.format}, {os.cpu_count()} CPUs "
              f"(usable: {len(os.sched_getaffinity(0))})")

        def sequential(out: Path) -> float:
            start = time.perf_counter()
            for brief in briefs:
                subprocess.run([sys.executable, "-m", "mechdesign", "run", str(brief), "-o",
                                str(out / brief.stem), "-f", args.format],
                               check=True, capture_output=True, env=env)
            return time.perf_counter() - start

        def batch(out: Path) -> float:
            start = time.perf_counter()
            done = subprocess.run([sys.executable, "-m", "mechdesign", "batch",
                                   str(tmp / "briefs"), "--jobs", str(args.jobs), "-o", str(out),
                                   "-f", args.format], capture_output=True, text=True, env=env)
            if done.returncode != 0:
                raise SystemExit(done.stderr[-2000:])
            return time.perf_counter() - start

        seq, bat = [], []
        for r in range(args.rounds):
            order = [("sequential", sequential, seq), ("batch", batch, bat)]
            if r % 2:
                order.reverse()
            for name, fn, into in order:
                into.append(fn(tmp / f"{name}-{r}"))
                shutil.rmtree(tmp / f"{name}-{r}", ignore_errors=True)
            print(f"round {r + 1}: sequential {seq[-1]:6.1f} s, batch --jobs {args.jobs} "
                  f"{bat[-1]:6.1f} s, ratio {bat[-1] / seq[-1]:.2f} "
                  f"(load average {os.getloadavg()[0]:.2f})", flush=True)
        ratios = [b / q for b, q in zip(bat, seq)]
        ratio = statistics.median(ratios)
        print(f"sequential: median {statistics.median(seq):.1f} s "
              f"({statistics.median(seq) / len(briefs):.2f} s a brief); batch: median "
              f"{statistics.median(bat):.1f} s")
        print(f"ratio batch / sequential: median {ratio:.2f} (rounds: "
              f"{', '.join(f'{x:.2f}' for x in ratios)}; target <= 0.60: "
              f"{'met' if ratio <= 0.6 else 'MISSED'})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
