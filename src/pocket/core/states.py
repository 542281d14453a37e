"""The vocabulary every solver returns: profiles, inflated and compressed states.

All quantities are dimensionless: lengths in units of the clamp radius R,
pressures as Phat = P R / (E T) (E = 6 (C1 + C2) the small-strain Young's
modulus, T the sheet thickness), tensions (membrane stress resultants) in units
of E T, volumes in R^3, force as Fhat = F / (P_I pi R^2).

A state echoes its inputs exactly: ``alpha``, ``pressure`` of an inflation,
``pressure_initial`` and ``force`` of a compression are the numbers the caller
gave, never recomputed ones.
Solvers share these containers and nothing else, so that a bug in one cannot
hide from the cross-check with another.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping

import numpy as np

__all__ = ["Profile", "InflatedState", "CompressedState"]


@dataclasses.dataclass(frozen=True)
class Profile:
    """The meridian of the deformed sheet, sampled at Lagrangian radii.

    Every field is a float array of shape (n,), ordered by increasing ``r``
    from the pole (r = 0) to the clamp (r = 1).

    r : Lagrangian radius r/R of the flat sheet.
    rho, eta : deformed radial position and height, in units of R.
    stretch_1, stretch_2 : meridional and hoop stretches lambda_1, lambda_2.
    tension_1, tension_2 : stress resultants T_1, T_2 in units of E T.
    contact : bool array, True where the sheet touches the plate.
    """

    r: np.ndarray
    rho: np.ndarray
    eta: np.ndarray
    stretch_1: np.ndarray
    stretch_2: np.ndarray
    tension_1: np.ndarray
    tension_2: np.ndarray
    contact: np.ndarray

    def __post_init__(self):
        shapes = {f.name: np.shape(getattr(self, f.name)) for f in dataclasses.fields(self)}
        if len(set(shapes.values())) != 1 or len(shapes["r"]) != 1:
            raise ValueError(f"Profile fields must be arrays of one common shape (n,), got {shapes}")

    @property
    def stretch_3(self) -> np.ndarray:
        """Thickness ratio lambda_3 = 1 / (lambda_1 lambda_2), shape (n,)."""
        return 1.0 / (self.stretch_1 * self.stretch_2)


def _scalars(state, keys, extra) -> dict[str, float]:
    out = {key: float(getattr(state, key)) for key in keys}
    out.update({k: (v if isinstance(v, (str, bool, int)) else float(v)) for k, v in extra.items()})
    out["solver"] = state.solver
    return out


@dataclasses.dataclass(frozen=True)
class InflatedState:
    """Step 1: the sheet inflated at pressure ``pressure`` (Phat).

    ``extra`` holds solver-specific diagnostics (mesh size, iterations, ...);
    ``scalars()`` returns the reported keys (``KEYS``) followed by those.
    ``warnings`` are one-line notes on a state that is returned but should not
    pass unremarked (an approximate model outside its range); the command line
    prints them and JSON carries them.
    """

    alpha: float
    pressure: float
    stretch_pole: float
    height: float
    volume: float
    stretch_clamp: float
    profile: Profile | None
    solver: str
    extra: Mapping[str, float] = dataclasses.field(default_factory=dict)
    warnings: tuple[str, ...] = ()

    KEYS = ("alpha", "pressure", "stretch_pole", "height", "volume", "stretch_clamp")

    def scalars(self) -> dict[str, float]:
        """The reported quantities as a flat dict (JSON-ready)."""
        return _scalars(self, self.KEYS, self.extra)


@dataclasses.dataclass(frozen=True)
class CompressedState:
    """Step 2: the inflated pocket pressed by a flat plate at fixed volume.

    ``contact_area`` is the deformed area A_c/(pi R^2) = pi (lambda_c a_c)^2 /
    (pi R^2); ``contact_radius`` the Lagrangian a_c/R. ``inflated`` is the
    step-1 state this one was compressed from. ``extra`` and ``warnings`` as
    for ``InflatedState``.
    """

    alpha: float
    pressure_initial: float
    force: float
    pressure: float
    pressure_ratio: float
    contact_area: float
    contact_radius: float
    stretch_contact: float
    height: float
    height_ratio: float
    volume: float
    profile: Profile | None
    inflated: InflatedState
    solver: str
    extra: Mapping[str, float] = dataclasses.field(default_factory=dict)
    warnings: tuple[str, ...] = ()

    KEYS = (
        "alpha",
        "pressure_initial",
        "force",
        "pressure",
        "pressure_ratio",
        "contact_area",
        "contact_radius",
        "stretch_contact",
        "height",
        "height_ratio",
        "volume",
    )

    def scalars(self) -> dict[str, float]:
        """The reported quantities as a flat dict (JSON-ready)."""
        return _scalars(self, self.KEYS, self.extra)
