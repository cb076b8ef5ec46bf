"""The VS Code extension as vsce packs it (scripts/release): the client bundled by esbuild into
dist/extension.js, the sources and node_modules left out by .vscodeignore, the files a marketplace
wants there, and nothing built committed."""
from __future__ import annotations

import json
import re
from pathlib import Path

from edingcnc_lang import HOMEPAGE

VSCODE = Path(__file__).resolve().parents[2] / "editors" / "vscode"


def manifest() -> dict:
    return dict(json.loads((VSCODE / "package.json").read_text(encoding="utf-8")))


def test_the_client_is_bundled_from_its_source() -> None:
    package = manifest()
    assert package["main"] == "./dist/extension.js"
    bundle = package["scripts"]["bundle"]
    source, out = re.search(r"esbuild (\S+) .*--outfile=(\S+)", bundle).groups()  # type: ignore[union-attr]
    assert (VSCODE / source).is_file() and "./" + out == package["main"] and "--external:vscode" in bundle
    assert "npm run bundle" in package["scripts"]["vscode:prepublish"]
    # everything the client needs is in the bundle: vsce must not pack node_modules
    assert "dependencies" not in package and "vscode-languageclient" in package["devDependencies"]


def test_vscodeignore_keeps_the_bundle_and_drops_the_rest() -> None:
    ignored = [line.strip() for line in (VSCODE / ".vscodeignore").read_text().splitlines()
               if line.strip() and not line.startswith("#")]
    assert {"src/**", "node_modules/**", "package-lock.json"} <= set(ignored)
    assert not any(pattern.startswith("dist") or pattern.startswith("syntaxes") for pattern in ignored)
    assert {"node_modules/", "dist/", "*.vsix"} <= set((VSCODE / ".gitignore").read_text().split())


def test_what_a_marketplace_reads_is_there() -> None:
    package = manifest()
    for key in ("name", "displayName", "description", "version", "publisher", "license", "repository", "engines"):
        assert package.get(key), key
    assert package["repository"]["url"].startswith(HOMEPAGE)
    for name in ("README.md", "LICENSE", "CHANGELOG.md", "language-configuration.json"):
        assert (VSCODE / name).is_file(), name
    readme = (VSCODE / "README.md").read_text(encoding="utf-8")
    for setting in package["contributes"]["configuration"]["properties"]:
        assert f"`{setting}`" in readme, setting  # every setting is explained
    lock = json.loads((VSCODE / "package-lock.json").read_text(encoding="utf-8"))
    assert (lock["name"], lock["version"]) == (package["name"], package["version"])
    assert lock["packages"][""]["devDependencies"] == package["devDependencies"]


def test_the_debugger_and_server_settings_start_ecnc() -> None:
    package = manifest()
    settings = package["contributes"]["configuration"]["properties"]
    assert settings["edingcnc.server.command"]["default"] == ["ecnc", "lsp"]
    assert settings["edingcnc.debug.command"]["default"] == ["ecnc", "debug"]
    (debugger,) = package["contributes"]["debuggers"]
    assert debugger["type"] == "ecnc" and "program" in debugger["configurationAttributes"]["launch"]["required"]
    source = (VSCODE / "src" / "extension.js").read_text(encoding="utf-8")
    assert '"server.command"' in source and '"debug.command"' in source and 'registerDebugAdapterDescriptorFactory("ecnc"' in source
