"""``ecnc vars``: the table, --json in the documented shape, --csv, --markdown, --unnamed, --sub,
errors as FILE:LINE:COL with the contract's exit codes."""
from __future__ import annotations

import csv
import io
import json
import time
from pathlib import Path

from edingcnc_lang.cli.vars_cmd import FORMATS
from edingcnc_lang.lint.variable_map import variable_map
from edingcnc_lang.varmap import render
from tests.cli_runner import invoke

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "variables" / "macro.cnc"


def test_formats_in_step_with_the_renderers() -> None:
    assert set(FORMATS) == set(render.FORMATS)


def test_json_shape() -> None:
    result = invoke("vars", EXAMPLE, "--json")
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert set(doc) == {"variables", "findings"}
    by_number = {v["number"]: v for v in doc["variables"]}
    diameter = by_number[1552]
    assert {k: diameter[k] for k in ("name", "source", "kind")} == {
        "name": "thread_major_diameter", "source": "annotation", "kind": "user"}
    assert diameter["writers"] == [{"file": str(EXAMPLE), "line": 12, "sub": "user_1"}]
    assert {r["line"] for r in diameter["readers"]} == {16, 17, 21, 23}
    assert diameter["named_at"] == {"file": str(EXAMPLE), "line": 8}
    assert by_number[1554]["name"] == "thread_pitch"  # the sidecar wins over the dlgmsg label "pitch"
    assert by_number[1554]["named_at"]["file"].endswith("variables.toml") and by_number[5071]["named_at"] is None
    assert by_number[4200]["kind"] == "persistent" and by_number[4200]["writers"] == []
    assert (by_number[5071]["source"], by_number[5071]["kind"]) == ("manual", "system read-only")
    assert [v["number"] for v in doc["variables"]] == sorted(by_number)


def test_table_csv_markdown() -> None:
    table = invoke("vars", EXAMPLE).stdout.splitlines()
    assert table[0].split() == ["number", "name", "source", "kind", "written", "in", "read", "in"]
    assert any(line.startswith("#1556   thread depth") and "user_1:17" in line for line in table)
    rows = list(csv.DictReader(io.StringIO(invoke("vars", EXAMPLE, "--csv").stdout)))
    row = next(r for r in rows if r["number"] == "1553")
    assert (row["name"], row["description"]) == ("thread_minor_diameter", "computed from the pitch")
    assert row["writers"] == f"{EXAMPLE}:16 (user_1)"
    markdown = invoke("vars", EXAMPLE, "--markdown").stdout.splitlines()
    assert markdown[0] == "| number | name | source | kind | written in | read in |"
    assert "| #5020 | x1 | comment | macro scratch | user_2:28 | user_2:31 |" in markdown


def test_unnamed_and_sub(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("#100 = 1 ; counter\n#101 = 2\nG0 X[#101]\nGoSub probe\nM30\nSub probe\n  #102 = #100\nEndSub\n",
                   encoding="utf-8")
    unnamed = json.loads(invoke("vars", job, "--json", "--unnamed").stdout)["variables"]
    assert [v["number"] for v in unnamed] == [101, 102]
    probe = json.loads(invoke("vars", job, "--json", "--sub", "PROBE").stdout)["variables"]
    assert [v["number"] for v in probe] == [100, 102]


def test_findings_are_included(tmp_path: Path) -> None:
    job = tmp_path / "job.nc"
    job.write_text("#5001 = 1\nG0 X[#5231]\n", encoding="utf-8")
    findings = json.loads(invoke("vars", job, "--json").stdout)["findings"]
    assert [(f["code"], f["line"]) for f in findings] == [("V301", 1), ("V307", 2)]


def test_bad_annotation_is_an_error_with_its_position(tmp_path: Path) -> None:
    macro = tmp_path / "macro.cnc"
    macro.write_text(";@unit mm\n;@var #27 1bad\n", encoding="utf-8")
    result = invoke("vars", macro)
    assert result.exit_code == 65
    assert f"{macro}:2:11: error: '1bad' is not a name" in result.stderr
    (tmp_path / "variables.toml").write_text("[27\n", encoding="utf-8")
    result = invoke("vars", macro)
    assert result.exit_code == 65 and f"{tmp_path / 'variables.toml'}:1:4: error:" in result.stderr


def test_usage_errors() -> None:
    assert invoke("vars").exit_code == 2
    missing = invoke("vars", "no/such/file.cnc")
    assert missing.exit_code == 2 and "Traceback" not in missing.output


def test_a_long_macro_maps_in_under_a_second(tmp_path: Path) -> None:
    """2,600 lines of subs with dialogs, loops and comments (the size of the largest real macro)."""
    lines = [";@unit mm"]
    for k in range(100):
        base = 100 + 10 * k
        lines += [f"Sub user_{k}", f'    dlgmsg "Cycle {k}" "Z1" {base} "Z2" {base + 1} "pitch" {base + 2}',
                  "    If [#5398 == -1]", "        M30", "    EndIf",
                  f"    #{base + 3} = 0 ;; pass counter", f"    While [#{base + 3} < 10]",
                  f"        #{base + 3} = [#{base + 3} + 1]", f"        G0 X[#{base} - #{base + 3}] Z[#{base + 1}]",
                  f"        G33 Z[#{base + 1}] K[#{base + 2}]", "        G0 X[#5071 + 1]", "    EndWhile",
                  *[f"    G1 X{i} Z-{i} F100 ; pass {i}" for i in range(12)], "EndSub", ""]
    macro = tmp_path / "macro.cnc"
    macro.write_text("\n".join(lines), encoding="utf-8")
    assert len(lines) > 2600
    start = time.perf_counter()
    varmap = variable_map([macro])
    elapsed = time.perf_counter() - start
    assert len(varmap.variables) == 402  # 400 of the subs, #5071, #5398
    assert elapsed < 1.0 * 3  # 0.3 s on the reference machine; slack for a loaded CI runner


def test_lint_reports_a_bad_sidecar_once_at_its_line(tmp_path: Path) -> None:
    from edingcnc_lang.lint import lint_paths

    (tmp_path / "macro.cnc").write_text(";@unit mm\n", encoding="utf-8")
    (tmp_path / "user_macro.cnc").write_text(";@unit mm\n", encoding="utf-8")
    (tmp_path / "variables.toml").write_text('[27]\nname = "ok"\n\n[28]\nname = "not ok"\n', encoding="utf-8")
    found = [(Path(d.path).name, d.line, d.col, d.code) for d in lint_paths([tmp_path])]
    assert found == [("variables.toml", 5, 9, "V308")]
