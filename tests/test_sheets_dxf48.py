"""The sheets chapter describes the DXF files (their layers) only where the run wrote them
(page review 47: every report described 'the DXF opens in AutoCAD/CAXA with layers …'
while the default run, md and pdf, writes no DXF)."""
from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from mechdesign.cli import app

ROOT = Path(__file__).resolve().parents[1]
LAYERS = {"en": "layers OUTLINE", "zh": "粗实线（OUTLINE）"}
ASKED = {"en": "a run asked for the DXF format", "zh": "按 DXF 格式输出时"}


@pytest.mark.parametrize("lang", ["en", "zh"])
def test_the_dxf_layers_are_described_where_the_files_are(tmp_path, lang):
    texts = {}
    for formats in ("md", "md,dxf"):
        out = tmp_path / formats.replace(",", "-")
        r = CliRunner().invoke(app, ["run", str(ROOT / "designs" / "cam_7_1.yaml"), "--lang", lang,
                                     "--format", formats, "--out", str(out)])
        assert r.exit_code == 0, r.output
        texts[formats] = ((out / "report.md").read_text(encoding="utf-8"),
                          sorted(p.name for p in out.rglob("*.dxf")))
    md, files = texts["md"]
    assert not files and LAYERS[lang] not in md and ASKED[lang] in md
    md, files = texts["md,dxf"]
    assert files and LAYERS[lang] in md and ASKED[lang] not in md
