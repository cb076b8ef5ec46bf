"""A G-code sender's live preview with a stop button.

    python examples/embedding/live_preview.py [JOB.nc]

The job runs in a worker thread as a ``MoveStream`` (bounded memory whatever its length); the
preview consumes moves as they come, and the "stop button" (here a timer on another thread, in a
GUI the button's handler) calls ``Run.cancel()``. The preview then shows how far the job got.
"""
from __future__ import annotations

import sys
import threading
from pathlib import Path

from edingcnc_lang import Run, RunOptions

HERE = Path(__file__).resolve().parent


def preview(job: Path, stop_after_moves: int | None = None) -> tuple[int, float, bool]:
    """Moves seen, XY path length drawn, and whether the stop button ended the run."""
    run = Run(RunOptions(plan=False))
    pressed = threading.Event()
    seen = 0
    drawn = 0.0
    with run.moves(job, buffer=256) as stream:
        for move in stream:
            seen += 1
            drawn += ((move.end[0] - move.start[0]) ** 2 + (move.end[1] - move.start[1]) ** 2) ** 0.5
            if stop_after_moves is not None and seen == stop_after_moves and not pressed.is_set():
                pressed.set()
                button = threading.Thread(target=run.cancel)  # the UI thread presses "stop"
                button.start()
                button.join()
    return seen, drawn, pressed.is_set()


def main(argv: list[str]) -> int:
    job = Path(argv[0]) if argv else HERE.parent / "pocket.nc"
    seen, drawn, stopped = preview(job, stop_after_moves=int(argv[1]) if len(argv) > 1 else None)
    print(f"{job.name}: {seen} moves previewed, {drawn:.1f} mm in XY" + (" (stopped)" if stopped else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
