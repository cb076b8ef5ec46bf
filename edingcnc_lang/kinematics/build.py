"""Compile a C kinematics plug-in into a shared library that ``CompiledKinematics`` can load."""
from __future__ import annotations

import subprocess
from pathlib import Path

from edingcnc_lang.errors import PluginError
from edingcnc_lang.kinematics.shipped import header_dir


def build_plugin(source: Path, output: Path | None = None, cc: str = "cc", check_exports: bool = True) -> Path:
    """Run ``cc -shared -fPIC -O2 -I<header dir> SOURCE -o OUTPUT -lm``; OUTPUT defaults to SOURCE.so.

    The library is then checked for every required export, so a missing function fails the build
    (``check_exports=False`` builds a deliberately incomplete library, for tests).
    """
    source = Path(source)
    target = Path(output) if output is not None else source.with_suffix(".so")
    if not source.is_file():
        raise PluginError(f"kinematics source {source} does not exist")
    with header_dir() as include:
        command = [cc, "-shared", "-fPIC", "-O2", f"-I{include}", str(source), "-o", str(target), "-lm"]
        try:
            result = subprocess.run(command, capture_output=True, text=True, check=False)
        except OSError as err:
            raise PluginError(f"cannot run the C compiler {cc!r}: {err.strerror or err}") from None
    if result.returncode != 0:
        raise PluginError(f"compiling {source} failed (exit {result.returncode}):\n"
                          f"{(result.stderr or result.stdout).strip()}")
    from edingcnc_lang.kinematics.ctypes_plugin import missing_exports

    missing = missing_exports(target) if check_exports else []
    if missing:
        raise PluginError(f"{target} was built but does not export {', '.join(missing)}: a kinematics plug-in "
                          "must define every function of kinematics.h (see docs/kinematics.md)")
    return target
