"""A case resolved to the dimensionless model, and its states back in SI units.

With E = 3 mu_0 the modulus (6 (C1 + C2) for Mooney-Rivlin), T the thickness and R the clamp radius (a
capsule's radius; its F the force on each plate, its H each plate's distance from the equatorial plane)
(``pocket.core.states``): P = Phat E T / R, F = Fhat P_I pi R^2 (an uninflated capsule's, P_I = 0, F = (F / (E T R))
E T R: its force in the solvers' unit ``force_unit = "ETR"``), lengths = (x/R) R, areas =
(A/(pi R^2)) pi R^2, volumes = (V/R^3) R^3; a gas's ambient pressure enters the solvers as
Phat_atm = P_atm R / (E T). The solvers get the rubber as ``Pocket.material``: the float
alpha = C2/C1 for Mooney-Rivlin (the path it always took), the law's ``Material`` scaled to
units of mu_0 otherwise, so that a state's parameters are dimensionless like its other keys.
An initial height H0 becomes Phat_I by ``pocket.apps.inverse.pressure_for_height``; an initial volume by the solver's
volume-controlled inflation, checked to lie on the pressure-controlled first
branch (compression starts from there). Plate heights become forces by
``pocket.apps.inverse.force_where``.
"""

from __future__ import annotations

import dataclasses
import math

from pocket.core.errors import InputError, OutOfRangeError, PocketError
from pocket.core.fluids import Fluid
from pocket.core.geometries import DISC
from pocket.core.indenters import PLATE
from pocket.core.inputs import MAGNITUDES, quote
from pocket.core.materials import Material, mooney_rivlin
from pocket.core.units import written_like

from .cases import THICKNESS_RATIO, Case
from .columns import row_scalars
from .contactpatch import KEYS as CONTACT_PRESSURES
from .contactpatch import contact_patch
from .forcerange import check_force
from .inverse import force_where, pressure_for_height, range_end
from .solvers import entry, record

__all__ = ["Pocket", "compressed_row", "forces", "inflated_row", "load_forces", "resolve"]


@dataclasses.dataclass(frozen=True)
class Pocket:
    """A case resolved to the dimensionless model: the case and its Phat_I.

    SI values carry their unit in the name (``pressure_initial_Pa``, ``force_scale_N``): P = Phat E T / R,
    F = Fhat P_I pi R^2, lengths = (x / R) R.

    Attributes
    ----------
    case : Case
        The case (``pocket.apps.cases``).
    pressure_initial : float
        Phat_I = P_I R / (E T).

    Examples
    --------
    >>> from pocket.apps.cases import sample
    >>> from pocket.apps.physical import resolve
    >>> pocket = resolve(sample(1))
    >>> print(pocket.pressure_initial, round(pocket.pressure_scale_Pa, 6), round(pocket.force_scale_N, 6))
    0.31 15525.0 6.04788
    """

    case: Case
    pressure_initial: float

    @property
    def alpha(self) -> float | None:
        """C2/C1 of a Mooney-Rivlin rubber, else None."""
        return self.case.alpha

    @property
    def material(self) -> Material:
        """The rubber as the solvers take it: a Mooney-Rivlin rubber by its C2/C1 (``mooney_rivlin``, as it
        always was solved), another law in units of mu_0."""
        if self.case.alpha is None:
            return self.case.material.scaled()
        given = mooney_rivlin(self.case.alpha)
        lp = self.case.material.prestretch
        return given if lp == 1.0 else dataclasses.replace(given, prestretch=lp)

    @property
    def fluid(self) -> Fluid:
        """The fluid as the solvers take it: a gas's ambient pressure as Phat_atm = P_atm R / (E T)."""
        return self.case.fluid.scaled(self.pressure_scale_Pa)

    @property
    def pressure_scale_Pa(self) -> float:
        """E T / R: P = Phat * pressure_scale_Pa."""
        return self.case.modulus * self.case.thickness / self.case.radius

    @property
    def pressure_initial_Pa(self) -> float:
        """P_I."""
        return self.pressure_initial * self.pressure_scale_Pa

    @property
    def force_scale_N(self) -> float:
        """P_I pi R^2: F = Fhat * force_scale_N (0 for an uninflated capsule, which has no Fhat)."""
        return self.pressure_initial_Pa * math.pi * self.case.radius**2

    @property
    def uninflated(self) -> bool:
        """Whether P_I = 0: an uninflated capsule, pressed by forces F / (E T R) (``force_unit``)."""
        return self.pressure_initial == 0.0

    @property
    def force_unit(self) -> str:
        """The unit of the forces the solvers are given (``pocket.core.inputs.FORCE_UNITS``): ``"Fhat"``, or
        ``"ETR"`` for an uninflated capsule."""
        return "ETR" if self.uninflated else "Fhat"

    @property
    def force_unit_N(self) -> float:
        """The solvers' unit of force in N: P_I pi R^2 (``force_scale_N``), or E T R for an uninflated capsule."""
        return self.pressure_scale_Pa * self.case.radius**2 if self.uninflated else self.force_scale_N

    def solver_force(self, state) -> float:
        """The force of a compressed ``state`` in the solvers' unit (``force_unit``): its Fhat, or an uninflated
        capsule's ``extra["force_ETR"]``."""
        return float(state.extra["force_ETR"]) if self.uninflated else state.force

    def force_N(self, state) -> float:
        """The force F of a compressed ``state``, N (on each plate of a capsule)."""
        return self.solver_force(state) * self.force_unit_N

    def solver(self):
        """The record of the case's solver (``pocket.core.solver.Solver``: its entry points by ``entry``)."""
        return record(self.case.solver)

    def options(self, step: str = "compress") -> dict:
        """The keyword arguments of ``step``'s entry points ("inflate" or "compress"): the case's solver
        options that the step takes, the geometry if it is not the flat pocket, and for a compression the fluid if
        it is a gas and the indenter if it is not the flat plate (``fluid_options``)."""
        solver = self.solver()
        return {**{k: v for k, v in self.case.options if step in solver.option(k).steps}, **self.fluid_options(step)}

    def curve_options(self) -> dict:
        """The keyword arguments of the solver's ``compression_curve`` for the case's loads: ``options()``, and for
        an uninflated capsule ``force_unit="ETR"``."""
        return {**self.options(), **({"force_unit": "ETR"} if self.uninflated else {})}

    def fluid_options(self, step: str = "compress") -> dict:
        """What a step is given besides its solver's options: ``{"geometry": ...}`` for a capsule (any surface
        but the flat pocket), and for a compression ``{"fluid": self.fluid}`` for a gas-filled pocket and
        ``{"indenter": ...}`` for an indenter other than the flat plate, else nothing (the flat pocket, a liquid
        and the flat plate are every solver's default)."""
        geometry = {} if self.case.geometry == DISC else {"geometry": self.case.geometry}
        if step != "compress":
            return geometry
        gas = {"fluid": self.fluid} if self.case.fluid.is_gas else {}
        return {**gas, **({} if self.case.indenter == PLATE else {"indenter": self.case.indenter}), **geometry}


def _inside(key: str, given: str, name: str, value: float) -> float:
    """``value``, the dimensionless form of the case's ``key``, if the model takes it (0, or a magnitude
    within ``pocket.core.inputs.MAGNITUDES``); else an InputError quoting the case's value."""
    low, high = MAGNITUDES
    if value != 0.0 and not low <= abs(value) <= high:
        raise InputError(f"{key} = {given} gives {name} = {value:.3g}, outside the magnitudes of the model's "
                         f"dimensionless inputs ({low:g} to {high:g})")
    return value


def _scales(case: Case) -> str:
    """The inputs that make the case's pressures dimensionless (Phat = P R / (E T)), as the case gives them."""
    return (f"sheet.thickness = {quote(case.as_given('sheet.thickness'))}, {case.radius_key} = "
            f"{quote(case.as_given(case.radius_key))} (E = {case.modulus:.6g} Pa)")


def resolve(case: Case) -> Pocket:
    """A case resolved to the model: Phat_I solved for from the case's initial state (pressure, height or volume).

    Parameters
    ----------
    case : Case
        The case (``pocket.apps.cases``).

    Returns
    -------
    Pocket

    Raises
    ------
    OutOfRangeError
        For a pressure, height or volume the model's first branch does not reach, quoting the value as the case
        gives it (a pressure with the thickness and radius that scale it).

    Examples
    --------
    A pocket given by its inflated height H0 gets the pressure that inflates it that high:

    >>> from pocket import shooting
    >>> from pocket.apps.cases import parse
    >>> from pocket.apps.physical import resolve
    >>> pocket = resolve(parse({"sheet": {"thickness": "0.25 mm", "c1": "160 kPa", "c2": "47 kPa"},
    ...                         "clamp": {"radius": "20 mm"}, "initial": {"height": "9 mm"}},
    ...                        require_loads=False))
    >>> H0 = shooting.inflate(pocket.material, pocket.pressure_initial).height * 20
    >>> print(round(H0, 9))
    9.0
    """
    kind, value = case.initial
    unit = Pocket(case, 1.0)  # Phat_I = 1: its pressure_initial_Pa is E T / R
    solver, options = unit.solver(), unit.options("inflate")
    given = quote(case.as_given(f"initial.{kind}"))
    if kind == "pressure":
        scales = f"{given} with {_scales(case)}"
        pocket = Pocket(case, _inside("initial.pressure", scales, "Phat_I = P_I R / (E T)",
                                      value / unit.pressure_scale_Pa))
        try:
            entry(solver, "inflate", f"initial.pressure = {given}")(pocket.material, pocket.pressure_initial,
                                                                   **options)  # solvers cache it for later
        except OutOfRangeError as err:
            raise OutOfRangeError(f"initial.pressure = {scales} gives Phat_I = P_I R / (E T) = "
                                  f"{pocket.pressure_initial:.6g}: {err}") from None
        return pocket
    if kind == "height":
        try:
            return Pocket(case, pressure_for_height(solver, unit.material, value / case.radius, **options))
        except OutOfRangeError as err:
            low = case.geometry != DISC and value < case.radius  # a capsule's pole is at R with no pressure
            raise OutOfRangeError(f"initial.height = {given}: no inflated state of the model's first branch is "
                                  f"that {'low' if low else 'high'} ({err})") from None
    volume = value / case.radius**3
    purpose = f"initial.volume = {given}"
    phat = entry(solver, "inflate_volume", purpose)(unit.material, volume, **options).pressure
    reached = entry(solver, "inflate", purpose)(unit.material, phat, **options).volume
    if abs(reached - volume) > 1e-6 * volume:  # the two solves agree to ~1e-10 on the first branch
        raise OutOfRangeError(f"initial.volume = {given} lies past the pressure maximum of the first branch, "
                              "where the pocket cannot be held at fixed pressure")
    return Pocket(case, phat)


def _what(case: Case) -> str:
    """What the case's membrane is, in a message: "pocket" or "capsule"."""
    return case.geometry.name


def _pressing(case: Case) -> str:
    """What presses the case's pocket, in a message: "plate" or "indenter"."""
    return "plate" if case.indenter == PLATE else "indenter"


def _height_error(pocket: Pocket, index: int, top: float, refusal: OutOfRangeError) -> OutOfRangeError:
    """Why height ``index`` of the indenter (below the inflated height ``top``, m) has no state: for a pocket, it is
    below the lowest height the model reaches, said in the case's own unit; for a capsule, the solver's
    ``refusal`` (a height above the start of its branch reached deep, or between its two branches) after the load
    as the case gives it."""
    case = pocket.case
    given = case.as_given(f"loads.heights[{index}]")
    if case.geometry != DISC:
        return OutOfRangeError(f"loads.heights[{index}] = {quote(given)} (H/R = "
                               f"{case.loads[index] / case.radius:.10g}): {refusal}")
    lowest = ""
    try:
        end = range_end(pocket.solver(), pocket.material, pocket.pressure_initial, **pocket.options())
        compress = entry(pocket.solver(), "compress", f"the lowest {_pressing(case)} height")
        low = compress(pocket.material, pocket.pressure_initial, end, **pocket.options()).height
        lowest = f" ({written_like(low * case.radius, given, 'length')}; the inflated height is " \
                 f"{written_like(top, given, 'length')})"
    except PocketError:  # the reason stands without the number
        pass
    why = ("the model's range ends first" if case.geometry != DISC else
           "the free part of the sheet would fold onto the clamp plane first" if case.indenter == PLATE else
           "the model's range under this indenter ends first")
    return OutOfRangeError(f"loads.heights[{index}] = {quote(given)} is below the lowest {_pressing(case)} height "
                           f"the model reaches{lowest}: {why}")


def forces(pocket: Pocket) -> list[float]:
    """The case's loads as forces in the solvers' unit (``load_forces``); the first load the model does not reach is
    its ``OutOfRangeError``."""
    out = []
    for value in load_forces(pocket):
        if isinstance(value, OutOfRangeError):
            raise value
        out.append(value)
    return out


def load_forces(pocket: Pocket, held: dict | None = None) -> list[float | OutOfRangeError]:
    """Each of the case's loads as a force in the solvers' unit (``Pocket.force_unit``: Fhat, or an uninflated
    capsule's F / (E T R)) (heights of the indenter's lowest point solved for their force: by the solver's
    ``compress_height`` where its record lists it, else by a search on its forces, ``force_where``), or, for a
    load the model does not reach, the ``OutOfRangeError`` saying why.

    A height above the inflated pocket, or below the lowest the model reaches, or a force past the
    end of the model's range (``pocket.apps.forcerange``), is not reached; its error quotes the load as the
    case gives it, with the bound in its unit. A capsule's load short of the start of its branch reached deep, or
    between its two branches, is not reached either: its error is the solver's refusal after the load as given.
    ``held``: a dict that gets, for each height the solver held itself (``compress_height``), its index -> the state
    solved there, so that it need not be solved again at its force.
    """
    case = pocket.case
    out: list[float | OutOfRangeError] = []
    if case.load_kind == "forces" and pocket.uninflated:
        return _uninflated_forces(pocket)
    if case.load_kind == "forces":
        for index, force in enumerate(case.loads):
            key, given = f"loads.forces[{index}]", case.as_given(f"loads.forces[{index}]")
            fhat = _inside(key, quote(given), "Fhat = F / (P_I pi R^2)", force / pocket.force_scale_N)
            try:
                out.append(check_force(pocket, key, given, fhat))
            except OutOfRangeError as err:
                out.append(err)
        return out
    solver, options = pocket.solver(), pocket.options()
    travel = solver.serves("compress_height")  # the solver holds the height itself: one solve, not a search
    inflate = entry(solver, "inflate", "loads.heights")
    top = inflate(pocket.material, pocket.pressure_initial, **pocket.options("inflate")).height * case.radius
    for index, height in enumerate(case.loads):
        if height > top:
            given = case.as_given(f"loads.heights[{index}]")
            out.append(OutOfRangeError(f"loads.heights[{index}] = {quote(given)} is above the inflated "
                                       f"{_what(case)} (H0 = {written_like(top, given, 'length')}): the "
                                       f"{_pressing(case)} would not "
                                       "touch it"))
            continue
        try:
            if travel:
                state = entry(solver, "compress_height", "loads.heights")(pocket.material, pocket.pressure_initial,
                                                                          height / case.radius, **options)
                if held is not None:
                    held[index] = state
                out.append(pocket.solver_force(state))
            else:
                out.append(force_where(solver, pocket.material, pocket.pressure_initial, "height",
                                       height / case.radius, increasing=False, **options))
        except OutOfRangeError as err:
            out.append(_height_error(pocket, index, top, err))
    return out


def _uninflated_forces(pocket: Pocket) -> list[float | OutOfRangeError]:
    """An uninflated capsule's force loads as F / (E T R), or for a force short of its states the solver's refusal
    after the load as the case gives it (``load_forces``).

    F = 0 is the unstressed sphere the plates touch. Every other state lies on the branch reached deep, which
    starts at a least force and whose force grows as the plates close: the loads are asked of the solver from the
    least up, and once one is solved every larger one lies on the branch.
    """
    case = pocket.case
    given = [case.as_given(f"loads.forces[{index}]") for index in range(len(case.loads))]
    values = [_inside(f"loads.forces[{index}]", quote(given[index]), "F / (E T R)", force / pocket.force_unit_N)
              for index, force in enumerate(case.loads)]
    out: list[float | OutOfRangeError] = list(values)
    compress = entry(pocket.solver(), "compress", "loads.forces")
    for index in sorted((i for i, f in enumerate(values) if f != 0.0), key=values.__getitem__):
        try:
            compress(pocket.material, 0.0, values[index], force_unit="ETR", **pocket.options())
            break
        except OutOfRangeError as err:
            out[index] = OutOfRangeError(f"loads.forces[{index}] = {quote(given[index])} (F / (E T R) = "
                                         f"{values[index]:.10g}): {err}")
    return out


def _lower(pocket: Pocket, state) -> tuple[dict, list[str]]:
    """({"volume_lower_m3": V_lower R^3}, []): the fluid's volume under the sheet's lower surface, the state's
    ``volume_lower`` at the case's T/R. Nothing for a solver that models the thickness (its record has the
    option ``THICKNESS_RATIO``: the solid), whose ``volume`` is under its lower surface already, nor for a capsule
    (``pocket.core.offset`` offsets a clamped sheet); nothing and a
    warning where the lower surface would fold (an OutOfRangeError of its own)."""
    if pocket.solver().option(THICKNESS_RATIO) is not None or pocket.case.geometry != DISC:
        return {}, []
    try:
        v = state.volume_lower(pocket.case.thickness / pocket.case.radius)
    except OutOfRangeError as err:
        return {}, [f"no volume_lower: {err}"]
    return {"volume_lower_m3": v * pocket.case.radius**3}, []


def _capsule_lengths(pocket: Pocket, state) -> dict:
    """A capsule's lengths in metres: ``gap_m`` = 2 H R, the gap between the plates (an inflated capsule's
    height 2 lambda R, where the plates first touch it), and ``radius_equator_m``, its equator's radius; nothing
    for a pocket."""
    if pocket.case.geometry == DISC:
        return {}
    r = pocket.case.radius
    return {"gap_m": 2.0 * state.height * r, "radius_equator_m": float(state.extra["radius_equator"]) * r}


def inflated_row(pocket: Pocket, state) -> dict:
    """The inflated state in SI units, then its dimensionless keys (``columns.row_scalars``) and its
    ``warnings`` (a list: the case's, then the state's). ``volume_lower_m3`` follows ``volume_m3``
    (``_lower``)."""
    r = pocket.case.radius
    lower, notes = _lower(pocket, state)
    return {"pressure_Pa": state.pressure * pocket.pressure_scale_Pa, "height_m": state.height * r,
            **_capsule_lengths(pocket, state), "volume_m3": state.volume * r**3, **lower, **row_scalars(state),
            "warnings": [*pocket.case.warnings, *state.warnings, *notes]}


def compressed_row(pocket: Pocket, state, load: int | None = None) -> dict:
    """A compressed state in SI units, then its dimensionless keys (``CompressedState.KEYS``) and its
    ``warnings`` (a list: the case's, then the state's).

    The inputs are the ones asked, never a solver's echo of them: ``alpha`` and
    ``pressure_initial`` are the pocket's. With ``load``, the state of the case's load of that
    index: the row starts with the load as the case gives it (``"0.2 N"``, ``"9 mm"``), and a
    force load's ``force_N`` is the force as parsed and its ``force`` the Fhat given to the solver
    (``forces``), not values recomputed from the state. ``contact_pressure_pole_Pa`` and
    ``contact_pressure_edge_Pa`` follow the pressure where the state carries them (``pocket.apps.contactpatch``:
    on the flat plate both are P); ``contact_area_m2`` is the curved area in contact,
    ``contact_radius_deformed_m`` the radius of the contact patch, rho_c R (``contactpatch.contact_patch``: on
    the plate sqrt(A_c / pi)), ``contact_radius_lagrangian_m`` the Lagrangian a_c R (where the contact edge
    was in the flat sheet) and ``height_m`` the indenter's lowest point above the clamp plane;
    ``volume_lower_m3`` follows ``volume_m3`` (``_lower``). The dimensionless keys
    (``columns.row_scalars``) carry ``contact_radius_deformed`` (rho_c / R) and the contact pressures
    (Phat) after the state's KEYS.
    """
    case, r, scale = pocket.case, pocket.case.radius, pocket.pressure_scale_Pa
    lower, notes = _lower(pocket, state)
    asked = {"pressure_initial": pocket.pressure_initial}
    if pocket.alpha is not None:
        asked["alpha"] = pocket.alpha
    row: dict[str, object] = {"force_N": pocket.force_N(state)}
    if load is not None:
        row = {"load": case.as_given(f"loads.{case.load_kind}[{load}]"), **row}
        if case.load_kind == "forces":
            force = "force_ETR" if pocket.uninflated else "force"
            row["force_N"], asked[force] = case.loads[load], case.loads[load] / pocket.force_unit_N
    patch = contact_patch(state)
    row.update({"pressure_Pa": state.pressure * scale,
                "pressure_rise_Pa": (state.pressure - pocket.pressure_initial) * scale,
                **{f"{k}_Pa": v * scale for k, v in patch.items() if k in CONTACT_PRESSURES},
                "contact_area_m2": state.contact_area * math.pi * r**2,
                **{f"{k}_m": v * r for k, v in patch.items() if k not in CONTACT_PRESSURES},
                "contact_radius_lagrangian_m": state.contact_radius * r, "height_m": state.height * r,
                "travel_m": (state.inflated.height - state.height) * r, **_capsule_lengths(pocket, state),
                "volume_m3": state.volume * r**3,
                **lower, **row_scalars(state, patch), **asked,
                "warnings": [*case.warnings, *state.warnings, *notes]})
    return row
