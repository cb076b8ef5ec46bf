"""Which controller version a lint run describes: ``--target``, a config file, or the cnc.ini.

Some findings describe one version's behaviour (EdingCNC 5 refuses a macro file
without ``@unit``, G1290; 4.03 does not care), so the linter needs a target.
It is, first found wins: ``ecnc lint --target``, ``target`` under ``[tool.ecnc]``
in the nearest ``pyproject.toml`` or ``ecnc.toml`` above the first path, the
``[SYSTEM] version`` line of the ``--ini`` file or, as real 4.03 files have none, its
``lastKnownServerVersion = "CNC V4.03.50"`` (the version of the controller that last wrote it),
else the newest version.
"""
from __future__ import annotations

import os
import re
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from edingcnc_lang.codes import CODES
from edingcnc_lang.errors import EXIT_USAGE, EcncError, Location

if TYPE_CHECKING:  # the ini reader loads only when an ini names the version (start-up time)
    from edingcnc_lang.config.ini import IniValue

TARGETS = ("4.03", "5")
NEWEST = TARGETS[-1]
CONFIG_FILES = ("ecnc.toml", "pyproject.toml")
_VERSION = re.compile(r"^\s*(?:CNC\s*)?V?\s*(\d+)(?:\.(\d+))?", re.IGNORECASE)
VERSION_KEYS = ("version", "lastKnownServerVersion")  # keys naming the controller version ([SYSTEM] first)


class TargetError(EcncError):
    """A target that names no known controller version (a usage error)."""

    exit_code = EXIT_USAGE


def normalise(text: str, where: Location | None = None) -> str:
    """``"4.03"``, ``"V4.03.52"``, ``"CNC V4.03.50"``, ``"5"``, ``"5.2"`` -> one of TARGETS."""
    match = _VERSION.match(text)
    major = match.group(1) if match else ""
    if major == "4":
        return "4.03"
    if major == "5":
        return "5"
    raise TargetError(f"unknown controller version {text!r}: choose one of {', '.join(TARGETS)}", where)


def applies(code: str, target: str) -> bool:
    """Whether a finding of ``code`` describes the target's behaviour (most codes: every version)."""
    versions = CODES[code].versions
    return not versions or target in versions


def resolve(given: str | None, paths: Sequence[str | os.PathLike[str]], ini: str | None) -> str:
    """The target of a lint run (see the module's docstring for the order)."""
    if given:
        return normalise(given)
    configured = _from_config(paths)
    if configured:
        return configured
    if ini:
        version = ini_version(ini)
        if version is not None:
            return normalise(version.text, Location(os.fspath(ini), version.line))
    return NEWEST


def ini_version(path: str | os.PathLike[str]) -> IniValue | None:
    """The controller version a cnc.ini names (see VERSION_KEYS), wherever in the file the key is."""
    from edingcnc_lang.config.ini import read_ini

    ini = read_ini(path)
    sections = ["system", *(name for name in ini.sections if name != "system")]
    for key in VERSION_KEYS:
        for section in sections:
            value = ini.get(section, key)
            if value is not None and value.text.strip():
                return value
    return None


def _from_config(paths: Sequence[str | os.PathLike[str]]) -> str | None:
    if not paths:
        return None
    start = Path(paths[0]).resolve()
    for folder in (start if start.is_dir() else start.parent, *start.parents):
        for name in CONFIG_FILES:
            candidate = folder / name
            if candidate.is_file():
                section = _tool_section(candidate)
                if section is not None and "target" in section:
                    return normalise(str(section["target"]), Location(os.fspath(candidate)))
    return None


def _tool_section(path: Path) -> dict[str, object] | None:
    """The ``[tool.ecnc]`` table of a TOML file (None if absent); a broken file is a usage error."""
    if sys.version_info >= (3, 11):  # imported here: only a folder with a TOML file pays for it
        import tomllib
    else:  # Python 3.10: the same parser, as a package (a dependency there)
        import tomli as tomllib

    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as err:
        raise TargetError(f"cannot read the configuration: {err}", Location(os.fspath(path))) from None
    section = data.get("tool", {}).get("ecnc")
    return section if isinstance(section, dict) else None
