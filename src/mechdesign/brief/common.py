"""Brief sections every machine shares: report metadata and analysis settings.

Field names carry their course unit as a suffix (``_mm``, ``_deg``, ``_rpm``, ``_kg``,
``_N``, ``_kgm2``); the description of every field repeats its unit and meaning.
The models are strict: unknown keys, wrong types and out-of-range values are errors.
"""
from __future__ import annotations

import datetime as _dt
import re
from fractions import Fraction
from typing import Annotated, Literal, Optional, Union

from pydantic import BaseModel, ConfigDict, Field, field_validator

from ..i18n import LANGUAGES, N_, Given, Msg  # noqa: F401  (Msg, Given: the program's message class)


_FRACTION = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+))\s*(?:/\s*(\d+\.?\d*|\.\d+)\s*)?$")


def parse_fraction(value, msgid: str, /, **fields):
    """``value`` as a number when it is text such as '1/25' or '0.04' (the course writes
    fluctuation coefficients as fractions); other values unchanged (the field checks them).
    ``msgid`` (with ``fields``) is the error raised for text that is no such number. Only
    plain decimals are read (no exponents), so the text cannot ask for a huge number."""
    if not isinstance(value, str):
        return value
    match = _FRACTION.match(value) if len(value) <= 40 else None
    if match is None:
        raise invalid(msgid, **fields)
    num, den = match.groups()
    if den is not None and Fraction(den) == 0:
        raise invalid(N_("{message}; the denominator is 0"), message=Msg(msgid, **fields))
    return float(Fraction(num) / (Fraction(den) if den is not None else 1))


class Listed(Msg):
    """Names joined with ", " in English and the catalogue's separator in other languages
    (、 in Chinese): ``Listed(sorted(points))``."""

    def __new__(cls, items):
        items = tuple(str(x) for x in items)
        self = str.__new__(cls, ", ".join(items))
        self.msgid, self.context, self.fields, self.items = ", ", None, {}, items
        return self

    def text(self, lang: str) -> str:
        from ..i18n import tr

        return tr(lang).pgettext("list", ", ").join(self.items)


class _Missing:
    """The value of a problem about a field the brief leaves out (shown as "missing")."""

    def __repr__(self) -> str:
        return "missing"

    __str__ = __repr__


MISSING = _Missing()


class Shown:
    """A problem's value shown as this text, without quotes (e.g. "no rise" for a whole list)."""

    def __init__(self, text: str):
        self.text = text

    def __repr__(self) -> str:
        return self.text

    __str__ = __repr__


class Problems:
    """The cross-field problems of one brief section, collected so that a model validator
    reports every one of them at once, each at its exact field path (``loc`` relative to
    the section), with the value found and what to change: an English msgid and its fields
    (a :class:`Msg`, shown in the reader's language).

    Use: ``out = Problems(self)``, ``out.add(("field",), value, N_("… {x} …"), x=…)`` for
    each problem, then ``out.raise_any()`` at the end of the validator."""

    def __init__(self, model: BaseModel):
        self.title = type(model).__name__
        self.items: list[tuple[tuple, object, Msg]] = []

    def add(self, loc: tuple | str, value, msgid: str, zh: str | None = None, /, **fields) -> None:
        """``zh``: a module not yet converted gives its Chinese text here (no fields then)."""
        if isinstance(value, float) and value.is_integer():   # as written: 3, not 3.0
            value = int(value)
        message = _message(msgid, zh, fields)
        self.items.append(((loc,) if isinstance(loc, (str, int)) else tuple(loc), value, message))

    def raise_any(self) -> None:
        """Raise one pydantic ValidationError carrying every problem (none: return)."""
        if not self.items:
            return
        from pydantic import ValidationError
        from pydantic_core import InitErrorDetails, PydanticCustomError

        raise ValidationError.from_exception_data(self.title, [InitErrorDetails(
            type=PydanticCustomError("value_error", "{msg}", {"msg": message}),
            loc=loc, input=value) for loc, value, message in self.items])


def _message(msgid: str, zh: str | None, fields: dict) -> "Msg":
    if isinstance(msgid, Msg):
        return msgid
    return Given(msgid, zh) if zh is not None else Msg(msgid, **fields)


def invalid(msgid: str, zh: str | None = None, /, **fields):
    """The error a single-field validator raises for a bad value: pydantic reports it at
    the field, the loader shows the message (msgid with its fields, in the reader's
    language) as what is allowed. Use: ``raise invalid(N_("must be … {x}"), x=…)`` (a module
    not yet converted: ``invalid(english, chinese)``)."""
    from pydantic_core import PydanticCustomError

    message = _message(msgid, zh, fields)
    return PydanticCustomError("value_error", "{msg}", {"msg": message})


#: A cast flywheel rim's proportions, as every flywheel section of a brief gives them
#: (the guide-bar machines', the die-cutter's and the general linkage's): H/b and γ.
RimHeightToWidth = Annotated[float, Field(gt=0, le=10, description="Rim height/width H/b")]
RimSpecificWeight = Annotated[float, Field(gt=0, le=3e5, description=(
    "Rim material specific weight γ [N/m³] (cast iron 7×10⁴)"))]


class StrictModel(BaseModel):
    """Base for brief sections: unknown keys forbidden, no silent type coercion."""

    model_config = ConfigDict(extra="forbid", strict=True, frozen=True, allow_inf_nan=False)


class ReportMeta(StrictModel):
    """Report metadata shown on the title page (封面)."""

    title: str = Field(description="Report title (设计题目)", min_length=1, max_length=200)
    subtitle: str = Field("", max_length=200, description="Optional subtitle")
    title_en: str = Field("", max_length=200, description=(
        "The title in an English report, when ``title`` is Chinese (default: ``title``)"))
    subtitle_en: str = Field("", max_length=200, description=(
        "The subtitle in an English report (default: ``subtitle``)"))
    student: str = Field(description="Student name (学生姓名)", min_length=1, max_length=100)
    student_id: str = Field("", max_length=40, description="Student number (学号); quote it in YAML")
    class_name: str = Field("", alias="class", max_length=100, description="Class (班级)")
    teacher: str = Field("", max_length=100, description="Teacher (指导教师)")
    date: str = Field("", max_length=40, description="Date shown on the title page, e.g. 2026-11-22")
    language: Literal[LANGUAGES] = Field(       # zh, en and every shipped catalogue
        "zh", description="Report language: zh (中文), en, or the name of another shipped "
                          "catalogue (src/mechdesign/locale/<lang>.po), e.g. zh_TW (繁體中文: the "
                          "zh report with the words of the Traditional Chinese catalogue)")

    model_config = ConfigDict(extra="forbid", strict=True, frozen=True, populate_by_name=True,
                              allow_inf_nan=False)

    @field_validator("date", mode="before")
    @classmethod
    def _date_to_text(cls, value):
        # YAML reads 2026-11-22 as a date; the report shows it as written.
        if isinstance(value, (_dt.date, _dt.datetime)):
            return value.isoformat()
        return value

    @field_validator("student_id", mode="before")
    @classmethod
    def _number_to_text(cls, value):
        # An unquoted student number is read by YAML as an int; keep its digits.
        if isinstance(value, int) and not isinstance(value, bool):
            return str(value)
        return value


#: The positions a brief may name by event (``analysis.events``): code → English name
#: (translated by :func:`event_name`).
#: ``link_vertical:<link>`` and ``link_horizontal:<link>`` name a link by its id.
EVENTS = {
    "work_start": N_("start of the working resistance (e.g. cutting starts)"),
    "work_end": N_("end of the working resistance (e.g. cutting ends)"),
    "max_velocity_working": N_("largest output speed in the working stroke"),
    "max_velocity_return": N_("largest output speed in the return stroke"),
    "link_vertical:<link>": N_("link <link> vertical"),
    "link_horizontal:<link>": N_("link <link> horizontal"),
}
_EVENT = re.compile(r"^(work_start|work_end|max_velocity_working|max_velocity_return|"
                    r"link_(?:vertical|horizontal):[A-Za-z0-9_]{1,8})$")
_POINT = re.compile(r"^[A-Za-z][A-Za-z0-9_']{0,15}$")


def event_name(code: str, lang: str) -> str:
    """The event's name in ``lang``."""
    from ..i18n import tr

    head, _sep, link = code.partition(":")
    name = EVENTS.get(head + (":<link>" if link else ""))
    return (tr(lang)(name) if name else code).replace("<link>", link)


def angle_label(value: float) -> str:
    """The label of a position asked for by its crank angle (``analysis.positions_deg``)."""
    return f"φ{value:g}"


class AnalysisSettings(StrictModel):
    """Numerical settings of the analysis, and the extra positions and points to analyse."""

    grid_points: int = Field(3600, ge=36, le=100_000,
                             description="Crank positions per revolution on the fine grid (count)")
    position_step_deg: float = Field(30.0, gt=0, le=90,
                                     description="Spacing of the textbook positions [°]")
    gravity: float = Field(9.81, gt=0, le=20, description="Gravitational acceleration g [m/s²]")
    positions_deg: list[Annotated[float, Field(ge=-360, le=360)]] = Field(
        default_factory=list, max_length=24, description=(
            "Extra positions by crank angle φ [°], each analysed like the regular ones (tables, "
            "forces, polygons); labelled φ45 etc. φ is the report's crank angle: measured from "
            "position 1 (the output's extreme position that starts the working stroke) in the "
            "crank's sense of rotation; with positions_from: x_axis, the crank's direction "
            "measured counter-clockwise from the +x axis of the frame coordinates instead"))
    positions_from: Literal["position_1", "x_axis"] = Field("position_1", description=(
        "What positions_deg is measured from: position_1 (the report's φ, in the sense of "
        "rotation) or x_axis (the crank's direction, counter-clockwise from +x, as textbook "
        "exercises give φ1)"))
    events: list[str] = Field(default_factory=list, max_length=12, description=(
        "Extra positions by event, found exactly (root finding) and labelled as the course "
        "does (the regular position before it, primed: 1′, 7′): "
        "work_start (工作阻力开始（如切削开始） / start of the working resistance (e.g. cutting starts)); "
        "work_end (工作阻力结束（如切削结束） / end of the working resistance (e.g. cutting ends)); "
        "max_velocity_working (工作行程输出速度最大 / largest output speed in the working stroke); "
        "max_velocity_return (空回行程输出速度最大 / largest output speed in the return stroke); "
        "link_vertical:<link> (构件 <link> 竖直 / link <link> vertical); "
        "link_horizontal:<link> (构件 <link> 水平 / link <link> horizontal)"))
    points: list[str] = Field(default_factory=list, max_length=12, description=(
        "Named points (any point of the linkage, incl. centres of mass) whose velocity and "
        "acceleration (magnitude and direction) the report tabulates at every position and "
        "plots over the cycle"))

    @field_validator("events")
    @classmethod
    def _events(cls, value):
        for code in value:
            if not _EVENT.match(code):
                raise invalid(
                    N_("unknown event {code!r}; allowed: {v1} (e.g. link_vertical:4)"),
                    code=code, v1=', '.join(EVENTS))
        if len(set(value)) != len(value):
            raise invalid(N_("each event once: remove the repeated one"))
        return value

    @field_validator("points")
    @classmethod
    def _points(cls, value):
        for name in value:
            if not _POINT.match(name):
                raise invalid(N_("{name!r} is not a point name (a letter, then letters, digits, _ "
                                 "or ')"), name=name)
        if len(set(value)) != len(value):
            raise invalid(N_("each point once: remove the repeated one"))
        return value


class SheetSettings(StrictModel):
    """Drawing sheets (图纸) written with the report (PDF with --format pdf, DXF with dxf)."""

    polygon_positions: Optional[list[Union[int, str]]] = Field(
        None, min_length=2, max_length=2,
        description=("Two crank positions whose velocity, acceleration and force polygons the A1 "
                     "sheet draws: a regular position (1, 2, …), or a position label of the report "
                     "as text ('4′' or \"4'\", 'φ45' for analysis.positions_deg: [45]) or an event "
                     "of analysis.events ('work_start'); default: the regular positions nearest "
                     "the middle of the working and of the return stroke; where the working "
                     "resistance acts on less than 60 % of the working stroke (a press's last "
                     "millimetres), the regular position under it with the largest balancing "
                     "torque in place of the first"))
    drawing_number: str = Field("MD", max_length=40,
                                description="Prefix of the drawing numbers (图号), e.g. MD → MD-01")
