"""The launch request's arguments: the job, the machine and how to run it, paths made absolute."""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from edingcnc_lang.host import DialogAnswer
from edingcnc_lang.machine import start_state


class LaunchError(Exception):
    """Launch arguments that cannot be used; the text is the failed response's message."""


@dataclass
class Launch:
    """The launch request's arguments, paths resolved."""

    program: Path
    ini: Path | None = None
    macro: Path | None = None
    user_macro: Path | None = None
    answers: list[DialogAnswer] = field(default_factory=list)
    probe_surface: Path | None = None
    stop_on_entry: bool = False
    no_debug: bool = False
    log_dir: Path | None = None
    max_steps: int | None = None
    # the machine before the job: vars, offsets and tools as parameters (machine.start_state), the probe's height
    variables: dict[int, float] = field(default_factory=dict)
    probe_at: float | None = None



def launch_of(args: dict[str, Any]) -> Launch:
    """The launch arguments, paths relative to ``cwd`` (the workspace folder) made absolute."""
    base = Path(str(args.get("cwd") or os.getcwd()))

    def path(key: str, must: bool = False) -> Path | None:
        value = args.get(key)
        if not value:
            if must:
                raise LaunchError(f"launch needs {key!r} (the job to run)")
            return None
        try:
            found = (base / str(value)).resolve()
            regular = found.is_file()
        except OSError as err:  # a name too long for the file system, a loop of links
            raise LaunchError(f"{key}: cannot read {_shown(value)}: {err.strerror or err}") from None
        if not regular:
            raise LaunchError(f"{key}: {_shown(value)} is not a file")
        return found

    try:
        answers = [DialogAnswer.parse(str(a)) for a in args.get("answers", [])]
    except ValueError as err:
        raise LaunchError(f"answers: {err}") from None
    program = path("program", must=True)
    assert program is not None
    log_dir = args.get("logDir")
    try:
        log_folder = (base / str(log_dir)).resolve() if log_dir else None
        not_folder = log_folder is not None and log_folder.exists() and not log_folder.is_dir()
    except OSError as err:
        raise LaunchError(f"logDir: cannot use {_shown(log_dir)}: {err.strerror or err}") from None
    if not_folder:
        raise LaunchError(f"logDir: {_shown(log_dir)} is not a folder")
    max_steps = args.get("maxSteps")
    probe_at = args.get("probeAt")
    return Launch(program, ini=path("ini"), macro=path("macro"), user_macro=path("userMacro"), answers=answers,
                  probe_surface=path("probeSurface"), stop_on_entry=bool(args.get("stopOnEntry")),
                  no_debug=bool(args.get("noDebug")), log_dir=log_folder,
                  max_steps=int(max_steps) if max_steps else None, variables=_start_state(args),
                  probe_at=float(probe_at) if probe_at is not None else None)


def _start_state(args: dict[str, Any]) -> dict[int, float]:
    """``vars`` ({"4520": 1}), ``offsets`` ({"G54": [100, 50, -20]}) and ``tools`` ({"3": [42.5, 6]} or
    {"3": 42.5}) as the parameters they set, read as ``--var``, ``--offset`` and ``--tool`` are."""
    def text(value: Any) -> str:
        return ",".join(map(str, value)) if isinstance(value, list) else str(value)

    found: dict[int, float] = {}
    for key, read in (("vars", start_state.variable), ("offsets", start_state.offset), ("tools", start_state.tool)):
        for name, value in (args.get(key) or {}).items():
            try:
                found.update(read(str(name), text(value)))
            except ValueError as err:
                raise LaunchError(f"{key}: {err}") from None
    return found


def _shown(value: object) -> str:
    """A path as the message shows it: at most 80 characters."""
    text = str(value)
    return text if len(text) <= 80 else text[:80] + "..."
