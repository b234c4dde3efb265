"""The summary names the passing checks nearest their limits (page review 48: it drew no
conclusion of its own). A hand-built results document whose margins are known:
σ = 58.8 of 60 MPa (2 %), a life of 50 500 h against 50 000 h (1 %), σ = 54 of 60 MPa (10 %,
not named), a failed check (named as failing, not as a margin), a diameter at 0.5 % (sized by
the standard series: not a load's check)."""
from mechdesign.render.summary import summary_context


def _check(key, name, value, allowable, unit, sense):
    scale = {"MPa": 1e6, "h": 3600.0, "mm": 1e-3}[unit]
    ok = value <= allowable if sense == "le" else value >= allowable
    return {"key": key, "name": name, "symbol": "x", "value": value * scale,
            "allowable": allowable * scale, "unit": unit, "sense": sense, "passed": ok,
            "inputs": {}, "name_args": {}}


def _document():
    return {"drive": {"shaft_designs": [{"index": 1, "checks": [
        _check("shaft_bending", "Shaft bending–torsion strength", 58.8, 60.0, "MPa", "le"),
        _check("bearing_life", "Bearing life", 50500, 50000, "h", "ge"),
        _check("key_crushing", "Key crushing", 54.0, 60.0, "MPa", "le"),
        _check("shaft_diameter", "Shaft diameter", 20.1, 20.0, "mm", "ge"),
        _check("gear_contact", "Contact fatigue (flanks)", 700.0, 600.0, "MPa", "le")]}]}}


def test_the_tightest_passing_checks_are_named_with_their_margins():
    watch = summary_context("x", _document(), {}, "en", "t")["margins"]
    tight = [w for w in watch if "margin" in w]
    assert len(tight) == 2
    assert tight[0].startswith("Bearing life") and "1.0 %" in tight[0]
    assert "50\u202f500 against 50\u202f000 h" in tight[0]     # grouped, narrow no-break space
    assert tight[1].startswith("Shaft bending–torsion strength") and "2.0 %" in tight[1]
    assert "58.8 against 60.0 MPa" in tight[1]
    assert not any("Key crushing" in w or "Shaft diameter" in w for w in tight)


def test_the_margins_in_chinese():
    watch = summary_context("x", _document(), {}, "zh", "t")["margins"]
    tight = [w for w in watch if "裕量" in w]
    assert len(tight) == 2 and "裕量仅 1.0 %" in tight[0] and "限值 50\u202f000 h" in tight[0]


def test_the_margins_are_listed_apart_from_the_points_that_need_action():
    ctx = summary_context("x", _document(), {}, "en", "t")
    assert not any("margin" in w for w in ctx["watch"])
    assert ctx["all_passed"] is False            # the contact check fails …
    assert any("Contact fatigue" in w and "FAILS" in w for w in ctx["watch"])   # … and is named


def test_the_die_cutter_summary_lists_its_closest_checks(handin_reports):
    md, _ = handin_reports("die_cutter", "en")
    tail = md[md.index("# Summary"):]
    assert "**Closest to their limits (passed):**" in tail
    block = tail.split("**Closest to their limits (passed):**")[1].split("# References")[0]
    assert block.count("% margin") >= 1
