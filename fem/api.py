"""Public entry points: inflate, compress, and the checks of what they are given.

Inputs are checked before any work (``pocket.core.inputs``; a mesh the solver
cannot use is an ``InputError`` saying why). The states are built and
checked by ``results``; the curves are driven by ``curves``.

The rubber comes first: a ``pocket.core.materials.Material``, any law in any
stress unit (``material``; a number is taken as a Mooney-Rivlin alpha = C2/C1
and converted once, by ``as_material``). The fluid of a compression is a keyword: None (a liquid) or a
``pocket.core.fluids.Fluid``, a gas with its ambient pressure in the model's
units, Phat_atm = P_atm R / (E T) (``gas``); so is the indenter: None (the flat plate) or a
``pocket.core.indenters.Indenter`` whose class ``CONTACTS`` maps to the contact methods that pose it
(an InputError for another class, or for a method that does not pose it); and the reference surface,
``geometry``: None (the flat clamped disc) or a ``pocket.core.geometries.Geometry`` of ``GEOMETRIES``
(an InputError for another). Every law's pressures are
Phat = P R / (E T) with E = 3 mu_0 its small-strain Young's modulus (for
Mooney-Rivlin 6 (C1 + C2), as in the paper); forces are Fhat = F / (P_I pi R^2).

The default mesh (``default_mesh``) is ``meshes.polar(DEFAULT_ELEMENTS,
power=POLAR_POWER)``: graded towards the axis, where the pole stretch needs
it (``post``), and mapped onto the free part by the edge-fitted contact. Its
size was chosen by measurement against the shooting solver (rtol 1e-12) on
the 14 validation cases (every law, liquids and gases) at Fhat = 0, 0.05, 0.19,
1 and 0.95 of the end of each range (``python benchmarks/bench_fem.py`` prints
the table): with P2 the worst relative error in any reported scalar is 1.5e-7
at 64 elements, 9.3e-9 at 128, 1.8e-9 at 192, 5.8e-10 at 256 and 1.1e-10 at 384,
each the height of the Gent rubber near its lock at Fhat = 49; 256 is the
smallest of these below the 1e-9 bar, with a margin of 1.7.
The P2 error falls as h^4, so 10 times the elements buys 1e-4 of the error.
P1 (error O(h^2)) gets 1024 elements by default: within 1e-6 of shooting.
"""

from __future__ import annotations

import pathlib
from dataclasses import replace
from typing import Any

import numpy as np

from pocket import meshes
from pocket.core import geometries
from pocket.core.errors import CAPSULE_EDGE, UNINFLATED_CAPSULE, InputError, OutOfRangeError, above_the_pocket
from pocket.core.fluids import as_fluid
from pocket.core.geometries import Geometry
from pocket.core.indenters import Indenter, Plate, Profile, Sphere, posed
from pocket.core.inputs import (
    FORCE_UNITS,
    check_choice,
    check_forces,
    check_non_negative,
    check_positive,
    check_volume,
    forces_in_fhat,
    quote,
)
from pocket.core.solver import FluidLike, GeometryLike, MaterialLike, Numbers, Progress
from pocket.core.states import CompressedState, InflatedState

from . import (
    DEFAULT_ELEMENTS,
    DEFAULT_ELEMENTS_P1,
    SOLVER,
    capsule,
    capsulestates,
    curves,
    descent,
    fitted,
    inflation,
    results,
    wrapping,
)
from .gas import sealed
from .model import FITTED, PENALTY, Control, Model, discretize
from .newton import Tolerances
from .surfaces import surface

#: a mesh argument: a mesh file's name, or the nodes of [0, 1] (shape (n+1,)); None for the default mesh
Mesh = str | pathlib.PurePath | np.ndarray | None

__all__ = [
    "CONTACTS",
    "DEFAULT_PENALTY",
    "GEOMETRIES",
    "POLAR_POWER",
    "compress",
    "compress_height",
    "compression_curve",
    "default_mesh",
    "inflate",
    "inflate_volume",
]

DEFAULT_PENALTY = 1e5
#: grading exponent of the default mesh family towards the axis (``meshes.polar``)
POLAR_POWER = 2.5
#: adjacent elements may differ in length by at most this factor
MAX_RATIO = 1e3
#: shortest usable element (units R): nodal values carry round-off of ~1e-16 R, so a shorter
#: element's slope (the stretch) would carry a relative error above 1e-6
MIN_LENGTH = 1e-10
#: indenter class -> the contact methods (the model's modes, ``model``) that pose it and whether it is curved: the
#: plate is posed by ``curves``, a curved one by its surface (``surfaces.surface``), edge-fitted by ``obstacle``,
#: by penalty with ``spherepenalty``
CONTACTS: dict[type[Indenter], tuple[tuple[str, ...], bool]] = {
    Plate: ((FITTED, PENALTY), False), Sphere: ((FITTED, PENALTY), True), Profile: ((FITTED, PENALTY), True)}
#: reference surface -> how the model poses it (``pocket.core.geometries``, ``model``)
GEOMETRIES = {"pocket": "the meridian meshed in r = S on [0, 1], clamped at its end",
              "capsule": "the upper half's meridian meshed in r = 2 S / pi on [0, 1], its end on the equator's "
                         "plane of symmetry (``capsule``)"}


def default_mesh(elements: int | None = None, order: int = 2) -> np.ndarray:
    """The nodes of the default mesh family of [0, 1] (the Lagrangian radius r / R), graded towards the axis.

    ``meshes.polar(elements, power)``: the power is ``POLAR_POWER`` up to 1585 elements; beyond,
    8 / log10(elements), so that the first element, about power / elements^power long, stays above 1e-8 R (the
    pole stretch on so fine a mesh is accurate to 1e-12 with any grading, and a shorter first element would only
    carry round-off: a nodal value's 1e-16 R over its radius).

    Parameters
    ----------
    elements : int, optional
        Number of elements; None for the default of the element order, ``DEFAULT_ELEMENTS`` (P2) or
        ``DEFAULT_ELEMENTS_P1`` (P1).
    order : int, optional
        Element order, 1 or 2.

    Returns
    -------
    numpy.ndarray
        The nodes, shape (elements + 1,), increasing from 0 to 1 (units R).

    Examples
    --------
    >>> from pocket import fem
    >>> nodes = fem.default_mesh(16)
    >>> print(nodes.shape, nodes[0], nodes[-1])
    (17,) 0.0 1.0
    >>> print(len(fem.default_mesh()) - 1 == fem.DEFAULT_ELEMENTS)
    True

    The elements shorten towards the axis, where the pole stretch needs them:

    >>> print(bool((nodes[1] - nodes[0]) < (nodes[-1] - nodes[-2])))
    True
    """
    if elements is None:
        elements = DEFAULT_ELEMENTS if order == 2 else DEFAULT_ELEMENTS_P1
    return meshes.polar(elements, power=min(POLAR_POWER, 8.0 / np.log10(elements)))


def _usable(nodes: np.ndarray, where: str) -> np.ndarray:
    """The nodes, if the solver can use them: elements not too short, neighbours of similar size."""
    lengths = np.diff(nodes)
    k = int(np.argmin(lengths))
    if lengths[k] < MIN_LENGTH:
        raise InputError(f"{where}: element {k + 1} (r from {quote(nodes[k])} to {quote(nodes[k + 1])}) is "
                         f"{lengths[k]:.3g} R long; elements must be at least {MIN_LENGTH:g} R long")
    ratio = np.maximum(lengths[1:] / lengths[:-1], lengths[:-1] / lengths[1:])
    if ratio.size and ratio.max() > MAX_RATIO:
        k = int(np.argmax(ratio))
        raise InputError(f"{where}: elements {k + 1} and {k + 2} (around r = {quote(nodes[k + 1])}) differ in length "
                         f"by a factor {ratio[k]:.3g}; neighbours may differ by at most {MAX_RATIO:g}")
    return nodes


def _nodes(mesh, elements, order) -> np.ndarray:
    """The mesh nodes: ``mesh`` (an array of nodes or a mesh file), or the default family of ``elements``."""
    if mesh is not None and elements is not None:
        raise InputError("give either mesh or elements, not both")
    if mesh is None:
        nodes = default_mesh(None if elements is None else SOLVER.check_option("elements", elements), order)
        return _usable(nodes, "default mesh")
    nodes = meshes.read(mesh) if isinstance(mesh, (str, pathlib.PurePath)) else meshes.check(mesh, "mesh")
    SOLVER.check_option("elements", nodes.size - 1, lambda _: "mesh elements")
    return _usable(nodes, "mesh" if not isinstance(mesh, (str, pathlib.PurePath)) else str(mesh))


def _model(material, mesh, elements, order, penalty, geometry: Geometry = geometries.DISC) -> Model:
    order = SOLVER.check_option("order", order)
    return discretize(material, _nodes(mesh, elements, order), order, penalty, geometry)


def _builder(geometry: Geometry):
    """The module that builds the compressed states of ``geometry``: ``results``, or ``capsulestates``."""
    return capsulestates if geometry is geometries.CAPSULE else results


def _tolerances(tol) -> Tolerances:
    tol = SOLVER.check_option("tol", tol)
    return Tolerances(tol, tol)


def _contact(indenter, methods, contact, penalty, augmented) -> tuple[str, float, bool]:
    """The contact method and, for the penalty method, its penalty and augmentation (checked), for the
    checked ``indenter`` and the ``methods`` that pose it."""
    contact = SOLVER.check_option("contact", contact)
    if contact not in methods:
        raise InputError(f"contact = {contact!r} does not apply to the {indenter.name} indenter (its methods: "
                         f"{', '.join(methods)})")
    if contact == FITTED:
        for name, value in (("penalty", penalty), ("augmented", augmented)):
            if value is not None:
                raise InputError(f"{name} = {value!r} applies only to contact = 'penalty', not to contact = 'fitted'")
        return contact, DEFAULT_PENALTY, False
    penalty = DEFAULT_PENALTY if penalty is None else SOLVER.check_option("penalty", penalty)
    augmented = True if augmented is None else SOLVER.check_option("augmented", augmented)
    return contact, penalty, augmented


def inflate(material: MaterialLike, pressure: float, *, geometry: GeometryLike = None, mesh: Mesh = None,
            elements: int | None = None, order: int = 2, tol: float = 1e-10) -> InflatedState:
    """Inflate the flat sheet at the pressure Phat = P R / (E T) (pressure control, first branch).

    Parameters
    ----------
    material : Material or float
        The rubber, a ``pocket.core.materials.Material`` of any law and stress unit; a number is a Mooney-Rivlin
        alpha = C2/C1 (``as_material``).
    pressure : float
        Phat = P R / (E T) > 0 (E = 3 mu_0 the rubber's small-strain Young's modulus, T its thickness, R the
        clamp radius, or the capsule's radius); >= 0 for the capsule (at 0, its unstressed sphere).
    geometry : Geometry or str, optional
        The reference surface: None (the flat clamped disc) or one of ``GEOMETRIES`` (``"capsule"``: the closed
        sphere, its upper half solved; its states report the whole capsule's volume, the pole's or the plate's
        height above the equatorial plane, and ``extra`` keys ``geometry`` and ``radius_equator``).
    mesh : numpy.ndarray or str or path, optional
        The nodes of [0, 1] (units R, shape (n+1,)) or a mesh file (any meshio format); None for the default mesh
        (``default_mesh``).
    elements : int, optional
        Elements of the default mesh (not with ``mesh``): default ``DEFAULT_ELEMENTS`` with P2,
        ``DEFAULT_ELEMENTS_P1`` with P1.
    order : int, optional
        Element order, 1 (P1) or 2 (P2).
    tol : float, optional
        Newton tolerance on residual and increment, at most 1e-4.

    Returns
    -------
    InflatedState
        Lengths in units of R, the volume V / R^3, tensions in units of E T.

    Raises
    ------
    InputError
        For an invalid rubber, pressure, mesh (an element too short, neighbours too different) or option.
    OutOfRangeError
        If Phat lies above the first branch's pressure maximum.
    ConvergenceError
        If Newton's method fails.

    Examples
    --------
    On a coarse mesh of 16 P2 elements, the height agrees with the shooting solver's to 1e-5 R:

    >>> from pocket import fem, shooting
    >>> state = fem.inflate(47 / 160, 0.31, elements=16)
    >>> print(f"H0/R = {state.height:.4f}")
    H0/R = 0.4939
    >>> print(abs(state.height - shooting.inflate(47 / 160, 0.31).height) < 1e-5)
    True

    The capsule inflates to a sphere of uniform stretch: its pole and its equator are as far from its centre,

    >>> ball = fem.inflate(47 / 160, 0.31, geometry="capsule", elements=16)
    >>> print(f"{ball.height:.4f} {ball.extra['radius_equator']:.4f}")
    1.1196 1.1196
    """
    geometry, _ = geometries.posed(GEOMETRIES, "fem", geometry)
    model = _model(material, mesh, elements, order, DEFAULT_PENALTY, geometry)
    if geometry is geometries.CAPSULE:
        pressure = check_non_negative("pressure", pressure)
        y, iterations = inflation.inflated_at(model, pressure, _tolerances(tol), capsule.inflate)
        return capsulestates.inflated(model, y, iterations, pressure=pressure)
    pressure = check_positive("pressure", pressure)
    y, iterations = inflation.inflated_at(model, pressure, _tolerances(tol))
    return results.inflated(model, y, iterations, pressure=pressure)


def inflate_volume(material: MaterialLike, volume: float, *, geometry: GeometryLike = None, mesh: Mesh = None,
                   elements: int | None = None, order: int = 2, tol: float = 1e-10) -> InflatedState:
    """Inflate the flat sheet to the enclosed volume V / R^3 (volume control: passes pressure maxima).

    Parameters
    ----------
    material : Material or float
        The rubber, as for ``inflate`` (a number is a Mooney-Rivlin alpha).
    volume : float
        V / R^3 > 0.
    geometry, mesh, elements, order, tol
        As for ``inflate``.

    Returns
    -------
    InflatedState
        Its ``pressure`` is the Phat found.

    Raises
    ------
    InputError
        For invalid input.
    OutOfRangeError
        For a volume the first branch does not reach.
    ConvergenceError
        If Newton's method fails.

    Examples
    --------
    Volume control inverts pressure control (to the coarse mesh's accuracy):

    >>> from pocket import fem
    >>> state = fem.inflate(47 / 160, 0.31, elements=16)
    >>> print(round(fem.inflate_volume(47 / 160, state.volume, elements=16).pressure, 8))
    0.31
    """
    geometry, _ = geometries.posed(GEOMETRIES, "fem", geometry)
    model = _model(material, mesh, elements, order, DEFAULT_PENALTY, geometry)
    volume = check_volume("volume", volume)
    if geometry is geometries.CAPSULE:
        y, iterations = capsule.inflate_volume(model, volume, _tolerances(tol))
        return capsulestates.inflated(model, y, iterations, volume=volume)
    y, iterations = inflation.to_volume(model, volume, _tolerances(tol))
    return results.inflated(model, y, iterations, volume=volume)


def _setup(material, pressure_initial, fluid, indenter, geometry, mesh, elements, order, contact, penalty, augmented,
           tol, uninflated=False):
    """Checked inputs, the model, the inflated state to compress, the fluid sealed in it with the indenter (the
    volume row's ``Control``) and whether the indenter is curved (``CONTACTS``). ``uninflated``: a capsule may be
    at P_I = 0 (height control)."""
    indenter, (methods, curved) = posed(CONTACTS, "fem", indenter)
    contact, penalty, augmented = _contact(indenter, methods, contact, penalty, augmented)
    if geometry is geometries.CAPSULE:
        _capsule_contact(indenter, contact)
    uninflated = uninflated and geometry is geometries.CAPSULE and pressure_initial == 0
    if geometry is geometries.CAPSULE and pressure_initial == 0 and not uninflated:
        raise InputError(f"pressure = 0: {UNINFLATED_CAPSULE}")
    model = _model(material, mesh, elements, order, penalty, geometry)
    p_i = 0.0 if uninflated else check_positive("pressure_initial", pressure_initial)
    fluid = as_fluid(fluid)
    tol = _tolerances(tol)
    if geometry is geometries.CAPSULE:  # the upper half's volume is the volume row's (``capsule``)
        y_i, state, fill = descent.filled(model, p_i, fluid, indenter, tol)
        return model, contact, augmented, tol, y_i, state, fill, curved
    y_i, iterations = inflation.inflated_at(model, p_i, tol)
    state = results.inflated(model, y_i, iterations, pressure=p_i)
    fill = Control(volume=state.volume, gas=sealed(fluid, p_i), indenter=indenter)
    if contact == PENALTY and curved:
        model = replace(model, obstacle=surface(indenter))
    return model, contact, augmented, tol, y_i, state, fill, curved


def _capsule_contact(indenter: Indenter, contact: str) -> None:
    """InputError unless the capsule is pressed by the flat plates with the edge-fitted contact."""
    if not isinstance(indenter, Plate):
        raise InputError(f"the capsule is pressed between two flat plates: the {indenter.name} indenter does not "
                         "apply to it")
    if contact != FITTED:
        raise InputError(f"contact = {contact!r} does not apply to the capsule (its method: {FITTED})")


def compression_curve(material: MaterialLike, pressure_initial: float, forces: Numbers, *, fluid: FluidLike = None,
                      indenter: Indenter | None = None, geometry: GeometryLike = None,
                      progress: Progress | None = None, mesh: Mesh = None, elements: int | None = None, order: int = 2,
                      contact: str = FITTED, penalty: float | None = None, augmented: bool | None = None,
                      tol: float = 1e-10, force_unit: str = "Fhat") -> list[CompressedState]:
    """Compress the inflated pocket at each force Fhat = F / (P_I pi R^2), each state seeded by those before it.

    Parameters
    ----------
    material : Material or float
        The rubber, a ``pocket.core.materials.Material`` (any stress unit) or a Mooney-Rivlin alpha = C2/C1.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0, the inflation pressure the fluid is sealed at.
    forces : sequence of float
        Fhat = F / (P_I pi R^2) >= 0 of each state.
    fluid : Fluid or str, optional
        None or ``"liquid"`` (fixed volume), or a gas (``pocket.core.fluids.gas``) sealed at Phat_I, its
        ambient pressure as Phat_atm = P_atm R / (E T).
    indenter : Indenter, optional
        None (the flat plate) or an ``Indenter`` of ``CONTACTS`` (``Sphere``, ``Profile``), lengths in units of R;
        the capsule is pressed between two flat plates only, with the fitted contact.
    geometry, mesh, elements, order, tol
        As for ``inflate``.
    progress : callable, optional
        ``progress(done, total)``, called after each force.
    contact : {"fitted", "penalty"}, optional
        "fitted" (a mesh node follows the contact edge, contact exact) or "penalty" (fixed mesh).
    penalty : float, optional
        The contact penalty of ``contact="penalty"``, units E T / R^2 (default 1e5).
    augmented : bool, optional
        Augmented-Lagrangian updates of ``contact="penalty"`` (default true).
    force_unit : {"Fhat", "ETR"}, optional
        The unit of ``forces``: Fhat (default) or F / (E T R), the force on each plate of a capsule in units of its
        wall's E T and its radius R: the only unit of an uninflated capsule's (P_I = 0, ``geometry="capsule"``),
        whose states lie deep (``pocket.fem.descent``), each reported with ``extra["force_ETR"]`` the force asked.

    Returns
    -------
    list of CompressedState
        In the order of ``forces``.

    Raises
    ------
    InputError
        For invalid input (``penalty`` or ``augmented`` with ``contact="fitted"``, an indenter this solver does
        not pose).
    OutOfRangeError
        For a force past the end of the model's range.
    ConvergenceError
        If Newton's method fails; it says at which force.

    Examples
    --------
    >>> from pocket import fem
    >>> states = fem.compression_curve(47 / 160, 0.31, [0.1, 0.19], elements=16)
    >>> print([f"{s.pressure_ratio:.4f}" for s in states])
    ['1.1564', '1.2944']

    The edge-fitted contact is exact: the plate carries F = P A_c to round-off,

    >>> print(all(abs(s.force * s.pressure_initial - s.pressure * s.contact_area) < 1e-9 for s in states))
    True

    An uninflated capsule (P_I = 0) of liquid pressed by F = 0.5 E T R on each plate, about half-way closed:

    >>> (squeezed,) = fem.compression_curve(0.0, 0.0, [0.5], geometry="capsule", force_unit="ETR", elements=32)
    >>> print(round(squeezed.extra["force_ETR"], 10), round(squeezed.height, 4))
    0.5 0.5583
    """
    unit = check_choice("force_unit", force_unit, FORCE_UNITS)
    geometry, _ = geometries.posed(GEOMETRIES, "fem", geometry)
    model, contact, augmented, tolerances, y_i, inflated, fill, curved = _setup(
        material, pressure_initial, fluid, indenter, geometry, mesh, elements, order, contact, penalty, augmented, tol,
        uninflated=unit == "ETR")
    if inflated.pressure == 0.0:
        return _uninflated_curve(model, inflated, fill, check_forces(forces), tolerances, progress)
    forces = forces_in_fhat(forces, unit, inflated.pressure)
    if curved and contact == FITTED:
        return wrapping.curve(model, y_i, inflated, fill, forces, tolerances, progress)
    if contact == FITTED and geometry is geometries.CAPSULE:
        return _capsule_curve(model, y_i, inflated, fill, forces, tolerances, progress)
    if contact == FITTED:
        return curves.fitted_curve(model, y_i, inflated, fill, forces, tolerances, progress, _builder(geometry))
    return curves.penalty_curve(model, y_i, inflated, fill, forces, tolerances, augmented, progress)


def _capsule_curve(model: Model, y_i: np.ndarray, inflated: InflatedState, fill: Control, forces: list[float],
                   tol: Tolerances, progress: Progress | None) -> list[CompressedState]:
    """A capsule's states at the forces Fhat, in increasing order of force (each from those before it): past the
    end of the branch from the touch, on the branch reached deep (``descent``), if they lie on it."""
    order = sorted(set(forces))
    unit = np.pi * inflated.pressure
    ends: list[str] = []  # the end of the branch from the touch, once met

    def deeper(force: float, fhat: float, end: str) -> tuple[np.ndarray, int]:
        ends.append(end)
        return descent.to_force(model, inflated.pressure, fill, force, tol, f"force = {fhat!r}", ends[0], unit)

    counted = None if progress is None else \
        lambda done, _total: progress(sum(forces.count(f) for f in order[:done]), len(forces))
    states = curves.fitted_curve(model, y_i, inflated, fill, order, tol, counted, capsulestates, deeper)
    solved = dict(zip(order, states, strict=True))
    return [solved[f] for f in forces]


def _uninflated_curve(model: Model, inflated: InflatedState, fill: Control, forces: list[float], tol: Tolerances,
                      progress: Progress | None) -> list[CompressedState]:
    """The uninflated capsule's states at the forces F / (E T R), each reached deep on its own
    (``descent.to_force``); at F = 0 the unstressed sphere the plates touch, the one state of its branch from the
    touch."""
    states: dict[float, CompressedState] = {}
    for done, force in enumerate(forces, start=1):
        if force == 0.0 and force not in states:  # the unstressed sphere the plates touch
            states[force] = capsulestates.uncompressed(inflated, fill, FITTED)
        if force not in states:
            y, iterations = descent.to_force(model, 0.0, fill, force, tol, f"force_ETR = {force!r}")
            states[force] = capsulestates.fitted_state(model, y, iterations, inflated, fill, force, tol)
        if progress is not None:
            progress(done, len(forces))
    return [states[f] for f in forces]


def compress(material: MaterialLike, pressure_initial: float, force: float, *, fluid: FluidLike = None,
             indenter: Indenter | None = None, geometry: GeometryLike = None, **options: Any) -> CompressedState:
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
    fluid, indenter, geometry
        As for ``compression_curve``.
    **options
        The options of ``compression_curve``: ``mesh``, ``elements``, ``order``, ``contact``, ``penalty``,
        ``augmented``, ``tol``, ``force_unit``.

    Returns
    -------
    CompressedState
        Pressures in units of E T / R, lengths of R, the deformed contact area in units of pi R^2.

    Raises
    ------
    InputError
        For invalid input.
    OutOfRangeError
        For a force past the end of the model's range.
    ConvergenceError
        If Newton's method fails.

    Examples
    --------
    The headline pocket on 16 P2 elements, against the shooting solver:

    >>> from pocket import fem, shooting
    >>> state = fem.compress(47 / 160, 0.31, 0.19, elements=16)
    >>> print(round(state.pressure_ratio, 3))
    1.294
    >>> print(abs(state.pressure_ratio / shooting.compress(47 / 160, 0.31, 0.19).pressure_ratio - 1) < 1e-5)
    True

    By penalty on a fixed mesh, the contact is approximate:

    >>> rough = fem.compress(47 / 160, 0.31, 0.19, elements=16, contact="penalty")
    >>> print(abs(rough.pressure_ratio / state.pressure_ratio - 1) < 1e-2)
    True

    A capsule between two plates, each pressing with Fhat: F = P A_c on each, its edge-fitted contact exact,

    >>> squeezed = fem.compress(47 / 160, 0.31, 0.19, geometry="capsule", elements=16)
    >>> print(abs(squeezed.pressure_ratio * squeezed.contact_area / 0.19 - 1) < 1e-12, squeezed.extra["geometry"])
    True capsule
    """
    return compression_curve(material, pressure_initial, [force], fluid=fluid, indenter=indenter, geometry=geometry,
                             **options)[0]


def compress_height(material: MaterialLike, pressure_initial: float, height: float, *, fluid: FluidLike = None,
                    indenter: Indenter | None = None, geometry: GeometryLike = None, mesh: Mesh = None,
                    elements: int | None = None, order: int = 2, contact: str = FITTED, penalty: float | None = None,
                    augmented: bool | None = None, tol: float = 1e-10) -> CompressedState:
    """The compressed state with the indenter's lowest point at H/R = ``height`` above the clamp plane.

    Travel control: the force is found.

    Parameters
    ----------
    material : Material or float
        The rubber, a ``pocket.core.materials.Material`` (any stress unit) or a Mooney-Rivlin alpha = C2/C1.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0.
    height : float
        H / R > 0, at most the inflated pocket's height (there the state is the uncompressed one, force 0).
    fluid, indenter, geometry, mesh, elements, order, contact, penalty, augmented, tol
        As for ``compression_curve``.

    Returns
    -------
    CompressedState
        Its ``force`` is the Fhat = F / (P_I pi R^2) found.

    Raises
    ------
    InputError
        For invalid input.
    OutOfRangeError
        For a height above the inflated pocket, where the indenter would not touch it, or past the range's end.
    ConvergenceError
        If Newton's method fails.

    Examples
    --------
    Travel control inverts force control:

    >>> from pocket import fem
    >>> pressed = fem.compress(47 / 160, 0.31, 0.19, elements=16)
    >>> print(round(fem.compress_height(47 / 160, 0.31, pressed.height, elements=16).force, 8))
    0.19
    """
    height = check_positive("height", height)
    geometry, _ = geometries.posed(GEOMETRIES, "fem", geometry)
    model, contact, augmented, tolerances, y_i, inflated, fill, curved = _setup(
        material, pressure_initial, fluid, indenter, geometry, mesh, elements, order, contact, penalty, augmented, tol,
        uninflated=True)
    if height > inflated.height:
        raise above_the_pocket(height, inflated.height)
    if height == inflated.height:
        return _builder(geometry).uncompressed(inflated, fill, contact)
    if geometry is geometries.CAPSULE and contact == FITTED:
        return _capsule_height(model, y_i, inflated, fill, height, tolerances)
    if curved and contact == FITTED:
        return wrapping.at_height(model, y_i, inflated, fill, height, tolerances)
    if contact == FITTED:
        return curves.fitted_height(model, y_i, inflated, fill, height, tolerances, _builder(geometry))
    return curves.penalty_height(model, y_i, inflated, fill, height, tolerances, augmented)


def _capsule_height(model: Model, y_i: np.ndarray, inflated: InflatedState, fill: Control, height: float,
                    tol: Tolerances) -> CompressedState:
    """The capsule's state with the plates at ``height``: pressed from the touch, or past the end of that branch
    (and at P_I = 0 always) on the branch reached deep (``descent``)."""
    end = None
    if inflated.pressure > 0.0:
        try:
            return curves.fitted_height(model, y_i, inflated, fill, height, tol, capsulestates)
        except OutOfRangeError as err:
            if err.end is None or CAPSULE_EDGE not in str(err):
                raise
            end = err.end
    y, iterations = descent.to_height(model, inflated.pressure, fill, height, tol, f"height = {height!r}", end)
    force = fitted.plate_force_of(model, y) / (np.pi * inflated.pressure if inflated.pressure > 0.0 else 1.0)
    return capsulestates.fitted_state(model, y, iterations, inflated, fill, force, tol)
