"""The held figures' fixed point (render/pdf.py _settle, templates/report.typ figure-held):
where typst's five passes do not settle the figures held back past a table, the rounds
outside typst give the held figures as an input and compile again until none is added."""
from __future__ import annotations

import json

import pytest

from mechdesign.render import pdf as P


class FakeTypst:
    """Stands for typst: ``layouts`` maps the held figures given (a JSON string, or None for
    the first compilation) to (settled, held next, far) of that compilation."""

    def __init__(self, layouts):
        self.layouts = layouts
        self.compiled = []                    # the inputs of each compilation
        self.sources = []

    def compile(self, typ_name, root, timestamp, stem, inputs):
        given = inputs.get("figure-held")
        self.compiled.append(given)
        with open(typ_name, encoding="utf-8") as handle:
            self.sources.append(handle.read())
        if P.FIGURE_RULES_OFF in self.sources[-1]:
            return b"pdf-off", []
        settled, _, _ = self.layouts[given]
        return f"pdf-{given}".encode(), [] if settled else ["document did not converge within five attempts"]

    def held_next(self, typ_name, root, inputs):
        _, held, far = self.layouts[inputs.get("figure-held")]
        return {"held": held, "far": far}


def settle(monkeypatch, tmp_path, layouts):
    fake = FakeTypst(layouts)
    monkeypatch.setattr(P, "_compile_report", fake.compile)
    monkeypatch.setattr(P, "_held_next", fake.held_next)
    source = "x\n" + P.FIGURE_RULES_ON + "y\n"
    typ = tmp_path / "r.typ"
    typ.write_text(source, encoding="utf-8")
    pdf, found, rounds = P._settle(str(typ), tmp_path, 0, "r", source)
    return fake, pdf, found, rounds


def key(held):
    return json.dumps(held, sort_keys=True)


def test_a_settled_layout_is_compiled_once(monkeypatch, tmp_path):
    fake, pdf, found, rounds = settle(monkeypatch, tmp_path, {None: (True, {}, [])})
    assert fake.compiled == [None] and pdf == b"pdf-None" and found == []
    assert rounds == [{"held": None, "settled": True}]


def test_the_holds_grow_until_a_round_adds_none(monkeypatch, tmp_path):
    # slotter zh: unsettled in typst's passes; the held figures read from its last pass are
    # given; that round holds one figure more; the next adds none: its layout is the report
    a, b = {"14": 23}, {"14": 23, "1": 4}
    fake, pdf, found, rounds = settle(monkeypatch, tmp_path, {
        None: (False, a, []), key(a): (True, b, []), key(b): (True, b, [])})
    assert fake.compiled == [None, key(a), key(b)]
    assert pdf == f"pdf-{key(b)}".encode() and not P._unsettled(found)
    assert [r["held"] for r in rounds] == [None, a, b]


def test_a_held_figure_far_from_its_text_is_let_go_with_those_held_with_it(monkeypatch, tmp_path):
    # linkage_sixbar zh: figures 1 and 2 held past table 3 (ordinal 2); figure 2 then lands
    # two pages after its text: both are let go (and not held again), figure 5's hold stays
    held = {"1": 2, "2": 2, "5": 7}
    fake, pdf, found, rounds = settle(monkeypatch, tmp_path, {
        None: (False, held, []), key(held): (True, held, [2]),
        key({"5": 7}): (True, held, [])})
    assert fake.compiled == [None, key(held), key({"5": 7})]
    assert pdf == f"pdf-{key({'5': 7})}".encode() and not P._unsettled(found)


def test_far_held_figures_are_let_go_also_where_their_round_did_not_settle(monkeypatch, tmp_path):
    # die_cutter zh (session 37): figure 2 held past table 5 and figures 17, 18 past table 47;
    # given all three, typst's passes do not settle and 17, 18 land far from their text.
    # They are let go; figure 2 held alone settles and holds nothing new (the fallback
    # without the figure rules set every figure as if none were held)
    all3, alone = {"2": 5, "17": 47, "18": 47}, {"2": 5}
    fake, pdf, found, rounds = settle(monkeypatch, tmp_path, {
        None: (False, all3, []), key(all3): (False, all3, [17, 18]),
        key(alone): (True, all3, [])})
    assert fake.compiled == [None, key(all3), key(alone)]
    assert pdf == f"pdf-{key(alone)}".encode() and not P._unsettled(found)


def test_rounds_without_a_fixed_point_fall_back_to_the_last_settled_one(monkeypatch, tmp_path):
    # each round holds one figure more (never a fixed point): after FIGURE_ROUNDS rounds the
    # last settled round's layout, with a warning that says so
    steps = [{str(k): 0 for k in range(1, n + 1)} for n in range(1, P.FIGURE_ROUNDS + 3)]
    layouts = {None: (False, steps[0], [])}
    for n, held in enumerate(steps[:-1]):
        layouts[key(held)] = (n % 2 == 0, steps[n + 1], [])
    fake, pdf, found, rounds = settle(monkeypatch, tmp_path, layouts)
    assert len(fake.compiled) == 1 + P.FIGURE_ROUNDS
    last_settled = max(n for n in range(P.FIGURE_ROUNDS) if n % 2 == 0)
    assert pdf == f"pdf-{key(steps[last_settled])}".encode()
    assert P._unsettled(found) and any(P.FELL_BACK in text for text in found)


def test_no_settled_round_falls_back_to_the_source_without_the_figure_rules(monkeypatch, tmp_path):
    a = {"3": 1}
    fake, pdf, found, rounds = settle(monkeypatch, tmp_path, {
        None: (False, a, []), key(a): (False, a, [])})
    assert fake.compiled == [None, key(a), None]
    assert P.FIGURE_RULES_OFF in fake.sources[-1] and pdf == b"pdf-off"
    assert any(P.FELL_BACK in text for text in found)


def test_the_close_plan_read_from_the_first_compilation_stands_in_every_round(monkeypatch, tmp_path):
    # textbook_guide_bar zh: the chapters' close plan, applied once more from typst's third
    # pass (figure 5 set smaller to stand under chapter 2's text), kept the fifth pass from
    # settling; the rounds give it as an input, the same in each, also where a later
    # compilation reads another
    first, later = [311.5, 267.8], [311.5, 297.6]
    fake = FakeTypst({None: (False, {}, []), key({}): (True, {}, [])})
    inputs = []
    compile_ = fake.compile

    def compile_with(typ_name, root, timestamp, stem, given):
        inputs.append(dict(given))
        return compile_(typ_name, root, timestamp, stem, given)

    def held_next(typ_name, root, given):
        return {"held": {}, "far": [], "close": later if given.get("figure-close") else first}

    monkeypatch.setattr(P, "_compile_report", compile_with)
    monkeypatch.setattr(P, "_held_next", held_next)
    source = "x\n" + P.FIGURE_RULES_ON + "y\n"
    typ = tmp_path / "r.typ"
    typ.write_text(source, encoding="utf-8")
    pdf, found, rounds = P._settle(str(typ), tmp_path, 0, "r", source)
    assert inputs[0] == {} and len(inputs) == 2
    assert inputs[1] == {"figure-held": key({}), "figure-close": json.dumps(first)}
    assert pdf == f"pdf-{key({})}".encode() and not P._unsettled(found)


@pytest.mark.e2e
def test_given_holds_stand_and_the_next_are_reported(tmp_path):
    # the template's side: a figure whose text stands before a table split across pages,
    # given no hold, floats between the table's parts (nothing is held anew inside the
    # compilation) and the query reports it as the one to hold; given that hold, it stands
    # after the table
    pytest.importorskip("typst")
    import typst
    from PIL import Image
    from test_typeset import _FILLER, tables_interrupted

    from mechdesign.render.pdf import typst_fonts, typst_source
    from mechdesign.render.report import template_dir

    rows = "\n".join(f"| r{k} | {k} |" for k in range(24))
    cases = []
    for lead in (6, 7, 8, 9, 10):
        folder = tmp_path / str(lead)
        folder.mkdir()
        md = (f"# One\n\n{_FILLER * lead}\n\nThe table is drawn in Figure 1.\n\n"
              f"![A figure](a.png){{width=80%}}\n\n| Name | Value |\n|---|--:|\n{rows}\n\n: Long table\n\n"
              f"{_FILLER * 8}\n")
        Image.new("RGB", (800, 500), (200, 220, 240)).save(folder / "a.png")
        (folder / "doc.md").write_text(md, encoding="utf-8")
        source = typst_source(folder / "doc.md", {"title": "T", "lang": "en"}, template_dir() / "report.typ").result()
        (folder / "doc.typ").write_text(source, encoding="utf-8")
        results = {}
        for given in ({}, {"1": 0}):
            inputs = {"figure-held": json.dumps(given)}
            pdf, found = typst.compile_with_warnings(str(folder / "doc.typ"), root=str(folder),
                                                     font_paths=typst_fonts(), sys_inputs=inputs)
            assert not P._unsettled([str(w) for w in found])
            (folder / "doc.pdf").write_bytes(pdf)
            nxt = json.loads(typst.query(str(folder / "doc.typ"), "<figure-held-next>", field="value",
                                         one=True, root=str(folder), font_paths=typst_fonts(), sys_inputs=inputs))
            results[json.dumps(given)] = (tables_interrupted(folder / "doc.pdf"), nxt)
        cases.append(results)
    # the case: given no hold, the figure stands between the table's parts in some of them
    interrupted = [r for r in cases if r["{}"][0]]
    assert interrupted
    for r in interrupted:
        assert r["{}"][1]["held"] == {"1": 0}
        parted, nxt = r['{"1": 0}']
        # (nxt["far"] may name it: the text under the table is plain filler, with nothing
        # typst locates, so hole-figures reads a band above the figure at the page's foot)
        assert parted == [] and nxt["held"] == {"1": 0}


_SERVED_QUERY = r"""
import sys
from pathlib import Path
from mechdesign.render import parallel, pdf

tmp = Path(sys.argv[1])
(tmp / "r.typ").write_text('#metadata((held: json(bytes(sys.inputs.at("figure-held"))), far: (2,)))<figure-held-next>\n'
                           'Hello', encoding="utf-8")
stop = pdf.start_service()
try:
    assert set(pdf._service_address) == {"file", "bytes"}
    got = pdf._held_next(str(tmp / "r.typ"), tmp, {"figure-held": '{"3": 1}'})
    assert got == {"held": {"3": 1}, "far": [2]}, got
    assert not parallel.typst_used()
finally:
    stop()
print("ok")
"""


def test_the_held_figures_are_read_by_the_compiling_process(tmp_path):
    # the query goes to the reports' compiling process (the watch's), with the inputs given
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    result = subprocess.run([sys.executable, "-c", _SERVED_QUERY, str(tmp_path)], cwd=root,
                            capture_output=True, text=True)
    assert result.stdout.strip().endswith("ok"), result.stderr[-2000:]


class CloseAgain:
    """typst for the close plan read again (templates/report.typ: close-again): the first
    compilation is unsettled and holds ``held``; each round with ``held`` given settles with
    the held figures of ``layouts[close given]`` (held, far) and reads the plan ``nexts[close]``
    again from its layout."""

    def __init__(self, held, layouts, nexts, first):
        self.held, self.layouts, self.nexts, self.first = held, layouts, nexts, first
        self.closes = []

    def compile(self, typ_name, root, timestamp, stem, inputs):
        close = inputs.get("figure-close")
        self.closes.append(None if close is None else json.loads(close))
        if close is None:
            return b"pdf-first", ["document did not converge within five attempts"]
        return f"pdf-{close}".encode(), []

    def held_next(self, typ_name, root, inputs):
        close = inputs.get("figure-close")
        if close is None:
            return {"held": self.held, "far": [], "close": self.first}
        held, far = self.layouts[close]
        return {"held": held, "far": far, "close": json.loads(close), "close-next": self.nexts[close]}


def close_again(monkeypatch, tmp_path, fake):
    monkeypatch.setattr(P, "_compile_report", fake.compile)
    monkeypatch.setattr(P, "_held_next", fake.held_next)
    source = "x\n" + P.FIGURE_RULES_ON + "y\n"
    typ = tmp_path / "r.typ"
    typ.write_text(source, encoding="utf-8")
    return P._settle(str(typ), tmp_path, 0, "r", source)


def test_the_close_plan_read_again_at_the_fixed_point_sets_a_last_figure_smaller(monkeypatch, tmp_path):
    # die_cutter en: the close plan read from the first compilation kept figure 14 at 399 pt;
    # with figures 1, 2 and 18 held its chapter's text ended higher and the figure went on to
    # the next page (p.23 42 % full). Read again at the fixed point: 379 pt, compiled once
    # more; that round's fixed point is the report
    held = {"1": 5, "2": 5}
    first, smaller = [311.5, 399.0], [311.5, 379.0]
    fake = CloseAgain(held, {json.dumps(first): (held, []), json.dumps(smaller): (held, [])},
                      {json.dumps(first): smaller, json.dumps(smaller): smaller}, first)
    pdf, found, rounds = close_again(monkeypatch, tmp_path, fake)
    assert fake.closes == [None, first, smaller]
    assert pdf == f"pdf-{json.dumps(smaller)}".encode() and not P._unsettled(found)


def test_the_close_plan_is_read_again_once_and_a_plan_that_finds_no_fixed_point_is_dropped(monkeypatch, tmp_path):
    # read again, the plan sets the figure smaller still in every layout: one more compilation
    # only. And where that round holds a figure more every time (no fixed point within the
    # rounds), the fixed point before it is the report, not a fallback
    held = {"1": 5}
    plans = [[300.0 - 10 * k] for k in range(8)]
    layouts = {json.dumps(plans[0]): (held, []), json.dumps(plans[1]): ({"1": 5, "9": 7}, [])}
    fake = CloseAgain(held, layouts, {json.dumps(p): q for p, q in zip(plans, plans[1:])}, plans[0])
    growing = iter(range(10, 40))

    def held_next(typ_name, root, inputs):
        value = CloseAgain.held_next(fake, typ_name, root, inputs)
        if inputs.get("figure-close") == json.dumps(plans[1]):
            value["held"] = dict(json.loads(inputs["figure-held"]), **{str(next(growing)): 9})
        return value

    fake.held_next = held_next
    pdf, found, rounds = close_again(monkeypatch, tmp_path, fake)
    assert fake.closes.count(plans[1]) >= 1 and plans[2] not in fake.closes
    assert pdf == f"pdf-{json.dumps(plans[0])}".encode()
    assert not any(P.FELL_BACK in text for text in found)
