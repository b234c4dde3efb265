"""The stages' words come from the catalogue (issue 22 point 3): stage titles, findings and
self-check names are English msgids translated where shown."""
from __future__ import annotations

import pickle

from mechdesign import i18n
from mechdesign.render.fmt import in_lang
from mechdesign.stages import titles
from mechdesign.stages.cam import CAM_CHECK_NAMES
from mechdesign.stages.drive import DRIVE_CHECK_NAMES
from mechdesign.stages.findings import Cat, Msg, Pair, en_zh, finding


def test_a_stage_title_is_its_english_msgid_translated_where_shown():
    t = titles.pgettext("stage", "drive")
    assert t == "drive" and in_lang(t, "en") == "drive"
    assert in_lang(t, "zh") == i18n.gettext("drive", "zh", "stage") == "传动装置设计"
    # one English title, two Chinese ones: told apart by the context
    assert in_lang(titles.pgettext("stage: self-checks", "verification"), "zh") == "计算校核"
    assert in_lang(titles.pgettext("stage", "verification"), "zh") == "校核"
    back = pickle.loads(pickle.dumps(t))             # worker processes
    assert back.context == "stage" and in_lang(back, "zh") == "传动装置设计"
    # the bilingual labels of the other helpers' tables are split as before
    assert in_lang("导杆 / guide bar", "zh") == "导杆" and in_lang("n / rpm", "zh") == "n / rpm"


def test_a_finding_has_the_catalogue_text_in_both_languages():
    f = finding("contact_ratio", "contact ratio ε = {eps:.3f} < {least}: use more teeth or a "
                "smaller working pressure angle.", eps=1.0512, least=1.2)
    assert f.en == ("contact ratio ε = 1.051 < 1.2: use more teeth or a smaller working pressure "
                    "angle.")
    assert f.zh == "重合度 ε = 1.051 < 1.2：增加齿数或减小啮合角。"
    assert f.text("zh") == f.zh and f.text("en") == f.en


def test_nested_messages_and_pairs_are_filled_per_language():
    en, zh = en_zh("{where}: {check} fails ({v} {rel} {a}{unit}): {fix}.",
                   where=Msg("stage {n} ({name})", n=2, name=Pair("V带传动", "V belt")),
                   check=Pair("弯曲应力", "bending stress"), v="120", rel=">", a="100",
                   unit=" MPa", fix=Cat(Msg("enlarge it or use a better material")))
    assert en == "stage 2 (V belt): bending stress fails (120 > 100 MPa): enlarge it or use a better material."
    assert zh == "第 2 级V带传动：弯曲应力不合格（120 > 100 MPa）：加大尺寸或改用更好的材料。"


def test_self_check_names_keep_their_zh_en_pairs():
    assert DRIVE_CHECK_NAMES["shaft_torque"] == ("各轴转矩 T = 9549.3 P/n（相对误差）",
                                                 "shaft torques T = 9549.3 P/n (relative error)")
    assert CAM_CHECK_NAMES["angle_sum"] == ("运动角之和", "sum of the programme's angles")
    assert set(CAM_CHECK_NAMES) >= {"closure", "envelope", "corner"}
