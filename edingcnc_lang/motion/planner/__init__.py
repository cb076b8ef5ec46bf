"""The motion planner: how long each move takes with the machine's velocity and acceleration limits.

``stage.Planner`` is the pipeline stage (behind the motion stage, in front of the output sinks);
``estimate`` holds the totals a run reports; ``profile``, ``segments`` and ``junctions`` are the
numpy model, testable alone; ``samples`` makes the time-true samples; ``limits_report`` the
limits report; ``overrides`` the feed and rapid overrides.  See docs/planner.md.
"""
