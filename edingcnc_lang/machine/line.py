"""One G-code line: its words evaluated and sorted by modal group, then dispatched."""
from __future__ import annotations

from collections.abc import Mapping

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.errors import Location, MachineError
from edingcnc_lang.machine.state import G_80, MachineState, StatementTable


class LineWords(MachineState):
    """A line calling an M-code sub goes to the sub; any other line runs its steps in the order of execution."""

    def _exec_block(self, block: n.Block) -> None:
        if block.block_delete and self.block_delete:
            return
        value = self.evaluator.value
        words: dict[str, float] = {}
        g_codes: dict[str, int] = {}
        m_codes: dict[str, int] = {}
        for word in block.words:
            self._add_word(words, g_codes, m_codes, word.letter, value(word.value), word.span.col)
        # Deferred assignment: every expression of the line is evaluated before any parameter changes.
        pending = [(self.evaluator.index(a.target), value(a.value), a.span) for a in block.assigns]
        for index, number, span in pending:
            self.params.write(index, number, self.where(span))
        if block.message is not None:
            self.message("msg", block.message)
        self._dispatch(words, g_codes, m_codes, block.span)

    def _exec_plain(self, block: n.PlainBlock) -> None:
        words: dict[str, float] = {}
        g_codes: dict[str, int] = {}
        m_codes: dict[str, int] = {}
        for letter, number, col in block.words:
            self._add_word(words, g_codes, m_codes, letter, number, col)
        self._dispatch(words, g_codes, m_codes, block.span)

    def _add_word(self, words: dict[str, float], g_codes: dict[str, int], m_codes: dict[str, int],
                  letter: str, number: float, col: int) -> None:
        """Sort one evaluated word into axis/parameter words, G codes by group and M codes by group."""
        if letter == "G" or letter == "M":
            key = int(round(number * 10))
            table, found = (t.G_GROUPS, g_codes) if letter == "G" else (t.M_GROUPS, m_codes)
            group = table.get(key)
            if group is None:
                if letter == "G":
                    hint = t.UNKNOWN_G_HINTS.get(key)
                    raise MachineError(f"unknown G code {t.code_name('G', key)}" + (f": {hint}" if hint else ""),
                                       Location(self.path, self.line, col))
                group = f"user_{key}"
            elif letter == "G" and key in t.LATHE_ONLY_G and not self.config.lathe:
                raise MachineError(t.lathe_code_message(key), Location(self.path, self.line, col))
            winner = t.same_line_winner(group, found[group], key) if group in found and letter == "G" else None
            if winner is not None:
                key = winner
            elif group in found:
                raise MachineError(f"{t.code_name(letter, found[group])} and {t.code_name(letter, key)} are in the "
                                   "same modal group; use one per line", Location(self.path, self.line, col))
            found[group] = key
        elif letter in words:
            raise MachineError(f"word {letter} appears twice on this line", Location(self.path, self.line, col))
        else:
            words[letter] = number

    def _dispatch(self, words: dict[str, float], g_codes: dict[str, int], m_codes: dict[str, int],
                  span: n.Span) -> None:
        """Run the sorted words of one line: an M-code sub call, or the built-in actions."""
        if not words and not g_codes and not m_codes:  # assignments or a message only
            return
        if len(m_codes) > t.MAX_M_WORDS:
            raise self.fail(f"{len(m_codes)} M words on one line; at most {t.MAX_M_WORDS} are allowed", span)
        if m_codes:
            user_m = [k for k in m_codes.values() if self._user_m_sub(k)]
            if user_m:
                self._call_m_sub(user_m[0], words, g_codes, m_codes, span)
                return
            for key in m_codes.values():
                if key not in t.M_GROUPS:  # manual 3.7.13: M1..M999 run a sub of that name, if there is one
                    self.message("warn", f"{t.code_name('M', key)} has no built-in meaning and no Sub "
                                 f"{t.m_sub_name(key) or t.code_name('m', key)} is defined: it does nothing")
        self._execute_line(words, g_codes, m_codes, span)

    def _user_m_sub(self, key: int) -> str | None:
        """The sub overriding M<key>, unless we are inside it (then the built-in runs).

        An M code with no built-in (M100, ...) inside its own sub, directly or through GoSub, is an
        error: there is nothing to run instead, and running nothing would hide the mistake.
        """
        name = t.m_sub_name(key)
        if name is None or name not in self.flow.subs:
            return None
        if all(frame.name != name for frame in self.flow.stack):
            return name
        if key not in t.M_GROUPS:
            raise self.fail(f"M{key // 10} inside Sub {name}, which is already running: M{key // 10} has no "
                            f"built-in action to run instead; write GoSub {name} if the recursion is meant")
        return None

    def _call_m_sub(self, key: int, words: dict[str, float], g_codes: Mapping[str, int],
                    m_codes: Mapping[str, int], span: n.Span) -> None:
        if g_codes or len(m_codes) > 1:
            raise self.fail(f"a line calling M{key // 10} (a macro sub) may hold only its letter arguments", span)
        owned = t.OWN_M_WORDS.get(key, frozenset())  # M104 S..: a temperature, not a spindle speed
        self._feed_speed_tool({k: v for k, v in words.items() if k not in owned}, span)  # F, S, T act first
        for i, letter in enumerate(t.LETTER_ARGS, 1):
            self.params.set(i, words.get(letter, t.ABSENT_ARGUMENT))
        name = t.m_sub_name(key)
        assert name is not None  # _user_m_sub chose this code: a whole M number
        self.call_sub(name, span)

    def _execute_line(self, words: dict[str, float], g: Mapping[str, int], m: Mapping[str, int],
                      span: n.Span) -> None:
        """One line's actions in the controller's order of execution (tables.ORDER_OF_EXECUTION)."""
        motion, non_modal = g.get("motion"), g.get("non_modal")
        if motion is not None and motion != G_80 and non_modal in t.AXIS_WORD_USERS:
            # manual p. 14: "Es ist ein Fehler, einen G-Code aus Gruppe 1 und einen G-Code aus Gruppe 0 in
            # dieselbe Zeile zu setzen, wenn beide Achsenwörter verwenden" (rs274 refuses it too)
            raise self.fail(f"{t.code_name('G', motion)} and {t.code_name('G', non_modal)} both use the axis words: "
                            "a motion code and G10, G28, G30 or G92 cannot share a line", span)
        own: dict[str, dict[str, float]] = {}  # a group whose code owns words of the line (G64 P Q R S D F)
        for codes, table in ((g, t.OWN_G_WORDS), (m, t.OWN_M_WORDS)):
            for group, code in codes.items():
                letters = table.get(code)
                if letters is not None:
                    own[group] = {k: v for k, v in words.items() if k in letters}
                    words = {k: v for k, v in words.items() if k not in letters}
        sources = {"G": g, "M": m, "word": words}
        for handler, source, key in self._LINE_STEPS:
            if source == "always":
                handler(self, g.get("motion"), words, g, span)
            else:
                found = sources[source]
                if key in found:
                    handler(self, found[key], own.get(key, words), g, span)

    def _feed_speed_tool(self, words: Mapping[str, float], span: n.Span) -> None:
        """The F, S and T steps alone (a line calling an M-code sub still sets them)."""
        for letter, step in (("F", self._step_feed), ("S", self._step_spindle_speed),
                             ("T", self._step_tool_select)):
            if letter in words:
                step(words[letter], words, {}, span)


# The statements this part executes (interpreter.py builds the dispatch table from every part's).
STATEMENTS: StatementTable = {n.Block: LineWords._exec_block, n.PlainBlock: LineWords._exec_plain}
