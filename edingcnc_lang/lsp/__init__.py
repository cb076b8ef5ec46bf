"""``ecnc lsp``: a Language Server for EdingCNC macro files and jobs, over stdio.

Needs the ``lsp`` extra (pygls).  One feature module per LSP request (``hover``,
``completion``, ``navigation``, ``actions``, ``formatting``) over one shared language
model (``model``), with the explanations from ``edingcnc_lang.knowledge`` and the
findings from ``ecnc lint``.
"""
from __future__ import annotations

import logging
import os
import sys

from edingcnc_lang.errors import require_extra


def main() -> int:
    """Serve LSP on stdin/stdout until the client says exit; 0 if it asked for a shutdown first, else 1.

    The protocol gets its own handle on stdout, which the server closes at the end; anything
    else printed meanwhile goes to stderr, so it cannot corrupt the protocol stream.
    """
    require_extra("pygls", "lsp", "the language server")
    require_extra("lsprotocol", "lsp", "the language server")
    from edingcnc_lang.lsp.server import server
    _log_in_one_line()
    protocol_out = os.fdopen(os.dup(sys.stdout.fileno()), "wb")
    saved, sys.stdout = sys.stdout, sys.stderr
    try:
        server.start_io(sys.stdin.buffer, protocol_out)
    finally:
        sys.stdout = saved
    return 0 if server.shut_down else 1


class _OneLine(logging.Formatter):
    """A log record as one line on stderr: a client's malformed message is its fault, not a crash."""

    def format(self, record: logging.LogRecord) -> str:
        first_line = record.getMessage().partition("\n")[0]  # pygls pastes tracebacks into some
        text = f"ecnc lsp: {record.levelname.lower()}: {first_line}"
        if record.exc_info and record.exc_info[1] is not None:
            error = record.exc_info[1]
            text += f": {type(error).__name__}: {error}"
        return text


def _log_in_one_line() -> None:
    """Route pygls's warnings (a message that is not JSON, an unknown method) to one line each,
    instead of logging's last-resort handler, which prints a Python traceback."""
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(_OneLine())
    pygls_log = logging.getLogger("pygls")
    pygls_log.addHandler(handler)
    pygls_log.setLevel(logging.WARNING)
    pygls_log.propagate = False
