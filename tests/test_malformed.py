"""Malformed briefs: every one gives a message naming the problem and exit code 2, fast,
never a traceback, never a hang, and nothing is written (issue 7, points 5 and 6).

``tests/malformed/`` holds one problem per file; its first line says what the message
must contain: ``# expect: <text>`` (usually the field path).
"""
from __future__ import annotations

import os
import re
import subprocess
import sys
import time
from pathlib import Path

try:
    import resource
except ImportError:  # not on Windows
    resource = None

import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.brief import loader
from mechdesign.brief.loader import BriefError, load_variant
from mechdesign.cli import app

ROOT = Path(__file__).resolve().parents[1]
CORPUS = sorted((ROOT / "tests" / "malformed").glob("*.yaml"))
runner = CliRunner()


def expected(path: Path) -> str:
    first = path.read_bytes().split(b"\n", 1)[0].decode("utf-8").lstrip("\ufeff")
    assert first.startswith("# expect:"), f"{path.name}: first line must be '# expect: …'"
    return first.split(":", 1)[1].strip()


def assert_clean_failure(result, expect: str) -> None:
    assert result.exit_code == 2, result.output
    assert isinstance(result.exception, SystemExit), repr(result.exception)  # no other exception
    assert "Traceback" not in result.output
    assert expect in result.output, result.output


def test_corpus_covers_the_issue():
    assert len(CORPUS) >= 30
    texts = [expected(p) for p in CORPUS]
    assert len(set(p.name for p in CORPUS)) == len(CORPUS) and all(texts)
    # several machines and the groups table are covered
    machines = {m.group(1) for p in CORPUS
                for m in [re.search(rb"^machine: (\w+)", p.read_bytes(), re.M)] if m}
    assert len(machines) >= 6, machines
    names = " ".join(p.name for p in CORPUS)
    for kind in ("groups_", "billion_laughs", "huge_list", "deep_nesting", "binary_junk",
                 "not_yaml", "empty", "nan", "inf", "unit_in_number", "fraction", "unknown_machine"):
        assert kind in names, kind


@pytest.mark.parametrize("path", CORPUS, ids=lambda p: p.name)
def test_check_and_run_reject_with_a_message(path, tmp_path):
    expect = expected(path)
    assert_clean_failure(runner.invoke(app, ["check", "--lang", "en", str(path)]), expect)
    out = tmp_path / "out"
    assert_clean_failure(runner.invoke(app, ["run", str(path), "-o", str(out), "-f", "md", "--lang", "en"]), expect)
    assert not out.exists(), "a rejected brief must not write its output folder"
    assert list(tmp_path.iterdir()) == []


def timed_run(args: list[str]) -> tuple[subprocess.CompletedProcess, float, float]:
    """Run ``python -m mechdesign ARGS``; (result, wall time, CPU time of the child) [s]."""
    env = dict(os.environ, PYTHONIOENCODING="utf-8")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "mechdesign", *args], capture_output=True,
                          text=True, encoding="utf-8", env=env, timeout=30)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return proc, wall, cpu


@pytest.mark.e2e
@pytest.mark.skipif(resource is None, reason="needs the resource module (POSIX)")
@pytest.mark.parametrize("name", ["binary_junk.bin.yaml", "billion_laughs.yaml", "deep_nesting.yaml",
                                  "huge_list.yaml", "fraction_exponent.yaml"])
def test_real_process_refuses_it(name, tmp_path):
    """As a user runs it: a fresh interpreter, exit 2 with the problem named, no traceback,
    no output folder (the 30 s subprocess timeout only guards against a hang; the time it
    takes is a benchmark, benchmarks/bench_limits.py: target < 1 s)."""
    path = ROOT / "tests" / "malformed" / name
    for args in (["check", "--lang", "en", str(path)],
                 ["run", str(path), "-o", str(tmp_path / "o"), "-f", "md", "--lang", "en"]):
        proc, _wall, _cpu = timed_run(args)
        assert proc.returncode == 2, proc.stderr
        assert "Traceback" not in proc.stderr + proc.stdout
        assert expected(path) in proc.stderr
    assert not (tmp_path / "o").exists()


# --------------------------------------------------------------------------- the file itself


def problem_of(path) -> loader.BriefProblem:
    with pytest.raises(BriefError) as info:
        load_variant(path)
    (problem,) = info.value.problems
    return problem


def test_a_file_larger_than_the_limit_is_refused_unread(tmp_path):
    path = tmp_path / "big.yaml"
    path.write_text("machine: shaper\n" + "# padding\n" * (loader.MAX_BYTES // 10 + 10), encoding="utf-8")
    p = problem_of(path)
    assert p.path == "(file)" and f"at most {loader.MAX_BYTES} bytes" in p.allowed


def test_folder_missing_file_and_special_files(tmp_path):
    assert problem_of(tmp_path).value == "a folder"
    assert problem_of(tmp_path / "nope.yaml").value == "no such file"
    result = runner.invoke(app, ["check", "--lang", "en", str(tmp_path), str(tmp_path / "nope.yaml")])
    assert result.exit_code == 2 and "Traceback" not in result.output
    assert "a folder" in result.output and "no such file" in result.output
    if hasattr(os, "mkfifo"):  # a pipe nobody writes to: refused, not read (which would hang)
        fifo = tmp_path / "pipe.yaml"
        os.mkfifo(fifo)
        assert problem_of(fifo).value == "not a regular file"
    if Path("/dev/zero").exists():  # endless: refused without reading
        assert problem_of("/dev/zero").value == "not a regular file"


def test_utf16_and_bom(tmp_path):
    path = tmp_path / "u16.yaml"
    path.write_text("machine: shaper\n", encoding="utf-16")
    assert problem_of(path).value == "UTF-16 text"
    brief = (ROOT / "designs" / "cam_7_1.yaml").read_text(encoding="utf-8")
    path.write_bytes(b"\xef\xbb\xbf" + brief.encode("utf-8"))   # a BOM is harmless
    assert load_variant(path).brief.machine == "eccentric_cam"


# --------------------------------------------------------------------------- YAML limits


def write(tmp_path, text: str) -> Path:
    path = tmp_path / "b.yaml"
    path.write_text(text, encoding="utf-8")
    return path


def test_alias_bomb_is_counted_expanded_and_stopped_fast(tmp_path):
    # 10 lines that expand to 9**9 ≈ 3.9e8 strings; PyYAML shares them, but validating
    # and printing the value would walk every one (measured: 90 s for 9**8 before the limit).
    text = "machine: cam\na: &a [x, x, x, x, x, x, x, x, x]\n" + "".join(
        f"{n}: &{n} [*{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}]\n"
        for p, n in zip("abcdefgh", "bcdefghi")) + "report: *i\n"
    p = problem_of(write(tmp_path, text))
    assert f"more than {loader.MAX_VALUES} values" in p.value
    # the expansion is counted exactly: a list of 2 aliases to a 2-item list is 1 + 2·3 = 7 values
    loader_ = loader._UniqueKeyLoader("a: &a [1, 2]\nb: [*a, *a]\n")
    try:
        node = loader_.get_single_node()
    finally:
        loader_.dispose()
    # document: mapping 1, key a 1, [1, 2] 3, key b 1, list b 1 + 3 + 3
    assert node.value[1][1]._md_size == 7 and loader_._values == 1 + 1 + 3 + 1 + 7


def test_anchors_aliases_and_merge_keys_of_real_briefs_still_work(tmp_path):
    brief = (ROOT / "designs" / "cam_7_1.yaml").read_text(encoding="utf-8")
    brief = brief.replace('  - {label: "(a)", contact: knife}\n',
                          '  - &knife {label: "(a)", contact: knife}\n  - {<<: *knife, label: "(d)"}\n')
    b = load_variant(write(tmp_path, brief)).brief
    assert [(f.label, f.contact) for f in b.followers][:2] == [("(a)", "knife"), ("(d)", "knife")]


def test_deep_nesting_is_refused_before_python_recursion(tmp_path):
    text = "machine: cam\nreport: " + "[" * 20000 + "]" * 20000 + "\n"
    p = problem_of(write(tmp_path, text))       # no RecursionError (time: bench_limits.py)
    assert f"nested more than {loader.MAX_DEPTH}" in p.value and p.path.startswith("report.0.0")


def test_limits_sit_far_above_every_example():
    """The limits reject no real brief: each example stays 10x below every one."""
    for path in sorted((ROOT / "designs").glob("*.yaml")):
        raw = path.read_bytes()
        assert len(raw) * 10 < loader.MAX_BYTES
        ld = loader._UniqueKeyLoader(raw.decode("utf-8"))
        try:
            ld.get_single_node()
        finally:
            ld.dispose()
        assert ld._values * 5 < loader.MAX_VALUES, path.name


@pytest.mark.parametrize("text, value", [
    ("1" + "0" * 400, float("inf")),            # more digits than any float: int() would refuse 4300+
    ("-" + "9" * 5000, float("-inf")),
    ("0x" + "f" * 5000, float("inf")),         # read by int(), but str() of it would raise
    ("0b" + "1" * 2000, float("inf")),
    ("1e400", float("inf")),
    ("1" + "0" * 299, 10**299),                 # a big integer below the limit stays exact
    ("2026-13-45", "2026-13-45"),               # looks like a date, is none: kept as text
    ("!!timestamp hello", "hello"),             # an explicit tag on no date at all: the same
])
def test_numbers_python_cannot_hold_are_read_as_inf(text, value):
    assert yaml.load(f"v: {text}\n", Loader=loader._UniqueKeyLoader) == {"v": value}


@pytest.mark.parametrize("text, found", [
    ("v: !!float abc\n", "cannot be read as float"),
    ("v: !!int abc\n", "cannot be read as int"),
    ("v: !!bool maybe\n", "cannot be read as bool"),
    ("v: !!int 0x\n", "cannot be read as int"),
])
def test_explicit_tags_that_fail_give_the_line(tmp_path, text, found):
    p = problem_of(write(tmp_path, text))
    assert p.path == "line 1, column 4" and found in p.allowed


# --------------------------------------------------------------------------- values


def shaper_with(tmp_path, old: str, new: str) -> Path:
    text = (ROOT / "designs" / "shaper.yaml").read_text(encoding="utf-8")
    assert text.count(old) == 1
    return write(tmp_path, text.replace(old, new))


@pytest.mark.parametrize("value, allowed", [
    ("320 mm", "a number in mm, without the unit: write 320"),
    ("320mm", "a number in mm, without the unit: write 320"),
    ("0.32 m", "convert '0.32 m' to mm and write the number alone"),
    ("'320'", "a number, not text: write 320 without quotes"),
])
def test_a_number_with_its_unit_says_to_drop_the_unit(tmp_path, value, allowed):
    p = problem_of(shaper_with(tmp_path, "stroke_H_mm: 320 ", f"stroke_H_mm: {value} "))
    assert p.path == "linkage.stroke_H_mm" and allowed in p.allowed and p.allowed_zh


@pytest.mark.parametrize("text", ["1/0", "1 / 0.0", "1e1000000000", "1e400", "9" * 41, "1/2/3", "nan"])
def test_fraction_fields_refuse_what_is_no_fraction_quickly(tmp_path, text):
    p = problem_of(shaper_with(tmp_path, "fluctuation_delta: 1/25", f"fluctuation_delta: '{text}'"))
    assert p.path == "flywheel.fluctuation_delta" and "fraction such as 1/25" in p.allowed


@pytest.mark.parametrize("text, value", [("1/25", 0.04), (" 1 / 20 ", 0.05), ("0.04", 0.04), ("1/12.5", 0.08)])
def test_fraction_fields_read_fractions(text, value):
    from mechdesign.brief.common import parse_fraction

    assert parse_fraction(text, "bad") == pytest.approx(value, rel=1e-15)


def test_union_fields_are_reported_once_at_the_data_path(tmp_path):
    text = (ROOT / "designs" / "cam_7_3.yaml").read_text(encoding="utf-8")
    with pytest.raises(BriefError) as info:
        load_variant(write(tmp_path, text.replace("base_radius_mm: 50", "base_radius_mm: big")))
    (p,) = info.value.problems          # not one line per member of float | 'auto'
    assert p.path == "cam.base_radius_mm" and "valid number" in p.allowed and "'auto'" in p.allowed


def test_a_group_that_creates_a_section_is_blamed_in_the_group(tmp_path):
    text = (ROOT / "designs" / "cam_7_1.yaml").read_text(encoding="utf-8").replace(
        "machine: eccentric_cam\n",
        "machine: eccentric_cam\ngroups: {default: 1, variants: {1: {gear.teeth: 20}}}\n")
    (p,) = [q for q in _problems(write(tmp_path, text))]
    assert p.path == "groups.variants.1.gear.teeth" and "unknown field" in p.allowed


def _problems(path):
    with pytest.raises(BriefError) as info:
        load_variant(path)
    return info.value.problems


def test_loader_problems_have_chinese_text(tmp_path):
    for name in ("billion_laughs.yaml", "binary_junk.bin.yaml", "huge_list.yaml", "empty.yaml",
                 "two_documents.yaml", "unit_in_number.yaml"):
        (p,) = _problems(ROOT / "tests" / "malformed" / name)
        assert p.allowed_zh and any("\u4e00" <= c <= "\u9fff" for c in p.allowed_zh), name


def test_the_frame_link_cannot_be_a_moving_link(tmp_path):
    # Found by the property test: `crank.link: 1` made the crank the frame and the
    # force analysis a singular matrix (LinAlgError) instead of a brief problem.
    text = (ROOT / "designs" / "linkage_sixbar.yaml").read_text(encoding="utf-8")
    data = yaml.safe_load(text)
    data["linkage"]["crank"]["link"] = 1
    (p,) = _problems(write(tmp_path, yaml.safe_dump(data, allow_unicode=True)))
    assert p.path == "linkage.crank.link" and "link '1' is the frame" in p.allowed
