"""Step 1, inflation: find the pole stretch lambda_0 = 1 + s such that lambda_2(1) = 1.

The first branch. A shot from the pole with strain s at pressure p lands at
rho(1) = 1 + m(s, p). At fixed s, m falls as p rises from m(s, 0) = s > 0 (the
flat sheet); p(s), the pressure with m = 0, is the pressure that holds the dome
of pole strain s. The first branch is the curve p(s) followed continuously from
s = 0, where the small-strain (Hencky) regime gives Phat ~ 4 sqrt(6) s^1.5 for every law
(``pocket.core.smallstrain``; p = ``Law.pressure_factor`` Phat, 3 (1 + alpha) Phat for
Mooney-Rivlin). Following it matters: a root of m found by marching s at the target pressure
can skip over a maximum of p(s), or land on another branch.

Pressure control (the paper's step 1). s is marched up by a factor 1.4 from
below the small-strain estimate, computing p(s) at each step from a power-law
prediction through the last two points (a bracket grown around the prediction,
then Brent's method: about 7 shots each), until p(s) passes the target. The pole
strain is then the root of m(s, p_target) in the last step, by Brent's method
relative to s (so Phat = 1e-6, s ~ 2e-5, is resolved as well as Phat = 1), and
checked to lie on p(s). In all, 35 to 90 shots (the paper's silicone at Phat = 0.31:
48; the fixed-pressure bisections used before took 123). If
p(s) falls first, the first branch has a maximum (alpha near 0 or below):
golden sections locate it, and above it no first-branch state exists
(``OutOfRangeError`` naming the maximum). For alpha < 0 the pole tension
(1 - l^-6)(1 + alpha l^2) vanishes at l^2 = -1/alpha: p(s) exists only below, and
the maximum lies there. A march that starts past a maximum (a target far above
it) is restarted lower. A maximum can hide inside one step, with the minimum after it: for Mooney-Rivlin
alpha from 0.0547 to 0.05544, p(s) has a dip so shallow and narrow (alpha = 0.05542: 1.4e-9 of p deep, over
3% of s) that the points on either side of it both rise. The slope d log p / d log s of the step over it is then
about 0, so a step of slope below ``_FLAT`` is marched in ``_SUBSTEPS`` smaller steps, and its least slope is
located by golden sections on the slope over 1e-4 of s: a negative one is a fall, and the maximum before it is
located as above. Without that the march passes the dip and returns a state of the second rising branch. The
marches end at the pole stretch ``STRETCH_LIMIT`` (``pocket.core.errors``, the reason there): a target not reached
by it is an OutOfRangeError, the one the finite-element solver gives. A rubber that locks (Gent: I1 - 3 < Jm)
has a largest pole stretch: the march halves its way to it instead of stepping past it, and a pressure or
volume not reached before it is an OutOfRangeError naming that stretch.

A prestretched sheet (``Law.prestretch`` > 1) is taut before any pressure: at small pressure it is a
membrane under the uniform tension N_0 of its prestretch (``Law.flat_tension``), the paraboloid
eta = Phat (1 - r^2) / (4 n_0) (n_0 = N_0 / (E T), lengths in R), whose pole strain is second order in
its height. Linear in-plane elasticity about the prestressed sheet, with the radial displacement
u = A r + B r^3 driven by the slope (eta')^2 / 2 = 2 H^2 r^2 and u(1) = 0, gives
s = A = (3 - nu) H^2 / 4 (nu the ratio of the incremental stiffnesses, 0 to 1/2): the marches
start from s = 0.7 H^2 (``_taut_strain``) where it lies below Hencky's estimate, and the pressure
of a stretch is guessed as the larger of the two estimates. Only starting points: each root is the
solver's own. Without prestretch the estimates are Hencky's alone, unchanged. The strain of a taut sheet
is small (5e-6 at Phat = 1e-3, lambda_p = 1.05) and rho(1) = 1 + O(s) resolves it only to the integration's
error (~ 1e-2 rtol), so the check that a root lies on the first branch allows p(s) a relative drift of
rtol / s more there; the state itself (its tensions, height, volume) is resolved to the tolerance.

Volume control (``inflate_volume``) marches V(s) on the first branch the same way;
the volume grows through pressure maxima, so it reaches states pressure control
cannot.

Below the first-branch root, at the target pressure, the pressure is too high
for the stretch: the meridian lands inside the clamp or curls back before
reaching it (the shot stops: axis, fold, vanishing tension). Only inside such a
bracket is a shot that stops early read as "too much pressure for this stretch".
A shot that fails for numerical reasons (too many steps) is a ConvergenceError,
and so is a final shot that does not land on the clamp.

The reference surface is the flat disc clamped at r = R (``pocket.core.geometries``, the only one in
``GEOMETRIES``): the shots run from the pole S = 0 to the clamp S = 1 with the arc length S for the
reference radius, and the final shot's landing is checked against the clamp's radius; each state carries
the surface it was solved on.
"""

from __future__ import annotations

import dataclasses
import itertools
import math

from pocket.core import smallstrain
from pocket.core.errors import (
    STRETCH_LIMIT,
    ConvergenceError,
    InputError,
    OutOfRangeError,
    above_pressure_maximum,
    past_stretch_limit,
)
from pocket.core.geometries import Geometry, Symmetry, clamp_of, posed
from pocket.core.inputs import check_non_negative, check_positive, check_volume
from pocket.core.materials import as_material
from pocket.core.solver import GeometryLike, MaterialLike, Numbers, Progress
from pocket.core.states import InflatedState

from . import brent
from .capsule import capsule_pressure, inflate_capsule
from .integrator import OK, STATUS, STEPS
from .laws import as_law, law_of
from .shots import Tolerance, profile_from_steps, shot_pole, tension_minima
from .tensions import inside, tensions

__all__ = ["GEOMETRIES", "inflate", "inflate_volume", "inflation_curve", "pressure_of_stretch"]

#: reference surface -> how this solver poses it (``pocket.core.geometries``)
GEOMETRIES = {"pocket": "the membrane equations shot from the pole to the clamp at S = 1, r0 = S",
              "capsule": "the sphere's closed form, checked by a shot from the pole to the equator at S = pi / 2, "
                         "r0 = sin S (pocket.shooting.capsule)"}

_GROWTH = 1.4  # ratio of successive s = lambda_0 - 1 in the marches
_S_MAX = STRETCH_LIMIT - 1.0  # s at which the marches stop (``pocket.core.errors.STRETCH_LIMIT``)
#: a march step whose slope d log p / d log s is below this is searched for a maximum inside it: the slope is
#: 1.5 at small strain and about 1 at large stretch, and it changes by at most 0.2 a step on the branches computed;
#: a maximum with a minimum after it inside one step (a neo-Hookean-like dip) makes the step's slope about 0
_FLAT = 0.1
_SUBSTEPS = 8  # the points computed inside such a step
_SLOPE_STEP = 1e-4  # the relative step in s of the slope where it is least
_S_RTOL = 1e-13  # relative accuracy of the root in s
_P_RTOL = 1e-14  # relative accuracy of the pressure p(s) where its value matters
_MARCH_RTOL = 1e-9  # ... and where only its trend matters (the march)
_PEAK_RTOL = 1e-9  # relative width in s to which a pressure maximum is located (its value to ~1e-18)
_LOCK_RTOL = 1e-9  # relative distance to a locking strain at which a march gives up
_P_CAP = 1e6  # largest pressure p tried for one pole stretch (Phat ~ 3e5; 1e6 is already no rubber pocket)


_TAUT = 0.7  # s / H^2 of a taut membrane at small pressure, (3 - nu) / 4 (module docstring)


def _taut_strain(law, height):
    """The pole strain of the taut (prestretched) membrane of pole height H / R = ``height``, inf without
    prestretch (no taut regime)."""
    return math.inf if law.prestretch == 1.0 else _TAUT * height * height


def _strain_of_pressure(law, phat):
    """An estimate of the pole strain at Phat: Hencky's, or the taut membrane's H = Phat / (4 n_0) if less."""
    hencky = smallstrain.pole_strain(phat)
    if law.prestretch == 1.0:
        return hencky
    return min(hencky, _taut_strain(law, phat / (4.0 * law.flat_tension)))


def _pressure_of_strain(law, s):
    """An estimate of Phat at pole strain s: Hencky's, or the taut membrane's 4 n_0 sqrt(s / 0.7) if more."""
    hencky = smallstrain.pressure_of_strain(s)
    if law.prestretch == 1.0:
        return hencky
    return max(hencky, 4.0 * law.flat_tension * math.sqrt(s / _TAUT))


def _tolerance(rtol, strain):
    """Integration tolerances for a dome of pole strain ~ ``strain`` (``Tolerance.scaled``)."""
    return Tolerance.scaled(rtol, smallstrain.height_of_strain(strain), smallstrain.volume_of_strain(strain))


def _landing(s, law, p, tol, what):
    """rho(1) - 1 of the shot from pole strain s at pressure p, or None if it stops before the clamp."""
    status, y, _ = shot_pole(1.0 + s, law, p, tol)
    if status == STEPS:
        raise ConvergenceError(f"inflation ({what}): the shot from lambda_0 = {1 + s:.12g} took too many steps",
                               load=1.0 + s)
    return y[0] - 1.0 if status == OK else None


def _signed(value):
    """A landing as a sign for bracketing: a shot that stopped early had too much pressure (-1)."""
    return -1.0 if value is None else value


def pressure_of_stretch(l0, law, *, rtol=1e-10, tol=None, guess=None, accuracy=_P_RTOL) -> float | None:
    """The pressure p (units tau T / R, ``pocket.shooting.tensions``; 2 C1 T / R for a Mooney-Rivlin
    alpha) at which the shot from pole stretch ``l0`` lands on rho(1) = 1, to relative ``accuracy``: the
    root of m(s, .) nearest above or below ``guess`` (default: the small-strain pressure). ``law``: a
    ``Law``, a Mooney-Rivlin alpha or a ``Material``. None if there is none: where the pole tension
    vanishes (for alpha < 0 past l0^2 = -1/alpha) or the pole is past the law's locking stretch.
    Infinite for a locking rubber when no p up to ``_P_CAP`` closes the shot: p(s) diverges as the
    pole approaches the locking stretch.
    """
    law = as_law(law)
    s = l0 - 1.0
    tol = _tolerance(rtol, s) if tol is None else tol
    if not (s > 0.0 and inside(l0, l0, law.code, law.params) and tensions(l0, l0, law.code, law.params)[0] > 0.0):
        return None
    what = f"p(lambda_0 = {l0:.12g})"

    def miss(p):
        return _signed(_landing(s, law, p, tol, what))

    p = law.pressure_factor * _pressure_of_strain(law, s) if guess is None else guess
    f, width = miss(p), 0.02 * p
    if f >= 0.0:  # grow a bracket upward from the guess
        lo, f_lo = p, f
        hi, f_hi = p + width, miss(p + width)
        while f_hi >= 0.0:
            width *= 4.0
            lo, f_lo, hi = hi, f_hi, hi + width
            if hi > _P_CAP:
                if law.stretch_limit < math.inf:  # a locking rubber: p(s) diverges at its locking stretch
                    return math.inf
                raise ConvergenceError(f"inflation: no pressure up to 1e6 closes the shot from lambda_0 = {l0!r}",
                                       load=l0)
            f_hi = miss(hi)
    else:  # downward: m(s, 0) = s > 0
        hi, f_hi = p, f
        lo = max(p - width, 0.0)
        f_lo = s if lo == 0.0 else miss(lo)
        while f_lo < 0.0:
            width *= 4.0
            hi, f_hi, lo = lo, f_lo, max(lo - width, 0.0)
            f_lo = s if lo == 0.0 else miss(lo)
    return brent.root(miss, lo, hi, fa=f_lo, fb=f_hi, rtol=accuracy)


class _Branch:
    """The first branch p(s) of one pocket, computed point by point; each pressure is predicted by
    the power law through the two points computed nearest to it (p ~ s^1.5 at first)."""

    def __init__(self, law, tol):
        self.law, self.tol, self.points = law, tol, []
        self.known: dict[float, tuple[float | None, bool]] = {}  # s -> (p(s), computed precisely)

    def pressure(self, s, precise=False):
        if s in self.known and (self.known[s][1] or not precise):  # a curve's next march starts where one ended
            return self.known[s][0]
        near = sorted(self.points, key=lambda point: abs(math.log(point[0] / s)))
        # a second point within 1e-9 of the first (a root beside a march's point) gives no slope: its noise
        # over a difference of a few ulps would make the exponent, and the guess, absurd
        near = near[:1] + [point for point in near[1:] if abs(point[0] / near[0][0] - 1.0) > 1e-9][:1]
        guess = None
        if len(near) == 2:
            (s0, p0), (s1, p1) = near
            guess = p0 * (s / s0) ** (math.log(p1 / p0) / math.log(s1 / s0))
        elif near:
            guess = near[0][1] * (s / near[0][0]) ** 1.5
        p = pressure_of_stretch(1.0 + s, self.law, tol=self.tol, guess=guess,
                                accuracy=_P_RTOL if precise else _MARCH_RTOL)
        if p is not None:
            self.points.append((s, p))
        self.known[s] = (p, precise)
        return p

    def phat(self, s, precise=False):
        p = self.pressure(s, precise)
        return None if p is None else p / self.law.pressure_factor


def _first_branch(value, target, s, what, limit=math.inf, above=None):
    """s_lo < s_hi with value(s_lo) < target <= value(s_hi) on the first branch, and whether s_hi is
    a maximum of ``value`` (a pressure or a volume, None where there is none; ``value(s, True)``
    to full accuracy). Raises OutOfRangeError when value has a maximum below ``target`` (``above(s, peak)``
    if given, the error to raise for the maximum ``peak`` at strain s), when the march reaches the
    law's locking strain ``limit`` (halving the way to it) without reaching it, or when it reaches the pole
    stretch ``STRETCH_LIMIT`` without reaching it (``what``: the target's name, as ``"Phat"``)."""
    s = min(s, _S_MAX)  # a start estimate past the limit (a large target's) is no state's
    while True:
        start = value(s)
        while start is None or start >= target:
            s /= _GROWTH**4
            start = value(s)
        history = [(s, start)]
        falling = False
        while not falling:
            if s >= _S_MAX:
                raise past_stretch_limit(f"{what} = {target!r}")
            if s >= limit * (1.0 - _LOCK_RTOL):
                raise OutOfRangeError(f"{what} = {target:.6g} is not reached below the rubber's locking stretch "
                                      f"(lambda_0 = {1 + limit:.10g}, where I1 - 3 = Jm)")
            for s, current in _step(value, history, min(s * _GROWTH, _S_MAX, 0.5 * (s + limit))):
                if current is not None and current >= target:
                    return history[-1][0], s, False
                if current is None or current < history[-1][1]:
                    falling = True
                    break
                history.append((s, current))
        if len(history) == 1:  # falling from the start: it lies past a maximum; start lower
            s = history[0][0] / _GROWTH**4
            continue
        lo = history[-2][0]
        peak_s, peak = brent.maximum(lambda x: _minus_inf(value(x, True)), lo, s, xtol=_PEAK_RTOL * s)
        if peak < target and above is not None:
            raise above(peak_s, peak)
        if peak < target:
            raise OutOfRangeError(
                f"no inflated state on the first branch: {what} = {target:.6g} is above "
                f"its maximum {peak:.6g} (reached at lambda_0 = {1 + peak_s:.6g})"
            )
        return lo, peak_s, True


def _step(value, history, s):
    """The march's points (s, value(s)) up to ``s`` from the last of ``history``: ``s`` alone, or where the
    branch is flat (its slope d log(value) / d log(s) over the step below ``_FLAT``), which is where a maximum
    narrower than a step hides, ``_SUBSTEPS`` points before it and, if the least slope there (``_least_slope``)
    is negative, the two points about it where the branch falls."""
    current = value(s)
    s_m, v_m = history[-1]
    if current is None or current < v_m or math.log(current / v_m) >= _FLAT * math.log(s / s_m):
        return [(s, current)]
    chain = [(s_m, v_m)] + [(x, value(x)) for x in _between(s_m, s, _SUBSTEPS)] + [(s, current)]
    if any(b is None or b < a for (_, a), (_, b) in itertools.pairwise(chain)):
        return chain[1:]
    x, slope = _least_slope(value, chain)
    if slope >= 0.0:
        return chain[1:]
    x_up = x * (1.0 + _SLOPE_STEP)
    return [point for point in chain[1:] if point[0] < x] + [(x, value(x, True)), (x_up, value(x_up, True))]


def _between(a, b, n):
    """``n`` points between a and b > a, evenly spaced in log."""
    return [a * (b / a) ** (k / (n + 1)) for k in range(1, n + 1)]


def _least_slope(value, chain):
    """(s, the slope d log(value) / d log(s) there) where the slope is least, near the least of the slopes between
    the points (s, value) of ``chain``: golden sections on the slope over ``_SLOPE_STEP``, from the full-accuracy
    values (1e-14), which resolve a slope of ~1e-10 (a maximum 1e-9 above the minimum after it, on a branch
    flat to 1e-4 in p: Mooney-Rivlin alpha within 1e-5 of where the maximum vanishes, ~0.0554)."""
    slopes = [math.log(b / a) / math.log(y / x) for (x, a), (y, b) in itertools.pairwise(chain)]
    k = slopes.index(min(slopes))
    lo, hi = chain[max(k - 1, 0)][0], chain[min(k + 2, len(chain) - 1)][0]

    def slope(x):
        return math.log(value(x * (1.0 + _SLOPE_STEP), True) / value(x, True)) / math.log1p(_SLOPE_STEP)

    x, minus = brent.maximum(lambda x: -slope(x), lo, hi, xtol=_SLOPE_STEP * lo)
    return x, -minus


def _minus_inf(value):
    return -math.inf if value is None else value


def _state(l0, law, p, tol, what, echo, geometry: Geometry):
    """The state at the root: scalars from the same shot as the root finder, the profile from a
    finer-stepped shot of the same problem; ``echo`` the inputs as given (rubber, and pressure or volume);
    ``geometry`` the reference surface, whose clamp the final shot must land on."""
    status, y, _ = shot_pole(l0, law, p, tol)
    miss = y[0] - clamp_of(geometry).radius
    # the miss against the material strain lambda_p lambda_0 - 1 (a taut sheet's is its prestretch's)
    if status != OK or abs(miss) > 1e-8 * (law.prestretch * l0 - 1.0) + 1e-13:
        raise ConvergenceError(f"inflation ({what}): the final shot from lambda_0 = {l0:.12g} "
                               f"{STATUS[status]}, rho(1) - 1 = {miss:.3g}", load=l0, residual=miss)
    status, _, steps = shot_pole(l0, law, p, tol, store=20000)
    if status != OK:
        raise ConvergenceError(f"inflation ({what}): the profile shot from lambda_0 = {l0:.12g} {STATUS[status]}",
                               load=l0)
    scalars = dict(pressure=p / law.pressure_factor, stretch_pole=l0, height=-y[1], volume=y[4], stretch_clamp=y[3])
    profile = profile_from_steps(steps, law, l0)
    low = tension_minima(profile, steps, law, p, tol)
    return InflatedState(**{**scalars, **echo}, profile=profile, solver="shooting", tension_1_min=low[0],
                         tension_2_min=low[1], geometry=geometry)


def inflate(material: MaterialLike, pressure: float, *, geometry: GeometryLike = None,
            rtol: float = 1e-10) -> InflatedState:
    """Inflate the flat sheet at the pressure Phat = P R / (E T) (pressure control, first branch).

    Parameters
    ----------
    material : Material or float
        The rubber, a ``pocket.core.materials.Material`` of any law, its stresses in any unit (only their
        ratios and E = 3 mu_0 enter); a number is a Mooney-Rivlin alpha = C2/C1 (``as_material``).
    pressure : float
        Phat = P R / (E T) > 0, dimensionless (P the gauge pressure, R the clamp radius, T the sheet's
        thickness, E = 3 mu_0 the rubber's small-strain Young's modulus).
    geometry : Geometry or str, optional
        The membrane's reference surface: None (the flat clamped disc) or one of ``GEOMETRIES``.
    rtol : float, optional
        Relative tolerance of the ODE integration, at most 1e-4.

    Returns
    -------
    InflatedState
        Lengths in units of R, the volume V / R^3, tensions in units of E T; ``pressure`` is the number given.

    Raises
    ------
    InputError
        For an invalid rubber, pressure, geometry or tolerance (before any work).
    OutOfRangeError
        If Phat lies above the first branch's pressure maximum (a neo-Hookean sheet's, say): ``inflate_volume``
        passes it.

    Examples
    --------
    The paper's silicone (alpha = 47/160) at Phat = 0.31:

    >>> from pocket import shooting
    >>> state = shooting.inflate(47 / 160, 0.31)
    >>> print(f"H0/R = {state.height:.4f}, lambda_0 = {state.stretch_pole:.4f}")
    H0/R = 0.4939, lambda_0 = 1.1633

    The profile ends at the clamp, rho = R on the clamp plane eta = 0 (to the integration's tolerance):

    >>> print(f"rho = {state.profile.rho[-1]:.8f}, eta = {state.profile.eta[-1]:.8f}")
    rho = 1.00000000, eta = 0.00000000
    """
    geometry, _ = posed(GEOMETRIES, "shooting", geometry)
    material = as_material(material)
    law = law_of(material)
    if isinstance(geometry.end, Symmetry):  # a closed capsule: a sphere, in closed form; P = 0 is its reference
        return inflate_capsule(material, law, check_non_negative("pressure", pressure), rtol)
    pressure = check_positive("pressure", pressure)
    s_est = _strain_of_pressure(law, pressure)
    tol = _tolerance(rtol, s_est)
    return _inflated(material, law, pressure, rtol, tol, _Branch(law, tol), s_est, geometry)[0]


def inflation_curve(material: MaterialLike, pressures: Numbers, *, geometry: GeometryLike = None,
                    rtol: float = 1e-10, progress: Progress | None = None) -> list[InflatedState]:
    """Inflated states at several pressures Phat (pressure control, first branch), from one march along the branch.

    The pressures are taken in increasing order, each march starting at the pole strain of the state before
    it and sharing the branch's computed points (about half the shots of as many ``inflate`` calls). Each
    state is ``inflate``'s to its tolerance; the integration's absolute tolerances are those of each
    pressure's own scale, the march's (which only guesses) those of the smallest.

    Parameters
    ----------
    material : Material or float
        The rubber, as for ``inflate`` (a number is a Mooney-Rivlin alpha).
    pressures : sequence of float
        Phat = P R / (E T) > 0 of each state, in any order.
    geometry : Geometry or str, optional
        The reference surface, as for ``inflate``.
    rtol : float, optional
        Relative tolerance of the ODE integration, at most 1e-4.
    progress : callable, optional
        ``progress(done, total)``, called after each pressure.

    Returns
    -------
    list of InflatedState
        In the order of ``pressures``.

    Raises
    ------
    InputError
        For invalid input, or no pressure.
    OutOfRangeError
        At the first pressure above the first branch's pressure maximum (as ``inflate``).

    Examples
    --------
    >>> from pocket import shooting
    >>> states = shooting.inflation_curve(47 / 160, [0.31, 0.2])
    >>> [s.pressure for s in states]
    [0.31, 0.2]

    Each is the state ``inflate`` finds at its pressure:

    >>> print(abs(states[0].height - shooting.inflate(47 / 160, 0.31).height) < 1e-9)
    True
    """
    geometry, _ = posed(GEOMETRIES, "shooting", geometry)
    material = as_material(material)
    law = law_of(material)
    if isinstance(geometry.end, Symmetry):
        return [inflate(material, p, geometry=geometry, rtol=rtol) for p in pressures] or _none_given()
    given = [check_positive("pressure", p) for p in pressures]
    if not given:
        _none_given()
    order = sorted(set(given))
    branch = _Branch(law, _tolerance(rtol, _strain_of_pressure(law, order[0])))
    states, start = {}, None
    for done, pressure in enumerate(order, start=1):
        s_est = _strain_of_pressure(law, pressure)
        states[pressure], start = _inflated(material, law, pressure, rtol, _tolerance(rtol, s_est), branch,
                                            s_est if start is None else start, geometry)
        if progress is not None:
            progress(done, len(order))
    return [states[p] for p in given]


def _none_given():
    raise InputError("no pressure given")


def _inflated(material, law, pressure, rtol, tol, branch, start, geometry) -> tuple[InflatedState, float]:
    """(the state at Phat = ``pressure``, its pole strain): the march along ``branch`` from pole strain
    ``start``, then the root of the landing at that pressure (module docstring); ``tol`` the integration's,
    ``geometry`` the reference surface."""
    p = law.pressure_factor * pressure
    what = f"Phat = {pressure!r}"

    def above(s, peak):  # the volume at the maximum, from the shot that lands there
        _, y, _ = shot_pole(1.0 + s, law, law.pressure_factor * peak, tol)
        return above_pressure_maximum(pressure, peak, y[4], f"lambda_0 = {1 + s:.6g}")

    lo, hi, peak = _first_branch(branch.phat, pressure, start, "Phat", law.stretch_limit - 1.0, above)

    def miss(s):
        return _signed(_landing(s, law, p, tol, what))

    # p(lo) < target <= p(hi) to the march's accuracy: the sign of m can still be the other one there
    f_lo, f_hi = miss(lo), miss(hi)
    while f_lo >= 0.0:
        hi, f_hi, lo = lo, f_lo, lo / _GROWTH
        f_lo = miss(lo)
    while f_hi < 0.0 and not peak:
        lo, f_lo, hi = hi, f_hi, hi * _GROWTH
        f_hi = miss(hi)
    if f_hi < 0.0:
        raise OutOfRangeError(f"no inflated state on the first branch: pressure = {pressure:.6g} is at its "
                              f"maximum (reached at lambda_0 = {1 + hi:.6g}) to within the solver's accuracy")
    s = brent.root(miss, lo, hi, fa=f_lo, fb=f_hi, rtol=_S_RTOL)
    # a taut sheet's p(s) is resolved only as far as rho(1) resolves its small strain s (module docstring)
    drift = 1e-7 if law.prestretch == 1.0 else 1e-7 + rtol / s
    if abs(branch.phat(s) / pressure - 1.0) > drift:  # a root of m on another branch: follow p(s) itself
        s = brent.root(lambda x: branch.phat(x, True) - pressure, lo, hi, rtol=_S_RTOL)
    return _state(1.0 + s, law, p, tol, what, dict(material=material, pressure=pressure), geometry), s


def inflate_volume(material: MaterialLike, volume: float, *, geometry: GeometryLike = None,
                   rtol: float = 1e-10) -> InflatedState:
    """Inflate the flat sheet to the enclosed volume V / R^3 (volume control, first branch).

    Volume control passes the pressure maxima that pressure control (``inflate``) cannot.

    Parameters
    ----------
    material : Material or float
        The rubber, as for ``inflate`` (a number is a Mooney-Rivlin alpha).
    volume : float
        V / R^3 > 0, the volume between the sheet and the clamp plane (R the clamp radius).
    geometry : Geometry or str, optional
        The reference surface, as for ``inflate``.
    rtol : float, optional
        Relative tolerance of the ODE integration, at most 1e-4.

    Returns
    -------
    InflatedState
        Its ``pressure`` is the Phat found; the ``volume`` the one given.

    Raises
    ------
    InputError
        For invalid input.
    OutOfRangeError
        For a volume the first branch does not reach (a rubber that locks, say).

    Examples
    --------
    Volume control inverts pressure control:

    >>> from pocket import shooting
    >>> state = shooting.inflate(47 / 160, 0.31)
    >>> print(round(shooting.inflate_volume(47 / 160, state.volume).pressure, 9))
    0.31

    A neo-Hookean sheet (alpha = 0) has a pressure maximum, Phat = 0.626 at V/R^3 = 2.80, which
    pressure control cannot pass and volume control does (the pressure falls beyond it):

    >>> shooting.inflate(0.0, 0.7)
    Traceback (most recent call last):
        ...
    pocket.core.errors.OutOfRangeError: no inflated state on the first branch: Phat = 0.7 is above its ...
    >>> print(f"{shooting.inflate_volume(0.0, 5.0).pressure:.4f}")
    0.5823
    """
    geometry, _ = posed(GEOMETRIES, "shooting", geometry)
    material = as_material(material)
    law = law_of(material)
    volume = check_volume("volume", volume)
    if isinstance(geometry.end, Symmetry):  # the sphere of that volume (the whole capsule's)
        stretch = (3.0 * volume / (4.0 * math.pi)) ** (1.0 / 3.0)
        state = inflate_capsule(material, law, capsule_pressure(law, stretch) / law.pressure_factor, rtol)
        return dataclasses.replace(state, volume=volume)  # echoed exactly, as the pocket's
    s_est = smallstrain.strain_of_volume(volume)
    if law.prestretch != 1.0:  # the paraboloid's volume pi H / 2 (units R^3)
        s_est = min(s_est, _taut_strain(law, 2.0 * volume / math.pi))
    tol = _tolerance(rtol, s_est)
    what = f"V = {volume!r}"
    branch = _Branch(law, tol)

    def volume_of(s, precise=True):
        p = branch.pressure(s, precise=True)
        if p is None:
            return None
        if p == math.inf:
            raise OutOfRangeError(f"no inflated state: volume = {volume!r} is not reached before the rubber locks "
                                  f"(lambda_0 = {1 + s:.10g} already needs Phat > {_P_CAP / law.pressure_factor:.3g}; "
                                  f"the locking stretch is {law.stretch_limit:.10g})")
        status, y, _ = shot_pole(1.0 + s, law, p, tol)
        if status != OK:
            raise ConvergenceError(f"inflation ({what}): the shot from lambda_0 = {1 + s:.12g} at its pressure "
                                   f"{STATUS[status]}", load=1.0 + s)
        return y[4]

    lo, hi, _ = _first_branch(volume_of, volume, s_est, "volume", law.stretch_limit - 1.0)
    s = brent.root(lambda x: volume_of(x) - volume, lo, hi, rtol=_S_RTOL)
    return _state(1.0 + s, law, branch.pressure(s, precise=True), tol, what, dict(material=material, volume=volume),
                  geometry)
