"""How the columns of pocket's results say their unit (``pocket run``'s CSV and JSON, ``pocket sweep``'s CSV).

- A quantity in SI units ends in its unit: ``_Pa``, ``_N``, ``_m``, ``_m2``, ``_m3`` (``pressure_Pa``,
  ``contact_radius_deformed_m``).
- A name without a unit is dimensionless: the model's keys (``pocket.core.states``) in the model's units,
  pressures as Phat = P R / (E T) (``pressure``, ``contact_pressure_edge``, a gas's ``ambient``), forces as
  Fhat = F / (P_I pi R^2), lengths in units of R, areas of pi R^2, volumes of R^3, tensions of E T; and
  stretches, ratios, flags and names.
- The rubber law's stresses are in units of mu_0, the rubber's small-strain shear modulus, and say so:
  ``c1_per_mu0``, ``c2_per_mu0`` (Mooney-Rivlin), ``mu_per_mu0`` (neo-Hookean, Gent, Ogden's list),
  ``c10_per_mu0``, ... (Yeoh); its dimensionless parameters keep their names (Gent's ``jm``, Ogden's
  ``exponents``), as does the prestretch.

Every column is in one table with its unit and meaning: the model's keys in ``pocket.core.reported``, the
columns added here in ``COLUMNS``, the stresses in units of mu_0 by the rule above. ``column(name)`` looks a
column up (a ``KeyError`` for one in neither table), and the writers of ``pocket run``'s and ``pocket sweep``'s
files look up every column they write (``documented``), so that no column leaves pocket unexplained.
"""

from __future__ import annotations

from collections.abc import Iterable

from pocket.core.materials import LAWS, Material
from pocket.core.reported import UNITS as MODEL_UNITS
from pocket.core.reported import Reported, reported

__all__ = ["COLUMNS", "PER_MU0", "STRESSES", "UNITS", "column", "documented", "in_mu0", "parameter_column",
           "row_scalars", "rubber_columns"]

#: the suffix of a law's stress given in units of mu_0
PER_MU0 = "_per_mu0"
#: the parameter names that are stresses, in any law (``RubberLaw.stresses``)
STRESSES = frozenset(name for law in LAWS.values() for name in law.stresses)
#: how far from 1 the mu_0 of a rubber may be and its stresses still count as in units of mu_0 (rounding of
#: ``Material.scaled``: mu_0 of Ogden's scaled stresses is 1 to a few ulps)
_UNIT = 1e-12


def parameter_column(name: str) -> str:
    """The column of the law parameter ``name``: ``name`` + ``PER_MU0`` for a stress, ``name`` otherwise."""
    return name + PER_MU0 if name in STRESSES else name


def in_mu0(material: Material) -> Material:
    """``material`` with its stresses in units of mu_0: as given if they are already (mu_0 = 1 to rounding),
    else ``Material.scaled``."""
    return material if abs(material.mu0 - 1.0) <= _UNIT else material.scaled()


def rubber_columns(material: Material) -> dict:
    """``material.describe()`` with its parameters under their columns (``parameter_column``), the stresses in
    units of mu_0 (``in_mu0``)."""
    return {parameter_column(name): value for name, value in in_mu0(material).describe().items()}


def row_scalars(state, contact: dict | None = None) -> dict:
    """The dimensionless keys of the state ``state`` (its ``scalars``) as a row names them: the rubber's
    parameters under their columns (``rubber_columns``), and ``contact`` (the contact patch of a compressed
    state, ``pocket.apps.contactpatch.contact_patch``), if given, after the state's KEYS in place of its own."""
    contact = contact or {}
    rubber, last = state.material.describe(), state.KEYS[-1]
    out = {}
    for key, value in state.scalars().items():
        if key == "material":
            out.update(rubber_columns(state.material))
        elif key not in rubber and key not in contact:
            out[key] = value
        if key == last:
            out.update(contact)
    return out


#: the units of the columns: the model's (``pocket.core.reported.UNITS``), SI and mu_0
UNITS = {**MODEL_UNITS, "N": "newtons", "Pa": "pascals", "m": "metres", "m2": "square metres",
         "m3": "cubic metres", "mu_0": "in units of the rubber's small-strain shear modulus mu_0"}

#: the columns pocket's applications add to the model's keys: a case's load, its SI values, a sweep's record
COLUMNS: dict[str, Reported] = {
    "load": Reported("text", "the load as the case file gives it ('0.2 N', '9 mm')"),
    "force_N": Reported("N", "the force F (of a force load, as the case gives it; a capsule's: on each plate)"),
    "pressure_Pa": Reported("Pa", "the fluid's gauge pressure P"),
    "pressure_rise_Pa": Reported("Pa", "P - P_I, the pressure's rise under the force"),
    "contact_pressure_pole_Pa": Reported("Pa", "the contact pressure at the pole (P on the flat plate)"),
    "contact_pressure_edge_Pa": Reported("Pa", "the contact pressure at the contact edge (P on the flat plate)"),
    "contact_area_m2": Reported("m2", "A_c, the deformed area in contact (the curved area under a sphere)"),
    "contact_radius_deformed_m": Reported("m", "rho_c, the contact patch's radius as a camera or an ink print "
                                               "measures it: the contact edge's distance from the axis"),
    "contact_radius_lagrangian_m": Reported("m", "a_c, where the contact edge was in the flat sheet (smaller "
                                                 "than rho_c by the hoop stretch there; a capsule's: the arc "
                                                 "length from the pole on the undeformed sphere)"),
    "height_m": Reported("m", "the inflated pole height H0; pressed, the indenter's lowest point H above the "
                              "clamp plane (a capsule's: above its equatorial plane, half the gap)"),
    "travel_m": Reported("m", "H0 - H, how far the indenter has pressed the pocket (a capsule's: each plate)"),
    "gap_m": Reported("m", "a capsule's gap between the plates, 2 H R (inflated: its height 2 lambda R, where the "
                           "plates first touch it)"),
    "radius_equator_m": Reported("m", "a capsule's deformed equatorial radius"),
    "volume_m3": Reported("m3", "the volume under the sheet (a membrane's mid-surface, the solid's lower "
                                "surface); a capsule's whole volume"),
    "volume_lower_m3": Reported("m3", "a membrane solver's fluid volume: under the sheet's lower surface, half "
                                      "the deformed thickness below the mid-surface"),
    "solver_options": Reported("text", "a sweep's solver options as name=value, separated by spaces (empty: the "
                                       "solver's defaults)"),
    "status": Reported("text", "a sweep point's outcome: ok, out_of_range or failed"),
    "message": Reported("text", "why a sweep point is out_of_range or failed (one line; empty when ok)"),
    "indenter": Reported("text", "what pressed: plate, 'sphere K=...' (K = R_s / R) or 'profile sha256=...' (a "
                                 "profile table, by its content)"),
}


def column(name: str) -> Reported:
    """The unit and meaning of a column of pocket's results.

    Parameters
    ----------
    name : str
        A column of ``pocket run``'s CSV and JSON rows or of a sweep file.

    Returns
    -------
    pocket.core.reported.Reported
        ``COLUMNS``'s entry, a law's stress in units of mu_0 (``c1_per_mu0``: unit ``mu_0``, the parameter's
        meaning), or a model's key (``pocket.core.reported.reported``).

    Raises
    ------
    KeyError
        For any other name, a bare stress (``c1``) included: a stress column says its unit.

    Examples
    --------
    >>> column("pressure_Pa").unit, column("c10_per_mu0").unit, column("height").unit
    ('Pa', 'mu_0', 'R')
    """
    if name in COLUMNS:
        return COLUMNS[name]
    if name.endswith(PER_MU0) and name[:-len(PER_MU0)] in STRESSES:
        return Reported("mu_0", reported(name[:-len(PER_MU0)]).meaning)
    if name in STRESSES:
        raise KeyError(f"{name!r} is a stress without its unit: a column names it {parameter_column(name)!r}")
    return reported(name)


def documented(names: Iterable[str]) -> None:
    """Check that every column is documented.

    Parameters
    ----------
    names : iterable of str
        The columns a writer is about to write.

    Raises
    ------
    KeyError
        For the first of ``names`` that ``column`` does not know.
    """
    for name in names:
        column(name)
