"""How much a validation run computes: the default run and ``--quick``.

Budgets (2 cores): the default under 2 minutes, ``--quick`` under 30 s. The
shooting and analytical columns are cheap (a compression curve in well under a
second), so every case gets them in both plans; the finite-element curves at the
default mesh cost seconds per force (tens of Newton iterations per load step),
so the headline case gets a FE curve to the end of the range, the cases tagged
"fem" (the alpha extremes, the lowest pressure) three forces, the others their
inflated state; ``--quick`` keeps the headline case's FE columns at three forces.
"""

from __future__ import annotations

import dataclasses

__all__ = ["Plan", "DEFAULT", "QUICK", "RANGE_FRACTION"]

#: curves run to this fraction of the end of the shooting model's range
RANGE_FRACTION = 0.95


@dataclasses.dataclass(frozen=True)
class Plan:
    """What a run computes.

    curve_points: shooting / analytical points on a linear Fhat grid to the range end
        (small forces, where the analytical model holds, and the design forces are added).
    fem: case tag -> Fhat of the FE curves at the default mesh, the first tag of the
        case found here wins, "*" matches every case; ``None`` stands for
        RANGE_FRACTION times the end of the range, 0 gives the inflated state.
    convergence_sizes: element counts per order of the mesh-convergence study.
    """

    name: str
    curve_points: int
    fem: dict
    convergence_sizes: dict

    def fem_forces_of(self, case) -> tuple:
        """The FE forces of ``case`` (empty: no FE column in this plan)."""
        for tag in (*case.tags, "*"):
            if tag in self.fem:
                return self.fem[tag]
        return ()


DEFAULT = Plan(
    name="default",
    curve_points=40,
    fem={"headline": (0.0, 0.05, 0.19, 0.5, 1.0, 2.0, 4.0, None), "fem": (0.0, 0.19, 1.0), "*": (0.0,)},
    convergence_sizes={1: (16, 32, 64, 128, 256), 2: (8, 16, 32, 64, 128)},
)

QUICK = Plan(
    name="quick",
    curve_points=20,
    fem={"headline": (0.0, 0.19, 1.0)},
    convergence_sizes={1: (32, 64, 128), 2: (16, 32, 64)},
)
