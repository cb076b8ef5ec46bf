"""Compile a C kinematics plug-in into a shared library that ``CompiledKinematics`` can load."""
from __future__ import annotations

import contextlib
import os
import subprocess
import tempfile
from pathlib import Path

from edingcnc_lang.errors import PluginError
from edingcnc_lang.outputs import umask
from edingcnc_lang.kinematics.shipped import header_dir


def build_plugin(source: Path, output: Path | None = None, cc: str = "cc", check_exports: bool = True) -> Path:
    """Run ``cc -shared -fPIC -O2 -I<header dir> SOURCE -o OUTPUT -lm``; OUTPUT defaults to SOURCE.so.

    The library is then checked for every required export, so a missing function fails the build
    (``check_exports=False`` builds a deliberately incomplete library, for tests).  The compiler
    writes a temporary file beside OUTPUT, which replaces OUTPUT only once it is built and checked:
    a failed build leaves the previous library as it was.  A name starting with ``-`` or ``@`` is
    refused, and the compiler is given absolute paths, so no file name reaches it as an option or a
    response file (GCC takes no ``--`` before its inputs).
    """
    source = Path(source)
    target = Path(output) if output is not None else source.with_suffix(".so")
    for what, path in (("source", source), ("output", target)):
        if path.name.startswith(("-", "@")):
            raise PluginError(f"kinematics {what} {path}: a file name starting with '-' or '@' would reach the "
                              "compiler as an option; rename the file")
    if not source.is_file():
        raise PluginError(f"kinematics source {source} does not exist")
    folder = os.path.dirname(os.path.abspath(target))
    try:
        fd, temporary = tempfile.mkstemp(prefix=f".{target.stem}.", suffix=target.suffix or ".so", dir=folder)
    except OSError as err:
        raise PluginError(f"cannot write {target}: {err.strerror or err}") from None
    os.close(fd)
    try:
        _compile(source, Path(temporary), cc, check_exports)
        os.chmod(temporary, 0o777 & ~umask())
        os.replace(temporary, target)
    except OSError as err:
        raise PluginError(f"cannot write {target}: {err.strerror or err}") from None
    finally:
        with contextlib.suppress(OSError):
            os.unlink(temporary)
    return target


def _compile(source: Path, library: Path, cc: str, check_exports: bool) -> None:
    """``library`` compiled from ``source`` and checked for every export (PluginError otherwise)."""
    with header_dir() as include:
        command = [cc, "-shared", "-fPIC", "-O2", f"-I{include}", os.path.abspath(source),
                   "-o", os.path.abspath(library), "-lm"]
        try:
            result = subprocess.run(command, capture_output=True, text=True, check=False)
        except OSError as err:
            raise PluginError(f"cannot run the C compiler {cc!r}: {err.strerror or err}") from None
    if result.returncode != 0:
        raise PluginError(f"compiling {source} failed (exit {result.returncode}):\n"
                          f"{(result.stderr or result.stdout).strip()}")
    from edingcnc_lang.kinematics.ctypes_plugin import missing_exports

    missing = missing_exports(library) if check_exports else []
    if missing:
        raise PluginError(f"{source} was built but does not export {', '.join(missing)}: a kinematics plug-in "
                          "must define every function of kinematics.h (see docs/kinematics.md)")

