"""Write a :class:`~.sheet.Sheet` as DXF with ezdxf: paper millimetres 1:1 on named layers
(line weight, line type and colour set per layer, so the drawing prints by layer in
AutoCAD or CAXA); dimensions are real DIMENSION entities that measure the true (model)
length through DIMLFAC. Texts use one style, STANDARD, set to the shipped Noto Sans SC
(render/fonts.py), which has the Chinese, Greek and symbol glyphs the drawings use; the
other text and dimension styles ezdxf's setup adds are removed, and $EXTMIN/$EXTMAX hold
the drawing's extents so a viewer opens on the drawing. Polylines are thinned to the
paper's resolution when they are drawn (sheet.thin) and written in bulk."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..fileio import atomic_path
from .fmt import dxf_text, plain_line
from .sheet import (LAYERS, Arc, Circle, Dimension, Fill, Line, Polyline, Sheet, Text,
                    DIM_ARROW, DIM_GAP, dimension_geometry, dimension_text, scripted, split_subscripts,
                    text_width)

TEXT_STYLE = "Standard"          # the one text style (DXF requires it to exist anyway)
TEXT_FONT = "NotoSansSC-Regular.otf", "Noto Sans SC"    # file and family (render/fonts.py)
_ALIGN = {("left", "bottom"): "BOTTOM_LEFT", ("center", "bottom"): "BOTTOM_CENTER",
          ("right", "bottom"): "BOTTOM_RIGHT", ("left", "middle"): "MIDDLE_LEFT",
          ("center", "middle"): "MIDDLE_CENTER", ("right", "middle"): "MIDDLE_RIGHT",
          ("left", "top"): "TOP_LEFT", ("center", "top"): "TOP_CENTER",
          ("right", "top"): "TOP_RIGHT"}


# MTEXT attachment points (1 top left … 9 bottom right)
_ATTACH = {(h, v): 1 + i + 3 * j for j, v in enumerate(("top", "middle", "bottom"))
           for i, h in enumerate(("left", "center", "right"))}


def mtext(text: str) -> str:
    """A sheet text as MTEXT content (also a dimension's text, which ezdxf writes as MTEXT):
    as written when it has no subscript, else with ``\\``, ``{``, ``}`` escaped and each
    subscript stacked below an empty top (``\\S^ v;``: AutoCAD's subscript; the caret is
    followed by a space, as AutoCAD writes it, since "^v" would be a control character)."""
    runs = split_subscripts(plain_line(text))
    if not any(is_sub for _, is_sub in runs):
        return text

    def escape(t: str) -> str:      # as dxf_text, and MTEXT's own codes
        return (t.replace("%", "%%%").replace("^", "^ ").replace("\\", "\\\\")
                .replace("{", "\\{").replace("}", "\\}"))

    def run(t: str, kind) -> str:
        if kind == "sup":
            return f"\\S{escape(t).replace(';', '')}^ ;"
        if kind == "it":        # obliqued by 15° (the font has no italic), then upright again
            return f"\\Q15;{escape(t)}\\Q0;"
        if kind:
            return f"\\S^ {escape(t).replace(';', '')};"
        return escape(t)

    return "".join(run(t, kind) for t, kind in runs)


def _column(t: Text, sheet: Sheet) -> float:
    """The column width of a text's MTEXT [mm]: wider than the text (an estimate with room
    to spare, so that CAD does not wrap it; ezdxf measures an MTEXT of no width as a narrow
    wrapped column), but not past the frame (the sheet's edge for a text outside it)
    in the text's direction."""
    want = 1.3 * text_width(t.text, t.height) + t.height
    u = complex(np.cos(t.angle), np.sin(t.angle))
    f = {"left": 0.0, "center": 0.5, "right": 1.0}[t.halign]
    room = want
    x0, y0, x1, y1 = sheet.inner
    if not (x0 <= t.position.real <= x1 and y0 <= t.position.imag <= y1):
        x0, y0, x1, y1 = 0.0, 0.0, sheet.width, sheet.height
    for share, sign in ((f, -1.0), (1.0 - f, 1.0)):      # the start and the end of the line
        if share == 0.0:
            continue
        for d, lo, hi, p in ((u.real, x0, x1, t.position.real), (u.imag, y0, y1, t.position.imag)):
            step = sign * share * d                    # how far this end moves per mm of width
            if step > 1e-12:
                room = min(room, (hi - p) / step)
            elif step < -1e-12:
                room = min(room, (lo - p) / step)
    return max(room, text_width(t.text, t.height))


def plain_text(entity) -> str:
    """The text of a TEXT, MTEXT or DIMENSION entity this module wrote, subscripts as plain
    letters ("μ\\S^ v; = 1" → "μv = 1"): what the sheet's text reads as (for tests and tools)."""
    import re

    text = entity.text if entity.dxftype() == "MTEXT" else entity.dxf.get("text", "")
    if entity.dxftype() == "TEXT" or ("\\S" not in text and "\\Q" not in text):
        return text
    text = re.sub(r"\\S\^ ([^;]*);", r"\1", text)
    text = re.sub(r"\\S([^;^]*)\^ ;", r"\1", text)
    text = re.sub(r"\\Q[0-9.]+;", "", text)
    return (text.replace("\\{", "{").replace("\\}", "}").replace("\\\\", "\\")
            .replace("%%%", "%").replace("^ ", "^"))


def _lineweight(mm: float) -> int:
    """Nearest DXF standard line weight [1/100 mm]."""
    valid = (0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100)
    return min(valid, key=lambda v: abs(v - mm * 100))


def build_document(sheet: Sheet, title: str = ""):
    """The ezdxf document of ``sheet`` (not yet saved)."""
    import ezdxf
    from ezdxf.enums import TextEntityAlignment

    doc = ezdxf.new("R2010", setup=True, units=4)        # 4 = millimetres
    doc.header["$LWDISPLAY"] = 1
    doc.header["$LTSCALE"] = 1.0
    doc.header["$PSLTSCALE"] = 0
    doc.header["$LIMMAX"] = (sheet.width, sheet.height)
    if title:
        doc.header["$PROJECTNAME"] = plain_line(title)[:255]
    style = doc.styles.get(TEXT_STYLE)
    font_file, family = _text_font()
    style.dxf.font = font_file
    style.dxf.discard("bigfont")
    style.dxf.width = 0.7
    style.set_extended_font_data(family)
    for lay in LAYERS.values():
        layer = doc.layers.add(lay.name, color=lay.color, linetype=lay.linetype,
                               lineweight=_lineweight(lay.weight))
        layer.description = lay.description
    for name in USED_DIMSTYLES:              # before any dimension is rendered
        doc.dimstyles.get(name).dxf.dimtxsty = TEXT_STYLE
    msp = doc.modelspace()

    def attribs(e):
        out = {"layer": e.layer}
        w = getattr(e, "weight", None)
        if w is not None and abs(w - LAYERS[e.layer].weight) > 1e-9:
            out["lineweight"] = _lineweight(w)
        return out

    for e in sheet.entities:
        if isinstance(e, Line):
            msp.add_line((e.p0.real, e.p0.imag), (e.p1.real, e.p1.imag), dxfattribs=attribs(e))
        elif isinstance(e, Polyline):
            # in bulk: ezdxf's add_lwpolyline/set_points append vertex by vertex, copying
            # the whole array each time (quadratic in the number of points)
            pl = msp.add_lwpolyline([], close=e.closed, dxfattribs=attribs(e))
            z = np.asarray(e.points, dtype=complex)
            pl.lwpoints.set(np.column_stack((z.real, z.imag, np.zeros((len(z), 3)))))
        elif isinstance(e, Circle):
            msp.add_circle((e.center.real, e.center.imag), e.radius, dxfattribs=attribs(e))
        elif isinstance(e, Arc):
            msp.add_arc((e.center.real, e.center.imag), e.radius, np.degrees(e.start),
                        np.degrees(e.end), dxfattribs=attribs(e))
        elif isinstance(e, Fill):
            hatch = msp.add_hatch(color=256, dxfattribs={"layer": e.layer})
            hatch.paths.add_polyline_path([(p.real, p.imag) for p in e.points], is_closed=True)
        elif isinstance(e, Text) and scripted(e.text):
            # a subscript: an MTEXT with stacked subscripts, placed and turned as the TEXT
            msp.add_mtext(mtext(e.text), dxfattribs={
                "layer": e.layer, "style": TEXT_STYLE, "char_height": e.height,
                "insert": (e.position.real, e.position.imag), "rotation": np.degrees(e.angle),
                "attachment_point": _ATTACH[(e.halign, e.valign)],
                "width": _column(e, sheet)})
        elif isinstance(e, Text):
            # as written: "%%d", "^J" … are control codes in DXF text (dxf_text escapes them)
            t = msp.add_text(dxf_text(e.text), height=e.height, rotation=np.degrees(e.angle),
                             dxfattribs={"layer": e.layer, "style": TEXT_STYLE})
            t.set_placement((e.position.real, e.position.imag),
                            align=TextEntityAlignment[_ALIGN[(e.halign, e.valign)]])
        elif isinstance(e, Dimension):
            _dimension(msp, e)
    _keep_used_styles(doc)
    _set_extents(doc)
    return doc


def _text_font() -> tuple[str, str]:
    """File name and family of the shipped CJK sans font (Noto Sans SC)."""
    try:
        from .fonts import _font_files, cjk_families

        path = _font_files().get("sans")
        if path is not None:
            return path.name, cjk_families()["sans"]
    except Exception:        # no font found: name the shipped one anyway
        pass
    return TEXT_FONT


USED_DIMSTYLES = ("Standard", "EZDXF", "EZ_RADIUS", "EZ_RADIUS_INSIDE")


def _keep_used_styles(doc) -> None:
    """Remove the text and dimension styles ezdxf's setup adds that the drawing does not
    use; the dimension styles kept write their texts in :data:`TEXT_STYLE`."""
    for name in [d.dxf.name for d in doc.dimstyles]:
        if name not in USED_DIMSTYLES:
            doc.dimstyles.remove(name)
    # (the line types ezdxf's setup adds are all simple ones: none refers to a text style)
    for name in [s.dxf.name for s in doc.styles]:
        if name.lower() != TEXT_STYLE.lower():
            doc.styles.remove(name)


def _set_extents(doc) -> None:
    """$EXTMIN/$EXTMAX: the bounding box of every model-space entity (dimension blocks
    included), so a viewer's "zoom extents" and first view show the drawing."""
    from ezdxf import bbox

    from .fonts import register_ezdxf_fonts

    register_ezdxf_fonts()
    msp = doc.modelspace()
    box = bbox.extents(msp, fast=False)
    if box.has_data:
        lo, hi = (box.extmin.x, box.extmin.y, 0.0), (box.extmax.x, box.extmax.y, 0.0)
        msp.reset_extents(lo, hi)        # saving copies the layout's extents to the header
        doc.header["$EXTMIN"], doc.header["$EXTMAX"] = lo, hi


def _xy(z: complex) -> tuple[float, float]:
    return z.real, z.imag


def _dimension(msp, d: Dimension) -> None:
    """A DIMENSION entity whose text stands where the PDF prints it (render/sheet.py
    :func:`dimension_geometry`: above the line, beyond an extension line when it does not fit
    between the arrows, outside the circle for a radius or diameter)."""
    paper = abs(d.p1 - d.p0)
    override = {"dimtxt": d.height, "dimasz": DIM_ARROW, "dimexe": 1.5, "dimexo": 1.0,
                "dimgap": DIM_GAP, "dimtad": 1, "dimdec": 2, "dimzin": 0, "dimtih": 0,
                "dimtoh": int(d.text_at is not None),
                "dimlfac": d.measurement / paper if paper else 1.0}
    attrs = {"layer": d.layer}
    _lines, _arrows, _text, pos, ang = dimension_geometry(d)
    # the text's middle: its baseline centre raised by half its height
    middle = pos + 1j * np.exp(1j * ang) * d.height / 2
    if d.kind == "aligned":
        dim = msp.add_aligned_dim(p1=(d.p0.real, d.p0.imag), p2=(d.p1.real, d.p1.imag),
                                  distance=d.offset, text=mtext(d.text) or "<>", dimstyle="EZDXF",
                                  override=override, dxfattribs=attrs)
        u = (d.p1 - d.p0) / paper if paper else 1.0
        a = d.p0 + 1j * u * d.offset
        if d.text_at is not None:          # level, on a leader from the dimension line
            dim.set_location(_xy(middle), leader=True)
        elif abs((np.conj(u) * (pos - a)).real - paper / 2) > 1e-6:    # beside, not between
            dim.set_location(_xy(middle), leader=False)
    else:
        # the text's location on the line from the centre (ezdxf takes the dimension's
        # direction from it): in the middle, or past the circle (EZ_RADIUS: text outside)
        centre = d.p0 if d.kind == "radius" else (d.p0 + d.p1) / 2
        radius = abs(d.p1 - centre)
        u = (d.p1 - centre) / radius if radius else 1.0
        w = text_width(dimension_text(d), d.height)
        inside = d.outside == 0
        at = centre + u * ((d.along if d.kind == "radius" else 0.5) * radius if inside
                           else radius + DIM_GAP + 0.5 + w / 2)
        if d.kind == "diameter" and inside:
            at = centre + 1e-3 * u
        add = msp.add_radius_dim if d.kind == "radius" else msp.add_diameter_dim
        dim = add(center=_xy(centre), radius=radius, angle=float(np.degrees(np.angle(u))),
                  location=_xy(at), text=mtext(d.text) or "<>",
                  dimstyle="EZ_RADIUS_INSIDE" if inside else "EZ_RADIUS", override=override,
                  dxfattribs=attrs)
    dim.render()


def _fix_class_order(doc) -> None:
    """Register the CLASS entries ezdxf adds on saving now, in a fixed order: it adds those
    of the entity types in use from a set, whose order changes from one process to the next."""
    try:
        from ezdxf.sections.classes import REQUIRED_CLASSES

        doc.classes.add_required_classes(doc.dxfversion)
        required = list(REQUIRED_CLASSES.get(doc.dxfversion, ()))
        rank = {name: i for i, name in enumerate(required)}
        items = sorted(doc.classes.classes.items(),
                       key=lambda kv: (rank.get(kv[0][0], len(rank)), kv[0]))
        doc.classes.classes.clear()
        doc.classes.classes.update(items)
    except (ImportError, AttributeError):     # another ezdxf: the order is cosmetic anyway
        pass


def write_dxf(sheet: Sheet, path: Path, title: str = "") -> Path:
    """Save ``sheet`` as a DXF file (written atomically)."""
    path = Path(path)
    import ezdxf

    # Reproducible file: ezdxf otherwise stamps the creation and save times and random
    # GUIDs into the file; with this option it writes fixed ones (2000-01-01, constant GUIDs).
    fixed = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        doc = build_document(sheet, title)
        _fix_class_order(doc)
        with atomic_path(path) as tmp:
            doc.saveas(tmp, encoding="utf-8")
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = fixed
    return path
