"""Parameter sweeps: a grid of compressed states solved on any executor (``pocket sweep``).

``grid`` (the grid's points solved curve by curve, and the sweep run on an executor), ``journal`` (the
sweep file: one CSV row per point, appended while the sweep runs, and how a rerun resumes it), and the
executors: ``workers`` (local processes that die with their parent; the validation suite runs on them
too) and ``cluster`` (a dask cluster that says when it cannot run the sweep).
"""
