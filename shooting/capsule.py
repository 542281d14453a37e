r"""The closed capsule: a spherical membrane inflated, then squeezed between two parallel plates, by shooting.

The reference surface is the upper half of the unit sphere (``pocket.core.geometries.CAPSULE``): the arc length
S runs from the pole (S = 0) to the equator (S = pi / 2), r0 = sin S, and the equator lies on the plane of mirror
symmetry. The equations are the pocket's with lambda_2 = rho / sin S (``pocket.shooting.equations.rhs_on``, the
pole series with k^2 - 1: ``pole_state(..., sphere=True)``); the derivation is in the theory's section on capsules.

Inflation. The inflated capsule is a sphere of uniform stretch lambda, rho = lambda sin S, whose pressure is
Laplace's, p = 2 t(lambda, lambda) / lambda (units tau T / R, t the kernel's tension). ``inflate`` finds lambda on
the first branch by Brent's method (``pocket.shooting.brent``) on a bracket marched up from the unstressed sphere
(lambda = 1 / lambda_p for a capsule inflated from a smaller radius with the prestretch lambda_p); a pressure
above the first branch's maximum (the balloon's limit point) is an OutOfRangeError quoting the maximum. The shot
from the pole at that lambda is the check: it must land on the equator vertical (psi(pi/2) = pi/2) at
rho(pi/2) = lambda, within 1e-8 (a ConvergenceError otherwise).

Compression by two plates, force given (``CapsuleProblem``). The contact zone 0 <= S <= a_c lies flat on the
plate: psi = 0, and the in-plane equations are the free ones at p = 0 (with psi = 0 the angle's equation gives
psi' = 0 exactly, eta' = 0 and v' = 0: the plate carries the fluid's pressure, q = P), integrated from the pole
series at pressure 0. The free part starts at the edge with psi = 0 (a smooth plate exerts no line force) and the
edge's rho and lambda_1 (continuous), at the pressure P. Unknowns x = (q, e, c): the pressure ratio q = P/P_I,
the pole strain relative to the inflated one e = (lambda_0 - 1)/(lambda_I - 1), and c = a_c / sqrt(Fhat) (of order
1 / lambda_I at every force: a_c ~ sqrt(Fhat) / lambda_I as Fhat -> 0). Residuals, each of order one:

    psi(pi/2) - pi/2                       (the equator's symmetry: the meridian vertical there)
    V / V_I - (the fluid's volume ratio)   (a liquid: V = V_I; a gas: the polytropic law)
    q rho_c^2 / Fhat - 1                   (F = P pi rho_c^2, the plate's balance)

with V = 2 v(pi/2) the whole capsule (v integrated from the edge: the volume between the plate and the
equatorial plane) and the plate's height H = -eta(pi/2) (eta measured from the plate). Each force is solved by
the continuation of ``pocket.shooting.compression``.

The shots. The zone's equations have a regular singular point at the pole (lambda_2 = rho / sin S), where the
integrator's steps grow only in proportion to S; the zone is therefore started from its pole series one order
further than ``pole_state``'s (``_zone_series``): with lambda_1 = l0 + c2 S^2 + c4 S^4 and lambda_2 = l0 + d2 S^2
+ d4 S^4 (rho = lambda_2 sin S), rho' = lambda_1 and (rho t1)' = t2 rho' order by order give c2 = l0 (A - 3B) /
(16 A) and d2 = l0 (3A - B) / (16 A) (A, B = dt1/dl1, dt1/dl2 at (l0, l0): ``pole_state``'s with k = 0), and at
S^4 c4 and d4, linear in t1's second derivatives there (the expressions in the code, solved by sympy). It leaves
out a relative O(S^6), so the zone starts at S_0 = (its rtol)^(1/6) (``CapsuleProblem.zone_start``, 0.015 at
rtol 1e-11) instead of ``R_POLE``: half the steps. The Jacobian is shot column by column, each shooting only
what its unknown moves (``CapsuleProblem.jacobian``: q the free part alone, c the free part from the edge carried
a step on along the zone, e the whole shot): about two shots instead of the residual's three differences, so
each force's Newton iteration starts from a fresh one at the predicted unknowns (a quartic in log F through
the last five states, ``CapsuleProblem.predictor``; two or three residuals a force) rather than from the last
force's, which the capsule's Jacobian outgrows from one force to the next (its Broyden steps then converged
linearly). A residual's shot and the Jacobian's, with the free part in one segment, are compiled whole
(``_compiled_shot``: the zone and the free part by the same calls of the integrator, without the Python between
them). A state's profile is read off its own final shot, by the integrator's dense output at equally spaced points
(``_N_CONTACT`` on the zone, ``PROFILE_STEP`` apart on the free part).

Low inflation pressures. A shot from the pole to the equator amplifies an error near the pole about
exp(pi / (2 sqrt(t)))-fold, t = lambda Phat_I / 2 (``amplification``; the theory's small-force section): the free
part is shot in K segments (``CapsuleProblem.segments``): a single shot where it amplifies at most ``_TAME``-fold
(Phat_I down to about 0.1), else segments each amplifying at most ``_SEGMENT_GROWTH``-fold, their starts (rho, psi,
lambda_1) unknowns and their continuity residuals, up to ``_SEGMENTS_MAX`` (Phat_I ~ 2e-3), below which a
compression is a ConvergenceError saying why.

Reference scales. q, e, the segments' count and ``residual_tol`` (from the pole strain, ``Contact.residual_tol``)
are scaled by the inflated capsule, which at P_I = 0 (the unstressed sphere: no pressure, no strain, no tension)
scales nothing. ``CapsuleProblem(reference=...)`` scales them by another inflated capsule instead (q = P / P_ref,
e = (lambda_0 - 1) / (lambda_ref - 1), the segments of a shot amplifying as on it), so that P_I = 0 is posed under
height control (``pocket.shooting.descent``); the volume residual's fluid law then reads the absolute pressure
P_ref q (a gas sealed at P_I = 0 gauge: (P + P_atm) V^gamma = P_atm V_I^gamma). Without a reference every number
is the inflated capsule's, bit for bit. A state at P_I = 0 has no P / P_I nor Fhat (NaN): its force is
``extra["force_ETR"]`` = pi P rho_c^2.

A slack patch. At a low Phat_I (or a gas that yields) the pole's stretch under the plate falls with the force and
can pass below that of the unstressed rubber (1 / lambda_p): the patch's tension at the pole vanishes and turns
compressive, where a real membrane would wrinkle under the plate. No equation of the flat zone divides by its
tension, so the shots go on (``integrate(..., slack=True)``) and such a state is returned flagged ``wrinkled`` with
a warning saying where, as a pocket's compressive hoop tension is (``pocket.core.states``); at larger forces the
stretch rises again and the flag clears.

The end of the range. No clamp ends it: the plates are infinite and the equator free, and as the plates close the
stretches grow without bound for a liquid. But where the patch goes slack, the compression can spread from the pole
to the contact edge: there the free part leaves the plate with the curvature P / T_1 of its normal equilibrium,
which grows without bound as T_1 at the edge falls to 0, and no membrane state lies beyond. Where a continuation
step fails, ``CapsuleProblem.end`` marches the force up to the largest it reaches; if the edge's tension has fallen
there below 1 % of the inflated capsule's, that force ends the range (an OutOfRangeError above it, saying so);
otherwise no end is known (force inf) and the failure is a ConvergenceError saying where.
"""

from __future__ import annotations

import dataclasses
import functools
import math

import numpy as np

from pocket.core.compiled import compiled
from pocket.core.errors import (
    CAPSULE_EDGE,
    STRETCH_LIMIT,
    ConvergenceError,
    OutOfRangeError,
    PocketError,
    above_pressure_maximum,
    past_stretch_limit,
)
from pocket.core.geometries import CAPSULE
from pocket.core.states import CompressedState, InflatedState, Profile

from . import brent, newton, tableau
from .contact import Contact
from .continuation import first_state
from .end import End
from .equations import pole_state
from .integrator import OK, STATUS, _integrate, integrate
from .shots import PROFILE_STEP, PSI_MAX_EDGE, R_POLE, Tolerance
from .tensions import inside, tensions, tensions_compiled

__all__ = ["CapsuleProblem", "amplification", "capsule_pressure", "inflate_capsule"]

_GROWTH = 1.4  # ratio of successive strains in the march for the bracket
_POINTS = 201  # points of an inflated capsule's profile
_N_CONTACT = 64  # the contact zone's points in a state's profile
_LANDING = 1e-8  # how far the check shot of an inflated capsule may land from the closed form, where it amplifies
# the integration's errors less than _TAME-fold
_TAME = 1e3
_WILD = 1e6  # the amplification past which a check shot of the inflated capsule from its pole keeps too few digits
_AHEAD = (1e-2, 1e-3, 1e-4, 1e-5)  # relative steps of the force tried for a neighbour of a state (``end``)
_END_RATIO = 1.5  # the largest ratio of successive forces in the march to the end of the range
_FORCE_CAP = 1e3  # ... and the force it stops at
_END_RTOL = 1e-7  # ... and the relative step below which it stops: the end's accuracy
_EDGE_SLACK = 1e-2  # the edge's tension, relative to the inflated capsule's, below which a march's stop is the end
_SEGMENT_GROWTH = 30.0  # the most a segment of the free part may amplify errors (``CapsuleProblem.segments``)
# the contact zone's relative tolerance, over rtol: the zone's end state is the integrator's error away from the exact
# one, and that error does not vary smoothly with the pole stretch (the adaptive steps change with it): at rtol 1e-10
# lambda_1 at the edge jitters by 3e-12 as lambda_0 moves by 1e-11, which the free part amplifies into the equator's
# angle; Newton, carrying its Jacobian from force to force, read it as a residual noise of about 2e-11, above its
# tolerance 1e-12, and stalled there (674 residual evaluations for the benchmark's 20 forces, 192 at 1e-2 rtol).
# Started from ``jacobian`` at each force, Newton takes as many at 1e-2, 1e-1 or 1 (111, then 94, measured); 1e-1
# keeps the zone's error, which the states carry (they move by 5e-12 from 1e-2 to 1e-1, by 3e-11 to 1), an order
# below the free part's: the states at rtol 1e-10 stay within 2.6e-11 of those at 1e-13 at each.
_ZONE_RTOL = 1e-1
_SEGMENTS_MAX = 16  # the most segments the free part is shot in (Phat_I down to about 1e-3)
# the free part's segments start with this fraction of their length as the first step: the integrator's default, a
# hundredth of the start's arc length, is made for shots from the pole; from the contact edge its first step was a
# tenth of the next ones, about a sixteenth of the free part (measured on the benchmark's curve): one step fewer of ten
_FIRST_STEPS = 16
_NO_STEPS = np.empty((0, 6))  # the steps of a shot that stores none
_NO_TABLE = np.empty((4, 0))  # (with _NO_NODES for its breakpoints) no profile table: ``_compiled_shot``'s free sheet
_NO_NODES = np.empty(0)  # the interior nodes of a free part shot in one segment
_NO_STARTS = np.empty((0, 3))  # ... and their unknown starts
_SUMMED = np.array([0.0, 1.0, 0.0, 0.0, 1.0])  # the components summed over the free part's segments: eta and v


def amplification(pressure: float, stretch: float) -> float:
    """exp(pi / (2 sqrt(t))), t = N_0 / (E T) = lambda Phat_I / 2: about how much a shot from the pole to the equator
    amplifies an error made near the pole, on the capsule inflated at Phat_I = ``pressure`` to ``stretch`` (the
    dent's homogeneous solutions grow like exp(r / l), l^2 = t R^2 lambda^2: the theory's small-force section)."""
    t = 0.5 * stretch * pressure
    return math.inf if t <= 0.0 else math.exp(min(700.0, 0.5 * math.pi / math.sqrt(t)))


@compiled
def _zone_series(l0, code, params, arc):
    """y = [rho, 0, 0, lambda_1, 0] of the contact zone (p = 0, psi = 0) at the arc length ``arc`` from the pole of
    stretch l0, by its series to O(S^4) (module docstring, "The shots"); t1's second derivatives by central
    differences of the kernel's first (a relative step 1e-4: their error, about 1e-8, enters the S^4 terms only)."""
    _, _, a, b = tensions_compiled(l0, l0, code, params)  # A, B: dt1/dl1, dt1/dl2; t11, t12, t22: t1's second
    h = 1e-4 * l0
    up, down = tensions_compiled(l0 + h, l0, code, params), tensions_compiled(l0 - h, l0, code, params)
    t11, t12 = (up[2] - down[2]) / (2 * h), (up[3] - down[3]) / (2 * h)
    t22 = (tensions_compiled(l0, l0 + h, code, params)[3] - tensions_compiled(l0, l0 - h, code, params)[3]) / (2 * h)
    c2 = l0 * (a - 3.0 * b) / (16.0 * a)
    d2 = l0 * (3.0 * a - b) / (16.0 * a)
    c4 = l0 * (18.0 * a**3 + 5.0 * a * a * t11 * l0 - 30.0 * a * a * t12 * l0 - 90.0 * a * a * b
               - 55.0 * a * a * t22 * l0 + 30.0 * a * t11 * b * l0 + 100.0 * a * t12 * b * l0 + 30.0 * a * b * b
               + 30.0 * a * b * t22 * l0 - 55.0 * t11 * b * b * l0 - 30.0 * t12 * b * b * l0 + 10.0 * b**3
               + 5.0 * b * b * t22 * l0) / (3072.0 * a**3)
    d4 = l0 * (74.0 * a**3 + a * a * t11 * l0 - 6.0 * a * a * t12 * l0 - 50.0 * a * a * b - 11.0 * a * a * t22 * l0
               + 6.0 * a * t11 * b * l0 + 20.0 * a * t12 * b * l0 + 6.0 * a * b * b + 6.0 * a * b * t22 * l0
               - 11.0 * t11 * b * b * l0 - 6.0 * t12 * b * b * l0 + 2.0 * b**3 + b * b * t22 * l0) / (3072.0 * a**3)
    s2 = arc * arc
    y = np.zeros(5)
    y[0] = (l0 + (d2 + d4 * s2) * s2) * np.sin(arc)
    y[3] = l0 + (c2 + c4 * s2) * s2
    return y


@compiled
def _compiled_shot(y_start, s_start, h0, a, p, code, params, zone_rtol, zone_atol, rtol, atol, psi_max, yes, no, none,
                   table, steps, A, B, C, E3, E5, AX, CX, D):
    """(status, y(pi/2), y(a)): the contact zone's state ``y_start`` at the arc length ``s_start`` carried on to the
    edge a (first step h0; none where a <= s_start), then the free part in one segment, storing nothing: compiled
    whole, ``CapsuleProblem._zone`` (or its carrying on, the Jacobian's column of c) then ``_free`` for the residual
    and its Jacobian (a third of a residual's cost was the Python between and around the two integrations). The
    same calls of the integrator with the same arguments, so the same numbers bit for bit
    (``tests/test_shooting_capsule_shots.py``); ``yes`` and ``no`` are True and False passed in (as literals they
    would type the integrator anew, and compile it again)."""
    status, edge = OK, y_start
    if a > s_start:
        status, _, edge, _ = _integrate(y_start, s_start, a, code, params, 0.0, 0.0, none, table, none, zone_rtol,
                                        zone_atol, h0, np.inf, np.pi, yes, yes, steps, none, A, B, C, E3, E5, AX, CX, D)
    if status != OK:
        return status, edge, edge
    y0 = np.zeros(5)
    y0[0], y0[3] = edge[0], edge[3]
    status, _, y, _ = _integrate(y0, a, 0.5 * np.pi, code, params, p, 0.0, none, table, none, rtol, atol,
                                 (0.5 * np.pi - a) / _FIRST_STEPS, np.inf, psi_max, yes, no, steps, none, A, B, C, E3,
                                 E5, AX, CX, D)
    return status, y, edge


def capsule_pressure(law, stretch: float) -> float:
    """p = 2 t(lambda, lambda) / lambda: the pressure (units tau T / R, ``Law.pressure_factor`` Phat) of the
    capsule inflated to the uniform stretch lambda = ``stretch`` (Laplace's law on the sphere of radius lambda R)."""
    return 2.0 * float(tensions(stretch, stretch, law.code, law.params)[0]) / stretch


def _tolerance(rtol: float) -> Tolerance:
    """The integration tolerances of a capsule: every quantity is of order one (lengths of R, V ~ 4)."""
    return Tolerance(rtol, 1e-2 * rtol * np.ones(5))


def _stretch_of_pressure(law, phat: float) -> float:
    """The uniform stretch lambda of the inflated capsule at Phat on the first branch (module docstring)."""
    p = law.pressure_factor * phat
    low = 1.0 / law.prestretch  # the unstressed sphere

    def excess(stretch):
        return capsule_pressure(law, stretch) - p

    if excess(low) >= 0.0:  # Phat = 0 and no prestretch: the sphere itself (or Phat below a taut capsule's)
        if p == capsule_pressure(law, low):
            return low
        raise OutOfRangeError(f"no inflated capsule at Phat = {phat:.6g}: below the pressure of the unstressed "
                              f"sphere ({capsule_pressure(law, low) / law.pressure_factor:.6g})")
    strain = max(phat / 8.0, 1e-14)
    previous, before = low, low
    while True:
        stretch = low * (1.0 + strain)
        if stretch > min(STRETCH_LIMIT, law.stretch_limit):
            raise past_stretch_limit(f"Phat = {phat!r}")
        if not inside(stretch, stretch, law.code, law.params):
            raise past_stretch_limit(f"Phat = {phat!r}")
        if excess(stretch) >= 0.0:
            return brent.root(excess, previous, stretch, rtol=1e-15)
        if previous > low and capsule_pressure(law, stretch) < capsule_pressure(law, previous):
            peak = _peak(law, before, stretch)
            if capsule_pressure(law, peak) >= p:
                return brent.root(excess, previous if previous < peak else before, peak, rtol=1e-15)
            volume = 4.0 * math.pi * peak**3 / 3.0
            raise above_pressure_maximum(phat, capsule_pressure(law, peak) / law.pressure_factor, volume,
                                         f"the capsule's stretch {peak:.6g}")
        before, previous, strain = previous, stretch, strain * _GROWTH


def _peak(law, low: float, high: float) -> float:
    """The stretch of the pressure maximum between ``low`` and ``high`` (golden-section search)."""
    ratio = (math.sqrt(5.0) - 1.0) / 2.0
    a, b = low, high
    while b - a > 1e-12 * b:
        x1, x2 = b - ratio * (b - a), a + ratio * (b - a)
        if capsule_pressure(law, x1) < capsule_pressure(law, x2):
            a = x1
        else:
            b = x2
    return 0.5 * (a + b)


def _sphere_profile(law, stretch: float) -> Profile:
    """The inflated capsule's meridian from the pole to the equator: rho = lambda sin S, eta = lambda cos S."""
    arc = np.linspace(0.0, 0.5 * math.pi, _POINTS)
    uniform = np.full_like(arc, stretch)
    t1, t2, _, _ = tensions(uniform, uniform, law.code, law.params)
    return Profile(r=arc, rho=stretch * np.sin(arc), eta=stretch * np.cos(arc), stretch_1=uniform,
                   stretch_2=uniform.copy(), tension_1=t1 * law.tension_scale, tension_2=t2 * law.tension_scale,
                   contact=np.zeros(arc.size, bool))


def inflate_capsule(material, law, pressure: float, rtol: float) -> InflatedState:
    """The capsule inflated at Phat = ``pressure`` (module docstring); ``law`` the rubber's kernel
    (``pocket.shooting.laws.law_of(material)``), ``rtol`` the check shot's tolerance."""
    stretch = _stretch_of_pressure(law, pressure)
    p = capsule_pressure(law, stretch)
    # the check: the shot from the pole lands on the equator, vertical, at rho = lambda
    if p > 0.0 and amplification(pressure, stretch) < _WILD:
        y0 = pole_state(stretch, law, p, R_POLE, sphere=True)
        tol = _tolerance(rtol)
        status, _, y, _ = integrate(y0, R_POLE, law, p, rtol=tol.rtol, atol=tol.atol, r_end=0.5 * math.pi,
                                    psi_max=PSI_MAX_EDGE, sphere=True)
        miss = max(abs(y[2] - 0.5 * math.pi), abs(y[0] / stretch - 1.0)) if status == OK else math.inf
        if miss > _LANDING * max(1.0, amplification(pressure, stretch) / _TAME):
            raise ConvergenceError(f"inflation of the capsule at Phat = {pressure!r}: the shot from the pole at "
                                   f"lambda = {stretch:.12g} {STATUS[status]}, missing the sphere by {miss:.3g}",
                                   load=pressure, residual=miss)
    return InflatedState(material=material, pressure=pressure, stretch_pole=stretch, height=stretch,
                         volume=4.0 * math.pi * stretch**3 / 3.0, stretch_clamp=stretch,
                         profile=_sphere_profile(law, stretch), solver="shooting",
                         extra={"geometry": CAPSULE.name, "radius_equator": stretch}, geometry=CAPSULE)


@dataclasses.dataclass(frozen=True)
class CapsuleProblem(Contact):
    """The compression of the inflated capsule ``inflated`` between two plates (module docstring); fields as
    ``Contact``. ``height``: None under force control, or the plates' height H / R under height control (the
    third residual then holds H, and the force is q rho_c^2). ``reference``: None, or another inflated capsule
    whose pressure and pole strain scale the unknowns (q = P / P_ref, e = (lambda_0 - 1) / (lambda_ref - 1)) and
    set the free part's segments (module docstring, "Reference scales"); None scales them by ``inflated``."""

    height: float | None = None
    reference: InflatedState | None = None

    @property
    def label(self) -> str:
        return "capsule, " + super().label

    @property
    def key(self) -> tuple:
        scale = () if self.reference is None else (self.scale.pressure, self.scale.stretch_pole)
        return (*super().key, CAPSULE.name, *scale)

    @property
    def scale(self) -> InflatedState:
        """The inflated capsule whose pressure and pole strain scale the unknowns: ``reference``, or ``inflated``."""
        return self.inflated if self.reference is None else self.reference

    @property
    def strain(self) -> float:
        """s = lambda_ref - 1, the scale of the pole strain's unknown e (``scale``)."""
        return self.scale.stretch_pole - 1.0

    @functools.cached_property
    def tolerance(self) -> Tolerance:
        """The free part's integration tolerances."""
        return _tolerance(self.rtol)

    @functools.cached_property
    def zone_tolerance(self) -> Tolerance:
        """The contact zone's integration tolerances, ``_ZONE_RTOL`` times tighter."""
        return _tolerance(_ZONE_RTOL * self.rtol)

    @property
    def growth(self) -> float:
        """The amplification of a shot from the pole to the equator on this capsule (``amplification``)."""
        scale = self.scale
        return amplification(scale.pressure, scale.stretch_pole)

    @functools.cached_property
    def segments(self) -> int:
        """K, the free part's segments: one where a single shot amplifies errors at most ``_TAME``-fold, else enough
        that each amplifies them at most ``_SEGMENT_GROWTH``-fold (growth^(1/K))."""
        if self.growth <= _TAME:
            return 1
        return math.ceil(math.log(self.growth) / math.log(_SEGMENT_GROWTH) - 1e-9)

    @property
    def residual_floor(self) -> float:
        """The stall accepted as the shots' noise: ``Contact``'s (each segment amplifies its errors at most
        ``_SEGMENT_GROWTH``-fold)."""
        return super().residual_floor

    def conditioned(self) -> None:
        """A ConvergenceError where the segments needed would be past ``_SEGMENTS_MAX`` (module docstring)."""
        if self.segments > _SEGMENTS_MAX:
            raise ConvergenceError(
                f"capsule compression at Phat_I = {self.inflated.pressure!r}: a shot from the pole to the equator "
                f"amplifies its errors about {self.growth:.1e}-fold at this low inflation pressure, more than "
                f"{_SEGMENTS_MAX} shooting segments resolve; the finite-element solver (fem) poses it",
                load=self.inflated.pressure)

    def start(self) -> np.ndarray:
        """Unknowns (q, e, c, nodes) of the inflated capsule (Fhat -> 0): the nodes' (rho, psi, lambda_1) on its
        sphere."""
        lam, scale = self.inflated.stretch_pole, self.scale
        arcs = self._nodes(0.0)
        nodes = np.column_stack([lam * np.sin(arcs), arcs, np.full_like(arcs, lam)]).ravel()
        q, e = self.inflated.pressure / scale.pressure, (lam - 1.0) / self.strain
        return np.concatenate([[q, e, 1.0 / lam], nodes])

    def _nodes(self, a: float) -> np.ndarray:
        """The arc lengths of the free part's interior nodes, dividing [a, pi/2] into ``segments`` equal parts."""
        k = self.segments
        return a + (0.5 * math.pi - a) * np.arange(1, k) / k if k > 1 else _NO_NODES

    def geometry(self, x, force):
        """(q, lambda_0, a_c, p, nodes) for unknowns x at ``force`` (nodes: shape (K - 1, 3), each node's (rho, psi,
        lambda_1)), or None outside the model's domain."""
        q, e, c = float(x[0]), float(x[1]), float(x[2])
        l0 = self.stretch(e)
        a = c * math.sqrt(force) if self.height is None else c
        if not (q > 0.0 and l0 > 0.0 and 0.0 < a < 0.5 * math.pi and force > 0.0):
            return None
        return q, l0, a, self._pressure * q, np.reshape(x[3:], (-1, 3)) if x.size > 3 else _NO_STARTS

    @functools.cached_property
    def _pressure(self) -> float:
        """p at q = 1: the pressure of ``scale`` in units of tau T / R."""
        return self.law.pressure_factor * self.scale.pressure

    @functools.cached_property
    def zone_start(self) -> float:
        """S_0, where the contact zone's shot starts from its pole series (``_zone_series``): the series' error there
        is of relative order S_0^6, so S_0 = (zone rtol)^(1/6) keeps it at the zone's tolerance, and the integrator's
        steps, which grow in proportion to S from the pole (its regular singular point), start there instead of at
        ``R_POLE``."""
        return self.zone_tolerance.rtol ** (1.0 / 6.0)

    def _zone(self, l0, a, store):
        """(status, y(a), steps) of the contact zone from the pole to the edge a (p = 0, psi = 0); ``store``: the
        steps are the profile's ``_N_CONTACT`` points, equally spaced on (0, a] (the shot's dense output; the pole
        series' below ``zone_start``)."""
        start, law = self.zone_start, self.law
        arcs = np.linspace(0.0, a, _N_CONTACT + 1)[1:] if store else None
        if a <= start:
            status, y, steps = OK, _zone_series(l0, law.code, law.params, a), _NO_STEPS
        else:
            tol = self.zone_tolerance
            status, _, y, steps = integrate(_zone_series(l0, law.code, law.params, start), start, law, 0.0,
                                            rtol=tol.rtol, atol=tol.atol, r_end=a, h0=start, sphere=True, slack=True,
                                            grid=arcs)
        if store and status == OK:
            near = arcs[arcs <= start]
            steps = np.vstack([[[arc, *_zone_series(l0, law.code, law.params, arc)] for arc in near],
                               steps[near.size:]]) if near.size else steps
        return status, y, steps

    def _free(self, edge, a, p, nodes, store):
        """(status, y(pi/2), steps, the segments' mismatches at the nodes) of the free part from the contact edge a
        (``edge`` the zone's state there) at the pressure p: each segment shot from its node (the first from the
        edge), eta and v summed over the segments (the steps' too). ``store``: the steps are the profile's points,
        equally spaced at most ``PROFILE_STEP`` apart on each segment (the shot's dense output)."""
        tol = self.tolerance
        begin, y0, offset = a, np.array([edge[0], 0.0, 0.0, edge[3], 0.0]), None
        pieces, mismatches = [], []
        for k, end in enumerate([*self._nodes(a), 0.5 * math.pi]):
            grid = np.linspace(begin, end, math.ceil((end - begin) / PROFILE_STEP) + 1) if store else None
            status, _, y, steps = integrate(y0, begin, self.law, p, rtol=tol.rtol, atol=tol.atol, r_end=end,
                                            h0=(end - begin) / _FIRST_STEPS,
                                            psi_max=PSI_MAX_EDGE, sphere=True, grid=grid)
            if status != OK:
                return status, y, _NO_STEPS, mismatches
            if k < len(nodes):  # the next segment starts at its node
                rho, psi, l1 = nodes[k]
                mismatches.extend((y[0] - rho, y[2] - psi, y[3] - l1))
                y0 = np.array([rho, 0.0, psi, l1, 0.0])
            if offset is not None:
                y += offset * _SUMMED
                steps[:, 1:] += offset * _SUMMED
            if store:
                pieces.append(steps[(1 if k else 0):])
            begin, offset = end, y
        return status, y, np.vstack(pieces) if store else _NO_STEPS, mismatches

    def _one_shot(self, l0, a, p):
        """(status, y(pi/2), y(a)) of the zone from the pole and a free part in one segment (``_zone`` then ``_free``,
        compiled whole: ``_carried``)."""
        start, law = self.zone_start, self.law
        if a <= start:
            return self._carried(_zone_series(l0, law.code, law.params, a), a, start, a, p)
        return self._carried(_zone_series(l0, law.code, law.params, start), start, start, a, p)

    def _carried(self, y, arc, h0, a, p):
        """(status, y(pi/2), y(a)): the zone's state y at ``arc`` carried on to the edge a (first step h0), then a
        free part in one segment at the pressure p (``_compiled_shot``)."""
        law, zone, free = self.law, self.zone_tolerance, self.tolerance
        return _compiled_shot(y, arc, h0, a, p, law.code, law.params, zone.rtol, zone.atol, free.rtol, free.atol,
                              PSI_MAX_EDGE, True, False, _NO_NODES, _NO_TABLE, _NO_STEPS, tableau.A, tableau.B,
                              tableau.C, tableau.E3, tableau.E5, tableau.A_EXTRA, tableau.C_EXTRA, tableau.D)

    def _shot(self, geometry, store):
        """(status, y(pi/2), steps of the free part, steps of the contact zone, y(a), the segments' mismatches at
        the nodes) at ``geometry`` (``_zone``, then ``_free``: compiled whole, ``_one_shot``, for a free part in one
        segment storing nothing)."""
        _q, l0, a, p, nodes = geometry
        if not (store or nodes.size):
            status, y, edge = self._one_shot(l0, a, p)
            return status, y, _NO_STEPS, _NO_STEPS, edge, []
        status, edge, zone = self._zone(l0, a, store)
        if status != OK:
            return status, edge, _NO_STEPS, zone
        status, y, steps, mismatches = self._free(edge, a, p, nodes, store)
        return status, y, steps, zone, edge, mismatches

    def residual(self, x, force, angle=None):
        """The three residuals at ``force`` (module docstring); None where a shot stops or x is outside."""
        shot = self.shoot(x, force)
        if shot is None or shot[0] != OK:
            if shot is not None:
                self._last["failure"] = (shot[0], float(x[0]), self.stretch(x[1]), float(force))
            return None
        return self._residuals(x, force, shot[1], shot[4], shot[5])

    def _residuals(self, x, force, y, edge, mismatches):
        """The residuals of unknowns x at ``force`` whose shot reached the equator at y with the contact edge's
        state ``edge`` and the segments' ``mismatches``."""
        inflated = self.inflated
        ratio = self.fluid.volume_ratio(self.scale.pressure * x[0], inflated.pressure)
        if self.height is None:
            last = x[0] * edge[0] ** 2 / force - 1.0
        else:
            last = (-y[1] - self.height) / inflated.stretch_pole
        return np.array([y[2] - 0.5 * math.pi, 2.0 * y[4] / inflated.volume - ratio, last, *mismatches])

    PREDICTOR_DEGREE = 4

    @staticmethod
    def predictor(force: float) -> float:
        """log F: the variable in which a continuation predicts the unknowns, a quartic through the last five
        states (``PREDICTOR_DEGREE``; the contact radius grows like sqrt(F), the curve is taken over decades of F;
        a quadratic in F itself missed ten times further than one in log F, a quartic in log F a hundred times less
        again: at the benchmark's last forces 4e-7, where one Newton step from the fresh Jacobian converges)."""
        return math.log(force)

    def jacobian(self, x, force, f):
        """dR/dx at x (its residuals f; its shot from ``Contact.shoot``'s cache when it was the last) by forward
        differences (``newton.difference_steps``), each column shooting only what its unknown moves: q the free
        part alone (the pressure), c the free part from the edge carried a step on along the zone (``_carried``),
        e the whole shot; about two shots' cost instead of three. None with segments (their nodes move one segment
        each: the residual's differences then) or where a shot of a column stops."""
        shot = self.shoot(x, force)
        if self.segments > 1 or shot is None or shot[0] != OK:
            return None
        a, edge = self.geometry(x, force)[2], shot[4]
        jac = np.empty((3, 3))
        for j, h in enumerate(newton.difference_steps(x)):
            moved = x.copy()
            moved[j] += h
            geometry = self.geometry(moved, force)
            if geometry is None:
                return None
            _, l0_j, a_j, p_j, _ = geometry
            status, y, edge_j = self._one_shot(l0_j, a_j, p_j) if j == 1 else \
                self._carried(edge, a, a_j - a, a_j, p_j)
            if status != OK:
                return None
            jac[:, j] = (self._residuals(moved, force, y, edge_j, []) - f) / h
        return jac

    def clamp_angle(self, x, force) -> float:
        """No clamp: 0, so that the continuation's test of the clamp plane never fires."""
        return 0.0

    def _closure(self, x, force, shot) -> tuple:
        return ()

    def compressed(self, force, x, fluid) -> tuple[CompressedState, float]:
        """The compressed state at ``force`` for the solved unknowns x, and 0 (no clamp angle)."""
        q, l0, a, _, _ = self.geometry(x, force)
        stored = self.shoot(x, force, store=True)  # the residual's shot, with the profile's points (dense output)
        if stored[0] != OK:
            raise ConvergenceError(f"capsule compression at force = {force!r}: the final shot {STATUS[stored[0]]}",
                                   load=force)
        _, y, free, zone, edge, _ = stored
        inflated = self.inflated
        height = -y[1]
        rho_c = edge[0]
        pressure = self.scale.pressure * q
        # P / P_I: q itself (bit for bit) where the scale is the inflated capsule's; none at P_I = 0 (nor Fhat)
        ratio = q * (self.scale.pressure / inflated.pressure) if inflated.pressure > 0.0 else math.nan
        force_out = force if self.height is None else ratio * rho_c**2
        force_etr = math.pi * (force_out * inflated.pressure if inflated.pressure > 0.0 else pressure * rho_c**2)
        profile = self._profile(l0, zone, free, height)
        state = CompressedState(
            pressure_initial=inflated.pressure, force=force_out, pressure=pressure, pressure_ratio=ratio,
            contact_area=rho_c**2, contact_radius=a, stretch_contact=rho_c / math.sin(a), height=height,
            height_ratio=height / inflated.height, volume=2.0 * y[4], profile=profile, inflated=inflated,
            solver="shooting", material=inflated.material, fluid=fluid, indenter=self.indenter,
            contact_radius_deformed=rho_c,
            extra={"geometry": CAPSULE.name, "stretch_pole": float(l0), "radius_equator": float(y[0]),
                   "force_ETR": force_etr},
        )
        return state, 0.0

    def _profile(self, l0, zone, free, height) -> Profile:
        """The meridian from the pole to the equator: the contact zone's points (flat at the plate), then the free
        part's; eta from the equatorial plane, the plate's ``height`` above it."""
        arc, rho, eta, _, l1, _ = np.vstack([[0.0, 0.0, 0.0, 0.0, l0, 0.0], zone, free[1:]]).T.copy()
        eta += height
        l2 = np.empty_like(arc)
        l2[0], l2[1:] = l0, rho[1:] / np.sin(arc[1:])
        t1, t2, _, _ = tensions(l1, l2, self.law.code, self.law.params)
        contact = np.zeros(arc.size, bool)
        contact[:zone.shape[0] + 1] = True
        scale = self.law.tension_scale
        return Profile(r=arc, rho=rho, eta=eta, stretch_1=l1, stretch_2=l2, tension_1=t1 * scale,
                       tension_2=t2 * scale, contact=contact)

    def end(self, seed) -> End:
        """The end of the range from the solved (force, x) ``seed`` (module docstring): the force is marched up from
        the seed (ratios up to ``_END_RATIO``, each state from the secant in log F through the last two, the ratio
        shrunk where a step fails) to the largest it reaches; if the meridional tension at the contact edge has
        fallen there below ``_EDGE_SLACK`` of the inflated capsule's, the range ends at that force (to the march's
        ``_END_RTOL``); otherwise, or past ``_FORCE_CAP``, no end is known (force inf)."""
        if seed is None:  # a state at a small force, by the continuation every force is solved by; a failure on
            if self._last.get("ending"):  # its way asks for the end again: that one has none
                return _NO_END
            self._last["ending"] = True
            try:
                seed = first_state(self, 1e-3)
            except PocketError:
                return _NO_END
            finally:
                self._last.pop("ending")
        pair = self._neighbour(*seed)
        if pair is None:
            return _NO_END
        points = list(pair)  # (force, x) along the branch, in order of force
        ratio = _END_RATIO
        while points[-1][0] < _FORCE_CAP and ratio > 1.0 + _END_RTOL:
            (f0, x0), (f1, x1) = points[-2:]
            near = f1 * ratio
            guess = x1 + math.log(ratio) * (x1 - x0) / math.log(f1 / f0)
            sol = newton.solve(functools.partial(self._at_force, near), guess, tol=self.residual_tol,
                               floor=self.residual_floor)
            if sol.success:
                points.append((near, sol.x))
                ratio = min(ratio * ratio, _END_RATIO)
            else:
                ratio = math.sqrt(ratio)
        force, x = points[-1]
        if force >= _FORCE_CAP or self.edge_tension(x, force) >= _EDGE_SLACK * self.inflated_tension:
            return _NO_END
        return End(force=float(force), angle=0.0, fold=False, path=(), reason=CAPSULE_EDGE)

    @property
    def inflated_tension(self) -> float:
        """T / (E T) of the inflated capsule: Phat_I lambda_I / 2 (Laplace's law)."""
        return 0.5 * self.inflated.pressure * self.inflated.stretch_pole

    def edge_tension(self, x, force) -> float:
        """T_1 / (E T) at the contact edge of the solved unknowns x at ``force``."""
        _, _, a, _, _ = self.geometry(x, force)
        edge = self.shoot(x, force)[4]
        return float(tensions(edge[3], edge[0] / math.sin(a), self.law.code, self.law.params)[0]) * \
            self.law.tension_scale

    def _neighbour(self, force, x):
        """[(force, x) and (a force a little below or above, its solved x)] in order of force, from the solved x at
        ``force``; None if no neighbour solves (the steps ``_AHEAD``, above first)."""
        for sign in (1.0, -1.0):
            for step in _AHEAD:
                near = (1.0 + sign * step) * force
                sol = newton.solve(functools.partial(self._at_force, near), x, tol=self.residual_tol,
                                   floor=self.residual_floor)
                if sol.success:
                    pair = [(force, x), (near, sol.x)]
                    return pair if sign > 0 else pair[::-1]
        return None

    def _at_force(self, force, x):
        """``residual(x, force)``, the force first (for ``functools.partial``)."""
        return self.residual(x, force)

    def untouched(self, state: CompressedState) -> CompressedState:
        """The inflated capsule seen as a compressed state at Fhat = 0 (``state``), with a capsule's keys."""
        inflated = self.inflated
        return dataclasses.replace(state, contact_radius_deformed=0.0,
                                   extra={**inflated.extra, "stretch_pole": inflated.stretch_pole, "force_ETR": 0.0})

    def on_branch(self, force):
        return None


_NO_END = End(force=math.inf, angle=0.0, fold=False, path=(), locks=True,
              reason="the stretches grow without bound as the plates close")
