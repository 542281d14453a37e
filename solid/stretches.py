r"""The Ogden rubber's energy derivatives through the isochoric principal stretches.

The Ogden energy is a sum over the principal stretches, not a function of I1 and I2, so the solid
evaluates it at the isochoric stretches lb_i = J^(-1/3) l_i (the volume is the constraint's alone,
as for the invariant laws: ``kinematics``):

    W = sum_p (mu_p / a_p) (J^(-a_p/3) S_p - 3),    S_p = l1^a_p + l2^a_p + l3^a_p.

Stretches. F is block diagonal: the in-plane block F2 (2x2) and the hoop stretch l3 = F_33 > 0.
The squares l1^2, l2^2 are the eigenvalues c1, c2 of the in-plane block of C, M = F2^T F2, so with
g(c) = c^(a/2) (one term; the index p dropped),

    S = G(M) + F_33^a,    G(M) = g(c1) + g(c2) = tr g(M),

an isotropic function of the symmetric M. With M = sum_k c_k n_k n_k^T (orthonormal n_k) and
X_kl = n_k^T X n_l, its derivatives are the classical ones of a spectral function,

    dG[X] = Q : X,   Q = g'(M) = sum_k g'(c_k) n_k n_k^T,
    d^2 G[X, Y] = g''(c1) X_11 Y_11 + g''(c2) X_22 Y_22 + 2 D X_12 Y_12,   D = (g'(c1) - g'(c2)) / (c1 - c2),

(check: g = c^2/2 gives X : Y). At c1 = c2, which is where every solve starts (F = I) and nearly
where thin regions stay, D is a removable 0/0 with limit g''(c1) and n_k are any orthonormal pair;
the form is then g'' X : Y whatever the pair. It stays accurate near the degeneracy because D is
evaluated without cancellation: with g'(c) = (a/2) c^b, b = a/2 - 1, and r = ln(c1/c2),

    D = (a/2) c2^(b-1) expm1(b r) / expm1(r)     (-> (a/2) b c2^(b-1) = g''(c2) as r -> 0),

a ratio of two accurately computed small numbers, taken as b at r = 0; and an eigenvector pair off
by an angle e changes the form by O(e |c1 - c2|), which is small exactly where e may be large.

Chain to F's components. dM[A] = A2^T F2 + F2^T A2 and d^2 M[A, B] = A2^T B2 + B2^T A2, so for the
unit components E_a = e_i e_j^T of the block (Q symmetric), with m_k = F2 n_k:

    dG[E_a] = 2 (F2 Q)_{ij},   Q : d^2 M[E_a, E_b] = 2 delta(i_a, i_b) Q_{j_a j_b},
    (dM[E_a])_kl = n_k[j] m_l[i] + m_k[i] n_l[j],

and the hoop component gives d(F_33^a) = a F_33^(a-1), d^2 = a (a-1) F_33^(a-2). Finally, with
j = ln J (``kinematics``: dj, d^2 j) and c = a/3, as for an isochoric invariant,

    dW = (mu/a) J^-c (dS - c S dj),
    d^2 W = (mu/a) J^-c (d^2 S - c (dS dj + dj dS) - c S d^2 j + c^2 S dj dj).

A test compares both with finite differences of W at random F, at F = I and where l1 = l2 to 1e-8 and
1e-12 (where the plain quotient (g'(c1) - g'(c2)) / (c1 - c2) has lost four digits).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from . import kinematics as kin

__all__ = ["Ogden"]

#: the in-plane components' (row, column) indices among the five, and the (4, 4) mask of equal rows
_PLANE_INDEX = (np.array([i for i, _ in kin.COMPONENTS[:4]]), np.array([j for _, j in kin.COMPONENTS[:4]]))
_SAME_ROW = (_PLANE_INDEX[0][:, None] == _PLANE_INDEX[0][None, :]).astype(float)


def _spectrum(F2: np.ndarray):
    """Eigenvalues c (2, ...) and orthonormal eigenvectors n (2 components, 2 vectors, ...) of F2^T F2."""
    M = np.einsum("ki...,kj...->...ij", F2, F2)
    c, n = np.linalg.eigh(M)
    return np.moveaxis(c, -1, 0), np.moveaxis(n, (-2, -1), (0, 1))


def _divided_difference(a: float, c: np.ndarray) -> np.ndarray:
    """D = (g'(c1) - g'(c2)) / (c1 - c2) for g = c^(a/2), without cancellation (module docstring)."""
    b = 0.5 * a - 1.0
    with np.errstate(invalid="ignore", divide="ignore"):  # 0/0 at r = 0, replaced by its limit
        r = np.log(c[0] / c[1])
        ratio = np.where(r == 0.0, b, np.expm1(b * r) / np.expm1(r))
    return 0.5 * a * c[1] ** (b - 1.0) * ratio


def _stretch_sum(a: float, F: np.ndarray, c, n, X):
    """S = l1^a + l2^a + l3^a (...), dS (5, ...) and d^2 S (5, 5, ...) in the components; c, n the spectrum of
    M and X (4, 3, ...) the in-plane components' (dM[E_a])_kl for kl = 11, 22, 12."""
    F2, hoop = F[:2, :2], F[2, 2]
    b = 0.5 * a
    g, g1, g2 = c**b, b * c ** (b - 1.0), b * (b - 1.0) * c ** (b - 2.0)  # g, g', g'' at c1, c2
    Q = np.einsum("k...,ik...,jk...->ij...", g1, n, n)
    rows, cols = _PLANE_INDEX
    weights = np.array([g2[0], g2[1], 2.0 * _divided_difference(a, c)])
    dS, d2S = np.zeros((5, *hoop.shape)), np.zeros((5, 5, *hoop.shape))
    dS[:4] = 2.0 * np.einsum("ik...,kj...->ij...", F2, Q)[rows, cols]
    d2S[:4, :4] = (np.einsum("k...,ak...,bk...->ab...", weights, X, X)
                   + 2.0 * _SAME_ROW.reshape((4, 4) + (1,) * hoop.ndim) * Q[cols[:, None], cols[None, :]])
    dS[4] = a * hoop ** (a - 1.0)
    d2S[4, 4] = a * (a - 1.0) * hoop ** (a - 2.0)
    return np.sum(g, axis=0) + hoop**a, dS, d2S


@dataclasses.dataclass(frozen=True)
class Ogden:
    """The Ogden rubber of stresses ``mu`` (units of mu_0) and ``exponents`` (one per term), as the solid's
    law: ``kinematics.energy_derivatives`` calls its ``energy_derivatives``."""

    mu: tuple[float, ...]
    exponents: tuple[float, ...]

    def energy_derivatives(self, F: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """dW (5, ...) and d^2 W (5, 5, ...) at F (3, 3, ...), in the components (module docstring)."""
        c, n = _spectrum(F[:2, :2])
        m = np.einsum("ik...,kl...->il...", F[:2, :2], n)  # m[:, k] = F2 n_k
        rows, cols = _PLANE_INDEX
        n_j, m_i = n[cols], m[rows]  # (4, 2, ...): n_k[j_a], m_k[i_a]
        X = np.stack([2.0 * n_j[:, 0] * m_i[:, 0], 2.0 * n_j[:, 1] * m_i[:, 1],
                      n_j[:, 0] * m_i[:, 1] + m_i[:, 0] * n_j[:, 1]], axis=1)
        J = kin.jacobian(F)
        dj, d2j = kin.log_jacobian_derivatives(F)
        djdj = dj[:, None] * dj[None, :]
        first, second = np.zeros_like(dj), np.zeros_like(d2j)
        # J <= 0 or a singular in-plane block (an inverted iterate): NaN, which Newton refuses
        with np.errstate(invalid="ignore", divide="ignore"):
            for mu, a in zip(self.mu, self.exponents, strict=True):
                S, dS, d2S = _stretch_sum(a, F, c, n, X)
                k, w = a / 3.0, mu / a * J ** (-a / 3.0)
                first = first + w * (dS - k * S * dj)
                second = second + w * (d2S - k * (dS[:, None] * dj[None, :] + dj[:, None] * dS[None, :])
                                       - k * S * d2j + k * k * S * djdj)
        return first, second
