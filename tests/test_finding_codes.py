"""Findings hold codes and numbers, never prose (issue 22 point 3): a finding is its code, a
catalogue msgid, the message's fields as data and the brief field; its text is made where it
is shown, in the report's language (zh, en or the zh_TW variant), and results.json stores
no Chinese in a finding's own fields (the English ``text`` beside them is the rendering)."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from mechdesign import i18n
from mechdesign.brief.loader import parse_brief, read_brief_data
from mechdesign.data import load_yaml
from mechdesign.i18n import Msg
from mechdesign.machines import get_machine, stages_for
from mechdesign.pipeline import run_stages
from mechdesign.results import dumps, to_plain
from mechdesign.stages.findings import Finding, Named, finding

DESIGNS = Path(__file__).parents[1] / "designs"
CJK = re.compile(r"[\u3000-\u303f\u3400-\u9fff\uff00-\uffef]")

# one of the drive's undercut messages, with a data-table name and a nested message
UNDERCUT = ("stage {n} ({name}): the {who} (z = {z}) is undercut: its equivalent tooth number z_v = "
            "z/cos³β = {zv:.2f} is below the least number without undercut, {z_min:g}; give it at "
            "least {need} teeth or use a larger helix angle.")
STAGE = "stage {n} ({name})"


@pytest.fixture
def variant_reset():
    yield
    i18n.set_variant(None)


def _expected(lang: str) -> str:
    """The catalogue's text of the finding below, assembled by hand from the .po entries
    and the data table (not through the finding)."""
    po = {"zh": "zh", "zh_TW": "zh_TW", "en": None}[lang]
    msg = UNDERCUT if po is None else i18n.catalogue(po)[(None, UNDERCUT)]
    name = load_yaml("transmissions.yaml")["helical"]["name_en" if lang == "en" else "name_zh"]
    if lang == "zh_TW":          # the data table's name converted with the catalogue (zh_TW.data.json)
        name = i18n.data_names("zh_TW")[name]
    who = "pinion" if po is None else i18n.catalogue(po)[("gear", "pinion")]
    return msg.format(n=2, name=name, who=who, z=14, zv=17.0123, z_min=17.1, need=15)


def _finding() -> Finding:
    return finding("undercut", UNDERCUT, field="drive.stages[1].z1", n=2, name=Named("transmissions", "helical"),
                   who=Msg.pgettext("gear", "pinion"), z=14, zv=17.0123, z_min=17.1, need=15)


def test_a_finding_is_rendered_in_the_language_it_is_shown_in(variant_reset):
    f = _finding()
    assert f.code == "undercut" and f.msgid == UNDERCUT and f.field == "drive.stages[1].z1"
    assert f.text("en") == _expected("en") and f.en == f.text("en")
    assert f.text("zh") == _expected("zh") and CJK.search(f.text("zh"))
    # the zh_TW catalogue, asked for after the finding was made: its words, not zh.po's
    assert i18n.catalogue("zh_TW")[(None, UNDERCUT)] != i18n.catalogue("zh")[(None, UNDERCUT)]
    assert f.text("zh_TW") == _expected("zh_TW")
    i18n.set_variant("zh_TW")          # a zh_TW run: its report asks for "zh"
    assert f.text("zh") == _expected("zh_TW")


def test_a_nested_message_is_translated_with_its_finding(variant_reset):
    f = finding("x", STAGE + ": the {who}", n=1, name=Msg.pgettext("gear", "pinion"),
                who=Msg.pgettext("gear", "wheel"))
    assert f.args["name"] == {"msgid": "pinion", "context": "gear"}
    for lang in ("zh", "zh_TW"):
        cat = i18n.catalogue(lang)
        want = cat.get((None, STAGE + ": the {who}"), STAGE + ": the {who}")
        assert f.text(lang) == want.format(n=1, name=cat[("gear", "pinion")], who=cat[("gear", "wheel")])
    assert f.text("en") == "stage 1 (pinion): the wheel"


def test_a_finding_survives_json_and_holds_no_prose_of_its_own():
    f = _finding()
    plain = json.loads(dumps({"w": [f]}))["w"][0]
    assert plain["text"] == _expected("en")
    assert not CJK.search(json.dumps({k: v for k, v in plain.items()}, ensure_ascii=False))
    back = Finding(**{k: v for k, v in plain.items() if k != "text"})
    assert back == f and back.text("zh") == _expected("zh") and hash(back) == hash(f)


def _run(data: dict) -> tuple[dict, dict]:
    data.pop("groups", None)
    b = parse_brief(data)
    m = get_machine(b.machine)
    p = m.to_params(b)
    results = run_stages(stages_for(m, p), {"params": p, "brief": b})[0]
    return results, json.loads(dumps(to_plain(m.document(results))))


def _findings(node, path="") -> list[tuple[str, dict]]:
    if isinstance(node, list):
        return [x for j, v in enumerate(node) for x in _findings(v, f"{path}[{j}]")]
    if not isinstance(node, dict):
        return []
    if {"code", "msgid", "args", "field", "text"} <= node.keys():
        return [(path, node)]
    return [x for k, v in node.items() for x in _findings(v, f"{path}.{k}")]


def _overridden_shaft() -> dict:
    """A drive whose given shaft (journal 20 mm at 4 kW, 300 rpm) fails its checks: findings
    with the brief's field and the design's advice (as tests/test_shaft_design.py)."""
    return {"machine": "drive", "report": {"title": "t", "student": "s"},
            "load": {"output_speed_rpm": 300, "power_kW": 4.0},
            "drive": {"stages": [{"type": "coupling"}, {"type": "spur", "z1": 24}],
                      "motor": {"speed_tolerance_pct": 5},
                      "shafts": [{"shaft": 2, "journal_mm": 20, "seat_mm": 22}]}}


def _undercut_press() -> dict:
    """The press's gear pair with a 16-tooth standard pinion: below z_min = 17 (α = 20°,
    ha* = 1), x_min = ha*(17 − 16)/17 = 0.059 > 0: undercut."""
    data = read_brief_data(DESIGNS / "press.yaml")
    data["gear_pair"]["z1"], data["gear_pair"]["x1"], data["gear_pair"]["x2"] = 16, 0.0, 0.0
    return data


def _undercut_drive() -> dict:
    data = read_brief_data(DESIGNS / "furnace_drive.yaml")
    data["drive"]["stages"][2]["z1"] = 12        # the open spur stage's pinion: undercut
    return data


@pytest.mark.parametrize("make,codes", [
    (_undercut_press, {"undercut"}),
    (_undercut_drive, {"undercut", "strength"}),
    (_overridden_shaft, {"strength"}),
])
def test_results_json_holds_codes_and_numbers_in_its_findings(make, codes):
    results, doc = _run(make())
    found = _findings(doc)
    assert {e["code"] for _, e in found} >= codes
    shown = [w for v in results.values() for w in getattr(v, "warnings", None) or ()]
    for path, entry in found:
        stored = {k: v for k, v in entry.items() if k != "text"}
        assert not CJK.search(json.dumps(stored, ensure_ascii=False)), (path, stored)
        assert not CJK.search(entry["text"])
        f = Finding(**stored)
        assert f.text("en") == entry["text"] and CJK.search(f.text("zh"))
        assert any(f.text("zh") == w.text("zh") for w in shown)


def test_a_failed_self_check_names_its_shaft_by_message():
    from mechdesign.stages.cam import SelfCheck, failed_findings
    from mechdesign.stages.drive import DRIVE_CHECK_NAMES

    shaft = i18n.catalogue("zh")[(None, "shaft {name}")]
    detail = {"shaft": 2}
    (f,) = failed_findings([SelfCheck("reactions", 1e-3, 1e-9, detail=detail)], DRIVE_CHECK_NAMES)
    assert f.code == "self_check" and not CJK.search(json.dumps(f.args, ensure_ascii=False))
    assert f" ({shaft.format(name=2)}) = 0.001" in f.text("zh")
    assert f.text("en").startswith("self-check failed: bearing reactions") and "(shaft 2) = 0.001" in f.text("en")


def test_old_results_with_finding_texts_still_compare():
    """tools/compare_results.py: a finding saved as its English string, or as {code, zh, en,
    field}, compares with the new finding's text and its rendering through zh.po."""
    import importlib.util

    root = Path(__file__).parents[1]
    spec = importlib.util.spec_from_file_location("compare_results", root / "tools" / "compare_results.py")
    cr = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(cr)
    plain = json.loads(dumps(_finding()))
    old = {"machine": "x", "gear": {"warnings": [_expected("en")]},
           "flywheel": {"warnings": [{"code": "undercut", "zh": _expected("zh"), "en": _expected("en"),
                                      "field": "drive.stages[1].z1"}]}}
    new = {"machine": "x", "gear": {"warnings": [plain]}, "flywheel": {"warnings": [plain]}}
    assert cr.compare(old, new) == []
    changed = json.loads(json.dumps(old))
    changed["flywheel"]["warnings"][0]["zh"] += "。"
    assert cr.compare(changed, new)
    changed = json.loads(json.dumps(old))
    changed["gear"]["warnings"][0] = "other"
    assert cr.compare(changed, new)


def test_a_missed_timing_requirement_names_it_by_codes():
    """The lock-beam's cycle finding: a requirement the brief does not word is "a before b"
    with the catalogue's word (no text stored); one the brief words stays the user's text."""
    from mechdesign.core import cycle as cy
    from mechdesign.machines.lockbeam.stages import _requirement

    plain = cy.Constraint("before", ("pin", "rise"), ("bend", "move"), 0.1)
    f = finding("cycle", "{req}", req=_requirement(plain))
    assert not CJK.search(json.dumps(f.args, ensure_ascii=False))
    assert f.text("en") == "pin.rise before bend.move"
    word = i18n.catalogue("zh")[("timing requirement", "before")]
    assert f.text("zh") == f"pin.rise {word} bend.move"
    worded = cy.Constraint("before", ("pin", "rise"), ("bend", "move"), 0.1, "销先升", "pin first")
    g = finding("cycle", "{req}", req=_requirement(worded))
    assert (g.text("zh"), g.text("en")) == ("销先升", "pin first")


def test_old_shaft_advice_compares_with_the_new_codes():
    """tools/compare_results.py: a shaft's advice saved as [check name, field, zh, en] (before
    session 31) compares with the new {check, field, fix: {msgid, args}}, whose texts are made
    from the catalogue; another field or fix text is a difference."""
    import importlib.util

    root = Path(__file__).parents[1]
    spec = importlib.util.spec_from_file_location("compare_results", root / "tools" / "compare_results.py")
    cr = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(cr)
    _, new = _run(_overridden_shaft())
    shafts = new["drive"]["shaft_designs"]
    given = next(s for s in shafts if s["advice"])
    zh = i18n.catalogue("zh")
    # an old document with the advice alone (compare reads the reference's paths)
    old = {"machine": "drive", "drive": {"shaft_designs": [{} for _ in shafts]}}
    old_shaft = old["drive"]["shaft_designs"][shafts.index(given)]
    names = {c["key"]: c["name"] for c in given["checks"]}      # an English msgid, no fields here

    def texts(fix):               # the fix by hand: msgid (or a list of them) and its numbers
        if fix["msgid"] == "{fix}":
            parts = fix["args"]["fix"]["items"]
            return ("；".join(zh[(None, p["msgid"])].format(**p["args"]) for p in parts),
                    "; ".join(p["msgid"].format(**p["args"]) for p in parts))
        args = fix.get("args", {})
        return zh[(None, fix["msgid"])].format(**args), fix["msgid"].format(**args)

    old_shaft["advice"] = [[names[a["check"]], a["field"], *texts(a["fix"])] for a in given["advice"]]
    assert all("drive.shafts" not in x for a in old_shaft["advice"] for x in a[2:])
    assert cr.compare(old, new, expected=False) == []
    old_shaft["advice"][0][1] = "drive.shafts[0].seat_mm" if old_shaft["advice"][0][1] != \
        "drive.shafts[0].seat_mm" else "drive.shafts[0].journal_mm"
    assert cr.compare(old, new, expected=False)
