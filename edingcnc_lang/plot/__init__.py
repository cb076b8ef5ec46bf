"""Pictures of a job: matplotlib plots (``ecnc plot``) and a self-contained HTML viewer (``ecnc view``).

Both draw the toolpath recorded from a run through the embedding API (``toolpath.record_job``).
matplotlib is an optional extra and is imported only by the plotting modules.
"""
