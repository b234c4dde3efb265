"""Times of the guards and bulk paths whose unit tests check only behaviour (the developer
guide keeps speed targets out of the unit tests):

- malformed briefs (tests/malformed/*): `mechdesign check` in a fresh interpreter — target
  < 1 s each, start-up included;
- deep nesting (20 000 levels), an alias bomb (9**9 values), fractions such as 1e1000000000:
  refused by the loader — target < 0.5 s each;
- thinning a 100 000-point curve (target < 0.1 s) and writing a 100 000-point DXF sheet
  (target < 10 s; it was quadratic, ~350 s);
- the shaper's GIF (target < 10 s).

    python benchmarks/bench_limits.py          # prints each figure against its target
"""
from __future__ import annotations

import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def timed(fn, repeat=3):
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def row(name, seconds, target):
    verdict = "ok" if seconds <= target else "OVER"
    print(f"{name:52s} {seconds:8.3f} s   target {target:g} s   {verdict}")


def main() -> None:
    from mechdesign.brief import loader
    from mechdesign.brief.loader import BriefError, load_variant

    print(f"load average {__import__('os').getloadavg()[0]:.1f}; best of 3")
    for path in sorted((ROOT / "tests" / "malformed").glob("*.yaml")):
        row(f"check {path.name} (fresh process)",
            timed(lambda: subprocess.run([sys.executable, "-m", "mechdesign", "check", "--lang", "en",
                                          str(path)], capture_output=True)), 1.0)
    tmp = Path(tempfile.mkdtemp())

    def refused(text):
        p = tmp / "x.yaml"
        p.write_text(text, encoding="utf-8")

        def go():
            try:
                load_variant(p)
            except BriefError:
                return
            raise AssertionError("accepted")
        return go

    row("deep nesting, 20 000 levels", timed(refused("machine: cam\nreport: " + "[" * 20000 + "]" * 20000 + "\n")), 0.5)
    bomb = "machine: cam\na: &a [x, x, x, x, x, x, x, x, x]\n" + "".join(
        f"{n}: &{n} [*{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}]\n"
        for p, n in zip("abcdefgh", "bcdefghi")) + "report: *i\n"
    row("alias bomb, 9**9 values", timed(refused(bomb)), 0.5)
    shaper = (ROOT / "designs" / "shaper.yaml").read_text(encoding="utf-8")
    row("fraction 1e1000000000", timed(refused(shaper.replace("fluctuation_delta: 1/25",
                                                              "fluctuation_delta: '1e1000000000'"))), 0.5)
    big = "machine: shaper\n" + "# padding\n" * (loader.MAX_BYTES // 10 + 10)
    row("file over the size limit", timed(refused(big)), 0.2)

    from mechdesign.render.sheet import Sheet, thin
    from mechdesign.render.sheet_dxf import write_dxf

    t = np.linspace(0, 2 * np.pi, 100_000)
    z = 50 * np.sin(t) + 1j * 20 * np.cos(3 * t)
    row("thin a 100 000-point curve", timed(lambda: thin(z)), 0.1)

    def dxf():
        s = Sheet("A3")
        s.polyline(50 + z + 150j, "CURVES")
        s.polyline(200 + z + 150j, "OUTLINE", closed=True, tolerance=None)
        write_dxf(s, tmp / "big.dxf")
    row("DXF sheet with two 100 000-point curves", timed(dxf, 1), 10.0)

    from mechdesign.brief.loader import load_brief
    from mechdesign.machines import get_machine, stages_for
    from mechdesign.machines.shaper import report as shaper_report
    from mechdesign.pipeline import run_stages

    brief = load_brief(ROOT / "designs" / "shaper.yaml")
    machine = get_machine(brief.machine)
    params = machine.to_params(brief)
    results, _ = run_stages(stages_for(machine, params), {"params": params, "brief": brief})
    row("shaper GIF", timed(lambda: shaper_report.animate(results, tmp / "s.gif", "zh"), 1), 10.0)


if __name__ == "__main__":
    main()
