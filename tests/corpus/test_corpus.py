"""The corpus: realistic macro files in the styles users publish, each loaded and every sub run.

The files (``files/``) mix what real macro files contain: CRLF and Latin-1, prose lines that were
never commented out (between subs and in a block that is never reached), ``%d`` in messages,
one-operand ATAN in a probing routine, a ZHC grid sub, ``G53 G38.2``, ``ZHCcheck``, spindle
selection, THC readouts and the rotary clamp; the stock macro.cnc's tool setter shape (GetToolInfo
over the job's tools, ``#[5400 + n]`` writes, ``m6t[#5011]``, bare ``f30`` lines).  Loading warns about the prose lines only; every
sub then runs to its end.  The probe touches a tilted board (Z) and a slightly skewed wall (Y).
"""
from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from edingcnc_lang.canon import Pose
from edingcnc_lang.config.heightmap import HeightMap, ProbeAt
from edingcnc_lang.host import Host
from edingcnc_lang.machine.named_commands import tools_used
from edingcnc_lang.runner import RunOptions, RunResult, run_string
from edingcnc_lang.syntax.parser import read_statements
from edingcnc_lang.syntax import nodes as n

FILES = Path(__file__).resolve().parent / "files"
BOARD = ProbeAt(HeightMap((0.0, 100.0), (0.0, 100.0), ((0.0, 0.5), (0.25, 0.75))))
WALL_ANGLE = 2.0  # degrees: the wall the edge probing touches, at Y = 5 + X tan(2)


def touch(start: Pose, target: Pose) -> Pose | None:
    """Z moves meet the board; Y moves meet the wall."""
    if abs(target[1] - start[1]) > 1e-9:
        # (within reach of every probe move of the corpus: a probe that misses is an error, manual 3.6.10.1)
        wall = 5.0 + start[0] * math.tan(math.radians(WALL_ANGLE))
        return (*target[:1], wall, *target[2:]) if min(start[1], target[1]) <= wall <= max(start[1], target[1]) else None
    return BOARD(start, target)


# file -> the lines that do not parse (warned about at load, never reached)
CORPUS = {
    "vendor_macro.cnc": [],
    "shared_macro.cnc": [],
    "conversational_addon.cnc": [4, 5, 6, 27, 28, 29],
    "user_macro.cnc": [],
    "bzt_macro.cnc": [112, 113, 114],
    "shop_macro.cnc": [],
    "toolsetter_macro.cnc": [],
}


def subs_of(path: Path) -> list[str]:
    return [stmt.name for stmt in read_statements(path, tolerant=True) if isinstance(stmt, n.Sub)]


def run_sub(path: Path, name: str, tmp_path: Path) -> RunResult:
    warnings: list[object] = []
    return run_string(f"GoSub {name}\nM30\n", RunOptions(macro=path, host=Host(probe=touch), log_dir=tmp_path,
                                                           on_warning=warnings.append))


def test_every_corpus_file_is_listed() -> None:
    assert sorted(p.name for p in FILES.glob("*.cnc")) == sorted(CORPUS)


@pytest.mark.parametrize("name", sorted(CORPUS))
def test_loading_warns_about_exactly_the_lines_that_do_not_parse(name: str, tmp_path: Path) -> None:
    result = run_string("M30\n", RunOptions(macro=FILES / name, log_dir=tmp_path))
    assert [w.line for w in result.warnings] == CORPUS[name]
    assert all(w.severity.value == "warning" for w in result.warnings)


@pytest.mark.parametrize("name, sub", [(name, sub) for name in sorted(CORPUS) for sub in subs_of(FILES / name)])
def test_every_sub_runs(name: str, sub: str, tmp_path: Path) -> None:
    result = run_sub(FILES / name, sub, tmp_path)
    assert result.ended_by == "M30", result.error


def test_the_vendor_edge_probe_measures_the_wall_angle_with_one_operand_atan(tmp_path: Path) -> None:
    result = run_sub(FILES / "vendor_macro.cnc", "user_1", tmp_path)
    assert result.variables[103] == pytest.approx(WALL_ANGLE)
    assert result.variables[5194] == pytest.approx(WALL_ANGLE)  # G68 R in G17: the XY angle, #5194 (manual 3.1)


def test_the_shared_zhc_grid_is_saved_and_the_engraving_follows_the_board(tmp_path: Path) -> None:
    moves: list[object] = []
    result = run_string("GoSub engrave_on_surface\nM30\n", RunOptions(
        macro=FILES / "shared_macro.cnc", host=Host(probe=touch), log_dir=tmp_path,
        on_move=lambda move, joints: moves.append(move)))
    assert (tmp_path / "zHeightCompTable.txt").is_file()
    texts = [m.data["text"] for m in result.messages]
    assert any(text.startswith("ZHC table 4 x 3 points, 20 x 20 mm: 12 measured") for text in texts)
    cut = [m for m in moves if m.kind == "linear" and m.end[2] < 0]  # type: ignore[attr-defined]
    assert cut and all(m.end[2] == pytest.approx(-0.2 + BOARD.surface.height(m.end[0], min(m.end[1], 40.0)), abs=1e-6)
                       for m in cut)  # type: ignore[attr-defined]


def test_the_unreached_prose_stops_the_run_when_it_is_reached(tmp_path: Path) -> None:
    from edingcnc_lang.diagnostics import SyntaxErrors

    with pytest.raises(SyntaxErrors) as info:
        run_string("#4699 = 1\nGoSub notes\n", RunOptions(macro=FILES / "conversational_addon.cnc"))
    assert info.value.diagnostics[0].line == 27 and info.value.exit_code == 65


def test_the_crlf_latin1_prose_is_the_same_message_at_load_and_when_reached(tmp_path: Path) -> None:
    """bzt_macro.cnc: CRLF, Latin-1 accents, and a retired sub whose note was never commented out."""
    from edingcnc_lang.diagnostics import SyntaxErrors

    loaded = run_string("M30\n", RunOptions(macro=FILES / "bzt_macro.cnc", log_dir=tmp_path))
    with pytest.raises(SyntaxErrors) as info:
        run_string("#4005 = 99\nGoSub user_9\n", RunOptions(macro=FILES / "bzt_macro.cnc", log_dir=tmp_path))
    assert info.value.exit_code == 65
    assert info.value.diagnostics[0].format() == loaded.warnings[0].format().replace("warning:", "error:")
    assert "Werkzeuglänge" in loaded.warnings[0].format()  # the Latin-1 line, decoded


def test_the_translated_vendor_style_measures_its_angle_both_ways(tmp_path: Path) -> None:
    """shop_macro.cnc: lower-case keywords, msg"..." without a space, g4p0.2, #5015..#5025 as scratch."""
    result = run_sub(FILES / "shop_macro.cnc", "zero_set_rotation", tmp_path)
    assert result.variables[5024] == pytest.approx(math.degrees(math.atan2(3, 100)))
    assert result.variables[5025] == pytest.approx(result.variables[5024])
    assert result.variables[5194] == pytest.approx(result.variables[5024])  # the XY angle (manual 3.1)


def test_the_toolsetter_measures_the_tools_the_job_uses(tmp_path: Path) -> None:
    """toolsetter_macro.cnc (the stock macro.cnc's shape): GetToolInfo walks the job's T words, the
    dialog ticks them, and each ticked tool is measured and stored with #[5400 + n]."""
    from edingcnc_lang.runner import run_file

    job = tmp_path / "job.nc"
    job.write_text("GoSub measure_used_tools\nT1 M6\nG0 X1\nT3 M6\nG0 X2\nM30\n")
    result = run_file(job, RunOptions(macro=FILES / "toolsetter_macro.cnc", host=Host(probe=touch), log_dir=tmp_path))
    assert result.ended_by == "M30", result.error
    assert result.variables[5025] == 3.0  # the last tool measured
    assert [result.variables[5030 + n] for n in (1, 2, 3)] == [1.0, 0.0, 1.0]
    assert {1, 3} <= {int(k) - 5400 for k in result.variables if 5401 <= int(k) <= 5499}


@settings(max_examples=300, deadline=None)
@given(st.lists(st.text(st.sampled_from(["T", "t", "1", "2", " ", "(", ")", '"', ";", "#", "X", "+"]), max_size=12),
                max_size=8))
def test_the_t_words_of_a_chunk_are_those_of_its_lines(lines: list[str]) -> None:
    """The check pass scans a chunk joined by LF at once: an unclosed comment or text ends with its line."""
    assert tools_used(("\n".join(lines),)) == tools_used(lines)
