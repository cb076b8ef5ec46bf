"""The plug-in author's workbench: prove, compare and picture a kinematics plug-in off-line.

``check_plugin`` runs every check and returns a ``Report``; ``compare_plugins`` sets two plug-ins side
by side; ``plot_envelope`` (needs matplotlib, the ``plot`` extra) draws the reachable workspace and the
Jacobian's condition number.  See docs/kinematics.md, "Proving a plug-in".
"""
from __future__ import annotations

from edingcnc_lang.kinematics.workbench.check import CheckOptions, check_plugin
from edingcnc_lang.kinematics.workbench.compare import Comparison, compare_plugins
from edingcnc_lang.kinematics.workbench.findings import FINDING_CODES, KinsFinding, Report

__all__ = ["CheckOptions", "Comparison", "FINDING_CODES", "KinsFinding", "Report", "check_plugin", "compare_plugins"]
