"""``ecnc lsp``: a Language Server for EdingCNC macro files and jobs, over stdio.

Needs the ``lsp`` extra (pygls).  One feature module per LSP request (``hover``,
``completion``, ``navigation``, ``actions``, ``formatting``) over one shared language
model (``model``), with the explanations from ``edingcnc_lang.knowledge`` and the
findings from ``ecnc lint``.
"""
from __future__ import annotations

import os
import sys

from ..errors import require_extra


def main() -> int:
    """Serve LSP on stdin/stdout until the client says exit; 0 if it asked for a shutdown first, else 1.

    The protocol gets its own handle on stdout, which the server closes at the end; anything
    else printed meanwhile goes to stderr, so it cannot corrupt the protocol stream.
    """
    require_extra("pygls", "lsp", "the language server")
    require_extra("lsprotocol", "lsp", "the language server")
    from .server import server
    protocol_out = os.fdopen(os.dup(sys.stdout.fileno()), "wb")
    saved, sys.stdout = sys.stdout, sys.stderr
    try:
        server.start_io(sys.stdin.buffer, protocol_out)
    finally:
        sys.stdout = saved
    return 0 if server.shut_down else 1
