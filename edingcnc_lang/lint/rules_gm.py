"""G rules: G and M words on one line, and probing.

Only literal G/M numbers are checked (``G[#1]`` is decided at run time).  There is no rule asking for
a check of #5067 after G38.2 (the retired G505): a probe that does not touch is a run error
(manual 3.6.10.1), so the job never goes on to such a check with #5067 = 0.
"""
from __future__ import annotations

from collections.abc import Iterator, Mapping

from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.machine.tables import (
    G_GROUPS,
    LATHE_ONLY_G,
    M_GROUPS,
    MAX_M_WORDS,
    MAX_TOOL,
    UNKNOWN_G_HINTS,
    code_key,
    code_name,
    lathe_code_message,
    same_line_winner,
    m_sub_name,
)
from edingcnc_lang.lint.evaluate import evaluate
from edingcnc_lang.lint.facts import BlockCodes, Code
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.project import Project
from edingcnc_lang.lint.registry import at, rule

PROBE = code_key(38.2)
ARCS = frozenset(code_key(c) for c in (2, 3))
G53 = code_key(53)
G53_MOTIONS = frozenset(code_key(c) for c in (0, 1, 38.2))  # G53 G38.2: probing in machine coordinates
FEED_MOVES = frozenset(code_key(c) for c in (1, 2, 3, 38.2, 73, 74, 76, 81, 82, 83, 84, 85, 86, 87, 88, 89))
AXES = frozenset("XYZABC")
CENTRE = frozenset("IJKR")


@rule("G500")
def modal_conflict(file: SourceFile, project: Project) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    for block in project.facts(file).coded:
        if len(block.g) > 1:  # most lines: no two codes to conflict
            _conflicts("G", block.g, G_GROUPS, found)
        if len(block.m) > 1:
            _conflicts("M", block.m, M_GROUPS, found)
    return found


def _conflicts(letter: str, codes: tuple[Code, ...], groups: Mapping[int, str], found: list[Diagnostic]) -> None:
    """Two codes of one modal group on a line, unless one of them wins on the same line (G only)."""
    seen: dict[str, int] = {}
    for key, word in codes:
        group = groups.get(key)
        if group is None:
            continue
        first = seen.setdefault(group, key)
        winner = same_line_winner(group, first, key) if letter == "G" and first != key else None
        if winner is not None:
            seen[group] = winner
        elif first != key:
            found.append(at("G500", f"{code_name(letter, first)} and {code_name(letter, key)} are both in "
                            f"the {group.replace('_', ' ')} group: one line may hold only one of them; "
                            "put them on separate lines", word.span))


@rule("G501", "G502", "G503", "G506", "G507")
def word_combinations(file: SourceFile, project: Project) -> list[Diagnostic]:
    found: list[Diagnostic] = []
    for codes in project.facts(file).coded:
        _line_words(codes, found)
    return found


def _line_words(codes: BlockCodes, found: list[Diagnostic]) -> None:
    """G501..G503, G506, G507 of one line; a code's word is the last one with that number, and the
    last F and T words count, as the controller reads a line (one pass each: this runs for most lines)."""
    block = codes.block
    last = {word.letter: word for word in block.words}  # each letter's last word
    feed, tool = last.get("F"), last.get("T")
    if codes.g:  # G501..G503 are about G codes
        axes, centre = not AXES.isdisjoint(last), not CENTRE.isdisjoint(last)
        g53 = arc = arc_word = move = None
        g53_motion = False
        for key, word in codes.g:
            if key == G53:
                g53 = word
            if key in G53_MOTIONS:
                g53_motion = True
            if key in ARCS and (arc is None or key == arc):  # the first arc code, its last word
                arc, arc_word = key, word
            if move is None and key in FEED_MOVES:
                move = key
        if g53 is not None and not g53_motion:
            found.append(at("G501", "G53 (machine coordinates) needs G0, G1 or G38.2 on the same line, e.g. "
                            "G53 G0 Z0", g53.span))
        if arc is not None and arc_word is not None and axes and not centre:
            found.append(at("G502", f"{code_name('G', arc)} arc needs its centre (I, J, K) or a radius (R)",
                            arc_word.span))
        if feed is not None and move is not None and evaluate(feed.value) == 0:
            found.append(at("G503", f"F0 on a {code_name('G', move)} move: give a feed rate above 0 "
                            "(EdingCNC G1516: incorrect feed rate)", feed.span))
    number = evaluate(tool.value) if tool else None
    if tool is not None and number is not None and number > MAX_TOOL:
        found.append(at("G506", f"T{number:g}: tool numbers go up to {MAX_TOOL}", tool.span))
    if len(block.words) > MAX_M_WORDS:
        m_words = [w for w in block.words if w.letter == "M"]
        if len(m_words) > MAX_M_WORDS:
            found.append(at("G507", f"{len(m_words)} M words on one line; the controller takes at most "
                            f"{MAX_M_WORDS}: split the line", m_words[MAX_M_WORDS].span))


@rule("G509")
def unknown_g_code(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """A literal G number outside the dialect's tables stops the job at run time (``unknown G code``),
    and so does a lathe code on the mill the ``--ini`` describes."""
    for block in project.facts(file).coded:
        for key, word in block.g:
            if key not in G_GROUPS:
                hint = UNKNOWN_G_HINTS.get(key)
                yield at("G509", f"unknown G code {code_name('G', key)}" + (f": {hint}" if hint else ""), word.span)
            elif project.mill and key in LATHE_ONLY_G:
                yield at("G509", lathe_code_message(key), word.span)


@rule("G510")
def m_code_without_meaning(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """An M code the controller has no action for runs the Sub mNNN of its number (manual 3.7.13);
    without one it does nothing, which the run reports too."""
    for block in project.facts(file).coded:
        for key, word in block.m:
            if key in M_GROUPS:  # most M codes: a built-in
                continue
            name = m_sub_name(key)
            if name is not None and project.resolve(file, name) is not None:
                continue
            yield at("G510", f"{code_name('M', key)} has no built-in meaning and no Sub "
                     f"{name or code_name('m', key)} is defined in the file or its macro files: it does nothing",
                     word.span)


@rule("G504")
def probe_guard(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """A probe move only makes sense on a real machine, so it belongs under a guard that keeps it out of the
    job's rendering (``If [#5397 == 0]``) or out of simulation and rendering (``#5380`` too)."""
    for block in project.facts(file).coded:
        for key, word in block.g:  # (a loop here, not a call: this runs for every coded block)
            if key == PROBE:
                if not project.is_guarded(file, block.scope):
                    yield at("G504", "G38.2 runs while the job is rendered too: wrap it in If [#5397 == 0] ... EndIf "
                             "(not while rendering), or If [[#5380 == 0] and [#5397 == 0]] (nor in simulation)",
                             word.span)
                break
