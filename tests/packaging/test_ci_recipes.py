"""The CI kit as a shop copies it: every ``ecnc`` command of docs/ci.md's recipes, the run steps of
action.yml and the hooks of .pre-commit-hooks.yaml, run with bash on an example project whose
folder name has a space, and their reports read back."""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import pytest

from tests.macro_tests.test_coverage_formats import parse_lcov

yaml = pytest.importorskip("yaml")
pytestmark = pytest.mark.slow  # the whole module: bash runs every recipe (pyproject's slow marker)

ROOT = Path(__file__).resolve().parents[2]
FENCE = re.compile(r"^```(\w*)\n(.*?)^```", re.MULTILINE | re.DOTALL)
COMMAND = re.compile(r"^\s*(?:-\s+|run:\s+)?(ecnc\s.*)$")


def recipes() -> dict[str, list[str]]:
    """docs/ci.md's fenced blocks under each ``##`` heading: the ``ecnc`` lines of each."""
    text = (ROOT / "docs" / "ci.md").read_text(encoding="utf-8")
    found: dict[str, list[str]] = {}
    for section in re.split(r"^## ", text, flags=re.MULTILINE)[1:]:
        title = section.splitlines()[0]
        for _lang, body in FENCE.findall(section):
            found.setdefault(title, []).extend(m[1] for line in body.splitlines() if (m := COMMAND.match(line)))
    return found


@pytest.fixture
def project(tmp_path: Path) -> Path:
    """A shop's repository: jobs, the stock macro.cnc and tests against it."""
    repo = tmp_path / "shop repo"
    shutil.copytree(ROOT / "examples", repo / "examples")
    shutil.copytree(ROOT / "stdlib", repo / "stdlib")
    shutil.copy(ROOT / "examples" / "pocket.nc", repo / "examples" / "pocket #1.nc")
    return repo


def bash(script: str, cwd: Path, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    path = os.pathsep.join([str(Path(sys.executable).parent), os.environ.get("PATH", "")])
    return subprocess.run(["bash", "-c", script], cwd=cwd, capture_output=True, text=True, timeout=300,
                          env={**os.environ, "PATH": path, **(env or {})})


def check_reports(folder: Path) -> set[str]:
    """Every report in ``folder`` parses as its format; returns their names."""
    seen = set()
    for path in folder.iterdir():
        if path.suffix == ".sarif":
            log = json.loads(path.read_text(encoding="utf-8"))
            assert log["version"] == "2.1.0" and log["runs"][0]["results"] == []
        elif path.name.endswith("junit.xml"):
            root = ET.parse(path).getroot()
            assert int(root.get("tests", 0)) >= 15 and root.get("failures") == root.get("errors") == "0"
        elif path.suffix == ".info":
            # the example tests run ecnc's packaged macro.cnc (outside the project: named by its full path)
            assert any(name.endswith("stdlib/macro.cnc") for name in parse_lcov(path.read_text(encoding="utf-8")))
        elif path.name.endswith("coverage.xml"):
            assert any(c.get("filename", "").endswith("stdlib/macro.cnc") for c in ET.parse(path).getroot().iter("class"))
        else:
            continue
        seen.add(path.name)
    return seen


def test_every_recipe_has_commands() -> None:
    found = recipes()
    assert {"GitHub Actions: the steps written out", "GitLab CI"} <= set(found)
    assert all(any(c.startswith("ecnc test") for c in found[t]) for t in ("GitHub Actions: the steps written out", "GitLab CI"))


@pytest.mark.parametrize("title", ["GitHub Actions: the steps written out", "GitLab CI"])
def test_a_recipes_commands_run_on_an_example_project(project: Path, title: str) -> None:
    for command in recipes()[title]:
        done = bash(command, project)
        assert done.returncode == 0, (command, done.stdout, done.stderr)
    assert len(check_reports(project)) == 3


def _steps() -> list[dict[str, Any]]:
    return list(yaml.safe_load((ROOT / "action.yml").read_text(encoding="utf-8"))["runs"]["steps"])


def test_the_actions_run_steps_work_with_its_defaults(project: Path, tmp_path: Path) -> None:
    action = yaml.safe_load((ROOT / "action.yml").read_text(encoding="utf-8"))
    assert action["runs"]["using"] == "composite"
    defaults = {name: spec.get("default", "") for name, spec in action["inputs"].items()}
    output = tmp_path / "github_output"
    output.touch()
    ran = []
    for step in _steps():
        if not re.search(r"^\s*ecnc ", step.get("run", ""), re.MULTILINE):
            continue
        env = {key: _inputs(value, defaults) for key, value in step.get("env", {}).items()}
        done = bash(step["run"], project, {**env, "GITHUB_OUTPUT": str(output)})
        assert done.returncode == 0, (step["name"], done.stdout, done.stderr)
        ran.append(step["name"])
    assert ran == ["ecnc lint (SARIF)", "ecnc test (JUnit, LCOV)"]
    assert output.read_text() == "exit-code=0\n"
    assert check_reports(project) == {"ecnc.sarif", "ecnc-junit.xml", "ecnc-coverage.info"}


def test_the_actions_lint_step_reports_findings_without_failing(project: Path, tmp_path: Path) -> None:
    (project / "examples" / "broken.nc").write_text("G1 X5 F0\n")
    action = yaml.safe_load((ROOT / "action.yml").read_text(encoding="utf-8"))
    defaults = {name: spec.get("default", "") for name, spec in action["inputs"].items()}
    (step,) = [s for s in _steps() if s.get("id") == "lint"]
    output = tmp_path / "github_output"
    env = {key: _inputs(value, defaults) for key, value in step["env"].items()}
    done = bash(step["run"], project, {**env, "GITHUB_OUTPUT": str(output)})
    assert done.returncode == 0 and output.read_text() == "exit-code=1\n"
    results = json.loads((project / "ecnc.sarif").read_text())["runs"][0]["results"]
    assert [r["ruleId"] for r in results] == ["G503"]


def _inputs(value: str, defaults: dict[str, str]) -> str:
    """``${{ inputs.NAME }}`` as GitHub fills it in with the input's default."""
    return re.sub(r"\$\{\{\s*inputs\.([\w-]+)\s*\}\}", lambda m: defaults[m[1]], value)


def test_the_pre_commit_hooks_run_on_the_files_they_match(project: Path) -> None:
    hooks = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text(encoding="utf-8"))
    assert [h["id"] for h in hooks] == ["ecnc-lint", "ecnc-test"]
    files = sorted(str(p.relative_to(project)) for p in project.rglob("*") if p.is_file())
    for hook in hooks:
        assert hook["language"] == "python" and hook["entry"].startswith("ecnc ")
        matched = [f for f in files if re.search(hook["files"], f)]  # pre-commit: re.search on the path
        assert matched, hook["id"]
        args = "" if hook.get("pass_filenames") is False else " ".join(f"'{f}'" for f in matched)
        done = bash(f"{hook['entry']} {args}", project)
        assert done.returncode == 0, (hook["id"], done.stdout, done.stderr)
    (project / "examples" / "broken.nc").write_text("G1 X5 F0\n")
    done = bash(f"{hooks[0]['entry']} examples/broken.nc", project)
    assert done.returncode == 1 and "G503" in done.stdout
