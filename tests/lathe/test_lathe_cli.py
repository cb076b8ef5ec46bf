"""Turning jobs and turning macro sets through ``ecnc run``, as a lathe user runs them."""
from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

from tests.cli_runner import invoke

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "lathe"
RADIUS = Path(__file__).resolve().parent / "data" / "radius_lathe"
ANSWERS = ("--answer", "ok", "--answer", "ok:#1423=48,#1425=-30", "--answer", "ok:#1451=16,#1452=2")


def run_json(*args: object) -> dict:
    result = invoke("run", *args, "--json")
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def test_example_shaft_runs_with_its_own_ini(tmp_path: Path) -> None:
    events = tmp_path / "events.jsonl"
    doc = run_json("--ini", EXAMPLE / "cnc.ini", EXAMPLE / "shaft.nc", "--events", events)
    assert doc["ended_by"] == "M30" and doc["tool"] == 4
    assert doc["machine"]["x"] == 78.0   # G28 at X 78 (radius), machine coordinates
    assert doc["position"]["x"] == pytest.approx(2 * (78.0 - 24.0 + 26.02 / 2))  # G54 X 24, T4 width -26.02: a diameter value
    assert doc["spindle"] == {"m": 5, "mode": "G97", "s": 700.0, "rpm": 0.0, "max_rpm": 3200.0}
    records = [json.loads(line) for line in events.read_text().splitlines()]
    moves = [r for r in records if r["type"] == "move"]
    assert len(moves) == doc["moves"]
    cuts = [m for m in moves if m["synchronised"]]
    assert cuts and all(m["pitch"] in (1.5, pytest.approx(1.5 * (1 + 0.9202 ** 2 / 1.5 ** 2) ** 0.5, rel=1e-3))
                        for m in cuts)
    assert all(m["feed"] == pytest.approx(m["pitch"] * 600.0) for m in cuts)   # threads at G97 S600
    faced = [m for m in moves if "spindle_start" in m]
    assert faced and max(m["spindle"] for m in faced) == 3000.0                 # G96 D3000 on the spigot
    kinds = {r["kind"] for r in records if r["type"] == "event"}
    assert {"spindle", "spindle_speed", "tool_change", "dwell", "dialog"} - kinds == {"dialog"}


@pytest.mark.slow
def test_example_dialogs_answered_like_an_operator(tmp_path: Path) -> None:
    samples = tmp_path / "cut.csv"
    doc = run_json("--ini", EXAMPLE / "cnc.ini", EXAMPLE / "dialogs.nc", *ANSWERS, "--samples", samples)
    assert doc["variables"]["1423"] == 48 and doc["variables"]["1451"] == 16
    assert [m["text"] for m in doc["messages"] if m["kind"] == "dialog"] == ["Facing", "OD turning",
                                                                            "Thread (external)"]
    with samples.open() as handle:
        rows = list(csv.DictReader(handle))
    speeds = {float(r["s"]) for r in rows}
    assert max(speeds) == 2500.0 and 600.0 in speeds and 0.0 in speeds  # facing CSS up to D, threading at G97


def test_cancel_ends_the_job_before_the_cycle_moves() -> None:
    result = invoke("run", "--ini", EXAMPLE / "cnc.ini", EXAMPLE / "dialogs.nc", "--answer", "cancel", "--json")
    doc = json.loads(result.stdout)
    assert result.exit_code == 0 and doc["ended_by"] == "M30"
    assert doc["moves"] == 2  # homing X and Z only
    assert "Facing cancelled" in [m["text"] for m in doc["messages"]]


def test_radius_mode_macro_set_in_latin1_with_crlf() -> None:
    doc = run_json("--ini", RADIUS / "cnc.ini", RADIUS / "job.nc")
    assert doc["ended_by"] == "M30" and doc["machine"]["x"] == 80.0 and doc["machine"]["z"] == 280.0
    assert doc["tool"] == 5 and doc["messages"][0]["text"] == "Längsdrehen"


def test_errmsg_guard_stops_with_the_macro_line() -> None:
    result = invoke("run", "--ini", RADIUS / "cnc.ini", RADIUS / "job.nc", "--answer", "ok:#1405=0")
    assert result.exit_code == 70
    assert "macro.cnc:31: error: Zustellung muss > 0 sein" in result.stderr


def test_g7_in_a_job_names_the_ini_key(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("G18\nG7 G0 X20\nM30\n")
    result = invoke("run", "--ini", EXAMPLE / "cnc.ini", job)
    assert result.exit_code == 70
    assert f"{job}:2:1: error: unknown G code G7:" in result.stderr and "diameterProgramming = 1" in result.stderr
    assert "Traceback" not in result.stderr


def _sync_cuts(events: Path) -> list[dict]:
    records = [json.loads(line) for line in events.read_text().splitlines()]
    return [r for r in records if r["type"] == "move" and r["synchronised"]]


def test_example_threading_cuts_the_diameters_of_its_threads(tmp_path: Path) -> None:
    """examples/lathe/threading.nc: M12x1.5 outside (T3, width -30.512: X -15.256) and M20x1.5 inside
    (T6, width 14.3: X +7.15), G54 X 24 (a radius): crest and root diameters and the pass counts."""
    events = tmp_path / "events.jsonl"
    doc = run_json("--ini", EXAMPLE / "cnc.ini", EXAMPLE / "threading.nc", "--events", events)
    assert doc["ended_by"] == "M30"
    cuts = _sync_cuts(events)
    outside = [c for c in cuts if c["line"] == 194]
    inside = [c for c in cuts if c["line"] == 215]
    assert len(outside) == 2 * 24 and len(inside) == 10   # 21 + K + H2 passes with an exit taper; 8 + K + H1
    diameter = {"outside": lambda c: 2 * (c["end"][0] - 24 + 15.256), "inside": lambda c: 2 * (c["end"][0] - 24 - 7.15)}
    outer = [diameter["outside"](c) for c in outside if c["pitch"] == 1.5]  # the cuts, not the exit tapers
    assert min(outer) == pytest.approx(12 - 2 * 0.6134 * 1.5) and max(outer) <= 12 + 1e-9
    inner = [diameter["inside"](c) for c in inside]
    assert max(inner) == pytest.approx(20.0) and min(inner) == pytest.approx(20 - 2 * 0.5413 * 1.5 + 2 * 0.1)


def test_example_facing_takes_the_face_to_work_z0(tmp_path: Path) -> None:
    events = tmp_path / "events.jsonl"
    doc = run_json("--ini", EXAMPLE / "cnc.ini", EXAMPLE / "facing.nc", "--events", events)
    records = [json.loads(line) for line in events.read_text().splitlines()]
    faces = [r for r in records if r["type"] == "move" and r["kind"] == "linear"]
    assert doc["ended_by"] == "M30" and len(faces) == 3
    assert [round(f["end"][2] + 118.25, 6) for f in faces] == [1.0, 0.5, 0.0]   # G54 Z -118.25, T1 length 0
    assert all(f["end"][0] == pytest.approx(24.0 + 0.03 / 2) for f in faces)     # to the centre: T1 xDelta 0.03
