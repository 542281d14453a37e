r"""Numbers behind "where the paper and the model disagree", from the full (shooting) model.

- ``eq9_residuals``: eq (9) of the paper evaluated on the shooting solution, as
  printed (pressure term ``(1/2) Phat (1+alpha)``) and corrected (``3 (1+alpha) Phat r~``),
  against dw/dr of the solution, w = d rho / d r~. Derivatives by np.gradient
  (second order on the solver's points); eq (9) reads, with t = T / (2 C1 T) of
  eq (6) and root = (lambda_1^2 - w^2)^(1/2) = -d eta / d r~,

      w' = lambda_1 root / (r~ t1) [root t2 / (lambda_1 lambda_2) - term] + (w / lambda_1) lambda_1'.

- ``pole_tensions``: T1 at the pole over 2 E T (lambda_0 - 1) at small Phat, for
  several alpha. Linearising eq (6) gives 1 (then eq (18) is alpha-free); the
  paper's eq (17a), T1 = 12 C1 T (lambda_0 - 1), gives 1 / (1 + alpha).
- ``buttons``: the soft button of section 6 by the full model, designed by
  ``pocket.apps.design.design`` ("full": the Phat_I that gives the wanted H0 and the
  Fhat where H/H0 is the target) and as the paper's rules size it ("paper":
  T = 0.216 P_I R^4 / (E H0^3), P_I = 5.7 F / (pi R^2)): each one's H0, H/H0 at the
  paper's Fhat = 1/5.7, and the Fhat (hence the coefficient 1/Fhat in P_I = c F / (pi R^2))
  where H/H0 is the target (``pocket.apps.inverse.force_where``).
- ``small_strain``: the analytical model's inflation error at lambda_0 = 1.1, the
  limit of validity the paper quotes.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from pocket import analytical
from pocket.apps.design import PAPER_FORCE_FACTOR, design
from pocket.apps.inverse import force_where
from pocket.core.errors import OutOfRangeError
from pocket.core.materials import mooney_rivlin

__all__ = ["Evidence", "collect", "eq9_residuals"]

POLE_ALPHAS = (0.0, 47 / 160, 1.0)
POLE_PRESSURE = 1e-3  # small enough for linearisation (lambda_0 - 1 ~ 2e-3)
STRAIN_LIMIT = 0.1  # the paper: the analytical model is good for lambda_0 <= 1.1


@dataclasses.dataclass(frozen=True)
class Evidence:
    """The numbers; see the module docstring. Dicts map alpha (or a name) to values."""

    pole_ratio: dict  # alpha -> T1(0) / (2 E T (lambda_0 - 1)), full model
    small_strain: dict  # key -> analytical / shooting - 1 at lambda_0 = 1.1
    buttons: dict  # "paper" (the paper's rules) / "full" (the full model's design): see ``_button``
    thickness_coefficient: float  # k in T = k P_I R^4 / (E H0^3) that gives H0, full model


def eq9_residuals(inflated) -> dict:
    """Max |w' - eq (9)| / max |w'| for r~ in [0.05, 0.95], with the printed and the corrected term."""
    p, alpha, phat = inflated.profile, inflated.alpha, inflated.pressure
    w, root = np.gradient(p.rho, p.r), -np.gradient(p.eta, p.r)
    dw, dl1 = np.gradient(w, p.r), np.gradient(p.stretch_1, p.r)
    inside = (p.r >= 0.05) & (p.r <= 0.95)
    r, l1, l2, w, root, dw, dl1 = (a[inside] for a in (p.r, p.stretch_1, p.stretch_2, w, root, dw, dl1))
    inv = 1.0 / (l1**3 * l2**3)
    t1 = (l1 / l2 - inv) * (1.0 + alpha * l2**2)
    t2 = (l2 / l1 - inv) * (1.0 + alpha * l1**2)
    scale = np.max(np.abs(dw))
    out = {}
    for name, term in (("printed", 0.5 * phat * (1.0 + alpha)), ("corrected", 3.0 * (1.0 + alpha) * phat * r)):
        rhs = l1 * root / (r * t1) * (root * t2 / (l1 * l2) - term) + w / l1 * dl1
        out[name] = float(np.max(np.abs(dw - rhs)) / scale)
    return out


def _pole_ratios() -> dict:
    from pocket import shooting

    out = {}
    for alpha in POLE_ALPHAS:
        state = shooting.inflate(mooney_rivlin(alpha), POLE_PRESSURE)
        assert state.profile is not None  # a shooting state carries its profile
        out[alpha] = float(state.profile.tension_1[0] / (2.0 * (state.stretch_pole - 1.0)))
    return out


def _small_strain(alpha) -> dict:
    from pocket.shooting.inflation import pressure_of_stretch

    from pocket import shooting

    rubber = mooney_rivlin(alpha)
    phat = pressure_of_stretch(1.0 + STRAIN_LIMIT, rubber) / (3.0 * (1.0 + alpha))
    full, model = shooting.inflate(rubber, phat), analytical.inflate(rubber, phat)
    return {"pressure_hat": float(phat), "height": float(model.height / full.height - 1.0),
            "volume": float(model.volume / full.volume - 1.0)}


def _button(rubber, phat, state, target, at=None) -> dict:
    """Phat_I, H0/R and H/H0 of ``state`` (None: no state there), the Fhat where H/H0 = ``target``
    (``at``, else solved for) and the coefficient 1/Fhat."""
    from pocket import shooting

    if at is None:
        at = force_where(shooting.SOLVER, rubber, phat, "height_ratio", target, increasing=False)
    return {"pressure_hat": float(phat), "height": None if state is None else float(state.inflated.height),
            "height_ratio": None if state is None else float(state.height_ratio),
            "force_at_target": float(at), "coefficient": 1.0 / at}


def _buttons(button) -> tuple[dict, float]:
    """The "full" and "paper" buttons (module docstring) and k of T = k P_I R^4 / (E H0^3), full model."""
    from pocket import shooting

    rubber, force, target = mooney_rivlin(button.alpha), 1.0 / PAPER_FORCE_FACTOR, button.height_ratio
    full = design(button.radius, button.height, button.modulus, rubber, button.force, target, solver="shooting")
    pressure, thickness = button.paper
    phat_paper = pressure * button.radius / (button.modulus * thickness)
    try:
        paper_state = shooting.compress(rubber, phat_paper, force)
    except OutOfRangeError:  # the paper's rules can ask for a pocket the model does not have
        paper_state = None
    buttons = {"full": _button(rubber, full.pressure_initial, shooting.compress(rubber, full.pressure_initial, force),
                               target, at=full.force),
               "paper": _button(rubber, phat_paper, paper_state, target)}
    return buttons, (button.height / button.radius) ** 3 / full.pressure_initial


def collect(button) -> Evidence:
    """Compute the evidence for ``button`` (a ``suite.Button``)."""
    buttons, coefficient = _buttons(button)
    return Evidence(pole_ratio=_pole_ratios(), small_strain=_small_strain(button.alpha), buttons=buttons,
                    thickness_coefficient=float(coefficient))
