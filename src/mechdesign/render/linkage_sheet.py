"""The shaper's A1 sheet (机构运动及动力分析图): the mechanism at every textbook position to
a length scale, velocity, acceleration and force polygons for two positions drawn to
their scales from the computed vectors, the ram's s, v, a curves, the M_b curve, the
flywheel energy curve with ΔW_max, a table of the positions and the title block.

:func:`polygons` builds the polygons as the graphical method constructs them (vector
equations of the relative-motion method, force equilibrium of each Assur group) from the
analytic results; the sheet draws exactly those vectors, so a teacher can measure them.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .sheet import (LabelPlacer, Series, Sheet, TitleInfo, chart, fit_height, format_number, frame,
                    ground, heading, length_scale, nice_scale, pin, scale_text, slider_block, table,
                    title_block_box)

DEG = 180.0 / np.pi

LABELS = {
    "zh": {"mechanism": "机构运动简图", "velocity": "位置 {p} 速度多边形", "acceleration": "位置 {p} 加速度多边形",
           "force56": "位置 {p} 杆组 5-6 力多边形", "force34": "位置 {p} 杆组 3-4 力多边形",
           "s": "刨头位移 s (mm)", "v": "刨头速度 v (m/s)", "a": "刨头加速度 a (m/s²)",
           "mb": "平衡力矩 Mb (N·m)", "dE": "动能增量 ΔE (J)", "work": "功 W、动能增量 ΔE (J)", "phase": "曲柄转角 φ (°)",
           "curves": "刨头运动线图", "mbt": "平衡力矩线图", "et": "飞轮能量线图",
           "md": "等效驱动力矩 Md = {v} N·m", "table": "各位置运动与力分析结果",
           "pos": "位置", "guide": "刨头导路", "stroke": "行程 H",
           "dw": "ΔWmax = {v} J", "jf": "飞轮转动惯量 JF = {v} kg·m²",
           "scales": "作图比例", "each": "μv、μa、μF 注在各多边形上方", "working": "工作行程", "return": "回程"},
    "en": {"mechanism": "Skeleton at the positions", "velocity": "Velocity polygon, position {p}",
           "acceleration": "Acceleration polygon, position {p}", "force56": "Force polygon, group 5-6, pos. {p}",
           "force34": "Force polygon, group 3-4, pos. {p}",
           "s": "ram displacement s (mm)", "v": "ram velocity v (m/s)", "a": "ram acceleration a (m/s²)",
           "mb": "balancing torque Mb (N·m)", "dE": "energy change ΔE (J)", "work": "work W, energy change ΔE (J)", "phase": "crank angle φ (°)",
           "curves": "Ram motion curves", "mbt": "Balancing torque", "et": "Flywheel energy",
           "md": "driving torque Md = {v} N·m", "table": "Results at the positions",
           "pos": "Pos.", "guide": "ram guide", "stroke": "stroke H",
           "dw": "ΔWmax = {v} J", "jf": "flywheel inertia JF = {v} kg·m²",
           "scales": "Drawing scales", "each": "μv, μa, μF above each polygon", "working": "working stroke", "return": "return stroke"},
}


@dataclass(frozen=True)
class Vector:
    """One vector of a polygon: from point ``tail`` to ``head`` (names as the graphical
    method writes them), value in SI units (complex)."""

    name: str          # e.g. "pa3", "a3a4", "R45"
    tail: str
    head: str
    value: complex


@dataclass(frozen=True)
class Polygon:
    kind: str                    # velocity | acceleration | force56 | force34 (Assur groups)
    position: str                # the position label
    points: dict                 # name → complex location in SI units, pole at 0
    vectors: tuple               # Vector, drawn in this order


def polygons(r: dict, label: str) -> list[Polygon]:
    """Velocity, acceleration and the two force polygons of the shaper at position ``label``."""
    k, motion, frc, p = r["kinematics"], r["motion"], r["forces"], r["params"]
    n = k.grid_size
    i = n + list(k.positions.labels).index(label)
    pos = {name: motion.points[name].pos[i] for name in ("O3", "A", "B", "F")}
    w4, al4 = motion.links["4"].omega[i], motion.links["4"].alpha[i]
    w5 = motion.links["5"].omega[i]
    rA = pos["A"] - pos["O3"]
    # Velocities: v_A3 = v_A2 (crank pin); v_A4 = v_A3 + v_A4A3 (v_A4 ⊥ O3A, v_A4A3 ∥ O3A);
    # v_B by the image of the bar; v_F = v_B + v_FB (v_F along the guide, v_FB ⊥ BF).
    vA3 = motion.points["A"].vel[i]
    vA4 = 1j * w4 * rA
    vB = motion.points["B"].vel[i]
    vF = motion.points["F"].vel[i]
    vel = Polygon("velocity", label, {"p": 0j, "a3": vA3, "a4": vA4, "b": vB, "f": vF}, (
        Vector("pa3", "p", "a3", vA3), Vector("a3a4", "a3", "a4", vA4 - vA3),
        Vector("pa4", "p", "a4", vA4), Vector("pb", "p", "b", vB),
        Vector("bf", "b", "f", vF - vB), Vector("pf", "p", "f", vF)))
    # Accelerations: a_A4 = a^n_A4 + a^t_A4 = a_A3 + a^k_A4A3 + a^r_A4A3;
    # a_F = a_B + a^n_FB + a^t_FB.
    aA3 = motion.points["A"].acc[i]
    an4, at4 = -w4 ** 2 * rA, 1j * al4 * rA
    aA4 = an4 + at4
    ak = 2j * w4 * (vA4 - vA3)
    ar = aA4 - aA3 - ak
    aB = motion.points["B"].acc[i]
    aF = motion.points["F"].acc[i]
    an5 = -w5 ** 2 * (pos["F"] - pos["B"])
    acc = Polygon("acceleration", label,
                  {"p'": 0j, "a3'": aA3, "k'": aA3 + ak, "n4'": an4, "a4'": aA4, "b'": aB,
                   "n5'": aB + an5, "f'": aF}, (
        Vector("p'a3'", "p'", "a3'", aA3),
        Vector("a3'k'", "a3'", "k'", ak), Vector("k'a4'", "k'", "a4'", ar),
        Vector("p'n4'", "p'", "n4'", an4), Vector("n4'a4'", "n4'", "a4'", at4),
        Vector("p'a4'", "p'", "a4'", aA4), Vector("p'b'", "p'", "b'", aB),
        Vector("b'n5'", "b'", "n5'", an5), Vector("n5'f'", "n5'", "f'", aF - aB - an5),
        Vector("p'f'", "p'", "f'", aF)))
    # Forces on each Assur group, known loads first, then the reactions that close it.
    g = p.gravity
    fc = -k.stroke_direction * frc.cutting_force[i] + 0j
    G6, PI6 = -1j * p.m6 * g, -p.m6 * motion.points["F"].acc[i]
    R45, R76 = frc.reactions["R45"][i], frc.reactions["R76"][i]
    G4, PI4 = -1j * p.m4 * g, -p.m4 * motion.points["S4"].acc[i]
    R23, R74 = frc.reactions["R23"][i], frc.reactions["R74"][i]
    return [vel, acc, _force("force56", label, [("Fc", fc), ("G6", G6), ("FI6", PI6),
                                               ("R45", R45), ("R76", R76)]),
            _force("force34", label, [("G4", G4), ("FI4", PI4), ("R54", -R45), ("R23", R23),
                                      ("R74", R74)])]


def _force(kind: str, label: str, forces: list) -> Polygon:
    """Forces laid tip to tail; zero forces (no cutting on the return stroke) are left out."""
    scale = max(abs(f) for _, f in forces)
    pts, vecs, at = {"0": 0j}, [], 0j
    for name, f in forces:
        if abs(f) < 1e-9 * scale:
            continue
        tail = list(pts)[-1]
        at = at + f
        head = str(len(pts))
        pts[head] = at
        vecs.append(Vector(name, tail, head, f))
    return Polygon(kind, label, pts, tuple(vecs))


def default_positions(k) -> list[str]:
    """Regular positions nearest the middle of the working and of the return stroke."""
    regular = [(lab, ph) for lab, ph, sp in zip(k.positions.labels, k.positions.phase,
                                                 k.positions.special) if not sp]
    w = k.working_span
    out = []
    for target in (w / 2, (w + 2 * np.pi) / 2):
        out.append(min(regular, key=lambda e: abs(e[1] - target))[0])
    return out


def linkage_sheet(r: dict, info: TitleInfo, lang: str, chosen: list[str] | None = None
                  ) -> tuple[Sheet, dict]:
    """The A1 sheet and the scales used: {"length": n (1:n), "velocity": μv, ...}."""
    lab = LABELS[lang]
    k = r["kinematics"]
    chosen = list(chosen or default_positions(k))
    polys = [polygons(r, c) for c in chosen]
    s = Sheet("A1")
    x0, y0, x1, y1 = s.inner
    n_len = _mechanism(s, r, lab, (x0 + 8, 178.0, 315.0, y1 - 6), chosen)
    scales = {"length": n_len}
    info = TitleInfo(**{**info.__dict__, "scale": scale_text(n_len)})
    frame(s, info)
    _table(s, r, lab, (x0 + 8, y0 + 8, 315.0, 168.0))
    # Column B: polygons. Rows: velocity, acceleration, the two force groups.
    bx0, bx1 = 330.0, 590.0
    half = (bx1 - bx0) / 2
    rows = {"velocity": (452.0, y1 - 8), "acceleration": (300.0, 440.0),
            "force56": (160.0, 288.0), "force34": (y0 + 10, 148.0)}
    units = {"velocity": ("μv", "(m/s)/mm", "m/s"), "acceleration": ("μa", "(m/s²)/mm", "m/s²"),
             "force56": ("μF", "N/mm", "N"), "force34": ("μF", "N/mm", "N")}
    by_kind = {kind: [pp for ps in polys for pp in ps if pp.kind == kind] for kind in rows}
    for kind, (ry0, ry1) in rows.items():
        box_h = ry1 - ry0 - 34.0          # heading above, vector list below
        sym, unit, vunit = units[kind]
        for j, pg in enumerate(by_kind[kind]):
            mu = nice_scale(_extent(pg, half - 16.0, box_h), 1.0)
            scales[f"{kind}_{pg.position}"] = mu
            cx0 = bx0 + j * half
            box = (cx0 + 4, ry0 + 22.0, cx0 + half - 4, ry1 - 10.0)
            _polygon(s, pg, mu, box)
            heading(s, cx0 + half / 2 + 1j * (ry1 - 7.5),
                    lab[kind].format(p=pg.position), 3.5)
            s.text(cx0 + half / 2 + 1j * (ry1 - 11.0),
                   f"{sym} = {format_number(mu)} {unit}", 3.0, "TEXT", "center", "top")
            _vector_list(s, pg, cx0 + 3 + 1j * (ry0 + 19.0), vunit, half - 6)
    # Column C: curves.
    _curves(s, r, lab, (612.0, 86.0, x1 - 8, y1 - 8), scales)
    return s, scales


def _extent(pg: Polygon, width: float, height: float) -> float:
    """The polygon's size in units per paper mm if it just filled width × height."""
    pts = np.array(list(pg.points.values()))
    return float(max(np.ptp(pts.real) / width, np.ptp(pts.imag) / height, 1e-12))


def _polygon(s: Sheet, pg: Polygon, mu: float, box) -> None:
    """Draw the polygon with its pole placed so that it is centred in ``box``."""
    pts = np.array(list(pg.points.values())) / mu
    bx0, by0, bx1, by1 = box
    centre = ((pts.real.min() + pts.real.max()) / 2 + 1j * (pts.imag.min() + pts.imag.max()) / 2)
    v = s.view((bx0 + bx1) / 2 + 1j * (by0 + by1) / 2 - centre, 1.0 / mu)
    placer = LabelPlacer(s)
    for vec in pg.vectors:
        v.arrow(pg.points[vec.tail], pg.points[vec.head], "VECTORS", head=3.0)
        placer.block_segment(v.p(pg.points[vec.tail]), v.p(pg.points[vec.head]))
    centroid = np.mean(list(pg.points.values()))
    for name, z in pg.points.items():
        s.circle(v.p(z), 0.5, "VECTORS", 0.25)
        placer.block(v.p(z), 1.0)
    if pg.kind.startswith("force"):
        for vec in pg.vectors:
            mid = (pg.points[vec.tail] + pg.points[vec.head]) / 2
            placer.place(v.p(mid), vec.name, 3.0, prefer=1j * vec.value, gap=1.5)
        placer.place(v.p(0j), "o", 3.5, prefer=-1 - 1j, gap=1.5)
        return
    for name, z in pg.points.items():
        d = z - centroid
        placer.place(v.p(z), name, 3.5, prefer=d if abs(d) > 1e-12 * mu else 1j, gap=1.5)


def _vector_list(s: Sheet, pg: Polygon, at: complex, unit: str, width: float) -> None:
    """The vectors' magnitudes in two columns under the polygon."""
    items = [f"{vec.name} = {format_number(abs(vec.value), 4)} {unit}" for vec in pg.vectors]
    cols = 2
    rows = int(np.ceil(len(items) / cols))
    for j, text in enumerate(items):
        c, row = divmod(j, rows)
        s.text(at + c * width / cols - 1j * 4.0 * row, text,
               min(2.5, fit_height(text, width / cols - 2, 2.5)), "TEXT", "left", "top")


def _mechanism(s: Sheet, r: dict, lab: dict, box, chosen: list[str]) -> float:
    k, syn = r["kinematics"], r["synthesis"]
    d = syn.design
    n = k.grid_size
    labels = list(k.positions.labels)
    mm = 1e3
    pts = {name: k.points[name][n:] * mm for name in ("O2", "O3", "A", "B", "F")}
    o2, o3 = pts["O2"][0], pts["O3"][0]
    guide_y = d.guide_height * mm
    ram_len = 0.25 * d.guide_bar * mm
    allpts = np.concatenate([pts["A"], pts["B"], pts["F"] - ram_len / 2, pts["F"] + ram_len / 2,
                             [o3 - 80j, o2]])
    lo = allpts.real.min() + 1j * allpts.imag.min() - (60 + 60j)
    hi = allpts.real.max() + 1j * allpts.imag.max() + (60 + 90j)
    bx0, by0, bx1, by1 = box
    avail = (bx1 - bx0) + 1j * (by1 - by0 - 16)
    n_len = length_scale(hi - lo, avail)
    sc = 1.0 / n_len
    centre = (lo + hi) / 2
    v = s.view((bx0 + bx1) / 2 + 1j * ((by0 + by1) / 2 - 6) - sc * centre, sc)
    heading(s, (bx0 + bx1) / 2 + 1j * (by1 - 6), f"{lab['mechanism']}  {scale_text(n_len)}  "
            f"(μL = {format_number(n_len / 1000)} m/mm)", 5.0)
    crank = d.crank * mm
    v.circle(o2, crank, "CENTER")
    bang = np.angle(pts["B"] - o3)
    v.arc(o3, d.guide_bar * mm, bang.min() - 0.05, bang.max() + 0.05, "CENTER")
    xs = np.concatenate([pts["F"].real - ram_len / 2, pts["F"].real + ram_len / 2])
    v.line(xs.min() - 30 + 1j * guide_y, xs.max() + 30 + 1j * guide_y, "CENTER")
    v.text(xs.min() - 30 + 1j * guide_y + 2j / sc, lab["guide"], 3.5, halign="left")
    order = [i for i in range(len(labels)) if labels[i] not in chosen] + \
            [labels.index(c) for c in chosen]
    placer = LabelPlacer(s)
    for i in order:
        bold = labels[i] in chosen
        layer = "OUTLINE" if bold else "CONSTRUCTION"
        w = None if bold else 0.25
        a, b, f = pts["A"][i], pts["B"][i], pts["F"][i]
        v.line(o2, a, layer, w)
        v.line(o3, b, layer, w)
        v.line(b, f, layer, w)
        if bold:
            slider_block(v, a, np.angle(b - o3), 10.0, 5.0)
            slider_block(v, f, 0.0, ram_len * sc, 6.0)
            pin(v, b)
            pin(v, f)
            placer.block_segment(v.p(o3), v.p(b), 1.5)
            placer.block(v.p(a), 5.0)
    for name, z in (("O2", o2), ("O3", o3)):
        ground(v, z, 7.0)
        placer.block(v.p(z), 4.0)
        placer.place(v.p(z), name, 3.5, prefer=1 + 0.3j, gap=2.5)
    for i in range(len(labels)):
        a = pts["A"][i]
        u = (a - o2) / abs(a - o2)
        placer.place(v.p(a), labels[i], 3.5 if labels[i] in chosen else 2.5, prefer=u, gap=1.5)
    i0 = labels.index(chosen[0])
    for name in ("A", "B", "F"):
        placer.place(v.p(pts[name][i0]), name, 3.5, prefer=-1 + 1j, gap=2.0)
    # Dimensions: frame, crank, bar, stroke, guide height.
    v.dimension(o3, o2, 14.0, measurement=abs(o2 - o3))
    v.dimension(o2, o2 + crank * np.exp(-0.75j * np.pi), 0.0, kind="radius", measurement=crank)
    left, right = pts["F"].real.min(), pts["F"].real.max()
    v.dimension(left + 1j * guide_y, right + 1j * guide_y, 16.0, measurement=right - left)
    v.dimension(o3, o3.real + 1j * guide_y, (o3.real - xs.min()) * sc + 10.0,
                measurement=guide_y - o3.imag)
    return n_len


def _table(s: Sheet, r: dict, lab: dict, box) -> None:
    k, frc = r["kinematics"], r["forces"]
    n = k.grid_size
    bx0, by0, bx1, by1 = box
    head = [lab["pos"], "φ (°)", "s (mm)", "v (m/s)", "a (m/s²)", "ω4 (rad/s)", "Mb (N·m)"]
    rows = []
    for j, label in enumerate(k.positions.labels):
        i = n + j
        rows.append([label, f"{k.phase[i] * DEG:.1f}", f"{k.ram_s[i] * 1e3:.1f}",
                     f"{k.ram_v[i]:.3f}", f"{k.ram_a[i]:.3f}", f"{k.omega4[i]:.3f}",
                     f"{frc.balancing_torque[i]:.1f}"])
    rh = min(7.0, (by1 - by0 - 8) / (len(rows) + 1))
    widths = np.array([0.1, 0.14, 0.15, 0.15, 0.16, 0.15, 0.15]) * (bx1 - bx0)
    top = by1 - 7.0
    heading(s, (bx0 + bx1) / 2 + 1j * (top + 1.5), lab["table"], 5.0)
    table(s, bx0, top, widths, rows, head, row_h=rh, height=2.5, head_height=3.0, margin=1.0,
          outer=0.7, rule=0.7, inner=0.25)


def _curves(s: Sheet, r: dict, lab: dict, box, scales: dict) -> None:
    k, frc, fl = r["kinematics"], r["forces"], r["flywheel"]
    n = k.grid_size
    ph = np.append(k.phase[:n], 2 * np.pi) * DEG

    def closed(y):
        return np.append(y[:n], y[0])

    labels = list(k.positions.labels)
    pos_ph = k.phase[n:] * DEG
    regular = [j for j, sp in enumerate(k.positions.special) if not sp]
    bx0, by0, bx1, by1 = box
    left = bx0 + 14.0
    ticks = range(0, 361, 30)
    span = k.working_span * DEG
    heading(s, (left + bx1) / 2 + 1j * (by1 - 5), lab["curves"], 5.0)
    panels = [(k.ram_s * 1e3, lab["s"]), (k.ram_v, lab["v"]), (k.ram_a, lab["a"])]
    top = by1 - 14.0
    # three stacked motion panels (gap 16), then M_b and ΔE with titles (gaps 24 and 26)
    h = (top - by0 - 3 * 16.0 - 8.0 - 26.0 - 12.0) / 5.0
    for j, (y, yl) in enumerate(panels):
        py1 = top - j * (h + 16.0)
        marks = [(pos_ph[q], y[n + q], labels[q] if j == 0 else "") for q in regular]
        chart(s, (left, py1 - h, bx1, py1), ph, [Series(closed(y))], xlabel=lab["phase"] if j == 2 else "",
              ylabel=yl, xticks=ticks, shade=[(0, span)], marks=marks)
    # M_b with the mean driving torque; ΔE with ΔW_max.
    y_mb = top - 3 * (h + 16.0) - 8.0
    md = fl.mean_torque
    mb = frc.balancing_torque
    chart(s, (left, y_mb - h, bx1, y_mb), ph, [Series(closed(mb))], xlabel=lab["phase"],
          ylabel=lab["mb"], title=lab["mbt"], xticks=ticks, shade=[(0, span)],
          hlines=[(md, lab["md"].format(v=format_number(md, 4)))],
          marks=[(pos_ph[q], mb[n + q], labels[q]) for q in regular])
    y_e = y_mb - h - 26.0
    e = fl.energy
    # the work-curve method: W_d = M_d φ (straight), W_r = ∫ M_b dφ, ΔE = W_d − W_r
    phi = np.radians(ph)
    mb_c = closed(mb)
    w_r = np.concatenate([[0.0], np.cumsum(0.5 * (mb_c[1:] + mb_c[:-1]) * np.diff(phi))])
    w_d = md * phi
    m = chart(s, (left, y_e - h, bx1, y_e), ph,
              [Series(w_d, weight=0.35), Series(w_r, weight=0.35), Series(np.append(e, e[0]))],
              xlabel=lab["phase"], ylabel=lab["work"], title=lab["et"], xticks=ticks,
              hlines=[(float(e.min()), ""), (float(e.max()), "")])
    j_r = int(np.argmax(w_r))
    j_d = int(0.85 * len(ph))
    s.text(m.p(ph[j_r], w_r[j_r]) + 2.0j, "Wr", 3.0, "TEXT", "center", "bottom")
    s.text(m.p(ph[j_d], w_d[j_d]) + (1.0 - 2.0j), "Wd", 3.0, "TEXT", "left", "top")
    s.text(m.p(ph[-1], e[0]) + (1.5 + 0j), "ΔE", 3.0, "TEXT", "left", "middle")
    x_at = 0.5 * (fl.phase_at_min + fl.phase_at_max) * DEG
    p_lo, p_hi = m.p(x_at, float(e.min())), m.p(x_at, float(e.max()))
    s.dimension(p_lo, p_hi, 0.0, fl.max_energy_swing,
                text=lab["dw"].format(v=format_number(fl.max_energy_swing, 5)), height=2.5)
    # Scales and flywheel result under the curves, clear of the title block.
    tb_x0, _, _, tb_y1 = title_block_box(s)
    notes = [lab["scales"] + f":  μL = {format_number(scales['length'] / 1000)} m/mm "
             f"({scale_text(scales['length'])}); " + lab["each"],
             lab["dw"].format(v=format_number(fl.max_energy_swing, 5)) + ",  " +
             lab["jf"].format(v=format_number(fl.inertia, 4))]
    for j, text in enumerate(notes):
        s.text(tb_x0 + 1j * (tb_y1 + 14.0 - 6.0 * j), text, 3.0)
