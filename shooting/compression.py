"""Step 2, compression at fixed volume by a rigid frictionless indenter, force given.

The indenter is an argument (``pocket.core.indenters``): this solver poses the flat plate,
its default (``pocket.shooting.plate``), and every curved indenter it has an entry for, a sphere or
a user's profile (``pocket.shooting.surface``, whose problem the continuation below solves the same
way), and refuses another kind (``pocket.shooting.problem.CONTACTS``).

The shooting problem (unknowns, residuals, their scaling) is ``pocket.shooting.contact`` and the
indenter's formulation; the fluid sealed in the pocket (a liquid: fixed volume; a gas: the
polytropic law) enters only its volume residual.
Each force is solved by the damped Newton-Broyden method of
``pocket.shooting.newton``, by continuation in the force from the inflated state:
forces are taken in increasing order, each seeded by secant extrapolation from
the last two states and the last Jacobian (or, for a problem that gives its Jacobian, that at the
prediction: ``pocket.shooting.continuation``). A step that does not converge is
halved (and the step grows again after successes). Near a fold of the force
(the end of the range for some alpha < 0, ``pocket.shooting.plateend``) continuation in
the force stalls; there the state is found on the branch by its clamp angle instead.
A solve fails, with a ConvergenceError saying at which force, from which force, with
what residual and why, only when both fail and the step is below 1e-9 of the force.

The model's range ends at the force Fhat_end where the free sheet reaches the
clamp plane (``pocket.shooting.plateend``; psi(1) = pi; under a curved indenter also the ends
of ``pocket.shooting.surfaceend``). A force above it is an
OutOfRangeError quoting Fhat_end, the same number whatever force was asked; a
force up to it is solved. Fhat_end is computed (once, cached) only when it can
matter: when a step fails, or when a state's clamp angle psi(1) comes within
1e-6 rad (or 1e4 rtol) of pi, or its indenter's lowest point lies below the clamp plane, or its
contact edge comes within 1e-6 (or 1e4 rtol) of the end of a profile (``pocket.shooting.surface``:
there the shots go on solving past the profile's last radius, so nothing else would stop them).
"""

from __future__ import annotations

import math

import numpy as np

from pocket.core.errors import CAPSULE_EDGE, UNINFLATED_CAPSULE, InputError, OutOfRangeError
from pocket.core.fluids import as_fluid
from pocket.core.geometries import CAPSULE, Symmetry, posed
from pocket.core.indenters import as_indenter
from pocket.core.inputs import FORCE_UNITS, check_choice, check_forces, check_positive, forces_in_fhat
from pocket.core.states import CompressedState

from .capsule import CapsuleProblem
from .contact import Contact
from .continuation import Branch, advance, band, beyond, past_the_profile
from .descent import branch_start, capsule_at_force
from .inflation import GEOMETRIES, inflate
from .laws import law_of
from .problem import problem_of

__all__ = ["compress", "compression_curve"]


def _uncompressed(problem: Contact, force: float, fluid) -> CompressedState:
    """Fhat = 0: the inflated state itself, seen as a compressed state with no contact (at P_I = 0, the unstressed
    capsule touched by the plates: its ``force`` and ``pressure_ratio`` NaN, its ``force_ETR`` 0)."""
    inflated = problem.inflated
    state = CompressedState(
        pressure_initial=inflated.pressure, force=force if inflated.pressure > 0.0 else math.nan,
        pressure=inflated.pressure, pressure_ratio=1.0 if inflated.pressure > 0.0 else math.nan, contact_area=0.0,
        contact_radius=0.0,
        stretch_contact=inflated.stretch_pole, height=inflated.height, height_ratio=1.0,
        volume=inflated.volume, profile=inflated.profile, inflated=inflated, solver="shooting",
        material=inflated.material, fluid=fluid, tension_1_min=inflated.tension_1_min,
        tension_2_min=inflated.tension_2_min, indenter=problem.indenter,
    )
    return problem.untouched(state) if isinstance(problem, CapsuleProblem) else state


def _uninflated(material, forces: list[float], fluid, rtol: float, progress) -> list[CompressedState]:
    """The uninflated capsule's states at the forces F / (E T R) (``compression_curve``), each its own root; at
    F = 0 the unstressed sphere the plates touch, the one state of its branch from the touch."""
    states: dict[float, CompressedState] = {}
    start = None  # where the branch reached deep starts, once located
    for done, force in enumerate(forces, start=1):
        if force == 0.0 and force not in states:
            sphere = inflate(material, 0.0, geometry=CAPSULE, rtol=rtol)
            states[force] = _uncompressed(CapsuleProblem(sphere, rtol, law_of(material), fluid), force, fluid)
        if force not in states:
            start = start or branch_start(material, 0.0, fluid=fluid, rtol=rtol)
            states[force] = capsule_at_force(material, 0.0, force, fluid=fluid, rtol=rtol, start=start)
        if progress is not None:
            progress(done, len(forces))
    return [states[f] for f in forces]


def _pressed(problem: Contact, branch: Branch, force: float, fluid, rtol: float) -> tuple[CompressedState, Branch]:
    """The state at ``force`` continued along ``branch``, and the branch extended to it; an OutOfRangeError past
    the range's end (``beyond``)."""
    branch = advance(problem, branch, force)
    past_the_profile(problem, force, branch.points[-1][1])
    state, clamp_angle = problem.compressed(force, branch.points[-1][1], fluid)
    # a solved state past an end: an indenter's lowest point below the clamp plane (a taut, prestretched sheet under
    # a small sphere gets there with no failed step), or the free sheet at the clamp plane
    if state.height < 0.0:  # no seed: the end is sought from inside the range
        beyond(force, problem, None)
    if clamp_angle >= math.pi - band(rtol):
        beyond(force, problem, branch.points[-1])
    return state, branch


def compression_curve(material, pressure_initial, forces, *, fluid=None, indenter=None, geometry=None, rtol=1e-10,
                      progress=None, force_unit="Fhat") -> list[CompressedState]:
    """Compress the inflated pocket at each force Fhat = F / (P_I pi R^2) of ``forces``, by continuation.

    The pocket is inflated at Phat_I (``inflate``), its fluid sealed, then pressed by the indenter; the
    forces are taken in increasing order, each state seeded by those before it.

    Parameters
    ----------
    material : Material or float
        The rubber, a ``pocket.core.materials.Material`` (any stress unit) or a Mooney-Rivlin alpha = C2/C1.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0, the inflation pressure the fluid is sealed at.
    forces : sequence of float
        Fhat = F / (P_I pi R^2) >= 0 of each state, in any order.
    fluid : Fluid or str, optional
        None or ``"liquid"`` (fixed volume), or a gas (``pocket.core.fluids.gas``) with its ambient pressure
        in the model's units, Phat_atm = P_atm R / (E T).
    indenter : Indenter, optional
        None (the flat plate) or a ``pocket.core.indenters.Indenter`` this solver poses (``Sphere``,
        ``Profile``), lengths in units of R.
    geometry : Geometry or str, optional
        The reference surface: None (the flat clamped disc) or one this solver poses (``GEOMETRIES``).
    rtol : float, optional
        Relative tolerance of the ODE integration, at most 1e-4.
    progress : callable, optional
        ``progress(done, total)``, called after each force (``total`` = len(forces)).
    force_unit : {"Fhat", "ETR"}, optional
        The unit of ``forces``: Fhat (default) or F / (E T R), the force on each plate of a capsule in units of
        its wall's E T and its radius R: the only unit of an uninflated capsule's (P_I = 0, ``geometry="capsule"``),
        whose states lie deep (``pocket.shooting.descent.capsule_at_force``), the force found to a relative 1e-12
        and reported as ``extra["force_ETR"]``.

    Returns
    -------
    list of CompressedState
        In the order of ``forces``, each echoing its inputs exactly.

    Raises
    ------
    InputError
        For invalid input (an indenter or geometry this solver does not pose, a negative force, no force).
    OutOfRangeError
        For a force past the end of the model's range (``range_end``), or a Phat_I above the pressure maximum.
    ConvergenceError
        If a solve fails; it says at which force.

    Examples
    --------
    >>> from pocket import shooting
    >>> states = shooting.compression_curve(47 / 160, 0.31, [0.1, 0.19])
    >>> print([f"{s.pressure_ratio:.4f}" for s in states])
    ['1.1564', '1.2944']

    The fluid's volume is held:

    >>> print(all(abs(s.volume - s.inflated.volume) < 1e-9 for s in states))
    True
    """
    geometry, _ = posed(GEOMETRIES, "shooting", geometry)
    law = law_of(material)
    unit = check_choice("force_unit", force_unit, FORCE_UNITS)
    if isinstance(geometry.end, Symmetry) and pressure_initial == 0:
        if unit == "Fhat":
            raise InputError(f"pressure = 0: {UNINFLATED_CAPSULE}")
        problem_of(geometry, as_indenter(indenter))  # an InputError for an indenter other than the plates
        return _uninflated(material, check_forces(forces), as_fluid(fluid), rtol, progress)
    pressure_initial = check_positive("pressure", pressure_initial)
    fluid = as_fluid(fluid)
    indenter = as_indenter(indenter)
    forces = forces_in_fhat(list(np.atleast_1d(np.asarray(forces, dtype=object))), unit, pressure_initial)
    problem = problem_of(geometry, indenter)(inflate(material, pressure_initial, geometry=geometry, rtol=rtol), rtol,
                                           law, fluid, indenter)
    if isinstance(problem, CapsuleProblem):
        problem.conditioned()
    counts = {f: forces.count(f) for f in forces}
    states, done = {}, 0
    branch = Branch(points=((0.0, problem.start()),))
    deep = None  # a capsule's first branch's end, once a force is past it: the later forces lie deeper
    start = None  # ... and where the branch reached deep starts, once located
    for f in sorted(counts):
        if f == 0.0:
            states[f] = _uncompressed(problem, f, fluid)
        elif deep is None:
            try:
                states[f], branch = _pressed(problem, branch, f, fluid, rtol)
            except OutOfRangeError as err:
                if not isinstance(problem, CapsuleProblem) or err.end is None or CAPSULE_EDGE not in str(err):
                    raise
                deep = err.end
        if f not in states:
            assert deep is not None, "a force the first branch did not solve is past its end"
            start = start or branch_start(material, pressure_initial, fluid=fluid, rtol=rtol)
            states[f] = capsule_at_force(material, pressure_initial, f, deep, fluid=fluid, rtol=rtol, start=start)
        done += counts[f]
        if progress is not None:
            progress(done, len(forces))
    return [states[f] for f in forces]


def compress(material, pressure_initial, force, *, fluid=None, indenter=None, geometry=None,
             rtol=1e-10, force_unit="Fhat") -> CompressedState:
    """Compress the pocket inflated at Phat_I = ``pressure_initial`` by the force Fhat = F / (P_I pi R^2).

    One state of ``compression_curve``.

    Parameters
    ----------
    material : Material or float
        The rubber, a ``pocket.core.materials.Material`` (any stress unit) or a Mooney-Rivlin alpha = C2/C1.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0.
    force : float
        Fhat = F / (P_I pi R^2) >= 0 (or F / (E T R): ``force_unit``).
    fluid, indenter, geometry, rtol, force_unit
        As for ``compression_curve``.

    Returns
    -------
    CompressedState
        Pressures in units of E T / R, lengths of R, the deformed contact area A_c in units of pi R^2.

    Raises
    ------
    InputError
        For invalid input.
    OutOfRangeError
        For a force past the end of the model's range (``range_end``).
    ConvergenceError
        If the solve fails.

    Examples
    --------
    The paper's headline pocket (alpha = 47/160, Phat_I = 0.31) at Fhat = 0.19:

    >>> from pocket import shooting
    >>> state = shooting.compress(47 / 160, 0.31, 0.19)
    >>> print(round(state.pressure_ratio, 3))
    1.294

    The flat plate carries the force by the pressure on the contact area, F = P A_c, that is
    Fhat Phat_I = Phat A_c / (pi R^2):

    >>> print(abs(state.force * state.pressure_initial - state.pressure * state.contact_area) < 1e-9)
    True

    A sphere of radius R_s = R / 2 (``pocket.core.indenters.Sphere``) and air (``pocket.core.fluids.gas``,
    the ambient pressure in units of E T / R):

    >>> from pocket.core.fluids import gas
    >>> from pocket.core.indenters import Sphere
    >>> pressed = shooting.compress(47 / 160, 0.31, 0.19, indenter=Sphere(0.5), fluid=gas(10.0, 1.4))
    >>> print(pressed.pressure > state.inflated.pressure, pressed.volume < state.volume)
    True True

    An uninflated capsule (P_I = 0) of liquid pressed by F = 0.5 E T R on each plate, about half-way closed:

    >>> squeezed = shooting.compress(0.0, 0.0, 0.5, geometry="capsule", force_unit="ETR")
    >>> print(round(squeezed.extra["force_ETR"], 10), round(squeezed.height, 4))
    0.5 0.5583
    """
    return compression_curve(material, pressure_initial, [force], fluid=fluid, indenter=indenter, geometry=geometry,
                             rtol=rtol, force_unit=force_unit)[0]
