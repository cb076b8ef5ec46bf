"""The compiled tokenizer (``_lexer.c``) gives exactly the tokens of the Python one, or gives up where
it gives up; the Python tokenizer is the reference.

Lines are built from the pieces the fast path meets (numbers near the digit limits, strings,
comments, operators, letters) and from arbitrary text (other characters, non-ASCII, lone
surrogates, newlines), read from a random start.
"""
from __future__ import annotations

import os
import subprocess
import sys

import pytest
from hypothesis import given
from hypothesis import strategies as st

from edingcnc_lang.syntax import fastparse
from edingcnc_lang.syntax.input_limits import MAX_NUMBER_DIGITS
from edingcnc_lang.syntax.plain_words import INTEGER_DIGITS

lexer = pytest.importorskip("edingcnc_lang._lexer", reason="the compiled tokenizer is not built")


def _python(text: str, pos: int) -> object:
    try:
        return fastparse._tokens_python(text, pos)
    except fastparse._GiveUp:
        return None


def _same(text: str, pos: int = 0) -> None:
    compiled = lexer.tokens(text, pos, INTEGER_DIGITS, MAX_NUMBER_DIGITS)
    if compiled is NotImplemented:  # not UTF-8: the wrapper hands it to the Python tokenizer
        with pytest.raises(UnicodeEncodeError):
            text.encode()
        return
    assert compiled == _python(text, pos), (text, pos)


def _digits(count: int) -> str:
    return "".join(str(i % 10) for i in range(count))


numbers = st.one_of(
    st.from_regex(r"[0-9]{1,4}(\.[0-9]{0,3})?|\.[0-9]{1,3}", fullmatch=True),
    st.sampled_from([INTEGER_DIGITS - 1, INTEGER_DIGITS, INTEGER_DIGITS + 1]).map(_digits),
    st.sampled_from([MAX_NUMBER_DIGITS - 1, MAX_NUMBER_DIGITS, MAX_NUMBER_DIGITS + 1])
      .map(lambda count: "1." + _digits(count)),
    st.sampled_from([MAX_NUMBER_DIGITS, MAX_NUMBER_DIGITS + 1]).map(lambda count: "." + _digits(count)),
)
pieces = st.one_of(
    numbers,
    st.sampled_from(["**", "==", "<>", "!=", "<=", ">=", "-", "+", "*", "/", "<", ">", "[", "]", "#", "=",
                     "!", ".", " ", "\t", "  ", "(", ")", ",", "_", "\r", "\n", "é", '"']),
    st.from_regex(r"[A-Za-z]{1,6}", fullmatch=True),
    st.from_regex(r'"[^"\n]{0,6}"', fullmatch=True),
    st.from_regex(r";[^\n]{0,8}", fullmatch=True),
    st.text(max_size=3),
)


@given(st.lists(pieces, max_size=14).map("".join), st.integers(0, 20))
def test_the_compiled_tokenizer_gives_the_python_tokens(text: str, pos: int) -> None:
    _same(text, min(pos, len(text)))


@given(st.text(max_size=30), st.integers(0, 40))
def test_any_text(text: str, pos: int) -> None:
    _same(text, min(pos, len(text)))


@pytest.mark.parametrize("text", [
    "#1 = [#2 * 2.5 + SIN[#3]] ; note", 'msg "é ü" #1 "ok"', "G1 X1.5 Y.5 Z-3.", "If [#1 <> 2] THEN",
    "", "   ", "; only", "#1 = 1 (x)", "a!b", "1..2", "x\ud800", 'msg "\ud800"', "; \ud800", "é", "X1 é",
    "1" * INTEGER_DIGITS + "." + "2" * MAX_NUMBER_DIGITS, "1" * (INTEGER_DIGITS + 1),
    "1." + "2" * (MAX_NUMBER_DIGITS + 1), '"open', "#1 ; a\nb",
])
@pytest.mark.parametrize("pos", [0, 1, 3])
def test_edges(text: str, pos: int) -> None:
    _same(text, min(pos, len(text)))


def test_the_fast_path_takes_the_compiled_tokenizer_unless_told_not_to() -> None:
    """``ECNC_PURE_PYTHON=1`` selects the Python tokenizer, as it selects the Python core."""
    code = "from edingcnc_lang.syntax import fastparse; print(fastparse._COMPILED is not None)"
    env = {k: v for k, v in os.environ.items() if k != "ECNC_PURE_PYTHON"}
    assert subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                          check=True).stdout.strip() == "True"
    assert subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env={**env, "ECNC_PURE_PYTHON": "1"}, check=True).stdout.strip() == "False"
