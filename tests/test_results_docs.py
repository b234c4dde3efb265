"""Typed results (issue 17 point 3): every machine registers a results class, every numeric
field of it (nested ones included) states its unit, results.json is produced from it, and
docs/results.md is generated from the field metadata and kept current."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from mechdesign.registry import entry, names, resolve
from mechdesign.results import SCHEMA, to_plain
from mechdesign.results_docs import markdown, missing_units, rows

ROOT = Path(__file__).parents[1]


@pytest.mark.parametrize("name", names())
def test_every_machine_has_typed_results_with_units(name):
    e = entry(name)
    assert e.results, f"{name}: no results class in its registry entry"
    cls = resolve(e.results)
    assert missing_units(cls) == []
    paths = [p for p, *_ in rows(cls)]
    assert paths[:3] == ["schema", "machine", "units"]


def test_missing_units_can_fail():
    from dataclasses import dataclass

    from mechdesign.core.fields import q

    @dataclass(frozen=True)
    class Bad:
        length: float = q("m")
        angle: float = 0.0          # a number without its unit
        name: str = ""

    assert missing_units(Bad) == ["angle"]


@pytest.mark.parametrize("name", ["shaper", "slotter", "linkage_sixbar", "cam_7_1"])
def test_results_json_is_the_typed_document(name, example_results):
    from mechdesign.machines import get_machine

    r = example_results(name)
    machine = get_machine(r["brief"].machine)
    doc = machine.document(r)
    cls = resolve(entry(machine.name).results)
    assert isinstance(doc, cls)
    plain = json.loads(json.dumps(to_plain(doc)))
    assert plain["schema"] == SCHEMA and plain["machine"] == machine.name
    # every documented top-level key is in the file and nothing else is
    top = {p.split(".")[0].removesuffix("[]") for p, *_ in rows(cls)}
    assert set(plain) == top


def test_docs_results_md_is_current():
    current = (ROOT / "docs" / "results.md").read_text(encoding="utf-8")
    assert current == markdown(), ("docs/results.md is stale; regenerate with: "
                                   "python -m mechdesign.results_docs > docs/results.md")


@pytest.mark.parametrize("name", names())
@pytest.mark.parametrize("lang", ["zh", "en"])
def test_every_machine_template_extends_the_one_base(name, lang):
    """Shared sections are written once (templates/*_section.*) and included by the base
    template whenever the context carries them; every machine's template extends it."""
    import re

    own = ROOT / "templates" / f"{name}.{lang}.md.j2"      # a language's own version, if any
    path = own if own.exists() else ROOT / "templates" / f"{name}.md.j2"
    text = path.read_text(encoding="utf-8")
    body = re.sub(r"\{##.*?##\}", "", text, flags=re.S).strip()
    assert body.startswith(('{% extends "base.md.j2" %}',
                            '{% extends "base.' + lang + '.md.j2" %}')), name
