"""The whole `mechdesign run`, as a user starts it: wall time by phase, imports included.

Run:  python benchmarks/bench_run.py [--brief designs/shaper.yaml] [--repeat 5]
                                     [--serial] [--imports] [--profile]

Each repetition is a fresh process (`python -m mechdesign run BRIEF --timings`), so
the interpreter's start-up and every import count, as they do for a student. The
`--timings` lines give the phases:

  start-up      process start → first stage (interpreter, imports, reading the brief)
  compute       the engineering stages (incl. the self-checks)
  render        figures and drawing sheets (in two processes on a multi-core machine),
                Markdown, results.json and data files, until the last file is written
  pandoc        waiting for pandoc's Markdown → typst after that (it starts as soon
                as the Markdown exists and mostly runs while the last figures are saved)
  typst         typst's compilation of report.pdf (in-process) and moving the files
  PDF           pandoc + typst: the part of the run that is there only for the PDF
  total         process start → report in place

Targets (issue 8, 2-core machine): total ≤ 3 s; the PDF step no more than a quarter of
a full run. `--serial` also measures with MECHDESIGN_SERIAL=1 (everything in one
process). `--imports` lists the slowest imports (python -X importtime); `--profile`
prints the top of a cProfile of one in-process run. Prints a table; never fails on time.
"""
from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
LINE = re.compile(r"^\s*(\d+\.\d+) s\s+(.*)$")


def _one_run(brief: Path, out: Path, serial: bool) -> dict[str, float]:
    env = dict(os.environ, MPLBACKEND="Agg")
    env["MECHDESIGN_SERIAL"] = "1" if serial else "0"
    proc = subprocess.run([sys.executable, "-m", "mechdesign", "run", str(brief), "-o", str(out),
                           "--timings"], capture_output=True, text=True, env=env)
    if proc.returncode != 0:
        raise SystemExit(f"the run failed:\n{proc.stderr}")
    marks = []
    for line in proc.stderr.splitlines():
        m = LINE.match(line)
        if m:
            marks.append((float(m.group(1)), m.group(2).strip()))

    def first(prefix: str) -> float:
        return next(t for t, text in marks if text.startswith(prefix))

    t_stage = first("[1/")
    t_render = first("rendering")
    t_written = first("rendering figures and sheets: all written")
    t_typst = first("rendering PDF: typst")
    t_done = first("done")
    return {"start-up": t_stage, "compute": t_render - t_stage,
            "render": t_written - t_render,
            "pandoc": t_typst - t_written, "typst": t_done - t_typst,
            "PDF": t_done - t_written, "total": t_done}


def _table(rows: list[dict[str, float]], label: str) -> None:
    keys = ["start-up", "compute", "render", "pandoc", "typst", "PDF", "total"]
    med = {k: statistics.median(r[k] for r in rows) for k in keys}
    print(f"\n{label} (median of {len(rows)} fresh processes)\n")
    print("| phase | seconds |")
    print("|---|---:|")
    for k in keys:
        print(f"| {k} | {med[k]:.2f} |")
    print(f"| PDF share of the run | {med['PDF'] / med['total']:.0%} |")
    return med


def _imports(brief: Path) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        proc = subprocess.run([sys.executable, "-X", "importtime", "-m", "mechdesign", "run",
                               str(brief), "-o", tmp], capture_output=True, text=True,
                              env=dict(os.environ, MPLBACKEND="Agg", MECHDESIGN_SERIAL="1"))
    rows = []
    for line in proc.stderr.splitlines():
        m = re.match(r"import time:\s+\d+ \|\s+(\d+) \|( *)(\S+)", line)
        if m and len(m.group(2)) <= 2:           # top-level and first-level imports
            rows.append((int(m.group(1)) / 1e6, m.group(3)))
    rows.sort(reverse=True)
    print("\nslowest imports (cumulative seconds, incl. what they import)\n")
    for sec, name in rows[:15]:
        print(f"  {sec:6.3f}  {name}")


def _profile(brief: Path) -> None:
    import cProfile
    import pstats

    os.environ["MECHDESIGN_SERIAL"] = "1"
    from mechdesign.runner import run_one

    with tempfile.TemporaryDirectory() as tmp:
        prof = cProfile.Profile()
        prof.enable()
        run_one(brief, out_dir=Path(tmp))
        prof.disable()
    print("\ncProfile of one in-process run (serial), top 25 by own time\n")
    pstats.Stats(prof).sort_stats("tottime").print_stats(25)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--brief", default=str(ROOT / "designs" / "shaper.yaml"))
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--serial", action="store_true", help="also measure in one process")
    parser.add_argument("--imports", action="store_true", help="list the slowest imports")
    parser.add_argument("--profile", action="store_true", help="cProfile one in-process run")
    args = parser.parse_args()
    brief = Path(args.brief).resolve()
    print(f"mechdesign run {brief.name}: {os.cpu_count()} CPUs")
    with tempfile.TemporaryDirectory() as tmp:
        _one_run(brief, Path(tmp) / "warm", False)       # font caches, page cache
        modes = [False, True] if args.serial else [False]
        for serial in modes:
            rows = [_one_run(brief, Path(tmp) / f"r{i}", serial) for i in range(args.repeat)]
            med = _table(rows, "serial (one process)" if serial else
                         "default (figures and sheets saved by a helper process)")
            print(f"\ntarget total ≤ 3 s: {'PASS' if med['total'] <= 3.0 else 'MISS'} "
                  f"({med['total']:.2f} s); PDF ≤ 1/4 of the run: "
                  f"{'PASS' if med['PDF'] <= med['total'] / 4 else 'MISS'}")
    if args.imports:
        _imports(brief)
    if args.profile:
        _profile(brief)


if __name__ == "__main__":
    main()
