"""Hypothesis strategies for fuzzing: lines built from the grammar's pieces, and mutants of real files.

Grammar lines are mostly valid and reach deep into the parser, the interpreter and the linter;
mutants (bytes deleted, duplicated, swapped, or replaced by delimiters) of the shipped examples
and macro files cover what a clumsy edit or a broken transfer produces.
"""
from __future__ import annotations

from pathlib import Path

from hypothesis import strategies as st

ROOT = Path(__file__).resolve().parents[2]
SEED_FILES = sorted([*ROOT.glob("examples/**/*.nc"), *ROOT.glob("examples/**/*.cnc"), ROOT / "stdlib" / "macro.cnc",
                     *ROOT.glob("tests/lint/cases/*.nc")])
SEEDS = [path.read_bytes() for path in SEED_FILES if path.stat().st_size < 200_000]
INI_SEEDS = [path.read_bytes() for path in sorted(ROOT.glob("examples/**/cnc.ini"))]
ZHC_TABLE_SEEDS = [b"; ecnc ZHC height table\nnx 3\nny 2\nx0 0\ny0 0\ndx 10\ndy 10\n0.1 0.2 nan\n0.3 0.4 0.5\n"]

numbers = st.one_of(st.integers(-99999, 99999).map(str),
                    st.floats(-1e6, 1e6, allow_nan=False).map(lambda v: f"{v:.4f}"),
                    st.sampled_from(["0", "-0", ".5", "5.", "1e3", "9" * 320, "0." + "1" * 30]))
params = st.one_of(st.integers(-5, 6005).map(lambda i: f"#{i}"), st.sampled_from(["##1", "#[#1+1]", "#5380"]))
functions = st.sampled_from(["ABS", "ACOS", "ASIN", "COS", "EXP", "FIX", "FUP", "LN", "ROUND", "SIN", "SQRT", "TAN"])
operators = st.sampled_from(["+", "-", "*", "/", "**", " MOD ", " AND ", " OR ", " XOR ", "==", "<>", "<", ">=",
                             " EQ ", " ne "])


def _expr(children: st.SearchStrategy[str]) -> st.SearchStrategy[str]:
    return st.one_of(
        st.tuples(children, operators, children).map(lambda t: f"[{t[0]}{t[1]}{t[2]}]"),
        st.tuples(functions, children).map(lambda t: f"{t[0]}[{t[1]}]"),
        st.tuples(children, children).map(lambda t: f"ATAN[{t[0]}]/[{t[1]}]"),
        children.map(lambda c: f"-{c}"),
        children.map(lambda c: f"#[{c}]"),
    )


expressions = st.recursive(st.one_of(numbers, params), _expr, max_leaves=12)
letters = st.sampled_from("GMXYZABCIJKFSTPQRLNDHEUVW")
words = st.tuples(letters, st.one_of(numbers, expressions)).map("".join)
blocks = st.lists(st.one_of(words, st.tuples(params, expressions).map(lambda t: f"{t[0]} = {t[1]}")),
                  min_size=1, max_size=6).map(" ".join)
strings = st.text(st.characters(blacklist_characters='"\n\r'), max_size=20).map(lambda t: f'"{t}"')
# What the second hardening round (issue 28) found: pass counts, long names, digits other than
# ASCII, command arguments, arcs that sweep almost nothing, files of the run as job targets.
_ODD_DIGITS = ["²", "⁵", "١٠", "𝟏", "１", "1_0", "٣.٥"]
hostile_lines = st.one_of(
    st.sampled_from(["G18 G76 P1 Z-10 I19 J0.1 K0.6 H1000000000", "G76 P1 Z-10 I19 J0.1 K0.6 H5",
                     "G2 X0.000001 Y0 R5 F100", "G2 X10 Y0 R10000000 F100", "G2 X0 Y0 I5 J0 F100",
                     "G83 X0 Y0 Z-10 R1 Q0.00001 F100", "Exec", "ZHCINIT 10 2 2", "ZHCcheck", 'logfile "job.nc" 0',
                     'logfile "a\u202eb.txt" 0', "ZHCS job.nc", f"G1 X{'9' * 309} F100", "M56 P1", "G38.2 Z-1 F10"]),
    st.tuples(st.sampled_from(["GetJobDistance ", "GetToolInfo num ", "GetHeightControlVact ", "G1 X", "T", "#1 = "]),
              st.sampled_from(_ODD_DIGITS)).map("".join),
    st.tuples(st.sampled_from(["Sub ", "GoSub ", "GoTo ", "logfile ", "ZHCS "]), st.integers(1, 3000))
    .map(lambda t: t[0] + "a" * t[1]),
)
statements = st.one_of(
    blocks, blocks, blocks,
    st.tuples(st.sampled_from(["If", "While"]), expressions).map(lambda t: f"{t[0]} [{t[1]}]"),
    st.sampled_from(["Else", "EndIf", "EndWhile", "EndSub", "M30", "M2", "G4 P0", "%", "M6 T1", "M3 S1000"]),
    st.from_regex(r"Sub [a-z0-9_]{1,8}", fullmatch=True), st.from_regex(r"GoSub [a-z0-9_]{1,8}", fullmatch=True),
    st.tuples(st.sampled_from(["msg", "warnmsg", "logmsg", "errmsg", "dlgmsg"]), strings, st.one_of(st.just(""), params))
    .map(" ".join),
    st.tuples(st.sampled_from(["logfile", "logfile"]), st.one_of(strings, st.just("x.txt"), st.just("../../y")),
              st.sampled_from(["", " 0", " 1"])).map(lambda t: f"{t[0]} {t[1]}{t[2]}"),
    st.sampled_from(["home x", "homeTandem y", "KIN ON", "KIN CTRL 1 2", "tanknife on", "GetToolInfo first 4000",
                     "G38.2 Z-10 F50", "G81 X1 Y1 Z-1 R1 F100 L3", "G2 X1 Y1 R5 F100", "(MSG hello)", "; note",
                     "G10 L2 P1 X5", "G92 X0", "G43 H1", "G53 G0 Z0", "G20", "G21", "G91", "G90"]),
    st.text(max_size=30),  # anything at all
    hostile_lines,
)
programs = st.lists(st.tuples(statements, st.sampled_from(["\n", "\r\n"])).map("".join), max_size=25).map("".join)


@st.composite
def mutants(draw: st.DrawFn, seeds: list[bytes] = SEEDS) -> bytes:
    """A shipped file (of ``seeds``) with a few edits: bytes deleted, repeated, swapped or replaced by delimiters."""
    data = bytearray(draw(st.sampled_from(seeds)))
    for _ in range(draw(st.integers(1, 8))):
        if not data:
            break
        at = draw(st.integers(0, len(data) - 1))
        size = draw(st.integers(1, 40))
        kind = draw(st.sampled_from(["delete", "repeat", "insert", "swap", "byte"]))
        if kind == "delete":
            del data[at:at + size]
        elif kind == "repeat":
            data[at:at] = data[at:at + size] * draw(st.integers(1, 50))
        elif kind == "insert":
            data[at:at] = draw(st.sampled_from([b"[", b"]", b"(", b")", b'"', b"#", b"-", b";", b"\x00", b"\xff\xfe",
                                                b"\r", b"\n", b"If [1]\n", b"EndWhile\n", b"Sub x\n", b"M30\n",
                                                b"GoSub x\n", b"9" * 400, b"[" * 300, b"\xc3", b"nan", b"1e400",
                                                b"-1", b"[VARIABLES]\n"]))
        elif kind == "swap":
            other = draw(st.integers(0, len(data) - 1))
            data[at], data[other] = data[other], data[at]
        else:
            data[at] = draw(st.integers(0, 255))
    return bytes(data)
