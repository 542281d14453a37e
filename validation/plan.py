"""How much a validation run computes: the default run and ``--quick``, the solver columns, and how much of
the headline path the report writes as VTK (``VTK``).

Budgets on 2 cores: the default under 60 s, ``--quick`` under 20 s. The
shooting and analytical columns are cheap (a compression curve in well under a
second), so every case gets them in both plans. Finite-element curves cost the
most, so the plan says per case tag at which forces the FE columns run: the
headline case to the end of the range, the cases tagged "fem" (the alpha
extremes, the lowest pressure) at a few forces, those tagged "fem-range" (the
other rubber laws and the gas-filled pockets) from the inflated state to near
the end of the range, the others at their inflated state; ``--quick`` keeps the
headline case's FE columns at three forces and the "fem-range" cases' at the
inflated state, Fhat = 1 and near the end of the range: every law and fluid is
cross-checked in both plans. The pockets pressed by a sphere (tag "sphere") get the P2
column only (``Plan.columns_of``): the P2 FE model against shooting is the verdict under a
curved indenter, and a P1 curve costs about five times a P2 one there; their forces include
Fhat = 0.5, where the contact-pressure figure compares the two solvers. Each law is
fitted to FE bulge data (``Plan.fits``): Ogden with two terms by default (about 10 s of a
worker), one term in ``--quick``. The capsules of ``capsules.CASES`` (every law and fluid) are pressed by the
shooting solver at 21 forces to Fhat = 5 (11 in ``--quick``), spaced quadratically (the force rises slowly at
first: a dent), each a task of well under a second. The report's timing table
gives each task's seconds, to re-tune these numbers.

A column is a solver of ``pocket.apps.solvers`` with options, checked by its
record when the plan is built: the same checks as the command line's flags and
the case files' ``[solver]`` tables.
"""

from __future__ import annotations

import dataclasses

from pocket.apps.solvers import record, solver_options

from .suite import on_plate

__all__ = [
    "APPROXIMATE",
    "DEFAULT",
    "FEM_COLUMNS",
    "INDENTER_COLUMNS",
    "QUICK",
    "RANGE_FRACTION",
    "REFERENCE",
    "VTK",
    "VTK_STEPS",
    "Column",
    "Plan",
]

#: curves run to this fraction of the end of the shooting model's range
RANGE_FRACTION = 0.95
#: how much of the headline pocket's compression path the report writes as VTK: VTK_STEPS of its forces (the
#: default: the folder stays a few MB, small enough to mail), every one, none
VTK = ("few", "all", "none")
#: the states of the default ("few") VTK series, spread evenly along the path, both ends included
VTK_STEPS = 12


@dataclasses.dataclass(frozen=True)
class Column:
    """A solver (a name in ``pocket.apps.solvers.SOLVERS``) with options, named ``label`` in the report."""

    solver: str
    label: str
    options: tuple[tuple[str, object], ...] = ()

    def __post_init__(self):
        checked = solver_options(self.solver, dict(self.options), "compress", spell=lambda k: f"{self.label}: {k}")
        object.__setattr__(self, "options", tuple(checked.items()))

    def kwargs(self, step: str = "compress") -> dict:
        """The options that ``step`` ("inflate" or "compress") takes, as keyword arguments."""
        solver, out = record(self.solver), {}
        for name, value in self.options:
            option = solver.option(name)
            assert option is not None, name  # every option was checked against the record (__post_init__)
            if step in option.steps:
                out[name] = value
        return out


REFERENCE = Column("shooting", "shooting")
APPROXIMATE = Column("analytical", "analytical")
FEM_COLUMNS = (Column("fem", "FEM P1", (("order", 1),)), Column("fem", "FEM P2", (("order", 2),)))
#: the FE columns of a pocket pressed by a curved indenter (module docstring)
INDENTER_COLUMNS = FEM_COLUMNS[1:]


@dataclasses.dataclass(frozen=True)
class Plan:
    """What a run computes.

    curve_points: shooting / analytical points per spacing (linear and geometric) on the Fhat
        grid to the range end (small forces, where the analytical model holds, and the design
        forces are added).
    fem: case tag -> Fhat of the FE columns, the first tag of the case found here wins, "*"
        matches every case; ``None`` stands for RANGE_FRACTION times the end of the range, 0
        gives the inflated state.
    convergence_sizes: element counts per order of the mesh-convergence study.
    fem_columns: the FE columns compared with the reference (shooting) on a pocket pressed by the plate.
    indenter_columns: those of a pocket pressed by a curved indenter.
    fits: the laws (with their number of terms) fitted to FE bulge data (``identification``).
    thickness: the pressures P_I (kPa) and the forces Fhat at which the paper's four samples are solved by the
        membrane and the solid (``thickness``); empty: no such section.
    thickness_refined: whether the solid of that section is solved again on a finer mesh, its own uncertainty
        beside each membrane error (``thickness.REFINED``: ten times the default's time).
    capsules: the forces Fhat at which each capsule of the suite is pressed by the shooting solver
        (``capsules``); empty: no capsule section.
    capsule_fem: the forces at which the FE model (P2) presses them too; 0 gives the inflated capsule.
    capsule_sizes: element counts of the FE model's mesh convergence on a capsule; empty: no such study.
    solid_study: the paper's samples whose solid is refined along each axis (``solidstudy``); empty: no such study.
    solid_refined: the element counts along the radius, the layers and the corner elements' lengths (in T, each
        half the one before) of that study, each holding the solid's default.
    """

    name: str
    curve_points: int
    fem: dict
    convergence_sizes: dict
    fem_columns: tuple[Column, ...] = FEM_COLUMNS
    indenter_columns: tuple[Column, ...] = INDENTER_COLUMNS
    fits: tuple[tuple[str, int], ...] = ()
    thickness: tuple[tuple[float, ...], tuple[float, ...]] | tuple = ()
    thickness_refined: bool = False
    capsules: tuple[float, ...] = ()
    capsule_fem: tuple[float, ...] = ()
    capsule_sizes: tuple[int, ...] = ()
    solid_study: tuple[int, ...] = ()
    solid_refined: tuple[tuple[float, ...], ...] = ((), (), ())

    def fem_forces_of(self, pocket) -> tuple:
        """The FE forces of ``pocket`` (empty: no FE column for it in this plan)."""
        for tag in (*pocket.case.tags, "*"):
            if tag in self.fem:
                return self.fem[tag]
        return ()

    def columns_of(self, pocket) -> tuple[Column, ...]:
        """The FE columns of ``pocket``: by the indenter that presses it."""
        return self.fem_columns if on_plate(pocket) else self.indenter_columns


DEFAULT = Plan(
    name="default",
    curve_points=40,
    fem={"headline": (0.0, 0.05, 0.19, 0.5, 1.0, 2.0, 4.0, None), "fem": (0.0, 0.19, 1.0),
         "fem-range": (0.0, 0.19, 1.0, 4.0, None), "sphere": (0.19, 0.5, 1.0, None), "*": (0.0,)},
    convergence_sizes={1: (16, 32, 64, 128, 256), 2: (8, 16, 32, 64, 128)},
    fits=(("neo-hookean", 1), ("mooney-rivlin", 1), ("yeoh", 1), ("gent", 1), ("ogden", 2)),
    thickness=((2.0, 5.0), (0.2, 0.5, 1.0)),
    thickness_refined=True,
    capsules=tuple(round(5.0 * (k / 20) ** 2, 12) for k in range(21)),
    capsule_fem=(0.0, 0.2, 1.25, 3.2, 5.0),
    capsule_sizes=(32, 64, 128, 256),
    solid_study=(1, 4),
    solid_refined=((12, 24, 48, 96, 192), (2, 4, 8), (0.25, 0.125, 0.0625)),
)

QUICK = Plan(
    name="quick",
    curve_points=20,
    fem={"headline": (0.0, 0.19, 1.0), "fem-range": (0.0, 1.0, None), "sphere": (0.5, None)},
    convergence_sizes={1: (32, 64, 128), 2: (16, 32, 64)},
    fits=(("neo-hookean", 1), ("mooney-rivlin", 1), ("yeoh", 1), ("gent", 1), ("ogden", 1)),
    thickness=((5.0,), (0.5,)),
    capsules=tuple(round(5.0 * (k / 10) ** 2, 12) for k in range(11)),
    capsule_fem=(0.0, 1.25, 5.0),
    capsule_sizes=(32, 64, 128),
    solid_study=(4,),
    solid_refined=((24, 48, 96), (2, 4, 8), (0.25, 0.125, 0.0625)),
)
