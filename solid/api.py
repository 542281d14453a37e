"""Public entry points of the solid (``pocket.core.solver``): inflate, compress, and their input checks.

Every input is checked before any work (one-line ``InputError``): the rubber (``as_material``; the
solid has the laws of ``laws``), the pressures and forces, the fluid, the indenter (the flat plate
or a sphere), the reference surface (``GEOMETRIES``: the flat clamped disc, None), the options of the
record ``SOLVER`` (thickness ratio, layers, elements, tolerance).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from pocket.core import geometries
from pocket.core.errors import above_the_pocket
from pocket.core.fluids import Fluid, as_fluid
from pocket.core.indenters import Indenter, Plate, Profile, Sphere, posed
from pocket.core.inputs import check_forces, check_positive, check_volume
from pocket.core.materials import Material, as_material
from pocket.core.solver import FluidLike, GeometryLike, MaterialLike, Numbers, Progress
from pocket.core.states import CompressedState, InflatedState

from . import (
    DEFAULT_ELEMENTS,
    DEFAULT_LAYERS,
    DEFAULT_THICKNESS,
    SOLVER,
    compression,
    contact,
    inflation,
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


def _model(material, thickness_ratio, layers, elements, tol, geometry) -> tuple[Material, model.Model, float]:
    """The checked rubber, the discretized sheet about the reference surface ``geometry`` and the checked
    tolerance."""
    material = as_material(material)
    law = laws.derivatives(material.scaled())
    t = SOLVER.check_option("thickness_ratio", thickness_ratio)
    layers = SOLVER.check_option("layers", layers)
    elements = SOLVER.check_option("elements", elements)
    tol = SOLVER.check_option("tol", tol)
    return material, model.discretize(t, mesh.section(t, elements, layers, geometry=geometry), law, geometry), tol


def inflate(material: MaterialLike, pressure: float, *, geometry: GeometryLike = None,
            thickness_ratio: float = DEFAULT_THICKNESS, layers: int = DEFAULT_LAYERS, elements: int = DEFAULT_ELEMENTS,
            tol: float = 1e-10) -> InflatedState:
    """Inflated state at Phat = ``pressure`` (first branch) of the sheet of T/R = ``thickness_ratio``, meshed by
    ``elements`` along the radius and ``layers`` through the thickness; ``tol`` the Newton tolerance (R);
    ``geometry`` the reference surface (``GEOMETRIES``; None the flat clamped disc)."""
    geometry, _ = geometries.posed(GEOMETRIES, "solid", geometry)
    material, m, tol = _model(material, thickness_ratio, layers, elements, tol, geometry)
    pressure = check_positive("pressure", pressure)
    y, iterations = inflation.to_pressure(m, 3.0 * m.thickness * pressure, tol)
    return results.inflated(m, material, y, iterations, pressure=pressure)


def inflate_volume(material: MaterialLike, volume: float, *, geometry: GeometryLike = None,
                   thickness_ratio: float = DEFAULT_THICKNESS, layers: int = DEFAULT_LAYERS,
                   elements: int = DEFAULT_ELEMENTS, tol: float = 1e-10) -> InflatedState:
    """Inflated state of cavity volume V/R^3 = ``volume`` (geometry and options as ``inflate``)."""
    geometry, _ = geometries.posed(GEOMETRIES, "solid", geometry)
    material, m, tol = _model(material, thickness_ratio, layers, elements, tol, geometry)
    volume = check_volume("volume", volume)
    y, iterations = inflation.to_volume(m, volume, tol)
    return results.inflated(m, material, y, iterations, volume_given=volume)


def _setup(material, pressure_initial, fluid, indenter, geometry, thickness_ratio, layers, elements,
           tol) -> tuple[Material, model.Model, float, Fluid, InflatedState, np.ndarray, compression.Control]:
    """The checked inputs, the inflated state to compress and the first contact from it (the state and its
    control)."""
    indenter, _ = posed(CONTACTS, "solid", indenter)
    fluid = as_fluid(fluid)
    material, m, tol = _model(material, thickness_ratio, layers, elements, tol, geometry)
    p_i = check_positive("pressure_initial", pressure_initial)
    y, iterations = inflation.to_pressure(m, 3.0 * m.thickness * p_i, tol)
    start = results.inflated(m, material, y, iterations, pressure=p_i)
    fill = compression.fluid_control(m, fluid, p_i, start.volume)
    y, control = compression.first_contact(m, y, fill, contact.Surface(indenter))
    return material, m, tol, fluid, start, y, control


def compression_curve(material: MaterialLike, pressure_initial: float, forces: Numbers, *, fluid: FluidLike = None,
                      indenter: Indenter | None = None, geometry: GeometryLike = None,
                      progress: Progress | None = None, thickness_ratio: float = DEFAULT_THICKNESS,
                      layers: int = DEFAULT_LAYERS, elements: int = DEFAULT_ELEMENTS,
                      tol: float = 1e-10) -> list[CompressedState]:
    """Compressed states at the forces Fhat = F / (P_I pi R^2) (in the order given, each from the one
    before); fluid None (a liquid) or a gas (``pocket.core.fluids.gas``, ambient as Phat_atm); indenter None
    (the flat plate) or an ``Indenter`` (``CONTACTS``: ``pocket.core.indenters.Sphere(K)``, say). Geometry and
    options as ``inflate``; ``progress(done, total)`` after each force. A force past the end of the range is an
    OutOfRangeError naming the end (``rangeend``)."""
    forces = check_forces(forces)
    geometry, _ = geometries.posed(GEOMETRIES, "solid", geometry)
    material, m, tol, fluid, start, y, control = _setup(material, pressure_initial, fluid, indenter, geometry,
                                                        thickness_ratio, layers, elements, tol)
    unit = np.pi * 3.0 * m.thickness * start.pressure
    out = []
    for k, force in enumerate(forces):
        y, control, iterations = compression.to_force(m, y, control, force * unit, unit, tol)
        out.append(results.compressed(m, material, y, control.active, iterations, start, fluid, force=force,
                                       surface=control.surface))
        if progress is not None:
            progress(k + 1, len(forces))
    return out


def compress(material: MaterialLike, pressure_initial: float, force: float, *, fluid: FluidLike = None,
             indenter: Indenter | None = None, geometry: GeometryLike = None, **options: Any) -> CompressedState:
    """Compressed state at the force Fhat (``compression_curve``)."""
    return compression_curve(material, pressure_initial, [force], fluid=fluid, indenter=indenter, geometry=geometry,
                             **options)[0]


def compress_height(material: MaterialLike, pressure_initial: float, height: float, *, fluid: FluidLike = None,
                    indenter: Indenter | None = None, geometry: GeometryLike = None,
                    thickness_ratio: float = DEFAULT_THICKNESS, layers: int = DEFAULT_LAYERS,
                    elements: int = DEFAULT_ELEMENTS, tol: float = 1e-10) -> CompressedState:
    """Compressed state with the plate at H/R = ``height`` above the clamp plane (options as
    ``compression_curve``); an OutOfRangeError above the inflated pocket's top, or below the end of the range
    (``rangeend``)."""
    height = check_positive("height", height)
    geometry, _ = geometries.posed(GEOMETRIES, "solid", geometry)
    material, m, tol, fluid, start, y, control = _setup(material, pressure_initial, fluid, indenter, geometry,
                                                        thickness_ratio, layers, elements, tol)
    if height >= start.height:
        raise above_the_pocket(height, start.height)
    unit = np.pi * 3.0 * m.thickness * start.pressure
    y, control, iterations = compression.to_height(m, y, control, height, unit, tol)
    return results.compressed(m, material, y, control.active, iterations, start, fluid, surface=control.surface)
