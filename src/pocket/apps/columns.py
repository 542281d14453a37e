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
"""

from __future__ import annotations

from pocket.core.materials import LAWS, Material

__all__ = ["PER_MU0", "STRESSES", "in_mu0", "parameter_column", "row_scalars", "rubber_columns"]

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
