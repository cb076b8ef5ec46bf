"""One test run and judged: answers, the probe list, expectations and forbid rules."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang import EcncError, RunOptions, run_string
from edingcnc_lang.testing.checks import failures
from edingcnc_lang.testing.execute import run_case
from edingcnc_lang.testing.spec import from_mapping


def judge(tmp_path: Path, **keys: object) -> list[str]:
    return failures(run_case(from_mapping(keys, tmp_path)))


def test_variables_are_set_after_the_macro_files_top_level_and_before_the_start_sub(tmp_path: Path) -> None:
    macro = tmp_path / "macro.cnc"
    macro.write_text("#4000 = 1\nSub start\n  #4001 = [#4000 * 10]\nEndSub\n")
    result = run_string("#1 = #4000\n#2 = #4520\nM30\n", RunOptions(macro=macro, variables={4000: 7, 4520: 2}))
    assert result.variables[1] == 7 and result.variables[2] == 2 and result.variables[4001] == 70


@pytest.mark.parametrize(("index", "message"), [(5380, "#5380 is a read-only system variable"),
                                                (6000, "#6000 is not a parameter")])
def test_variables_refuse_what_no_program_could_set(index: int, message: str) -> None:
    with pytest.raises(EcncError, match=message):
        run_string("M30\n", RunOptions(variables={index: 0}))


def test_a_probe_entry_is_in_work_coordinates_and_the_other_axes_are_the_targets(tmp_path: Path) -> None:
    outcome = run_case(from_mapping({"job": "G0 X5 Z10\nG38.2 X15 Z-20 F100\nM30\n", "vars": {"5223": -50},
                                     "probe": [{"z": -3}]}, tmp_path))
    assert outcome.error is None
    assert outcome.var(5067) == 1 and outcome.var(5063) == pytest.approx(-3) and outcome.var(5053) == pytest.approx(-53)
    assert outcome.var(5061) == pytest.approx(15)  # X not named: the target's
    assert outcome.position["z"] > -3  # backed off towards the start (manual p. 25)


def test_a_miss_stops_the_run_at_its_probe_and_past_the_list_the_probe_trips_at_the_target(tmp_path: Path) -> None:
    missed = run_case(from_mapping({"job": "G38.2 Z-5 F100\nM30\n", "probe": ["miss"]}, tmp_path))
    assert missed.error is not None and "without the probe tripping" in missed.error and ":1:" in missed.error
    past = run_case(from_mapping({"job": "G38.2 Z-5 F100\nG38.2 Z-10\n#2 = #5067\nM30\n",
                                  "probe": [{"z": -5}]}, tmp_path))
    assert past.var(2) == 1 and past.var(5063) == -10


def test_a_probe_entry_off_the_move_is_a_mistake_in_the_test(tmp_path: Path) -> None:
    found = judge(tmp_path, job="G0 Z10\nG38.2 Z-20 F100\nM30\n", probe=[{"z": -30}], expect={"vars": {"1": 5}})
    assert found == ["probe 1: z = -30 is not on the move from z = 10 to z = -20"]


def test_unused_answers_and_probes_are_failures_with_a_hint(tmp_path: Path) -> None:
    job = 'If [#5380 == 0]\n  G38.2 Z-5 F100\nEndIf\ndlgmsg "a" "b" 4000\nM30\n'
    assert judge(tmp_path, job=job, answers=["ok", "cancel"], probe=[{"z": -1}]) == [
        "answers: 2 given, 1 dialog shown",
        "probe: 1 given, the run probed 0 times; probing behind the simulation guard needs simulation = false"]
    assert judge(tmp_path, job=job, answers=["ok:#4000=3"], probe=[{"z": -1}], simulation=False,
                 expect={"vars": {"4000": 3, "5063": -1}}) == []


def test_expectations_say_expected_and_got(tmp_path: Path) -> None:
    found = judge(tmp_path, job='#1 = 2.5\nG0 Z4\nmsg "hello"\nM30\n',
                  expect={"vars": {"1": 2, "2": {"approx": 0.1, "tol": 0.05}},
                          "position": {"z": 4.0000001, "x": 1}, "messages": ["hell", "bye"]})
    assert found == ["#1: expected 2, got 2.5", "#2: expected 0.1 ± 0.05, got 0", "position x: expected 1, got 0",
                     "message 'bye': expected, got 'hello'"]


def test_errors_expected_and_unexpected(tmp_path: Path) -> None:
    macro = tmp_path / "macro.cnc"
    macro.write_text('Sub check\n  errmsg "too deep"\nEndSub\n')
    assert judge(tmp_path, job="GoSub check\nM30\n", macro="macro.cnc") == [
        f"the run stopped: {macro}:2:3: error: too deep; in Sub check, called from <job>:1"]
    assert judge(tmp_path, job="GoSub check\nM30\n", macro="macro.cnc", expect={"error": "too deep"}) == []
    assert judge(tmp_path, job="GoSub check\nM30\n", macro="macro.cnc", expect={"error": "shallow"})[0].startswith(
        "error: expected one containing 'shallow', got ")
    assert judge(tmp_path, job="M30\n", expect={"error": "x"}) == [
        "error: expected one containing 'x', got none (the run ended by M30)"]
    assert judge(tmp_path, job='dlgmsg "a" 5 "b" 4000\nM30\n', expect={"error": "G1167"}) == []  # a syntax error


def test_forbid_rules_name_the_line_of_the_move(tmp_path: Path) -> None:
    job = "G0 Z5\nG0 Z1\nG1 Z-1 F100\nM3 S1000\nG1 X10\nG2 X20 Y0 I5 J0\nM5\nG0 Z-2\nG0 Z-3\nM30\n"
    found = judge(tmp_path, job=job, forbid={"rapid_below_z": 2, "feed_with_spindle_off": True,
                                             "outside": [-1, -1, -5, 30, 3, 10]})
    assert found == [
        "forbid.rapid_below_z: the rapid at <job>:2 ends at work Z1, below Z2 (and 2 more)",
        "forbid.feed_with_spindle_off: the linear move at <job>:3 feeds with the spindle off",
        "forbid.outside: the arc move at <job>:6 reaches work X15 Y5 Z-1, outside the box"]  # the arc bulges to Y5


def test_rules_hold_in_work_coordinates_and_probing_is_no_feed(tmp_path: Path) -> None:
    job = "G10 L2 P1 Z-50\nG0 Z1\nG38.2 Z-5 F100\nG0 Z3\nM30\n"  # machine Z -49 is work Z 1
    assert judge(tmp_path, job=job, forbid={"rapid_below_z": 1, "feed_with_spindle_off": True}) == []


def test_forbid_rules_see_the_moves_of_a_job_files_bulk_path(tmp_path: Path) -> None:
    (tmp_path / "job.nc").write_text("G0 X1\nG0 Z-1\nG1 X5 F100\nG0 Z-2\nM30\n")  # plain lines: run in chunks
    assert judge(tmp_path, job_file="job.nc", forbid={"rapid_below_z": 0, "feed_with_spindle_off": True}) == [
        f"forbid.rapid_below_z: the rapid at {tmp_path / 'job.nc'}:2 ends at work Z-1, below Z0 (and 1 more)",
        f"forbid.feed_with_spindle_off: the linear move at {tmp_path / 'job.nc'}:3 feeds with the spindle off"]


def test_a_failed_variable_shows_its_name(tmp_path: Path) -> None:
    """The names of the variable map: an annotation in the macro file, a comment in the job, a sidecar."""
    (tmp_path / "macro.cnc").write_text(';@unit mm\n;@var #1552 thread_major_diameter\nSub thread\n'
                                        '  #1552 = 0\nEndSub\n', encoding="utf-8")
    (tmp_path / "variables.toml").write_text('1554 = "thread_pitch"\n', encoding="utf-8")
    found = judge(tmp_path, job="#100 = 1 ;; pass counter\nGoSub thread\nM30\n", macro="macro.cnc",
                  expect={"vars": {"1552": 12, "100": 2, "1554": 1, "27": 1}})
    assert found == ["#1552 thread_major_diameter: expected 12, got 0", "#100 pass counter: expected 2, got 1",
                     "#1554 thread_pitch: expected 1, got 0", "#27: expected 1, got 0"]
