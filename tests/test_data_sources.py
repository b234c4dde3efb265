"""Issue 20 point 4: every shipped data table states its source and whether it was confirmed
against a public copy; the confirmed tables are checked here against the values typed from
those copies (independent references, not the program's output).

Public copies used (see each data file's header for the details):
* V-belt tables: two public transcriptions of 濮良贵《机械设计》9th ed. tables 8-4/8-5 and the
  GB/T 13575.1 tables — a C++ V-belt designer (public GitHub code; arrays Z50 … B280 over
  n1 = 400, 700, 800, 950, 1200, 1450, 1600, 2000, 2400, 2800 r/min and Z100D … B200D) and a
  MATLAB V-belt GUI "VBC" (P0array over 100 … 6000 r/min, Kaarray, Klarray, the K_A rows).
"""
from __future__ import annotations

import pytest

from mechdesign.data import load_yaml

# rows of the C++ copy (kW; n1 = 400, 700, 800, 950, 1200, 1450, 1600, 2000, 2400, 2800 r/min)
_P0_CPP = {
    ("Z", 50): [0.06, 0.09, 0.10, 0.12, 0.14, 0.16, 0.17, 0.20, 0.22, 0.26],
    ("Z", 71): [0.09, 0.17, 0.20, 0.23, 0.27, 0.30, 0.33, 0.39, 0.46, 0.50],
    ("Z", 90): [0.14, 0.22, 0.24, 0.28, 0.33, 0.36, 0.40, 0.48, 0.54, 0.60],
    ("A", 75): [0.26, 0.40, 0.45, 0.51, 0.60, 0.68, 0.73, 0.84, 0.92, 1.00],
    ("A", 125): [0.67, 1.07, 1.19, 1.37, 1.66, 1.92, 2.07, 2.44, 2.74, 2.98],
    ("A", 180): [1.09, 1.76, 1.97, 2.27, 2.74, 3.16, 3.40, 3.93, 4.32, 4.54],
    ("B", 125): [0.84, 1.30, 1.44, 1.64, 1.93, 2.19, 2.33, 2.64, 2.85, 2.96],
    ("B", 140): [1.05, 1.64, 1.82, 2.08, 2.47, 2.82, 3.00, 3.42, 3.70, 3.85],
    ("B", 280): [2.89, 4.61, 5.13, 5.85, 6.90, 7.76, 8.13, 8.60, 8.22, 6.80],
}
# the MATLAB copy's rows over 100, 200, 400, 700, 800, 950, 1200, 1450, 1600, 2000, 2400, 2800
_P0_MATLAB = {
    ("A", 100): [0.00, 0.26, 0.47, 0.74, 0.83, 0.95, 1.14, 1.32, 1.42, 1.66, 1.87, 2.05],
    ("B", 160): [0.00, 0.74, 1.32, 2.09, 2.32, 2.66, 3.17, 3.62, 3.86, 4.40, 4.75, 4.89],
}
# ΔP0 of the C++ copy at n1 = 1450 r/min over the ten ratio ranges
_DP0_1450 = {"Z": [0.00, 0.00, 0.01, 0.01, 0.01, 0.02, 0.02, 0.02, 0.02, 0.03],
             "A": [0.00, 0.02, 0.04, 0.06, 0.08, 0.09, 0.11, 0.13, 0.15, 0.17],
             "B": [0.00, 0.05, 0.10, 0.15, 0.20, 0.25, 0.31, 0.36, 0.40, 0.46]}
# the MATLAB copy's K_L (Klarray) and Kα (Kaarray) rows
_KL_MATLAB = {"Z": {400: 0.87, 710: 0.99, 1250: 1.10, 1800: 1.18},
              "A": {630: 0.81, 710: 0.83, 1400: 0.96, 2500: 1.09, 4000: 1.19},
              "B": {900: 0.82, 1400: 0.90, 2000: 0.98, 3150: 1.07, 5000: 1.18}}
_KALPHA_MATLAB = {180: 1.00, 170: 0.98, 160: 0.95, 150: 0.92, 140: 0.89, 130: 0.86, 120: 0.82, 110: 0.78}


def test_belt_rated_power_is_the_public_9th_edition_table():
    t = load_yaml("belts.yaml")["rated_power"]
    assert t["n1_rpm"] == [400, 700, 800, 950, 1200, 1450, 1600, 2000, 2400, 2800]
    for (sec, d), row in _P0_CPP.items():
        assert t[sec][d] == row, (sec, d)
    for (sec, d), row in _P0_MATLAB.items():
        assert t[sec][d] == row[2:], (sec, d)


def test_belt_power_increment_and_factors_are_the_public_tables():
    b = load_yaml("belts.yaml")
    t = b["power_increment"]
    assert t["n1_rpm"][5] == 1450
    for sec, row in _DP0_1450.items():
        assert t[sec][5] == row
    lengths = b["datum_lengths"]
    for sec, cells in _KL_MATLAB.items():
        for L, k in cells.items():
            assert lengths[sec]["K_L"][lengths[sec]["L_d_mm"].index(L)] == k, (sec, L)
    w = b["wrap_factor"]
    for a, k in _KALPHA_MATLAB.items():
        assert w["K_alpha"][w["alpha1_deg"].index(a)] == k
    assert [r["K_A"] for r in b["application_factor"]["rows"]] == [
        [1.0, 1.1, 1.2], [1.1, 1.2, 1.3], [1.2, 1.3, 1.4], [1.3, 1.4, 1.5]]


def test_belt_table_status_is_stated():
    b = load_yaml("belts.yaml")
    assert b["unconfirmed"] == ["selection_chart"]
    assert set(b["confirmed"]) == {"rated_power", "power_increment", "sections", "wrap_factor",
                                   "datum_lengths", "application_factor"}
