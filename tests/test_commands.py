"""`mechdesign check`, `schema` and `new`."""
from __future__ import annotations

import json
from pathlib import Path

import yaml
from typer.testing import CliRunner

from mechdesign.brief.loader import BRIEF_MODELS
from mechdesign.cli import EXAMPLES, app

ROOT = Path(__file__).resolve().parents[1]
DESIGNS = sorted((ROOT / "designs").glob("*.yaml"))
runner = CliRunner()


def test_check_accepts_every_example_without_computing():
    result = runner.invoke(app, ["check", *map(str, DESIGNS)])
    assert result.exit_code == 0, result.output
    assert result.output.count("ok: ") == len(DESIGNS)


def test_check_names_the_bad_field_and_still_reports_the_good(tmp_path):
    data = yaml.safe_load((ROOT / "designs" / "furnace_pusher.yaml").read_text(encoding="utf-8"))
    data["pusher"]["stroke_H_mm"] = -220
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    result = runner.invoke(app, ["check", str(ROOT / "designs" / "shaper.yaml"), str(bad)])
    assert result.exit_code == 2
    assert "ok: " in result.output and "pusher.stroke_H_mm" in result.output
    assert "-220" in result.output and "1 of 2 briefs invalid" in result.output
    assert "Traceback" not in result.output


def test_schema_covers_every_machine_and_the_examples():
    result = runner.invoke(app, ["schema"])
    assert result.exit_code == 0
    schema = json.loads(result.output)
    mapping = schema["discriminator"]["mapping"]
    assert set(mapping) == set(BRIEF_MODELS)
    for path in DESIGNS:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
        ref = mapping[data["machine"]].rsplit("/", 1)[1]
        model = schema["$defs"][ref]
        assert set(data) <= set(model["properties"]), path.name
        assert set(model.get("required", [])) <= set(data), path.name
        assert model["additionalProperties"] is False


def test_schema_of_one_machine_and_an_unknown_one():
    result = runner.invoke(app, ["schema", "shaper"])
    props = json.loads(result.output)["properties"]
    assert {"machine", "report", "linkage", "masses"} <= set(props)
    result = runner.invoke(app, ["schema", "lathe"])
    assert result.exit_code == 2 and "shaper" in result.output


def test_new_writes_a_commented_starter_that_checks(tmp_path):
    assert set(EXAMPLES) == set(BRIEF_MODELS)
    for machine, example in EXAMPLES.items():
        target = tmp_path / f"{machine}.yaml"
        result = runner.invoke(app, ["new", machine, "-o", str(target)])
        assert result.exit_code == 0, result.output
        text = target.read_text(encoding="utf-8")
        shipped = (ROOT / "designs" / example).read_text(encoding="utf-8")
        # the shipped example, its comments' commands naming the file written (issue 22)
        assert text == shipped.replace(f"designs/{example}", str(target)).replace(
            f"mechdesign run {example}", f"mechdesign run {target}")
        assert f"designs/{example}" not in text
        assert f"{target}`" in text or example not in shipped   # the next-step hint names it
        assert text.lstrip().startswith("#")
        assert yaml.safe_load(text)["machine"] == machine
    result = runner.invoke(app, ["check", *map(str, sorted(tmp_path.glob("*.yaml")))])
    assert result.exit_code == 0, result.output


def test_new_never_overwrites_and_rejects_unknown_machines(tmp_path):
    target = tmp_path / "mine.yaml"
    target.write_text("my work", encoding="utf-8")
    result = runner.invoke(app, ["new", "shaper", "-o", str(target)])
    assert result.exit_code == 2 and "exists" in result.output
    assert target.read_text(encoding="utf-8") == "my work"
    result = runner.invoke(app, ["new", "lathe", "-o", str(tmp_path / "x.yaml")])
    assert result.exit_code == 2 and "furnace_pusher" in result.output
    assert not (tmp_path / "x.yaml").exists()


def test_new_prints_the_path_it_wrote_and_names_it_in_the_next_step(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, ["new", "shaper"])
    assert result.exit_code == 0, result.output
    assert result.stdout.strip() == "shaper.yaml"
    assert "mechdesign run shaper.yaml" in result.output          # the hint on stderr
    text = (tmp_path / "shaper.yaml").read_text(encoding="utf-8")
    assert "`mechdesign run shaper.yaml` renders the report" in text
    assert "designs/shaper.yaml" not in text


def test_choices_are_case_insensitive_everywhere(tmp_path):
    """--lang EN and --format PDF are both accepted (by check, run, batch, watch alike)."""
    shaper = str(ROOT / "designs" / "shaper.yaml")
    assert runner.invoke(app, ["check", shaper, "--lang", "EN"]).exit_code == 0
    assert runner.invoke(app, ["check", shaper, "--lang", "En"]).exit_code == 0
    bad = runner.invoke(app, ["check", shaper, "--lang", "fr"])
    assert bad.exit_code == 2 and "zh" in bad.output and "en" in bad.output
    from mechdesign.cli import _parse_formats

    assert _parse_formats("MD,Pdf") == ("md", "pdf")


def test_help_is_written_for_people():
    """Metavars BRIEF, DIR, N, i/n, LANG, FORMATS; no Python types; an Examples epilogue per
    command; shell completion offered."""
    import re

    top = runner.invoke(app, ["--help"], terminal_width=100)
    assert top.exit_code == 0
    assert "--install-completion" in top.output and "--show-completion" in top.output
    for command in ("run", "batch", "merge", "watch", "check", "schema", "new"):
        result = runner.invoke(app, [command, "--help"], terminal_width=100)
        assert result.exit_code == 0, command
        text = result.output
        assert "Examples:" in text and f"mechdesign {command}" in text.split("Examples:")[1], command
        for python_type in ("<list[Path]>", "<bool>", "<int", "<str>", "<file>", "<dir>",
                            "<path>", "{brief}", "{BRIEF}", "<zh|en>", "range]"):
            assert python_type not in text, (command, python_type)
        # the summary is one line in the command list
        line = next(ln for ln in top.output.splitlines() if re.search(rf"│ {command}\s", ln))
        assert line.rstrip("│ ").strip() != command
    run = runner.invoke(app, ["run", "--help"], terminal_width=100).output
    assert "BRIEF" in run and "DIR" in run and "LANG" in run and "FORMATS" in run
    batch = runner.invoke(app, ["batch", "--help"], terminal_width=100).output
    assert " N " in batch and "i/n" in batch
    # The completion script for a named shell. In a fresh process with typer's shell detection
    # off: whether `--show-completion` takes a shell name depends on whether typer could detect
    # the calling shell when the app was built (it cannot in a detached CI job).
    import os
    import subprocess
    import sys

    env = dict(os.environ, _TYPER_COMPLETE_TEST_DISABLE_SHELL_DETECTION="1")
    completion = subprocess.run([sys.executable, "-m", "mechdesign", "--show-completion", "bash"],
                                capture_output=True, text=True, env=env, timeout=120)
    assert completion.returncode == 0, completion.stderr
    assert "complete" in completion.stdout and "_MECHDESIGN_COMPLETE" in completion.stdout


def test_an_unexpected_error_is_one_line_without_debug(monkeypatch, capsys):
    import mechdesign.cli as cli

    def boom(*args, **kwargs):
        raise RuntimeError("disk on fire")

    monkeypatch.setattr(cli, "app", boom)
    monkeypatch.setattr("sys.argv", ["mechdesign", "run", "x.yaml"])
    monkeypatch.delenv("MECHDESIGN_DEBUG", raising=False)
    import pytest

    with pytest.raises(SystemExit) as exit_info:
        cli.entry()
    assert exit_info.value.code == 1
    err = capsys.readouterr().err
    assert "internal error: RuntimeError: disk on fire" in err and "--debug" in err
    assert "Traceback" not in err
    monkeypatch.setattr("sys.argv", ["mechdesign", "run", "x.yaml", "--debug"])
    with pytest.raises(RuntimeError):
        cli.entry()
