"""The stages of the move pipeline, in the order moves pass through them (see base.py).

To add a stage: write a ``Stage`` (or ``LookaheadStage``) subclass in a module of its own here
and put its class in ``STAGES`` at the place it belongs; it is built with the next canon and the
machine configuration.  A stage may import ``canon``, ``config``, ``geometry``, ``heightmap`` and
``errors``, never the interpreter or the motion stage.  Moves come one at a time (``move``) or in
bulk (``move_batch``): a batch may hold arcs (``Batch.arcs``), and a stage with no batch form for
what it changes hands the moves to its own ``move`` one at a time with ``batch.each(self.move)``, so a
move refused among them says how many of the batch were made before it (``EcncError.done``).
"""
from __future__ import annotations

from edingcnc_lang.pipeline.base import LookaheadStage, Pipeline, Stage, StageFactory
from edingcnc_lang.pipeline.cutter_comp import CutterCompensation
from edingcnc_lang.pipeline.height_comp import HeightCompensation
from edingcnc_lang.pipeline.rotation import Rotation
from edingcnc_lang.pipeline.scaling import Scaling

# First to last: the interpreter emits into the first; the last hands on to the motion stage.
# Height compensation comes last: it follows the surface under the path the machine really cuts.
STAGES: tuple[StageFactory, ...] = (Rotation, Scaling, CutterCompensation, HeightCompensation)

__all__ = ["STAGES", "LookaheadStage", "Pipeline", "Stage", "StageFactory"]
