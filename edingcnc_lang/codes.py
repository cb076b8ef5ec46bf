"""The registry of diagnostic codes: one table, shared by the parser, the checker and the linter.

Codes are stable public names (scripts filter on them).  The first letter
groups them: E syntax, S structure, V expressions and variables, D dialogs,
G G/M-code usage, F files, C configuration; K is ``ecnc kins check``'s findings about a
kinematics plug-in (``KINS_CODES``, not lint codes).
"""
from __future__ import annotations


import re
from enum import Enum
from functools import cache
from edingcnc_lang.records import record


class Severity(str, Enum):
    """How bad a finding is: an error (the controller refuses it) or a warning (it runs, likely wrongly)."""

    ERROR = "error"
    WARNING = "warning"


@record(frozen=True)
class Code:
    """One diagnostic code of the registry: the stable code, its severity and a one-line summary."""

    code: str
    severity: Severity
    summary: str
    versions: frozenset[str] = frozenset()  # the controller versions it describes (empty: all)


def _table(*rows: tuple[str, Severity, str]) -> dict[str, Code]:
    return {code: Code(code, severity, summary, VERSIONS.get(code, frozenset()))
            for code, severity, summary in rows}


# Findings that describe one controller version's behaviour (ecnc lint --target).
VERSIONS: dict[str, frozenset[str]] = {
    "F600": frozenset({"5"}),  # G1290 "Macro does not specify unit" is EdingCNC 5's
}


E, W = Severity.ERROR, Severity.WARNING

CODES: dict[str, Code] = _table(
    ("E100", E, "syntax error: the line is not a valid statement"),
    ("E101", E, "unclosed '[' in an expression"),
    ("E102", E, "unbalanced ']' without a matching '['"),
    ("E103", E, "unclosed '(' comment"),
    ("E104", E, "unterminated string"),
    ("E105", E, "expression without brackets after a word (write X[10+5], not X10+5)"),
    ("E106", E, "If/While condition is not one bracketed expression (EdingCNC G1171)"),
    ("E107", E, "unknown KIN mode"),
    ("E108", E, "word letter without a value"),
    ("E109", E, "invalid @unit directive"),
    ("E110", E, "line longer than the parser's limit (65,536 characters)"),
    ("E111", E, "expression nested too deeply: over 100 operators or 200 open brackets on a line"),
    ("E112", E, "blocks (If, While, Sub) nested more than 50 deep"),
    ("E113", E, "number with more than 400 digits in a row"),
    ("E114", E, "G-code line longer than 256 characters (manual 3.4, rs274)"),
    ("E115", E, "line number with more than five digits (manual 3.4.1, rs274)"),
    ("E116", E, "nested comment: a '(' inside a ( ) comment (manual 3.4.4, rs274)"),
    ("S200", E, "EndIf without If"),
    ("S201", E, "Else without If"),
    ("S202", E, "EndWhile without While"),
    ("S203", E, "EndSub without Sub"),
    ("S204", E, "block not closed: If without EndIf, While without EndWhile, Sub without EndSub"),
    ("S205", E, "Sub defined inside another Sub"),
    ("S206", E, "second Else in one If"),
    ("S207", E, "Sub defined twice in one file (names are case-insensitive)"),
    ("S208", E, "GoSub to a sub that is not defined in the file or its macro files"),
    ("S209", W, "code after an unconditional M30, M2 or errmsg in the same block never runs"),
    ("S210", W, "Sub in a job file that nothing calls"),
    ("V300", E, "parameter index outside 1..5999"),
    ("V301", E, "write to a read-only system variable"),
    ("V302", W, "volatile variable (#27..#3999) read but never written anywhere"),
    ("V303", W, "#1..#26 read in an M-code sub after a call that may have overwritten them"),
    ("V304", W, "extra ']' after an If/While condition"),
    ("V305", W, "one number named for two different things by subs that do not run each other"),
    ("V306", W, "variable read where no write can have run (writes in an uncalled sub, or later in the job)"),
    ("V307", W, "a number from #5000 up that the manual reserves or gives no meaning"),
    ("V308", E, "malformed ;@var annotation or variables.toml entry"),
    ("D400", E, "dlgmsg with more than 15 fields"),
    ("D401", E, "dlgmsg label longer than 31 characters"),
    ("D402", E, "dlgmsg items out of order: a value where a label belongs (EdingCNC G1167)"),
    ("D403", E, "dlgmsg field index written with '#' (EdingCNC G1167)"),
    ("G500", E, "two words of one modal group on a line"),
    ("G501", E, "G53 without G0, G1 or G38.2 on the line"),
    ("G502", E, "G2/G3 arc without I, J, K or R"),
    ("G503", E, "feed rate 0 on a feed or probe move (EdingCNC G1516)"),
    ("G504", W, "G38.2 outside the simulation guard"),
    ("G506", E, "tool number over 99"),
    ("G507", E, "more than 4 M words on a line"),
    ("G508", W, "arc with the compensated tool inside it that is not larger than the tool radius"),
    ("G509", E, "a G code the controller does not know (G7/G8: see diameterProgramming)"),
    ("G510", W, "an M code with no built-in meaning and no Sub mNNN in the file or its macro files"),
    ("G520", E, "G76 I zero or negative: LinuxCNC's offset form; EdingCNC reads I as the crest diameter"),
    ("G521", W, "spindle speed outside the ini's spindleNmin..spindleNmax: the controller clamps it"),
    ("F600", E, "macro file without an @unit directive on its first line (EdingCNC G1290)"),
    ("F601", W, "line longer than 256 characters"),
    ("F602", E, "line longer than 1055 characters"),
    ("F603", E, "line of prose text that is not a statement"),
    ("C700", E, "kinematics user output variables out of range in cnc.ini"),
    ("C701", E, "invalid value in cnc.ini"),
    ("C702", W, "value in cnc.ini the toolchain does not know (an unknown machineType): run with a default"),
)


# Codes no rule reports any more, with the reason.  Codes are never reused, and these stay accepted
# by --select, --ignore and noqa (they match nothing), so scripts that name them keep working.
RETIRED: dict[str, str] = {
    "G505": "retired: it asked for a check of #5067 after every G38.2, but a G38.2 whose probe does not "
            "touch (even slightly past its target) is a run error (manual 3.6.10.1), so the job never "
            "reaches such a check with #5067 = 0. G38.2 is the dialect's only probe move.",
}

# K: ``ecnc kins check`` findings about a kinematics plug-in, code -> (check, one-line summary).  Kept
# apart from CODES because ``ecnc lint`` never reports them (no --select K); ``ecnc help K101`` explains
# them from docs/kinematics.md.  The digit after K groups them by check: 1 round trip, 2 continuity,
# 3 singularities, 4 domain, 5 control and state, 6 compiled libraries.
KINS_CODES: dict[str, tuple[str, str]] = {
    "K101": ("round trip", "forward(inverse(p)) does not come back to p"),
    "K102": ("round trip", "inverse(forward(j)) does not come back to the joints j the inverse gave"),
    "K103": ("round trip", "forward fails on joints that the inverse produced"),
    "K201": ("continuity", "neighbouring poses give joints that jump (a branch switch or a discontinuity)"),
    "K202": ("continuity", "a joint angle wraps around (a jump of a whole turn) inside the workspace"),
    "K301": ("singularity", "the Jacobian's condition number explodes: a singular pose inside the workspace"),
    "K401": ("domain", "NaN or infinite values instead of a KinematicsDomainError"),
    "K402": ("domain", "an exception other than KinematicsDomainError"),
    "K403": ("domain", "no pose of the workspace is reachable"),
    "K501": ("control", "a control call failed (KIN ON/OFF returned non-zero, or an unknown ID raised)"),
    "K502": ("control", "the user output is not at most 12 finite numbers"),
    "K503": ("state", "the same pose gives other joints later: hidden state drifts"),
    "K504": ("state", "switching the kinematics OFF and ON again changes its answers"),
    "K601": ("compiled", "the library cannot be loaded or lacks a required export"),
    "K602": ("compiled", "a call crashed the process"),
    "K603": ("compiled", "KinematicsType or KinematicsVersion returns a value the header does not allow"),
    "K604": ("compiled", "a call did not return (hung)"),
}


def lookup(code: str) -> Code:
    """The registered code; an unknown code is a programming error."""
    return CODES[code]


# R: errors that stop a run (``ecnc run``, the embedding API, ``ecnc debug``'s exception info).  An
# error's code comes from its kind (errmsg, Ctrl-C, cancel, a callback, the ini, a plug-in) or, for the
# machine's own refusals, from the first row whose pattern is found in its message: the messages are
# written once, where the error is raised, and tests/api/test_runtime_codes.py proves every message the
# package can raise has a row other than R899.  ``ecnc help R812`` explains a code from docs/errors.md.
@record(frozen=True)
class RuntimeCode:
    """One runtime error code: the stable code, a one-line summary and the message patterns it covers."""

    code: str
    summary: str
    patterns: tuple[str, ...] = ()  # regular expressions searched in the message (case-sensitive)


def _runtime(*rows: tuple[str, str, tuple[str, ...]]) -> dict[str, RuntimeCode]:
    return {code: RuntimeCode(code, summary, patterns) for code, summary, patterns in rows}


RUNTIME_CODES: dict[str, RuntimeCode] = _runtime(
    # by kind (errors.py's classes): no pattern
    ("R800", "errmsg: the job stopped itself with a message", ()),
    ("R801", "interrupted (Ctrl-C)", ()),
    ("R802", "cancelled by the embedding program (Run.cancel)", ()),
    ("R803", "a callback of the embedding program raised", ()),
    ("R804", "the machine configuration (cnc.ini) cannot be used", ()),
    ("R805", "a kinematics plug-in failed", ()),
    ("R806", "a command line, option or input that cannot be used (exit 2)", ()),
    # the machine's refusals, by message (first match wins: the more specific rows first)
    ("R810", "step budget exhausted (an endless loop?)", (r"^step budget of",)),
    ("R811", "blocks or sub calls nested too deeply", (r"nested (too deeply|deeper than)", r"defined inside a block")),
    ("R812", "GoSub to a sub that does not exist", (r"^GoSub .*: no Sub",)),
    ("R813", "arithmetic without a finite result (division by zero, a power, a function's domain)",
     (r"division by zero", r"fractional power", r"has no finite value", r"is not a finite number",
      r"^\S+\[.*\]: ")),
    ("R814", "a parameter number that does not exist or is not whole",
     (r"^parameter (number|#)", r"is not a parameter", r"^the answer sets #")),
    ("R815", "a write to a read-only system variable", (r"read-only system variable",)),
    ("R816", "outside the machine's limits (joints, Cartesian limits, velocity, the tool-change area)",
     (r"outside its limits", r"outside the Cartesian limits", r"above its maxVelocity", r"would make joint .* jump",
      r"tool-change area", r"no move could start", r"more than its maximum velocity")),
    ("R817", "words that cannot go together on one line (modal groups, repeated words, too many M words)",
     (r"same modal group", r"appears twice on this line", r"M words on one line", r"may hold only its letter",
      r"takes either .* not both", r"not .* together", r"takes no .* word", r"^G80 cancels", r"is already running",
      r"cannot share a line")),
    ("R818", "a word a code needs is missing or out of range",
     (r"needs ", r"must be ", r"must lie ", r"must not be", r"is below the hole", r"is negative",
      r"write .*1 to turn", r"expects ", r"is less than", r"at least .* mm", r"^negative feed rate",
      r"^spindle speed", r"^L \(repeat", r"without a motion mode", r"^G53 moves", r"^G38\.2 needs",
      r"would flatten", r"is a whole number 1\.\.9")),
    ("R819", "feed rate missing or zero on a feed move", (r"^feed rate is 0", r"^feed per revolution")),
    ("R820", "the spindle must turn for this move", (r"needs the spindle turning",)),
    ("R821", "a tool that does not exist", (r"^tool T.* does not exist", r"no such tool", r"is a tool number")),
    ("R822", "cutter compensation cannot do this (gouge, on already, not allowed while on)",
     (r"cutter compensation",)),
    ("R823", "probing failed (no contact, target too close)", (r"probe tripping", r"^G38\.2 ")),
    ("R824", "a canned cycle cannot run as written", (r"^canned cycles ", r"^G87 ")),
    ("R825", "G68 rotation, G51 scaling or Z height compensation cannot follow this arc or move",
     (r"cannot be turned by G68", r"cannot be scaled", r"height compensation", r"^ZHC", r"height table",
      r"clamped \(M26\)")),
    ("R826", "threading (G33, G33.1, G76) cannot run as written", (r"^G76 ", r"^G33", r"the pitch")),
    ("R827", "a file the run writes or reads cannot be used (log file, trace, Exec)",
     (r"^cannot (write|read|run)", r"log file", r"^logmsg: ", r"^logfile ", r"^Exec ", r"another run is writing")),
    ("R828", "a named command or device given wrong arguments (modbus, GetToolInfo, M54, M22)",
     (r"^modbus", r"^a modbus", r"^GetToolInfo", r"^M\d+ [A-Z]", r"^M\{", r"^PrepareLinDeltaHome", r"\(got ")),
    ("R829", "a kinematics mode or control call failed, or a pose the kinematics cannot reach",
     (r"^unknown (KIN|kinematics) mode", r"^KIN ", r"^kinematics ", r"\(kinematics [^)]*\)$")),
    ("R830", "something this simulator does not support", (r"not supported by this simulator",
                                                           r"out of memory")),
    ("R831", "an arc that cannot be made as written (radius, centre and end do not agree)",
     (r" in the \S+ plane$",)),
    ("R899", "any other run-time error", ()),
)

RUNTIME_BY_KIND: dict[str, str] = {"errmsg": "R800", "interrupted": "R801", "cancelled": "R802",
                                   "callback": "R803", "configuration": "R804", "plugin": "R805",
                                   "usage": "R806"}


@cache
def _runtime_patterns() -> tuple[tuple[str, re.Pattern[str]], ...]:
    return tuple((row.code, re.compile(pattern)) for row in RUNTIME_CODES.values() for pattern in row.patterns)


def runtime_code(kind: str, message: str) -> str:
    """The stable code of an error that stopped a run: by its kind, else by its message's row."""
    code = RUNTIME_BY_KIND.get(kind)
    if code is not None:
        return code
    for code, pattern in _runtime_patterns():
        if pattern.search(message):
            return code
    return "R899"
