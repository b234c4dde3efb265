"""A helical pair's centre distance is rounded to a whole millimetre and its helix angle
corrected to it (PU Lianggui, Machine Design, ch. 10: 圆整中心距, 修正螺旋角); the strength
checks and the shaft loads then use the corrected β.

Independent references: the closed forms a = m_n (z1 + z2) / (2 cos β), d = m_n z / cos β,
F_a = F_t tan β, F_r = F_t tan α_n / cos β; a brute-force search over whole millimetres."""
import math

import pytest

from mechdesign.stages.drive_strength import HELIX_RANGE, rounded_helix


def _brute(m, z1, z2, beta):
    a0 = m * (z1 + z2) / (2 * math.cos(beta)) * 1e3
    ok = []
    for a in range(int(a0) - 50, int(a0) + 51):
        c = m * (z1 + z2) / (2 * a * 1e-3)
        if c < 1 and math.radians(8) <= math.acos(c) <= math.radians(20):
            ok.append((abs(a - a0), a))
    return min(ok)[1] if ok else None


@pytest.mark.parametrize("m, z1, z2, beta_deg", [
    (5e-3, 24, 107, 14), (8e-3, 24, 76, 14), (2e-3, 24, 77, 14), (3e-3, 20, 81, 8.2),
    (4e-3, 31, 99, 19.9), (2.5e-3, 19, 60, 12)])
def test_the_nearest_whole_millimetre_within_8_to_20_degrees(m, z1, z2, beta_deg):
    beta = rounded_helix(m, z1, z2, math.radians(beta_deg))
    a = m * (z1 + z2) / (2 * math.cos(beta)) * 1e3
    assert abs(a - round(a)) < 1e-9
    assert round(a) == _brute(m, z1, z2, math.radians(beta_deg))
    assert HELIX_RANGE[0] - 1e-12 <= beta <= HELIX_RANGE[1] + 1e-12


def test_the_die_cutters_helical_stages_use_the_corrected_angle(example_results):
    r = example_results("die_cutter")
    helical = [s for s in r["drive"].stages if s.type == "helical"]
    assert len(helical) == 2
    for s in helical:
        g = s.design
        geo, m = g.geometry, g.module
        beta = geo.beta
        a = m * (s.z1 + s.z2) / (2 * math.cos(beta))
        assert abs(geo.a - a) < 1e-12
        assert abs(a * 1e3 - round(a * 1e3)) < 1e-9             # a whole millimetre
        a0 = m * (s.z1 + s.z2) / (2 * math.cos(math.radians(14)))
        assert abs(a - a0) <= 0.5e-3 + 1e-12                     # the nearest one
        assert abs(g.forces["d1"] - m * s.z1 / math.cos(beta)) < 1e-12
        Ft = g.forces["Ft"]
        assert abs(g.forces["Fa"] - Ft * math.tan(beta)) < 1e-9 * Ft
        assert abs(g.forces["Fr"] - Ft * math.tan(math.radians(20)) / math.cos(beta)) < 1e-9 * Ft
        assert g.extra["beta"] == beta
        # the contact ratio's estimate with the corrected β
        eps = (1.88 - 3.2 * (1 / s.z1 + 1 / s.z2)) * math.cos(beta)
        assert abs(g.extra["eps_alpha"] - eps) < 1e-12
