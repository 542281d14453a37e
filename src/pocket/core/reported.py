"""The keys a state reports (``InflatedState.scalars``, ``CompressedState.scalars``), each with its unit and
meaning: the one table that pocket's outputs look their keys up in and its documentation is written from.

Every key is dimensionless, in the model's units (``UNITS``): lengths in units of the clamp radius R,
pressures as Phat = P R / (E T) (E = 3 mu_0 the rubber's small-strain Young's modulus, T the sheet's
thickness), forces as Fhat = F / (P_I pi R^2), areas in pi R^2, volumes in R^3, tensions in E T. The
columns that pocket's applications add in SI units (``force_N``, ``pressure_Pa``, ...) are
``pocket.apps.columns``'s.

``GROUPS`` holds the keys by what they describe; ``REPORTED`` is the same table flat, and ``reported(key)``
looks one up, a ``KeyError`` naming the table for a key that is not in it: a key a solver adds without
saying what it means fails the outputs that would write it, and the tests.
"""

from __future__ import annotations

import dataclasses

from .materials import LAWS

__all__ = ["GROUPS", "REPORTED", "UNITS", "Reported", "reported"]


@dataclasses.dataclass(frozen=True)
class Reported:
    """One reported key: its ``unit`` (a key of ``UNITS``) and its ``meaning`` (a sentence)."""

    unit: str
    meaning: str


#: unit -> what it is: the model's units, and the words for values that have none
UNITS = {
    "Phat": "pressure in units of E T / R: Phat = P R / (E T)",
    "Fhat": "force in units of P_I pi R^2: Fhat = F / (P_I pi R^2)",
    "R": "length in units of the clamp radius R",
    "pi R^2": "area in units of the clamp's area pi R^2",
    "R^3": "volume in units of R^3",
    "E T": "tension (force per unit length of the sheet) in units of E T",
    "E T R^2": "energy in units of E T R^2",
    "stress": "a stress of the rubber law, in the unit the rubber was given in (units of mu_0 on the command "
              "line; a file's column says its unit)",
    "1": "a pure number: a stretch, a ratio, a count or an exponent",
    "flag": "true or false",
    "text": "a name or a message",
}


def _law_parameters() -> dict[str, Reported]:
    """Every law's parameters (``pocket.core.materials.LAWS``), each with its own help and the laws that have
    it; a name two laws share (``mu``) is described once, with each law's help."""
    helps: dict[str, dict[str, list[str]]] = {}
    units: dict[str, str] = {}
    for law in LAWS.values():
        for parameter in law.parameters:
            helps.setdefault(parameter.name, {}).setdefault(parameter.help, []).append(law.name)
            units[parameter.name] = "stress" if parameter.unit == "stress" else "1"
    return {name: Reported(units[name], "; ".join(f"{text} ({', '.join(laws)})" for text, laws in by.items()))
            for name, by in helps.items()}


#: the state's own keys (``InflatedState.KEYS``, ``CompressedState.KEYS``)
_STATE = {
    "alpha": Reported("1", "alpha = C2/C1 of a Mooney-Rivlin rubber given by it (absent for a rubber given by its "
                           "parameters)"),
    "pressure": Reported("Phat", "the fluid's gauge pressure P: the inflation pressure of an inflated state, the "
                                 "pressure after pressing of a compressed one"),
    "stretch_pole": Reported("1", "the sheet's stretch at the pole (equal in every direction there)"),
    "height": Reported("R", "an inflated state's pole height H0; a compressed state's indenter's lowest point H "
                            "above the clamp plane (the dome's height under the plate); a capsule's: the pole's "
                            "or the plate's distance from its equatorial plane"),
    "volume": Reported("R^3", "the volume under the sheet (a membrane's mid-surface; the solid's lower surface, "
                              "the fluid's); a capsule's whole volume"),
    "stretch_clamp": Reported("1", "the meridional stretch at the clamp"),
    "pressure_initial": Reported("Phat", "P_I, the inflation pressure at which the fluid was sealed"),
    "force": Reported("Fhat", "the force F pressing the indenter on the pocket"),
    "pressure_ratio": Reported("1", "P / P_I, the pressure's rise under the force"),
    "contact_area": Reported("pi R^2", "A_c, the deformed area in contact (the curved area under a sphere or a "
                                       "profile); F / P on the flat plate"),
    "contact_radius": Reported("R", "a_c, the Lagrangian contact radius: where the contact edge was in the "
                                    "flat sheet (a capsule's: the arc length from the pole to the contact edge on "
                                    "the undeformed sphere, its polar angle)"),
    "stretch_contact": Reported("1", "the stretch of the sheet in contact (uniform on the plate; the pole's "
                                     "under a curved indenter; a capsule's hoop stretch at the contact edge)"),
    "height_ratio": Reported("1", "H / H0, the pressed height over the inflated one"),
}

#: the contact patch, where a solver gives it (``CompressedState.CONTACT_KEYS``)
_CONTACT = {
    "contact_radius_deformed": Reported("R", "rho_c, the contact edge's distance from the axis in the deformed "
                                             "sheet: the radius of the patch a camera or an ink print shows"),
    "contact_pressure_pole": Reported("Phat", "the contact pressure at the pole (P on the flat plate; P + (T_1 + "
                                              "T_2) / R_s on a sphere)"),
    "contact_pressure_edge": Reported("Phat", "the contact pressure at the contact edge (P on the flat plate)"),
}

#: a capsule's own keys (its states' ``extra``)
_CAPSULE = {
    "geometry": Reported("text", "the membrane's reference shape: pocket (a flat sheet clamped at its rim) or "
                                 "capsule (a closed sphere pressed between two parallel plates)"),
    "radius_equator": Reported("R", "a capsule's deformed equatorial radius"),
    "force_ETR": Reported("1", "a capsule's force on each plate in units of E T R: F / (E T R) = pi Fhat Phat_I"),
}

#: the membrane's validity (``pocket.core.states.CHECKS``)
_CHECKS = {
    "tension_1_min": Reported("E T", "the smallest meridional tension T_1 over the sheet"),
    "tension_2_min": Reported("E T", "the smallest hoop tension T_2 over the sheet"),
    "wrinkled": Reported("flag", "a tension is not positive somewhere: outside membrane theory, where a real "
                                 "sheet would wrinkle (a warning says where)"),
}

#: the rubber and the fluid, as given (``Material.describe``, ``Fluid.describe``)
_RUBBER = {
    "material": Reported("text", "the rubber's law: mooney-rivlin, neo-hookean, yeoh, gent or ogden"),
    **_law_parameters(),
    "prestretch": Reported("1", "lambda_p, the equibiaxial stretch the sheet was clamped with (reported where "
                                "it is not 1)"),
}
_FLUID = {
    "fluid": Reported("text", "liquid (a fixed volume) or gas (an ideal gas sealed at P_I)"),
    "ambient": Reported("Phat", "a gas's ambient (absolute) pressure, Phat_atm = P_atm R / (E T)"),
    "gamma": Reported("1", "a gas's polytropic exponent: 1 isothermal to 5/3"),
}

#: what every state ends with
_RUN = {
    "solver": Reported("text", "the solver that computed the state: shooting, fem, analytical or solid"),
    "warnings": Reported("text", "notes on a state that should not pass unremarked (a compressive tension, an "
                                 "approximate model outside its range), one line each"),
}

#: the finite-element solver's diagnostics (``pocket.fem``'s states' ``extra``)
_FEM = {
    "elements": Reported("1", "elements of the mesh"),
    "order": Reported("1", "element order: 1 (P1) or 2 (P2)"),
    "newton_iterations": Reported("1", "Newton iterations of the solve (0 for the state at zero force)"),
    "contact": Reported("text", "contact method: fitted (a mesh node follows the contact edge) or penalty"),
    "force_reaction": Reported("Fhat", "the indenter's reaction, summed from the contact zone's nodes (equals "
                                       "the force asked)"),
    "force_pressure_area": Reported("Fhat", "P times the deformed contact area (the flat plate's F = P A_c)"),
    "force_difference": Reported("Fhat", "the difference of the two force balances (force_reaction - "
                                         "force_pressure_area, or force_cap - force_contact_pressure)"),
    "contact_pressure_error": Reported("1", "the plate's nodal reactions against the fluid pressure's nodal "
                                            "loads in the contact zone, max |difference| / max |load|"),
    "penetration": Reported("R", "how far the free sheet reaches above the indenter's surface (0, or round-off "
                                 "and the penalty's error)"),
    "penetration_pole": Reported("R", "penalty contact: the pole's height above the plate's"),
    "force_cap": Reported("Fhat", "a curved indenter: the contact cap's balance as a free body"),
    "force_contact_pressure": Reported("Fhat", "a curved indenter: the contact pressure integrated over the "
                                               "contact area"),
    "contact_pressure_min": Reported("Phat", "a curved indenter: the smallest contact pressure in the zone"),
    "energy": Reported("E T R^2", "a curved indenter: the stored elastic energy U"),
}

#: the solid's diagnostics (``pocket.solid``'s states' ``extra``)
_SOLID = {
    "height_mid": Reported("R", "the mid-surface's pole height (height is the upper surface's)"),
    "volume_mid": Reported("R^3", "the volume under the mid-surface (volume is under the lower surface)"),
    "det_f_constraint_residual": Reported("1", "the residual of the incompressibility constraint, |int q (det F "
                                               "- 1)| / int q over the pressures q: at Newton's tolerance"),
    "mesh_det_f_error_peak": Reported("1", "the largest |det F - 1| at one quadrature point: a local error of "
                                           "the mesh at the clamp's corners, not a volume error"),
    "thickness_ratio": Reported("1", "T / R, the sheet's thickness over the clamp radius"),
    "mesh_elements": Reported("1", "elements along the radius, as built"),
    "mesh_layers": Reported("1", "layers of elements through the thickness"),
    "iterations": Reported("1", "Newton iterations of the solve"),
    "reaction": Reported("Fhat", "the indenter's reaction, the sum of the contact forces"),
    "contact_radius_error": Reported("R", "the contact edge's own error estimate: the spread of its extrapolations "
                                          "from the gaps beyond it, on the mesh's cluster of short elements there"),
}

#: the keys by what they describe (the documentation's sections)
GROUPS: dict[str, dict[str, Reported]] = {
    "state": _STATE, "contact patch": _CONTACT, "capsule": _CAPSULE, "membrane checks": _CHECKS, "rubber": _RUBBER,
    "fluid": _FLUID,
    "solver and warnings": _RUN, "fem diagnostics": _FEM, "solid diagnostics": _SOLID,
}

#: every reported key
REPORTED: dict[str, Reported] = {key: entry for group in GROUPS.values() for key, entry in group.items()}


def reported(key: str) -> Reported:
    """The unit and meaning of a reported key.

    Parameters
    ----------
    key : str
        A key of a state's ``scalars`` (``"pressure_ratio"``, ``"force_reaction"``) or ``"warnings"``.

    Returns
    -------
    Reported
        Its unit (a key of ``UNITS``) and meaning.

    Raises
    ------
    KeyError
        For a key not in ``REPORTED``, naming it.

    Examples
    --------
    >>> reported("contact_area").unit
    'pi R^2'
    """
    try:
        return REPORTED[key]
    except KeyError:
        raise KeyError(f"{key!r} is not a reported key of pocket.core.reported: say there what it means") from None
