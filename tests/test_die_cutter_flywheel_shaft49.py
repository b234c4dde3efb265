"""The die-cutter's flywheel hangs on its drive shaft (review 48, A): the rim that chapter 7
sizes is a load on that shaft, between its bearings, and the bearings carry it.

Independent references: the rim's weight is m·g of the flywheel stage's own rim; the shaft's
reactions balance its loads (ΣF = 0, ΣM_A = 0 in the vertical plane, statics)."""

def test_the_flywheel_rim_loads_its_shaft(example_results):
    r = example_results("die_cutter")
    p, fl = r["params"], r["press_flywheel"]
    j = p.flywheel_shaft
    sd = next(s for s in r["drive"].shaft_designs if s.index == j)
    assert "flywheel" in sd.elements
    load = sd.loads[sd.elements.index("flywheel")]
    W = fl.rim.rim_mass * p.gravity
    assert W > 600                                   # the 71 kg rim of chapter 7
    assert abs(load.Fv + W) < 1e-9 * W
    assert 0 < load.x < sd.span                      # between the bearings
    # statics of the vertical plane: the reactions carry every load, the rim's included
    res = sd.result
    loads = sd.loads
    assert abs(res.RAv + res.RBv + sum(l.Fv for l in loads)) < 1e-6 * W
    # moment about bearing A (z axis): M_z = x·F_y − y·F_x, an axial force at height r
    moment = sum(l.Fv * l.x - l.Fa * l.r for l in loads) + res.RBv * sd.span
    assert abs(moment) < 1e-6 * W * sd.span


def test_the_other_placement_carries_its_own_rim(example_results):
    """The placement comparison sizes the other shaft with the other flywheel's rim on it."""
    r = example_results("die_cutter")
    other = r["flywheel_placement"].other
    assert other.rim is not None
    assert other.shaft != r["params"].flywheel_shaft
