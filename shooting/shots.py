"""Single shots: integrate from the pole (inflation) or from the contact edge
(compression) to the clamp, and turn stored steps into a ``Profile``.

Pressures here are p = P R / (tau T) = ``Law.pressure_factor`` Phat (3 (1 + alpha) Phat for
Mooney-Rivlin); tensions in units of tau T inside (``pocket.shooting.tensions``), of E T in the
returned profile.

Tolerances (``Tolerance``) scale with the pocket: a dome inflated at Phat = 1e-6 is
5e-3 high, encloses 9e-3 and its meridian angle stays below 1e-2, so the absolute
tolerances of the height, the angle and the volume are rtol/100 times the dome's
height (or volume) when that is below 1, and the relative tolerance does the rest.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from pocket.core.states import Profile

from .equations import pole_state
from .integrator import OK, integrate
from .tensions import tensions

__all__ = ["R_POLE", "Tolerance", "edge_state", "profile_from_steps", "shot_edge", "shot_pole", "tension_minima"]

#: Start of the pole series: its error is O(R_POLE^3) in psi and O(R_POLE^4) in the
#: stretches, below the integration tolerance (``tests/test_shooting_equations.py``). It needs no
#: scaling with the pressure: the series is in k r (k the pole curvature), and k ~ sqrt(s) is small
#: in Hencky's regime; at lambda_0 = 18.6 (Phat = 2.37, alpha = 0.1) the pressure p(lambda_0) agrees
#: to 1e-10 for starts at 1e-4, 1e-5 and 1e-6 (measured).
R_POLE = 1e-5

#: Largest step when a profile is stored, so that plots and VTK files of the
#: profile have at least this many points per unit radius.
PROFILE_STEP = 1.0 / 200


#: the meridian angle past which a shot from the contact edge counts as folded: beyond pi it runs
#: below the clamp plane (outside the model, decided by the range end), not into the solver's way
PSI_MAX_EDGE = 1.5 * np.pi


@dataclasses.dataclass(frozen=True)
class Tolerance:
    """The integration tolerances of one pocket: ``rtol``, and ``atol`` per component, shape (5,)."""

    rtol: float
    atol: np.ndarray

    @classmethod
    def scaled(cls, rtol: float, height: float, volume: float) -> Tolerance:
        """rtol, with absolute tolerances rtol/100 times min(1, height) for rho, eta, psi and
        lambda_1 and times min(1, volume) for the volume (module docstring)."""
        h, v = min(1.0, height), min(1.0, volume)
        return cls(rtol, 1e-2 * rtol * np.array([h, h, h, h, v]))


def shot_pole(l0, law, p, tol: Tolerance, store=0):
    """Integrate from the pole with pole stretch l0 (``law`` a ``Law``). Returns (status, y(1), steps)."""
    y0 = pole_state(l0, law, p, R_POLE)
    status, _, y, steps = integrate(y0, R_POLE, law, p, rtol=tol.rtol, atol=tol.atol, store=store,
                                    max_step=PROFILE_STEP if store else np.inf)
    return status, y, steps


def edge_state(lc, a):
    """State at the contact edge r = a: flat (psi = 0), equibiaxial lambda_c, v = 0.

    eta is measured from the plate, so the height is -eta(1).
    """
    return np.array([lc * a, 0.0, 0.0, lc, 0.0])


def shot_edge(lc, a, law, p, tol: Tolerance, store=0):
    """Integrate the free part from the contact edge r = a. Returns (status, y(1), steps).

    The meridian may turn past the horizontal (psi up to PSI_MAX_EDGE): the root finders
    then see a smooth residual across the end of the model's range.
    """
    status, _, y, steps = integrate(edge_state(lc, a), a, law, p, rtol=tol.rtol, atol=tol.atol, store=store,
                                    max_step=PROFILE_STEP if store else np.inf, psi_max=PSI_MAX_EDGE)
    return status, y, steps


def profile_from_steps(steps, law, stretch_centre, *, contact_radius=0.0, n_contact=32):
    """Build a ``Profile`` from integrator steps (columns r, rho, eta, psi, lambda_1, v).

    ``stretch_centre`` is the equibiaxial stretch at r = 0 (lambda_0 or lambda_c).
    For inflation (contact_radius = 0) the pole point r = 0 is prepended. For
    compression the flat contact zone 0 <= r <= a (rho = lambda_c r) is prepended
    with ``n_contact`` points. Heights are shifted so that eta(1) = 0.
    """
    r, rho, eta, l1 = steps[:, 0], steps[:, 1], steps[:, 2], steps[:, 4]
    if contact_radius > 0.0:
        rc = np.linspace(0.0, contact_radius, n_contact, endpoint=False)
        r = np.concatenate([rc, r])
        rho = np.concatenate([stretch_centre * rc, rho])
        eta = np.concatenate([np.zeros_like(rc), eta])
        l1 = np.concatenate([np.full_like(rc, stretch_centre), l1])
        contact = np.concatenate([np.ones(rc.size, bool), np.zeros(steps.shape[0], bool)])
        contact[n_contact] = True  # the edge itself touches the plate
    else:
        r = np.concatenate([[0.0], r])
        rho = np.concatenate([[0.0], rho])
        eta = np.concatenate([[0.0], eta])
        l1 = np.concatenate([[stretch_centre], l1])
        contact = np.zeros(r.size, bool)
    l2 = np.empty_like(r)
    l2[1:] = rho[1:] / r[1:]
    l2[0] = stretch_centre
    t1, t2, _, _ = tensions(l1, l2, law.code, law.params)
    scale = law.tension_scale
    return Profile(
        r=r, rho=rho, eta=eta - eta[-1], stretch_1=l1, stretch_2=l2,
        tension_1=t1 * scale, tension_2=t2 * scale, contact=contact,
    )



#: refinement of an interior tension minimum: the two steps around it are integrated again this much finer
_REFINE = 64


def tension_minima(profile, steps, law, p, tol: Tolerance) -> tuple[float, float]:
    """The smallest T_1 and T_2 of a solved state (units E T): the profile's minima, each refined where it
    lies inside the integrated part (not at its first or last step): the two steps around it are
    integrated again with steps ``_REFINE`` times shorter, and the minimum taken over those points and
    the vertex of the parabola through the smallest of them and its neighbours.
    ``steps`` are the integrator's (the profile's last ``len(steps)`` points), ``p`` its pressure."""
    offset = profile.r.size - steps.shape[0]
    out: list[float] = []
    for tension in (profile.tension_1, profile.tension_2):
        i = int(np.argmin(tension))
        low = float(tension[i])
        k = i - offset
        if 0 < k < steps.shape[0] - 1:
            r0, r1 = steps[k - 1, 0], steps[k + 1, 0]
            status, _, _, fine = integrate(steps[k - 1, 1:], r0, law, p, rtol=tol.rtol, atol=tol.atol,
                                           store=4 * _REFINE, max_step=(r1 - r0) / _REFINE, r_end=r1,
                                           psi_max=PSI_MAX_EDGE)
            if status == OK:
                t = tensions(fine[:, 4], fine[:, 1] / fine[:, 0], law.code, law.params)[len(out)]
                low = min(low, _vertex(fine[:, 0], t) * law.tension_scale)
        out.append(low)
    return out[0], out[1]


def _vertex(r, t) -> float:
    """The smallest of the samples t(r), or below it the vertex of the parabola through the smallest and
    its two neighbours (a sampled minimum is off by O(h^2), the vertex by O(h^3))."""
    j = int(np.argmin(t))
    low = float(t[j])
    if 0 < j < t.size - 1:
        a, b, c = np.polyfit(r[j - 1:j + 2] - r[j], t[j - 1:j + 2] - t[j], 2)
        if a > 0.0:
            low = min(low, float(low + c - b * b / (4.0 * a)))
    return low
