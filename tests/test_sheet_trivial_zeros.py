"""The A1 sheet's polygon cells list results, not zeros by construction (review 34).

The shaper's velocity cells listed "vS6F = 0 m/s, vPF = 0 m/s": relative velocities of two
points of the ram, a link in translation — zero by construction, nothing measured (the
report's graphical section leaves such an equation out). A relative vector whose value is
exactly zero is left out of the cell's list; a sliding velocity that happens to be zero
(a guide bar at its extreme) is a result and stays.
"""
from __future__ import annotations


def test_a_zero_relative_vector_of_a_translating_link_is_not_listed():
    from mechdesign.core.polygons import Polygon, Vector
    from mechdesign.render.analysis_sheet import _items

    pg = Polygon("velocity", "4", {"p": 0j, "s6": 1 + 0j, "f": 1 + 0j, "a3": 0j, "a4": 0j},
                 (Vector("vS6", "p", "s6", 1.166 + 0j, "absolute"),
                  Vector("vS6F", "f", "s6", 0j, "relative"),
                  Vector("vA4A3", "a3", "a4", 0j, "sliding")))
    items = _items(pg, [])
    assert len(items) == 2 and items[1] == "vA4A3 = 0 m/s"
    assert not any(t.startswith("vS6F") for t in items)
    acc = Polygon("acceleration", "4", {"p": 0j, "s6": 1 + 0j, "f": 1 + 0j},
                  (Vector("aS6", "p", "s6", 2.0 + 0j, "absolute"),
                   Vector("aS6Fn", "f", "x", 0j, "normal"),
                   Vector("aS6Ft", "x", "s6", 0j, "tangential")))
    assert len(_items(acc, [])) == 1
