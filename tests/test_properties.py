"""Property-based tests (hypothesis): random changes to the shipped example briefs.

The contract (issue 7): a brief either loads or raises BriefError, and every problem
names a real path into the brief's data (or one of the loader's special paths); a brief
that loads converts to SI parameters (or raises ValueError, which ``run`` reports as an
invalid brief) and its stages either finish or raise one of the design errors, never
another exception (ZeroDivisionError, IndexError, a singular matrix, a numpy warning).

The strategies start from ``designs/*.yaml`` and replace a random value with a random
one (numbers of every sign and size, nan/inf, text, lists, mappings, null, booleans, a
number with its unit), delete a key, add an unknown key, or scale numbers to absurd
sizes. Runs are derandomized (the same examples every time) and sized to take a few
seconds; ``@example`` keeps the cases that once broke.
"""
from __future__ import annotations

import copy
import re
import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from mechdesign.brief.loader import BriefError, load_variant
from mechdesign.machines import get_machine, stages_for
from mechdesign.pipeline import run_stages
from mechdesign.runner import design_error_kinds

ROOT = Path(__file__).resolve().parents[1]
DESIGNS = {p.name: yaml.safe_load(p.read_text(encoding="utf-8"))
           for p in sorted((ROOT / "designs").glob("*.yaml"))}
#: Quick to compute (a full pipeline well under 0.3 s), for the stage property.
QUICK = ["cam_7_1.yaml", "crank_rocker.yaml", "die_cutter.yaml", "furnace_drive.yaml",
         "furnace_pusher.yaml", "linkage_sixbar.yaml", "shaper.yaml"]
DESIGN_ERRORS = tuple(design_error_kinds())
SPECIAL = re.compile(r"^(\(file\)|\(top level\)|line \d+, column \d+|--group)$")

SETTINGS = dict(derandomize=True, deadline=None, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


# --------------------------------------------------------------------------- paths


def paths(node, prefix=()):
    """Every path into ``node`` (mappings and lists), the root excluded, in document order."""
    if isinstance(node, dict):
        items = list(node.items())
    elif isinstance(node, list):
        items = list(enumerate(node))
    else:
        return
    for key, value in items:
        yield prefix + (key,)
        yield from paths(value, prefix + (key,))


def parent_of(data, path):
    for part in path[:-1]:
        data = data[part]
    return data


def resolves(data, dotted: str, missing_ok: bool) -> bool:
    """``dotted`` leads into ``data``; keys may themselves contain dots (a group's
    ``pusher.stroke_H_mm``); a missing field may end the path when ``missing_ok``."""
    parts = dotted.split(".")
    node, i = data, 0
    while i < len(parts):
        if isinstance(node, dict):
            for j in range(len(parts), i, -1):
                key = next((k for k in node if str(k) == ".".join(parts[i:j])), KeyError)
                if key is not KeyError:
                    node, i = node[key], j
                    break
            else:
                rest = ".".join(parts[i:])
                if any(str(k).startswith(rest + ".") for k in node):
                    return True      # a group's dotted key, cut where its problem is
                return missing_ok and i == len(parts) - 1
        elif isinstance(node, list) and parts[i].isdigit() and int(parts[i]) < len(node):
            node, i = node[int(parts[i])], i + 1
        else:
            return False
    return True


# --------------------------------------------------------------------------- strategies

UNITS = ["mm", " mm", " m", "°", " deg", " rpm", " N", " kg", "%"]

numbers = st.one_of(
    st.integers(-10, 10), st.integers(-10**6, 10**6), st.integers(10**15, 10**20),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0.0, -0.0, 1e-300, 5e-324, 1e-9, 1e9, 1e300, -1e300, 2.0**53]))
junk = st.one_of(
    numbers, st.none(), st.booleans(), st.text(max_size=12),
    st.sampled_from(["auto", "", "1/0", "1/25", "nan", "inf", "-inf", "1e999", "~", "yes",
                     "cw", "ccw", "3,5", "0x10", "1_000"]),
    st.lists(st.integers(-5, 5), max_size=4),
    st.dictionaries(st.sampled_from(["a", "type", "link", "mm", "1"]), st.integers(-5, 5), max_size=3),
    st.builds(lambda x, u: f"{x:g}{u}", st.floats(-1e4, 1e4), st.sampled_from(UNITS)))


@st.composite
def mutated(draw, names=tuple(DESIGNS)):
    """(design name, data, what was done) with one or two random changes."""
    name = draw(st.sampled_from(names))
    data = copy.deepcopy(DESIGNS[name])
    done = []
    for _ in range(draw(st.integers(1, 2))):
        where = list(paths(data))
        path = draw(st.sampled_from(where))
        action = draw(st.sampled_from(["replace", "replace", "replace", "delete", "add", "unit"]))
        parent, key = parent_of(data, path), path[-1]
        if action == "delete" and isinstance(parent, dict):
            del parent[key]
        elif action == "add" and isinstance(parent[key], dict):
            parent[key][draw(st.sampled_from(["extra", "stroke_H", "Unit_mm", "2"]))] = draw(junk)
        elif action == "unit" and isinstance(parent[key], (int, float)) \
                and not isinstance(parent[key], bool):
            parent[key] = f"{parent[key]}{draw(st.sampled_from(UNITS))}"
        else:
            action = "replace"
            parent[key] = draw(junk)
        done.append((action, ".".join(map(str, path))))
    return name, data, done


@st.composite
def absurd(draw, names=tuple(QUICK)):
    """A design with one to three numbers scaled to absurd (but often still valid) sizes."""
    name = draw(st.sampled_from(names))
    data = copy.deepcopy(DESIGNS[name])
    data.pop("groups", None)
    numeric = [p for p in paths(data) if p[0] != "report"
               and isinstance(parent_of(data, p)[p[-1]], (int, float))
               and not isinstance(parent_of(data, p)[p[-1]], bool)]
    done = []
    for _ in range(draw(st.integers(1, 3))):
        path = draw(st.sampled_from(numeric))
        parent = parent_of(data, path)
        factor = draw(st.sampled_from([0, -1, 1e-9, 1e-4, 0.01, 0.3, 0.9, 0.999, 1.001, 1.1, 2,
                                       10, 1e3, 1e6]))
        value = parent[path[-1]] * factor if parent[path[-1]] else factor
        if isinstance(parent[path[-1]], int) and abs(value) < 1e12:
            value = int(round(value))
        parent[path[-1]] = value
        done.append((".".join(map(str, path)), value))
    return name, data, done


# --------------------------------------------------------------------------- the properties


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return tmp_path_factory.mktemp("briefs")


def write(folder: Path, data) -> Path:
    path = folder / "brief.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True, sort_keys=False), encoding="utf-8")
    return path


def load_or_problems(path: Path, data):
    """The loaded variant, or None after checking every problem's path."""
    try:
        return load_variant(path)
    except BriefError as exc:
        assert exc.problems, "a BriefError names at least one problem"
        for p in exc.problems:
            assert SPECIAL.match(p.path) or resolves(data, p.path, missing_ok=p.value == "missing"
                                                      or p.path.startswith("groups.")), \
                f"problem path {p.path!r} is not in the data ({p})"
            assert p.value and p.allowed
        return None


def compute(variant):
    """to_params and every stage; only the errors a run reports as an invalid design pass."""
    machine = get_machine(variant.brief.machine)
    try:
        params = machine.to_params(variant.brief)
    except ValueError:        # runner: exit 2 with the message
        return "invalid"
    # Overflow, 0/0 and x/0 raise (a silent inf or nan would reach the report); an
    # underflow to 0 is harmless.
    with warnings.catch_warnings(), np.errstate(divide="raise", over="raise", invalid="raise"):
        warnings.simplefilter("error", RuntimeWarning)
        try:
            run_stages(stages_for(machine, params), {"params": params, "brief": variant.brief})
        except DESIGN_ERRORS:
            return "infeasible"
    return "ok"


def _changed(name, path, value):
    data = copy.deepcopy(DESIGNS[name])
    parent_of(data, path)[path[-1]] = value
    return name, data, [("replace", ".".join(map(str, path)))]


@settings(max_examples=150, **SETTINGS)
@given(mutated())
@example(("cam_7_1.yaml", {"machine": "eccentric_cam", "report": [1]}, []))
# once reported at cam.base_radius_mm.float and cam.base_radius_mm.literal['auto']
@example(_changed("cam_7_3.yaml", ("cam", "base_radius_mm"), "big"))
# once reported at linkage.groups.0.RRR.lengths_mm (the union member's tag)
@example(_changed("linkage_sixbar.yaml", ("linkage", "groups", 0, "lengths_mm"), [-1, 5]))
# a group creating a section the brief lacks: once reported at `gear`, not in the data
@example(_changed("shaper.yaml", ("groups", "variants", "I"), {"gear.teeth": 3}))
# once a hang: Fraction('1e1000000000') computes 10**1000000000
@example(_changed("shaper.yaml", ("flywheel", "fluctuation_delta"), "1e1000000000"))
def test_any_change_loads_or_names_real_paths(folder, case):
    name, data, _ = case
    load_or_problems(write(folder, data), data)


@settings(max_examples=80, **SETTINGS)
@given(mutated(names=tuple(QUICK)))
def test_a_changed_brief_that_loads_computes_or_fails_by_name(folder, case):
    _, data, _ = case
    variant = load_or_problems(write(folder, data), data)
    if variant is not None:
        compute(variant)


TEXTS = {p.name: p.read_text(encoding="utf-8") for p in sorted((ROOT / "designs").glob("*.yaml"))}
SPECIALS = list("&*!|>{}[]:,-?#%@`'\"\t\n \\<") + ["\x00", "\x07", "\ufeff", "---\n", "<<: ",
                                                 "!!python/name:os.system ", "*a", "&a ", "é", "\r"]


@st.composite
def garbled(draw):
    """An example file with a few characters inserted, deleted or replaced (YAML's special
    characters weighted up), as text or as raw bytes."""
    text = TEXTS[draw(st.sampled_from(sorted(TEXTS)))]
    for _ in range(draw(st.integers(1, 4))):
        i = draw(st.integers(0, len(text)))
        j = min(len(text), i + draw(st.integers(0, 3)))
        new = draw(st.one_of(st.sampled_from(SPECIALS), st.text(max_size=3)))
        text = text[:i] + new + text[j:]
    raw = text.encode("utf-8", "surrogatepass")
    if draw(st.booleans()):
        return raw
    i = draw(st.integers(0, len(raw)))
    return raw[:i] + draw(st.binary(max_size=4)) + raw[i:]


@settings(max_examples=300, **SETTINGS)
@given(st.one_of(garbled(), st.binary(max_size=300)))
@example(b"v: !!timestamp hello\n")        # once AttributeError from PyYAML's date reader
@example(b"v: 0x" + b"f" * 5000 + b"\n")   # once ValueError printing the value (4300 digits)
def test_garbled_files_load_or_fail_as_brief_errors(folder, raw):
    path = folder / "garbled.yaml"
    path.write_bytes(raw)
    try:
        load_variant(path)
    except BriefError as exc:
        for p in exc.problems:
            assert p.path and p.value and p.allowed


def _crank_is_frame():
    data = copy.deepcopy(DESIGNS["linkage_sixbar.yaml"])
    data["linkage"]["crank"]["link"] = 1     # once: LinAlgError (singular matrix) in the forces
    return ("linkage_sixbar.yaml", data, [("linkage.crank.link", 1)])


@settings(max_examples=60, **SETTINGS)
@given(absurd())
@example(_crank_is_frame())
def test_absurd_values_load_or_compute_or_fail_by_name(folder, case):
    _, data, _ = case
    variant = load_or_problems(write(folder, data), data)
    if variant is not None:
        compute(variant)


def test_the_strategies_reach_the_stages(folder):
    """Guard against a property that cannot fail: a fair share of the changed briefs
    loads and runs the stages (else the stage properties would test nothing)."""
    import random

    rng = random.Random(7)
    outcomes = []
    for _ in range(12):
        name = rng.choice(QUICK)
        data = copy.deepcopy(DESIGNS[name])
        data.pop("groups", None)
        numeric = [p for p in paths(data) if p[0] != "report"
                   and type(parent_of(data, p)[p[-1]]) in (int, float)]
        path = rng.choice(numeric)
        parent_of(data, path)[path[-1]] *= rng.choice([0.98, 1.02])
        variant = load_or_problems(write(folder, data), data)
        outcomes.append("brief" if variant is None else compute(variant))
    assert outcomes.count("ok") >= 6, outcomes


def test_resolves_is_strict():
    data = {"a": {"b.c": 1, "d": [0, {"e": 2}]}}
    assert resolves(data, "a.b.c", False) and resolves(data, "a.d.1.e", False)
    assert not resolves(data, "a.x", False) and resolves(data, "a.x", True)
    assert not resolves(data, "a.d.2", True) and not resolves(data, "a.x.y", True)
    assert not resolves(data, "a.d.1.e.f", True)
    assert resolves(data, "a.b", False)          # the start of a dotted key (a group's path)
