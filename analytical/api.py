"""Public entry points of the analytical model (``pocket.core.solver``): ``inflate``, ``compress``,
``compression_curve`` and ``range_end``, with their types, and the model's shape function G(r, a).

They are defined, with the model they evaluate, in ``pocket.analytical.model``; this module is the
solver's face, the same in every solver: one place to read what the solver offers.
"""

from .model import compress, compression_curve, inflate, range_end, shape_function

__all__ = ["compress", "compression_curve", "inflate", "range_end", "shape_function"]
