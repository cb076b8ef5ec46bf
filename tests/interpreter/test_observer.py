"""The observer seam (interpreter/observe.py): every statement, branch and sub call is seen, in order."""
from __future__ import annotations

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.machine.observe import Observer


class Recorder(Observer):
    def __init__(self) -> None:
        self.seen: list[tuple] = []

    def statement(self, machine, stmt):
        self.seen.append(("stmt", machine.path, machine.line, type(stmt).__name__))

    def branch(self, machine, stmt, taken):
        self.seen.append(("branch", stmt.span.line, taken))

    def call(self, machine, frame, sub):
        self.seen.append(("call", sub.name, frame.line, len(machine.stack)))

    def ret(self, machine, frame):
        self.seen.append(("ret", frame.name))


JOB = "G1 X1 F100\nG1 X2\n#1 = 2\nIf [#1 == 2]\n  GoSub probe\nElse\n  G0 X0\nEndif\nM30\nSub probe\n  #2 = 0\n  While [#2 < 2]\n    #2 = [#2 + 1]\n  EndWhile\nEndSub\n"


def test_every_statement_branch_and_call_in_order() -> None:
    rec = Recorder()
    run_string(JOB, RunOptions(observer=rec))
    job = [e for e in rec.seen if e[1] in ("<string>", "probe") or e[0] == "branch"]
    assert job == [
        ("stmt", "<string>", 1, "Block"), ("stmt", "<string>", 2, "Block"),
        ("stmt", "<string>", 3, "Block"), ("stmt", "<string>", 4, "If"), ("branch", 4, True),
        ("stmt", "<string>", 5, "GoSub"), ("call", "probe", 5, 1),
        ("stmt", "<string>", 11, "Block"), ("stmt", "<string>", 12, "While"),
        ("branch", 12, True), ("stmt", "<string>", 13, "Block"),
        ("branch", 12, True), ("stmt", "<string>", 13, "Block"),
        ("branch", 12, False), ("ret", "probe"),
        ("stmt", "<string>", 9, "Block"),
    ]


def test_plain_chunks_of_a_file_reach_the_observer_line_by_line(tmp_path) -> None:
    from edingcnc_lang import run_file
    job = tmp_path / "job.nc"
    job.write_text("".join(f"G1 X{i} F100\n" for i in range(1, 2001)) + "M30\n")
    rec = Recorder()
    result = run_file(job, RunOptions(observer=rec))
    lines = [e[2] for e in rec.seen if e[0] == "stmt" and e[1] == str(job)]
    assert lines == list(range(1, 2002))
    assert result.moves == 2000


def test_an_observer_can_keep_the_bulk_path(tmp_path) -> None:
    from edingcnc_lang import run_file

    class Bulk(Recorder):
        def line_by_line(self, machine, run):
            return False

    job = tmp_path / "job.nc"
    job.write_text("".join(f"G1 X{i} F100\n" for i in range(1, 2001)) + "M30\n")
    rec = Bulk()
    result = run_file(job, RunOptions(observer=rec))
    assert [e for e in rec.seen if e[1] == str(job)] == [("stmt", str(job), 2001, "PlainBlock")]
    assert result.moves == 2000
