"""``ecnc lsp``: the language server editors start, speaking LSP on stdin/stdout."""
from __future__ import annotations

import click

from edingcnc_lang.cli.base import Command


@click.command("lsp", cls=Command,
               short_help="The language server for editors, on stdin/stdout.")
@click.option("--stdio", is_flag=True,
              help="Talk over stdin/stdout: the only transport, accepted because some editors ask for it.")
def lsp(stdio: bool) -> int:
    """Serve the Language Server Protocol on stdin/stdout (started by an editor; see docs/editors.md).

    Needs the lsp extra: pip install 'edingcnc-lang[lsp]'.
    """
    from edingcnc_lang.lsp import main

    return main()
