"""Outputs never over inputs, for every command (issue 43, item 1): each option that writes is tried
on each input of the same invocation (and on another output), and the input must come out byte for
byte as it went in, with exit 2 and a message naming both.  Then every output is whole or untouched:
an exception mid-write (Ctrl-C) and a full disk leave the previous file as it was, and the error
names the file."""
from __future__ import annotations

import errno
import os
from pathlib import Path

import pytest

from edingcnc_lang import outputs
from edingcnc_lang.errors import EcncError, UsageFailure
from tests.cli_runner import invoke

JOB = "G0 X10 Y15\nG1 Z-1 F300\nG1 X30\nG0 Z5\nM30\n"
STOCK = "0,0,-10,40,30,0"
TOOLS = '[tool.0]\nshape = "flat"\ndiameter = 6\nflute_length = 10\n'
MACRO = "Sub helper\n#4000 = 1\nEndSub\n"


def _snapshot(*paths: Path) -> dict[Path, bytes]:
    return {path: path.read_bytes() for path in paths}


def _refused(result: object, *names: object) -> None:
    assert result.exit_code == 2, result.output  # type: ignore[attr-defined]
    assert "Traceback" not in result.output  # type: ignore[attr-defined]
    message = result.stderr  # type: ignore[attr-defined]
    assert "is also an input" in message or "cannot be written twice" in message, message
    for name in names:
        assert str(name) in message, message


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    (tmp_path / "job.nc").write_text(JOB)
    (tmp_path / "macro.cnc").write_text(MACRO)
    (tmp_path / "tools.toml").write_text(TOOLS)
    (tmp_path / "cnc.ini").write_bytes(b"[VARIABLES]\r\n#4000 = 1.000000\r\n")
    return tmp_path


def _stl(path: Path) -> Path:
    np = pytest.importorskip("numpy")
    from edingcnc_lang.sim.stl import write_stl

    square = np.array([[[0, 0, 0], [40, 0, 0], [40, 30, 0]], [[0, 0, 0], [40, 30, 0], [0, 30, 0]]], dtype=float)
    write_stl(path, [square])
    return path


# --------------------------------------------------------------------------- the shared check

def test_the_check_compares_files_not_names(tmp_path: Path) -> None:
    source = tmp_path / "a.nc"
    source.write_text("x")
    os.link(source, tmp_path / "link.csv")
    os.symlink(source, tmp_path / "sym.csv")
    for spelling in (source, tmp_path / "link.csv", tmp_path / "sym.csv", tmp_path / "." / "a.nc"):
        with pytest.raises(UsageFailure, match="is also an input"):
            outputs.check_outputs({"-o": spelling}, [source])
    with pytest.raises(UsageFailure, match="cannot be written twice"):
        outputs.check_outputs({"-o": tmp_path / "new.png", "--stl": tmp_path / "sub" / ".." / "new.png"}, [])
    outputs.check_outputs({"-o": "-", "--stl": None, "--x": tmp_path / "other"}, [source, None, "-"])


# --------------------------------------------------------------------------- per command

@pytest.mark.parametrize("victim", ["job.nc", "macro.cnc", "cnc.ini", "tools.toml", "stock.stl", "part.stl"])
@pytest.mark.parametrize("option", ["--stl", "-o"])
def test_sim_never_writes_over_an_input(folder: Path, victim: str, option: str) -> None:
    _stl(folder / "stock.stl")
    _stl(folder / "part.stl")
    inputs = [folder / name for name in ("job.nc", "macro.cnc", "cnc.ini", "tools.toml", "stock.stl", "part.stl")]
    before = _snapshot(*inputs)
    result = invoke("sim", folder / "job.nc", "--stock-stl", folder / "stock.stl", "--compare-stl",
                    folder / "part.stl", "--tools", folder / "tools.toml", "--ini", folder / "cnc.ini",
                    "--macro", folder / "macro.cnc", option, folder / victim)
    _refused(result, option, folder / victim)
    assert _snapshot(*inputs) == before


def test_sim_refuses_one_file_for_both_outputs(folder: Path) -> None:
    result = invoke("sim", folder / "job.nc", "--stock", STOCK, "-o", folder / "x.png", "--stl", folder / "x.png")
    _refused(result, "-o", "--stl")
    assert not (folder / "x.png").exists()


@pytest.mark.parametrize("option", ["--junit", "json", "html"])
@pytest.mark.parametrize("victim", ["test_a.toml", "macro.cnc", "job.nc", "cnc.ini"])
def test_test_never_writes_over_an_input(folder: Path, option: str, victim: str) -> None:
    (folder / "test_a.toml").write_text('[[test]]\nname = "t"\nini = "cnc.ini"\nmacro = "macro.cnc"\n'
                                        'job_file = "job.nc"\n')
    inputs = [folder / name for name in ("test_a.toml", "macro.cnc", "job.nc", "cnc.ini")]
    before = _snapshot(*inputs)
    target = folder / victim
    if option == "html":  # the folder's index.html, linked to the input
        (folder / "cov").mkdir()
        os.link(target, folder / "cov" / "index.html")
        args = ["--cov-report", f"html:{folder / 'cov'}"]
    elif option == "json":
        args = ["--cov-report", f"json:{target}"]
    else:
        args = ["--junit", target]
    result = invoke("test", folder / "test_a.toml", *args)
    _refused(result)
    assert _snapshot(*inputs) == before


def test_test_refuses_two_reports_in_one_file_and_a_file_as_the_html_folder(folder: Path) -> None:
    (folder / "test_a.toml").write_text('[[test]]\nname = "t"\njob = "M30"\n')
    _refused(invoke("test", folder / "test_a.toml", "--junit", folder / "r.xml", "--cov-report",
                    f"json:{folder / 'r.xml'}"), "--junit")
    result = invoke("test", folder / "test_a.toml", "--cov-report", f"html:{folder / 'job.nc'}")
    assert result.exit_code == 2 and "is a file, not a folder" in result.stderr
    assert (folder / "job.nc").read_text() == JOB


@pytest.mark.parametrize("victim", ["old.svg", "new.nc", "macro.cnc", "cnc.ini"])
def test_diff_never_writes_over_an_input(folder: Path, victim: str) -> None:
    (folder / "old.svg").write_text(JOB)  # a job may have any name, also a picture's
    (folder / "new.nc").write_text(JOB.replace("X30", "X31"))
    inputs = [folder / name for name in ("old.svg", "new.nc", "macro.cnc", "cnc.ini")]
    before = _snapshot(*inputs)
    target = folder / victim
    if target.suffix not in (".svg", ".png", ".pdf"):
        os.link(target, folder / "linked.png")
        target = folder / "linked.png"
    result = invoke("diff", folder / "old.svg", folder / "new.nc", "--macro", folder / "macro.cnc",
                    "--ini", folder / "cnc.ini", "-o", target)
    _refused(result, "-o")
    assert _snapshot(*inputs) == before


@pytest.mark.parametrize("command", ["plot", "view"])
@pytest.mark.parametrize("victim", ["macro.cnc", "cnc.ini"])
def test_plot_and_view_never_write_over_a_file_the_run_reads(folder: Path, command: str, victim: str) -> None:
    if command == "plot":
        pytest.importorskip("matplotlib")
    inputs = [folder / name for name in ("job.nc", "macro.cnc", "cnc.ini")]
    before = _snapshot(*inputs)
    target = folder / ("o.png" if command == "plot" else "o.html")
    os.link(folder / victim, target)
    result = invoke(command, folder / "job.nc", "--macro", folder / "macro.cnc", "--ini", folder / "cnc.ini",
                    "-o", target)
    _refused(result, "-o")
    assert _snapshot(*inputs) == before


def test_view_diff_never_writes_over_old(folder: Path) -> None:
    (folder / "old.html").write_text(JOB)
    result = invoke("view", "--diff", folder / "old.html", folder / "job.nc", "-o", folder / "old.html")
    _refused(result, "-o")
    assert (folder / "old.html").read_text() == JOB


def test_kins_plot_never_writes_over_its_plugin(folder: Path) -> None:
    plugin = folder / "k.py"
    plugin.write_text("x = 1\n")
    os.link(plugin, folder / "k.png")
    result = invoke("kins", "plot", str(plugin), "-o", folder / "k.png")
    _refused(result, "-o")
    assert plugin.read_text() == "x = 1\n"


# --------------------------------------------------------------------------- whole or untouched

def test_an_exception_mid_write_keeps_the_previous_file(tmp_path: Path) -> None:
    target = tmp_path / "out.txt"
    target.write_text("previous\n")
    with pytest.raises(KeyboardInterrupt):
        with outputs.replacing(target) as handle:
            handle.write("half of the new")
            raise KeyboardInterrupt
    assert target.read_text() == "previous\n"
    assert os.listdir(tmp_path) == ["out.txt"]  # no temporary file left


def _full_disk(monkeypatch: pytest.MonkeyPatch) -> None:
    def full(fd: int) -> None:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(outputs, "_sync", full)


def test_a_full_disk_keeps_the_previous_file_and_names_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    target = tmp_path / "out.txt"
    target.write_text("previous\n")
    _full_disk(monkeypatch)
    with pytest.raises(EcncError, match=f"cannot write {target}: No space left on device"):
        outputs.write_text(target, "new\n")
    assert target.read_text() == "previous\n" and os.listdir(tmp_path) == ["out.txt"]


def test_a_new_file_keeps_the_usual_permissions_and_an_old_one_its_own(tmp_path: Path) -> None:
    outputs.write_text(tmp_path / "new.txt", "x")
    assert (tmp_path / "new.txt").stat().st_mode & 0o777 == 0o666 & ~outputs.umask()
    (tmp_path / "old.txt").write_text("x")
    os.chmod(tmp_path / "old.txt", 0o600)
    outputs.write_text(tmp_path / "old.txt", "y")
    assert (tmp_path / "old.txt").stat().st_mode & 0o777 == 0o600


def test_a_symbolic_link_keeps_pointing_at_the_new_file(tmp_path: Path) -> None:
    (tmp_path / "real.txt").write_text("old")
    os.symlink(tmp_path / "real.txt", tmp_path / "link.txt")
    outputs.write_text(tmp_path / "link.txt", "new")
    assert (tmp_path / "link.txt").is_symlink() and (tmp_path / "real.txt").read_text() == "new"


def test_sim_stl_interrupted_mid_write_keeps_the_previous_mesh(folder: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    pytest.importorskip("numpy")
    from edingcnc_lang.sim import stl

    mesh = folder / "cut.stl"
    assert invoke("sim", folder / "job.nc", "--stock", STOCK, "--stl", mesh).exit_code in (0, 1)  # 1: findings
    before = mesh.read_bytes()
    whole = stl.stock_mesh

    def cut_short(stock):  # type: ignore[no-untyped-def]
        yield next(iter(whole(stock)))
        raise KeyboardInterrupt

    monkeypatch.setattr(stl, "stock_mesh", cut_short)
    result = invoke("sim", folder / "job.nc", "--stock", "0,0,-10,40,30,-1", "--stl", mesh)
    assert result.exit_code == 130 and "Traceback" not in result.output
    assert mesh.read_bytes() == before
    assert sorted(os.listdir(folder)) == ["cnc.ini", "cut.stl", "job.nc", "macro.cnc", "tools.toml"]


def test_sim_stl_on_a_full_disk_keeps_the_previous_mesh_and_names_it(folder: Path,
                                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    pytest.importorskip("numpy")
    mesh = folder / "cut.stl"
    assert invoke("sim", folder / "job.nc", "--stock", STOCK, "--stl", mesh).exit_code in (0, 1)  # 1: findings
    before = mesh.read_bytes()
    _full_disk(monkeypatch)
    result = invoke("sim", folder / "job.nc", "--stock", "0,0,-10,40,30,-1", "--stl", mesh)
    assert result.exit_code == 70, result.output
    assert f"cannot write {mesh}: No space left on device" in result.stderr
    assert "standard output" not in result.stderr and mesh.read_bytes() == before


@pytest.mark.parametrize("kind", ["json", "html"])
def test_coverage_reports_on_a_full_disk_name_the_file(folder: Path, monkeypatch: pytest.MonkeyPatch,
                                                       kind: str) -> None:
    (folder / "test_a.toml").write_text('[[test]]\nname = "t"\nmacro = "macro.cnc"\njob = "GoSub helper\\nM30"\n')
    target = folder / ("cov.json" if kind == "json" else "cov")
    _full_disk(monkeypatch)
    result = invoke("test", folder / "test_a.toml", "--cov-report", f"{kind}:{target}")
    assert result.exit_code == 70, result.output
    assert f"cannot write {target}" in result.stderr and "standard output" not in result.stderr


@pytest.mark.parametrize("option", ["--trace", "--events", "--samples"])
def test_run_outputs_on_a_full_disk_keep_the_previous_file(folder: Path, monkeypatch: pytest.MonkeyPatch,
                                                          option: str) -> None:
    out = folder / "out.csv"
    out.write_text("previous\n")
    _full_disk(monkeypatch)
    result = invoke("run", folder / "job.nc", option, out)
    assert result.exit_code == 70 and f"cannot write {out}: No space left on device" in result.stderr
    assert out.read_text() == "previous\n"
    assert sorted(os.listdir(folder)) == ["cnc.ini", "job.nc", "macro.cnc", "out.csv", "tools.toml"]


def test_run_outputs_replace_the_old_file_whole(folder: Path) -> None:
    out = folder / "out.csv"
    out.write_text("x" * 100_000)
    assert invoke("run", folder / "job.nc", "--trace", out).exit_code == 0
    assert out.read_text().startswith("line,kind") and len(out.read_text()) < 1000


def test_kins_build_refuses_option_like_names_and_keeps_the_old_library(tmp_path: Path) -> None:
    for name in ("-fplugin=x.c", "@args.c"):
        (tmp_path / name).write_text("int x;\n")
        result = invoke("kins", "build", tmp_path / name)
        assert result.exit_code != 0 and "would reach the compiler as an option" in result.stderr, result.output
    library = tmp_path / "k.so"
    library.write_bytes(b"old library")
    (tmp_path / "k.c").write_text("this is not C\n")
    result = invoke("kins", "build", tmp_path / "k.c", "-o", library, "--cc", "cc")
    assert result.exit_code != 0 and library.read_bytes() == b"old library"
    assert sorted(os.listdir(tmp_path)) == ["-fplugin=x.c", "@args.c", "k.c", "k.so"]
