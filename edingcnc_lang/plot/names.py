"""The views and colour schemes ``ecnc plot`` and ``ecnc view`` offer, by name.

Apart from ``views`` (which needs numpy and the run) so that the command line can list them as
choices without importing either: ``ecnc --help`` stays quick.
"""
from __future__ import annotations

VIEW_NAMES = ("top", "front", "side", "iso", "lathe")   # the projections of views.VIEWS, in this order
COLOR_MODES = ("tool", "kind", "feed", "speed")
