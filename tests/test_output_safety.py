"""A run writes only inside its output folder, and an interrupted or failed run leaves
the previous report exactly as it was (issue 7, point 5)."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

from mechdesign.cli import app
from mechdesign.runner import run_one

DESIGNS = Path(__file__).resolve().parents[1] / "designs"
BRIEF = "crank_rocker.yaml"          # small and quick
runner = CliRunner()


def _snapshot(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes()
            for p in sorted(root.rglob("*")) if p.is_file()}


@pytest.fixture()
def workspace(tmp_path, monkeypatch):
    """A class folder with one brief, the current directory inside it."""
    (tmp_path / "briefs").mkdir()
    shutil.copy(DESIGNS / BRIEF, tmp_path / "briefs" / BRIEF)
    monkeypatch.chdir(tmp_path)
    return tmp_path


@pytest.mark.e2e
def test_a_run_writes_only_its_output_folder(workspace):
    before = _snapshot(workspace)
    result = runner.invoke(app, ["run", f"briefs/{BRIEF}", "-f", "md"])
    assert result.exit_code == 0, result.output
    after = _snapshot(workspace)
    new = sorted(set(after) - set(before))
    assert new and all(name.startswith("out/crank_rocker/") for name in new), new
    assert {k: after[k] for k in before} == before           # the brief is untouched
    assert not [p for p in (workspace / "out" / "crank_rocker").iterdir() if p.name.startswith(".")]


def _render_fails(monkeypatch, exc: BaseException) -> None:
    """Make the next render fail after its figures are drawn, for a changed brief (so a
    run that wrote into the folder directly would leave different files behind)."""
    import mechdesign.machines.crank_rocker.report as report

    brief = Path("briefs") / BRIEF
    brief.write_text(brief.read_text(encoding="utf-8").replace("rocker_swing_deg: 40",
                                                               "rocker_swing_deg: 45"),
                     encoding="utf-8")

    def broken(*args, **kwargs):
        raise exc

    monkeypatch.setattr(report, "context", broken)


@pytest.mark.e2e
def test_an_interrupted_run_leaves_the_previous_report(workspace, monkeypatch):
    out = workspace / "out" / "cr"
    first = run_one(workspace / "briefs" / BRIEF, out_dir=out, formats=("md",))
    assert first.status == "ok"
    before = _snapshot(out)
    _render_fails(monkeypatch, KeyboardInterrupt())      # Ctrl-C (or SIGTERM, see cli.run)
    with pytest.raises(KeyboardInterrupt):
        run_one(workspace / "briefs" / BRIEF, out_dir=out, formats=("md",))
    assert _snapshot(out) == before
    assert [p.name for p in out.iterdir() if p.name.startswith(".")] == []


@pytest.mark.e2e
def test_an_interrupted_run_through_the_cli_exits_130(workspace, monkeypatch):
    out = workspace / "out" / "cr"
    assert runner.invoke(app, ["run", f"briefs/{BRIEF}", "-o", str(out), "-f", "md"]).exit_code == 0
    before = _snapshot(out)
    _render_fails(monkeypatch, KeyboardInterrupt())
    result = runner.invoke(app, ["run", f"briefs/{BRIEF}", "-o", str(out), "-f", "md"])
    assert result.exit_code == 130 and "已中断" in result.output          # a zh brief
    assert "Traceback" not in result.output
    assert _snapshot(out) == before


@pytest.mark.e2e
def test_a_failed_render_leaves_the_previous_report(workspace, monkeypatch):
    out = workspace / "out" / "cr"
    assert run_one(workspace / "briefs" / BRIEF, out_dir=out, formats=("md",)).status == "ok"
    before = _snapshot(out)
    _render_fails(monkeypatch, OSError("disk full"))
    result = runner.invoke(app, ["run", f"briefs/{BRIEF}", "-o", str(out), "-f", "md"])
    assert result.exit_code == 1 and "disk full" in result.output
    assert "Traceback" not in result.output
    assert _snapshot(out) == before
    assert not [p for p in out.iterdir() if p.name.startswith(".")]


def test_an_invalid_brief_writes_nothing(workspace):
    bad = workspace / "briefs" / "bad.yaml"
    bad.write_text((DESIGNS / BRIEF).read_text(encoding="utf-8").replace("machine: crank_rocker",
                                                                          "machine: crank_rocker\nfoo: 1"),
                   encoding="utf-8")
    result = runner.invoke(app, ["run", str(bad), "-o", "out/bad"])
    assert result.exit_code == 2 and "foo" in result.output
    assert not (workspace / "out").exists()
