"""The import paths a user's program may hold still work after the package was split into layers."""
from __future__ import annotations

import edingcnc_lang


def test_the_public_api_names_import_from_the_package() -> None:
    for name in edingcnc_lang.__all__:
        assert getattr(edingcnc_lang, name) is not None, name


def test_the_old_parser_and_config_paths_re_export_their_entry_points() -> None:
    from edingcnc_lang import parser
    from edingcnc_lang.config import MachineConfig, load_config, save_variables
    from edingcnc_lang.config.machine_config import MachineConfig as Defined
    from edingcnc_lang.syntax import parser as real

    assert MachineConfig is Defined and callable(load_config) and callable(save_variables)
    for name in parser.__all__:
        assert getattr(parser, name) is getattr(real, name), name
    assert parser.parse_text("G1 X1\n").body
