"""``python -m pocket``: the same as the ``pocket`` command."""

import sys

from pocket.cli import main

sys.exit(main())
