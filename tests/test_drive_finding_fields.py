"""Drive findings name no brief field in the report's prose (issue 19 point 4, issue 22
point 3): a finding of a drive stage or shaft says the limit and what to change in words;
the brief field it is about is the finding's ``field`` (``drive.stages[1].x1``), which
the terminal prints after the text (``… [drive.stages[1].x1]``), never the report.

The brief's field names are read from its models (pydantic), not listed here; a brief path
is ``section.field`` or ``list[i].field`` whose last name is one of them."""
from __future__ import annotations

import re
import typing

import pytest
import yaml

from mechdesign.brief import drive as brief_drive
from mechdesign.brief.loader import read_brief_data
from mechdesign.machines.drive.brief import DriveBrief, drive_brief_to_si
from mechdesign.stages.drive import design_drive
from tests.test_finding_codes import DESIGNS

# a dotted path (the brief's regex ``\b[a-z_]+(\[\d+\])?\.[a-z_0-9]+\b``, taken whole)
PATH = re.compile(r"\b[a-z_]+(?:\[\d+\])?(?:\.[a-z_][a-z_0-9]*(?:\[\d+\])?)+")


def _field_names(model, seen=None) -> set[str]:
    """Every field name of a brief model and the models it holds."""
    seen = set() if seen is None else seen
    if model in seen:
        return set()
    seen.add(model)
    out = set()
    for name, info in model.model_fields.items():
        out.add(name)
        stack = [info.annotation]
        while stack:
            t = stack.pop()
            if isinstance(t, type) and hasattr(t, "model_fields"):
                out |= _field_names(t, seen)
            stack.extend(typing.get_args(t))
    return out


FIELDS = _field_names(DriveBrief) | {"x1", "x2", "z1", "z2", "d1_mm", "journal_mm", "seat_mm"}


def brief_paths(text: str) -> list[str]:
    """The brief field paths written in ``text`` (``drive.stages[2].x1``, ``gear_pair.x1``)."""
    return [m.group(0) for m in PATH.finditer(text)
            if re.sub(r"\[\d+\]$", "", m.group(0).rsplit(".", 1)[1]) in FIELDS]


def test_the_scan_finds_the_old_texts_paths():
    old = ("stage 2 (spur gear): the pinion (z1 = 12) is undercut: z1 < z_min = 17.1 and x1 = 0 < "
           "x_min = 0.298; set drive.stages[1].x1 ≥ 0.298 (a positive shift) or drive.stages[1].z1 ≥ 18.")
    assert brief_paths(old) == ["drive.stages[1].x1", "drive.stages[1].z1"]
    assert brief_paths("增大 drive.stages[0].d1_mm") == ["drive.stages[0].d1_mm"]
    assert not brief_paths("z_v = z/cos³β = 14.23, s_a = 0.625 mm < 0.25 m, shaft Ⅱ, 1.5 d")


_POWER = {"output_speed_rpm": 300, "power_kW": 4.0}
# (stages, load, drive extras, the stage field or shaft field the finding is about)
CASES = {
    "spur undercut": ([{"type": "coupling"}, {"type": "spur", "z1": 12}], _POWER, {},
                      "drive.stages[1].x1"),
    "helical undercut": ([{"type": "coupling"}, {"type": "helical", "z1": 13}], _POWER, {},
                         "drive.stages[1].z1"),
    "pointed tooth": ([{"type": "coupling"}, {"type": "spur", "z1": 20, "x1": 1.0}], _POWER, {},
                      "drive.stages[1].x1"),
    "small pulley": ([{"type": "belt", "d1_mm": 60}, {"type": "spur", "z1": 24}], _POWER, {},
                     "drive.stages[0].d1_mm"),
    "wrap angle": ([{"type": "belt", "center_distance_mm": 100, "ratio": 4}, {"type": "spur", "z1": 24}],
                   _POWER, {}, "drive.stages[0].center_distance_mm"),
    "sprocket teeth": ([{"type": "coupling"}, {"type": "spur", "z1": 24}, {"type": "chain", "z1": 11}],
                       {"output_speed_rpm": 50, "power_kW": 2.0}, {}, "drive.stages[2].z1"),
    "given shaft": ([{"type": "coupling"}, {"type": "spur", "z1": 24}], _POWER,
                    {"shafts": [{"shaft": 2, "journal_mm": 20, "seat_mm": 22}]}, "drive.shafts[0].journal_mm"),
    # a given bearing far too small for the load: the free seat grew by 5 mm a step without
    # bound (to 205 mm, beyond the flat-key table: "internal error … ValueError"); it stops
    # at the journal's limit and the finding names the bearing
    "given small bearing": ([{"type": "coupling"}, {"type": "spur", "z1": 24}],
                            {"output_speed_rpm": 300, "power_kW": 15.0},
                            {"shafts": [{"shaft": 2, "bearing": "6204"}]}, "drive.shafts[0].bearing"),
}


def _design(stages, load, extra):
    data = {"machine": "drive", "report": {"title": "t", "student": "s"}, "load": load,
            "drive": {"stages": stages, "motor": {"speed_tolerance_pct": 5}, **extra}}
    p = drive_brief_to_si(DriveBrief.model_validate(data))
    return design_drive(p.drive, p.load.power, p.load.output_speed_rpm, p.load.how)


def _stage_fields(path: str) -> set[str]:
    """The fields the brief allows at a stage or shaft path (by its type, or a shaft's)."""
    return set().union(*brief_drive._FIELDS_BY_TYPE.values()) if ".stages[" in path else \
        set(brief_drive.ShaftOverride.model_fields)


@pytest.mark.parametrize("case", list(CASES))
def test_drive_findings_say_the_fix_in_words_and_hold_the_field(case):
    stages, load, extra, field = CASES[case]
    found = _design(stages, load, extra).warnings
    assert any(w.field == field for w in found), [(w.code, w.field) for w in found]
    for w in found:
        for lang in ("en", "zh", "zh_TW"):
            assert not brief_paths(w.text(lang)), (case, lang, w.text(lang))
        if w.field.count(".") == 2:          # drive.stages[i].name: a field of that stage
            assert w.field.rsplit(".", 1)[1] in _stage_fields(w.field), w.field
    # a stage of the type that has no shifts is not told to set them
    if case == "helical undercut":
        assert all(not w.field.endswith((".x1", ".x2")) for w in found)


def test_the_report_names_no_field_and_the_terminal_does(tmp_path):
    """An undercut open spur stage of the furnace drive: the report (zh and en) lists the
    findings without the brief path; the run's warnings (the terminal) end with it."""
    from mechdesign.runner import run_one

    data = read_brief_data(DESIGNS / "furnace_drive.yaml")
    data.pop("groups", None)
    data["drive"]["stages"][2]["z1"] = 12
    brief = tmp_path / "b.yaml"
    brief.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    for lang in ("zh", "en"):
        out = run_one(brief, out_dir=tmp_path / lang, lang=lang, formats=("md",))
        assert out.status == "ok", out.message
        assert any(w.endswith("[drive.stages[2].x1]") for w in out.warnings), out.warnings
        md = (tmp_path / lang / "report.md").read_text(encoding="utf-8")
        md = re.sub(r"^```.*?^```", "", md, flags=re.S | re.M)      # the program listing
        assert "根切" in md if lang == "zh" else "undercut" in md
        assert not brief_paths(md), brief_paths(md)[:5]


def test_the_flywheel_rim_finding_names_its_field_outside_the_text():
    """The thick-rim finding (H > D/2 at a rim diameter the brief gives) says "the rim's mean
    diameter D" in words; the brief field is the finding's."""
    from mechdesign.core.flywheel import RimFlywheel
    from mechdesign.stages.flywheel import rim_findings

    rim = RimFlywheel(diameter=0.300, width=0.100, height=0.200, rim_mass=50.0, rim_speed=10.0)
    (f,) = [w for w in rim_findings(rim, "flywheel.rim_diameter_mm") if w.code == "rim_proportion"]
    assert f.field == "flywheel.rim_diameter_mm"
    for lang in ("en", "zh"):
        assert "flywheel." not in f.text(lang) and not brief_paths(f.text(lang))
    assert "mean diameter D" in f.text("en") and "平均直径 D" in f.text("zh")
