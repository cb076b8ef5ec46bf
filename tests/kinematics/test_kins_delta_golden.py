"""deltakins against values recorded from LinuxCNC's lineardeltakins (tests/golden/lineardelta/cases.json)."""
from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from edingcnc_lang.kinematics.base import KinematicsDomainError
from edingcnc_lang.kinematics.shipped import import_shipped

GOLDEN = Path(__file__).resolve().parents[1] / "golden" / "lineardelta" / "cases.json"
DeltaKins = import_shipped("deltakins").DeltaKins


@pytest.fixture(scope="module")
def golden() -> dict[str, Any]:
    if not GOLDEN.exists():
        pytest.skip(f"{GOLDEN} has not been recorded from LinuxCNC yet")
    return json.loads(GOLDEN.read_text())


def kins_for(golden: dict[str, Any]) -> Any:
    return DeltaKins({"lindeltaradius": repr(golden["R"]), "lindeltaarmlength": repr(golden["L"])})


def test_inverse_matches_lineardeltakins(golden: dict[str, Any]) -> None:
    cases = golden["cases"]
    assert len(cases) >= 10
    pos = np.array([[*c["pos"], 0.0, 0.0, 0.0] for c in cases])
    joints = kins_for(golden).inverse_many(pos)
    np.testing.assert_allclose(joints[:, :3], [c["joints"] for c in cases], rtol=0, atol=1e-9)


def test_forward_matches_lineardeltakins(golden: dict[str, Any]) -> None:
    cases = golden.get("forward", [])
    if not cases:
        pytest.skip("the golden file has no forward cases")
    joints = np.array([[*c["joints"], 0.0, 0.0, 0.0] for c in cases])
    pos = kins_for(golden).forward_many(joints)
    np.testing.assert_allclose(pos[:, :3], [c["pos"] for c in cases], rtol=0, atol=1e-9)


def test_unreachable_like_lineardeltakins(golden: dict[str, Any]) -> None:
    kins = kins_for(golden)
    for x, y, z in golden.get("unreachable", []):
        with pytest.raises(KinematicsDomainError, match="out of reach"):
            kins.inverse((x, y, z, 0.0, 0.0, 0.0))
