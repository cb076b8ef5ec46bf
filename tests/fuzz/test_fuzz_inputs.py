"""Fuzzing the inputs of the newer commands (issue 43, item 7): ``ecnc test``'s TOML files and ``-k``,
``ecnc sim``'s tools file and ``--stock``, ``ecnc diff``'s options.  Whatever they hold, reading
them ends in a value or the command's own error (an EcncError, a click usage error), never another
exception; a diff never writes over its jobs.

Runs under the derandomized ``ci`` profile like ``test_fuzz.py``; hunt for more with
``--hypothesis-profile=fuzz``.
"""
from __future__ import annotations

import json
import tempfile
from pathlib import Path

import click
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from edingcnc_lang.errors import EcncError
from edingcnc_lang.sim.stock import grid_size
from edingcnc_lang.sim.tools import load_tools
from edingcnc_lang.testing.session import keyword_matcher
from edingcnc_lang.testing.spec import load_file
from tests.cli_runner import invoke

from .strategies import mutants

RELAXED = settings(deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                                         HealthCheck.function_scoped_fixture])

# Values as a TOML file may write them: huge integers, specials, Unicode digits (in strings), nesting.
toml_numbers = st.one_of(
    st.integers(-10**6, 10**6).map(str), st.integers(10**300, 10**420).map(str),
    st.floats(allow_nan=True, allow_infinity=True).map(lambda v: repr(v).replace("e+", "e")),
    st.sampled_from(["inf", "-inf", "nan", "1e400", "-0.0", "0x1F", "1_000", "9" * 400, "0", "true"]))
toml_keys = st.one_of(
    st.sampled_from(["4000", "#5008", "\u00b2", "\u0665\u0660\u0660\u0668", "\uff15", "0", "5380", "6000",
                     "9" * 400, "-1", " 4001 ", "", "x", "1e3"]),
    st.text(max_size=6)).map(lambda key: json.dumps(key, ensure_ascii=False))
nested = st.integers(1, 400).map(lambda depth: "[" * depth + "1" + "]" * depth)
toml_values = st.one_of(toml_numbers, nested, st.text(max_size=8).map(lambda t: json.dumps(t, ensure_ascii=False)))

test_lines = st.one_of(
    st.tuples(toml_keys, toml_values).map(lambda t: f"vars = {{ {t[0]} = {t[1]} }}"),
    st.tuples(toml_keys, toml_values).map(lambda t: f"expect.vars = {{ {t[0]} = {t[1]} }}"),
    st.tuples(toml_values, toml_values).map(lambda t: f"expect.position = {{ x = {{ approx = {t[0]}, tol = {t[1]} }} }}"),
    st.lists(toml_values, min_size=0, max_size=7).map(lambda v: f"forbid.outside = [{', '.join(v)}]"),
    toml_values.map(lambda v: f"max_steps = {v}"),
    toml_values.map(lambda v: f"probe = [{{ z = {v} }}]"),
    toml_values.map(lambda v: f"forbid.rapid_below_z = {v}"),
    st.sampled_from(['answers = ["ok", "ok:#4100=5", "cancel"]', 'answers = ["ok:#' + "9" * 400 + '=1"]',
                     "simulation = 1", 'job_file = "missing.nc"', "[defaults]", "[[test]]", 'name = ""']))


@st.composite
def spec_files(draw: st.DrawFn) -> bytes:
    body = "\n".join(draw(st.lists(test_lines, max_size=6)))
    return f'[[test]]\nname = "t"\njob = "M30"\n{body}\n'.encode("utf-8", "surrogatepass")


TEST_SEED = b'[defaults]\nvars = { "4000" = 1 }\n[[test]]\nname = "t"\njob = "#4000 = 2\\nM30"\nexpect.vars = { "4000" = 2 }\n'
TOOLS_SEED = b'[tool.1]\nshape = "vee"\ndiameter = 6\nangle = 90\nflute_length = 10\nholder_length = 30\n'

tool_lines = st.one_of(
    toml_values.map(lambda v: f"diameter = {v}"), toml_values.map(lambda v: f"angle = {v}"),
    toml_values.map(lambda v: f"corner_radius = {v}"), toml_values.map(lambda v: f"flute_length = {v}"),
    toml_values.map(lambda v: f"holder_length = {v}"),
    st.sampled_from(['shape = "vee"', 'shape = "bull"', 'shape = "ball"', 'shape = 1', "unknown = 1"]))


@st.composite
def tools_files(draw: st.DrawFn) -> bytes:
    key = draw(toml_keys)
    body = "\n".join(draw(st.lists(tool_lines, max_size=6)))
    return f"[tool.{key}]\n{body}\n".encode("utf-8", "surrogatepass")


def _read(data: bytes, name: str, read) -> None:  # type: ignore[no-untyped-def]
    """``data`` written as ``name`` and read: only EcncError may come out."""
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / name
        path.write_bytes(data)
        try:
            read(path)
        except EcncError:
            pass


@RELAXED
@given(st.one_of(spec_files(), mutants([TEST_SEED])))
def test_test_files_never_crash_the_reader(data: bytes) -> None:
    _read(data, "test_x.toml", load_file)


@RELAXED
@given(st.one_of(tools_files(), mutants([TOOLS_SEED])))
def test_tools_files_never_crash_the_reader(data: bytes) -> None:
    _read(data, "tools.toml", load_tools)


keyword_tokens = st.sampled_from(["(", ")", "and", "or", "not", "a", "NOT", "\u0661", "", "((", "not not"])


@RELAXED
@given(st.one_of(st.lists(keyword_tokens, max_size=40).map(" ".join), st.text(max_size=60),
                 st.integers(150, 3000).map(lambda n: "(" * n + "a" + ")" * n),
                 st.integers(150, 3000).map(lambda n: "not " * n + "a")))
def test_k_expressions_are_a_matcher_or_a_value_error(expression: str) -> None:
    try:
        matcher = keyword_matcher(expression)
    except ValueError:
        return
    matcher("file::name")


stock_numbers = st.one_of(st.floats(allow_nan=True, allow_infinity=True).map(repr),
                          st.sampled_from(["1e308", "-1e308", "0", "1e9", "1e-300", "\u0661", "1_0", "", "9" * 400]))


@RELAXED
@given(st.lists(stock_numbers, min_size=0, max_size=8).map(",".join),
       st.one_of(st.floats(min_value=0.0, exclude_min=True), st.sampled_from([float("inf"), float("nan"), 1e-300])))
def test_stock_boxes_are_a_grid_or_a_usage_error(text: str, resolution: float) -> None:
    from edingcnc_lang.cli.sim_cmd import StockBox

    try:
        box = StockBox().convert(text, None, None)
    except click.BadParameter:
        return
    try:
        nx, ny = grid_size(box[:3], box[3:], resolution)  # type: ignore[arg-type]
    except EcncError:
        return
    assert 1 <= nx * ny <= 400_000_000


@pytest.fixture(scope="module")
def diff_jobs(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    folder = tmp_path_factory.mktemp("diff")
    old, new = folder / "old.nc", folder / "new.nc"
    old.write_text("G0 X1 Y1\nG1 X5 F300\nM30\n")
    new.write_text("G0 X1 Y1\nG1 X5.01 F300\nM30\n")
    return old, new


diff_values = st.one_of(st.floats(allow_nan=True, allow_infinity=True).map(repr),
                        st.sampled_from(["0", "-1", "1e-320", "1e308", "\u0661", "9" * 400, "", "x"]))


@settings(RELAXED, max_examples=30)
@given(tolerance=diff_values, limit=diff_values, as_json=st.booleans())
def test_diff_options_end_in_an_exit_code(diff_jobs: tuple[Path, Path], tolerance: str, limit: str,
                                          as_json: bool) -> None:
    old, new = diff_jobs
    before = (old.read_bytes(), new.read_bytes())
    result = invoke("diff", old, new, "--tolerance", tolerance, "--limit", limit, *(["--json"] if as_json else []))
    assert result.exit_code in (0, 1, 2), result.output
    assert "Traceback" not in result.output
    if as_json and result.exit_code != 2:
        json.loads(result.stdout)
    assert (old.read_bytes(), new.read_bytes()) == before
