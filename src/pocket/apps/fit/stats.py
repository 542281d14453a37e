r"""What a fit's data determine: standard errors, correlations, intervals and identifiability warnings.

At the solution x (the scaled unknowns, x_k = coordinate_k / s_k) with residuals r (n of them) and
Jacobian J = dr/dx (n x p), the linearised model gives, for residuals with a common unknown variance
sigma^2 (relative residuals, or residuals in units of the stated uncertainties),

    s^2 = RSS / (n - p),   RSS = r . r,
    Cov(x) = s^2 (J^T J)^-1,   Cov(value) = G Cov(x) G^T,   G = d value / dx

(G = diag(s_k) where each key is its own coordinate, Ogden's: ``pocket.apps.fit.keys``), standard
errors SE_k = sqrt(Cov_kk), correlations Cov_kl / (SE_k SE_l) and linearised 95 % intervals value_k +-
t_{0.975, n-p} SE_k (Student's t: s^2 is estimated from the same n - p degrees of freedom), cut at the
key's bounds (a value outside the admissible set is no rubber); the fit replaces them by profile intervals
where it can (``pocket.apps.fit.intervals``: where the model bends, the linearised interval misses the truth
and leaves the admissible set). (J^T J)^-1 is taken from the SVD of J,
J = U S V^T: (J^T J)^-1 = V S^-2 V^T, each singular value floored at ``_RCOND`` times the largest, so
that a direction the data do not see gets a huge variance, never a zero one (a pseudo-inverse of J^T J
would drop it, and report a parameter the data do not determine with a standard error of 0). mu_0 =
mu_0(values) is reported with its error by the delta method, grad(mu_0)^T Cov grad(mu_0), and its
interval as the keys' linearised ones.

At a bound. A parameter within the fit's Jacobian step (a relative 1e-6, ``pocket.apps.fit.leastsquares``) of a bound
of its admissible set (C1 > 0, Jm > 0, a prestretch >= 1: the keys' ``lower``) sits there: the data pull
it past the bound, the least squares stop at it, and its standard error is of a one-sided fit (it can be
tiny). Each such parameter is a warning saying so.

Identifiability. Non-uniqueness is real for these laws (Ogden, Saccomandi and Sgura, 2004): a
parameter whose SE exceeds |value| is not determined, and two parameters correlated beyond
``CORRELATED`` in magnitude are determined only as a combination. For such a pair (a, b), the
combination determined best is the eigenvector (u_a, u_b) of their covariance in relative units
(Cov / (|a| |b|)) with the smaller eigenvalue lambda: u_a a/|a| + u_b b/|b| has relative error
sqrt(lambda), reported as "a + c b" with c = (u_b / u_a) |a| / |b|. With any such warning the
report adds mu_0 and its error, the combination small-strain data always determine.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.core.materials import Material

__all__ = ["CORRELATED", "LINEARISED", "Statistics", "at_bound", "normal_inverse", "quantile", "statistics"]

#: |correlation| above which two parameters are reported as determined only together
CORRELATED = 0.99
#: the method of the intervals made here, as the report names it
LINEARISED = "linearised"
_LEVEL = 0.95  # the intervals' confidence
_RCOND = 1e-12  # the smallest singular value of J kept, relative to the largest (the solvers' noise is ~1e-10)
_NEAR = 1e-6  # a parameter this close to a bound (relative, as the fit's Jacobian step) sits at it


@dataclasses.dataclass(frozen=True)
class Statistics:
    """A fit's statistics: ``names`` of the p free keys, their ``values``, ``standard_errors``,
    ``covariance`` (p x p), ``correlation`` (p x p) and 95 % ``intervals`` (p x 2), all in the
    material's units; ``mu0`` and ``mu0_error`` (same unit); the residual ``rms``, the degrees of
    freedom ``dof`` = n - p; and the identifiability ``warnings`` (one line each). ``mu0_interval`` is mu_0's
    95 % interval (2,); ``methods`` names how each key's interval was made (``pocket.apps.fit.intervals``)."""

    names: tuple[str, ...]
    values: np.ndarray
    standard_errors: np.ndarray
    covariance: np.ndarray
    correlation: np.ndarray
    intervals: np.ndarray
    mu0: float
    mu0_error: float
    rms: float
    dof: int
    warnings: tuple[str, ...]
    mu0_interval: np.ndarray
    methods: tuple[str, ...]


def quantile(dof: int) -> float:
    """t_{0.975, dof}, Student's t quantile of the 95 % intervals."""
    from scipy.special import stdtrit  # scipy.stats would add a second to a fit's start

    return float(stdtrit(dof, 0.5 + 0.5 * _LEVEL))


def normal_inverse(jac) -> np.ndarray:
    """(J^T J)^-1 (p x p) of the Jacobian ``jac`` (n x p) from its SVD, singular values floored (module
    docstring)."""
    _, singular, vt = np.linalg.svd(jac, full_matrices=False)
    singular = np.maximum(singular, _RCOND * max(float(singular[0]), np.finfo(float).tiny))
    return (vt.T / singular**2) @ vt


def at_bound(key, value: float, mu0: float) -> bool:
    """Whether ``key`` at ``value`` sits at a bound of its admissible set (module docstring; ``mu0`` > 0 in the
    unit of the key's stress)."""
    near = _NEAR * (mu0 if key.unit == "stress" else max(abs(value), 1.0))
    return any(math.isfinite(b) and abs(value - b) <= near for b in (key.lower, key.upper))


def statistics(setup, material: Material, free, gradient, r, jac) -> Statistics:
    """The statistics (module docstring) of ``material``, the fit of keys ``free`` at scaled unknowns x with
    residuals ``r`` (n,), Jacobian ``jac`` = dr/dx (n x p) and ``gradient`` G = d(key values)/dx (p x p)."""
    n, p = jac.shape
    dof = n - p
    s2 = float(r @ r) / dof
    cov = gradient @ (s2 * normal_inverse(jac)) @ gradient.T
    se = np.sqrt(np.maximum(np.diag(cov), 0.0))
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = np.where(np.outer(se, se) > 0.0, cov / np.outer(se, se), 0.0)
    np.fill_diagonal(corr, 1.0)
    values = np.array([k.get(material) for k in free])
    t = quantile(dof)
    lower, upper = np.array([k.lower for k in free]), np.array([k.upper for k in free])
    intervals = np.clip(np.stack([values - t * se, values + t * se], axis=1), lower[:, None], upper[:, None])
    steps = [1e-6 * max(abs(v), abs(material.mu0) if k.unit == "stress" else 1.0)
             for k, v in zip(free, values, strict=True)]
    grad = np.array([(k.put(material, v + h).mu0 - material.mu0) / h
                     for k, v, h in zip(free, values, steps, strict=True)])
    mu0_error = math.sqrt(max(float(grad @ cov @ grad), 0.0))
    names = tuple(k.name for k in free)
    warnings = _at_bounds(free, values, se, abs(material.mu0)) + _warnings(names, values, se, cov, corr)
    if warnings:
        warnings.append(f"what the data do determine: mu_0 = {material.mu0:.6g} +- {mu0_error:.2g}"
                        f"{'' if setup.thickness else ' (times T, N/m)'}, the small-strain shear modulus")
    return Statistics(names, values, se, cov, corr, intervals, material.mu0, mu0_error, math.sqrt(float(r @ r) / n),
                      dof, tuple(warnings), np.array([material.mu0 - t * mu0_error, material.mu0 + t * mu0_error]),
                      (LINEARISED,) * p)


def _at_bounds(free, values, se, mu0: float) -> list[str]:
    """A warning for each parameter that sits at a bound of its admissible set (module docstring)."""
    out = []
    for key, v, e in zip(free, values, se, strict=True):
        if at_bound(key, v, mu0):
            bound = min((key.lower, key.upper), key=lambda b: abs(v - b))
            out.append(f"{key.name} = {v:.6g} +- {e:.2g} sits at {bound:g}, a bound of its admissible set: the "
                       "data pull it there and the fit stops at it, so its standard error is of a one-sided fit "
                       "and its interval is cut at the bound")
    return out


def _warnings(names, values, se, cov, corr) -> list[str]:
    out = [f"{name} = {v:.6g} +- {e:.2g}: the data do not determine it (its standard error exceeds its value)"
           for name, v, e in zip(names, values, se, strict=True) if e > abs(v)]
    for i in range(len(names)):
        for j in range(i + 1, len(names)):
            if abs(corr[i, j]) > CORRELATED:
                a, b = abs(values[i]), abs(values[j])
                if a == 0.0 or b == 0.0:
                    continue
                rel = cov[np.ix_([i, j], [i, j])] / np.outer([a, b], [a, b])
                lam, vec = np.linalg.eigh(rel)
                ua, ub = vec[:, 0]
                combination = f"{names[i]} {'+' if ub / ua >= 0 else '-'} {abs(ub / ua) * a / b:.4g} {names[j]}"
                out.append(f"{names[i]} and {names[j]} are correlated (r = {corr[i, j]:+.4f}): the data determine "
                           f"{combination} (to {math.sqrt(max(lam[0], 0.0)):.2g} relative), not each")
    return out
