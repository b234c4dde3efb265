"""`mechdesign watch` (issue 22, point 4): a warm process that re-runs a brief on every save,
prints which headline results changed, shows an invalid edit's messages and goes on, and
ends cleanly on Ctrl-C / SIGTERM."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import wait_until

from mechdesign.watch import snapshot, summary_changes, watched_files

ROOT = Path(__file__).resolve().parents[1]


def test_summary_changes_lists_old_and_new():
    before = {"r0 [mm]": "50", "rho [mm]": "37.37", "gone": "1"}
    after = {"r0 [mm]": "55", "rho [mm]": "37.37", "new": "2"}
    assert summary_changes(before, after) == ["  r0 [mm]: 50 → 55", "  new: — → 2", "  gone: 1 → —"]
    assert summary_changes(after, after) == []


def test_watched_files_are_the_brief_its_class_table_and_the_templates(tmp_path):
    brief = tmp_path / "class.yaml"
    brief.write_text("machine: shaper\ngroups: {file: class.csv, default: 1}\n", encoding="utf-8")
    templates = tmp_path / "tpl"
    (templates / "sub").mkdir(parents=True)
    (templates / "base.zh.md.j2").write_text("x", encoding="utf-8")
    (templates / "sub" / "x.typ").write_text("y", encoding="utf-8")
    files = watched_files(brief, templates)
    assert files == [brief, tmp_path / "class.csv", templates / "base.zh.md.j2",
                     templates / "sub" / "x.typ"]
    state = snapshot(files)
    assert state[tmp_path / "class.csv"] is None and state[brief] is not None
    # a broken brief is still watched (its run says what is wrong)
    brief.write_text("machine: [", encoding="utf-8")
    assert watched_files(brief, None) == [brief]


def _wait(predicate, timeout: float, proc) -> None:
    wait_until(predicate, timeout, proc, step=0.1)


def _base_radius(results: Path):
    try:
        return json.loads(results.read_text(encoding="utf-8"))["cam"]["base_radius"]
    except (OSError, ValueError, KeyError):
        return None


@pytest.mark.e2e
def test_watch_reruns_on_save_reports_changes_survives_an_invalid_edit(tmp_path):
    brief = tmp_path / "cam.yaml"
    text = (ROOT / "designs" / "cam_7_3.yaml").read_text(encoding="utf-8")
    assert "base_radius_mm: 50 " in text
    brief.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    results = out / "results.json"
    log = tmp_path / "stderr.txt"
    with open(log, "w", encoding="utf-8") as err:
        proc = subprocess.Popen([sys.executable, "-m", "mechdesign", "watch", str(brief),
                                 "--format", "md", "-o", str(out)],
                                stdout=subprocess.PIPE, stderr=err, text=True,
                                env={**os.environ, "MPLBACKEND": "Agg"})
    try:
        _wait(lambda: _base_radius(results) == pytest.approx(0.050), 180, proc)

        def edit(value: str) -> None:
            brief.write_text(text.replace("base_radius_mm: 50 ", f"base_radius_mm: {value} "),
                             encoding="utf-8")

        edit("55")     # r0 = 55 mm: results.json rewritten with 0.055 m
        _wait(lambda: _base_radius(results) == pytest.approx(0.055), 120, proc)
        _wait(lambda: "50 → 55" in log.read_text(encoding="utf-8"), 10, proc)
        edit("-5")     # invalid: the field's message, the watch goes on, the report stays
        _wait(lambda: "cam.base_radius_mm" in log.read_text(encoding="utf-8"), 120, proc)
        assert "-5" in log.read_text(encoding="utf-8")
        assert _base_radius(results) == pytest.approx(0.055)
        edit("60")
        _wait(lambda: _base_radius(results) == pytest.approx(0.060), 120, proc)
        _wait(lambda: "55 → 60" in log.read_text(encoding="utf-8"), 10, proc)
    finally:
        proc.send_signal(signal.SIGTERM)       # as Ctrl-C (SIGINT is ignored in a background job)
        try:
            stdout, _ = proc.communicate(timeout=60)
        except subprocess.TimeoutExpired:
            proc.kill()
            raise
    stderr = log.read_text(encoding="utf-8")
    assert proc.returncode == 0, stderr
    assert "监视结束" in stderr and "Traceback" not in stderr
    assert str(out / "report.md") in stdout
    assert not list(out.glob(".mechdesign-*")), "no staging folder left"
