"""The launch reads the job once: its breakpoint lines and subs come from the run's own check pass,
which the run then takes instead of checking the job again (docs/performance.md, ``ecnc debug``)."""
from __future__ import annotations

import json
import os
import random
import threading
from pathlib import Path
from typing import Any

import pytest

from edingcnc_lang.debug import serve
from edingcnc_lang.debug.breakpoints import _read, file_key, job_facts
from edingcnc_lang.errors import EcncError
from edingcnc_lang.runner import Run, RunOptions
from edingcnc_lang.syntax import parser

TESTS = Path(__file__).resolve().parents[1]
PLAIN = ["G1 X1 Y2", "G0 Z5", "N10 G1 X[1]", "\tG1 X1 ; c", "T1 M6", "G1 X1 (c)", "M3 S1000", "F100", "g1x1"]
OTHER = ["", "   ", "; comment", "(comment)", "#1 = [#1 + 1]", 'msg "hi"', "GoSub s1", "M6 T2", "%",
         "#2 = 3 ; set", "G1 X[#1]", ";@unit mm", "\t; tabbed"]


def _block(rng: random.Random, depth: int) -> list[str]:
    lines: list[str] = []
    for _ in range(rng.randint(0, 6)):
        draw = rng.random()
        if draw < 0.45:
            lines.append(rng.choice(PLAIN))
        elif draw < 0.75:
            lines.append(rng.choice(OTHER))
        elif draw < 0.87 and depth < 4:
            lines += ["If [#1 > 0]", *_block(rng, depth + 1)]
            if rng.random() < 0.5:
                lines += ["Else", *_block(rng, depth + 1)]
            lines.append("EndIf")
        elif depth < 4:
            lines += ["While [#1 < 3]", *_block(rng, depth + 1), "EndWhile"]
    return lines


def _job(rng: random.Random) -> str:
    lines: list[str] = []
    for _ in range(rng.randint(1, 12)):
        if rng.random() < 0.15:
            lines += [f"Sub s{rng.randint(0, 3)}", *_block(rng, 1), "EndSub"]
        else:
            lines += _block(rng, 0)
    return "\n".join(lines) + ("\n" if rng.random() < 0.8 else "")


def _jobs(tmp_path: Path) -> list[Path]:
    """Generated jobs (blocks, comments, plain and macro lines) and the project's own files."""
    rng = random.Random(5)
    made = []
    for i in range(300):
        path = tmp_path / f"job{i}.nc"
        path.write_text(_job(rng))
        made.append(path)
    return made + sorted(p for ext in ("nc", "cnc") for p in TESTS.rglob(f"*.{ext}"))


def test_the_checks_breakpoint_lines_are_the_run_reads(tmp_path: Path) -> None:
    """For every job the check passes, each line a breakpoint may ask for moves where the run's own
    reader (every statement listed, the reference) says, and the subs are the same."""
    run = Run(RunOptions(plan=False))
    checked = 0
    for path in _jobs(tmp_path):
        try:
            reference = _read(file_key(str(path)))
        except EcncError:
            continue
        found, check = job_facts(run, path)
        if check is None:
            continue
        checked += 1
        assert reference.error is None, path
        assert found.subs == reference.subs, path
        for wanted in range(-1, reference.count + 3):
            assert found.first_at(wanted) == reference.first_at(wanted), (path, wanted)
    assert checked > 200


def test_the_check_is_the_runs_while_the_file_is_unchanged(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G1 X1\nT3 M6\nM30\n")
    found, check = job_facts(Run(RunOptions(plan=False)), job)
    assert check is not None and check.current() is check.checked
    assert check.checked.tools == frozenset({3}) and found.first_at(1) == 1
    job.write_text("G1 X1\nT3 M6\nG1 X2\nM30\n")
    assert check.current() is None  # changed since: the run checks it again
    job.unlink()
    assert check.current() is None


def test_a_job_that_fails_its_check_is_read_as_before(tmp_path: Path) -> None:
    """A dlgmsg the controller refuses (G1167) fails the check, not the run's reader: the launch
    answers as it did (no error), and the run checks the job itself and reports it."""
    job = tmp_path / "job.nc"
    job.write_text('dlgmsg "a" 5 "b" 4000\nM30\n')
    found, check = job_facts(Run(RunOptions(plan=False)), job)
    assert check is None and found.error is None and found.first_at(1) == 1


class _Session:
    """``serve`` in this process over a pipe: the requests, then the events up to ``exited``."""

    def __init__(self) -> None:
        self.read_end, self.write_end = os.pipe()
        self.out = bytearray()
        self.exited = threading.Event()
        self.seq = 0

    def write(self, data: bytes) -> int:
        self.out += data
        if b'"event": "exited"' in data or b'"event":"exited"' in data:
            self.exited.set()
        return len(data)

    def flush(self) -> None:
        pass

    def request(self, command: str, **arguments: Any) -> bytes:
        self.seq += 1
        body = json.dumps({"seq": self.seq, "type": "request", "command": command, "arguments": arguments}).encode()
        return b"Content-Length: %d\r\n\r\n" % len(body) + body

    def run(self, job: Path, on_launched: Any = None) -> str:
        """Launch ``job``, set a breakpoint never hit, run to the end; the output events' text."""
        to_adapter = os.fdopen(self.write_end, "wb")

        def client() -> None:
            to_adapter.write(self.request("initialize", adapterID="ecnc") + self.request("launch", program=str(job)))
            to_adapter.flush()
            if on_launched is not None:
                while b'"event": "initialized"' not in self.out and b'"event":"initialized"' not in self.out:
                    self.exited.wait(0.01)
                on_launched()
            to_adapter.write(self.request("setBreakpoints", source={"path": str(job)}, breakpoints=[{"line": 3}])
                             + self.request("configurationDone"))
            to_adapter.flush()
            assert self.exited.wait(60)
            to_adapter.write(self.request("disconnect"))
            to_adapter.close()

        thread = threading.Thread(target=client)
        thread.start()
        serve(os.fdopen(self.read_end, "rb"), self)  # type: ignore[arg-type]
        thread.join()
        text = self.out.decode()
        return "".join(json.loads(body)["body"].get("output", "") for body in
                       (part.split("\r\n\r\n", 1)[1] for part in text.split("Content-Length")[1:])
                       if '"event": "output"' in body or '"event":"output"' in body)


def _reads(monkeypatch: pytest.MonkeyPatch, job: Path) -> list[str]:
    """Each time the job is read through (by any reader), its path."""
    reads: list[str] = []
    blocks = parser.iter_file_blocks

    def counted(path: Any) -> Any:
        if Path(path) == job:
            reads.append("read")
        return blocks(path)
    monkeypatch.setattr(parser, "iter_file_blocks", counted)
    return reads


def test_a_debugged_run_reads_the_job_as_often_as_a_run(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Twice, as ``ecnc run``: the check (the launch's, which the run takes) and the run's reading."""
    job = tmp_path / "job.nc"
    job.write_text("G21 G90 F1000\nG1 X1\nSub never\n  #2 = 1\nEndSub\nG1 X2\nM30\n")
    reads = _reads(monkeypatch, job)
    output = _Session().run(job)
    assert "after 2 moves" in output
    assert len(reads) == 2


def test_a_job_changed_after_the_launch_runs_as_it_is_now(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G21 G90 F1000\nG1 X1\nSub never\n  #2 = 1\nEndSub\nG1 X2\nM30\n")
    reads = _reads(monkeypatch, job)
    output = _Session().run(job, on_launched=lambda: job.write_text(
        "G21 G90 F1000\nG1 X1\nSub never\n  #2 = 1\nEndSub\nG1 X2\nG1 X3\nG1 X4\nM30\n"))
    assert "after 4 moves" in output
    # the breakpoints are verified against the file as it is now, and the run checks it again:
    # the launch's check was of another version
    assert len(reads) == 4
