"""Facts about the whole linted set (jobs plus their macro files) that single-file rules need.

Which sub a call reaches, which subs only ever run under the simulation
guard, which subs may overwrite the M-code arguments #1..#26, and which
parameters are written anywhere: each is computed once, on first use.
"""
from __future__ import annotations

import re
from collections.abc import Iterator, Mapping, Sequence
from functools import cached_property

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.records import record
from edingcnc_lang.machine.tables import ARG_PARAMS, TOOL_CHANGE, TOOL_CHANGE_SUB, m_code_sub
from edingcnc_lang.lint.facts import Code, FileFacts, indexed_reads, survey
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.names import is_entry_point, m_sub_number
from edingcnc_lang.lint.walk import Scope, dialog_fields
from edingcnc_lang.varmap.convention import sidecar_of
from edingcnc_lang.varmap.names import Names, Source, sub_lines

SubKey = tuple[str, str]  # (path, lower-case name)
# Commands that store a result in the variable whose number they are given.
_WRITING_COMMANDS = frozenset({"gettoolinfo", "getjobdistance", "getheightcontrolvact", "getheightcontrolvset"})
_MODBUS_TARGET = re.compile(r"u(\d+)", re.IGNORECASE)  # modbus ... u4000: a read's result goes to #4000


def command_writes(command: n.Command) -> Iterator[int]:
    """The variables a command sets: the bare numbers of the Get* commands, the ``uNNN`` of ``modbus``."""
    if command.name in _WRITING_COMMANDS:
        yield from (int(word) for word in command.args.split() if word.isascii() and word.isdigit())
    elif command.name == "modbus":
        yield from (int(m.group(1)) for word in command.args.split() if (m := _MODBUS_TARGET.fullmatch(word)))


@record(frozen=True)
class Call:
    """A statement that runs a sub: GoSub, an M code with a ``Sub mNNN``, or M6."""

    caller: SourceFile
    scope: Scope
    stmt: n.Stmt
    callee: SourceFile
    sub: n.Sub

    @property
    def key(self) -> SubKey:
        return sub_key(self.callee, self.sub)


def _own_code(scope: Scope) -> int | None:
    """The M number (whole) a sub answers to, whose own M code inside it is the built-in: ``Sub m3``'s
    M3, ``change_tool``'s M6."""
    if scope.sub is None:
        return None
    if scope.sub.name.lower() == TOOL_CHANGE_SUB:
        return TOOL_CHANGE // 10
    return m_sub_number(scope.sub.name)


def sub_key(file: SourceFile, sub: n.Sub) -> SubKey:
    return file.path, sub.name.lower()


class Project:
    """The files being linted and the macro files each one can call into."""

    def __init__(self, files: Sequence[SourceFile], macros: Mapping[str, Sequence[SourceFile]],
                 extra_written: frozenset[int] = frozenset(),
                 tool_diameters: Mapping[int, float] | None = None, mill: bool = False,
                 spindle_range: tuple[float, float] = (0.0, 0.0)) -> None:
        self.files = tuple(files)
        self.spindle_range = spindle_range  # the --ini's spindleNmin, spindleNmax (0: no limit), for G521
        self.tool_diameters = dict(tool_diameters or {})  # [TOOL_n] diameter (mm) of the --ini, for G41/G42 D
        self.mill = mill  # the --ini is a mill's (machineType = 0): lathe codes stop the job there
        self._macros = macros
        self._extra_written = extra_written
        self._facts: dict[str, FileFacts] = {}
        self._resolved: dict[tuple[str, str], tuple[SourceFile, n.Sub] | None] = {}

    def walked(self, file: SourceFile) -> tuple[tuple[n.Stmt, Scope], ...]:
        """Every statement of the file with its scope."""
        return self.facts(file).walked

    def facts(self, file: SourceFile) -> FileFacts:
        found = self._facts.get(file.path)
        if found is None:
            found = self._facts[file.path] = survey(file.body)
        return found

    def reads(self, file: SourceFile, stmt: n.Stmt) -> tuple[tuple[n.Param, int | None], ...]:
        """The parameters a statement of ``file`` reads, each with its literal index (None if computed)."""
        found = self.facts(file).reads_of.get(id(stmt))
        return found if found is not None else indexed_reads(stmt)

    def codes(self, file: SourceFile, stmt: n.Stmt, letter: str) -> tuple[Code, ...]:
        """The literal G or M codes of a block of ``file`` (none for other statements)."""
        found = self.facts(file).codes_of.get(id(stmt))
        if found is None:
            return ()
        return found.g if letter == "G" else found.m if letter == "M" else ()

    # ----------------------------------------------------------------- calls
    def searched(self, file: SourceFile) -> tuple[SourceFile, ...]:
        """Where a call in ``file`` looks for its sub, in order: the file itself, then its macro files."""
        return (file, *self._macros.get(file.path, ()))

    def resolve(self, file: SourceFile, name: str) -> tuple[SourceFile, n.Sub] | None:
        """The sub ``name`` as the controller finds it: in the file itself, then its macro files."""
        key = file.path, name.lower()
        if key in self._resolved:  # the same few names (m3, m5, a GoSub target) are asked for again and again
            return self._resolved[key]
        found = None
        for candidate in self.searched(file):
            sub = candidate.subs.get(key[1])
            if sub is not None:
                found = candidate, sub
                break
        self._resolved[key] = found
        return found

    def callees(self, file: SourceFile, stmt: n.Stmt, scope: Scope) -> Iterator[tuple[SourceFile, n.Sub]]:
        """The subs a statement runs (inside ``Sub m3`` an M3 is the built-in, not a call; so is M6
        inside ``change_tool``, where it commits the tool)."""
        if isinstance(stmt, n.GoSub):
            found = self.resolve(file, stmt.name)
            if found:
                yield found
        elif isinstance(stmt, n.Block):
            for key, _word in self.codes(file, stmt, "M"):
                name = m_code_sub(key)
                found = self.resolve(file, name) if name is not None else None
                if found and key // 10 != _own_code(scope):
                    yield found

    @cached_property
    def calls(self) -> tuple[Call, ...]:
        return tuple(Call(file, scope, stmt, *target)
                     for file in self.files for stmt, scope in self.facts(file).callers
                     for target in self.callees(file, stmt, scope))

    @cached_property
    def called(self) -> frozenset[SubKey]:
        return frozenset(call.key for call in self.calls)

    @cached_property
    def guarded_subs(self) -> frozenset[SubKey]:
        """Subs that only ever run under the simulation guard: called, and only from guarded code.

        Entry points (controller and M-code subs) can run from anywhere, so never count.
        """
        guarded = {call.key for call in self.calls if not is_entry_point(call.sub.name)}
        changed = True
        while changed:  # shrink to the largest consistent set (handles recursion)
            changed = False
            for call in self.calls:
                if call.key in guarded and not self.is_guarded(call.caller, call.scope, guarded):
                    guarded.discard(call.key)
                    changed = True
        return frozenset(guarded)

    def is_guarded(self, file: SourceFile, scope: Scope,
                   guarded_subs: frozenset[SubKey] | set[SubKey] | None = None) -> bool:
        """True if code in ``scope`` only runs on a real machine (outside simulation)."""
        subs = self.guarded_subs if guarded_subs is None else guarded_subs
        return scope.guarded or (scope.sub is not None and sub_key(file, scope.sub) in subs)

    @cached_property
    def argument_clobbering_subs(self) -> frozenset[SubKey]:
        """Subs that may overwrite #1..#26: they assign them, call an M-code sub, or GoSub one that does."""
        clobbering = {call.key for call in self.calls if m_sub_number(call.sub.name) is not None}
        for file in self.files:
            for _param, index, scope in self.facts(file).targets:
                if scope.sub and index in ARG_PARAMS:
                    clobbering.add(sub_key(file, scope.sub))
        changed = True
        while changed:
            changed = False
            for call in self.calls:
                caller = call.scope.sub
                if caller and call.key in clobbering and sub_key(call.caller, caller) not in clobbering:
                    clobbering.add(sub_key(call.caller, caller))
                    changed = True
        return frozenset(clobbering)

    def clobbers_arguments(self, file: SourceFile, stmt: n.Stmt, scope: Scope) -> bool:
        """True if running ``stmt`` may change #1..#26 (an M-code sub call sets them all)."""
        return any(m_sub_number(sub.name) is not None or
                   sub_key(target, sub) in self.argument_clobbering_subs
                   for target, sub in self.callees(file, stmt, scope))

    # ----------------------------------------------------------------- variables
    @cached_property
    def written(self) -> frozenset[int]:
        """Parameters assigned by number anywhere, set by a dlgmsg field or a command, or by the ini."""
        found = set(self._extra_written)
        for file in self.files:
            facts = self.facts(file)
            found.update(index for index in facts.target_indices if index is not None)
            for dialog, _scope in facts.dialogs:
                found.update(index for index, _ in dialog_fields(dialog))
            for command in facts.commands:
                found.update(command_writes(command))
        return frozenset(found)

    @cached_property
    def names(self) -> Names:
        """The names the files give their variables (annotations, sidecars, dlgmsg labels, comments)."""
        return Names(map(self._named, self.files), (sidecar_of(f.path) for f in self.files))

    def _named(self, file: SourceFile) -> Source:
        """What the names of ``file`` are read from: its lines, and the dialogs of its walk."""
        dialogs = [(dialog, scope.sub.name if scope.sub is not None else None)
                   for dialog, scope in self.facts(file).dialogs]
        return Source(file.path, file.lines, dialogs, sub_lines(file.body))
