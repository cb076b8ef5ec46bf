"""The input limits every stage relies on: one table, documented in docs/language.md#limits.

Real jobs stay far below each limit; they exist so that hostile or broken input gets a clear
error found in linear time instead of a traceback, a hang or unbounded memory.  Each limit is
checked once, where the input is first read, so the later stages (builder, evaluator, printer,
linter) may recurse over what they are given.
"""
from __future__ import annotations

import re
from itertools import islice

# Characters on one source line.  EdingCNC itself reads at most 1055 (lint rule F602); longer
# lines are still parsed up to this limit so that generated files can be checked and run.
MAX_LINE_LENGTH = 65_536

# The RS274/NGC limits the manual states (3.4, p. 7) and rs274 enforces: a G-code line (words and
# assignments) of at most 256 characters, and a line number N of at most five digits ("000009 ist
# nicht in Ordnung").  Macro statements (dlgmsg, msg) may be longer: real 4.03 macros hold dialogs
# of 258..318 characters, which the controller runs (docs/dialect.md).
MAX_GCODE_LINE = 256
LINE_NUMBER_DIGITS = 5

# Operators in the code of one line: signs, '#', arithmetic, comparisons, logic, and function
# calls ('SQRT['), each counted once.  Every level of an
# expression tree needs one of them, so this bounds how deeply expressions nest, and printing a
# tree back never adds any (the printer's extra brackets are not operators).
MAX_LINE_OPERATORS = 100

# '[' open at once on one line; the printer's brackets stay below it for any accepted line.
MAX_BRACKET_DEPTH = 200

# If, While and Sub blocks open inside each other in one file.
MAX_BLOCK_DEPTH = 50

# Digits in a row in a number (before or after its point).  Every double fits: 309 digits
# before the point for 1.8e308, 341 after it for the smallest, 4.9e-324, written out in full as
# the printer does; a longer run is a mistake, and would slow the lexers down.
MAX_NUMBER_DIGITS = 400

# Digits before the point of a number the fast paths (plain_words.FAST_NUMBER, and the compiled
# scans, which are given it) take: 300 always make a finite double; a longer integer part is left to
# the parser, which reads it exactly.
INTEGER_DIGITS = 300

# What counts towards MAX_LINE_OPERATORS: two-character operators once, word operators wherever
# they stand (also inside names: the count only has to be an upper bound).  Strings and
# comments do not count.
# A function call is tried only where a run of letters starts, so a long name is scanned once, not
# once for every letter in it (which took minutes for a 65,000-letter line).
_OPERATOR = re.compile(r"==|<>|!=|<=|>=|\*\*|[#+\-*/<>=!]|(?<![A-Za-z])[A-Za-z]{2,}[ \t]*\[|and|or|xor|mod|eq|ne|gt|ge|lt|le",
                       re.IGNORECASE)
_BRACKET = re.compile(r"[\[\]]")
_DIGITS = re.compile(r"[0-9]+")
_NOT_CODE = re.compile(r'"[^"\n]*"|\([^)\n]*\)|;.*')

# Statements, loop turns and canned-cycle holes and pecks one run may execute unless told
# otherwise (--max-steps, RunOptions.max_steps): far more than any real job (a million-line job
# is a million steps), and a runaway While [1] stops in a minute or two with a clear error.
DEFAULT_MAX_STEPS = 100_000_000

# Bytes of a cnc.ini.  A real one holds a few hundred lines (about 50 KB); reading one takes some
# 50 times its size in memory, so a larger file (a wrong --ini, a log renamed) is refused.
MAX_INI_BYTES = 1024 * 1024

# Nodes of a ZHC height table (ZHCINIT, ZHCINITEX, or a table ZHCL reads): a probed grid holds a
# few hundred; the table is allocated whole, so its header is checked against this first.
MAX_ZHC_POINTS = 100_000

# Bytes one run may write into its log files (logmsg): a real job logs a few lines per part; a
# logmsg in a runaway loop would otherwise fill the disk before the step budget stops it.
MAX_LOG_BYTES = 64 * 1024 * 1024

# Samples of one move when a run samples the trajectory (kinematics, --samples, the planner):
# each needs a few hundred bytes while the move is checked, so this bounds the memory; at the
# usual 200 Hz it is a move of 83 minutes.
MAX_MOVE_SAMPLES = 1_000_000

# Passes of one G76 thread, cut passes and spring passes (H) together: a real thread takes a few
# dozen.  The passes are counted from the words before any is computed, so H1000000000 is an
# error at once, not gigabytes.
MAX_THREAD_PASSES = 10_000

# Pecks of one G73/G83 hole (depth / Q), counted before the pecks are listed: a deep hole takes a
# few hundred.
MAX_CYCLE_PECKS = 100_000

# The range of an axis's maxVelocity (mm/s, deg/s) and maxAcceleration (mm/s^2) in a cnc.ini:
# the planner squares them and divides by them, so at 1e-200 mm/s a move took 0 s, at 1e-320
# mm/s^2 NaN s, and at 1e308 both overflowed.  A micrometre per second is slower than any real
# axis, a thousand kilometres per second faster.
MIN_AXIS_RATE = 1e-6
MAX_AXIS_RATE = 1e9

# The largest coordinate or height (mm) in a height table (ZHCL, ZHCADDPOINT) or a probe surface:
# a thousand kilometres.  Beyond it a table's range and mean overflowed (ZHCcheck printed "range
# inf") and the bilinear interpolation gave inf.
MAX_HEIGHT_MAP_VALUE = 1e9

# Sample poses of ``ecnc kins check``/``compare`` (--samples): each costs some kilobytes of poses,
# joints and Jacobians while the checks run; the default is 2,000, 1e9 asked for tens of GB.
MAX_CHECK_SAMPLES = 200_000

# Grid points per side of ``ecnc kins plot`` (--resolution): three slices of N x N poses; the
# default is 60, 1e6 asked for 3e12 poses.
MAX_ENVELOPE_RESOLUTION = 1_000

# The language server: characters of a document it analyses (a 50 MB document took 2.7 GB and
# 32 s to its first hover; a larger one gets one diagnostic saying so, ecnc lint still reads it),
# and the tabSize it indents with (2e9 asked for gigabytes of spaces).
MAX_LSP_DOCUMENT_CHARS = 10_000_000
MAX_TAB_SIZE = 16

# Lengths of ``ecnc sim``: the stock's corners (--stock) and a tool's sizes (--tools), in mm, at most
# a thousand kilometres and (a size) at least a micrometre; a vee tool's angle at least one degree.
# Beyond them the grid's cell count overflowed (--stock 0,0,-5,1e308,1e308,0), a 1e200 mm tool
# squared its radius to inf, and a 1e-300 degree vee had an infinite cone.
MAX_SIM_LENGTH = 1e9
MIN_SIM_SIZE = 1e-6
MIN_VEE_ANGLE = 1.0

# Jobs of ``ecnc test -j``: a worker process each; more than this is a typo (-j 1000000).
MAX_TEST_JOBS = 256

Problem = tuple[str, str, int]  # code, message, column


def _blank(match: re.Match[str]) -> str:
    return " " * len(match.group())


# Each operator, '[' and digit is at least one character: a line this short passes every limit.
SHORTEST_PROBLEM = min(MAX_LINE_OPERATORS, MAX_BRACKET_DEPTH, MAX_NUMBER_DIGITS)


def line_problem(text: str) -> Problem | None:
    """What makes a line (not longer than MAX_LINE_LENGTH) too complex to parse, if anything.

    One linear pass each: the operator past MAX_LINE_OPERATORS, the '[' past MAX_BRACKET_DEPTH,
    a run of digits past MAX_NUMBER_DIGITS; strings and comments are left out.
    """
    if len(text) <= SHORTEST_PROBLEM:  # every limit needs more characters than that to be passed
        return None
    code = _NOT_CODE.sub(_blank, text) if ('"' in text or "(" in text or ";" in text) else text
    past = next(islice(_OPERATOR.finditer(code), MAX_LINE_OPERATORS, None), None)
    if past is not None:
        return ("E111", f"expression too complex: more than {MAX_LINE_OPERATORS} operators, '#' signs and "
                "function calls on one line (the nesting limit); compute parts into #variables first",
                past.start() + 1)
    depth = 0
    for bracket in _BRACKET.finditer(code):
        depth += 1 if bracket.group() == "[" else -1
        if depth > MAX_BRACKET_DEPTH:
            return ("E111", f"brackets nested more than {MAX_BRACKET_DEPTH} deep (the nesting limit); compute "
                    "parts into #variables first", bracket.start() + 1)
    for run in _DIGITS.finditer(code):
        if run.end() - run.start() > MAX_NUMBER_DIGITS:
            return ("E113", f"number with more than {MAX_NUMBER_DIGITS} digits in a row (the limit); a value "
                    "keeps 17 significant digits: write it shorter", run.start() + 1)
    return None
