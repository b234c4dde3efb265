"""The A1 analysis sheet (机构运动及动力分析图) of ANY linkage computed by the shared linkage
stages: the mechanism at every textbook position to a length scale, the velocity and
acceleration polygons at the chosen positions, the force polygon of every Assur group
(the crank included) at those positions, the output's s, v, a curves, the M_b curve, the
energy curve with ΔW_max when there is a flywheel, a table of the positions and the title
block.

The polygons are computed by the polygons stage (:mod:`mechdesign.stages.polygons`, from
the group types of :mod:`mechdesign.core.polygons`) and stored with the results; the sheet
only places and draws them, each to a scale written above it. :func:`analysis_sheet` takes
the run's :class:`~mechdesign.render.sheets.LinkageResults` (model, motion, forces,
flywheel, polygons), so it does not care which machine it draws; the model's link names
(``names``) are written on the skeleton.
"""
from __future__ import annotations

import re

import numpy as np

from ..core.polygons import Polygon, spread
from . import fmt
from .labels import LabelTable, pgettext, sheet_names, sheet_point
from .sheet import (DIM_GAP, GRID_WEIGHT, Dimension, Fill, LabelPlacer, Line, Text, _near_segment,
                    break_lines, clip_segment, dimension_geometry, sample_polyline, Series, Sheet,
                    TitleInfo, chart, fit_height,
                    fill_scale, frame, ground, heading, length_scale, pin,
                    scale_text, slider_block, sub, sup, table, text_width, title_block_box,
                    with_subscripts)

DEG = 180.0 / np.pi
TWO_PI = 2.0 * np.pi

LABELS = LabelTable({
    "mechanism": pgettext("analysis sheet", "Skeleton at the positions"),
    "velocity": pgettext("analysis sheet", "Velocity polygon, position {p}"),
    "acceleration": pgettext("analysis sheet", "Acceleration polygon, position {p}"),
    "force": pgettext("analysis sheet", "Force polygon, {g}, pos. {p}"),
    "crank_group": pgettext("analysis sheet", "driver {l}"),
    "group": pgettext("analysis sheet", "group {l}"),
    "s": pgettext("analysis sheet", "output displacement s ({u})"),
    "v": pgettext("analysis sheet", "output velocity v ({u})"),
    "a": pgettext("analysis sheet", "output acceleration a ({u})"),
    # a rocking output: its swing, angular velocity and acceleration (review39: a rocker's
    # curves and columns were labelled s, v, a as a slider's)
    "s_rot": pgettext("analysis sheet", "output swing ψ ({u})"),
    "v_rot": pgettext("analysis sheet", "output angular velocity ω ({u})"),
    "a_rot": pgettext("analysis sheet", "output angular acceleration α ({u})"),
    "mb": pgettext("analysis sheet", "balancing torque Mb (N·m)"),
    "work": pgettext("analysis sheet", "work W, energy change ΔE (J)"),
    "phase": pgettext("analysis sheet", "crank angle φ (°)"),
    "curves": pgettext("analysis sheet", "Output motion curves"),
    "mbt": pgettext("analysis sheet", "Balancing torque"),
    "signs": pgettext("analysis sheet", "Signs: Mb, Md and Pb positive in the crank's sense of "
                      "rotation, MI counter-clockwise positive"),
    "et": pgettext("analysis sheet", "Flywheel energy"),
    "md": pgettext("analysis sheet", "driving torque Md = {v} N·m"),
    "mean": pgettext("analysis sheet", "mean Mb = {v} N·m"),
    "table": pgettext("analysis sheet", "Results at the positions"),
    "table_kin": pgettext("analysis sheet", "Kinematic results at the positions"),
    "pos": pgettext("analysis sheet", "Pos."),
    "dw": "ΔWmax = {v} J",
    "jf": pgettext("analysis sheet", "flywheel inertia JF = {v} kg·m²"),
    "scales": pgettext("analysis sheet", "Drawing scales"),
    # the cells list the exact values the polygons are drawn from; the report's graphical
    # method measures the same polygons (to the drawing's accuracy)
    "each": pgettext("analysis sheet", "μv, μa, μF above each polygon; the values beside each are analytic"),
    "noforce": pgettext("analysis sheet", "no load at this position (all reactions zero)"),
    "each_kin": pgettext("analysis sheet", "μv, μa above each polygon; the values beside each are analytic"),
    "noload": pgettext("analysis sheet", "No load or masses given: all reactions and Mb are zero, "
                       "so no force polygons or Mb curve are drawn"),
    "kinonly": pgettext("analysis sheet", "Kinematics only (the task gives no loads): no force "
                        "polygons or Mb curve are drawn"),
    "nofly": pgettext("analysis sheet", "no flywheel"),
    "flat0": pgettext("analysis sheet", "all vectors parallel: the polygon closes on a line"),
    "flat": pgettext("analysis sheet", "nearly flat polygon (width {w} % of its length): "
                     "its vectors are almost parallel"),
    "links": pgettext("analysis sheet", "Links: "),
    "guide": pgettext("analysis sheet", "{n} guide"),
    "guide_plain": pgettext("analysis sheet", "guide"),
})

# symbols written with a subscript wherever they stand in this sheet's texts
SYMBOLS = ("M_b", "P_b", "M_d", "M_I", "J_F", "ΔW_max", "μ_v", "μ_a", "μ_F")
UNITS = {"velocity": (sub("μ", "v"), "(m/s)/mm", "m/s"),
         "acceleration": (sub("μ", "a"), "(m/s²)/mm", "m/s²"), "force": (sub("μ", "F"), "N/mm", "N")}


# ------------------------------------------------------------------ the sheet

def analysis_sheet(found, info: TitleInfo, lang: str, labels: dict | None = None
                   ) -> tuple[Sheet, dict]:
    """The A1 sheet of a linkage (``found``: model, motion, forces, flywheel, polygons of the
    run) and the scales used ({"length": n (1:n), "velocity_4": μv, …}). ``labels``
    overrides texts of :data:`LABELS` (e.g. the output's name)."""
    model, k, forces, flywheel = found.model, found.motion, found.forces, found.flywheel
    lab = {key: with_subscripts(v, *SYMBOLS) if isinstance(v, str) else v
           for key, v in {**LABELS[lang], **(labels or {})}.items()}
    chosen = [str(c) for c in found.polygons.positions]
    unloaded = forces is not None and _unloaded(forces)
    # only the kinematics exist: no empty force cells, no zero curve, no μF in the notes
    kinematic_only = forces is None or unloaded
    if unloaded:
        forces = flywheel = None
    polys = {c: found.polygons.at(c)[:2] if unloaded else found.polygons.at(c) for c in chosen}
    symbols = vector_symbols(getattr(found, "graphical", None))
    s = Sheet("A1")
    x0, y0, x1, y1 = s.inner
    right, rh = _left_column(model, k, lang, s.inner, widen=WIDEN if kinematic_only else
                             WIDEN_FORCES)
    table_top = y0 + 8 + _table_height(k, rh)
    n_len = _mechanism(s, model, k, lab, (x0 + 8, table_top + 10.0, right, y1 - 6), chosen,
                       lang)
    scales = {"length": n_len}
    info = TitleInfo(**{**info.__dict__, "scale": scale_text(n_len)})
    frame(s, info)
    _table(s, model, k, forces, lab, (x0 + 8, y0 + 8, right, table_top), rh)
    _polygon_grid(s, model, polys, chosen, lab, (right + 10.0, y0 + 8, 602.0, y1 - 4), scales,
                  symbols)
    _curves(s, model, k, forces, flywheel, lab, (622.0, 72.0, x1 - 8, y1 - 6))
    tb_x0, _, _, tb_y1 = title_block_box(s)
    notes = [lab["scales"] + f":  {sub('μ', 'L')} = {fmt.exact(n_len / 1000)} m/mm ({scale_text(n_len)}); "
             + lab["each_kin" if kinematic_only else "each"]]
    if unloaded:
        notes.append(lab["noload"])
    elif forces is None:
        notes.append(lab["kinonly"])
    else:
        notes.append(lab["signs"])
    if flywheel is not None:
        notes.append(lab["dw"].format(v=fmt.sig(flywheel.max_energy_swing)) + ",  "
                     + lab["jf"].format(v=fmt.sig(flywheel.inertia)))
    top = tb_y1 + 10.0 + 5.5 * max(len(notes) - 2, 0)     # a third line above, not on the title block
    # one text height for the notes: the longest line's fit (review35: a short line set larger)
    height = min(fit_height(text, 205.0, 3.0) for text in notes)
    for j, text in enumerate(notes):
        s.text(tb_x0 - 30.0 + 1j * (top - 5.5 * j), text, height, "TEXT")
    return s, scales


def _unloaded(forces) -> bool:
    """No load and no masses: every reaction and the balancing torque are exactly zero
    (:attr:`.sheets.LinkageResults.kinematic_only` with forces computed)."""
    return not np.any(forces.balancing_torque) and \
        not any(np.any(v) for v in forces.reactions.values())


def _group_title(model, pg: Polygon, lab: dict) -> str:
    g = next(g for g in model.mechanism.groups if g.name == pg.group)
    key = "crank_group" if g.driver is not None else "group"
    return lab[key].format(l="-".join(g.links))


def _polygon_grid(s: Sheet, model, polys: dict, chosen: list[str], lab: dict, box,
                  scales: dict, symbols: dict | None = None) -> None:
    """Rows: velocity, acceleration, then one row per group's force polygon; one column
    per chosen position. Row heights are shared out so that every cell fits."""
    bx0, by0, bx1, by1 = box
    cols = max(len(chosen), 1)
    width = (bx1 - bx0) / cols
    rows = [kind for kind in ("velocity", "acceleration")]
    n_force = max((len(p) - 2 for p in polys.values()), default=0)
    rows += [f"force{j}" for j in range(n_force)]
    shares = [1.5 if r in ("velocity", "acceleration") else 1.0 for r in rows]
    gap = 3.0
    avail = by1 - by0 - gap * (len(rows) - 1)
    heights = [avail * w / sum(shares) for w in shares]
    top = by1
    for r, h in zip(rows, heights):
        for c, label in enumerate(chosen):
            ps = polys[label]
            pg = ps[0] if r == "velocity" else ps[1] if r == "acceleration" else (
                ps[2 + int(r[5:])] if 2 + int(r[5:]) < len(ps) else None)
            if pg is None:
                continue
            cell = (bx0 + c * width + 2.0, top - h, bx0 + (c + 1) * width - 2.0, top)
            title = (lab[pg.kind].format(p=label) if pg.kind != "force"
                     else lab["force"].format(p=label, g=_group_title(model, pg, lab)))
            mu = _cell(s, pg, cell, title, lab,
                       (symbols or {}).get((label, pg.kind), []), _sense(model))
            key = pg.kind if pg.kind != "force" else f"force_{pg.group}"
            scales[f"{key}_{label}"] = mu
        top -= h + gap


def force_symbol(name: str) -> str:
    """A force polygon's vector or moment name with its subscript, as the report writes it
    (render/graphical_report.sym): "R12" → F with R12, "FI4" → F with I4, "G4", "Pb", "Mb",
    "MI3", "Fr", "Fc" → G₄, P_b, M_b, M_I3, F_r, F_c; other names (with ^ or _) as written."""
    prime = "'" if name.endswith("'") else ""
    s = name[:-1] if prime else name
    if "^" in s or "_" in s or len(s) < 2 or not s.startswith(("R", "FI", "Fr", "Fc", "G", "Pb", "Mb", "M")):
        return name
    if s.startswith("R"):
        return sub("F", s) + prime
    if s.startswith(("FI", "Fr", "Fc")):
        return sub("F", s[1:]) + prime
    return sub(s[0], s[1:]) + prime


def vector_symbols(document) -> dict:
    """{(position label, "velocity" | "acceleration"): [(tail, head, kind, value, symbol)]}
    from the graphical method's document (stages/graphical.py): the quantity each segment
    of its polygons stands for, as the report's tables name it (segment aa4 is v_A4A3,
    n4'a4' is a^t_A4O3), in the order of its equations."""
    out: dict = {}
    for pos in getattr(document, "positions", ()) or ():
        for kind in ("velocity", "acceleration"):
            out[(str(pos.label), kind)] = [
                (t.tail, t.head, t.kind, complex(t.value), t.symbol)
                for eq in getattr(getattr(pos, kind), "equations", ())
                for t in list(eq.left) + list(eq.right) if t.tail and t.head and t.tail != t.head]
    return out


def _image_point(name: str) -> str | None:
    """The mechanism point of a polygon image: "a4" → "A4", "s6'" → "S6", "p(P)'" → "P";
    None for the pole or an intermediate point (n4', k')."""
    name = name.rstrip("'")
    if name.startswith("p(") and name.endswith(")"):
        return name[2:-1]
    if not name or name == "p" or name[0] in "nk" or not name[0].isalpha():
        return None
    return name.upper()


def symbol_of(vec, terms, vectors=()) -> str | None:
    """The symbol of polygon vector ``vec`` among the graphical method's ``terms`` (see
    :func:`vector_symbols`): the term of the same segment, the intermediate points of a
    normal + tangential pair matched through the tangential vector that ends at the same
    point (the two constructions name them apart: n4b' and nb'); else an absolute vector
    from the pole is the point's own (a_A4), else None (the segment's name is written)."""
    named = {p for tail, head, *_ in terms for p in (tail, head)}
    alias = {}
    for v in vectors:
        if v.role == "tangential" and v.tail not in named:
            found = [tail for tail, head, kind, _, _ in terms
                     if kind == "tangential" and head == v.head and tail not in
                     {w.tail for w in vectors}]
            if len(found) == 1:
                alias[v.tail] = found[0]
    key = (alias.get(vec.tail, vec.tail), alias.get(vec.head, vec.head))
    for tail, head, _, _, symbol in terms:
        if (tail, head) == key:
            return symbol
    # a pair normal + tangential through an intermediate point the graphical method does not
    # name: it left out the zero tangential term (α = 0 there) and drew the normal straight
    # to the point (p'd' is a^n_DO3), so the pair's normal is that term and its tangential
    # the same index with t (a^t_DO3, of zero length)
    if vec.role in ("normal", "tangential") and (vec.head if vec.role == "normal" else vec.tail) not in named:
        mid = vec.head if vec.role == "normal" else vec.tail
        first = [v for v in vectors if v.role == "normal" and v.head == mid]
        second = [v for v in vectors if v.role == "tangential" and v.tail == mid]
        if len(first) == 1 and len(second) == 1:
            ends = (first[0].tail, second[0].head)
            found = [symbol for tail, head, kind, _, symbol in terms
                     if (tail, head) == ends and kind == "normal" and symbol.startswith(("a^n_", "v^n_"))]
            if len(found) == 1:
                return found[0] if vec.role == "normal" else found[0].replace("^n_", "^t_", 1)
    point = _image_point(vec.head)
    if vec.role == "absolute" and vec.tail.rstrip("'") == "p" and point is not None:
        return ("a_" if vec.tail.endswith("'") else "v_") + point
    return None


def vector_text(symbol: str) -> str:
    """A velocity or acceleration symbol for a sheet text: "v_A4A3" → v with the subscript
    A4A3, "a^n_BO3" → a with the subscript BO3, then the superscript n (the sheet's text
    runs one after the other: the subscript next to its letter)."""
    head, _, index = symbol.partition("_")
    base, _, up = head.partition("^")
    text = sub(base, index) if index else base
    return sup(text, up) if up else text


def _value(x: float, ref: float) -> str:
    """A polygon's value by the table rule (render/fmt.py; :func:`_cell_number`): the
    decimals that give the polygon's largest value ``ref`` 4 significant digits, so a
    vector far shorter than the drawing's accuracy is written 0.002 m/s², not 0.001523
    (nor 0.00002167); the true minus sign. A power of ten (fmt.e) is not used here: the
    sheet font has no superscript minus or digits 0, 5–9."""
    if not ref > 0 or abs(x) <= 1e-9 * ref:
        return "0"
    return fmt.minus(fmt.f(x, fmt.column_decimals(ref), group=True))


def _items(pg: Polygon, symbols: list | None = None, sense: float = 1.0) -> list[str]:
    """The polygon's vectors as "symbol = value unit": a force by its name (F_R12), a
    velocity or acceleration by the quantity its segment stands for (v_A4A3 = … m/s; the
    segment's name, aa4, only where the graphical method names no quantity for it). The
    polygon's M_b (counter-clockwise positive) is written in the crank's sense of rotation,
    ``sense`` the sign of ω (:func:`crank_torque`); an inertia couple counter-clockwise
    positive."""
    unit = UNITS[pg.kind][2]
    symbols = symbols or []

    def name(v) -> str:
        if pg.kind == "force":
            return force_symbol(v.name)
        symbol = symbol_of(v, symbols, pg.vectors)
        return vector_text(symbol) if symbol else v.name

    moments = {key: sense * value if key == "Mb" else value for key, value in pg.moments.items()}

    def signed(v) -> float:
        # P_b = M_b/l signed as M_b, positive in the crank's sense of rotation as the
        # report's tables and M_b curve; every other vector by its length
        if pg.kind == "force" and v.name == "Pb" and "Mb" in moments:
            return float(np.copysign(abs(v.value), moments["Mb"]))
        return abs(v.value)

    ref = max([abs(v.value) for v in pg.vectors], default=0.0)
    # a relative vector that is zero by construction (two points of a link in translation:
    # v_S6F, a_S6F^n of the ram) is no result: not listed
    def value(v) -> str:
        # a weight G_i is given: one text on every cell of the sheet, not decided by the
        # polygon's largest force (the shaper's "G2 = 500 N" at position 4 and "500.0 N" at
        # position 10): from its own value by the sheets' rule, 4 significant digits,
        # trailing zeros dropped (117.72 N → 117.7 N; the report's chains may carry more)
        if pg.kind == "force" and re.fullmatch(r"G\d+", str(v.name)) and v.value:
            return fmt.minus(fmt.exact(abs(v.value), 4))
        return _value(signed(v), ref)

    out = [f"{name(v)} = {value(v)} {unit}" for v in pg.vectors
           if not (v.value == 0 and v.role in ("relative", "normal", "tangential"))]
    ref = max([abs(m) for m in moments.values()], default=0.0)
    out += [f"{force_symbol(key)} = {_value(value, ref)} N·m" for key, value in moments.items()]
    return out


def _cell(s: Sheet, pg: Polygon, cell, title: str, lab: dict, symbols: list | None = None,
          sense: float = 1.0) -> float:
    """One polygon with its heading, scale and the list of its vectors (M_b and P_b in the
    crank's sense of rotation: ``sense`` is the sign of ω); returns μ."""
    cx0, cy0, cx1, cy1 = cell
    w = cx1 - cx0
    s.polyline([cx0 + 1j * cy0, cx1 + 1j * cy0, cx1 + 1j * cy1, cx0 + 1j * cy1], "CONSTRUCTION",
               closed=True, weight=0.13)
    head_h = fit_height(title, w - 4.0, 3.5)
    s.text((cx0 + cx1) / 2 + 1j * (cy1 - 1.5), title, head_h, "TEXT", "center", "top")
    items = _items(pg, symbols, sense)
    ncol = 3 if w > 110 else 2
    nrow = int(np.ceil(len(items) / ncol))
    line = 3.4
    list_h = nrow * line + 1.0
    colw = (w - 4.0) / ncol
    for j, text in enumerate(items):
        c, row = divmod(j, nrow)
        s.text(cx0 + 2.0 + c * colw + 1j * (cy0 + 1.0 + list_h - row * line), text,
               min(2.5, fit_height(text, colw - 1.5, 2.5, smallest=1.8)), "TEXT", "left", "top")
    sym, unit, _ = UNITS[pg.kind]
    pbox = (cx0 + 8.0, cy0 + list_h + 5.0, cx1 - 8.0, cy1 - 12.0)
    if not pg.vectors:
        s.text((cx0 + cx1) / 2 + 1j * (pbox[1] + pbox[3]) / 2, lab["noforce"], 2.5, "TEXT",
               "center", "middle")
        return 1.0
    pts = np.array(list(pg.points.values()))
    note = _flat_note(pts, lab)
    if note is not None:          # the note under the scale, the polygon below it
        # on a narrow cell in two lines, broken after its colon (lockbeam en: one line ran
        # into the next cell's note)
        lines = [note]
        if text_width(note, 2.5) > w - 4.0:
            for sep in (": ", chr(0xFF1A)):      # an ASCII or a full-width colon
                if sep in note:
                    head, tail = note.split(sep, 1)
                    lines = [head + sep.strip(), tail]
                    break
        for k, line_text in enumerate(lines):
            s.text((cx0 + cx1) / 2 + 1j * (cy1 - 2.0 - head_h - 1.0 - 2.5 - 1.5 - 3.0 * k),
                   line_text, fit_height(line_text, w - 4.0, 2.5, smallest=1.5), "TEXT",
                   "center", "top")
        pbox = (pbox[0], pbox[1], pbox[2], pbox[3] - 4.0 - 5.0 * (len(lines) - 1))
    extent = max(np.ptp(pts.real) / (pbox[2] - pbox[0]), np.ptp(pts.imag) / (pbox[3] - pbox[1]),
                 1e-12)
    mu = fill_scale(extent, 1.0)
    text = f"{sym} = {fmt.exact(mu)} {unit}"
    s.text((cx0 + cx1) / 2 + 1j * (cy1 - 2.0 - head_h - 1.0), text, 2.5, "TEXT", "center", "top")
    # labels keep clear of the heading and scale above and the vector list below
    _draw_polygon(s, pg, mu, pbox, [(cx0, pbox[3] + 2.0, cx1, cy1), (cx0, cy0, cx1, pbox[1] - 2.0)])
    return mu


#: A polygon narrower than this fraction of its length is called nearly flat on its cell
#: (render/graphical_report.FLAT, the report's rule for its force polygons).
FLAT = 0.08


def _flat_note(pts, lab: dict) -> str | None:
    """The note of a polygon whose vectors are (almost) parallel, so that it closes on a
    line (the lock-beam's velocity polygons where the crank lies on the frame line: the
    sliding velocity and ω5 are zero, every velocity is square to the bar): its width
    across its length as a share of the length, or None for a polygon that is not flat."""
    if len(pts) < 3:
        return None
    length, width = spread(pts)
    if not length > 0 or width >= FLAT * length:
        return None
    if width < 1e-6 * length:
        return lab["flat0"]
    return lab["flat"].format(w=fmt.percent(100.0 * width / length))


# a polygon's label is kept within this of its point [mm] (else it goes on a leader): one
# farther out, across the vectors, is read as another point's ("s4′" 7 mm from its point,
# beyond the vector b′f′)
POLYGON_REACH = 4.5


def _draw_polygon(s: Sheet, pg: Polygon, mu: float, box, keep_out=()) -> None:
    """The polygon centred in ``box`` at μ (units per paper mm), labels kept clear of each
    other, of the vectors and of the ``keep_out`` boxes."""
    pts = np.array(list(pg.points.values())) / mu
    bx0, by0, bx1, by1 = box
    centre = (pts.real.min() + pts.real.max()) / 2 + 1j * (pts.imag.min() + pts.imag.max()) / 2
    v = s.view((bx0 + bx1) / 2 + 1j * (by0 + by1) / 2 - centre, 1.0 / mu)
    # every label inside the cell (the box and the keep-out strips round it): a leader from
    # a short vector at the polygon's top edge went up into the cell above, onto its vector
    # list (the press at position 5: F_R65 over "F_R63 = 2079 N")
    cell = [box, *keep_out]
    placer = LabelPlacer(s, area=(min(b[0] for b in cell), min(b[1] for b in cell),
                                  max(b[2] for b in cell), max(b[3] for b in cell)))
    for b in keep_out:
        placer.block_box(b)
    for vec in pg.vectors:
        a, b = pg.points[vec.tail], pg.points[vec.head]
        if abs(b - a) / mu < 1e-6:
            continue
        weight = 0.25 if vec.role in ("absolute", "internal") else None
        v.arrow(a, b, "VECTORS", head=2.5, weight=weight)
        placer.block_segment(v.p(a), v.p(b))
    for z in pg.points.values():
        s.circle(v.p(z), 0.4, "VECTORS", 0.25)
        placer.block(v.p(z), 0.8)
    if pg.kind == "force":
        for vec in pg.vectors:
            mid = (pg.points[vec.tail] + pg.points[vec.head]) / 2
            text = force_symbol(vec.name)
            # beside its vector where there is room, else on a leader (the subscripted names,
            # F_R12, are longer than R12 and crowd a small polygon)
            if placer.place(v.p(mid), text, 2.5, prefer=1j * vec.value, gap=1.2, crowded=False,
                            apart=True, reach=POLYGON_REACH) is None:
                placer.leader(v.p(mid), text, 2.5, prefer=1j * vec.value, lengths=(4.0, 6.0, 9.0, 13.0, 18.0),
                              avoid_lines=True, both_sides=True)
        placer.place(v.p(0j), "o", 2.5, prefer=-1 - 1j, gap=1.2, apart=True, last_leader=True,
                     reach=POLYGON_REACH)
        return
    values = list(pg.points.values())
    centroid = np.mean(values)
    done = {}
    for name, z in pg.points.items():
        key = (round(z.real / mu, 1), round(z.imag / mu, 1))
        text = name if key not in done else None
        if text is None:           # coincident points share one label: "a', b'"
            continue
        same = [n for n, zz in pg.points.items()
                if (round(zz.real / mu, 1), round(zz.imag / mu, 1)) == key]
        # an intermediate point (n4d', k') on a named one: a zero component, which the
        # graphical method leaves out (its point is not named in the report either)
        named = [n for n in same if _image_point(n) is not None or n.rstrip("'") == "p"]
        same = named or same
        done[key] = True
        d = z - centroid
        # (1.1 mm from the other labels: a′ beside n3s3′ read as one)
        placer.place(v.p(z), ", ".join(same), 2.5, prefer=d if abs(d) > 1e-9 * mu else 1j,
                     gap=1.2, apart=True, last_leader=True, reach=POLYGON_REACH)


# ------------------------------------------------------------------ the mechanism

def _joint_points(mech) -> set:
    return {j.point for js in mech.joints.values() for j in js}


def _link_outline(zs: list) -> list:
    """The points to join for one link: the two farthest apart when they are in line,
    else all of them around their centre (a ternary link)."""
    zs = list(dict.fromkeys(complex(z) for z in zs))
    if len(zs) <= 2:
        return zs
    pairs = [(abs(a - b), a, b) for a in zs for b in zs]
    _, a, b = max(pairs, key=lambda t: t[0])
    u = (b - a) / abs(b - a)
    if all(abs((np.conj(u) * (z - a)).imag) < 1e-6 * abs(b - a) for z in zs):
        return [a, b]
    c = np.mean(zs)
    return sorted(zs, key=lambda z: np.angle(z - c)) + [sorted(zs, key=lambda z: np.angle(z - c))[0]]


def _block_dimension(placer: LabelPlacer, d: Dimension) -> None:
    """Mark a dimension's lines and text as obstacles for the labels."""
    if abs(d.p1 - d.p0) < 1e-9:
        return
    lines, _arrows, text, pos, ang = dimension_geometry(d)
    for a, b in lines:
        placer.block_segment(a, b, 1.0)
    u = np.exp(1j * ang)
    mid = pos + 1j * u * d.height / 2
    half = text_width(text, d.height) / 2 + 0.5
    for t in np.linspace(-half, half, max(2, int(2 * half / 1.5) + 1)):
        placer.block(mid + u * t, d.height / 2 + 0.3)


def _radius_angle(s: Sheet, placer: LabelPlacer, v, centre: complex, radius: float) -> float:
    """The direction [rad, model] of a radius dimension about ``centre`` whose text (outside
    the circle, render/sheet.py dimension_geometry) covers the fewest points of the lines
    drawn so far; −135° (the old place) when several tie."""
    pts = placer._drawn_points()
    best = None
    for k in range(24):
        ang = -0.75 * np.pi + k * np.pi / 12
        d = Dimension(v.p(centre), v.p(centre + radius * np.exp(1j * ang)), 0.0, radius,
                      kind="radius")
        _lines, _arrows, text, pos, tang = dimension_geometry(d)
        w = text_width(text, d.height)
        local = (pts - pos) * np.exp(-1j * tang)      # the text's frame: x along, y up
        hits = np.count_nonzero((np.abs(local.real) < w / 2 + 0.5) & (local.imag > -0.5)
                                & (local.imag < d.height + 0.5))
        if best is None or hits < best[0]:
            best = (hits, ang)
    return float(best[1])


def _clear_offset(placer: LabelPlacer, v, a: complex, b: complex, offsets, measurement: float,
                  area) -> float:
    """The offset [paper mm] of an aligned dimension a–b (model) among ``offsets`` (in the
    order of preference) whose text covers the fewest points of the lines drawn so far and
    stays inside ``area``: the skeleton's frame and stroke dimensions set clear of the fan of
    the other positions' links (GB/T 4458.4: a dimension's text never crossed by a line)."""
    pts = placer._drawn_points()
    best = None
    for rank, off in enumerate(offsets):
        d = Dimension(v.p(a), v.p(b), float(off), measurement)
        _lines, _arrows, text, pos, tang = dimension_geometry(d)
        w = text_width(text, d.height)
        u = np.exp(1j * tang)
        corners = [pos + x * u * (w / 2 + 0.5) + y * 1j * u for x in (-1, 1) for y in (-0.5, d.height + 0.5)]
        if not all(area[0] <= c.real <= area[2] and area[1] <= c.imag <= area[3] for c in corners):
            continue
        local = (pts - pos) * np.conj(u)              # the text's frame: x along, y up
        hits = np.count_nonzero((np.abs(local.real) < w / 2 + 0.5) & (local.imag > -0.5)
                                & (local.imag < d.height + 0.5))
        if best is None or (hits, rank) < best[:2]:
            best = (hits, rank, float(off))
    return offsets[0] if best is None else best[2]


def _name(model, link: str, lang: str) -> str | None:
    from ..stages.linkage import link_name

    name = link_name(getattr(model, "names", None), link, lang)
    return None if name is None else sheet_names(name)      # "导杆 O3B": O₃B


def _fixed_guides(P: dict, sliders: list, mm: float) -> list:
    """(slider link, point, guide point [mm], unit direction, t0, t1) of every slider on a
    fixed guide: the centre line runs a quarter of the travel beyond each end."""
    out = []
    for slider, point, guide, gpoint in sliders:
        if isinstance(guide, str):
            continue
        u = np.exp(1j * guide)
        t = (np.conj(u) * (P[point] - gpoint * mm)).real
        span = max(np.ptp(t), 1.0)
        out.append((slider, point, gpoint * mm, u, t.min() - 0.25 * span, t.max() + 0.25 * span))
    return out


def _pivot_arcs(members: dict, mech, crank, grid: dict, joints: set) -> list:
    """(pivot, radius, start, end) [mm, rad] of the arcs traced by the joints of the links
    turning about a frame point (the crank's circle is drawn apart)."""
    out = []
    for link, names in members.items():
        if link == crank.link:
            continue
        for pivot in (n for n in names if n in mech.frame_points):
            o = grid[pivot][0]
            for name in names:
                if name == pivot or name not in joints or name not in grid:
                    continue
                d = grid[name] - o
                radius = np.abs(d)
                if radius.max() < 1e-9 or np.ptp(radius) > 1e-9 * radius.max():
                    continue           # not at a fixed distance (a slider on the link)
                base = np.mean(d / radius)
                base = base / abs(base) if abs(base) > 1e-9 else 1.0
                rel = np.angle(d / radius * np.conj(base))
                lo, hi = float(rel.min()), float(rel.max())
                if hi - lo > 2 * np.pi - 0.2:
                    continue           # a full turn: a crank of its own
                a0 = float(np.angle(base))
                out.append((o, float(radius[0]), a0 + lo - 0.05, a0 + hi + 0.05))
    return out


def _top_room(legend: str) -> float:
    """The mechanism view's heading (and legend line) above the drawing [mm]."""
    return 16.0 + (7.0 if legend else 0.0)


def _mechanism_extent(model, k, lang: str) -> dict:
    """The points, guides and arcs of the mechanism view and its padded extent (``lo``,
    ``hi`` in model mm) with the link names of its legend: what fixes the view's scale."""
    from ..stages.linkage import link_members

    mech = model.mechanism
    members, sliders = link_members(mech)
    n = k.grid_size
    mm = 1e3
    P = {name: np.asarray(z[n:]) * mm for name, z in k.points.items()}
    grid = {name: np.asarray(z[:n]) * mm for name, z in k.points.items()}
    joints = _joint_points(mech) | set(mech.frame_points)
    coms = {b.com for b in model.bodies if b.com is not None} - joints
    # points that only carry a load (a cutting-force line) are not drawn
    # a point the brief asks about (analysis.points: the textbook's D) is drawn and named
    # even where a load acts on it
    asked = (set(getattr(k, "point_vel", None) or {}) & set(P)) - joints - coms
    loads = {r.point for r in model.resistances} - joints - coms - asked
    drawn = {name: z for name, z in P.items() if name not in coms | loads}
    allpts = np.concatenate([z for z in drawn.values()])
    guides = _fixed_guides(P, sliders, mm)
    for _, _, g0, u, t0, t1 in guides:
        allpts = np.concatenate([allpts, [g0 + u * t0, g0 + u * t1]])
    arcs = _pivot_arcs(members, mech, model.crank, grid, joints)
    for o, r, a0, a1 in arcs:
        allpts = np.concatenate([allpts, o + r * np.exp(1j * np.linspace(a0, a1, 9))])
    lo = complex(allpts.real.min(), allpts.imag.min())
    hi = complex(allpts.real.max(), allpts.imag.max())
    pad = 0.08 * max(hi.real - lo.real, hi.imag - lo.imag) + 20.0
    lo, hi = lo - pad * (1 + 1j), hi + pad * (1 + 1j)
    named = [(link, _name(model, link, lang)) for link in sorted(members.keys() | {
        sl for sl, *_ in sliders}, key=lambda x: (len(x), x))]
    legend = "  ".join(f"{link} {nm}" for link, nm in named if nm)
    return {"P": P, "grid": grid, "joints": joints, "coms": coms, "asked": asked,
            "drawn": drawn, "guides": guides, "arcs": arcs, "allpts": allpts, "lo": lo,
            "hi": hi, "named": named, "legend": legend}


def _mechanism(s: Sheet, model, k, lab: dict, box, chosen: list[str], lang: str) -> float:
    from ..stages.linkage import link_members

    mech = model.mechanism
    members, sliders = link_members(mech)
    n = k.grid_size
    labels = list(k.positions.labels)
    mm = 1e3
    ext = _mechanism_extent(model, k, lang)
    P, grid, joints, coms, asked = ext["P"], ext["grid"], ext["joints"], ext["coms"], ext["asked"]
    drawn, guides, arcs, allpts = ext["drawn"], ext["guides"], ext["arcs"], ext["allpts"]
    lo, hi, named, legend = ext["lo"], ext["hi"], ext["named"], ext["legend"]
    bx0, by0, bx1, by1 = box
    top_room = _top_room(legend)
    avail = (bx1 - bx0) + 1j * (by1 - by0 - top_room)
    n_len = length_scale(hi - lo, avail, enlarge=True)
    sc = 1.0 / n_len
    centre = (lo + hi) / 2
    v = s.view((bx0 + bx1) / 2 + 1j * ((by0 + by1 - top_room + 16.0) / 2 - 6) - sc * centre, sc)
    title = f"{lab['mechanism']}  {scale_text(n_len)}  ({sub('μ', 'L')} = {fmt.exact(n_len / 1000)} m/mm)"
    heading(s, (bx0 + bx1) / 2 + 1j * (by1 - 6), title, min(5.0, fit_height(title, bx1 - bx0, 5.0)))
    placer = LabelPlacer(s)
    if legend:
        text = lab["links"] + legend
        h = min(3.0, fit_height(text, bx1 - bx0, 3.0))
        placer.text((bx0 + bx1) / 2 + 1j * (by1 - 14.0), text, h, "center", "middle")
    crank = model.crank
    body_link = dict((b.com, b.link) for b in model.bodies if b.com is not None)
    v.circle(P[crank.pivot][0], crank.length * mm, "CENTER")
    for o, r, a0, a1 in arcs:
        v.arc(o, r, a0, a1, "CENTER")
    for _, _, g0, u, t0, t1 in guides:
        v.line(g0 + u * t0, g0 + u * t1, "CENTER")
        placer.block_segment(v.p(g0 + u * t0), v.p(g0 + u * t1), 1.0)
    out = model.output
    first_link = len(s.entities)
    order = [i for i in range(len(labels)) if labels[i] not in chosen] + \
            [labels.index(c) for c in chosen if c in labels]
    for i in order:
        bold = labels[i] in chosen
        layer, w = ("OUTLINE", None) if bold else ("CONSTRUCTION", 0.25)
        for link, names in members.items():
            zs = [P[p][i] for p in names if p in drawn]
            outline = _link_outline(zs)
            if len(outline) >= 2:
                v.polyline(np.array(outline), layer, weight=w)
                if bold:
                    for a, b in zip(outline[:-1], outline[1:]):
                        placer.block_segment(v.p(a), v.p(b), 1.5)
        if bold:
            for slider, point, guide, _ in sliders:
                ang = guide if not isinstance(guide, str) else float(k.link_angle[guide][n + i])
                slider_block(v, P[point][i], ang, 10.0, 5.0)
                placer.block(v.p(P[point][i]), 5.0)
            for name in sorted(joints - set(mech.frame_points)):
                if name in P:
                    pin(v, P[name][i])
                    placer.block(v.p(P[name][i]), 1.5)
            for name in sorted(coms):
                if name in P:
                    s.circle(v.p(P[name][i]), 0.8, "OUTLINE", 0.25)
                    # tied to its link by a thin line to the link's nearest point drawn (the
                    # ram's S6, 200 mm ahead of and 50 mm above F, stood alone as a stray pin:
                    # page review 45, shaper_lengths)
                    ends = [P[p][i] for p in members.get(body_link.get(name), ()) if p in drawn]
                    if ends:
                        near = min(ends, key=lambda z: abs(z - P[name][i]))
                        if abs(near - P[name][i]) > 1e-9:
                            v.polyline(np.array([near, P[name][i]]), "CONSTRUCTION", weight=0.25)
    # the links of the other positions (thin) are broken under a pivot's name and a
    # position's number (GB/T 4457.4), which stand at their points
    placer.mark_breakable(first_link)
    tip = P[crank.tip]
    piv = P[crank.pivot][0]
    n_before = len(s.entities)
    # Dimensions: the crank, the frame, the output's stroke, each fixed guide's distance
    # from the first frame point off it.
    # the crank's radius where its text, outside the circle, crosses the fewest lines drawn
    v.dimension(piv, piv + crank.length * mm * np.exp(1j * _radius_angle(s, placer, v, piv, crank.length * mm)),
                0.0, kind="radius", measurement=crank.length * mm)
    # the frame's and the stroke's dimension at the offset, on either side, where their text
    # is crossed by the fewest lines (the links of the other positions fan out across them)
    area = (bx0, by0, bx1, by1 - top_room)
    frames = list(mech.frame_points.values())
    if len(frames) >= 2:
        a, b = frames[0] * mm, frames[1] * mm
        off = _clear_offset(placer, v, a, b, (12.0, -12.0, 20.0, -20.0, 28.0, -28.0), abs(b - a), area)
        v.dimension(a, b, off, measurement=abs(b - a))
    if out.kind == "point" and out.name in P:
        j = int(np.argmax(np.abs(k.s[n:])))
        a, b = P[out.name][0], P[out.name][j]
        if abs(b - a) > 1e-9:
            off = _clear_offset(placer, v, a, b, (-14.0, 14.0, -22.0, 22.0, -30.0, 30.0), k.stroke * mm,
                                area)
            v.dimension(a, b, off, measurement=k.stroke * mm)
    for _, _, g0, u, t0, t1 in guides:
        # from the first frame point off the guide line to the line
        off = [(f * mm, g0 + u * (np.conj(u) * (f * mm - g0)).real) for f in frames]
        off = [(f, foot) for f, foot in off if abs(foot - f) >= 1e-6]
        if off:
            f0, foot = off[0]
            dist = abs(foot - f0)
            # beside the drawing, on the side of the guide's direction nearer to f0
            proj = (np.conj(u) * (allpts - f0)).real
            edge = min((proj.max(), 1.0), (proj.min(), -1.0), key=lambda e: abs(e[0]))
            shift = edge[0] * sc + edge[1] * 6.0           # paper mm along u
            side = (np.conj((foot - f0) / dist) * u).imag  # +1: u is to the left of f0 → foot
            v.dimension(f0, foot, float(shift * np.sign(side)), measurement=dist)
    for e in s.entities[n_before:]:          # labels keep clear of the dimensions
        if isinstance(e, Dimension):
            _block_dimension(placer, e)
    for name, z in mech.frame_points.items():
        ground(v, z * mm, 6.0)
    for name, z in mech.frame_points.items():
        # beside its pivot, the thin links of the other positions broken under it; on a
        # leader only where even that leaves no room
        if placer.place_breaking(v.p(z * mm), sheet_point(name), 3.5, prefer=1 + 0.3j,
                                 gaps=(1.5, 2.5, 3.5, 4.5)) is None:
            placer.block(v.p(z * mm), 4.0)
            placer.place(v.p(z * mm), sheet_point(name), 3.5, prefer=1 + 0.3j, gap=2.5, leader=True)
        placer.block(v.p(z * mm), 2.0)
    for i in range(len(labels)):
        u = (tip[i] - piv) / abs(tip[i] - piv)
        bold = labels[i] in chosen            # clear of the slider block drawn there
        # a position's number in a circle (told from the links' numbers), beside its crank
        # pin, outside the crank circle where it can be
        if placer.place_breaking(v.p(tip[i]), labels[i], 3.5 if bold else 2.5, prefer=u, circled=True,
                                 gaps=(1.0, 2.0, 3.2, 4.5, 6.0, 8.0),
                                 balloon=(10.0, 12.5, 15.0, 18.0, 22.0)) is None:
            placer.place(v.p(tip[i]), labels[i], 3.5 if bold else 2.5, prefer=u,
                         gap=5.5 if bold and sliders else 1.5, apart=True, last_leader=True)
    if chosen and chosen[0] in labels:
        i0 = labels.index(chosen[0])
        mid = np.mean([P[nm][i0] for nm in drawn])
        for name in sorted((joints - set(mech.frame_points)) | asked | coms):
            if name in P:
                d = P[name][i0] - mid
                if placer.place_breaking(v.p(P[name][i0]), sheet_point(name), 3.5,
                                         prefer=d if abs(d) > 1e-9 else 1j,
                                         gaps=(1.5, 2.5, 3.5, 4.5, 6.0, 8.0)) is None:
                    placer.place(v.p(P[name][i0]), sheet_point(name), 3.5, prefer=d if abs(d) > 1e-9 else 1j,
                                 gap=2.0, leader=True)
        # the link numbers at the first chosen position: beside each link (a third of the
        # way from its frame pivot, if it has one), a slider's number beside its block
        numbered = set()
        for link, names in members.items():
            outline = _link_outline([P[p][i0] for p in names if p in drawn])
            if len(outline) < 2:
                continue
            a, b = outline[0], outline[1]
            fixed = [P[p][i0] for p in names if p in mech.frame_points]
            if fixed and abs(b - fixed[0]) < abs(a - fixed[0]):
                a, b = b, a
            d = (b - a) / abs(b - a) if abs(b - a) > 1e-9 else 1.0
            at = a + (b - a) * (0.3 if fixed else 0.5)
            if placer.place_breaking(v.p(at), link, 3.5, prefer=1j * d, gaps=(1.5, 2.5, 3.5, 4.5, 6.0, 8.0)) is None:
                placer.place(v.p(at), link, 3.5, prefer=1j * d, gap=1.5, leader=True)
            numbered.add(link)
        for slider, point, guide, _ in sliders:
            if slider not in numbered:
                ang = guide if not isinstance(guide, str) else float(k.link_angle[guide][n + i0])
                if placer.place_breaking(v.p(P[point][i0]), slider, 3.5, prefer=1j * np.exp(1j * ang),
                                         gaps=(4.0, 5.0, 6.0, 8.0)) is None:
                    placer.place(v.p(P[point][i0]), slider, 3.5, prefer=1j * np.exp(1j * ang), gap=4.0,
                                 leader=True)
    for slider, point, g0, u, t0, t1 in guides:
        nm = _name(model, slider, lang)
        text = lab["guide"].format(n=nm) if nm else lab["guide_plain"]
        end = g0 + u * t0
        placer.place(v.p(end), text, 3.0, prefer=-u + 0.6j * u, gap=1.5)
    return n_len


# ------------------------------------------------------------------ table and curves

def _moving_links(model, k) -> list[str]:
    """Links whose ω varies (the crank and translating sliders left out), in order. A
    slider on a turning guide turns with its guide: the guide's number is written (ω4 of
    the shaper's guide bar 4, as the report writes it, not ω3 of its slider 3)."""
    from ..stages.linkage import link_members

    out = []
    n = k.grid_size
    _, sliders = link_members(model.mechanism)
    blocks = {slider for slider, *_ in sliders}
    for g in model.mechanism.groups:
        for link in sorted(g.links, key=lambda x: x in blocks):
            if link in out or link == model.crank.link or link not in k.link_omega:
                continue
            w = np.asarray(k.link_omega[link][:n])
            if np.ptp(w) > 1e-12 and not any(np.array_equal(k.link_omega[o], k.link_omega[link])
                                              for o in out):
                out.append(link)
    return out[:4]


def _output_units(k) -> tuple[float, str, str, str]:
    if k.output_unit == "m":
        return 1e3, "mm", "m/s", "m/s²"
    return DEG, "°", "rad/s", "rad/s²"


ROW_H = 6.5
#: the table's largest row height [mm], where the mechanism view leaves the left column's
#: height unused
ROW_H_MAX = 9.0
#: how far the left column may widen into the polygons' column [mm] for a mechanism wider
#: than tall (its view limited by the column's width): on a sheet of kinematic polygons
#: only (two rows of tall cells); not on one with force polygons (narrower cells, longer
#: lists; shaper_lengths widened to 1:2.5 had its O3 label crossed by a line)
WIDEN = 70.0
WIDEN_FORCES = 0.0
#: the left column's right edge by default [mm from the sheet's left edge]
LEFT_RIGHT = 300.0


def _table_height(k, rh: float = ROW_H) -> float:
    """Heading plus a head row and one row per position [mm]."""
    return 9.0 + rh * (len(k.positions.labels) + 1)


def _left_column(model, k, lang: str, inner, widen: float) -> tuple[float, float]:
    """The left column's right edge and the table's row height: a mechanism view limited by
    the column's width (a wide mechanism: the lock-beam feed, the six-bar, the crank-rocker)
    left most of the column's height empty (review39: the lock-beam sheet's left column
    60 % empty). The column widens (by at most ``widen`` mm, in 5 mm steps) where that
    draws the mechanism at the next larger standard scale, and the table's rows grow (up
    to :data:`ROW_H_MAX`) into half of the height the view then leaves unused."""
    x0, y0, x1, y1 = inner
    ext = _mechanism_extent(model, k, lang)
    extent = ext["hi"] - ext["lo"]
    top_room = _top_room(ext["legend"])

    def scale(right: float, rh: float) -> tuple[float, float]:
        height = (y1 - 6) - (y0 + 8 + _table_height(k, rh) + 10.0) - top_room
        return length_scale(extent, (right - x0 - 8) + 1j * height, enlarge=True), height

    base, _ = scale(LEFT_RIGHT, ROW_H)
    right = LEFT_RIGHT
    for extra in np.arange(5.0, widen + 1e-9, 5.0):
        if scale(LEFT_RIGHT + extra, ROW_H)[0] < base:
            right = LEFT_RIGHT + float(extra)
            break
    n_len, height = scale(right, ROW_H)
    rows = len(k.positions.labels) + 1
    spare = height - extent.imag / n_len
    rh = min(ROW_H_MAX, ROW_H + max(spare, 0.0) * 0.5 / rows)
    if scale(right, rh)[0] != n_len:          # the view keeps its scale
        rh = ROW_H
    return right, rh


def _cell_number(x: float, column, decimals: int | None = None) -> str:
    """A table entry by the number rule (render/fmt.py): the decimals that give the
    column's largest value 4 significant digits, as a table keeps fixed decimals (or the
    column's ``decimals``), so a value near zero (the die-cutter's platen at its top) is
    written 0.0000, not 0.000005898; the true minus sign."""
    if decimals is None:
        peak = float(np.max(np.abs(column)))
        decimals = fmt.column_decimals(peak)
    return fmt.minus(fmt.f(x, decimals, group=True))


def _sense(model) -> float:
    """+1 for a crank turning counter-clockwise, −1 for one turning clockwise."""
    return 1.0 if float(model.crank.omega) >= 0 else -1.0


def crank_torque(forces) -> np.ndarray:
    """The balancing torque positive in the crank's sense of rotation, as the forces stage
    gives it and as the report's tables and M_b curve write it (review36 Top 13: the sheet
    wrote it counter-clockwise positive, the opposite sign for a clockwise crank). The
    table, the crank's force polygon cell (M_b and P_b = M_b/l, :func:`_items`) and the M_b
    curve with its mean M_d write this one convention, stated in the sheet's notes; the force
    polygons store M_b counter-clockwise positive, as the graphical method's moment
    equations sign it."""
    return np.asarray(forces.balancing_torque)


def _table(s: Sheet, model, k, forces, lab: dict, box, rh: float = ROW_H) -> None:
    n = k.grid_size
    bx0, by0, bx1, by1 = box
    fs, us, uv, ua = _output_units(k)
    # a rocking output's ω is the output's own column: not listed twice (review39: the crank
    # rocker's "v" and "ω3" columns were the same numbers)
    moving = _moving_links(model, k)
    links = [link for link in moving
             if k.output_unit == "m" or not np.allclose(k.link_omega[link], k.v)]
    sv, vv, av = ("s", "v", "a") if k.output_unit == "m" else ("ψ", "ω", "α")
    own = [link for link in moving if link not in links]
    if len(own) == 1:             # the rocker's columns name their link (ψ3, ω3, α3)
        sv, vv, av = (sub(x, str(own[0])) for x in (sv, vv, av))
    head = [lab["pos"], "φ (°)", f"{sv} ({us})", f"{vv} ({uv})", f"{av} ({ua})"] + \
        [sub("ω", str(link)) + " (rad/s)" for link in links] + ([sub("M", "b") + " (N·m)"] if forces is not None else [])
    columns = [k.v, k.a] + [k.link_omega[link] for link in links] + \
        ([crank_torque(forces)] if forces is not None else [])
    rows = []
    for j, label in enumerate(k.positions.labels):
        i = n + j
        rows.append([label, fmt.f(k.phase[i] * DEG, 1), _cell_number(k.s[i] * fs, k.s[:n] * fs, 2)]
                    + [_cell_number(c[i], c[:n]) for c in columns])
    # the text grows with the rows (2.5 mm in a 6.5 mm row, at most 3.5 mm)
    text_h = min(3.5, 2.5 * rh / ROW_H)
    weights = np.array([0.8, 1.0] + [1.2] * (len(head) - 2))
    widths = weights / weights.sum() * (bx1 - bx0)
    top = by1 - 7.0
    heading(s, (bx0 + bx1) / 2 + 1j * (top + 1.5), lab["table" if forces is not None else "table_kin"],
            5.0)
    table(s, bx0, top, widths, rows, head, row_h=rh, height=text_h, head_height=text_h, margin=1.0,
          outer=0.7, rule=0.7, inner=0.25)


def _leader_text_at(s: Sheet, first: int, area, m, e, swing: float, text: str, mid: float):
    """ΔW_max whose text is crossed by a line wherever it stands along its dimension (a swing
    shorter than its text, a grid line across it): the dimension and the start of a level
    text's shoulder on a slanted leader from the dimension line's middle (GB/T 4458.4), where
    no curve, bound or axis crosses the text and the fewest grid lines do (those are broken
    under it: :func:`break_lines`), the leader crossing the fewest lines, as near the middle
    of ΔE's bounds as may be; None if there is no such spot in the chart. The chart is drawn
    from ``s.entities[first]`` on."""
    w = text_width(text, 2.5) + 1.0
    chart_lines = [g for g in s.entities[first:] if not isinstance(g, (Text, Fill))]
    grid = [g for g in chart_lines if _grid_line(g, area)]
    firm = LabelPlacer(s)
    firm.absorb([g for g in chart_lines if not _grid_line(g, area)], 0.5)
    pts = firm.points
    every = np.concatenate([pts] + [sample_polyline([g.p0, g.p1], 0.5) for g in grid])
    # (the chart's lines only: the rest of the sheet is outside every candidate)

    def inside(z):
        return z[(z.real > area[0] - 1.0) & (z.real < area[2] + 1.0) & (z.imag > area[1] - 1.0)
                 & (z.imag < area[3] + 1.0)]

    pts, every = inside(pts), inside(every)
    best = None
    for x_at in np.arange(6.0, 355.0, 3.0):
        p0, p1 = m.p(x_at, float(e.min())), m.p(x_at, float(e.max()))
        tips = sum(int(np.count_nonzero(np.abs(every - q) < 1.5)) for q in (p0, p1))
        centre = (p0 + p1) / 2
        for length in (6.0, 9.0, 13.0, 18.0):
            for deg in (45.0, 135.0, -45.0, -135.0, 30.0, 150.0, -30.0, -150.0, 60.0, 120.0,
                        -60.0, -120.0):
                elbow = centre + length * np.exp(1j * np.radians(deg))
                x0, x1 = (elbow.real, elbow.real + w) if elbow.real >= centre.real else \
                    (elbow.real - w, elbow.real)
                box = (x0 - 0.5, elbow.imag - 0.5, x1 + 0.5, elbow.imag + DIM_GAP + 2.5 + 0.5)
                if not (box[0] >= area[0] and box[2] <= area[2] and box[1] >= area[1]
                        and box[3] <= area[3]) or firm.crossed(box, pts):
                    continue
                broken = sum(1 for g in grid if clip_segment(g.p0, g.p1, box) is not None)
                # (the leader and the shoulder not along a line: a bound's dashes under the text)
                end = complex(x1 if elbow.real >= centre.real else x0, elbow.imag)
                cost = (3.0 * broken + _near_segment(every, centre, elbow, 0.4, 0.0)
                        + _near_segment(every, elbow, end, 0.8, 0.0) + 0.3 * tips
                        + 0.05 * length + abs(x_at - mid) / 30.0)
                if best is None or cost < best[0]:
                    best = (cost, Dimension(p0, p1, 0.0, swing), elbow, box)
    if best is None:
        return None
    break_lines(s, best[3], grid)
    return best[1], best[2]


def _grid_line(g, area) -> bool:
    """Whether ``g`` is one of a chart's thin grid lines inside ``area`` (:func:`chart`)."""
    return (isinstance(g, Line) and g.layer == "CONSTRUCTION" and g.weight == GRID_WEIGHT
            and all(area[0] - 1e-6 <= p.real <= area[2] + 1e-6 and area[1] - 1e-6 <= p.imag <= area[3] + 1e-6
                    for p in (g.p0, g.p1)))


def _curves(s: Sheet, model, k, forces, fl, lab: dict, box) -> None:
    n = k.grid_size
    ph = np.append(k.phase[:n], TWO_PI) * DEG

    def closed(y):
        return np.append(y[:n], y[0])

    labels = list(k.positions.labels)
    pos_ph = k.phase[n:] * DEG
    regular = [j for j, sp in enumerate(k.positions.special) if not sp]
    bx0, by0, bx1, by1 = box
    left = bx0 + 6.0
    ticks = range(0, 361, 30)
    span = k.working_span * DEG
    fs, us, uv, ua = _output_units(k)
    heading(s, (left + bx1) / 2 + 1j * (by1 - 5), lab["curves"], 5.0)
    rot = "" if k.output_unit == "m" else "_rot"
    panels = [(k.s * fs, lab["s" + rot].format(u=us)), (k.v, lab["v" + rot].format(u=uv)),
              (k.a, lab["a" + rot].format(u=ua))]
    top = by1 - 14.0
    n_panels = 3 + (forces is not None) + (fl is not None)
    gaps = 3 * 15.0 + (forces is not None) * 24.0 + (fl is not None) * 26.0
    h = (top - by0 - gaps) / n_panels
    y = top
    for j, (yv, yl) in enumerate(panels):
        marks = [(pos_ph[q], yv[n + q], labels[q] if j == 0 else "") for q in regular]
        chart(s, (left, y - h, bx1, y), ph, [Series(closed(yv))], xlabel=lab["phase"] if j == 2 else "",
              ylabel=yl, xticks=ticks, shade=[(0, span)], marks=marks)
        y -= h + 15.0
    if forces is None:
        return
    y -= 9.0
    # M_b and its mean M_d in the crank's sense of rotation, as the table, the crank's force
    # polygon cell and the report (one sign convention on the sheet; the energy chart's works too)
    mb = crank_torque(forces)
    md_crank = fl.mean_torque if fl is not None else forces.mean_torque
    md = md_crank
    text = lab["md"] if fl is not None else lab["mean"]
    chart(s, (left, y - h, bx1, y), ph, [Series(closed(mb))], xlabel=lab["phase"],
          ylabel=lab["mb"], title=lab["mbt"], xticks=ticks, shade=[(0, span)],
          hlines=[(md, text.format(v=fmt.minus(fmt.sig(md))))],
          marks=[(pos_ph[q], mb[n + q], "") for q in regular])
    if fl is None:
        return
    y -= h + 26.0
    e = fl.energy
    phi = np.radians(ph)
    w_d = md_crank * phi
    w_r = w_d - np.append(e, e[0])        # ∫M_b dφ = M_d·φ − ΔE (exact, from the results)
    first = len(s.entities)
    m = chart(s, (left, y - h, bx1, y), ph,
              [Series(w_d, weight=0.35), Series(w_r, weight=0.35), Series(np.append(e, e[0]))],
              xlabel=lab["phase"], ylabel=lab["work"], title=lab["et"], xticks=ticks,
              hlines=[(float(e.min()), ""), (float(e.max()), "")])
    # ΔW_max between ΔE's bounds, at the phase nearest midway between them where no curve
    # or grid line crosses its text (a text too long for the swing goes above it, not onto
    # the φ ticks); then W_r and W_d clear of it
    placer = LabelPlacer(s, area=(left, y - h, bx1, y))
    drawn = placer._drawn_points()
    mid = 0.5 * (fl.phase_at_min + fl.phase_at_max) * DEG
    text = lab["dw"].format(v=fmt.sig(fl.max_energy_swing))
    best = None
    for x_at in np.arange(6.0, 355.0, 3.0):
        dim = Dimension(m.p(x_at, float(e.min())), m.p(x_at, float(e.max())), 0.0,
                        fl.max_energy_swing, text, height=2.5, outside=1)
        _lines, _arrows, txt, pos, ang = dimension_geometry(dim)
        u, w = np.exp(1j * ang), text_width(txt, 2.5)
        corners = [pos + a * u * (w / 2 + 0.5) + b * 1j * u for a in (-1, 1) for b in (-0.5, 3.0)]
        box = (min(c.real for c in corners), min(c.imag for c in corners),
               max(c.real for c in corners), max(c.imag for c in corners))
        # (and its arrowheads off the curves' crossings: the lines within 1.5 mm of a tip)
        tips = sum(int(np.count_nonzero(np.abs(drawn - q) < 1.5)) for q in (dim.p0, dim.p1))
        crossed = placer.crossed(box, drawn)
        cost = crossed + 0.3 * tips + abs(x_at - mid) / 360.0
        if best is None or cost < best[0]:
            best = (cost, dim, crossed)
    d = best[1]
    at = _leader_text_at(s, first, placer.area, m, e, fl.max_energy_swing, text, mid) if best[2] else None
    if at is not None:
        d = at[0]
    s.dimension(d.p0, d.p1, 0.0, d.measurement, text=text, height=2.5, outside=1,
                text_at=None if at is None else at[1])
    # W_r and W_d beside their curves where no line crosses them (the grid, the other curve,
    # ΔE's bounds, the ΔW_max dimension), tried along the curve from its end; else on a leader
    for ys, text, prefer in ((w_r, sub("W", "r"), 1j), (w_d, sub("W", "d"), -1j)):
        for frac in (0.85, 0.75, 0.65, 0.55, 0.45, 0.35, 0.95):
            j = int(frac * (len(ph) - 1))
            c = placer.spot(m.p(ph[j], ys[j]), text, 3.0, prefer, gap=1.0)
            if c is not None:
                placer.text(c, text, 3.0, "center", "middle")
                break
        else:
            j = int(0.85 * (len(ph) - 1))
            placer.leader(m.p(ph[j], ys[j]), text, 3.0, prefer, lengths=(6.0, 9.0, 13.0),
                          avoid_lines=True)
    s.text(m.p(ph[-1], e[0]) + (1.5 + 0j), "ΔE", 3.0, "TEXT", "left", "middle")

