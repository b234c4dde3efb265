"""The `cam` machine: the shared cam stage (:mod:`mechdesign.stages.cam`) on its own, with its results document."""
from __future__ import annotations

from dataclasses import dataclass
from ...core.fields import q
from ...pipeline import Stage
from ...stages.cam import CamDocument, VerificationDocument, cam_document, cam_stage, verification_document, verify_cam
from ...stages import titles


CAM_STAGES = [cam_stage(),
              Stage("cam_verification", titles.pgettext("stage: self-checks", "verification"), lambda r: verify_cam(r["cam"]))]


CAM_UNITS = "SI: m, rad; derivatives per radian of cam angle; complex points as [x, y]"


@dataclass(frozen=True)
class CamResults:
    """Disc cam (凸轮机构设计): the follower programme, the base circle (given or the smallest
    for the allowed pressure angles), the pitch curve and the actual profile, their pressure
    angle and curvature checks, and the self-checks. Cam frame: cam centre at the origin, the
    follower above it (a translating follower's axis at x = offset); at δ = 0 the frame and
    the cam coincide. The follower's displacement s is in m (translating) or rad (the
    oscillating arm's angle); derivatives are per radian of cam angle."""

    schema: str = q("", "'mechdesign.results/2'")
    machine: str = q("", "'cam'")
    units: str = q("", "reminder of the unit system")
    cam: CamDocument = q("", "the cam")
    verification: VerificationDocument | None = q("", "self-checks")


def cam_results_document(r: dict) -> CamResults:
    from ...results import SCHEMA

    return CamResults(
        schema=SCHEMA, machine="cam", units=CAM_UNITS, cam=cam_document(r["cam"]),
        verification=(None if r.get("cam_verification") is None
                      else verification_document(r["cam_verification"])))
