"""``ecnc run JOB``: run a job on the virtual machine and report what it did."""
from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING

import click

from ..errors import EcncError, JobAborted
from ..host import DialogAnswer, Host, scripted_dialogs
from .common import existing_file

if TYPE_CHECKING:
    from ..runner import RunResult

MESSAGE_LABEL = {"msg": "msg", "warn": "warning", "error": "error", "log": "log", "dialog": "dialog"}


def _answers(values: tuple[str, ...]) -> list[DialogAnswer]:
    try:
        return [DialogAnswer.parse(v) for v in values]
    except ValueError as err:
        raise click.BadParameter(str(err), param_hint="--answer") from None


@click.command()
@click.argument("job", type=existing_file())
@click.option("--ini", type=existing_file(), help="Machine configuration (cnc.ini).")
@click.option("--macro", type=existing_file(), help="Macro file (default: the ini's, else the packaged one).")
@click.option("--user-macro", type=existing_file(), help="User macro file.")
@click.option("--json", "as_json", is_flag=True, help="Print the final machine state as JSON on stdout.")
@click.option("--trace", type=click.Path(dir_okay=False), help="Write one CSV row per executed move.")
@click.option("--samples", type=click.Path(dir_okay=False), help="Write the interpolated trajectory (.csv or .npz).")
@click.option("--answer", "answers", multiple=True, metavar="VALUE",
              help="Answer for the next dlgmsg: ok, cancel or ok:#N=V,#M=W (repeatable).")
@click.option("--max-steps", type=click.IntRange(min=1), help="Stop with an error after this many statements.")
@click.option("--log-dir", type=click.Path(file_okay=False), help="Folder for logfile/logmsg (default: the job's).")
@click.option("--allow-exec", is_flag=True, help="Let Exec start external programs.")
@click.option("--save-vars", is_flag=True, help="Write persistent variables back to the ini.")
@click.option("--no-simulation", is_flag=True, help="Run with #5380 = 0 (as if on the real machine).")
@click.option("--block-delete", is_flag=True, help="Skip lines that start with '/'.")
def run(job: str, ini: str | None, macro: str | None, user_macro: str | None, as_json: bool,
        trace: str | None, samples: str | None, answers: tuple[str, ...], max_steps: int | None,
        log_dir: str | None, allow_exec: bool, save_vars: bool, no_simulation: bool, block_delete: bool) -> None:
    """Run JOB as the controller would (in simulation) and report what the machine does."""
    import json

    from ..runner import RunOptions, run_file

    if save_vars and not ini:
        raise click.UsageError("--save-vars needs --ini (the file to write the variables to)")
    if log_dir and not Path(log_dir).is_dir():
        raise click.BadParameter(f"folder {log_dir} does not exist", param_hint="--log-dir")

    def show(kind: str, text: str, path: str, line: int) -> None:
        if not as_json and kind in MESSAGE_LABEL and kind != "dialog":
            click.echo(f"{path}:{line}: {MESSAGE_LABEL[kind]}: {text}", err=True)

    options = RunOptions(
        ini=Path(ini) if ini else None, macro=Path(macro) if macro else None,
        user_macro=Path(user_macro) if user_macro else None,
        host=Host(dialog=scripted_dialogs(_answers(answers)), message=show),
        max_steps=max_steps, trace=Path(trace) if trace else None, samples=Path(samples) if samples else None,
        log_dir=Path(log_dir) if log_dir else None, allow_exec=allow_exec, simulation=not no_simulation,
        block_delete=block_delete, save_vars=save_vars)
    try:
        result = run_file(job, options)
    except EcncError as err:
        partial: RunResult | None = getattr(err, "result", None)
        if as_json and partial is not None:
            click.echo(json.dumps(partial.to_json(), indent=1))
        if not isinstance(err, JobAborted):  # an errmsg text was shown as it ran (or is in the JSON)
            click.echo(err.format(), err=True)
        sys.exit(err.exit_code)
    if as_json:
        click.echo(json.dumps(result.to_json(), indent=1))

