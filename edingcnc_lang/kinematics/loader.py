"""Find and construct the kinematics named by ``[KINEMATICS] kinematicsDLLName``.

Resolution order (docs/kinematics.md): a file (the name as a path, else in each search folder:
``.py`` source, ``.so`` library, or the ``.so`` sibling of a Windows ``.dll`` name), then a name
registered under the entry-point group ``edingcnc_lang.kinematics``, then the built-in table
(the same names, for source checkouts without installed metadata).  Every failure is a
``PluginError`` naming the plug-in.  ``importlib.metadata`` and ctypes are imported only when a
lookup needs them (reading every installed package's entry points is slow on a big site-packages).
"""
from __future__ import annotations

import contextlib
import importlib
import importlib.util
import inspect
import sys
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING, Any

from edingcnc_lang.errors import EcncError, Location, PluginError
from edingcnc_lang.kinematics.base import PLUGIN_FAILURES, Kinematics, KinematicsPlugin, guard_python_plugin
from edingcnc_lang.kinematics.shipped import import_shipped

if TYPE_CHECKING:
    from importlib import metadata

ENTRY_POINT_GROUP = "edingcnc_lang.kinematics"

# name -> (module, class); must match pyproject's entry points (a test checks this).
BUILTIN: dict[str, tuple[str, str]] = {
    "trivial": ("edingcnc_lang.kinematics.builtin", "TrivialKinematics"),
    "corexy": ("edingcnc_lang.kinematics.builtin", "CoreXYKinematics"),
    "rotatekins": ("edingcnc_lang.kins.rotatekins", "RotateKins"),
    "deltakins": ("edingcnc_lang.kins.deltakins", "DeltaKins"),
}
NAME_SUFFIXES = (".dll", ".so", ".py")
REQUIRED_METHODS = ("kin_type", "version", "inverse", "forward", "control", "inverse_many", "user_output")


def _plugin_name(name_or_path: str) -> str:
    """The lookup name: file name without folder and without a .dll/.so/.py suffix, lower case."""
    path = Path(name_or_path)
    stem = path.stem if path.suffix.lower() in NAME_SUFFIXES else path.name
    return stem.lower()


def _file_candidates(path: Path) -> list[Path]:
    """Files that may implement ``path``: itself, or for a .dll/bare name its .so and .py siblings."""
    suffix = path.suffix.lower()
    if suffix in (".py", ".so"):
        return [path]
    base = path.with_suffix("") if suffix == ".dll" else path
    return [base.with_name(base.name + ".so"), base.with_name(base.name + ".py")]


def is_compiled_plugin(name_or_path: str, search_dirs: Sequence[Path]) -> bool:
    """Whether the plug-in resolves to a shared library (the workbench calls those out of process)."""
    found = find_plugin_file(name_or_path, search_dirs)
    return found is not None and found.suffix.lower() == ".so"


def find_plugin_file(name_or_path: str, search_dirs: Sequence[Path]) -> Path | None:
    """A typed path (folder parts or a .py/.so suffix) is tried as given; every name in the search folders."""
    path = Path(name_or_path)
    typed = path.is_absolute() or len(path.parts) > 1 or path.suffix.lower() in (".py", ".so")
    bases = [path] if typed else []
    if not path.is_absolute():
        bases += [Path(d) / path for d in search_dirs]
    for base in bases:
        for candidate in _file_candidates(base):
            found = _existing(candidate)
            if found is not None:
                return found
    return None


def _existing(candidate: Path) -> Path | None:
    """The file itself, else one in its folder whose name differs only in case (names come from Windows)."""
    if candidate.is_file():
        return candidate
    if not candidate.parent.is_dir():
        return None
    wanted = candidate.name.lower()
    return next((f for f in sorted(candidate.parent.iterdir()) if f.name.lower() == wanted and f.is_file()), None)


def _import_file(path: Path) -> ModuleType:
    module_name = f"edingcnc_lang_user_kins_{abs(hash(path.resolve()))}"
    spec = importlib.util.spec_from_file_location(module_name, path)
    if spec is None or spec.loader is None:
        raise PluginError(f"kinematics plug-in {path}: not a Python module")
    module = importlib.util.module_from_spec(spec)
    try:
        with contextlib.redirect_stdout(sys.stderr):  # its print() never lands in a --json document
            spec.loader.exec_module(module)
    except PLUGIN_FAILURES as err:  # the user's module may fail in any way
        detail = err.msg if isinstance(err, SyntaxError) else str(err)
        raise PluginError(f"kinematics plug-in {path}: importing it failed: {type(err).__name__}: {detail}",
                          _failure_location(err, path)) from None
    return module


def _failure_location(err: BaseException, path: Path) -> Location | None:
    """Where in the plug-in's own file its import failed, so the author is sent to the line."""
    if isinstance(err, SyntaxError) and err.lineno:
        return Location(str(path), err.lineno, err.offset or 0)
    import traceback  # only when a plug-in fails (start-up time)

    own = path.resolve()
    lines = [line for frame, line in traceback.walk_tb(err.__traceback__)
             if Path(frame.f_code.co_filename).resolve() == own]
    return Location(str(path), lines[-1]) if lines else None


def _plugin_class(module: ModuleType, label: str) -> Callable[..., Any]:
    """``KINEMATICS = ClassName`` if the module says so, else its single KinematicsPlugin subclass."""
    chosen = getattr(module, "KINEMATICS", None)
    if chosen is not None:
        return chosen
    classes = [cls for _, cls in inspect.getmembers(module, inspect.isclass)
               if issubclass(cls, KinematicsPlugin) and cls.__module__ == module.__name__]
    if len(classes) != 1:
        found = ", ".join(c.__name__ for c in classes) or "none"
        raise PluginError(f"kinematics plug-in {label}: expected one KinematicsPlugin subclass or a "
                          f"module-level KINEMATICS = ClassName (found: {found})")
    return classes[0]


def _construct(factory: Callable[..., Any], label: str, settings: Mapping[str, str]) -> Kinematics:
    try:
        kins = factory(settings)
    except PLUGIN_FAILURES as err:  # a plug-in's constructor may fail in any way
        reason = err.message if isinstance(err, EcncError) else f"{type(err).__name__}: {err}"
        raise PluginError(f"kinematics plug-in {label}: constructing it failed: {reason}") from None
    missing = [m for m in REQUIRED_METHODS if not callable(getattr(kins, m, None))]
    if missing:
        raise PluginError(f"kinematics plug-in {label}: it lacks {', '.join(missing)}")
    if not getattr(kins, "name", ""):
        kins.name = label
    guard_python_plugin(kins, label)
    return kins


def _load_file(path: Path, settings: Mapping[str, str]) -> Kinematics:
    if path.suffix.lower() == ".so":
        from edingcnc_lang.kinematics.ctypes_plugin import CompiledKinematics

        return CompiledKinematics(path, settings)
    return _construct(_plugin_class(_import_file(path), str(path)), str(path), settings)


def _entry_points() -> dict[str, metadata.EntryPoint]:
    from importlib import metadata

    return {ep.name.lower(): ep for ep in metadata.entry_points(group=ENTRY_POINT_GROUP)}


def _import_builtin(name: str) -> Callable[..., Any]:
    module, cls = BUILTIN[name]
    if module.startswith("edingcnc_lang.kins."):
        return getattr(import_shipped(module.rsplit(".", 1)[1]), cls)
    return getattr(importlib.import_module(module), cls)


def _registered_factory(name: str) -> Callable[..., Any] | None:
    entry = _entry_points().get(name)
    if entry is not None:
        try:
            return entry.load()
        except PLUGIN_FAILURES as err:  # a third-party entry point may fail in any way
            raise PluginError(f"kinematics plug-in {name!r}: loading entry point {entry.value} failed: "
                              f"{type(err).__name__}: {err}") from None
    return _import_builtin(name) if name in BUILTIN else None


def registered_names() -> list[str]:
    """Every name ``load_kinematics`` resolves without a file, sorted."""
    return sorted({*_entry_points(), *BUILTIN})


def load_kinematics(name_or_path: str, settings: Mapping[str, str],
                    search_dirs: Sequence[Path] = ()) -> Kinematics:
    """Construct the kinematics ``name_or_path`` (see the module docstring for the search order)."""
    path = find_plugin_file(name_or_path, search_dirs)
    if path is not None:
        return _load_file(path, settings)
    name = _plugin_name(name_or_path)
    factory = _registered_factory(name)
    if factory is not None:
        return _construct(factory, name, settings)
    files = (f"no .so or .py file of that name is in {', '.join(str(d) for d in search_dirs)}" if search_dirs
             else "it is not the path of a .py or .so file")
    sources = [d / f"{name}.c" for d in search_dirs if (d / f"{name}.c").is_file()]
    hint = f"; {sources[0]} is there: build it first with `ecnc kins build {sources[0]}`" if sources else ""
    raise PluginError(f"kinematics plug-in {name_or_path!r} not found: it is not a registered name "
                      f"({', '.join(registered_names())}) and {files}{hint}")


def available_kinematics() -> list[tuple[str, int, str]]:
    """(name, type, version) of every registered kinematics, constructed with default settings.

    One broken third-party plug-in must not hide the others: it is listed as type 0 with the
    reason in place of the version.
    """
    result = []
    for name in registered_names():
        try:
            kins = load_kinematics(name, {})
        except PluginError as err:
            result.append((name, 0, f"failed to load: {err.message}"))
        else:
            result.append((name, kins.kin_type(), kins.version()))
    return result
