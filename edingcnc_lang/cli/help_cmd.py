"""``ecnc help [CODE | COMMAND...]``: the long explanation of a lint code, or a command's help."""
from __future__ import annotations

import click

from edingcnc_lang.errors import EXIT_OK
from edingcnc_lang.cli.base import Command, usage_error
from edingcnc_lang.cli.value_types import HELP_TOPIC


@click.command("help", cls=Command, short_help="Explain a lint or kins check code (ecnc help V302) or show a command's help.")
@click.argument("topic", metavar="[CODE | COMMAND...]", nargs=-1, type=HELP_TOPIC)
@click.pass_context
def help_command(ctx: click.Context, topic: tuple[str, ...]) -> int:
    """Print the long explanation of lint CODE (as ecnc lint --explain CODE) or of a kins check
    finding (ecnc help K101), or the help of
    COMMAND (ecnc help kins inverse); alone, the help of ecnc."""
    context = ctx.find_root()
    for word in topic:
        group = context.command
        command = group.get_command(context, word) if isinstance(group, click.Group) else None
        if command is None:
            if context is ctx.find_root() and len(topic) == 1:
                print(explain_or_fail(word))
                return EXIT_OK
            raise usage_error(f"no command {' '.join([*context.command_path.split()[1:], word])!r} "
                              "(see ecnc --help)")
        context = click.Context(command, info_name=word, parent=context)
    print(context.get_help())
    return EXIT_OK


def explain_or_fail(code: str) -> str:
    """The explanation of lint ``code``, else of a G/M code, parameter, command or function of the
    language (the table hover and completion use), or a usage error that points to the lists."""
    from edingcnc_lang.lint import UnknownCode
    from edingcnc_lang.lint.explain import explain, explain_kins

    try:
        return explain(code)
    except UnknownCode:
        from edingcnc_lang.knowledge import describe

        text = explain_kins(code) or describe(code)
        if text is None:
            shown = code if len(code) <= 40 else code[:40] + "..."
            raise usage_error(f"no command or lint code {shown!r} (see ecnc --help and ecnc lint --list-codes)") from None
        return text
