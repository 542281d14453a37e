"""Mooney-Rivlin membrane energy and its derivatives, in units of E T.

Per unit reference area, with lambda_3 = 1 / (lambda_1 lambda_2),

    W = C1 T [(I1 - 3) + alpha (I2 - 3)],
    I1 = a^2 + b^2 + a^-2 b^-2,    I2 = a^-2 + b^-2 + a^2 b^2,

where a = lambda_1 (meridional) and b = lambda_2 (hoop). Dividing by
E T = 6 (1 + alpha) C1 T gives the dimensionless density

    w(a, b) = [(I1 - 3) + alpha (I2 - 3)] / (6 (1 + alpha)).

Its derivatives (the hessian is what the consistent tangent needs):

    dI1/da = 2a - 2 a^-3 b^-2          dI2/da = -2 a^-3 + 2 a b^2
    d2I1/da2 = 2 + 6 a^-4 b^-2         d2I2/da2 = 6 a^-4 + 2 b^2
    d2I1/dadb = 4 a^-3 b^-3            d2I2/dadb = 4 a b

and the same with a and b swapped. The stress resultants are
T1 = (1/b) dw/da and T2 = (1/a) dw/db, which expand to the paper's eq (6)
divided by E T: T1 = (a/b - a^-3 b^-3)(1 + alpha b^2) / (3 (1 + alpha)).
"""

from __future__ import annotations

import dataclasses

__all__ = ["MooneyRivlin"]


@dataclasses.dataclass(frozen=True)
class MooneyRivlin:
    """Dimensionless Mooney-Rivlin membrane with ratio ``alpha`` = C2/C1."""

    alpha: float

    @property
    def _scale(self) -> float:
        return 1.0 / (6.0 * (1.0 + self.alpha))

    def energy(self, a, b):
        """w(a, b), energy per unit reference area in units of E T."""
        al = self.alpha
        i1 = a**2 + b**2 + 1.0 / (a * b) ** 2
        i2 = 1.0 / a**2 + 1.0 / b**2 + (a * b) ** 2
        return self._scale * ((i1 - 3.0) + al * (i2 - 3.0))

    def gradient(self, a, b):
        """(dw/da, dw/db)."""
        return self._first(a, b), self._first(b, a)

    def hessian(self, a, b):
        """(d2w/da2, d2w/dadb, d2w/db2)."""
        al = self.alpha
        mixed = self._scale * (4.0 / (a * b) ** 3 + al * 4.0 * a * b)
        return self._second(a, b), mixed, self._second(b, a)

    def derivatives(self, a, b):
        """(w_1, w_2, w_11, w_12, w_22) at once, sharing the powers (what an assembly needs)."""
        al, s = self.alpha, self._scale
        ia, ib = 1.0 / a, 1.0 / b
        ia2, ib2 = ia * ia, ib * ib
        both = ia2 * ib2  # (a b)^-2
        a2, b2 = a * a, b * b
        w1 = 2.0 * s * (a - ia * both + al * (a * b2 - ia * ia2))
        w2 = 2.0 * s * (b - ib * both + al * (b * a2 - ib * ib2))
        w11 = s * (2.0 + 6.0 * ia2 * both + al * (6.0 * ia2 * ia2 + 2.0 * b2))
        w22 = s * (2.0 + 6.0 * ib2 * both + al * (6.0 * ib2 * ib2 + 2.0 * a2))
        w12 = 4.0 * s * (ia * ib * both + al * a * b)
        return w1, w2, w11, w12, w22

    def tensions(self, a, b):
        """(T1, T2) = ((1/b) dw/da, (1/a) dw/db), in units of E T."""
        wa, wb = self.gradient(a, b)
        return wa / b, wb / a

    def _first(self, a, b):
        al = self.alpha
        return self._scale * (2.0 * a - 2.0 / (a**3 * b**2) + al * (-2.0 / a**3 + 2.0 * a * b**2))

    def _second(self, a, b):
        al = self.alpha
        return self._scale * (2.0 + 6.0 / (a**4 * b**2) + al * (6.0 / a**4 + 2.0 * b**2))
