"""``python -m pocket.cli``: the same as the ``pocket`` command."""

import sys

from .main import main

sys.exit(main())
