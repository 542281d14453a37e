"""The validation report built with the site: ``pocket validate --quick`` written into the built HTML.

When an HTML build ends without error, the quick plan of the validation suite (fewer forces, finite-element
columns and meshes than ``pocket validate``'s full plan, every comparison and verdict kept) writes its report
into ``validation-report/`` of the output folder, where the validation page links to it. A report is a run's,
with that run's provenance: this one is of the code the site documents. ``-D pocket_validation_report=0`` skips
it (a quicker build while writing pages); the link then leads nowhere.
"""

from __future__ import annotations

import contextlib
import io
import pathlib

from sphinx.errors import ExtensionError

#: the report's folder in the built site, which the validation page links to
FOLDER = "validation-report"


def _report(app, exception) -> None:
    """Write the quick validation report into the built site; an ExtensionError with its output if it fails."""
    if exception is not None or app.builder.format != "html" or not app.config.pocket_validation_report:
        return
    from pocket.cli.main import main

    out = pathlib.Path(app.outdir) / FOLDER
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed), contextlib.redirect_stderr(printed):
        status = main(["validate", "--quick", "--vtk", "none", "--out", str(out)])
    if status != 0:
        raise ExtensionError(f"pocket validate --quick exited {status}:\n{printed.getvalue()}")


def setup(app):
    """Register the report with Sphinx."""
    app.add_config_value("pocket_validation_report", True, "html", types=(bool, int))
    app.connect("build-finished", _report)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
