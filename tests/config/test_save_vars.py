"""--save-vars under concurrency and permissions (issue 17): only changed variables, merged under a
lock; read-only files refused; hard links and owner kept; temporaries of killed runs removed."""
from __future__ import annotations

import os
import signal
import stat
import subprocess
import sys
import threading
from collections.abc import Mapping
from pathlib import Path

import pytest

from edingcnc_lang.config import ini as ini_module
from edingcnc_lang.errors import ConfigError
from edingcnc_lang.runner import RunOptions, run_string

INI = "[VARIABLES]\r\n#4000 = 1.000000\r\n#4001 = 2.000000\r\n"


def save(ini: Path, source: str) -> None:
    run_string(source, RunOptions(ini=ini, save_vars=True))


@pytest.fixture()
def ini(tmp_path: Path) -> Path:
    path = tmp_path / "cnc.ini"
    path.write_bytes(INI.encode())
    return path


@pytest.mark.slow
def test_concurrent_runs_each_keep_their_change(ini: Path) -> None:
    runs = []
    for i in range(10):
        job = ini.parent / f"job{i}.nc"
        job.write_text(f"#{4100 + i} = {i + 1}\n")
        runs.append(subprocess.Popen([sys.executable, "-m", "edingcnc_lang", "run", str(job), "--ini", str(ini),
                                      "--save-vars"], stderr=subprocess.PIPE))
    assert [run.wait() for run in runs] == [0] * 10, [run.stderr.read() for run in runs]  # type: ignore[union-attr]
    text = ini.read_text()
    assert all(f"#{4100 + i} = {i + 1}.000000" in text for i in range(10)), text
    assert sorted(p.name for p in ini.parent.iterdir() if not p.name.startswith("job")) == ["cnc.ini"]


def test_only_changed_variables_are_written(ini: Path) -> None:
    save(ini, "#4000 = 1\n#4001 = 7\n#4001 = 2\n")  # #4000 written with its own value, #4001 back to it
    assert ini.read_bytes() == INI.encode()
    ini.write_bytes(INI.replace("#4001 = 2.000000", "#4001 = 9.000000").encode())  # another run's change
    save(ini, "#4000 = 5\n#4001 = 2\n")  # started from #4001 = 9, so writing 2 is a change
    assert ini.read_bytes() == INI.replace("#4000 = 1.000000", "#4000 = 5.000000").encode()


def test_a_read_only_ini_is_refused_not_replaced(ini: Path) -> None:
    ini.chmod(0o444)
    with pytest.raises(ConfigError, match=r"the file is read-only \(mode 0444\)"):
        save(ini, "#4000 = 5\n")
    assert ini.read_bytes() == INI.encode() and stat.S_IMODE(ini.stat().st_mode) == 0o444


def test_a_hard_link_survives_a_save(ini: Path) -> None:
    other = ini.parent / "backup" / "cnc.ini"
    other.parent.mkdir()
    os.link(ini, other)
    save(ini, "#4000 = 5\n")
    assert other.read_bytes() == ini.read_bytes() and b"#4000 = 5.000000" in ini.read_bytes()
    assert ini.stat().st_ino == other.stat().st_ino


@pytest.mark.skipif(not hasattr(os, "getuid") or os.getuid() != 0, reason="changing a file's owner needs root")
def test_the_owner_is_kept(ini: Path) -> None:
    os.chown(ini, 4321, 4321)
    save(ini, "#4000 = 5\n")
    assert (ini.stat().st_uid, ini.stat().st_gid) == (4321, 4321)


def test_temporaries_of_a_killed_save_are_removed(ini: Path) -> None:
    stale = ini.parent / ".cnc.ini.abc123.tmp"
    stale.write_bytes(b"half")
    unrelated = ini.parent / ".other.ini.abc123.tmp"
    unrelated.write_bytes(b"not ours")
    save(ini, "#4000 = 5\n")
    assert not stale.exists() and unrelated.exists()


def test_a_ctrl_c_during_the_write_back_waits_until_the_file_is_whole(ini: Path,
                                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    os.link(ini, ini.parent / "link.ini")  # rewritten in place: a stop mid-write would cut it short
    update = ini_module._update_variables

    def interrupted(text: str, values: Mapping[int, float]) -> str:
        os.kill(os.getpid(), signal.SIGINT)  # Ctrl-C while the new text is being made
        return update(text, values)

    monkeypatch.setattr(ini_module, "_update_variables", interrupted)
    # Python's own Ctrl-C handler, even where the tests run with SIGINT ignored (a shell's background job)
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    other = threading.Event()  # a thread that could take the signal (a mask on the main thread did not hold)
    threading.Thread(target=other.wait, daemon=True).start()
    try:
        with pytest.raises(KeyboardInterrupt):  # still stops the run, right after the write
            ini_module.write_variables(ini, {4000: 5.0, 4123: 7.0})
    finally:
        other.set()
        signal.signal(signal.SIGINT, before)
    assert ini.read_bytes() == (INI.replace("#4000 = 1.000000", "#4000 = 5.000000") + "#4123 = 7.000000\r\n").encode()
