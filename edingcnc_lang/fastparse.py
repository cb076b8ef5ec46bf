"""A hand-written parser for the most common macro lines, a fast path in front of Lark.

It covers blocks of words and assignments with expressions, If/While heads,
Else/End lines, Sub/GoSub and messages, and builds exactly the nodes (spans
included) the Lark grammar builds; property tests compare the two on generated
lines.  It never reports errors: on anything it is not sure about it gives up
(returns ``GIVE_UP``) and the caller asks the grammar, which is the reference
and explains mistakes.
"""
from __future__ import annotations

import re

from . import nodes as n
from .markers import Close, LineResult, Open

# A number the fast paths take: at most 300 integer digits, so always a finite double (a longer
# one is left to the grammar, which reports it).
FAST_NUMBER = r"(?:\d{1,300}(?:\.\d*)?|\.\d+)(?!\d)"

GIVE_UP = object()


class _GiveUp(Exception):
    pass


_NUMBER = re.compile(FAST_NUMBER)
_IDENT = re.compile(r"[A-Za-z0-9_]+")
_STRING = re.compile(r'"[^"\n]*"')
_FUNC = re.compile(r"(abs|acos|asin|cos|exp|fix|fup|ln|round|sin|sqrt|tan|atan)(?=\s*\[)", re.IGNORECASE)
_OPERATOR = re.compile(r"\*\*|==|<>|!=|<=|>=|[-+*/<>]|(?:mod|or|xor|and|eq|ne|gt|ge|lt|le)(?![A-Za-z0-9_])",
                       re.IGNORECASE)
_OPERATOR_START = frozenset("*=<>!+-/mMoOxXaAeEnNgGlL")
# Binding levels, loosest first: comparisons, then + - OR XOR AND, then * / MOD, then **.
_LEVEL = {op: 1 for op in ("==", "<>", "!=", "<=", ">=", "<", ">", "EQ", "NE", "GT", "GE", "LT", "LE")}
_LEVEL.update({op: 2 for op in ("+", "-", "OR", "XOR", "AND")})
_LEVEL.update({op: 3 for op in ("*", "/", "MOD")})
_LEVEL["**"] = 4
_COMPARE_OPS = {"==": "==", "EQ": "==", "<>": "<>", "!=": "<>", "NE": "<>", "<": "<", "LT": "<",
                ">": ">", "GT": ">", "<=": "<=", "LE": "<=", ">=": ">=", "GE": ">="}
# Names the grammar's lexer prefers to a word letter (they outrank LETTER): "A0 ASIN[0]" is read
# as the function ASIN, not as the word A, so a line with one is left to the grammar.
_RESERVED = re.compile(r"(abs|acos|asin|cos|exp|fix|fup|ln|round|sin|sqrt|tan|atan)\s*\[|"
                       r"(mod|or|xor|and|eq|ne|gt|ge|lt|le)(?![A-Za-z0-9_])", re.IGNORECASE)
_AXIS = re.compile(r"[xyzabc](?![A-Za-z0-9_])", re.IGNORECASE)
_FILE_NAME = re.compile(r'[^\s;"]+')
_STRINGS = re.compile(r'"[^"\n]*"')
_MESSAGES = frozenset({"msg", "warnmsg", "errmsg", "logmsg"})
_CLOSERS = {"endsub": "EndSub", "endif": "EndIf", "endwhile": "EndWhile", "else": "Else"}
# Every keyword the grammar knows at the start of a line; those not handled here go to Lark.
_KEYWORDS = frozenset({
    "sub", "endsub", "gosub", "if", "then", "else", "endif", "while", "endwhile", "msg", "warnmsg", "errmsg",
    "logmsg", "dlgmsg", "logfile", "home", "hometandem", "tanknife", "homeisestop", "tcaguard", "zhc",
    "laserengrave", "kin", "preparelindeltahome", "zhcinitex", "zhcinit", "zhcaddpoint", "zhcs",
    "gettoolinfo", "modbus", "getjobdistance", "exec"})


class _Line:
    """Recursive descent over one line; positions are 0-based, spans 1-based like Lark's."""

    def __init__(self, text: str, path: str, line: int) -> None:
        self.text = text
        self.path = path
        self.line = line
        self.pos = 0
        self.end = len(text)

    # ---------------------------------------------------------------- scanning
    def skip(self) -> None:
        text, pos, end = self.text, self.pos, self.end
        while pos < end and (text[pos] == " " or text[pos] == "\t"):
            pos += 1
        self.pos = end if pos < end and text[pos] == ";" else pos

    def at_end(self) -> bool:
        self.skip()
        return self.pos >= self.end

    def peek(self) -> str:
        self.skip()
        return self.text[self.pos] if self.pos < self.end else ""

    def take(self, pattern: re.Pattern[str]) -> re.Match[str] | None:
        self.skip()
        match = pattern.match(self.text, self.pos)
        if match:
            self.pos = match.end()
        return match

    def expect(self, char: str) -> int:
        """Consume ``char``; returns its 1-based column."""
        if self.peek() != char:
            raise _GiveUp
        self.pos += 1
        return self.pos

    def span(self, start: int, end: int) -> n.Span:
        return n.Span(self.path, self.line, start, self.line, end)

    # ---------------------------------------------------------------- expressions
    # Each returns (node, start column, end column) where the columns include any
    # brackets around the node: the grammar counts them for the enclosing node only.
    def atom(self) -> tuple[n.Expr, int, int]:
        ch = self.peek()
        start = self.pos + 1
        if ch == "[":
            self.pos += 1
            node, _s, _e = self.expr()
            end = self.expect("]") + 1
            return node, start, end
        if ch == "#":
            return self.param()
        match = self.take(_NUMBER)
        if match:
            return n.Number(float(match.group()), self.span(start, self.pos + 1)), start, self.pos + 1
        match = self.take(_FUNC)
        if match:
            name = match.group().upper()
            self.expect("[")
            first, _s, _e = self.expr()
            end = self.expect("]") + 1
            if name != "ATAN":
                return n.Call(name, (first,), self.span(start, end)), start, end
            if self.peek() != "/":
                raise _GiveUp
            self.pos += 1
            self.expect("[")
            second, _s, _e = self.expr()
            end = self.expect("]") + 1
            return n.Call(name, (first, second), self.span(start, end)), start, end
        raise _GiveUp

    def param(self) -> tuple[n.Expr, int, int]:
        start = self.expect("#")
        ch = self.peek()
        if ch == "#":
            index, _s, end = self.param()
        elif ch == "[":
            self.pos += 1
            index, _s, _e = self.expr()
            end = self.expect("]") + 1
        else:
            match = self.take(_NUMBER)
            if not match:
                raise _GiveUp
            end = self.pos + 1
            index = n.Number(float(match.group()), self.span(match.start() + 1, end))
        return n.Param(index, self.span(start, end)), start, end

    def signed(self) -> tuple[n.Expr, int, int]:
        ch = self.peek()
        if ch in "+-" and ch:
            start = self.pos + 1
            self.pos += 1
            operand, _s, end = self.signed()
            span = self.span(start, end)
            if isinstance(operand, n.Number):
                return n.Number(-operand.value if ch == "-" else operand.value, span), start, end
            return n.Unary(ch, operand, span), start, end
        return self.atom()

    def expr(self, min_level: int = 1) -> tuple[n.Expr, int, int]:
        """Precedence climbing over the grammar's levels; every level is left-associative."""
        left, start, end = self.signed()
        while True:
            ch = self.peek()
            if not ch or ch not in _OPERATOR_START:
                return left, start, end
            match = _OPERATOR.match(self.text, self.pos)
            if match is None:
                return left, start, end
            op = match.group().upper()
            level = _LEVEL[op]
            if level < min_level:
                return left, start, end
            self.pos = match.end()
            right, _s, end = self.expr(level + 1)
            span = self.span(start, end)
            left = n.Compare(_COMPARE_OPS[op], left, right, span) if level == 1 else n.Binary(op, left, right, span)

    # ---------------------------------------------------------------- statements
    def block(self) -> n.Block:
        words: list[n.Word] = []
        assigns: list[n.Assign] = []
        block_delete = self.peek() == "/"
        start = self.pos + 1
        if block_delete:
            self.pos += 1
        end = self.pos + 1
        while not self.at_end():
            ch = self.text[self.pos]
            item_start = self.pos + 1
            if ch == "#":
                target, _s, _e = self.param()
                self.expect("=")
                if self.peek() == "=":
                    raise _GiveUp
                value, _s, end = self.expr()
                assert isinstance(target, n.Param)
                assigns.append(n.Assign(target, value, self.span(item_start, end)))
            elif ch.isalpha() and ch.isascii():
                if _RESERVED.match(self.text, self.pos):
                    raise _GiveUp
                self.pos += 1
                value, _s, end = self.signed()
                words.append(n.Word(ch.upper(), value, self.span(item_start, end)))
            else:
                raise _GiveUp
        if not words and not assigns:
            raise _GiveUp
        line_number = None
        if words and words[0].letter == "N" and isinstance(words[0].value, n.Number):
            line_number = int(words[0].value.value)
            words = words[1:]
        return n.Block(tuple(words), tuple(assigns), None, line_number, block_delete, self.span(start, end))

    def condition(self, kind: str, start: int) -> Open:
        self.expect("[")
        cond, _s, end = self.expr()
        end = self.expect("]") + 1
        extra = 0
        while self.peek() == "]":
            self.pos += 1
            extra += 1
            end = self.pos + 1
        if kind == "If":
            match = self.take(_IDENT)
            if match:
                if match.group().lower() != "then":
                    raise _GiveUp
                end = self.pos + 1
        if not self.at_end():
            raise _GiveUp
        return Open(kind, self.span(start, end), cond=cond, extra=extra)

    def items(self) -> tuple[list[n.MessageItem], int]:
        """Strings and values up to the end of the line (msg, dlgmsg), and the end column."""
        items: list[n.MessageItem] = []
        end = self.pos + 1
        while not self.at_end():
            if self.text[self.pos] == '"':
                match = self.take(_STRING)
                if not match:
                    raise _GiveUp
                items.append(match.group()[1:-1])
                end = self.pos + 1
            else:
                value, _s, end = self.signed()
                items.append(value)
        return items, end

    def logfile(self, start: int) -> n.LogFile:
        self.skip()
        if self.peek() == '"':
            match = self.take(_STRING)
            name = match.group()[1:-1] if match else None
        else:
            match = self.take(_FILE_NAME)
            name = match.group() if match else None
        if match is None or name is None:
            raise _GiveUp
        end = self.pos + 1
        mode = None
        if not self.at_end():
            mode, _s, end = self.signed()
            if not self.at_end():
                raise _GiveUp
        return n.LogFile(name, mode, self.span(start, end))

    def statement(self) -> LineResult:
        if self.at_end():
            return None
        match = _IDENT.match(self.text, self.pos)
        word = match.group().lower() if match else ""
        if word not in _KEYWORDS:
            return self.block()
        start = self.pos + 1
        self.pos = match.end()  # type: ignore[union-attr]
        end = self.pos + 1
        if word in _CLOSERS:
            if not self.at_end():
                raise _GiveUp
            return Close(_CLOSERS[word], self.span(start, end))
        if word in ("if", "while"):
            return self.condition(word.capitalize(), start)
        if word in _MESSAGES:
            items, last = self.items()
            return n.Message(word, tuple(items), self.span(start, last if items else end))
        if word == "dlgmsg":
            items, last = self.items()
            return n.Dialog(tuple(items), self.span(start, last if items else end))
        if word == "logfile":
            return self.logfile(start)
        if word in ("home", "hometandem"):
            axis = self.take(_AXIS)
            if not axis or not self.at_end():
                raise _GiveUp
            return n.Home(axis.group().upper(), word == "hometandem", self.span(start, axis.end() + 1))
        if word in ("sub", "gosub"):
            name = self.take(_IDENT)
            if not name or not self.at_end():
                raise _GiveUp
            span = self.span(start, name.end() + 1)
            return Open("Sub", span, name=name.group()) if word == "sub" else n.GoSub(name.group(), span)
        raise _GiveUp


def parse_fast(text: str, path: str, line: int) -> LineResult | object:
    """The line's node, or GIVE_UP when the grammar must decide."""
    if "(" in text and "(" in _STRINGS.sub("", text):  # ( ) comments and MSG comments: the grammar's business
        return GIVE_UP
    try:
        return _Line(text, path, line).statement()
    except (_GiveUp, IndexError, RecursionError):  # RecursionError: absurdly deep nesting, the grammar decides
        return GIVE_UP
