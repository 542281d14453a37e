"""Public entry points of the solid (``pocket.core.solver``): inflate, compress, and their input checks.

Every input is checked before any work (one-line ``InputError``): the rubber (``as_material``; the
solid has the laws of ``laws``), the pressures and forces, the fluid, the indenter (the flat plate
or a sphere), the reference surface (``GEOMETRIES``: the flat clamped disc, None), the options of the
record ``SOLVER`` (thickness ratio, layers, elements, tolerance, the clamp's upper jaw).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from pocket.core import geometries
from pocket.core.errors import InputError, above_the_pocket
from pocket.core.fluids import Fluid, as_fluid
from pocket.core.indenters import Indenter, Plate, Profile, Sphere, posed
from pocket.core.inputs import check_forces, check_positive, check_volume
from pocket.core.materials import Material, as_material
from pocket.core.solver import FluidLike, GeometryLike, MaterialLike, Numbers, Progress
from pocket.core.states import CompressedState, InflatedState

from . import (
    DEFAULT_CLAMP_RADIUS,
    DEFAULT_CORNER,
    DEFAULT_ELEMENTS,
    DEFAULT_LAYERS,
    DEFAULT_THICKNESS,
    SOLVER,
    compression,
    contact,
    edgemesh,
    inflation,
    jaw,
    laws,
    mesh,
    model,
    results,
)

__all__ = ["CONTACTS", "GEOMETRIES", "compress", "compress_height", "compression_curve", "inflate", "inflate_volume"]

#: indenter class -> contact formulations (the flat plate, the sphere and a profile, ``contact``)
CONTACTS: dict[type[Indenter], tuple[str, ...]] = {Plate: ("active set",), Sphere: ("active set",),
                                                   Profile: ("active set",)}
#: reference surface -> how the solid poses it (``pocket.core.geometries``): the sheet's section about it
GEOMETRIES = {"pocket": "the rectangle [0, 1] x [-t/2, t/2], clamped through its thickness at r = R"}


def _model(material, thickness_ratio, layers, elements, tol, geometry,
           corner) -> tuple[Material, model.Model, float]:
    """The checked rubber, the discretized sheet about the reference surface ``geometry`` and the checked
    tolerance."""
    material = as_material(material)
    law = laws.derivatives(material.scaled())
    t = SOLVER.check_option("thickness_ratio", thickness_ratio)
    layers = SOLVER.check_option("layers", layers)
    elements = SOLVER.check_option("elements", elements)
    tol = SOLVER.check_option("tol", tol)
    corner = SOLVER.check_option("corner", corner)
    section = mesh.section(t, elements, layers, corner, geometry=geometry)
    return material, model.discretize(t, section, law, geometry), tol


def _jaw(clamp_radius, m: model.Model) -> jaw.Jaw | None:
    """The clamp's upper jaw of edge radius ``clamp_radius`` thicknesses (checked), or None (0: no jaw)."""
    radius = SOLVER.check_option("clamp_radius", clamp_radius)
    if radius * m.thickness >= 0.5:
        raise InputError(f"clamp_radius = {clamp_radius} thicknesses is {radius * m.thickness:.6g} R at T/R = "
                         f"{m.thickness:g}, but the jaw's edge must be shorter than half the clamp's radius")
    return jaw.Jaw(radius * m.thickness) if radius > 0.0 else None


def inflate(material: MaterialLike, pressure: float, *, geometry: GeometryLike = None,
            thickness_ratio: float = DEFAULT_THICKNESS, layers: int = DEFAULT_LAYERS, elements: int = DEFAULT_ELEMENTS,
            corner: float = DEFAULT_CORNER, tol: float = 1e-10,
            clamp_radius: float = DEFAULT_CLAMP_RADIUS) -> InflatedState:
    """Inflate the sheet, modelled as an axisymmetric incompressible solid, at Phat = ``pressure`` (first branch).

    Parameters
    ----------
    material : Material or float
        The rubber, a ``pocket.core.materials.Material`` of the laws the solid has (any stress unit), or a
        Mooney-Rivlin alpha = C2/C1.
    pressure : float
        Phat = P R / (E T) > 0, P the pressure on the sheet's lower surface.
    geometry : Geometry or str, optional
        The reference surface: None (the flat clamped disc) or one of ``GEOMETRIES``.
    thickness_ratio : float, optional
        The sheet's thickness over the clamp radius, T / R in (0, 0.5).
    layers : int, optional
        Elements through the thickness, ``MIN_LAYERS`` to ``MAX_LAYERS``.
    elements : int, optional
        Elements along the radius, ``MIN_ELEMENTS`` to ``MAX_ELEMENTS`` (graded towards the clamp).
    corner : float, optional
        The length of the clamp's corner elements, in thicknesses T (``mesh``: with the jaw, a mesh of its
        rounded edge; without it, a regularisation of the singular corner that the answer depends on;
        ``MIN_CORNER`` to ``MAX_CORNER``).
    tol : float, optional
        Newton tolerance on the displacement increment, units R, at most 1e-4.
    clamp_radius : float, optional
        The clamp's upper jaw as a rigid frictionless obstacle, its edge rounded to this radius in thicknesses
        T (``jaw``; default ``DEFAULT_CLAMP_RADIUS``); 0: no jaw, the sheet only fixed at r >= R.

    Returns
    -------
    InflatedState
        Lengths in units of R (the height of the sheet's mid-surface at the pole), the volume under its lower
        surface V / R^3; ``membrane`` is false.

    Raises
    ------
    InputError
        For an invalid rubber, pressure or option.
    OutOfRangeError
        If Phat lies above the first branch's pressure maximum.
    ConvergenceError
        If Newton's method fails.

    Examples
    --------
    On the coarsest mesh, a sheet of T/R = 0.0125 stands within 1 % of the membrane's height:

    >>> from pocket import shooting, solid
    >>> state = solid.inflate(47 / 160, 0.31, elements=8, layers=2)
    >>> print(state.membrane, abs(state.height / shooting.inflate(47 / 160, 0.31).height - 1) < 0.01)
    False True
    """
    geometry, _ = geometries.posed(GEOMETRIES, "solid", geometry)
    material, m, tol = _model(material, thickness_ratio, layers, elements, tol, geometry, corner)
    pressure = check_positive("pressure", pressure)
    y, iterations = inflation.to_pressure(m, 3.0 * m.thickness * pressure, tol, _jaw(clamp_radius, m))
    return results.inflated(m, material, y, iterations, pressure=pressure)


def inflate_volume(material: MaterialLike, volume: float, *, geometry: GeometryLike = None,
                   thickness_ratio: float = DEFAULT_THICKNESS, layers: int = DEFAULT_LAYERS,
                   elements: int = DEFAULT_ELEMENTS, corner: float = DEFAULT_CORNER,
                   tol: float = 1e-10, clamp_radius: float = DEFAULT_CLAMP_RADIUS) -> InflatedState:
    """Inflate the solid sheet to the cavity volume V / R^3 = ``volume`` (volume control).

    Parameters
    ----------
    material : Material or float
        The rubber, as for ``inflate``.
    volume : float
        V / R^3 > 0, the volume under the sheet's lower surface.
    geometry, thickness_ratio, layers, elements, corner, tol, clamp_radius
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
    Volume control inverts pressure control:

    >>> from pocket import solid
    >>> state = solid.inflate(47 / 160, 0.31, elements=8, layers=2)
    >>> print(round(solid.inflate_volume(47 / 160, state.volume, elements=8, layers=2).pressure, 6))
    0.31
    """
    geometry, _ = geometries.posed(GEOMETRIES, "solid", geometry)
    material, m, tol = _model(material, thickness_ratio, layers, elements, tol, geometry, corner)
    volume = check_volume("volume", volume)
    y, iterations = inflation.to_volume(m, volume, tol, _jaw(clamp_radius, m))
    return results.inflated(m, material, y, iterations, volume_given=volume)


def _setup(material, pressure_initial, fluid, indenter, geometry, thickness_ratio, layers, elements,
           tol, corner, clamp_radius) -> tuple[Material, model.Model, float, Fluid, InflatedState, np.ndarray,
                                              compression.Control]:
    """The checked inputs, the inflated state to compress and the first contact from it (the state and its
    control)."""
    indenter, _ = posed(CONTACTS, "solid", indenter)
    fluid = as_fluid(fluid)
    material, m, tol = _model(material, thickness_ratio, layers, elements, tol, geometry, corner)
    p_i = check_positive("pressure_initial", pressure_initial)
    clamp = _jaw(clamp_radius, m)
    y, iterations = inflation.to_pressure(m, 3.0 * m.thickness * p_i, tol, clamp)
    start = results.inflated(m, material, y, iterations, pressure=p_i)
    fill = compression.fluid_control(m, fluid, p_i, start.volume)
    y, control = compression.first_contact(m, y, fill, contact.Surface(indenter), clamp)
    return material, m, tol, fluid, start, y, control


def compression_curve(material: MaterialLike, pressure_initial: float, forces: Numbers, *, fluid: FluidLike = None,
                      indenter: Indenter | None = None, geometry: GeometryLike = None,
                      progress: Progress | None = None, thickness_ratio: float = DEFAULT_THICKNESS,
                      layers: int = DEFAULT_LAYERS, elements: int = DEFAULT_ELEMENTS,
                      corner: float = DEFAULT_CORNER, tol: float = 1e-10,
                      clamp_radius: float = DEFAULT_CLAMP_RADIUS) -> list[CompressedState]:
    """Compressed states of the solid sheet at the forces Fhat = F / (P_I pi R^2), each from the one before.

    Parameters
    ----------
    material : Material or float
        The rubber, as for ``inflate``.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0.
    forces : sequence of float
        Fhat >= 0 of each state, solved in the order given.
    fluid : Fluid or str, optional
        None (a liquid) or a gas (``pocket.core.fluids.gas``, its ambient pressure as Phat_atm =
        P_atm R / (E T)).
    indenter : Indenter, optional
        None (the flat plate) or an ``Indenter`` of ``CONTACTS`` (``pocket.core.indenters.Sphere(K)``, say).
    geometry, thickness_ratio, layers, elements, corner, tol, clamp_radius
        As for ``inflate``.
    progress : callable, optional
        ``progress(done, total)``, called after each force.

    Returns
    -------
    list of CompressedState
        In the order of ``forces``.

    Raises
    ------
    InputError
        For invalid input.
    OutOfRangeError
        For a force past the end of the range, naming the end (``rangeend``).
    ConvergenceError
        If Newton's method fails.

    Examples
    --------
    >>> from pocket import solid
    >>> states = solid.compression_curve(47 / 160, 0.31, [0.1, 0.19], elements=8, layers=2)
    >>> print([f"{s.pressure_ratio:.3f}" for s in states])
    ['1.158', '1.297']
    """
    forces = check_forces(forces)
    geometry, _ = geometries.posed(GEOMETRIES, "solid", geometry)
    material, m, tol, fluid, start, y, control = _setup(material, pressure_initial, fluid, indenter, geometry,
                                                        thickness_ratio, layers, elements, tol, corner, clamp_radius)
    unit = np.pi * 3.0 * m.thickness * start.pressure
    out, before = [], (0.0, 3.0 * m.thickness * start.pressure)  # the first contact: no force, P_I
    for k, force in enumerate(forces):
        if control.force:  # under a force already: the mesh's cluster moved to where the edge is going
            m, y, control = edgemesh.ahead(m, y, control, force * unit, before)
            before = (control.force, float(y[m.size]))
        y, control, iterations = compression.to_force(m, y, control, force * unit, unit, tol)
        m, y, control, moved = edgemesh.follow(m, y, control, tol)
        iterations += moved
        out.append(results.compressed(m, material, y, control.active, iterations, start, fluid, force=force,
                                       surface=control.surface))
        if progress is not None:
            progress(k + 1, len(forces))
    return out


def compress(material: MaterialLike, pressure_initial: float, force: float, *, fluid: FluidLike = None,
             indenter: Indenter | None = None, geometry: GeometryLike = None, **options: Any) -> CompressedState:
    """The compressed state of the solid sheet at the force Fhat = F / (P_I pi R^2) (``compression_curve``).

    Parameters
    ----------
    material : Material or float
        The rubber, as for ``inflate``.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0.
    force : float
        Fhat >= 0.
    fluid, indenter, geometry
        As for ``compression_curve``.
    **options
        ``thickness_ratio``, ``layers``, ``elements``, ``corner``, ``tol``, ``clamp_radius`` (as for ``inflate``).

    Returns
    -------
    CompressedState
        Pressures in units of E T / R, lengths of R.

    Raises
    ------
    InputError
        For invalid input.
    OutOfRangeError
        For a force past the end of the range.
    ConvergenceError
        If Newton's method fails.

    Examples
    --------
    A sheet of T/R = 0.0125 on the coarsest mesh: its pressure rise differs from the membrane's by less than
    T/R (the membrane's error is O(T/R), here mostly the clamp's jaw, which a membrane does not see):

    >>> from pocket import shooting, solid
    >>> state = solid.compress(47 / 160, 0.31, 0.19, elements=8, layers=2)
    >>> print(abs(state.pressure_ratio / shooting.compress(47 / 160, 0.31, 0.19).pressure_ratio - 1) < 0.0125)
    True
    """
    return compression_curve(material, pressure_initial, [force], fluid=fluid, indenter=indenter, geometry=geometry,
                             **options)[0]


def compress_height(material: MaterialLike, pressure_initial: float, height: float, *, fluid: FluidLike = None,
                    indenter: Indenter | None = None, geometry: GeometryLike = None,
                    thickness_ratio: float = DEFAULT_THICKNESS, layers: int = DEFAULT_LAYERS,
                    elements: int = DEFAULT_ELEMENTS, corner: float = DEFAULT_CORNER,
                    tol: float = 1e-10, clamp_radius: float = DEFAULT_CLAMP_RADIUS) -> CompressedState:
    """The compressed state of the solid sheet with the plate at H/R = ``height`` above the clamp plane.

    Travel control: the force is found.

    Parameters
    ----------
    material : Material or float
        The rubber, as for ``inflate``.
    pressure_initial : float
        Phat_I = P_I R / (E T) > 0.
    height : float
        H / R > 0, below the inflated pocket's top.
    fluid, indenter, geometry, thickness_ratio, layers, elements, corner, tol, clamp_radius
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
        For a height above the inflated pocket's top, or below the end of the range (``rangeend``).
    ConvergenceError
        If Newton's method fails.

    Examples
    --------
    Pressed 5 % of the way down from the inflated top:

    >>> from pocket import solid
    >>> top = solid.inflate(47 / 160, 0.31, elements=16, layers=2).height
    >>> state = solid.compress_height(47 / 160, 0.31, 0.95 * top, elements=16, layers=2)
    >>> print(f"{state.height_ratio:.4f}, Fhat = {state.force:.4f}")
    0.9500, Fhat = 0.0215
    >>> solid.compress_height(47 / 160, 0.31, 1.01 * top, elements=16, layers=2)
    Traceback (most recent call last):
        ...
    pocket.core.errors.OutOfRangeError: height = ... is above the inflated pocket ...
    """
    height = check_positive("height", height)
    geometry, _ = geometries.posed(GEOMETRIES, "solid", geometry)
    material, m, tol, fluid, start, y, control = _setup(material, pressure_initial, fluid, indenter, geometry,
                                                        thickness_ratio, layers, elements, tol, corner, clamp_radius)
    if height >= start.height:
        raise above_the_pocket(height, start.height)
    unit = np.pi * 3.0 * m.thickness * start.pressure
    y, control, iterations = compression.to_height(m, y, control, height, unit, tol)
    m, y, control, moved = edgemesh.follow(m, y, control, tol)
    iterations += moved
    return results.compressed(m, material, y, control.active, iterations, start, fluid, surface=control.surface)
