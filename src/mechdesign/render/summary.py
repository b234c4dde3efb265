"""The hand-in's closing chapters: 设计小结 / Summary, 参考文献 / References and, where the
machine's report asks for it (``program_appendix`` in its report module: the lock-beam,
whose seed hands in its analysis program), the appendix with the program's flow chart, its
steps and its listing: a short, self-contained program with the brief's numbers written in.

Everything here reads a finished run: the results document (what results.json holds),
the report context the machine prepared (its verification rows and findings) and, for the
appendix, what the machine's report module gives (its program's template, steps and data). The templates
(``summary_section``, ``references_section``, ``appendix_section``) only place the rows.

Citations: a template writes ``{{ cite("sun") }}`` where a method or table of a source is
used; :class:`Citations` numbers the sources in order of first citation and the references
chapter, rendered last, lists exactly the cited ones (data/references.yaml), so that every
marker has its entry and every entry is cited.
"""
from __future__ import annotations

import math
import re
from functools import lru_cache
from importlib import resources
from pathlib import Path
from typing import Any

from .fmt import exact, f, grouped, length, md_text, rpm, sig, time_ratio, verdict
from ..i18n import N_, data_text, tr
from .labels import pgettext, translated

# --------------------------------------------------------------------------- references


@lru_cache(maxsize=1)
def references() -> dict[str, dict]:
    """data/references.yaml: key → {zh, en, source, unconfirmed}."""
    import yaml

    text = resources.files("mechdesign.data").joinpath("references.yaml").read_text(encoding="utf-8")
    return yaml.safe_load(text)


def _unknown_datum(key: str, _) -> str:
    """The name of a bibliographic datum a reference lacks (``unconfirmed`` in
    data/references.yaml)."""
    names = {"edition": _.pgettext("reference", "edition"), "year": _.pgettext("reference", "year"),
             "authors": _.pgettext("reference", "authors"), "author": _.pgettext("reference", "author"),
             "journal": _.pgettext("reference", "journal"), "school": _.pgettext("reference", "school")}
    return names.get(key, key)


def reference_text(key: str, lang: str) -> str:
    """A reference as the list prints it (plain text): the entry in the report's language, then
    what could not be confirmed ("（版次、出版年不详）") and the entry's note, if any."""
    entry = references()[key]
    lang = "zh" if lang == "zh" else "en"
    _ = tr(lang)
    text = entry[lang]
    missing = [_unknown_datum(k, _) for k in entry.get("unconfirmed", ())]
    if missing:
        text += _(" ({items} not known)", items=_.pgettext("list", ", ").join(missing))
    if entry.get(f"note_{lang}"):
        text += ("" if _.zh else " ") + data_text(entry[f"note_{lang}"], lang)
    return text


class Citations:
    """``cite("a", "b")`` → ``[1, 2]``: numbers in order of first citation; ``entries()`` the
    cited sources in that order (the references chapter, rendered after every citation)."""

    def __init__(self, lang: str):
        self.lang = lang
        self.order: list[str] = []

    def __call__(self, *keys: str) -> str:
        known = references()
        nums = []
        for key in keys:
            if key not in known:
                raise KeyError(f"unknown reference {key!r}: add it to mechdesign/data/references.yaml")
            if key not in self.order:
                self.order.append(key)
            nums.append(self.order.index(key) + 1)
        # escaped brackets: pandoc must not read "[1]" before a parenthesis as a link
        return "\\[" + ", ".join(str(n) for n in sorted(set(nums))) + "\\]" if nums else ""

    def entries(self) -> list[dict]:
        lang = "zh" if self.lang == "zh" else "en"
        return [{"n": i, "key": key, "text": md_text(reference_text(key, lang))}
                for i, key in enumerate(self.order, 1)]


# --------------------------------------------------------------------------- checks

def verdict_word(ok: bool, lang: str) -> str:
    """The one verdict vocabulary of the summary: 合格/不合格, PASS/FAIL (:func:`.fmt.verdict`)."""
    return verdict(ok, lang)


def read_verdict(cell: str, lang: str) -> bool | None:
    """A verification table's verdict cell as the boolean it was made from: a cell written
    by :func:`.fmt.verdict` is a :class:`.fmt.Verdict` and carries its ``passed``; the
    word is not read. Anything else (an explanation, a dash, a plain string) is no verdict
    (None)."""
    passed = getattr(cell, "passed", None)
    return passed if isinstance(passed, bool) else None


def _check_names() -> dict[str, tuple[str, str]]:
    """key → (zh, en) of the self-checks that carry only a key."""
    from ..machines.eccentric_cam.stages import DISC_CHECK_NAMES
    from ..stages.cam import CAM_CHECK_NAMES
    from ..stages.drive import DRIVE_CHECK_NAMES

    return {**DRIVE_CHECK_NAMES, **CAM_CHECK_NAMES, **DISC_CHECK_NAMES}


# a cam's checks (its segments' pressure angles, its profile's curvature) under the cam's name
_CAM_OWNERS = {"cam": N_("cam mechanism"), "positioning_cam": N_("positioning cam"),
               "bending_cam": N_("bending cam")}
#: the names of a cam profile's curvature checks (the cam chapter's check table uses them too)
CURVATURE_NAMES = {"pitch_curvature": N_("smallest convex radius $\\rho_{min}$ of the pitch curve"),
              "actual_curvature": N_("actual profile $\\rho_a = \\rho_{min} - r_r$"),
              "convex": N_("smallest radius of curvature (must stay convex)")}
_SEGMENT = {"rise": N_("largest pressure angle of the rise"),
            "return": N_("largest pressure angle of the return")}


def _both(msgid: str, /, context: str | None = None, **fields) -> tuple[str, str]:
    """(Chinese, English) of a catalogue message, as the check rows hold names."""
    zh, en = tr("zh"), tr("en")
    if context is None:
        return zh(msgid, **fields), en(msgid, **fields)
    return zh.pgettext(context, msgid, **fields), en.pgettext(context, msgid, **fields)


def document_checks(document: dict) -> list[dict]:
    """Every check the run's results record with a verdict (a dict with a boolean ``passed``
    or ``ok``), in document order: {path, group (zh, en), name (zh, en), ok}."""
    names = _check_names()
    out: list[dict] = []

    def actuator(doc_cycle: dict, ref: str, zh: bool) -> str:
        key = ref.split(".")[0]
        for a in doc_cycle.get("actuators", ()):
            if a.get("key") == key:
                if isinstance(a.get("name"), dict):            # a name the program gives
                    from ..stages.findings import decode

                    return decode(a["name"]).text("zh" if zh else "en")
                return a.get("name_zh" if zh else "name_en") or key
        return key

    def walk(node: Any, path: tuple, parents: tuple) -> None:
        if isinstance(node, dict):
            flag = node.get("passed", node.get("ok"))
            # a cam's dwell records ok with no limit: nothing is checked there (review39:
            # "cam pressure angle 4" counted the shaper's two dwells beside rise and return)
            unchecked = "segments" in path and "limit" in node and node["limit"] is None
            if isinstance(flag, bool) and not unchecked:
                out.append({"path": ".".join(str(p) for p in path), "ok": flag,
                            "_id": repr(sorted((k, repr(v)) for k, v in node.items())),
                            "margin": _margin(node),
                            **_describe(node, path, parents, names, actuator)})
            for k, v in node.items():
                walk(v, path + (k,), parents + (node,))
        elif isinstance(node, list):
            for i, v in enumerate(node):
                walk(v, path + (i,), parents + (node,))

    walk(document, (), ())
    # a check recorded twice (a shaft's governing check is also in its list) counts once
    seen, unique = set(), []
    for c in out:
        mark = (c["group"], c["name"], c["ok"], c.pop("_id"))
        if mark not in seen:
            seen.add(mark)
            unique.append(c)
    return unique


def _margin(node: dict) -> tuple[float, str, str, str] | None:
    """A strength check's margin (value against its allowable, a fraction of the allowable:
    ≥ 0 passes) with the value, the allowable and the unit as its table prints them; None
    for a check without a value and an allowable (a verdict only)."""
    from dataclasses import fields

    from ..core.strength import Check
    from .strength_tex import cell

    # a load's checks only: stresses, lives, temperatures (a diameter against its torsion
    # estimate or a tip thickness is sized by the standard series, not near a failure)
    if (node.get("sense") not in ("le", "ge") or not node.get("allowable")
            or node.get("unit") not in LOAD_UNITS):
        return None
    names = {fl.name for fl in fields(Check)}
    try:
        c = Check(**{k: v for k, v in node.items() if k in names})
    except TypeError:
        return None
    value, allowed = float(c.value), float(c.allowable)
    margin = (allowed - value) / allowed if c.sense == "le" else (value - allowed) / allowed
    return (margin, grouped(cell(c.course_value, c)), grouped(cell(c.course_allowable, c)),
            "" if c.unit == "1" else c.unit)


#: The units of the checks a larger load brings nearer their limits.
LOAD_UNITS = ("MPa", "h", "°C")

#: A check within this fraction of its limit is named in the summary's points to watch.
TIGHT_MARGIN = 0.05


def _tightest(checks: list[dict], lang: str, most: int = 3) -> list[str]:
    """The passing checks nearest their limits (margin below :data:`TIGHT_MARGIN`, at most
    ``most``, the tightest first), as the designer's points to watch: a larger load
    makes them exceed their limits first (page review 48: the summary drew no conclusion)."""
    _ = tr(lang)
    i = 0 if _.zh else 1
    tight = sorted((c for c in checks if c["ok"] and c.get("margin") is not None
                    and c["margin"][0] < TIGHT_MARGIN), key=lambda c: c["margin"][0])
    out = []
    for c in tight[:most]:
        margin, value, allowed, unit = c["margin"]
        out.append(_("{name} ({group}): only {margin} % margin ({value} against {allowed}{unit}); "
                     "a larger load than the brief's exceeds this limit first.",
                     group=c["group"][i], name=c["name"][i], margin=f(margin * 100, 1),
                     value=value, allowed=allowed, unit=(" " + unit) if unit else ""))
    return out


def _describe(node: dict, path: tuple, parents: tuple, names: dict, actuator) -> dict:
    """(group, name) of one check, both as (zh, en)."""
    keys = [p for p in path if isinstance(p, str)]
    if "stages" in keys and "drive" in keys:              # a transmission stage's strength check
        stage = _owner(parents, path, "stages")
        from ..data import load_yaml

        row = load_yaml("transmissions.yaml").get(stage.get("kind"), {})   # the stage's names
        group = _both(N_("stage {n}: {name_en}"), n=stage.get("index", 0) + 1,
                      name_zh=data_text(row.get("name_zh", "")), name_en=row.get("name_en", ""))
    elif "shaft_designs" in keys:                         # a shaft's strength, bearing, key checks
        from .drive_report import _shaft_name

        shaft = _owner(parents, path, "shaft_designs")
        last = len(_field(parents, path, "shafts") or ()) - 1
        group = (_shaft_name(shaft.get("index", 0), last, True),
                 _shaft_name(shaft.get("index", 0), last, False))
    elif "segments" in keys or "curvature_checks" in keys:   # a cam's pressure angle, curvature
        part = "segments" if "segments" in keys else "curvature_checks"
        owner = keys[keys.index(part) - 1] if keys.index(part) else "cam"
        group = _both(_CAM_OWNERS.get(owner, _CAM_OWNERS["cam"]))
        kind = node.get("kind", node.get("key", ""))
        if part == "curvature_checks":
            name = _both(CURVATURE_NAMES.get(kind, kind))
        else:
            name = _both(_SEGMENT[kind]) if kind in _SEGMENT else \
                _both(N_("largest pressure angle of the {kind}"), kind=kind)
        return {"group": group, "name": name}
    elif keys[:1] == ["cam_phase"]:                       # the feed cam within the return stroke
        return {"group": _both(_CAM_OWNERS["cam"]),
                "name": _both(N_("follower's motion within the return stroke"))}
    elif "quality" in keys and node.get("kind") in ("transmission", "pressure"):   # γ_min, α_max
        from .labels import point_tex

        point = point_tex(node.get("point", ""))
        if node["kind"] == "transmission":
            name = _both(N_("minimum transmission angle $\\gamma_{{min}}$ at ${point}$"), point=point)
        else:
            name = _both(N_("largest pressure angle $\\alpha_{{max}}$ at ${point}$ (working stroke)"),
                         point=point)
        return {"group": _both(N_("Transmission and pressure angles")), "name": name}
    elif "comparison" in keys and "graphical" in keys:     # graphical beside analytic, by position
        from .graphical_report import comparison_name

        label = str(_owner(parents, path, "positions").get("label", "")).replace("'", "′")
        return {"group": _both(N_("graphical method at position {label}"), label=label),
                "name": (comparison_name(node.get("quantity", "")),) * 2}
    elif "constraints" in keys and "cycle" in keys:        # a timing rule of the cycle diagram
        cyc = _field(parents, path, "cycle", whole=True) or {}
        group = _both(N_("motion-cycle timing"))
        return {"group": group,
                "name": (f"{actuator(cyc, node.get('a', ''), True)}—{actuator(cyc, node.get('b', ''), True)}",
                         f"{actuator(cyc, node.get('a', ''), False)}–{actuator(cyc, node.get('b', ''), False)}")}
    elif "verification" in keys or "checks" in keys:
        group = _both(_SELF_CHECKS)
    else:
        group = (keys[0] if keys else "", keys[0] if keys else "")
    if isinstance(node.get("name_args"), dict) and node.get("name"):     # a strength check (msgid)
        from ..stages.findings import check_name

        msg = check_name(node)
        name = (msg.text("zh"), msg.text("en"))
    elif node.get("name_zh") or node.get("name_en"):
        name = (node.get("name_zh") or node.get("name_en"), node.get("name_en") or node.get("name_zh"))
    else:
        key = node.get("key", "")
        name = names.get(key, (key, key))
        label = (node.get("detail") or {}).get("label")
        if label:
            name = (f"{label} {name[0]}", f"{label} {name[1]}")
    return {"group": group, "name": name}


def _owner(parents: tuple, path: tuple, key: str) -> dict:
    """The list item under ``key`` that holds the check."""
    i = path.index(key)       # parents[j] holds path[j]; parents[i + 2] is the list's item
    item = parents[i + 2] if i + 2 < len(parents) else {}
    return item if isinstance(item, dict) else {}


def _field(parents: tuple, path: tuple, key: str, whole: bool = False) -> Any:
    """The value of ``key`` in the dict that holds it on the way to the check."""
    i = path.index(key) if key in path else None
    if i is not None:
        return parents[i + 1] if whole and i + 1 < len(parents) else parents[i].get(key)
    for p in reversed(parents):
        if isinstance(p, dict) and key in p:
            return p[key]
    return None


_SELF_CHECKS = N_("self-checks")


def check_groups(document: dict, ctx: dict, lang: str, checks: list[dict] | None = None) -> list[dict]:
    """The summary's verdict rows: one per group of checks, {group, count, failed names,
    verdict}; the report's verification table is one group when the results hold no
    self-checks of their own (it then carries verdicts the machine judged)."""
    _ = tr(lang)
    i = 0 if _.zh else 1
    groups: dict[str, dict] = {}
    # ``checks``: the document's checks when the caller has them (:func:`document_checks`)
    checks = document_checks(document) if checks is None else checks
    # the transmission and pressure angles against their limits count where the report shows
    # them, in the linkage chapter's table with its verdict column (the crank-rocker's report
    # judges its γ_min in its own verification table instead)
    shown = any(isinstance(v, dict) and v.get("qual_rows") for v in ctx.values())
    angles = _both(N_("Transmission and pressure angles"))
    checks = [c for c in checks if shown or c["group"] != angles]
    for c in checks:
        g = groups.setdefault(c["group"][i], {"group": c["group"][i], "count": 0, "failed": []})
        g["count"] += 1
        if not c["ok"]:
            g["failed"].append(c["name"][i])
    if not any(c["group"][1] == _SELF_CHECKS for c in checks):
        rows = [(r[0], read_verdict(r[-1], lang)) for r in (ctx.get("verify_rows") or ()) if len(r) >= 2]
        rows = [(name, ok) for name, ok in rows if ok is not None]
        if rows:
            g = {"group": _.pgettext("check group", "verification"), "count": len(rows),
                 "failed": [name for name, ok in rows if not ok]}
            groups = {g["group"]: g, **groups}
    # the gear chapter's checks (no undercut, tip thickness, contact ratio): stated in its
    # text, judged from the stage's findings, not recorded as checks in the results
    gear = ctx.get("gear") if isinstance(ctx.get("gear"), dict) else None
    if gear and gear.get("checks"):
        name = _.pgettext("check group", "gear pair")
        groups[name] = {"group": name, "count": len(gear["checks"]),
                        "failed": [n for n, ok in gear["checks"] if not ok]}
    out = []
    for g in groups.values():
        failed = list(dict.fromkeys(g["failed"]))
        word = verdict_word(not failed, lang)
        if failed:
            word = _("{verdict}: {names}", verdict=word, names=_.pgettext("list", ", ").join(failed))
        out.append({"group": g["group"], "count": str(g["count"]), "failed": failed,
                    "verdict": word, "ok": not failed})
    return out


# --------------------------------------------------------------------------- key numbers

# (leaf key, label (msgid), unit, factor SI → unit): found anywhere in the results
# document (first occurrence outside the verification and comparison parts), shown when the
# machine's registry summary does not already give the same quantity.
_PROBES = (
    ("stroke", N_("stroke"), "mm", 1e3),
    ("time_ratio", N_("time ratio $K$"), "", 1.0),
    ("extreme_angle", N_("extreme-position angle $\\theta$"), "°", 180 / math.pi),
    ("gamma_min", N_("minimum transmission angle $\\gamma_{min}$"), "°", 180 / math.pi),
    ("peak_torque", N_("peak balancing torque"), "N·m", 1.0),
    ("max_energy_swing", N_("largest energy swing $\\Delta W_{max}$"), "J", 1.0),
    ("inertia", N_("flywheel $J_F$"), "kg·m²", 1.0),
    ("base_radius", N_("cam base radius $r_0$"), "mm", 1e3),
    ("roller_radius", N_("roller radius $r_r$"), "mm", 1e3),
    ("module", N_("gear module $m$"), "mm", 1e3),
    ("contact_ratio", N_("contact ratio $\\varepsilon_\\alpha$"), "", 1.0),
    ("designation", pgettext("key number", "motor"), "", 1.0),
    ("total_ratio", N_("total ratio"), "", 1.0),
)
# a probe found in a named part: the label names the part (review39: the die-cutter's
# summary gave the incomplete gear's module as "gear module", beside a reducer of m_n 5 and 8;
# the lock-beam's gave one cam of two)
_QUALIFIED = {
    "feed.gear.module": N_("incomplete gear module $m$"),
    "positioning_cam.base_radius": N_("positioning cam base radius $r_0$"),
    "positioning_cam.roller_radius": N_("positioning cam roller radius $r_r$"),
}
# parts a breadth-first probe would not reach (a second cam): (path, label, unit, factor)
_PARTS_ROWS = (
    ("bending_cam.base_radius", N_("bending cam base radius $r_0$"), "mm", 1e3),
    ("bending_cam.roller_radius", N_("bending cam roller radius $r_r$"), "mm", 1e3),
)
_SAME = {"time_ratio_simulated": "time_ratio"}   # registry quantity → the probe it covers
_SKIP = ("verification", "seed", "textbook", "compare", "best_offset", "residuals", "simulated",
         "check", "candidates", "motor_candidates", "positions", "table", "stages", "shaft_designs",
         "rounded", "quality", "boundaries", "segments", "outline", "energy", "followers")


def _find(document: Any, leaf: str) -> tuple[str, Any] | None:
    """(dotted path, value) of the first scalar ``leaf`` breadth-first outside _SKIP."""
    queue = [("", document)]
    while queue:
        path, node = queue.pop(0)
        if not isinstance(node, dict):
            continue
        value = node.get(leaf)
        if value is not None and not isinstance(value, (dict, list, bool)):
            return (f"{path}.{leaf}" if path else leaf), value
        for k, v in node.items():
            if isinstance(v, dict) and k not in _SKIP:
                queue.append((f"{path}.{k}" if path else k, v))
    return None


#: a summary row's number by the rule of its quantity (render/fmt.py), as the report's body
#: writes it: a length to 0.01 mm, an angle to 0.01°, a speed to 0.01 rpm, K to 0.001
_RULES = {"mm": length, "°": lambda x: f(x, 2), "rpm": rpm, "r/min": rpm}


def _show(value: Any, factor: float, unit: str = "", label: str = "",
          digits: int | str | None = None) -> str | None:
    """``value`` × ``factor`` for the summary table, as the report's body writes it: with
    ``digits`` decimals, or as the design gives it (``digits="exact"``) where the machine's
    registry row says so; else by its unit's rule (:data:`_RULES`), the time-ratio
    coefficient K by :func:`~.fmt.time_ratio`, anything else to 4 significant digits with
    the trailing zeros (:func:`~.fmt.sig`: 300.0 W, 28.80)."""
    if isinstance(value, bool) or value is None:
        return None
    if isinstance(value, str):
        return md_text(value)
    try:
        x = float(value) * factor
    except (TypeError, ValueError):
        return None
    if not math.isfinite(x):
        return None
    if digits == "exact":
        return exact(x)
    if digits is not None:
        return f(0.0 if abs(x) < 5e-13 else x, int(digits))
    rule = _RULES.get(unit) or (time_ratio if re.search(r"(?<![\w\\])K\b", label) else None)
    if rule is not None and abs(x) < 1e4:
        return rule(0.0 if abs(x) < 5e-13 else x)
    return sig(x)


# symbols in the registry's plain-text labels (also shown in the terminal) → typeset
_LABEL_MATH = ((re.compile(r"\bJ_F\b"), r"$J_F$"), (re.compile(r"γ_?min"), r"$\gamma_{min}$"),
               (re.compile(r"\bK\b"), r"$K$"), (re.compile(r"\br0\b"), r"$r_0$"),
               (re.compile(r"(?<![\w$])H(?![\w$])"), r"$H$"))
# a length named by its letter at the label's end ("offset slider-crank: crank a", "连杆 b")
_END_LETTER = re.compile(r"(?<=\s)([a-e])$")


# a link named by its points ("coupler BC", "摇杆 DE"): math italic, as every point name
_LINK_NAME = re.compile(r"(?<![\w\\$])([A-H]{2,4})(?![\w$])")


def _label(text: str) -> str:
    text = _LINK_NAME.sub(lambda m: f"${m[1]}$", md_text(text))
    for pattern, math_ in _LABEL_MATH:
        text = pattern.sub(lambda _m: math_, text)
    text = _END_LETTER.sub(lambda m: f"${m[1]}$", text)
    return (text.replace("γ\\_min", r"$\gamma_{min}$").replace("J\\_F", "$J_F$")
            .replace("ΔW\\_max", r"$\Delta W_{max}$"))


def _uniform(point: dict) -> bool:
    """A requested point whose speed and acceleration are the same over the whole cycle
    (sampled on the grid): a point of a crank turning at constant speed, whose answers
    v = ωr, a = ω²r are given data, not results (the crank pin B of the textbook exercise)."""
    for key in ("grid_velocity", "grid_acceleration"):
        values = [v for v in point.get(key) or () if isinstance(v, (int, float))]
        if len(values) < 2 or max(values) - min(values) > 1e-9 * max(max(values), 1e-300):
            return False
    return True


def _asked_rows(document: dict, lang: str) -> list[list[str]]:
    """The answers at the crank angles the brief asks for (``analysis_requests``, e.g. φ45):
    the output link's ω and α there, then the speed and acceleration of each requested point
    but a point in uniform circular motion (:func:`_uniform`)."""
    _ = tr(lang)
    asked = document.get("analysis_requests") or {}
    linkage = document.get("linkage") or {}
    output = linkage.get("output") or {}
    by_label = {p.get("label"): p for p in linkage.get("positions") or () if isinstance(p, dict)}
    rows = []
    for req in asked.get("positions") or ():
        label = req.get("label")
        pos = by_label.get(label)
        if pos is None or req.get("asked") != label:
            continue            # a crank angle the brief gives (φ45), not an event it names
        where = md_text(label)
        if output.get("kind") == "link" and output.get("unit") == "rad":
            name = str(output.get("name"))
            for sym, key, unit in (("\\omega", "link_omega", "rad/s"),
                                   ("\\alpha", "link_alpha", "rad/s²")):
                text = _show((pos.get(key) or {}).get(name), 1.0)
                symbol = "$" + sym + "_{" + name + "}$"
                if text is not None:
                    rows.append([_("{symbol} at position {label}", symbol=symbol, label=where),
                                 text, unit])
        for pt in asked.get("points") or ():
            if _uniform(pt):
                continue        # the crank pin: v = ωr, a = ω²r at every position
            at = next((q for q in pt.get("positions") or () if q.get("label") == label), None)
            if at is None:
                continue
            for sym, key, unit in (("v", "velocity", "m/s"), ("a", "acceleration", "m/s²")):
                text = _show(at.get(key), 1.0)
                symbol = "$" + sym + "_{" + str(pt.get("name")) + "}$"
                if text is not None:
                    rows.append([_("{symbol} at position {label}", symbol=symbol, label=where),
                                 text, unit])
    return rows


def key_rows(machine: str, document: dict, lang: str) -> list[list[str]]:
    """[quantity, value, unit]: the machine's registry summary, then the probed quantities
    it does not give."""
    from ..registry import entry, shown_row

    _ = tr(lang)
    rows, paths = [], set()
    try:
        listed = entry(machine).summary
    except KeyError:
        listed = ()
    for row in listed:
        shown = shown_row(row, lang, document)
        if shown is None:
            continue
        label, unit, factor, value = shown
        path = row[2]
        text = _show(value, factor, unit or "", label, row[4] if len(row) > 4 else None)
        if text is None:
            continue
        rows.append([_label(label), text, unit or "—"])
        leaf = path.rsplit(".", 1)[-1]
        paths.add(_SAME.get(leaf, leaf))
    for leaf, label, unit, factor in _PROBES:
        if leaf in paths or (leaf == "inertia" and "flywheel" not in str(_find(document, leaf))):
            continue
        found = _find(document, leaf)
        if found is None:
            continue
        if leaf == "peak_torque" and not found[1]:
            continue        # no loads given: no driving torque was computed
        shown_label, shown_unit, shown_factor = translated(_QUALIFIED.get(found[0], label), _), unit, factor
        if leaf == "stroke":        # a rocker's stroke is its swing (rad → °)
            shown_label, shown_unit, shown_factor, _value = shown_row(
                (label, unit, found[0], factor), lang, document)
        text = _show(found[1], shown_factor, shown_unit or "", shown_label)
        if text is not None:
            rows.append([shown_label, text, shown_unit or "—"])
            paths.add(leaf)
    for path, label, unit, factor in _PARTS_ROWS:
        node: Any = document
        for key in path.split("."):
            node = node.get(key) if isinstance(node, dict) else None
        text = _show(node, factor, unit) if node is not None else None
        if text is not None:
            rows.append([translated(label, _), text, unit])
    rows += _asked_rows(document, lang)
    for fol in document.get("followers") or ():        # the disc cam's followers
        text = _show(fol.get("stroke"), 1e3, "mm")
        label = md_text(str(fol.get("label", "")))
        if text is not None:
            rows.append([_("{label} follower stroke", label=label), text, "mm"])
        # the task asks for the pressure angles too (page review 48: cam_7_1's summary gave
        # only the strokes)
        alpha = _show(fol.get("max_pressure_angle"), 180.0 / math.pi, "°")
        if alpha is not None:
            rows.append([_("{label} largest pressure angle", label=label), alpha, "°"])
    return rows


# --------------------------------------------------------------------------- the summary

_PARTS = (  # (document key, msgid): what a results document shows was designed
    ("synthesis", N_("dimensional synthesis of the linkage")),
    ("toggle", N_("toggle linkage design")),
    ("optimum", N_("crank-rocker design")),
    ("slider_crank", N_("offset slider-crank design")),
    ("positions", N_("kinematic and kinetostatic analysis")),
    ("linkage", N_("kinematic and kinetostatic analysis")),
    ("press", N_("kinematic and kinetostatic analysis")),       # the die-cutter's toggle press
    ("feed", N_("kinematic analysis of the feed linkage")),
    ("feed.gear", N_("incomplete-gear chain feed design")),      # the die-cutter's feed
    ("bending", N_("bending linkage design")),
    ("flywheel", N_("flywheel design")),
    ("followers", N_("follower motion of the disc cam")),
    ("cam", N_("cam design")),
    ("positioning_cam", N_("cam design")),
    ("gear", N_("gear pair design")),
    ("transmission", N_("transmission design")),
    ("drive", N_("drive design and strength checks")),
    ("cycle", N_("motion cycle diagram")),
    ("morphology", N_("concept selection (morphological matrix)")),
)


def _has_part(document: dict, key: str) -> bool:
    """``key`` ("feed") is in the document; "feed.gear": the feed is an incomplete-gear drive
    (a plain "feed" then names a feed linkage only when the feed has no gear)."""
    head, _dot, sub = key.partition(".")
    doc = document.get(head)
    if not isinstance(doc, dict):
        return doc is not None and not sub
    if sub:
        return doc.get(sub) is not None
    return not any(k.startswith(head + ".") and doc.get(k.partition(".")[2]) is not None
                   for k, _m in _PARTS)


def _forces_computed(document: dict, key: str) -> bool:
    """Whether the linkage analysis under ``key`` computed forces: some position carries
    joint reactions (a brief without loads gives none: kinematics only)."""
    node = document.get(key)
    positions = node if key == "positions" else (node or {}).get("positions")
    return any(isinstance(p, dict) and p.get("reactions") for p in positions or ())


def _designed(document: dict, lang: str) -> list[str]:
    _ = tr(lang)
    out = []
    for key, msgid in _PARTS:
        if not _has_part(document, key):
            continue
        if key == "synthesis" and (document.get("synthesis") or {}).get("given_dimensions"):
            continue          # every link length given: nothing synthesised (page review 41)
        if key in ("positions", "linkage") and not _forces_computed(document, key):
            msgid = N_("kinematic analysis")
        out.append(_(msgid))
    # parts nested in a linkage's results (the generic linkage, the die-cutter's press, the
    # lockbeam's feed): the graphical method and the flywheel (page review 47: the six-bar's
    # summary said "kinematic and kinetostatic analysis" over a graphical chapter and a flywheel)
    # they follow the analysis they belong to
    analysis = [_(m) for m in (N_("kinematic and kinetostatic analysis"), N_("kinematic analysis"),
                               N_("kinematic analysis of the feed linkage"))]
    at = next((i + 1 for i, text in enumerate(out) if text in analysis), len(out))
    nested = []
    for head in ("", "linkage", "press", "feed"):
        node = document if not head else document.get(head)
        if not isinstance(node, dict):
            continue
        g = node.get("graphical")
        positions = (g or {}).get("positions") if isinstance(g, dict) else None
        if positions:
            nested.append(_("graphical method (velocity, acceleration and force polygons)")
                          if any(isinstance(q, dict) and q.get("forces") for q in positions)
                          else _("graphical method (velocity and acceleration polygons)"))
        if head and isinstance(node.get("flywheel"), dict):
            nested.append(_("flywheel design"))
    out[at:at] = [t for t in nested if t not in out]
    return list(dict.fromkeys(out))


def _findings(ctx: Any, out: list[str]) -> list[str]:
    """The texts of every ``findings``/``warnings`` list the machine put in the context."""
    if isinstance(ctx, dict):
        for k, v in ctx.items():
            if k in ("findings", "warnings") and isinstance(v, (list, tuple)):
                out.extend(w for w in v if isinstance(w, str) and w.strip())
            elif isinstance(v, dict):
                _findings(v, out)
    return out


def summary_context(machine: str, document: dict, ctx: dict, lang: str, title: str) -> dict:
    """What the summary template places: designed parts, key numbers, check verdicts and
    what to watch (failed checks named, then the run's findings)."""
    _ = tr(lang)
    checks = document_checks(document)       # one walk of the document for both uses
    groups = check_groups(document, ctx, lang, checks)
    findings = list(dict.fromkeys(_findings(ctx, [])))
    watch = []
    for g in groups:
        for name in g["failed"]:
            # a failed check is named here unless a finding of the run already names it
            if not any(name in w for w in findings):
                watch.append(_("{group}: {name} FAILS.", group=g["group"], name=name))
    watch += findings
    # the handbook values used without a public copy to confirm them (the drive chapter's
    # "Data assumptions"): the summary must not read as nothing to act on (page review 41)
    unconfirmed = sum(len(v.get("data_assumptions") or ()) for v in document.values() if isinstance(v, dict))
    if unconfirmed:
        watch.append(_("The drive design uses {n} handbook values to be confirmed in the handbook before "
                       "handing in (listed under “Data assumptions”).", n=unconfirmed))
    total = sum(int(g["count"]) for g in groups)
    failed = sum(len(g["failed"]) for g in groups)
    return {"title": md_text(title) if title else "", "parts": _designed(document, lang),
            "key_rows": key_rows(machine, document, lang), "check_rows": groups,
            "checks_total": total, "checks_failed": failed, "all_passed": failed == 0,
            # all checks passed, yet the run found design problems no check covers (an
            # undercut gear): the verdict sentence must not read as a clean bill
            "passed_with_findings": failed == 0 and bool(findings or unconfirmed),
            "has_checks": bool(groups),
            "watch": watch,
            # passing checks near their limits: inside the checks, listed apart from the
            # points that need action
            "margins": _tightest(checks, lang)}


# --------------------------------------------------------------------------- the appendix

LISTING_WIDTH = 80   # display columns of a code line on the A4 text block (CJK count 2)




def flow_chart(path: Path, steps, lang: str) -> Path:
    """The analysis program's flow chart: its steps (``(kind, msgid, …)``: "io" input or
    output, "proc" a computation, "loop" the head of the loop, "cond" the loop's test, which
    returns to the head on "yes") as boxes and arrows between start and end."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import FancyBboxPatch, Polygon

    from .fonts import configure_matplotlib

    configure_matplotlib()
    _ = tr(lang)
    boxes = [(_.pgettext("flow chart", "start"), "term")]
    boxes += [(_(step[1]), step[0]) for step in steps]
    boxes += [(_.pgettext("flow chart", "end"), "term")]
    n = len(boxes)
    step, h, w = 0.8, 0.5, 5.6
    fig, ax = plt.subplots(figsize=(4.6, 0.34 * n + 0.3))
    head = next((k for k, (_t, kind) in enumerate(boxes) if kind == "loop"), None)
    for k, (text, kind) in enumerate(boxes):
        y = -k * step
        face = {"term": "#e8e8e8", "io": "#eef4fb", "proc": "white", "loop": "white",
                "cond": "white"}[kind]
        if kind == "cond":         # a diamond, the loop's test
            ax.add_patch(Polygon([(-w / 3, y), (0, y + h / 2), (w / 3, y), (0, y - h / 2)],
                                 closed=True, fc=face, ec="black", lw=0.8))
        else:
            style = {"term": "round,pad=0.02,rounding_size=0.3",
                     "io": "round,pad=0.02,rounding_size=0.05"}.get(kind, "square,pad=0.02")
            ax.add_patch(FancyBboxPatch((-w / 2, y - h / 2), w, h, boxstyle=style, fc=face,
                                        ec="black", lw=0.8))
        ax.text(0, y, text, ha="center", va="center", fontsize=8)
        if k < n - 1:
            ax.annotate("", xy=(0, y - step + h / 2), xytext=(0, y - h / 2),
                        arrowprops={"arrowstyle": "-|>", "lw": 0.8, "color": "black"})
        if kind == "cond":
            ax.text(0.5, y - step / 2, _.pgettext("flow chart", "no"), ha="left", va="center", fontsize=7)
            if head is not None:   # "yes": back to the loop's head, round the right side
                x_out, yh = w / 2 + 0.3, -head * step
                ax.plot([w / 3, x_out, x_out], [y, y, yh], color="black", lw=0.8)
                ax.annotate("", xy=(w / 2, yh), xytext=(x_out, yh),
                            arrowprops={"arrowstyle": "-|>", "lw": 0.8, "color": "black"})
                ax.text(w / 3 + 0.1, y + 0.05, _.pgettext("flow chart", "yes"), ha="left", va="bottom",
                        fontsize=7)
    ax.set_xlim(-w / 2 - 0.2, w / 2 + 0.5)
    ax.set_ylim(-(n - 1) * step - h, h)      # the whole chart, terminals included
    ax.set_aspect("equal")
    ax.axis("off")
    from ..fileio import atomic_path

    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=200, bbox_inches="tight", format="png")
    plt.close(fig)
    return path


def appendix_context(program: dict, fig_dir: Path, lang: str) -> dict:
    """{chart, steps, template, data, table} for the appendix template; ``program`` is what
    the machine's report module gives (``program_appendix``): the program's template, the
    brief's numbers it is written with (Python literals), its flow chart's steps and the
    label of the report's table it prints."""
    _ = tr(lang)
    steps = program["steps"]
    chart = flow_chart(Path(fig_dir) / "program_flow.png", steps, lang)
    rows = [[str(i), _(box), _(what)]
            for i, (_kind, box, what) in enumerate((s for s in steps if s[2] is not None), 1)]
    return {"chart": f"{Path(fig_dir).name}/{chart.name}", "steps": rows,
            "template": program["template"], "data": program["data"], "table": program["table"]}


def handin_context(machine: str, document: dict, ctx: dict, lang: str, title: str,
                   program: dict | None = None, fig_dir: Path | None = None) -> dict:
    """The context keys of the closing chapters: ``cite`` (the citation counter),
    ``summary`` and ``appendix`` (None when the machine hands in no program)."""
    out = {"summary": summary_context(machine, document, ctx, lang, title),
           "appendix": None}
    if program is not None and fig_dir is not None:
        out["appendix"] = appendix_context(program, fig_dir, lang)
    return out
