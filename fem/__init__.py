"""Finite-element solver of the axisymmetric Mooney-Rivlin membrane (scikit-fem).

Unknowns rho(r), eta(r) on P1 or P2 Lagrange elements of the Lagrangian radius
r in [0, 1], the pressure as the multiplier of the volume, a frictionless flat
plate by penalty (optionally augmented Lagrangian). Modules: ``material`` (the
energy), ``forms`` (residual and tangent, derived in its docstring), ``model``
(the bordered system), ``newton``, ``continuation``, ``inflation``,
``compression``, ``post`` and ``solve`` (the entry points below).
"""

from .solve import compress, compress_height, compression_curve, default_mesh, inflate, inflate_volume

__all__ = ["inflate", "inflate_volume", "compress", "compression_curve", "compress_height", "default_mesh"]
