"""The machine model (``machine_config``), the cnc.ini format (``ini``) and height maps (``heightmap``).

``MachineConfig``, ``load_config`` and ``save_variables`` are re-exported here, where they were
before the package was split (``from edingcnc_lang.config import MachineConfig``).
"""
from __future__ import annotations

from edingcnc_lang.config.machine_config import MachineConfig, load_config, save_variables

__all__ = ["MachineConfig", "load_config", "save_variables"]
