"""The embedding API: run_file/run_string, streamed moves and events, job start-up from the ini,
file encodings, and independent runs (no global state)."""
from __future__ import annotations

from pathlib import Path

from edingcnc_lang.canon import Event, Move, Pose
from edingcnc_lang.runner import RunOptions, run_file, run_string

DATA = Path(__file__).parent / "data"
EMPTY_MACRO = DATA / "empty_macro.cnc"


def test_moves_and_events_stream_in_program_order() -> None:
    stream: list[tuple[str, str, int]] = []

    def on_move(move: Move, joints: Pose) -> None:
        assert joints == move.end  # trivial kinematics
        stream.append(("move", move.kind, move.line))

    def on_event(event: Event) -> None:
        stream.append(("event", event.kind, event.line))

    run_string('G0 X1\nM3 S1000\nG4 P0.5\nmsg "hi"\nG1 X2 F100\nM8\nT2 M6\nM30\n',
               RunOptions(macro=EMPTY_MACRO, on_move=on_move, on_event=on_event), path="job.nc")
    assert stream == [("move", "rapid", 1), ("event", "spindle_speed", 2), ("event", "spindle", 2),
                      ("event", "dwell", 3), ("event", "msg", 4),
                      ("move", "linear", 5), ("event", "coolant", 6), ("event", "tool_change", 7),
                      ("event", "spindle", 7),  # M6 leaves the spindle stopped (manual 3.7.3)
                      ("event", "override", 8),  # M30 switches the overrides on (3.7.1)
                      ("event", "coolant", 8), ("event", "end", 8)]  # and the coolant off, visibly (M9)


def test_dwell_seconds_follow_the_ini(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text("[INTERPRETER]\ng4InMilliseconds = 1\n")
    dwells: list[float] = []

    def on_event(event: Event) -> None:
        if event.kind == "dwell":
            dwells.append(event.data["seconds"])

    run_string("G4 P500\n", RunOptions(macro=EMPTY_MACRO, on_event=on_event))
    run_string("G4 P500\n", RunOptions(ini=ini, macro=EMPTY_MACRO, on_event=on_event))
    assert dwells == [500.0, 0.5]


def test_initial_string_from_the_ini_sets_the_start_modes(tmp_path: Path) -> None:
    ini = tmp_path / "cnc.ini"
    ini.write_text('[INTERPRETER]\ninitialString = "G18 G91 F500"\n')
    moves: list[Move] = []
    result = run_string("G1 X1\nG1 X1\n", RunOptions(ini=ini, macro=EMPTY_MACRO,
                                                     on_move=lambda m, _j: moves.append(m)))
    assert [m.end[0] for m in moves] == [1.0, 2.0] and moves[0].feed == 500.0
    assert "G18" in result.modal and "G91" in result.modal


def test_start_sub_runs_before_the_job(tmp_path: Path) -> None:
    macro = tmp_path / "macro.cnc"
    macro.write_text(";@unit mm\nSub start\n  #100 = [#100 + 1]\n  G91\nEndSub\n")
    result = run_string("#101 = #100\nG0 X1\nG0 X1\n", RunOptions(macro=macro))
    assert (result.variables[100], result.variables[101]) == (1.0, 1.0)
    assert result.position[0] == 2.0


def test_run_file_reads_latin1_and_utf8_with_bom(tmp_path: Path) -> None:
    latin1 = tmp_path / "latin1.nc"
    latin1.write_bytes('msg "Maße geprüft"\nG0 X1\n'.encode("latin-1"))
    bom = tmp_path / "bom.nc"
    bom.write_bytes(b"\xef\xbb\xbf" + 'msg "Maße geprüft"\r\nG0 X2\r\n'.encode("utf-8"))
    for job, x in ((latin1, 1.0), (bom, 2.0)):
        result = run_file(job, RunOptions(macro=EMPTY_MACRO))
        assert [m.data["text"] for m in result.messages] == ["Maße geprüft"]
        assert result.messages[0].path == str(job) and result.position[0] == x


def test_percent_lines_and_repeated_n_numbers(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("%\nG0 X1\nN10 G0 X2\nN10 G0 X3\n%\n")
    moves: list[Move] = []
    run_file(job, RunOptions(macro=EMPTY_MACRO, on_move=lambda m, _j: moves.append(m)))
    assert [(m.line, m.end[0]) for m in moves] == [(2, 1.0), (3, 2.0), (4, 3.0)]


def test_runs_are_independent() -> None:
    first = run_string("#100 = 5\nG10 L2 P1 X3\nG0 X1\nT4 M6\n", RunOptions(macro=EMPTY_MACRO))
    second = run_string("#101 = #100\n#102 = #5221\n", RunOptions(macro=EMPTY_MACRO))
    assert first.tool == 4 and first.machine[0] == 4.0
    assert (second.variables[101], second.variables[102], second.tool) == (0.0, 0.0, 0)
    assert second.machine == (0.0,) * 6


def test_result_to_json_matches_the_cli_contract() -> None:
    doc = run_string('G0 X1\nmsg "m"\n', RunOptions(macro=EMPTY_MACRO), path="job.nc").to_json()
    assert {"position", "machine", "joints", "variables", "messages", "kinematics", "tool", "moves",
            "modal"} <= set(doc)
    assert doc["messages"] == [{"kind": "msg", "text": "m", "file": "job.nc", "line": 2}]


def test_variables_list_only_what_the_run_wrote() -> None:
    from edingcnc_lang.runner import run_string

    result = run_string("#100 = 2\nG0 X1\n")
    assert result.variables == {100: 2.0}
