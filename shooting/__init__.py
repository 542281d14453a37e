"""The reference solver: shooting on the axisymmetric membrane equations (Yang & Feng).

``inflate`` / ``inflate_volume`` solve step 1 (pressure or volume control),
``compress`` / ``compression_curve`` step 2 (fixed volume, flat frictionless
plate, force given). All return ``pocket.states`` containers; the equations and
their derivation are in ``shooting.equations``.
"""

from .compression import compress, compression_curve
from .inflation import inflate, inflate_volume

__all__ = ["inflate", "inflate_volume", "compress", "compression_curve"]
