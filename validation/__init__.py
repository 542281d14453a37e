"""The validation suite: cases, cross-checks of the solvers, the paper's figures, the report.

``pocket validate`` (and ``pocket converge``) run it from the command line
(``validation/cli.py``). From Python::

    from validation import load, run, write_report, DEFAULT
    cases, design = load()
    results = run(cases, design, DEFAULT)
    write_report(results, "validation-report")

Modules: ``cases`` (cases.toml, units), ``plan`` (what a run computes),
``compute`` / ``convergence`` / ``evidence`` (the solves), ``checks`` and
``findings`` (tolerances, verdicts, the paper's statements), ``run`` (the
parallel run), ``figures`` / ``draw`` / ``render`` (plots, 3-D picture),
``sections`` / ``document`` / ``report`` (the report folder).
"""

import importlib

__all__ = ["load", "run", "write_report", "DEFAULT", "QUICK"]

_HOMES = {"load": "cases", "run": "run", "write_report": "report", "DEFAULT": "plan", "QUICK": "plan"}


def __getattr__(name):
    """Import on first use: ``pocket`` imports ``validation.cli`` for every command, and the rest
    (scipy, the solvers) costs about 0.6 s that ``pocket inflate`` should not pay."""
    if name in _HOMES:
        return getattr(importlib.import_module(f".{_HOMES[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
