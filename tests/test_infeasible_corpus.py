"""A corpus of infeasible, absurd and careless briefs derived from the examples (issue 21,
point 7): each class the issue lists, run through `mechdesign run` as a user would.

Every brief must end with exit 0 (a valid design, perhaps with named warnings) or exit 2 (a
brief or design problem, at its field) — never exit 1 or a traceback — and its output must
not contain the texts the issue found wrong (pydantic's wording, a section's contents as the
value, advice in the wrong direction or by a round-off amount, a self-check blamed on the
program for what the design does).
"""
from __future__ import annotations

import copy
import re
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.cli import app

pytestmark = pytest.mark.e2e     # every case runs `mechdesign run` to a report

ROOT = Path(__file__).resolve().parents[1]
runner = CliRunner()
DELETE = object()

NEVER = ("Traceback", "pydantic", "errors.pydantic.dev", "(top level)", "{'", "e-14 mm",
         "e-15 mm", "e-13 mm", "cannot be trusted", "exceeds its maximum", "below −", "below -")


def _edit(data: dict, path: str, value) -> None:
    keys = [int(k) if k.isdigit() else k for k in path.split(".")]
    node = data
    for k in keys[:-1]:
        node = node[k]
    if value is DELETE:
        del node[keys[-1]]
    else:
        node[keys[-1]] = value


def _spur_stage(data) -> int:
    return next(i for i, s in enumerate(data["drive"]["stages"]) if s["type"] == "spur")


# (id, example, edits, exit code, texts that must appear)
CASES = [
    # duplicate names: the solver's groups were keyed by name (LinAlgError, exit 1)
    ("duplicate-group-names", "linkage_sixbar", {"linkage.groups.4.name": "摇杆 O4B"}, 2,
     ["linkage.groups.4.name", "already used by groups[0]"]),
    # a valid cam with a 2000 mm stroke crashed the cam sheet's layout
    ("huge-stroke-cam", "cam_7_3", {"cam.follower.stroke_h_mm": 2000, "cam.base_radius_mm": "auto"},
     0, []),
    # a 30 mm rise over 0.001° reported a pressure angle of 13.9°
    ("tiny-rise", "cam_7_3", {"cam.programme.0.angle_deg": 0.001, "cam.programme.3.angle_deg": 179.999},
     0, ["90.00°", "larger cam angle"]),
    # a roller larger than the base circle exited 0 advising a negative roller
    ("roller-above-base-circle", "cam_7_3", {"cam.follower.roller_radius_mm": 60}, 2,
     ["cam.follower.roller_radius_mm", "cannot be made"]),
    # a drive spur stage with a pointed tooth (s_a ≤ 0) passed silently
    ("pointed-drive-tooth", "furnace_drive", {"drive.stages.{spur}.z1": 14, "drive.stages.{spur}.x1": 1.2},
     2, ["drive.stages[{spur}].x1", "cannot be cut"]),
    ("negative-dedendum", "furnace_drive", {"drive.stages.{spur}.x1": 1.4}, 0,
     # the fix in words, the brief field after the text on the terminal (not in the report)
     ["negative dedendum", "pointed tooth", "reduce its shift", "[drive.stages[{spur}].x1]"]),
    # a chain stage with z1 = 1 was accepted
    ("chain-one-tooth", "furnace_drive", {"drive.stages.{spur}": {"type": "chain", "z1": 1, "z2": 40}},
     2, ["drive.stages.{spur}.z1", "at least 9 teeth"]),
    # gear_pair.z1: 1000 leaked pydantic's raw message and URL without the field
    ("gear-z1-1000", "shaper", {"gear_pair.z1": 1000}, 2, ["gear_pair.z2", "at least z1 = 1000"]),
    # a rim diameter of 0.001 mm gave a 4.9e7 m rim
    ("rim-0.001mm", "shaper", {"flywheel.rim_diameter_mm": 0.001}, 2, ["flywheel.rim_diameter_mm"]),
    # H = 100 with a 650 mm frame drew the crank circle off the guide bar and reported numbers
    ("stroke-100-frame-650", "shaper", {"linkage.stroke_H_mm": 100}, 2,
     ["linkage.stroke_H_mm", "crank pin's reach"]),
    # 1e-9 rpm gave J_F = 3.4e23 kg·m² as a result
    ("speed-1e-9", "shaper", {"linkage.crank_speed_n2_rpm": 1e-9}, 2, ["crank speed"]),
    # since session 44 the sixbar sizes a rim (linkage.flywheel.rim_diameter_mm): as the press's
    ("speed-1e-9-linkage", "linkage_sixbar", {"linkage.crank.speed_rpm": 1e-9}, 2,
     ["linkage.flywheel.rim_diameter_mm", "1e-09 rpm"]),
    ("speed-1e-9-press", "press", {"linkage.crank_speed_n1_rpm": 1e-9}, 2,
     ["flywheel.rim_diameter_mm", "crank speed n = 1e-09 rpm"]),
    # the crank turning against the quick return (K < 1) was reported silently as K = 0.5
    ("crank-reversed", "linkage_sixbar", {"linkage.crank.rotation": "ccw"}, 0,
     ["linkage.crank.rotation"]),
    # a four-bar exactly at the Grashof limit: no 1e-14 mm advice
    ("change-point", "linkage_sixbar", {"linkage.groups.0.lengths_mm": [300, 400]}, None, []),
    # cross-field problems at the field, in the brief's language (zh)
    ("zh-cross-field", "cam_7_3", {"report.language": "zh", "cam.follower.roller_radius_mm": 60}, 2,
     ["cam.follower.roller_radius_mm", "滚子半径"]),
]


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_corpus_brief_is_handled(tmp_path, case):
    name, example, edits, code, texts = case
    data = yaml.safe_load((ROOT / "designs" / f"{example}.yaml").read_text(encoding="utf-8"))
    data.pop("groups", None)
    data = copy.deepcopy(data)
    spur = _spur_stage(data) if any("{spur}" in k for k in edits) else None
    for path, value in edits.items():
        _edit(data, path.replace("{spur}", str(spur)), value)
    brief = tmp_path / f"{name}.yaml"
    brief.write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")
    lang = [] if data["report"].get("language") == "zh" and name.startswith("zh") else ["--lang", "en"]
    result = runner.invoke(app, ["run", str(brief), "-o", str(tmp_path / "out"), "-f", "md,dxf",
                                 *lang])
    out = result.output
    assert result.exit_code in (0, 2), out
    if code is not None:
        assert result.exit_code == code, out
    for bad in NEVER:
        assert bad not in out, (bad, out)
    for text in texts:
        assert text.replace("{spur}", str(spur)) in out, (text, out)
    if result.exit_code == 2:     # nothing written
        assert not (tmp_path / "out" / "report.md").exists()
    # no advice by a round-off amount: a printed change is at least 0.001 mm
    for amount in re.findall(r"by (\d[\d.e+-]*) mm", out):
        assert float(amount) >= 1e-3, (amount, out)


def test_the_corpus_covers_the_issues_classes():
    """Each class of issue 21's list has a case (names above)."""
    names = {c[0] for c in CASES}
    assert {"duplicate-group-names", "huge-stroke-cam", "tiny-rise", "roller-above-base-circle",
            "pointed-drive-tooth", "chain-one-tooth", "gear-z1-1000", "rim-0.001mm",
            "stroke-100-frame-650", "speed-1e-9"} <= names
