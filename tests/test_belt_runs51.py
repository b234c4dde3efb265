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


@pytest.mark.e2e
def test_the_transmission_sheets_belt_runs_are_tangent(tmp_path):
    # the transmission schematic drew its belts with a copy of the tangent construction that
    # kept the old sign (the shaper's sheet, after _tangent_runs was mended): every straight
    # run that joins two wheel circles of the DXF touches both (distance of each centre from
    # the run's line = its radius)
    import ezdxf
    from typer.testing import CliRunner

    from mechdesign.cli import app

    out = tmp_path / "shaper"
    r = CliRunner().invoke(app, ["run", "designs/shaper.yaml", "--lang", "en", "--format", "dxf",
                                 "--out", str(out)])
    assert r.exit_code == 0, r.output
    msp = ezdxf.readfile(out / "sheets" / "transmission_A3.dxf").modelspace()
    circles = [(complex(c.dxf.center.x, c.dxf.center.y), c.dxf.radius) for c in msp.query("CIRCLE")
               if c.dxf.layer == "OUTLINE" and c.dxf.radius > 2.0]

    def on(p):
        return [k for k, (c, rr) in enumerate(circles) if abs(abs(p - c) - rr) < 1e-6]

    runs = 0
    for ln in msp.query("LINE"):
        p0, p1 = complex(ln.dxf.start.x, ln.dxf.start.y), complex(ln.dxf.end.x, ln.dxf.end.y)
        ends0, ends1 = on(p0), on(p1)
        pairs = [(i, j) for i in ends0 for j in ends1 if i != j]
        if not pairs or abs(p1 - p0) < 1.0:
            continue
        i, j = pairs[0]
        t = (p1 - p0) / abs(p1 - p0)
        for c, rr in (circles[i], circles[j]):
            assert abs(abs((np.conj(t) * (c - p0)).imag) - rr) < 1e-6
        runs += 1
    assert runs == 2                       # the V-belt's two runs
