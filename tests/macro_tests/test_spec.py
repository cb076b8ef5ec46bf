"""Reading test files: every mistake is FILE:LINE: error: ... before anything runs."""
from __future__ import annotations

from pathlib import Path

import pytest

from edingcnc_lang.testing.spec import Approx, TestFileError, discover, load_file


def write(tmp_path: Path, text: str, name: str = "test_x.toml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def error_of(path: Path) -> str:
    with pytest.raises(TestFileError) as caught:
        load_file(path)
    assert caught.value.exit_code == 65
    return caught.value.format()


def test_the_format_of_the_issue_loads_with_defaults_merged(tmp_path: Path) -> None:
    (tmp_path / "macro.cnc").write_text("Sub user_1\nEndSub\n")
    (tmp_path / "job.nc").write_text("M30\n")
    path = write(tmp_path, """
[defaults]
macro = "macro.cnc"
vars = { "4000" = 1 }
forbid.rapid_below_z = 2.0

[[test]]
name = "tool change measures the new tool"
job = "T2 M6\\nM30\\n"
vars = { "4520" = 2 }
answers = ["ok", "ok:#4100=5"]
probe = [{ z = -42.5 }, "miss"]
expect.vars = { "5008" = 2, "5021" = { approx = 20.0, tol = 0.01 } }
expect.position = { z = 10.0 }
expect.messages = ["length"]
expect.error = "G1167"
forbid.outside = [0, 0, -50, 400, 300, 100]
forbid.feed_with_spindle_off = true

[[test]]
name = "from a file"
job_file = "job.nc"
forbid.rapid_below_z = 5
""")
    first, second = load_file(path)
    assert first.name == "tool change measures the new tool" and first.line == 7
    assert first.macro == tmp_path / "macro.cnc" and first.job == "T2 M6\nM30\n"
    assert first.vars == {4000: 1.0, 4520: 2.0}  # [defaults] tables are merged key by key
    assert [a.ok for a in first.answers] == [True, True] and first.answers[1].values == {4100: 5.0}
    assert first.probe == ({"z": -42.5}, None)
    assert first.expect.vars == {5008: Approx(2.0), 5021: Approx(20.0, 0.01)}
    assert first.expect.position == {"z": Approx(10.0)} and first.expect.messages == ("length",)
    assert first.expect.error == "G1167"
    assert first.forbid.rapid_below_z == 2.0 and first.forbid.outside == (0, 0, -50, 400, 300, 100)
    assert first.forbid.feed_with_spindle_off
    assert second.job_file == tmp_path / "job.nc" and second.forbid.rapid_below_z == 5.0
    assert second.vars == {4000: 1.0}


def test_a_bare_number_is_equal_within_a_millionth() -> None:
    assert Approx(2.0).matches(2.0000009) and not Approx(2.0).matches(2.000002)
    assert Approx(20.0, 0.01).matches(20.009) and str(Approx(20.0, 0.01)) == "20 ± 0.01"


@pytest.mark.parametrize(("text", "expected"), [
    ('[[test]]\nname = "a"\njob = "M30"\nexpect.varz = { "5008" = 2 }\n',
     ":4: error: unknown key 'varz' in expect (it takes error, messages, position, vars)"),
    ('[[test]]\nname = "a"\njob = "M30"\n\n[[test]]\nname = "b"\njob = "M30"\nspeed = 3\n',
     ":8: error: unknown key 'speed'"),
    ('[[test]]\nname = "a"\njob = "M30\n', ":3: error: Illegal character"),
    ('[[test]]\nname = "a"\njob = "M30"\nvars = { "5380" = 0 }\n',
     ":4: error: vars: #5380 is a read-only system variable (use simulation = false for #5380)"),
    ('[[test]]\nname = "a"\njob = "M30"\nanswers = ["yes"]\n', ":4: error: answer 'yes': expected ok, cancel"),
    ('[[test]]\nname = "a"\njob = "M30"\nprobe = [{ q = 1 }]\n', ":4: error: unknown key 'q' in probe"),
    ('[[test]]\nname = "a"\njob = "M30"\n\n[[test]]\nname = "a"\njob = "M2"\n',
     ":5: error: two tests are called 'a' (the first at line 1)"),
    ('[[test]]\nname = "a"\n', ":1: error: test 'a': give the G-code to run as job"),
    ('[[test]]\nname = "a"\njob = "M30"\nmacro = "missing.cnc"\n', ":4: error: macro 'missing.cnc': no such file"),
    ('[[test]]\nname = "a"\njob = "M30"\nforbid.outside = [0, 0, 0, 1, 1]\n', ":4: error: forbid.outside must be"),
    ('[[test]]\nname = "a"\njob = "M30"\nexpect.vars = { "x1" = 2 }\n', ":4: error: expect.vars: 'x1' is not"),
    ('[[test]]\nname = "a"\njob = "M30"\nexpect.position = { z = "high" }\n', ":4: error: expect.position.z: 'high' is not a number"),
    ('[defaults]\nname = "x"\n[[test]]\nname = "a"\njob = "M30"\n', ":2: error: [defaults] cannot give a name"),
    ('[test]\nname = "a"\n', ":1: error: no [[test]] table"),
    ('title = "x"\n[[test]]\nname = "a"\njob = "M30"\n', ":1: error: unknown table or key 'title'"),
])
def test_mistakes_name_their_line(tmp_path: Path, text: str, expected: str) -> None:
    path = write(tmp_path, text)
    assert error_of(path).startswith(f"{path}{expected}")


def test_a_file_that_is_not_utf8_is_an_error(tmp_path: Path) -> None:
    path = tmp_path / "test_latin.toml"
    path.write_bytes('[[test]]\nname = "Fräse"\njob = "M30"\n'.encode("latin-1"))
    assert "must be UTF-8" in error_of(path)


def test_a_bom_and_crlf_line_ends_are_read(tmp_path: Path) -> None:
    path = tmp_path / "test_bom.toml"
    path.write_bytes('\ufeff[[test]]\r\nname = "Fräse"\r\njob = "M30"\r\nfoo = 1\r\n'.encode("utf-8"))
    assert error_of(path).endswith(":4: error: unknown key 'foo' (a test takes answers, expect, forbid, ini, job, "
                                   "job_file, macro, max_steps, name, probe, simulation, user_macro, vars)")


def test_discover_finds_test_files_below_folders_but_not_in_hidden_ones(tmp_path: Path) -> None:
    for name in ("a/test_one.toml", "a/b/test_two.toml", "a/other.toml", ".venv/test_no.toml", "pyproject.toml"):
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text("")
    assert discover([tmp_path]) == [tmp_path / "a/b/test_two.toml", tmp_path / "a/test_one.toml"]
    assert discover([tmp_path / "a/other.toml"]) == [tmp_path / "a/other.toml"]  # a file given is taken
