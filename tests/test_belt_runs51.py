"""The straight runs of a belt or chain on the schematics are the outer common tangents of its
two wheels (page review 51: the shaper's V-belt, 106 mm and 355 mm pulleys, was drawn along
secants that cut the larger pulley). Independent reference: the distance of a centre from a
straight line, |(c − p) × t|, must equal the wheel's radius, and both centres lie on the same
side of the run (outer tangent); checked for unequal wheels either way round."""
import numpy as np
import pytest

from mechdesign.render.kinematic_sheet import _tangent_runs


def _dist(c: complex, p: complex, q: complex) -> float:
    t = (q - p) / abs(q - p)
    return ((c - p).real * t.imag - (c - p).imag * t.real)


@pytest.mark.parametrize("a, r1, b, r2", [
    (0j, 53.0, 400 + 0j, 177.5),          # the shaper's V-belt: small driving pulley first
    (0j, 177.5, 400 + 0j, 53.0),          # the larger wheel first (the lock-beam's chain)
    (10 + 20j, 30.0, -200 + 350j, 90.0),  # an oblique pair
    (0j, 40.0, 300 + 0j, 40.0),           # equal wheels: the runs parallel to the centre line
])
def test_runs_touch_both_wheels(a, r1, b, r2):
    runs = _tangent_runs(a, r1, b, r2)
    assert len(runs) == 2
    sides = []
    for p, q in runs:
        # each end lies on its wheel
        assert abs(abs(p - a) - r1) < 1e-9 and abs(abs(q - b) - r2) < 1e-9
        da, db = _dist(a, p, q), _dist(b, p, q)
        # tangent to both: each centre at its radius from the run's line, on the same side
        assert abs(abs(da) - r1) < 1e-9 and abs(abs(db) - r2) < 1e-9
        assert np.sign(da) == np.sign(db)
        # the run's end is the foot of the perpendicular from the centre (touching, not cutting)
        t = (q - p) / abs(q - p)
        assert abs(((p - a) * t.conjugate()).real) < 1e-9
        assert abs(((q - b) * t.conjugate()).real) < 1e-9
        sides.append(np.sign(da))
    assert sides[0] == -sides[1]             # one run on each side of the centre line
