r"""The membrane energy of each rubber law and its first and second derivatives, compiled.

Per unit reference area, in units of E T (E = 3 mu_0 the small-strain Young's
modulus, T the thickness), the membrane energy of an incompressible sheet is

    w(a, b) = W(a, b, 1/(a b)) / E,       a = lambda_1 (meridional), b = lambda_2 (hoop),

W the strain energy per unit reference volume (``pocket.core.materials``). The
kernel needs w_1 = dw/da, w_2 = dw/db and the Hessian w_11, w_12, w_22; the
tensions are T_1 = w_1 / b, T_2 = w_2 / a. Every parameter below is a stress
divided by E (``material`` divides), so W stands for W / E.

Invariant laws. With I1 = a^2 + b^2 + a^-2 b^-2 and I2 = a^-2 + b^-2 + a^2 b^2,

    dI1/da = 2 a - 2 a^-3 b^-2,     d2I1/da2 = 2 + 6 a^-4 b^-2,     d2I1/dadb = 4 a^-3 b^-3,
    dI2/da = 2 a b^2 - 2 a^-3,      d2I2/da2 = 2 b^2 + 6 a^-4,      d2I2/dadb = 4 a b,

and the same with a and b swapped. For W(I1, I2) the chain rule gives

    w_a  = W_1 I1_a + W_2 I2_a,
    w_ab = W_11 I1_a I1_b + W_12 (I1_a I2_b + I2_a I1_b) + W_22 I2_a I2_b + W_1 I1_ab + W_2 I2_ab,

(W_i = dW/dI_i, W_ij the second derivatives; a, b stand for either stretch). The
laws of I1 alone (W_2 = W_12 = W_22 = 0), with x = I1 - 3:

    Yeoh (C10, C20, C30):  W_1 = C10 + 2 C20 x + 3 C30 x^2,    W_11 = 2 C20 + 6 C30 x;
    neo-Hookean (mu): Yeoh with C10 = mu / 2, C20 = C30 = 0;
    Gent (mu, Jm):    W = -(mu Jm / 2) ln(1 - x / Jm),  W_1 = (mu / 2) / (1 - x / Jm),
                      W_11 = (mu / (2 Jm)) / (1 - x / Jm)^2,   defined only for x < Jm.

Past Gent's locking (x >= Jm) every derivative is NaN: the energy does not
exist there, and a Newton iterate that reaches it is rejected as non-finite
(the formulas alone would return finite numbers of the wrong sign).

Mooney-Rivlin (C1, C2 = alpha C1) is W_1 = C1, W_2 = C2 with the invariant
derivatives expanded (the paper's law, the hot path, kept in the closed form
the solver has always used): with s = C1 / E = 1 / (6 (1 + alpha)),

    w_a  = 2 s (a - a^-3 b^-2 + alpha (a b^2 - a^-3)),
    w_aa = s (2 + 6 a^-4 b^-2 + alpha (6 a^-4 + 2 b^2)),   w_ab = 4 s (a^-3 b^-3 + alpha a b).

Ogden (mu_p, alpha_p), in principal stretches, with c = a^-1 b^-1 (lambda_3):

    W = sum_p (mu_p / alpha_p) (a^alpha_p + b^alpha_p + c^alpha_p - 3),   dc/da = -c / a,
    w_a  = sum_p mu_p (a^alpha_p - c^alpha_p) / a,
    w_aa = sum_p mu_p ((alpha_p - 1) a^alpha_p + (alpha_p + 1) c^alpha_p) / a^2,
    w_ab = sum_p mu_p alpha_p c^alpha_p / (a b).

Prestretch (``pocket.core.materials``). A sheet clamped with an equibiaxial prestretch lambda_p has,
per unit area of the clamped flat sheet and at stretches (a, b) relative to it, the energy
w(a, b) = w_u(lambda_p a, lambda_p b) / lambda_p^2 of the unstretched sheet (w_u, thickness and E the
unstretched rubber's) at the material stretches A = lambda_p a, B = lambda_p b, so

    w_a = w_u,a(A, B) / lambda_p,    w_ab = w_u,ab(A, B),

and the tensions w_a / b = w_u,a(A, B) / B are the unstretched sheet's at the material stretches.
Gent's domain is that of the material stretches. With lambda_p = 1 the products and quotients by
1.0 are exact: bit for bit the unstretched kernel.

``derivatives`` evaluates one point (called inside the element loop, ``loops``);
``evaluate`` maps it over arrays. A law is an integer code and a parameter
array (the table ``material.KERNELS`` builds them from a ``pocket.core.materials.Material``):

    MOONEY_RIVLIN [s, alpha];  YEOH [C10, C20, C30];  GENT [mu, Jm];  OGDEN [mu_1..mu_n, alpha_1..alpha_n],

each followed by the prestretch lambda_p as the array's last entry.

A code with no formula here is a ValueError, never another law's numbers.
"""

from __future__ import annotations

import numpy as np

from pocket.core.compiled import compiled

__all__ = ["GENT", "MOONEY_RIVLIN", "OGDEN", "YEOH", "derivatives", "evaluate"]

MOONEY_RIVLIN, YEOH, GENT, OGDEN = 0, 1, 2, 3


@compiled
def _mooney_rivlin(s, alpha, a, b):
    ia, ib = 1.0 / a, 1.0 / b
    ia2, ib2 = ia * ia, ib * ib
    both = ia2 * ib2
    w1 = 2.0 * s * (a - ia * both + alpha * (a * b * b - ia * ia2))
    w2 = 2.0 * s * (b - ib * both + alpha * (b * a * a - ib * ib2))
    w11 = s * (2.0 + 6.0 * ia2 * both + alpha * (6.0 * ia2 * ia2 + 2.0 * b * b))
    w22 = s * (2.0 + 6.0 * ib2 * both + alpha * (6.0 * ib2 * ib2 + 2.0 * a * a))
    w12 = 4.0 * s * (ia * ib * both + alpha * a * b)
    return w1, w2, w11, w12, w22


@compiled
def _first_invariant(code, params, a, b):
    """The laws of I1 alone: (W_1, W_11) through the chain rule of the module docstring."""
    ia, ib = 1.0 / a, 1.0 / b
    both = ia * ia * ib * ib  # (a b)^-2
    x = a * a + b * b + both - 3.0
    if code == YEOH:
        c10, c20, c30 = params[0], params[1], params[2]
        d1, d11 = c10 + x * (2.0 * c20 + 3.0 * c30 * x), 2.0 * c20 + 6.0 * c30 * x
    elif code == GENT:
        mu, jm = params[0], params[1]
        if not x < jm:
            return np.nan, np.nan, np.nan, np.nan, np.nan
        slack = 1.0 / (1.0 - x / jm)
        d1, d11 = 0.5 * mu * slack, 0.5 * mu / jm * slack * slack
    else:
        raise ValueError("finite-element kernel: no energy derivatives for this law code")
    i1a, i1b = 2.0 * (a - ia * both), 2.0 * (b - ib * both)
    return (d1 * i1a, d1 * i1b, d11 * i1a * i1a + d1 * (2.0 + 6.0 * ia * ia * both),
            d11 * i1a * i1b + d1 * 4.0 * ia * ib * both, d11 * i1b * i1b + d1 * (2.0 + 6.0 * ib * ib * both))


@compiled
def _ogden(params, a, b):
    n = params.size // 2
    c = 1.0 / (a * b)
    w1 = w2 = w11 = w12 = w22 = 0.0
    for p in range(n):
        mu, ex = params[p], params[n + p]
        pa, pb, pc = a**ex, b**ex, c**ex
        w1 += mu * (pa - pc)
        w2 += mu * (pb - pc)
        w11 += mu * ((ex - 1.0) * pa + (ex + 1.0) * pc)
        w22 += mu * ((ex - 1.0) * pb + (ex + 1.0) * pc)
        w12 += mu * ex * pc
    return w1 / a, w2 / b, w11 / (a * a), w12 / (a * b), w22 / (b * b)


@compiled
def derivatives(code, params, a, b):
    """(w_1, w_2, w_11, w_12, w_22) of the law ``code`` with ``params`` (the prestretch last) at the
    stretches (a, b) relative to the clamped flat sheet."""
    lp = params[-1]
    w1, w2, w11, w12, w22 = _material(code, params[:-1], lp * a, lp * b)
    return w1 / lp, w2 / lp, w11, w12, w22


@compiled
def _material(code, params, a, b):
    """``derivatives`` of the unstretched sheet at the material stretches (a, b), of the law's own ``params``."""
    if code == MOONEY_RIVLIN:
        return _mooney_rivlin(params[0], params[1], a, b)
    if code == OGDEN:
        return _ogden(params, a, b)
    return _first_invariant(code, params, a, b)


@compiled
def evaluate(code, params, a, b):
    """``derivatives`` at every point of the flat arrays a, b (n,): shape (5, n)."""
    out = np.empty((5, a.size))
    for i in range(a.size):
        out[0, i], out[1, i], out[2, i], out[3, i], out[4, i] = derivatives(code, params, a[i], b[i])
    return out
