r"""A fit's 95 % intervals by the profile likelihood: each parameter held at trial values, the others re-fitted.

The linearised interval (``pocket.apps.fit.stats``) assumes the residuals are linear in the parameter over
its interval. Where they are strongly nonlinear it fails: Gent's Jm enters through the locking term, the
curve sees about 1/Jm, and an interval symmetric in Jm misses the truth above it and reaches Jm <= 0, which
the law does not admit. The profile interval asks the data directly. With the fit's residual sum of squares
RSS at the optimum, s^2 = RSS / (n - p), and RSS(theta) the least RSS with the parameter held at theta (the
other p - 1 unknowns re-fitted), the profile statistic

    tau^2(theta) = (RSS(theta) - RSS) / s^2

is the squared t statistic of the hypothesis "the parameter is theta" (Bates and Watts, Nonlinear regression
analysis, 1988, sec. 6.1: its distribution is t_{n-p}^2 = F_{1, n-p} to the order the linearisation holds,
and exactly so where the model is linear), and the interval is {theta : tau(theta) <= t_{0.975, n-p}}. It
is the linearised one for a linear model, and follows the data where the model bends.

Search. Each end is found on its own along u, the parameter mapped onto the real line by its admissible set:
u = ln(theta - L) for a parameter bounded below by L (C1, mu, C10, Jm > 0; a fitted prestretch > 1), u =
theta otherwise. Every trial theta is then inside the bounds, and so are the ends. In units of the linearised
error of u (SE_u = SE / (theta - L) by the delta method), tau(u) ~ |u - u_hat| / SE_u near the optimum, so
the first trial is the linearised end u_hat +- t SE_u (in u: for a bounded parameter an interval that is not
symmetric), or a factor e from the optimum in theta - L where t SE_u is larger (the linearisation says
nothing there: Jm = 776 +- 4400). If tau is still below t there, the step grows (by the secant through the
optimum, at least 1.5 times, at most 4), up to a reach (u: ``_DECADES`` decades of theta - L, or 30 t SE_u
for an unbounded parameter) or for ``_TRIALS`` trials; a profile that stays below t that far is not bounded
by the data on that side, and the end is the bound (L below, infinite above; the fit warns). Once bracketed,
the crossing is found by regula falsi (Illinois), or by bisection towards a held value at which some datum
has no state (outside the model's range, such as a Jm below the data's I1 - 3: tau is infinite there), to
``_TOLERANCE`` in tau (an end at a level within about 0.3 % of 95 %), in at most ``_TRIALS`` more trials.
An end is never past a trial with no state.

Cost. Each trial is a least-squares fit of the p - 1 other unknowns from the optimum (shifted along their
regression on the held one), a few evaluations each; a one-parameter fit has none to re-fit and costs one
evaluation a trial. Measured over 25 Gent fits to ten bulge heights with 0-3 % noise: 2.5 trials per end on
average (3.4 where the data see the locking weakly and Jm is often not bounded above), and 115 solver calls
per fit where the fit alone makes about 50.

Where it is not used. Ogden's keys are fitted along other coordinates (``pocket.apps.fit.keys``): holding
mu_p alone would need another parametrisation; their intervals stay linearised. A parameter at a bound keeps
the linearised interval cut there (``pocket.apps.fit.stats`` warns). A fit whose residual RMS is below
``FLOOR`` (noise-free data: the residuals are the solvers' ~1e-10) has no noise for a profile to resolve: its
intervals are the linearised ones in u, mapped back (inside the bounds as well).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable

from .stats import LINEARISED, Statistics, at_bound, quantile

__all__ = ["FLOOR", "LOG_LINEARISED", "PROFILE", "interval", "intervals", "linearised"]

#: residual RMS below which a fit's intervals are not profiled (the solvers' noise, not the data's)
FLOOR = 1e-8
#: the methods, as the report names them (and ``pocket.apps.fit.stats.LINEARISED``)
PROFILE, LOG_LINEARISED = "profile likelihood", "linearised in log"
_TOLERANCE = 0.01  # |tau - t| / t at which an end is accepted: t +- 1 % is a level of 95 +- 0.3 %
_TRIALS = 8  # held values tried per end
_DECADES = 4.0  # reach of the search in theta - L, decades either way (a Jm 1e4 times the fitted one is neo-Hookean)


def _mapping(lower: float):
    """(u(theta), theta(u)) for a parameter bounded below by ``lower`` (module docstring)."""
    if math.isfinite(lower):
        return (lambda v: math.log(v - lower)), (lambda u: lower + math.exp(u))
    return (lambda v: v), (lambda u: u)


def intervals(statistics: Statistics, free, excess: Callable[[int], Callable[[float], float]]) -> Statistics:
    """``statistics`` (``pocket.apps.fit.stats.Statistics``) of a fit of keys ``free`` with each interval made
    by the method the module docstring gives it, named in ``methods``, and a warning for each end the data do
    not bound. ``excess(k)`` is tau^2 of key k as a function of its held value."""
    t, out, methods, warnings = quantile(statistics.dof), statistics.intervals.copy(), [], []
    for k, (key, value, error) in enumerate(zip(free, statistics.values, statistics.standard_errors, strict=True)):
        bounded = math.isfinite(key.lower)
        if key.unknown is not None or at_bound(key, value, abs(statistics.mu0)) or not 0.0 < error < math.inf:
            methods.append(LINEARISED)
            continue
        if statistics.rms < FLOOR:
            out[k], method = linearised(value, error, key.lower, t), LOG_LINEARISED if bounded else LINEARISED
        else:
            out[k], method = interval(excess(k), value, error, key.lower, t), PROFILE
        methods.append(method)
        lo, hi = out[k]
        unbound = [side for side, end, limit in (("below", lo, key.lower), ("above", hi, math.inf)) if end == limit]
        if unbound:
            warnings.append(f"{key.name} = {value:.6g}: the data do not bound it {' or '.join(unbound)} (its 95 % "
                            f"interval is [{lo:.6g}, {hi:.6g}])")
    return dataclasses.replace(statistics, intervals=out, methods=tuple(methods),
                               warnings=(*statistics.warnings, *warnings))


def linearised(value: float, error: float, lower: float, t: float) -> tuple[float, float]:
    """The linearised interval of ``value`` +- ``t`` ``error``, taken in u (module docstring) and mapped back:
    inside (``lower``, inf) for a bounded parameter."""
    u, theta = _mapping(lower)
    step = t * error / (value - lower) if math.isfinite(lower) else t * error
    return theta(u(value) - step), theta(u(value) + step)


def interval(excess: Callable[[float], float], value: float, error: float, lower: float,
             t: float) -> tuple[float, float]:
    """The profile interval (module docstring) of a parameter fitted at ``value`` (above ``lower``, its bound,
    -inf for none) with linearised standard error ``error`` > 0, at the quantile ``t``.

    ``excess(theta)`` is tau^2 at the held value theta: (RSS(theta) - RSS) / s^2, inf where some datum has no
    state."""
    u, theta = _mapping(lower)
    u0 = u(value)
    scale = error / (value - lower) if math.isfinite(lower) else error
    # the first trial: the linearised end, or a factor e in theta - L where the linearisation spans more
    first = min(t, 1.0 / scale) if math.isfinite(lower) else t
    reach = _DECADES * math.log(10.0) / scale if math.isfinite(lower) else 30.0 * t
    ends = []
    for side in (-1.0, 1.0):
        def gap(s, side=side):  # tau - t at the normalised distance s from the optimum, on this side
            return math.sqrt(max(excess(theta(u0 + side * s * scale)), 0.0)) - t
        s = _crossing(gap, t, first, reach)
        ends.append(theta(u0 + side * s * scale) if math.isfinite(s) else lower if side < 0.0 else math.inf)
    return ends[0], ends[1]


def _crossing(gap: Callable[[float], float], t: float, first: float, reach: float) -> float:
    """The normalised distance s >= 0 at which ``gap`` (tau - t, -t at 0) crosses 0, searched from ``first``:
    inf if it does not within ``reach`` (the data do not bound the parameter on this side), else the crossing
    found in ``_TRIALS`` trials, never beyond a trial with no state (module docstring)."""
    inside, g_in = 0.0, -t
    s = min(first, reach)
    for _ in range(_TRIALS):  # grow the step until tau passes t
        g = gap(s)
        if abs(g) <= _TOLERANCE * t:
            return s
        if g > 0.0:
            break
        if s >= reach:
            return math.inf
        inside, g_in = s, g
        secant = s * t / (g + t) if g + t > 0.0 else 4.0 * s
        s = min(max(secant, 1.5 * s), 4.0 * s, reach)
    else:
        return math.inf
    outside, g_out, last = s, g, 0  # Illinois: an end kept twice in a row has its gap halved
    for _ in range(_TRIALS):
        s = _between(inside, g_in, outside, g_out)
        g = gap(s)
        if abs(g) <= _TOLERANCE * t:
            return s
        if g > 0.0:
            outside, g_out, g_in, last = s, g, g_in * (0.5 if last > 0 else 1.0), 1
        else:
            inside, g_in, g_out, last = s, g, g_out * (0.5 if last < 0 else 1.0), -1
    return inside if not math.isfinite(g_out) else _between(inside, g_in, outside, g_out)


def _between(inside: float, g_in: float, outside: float, g_out: float) -> float:
    """The next trial within the bracket: regula falsi, or its midpoint where the outer end has no state."""
    if not math.isfinite(g_out):
        return 0.5 * (inside + outside)
    return inside - g_in * (outside - inside) / (g_out - g_in)
