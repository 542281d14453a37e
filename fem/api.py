"""Public entry points: inflate, compress, and the states they return.

Reported quantities (the keys of ``pocket.core.states``) from a converged state:

- ``height``: eta at the pole, the sheet's own height (with a pure penalty the
  sheet sits about p_N/kappa above the plate; the sheet is what is measured).
- ``stretch_pole`` / ``stretch_contact``: ``post.pole_stretch`` (in the contact
  zone the stretch is uniform and equibiaxial, so its value at the pole is
  lambda_c). ``stretch_clamp``: from the clamp reaction (``post``).
- ``contact_area`` = A_c / (pi R^2) with A_c = F/P, from the plate force and the
  pressure: both global, both converge like the energy, whereas the edge of the
  contact zone, where the gap closes quadratically, is ill-conditioned.
  ``contact_radius`` = sqrt(A_c/pi) / lambda_c (Lagrangian: the zone is a disc
  of reference radius a_c stretched uniformly by lambda_c).
- ``extra``: ``elements``, ``order``, ``newton_iterations`` (all iterations
  spent to reach this state from the previous one), ``penetration`` (max of
  eta - h over the quadrature points, in R), and for compression
  ``penetration_pole`` (eta(0) - h, what the penalty adds to the height),
  ``force_reaction`` (the plate reaction as Fhat),
  ``force_pressure_area`` (P times the deformed area of the active contact
  set, an independent O(h) estimate, as Fhat) and ``force_difference``.
"""

from __future__ import annotations

import pathlib

import numpy as np

from pocket import meshes
from pocket.core.errors import InputError
from pocket.core.inputs import check_alpha, check_non_negative, check_positive
from pocket.core.states import CompressedState, InflatedState

from . import DEFAULT_ELEMENTS, SOLVER, inflation, post
from .compression import augment, force_path, press_to_force, press_to_height
from .model import Control, Model, discretize, penetration
from .newton import Tolerances

__all__ = [
    "inflate",
    "inflate_volume",
    "compress",
    "compression_curve",
    "compress_height",
    "default_mesh",
]

DEFAULT_PENALTY = 1e5


def default_mesh() -> np.ndarray:
    """The default mesh: ``meshes.uniform(DEFAULT_ELEMENTS)``.

    Uniform because the contact edge moves along a compression curve; with P2,
    1000 elements put inflation within ~1e-9 and compression within ~2e-7 of the
    shooting reference (the contact edge limits the latter; tests/test_fem_*).
    """
    return meshes.uniform(DEFAULT_ELEMENTS)


def _nodes(mesh, elements) -> np.ndarray:
    """The mesh nodes: ``mesh`` (an array of nodes or a mesh file), or a uniform mesh of ``elements``."""
    if mesh is not None and elements is not None:
        raise InputError("give either mesh or elements, not both")
    if mesh is None:
        count = DEFAULT_ELEMENTS if elements is None else SOLVER.option("elements").checked(elements)
        return meshes.uniform(count)
    nodes = meshes.read(mesh) if isinstance(mesh, (str, pathlib.PurePath)) else meshes.check(mesh, "mesh")
    SOLVER.option("elements").checked(nodes.size - 1, lambda _: "mesh elements")
    return nodes


def _model(alpha, mesh, elements, order, penalty) -> Model:
    alpha = check_alpha(alpha)
    order = SOLVER.option("order").checked(order)
    penalty = check_positive("penalty", penalty)
    return discretize(alpha, _nodes(mesh, elements), order, penalty)


def _extra(model, y, iterations) -> dict:
    return dict(
        elements=model.elements,
        order=model.order,
        newton_iterations=int(iterations),
        penetration=penetration(model, y),
    )


def _inflated(model, y, iterations) -> InflatedState:
    lam = model.zero_multiplier()
    _, _, eta = post.nodal(model, y)
    return InflatedState(
        alpha=model.material.alpha,
        pressure=float(y[-2]),
        stretch_pole=post.pole_stretch(model, y),
        height=float(eta[0]),
        volume=post.volume(model, y),
        stretch_clamp=post.clamp_stretch(model, y, lam),
        profile=post.profile(model, y, lam),
        solver="fem",
        extra=_extra(model, y, iterations),
    )


def _compressed(model, y, lam, iterations, inflated: InflatedState, force=None) -> CompressedState:
    p_i, p = inflated.pressure, float(y[-2])
    reaction = post.plate_force(model, y, lam) / (np.pi * p_i)
    force = reaction if force is None else force
    area = force * p_i / p
    stretch = post.pole_stretch(model, y)
    radius = np.sqrt(area) / stretch
    active = p * post.contact_area_active(model, y, lam) / (np.pi * p_i)
    _, _, eta = post.nodal(model, y)
    extra = _extra(model, y, iterations)
    extra.update(
        penetration_pole=max(0.0, float(eta[0] - y[-1])),
        force_reaction=reaction,
        force_pressure_area=active,
        force_difference=reaction - active,
    )
    return CompressedState(
        alpha=model.material.alpha,
        pressure_initial=p_i,
        force=float(force),
        pressure=p,
        pressure_ratio=p / p_i,
        contact_area=float(area),
        contact_radius=float(radius),
        stretch_contact=stretch,
        height=float(eta[0]),
        height_ratio=float(eta[0]) / inflated.height,
        volume=post.volume(model, y),
        profile=post.profile(model, y, lam, radius),
        inflated=inflated,
        solver="fem",
        extra=extra,
    )


def _uncompressed(inflated: InflatedState) -> CompressedState:
    return CompressedState(
        alpha=inflated.alpha,
        pressure_initial=inflated.pressure,
        force=0.0,
        pressure=inflated.pressure,
        pressure_ratio=1.0,
        contact_area=0.0,
        contact_radius=0.0,
        stretch_contact=inflated.stretch_pole,
        height=inflated.height,
        height_ratio=1.0,
        volume=inflated.volume,
        profile=inflated.profile,
        inflated=inflated,
        solver="fem",
        extra={
            **inflated.extra,
            "newton_iterations": 0,
            "penetration_pole": 0.0,
            "force_reaction": 0.0,
            "force_pressure_area": 0.0,
            "force_difference": 0.0,
        },
    )


def inflate(alpha, pressure, *, mesh=None, elements=None, order=2, tol=1e-10) -> InflatedState:
    """Inflated state at Phat = ``pressure`` (first branch), by pressure control.

    mesh: nodes of [0, 1] (array, shape (n+1,)) or a mesh file; else a uniform mesh of
    ``elements`` (default ``DEFAULT_ELEMENTS``). order: 1 or 2. tol: Newton tolerance.
    """
    model = _model(alpha, mesh, elements, order, DEFAULT_PENALTY)
    pressure = check_positive("pressure", pressure)
    tol = SOLVER.option("tol").checked(tol)
    y, iterations = inflation.to_pressure(model, pressure, model.zero_multiplier(), Tolerances(tol, tol))
    return _inflated(model, y, iterations)


def inflate_volume(alpha, volume, *, mesh=None, elements=None, order=2, tol=1e-10) -> InflatedState:
    """Inflated state of volume V/R^3 = ``volume``, by volume control (options as ``inflate``)."""
    model = _model(alpha, mesh, elements, order, DEFAULT_PENALTY)
    volume = check_positive("volume", volume)
    tol = SOLVER.option("tol").checked(tol)
    y, iterations = inflation.to_volume(model, volume, model.zero_multiplier(), Tolerances(tol, tol))
    return _inflated(model, y, iterations)


def compression_curve(
    alpha, pressure_initial, forces, *, mesh=None, elements=None, order=2, penalty=DEFAULT_PENALTY, augmented=True,
    tol=1e-10
) -> list[CompressedState]:
    """Compressed states at the forces Fhat = F/(P_I pi R^2), each seeded by the last.

    Options as ``inflate``, and the contact ``penalty`` (units E T / R^2) with ``augmented``
    Lagrangian updates.
    """
    model = _model(alpha, mesh, elements, order, penalty)
    p_i = check_positive("pressure_initial", pressure_initial)
    tol = SOLVER.option("tol").checked(tol)
    augmented = SOLVER.option("augmented").checked(augmented)
    forces = [check_non_negative("force", f) for f in np.atleast_1d(np.asarray(forces, dtype=object))]
    if not forces:
        raise InputError("no force given")
    tol = Tolerances(tol, tol)
    lam = model.zero_multiplier()
    y_i, iterations = inflation.to_pressure(model, p_i, lam, tol)
    inflated = _inflated(model, y_i, iterations)
    touching = np.concatenate([y_i[:-1], [inflated.height]])
    states, y, in_contact = [], touching, False
    for fhat in forces:
        if fhat == 0.0:
            states.append(_uncompressed(inflated))
            continue
        force = fhat * np.pi * p_i
        step = force_path if in_contact else press_to_force
        y, iterations = step(model, y if in_contact else touching, inflated.volume, force, lam, tol)
        if augmented:
            control = Control(volume=inflated.volume, height=None, force=force)
            y, lam, more = augment(model, y, control, lam, tol)
            iterations += more
        states.append(_compressed(model, y, lam, iterations, inflated, fhat))
        in_contact = True
    return states


def compress(alpha, pressure_initial, force, **options) -> CompressedState:
    """Compressed state at the force Fhat = F/(P_I pi R^2); options as ``compression_curve``."""
    return compression_curve(alpha, pressure_initial, [force], **options)[0]


def compress_height(
    alpha, pressure_initial, height, *, mesh=None, elements=None, order=2, penalty=DEFAULT_PENALTY, augmented=True,
    tol=1e-10
) -> CompressedState:
    """Compressed state with the plate at height H/R = ``height`` (plate-height control)."""
    model = _model(alpha, mesh, elements, order, penalty)
    p_i = check_positive("pressure_initial", pressure_initial)
    height = check_positive("height", height)
    tol = SOLVER.option("tol").checked(tol)
    tol = Tolerances(tol, tol)
    lam = model.zero_multiplier()
    y_i, iterations = inflation.to_pressure(model, p_i, lam, tol)
    inflated = _inflated(model, y_i, iterations)
    if height >= inflated.height:
        return _uncompressed(inflated)
    touching = np.concatenate([y_i[:-1], [inflated.height]])
    y, iterations = press_to_height(model, touching, inflated.volume, height, lam, tol)
    if augmented:
        y, lam, more = augment(model, y, Control(volume=inflated.volume, height=height), lam, tol)
        iterations += more
    return _compressed(model, y, lam, iterations, inflated)

