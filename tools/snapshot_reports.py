"""Render every example brief (designs/*.yaml) in zh and en as Markdown into a folder, so
that a change that must not alter the reports (moving words into the catalogues, a
restructuring) can be checked with ``diff -r``:

    python tools/snapshot_reports.py /tmp/before            # on the old tree
    python tools/snapshot_reports.py /tmp/after             # on the new tree
    diff -r /tmp/before /tmp/after                          # must print nothing

Options: ``--only shaper,cam`` (brief stems), ``--formats md`` (default md; the figures
are written with it, so their text is compared too; add ``dxf`` for the sheets),
``--lang zh`` (default both).
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("out", type=Path)
    ap.add_argument("--only", default="")
    ap.add_argument("--formats", default="md")
    ap.add_argument("--lang", default="zh,en")
    a = ap.parse_args()
    from mechdesign.runner import run_one

    only = {s for s in a.only.split(",") if s}
    bad = 0
    for brief in sorted((ROOT / "designs").glob("*.yaml")):
        if only and brief.stem not in only:
            continue
        for lang in a.lang.split(","):
            out = a.out / f"{brief.stem}.{lang}"
            o = run_one(brief, out_dir=out, lang=lang, formats=tuple(a.formats.split(",")))
            print(f"{brief.stem:24s} {lang}: {o.status} {o.seconds:.1f} s", flush=True)
            if o.status != "ok":
                print("   ", o.message[:300])
                bad += 1
            (out / "warnings.txt").write_text("\n".join(o.warnings) + "\n" + o.message + "\n",
                                              encoding="utf-8")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
