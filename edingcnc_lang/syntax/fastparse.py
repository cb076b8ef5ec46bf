"""A hand-written parser for the most common macro lines, a fast path in front of Lark.

It covers blocks of words and assignments with expressions, If/While heads,
Else/End lines, Sub/GoSub, messages, the on/off switches and the commands (ZHC*,
modbus, ...), with a ';' comment that may hold parentheses, and builds exactly the
nodes (spans included) the Lark grammar builds; property tests compare the two on generated
lines.  It never reports errors: on anything it is not sure about it gives up
(returns ``GIVE_UP``) and the caller asks the grammar, which is the reference
and explains mistakes.

Speed comes from splitting the line into tokens with one regular expression
pass (or the optional compiled tokenizer, ``_lexer.c``, which gives the same tokens) and then
descending over that list: no character-level scanning in Python.
"""
from __future__ import annotations

import re
from collections.abc import Callable
from typing import TypeVar

from edingcnc_lang import speedups
from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.syntax.input_limits import INTEGER_DIGITS, LINE_NUMBER_DIGITS, MAX_NUMBER_DIGITS, SHORTEST_PROBLEM
from edingcnc_lang.syntax.plain_words import FAST_NUMBER
from edingcnc_lang.syntax.blocks import Close, LineResult, Open
from edingcnc_lang.syntax.tree_builder import command_values


GIVE_UP = object()
_new_span = tuple.__new__  # Span(...) without the named tuple's Python-level __new__: one per node


class _GiveUp(Exception):
    pass


# The tokens of a line: blanks, a ';' comment, a number, a string, an operator or bracket, or a
# run of ASCII letters.  Letters only, because a block's words are glued together (G1X10); a name
# with digits or '_' in an expression is the grammar's.
_TOKEN = re.compile(rf'[ \t]+|;.*|{FAST_NUMBER}|"[^"\n]*"|\*\*|==|<>|!=|<=|>=|[-+*/<>\[\]#=]|[A-Za-z]+')
# A token's kind from its first character: "n" number, "s" string, "i" letters, " " blank or
# comment; an operator's kind is its own text.
_KIND = {**dict.fromkeys("0123456789.", "n"), '"': "s", **dict.fromkeys(" \t;", " "),
         **dict.fromkeys("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz", "i")}
Token = tuple[str, str, int, int]  # kind ("n", "s", "i" or the operator), text, column, end column
_FUNCTIONS = frozenset(n.FUNCTION_NAMES)
# Binding levels, loosest first: comparisons, then + - OR XOR AND, then * / MOD, then **.
_LEVEL = {op: 1 for op in ("==", "<>", "!=", "<=", ">=", "<", ">", "EQ", "NE", "GT", "GE", "LT", "LE")}
_LEVEL.update({op: 2 for op in ("+", "-", "OR", "XOR", "AND")})
_LEVEL.update({op: 3 for op in ("*", "/", "MOD")})
_LEVEL["**"] = 4
_COMPARE_OPS = {"==": "==", "EQ": "==", "<>": "<>", "!=": "<>", "NE": "<>", "<": "<", "LT": "<",
                ">": ">", "GT": ">", "<=": "<=", "LE": "<=", ">=": ">=", "GE": ">="}
_BLANK = re.compile(r"[ \t]*(?:;.*)?\Z")
_HEAD = re.compile(r"[ \t]*([A-Za-z0-9_]+)")
_NAME = re.compile(r"[ \t]*([A-Za-z0-9_]+)[ \t]*(?:;.*)?\Z")
_AXIS = re.compile(r"[ \t]*([xyzabc])(?![A-Za-z0-9_])[ \t]*(?:;.*)?\Z", re.IGNORECASE)
_FILE_NAME = re.compile(r'[ \t]*(?:"([^"\n]*)"|([^\s;"]+))')
_STRINGS = re.compile(r'"[^"\n]*"')
_MESSAGES = frozenset({"msg", "warnmsg", "errmsg", "logmsg"})
_CLOSERS = {"endsub": "EndSub", "endif": "EndIf", "endwhile": "EndWhile", "else": "Else"}
# Every keyword the grammar knows at the start of a line; those not handled here go to Lark.
_KEYWORDS = frozenset({
    "sub", "endsub", "gosub", "if", "then", "else", "endif", "while", "endwhile", "msg", "warnmsg", "errmsg",
    "logmsg", "dlgmsg", "logfile", "home", "hometandem", "tanknife", "homeisestop", "tcaguard", "zhc",
    "laserengrave", "kin", "preparelindeltahome", "zhcinitex", "zhcinit", "zhcaddpoint", "zhccheck", "zhcs",
    "zhcl", "gettoolinfo", "modbus", "getjobdistance", "getheightcontrolvact", "getheightcontrolvset",
    "service", "exec"})
# The keywords handled here and by the compiled reader; a line starting with another one goes to Lark
# untokenized, unless it is a switch or a command (handled here only: rare lines, read by regular expressions).
_HANDLED = frozenset({*_CLOSERS, *_MESSAGES, "sub", "gosub", "home", "hometandem", "logfile", "if", "while",
                      "dlgmsg"})
_SWITCHES = frozenset({"tanknife", "homeisestop", "tcaguard", "zhc", "laserengrave"})  # the grammar's SWITCH_KW
_COMMANDS = frozenset({"zhcinitex", "zhcinit", "zhcaddpoint", "zhccheck", "zhcs", "zhcl", "gettoolinfo", "modbus",
                       "getjobdistance", "getheightcontrolvact", "getheightcontrolvset", "service", "exec"})
_ON_OFF = re.compile(r"[ \t]*(on|off)(?![a-z0-9_])[ \t]*(?:;.*)?\Z", re.IGNORECASE)
# a command's RAW_ARGS (the grammar's terminal) after the blanks, then the ';' comment
_RAW_ARGS = re.compile(r"[ \t]*([^;\s][^;\n]*)?(?:;.*)?\Z")


def _tokens_python(text: str, pos: int) -> list[Token]:
    """The tokens of ``text`` from ``pos`` on, ending with an empty-kind sentinel (the reference
    for the compiled ``_lexer.tokens``)."""
    tokens: list[Token] = []
    for value in _TOKEN.findall(text, pos):
        start = pos
        pos += len(value)
        kind = _KIND.get(value[0], value)
        if kind != " ":
            tokens.append((kind, value, start + 1, pos + 1))
    if pos != len(text):  # findall skipped a character no token covers: the grammar's business
        raise _GiveUp
    tokens.append(("", "", pos + 1, pos + 1))
    return tokens


_Compiled = Callable[..., object] | None
_N = TypeVar("_N")


def _compiled() -> tuple[_Compiled, _Compiled, _Compiled, _Compiled, _Compiled, _Compiled]:
    """The compiled tokenizer, block, condition, statement and lines readers and the block assembler
    (``_lexer.c``), when ``speedups`` loaded it (built, and the Python core not asked for)."""
    from edingcnc_lang.syntax import blocks

    _lexer = speedups.LEXER
    if _lexer is None:
        return None, None, None, None, None, None
    _lexer.setup(n, blocks, GIVE_UP, _KEYWORDS - _HANDLED)
    return _lexer.tokens, _lexer.block, _lexer.condition, _lexer.statement, _lexer.statements, _lexer.assemble


(_COMPILED, _COMPILED_BLOCK, _COMPILED_CONDITION, _COMPILED_STATEMENT, _COMPILED_STATEMENTS,
 COMPILED_ASSEMBLE) = _compiled()
COMPILED_READER = _COMPILED_BLOCK is not None


def _construct(cls: type[_N], values: tuple[object, ...]) -> _N:
    """A node of ``cls`` with these field values (the reference for the compiled ``_lexer.new``)."""
    return cls(*values)


# A node of a frozen dataclass from its field values: on the compiled reader without the Python-level
# call of the dataclass's __init__ (the reader makes an If, While or Sub node at every end line).
new_node: Callable[[type[_N], tuple[object, ...]], _N] = _construct
if COMPILED_READER:
    new_node = speedups.LEXER.new


def _tokens(text: str, pos: int) -> list[Token]:
    """The tokens of ``text`` from ``pos`` on, on the compiled tokenizer when it is there."""
    if _COMPILED is None:
        return _tokens_python(text, pos)
    found = _COMPILED(text, pos, INTEGER_DIGITS, MAX_NUMBER_DIGITS)
    if found is None:
        raise _GiveUp
    if found is NotImplemented:  # a lone surrogate: not UTF-8, the Python tokenizer reads it
        return _tokens_python(text, pos)
    return found  # type: ignore[return-value]


class _Line:
    """Recursive descent over the tokens of one line; columns are 1-based like Lark's."""

    __slots__ = ("i", "line", "path", "tokens")

    def __init__(self, tokens: list[Token], path: str, line: int) -> None:
        self.tokens = tokens
        self.i = 0
        self.path = path
        self.line = line

    def span(self, start: int, end: int) -> n.Span:
        return _new_span(n.Span, (self.path, self.line, start, self.line, end))

    def expect(self, kind: str) -> int:
        """Consume a token of ``kind``; returns its end column."""
        token = self.tokens[self.i]
        if token[0] != kind:
            raise _GiveUp
        self.i += 1
        return token[3]

    def at_end(self) -> None:
        if self.tokens[self.i][0]:
            raise _GiveUp

    # ---------------------------------------------------------------- expressions
    # Each returns (node, start column, end column) where the columns include any
    # brackets around the node: the grammar counts them for the enclosing node only.
    def operand(self) -> tuple[n.Expr, int, int]:
        """A signed operand: ``-x``, ``[expr]``, ``#n``, a number or a function call."""
        kind, text, col, end = self.tokens[self.i]
        if kind == "n":  # first: most operands are numbers
            self.i += 1
            return n.Number(float(text), _new_span(n.Span, (self.path, self.line, col, self.line, end))), col, end
        if kind == "#":
            return self.param()
        if kind == "-" or kind == "+":
            self.i += 1
            operand, _s, end = self.operand()
            span = self.span(col, end)
            if isinstance(operand, n.Number):
                return n.Number(-operand.value if kind == "-" else operand.value, span), col, end
            return n.Unary(kind, operand, span), col, end
        if kind == "[":
            self.i += 1
            node = self.expr()[0]
            return node, col, self.expect("]")
        name = text.upper()
        if kind != "i" or name not in _FUNCTIONS or self.tokens[self.i + 1][0] != "[":
            raise _GiveUp
        self.i += 2
        first = self.expr()[0]
        end = self.expect("]")
        if name != "ATAN" or self.tokens[self.i][0] != "/" or self.tokens[self.i + 1][0] != "[":
            return n.Call(name, (first,), self.span(col, end)), col, end  # ATAN[x]/2 divides: one operand
        self.i += 2
        second = self.expr()[0]
        end = self.expect("]")
        return n.Call(name, (first, second), self.span(col, end)), col, end

    def param(self) -> tuple[n.Param, int, int]:
        col = self.tokens[self.i][2]
        self.i += 1
        kind, text, index_col, end = self.tokens[self.i]
        index: n.Expr
        if kind == "#":
            index, _s, end = self.param()
        elif kind == "[":
            self.i += 1
            index = self.expr()[0]
            end = self.expect("]")
        elif kind == "n":
            self.i += 1
            index = n.Number(float(text), self.span(index_col, end))
        else:
            raise _GiveUp
        return n.Param(index, self.span(col, end)), col, end

    def expr(self, min_level: int = 1) -> tuple[n.Expr, int, int]:
        """Precedence climbing over the grammar's levels; every level is left-associative."""
        left, start, end = self.operand()
        tokens = self.tokens
        while True:
            kind, text, _col, op_end = tokens[self.i]
            op = kind
            if kind == "i":
                op = text.upper()
                after = tokens[self.i + 1]
                if after[0] == "n" and after[2] == op_end and after[1][0] != ".":  # MOD2 is a name, MOD.5 is not
                    return left, start, end
            level = _LEVEL.get(op, 0)
            if level < min_level:
                return left, start, end
            self.i += 1
            right, _s, end = self.expr(level + 1)
            span = self.span(start, end)
            left = n.Compare(_COMPARE_OPS[op], left, right, span) if level == 1 else n.Binary(op, left, right, span)

    # ---------------------------------------------------------------- statements
    def block(self) -> n.Block:
        words: list[n.Word] = []
        assigns: list[n.Assign] = []
        tokens = self.tokens
        start = tokens[0][2]
        block_delete = tokens[0][0] == "/"
        if block_delete:
            self.i = 1
        while True:
            kind, text, col, _end = tokens[self.i]
            if kind == "#":
                target = self.param()[0]
                self.expect("=")
                if tokens[self.i][0] == "=":
                    raise _GiveUp
                value, _s, end = self.expr()
                assigns.append(n.Assign(target, value, self.span(col, end)))
            elif kind == "i":
                if len(text) == 1:
                    self.i += 1
                elif text[1:].upper() in _FUNCTIONS and text.upper() not in _FUNCTIONS:
                    tokens[self.i] = ("i", text[1:], col + 1, _end)  # XSIN[1]: the word X, then SIN
                else:  # ASIN[ (the function wins), MOD, GX: the grammar's
                    raise _GiveUp
                value, value_start, end = self.operand()
                if not words and text[0] in "Nn" and end - value_start > LINE_NUMBER_DIGITS:
                    raise _GiveUp  # a line number of more than five digits: the grammar's (the limit is checked there)
                words.append(n.Word(text[0].upper(), value, self.span(col, end)))
            elif kind:
                raise _GiveUp
            else:
                break
        if not words and not assigns:
            raise _GiveUp
        line_number = None
        first = words[0] if words else None
        if first is not None and first.letter == "N" and isinstance(first.value, n.Number):
            line_number = int(first.value.value)
            words = words[1:]
        return n.Block(tuple(words), tuple(assigns), None, line_number, block_delete, self.span(start, end))

    def condition(self, kind: str, start: int) -> Open:
        self.expect("[")
        cond = self.expr()[0]
        end = self.expect("]")
        extra = 0
        while self.tokens[self.i][0] == "]":
            end = self.expect("]")
            extra += 1
        then = self.tokens[self.i]
        if kind == "If" and then[0] == "i":
            if then[1].lower() != "then":
                raise _GiveUp
            end = self.expect("i")
        self.at_end()
        return Open(kind, self.span(start, end), cond=cond, extra=extra)

    def items(self, end: int) -> tuple[list[n.MessageItem], int]:
        """Strings and values up to the end of the line (msg, dlgmsg), and the end column."""
        items: list[n.MessageItem] = []
        while True:
            kind, text, _col, _end = self.tokens[self.i]
            if kind == "s":
                items.append(text[1:-1])
                end = self.expect("s")
            elif kind:
                value, _s, end = self.operand()
                items.append(value)
            else:
                return items, end


def _statement(text: str, path: str, line: int) -> LineResult:
    if _BLANK.match(text):
        return None
    head = _HEAD.match(text)
    word = head.group(1).lower() if head else ""
    if head is None or word not in _KEYWORDS:
        return _block(text, path, line)
    start, pos = head.start(1) + 1, head.end()
    if word in _SWITCHES or word in _COMMANDS:
        return _switch_or_command(text, path, line, word, start, pos)
    if word not in _HANDLED:  # kin, preparelindeltahome: the grammar's
        raise _GiveUp
    end = pos + 1
    if word in _CLOSERS:
        if not _BLANK.match(text, pos):
            raise _GiveUp
        return Close(_CLOSERS[word], n.Span(path, line, start, line, end))
    if word in ("sub", "gosub"):
        name = _NAME.match(text, pos)
        if not name:
            raise _GiveUp
        span = n.Span(path, line, start, line, name.end(1) + 1)
        return Open("Sub", span, name=name.group(1)) if word == "sub" else n.GoSub(name.group(1), span)
    if word in ("home", "hometandem"):
        axis = _AXIS.match(text, pos)
        if not axis:
            raise _GiveUp
        return n.Home(axis.group(1).upper(), word == "hometandem", n.Span(path, line, start, line, axis.end(1) + 1))
    if word == "logfile":
        return _logfile(text, path, line, start, pos)
    if word in ("if", "while"):
        return _condition(text, path, line, word.capitalize(), start, pos)
    rest = _Line(_tokens(text, pos), path, line)
    if word in _MESSAGES:
        items, last = rest.items(end)
        return n.Message(word, tuple(items), rest.span(start, last))
    if word == "dlgmsg":
        items, last = rest.items(end)
        return n.Dialog(tuple(items), rest.span(start, last))
    raise _GiveUp


def compiled_block(text: str, path: str, line: int) -> n.Block | None:
    """The Block of a line of words and assignments on the compiled reader, the same as
    ``_Line.block`` builds (and, for a plain word line, ``line_parser._fast_block``); None when the
    reader is not built or gives up."""
    if _COMPILED_BLOCK is None:
        return None
    return _COMPILED_BLOCK(text, path, line, INTEGER_DIGITS, MAX_NUMBER_DIGITS)  # type: ignore[return-value]


def compiled_statement(text: str, path: str, line: int) -> LineResult | object:
    """``parse_fast`` of a line without '(' that passes the input limits, on the compiled reader
    (``_lexer.statement``): the same node, None for a blank line, or GIVE_UP where ``parse_fast``
    gives up or the compiled reader does not try (then ``parse_fast`` decides)."""
    if _COMPILED_STATEMENT is None:
        return GIVE_UP
    return _COMPILED_STATEMENT(text, path, line, INTEGER_DIGITS, MAX_NUMBER_DIGITS)


def compiled_statements(lines: list[str], path: str, first: int) -> list[LineResult | object] | None:
    """``compiled_statement`` of each line (numbered from ``first`` on) that is short enough to pass
    every input limit and holds no '(', GIVE_UP for the others, in one call; None when the compiled
    reader is not built or not asked for."""
    if _COMPILED_STATEMENTS is None:
        return None
    return _COMPILED_STATEMENTS(lines, path, first, SHORTEST_PROBLEM, INTEGER_DIGITS,  # type: ignore[return-value]
                                MAX_NUMBER_DIGITS)


def _block(text: str, path: str, line: int) -> n.Block:
    return compiled_block(text, path, line) or _Line(_tokens(text, 0), path, line).block()


def _condition(text: str, path: str, line: int, kind: str, start: int, pos: int) -> Open:
    """An If/While head from ``pos`` on (the keyword before it): on the compiled reader when it is
    there (the same condition as ``_Line.condition``, or None to let that method decide)."""
    if _COMPILED_CONDITION is not None:
        found: tuple[n.Expr, int, int] | None = _COMPILED_CONDITION(  # type: ignore[assignment]
            text, pos, path, line, kind == "If", INTEGER_DIGITS, MAX_NUMBER_DIGITS)
        if found is not None:
            cond, end, extra = found
            return Open(kind, _new_span(n.Span, (path, line, start, line, end)), cond=cond, extra=extra)
    return _Line(_tokens(text, pos), path, line).condition(kind, start)


def _logfile(text: str, path: str, line: int, start: int, pos: int) -> n.LogFile:
    """``logfile NAME [mode]``: the name is a quoted string or a bare file name (C:\\temp\\l.txt)."""
    match = _FILE_NAME.match(text, pos)
    if match is None:
        raise _GiveUp
    quoted = match.group(1)
    name = quoted if quoted is not None else match.group(2)
    rest = _Line(_tokens(text, match.end()), path, line)
    end = match.end() + 1
    mode = None
    if rest.tokens[0][0]:
        mode, _s, end = rest.operand()
        rest.at_end()
    return n.LogFile(name, mode, rest.span(start, end))


def _switch_or_command(text: str, path: str, line: int, word: str, start: int, pos: int) -> n.Switch | n.Command:
    """``TCAGuard on``, ``ZHC off``: a Switch; ``ZHCINIT [#4104] 10 5``, ``modbus s1 f5 a22 v1``: a Command
    whose arguments are the rest of the line up to its ';' comment (its span ends there, blanks included,
    as the grammar's RAW_ARGS does), and their values as the grammar's builder reads them."""
    if pos < len(text) and text[pos] not in " \t;":  # not the keyword alone (ZHCx, a non-ASCII letter)
        raise _GiveUp
    if word in _SWITCHES:
        state = _ON_OFF.match(text, pos)
        if state is None:
            raise _GiveUp
        return n.Switch(word, state.group(1).lower() == "on", n.Span(path, line, start, line, state.end(1) + 1))
    raw = _RAW_ARGS.match(text, pos)
    if raw is None:
        raise _GiveUp
    if raw.group(1) is None:
        return n.Command(word, "", n.Span(path, line, start, line, pos + 1), None)
    args = raw.group(1).strip()
    values = command_values(args, raw.start(1) + 1, path, line)
    return n.Command(word, args, n.Span(path, line, start, line, raw.end(1) + 1), values)


def paren_before_comment(text: str) -> bool:
    """Whether a '(' (a ( ) comment, an operator message) stands in ``text`` before its ';' comment,
    strings left out: such a line is the grammar's, while a '(' inside the ';' comment is only its
    text (``#4504 = 50 ; feed (mm/min)``).  ``_lexer.c``'s ``paren_before_comment`` is the same."""
    bare = _STRINGS.sub("", text) if '"' in text else text
    paren = bare.find("(")
    return paren >= 0 and bare.find(";", 0, paren) < 0


def parse_fast(text: str, path: str, line: int) -> LineResult | object:
    """The line's node, or GIVE_UP when the grammar must decide."""
    if "(" in text and paren_before_comment(text):  # ( ) comments and MSG comments: the grammar's business
        return GIVE_UP
    try:
        return _statement(text, path, line)
    except (_GiveUp, IndexError):
        return GIVE_UP
