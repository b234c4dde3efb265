"""The `drive` brief: a transmission designed for a given load (its drive section is shared, :class:`mechdesign.brief.drive.DriveSection`)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, Optional
from ...lazy import np
from pydantic import Field, model_validator
from ...brief.common import MISSING, Problems, ReportMeta, Shown, StrictModel
from ...brief.drive import DriveParams, DriveSection, drive_to_si
from ...i18n import N_


class StrokeLoad(StrictModel):
    """A reciprocating output with constant resistance on each stroke."""

    stroke_mm: float = Field(gt=0, le=5000, description="Stroke H [mm]")
    working_force_N: float = Field(ge=0, le=1e7, description="Resistance on the working stroke [N]")
    return_force_N: float = Field(0.0, ge=0, le=1e7, description="Resistance on the return stroke [N]")


class DriveLoad(StrictModel):
    """What the machine's input shaft needs, when no mechanism computes it: one of
    power_kW, torque_Nm or stroke (mean power = (F_w + F_r) H n / 60)."""

    output_speed_rpm: float = Field(gt=0, le=10000, description="Speed of the machine's input (crank) shaft [rpm]")
    power_kW: Optional[float] = Field(None, gt=0, le=1000, description="Mean power at the machine's input [kW]")
    torque_Nm: Optional[float] = Field(None, gt=0, le=1e7, description="Mean torque at the machine's input [N·m]")
    stroke: Optional[StrokeLoad] = Field(None, description="Reciprocating output, one stroke pair per revolution")

    @model_validator(mode="after")
    def _one_load(self):
        out = Problems(self)
        given = [n for n in ("power_kW", "torque_Nm", "stroke") if getattr(self, n) is not None]
        if not given:
            out.add("power_kW", MISSING, N_("give the load: exactly one of power_kW, torque_Nm or "
                                            "stroke"))
        for name in given[1:]:
            value = getattr(self, name)
            out.add(name, Shown("a section") if isinstance(value, StrictModel) else value,
                    N_("the load is already given by {v1}: give exactly one of power_kW, "
                       "torque_Nm or stroke (remove {name})"), v1=given[0], name=name)
        out.raise_any()
        return self


class DriveBrief(StrictModel):
    """Design brief of a drive alone (``machine: drive``)."""

    machine: Literal["drive"] = Field(description="Machine type")
    report: ReportMeta
    load: DriveLoad
    drive: DriveSection


@dataclass(frozen=True)
class DriveLoadParams:
    output_speed_rpm: float
    power: float                # mean power at the machine's input [W]
    how: str                    # "power" | "torque" | "stroke"
    stroke: float | None = None  # [m]
    working_force: float = 0.0  # [N]
    return_force: float = 0.0   # [N]


@dataclass(frozen=True)
class DriveBriefParams:
    load: DriveLoadParams
    drive: DriveParams


def load_to_si(ld: DriveLoad) -> DriveLoadParams:
    n = ld.output_speed_rpm
    if ld.power_kW is not None:
        return DriveLoadParams(n, ld.power_kW * 1e3, "power")
    if ld.torque_Nm is not None:
        return DriveLoadParams(n, ld.torque_Nm * n * np.pi / 30.0, "torque")
    st = ld.stroke
    H = st.stroke_mm * 1e-3
    # Work per revolution: F_w H on the working stroke plus F_r H on the return.
    return DriveLoadParams(n, (st.working_force_N + st.return_force_N) * H * n / 60.0, "stroke",
                           H, st.working_force_N, st.return_force_N)


def drive_brief_to_si(b: DriveBrief) -> DriveBriefParams:
    return DriveBriefParams(load_to_si(b.load), drive_to_si(b.drive))
