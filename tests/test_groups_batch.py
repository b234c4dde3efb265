"""Data groups (brief/groups.py, run --group) and batch runs (batch.py, mechdesign batch).

References are independent of the code under test: group overrides are checked against
the YAML edited by hand, job counts against the groups tables read with PyYAML, shards
against the definition of a partition, statuses against briefs known to be good or bad.
"""
from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.batch import (Job, Progress, collect_briefs, exit_code, index_document,
                              index_markdown, parse_shard, plan_jobs, shard, BatchError)
from mechdesign.brief.groups import GroupError, apply_group, parse_groups
from mechdesign.brief.loader import BriefError, brief_groups, brief_schema, load_variant
from mechdesign.cli import app
from mechdesign.machines import get_machine

DESIGNS = Path(__file__).resolve().parents[1] / "designs"
runner = CliRunner()


def _write(path: Path, data: dict) -> Path:
    path.write_text(yaml.safe_dump(data, allow_unicode=True, sort_keys=False), encoding="utf-8")
    return path


def _furnace() -> dict:
    return yaml.safe_load((DESIGNS / "furnace_pusher.yaml").read_text(encoding="utf-8"))


# ------------------------------------------------------------------------ the groups table
def test_apply_group_dotted_nested_and_list_paths():
    data = {"machine": "x", "a": {"b": 1, "c": [{"d": 1}, {"d": 2}]}}
    table = parse_groups({"variants": {2: {"a.b": 5, "a.c.1.d": 7}, "II": {"a": {"b": 9}}}})
    assert table.labels == ["2", "II"]
    out, located = apply_group(data, table, "2")
    assert out["a"]["b"] == 5 and out["a"]["c"][1]["d"] == 7 and out["a"]["c"][0]["d"] == 1
    assert located == {"a.b": "groups.variants.2.a.b", "a.c.1.d": "groups.variants.2.a.c.1.d"}
    assert data["a"]["b"] == 1 and data["a"]["c"][1]["d"] == 2      # the input is not changed
    out, _ = apply_group(data, table, "II")
    assert out["a"] == {"b": 9, "c": [{"d": 1}, {"d": 2}]}             # nested mapping merges


@pytest.mark.parametrize("raw, where", [
    ([1, 2], "groups"),
    ({"variants": {}}, "groups.variants"),
    ({"variants": {1: {}}, "default": 2}, "groups.default"),
    ({"variants": {1: {}}, "extra": 1}, "groups.extra"),
    ({"variants": {1: 5}}, "groups.variants.1"),
    ({"variants": {1: {}, "1": {}}}, "groups.variants.1"),
])
def test_malformed_groups_tables_name_the_field(raw, where):
    with pytest.raises(GroupError) as info:
        parse_groups(raw)
    assert info.value.path == where


@pytest.mark.parametrize("overrides, where", [
    ({"machine": "shaper"}, "groups.variants.1.machine"),
    ({"a.c.5.d": 1}, "groups.variants.1.a.c.5"),
    ({"a.b.z": 1}, "groups.variants.1.a.b.z"),
])
def test_bad_overrides_name_the_path(overrides, where):
    table = parse_groups({"variants": {1: overrides}})
    with pytest.raises(GroupError) as info:
        apply_group({"machine": "x", "a": {"b": 1, "c": [{"d": 1}]}}, table, "1")
    assert info.value.path == where


def test_group_values_reach_the_parameters(tmp_path):
    """Group 3 of the shipped furnace brief: the SI parameters carry the group's H and K,
    the fields no group touches keep the brief's values."""
    data = _furnace()
    group3 = data["groups"]["variants"][3]
    v = load_variant(DESIGNS / "furnace_pusher.yaml", "3")
    assert v.group == "3" and v.groups == tuple(str(k) for k in data["groups"]["variants"])
    assert v.brief.pusher.stroke_H_mm == group3["pusher.stroke_H_mm"]
    assert v.brief.pusher.time_ratio_K == group3["pusher.time_ratio_K"]
    assert v.brief.pusher.rocker_DC_mm == data["pusher"]["rocker_DC_mm"]
    default = load_variant(DESIGNS / "furnace_pusher.yaml")
    assert default.group == str(data["groups"]["default"])
    assert default.brief.pusher.stroke_H_mm == data["pusher"]["stroke_H_mm"]


def test_a_bad_value_in_a_group_is_reported_in_the_group(tmp_path):
    data = _furnace()
    data["groups"]["variants"]["bad"] = {"pusher": {"stroke_H_mm": -5}}
    path = _write(tmp_path / "f.yaml", data)
    load_variant(path, "2")                                      # other groups are fine
    with pytest.raises(BriefError) as info:
        load_variant(path, "bad")
    assert [p.path for p in info.value.problems] == ["groups.variants.bad.pusher.stroke_H_mm"]
    with pytest.raises(BriefError) as info:
        load_variant(path, "nope")
    assert info.value.problems[0].path == "--group" and "bad" in info.value.problems[0].allowed


def test_group_option_on_a_brief_without_groups():
    with pytest.raises(BriefError) as info:
        load_variant(DESIGNS / "cam_7_1.yaml", "2")
    assert "no `groups` table" in str(info.value)


def test_schema_offers_groups_for_every_machine():
    schema = brief_schema()
    assert "Groups" in schema["$defs"]
    briefs = [d for d in schema["$defs"].values()
              if "machine" in d.get("properties", {}) and "report" in d.get("properties", {})]
    from mechdesign.registry import names

    assert len(briefs) == len(names()) == 11   # with the press (issue 18)
    assert all(d["properties"]["groups"] == {"$ref": "#/$defs/Groups"} for d in briefs)


def test_check_validates_every_group(tmp_path):
    data = _furnace()
    result = runner.invoke(app, ["check", str(_write(tmp_path / "ok.yaml", data))])
    assert result.exit_code == 0 and "groups 1, 2, 3, 4" in result.output
    data["groups"]["variants"][4]["pusher.time_ratio_K"] = 0.5
    result = runner.invoke(app, ["check", str(_write(tmp_path / "bad.yaml", data))])
    assert result.exit_code == 2
    assert "groups.variants.4.pusher.time_ratio_K" in result.output


@pytest.mark.e2e
def test_run_with_a_group_states_it(tmp_path):
    """`run --group 2` computes group 2's stroke and says so in the report and results."""
    out = tmp_path / "g2"
    result = runner.invoke(app, ["run", str(DESIGNS / "furnace_pusher.yaml"), "--group", "2",
                                 "-o", str(out), "-f", "md"])
    assert result.exit_code == 0, result.output
    doc = json.loads((out / "results.json").read_text(encoding="utf-8"))
    H = _furnace()["groups"]["variants"][2]["pusher.stroke_H_mm"] / 1000
    assert doc["data_group"] == "2"
    assert abs(doc["linkage"]["output"]["stroke"] - H) < 1e-9
    md = (out / "report.md").read_text(encoding="utf-8")
    assert md.startswith("**分组（方案）：2**")


# ------------------------------------------------------------------------------- batch
def test_plan_all_groups_counts_every_variant():
    briefs = collect_briefs([DESIGNS])
    assert briefs == sorted(DESIGNS.rglob("*.yaml"))    # designs/class/ included
    expected = 0
    for path in briefs:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
        if "groups" not in data:
            expected += 1
        elif "file" in data["groups"]:                   # a class table: one group per row
            with open(path.parent / data["groups"]["file"], encoding="utf-8", newline="") as f:
                expected += len(list(csv.reader(f))) - 1
        else:
            expected += len(data["groups"]["variants"])
    jobs = plan_jobs(briefs, "all")
    assert len(jobs) == expected > len(briefs)
    assert len({j.run_id for j in jobs}) == len(jobs)
    assert len(plan_jobs(briefs, "default")) == len(briefs)
    assert {j.group for j in plan_jobs(briefs, "2,III") if j.group} == {"2", "III"}


def test_shards_partition_the_jobs_deterministically():
    jobs = plan_jobs(collect_briefs([DESIGNS]), "all")
    for n in (1, 2, 3, 5, len(jobs) + 2):
        parts = [shard(jobs, (i, n)) for i in range(1, n + 1)]
        flat = [j for part in parts for j in part]
        assert sorted(flat, key=jobs.index) == jobs and len(flat) == len(jobs)
        assert max(map(len, parts)) - min(map(len, parts)) <= 1
        assert parts == [shard(plan_jobs(collect_briefs([DESIGNS]), "all"), (i, n))
                         for i in range(1, n + 1)]


@pytest.mark.parametrize("text", ["0/3", "4/3", "1/0", "a/b", "3", "1/2/3"])
def test_bad_shard(text):
    with pytest.raises(BatchError):
        parse_shard(text)


def test_same_stem_in_two_folders_gets_two_folders(tmp_path):
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    for d in ("a", "b"):
        (tmp_path / d / "cam.yaml").write_text((DESIGNS / "cam_7_1.yaml").read_text(encoding="utf-8"),
                                              encoding="utf-8")
    jobs = plan_jobs(collect_briefs([tmp_path]), "all")
    assert [j.run_id for j in jobs] == ["a_cam", "b_cam"]


def test_group_labels_cannot_leave_the_output_folder(tmp_path):
    data = yaml.safe_load((DESIGNS / "cam_7_1.yaml").read_text(encoding="utf-8"))
    data["groups"] = {"variants": {"../../escape": {}, "方案一": {}}}
    jobs = plan_jobs([_write(tmp_path / "c.yaml", data)], "all")
    for job in jobs:
        assert "/" not in job.run_id and ".." not in job.run_id and job.run_id.startswith("c-g")


@pytest.mark.e2e
def test_batch_continues_past_a_bad_brief_and_indexes_everything(tmp_path):
    """Two good briefs (one with two groups) and a broken one, two workers: every good
    report is written, the index lists all four runs, the exit code is 2."""
    good = tmp_path / "briefs"
    good.mkdir()
    data = yaml.safe_load((DESIGNS / "cam_7_1.yaml").read_text(encoding="utf-8"))
    data["groups"] = {"default": 1, "variants": {1: {}, 2: {"disc.radius_R_mm": 45}}}
    _write(good / "disc.yaml", data)
    (good / "drive.yaml").write_text((DESIGNS / "furnace_drive.yaml").read_text(encoding="utf-8"),
                                     encoding="utf-8")
    (good / "broken.yaml").write_text("machine: shaper\nreport: [1\n", encoding="utf-8")
    out = tmp_path / "out"
    result = runner.invoke(app, ["batch", str(good), "--groups", "all", "--jobs", "2",
                                 "-o", str(out), "-f", "md"])
    assert result.exit_code == 2, result.output
    index = json.loads((out / "index.json").read_text(encoding="utf-8"))
    status = {r["id"]: r["status"] for r in index["runs"]}
    assert status == {"broken": "invalid", "disc-g1": "ok", "disc-g2": "ok", "drive": "ok"}
    assert index["totals"] == {"runs": 4, "ok": 3, "invalid": 1, "failed": 0}
    for run in index["runs"]:
        if run["status"] == "ok":
            assert (out / run["links"]["report.md"]).is_file()
            assert run["summary"]
    assert not (out / "broken").exists()
    r2 = json.loads((out / "disc-g2" / "results.json").read_text(encoding="utf-8"))
    assert abs(r2["radius"] - 0.045) < 1e-12 and r2["data_group"] == "2"
    md = (out / "index.md").read_text(encoding="utf-8")
    assert md.count("\n| ") == 5 and "(<disc-g2/report.md>)" in md and "broken" in md
    assert "[1/4]" in result.output and "[4/4]" in result.output


def test_no_briefs_is_a_clear_error(tmp_path):
    result = runner.invoke(app, ["batch", str(tmp_path)])
    assert result.exit_code == 2 and "no briefs" in result.output
    result = runner.invoke(app, ["batch", str(tmp_path / "missing.yaml")])
    assert result.exit_code == 2 and "no such file" in result.output


def test_exit_code_and_progress_lines():
    ok = {"status": "ok", "exit_code": 0, "seconds": 1.0}
    bad = {"status": "invalid", "exit_code": 2, "message": "x.yaml: 1 problem\n  a: b — c"}
    failed = {"status": "failed", "exit_code": 1, "message": "boom"}
    assert exit_code([ok, ok]) == 0 and exit_code([ok, failed]) == 1
    assert exit_code([failed, bad]) == 2
    stream = io.StringIO()
    p = Progress(2, stream, tty=False)
    p.update(Job("x.yaml", None, "x"), bad)
    p.update(Job("y.yaml", None, "y"), ok)
    lines = stream.getvalue().splitlines()
    assert lines[0].startswith("[1/2] invalid x") and "  a: b — c" in lines[2]
    assert lines[-1].startswith("[2/2] ok") and "\r" not in stream.getvalue()
    tty = io.StringIO()
    Progress(1, tty, tty=True).update(Job("y.yaml", None, "y"), ok)
    assert "\r" in tty.getvalue() and "1/1" in tty.getvalue()


def test_index_markdown_escapes_user_text():
    doc = index_document([Job("a|b*.yaml", "I", "a")],
                         [{"status": "ok", "exit_code": 0, "group": "I|*", "machine": "cam",
                           "files": (), "summary": (("r | x", "5"),)}], Path("."))
    md = index_markdown(doc, "en")
    row = md.splitlines()[-1]
    assert row.count(" | ") == 7            # the user's | did not add a column (8 columns: the
    #                                         student's was added after the group's)
