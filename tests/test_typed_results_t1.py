"""Typed results of the cam, eccentric_cam, gear and crank_rocker machines (issue 17 point 3):
every numeric field states its unit, and the registry names the classes."""
import dataclasses

import numpy as np
import pytest

from mechdesign.core import gears
from mechdesign.stages.cam import CamDocument, CheckDoc, SelfCheck, VerificationDocument, verification_document
from mechdesign.machines.cam.stages import CamResults
from mechdesign.machines.eccentric_cam.stages import EccentricCamResults
from mechdesign.machines.crank_rocker.stages import CrankRockerResults
from mechdesign.stages.gear import GearDocument
from mechdesign.registry import entry, resolve
from mechdesign.results import to_plain
from mechdesign.results_docs import missing_units


@pytest.mark.parametrize("cls", [CamResults, EccentricCamResults, CamDocument,
                                 VerificationDocument, GearDocument, CrankRockerResults,
                                 gears.SpurPair])
def test_every_numeric_field_states_its_unit(cls):
    assert missing_units(cls) == []


@pytest.mark.parametrize("name, cls", [("cam", CamResults), ("eccentric_cam", EccentricCamResults),
                                       ("crank_rocker", CrankRockerResults)])
def test_registry_names_the_results_class(name, cls):
    assert resolve(entry(name).results) is cls


def test_spur_pair_serialises_with_its_field_names():
    # m = 2 mm, z = 20/40, standard: d1 = m z1 = 40 mm, a = m (z1 + z2)/2 = 60 mm
    pair = gears.spur_pair(0.002, 20, 40)
    plain = to_plain(GearDocument(pair, ()))
    assert plain["pair"]["g1"]["d"] == pytest.approx(0.040, rel=1e-12)
    assert plain["pair"]["a"] == pytest.approx(0.060, rel=1e-12)
    assert plain["warnings"] == []
    assert list(plain["pair"]) == [f.name for f in dataclasses.fields(gears.SpurPair)]


def test_verification_document_keeps_the_verdict():
    class V:
        checks = (SelfCheck("a", 1.0, 2.0), SelfCheck("b", 3.0, 2.0),
                  SelfCheck("c", np.nan, None, sense="info"))
        warnings = ()
    doc = verification_document(V())
    assert [c.passed for c in doc.checks] == [True, False, None]
    assert isinstance(doc.checks[0], CheckDoc)
    plain = to_plain(doc)
    assert list(plain["checks"][0]) == ["key", "value", "limit", "sense", "reference", "passed",
                                        "requirement", "detail"]
    assert plain["checks"][2]["value"] is None and plain["failed"] == []
