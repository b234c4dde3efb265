"""``python -m mechdesign`` and the ``mechdesign`` console script.

The command line ends its process as soon as its outputs are closed: after the command has
returned (every file written and closed, every helper process waited for), stdout and
stderr are flushed and the process leaves with ``os._exit``, skipping the interpreter's
shutdown, which would otherwise tear down every module and collect the run's objects one by
one (0.3 s after a shaper run, ~10 % of it; benchmarks/bench_run.py measures it). Only
this entry point does so: the CLI invoked in-process (``typer.testing.CliRunner``, a
program calling ``mechdesign.cli.app``) returns as usual. ``MECHDESIGN_CLEAN_EXIT=1`` keeps
the ordinary shutdown (for profilers and coverage tools that write at exit).
"""
from __future__ import annotations

import os
import sys


def main() -> None:
    from .cli import entry

    try:
        entry()                      # the app, an unexpected error as one line
        code = 0
    except SystemExit as exc:
        code = exc.code
    if os.environ.get("MECHDESIGN_CLEAN_EXIT", "") in ("1", "true", "yes") or \
            "coverage" in sys.modules:
        sys.exit(code)
    if code is None:
        code = 0
    elif not isinstance(code, int):          # sys.exit("message"): printed, status 1
        print(code, file=sys.stderr)
        code = 1
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):        # a closed pipe (mechdesign … | head)
            code = code or 1
    os._exit(code)


if __name__ == "__main__":
    main()
