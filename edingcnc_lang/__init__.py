"""edingcnc-lang: parser, interpreter, linter and kinematics simulator for EdingCNC G-code and macros.

The embedding API in one place::

    from edingcnc_lang import Host, RunOptions, run_file
    result = run_file("job.nc", RunOptions(host=Host(dialog=my_dialog)))
    print(result.machine, result.variables)

The names are imported on first use (PEP 562), so ``import edingcnc_lang`` and the ``ecnc``
command start without loading the parser, the interpreter or numpy until they are needed.
"""
from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from edingcnc_lang.canon import Arc, Event, Move
    from edingcnc_lang.config import MachineConfig, load_config
    from edingcnc_lang.diagnostics import Diagnostic, SyntaxErrors
    from edingcnc_lang.errors import ConfigError, EcncError, JobAborted, MachineError, PluginError
    from edingcnc_lang.host import DialogAnswer, DialogField, Host
    from edingcnc_lang.syntax.nodes import Program
    from edingcnc_lang.syntax.parser import parse_file, parse_text, read_statements
    from edingcnc_lang.runner import Run, RunOptions, RunResult, run_file, run_string

__version__ = "0.1.0"
# where the project lives: SARIF rules' helpUri, the tool's informationUri, the editor extension's links
HOMEPAGE = "https://github.com/edingcnc-lang/edingcnc-lang"

# public name -> the module (relative to this package) that defines it
_EXPORTS: dict[str, str] = {
    **dict.fromkeys(("Arc", "Event", "Move"), ".canon"),
    **dict.fromkeys(("MachineConfig", "load_config"), ".config"),
    **dict.fromkeys(("Diagnostic", "SyntaxErrors"), ".diagnostics"),
    **dict.fromkeys(("ConfigError", "EcncError", "JobAborted", "MachineError", "PluginError"), ".errors"),
    **dict.fromkeys(("DialogAnswer", "DialogField", "Host"), ".host"),
    "Program": ".syntax.nodes",
    **dict.fromkeys(("parse_file", "parse_text", "read_statements"), ".syntax.parser"),
    **dict.fromkeys(("Run", "RunOptions", "RunResult", "run_file", "run_string"), ".runner"),
}

__all__ = [
    "Arc", "ConfigError", "Diagnostic", "DialogAnswer", "DialogField", "EcncError", "Event", "Host",
    "JobAborted", "MachineConfig", "MachineError", "Move", "PluginError", "Program", "Run", "RunOptions", "RunResult",
    "SyntaxErrors", "load_config", "parse_file", "parse_text", "read_statements", "run_file", "run_string",
]


def __getattr__(name: str) -> Any:
    """Import a public name's module the first time the name is asked for, then cache the name."""
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(module, __name__), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
