"""The drive report states its task and the brief's data before it uses them (page review 47:
furnace_drive began with P_w = (F_w + F_r) H n_w / 60 = (500 + 100) × 0.220 × 20.00/60 and
defined none of F_w, F_r, H, n_w)."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from mechdesign.cli import app

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_drive_report_tabulates_the_data_its_first_formula_uses(tmp_path, lang):
    brief = yaml.safe_load((ROOT / "designs" / "furnace_drive.yaml").read_text(encoding="utf-8"))
    st = brief["load"]["stroke"]
    r = CliRunner().invoke(app, ["run", str(ROOT / "designs" / "furnace_drive.yaml"), "--lang", lang,
                                 "--format", "md", "--out", str(tmp_path / "r")])
    assert r.exit_code == 0, r.output
    md = (tmp_path / "r" / "report.md").read_text(encoding="utf-8")
    table = md[:md.index("{#tbl:data}")]
    rows = {m[1]: m[2] for m in re.finditer(r"^\| \$([^$]+)\$ \| [^|]+ \| ([^|]+) \|", table, re.M)}
    assert rows["F_w"].strip() == f"{st['working_force_N']:g}"
    assert rows["F_r"].strip() == f"{st['return_force_N']:g}"
    assert rows["H"].strip() == f"{st['stroke_mm']:g}"
    assert float(rows["n_w"]) == brief["load"]["output_speed_rpm"]
    life = brief["drive"]["service"]
    assert rows["L_h"].replace("\u202f", "").replace(" ", "").strip() == str(
        life["life_years"] * life["days_per_year"] * life["hours_per_day"])
    # the table stands before the first formula, which uses exactly these symbols
    first = md.index("$$")
    assert md.index("{#tbl:data}") < first
    assert re.search(r"P_w = \\frac\{\(F_w \+ F_r\) H n_w\}\{60\}", md[first:first + 200])
