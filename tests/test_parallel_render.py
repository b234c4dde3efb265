"""Figures saved by a helper process (render/parallel.py); sheets drawn by typst.

The helper is a fork: what it writes must be exactly what the parent would have
written, its failures must reach the parent with their traceback, and an interrupted
parent must leave no helper running.
"""
from __future__ import annotations

import hashlib
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from mechdesign.render import parallel

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"),
                                reason="background saves fork, on Linux only")


def _fork_allowed(monkeypatch):
    # typst may have run earlier in this test process; its threads do not survive a fork,
    # and the module refuses to fork after it. These tests only write plain files.
    monkeypatch.setattr(parallel, "_typst_used", False)
    monkeypatch.setattr(parallel, "usable_cpus", lambda: 2)
    monkeypatch.delenv("MECHDESIGN_SERIAL", raising=False)


def test_background_saves_write_every_file_from_a_child(tmp_path, monkeypatch):
    _fork_allowed(monkeypatch)
    parent = os.getpid()
    writers = {}

    def job(k):
        def write():
            (tmp_path / f"{k}.txt").write_text(f"{k} {os.getpid()}")
        return write

    with parallel.background_saves(True):
        for k in range(6):
            parallel.save(job(k), f"file {k}")
    for k in range(6):
        text = (tmp_path / f"{k}.txt").read_text().split()
        writers[k] = int(text[1])
        assert text[0] == str(k)
    # at least one was written by a helper, and no helper is left afterwards
    assert any(pid != parent for pid in writers.values())
    assert parallel._children == []


def test_a_failing_save_in_the_child_raises_in_the_parent_with_its_traceback(tmp_path, monkeypatch):
    _fork_allowed(monkeypatch)
    cleanup = tmp_path / "cleanup-ran"

    def boom():
        raise ValueError("no such figure 42")

    with pytest.raises(parallel.BackgroundSaveError, match="no such figure 42") as info:
        try:
            with parallel.background_saves(True):
                parallel.save(boom, "figure X")
        finally:
            # the child leaves with os._exit: this finally runs once, in the parent
            cleanup.write_text(cleanup.read_text() + "x" if cleanup.exists() else "x")
    # the message names the figure and the error; the helper's traceback is kept for --debug
    # (issue 21: no traceback without --debug, also from helper processes)
    assert "figure X" in str(info.value) and "Traceback" not in str(info.value)
    assert "Traceback" in info.value.detail and "no such figure 42" in info.value.detail
    assert cleanup.read_text() == "x"


def test_an_exception_in_the_parent_kills_the_running_child(tmp_path, monkeypatch):
    _fork_allowed(monkeypatch)
    marker = tmp_path / "late"

    def slow():
        import time

        time.sleep(5)
        marker.write_text("written after the parent gave up")

    with pytest.raises(KeyboardInterrupt):
        with parallel.background_saves(True):
            parallel.save(slow, "slow figure")
            assert len(parallel._children) == 1
            raise KeyboardInterrupt
    assert parallel._children == []
    import time

    time.sleep(0.2)
    assert not marker.exists()


def test_without_background_saves_everything_happens_in_place(tmp_path, monkeypatch):
    _fork_allowed(monkeypatch)
    pids = []
    parallel.save(lambda: pids.append(os.getpid()), "a")
    with parallel.background_saves(False):
        parallel.save(lambda: pids.append(os.getpid()), "b")
    monkeypatch.setenv("MECHDESIGN_SERIAL", "1")
    with parallel.background_saves(True):
        parallel.save(lambda: pids.append(os.getpid()), "c")
    assert pids == [os.getpid()] * 3


def test_typst_in_this_process_stops_forking(monkeypatch):
    _fork_allowed(monkeypatch)
    assert parallel.can_fork()
    parallel.note_typst_used()
    assert not parallel.can_fork()


def _tree_digest(folder: Path) -> dict[str, str]:
    return {p.relative_to(folder).as_posix(): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(folder.rglob("*")) if p.is_file()}


@pytest.mark.e2e
def test_parallel_and_serial_runs_write_the_same_bytes(tmp_path):
    """The whole shaper report (figures, sheets, previews, PDF) from a run that forks
    helpers and from one that does not: every file byte for byte the same."""
    env = dict(os.environ, SOURCE_DATE_EPOCH="1767225600", MPLBACKEND="Agg")
    outs = {}
    for mode in ("parallel", "serial"):
        run_env = dict(env, MECHDESIGN_SERIAL="1" if mode == "serial" else "0")
        out = tmp_path / mode
        proc = subprocess.run([sys.executable, "-m", "mechdesign", "run",
                               str(ROOT / "designs" / "shaper.yaml"), "-o", str(out)],
                              env=run_env, capture_output=True, text=True, timeout=600)
        assert proc.returncode == 0, proc.stderr
        outs[mode] = _tree_digest(out)
    assert outs["parallel"] == outs["serial"]
    assert "report.pdf" in outs["serial"] and "sheets/analysis_A1.pdf" in outs["serial"]
    assert not any(".tmp" in name or ".typ" in name for name in outs["parallel"])


@pytest.mark.e2e
def test_sheet_preview_shows_the_drawing_where_the_sheet_puts_it(tmp_path):
    """write_sheet's PNG preview (the sheet's typst document at the asked width): the
    lines and the circle at their paper coordinates, y upwards on paper."""
    from mechdesign.render.sheet import Sheet
    from mechdesign.render.sheet_typst import write_sheet

    sheet = Sheet("A3")
    sheet.line(10 + 10j, 410 + 10j, "OUTLINE")
    sheet.line(10 + 287j, 410 + 287j, "OUTLINE")
    sheet.circle(210 + 148.5j, 50.0, "OUTLINE")
    write_sheet(sheet, pdf=tmp_path / "s.pdf", png=tmp_path / "s.png", png_width_px=840)
    from matplotlib.image import imread

    img = imread(tmp_path / "s.png")
    assert img.shape[1] == 840 and abs(img.shape[0] - round(840 * 297 / 420)) <= 1
    dark = img[..., :3].mean(axis=2) < 0.5
    rows = np.flatnonzero(dark.any(axis=1))
    cols = np.flatnonzero(dark.any(axis=0))
    px = 840 / 420   # pixels per paper mm
    # the lines at y = 10 and 287 mm and x from 10 to 410 mm (PNG rows run downwards)
    assert abs(rows.min() - (297 - 287) * px) <= 3 and abs(rows.max() - (297 - 10) * px) <= 3
    assert abs(cols.min() - 10 * px) <= 3 and abs(cols.max() - 410 * px) <= 3
    # the circle of radius 50 mm about the centre: dark pixels on its top and bottom
    centre_col = int(210 * px)
    col = np.flatnonzero(dark[:, centre_col - 1:centre_col + 2].any(axis=1))
    inner = col[(col > rows.min() + 5) & (col < rows.max() - 5)]
    assert abs(inner.min() - (148.5 - 50) * px) <= 3 and abs(inner.max() - (148.5 + 50) * px) <= 3


@pytest.mark.e2e
def test_timings_prefix_every_progress_line_with_a_growing_time(tmp_path):
    from typer.testing import CliRunner

    from mechdesign.cli import app

    result = CliRunner().invoke(app, ["run", str(ROOT / "designs" / "cam_7_3.yaml"), "-o",
                                      str(tmp_path / "o"), "--format", "md", "--timings"])
    assert result.exit_code == 0, result.output
    import re

    times = [float(m.group(1)) for m in re.finditer(r"^\s*(\d+\.\d+) s  ", result.output, re.M)]
    # progress lines: stages "[i/n] …" and rendering steps (the zh brief says 生成 …)
    lines = [ln for ln in result.output.splitlines()
             if re.search(r"\[\d+/\d+\]|rendering|生成", ln)]
    assert len(times) >= len(lines) >= 3
    assert times == sorted(times) and times[0] > 0


def test_prefer_heap_takes_effect_exactly_on_glibc():
    import platform

    from mechdesign.allocator import prefer_heap

    glibc = sys.platform.startswith("linux") and platform.libc_ver()[0] == "glibc"
    assert prefer_heap() is glibc
    a = np.ones(2_000_000)          # large arrays still allocate and free normally
    assert float(a.sum()) == 2_000_000.0


@pytest.mark.parametrize("text", ['a "quoted" \\ back\\slash', "#let x = 1 $y$ [z] <l> @r *b* _i_",
                                  "tab\there\x01\x7f", "中文 ΔW_max 😀"])
def test_sheet_text_is_a_typst_string_literal(text):
    """Any user text (title block names) becomes a typst string that compiles and holds
    exactly that text: typst's repr of the value, read back, is the text."""
    import typst

    from mechdesign.render.sheet_typst import typst_string

    literal = typst_string(text)
    source = f"#let s = {literal}\n#assert.eq(s.len(), {len(text.encode('utf-8'))})\n#s\n"
    typst.compile(source.encode("utf-8"))   # raises on a syntax error or a failed assert


def test_pandoc_failure_is_a_render_error_naming_pandoc(tmp_path):
    from mechdesign.render.pdf import PdfRenderError, markdown_to_typst

    with pytest.raises(PdfRenderError, match="pandoc"):
        markdown_to_typst("# T\n", tmp_path / "no-such-template.typ", {}, tmp_path)
