"""Drawing sheets of a large run: each sheet's build, DXF and PDF time, and its points.

Run:  python benchmarks/bench_sheets.py [--brief designs/shaper.yaml] [--points 100000]
                                        [--repeat 3]

The brief is computed at analysis.grid_points = --points (a 100,000-point run, as
`analysis.grid_points: 100000` in a brief), then every drawing sheet the run draws is built
(render/sheets.py's builders) and written as DXF (render/sheet_dxf.py) and as PDF with its
PNG preview (render/sheet_typst.py), each timed (median of --repeat; the PDF in this
process, serially). Polylines are thinned to the paper's resolution as they are drawn
(render/sheet.thin, 0.02 mm chord error, the extremes kept), and DXF polylines are written in
bulk; the "unthinned" columns build and write the same sheets with thinning switched off
(every computed point kept), to show what the thinning saves. Before issue 22 a 100,000-point
run's DXF took ~350 s (ezdxf appended the vertices one by one, copying the array each time).

Target (issue 22): a 100,000-point run's DXF and PDF sheets in seconds. Prints a table;
never fails on time.
"""
from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _results(brief_path: Path, points: int) -> tuple[dict, object]:
    from mechdesign.brief.loader import load_brief
    from mechdesign.machines import get_machine, stages_for
    from mechdesign.pipeline import run_stages

    brief = load_brief(brief_path)
    brief = brief.model_copy(update={"analysis": brief.analysis.model_copy(
        update={"grid_points": points})})
    machine = get_machine(brief.machine)
    params = machine.to_params(brief)
    results, _ = run_stages(stages_for(machine, params), {"params": params, "brief": brief})
    return results, brief


def _time(fn, repeat: int) -> tuple[float, object]:
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--brief", default=str(ROOT / "designs" / "shaper.yaml"))
    ap.add_argument("--points", type=int, default=100_000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--lang", default="zh")
    a = ap.parse_args()
    os.environ.setdefault("MPLBACKEND", "Agg")
    from mechdesign.render import sheet as sheet_mod
    from mechdesign.render.sheet import Polyline, TitleInfo
    from mechdesign.render.sheet_dxf import write_dxf
    from mechdesign.render.sheet_typst import write_sheets
    from mechdesign.render.sheets import _builders

    t0 = time.perf_counter()
    results, brief = _results(Path(a.brief), a.points)
    print(f"{Path(a.brief).name} at {a.points:,} grid points: computed in "
          f"{time.perf_counter() - t0:.1f} s; {os.cpu_count()} CPUs, load average "
          f"{os.getloadavg()[0]:.2f}")
    info = TitleInfo(drawing="bench", project="bench", date="2026-01-01")
    thin = sheet_mod.thin
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, build in _builders(results, brief):
            for mode in ("thinned", "unthinned"):
                sheet_mod.thin = thin if mode == "thinned" else (lambda z, tol=0: z)
                try:
                    t_build, sheet = _time(lambda: build(info, a.lang), a.repeat)
                finally:
                    sheet_mod.thin = thin
                points = sum(len(e.points) for e in sheet.entities if isinstance(e, Polyline))
                t_dxf, _ = _time(lambda: write_dxf(sheet, Path(tmp) / f"{name}.dxf"), a.repeat)
                t_pdf = None
                if mode == "thinned":
                    t_pdf, _ = _time(lambda: write_sheets(
                        [(sheet, Path(tmp) / f"{name}.pdf", Path(tmp) / f"{name}.png", 1200)]),
                        a.repeat)
                rows.append((name, mode, points, t_build, t_dxf, t_pdf))
    print()
    print("| sheet | polylines | points | build [s] | DXF [s] | PDF + PNG preview [s] |")
    print("|---|---|---:|---:|---:|---:|")
    for name, mode, points, tb, td, tp in rows:
        print(f"| {name} | {mode} | {points:,} | {tb:.2f} | {td:.2f} | "
              f"{'—' if tp is None else f'{tp:.2f}'} |")
    total = sum(r[4] + (r[5] or 0) + r[3] for r in rows if r[1] == "thinned")
    print(f"\nall sheets, thinned: build + DXF + PDF {total:.1f} s "
          f"(target: seconds: {'met' if total <= 10 else 'MISSED'})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
