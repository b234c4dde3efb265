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
        assert text == (ROOT / "designs" / example).read_text(encoding="utf-8")
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
