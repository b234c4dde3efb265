"""Own only your files, survive interrupts and dead workers (issue 21, points 1, 2, 6).

* A run into a folder with foreign files leaves them byte-identical, and refuses (exit 2,
  nothing changed) when it would have to replace a file it did not write.
* A run replaces or removes exactly the files of its manifest: an `md` run after an
  `md,pdf` run leaves no stale report.pdf.
* An interrupt while the files move is held back until the new report is complete, and the
  message after an interrupt is true in every window; dead runs' staging folders go.
* A batch whose worker is killed finishes every other run `ok`; the run whose worker dies
  twice is marked with the cause.
* A user's template runs in Jinja's sandbox.
"""
from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from mechdesign import publish
from mechdesign.cli import app
from mechdesign.publish import MANIFEST, STAGING_PREFIX

DESIGNS = Path(__file__).resolve().parents[1] / "designs"
BRIEF = "cam_7_3.yaml"          # small and quick
runner = CliRunner()


def _snapshot(root: Path, skip=()) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*"))
            if p.is_file() and not p.relative_to(root).as_posix().startswith(tuple(skip))}


@pytest.fixture()
def folder(tmp_path, monkeypatch):
    """A student's folder holding the brief and their own files, the current directory."""
    shutil.copy(DESIGNS / BRIEF, tmp_path / BRIEF)
    (tmp_path / "figures").mkdir()
    (tmp_path / "figures" / "my_drawing.png").write_bytes(b"\x89PNG my own drawing")
    (tmp_path / "sheets").mkdir()
    (tmp_path / "sheets" / "my_sheet.dwg").write_bytes(b"AC1032 my sheet")
    (tmp_path / "notes.txt").write_text("my notes\n", encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    return tmp_path


def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


# ----------------------------------------------------------------------------- manifest

@pytest.mark.e2e
def test_a_run_into_a_folder_with_foreign_files_leaves_them_byte_identical(folder):
    before = _snapshot(folder)
    result = runner.invoke(app, ["run", BRIEF, "--out", ".", "-f", "md,dxf"])
    assert result.exit_code == 0, result.output
    after = _snapshot(folder)
    assert {k: after[k] for k in before} == before
    owned = set(json.loads((folder / MANIFEST).read_text(encoding="utf-8"))["files"])
    new = set(after) - set(before) - {MANIFEST}
    assert owned == new and "report.md" in owned and "results.json" in owned
    assert any(f.startswith("figures/") for f in owned) and any(f.startswith("sheets/") for f in owned)
    # a second run replaces its own files and still leaves the user's alone
    result = runner.invoke(app, ["run", BRIEF, "--out", ".", "-f", "md"])
    assert result.exit_code == 0, result.output
    again = _snapshot(folder)
    assert {k: again[k] for k in before} == before
    # the md run writes no sheets: the sheets of the first run (its own) are gone, the user's stay
    assert not [f for f in again if f.startswith("sheets/") and f not in before]
    assert (folder / "sheets" / "my_sheet.dwg").exists()
    assert not [p for p in folder.iterdir() if p.name.startswith(STAGING_PREFIX)]


@pytest.mark.parametrize("name", ["report.md", "results.json"])
def test_a_report_that_is_not_ours_stops_the_run_before_anything_changes(folder, name):
    (folder / name).write_text("the student's own text\n", encoding="utf-8")
    before = _snapshot(folder)
    result = runner.invoke(app, ["run", BRIEF, "--out", ".", "-f", "md", "--lang", "en"])
    assert result.exit_code == 2, result.output
    assert name in result.output and "not written by mechdesign" in result.output
    assert "Traceback" not in result.output
    assert _snapshot(folder) == before
    assert not (folder / MANIFEST).exists()


def test_a_figure_name_clash_is_refused_at_publish(tmp_path):
    """A foreign file where the run would put a figure: nothing moves, the staged files stay
    where they were and the foreign file is unchanged."""
    out, staging = tmp_path / "out", tmp_path / "out" / ".mechdesign-staging-1-x"
    (staging / "figures").mkdir(parents=True)
    (staging / "report.md").write_text("new", encoding="utf-8")
    (staging / "figures" / "cam.png").write_bytes(b"new png")
    (out / "figures").mkdir()
    (out / "figures" / "cam.png").write_bytes(b"theirs")
    with pytest.raises(publish.ForeignFiles) as info:
        publish.publish(staging, out)
    assert info.value.paths == ["figures/cam.png"]
    assert (out / "figures" / "cam.png").read_bytes() == b"theirs"
    assert not (out / "report.md").exists() and not (out / MANIFEST).exists()
    # a folder where a file must go, and a file where a folder must go, clash too
    shutil.rmtree(out / "figures")
    (out / "figures").write_text("a file", encoding="utf-8")
    with pytest.raises(publish.ForeignFiles) as info:
        publish.publish(staging, out)
    assert info.value.paths == ["figures"]


def test_a_manifest_never_reaches_outside_its_folder(tmp_path):
    """Entries that leave the folder (.., absolute paths) are ignored: the files they name
    are never removed."""
    out = tmp_path / "out"
    out.mkdir()
    outside = tmp_path / "keep.txt"
    outside.write_text("keep", encoding="utf-8")
    (out / MANIFEST).write_text(json.dumps({"files": ["../keep.txt", str(outside), "a/../../keep.txt",
                                                      "ok.txt"]}), encoding="utf-8")
    assert publish.read_manifest(out) == {"ok.txt"}
    staging = out / ".mechdesign-staging-1-y"
    staging.mkdir()
    (staging / "new.txt").write_text("n", encoding="utf-8")
    publish.publish(staging, out)
    assert outside.read_text(encoding="utf-8") == "keep"
    assert publish.read_manifest(out) == {"new.txt"}


@pytest.mark.e2e
def test_no_stale_report_beside_a_newer_one(folder):
    """md,pdf then md with a changed brief: the old report.pdf is removed (it would say the
    old base radius beside a report.md saying the new one)."""
    out = folder / "out"
    assert runner.invoke(app, ["run", BRIEF, "-o", str(out), "-f", "md,pdf"]).exit_code == 0
    assert (out / "report.pdf").exists()
    text = (folder / BRIEF).read_text(encoding="utf-8")
    changed = text.replace("base_radius_mm: 50", "base_radius_mm: 55")
    assert changed != text
    (folder / BRIEF).write_text(changed, encoding="utf-8")
    result = runner.invoke(app, ["run", BRIEF, "-o", str(out), "-f", "md"])
    assert result.exit_code == 0, result.output
    assert not (out / "report.pdf").exists()
    assert set(json.loads((out / MANIFEST).read_text(encoding="utf-8"))["files"]) == \
        set(_snapshot(out)) - {MANIFEST}


# ----------------------------------------------------------------------------- staging

def test_dead_runs_staging_folders_are_removed_live_ones_kept(tmp_path):
    out = tmp_path / "out"
    dead = out / f"{STAGING_PREFIX}{_dead_pid()}-abc"
    live = out / f"{STAGING_PREFIX}{os.getpid()}-def"
    legacy_old, legacy_new = out / ".mechdesign-staging-x1y2", out / ".mechdesign-old-z3"
    for d in (dead, live, legacy_old, legacy_new):
        d.mkdir(parents=True)
        (d / "report.md").write_text("half", encoding="utf-8")
    os.utime(legacy_old, (1e9, 1e9))
    fresh = publish.make_staging(out)
    assert not dead.exists() and not legacy_old.exists()
    assert live.exists() and legacy_new.exists() and fresh.exists()
    assert fresh.name.startswith(f"{STAGING_PREFIX}{os.getpid()}-")


# ----------------------------------------------------------------------------- interrupts

def test_an_interrupt_while_the_files_move_is_held_until_all_are_in_place(tmp_path, monkeypatch):
    out = tmp_path / "out"
    (out / "figures").mkdir(parents=True)
    (out / "figures" / "old.png").write_bytes(b"old")
    (out / "report.md").write_text("old report", encoding="utf-8")
    (out / MANIFEST).write_text(json.dumps({"files": ["figures/old.png", "report.md"]}),
                                encoding="utf-8")
    staging = out / f"{STAGING_PREFIX}{os.getpid()}-z"
    (staging / "figures").mkdir(parents=True)
    for name in ("report.md", "results.json", "figures/a.png", "figures/b.png"):
        (staging / name).write_text(f"new {name}", encoding="utf-8")
    real = os.replace
    calls = []

    def replace_then_interrupt(src, dst):
        calls.append(dst)
        if len(calls) == 2:          # the first file moved (after the manifest): Ctrl-C, twice
            os.kill(os.getpid(), signal.SIGINT)
            os.kill(os.getpid(), signal.SIGTERM)
        return real(src, dst)

    monkeypatch.setattr(publish.os, "replace", replace_then_interrupt)
    handler_before = signal.getsignal(signal.SIGINT)   # SIG_IGN in a background job
    mark = publish.journal_mark()
    with pytest.raises(publish.InterruptedAfterPublish):
        publish.publish(staging, out)
    monkeypatch.setattr(publish.os, "replace", real)
    assert publish.published_since(mark) == [out]
    got = _snapshot(out)
    assert got == {MANIFEST: got[MANIFEST], "report.md": b"new report.md",
                   "results.json": b"new results.json", "figures/a.png": b"new figures/a.png",
                   "figures/b.png": b"new figures/b.png"}
    assert publish.read_manifest(out) == {"report.md", "results.json", "figures/a.png",
                                          "figures/b.png"}
    assert signal.getsignal(signal.SIGINT) is handler_before     # restored


@pytest.mark.e2e
@pytest.mark.parametrize("when", ["publishing", "after"])
def test_the_message_after_an_interrupt_is_true(folder, monkeypatch, when):
    """Interrupted while the files move, or after they moved (summarising the run): the
    report is complete and the CLI says so (exit 130); nothing half old, half new."""
    out = folder / "out"
    if when == "publishing":
        real = os.replace
        state = {"n": 0}

        def replace(src, dst):     # os.replace is also each atomic write's last step
            if STAGING_PREFIX in str(src) and STAGING_PREFIX not in str(dst):
                state["n"] += 1      # a staged file moving into the output folder
                if state["n"] == 2:
                    os.kill(os.getpid(), signal.SIGTERM)
            return real(src, dst)

        monkeypatch.setattr(publish.os, "replace", replace)
    else:
        import mechdesign.machines.summary as summary

        def interrupted(*args, **kwargs):
            raise KeyboardInterrupt

        monkeypatch.setattr(summary, "summary_rows", interrupted)
    result = runner.invoke(app, ["run", BRIEF, "-o", str(out), "-f", "md"])
    assert result.exit_code == 130, result.output
    assert "已中断：新报告此前已完整写入" in result.output      # the brief is a zh one
    assert "未写入任何文件" not in result.output and "Traceback" not in result.output
    md = (out / "report.md").read_text(encoding="utf-8")
    assert md.strip() and publish.read_manifest(out) == set(_snapshot(out)) - {MANIFEST}
    if when == "publishing":
        assert state["n"] > 2           # every file moved after the signal arrived


# ----------------------------------------------------------------------------- batch

def _killer(out_root: Path, plan: dict, stop, killed: dict):
    """Kill workers from outside, as the OS would: a run's staging folder carries its worker's
    pid; SIGKILL the worker of every run named in ``plan`` — "always", or "once" (the first
    worker only) — as soon as its staging folder appears."""
    import re
    import time

    while not stop.is_set():
        for run_id, mode in plan.items():
            for d in (out_root / run_id).glob(f"{STAGING_PREFIX}*"):
                m = re.match(re.escape(STAGING_PREFIX) + r"(\d+)-", d.name)
                pid = int(m.group(1)) if m else 0
                if not pid or pid in killed.get(run_id, ()) or pid == os.getpid():
                    continue
                if mode == "once" and killed.get(run_id):
                    continue
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    continue
                killed.setdefault(run_id, []).append(pid)
        time.sleep(0.005)


@pytest.mark.e2e
@pytest.mark.skipif(sys.platform == "win32", reason="SIGKILL")
def test_a_killed_worker_fails_only_its_own_run(tmp_path):
    """5 runs, 2 workers: run b's worker is killed every time (its retry too), run c's once.
    The others finish ok; c is retried alone and ends ok; b is marked with the cause."""
    import threading

    from mechdesign import batch

    briefs = tmp_path / "briefs"
    briefs.mkdir()
    for stem in "abcde":
        shutil.copy(DESIGNS / BRIEF, briefs / f"{stem}.yaml")
    jobs = batch.plan_jobs(batch.collect_briefs([briefs]))
    out = tmp_path / "out"
    stop, killed = threading.Event(), {}
    thread = threading.Thread(target=_killer, args=(out, {"b": "always", "c": "once"}, stop, killed),
                              daemon=True)
    thread.start()
    seen = []
    try:
        results = batch.run_batch(jobs, out, jobs_n=2, formats=("md",),
                                  on_result=lambda job, r: seen.append(job.run_id))
    finally:
        stop.set()
        thread.join()
    status = {Path(r["brief"]).stem: r["status"] for r in results}
    assert status == {"a": "ok", "b": "failed", "c": "ok", "d": "ok", "e": "ok"}, (status, killed)
    assert len(killed["b"]) == 2 and len(killed["c"]) == 1      # b: first try and its retry
    (b,) = [r for r in results if Path(r["brief"]).stem == "b"]
    assert "died twice" in b["message"] and "SIGKILL" in b["message"]
    assert sorted(seen) == sorted(j.run_id for j in jobs)          # each reported once
    for job in jobs:
        assert not list((out / job.run_id).glob(f"{STAGING_PREFIX}*"))
    assert (out / "c" / "report.md").exists() and not (out / "b" / "report.md").exists()


# ----------------------------------------------------------------------------- templates

@pytest.mark.e2e
def test_a_users_template_runs_in_the_sandbox(folder):
    tpl = folder / "tpl"
    tpl.mkdir()
    (tpl / "cam.en.md.j2").write_text(
        "# Cam\n{{ ''.__class__.__mro__[1].__subclasses__() }}\n", encoding="utf-8")
    result = runner.invoke(app, ["run", BRIEF, "-o", "out", "-f", "md", "--lang", "en",
                                 "--templates", str(tpl)])
    assert result.exit_code == 1, result.output
    assert "unsafe" in result.output and "Traceback" not in result.output
    assert not (folder / "out" / "report.md").exists()
