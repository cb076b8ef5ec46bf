"""The picture files every drawing command writes (``ecnc plot``, ``ecnc kins plot``): which
extensions name a format, and the one error for a missing matplotlib.  No matplotlib import here,
so a command can check its output name before the slow part (running the job) starts."""
from __future__ import annotations

from pathlib import Path

from edingcnc_lang.errors import EXIT_USAGE, EcncError, require_extra

FORMATS = (".png", ".svg", ".pdf")


class PictureNameError(EcncError):
    """The output file's extension names no picture format we write: the user's mistake (exit 2)."""

    exit_code = EXIT_USAGE


def require_matplotlib() -> None:
    """Fail with how to install matplotlib (the ``plot`` extra), rather than an ImportError traceback."""
    require_extra("matplotlib", "plot", "drawing a picture")


def picture_format(out: Path) -> str:
    """``png``, ``svg`` or ``pdf``, as the file's extension names it; any other is told plainly."""
    suffix = out.suffix.lower()
    if suffix not in FORMATS:
        raise PictureNameError(f"cannot write {out}: the extension names the picture format, one of "
                               f"{', '.join(FORMATS)} (not {suffix or 'none'})")
    return suffix[1:]


def picture_target(out: Path) -> str:
    """What a drawing command checks once, before its work: matplotlib is there and ``out`` names a format."""
    require_matplotlib()
    return picture_format(out)
