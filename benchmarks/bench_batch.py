"""Batch throughput: `mechdesign batch` against the same briefs run one by one.

Run:  python benchmarks/bench_batch.py [--briefs 40] [--jobs 2] [--format md,pdf]

Target (issue 7, 2-core machine): 40 briefs through `mechdesign batch --jobs 2` in at
most 0.6 x the time of 40 sequential `mechdesign run` commands (each a new process, as a
teacher's shell loop would do). The 40 briefs are the shipped examples and their data
groups, repeated in order until there are 40, each written as its own brief file (a
group applied as `default`), so both sides do exactly the same work. Prints the figures;
it is not a test and never fails on time.
"""
from __future__ import annotations

import argparse
import os
import shutil
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
    args = ap.parse_args()
    env = dict(os.environ, PYTHONWARNINGS="ignore")
    with tempfile.TemporaryDirectory(prefix="mechdesign-bench-") as tmp:
        tmp = Path(tmp)
        (tmp / "briefs").mkdir()
        briefs = make_briefs(tmp / "briefs", args.briefs)
        print(f"{len(briefs)} briefs, formats {args.format}, {os.cpu_count()} CPUs "
              f"(usable: {len(os.sched_getaffinity(0))})")

        start = time.perf_counter()
        per_run = []
        for brief in briefs:
            t0 = time.perf_counter()
            subprocess.run([sys.executable, "-m", "mechdesign", "run", str(brief), "-o",
                            str(tmp / "seq" / brief.stem), "-f", args.format],
                           check=True, capture_output=True, env=env)
            per_run.append(time.perf_counter() - t0)
        sequential = time.perf_counter() - start
        print(f"sequential: {len(briefs)} x `mechdesign run`: {sequential:7.1f} s "
              f"(mean {sequential / len(briefs):.2f} s, slowest {max(per_run):.2f} s)")

        start = time.perf_counter()
        done = subprocess.run([sys.executable, "-m", "mechdesign", "batch", str(tmp / "briefs"),
                               "--jobs", str(args.jobs), "-o", str(tmp / "batch"), "-f", args.format],
                              capture_output=True, text=True, env=env)
        batch = time.perf_counter() - start
        if done.returncode != 0:
            print(done.stderr[-2000:])
            return 1
        ratio = batch / sequential
        print(f"batch --jobs {args.jobs}:          {batch:7.1f} s")
        print(f"ratio batch / sequential: {ratio:.2f} (target <= 0.60: "
              f"{'met' if ratio <= 0.6 else 'MISSED'})")
        shutil.rmtree(tmp / "seq", ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
