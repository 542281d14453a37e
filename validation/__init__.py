"""The validation suite: cases, cross-checks of the solvers, the paper's figures, the report.

``pocket validate`` (and ``pocket converge``) run it from the command line
(``pocket.cli.validate``). From Python::

    from pocket.validation import load, run, write_report, DEFAULT
    pockets, button = load()
    results = run(pockets, button, DEFAULT)
    write_report(results, "validation-report")

Modules: ``suite`` (the pockets of cases.toml, read as case files, and the
button of the paper's section 6), ``plan`` (what a run computes, the solver
columns), ``compute`` / ``convergence`` / ``evidence`` (the solves),
``verdicts`` and ``findings`` (tolerances, verdicts, the paper's statements),
``limits`` (the headline: the numerics' verdict and the models' limits),
``failures`` (a solver failure re-raised naming its case, study, mesh and force),
``runner`` (the parallel run), ``figures`` / ``others`` / ``draw`` / ``render`` (the
paper's figures, the gas and other-law figures, plots, 3-D picture), ``pockets`` /
``sections`` / ``checkpage`` / ``document`` / ``report`` (the report folder).
"""

import importlib

from pocket.core.importname import require_import_name

require_import_name(__name__, "pocket.validation")

__all__ = ["DEFAULT", "QUICK", "load", "run", "write_report"]

_HOMES = {"load": "suite", "run": "runner", "write_report": "report", "DEFAULT": "plan", "QUICK": "plan"}


def __getattr__(name):
    """Import on first use: the solvers and scipy cost time that importing the package should not."""
    if name in _HOMES:
        return getattr(importlib.import_module(f".{_HOMES[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
