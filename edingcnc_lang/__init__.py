"""edingcnc-lang: parser, interpreter, linter and kinematics simulator for EdingCNC G-code and macros.

The embedding API in one place (every name in ``__all__``; docs/api.md is its reference)::

    from edingcnc_lang import Host, RunOptions, run_file
    result = run_file("job.nc", RunOptions(ini="cnc.ini", host=Host(dialog=my_dialog)))
    print(result.machine, result.parameters[4050])

The names are imported on first use (PEP 562), so ``import edingcnc_lang`` and the ``ecnc``
command start without loading the parser, the interpreter or numpy until they are needed.
"""
from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from edingcnc_lang.canon import Arc, Batch, Css, Event, Move, Pose
    from edingcnc_lang.codes import Code, RuntimeCode, Severity
    from edingcnc_lang.config import MachineConfig, load_config
    from edingcnc_lang.diagnostics import Diagnostic, SyntaxErrors
    from edingcnc_lang.errors import (
        CallbackError,
        Cancelled,
        ConfigError,
        EcncError,
        Frame,
        Interrupted,
        JobAborted,
        Location,
        MachineError,
        PluginError,
    )
    from edingcnc_lang.host import DialogAnswer, DialogField, Host
    from edingcnc_lang.kinematics.trajectory import move_length, move_points
    from edingcnc_lang.lint.driver import LintOptions, lint_paths
    from edingcnc_lang.machine.observe import MachineView
    from edingcnc_lang.machine.parameters import ParameterView
    from edingcnc_lang.mdi import MdiOutcome, MdiSession
    from edingcnc_lang.motion.planner.estimate import Estimate
    from edingcnc_lang.motion.sinks import Timing
    from edingcnc_lang.plot.render import plot_toolpath
    from edingcnc_lang.plot.toolpath import Toolpath, record_job
    from edingcnc_lang.syntax.nodes import Program, Span, Stmt
    from edingcnc_lang.syntax.parser import parse_file, parse_text, read_statements
    from edingcnc_lang.syntax.visit import Visitor, walk
    from edingcnc_lang.runner import MoveStream, Run, RunOptions, RunResult, result_of, run_file, run_string

__version__ = "0.1.0"
# where the project lives: SARIF rules' helpUri, the tool's informationUri, the editor extension's links
HOMEPAGE = "https://github.com/edingcnc-lang/edingcnc-lang"

# public name -> the module (relative to this package) that defines it
_EXPORTS: dict[str, str] = {
    **dict.fromkeys(("Arc", "Batch", "Css", "Event", "Move", "Pose"), ".canon"),
    **dict.fromkeys(("Code", "RuntimeCode", "Severity"), ".codes"),
    **dict.fromkeys(("MachineConfig", "load_config"), ".config"),
    **dict.fromkeys(("Diagnostic", "SyntaxErrors"), ".diagnostics"),
    **dict.fromkeys(("CallbackError", "Cancelled", "ConfigError", "EcncError", "Frame", "Interrupted", "JobAborted",
                     "Location", "MachineError", "PluginError"), ".errors"),
    **dict.fromkeys(("DialogAnswer", "DialogField", "Host"), ".host"),
    **dict.fromkeys(("move_length", "move_points"), ".kinematics.trajectory"),
    **dict.fromkeys(("LintOptions", "lint_paths"), ".lint.driver"),
    "MachineView": ".machine.observe",
    "ParameterView": ".machine.parameters",
    **dict.fromkeys(("MdiOutcome", "MdiSession"), ".mdi"),
    "Estimate": ".motion.planner.estimate",
    "Timing": ".motion.sinks",
    "plot_toolpath": ".plot.render",
    **dict.fromkeys(("Toolpath", "record_job"), ".plot.toolpath"),
    **dict.fromkeys(("Program", "Span", "Stmt"), ".syntax.nodes"),
    **dict.fromkeys(("parse_file", "parse_text", "read_statements"), ".syntax.parser"),
    **dict.fromkeys(("Visitor", "walk"), ".syntax.visit"),
    **dict.fromkeys(("MoveStream", "Run", "RunOptions", "RunResult", "result_of", "run_file", "run_string"),
                    ".runner"),
}

# written out (not computed) so type checkers see what is exported; tests/api pins it to _EXPORTS
__all__ = [
    "Arc", "Batch", "CallbackError", "Cancelled", "Code", "ConfigError", "Css", "Diagnostic", "DialogAnswer",
    "DialogField", "EcncError", "Estimate", "Event", "Frame", "Host", "Interrupted", "JobAborted",
    "LintOptions", "Location", "MachineConfig", "MachineError", "MachineView", "MdiOutcome", "MdiSession", "Move",
    "MoveStream", "ParameterView", "PluginError", "Pose", "Program", "Run", "RunOptions", "RunResult",
    "RuntimeCode", "Severity", "Span", "Stmt", "SyntaxErrors", "Timing", "Toolpath", "Visitor", "lint_paths",
    "load_config", "move_length", "move_points", "parse_file", "parse_text", "plot_toolpath",
    "read_statements", "record_job", "result_of", "run_file", "run_string", "walk",
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
