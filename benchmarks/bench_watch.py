"""`mechdesign watch`: from saving an edit of the brief to the rewritten report.pdf.

Run:  python benchmarks/bench_watch.py [--brief designs/shaper.yaml] [--edits 6]
                                       [--cache DIR]

Starts `python -m mechdesign watch BRIEF` on a copy of the brief (default formats md+pdf),
waits for the first report, then saves edits of two kinds, alternated (text, number,
text, number, …), each waiting for the previous one to land:

  text     the report's student name changes (every figure and sheet unchanged: copied
           from the render cache; the PDF laid out again by the warm typst process)
  number   the cutting force changes between two values (the force, torque, energy and
           flywheel figures and the analysis sheet are drawn again; the kinematics are not)

Each edit is timed by this script's clock from the moment the edited file is written
(os.replace of a complete file, as an editor saves) to the moment report.pdf is replaced
(polled every 10 ms: its inode changes), so the watch's polling, the run and the move into
place all count. The table gives medians and the spread of each kind, the watch's own
"report updated in X s" figures and the load average.

The render cache is a fresh folder (--cache, else a temporary one): the first run fills
it, as a student's first run would. Target (issue 22 point 4): the shaper report
rewritten within 1 s of an edit. Prints a table; never fails on time.
"""
from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TARGET = 1.0


def _inode(path: Path):
    try:
        st = path.stat()
        return (st.st_ino, st.st_mtime_ns)
    except OSError:
        return None


def _wait_new(path: Path, old, timeout: float, proc) -> float:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        now = _inode(path)
        if now is not None and now != old:
            return time.perf_counter()
        if proc.poll() is not None:
            raise SystemExit("the watch ended")
        time.sleep(0.01)
    raise SystemExit(f"{path} was not rewritten within {timeout} s")


def _save(path: Path, text: str) -> float:
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    t = time.perf_counter()
    os.replace(tmp, path)
    return t


def _spread(xs):
    xs = sorted(xs)
    if len(xs) < 2:
        return xs[0], xs[0], xs[0]
    q1, _, q3 = statistics.quantiles(xs, n=4, method="inclusive")
    return statistics.median(xs), q1, q3


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--brief", default="designs/shaper.yaml")
    ap.add_argument("--edits", type=int, default=6, help="edits of each kind")
    ap.add_argument("--cache", default=None, help="render cache folder (default: a new one)")
    args = ap.parse_args()

    work = Path(tempfile.mkdtemp(prefix="bench-watch-"))
    brief = work / "brief.yaml"
    text = (ROOT / args.brief).read_text(encoding="utf-8")
    student = re.search(r"^  student: (.*)$", text, re.M)
    force = re.search(r"^  cutting_force_Fc_N: (\d+)", text, re.M)
    if not student or not force:
        raise SystemExit("the brief needs report.student and loads.cutting_force_Fc_N")
    brief.write_text(text, encoding="utf-8")
    out = work / "out"
    pdf = out / "report.pdf"
    env = dict(os.environ, MPLBACKEND="Agg",
               MECHDESIGN_CACHE=args.cache or str(work / "cache"))
    log = work / "watch.log"
    with open(log, "w", encoding="utf-8") as err:
        proc = subprocess.Popen([sys.executable, "-m", "mechdesign", "watch", str(brief),
                                 "-o", str(out)], stdout=subprocess.DEVNULL, stderr=err,
                                env=env, cwd=ROOT)
    times: dict[str, list[float]] = {"text": [], "number": []}
    try:
        t0 = time.perf_counter()
        first = _wait_new(pdf, None, 600, proc) - t0
        f0 = int(force.group(1))
        for k in range(2 * args.edits):
            kind = "text" if k % 2 == 0 else "number"
            if kind == "text":
                edited = text.replace(student.group(0), f"  student: 学生{k}")
            else:
                value = f0 + (10 if (k // 2) % 2 == 0 else 20)
                edited = text.replace(force.group(0), f"  cutting_force_Fc_N: {value}")
            text = edited
            old = _inode(pdf)
            time.sleep(0.3)                   # the watch is idle, polling
            start = _save(brief, edited)
            times[kind].append(_wait_new(pdf, old, 600, proc) - start)
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=30)
        except subprocess.TimeoutExpired:
            proc.kill()
    said = [float(x) for x in re.findall(r"(\d+\.\d+) s", log.read_text(encoding="utf-8"))]
    load = os.getloadavg()
    print(f"mechdesign watch {args.brief} (md+pdf), {os.cpu_count()} CPUs, "
          f"load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    print(f"  first report (start-up, imports, cold cache): {first:.2f} s")
    print("  edit saved → report.pdf replaced, median [first–third quartile] of "
          f"{args.edits} each:")
    for kind, xs in times.items():
        m, q1, q3 = _spread(xs)
        verdict = "met" if m <= TARGET else "missed"
        print(f"    {kind:7s} {m:5.2f} s [{q1:.2f}–{q3:.2f}]   target ≤ {TARGET:.1f} s: {verdict}")
    if said:
        m, q1, q3 = _spread(said[1:] or said)
        print(f"  the watch's own 'report updated in' (re-runs): {m:.2f} s [{q1:.2f}–{q3:.2f}]")


if __name__ == "__main__":
    main()
