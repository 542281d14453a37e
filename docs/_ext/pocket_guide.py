"""The user guide's generated pages: the case files' keys, the command line, the reported keys.

Written when the docs build (``builder-inited``), from the code that reads the case files (``guide_cases``),
parses the command line (``guide_cli``) and writes the results (``guide_outputs``), into
``docs/guide/generated/``, which the guide's hand-written pages include: the guide cannot drift from what pocket
does. The folder is not a source of pages of its own (``exclude_patterns``) and not kept in git.
"""

from __future__ import annotations

import pathlib

import guide_cases
import guide_cli
import guide_outputs

#: the folder of the generated fragments, relative to the docs' source folder
FOLDER = "guide/generated"

#: file name -> the function that writes its Markdown
FRAGMENTS = {
    "case-keys.md": guide_cases.page,
    "commands.md": guide_cli.page,
    "exit-codes.md": guide_cli.exit_codes,
    "solvers.md": guide_cli.solvers,
    "ranges.md": guide_cli.ranges,
    "units.md": guide_outputs.units,
    "model-keys.md": guide_outputs.model_keys,
    "si-columns.md": guide_outputs.si_columns,
    "sweep-columns.md": guide_outputs.sweep_columns,
    "vtk-codes.md": guide_outputs.vtk_codes,
}


def _exclude(app, config) -> None:
    """The fragments are included by the guide's pages, not pages of their own."""
    config.exclude_patterns.append(f"{FOLDER}/*")


def _write(app) -> None:
    """Write every fragment from the live code; a file is rewritten only if its text changed (Sphinx then
    rereads the pages that include it)."""
    folder = pathlib.Path(app.srcdir) / FOLDER
    folder.mkdir(parents=True, exist_ok=True)
    for name, write in FRAGMENTS.items():
        path, text = folder / name, write()
        if not path.exists() or path.read_text(encoding="utf-8") != text:
            path.write_text(text, encoding="utf-8")


def setup(app):
    """Register the generator with Sphinx."""
    app.connect("config-inited", _exclude)
    app.connect("builder-inited", _write)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
