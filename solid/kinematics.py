r"""Axisymmetric kinematics, the first Piola stress and its linearisation, from W(I1, I2).

Coordinates (r, z) of the flat sheet's cross-section, in units of R; the displacement
u = (u_r, u_z)(r, z). The deformation gradient in the cylindrical basis is

        [ 1 + du_r/dr    du_r/dz       0         ]
    F = [ du_z/dr        1 + du_z/dz   0         ],      J = det F = F_33 (F_11 F_22 - F_12 F_21),
        [ 0              0             1 + u_r/r ]

and a variation du gives dF of the same pattern without the identity (dF_33 = du_r / r).

Stress. With C = F^T F, I1 = F : F and I2 = (I1^2 - C : C) / 2,

    dI1/dF = 2 F,    dI2/dF = 2 (I1 F - F C),

so P = dW/dF = 2 W_1 F + 2 W_2 (I1 F - F C). Its linearisation along dF, with
dI1 = 2 F : dF, dI2 = 2 (I1 F - F C) : dF and dC = dF^T F + F^T dF:

    dP = 2 (W_11 dI1 + W_12 dI2) F + 2 W_1 dF
         + 2 (W_12 dI1 + W_22 dI2) (I1 F - F C) + 2 W_2 (dI1 F + I1 dF - dF C - F dC).

Incompressibility. The constraint J = 1 enters with a multiplier p (units of the stresses):
dJ/dF = J F^-T, and the second variation is
d^2 J [A, B] = J (tr(F^-1 A) tr(F^-1 B) - tr(F^-1 A F^-1 B)).

Every array here has the tensor indices first: F is (3, 3, ...), the rest of the shape that of the
quadrature points (elements, points).
"""

from __future__ import annotations

import numpy as np

__all__ = ["gradient", "variation", "stress", "stress_variation", "jacobian", "cofactor", "jacobian_second"]


def _tensor(grad: np.ndarray, hoop: np.ndarray, identity: float) -> np.ndarray:
    out = np.zeros((3, 3) + hoop.shape)
    out[:2, :2] = grad
    out[2, 2] = hoop
    if identity:
        out[0, 0] += identity
        out[1, 1] += identity
        out[2, 2] += identity
    return out


def gradient(grad: np.ndarray, u_r: np.ndarray, r: np.ndarray) -> np.ndarray:
    """F (3, 3, ...) from the displacement's in-plane gradient ``grad`` (2, 2, ...; grad[i, j] = du_i/dx_j),
    its radial component ``u_r`` and the radius ``r`` (> 0, the quadrature points')."""
    return _tensor(grad, u_r / r, 1.0)


def variation(grad: np.ndarray, u_r: np.ndarray, r: np.ndarray) -> np.ndarray:
    """dF (3, 3, ...) of a displacement variation, as ``gradient`` without the identity."""
    return _tensor(grad, u_r / r, 0.0)


def _dot(a, b):
    return np.einsum("ik...,kj...->ij...", a, b)


def _ddot(a, b):
    return np.einsum("ij...,ij...->...", a, b)


def _invariants(F):
    C = _dot(np.swapaxes(F, 0, 1), F)
    i1 = _ddot(F, F)
    return C, i1, 0.5 * (i1**2 - _ddot(C, C))


def stress(F: np.ndarray, law) -> np.ndarray:
    """P = dW/dF (3, 3, ...) of the law ``law`` ((I1, I2) -> (W_1, W_2, W_11, W_12, W_22), ``laws``)."""
    C, i1, i2 = _invariants(F)
    w1, w2 = law(i1, i2)[:2]
    return 2.0 * w1 * F + 2.0 * w2 * (i1 * F - _dot(F, C))


def stress_variation(F: np.ndarray, dF: np.ndarray, law) -> np.ndarray:
    """dP (3, 3, ...): the linearisation of ``stress`` at F along dF."""
    C, i1, i2 = _invariants(F)
    w1, w2, w11, w12, w22 = law(i1, i2)
    G = i1 * F - _dot(F, C)
    di1 = 2.0 * _ddot(F, dF)
    di2 = 2.0 * _ddot(G, dF)
    dC = _dot(np.swapaxes(dF, 0, 1), F) + _dot(np.swapaxes(F, 0, 1), dF)
    return (2.0 * (w11 * di1 + w12 * di2) * F + 2.0 * w1 * dF + 2.0 * (w12 * di1 + w22 * di2) * G
            + 2.0 * w2 * (di1 * F + i1 * dF - _dot(dF, C) - _dot(F, dC)))


def jacobian(F: np.ndarray) -> np.ndarray:
    """J = det F (...), for the axisymmetric pattern of F."""
    return F[2, 2] * (F[0, 0] * F[1, 1] - F[0, 1] * F[1, 0])


def cofactor(F: np.ndarray) -> np.ndarray:
    """dJ/dF = J F^-T (3, 3, ...), for the axisymmetric pattern of F."""
    out = np.zeros_like(F)
    out[0, 0], out[0, 1] = F[2, 2] * F[1, 1], -F[2, 2] * F[1, 0]
    out[1, 0], out[1, 1] = -F[2, 2] * F[0, 1], F[2, 2] * F[0, 0]
    out[2, 2] = F[0, 0] * F[1, 1] - F[0, 1] * F[1, 0]
    return out


def jacobian_second(F: np.ndarray, A: np.ndarray, B: np.ndarray) -> np.ndarray:
    """d^2 J [A, B] = J (tr(F^-1 A) tr(F^-1 B) - tr(F^-1 A F^-1 B)) (...)."""
    J = jacobian(F)
    inverse = np.swapaxes(cofactor(F), 0, 1) / J
    fa, fb = _dot(inverse, A), _dot(inverse, B)
    return J * (np.einsum("ii...->...", fa) * np.einsum("ii...->...", fb) - _ddot(fa, np.swapaxes(fb, 0, 1)))
