"""The element loops, compiled (numba): the forms of ``kernel``, point by point, and the condensation.

``element_loop`` evaluates, in one pass over the elements and their Gauss
points, the state and the material law (``laws.derivatives``, compiled with the loop: the law's code is a
branch taken the same way at every point), and adds up the residual, its
derivatives with respect to P and to the contact radius a, the penalty
plate's force terms, the volume, and (if asked) every element's tangent
matrix. The formulas are those of ``kernel``'s docstring, in the same
notation; the element layout is ``reference``'s (node a of element e is the
global node p e + a, dofs interleaved rho, eta).

``condense`` eliminates the P2 midpoint dofs element by element and writes
the vertex band (``banded``'s docstring gives the algebra); ``condense_rhs``
and ``expand`` do the same for a right-hand side and back-substitute.

Compiled once per installation and cached outside the package (``pocket.core.compiled``: an edit of
``laws`` makes the cached loops stale): a cold start costs a few seconds, later imports a fraction of
one. Arithmetic follows numpy's rules: a division by zero gives an infinity that the Newton iteration
rejects, not an exception.
"""

from __future__ import annotations

import numpy as np

from pocket.core.compiled import compiled

from . import laws

__all__ = ["condense", "condense_rhs", "element_loop", "expand"]

TWO_PI = 2.0 * np.pi


@compiled
def element_loop(u, vertices, t, wq, phi, dphi, pressure, code, params, height, penalty, multiplier, radius, vectors,
                 matrices, scale=1.0, sphere=False, flat=1):
    """One pass over the elements.

    u: nodal dofs (N,); vertices: physical vertices (n + 1,); t, wq: Gauss points and weights on
    [0, 1] (Q,); phi, dphi: shape functions and t-derivatives there (Q, p + 1); pressure: P;
    code, params: the rubber law (``laws``); height, penalty, multiplier (n, Q): the penalty plate (penalty 0: none);
    radius: the contact radius of the ALE map (0: none, dR/da is then zero), whose first ``flat`` elements
    map onto the contact zone; scale, sphere: the reference surface (``kernel``: S = scale r, and r0 = sin S
    on the sphere, r0 = r on the flat disc, where scale is 1 and every product with it exact). Written over:
    ``vectors`` (4, N) gets R, dR/dP, dR/da, dF/dx; ``matrices`` (n, 2 (p + 1), 2 (p + 1)) the
    element tangents [test dof, trial dof], or has no rows when the tangent is not wanted.

    Returns (dF/dh, F, V, min T_1, min T_2), the tensions T_1 = w_1 / l2, T_2 = w_2 / l1 over the points.
    """
    n = vertices.size - 1
    k = phi.shape[1]
    p = k - 1
    size = 2 * k
    tangent = matrices.shape[0] == n
    vectors[:] = 0.0
    matrices[:] = 0.0
    res, res_p, res_a, force_x = vectors[0], vectors[1], vectors[2], vectors[3]
    scalars = np.array([0.0, 0.0, 0.0, np.inf, np.inf])
    for e in range(n):
        r0, length = vertices[e], vertices[e + 1] - vertices[e]
        first = 2 * p * e
        rate = 0.0  # V' = (dL/da) / L of the ALE map
        if radius > 0.0:
            rate = 1.0 / radius if e < flat else -1.0 / (1.0 - radius)
        for q in range(t.size):
            r = r0 + length * t[q]
            if sphere:
                surface, slope = np.sin(scale * r), scale * np.cos(scale * r)
            else:
                surface, slope = r, 1.0
            rho = eta = drho = deta = 0.0
            for a in range(k):
                rho += phi[q, a] * u[first + 2 * a]
                eta += phi[q, a] * u[first + 2 * a + 1]
                drho += dphi[q, a] * u[first + 2 * a]
                deta += dphi[q, a] * u[first + 2 * a + 1]
            drho /= length
            deta /= length
            norm = np.sqrt(drho * drho + deta * deta)
            l1 = norm / scale
            l2 = rho / surface
            w1, w2, w11, w12, w22 = laws.derivatives(code, params, l1, l2)
            t0, t1 = drho / norm, deta / norm
            scalars[3] = min(scalars[3], w1 / l2)
            scalars[4] = min(scalars[4], w2 / l1)
            weight = wq[q]
            trial = multiplier[e, q] + penalty * (eta - height)
            chi = 1.0 if (penalty > 0.0 and trial > 0.0) else 0.0
            f0 = TWO_PI * w1 * t0 * surface
            f1 = TWO_PI * w1 * t1 * surface + np.pi * pressure * rho * rho
            g0 = TWO_PI * (scale * w2 + pressure * rho * deta)
            g1 = TWO_PI * chi * trial * r
            scalars[1] += weight * length * g1  # F = 2 pi int p_N r dr
            scalars[2] -= np.pi * weight * length * rho * rho * deta  # V
            stiff = TWO_PI * penalty * chi * r
            scalars[0] -= weight * length * stiff  # dF/dh
            if radius > 0.0:
                velocity = r / radius if e < flat else (1.0 - r) / (1.0 - radius)
                common = TWO_PI * ((w1 - l2 * w12) * slope * velocity - w11 * surface * l1 * rate)
                fa0, fa1 = common * t0, common * t1
                ga0 = TWO_PI * scale * ((w2 - l1 * w12) * rate - w22 * l2 * slope / surface * velocity)
            else:
                fa0 = fa1 = ga0 = 0.0
            for a in range(k):
                da, pa = weight * dphi[q, a], weight * length * phi[q, a]
                res[first + 2 * a] += f0 * da + g0 * pa
                res[first + 2 * a + 1] += f1 * da + g1 * pa
                res_p[first + 2 * a] += TWO_PI * rho * deta * pa
                res_p[first + 2 * a + 1] += np.pi * rho * rho * da
                res_a[first + 2 * a] += fa0 * da + ga0 * pa
                res_a[first + 2 * a + 1] += fa1 * da
                force_x[first + 2 * a + 1] += stiff * pa
            if not tangent:
                continue
            along, across = TWO_PI * (w11 - w1 / l1) * surface / scale, TWO_PI * w1 / l1 * surface / scale
            g00, g01, g11 = along * t0 * t0 + across, along * t0 * t1, along * t1 * t1 + across
            m00, m01 = TWO_PI * w12 * t0, TWO_PI * (w12 * t1 + pressure * rho)
            n00, n11 = TWO_PI * (scale * w22 / surface + pressure * deta), stiff
            for a in range(k):  # the upper triangle (b >= a); K is symmetric
                da, pa = dphi[q, a], phi[q, a]
                for b in range(a, k):
                    db, pb = dphi[q, b], phi[q, b]
                    dd = weight * da * db / length
                    dp, pd, pp = weight * da * pb, weight * pa * db, weight * length * pa * pb
                    matrices[e, 2 * a, 2 * b] += g00 * dd + m00 * (dp + pd) + n00 * pp
                    matrices[e, 2 * a, 2 * b + 1] += g01 * dd + m01 * pd
                    matrices[e, 2 * a + 1, 2 * b + 1] += g11 * dd + n11 * pp
                    if b > a:
                        matrices[e, 2 * a + 1, 2 * b] += g01 * dd + m01 * dp
        if tangent:
            for i in range(size):
                for j in range(i):
                    matrices[e, i, j] = matrices[e, j, i]
    return scalars


_VERTEX = (0, 1, 4, 5)


@compiled
def condense(matrices, border_columns, border_rows, band, b_v, c_v, inv, x, y):
    """Static condensation of the P2 midpoint dofs (``banded``'s docstring).

    matrices (n, 6, 6) constrained; border_columns B (N, m); border_rows C (m, N). Written over:
    ``band`` (Nv, 10), the vertex band in gbtrf storage, column j in band[j] (A[i, j] at
    band[j, 6 + i - j]); B_v ``b_v`` (Nv, m); C_v ``c_v`` (m, Nv); K_mm^-1 ``inv`` (n, 2, 2);
    K_mm^-1 K_mv ``x`` (n, 2, 4); K_mm^-1 B_m ``y`` (n, 2, m).
    Returns (regular, the correction to D (m, m)).
    """
    n = matrices.shape[0]
    m = border_columns.shape[1]
    band[:] = 0.0
    b_v[:] = 0.0
    c_v[:] = 0.0
    d = np.zeros((m, m))
    kvm = np.empty((4, 2))
    c_m = np.empty((2, m))
    for e in range(n):
        k = matrices[e]
        a00, a01, a10, a11 = k[2, 2], k[2, 3], k[3, 2], k[3, 3]
        det = a00 * a11 - a01 * a10
        scale = max(abs(a00), abs(a01), abs(a10), abs(a11))
        if not abs(det) > 1e-12 * scale * scale:
            return False, d
        inv[e, 0, 0], inv[e, 0, 1], inv[e, 1, 0], inv[e, 1, 1] = a11 / det, -a01 / det, -a10 / det, a00 / det
        mid = 4 * e + 2
        for i in range(2):
            for j in range(4):
                x[e, i, j] = inv[e, i, 0] * k[2, _VERTEX[j]] + inv[e, i, 1] * k[3, _VERTEX[j]]
            for j in range(m):
                y[e, i, j] = inv[e, i, 0] * border_columns[mid, j] + inv[e, i, 1] * border_columns[mid + 1, j]
                c_m[i, j] = border_rows[j, mid + i]
        for i in range(4):
            kvm[i, 0], kvm[i, 1] = k[_VERTEX[i], 2], k[_VERTEX[i], 3]
        for i in range(4):
            gi = 2 * e + i
            for j in range(4):
                gj = 2 * e + j
                schur = k[_VERTEX[i], _VERTEX[j]] - kvm[i, 0] * x[e, 0, j] - kvm[i, 1] * x[e, 1, j]
                band[gj, 6 + gi - gj] += schur
            for j in range(m):
                b_v[gi, j] -= kvm[i, 0] * y[e, 0, j] + kvm[i, 1] * y[e, 1, j]
                c_v[j, gi] -= c_m[0, j] * x[e, 0, i] + c_m[1, j] * x[e, 1, i]
        for i in range(m):
            for j in range(m):
                d[i, j] -= c_m[0, i] * y[e, 0, j] + c_m[1, i] * y[e, 1, j]
    for g in range(n + 1):
        for c in range(2):
            for j in range(m):
                b_v[2 * g + c, j] += border_columns[4 * g + c, j]
                c_v[j, 2 * g + c] += border_rows[j, 4 * g + c]
    return True, d


@compiled
def condense_rhs(r, s, matrices, border_rows, inv):
    """(r_v, s', z = K_mm^-1 r_m) of the right-hand side (r (N,), s (m,)), with ``condense``'s K_mm^-1."""
    n = inv.shape[0]
    r_v = np.zeros(2 * (n + 1))
    s_out = s.copy()
    z = np.zeros((n, 2))
    for g in range(n + 1):
        r_v[2 * g], r_v[2 * g + 1] = r[4 * g], r[4 * g + 1]
    for e in range(n):
        mid = 4 * e + 2
        z[e, 0] = inv[e, 0, 0] * r[mid] + inv[e, 0, 1] * r[mid + 1]
        z[e, 1] = inv[e, 1, 0] * r[mid] + inv[e, 1, 1] * r[mid + 1]
        for i in range(4):
            r_v[2 * e + i] -= matrices[e, _VERTEX[i], 2] * z[e, 0] + matrices[e, _VERTEX[i], 3] * z[e, 1]
        for j in range(s.size):
            s_out[j] -= border_rows[j, mid] * z[e, 0] + border_rows[j, mid + 1] * z[e, 1]
    return r_v, s_out, z


@compiled
def expand(x_v, y, z, x, ymid):
    """The whole solution (N,) from the vertex one: x_m = z - K_mm^-1 K_mv x_v - K_mm^-1 B_m y."""
    n = z.shape[0]
    out = np.zeros(4 * n + 2)
    for g in range(n + 1):
        out[4 * g], out[4 * g + 1] = x_v[2 * g], x_v[2 * g + 1]
    for e in range(n):
        for i in range(2):
            value = z[e, i]
            for j in range(4):
                value -= x[e, i, j] * x_v[2 * e + j]
            for j in range(y.size):
                value -= ymid[e, i, j] * y[j]
            out[4 * e + 2 + i] = value
    return out
