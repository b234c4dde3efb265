"""The offset slider-crank's given data stand in the design data table and the task names
the section (page review 48: K = 1.400, H = 100 mm and e = 20 mm appeared first in section 4).
Reference: designs/crank_rocker.yaml's slider_crank block (the brief's values)."""
import re

import yaml

from conftest import ROOT


def _table(md):
    head = md.split("{#tbl:data}")[0]
    return head[head.rindex("| Symbol") if "| Symbol" in head else head.rindex("| 符号"):]


def test_the_slider_cranks_data_are_in_the_data_table(handin_reports):
    brief = yaml.safe_load((ROOT / "designs" / "crank_rocker.yaml").read_text(encoding="utf-8"))
    sc = brief["slider_crank"]
    for lang, words in {"en": ("offset slider-crank: time ratio", "offset slider-crank: stroke",
                               "offset slider-crank: offset", "Then design an offset slider-crank"),
                        "zh": ("偏置曲柄滑块机构：行程速比系数", "偏置曲柄滑块机构：滑块行程",
                               "偏置曲柄滑块机构：偏距", "再按表中最后几行的数据设计")}.items():
        md, _ = handin_reports("crank_rocker", lang)
        table = _table(md)
        K = re.search(re.escape(words[0]) + r" \| ([\d.]+) \|", table)
        H = re.search(re.escape(words[1]) + r" \| ([\d.]+) \|", table)
        e = re.search(re.escape(words[2]) + r" \| ([\d.]+) \|", table)
        assert K and H and e, table
        assert float(K.group(1)) == sc["time_ratio_K"]
        assert float(H.group(1)) == sc["stroke_H_mm"]
        assert float(e.group(1)) == sc["offset_e_mm"]
        assert words[3] in md.split("{#tbl:data}")[0]
