r"""The end of the solid's compression range, by the membrane solvers' rules, and the refusal of a load past it.

The membrane's range ends where its sheet reaches the clamp plane (the free part, as under the plate; under
a sphere also its pole, on the sphere's lowest point) or where its contact reaches the sphere's equator (a
profile's end): ``pocket.shooting.plateend`` and ``pocket.shooting.surfaceend``. The solid's sheet has a
thickness. What it reports as the sheet is its mid-surface (a state's profile), and its clamp plane is the
flat sheet's mid-plane z = 0, which its heights are measured from. So the solid's range ends where the
first of these lengths (units R, positive inside the model: ``margins``) reaches zero:

- the mid-surface's lowest height over the contact zone (r <= r_c, ``results.contact_radius``): the sheet
  under the indenter reaching the clamp plane. The indenter touches the upper surface, half the sheet's
  deformed thickness above the mid-surface, so its lowest point is still above the plane then. Every state the
  solid returns has both its sheet (at its nodes) and the indenter's lowest point above the clamp plane. (An
  end at the indenter's lowest point h = 0 would let the mid-surface, and the lower surface further, dip about
  half a thickness below the plane; the two ends differ by that travel, O(T/R) like the solid's other
  differences from the membrane.)
- the mid-surface's lowest height over the free part (r_c < r < 1, the clamp's own node, fixed at z = 0,
  left out; with the clamp's upper jaw, r < 1 - its edge's radius): the free part reaching the clamp plane;
- the indenter's reach less the contact's deformed radius rho_c (its upper surface's at r_c): the contact
  reaching the sphere's equator or the profile's last radius.

Along a load path (``compression``) the margins of each converged state are checked. The first state with one
at or below zero is past the end, which lies between it and the state before. The end is located there by the
Illinois variant of regula falsi on the smallest margin as a function of the load (the force, or the
indenter's height under height control), each trial solved by Newton from the last state inside, until the
bracket is narrower than ``END_RTOL`` of the load (or, after ``MAX_TRIALS`` trials, as it stands: then both
its ends are quoted). The end quoted is the bracket's inside end, the last load solved inside the model: a
load up to it solves; a load past the bracket's other end, within ``END_RTOL`` of it, is refused
(``pocket.core.errors.beyond_range``), naming the end and what closes it (the smallest margin past it). A
trial whose Newton iterates put a node in contact past the indenter's reach (``contact.rows``, an
OutOfRangeError) counts as outside, its margin unknown: that step bisects the bracket. A margin that dips
below zero and comes back between two steps of the path (at most ``compression.MAX_FORCE_STEP`` in Fhat) is
not seen.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from pocket.core.errors import CLAMP_PLANE, OutOfRangeError, beyond_range

from .contact import Surface
from .contact import force as force_of
from .equations import Control
from .model import Model
from .newton import contact
from .results import contact_radius

__all__ = ["END_RTOL", "margins", "past_end"]

#: the bracket's width at the end, relative to the load (force or height) there: the margins are solved to the
#: Newton tolerance (1e-10 R by default), the force moves by ~10 Fhat per R of travel near the end, so the end
#: is resolved to ~1e-9 and a narrower bracket would chase Newton's error
END_RTOL = 1e-8
#: trials before the bracket is quoted as it stands (Illinois narrows a smooth margin's bracket in ~10)
MAX_TRIALS = 60


def _under(surface: Surface) -> str:
    """The reason of the contact zone's margin, naming the indenter."""
    what = surface.word
    return (f"the sheet's mid-surface under the {what} reaches the clamp plane (the {what}'s lowest point half "
            "the sheet's thickness above it)")


def margins(model: Model, y: np.ndarray, control: Control) -> dict[str, float]:
    """What stands between the state y in contact on ``control.active`` and the end of the range (module
    docstring): reason -> margin (units R), positive inside the model."""
    surface, active = control.surface, np.asarray(control.active)
    r_c = contact_radius(model, y, active, surface)
    eta = y[model.mid_dofs[1]]
    under = model.mid_r <= r_c
    # the free part ends at the clamp, or where the clamp's upper jaw's edge begins (``jaw``): beneath the edge the
    # sheet wraps the jaw, which may press its mid-surface a little below the plane (4e-4 T at 0.03 T from the
    # clamp, under an edge of radius T at corner elements T/16): the jaw's corner, not the free sheet's end
    free = ~under & (model.mid_r < (1.0 if control.jaw is None else 1.0 - control.jaw.radius))
    out = {_under(surface): float(eta[under].min()),
           CLAMP_PLANE: float(eta[free].min()) if free.any() else np.inf}
    if not surface.flat:
        rho_c = float(np.interp(r_c, model.top_r, model.top_r + y[model.top_radial]))
        out[f"the sheet would wrap past {surface.end}"] = surface.reach - rho_c
    return out


def _trial(model, inside, key, load, tol):
    """(y, control, margins) at ``key`` = ``load``, solved from the ``inside`` state (y, control); margins None
    if the contact left the indenter's surface on the way."""
    y, control = inside
    try:
        y, control, _ = contact(model, y, dataclasses.replace(control, **{key: load}), tol)
    except OutOfRangeError:
        return None, None, None
    return y, control, margins(model, y, control)


def _locate(model, inside, outside, key, tol):
    """The end between the ``inside`` state (load, y, control, smallest margin > 0) and the ``outside`` load
    (load, margins or None): (the last load inside, its y and control, the nearest load found outside, the
    reason there)."""
    (a, y, control, m_a), (b, out) = inside, outside
    m_b = None if out is None else min(out.values())
    kept = 0  # +1 while the outside end is kept, -1 while the inside end is (Illinois: halve the kept margin)
    for _ in range(MAX_TRIALS):
        if abs(b - a) <= END_RTOL * abs(a):
            break
        c = None if m_b is None else a + (b - a) * m_a / (m_a - m_b)
        pad = 0.25 * END_RTOL * abs(a)  # a trial at an end of the bracket would not narrow it: bisect instead
        if c is None or not min(a, b) + pad < c < max(a, b) - pad:
            c = 0.5 * (a + b)
        y_c, control_c, out_c = _trial(model, (y, control), key, c, tol)
        m_c = None if out_c is None else min(out_c.values())
        if m_c is not None and m_c > 0.0:
            a, y, control, m_a = c, y_c, control_c, m_c
            kept = min(kept, 0) - 1
            if kept <= -2 and m_b is not None:
                m_b *= 0.5
        else:
            b, out, m_b = c, out_c if out_c is not None else out, m_c
            kept = max(kept, 0) + 1
            if kept >= 2:
                m_a *= 0.5
    reason = f"the sheet would wrap past {control.surface.end}" if out is None else min(out, key=out.get)
    return a, y, control, b, reason


def past_end(model: Model, inside, outside, key: str, target: float, unit: float, tol: float) -> OutOfRangeError:
    """The error refusing ``key`` = ``target`` ("force", mu_0 R^2, or "height", R), past the end that lies
    between the ``inside`` state (load, y, control) and the ``outside`` load (load, its margins or None),
    located there (module docstring); ``unit`` is the force of Fhat = 1, the Newton tolerance ``tol``."""
    load, y, control = inside
    end, y, control, beyond, reason = _locate(model, (load, y, control, min(margins(model, y, control).values())),
                                              outside, key, tol)
    scale = unit if key == "force" else 1.0
    at = f"{key} = {end / scale:.10g}"
    if abs(beyond - end) > END_RTOL * abs(end):
        at = f"{at} to {beyond / scale:.10g} (the last {key} solved inside and the nearest found beyond)"
    if key == "height":
        at = f"{at}, force = {force_of(model, control.surface, y, np.asarray(control.active)) / unit:.10g}"
    return beyond_range(f"{key} = {target / scale:.10g}", f"{at} (the solid at T/R = {model.thickness:.6g})", reason)
