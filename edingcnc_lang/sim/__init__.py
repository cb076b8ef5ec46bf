"""Cutting a stock with a job: a height-field milling simulation (``ecnc sim``, docs/simulation.md).

``simulate(job, Stock.box(...), options, load_tools(...))`` runs the job through the embedding API
and sweeps every move's tool through the stock (``sweep.py``, ``envelope.py``); the result holds the
cut stock, the findings (``findings.py``) and the volumes.  Pictures (``picture.py``), STL in and out
(``stl.py``), the comparison with the intended part (``compare.py``) and the report (``report.py``)
work on that result.  Round stock (``round_stock.py``): a lathe's bar turned by ``lathe.simulate_bar``
(the nose's sweep in ``turning.py``) and a bar on a mill's A axis cut by ``rotary.simulate_cylinder``;
their outputs in ``bar_output.py``.  ``simulate_bar(job, RoundStock.bar(...), options, tools)``
turns a bar (the insert and holder beyond the nose in ``insert.py``).  The rotary tool's parts on the bar's rays: ``rotary_stamp.py``;
the rotary part's STL, shaded view and comparison: ``rotary_output.py``.
"""
from __future__ import annotations

from edingcnc_lang.sim.job import SimResult, simulate
from edingcnc_lang.sim.lathe import BarResult, simulate_bar
from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.stock import Stock
from edingcnc_lang.sim.tools import Tool, load_tools

__all__ = ["SimResult", "Stock", "Tool", "load_tools", "simulate"]
__all__ += ["BarResult", "RoundStock", "simulate_bar"]  # round stock: a lathe's bar
