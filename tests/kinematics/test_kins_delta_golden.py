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
def cases() -> dict[str, Any]:
    """The recorded cases; a golden that went missing fails (it was recorded once, a skip would hide its loss)."""
    assert GOLDEN.exists(), f"{GOLDEN} is missing: record it again with scripts/regen_lineardelta_goldens.py"
    return json.loads(GOLDEN.read_text())


def kins_for(cases: dict[str, Any]) -> Any:
    return DeltaKins({"lindeltaradius": repr(cases["R"]), "lindeltaarmlength": repr(cases["L"])})


def test_inverse_matches_lineardeltakins(cases: dict[str, Any]) -> None:
    recorded = cases["cases"]
    assert len(recorded) >= 10
    pos = np.array([[*c["pos"], 0.0, 0.0, 0.0] for c in recorded])
    joints = kins_for(cases).inverse_many(pos)
    np.testing.assert_allclose(joints[:, :3], [c["joints"] for c in recorded], rtol=0, atol=1e-9)


def test_forward_matches_lineardeltakins(cases: dict[str, Any]) -> None:
    recorded = cases["forward"]
    assert recorded, "the golden file has no forward cases"
    joints = np.array([[*c["joints"], 0.0, 0.0, 0.0] for c in recorded])
    pos = kins_for(cases).forward_many(joints)
    np.testing.assert_allclose(pos[:, :3], [c["pos"] for c in recorded], rtol=0, atol=1e-9)


def test_unreachable_like_lineardeltakins(cases: dict[str, Any]) -> None:
    kins = kins_for(cases)
    for x, y, z in cases.get("unreachable", []):
        with pytest.raises(KinematicsDomainError, match="out of reach"):
            kins.inverse((x, y, z, 0.0, 0.0, 0.0))
