"""edingcnc-lang: parser, interpreter, linter and kinematics simulator for EdingCNC G-code and macros.

The embedding API in one place::

    from edingcnc_lang import Host, RunOptions, run_file
    result = run_file("job.nc", RunOptions(host=Host(dialog=my_dialog)))
    print(result.machine, result.variables)
"""
from __future__ import annotations

from .canon import Arc, Event, Move
from .config import MachineConfig, load_config
from .diagnostics import Diagnostic, SyntaxErrors
from .errors import ConfigError, EcncError, MachineError, PluginError
from .host import DialogAnswer, DialogField, Host
from .nodes import Program
from .parser import parse_file, parse_text, read_statements
from .runner import Run, RunOptions, RunResult, run_file, run_string

__version__ = "0.1.0"

__all__ = [
    "Arc", "ConfigError", "Diagnostic", "DialogAnswer", "DialogField", "EcncError", "Event", "Host",
    "MachineConfig", "MachineError", "Move", "PluginError", "Program", "Run", "RunOptions", "RunResult",
    "SyntaxErrors", "load_config", "parse_file", "parse_text", "read_statements", "run_file", "run_string",
]
