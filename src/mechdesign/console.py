"""What the commands print on stderr: rich on a terminal (a live progress bar, coloured
warnings and errors), the same plain lines as before everywhere else (CI logs, pipes,
tests parse them).

``Terminal(stream)`` decides once: rich when the stream is a terminal (and ``TERM`` is not
``dumb``), plain otherwise; ``MECHDESIGN_PLAIN=1`` forces plain lines on a terminal too.
Every command line (progress, warnings, errors) goes through :meth:`Terminal.line`, so the
text is the same in both modes; only colour and the live bar differ.
"""
from __future__ import annotations

import os
import sys
from contextlib import contextmanager


def wants_rich(stream) -> bool:
    if os.environ.get("MECHDESIGN_PLAIN") or os.environ.get("TERM") == "dumb":
        return False
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


class Terminal:
    """Lines on ``stream`` (default stderr): styled by rich on a terminal, plain otherwise."""

    def __init__(self, stream=None, rich: bool | None = None):
        self.stream = stream if stream is not None else sys.stderr
        self.rich = wants_rich(self.stream) if rich is None else rich
        self.console = None
        self._bar = None            # the live progress bar, while one runs
        if self.rich:
            from rich.console import Console

            self.console = Console(file=self.stream, force_terminal=True, highlight=False,
                                   soft_wrap=True)

    def line(self, text: str, style: str | None = None) -> None:
        """One line (or several) of text; above the live bar while one runs."""
        if self.console is None:
            self.stream.write(text + "\n")
            self.stream.flush()
            return
        from rich.text import Text

        console = self._bar.console if self._bar is not None else self.console
        console.print(Text(text, style=style or ""))

    def warning(self, text: str) -> None:
        self.line(text, "yellow")

    def error(self, text: str) -> None:
        self.line(text, "bold red")

    def success(self, text: str) -> None:
        self.line(text, "green")

    @contextmanager
    def bar(self, total: int, description: str = ""):
        """A live progress bar of ``total`` steps on a terminal (yields a :class:`Bar`); a
        do-nothing bar otherwise (the caller prints its plain lines itself)."""
        if self.console is None:
            yield Bar(None, None)
            return
        from rich.progress import (BarColumn, MofNCompleteColumn, Progress, SpinnerColumn,
                                   TextColumn, TimeElapsedColumn)

        progress = Progress(SpinnerColumn(), TextColumn("{task.description}"), BarColumn(),
                            MofNCompleteColumn(), TimeElapsedColumn(), console=self.console,
                            transient=True, auto_refresh=False,
                            redirect_stdout=False, redirect_stderr=False)
        task = progress.add_task(description, total=max(total, 1))
        self._bar = progress
        progress.start()
        try:
            yield Bar(progress, task)
        finally:
            self._bar = None
            progress.stop()


class Bar:
    """The live bar's handle: ``update(completed=…, description=…)``; nothing off a terminal."""

    def __init__(self, progress, task):
        self.progress, self.task = progress, task

    def update(self, completed: int | None = None, description: str | None = None,
               total: int | None = None) -> None:
        if self.progress is None:
            return
        fields = {k: v for k, v in (("completed", completed), ("description", description),
                                    ("total", total)) if v is not None}
        self.progress.update(self.task, **fields)
        self.progress.refresh()
