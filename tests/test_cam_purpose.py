"""What a cam is for (issue 19, a complete hand-in): the cam chapter opens with the cam's
purpose as the brief's designer states it (``cam.purpose_zh`` / ``purpose_en``), in the
report's language; a brief without it prints nothing in its place. The page review found the
press's oil-pump cam, the slotter's and shaper's feed cams and the stand-alone positioning
cam (lockbeam_cam) designed without a word on what they drive or when."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]

HEADING = {"zh": "# 凸轮机构设计", "en": "# Cam mechanism"}


def _first_paragraph_after(md: str, heading: str) -> str:
    at = md.index(heading + "\n")
    rest = md[at + len(heading):].lstrip("\n")
    # the Markdown as written, less its escapes (md_text escapes an apostrophe: \')
    return re.sub(r"\\(.)", r"\1", rest.split("\n\n", 1)[0])


def _brief_cam(name: str, key: str = "cam") -> dict:
    return yaml.safe_load((ROOT / "designs" / f"{name}.yaml").read_text(encoding="utf-8"))[key]


@pytest.mark.parametrize("name", ["press", "slotter", "shaper", "lockbeam", "lockbeam_cam"])
@pytest.mark.parametrize("lang", ["zh", "en"])
def test_the_cam_chapter_opens_with_the_briefs_purpose(handin_reports, name, lang):
    md, _doc = handin_reports(name, lang)
    first = _first_paragraph_after(md, HEADING[lang])
    given = _brief_cam(name)[f"purpose_{lang}"]
    if lang == "zh":
        assert first == f"**用途：**{given}。"
    else:
        assert first == f"**Purpose:** {given[0].upper()}{given[1:]}."
        # the English report prints the English text: no Chinese in it
        assert not re.search(r"[\u4e00-\u9fff]", first)


def test_the_die_cutters_gripper_cam_states_its_purpose(handin_reports):
    md, _doc = handin_reports("die_cutter", "en")
    first = _first_paragraph_after(md, HEADING["en"])
    assert "spring grippers" in first and first.startswith("**Purpose:** Opens")


def test_a_cam_without_a_stated_purpose_prints_none(handin_reports):
    md, _doc = handin_reports("cam_7_3", "zh")
    assert "用途" not in md
    first = _first_paragraph_after(md, HEADING["zh"])
    assert first.startswith("## ")


def test_one_language_given_is_shown_in_either_report():
    """A brief that gives the purpose in one language only: that text in both reports (the
    user's own words, as the title without title_en)."""
    from mechdesign.brief.cam import CamSection
    from mechdesign.render.cam_report import purpose_line

    data = _brief_cam("press")
    data.pop("purpose_en")
    section = CamSection.model_validate(data)
    zh = data["purpose_zh"]
    assert purpose_line(section, "zh") == f"**用途：**{zh}。"
    assert purpose_line(section, "en") == f"**Purpose:** {zh}。"
    data.pop("purpose_zh")
    assert purpose_line(CamSection.model_validate(data), "en") == ""


def test_an_overlong_purpose_names_its_field(tmp_path):
    from mechdesign.brief.loader import BriefError, load_brief

    text = (ROOT / "designs" / "press.yaml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^  purpose_en: .*$", "  purpose_en: '" + "x" * 500 + "'", text)
    path = tmp_path / "press.yaml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(BriefError) as err:
        load_brief(path)
    assert "cam.purpose_en" in str(err.value)
