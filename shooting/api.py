"""Public entry points of the shooting solver (``pocket.core.solver``), with their types.

Each lives with the part of the solver it drives: ``inflate``, ``inflation_curve`` and ``inflate_volume``
in ``inflation``, ``compress`` and ``compression_curve`` in ``compression``, ``compress_height`` in
``travel``, ``range_end`` in ``rangeend``; this module is the solver's face, the same in every solver:
one place to read what the solver offers. Those of ``compression`` and ``rangeend`` are declared here
with the face ``pocket.core.solver`` gives every solver's (``Compress``, ``CompressionCurve``,
``RangeEnd``: the arguments before the keywords, and the result); the others carry their own types.
Each takes the membrane's reference surface ``geometry`` (``pocket.core.solver.GeometryLike``; the surfaces
this solver poses are ``inflation.GEOMETRIES``).
"""

from pocket.core.solver import Compress, CompressionCurve, RangeEnd

from . import compression, rangeend
from .inflation import inflate, inflate_volume, inflation_curve
from .travel import compress_height

__all__ = [
    "compress",
    "compress_height",
    "compression_curve",
    "inflate",
    "inflate_volume",
    "inflation_curve",
    "range_end",
]

compress: Compress = compression.compress
compression_curve: CompressionCurve = compression.compression_curve
range_end: RangeEnd = rangeend.range_end
