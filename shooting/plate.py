"""Step 2 of one inflated pocket under the flat plate as a shooting problem: unknowns, shots and state.

Contact zone (0 <= r <= a): the sheet lies flat on the plate; tangential
equilibrium with no friction and regularity at the axis leave the uniform
equibiaxial stretch rho = lambda_c r, lambda_1 = lambda_2 = lambda_c (the normal
load is carried by the plate). At the contact edge the tension T_1 and the
position are continuous and the meridian is horizontal (a smooth plate cannot
exert a line force), so the free part a <= r <= 1 starts from
rho = lambda_c a, psi = 0, lambda_1 = lambda_c and is integrated to the clamp.

Unknowns x = (q, e) and the two residuals every contact shares (``pocket.shooting.contact``;
V = -pi int rho^2 eta' dr over the free part alone, eta' = 0 on the contact zone). The force fixes the
contact radius: F = P A_c with A_c = pi (lambda_c a)^2 gives Fhat = q (lambda_c a)^2,
so a = sqrt(Fhat / q) / lambda_c. The end of the range is ``pocket.shooting.plateend``.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from pocket.core.states import CompressedState

from . import plateend
from .contact import Contact, final_shots
from .shots import profile_from_steps, shot_edge, tension_minima

__all__ = ["PlateProblem"]


@dataclasses.dataclass(frozen=True)
class PlateProblem(Contact):
    """The compression of ``inflated`` by the flat plate (module docstring); fields as ``Contact``."""

    def start(self) -> np.ndarray:
        """Unknowns (q, e) of the inflated state (Fhat -> 0): the guess for the first force."""
        return np.array([1.0, 1.0])

    def geometry(self, x, force):
        """(q, lambda_c, a, p) for unknowns x at ``force``, or None outside the model's domain."""
        q, e = x[0], x[1]
        lc = self.stretch(e)
        if not (q > 0.0 and lc > 0.0 and force > 0.0):
            return None
        a = math.sqrt(force / q) / lc
        if not a < 1.0:
            return None
        return q, lc, a, self.law.pressure_factor * self.inflated.pressure * q

    def _shot(self, geometry, store):
        """(status, y(1), steps) of the free part at ``geometry`` = (q, lambda_c, a, p)."""
        _q, lc, a, p = geometry
        return shot_edge(lc, a, self.law, p, self.tolerance, store=store)

    def _closure(self, x, force, shot) -> tuple:
        """None beyond the common two: the force fixes the contact radius (module docstring)."""
        return ()

    def compressed(self, force, x, fluid) -> tuple[CompressedState, float]:
        """The compressed state at ``force`` (as given, ``fluid`` too) for the solved unknowns x, and its
        clamp angle psi(1)."""
        q, lc, a, p = self.geometry(x, force)
        status, y, _ = self.shoot(x, force)
        profile_status, _, steps = self.shoot(x, force, store=20000)
        final_shots(force, status, profile_status)
        inflated = self.inflated
        height = -y[1]
        profile = profile_from_steps(steps, self.law, lc, contact_radius=a)
        low = tension_minima(profile, steps, self.law, p, self.tolerance)
        state = CompressedState(
            pressure_initial=inflated.pressure, force=force, pressure=inflated.pressure * q, pressure_ratio=q,
            contact_area=(lc * a) ** 2, contact_radius=a, stretch_contact=lc, height=height,
            height_ratio=height / inflated.height, volume=y[4], profile=profile, inflated=inflated,
            solver="shooting", material=inflated.material, fluid=fluid, tension_1_min=low[0],
            tension_2_min=low[1], indenter=self.indenter,
        )
        return state, y[2]

    def end(self, seed):
        """The range end from the solved (force, x) ``seed`` or None (``pocket.shooting.plateend``)."""
        return plateend.plate_end(self, seed)

    def on_branch(self, force):
        """Unknowns x at ``force`` near a fold, found on the end's branch by the clamp angle, or None
        (``pocket.shooting.plateend.solve_on_branch``)."""
        return plateend.solve_on_branch(self, force)
