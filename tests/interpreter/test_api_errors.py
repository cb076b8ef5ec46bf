"""The Python API raises EcncError subclasses (with a location and an exit code), never OSError and friends."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang import parse_file, run_file
from edingcnc_lang.errors import EXIT_USAGE, UnreadableFile


def test_a_missing_file_is_an_ecnc_error_in_the_api(tmp_path: Path) -> None:
    for read in (run_file, parse_file):
        with pytest.raises(UnreadableFile) as caught:
            read(tmp_path / "missing.nc")
        assert caught.value.exit_code == EXIT_USAGE
        assert caught.value.format() == f"{tmp_path / 'missing.nc'}: error: cannot read: No such file or directory"


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="no /dev/zero")
def test_a_device_is_refused_not_read_for_ever_in_the_api() -> None:
    for read in (run_file, parse_file):
        with pytest.raises(UnreadableFile) as caught:
            read(Path("/dev/zero"))  # never ends: reading it would hang
        assert caught.value.format() == "/dev/zero: error: cannot read: a device, not a file"


@pytest.mark.parametrize("option", ["--trace", "--samples", "--events"])
def test_an_empty_output_file_name_is_a_usage_error(tmp_path: Path, option: str) -> None:
    from tests.cli_runner import invoke

    job = tmp_path / "job.nc"
    job.write_text("G0 X1\n")
    result = invoke("run", job, option, "")
    assert result.exit_code == EXIT_USAGE
    assert "the file name is empty" in result.stderr


def test_samples_with_another_extension_is_refused_in_the_api(tmp_path: Path) -> None:
    from edingcnc_lang import RunOptions
    from edingcnc_lang.errors import UsageFailure

    job = tmp_path / "job.nc"
    job.write_text("G0 X1\n")
    with pytest.raises(UsageFailure, match=r"out\.xyz: the samples file must end in \.csv or \.npz") as caught:
        run_file(job, RunOptions(samples=tmp_path / "out.xyz"))
    assert caught.value.exit_code == EXIT_USAGE and not (tmp_path / "out.xyz").exists()
