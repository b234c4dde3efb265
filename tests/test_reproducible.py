"""The same brief gives the same bytes: results.json, report.md, report.pdf, report.docx,
the figures, the drawing sheets (PDF and DXF), also for a data group, whatever process
(and hash seed) renders it and whenever. Dates written into the files come from the
brief's date (or SOURCE_DATE_EPOCH), never from the clock."""
from __future__ import annotations

import importlib.util
import os
import re
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
import yaml

from mechdesign.render.pdf import FALLBACK_TIMESTAMP, source_timestamp

ROOT = Path(__file__).resolve().parents[1]
needs_pdf = pytest.mark.skipif(importlib.util.find_spec("pypandoc") is None
                               or importlib.util.find_spec("typst") is None,
                               reason="pypandoc and typst are needed")
# A day that is not today, so that a date from the clock cannot pass for the brief's.
DATE = "2025-06-30"
EPOCH_DATE = 1751241600            # 2025-06-30T00:00:00Z


def test_source_timestamp(monkeypatch):
    monkeypatch.delenv("SOURCE_DATE_EPOCH", raising=False)
    assert source_timestamp("2025-06-30") == EPOCH_DATE
    assert source_timestamp("2025.6.30") == EPOCH_DATE
    assert source_timestamp("2025年6月30日") == EPOCH_DATE
    assert source_timestamp("2025-06-30T13:45:00") == EPOCH_DATE
    for text in ("", None, "next Monday", "2025-02-30", "1970-01-01"):
        assert source_timestamp(text) == FALLBACK_TIMESTAMP       # 1980-01-01 (ZIP minimum)
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    assert source_timestamp("2025-06-30") == 1700000000
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "soon")
    assert source_timestamp("2025-06-30") == EPOCH_DATE


def _env(seed: str) -> dict:
    env = {k: v for k, v in os.environ.items() if k != "SOURCE_DATE_EPOCH"}
    env["PYTHONHASHSEED"] = seed
    return env


def _files(folder: Path) -> dict[str, bytes]:
    return {p.relative_to(folder).as_posix(): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file()}


@pytest.fixture(scope="module")
def two_runs(tmp_path_factory):
    """designs/cam_7_1.yaml with a groups table and another date, run for a group in two
    processes with different hash seeds, a second apart."""
    tmp = tmp_path_factory.mktemp("repro")
    data = yaml.safe_load((ROOT / "designs" / "cam_7_1.yaml").read_text(encoding="utf-8"))
    data["report"]["date"] = DATE
    data["groups"] = {"default": "A", "variants": {"A": {}, "B *2*": {"disc.eccentricity_mm": 18}}}
    brief = tmp / "brief.yaml"
    brief.write_text(yaml.safe_dump(data, allow_unicode=True, sort_keys=False), encoding="utf-8")
    outs = []
    for seed in ("1", "2"):
        out = tmp / f"out{seed}"
        proc = subprocess.run([sys.executable, "-m", "mechdesign", "run", str(brief), "-o", str(out),
                               "--group", "B *2*", "-f", "md,pdf,docx"],
                              env=_env(seed), capture_output=True, text=True, timeout=300)
        assert proc.returncode == 0, proc.stdout + proc.stderr
        outs.append(out)
    return outs


@pytest.mark.e2e
@needs_pdf
def test_two_runs_give_identical_bytes(two_runs):
    a, b = (_files(out) for out in two_runs)
    assert {"results.json", "report.md", "report.pdf", "report.docx"} <= set(a)
    assert any(name.startswith("figures/") and name.endswith(".png") for name in a)
    assert sorted(a) == sorted(b)
    differ = [name for name in a if a[name] != b[name]]
    assert differ == []


@pytest.mark.e2e
@needs_pdf
def test_dates_in_the_files_are_the_briefs(two_runs):
    out = two_runs[0]
    pdf = (out / "report.pdf").read_bytes()
    dates = set(re.findall(rb"/(?:CreationDate|ModDate)\s*\(D:(\d{8})", pdf))
    assert dates == {b"20250630"}
    with zipfile.ZipFile(out / "report.docx") as docx:
        core = docx.read("docProps/core.xml").decode("utf-8")
        stamps = {info.date_time[:3] for info in docx.infolist()}
    assert re.findall(r"<dcterms:(?:created|modified)[^>]*>([^<]*)<", core) == \
        ["2025-06-30T00:00:00Z"] * 2
    # ZIP entries: the brief's date (entries pandoc copies from reference.docx keep 1980)
    assert (2025, 6, 30) in stamps and stamps <= {(2025, 6, 30), (1980, 1, 1)}
    assert '"data_group": "B *2*"' in (out / "results.json").read_text(encoding="utf-8")


_SHEET_SCRIPT = r"""
import sys
from pathlib import Path
from mechdesign.render.sheet import Sheet, TitleInfo, frame
from mechdesign.render.sheet_dxf import write_dxf
from mechdesign.render.sheet_typst import write_sheet

out = Path(sys.argv[1])
out.mkdir()
s = Sheet("A4")
frame(s, TitleInfo(drawing="测试图", project="- T $x$ 100%%d ^J", student="张三",
                   date="2025-06-30", number="MD-01", lang="zh"))
s.circle(80 + 100j, 20)
s.arc(80 + 100j, 30, 0.0, 1.0)
s.fill([60 + 60j, 70 + 60j, 65 + 70j])
s.line(40 + 40j, 120 + 40j)
s.dimension(40 + 40j, 120 + 40j, 8.0, 80.0)
s.dimension(80 + 100j, 100 + 100j, 0.0, 20.0, kind="radius")
s.text(40 + 150j, "R $a$ ^ %")
write_sheet(s, pdf=out / "s.pdf", png=out / "s.png", png_width_px=400)
write_dxf(s, out / "s.dxf", "- T $x$")
"""


@pytest.mark.e2e
def test_drawing_sheets_are_reproducible(tmp_path):
    outs = []
    for seed in ("1", "2"):
        out = tmp_path / f"sheet{seed}"
        proc = subprocess.run([sys.executable, "-c", _SHEET_SCRIPT, str(out)], env=_env(seed),
                              capture_output=True, text=True, timeout=120)
        assert proc.returncode == 0, proc.stderr
        outs.append(_files(out))
    assert sorted(outs[0]) == ["s.dxf", "s.pdf", "s.png"]
    assert [n for n in outs[0] if outs[0][n] != outs[1][n]] == []
    assert re.search(rb"/CreationDate ?\(D:20250630", outs[0]["s.pdf"])
