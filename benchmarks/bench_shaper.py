"""Shaper benchmark: core pipeline time and the whole `mechdesign run` split by phase.

Run:  python benchmarks/bench_shaper.py  [--repeat 20]

Targets (issue 2, 2-core machine): core pipeline (kinematics + kinetostatics +
flywheel) at 3600 crank positions <= 50 ms; the whole run (compute + figures + PDF)
<= 3 s. Prints a table; it is not a test and never fails on time.
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


def _median_ms(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append((time.perf_counter() - start) * 1e3)
    return statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=20, help="repetitions of the core timing")
    parser.add_argument("--brief", default=str(ROOT / "designs" / "shaper.yaml"))
    args = parser.parse_args()

    from mechdesign.brief.loader import load_brief
    from mechdesign.machines import get_machine, shaper, stages_for
    from mechdesign.pipeline import run_stages
    from mechdesign.render import shaper_report
    from mechdesign.render.report import pdf_metadata, render_markdown, template_dir
    from mechdesign.render.pdf import render_pdf
    from mechdesign.results import dumps

    brief = load_brief(args.brief)
    machine = get_machine(brief.machine)
    params = machine.to_params(brief)
    syn = shaper.synthesize(params)

    def core():
        k, mech, motion = shaper.kinematics(syn, params)
        f = shaper.kinetostatics(k, mech, motion, params)
        shaper.flywheel(k, f, params)

    core()  # warm-up (imports, caches)
    core_ms = _median_ms(core, args.repeat)

    rows = [("core pipeline, %d crank positions (median of %d)" % (params.grid_points, args.repeat),
             core_ms, 50.0)]

    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)
        start = time.perf_counter()
        results, _ = run_stages(stages_for(machine, params), {"params": params, "brief": brief})
        document = dumps(machine.document(results))
        t_compute = time.perf_counter() - start

        start = time.perf_counter()
        (out / "figures").mkdir()
        figs = shaper_report.make_figures(results, out / "figures", "zh")
        t_figures = time.perf_counter() - start

        start = time.perf_counter()
        ctx = shaper_report.context(results, brief, figs, "zh")
        md = render_markdown("shaper.zh.md.j2", ctx, template_dir())
        (out / "report.md").write_text(md, encoding="utf-8")
        (out / "results.json").write_text(document, encoding="utf-8")
        t_md = time.perf_counter() - start

        start = time.perf_counter()
        render_pdf(out / "report.md", out / "report.pdf", pdf_metadata(brief.report, "zh"),
                   template_dir() / "report.typ")
        t_pdf = time.perf_counter() - start

    total = t_compute + t_figures + t_md + t_pdf
    rows += [("run: compute (all stages + results.json)", t_compute * 1e3, None),
             ("run: figures (6 PNG)", t_figures * 1e3, None),
             ("run: Markdown", t_md * 1e3, None),
             ("run: PDF (pandoc + typst)", t_pdf * 1e3, None),
             ("run: total", total * 1e3, 3000.0)]

    print(f"mechdesign shaper benchmark  ({os.cpu_count()} CPUs, Python {sys.version.split()[0]})")
    print(f"{'what':58s} {'ms':>9s} {'target':>8s}  ok")
    for what, ms, target in rows:
        tgt = f"{target:.0f}" if target else ""
        ok = "" if target is None else ("yes" if ms <= target else "NO")
        print(f"{what:58s} {ms:9.1f} {tgt:>8s}  {ok}")


if __name__ == "__main__":
    main()
