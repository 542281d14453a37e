r"""The membrane tensions of each rubber law and their derivatives, derived from its strain energy.

Derivation
----------
An incompressible sheet of thickness T in plane stress, principal stretches l1
(meridian), l2 (hoop), l3 = 1 / (l1 l2). With W~(l1, l2) = W(l1, l2, 1/(l1 l2)) the
energy per unit reference volume (``pocket.core.materials.energy``), the Cauchy stress
is sigma_1 = l1 dW~/dl1 and the resultant per unit deformed length is
T_1 = T l3 sigma_1, so

    T_1 = (T / l2) dW~/dl1,    T_2 = (T / l1) dW~/dl2.

Every law here is isotropic: W~ is symmetric in l1, l2, hence T_2(l1, l2) = T_1(l2, l1),
and only t1 = T_1 / (tau T) with its two derivatives needs a formula (tau: the unit below).

Invariant laws, W(I1, I2), I1 = l1^2 + l2^2 + l3^2, I2 = l1^-2 + l2^-2 + l3^-2. With
dl3/dl1 = -l3 / l1,

    dI1/dl1 = 2 (l1 - l3^2 / l1),    dI2/dl1 = -2 l1^-3 + 2 l1 l2^2 = 2 l2^2 (l1 - l3^2 / l1),

so T_1 / T = 2 g1 (W_1 + l2^2 W_2), g1 = l1 / l2 - 1 / (l1^3 l2^3), W_k = dW/dI_k.

- Mooney-Rivlin, W_1 = C1, W_2 = C2 = alpha C1: t1 = g1 (1 + alpha l2^2) in units of
  tau = 2 C1: the paper's eq (6), kept in its units and in the closed form of the
  paper's solver (dt1/dl1 = dg1/dl1 (1 + alpha l2^2), dt1/dl2 = dg1/dl2 (1 + alpha l2^2)
  + 2 alpha l2 g1) so that a rubber given by alpha is solved exactly as before.
- The laws of I1 alone (W_2 = 0), in units of tau = mu_0: t1 = 2 g1 W_1(I1), and

      dt1/dl1 = 2 (dg1/dl1) W_1 + 2 g1 W_11 dI1/dl1,
      dt1/dl2 = 2 (dg1/dl2) W_1 + 2 g1 W_11 dI1/dl2,

      dg1/dl1 = 1/l2 + 3/(l1^4 l2^3),   dg1/dl2 = -l1/l2^2 + 3/(l1^3 l2^4),   dI1/dl2 = 2 (l2 - l3^2/l2),

  with x = I1 - 3:   neo-Hookean W_1 = mu/2, W_11 = 0;
  Yeoh W_1 = C10 + 2 C20 x + 3 C30 x^2, W_11 = 2 C20 + 6 C30 x;
  Gent W_1 = (mu/2) / (1 - x/Jm), W_11 = (mu/2) / (Jm (1 - x/Jm)^2), defined for x < Jm only.

Ogden, directly in the stretches: W~ = sum_p (mu_p/alpha_p)(l1^alpha_p + l2^alpha_p + l3^alpha_p - 3),
d(l3^a)/dl1 = -a l3^a / l1, so dW~/dl1 = sum_p mu_p (l1^(alpha_p - 1) - l3^alpha_p / l1) and, in units of mu_0,

    t1 = S / (l1 l2),                 S = sum_p mu_p (l1^alpha_p - l3^alpha_p),
    dt1/dl1 = sum_p mu_p alpha_p (l1^alpha_p + l3^alpha_p) / (l1^2 l2) - t1 / l1,
    dt1/dl2 = sum_p mu_p alpha_p l3^alpha_p / (l1 l2^2) - t1 / l2.

Small strain: at l1 = l2 = 1 + e every law gives t1 = 6 (mu_0 / tau) e + O(e^2), i.e.
T_1 = 6 mu_0 T e = 2 E T e with E = 3 mu_0 (tests: ``tests/test_shooting_laws.py``, which also
checks each formula against central differences of ``pocket.core.materials.energy``).

Units. Tensions are in units of tau T and pressures p = P R / (tau T) = (3 mu_0 / tau) Phat:
``Law.pressure_factor`` is 3 mu_0 / tau (3 (1 + alpha) for Mooney-Rivlin, 3 for the rest) and
tensions in units of E T are t / pressure_factor.

Prestretch (``pocket.core.materials``). A sheet clamped with an equibiaxial prestretch lambda_p has,
at stretches (l1, l2) relative to the clamped flat sheet, the tensions of the unstretched sheet at
the material stretches L_i = lambda_p l_i: t1(l1, l2) = t1^u(L1, L2), and each derivative with
respect to l_j is lambda_p dt1^u/dL_j. The thickness and the unit tau stay the unstretched sheet's.
The domain of a locking law is that of the material stretches (``inside``). With lambda_p = 1 the
products by 1.0 are exact: the kernel is bit for bit the unstretched one.

The kernel takes the law as an integer ``code`` and a float array ``params`` (the table
``pocket.shooting.laws.KERNELS`` maps each law of the registry to them): Mooney-Rivlin [alpha];
neo-Hookean [mu]; Yeoh [C10, C20, C30]; Gent [mu, Jm]; Ogden [mu_1, alpha_1, mu_2, alpha_2, ...],
stresses in units of mu_0; the prestretch lambda_p is appended as the array's last entry. A code with
no formula here is a ValueError, never another law's numbers.
``tensions`` works on floats and on arrays of one shape; ``tensions_compiled`` is it compiled for
the integrator (its helpers are ``register_jitable``: plain Python when called from
Python, compiled when called from compiled code).
"""

from __future__ import annotations

from numba.extending import register_jitable

from pocket.core.compiled import compiled

__all__ = [
    "GENT",
    "MOONEY_RIVLIN",
    "NEO_HOOKEAN",
    "OGDEN",
    "YEOH",
    "inside",
    "inside_compiled",
    "tensions",
    "tensions_compiled",
]

MOONEY_RIVLIN, NEO_HOOKEAN, YEOH, GENT, OGDEN = 0, 1, 2, 3, 4


def tensions(l1, l2, code, params):
    """(t1, t2, dt1/dl1, dt1/dl2) at stretches (l1, l2) relative to the clamped flat sheet, in units of
    tau T (module docstring); ``params[-1]`` is the prestretch."""
    lp = params[-1]
    t1, t2, a11, a12 = _material(lp * l1, lp * l2, code, params[:-1])
    return t1, t2, lp * a11, lp * a12


@register_jitable
def _material(l1, l2, code, params):
    """``tensions`` at the material stretches (l1, l2), of the law's own ``params``."""
    if code == MOONEY_RIVLIN:
        return _mooney_rivlin(l1, l2, params[0])
    if code == OGDEN:
        return _ogden(l1, l2, params)
    return _first_invariant(l1, l2, code, params)


@register_jitable
def _mooney_rivlin(l1, l2, alpha):
    inv = 1.0 / (l1**3 * l2**3)
    g1 = l1 / l2 - inv
    t1 = g1 * (1.0 + alpha * l2 * l2)
    t2 = (l2 / l1 - inv) * (1.0 + alpha * l1 * l1)
    dt1_dl1 = (1.0 / l2 + 3.0 * inv / l1) * (1.0 + alpha * l2 * l2)
    dt1_dl2 = (-l1 / (l2 * l2) + 3.0 * inv / l2) * (1.0 + alpha * l2 * l2) + 2.0 * alpha * l2 * g1
    return t1, t2, dt1_dl1, dt1_dl2


@register_jitable
def _first_invariant(l1, l2, code, params):
    inv = 1.0 / (l1**3 * l2**3)
    l3sq = inv * l1 * l2  # l3^2
    x = l1 * l1 + l2 * l2 + l3sq - 3.0
    w1, w11 = _slopes(x, code, params)
    g1 = l1 / l2 - inv
    g2 = l2 / l1 - inv
    dg1_dl1 = 1.0 / l2 + 3.0 * inv / l1
    dg1_dl2 = -l1 / (l2 * l2) + 3.0 * inv / l2
    di1_dl1 = 2.0 * (l1 - l3sq / l1)
    di1_dl2 = 2.0 * (l2 - l3sq / l2)
    return (2.0 * g1 * w1, 2.0 * g2 * w1, 2.0 * (dg1_dl1 * w1 + g1 * w11 * di1_dl1),
            2.0 * (dg1_dl2 * w1 + g1 * w11 * di1_dl2))


@register_jitable
def _slopes(x, code, params):
    """(W_1, W_11) of a law of I1 alone at x = I1 - 3."""
    if code == NEO_HOOKEAN:
        return 0.5 * params[0] + 0.0 * x, 0.0 * x
    if code == YEOH:
        return params[0] + x * (2.0 * params[1] + 3.0 * params[2] * x), 2.0 * params[1] + 6.0 * params[2] * x
    if code == GENT:  # defined for x < Jm (``inside``); past it the formulas stay finite and the integrator stops
        half_mu, jm = 0.5 * params[0], params[1]
        slack = 1.0 - x / jm
        return half_mu / slack, half_mu / (jm * slack * slack)
    raise ValueError("shooting kernel: no tension formula for this law code")


@register_jitable
def _ogden(l1, l2, params):
    l3 = 1.0 / (l1 * l2)
    s1 = 0.0 * l1
    s2 = 0.0 * l1
    d11 = 0.0 * l1
    d12 = 0.0 * l1
    for k in range(params.size // 2):
        mu, a = params[2 * k], params[2 * k + 1]
        p1, p2, p3 = l1**a, l2**a, l3**a
        s1 = s1 + mu * (p1 - p3)
        s2 = s2 + mu * (p2 - p3)
        d11 = d11 + mu * a * (p1 + p3)
        d12 = d12 + mu * a * p3
    t1 = s1 * l3
    return t1, s2 * l3, d11 * l3 / l1 - t1 / l1, d12 * l3 / l2 - t1 / l2


def inside(l1, l2, code, params):
    """Whether the stretches (relative to the clamped flat sheet) lie in the law's domain: x = I1 - 3 < Jm
    of the material stretches for Gent, everywhere for the rest."""
    if code != GENT:
        return True
    m1, m2 = params[-1] * l1, params[-1] * l2
    return m1 * m1 + m2 * m2 + 1.0 / (m1 * m1 * m2 * m2) - 3.0 < params[1]


tensions_compiled = compiled(tensions, inline="always")
inside_compiled = compiled(inside, inline="always")
