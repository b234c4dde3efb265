"""Deliverables from one run, as a user gets them: every example brief with a linkage, cam
or gear stage gets its sheets (DXF re-opens with the named layers), the report embeds
their previews, --format docx writes a Word file with the Chinese text, tables and
equations, --format gif an animation."""
from __future__ import annotations

import re
import zipfile
from pathlib import Path

import pytest
from typer.testing import CliRunner

from mechdesign.cli import app
from test_sheet_dxf import check_dxf_tables

ezdxf = pytest.importorskip("ezdxf")

ROOT = Path(__file__).resolve().parents[1]
LAYERS = {"OUTLINE", "CENTER", "CONSTRUCTION", "DIMENSIONS", "TEXT", "FRAME"}

# brief → the sheets it must give (by the stages it has)
EXPECTED = {
    # kinematic diagram (机构运动简图), transmission schematic, cycle diagram (A3) first
    "shaper": ["kinematic_A3", "transmission_A3", "analysis_A1", "cam_A2", "gear_A2"],
    "cam_7_3": ["kinematic_A3", "cam_A2"],
    "lockbeam_cam": ["kinematic_A3", "cam_A2"],
    # the feed linkage's analysis sheet, a cam sheet for each of its two cams (the positioning
    # cam, the bending cam: issue 19 point 8); the brief's motion cycle diagram
    "lockbeam": ["kinematic_A3", "cycle_A3", "analysis_A1", "cam_A2", "bending_cam_A2"],
    # the optimum four-bar and the slider-crank; the four-bar's analysis sheet (it runs the
    # shared linkage stages)
    "crank_rocker": ["kinematic_A3", "analysis_A1"],
    "cam_7_1": ["kinematic_A3"],           # the eccentric disc with each follower
    "furnace_drive": ["transmission_A3"],  # drive only
    "furnace_pusher": ["kinematic_A3", "transmission_A3", "analysis_A1"],  # the six-bar's analysis sheet
    "linkage_sixbar": ["kinematic_A3", "analysis_A1"],  # generic linkage: its analysis sheet
    "textbook_guide_bar": ["kinematic_A3", "analysis_A1"],  # a textbook exercise as a linkage brief
    "die_cutter": ["kinematic_A3", "transmission_A3", "cycle_A3", "analysis_A1", "cam_A2"],
    "slotter": ["kinematic_A3", "transmission_A3", "analysis_A1", "cam_A2", "gear_A2"],
    "press": ["kinematic_A3", "analysis_A1", "cam_A2", "gear_A2"],    # the press's six-bar, oil-pump cam, gear pair
    "shaper_lengths": ["kinematic_A3", "analysis_A1"],  # link-length form: no cam, no gear pair
}


def _run(args):
    result = CliRunner().invoke(app, args)
    return result


def test_every_example_brief_is_covered():
    briefs = {p.stem for p in (ROOT / "designs").glob("*.yaml")}
    assert briefs == set(EXPECTED)


@pytest.mark.e2e
@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_sheets_for_each_example_brief(name, tmp_path):
    out = tmp_path / name
    result = _run(["run", str(ROOT / "designs" / f"{name}.yaml"), "-o", str(out), "-f", "md,dxf"])
    assert result.exit_code == 0, result.output
    got = sorted(p.stem for p in (out / "sheets").glob("*.dxf")) if (out / "sheets").exists() else []
    assert got == sorted(EXPECTED[name])
    md = (out / "report.md").read_text(encoding="utf-8")
    numbered = {}
    for stem in EXPECTED[name]:
        doc = ezdxf.readfile(out / "sheets" / f"{stem}.dxf")
        # the title block: "第 i 张  共 n 张" (n: the sheets written) and the drawing number
        # PREFIX-0i (MD-03, JY-03: the brief's sheets.drawing_number)
        texts = [t.dxf.text for t in doc.modelspace().query("TEXT")]
        marks = [m for t in texts if (m := re.fullmatch(r"第\s*(\d+)\s*张\s*共\s*(\d+)\s*张", t))]
        assert len(marks) == 1, (stem, texts)
        i, n = int(marks[0].group(1)), int(marks[0].group(2))
        assert n == len(EXPECTED[name]), (stem, i, n)
        assert any(re.fullmatch(rf"[A-Z]+-{i:02d}", t) for t in texts), (stem, i, texts)
        numbered[i] = stem
        layers = {layer.dxf.name for layer in doc.layers}
        assert LAYERS <= layers
        used = {e.dxf.layer for e in doc.modelspace()}
        # the diagrams (kinematic, transmission, cycle) carry no dimensions
        need = (LAYERS if stem.split("_")[0] in ("analysis", "cam", "gear") or "_cam_" in stem
                else {"OUTLINE", "TEXT", "FRAME"})
        assert need <= used, (stem, need - used)
        assert doc.units == 4                                     # millimetres
        check_dxf_tables(doc)          # extents ⊇ every entity, only the styles used
        kind = stem.rsplit("_", 1)[0]                           # "bending_cam_A2": bending_cam
        preview = out / "figures" / f"sheet_{kind}.png"
        assert preview.exists() and f"figures/sheet_{kind}.png" in md
    assert sorted(numbered) == list(range(1, len(EXPECTED[name]) + 1))
    # the drawings table lists each sheet once, by its title and size (a 说明书 names the
    # drawings, not their files: issue 19 review 34); its rows stand above "{#tbl:sheets}"
    if EXPECTED[name]:
        table = md.partition("{#tbl:sheets}")[0].rsplit("\n\n", 2)[-2]
        sizes = sorted(re.findall(r"^\|[^|\n]+\|\s*(A\d)\s*\|", table, flags=re.M))
        assert sizes == sorted(stem.rsplit("_", 1)[1] for stem in EXPECTED[name]), table
        assert ".dxf" not in table and ".pdf" not in table
    if not EXPECTED[name]:
        assert "设计图纸" not in md and "Drawing sheets" not in md


@pytest.mark.e2e
def test_shaper_all_formats(tmp_path):
    """The issue's command: report, three sheets (PDF + DXF), Word, animation."""
    out = tmp_path / "shaper"
    result = _run(["run", str(ROOT / "designs" / "shaper.yaml"), "-o", str(out),
                   "-f", "md,pdf,docx,dxf,gif"])
    assert result.exit_code == 0, result.output
    for stem in EXPECTED["shaper"]:
        assert (out / "sheets" / f"{stem}.dxf").exists()
        pdf = (out / "sheets" / f"{stem}.pdf").read_bytes()
        assert pdf.startswith(b"%PDF")
        # vector drawing at true paper size (A1 841 × 594 mm, A2 594 × 420 mm)
        w, h = {"A1": (841, 594), "A2": (594, 420), "A3": (420, 297)}[stem.rsplit("_", 1)[1]]
        box = re.search(rb"/MediaBox *\[ *0 0 ([0-9.]+) ([0-9.]+)", pdf)
        assert abs(float(box.group(1)) - w / 25.4 * 72) < 0.5
        assert abs(float(box.group(2)) - h / 25.4 * 72) < 0.5
        assert b"/Subtype /Image" not in pdf
    # Word: the same report with its Chinese text, tables and equations
    with zipfile.ZipFile(out / "report.docx") as z:
        xml = z.read("word/document.xml").decode("utf-8")
        media = [n for n in z.namelist() if n.startswith("word/media/")]
    assert "导杆机构设计" in xml and "飞轮设计" in xml
    assert xml.count("<w:tbl>") + xml.count("<w:tbl ") >= 10
    assert xml.count("<m:oMath") >= 20
    # the text runs with the fields' results (not their instructions)
    plain = re.sub(r"<w:instrText[^>]*>.*?</w:instrText>", "", xml)
    plain = re.sub(r"\s+", " ", re.sub(r"<[^>]+>", "", plain))
    assert "图 1" in plain and "表 1" in plain and "(1)" in plain
    assert len(media) >= 8
    # the animation: one revolution, small
    from PIL import Image

    gif = out / "animation.gif"
    assert gif.stat().st_size < 1_000_000
    with Image.open(gif) as im:
        assert im.is_animated and im.n_frames >= 36
    # nothing left from the staging
    assert not [p for p in out.iterdir() if p.name.startswith(".")]


@pytest.mark.e2e
def test_gif_for_a_machine_without_linkage_warns(tmp_path):
    out = tmp_path / "cam"
    result = _run(["run", str(ROOT / "designs" / "cam_7_3.yaml"), "-o", str(out), "-f", "md,gif"])
    assert result.exit_code == 0, result.output
    assert "no linkage to animate" in result.output
    assert not (out / "animation.gif").exists()


def test_polygon_positions_from_the_brief_are_validated(tmp_path):
    text = (ROOT / "designs" / "shaper.yaml").read_text(encoding="utf-8")
    bad = tmp_path / "bad.yaml"
    bad.write_text(text.replace("polygon_positions: [4, 10]", "polygon_positions: [4, 13]"),
                   encoding="utf-8")
    result = _run(["run", str(bad), "-o", str(tmp_path / "o"), "-f", "md"])
    assert result.exit_code == 2
    assert "sheets.polygon_positions" in result.output and "1 … 12" in result.output
    assert "Traceback" not in result.output
