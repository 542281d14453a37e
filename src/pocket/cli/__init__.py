"""The ``pocket`` command line: one module per subcommand, on top of every other layer.

``main(argv=None)`` runs it and returns the exit status (``pocket.cli.main``).
"""

from .main import main

__all__ = ["main"]
