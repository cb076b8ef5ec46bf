"""The registry of diagnostic codes: one table, shared by the parser, the checker and the linter.

Codes are stable public names (scripts filter on them).  The first letter
groups them: E syntax, S structure, V expressions and variables, D dialogs,
G G/M-code usage, F files, C configuration; K is ``ecnc kins check``'s findings about a
kinematics plug-in (``KINS_CODES``, not lint codes).
"""
from __future__ import annotations


from enum import Enum
from edingcnc_lang.records import record


class Severity(str, Enum):
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
