"""The [TRAJECTORY] and G64 keys the planner reads from cnc.ini, and the errors for bad values."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang import ConfigError, load_config


def write(tmp_path: Path, trajectory: str, interpreter: str = "") -> Path:
    path = tmp_path / "cnc.ini"
    path.write_text(f"[INTERPRETER]\r\n{interpreter}[TRAJECTORY]\r\n{trajectory}", newline="")
    return path


def test_trajectory_keys_are_read(tmp_path: Path) -> None:
    config = load_config(write(tmp_path, "lafAngle = 12.5\r\ng0AccelelerationFactor = 0.5 ;sic\r\n"
                                         "lafArcfeedFactor = 0.8\r\nminCircleSegmentSize = 0.25\r\n",
                               "g64pvalue = 0.02\r\ng64Active = 0\r\n"))
    assert (config.laf_angle, config.g0_acceleration_factor, config.laf_arcfeed_factor,
            config.min_circle_segment_size, config.g64_p, config.g64_active) == (12.5, 0.5, 0.8, 0.25, 0.02, False)


def test_defaults_without_the_keys(tmp_path: Path) -> None:
    config = load_config(write(tmp_path, ""))
    assert (config.laf_angle, config.g0_acceleration_factor, config.laf_arcfeed_factor,
            config.min_circle_segment_size) == (5.0, 1.0, 1.0, 0.0)


@pytest.mark.parametrize(("trajectory", "interpreter", "key"), [
    ("lafAngle = 200\r\n", "", "lafAngle"),
    ("g0AccelelerationFactor = 0\r\n", "", "g0AccelelerationFactor"),
    ("lafArcfeedFactor = -1\r\n", "", "lafArcfeedFactor"),
    ("", "g64pvalue = -0.1\r\n", "g64pvalue"),
])
def test_bad_values_are_reported_at_their_line(tmp_path: Path, trajectory: str, interpreter: str, key: str) -> None:
    with pytest.raises(ConfigError) as caught:
        load_config(write(tmp_path, trajectory, interpreter))
    assert key in caught.value.format() and "cnc.ini:" in caught.value.format()
