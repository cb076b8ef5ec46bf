"""The launch request's arguments: the job, the machine and how to run it, paths made absolute."""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from edingcnc_lang.host import DialogAnswer


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



def launch_of(args: dict[str, Any]) -> Launch:
    """The launch arguments, paths relative to ``cwd`` (the workspace folder) made absolute."""
    base = Path(str(args.get("cwd") or os.getcwd()))

    def path(key: str, must: bool = False) -> Path | None:
        value = args.get(key)
        if not value:
            if must:
                raise LaunchError(f"launch needs {key!r} (the job to run)")
            return None
        found = (base / str(value)).resolve()
        if not found.is_file():
            raise LaunchError(f"{key}: {value} is not a file")
        return found

    try:
        answers = [DialogAnswer.parse(str(a)) for a in args.get("answers", [])]
    except ValueError as err:
        raise LaunchError(f"answers: {err}") from None
    program = path("program", must=True)
    assert program is not None
    log_dir = args.get("logDir")
    max_steps = args.get("maxSteps")
    return Launch(program, ini=path("ini"), macro=path("macro"), user_macro=path("userMacro"), answers=answers,
                  probe_surface=path("probeSurface"), stop_on_entry=bool(args.get("stopOnEntry")),
                  no_debug=bool(args.get("noDebug")), log_dir=(base / str(log_dir)).resolve() if log_dir else None,
                  max_steps=int(max_steps) if max_steps else None)
