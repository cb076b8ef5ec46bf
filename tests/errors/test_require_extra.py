"""One helper says how to install a missing extra, in one wording, for every feature that needs one."""
from __future__ import annotations

import sys

import pytest

from edingcnc_lang.errors import EXIT_USAGE, MissingExtra, require_extra


def test_an_installed_module_is_returned() -> None:
    assert require_extra("json", "plot", "a picture") is sys.modules["json"]


def test_a_missing_module_names_the_feature_the_module_and_the_install_command(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(MissingExtra) as caught:
        require_extra("matplotlib", "plot", "ecnc kins plot")
    assert caught.value.message == ("ecnc kins plot needs matplotlib (matplotlib is missing): "
                                         "pip install 'edingcnc-lang[plot]'")
    assert caught.value.exit_code == EXIT_USAGE


def test_kins_plot_without_matplotlib_uses_the_helper(monkeypatch: pytest.MonkeyPatch) -> None:
    from edingcnc_lang.kinematics.workbench import envelope

    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(MissingExtra, match=r"ecnc kins plot needs matplotlib .*edingcnc-lang\[plot\]"):
        envelope._pyplot()
