r"""Axisymmetric kinematics and the rubber's energy derivatives through the isochoric invariants.

Coordinates (r, z) of the flat sheet's cross-section, in units of R; the displacement
u = (u_r, u_z)(r, z). The deformation gradient in the cylindrical basis is

        [ 1 + du_r/dr    du_r/dz       0         ]
    F = [ du_z/dr        1 + du_z/dz   0         ],      J = det F = F_33 (F_11 F_22 - F_12 F_21),
        [ 0              0             1 + u_r/r ]

and a variation du gives dF of the same pattern without the identity (dF_33 = du_r / r): five
components a = (i, j) in ``COMPONENTS``, each the unit matrix E_a = e_i e_j^T.

Energy. The rubber's W(I1, I2) is evaluated at the isochoric invariants of C = F^T F,

    Ib1 = J^(-2/3) I1,   Ib2 = J^(-4/3) I2,   I1 = F : F,   I2 = (I1^2 - C : C) / 2,

which equal I1, I2 at J = 1 (so W is the law's energy there) and do not change under a change of
volume: the volume is the constraint's alone (the weak forms, ``assembly``). Evaluated at I1, I2
instead, W would have a concave volumetric part (3 C1 (J^(2/3) - 1) under F = s I), which Taylor-Hood's
constraint, J = 1 only against bilinear pressures, does not control at the clamp's singular
corners: elements there folded and Newton stalled. The Ogden law, a function of the principal
stretches, is evaluated at the isochoric stretches J^(-1/3) l_i for the same reason (``stretches``).

Derivatives, with j = ln J (dj[A] = tr(F^-1 A), d^2 j[A, B] = -tr(F^-1 B F^-1 A)) and
dC[A] = A^T F + F^T A:

    dI1[A] = 2 F : A,                    d^2 I1[A, B] = 2 A : B,
    dI2[A] = 2 (I1 F - F C) : A,         d^2 I2[A, B] = dI1[A] dI1[B] + 2 I1 A : B - dC[A] : dC[B]
                                                        - C : (A^T B + B^T A),
    Ib = J^(-c) I (c = 2/3 for I1, 4/3 for I2):
    dIb[A] = J^(-c) (dI[A] - c I dj[A]),
    d^2 Ib[A, B] = J^(-c) (d^2 I[A, B] - c (dI[A] dj[B] + dI[B] dj[A]) - c I d^2 j[A, B] + c^2 I dj[A] dj[B]),

    dW[A] = W_1 dIb1[A] + W_2 dIb2[A],
    d^2 W[A, B] = W_1 d^2 Ib1 + W_2 d^2 Ib2 + W_11 dIb1 dIb1 + W_12 (dIb1[A] dIb2[B] + dIb2[A] dIb1[B])
                  + W_22 dIb2 dIb2,

and for the constraint dJ[A] = J dj[A] (cof F = J F^-T), d^2 J[A, B] = J (dj[A] dj[B] + d^2 j[A, B]).
For the unit components: (A^T B)_{kl} = delta(i_a, i_b) delta(k, j_a) delta(l, j_b), so
C : (A^T B + B^T A) = 2 delta(i_a, i_b) C_{j_a j_b}, d^2 j[E_a, E_b] = -Finv_{j_a i_b} Finv_{j_b i_a}, and
with dC[E_a] = E_a^T F + F^T E_a, (E_a^T F) : (E_b^T F) = delta(j_a, j_b) (F F^T)_{i_a i_b} and
(E_a^T F) : (F^T E_b) = F_{i_a j_b} F_{i_b j_a}, so dC[E_a] : dC[E_b] = 2 delta(j_a, j_b) (F F^T)_{i_a i_b}
+ 2 F_{i_a j_b} F_{i_b j_a}.

Every array has its tensor or component indices first, then the quadrature points' shape.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "COMPONENTS",
    "cofactor",
    "components",
    "energy_derivatives",
    "gradient",
    "jacobian",
    "jacobian_derivatives",
    "log_jacobian_derivatives",
    "tensor",
    "variation",
]

#: the nonzero components (i, j) of an axisymmetric F or dF
COMPONENTS = ((0, 0), (0, 1), (1, 0), (1, 1), (2, 2))


def _tensor(grad: np.ndarray, hoop: np.ndarray, identity: float) -> np.ndarray:
    out = np.zeros((3, 3, *hoop.shape))
    out[:2, :2] = grad
    out[2, 2] = hoop
    for k in range(3):
        out[k, k] += identity
    return out


def tensor(components: np.ndarray, identity: float) -> np.ndarray:
    """identity I + sum_a components[a] E_a (3, 3, ...) from the five components (5, ...): F from those of
    the displacement's gradient (identity 1), dF from a variation's (identity 0)."""
    return _tensor(components[:4].reshape((2, 2, *components.shape[1:])), components[4], identity)


def gradient(grad: np.ndarray, u_r: np.ndarray, r: np.ndarray) -> np.ndarray:
    """F (3, 3, ...) from the displacement's in-plane gradient ``grad`` (2, 2, ...; grad[i, j] = du_i/dx_j),
    its radial component ``u_r`` and the radius ``r`` (> 0, the quadrature points')."""
    return _tensor(grad, u_r / r, 1.0)


def variation(grad: np.ndarray, u_r: np.ndarray, r: np.ndarray) -> np.ndarray:
    """dF (3, 3, ...) of a displacement variation, as ``gradient`` without the identity."""
    return _tensor(grad, u_r / r, 0.0)


def field_components(field, r) -> np.ndarray:
    """The five components (5, ...) of dF of a vector field (a scikit-fem DiscreteField) at radius r."""
    g = field.grad
    return np.array([g[0, 0], g[0, 1], g[1, 0], g[1, 1], field[0] / r])


def components(T: np.ndarray) -> np.ndarray:
    """The five components (5, ...) of an axisymmetric (3, 3, ...) tensor."""
    return np.array([T[i, j] for i, j in COMPONENTS])


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


def log_jacobian_derivatives(F: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """dj (5, ...) and d^2 j (5, 5, ...) of j = ln J, in the components."""
    inverse = np.swapaxes(cofactor(F), 0, 1) / jacobian(F)
    dj = np.array([inverse[j, i] for i, j in COMPONENTS])
    d2j = np.array([[-inverse[ja, ib] * inverse[jb, ia] for ib, jb in COMPONENTS] for ia, ja in COMPONENTS])
    return dj, d2j


def jacobian_derivatives(F: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """dJ (5, ...) and d^2 J (5, 5, ...) in the components."""
    J = jacobian(F)
    dj, d2j = log_jacobian_derivatives(F)
    return J * dj, J * (dj[:, None] * dj[None, :] + d2j)


def energy_derivatives(F: np.ndarray, law) -> tuple[np.ndarray, np.ndarray]:
    """dW (5, ...) and d^2 W (5, 5, ...) of W(Ib1, Ib2) at F, in the components; ``law`` is
    (I1, I2) -> (W_1, W_2, W_11, W_12, W_22) (``laws.derivatives``), or a law of the principal stretches
    (``stretches.Ogden``), which has its own ``energy_derivatives(F)``.

    With s_k = J^(-c_k) and the chain rule of the module docstring gathered by term, d^2 W is
    sum_k W_k s_k (d^2 I_k - c_k (dI_k dj + dj dI_k) - c_k I_k d^2 j + c_k^2 I_k dj dj) + sum_kl W_kl dIb_k dIb_l:
    five products of (5, 5) arrays instead of one chain per invariant (the W_kl terms skipped where zero)."""
    if hasattr(law, "energy_derivatives"):
        return law.energy_derivatives(F)
    C = np.einsum("ki...,kj...->ij...", F, F)
    i1 = np.einsum("ij...,ij...->...", F, F)
    i2 = 0.5 * (i1**2 - np.einsum("ij...,ij...->...", C, C))
    FC = np.einsum("ik...,kj...->ij...", F, C)
    rows, cols = _INDEX
    same_row, same_column, eye = (m.reshape((5, 5) + (1,) * i1.ndim) for m in (_SAME_ROW, _SAME_COLUMN, _EYE))
    d_i1 = 2.0 * F[rows, cols]
    d_i2 = 2.0 * (i1 * F[rows, cols] - FC[rows, cols])
    # dC[E_a] : dC[E_b] = 2 delta(j_a, j_b) (F F^T)_{i_a i_b} + 2 F_{i_a j_b} F_{i_b j_a}
    B = np.einsum("ik...,jk...->ij...", F, F)
    dc_dc = 2.0 * same_column * B[rows[:, None], rows[None, :]] + 2.0 * F[rows[:, None], cols[None, :]] * F[
        rows[None, :], cols[:, None]]
    c_pairs = C[cols[:, None], cols[None, :]]
    d2_i2 = d_i1[:, None] * d_i1[None, :] + 2.0 * i1 * eye - dc_dc - 2.0 * same_row * c_pairs
    J = jacobian(F)
    dj, d2j = log_jacobian_derivatives(F)
    with np.errstate(invalid="ignore"):  # J <= 0 (an inverted iterate): NaN, which Newton refuses
        s1, s2 = J ** (-2.0 / 3.0), J ** (-4.0 / 3.0)
    c1, c2 = 2.0 / 3.0, 4.0 / 3.0
    db1, db2 = s1 * (d_i1 - c1 * i1 * dj), s2 * (d_i2 - c2 * i2 * dj)
    w1, w2, w11, w12, w22 = law(s1 * i1, s2 * i2)
    first = w1 * db1 + w2 * db2
    a1, a2 = w1 * s1, w2 * s2
    mixed = -(a1 * c1 * d_i1 + a2 * c2 * d_i2)  # the dI_k dj terms
    second = (2.0 * a1 * eye + a2 * d2_i2 + mixed[:, None] * dj[None, :] + dj[:, None] * mixed[None, :]
              - (a1 * c1 * i1 + a2 * c2 * i2) * d2j
              + (a1 * c1 * c1 * i1 + a2 * c2 * c2 * i2) * dj[:, None] * dj[None, :])
    for w, x, y in ((w11, db1, db1), (w12, db1, db2), (w12, db2, db1), (w22, db2, db2)):
        if np.any(w):
            second = second + w * x[:, None] * y[None, :]
    return first, second


#: the components' (row, column) indices as arrays, and the (5, 5) masks of equal rows, equal columns, a = b
_INDEX = (np.array([i for i, _ in COMPONENTS]), np.array([j for _, j in COMPONENTS]))
_SAME_ROW = (_INDEX[0][:, None] == _INDEX[0][None, :]).astype(float)
_SAME_COLUMN = (_INDEX[1][:, None] == _INDEX[1][None, :]).astype(float)
_EYE = np.eye(5)
