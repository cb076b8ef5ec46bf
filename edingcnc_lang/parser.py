"""The old place of the parser's entry points, kept for programs that import them from here.

The parser lives in ``edingcnc_lang.syntax`` (``syntax/parser.py``); new code imports it from there
or uses the names ``edingcnc_lang`` itself exports.
"""
from __future__ import annotations

from edingcnc_lang.syntax.parser import StatementReader, check_file, parse_file, parse_text, read_statements

__all__ = ["StatementReader", "check_file", "parse_file", "parse_text", "read_statements"]
