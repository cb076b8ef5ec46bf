"""Lark trees of one line -> AST nodes with spans (the grammar's half of the parser).

``line_parser.py`` parses a line with the grammar and hands the tree to ``Builder``;
mistakes the grammar cannot see (an unknown KIN mode, a number too large for a
double) are raised here as ``LineError`` with the code and column to report.
"""
from __future__ import annotations

import math
import re
from collections.abc import Callable
from typing import TYPE_CHECKING

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.syntax.blocks import Close, LineResult, Open

if TYPE_CHECKING:
    from lark import Token, Tree

KIN_MODES = frozenset({"ON", "OFF", "CTRL", "X2A", "X2XA", "Y2A", "Y2YA", "Z2C", "Z2ZC", "Y2YAZ2ZC"})


class LineError(Exception):
    """A problem found while converting one line (code, message, column)."""

    def __init__(self, code: str, message: str, col: int) -> None:
        super().__init__(message)
        self.code, self.message, self.col = code, message, col


def _strip(name: str) -> str:
    return name.rsplit("__", 1)[-1]


class Builder:
    """Converts the Lark tree of one line into AST nodes with spans."""

    def __init__(self, path: str, line: int) -> None:
        self.path = path
        self.line = line

    def span(self, item: Tree | Token) -> n.Span:
        if isinstance(item, str):
            return n.Span(self.path, self.line, item.column or 0, self.line, item.end_column or 0)
        meta = item.meta
        if getattr(meta, "empty", True):
            return n.Span(self.path, self.line, 0, self.line, 0)
        return n.Span(self.path, self.line, meta.column, self.line, meta.end_column)

    # expressions ------------------------------------------------------------
    def expr(self, item: Tree | Token) -> n.Expr:
        if isinstance(item, str):  # a bare NUMBER inlined by '?' rules
            return n.Number(self._finite(item), self.span(item))
        kind = _strip(item.data)
        handler = self._EXPR[kind]
        return handler(self, item)

    def _number(self, tree: Tree) -> n.Expr:
        return n.Number(self._finite(_token(tree.children[0])), self.span(tree))

    def _finite(self, token: Token) -> float:
        value = float(token.replace(" ", "").replace("\t", "") if " " in token or "\t" in token else token)
        if math.isinf(value):
            raise LineError("E100", f"the number {str(token)[:12]}... is too large", token.column or 0)
        return value

    def _param(self, tree: Tree) -> n.Expr:
        return n.Param(self.expr(tree.children[0]), self.span(tree))

    def _unary(self, tree: Tree) -> n.Expr:
        op, operand = str(tree.children[0]), self.expr(tree.children[1])
        if isinstance(operand, n.Number):  # fold signs into literals: X-5 is Number(-5)
            value = -operand.value if op == "-" else operand.value
            return n.Number(value, self.span(tree))
        return n.Unary(op, operand, self.span(tree))

    def _binary(self, tree: Tree) -> n.Expr:
        left, op, right = tree.children
        return n.Binary(str(op).upper(), self.expr(left), self.expr(right), self.span(tree))

    def _compare(self, tree: Tree) -> n.Expr:
        left, op, right = tree.children
        return n.Compare(_COMPARE_OPS[str(op).upper()], self.expr(left), self.expr(right),
                         self.span(tree))

    def _call(self, tree: Tree) -> n.Expr:
        name, arg = tree.children
        return n.Call(str(name).upper(), (self.expr(arg),), self.span(tree))

    def _atan(self, tree: Tree) -> n.Expr:
        _, y, _slash, x = tree.children
        return n.Call("ATAN", (self.expr(y), self.expr(x)), self.span(tree))

    def _atan1(self, tree: Tree) -> n.Expr:
        return n.Call("ATAN", (self.expr(tree.children[1]),), self.span(tree))

    _EXPR: dict[str, Callable[["Builder", Tree], n.Expr]] = {
        "number": _number, "param": _param, "unary": _unary, "binary": _binary,
        "compare": _compare, "call": _call, "atan": _atan, "atan1": _atan1,
    }

    # statements -------------------------------------------------------------
    def statement(self, tree: Tree) -> LineResult:
        if not tree.children:
            return None
        stmt = tree.children[0]
        return self._STMT[_strip(stmt.data)](self, stmt)

    def _block(self, tree: Tree) -> n.Stmt:
        words: list[n.Word] = []
        assigns: list[n.Assign] = []
        message: str | None = None
        block_delete = False
        for child in tree.children:
            if isinstance(child, str):
                if _strip(_token(child).type) == "SLASH":
                    block_delete = True
                else:  # MSG_COMMENT: "(MSG text)"
                    message = _MSG_TEXT.match(str(child)).group(1)  # type: ignore[union-attr]
            elif _strip(child.data) == "word":
                letter, value = child.children
                words.append(n.Word(str(letter).upper(), self.expr(value), self.span(child)))
            else:
                target, value = child.children
                param = self.expr(target)
                assert isinstance(param, n.Param)
                assigns.append(n.Assign(param, self.expr(value), self.span(child)))
        return make_block(words, assigns, message, block_delete, self.span(tree))

    def _sub_head(self, tree: Tree) -> LineResult:
        return Open("Sub", self.span(tree), name=str(tree.children[1]))

    def _cond(self, tree: Tree) -> tuple[n.Expr, int]:
        expr, *extra = tree.children
        return self.expr(expr), len(extra)

    def _if_head(self, tree: Tree) -> LineResult:
        cond, extra = self._cond(tree.children[1])
        return Open("If", self.span(tree), cond=cond, extra=extra)

    def _while_head(self, tree: Tree) -> LineResult:
        cond, extra = self._cond(tree.children[1])
        return Open("While", self.span(tree), cond=cond, extra=extra)

    def _close(kind: str) -> Callable[["Builder", Tree], LineResult]:  # type: ignore[misc]
        def handler(self: "Builder", tree: Tree) -> LineResult:
            return Close(kind, self.span(tree))
        return handler

    def _gosub(self, tree: Tree) -> n.Stmt:
        return n.GoSub(str(tree.children[1]), self.span(tree))

    def _items(self, children: list[Tree | Token]) -> tuple[n.MessageItem, ...]:
        return tuple(self._item(c) for c in children)

    def _item(self, child: Tree | Token) -> n.MessageItem:
        kind = _strip(child.type) if isinstance(child, str) else ""
        if kind == "STRING":
            return str(child)[1:-1]
        if kind == "STAMP":
            return n.Stamp(self.span(child))
        return self.expr(child)

    def _message(self, tree: Tree) -> n.Stmt:
        kind = str(tree.children[0]).lower()
        return n.Message(kind, self._items(tree.children[1:]), self.span(tree))

    def _dialog(self, tree: Tree) -> n.Stmt:
        return n.Dialog(self._items(tree.children[1:]), self.span(tree))

    def _logfile(self, tree: Tree) -> n.Stmt:
        name_tok = _token(tree.children[1])
        name = str(name_tok)
        if _strip(name_tok.type) == "STRING":
            name = name[1:-1]
        mode = self.expr(tree.children[2]) if len(tree.children) > 2 else None
        return n.LogFile(name, mode, self.span(tree))

    def _home(self, tree: Tree) -> n.Stmt:
        keyword, axis = tree.children
        return n.Home(str(axis).upper(), str(keyword).lower() == "hometandem", self.span(tree))

    def _switch(self, tree: Tree) -> n.Stmt:
        name, state = tree.children
        return n.Switch(str(name).lower(), str(state).lower() == "on", self.span(tree))

    def _kin(self, tree: Tree) -> n.Stmt:
        mode_tok = _token(tree.children[1])
        mode = str(mode_tok).upper()
        if mode not in KIN_MODES:
            raise LineError("E107", f"unknown KIN mode '{mode_tok}' (expected ON, OFF, CTRL or one of "
                             "X2A X2XA Y2A Y2YA Z2C Z2ZC Y2YAZ2ZC)", mode_tok.column or 0)
        args = tuple(self.expr(c) for c in tree.children[2:])
        if args and mode != "CTRL":
            raise LineError("E100", f"KIN {mode} takes no arguments", self.span(tree.children[2]).col)
        if mode == "CTRL" and not 1 <= len(args) <= 7:
            raise LineError("E100", "KIN CTRL needs a control id and up to 6 values", mode_tok.column or 0)
        return n.Kin(mode, args, self.span(tree))

    def _prepare_delta(self, tree: Tree) -> n.Stmt:
        vel = self.expr(tree.children[1]) if len(tree.children) > 1 else None
        return n.PrepareLinDeltaHome(vel, self.span(tree))

    def _command(self, tree: Tree) -> n.Stmt:
        args = str(tree.children[1]).strip() if len(tree.children) > 1 else ""
        values = command_values(args, _token(tree.children[1]).column or 1, self.path, self.line) if args else None
        return n.Command(str(tree.children[0]).lower(), args, self.span(tree), values)

    def _percent(self, tree: Tree) -> LineResult:
        return None

    _STMT: dict[str, Callable[["Builder", Tree], LineResult]] = {
        "block": _block, "sub_head": _sub_head, "endsub": _close("EndSub"),
        "if_head": _if_head, "else_": _close("Else"), "endif": _close("EndIf"),
        "while_head": _while_head, "endwhile": _close("EndWhile"), "gosub": _gosub,
        "message": _message, "dialog": _dialog, "logfile": _logfile, "home": _home,
        "switch": _switch, "kin": _kin, "prepare_delta": _prepare_delta,
        "command": _command, "percent": _percent,
    }
    del _close


_MSG_TEXT = re.compile(r"\(\s*msg\b[ \t,]*([^)]*)\)", re.IGNORECASE)
_COMPARE_OPS = {"==": "==", "EQ": "==", "<>": "<>", "!=": "<>", "NE": "<>", "<": "<", "LT": "<",
                ">": ">", "GT": ">", "<=": "<=", "LE": "<=", ">=": ">=", "GE": ">="}


def command_values(args: str, col: int, path: str, line: int) -> tuple[n.Expr, ...] | None:
    """A command's arguments (starting at column ``col``) read as expressions, each spanned where it
    stands in the line, or None when they are not a list of expressions (a file name, words).  Shared
    by the grammar's builder and the fast path (``fastparse``), so both read a command alike."""
    from edingcnc_lang.syntax.line_parser import _LineError, parse_line  # the line parser builds its trees here

    if _not_values(args):
        return None
    pad = " " * max(0, col - 1 - len("msg "))  # "msg " ends where the arguments start
    try:
        message = parse_line(f"{pad}msg {args}", path, line)
    except _LineError:
        return None
    if not isinstance(message, n.Message) or any(isinstance(item, (str, n.Stamp)) for item in message.items):
        return None
    return message.items  # type: ignore[return-value]  # (no strings or stamps: expressions)


def _not_values(args: str) -> bool:
    """Whether ``args`` (no ';' in them) are surely not a list of expressions, without parsing them:
    a '"' (a string, or a mistake) or a letter outside brackets (a word: ``s1 f5``, ``num 5025``,
    ``table.txt``; a list item never starts with a letter) makes ``msg ARGS`` a message with a
    string or stamp in it, or a syntax error.  A '(' comment could hide either: then it parses."""
    if "(" in args:
        return False
    if '"' in args:
        return True
    depth = 0
    for ch in args:
        if ch == "[":
            depth += 1
        elif ch == "]":
            depth -= 1
        elif depth <= 0 and ch.isalpha():
            return True
    return False


def make_block(words: list[n.Word], assigns: list[n.Assign], message: str | None,
                block_delete: bool, span: n.Span) -> n.Block:
    """Build a Block, moving a literal N word into ``line_number``."""
    line_number = None
    if words and words[0].letter == "N" and isinstance(words[0].value, n.Number):
        line_number = int(words[0].value.value)
        words = words[1:]
    return n.Block(tuple(words), tuple(assigns), message, line_number, block_delete, span)


def _token(child: Token | Tree | str) -> Token:
    """A child the grammar makes a token (a terminal), typed as one."""
    return child  # type: ignore[return-value]
