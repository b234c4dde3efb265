"""The cam table lists the follower's velocity v where the pressure-angle formula uses
ds/dδ (page review 48: eq. (18) re-evaluated with the table's v gave 22.62° against the
printed 21.70°). The report writes ds/dδ = v/ω with ω; the closed form of a translating
roller follower, tan α = |ds/dδ − e| / (s0 + s) (孙桓, 机械原理, ch. 9), holds with it."""
import numpy as np


def test_the_pressure_angle_closed_form_with_v_over_omega(example_results, handin_reports):
    r = example_results("lockbeam_cam")
    c = r["cam"]
    g = c.grid
    w = c.params.omega
    v = g.motion.ds * w                       # the table's velocity, m/s
    s, e, s0 = g.motion.s, c.offset, g.initial_angle
    alpha = np.arctan(np.abs(v / w - e) / (s0 + s))
    assert np.max(np.abs(alpha - g.pressure_angle)) < 1e-9
    md, _ = handin_reports("lockbeam_cam", "en")
    assert r"\frac{ds}{d\delta} = \frac{v}{\omega},\ \omega = 1.047\ \text{rad/s}" in md
