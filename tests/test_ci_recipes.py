"""The CI recipes of docs/ci/ (issue 22, point 8): they parse, they name the commands a
sharded batch needs, and those commands, run here the same way (two shards into one
folder, then `mechdesign merge`), give the index an unsharded batch writes."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.cli import app

ROOT = Path(__file__).resolve().parents[1]
DESIGNS = ROOT / "designs"
runner = CliRunner()


def _commands(node) -> list[str]:
    """Every shell line of a CI file (GitHub `run:`, GitLab `script:`/`before_script:`)."""
    found = []
    if isinstance(node, dict):
        for key, value in node.items():
            if key in ("run", "script", "before_script"):
                found += [value] if isinstance(value, str) else list(value)
            else:
                found += _commands(value)
    elif isinstance(node, list):
        for item in node:
            found += _commands(item)
    return found


@pytest.mark.parametrize("name", ["github-actions.yml", "gitlab-ci.yml"])
def test_ci_recipe_parses_and_names_the_sharded_batch_commands(name):
    doc = yaml.safe_load((ROOT / "docs" / "ci" / name).read_text(encoding="utf-8"))
    lines = "\n".join(_commands(doc))
    # install in a virtual environment (a CI image's system pip may be externally managed)
    assert re.search(r"python3 -m venv \.venv && \.venv/bin/pip install -e \.", lines)
    shard = re.search(r"\.venv/bin/mechdesign batch \S+ --shard (\S+|\$\{\{ [\w.]+ \}\})/(\S+) "
                      r"--out out", lines)
    assert shard, lines
    assert re.search(r"\.venv/bin/mechdesign merge out\b", lines)
    text = (ROOT / "docs" / "ci" / name).read_text(encoding="utf-8")
    if name == "github-actions.yml":
        jobs = doc["jobs"]
        assert jobs["shard"]["strategy"]["matrix"]["shard"] == [1, 2, 3, 4]
        assert shard.groups() == ("${{ matrix.shard }}", "4")
        assert jobs["merge"]["needs"] == "shard" and jobs["merge"]["if"] == "always()"
        uploads = [s for s in jobs["merge"]["steps"] if "upload-artifact" in str(s.get("uses"))]
        assert uploads and "out/**/*.pdf" in uploads[-1]["with"]["path"]
    else:
        assert doc["reports"]["parallel"] == 4
        assert shard.groups() == ("$CI_NODE_INDEX", "$CI_NODE_TOTAL")
        assert doc["merge"]["needs"][0]["job"] == "reports"
        assert "out/" in doc["reports"]["artifacts"]["paths"]
        assert doc["reports"]["artifacts"]["when"] == "always"
    assert "pdf" in text.lower()


def _briefs(folder: Path) -> Path:
    folder.mkdir()
    data = yaml.safe_load((DESIGNS / "cam_7_1.yaml").read_text(encoding="utf-8"))
    data["groups"] = {"default": 1, "variants": {1: {}, 2: {"disc.radius_R_mm": 45}}}
    (folder / "disc.yaml").write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    for name in ("cam_7_3.yaml", "lockbeam_cam.yaml"):
        (folder / name).write_text((DESIGNS / name).read_text(encoding="utf-8"), encoding="utf-8")
    (folder / "broken.yaml").write_text("machine: shaper\nreport: [1\n", encoding="utf-8")
    return folder


def _without_times(doc: dict) -> dict:
    return {**doc, "runs": [{k: v for k, v in run.items() if k != "seconds"} for run in doc["runs"]]}


@pytest.mark.e2e
def test_two_shards_merged_give_the_unsharded_index(tmp_path):
    briefs = _briefs(tmp_path / "designs")
    common = ["--groups", "all", "--format", "md", "--jobs", "1"]
    unsharded = runner.invoke(app, ["batch", str(briefs), "--out", str(tmp_path / "ref"), *common])
    assert unsharded.exit_code == 2, unsharded.output        # the broken brief
    out = tmp_path / "out"
    for i in (1, 2):   # as the CI machines do, each into its own out/, collected in one folder
        shard = runner.invoke(app, ["batch", str(briefs), "--shard", f"{i}/2", "--out", str(out),
                                    *common])
        assert shard.exit_code in (0, 2), shard.output
        assert (out / f"index.shard-{i}-of-2.json").is_file()
    assert not (out / "index.json").exists()
    merged = runner.invoke(app, ["merge", str(out)])
    assert merged.exit_code == 2, merged.output              # as the unsharded batch's
    assert "merged 5 runs: 4 ok, 1 invalid, 0 failed" in merged.output
    ref = json.loads((tmp_path / "ref" / "index.json").read_text(encoding="utf-8"))
    got = json.loads((out / "index.json").read_text(encoding="utf-8"))
    assert [r["id"] for r in got["runs"]] == [r["id"] for r in ref["runs"]]
    assert _without_times(got) == _without_times(ref)
    # index.md alike but for the time column
    def table(path):
        return [re.sub(r"\| [\d.]+ \|$", "|", line)
                for line in path.read_text(encoding="utf-8").splitlines()]
    assert table(out / "index.md") == table(tmp_path / "ref" / "index.md")
    for run in got["runs"]:
        if run["status"] == "ok":
            assert (out / run["links"]["report.md"]).is_file()


def test_merge_names_a_missing_shard_and_an_empty_folder(tmp_path):
    result = runner.invoke(app, ["merge", str(tmp_path)])
    assert result.exit_code == 2 and "no shard indexes" in result.output
    doc = {"schema": "mechdesign.batch/1", "shard": [1, 3], "runs": [], "totals": {}}
    (tmp_path / "index.shard-1-of-3.json").write_text(json.dumps(doc), encoding="utf-8")
    result = runner.invoke(app, ["merge", str(tmp_path)])
    assert result.exit_code == 2 and "shards 2/3, 3/3 missing" in result.output
    assert not (tmp_path / "index.json").exists()
