"""The whole `mechdesign run`, as a user starts it: wall time to process exit, and each
output's marginal cost.

Run:  python benchmarks/bench_run.py [--brief designs/shaper.yaml] [--repeat 5]
                                     [--big 100000] [--imports] [--profile]

Every run is a fresh process (`python -m mechdesign run BRIEF -f FORMATS --timings`) timed
by this script's wall clock from the start of the subprocess to its exit, so the
interpreter's start-up, every import and whatever happens after the "done" line (the
interpreter's shutdown) count, as they do for a student. The configurations run in
interleaved rounds (round r: md, md+pdf, md+pdf+dxf, then the --big grid's md and
md+pdf+dxf, the order rotated by r), so the machine's load hits all alike; the table gives
medians and the spread (first–third quartile) of the rounds, with the load average.

  md, md+pdf, md+pdf+dxf       whole runs to process exit, the render cache off (cold:
                               every figure drawn, every PDF compiled)
  md+pdf, warm cache           the same with the render cache filled by an earlier run
                               of the brief (render/cache.py: a re-run, or watch)
  CPU                          user + system time of the run and its helper processes:
                               what the run costs, less sensitive to the machine's load
  PDF (marginal)               md+pdf − md: what the PDF adds (pandoc, typst, the sheets' PDFs)
  DXF (marginal)               md+pdf+dxf − md+pdf
  start-up, compute            from the --timings lines: process start → first stage, and the
                               engineering stages (medians)
  after "done"                 exit − the "done" line: the interpreter's shutdown (the CLI now
                               leaves with os._exit once its outputs are flushed)
  big grid                     the same brief at analysis.grid_points = --big (a 100,000-point
                               run): md and md+pdf+dxf, and their ratio

Bytecode: the runs are started without PYTHONDONTWRITEBYTECODE (set in some CI and agent
shells), so that mechdesign's modules load from their compiled bytecode as they do after an
installation (the warm-up run writes it).

Targets (issue 22, 2-core machine): the shaper's md+pdf run ≤ 2.0 s to process exit; the
--big run with every output ≤ 2× its md-only run. Prints a table; never fails on time.
"""
from __future__ import annotations

import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
LINE = re.compile(r"^\s*(\d+\.\d+) s\s+(.*)$")


def _one_run(brief: Path, out: Path, formats: str, cache: str = "off") -> dict[str, float]:
    """Wall time of one fresh `mechdesign run` to its exit, its CPU time (user + system of
    the process and its helpers) and its --timings marks. ``cache``: MECHDESIGN_CACHE."""
    env = dict(os.environ, MPLBACKEND="Agg", MECHDESIGN_CACHE=cache)
    env.pop("MECHDESIGN_SERIAL", None)
    # An installed package has its bytecode (pip compiles it at install; an editable
    # install writes it on the first import): a shell that forbids writing it would make
    # every run compile mechdesign's ~80 modules from source (~0.1 s), which no user's does.
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "mechdesign", "run", str(brief), "-o", str(out),
                           "-f", formats, "--timings"], capture_output=True, text=True, env=env)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if proc.returncode != 0:
        raise SystemExit(f"the run failed:\n{proc.stderr}")
    marks = []
    for line in proc.stderr.splitlines():
        m = LINE.match(line)
        if m:
            marks.append((float(m.group(1)), m.group(2).strip()))
    stage = next((t for t, text in marks if text.startswith("[1/")), float("nan"))
    render = next((t for t, text in marks if "[" not in text[:1] and t > stage),
                  float("nan"))
    done = marks[-1][0] if marks else float("nan")
    return {"wall": wall, "cpu": cpu, "start-up": stage, "compute": render - stage,
            "done": done, "after done": wall - done}


def _spread(xs: list[float]) -> tuple[float, float, float]:
    xs = sorted(xs)
    if len(xs) < 2:
        return xs[0], xs[0], xs[0]
    q1, _, q3 = statistics.quantiles(xs, n=4, method="inclusive")
    return statistics.median(xs), q1, q3


def _fmt(sp) -> str:
    m, q1, q3 = sp
    return f"{m:6.2f} [{q1:.2f}–{q3:.2f}]"


def _big_brief(brief: Path, points: int, folder: Path) -> Path:
    """A copy of ``brief`` (beside its data files) at analysis.grid_points = points."""
    data = yaml.safe_load(brief.read_text(encoding="utf-8"))
    data.setdefault("analysis", {})["grid_points"] = points
    target = brief.parent / f".bench-{os.getpid()}-{brief.stem}-{points}.yaml"
    target.write_text(yaml.safe_dump(data, allow_unicode=True, sort_keys=False),
                      encoding="utf-8")
    return target


def measure(brief: Path, repeat: int, big: int) -> None:
    # cold: the render cache off (every figure drawn, every PDF compiled); warm: the cache
    # filled by an earlier run of the same brief (render/cache.py: what a re-run gets)
    configs = [("md", brief, "md", "off"), ("md+pdf", brief, "md,pdf", "off"),
               ("md+pdf+dxf", brief, "md,pdf,dxf", "off"),
               ("md+pdf, warm cache", brief, "md,pdf", "warm")]
    big_brief = None
    if big:
        big_brief = _big_brief(brief, big, brief.parent)
        configs += [(f"{big:,} pts md", big_brief, "md", "off"),
                    (f"{big:,} pts md+pdf+dxf", big_brief, "md,pdf,dxf", "off")]
    load0 = os.getloadavg()[0]
    got: dict[str, list[dict]] = {label: [] for label, *_ in configs}
    try:
        with tempfile.TemporaryDirectory() as tmp:
            warm = str(Path(tmp) / "cache")
            # font caches, the page cache, and the render cache of the warm runs
            _one_run(brief, Path(tmp) / "warm", "md,pdf,dxf", warm)
            for r in range(repeat):
                k = len(configs)
                for i in range(k):
                    label, b, formats, cache = configs[(r + i) % k]
                    got[label].append(_one_run(b, Path(tmp) / f"r{r}-{i}", formats,
                                               warm if cache == "warm" else cache))
    finally:
        if big_brief is not None:
            big_brief.unlink(missing_ok=True)
    load1 = os.getloadavg()[0]
    print(f"mechdesign run {brief.name}: {os.cpu_count()} CPUs, {repeat} interleaved rounds, "
          f"load average {load0:.2f} before, {load1:.2f} after (the machine is shared)")
    print()
    print("| run | to process exit [s], median [IQR] | CPU [s] | start-up | compute | "
          "after \"done\" |")
    print("|---|---:|---:|---:|---:|---:|")
    wall = {}
    for label, *_ in configs:
        rows = got[label]
        wall[label] = [x["wall"] for x in rows]
        med = {k: statistics.median(x[k] for x in rows)
               for k in ("cpu", "start-up", "compute", "after done")}
        print(f"| {label} | {_fmt(_spread(wall[label]))} | {med['cpu']:.2f} | "
              f"{med['start-up']:.2f} | {med['compute']:.2f} | {med['after done']:.3f} |")

    def marginal(a: str, b: str) -> tuple[float, float, float]:
        # per round (the two runs of a round saw the same load), then their spread
        return _spread([x - y for x, y in zip(wall[a], wall[b])])
    print()
    print("| marginal cost | seconds, median [IQR] of the per-round differences | share |")
    print("|---|---:|---:|")
    full = statistics.median(wall["md+pdf"])
    pdf = marginal("md+pdf", "md")
    print(f"| PDF (md+pdf − md) | {_fmt(pdf)} | {pdf[0] / full:.0%} of md+pdf |")
    dxf = marginal("md+pdf+dxf", "md+pdf")
    print(f"| DXF (md+pdf+dxf − md+pdf) | {_fmt(dxf)} | "
          f"{dxf[0] / statistics.median(wall['md+pdf+dxf']):.0%} of md+pdf+dxf |")
    print()
    ok = full <= 2.0
    print(f"target: md+pdf ≤ 2.0 s to process exit, cold: {'met' if ok else 'MISSED'} "
          f"({full:.2f} s)")
    warm = statistics.median(wall["md+pdf, warm cache"])
    print(f"target: md+pdf ≤ 2.0 s to process exit, warm render cache: "
          f"{'met' if warm <= 2.0 else 'MISSED'} ({warm:.2f} s)")
    if big:
        a, b = f"{big:,} pts md+pdf+dxf", f"{big:,} pts md"
        ratio = _spread([x / y for x, y in zip(wall[a], wall[b])])
        print(f"target: {big:,}-point run with md+pdf+dxf ≤ 2× its md-only run: "
              f"{'met' if ratio[0] <= 2.0 else 'MISSED'} ({ratio[0]:.2f}× "
              f"[{ratio[1]:.2f}–{ratio[2]:.2f}])")


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
    """Each figure's CPU time by kind in one in-process, serial run (md only, render cache
    off): drawn and saved (inside render.figures.figure), of it the label placement
    (render/label_layout.py) and the save (tight_layout, draw, PNG); then a cProfile
    (CPU-time clock, so the machine's load does not enter) of a second such run in the
    same process (imports and font loading already done)."""
    import collections
    import cProfile
    import pstats
    from contextlib import contextmanager

    os.environ["MECHDESIGN_SERIAL"] = "1"
    os.environ["MECHDESIGN_CACHE"] = "off"
    from mechdesign.render import (cam_figures, cycle_figures, figures, gear_figures,
                                   graphical_report, label_layout, linkage_report)
    from mechdesign.runner import run_one

    rows: dict[str, list[float]] = {}
    now: dict[str, float] = {}
    figure, save_png, place = figures.figure, figures.save_png, label_layout.place

    @contextmanager
    def timed_figure(path, *args, **kwargs):
        t0 = time.process_time()
        now.update(place=0.0, save=0.0)
        with figure(path, *args, **kwargs) as axes:
            yield axes
        rows[Path(path).name] = [time.process_time() - t0, now["place"], now["save"]]

    def timed_save(fig, path):
        t0 = time.process_time()
        save_png(fig, path)
        now["save"] = now.get("save", 0.0) + time.process_time() - t0

    def timed_place(*args, **kwargs):
        t0 = time.process_time()
        out = place(*args, **kwargs)
        now["place"] = now.get("place", 0.0) + time.process_time() - t0
        return out

    figures.figure, figures.save_png = timed_figure, timed_save
    for module in (cam_figures, cycle_figures, gear_figures):
        module.figure = timed_figure
    graphical_report.place = linkage_report.place = timed_place
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.process_time()
        run_one(brief, out_dir=Path(tmp) / "timed", formats=("md",))
        total = time.process_time() - t0
        timed = dict(rows)
        prof = cProfile.Profile(time.process_time)
        prof.enable()
        run_one(brief, out_dir=Path(tmp) / "profiled", formats=("md",))
        prof.disable()
    kinds: dict[str, list[float]] = collections.defaultdict(lambda: [0, 0.0, 0.0, 0.0])
    for name, (cpu, placing, saving) in timed.items():
        stem = name.removesuffix(".png")
        kind = ("polygons: force" if re.search(r"_graph_.*_f\d+$", stem) else
                "polygons: kinematic" if re.search(r"_graph_.*_kin$", stem) else
                re.sub(r"_\d+$", "", stem))
        k = kinds[kind]
        k[0] += 1
        k[1] += cpu
        k[2] += placing
        k[3] += saving
    print("\nCPU time [s] of each figure kind, one serial md run (the first figure also"
          " loads the fonts)\n")
    print(f"  {'figure kind':28s}  n  drawn+saved  label placement  save (tight_layout, PNG)")
    for kind, (n, cpu, placing, saving) in sorted(kinds.items(), key=lambda x: -x[1][1]):
        print(f"  {kind:28s} {n:2d}  {cpu:11.3f}  {placing:15.3f}  {saving:10.3f}")
    drawn = sum(r[0] for r in timed.values())
    print(f"  all figures: {drawn:.2f} s CPU of the run's {total:.2f} s\n")
    print("cProfile of a second run in the same process, top 25 by cumulative CPU time\n")
    pstats.Stats(prof).sort_stats("cumulative").print_stats(25)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--brief", default=str(ROOT / "designs" / "shaper.yaml"))
    parser.add_argument("--repeat", type=int, default=5,
                        help="interleaved rounds (0: none, e.g. with --profile alone)")
    parser.add_argument("--big", type=int, default=100_000,
                        help="grid points of the large run (0: skip it)")
    parser.add_argument("--imports", action="store_true", help="list the slowest imports")
    parser.add_argument("--profile", action="store_true",
                        help="cProfile one in-process run; CPU time of each figure kind")
    args = parser.parse_args()
    brief = Path(args.brief).resolve()
    if args.repeat > 0:
        measure(brief, args.repeat, args.big)
    if args.imports:
        _imports(brief)
    if args.profile:
        _profile(brief)


if __name__ == "__main__":
    main()
