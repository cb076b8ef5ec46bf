"""``ecnc lint`` on 30,000 lines of generated macro code (target: at most 0.5 s, process start included).

The code is generated deterministically (fixed seed) in the style of real
macro files: subs with If/While blocks, assignments, expressions, messages,
dialogs, guarded probing, G-code moves and comments.  Prints the median wall
and CPU time of the command (run several times, alternately on the compiled
core and on the pure-Python one, ``ECNC_PURE_PYTHON=1``), the start-up part of
it (``ecnc lint`` of a one-line file), and, measured in this process, how the
rest splits into parsing and the rules.

    python benchmarks/bench_lint.py [--lines N] [--repeat N]
    python benchmarks/bench_lint.py --before /tmp/old   # side by side with an older checkout (its
                                                        # extensions built in place), run alternately
    python benchmarks/bench_lint.py --files 400 --jobs 2   # many files: -j 1 beside -j N
    python benchmarks/bench_lint.py --corpus DIR    # real macro files instead (target: at most 0.4 s)

``--corpus DIR`` (or the environment variable ``ECNC_BENCH_CORPUS``) reads every ``*.cnc`` file under
DIR (``.git`` folders left out, sorted by path) and concatenates them, over and over, up to
``--lines`` lines: real users' files are not copied into the project, so the benchmark reads them
from wherever they were fetched (issue 42 used the public macro files of kgerrits/EdingCNC_turning_macros,
Phobia943/CNC_Macro_for_Sorotec, Schallbert/macro_edingCNC_sorotec, Miniclubbin/Eding_CNC_Macros_English,
GameOEver/EdingCNC_Macro and plylab-nl/JKR2513, cloned into one folder).  It also prints how many
lines the Lark grammar read (the rest took the fast reader).
"""
from __future__ import annotations

import argparse
import gc
import os
import random
import statistics
import tempfile
import time
from pathlib import Path

from bench_run import ECNC, PURE, measure, median_runs

from edingcnc_lang.lint.model import load_source
from edingcnc_lang.lint.project import Project
from edingcnc_lang.lint.registry import RULES

SEED = 20240501


def _sub(rng: random.Random, number: int) -> list[str]:
    """One sub of 20..40 lines; variables #1000+ are assigned before they are read."""
    base = 1000 + 3 * (number % 900)
    a, b, c = base, base + 1, base + 2
    lines = [f"Sub user_macro_{number}", f"    ; generated sub {number}: moves, maths and checks",
             f"    #{a} = {rng.randint(1, 50)}", f"    #{b} = [#{a} * {rng.uniform(0.5, 2):.3f} + #4000]",
             f"    #{c} = 0"]
    for _ in range(rng.randint(3, 6)):
        kind = rng.randrange(6)
        if kind == 0:
            lines += [f"    While [#{c} < #{a}]",
                      f"        G1 X[#{c} * 2.5] Y[SIN[#{c} * 10] * #{b}] F[#4001 + 100]",
                      f"        #{c} = [#{c} + 1]", "    EndWhile"]
        elif kind == 1:
            lines += [f"    If [[#{a} > {rng.randint(0, 40)}] and [#{b} <> 0]]",
                      f"        msg \"value \"#{a}\" ok\"", "    Else",
                      f"        warnmsg \"value \"#{b}\" is low\"", "    EndIf"]
        elif kind == 2:
            lines += ["    If [[#5380 == 0] and [#5397 == 0]]",
                      f"        G38.2 G91 Z-[#4013 + {rng.randint(1, 9)}] F[#4001]", "        G90",
                      "        If [#5067 <> 1]", "            errmsg \"probe did not touch\"",
                      "        EndIf", "    EndIf"]
        elif kind == 3:
            x, y = rng.uniform(-100, 100), rng.uniform(-100, 100)
            lines += [f"    G0 X{x:.3f} Y{y:.3f}", f"    G1 Z-{rng.uniform(0, 5):.3f} F{rng.randint(100, 900)}",
                      f"    G2 X{x + 10:.3f} Y{y:.3f} I5 J0", "    G0 Z5"]
        elif kind == 4:
            lines += [f"    dlgmsg \"Setup {number}\" \"Depth\" {a} \"Width\" {b}",
                      "    If [#5398 <> 1]", "        msg \"cancelled\"", "    EndIf"]
        else:
            lines += [f"    #{b} = [ABS[#{a} - #{b}] / 2 + ROUND[#{a} MOD 7]]   ; tidy up",
                      "    G53 G0 Z[#4012] ; park", f"    M3 S[#{a} * 100]", "    M5"]
    return [*lines, "EndSub", ""]


def generate(folder: Path, total: int) -> Path:
    rng = random.Random(SEED)
    lines = [";@unit mm", "; generated for bench_lint.py", ""]
    number = 0
    while True:
        sub = _sub(rng, number)
        if len(lines) + len(sub) > total:
            break
        lines += sub
        number += 1
    lines += ["; end of the generated subs"] * (total - len(lines))
    path = folder / "macro.cnc"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def from_corpus(folder: Path, corpus: Path, total: int) -> Path:
    """The ``*.cnc`` files under ``corpus`` concatenated (repeated as needed) into ``total`` lines."""
    from edingcnc_lang.syntax.source import iter_file_lines

    files = sorted(p for p in corpus.rglob("*") if p.suffix.lower() == ".cnc" and ".git" not in p.parts
                   and p.is_file())
    if not files:
        raise SystemExit(f"{corpus}: no .cnc files")
    text = [line for path in files for line in iter_file_lines(path)]
    lines = (text * (total // len(text) + 1))[:total]
    path = folder / "macro.cnc"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def grammar_lines(path: Path) -> int:
    """How many lines (and command arguments) of ``path`` the Lark grammar reads: the fast reader's misses."""
    from edingcnc_lang.syntax import line_parser

    count = 0
    grammar = line_parser.parse_line_grammar

    def counted(*args: object) -> object:
        nonlocal count
        count += 1
        return grammar(*args)  # type: ignore[arg-type]

    line_parser.parse_line_grammar = counted  # type: ignore[assignment]
    try:
        load_source(path, is_macro=True)
    finally:
        line_parser.parse_line_grammar = grammar
    return count


def _median_wall(cmd: list[str], repeat: int) -> float:
    return statistics.median(measure(cmd)[0] for _ in range(repeat))


def _split(path: Path, repeat: int) -> tuple[float, float, float]:
    """Best-of-``repeat`` seconds of parsing, of the one walk that gathers the facts, and of running every
    rule, with the GC paused as the CLI does."""
    parse, walk, rules = [], [], []
    gc.disable()
    for _ in range(repeat):
        start = time.perf_counter()
        source = load_source(path, is_macro=True)
        parse.append(time.perf_counter() - start)
        start = time.perf_counter()
        project = Project([source], {source.path: []})
        project.facts(source)
        walk.append(time.perf_counter() - start)
        start = time.perf_counter()
        for rule in RULES:
            list(rule.check(source, project))
        rules.append(time.perf_counter() - start)
    gc.enable()
    return min(parse), min(walk), min(rules)


def bench_many(files: int, lines: int, jobs: int, repeat: int) -> None:
    """``ecnc lint -j 1`` and ``-j N`` on a folder of ``files`` generated files of ``lines`` lines each."""
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp) / "jobs"
        folder.mkdir()
        text = generate(Path(tmp), lines).read_text(encoding="utf-8")
        for index in range(files):
            (folder / f"job{index:04d}.nc").write_text(text, encoding="utf-8")
        one = _median_wall([*ECNC, "lint", "-j", "1", str(folder)], repeat)
        many = _median_wall([*ECNC, "lint", "-j", str(jobs), str(folder)], repeat)
    print(f"{files} files of {lines} lines: -j 1 {one:.2f} s, -j {jobs} {many:.2f} s ({one / many:.2f}x)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lines", type=int, default=30_000)
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--files", type=int, help="Many files instead: this many, of --lines lines each.")
    parser.add_argument("--jobs", type=int, default=2, help="With --files: the -j to compare with -j 1.")
    parser.add_argument("--before", type=Path, help="An older checkout to time alongside (PYTHONPATH).")
    parser.add_argument("--corpus", type=Path, default=os.environ.get("ECNC_BENCH_CORPUS") or None,
                        help="A folder of real macro files to concatenate instead of the generated code.")
    args = parser.parse_args()
    if args.files:
        bench_many(args.files, args.lines, args.jobs, args.repeat)
        return
    with tempfile.TemporaryDirectory() as tmp:
        path = from_corpus(Path(tmp), args.corpus, args.lines) if args.corpus else generate(Path(tmp), args.lines)
        one = Path(tmp) / "alone" / "one.cnc"  # a folder of its own: no macro.cnc beside it to load
        one.parent.mkdir()
        one.write_text(";@unit mm\nG0 X1\n")
        lines = len(path.read_text(encoding="utf-8").splitlines())
        cmds = {"compiled": [*ECNC, "lint", str(path)], "python": [*ECNC, "lint", str(path)],
                "start-up": [*ECNC, "lint", str(one)], "start-up, python": [*ECNC, "lint", str(one)]}
        envs = {"python": PURE, "start-up, python": PURE}
        if args.before:  # the same commands on the older checkout, in the same rounds
            older = {"PYTHONPATH": str(args.before.resolve())}
            for name, cmd in list(cmds.items()):
                cmds[f"before: {name}"] = cmd
                envs[f"before: {name}"] = {**envs.get(name, {}), **older}
        runs = median_runs(cmds, args.repeat, envs)
        parse, walk, rules = _split(path, args.repeat)
        slow = grammar_lines(path)
    what = f"real files under {args.corpus}" if args.corpus else "generated"
    print(f"lines:                      {lines} {what}  (load average {' '.join(f'{x:.2f}' for x in os.getloadavg())})")
    print(f"  read by the grammar:      {slow} ({100 * slow / lines:.2f} %)")
    for name, (wall, cpu, _rss) in runs.items():
        what = "ecnc lint" if "start-up" not in name else "  start-up (one-line file)"
        core = "python core" if name.endswith("python") else "compiled core"
        before = "before: " if name.startswith("before") else ""
        print(f"{before}{what}, {core} (median of {args.repeat}): {wall:.3f} s wall, {cpu:.3f} s CPU")
    print(f"  parse (best, in process): {parse:.3f} s")
    print(f"  facts (best, in process): {walk:.3f} s")
    print(f"  rules (best, in process): {rules:.3f} s")
    wall, bound = runs["compiled"][0], 0.4 if args.corpus else 0.5
    print(f"target <= {bound} s: {'met' if wall <= bound else 'NOT met'} ({lines / wall:,.0f} lines/s)")


if __name__ == "__main__":
    main()
