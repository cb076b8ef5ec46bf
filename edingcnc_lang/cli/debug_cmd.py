"""``ecnc debug``: the step debugger, speaking the Debug Adapter Protocol on stdin/stdout."""
from __future__ import annotations

import sys

import click

from edingcnc_lang.cli.base import Command


@click.command("debug", cls=Command, short_help="Debug jobs and macro files over the Debug Adapter Protocol.")
def debug() -> int:
    """Speak the Debug Adapter Protocol (DAP) on standard input and output, for an editor.

    The editor starts this command and sends `launch` with the job (`program`) and the machine
    (`ini`, `macro`, `userMacro`, `answers`, `probeSurface`, `stopOnEntry`, `noDebug`); see
    docs/debugging.md.  Nothing else is written to standard output.
    """
    from edingcnc_lang.debug import serve

    protocol_out = sys.stdout.buffer
    sys.stdout = sys.stderr  # a stray print must not break the protocol stream
    return serve(sys.stdin.buffer, protocol_out)
