"""The brief's two YAML readers agree: libyaml's scanner (brief.loader._FastLoader, used when
a file reads without error) gives the data PyYAML's (_UniqueKeyLoader, the reference, whose
messages the user sees) gives, and never reads a file PyYAML refuses.

The reference is PyYAML's pure-Python reader itself: each file is read by both and compared.
"""
from __future__ import annotations

import random
from pathlib import Path

import pytest
import yaml

from mechdesign.brief import loader as L

ROOT = Path(__file__).resolve().parents[1]
BRIEFS = sorted((ROOT / "designs").rglob("*.yaml"))

pytestmark = pytest.mark.skipif(L._FastLoader is None, reason="PyYAML built without libyaml")


def _read(loader, text: str):
    try:
        return "ok", repr(yaml.load(text, Loader=loader))  # noqa: S506 - safe loaders
    except Exception as exc:  # noqa: BLE001 - the kind of outcome is compared
        return "error", type(exc).__name__


@pytest.mark.parametrize("path", BRIEFS, ids=lambda p: p.name)
def test_every_example_reads_the_same(path):
    text = path.read_text(encoding="utf-8")
    assert not L._PYYAML_ONLY.search(text)          # the examples take the fast path
    assert _read(L._FastLoader, text) == _read(L._UniqueKeyLoader, text)
    assert _read(L._FastLoader, text)[0] == "ok"


# Characters and tokens YAML gives a meaning to, and text that looks like them.
_PIECES = list(":-[]{}#&*!|>'\"%@`,? \n\r\\.0ex中é~") + [
    "\t", "\ufeff", "\x85", "\u2028", "\u3000", "\u00a0", "\x1b", "---", "...", "<<: ", "- ",
    ": ", "!!str ", "!!float ", "!!python/name:os.system ", "&a ", "*a", "? ", "|-\n", ">+\n",
    "%YAML 1.1\n---\n", "'", '"\\x41"', "0x1F", "0o17", "1_000", ".inf", "-.nan", "2026-13-45",
    "2026-11-22T10:00:00Z", "yes", "null", "<<"]


def _mutants(n: int, seed: int):
    rnd = random.Random(seed)
    texts = [p.read_text(encoding="utf-8") for p in BRIEFS]
    for _ in range(n):
        text = rnd.choice(texts)
        for _ in range(rnd.randint(1, 4)):
            pos, kind = rnd.randrange(len(text) + 1), rnd.random()
            if kind < 0.55:
                text = text[:pos] + rnd.choice(_PIECES) + text[pos:]
            elif kind < 0.75:
                text = text[:pos] + text[pos + rnd.randint(1, 5):]
            else:
                lines = text.split("\n")
                lines.insert(rnd.randrange(len(lines)), rnd.choice(lines))
                text = "\n".join(lines)
        yield text


def test_mutated_briefs_read_the_same_or_by_pyyaml_alone():
    """Differential fuzzing: whenever libyaml's scanner reads a damaged brief, PyYAML's reads
    the same data (where they differ — a tab, a ``?`` in a flow scalar, a byte-order mark —
    the file goes to PyYAML alone); errors are reported by PyYAML's reader."""
    fast = 0
    for text in _mutants(400, seed=22):
        if L._PYYAML_ONLY.search(text):
            continue
        outcome = _read(L._FastLoader, text)
        if outcome[0] == "ok":
            fast += 1
            assert outcome == _read(L._UniqueKeyLoader, text), text
    assert fast > 100


def test_errors_are_pyyaml_s(tmp_path):
    """A file libyaml refuses is read again by PyYAML, whose message names the problem."""
    path = tmp_path / "b.yaml"
    path.write_text("machine: cam\nreport: {title: x\n", encoding="utf-8")
    with pytest.raises(L.BriefError) as fast:
        L.read_brief_data(path)
    with pytest.raises(yaml.YAMLError) as reference:
        yaml.load(path.read_text(encoding="utf-8"), Loader=L._UniqueKeyLoader)  # noqa: S506
    # PyYAML: "expected ',' or '}', but got '<stream end>'"; libyaml: "did not find expected …"
    assert reference.value.problem == "expected ',' or '}', but got '<stream end>'"
    assert reference.value.problem in str(fast.value)
