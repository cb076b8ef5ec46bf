"""``ecnc lsp`` answering an editor, on a 30,000-line macro.cnc and a job beside it.

Drives the server over stdio with the test suite's JSON-RPC client, as an editor does, and
prints the wall time of each kind of request next to ``ecnc lint`` of the same file: start-up
to the initialize answer, diagnostics after opening the macro file and after an edit (the
0.3 s debounce included), hover, go to definition, completion and references from the job,
and formatting the macro file.  Medians of ``--repeat`` runs; the macro code is
bench_lint.py's (fixed seed).

    python benchmarks/bench_lsp.py [--lines N] [--repeat N]
"""
from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from bench_lint import generate
from bench_run import ECNC, measure

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from tests.lsp.client import LspClient, at  # noqa: E402  (after the path is set)


def timed(action: Callable[[], Any], repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        action()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lines", type=int, default=30_000)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    rows: list[tuple[str, float]] = []
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        macro = generate(folder, args.lines)
        job = folder / "job.nc"
        job.write_text("G0 X0 Y0\nGoSub user_macro_7\nGoSub \nM30\n", encoding="utf-8")

        def start() -> None:
            client = LspClient()
            client.initialize(folder)
            client.close()

        rows.append(("start-up to initialize answer", timed(start, args.repeat)))
        rows.append(("reference: ecnc lint of the macro.cnc (process start included)",
                     statistics.median(measure([*ECNC, "lint", str(macro)])[0] for _ in range(args.repeat))))
        client = LspClient()
        client.initialize(folder)
        text = macro.read_text(encoding="utf-8")
        version = [1]

        def open_macro() -> None:  # a new text each time: nothing is parsed yet
            version[0] += 1
            uri = client.open(macro, text + f"; opened {version[0]}\n")
            client.diagnostics(uri)
            client.notify("textDocument/didClose", {"textDocument": {"uri": uri}})
            client.diagnostics(uri)  # the close clears them

        rows.append((f"diagnostics after opening a {args.lines}-line macro.cnc", timed(open_macro, args.repeat)))
        uri = client.open(macro, text)
        client.diagnostics(uri)

        def edit() -> None:
            version[0] += 1
            client.change(uri, text + f"#{100 + version[0] % 50} = 1\n", version[0])
            client.diagnostics(uri)

        rows.append(("diagnostics after an edit (0.3 s debounce included)", timed(edit, args.repeat)))
        job_uri = client.open(job)
        client.diagnostics(job_uri)
        for label, method, line, col in (("hover on a GoSub", "textDocument/hover", 1, 8),
                                         ("go to definition", "textDocument/definition", 1, 8),
                                         ("completion after GoSub", "textDocument/completion", 2, 6)):
            rows.append((label, timed(lambda: client.request(method, at(job_uri, line, col)), args.repeat)))
        rows.append(("references of a sub (whole folder)", timed(lambda: client.request(
            "textDocument/references", {**at(job_uri, 1, 8), "context": {"includeDeclaration": True}}), args.repeat)))
        formatting = {"textDocument": {"uri": uri}, "options": {"tabSize": 4, "insertSpaces": True}}
        rows.append((f"formatting the {args.lines}-line macro.cnc",
                     timed(lambda: client.request("textDocument/formatting", formatting), args.repeat)))
        client.close()
    width = max(len(label) for label, _ in rows)
    for label, seconds in rows:
        print(f"{label:<{width}}  {seconds * 1000:8.1f} ms")


if __name__ == "__main__":
    main()
